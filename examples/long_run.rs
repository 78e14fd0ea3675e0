//! Long-run invariants of the Lie–Poisson integrators on the free rigid body (I = diag(1, 2, 3),
//! h = 0.01): orthogonality of R after 10⁷ steps, Casimir |Π| and the energy error, for every
//! τ ∈ {exp, Cayley} and θ ∈ {0, ½}. The figures in docs/long-runs.md come from this program:
//!
//! ```sh
//! cargo run --release -p lie-integrators --example long_run            # 10⁷ steps per method
//! cargo run --release -p lie-integrators --example long_run -- 1000000 # a shorter run
//! ```

use integrators::{Integrator, LiePoisson};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};
use std::time::Instant;

fn run<T: Tau<So3>>(theta: f64, steps: usize) {
    let h = 0.01;
    let body = RigidBody::principal([1.0, 2.0, 3.0]).expect("valid inertia");
    let pi0 = Vector3::new(0.6, 1.0, 0.8);
    let mut lp = LiePoisson::<So3, T, _>::new(body, theta, pi0, Some(So3::identity()))
        .expect("valid initial state");
    let e0 = lp.energy();
    let c0 = lp.casimir().expect("free body has a Casimir");
    let (mut max_de, mut max_dc) = (0.0f64, 0.0f64);
    let (mut de_first, mut de_last) = (0.0f64, 0.0f64);
    let start = Instant::now();
    for k in 0..steps {
        lp.step(h).expect("step converges");
        if k % 100 == 0 || k + 1 == steps {
            let de = ((lp.energy() - e0) / e0).abs();
            max_de = max_de.max(de);
            max_dc = max_dc.max(((lp.casimir().unwrap() - c0) / c0).abs());
            if k < steps / 10 {
                de_first = de_first.max(de);
            }
            if k >= steps - steps / 10 {
                de_last = de_last.max(de);
            }
        }
    }
    let elapsed = start.elapsed().as_secs_f64();
    let r = lp.configuration().expect("reconstructed").as_matrix();
    let orth = (r.transpose() * r - Matrix3::identity()).amax();
    println!(
        "| {:6} | {:3} | {:>9} | {:>9.2e} | {:>9.2e} | {:>9.2e} | {:>9.2e} | {:>9.2e} | {:>7.0} |",
        T::NAME,
        theta,
        steps,
        orth,
        max_dc,
        max_de,
        de_first,
        de_last,
        elapsed / steps as f64 * 1e9
    );
}

fn main() {
    let steps: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse().expect("number of steps"))
        .unwrap_or(10_000_000);
    println!("| τ      | θ   | steps     | ‖RᵀR−I‖   | max ΔC/C  | max ΔE/E  | first 10% | last 10%  | ns/step |");
    println!("| ---    | --- | ---       | ---       | ---       | ---       | ---       | ---       | ---     |");
    for theta in [0.0, 0.5] {
        run::<ExpMap>(theta, steps);
        run::<Cayley>(theta, steps);
    }
}
