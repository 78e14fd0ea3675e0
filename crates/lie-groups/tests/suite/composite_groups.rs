//! Composite groups: ℝⁿ (`Rn`), the direct product G × H (`Product`) and the power Gᴺ (`Power`).
//!
//! - The generic suite (group axioms, exp/log against the Taylor matrix series, Ad/ad against
//!   matrix conjugation and commutators, d^L exp against finite differences and Van Loan), the τ
//!   suites for exp and Cayley, and the Cayley closed forms against the generic matrix path, on
//!   ℝ³, SO(3) × ℝ³, SE(2) × SO(3), SO(3)³ and ℝ² × ℝ³.
//! - Factor by factor: every map of the product equals, block by block, the factors' own maps
//!   (computed on the factors alone), with zero off-diagonal blocks; the same for each copy of the
//!   power. ℝⁿ's maps against their closed forms (exp = identity, Ad = I, ad = 0).
//! - Coordinates concatenate; refused matrices give the named error.

use lie_groups::testing::proptest::prelude::*;
use lie_groups::testing::{algebra, assert_small};
use lie_groups::{
    Cayley, CayleyGroup, DenseMatrix, ExpMap, LieError, LieGroup, Power, PowerAlgebra, Product,
    ProductAlgebra, Rn, Se2, So3, StructureCheck, Tau, Vector,
};
use nalgebra::DMatrix as Mat;
use nalgebra::{Matrix3, Vector2, Vector3};

type So3R3 = Product<So3, Rn<3>>;
type Se2So3 = Product<Se2, So3>;
type So3Cubed = Power<So3, 3>;

// |ξ| < π on each SO(3) factor needs components ≤ 1.8 (|ξ| ≤ √3·1.8 = 3.12); SE(2)'s |ω| ≤ 1.8.
lie_groups::lie_group_suite!(r3, lie_groups::Rn<3>, 10.0);
lie_groups::lie_group_suite!(so3_r3, lie_groups::Product<lie_groups::So3, lie_groups::Rn<3>>, 1.7);
lie_groups::lie_group_suite!(se2_so3, lie_groups::Product<lie_groups::Se2, lie_groups::So3>, 1.7);
lie_groups::lie_group_suite!(so3_cubed, lie_groups::Power<lie_groups::So3, 3>, 1.7);
lie_groups::lie_group_suite!(
    r2_r3,
    lie_groups::Product<lie_groups::Rn<2>, lie_groups::Rn<3>>,
    5.0
);
lie_groups::tau_suite!(r3_exp, lie_groups::Rn<3>, lie_groups::ExpMap, 10.0);
lie_groups::tau_suite!(r3_cayley, lie_groups::Rn<3>, lie_groups::Cayley, 10.0);
lie_groups::tau_suite!(so3_r3_exp, lie_groups::Product<lie_groups::So3, lie_groups::Rn<3>>, lie_groups::ExpMap, 1.7);
lie_groups::tau_suite!(so3_r3_cayley, lie_groups::Product<lie_groups::So3, lie_groups::Rn<3>>, lie_groups::Cayley, 1.7);
lie_groups::tau_suite!(se2_so3_exp, lie_groups::Product<lie_groups::Se2, lie_groups::So3>, lie_groups::ExpMap, 1.7);
lie_groups::tau_suite!(se2_so3_cayley, lie_groups::Product<lie_groups::Se2, lie_groups::So3>, lie_groups::Cayley, 1.7);
lie_groups::tau_suite!(so3_cubed_exp, lie_groups::Power<lie_groups::So3, 3>, lie_groups::ExpMap, 1.7);
lie_groups::tau_suite!(so3_cubed_cayley, lie_groups::Power<lie_groups::So3, 3>, lie_groups::Cayley, 1.7);
lie_groups::cayley_group_suite!(r3_cayley_closed_forms, lie_groups::Rn<3>, 10.0);
lie_groups::cayley_group_suite!(so3_r3_cayley_closed_forms, lie_groups::Product<lie_groups::So3, lie_groups::Rn<3>>, 1.7);
lie_groups::cayley_group_suite!(se2_so3_cayley_closed_forms, lie_groups::Product<lie_groups::Se2, lie_groups::So3>, 1.7);
lie_groups::cayley_group_suite!(so3_cubed_cayley_closed_forms, lie_groups::Power<lie_groups::So3, 3>, 1.7);

/// `‖block(M; r0, c0) − B‖_max` for a block of M starting at (r0, c0) of B's shape.
fn block_diff(m: &Mat<f64>, r0: usize, c0: usize, b: &Mat<f64>) -> f64 {
    let mut e = 0.0f64;
    for j in 0..b.ncols() {
        for i in 0..b.nrows() {
            e = e.max((m[(r0 + i, c0 + j)] - b[(i, j)]).abs());
        }
    }
    e
}

/// `M` is `diag(blocks…)`: each diagonal block equals its factor's operator to `tol`, and every
/// entry outside the diagonal blocks is exactly 0.
fn assert_block_diagonal(what: &str, m: &Mat<f64>, blocks: &[Mat<f64>], tol: f64) {
    let n: usize = blocks.iter().map(|b| b.nrows()).sum();
    assert_eq!((m.nrows(), m.ncols()), (n, n), "{what}: shape");
    let mut start = 0;
    let mut owner = vec![0usize; n];
    for (k, b) in blocks.iter().enumerate() {
        assert_small(what, block_diff(m, start, start, b), tol);
        owner[start..start + b.nrows()].fill(k);
        start += b.nrows();
    }
    for j in 0..n {
        for i in 0..n {
            if owner[i] != owner[j] {
                assert_eq!(m[(i, j)], 0.0, "{what}: off-diagonal entry ({i}, {j})");
            }
        }
    }
}

/// Every map of G × H against the factors' own, at (ξ, η) with covector (μ, ν).
fn check_product_factorwise<G: CayleyGroup, H: CayleyGroup>(
    xi: &ProductAlgebra<G, H>,
    mu: &ProductAlgebra<G, H>,
    eta: &ProductAlgebra<G, H>,
) {
    type P<G, H> = Product<G, H>;
    let tol = 1e-15;
    let (a, b) = (&xi.a, &xi.b);
    let p = P::<G, H>::exp(xi);
    let (g, h) = (G::exp(a), H::exp(b));
    assert_small("exp: G part", p.g.matrix_distance(&g), tol);
    assert_small("exp: H part", p.h.matrix_distance(&h), tol);
    let q = P::<G, H>::exp(eta);
    let pq = p.compose(&q);
    assert_small(
        "compose: G part",
        pq.g.matrix_distance(&g.compose(&q.g)),
        tol,
    );
    assert_small(
        "compose: H part",
        pq.h.matrix_distance(&h.compose(&q.h)),
        tol,
    );
    let pi = p.inverse();
    assert_small("inverse: G part", pi.g.matrix_distance(&g.inverse()), tol);
    assert_small("inverse: H part", pi.h.matrix_distance(&h.inverse()), tol);
    let l = p.log().unwrap();
    assert_small("log: G part", l.a.sub(&g.log().unwrap()).norm_max(), tol);
    assert_small("log: H part", l.b.sub(&h.log().unwrap()).norm_max(), tol);
    let c = P::<G, H>::cay(xi);
    assert_small("cay: G part", c.g.matrix_distance(&G::cay(a)), tol);
    assert_small("cay: H part", c.h.matrix_distance(&H::cay(b)), tol);
    let ci = c.cay_inv().unwrap();
    assert_small(
        "cay⁻¹: G part",
        ci.a.sub(&c.g.cay_inv().unwrap()).norm_max(),
        tol,
    );
    assert_small(
        "cay⁻¹: H part",
        ci.b.sub(&c.h.cay_inv().unwrap()).norm_max(),
        tol,
    );
    // the operators are block diagonal with the factors' operators as blocks
    let ops = [
        (
            "Ad",
            p.adjoint().to_dmatrix(),
            g.adjoint().to_dmatrix(),
            h.adjoint().to_dmatrix(),
        ),
        (
            "ad",
            P::<G, H>::ad(xi),
            G::ad(a).to_dmatrix(),
            H::ad(b).to_dmatrix(),
        ),
        (
            "d^L exp",
            P::<G, H>::dexp_left(xi),
            G::dexp_left(a).to_dmatrix(),
            H::dexp_left(b).to_dmatrix(),
        ),
        (
            "(d^L exp)⁻¹",
            P::<G, H>::dexp_left_inv(xi),
            G::dexp_left_inv(a).to_dmatrix(),
            H::dexp_left_inv(b).to_dmatrix(),
        ),
        (
            "d^L cay",
            P::<G, H>::dcay_left(xi),
            G::dcay_left(a).to_dmatrix(),
            H::dcay_left(b).to_dmatrix(),
        ),
        (
            "(d^L cay)⁻¹",
            P::<G, H>::dcay_left_inv(xi),
            G::dcay_left_inv(a).to_dmatrix(),
            H::dcay_left_inv(b).to_dmatrix(),
        ),
        (
            "M(μ) = ad*_(·) μ",
            P::<G, H>::ad_dual_operator(mu),
            G::ad_dual_operator(&mu.a).to_dmatrix(),
            H::ad_dual_operator(&mu.b).to_dmatrix(),
        ),
        (
            "D exp(ξ; μ)",
            P::<G, H>::dexp_left_dual_derivative(xi, mu),
            G::dexp_left_dual_derivative(a, &mu.a).to_dmatrix(),
            H::dexp_left_dual_derivative(b, &mu.b).to_dmatrix(),
        ),
        (
            "D cay(ξ; μ)",
            P::<G, H>::dcay_left_dual_derivative(xi, mu),
            G::dcay_left_dual_derivative(a, &mu.a).to_dmatrix(),
            H::dcay_left_dual_derivative(b, &mu.b).to_dmatrix(),
        ),
    ];
    for (what, m, ma, mb) in ops {
        assert_block_diagonal(what, &m, &[ma, mb], tol);
    }
    assert_block_diagonal(
        "hat",
        &P::<G, H>::hat(xi),
        &[G::hat(a).to_dmatrix(), H::hat(b).to_dmatrix()],
        0.0,
    );
    assert_block_diagonal(
        "matrix",
        &p.matrix(),
        &[g.matrix().to_dmatrix(), h.matrix().to_dmatrix()],
        tol,
    );
    // the vector maps of a step, factor by factor
    let pairs = [
        (
            "Ad*_g μ",
            p.coadjoint_apply(mu),
            g.coadjoint_apply(&mu.a),
            h.coadjoint_apply(&mu.b),
        ),
        (
            "Ad_{g⁻¹} η",
            p.adjoint_inverse_apply(eta),
            g.adjoint_inverse_apply(&eta.a),
            h.adjoint_inverse_apply(&eta.b),
        ),
        (
            "[ξ, η]",
            P::<G, H>::bracket(xi, eta),
            G::bracket(a, &eta.a),
            H::bracket(b, &eta.b),
        ),
        (
            "ad*_ξ μ",
            P::<G, H>::ad_dual_apply(xi, mu),
            G::ad_dual_apply(a, &mu.a),
            H::ad_dual_apply(b, &mu.b),
        ),
        (
            "(Ad*_{exp ξ} − I) μ",
            P::<G, H>::exp_coadjoint_increment(xi, mu),
            G::exp_coadjoint_increment(a, &mu.a),
            H::exp_coadjoint_increment(b, &mu.b),
        ),
        (
            "d^{L*}exp_ξ μ",
            P::<G, H>::dexp_left_dual_apply(xi, mu),
            G::dexp_left_dual_apply(a, &mu.a),
            H::dexp_left_dual_apply(b, &mu.b),
        ),
        (
            "(Ad*_{cay ξ} − I) μ",
            P::<G, H>::cay_coadjoint_increment(xi, mu),
            G::cay_coadjoint_increment(a, &mu.a),
            H::cay_coadjoint_increment(b, &mu.b),
        ),
        (
            "d^{L*}cay_ξ μ",
            P::<G, H>::dcay_left_dual_apply(xi, mu),
            G::dcay_left_dual_apply(a, &mu.a),
            H::dcay_left_dual_apply(b, &mu.b),
        ),
    ];
    for (what, v, va, vb) in pairs {
        assert_small(what, v.a.sub(&va).norm_max(), tol);
        assert_small(what, v.b.sub(&vb).norm_max(), tol);
    }
    let gx = P::<G, H>::exp_compose(&q, xi);
    assert_small(
        "g exp ξ: G part",
        gx.g.matrix_distance(&G::exp_compose(&q.g, a)),
        tol,
    );
    assert_small(
        "g exp ξ: H part",
        gx.h.matrix_distance(&H::exp_compose(&q.h, b)),
        tol,
    );
    let gs = P::<G, H>::cay_split_compose(&q, 0.3, xi);
    assert_small(
        "g cay(θξ) cay((1−θ)ξ): G part",
        gs.g.matrix_distance(&G::cay_split_compose(&q.g, 0.3, a)),
        tol,
    );
    assert_small(
        "g cay(θξ) cay((1−θ)ξ): H part",
        gs.h.matrix_distance(&H::cay_split_compose(&q.h, 0.3, b)),
        tol,
    );
}

/// Every map of Gᴺ against G's own on each copy.
fn check_power_factorwise<G: CayleyGroup, const N: usize>(
    xi: &PowerAlgebra<G, N>,
    mu: &PowerAlgebra<G, N>,
) {
    let tol = 1e-15;
    let p = Power::<G, N>::exp(xi);
    let l = p.log().unwrap();
    let c = Power::<G, N>::cay(xi);
    let inc = Power::<G, N>::exp_coadjoint_increment(xi, mu);
    let dual = Power::<G, N>::dexp_left_dual_apply(xi, mu);
    let cdual = Power::<G, N>::dcay_left_dual_apply(xi, mu);
    let coad = p.coadjoint_apply(mu);
    let adj = p.adjoint_apply(mu);
    let br = Power::<G, N>::bracket(xi, mu);
    let addual = Power::<G, N>::ad_dual_apply(xi, mu);
    for k in 0..N {
        let (a, m) = (&xi.parts[k], &mu.parts[k]);
        let g = G::exp(a);
        assert_small("exp, copy k", p.parts[k].matrix_distance(&g), tol);
        assert_small(
            "log, copy k",
            l.parts[k].sub(&g.log().unwrap()).norm_max(),
            tol,
        );
        assert_small("cay, copy k", c.parts[k].matrix_distance(&G::cay(a)), tol);
        assert_small(
            "(Ad*_{exp ξ} − I) μ, copy k",
            inc.parts[k]
                .sub(&G::exp_coadjoint_increment(a, m))
                .norm_max(),
            tol,
        );
        assert_small(
            "d^{L*}exp_ξ μ, copy k",
            dual.parts[k].sub(&G::dexp_left_dual_apply(a, m)).norm_max(),
            tol,
        );
        assert_small(
            "d^{L*}cay_ξ μ, copy k",
            cdual.parts[k]
                .sub(&G::dcay_left_dual_apply(a, m))
                .norm_max(),
            tol,
        );
        let vector_maps = [
            ("Ad*_g μ, copy k", &coad, g.coadjoint_apply(m)),
            ("Ad_g ξ, copy k", &adj, g.adjoint_apply(m)),
            ("[ξ, η], copy k", &br, G::bracket(a, m)),
            ("ad*_ξ μ, copy k", &addual, G::ad_dual_apply(a, m)),
        ];
        for (what, v, want) in vector_maps {
            assert_small(what, v.parts[k].sub(&want).norm_max(), tol);
        }
    }
    let blocks = |f: &dyn Fn(usize) -> Mat<f64>| (0..N).map(f).collect::<Vec<_>>();
    assert_block_diagonal(
        "Ad",
        &p.adjoint(),
        &blocks(&|k| p.parts[k].adjoint().to_dmatrix()),
        tol,
    );
    assert_block_diagonal(
        "ad",
        &Power::<G, N>::ad(xi),
        &blocks(&|k| G::ad(&xi.parts[k]).to_dmatrix()),
        tol,
    );
    assert_block_diagonal(
        "d^L exp",
        &Power::<G, N>::dexp_left(xi),
        &blocks(&|k| G::dexp_left(&xi.parts[k]).to_dmatrix()),
        tol,
    );
    assert_block_diagonal(
        "(d^L exp)⁻¹",
        &Power::<G, N>::dexp_left_inv(xi),
        &blocks(&|k| G::dexp_left_inv(&xi.parts[k]).to_dmatrix()),
        tol,
    );
    assert_block_diagonal(
        "d^L cay",
        &Power::<G, N>::dcay_left(xi),
        &blocks(&|k| G::dcay_left(&xi.parts[k]).to_dmatrix()),
        tol,
    );
    assert_block_diagonal(
        "D exp(ξ; μ)",
        &Power::<G, N>::dexp_left_dual_derivative(xi, mu),
        &blocks(&|k| G::dexp_left_dual_derivative(&xi.parts[k], &mu.parts[k]).to_dmatrix()),
        tol,
    );
    assert_block_diagonal(
        "matrix",
        &p.matrix(),
        &blocks(&|k| p.parts[k].matrix().to_dmatrix()),
        tol,
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    #[test]
    fn so3_r3_maps_are_the_factors_maps(
        xi in algebra::<So3R3>(1.7), mu in algebra::<So3R3>(2.0), eta in algebra::<So3R3>(1.7)
    ) {
        check_product_factorwise::<So3, Rn<3>>(&xi, &mu, &eta);
    }
    #[test]
    fn se2_so3_maps_are_the_factors_maps(
        xi in algebra::<Se2So3>(1.7), mu in algebra::<Se2So3>(2.0), eta in algebra::<Se2So3>(1.7)
    ) {
        check_product_factorwise::<Se2, So3>(&xi, &mu, &eta);
    }
    #[test]
    fn so3_cubed_maps_are_the_copies_maps(xi in algebra::<So3Cubed>(1.7), mu in algebra::<So3Cubed>(2.0)) {
        check_power_factorwise::<So3, 3>(&xi, &mu);
    }
    /// ℝⁿ against its closed forms: exp and cay are the identity map, Ad = I, ad = 0,
    /// d^L exp = d^L cay = I, the product is vector addition.
    #[test]
    fn r3_is_vector_addition_with_trivial_adjoint(
        a in algebra::<Rn<3>>(10.0), b in algebra::<Rn<3>>(10.0), mu in algebra::<Rn<3>>(10.0)
    ) {
        let (x, y) = (Rn::<3>::exp(&a), Rn::<3>::exp(&b));
        prop_assert_eq!(x.vector(), a);
        prop_assert_eq!(Rn::<3>::cay(&a).vector(), a);
        prop_assert_eq!(x.compose(&y).vector(), a + b);
        prop_assert_eq!(x.inverse().vector(), -a);
        prop_assert_eq!(x.log().unwrap(), a);
        prop_assert_eq!(x.adjoint(), Matrix3::identity());
        prop_assert_eq!(x.adjoint_apply(&b), b);
        prop_assert_eq!(x.coadjoint_apply(&mu), mu);
        prop_assert_eq!(Rn::<3>::ad(&a), Matrix3::zeros());
        prop_assert_eq!(Rn::<3>::bracket(&a, &b), Vector3::zeros());
        prop_assert_eq!(Rn::<3>::dexp_left(&a), Matrix3::identity());
        prop_assert_eq!(Rn::<3>::dexp_left_dual_apply(&a, &mu), mu);
        prop_assert_eq!(<Cayley as Tau<Rn<3>>>::dtau_left(&a), Matrix3::identity());
        prop_assert_eq!(<ExpMap as Tau<Rn<3>>>::compose_tau_split(&y, 0.5, &a).vector(), b + a);
        prop_assert_eq!(Rn::<3>::exp_coadjoint_increment(&a, &mu), Vector3::zeros());
        let m = x.matrix();
        for i in 0..4 {
            for j in 0..4 {
                let want = if i == j { 1.0 } else if j == 3 { a[i] } else { 0.0 };
                prop_assert_eq!(m[(i, j)], want);
            }
        }
    }
}

/// Components concatenate, G's (or copy 0's) first; `zeros` splits at the factors' dimensions.
#[test]
fn coordinates_concatenate_factor_by_factor() {
    let v = ProductAlgebra::<Se2, Rn<2>>::new(Vector3::new(1.0, 2.0, 3.0), Vector2::new(4.0, 5.0));
    assert_eq!(v.dim(), 5);
    assert_eq!(v.to_vec(), vec![1.0, 2.0, 3.0, 4.0, 5.0]);
    let mut z = ProductAlgebra::<Se2, Rn<2>>::zeros(5);
    for i in 0..5 {
        z.set(i, v.get(i));
    }
    assert_eq!(z, v);
    assert_eq!(v.dot(&v), 55.0);
    #[cfg(feature = "faer")]
    assert_eq!(ProductAlgebra::<Se2, Rn<2>>::from_col(&v.to_col()), v);
    let w = PowerAlgebra::<So3, 2>::new([Vector3::new(1.0, 2.0, 3.0), Vector3::new(4.0, 5.0, 6.0)]);
    assert_eq!(w.to_vec(), vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    let mut z = PowerAlgebra::<So3, 2>::zeros(6);
    z.set(4, 7.0);
    assert_eq!(z.parts[1], Vector3::new(0.0, 7.0, 0.0));
    assert_eq!(w.dot(&w), 91.0);
    assert_eq!(
        (So3R3::dim(), Se2So3::dim(), So3Cubed::dim(), Rn::<4>::dim()),
        (6, 6, 9, 4)
    );
    assert_eq!(So3R3::name(), "SO(3) × R^3");
    assert_eq!(So3Cubed::name(), "SO(3)^3");
    // Power<G, 2> and Product<G, G> are the same group in the same coordinates
    let a = Vector3::new(0.3, -0.2, 0.9);
    let b = Vector3::new(-1.1, 0.4, 0.2);
    let pw = Power::<So3, 2>::exp(&PowerAlgebra::new([a, b]));
    let pr = Product::<So3, So3>::exp(&ProductAlgebra::new(a, b));
    assert_eq!(pw.matrix(), pr.matrix());
    assert_eq!(
        Power::<So3, 2>::dexp_left(&PowerAlgebra::new([a, b])),
        Product::<So3, So3>::dexp_left(&ProductAlgebra::new(a, b))
    );
}

/// Matrices off the group are refused with the named error; on the group they are accepted.
#[test]
fn refused_matrices_name_what_is_wrong() {
    let x = Rn::<3>::new(Vector3::new(1.0, -2.0, 0.5));
    assert_eq!(Rn::<3>::from_matrix(&x.matrix()).unwrap(), x);
    let mut m = x.matrix();
    m[(0, 1)] = 1e-6;
    assert!(matches!(
        Rn::<3>::from_matrix(&m),
        Err(LieError::NotStructured {
            check: StructureCheck::TranslationLinearBlock,
            ..
        })
    ));
    let mut m = x.matrix();
    m[(3, 3)] = 2.0;
    assert!(matches!(
        Rn::<3>::from_matrix(&m),
        Err(LieError::NotHomogeneous { .. })
    ));
    let mut m = x.matrix();
    m[(1, 3)] = f64::NAN;
    assert!(matches!(
        Rn::<3>::from_matrix(&m),
        Err(LieError::NonFinite { .. })
    ));
    assert!(matches!(
        Rn::<3>::from_matrix(&Mat::identity(3, 3)),
        Err(LieError::DimensionMismatch {
            expected: 4,
            got: 3
        })
    ));
    assert!(matches!(
        Rn::<3>::new(Vector3::new(f64::INFINITY, 0.0, 0.0)).log(),
        Err(LieError::NonFinite { .. })
    ));

    let p = So3R3::exp(&ProductAlgebra::new(
        Vector3::new(0.2, 0.3, -0.1),
        Vector3::new(1.0, 2.0, 3.0),
    ));
    assert!(So3R3::from_matrix(&p.matrix()).unwrap().matrix_distance(&p) == 0.0);
    let mut m = p.matrix();
    m[(0, 5)] = 1e-3;
    assert!(matches!(
        So3R3::from_matrix(&m),
        Err(LieError::NotStructured {
            check: StructureCheck::ProductOffDiagonal,
            ..
        })
    ));
    let mut m = p.matrix();
    m[(0, 0)] += 1e-3; // the SO(3) block is no longer orthogonal: So3's own error
    assert!(matches!(
        So3R3::from_matrix(&m),
        Err(LieError::NotOrthogonal { .. })
    ));
    assert!(matches!(
        So3R3::from_matrix(&Mat::identity(6, 6)),
        Err(LieError::DimensionMismatch {
            expected: 7,
            got: 6
        })
    ));
    let mut m = p.matrix();
    m[(4, 6)] = f64::NAN;
    assert!(matches!(
        So3R3::from_matrix(&m),
        Err(LieError::NonFinite { .. })
    ));

    let w = So3Cubed::identity();
    let mut m = w.matrix();
    m[(7, 1)] = 0.1;
    assert!(matches!(
        So3Cubed::from_matrix(&m),
        Err(LieError::NotStructured {
            check: StructureCheck::ProductOffDiagonal,
            ..
        })
    ));
    let mut m = w.matrix();
    m[(4, 4)] = -1.0; // det −1 in copy 1
    assert!(So3Cubed::from_matrix(&m).is_err());
    assert!(So3Cubed::from_matrix(&w.matrix()).is_ok());
    // a log that fails in one factor fails for the product
    let half_turn_pair = Product::<So3, So3>::new(
        So3::identity(),
        So3::from_matrix(&Matrix3::new(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0)).unwrap(),
    );
    assert!(half_turn_pair.cay_inv().is_err());
}
