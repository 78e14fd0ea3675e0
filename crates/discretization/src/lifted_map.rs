//! [`LiftedMap`]: the components of the tangent and cotangent lifts of a discretization map that
//! an integrator composes with a vector field — composed from the paper's lifts by default, fused
//! closed forms where a map has them.
//!
//! An integrator of the paper is a lift of a discretization map applied to a vector field:
//! eq. (18) sets `(η, ζ) = h X̃(g, ξ)` in the tangent lift `R̃_d^T(g, ξ, η, ζ)`, eq. (19) sets
//! `(ξ, ν) = h X̃(ḡ, μ̄)` in the inverse cotangent lift `(R̃_d^{T*})⁻¹`, and both solve for the one
//! unknown algebra vector. A step needs the lifts' components separately, evaluated many times
//! per step: this trait names exactly those. The integrators (`integrators::CotangentLiftIntegrator`,
//! `integrators::TangentLiftIntegrator`) are written against it alone.
//!
//! ## The default path: the paper's composition
//! Every method is provided for any [`Discretization`] `R̃_d(g, ξ) = (g a(ξ), g b(ξ))`, composed
//! from its factors and their tangents:
//! - the velocities are the fibres of `R̃_d^T = T R̃_d ∘ κ̃` ([`crate::tangent_lift`]) at
//!   `(e, ξ, η, ζ)`, T R̃_d being the product `(g, ξ̄)·(a(ξ), d^L a_ξ δ)` of TG;
//! - the base momentum is the μ-component of `(R̃_d^{T*})⁻¹ = α̃⁻¹ ∘ T*R̃_d ∘ Φ̃⁻¹`
//!   ([`crate::cotangent_lift_inverse_at`]) at the known `(ḡ, η)`: with `(μ₁, μ₂) = (−μ_k, μ_{k+1})`
//!   from Φ̃, `μ̄ = d^{L*}a_η μ₁ + d^{L*}b_η μ₂ = −d^{L*}a_η μ_k + d^{L*}b_η μ_{k+1}`;
//! - the momentum update solves that lift's ν-component `ν = Ad*_{b⁻¹} μ_{k+1} − Ad*_{a⁻¹} μ_k`
//!   for μ_{k+1}: in T*G it is the product `(g_k, μ_k)·(a(η)⁻¹, ν)·(b(η), 0) = (g_{k+1}, μ_{k+1})`
//!   (`(g, μ)(h, ν) = (gh, Ad*_h μ + ν)`), evaluated in increment form (below);
//! - the points are `ḡ = g_k a(η)⁻¹` and `g_{k+1} = ḡ b(η)`;
//! - the Newton derivatives: `∂μ̄/∂ν = (Ad_b d^L b_η)ᵀ` and `ḡ⁻¹∂ḡ/∂η = −Ad_a d^L a_η` in closed
//!   form; `∂μ̄/∂η` and `∂ξ_k/∂ξ` by five-point differences of the composed components
//!   (≈ 10⁻⁹ relative, see `finite_differences.rs`: Newton's contraction is then that much slower,
//!   its fixed point the same).
//!
//! A right-sided map ([`crate::Side::Right`]) gets its components by the inversion ι(g) = g⁻¹, which
//! carries it onto the left map at −η (see [`crate::RightDiscretizationMap`]): the left components
//! at −η, points multiplied on the left.
//!
//! Precision of the default path. The momentum update and the velocity increments are evaluated in
//! increment form, as the fused θ-forms are: `(Ad*_g − I) μ` and `(Ad_g − I) ξ` for the factors g
//! come from `log g` (`LieGroup::exp_coadjoint_increment`, `exp_adjoint_increment`), rounded
//! relative to their own size, not from g's matrix entries `1 − O(|η|²)`; the integrators add
//! them with compensated summation. So the Casimir |Π|² stays at round-off on the default path
//! too (3.3e-16 relative over 10⁴ steps against 2.2e-16 fused; with Ad* from the matrices it
//! random-walked to 1.4–3.5e-14; `tests/methods/user_map.rs` of `integrators`). Only where log g
//! does not exist (far from e, outside the steps integrators take) is the matrix product used,
//! rounded at ε|μ|.
//!
//! ## The fused overrides
//! [`DiscretizationMap`] (and [`crate::RightDiscretizationMap`] through it) overrides every
//! component with hand-fused θ-formulas: the same compositions written out, in increment form,
//! sharing τ's coefficients, without forming τ where a closed form exists and without allocating.
//! They are what the integrators call for the θ-family; `tests/composed_lift.rs` pins them equal
//! to the default path on every group, τ, θ and side, and [`crate::Composed`] gives the default path of
//! any map, whatever it overrides.
//!
//! Notation (left-trivialized, as in the paper): the map `R̃_d(ḡ, η) = (g_k, g_{k+1})`; covectors
//! μ are body momenta, vectors ξ body velocities; η already contains the step h.

use crate::composed;
use crate::{Discretization, DiscretizationMap};
use core::fmt::Debug;
use lie_groups::{LieGroup, Operator, Tau, Vector};

/// The new momentum of one cotangent-lift step at a trial η (see
/// [`LiftedMap::momentum_update`]).
#[derive(Debug, Clone, PartialEq)]
pub struct MomentumUpdate<A> {
    /// The momentum carried to the base point, `Ad*_{a(η)⁻¹} μ_k` for the left map
    /// (`Ad*_{τ(θη)} μ_k` for the θ-family; what the Newton Jacobian differentiates).
    pub transported: A,
    /// `μ_{k+1}`.
    pub next: A,
    /// `μ_{k+1} − μ_k` before it is rounded into μ_{k+1}: a step adds it to μ_k with compensated
    /// summation.
    pub increment: A,
}

/// The components of the lifts (eqs. 16–17) of a discretization map that a step of eq. (18) or
/// (19) evaluates. Every method is provided, composed from the map's factors (see the module
/// page); a map overrides the ones it has in closed form. A user's map needs only
/// `impl LiftedMap<G> for MyMap {}` after its [`Discretization`].
///
/// Contract, checked by `tests/composed_lift.rs` (fused against composed) and
/// `tests/lifted_map.rs` (against the whole-point lifts and finite differences):
/// - `(base_point(g_k, η), η)` is `R̃_d⁻¹(g_k, second_point(base_point(g_k, η), η))`;
/// - with `u = momentum_update(η, μ_k, ν)`, `(R̃_d^{T*})⁻¹((g_k, μ_k), (g_{k+1}, u.next))` is
///   `(ḡ, base_momentum(η, μ_k, u.next), η, ν)`;
/// - `R̃_d^T(ḡ, ξ, η, ζ)` has body velocities `first_velocity(η, ξ, ζ)` and
///   `second_velocity(η, ξ, ζ)`, and at η = hξ `first_velocity_increment`,
///   `second_velocity_increment` are these less ξ;
/// - the derivatives are those of the named maps, exact where the map has closed forms of its
///   second derivatives, otherwise accurate enough for Newton's convergence (O(|η|²) for the
///   θ-family without closed forms of `∂/∂ζ (d^{L*}τ_ζ μ)`, ≈ 10⁻⁹ by differences on the
///   default path).
pub trait LiftedMap<G: LieGroup>: Discretization<G> {
    /// The base point ḡ of `R̃_d(ḡ, η)` whose first point is g_k: `g_k a(η)⁻¹`.
    fn base_point(&self, gk: &G, eta: &G::Algebra) -> G {
        composed::base_point(self, gk, eta)
    }
    /// The second point `R̃_d(ḡ, η)₂ = ḡ b(η) = g_{k+1}`, not renormalized onto the group.
    fn second_point(&self, gbar: &G, eta: &G::Algebra) -> G {
        composed::second_point(self, gbar, eta)
    }
    /// `g_{k+1}` from g_k directly, `second_point(base_point(g_k, η), η)` up to round-off, for a
    /// step that needs no ḡ; maps override it with a single product where they can. Like
    /// [`Self::second_point`] it is not renormalized onto the group: the caller decides how often
    /// (renormalizing every step rounds g twice per step, with a bias the momentum map
    /// accumulates).
    fn next_point(&self, gk: &G, eta: &G::Algebra) -> G {
        self.second_point(&self.base_point(gk, eta), eta)
    }

    /// The ν-component of `(R̃_d^{T*})⁻¹` solved for `μ_{k+1}` given μ_k, η and the impulse ν
    /// (`None` for ν = 0): `μ_{k+1} = Ad*_{b(η)} (Ad*_{a(η)⁻¹} μ_k + ν)`, with its increment.
    fn momentum_update(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        nu: Option<&G::Algebra>,
    ) -> MomentumUpdate<G::Algebra> {
        composed::momentum_update(self, eta, mu_k, nu)
    }
    /// `μ_{k+1} − μ_k` of [`Self::momentum_update`] alone, what a step adds to μ_k at its
    /// solution; maps override it where the increment is cheaper without the other parts (the
    /// left map without an impulse: `Tau::tau_split_coadjoint_increment`, one increment for exp
    /// and for Cayley on SO(3)).
    fn momentum_increment(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        nu: Option<&G::Algebra>,
    ) -> G::Algebra {
        self.momentum_update(eta, mu_k, nu).increment
    }
    /// The μ-component of `(R̃_d^{T*})⁻¹((g_k, μ_k), (g_{k+1}, μ_{k+1}))`: the base momentum
    /// `μ̄ = −d^{L*}a_η μ_k + d^{L*}b_η μ_{k+1}`.
    fn base_momentum(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        mu_next: &G::Algebra,
    ) -> G::Algebra {
        composed::base_momentum(self, eta, mu_k, mu_next)
    }
    /// The base momentum μ̄ of a trial η straight from μ_k and the impulse ν:
    /// `base_momentum(η, μ_k, momentum_update(η, μ_k, ν).next)` up to round-off, the quantity
    /// every residual of a cotangent-lift step needs. The provided form is exactly that
    /// composition; maps override it where μ̄ is cheaper to form without μ_{k+1} (the left map
    /// by `d^{L*}τ_ζ Ad*_{τ(ζ)} = d^{L*}τ_{−ζ}`), so that a step forms μ_{k+1} once, at the
    /// solution.
    fn base_momentum_from_impulse(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        nu: Option<&G::Algebra>,
    ) -> G::Algebra {
        self.base_momentum(eta, mu_k, &self.momentum_update(eta, mu_k, nu).next)
    }
    /// `∂μ̄/∂η` along [`Self::momentum_update`] with ν held fixed. Provided by differences of the
    /// composed μ̄ (ν read back from the update: `Ad*_{b⁻¹} μ_{k+1} − transported`).
    fn base_momentum_derivative(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        update: &MomentumUpdate<G::Algebra>,
    ) -> G::Operator {
        composed::base_momentum_derivative(self, eta, mu_k, update)
    }

    /// `∂μ̄/∂ν`: how the base momentum moves with the impulse ν of [`Self::momentum_update`]
    /// (μ̄ is affine in ν), for the force's term of Newton's matrix: `(Ad_{b(η)} d^L b_η)ᵀ`.
    /// `None` where the map does not provide it (the integrators then leave that term out).
    fn base_momentum_impulse_derivative(&self, eta: &G::Algebra) -> Option<G::Operator> {
        Some(composed::base_momentum_impulse_derivative(self, eta))
    }
    /// `ḡ⁻¹ ∂ḡ/∂η`, the left-trivialized derivative of the base point [`Self::base_point`] in η
    /// (g_k fixed), for the force's term of Newton's matrix: `−Ad_{a(η)} d^L a_η` for the left
    /// map; `None` where not provided (a right-sided map: its ḡ = a(−η) g_k moves by a
    /// derivative that depends on g_k).
    fn base_point_derivative(&self, eta: &G::Algebra) -> Option<G::Operator> {
        composed::base_point_derivative(self, eta)
    }

    /// The body velocity `ξ_k = Ad_{a(η)⁻¹} ξ + d^L a_η ζ` of the first point of
    /// `R̃_d^T(ḡ, ξ, η, ζ)`.
    fn first_velocity(&self, eta: &G::Algebra, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        composed::first_velocity(self, eta, xi, zeta)
    }
    /// The body velocity `ξ_{k+1} = Ad_{b(η)⁻¹} ξ + d^L b_η ζ` of the second point of
    /// `R̃_d^T(ḡ, ξ, η, ζ)`.
    fn second_velocity(&self, eta: &G::Algebra, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        composed::second_velocity(self, eta, xi, zeta)
    }
    /// For the field's step `η = hξ`: `ξ_k − ξ` of `R̃_d^T(ḡ, ξ, hξ, ζ)`, the
    /// [`Self::first_velocity`] less ξ in increment form: O(h|ξ|² + |ζ|), rounded relative to
    /// that size rather than to |ξ|, so that a step solving for ξ − ξ_k (the Euler–Poincaré step)
    /// and adding its velocity change to ξ_k keeps its rounding at that size. The provided form is
    /// `(Ad_{a(hξ)⁻¹} − I) ξ + d^L a_{hξ} ζ` with the Ad term from `log a(hξ)⁻¹`
    /// (`LieGroup::exp_adjoint_increment`; the matrix product where log fails, rounded at ε|ξ|).
    fn first_velocity_increment(&self, h: f64, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        composed::first_velocity_increment(self, h, xi, zeta)
    }
    /// For the field's step `η = hξ`: `ξ_{k+1} − ξ`, the [`Self::second_velocity`] less ξ in
    /// increment form (see [`Self::first_velocity_increment`]), with b for a.
    fn second_velocity_increment(&self, h: f64, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        composed::second_velocity_increment(self, h, xi, zeta)
    }
    /// For the field's step `η = hξ` at `ζ = ζ(ξ)`: `(A, B)` with
    /// `∂/∂ξ first_velocity(hξ, ξ, ζ(ξ)) = A + B ∂ζ/∂ξ` — A the derivative with ζ held fixed,
    /// B = ∂/∂ζ = `d^L a_{hξ}` — what the Newton matrix of the Euler–Poincaré step is built from
    /// (with ∂r/∂δ = ∂r/∂ξ for its unknown δ = ξ − ξ_k). Provided: A by differences of the
    /// composed [`Self::first_velocity`], B in closed form.
    fn first_velocity_derivative(
        &self,
        h: f64,
        xi: &G::Algebra,
        zeta: &G::Algebra,
    ) -> (G::Operator, G::Operator) {
        composed::first_velocity_derivative(self, h, xi, zeta)
    }
}

/// The fused θ-formulas of the left-trivialized map `R̃_d(ḡ, η) = (ḡ τ(−θη), ḡ τ((1−θ)η))` of
/// §3.2: the default path of every component written out for `a(η) = τ(−θη)`, `b(η) = τ((1−θ)η)`.
impl<G: LieGroup, T: Tau<G>> LiftedMap<G> for DiscretizationMap<T> {
    /// `ḡ = g_k τ(θη)` (`Tau::compose_tau`: g_k rounded once).
    #[inline]
    fn base_point(&self, gk: &G, eta: &G::Algebra) -> G {
        let th = self.theta();
        if th == 0.0 {
            gk.clone()
        } else {
            T::compose_tau(gk, &eta.scale(th))
        }
    }
    /// `g_{k+1} = ḡ τ((1−θ)η)` (in increment form, not renormalized).
    #[inline]
    fn second_point(&self, gbar: &G, eta: &G::Algebra) -> G {
        T::compose_tau(gbar, &eta.scale(1.0 - self.theta()))
    }
    /// `g_{k+1} = g_k τ(θη) τ((1−θ)η)` in one product (`Tau::compose_tau_split`), not
    /// renormalized.
    #[inline(always)]
    fn next_point(&self, gk: &G, eta: &G::Algebra) -> G {
        T::compose_tau_split(gk, self.theta(), eta)
    }
    /// `μ_{k+1} = Ad*_{τ((1−θ)η)} (Ad*_{τ(θη)} μ_k + ν)` in increment form: with
    /// `δ_ζ(x) := (Ad*_{τ(ζ)} − I) x` (`Tau::tau_coadjoint_increment`, linear in x, computed from
    /// ζ), `Δ = δ_{θη}(μ_k) + ν` and `μ_{k+1} − μ_k = Δ + δ_{(1−θ)η}(μ_k) + δ_{(1−θ)η}(Δ)`: μ_k
    /// enters once, so |μ|² follows a random walk of roundings instead of drifting with the
    /// rounding of τ's entries `1 − O(|η|²)` at small steps. τ itself is not formed.
    #[inline(always)]
    fn momentum_update(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        nu: Option<&G::Algebra>,
    ) -> MomentumUpdate<G::Algebra> {
        let th = self.theta();
        let xa = eta.scale(th);
        if th == 0.0 && nu.is_none() {
            // Δ = 0: μ_{k+1} − μ_k = δ_η(μ_k) alone.
            let increment = T::tau_coadjoint_increment(eta, mu_k);
            return MomentumUpdate {
                transported: mu_k.clone(),
                next: mu_k.add(&increment),
                increment,
            };
        }
        let carried = if th == 0.0 {
            G::Algebra::zeros(G::dim())
        } else {
            T::tau_coadjoint_increment(&xa, mu_k)
        };
        let transported = mu_k.add(&carried);
        let d = match nu {
            Some(nu) => carried.add(nu),
            None => carried.clone(),
        };
        // θ = ½: both factors are τ(η/2), so δ_{(1−θ)η}(μ_k) is `carried` (bitwise).
        // (θ = ½: the same vector as xa, so the compiler shares τ's coefficients.)
        let eb = if th == 0.5 { xa } else { eta.scale(1.0 - th) };
        let second = if th == 0.5 {
            carried
        } else {
            T::tau_coadjoint_increment(&eb, mu_k)
        };
        let increment = d.add(&second).add(&T::tau_coadjoint_increment(&eb, &d));
        MomentumUpdate {
            transported,
            next: mu_k.add(&increment),
            increment,
        }
    }

    /// Without an impulse, `μ_{k+1} = Ad*_{τ(θη)τ((1−θ)η)} μ_k`: one
    /// `Tau::tau_split_coadjoint_increment` (the two factors in one where τ allows it).
    #[inline(always)]
    fn momentum_increment(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        nu: Option<&G::Algebra>,
    ) -> G::Algebra {
        match nu {
            None => T::tau_split_coadjoint_increment(self.theta(), eta, mu_k),
            Some(_) => self.momentum_update(eta, mu_k, nu).increment,
        }
    }

    /// `μ̄ = θ d^{L*}τ_{−θη} μ_k + (1−θ) d^{L*}τ_{(1−θ)η} μ_{k+1}`.
    #[inline]
    fn base_momentum(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        mu_next: &G::Algebra,
    ) -> G::Algebra {
        let th = self.theta();
        let b = 1.0 - th;
        let mut bar = T::dtau_left_dual_apply(&eta.scale(b), mu_next).scale(b);
        if th != 0.0 {
            bar = bar.axpy(th, &T::dtau_left_dual_apply(&eta.scale(-th), mu_k));
        }
        bar
    }

    /// `μ̄ = θ d^{L*}τ_{−θη} μ_k + (1−θ) d^{L*}τ_{−(1−θ)η} (Ad*_{τ(θη)} μ_k + ν)`: the second term
    /// of [`LiftedMap::base_momentum`] with `μ_{k+1} = Ad*_{τ((1−θ)η)}(Ad*_{τ(θη)} μ_k + ν)` and
    /// `d^{L*}τ_ζ Ad*_{τ(ζ)} = (Ad_{τ(ζ)} d^Lτ_ζ)ᵀ = (d^Rτ_ζ)ᵀ = d^{L*}τ_{−ζ}` (τ(ζ)⁻¹ = τ(−ζ)).
    /// For θ = ½ both terms share `d^{L*}τ_{−η/2}`: `Tau::midpoint_base_momentum` (one coadjoint
    /// increment and one dual tangent, or a closed form), one dual tangent for θ ∈ {0, 1},
    /// against two of each through μ_{k+1}. Always inlined, as the velocity increments below:
    /// the integrators call these at every residual, and a call passes its vectors through
    /// memory.
    #[inline(always)]
    fn base_momentum_from_impulse(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        nu: Option<&G::Algebra>,
    ) -> G::Algebra {
        let th = self.theta();
        let b = 1.0 - th;
        if b == 0.0 {
            // θ = 1: μ̄ = d^{L*}τ_{−η} μ_k (the impulse enters only μ_{k+1}).
            return T::dtau_left_dual_apply(&eta.neg(), mu_k);
        }
        if th == b {
            // θ = ½: ½ d^{L*}τ_{−η/2}(μ_k + Ad*_{τ(η/2)} μ_k) fused (Tau::midpoint_base_momentum),
            // plus ½ d^{L*}τ_{−η/2} ν.
            let a = eta.scale(0.5);
            let bar = T::midpoint_base_momentum(&a, mu_k);
            return match nu {
                None => bar,
                Some(nu) => bar.axpy(0.5, &T::dtau_left_dual_apply(&a.neg(), nu)),
            };
        }
        // x = Ad*_{τ(θη)} μ_k + ν
        let xa = eta.scale(th);
        let mut x = if th == 0.0 {
            mu_k.clone()
        } else {
            mu_k.add(&T::tau_coadjoint_increment(&xa, mu_k))
        };
        if let Some(nu) = nu {
            x = x.add(nu);
        }
        if th == 0.0 {
            T::dtau_left_dual_apply(&eta.neg(), &x)
        } else {
            T::dtau_left_dual_apply(&eta.scale(-b), &x)
                .scale(b)
                .axpy(th, &T::dtau_left_dual_apply(&xa.neg(), mu_k))
        }
    }

    /// With `M(μ) := (δ ↦ ad*_δ μ)` and `D(ζ; μ) := ∂/∂ζ (d^{L*}τ_ζ μ)`
    /// (`Tau::dtau_left_dual_derivative`):
    ///
    /// `∂μ_{k+1}/∂η = (1−θ) M(μ_{k+1}) d^Lτ_{(1−θ)η} + θ Ad*_{τ((1−θ)η)} M(Ad*_{τ(θη)} μ_k) d^Lτ_{θη}`
    /// (exact with ν fixed: `∂_ε Ad*_{τ(ζ + εδ)} x = ad*_{d^Lτ_ζ δ} Ad*_{τ(ζ)} x`), and
    /// `∂μ̄/∂η = (1−θ) d^{L*}τ_{(1−θ)η} ∂μ_{k+1}/∂η + (1−θ)² D((1−θ)η; μ_{k+1}) − θ² D(−θη; μ_k)`.
    /// For θ = ½ both terms of the first line end in the same `d^Lτ_{η/2}`, factored out.
    fn base_momentum_derivative(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        update: &MomentumUpdate<G::Algebra>,
    ) -> G::Operator {
        let th = self.theta();
        let b = 1.0 - th;
        let xa = eta.scale(th);
        let xb = eta.scale(b);
        let dtb = T::dtau_left(&xb);
        let m1 = G::ad_dual_operator(&update.next);
        let dmu1 = if th == 0.0 {
            m1.compose(&dtb).scale(b)
        } else {
            // Ad*_{τ((1−θ)η)} M(ν̂) = (Ad_{τ((1−θ)η)})ᵀ M(ν̂).
            let mnu = T::tau(&xb)
                .adjoint()
                .transpose()
                .compose(&G::ad_dual_operator(&update.transported));
            if th == b {
                m1.add(&mnu).compose(&dtb).scale(b)
            } else {
                m1.compose(&dtb)
                    .scale(b)
                    .add(&mnu.compose(&T::dtau_left(&xa)).scale(th))
            }
        };
        let mut dbar = dtb
            .transpose()
            .compose(&dmu1)
            .scale(b)
            .add(&T::dtau_left_dual_derivative(&xb, &update.next).scale(b * b));
        if th != 0.0 {
            dbar = dbar.add(&T::dtau_left_dual_derivative(&xa.neg(), mu_k).scale(-th * th));
        }
        dbar
    }

    /// `∂μ̄/∂ν = (1−θ) d^{L*}τ_{(1−θ)η} Ad*_{τ((1−θ)η)}` (from `μ_{k+1} = Ad*_{τ((1−θ)η)}(… + ν)`).
    fn base_momentum_impulse_derivative(&self, eta: &G::Algebra) -> Option<G::Operator> {
        let b = 1.0 - self.theta();
        if b == 0.0 {
            return Some(G::Operator::identity(G::dim()).scale(0.0));
        }
        let xb = eta.scale(b);
        Some(
            T::dtau_left(&xb)
                .transpose()
                .compose(&T::tau(&xb).adjoint().transpose())
                .scale(b),
        )
    }
    /// `ḡ = g_k τ(θη)`: `ḡ⁻¹ ∂ḡ/∂η = θ d^Lτ_{θη}`.
    fn base_point_derivative(&self, eta: &G::Algebra) -> Option<G::Operator> {
        let th = self.theta();
        Some(T::dtau_left(&eta.scale(th)).scale(th))
    }

    /// `ξ_k = Ad_{τ(θη)} ξ − θ d^Lτ_{−θη} ζ`.
    #[inline]
    fn first_velocity(&self, eta: &G::Algebra, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        let th = self.theta();
        let xa = eta.scale(th);
        T::tau(&xa)
            .adjoint_apply(xi)
            .sub(&T::dtau_left(&xa.neg()).apply(zeta).scale(th))
    }
    /// `ξ_{k+1} = Ad_{τ(−(1−θ)η)} ξ + (1−θ) d^Lτ_{(1−θ)η} ζ`.
    #[inline]
    fn second_velocity(&self, eta: &G::Algebra, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        let b = 1.0 - self.theta();
        let xb = eta.scale(b);
        T::tau(&xb)
            .inverse()
            .adjoint_apply(xi)
            .add(&T::dtau_left(&xb).apply(zeta).scale(b))
    }
    /// `ξ_k − ξ = (Ad_{τ(θhξ)} − I) ξ − θ d^Lτ_{−θhξ} ζ`; 0 for θ = 0. The first term vanishes
    /// where τ(sξ) commutes with ξ (`Tau::COMMUTES_WITH_ARGUMENT`: exp, Cayley) and is not formed
    /// there; otherwise it is `Tau::tau_adjoint_increment` (no term of size |ξ| formed).
    #[inline(always)]
    fn first_velocity_increment(&self, h: f64, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        let th = self.theta();
        if th == 0.0 {
            return G::Algebra::zeros(G::dim());
        }
        let xa = xi.scale(th * h);
        let inc = T::dtau_left(&xa.neg()).apply(zeta).scale(-th);
        if T::COMMUTES_WITH_ARGUMENT {
            inc
        } else {
            inc.add(&T::tau_adjoint_increment(&xa, xi))
        }
    }
    /// `ξ_{k+1} − ξ = (Ad_{τ(−(1−θ)hξ)} − I) ξ + (1−θ) d^Lτ_{(1−θ)hξ} ζ`; 0 for θ = 1; the first
    /// term as in [`LiftedMap::first_velocity_increment`].
    #[inline(always)]
    fn second_velocity_increment(&self, h: f64, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        let b = 1.0 - self.theta();
        if b == 0.0 {
            return G::Algebra::zeros(G::dim());
        }
        let xb = xi.scale(b * h);
        let inc = T::dtau_left(&xb).apply(zeta).scale(b);
        if T::COMMUTES_WITH_ARGUMENT {
            inc
        } else {
            inc.add(&T::tau_adjoint_increment(&xb.neg(), xi))
        }
    }
    /// With `a = θh`: `A = Ad_{τ(aξ)} (I − a ad_ξ d^Lτ_{aξ}) + θa E(−aξ; ζ)` (the derivative of
    /// `Ad_{τ(aξ)} ξ`, which is I where τ commutes with its argument, and of `−θ d^Lτ_{−aξ} ζ` at
    /// fixed ζ with `E(x; v) = ∂/∂x (d^Lτ_x v)`, `Tau::dtau_left_derivative`) and
    /// `B = −θ d^Lτ_{−aξ}`.
    fn first_velocity_derivative(
        &self,
        h: f64,
        xi: &G::Algebra,
        zeta: &G::Algebra,
    ) -> (G::Operator, G::Operator) {
        let th = self.theta();
        let a = th * h;
        let xa = xi.scale(a);
        let id = G::Operator::identity(G::dim());
        let transport = if T::COMMUTES_WITH_ARGUMENT {
            id
        } else {
            T::tau(&xa)
                .adjoint()
                .compose(&id.add(&G::ad(xi).compose(&T::dtau_left(&xa)).scale(-a)))
        };
        let first = transport.add(&T::dtau_left_derivative(&xa.neg(), zeta).scale(th * a));
        (first, T::dtau_left(&xa.neg()).scale(-th))
    }
}
