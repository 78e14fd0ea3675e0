//! SO(3): the generic suite of `lie_groups::testing` plus SO(3)-specific checks.
//!
//! The suite's `log(exp ξ) = ξ` check needs |ξ| < π; with components uniform in [−s, s],
//! |ξ| ≤ √3 s, so the round-trip suites use s ≤ 1.8 (|ξ| ≤ 3.12). Angles beyond π are covered in
//! `tests/extremes.rs`.

use lie_groups::{Action, Cayley, CayleyGroup, ExpMap, LieGroup, So3};
use nalgebra::{Matrix3, Vector3};

lie_groups::lie_group_suite!(so3_group_small, lie_groups::So3, 0.3);
lie_groups::lie_group_suite!(so3_group, lie_groups::So3, 1.0);
lie_groups::lie_group_suite!(so3_group_large, lie_groups::So3, 1.8);
lie_groups::tau_suite!(so3_exp, lie_groups::So3, lie_groups::ExpMap, 1.0);
lie_groups::tau_suite!(so3_exp_large, lie_groups::So3, lie_groups::ExpMap, 1.8);
lie_groups::tau_suite!(so3_cayley, lie_groups::So3, lie_groups::Cayley, 1.0);
lie_groups::tau_suite!(so3_cayley_large, lie_groups::So3, lie_groups::Cayley, 3.0);
lie_groups::cayley_group_suite!(so3_cayley_closed_forms, lie_groups::So3, 1.0);
lie_groups::cayley_group_suite!(so3_cayley_closed_forms_large, lie_groups::So3, 1.8);

#[test]
fn exp_of_rotation_about_z_is_the_planar_rotation() {
    let t = 0.7f64;
    let r = So3::exp(&Vector3::new(0.0, 0.0, t));
    let expected = Matrix3::new(t.cos(), -t.sin(), 0.0, t.sin(), t.cos(), 0.0, 0.0, 0.0, 1.0);
    assert!((r.matrix() - expected).amax() < 1e-15);
}

#[test]
fn action_rotates_vectors_like_the_matrix_and_hat_is_the_cross_product() {
    let w = Vector3::new(0.3, -1.1, 0.4);
    let p = Vector3::new(1.0, 2.0, -0.5);
    let r = So3::exp(&w);
    assert!((r.act(&p) - r.matrix() * p).amax() < 1e-15);
    assert!((So3::hat(&w) * p - w.cross(&p)).amax() < 1e-15);
    assert_eq!(So3::vee(&So3::hat(&w)), w);
}

#[test]
fn ad_dual_is_mu_cross_xi() {
    // ⟨ad*_ξ μ, η⟩ = ⟨μ, ξ × η⟩ = ⟨μ × ξ, η⟩
    let xi = Vector3::new(0.3, -1.1, 0.4);
    let mu = Vector3::new(1.0, 2.0, -0.5);
    assert!((So3::ad_dual_apply(&xi, &mu) - mu.cross(&xi)).amax() < 1e-15);
    assert!((So3::ad_dual_apply(&xi, &mu) - So3::ad(&xi).transpose() * mu).amax() < 1e-15);
}

#[test]
fn dexp_at_pi_is_finite_and_inverse_blows_up_at_two_pi() {
    let w = Vector3::new(0.0, std::f64::consts::PI, 0.0);
    let j = So3::dexp_left(&w);
    let ji = So3::dexp_left_inv(&w);
    assert!(((j * ji) - Matrix3::identity()).amax() < 1e-14);
    let w2 = Vector3::new(0.0, 2.0 * std::f64::consts::PI, 0.0);
    // 2π is not representable, so sin(θ/2) ≈ 1.2e-16 rather than 0: the inverse is huge, not inf.
    assert!(So3::dexp_left_inv(&w2).amax() > 1e14);
}

#[test]
fn cayley_inverse_is_refused_at_a_half_turn() {
    let r = So3::exp(&Vector3::new(std::f64::consts::PI, 0.0, 0.0));
    assert!(r.cay_inv().is_err());
    let tau_inv = <Cayley as lie_groups::Tau<So3>>::tau_inv(&r);
    assert!(tau_inv.is_err());
    // exp is unaffected
    assert!(<ExpMap as lie_groups::Tau<So3>>::tau_inv(&r).is_ok());
}

// ∂/∂ω (d^{L*}τ_ω μ): the closed forms against central differences of `dtau_left_dual_apply`.

use lie_groups::Tau;
use proptest::prelude::*;

/// Central differences of ξ ↦ d^{L*}τ_ξ μ, column j along the j-th basis vector, step `d`.
/// Error O(d²)·‖third derivative‖ + O(ε/d): with d = 1e-5 and |ξ|, |μ| = O(1), below ~1e-9.
fn fd_dual_derivative<G: LieGroup, T: Tau<G>>(
    xi: &G::Algebra,
    mu: &G::Algebra,
    d: f64,
) -> G::Operator {
    use lie_groups::Vector;
    let n = G::dim();
    lie_groups::matrix_path::operator_from_column_fn::<G>(|j| {
        let e = G::Algebra::basis(n, j);
        let p = T::dtau_left_dual_apply(&xi.axpy(d, &e), mu);
        let m = T::dtau_left_dual_apply(&xi.axpy(-d, &e), mu);
        p.sub(&m).scale(0.5 / d)
    })
}

/// The directions of ω are uniform in the cube; its size is spread over 1e-8 … 2 so that the
/// small-angle series (θ < 0.1 for a, b; θ < 1 for a′, b′) and the closed forms are exercised.
fn omega() -> impl Strategy<Value = Vector3<f64>> {
    (
        prop::array::uniform3(-1.0f64..1.0),
        prop::sample::select(vec![1e-8, 1e-4, 0.03, 0.3, 0.577, 1.0, 2.0]),
    )
        .prop_map(|(v, s)| Vector3::from(v) * s)
}

fn covector() -> impl Strategy<Value = Vector3<f64>> {
    prop::array::uniform3(-2.0f64..2.0).prop_map(Vector3::from)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// The So3 exp closed form is the derivative of d^{L*}exp: |ω| ≤ 2√3 < 2π, |μ| ≤ 2√3, the
    /// central-difference error is ≲ 1e-9; tolerance 1e-8.
    #[test]
    fn so3_exp_dual_derivative_matches_central_differences(w in omega(), mu in covector()) {
        let exact = <ExpMap as Tau<So3>>::dtau_left_dual_derivative(&w, &mu);
        let fd = fd_dual_derivative::<So3, ExpMap>(&w, &mu, 1e-5);
        prop_assert!((exact - fd).amax() < 1e-8, "|ω| = {}: {}", w.norm(), (exact - fd).amax());
    }

    /// Same for Cayley (smooth everywhere on 𝔰𝔬(3)).
    #[test]
    fn so3_cayley_dual_derivative_matches_central_differences(w in omega(), mu in covector()) {
        let exact = <Cayley as Tau<So3>>::dtau_left_dual_derivative(&w, &mu);
        let fd = fd_dual_derivative::<So3, Cayley>(&w, &mu, 1e-5);
        prop_assert!((exact - fd).amax() < 1e-8, "|ω| = {}: {}", w.norm(), (exact - fd).amax());
    }
}

/// At |ω| = 1e-8 both closed forms equal their first-order expansions to full double precision
/// (the O(θ²) remainder is 1e-16 |μ|): no 0/0 in the small-angle branch.
/// exp: `D = −½ μ̂ − (1/6)((ω×μ)^ + ω̂ μ̂) + O(θ²)`; Cayley: `D = −½ μ̂ − ½ μ ωᵀ + O(θ²)`.
#[test]
fn so3_dual_derivatives_at_tiny_angle_match_their_first_order_expansion() {
    let w = Vector3::new(0.6e-8, -0.8e-8, 0.3e-8);
    let mu = Vector3::new(1.5, -0.7, 2.0);
    let hat = |v: &Vector3<f64>| So3::hat(v);
    let exp_expected = -hat(&mu) * 0.5 - (hat(&w.cross(&mu)) + hat(&w) * hat(&mu)) / 6.0;
    let cay_expected = -hat(&mu) * 0.5 - mu * w.transpose() * 0.5;
    let exp = So3::dexp_left_dual_derivative(&w, &mu);
    let cay = So3::dcay_left_dual_derivative(&w, &mu);
    assert!((exp - exp_expected).amax() < 4e-16 * mu.amax());
    assert!((cay - cay_expected).amax() < 4e-16 * mu.amax());
    assert_eq!(
        So3::dexp_left_dual_derivative(&Vector3::zeros(), &mu),
        -hat(&mu) * 0.5
    );
}

/// The series and closed-form branches of the exp derivative agree at the switch θ = 1: just
/// below and just above it (θ = 1 ∓ 1e-15) the operator moves by ~1e-15 |μ| from θ, plus the
/// round-off of either branch (a few ulps of |μ|): < 5e-15 |μ|_max. (A wrong series or closed
/// form would show as a jump of the size of its error.)
#[test]
fn so3_exp_dual_derivative_is_continuous_across_the_small_angle_switch() {
    let dir = Vector3::new(0.6, 0.0, 0.8);
    let mu = Vector3::new(0.4, 1.3, -0.9);
    let below = So3::dexp_left_dual_derivative(&(dir * (1.0 - 1e-15)), &mu);
    let above = So3::dexp_left_dual_derivative(&(dir * (1.0 + 1e-15)), &mu);
    assert!(
        (below - above).amax() < 5e-15 * mu.amax(),
        "{}",
        (below - above).amax()
    );
}

/// `compose_exp(ω)` is `compose(&exp(ω))` bit for bit, on every branch of the exponential (the
/// series below 0.1, the kernels up to π/2 and π, libm beyond, the huge-angle path, NaN).
#[test]
fn compose_exp_is_compose_of_exp_bit_for_bit() {
    let r0 = So3::exp(&Vector3::new(0.4, -1.1, 0.7));
    for w in [
        Vector3::zeros(),
        Vector3::new(1e-9, -2e-9, 3e-10),
        Vector3::new(0.03, -0.02, 0.05),
        Vector3::new(0.4, 0.9, -0.3),
        Vector3::new(1.5, -2.0, 1.0),
        Vector3::new(5.0, 3.0, -4.0),
        Vector3::new(1e200, -3e199, 1e199),
    ] {
        let (a, b) = (r0.compose_exp(&w), r0.compose(&So3::exp(&w)));
        for (x, y) in a.as_matrix().iter().zip(b.as_matrix().iter()) {
            assert_eq!(x.to_bits(), y.to_bits(), "ω = {w:?}");
        }
    }
    let nan = r0.compose_exp(&Vector3::new(f64::NAN, 0.0, 1.0));
    assert!(nan.as_matrix().iter().any(|x| x.is_nan()));
}

/// `rotate_about_body_axis(i, sin α, cos α)` is `R exp(α eᵢ)` for each body axis (and the index is
/// taken mod 3), to round-off.
#[test]
fn rotate_about_body_axis_is_composition_with_the_axis_exponential() {
    let r0 = So3::exp(&nalgebra::Vector3::new(0.4, -1.1, 0.7));
    for i in 0..6 {
        for alpha in [0.0, 1e-9, 0.3, -2.0, 3.1] {
            let mut r = r0;
            r.rotate_about_body_axis(i, f64::sin(alpha), f64::cos(alpha));
            let mut e = nalgebra::Vector3::zeros();
            e[i % 3] = alpha;
            let want = r0.compose(&So3::exp(&e));
            let err = (r.as_matrix() - want.as_matrix()).amax();
            assert!(err < 1e-15, "axis {i}, α = {alpha}: {err:e}");
        }
    }
}

/// Unit direction of a random vector (x when it is too short to have one).
fn direction(v: &Vector3<f64>) -> Vector3<f64> {
    v.try_normalize(1e-3).unwrap_or_else(Vector3::x)
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(24))]

    /// ⊕/⊖ inverse to each other, between, interpolation at constant speed, and every Jacobian
    /// against finite differences, for rotations by π − 10⁻² and π − 10⁻³ (where log, (d^L exp)⁻¹
    /// and the closed forms' branches are at their least accurate but still smooth; the central
    /// differences' step 10⁻⁵ stays clear of the cut locus at π).
    #[test]
    fn operations_and_jacobians_hold_near_pi(
        u in lie_groups::testing::algebra::<So3>(1.0),
        v in lie_groups::testing::algebra::<So3>(1.0),
        w in lie_groups::testing::algebra::<So3>(1.0),
    ) {
        for delta in [1e-2, 1e-3] {
            let r = core::f64::consts::PI - delta;
            let (a, b, c) = (direction(&u) * r, direction(&v) * r, direction(&w) * r);
            lie_groups::testing::check_plus_minus_between_interpolate::<So3>(&a, &b, &c);
            lie_groups::testing::check_jacobians::<So3>(&a, &b, &c);
        }
    }
}
