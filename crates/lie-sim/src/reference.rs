//! The reference solution of `lie-sim trade` and `lie-sim choose`: the state at T every candidate
//! is compared with, made independently of the candidates, with its estimated error.
//!
//! - **Free rigid body without forces:** the exact flow (`mechanics::exact`, Jacobi elliptic
//!   functions): the mean of its evaluations in one step to T and in n, n + 1, n + 2 steps
//!   (n = max(8, ⌈T/h₀⌉), h₀ below), whose spread is its estimated error: what rounding leaves,
//!   ~1e-15 … 1e-14.
//! - **Every other scene:** the Gragg–Bulirsch–Stoer method of order 12
//!   ([`integrators::GraggBulirschStoer`]; it shares no discretization with any candidate) on a
//!   mesh that follows the motion: the accepted steps of [`RkmkDop853`] under [`Adaptive`] at
//!   rtol = [`MESH_TOLERANCE`], which land on the knots of the force schedules (torque, force,
//!   thrust, wheel torques: where the force has kinks) and on T. The mesh only places the steps
//!   (short at a periapsis passage or a flip, long in the slow phases); the accuracy comes from
//!   the order-12 extrapolation on it, run on the mesh, then with every step split in 2, 4, …,
//!   until two successive runs agree to the tolerance (`--reference-tolerance`, default
//!   [`DEFAULT_TOLERANCE`] relative, in the trade's error measure
//!   `crate::trade::FinalState::error`). A uniform step, as before, is set by the fastest phase:
//!   on a satellite on an orbit of eccentricity 0.8 it stalled at an estimated 1e-4 within the
//!   budget, where the mesh reaches the rounding level in well under a second
//!   (`examples/scenes/eccentric-orbit.toml`); on the smooth scenes both cost alike and agree
//!   within their estimated errors. Refinement stops
//!   early when it stalls at the rounding level (two successive refinements each reduce the
//!   difference by less than [`STALL_RATIO`], once it is below [`STALL_GATE`]), and when
//!   `--reference-budget` (default [`DEFAULT_BUDGET`]) has run out: the first two runs always
//!   complete, a later run is abandoned at the deadline. The finer run of the closest-agreeing pair
//!   is then run again [`EXTRA_SAMPLES`] times with 1, 2 more steps in its longest step (the same
//!   accuracy, roundings that fall differently): the reference is the mean of these runs, and the
//!   spread of them and the run at twice the step (the largest difference between two) bounds both
//!   the truncation error (at order 12 the finer run's is ~2¹² times below the difference) and the
//!   rounding error of the mean. Two runs alone can agree by chance far better than either is
//!   accurate (the heavy top over T = 2: 6.7e-16 between h and h/2, 3.7e-14 between runs of 160
//!   and 162 steps).
//!
//! To either estimate [`data_rounding`] is added: what rounding the scene's data (inertia,
//! masses) does to every run alike, which no comparison of runs can see. When the estimate is
//! above the tolerance, [`Reference::shortfall`] says so in one line.
//! - **`--reference FILE.csv`:** the user's own, read by [`from_csv`]: the last row of a
//!   trajectory CSV in the shape `lie-sim run` writes (and `trade --write-reference` writes),
//!   taken to be accurate to the tolerance, which is then its estimated error.
//!
//! The estimated error is the trade's **floor**: an error below it measures the reference, not the
//! method, and is reported as unresolved (never as a number); a run counts as meeting an accuracy
//! target only when its error is resolved and its error plus the floor is within the target
//! ([`meets`]).

use crate::build::{build, characteristic_rate};
use crate::error::SimError;
use crate::measure::{timed_run, FinalState};
use crate::methods::{MethodId, MethodSpec};
use crate::model::{Alg, Job, Model};
use crate::scene::Scene;
use crate::sim::Entries;
use crate::systems::System;
use integrators::adaptive::{Adaptive, RkmkDop853, Tolerance};
use integrators::{GraggBulirschStoer, Integrator, IntegratorError};
use lie_groups::{LieGroup, Vector};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The default relative tolerance two successive refinements must agree to (`--reference-tolerance`'s
/// default, written there as "1e-13": unit test `the_flag_default_is_the_default_tolerance`).
pub const DEFAULT_TOLERANCE: f64 = 1e-13;

/// The default time the refinement may take (beyond its first two runs).
pub const DEFAULT_BUDGET: &str = "30s";

/// Refinement has stalled when a halving of h reduces the difference between successive runs by
/// less than this factor, twice in a row (at order 12 it falls ~4096-fold while truncation
/// dominates).
pub const STALL_RATIO: f64 = 0.5;

/// Stalling is only recognised below this difference: above it an order-12 method may still be
/// outside its asymptotic range, where differences need not fall.
pub const STALL_GATE: f64 = 1e-6;

/// The most halvings of h₀ (h₀/2³⁰: far beyond any budget on a scene the trade can run).
pub const MAX_REFINEMENTS: usize = 30;

/// A user reference's last row must be at T to this, relative to max(1, T) (a run's clock adds h
/// at every step and drifts by a few ulps per step).
pub const TIME_TOLERANCE: f64 = 1e-9;

/// How the reference is made: `--reference-tolerance`, `--reference-budget`, `--reference`.
#[derive(Debug, Clone)]
pub struct Options {
    /// The relative agreement required of two successive refinements (and the accuracy a user
    /// reference is taken to have).
    pub tolerance: f64,
    /// The time the refinements after the first two may take.
    pub budget: Duration,
    /// A user reference (the last row of a trajectory CSV), instead of computing one.
    pub file: Option<PathBuf>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            tolerance: DEFAULT_TOLERANCE,
            budget: Duration::from_secs(30),
            file: None,
        }
    }
}

/// The reference solution at T and how it was made.
#[derive(Debug, Clone)]
pub struct Reference {
    /// The state at T.
    pub state: FinalState,
    /// T.
    pub time: f64,
    /// The energy at the reference state (NaN for a user reference without one).
    pub energy: f64,
    /// The Casimir at the reference state, where the system monitors one.
    pub casimir: Option<f64>,
    /// E.g. `gragg-bulirsch-stoer (order 12) at h = 1.56e-2 (640 steps) …`.
    pub description: String,
    /// The estimated error (the floor): below it errors are unresolved. Infinite when no estimate
    /// could be made.
    pub estimated_error: f64,
    /// One line when the tolerance was not met (budget exhausted, rounding level reached).
    pub shortfall: Option<String>,
}

impl Reference {
    /// The reference as a one-row trajectory CSV (the shape `lie-sim run` writes and
    /// [`from_csv`] reads).
    pub fn to_csv(&self) -> String {
        let side = self
            .state
            .group
            .as_ref()
            .map(|g| (g.len() as f64).sqrt().round() as usize);
        let header = crate::columns::Layout {
            momentum: self.state.momentum.len(),
            side,
            casimir: self.casimir.is_some(),
            forced: false,
            bodies: 0,
        }
        .names();
        let mut row = vec![self.time];
        row.extend(&self.state.momentum);
        row.extend(self.state.group.iter().flatten());
        row.push(self.energy);
        row.extend(self.casimir);
        let mut s = header.join(",");
        s.push('\n');
        let cells: Vec<String> = row
            .iter()
            .map(|x| crate::run::Cell(*x).to_string())
            .collect();
        let _ = writeln!(s, "{}", cells.join(","));
        s
    }
}

/// Whether a measured error `value` meets `target` against a reference of estimated error
/// `floor`: its bound on the true error, `value + floor`, must be within the target. An
/// unresolved error (below the floor: there the reference, not the run, is measured) is bounded
/// by `2·floor` only — the run is at least as accurate as the reference can tell — so it meets a
/// target of twice the floor or looser, and a run is never credited with accuracy the reference
/// cannot show. A target below twice the floor cannot be met. (Before, unresolved runs never
/// qualified: the exact free-body flow, the reference itself, was then never picked.)
pub fn meets(value: f64, floor: f64, target: f64) -> bool {
    value.max(floor) + floor <= target
}

/// The reference of the module page for `scene` (over its duration T).
pub fn reference(scene: &Scene, options: &Options) -> Result<Reference, SimError> {
    if let Some(path) = &options.file {
        return from_csv(path, scene, options.tolerance);
    }
    let (omega, h0) = time_scale(scene)?;
    let data = data_rounding(omega, scene.duration);
    if matches!(scene.system, System::FreeRigidBody(_)) && scene.system.forces().is_none() {
        return exact_free_body(scene, h0, data, options.tolerance);
    }
    let start = Instant::now();
    let breaks = breakpoints(scene);
    let grid = mesh(scene, &breaks)?;
    let base = Base {
        label: format!(
            "the {} steps of rkmk-dop853 at rtol = {MESH_TOLERANCE:.0e}",
            grid.len()
        ),
        grid,
    };
    refined(scene, &base, breaks.len(), data, options, start)
}

/// The scene's time scale ω ([`crate::build::characteristic_rate`] at its initial state; 0 at
/// rest) and h₀ = min(T, 1/ω) of the module page (the scene's step when ω = 0).
fn time_scale(scene: &Scene) -> Result<(f64, f64), SimError> {
    let omega = characteristic_rate(&scene.system, scene.reconstruct)?;
    if omega.is_finite() && omega > 0.0 {
        Ok((omega, (1.0 / omega).min(scene.duration)))
    } else {
        Ok((0.0, scene.step.min(scene.duration)))
    }
}

/// The exact flow: the mean of its evaluations in one step to T and in n, n + 1, n + 2 steps
/// (n = max(8, ⌈T/h₀⌉)); the estimated error is their spread ([`spread`]).
fn exact_free_body(
    scene: &Scene,
    h0: f64,
    data: f64,
    tolerance: f64,
) -> Result<Reference, SimError> {
    let m = MethodSpec::plain(MethodId::Exact);
    let n = crate::scene::steps_for(scene.duration, h0).max(EXACT_MIN_STEPS);
    let mut samples = Vec::new();
    let (mut energy, mut casimir) = (f64::NAN, None);
    for steps in [1, n, n + 1, n + 2] {
        let mut sim = build(&scene.system, &m, scene.reconstruct, &scene.solver)?;
        let h = scene.duration / steps as f64;
        samples.push(timed_run(sim.as_mut(), scene.duration, h)?.state);
        if steps == 1 {
            (energy, casimir) = (sim.energy(), sim.casimir());
        }
    }
    let spread = spread(&samples);
    let estimated_error = spread + data;
    Ok(Reference {
        state: mean(&samples),
        time: scene.duration,
        energy,
        casimir,
        description: format!(
            "the exact free-body flow, the mean of its evaluations in 1, {n}, {} and {} steps to \
             T = {}: they spread by {spread:.1e}, plus {data:.1e} for the data's rounding",
            n + 1,
            n + 2,
            scene.duration
        ),
        estimated_error,
        shortfall: (estimated_error > tolerance).then(|| {
            format!(
                "tolerance {tolerance:.1e} not met: the exact flow's evaluations in 1, {n}, {} and \
                 {} steps spread by {spread:.1e} (rounding errors, amplified by the scene over T); \
                 errors below the estimated error {estimated_error:.1e} are reported as unresolved",
                n + 1,
                n + 2
            )
        }),
    })
}

/// The share of the estimated error that no run can see: the scene's data (inertia, masses, …)
/// enter every run as the same doubles, and a relative rounding ε of a rate ω shifts the phase by
/// ε ωT over T. Added to the spread of the runs: [`DATA_ROUNDING_ULPS`] · ε · (1 + ωT), with ω the
/// scene's time scale.
pub fn data_rounding(omega: f64, duration: f64) -> f64 {
    DATA_ROUNDING_ULPS * f64::EPSILON * (1.0 + omega * duration)
}

/// The number of roundings of a rate (1/I, I⁻¹Π, …) [`data_rounding`] allows for: measured on
/// fast-spinning free bodies in SE(3) against closed forms, the true error of the reference
/// reached 1.05× the spread of its runs, and 0.53× that spread plus 2ε(1 + ωT)
/// (`tests/reference.rs`).
pub const DATA_ROUNDING_ULPS: f64 = 2.0;

/// The fewest steps of the exact flow's stepped evaluations.
const EXACT_MIN_STEPS: u64 = 8;

/// The componentwise mean of final states (μ, and g's entries where every state has g).
fn mean(states: &[FinalState]) -> FinalState {
    let avg = |vs: Vec<&Vec<f64>>| -> Vec<f64> {
        let k = vs.len() as f64;
        (0..vs[0].len())
            .map(|i| vs.iter().map(|v| v[i]).sum::<f64>() / k)
            .collect()
    };
    FinalState {
        momentum: avg(states.iter().map(|s| &s.momentum).collect()),
        group: states
            .iter()
            .map(|s| s.group.as_ref())
            .collect::<Option<Vec<_>>>()
            .map(avg),
    }
}

/// The largest distance (the trade's error measure) between two of the states.
fn spread(states: &[FinalState]) -> f64 {
    let mut worst = 0.0f64;
    for (i, a) in states.iter().enumerate() {
        for b in &states[i + 1..] {
            worst = worst.max(a.error(b)).max(b.error(a));
        }
    }
    worst
}

/// The times in (0, T) where the scene's forces have kinks: the knots of every schedule (body
/// torque and force, thrust, wheel torques), sorted, each once.
fn breakpoints(scene: &Scene) -> Vec<f64> {
    let Some(f) = scene.system.forces() else {
        return Vec::new();
    };
    let mut v: Vec<f64> = [&f.torque, &f.force, &f.thrust, &f.wheel_torque]
        .into_iter()
        .flatten()
        .flat_map(|s| s.times().iter().copied())
        .filter(|&t| t > 0.0 && t < scene.duration)
        .collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

/// What one run of the refinement gave.
enum Outcome {
    /// The state at T (with the energy and Casimir there).
    Done(FinalState, f64, Option<f64>),
    /// The deadline passed before T.
    OutOfTime,
    /// A step left the domain of the exponential coordinates: h is too large.
    TooLarge,
}

/// The [`Job`] that runs [`GraggBulirschStoer`] over a grid (segments of equal steps, [`refine`])
/// on the scene's group and system.
struct GbsRun<'a> {
    grid: &'a [(f64, u64)],
    deadline: Option<Instant>,
}

/// How often (in steps) the deadline is read.
const DEADLINE_EVERY: u64 = 16;

impl Job for GbsRun<'_> {
    type Out = Result<Outcome, (u64, f64, IntegratorError)>;
    fn run<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<Self::Out, SimError> {
        let mut m = GraggBulirschStoer::new(model.system().clone(), mu0, g0).map_err(|e| {
            SimError::Build {
                what: format!("the reference (gragg-bulirsch-stoer) of {}", model.kind()),
                message: e.to_string(),
            }
        })?;
        let (mut k, mut check_at) = (0u64, 0u64);
        for &(h, n) in self.grid {
            for _ in 0..n {
                if k == check_at {
                    check_at += DEADLINE_EVERY;
                    if self.deadline.is_some_and(|d| Instant::now() > d) {
                        return Ok(Ok(Outcome::OutOfTime));
                    }
                }
                match m.step(h) {
                    Ok(()) => {}
                    Err(IntegratorError::StepTooLarge { .. }) => return Ok(Ok(Outcome::TooLarge)),
                    Err(e) => return Ok(Err((k, m.time(), e))),
                }
                k += 1;
            }
        }
        Ok(Ok(Outcome::Done(final_state(&m), m.energy(), m.casimir())))
    }
}

/// The state of a method as the trade compares it: μ, and g's matrix entries row by row.
fn final_state<I: Integrator<Group: crate::sim::SimGroup>>(m: &I) -> FinalState {
    FinalState {
        momentum: m.momentum().to_vec(),
        group: m.configuration().map(|g| {
            let matrix = g.matrix();
            let side = matrix.side();
            let mut entries = vec![0.0; side * side];
            matrix.write_row_major(&mut entries);
            entries
        }),
    }
}

/// The [`Job`] that runs [`RkmkDop853`] under [`Adaptive`] at `tolerance`, its steps landing on
/// each of `ends` (the force schedules' knots, then T) in turn, and returns the lengths of its
/// accepted steps: the mesh of the reference's refinement.
struct MeshRun<'a> {
    ends: &'a [f64],
    tolerance: Tolerance,
}

impl Job for MeshRun<'_> {
    type Out = Result<Vec<f64>, (u64, f64, IntegratorError)>;
    fn run<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<Self::Out, SimError> {
        let method =
            RkmkDop853::new(model.system().clone(), mu0, g0).map_err(|e| SimError::Build {
                what: format!("the reference's mesh (rkmk-dop853) of {}", model.kind()),
                message: e.to_string(),
            })?;
        let mut run = Adaptive::new(method, self.tolerance).with_max_steps(MESH_MAX_STEPS);
        let mut steps = Vec::new();
        for &end in self.ends {
            while run.method().time() != end {
                let t = run.method().time();
                if let Err(e) = run.step_towards(end) {
                    return Ok(Err((steps.len() as u64, t, e)));
                }
                steps.push(run.method().time() - t);
            }
        }
        Ok(Ok(steps))
    }
}

/// The tolerance (rtol; atol the same in the units of μ) of the run whose steps are the mesh of the
/// refinement: loose, the mesh only has to follow the motion's time scales; the accuracy comes
/// from the order-12 extrapolation on it and from halving it.
pub const MESH_TOLERANCE: f64 = 1e-6;

/// The most steps (accepted and rejected) of the run that makes the mesh.
pub const MESH_MAX_STEPS: usize = 10_000_000;

/// The mesh of the refinement: the steps of [`RkmkDop853`] under [`Adaptive`] at
/// [`MESH_TOLERANCE`], landing on `breaks` and T, as a grid of (step, 1).
fn mesh(scene: &Scene, breaks: &[f64]) -> Result<Vec<(f64, u64)>, SimError> {
    let ends: Vec<f64> = breaks
        .iter()
        .copied()
        .chain(std::iter::once(scene.duration))
        .collect();
    // atol in the units of μ: the trade measures μ relative to its largest component.
    let mu_scale = match scene.system.dispatch(scene.reconstruct, InitialMomentum)? {
        m if m > 0.0 && m.is_finite() => m.min(1.0),
        _ => 1.0,
    };
    let tolerance =
        Tolerance::new(MESH_TOLERANCE, MESH_TOLERANCE * mu_scale).map_err(|e| SimError::Build {
            what: "the reference's mesh (rkmk-dop853)".into(),
            message: e.to_string(),
        })?;
    match scene.system.dispatch(
        scene.reconstruct,
        MeshRun {
            ends: &ends,
            tolerance,
        },
    )? {
        Ok(steps) => Ok(steps.into_iter().map(|h| (h, 1)).collect()),
        Err((step, time, e)) => Err(SimError::Step {
            step,
            time,
            message: format!(
                "the reference's mesh (rkmk-dop853 at rtol = {MESH_TOLERANCE:.0e}): {e}"
            ),
        }),
    }
}

/// The [`Job`] that reads the largest component of μ₀ in max norm.
struct InitialMomentum;

impl Job for InitialMomentum {
    type Out = f64;
    fn run<M: Model>(self, _: &M, mu0: Alg<M::G>, _: Option<M::G>) -> Result<f64, SimError> {
        Ok(mu0.norm_max())
    }
}

/// `base` with each segment's steps split in `2^level`.
fn refine(base: &[(f64, u64)], level: u32) -> Vec<(f64, u64)> {
    let k = 1u64 << level;
    base.iter().map(|&(h, n)| (h / k as f64, n * k)).collect()
}

/// `grid` with `extra` more steps in its longest segment: a run of the same accuracy whose
/// roundings fall differently.
fn with_extra(grid: &[(f64, u64)], extra: u64) -> Vec<(f64, u64)> {
    let longest = (0..grid.len())
        .max_by(|&a, &b| (grid[a].0 * grid[a].1 as f64).total_cmp(&(grid[b].0 * grid[b].1 as f64)))
        .unwrap_or(0);
    grid.iter()
        .enumerate()
        .map(|(i, &(h, n))| {
            if i == longest {
                (h * n as f64 / (n + extra) as f64, n + extra)
            } else {
                (h, n)
            }
        })
        .collect()
}

/// The number of extra runs at the reference's step (with 1, 2, … more steps) whose mean is the
/// reference and whose spread enters its estimated error.
pub const EXTRA_SAMPLES: u64 = 2;

/// The level-0 grid of the refinement and how to name it.
struct Base {
    /// Segments (step, count), ending on the knots and T.
    grid: Vec<(f64, u64)>,
    /// E.g. `h = 1.0e-1` or `the 412 steps of rkmk-dop853 at rtol = 1e-6`.
    label: String,
}

/// The Gragg–Bulirsch–Stoer refinement of the module page on the grid `base`, its steps split in
/// 1, 2, 4, … .
fn refined(
    scene: &Scene,
    base: &Base,
    knots: usize,
    data: f64,
    options: &Options,
    start: Instant,
) -> Result<Reference, SimError> {
    let run = |grid: &[(f64, u64)], deadline: Option<Instant>, level: u32| {
        let job = GbsRun { grid, deadline };
        match scene.system.dispatch(scene.reconstruct, job)? {
            Err((step, time, e)) => Err(SimError::Step {
                step,
                time,
                message: format!(
                    "the reference (gragg-bulirsch-stoer on {}, split in {}): {e}",
                    base.label,
                    1u64 << level
                ),
            }),
            Ok(outcome) => Ok(outcome),
        }
    };
    let tolerance = options.tolerance;
    // (level, steps, state, energy, Casimir) of each completed run, and the differences between
    // successive runs.
    let mut runs: Vec<(u32, u64, FinalState, f64, Option<f64>)> = Vec::new();
    let mut diffs: Vec<f64> = Vec::new();
    let mut why_stopped: Option<String> = None;
    for level in 0..=MAX_REFINEMENTS as u32 {
        let grid = refine(&base.grid, level);
        let deadline = (runs.len() >= 2).then(|| start + options.budget);
        match run(&grid, deadline, level)? {
            Outcome::OutOfTime => {
                why_stopped = Some(format!(
                    "--reference-budget {:?} ran out at {} split in {}",
                    options.budget,
                    base.label,
                    1u64 << level
                ));
                break;
            }
            Outcome::TooLarge => {}
            Outcome::Done(state, energy, casimir) => {
                let steps = grid.iter().map(|s| s.1).sum();
                if let Some(prev) = runs.last() {
                    diffs.push(state.error(&prev.2));
                }
                runs.push((level, steps, state, energy, casimir));
                let d = diffs.last().copied().unwrap_or(f64::INFINITY);
                if d <= tolerance {
                    break;
                }
                let stalled = |i: usize| diffs[i] > STALL_RATIO * diffs[i - 1];
                let n = diffs.len();
                if n >= 3 && d < STALL_GATE && stalled(n - 1) && stalled(n - 2) {
                    why_stopped = Some(format!(
                        "the refinement stalled at the rounding level (differences {})",
                        diffs[n - 3..]
                            .iter()
                            .map(|d| format!("{d:.1e}"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ));
                    break;
                }
            }
        }
    }
    // The finer run of the closest-agreeing pair (the last one when the tolerance was met).
    let Some(index) = (0..diffs.len())
        .min_by(|&a, &b| diffs[a].total_cmp(&diffs[b]))
        .map(|i| i + 1)
    else {
        return Err(SimError::Step {
            step: 0,
            time: 0.0,
            message: format!(
                "the reference: gragg-bulirsch-stoer did not complete two runs on {} and its \
                 halvings (every step left the domain of the exponential coordinates)",
                base.label
            ),
        });
    };
    let (level, steps, fine, energy, casimir) = runs[index].clone();
    let fine_grid = refine(&base.grid, level);
    // Runs of the same accuracy with 1, 2, … more steps: their roundings fall differently.
    let mut samples = vec![fine];
    for extra in 1..=EXTRA_SAMPLES {
        if let Outcome::Done(state, ..) = run(&with_extra(&fine_grid, extra), None, level)? {
            samples.push(state);
        }
    }
    let state = mean(&samples);
    samples.push(runs[index - 1].2.clone());
    let spread = spread(&samples);
    let estimated_error = spread + data;
    let met = estimated_error <= tolerance;
    let shortfall = (!met).then(|| {
        format!(
            "tolerance {tolerance:.1e} not met: {}; errors below the estimated error \
             {estimated_error:.1e} are reported as unresolved",
            why_stopped.clone().unwrap_or_else(|| {
                if diffs[index - 1] <= tolerance {
                    "the runs at the reference's step spread beyond it (rounding errors, \
                     amplified by the scene over T)"
                        .to_string()
                } else {
                    format!("{MAX_REFINEMENTS} halvings of the steps were not enough")
                }
            })
        )
    });
    Ok(Reference {
        state,
        time: scene.duration,
        energy,
        casimir,
        description: format!(
            "gragg-bulirsch-stoer (order {}), the mean of its runs on {} split in {} ({steps} \
             steps{} and {EXTRA_SAMPLES} with 1, 2 more): with the run at twice the step they \
             spread by {spread:.1e}, plus {data:.1e} for the data's rounding ({:.2} s)",
            2 * GraggBulirschStoer::<lie_groups::So3, mechanics::systems::RigidBody>::DEFAULT_COLUMNS,
            base.label,
            1u64 << level,
            if knots == 0 {
                String::new()
            } else {
                format!(", ending on the force schedules' {knots} knots")
            },
            start.elapsed().as_secs_f64()
        ),
        estimated_error,
        shortfall,
    })
}

/// A user reference: the last row of the trajectory CSV at `path` (header `t, mu1 … muN, g11 …,
/// energy[, casimir]` as `lie-sim run` writes it; the g columns are required when the scene
/// reconstructs g and ignored otherwise), which must be at T and finite, with the momentum and
/// group dimensions of the scene. Its estimated error is `tolerance`.
pub fn from_csv(path: &Path, scene: &Scene, tolerance: f64) -> Result<Reference, SimError> {
    let label = path.display().to_string();
    let text = crate::input::read_text(path)?;
    let traj = crate::plot::parse_csv(&text, &label)?;
    let line = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .last()
        .map_or(1, |(i, _)| i + 1);
    let bad = |message: String| SimError::Csv {
        path: label.clone(),
        line,
        message,
    };
    let sim = build(
        &scene.system,
        &scene.method,
        scene.reconstruct,
        &scene.solver,
    )?;
    let n = sim.momentum_dim();
    let side = sim.group_side();
    let last = traj.rows() - 1;
    let value = |name: &str| -> Result<f64, SimError> {
        let v = traj
            .column(name)
            .ok_or_else(|| bad(format!("no `{name}` column")))?[last];
        if v.is_finite() {
            Ok(v)
        } else {
            Err(bad(format!("`{name}` = {v} in the last row is not finite")))
        }
    };
    let momenta = traj.momentum().len();
    if momenta != n {
        return Err(bad(format!(
            "{momenta} momentum columns (mu1 …); the scene's {} has {n}",
            scene.system.kind()
        )));
    }
    let t = value("t")?;
    if (t - scene.duration).abs() > TIME_TOLERANCE * scene.duration.max(1.0) {
        return Err(bad(format!(
            "the last row is at t = {t}, not at the horizon T = {}",
            scene.duration
        )));
    }
    let momentum = (1..=n)
        .map(|i| value(&format!("mu{i}")))
        .collect::<Result<Vec<f64>, SimError>>()?;
    let group = match side {
        None => None,
        Some(m) => {
            let g_names = &crate::columns::group_names(Some(m));
            let found = traj
                .header
                .iter()
                .filter(|h| h.starts_with('g') && h[1..].starts_with(|c: char| c.is_ascii_digit()))
                .count();
            if found != m * m || g_names.iter().any(|g| traj.column(g).is_none()) {
                return Err(bad(format!(
                    "{found} group columns (g11 …); the scene reconstructs a {m}×{m} matrix \
                     ({} columns {} … {})",
                    m * m,
                    g_names[0],
                    g_names[m * m - 1]
                )));
            }
            Some(
                g_names
                    .iter()
                    .map(|g| value(g))
                    .collect::<Result<Vec<f64>, SimError>>()?,
            )
        }
    };
    let energy = traj.column("energy").map_or(f64::NAN, |c| c[last]);
    let casimir = traj.column("casimir").map(|c| c[last]);
    Ok(Reference {
        state: FinalState { momentum, group },
        time: t,
        energy,
        casimir,
        description: format!(
            "{label} (its last row, t = {t}), taken to be accurate to the tolerance \
             {tolerance:.1e}"
        ),
        estimated_error: tolerance,
        shortfall: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_flag_default_is_the_default_tolerance() {
        assert_eq!("1e-13".parse::<f64>().unwrap(), DEFAULT_TOLERANCE);
        assert_eq!(budget_of(DEFAULT_BUDGET), Options::default().budget);
    }

    /// `DEFAULT_BUDGET` ("30s") as a duration.
    fn budget_of(s: &str) -> Duration {
        Duration::from_secs(s.trim_end_matches('s').parse().unwrap())
    }

    /// The ends of a grid's steps, in order.
    fn ends(grid: &[(f64, u64)]) -> Vec<f64> {
        let mut t = 0.0;
        let mut v = Vec::new();
        for &(h, n) in grid {
            for _ in 0..n {
                t += h;
                v.push(t);
            }
        }
        v
    }

    /// The mesh's steps end on every knot of the force schedules and on T (the detumbling scene's
    /// torque kinks at 5 and 5.1), and stay there when split in 2ᵏ or given extra steps.
    #[test]
    fn the_mesh_ends_its_steps_on_the_breakpoints() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/scenes/detumbling-spacecraft.toml");
        let overrides = crate::scene::Overrides {
            duration: Some(8.0),
            duration_flag: None,
            step: None,
            stride: None,
        };
        let scene = Scene::load(&path, overrides).unwrap();
        let breaks = breakpoints(&scene);
        let base = mesh(&scene, &breaks).unwrap();
        assert!(base.len() > 3, "{base:?}");
        for grid in [
            base.clone(),
            refine(&base, 3),
            with_extra(&refine(&base, 1), 2),
        ] {
            let e = ends(&grid);
            for x in [5.0, 5.1, 8.0] {
                let near = e
                    .iter()
                    .map(|t| (t - x).abs())
                    .fold(f64::INFINITY, f64::min);
                assert!(near < 1e-13, "no step ends at {x}: {near:e}");
            }
            assert!((e.last().unwrap() - 8.0).abs() < 1e-13);
        }
        assert_eq!(refine(&[(0.5, 3)], 2), vec![(0.125, 12)]);
        assert_eq!(
            with_extra(&[(0.1, 1), (1.0, 2)], 1),
            vec![(0.1, 1), (2.0 / 3.0, 3)]
        );
    }

    /// The detumbling scene's torque has knots at 0, 5 and 5.1: the reference's steps end on the
    /// interior ones that lie before T. The quadrotor's thrust and torque schedules both count
    /// (thrust 0, 1, 1.1, 2, 2.1; torque 2.5 … 3.4), merged in order; the reaction wheels' too.
    #[test]
    fn the_breakpoints_are_the_knots_of_every_schedule_inside_the_horizon() {
        let scene = |name: &str, duration: f64| {
            let path = Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../examples/scenes")
                .join(name);
            let overrides = crate::scene::Overrides {
                duration: Some(duration),
                duration_flag: None,
                step: None,
                stride: None,
            };
            Scene::load(&path, overrides).unwrap()
        };
        let at = |duration: f64| breakpoints(&scene("detumbling-spacecraft.toml", duration));
        assert_eq!(at(60.0), [5.0, 5.1]);
        assert_eq!(at(5.05), [5.0]);
        assert!(at(5.0).is_empty());
        assert_eq!(
            breakpoints(&scene("quadrotor.toml", 5.0)),
            [1.0, 1.1, 2.0, 2.1, 2.5, 2.6, 2.9, 3.0, 3.3, 3.4]
        );
        assert_eq!(
            breakpoints(&scene("reaction-wheel-slew.toml", 60.0)),
            [20.0, 20.05, 40.0, 40.05]
        );
        let free = Scene::default_scene(Default::default()).unwrap();
        assert!(breakpoints(&free).is_empty());
    }

    #[test]
    fn a_run_meets_a_target_by_its_error_bound_with_the_floor_added() {
        assert!(meets(5e-11, 1e-13, 1e-10));
        assert!(!meets(9.995e-11, 1e-13, 1e-10));
        // Unresolved (below the floor): bounded by twice the floor, not by its own value.
        assert!(meets(1e-16, 1e-13, 1.0));
        assert!(meets(1e-16, 1e-13, 2e-13));
        assert!(!meets(1e-16, 1e-13, 1.9e-13));
        assert!(meets(1e-13, 1e-13, 2e-13));
        assert!(!meets(0.5, f64::INFINITY, 1.0));
    }
}
