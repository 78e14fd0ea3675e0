//! The plain competitor of the benches (`benches/common/hand_rk4.rs`) integrates the same
//! equations as the library's `QuaternionRk4`: both are classical RK4 on (q, Π) with q
//! renormalised each step, so their trajectories agree to round-off. A competitor with another
//! sign of gravity or another inertia would be timed on a different problem.

#[path = "../benches/common/hand_rk4.rs"]
#[allow(dead_code)]
mod hand_rk4;

use hand_rk4::HandRk4;
use integrators::baselines::QuaternionRk4;
use integrators::{Integrator, System};
use lie_groups::{LieGroup, So3};
use mechanics::systems::{HeavyTop, RigidBody};
use nalgebra::{UnitQuaternion, Vector3};

const MOMENTS: [f64; 3] = [1.0, 2.0, 3.0];
const STEPS: usize = 500;
const H: f64 = 0.01;

fn g0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.5, 0.8))
}

/// Steps both for `STEPS` steps of size `H`; returns the largest difference of Π and of R.
fn gap<const GRAVITY: bool, S: System<So3>>(system: S, mgchi: Vector3<f64>) -> (f64, f64) {
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let mut hand = HandRk4::<GRAVITY>::new(MOMENTS, mgchi, pi0, g0().as_matrix());
    let mut rk4 = QuaternionRk4::new(system, pi0, Some(g0())).unwrap();
    let (mut dpi, mut dr) = (0.0_f64, 0.0_f64);
    for _ in 0..STEPS {
        hand.step(H);
        rk4.step(H).unwrap();
        let r_hand = UnitQuaternion::from_quaternion(hand.q).to_rotation_matrix();
        let r_lib = rk4.configuration().unwrap().as_matrix();
        dpi = dpi.max((hand.pi - rk4.momentum()).amax());
        dr = dr.max((r_hand.matrix() - r_lib).amax());
    }
    (dpi, dr)
}

#[test]
fn the_free_body_competitor_follows_quaternion_rk4() {
    let (dpi, dr) = gap::<false, _>(
        RigidBody::principal([MOMENTS[0], MOMENTS[1], MOMENTS[2]]).unwrap(),
        Vector3::zeros(),
    );
    assert!(dpi < 1e-13 && dr < 1e-13, "Π gap {dpi:e}, R gap {dr:e}");
}

#[test]
fn the_heavy_top_competitor_follows_quaternion_rk4() {
    let mgchi = Vector3::new(0.0, 0.1, 0.5);
    let top = HeavyTop::principal(MOMENTS, 1.0, 1.0, mgchi).unwrap();
    let (dpi, dr) = gap::<true, _>(top, mgchi);
    assert!(dpi < 1e-13 && dr < 1e-13, "Π gap {dpi:e}, R gap {dr:e}");
}
