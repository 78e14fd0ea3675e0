//! The default path of [`LiftedMap`]: every component a step evaluates, composed from the
//! general lifts of a [`Discretization`] (κ̃, α̃, Φ̃ and the products of TG and T*G, see the page of
//! [`crate::LiftedMap`]), and [`Composed`], a map with nothing but that path.
//!
//! Each component is written once for the left map (`left_*`) and carried to a right-sided map by
//! the inversion ι(g) = g⁻¹: the left component at −η, points multiplied on the left, ∂/∂η of the
//! left one at −η negated (the page of [`crate::RightDiscretizationMap`] derives it).

use crate::finite_differences::jacobian;
use crate::{
    cotangent_lift_inverse_at, tangent_lift, Discretization, DiscretizationError, LiftedMap,
    MomentumUpdate, Side, ThetaFamily,
};
use lie_groups::{LieGroup, Operator, Vector};
use trivial_bundles::prelude::*;

/// A map M with every [`LiftedMap`] component taken from the default path — the composition of
/// the paper's lifts from M's factors — whatever M overrides. `Composed(DiscretizationMap::new(θ))`
/// is the θ-map without its fused formulas: the tests pin the fused components to it, and its
/// integrators to the fused ones. The descriptors are M's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Composed<M>(pub M);

impl<M: ThetaFamily> ThetaFamily for Composed<M> {
    fn with_theta(theta: f64) -> Result<Self, DiscretizationError> {
        M::with_theta(theta).map(Composed)
    }
}

impl<G: LieGroup, M: Discretization<G>> Discretization<G> for Composed<M> {
    fn first_factor(&self, xi: &G::Algebra) -> G {
        self.0.first_factor(xi)
    }
    fn second_factor(&self, xi: &G::Algebra) -> G {
        self.0.second_factor(xi)
    }
    fn first_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        self.0.first_factor_tangent(xi)
    }
    fn second_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        self.0.second_factor_tangent(xi)
    }
    fn label(&self) -> String {
        format!("{}, composed", self.0.label())
    }
    fn side(&self) -> Side {
        self.0.side()
    }
    fn theta(&self) -> f64 {
        self.0.theta()
    }
    fn symmetric(&self) -> bool {
        self.0.symmetric()
    }
    fn order(&self) -> u32 {
        self.0.order()
    }
    fn reversible_increment(&self) -> bool {
        self.0.reversible_increment()
    }
    fn increment_order(&self) -> u32 {
        self.0.increment_order()
    }
    fn base_is_first_point(&self) -> bool {
        self.0.base_is_first_point()
    }
    fn check_domain(&self, eta: &G::Algebra) -> Result<(), DiscretizationError> {
        self.0.check_domain(eta)
    }
}

impl<G: LieGroup, M: Discretization<G>> LiftedMap<G> for Composed<M> {}

/// η for the left map: η itself on the left, −η on the right.
fn left_eta<G: LieGroup, M: Discretization<G>>(map: &M, eta: &G::Algebra) -> G::Algebra {
    match map.side() {
        Side::Left => eta.clone(),
        Side::Right => eta.neg(),
    }
}

/// `ḡ = g_k a(η)⁻¹`; on the right `(g_k⁻¹ a(−η)⁻¹)⁻¹ = a(−η) g_k`.
pub(crate) fn base_point<G: LieGroup, M: Discretization<G>>(
    map: &M,
    gk: &G,
    eta: &G::Algebra,
) -> G {
    match map.side() {
        Side::Left => gk.compose(&map.first_factor(eta).inverse()),
        Side::Right => map.first_factor(&eta.neg()).compose(gk),
    }
}

/// `g_{k+1} = ḡ b(η)`; on the right `(ḡ⁻¹ b(−η))⁻¹ = b(−η)⁻¹ ḡ`.
pub(crate) fn second_point<G: LieGroup, M: Discretization<G>>(
    map: &M,
    gbar: &G,
    eta: &G::Algebra,
) -> G {
    match map.side() {
        Side::Left => gbar.compose(&map.second_factor(eta)),
        Side::Right => map.second_factor(&eta.neg()).inverse().compose(gbar),
    }
}

/// `(Ad*_g − I) μ` for g near e, in increment form: `exp_coadjoint_increment(log g, μ)`, computed
/// from log g and rounded relative to its own size O(|log g||μ|) (`LieGroup::exp_coadjoint_increment`)
/// — the rounding of g's entries `1 − O(|log g|²)` does not enter. Where log g does not exist, the
/// product with g's matrix, rounded at ε|μ|.
fn coadjoint_increment<G: LieGroup>(
    g: &G,
    log: &Option<G::Algebra>,
    mu: &G::Algebra,
) -> G::Algebra {
    match log {
        Some(x) => G::exp_coadjoint_increment(x, mu),
        None => g.coadjoint_apply(mu).sub(mu),
    }
}

/// `(Ad_g − I) v`, the adjoint counterpart of [`coadjoint_increment`].
fn adjoint_increment<G: LieGroup>(g: &G, v: &G::Algebra) -> G::Algebra {
    match finite_log(g) {
        Some(x) => G::exp_adjoint_increment(&x, v),
        None => g.adjoint_apply(v).sub(v),
    }
}

fn finite_log<G: LieGroup>(g: &G) -> Option<G::Algebra> {
    g.log().ok().filter(Vector::is_finite)
}

/// The product `(e, μ_k)·(a(η)⁻¹, 0)·(e, ν)·(b(η), 0) = (a⁻¹b, μ_{k+1})` of T*G
/// (`(g, μ)(h, ν) = (gh, Ad*_h μ + ν)`): μ_k carried to the base point (`transported`), kicked by
/// ν, carried to the second point — evaluated in increment form, as the θ-map's: with
/// `δ_g = Ad*_g − I` ([`coadjoint_increment`]), `Δ = δ_{a⁻¹}(μ_k) + ν` and
/// `μ_{k+1} − μ_k = Δ + δ_b(μ_k) + δ_b(Δ)`, so μ_k enters once and |μ|² follows the rounding of
/// the increments, not of a(η)'s and b(η)'s entries.
fn left_momentum_update<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    mu_k: &G::Algebra,
    nu: Option<&G::Algebra>,
) -> MomentumUpdate<G::Algebra> {
    let a_inv = map.first_factor(eta).inverse();
    let b = map.second_factor(eta);
    let carried = coadjoint_increment(&a_inv, &finite_log(&a_inv), mu_k);
    let transported = mu_k.add(&carried);
    let kick = match nu {
        Some(nu) => carried.add(nu),
        None => carried,
    };
    let log_b = finite_log(&b);
    let increment = kick
        .add(&coadjoint_increment(&b, &log_b, mu_k))
        .add(&coadjoint_increment(&b, &log_b, &kick));
    MomentumUpdate {
        transported,
        next: mu_k.add(&increment),
        increment,
    }
}

pub(crate) fn momentum_update<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    mu_k: &G::Algebra,
    nu: Option<&G::Algebra>,
) -> MomentumUpdate<G::Algebra> {
    left_momentum_update(map, &left_eta(map, eta), mu_k, nu)
}

/// The μ-component of `α̃⁻¹ ∘ T*R̃_d ∘ Φ̃⁻¹` at `(e, η)`.
fn left_base_momentum<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    mu_k: &G::Algebra,
    mu_next: &G::Algebra,
) -> G::Algebra {
    let base = TangentBundle::from_parts(G::identity(), eta.clone());
    cotangent_lift_inverse_at(map, &base, mu_k, mu_next)
        .mu()
        .clone()
}

pub(crate) fn base_momentum<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    mu_k: &G::Algebra,
    mu_next: &G::Algebra,
) -> G::Algebra {
    left_base_momentum(map, &left_eta(map, eta), mu_k, mu_next)
}

/// `∂μ̄/∂η` with ν fixed, by differences of η ↦ μ̄(η, μ_k, μ_{k+1}(η; ν)); ν is read back from
/// the update: `(e, μ_{k+1})·(b(η)⁻¹, 0)` has the fibre `Ad*_{b⁻¹} μ_{k+1} = transported + ν`.
fn left_base_momentum_derivative<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    mu_k: &G::Algebra,
    update: &MomentumUpdate<G::Algebra>,
) -> G::Operator {
    let back = CotangentBundle::from_parts(G::identity(), update.next.clone()).compose(
        &CotangentBundle::from_parts(
            map.second_factor(eta).inverse(),
            G::Algebra::zeros(G::dim()),
        ),
    );
    let nu = back.fiber().sub(&update.transported);
    jacobian::<G>(
        |e| {
            let next = left_momentum_update(map, e, mu_k, Some(&nu)).next;
            left_base_momentum(map, e, mu_k, &next)
        },
        eta,
    )
}

pub(crate) fn base_momentum_derivative<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    mu_k: &G::Algebra,
    update: &MomentumUpdate<G::Algebra>,
) -> G::Operator {
    match map.side() {
        Side::Left => left_base_momentum_derivative(map, eta, mu_k, update),
        Side::Right => left_base_momentum_derivative(map, &eta.neg(), mu_k, update).scale(-1.0),
    }
}

/// `∂μ̄/∂ν = d^{L*}b_η Ad*_{b(η)} = (Ad_{b(η)} d^L b_η)ᵀ` (from `μ_{k+1} = Ad*_b(… + ν)`).
pub(crate) fn base_momentum_impulse_derivative<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
) -> G::Operator {
    let e = left_eta(map, eta);
    map.second_factor(&e)
        .adjoint()
        .compose(&map.second_factor_tangent(&e))
        .transpose()
}

/// `ḡ = g_k a(η)⁻¹`: `ḡ⁻¹∂ḡ = a ∂(a⁻¹) = −(∂a) a⁻¹ = −Ad_a (a⁻¹∂a) = −Ad_{a(η)} d^L a_η`. Not on
/// the right (it depends on g_k there).
pub(crate) fn base_point_derivative<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
) -> Option<G::Operator> {
    match map.side() {
        Side::Left => Some(
            map.first_factor(eta)
                .adjoint()
                .compose(&map.first_factor_tangent(eta))
                .scale(-1.0),
        ),
        Side::Right => None,
    }
}

/// The two velocities of `R̃_d^T(e, ξ, η, ζ)` (eq. 16), for the left map.
fn left_velocities<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    xi: &G::Algebra,
    zeta: &G::Algebra,
) -> (G::Algebra, G::Algebra) {
    let x = Ttg::<G>::new(G::identity(), xi.clone(), eta.clone(), zeta.clone());
    let (first, second) = tangent_lift(map, &x);
    (first.into_parts().1, second.into_parts().1)
}

pub(crate) fn first_velocity<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    xi: &G::Algebra,
    zeta: &G::Algebra,
) -> G::Algebra {
    left_velocities(map, &left_eta(map, eta), xi, zeta).0
}

pub(crate) fn second_velocity<G: LieGroup, M: Discretization<G>>(
    map: &M,
    eta: &G::Algebra,
    xi: &G::Algebra,
    zeta: &G::Algebra,
) -> G::Algebra {
    left_velocities(map, &left_eta(map, eta), xi, zeta).1
}

/// `(A, B)`: A by differences of ξ ↦ ξ_k(hξ, ξ, ζ) at fixed ζ, `B = d^L a_{hξ}` (ξ_k is
/// `Ad_{a⁻¹} ξ + d^L a_η ζ`, linear in ζ). On the right: the left map's at −h.
pub(crate) fn first_velocity_derivative<G: LieGroup, M: Discretization<G>>(
    map: &M,
    h: f64,
    xi: &G::Algebra,
    zeta: &G::Algebra,
) -> (G::Operator, G::Operator) {
    let h = left_h(map, h);
    let a = jacobian::<G>(|x| left_velocities(map, &x.scale(h), x, zeta).0, xi);
    (a, map.first_factor_tangent(&xi.scale(h)))
}

/// `ξ_k − ξ = (Ad_{a(hξ)⁻¹} − I) ξ + d^L a_{hξ} ζ` (the first velocity of `R̃_d^T(e, ξ, hξ, ζ)`
/// less ξ), the Ad term in increment form ([`adjoint_increment`]): rounded relative to
/// O(h|ξ|² + |ζ|), not to |ξ|. On the right: the left map's at −h.
pub(crate) fn first_velocity_increment<G: LieGroup, M: Discretization<G>>(
    map: &M,
    h: f64,
    xi: &G::Algebra,
    zeta: &G::Algebra,
) -> G::Algebra {
    let eta = xi.scale(left_h(map, h));
    adjoint_increment(&map.first_factor(&eta).inverse(), xi)
        .add(&map.first_factor_tangent(&eta).apply(zeta))
}

/// `ξ_{k+1} − ξ = (Ad_{b(hξ)⁻¹} − I) ξ + d^L b_{hξ} ζ`, as [`first_velocity_increment`].
pub(crate) fn second_velocity_increment<G: LieGroup, M: Discretization<G>>(
    map: &M,
    h: f64,
    xi: &G::Algebra,
    zeta: &G::Algebra,
) -> G::Algebra {
    let eta = xi.scale(left_h(map, h));
    adjoint_increment(&map.second_factor(&eta).inverse(), xi)
        .add(&map.second_factor_tangent(&eta).apply(zeta))
}

/// h for the left map: h itself on the left, −h on the right.
fn left_h<G: LieGroup, M: Discretization<G>>(map: &M, h: f64) -> f64 {
    match map.side() {
        Side::Left => h,
        Side::Right => -h,
    }
}
