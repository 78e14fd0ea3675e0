use integrators::baselines::QuaternionRk4;
use integrators::systems::RigidBody;
use integrators::{Integrator, LiePoisson};
use lie_groups::{Cayley, LieGroup, So3};
use nalgebra::Vector3;
fn main() {
    let which = std::env::args().nth(1).unwrap_or_default();
    let theta: f64 = std::env::args()
        .nth(2)
        .map(|s| s.parse().unwrap())
        .unwrap_or(0.5);
    let body = RigidBody::principal(1.0, 2.0, 3.0).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let g0 = Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8)));
    let n = 10_000_000;
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let t = std::time::Instant::now();
        if which == "rk4" {
            let mut r = QuaternionRk4::new(body.clone(), pi0, g0).unwrap();
            for _ in 0..n {
                r.step(0.01).unwrap();
            }
            std::hint::black_box(r.momentum());
        } else {
            let g0 = if std::env::args().nth(3).as_deref() == Some("nog") {
                None
            } else {
                g0
            };
            let mut lp = LiePoisson::<So3, Cayley, _>::new(body.clone(), theta, pi0, g0).unwrap();
            for _ in 0..n {
                lp.step(0.01).unwrap();
            }
            std::hint::black_box(lp.momentum());
        }
        best = best.min(t.elapsed().as_nanos() as f64 / n as f64);
    }
    println!("{which} {theta}: {best:.1} ns/step (best of 3)");
}
