//! The cotangent-lift (Lie–Poisson) integrator, eq. (19) of the paper, for any discretization map
//! `R̃_d(g, ξ) = (g a(ξ), g b(ξ))` ([`discretization::Discretization`]); [`LiePoisson`] is the one of
//! the paper's θ-map `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))`, θ ∈ [0, 1]. The derivation below is
//! written for the θ-map; for any a, b replace `τ(−θξ)` by a(ξ), `τ((1−θ)ξ)` by b(ξ),
//! `−θ d^Lτ_{−θξ}` by `d^L a_ξ` and `(1−θ) d^Lτ_{(1−θ)ξ}` by `d^L b_ξ`.
//!
//! ## Derivation (composing α̃, T*R̃_d⁻¹ and Φ̃ as in §4)
//! Write `ḡ = g_k τ(θξ)` for the base point, so that `g_k = ḡ τ(−θξ)` and
//! `g_{k+1} = ḡ τ((1−θ)ξ)`. Varying (ḡ, ξ) by (ḡ η, δξ):
//! `g_k⁻¹ δg_k = Ad_{τ(θξ)} η − θ d^Lτ_{−θξ} δξ`,
//! `g_{k+1}⁻¹ δg_{k+1} = Ad_{τ(−(1−θ)ξ)} η + (1−θ) d^Lτ_{(1−θ)ξ} δξ`.
//! So a covector `(P_k, P_{k+1})` of G × G (left-trivialized) pulls back to
//! `p_g = Ad*_{τ(θξ)} P_k + Ad*_{τ(−(1−θ)ξ)} P_{k+1}`,
//! `p_ξ = −θ d^{L*}τ_{−θξ} P_k + (1−θ) d^{L*}τ_{(1−θ)ξ} P_{k+1}`.
//! The trivialization of T*(G ⋉ 𝔤) adds `ad*_ξ p_ξ` to the first slot and α̃⁻¹ subtracts it
//! again, so the point of TT*G is `(ḡ, μ̄ = p_ξ; ξ, ν = p_g)` with ν = μ̇ − ad*_ξ μ the trivialized
//! momentum velocity. The twist is `Φ̃: (P_k, P_{k+1}) = (−μ_k, μ_{k+1})` — the opposite of the
//! sign printed in §4, which runs the reconstruction backwards (NOTES.md, slip 2; the tests
//! `lie_poisson_*_converges_*` pin this sign). Setting `(ξ, ν) = h X̃(ḡ, μ̄)` with
//! `X̃(g, μ) = (∂h/∂μ, F(g))`, `F = −T*_e L_g dV`, gives the scheme
//!
//! ```text
//! μ̄       = θ d^{L*}τ_{−θξ} μ_k + (1−θ) d^{L*}τ_{(1−θ)ξ} μ_{k+1}
//! ξ       = h ∂h/∂μ(μ̄)                                   (n implicit equations for ξ)
//! μ_{k+1} = Ad*_{τ((1−θ)ξ)} (Ad*_{τ(θξ)} μ_k + h F(g_k τ(θξ)))
//! g_{k+1} = g_k τ(θξ) τ((1−θ)ξ)
//! ```
//!
//! For θ = 0 this is NOTES.md's corrected §4 scheme. Without a potential,
//! `μ_{k+1} = Ad*_{g_k⁻¹ g_{k+1}} μ_k` stays on the coadjoint orbit of μ_k, so Casimirs are conserved
//! to round-off, and the μ-equation does not involve g (reconstruction is optional). Using
//! `d^{R*}τ_ξ = d^{L*}τ_ξ Ad*_{τ(ξ)}`, the schemes for θ = 0 and θ = 1 coincide without a
//! potential. Measured orders: see the crate page.
//!
//! ## Your own map
//! A map given by its factors ([`discretization::Discretization`], with an empty
//! `impl LiftedMap<G>`) is integrated by [`CotangentLiftIntegrator::with_map`]: every piece of
//! the step comes from the composition of the paper's lifts, and `info()` reports the order and
//! symmetry the map has (`tests/methods/user_map.rs` fits them for maps outside the θ-family):
//!
//! ```
//! use discretization::{Discretization, LiftedMap};
//! use integrators::{CotangentLiftIntegrator, Integrator};
//! use lie_groups::{CayleyGroup, LieGroup, So3};
//! use mechanics::RigidBody;
//! use nalgebra::Vector3;
//!
//! /// `R̃_d(g, ξ) = (g exp(−ξ/3), g cay(2ξ/3))`: two different τ.
//! #[derive(Debug, Clone, Copy)]
//! struct ExpCayley;
//! impl Discretization<So3> for ExpCayley {
//!     fn first_factor(&self, xi: &Vector3<f64>) -> So3 {
//!         So3::exp(&(xi / -3.0))
//!     }
//!     fn second_factor(&self, xi: &Vector3<f64>) -> So3 {
//!         So3::cay(&(xi * (2.0 / 3.0)))
//!     }
//! }
//! impl LiftedMap<So3> for ExpCayley {}
//!
//! let body = RigidBody::principal([1.0, 2.0, 3.0])?;
//! let pi0 = Vector3::new(0.5, 1.0, 0.2);
//! let mut lp = CotangentLiftIntegrator::with_map(body, ExpCayley, pi0, Some(So3::identity()))?;
//! for _ in 0..100 {
//!     lp.step(0.01)?;
//! }
//! assert!((lp.casimir().unwrap() - pi0.norm_squared()).abs() < 1e-14);
//! // without a potential the step sees only c(η) = exp(η/3) cay(2η/3), reversible:
//! let info = lp.info();
//! assert!(info.symmetric && info.order == 2);
//! # Ok::<(), integrators::IntegratorError>(())
//! ```
//!
//! The Newton Jacobian of the ξ-equation differentiates μ̄ through
//! `D(ζ; μ) = ∂/∂ζ (d^{L*}τ_ζ μ)` ([`lie_groups::Tau::dtau_left_dual_derivative`]): exact on SO(3)
//! for exp and Cayley (with the step's O(h³) predictor and the default simplified Newton,
//! 2 iterations per step up to h = 0.1 on the free rigid body; the leading-term approximation
//! `−½ ad*_{(·)} μ`, which remains the default for other groups, keeps J exact up to O(h²) and
//! needed 5–6); the force's derivative is dropped (see [`crate::solver`]).

use crate::checks::{check_state, check_theta, step_too_large};
use crate::compensated::two_sum;
use crate::solver::{solve, Scales, Solution};
use crate::step_state::{state_accessors, StepState};
use crate::system::force;
use crate::WarmStart;
use crate::{Integrator, IntegratorError, SolverConfig, System};
use discretization::{DiscretizationMap, LiftedMap, ThetaFamily};
use lie_groups::{LieGroup, Operator, Vector};

/// The Lie–Poisson integrator (eq. 19) on G for the left-trivialized discretization map
/// `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))` with τ map `T`: the [`CotangentLiftIntegrator`] of
/// [`DiscretizationMap<T>`].
///
/// ```
/// use integrators::{LiePoisson, Integrator};
/// use mechanics::RigidBody;
/// use lie_groups::{Cayley, So3, LieGroup};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
/// let mut lp = LiePoisson::<So3, Cayley, _>::new(body, 0.5, Vector3::new(1.0, 0.1, 0.5),
///                                               Some(So3::identity())).unwrap();
/// lp.step(0.01).unwrap();
/// assert!((lp.time() - 0.01).abs() < 1e-15);
/// ```
pub type LiePoisson<G, T, S> = CotangentLiftIntegrator<G, DiscretizationMap<T>, S>;

/// The cotangent lift `R̃_d^{T*}` of a discretization map `M` (any [`LiftedMap`]: the θ-maps, or a
/// user's own, see the module page) applied to the Hamiltonian vector field of the system `S`
/// (eq. 19): each step solves
/// `(R̃_d^{T*})⁻¹((g_k, μ_k), (g_{k+1}, μ_{k+1})) = h X̃(ḡ, μ̄)` for the one unknown η = h ∂h/∂μ(μ̄).
/// Every piece of the lift comes from `M`; this type adds the vector field, the solver and the
/// state.
///
/// State: time t, body momentum μ ∈ 𝔤*, and the configuration g ∈ G when it is reconstructed
/// (`None` skips reconstruction; systems with a potential require it).
#[derive(Debug, Clone)]
pub struct CotangentLiftIntegrator<G: LieGroup, M: LiftedMap<G>, S: System<G>> {
    system: S,
    map: M,
    config: SolverConfig,
    mu: G::Algebra,
    /// The rounding error of μ carried to the next step (compensated summation: μ + mu_err is
    /// the sum of the increments to O(ε²)), so that |μ|² does not random-walk either.
    mu_err: G::Algebra,
    /// t, g and g's renormalization (one product a step: g_{k+1} = g_k a(η)⁻¹ b(η) fused).
    state: StepState<G>,
    iterations: usize,
    /// Jacobians evaluated by the last successful step.
    jacobians: usize,
    /// Past solutions and the Newton matrix, for the next step of the same size.
    warm: WarmStart<G>,
}

impl<G: LieGroup, M: LiftedMap<G>, S: System<G>> CotangentLiftIntegrator<G, M, S> {
    /// Builds the integrator of a configured map at t = 0 from μ₀ and optionally g₀, with the
    /// default [`SolverConfig`]: any [`LiftedMap`], a user's own included (see the crate page
    /// of `discretization`). Errors: non-finite μ₀ or g₀, g₀ missing for a system with a
    /// potential, a potential or force with a right-sided map.
    pub fn with_map(
        system: S,
        map: M,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Self, IntegratorError> {
        check_state(&system, &mu0, "momentum μ", g0.as_ref())?;
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
            mu_err: G::Algebra::zeros(G::dim()),
            mu: mu0,
            state: StepState::new(g0, 1),
            iterations: 0,
            jacobians: 0,
            warm: WarmStart::default(),
        })
    }
    /// The integrator of the θ-map of a [`ThetaFamily`] (the paper's
    /// `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))`), as [`Self::with_map`]. Errors: θ ∉ [0, 1], and
    /// those of [`Self::with_map`].
    pub fn new(
        system: S,
        theta: f64,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Self, IntegratorError>
    where
        M: ThetaFamily,
    {
        check_theta(theta)?;
        let map = M::with_theta(theta).map_err(|_| IntegratorError::InvalidTheta { theta })?;
        Self::with_map(system, map, mu0, g0)
    }
    /// Replaces the solver configuration.
    pub fn with_solver(mut self, config: SolverConfig) -> Self {
        self.config = config;
        self.warm.clear();
        self
    }
    /// Resets the state to (t, μ, g), with the checks of [`LiePoisson::new`].
    pub fn reset(&mut self, t: f64, mu: G::Algebra, g: Option<G>) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        check_state(&self.system, &mu, "momentum μ", g.as_ref())?;
        self.state.reset(t, g);
        self.mu = mu;
        self.mu_err = G::Algebra::zeros(G::dim());
        self.warm.clear();
        Ok(())
    }
    /// Sets the time alone (the compensation of μ kept).
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
    /// ([`discretization::Discretization::symmetric`]: the step of the adjoint map at −h undoes
    /// this one), or, without a potential or force, where the step's increment
    /// `c(η) = a(η)⁻¹ b(η)` is reversible
    /// ([`discretization::Discretization::reversible_increment`]): the step then sees c alone
    /// (`μ_{k+1} = Ad*_{c(η)} μ_k`, `μ̄ = d^{L*}c_η μ_{k+1}`) and η ↦ −η solves it backwards.
    /// For the θ-map: θ = ½, or every θ without a potential on exp and Cayley (their factors
    /// commute), measured reversible by `tests/user_map.rs`.
    pub fn is_self_adjoint(&self) -> bool {
        self.map.symmetric()
            || (!self.system.has_potential()
                && !self.system.is_forced()
                && self.map.reversible_increment())
    }
    /// The solver configuration.
    pub fn solver(&self) -> &SolverConfig {
        &self.config
    }
    /// Solver iterations used by the last successful step (0 before the first).
    pub fn last_iterations(&self) -> usize {
        self.iterations
    }
    /// Jacobians of the step equations evaluated by the last successful step: 1 for a cold
    /// start, 0 once the [`WarmStart`] matrix of earlier steps of the same size serves.
    pub fn last_jacobians(&self) -> usize {
        self.jacobians
    }

    /// For a trial ξ (= η, the step's algebra vector): the impulse `ν = h F(ḡ)` at the base
    /// point `ḡ` of `R̃_d(ḡ, ξ)` (formed only for a system with a potential), plus
    /// `h F_ext(t_k + θh, ḡ, ξ/h)` for a forced system (discrete Lagrange–d'Alembert, see
    /// [`crate::forces`]); `None` when there is neither.
    #[inline]
    fn impulse(&self, h: f64, xi: &G::Algebra) -> Option<G::Algebra> {
        if self.system.is_forced() {
            return Some(self.forced_impulse(h, xi));
        }
        self.state
            .g
            .as_ref()
            .filter(|_| self.system.has_potential())
            .and_then(|gk| force(&self.system, Some(&self.map.base_point(gk, xi))))
            .map(|f| f.scale(h))
    }

    /// [`Self::impulse`] of a forced system.
    fn forced_impulse(&self, h: f64, xi: &G::Algebra) -> G::Algebra {
        let gbar = self
            .state
            .g
            .as_ref()
            .filter(|_| self.system.needs_configuration())
            .map(|gk| self.map.base_point(gk, xi));
        let velocity = if h != 0.0 {
            xi.scale(1.0 / h)
        } else {
            self.system.velocity(&self.mu)
        };
        let t = self.state.now() + self.theta() * h;
        let mut f = self.system.external_force(t, gbar.as_ref(), &velocity);
        if let Some(fp) = force(&self.system, gbar.as_ref()) {
            f = f.add(&fp);
        }
        f.scale(h)
    }

    /// For a trial ξ: the impulse ([`Self::impulse`]) and the base momentum μ̄ straight from
    /// μ_k ([`LiftedMap::base_momentum_from_impulse`]): μ_{k+1} is formed once per step, at the
    /// solution ([`LiftedMap::momentum_update`]).
    ///
    /// Inlined whole into the solver's loop, with the map's part
    /// ([`LiftedMap::base_momentum_from_impulse`]): called out of line, ξ and μ_k went through
    /// memory at every residual (see [`crate::solver::solve`]'s loop).
    #[inline(always)]
    fn evaluate(&self, h: f64, xi: &G::Algebra) -> Evaluation<G> {
        let impulse = self.impulse(h, xi);
        // μ_k entry by entry (crate::carried_state): the last step stored it.
        let mu = crate::carried_state::read(&self.mu);
        let bar = self
            .map
            .base_momentum_from_impulse(xi, &mu, impulse.as_ref());
        Evaluation { bar, impulse }
    }

    /// The predictor `ξ⁰ = h ∂h/∂μ(μ_k + ½ h ad*_{v_k} μ_k + (1−θ) h F(g_k))`, v_k = ∂h/∂μ(μ_k).
    ///
    /// Expanding the scheme to first order in h (ξ = h v_k + O(h²), `Ad*_{τ(ζ)} = I + ad*_ζ + O(ζ²)`,
    /// `d^{L*}τ_ζ = I − ½ ad*_ζ + O(ζ²)`) gives `μ_{k+1} = μ_k + h ad*_{v_k} μ_k + h F + O(h²)` and
    /// `μ̄ = θ μ_k + (1−θ) μ_{k+1} + ½(θ² − (1−θ)²) h ad*_{v_k} μ_k + O(h²)`
    /// `  = μ_k + ½ h ad*_{v_k} μ_k + (1−θ) h F + O(h²)`, so ξ⁰ is within O(h³) of the solution
    /// (the plain `h ∂h/∂μ(μ_k)` is only O(h²)), which saves the solver an iteration.
    fn predictor(&self, h: f64) -> G::Algebra {
        let v = self.system.velocity(&self.mu);
        let sign = self.map.side().ad_dual_sign();
        let mut mid = self
            .mu
            .axpy(0.5 * h * sign, &G::ad_dual_apply(&v, &self.mu));
        if let Some(f) = force(&self.system, self.state.g.as_ref()) {
            mid = mid.axpy((1.0 - self.theta()) * h, &f);
        }
        if self.system.is_forced() {
            let f = self
                .system
                .external_force(self.state.now(), self.state.g.as_ref(), &v);
            mid = mid.axpy((1.0 - self.theta()) * h, &f);
        }
        self.system.velocity(&mid).scale(h)
    }

    /// Solves `r(ξ) = ξ − h ∂h/∂μ(μ̄(ξ)) = 0` from the [`WarmStart`] extrapolation of the last
    /// solutions and their Newton matrix when the last steps had size h, else from the
    /// [`Self::predictor`].
    #[inline(always)]
    fn solve_velocity(&mut self, h: f64) -> Result<StepSolution<G>, IntegratorError> {
        let guess = self.warm.predict(h).unwrap_or_else(|| self.predictor(h));
        // The warm matrix is taken out for the solve (which updates it in place) and put back
        // for WarmStart::record; a failed step drops it.
        let prior = self.warm.prior_contraction(h);
        let mut chord = core::mem::take(self.warm.chord(h));
        let solution = solve::<G, _>(
            &self.config,
            h,
            Scales::default,
            // Formed only if the updates stop contracting short of the tolerance.
            || self.amplified_rounding(h),
            guess,
            &mut chord,
            prior,
            // The residual, inlined where the solver calls it: out of line, each call spilled
            // the step's live registers around it.
            #[inline(always)]
            |xi: &G::Algebra| {
                let ev = self.evaluate(h, xi);
                (xi.sub(&self.system.velocity(&ev.bar).scale(h)), ev)
            },
            |xi: &G::Algebra, ev: &Evaluation<G>| self.jacobian(h, xi, ev),
        )?;
        *self.warm.chord(h) = chord;
        Ok(solution)
    }

    /// How far the residual's rounding reaches into the updates ([`solve`]'s `amplified`), at
    /// (g_k, μ_k): `‖ξ‖ (1 + s) + |h|² ‖∂²h/∂μ²‖ (‖F‖ + ‖F_ext‖)` with the stiffness
    /// `s = |h| ‖∂²h/∂μ²‖ ‖μ_k‖`, ‖ξ‖ ≈ |h| ‖∂h/∂μ(μ_k)‖ and max norms (the [`Scales`] are zero:
    /// η = hξ is of the size of its data and not added to a larger state). The residual's
    /// terms are ξ and h ∂h/∂μ(μ̄), with μ̄ = μ_k + O(‖ξ‖ ‖μ_k‖) + the impulse h(F + F_ext): the
    /// part of μ̄ beyond μ_k is rounded at ε(‖ξ‖ ‖μ_k‖ + |h| ‖F + F_ext‖), which the Hessian
    /// carries into ξ; s is also the size of the Newton matrix's term `h ∂²h/∂μ² ∂μ̄/∂ξ`. On the
    /// rod of inertia ratio 10⁶ (s ≈ 10³ at hω = 10⁻³: u₁ = 1/𝕀₁ = 10⁶ times |Π|) that
    /// rounding, amplified by J⁻¹, is above the default tolerance 1e-14 ‖ξ‖, and an iteration
    /// that can resolve ξ no further stops on its cycle instead of running into `NoConvergence`
    /// (`tests/methods/rod_separatrix.rs`); an iteration that still contracts never reads it.
    fn amplified_rounding(&self, h: f64) -> f64 {
        let t = self.state.now();
        let g = self.state.g.as_ref();
        let v = self.system.velocity(&self.mu);
        let xi = h.abs() * v.norm_max();
        let mut impulse = 0.0;
        if let Some(f) = force(&self.system, g) {
            impulse += f.norm_max();
        }
        if self.system.is_forced() {
            impulse += self.system.external_force(t, g, &v).norm_max();
        }
        let scaled_hessian = h.abs() * self.system.hessian_norm(&self.mu);
        xi * (1.0 + scaled_hessian * self.mu.norm_max()) + scaled_hessian * h.abs() * impulse
    }

    /// Jacobian of r(ξ) = ξ − h ∂h/∂μ(μ̄(ξ)) from the [`Self::evaluate`] of the same ξ:
    /// `I − h H(μ̄) ∂μ̄/∂ξ` with the map's [`LiftedMap::base_momentum_derivative`] (exact without a
    /// potential where D τ is exact: exp on every group, Cayley on SO(3), SE(3), SE(2); exact up
    /// to O(h²) otherwise), plus the potential's term [`Self::force_term`].
    fn jacobian(&self, h: f64, xi: &G::Algebra, ev: &Evaluation<G>) -> G::Operator {
        let up = self.map.momentum_update(xi, &self.mu, ev.impulse.as_ref());
        let mut dbar = self.map.base_momentum_derivative(xi, &self.mu, &up);
        if let Some(force) = self.force_term(h, xi) {
            dbar = dbar.add(&force);
        }
        G::Operator::identity(G::dim()).add(&self.system.hessian(&ev.bar).compose(&dbar).scale(-h))
    }

    /// The potential's part of `∂μ̄/∂ξ` through the impulse `ν = h F(ḡ(ξ))`:
    /// `∂μ̄/∂ν · h K(ḡ) · ḡ⁻¹∂ḡ/∂ξ` with K the force's derivative along the group
    /// ([`System::force_derivative`]) — `None` without a potential or g, or where the map does
    /// not give its pieces. (An external force's own derivative is not included.)
    fn force_term(&self, h: f64, xi: &G::Algebra) -> Option<G::Operator> {
        let gk = self
            .state
            .g
            .as_ref()
            .filter(|_| self.system.has_potential())?;
        let dnu = self.map.base_momentum_impulse_derivative(xi)?;
        let dg = self.map.base_point_derivative(xi)?;
        let k = self.system.force_derivative(&self.map.base_point(gk, xi));
        Some(dnu.compose(&k).compose(&dg).scale(h))
    }
}

/// The solver's result for one step: ξ, the last [`Evaluation`] and the Newton matrix.
type StepSolution<G> = Solution<<G as LieGroup>::Algebra, Evaluation<G>>;

/// The quantities of one evaluation of the step map at a trial ξ, shared by the residual and
/// the Newton Jacobian at the same ξ.
struct Evaluation<G: LieGroup> {
    bar: G::Algebra,
    impulse: Option<G::Algebra>,
}

impl<G: LieGroup, M: LiftedMap<G>, S: System<G>> Integrator for CotangentLiftIntegrator<G, M, S> {
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let solution = self.solve_velocity(h)?;
        let xi = solution.xi;
        if self.config.check_domain {
            self.map.check_domain(&xi).map_err(step_too_large(h))?;
        }
        // The new momentum at the solution, with the impulse of the solver's last evaluation
        // when that was at exactly this ξ, else evaluated again (bitwise the same either way).
        let impulse = match solution.evaluation {
            Some(ev) => ev.impulse,
            None => self.impulse(h, &xi),
        };
        let dmu = self.map.momentum_increment(&xi, &self.mu, impulse.as_ref());
        // μ_{k+1} = μ_k + (Δμ + carried error), by TwoSum (Knuth): the new rounding error is kept
        // exactly for the next step (compensated summation, Vilmart 2008).
        let (mu1, err) = two_sum(&self.mu, &dmu.add(&self.mu_err));
        if !mu1.is_finite() || !err.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "momentum μ_{k+1}",
            });
        }
        // g_{k+1}: the second point of R̃_d(ḡ, ξ), ḡ the base point over g_k (in one product).
        let g1 = self
            .state
            .next_configuration(|gk| self.map.next_point(gk, &xi))?;
        self.mu = mu1;
        self.mu_err = err;
        self.state.commit(h, g1);
        self.iterations = solution.iterations;
        self.jacobians = solution.jacobians;
        self.warm.record(
            h,
            self.state.now(),
            &xi,
            solution.contraction.zip(solution.contraction_bound),
            solution.jacobians,
        );
        Ok(())
    }
    state_accessors!(mu);
    fn method_name(&self) -> String {
        format!("lie-poisson({}, theta={})", self.map.label(), self.theta())
    }
    /// From the map and the system: with a potential or force, the map's order
    /// ([`discretization::Discretization::order`]: 2 for θ = ½, else 1); without, the step sees
    /// only the increment c and has at least its order
    /// ([`discretization::Discretization::increment_order`]: 2 for every θ-map); a symmetric
    /// step ([`Self::is_self_adjoint`]) has order at least 2 (`tests/order.rs`,
    /// `tests/potential.rs`, `tests/forces.rs`, `tests/user_map.rs`). Implicit, a Poisson map
    /// keeping μ on its coadjoint orbit and, for an invariant system, the spatial momentum map
    /// `Ad*_{g⁻¹} μ` (g_{k+1} = g_k a(η)⁻¹ b(η) and μ_{k+1} the matching Ad*).
    fn side(&self) -> discretization::Side {
        self.map.side()
    }
    fn info(&self) -> crate::MethodInfo {
        let symmetric = self.is_self_adjoint();
        let free = !(self.system.has_potential() || self.system.is_forced());
        let mut order = self.map.order();
        if free {
            order = order.max(self.map.increment_order());
        }
        if symmetric {
            order = order.max(2);
        }
        crate::MethodInfo {
            order,
            symmetric,
            explicit: false,
            poisson: true,
            casimirs: !self.system.has_potential() && !self.system.is_forced(),
            momentum_map: !self.system.is_forced(),
            energy: false,
            on_group: true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::EulerArnold;
    use lie_groups::{Cayley, ExpMap, So3, Tau};
    use nalgebra::{Matrix3, Vector3};

    /// A heavy top in a few lines (the `mechanics` crate's is out of reach of a unit test):
    /// V(R) = ⟨m g χ, Rᵀe₃⟩, `T*_e L_R dV = m g χ × Rᵀe₃`.
    #[derive(Debug, Clone)]
    struct Top {
        body: EulerArnold<So3>,
        mgchi: Vector3<f64>,
    }

    impl Top {
        fn vertical_in_body(g: &So3) -> Vector3<f64> {
            g.as_matrix().transpose() * Vector3::z()
        }
    }

    impl System<So3> for Top {
        fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
            self.body.hamiltonian(mu)
        }
        fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
            self.body.velocity(mu)
        }
        fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
            self.body.hessian(mu)
        }
        fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
            self.body.momentum(xi)
        }
        fn has_potential(&self) -> bool {
            true
        }
        fn potential(&self, g: &So3) -> f64 {
            self.mgchi.dot(&Self::vertical_in_body(g))
        }
        fn potential_differential(&self, g: &So3) -> Vector3<f64> {
            self.mgchi.cross(&Self::vertical_in_body(g))
        }
    }

    /// |ξ⁰ − ξ*| for the predictor ξ⁰ and the solved ξ* of one step of size h.
    fn predictor_gap<T: Tau<So3>, S: System<So3> + Clone>(
        system: &S,
        theta: f64,
        g0: Option<So3>,
        h: f64,
    ) -> f64 {
        let mut lp =
            LiePoisson::<So3, T, _>::new(system.clone(), theta, Vector3::new(0.5, 1.0, 0.2), g0)
                .unwrap();
        let solved = lp.solve_velocity(h).unwrap().xi;
        (lp.predictor(h) - solved).amax()
    }

    /// The predictor is within O(h³) of the solution for every θ and τ, with and without a force: halving h divides the gap by 2³ (fitted order within [2.8, 3.3]
    /// between h = 0.02 and h = 0.005); the plain predictor h ∂h/∂μ(μ_k) would be O(h²).
    #[test]
    fn predictor_is_third_order_accurate() {
        let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0));
        let body = EulerArnold::<So3>::new(inertia).unwrap();
        let top = Top {
            body: body.clone(),
            mgchi: Vector3::new(0.0, 0.1, 0.5),
        };
        let g0 = So3::exp(&Vector3::new(0.3, -0.5, 0.8));
        for theta in [0.0, 0.3, 0.5, 1.0] {
            let gaps = |h: f64| {
                [
                    predictor_gap::<Cayley, _>(&body, theta, None, h),
                    predictor_gap::<ExpMap, _>(&body, theta, None, h),
                    predictor_gap::<Cayley, _>(&top, theta, Some(g0), h),
                    predictor_gap::<ExpMap, _>(&top, theta, Some(g0), h),
                ]
            };
            let (coarse, fine) = (gaps(0.02), gaps(0.005));
            let names = [
                "free body, cayley",
                "free body, exp",
                "heavy top, cayley",
                "heavy top, exp",
            ];
            for ((name, c), f) in names.iter().zip(coarse).zip(fine) {
                let order = (c / f).log2() / 2.0;
                assert!(
                    (2.8..=3.3).contains(&order),
                    "{name}, θ = {theta}: predictor gap order {order:.3}"
                );
            }
        }
    }
}
