//! Body-steps per second of the batched methods (`batch`) against the scalar ones, per
//! instruction set, and against plain competitors written here: a hand-written scalar NO_SQUISH
//! free-rotor step (Miller et al. 2002, as LAMMPS writes it; `common/no_squish.rs`) and the
//! hand-written scalar RK4 on (q, Π) (`common/hand_rk4.rs`).
//!
//! Groups (criterion's throughput is in bodies, so its `elem/s` are body-steps per second):
//! - `batch/free_body`: 𝕀 = diag(1, 2, 3), 1024 bodies with |Π| = 1 drawn on the sphere, random
//!   attitudes, h = 0.01, 16 steps of every body per iteration (each body, or each block of 128
//!   batched bodies, stepped 16 times in a row, as a sweep steps them): the scalar library's Strang step
//!   (`Splitting`, with R), `QuaternionRk4`, `Rkmk4` and the exact flow (`ExactFreeBody`), the
//!   hand-written NO_SQUISH and RK4, and the batched Strang, RK4, RKMK4 and exact flow on each
//!   level this CPU runs (`avx512`, `avx2` forced on an AVX-512 machine, `scalar`).
//! - `batch/field`: the same bodies as heavy tops (m g χ = (0.15, −0.3, 0.75)): scalar Strang,
//!   RK4 and RKMK4, hand-written RK4, batched Strang, RK4 and RKMK4 per level.
//! - `batch/size`: the batched Strang step (widest level) for N = 64 … 4·10⁶ bodies, one step of
//!   all of them per iteration, which streams the state (13 + 7 doubles a body) through the
//!   caches: where the memory bandwidth takes over; and `run/N` — 64 steps per call, each block
//!   of 128 bodies stepped 64 times while it sits in L1 — the compute-bound rate at any N.
//!
//! One core: the batches run sequentially (`Execution::Sequential`); threads multiply the rate
//! (blocks are independent). Run:
//! `cargo bench -p lie-integrators --bench batch -- --warm-up-time 1 --measurement-time 2`.
//! The figures and the flop-and-sincos bound are in docs/benchmarks.md.

use batch::{
    Batch, BodyModel, ExactFlow, Level, QuaternionRk4 as BatchRk4, Rkmk4 as BatchRkmk4, Strang,
};
use criterion::measurement::WallTime;
use criterion::{criterion_group, criterion_main, BenchmarkGroup, Criterion, Throughput};
use integrators::ensemble::sphere_point;
use integrators::splitting::Splitting;
use integrators::{Integrator, QuaternionRk4, Rkmk4};
use lie_groups::{LieGroup, So3};
use mechanics::exact::ExactFreeBody;
use mechanics::{HeavyTop, RigidBody};
use nalgebra::{UnitQuaternion, Vector3};
use std::hint::black_box;
use std::time::Duration;

#[path = "common/hand_rk4.rs"]
mod hand_rk4;
#[path = "common/no_squish.rs"]
mod no_squish;
use hand_rk4::HandRk4;
use no_squish::NoSquish;

const H: f64 = 0.01;
const N: usize = 1024;
/// Steps of every body per iteration in `batch/free_body` and `batch/field`: each body (scalar)
/// or block of bodies (batched) is stepped this many times in a row, as a sweep steps them, so
/// that neither pays for reloading its state from L2 every step.
const STEPS: usize = 16;
const MOMENTS: [f64; 3] = [1.0, 2.0, 3.0];

fn states(n: usize) -> (Vec<Vector3<f64>>, Vec<So3>) {
    let pis = (0..n as u64)
        .map(|i| sphere_point(3, 1.0, 1, i).expect("sphere"))
        .collect();
    let rs = (0..n as u64)
        .map(|i| So3::exp(&sphere_point(3, 2.0, 2, i).expect("sphere")))
        .collect();
    (pis, rs)
}

fn mgchi() -> Vector3<f64> {
    Vector3::new(0.1, -0.2, 0.5) * 1.5
}

/// [`STEPS`] steps of each of `integs` per iteration.
fn scalar_steps<I: Integrator>(g: &mut BenchmarkGroup<'_, WallTime>, id: &str, mut integs: Vec<I>) {
    g.bench_function(id, |b| {
        b.iter(|| {
            for s in integs.iter_mut() {
                for _ in 0..STEPS {
                    s.step(black_box(H)).expect("step");
                }
            }
        })
    });
}

/// [`STEPS`] steps of each of the hand-written `steppers` per iteration.
fn hand_steps<T>(
    g: &mut BenchmarkGroup<'_, WallTime>,
    id: &str,
    steppers: &mut [T],
    step: impl Fn(&mut T, f64),
) {
    g.bench_function(id, |b| {
        b.iter(|| {
            for r in steppers.iter_mut() {
                for _ in 0..STEPS {
                    step(r, black_box(H));
                }
            }
        })
    });
}

fn batch_steps<K: batch::Kernel>(
    g: &mut BenchmarkGroup<'_, WallTime>,
    id: &str,
    kernel: K,
    pis: &[Vector3<f64>],
    rs: &[So3],
) {
    for level in Level::available() {
        let mut b = Batch::new(kernel.clone(), pis, rs, level).expect("batch");
        g.bench_function(format!("{id}/{level}"), |bch| {
            bch.iter(|| b.run(black_box(H), STEPS as u64).expect("steps"))
        });
    }
}

/// NO_SQUISH is a legitimate competitor: it keeps the energy and follows the Strang splitting's
/// momentum to O(h²).
fn check_no_squish(rotor: &NoSquish, pi0: Vector3<f64>, r0: So3) {
    let body = RigidBody::principal([MOMENTS[0], MOMENTS[1], MOMENTS[2]]).expect("body");
    let mut a = rotor.clone();
    let mut s = Splitting::new(body, pi0, Some(r0)).expect("splitting");
    for _ in 0..200 {
        a.step(H);
        s.step(H).expect("step");
    }
    let d = (Vector3::from(a.momentum()) - s.momentum()).amax();
    assert!(d < 1e-3, "NO_SQUISH drifts from the splitting by {d:e}");
}

fn free_body(c: &mut Criterion) {
    let (pis, rs) = states(N);
    let body = RigidBody::principal([MOMENTS[0], MOMENTS[1], MOMENTS[2]]).expect("body");
    let mut g = c.benchmark_group("batch/free_body");
    g.throughput(Throughput::Elements((N * STEPS) as u64));
    let strang: Vec<_> = (0..N)
        .map(|i| Splitting::new(body.clone(), pis[i], Some(rs[i])).expect("splitting"))
        .collect();
    scalar_steps(&mut g, "scalar/strang", strang);
    let rk4: Vec<_> = (0..N)
        .map(|i| QuaternionRk4::new(body.clone(), pis[i], Some(rs[i])).expect("rk4"))
        .collect();
    scalar_steps(&mut g, "scalar/rk4", rk4);
    let rkmk4: Vec<_> = (0..N)
        .map(|i| Rkmk4::new(body.clone(), pis[i], Some(rs[i])).expect("rkmk4"))
        .collect();
    scalar_steps(&mut g, "scalar/rkmk4", rkmk4);
    let exact: Vec<_> = (0..N)
        .map(|i| ExactFreeBody::new(body.clone(), pis[i], Some(rs[i])).expect("exact"))
        .collect();
    scalar_steps(&mut g, "scalar/exact", exact);
    let quat = |r: &So3| UnitQuaternion::from(*r).into_inner();
    let mut rotors: Vec<NoSquish> = (0..N)
        .map(|i| {
            let q = quat(&rs[i]);
            NoSquish::new(MOMENTS, [q.w, q.i, q.j, q.k], pis[i].into())
        })
        .collect();
    check_no_squish(&rotors[0], pis[0], rs[0]);
    hand_steps(&mut g, "hand/no_squish", &mut rotors, |r, h| r.step(h));
    let mut hand: Vec<HandRk4<false>> = (0..N)
        .map(|i| HandRk4::new(MOMENTS, Vector3::zeros(), pis[i], rs[i].as_matrix()))
        .collect();
    hand_steps(&mut g, "hand/rk4", &mut hand, |r, h| r.step(h));
    let model = BodyModel::free(&body).expect("model");
    batch_steps(
        &mut g,
        "batch/strang",
        Strang::new(model.clone()),
        &pis,
        &rs,
    );
    batch_steps(&mut g, "batch/rk4", BatchRk4::new(model.clone()), &pis, &rs);
    batch_steps(
        &mut g,
        "batch/rkmk4",
        BatchRkmk4::new(model.clone()),
        &pis,
        &rs,
    );
    batch_steps(
        &mut g,
        "batch/exact",
        ExactFlow::new(model).expect("exact"),
        &pis,
        &rs,
    );
    g.finish();
}

fn field(c: &mut Criterion) {
    let (pis, rs) = states(N);
    let top = HeavyTop::principal(MOMENTS, 1.5, 1.0, mgchi() / 1.5).expect("top");
    let mut g = c.benchmark_group("batch/field");
    g.throughput(Throughput::Elements((N * STEPS) as u64));
    let strang: Vec<_> = (0..N)
        .map(|i| Splitting::new(top.clone(), pis[i], Some(rs[i])).expect("splitting"))
        .collect();
    scalar_steps(&mut g, "scalar/strang", strang);
    let rk4: Vec<_> = (0..N)
        .map(|i| QuaternionRk4::new(top.clone(), pis[i], Some(rs[i])).expect("rk4"))
        .collect();
    scalar_steps(&mut g, "scalar/rk4", rk4);
    let rkmk4: Vec<_> = (0..N)
        .map(|i| Rkmk4::new(top.clone(), pis[i], Some(rs[i])).expect("rkmk4"))
        .collect();
    scalar_steps(&mut g, "scalar/rkmk4", rkmk4);
    let mut hand: Vec<HandRk4<true>> = (0..N)
        .map(|i| HandRk4::new(MOMENTS, mgchi(), pis[i], rs[i].as_matrix()))
        .collect();
    hand_steps(&mut g, "hand/rk4", &mut hand, |r, h| r.step(h));
    let model = BodyModel::heavy_top(&top).expect("model");
    batch_steps(
        &mut g,
        "batch/strang",
        Strang::new(model.clone()),
        &pis,
        &rs,
    );
    batch_steps(&mut g, "batch/rk4", BatchRk4::new(model.clone()), &pis, &rs);
    batch_steps(&mut g, "batch/rkmk4", BatchRkmk4::new(model), &pis, &rs);
    g.finish();
}

fn size(c: &mut Criterion) {
    let body = RigidBody::principal([MOMENTS[0], MOMENTS[1], MOMENTS[2]]).expect("body");
    let model = BodyModel::free(&body).expect("model");
    let mut g = c.benchmark_group("batch/size");
    g.sample_size(10);
    for n in [64usize, 1024, 16_384, 262_144, 4_194_304] {
        let (pis, _) = states(n);
        let mut b = Batch::new(
            Strang::new(model.clone()),
            &pis,
            &[So3::identity()],
            Level::detect(),
        )
        .expect("batch");
        g.throughput(Throughput::Elements(n as u64));
        g.bench_function(format!("step/{n}"), |bch| {
            bch.iter(|| b.step(black_box(H)).expect("step"))
        });
        g.throughput(Throughput::Elements(64 * n as u64));
        g.bench_function(format!("run/{n}"), |bch| {
            bch.iter(|| b.run(black_box(H), 64).expect("run"))
        });
    }
    g.finish();
}

fn config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(20)
}

criterion_group! {
    name = benches;
    config = config();
    targets = free_body, field, size
}
criterion_main!(benches);
