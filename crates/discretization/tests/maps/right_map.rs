//! The right-trivialized discretization map `R̃_d^R(g, ξ) = (τ(−θξ) g, τ((1−θ)ξ) g)`: the axioms of
//! a discretization map in the right trivialization, its inverse, its points, the right momentum
//! map `Ad*_g μ` kept exactly by the momentum update, and ∂μ̄/∂η against central differences —
//! on SO(3), SE(3), SE(2) and SO(4), τ = exp and Cayley, several θ.

use crate::common::fd_vector;
use discretization::{Discretization, LiftedMap, RightDiscretizationMap, Side, ThetaFamily};
use lie_groups::testing::{algebra, assert_small};
use lie_groups::{
    Cayley, DenseMatrix, ExpMap, LieGroup, Operator, Se2, Se3, So3, SoN, Tau, Vector,
};
use proptest::prelude::*;

fn map<G: LieGroup, T: Tau<G>>(theta: f64) -> RightDiscretizationMap<T> {
    RightDiscretizationMap::<T>::with_theta(theta).expect("θ ∈ [0, 1]")
}

/// Axioms: `R̃_d^R(g, 0) = (g, g)` and `d/dt [R²(tξ) − R¹(tξ)]_{t=0} = ξ̂ g` (the right-trivialized
/// tangent vector ξ at g); the inverse recovers (g, ξ); base/second/next points agree with `apply`.
fn check_map<G: LieGroup, T: Tau<G>>(a: &G::Algebra, xi: &G::Algebra, theta: f64) {
    let m = map::<G, T>(theta);
    let g = G::exp(a);
    let (r1, r2) = m.apply(&g, &G::Algebra::zeros(G::dim()));
    assert_small("R(g, 0)₁ = g", r1.matrix_distance(&g), 1e-15);
    assert_small("R(g, 0)₂ = g", r2.matrix_distance(&g), 1e-15);
    let d = 1e-6;
    let curve = |t: f64| {
        let (p, q) = m.apply(&g, &xi.scale(t));
        q.matrix().to_mat() - p.matrix().to_mat()
    };
    let derivative = (curve(d) - curve(-d)) * faer::Scale(0.5 / d);
    let want = G::hat(xi).to_mat() * g.matrix().to_mat();
    let off = lie_groups::matrix::dense::max_abs_diff(derivative.as_ref(), want.as_ref());
    assert_small("d/dt (R² − R¹) = ξ̂ g", off, 1e-8 * (1.0 + xi.norm()));
    let (gk, gk1) = m.apply(&g, xi);
    let (gbar, back) = m.inverse(&gk, &gk1).expect("inside the domain");
    let s = 1.0 + xi.norm();
    assert_small("inverse: ξ", back.sub(xi).norm_max(), 1e-11 * s);
    assert_small("inverse: g", gbar.matrix_distance(&g), 1e-11 * s);
    let base = m.base_point(&gk, xi);
    assert_small("base point", base.matrix_distance(&g), 1e-13 * s);
    assert_small(
        "second point",
        m.second_point(&base, xi).matrix_distance(&gk1),
        1e-13 * s,
    );
    assert_small(
        "next point",
        m.next_point(&gk, xi).matrix_distance(&gk1),
        1e-13 * s,
    );
    assert_eq!(Discretization::<G>::side(&m), Side::Right);
}

/// For any η the step `μ_{k+1} = momentum_update(η, μ_k).next`, `g_{k+1} = next_point(g_k, η)`
/// keeps the right momentum map `Ad*_g μ` (the conserved quantity of a right-invariant system).
fn check_momentum_map<G: LieGroup, T: Tau<G>>(
    a: &G::Algebra,
    eta: &G::Algebra,
    mu: &G::Algebra,
    theta: f64,
) {
    let m = map::<G, T>(theta);
    let gk = G::exp(a);
    let mu1 = m.momentum_update(eta, mu, None).next;
    let g1 = m.next_point(&gk, eta);
    let before = gk.coadjoint_apply(mu);
    let after = g1.coadjoint_apply(&mu1);
    assert_small(
        "Ad*_{g_{k+1}} μ_{k+1} = Ad*_{g_k} μ_k",
        after.sub(&before).norm_max(),
        1e-13 * (1.0 + mu.norm()) * (1.0 + a.norm()).powi(2),
    );
}

/// The velocity increments are the right map's velocities less ξ at η = hξ (the left map's at
/// −h).
fn check_velocity_increments<G: LieGroup, T: Tau<G>>(
    xi: &G::Algebra,
    zeta: &G::Algebra,
    theta: f64,
) {
    let m = map::<G, T>(theta);
    let h = 0.3;
    let eta = xi.scale(h);
    let s = 1.0 + xi.norm() + zeta.norm();
    assert_small(
        "ξ + first_velocity_increment = first_velocity",
        xi.add(&m.first_velocity_increment(h, xi, zeta))
            .sub(&m.first_velocity(&eta, xi, zeta))
            .norm_max(),
        1e-14 * s,
    );
    assert_small(
        "ξ + second_velocity_increment = second_velocity",
        xi.add(&m.second_velocity_increment(h, xi, zeta))
            .sub(&m.second_velocity(&eta, xi, zeta))
            .norm_max(),
        1e-14 * s,
    );
}

/// ∂μ̄/∂η against central differences (exact on SO(3), O(|η|) elsewhere, as for the left map).
fn check_derivative<G: LieGroup, T: Tau<G>>(
    eta: &G::Algebra,
    mu: &G::Algebra,
    theta: f64,
    exact: bool,
) {
    let m = map::<G, T>(theta);
    let bar = |e: &G::Algebra| m.base_momentum(e, mu, &m.momentum_update(e, mu, None).next);
    let d = m.base_momentum_derivative(eta, mu, &m.momentum_update(eta, mu, None));
    let s = 1.0 + mu.norm();
    let tol = if exact {
        1e-8 * s * (1.0 + eta.norm()).powi(3)
    } else {
        0.5 * s * eta.norm() + 1e-8 * s
    };
    for j in 0..G::dim() {
        let e = G::Algebra::basis(G::dim(), j);
        let fd = fd_vector(|t| bar(&eta.axpy(t, &e)));
        assert_small(
            &format!("∂μ̄/∂η column {j}"),
            d.apply(&e).sub(&fd).norm_max(),
            tol,
        );
    }
}

macro_rules! right_map_suite {
    ($name:ident, $G:ty, $T:ty, $exact:expr) => {
        mod $name {
            use super::*;
            type G = $G;
            fn theta() -> impl Strategy<Value = f64> {
                prop_oneof![Just(0.0), Just(0.5), Just(1.0), 0.0..1.0f64]
            }
            proptest! {
                #![proptest_config(ProptestConfig::with_cases(24))]
                #[test]
                fn axioms_inverse_and_points(a in algebra::<G>(1.0), xi in algebra::<G>(0.5), th in theta()) {
                    check_map::<G, $T>(&a, &xi, th);
                }
                #[test]
                fn the_update_keeps_the_right_momentum_map(a in algebra::<G>(1.0), eta in algebra::<G>(0.5), mu in algebra::<G>(1.0), th in theta()) {
                    check_momentum_map::<G, $T>(&a, &eta, &mu, th);
                }
                #[test]
                fn velocity_increments_are_the_velocities_less_xi(xi in algebra::<G>(1.5), zeta in algebra::<G>(0.3), th in theta()) {
                    check_velocity_increments::<G, $T>(&xi, &zeta, th);
                }
                #[test]
                fn base_momentum_derivative_matches_finite_differences(eta in algebra::<G>(if $exact { 0.5 } else { 0.05 }), mu in algebra::<G>(1.0), th in theta()) {
                    check_derivative::<G, $T>(&eta, &mu, th, $exact);
                }
            }
        }
    };
}

right_map_suite!(so3_exp, So3, ExpMap, true);
right_map_suite!(so3_cayley, So3, Cayley, true);
right_map_suite!(se3_cayley, Se3, Cayley, false);
right_map_suite!(se2_exp, Se2, ExpMap, false);
right_map_suite!(so4_cayley, SoN<4>, Cayley, false);
