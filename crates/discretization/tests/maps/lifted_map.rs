//! The fused pieces of [`LiftedMap`] that integrators compose with a vector field, checked on every
//! group and τ map against the unfused lifts of `cotangent_lift.rs` and `tangent_lift.rs`
//! (independent code: whole bundle points, matrices of τ, M_θ inverted) and against central
//! differences.

use crate::common::fd_vector;
use discretization::{
    Discretization, DiscretizationError, DiscretizationMap, LiftedMap, ThetaFamily,
};
use lie_groups::testing::assert_small;
use lie_groups::{LieGroup, Operator, Tau, Vector};
use trivial_bundles::prelude::*;

fn map<G: LieGroup, T: Tau<G>>(theta: f64) -> DiscretizationMap<T> {
    DiscretizationMap::<T>::with_theta(theta).expect("θ ∈ [0, 1]")
}

/// base_point, second_point, momentum_update and base_momentum are the components of
/// `(R̃_d^{T*})⁻¹((g_k, μ_k), (g_{k+1}, μ_{k+1})) = (ḡ, μ̄, η, ν)`.
fn check_cotangent_pieces<G: LieGroup, T: Tau<G>>(
    a: &G::Algebra,
    eta: &G::Algebra,
    mu: &G::Algebra,
    nu: &G::Algebra,
    theta: f64,
) {
    let m = map::<G, T>(theta);
    let gk = G::exp(a);
    let gbar = m.base_point(&gk, eta);
    let g1 = m.second_point(&gbar, eta);
    // the fused g_{k+1} from g_k, against the plain product of τ's matrices
    let plain_g1 = gk
        .compose(&T::tau(&eta.scale(theta)))
        .compose(&T::tau(&eta.scale(1.0 - theta)));
    assert_small(
        "next_point = g_k τ(θη) τ((1−θ)η)",
        m.next_point(&gk, eta).matrix_distance(&plain_g1),
        1e-13 * (1.0 + eta.norm()),
    );
    let up = m.momentum_update(eta, mu, Some(nu));
    let bar = m.base_momentum(eta, mu, &up.next);
    let s = 1.0 + eta.norm() + mu.norm() + nu.norm();
    // μ̄ without μ_{k+1} (d^{L*}τ_ζ Ad*_{τ(ζ)} = d^{L*}τ_{−ζ}), with and without an impulse
    assert_small(
        "base_momentum_from_impulse = base_momentum through μ_{k+1}",
        m.base_momentum_from_impulse(eta, mu, Some(nu))
            .sub(&bar)
            .norm_max(),
        1e-13 * s,
    );
    let free = m.base_momentum(eta, mu, &m.momentum_update(eta, mu, None).next);
    assert_small(
        "base_momentum_from_impulse without ν",
        m.base_momentum_from_impulse(eta, mu, None)
            .sub(&free)
            .norm_max(),
        1e-13 * s,
    );
    // the transported momentum, from the matrix of τ
    let plain = T::tau(&eta.scale(theta)).coadjoint_apply(mu);
    assert_small(
        "Ad*_{τ(θη)} μ_k",
        up.transported.sub(&plain).norm_max(),
        1e-13 * s,
    );
    assert_small(
        "μ_k + increment = μ_{k+1}",
        mu.add(&up.increment).sub(&up.next).norm_max(),
        1e-15 * s,
    );
    // the step's increment alone, with and without ν, against the matrices of τ
    let ta = T::tau(&eta.scale(theta));
    let tb = T::tau(&eta.scale(1.0 - theta));
    let with_nu = tb.coadjoint_apply(&ta.coadjoint_apply(mu).add(nu)).sub(mu);
    assert_small(
        "momentum_increment with ν",
        m.momentum_increment(eta, mu, Some(nu))
            .sub(&with_nu)
            .norm_max(),
        1e-13 * s,
    );
    let without = tb.coadjoint_apply(&ta.coadjoint_apply(mu)).sub(mu);
    assert_small(
        "momentum_increment without ν (Tau::tau_split_coadjoint_increment)",
        m.momentum_increment(eta, mu, None).sub(&without).norm_max(),
        1e-13 * s,
    );
    let k = CotangentBundle::from_parts(gk.clone(), mu.clone());
    let k1 = CotangentBundle::from_parts(g1, up.next.clone());
    let x = m
        .cotangent_lift_inverse(&k, &k1)
        .expect("inside the domain");
    assert_small("ḡ", x.g().matrix_distance(&gbar), 1e-12 * s);
    assert_small("η", x.xi().sub(eta).norm_max(), 1e-12 * s);
    assert_small("ν", x.nu().sub(nu).norm_max(), 1e-12 * s);
    assert_small("μ̄", x.mu().sub(&bar).norm_max(), 1e-12 * s);
}

/// `∂μ̄/∂η` against central differences of η ↦ μ̄(η, μ_k, μ_{k+1}(η)) with ν fixed; `exact`
/// where τ has closed forms of ∂(d^{L*}τ_ζ μ)/∂ζ, else only up to O(|η|²).
fn check_momentum_derivative<G: LieGroup, T: Tau<G>>(
    eta: &G::Algebra,
    mu: &G::Algebra,
    nu: &G::Algebra,
    theta: f64,
    exact: bool,
) {
    let m = map::<G, T>(theta);
    let bar = |e: &G::Algebra| m.base_momentum(e, mu, &m.momentum_update(e, mu, Some(nu)).next);
    let d = m.base_momentum_derivative(eta, mu, &m.momentum_update(eta, mu, Some(nu)));
    let s = 1.0 + mu.norm() + nu.norm();
    // Without closed forms D(ζ; μ) is its leading term −½ ad*_(·) μ, exact up to O(|ζ|).
    let tol = if exact {
        1e-8 * s * (1.0 + eta.norm()).powi(3)
    } else {
        0.5 * s * eta.norm() + 1e-8 * s
    };
    for i in 0..G::dim() {
        let dir = G::Algebra::from_fn(G::dim(), |j| if i == j { 1.0 } else { 0.0 });
        let fd = fd_vector(|t| bar(&eta.axpy(t, &dir)));
        assert_small("∂μ̄/∂η", d.apply(&dir).sub(&fd).norm_max(), tol);
    }
}

/// first/second_velocity and the points are the components of `R̃_d^T(ḡ, ξ, η, ζ)`; the
/// derivative of ξ ↦ first_velocity(hξ, ξ, hKξ) is `A + B hK`.
fn check_tangent_pieces<G: LieGroup, T: Tau<G>>(
    a: &G::Algebra,
    xi: &G::Algebra,
    zeta: &G::Algebra,
    c: &G::Algebra,
    theta: f64,
    exact_tangent: bool,
) {
    let m = map::<G, T>(theta);
    let h = 0.3;
    let eta = xi.scale(h);
    let gbar = G::exp(a);
    let (k, k1) = m.tangent_lift(&Ttg::new(
        gbar.clone(),
        xi.clone(),
        eta.clone(),
        zeta.clone(),
    ));
    let s = 1.0 + xi.norm() + zeta.norm();
    assert_small(
        "base_point(g_k, η) = ḡ",
        m.base_point(k.base(), &eta).matrix_distance(&gbar),
        1e-12 * s,
    );
    assert_small(
        "second_point",
        m.second_point(&gbar, &eta).matrix_distance(k1.base()),
        1e-12 * s,
    );
    assert_small(
        "ξ_k",
        m.first_velocity(&eta, xi, zeta).sub(k.fiber()).norm_max(),
        1e-12 * s,
    );
    assert_small(
        "ξ_{k+1}",
        m.second_velocity(&eta, xi, zeta).sub(k1.fiber()).norm_max(),
        1e-12 * s,
    );
    // the increment forms: the same velocities less ξ
    assert_small(
        "ξ + first_velocity_increment = ξ_k",
        xi.add(&m.first_velocity_increment(h, xi, zeta))
            .sub(k.fiber())
            .norm_max(),
        1e-12 * s,
    );
    assert_small(
        "ξ + second_velocity_increment = ξ_{k+1}",
        xi.add(&m.second_velocity_increment(h, xi, zeta))
            .sub(k1.fiber())
            .norm_max(),
        1e-12 * s,
    );
    // ζ ≡ 0 and ζ = hKξ: A(ξ, ζ(ξ)) + B hK, exact where τ's second derivative E is (else up to
    // O(h|hξ||ζ|), h = 0.3 here).
    let kop = G::ad(c);
    for k in [0.0, 1.0] {
        let zeta_of = |x: &G::Algebra| kop.apply(x).scale(h * k);
        let (da, db) = m.first_velocity_derivative(h, xi, &zeta_of(xi));
        let exact = 1e-8 * s * (1.0 + xi.norm()).powi(3) * (1.0 + c.norm());
        let tol = if exact_tangent || k == 0.0 {
            exact
        } else {
            exact + 2.0 * h * h * c.norm() * xi.norm() * (1.0 + xi.norm())
        };
        let f = |x: &G::Algebra| m.first_velocity(&x.scale(h), x, &zeta_of(x));
        let d = da.add(&db.compose(&kop).scale(h * k));
        for i in 0..G::dim() {
            let dir = G::Algebra::from_fn(G::dim(), |j| if i == j { 1.0 } else { 0.0 });
            let fd = fd_vector(|t| f(&xi.axpy(t, &dir)));
            assert_small("∂ξ_k/∂ξ", d.apply(&dir).sub(&fd).norm_max(), tol);
        }
    }
}

/// The velocity increments keep their accuracy relative to their own size at small steps: at
/// η = hξ with |η| = 1e-8 and |ζ| = 1e-8 (ζ of the size of h f) they are within
/// 1e-13 (|η||ξ| + |ζ|) of the series `ξ_k − ξ = θ ad_η ξ + ½θ² ad_η² ξ − θ(ζ + ½θ ad_η ζ)`,
/// `ξ_{k+1} − ξ = −(1−θ) ad_η ξ + ½(1−θ)² ad_η² ξ + (1−θ)(ζ − ½(1−θ) ad_η ζ)` (from
/// `Ad_{τ(x)} = I + ad_x + ½ad_x² + O(x³)` and `d^Lτ_x = I − ½ad_x + O(x²)` for both τ; the
/// dropped terms are 1e-16 of the size there; the ad_η ξ terms vanish along η = hξ). The whole
/// velocities less ξ round at ε|ξ|, 1e-8 of the size.
fn check_velocity_increments_at_small_steps<G: LieGroup, T: Tau<G>>(
    xi: &G::Algebra,
    zdir: &G::Algebra,
    theta: f64,
) {
    let m = map::<G, T>(theta);
    let unit = |v: &G::Algebra| {
        let n = v.norm_max();
        if n == 0.0 {
            v.clone()
        } else {
            v.scale(1e-8 / n)
        }
    };
    let h = 1e-8 / xi.norm_max().max(f64::MIN_POSITIVE);
    let (eta, zeta) = (xi.scale(h), unit(zdir));
    let ad = |x: &G::Algebra| G::bracket(&eta, x);
    let b = 1.0 - theta;
    let first = ad(xi)
        .scale(theta)
        .axpy(0.5 * theta * theta, &ad(&ad(xi)))
        .sub(&zeta.axpy(0.5 * theta, &ad(&zeta)).scale(theta));
    let second = ad(xi)
        .scale(-b)
        .axpy(0.5 * b * b, &ad(&ad(xi)))
        .add(&zeta.axpy(-0.5 * b, &ad(&zeta)).scale(b));
    let size = eta.norm_max() * xi.norm_max() + zeta.norm_max();
    assert_small(
        "first_velocity_increment at |η| = 1e-8",
        m.first_velocity_increment(h, xi, &zeta)
            .sub(&first)
            .norm_max(),
        1e-13 * size,
    );
    assert_small(
        "second_velocity_increment at |η| = 1e-8",
        m.second_velocity_increment(h, xi, &zeta)
            .sub(&second)
            .norm_max(),
        1e-13 * size,
    );
}

/// A τ map on SO(3) that does not commute with its argument: `τ(ξ) = k(ξ) exp(ξ) k(ξ)⁻¹` with
/// `k(ξ) = exp(|ξ|² a)`, a fixed (k even and k(0) = e, so τ(0) = e, dτ₀ = id and
/// τ(ξ)τ(−ξ) = e hold), but `Ad_{τ(ξ)} ξ = Ad_k Ad_{exp ξ} Ad_{k⁻¹} ξ ≠ ξ`: the maps' general path,
/// which forms `(Ad_{τ(sη)} − I) ξ` (`Tau::tau_adjoint_increment`, its provided matrix form here)
/// and the transport term of the derivative. Its tangent is central differences of τ, its inverse
/// `d^Lτ_ξ = Ad_k ((Ad_{exp(−ξ)} − I) 2aξᵀ + d^L exp_ξ)` (from τ⁻¹dτ with k⁻¹dk = 2(ξ·δ) a; checked
/// against central differences below), its inverse a fixed-point iteration ξ = log(k(ξ)⁻¹ g k(ξ)).
#[derive(Debug, Clone, Copy, Default)]
struct Conjugated;

impl Conjugated {
    const A: [f64; 3] = [0.3, -0.2, 0.5];
    fn k(xi: &nalgebra::Vector3<f64>) -> So3 {
        So3::exp(&(nalgebra::Vector3::from(Self::A) * xi.norm_squared()))
    }
}

impl Tau<So3> for Conjugated {
    const NAME: &'static str = "conjugated-exp";
    fn tau(xi: &nalgebra::Vector3<f64>) -> So3 {
        let k = Self::k(xi);
        k.compose(&So3::exp(xi)).compose(&k.inverse())
    }
    fn tau_inv(g: &So3) -> Result<nalgebra::Vector3<f64>, lie_groups::LieError> {
        let mut xi = g.log()?;
        for _ in 0..60 {
            let k = Self::k(&xi);
            xi = k.inverse().compose(g).compose(&k).log()?;
        }
        Ok(xi)
    }
    fn dtau_left(xi: &nalgebra::Vector3<f64>) -> nalgebra::Matrix3<f64> {
        let a = nalgebra::Vector3::from(Self::A);
        let back = So3::exp(&-xi).adjoint() - nalgebra::Matrix3::identity();
        Self::k(xi).adjoint() * (back * (a * 2.0) * xi.transpose() + So3::dexp_left(xi))
    }
    fn dtau_left_inv(xi: &nalgebra::Vector3<f64>) -> nalgebra::Matrix3<f64> {
        Self::dtau_left(xi)
            .try_inverse()
            .expect("d^Lτ invertible near 0")
    }
}

/// The general path, on the non-commuting τ: the increments are the whole velocities less ξ
/// along η = hξ (1e-14 of their size; here the Ad terms are not zero), and the
/// derivative A at ζ = 0, `Ad_{τ(aξ)}(I − a ad_ξ d^Lτ_{aξ})`, matches central differences of
/// ξ ↦ first_velocity(hξ, ξ, 0) (which only applies τ's matrix) to 1e-7, every θ.
fn check_general_path(xi: &nalgebra::Vector3<f64>, zeta: &nalgebra::Vector3<f64>, theta: f64) {
    let m = map::<So3, Conjugated>(theta);
    assert_small(
        "d^Lτ of the conjugated exp = central differences",
        (Conjugated::dtau_left(xi) - lie_groups::testing::fd_left::<So3>(Conjugated::tau, xi))
            .amax(),
        1e-8,
    );
    let h = 0.3;
    let eta = xi.scale(h);
    let size = h * xi.amax() * xi.amax() + zeta.amax();
    let first = m.first_velocity(&eta, xi, zeta) - xi;
    let second = m.second_velocity(&eta, xi, zeta) - xi;
    assert_small(
        "first_velocity_increment, τ not commuting",
        (m.first_velocity_increment(h, xi, zeta) - first).amax(),
        1e-14 * size,
    );
    assert_small(
        "second_velocity_increment, τ not commuting",
        (m.second_velocity_increment(h, xi, zeta) - second).amax(),
        1e-14 * size,
    );
    // the Ad term is there to be tested: first with ζ = 0 is (Ad_{τ(θhξ)} − I) ξ alone, 1e5
    // times the tolerance above at least
    let zero = nalgebra::Vector3::zeros();
    let transported = m.first_velocity_increment(h, xi, &zero).amax();
    if theta > 0.2 && xi.amax() > 0.3 {
        assert!(
            transported > 1e-9 * xi.amax(),
            "the Ad term vanishes ({transported:e}): the test would not see it"
        );
    }
    let (a, _) = m.first_velocity_derivative(h, xi, &zero);
    for i in 0..3 {
        let dir = nalgebra::Vector3::from_fn(|j, _| if i == j { 1.0 } else { 0.0 });
        let fd = fd_vector(|t| {
            let x = xi.axpy(t, &dir);
            m.first_velocity(&x.scale(h), &x, &zero)
        });
        assert_small("A, τ not commuting", (a * dir - fd).amax(), 1e-7);
    }
}

macro_rules! lifted_map_suite {
    ($name:ident, $G:ty, $T:ty, $exact:expr, $exact_tangent:expr) => {
        mod $name {
            use super::*;
            use lie_groups::testing::algebra;
            use proptest::prelude::*;
            type G = $G;

            fn theta() -> impl Strategy<Value = f64> {
                prop_oneof![Just(0.0), Just(0.5), Just(1.0), 0.0..1.0f64]
            }

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(24))]
                #[test]
                fn cotangent_pieces_are_the_inverse_cotangent_lift(a in algebra::<G>(1.0), eta in algebra::<G>(0.5), mu in algebra::<G>(1.0), nu in algebra::<G>(0.3), th in theta()) {
                    check_cotangent_pieces::<G, $T>(&a, &eta, &mu, &nu, th);
                }
                #[test]
                fn base_momentum_derivative_matches_finite_differences(eta in algebra::<G>(if $exact { 0.5 } else { 0.05 }), mu in algebra::<G>(1.0), nu in algebra::<G>(0.3), th in theta()) {
                    check_momentum_derivative::<G, $T>(&eta, &mu, &nu, th, $exact);
                }
                #[test]
                fn tangent_pieces_are_the_tangent_lift(a in algebra::<G>(1.0), xi in algebra::<G>(1.0), zeta in algebra::<G>(0.3), c in algebra::<G>(1.0), th in theta()) {
                    check_tangent_pieces::<G, $T>(&a, &xi, &zeta, &c, th, $exact_tangent);
                }
            }
        }
    };
}

use lie_groups::{Cayley, ExpMap, Se2, Se3, So3, SoN};
proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(24))]
    #[test]
    fn the_general_path_forms_the_ad_terms_of_a_non_commuting_tau(
        w in lie_groups::testing::algebra::<So3>(1.0),
        u in lie_groups::testing::algebra::<So3>(0.3),
        th in proptest::prop_oneof![proptest::prelude::Just(0.0), proptest::prelude::Just(0.5), proptest::prelude::Just(1.0), 0.0..1.0f64],
    ) {
        check_general_path(&w, &u, th);
    }
}

// (name, group, τ, ∂μ̄/∂η checked as exact at large η, E τ exact: the Euler–Poincaré derivative)
lifted_map_suite!(so3_exp, So3, ExpMap, true, true);
lifted_map_suite!(so3_cayley, So3, Cayley, true, true);
lifted_map_suite!(se3_exp, Se3, ExpMap, false, true);
lifted_map_suite!(se3_cayley, Se3, Cayley, false, true);
lifted_map_suite!(se2_exp, Se2, ExpMap, false, true);
lifted_map_suite!(se2_cayley, Se2, Cayley, false, true);
lifted_map_suite!(so4_exp, SoN<4>, ExpMap, false, true);
lifted_map_suite!(so4_cayley, SoN<4>, Cayley, false, false);

/// [`check_velocity_increments_at_small_steps`] where τ has closed-form adjoint increments
/// (`Tau::tau_adjoint_increment`; SO(4) has only the matrix form, rounded at ε|ξ|).
macro_rules! increment_suite {
    ($name:ident, $G:ty, $T:ty) => {
        mod $name {
            use super::*;
            use lie_groups::testing::algebra;
            use proptest::prelude::*;
            type G = $G;
            proptest! {
                #![proptest_config(ProptestConfig::with_cases(48))]
                #[test]
                fn velocity_increments_keep_their_relative_accuracy_at_small_steps(xi in algebra::<G>(2.0), zeta in algebra::<G>(1.0), th in prop_oneof![Just(0.0), Just(0.5), Just(1.0), 0.0..1.0f64]) {
                    check_velocity_increments_at_small_steps::<G, $T>(&xi, &zeta, th);
                }
            }
        }
    };
}

increment_suite!(so3_exp_increments, So3, ExpMap);
increment_suite!(so3_cayley_increments, So3, Cayley);
increment_suite!(se3_exp_increments, Se3, ExpMap);
increment_suite!(se3_cayley_increments, Se3, Cayley);
increment_suite!(se2_exp_increments, Se2, ExpMap);
increment_suite!(se2_cayley_increments, Se2, Cayley);

/// SO(3)'s one-product `g cay(θη) cay((1−θ)η) = g cay(η/(1 − θ(1−θ)|η|²/4))`, and the one
/// coadjoint increment of the same element, on both sides of the switch to two factors
/// (denominator ½): total angles up to and beyond a half turn, every θ.
#[test]
fn so3_cayley_split_compose_is_the_product_of_the_two_factors() {
    use lie_groups::{CayleyGroup, So3};
    use nalgebra::Vector3;
    let g = So3::exp(&Vector3::new(0.4, -1.1, 0.7));
    let axis = Vector3::new(0.3, -0.5, 0.8).normalize();
    for theta in [0.0, 0.2, 0.5, 0.9, 1.0] {
        for size in [0.0, 1e-9, 0.01, 1.0, 2.5, 2.9, 3.0, 4.0, 7.0, 40.0] {
            let w = axis * size;
            let two = g
                .compose(&So3::cay(&(w * theta)))
                .compose(&So3::cay(&(w * (1.0 - theta))));
            let one = So3::cay_split_compose(&g, theta, &w);
            assert_small(
                &format!("θ = {theta}, |η| = {size}"),
                one.matrix_distance(&two),
                2e-15 * (1.0 + size),
            );
            // the coadjoint counterpart, on the same switch
            let mu = Vector3::new(0.7, -0.2, 1.3);
            let plain = So3::cay(&(w * (1.0 - theta)))
                .coadjoint_apply(&So3::cay(&(w * theta)).coadjoint_apply(&mu))
                - mu;
            assert_small(
                &format!("increment: θ = {theta}, |η| = {size}"),
                (So3::cay_split_coadjoint_increment(theta, &w, &mu) - plain).amax(),
                4e-15 * (1.0 + size),
            );
        }
    }
}

/// The domain check: exp on SO(3) inverts below a half turn only; NaN is outside.
#[test]
fn check_domain_refuses_steps_tau_cannot_invert() {
    use nalgebra::Vector3;
    let m = map::<So3, ExpMap>(0.5);
    assert!(Discretization::<So3>::check_domain(&m, &Vector3::new(0.3, -1.0, 2.0)).is_ok());
    let far = Vector3::new(0.0, 0.0, 3.5);
    assert!(matches!(
        Discretization::<So3>::check_domain(&m, &far),
        Err(DiscretizationError::OutsideTauDomain { tau: "exp", .. })
    ));
    let nan = Vector3::new(f64::NAN, 0.0, 0.0);
    assert!(Discretization::<So3>::check_domain(&m, &nan).is_err());
    assert!(DiscretizationMap::<Cayley>::with_theta(1.5).is_err());
    assert_eq!(
        Discretization::<So3>::label(&map::<So3, Cayley>(0.0)),
        "tau=cayley"
    );
}
