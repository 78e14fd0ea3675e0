//! What the adaptive driver needs of a method: an error estimate with each step, and steps that
//! land exactly on a requested time.

use super::{Controller, Tolerance};
use crate::{Integrator, IntegratorError};

/// A one-step method with an embedded error estimate, driven by [`crate::adaptive::Adaptive`].
///
/// Implemented by the RKMK pairs on any group ([`crate::adaptive::RkmkDopri5`],
/// [`crate::adaptive::RkmkDop853`]) and by the (q, Π) baselines
/// ([`crate::baselines::QuaternionDopri5`], [`crate::baselines::QuaternionDop853`]). Its
/// [`Integrator::step`] takes a fixed step of the advanced (higher-order) solution.
///
/// `Clone` because the driver evaluates the solution inside an accepted step (output times,
/// events) by a step from a copy of the state at the step's start.
pub trait EmbeddedPair: Integrator + Clone {
    /// The orders (p, p̂) of the advanced and of the embedded solution.
    fn orders(&self) -> (u32, u32);
    /// The controller the pair's authors recommend ([`crate::adaptive::ButcherPair::controller`]).
    fn controller(&self) -> Controller;
    /// The power k of h the error estimate scales with (the exponent of Hairer's starting step).
    fn error_exponent(&self) -> u32;
    /// Attempts the step from t to `t1` and returns its scaled error against `tolerance`
    /// ([`Tolerance`]); if it is ≤ 1 the step is taken and the time is then `t1` exactly,
    /// otherwise the state is left exactly as it was. A step whose result is not finite is
    /// reported as an infinite error (the controller shrinks it), not as an error. Errors:
    /// `t1` not finite or equal to t (state untouched).
    fn try_step_to(&mut self, t1: f64, tolerance: &Tolerance) -> Result<f64, IntegratorError>;
    /// The step from t to `t1` without error control; the time is then `t1` exactly. Errors as
    /// [`Integrator::step`] (state untouched).
    fn step_to(&mut self, t1: f64) -> Result<(), IntegratorError>;
    /// A first step towards the sign of `direction` for `tolerance`, by Hairer's algorithm
    /// ([`starting_step`]); it evaluates the vector field twice.
    fn starting_step(&mut self, direction: f64, tolerance: &Tolerance) -> f64;
}

/// Hairer's starting step (Hairer–Nørsett–Wanner, *Solving ODEs I*, §II.4; `dopri5.f`'s
/// `HINIT`): with d₀ = ‖y₀‖ and d₁ = ‖f(y₀)‖ in the scaled RMS norm of the tolerance,
/// `h₀ = 0.01 d₀/d₁` (1e-6 if either is below 1e-5), one explicit Euler step of h₀ giving
/// `d₂ = ‖f(y₀ + h₀f(y₀)) − f(y₀)‖/h₀` (the closure), and
/// `h = min(100 h₀, (0.01/max(d₁, d₂))^{1/k})`, k the error exponent of the pair.
pub fn starting_step(k: u32, d0: f64, d1: f64, d2: impl FnOnce(f64) -> f64) -> f64 {
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    let d2 = d2(h0);
    let m = d1.max(d2);
    let h1 = if m <= 1e-15 || !m.is_finite() {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / m).powf(1.0 / f64::from(k.max(1)))
    };
    (100.0 * h0).min(h1)
}

/// The checks of a step's end time: finite and not the current time. Inlined into every
/// attempt, with the refusals out of line.
#[inline(always)]
pub(crate) fn check_end_time(t: f64, t1: f64) -> Result<f64, IntegratorError> {
    let h = t1 - t;
    if !t1.is_finite() || h == 0.0 {
        return Err(end_time_refused(t, t1));
    }
    Ok(h)
}

#[cold]
#[inline(never)]
fn end_time_refused(t: f64, t1: f64) -> IntegratorError {
    if !t1.is_finite() {
        IntegratorError::NonFinite {
            what: "step end time t1",
        }
    } else {
        IntegratorError::InvalidParameter {
            reason: format!("a step needs an end time t1 ≠ t (both {t})"),
        }
    }
}
