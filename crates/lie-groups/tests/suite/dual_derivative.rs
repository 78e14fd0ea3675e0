//! `D τ(ξ; μ) = ∂/∂ξ (d^{L*}τ_ξ μ)`, the second derivative of τ that Newton's matrix for the
//! Lie–Poisson step needs, exact on every group: the provided series for τ = exp (SE(3), SE(2),
//! SO(4), products) and the closed forms of Cayley on SE(3) and SE(2), against central
//! differences of the (independently tested) d^{L*}τ_ξ μ, and the series against So3's closed
//! form.

use lie_groups::testing::proptest::prelude::*;
use lie_groups::testing::{algebra, assert_small};
#[cfg(feature = "faer")]
use lie_groups::SoN;
use lie_groups::{
    dexp_dual_derivative_series, Cayley, ExpMap, LieGroup, Operator, Product, Rn, Se2, Se3, So3,
    Tau, Vector,
};

/// Central differences of ξ ↦ d^{L*}τ_ξ μ along each basis vector, step d: error
/// O(d²)‖∂³‖ + O(ε/d), ≲ 1e-9 for |ξ|, |μ| = O(1) at d = 1e-5.
fn fd<G: LieGroup, T: Tau<G>>(xi: &G::Algebra, mu: &G::Algebra) -> G::Operator {
    let (n, d) = (G::dim(), 1e-5);
    lie_groups::matrix_path::operator_from_column_fn::<G>(|j| {
        let e = G::Algebra::basis(n, j);
        let p = T::dtau_left_dual_apply(&xi.axpy(d, &e), mu);
        let m = T::dtau_left_dual_apply(&xi.axpy(-d, &e), mu);
        p.sub(&m).scale(0.5 / d)
    })
}

fn check<G: LieGroup, T: Tau<G>>(xi: &G::Algebra, mu: &G::Algebra) {
    let exact = T::dtau_left_dual_derivative(xi, mu);
    let off = exact.add(&fd::<G, T>(xi, mu).scale(-1.0)).norm_max();
    let scale = 1.0 + mu.norm_max() * (1.0 + xi.norm_max());
    assert_small(
        &format!("D {} on {} at |ξ| = {:.2}", T::NAME, G::name(), xi.norm()),
        off,
        1e-8 * scale,
    );
}

/// Central differences of ξ ↦ d^Lτ_ξ v (the tangent itself, independently tested against
/// finite differences of τ by the τ suite).
fn fd_tangent<G: LieGroup, T: Tau<G>>(xi: &G::Algebra, v: &G::Algebra) -> G::Operator {
    let (n, d) = (G::dim(), 1e-5);
    lie_groups::matrix_path::operator_from_column_fn::<G>(|j| {
        let e = G::Algebra::basis(n, j);
        let p = T::dtau_left(&xi.axpy(d, &e)).apply(v);
        let m = T::dtau_left(&xi.axpy(-d, &e)).apply(v);
        p.sub(&m).scale(0.5 / d)
    })
}

/// `E τ(ξ; v) = ∂/∂ξ (d^Lτ_ξ v)` (from D by duality) against central differences of d^Lτ_ξ v;
/// at ξ = 0 it is `½ ad_v`.
fn check_tangent_derivative<G: LieGroup, T: Tau<G>>(xi: &G::Algebra, v: &G::Algebra) {
    let e = T::dtau_left_derivative(xi, v);
    let off = e.add(&fd_tangent::<G, T>(xi, v).scale(-1.0)).norm_max();
    let scale = 1.0 + v.norm_max() * (1.0 + xi.norm_max());
    assert_small(
        &format!("E {} on {} at |ξ| = {:.2}", T::NAME, G::name(), xi.norm()),
        off,
        1e-8 * scale,
    );
    let zero = G::Algebra::zeros(G::dim());
    assert_small(
        "E(0; v) = ½ ad_v",
        T::dtau_left_derivative(&zero, v)
            .add(&G::ad(v).scale(-0.5))
            .norm_max(),
        1e-15 * (1.0 + v.norm_max()),
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn tangent_derivative_is_exact_where_d_is(xi in algebra::<Se3>(1.5), v in algebra::<Se3>(2.0), w in algebra::<So3>(2.5), u in algebra::<So3>(2.0), p in algebra::<Se2>(2.0), q in algebra::<Se2>(2.0)) {
        check_tangent_derivative::<Se3, ExpMap>(&xi, &v);
        check_tangent_derivative::<Se3, Cayley>(&xi, &v);
        check_tangent_derivative::<So3, ExpMap>(&w, &u);
        check_tangent_derivative::<So3, Cayley>(&w, &u);
        check_tangent_derivative::<Se2, ExpMap>(&p, &q);
        check_tangent_derivative::<Se2, Cayley>(&p, &q);
    }

    #[cfg(feature = "faer")]
    #[test]
    fn so4_exp_tangent_derivative_is_exact(xi in algebra::<SoN<4>>(1.5), v in algebra::<SoN<4>>(2.0)) {
        check_tangent_derivative::<SoN<4>, ExpMap>(&xi, &v);
    }

    #[test]
    fn se3_exact(xi in algebra::<Se3>(1.5), mu in algebra::<Se3>(2.0)) {
        check::<Se3, ExpMap>(&xi, &mu);
        check::<Se3, Cayley>(&xi, &mu);
    }

    #[test]
    fn se2_exact(xi in algebra::<Se2>(2.0), mu in algebra::<Se2>(2.0)) {
        check::<Se2, ExpMap>(&xi, &mu);
        check::<Se2, Cayley>(&xi, &mu);
    }

    #[cfg(feature = "faer")]
    #[test]
    fn so4_exp_exact(xi in algebra::<SoN<4>>(1.5), mu in algebra::<SoN<4>>(2.0)) {
        check::<SoN<4>, ExpMap>(&xi, &mu);
    }

    #[test]
    fn product_exp_exact(xi in algebra::<Product<Se2, Rn<2>>>(1.5), mu in algebra::<Product<Se2, Rn<2>>>(2.0)) {
        check::<Product<Se2, Rn<2>>, ExpMap>(&xi, &mu);
    }

    /// The series equals So3's closed form (independent derivations) to round-off, at
    /// |ω| up to 3.
    #[test]
    fn series_is_so3s_closed_form(xi in algebra::<So3>(1.7), mu in algebra::<So3>(2.0)) {
        let series = dexp_dual_derivative_series::<So3>(&xi, &mu);
        let closed = So3::dexp_left_dual_derivative(&xi, &mu);
        assert_small("series − closed form", (series - closed).amax(), 1e-14 * (1.0 + mu.amax()));
    }
}

/// At ξ = 0 the derivative is `−½ M(μ)`, `M(μ): δ ↦ ad*_δ μ`, for both τ; at huge steps
/// (|ξ| = 12, where the series needs its most terms) the series stays finite and accurate.
#[test]
fn at_zero_and_at_large_steps() {
    let mu = nalgebra::Vector6::new(0.3, -1.2, 0.8, 2.0, -0.4, 1.1);
    let zero = nalgebra::Vector6::zeros();
    let half = Se3::ad_dual_operator(&mu) * -0.5;
    for d in [
        Se3::dexp_left_dual_derivative(&zero, &mu),
        <Cayley as Tau<Se3>>::dtau_left_dual_derivative(&zero, &mu),
    ] {
        assert_small("D(0; μ) = −½ M(μ)", (d - half).amax(), 1e-16);
    }
    let big = nalgebra::Vector6::new(7.0, -6.0, 8.0, 3.0, 5.0, -4.0);
    check::<Se3, ExpMap>(&big, &mu);
    check::<Se3, Cayley>(&big, &mu);
}
