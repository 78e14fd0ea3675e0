//! The generic group suite of `lie_groups::testing` on the bundles: TG and T*G over every base group
//! with the full suite, the four nested bundles with a handful of cases each (their dense
//! operators and block matrices are 4–8× the base size, and the suite is slow in debug builds).
//!
//! Beyond the suite, `check_bundle_overrides` pins the hand-written applied maps (bracket,
//! ad*_ξ, Ad*_g) that the nested products are built from to the operators `ad`, `adjoint`.

use lie_groups::testing::{
    assert_small, check_adjoint, check_dexp, check_exp_log, check_group_axioms,
};
use lie_groups::{DenseMatrix, LieGroup, Operator, Se2, Se3, So3, SoN, Vector};
use trivial_bundles::{CotangentBundle, TangentBundle, Tstg, Tstsg, Ttg, Ttsg};

/// The overridden applied maps agree with the block operators they stand for: `[x, y] = ad_x y`,
/// `ad*_x μ = ad_xᵀ μ`, `Ad_g x = Ad_g · x`, `Ad*_g μ = Ad_gᵀ μ` (to 1e-12 relative: a few
/// roundings of products of entries of size ≤ s²).
fn check_bundle_overrides<B: LieGroup>(a: &B::Algebra, b: &B::Algebra, c: &B::Algebra) {
    let g = B::exp(a);
    let s = 1.0 + g.matrix().to_mat().as_ref().norm_max();
    let tol = 1e-12 * s * s * (1.0 + a.norm()) * (1.0 + b.norm() + c.norm());
    assert_small(
        "[x, y] = ad_x y",
        B::bracket(a, b).sub(&B::ad(a).apply(b)).norm_max(),
        tol,
    );
    assert_small(
        "ad*_x μ = ad_xᵀ μ",
        B::ad_dual_apply(a, c)
            .sub(&B::ad(a).apply_transpose(c))
            .norm_max(),
        tol,
    );
    assert_small(
        "Ad*_g μ = Ad_gᵀ μ",
        g.coadjoint_apply(c)
            .sub(&g.adjoint().apply_transpose(c))
            .norm_max(),
        tol,
    );
    assert_small(
        "Ad_g x = Ad_g · x",
        g.adjoint_apply(b).sub(&g.adjoint().apply(b)).norm_max(),
        tol,
    );
}

macro_rules! bundle_suite {
    ($name:ident, $B:ty, $scale:expr, $cases:expr) => {
        mod $name {
            use super::*;
            use lie_groups::testing::{algebra, check_cases};
            type B = $B;
            #[test]
            fn group_axioms_hold() {
                check_cases(
                    concat!(module_path!(), "::group_axioms_hold"),
                    file!(),
                    $cases,
                    &(
                        algebra::<B>($scale),
                        algebra::<B>($scale),
                        algebra::<B>($scale),
                    ),
                    &|(a, b, c)| check_group_axioms::<B>(&a, &b, &c),
                );
            }
            #[test]
            fn exp_log_round_trip_and_match_block_matrix_series() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::exp_log_round_trip_and_match_block_matrix_series"
                    ),
                    file!(),
                    $cases,
                    &algebra::<B>($scale),
                    &|a| check_exp_log::<B>(&a),
                );
            }
            #[test]
            fn adjoint_is_block_conjugation_and_ad_is_block_commutator() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::adjoint_is_block_conjugation_and_ad_is_block_commutator"
                    ),
                    file!(),
                    $cases,
                    &(
                        algebra::<B>($scale),
                        algebra::<B>($scale),
                        algebra::<B>($scale),
                    ),
                    &|(a, b, c)| check_adjoint::<B>(&a, &b, &c),
                );
            }
            #[test]
            fn dexp_matches_finite_differences_and_inverts() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::dexp_matches_finite_differences_and_inverts"
                    ),
                    file!(),
                    $cases,
                    &algebra::<B>($scale),
                    &|a| check_dexp::<B>(&a),
                );
            }
            #[test]
            fn applied_maps_match_block_operators() {
                check_cases(
                    concat!(module_path!(), "::applied_maps_match_block_operators"),
                    file!(),
                    $cases,
                    &(
                        algebra::<B>($scale),
                        algebra::<B>($scale),
                        algebra::<B>($scale),
                    ),
                    &|(a, b, c)| check_bundle_overrides::<B>(&a, &b, &c),
                );
            }
        }
    };
}

// Scale 1: |a| ≤ √3 < π on SO(3), inside the domain of log; the fibre components are of order 1.
bundle_suite!(tangent_so3, TangentBundle<So3>, 1.0, 48);
bundle_suite!(cotangent_so3, CotangentBundle<So3>, 1.0, 48);
bundle_suite!(tangent_se3, TangentBundle<Se3>, 1.0, 32);
bundle_suite!(cotangent_se3, CotangentBundle<Se3>, 1.0, 32);

bundle_suite!(tangent_se2, TangentBundle<Se2>, 1.0, 32);
bundle_suite!(cotangent_se2, CotangentBundle<Se2>, 1.0, 32);
bundle_suite!(tangent_son3, TangentBundle<SoN<3>>, 1.0, 16);
bundle_suite!(cotangent_son3, CotangentBundle<SoN<3>>, 1.0, 16);

bundle_suite!(ttg_so3, Ttg<So3>, 0.8, 8);
bundle_suite!(ttsg_so3, Ttsg<So3>, 0.8, 8);
bundle_suite!(tstg_so3, Tstg<So3>, 0.8, 8);
bundle_suite!(tstsg_so3, Tstsg<So3>, 0.8, 8);
bundle_suite!(ttg_se2, Ttg<Se2>, 0.8, 4);
bundle_suite!(tstsg_se2, Tstsg<Se2>, 0.8, 4);
bundle_suite!(ttg_son3, Ttg<SoN<3>>, 0.8, 4);
bundle_suite!(ttsg_son3, Ttsg<SoN<3>>, 0.8, 4);
bundle_suite!(ttg_se3, Ttg<Se3>, 0.6, 4);
bundle_suite!(ttsg_se3, Ttsg<Se3>, 0.6, 4);
bundle_suite!(tstg_se3, Tstg<Se3>, 0.6, 4);
bundle_suite!(tstsg_se3, Tstsg<Se3>, 0.6, 4);

#[test]
fn identity_is_the_zero_fibre_over_e_and_names_nest() {
    let e = Ttsg::<So3>::identity();
    assert_eq!(
        e.matrix_distance(&Ttsg::<So3>::exp(&<Ttsg<So3> as LieGroup>::Algebra::zeros(
            12
        ))),
        0.0
    );
    assert_eq!(Ttg::<So3>::dim(), 12);
    assert_eq!(Tstsg::<Se3>::dim(), 24);
    assert_eq!(Ttsg::<So3>::name(), format!("TT*{}", So3::name()));
}

#[test]
fn from_matrix_rejects_broken_block_structure() {
    let x = TangentBundle::<So3>::exp(&trivial_bundles::Pair::new(
        nalgebra::Vector3::new(0.1, 0.2, 0.3),
        nalgebra::Vector3::new(1.0, -1.0, 0.5),
    ));
    let mut m = x.matrix();
    m[(4, 0)] = 0.1; // bottom-left block must vanish
    assert!(TangentBundle::<So3>::from_matrix(&m).is_err());
    let mut m = x.matrix();
    m[(0, 3)] += 0.1; // g⁻¹ u leaves 𝔰𝔬(3): its diagonal is no longer 0
    assert!(TangentBundle::<So3>::from_matrix(&m).is_err());
    let mut m = x.matrix();
    m[(1, 1)] = f64::NAN;
    assert!(TangentBundle::<So3>::from_matrix(&m).is_err());
    assert!(TangentBundle::<So3>::from_matrix(&faer::Mat::identity(5, 5)).is_err());

    let y = CotangentBundle::<So3>::exp(&trivial_bundles::Pair::new(
        nalgebra::Vector3::new(0.1, 0.2, 0.3),
        nalgebra::Vector3::new(1.0, -1.0, 0.5),
    ));
    let mut m = y.matrix();
    m[(4, 4)] += 0.1; // middle block must be Ad_g
    assert!(CotangentBundle::<So3>::from_matrix(&m).is_err());
    let mut m = y.matrix();
    m[(3, 6)] = 0.1; // last column must be (0, …, 0, 1)
    assert!(CotangentBundle::<So3>::from_matrix(&m).is_err());
    assert!(CotangentBundle::<So3>::from_matrix(&y.matrix()).is_ok());
}
