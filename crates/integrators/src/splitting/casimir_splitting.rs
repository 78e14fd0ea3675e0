//! The splitting of a Casimir part plus two pieces: the Casimir part's flow once a step, a
//! two-part scheme over the pieces.

use super::{CasimirSplit, SplittingScheme};
use crate::checks::check_state;
use crate::compose::{StateSnapshot, SymmetricMethod};
use crate::step_state::{state_accessors, StepState};
use crate::{Integrator, IntegratorError, MethodInfo};
use core::marker::PhantomData;
use lie_groups::{LieGroup, Vector};

/// The splitting of `h = C + h_A + h_B` ([`CasimirSplit`]: C a Casimir function, A and B pieces
/// with explicit flows) with the coefficients of a [`SplittingScheme`]:
///
/// ```text
/// Ψ_h = φᶜ_h ∘ φᴬ_{a_{m+1}h} ∘ φᴮ_{b_m h} ∘ … ∘ φᴬ_{a₂h} ∘ φᴮ_{b₁h} ∘ φᴬ_{a₁h}.
/// ```
///
/// As φᶜ commutes with φᴬ and φᴮ, `e^{h} = e^{C} ∘ e^{h_A + h_B}` exactly, and the error of Ψ_h
/// is that of the scheme on `h_A + h_B` alone: order of the scheme (Strang 2, Blanes–Moan 4 and
/// 6, a composition of Strang 4 to 10 by [`SplittingScheme::strang_composed`]), symmetric
/// (`Ψ_{−h} = Ψ_h⁻¹`: φᶜ_h commutes with the palindrome), explicit, and a Poisson map of each
/// coadjoint orbit, so the Casimirs and the spatial momentum map `Ad*_{g⁻¹} μ` are kept to
/// round-off (every flow is `g ↦ g exp(tξ)`, `μ ↦ Ad*_{exp(tξ)} μ`). On the free rigid body
/// (`mechanics::RigidBody`: C = |Π|²/2I_r, I_r the middle moment, A and B rotations about the
/// other two principal axes) φᶜ is the one Rodrigues product a step and every other flow a plane
/// rotation; the Strang scheme is the same map as [`super::Splitting`] of the body (whose second
/// piece is φᶜ with B), and a composition of Strang folded into one scheme applies φᶜ once per
/// composite step where [`crate::Composition`] of the Strang step applies it once per stage.
///
/// **First same as last**, as in [`super::Splitting`]: the closing flow `φᴬ_{a_{m+1}h}` of a step
/// and the opening `φᴬ_{a₁h'}` of the next merge into one (a one-parameter group); the published
/// state still gets the closing flow, off the chain from one step to the next. Reads never change
/// the run; a reset or `restore` starts afresh from the published state.
///
/// ```
/// use integrators::splitting::{CasimirSplitting, SplittingScheme};
/// use integrators::{CompositionScheme, Integrator};
/// use mechanics::RigidBody;
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([2.0, 3.0, 4.0])?;
/// let pi0 = Vector3::new(1.0, 0.5, -0.3);
/// let scheme = SplittingScheme::strang_composed(&CompositionScheme::kahan_li_8())?;
/// let mut psi = CasimirSplitting::new(body, scheme, pi0, Some(So3::identity()))?;
/// for _ in 0..100 {
///     psi.step(0.1)?;
/// }
/// assert!((psi.casimir().unwrap() - pi0.norm_squared()).abs() < 1e-14);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct CasimirSplitting<G: LieGroup, S: CasimirSplit<G>> {
    system: S,
    scheme: SplittingScheme,
    mu: G::Algebra,
    /// t, g and g's renormalization (one rounded product per flow).
    state: StepState<G>,
    /// First same as last: the state (μ, g) before the last step's closing flow of A, and that
    /// flow's time `lag`, which the next step merges with its own opening one. After a reset, the
    /// state itself with lag 0.
    lead_mu: G::Algebra,
    lead_g: Option<G>,
    lag: f64,
    _group: PhantomData<G>,
}

impl<G: LieGroup, S: CasimirSplit<G>> CasimirSplitting<G, S> {
    /// The integrator at t = 0 from μ₀ and optionally g₀. Errors: non-finite μ₀ or g₀; a system
    /// with a potential or an external force (C does not commute with them:
    /// [`IntegratorError::InvalidParameter`]).
    pub fn new(
        system: S,
        scheme: SplittingScheme,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Self, IntegratorError> {
        if system.has_potential() || system.is_forced() {
            return Err(IntegratorError::InvalidParameter {
                reason: "the Casimir splitting needs a system without potential or force: the \
                         Casimir part's flow commutes with the kinetic pieces only"
                    .into(),
            });
        }
        check_state(&system, &mu0, "momentum μ", g0.as_ref())?;
        // One rounded product of g per flow: the A flows (one merged away), the B flows, φᶜ.
        let products = u32::try_from(scheme.a().len() + scheme.b().len()).unwrap_or(u32::MAX);
        Ok(Self {
            system,
            scheme,
            lead_mu: mu0.clone(),
            lead_g: g0.clone(),
            lag: 0.0,
            mu: mu0,
            state: StepState::new(g0, products),
            _group: PhantomData,
        })
    }
    /// Resets the state to (t, μ, g), with the checks of [`CasimirSplitting::new`].
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
    /// The scheme.
    pub fn scheme(&self) -> &SplittingScheme {
        &self.scheme
    }
    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }
}

impl<G: LieGroup, S: CasimirSplit<G>> Integrator for CasimirSplitting<G, S> {
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let system = &self.system;
        let (a, b) = (self.scheme.a(), self.scheme.b());
        let m = b.len();
        let (mut mu, mut g) = (self.lead_mu.clone(), self.lead_g.clone());
        system.perturbation_flow(0, self.lag + a[0] * h, &mut mu, g.as_mut());
        for (i, &bi) in b.iter().enumerate() {
            system.perturbation_flow(1, bi * h, &mut mu, g.as_mut());
            if i + 1 < m {
                system.perturbation_flow(0, a[i + 1] * h, &mut mu, g.as_mut());
            }
        }
        if let Some(g) = g.as_mut() {
            system.casimir_flow(h, &mu, g);
        }
        // The closing flow of the published state is off the next step's critical path.
        let mut lead = (mu.clone(), g.clone());
        let close = a[m] * h;
        system.perturbation_flow(0, close, &mut mu, g.as_mut());
        if !mu.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "momentum μ_{k+1}",
            });
        }
        // Each flow moves g by an exact group element: renormalized rarely (crate::step_state),
        // the chain's g with it.
        self.state.finish_configuration(&mut g)?;
        if self.state.renormalizes() {
            lead.1 = lead.1.map(|g0| g0.normalize());
        }
        (self.lead_mu, self.lead_g) = lead;
        self.lag = close;
        self.mu = mu;
        self.state.commit(h, g);
        Ok(())
    }
    state_accessors!(mu);
    fn method_name(&self) -> String {
        format!("casimir-splitting({})", self.scheme.name())
    }
    /// The scheme's order; symmetric, explicit, Poisson, Casimirs and the spatial momentum map
    /// kept (the system is free and every flow a coadjoint motion).
    fn info(&self) -> MethodInfo {
        MethodInfo {
            order: self.scheme.order(),
            symmetric: true,
            explicit: true,
            poisson: true,
            casimirs: true,
            momentum_map: true,
            energy: false,
            on_group: true,
        }
    }
}

impl<G: LieGroup, S: CasimirSplit<G>> SymmetricMethod for CasimirSplitting<G, S> {
    /// Always: a palindrome of exact flows, and φᶜ_h commuting with it.
    fn is_symmetric(&self) -> bool {
        true
    }
    /// The spin about Π followed exactly: every flow is exact.
    fn density_scope(&self) -> crate::DensityScope {
        crate::DensityScope::SpinFollowed
    }
}

impl<G: LieGroup, S: CasimirSplit<G>> StateSnapshot for CasimirSplitting<G, S> {
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
