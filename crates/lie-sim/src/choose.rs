//! `lie-sim choose`: the cheapest method and step that meets an accuracy target on the user's own
//! scene, measured, not guessed.
//!
//! It runs the candidates of [`crate::methods::candidates`] breadth first over a ladder of steps
//! h₀, h₀/r, …, h₀/r^{L−1} (r = 2 unless `--ratio` says otherwise; the exact flow also in one step
//! to T): every method at the coarsest step, then every method at the next, so that a budget cut
//! stops at an equally explored ladder, not in the middle of one slow method's fine steps. A
//! method that met the target is not run at finer steps (they only cost more); one that failed is
//! not run again. The measure is
//!
//! - `error`: the error at T against the reference of [`crate::reference`] (the exact flow on
//!   free-body scenes, elsewhere Gragg–Bulirsch–Stoer refined to `--reference-tolerance`, or the
//!   user's `--reference`); a run meets the target when its error bound is within it — its error
//!   plus the reference's estimated error (the floor), or twice the floor for an error below the
//!   floor, which the reference cannot resolve ([`crate::reference::meets`]) — and a target below
//!   twice the floor is refused, since no run could be shown to meet it; or
//! - `energy`: the maximum relative energy error over the run (no reference needed),
//!
//! and the cost the stepping time of the whole run.
//!
//! The tolerance-driven methods (the embedded pairs, `crate::trade::tolerance_driven`) run in the
//! same breadth-first order over a ladder of tolerances instead of steps: 10 × target at the
//! first level, then a tenth of it at each level (a pair's error at T is usually within a decade
//! or two of its tolerance, on either side), down to the smallest `rtol` f64 allows. Their
//! answer is a tolerance, written to the scene as `tolerance = …` in place of `step`. The choice is the cheapest run meeting the
//! target, the runner-up the cheapest run of another method; both are reported with their cost
//! and measured error. When nothing meets the target within the budget, it says so, with the best
//! value reached.

use crate::build::{build, build_with, epsilon_scale};
use crate::error::SimError;
use crate::invariants::relative_error;
use crate::measure::{timed_adaptive_run, timed_run};
use crate::methods::{candidates, MethodSpec};
use crate::reference::{meets, reference, Options as ReferenceOptions};
use crate::scene::{steps_for, Scene};
use crate::stepping::VariableSteps;
use crate::trade::tolerance_driven;
use integrators::adaptive::Tolerance;
use std::time::{Duration, Instant};

/// What is measured against the target.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Metric {
    /// The error at T against the reference.
    Error,
    /// The maximum relative energy error over the run.
    Energy,
}

/// One measured run.
#[derive(Debug, Clone)]
pub struct Candidate {
    /// The method.
    pub method: MethodSpec,
    /// Its step (the duration T for a run with variable steps).
    pub h: f64,
    /// How a run with variable steps chose them (a tolerance, rtol = atol, or reversible steps
    /// with ε), `None` for fixed steps.
    pub variable: Option<VariableSteps>,
    /// Stepping time of the whole run.
    pub seconds: f64,
    /// The measured value of the metric.
    pub value: f64,
}

impl Candidate {
    /// `h = 0.01`, `tolerance = 1e-8` for a tolerance-driven run, `epsilon = 0.05` for
    /// reversible steps.
    pub fn setting(&self) -> String {
        match self.variable {
            Some(VariableSteps::Tolerance(t)) => format!("tolerance = {:e}", t.rtol),
            Some(VariableSteps::Reversible(e)) => format!("epsilon = {e}"),
            None => format!("h = {}", self.h),
        }
    }
}

/// The tolerance a tolerance-driven method runs at on `level` (≥ 1) of the search for `target`:
/// 10 × target at the first, a tenth of it at each next; `None` below what f64 delivers.
fn tolerance_at(level: usize, target: f64) -> Option<f64> {
    let t = target * 10f64.powi(2 - level as i32);
    (t >= Tolerance::MIN_RTOL).then_some(t)
}

/// The outcome of [`choose`].
#[derive(Debug, Clone)]
pub struct Choice {
    /// The cheapest run meeting the target, if any.
    pub best: Option<Candidate>,
    /// The cheapest run of another method meeting the target.
    pub runner_up: Option<Candidate>,
    /// The run with the smallest value of the metric (what was reached).
    pub most_accurate: Option<Candidate>,
    /// Runs measured.
    pub runs: usize,
    /// Whether the budget stopped the search before the ladder was explored.
    pub truncated: bool,
    /// How the reference was made (error metric only).
    pub reference: Option<String>,
    /// The reference's estimated error (error metric only): values below it are unresolved.
    pub floor: Option<f64>,
    /// The reference's one-line shortfall, when its tolerance was not met.
    pub shortfall: Option<String>,
}

/// Runs the bounded search (see the module page) over `levels` steps `ratio` apart. Errors: a
/// target that is not finite and positive, a target (error metric) below the reference's
/// estimated error, and whatever stops the reference.
pub fn choose(
    scene: &Scene,
    target: f64,
    metric: Metric,
    levels: usize,
    ratio: f64,
    budget: Duration,
    reference_options: &ReferenceOptions,
) -> Result<Choice, SimError> {
    if !(target.is_finite() && target > 0.0) {
        return Err(SimError::Invalid {
            path: scene.source.clone(),
            field: "--target".into(),
            message: format!("must be finite and positive, got {target}"),
        });
    }
    let ladder: Vec<f64> = (0..levels)
        .map(|k| scene.step / ratio.powi(k as i32))
        .collect();
    let reference = match metric {
        Metric::Error => Some(reference(scene, reference_options)?),
        Metric::Energy => None,
    };
    let floor = reference.as_ref().map(|r| r.estimated_error);
    if let Some(floor) = floor.filter(|&f| f.is_nan() || 2.0 * f > target) {
        return Err(SimError::Choose {
            message: format!(
                "the target {target:e} is below twice the reference's estimated error \
                 {floor:.1e}: no resolved error plus that estimate is within it (loosen --target, \
                 or tighten the reference with --reference-tolerance / --reference-budget)"
            ),
        });
    }
    // The search's budget starts after the reference (which has its own).
    let deadline = Instant::now() + budget;
    let met = |value: f64| match floor {
        Some(f) => meets(value, f, target),
        None => value <= target,
    };
    let methods = candidates();
    // Reversible steps run with ε = h s at the level of step h (`epsilon_scale`): they start
    // with that step where ρ(y₀) sets s.
    let scale = epsilon_scale(&scene.system, scene.reconstruct)?;
    let mut done = vec![false; methods.len()];
    let mut rows: Vec<Candidate> = Vec::new();
    let mut truncated = false;
    // The exact flow's one step to T comes first: it costs one step.
    let steps = std::iter::once(scene.duration).chain(ladder.iter().copied());
    'ladder: for (level, h) in steps.enumerate() {
        for (k, m) in methods.iter().enumerate() {
            if done[k] || (level == 0 && !m.method.row().trade.one_step) {
                continue;
            }
            if Instant::now() > deadline {
                truncated = true;
                break 'ladder;
            }
            let variable = if tolerance_driven(m) {
                let Some(t) = tolerance_at(level, target).and_then(|t| Tolerance::uniform(t).ok())
                else {
                    done[k] = true;
                    continue;
                };
                Some(VariableSteps::Tolerance(t))
            } else if m.reversible {
                Some(VariableSteps::Reversible(h * scale))
            } else {
                None
            };
            let adaptive = variable.is_some();
            let built = build_with(&scene.system, m, scene.reconstruct, &scene.solver, variable);
            let mut sim = match built {
                Ok(s) => s,
                Err(_) => {
                    done[k] = true; // not available or not applicable to this system
                    continue;
                }
            };
            let run = if adaptive {
                timed_adaptive_run(sim.as_mut(), scene.duration)
            } else {
                timed_run(sim.as_mut(), scene.duration, h)
            };
            let Ok(run) = run else {
                done[k] = true; // a failed step: finer steps of a failing method are not tried
                continue;
            };
            let value = match &reference {
                Some(r) => run.state.error(&r.state),
                None => run.max_energy_error,
            };
            if !value.is_finite() {
                done[k] = true;
                continue;
            }
            // Met, or unresolved (finer steps of this method stay below the floor).
            done[k] = met(value) || floor.is_some_and(|f| value < f);
            rows.push(Candidate {
                method: m.clone(),
                h: if adaptive { scene.duration } else { h },
                variable,
                seconds: run.stepping.as_secs_f64(),
                value,
            });
        }
    }
    if metric == Metric::Energy {
        // The trade samples the energy every few steps; a chosen run must meet the target at
        // every step, so the runs that met it are checked step by step (one run each, cheapest
        // first) and dropped if a sample between the trade's missed a peak.
        rows.sort_by(|a, b| a.seconds.total_cmp(&b.seconds));
        for r in rows.iter_mut().filter(|r| met(r.value)) {
            r.value = energy_error_every_step(scene, &r.method, r.h, r.variable)?;
        }
    }
    let cheapest = |exclude: Option<&MethodSpec>| {
        rows.iter()
            .filter(|r| met(r.value) && Some(&r.method) != exclude)
            .min_by(|a, b| a.seconds.total_cmp(&b.seconds))
            .cloned()
    };
    let best = cheapest(None);
    let runner_up = best.as_ref().and_then(|b| cheapest(Some(&b.method)));
    let most_accurate = rows
        .iter()
        .min_by(|a, b| a.value.total_cmp(&b.value))
        .cloned();
    Ok(Choice {
        best,
        runner_up,
        most_accurate,
        runs: rows.len(),
        truncated,
        shortfall: reference.as_ref().and_then(|r| r.shortfall.clone()),
        reference: reference.map(|r| {
            format!(
                "{} (estimated error {:.1e})",
                r.description, r.estimated_error
            )
        }),
        floor,
    })
}

/// max_k |E_k − E₀|/|E₀| over every step of the scene run with `method` at step h, or with
/// the `variable` steps (∞ if a step fails).
fn energy_error_every_step(
    scene: &Scene,
    method: &MethodSpec,
    h: f64,
    variable: Option<VariableSteps>,
) -> Result<f64, SimError> {
    let Some(variable) = variable else {
        let mut sim = build(&scene.system, method, scene.reconstruct, &scene.solver)?;
        let n = steps_for(scene.duration, h);
        let h_last = scene.duration - (n - 1) as f64 * h;
        let e0 = sim.energy();
        let mut worst = 0.0f64;
        for k in 0..n {
            if sim.step(if k + 1 == n { h_last } else { h }).is_err() {
                return Ok(f64::INFINITY);
            }
            worst = worst.max(relative_error(sim.energy(), e0));
        }
        return Ok(worst);
    };
    let mut sim = build_with(
        &scene.system,
        method,
        scene.reconstruct,
        &scene.solver,
        Some(variable),
    )?;
    let e0 = sim.energy();
    let mut worst = 0.0f64;
    while sim.time() != scene.duration {
        if sim.step_towards(scene.duration).is_err() {
            return Ok(f64::INFINITY);
        }
        worst = worst.max(relative_error(sim.energy(), e0));
    }
    Ok(worst)
}

/// The scene text with its `[integrator]` set to the chosen method, step and the duration the
/// choice was measured over (the other keys of the table kept: reconstruct, solver options).
pub fn scene_with(text: &str, chosen: &Candidate, duration: f64) -> Result<String, SimError> {
    let mut doc: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| SimError::Choose {
            message: format!("cannot re-read the scene to write it: {e}"),
        })?;
    let it = doc
        .entry("integrator")
        .or_insert_with(|| toml::Value::Table(toml::Table::new()));
    let Some(it) = it.as_table_mut() else {
        return Err(SimError::Choose {
            message: "the scene's [integrator] is not a table".into(),
        });
    };
    for key in [
        "method",
        "tau",
        "theta",
        "composition",
        "splitting",
        "processing",
        "modified",
        "order",
        "step",
        "tolerance",
        "rtol",
        "atol",
        "epsilon",
        "duration",
    ] {
        it.remove(key);
    }
    let m = &chosen.method;
    it.insert("method".into(), m.method.name().into());
    if let Some(t) = m.tau {
        it.insert("tau".into(), t.name().into());
    }
    if let Some(th) = m.theta {
        it.insert("theta".into(), th.into());
    }
    if let Some(c) = &m.composition {
        it.insert("composition".into(), c.name().into());
    }
    if let Some(s) = &m.splitting {
        it.insert("splitting".into(), s.name().into());
    }
    if let Some(p) = &m.processing {
        it.insert("processing".into(), p.name().into());
    }
    if let Some(order) = m.modified {
        it.insert("modified".into(), true.into());
        it.insert("order".into(), i64::from(order).into());
    }
    match chosen.variable {
        Some(VariableSteps::Tolerance(t)) => it.insert("tolerance".into(), t.rtol.into()),
        Some(VariableSteps::Reversible(e)) => it.insert("epsilon".into(), e.into()),
        None => it.insert("step".into(), chosen.h.into()),
    };
    it.insert("duration".into(), duration.into());
    Ok(format!(
        "# Chosen by `lie-sim choose`: {m} at {}.\n{}",
        chosen.setting(),
        toml::to_string(&doc).map_err(|e| SimError::Choose {
            message: format!("cannot write the chosen scene: {e}"),
        })?
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::MethodId;
    use crate::scene::{Overrides, DEFAULT_SCENE};

    /// A tolerance-driven choice is written as `tolerance` in place of `step` (and a fixed-step
    /// one as `step`), and the written scene reads back as that method at that tolerance.
    #[test]
    fn a_tolerance_is_written_in_place_of_the_step() {
        let chosen = Candidate {
            method: MethodSpec::plain(MethodId::Dop853),
            h: 10.0,
            variable: Some(VariableSteps::Tolerance(Tolerance::uniform(1e-9).unwrap())),
            seconds: 1.0,
            value: 1e-9,
        };
        let text = scene_with(DEFAULT_SCENE, &chosen, 10.0).unwrap();
        let scene = Scene::parse(&text, "w", "w", Overrides::default()).unwrap();
        assert_eq!(scene.method.method, MethodId::Dop853);
        assert_eq!(
            scene.variable,
            Some(VariableSteps::Tolerance(Tolerance::uniform(1e-9).unwrap()))
        );
        assert!(!text.contains("step ="), "{text}");
        let fixed = Candidate {
            method: MethodSpec::plain(MethodId::Rk4),
            variable: None,
            h: 0.05,
            ..chosen
        };
        let scene = Scene::parse(
            &scene_with(DEFAULT_SCENE, &fixed, 10.0).unwrap(),
            "w",
            "w",
            Overrides::default(),
        )
        .unwrap();
        assert_eq!((scene.variable, scene.step), (None, 0.05));
    }
}
