//! The speed side of the speed–accuracy trade: ns per step of the explicit splittings, the exact
//! free-body flow and the kinetic–kick schemes, against the best plain competitor — a hand-written
//! nalgebra RK4 on (q, Π) — and the library's own baselines, all in the same run.
//!
//! Groups:
//! - `trade/free_body`: 𝕀 = diag(1, 2, 3), Π₀ = (0.5, 1, 0.2), R₀ given, h = 0.01: hand-written
//!   RK4, `QuaternionRk4`, `Rkmk4`, Strang (the body's split: an axisymmetric body and a rotation), the exact flow as a
//!   method (`ExactFreeBody`), each with the attitude (`+g`); Π alone (`-g`) for RK4, Strang and
//!   the exact flow; the implicit Lie–Poisson step (Cayley, θ = ½ and 0, `+g`) for the issue's
//!   ratio against the hand-written RK4; the modified Lie–Poisson steps (order 4 and 6, θ = ½ and
//!   0, τ = exp and Cayley, `+g`: one implicit step each) and the processed Strang splitting
//!   (`processed/<scheme>+g`: the kernel's steps only, as a run pays them; `…/read+g`: one step and
//!   a read of the state, which applies the processor — the cost of an output row).
//! - `trade/exact_flow`: one call of `FreeBodyFlow::advance` to T = 1, 10, 1000 (its cost does
//!   not grow with T), with and without R.
//! - `trade/heavy_top`: an asymmetric top 𝕀 = diag(1, 2, 3), mgχ = (0, 0.1, 0.5), h = 0.01:
//!   hand-written RK4, `QuaternionRk4`, `Rkmk4`, Strang of the axes and kick, the exact kinetic
//!   flow with kicks (Strang, Blanes–Moan 4 (S6) and 6 (S10) coefficients), and the processed
//!   Strang and kinetic–kick (Strang) splittings of each processing scheme.
//!
//! Run: `cargo bench -p lie-integrators --bench splitting -- --warm-up-time 1 --measurement-time 2`.
//! The figures are in docs/work-precision.md.

use criterion::{
    criterion_group, criterion_main, measurement::WallTime, BenchmarkGroup, Criterion,
};
use integrators::baselines::{QuaternionRk4, Rkmk4};
use integrators::exact::{ExactFreeBody, FreeBodyFlow};
use integrators::modified::{ModifiedLiePoisson, ModifiedScheme};
use integrators::processing::{Processed, ProcessingScheme};
use integrators::splitting::{KineticKick, Splitting, SplittingScheme};
use integrators::systems::{HeavyTop, RigidBody};
use integrators::{Integrator, LiePoisson};
use lie_groups::{Cayley, ExpMap, LieGroup, So3};
use nalgebra::Vector3;
use std::hint::black_box;

const H: f64 = 0.01;

#[path = "common/hand_rk4.rs"]
mod hand_rk4;
use hand_rk4::HandRk4;

fn bench_step<I: Integrator>(group: &mut BenchmarkGroup<'_, WallTime>, id: &str, mut integ: I) {
    group.bench_function(id, |b| b.iter(|| integ.step(black_box(H)).unwrap()));
}

fn g0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.5, 0.8))
}

fn hand_rk4<const GRAVITY: bool>(
    moments: [f64; 3],
    mgchi: Vector3<f64>,
    pi0: Vector3<f64>,
) -> HandRk4<GRAVITY> {
    let r = nalgebra::Rotation3::from_matrix_unchecked(*g0().as_matrix());
    HandRk4 {
        inv_i: Vector3::from(moments).map(|i| 1.0 / i),
        mgchi,
        q: nalgebra::UnitQuaternion::from_rotation_matrix(&r).into_inner(),
        pi: pi0,
    }
}

fn free_body(c: &mut Criterion) {
    let body = RigidBody::principal(1.0, 2.0, 3.0).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let mut group = c.benchmark_group("trade/free_body");
    let mut hand = hand_rk4::<false>([1.0, 2.0, 3.0], Vector3::zeros(), pi0);
    group.bench_function("rk4-hand-written+g", |b| b.iter(|| hand.step(black_box(H))));
    for (suffix, g) in [("+g", Some(g0())), ("-g", None)] {
        let rk4 = QuaternionRk4::new(body.clone(), pi0, g).unwrap();
        bench_step(&mut group, &format!("rk4-quaternion{suffix}"), rk4);
        let strang = Splitting::new(body.clone(), pi0, g).unwrap();
        bench_step(&mut group, &format!("splitting-strang{suffix}"), strang);
        let exact = ExactFreeBody::new(body.clone(), pi0, g).unwrap();
        bench_step(&mut group, &format!("exact{suffix}"), exact);
    }
    let rkmk = Rkmk4::new(body.clone(), pi0, Some(g0())).unwrap();
    bench_step(&mut group, "rkmk4+g", rkmk);
    for theta in [0.5, 0.0] {
        let lp = LiePoisson::<So3, Cayley, _>::new(body.clone(), theta, pi0, Some(g0())).unwrap();
        bench_step(&mut group, &format!("lp/cayley/{theta}+g"), lp);
        for order in [4, 6] {
            let scheme = ModifiedScheme::new(theta, order).unwrap();
            let m =
                ModifiedLiePoisson::<Cayley>::with_scheme(body.clone(), scheme, pi0, Some(g0()))
                    .unwrap();
            bench_step(&mut group, &format!("modified/cayley/{theta}/{order}+g"), m);
            let m =
                ModifiedLiePoisson::<ExpMap>::with_scheme(body.clone(), scheme, pi0, Some(g0()))
                    .unwrap();
            bench_step(&mut group, &format!("modified/exp/{theta}/{order}+g"), m);
        }
    }
    for scheme in ProcessingScheme::builtin() {
        let strang = Splitting::new(body.clone(), pi0, Some(g0())).unwrap();
        let psi = Processed::composition(strang, scheme.clone()).unwrap();
        let mut read = psi.clone();
        bench_step(&mut group, &format!("processed/{}+g", scheme.name()), psi);
        group.bench_function(format!("processed/{}/read+g", scheme.name()), |b| {
            b.iter(|| {
                read.step(black_box(H)).unwrap();
                black_box(read.momentum())
            })
        });
    }
    group.finish();

    let mut group = c.benchmark_group("trade/exact_flow");
    let flow = FreeBodyFlow::new(&body);
    let g = g0();
    for t in [1.0, 10.0, 1000.0] {
        group.bench_function(format!("advance/T={t}+g"), |b| {
            b.iter(|| {
                flow.advance(black_box(t), black_box(&pi0), Some(&g))
                    .unwrap()
            })
        });
        group.bench_function(format!("advance/T={t}-g"), |b| {
            b.iter(|| flow.advance(black_box(t), black_box(&pi0), None).unwrap())
        });
    }
    group.finish();
}

fn heavy_top(c: &mut Criterion) {
    let mgchi = Vector3::new(0.0, 0.1, 0.5);
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 1.0, mgchi).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let mut group = c.benchmark_group("trade/heavy_top");
    let mut hand = hand_rk4::<true>([1.0, 2.0, 3.0], mgchi, pi0);
    group.bench_function("rk4-hand-written+g", |b| b.iter(|| hand.step(black_box(H))));
    let rk4 = QuaternionRk4::new(top.clone(), pi0, Some(g0())).unwrap();
    bench_step(&mut group, "rk4-quaternion+g", rk4);
    let rkmk = Rkmk4::new(top.clone(), pi0, Some(g0())).unwrap();
    bench_step(&mut group, "rkmk4+g", rkmk);
    let strang = Splitting::new(top.clone(), pi0, Some(g0())).unwrap();
    bench_step(&mut group, "splitting-strang+g", strang);
    let flow = FreeBodyFlow::new(top.body());
    for scheme in SplittingScheme::builtin() {
        let kk =
            KineticKick::new(top.clone(), flow.clone(), scheme.clone(), pi0, Some(g0())).unwrap();
        bench_step(&mut group, &format!("kinetic-kick/{}+g", scheme.name()), kk);
    }
    for scheme in ProcessingScheme::builtin() {
        let strang = Splitting::new(top.clone(), pi0, Some(g0())).unwrap();
        let psi = Processed::composition(strang, scheme.clone()).unwrap();
        bench_step(
            &mut group,
            &format!("processed-strang/{}+g", scheme.name()),
            psi,
        );
        let kk = KineticKick::new(
            top.clone(),
            flow.clone(),
            SplittingScheme::strang(),
            pi0,
            Some(g0()),
        )
        .unwrap();
        let psi = Processed::composition(kk, scheme.clone()).unwrap();
        bench_step(
            &mut group,
            &format!("processed-kinetic-kick/{}+g", scheme.name()),
            psi,
        );
    }
    group.finish();
}

criterion_group!(benches, free_body, heavy_top);
criterion_main!(benches);
