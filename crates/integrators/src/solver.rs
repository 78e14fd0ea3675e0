//! Solving the implicit step equations r(ξ) = 0 for the discrete velocity ξ ∈ 𝔤.
//!
//! Every implicit integrator of this crate reduces its step to n equations in n unknowns,
//! `r(ξ) = 0` with `∂r/∂ξ = I + O(h)`. Three iterations are offered ([`SolverKind`]):
//!
//! - [`SolverKind::Newton`]: `ξ ← ξ − J(ξ)⁻¹ r(ξ)` with the analytic Jacobian J assembled by the
//!   integrator from the operators of the group and the system (Ad, ad*, d^L τ, ∂²h/∂μ², and the
//!   second derivative `D(ζ; μ) = ∂/∂ζ (d^{L*}τ_ζ μ)` from
//!   [`lie_groups::Tau::dtau_left_dual_derivative`]). Where the group has a closed form of D
//!   (SO(3) with exp and Cayley) the Lie–Poisson Jacobian is exact and Newton converges
//!   quadratically; otherwise D is its leading term `δ ↦ −½ ad*_δ μ` (exact at ζ = 0 for every τ
//!   with `τ(ζ) = exp(ζ) + O(ζ³)`, which holds for exp and Cayley) and J is exact up to O(h²), so the
//!   iteration contracts by a factor O(h²) per step. The derivative of the force is dropped in
//!   both cases (an O(h²) error with a potential); the Euler–Poincaré Jacobian has its own
//!   O(h²) approximations (see [`crate::euler_poincare`]).
//! - [`SolverKind::NewtonFiniteDifference`]: Newton with J from central differences of r
//!   (2n residual evaluations per iteration): quadratic convergence, a documented fallback for
//!   large steps where an O(h²) Jacobian error matters (groups without closed forms, potentials).
//! - [`SolverKind::FixedPoint`]: `ξ ← ξ − r(ξ)` (J replaced by I), the cheapest iteration; it
//!   contracts by a factor O(h ‖∂²h/∂μ²‖ ‖μ‖).
//!
//! The iteration stops when the update satisfies `‖Δξ‖_max ≤ tolerance · ‖ξ‖_max` (relative, so that
//! |μ| = 1e-8 is solved as accurately as |μ| = 1), or when `Δξ = 0`.

use crate::IntegratorError;
use lie_groups::{LieGroup, Operator, Vector};

/// Which iteration solves the implicit step equations (see the module page).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SolverKind {
    /// Newton's method with the analytic Jacobian (exact or O(h²)-accurate, see the module page).
    #[default]
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
    /// Relative tolerance on the update: stop when `‖Δξ‖_max ≤ tolerance · ‖ξ‖_max`.
    /// The default 1e-14 is ~50 ulps: the residual itself is evaluated with a relative round-off
    /// of a few ulps, so tighter values may never be met.
    pub tolerance: f64,
    /// Maximum number of iterations before [`IntegratorError::NoConvergence`].
    pub max_iterations: usize,
    /// Check after convergence that ξ lies in the domain where τ is invertible
    /// (`τ⁻¹(τ(ξ)) = ξ`), returning [`IntegratorError::StepTooLarge`] otherwise. For τ = exp on
    /// SO(3) this refuses rotations by more than π per step.
    pub check_domain: bool,
}

impl Default for SolverConfig {
    fn default() -> Self {
        Self {
            kind: SolverKind::Newton,
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

/// The operator `δ ↦ ad*_δ μ` (linear in δ; antisymmetric: its transpose is `η ↦ −ad*_η μ`).
pub fn ad_dual_operator<G: LieGroup>(mu: &G::Algebra) -> G::Operator {
    let n = G::dim();
    operator_from_columns::<G>(n, |j| G::ad_dual_apply(&G::Algebra::basis(n, j), mu))
}

/// Solves `r(ξ) = 0` from the guess `xi`, with `jacobian(ξ)` used by [`SolverKind::Newton`].
///
/// Returns the solution and the number of iterations. The residual closure returns an error for
/// non-finite values or points outside τ's domain; those errors are passed on.
pub fn solve<G: LieGroup>(
    config: &SolverConfig,
    step: f64,
    mut xi: G::Algebra,
    mut residual: impl FnMut(&G::Algebra) -> Result<G::Algebra, IntegratorError>,
    mut jacobian: impl FnMut(&G::Algebra) -> G::Operator,
) -> Result<(G::Algebra, usize), IntegratorError> {
    let n = G::dim();
    let mut last_residual = f64::INFINITY;
    for it in 1..=config.max_iterations {
        let r = residual(&xi)?;
        if !r.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "step residual",
            });
        }
        last_residual = r.norm_max();
        let delta = match config.kind {
            SolverKind::FixedPoint => r,
            SolverKind::Newton => newton_update::<G>(step, &jacobian(&xi), &r)?,
            SolverKind::NewtonFiniteDifference => {
                let scale = xi.norm_max().max(f64::MIN_POSITIVE.sqrt());
                // Central differences: error O(δ²) + O(ε/δ); δ = ε^{1/3} ‖ξ‖ balances them.
                let d = 6.055e-6 * scale;
                let mut err = None;
                let j = operator_from_columns::<G>(n, |k| {
                    let e = G::Algebra::basis(n, k);
                    let plus = residual(&xi.axpy(d, &e));
                    let minus = residual(&xi.axpy(-d, &e));
                    match (plus, minus) {
                        (Ok(p), Ok(m)) => p.sub(&m).scale(0.5 / d),
                        (Err(e), _) | (_, Err(e)) => {
                            err = Some(e);
                            G::Algebra::zeros(n)
                        }
                    }
                });
                if let Some(e) = err {
                    return Err(e);
                }
                newton_update::<G>(step, &j, &r)?
            }
        };
        xi = xi.sub(&delta);
        if !xi.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "solver iterate ξ",
            });
        }
        let dn = delta.norm_max();
        if dn == 0.0 || dn <= config.tolerance * xi.norm_max() {
            return Ok((xi, it));
        }
    }
    Err(IntegratorError::NoConvergence {
        iterations: config.max_iterations,
        residual: last_residual,
    })
}

fn newton_update<G: LieGroup>(
    step: f64,
    j: &G::Operator,
    r: &G::Algebra,
) -> Result<G::Algebra, IntegratorError> {
    let inv = j
        .try_inverse()
        .ok_or_else(|| IntegratorError::StepTooLarge {
            step,
            reason: "the Newton matrix of the step equations is singular".into(),
        })?;
    Ok(inv.apply(r))
}

/// Checks that ξ lies where τ is invertible, `τ⁻¹(τ(ξ)) = ξ` to `1e-8 (1 + ‖ξ‖)`; a failure is
/// [`IntegratorError::StepTooLarge`] (for τ = exp on SO(3): a rotation by more than π in one step).
pub fn check_tau_domain<G: LieGroup, T: lie_groups::Tau<G>>(
    xi: &G::Algebra,
    step: f64,
) -> Result<(), IntegratorError> {
    let back = T::tau_inv(&T::tau(xi)).map_err(|e| IntegratorError::StepTooLarge {
        step,
        reason: format!("τ = {} cannot be inverted at the step's ξ: {e}", T::NAME),
    })?;
    let err = back.sub(xi).norm_max();
    if err <= 1e-8 * (1.0 + xi.norm_max()) {
        Ok(())
    } else {
        Err(IntegratorError::StepTooLarge {
            step,
            reason: format!(
                "ξ = {:?} (‖ξ‖ = {:.3e}) leaves the domain where τ = {} is invertible",
                xi.to_vec(),
                xi.norm(),
                T::NAME
            ),
        })
    }
}
