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
