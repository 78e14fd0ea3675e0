//! Splittings into the exact kinetic flow and potential kicks.

use super::kick::kick;
use super::SplittingScheme;
use super::PRODUCTS_PER_STEP;
use crate::checks::check_state;
use crate::compose::{StateSnapshot, SymmetricMethod};
use crate::step_state::{state_accessors, StepState};
use crate::{Integrator, IntegratorError, MethodInfo, System};
use lie_groups::{LieGroup, Vector};

/// The exact flow of a system's kinetic Hamiltonian h(μ): `(μ, g) ↦ φ_t(μ, g)` solving
/// `μ̇ = ad*_{∂h/∂μ} μ`, `ġ = g ∂h/∂μ` (§2 of the paper, without the potential).
///
/// Implemented by `mechanics::exact::AxisymmetricFlow` (closed form for a body with two equal moments),
/// `mechanics::exact::FreeBodyFlow` (any rigid body, Jacobi elliptic functions) and
/// `mechanics::exact::FreeBodySe3Flow` (the free body on SE(3)).
/// `Ok` only with a finite result; on error the arguments are left as they were.
pub trait KineticFlow<G: LieGroup> {
    /// Advances (μ, g) by the kinetic flow for a time t (of either sign).
    fn kinetic_flow(
        &self,
        t: f64,
        mu: &mut G::Algebra,
        g: Option<&mut G>,
    ) -> Result<(), IntegratorError>;
}

/// The splitting `h + V` into the exact kinetic flow B = φ_t and the kick A: `μ ↦ μ + tF(g)`,
/// `F(g) = −T*_e L_g dV(g)` (plus an external force of a [`crate::forces::Forced`] system at the
/// kick's time, advanced by the kinetic flows: exact for forces of (t, g), the implicit midpoint
/// rule for forces that read ξ, which caps the order at 2), composed with the coefficients of a
/// [`SplittingScheme`]:
///
/// ```text
/// Ψ_h = A_{a₁h} ∘ B_{b₁h} ∘ A_{a₂h} ∘ … ∘ B_{b_m h} ∘ A_{a_{m+1}h}
/// ```
///
/// (Touma–Wisdom 1994; Dullweber–Leimkuhler–McLachlan 1997). The kinetic flow of the free body
/// being exact, only the potential's effect is discretised: a fast spin costs nothing in accuracy.
/// Order of the scheme (2, 4, 6), symmetric, explicit, Poisson; the kinetic part must be the exact
/// flow of `S`'s h (the constructors of the flows check it where they can).
#[derive(Debug, Clone)]
pub struct KineticKick<G: LieGroup, S: System<G>, K: KineticFlow<G>> {
    system: S,
    kinetic: K,
    scheme: SplittingScheme,
    mu: G::Algebra,
    /// t, g and g's renormalization ([`PRODUCTS_PER_STEP`]).
    state: StepState<G>,
}

impl<G: LieGroup, S: System<G>, K: KineticFlow<G>> KineticKick<G, S, K> {
    /// The integrator at t = 0. Errors: non-finite μ₀ or g₀, g₀ missing for a system with a
    /// potential.
    pub fn new(
        system: S,
        kinetic: K,
        scheme: SplittingScheme,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Self, IntegratorError> {
        check_state(&system, &mu0, "momentum μ", g0.as_ref())?;
        Ok(Self {
            system,
            kinetic,
            scheme,
            mu: mu0,
            state: StepState::new(g0, PRODUCTS_PER_STEP),
        })
    }
    /// Resets the state to (t, μ, g), with the checks of [`KineticKick::new`].
    pub fn reset(&mut self, t: f64, mu: G::Algebra, g: Option<G>) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        check_state(&self.system, &mu, "momentum μ", g.as_ref())?;
        self.state.reset(t, g);
        self.mu = mu;
        Ok(())
    }
    /// The scheme.
    pub fn scheme(&self) -> &SplittingScheme {
        &self.scheme
    }
    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }
}

impl<G: LieGroup, S: System<G>, K: KineticFlow<G>> Integrator for KineticKick<G, S, K> {
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let mut mu = self.mu.clone();
        let mut g = self.state.g.clone();
        let (a, b) = (self.scheme.a(), self.scheme.b());
        // The kicks' time: t_k advanced by the kinetic flows (t' = 1 belongs to the kinetic part).
        let mut t = self.state.now();
        for (i, &ai) in a.iter().enumerate() {
            kick(&self.system, t, ai * h, &mut mu, g.as_ref())?;
            if let Some(&bi) = b.get(i) {
                self.kinetic.kinetic_flow(bi * h, &mut mu, g.as_mut())?;
                t += bi * h;
            }
        }
        if !mu.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "momentum μ_{k+1}",
            });
        }
        // Each flow moves g by an exact group element, so g leaves the group only by a random walk
        // of roundings: renormalized rarely (crate::step_state), not at each (which would bias
        // the spatial momentum map, as for Lie–Poisson).
        self.state.finish_configuration(&mut g)?;
        self.mu = mu;
        self.state.commit(h, g);
        Ok(())
    }
    state_accessors!(mu);
    fn method_name(&self) -> String {
        format!("kinetic-kick({})", self.scheme.name())
    }
    /// The scheme's order (at most 2 with a velocity-dependent force, whose kick is the implicit
    /// midpoint rule); symmetric, explicit, Poisson; without a potential or force it is the exact
    /// flow (energy kept too).
    fn info(&self) -> MethodInfo {
        let forced = self.system.is_forced();
        let free = !self.system.has_potential() && !forced;
        MethodInfo {
            order: if free {
                MethodInfo::EXACT
            } else if self.system.external_force_reads_velocity() {
                self.scheme.order().min(2)
            } else {
                self.scheme.order()
            },
            symmetric: true,
            explicit: true,
            poisson: true,
            casimirs: free,
            momentum_map: !forced,
            energy: free,
            on_group: true,
        }
    }
}

impl<G: LieGroup, S: System<G>, K: KineticFlow<G>> SymmetricMethod for KineticKick<G, S, K> {
    /// Always: the schemes are palindromes of exact flows.
    fn is_symmetric(&self) -> bool {
        true
    }
    /// The spin about Π followed exactly: the kinetic energy's flow is exact.
    fn density_scope(&self) -> crate::DensityScope {
        crate::DensityScope::SpinFollowed
    }
}

impl<G: LieGroup, S: System<G>, K: KineticFlow<G>> StateSnapshot for KineticKick<G, S, K> {
    /// (t, μ, g).
    type State = (f64, G::Algebra, Option<G>);
    fn snapshot(&self) -> Self::State {
        (self.state.now(), self.mu.clone(), self.state.g.clone())
    }
    fn restore(&mut self, (t, mu, g): Self::State) -> Result<(), IntegratorError> {
        self.reset(t, mu, g)
    }
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        self.state.t.set(t);
        Ok(())
    }
}
