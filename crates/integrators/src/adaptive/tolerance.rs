//! The accuracy a run is asked for: a relative and an absolute tolerance, named as scipy's
//! `solve_ivp(rtol, atol)` and diffsol name them.

use crate::IntegratorError;

/// The local error a step may make, component by component: a step is accepted when its scaled
/// error `‖(êᵢ / (atol + rtol·|yᵢ|))ᵢ‖_rms ≤ 1` (Hairer–Nørsett–Wanner, *Solving ODEs I*, §II.4,
/// with |yᵢ| the larger of the component at the step's two ends).
///
/// What |yᵢ| is for a state on the group: the RKMK pairs measure the error of g as the algebra
/// element `log(ĝ⁻¹g)` (a left-invariant, hence relative, distance between the two solutions the
/// pair computes), so its components are scaled by `atol + rtol` — the size of a rotation taken
/// as 1. On SE(3) the translation part of that distance is the body-frame displacement, in the
/// units of the translation. The components of μ and of (q, Π) are scaled by their own size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// The relative tolerance (scipy's `rtol`).
    pub rtol: f64,
    /// The absolute tolerance (scipy's `atol`).
    pub atol: f64,
}

impl Tolerance {
    /// The smallest `rtol` accepted: 100 ε ≈ 2.2e-14. Below it the error estimate of a step is
    /// the rounding of the state itself (ε|y| per component per step) and the controller would
    /// shrink the step without end; scipy raises a tighter `rtol` to the same bound with a
    /// warning, Hairer's codes refuse `rtol ≤ 10 ε`.
    pub const MIN_RTOL: f64 = 100.0 * f64::EPSILON;

    /// `rtol` and `atol`, both finite and > 0, `rtol ≥` [`Self::MIN_RTOL`]. Errors:
    /// [`IntegratorError::InvalidTolerance`] naming the tolerance and the value given.
    pub fn new(rtol: f64, atol: f64) -> Result<Self, IntegratorError> {
        for (name, value) in [("rtol", rtol), ("atol", atol)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(IntegratorError::InvalidTolerance {
                    name,
                    value,
                    requirement: "finite and > 0".into(),
                });
            }
        }
        if rtol < Self::MIN_RTOL {
            return Err(IntegratorError::InvalidTolerance {
                name: "rtol",
                value: rtol,
                requirement: format!(
                    "≥ 100 ε = {:.1e}: f64 cannot deliver a smaller relative error per step",
                    Self::MIN_RTOL
                ),
            });
        }
        Ok(Self { rtol, atol })
    }

    /// `rtol = atol = tol`.
    pub fn uniform(tol: f64) -> Result<Self, IntegratorError> {
        Self::new(tol, tol)
    }

    /// The scale `atol + rtol·max(|a|, |b|)` of a component that is `a` at the step's start and
    /// `b` at its end.
    #[inline(always)]
    pub fn scale(&self, a: f64, b: f64) -> f64 {
        self.atol + self.rtol * a.abs().max(b.abs())
    }
}
