//! `lie-sim run`: advance a scene and write its trajectory as CSV.
//!
//! Columns ([`crate::columns`]): `t`, `mu1 … muN` (body momentum μ), `g11, g12, …` (the group
//! element's matrix, row-major; left out when the scene does not reconstruct g), `energy`,
//! `casimir` where the system has one, `power, work` where the scene has forces, and each body's
//! attitude as a unit quaternion and a rotation vector ([`crate::attitude`]) where g is
//! reconstructed.
//!
//! The summary's energy line: without forces the energy is conserved by the flow, and
//! `max |E − E₀|/|E₀|` is the method's energy error. With forces the energy changes by their work:
//! the summary then reports the **energy change** `E(T) − E₀` as such, the **work**
//! `W = ∫₀ᵀ ⟨F_ext, ξ⟩ dt` (trapezoid rule over the steps), and the **energy balance error**
//! `max_k |E_k − E₀ − W_k| / max_k |E_k|` — the part of the change the forces do not account for,
//! which is the method's error plus the quadrature's O(h²).

use crate::build::build_with;
use crate::error::SimError;
use crate::invariants::relative_error;
use crate::output::AtomicFile;
use crate::scene::{EventSpec, Scene};
use crate::sim::Simulation;
use indicatif::{ProgressBar, ProgressStyle};
use integrators::adaptive::Stats;
use integrators::events::find_crossing;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Runs shorter than this many steps get no progress bar.
pub const PROGRESS_MIN_STEPS: u64 = 200_000;

/// What a run did, for the summary.
#[derive(Debug, Clone)]
pub struct RunSummary {
    /// Steps taken (accepted, for a tolerance-driven run).
    pub steps: u64,
    /// A tolerance-driven run's accepted and rejected steps and smallest and largest step.
    pub stats: Option<Stats>,
    /// CSV rows written (without the header).
    pub rows: u64,
    /// Wall time of the whole run, stepping and writing.
    pub wall: Duration,
    /// max_k |E_k − E₀| / |E₀| (absolute when E₀ = 0).
    pub max_energy_error: f64,
    /// max_k |C_k − C₀| / |C₀| for the Casimir, where the system has one.
    pub max_casimir_error: Option<f64>,
    /// E(T) − E₀ (at the run's last state).
    pub energy_change: f64,
    /// With forces: their work W(T) and the energy balance error
    /// `max_k |E_k − E₀ − W_k| / max_k |E_k|` (see the module page).
    pub work: Option<Work>,
    /// How far each body turned from its initial attitude by the run's end: the angle of R₀ᵀR
    /// ([`crate::attitude::turned`]); empty without attitudes.
    pub turned: Vec<f64>,
    /// The state at the run's end, compared with a reference by `run --reference`.
    pub final_state: crate::measure::FinalState,
    /// Where the CSV went.
    pub out: PathBuf,
    /// What the method is and keeps, as it describes itself.
    pub info: integrators::MethodInfo,
    /// The crossings of the scene's `[[events]]`, in time order.
    pub events: Vec<EventRecord>,
    /// The time at which a `stop = true` event ended the run.
    pub stopped_at: Option<f64>,
}

/// The work of the forces over a run and the energy balance it leaves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Work {
    /// W(T) = ∫₀ᵀ ⟨F_ext, ξ⟩ dt, trapezoid rule over the steps.
    pub work: f64,
    /// max_k |E_k − E₀ − W_k| / max_k |E_k| (absolute when the energy stays 0).
    pub max_balance_error: f64,
}

/// The work of the forces accumulated along a run by the trapezoid rule over its steps, and the
/// energy balance it leaves (see the module page). Reads nothing but what it is given: no
/// allocation per step.
#[derive(Debug, Clone, Copy)]
pub struct WorkMeter {
    e0: f64,
    /// (t, P, W) at the last step's end.
    last: (f64, f64, f64),
    max_balance: f64,
    max_energy: f64,
}

impl WorkMeter {
    /// A meter started at time t₀ with energy E₀ and power P₀.
    pub fn new(t0: f64, e0: f64, p0: f64) -> Self {
        Self {
            e0,
            last: (t0, p0, 0.0),
            max_balance: 0.0,
            max_energy: e0.abs(),
        }
    }
    /// W(t) for a time t in the current step with power P(t) there: the last step's end's W plus
    /// the trapezoid from it to t.
    pub fn work_at(&self, t: f64, p: f64) -> f64 {
        let (t0, p0, w0) = self.last;
        w0 + 0.5 * (t - t0) * (p0 + p)
    }
    /// Closes a step ending at t with energy E and power P there; returns W(t).
    pub fn step(&mut self, t: f64, e: f64, p: f64) -> f64 {
        let w = self.work_at(t, p);
        self.last = (t, p, w);
        self.max_balance = self.max_balance.max((e - self.e0 - w).abs());
        self.max_energy = self.max_energy.max(e.abs());
        w
    }
    /// W and the balance error so far.
    pub fn result(&self) -> Work {
        Work {
            work: self.last.2,
            max_balance_error: if self.max_energy > 0.0 {
                self.max_balance / self.max_energy
            } else {
                self.max_balance
            },
        }
    }
}

/// One located crossing of a scene event.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRecord {
    /// The column that crossed.
    pub quantity: String,
    /// The value it crossed.
    pub value: f64,
    /// The crossing time, located on the step's interpolant to [`EVENT_TOLERANCE`] × max(1, T).
    pub t: f64,
    /// Whether the column was rising.
    pub rising: bool,
}

/// Relative width (in units of max(1, T)) to which event times are located.
pub const EVENT_TOLERANCE: f64 = 1e-12;

/// The CSV header for a simulation's columns ([`crate::columns`]).
pub fn header(sim: &dyn Simulation) -> Vec<String> {
    sim.layout().names()
}

/// A CSV cell: the shortest decimal that reads back to the same double (`{:?}`), in exponent form
/// for very small or large magnitudes (`1e-300`, not 300 digits).
pub struct Cell(pub f64);

impl std::fmt::Display for Cell {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:?}", self.0)
    }
}

/// One CSV row of cells.
fn write_cells(w: &mut impl Write, row: &[f64]) -> std::io::Result<()> {
    for (i, x) in row.iter().enumerate() {
        if i > 0 {
            write!(w, ",")?;
        }
        write!(w, "{}", Cell(*x))?;
    }
    writeln!(w)
}

/// The row at time tc of step k: the step's end `row1` itself, or interpolated into `between`
/// (its `work` cell, at index `work.0`, the trapezoid from the step's start, `work.1`).
fn row_at<'a>(
    sim: &dyn Simulation,
    row1: &'a [f64],
    between: &'a mut [f64],
    tc: f64,
    k: u64,
    work: Option<(usize, &WorkMeter)>,
) -> Result<&'a [f64], SimError> {
    if tc == row1[0] {
        Ok(row1)
    } else {
        sim.read_at(tc, between).map_err(|message| SimError::Step {
            step: k,
            time: tc,
            message,
        })?;
        if let Some((j, meter)) = work {
            between[j] = meter.work_at(tc, between[j - 1]);
        }
        Ok(between)
    }
}

/// Builds the scene's simulation and runs it, writing the CSV to `out` (atomically), after
/// checking the work against the limits of [`crate::bounds`] (unless `allow_large`).
pub fn run_scene(
    scene: &Scene,
    out: &Path,
    progress: bool,
    allow_large: bool,
) -> Result<RunSummary, SimError> {
    let mut sim = build_with(
        &scene.system,
        &scene.method,
        scene.reconstruct,
        &scene.solver,
        scene.variable,
    )?;
    let n = u128::from(scene.steps());
    // The runner reads the state after every step (energy monitor, rows, events): a processed
    // method pays its processor there too.
    let stages = (scene.method.stages()
        + scene
            .method
            .processing
            .as_ref()
            .map_or(0, |p| p.processor_stages())) as u128;
    let rows = 2 + n / u128::from(scene.stride);
    let estimate = crate::bounds::Estimate {
        steps: n.saturating_mul(stages),
        bytes: crate::bounds::Estimate::csv(rows, sim.columns() as u128),
        step_cost: crate::build::step_cost(
            sim.as_ref(),
            &scene.solver,
            crate::bounds::dynamic_group(scene.system.kind()),
        ),
    };
    estimate.check("run", allow_large)?;
    run_simulation(sim.as_mut(), scene, out, progress)
}

/// Runs an already built simulation for the scene's duration, writing the CSV to `out`.
///
/// Steps of size h, the last one shortened so that the run ends at T exactly — or, for a
/// tolerance-driven scene, the steps its controller accepts, the last one landing on T
/// ([`Simulation::step_towards`]); a row at t = 0, every `stride` steps, and at t = T — or, with `[output] times`, rows at exactly those times,
/// interpolated between steps ([`Simulation::read_at`]). `[[events]]` crossings are located on
/// the step's interpolant to [`EVENT_TOLERANCE`] × max(1, T) and returned; a `stop = true`
/// event ends the run with a last row at its time.
///
/// After each step the loop reads what it needs from the state in place — the energy and the
/// Casimir for the monitor, the whole row only when an event watches a column or a row is
/// written — into buffers made once, and formats a row only when it writes it: a run that writes
/// few rows costs what its steps cost.
pub fn run_simulation(
    sim: &mut dyn Simulation,
    scene: &Scene,
    out: &Path,
    progress: bool,
) -> Result<RunSummary, SimError> {
    let start = Instant::now();
    let file = AtomicFile::new(out)?;
    let mut w = file.create()?;
    let adaptive = scene.variable.is_some();
    // A run with variable steps does not know its steps ahead: its progress is the time reached.
    let n = if adaptive { u64::MAX } else { scene.steps() };
    let h = scene.step;
    let h_last = scene.duration - (n - 1) as f64 * h;

    let werr = |e| file.write_error(e);
    let columns = header(sim);
    // each event's column in the rows
    let events: Vec<(usize, &EventSpec)> = scene
        .events
        .iter()
        .enumerate()
        .map(|(i, e)| {
            columns
                .iter()
                .position(|c| *c == e.quantity)
                .map(|j| (j, e))
                .ok_or_else(|| SimError::Invalid {
                    path: scene.source.clone(),
                    field: format!("events[{i}].quantity"),
                    message: format!(
                        "\"{}\" is not a column of this run (the columns are {})",
                        e.quantity,
                        columns[1..].join(", ")
                    ),
                })
        })
        .collect::<Result<_, _>>()?;
    let dense = scene.output_times.is_some() || !events.is_empty();
    let tolerance = EVENT_TOLERANCE * scene.duration.max(1.0);
    writeln!(w, "{}", columns.join(",")).map_err(werr)?;
    // The row before the step, the row after it, and an interpolated row.
    let width = columns.len();
    let (mut row0, mut row1, mut between) = (vec![0.0; width], vec![0.0; width], vec![0.0; width]);
    let mut rows = 0u64;
    let mut next_time = 0usize;
    let times: &[f64] = scene.output_times.as_deref().unwrap_or(&[]);
    sim.read(&mut row0);
    let work_column = sim.layout().work();
    let mut attitudes0 = vec![0.0; sim.bodies() * crate::attitude::CELLS];
    sim.read_attitudes(&mut attitudes0);
    let mut meter = sim
        .power()
        .map(|p0| WorkMeter::new(sim.time(), sim.energy(), p0));
    if let Some(j) = work_column {
        row0[j] = 0.0;
    }
    if scene.output_times.is_none() {
        write_cells(&mut w, &row0).map_err(werr)?;
        rows += 1;
    } else {
        while next_time < times.len() && times[next_time] <= row0[0] {
            write_cells(&mut w, &row0).map_err(werr)?;
            rows += 1;
            next_time += 1;
        }
    }
    let mut since_row = 0u64;
    let mut records = Vec::new();
    let mut stopped_at = None;

    let e0 = sim.energy();
    let c0 = sim.casimir();
    let mut max_e = 0.0f64;
    let mut max_c = c0.map(|_| 0.0f64);

    const TIME_TICKS: u64 = 1000;
    let bar = (progress && (adaptive || n >= PROGRESS_MIN_STEPS)).then(|| {
        let b = ProgressBar::new(if adaptive { TIME_TICKS } else { n });
        if let Ok(style) = ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} steps (eta {eta})",
        ) {
            b.set_style(style);
        }
        b
    });
    let tick = if adaptive { 64 } else { (n / 500).max(1) };
    let position = |k: u64, t: f64| {
        if adaptive {
            (t / scene.duration * TIME_TICKS as f64) as u64
        } else {
            k
        }
    };

    let mut taken = 0;
    let mut k = 0u64;
    // The time at the start of the step: the last step's end (a failed step leaves the state,
    // and its time, as it was).
    let mut t = sim.time();
    loop {
        if dense {
            sim.mark();
        }
        let stepped = if adaptive {
            sim.step_towards(scene.duration)
        } else {
            sim.step(if k + 1 == n { h_last } else { h })
        };
        stepped.map_err(|message| SimError::Step {
            step: k,
            time: t,
            message,
        })?;
        let t_now = sim.time();
        taken += 1;
        let last = if adaptive {
            t_now == scene.duration
        } else {
            k + 1 == n
        };
        let e = sim.energy();
        if !e.is_finite() {
            if let Some(message) = sim.read_error() {
                return Err(SimError::Step {
                    step: k,
                    time: t,
                    message: format!("reading the state: {message}"),
                });
            }
            return Err(SimError::NonFinite { step: k, time: t });
        }
        max_e = max_e.max(relative_error(e, e0));
        // The meter before this step, for rows between its ends.
        let before = meter;
        // The power only where there are forces to meter.
        let work_now = meter
            .as_mut()
            .and_then(|m| sim.power().map(|p| m.step(t_now, e, p)));
        if let (Some(c0), Some(mc)) = (c0, max_c.as_mut()) {
            if let Some(c) = sim.casimir() {
                *mc = mc.max(relative_error(c, c0));
            }
        }
        let stride_row = scene.output_times.is_none() && (since_row + 1 == scene.stride || last);
        let time_row = next_time < times.len() && times[next_time] <= t_now;
        if events.is_empty() && !stride_row && !time_row {
            since_row += 1;
            if let Some(b) = &bar {
                if k.is_multiple_of(tick) {
                    b.set_position(position(k, t_now));
                }
            }
            if last {
                break;
            }
            k += 1;
            t = t_now;
            continue;
        }
        sim.read(&mut row1);
        let work = work_column.zip(before.as_ref());
        if let (Some(j), Some(w)) = (work_column, work_now) {
            row1[j] = w;
        }
        // events: sign changes of (column − value) over the step, located on the interpolant
        let mut step_records = Vec::new();
        for &(j, ev) in &events {
            let (v0, v1) = (row0[j] - ev.value, row1[j] - ev.value);
            if let Some(rising) = ev.direction.crossing(v0, v1) {
                let f = |tc: f64| {
                    let mut r = vec![0.0; width];
                    match sim.read_at(tc, &mut r) {
                        Ok(()) => {
                            if let Some((jw, m)) = work {
                                r[jw] = m.work_at(tc, r[jw - 1]);
                            }
                            r[j] - ev.value
                        }
                        Err(_) => f64::NAN,
                    }
                };
                let tc = find_crossing(f, (row0[0], v0), (row1[0], v1), tolerance);
                step_records.push((
                    ev.stop,
                    EventRecord {
                        quantity: ev.quantity.clone(),
                        value: ev.value,
                        t: tc,
                        rising,
                    },
                ));
            }
        }
        step_records.sort_by(|a, b| a.1.t.total_cmp(&b.1.t));
        if let Some(i) = step_records.iter().position(|(stop, _)| *stop) {
            step_records.truncate(i + 1);
            stopped_at = Some(step_records[i].1.t);
        }
        records.extend(step_records.into_iter().map(|(_, r)| r));
        let t_end = stopped_at.unwrap_or(row1[0]);
        if scene.output_times.is_some() {
            while next_time < times.len() && times[next_time] <= t_end {
                write_cells(
                    &mut w,
                    row_at(sim, &row1, &mut between, times[next_time], k, work)?,
                )
                .map_err(werr)?;
                rows += 1;
                next_time += 1;
            }
        } else {
            since_row += 1;
            if stopped_at.is_some() {
                write_cells(&mut w, row_at(sim, &row1, &mut between, t_end, k, work)?)
                    .map_err(werr)?;
                rows += 1;
            } else if since_row == scene.stride || last {
                write_cells(&mut w, &row1).map_err(werr)?;
                rows += 1;
                since_row = 0;
            }
        }
        if let Some(b) = &bar {
            if k.is_multiple_of(tick) {
                b.set_position(position(k, t_now));
            }
        }
        std::mem::swap(&mut row0, &mut row1);
        if stopped_at.is_some() || last {
            break;
        }
        k += 1;
        t = t_now;
    }
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    file.commit_writer(w)?;
    let mut attitudes = vec![0.0; attitudes0.len()];
    sim.read_attitudes(&mut attitudes);
    Ok(RunSummary {
        turned: crate::attitude::turned(&attitudes0, &attitudes),
        steps: taken,
        stats: sim.stats(),
        rows,
        wall: start.elapsed(),
        max_energy_error: max_e,
        max_casimir_error: max_c,
        energy_change: sim.energy() - e0,
        work: meter.map(|m| m.result()),
        final_state: crate::measure::FinalState::of(sim),
        out: out.to_path_buf(),
        info: sim.info(),
        events: records,
        stopped_at,
    })
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::scene::Overrides;
    use crate::sim::mock::Spin;

    fn scene(duration: f64, step: f64, stride: u64) -> Scene {
        let mut s = Scene::default_scene(Overrides::default()).unwrap();
        s.duration = duration;
        s.step = step;
        s.stride = stride;
        s
    }

    fn tmp(name: &str) -> PathBuf {
        std::env::temp_dir()
            .join(format!("lie-sim-run-{}", std::process::id()))
            .join(name)
    }

    #[test]
    fn cells_are_short_and_read_back_exactly() {
        for x in [
            1e-300,
            0.1,
            1e16,
            -2.5e-7,
            123.456,
            0.0,
            f64::MIN_POSITIVE / 8.0,
        ] {
            let text = Cell(x).to_string();
            assert!(text.len() <= 24, "{text}");
            assert_eq!(text.parse::<f64>().unwrap(), x, "{text}");
        }
        assert_eq!(Cell(1e-300).to_string(), "1e-300");
    }

    #[test]
    fn csv_has_header_and_one_row_per_stride_plus_ends() {
        let out = tmp("spin.csv");
        let mut sim = Spin {
            t: 0.0,
            omega: 1.0,
            reconstruct: true,
            fail_after: None,
            steps: 0,
        };
        // T = 1, h = 0.1: 10 steps; stride 3 gives rows at steps 0, 3, 6, 9, 10.
        let s = run_simulation(&mut sim, &scene(1.0, 0.1, 3), &out, false).unwrap();
        assert_eq!((s.steps, s.rows), (10, 5));
        let text = std::fs::read_to_string(&out).unwrap();
        let mut lines = text.lines();
        assert_eq!(
            lines.next().unwrap(),
            "t,mu1,mu2,mu3,g11,g12,g13,g21,g22,g23,g31,g32,g33,energy,casimir,\
             qw,qx,qy,qz,rv1,rv2,rv3"
        );
        let last: Vec<f64> = text
            .lines()
            .last()
            .unwrap()
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        assert_eq!(last.len(), 22);
        // The last step lands on T to rounding of ten additions of 0.1.
        assert!((last[0] - 1.0).abs() < 1e-14);
        // R = exp(t ω ê₃): q = (cos ωt/2, 0, 0, sin ωt/2), φ = (0, 0, ωt).
        let t = last[0];
        let want = [(t / 2.0).cos(), 0.0, 0.0, (t / 2.0).sin(), 0.0, 0.0, t];
        for (got, want) in last[15..].iter().zip(want) {
            assert!((got - want).abs() < 1e-15, "{:?}", &last[15..]);
        }
        assert_eq!(text.lines().count(), 6);
    }

    #[test]
    fn failing_step_reports_the_step_and_leaves_no_file() {
        let out = tmp("fail.csv");
        let mut sim = Spin {
            t: 0.0,
            omega: 1.0,
            reconstruct: false,
            fail_after: Some(4),
            steps: 0,
        };
        let err = run_simulation(&mut sim, &scene(1.0, 0.1, 1), &out, false).unwrap_err();
        assert!(err.to_string().starts_with("step 4 at t = 0.4"), "{err}");
        assert!(!out.exists());
    }

    /// A scene with a tolerance: the run takes the steps of the library's driver, lands on T
    /// exactly, reports its accepted and rejected steps and their range, writes the rows at the
    /// requested times by partial steps — and each row is the library's own run
    /// (`Adaptive::solve` on the same pair, bit for bit).
    #[test]
    fn a_tolerance_driven_run_lands_on_t_and_reports_its_steps() {
        use integrators::adaptive::{Adaptive, RkmkDop853, Tolerance};
        use lie_groups::{LieGroup, So3};
        use mechanics::RigidBody;
        use nalgebra::Vector3;
        let text = "[system]\nkind = \"free-rigid-body\"\ninertia = [1.0, 2.0, 3.0]\n\
                    [initial]\nmomentum = [0.3, 2.0, 0.1]\n\
                    [integrator]\nmethod = \"rkmk-dop853\"\ntolerance = 1e-9\nduration = 7.3\n\
                    [output]\ntimes = [0.0, 1.25, 7.3]\n";
        let scene = Scene::parse(text, "s", "s", Overrides::default()).unwrap();
        let out = tmp("adaptive.csv");
        let s = run_scene(&scene, &out, false, false).unwrap();
        let stats = s.stats.expect("a tolerance-driven run reports its steps");
        assert_eq!(stats.accepted as u64, s.steps);
        assert!(
            stats.accepted > 3 && stats.min_step < stats.max_step,
            "{stats:?}"
        );
        let text = std::fs::read_to_string(&out).unwrap();
        let rows: Vec<Vec<f64>> = text
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[2][0], 7.3, "the last row is at T exactly");

        let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
        let pi0 = Vector3::new(0.3, 2.0, 0.1);
        let method = RkmkDop853::new(body, pi0, Some(So3::identity())).unwrap();
        let mut run = Adaptive::new(method, Tolerance::uniform(1e-9).unwrap());
        let mut samples = Vec::new();
        run.solve(
            7.3,
            &[0.0, 1.25, 7.3],
            |t, pi, _| samples.push((t, *pi)),
            &[],
        )
        .unwrap();
        assert_eq!(run.stats(), &stats);
        for (row, (t, pi)) in rows.iter().zip(&samples) {
            assert_eq!(row[0], *t);
            assert_eq!(&row[1..4], pi.as_slice(), "at t = {t}");
        }
    }

    /// The meter's work is the trapezoid rule: exact for a power linear in t over each step
    /// (P = 2t: W = t², whatever the steps), and the balance error is what E − E₀ − W leaves,
    /// relative to the largest |E|.
    #[test]
    fn the_work_meter_integrates_the_power_by_the_trapezoid_rule() {
        let mut m = WorkMeter::new(0.0, 1.0, 0.0);
        for t in [0.1, 0.35, 0.5, 1.0] {
            // E = 1 + t² + 0.01 t: the forces' work plus a drift of 0.01 t.
            let w = m.step(t, 1.0 + t * t + 0.01 * t, 2.0 * t);
            assert!((w - t * t).abs() < 1e-15, "W({t}) = {w}");
        }
        assert!((m.work_at(1.5, 3.0) - 2.25).abs() < 1e-15);
        let r = m.result();
        assert!((r.work - 1.0).abs() < 1e-15);
        assert!((r.max_balance_error - 0.01 / 2.01).abs() < 1e-15, "{r:?}");
    }

    /// A scene refused for its tolerance leaves no output file.
    #[test]
    fn a_bad_tolerance_is_refused_before_anything_is_written() {
        let text = "[system]\nkind = \"free-rigid-body\"\ninertia = [1.0, 2.0, 3.0]\n\
                    [initial]\nmomentum = [0.3, 2.0, 0.1]\n\
                    [integrator]\nmethod = \"dop853\"\ntolerance = 1e-17\nduration = 1.0\n";
        let e = Scene::parse(text, "s", "s", Overrides::default())
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("integrator.tolerance") && e.contains("1e-17"),
            "{e}"
        );
    }

    /// The geodesic scene on SO(n) with Lie–Poisson (τ = Cayley, θ = ½, simplified Newton) at
    /// h = 0.01 for `steps` steps (also the trade's test scene).
    pub(crate) fn so_n(n: usize, steps: u64) -> crate::scene::Scene {
        let d = n * (n - 1) / 2;
        let inertia: Vec<String> = (0..n)
            .map(|i| format!("{}", 1.0 + 0.1 * i as f64))
            .collect();
        let momentum: Vec<String> = (0..d)
            .map(|i| format!("{}", 0.1 / (1 + i) as f64))
            .collect();
        let text = format!(
            "[system]\nkind = \"geodesic-so-n\"\nn = {n}\ninertia = [{}]\n\
             [initial]\nmomentum = [{}]\n\
             [integrator]\nmethod = \"lie-poisson\"\ntau = \"cayley\"\ntheta = 0.5\n\
             step = 0.01\nduration = {}\n",
            inertia.join(", "),
            momentum.join(", "),
            steps as f64 * 0.01
        );
        crate::scene::Scene::parse(&text, "so(n)", "so-n", Default::default()).unwrap()
    }

    /// `run` on SO(4) and SO(50) counts each step at its measured cost ([`crate::bounds::stage_cost`]'s table):
    /// beyond the limit it refuses, naming that cost, before it writes anything; within it the
    /// run goes ahead. With the previous model (no floor for dynamically sized groups, SO(4)'s
    /// step counted as 1 and SO(50)'s as 6·10⁵ where they cost 229 and ~9·10³) 10⁷ steps on
    /// SO(4) were accepted and 10⁴ on SO(50) refused: both checks below fail (checked).
    #[test]
    fn so_n_runs_beyond_the_limit_are_refused_naming_their_cost_and_within_it_accepted() {
        let dir = std::env::temp_dir().join(format!("lie-sim-bounds-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for (n, refused, accepted) in [(4usize, 10_000_000u64, 1000u64), (50, 1_000_000, 10_000)] {
            let big = so_n(n, refused);
            let cost = big.step_cost(false).unwrap();
            assert!(cost > 100, "SO({n}): {cost}");
            let out = dir.join(format!("so{n}.csv"));
            let e = run_scene(&big, &out, false, false).unwrap_err().to_string();
            assert!(e.contains(&format!("× {cost} ")), "SO({n}): {e}");
            assert!(
                !out.exists(),
                "SO({n}): a refused run wrote {}",
                out.display()
            );
            // Within the limit: the estimate passes (a run of 10⁴ steps on SO(50) takes tens of
            // seconds; it is run to the end on a few steps below).
            let fine = so_n(n, accepted);
            let estimate = crate::bounds::Estimate {
                steps: u128::from(accepted),
                bytes: 0,
                step_cost: fine.step_cost(false).unwrap(),
            };
            assert!(
                estimate.check("run", false).is_ok(),
                "SO({n}): {estimate:?}"
            );
            let summary = run_scene(&so_n(n, 3), &out, false, false).map(|_| ());
            assert!(summary.is_ok(), "SO({n}): {summary:?}");
        }
        std::fs::remove_dir_all(&dir).ok();
    }
}
