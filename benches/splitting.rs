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
//!   hand-written RK4, `QuaternionRk4`, `Rkmk4`, Strang (the body's split) and kick, the exact kinetic
//!   flow with kicks (Strang, Blanes–Moan 4 (S6) and 6 (S10) coefficients), and the processed
//!   Strang and kinetic–kick (Strang) splittings of each processing scheme.
//! - `trade/satellite`: the SE(3) satellite (𝕀 = diag(1, 2, 3), m = 2, GM = 400, r ≈ 20), h = 0.01:
//!   `Rkmk4`, Lie–Poisson Cayley θ = ½, Strang with the body's two in-place pieces, and Strang
//!   with the four generic pieces (`Se3::exp` / Ad* flows) it replaced.
//!
//! Run: `cargo bench -p lie-integrators --bench splitting -- --warm-up-time 1 --measurement-time 2`.
//! The figures are in docs/work-precision.md.

use criterion::{
    criterion_group, criterion_main, measurement::WallTime, BenchmarkGroup, Criterion,
};
use integrators::baselines::{QuaternionRk4, Rkmk4};
use integrators::processing::{Processed, ProcessingScheme};
use integrators::splitting::SplitSystem;
use integrators::splitting::{KineticKick, Splitting, SplittingScheme};
use integrators::{Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, Se3, So3};
use mechanics::exact::{ExactFreeBody, FreeBodyFlow};
use mechanics::modified::{ModifiedLiePoisson, ModifiedScheme};
use mechanics::systems::{HeavyTop, RigidBody, RigidBodySe3};
use nalgebra::{Matrix3, Vector3, Vector6};
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
    HandRk4::new(moments, mgchi, pi0, g0().as_matrix())
}

fn free_body(c: &mut Criterion) {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
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

/// The SE(3) satellite's splitting by generic pieces: four (the three principal-axis rotations,
/// the translation) by the trait's generic `Se3::exp` / Ad* flows — the same-run comparison for
/// `RigidBodySe3`'s own two in-place pieces.
#[derive(Clone)]
struct FourGenericPieces(RigidBodySe3);

impl System<Se3> for FourGenericPieces {
    fn hamiltonian(&self, mu: &Vector6<f64>) -> f64 {
        self.0.hamiltonian(mu)
    }
    fn velocity(&self, mu: &Vector6<f64>) -> Vector6<f64> {
        self.0.velocity(mu)
    }
    fn momentum(&self, xi: &Vector6<f64>) -> Vector6<f64> {
        self.0.momentum(xi)
    }
    fn has_potential(&self) -> bool {
        self.0.has_potential()
    }
    fn potential(&self, g: &Se3) -> f64 {
        self.0.potential(g)
    }
    fn potential_differential(&self, g: &Se3) -> Vector6<f64> {
        self.0.potential_differential(g)
    }
}

impl SplitSystem<Se3> for FourGenericPieces {
    fn pieces(&self) -> usize {
        4
    }
    fn piece_velocity(&self, i: usize, mu: &Vector6<f64>) -> Vector6<f64> {
        let pi = mu.fixed_rows::<3>(0).into_owned();
        if i < 3 {
            let w = self.0.body().principal_piece_velocity(i, &pi);
            Vector6::new(w.x, w.y, w.z, 0.0, 0.0, 0.0)
        } else {
            let v = mu.fixed_rows::<3>(3) / self.0.mass();
            Vector6::new(0.0, 0.0, 0.0, v.x, v.y, v.z)
        }
    }
}

/// A satellite on SE(3) (𝕀 = diag(1, 2, 3), m = 2, GM = 400, a tumbling body started at r = 20
/// with the circular orbit's speed; the gravity gradient exchanges energy between spin and orbit,
/// so r wanders in 18–22 over the bench's millions of steps — at r = 5 the body would fall into
/// the centre), h = 0.01: RKMK4 and Lie–Poisson Cayley θ = ½ on SE(3), the Strang
/// splitting with the body's two in-place pieces and with the four generic ones.
fn satellite(c: &mut Criterion) {
    let sat = RigidBodySe3::satellite(
        2.0,
        Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
        50.0,
    )
    .unwrap();
    let g = Se3::from_parts(g0(), Vector3::new(20.0, 0.0, 0.0));
    // Body-frame momentum of a circular orbit's velocity √(GM/r) along e₂ in space.
    let p = g0()
        .as_matrix()
        .tr_mul(&Vector3::new(0.0, 2.0 * (50.0_f64 / 5.0).sqrt(), 0.0));
    let mu0 = Vector6::new(0.5, 1.0, 0.2, p.x, p.y, p.z);
    let mut group = c.benchmark_group("trade/satellite");
    bench_step(
        &mut group,
        "rkmk4+g",
        Rkmk4::new(sat.clone(), mu0, Some(g)).unwrap(),
    );
    bench_step(
        &mut group,
        "lp/cayley/0.5+g",
        LiePoisson::<Se3, Cayley, _>::new(sat.clone(), 0.5, mu0, Some(g)).unwrap(),
    );
    bench_step(
        &mut group,
        "splitting-strang+g",
        Splitting::new(sat.clone(), mu0, Some(g)).unwrap(),
    );
    bench_step(
        &mut group,
        "splitting-strang-four-generic-pieces+g",
        Splitting::new(FourGenericPieces(sat), mu0, Some(g)).unwrap(),
    );
    group.finish();
}

criterion_group!(benches, free_body, heavy_top, satellite);
criterion_main!(benches);
