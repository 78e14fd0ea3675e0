//! Ensemble throughput (`integrators::ensemble`): trajectories per second of the free rigid body
//! (Lie–Poisson, τ = Cayley, θ = ½, no reconstruction), 256 trajectories × 1000 steps, on rayon
//! pools of 1 and 2 threads. The scaling factor is the ratio of the two throughputs; the issue's
//! target is ≥ 1.8× on 2 cores (only reachable on an otherwise idle machine).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use integrators::ensemble::{momenta_on_sphere, Ensemble};
use integrators::LiePoisson;
use lie_groups::{Cayley, So3};
use mechanics::RigidBody;
use nalgebra::Vector3;
use std::hint::black_box;
use std::time::Duration;

const TRAJECTORIES: usize = 256;
const STEPS: usize = 1000;

fn ensemble_throughput(c: &mut Criterion) {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).expect("valid inertia");
    let mu0: Vec<Vector3<f64>> = momenta_on_sphere(3, 1.0, TRAJECTORIES, 1).expect("sphere");
    let sweep = Ensemble::new(mu0, 0.01 * STEPS as f64, STEPS).expect("valid sweep");
    let build = |_: usize, mu: &Vector3<f64>| {
        LiePoisson::<So3, Cayley, _>::new(body.clone(), 0.5, *mu, None)
    };
    let mut group = c.benchmark_group("ensemble_rigid_body_256x1000");
    group.throughput(Throughput::Elements(TRAJECTORIES as u64));
    group.sample_size(10);
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(5));
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("thread pool");
        group.bench_function(format!("threads_{threads}"), |b| {
            b.iter(|| pool.install(|| black_box(sweep.run_parallel(&build))))
        });
    }
    group.finish();
}

criterion_group!(benches, ensemble_throughput);
criterion_main!(benches);
