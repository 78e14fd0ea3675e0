//! The checks every integrator makes of its inputs, in one place: a state that cannot be
//! stepped is refused with the error that names it, before anything moves.

use crate::{IntegratorError, System};
use discretization::DiscretizationError;
use lie_groups::{LieGroup, Vector};

/// A map's domain error as the integrator's [`IntegratorError::StepTooLarge`].
pub fn step_too_large(step: f64) -> impl Fn(DiscretizationError) -> IntegratorError {
    move |e| IntegratorError::StepTooLarge {
        step,
        reason: e.to_string(),
    }
}

/// Refuses θ outside [0, 1] (NaN included).
pub fn check_theta(theta: f64) -> Result<(), IntegratorError> {
    if (0.0..=1.0).contains(&theta) {
        Ok(())
    } else {
        Err(IntegratorError::InvalidTheta { theta })
    }
}

/// Refuses non-finite algebra vectors and group elements, a g that is not an element of G (its
/// matrix refused by the group's checked constructor `LieGroup::from_matrix`, e.g. a non-rotation
/// built with `from_matrix_unchecked`), and a missing g where V needs it.
pub fn check_state<G: LieGroup, S: System<G>>(
    system: &S,
    v: &G::Algebra,
    what: &'static str,
    g: Option<&G>,
) -> Result<(), IntegratorError> {
    if v.dim() != G::dim() {
        return Err(IntegratorError::InvalidParameter {
            reason: format!("{what} has dimension {}, the algebra {}", v.dim(), G::dim()),
        });
    }
    if !v.is_finite() {
        return Err(IntegratorError::NonFinite { what });
    }
    if let Some(g) = g {
        if !g.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "configuration g",
            });
        }
        if let Err(e) = G::from_matrix(&g.matrix()) {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("configuration g is not an element of {}: {e}", G::name()),
            });
        }
    } else if system.needs_configuration() {
        return Err(IntegratorError::MissingConfiguration);
    }
    Ok(())
}
