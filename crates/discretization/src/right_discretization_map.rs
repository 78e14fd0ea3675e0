//! [`RightDiscretizationMap`]: the right-trivialized discretization map
//! `R̃_d^R(g, ξ) = (τ(−θξ) g, τ((1−θ)ξ) g)` ("defined analogously", §3 of the paper), with the
//! right-trivialized retraction `g ↦ τ(ξ) g` and bundles `u_g = ξ g`, `p_g = μ g⁻¹`.
//!
//! Inversion `ι(g) = g⁻¹` carries it onto the left map: with `τ(−x) = τ(x)⁻¹`,
//! `(τ(−θξ) g)⁻¹ = g⁻¹ τ(θξ)`, so `ι × ι ∘ R̃_d^R(g, ξ) = R̃_d^L(g⁻¹, −ξ)`. A right-trivialized
//! tangent vector ξ at g goes to the left-trivialized −ξ at g⁻¹ and a right-trivialized covector
//! μ to −μ; a right-invariant h(μ) becomes the left-invariant h(−ν). Every component of the lifts
//! is therefore the left one at −η — the momentum update and the base momentum are linear in the
//! momenta, the velocities linear in (ξ, ζ), so the signs of μ and ξ cancel — and the points are
//! multiplied on the left. The tests check the map's axioms, the lifts against finite differences
//! and the integrators against an independent integration of the right equations
//! `μ̇ = −ad*_ξ μ`, `ġ = ξ g` (crates/integrators/tests/right_trivialized.rs).

use crate::{
    Discretization, DiscretizationError, DiscretizationMap, LiftedMap, MomentumUpdate, Side,
    ThetaFamily,
};
use lie_groups::{LieGroup, Tau, Vector};

/// `R̃_d^R(g, ξ) = (τ(−θξ) g, τ((1−θ)ξ) g)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RightDiscretizationMap<T> {
    left: DiscretizationMap<T>,
}

impl<T> RightDiscretizationMap<T> {
    /// The map with parameter θ; an error unless θ ∈ [0, 1].
    pub fn new(theta: f64) -> Result<Self, DiscretizationError> {
        Ok(Self {
            left: DiscretizationMap::new(theta)?,
        })
    }
    /// θ.
    pub fn theta(&self) -> f64 {
        self.left.theta()
    }
    /// `R̃_d^R(g, ξ) = (τ(−θξ) g, τ((1−θ)ξ) g)`.
    pub fn apply<G: LieGroup>(&self, g: &G, xi: &G::Algebra) -> (G, G)
    where
        T: Tau<G>,
    {
        let th = self.theta();
        (
            T::tau(&xi.scale(-th)).compose(g),
            T::tau(&xi.scale(1.0 - th)).compose(g),
        )
    }
    /// `(R̃_d^R)⁻¹(g_k, g_{k+1}) = (g, ξ)`, from the left map's inverse at `(g_k⁻¹, g_{k+1}⁻¹)`.
    pub fn inverse<G: LieGroup>(
        &self,
        gk: &G,
        gk1: &G,
    ) -> Result<(G, G::Algebra), DiscretizationError>
    where
        T: Tau<G>,
    {
        let (k, xi) = self.left.inverse(&gk.inverse(), &gk1.inverse())?;
        Ok((k.inverse(), xi.neg()))
    }
}

impl<T> ThetaFamily for RightDiscretizationMap<T> {
    fn with_theta(theta: f64) -> Result<Self, DiscretizationError> {
        Self::new(theta)
    }
}

/// The θ-map's factors used on the right: `R̃_d^R(g, ξ) = (a(−ξ)⁻¹ g, b(−ξ)⁻¹ g)` with
/// `a(−ξ)⁻¹ = τ(−θξ)`, `b(−ξ)⁻¹ = τ((1−θ)ξ)`; every descriptor is the left map's (ι preserves
/// them).
impl<G: LieGroup, T: Tau<G>> Discretization<G> for RightDiscretizationMap<T> {
    fn first_factor(&self, xi: &G::Algebra) -> G {
        self.left.first_factor(xi)
    }
    fn second_factor(&self, xi: &G::Algebra) -> G {
        self.left.second_factor(xi)
    }
    fn first_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        Discretization::<G>::first_factor_tangent(&self.left, xi)
    }
    fn second_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        Discretization::<G>::second_factor_tangent(&self.left, xi)
    }
    fn label(&self) -> String {
        format!("tau={}, right", T::NAME)
    }
    fn side(&self) -> Side {
        Side::Right
    }
    fn theta(&self) -> f64 {
        self.left.theta()
    }
    fn symmetric(&self) -> bool {
        Discretization::<G>::symmetric(&self.left)
    }
    fn order(&self) -> u32 {
        Discretization::<G>::order(&self.left)
    }
    fn reversible_increment(&self) -> bool {
        Discretization::<G>::reversible_increment(&self.left)
    }
    fn increment_order(&self) -> u32 {
        Discretization::<G>::increment_order(&self.left)
    }
    fn base_is_first_point(&self) -> bool {
        Discretization::<G>::base_is_first_point(&self.left)
    }
    /// The left map's at −η.
    fn check_domain(&self, eta: &G::Algebra) -> Result<(), DiscretizationError> {
        Discretization::<G>::check_domain(&self.left, &eta.neg())
    }
}

/// The components of the right-trivialized lifts: the left ones at −η, points multiplied on the
/// left (see the module page).
impl<G: LieGroup, T: Tau<G>> LiftedMap<G> for RightDiscretizationMap<T> {
    /// `ḡ = τ(θη) g_k`.
    fn base_point(&self, gk: &G, eta: &G::Algebra) -> G {
        T::tau(&eta.scale(self.theta())).compose(gk)
    }
    /// `g_{k+1} = τ((1−θ)η) ḡ`.
    fn second_point(&self, gbar: &G, eta: &G::Algebra) -> G {
        T::tau(&eta.scale(1.0 - self.theta())).compose(gbar)
    }
    /// `g_{k+1} = τ((1−θ)η) τ(θη) g_k = (g_k⁻¹ τ(−θη) τ(−(1−θ)η))⁻¹`, the left map's one product
    /// on the inverse.
    fn next_point(&self, gk: &G, eta: &G::Algebra) -> G {
        T::compose_tau_split(&gk.inverse(), self.theta(), &eta.neg()).inverse()
    }
    fn momentum_update(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        nu: Option<&G::Algebra>,
    ) -> MomentumUpdate<G::Algebra> {
        LiftedMap::<G>::momentum_update(&self.left, &eta.neg(), mu_k, nu)
    }
    fn base_momentum(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        mu_next: &G::Algebra,
    ) -> G::Algebra {
        LiftedMap::<G>::base_momentum(&self.left, &eta.neg(), mu_k, mu_next)
    }
    /// `∂μ̄/∂η = −(∂μ̄_L/∂η)(−η)`.
    fn base_momentum_derivative(
        &self,
        eta: &G::Algebra,
        mu_k: &G::Algebra,
        update: &MomentumUpdate<G::Algebra>,
    ) -> G::Operator {
        use lie_groups::Operator;
        LiftedMap::<G>::base_momentum_derivative(&self.left, &eta.neg(), mu_k, update).scale(-1.0)
    }
    /// The left map's at −η (μ̄ is affine in ν whatever the sign of η).
    fn base_momentum_impulse_derivative(&self, eta: &G::Algebra) -> Option<G::Operator> {
        LiftedMap::<G>::base_momentum_impulse_derivative(&self.left, &eta.neg())
    }
    /// `ḡ = τ(θη) g_k` moves by a derivative that depends on g_k: not provided (the right maps
    /// take no potential).
    fn base_point_derivative(&self, _eta: &G::Algebra) -> Option<G::Operator> {
        None
    }
    fn first_velocity(&self, eta: &G::Algebra, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        LiftedMap::<G>::first_velocity(&self.left, &eta.neg(), xi, zeta)
    }
    fn second_velocity(&self, eta: &G::Algebra, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        LiftedMap::<G>::second_velocity(&self.left, &eta.neg(), xi, zeta)
    }
    /// The left map's at −h.
    fn first_velocity_increment(&self, h: f64, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        LiftedMap::<G>::first_velocity_increment(&self.left, -h, xi, zeta)
    }
    /// The left map's at −h.
    fn second_velocity_increment(&self, h: f64, xi: &G::Algebra, zeta: &G::Algebra) -> G::Algebra {
        LiftedMap::<G>::second_velocity_increment(&self.left, -h, xi, zeta)
    }
    /// The left map's at −h: `first_velocity(hξ, ξ, ζ) = first_velocity_L((−h)ξ, ξ, ζ)`.
    fn first_velocity_derivative(
        &self,
        h: f64,
        xi: &G::Algebra,
        zeta: &G::Algebra,
    ) -> (G::Operator, G::Operator) {
        LiftedMap::<G>::first_velocity_derivative(&self.left, -h, xi, zeta)
    }
}
