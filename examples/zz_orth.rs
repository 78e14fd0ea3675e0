use integrators::systems::RigidBody;
use integrators::{Integrator, LiePoisson};
use lie_groups::{Cayley, ExpMap, LieGroup, So3};
use nalgebra::{Matrix3, Vector3};
fn main() {
    let body = RigidBody::principal(1.0, 2.0, 3.0).unwrap();
    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let g0 = So3::exp(&Vector3::new(0.3, -0.5, 0.8));
    for h in [1e-5, 1e-2, 0.1] {
        let mut lp = LiePoisson::<So3, Cayley, _>::new(body.clone(), 0.5, pi0, Some(g0)).unwrap();
        let mut e = LiePoisson::<So3, ExpMap, _>::new(body.clone(), 0.5, pi0, Some(g0)).unwrap();
        for k in 1..=10_000_000u64 {
            lp.step(h).unwrap();
            e.step(h).unwrap();
            if k == 1_000_000 || k == 10_000_000 {
                let r = lp.configuration().unwrap().as_matrix();
                let d = (r.transpose() * r - Matrix3::identity()).amax();
                let r2 = e.configuration().unwrap().as_matrix();
                let d2 = (r2.transpose() * r2 - Matrix3::identity()).amax();
                println!("h={h} k={k}: ‖RᵀR − I‖ cayley {d:.2e} exp {d2:.2e}");
            }
        }
    }
}
