//! The Strang splitting of all pieces: order 2, symmetric, explicit.

use super::kick::kick;
use super::SplitSystem;
use super::PRODUCTS_PER_STEP;
use crate::checks::check_state;
use crate::compose::{StateSnapshot, SymmetricMethod};
use crate::step_state::{state_accessors, StepState};
use crate::{Integrator, IntegratorError, MethodInfo};
use core::marker::PhantomData;
use lie_groups::{LieGroup, Vector};

/// The Strang splitting of `h = Σᵢ hᵢ + V` ([`SplitSystem`]):
///
/// ```text
/// Ψ_h = V_{h/2} ∘ φ⁰_{h/2} ∘ … ∘ φⁿ⁻²_{h/2} ∘ φⁿ⁻¹_h ∘ φⁿ⁻²_{h/2} ∘ … ∘ φ⁰_{h/2} ∘ V_{h/2}
/// ```
///
/// (applied right to left; `V_t: μ ↦ μ + t F(g)` is the kick, present only with a potential or an
/// external force: [`crate::forces::Forced`] systems are split too, the force joining the kick at the
/// kick's time — t_k first, t_k + h last — by the kick rules (`splitting/kick.rs`): exact for forces of
/// (t, g), the implicit midpoint rule for forces that read ξ, so the step stays symmetric and of
/// order 2).
/// Order 2, symmetric (Ψ_{−h} = Ψ_h⁻¹: the sequence is a palindrome of exact flows), explicit, and
/// a Poisson map preserving each coadjoint orbit; compose it with [`crate::Composition`] for order
/// 4 to 10. Without a potential it keeps the Casimirs and the spatial momentum map to round-off.
///
/// **First same as last.** The closing outer half-flow of one step and the opening one of the
/// next are flows of the same piece (the kick, or φ⁰ without one) at the same time, so they are
/// merged: each step starts from the state *before* the previous closing half-flow and applies
/// `φ⁰_{h_prev/2 + h/2}` once. The published state (what `momentum`, `configuration`, `energy`
/// read) still gets its closing half-flow, computed off the chain from one step to the next, so
/// that a run's loop-carried work is one flow shorter (the free body: two dependent plane
/// rotations of Π a step instead of three). Reads never change the run: n steps give the same
/// bits whether the state is read after each or not. The merged flow equals the two half-flows
/// to round-off (a one-parameter group); a reset, `restore` or, for a forced system, `set_time`
/// starts afresh from the published state. Not merged: kicks of velocity-dependent forces (the
/// implicit midpoint rule is not a group in its time).
///
/// ```
/// use integrators::{splitting::Splitting, Integrator};
/// use mechanics::HeavyTop;
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5))?;
/// let mut s = Splitting::new(top, Vector3::new(0.3, 1.0, 2.0), Some(So3::identity()))?;
/// let e0 = s.energy();
/// for _ in 0..1000 {
///     s.step(0.001)?;
/// }
/// assert!((s.energy() - e0).abs() < 1e-4 * e0.abs());
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Splitting<G: LieGroup, S: SplitSystem<G>> {
    system: S,
    mu: G::Algebra,
    /// t, g and g's renormalization ([`PRODUCTS_PER_STEP`]).
    state: StepState<G>,
    /// First same as last: the state (μ, g) before the last step's closing outer half-flow, and
    /// that half-flow's time `lag`, which the next step merges with its own opening one (the
    /// outer flow is a one-parameter group in its time: `φ_{s'} ∘ φ_s = φ_{s+s'}`). After a
    /// reset, the state itself with lag 0; unused when the outer flow does not merge (a kick of
    /// a velocity-dependent force).
    lead_mu: G::Algebra,
    lead_g: Option<G>,
    lag: f64,
    _group: PhantomData<G>,
}

impl<G: LieGroup, S: SplitSystem<G>> Splitting<G, S> {
    /// The integrator at t = 0 from μ₀ and optionally g₀. Errors: non-finite μ₀ or g₀, g₀ missing
    /// for a system with a potential, a system declaring no piece.
    pub fn new(system: S, mu0: G::Algebra, g0: Option<G>) -> Result<Self, IntegratorError> {
        if system.pieces() == 0 {
            return Err(IntegratorError::InvalidParameter {
                reason: "the system declares no kinetic piece to split: its kinetic energy has \
                         no splitting into pieces with explicit flows (e.g. an underwater \
                         vehicle whose mass matrix couples rotation and translation)"
                    .into(),
            });
        }
        check_state(&system, &mu0, "momentum μ", g0.as_ref())?;
        Ok(Self {
            system,
            lead_mu: mu0.clone(),
            lead_g: g0.clone(),
            lag: 0.0,
            mu: mu0,
            state: StepState::new(g0, PRODUCTS_PER_STEP),
            _group: PhantomData,
        })
    }
    /// Resets the state to (t, μ, g), with the checks of [`Splitting::new`].
    pub fn reset(&mut self, t: f64, mu: G::Algebra, g: Option<G>) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        check_state(&self.system, &mu, "momentum μ", g.as_ref())?;
        self.state.reset(t, g.clone());
        self.lead_mu = mu.clone();
        self.lead_g = g;
        self.lag = 0.0;
        self.mu = mu;
        Ok(())
    }
    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }

    /// The Strang step of a single kinetic piece without kick: its exact flow.
    fn commit_single(&mut self, h: f64) -> Result<(), IntegratorError> {
        let (mut mu, mut g) = (self.mu.clone(), self.state.g.clone());
        self.system.piece_flow(0, h, &mut mu, g.as_mut());
        self.commit(h, mu, g, None)
    }

    /// Checks the new state (μ, g) and takes it, with the FSAL state. Each flow moves g by an
    /// exact group element, so g leaves the group only by a random walk of roundings:
    /// renormalized rarely, not at each step (crate::step_state), the FSAL g with it.
    fn commit(
        &mut self,
        h: f64,
        mu: G::Algebra,
        mut g: Option<G>,
        mut lead: Option<(G::Algebra, Option<G>)>,
    ) -> Result<(), IntegratorError> {
        if !mu.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "momentum μ_{k+1}",
            });
        }
        self.state.finish_configuration(&mut g)?;
        if self.state.renormalizes() {
            if let Some((_, Some(g0))) = lead.as_mut() {
                *g0 = g0.normalize();
            }
        }
        if let Some((lead_mu, lead_g)) = lead {
            self.lead_mu = lead_mu;
            self.lead_g = lead_g;
            self.lag = 0.5 * h;
        }
        self.mu = mu;
        self.state.commit(h, g);
        Ok(())
    }
}

impl<G: LieGroup, S: SplitSystem<G>> Integrator for Splitting<G, S> {
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let half = 0.5 * h;
        let system = &self.system;
        let last = system.pieces() - 1;
        // The outer flow: the kick with a potential or a force, else the first kinetic piece (the
        // whole step when it is the only one).
        let kicked = system.has_potential() || system.is_forced();
        if !kicked && last == 0 {
            return self.commit_single(h);
        }
        let merges = !system.external_force_reads_velocity();
        let (mut mu, mut g, opening) = if merges {
            (self.lead_mu.clone(), self.lead_g.clone(), self.lag + half)
        } else {
            (self.mu.clone(), self.state.g.clone(), half)
        };
        let first = if kicked {
            kick(system, self.state.now(), opening, &mut mu, g.as_ref())?;
            0
        } else {
            system.piece_flow(0, opening, &mut mu, g.as_mut());
            1
        };
        for i in first..last {
            system.piece_flow(i, half, &mut mu, g.as_mut());
        }
        system.piece_flow(last, h, &mut mu, g.as_mut());
        for i in (first..last).rev() {
            system.piece_flow(i, half, &mut mu, g.as_mut());
        }
        // The closing half-flow of the published state is off the next step's critical path: the
        // next step starts from the state before it (`lead_mu`, `lead_g`).
        let before = merges.then(|| (mu.clone(), g.clone()));
        if kicked {
            kick(system, self.state.now() + h, half, &mut mu, g.as_ref())?;
        } else {
            system.piece_flow(0, half, &mut mu, g.as_mut());
        }
        self.commit(h, mu, g, before)
    }
    state_accessors!(mu);
    fn method_name(&self) -> String {
        "splitting(strang)".into()
    }
    /// Order 2, symmetric, explicit, Poisson; Casimirs kept without a potential or force (the kick
    /// moves μ off its orbit, as the exact flow does); the spatial momentum map kept for an
    /// invariant unforced system. Explicit also with a velocity-dependent force, whose kick is a
    /// small fixed-point iteration (no Newton matrix).
    fn info(&self) -> MethodInfo {
        MethodInfo {
            order: 2,
            symmetric: true,
            explicit: true,
            poisson: true,
            casimirs: !self.system.has_potential() && !self.system.is_forced(),
            momentum_map: !self.system.is_forced(),
            energy: false,
            on_group: true,
        }
    }
}

impl<G: LieGroup, S: SplitSystem<G>> SymmetricMethod for Splitting<G, S> {
    /// Always: the Strang sequence is a palindrome of exact flows.
    fn is_symmetric(&self) -> bool {
        true
    }
    /// The spin about Π followed exactly: the rotation pieces are exact flows.
    fn density_scope(&self) -> crate::DensityScope {
        crate::DensityScope::SpinFollowed
    }
}

impl<G: LieGroup, S: SplitSystem<G>> StateSnapshot for Splitting<G, S> {
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
        // The merged opening kick of the next step reads t: a forced system starts afresh.
        if self.system.is_forced() {
            self.lead_mu = self.mu.clone();
            self.lead_g = self.state.g.clone();
            self.lag = 0.0;
        }
        Ok(())
    }
}
