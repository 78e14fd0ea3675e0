//! The steps a trade runs: chosen from the scene's time scale, or given with `--steps`.
//!
//! **Automatic ladder.** A characteristic rate ω of the scene at its initial state, the model's
//! own (`integrators::System::characteristic_rate`, through [`crate::build::characteristic_rate`]):
//! the largest of the initial body angular velocity |ξ₀| (|Ω₀| = |𝕀⁻¹Π₀| for the rigid body), the
//! frequencies of the potential (the heavy top's pendulum, the satellite's orbit, the planar
//! body's spring, the vehicle's righting moment, the springs between bodies) and of the forces
//! (a schedule's shortest ramp, a torque's spin-up, damping). The ladder starts at h₀ = 1/ω (h₀ω = 1, near the stability edge of the explicit
//! methods and where every method's error is of order one; h₀ ≤ T) and divides it by the ratio r
//! (`--ratio`, [`DEFAULT_RATIO`] = 2: it halves) down to the step where the highest-order candidate
//! (order [`HIGHEST_ORDER`]) is predicted to reach the reference floor over the horizon,
//! `(hω)^p · max(1, ωT) = `[`REFERENCE_FLOOR`] — finer steps only measure the lower-order methods
//! at a higher cost — with at least 2 levels and at most the span of [`MAX_AUTO_LEVELS`] halvings'
//! levels ([`max_levels`]; `--levels` fixes the count instead; without it, the finest levels are
//! dropped, down to two, when the trade would exceed the work limits of [`crate::bounds`]). A scene
//! at rest (ω = 0) has no time scale of its own: its ladder starts at the scene's step h instead.
//!
//! **The ratio.** The cheapest run that reaches a target is a ladder point: between two points a
//! method's error falls by r^p, so the run picked may be up to r^p more accurate, and r times
//! dearer, than the target needs, and which method that penalises most depends on where its points
//! fall. A ratio of √2 (`--ratio 1.41`) halves that granularity (in log h) for about twice the
//! runs.
//!
//! **Explicit ladder.** `--steps 0.1,0.05,0.02`: exactly these steps, in this order; each finite,
//! positive and at most T.

use crate::build::characteristic_rate;
use crate::error::SimError;
use crate::scene::Scene;

/// The error level the automatic ladder aims its finest step at: the free-body reference (the
/// exact flow) is good to ~1e-14, a refined reference to its tolerance, ~1e-13.
pub const REFERENCE_FLOOR: f64 = 1e-13;

/// The highest order among the trade's candidates (Kahan–Li's order-8 composition).
pub const HIGHEST_ORDER: i32 = 8;

/// The most levels the automatic ladder takes at the default ratio 2 (nine halvings).
pub const MAX_AUTO_LEVELS: usize = 10;

/// The ratio of successive steps of the automatic ladder unless `--ratio` says otherwise.
pub const DEFAULT_RATIO: f64 = 2.0;

/// The range `--ratio` accepts: finer than 1.1 multiplies the runs for no new information, coarser
/// than 16 leaves an order-4 method 16⁴ apart between points.
pub const RATIO_RANGE: std::ops::RangeInclusive<f64> = 1.1..=16.0;

/// The most levels of the automatic ladder with ratio r: those spanning the same range as
/// [`MAX_AUTO_LEVELS`] levels of ratio 2, `1 + ⌈9 ln 2 / ln r⌉` (10 at r = 2, 19 at r = √2).
pub fn max_levels(ratio: f64) -> usize {
    let span = (MAX_AUTO_LEVELS - 1) as f64 * std::f64::consts::LN_2;
    // Less 1e-9 so that the rounding of the quotient cannot add a level (r = 2: exactly nine).
    1 + (span / ratio.ln() - 1e-9).ceil().max(1.0) as usize
}

/// The value of `--steps`, parsed by [`parse_steps`].
#[derive(Debug, Clone, PartialEq)]
pub struct StepList(pub Vec<f64>);

/// The steps of a trade and the rule that chose them.
#[derive(Debug, Clone, PartialEq)]
pub struct Ladder {
    /// The steps, coarsest first for the automatic ladder, as given for `--steps`.
    pub steps: Vec<f64>,
    /// One line saying how they were chosen.
    pub rule: String,
    /// Whether the rule alone chose them (no `--steps`, no `--levels`), so that the finest may be
    /// dropped to stay within the work limits.
    pub may_trim: bool,
}

/// The automatic ladder of the module page for `scene`, successive steps `ratio` apart; `levels`
/// replaces the computed count.
pub fn automatic(scene: &Scene, levels: Option<usize>, ratio: f64) -> Result<Ladder, SimError> {
    let omega = characteristic_rate(&scene.system, scene.reconstruct)?;
    Ok(automatic_for(
        omega,
        scene.duration,
        scene.step,
        levels,
        ratio,
    ))
}

/// The ladder for rate ω over horizon T (`step`: the scene's, used when ω = 0), successive
/// steps `ratio` apart (in [`RATIO_RANGE`]).
pub fn automatic_for(
    omega: f64,
    duration: f64,
    step: f64,
    levels: Option<usize>,
    ratio: f64,
) -> Ladder {
    let resting = !(omega.is_finite() && omega > 0.0);
    let top = if resting { step } else { 1.0 / omega }.min(duration);
    let most = max_levels(ratio);
    let count = levels.unwrap_or_else(|| {
        if resting {
            return 2;
        }
        // (hω)^p max(1, ωT) = floor at h_floor; levels cover h₀ … ≤ h_floor.
        let h_floor = (REFERENCE_FLOOR / (omega * duration).max(1.0))
            .powf(1.0 / f64::from(HIGHEST_ORDER))
            / omega;
        let divisions = ((top / h_floor).log2() / ratio.log2()).ceil().max(0.0) as usize;
        (divisions + 1).clamp(2, most)
    });
    let steps: Vec<f64> = (0..count).map(|k| top / ratio.powi(k as i32)).collect();
    let divided = if ratio == 2.0 {
        "halved".to_string()
    } else {
        format!("divided by {ratio}")
    };
    let rule = if resting {
        format!(
            "the scene is at rest (ω = 0): h = {step:e} … h/{ratio}^{} from its step",
            count - 1
        )
    } else {
        format!(
            "ω = {omega:.4e} rad/s: h = {:.4e} (hω = {:.2}) {divided} {} times{}",
            top,
            top * omega,
            count - 1,
            if levels.is_some() {
                " (--levels)".to_string()
            } else {
                format!(
                    " (down to the highest order at the reference floor, at most {most} levels)"
                )
            }
        )
    };
    Ladder {
        steps,
        rule,
        may_trim: levels.is_none(),
    }
}

/// Parses `--steps`: a comma-separated list of finite positive steps (T is checked by
/// [`explicit`]).
pub fn parse_steps(text: &str) -> Result<Vec<f64>, String> {
    let items: Vec<&str> = text.split(',').map(str::trim).collect();
    if items.iter().all(|s| s.is_empty()) {
        return Err("the step list is empty (e.g. --steps 0.1,0.05,0.02)".into());
    }
    items
        .iter()
        .map(|s| {
            let h: f64 = s
                .parse()
                .map_err(|_| format!("{s:?} is not a number (e.g. --steps 0.1,0.05,0.02)"))?;
            if h.is_finite() && h > 0.0 {
                Ok(h)
            } else {
                Err(format!("every step must be finite and positive, got {s}"))
            }
        })
        .collect()
}

/// The explicit ladder `steps`, each at most T.
pub fn explicit(steps: Vec<f64>, duration: f64) -> Result<Ladder, SimError> {
    if let Some(h) = steps.iter().find(|&&h| h > duration) {
        return Err(SimError::Usage {
            flag: "--steps".into(),
            message: format!("the step {h} is longer than the horizon T = {duration}"),
        });
    }
    Ok(Ladder {
        rule: format!("--steps ({} steps)", steps.len()),
        steps,
        may_trim: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ladder_starts_at_h_omega_one_and_stops_where_order_8_meets_the_floor() {
        // ω = 1, T = 10: h_floor = (1e-14)^{1/8} = 10^{-1.75} = 0.0178, 1/0.0178 = 2^5.81: six
        // halvings, seven levels.
        let l = automatic_for(1.0, 10.0, 0.1, None, 2.0);
        assert_eq!(l.steps.len(), 7);
        assert_eq!(l.steps[0], 1.0);
        assert_eq!(l.steps[6], 1.0 / 64.0);
        // Ten times faster: ten times smaller steps, and h_floor·ω = (1e-15)^{1/8} one level more.
        let fast = automatic_for(10.0, 10.0, 0.1, None, 2.0);
        assert_eq!(fast.steps[0], 0.1);
        assert_eq!(fast.steps.len(), 8);
        // Capped at T, at MAX_AUTO_LEVELS, and fixed by --levels.
        assert_eq!(automatic_for(0.01, 10.0, 0.1, None, 2.0).steps[0], 10.0);
        assert_eq!(
            automatic_for(1.0, 1e30, 0.1, None, 2.0).steps.len(),
            MAX_AUTO_LEVELS
        );
        assert_eq!(
            automatic_for(1.0, 10.0, 0.1, Some(3), 2.0).steps,
            [1.0, 0.5, 0.25]
        );
        // At rest: the scene's step.
        assert_eq!(automatic_for(0.0, 10.0, 0.1, None, 2.0).steps, [0.1, 0.05]);
    }

    #[test]
    fn a_finer_ratio_spans_the_same_range_in_more_levels() {
        assert_eq!(max_levels(2.0), MAX_AUTO_LEVELS);
        let r = std::f64::consts::SQRT_2;
        assert_eq!(max_levels(r), 19);
        assert_eq!(max_levels(4.0), 6);
        assert_eq!(max_levels(16.0), 4);
        // ω = 1, T = 10: h_floor = 2^-5.81, so √2 apart: ⌈11.6⌉ = 12 divisions, 13 levels, the
        // last at or below h_floor and the one before above it.
        let fine = automatic_for(1.0, 10.0, 0.1, None, r);
        assert_eq!(fine.steps.len(), 13);
        let h_floor = (1e-14f64).powf(1.0 / 8.0);
        assert!(fine.steps[12] <= h_floor && fine.steps[11] > h_floor);
        for (k, h) in fine.steps.iter().enumerate() {
            assert!((h - r.powi(-(k as i32))).abs() < 1e-15);
        }
        assert!(fine.rule.contains("divided by 1.414"), "{}", fine.rule);
        assert!(fine.rule.contains("at most 19 levels"), "{}", fine.rule);
        // Capped at the span of nine halvings.
        assert_eq!(automatic_for(1.0, 1e30, 0.1, None, r).steps.len(), 19);
        assert_eq!(
            automatic_for(1.0, 10.0, 0.1, Some(3), 4.0).steps,
            [1.0, 0.25, 0.0625]
        );
    }

    #[test]
    fn step_lists_parse_or_say_why_not() {
        assert_eq!(parse_steps("0.1, 0.05,2e-2").unwrap(), [0.1, 0.05, 0.02]);
        for bad in ["", " , ", "0.1,,0.05", "0.1,-1", "0", "NaN", "inf", "a"] {
            assert!(parse_steps(bad).is_err(), "{bad:?}");
        }
        assert!(explicit(vec![0.1, 2.0], 1.0).is_err());
        assert_eq!(explicit(vec![1.0, 0.5], 1.0).unwrap().steps, [1.0, 0.5]);
    }

    /// The vehicle scenes: the quadrotor's schedules' shortest gap (0.1 s) beats its torque rate
    /// √(0.05/0.082) = 0.78; the coupled bodies' stiffest spring √(8(1/1 + 1/2)) = √12 beats the
    /// spins and the off-centre turns.
    #[test]
    fn vehicle_rates_come_from_schedules_and_springs() {
        let example = |file: &str| {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../examples/scenes")
                .join(file);
            Scene::load(&path, Default::default()).unwrap()
        };
        let quad = example("quadrotor.toml");
        let rate = characteristic_rate(&quad.system, true).unwrap();
        assert!((rate - 10.0).abs() < 1e-9, "{rate}");
        let chain = example("coupled-bodies.toml");
        let rate = characteristic_rate(&chain.system, true).unwrap();
        assert!((rate - 12f64.sqrt()).abs() < 1e-12, "{rate}");
    }

    #[test]
    fn the_rate_is_the_body_velocity_or_the_potential_frequency() {
        let scene = |text: &str| Scene::parse(text, "s", "s", Default::default()).unwrap();
        let top = scene(
            r#"
[system]
kind = "heavy-top"
inertia = [2.0, 4.0, 5.0]
mass = 2.0
center_of_mass = [0.0, 0.0, 0.5]
gravity = 4.0
[initial]
momentum = [0.0, 0.0, 0.1]
[integrator]
method = "rk4"
step = 0.1
duration = 1.0
"#,
        );
        // √(2·4·0.5/2) = √2 > |Ω₀| = 0.02.
        let l = automatic(&top, Some(2), DEFAULT_RATIO).unwrap();
        assert!((l.steps[0] - 0.5f64.sqrt()).abs() < 1e-15, "{l:?}");
        let body = scene(
            r#"
[system]
kind = "free-rigid-body"
inertia = [2.0, 4.0, 5.0]
[initial]
momentum = [6.0, 0.0, -20.0]
[integrator]
method = "rk4"
step = 0.1
duration = 10.0
"#,
        );
        // |Ω₀| = |(3, 0, −4)| = 5.
        assert_eq!(
            automatic(&body, Some(2), DEFAULT_RATIO).unwrap().steps[0],
            0.2
        );
    }
}
