//! The speed side of the speed–accuracy trade: ns per step of the explicit splittings, the exact
//! free-body flow and the kinetic–kick schemes, against the best plain competitor — a hand-written
//! nalgebra RK4 on (q, Π) — and the library's own baselines, all in the same run.
//!
//! Groups:
//! - `trade/free_body`: 𝕀 = diag(1, 2, 3), Π₀ = (0.5, 1, 0.2), R₀ given, h = 0.01: hand-written
//!   RK4, `QuaternionRk4`, `Rkmk4`, Strang of the principal-axis rotations, the exact flow as a
//!   method (`ExactFreeBody`), each with the attitude (`+g`); Π alone (`-g`) for RK4, Strang and
//!   the exact flow; the implicit Lie–Poisson step (Cayley, θ = ½ and 0, `+g`) for the issue's
//!   ratio against the hand-written RK4.
//! - `trade/exact_flow`: one call of `FreeBodyFlow::advance` to T = 1, 10, 1000 (its cost does
//!   not grow with T), with and without R.
//! - `trade/heavy_top`: an asymmetric top 𝕀 = diag(1, 2, 3), mgχ = (0, 0.1, 0.5), h = 0.01:
//!   hand-written RK4, `QuaternionRk4`, `Rkmk4`, Strang of the axes + kick, and exact kinetic flow
//!   + kicks with Strang, Blanes–Moan 4 (S6) and 6 (S10) coefficients.
//!
//! Run: `cargo bench -p lie-integrators --bench splitting -- --warm-up-time 1 --measurement-time 2`.
//! The figures are in docs/work-precision.md.

use criterion::{
    criterion_group, criterion_main, measurement::WallTime, BenchmarkGroup, Criterion,
};
use integrators::baselines::{QuaternionRk4, Rkmk4};
use integrators::exact::{ExactFreeBody, FreeBodyFlow};
use integrators::splitting::{KineticKick, Splitting, SplittingScheme};
use integrators::systems::{HeavyTop, RigidBody};
use integrators::{Integrator, LiePoisson};
use lie_groups::{Cayley, LieGroup, So3};
use nalgebra::{Quaternion, Vector3};
use std::hint::black_box;

const H: f64 = 0.01;

/// The plain competitor: classical RK4 on (q, Π) ∈ ℝ⁴ × ℝ³ for a body with principal moments
/// `1/inv_i` and a constant body-frame gravity arm `mgchi` (zero for the free body), written as
/// anyone would with nalgebra: `q̇ = ½ q ⊗ (0, Ω)`, `Π̇ = Π × Ω + mgχ × Rᵀe₃`, q renormalised
/// once per step.
///
/// `GRAVITY` is a compile-time switch, as a hand-written free-body step simply has no gravity
/// code: a run-time `mgχ ≠ 0` test in each stage costs the free-body step ~40 % (it was
/// measured at 1.45× the branch-free step) and would flatter every ratio against it.
#[derive(Clone)]
struct HandRk4<const GRAVITY: bool> {
    inv_i: Vector3<f64>,
    mgchi: Vector3<f64>,
    q: Quaternion<f64>,
    pi: Vector3<f64>,
}

impl<const GRAVITY: bool> HandRk4<GRAVITY> {
    #[inline]
    fn rate(&self, q: &Quaternion<f64>, pi: &Vector3<f64>) -> (Quaternion<f64>, Vector3<f64>) {
        let omega = pi.component_mul(&self.inv_i);
        let dq = (q * Quaternion::from_imag(omega)) * 0.5;
        let mut dpi = pi.cross(&omega);
        if GRAVITY {
            // Rᵀe₃ for R = R(q/|q|): the third row of the rotation matrix.
            let (w, x, y, z) = (q.w, q.i, q.j, q.k);
            let s = 1.0 / q.norm_squared();
            let up = Vector3::new(
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                w * w - x * x - y * y + z * z,
            ) * s;
            dpi += self.mgchi.cross(&up);
        }
        (dq, dpi)
    }
    #[inline]
    fn step(&mut self, h: f64) {
        let (q, pi) = (self.q, self.pi);
        let (l1, k1) = self.rate(&q, &pi);
        let (l2, k2) = self.rate(&(q + l1 * (0.5 * h)), &(pi + k1 * (0.5 * h)));
        let (l3, k3) = self.rate(&(q + l2 * (0.5 * h)), &(pi + k2 * (0.5 * h)));
        let (l4, k4) = self.rate(&(q + l3 * h), &(pi + k3 * h));
        let q1 = q + (l1 + (l2 + l3) * 2.0 + l4) * (h / 6.0);
        self.pi = pi + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0);
        self.q = q1 / q1.norm();
    }
}

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
    group.finish();
}

criterion_group!(benches, free_body, heavy_top);
criterion_main!(benches);
