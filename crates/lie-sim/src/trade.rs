//! `lie-sim trade`: the speed–accuracy trade of every method that applies to a scene.
//!
//! Every candidate of the method registry ([`crate::methods::candidates`]: each method's
//! configurations over the τ and θ it takes, the compositions, modified Hamiltonians and processed
//! forms its row names) runs the scene over a ladder of steps ([`crate::ladder`]: from the scene's
//! time scale, h ω = 1 halved down to the reference floor, or the `--steps` list; an exact flow
//! also in one step to T); a composite step of size h is s base steps. Methods that do not apply
//! to the system (their row needs a capability the system's model lacks) are left out, with the
//! model's reason. Each run is compared at the final time T with a reference made independently of
//! the candidates, with its estimated error ([`crate::reference`]: the exact flow on the free rigid
//! body, elsewhere Gragg–Bulirsch–Stoer on the mesh of an error-controlled run, refined until two
//! runs agree to `--reference-tolerance`, or
//! the user's `--reference`). An error below the reference's estimated error (the floor) measures
//! the reference, not the method: the table prints it as `unresolved`, the CSV leaves its `error`
//! cell empty with `error_status` `unresolved`, and the plot draws it as ▽ on the floor line. The
//! table reports, per run, the
//! cost (ns per step, total time), the error at T and the long-horizon measures of
//! [`crate::invariants`]: the maximum relative energy, Casimir and spatial momentum-map errors
//! over the run (`-` where they do not apply); `--metric` picks the one the plot draws against
//! cost.
//!
//! The tolerance-driven methods (their row's `Stepping::Tolerance`: the embedded pairs) run over
//! the ladder of tolerances [`TOLERANCES`] (rtol = atol) instead of the steps, next to the
//! fixed-step runs in the same table and plot (their own colour and markers); their `h` is the
//! mean accepted step T/steps, their `tolerance` the one asked for, and the table reports the
//! tolerance proportionality error/tolerance of each run (how far the achieved error at T is
//! from what was asked: a local tolerance does not bound the global error, and the ratio says
//! by how much it misses or beats it on this scene). The CSV's `geometric` column says whether
//! the method keeps structure beyond g on G ([`crate::methods::geometric`], from its
//! `MethodInfo`).
//!
//! The configurations a row declares for reversible variable steps (`Trade::reversible`: a
//! symmetric method steered by the step-density controller, `integrator.epsilon`) run over the
//! ladder ε = h s of the steps, `s = max(ρ(y₀), ω)` ([`crate::build::epsilon_scale`]: ρ the
//! model's step density at the initial state, ω the scene's time scale that sets the ladder, so
//! that each starts with the ladder's step h where ρ(y₀) ≥ ω, and then follows the motion);
//! their `h` is the mean step T/steps and their `epsilon` the ε asked for.
//!
//! Error at T and timing: [`crate::measure`]; nothing of the trajectory is stored.

use crate::build::{build, build_with, epsilon_scale};
use crate::error::SimError;
use crate::measure::{timed_adaptive_run, timed_run, Timed};
use crate::methods::row::Stepping;
use crate::methods::{candidates, geometric, style, MethodSpec};
use crate::output::write_atomic;
use crate::plot::{plot_loglog, Annotations, Curve};
use crate::reference::{meets, Reference};
use crate::run::Cell;
use crate::scene::{steps_for, Scene};
use crate::stepping::VariableSteps;
use integrators::adaptive::Tolerance;
use integrators::MethodInfo;
use std::fmt::Write as _;
use std::path::Path;

/// Rows whose error is below this multiple of the reference's estimated error measure the
/// reference, not the method: they are left out of the order fit.
pub const ORDER_FIT_REFERENCE_MARGIN: f64 = 10.0;

/// Rows whose error is above this are outside the asymptotic regime (a phase error of order one
/// saturates): they are left out of the order fit.
pub const ORDER_FIT_MAX_ERROR: f64 = 0.1;

/// The tolerances (rtol = atol) a tolerance-driven method runs over, loosest first.
pub const TOLERANCES: &[f64] = &[
    1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12,
];

/// Whether a configuration runs to a tolerance rather than with fixed steps.
pub fn tolerance_driven(m: &MethodSpec) -> bool {
    m.method.row().takes.stepping == Stepping::Tolerance
}

/// How one run of the trade steps: a fixed step h, a tolerance, or reversible steps with ε.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Run {
    Step(f64),
    Tolerance(f64),
    Epsilon(f64),
}

/// The runs of a method in the trade: [`TOLERANCES`] for a tolerance-driven method, ε = h s
/// over the ladder for reversible steps (s of [`epsilon_scale`]), the steps of [`steps_of`]
/// otherwise.
fn runs_of(m: &MethodSpec, ladder: &[f64], duration: f64, scale: f64) -> Vec<Run> {
    if tolerance_driven(m) {
        TOLERANCES.iter().map(|&t| Run::Tolerance(t)).collect()
    } else if m.reversible {
        ladder.iter().map(|&h| Run::Epsilon(h * scale)).collect()
    } else {
        steps_of(m, ladder, duration)
            .into_iter()
            .map(Run::Step)
            .collect()
    }
}

/// The steps a method runs in the trade: the ladder, and for the exact flow (whose error does not
/// depend on h and whose cost per step does not depend on h either) one step to T first.
fn steps_of(m: &MethodSpec, ladder: &[f64], duration: f64) -> Vec<f64> {
    if m.method.row().trade.one_step {
        std::iter::once(duration)
            .chain(ladder.iter().copied())
            .collect()
    } else {
        ladder.to_vec()
    }
}

/// The work of [`trade`] before it starts: every candidate over the ladder (a composite step
/// counts its stages), `repeats` times. The reference is not counted: its refinement is bounded
/// by `--reference-budget` (and its first two runs, at h₀ = 1/ω and h₀/2, cost less than the
/// ladder's coarsest level), nor are the tolerance-driven runs, whose steps are not known ahead
/// (each is bounded by the driver's budget of attempted steps). A step costs what an implicit
/// step on the scene's group costs ([`Scene::step_cost`](crate::scene::Scene::step_cost): an upper figure, the
/// candidates include implicit methods), so that a trade on SO(50) is refused as `run` refuses
/// it; a scene whose method does not build counts 1 (the trade reports that error itself).
/// Bytes: the table.
pub fn estimate(scene: &Scene, ladder: &[f64], repeats: usize) -> crate::bounds::Estimate {
    let per_unit_h: u128 = candidates()
        .iter()
        .filter(|m| !tolerance_driven(m))
        .map(|m| m.stages() as u128)
        .sum();
    let steps = |h: f64| u128::from(steps_for(scene.duration, h));
    let ladder_steps: u128 = ladder.iter().map(|&h| steps(h)).sum();
    crate::bounds::Estimate {
        steps: ladder_steps
            .saturating_mul(per_unit_h)
            .saturating_mul(repeats as u128),
        bytes: crate::bounds::Estimate::csv((candidates().len() * (ladder.len() + 1)) as u128, 15),
        step_cost: scene.step_cost(true).unwrap_or(1),
    }
}

/// One line of the work-precision table.
#[derive(Debug, Clone)]
pub struct TradeRow {
    /// The method.
    pub method: MethodSpec,
    /// Step h (the mean accepted step T/steps of a run with variable steps).
    pub h: f64,
    /// The tolerance (rtol = atol) of a tolerance-driven run, `None` otherwise.
    pub tolerance: Option<f64>,
    /// The ε of a run with reversible variable steps, `None` otherwise.
    pub epsilon: Option<f64>,
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

    /// The tolerance proportionality of a tolerance-driven run: its resolved error at T over
    /// its tolerance.
    pub fn proportionality(&self) -> Option<f64> {
        Some(self.resolved_error()? / self.tolerance?)
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
    /// Methods that do not apply to this system, with why.
    pub inapplicable: Vec<(MethodSpec, String)>,
}

/// Runs the trade over the steps of `ladder`; each run is repeated `repeats` times from the same
/// initial state and the fastest stepping time kept (the minimum is the least disturbed by other
/// load on the machine; the numbers themselves are identical between repeats). `on_row` sees each
/// row as soon as it is measured; `reference` is what every run is compared with
/// ([`crate::reference::reference`]). (`on_row` is a trait object so that the trade is compiled
/// once, in this crate, not again in every caller.)
pub fn trade(
    scene: &Scene,
    ladder: &[f64],
    repeats: usize,
    reference: Reference,
    on_row: &mut dyn FnMut(&TradeRow),
) -> Result<TradeReport, SimError> {
    let mut rows = Vec::new();
    let mut unavailable = Vec::new();
    let mut inapplicable = Vec::new();
    let scale = epsilon_scale(&scene.system, scene.reconstruct)?;
    for m in candidates() {
        for run in runs_of(&m, ladder, scene.duration, scale) {
            let variable = match run {
                Run::Step(_) => None,
                Run::Tolerance(t) => Some(VariableSteps::Tolerance(
                    Tolerance::uniform(t).map_err(|e| SimError::Build {
                        what: m.to_string(),
                        message: e.to_string(),
                    })?,
                )),
                Run::Epsilon(e) => Some(VariableSteps::Reversible(e)),
            };
            let mut best: Option<Result<Timed, SimError>> = None;
            let mut info = None;
            for _ in 0..repeats.max(1) {
                let built = build_with(
                    &scene.system,
                    &m,
                    scene.reconstruct,
                    &scene.solver,
                    variable,
                );
                let mut sim = match built {
                    Ok(s) => s,
                    Err(SimError::NotYetAvailable { .. }) => break,
                    Err(SimError::Inapplicable { why, .. }) => {
                        inapplicable.push((m.clone(), why));
                        break;
                    }
                    Err(e) => return Err(e),
                };
                info = Some(sim.info());
                let t = match run {
                    Run::Step(h) => timed_run(sim.as_mut(), scene.duration, h),
                    Run::Tolerance(_) | Run::Epsilon(_) => {
                        timed_adaptive_run(sim.as_mut(), scene.duration)
                    }
                };
                best = Some(match (best, t) {
                    (Some(Ok(b)), Ok(t)) if b.stepping <= t.stepping => Ok(b),
                    (_, t) => t,
                });
                if matches!(best, Some(Err(_))) {
                    break;
                }
            }
            let Some(result) = best else {
                if inapplicable.last().map(|(i, _)| i) != Some(&m) {
                    unavailable.push(m.clone());
                }
                break;
            };
            let (h, tolerance, epsilon) = match run {
                Run::Step(h) => (h, None, None),
                Run::Tolerance(tol) => (f64::NAN, Some(tol), None),
                Run::Epsilon(e) => (f64::NAN, None, Some(e)),
            };
            let row = match result {
                Ok(t) => TradeRow {
                    method: m.clone(),
                    h: if variable.is_some() {
                        scene.duration / t.steps as f64
                    } else {
                        h
                    },
                    tolerance,
                    epsilon,
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
                    tolerance,
                    epsilon,
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
        "{:<20} {:>6} {:>5} {:>13} {:>10} {:>10} {:>11} {:>11} {:>11} {:>11} {:>11} {:>9} {:>9} \
         {:>9}",
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
        "max|dJ|/|J|",
        "tolerance",
        "err/tol",
        "epsilon"
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
            "{head} {:>10} {:>11.1} {:>11} {:>11.3e} {:>11} {:>11} {:>9} {:>9} {:>9}",
            r.steps,
            r.ns_per_step,
            r.resolved_error()
                .map_or_else(|| "unresolved".into(), |e| format!("{e:.3e}")),
            r.max_energy_error,
            optional(r.max_casimir_error),
            optional(r.max_momentum_map_error),
            r.tolerance
                .map_or_else(|| "-".into(), |t| format!("{t:.0e}")),
            r.proportionality()
                .map_or_else(|| "-".into(), |p| format!("{p:.2e}")),
            r.epsilon.map_or_else(|| "-".into(), |e| format!("{e:.2e}"))
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
/// `failed`. `tolerance` is the tolerance of a tolerance-driven run (empty for fixed steps, whose
/// `h` is the step; a run with variable steps has its mean step as `h`); `epsilon` is the ε of
/// a run with reversible variable steps (empty otherwise); `geometric` is `true` or
/// `false` as [`crate::methods::geometric`] reads the method's own `MethodInfo` (empty when the
/// method was never built).
pub fn to_csv(rows: &[TradeRow]) -> String {
    let mut s = String::from(
        "method,tau,theta,composition,tolerance,h,steps,ns_per_step,seconds,error,error_status,\
         reference_error,max_energy_error,max_casimir_error,max_momentum_map_error,geometric,\
         failure,epsilon\n",
    );
    let cell = |x: Option<f64>| x.map_or_else(String::new, |v| Cell(v).to_string());
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.method.method_label(),
            r.method.tau_label(),
            r.method.theta_label(),
            r.method.composition_label(),
            cell(r.tolerance),
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
            r.info
                .map_or_else(String::new, |i| geometric(&i).to_string()),
            r.failure.as_deref().unwrap_or("").replace(',', ";"),
            cell(r.epsilon)
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
/// (`integrators::System::conserved_momentum_map`).
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
            let sim = build(
                &scene.system,
                &scene.method,
                scene.reconstruct,
                &scene.solver,
            )?;
            if sim.conserved_momentum_map().is_empty() {
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
    let label = match info {
        Some(i) if i.order == MethodInfo::EXACT => format!("{m} — exact"),
        Some(i) => format!(
            "{m} — order {}, {}",
            i.order,
            if i.explicit { "explicit" } else { "implicit" }
        ),
        None => m.to_string(),
    };
    if tolerance_driven(m) {
        format!(
            "{label}, tolerances {:.0e} … {:.0e}",
            TOLERANCES[0],
            TOLERANCES[TOLERANCES.len() - 1]
        )
    } else if m.reversible {
        format!("{label}, reversible steps over ε")
    } else {
        label
    }
}

/// A run as the summaries name it: `h = 1.000e-2`, `tolerance = 1e-8` for a tolerance-driven
/// run, `ε = 2.500e-2` for reversible steps.
pub fn run_label(r: &TradeRow) -> String {
    match (r.tolerance, r.epsilon) {
        (Some(t), _) => format!("tolerance = {t:.0e}"),
        (None, Some(e)) => format!("ε = {e:.3e}"),
        (None, None) => format!("h = {:.3e}", r.h),
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
/// per method (`style_of`), the reference's estimated error as a dashed line (error at T), and
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
            style: style(&m),
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
                    format!("≤ {target:.0e}: {} {}", r.method, run_label(r)),
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
            tolerance: None,
            epsilon: None,
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

    /// The geodesic scene on SO(n) with Lie–Poisson (simplified Newton) over T = 10.
    fn so_n_scene(n: usize) -> Scene {
        crate::run::tests::so_n(n, 1000)
    }

    /// A trade counts a step at its cost on the group, as `run` does: the same ladder (every
    /// candidate over 3000 steps) passes on SO(3) and is refused on SO(50), whose implicit step
    /// costs ~8·10³ steps on SO(3) (`bounds::stage_cost`, measured). With the step counted as
    /// one on SO(3) (as before) SO(50) passes and this fails.
    #[test]
    fn a_trade_on_a_large_group_counts_its_step_cost() {
        let ladder = [0.01, 0.005];
        let (small, large) = (so_n_scene(3), so_n_scene(50));
        // SO(3) stored as SO(n) pays the dynamically sized group's floor (`bounds::stage_cost`).
        assert!(small.step_cost(true).unwrap() < 1000);
        assert!(large.step_cost(true).unwrap() > 5000);
        assert!(estimate(&small, &ladder, 1).check("trade", false).is_ok());
        let e = estimate(&large, &ladder, 1)
            .check("trade", false)
            .unwrap_err()
            .to_string();
        assert!(e.contains("SO(3)-step equivalents"), "{e}");
        // A sweep of 100 members of 10⁴ steps likewise.
        let spec = crate::scene::SweepSpec {
            count: 100,
            seed: 1,
            kind: crate::scene::SweepKind::MomentaOnSphere,
            monitor_every: 1,
        };
        let shard = integrators::ensemble::Shard::all();
        let cost = |s: &Scene| s.step_cost(false).unwrap();
        assert!(
            crate::sweep::estimate(&spec, shard, 10_000, 1, cost(&small))
                .check("sweep", false)
                .is_ok()
        );
        assert!(
            crate::sweep::estimate(&spec, shard, 10_000, 1, cost(&large))
                .check("sweep", false)
                .is_err()
        );
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
        use crate::methods::MethodId;
        let ladder = [0.1, 0.05];
        let exact = MethodSpec::plain(MethodId::Exact);
        assert_eq!(steps_of(&exact, &ladder, 10.0), [10.0, 0.1, 0.05]);
        let rk4 = MethodSpec::plain(MethodId::Rk4);
        assert_eq!(steps_of(&rk4, &ladder, 10.0), ladder);
    }

    /// The CSV has a `tolerance` column (empty for fixed steps) and a `geometric` column read
    /// from each method's own `MethodInfo`: on the free body the embedded pairs and the RK
    /// baselines are not geometric, the Lie–Poisson and splitting methods are.
    #[test]
    fn the_csv_names_tolerances_and_reads_geometric_from_the_descriptors() {
        use crate::methods::MethodId;
        let scene = Scene::default_scene(Default::default()).unwrap();
        let mut rows = Vec::new();
        for m in candidates() {
            let Ok(sim) = build(&scene.system, &m, true, &scene.solver) else {
                continue;
            };
            let mut r = row(0.1, 1e-3);
            r.method = m.clone();
            r.info = Some(sim.info());
            r.tolerance = tolerance_driven(&m).then_some(1e-8);
            rows.push(r);
        }
        let csv = to_csv(&rows);
        let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
        let col = |name: &str| header.iter().position(|c| *c == name).unwrap();
        let (tol, geo, method) = (col("tolerance"), col("geometric"), col("method"));
        let mut seen = std::collections::HashMap::new();
        for (line, r) in csv.lines().skip(1).zip(&rows) {
            let cells: Vec<&str> = line.split(',').collect();
            assert_eq!(cells.len(), header.len(), "{line}");
            assert_eq!(
                cells[geo],
                geometric(&r.info.unwrap()).to_string(),
                "{line}"
            );
            assert_eq!(
                cells[tol].is_empty(),
                !tolerance_driven(&r.method),
                "{line}"
            );
            seen.insert(cells[method].to_string(), cells[geo].to_string());
        }
        for (name, want) in [
            (MethodId::Dop853.name(), "false"),
            (MethodId::RkmkDopri5.name(), "false"),
            (MethodId::Rk4.name(), "false"),
            (MethodId::LiePoisson.name(), "true"),
            (MethodId::Splitting.name(), "true"),
            (MethodId::Exact.name(), "true"),
        ] {
            assert_eq!(seen.get(name).map(String::as_str), Some(want), "{name}");
        }
    }
}
