//! Control inputs through an input map (`forces::ControlInput`, `forces::BodyInputMap`,
//! `forces::InputMap`) and quadratic drag (`forces::QuadraticDrag`): malformed maps and
//! schedules refused by name; B = I is the body torque, bit for bit; an input map that reads g
//! (a torque fixed in space) moves the spatial momentum map by exactly the applied impulse; the
//! drag's force and power are its formula's.

use integrators::forces::{
    BodyInputMap, BodyTorque, ControlInput, ExternalForce, Forced, InputMap, QuadraticDrag,
    Schedule,
};
use integrators::{Integrator, IntegratorError, LiePoisson};
use lie_groups::{Cayley, LieGroup, Se3, So3};
use mechanics::RigidBody;
use nalgebra::{Vector3, Vector6};

fn schedule3() -> Schedule {
    Schedule::new(
        vec![0.0, 0.5, 1.5],
        vec![
            vec![0.2, -0.1, 0.3],
            vec![0.0, 0.4, -0.2],
            vec![0.1, 0.1, 0.0],
        ],
    )
    .unwrap()
}

#[test]
fn malformed_input_maps_and_schedules_are_refused_by_name() {
    let msg = |e: IntegratorError| e.to_string();
    assert!(msg(BodyInputMap::<So3>::new(vec![]).unwrap_err()).contains("at least one"));
    let nan = BodyInputMap::<So3>::new(vec![Vector3::x(), Vector3::new(0.0, f64::NAN, 0.0)]);
    assert!(msg(nan.unwrap_err()).contains("column 1"));
    assert!(msg(BodyInputMap::<Se3>::components(4, 3).unwrap_err()).contains("4..7"));
    assert!(BodyInputMap::<Se3>::components(0, 0).is_err());
    let map = BodyInputMap::<Se3>::components(0, 3).unwrap();
    let wrong = ControlInput::new(map, Schedule::constant(vec![1.0, 2.0]).unwrap());
    assert!(msg(wrong.unwrap_err()).contains("takes 3 inputs"));
}

/// `B u = Σ uⱼ bⱼ`, and components(i₀, k) picks the basis covectors.
#[test]
fn a_body_input_map_sums_its_columns() {
    let b = BodyInputMap::<Se3>::new(vec![
        Vector6::new(0.0, 0.0, 0.0, 0.0, 0.0, 1.0),
        Vector6::new(0.1, 0.2, 0.3, 0.0, 0.0, 0.0),
    ])
    .unwrap();
    assert_eq!(b.inputs(), 2);
    assert_eq!(
        b.apply(None, &[2.0, -1.0]),
        Vector6::new(-0.1, -0.2, -0.3, 0.0, 0.0, 2.0)
    );
    let c = BodyInputMap::<Se3>::components(3, 2).unwrap();
    assert_eq!(
        c.apply(None, &[5.0, 7.0]),
        Vector6::new(0.0, 0.0, 0.0, 5.0, 7.0, 0.0)
    );
}

/// A control input through B = I is `BodyTorque`: the forced Lie–Poisson runs agree bit for bit.
#[test]
fn identity_input_map_is_the_body_torque() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, -0.3);
    let r0 = So3::exp(&Vector3::new(0.3, -0.5, 0.8));
    let input =
        ControlInput::new(BodyInputMap::<So3>::components(0, 3).unwrap(), schedule3()).unwrap();
    let torque = BodyTorque::<So3>::new(schedule3()).unwrap();
    let mut a =
        LiePoisson::<So3, Cayley, _>::new(Forced::new(body.clone(), input), 0.5, pi0, Some(r0))
            .unwrap();
    let mut b =
        LiePoisson::<So3, Cayley, _>::new(Forced::new(body, torque), 0.5, pi0, Some(r0)).unwrap();
    for _ in 0..300 {
        a.step(0.01).unwrap();
        b.step(0.01).unwrap();
    }
    assert_eq!(a.momentum(), b.momentum());
    assert_eq!(a.configuration(), b.configuration());
}

/// A torque fixed in space, `B(R) τ_s = Rᵀ τ_s`: an input map that reads g.
#[derive(Debug, Clone)]
struct SpatialTorque;

impl InputMap<So3> for SpatialTorque {
    fn inputs(&self) -> usize {
        3
    }
    fn apply(&self, g: Option<&So3>, u: &[f64]) -> Vector3<f64> {
        let r = g.expect("a spatial torque needs the attitude");
        r.as_matrix().tr_mul(&Vector3::new(u[0], u[1], u[2]))
    }
    fn needs_configuration(&self) -> bool {
        true
    }
}

/// The spatial angular momentum RΠ of a body under a constant spatial torque τ_s grows by exactly
/// t τ_s: Lie–Poisson applies the impulse `h R̄ (R̄ᵀτ_s) = h τ_s` per step, so after 1000 steps
/// RΠ = R₀Π₀ + T τ_s to round-off (≤ 1e-13), for every θ. Without g the run is refused.
#[test]
fn an_input_map_that_reads_g_moves_the_momentum_map_by_the_applied_impulse() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, -0.3);
    let r0 = So3::exp(&Vector3::new(0.3, -0.5, 0.8));
    let tau = vec![0.3, -0.2, 0.1];
    let force =
        || ControlInput::new(SpatialTorque, Schedule::constant(tau.clone()).unwrap()).unwrap();
    assert!(force().needs_configuration());
    let refused =
        LiePoisson::<So3, Cayley, _>::new(Forced::new(body.clone(), force()), 0.5, pi0, None);
    assert_eq!(refused.unwrap_err(), IntegratorError::MissingConfiguration);
    for theta in [0.0, 0.5, 1.0] {
        let mut lp = LiePoisson::<So3, Cayley, _>::new(
            Forced::new(body.clone(), force()),
            theta,
            pi0,
            Some(r0),
        )
        .unwrap();
        for _ in 0..1000 {
            lp.step(0.005).unwrap();
        }
        let j = lp.configuration().unwrap().as_matrix() * lp.momentum();
        let want = r0.as_matrix() * pi0 + Vector3::from_vec(tau.clone()) * lp.time();
        println!(
            "spatial torque θ = {theta}: |RΠ − (R₀Π₀ + tτ_s)| = {:.1e}",
            (j - want).amax()
        );
        assert!((j - want).amax() < 1e-13, "θ = {theta}: {j} vs {want}");
    }
}

/// `F_ext(ξ)ᵢ = −dᵢ|ξᵢ|ξᵢ` and its power `−Σ dᵢ|ξᵢ|³`.
#[test]
fn quadratic_drag_is_its_formula_and_dissipates() {
    let d = Vector6::new(0.1, 0.0, 2.0, 1.0, 3.0, 0.5);
    let drag = QuadraticDrag::<Se3>::new(d).unwrap();
    let xi = Vector6::new(0.5, -1.0, -0.3, 2.0, -0.7, 0.0);
    let f = drag.force(0.0, None, &xi);
    let want = Vector6::new(-0.025, 0.0, 0.18, -4.0, 1.47, 0.0);
    assert!((f - want).amax() < 1e-15, "{f} vs {want}");
    let power: f64 = (0..6).map(|i| -d[i] * xi[i].abs().powi(3)).sum();
    assert!((f.dot(&xi) - power).abs() < 1e-15);
    assert!(drag.reads_velocity());
    let e = QuadraticDrag::<Se3>::new(Vector6::new(0.0, 0.0, -1.0, 0.0, 0.0, 0.0)).unwrap_err();
    assert!(e.to_string().contains("d[2]"), "{e}");
}
