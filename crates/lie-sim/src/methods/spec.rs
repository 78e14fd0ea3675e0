//! The `[integrator]` table: what it may hold, and the checks of a method's options against what
//! its registry row takes ([`super::row::Takes`]). Whether a composition's base is symmetric, and
//! whether the method applies to the system, is the library's answer when the method is built
//! on the scene's model ([`super::build`]), not a rule written here.

use super::row::{Takes, TauRule};
use super::{MethodId, MethodSpec};
use crate::fields::FieldError;
use crate::taus::TauKind;
use integrators::processing::ProcessingScheme;
use integrators::splitting::SplittingScheme;
use integrators::{CompositionScheme, SolverConfig, SolverKind};
use serde::Deserialize;

/// `[integrator]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawIntegrator {
    /// The method (a row of the registry, [`super::MethodId`]).
    pub method: MethodId,
    /// τ map.
    pub tau: Option<TauKind>,
    /// θ ∈ [0, 1].
    pub theta: Option<f64>,
    /// Step h > 0, for a fixed-step method (`crate::stepping`).
    pub step: Option<f64>,
    /// The tolerance of a tolerance-driven method: rtol = atol (`crate::stepping`).
    pub tolerance: Option<f64>,
    /// Its relative tolerance (scipy's `rtol`), with `atol`.
    pub rtol: Option<f64>,
    /// Its absolute tolerance (scipy's `atol`), with `rtol`.
    pub atol: Option<f64>,
    /// ε of reversible variable steps h = ε/ρ, for a symmetric method (`crate::stepping`).
    pub epsilon: Option<f64>,
    /// Duration T > 0.
    pub duration: f64,
    /// Integrate the group element too (default true).
    pub reconstruct: Option<bool>,
    /// The iteration of the implicit solver (default: the integrators crate's).
    pub solver: Option<SolverChoice>,
    /// Tolerance of the implicit solver (default: the integrators crate's).
    pub solver_tolerance: Option<f64>,
    /// Iteration limit of the implicit solver (default: the integrators crate's).
    pub max_iterations: Option<usize>,
    /// Composition scheme around a symmetric base method (any name
    /// `integrators::CompositionScheme` parses, e.g. `kahan-li-6`).
    pub composition: Option<String>,
    /// Coefficients of the methods that take them (kinetic-kick): `strang`, `blanes-moan-4`, …
    pub splitting: Option<String>,
    /// Processing scheme around a symmetric base method (a name
    /// `integrators::processing::ProcessingScheme` parses, e.g. `blanes-casas-murua-6-11`).
    pub processing: Option<String>,
    /// The modified Hamiltonian (the methods that take it: lie-poisson on the free body).
    pub modified: Option<bool>,
    /// The order of the modified Hamiltonian: 4 (default) or 6.
    pub order: Option<u32>,
}

/// The iteration that solves the implicit step equations (`integrators::SolverKind`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SolverChoice {
    /// Simplified Newton: one analytic Jacobian per step (the default).
    SimplifiedNewton,
    /// Newton with the analytic Jacobian at every iterate.
    Newton,
    /// Newton with a finite-difference Jacobian.
    NewtonFd,
    /// Fixed-point iteration.
    FixedPoint,
}

/// Options of the implicit solver, passed to the integrators crate where it takes them.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SolverOptions {
    /// The iteration.
    pub kind: Option<SolverChoice>,
    /// Residual tolerance.
    pub tolerance: Option<f64>,
    /// Iteration limit.
    pub max_iterations: Option<usize>,
}

impl SolverOptions {
    /// The integrators crate's configuration with these options applied.
    pub fn config(&self) -> SolverConfig {
        let mut config = SolverConfig::default();
        if let Some(kind) = self.kind {
            config.kind = match kind {
                SolverChoice::SimplifiedNewton => SolverKind::SimplifiedNewton,
                SolverChoice::Newton => SolverKind::Newton,
                SolverChoice::NewtonFd => SolverKind::NewtonFiniteDifference,
                SolverChoice::FixedPoint => SolverKind::FixedPoint,
            };
        }
        if let Some(t) = self.tolerance {
            config.tolerance = t;
        }
        if let Some(m) = self.max_iterations {
            config.max_iterations = m;
        }
        config
    }
}

/// The names of the rows whose `takes` has `what`, for messages ("for lie-poisson").
fn rows_taking(what: impl Fn(&Takes) -> bool) -> String {
    MethodId::ALL
        .iter()
        .filter(|m| what(&m.row().takes))
        .map(|m| m.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Checks the method keys of `[integrator]` against what the method's row takes.
pub fn check(it: &RawIntegrator) -> Result<MethodSpec, FieldError> {
    let m = it.method;
    let takes = &m.row().takes;
    let field = |f: &str| format!("integrator.{f}");
    let tau = match (takes.tau, it.tau) {
        (TauRule::None, Some(t)) => {
            return Err((field("tau"), format!("{m} takes no τ map (got \"{t}\")")))
        }
        (TauRule::None, None) => None,
        (TauRule::Only(only), None) => Some(only),
        (TauRule::Only(only), Some(t)) if t == only => Some(t),
        (TauRule::Only(only), Some(t)) => {
            return Err((
                field("tau"),
                format!("{m} is built on τ = {only} (got \"{t}\")"),
            ))
        }
        (TauRule::Any, None) => {
            let names: Vec<String> = TauKind::ALL.iter().map(|t| format!("\"{t}\"")).collect();
            return Err((
                field("tau"),
                format!("{m} needs a τ map: {}", names.join(" or ")),
            ));
        }
        (TauRule::Any, Some(t)) => Some(t),
    };
    let theta = match (takes.theta, it.theta) {
        (true, None) => {
            return Err((
                field("theta"),
                format!("{m} needs θ ∈ [0, 1] (0, 0.5 or 1 are the usual choices)"),
            ))
        }
        (true, Some(th)) if !(0.0..=1.0).contains(&th) => {
            return Err((field("theta"), format!("must lie in [0, 1], got {th}")))
        }
        (true, Some(th)) => Some(th),
        (false, Some(th)) => return Err((field("theta"), format!("{m} takes no θ (got {th})"))),
        (false, None) => None,
    };
    let composition = match &it.composition {
        None => None,
        Some(name) => {
            let scheme: CompositionScheme = name.parse().map_err(|_| {
                // The built-in list, and the order-10 recursive schemes (81 and 625 stages)
                // that parse too but are left out of it.
                let known: Vec<String> = CompositionScheme::builtin()
                    .iter()
                    .map(|c| c.name().to_string())
                    .chain(["triple-jump-10".to_string(), "suzuki-10".to_string()])
                    .filter(|n| n.parse::<CompositionScheme>().is_ok())
                    .collect();
                (
                    field("composition"),
                    format!(
                        "unknown composition scheme \"{name}\" (known: {})",
                        known.join(", ")
                    ),
                )
            })?;
            if !takes.wrappers {
                return Err((
                    field("composition"),
                    format!(
                        "{} composes a symmetric base method, and {m} cannot be composed (the \
                         methods that can: {})",
                        scheme.name(),
                        rows_taking(|t| t.wrappers)
                    ),
                ));
            }
            Some(scheme)
        }
    };
    let splitting = match (&it.splitting, takes.coefficients) {
        (None, true) => Some(SplittingScheme::strang()),
        (None, false) => None,
        (Some(name), true) => Some(SplittingScheme::by_name(name).map_err(|_| {
            let known: Vec<String> = SplittingScheme::builtin()
                .iter()
                .map(|s| s.name().to_string())
                .collect();
            (
                field("splitting"),
                format!(
                    "unknown splitting scheme \"{name}\" (known: {})",
                    known.join(", ")
                ),
            )
        })?),
        (Some(name), false) => {
            return Err((
                field("splitting"),
                format!(
                    "the coefficients \"{name}\" are for method = {}; {m} takes none (method = \
                     \"splitting\" is Strang, composed with `composition`)",
                    rows_taking(|t| t.coefficients)
                ),
            ))
        }
    };
    let modified = match (it.modified.unwrap_or(false), it.order) {
        (false, None) => None,
        (false, Some(order)) => {
            return Err((
                field("order"),
                format!(
                    "order = {order} is the order of the modified Hamiltonian: it needs \
                     modified = true"
                ),
            ))
        }
        (true, order) => {
            let order = order.unwrap_or(4);
            if order != 4 && order != 6 {
                return Err((
                    field("order"),
                    format!("the modified Hamiltonian is derived to order 4 and 6, got {order}"),
                ));
            }
            // θ and the composition: the scheme exists for θ = ½ and θ = 0 (mechanics'
            // `ModifiedScheme`), and is of its order on its own.
            let scheme_exists =
                theta.is_some_and(|t| mechanics::modified::ModifiedScheme::new(t, order).is_ok());
            if !(takes.modified && scheme_exists && composition.is_none()) {
                return Err((
                    field("modified"),
                    format!(
                        "the modified Hamiltonian is derived for {} with θ = 0.5 or 0 and no \
                         composition (it is order {order} on its own), got {m}{}",
                        rows_taking(|t| t.modified),
                        theta.map_or_else(String::new, |t| format!(" with θ = {t}"))
                    ),
                ));
            }
            Some(order)
        }
    };
    let processing = match &it.processing {
        None => None,
        Some(name) => {
            let scheme: ProcessingScheme = name.parse().map_err(|_| {
                let known: Vec<&str> = ProcessingScheme::builtin()
                    .iter()
                    .map(|p| p.name())
                    .collect();
                (
                    field("processing"),
                    format!(
                        "unknown processing scheme \"{name}\" (known: {})",
                        known.join(", ")
                    ),
                )
            })?;
            if composition.is_some() || modified.is_some() {
                return Err((
                    field("processing"),
                    format!(
                        "{} processes a composition of the base method itself: it does not go \
                         with `composition` or `modified`",
                        scheme.name()
                    ),
                ));
            }
            if !takes.wrappers {
                return Err((
                    field("processing"),
                    format!(
                        "{} processes a symmetric base method, and {m} cannot be processed (the \
                         methods that can: {})",
                        scheme.name(),
                        rows_taking(|t| t.wrappers)
                    ),
                ));
            }
            Some(scheme)
        }
    };
    Ok(MethodSpec {
        method: m,
        tau,
        theta,
        composition,
        splitting,
        processing,
        modified,
        // Set from the scene's stepping keys (`integrator.epsilon`, `crate::stepping`).
        reversible: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every candidate of `trade` passes the scene's own option check: `trade` runs nothing a
    /// scene could not name.
    #[test]
    fn every_candidate_is_a_method_a_scene_can_name() {
        let all = super::super::candidates();
        for s in &all {
            let raw = RawIntegrator {
                method: s.method,
                tau: s.tau,
                theta: s.theta,
                step: Some(0.1),
                tolerance: None,
                rtol: None,
                atol: None,
                epsilon: None,
                duration: 1.0,
                reconstruct: None,
                solver: None,
                solver_tolerance: None,
                max_iterations: None,
                composition: s.composition.as_ref().map(|c| c.name().to_string()),
                splitting: s.splitting.as_ref().map(|c| c.name().to_string()),
                processing: s.processing.as_ref().map(|c| c.name().to_string()),
                modified: s.modified.map(|_| true),
                order: s.modified,
            };
            // Reversible steps are set by the scene's stepping keys (`epsilon`), not by these.
            let expected = MethodSpec {
                reversible: false,
                ..s.clone()
            };
            assert_eq!(check(&raw), Ok(expected), "{s}");
        }
    }
}
