//! The Strang splitting of all pieces: order 2, symmetric, explicit.

use super::kick::kick;
use super::SplitSystem;
use super::RENORMALIZE_EVERY;
use crate::compose::{StateSnapshot, SymmetricMethod};
use crate::lie_poisson::check_state;
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
/// ```
/// use integrators::{splitting::Splitting, Integrator, systems::HeavyTop};
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
    t: f64,
    mu: G::Algebra,
    g: Option<G>,
    /// Steps since g was last renormalized ([`RENORMALIZE_EVERY`]).
    unnormalized: u32,
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
            t: 0.0,
            mu: mu0,
            g: g0,
            unnormalized: 0,
            _group: PhantomData,
        })
    }
    /// Resets the state to (t, μ, g), with the checks of [`Splitting::new`].
    pub fn reset(&mut self, t: f64, mu: G::Algebra, g: Option<G>) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        check_state(&self.system, &mu, "momentum μ", g.as_ref())?;
        self.t = t;
        self.mu = mu;
        self.g = g;
        self.unnormalized = 0;
        Ok(())
    }
    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }
}

impl<G: LieGroup, S: SplitSystem<G>> Integrator for Splitting<G, S> {
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let half = 0.5 * h;
        let mut mu = self.mu.clone();
        let mut g = self.g.clone();
        kick(&self.system, self.t, half, &mut mu, g.as_ref())?;
        let last = self.system.pieces() - 1;
        for i in 0..last {
            self.system.piece_flow(i, half, &mut mu, g.as_mut());
        }
        self.system.piece_flow(last, h, &mut mu, g.as_mut());
        for i in (0..last).rev() {
            self.system.piece_flow(i, half, &mut mu, g.as_mut());
        }
        kick(&self.system, self.t + h, half, &mut mu, g.as_ref())?;
        if !mu.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "momentum μ_{k+1}",
            });
        }
        // Each flow moves g by an exact group element, so g leaves the group only by a random walk
        // of roundings: renormalized every RENORMALIZE_EVERY steps, not at each (which would bias
        // the spatial momentum map, as for Lie–Poisson).
        let renormalize = self.unnormalized + 1 >= RENORMALIZE_EVERY;
        if let Some(g1) = g.as_mut() {
            if renormalize {
                *g1 = g1.normalize();
            }
            if !g1.is_finite() {
                return Err(IntegratorError::NonFinite {
                    what: "configuration g_{k+1}",
                });
            }
        }
        self.mu = mu;
        self.g = g;
        self.t += h;
        self.unnormalized = if renormalize {
            0
        } else {
            self.unnormalized + 1
        };
        Ok(())
    }
    fn time(&self) -> f64 {
        self.t
    }
    fn momentum(&self) -> G::Algebra {
        self.mu.clone()
    }
    fn velocity(&self) -> G::Algebra {
        self.system.velocity(&self.mu)
    }
    fn momentum_rate(&self) -> G::Algebra {
        crate::dense_output::momentum_rate(
            &self.system,
            self.time(),
            &self.momentum(),
            self.configuration(),
        )
    }
    fn configuration(&self) -> Option<&G> {
        self.g.as_ref()
    }
    fn energy(&self) -> f64 {
        self.system.energy(&self.mu, self.g.as_ref())
    }
    fn casimir(&self) -> Option<f64> {
        self.system.casimir(&self.mu)
    }
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
}

impl<G: LieGroup, S: SplitSystem<G>> StateSnapshot for Splitting<G, S> {
    /// (t, μ, g).
    type State = (f64, G::Algebra, Option<G>);
    fn snapshot(&self) -> Self::State {
        (self.t, self.mu.clone(), self.g.clone())
    }
    fn restore(&mut self, (t, mu, g): Self::State) -> Result<(), IntegratorError> {
        self.reset(t, mu, g)
    }
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        self.t = t;
        Ok(())
    }
}
