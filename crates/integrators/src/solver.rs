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
//!   ([`crate::WarmStart`]): from the quintic extrapolation of the last six solutions (O(h⁶)
//!   relative) with the previous step's J⁻¹ and its contraction prior, mostly one residual and no
//!   Jacobian (measured 1.16 residuals and 1e-4 Jacobians per step for Lie–Poisson on the free
//!   body at h = 0.01, 1.23 for Euler–Poincaré).
//! - [`SolverKind::Newton`]: `ξ ← ξ − J(ξ)⁻¹ r(ξ)` with the analytic Jacobian J re-assembled at every
//!   iterate by the integrator from the operators of the group and the system (Ad, ad*, d^L τ,
//!   ∂²h/∂μ², and the second derivative `D(ζ; μ) = ∂/∂ζ (d^{L*}τ_ζ μ)` from
//!   [`lie_groups::Tau::dtau_left_dual_derivative`]). D is exact for τ = exp on every group (a
//!   series, [`lie_groups::LieGroup::dexp_left_dual_derivative`]) and for Cayley on SO(3), SE(3)
//!   and SE(2) (closed forms): there the Lie–Poisson Jacobian of a system without potential is
//!   exact and Newton converges quadratically — on the free SE(3) body at h = 0.1, 3.0 iterations
//!   per step, as many as Newton on a central-difference Jacobian (with D's first-order term
//!   alone the convergence is only linear; `tests/methods/newton_jacobian.rs`). Elsewhere (Cayley on SO(n), GL(n), a user's τ)
//!   D is its leading term `δ ↦ −½ ad*_δ μ` and J is exact up to O(h²). With a potential the
//!   Lie–Poisson matrix includes the force's term `∂μ̄/∂ν · h K(ḡ) · ∂ḡ/∂ξ`
//!   ([`crate::System::force_derivative`], central differences unless the system gives it): the
//!   heavy top at h = 0.1 takes 2.8 Newton iterations per step, as with a finite-difference
//!   Jacobian (5.4 without the term). An external force's derivative is not included. The
//!   Euler–Poincaré Jacobian differentiates d^Lτ through `E(ξ; v) = ∂/∂ξ (d^Lτ_ξ v)`
//!   ([`lie_groups::Tau::dtau_left_derivative`], from D by duality) and includes the potential's
//!   term likewise: exact for a quadratic Hamiltonian wherever D is (see
//!   [`crate::euler_poincare`]).
//! - [`SolverKind::NewtonFiniteDifference`]: Newton with J from central differences of r
//!   (2n residual evaluations per iteration): quadratic convergence, a documented fallback for
//!   large steps where an O(h²) Jacobian error matters (groups without closed forms, potentials).
//! - [`SolverKind::FixedPoint`]: `ξ ← ξ − r(ξ)` (J replaced by I), the cheapest iteration; it
//!   contracts by a factor O(h ‖∂²h/∂μ²‖ ‖μ‖).
//!
//! The iteration stops when the estimated error of ξ is within `tolerance · ‖ξ‖_max` (relative, so
//! that |μ| = 1e-8 is solved as accurately as |μ| = 1) — or, for an unknown that may be much
//! smaller than the data it is computed from, within the rounding 8ε·scale of that data (the
//! Euler–Poincaré step solves for the increment ξ̄ − ξ_k, which vanishes where the field does
//! while its residual is still rounded at ε·θh|ξ|²; see [`solve`]): with `ρ = ‖Δξ_k‖/‖Δξ_{k−1}‖ < 1` the
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
    /// of a few ulps. Values below the rounding floor 8ε ≈ 1.8e-15 are taken as that floor: the
    /// iteration stops as converged as floating point allows, rather than cycling between
    /// neighbouring floats into [`IntegratorError::NoConvergence`] with a residual of 1e-16.
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

/// Updates of at most this many ε‖ξ‖ are rounding: they measure no contraction.
const ROUNDING_UPDATES: f64 = 8.0;

/// The relative size, against the state the solution is added to, below which updates that no
/// longer contract are taken as the noise of the residual (√ε: far above rounding, far below any
/// step's own size; see [`solve`]).
const STALLED_NOISE: f64 = 1.4901161193847656e-8;

/// Observed contraction above which [`SolverKind::SimplifiedNewton`] re-evaluates its Jacobian.
const REFRESH_CONTRACTION: f64 = 0.1;

/// The converged ξ of [`solve`].
pub struct Solution<A, E> {
    /// The solution ξ.
    pub xi: A,
    /// The number of iterations (residual evaluations, not counting finite differences).
    pub iterations: usize,
    /// The by-products of the last evaluation when it was made at exactly (bitwise) the returned
    /// ξ — the usual case at convergence, where the last update no longer changes ξ in floating
    /// point — so the caller need not evaluate again.
    pub evaluation: Option<E>,
    /// How many Jacobians were evaluated (0 when a warm [`SolverKind::SimplifiedNewton`] matrix
    /// served the whole iteration).
    pub jacobians: usize,
    /// The largest contraction ‖Δξ_k‖/‖Δξ_{k−1}‖ observed; `None` when the iteration stopped
    /// after its first update, before it could measure one.
    pub contraction: Option<f64>,
    /// An upper bound of the contraction that rounding cannot fake: the largest
    /// `max(‖Δξ_k‖, ε‖ξ‖)/‖Δξ_{k−1}‖` (an update at the rounding of ξ, even a zero one, only
    /// bounds ρ by ε‖ξ‖/‖Δξ_{k−1}‖); what a next step may take as its prior.
    pub contraction_bound: Option<f64>,
}

/// Solves `r(ξ) = 0` from the guess `xi`; [`SolverKind::SimplifiedNewton`] starts from the
/// inverse matrix in `chord` when there is one (a previous step's, see [`crate::WarmStart`]),
/// evaluates J only if there is none or the iteration contracts by less than 0.1, and leaves its
/// final J⁻¹ in `chord` (in place: the matrix is not moved per iteration); the other kinds
/// leave `chord` empty. `prior` is an estimate of the contraction of the matrix in `chord` (from
/// the previous steps that used it, [`crate::WarmStart::prior_contraction`]): with it the first
/// update Δξ₁ leaves an error estimated by `prior/(1 − prior) ‖Δξ₁‖`, so a guess already close
/// enough is accepted after one residual evaluation, and no later update of the same matrix is
/// estimated to contract better than the prior.
///
/// `evaluate(ξ)` returns the residual r(ξ) together with whatever by-products of its evaluation
/// the Jacobian and the caller can reuse; `jacobian(ξ, by-products)` is called by the Newton kinds
/// right after `evaluate` at the same ξ. A non-finite residual (NaN from outside τ's domain,
/// an overflow) is [`IntegratorError::NonFinite`].
///
/// Stopping rule (Hairer & Wanner, *Solving ODEs II*, §IV.8): with the contraction estimate
/// `ρ = ‖Δξ_k‖/‖Δξ_{k−1}‖ < 1`, the error left after the update Δξ_k is at most about
/// `ρ/(1−ρ) ‖Δξ_k‖`; the iteration stops when that estimate (or ‖Δξ_k‖ itself at the first
/// iteration, or when the updates stop contracting at round-off level) is within
/// `max(tolerance · ‖ξ‖_max, 8ε · scales.data)`, or when the update no longer changes ξ in
/// floating point (Δξ = 0 or below half an ulp of ξ), where further iterations would repeat the
/// last one, or when the updates stop contracting (‖Δξ_k‖ ≥ ‖Δξ_{k−1}‖, measured) below
/// √ε · `scales.state`, or below 8ε · `amplified`, where it returns the mean of its last two
/// iterates.
///
/// `scales` gives, for an unknown that may be far smaller than its data (called at most once,
/// and only by a step that does not stop on its tolerance at once), the size of the data the
/// residual is formed from and of the state the solution is added to ([`Scales`]). The tolerance
/// stays relative to ‖ξ‖, but no iteration can resolve ξ better than the rounding of the data,
/// 8ε·data (8 ulps), which is therefore a floor of the stopping test (updates below it measure no
/// contraction, and finite differences step relative to `max(‖ξ‖_max, data)`); and updates that
/// no longer contract have reached the residual's own noise, which no iteration can reduce —
/// rounding, or an approximate derivative inside the residual (Euler–Poincaré's field applies
/// ∂²h/∂μ², a finite-difference Hessian unless the system gives its closed form, ~1e-10
/// relative) — accepted below √ε of the state. An increment that may vanish while its residual
/// still rounds at the data's size passes both (Euler–Poincaré's ξ̄ − ξ_k), without which an
/// increment of 1e-20 against a residual rounded at 1e-18 could never be certified.
///
/// An unknown whose updates the inverse matrix fills with the residual's rounding far above
/// ε‖ξ‖ passes that size as `amplified` (Lie–Poisson's η = hξ on a stiff Hessian: on a
/// thin rod of inertia ratio 10⁶ the updates cycle between two floats 1.35e-14 ‖ξ‖ apart, above
/// the default tolerance; zero for an unknown without). It is called only once the updates stop
/// contracting (at most once), so it costs nothing on the usual path, and an iteration
/// that still contracts runs on to its tolerance however large that size is; a cycle within
/// it straddles the solution, and the mean of its last two iterates is returned (on the rod,
/// 2000 θ = ½ steps forward and back return 3.5× closer to the start than with the last
/// iterate).
#[inline(always)]
#[allow(clippy::too_many_arguments)] // each an independent input: config, h (named by errors), the data's sizes, guess, warm matrix and prior, the two callbacks
pub fn solve<G: LieGroup, E>(
    config: &SolverConfig,
    step: f64,
    scales: impl FnOnce() -> Scales,
    amplified: impl FnOnce() -> f64,
    mut xi: G::Algebra,
    chord: &mut Option<G::Operator>,
    prior: Option<f64>,
    mut evaluate: impl FnMut(&G::Algebra) -> (G::Algebra, E),
    mut jacobian: impl FnMut(&G::Algebra, &E) -> G::Operator,
) -> Result<Solution<G::Algebra, E>, IntegratorError> {
    let n = G::dim();
    let mut scales = Lazy::new(scales);
    let mut amplified = Lazy::new(amplified);
    let mut previous_update = f64::INFINITY;
    let mut contraction = 0.0f64;
    let mut bound = 0.0f64;
    let mut jacobians = 0;
    // Simplified Newton's J⁻¹, kept across iterations (and steps).
    if config.kind != SolverKind::SimplifiedNewton {
        *chord = None;
    }
    // The prior belongs to the matrix it came with: while that matrix serves, no update is
    // estimated to contract better (a ratio of two updates measures the contraction only along
    // the current error, and underestimates it before the iteration is asymptotic); without one,
    // the first update is its own estimate (rate 1).
    // A tolerance below the rounding of ξ cannot be certified by updates that are themselves
    // rounding: it is raised to that floor (ROUNDING_UPDATES ulps), where the iteration is as
    // converged as floating point allows, instead of cycling between neighbouring floats.
    let tolerance = config.tolerance.max(ROUNDING_UPDATES * f64::EPSILON);
    let floor = prior.filter(|_| chord.is_some());
    let mut rate = floor.unwrap_or(1.0);
    // The iterate ξ is the loop's carried value, and no reference to it leaves the inlined code:
    // the finite-difference columns' closure and the Jacobian callback (out of line) get copies.
    // A reference that escapes on any path, even a cold one, makes the compiler keep ξ in memory
    // for the whole loop and reload it with loads wider than its stores, which the processor
    // cannot forward (see `crate::carried_state`); the copies cost nothing on the default path.
    // Inlining the residual whole into this loop pays only once ξ stays in registers.
    for it in 1..=config.max_iterations {
        let (r, by_products) = evaluate(&xi);
        let delta = match config.kind {
            SolverKind::FixedPoint => r,
            SolverKind::Newton => {
                jacobians += 1;
                // A copy of ξ (here and below): see the note above the loop.
                invert::<G>(step, &jacobian(&xi.clone(), &by_products))?.apply(&r)
            }
            SolverKind::SimplifiedNewton => match chord {
                Some(inv) => inv.apply(&r),
                None => {
                    jacobians += 1;
                    chord
                        .insert(invert::<G>(step, &jacobian(&xi.clone(), &by_products))?)
                        .apply(&r)
                }
            },
            SolverKind::NewtonFiniteDifference => {
                let size = xi
                    .norm_max()
                    .max(scales.get().data)
                    .max(f64::MIN_POSITIVE.sqrt());
                // Central differences: error O(δ²) + O(ε/δ); δ = ε^{1/3} ‖ξ‖ balances them.
                let d = 6.055e-6 * size;
                // The columns' closure captures a copy, not ξ itself (the note above the loop).
                let x0 = xi.clone();
                let j = operator_from_columns::<G>(n, |k| {
                    let e = G::Algebra::basis(n, k);
                    let (plus, _) = evaluate(&x0.axpy(d, &e));
                    let (minus, _) = evaluate(&x0.axpy(-d, &e));
                    plus.sub(&minus).scale(0.5 / d)
                });
                // A non-finite J (a trial point where r is not finite) makes ξ non-finite below.
                invert::<G>(step, &j)?.apply(&r)
            }
        };
        let next = xi.sub(&delta);
        // A non-finite residual, Jacobian or update makes the iterate non-finite.
        if !next.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "solver iterate ξ",
            });
        }
        let dn = delta.norm_max();
        if it > 1 {
            rate = dn / previous_update;
            if jacobians == 0 {
                rate = rate.max(floor.unwrap_or(0.0));
            }
            // An update at the rounding of ξ (a few ulps) measures the rounding, not the
            // contraction: it neither counts against the matrix nor claims ρ ≈ 0 for the next
            // step's prior, which gets the bound ρ ≤ max(‖Δξ_k‖, ε‖ξ‖)/‖Δξ_{k−1}‖ instead.
            let rounding = f64::EPSILON * xi.norm_max().max(scales.get().data);
            if dn > ROUNDING_UPDATES * rounding {
                contraction = contraction.max(dn / previous_update);
            }
            bound = bound.max(dn.max(rounding) / previous_update);
        }
        // `unchanged`: ξ is a fixed point of the iteration in floating point, so every further
        // iteration would repeat this one.
        let unchanged = same_bits(&next, &xi);
        xi = next;
        let error_estimate = if rate < 1.0 {
            dn * rate / (1.0 - rate)
        } else {
            dn
        };
        // Below the rounding of the data (ROUNDING_UPDATES ulps of `scales.data`) the residual
        // cannot resolve ξ any better: there the iteration is as converged as floating point
        // allows (iterating on would cycle or creep into NoConvergence where ξ is far smaller than
        // its data). Updates that no longer contract (measured: ‖Δξ_k‖ ≥ ‖Δξ_{k−1}‖) have reached the
        // noise of the residual itself — rounding, or an approximate derivative inside it (a
        // finite-difference Hessian, ~1e-10 relative) — and no further iteration can do better:
        // accepted while that noise is below √ε of the state the solution is added to
        // (`scales.state`).
        let stalled = it > 1 && dn >= previous_update;
        let converged = unchanged
            || error_estimate <= tolerance * xi.norm_max()
            || error_estimate <= ROUNDING_UPDATES * f64::EPSILON * scales.get().data
            || (stalled && dn <= STALLED_NOISE * scales.get().state);
        // Updates that stop contracting within the residual's rounding as the inverse matrix
        // amplifies it (`amplified`) cycle about the solution between floats the residual
        // cannot tell apart: the last two iterates straddle it, and their mean is returned.
        let cycling =
            !converged && stalled && dn <= ROUNDING_UPDATES * f64::EPSILON * amplified.get();
        if cycling {
            xi = xi.axpy(0.5, &delta);
        }
        if converged || cycling {
            return Ok(Solution {
                xi,
                iterations: it,
                evaluation: (unchanged && !cycling).then_some(by_products),
                jacobians,
                contraction: (it > 1).then_some(contraction),
                contraction_bound: (it > 1).then_some(bound),
            });
        }
        if it > 1 && rate > REFRESH_CONTRACTION {
            *chord = None;
        }
        previous_update = dn;
    }
    // The residual at the last iterate, evaluated once more here rather than at every iteration.
    let (r, _) = evaluate(&xi);
    Err(IntegratorError::NoConvergence {
        iterations: config.max_iterations,
        residual: r.norm_max(),
    })
}

/// What an unknown's residual is measured against where its rounding may be far above ε times
/// the unknown: the data it is computed from (Euler–Poincaré's increment δ = ξ̄ − ξ_k, which
/// may vanish; Lie–Poisson's η = hξ, whose residual is formed through the Hessian
/// ∂²h/∂μ²) and the state it is added to (Euler–Poincaré's ξ_k); zero where the unknown is of
/// the size of both. See [`solve`].
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Scales {
    /// The size of the data the residual is formed from: its rounding, 8ε·data, is a floor of
    /// the stopping test, and finite differences step relative to it.
    pub data: f64,
    /// The size of the state the solution is added to: updates that no longer contract are
    /// accepted below √ε · state.
    pub state: f64,
}

/// A value computed at its first use only ([`Scales`], the amplified rounding: most steps stop on
/// their tolerance before needing them).
struct Lazy<T, F> {
    f: Option<F>,
    value: T,
}

impl<T: Copy + Default, F: FnOnce() -> T> Lazy<T, F> {
    #[inline(always)]
    fn new(f: F) -> Self {
        Self {
            f: Some(f),
            value: T::default(),
        }
    }
    #[inline(always)]
    fn get(&mut self) -> T {
        if let Some(f) = self.f.take() {
            self.value = f();
        }
        self.value
    }
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
    /// asks for more than round-off allows, rather than running into the iteration limit.
    #[test]
    fn an_update_that_no_longer_changes_xi_ends_the_iteration() {
        let config = SolverConfig {
            kind: SolverKind::FixedPoint,
            tolerance: 1e-40,
            ..SolverConfig::default()
        };
        let xi0 = Vector3::new(1.0, 1.0, 1.0);
        let evaluate = |xi: &Vector3<f64>| (Vector3::new(1e-30, 0.0, 0.0), *xi);
        let solution = solve::<So3, Vector3<f64>>(
            &config,
            0.1,
            Scales::default,
            || 0.0,
            xi0,
            &mut None,
            None,
            evaluate,
            |_, _| Matrix3::identity(),
        )
        .unwrap();
        assert_eq!(solution.xi, xi0);
        assert_eq!(solution.iterations, 1);
        assert_eq!(solution.evaluation, Some(xi0));
    }

    /// A residual whose rounding never lets the iteration settle: r(ξ) = (ξ − ξ*) + δ sign(ξ − ξ*)
    /// with δ one ulp of ξ* sends ξ* + δ to ξ* − δ and back, forever (the two-float cycle of an
    /// iteration at the rounding floor of its residual). With a tolerance below that floor it ran
    /// into NoConvergence; now it stops there, within two ulps of the solution.
    #[test]
    fn a_tolerance_below_the_rounding_floor_stops_at_the_floor() {
        let target = Vector3::new(1.0, -2.0, 0.5);
        let delta = f64::EPSILON * 2.0;
        let evaluate = |xi: &Vector3<f64>| {
            let d = xi - target;
            (
                d + d.map(|x| delta * if x == 0.0 { 0.0 } else { x.signum() }),
                (),
            )
        };
        for kind in [
            SolverKind::FixedPoint,
            SolverKind::Newton,
            SolverKind::SimplifiedNewton,
        ] {
            let config = SolverConfig {
                kind,
                tolerance: 1e-17,
                ..SolverConfig::default()
            };
            let solution = solve::<So3, ()>(
                &config,
                0.1,
                Scales::default,
                || 0.0,
                target + Vector3::repeat(delta),
                &mut None,
                None,
                evaluate,
                |_, _| Matrix3::identity(),
            )
            .unwrap_or_else(|e| panic!("{kind:?}: {e}"));
            assert!((solution.xi - target).amax() <= 2.0 * delta, "{kind:?}");
        }
    }

    /// An increment whose solution is ~0 while its residual rounds at the size of the data it is
    /// computed from: r(ξ) = (ξ − ξ*) + δ sign(ξ − ξ*) with ξ* = 1e-20 and δ = 1e-18 (the
    /// rounding of data of size 1e-2) cycles between ξ* ± δ. Relative to ‖ξ‖ alone no tolerance
    /// is ever met (NoConvergence after the iteration limit); with the data's size 1e-2 as
    /// `scale` the updates of 2δ are within its rounding floor 8ε · 1e-2 and the iteration stops,
    /// within 2δ of ξ*.
    #[test]
    fn an_increment_at_the_rounding_of_its_data_is_certified_against_the_scale() {
        let target = Vector3::new(1e-20, -1e-20, 0.0);
        let delta = 1e-18;
        let evaluate = |xi: &Vector3<f64>| {
            let d = xi - target;
            (
                d + d.map(|x| delta * if x == 0.0 { 0.0 } else { x.signum() }),
                (),
            )
        };
        let config = SolverConfig {
            kind: SolverKind::FixedPoint,
            ..SolverConfig::default()
        };
        let start = target + Vector3::repeat(delta);
        let run = |scale: f64| {
            solve::<So3, ()>(
                &config,
                0.1,
                || Scales {
                    data: scale,
                    state: 0.0,
                },
                || 0.0,
                start,
                &mut None,
                None,
                evaluate,
                |_, _| Matrix3::identity(),
            )
        };
        assert!(matches!(
            run(0.0),
            Err(IntegratorError::NoConvergence { .. })
        ));
        let solution = run(1e-2).expect("certified against the scale");
        assert!((solution.xi - target).amax() <= 2.0 * delta);
    }

    /// The amplified rounding accepts a cycle only within it: r(ξ) = k(ξ − ξ*) with J = I sends
    /// ξ* + a to ξ* − (k − 1)a, a two-float cycle for k = 2 (the Lie–Poisson step on a thin rod
    /// ends in one, of 1.35e-14 ‖ξ‖, from its residual's rounding amplified by J⁻¹) and a
    /// diverging iteration for k = 3. From a = 2⁻³⁰, far above the floor of amplified 10³
    /// (8ε·10³ = 1.8e-12), both end in NoConvergence, for every kind (the chord refreshed at
    /// every iteration does not help: J = I is wrong); the cycle is accepted against amplified
    /// 10⁷ (floor 1.8e-8), and the mean of its two iterates is ξ* itself.
    #[test]
    fn a_cycle_is_accepted_only_within_the_rounding_floor_of_its_data() {
        let target = Vector3::new(1.0, -2.0, 0.5);
        let a = 2f64.powi(-30);
        let run = |kind: SolverKind, k: f64, data: f64| {
            let config = SolverConfig {
                kind,
                ..SolverConfig::default()
            };
            solve::<So3, ()>(
                &config,
                0.1,
                Scales::default,
                || data,
                target + Vector3::repeat(a),
                &mut None,
                None,
                |xi: &Vector3<f64>| ((xi - target) * k, ()),
                |_, _| Matrix3::identity(),
            )
        };
        for kind in [
            SolverKind::FixedPoint,
            SolverKind::Newton,
            SolverKind::SimplifiedNewton,
        ] {
            for k in [2.0, 3.0] {
                assert!(
                    matches!(
                        run(kind, k, 1e3),
                        Err(IntegratorError::NoConvergence { .. })
                    ),
                    "{kind:?}, k = {k}"
                );
            }
            let solution = run(kind, 2.0, 1e7).unwrap_or_else(|e| panic!("{kind:?}: {e}"));
            assert!(
                (solution.xi - target).amax() <= 4.0 * f64::EPSILON,
                "{kind:?}: {:e}",
                (solution.xi - target).amax()
            );
        }
    }

    /// The amplified rounding does not cut a contracting iteration short: r(ξ) = (ξ − ξ*)/2
    /// (fixed point, contraction ½) from a = 2⁻³⁰ with amplified 10⁷ (8ε·10⁷ = 1.8e-8 > a) runs
    /// on to the tolerance 1e-14 ‖ξ*‖. (Read as a floor of the error estimate, like `data`,
    /// that size stopped the iteration at its first update, 4.7e-10 from ξ*: the gyrostat's
    /// steps lost their reversibility that way.)
    #[test]
    fn a_contracting_iteration_runs_to_its_tolerance_whatever_its_amplified_rounding() {
        let target = Vector3::new(1.0, -2.0, 0.5);
        let config = SolverConfig {
            kind: SolverKind::FixedPoint,
            ..SolverConfig::default()
        };
        let solution = solve::<So3, ()>(
            &config,
            0.1,
            Scales::default,
            || 1e7,
            target + Vector3::repeat(2f64.powi(-30)),
            &mut None,
            None,
            |xi: &Vector3<f64>| ((xi - target) * 0.5, ()),
            |_, _| Matrix3::identity(),
        )
        .unwrap();
        let error = (solution.xi - target).amax();
        assert!(
            error <= 2e-14,
            "{error:e} after {} iterations",
            solution.iterations
        );
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
        let evaluate = |xi: &Vector3<f64>| ((xi - target) * 0.1, ());
        let solution = solve::<So3, ()>(
            &config,
            0.1,
            Scales::default,
            || 0.0,
            Vector3::zeros(),
            &mut None,
            None,
            evaluate,
            |_, _| Matrix3::identity(),
        )
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
