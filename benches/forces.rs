//! The cost of an external force: one Lie–Poisson step (Cayley, θ = ½, with reconstruction) of the
//! free rigid body 𝕀 = diag(1, 2, 3), Π₀ = (0.5, 1, 0.2), h = 0.01, unforced and with a constant
//! body torque (target: forced ≤ 1.2× unforced), and with torque + damping; RK4 alongside.
//! Every measured step starts from the same state (`iter_batched_ref`), so the torque's growth of
//! Π does not change what is measured: the initial state with nothing carried (a run's first,
//! cold step), and for Lie–Poisson also the state after 10 steps with what they left for the next
//! (`…/warm`: a run's steady step).
//!
//! Run: `cargo bench -p lie-integrators --bench forces -- --warm-up-time 1 --measurement-time 2`.
//! The figures are in docs/benchmarks.md.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use integrators::forces::{BodyTorque, Forced, LinearDamping};
use integrators::{Integrator, LiePoisson, QuaternionRk4};
use lie_groups::{Cayley, LieGroup, So3};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};
use std::hint::black_box;

const H: f64 = 0.01;

fn bench<I: Integrator + Clone>(
    c: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    id: &str,
    integ: I,
) {
    c.bench_function(id, |b| {
        b.iter_batched_ref(
            || integ.clone(),
            |i| i.step(black_box(H)).unwrap(),
            BatchSize::SmallInput,
        )
    });
}

/// [`bench`] from the state after [`WARM`] steps, with what they left for the next step (the
/// warm start): a run's steady step, where the cold one is its first.
fn bench_warm<I: Integrator + Clone>(
    c: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    id: &str,
    mut integ: I,
) {
    for _ in 0..WARM {
        integ.step(H).unwrap();
    }
    bench(c, id, integ);
}

/// Steps taken before a warm measured step (the warm start extrapolates from six).
const WARM: usize = 10;

fn forces(c: &mut Criterion) {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let g0 = Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8)));
    let torque = BodyTorque::<So3>::constant(Vector3::new(0.1, -0.05, 0.2)).unwrap();
    let damping = LinearDamping::<So3>::new(Matrix3::identity() * 0.1).unwrap();
    let mut group = c.benchmark_group("forces/free_body");
    let lp = |s| LiePoisson::<So3, Cayley, _>::new(s, 0.5, pi0, g0).unwrap();
    bench(
        &mut group,
        "lp-cayley-0.5/unforced",
        lp_unforced(&body, pi0, g0),
    );
    bench(
        &mut group,
        "lp-cayley-0.5/torque",
        lp(Forced::new(body.clone(), torque.clone())),
    );
    bench(
        &mut group,
        "lp-cayley-0.5/torque+damping",
        LiePoisson::<So3, Cayley, _>::new(
            Forced::new(body.clone(), (torque.clone(), damping)),
            0.5,
            pi0,
            g0,
        )
        .unwrap(),
    );
    bench_warm(
        &mut group,
        "lp-cayley-0.5/unforced/warm",
        lp_unforced(&body, pi0, g0),
    );
    bench_warm(
        &mut group,
        "lp-cayley-0.5/torque/warm",
        lp(Forced::new(body.clone(), torque.clone())),
    );
    bench(
        &mut group,
        "rk4/unforced",
        QuaternionRk4::new(body.clone(), pi0, g0).unwrap(),
    );
    bench(
        &mut group,
        "rk4/torque",
        QuaternionRk4::new(Forced::new(body, torque), pi0, g0).unwrap(),
    );
    group.finish();
}

fn lp_unforced(
    body: &RigidBody,
    pi0: Vector3<f64>,
    g0: Option<So3>,
) -> LiePoisson<So3, Cayley, RigidBody> {
    LiePoisson::<So3, Cayley, _>::new(body.clone(), 0.5, pi0, g0).unwrap()
}

criterion_group!(benches, forces);
criterion_main!(benches);
