//! Solving the implicit step equations r(ξ) = 0 for the discrete velocity ξ ∈ 𝔤.
//!
//! Every implicit integrator of this crate reduces its step to n equations in n unknowns,
//! `r(ξ) = 0` with `∂r/∂ξ = I + O(h)`. Four iterations are offered ([`SolverKind`]):
//!
//! - [`SolverKind::SimplifiedNewton`] (default): `ξ ← ξ − J(ξ⁰)⁻¹ r(ξ)` with the analytic
//!   Jacobian evaluated and inverted once per step, at the predictor ξ⁰ (re-evaluated at the
//!   current iterate if the observed contraction exceeds 0.1). Its contraction factor is
//!   ‖J(ξ⁰)⁻¹ (J(ξ⁰) − J(ξ*))‖ = O(h ‖ξ⁰ − ξ*‖) plus the Jacobian's own error, tiny from the O(h³)
//!   predictors of the integrators: at moderate steps two iterations (two residuals, one Jacobian)
//!   meet the default tolerance. Along a run at a fixed step the integrators start warm
//!   ([`crate::WarmStart`]): from the cubic extrapolation of the last four solutions (O(h⁴)
//!   relative) with the previous step's J⁻¹, two residuals and no Jacobian (measured 2.00 residuals
//!   and 0.009 Jacobians per step on the free body at h = 0.01, `tests/warm_start.rs`).
//! - [`SolverKind::Newton`]: `ξ ← ξ − J(ξ)⁻¹ r(ξ)` with the analytic Jacobian J re-assembled at every
//!   iterate by the integrator from the operators of the group and the system (Ad, ad*, d^L τ,
//!   ∂²h/∂μ², and the second derivative `D(ζ; μ) = ∂/∂ζ (d^{L*}τ_ζ μ)` from
//!   [`lie_groups::Tau::dtau_left_dual_derivative`]). D is exact for τ = exp on every group (a
//!   series, [`lie_groups::LieGroup::dexp_left_dual_derivative`]) and for Cayley on SO(3), SE(3)
//!   and SE(2) (closed forms): there the Lie–Poisson Jacobian of a system without potential is
//!   exact and Newton converges quadratically — on the free SE(3) body at h = 0.1, 3.0 iterations
//!   per step, as many as Newton on a central-difference Jacobian (12.0 with the former
//!   first-order D; `tests/newton_jacobian.rs`). Elsewhere (Cayley on SO(n), GL(n), a user's τ)
//!   D is its leading term `δ ↦ −½ ad*_δ μ` and J is exact up to O(h²). With a potential the
//!   Lie–Poisson matrix includes the force's term `∂μ̄/∂ν · h K(ḡ) · ∂ḡ/∂ξ`
//!   ([`crate::System::force_derivative`], central differences unless the system gives it): the
//!   heavy top at h = 0.1 takes 2.8 Newton iterations per step, as with a finite-difference
//!   Jacobian (5.4 without the term). An external force's derivative is not included; the
//!   Euler–Poincaré Jacobian has its own O(h²) approximations (see [`crate::euler_poincare`]).
//! - [`SolverKind::NewtonFiniteDifference`]: Newton with J from central differences of r
//!   (2n residual evaluations per iteration): quadratic convergence, a documented fallback for
//!   large steps where an O(h²) Jacobian error matters (groups without closed forms, potentials).
//! - [`SolverKind::FixedPoint`]: `ξ ← ξ − r(ξ)` (J replaced by I), the cheapest iteration; it
//!   contracts by a factor O(h ‖∂²h/∂μ²‖ ‖μ‖).
//!
//! The iteration stops when the estimated error of ξ is within `tolerance · ‖ξ‖_max` (relative, so
//! that |μ| = 1e-8 is solved as accurately as |μ| = 1): with `ρ = ‖Δξ_k‖/‖Δξ_{k−1}‖ < 1` the
//! error left after the update Δξ_k is estimated by `ρ/(1−ρ) ‖Δξ_k‖` (Hairer & Wanner, *Solving
//! ODEs II*, §IV.8), which saves the last, confirming iteration of a plain `‖Δξ_k‖ ≤ tolerance`
//! test; at the first iteration, or when the updates no longer contract (round-off level), the
//! estimate is ‖Δξ_k‖ itself. It also stops when an update no longer changes ξ in floating point:
//! every further iteration would repeat it.

use crate::IntegratorError;
use lie_groups::{LieGroup, Operator, Vector};

/// Which iteration solves the implicit step equations (see the module page).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SolverKind {
    /// Simplified Newton (the chord method): the analytic Jacobian is evaluated and inverted once,
    /// at the predictor, and reused by every iteration of the step — and by the next steps of
    /// the same size while it contracts by 10⁻³ or better ([`crate::WarmStart`]); it is
    /// re-evaluated at the current iterate when the observed contraction ‖Δξ_k‖/‖Δξ_{k−1}‖
    /// exceeds 0.1. The default: it converges in 2 iterations at moderate steps, each one residual
    /// evaluation and one operator apply.
    #[default]
    SimplifiedNewton,
    /// Newton's method with the analytic Jacobian re-evaluated at every iterate (exact or
    /// O(h²)-accurate, see the module page): quadratic convergence, for large steps.
    Newton,
    /// Newton's method with a central finite-difference Jacobian (fallback; 2n extra residuals).
    NewtonFiniteDifference,
    /// Fixed-point iteration `ξ ← ξ − r(ξ)`.
    FixedPoint,
}

/// Tolerance, iteration limit and options of the step solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverConfig {
    /// The iteration used.
    pub kind: SolverKind,
    /// Relative tolerance on the error of ξ, estimated from the updates (see the module page):
    /// stop when `ρ/(1−ρ) ‖Δξ‖_max ≤ tolerance · ‖ξ‖_max`.
    /// The default 1e-14 is ~50 ulps: the residual itself is evaluated with a relative round-off
    /// of a few ulps. Tighter values are met when the iteration reaches a floating-point fixed
    /// point (the update no longer changes ξ); otherwise round-off noise in the updates may keep
    /// them from being met ([`IntegratorError::NoConvergence`]).
    pub tolerance: f64,
    /// Maximum number of iterations before [`IntegratorError::NoConvergence`].
    pub max_iterations: usize,
    /// Check after convergence that ξ lies in the domain where τ is invertible
    /// (`τ⁻¹(τ(ξ)) = ξ`), returning [`IntegratorError::StepTooLarge`] otherwise. For τ = exp on
    /// SO(3) this refuses rotations by more than π per step. Inside
    /// [`lie_groups::Tau::INVERTIBLE_RADIUS`] the check is known to pass and costs nothing.
    pub check_domain: bool,
}

impl Default for SolverConfig {
    fn default() -> Self {
        Self {
            kind: SolverKind::SimplifiedNewton,
            tolerance: 1e-14,
            max_iterations: 50,
            check_domain: true,
        }
    }
}

/// The n×n operator whose j-th column is `col(j)` (n must be dim 𝔤): stack-buffered for the
/// fixed-size groups, see [`lie_groups::matrix_path::operator_from_column_fn`].
pub fn operator_from_columns<G: LieGroup>(
    n: usize,
    col: impl FnMut(usize) -> G::Algebra,
) -> G::Operator {
    debug_assert_eq!(n, G::dim());
    lie_groups::matrix_path::operator_from_column_fn::<G>(col)
}

/// The operator `δ ↦ ad*_δ μ` ([`LieGroup::ad_dual_operator`], closed form where the group has one).
#[inline]
pub fn ad_dual_operator<G: LieGroup>(mu: &G::Algebra) -> G::Operator {
    G::ad_dual_operator(mu)
}

/// Observed contraction above which [`SolverKind::SimplifiedNewton`] re-evaluates its Jacobian.
const REFRESH_CONTRACTION: f64 = 0.1;

/// The converged ξ of [`solve`].
pub struct Solution<A, E, G = ()> {
    /// The solution ξ.
    pub xi: A,
    /// The number of iterations (residual evaluations, not counting finite differences).
    pub iterations: usize,
    /// The by-products of the last evaluation when it was made at exactly (bitwise) the returned
    /// ξ — the usual case at convergence, where the last update no longer changes ξ in floating
    /// point — so the caller need not evaluate again.
    pub evaluation: Option<E>,
    /// [`SolverKind::SimplifiedNewton`]'s inverse matrix J⁻¹ at the end, for the next step of
    /// the same size ([`crate::WarmStart`]); `None` for the other kinds.
    pub chord: Option<G>,
    /// How many Jacobians were evaluated (0 when a warm [`SolverKind::SimplifiedNewton`] matrix
    /// served the whole iteration).
    pub jacobians: usize,
    /// The largest contraction ‖Δξ_k‖/‖Δξ_{k−1}‖ observed (0 after one iteration).
    pub contraction: f64,
}

/// Solves `r(ξ) = 0` from the guess `xi`; [`SolverKind::SimplifiedNewton`] starts from the
/// inverse matrix `chord` when given (a previous step's, see [`crate::WarmStart`]) and evaluates
/// J only if there is none or the iteration contracts by less than 0.1.
///
/// `evaluate(ξ)` returns the residual r(ξ) together with whatever by-products of its evaluation
/// the Jacobian and the caller can reuse; `jacobian(ξ, by-products)` is called by the Newton kinds
/// right after `evaluate` at the same ξ. `evaluate` returns an error for non-finite values or
/// points outside τ's domain; those errors are passed on.
///
/// Stopping rule (Hairer & Wanner, *Solving ODEs II*, §IV.8): with the contraction estimate
/// `ρ = ‖Δξ_k‖/‖Δξ_{k−1}‖ < 1`, the error left after the update Δξ_k is at most about
/// `ρ/(1−ρ) ‖Δξ_k‖`; the iteration stops when that estimate (or ‖Δξ_k‖ itself at the first
/// iteration, or when the updates stop contracting at round-off level) is within
/// `tolerance · ‖ξ‖_max`, or when the update no longer changes ξ in floating point (Δξ = 0 or
/// below half an ulp of ξ), where further iterations would repeat the last one.
pub fn solve<G: LieGroup, E>(
    config: &SolverConfig,
    step: f64,
    mut xi: G::Algebra,
    mut chord: Option<G::Operator>,
    mut evaluate: impl FnMut(&G::Algebra) -> Result<(G::Algebra, E), IntegratorError>,
    mut jacobian: impl FnMut(&G::Algebra, &E) -> G::Operator,
) -> Result<Solution<G::Algebra, E, G::Operator>, IntegratorError> {
    let n = G::dim();
    let mut last_residual = f64::INFINITY;
    let mut previous_update = f64::INFINITY;
    let mut contraction = 0.0f64;
    let mut jacobians = 0;
    // Simplified Newton's J⁻¹, kept across iterations (and steps).
    if config.kind != SolverKind::SimplifiedNewton {
        chord = None;
    }
    for it in 1..=config.max_iterations {
        let (r, by_products) = evaluate(&xi)?;
        if !r.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "step residual",
            });
        }
        last_residual = r.norm_max();
        let delta = match config.kind {
            SolverKind::FixedPoint => r,
            SolverKind::Newton => {
                jacobians += 1;
                invert::<G>(step, &jacobian(&xi, &by_products))?.apply(&r)
            }
            SolverKind::SimplifiedNewton => {
                let inv = match chord.take() {
                    Some(inv) => inv,
                    None => {
                        jacobians += 1;
                        invert::<G>(step, &jacobian(&xi, &by_products))?
                    }
                };
                let delta = inv.apply(&r);
                chord = Some(inv);
                delta
            }
            SolverKind::NewtonFiniteDifference => {
                let scale = xi.norm_max().max(f64::MIN_POSITIVE.sqrt());
                // Central differences: error O(δ²) + O(ε/δ); δ = ε^{1/3} ‖ξ‖ balances them.
                let d = 6.055e-6 * scale;
                let mut err = None;
                let j = operator_from_columns::<G>(n, |k| {
                    let e = G::Algebra::basis(n, k);
                    let plus = evaluate(&xi.axpy(d, &e));
                    let minus = evaluate(&xi.axpy(-d, &e));
                    match (plus, minus) {
                        (Ok((p, _)), Ok((m, _))) => p.sub(&m).scale(0.5 / d),
                        (Err(e), _) | (_, Err(e)) => {
                            err = Some(e);
                            G::Algebra::zeros(n)
                        }
                    }
                });
                if let Some(e) = err {
                    return Err(e);
                }
                invert::<G>(step, &j)?.apply(&r)
            }
        };
        let next = xi.sub(&delta);
        let unchanged = same_bits(&next, &xi);
        xi = next;
        if !xi.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "solver iterate ξ",
            });
        }
        let dn = delta.norm_max();
        let rho = dn / previous_update;
        contraction = contraction.max(rho);
        // No contraction estimate at the first iteration (previous_update = ∞, ρ = 0).
        let error_estimate = if it > 1 && rho < 1.0 {
            dn * rho / (1.0 - rho)
        } else {
            dn
        };
        // `unchanged`: ξ is a fixed point of the iteration in floating point, so every further
        // iteration would repeat this one.
        if unchanged || error_estimate <= config.tolerance * xi.norm_max() {
            return Ok(Solution {
                xi,
                iterations: it,
                evaluation: unchanged.then_some(by_products),
                chord,
                jacobians,
                contraction,
            });
        }
        if rho > REFRESH_CONTRACTION {
            chord = None;
        }
        previous_update = dn;
    }
    Err(IntegratorError::NoConvergence {
        iterations: config.max_iterations,
        residual: last_residual,
    })
}

/// Whether two algebra vectors are bitwise equal.
#[inline]
fn same_bits<V: Vector>(a: &V, b: &V) -> bool {
    (0..a.dim()).all(|i| a.get(i).to_bits() == b.get(i).to_bits())
}

fn invert<G: LieGroup>(step: f64, j: &G::Operator) -> Result<G::Operator, IntegratorError> {
    j.try_inverse()
        .ok_or_else(|| IntegratorError::StepTooLarge {
            step,
            reason: "the Newton matrix of the step equations is singular".into(),
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use lie_groups::So3;
    use nalgebra::{Matrix3, Vector3};

    /// An update below half an ulp of ξ leaves ξ bitwise unchanged: the iteration has reached a
    /// floating-point fixed point and stops (returning that evaluation), even when the tolerance
    /// asks for more than round-off allows; it used to run into the iteration limit.
    #[test]
    fn an_update_that_no_longer_changes_xi_ends_the_iteration() {
        let config = SolverConfig {
            kind: SolverKind::FixedPoint,
            tolerance: 1e-40,
            ..SolverConfig::default()
        };
        let xi0 = Vector3::new(1.0, 1.0, 1.0);
        let evaluate = |xi: &Vector3<f64>| Ok((Vector3::new(1e-30, 0.0, 0.0), *xi));
        let solution = solve::<So3, Vector3<f64>>(&config, 0.1, xi0, None, evaluate, |_, _| {
            Matrix3::identity()
        })
        .unwrap();
        assert_eq!(solution.xi, xi0);
        assert_eq!(solution.iterations, 1);
        assert_eq!(solution.evaluation, Some(xi0));
    }

    /// The error estimate ρ/(1−ρ)‖Δξ‖ bounds what a slowly contracting iteration leaves: for
    /// r(ξ) = (ξ − ξ*)/10 the fixed point contracts by ρ = 0.9, so after an update Δξ the error is
    /// 9‖Δξ‖. The result is within the tolerance of ξ*; a plain ‖Δξ‖ ≤ tolerance test would stop
    /// with 9× the tolerance.
    #[test]
    fn the_error_estimate_keeps_a_slow_iteration_within_the_tolerance() {
        let tolerance = 1e-8;
        let config = SolverConfig {
            kind: SolverKind::FixedPoint,
            tolerance,
            max_iterations: 1000,
            ..SolverConfig::default()
        };
        let target = Vector3::new(1.0, -2.0, 0.5);
        let evaluate = |xi: &Vector3<f64>| Ok(((xi - target) * 0.1, ()));
        let solution = solve::<So3, ()>(&config, 0.1, Vector3::zeros(), None, evaluate, |_, _| {
            Matrix3::identity()
        })
        .unwrap();
        let error = (solution.xi - target).amax();
        assert!(
            error <= tolerance * solution.xi.amax(),
            "error {error:e} after {} iterations",
            solution.iterations
        );
        assert!(
            error > 0.5 * tolerance * solution.xi.amax(),
            "stopped later than needed"
        );
    }
}
