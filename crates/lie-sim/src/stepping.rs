//! How a scene's run steps: a fixed step h (`integrator.step`), or a tolerance the method's
//! error estimate meets (`integrator.tolerance`, or `rtol` and `atol`, named as scipy's
//! `solve_ivp(rtol, atol)` and diffsol name them), whichever its registry row takes
//! ([`crate::methods::row::Stepping`]); or, for a fixed-step method that is symmetric, reversible
//! variable steps (`integrator.epsilon`): the step-density controller of Hairer–Söderlind
//! (`integrators::adaptive::ReversibleSteps`), h_n = ε/ρ_{n+½} with ρ the rate of the motion
//! (`integrators::System::step_density`), so that ε is the step in units of the motion's time
//! scale, and the error of an order-p method falls as ε^p. Whether the method is symmetric is
//! decided when it is built (`SymmetricMethod::is_symmetric`: the one rule).
//!
//! `tolerance = 1e-8` is `rtol = atol = 1e-8`; `rtol` and `atol` give them apart (both, not
//! one). The library's [`Tolerance::new`] decides what is valid (finite, > 0, `rtol` no smaller
//! than 100 ε, below which f64 cannot deliver the relative error of a step), and its refusal is
//! reported against the key the scene wrote. A step on a tolerance-driven method, a tolerance on
//! a fixed-step one, or both `tolerance` and `rtol`/`atol`, are refused naming the key.

use crate::fields::{positive, FieldError};
use crate::methods::row::Stepping;
use crate::methods::MethodId;
use integrators::adaptive::Tolerance;
use integrators::IntegratorError;

/// The keys of `[integrator]` that say how it steps, as written.
#[derive(Debug, Clone, Copy, Default)]
pub struct RawStepping {
    /// `step`.
    pub step: Option<f64>,
    /// `tolerance` (rtol = atol).
    pub tolerance: Option<f64>,
    /// `rtol`.
    pub rtol: Option<f64>,
    /// `atol`.
    pub atol: Option<f64>,
    /// `epsilon`.
    pub epsilon: Option<f64>,
}

/// How a checked scene steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepChoice {
    /// A fixed step h > 0, at most T.
    Fixed(f64),
    /// Steps chosen as the run goes.
    Variable(VariableSteps),
}

/// Steps chosen as the run goes, and by what.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum VariableSteps {
    /// The error controller of an embedded pair, to this tolerance.
    Tolerance(Tolerance),
    /// The reversible step-density controller of a symmetric method, with this ε > 0.
    Reversible(f64),
}

/// The methods whose row takes `stepping`, for messages.
fn methods_stepping(stepping: Stepping) -> String {
    MethodId::ALL
        .iter()
        .filter(|m| m.row().takes.stepping == stepping)
        .map(|m| m.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// `raw` checked against what `method` takes, for a run of `duration` (given by the field or
/// flag `duration_name`).
pub fn check(
    raw: &RawStepping,
    method: MethodId,
    duration: f64,
    duration_name: &str,
) -> Result<StepChoice, FieldError> {
    let field = |f: &str| format!("integrator.{f}");
    let given_tolerance = [
        ("tolerance", raw.tolerance),
        ("rtol", raw.rtol),
        ("atol", raw.atol),
    ]
    .into_iter()
    .find_map(|(k, v)| v.map(|v| (k, v)));
    match method.row().takes.stepping {
        Stepping::Fixed if raw.epsilon.is_some() => {
            let epsilon = raw.epsilon.unwrap_or_default();
            if let Some((key, value)) = given_tolerance {
                return Err((
                    field(key),
                    format!(
                        "give epsilon (= {epsilon:e}, reversible variable steps) or {key}                          (= {value:e}), not both; {method} takes epsilon, the methods that take                          a tolerance: {}",
                        methods_stepping(Stepping::Tolerance)
                    ),
                ));
            }
            if let Some(step) = raw.step {
                return Err((
                    field("step"),
                    format!(
                        "give step (= {step}, fixed steps) or epsilon (= {epsilon:e}, reversible                          variable steps h = ε/ρ), not both"
                    ),
                ));
            }
            let epsilon = positive(&field("epsilon"), epsilon)?;
            Ok(StepChoice::Variable(VariableSteps::Reversible(epsilon)))
        }
        Stepping::Fixed => {
            if let Some((key, value)) = given_tolerance {
                return Err((
                    field(key),
                    format!(
                        "{method} takes a fixed step h, not a tolerance (got {key} = {value:e}); \
                         the methods that take one: {} (the implicit solver's tolerance is \
                         solver_tolerance)",
                        methods_stepping(Stepping::Tolerance)
                    ),
                ));
            }
            let Some(step) = raw.step else {
                return Err((
                    field("step"),
                    format!(
                        "{method} needs a step h > 0 (or name a method that takes a tolerance: \
                         {})",
                        methods_stepping(Stepping::Tolerance)
                    ),
                ));
            };
            let step = positive(&field("step"), step)?;
            if step > duration {
                return Err((
                    field("step"),
                    format!(
                        "h = {step:?} exceeds the duration T = {duration:?} ({duration_name}): \
                         give a step no longer than the run (one step to T is step = duration)"
                    ),
                ));
            }
            Ok(StepChoice::Fixed(step))
        }
        Stepping::Tolerance => {
            if let Some(epsilon) = raw.epsilon {
                return Err((
                    field("epsilon"),
                    format!(
                        "{method} chooses its own steps to meet a tolerance: give tolerance                          (or rtol and atol) instead of epsilon = {epsilon:e} (reversible steps are                          for the symmetric fixed-step methods)"
                    ),
                ));
            }
            if let Some(step) = raw.step {
                return Err((
                    field("step"),
                    format!(
                        "{method} chooses its own steps to meet a tolerance: give tolerance \
                         (or rtol and atol) instead of step = {step}"
                    ),
                ));
            }
            let (rtol, atol, key) = match (raw.tolerance, raw.rtol, raw.atol) {
                (Some(t), None, None) => (t, t, Some("tolerance")),
                (Some(t), _, _) => {
                    let other = if raw.rtol.is_some() { "rtol" } else { "atol" };
                    return Err((
                        field(other),
                        format!(
                            "give either tolerance (= {t:e}, rtol = atol) or rtol and atol, \
                             not both"
                        ),
                    ));
                }
                (None, Some(r), Some(a)) => (r, a, None),
                (None, Some(r), None) => {
                    return Err((
                        field("atol"),
                        format!("rtol = {r:e} needs atol too (or give tolerance alone)"),
                    ))
                }
                (None, None, Some(a)) => {
                    return Err((
                        field("rtol"),
                        format!("atol = {a:e} needs rtol too (or give tolerance alone)"),
                    ))
                }
                (None, None, None) => {
                    return Err((
                        field("tolerance"),
                        format!(
                            "{method} chooses its own steps: give tolerance = 1e-8 (rtol = atol) \
                             or rtol and atol"
                        ),
                    ))
                }
            };
            Tolerance::new(rtol, atol)
                .map(|t| StepChoice::Variable(VariableSteps::Tolerance(t)))
                .map_err(|e| match e {
                    IntegratorError::InvalidTolerance {
                        name,
                        value,
                        requirement,
                    } => (
                        field(key.unwrap_or(name)),
                        format!("{name} = {value:e} must be {requirement}"),
                    ),
                    e => (field(key.unwrap_or("rtol")), e.to_string()),
                })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn raw(
        step: Option<f64>,
        tol: Option<f64>,
        rtol: Option<f64>,
        atol: Option<f64>,
    ) -> RawStepping {
        RawStepping {
            step,
            tolerance: tol,
            rtol,
            atol,
            epsilon: None,
        }
    }

    /// Each bad combination is refused naming the key the scene wrote and the value it gave.
    #[test]
    fn bad_tolerances_name_the_key_and_the_value() {
        let dop = MethodId::RkmkDop853;
        let cases: &[(RawStepping, &str, &str)] = &[
            (
                raw(None, Some(0.0), None, None),
                "integrator.tolerance",
                "0e0",
            ),
            (
                raw(None, Some(-1e-6), None, None),
                "integrator.tolerance",
                "-1e-6",
            ),
            (
                raw(None, Some(f64::NAN), None, None),
                "integrator.tolerance",
                "NaN",
            ),
            (
                raw(None, Some(1e-17), None, None),
                "integrator.tolerance",
                "1e-17",
            ),
            (
                raw(None, None, Some(1e-8), Some(0.0)),
                "integrator.atol",
                "0e0",
            ),
            (
                raw(None, None, Some(1e-16), Some(1e-8)),
                "integrator.rtol",
                "1e-16",
            ),
            (raw(None, None, Some(1e-8), None), "integrator.atol", "1e-8"),
            (
                raw(None, Some(1e-8), Some(1e-8), None),
                "integrator.rtol",
                "1e-8",
            ),
            (
                raw(Some(0.1), Some(1e-8), None, None),
                "integrator.step",
                "0.1",
            ),
            (
                raw(None, None, None, None),
                "integrator.tolerance",
                "tolerance = 1e-8",
            ),
        ];
        for (r, key, value) in cases {
            let (field, message) = check(r, dop, 10.0, "integrator.duration").unwrap_err();
            assert_eq!(field, *key, "{r:?}: {message}");
            assert!(message.contains(value), "{r:?}: {message}");
        }
        let (field, message) = check(
            &raw(Some(0.1), Some(1e-8), None, None),
            MethodId::Rk4,
            10.0,
            "integrator.duration",
        )
        .unwrap_err();
        assert_eq!(field, "integrator.tolerance", "{message}");
        assert!(
            message.contains("fixed step") && message.contains("rkmk-dop853"),
            "{message}"
        );
        let (field, _) = check(
            &raw(None, None, None, None),
            MethodId::Rk4,
            10.0,
            "integrator.duration",
        )
        .unwrap_err();
        assert_eq!(field, "integrator.step");
    }

    #[test]
    fn a_tolerance_is_rtol_and_atol_and_a_step_is_fixed() {
        let dop = MethodId::RkmkDop853;
        assert_eq!(
            check(
                &raw(None, Some(1e-8), None, None),
                dop,
                1.0,
                "integrator.duration"
            ),
            Ok(StepChoice::Variable(VariableSteps::Tolerance(
                Tolerance::new(1e-8, 1e-8).unwrap()
            )))
        );
        assert_eq!(
            check(
                &raw(None, None, Some(1e-6), Some(1e-9)),
                dop,
                1.0,
                "integrator.duration"
            ),
            Ok(StepChoice::Variable(VariableSteps::Tolerance(
                Tolerance::new(1e-6, 1e-9).unwrap()
            )))
        );
        assert_eq!(
            check(
                &raw(Some(0.1), None, None, None),
                MethodId::Rk4,
                1.0,
                "integrator.duration"
            ),
            Ok(StepChoice::Fixed(0.1))
        );
    }

    /// ε is taken by the fixed-step methods instead of a step (their symmetry is checked when
    /// built), refused beside a step or a tolerance and by the tolerance-driven methods, and
    /// must be finite and > 0.
    #[test]
    fn epsilon_replaces_the_step_of_a_fixed_step_method() {
        let with_epsilon = |step, tol, eps| RawStepping {
            epsilon: Some(eps),
            ..raw(step, tol, None, None)
        };
        assert_eq!(
            check(
                &with_epsilon(None, None, 0.05),
                MethodId::Splitting,
                1.0,
                "integrator.duration"
            ),
            Ok(StepChoice::Variable(VariableSteps::Reversible(0.05)))
        );
        let refused = [
            (
                with_epsilon(Some(0.1), None, 0.05),
                MethodId::Splitting,
                "integrator.step",
            ),
            (
                with_epsilon(None, Some(1e-8), 0.05),
                MethodId::Splitting,
                "integrator.tolerance",
            ),
            (
                with_epsilon(None, Some(1e-8), 0.05),
                MethodId::RkmkDop853,
                "integrator.epsilon",
            ),
            (
                with_epsilon(None, None, 0.0),
                MethodId::Splitting,
                "integrator.epsilon",
            ),
            (
                with_epsilon(None, None, -0.1),
                MethodId::LiePoisson,
                "integrator.epsilon",
            ),
            (
                with_epsilon(None, None, f64::NAN),
                MethodId::Splitting,
                "integrator.epsilon",
            ),
        ];
        for (raw, method, key) in refused {
            let (field, message) = check(&raw, method, 1.0, "integrator.duration").unwrap_err();
            assert_eq!(field, key, "{message}");
        }
    }
}
