//! One measured run, as `trade`, `choose` and the reference make them: a simulation advanced to T
//! with its stepping timed, the invariants of [`crate::invariants`] sampled between the timed
//! intervals, and its state at T ([`FinalState`]) with the error measure between two such states.
//!
//! Error at T: `max(‖μ − μ_ref‖_∞ / ‖μ_ref‖_∞, ‖g − g_ref‖_∞ / max(1, ‖g_ref‖_∞))`, the group term
//! only where both runs reconstruct g. Timing covers the steps and the read of the state at T
//! (for a processed method that read applies its processor P, part of the run's cost): the
//! invariants are sampled every [`ENERGY_SAMPLE`] steps outside the timed intervals, so that the
//! time measures the integrator, not the bookkeeping.
//!
//! On a machine busy with other work the scheduler takes the core away for whole time slices
//! (milliseconds), and a wall clock charges each slice to the interval it fell in: every run
//! longer than a slice would look several times slower per step than the short ones. Such an
//! interval stands out, as a chunk of [`ENERGY_SAMPLE`] steps lasts microseconds: intervals more
//! than [`INTERRUPTED`] times the run's median are counted at the mean of the others. The
//! thread's CPU clock would say the same directly, but reading it is a system call, as slow as
//! several steps. On an idle machine no interval stands out and the figure is the plain sum.

use crate::error::SimError;
use crate::invariants::Monitor;
use crate::scene::steps_for;
use crate::sim::Simulation;
use std::time::{Duration, Instant};

/// Steps between two energy samples (and two clock reads) in a timed run.
pub const ENERGY_SAMPLE: u64 = 8;

/// An interval of steps longer than this many times the run's median interval was interrupted
/// (the thread was off the CPU during it): a time slice of another process, not the steps' cost.
/// Far above what the steps vary by (rejected attempts, Newton iterations, the shortened last
/// chunk), far below a time slice's length over a chunk's.
pub const INTERRUPTED: f64 = 32.0;

/// The durations of a run's timed intervals in octaves (bin b holds [2ᵇ, 2ᵇ⁺¹) ns): their count
/// and sum per octave, in constant memory whatever the run's length.
#[derive(Debug, Clone)]
struct Intervals {
    count: [u64; 64],
    sum: [f64; 64],
}

impl Intervals {
    fn new() -> Self {
        Self {
            count: [0; 64],
            sum: [0.0; 64],
        }
    }

    fn add(&mut self, d: Duration) {
        let ns = d.as_nanos().max(1) as f64;
        let bin = (ns.log2() as usize).min(63);
        self.count[bin] += 1;
        self.sum[bin] += ns;
    }

    /// The intervals' total, those in octaves above the median's by more than [`INTERRUPTED`]
    /// counted at the mean of the others.
    fn total(&self) -> Duration {
        let n: u64 = self.count.iter().sum();
        if n == 0 {
            return Duration::ZERO;
        }
        let mut seen = 0;
        let median = (0..64)
            .find(|&b| {
                seen += self.count[b];
                2 * seen >= n
            })
            .unwrap_or(63);
        // bins from `median + 1 + log2(INTERRUPTED)` start at INTERRUPTED times the median's top
        let first_out = median + 1 + INTERRUPTED.log2() as usize;
        let (mut kept, mut kept_n, mut out_n) = (0.0, 0u64, 0u64);
        for b in 0..64 {
            if b < first_out {
                kept += self.sum[b];
                kept_n += self.count[b];
            } else {
                out_n += self.count[b];
            }
        }
        let ns = kept + out_n as f64 * kept / kept_n as f64;
        Duration::from_nanos(ns.round() as u64)
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
    /// Steps taken (accepted, for a tolerance-driven run).
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

/// Runs `sim` to `duration` with step `h` (the last step shortened to land on T), sampling the
/// invariants of [`crate::invariants`] every [`ENERGY_SAMPLE`] steps and at T, outside the timed
/// intervals.
pub fn timed_run(sim: &mut dyn Simulation, duration: f64, h: f64) -> Result<Timed, SimError> {
    timed(sim, duration, Some(h))
}

/// Runs a `sim` with variable steps ([`crate::driven::DrivenSim`]) to `duration` with the steps its
/// controller accepts, the last landing on T, sampling as [`timed_run`] does.
pub fn timed_adaptive_run(sim: &mut dyn Simulation, duration: f64) -> Result<Timed, SimError> {
    timed(sim, duration, None)
}

/// [`timed_run`] with the step `h`, or [`timed_adaptive_run`] without.
fn timed(sim: &mut dyn Simulation, duration: f64, h: Option<f64>) -> Result<Timed, SimError> {
    let n = h.map_or(u64::MAX, |h| steps_for(duration, h));
    let h_last = h.map_or(0.0, |h| duration - (n - 1) as f64 * h);
    let done = |sim: &dyn Simulation, k: u64| match h {
        Some(_) => k == n,
        None => sim.time() == duration,
    };
    let mut monitor = Monitor::new(sim);
    let mut intervals = Intervals::new();
    let mut k = 0u64;
    let mut state = None;
    while !done(sim, k) {
        let chunk_end = (k + ENERGY_SAMPLE).min(n);
        let start = Instant::now();
        while k < chunk_end && !done(sim, k) {
            let stepped = match h {
                Some(h) => sim.step(if k + 1 == n { h_last } else { h }),
                None => sim.step_towards(duration),
            };
            if let Err(message) = stepped {
                return Err(SimError::Step {
                    step: k,
                    time: sim.time(),
                    message,
                });
            }
            k += 1;
        }
        if done(sim, k) {
            // The state at T is part of the run's cost: for a processed method, the processor.
            state = Some(FinalState::of(sim));
        }
        intervals.add(start.elapsed());
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
        steps: k,
        stepping: intervals.total(),
        max_energy_error: monitor.energy,
        max_casimir_error: monitor.casimir,
        max_momentum_map_error: monitor.momentum_map,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build::build_with;
    use crate::scene::{Overrides, Scene};
    use crate::stepping::VariableSteps;
    use integrators::adaptive::Tolerance;

    /// The runs `trade` and `choose` time end exactly at T, whatever the steps: fixed steps with
    /// T/h an integer (1.0 / 0.1, 50 / 0.01: `t += h` would end at 0.9999999999999999 and
    /// 49.99999999999862) and not (0.7 / 0.3, the last step shortened), a tolerance-driven pair,
    /// and reversible steps. On the heavy top, so that g matters.
    #[test]
    fn timed_runs_end_exactly_at_t() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/scenes/heavy-top.toml"
        ))
        .unwrap();
        let scene = Scene::parse(&text, "top", "top", Overrides::default()).unwrap();
        let splitting = crate::methods::MethodSpec::plain(crate::methods::MethodId::Splitting);
        let rkmk = crate::methods::MethodSpec::plain(crate::methods::MethodId::RkmkDop853);
        for (duration, h) in [(1.0, 0.1), (50.0, 0.01), (0.7, 0.3)] {
            let mut sim = build_with(&scene.system, &splitting, true, &scene.solver, None).unwrap();
            let t = timed_run(sim.as_mut(), duration, h).unwrap();
            assert_eq!(sim.time(), duration, "h = {h}");
            assert_eq!(t.steps, steps_for(duration, h));
        }
        let variable = [
            (
                &rkmk,
                VariableSteps::Tolerance(Tolerance::uniform(1e-8).unwrap()),
            ),
            (&splitting, VariableSteps::Reversible(0.05)),
        ];
        for (m, v) in variable {
            for duration in [1.0, 7.3] {
                let mut sim = build_with(&scene.system, m, true, &scene.solver, Some(v)).unwrap();
                timed_adaptive_run(sim.as_mut(), duration).unwrap();
                assert_eq!(sim.time(), duration, "{m} {v:?}");
            }
        }
    }

    /// Intervals a time slice long among microsecond ones are counted at the others' mean; with
    /// none, or intervals that merely vary, the total is the plain sum.
    #[test]
    fn interrupted_intervals_count_at_the_mean_of_the_others() {
        let us = |x: u64| Duration::from_nanos(x * 1000);
        let mut i = Intervals::new();
        for k in 0..1000 {
            i.add(us(2 + k % 3));
        }
        let plain = i.total();
        assert_eq!(plain, us(2999));
        i.add(Duration::from_millis(4));
        i.add(Duration::from_millis(9));
        let mean = 2999.0 / 1000.0;
        assert!((i.total().as_secs_f64() * 1e6 - mean * 1002.0).abs() < 1e-3);
        // a spread of 13× (a chunk with rejected attempts, the shortened last one) is kept
        let mut j = Intervals::new();
        for k in 0..100 {
            j.add(us(if k % 10 == 0 { 40 } else { 3 }));
        }
        assert_eq!(j.total(), us(10 * 40 + 90 * 3));
        assert_eq!(Intervals::new().total(), Duration::ZERO);
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
