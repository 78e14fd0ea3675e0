//! `System::diagonal_velocity`: the systems that declare a diagonal quadratic Hamiltonian keep
//! `∂h/∂μ(μ) = a ∘ μ` bitwise, the others declare nothing, and the explicit baselines' fast path
//! (Ω = a ∘ Π in every stage, the system's shape tested once per step) steps bit for bit as the
//! general path through `System::velocity`.

use integrators::baselines::{QuaternionRk4, Rkmk4};
use integrators::forces::{BodyTorque, Forced};
use integrators::{Integrator, System};
use lie_groups::{LieGroup, So3};
use mechanics::systems::{HeavyTop, RigidBody};
use nalgebra::{Matrix3, Vector3};

/// A system seen through its general interface only: every method delegates, except
/// `diagonal_velocity`, which keeps the provided `None`.
struct Hidden<S>(S);

impl<S: System<So3>> System<So3> for Hidden<S> {
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.0.hamiltonian(mu)
    }
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.0.velocity(mu)
    }
    fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
        self.0.hessian(mu)
    }
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.0.momentum(xi)
    }
    fn has_potential(&self) -> bool {
        self.0.has_potential()
    }
    fn potential(&self, g: &So3) -> f64 {
        self.0.potential(g)
    }
    fn potential_differential(&self, g: &So3) -> Vector3<f64> {
        self.0.potential_differential(g)
    }
    fn needs_configuration(&self) -> bool {
        self.0.needs_configuration()
    }
    fn casimir(&self, mu: &Vector3<f64>) -> Option<f64> {
        self.0.casimir(mu)
    }
}

fn top() -> HeavyTop {
    HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 1.0, Vector3::new(0.0, 0.1, 0.5)).unwrap()
}

/// Momenta over 300 orders of magnitude, signed zeros and subnormals included.
fn momenta() -> Vec<Vector3<f64>> {
    let mut out = vec![
        Vector3::new(0.0, -0.0, 5e-324),
        Vector3::new(1e-310, -3.7, 1e150),
    ];
    let mut x = 0.123_456_789_f64;
    for k in 0..200 {
        let mut next = || {
            x = (x * 3.999_999 * (1.0 - x)).clamp(1e-9, 1.0 - 1e-9);
            x - 0.5
        };
        let scale = 10f64.powi(k % 61 * 5 - 150);
        out.push(Vector3::new(next(), next(), next()) * scale);
    }
    out
}

#[test]
fn diagonal_bodies_declare_their_velocity_bitwise_and_others_nothing() {
    let bodies = [
        RigidBody::principal([1.0, 2.0, 3.0]).unwrap(),
        RigidBody::principal([1e-3, 1.0, 1e3]).unwrap(),
        RigidBody::principal([7.0, 7.0, 0.1]).unwrap(),
    ];
    for body in &bodies {
        let a = body
            .diagonal_velocity()
            .expect("a principal body is diagonal");
        for mu in momenta() {
            let (want, got) = (body.velocity(&mu), a.component_mul(&mu));
            for i in 0..3 {
                assert_eq!(want[i].to_bits(), got[i].to_bits(), "{mu:?}");
            }
        }
    }
    let top = top();
    assert_eq!(
        top.diagonal_velocity(),
        top.body().diagonal_velocity(),
        "the heavy top's h is its body's"
    );
    // An external torque does not enter h: the forced body declares the body's a.
    let torqued = Forced::new(
        bodies[0].clone(),
        BodyTorque::<So3>::constant(Vector3::new(0.1, 0.0, -0.2)).unwrap(),
    );
    assert_eq!(torqued.diagonal_velocity(), bodies[0].diagonal_velocity());
    // A full inertia tensor (its principal axes are not the body axes) declares nothing.
    let tilted = Matrix3::new(2.0, 0.3, 0.0, 0.3, 1.5, -0.2, 0.0, -0.2, 1.0);
    assert!(RigidBody::new(tilted)
        .unwrap()
        .diagonal_velocity()
        .is_none());
}

/// Steps `a` and `b` n times from the same state and asserts bitwise equal Π and R at every step.
fn same_path(mut a: impl Integrator<Group = So3>, mut b: impl Integrator<Group = So3>, h: f64) {
    for k in 0..300 {
        a.step(h).unwrap();
        b.step(h).unwrap();
        let (pa, pb) = (a.momentum(), b.momentum());
        let (ra, rb) = (
            a.configuration().unwrap().as_matrix(),
            b.configuration().unwrap().as_matrix(),
        );
        assert!(
            (0..3).all(|i| pa[i].to_bits() == pb[i].to_bits())
                && ra
                    .iter()
                    .zip(rb.iter())
                    .all(|(x, y)| x.to_bits() == y.to_bits()),
            "step {k}: {pa:?} against {pb:?}"
        );
    }
}

#[test]
fn the_diagonal_fast_path_steps_bit_for_bit_as_the_general_one() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let g0 = Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8)));
    for h in [0.01, 0.3] {
        same_path(
            QuaternionRk4::new(body.clone(), pi0, g0).unwrap(),
            QuaternionRk4::new(Hidden(body.clone()), pi0, g0).unwrap(),
            h,
        );
        same_path(
            QuaternionRk4::new(top(), pi0, g0).unwrap(),
            QuaternionRk4::new(Hidden(top()), pi0, g0).unwrap(),
            h,
        );
        same_path(
            Rkmk4::new(body.clone(), pi0, g0).unwrap(),
            Rkmk4::new(Hidden(body.clone()), pi0, g0).unwrap(),
            h,
        );
        same_path(
            Rkmk4::new(top(), pi0, g0).unwrap(),
            Rkmk4::new(Hidden(top()), pi0, g0).unwrap(),
            h,
        );
    }
    // The comparison is sharp: moments 8 ulps apart part within 100 steps.
    let nudged = RigidBody::principal([1.0, 2.0, 3.0 * (1.0 + 8.0 * f64::EPSILON)]).unwrap();
    let mut a = QuaternionRk4::new(body, pi0, g0).unwrap();
    let mut b = QuaternionRk4::new(Hidden(nudged), pi0, g0).unwrap();
    for _ in 0..100 {
        a.step(0.01).unwrap();
        b.step(0.01).unwrap();
    }
    assert_ne!(a.momentum(), b.momentum());
}
