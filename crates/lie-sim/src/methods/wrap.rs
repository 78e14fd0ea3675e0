//! Building a method: why it can fail ([`BuildError`]), and the composition or processing around
//! a symmetric base ([`wrap`]).

use super::options::Options;
use crate::model::Missing;
use crate::sim::Boxed;
use integrators::processing::Processed;
use integrators::{Composition, IntegratorError, StateSnapshot, SymmetricMethod};

/// Why a method could not be built on a model.
#[derive(Debug, Clone)]
pub enum BuildError {
    /// The model lacks what the method needs: the method's need, the model's reason, and whether
    /// the library could have it but does not yet (`unavailable`) rather than the method not
    /// applying.
    Missing {
        /// What the method needs, as a sentence about it.
        need: String,
        /// The model's own reason, if it gives one.
        why: Option<String>,
        /// Not provided yet, rather than inapplicable.
        unavailable: bool,
    },
    /// A composition or processing around a base the library reports not symmetric.
    NotSymmetric {
        /// `integrator.composition` or `integrator.processing`.
        field: &'static str,
        /// What was refused.
        message: String,
    },
    /// The integrators crate refused the system, the state or the options.
    Integrator(IntegratorError),
}

/// The refusal as one sentence.
impl std::fmt::Display for BuildError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Missing { need, why, .. } => f.write_str(&Self::reason(need, why)),
            Self::NotSymmetric { message, .. } => f.write_str(message),
            Self::Integrator(e) => write!(f, "{e}"),
        }
    }
}

impl From<IntegratorError> for BuildError {
    fn from(e: IntegratorError) -> Self {
        Self::Integrator(e)
    }
}

impl BuildError {
    /// The method needs `need` and the model lacks it (`missing`: its reason, if any).
    pub fn missing(need: impl Into<String>, missing: Missing) -> Self {
        Self::Missing {
            need: need.into(),
            why: missing.0,
            unavailable: false,
        }
    }
    /// As [`Self::missing`], for what the library does not provide yet.
    pub fn unavailable(need: impl Into<String>, missing: Missing) -> Self {
        Self::Missing {
            need: need.into(),
            why: missing.0,
            unavailable: true,
        }
    }
    /// The message of a missing capability: the need and the model's reason.
    pub fn reason(need: &str, why: &Option<String>) -> String {
        match why {
            Some(w) => format!("{need}; {w}"),
            None => need.to_string(),
        }
    }
}

/// `inner`, or `inner` composed with the spec's composition scheme, or processed by its
/// processing scheme — when `inner` is symmetric as the integrators crate reports it
/// (`SymmetricMethod::is_symmetric`: the one rule), refused naming the base otherwise. A
/// symmetric result (the base, or its composition) keeps `system` as the monitor of its
/// reversible variable steps ([`Boxed::symmetric`]); a processed method takes fixed steps only
/// (its processor P is applied once, at the ends of a run of equal kernel steps).
pub fn wrap<I, S>(
    inner: I,
    system: &S,
    options: &Options,
    name: &str,
    kind: &str,
) -> Result<Boxed<I::Group>, BuildError>
where
    I: SymmetricMethod + StateSnapshot + Clone + 'static,
    S: integrators::System<I::Group> + Clone + 'static,
{
    let (field, scheme) = match (&options.composition, &options.processing) {
        (None, None) => return Ok(Boxed::symmetric(inner, system.clone())),
        (Some(c), _) => ("integrator.composition", c.name().to_string()),
        (None, Some(p)) => ("integrator.processing", p.name().to_string()),
    };
    if !inner.is_symmetric() {
        return Err(BuildError::NotSymmetric {
            field,
            message: format!(
                "{scheme} needs a symmetric base method, and {} is not symmetric on this {kind} \
                 (as the integrators crate reports it: Φ_{{−h}} ≠ Φ_h⁻¹)",
                options.base(name)
            ),
        });
    }
    Ok(match (&options.composition, &options.processing) {
        (Some(c), _) => Boxed::symmetric(Composition::new(inner, c.clone())?, system.clone()),
        (None, Some(p)) => Boxed::new(Processed::composition(inner, p.clone())?),
        (None, None) => Boxed::symmetric(inner, system.clone()),
    })
}
