//! The tangent-lift (Euler–Poincaré) integrator, eq. (18) of the paper: `R̃_d^T = T R̃_d ∘ κ̃` for
//! any discretization map `R̃_d(g, ξ) = (g a(ξ), g b(ξ))` ([`discretization::Discretization`]);
//! [`EulerPoincare`] is the one of the paper's θ-map `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))`,
//! θ ∈ [0, 1]. The derivation below is written for the θ-map; for any a, b replace `τ(−θξ̄)` by
//! a(ξ̄), `τ((1−θ)ξ̄)` by b(ξ̄), `−θ d^Lτ_{−θξ̄}` by `d^L a_ξ̄` and `(1−θ) d^Lτ_{(1−θ)ξ̄}` by `d^L b_ξ̄`.
//! A map of one's own is integrated by [`TangentLiftIntegrator::with_map`] (see the module page
//! of [`crate::lie_poisson`] for how to write one):
//!
//! ```
//! use discretization::{Discretization, LiftedMap};
//! use integrators::{Integrator, TangentLiftIntegrator};
//! use lie_groups::{CayleyGroup, LieGroup, So3};
//! use mechanics::RigidBody;
//! use nalgebra::Vector3;
//!
//! /// `R̃_d(g, ξ) = (g exp(−ξ/4) cay(−ξ/4), g exp(ξ/4) cay(ξ/4))`: equal to its adjoint.
//! #[derive(Debug, Clone, Copy)]
//! struct MixedMidpoint;
//! impl Discretization<So3> for MixedMidpoint {
//!     fn first_factor(&self, xi: &Vector3<f64>) -> So3 {
//!         So3::exp(&(xi * -0.25)).compose(&So3::cay(&(xi * -0.25)))
//!     }
//!     fn second_factor(&self, xi: &Vector3<f64>) -> So3 {
//!         So3::exp(&(xi * 0.25)).compose(&So3::cay(&(xi * 0.25)))
//!     }
//! }
//! impl LiftedMap<So3> for MixedMidpoint {}
//!
//! let body = RigidBody::principal([1.0, 2.0, 3.0])?;
//! let xi0 = Vector3::new(0.5, 0.5, 0.2 / 3.0);
//! let mut ep = TangentLiftIntegrator::with_map(body, MixedMidpoint, xi0, Some(So3::identity()))?;
//! ep.step(0.05)?;
//! ep.step(-0.05)?; // symmetric: back to the start
//! assert!((ep.velocity() - xi0).amax() < 1e-14);
//! assert!(ep.info().symmetric && ep.info().order == 2 && !ep.info().explicit);
//! # Ok::<(), integrators::IntegratorError>(())
//! ```
//!
//! ## Derivation
//! A point `(g, ξ; ξ̄, ξ̃)` of TTG ≅ (G ⋉ 𝔤) ⋉ (𝔤 ⋉ 𝔤) is flipped by
//! `κ̃(g, ξ, ξ̄, ξ̃) = (g, ξ̄, ξ, ξ̃ + [ξ, ξ̄])`; undoing the left trivialization of T(G ⋉ 𝔤)
//! (whose second slot is `δξ̄ − ad_{ξ̄} (g⁻¹δg)`) the bracket cancels, and the flipped point is the
//! tangent vector `(g⁻¹δg, δξ̄) = (ξ, ξ̃)` at the base `(g, ξ̄)`. Applying T R̃_d there
//! (same variations as in [`crate::lie_poisson`]) gives
//!
//! ```text
//! g_k     = g τ(−θξ̄),       ξ_k     = Ad_{τ(θξ̄)} ξ − θ d^Lτ_{−θξ̄} ξ̃
//! g_{k+1} = g τ((1−θ)ξ̄),    ξ_{k+1} = Ad_{τ(−(1−θ)ξ̄)} ξ + (1−θ) d^Lτ_{(1−θ)ξ̄} ξ̃.
//! ```
//!
//! The trivialized Euler–Poincaré field is `X̃(g, ξ) = (g, ξ; ξ, f(g, ξ))` with
//! `f(g, ξ) = ξ̇ = ∂²h/∂μ² (ad*_ξ μ + F(g))`, μ = ∂l/∂ξ, F = −T*_e L_g dV. Eq. (18),
//! `(ξ̄, ξ̃) = h (ξ, f(g, ξ))`, then reads, with unknown base velocity ξ and ḡ = g_k τ(θhξ):
//!
//! ```text
//! ξ_k     = Ad_{τ(θhξ)} ξ − θh d^Lτ_{−θhξ} f(ḡ, ξ)         (n implicit equations for ξ)
//! ξ_{k+1} = Ad_{τ(−(1−θ)hξ)} ξ + (1−θ)h d^Lτ_{(1−θ)hξ} f(ḡ, ξ)
//! g_{k+1} = ḡ τ((1−θ)hξ)
//! ```
//!
//! θ = 0 is explicit (ξ = ξ_k, ḡ = g_k). The state is (g, ξ); its momentum is μ = ∂l/∂ξ.
//! Unlike the Lie–Poisson integrator, this one does not keep μ on its coadjoint orbit.
//!
//! ## Increment form
//! The step solves for the increment δ = ξ − ξ_k (O(h)), not for ξ itself (O(1)): with
//! ξ = ξ_k + δ the residual is
//!
//! ```text
//! r(δ) = δ + (Ad_{τ(θhξ)} − I) ξ − θh d^Lτ_{−θhξ} f(ḡ, ξ)      (LiftedMap::first_velocity_increment)
//! ```
//!
//! and the new velocity is `ξ_{k+1} = ξ_k + Δξ`,
//! `Δξ = δ + (Ad_{τ(−(1−θ)hξ)} − I) ξ + (1−θ)h d^Lτ_{(1−θ)hξ} f(ḡ, ξ)`
//! (`LiftedMap::second_velocity_increment`; Δξ is `second − first velocity + r`), added with
//! compensated summation (TwoSum, the rounding error carried to the next step) as the
//! Lie–Poisson step adds its Δμ. Every term is O(h) and formed without a term of size |ξ|, so
//! the residual rounds at ε·h|ξ|² instead of ε|ξ|, and the solver's relative tolerance applies
//! to δ. The Ad terms vanish along η = hξ where τ(shξ) commutes with ξ (exp and Cayley,
//! `Tau::COMMUTES_WITH_ARGUMENT`) and are then not formed; for another τ they come from
//! `Tau::tau_adjoint_increment`, with no term of size |ξ| either. Solving for δ rather than
//! for ξ itself also lets the warm start's guess be accepted more often: fewer residuals per step.
//!
//! Where δ itself vanishes — a sphere, a principal-axis rotation, forces in balance — its
//! residual is still rounded at ε times the data it is formed from,
//! `θ|h| (‖ξ‖² + ‖∂²h/∂μ²‖ (‖ξ‖‖μ‖ + ‖F‖ + ‖F_ext‖))` at (g_k, ξ_k): the `scale` the solver
//! takes as its rounding floor (see [`crate::solver::solve`]; formed only by a step that does not
//! stop on its tolerance at once), without which such steps were refused
//! (tests/error_floor.rs). The Newton matrix is ∂r/∂δ = ∂r/∂ξ, exact for a quadratic
//! Hamiltonian where τ's second derivatives are (see [`TangentLiftIntegrator`]'s `jacobian`):
//! with its former O(h²) error the iteration contracted by only ~1e-5 at h ≈ 0.02 and stopped
//! with errors of the tolerance's size, of one sign from step to step.
//!
//! Solved for ξ itself, with the tolerance 1e-14|ξ| and whole-vector velocities rounded at ε|ξ|,
//! those errors added up over the sub-steps of a composition: Kahan–Li 8 ∘ θ = ½ on the free
//! body stalled at 4.4e-12 (h = 0.1) and 2.4e-12 (h = 0.05), where Lie–Poisson reaches 1e-14
//! and 2e-15; in increment form it reaches 1.0e-14 and 2.5e-15 (`tests/error_floor.rs`).

use crate::checks::{check_state, check_theta, step_too_large};
use crate::compensated::two_sum;
use crate::solver::{solve, Scales};
use crate::step_state::StepState;
use crate::system::force;
use crate::WarmStart;
use crate::{Integrator, IntegratorError, SolverConfig, System};
use discretization::{DiscretizationMap, LiftedMap, ThetaFamily};
use lie_groups::{LieGroup, Operator, Vector};

/// The Euler–Poincaré integrator (eq. 18) on G for the left-trivialized discretization map
/// `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))` with τ map `T`: the [`TangentLiftIntegrator`] of
/// [`DiscretizationMap<T>`].
///
/// ```
/// use integrators::{EulerPoincare, Integrator};
/// use mechanics::RigidBody;
/// use lie_groups::{ExpMap, So3, LieGroup};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
/// let mut ep = EulerPoincare::<So3, ExpMap, _>::new(body, 0.5, Vector3::new(1.0, 0.05, 0.2),
///                                                  Some(So3::identity())).unwrap();
/// ep.step(0.01).unwrap();
/// assert!((ep.time() - 0.01).abs() < 1e-15);
/// ```
pub type EulerPoincare<G, T, S> = TangentLiftIntegrator<G, DiscretizationMap<T>, S>;

/// The tangent lift `R̃_d^T` of a discretization map `M` (any [`LiftedMap`]: the θ-maps, or a
/// user's own, see the module page) applied to the Euler–Poincaré vector field of the system `S`
/// (eq. 18): each step solves
/// `R̃_d^T(ḡ, ξ, hξ, h f(ḡ, ξ))₁ = (g_k, ξ_k)` for the base velocity ξ — in increment form, for
/// δ = ξ − ξ_k (see the module page) — and reads `(g_{k+1}, ξ_{k+1})` from the second point.
/// Every piece of the lift comes from `M`; this type adds the vector field, the solver and the
/// state.
///
/// State: time t, body velocity ξ ∈ 𝔤 (with the rounding error of its last compensated sum),
/// and the configuration g when it is reconstructed.
#[derive(Debug, Clone)]
pub struct TangentLiftIntegrator<G: LieGroup, M: LiftedMap<G>, S: System<G>> {
    system: S,
    map: M,
    config: SolverConfig,
    xi: G::Algebra,
    /// The rounding error of ξ carried to the next step (compensated summation: ξ + xi_err is
    /// the sum of the increments to O(ε²)).
    xi_err: G::Algebra,
    /// t, g and g's renormalization (one product a step).
    state: StepState<G>,
    iterations: usize,
    /// Jacobians evaluated by the last successful step.
    jacobians: usize,
    /// Past solutions and the Newton matrix, for the next step of the same size.
    warm: WarmStart<G>,
}

impl<G: LieGroup, M: LiftedMap<G>, S: System<G>> TangentLiftIntegrator<G, M, S> {
    /// Builds the integrator of a configured map at t = 0 from the body velocity ξ₀ and
    /// optionally g₀: any [`LiftedMap`], a user's own included (see the crate page of
    /// `discretization`). Errors: non-finite ξ₀ or g₀, g₀ missing for a system with a
    /// potential, a potential or force with a right-sided map.
    pub fn with_map(
        system: S,
        map: M,
        xi0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Self, IntegratorError> {
        check_state(&system, &xi0, "velocity ξ", g0.as_ref())?;
        if map.side() == discretization::Side::Right
            && (system.has_potential() || system.is_forced())
        {
            return Err(IntegratorError::InvalidParameter {
                reason: "the right-trivialized integrators take right-invariant systems: no \
                         potential V(g) and no external force"
                    .into(),
            });
        }
        Ok(Self {
            system,
            map,
            config: SolverConfig::default(),
            xi_err: G::Algebra::zeros(G::dim()),
            xi: xi0,
            state: StepState::new(g0, 1),
            iterations: 0,
            jacobians: 0,
            warm: WarmStart::default(),
        })
    }
    /// The integrator of the θ-map of a [`ThetaFamily`] at t = 0 from the body velocity ξ₀ and
    /// optionally g₀, as [`Self::with_map`]. Errors: θ ∉ [0, 1], and those of
    /// [`Self::with_map`].
    pub fn new(
        system: S,
        theta: f64,
        xi0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Self, IntegratorError>
    where
        M: ThetaFamily,
    {
        check_theta(theta)?;
        let map = M::with_theta(theta).map_err(|_| IntegratorError::InvalidTheta { theta })?;
        Self::with_map(system, map, xi0, g0)
    }
    /// Builds the integrator from the momentum μ₀ (ξ₀ = ∂h/∂μ(μ₀)).
    pub fn from_momentum(
        system: S,
        theta: f64,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Self, IntegratorError>
    where
        M: ThetaFamily,
    {
        check_state(&system, &mu0, "momentum μ", g0.as_ref())?;
        let xi0 = system.velocity(&mu0);
        Self::new(system, theta, xi0, g0)
    }
    /// Replaces the solver configuration.
    pub fn with_solver(mut self, config: SolverConfig) -> Self {
        self.config = config;
        self.warm.clear();
        self
    }
    /// Resets the state to (t, ξ, g), with the checks of [`EulerPoincare::new`].
    pub fn reset(&mut self, t: f64, xi: G::Algebra, g: Option<G>) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        check_state(&self.system, &xi, "velocity ξ", g.as_ref())?;
        self.state.reset(t, g);
        self.xi = xi;
        self.xi_err = G::Algebra::zeros(G::dim());
        self.warm.clear();
        Ok(())
    }
    /// Sets the time alone (the compensation of ξ and the warm start kept).
    pub(crate) fn set_time_only(&mut self, t: f64) {
        self.state.t.set(t);
    }
    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }
    /// θ.
    pub fn theta(&self) -> f64 {
        self.map.theta()
    }
    /// The discretization map.
    pub fn map(&self) -> &M {
        &self.map
    }
    /// Whether the step is its own adjoint, Φ_{−h} = Φ_h⁻¹: where the map equals its adjoint
    /// ([`discretization::Discretization::symmetric`]; θ = ½ for the θ-map).
    pub fn is_self_adjoint(&self) -> bool {
        self.map.symmetric()
    }
    /// Solver iterations used by the last successful step (0 for θ = 0 or before the first).
    pub fn last_iterations(&self) -> usize {
        self.iterations
    }
    /// Jacobians of the step equations evaluated by the last successful step: 1 for a cold
    /// start, 0 once the [`WarmStart`] matrix of earlier steps of the same size serves.
    pub fn last_jacobians(&self) -> usize {
        self.jacobians
    }

    /// `f(t, g, ξ) = ∂²h/∂μ² (ad*_ξ μ + F(g) + F_ext(t, g, ξ))`, μ = ∂l/∂ξ: the Euler–Poincaré
    /// vector field (F_ext only for a forced system, see [`crate::forces`]).
    #[inline]
    fn field(&self, t: f64, g: Option<&G>, xi: &G::Algebra) -> G::Algebra {
        let mu = self.system.momentum(xi);
        let mut rhs = G::ad_dual_apply(xi, &mu).scale(self.map.side().ad_dual_sign());
        if let Some(f) = force(&self.system, g) {
            rhs = rhs.add(&f);
        }
        if self.system.is_forced() {
            rhs = rhs.add(&self.system.external_force(t, g, xi));
        }
        self.system.hessian(&mu).apply(&rhs)
    }

    /// The size of the data [`Self::field`] is formed from,
    /// `‖∂²h/∂μ²‖ (‖ξ‖ ‖μ‖ + ‖F‖ + ‖F_ext‖)` (max norms): f is rounded at ε times that size even
    /// where f itself vanishes — a sphere, a principal-axis rotation, forces in balance.
    fn data_size(&self, t: f64, g: Option<&G>, xi: &G::Algebra) -> f64 {
        let mu = self.system.momentum(xi);
        let mut data = xi.norm_max() * mu.norm_max();
        if let Some(f) = force(&self.system, g) {
            data += f.norm_max();
        }
        if self.system.is_forced() {
            data += self.system.external_force(t, g, xi).norm_max();
        }
        self.system.hessian(&mu).norm_max() * data
    }

    /// The quantities of the step at a trial increment δ: ξ = ξ_k + δ, the base point ḡ over g_k
    /// of `R̃_d(ḡ, hξ)` (formed only when g is reconstructed and the field reads it) and
    /// ζ = h f(t_k + θh, ḡ, ξ).
    #[inline]
    fn evaluate(&self, h: f64, delta: &G::Algebra) -> Evaluation<G> {
        let xi = self.xi.add(delta);
        let gbar = self
            .state
            .g
            .as_ref()
            .filter(|_| self.system.needs_configuration())
            .map(|gk| self.map.base_point(gk, &xi.scale(h)));
        let zeta = self
            .field(self.state.now() + self.theta() * h, gbar.as_ref(), &xi)
            .scale(h);
        Evaluation { xi, gbar, zeta }
    }

    /// `r(δ) = δ + (ξ_k-component of R̃_d^T(ḡ, ξ, hξ, ζ) − ξ)`
    /// ([`LiftedMap::first_velocity_increment`]) = ξ_k-component − ξ_k, for ξ = ξ_k + δ.
    #[inline]
    fn residual(&self, h: f64, delta: &G::Algebra, ev: &Evaluation<G>) -> G::Algebra {
        delta.add(&self.map.first_velocity_increment(h, &ev.xi, &ev.zeta))
    }

    /// ∂r/∂δ = ∂r/∂ξ = `A + B h ∂f/∂ξ` with the map's [`LiftedMap::first_velocity_derivative`]
    /// (A, B) at this evaluation's ζ and
    /// `∂f/∂ξ = H (M(μ) + ad_ξᵀ H⁻¹ + K(ḡ) ḡ⁻¹∂ḡ/∂ξ)`, H = ∂²h/∂μ², M(μ) = (δ ↦ ad*_δ μ),
    /// K = ∂F(ḡ exp ζ)/∂ζ ([`System::force_derivative`], with a potential and g) and
    /// `ḡ⁻¹∂ḡ/∂ξ = h · ḡ⁻¹∂ḡ/∂η` ([`LiftedMap::base_point_derivative`]): exact for a quadratic
    /// Hamiltonian where τ's second derivatives are (exp on every group, Cayley on SO(3), SE(3),
    /// SE(2)); it drops ∂H/∂μ and an external force's own derivative.
    fn jacobian(&self, h: f64, ev: &Evaluation<G>) -> G::Operator {
        let xi = &ev.xi;
        let (a, b) = self.map.first_velocity_derivative(h, xi, &ev.zeta);
        let mu = self.system.momentum(xi);
        let hess = self.system.hessian(&mu);
        let mut rhs = G::ad_dual_operator(&mu);
        if let Some(hinv) = hess.try_inverse() {
            rhs = rhs.add(&G::ad(xi).transpose().compose(&hinv));
        }
        rhs = rhs.scale(self.map.side().ad_dual_sign());
        if let Some(gbar) = ev.gbar.as_ref().filter(|_| self.system.has_potential()) {
            if let Some(dg) = self.map.base_point_derivative(&xi.scale(h)) {
                rhs = rhs.add(&self.system.force_derivative(gbar).compose(&dg).scale(h));
            }
        }
        a.add(&b.compose(&hess.compose(&rhs)).scale(h))
    }
}

/// One evaluation of the step at a trial increment δ, shared by the residual, the Newton matrix
/// and (at the solution) the new state.
struct Evaluation<G: LieGroup> {
    /// ξ = ξ_k + δ, the base velocity.
    xi: G::Algebra,
    /// ḡ, when formed.
    gbar: Option<G>,
    /// ζ = h f(t_k + θh, ḡ, ξ).
    zeta: G::Algebra,
}

impl<G: LieGroup, M: LiftedMap<G>, S: System<G>> Integrator for TangentLiftIntegrator<G, M, S> {
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let theta = self.theta();
        let (delta, ev, iterations, jacobians, contraction) = if self.map.base_is_first_point() {
            let delta = G::Algebra::zeros(G::dim());
            let ev = self.evaluate(h, &delta);
            (delta, ev, 0, 0, Some((0.0, 0.0)))
        } else {
            // Taken out for the solve (updated in place), put back for WarmStart::record.
            let prior = self.warm.prior_contraction(h);
            let mut chord = core::mem::take(self.warm.chord(h));
            let evaluate = |d: &G::Algebra| {
                let ev = self.evaluate(h, d);
                (self.residual(h, d, &ev), ev)
            };
            // Predictor δ⁰ = θh f(g_k, ξ_k): r(δ) = δ − θh f + O(h²) at δ = O(h), so δ⁰ is within
            // O(h²) of the solution (δ = 0 is O(h)). After six steps of this size: the
            // WarmStart extrapolation of the past increments, O(h⁷).
            let guess = self.warm.predict(h).unwrap_or_else(|| {
                self.field(self.state.now(), self.state.g.as_ref(), &self.xi)
                    .scale(theta * h)
            });
            // The residual's terms are rounded at ε·θ|h| (‖ξ‖² + the field's data) even where δ
            // itself vanishes (the Ad terms of a τ that does not commute with its argument, the
            // field's own rounding): the solver's floor. And δ is added to ξ_k: where the
            // residual's own noise stops the iteration (a finite-difference Hessian), it is
            // accepted below √ε ‖ξ_k‖. Formed only if a step needs them.
            let scales = || {
                let xn = self.xi.norm_max();
                Scales {
                    data: theta
                        * h.abs()
                        * (xn * xn
                            + self.data_size(self.state.now(), self.state.g.as_ref(), &self.xi)),
                    state: xn,
                }
            };
            let solution = solve::<G, _>(
                &self.config,
                h,
                scales,
                || 0.0,
                guess,
                &mut chord,
                prior,
                evaluate,
                |_, ev| self.jacobian(h, ev),
            )?;
            *self.warm.chord(h) = chord;
            // The last evaluation when it was at exactly the solution, else evaluated again.
            let ev = match solution.evaluation {
                Some(ev) => ev,
                None => self.evaluate(h, &solution.xi),
            };
            (
                solution.xi,
                ev,
                solution.iterations,
                solution.jacobians,
                solution.contraction.zip(solution.contraction_bound),
            )
        };
        let eta = ev.xi.scale(h);
        if self.config.check_domain {
            self.map.check_domain(&eta).map_err(step_too_large(h))?;
        }
        // ξ_{k+1} = ξ_k + Δξ, Δξ = δ + (second velocity of R̃_d^T(ḡ, ξ, η, ζ) − ξ), by TwoSum with
        // the carried error (compensated summation, as Lie–Poisson's μ).
        let dxi = delta.add(&self.map.second_velocity_increment(h, &ev.xi, &ev.zeta));
        let (xi1, err) = two_sum(&self.xi, &dxi.add(&self.xi_err));
        if !xi1.is_finite() || !err.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "velocity ξ_{k+1}",
            });
        }
        // g_{k+1} from ḡ when it was formed, else in one product from g_k.
        let g1 = self.state.next_configuration(|gk| match &ev.gbar {
            Some(gb) => self.map.second_point(gb, &eta),
            None => self.map.next_point(gk, &eta),
        })?;
        self.xi = xi1;
        self.xi_err = err;
        self.state.commit(h, g1);
        self.iterations = iterations;
        self.jacobians = jacobians;
        self.warm
            .record(h, self.state.now(), &delta, contraction, jacobians);
        Ok(())
    }
    fn time(&self) -> f64 {
        self.state.now()
    }
    fn momentum(&self) -> G::Algebra {
        self.system.momentum(&self.xi)
    }
    fn velocity(&self) -> G::Algebra {
        self.xi.clone()
    }
    fn momentum_rate(&self) -> G::Algebra {
        crate::dense_output::momentum_rate_on(
            self.map.side(),
            &self.system,
            self.time(),
            &self.momentum(),
            self.configuration(),
        )
    }
    fn configuration(&self) -> Option<&G> {
        self.state.g.as_ref()
    }
    fn energy(&self) -> f64 {
        self.system.energy(&self.momentum(), self.state.g.as_ref())
    }
    fn casimir(&self) -> Option<f64> {
        self.system.casimir(&self.momentum())
    }
    fn method_name(&self) -> String {
        format!(
            "euler-poincare({}, theta={})",
            self.map.label(),
            self.theta()
        )
    }
    /// From the map: its order ([`discretization::Discretization::order`]: 2 for θ = ½, else 1;
    /// `tests/order.rs`, `tests/user_map.rs`) and symmetry (symmetric where the map equals its
    /// adjoint); explicit where the base point is the first point (θ = 0). A variational
    /// integrator: symplectic in (g, ξ) through the discrete Legendre map, but μ = ∂l/∂ξ leaves
    /// its coadjoint orbit (Casimirs are not kept).
    fn side(&self) -> discretization::Side {
        self.map.side()
    }
    fn info(&self) -> crate::MethodInfo {
        let symmetric = self.is_self_adjoint();
        crate::MethodInfo {
            order: if symmetric {
                self.map.order().max(2)
            } else {
                self.map.order()
            },
            symmetric,
            explicit: self.map.base_is_first_point(),
            poisson: false,
            casimirs: false,
            momentum_map: false,
            energy: false,
            on_group: true,
        }
    }
}
