//! SO(n) and GL(n) on faer, and the dense matrix functions under them: the generic suite for
//! SO(3), SO(4), SO(6), GL(3), the τ maps, expm against the Taylor reference, logm ∘ expm = id,
//! the logarithm at rotation angle π, agreement with the closed-form `So3`, refused matrices.

use core::f64::consts::PI;
use faer::{Col, Mat};
use lie_groups::matrix::dense::logm;
use lie_groups::matrix::dense::{expm, max_abs_diff, norm1};
use lie_groups::matrix::so_n::{so_hat, so_vee};
use lie_groups::testing::{
    assert_small, check_adjoint, check_cayley_closed_forms, check_dexp, check_exp_log,
    check_group_axioms, check_tau, expm_taylor,
};
use lie_groups::{matrix_path, Cayley, CayleyGroup, ExpMap, GlN, LieError, LieGroup, So3, SoN};
use nalgebra::Vector3;
use proptest::prelude::*;

lie_groups::lie_group_suite!(so3n, lie_groups::SoN<3>, 1.7);
lie_groups::lie_group_suite!(so4n, lie_groups::SoN<4>, 1.2);
lie_groups::lie_group_suite!(gl3, lie_groups::GlN<3>, 0.5);
lie_groups::tau_suite!(so3n_exp, lie_groups::SoN<3>, lie_groups::ExpMap, 1.7);
lie_groups::tau_suite!(so3n_cayley, lie_groups::SoN<3>, lie_groups::Cayley, 1.7);
lie_groups::tau_suite!(so4n_exp, lie_groups::SoN<4>, lie_groups::ExpMap, 1.2);
lie_groups::tau_suite!(so4n_cayley, lie_groups::SoN<4>, lie_groups::Cayley, 1.2);
lie_groups::tau_suite!(gl3_exp, lie_groups::GlN<3>, lie_groups::ExpMap, 0.5);
lie_groups::tau_suite!(gl3_cayley, lie_groups::GlN<3>, lie_groups::Cayley, 0.5);
lie_groups::cayley_group_suite!(so3n_cayley_closed_forms, lie_groups::SoN<3>, 1.7);
lie_groups::cayley_group_suite!(so4n_cayley_closed_forms, lie_groups::SoN<4>, 1.2);

/// A deterministic pseudo-random vector (LCG), for fixed-sample checks that must reproduce.
fn sample(dim: usize, seed: u64, scale: f64) -> Col<f64> {
    let mut s = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    Col::from_fn(dim, |_| {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        scale * (2.0 * ((s >> 11) as f64 / (1u64 << 53) as f64) - 1.0)
    })
}

/// SO(6) (dim 15) is too slow in debug builds for 48 proptest cases per property; the same check
/// functions run on six fixed pseudo-random samples instead.
#[test]
fn so6_suite_holds_on_fixed_samples() {
    type G = SoN<6>;
    for seed in 0..6 {
        let (a, b, c) = (
            sample(15, seed, 0.6),
            sample(15, seed + 100, 0.6),
            sample(15, seed + 200, 1.0),
        );
        check_group_axioms::<G>(&a, &b, &c);
        check_exp_log::<G>(&a);
        check_adjoint::<G>(&a, &b, &c);
        check_dexp::<G>(&a);
        check_tau::<G, ExpMap>(&a, &c);
        check_tau::<G, Cayley>(&a, &c);
        check_cayley_closed_forms::<G>(&a);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// expm against the independent Taylor reference for random 5×5 matrices of 1-norm up to 20,
    /// relative to ‖e^A‖ (both are backward stable; 1e-12 leaves room for the conditioning of
    /// e^A at ‖A‖ = 20).
    #[test]
    fn expm_matches_taylor_reference_up_to_norm_20(v in proptest::collection::vec(-1.0f64..1.0, 25), r in 0.0f64..20.0) {
        use lie_groups::linalg;
        let a0 = nalgebra::DMatrix::from_fn(5, 5, |i, j| v[5 * i + j]);
        let n0 = linalg::norm1(a0.as_view()).max(1e-300);
        let a = a0 * (r / n0);
        let e = linalg::expm(a.as_view());
        let t = expm_taylor(a.as_view());
        let size = t.amax().max(1.0);
        assert_small("expm = Taylor reference", linalg::max_abs_diff(e.as_view(), t.as_view()) / size, 1e-12);
    }

    /// logm(expm(A)) = A for A with ‖A‖₁ < 3 (< π, so every eigenvalue has |Im λ| < π and A is the
    /// principal logarithm of e^A).
    #[test]
    fn logm_inverts_expm_inside_the_principal_strip(v in proptest::collection::vec(-1.0f64..1.0, 16), r in 0.0f64..3.0) {
        let a0 = Mat::from_fn(4, 4, |i, j| v[4 * i + j]);
        let n0 = norm1(a0.as_ref()).max(1e-300);
        let a = Mat::from_fn(4, 4, |i, j| r / n0 * a0[(i, j)]);
        let l = logm(expm(a.as_ref()).as_ref()).unwrap();
        assert_small("logm(expm A) = A", max_abs_diff(l.as_ref(), a.as_ref()), 1e-12 * (1.0 + r));
    }
}

/// ξ in the SoN<3> basis for the cross-product vector ω of So3: (ξ₀, ξ₁, ξ₂) = (ω_z, −ω_y, ω_x).
fn so3_coords(w: &Vector3<f64>) -> Col<f64> {
    Col::from_fn(3, |p| [w.z, -w.y, w.x][p])
}

#[test]
fn son3_agrees_with_closed_form_so3() {
    for w in [
        Vector3::new(0.3, -0.2, 0.5),
        Vector3::new(1e-8, 2e-8, -1e-8),
        Vector3::new(2.0, 1.0, -1.5),
        Vector3::new(0.0, 0.0, PI - 1e-7),
    ] {
        let xi = so3_coords(&w);
        assert_small(
            "hat agrees",
            max_abs_diff(SoN::<3>::hat(&xi).as_ref(), So3::hat(&w).to_mat().as_ref()),
            0.0,
        );
        let (g, r) = (SoN::<3>::exp(&xi), So3::exp(&w));
        assert_small(
            "exp agrees",
            max_abs_diff(
                g.matrix().as_ref(),
                lie_groups::DenseMatrix::to_mat(&r.matrix()).as_ref(),
            ),
            1e-15,
        );
        let (lg, lr) = (g.log().unwrap(), r.log().unwrap());
        assert_small("log agrees", (&lg - &so3_coords(&lr)).norm_max(), 1e-14);
        // Ad agrees up to the change of basis (ξ₀, ξ₁, ξ₂) = (ω_z, −ω_y, ω_x)
        let u = Vector3::new(0.7, -0.1, 0.4);
        let ad_n = g.adjoint_apply(&so3_coords(&u));
        let ad_r = so3_coords(&r.adjoint_apply(&u));
        assert_small("Ad agrees", (&ad_n - &ad_r).norm_max(), 1e-15);
    }
}

use lie_groups::DenseMatrix as _;

fn rotation_about_z(theta: f64) -> Col<f64> {
    // pair (0,1) is the rotation of the xy-plane
    Col::from_fn(3, |p| if p == 0 { theta } else { 0.0 })
}

#[test]
fn son_log_is_exact_at_and_near_angle_pi() {
    // exactly π: R = diag(−1, −1, 1); either sign is a logarithm
    let r = SoN::<3>::from_matrix(&Mat::from_fn(3, 3, |i, j| {
        if i != j {
            0.0
        } else if i < 2 {
            -1.0
        } else {
            1.0
        }
    }))
    .unwrap();
    let l = r.log().unwrap();
    assert_small("|θ| = π", (l.norm_l2() - PI).abs(), 1e-15);
    assert_small(
        "exp(log R) = R at π",
        SoN::<3>::exp(&l).matrix_distance(&r),
        1e-15,
    );
    // generic axis, angle π − 1e-9: the logarithm is unique and recovered to round-off
    let axis = so3_coords(&Vector3::new(1.0, -2.0, 0.5).normalize());
    for th in [PI - 1e-9, PI - 1e-5, PI] {
        let xi = Col::from_fn(3, |p| th * axis[p]);
        let g = SoN::<3>::exp(&xi);
        let l = g.log().unwrap();
        let err = (&l - &xi)
            .norm_max()
            .min(
                (&l + &xi)
                    .norm_max()
                    .max(if th < PI { f64::INFINITY } else { 0.0 }),
            );
        assert_small("log near π", err, 1e-13);
        assert_small(
            "exp(log g) = g near π",
            SoN::<3>::exp(&l).matrix_distance(&g),
            1e-14,
        );
    }
    let _ = rotation_about_z(0.0);
}

#[test]
fn son_log_handles_several_planes_near_and_at_pi() {
    // SO(4): planes (0,1) and (2,3) are coordinates 0 and 5 of the lexicographic basis
    let two_planes = |a: f64, b: f64| {
        Col::from_fn(6, |p| {
            if p == 0 {
                a
            } else if p == 5 {
                b
            } else {
                0.0
            }
        })
    };
    let q = SoN::<4>::exp(&sample(6, 7, 1.0)); // a generic change of basis
    for (a, b) in [
        (PI, 1.0),
        (PI - 1e-3, PI - 2e-3),
        (PI - 1e-3, -(PI - 1e-3)),
        (PI - 1e-10, 0.5),
        (PI, PI),
    ] {
        let r = q
            .compose(&SoN::<4>::exp(&two_planes(a, b)))
            .compose(&q.inverse());
        let l = r
            .log()
            .unwrap_or_else(|e| panic!("log failed at angles ({a}, {b}): {e}"));
        assert_small(
            "exp(log R) = R",
            SoN::<4>::exp(&l).matrix_distance(&r),
            1e-13,
        );
        // the log is skew and its angles are the given ones (up to sign at exactly π)
        let angles_sq = a * a + b * b;
        assert_small(
            "‖log R‖² = θ₁² + θ₂²",
            (l.squared_norm_l2() - angles_sq).abs(),
            1e-12,
        );
    }
}

#[test]
fn son_checked_constructor_refuses_non_rotations() {
    let reflection = Mat::from_fn(3, 3, |i, j| {
        if i != j {
            0.0
        } else if i == 0 {
            -1.0
        } else {
            1.0
        }
    });
    assert!(matches!(
        SoN::<3>::from_matrix(&reflection),
        Err(LieError::WrongDeterminant { .. })
    ));
    let scaled = Mat::from_fn(3, 3, |i, j| if i == j { 1.01 } else { 0.0 });
    assert!(matches!(
        SoN::<3>::from_matrix(&scaled),
        Err(LieError::NotOrthogonal { .. })
    ));
    let mut nan = Mat::<f64>::identity(3, 3);
    nan[(1, 2)] = f64::NAN;
    assert!(matches!(
        SoN::<3>::from_matrix(&nan),
        Err(LieError::NonFinite { .. })
    ));
    assert!(matches!(
        SoN::<3>::from_matrix(&Mat::identity(4, 4)),
        Err(LieError::DimensionMismatch { .. })
    ));
    assert!(matches!(
        SoN::<3>::from_matrix_unchecked(&nan).log(),
        Err(LieError::NonFinite { .. })
    ));
    // a lone eigenvalue −1 (det −1) is refused by log as well
    assert!(SoN::<3>::from_matrix_unchecked(&reflection).log().is_err());
}

#[test]
fn son_projection_is_the_nearest_rotation() {
    let g = SoN::<5>::exp(&sample(10, 3, 1.0));
    // symmetric positive perturbation of the polar factor: g S with S = I + 0.1 sym
    let s = Mat::from_fn(5, 5, |i, j| if i == j { 1.2 } else { 0.05 });
    let m = g.matrix() * &s;
    let p = SoN::<5>::project(&m).unwrap();
    assert_small("polar factor of g S is g", p.matrix_distance(&g), 1e-14);
    // a reflection-contaminated input still projects onto det +1
    let refl = Mat::from_fn(5, 5, |i, j| {
        if i != j {
            0.0
        } else if i == 0 {
            -1.0
        } else {
            1.0
        }
    });
    let p = SoN::<5>::project(&refl).unwrap();
    assert!(SoN::<5>::from_matrix(&p.matrix()).is_ok());
    assert!(SoN::<5>::project(&Mat::from_fn(5, 5, |_, _| f64::NAN)).is_err());
}

#[test]
fn gl_checked_constructor_refuses_singular_and_non_finite() {
    let singular = Mat::from_fn(3, 3, |i, j| (i + j) as f64);
    let res = GlN::<3>::from_matrix(&singular);
    assert!(matches!(res, Err(LieError::Singular { .. })), "{res:?}");
    let mut nan = Mat::<f64>::identity(3, 3);
    nan[(0, 0)] = f64::INFINITY;
    assert!(matches!(
        GlN::<3>::from_matrix(&nan),
        Err(LieError::NonFinite { .. })
    ));
    let g = GlN::<3>::exp(&sample(9, 1, 0.7));
    assert!(GlN::<3>::from_matrix(&g.matrix()).is_ok());
    // a negative real eigenvalue has no real principal log
    let neg = Mat::from_fn(3, 3, |i, j| {
        if i != j {
            0.0
        } else if i == 0 {
            -2.0
        } else {
            1.0
        }
    });
    assert!(GlN::<3>::from_matrix(&neg).unwrap().log().is_err());
}

#[test]
fn son_adjoint_and_ad_match_the_generic_matrix_path_at_n10() {
    type G = SoN<10>;
    let (a, b) = (sample(45, 11, 0.8), sample(45, 12, 0.8));
    let g = G::exp(&a);
    assert_small(
        "Ad_g = compound",
        max_abs_diff(g.adjoint().as_ref(), matrix_path::adjoint(&g).as_ref()),
        1e-13,
    );
    assert_small(
        "ad_ξ = commutator",
        max_abs_diff(G::ad(&a).as_ref(), matrix_path::ad::<G>(&a).as_ref()),
        1e-14,
    );
    let ad_b = g.adjoint() * &b;
    assert_small(
        "Ad_g apply",
        (&g.adjoint_apply(&b) - &ad_b).norm_max(),
        1e-13,
    );
    let adt_b = g.adjoint().transpose() * &b;
    assert_small(
        "Ad*_g apply",
        (&g.coadjoint_apply(&b) - &adt_b).norm_max(),
        1e-13,
    );
    let ad_dual = G::ad(&a).transpose() * &b;
    assert_small(
        "ad*_ξ apply",
        (&G::ad_dual_apply(&a, &b) - &ad_dual).norm_max(),
        1e-13,
    );
    assert_small(
        "dcay = generic",
        max_abs_diff(
            G::dcay_left(&a).as_ref(),
            matrix_path::dcay_left::<G>(&a).as_ref(),
        ),
        1e-13,
    );
    assert_small(
        "vee ∘ hat = id",
        (&so_vee(so_hat(10, &a).as_ref()) - &a).norm_max(),
        0.0,
    );
}
