//! Work-precision table of every integrator on the free rigid body 𝕀 = diag(1, 2, 3).
//!
//! For each method (Lie–Poisson and Euler–Poincaré × τ ∈ {exp, Cayley} × θ ∈ {0, ½, 1}, the
//! explicit splitting (Strang of an axisymmetric body and a rotation) and its compositions to order 4 and 6,
//! the exact flow (Jacobi elliptic functions; also in one step to T), the explicit RK4
//! quaternion baseline and RKMK4) and each step h of a ladder, it measures
//!
//! - the global error at T = 10, `max(‖R − R_ref‖_max, ‖Π − Π_ref‖_max / |Π₀|)`, against a
//!   reference computed independently of the crate: classical RK4 on (R as a 3×3 matrix, Π) at
//!   h = 1e-4, Richardson-extrapolated with the h = 2e-4 run (`(16 y_h − y_{2h})/15`);
//! - the cost: ns per step, the best of three timed repetitions of the T = 10 run;
//! - the maximum relative energy error `max_k |E_k − E₀|/E₀` and Casimir error
//!   `max_k ||Π_k|² − |Π₀|²|/|Π₀|²` over T = 1000;
//! - the same over T = 10⁵ for the coarse steps h ≥ 0.05.
//!
//! It prints the table and a summary (the cheapest method reaching each error target) as Markdown,
//! and writes the raw numbers as CSV to the path given as its argument, `docs/work-precision.csv`
//! by default (written whole at the end: an interrupted run leaves the file as it was). Run:
//! `cargo run --release -p lie-integrators --example work_precision [CSV]` (a few minutes), or
//! `cargo xtask docs --only work-precision-example`, which also puts the table into
//! docs/work-precision.md.

use lie_integrators::integrators::baselines::{QuaternionRk4, Rkmk4};
use lie_integrators::integrators::splitting::Splitting;
use lie_integrators::integrators::{
    Composition, CompositionScheme, EulerPoincare, Integrator, LiePoisson,
};
use lie_integrators::lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use lie_integrators::mechanics::exact::ExactFreeBody;
use lie_integrators::mechanics::systems::RigidBody;
use nalgebra::{Matrix3, Vector3};
use std::fmt::Write as _;
use std::time::Instant;

const INERTIA: [f64; 3] = [1.0, 2.0, 3.0];
const T_ERROR: f64 = 10.0;
const T_ENERGY: f64 = 1000.0;
const T_LONG: f64 = 1e5;
const STEPS: [f64; 7] = [0.4, 0.2, 0.1, 0.05, 0.025, 0.0125, 0.00625];
/// Steps also run over T = 10⁵ (10: the exact flow in steps of the T = 10 horizon).
const LONG_STEPS: [f64; 5] = [10.0, 0.4, 0.2, 0.1, 0.05];

fn pi0() -> Vector3<f64> {
    Vector3::new(0.4, 1.0, 0.3)
}
fn r0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.5, 0.8))
}

/// Classical RK4 on `Ṙ = R Ω̂`, `Π̇ = Π × Ω` with R a plain 3×3 matrix (no crate code).
fn reference_rk4(t: f64, n: usize) -> (Matrix3<f64>, Vector3<f64>) {
    let iinv = Matrix3::from_diagonal(&Vector3::from(INERTIA).map(|i| 1.0 / i));
    let f = |r: &Matrix3<f64>, p: &Vector3<f64>| {
        let om = iinv * p;
        (r * om.cross_matrix(), p.cross(&om))
    };
    let h = t / n as f64;
    let (mut r, mut p) = (*r0().as_matrix(), pi0());
    for _ in 0..n {
        let (k1r, k1p) = f(&r, &p);
        let (k2r, k2p) = f(&(r + k1r * (h / 2.0)), &(p + k1p * (h / 2.0)));
        let (k3r, k3p) = f(&(r + k2r * (h / 2.0)), &(p + k2p * (h / 2.0)));
        let (k4r, k4p) = f(&(r + k3r * h), &(p + k3p * h));
        r += (k1r + k2r * 2.0 + k3r * 2.0 + k4r) * (h / 6.0);
        p += (k1p + k2p * 2.0 + k3p * 2.0 + k4p) * (h / 6.0);
    }
    (r, p)
}

#[derive(Clone)]
struct Row {
    method: String,
    h: f64,
    error_t10: f64,
    ns_per_step: f64,
    energy_t1e3: f64,
    casimir_t1e3: f64,
    energy_t1e5: Option<f64>,
    casimir_t1e5: Option<f64>,
}

fn steps_for(t: f64, h: f64) -> usize {
    (t / h).round() as usize
}

/// Max relative energy and Casimir errors over [0, t].
fn invariants<I: Integrator<Group = So3>>(mut integ: I, h: f64, t: f64) -> (f64, f64) {
    let (e0, c0) = (integ.energy(), integ.casimir().unwrap());
    let (mut de, mut dc) = (0.0f64, 0.0f64);
    for _ in 0..steps_for(t, h) {
        integ.step(h).expect("step");
        de = de.max(((integ.energy() - e0) / e0).abs());
        dc = dc.max(((integ.casimir().unwrap() - c0) / c0).abs());
    }
    (de, dc)
}

fn measure<I: Integrator<Group = So3>>(
    make: impl Fn() -> I,
    h: f64,
    reference: &(Matrix3<f64>, Vector3<f64>),
) -> Row {
    let n = steps_for(T_ERROR, h);
    // Error at T = 10, and timing: best of three repetitions of enough T = 10 runs for ≥ 20 ms.
    let mut best = f64::INFINITY;
    let mut end = None;
    for _ in 0..3 {
        let start = Instant::now();
        let mut reps = 0usize;
        while start.elapsed().as_secs_f64() < 0.02 || reps == 0 {
            let mut integ = make();
            for _ in 0..n {
                integ.step(h).expect("step");
            }
            end = Some((
                *integ.configuration().unwrap().as_matrix(),
                integ.momentum(),
            ));
            reps += 1;
        }
        best = best.min(start.elapsed().as_secs_f64() * 1e9 / (reps * n) as f64);
    }
    let (r, p) = end.unwrap();
    let error_t10 = (r - reference.0)
        .amax()
        .max((p - reference.1).amax() / pi0().norm());
    let (energy_t1e3, casimir_t1e3) = invariants(make(), h, T_ENERGY);
    let long = LONG_STEPS
        .contains(&h)
        .then(|| invariants(make(), h, T_LONG));
    Row {
        method: make().method_name(),
        h,
        error_t10,
        ns_per_step: best,
        energy_t1e3,
        casimir_t1e3,
        energy_t1e5: long.map(|l| l.0),
        casimir_t1e5: long.map(|l| l.1),
    }
}

fn ladder<I: Integrator<Group = So3>>(
    rows: &mut Vec<Row>,
    reference: &(Matrix3<f64>, Vector3<f64>),
    make: impl Fn() -> I,
) {
    ladder_of(rows, reference, make, &STEPS);
}

fn ladder_of<I: Integrator<Group = So3>>(
    rows: &mut Vec<Row>,
    reference: &(Matrix3<f64>, Vector3<f64>),
    make: impl Fn() -> I,
    steps: &[f64],
) {
    for &h in steps {
        let row = measure(&make, h, reference);
        print_row(&row);
        rows.push(row);
    }
}

fn geometric<T: Tau<So3>>(
    rows: &mut Vec<Row>,
    body: &RigidBody,
    reference: &(Matrix3<f64>, Vector3<f64>),
) {
    for theta in [0.0, 0.5, 1.0] {
        ladder(rows, reference, || {
            LiePoisson::<So3, T, _>::new(body.clone(), theta, pi0(), Some(r0())).unwrap()
        });
    }
    for theta in [0.0, 0.5, 1.0] {
        ladder(rows, reference, || {
            EulerPoincare::<So3, T, _>::from_momentum(body.clone(), theta, pi0(), Some(r0()))
                .unwrap()
        });
    }
}

fn opt(x: Option<f64>) -> String {
    x.map_or("—".into(), |v| format!("{v:.2e}"))
}

fn print_row(r: &Row) {
    println!(
        "| {:<38} | {:>7} | {:>9.2e} | {:>8.1} | {:>9.2e} | {:>9.2e} | {:>9} | {:>9} |",
        r.method,
        r.h,
        r.error_t10,
        r.ns_per_step,
        r.energy_t1e3,
        r.casimir_t1e3,
        opt(r.energy_t1e5),
        opt(r.casimir_t1e5)
    );
}

fn main() {
    let body = RigidBody::principal([INERTIA[0], INERTIA[1], INERTIA[2]]).unwrap();
    let start = Instant::now();
    let fine = reference_rk4(T_ERROR, 100_000);
    let coarse = reference_rk4(T_ERROR, 50_000);
    let reference = (
        (fine.0 * 16.0 - coarse.0) / 15.0,
        (fine.1 * 16.0 - coarse.1) / 15.0,
    );
    let ref_err = ((fine.0 - coarse.0).amax()).max((fine.1 - coarse.1).amax() / pi0().norm());
    println!(
        "Free rigid body 𝕀 = diag{INERTIA:?}, Π₀ = {:?}, R₀ = exp((0.3, −0.5, 0.8)^).\n",
        pi0().as_slice()
    );
    println!(
        "Reference at T = {T_ERROR}: RK4 h = 1e-4 and 2e-4, Richardson; their difference {ref_err:.1e} \
         bounds the h = 1e-4 error by {:.1e}, the extrapolated one is far below.\n",
        ref_err / 15.0
    );
    println!(
        "| {:<38} | {:>7} | {:>9} | {:>8} | {:>9} | {:>9} | {:>9} | {:>9} |",
        "method", "h", "err T=10", "ns/step", "ΔE T=1e3", "ΔC T=1e3", "ΔE T=1e5", "ΔC T=1e5"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    let mut rows = Vec::new();
    ladder(&mut rows, &reference, || {
        QuaternionRk4::new(body.clone(), pi0(), Some(r0())).unwrap()
    });
    ladder(&mut rows, &reference, || {
        Rkmk4::new(body.clone(), pi0(), Some(r0())).unwrap()
    });
    geometric::<Cayley>(&mut rows, &body, &reference);
    geometric::<ExpMap>(&mut rows, &body, &reference);
    let strang = || Splitting::new(body.clone(), pi0(), Some(r0())).unwrap();
    ladder(&mut rows, &reference, strang);
    for scheme in [
        CompositionScheme::triple_jump(4).unwrap(),
        CompositionScheme::kahan_li_6(),
    ] {
        ladder(&mut rows, &reference, || {
            Composition::new(strang(), scheme.clone()).unwrap()
        });
    }
    // The exact flow: its error does not depend on h, so it also runs in one step to T.
    let mut exact_steps = vec![T_ERROR];
    exact_steps.extend(STEPS);
    ladder_of(
        &mut rows,
        &reference,
        || ExactFreeBody::new(body.clone(), pi0(), Some(r0())).unwrap(),
        &exact_steps,
    );

    // Summary: the cheapest (cost = ns/step × steps over T) row meeting each target, among the
    // baselines (rk4, rkmk4) and among the geometric methods, and their ratio.
    let baseline = |r: &&Row| r.method.starts_with("rk");
    let cheapest = |rows: &[Row], ok: &dyn Fn(&Row) -> bool, base: bool| -> Option<Row> {
        rows.iter()
            .filter(|r| ok(r) && baseline(r) == base)
            .min_by(|a, b| {
                (a.ns_per_step / a.h)
                    .partial_cmp(&(b.ns_per_step / b.h))
                    .unwrap()
            })
            .cloned()
    };
    println!("\n```text");
    let summary = |title: &str, targets: &[f64], ok: &dyn Fn(&Row, f64) -> bool, t: f64| {
        println!("{title}");
        for &target in targets {
            let b = cheapest(&rows, &|r| ok(r, target), true);
            let g = cheapest(&rows, &|r| ok(r, target), false);
            let cost = |r: &Row| r.ns_per_step * (t / r.h).ceil().max(1.0) * 1e-3;
            let show = |r: &Option<Row>| match r {
                Some(r) => format!("{} h = {} ({:.1} µs)", r.method, r.h, cost(r)),
                None => "none of the ladder".into(),
            };
            let ratio = match (&b, &g) {
                (Some(b), Some(g)) => format!("{:.2}", cost(g) / cost(b)),
                _ => "—".into(),
            };
            println!(
                "  ≤ {target:.0e}: baseline {}; geometric {}; geometric/baseline {ratio}",
                show(&b),
                show(&g)
            );
        }
        println!();
    };
    summary(
        "cheapest run reaching each error at T = 10 (cost = ns/step × 10/h):",
        &[1e-2, 1e-4, 1e-6, 1e-8, 1e-10],
        &|r, target| r.error_t10 <= target,
        T_ERROR,
    );
    summary(
        "cheapest run keeping the energy error over T = 1e3 below each target (cost of T = 1e3):",
        &[1e-3, 1e-5, 1e-7, 1e-9],
        &|r, target| r.energy_t1e3 <= target,
        T_ENERGY,
    );
    summary(
        "cheapest run keeping the energy error over T = 1e5 below each target (cost of T = 1e5):",
        &[1e-2, 1e-3, 1e-4, 1e-5],
        &|r, target| r.energy_t1e5.is_some_and(|e| e <= target),
        T_LONG,
    );

    println!("```");

    let mut csv = String::from(
        "method,h,error_t10,ns_per_step,max_rel_energy_error_t1e3,max_rel_casimir_error_t1e3,\
         max_rel_energy_error_t1e5,max_rel_casimir_error_t1e5\n",
    );
    for r in &rows {
        let o = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v:e}"));
        writeln!(
            csv,
            "\"{}\",{},{:e},{:.1},{:e},{:e},{},{}",
            r.method,
            r.h,
            r.error_t10,
            r.ns_per_step,
            r.energy_t1e3,
            r.casimir_t1e3,
            o(r.energy_t1e5),
            o(r.casimir_t1e5)
        )
        .unwrap();
    }
    let path = std::env::args().nth(1).map_or_else(
        || concat!(env!("CARGO_MANIFEST_DIR"), "/docs/work-precision.csv").into(),
        std::path::PathBuf::from,
    );
    // Whole or not at all: a temporary file beside the target, renamed over it.
    let tmp = path.with_extension("csv.tmp");
    std::fs::write(&tmp, csv).expect("write the CSV");
    std::fs::rename(&tmp, &path).expect("move the CSV into place");
    eprintln!(
        "wrote {} ({} rows) in {:.0} s",
        path.display(),
        rows.len(),
        start.elapsed().as_secs_f64()
    );
}
