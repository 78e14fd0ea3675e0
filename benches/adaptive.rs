//! Tolerance-driven runs: the adaptive pairs of `integrators::adaptive` and the (q, Π)
//! baselines against `ode_solvers`' `Dopri5` and `Dop853` (Hairer's codes in Rust) on the same
//! (q, Π) right-hand side, and the cost of error control per accepted step.
//!
//! Groups (each benchmark is one whole run, constructor included):
//! - `adaptive/free_body/{tol}`: 𝕀 = diag(2, 3, 4), Π₀ = (1, 0.5, −0.3), R₀ = 60° about e₃, to
//!   T = 10 at rtol = atol = tol (the trade's free-body scene);
//! - `adaptive/fast_heavy_top/{tol}`: the trade's fast heavy top (examples/scenes/fast-heavy-top.toml)
//!   to T = 5;
//! - `adaptive/overhead/...`: a method's adaptive run against the same method's fixed steps, as
//!   many as the adaptive run accepted, over the same interval: the price of the estimate, the
//!   controller and the bookkeeping per accepted step.
//!
//! Before timing, each run's accepted and rejected steps and its error at T (against a DOP853
//! run at T/20000) are printed to stderr, so that the timings can be read as work per accuracy.
//! `ode_solvers` runs with `OutputType::Sparse` (no dense-output stages) and its default
//! controllers, which are Hairer's as ours (the accepted step counts agree to a few steps).
//! Run: `cargo bench -p lie-integrators --bench adaptive -- --warm-up-time 1 --measurement-time 2`.

use criterion::{
    criterion_group, criterion_main, measurement::WallTime, BenchmarkGroup, Criterion,
};
use integrators::adaptive::{Adaptive, EmbeddedPair, RkmkDop853, RkmkDopri5, Tolerance};
use integrators::baselines::{QuaternionDop853, QuaternionDopri5};
use integrators::{Integrator, System};
use lie_groups::{LieGroup, So3};
use mechanics::systems::{HeavyTop, RigidBody};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use ode_solvers::{Dop853, Dopri5, OutputType};
use std::hint::black_box;

type State = ode_solvers::SVector<f64, 7>;

/// The (q, Π) equations of a body with principal moments `1/inv_i` and gravity arm `mgchi`
/// (zero for the free body) for `ode_solvers`: `q̇ = ½ q ⊗ (0, Ω)`, `Π̇ = Π × Ω + Rᵀe₃ × mgχ`
/// with R = R(q/|q|), as `benches/common/hand_rk4.rs` writes them.
#[derive(Clone, Copy)]
struct QuaternionBody<const GRAVITY: bool> {
    inv_i: [f64; 3],
    mgchi: [f64; 3],
}

impl<const GRAVITY: bool> ode_solvers::System<f64, State> for QuaternionBody<GRAVITY> {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        let (w, x, yy, z) = (y[0], y[1], y[2], y[3]);
        let pi = [y[4], y[5], y[6]];
        let om = [
            pi[0] * self.inv_i[0],
            pi[1] * self.inv_i[1],
            pi[2] * self.inv_i[2],
        ];
        // ½ q ⊗ (0, Ω)
        dy[0] = 0.5 * (-x * om[0] - yy * om[1] - z * om[2]);
        dy[1] = 0.5 * (w * om[0] + yy * om[2] - z * om[1]);
        dy[2] = 0.5 * (w * om[1] + z * om[0] - x * om[2]);
        dy[3] = 0.5 * (w * om[2] + x * om[1] - yy * om[0]);
        let mut dpi = [
            pi[1] * om[2] - pi[2] * om[1],
            pi[2] * om[0] - pi[0] * om[2],
            pi[0] * om[1] - pi[1] * om[0],
        ];
        if GRAVITY {
            let s = 1.0 / (w * w + x * x + yy * yy + z * z);
            let up = [
                2.0 * (x * z - w * yy) * s,
                2.0 * (yy * z + w * x) * s,
                (w * w - x * x - yy * yy + z * z) * s,
            ];
            let m = self.mgchi;
            dpi[0] += up[1] * m[2] - up[2] * m[1];
            dpi[1] += up[2] * m[0] - up[0] * m[2];
            dpi[2] += up[0] * m[1] - up[1] * m[0];
        }
        dy[4] = dpi[0];
        dy[5] = dpi[1];
        dy[6] = dpi[2];
    }
}

/// A scene: the system for the library, the same equations for `ode_solvers`, the start, T.
struct Scene<S, const GRAVITY: bool> {
    name: &'static str,
    system: S,
    plain: QuaternionBody<GRAVITY>,
    pi0: Vector3<f64>,
    r0: So3,
    t_end: f64,
}

impl<S: System<So3> + Clone, const GRAVITY: bool> Scene<S, GRAVITY> {
    fn y0(&self) -> State {
        let q = UnitQuaternion::from(self.r0).into_inner();
        State::from_column_slice(&[q.w, q.i, q.j, q.k, self.pi0.x, self.pi0.y, self.pi0.z])
    }
    /// (Π, R) at T of a fine fixed-step DOP853 run.
    fn reference(&self) -> (Vector3<f64>, So3) {
        let mut m = QuaternionDop853::new(self.system.clone(), self.pi0, Some(self.r0)).unwrap();
        let n = 20_000;
        integrators::integrate(&mut m, self.t_end / n as f64, n, |_| {}).unwrap();
        (m.momentum(), *m.configuration().unwrap())
    }
    fn error(&self, pi: &Vector3<f64>, r: &So3, reference: &(Vector3<f64>, So3)) -> f64 {
        ((pi - reference.0).amax() / reference.0.amax()).max(r.matrix_distance(&reference.1))
    }
    fn dopri5(&self, tol: f64) -> Dopri5<f64, State, QuaternionBody<GRAVITY>> {
        Dopri5::from_param(
            self.plain,
            0.0,
            self.t_end,
            self.t_end,
            self.y0(),
            tol,
            tol,
            0.9,
            0.04,
            0.2,
            10.0,
            self.t_end,
            0.0,
            1_000_000,
            1_000_000,
            OutputType::Sparse,
        )
    }
    fn dop853(&self, tol: f64) -> Dop853<f64, State, QuaternionBody<GRAVITY>> {
        Dop853::from_param(
            self.plain,
            0.0,
            self.t_end,
            self.t_end,
            self.y0(),
            tol,
            tol,
            0.9,
            0.0,
            1.0 / 3.0,
            6.0,
            self.t_end,
            0.0,
            1_000_000,
            1_000_000,
            OutputType::Sparse,
        )
    }
    /// ode_solvers' final (Π, R).
    fn plain_final(y: &State) -> (Vector3<f64>, So3) {
        let q = UnitQuaternion::from_quaternion(Quaternion::new(y[0], y[1], y[2], y[3]));
        (Vector3::new(y[4], y[5], y[6]), So3::from(q))
    }

    fn run<M: EmbeddedPair<Group = So3>>(&self, make: impl Fn() -> M, tol: f64) -> Adaptive<M> {
        let mut run = Adaptive::new(make(), Tolerance::new(tol, tol).unwrap());
        run.advance_to(self.t_end).unwrap();
        run
    }

    fn bench(&self, c: &mut Criterion) {
        let reference = self.reference();
        let (s, pi0, r0) = (&self.system, self.pi0, Some(self.r0));
        let q5 = || QuaternionDopri5::new(s.clone(), pi0, r0).unwrap();
        let q8 = || QuaternionDop853::new(s.clone(), pi0, r0).unwrap();
        let k5 = || RkmkDopri5::new(s.clone(), pi0, r0).unwrap();
        let k8 = || RkmkDop853::new(s.clone(), pi0, r0).unwrap();
        for tol in [1e-6, 1e-9, 1e-12] {
            let mut group = c.benchmark_group(format!("adaptive/{}/{tol:e}", self.name));
            self.library(&mut group, "dopri5(quaternion)", q5, tol, &reference);
            self.library(&mut group, "dop853(quaternion)", q8, tol, &reference);
            self.library(&mut group, "rkmk-dopri5", k5, tol, &reference);
            self.library(&mut group, "rkmk-dop853", k8, tol, &reference);
            // ode_solvers on the same equations.
            let mut d5 = self.dopri5(tol);
            let st = d5.integrate().unwrap();
            let (pi, r) = Self::plain_final(d5.y_out().last().unwrap());
            eprintln!(
                "{} tol {tol:e} ode_solvers::Dopri5: {} accepted, {} rejected, error {:.2e}",
                self.name,
                st.accepted_steps,
                st.rejected_steps,
                self.error(&pi, &r, &reference)
            );
            group.bench_function("ode_solvers::Dopri5", |b| {
                b.iter(|| black_box(self.dopri5(black_box(tol)).integrate().unwrap()))
            });
            let mut d8 = self.dop853(tol);
            let st = d8.integrate().unwrap();
            let (pi, r) = Self::plain_final(d8.y_out().last().unwrap());
            eprintln!(
                "{} tol {tol:e} ode_solvers::Dop853: {} accepted, {} rejected, error {:.2e}",
                self.name,
                st.accepted_steps,
                st.rejected_steps,
                self.error(&pi, &r, &reference)
            );
            group.bench_function("ode_solvers::Dop853", |b| {
                b.iter(|| black_box(self.dop853(black_box(tol)).integrate().unwrap()))
            });
            group.finish();
        }
        // The price of error control per accepted step: the adaptive run against as many fixed
        // steps of the same method over the same interval.
        let mut group = c.benchmark_group(format!("adaptive/overhead/{}", self.name));
        self.overhead(&mut group, "dopri5(quaternion)", q5);
        self.overhead(&mut group, "dop853(quaternion)", q8);
        self.overhead(&mut group, "rkmk-dopri5", k5);
        self.overhead(&mut group, "rkmk-dop853", k8);
        group.finish();
    }

    fn library<M: EmbeddedPair<Group = So3>>(
        &self,
        group: &mut BenchmarkGroup<'_, WallTime>,
        id: &str,
        make: impl Fn() -> M,
        tol: f64,
        reference: &(Vector3<f64>, So3),
    ) {
        let run = self.run(&make, tol);
        let m = run.method();
        eprintln!(
            "{} tol {tol:e} {id}: {} accepted, {} rejected, error {:.2e}",
            self.name,
            run.stats().accepted,
            run.stats().rejected,
            self.error(&m.momentum(), m.configuration().unwrap(), reference)
        );
        group.bench_function(id, |b| {
            b.iter(|| black_box(self.run(&make, black_box(tol)).method().momentum()))
        });
    }

    fn overhead<M: EmbeddedPair<Group = So3>>(
        &self,
        group: &mut BenchmarkGroup<'_, WallTime>,
        id: &str,
        make: impl Fn() -> M,
    ) {
        let tol = 1e-9;
        let run = self.run(&make, tol);
        let n = run.stats().accepted;
        eprintln!(
            "{} overhead {id}: {n} accepted, {} rejected at {tol:e}",
            self.name,
            run.stats().rejected
        );
        group.bench_function(format!("{id}/adaptive"), |b| {
            b.iter(|| black_box(self.run(&make, black_box(tol)).method().momentum()))
        });
        let h = self.t_end / n as f64;
        group.bench_function(format!("{id}/fixed"), |b| {
            b.iter(|| {
                let mut m = make();
                integrators::integrate(&mut m, black_box(h), n, |_| {}).unwrap();
                black_box(m.momentum())
            })
        });
    }
}

fn free_body(c: &mut Criterion) {
    let r0 = So3::from(UnitQuaternion::from_axis_angle(
        &Vector3::z_axis(),
        std::f64::consts::FRAC_PI_3,
    ));
    Scene::<_, false> {
        name: "free_body",
        system: RigidBody::principal([2.0, 3.0, 4.0]).unwrap(),
        plain: QuaternionBody {
            inv_i: [0.5, 1.0 / 3.0, 0.25],
            mgchi: [0.0; 3],
        },
        pi0: Vector3::new(1.0, 0.5, -0.3),
        r0,
        t_end: 10.0,
    }
    .bench(c);
}

fn fast_heavy_top(c: &mut Criterion) {
    let chi = Vector3::new(0.1, 0.0, 1.0);
    Scene::<_, true> {
        name: "fast_heavy_top",
        system: HeavyTop::principal([1.0, 1.5, 0.5], 1.0, 9.81, chi).unwrap(),
        plain: QuaternionBody {
            inv_i: [1.0, 1.0 / 1.5, 2.0],
            mgchi: [0.981, 0.0, 9.81],
        },
        pi0: Vector3::new(0.5, 0.3, 10.0),
        r0: So3::exp(&Vector3::new(0.3, 0.0, 0.0)),
        t_end: 5.0,
    }
    .bench(c);
}

criterion_group!(benches, free_body, fast_heavy_top);
criterion_main!(benches);
