//! `lie-sim trade`: the speed–accuracy trade of every method that applies to a scene.
//!
//! Every candidate method (each Lie integrator × τ ∈ {exp, cayley} × θ ∈ {0, ½, 1}, the
//! compositions [`COMPOSITIONS`] of the θ = ½ Lie–Poisson method for each τ, the Strang splitting
//! and its compositions [`SPLITTING_COMPOSITIONS`], the kinetic–kick splittings (Strang,
//! Blanes–Moan 4 and 6), the exact free-body flow, rk4 and rkmk4) runs the scene over a ladder of
//! steps ([`crate::ladder`]: from the scene's time scale, h ω = 1 halved down to the reference
//! floor, or the `--steps` list; the exact flow also in one step to T); a composite step of size h
//! is s base steps. Methods that do not apply to the system (euler-arnold with a potential, rk4
//! off SO(3), the exact flow off the free body, …) are left out. Each run is compared at the final
//! time T with a reference made independently of the candidates, with its estimated error
//! ([`crate::reference`]: the exact flow on the free rigid body, elsewhere Gragg–Bulirsch–Stoer
//! refined until two runs agree to `--reference-tolerance`, or the user's `--reference`). An error
//! below the reference's estimated error (the floor) measures the reference, not the method: the
//! table prints it as `unresolved`, the CSV leaves its `error` cell empty with `error_status`
//! `unresolved`, and the plot draws it as ▽ on the floor line. The table reports, per run, the
//! cost (ns per step, total time), the error at T and the long-horizon measures of
//! [`crate::invariants`]: the maximum relative energy, Casimir and spatial momentum-map errors
//! over the run (`-` where they do not apply); `--metric` picks the one the plot draws against
//! cost.
//!
//! Error at T: `max(‖μ − μ_ref‖_∞ / ‖μ_ref‖_∞, ‖g − g_ref‖_∞ / max(1, ‖g_ref‖_∞))`, the group term
//! only where both runs reconstruct g. Timing covers the steps and the read of the state at T
//! (for a processed method that read applies its processor P, part of the run's cost): the
//! invariants are sampled every [`ENERGY_SAMPLE`] steps outside the timed intervals, so that the
//! table measures the integrator, not the bookkeeping, and nothing of the trajectory is stored.

use crate::error::SimError;
use crate::invariants::Monitor;
use crate::output::write_atomic;
use crate::plot::{plot_loglog, Annotations, Curve, Marker, SeriesStyle};
use crate::reference::{meets, Reference};
use crate::run::Cell;
use crate::scene::{steps_for, Method, MethodSpec, Scene, System, TauKind};
use crate::sim::{build, Simulation};
use integrators::processing::ProcessingScheme;
use integrators::splitting::SplittingScheme;
use integrators::{CompositionScheme, MethodInfo};
use plotters::style::RGBColor;
use std::fmt::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

/// Steps between two energy samples (and two clock reads) in a timed run.
pub const ENERGY_SAMPLE: u64 = 8;

/// Rows whose error is below this multiple of the reference's estimated error measure the
/// reference, not the method: they are left out of the order fit.
pub const ORDER_FIT_REFERENCE_MARGIN: f64 = 10.0;

/// Rows whose error is above this are outside the asymptotic regime (a phase error of order one
/// saturates): they are left out of the order fit.
pub const ORDER_FIT_MAX_ERROR: f64 = 0.1;

/// The θ values swept for each Lie method.
pub const THETAS: [f64; 3] = [0.0, 0.5, 1.0];

/// The composition schemes of the trade, each on the θ = ½ Lie–Poisson method with τ = exp and
/// τ = cayley: the cheapest order 4 (3 stages) and the optimised order-6 (9 stages) and order-8
/// (17 stages) schemes, so that the plot shows where each order starts to pay for its stages.
pub const COMPOSITIONS: [&str; 3] = ["triple-jump-4", "kahan-li-6", "kahan-li-8"];

fn scheme(name: &str) -> CompositionScheme {
    // The names above are built-in schemes of the integrators crate (unit test
    // `trade_compositions_are_builtin_schemes`).
    name.parse()
        .unwrap_or_else(|_| CompositionScheme::kahan_li_8())
}

/// Every method the trade tries, in table order.
pub fn candidates() -> Vec<MethodSpec> {
    let mut v = Vec::new();
    for method in [
        Method::LiePoisson,
        Method::EulerPoincare,
        Method::EulerArnold,
    ] {
        for tau in [TauKind::Exp, TauKind::Cayley] {
            for theta in THETAS {
                v.push(MethodSpec {
                    method,
                    tau: Some(tau),
                    theta: Some(theta),
                    composition: None,
                    splitting: None,
                    processing: None,
                    modified: None,
                });
            }
        }
    }
    for name in COMPOSITIONS {
        for tau in [TauKind::Exp, TauKind::Cayley] {
            v.push(MethodSpec {
                method: Method::LiePoisson,
                tau: Some(tau),
                theta: Some(0.5),
                composition: Some(scheme(name)),
                splitting: None,
                processing: None,
                modified: None,
            });
        }
    }
    for (theta, order) in MODIFIED {
        for tau in [TauKind::Exp, TauKind::Cayley] {
            v.push(MethodSpec {
                method: Method::LiePoisson,
                tau: Some(tau),
                theta: Some(theta),
                composition: None,
                splitting: None,
                processing: None,
                modified: Some(order),
            });
        }
    }
    for p in ProcessingScheme::builtin() {
        for tau in [TauKind::Exp, TauKind::Cayley] {
            v.push(MethodSpec {
                method: Method::LiePoisson,
                tau: Some(tau),
                theta: Some(0.5),
                processing: Some(p.clone()),
                ..MethodSpec::plain(Method::LiePoisson, None)
            });
        }
        v.push(MethodSpec {
            processing: Some(p.clone()),
            ..MethodSpec::plain(Method::Splitting, None)
        });
        v.push(MethodSpec {
            processing: Some(p),
            splitting: Some(SplittingScheme::strang()),
            ..MethodSpec::plain(Method::KineticKick, None)
        });
    }
    v.push(MethodSpec::plain(Method::Splitting, None));
    for name in SPLITTING_COMPOSITIONS {
        v.push(MethodSpec {
            composition: Some(scheme(name)),
            ..MethodSpec::plain(Method::Splitting, None)
        });
    }
    for s in SplittingScheme::builtin() {
        v.push(MethodSpec {
            splitting: Some(s),
            ..MethodSpec::plain(Method::KineticKick, None)
        });
    }
    v.push(MethodSpec::plain(Method::Exact, None));
    v.push(MethodSpec::plain(Method::Rk4, None));
    v.push(MethodSpec::plain(Method::Rkmk4, Some(TauKind::Exp)));
    v
}

/// The modified Lie–Poisson methods of the trade, as (θ, order): every one derived (for τ = exp
/// the θ = 0 and θ = ½ schemes are the same map, θ = 0 the cheaper step).
pub const MODIFIED: [(f64, u32); 4] = [(0.5, 4), (0.0, 4), (0.5, 6), (0.0, 6)];

/// The compositions of the Strang splitting in the trade: order 4 (3 and 5 stages) and 6.
pub const SPLITTING_COMPOSITIONS: [&str; 3] = ["triple-jump-4", "mclachlan-4", "kahan-li-6"];

/// The steps a method runs in the trade: the ladder, and for the exact flow (whose error does not
/// depend on h and whose cost per step does not depend on h either) one step to T first.
fn steps_of(m: &MethodSpec, ladder: &[f64], duration: f64) -> Vec<f64> {
    if m.method == Method::Exact {
        std::iter::once(duration)
            .chain(ladder.iter().copied())
            .collect()
    } else {
        ladder.to_vec()
    }
}

/// The state compared at the final time.
#[derive(Debug, Clone)]
pub struct FinalState {
    /// μ(T).
    pub momentum: Vec<f64>,
    /// g(T) row-major, if reconstructed.
    pub group: Option<Vec<f64>>,
}

impl FinalState {
    /// The state of a simulation.
    pub fn of(sim: &dyn Simulation) -> Self {
        Self {
            momentum: sim.momentum(),
            group: sim.group_matrix(),
        }
    }

    /// The error of `self` against `reference` (see the module page).
    pub fn error(&self, reference: &FinalState) -> f64 {
        let max_abs = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let diff = |a: &[f64], b: &[f64]| {
            a.iter()
                .zip(b)
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        };
        let mu_scale = max_abs(&reference.momentum);
        let mut e =
            diff(&self.momentum, &reference.momentum) / if mu_scale > 0.0 { mu_scale } else { 1.0 };
        if let (Some(g), Some(gr)) = (&self.group, &reference.group) {
            e = e.max(diff(g, gr) / max_abs(gr).max(1.0));
        }
        e
    }
}

/// One timed run.
#[derive(Debug, Clone)]
pub struct Timed {
    /// The state at T.
    pub state: FinalState,
    /// Steps taken.
    pub steps: u64,
    /// Time spent in `step` (the clock is read every [`ENERGY_SAMPLE`] steps).
    pub stepping: Duration,
    /// Maximum relative energy error over the samples.
    pub max_energy_error: f64,
    /// Maximum relative Casimir error over the samples, where the system has a Casimir.
    pub max_casimir_error: Option<f64>,
    /// Maximum relative error of the conserved part of the spatial momentum map over the samples,
    /// where g is reconstructed and the system keeps one ([`crate::invariants`]).
    pub max_momentum_map_error: Option<f64>,
}

/// Runs `sim` (a simulation of `system`) to `duration` with step `h` (the last step shortened to
/// land on T), sampling the invariants of [`crate::invariants`] every [`ENERGY_SAMPLE`] steps
/// and at T, outside the timed intervals.
pub fn timed_run(
    sim: &mut dyn Simulation,
    system: &System,
    duration: f64,
    h: f64,
) -> Result<Timed, SimError> {
    let n = steps_for(duration, h);
    let h_last = duration - (n - 1) as f64 * h;
    let mut monitor = Monitor::new(sim, system);
    let mut stepping = Duration::ZERO;
    let mut k = 0u64;
    let mut state = None;
    while k < n {
        let chunk_end = (k + ENERGY_SAMPLE).min(n);
        let start = Instant::now();
        while k < chunk_end {
            let hk = if k + 1 == n { h_last } else { h };
            if let Err(message) = sim.step(hk) {
                return Err(SimError::Step {
                    step: k,
                    time: sim.time(),
                    message,
                });
            }
            k += 1;
        }
        if k == n {
            // The state at T is part of the run's cost: for a processed method, the processor.
            state = Some(FinalState::of(sim));
        }
        stepping += start.elapsed();
        let e = monitor.sample(sim);
        if !e.is_finite() {
            if let Some(message) = sim.read_error() {
                return Err(SimError::Step {
                    step: k - 1,
                    time: sim.time(),
                    message: format!("reading the state: {message}"),
                });
            }
            return Err(SimError::NonFinite {
                step: k - 1,
                time: sim.time(),
            });
        }
    }
    Ok(Timed {
        state: state.unwrap_or_else(|| FinalState::of(sim)),
        steps: n,
        stepping,
        max_energy_error: monitor.energy,
        max_casimir_error: monitor.casimir,
        max_momentum_map_error: monitor.momentum_map,
    })
}

/// The work of [`trade`] before it starts: every candidate over the ladder (a composite step
/// counts its stages), `repeats` times. The reference is not counted: its refinement is bounded
/// by `--reference-budget` (and its first two runs, at h₀ = 1/ω and h₀/2, cost less than the
/// ladder's coarsest level). Bytes: the table.
pub fn estimate(scene: &Scene, ladder: &[f64], repeats: usize) -> crate::bounds::Estimate {
    let per_unit_h: u128 = candidates().iter().map(|m| m.stages() as u128).sum();
    let steps = |h: f64| u128::from(steps_for(scene.duration, h));
    let ladder_steps: u128 = ladder.iter().map(|&h| steps(h)).sum();
    crate::bounds::Estimate {
        steps: ladder_steps
            .saturating_mul(per_unit_h)
            .saturating_mul(repeats as u128),
        bytes: crate::bounds::Estimate::csv((candidates().len() * (ladder.len() + 1)) as u128, 15),
    }
}

/// One line of the work-precision table.
#[derive(Debug, Clone)]
pub struct TradeRow {
    /// The method.
    pub method: MethodSpec,
    /// Step h.
    pub h: f64,
    /// Steps taken (0 when the run failed before the first).
    pub steps: u64,
    /// Mean time per step, ns.
    pub ns_per_step: f64,
    /// Total stepping time, s.
    pub seconds: f64,
    /// Error at T against the reference (NaN when the run failed).
    pub error: f64,
    /// The reference's estimated error: an `error` below it is unresolved.
    pub reference_error: f64,
    /// Maximum relative energy error (NaN when the run failed).
    pub max_energy_error: f64,
    /// Maximum relative Casimir error, where the system has a Casimir (`None` also when the run
    /// failed: see `failure`).
    pub max_casimir_error: Option<f64>,
    /// Maximum relative error of the conserved part of the spatial momentum map, where it applies
    /// (`None` also when the run failed).
    pub max_momentum_map_error: Option<f64>,
    /// Why the run failed, if it did.
    pub failure: Option<String>,
    /// What the method says it is (`integrators::MethodInfo`): its order labels the plot.
    pub info: Option<MethodInfo>,
}

impl TradeRow {
    /// The error at T where it is measured: `None` for a failed run and for an error below the
    /// reference's estimated error (unresolved).
    pub fn resolved_error(&self) -> Option<f64> {
        (self.failure.is_none() && self.error.is_finite() && self.error >= self.reference_error)
            .then_some(self.error)
    }

    /// `measured`, `unresolved` (below the reference's estimated error) or `failed`.
    pub fn error_status(&self) -> &'static str {
        if self.failure.is_some() {
            "failed"
        } else if self.resolved_error().is_some() {
            "measured"
        } else {
            "unresolved"
        }
    }
}

/// The outcome of a trade: the rows, the reference, and the methods that were not available.
#[derive(Debug, Clone)]
pub struct TradeReport {
    /// Rows in table order.
    pub rows: Vec<TradeRow>,
    /// The reference solution.
    pub reference: Reference,
    /// Methods the integrators crate does not provide for this system.
    pub unavailable: Vec<MethodSpec>,
    /// Methods that do not apply to this system (euler-arnold with a potential).
    pub inapplicable: Vec<MethodSpec>,
}

/// Runs the trade over the steps of `ladder`; each run is repeated `repeats` times from the same
/// initial state and the fastest stepping time kept (the minimum is the least disturbed by other
/// load on the machine; the numbers themselves are identical between repeats). `on_row` sees each
/// row as soon as it is measured; `reference` is what every run is compared with
/// ([`crate::reference::reference`]).
pub fn trade(
    scene: &Scene,
    ladder: &[f64],
    repeats: usize,
    reference: Reference,
    mut on_row: impl FnMut(&TradeRow),
) -> Result<TradeReport, SimError> {
    let mut rows = Vec::new();
    let mut unavailable = Vec::new();
    let mut inapplicable = Vec::new();
    for m in candidates() {
        for h in steps_of(&m, ladder, scene.duration) {
            let mut best: Option<Result<Timed, SimError>> = None;
            let mut info = None;
            for _ in 0..repeats.max(1) {
                let mut sim = match build(&scene.system, &m, scene.reconstruct, &scene.solver) {
                    Ok(s) => s,
                    Err(SimError::NotYetAvailable { .. }) => break,
                    Err(SimError::Inapplicable { .. }) => {
                        inapplicable.push(m.clone());
                        break;
                    }
                    Err(e) => return Err(e),
                };
                info = Some(sim.info());
                let t = timed_run(sim.as_mut(), &scene.system, scene.duration, h);
                best = Some(match (best, t) {
                    (Some(Ok(b)), Ok(t)) if b.stepping <= t.stepping => Ok(b),
                    (_, t) => t,
                });
                if matches!(best, Some(Err(_))) {
                    break;
                }
            }
            let Some(result) = best else {
                if inapplicable.last() != Some(&m) {
                    unavailable.push(m.clone());
                }
                break;
            };
            let row = match result {
                Ok(t) => TradeRow {
                    method: m.clone(),
                    h,
                    steps: t.steps,
                    ns_per_step: t.stepping.as_nanos() as f64 / t.steps as f64,
                    seconds: t.stepping.as_secs_f64(),
                    error: t.state.error(&reference.state),
                    reference_error: reference.estimated_error,
                    max_energy_error: t.max_energy_error,
                    max_casimir_error: t.max_casimir_error,
                    max_momentum_map_error: t.max_momentum_map_error,
                    failure: None,
                    info,
                },
                Err(e) => TradeRow {
                    method: m.clone(),
                    h,
                    steps: 0,
                    ns_per_step: f64::NAN,
                    seconds: f64::NAN,
                    error: f64::NAN,
                    reference_error: reference.estimated_error,
                    max_energy_error: f64::NAN,
                    max_casimir_error: None,
                    max_momentum_map_error: None,
                    failure: Some(e.to_string()),
                    info,
                },
            };
            on_row(&row);
            rows.push(row);
        }
    }
    Ok(TradeReport {
        rows,
        reference,
        unavailable,
        inapplicable,
    })
}

/// The least-squares slope of log(error) against log(h) over a method's successful rows in the
/// asymptotic regime: the observed order of convergence. From the coarsest step down, rows with
/// an error above [`ORDER_FIT_MAX_ERROR`] are skipped (saturated), and the fit ends at the first
/// row whose error is at or below [`ORDER_FIT_REFERENCE_MARGIN`] × `reference_error` or no
/// smaller than the previous row's: what follows is the reference's or the method's own rounding
/// floor (a method at its floor, ~1e-13, reads 4e-13 at one step and 2e-13 at the next, which
/// taken in the fit bent Blanes–Moan 4 from 4.0 to 2.0 on the quadrotor). `None` with fewer than
/// two usable points.
pub fn fitted_order(rows: &[&TradeRow], reference_error: f64) -> Option<f64> {
    let floor = ORDER_FIT_REFERENCE_MARGIN * reference_error;
    let mut ok: Vec<&TradeRow> = rows
        .iter()
        .copied()
        .filter(|r| r.failure.is_none() && r.error.is_finite() && r.error <= ORDER_FIT_MAX_ERROR)
        .collect();
    ok.sort_by(|a, b| b.h.total_cmp(&a.h));
    let mut pts: Vec<(f64, f64)> = Vec::new();
    let mut last = f64::INFINITY;
    for r in ok {
        if r.error <= floor || r.error <= 0.0 || r.error >= last {
            break;
        }
        last = r.error;
        pts.push((r.h.ln(), r.error.ln()));
    }
    if pts.len() < 2 {
        return None;
    }
    let n = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / n, sy / n);
    let (sxy, sxx) = pts.iter().fold((0.0, 0.0), |(a, b), p| {
        (a + (p.0 - mx) * (p.1 - my), b + (p.0 - mx) * (p.0 - mx))
    });
    (sxx > 0.0).then(|| sxy / sxx)
}

/// Table header, fixed width.
pub fn table_header() -> String {
    format!(
        "{:<20} {:>6} {:>5} {:>13} {:>10} {:>10} {:>11} {:>11} {:>11} {:>11} {:>11}",
        "method",
        "tau",
        "theta",
        "composition",
        "h",
        "steps",
        "ns/step",
        "error(T)",
        "max|dE/E|",
        "max|dC/C|",
        "max|dJ|/|J|"
    )
}

/// One table line.
pub fn table_line(r: &TradeRow) -> String {
    let head = format!(
        "{:<20} {:>6} {:>5} {:>13} {:>10.3e}",
        r.method.method_label(),
        r.method.tau_label(),
        r.method.theta_label(),
        r.method.composition_label(),
        r.h
    );
    match &r.failure {
        Some(f) => format!("{head} failed: {f}"),
        None => format!(
            "{head} {:>10} {:>11.1} {:>11} {:>11.3e} {:>11} {:>11}",
            r.steps,
            r.ns_per_step,
            r.resolved_error()
                .map_or_else(|| "unresolved".into(), |e| format!("{e:.3e}")),
            r.max_energy_error,
            optional(r.max_casimir_error),
            optional(r.max_momentum_map_error)
        ),
    }
}

/// A table cell for a measure that may not apply: `-` where it does not.
fn optional(x: Option<f64>) -> String {
    x.map_or_else(|| "-".into(), |v| format!("{v:.3e}"))
}

/// The rows as CSV; a measure that does not apply (or of a failed run) is an empty cell. The
/// `error` cell holds the error at T only where it is resolved; `error_status` says `measured`,
/// `unresolved` (below `reference_error`, the reference's estimated error: the cell is empty) or
/// `failed`.
pub fn to_csv(rows: &[TradeRow]) -> String {
    let mut s = String::from(
        "method,tau,theta,composition,h,steps,ns_per_step,seconds,error,error_status,\
         reference_error,max_energy_error,max_casimir_error,max_momentum_map_error,failure\n",
    );
    let cell = |x: Option<f64>| x.map_or_else(String::new, |v| Cell(v).to_string());
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.method.method_label(),
            r.method.tau_label(),
            r.method.theta_label(),
            r.method.composition_label(),
            Cell(r.h),
            r.steps,
            Cell(r.ns_per_step),
            Cell(r.seconds),
            cell(r.resolved_error()),
            r.error_status(),
            Cell(r.reference_error),
            Cell(r.max_energy_error),
            cell(r.max_casimir_error),
            cell(r.max_momentum_map_error),
            r.failure.as_deref().unwrap_or("").replace(',', ";")
        );
    }
    s
}

/// What the plot draws against cost (every one is in the table and the CSV).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Metric {
    /// The error at T against the reference.
    Error,
    /// The maximum relative energy error over the run.
    Energy,
    /// The maximum relative Casimir error over the run.
    Casimir,
    /// The maximum relative error of the conserved part of the spatial momentum map over the run.
    MomentumMap,
}

impl Metric {
    /// The value of the metric for a row (`None` where it does not apply).
    pub fn of(self, r: &TradeRow) -> Option<f64> {
        match self {
            Self::Error => Some(r.error),
            Self::Energy => Some(r.max_energy_error),
            Self::Casimir => r.max_casimir_error,
            Self::MomentumMap => r.max_momentum_map_error,
        }
    }

    /// The axis label.
    pub fn describe(self) -> &'static str {
        match self {
            Self::Error => "error at T",
            Self::Energy => "max relative energy error |E − E₀|/|E₀|",
            Self::Casimir => "max relative Casimir error |C − C₀|/|C₀|",
            Self::MomentumMap => "max relative momentum-map error |J − J₀|/|J₀|",
        }
    }

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Self::Error => "error",
            Self::Energy => "energy",
            Self::Casimir => "casimir",
            Self::MomentumMap => "momentum-map",
        }
    }
}

/// Refuses a metric the scene does not have: a Casimir where its system monitors none, the
/// momentum map without reconstruction or where the system keeps no part of it
/// ([`crate::invariants::conserved_momentum_map`]).
pub fn check_metric(scene: &Scene, metric: Metric) -> Result<(), SimError> {
    let why = match metric {
        Metric::Error | Metric::Energy => None,
        Metric::Casimir => {
            let sim = build(
                &scene.system,
                &scene.method,
                scene.reconstruct,
                &scene.solver,
            )?;
            sim.casimir()
                .is_none()
                .then(|| format!("{} monitors no Casimir", scene.system.kind()))
        }
        Metric::MomentumMap => {
            if crate::invariants::conserved_momentum_map(&scene.system).is_none() {
                Some(format!(
                    "this {} keeps no part of the spatial momentum map (a potential or forces \
                     break its symmetry)",
                    scene.system.kind()
                ))
            } else if !scene.reconstruct {
                Some("the scene does not reconstruct g (reconstruct = false)".into())
            } else {
                None
            }
        }
    };
    match why {
        Some(message) => Err(SimError::Usage {
            flag: format!("--metric {}", metric.name()),
            message,
        }),
        None => Ok(()),
    }
}

/// Drops the finest steps of a ladder the rule alone chose (down to 2) while the trade's
/// [`estimate`] is beyond the work limits, unless `allow_large`; returns how many were dropped. A
/// ladder given by `--steps` or `--levels` is left as given (the limit check then refuses it).
pub fn fit_to_limits(
    scene: &Scene,
    ladder: &mut crate::ladder::Ladder,
    repeats: usize,
    allow_large: bool,
) -> usize {
    let mut dropped = 0;
    while ladder.may_trim
        && !allow_large
        && ladder.steps.len() > 2
        && estimate(scene, &ladder.steps, repeats)
            .check("trade", false)
            .is_err()
    {
        ladder.steps.pop();
        dropped += 1;
    }
    dropped
}

/// A series' label in the plot: the method, and the order it reports through
/// `integrators::MethodInfo` (effective for a processed method), e.g.
/// `processed blanes-casas-murua-6-11 ∘ splitting — order 6, explicit`.
pub fn curve_label(m: &MethodSpec, info: Option<MethodInfo>) -> String {
    match info {
        Some(i) if i.order == MethodInfo::EXACT => format!("{m} — exact"),
        Some(i) => format!(
            "{m} — order {}, {}",
            i.order,
            if i.explicit { "explicit" } else { "implicit" }
        ),
        None => m.to_string(),
    }
}

/// Groups rows by method, in first-seen order.
pub fn by_method(rows: &[TradeRow]) -> Vec<(MethodSpec, Vec<&TradeRow>)> {
    let mut groups: Vec<(MethodSpec, Vec<&TradeRow>)> = Vec::new();
    for r in rows {
        match groups.iter_mut().find(|(m, _)| *m == r.method) {
            Some((_, v)) => v.push(r),
            None => groups.push((r.method.clone(), vec![r])),
        }
    }
    groups
}

/// The colour of a method's family in the plot: Lie–Poisson, Euler–Poincaré, Euler–Arnold, the
/// compositions (of Lie–Poisson), the splittings (Strang, its compositions, kinetic–kick), the
/// exact flow, the Runge–Kutta baselines (rk4, rkmk4), the modified Lie–Poisson methods and the
/// processed methods.
pub fn family(m: &MethodSpec) -> (&'static str, RGBColor) {
    match m.method {
        Method::LiePoisson if m.modified.is_some() => ("modified", RGBColor(227, 119, 194)),
        _ if m.processing.is_some() => ("processed", RGBColor(23, 190, 207)),
        Method::LiePoisson if m.composition.is_some() => ("compositions", RGBColor(44, 160, 44)),
        Method::LiePoisson => ("lie-poisson", RGBColor(31, 119, 180)),
        Method::EulerPoincare => ("euler-poincare", RGBColor(255, 127, 14)),
        Method::EulerArnold => ("euler-arnold", RGBColor(140, 86, 75)),
        Method::Splitting | Method::KineticKick => ("splitting", RGBColor(148, 103, 189)),
        Method::Exact => ("exact", RGBColor(0, 0, 0)),
        Method::Rk4 | Method::Rkmk4 => ("rk4/rkmk4", RGBColor(214, 39, 40)),
    }
}

/// How a method's series is drawn: the colour of its [`family`]; τ = cayley (and the second
/// member of a pair without τ: kinetic–kick beside splitting, rkmk4 beside rk4) dashed with
/// hollow markers, τ = exp solid with filled ones; the marker by θ (0 ▲, ½ ●, 1 ■) or by
/// scheme (order-4 triple jump ▲, McLachlan's ×, order 6 ■, order 8 ◆; the kinetic–kick
/// schemes ●, ▲, ■ by order; the exact flow ◆); the modified Lie–Poisson methods by (θ, order)
/// (½ and 4 ●, 0 and 4 ▲, ½ and 6 ■, 0 and 6 ◆); the processed methods by scheme (blanes-6 ●,
/// 6-11 ▲, 6-13 ■) and base (Lie–Poisson exp solid filled, cayley dashed hollow, splitting solid
/// hollow, kinetic–kick dashed filled).
pub fn style_of(m: &MethodSpec) -> SeriesStyle {
    let second =
        m.tau == Some(TauKind::Cayley) || matches!(m.method, Method::KineticKick | Method::Rkmk4);
    if let Some(p) = &m.processing {
        // Processed: the marker by scheme; LP τ = exp solid filled, τ = cayley dashed hollow,
        // splitting solid hollow, kinetic–kick dashed filled.
        let marker = match p.name() {
            "blanes-6" => Marker::Circle,
            "blanes-casas-murua-6-11" => Marker::Triangle,
            _ => Marker::Square,
        };
        let (dashed, filled) = match (m.method, m.tau) {
            (Method::Splitting, _) => (false, false),
            (Method::KineticKick, _) => (true, true),
            (_, Some(TauKind::Cayley)) => (true, false),
            _ => (false, true),
        };
        return SeriesStyle {
            color: family(m).1,
            dashed,
            marker,
            filled,
        };
    }
    let marker = if let Some(order) = m.modified {
        match (m.theta, order) {
            (Some(0.0), 4) => Marker::Triangle,
            (Some(0.0), _) => Marker::Diamond,
            (_, 4) => Marker::Circle,
            _ => Marker::Square,
        }
    } else if let Some(c) = &m.composition {
        match c.name() {
            "triple-jump-4" => Marker::Triangle,
            "mclachlan-4" => Marker::Cross,
            "kahan-li-6" => Marker::Square,
            _ => Marker::Diamond,
        }
    } else if let Some(s) = &m.splitting {
        match s.order() {
            2 => Marker::Circle,
            4 => Marker::Triangle,
            _ => Marker::Square,
        }
    } else if m.method == Method::Exact {
        Marker::Diamond
    } else {
        match m.theta {
            Some(0.0) => Marker::Triangle,
            Some(1.0) => Marker::Square,
            _ => Marker::Circle,
        }
    };
    SeriesStyle {
        color: family(m).1,
        dashed: second,
        marker,
        filled: !second,
    }
}

/// The cheapest run (least stepping time) meeting each decade target 10⁻¹, 10⁻², … of `metric`,
/// loosest target first, down to the smallest value measured and, for the error at T, no lower
/// than `floor` (the reference's estimated error: below it nothing is resolved). For the error
/// at T a run meets a target when its error bound — its error plus the floor, twice the floor
/// for an unresolved error — is within the target ([`meets`]). A run cheapest for several
/// consecutive targets is listed once, at the tightest.
pub fn cheapest_per_target(rows: &[TradeRow], metric: Metric, floor: f64) -> Vec<(f64, &TradeRow)> {
    let measured: Vec<(f64, &TradeRow)> = rows
        .iter()
        .filter(|r| r.failure.is_none() && r.seconds.is_finite())
        .filter_map(|r| Some((metric.of(r)?, r)))
        .filter(|(v, _)| v.is_finite())
        .collect();
    let lowest = measured
        .iter()
        .map(|(v, _)| *v)
        .fold(f64::INFINITY, f64::min);
    let mut out: Vec<(f64, &TradeRow)> = Vec::new();
    for k in 1..=16 {
        let target = 10f64.powi(-k);
        if (metric == Metric::Error && target < floor) || target < lowest {
            break;
        }
        let Some(&(_, best)) = measured
            .iter()
            .filter(|(v, _)| match metric {
                Metric::Error => meets(*v, floor, target),
                _ => *v <= target,
            })
            .min_by(|a, b| a.1.seconds.total_cmp(&b.1.seconds))
        else {
            continue;
        };
        match out.last_mut() {
            Some(last) if std::ptr::eq(last.1, best) => last.0 = target,
            _ => out.push((target, best)),
        }
    }
    out
}

/// Writes the table as CSV to `csv` and the plot of `metric` against cost to `svg`: one series
/// per method ([`style_of`]), the reference's estimated error as a dashed line (error at T), and
/// the [`cheapest_per_target`] runs ringed and labelled.
pub fn write_outputs(
    report: &TradeReport,
    scene: &Scene,
    csv: &Path,
    svg: &Path,
    metric: Metric,
) -> Result<(), SimError> {
    write_atomic(csv, &to_csv(&report.rows))?;
    // The error at T is drawn only where it is resolved; the runs below the floor are marked on it.
    let value = |r: &TradeRow| match metric {
        Metric::Error => r.resolved_error(),
        _ => metric.of(r),
    };
    let curves: Vec<Curve> = by_method(&report.rows)
        .into_iter()
        .map(|(m, rows)| Curve {
            label: curve_label(&m, rows.iter().find_map(|r| r.info)),
            style: style_of(&m),
            points: rows
                .iter()
                .filter(|r| r.failure.is_none())
                .filter_map(|r| Some((r.seconds, value(r)?)))
                .collect(),
        })
        .collect();
    let floor = report.reference.estimated_error;
    let below: Vec<f64> = report
        .rows
        .iter()
        .filter(|r| metric == Metric::Error && r.error_status() == "unresolved")
        .map(|r| r.seconds)
        .collect();
    let annotations = Annotations {
        hline: (metric == Metric::Error).then(|| {
            (
                floor,
                format!(
                    "reference floor: its estimated error {floor:.1e}{}",
                    if below.is_empty() {
                        String::new()
                    } else {
                        format!(
                            " (▽: {} runs below it, unresolved, drawn on it)",
                            below.len()
                        )
                    }
                ),
            )
        }),
        below,
        labels: cheapest_per_target(&report.rows, metric, floor)
            .into_iter()
            .filter_map(|(target, r)| {
                let value = metric.of(r)?;
                // An error below the reference's floor is not resolved: labelled on the floor.
                let y = if metric == Metric::Error {
                    value.max(floor)
                } else {
                    value
                };
                Some((
                    r.seconds,
                    y,
                    format!("≤ {target:.0e}: {} h = {:.3e}", r.method, r.h),
                ))
            })
            .collect(),
    };
    plot_loglog(
        &curves,
        &annotations,
        svg,
        &format!(
            "{} ({}), T = {}: {} against cost",
            scene.name,
            scene.system.kind(),
            scene.duration,
            metric.name()
        ),
        "cost: stepping time (s)",
        metric.describe(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(h: f64, error: f64) -> TradeRow {
        TradeRow {
            method: candidates()[0].clone(),
            h,
            steps: 1,
            ns_per_step: 1.0,
            seconds: 1.0,
            error,
            reference_error: 0.0,
            max_energy_error: 0.0,
            max_casimir_error: None,
            max_momentum_map_error: None,
            failure: None,
            info: None,
        }
    }

    #[test]
    fn fitted_order_recovers_the_exponent_of_a_power_law() {
        let rows: Vec<TradeRow> = [0.1, 0.05, 0.025, 0.0125]
            .iter()
            .map(|&h| row(h, 3.0 * h * h))
            .collect();
        let refs: Vec<&TradeRow> = rows.iter().collect();
        assert!((fitted_order(&refs, 0.0).unwrap() - 2.0).abs() < 1e-12);
        assert_eq!(fitted_order(&refs[..1], 0.0), None);
    }

    #[test]
    fn fitted_order_ignores_points_at_the_reference_floor_or_saturated() {
        // Errors 3h² down to 4.7e-4, then two rows at a 1e-9 floor and one saturated at 0.5.
        let mut rows: Vec<TradeRow> = [0.1, 0.05, 0.025, 0.0125]
            .iter()
            .map(|&h| row(h, 3.0 * h * h))
            .collect();
        rows.push(row(0.00625, 1e-9));
        rows.push(row(0.003125, 1e-9));
        rows.push(row(0.2, 0.5));
        let refs: Vec<&TradeRow> = rows.iter().collect();
        assert!((fitted_order(&refs, 1e-9).unwrap() - 2.0).abs() < 1e-12);
    }

    /// Errors 3h⁴ at four steps, then the method's rounding floor: one row below the reference
    /// margin, then one above it again (4e-12 > 10 × 1e-13). The fit stops at the floor and reads
    /// 4; taking the last row in (as the fit did when it only filtered rows) made it 5.2.
    #[test]
    fn fitted_order_stops_at_the_first_row_of_the_rounding_floor() {
        let mut rows: Vec<TradeRow> = [0.1, 0.05, 0.025, 0.0125]
            .iter()
            .map(|&h| row(h, 3.0 * h.powi(4)))
            .collect();
        rows.push(row(0.00625, 5e-13));
        rows.push(row(0.003125, 4e-12));
        let refs: Vec<&TradeRow> = rows.iter().collect();
        let p = fitted_order(&refs, 1e-13).unwrap();
        assert!((p - 4.0).abs() < 1e-12, "{p}");
        // an error that stops falling ends the fit too
        rows.truncate(4);
        rows.push(row(0.00625, 8e-8));
        let refs: Vec<&TradeRow> = rows.iter().collect();
        assert!((fitted_order(&refs, 1e-13).unwrap() - 4.0).abs() < 1e-12);
    }

    #[test]
    fn candidates_cover_every_lie_method_tau_theta_the_compositions_the_splittings_and_the_baselines(
    ) {
        // 3 methods × 2 τ × 3 θ + 3 compositions × 2 τ + modified LP × (2 θ × 2 orders) × 2 τ
        // + 3 processing schemes × (LP × 2 τ, splitting, kinetic-kick) + splitting (plain,
        // 3 compositions) + kinetic-kick × 3 schemes + exact + rk4 + rkmk4.
        assert_eq!(candidates().len(), 54);
        let processed: Vec<_> = candidates()
            .into_iter()
            .filter(|m| m.processing.is_some())
            .collect();
        assert_eq!(processed.len(), 12);
        assert!(processed.iter().all(|m| m.composition.is_none()
            && m.modified.is_none()
            && ((m.method == Method::LiePoisson && m.theta == Some(0.5))
                || matches!(m.method, Method::Splitting | Method::KineticKick))));
        let modified: Vec<_> = candidates()
            .into_iter()
            .filter_map(|m| Some((m.theta?, m.modified?, m.tau?)))
            .collect();
        assert_eq!(modified.len(), 8);
        let composed: Vec<_> = candidates()
            .into_iter()
            .filter(|m| m.composition.is_some())
            .collect();
        assert_eq!(composed.len(), 9);
        assert!(composed
            .iter()
            .all(|m| (m.method == Method::LiePoisson && m.theta == Some(0.5))
                || m.method == Method::Splitting));
        let kicks: Vec<_> = candidates()
            .into_iter()
            .filter(|m| m.method == Method::KineticKick && m.processing.is_none())
            .map(|m| m.splitting.unwrap().order())
            .collect();
        assert_eq!(kicks, [2, 4, 6]);
    }

    #[test]
    fn a_ladder_the_rule_chose_is_cut_to_the_work_limit_and_a_given_one_is_not() {
        let mut scene = Scene::default_scene(Default::default()).unwrap();
        scene.duration = 1e5;
        // ωT = 1e5: (1e-18)^{1/8} = 2^{-7.5}, nine levels, 2.6e7 steps per run at the finest.
        let mut ladder = crate::ladder::automatic_for(1.0, scene.duration, 0.1, None, 2.0);
        assert_eq!(ladder.steps.len(), 9);
        assert!(estimate(&scene, &ladder.steps, 3)
            .check("t", false)
            .is_err());
        let dropped = fit_to_limits(&scene, &mut ladder, 3, false);
        assert!(dropped > 0 && ladder.steps.len() >= 2, "{ladder:?}");
        assert!(estimate(&scene, &ladder.steps, 3).check("t", false).is_ok());
        // One level more is over the limit: only what had to go was dropped.
        let mut one_more = ladder.steps.clone();
        one_more.push(ladder.steps[ladder.steps.len() - 1] / 2.0);
        assert!(estimate(&scene, &one_more, 3).check("t", false).is_err());
        let mut given = crate::ladder::automatic_for(1.0, scene.duration, 0.1, Some(10), 2.0);
        assert_eq!(fit_to_limits(&scene, &mut given, 3, false), 0);
        let mut allowed = crate::ladder::automatic_for(1.0, scene.duration, 0.1, None, 2.0);
        assert_eq!(fit_to_limits(&scene, &mut allowed, 3, true), 0);
    }

    #[test]
    fn every_candidate_is_drawn_in_its_own_style_and_families_share_a_colour() {
        let styles: Vec<SeriesStyle> = candidates().iter().map(style_of).collect();
        for (i, a) in styles.iter().enumerate() {
            for b in &styles[i + 1..] {
                assert_ne!(a, b);
            }
        }
        let families: Vec<&str> = candidates().iter().map(|m| family(m).0).collect();
        let mut distinct = families.clone();
        distinct.sort();
        distinct.dedup();
        assert_eq!(distinct.len(), 9);
        for (m, f) in candidates().iter().zip(&families) {
            for (n, g) in candidates().iter().zip(&families) {
                assert_eq!(f == g, family(m).1 == family(n).1, "{m} {n}");
            }
        }
    }

    #[test]
    fn cheapest_per_target_takes_the_least_time_meeting_each_decade_once() {
        let mut rows = Vec::new();
        // (seconds, error): a cheap coarse run at 5e-3, a dearer one at 2e-5, the dearest 1e-9.
        for (s, e) in [(1.0, 5e-3), (2.0, 2e-5), (8.0, 1e-9), (9.0, 3e-3)] {
            let mut r = row(0.1, e);
            r.seconds = s;
            rows.push(r);
        }
        let picks: Vec<(f64, f64)> = cheapest_per_target(&rows, Metric::Error, 1e-12)
            .iter()
            .map(|(t, r)| (*t, r.seconds))
            .collect();
        // 1e-1, 1e-2: the 1 s run (listed at 1e-2); 1e-3 … 1e-4: the 2 s run; 1e-5 … 1e-8: 8 s
        // (not 1e-9: its error plus the floor, 1e-9 + 1e-12, is beyond it).
        assert_eq!(picks, [(1e-2, 1.0), (1e-4, 2.0), (1e-8, 8.0)]);
        // Against a floor of 1e-6 the 1e-9 run is unresolved, bounded by 2e-6: it meets 1e-5 but
        // not its own 1e-9, the 2 s run stays the pick at 1e-4 (2e-5 + 1e-6 within it), and the
        // targets stop at the floor.
        let picks: Vec<(f64, f64)> = cheapest_per_target(&rows, Metric::Error, 1e-6)
            .iter()
            .map(|(t, r)| (*t, r.seconds))
            .collect();
        assert_eq!(picks, [(1e-2, 1.0), (1e-4, 2.0), (1e-5, 8.0)]);
    }

    #[test]
    fn the_exact_flow_also_runs_in_one_step() {
        let ladder = [0.1, 0.05];
        let exact = MethodSpec::plain(Method::Exact, None);
        assert_eq!(steps_of(&exact, &ladder, 10.0), [10.0, 0.1, 0.05]);
        let rk4 = MethodSpec::plain(Method::Rk4, None);
        assert_eq!(steps_of(&rk4, &ladder, 10.0), ladder);
    }

    #[test]
    fn trade_compositions_are_builtin_schemes() {
        for name in COMPOSITIONS.iter().chain(&SPLITTING_COMPOSITIONS) {
            let s: CompositionScheme = name.parse().unwrap();
            assert_eq!(s.name(), *name);
        }
    }

    #[test]
    fn error_is_relative_in_momentum_and_absolute_below_one_in_the_group() {
        let r = FinalState {
            momentum: vec![2.0, 0.0],
            group: Some(vec![0.5]),
        };
        let x = FinalState {
            momentum: vec![2.0, 0.2],
            group: Some(vec![0.5 + 0.3]),
        };
        assert!((x.error(&r) - 0.3).abs() < 1e-15);
    }
}
