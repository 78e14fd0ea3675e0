//! Reversible variable steps (`integrators::adaptive::ReversibleSteps`, the Hairer–Söderlind
//! step-density controller) against fixed steps of the same method, on the satellite on an
//! eccentric orbit (`mechanics::RigidBodySe3::satellite`, e = 0.8, GM = a = 1, one orbit T = 2π,
//! a nearly axisymmetric body coupled by the gravity gradient).
//!
//! Groups (each benchmark is one whole run, constructor included):
//! - `step_density/eccentric_orbit/variable`: Strang splitting with ε = 0.003;
//! - `step_density/eccentric_orbit/fixed_equal_error`: Strang with the fewest fixed steps (on a
//!   ladder ×5/4) whose error at T is at most the variable run's;
//! - `step_density/eccentric_orbit/fixed_same_count`: as many fixed steps as the variable run
//!   took: the price of the controller (one evaluation of the density's G per step).
//!
//! The error at T is against RKMK DOP853 at 1e-13; the step counts and errors are printed to
//! stderr before timing. Compare ratios within one run only.
//! Run: `cargo bench -p lie-integrators --bench step_density -- --warm-up-time 1 --measurement-time 2`.

use criterion::{criterion_group, criterion_main, Criterion};
use integrators::adaptive::{Adaptive, ReversibleSteps, RkmkDop853, Tolerance};
use integrators::splitting::Splitting;
use integrators::Integrator;
use lie_groups::{LieGroup, Se3, So3};
use mechanics::RigidBodySe3;
use nalgebra::{Matrix3, Vector3, Vector6};
use std::hint::black_box;

const E: f64 = 0.8;
const T: f64 = 2.0 * std::f64::consts::PI;
const EPSILON: f64 = 0.003;

fn satellite() -> RigidBodySe3 {
    let inertia = Matrix3::new(1.0, 0.01, 0.0, 0.01, 1.03, 0.02, 0.0, 0.02, 1.06) * 1e-3;
    RigidBodySe3::satellite(1.0, inertia, 1.0).unwrap()
}

fn strang() -> Splitting<Se3, RigidBodySe3> {
    let sat = satellite();
    let pi = sat.inertia() * Vector3::new(0.02, -0.01, 0.1);
    let vp = ((1.0 + E) / (1.0 - E)).sqrt();
    let g0 = Se3::from_parts(So3::identity(), Vector3::new(1.0 - E, 0.0, 0.0));
    let mu0 = Vector6::new(pi.x, pi.y, pi.z, 0.0, vp, 0.0);
    Splitting::new(sat, mu0, Some(g0)).unwrap()
}

fn variable() -> Splitting<Se3, RigidBodySe3> {
    let mut run = ReversibleSteps::new(strang(), satellite(), EPSILON).unwrap();
    run.advance_to(T).unwrap()
}

fn fixed(n: usize) -> Splitting<Se3, RigidBodySe3> {
    let mut m = strang();
    for _ in 0..n {
        m.step(T / n as f64).unwrap();
    }
    m
}

fn bench(c: &mut Criterion) {
    let start = strang();
    let pair = RkmkDop853::new(
        satellite(),
        start.momentum(),
        start.configuration().copied(),
    );
    let mut reference = Adaptive::new(pair.unwrap(), Tolerance::uniform(1e-13).unwrap());
    reference.advance_to(T).unwrap();
    let reference = reference.into_method();
    let error = |m: &Splitting<Se3, RigidBodySe3>| {
        let (g, r) = (
            m.configuration().unwrap(),
            reference.configuration().unwrap(),
        );
        (g.translation() - r.translation()).norm()
            + (g.rotation().as_matrix() - r.rotation().as_matrix()).norm()
            + (m.momentum() - reference.momentum()).norm()
    };
    let mut run = ReversibleSteps::new(strang(), satellite(), EPSILON).unwrap();
    let variable_error = error(&run.advance_to(T).unwrap());
    let count = run.stats().accepted + 1;
    let mut n = count;
    while error(&fixed(n)) > variable_error {
        n = n * 5 / 4;
    }
    eprintln!(
        "eccentric orbit, one orbit: variable {count} steps (error {variable_error:.2e}), \
         fixed {n} steps (error {:.2e}): step ratio {:.3}",
        error(&fixed(n)),
        count as f64 / n as f64
    );
    let mut group = c.benchmark_group("step_density/eccentric_orbit");
    group.bench_function("variable", |b| b.iter(|| black_box(variable())));
    group.bench_function("fixed_equal_error", |b| b.iter(|| black_box(fixed(n))));
    group.bench_function("fixed_same_count", |b| b.iter(|| black_box(fixed(count))));
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
