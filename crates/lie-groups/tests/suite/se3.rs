//! SE(3): the generic suite of `lie_groups::testing` plus SE(3)-specific checks.
//!
//! Algebra ordering ξ = (ω, v). The round-trip suites need |ω| < π: with components uniform in
//! [−s, s], |ω| ≤ √3 s, so they use s ≤ 1.8.

use lie_groups::{Action, CayleyGroup, LieGroup, Se3, So3};
use nalgebra::{Vector3, Vector6};

lie_groups::lie_group_suite!(se3_group_small, lie_groups::Se3, 0.05);
lie_groups::lie_group_suite!(se3_group, lie_groups::Se3, 1.0);
lie_groups::lie_group_suite!(se3_group_large, lie_groups::Se3, 1.8);
lie_groups::tau_suite!(se3_exp, lie_groups::Se3, lie_groups::ExpMap, 1.0);
lie_groups::tau_suite!(se3_exp_large, lie_groups::Se3, lie_groups::ExpMap, 1.8);
lie_groups::tau_suite!(se3_cayley, lie_groups::Se3, lie_groups::Cayley, 1.0);
lie_groups::tau_suite!(se3_cayley_large, lie_groups::Se3, lie_groups::Cayley, 3.0);
lie_groups::cayley_group_suite!(se3_cayley_closed_forms, lie_groups::Se3, 1.0);
lie_groups::cayley_group_suite!(se3_cayley_closed_forms_large, lie_groups::Se3, 1.8);

#[test]
fn algebra_is_ordered_rotation_then_translation() {
    // ξ = (0, v) is a pure translation by v; ξ = (ω, 0) a pure rotation.
    let v = Vector3::new(1.0, -2.0, 3.0);
    let g = Se3::exp(&Vector6::new(0.0, 0.0, 0.0, v.x, v.y, v.z));
    assert_eq!(g.rotation(), &So3::identity());
    assert!((g.translation() - v).amax() < 1e-15);
    let w = Vector3::new(0.1, 0.2, -0.3);
    let h = Se3::exp(&Vector6::new(w.x, w.y, w.z, 0.0, 0.0, 0.0));
    assert!(h.rotation().matrix_distance(&So3::exp(&w)) < 1e-15);
    assert_eq!(h.translation(), &Vector3::zeros());
}

#[test]
fn action_is_rotation_then_translation_and_matches_the_homogeneous_matrix() {
    let g = Se3::exp(&Vector6::new(0.3, -0.2, 0.9, 1.0, 2.0, -1.0));
    let p = Vector3::new(0.5, -1.5, 2.0);
    let q = g.act(&p);
    let hom = g.matrix() * nalgebra::Vector4::new(p.x, p.y, p.z, 1.0);
    assert!((q - hom.xyz()).amax() < 1e-14);
    assert!((q - (g.rotation().as_matrix() * p + g.translation())).amax() < 1e-15);
}

#[test]
fn cayley_translation_solves_the_matrix_cayley_equation() {
    // (I − ξ̂/2) cay(ξ) = I + ξ̂/2, the defining equation of the 4×4 Cayley map.
    let xi = Vector6::new(0.7, -1.2, 0.4, 2.0, -3.0, 0.5);
    let c = Se3::cay(&xi).matrix();
    let h = Se3::hat(&xi) * 0.5;
    let id = nalgebra::Matrix4::identity();
    assert!(((id - h) * c - (id + h)).amax() < 1e-14);
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(24))]

    /// ⊕/⊖ inverse to each other, between, interpolation at constant speed, and every Jacobian
    /// against finite differences, for rigid motions whose rotation angle is π − 10⁻² or
    /// π − 10⁻³ and whose translation part is random (see the SO(3) test of the same name).
    #[test]
    fn operations_and_jacobians_hold_near_pi(
        u in lie_groups::testing::algebra::<Se3>(1.0),
        v in lie_groups::testing::algebra::<Se3>(1.0),
        w in lie_groups::testing::algebra::<Se3>(1.0),
    ) {
        for delta in [1e-2, 1e-3] {
            let r = core::f64::consts::PI - delta;
            let near_pi = |x: &Vector6<f64>| {
                let axis = x.fixed_rows::<3>(0).try_normalize(1e-3).unwrap_or_else(Vector3::x);
                let (w, v) = (axis * r, x.fixed_rows::<3>(3).into_owned());
                Vector6::new(w.x, w.y, w.z, v.x, v.y, v.z)
            };
            let (a, b, c) = (near_pi(&u), near_pi(&v), near_pi(&w));
            lie_groups::testing::check_plus_minus_between_interpolate::<Se3>(&a, &b, &c);
            lie_groups::testing::check_jacobians::<Se3>(&a, &b, &c);
        }
    }
}
