//! τ maps (§3.1 of the paper): local diffeomorphisms τ: 𝔤 → G around 0 ↦ e with
//! τ(ξ) τ(−ξ) = e, used by retractions `g τ(ξ)` and discretization maps.
//!
//! A τ map is a type of its own, separate from the group, so that every integrator is generic over
//! it: [`ExpMap`] works on every [`LieGroup`], [`Cayley`] on every [`CayleyGroup`].
//!
//! Tangent maps, in the paper's notation:
//! - left-trivialized: `d^L τ_ξ (η) = τ(ξ)⁻¹ · (d/ds) τ(ξ + s η)|_{s=0}`;
//! - right-trivialized: `d^R τ_ξ (η) = (d/ds) τ(ξ + s η)|_{s=0} · τ(ξ)⁻¹`, which equals `d^L τ_{−ξ}`
//!   because τ(ξ)⁻¹ = τ(−ξ) (differentiate τ(ξ) τ(−ξ) = e);
//! - duals `d^{L*} τ_ξ`, `d^{R*} τ_ξ` are the transposes under the Euclidean pairing.

use crate::{LieError, LieGroup, Operator, Vector};
use core::fmt::Debug;

/// A local diffeomorphism τ: 𝔤 → G with τ(0) = e, d τ_0 = id and τ(ξ) τ(−ξ) = e.
pub trait Tau<G: LieGroup>: Copy + Debug + Default + Send + Sync + 'static {
    /// Short name: `"exp"` or `"cayley"`.
    const NAME: &'static str;
    /// Whether s ↦ τ(sξ) is a one-parameter subgroup, τ(sξ) τ(tξ) = τ((s+t)ξ) (true for exp only).
    /// Discretization maps use it: then τ(θξ) τ((1−θ)ξ) = τ(ξ) and R̃_d inverts in closed form.
    const ONE_PARAMETER_SUBGROUP: bool = false;
    /// Whether τ(ξ) commutes with ξ: `Ad_{τ(ξ)} ξ = ξ` for every ξ (true for exp and Cayley,
    /// functions of ξ̂; the axioms of τ do not imply it — `k(ξ) exp(ξ) k(ξ)⁻¹` with k even and
    /// k(0) = e satisfies them). Tangent lifts use it: along the field's step η = hξ the terms
    /// `(Ad_{τ(sη)} − I) ξ` of the Euler–Poincaré step then vanish exactly and are not formed.
    const COMMUTES_WITH_ARGUMENT: bool = false;
    /// A radius r such that `τ⁻¹(τ(ξ)) = ξ` holds to round-off (relative error ≤ 1e-8) for every
    /// ‖ξ‖ ≤ r; 0 where no such bound is known. Integrators skip their domain check (the round trip)
    /// inside it. [`ExpMap`] and [`Cayley`] take it from [`LieGroup::EXP_INVERTIBLE_RADIUS`] and
    /// [`CayleyGroup::CAY_INVERTIBLE_RADIUS`].
    const INVERTIBLE_RADIUS: f64 = 0.0;

    /// τ(ξ).
    fn tau(xi: &G::Algebra) -> G;
    /// τ⁻¹(g), the local inverse; an error outside its domain.
    fn tau_inv(g: &G) -> Result<G::Algebra, LieError>;
    /// `d^L τ_ξ`.
    fn dtau_left(xi: &G::Algebra) -> G::Operator;
    /// `(d^L τ_ξ)⁻¹`; non-finite entries where d^L τ_ξ is singular.
    fn dtau_left_inv(xi: &G::Algebra) -> G::Operator;

    /// `d^R τ_ξ = d^L τ_{−ξ}`.
    fn dtau_right(xi: &G::Algebra) -> G::Operator {
        Self::dtau_left(&xi.neg())
    }
    /// `(d^R τ_ξ)⁻¹ = (d^L τ_{−ξ})⁻¹`.
    fn dtau_right_inv(xi: &G::Algebra) -> G::Operator {
        Self::dtau_left_inv(&xi.neg())
    }
    /// The increment `(Ad*_{τ(ξ)} − I) μ`, linear in μ, computed from ξ directly where the group
    /// has a closed form (see [`LieGroup::exp_coadjoint_increment`]; the provided form builds
    /// τ(ξ)).
    fn tau_coadjoint_increment(xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        Self::tau(xi).coadjoint_apply(mu).sub(mu)
    }
    /// The increment `(Ad_{τ(ξ)} − I) v`, linear in v, the adjoint counterpart of
    /// [`Tau::tau_coadjoint_increment`]: computed from ξ directly where the group has a closed
    /// form ([`LieGroup::exp_adjoint_increment`], [`CayleyGroup::cay_adjoint_increment`]), so
    /// that its rounding is relative to its size O(|ξ||v|); the provided form builds τ(ξ) and
    /// rounds at ε|v|. (On SO(3), where Ad is orthogonal, `Ad_{τ(ξ)} = Ad*_{τ(−ξ)}` and this is
    /// `tau_coadjoint_increment(−ξ, v)`; on SE(3) and SE(2) the two differ.)
    fn tau_adjoint_increment(xi: &G::Algebra, v: &G::Algebra) -> G::Algebra {
        Self::tau(xi).adjoint_apply(v).sub(v)
    }
    /// `g τ(ξ)`, in the increment form `g + g (τ(ξ) − I)` where the group has one
    /// ([`LieGroup::exp_compose`]).
    fn compose_tau(g: &G, xi: &G::Algebra) -> G {
        g.compose(&Self::tau(xi))
    }
    /// `g τ(θξ) τ((1−θ)ξ)`, the two factors of a discretization map's step in one product where
    /// τ allows it: for exp the product is `g exp(ξ)` (a one-parameter subgroup), for the Cayley
    /// map of SO(3) `g cay(ξ / (1 − θ(1−θ)|ξ|²/4))` (parallel Gibbs vectors compose by the tangent
    /// addition formula); otherwise the two products.
    fn compose_tau_split(g: &G, theta: f64, xi: &G::Algebra) -> G {
        Self::compose_tau(
            &Self::compose_tau(g, &xi.scale(theta)),
            &xi.scale(1.0 - theta),
        )
    }
    /// The increment `(Ad*_{τ((1−θ)ξ)} Ad*_{τ(θξ)} − I) μ = (Ad*_{τ(θξ) τ((1−θ)ξ)} − I) μ`, the
    /// coadjoint counterpart of [`Tau::compose_tau_split`]: one increment where the two factors
    /// are one element τ(cξ) (exp: c = 1; Cayley on SO(3): the Gibbs composition), otherwise
    /// `δ_a μ + δ_b μ + δ_b(δ_a μ)` with `δ_ζ = Ad*_{τ(ζ)} − I`, a = θξ, b = (1−θ)ξ.
    fn tau_split_coadjoint_increment(theta: f64, xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        split_increment_of_factors::<G, Self>(theta, xi, mu)
    }
    /// `½ d^{L*}τ_{−a} (μ + Ad*_{τ(a)} μ)`, the base momentum of the midpoint (θ = ½) map with
    /// a = η/2 and no impulse (see `discretization`'s `LiftedMap::base_momentum_from_impulse`).
    /// The provided form is that composition (one coadjoint increment, one dual tangent);
    /// Cayley on SO(3) has the closed form `Ad*_{cay(a)} μ / (1 + |a|²/4)` (one division).
    fn midpoint_base_momentum(a: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        let x = mu.add(mu).add(&Self::tau_coadjoint_increment(a, mu));
        Self::dtau_left_dual_apply(&a.neg(), &x).scale(0.5)
    }
    /// `d^{L*} τ_ξ μ = (d^L τ_ξ)ᵀ μ`.
    fn dtau_left_dual_apply(xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        Self::dtau_left(xi).apply_transpose(mu)
    }
    /// `d^{R*} τ_ξ μ = (d^R τ_ξ)ᵀ μ`.
    fn dtau_right_dual_apply(xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        Self::dtau_right(xi).apply_transpose(mu)
    }
    /// `D τ(ξ; μ) := ∂/∂ξ (d^{L*}τ_ξ μ)`, the operator `δ ↦ (d/ds) d^{L*}τ_{ξ+sδ} μ |_{s=0}`.
    ///
    /// [`ExpMap`] and [`Cayley`] delegate to [`LieGroup::dexp_left_dual_derivative`] (exact on
    /// every group) and [`CayleyGroup::dcay_left_dual_derivative`] (exact on SO(3), SE(3), SE(2)
    /// and the composite groups built from them); the
    /// provided form is the first-order approximation `δ ↦ −½ ad*_δ μ`, exact at ξ = 0 for every
    /// τ with `τ(ξ) = exp(ξ) + O(ξ³)`.
    fn dtau_left_dual_derivative(_xi: &G::Algebra, mu: &G::Algebra) -> G::Operator {
        crate::group::half_ad_dual_operator::<G>(mu)
    }
    /// `E τ(ξ; v) := ∂/∂ξ (d^Lτ_ξ v)`, the operator `δ ↦ (d/ds) d^Lτ_{ξ+sδ} v |_{s=0}`: the
    /// second derivative of τ that Newton's matrix for the Euler–Poincaré step needs (its
    /// velocities apply d^Lτ, not the dual).
    ///
    /// Differentiating `⟨μ, d^Lτ_ξ v⟩ = ⟨d^{L*}τ_ξ μ, v⟩` gives `⟨μ, E(ξ; v) δ⟩ = ⟨D(ξ; μ) δ, v⟩`
    /// ([`Tau::dtau_left_dual_derivative`]), so the i-th row of E is `vᵀ D(ξ; eᵢ)`: n evaluations
    /// of D, exact wherever D is (exp on every group, Cayley on SO(3), SE(3), SE(2)); at ξ = 0 it
    /// is `½ ad_v` (from `d^Lτ_ξ = I − ½ ad_ξ + O(ξ²)`).
    fn dtau_left_derivative(xi: &G::Algebra, v: &G::Algebra) -> G::Operator {
        let n = G::dim();
        // Row i of E is (D(ξ; eᵢ)ᵀ v)ᵀ: Eᵀ column by column, one D each (on the stack for the
        // fixed-size groups).
        crate::matrix_path::operator_from_column_fn::<G>(|i| {
            Self::dtau_left_dual_derivative(xi, &G::Algebra::basis(n, i)).apply_transpose(v)
        })
        .transpose()
    }
}

/// `δ_a μ + δ_b μ + δ_b(δ_a μ)` (a = θξ, b = (1−θ)ξ, `δ_ζ = Ad*_{τ(ζ)} − I`): the provided
/// [`Tau::tau_split_coadjoint_increment`], factor by factor (one factor skipped at θ ∈ {0, 1}).
pub(crate) fn split_increment_of_factors<G: LieGroup, T: Tau<G>>(
    theta: f64,
    xi: &G::Algebra,
    mu: &G::Algebra,
) -> G::Algebra {
    if theta == 0.0 {
        return T::tau_coadjoint_increment(xi, mu);
    }
    if theta == 1.0 {
        return T::tau_coadjoint_increment(xi, mu);
    }
    let a = T::tau_coadjoint_increment(&xi.scale(theta), mu);
    let eb = xi.scale(1.0 - theta);
    a.add(&T::tau_coadjoint_increment(&eb, mu))
        .add(&T::tau_coadjoint_increment(&eb, &a))
}

/// τ = exp, the group exponential, on every Lie group.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ExpMap;

impl<G: LieGroup> Tau<G> for ExpMap {
    const NAME: &'static str = "exp";
    const ONE_PARAMETER_SUBGROUP: bool = true;
    /// exp(ξ) = Σ ξ̂ᵏ/k! commutes with ξ̂.
    const COMMUTES_WITH_ARGUMENT: bool = true;
    const INVERTIBLE_RADIUS: f64 = G::EXP_INVERTIBLE_RADIUS;
    #[inline]
    fn tau(xi: &G::Algebra) -> G {
        G::exp(xi)
    }
    #[inline]
    fn tau_inv(g: &G) -> Result<G::Algebra, LieError> {
        g.log()
    }
    #[inline]
    fn dtau_left(xi: &G::Algebra) -> G::Operator {
        G::dexp_left(xi)
    }
    #[inline]
    fn dtau_left_inv(xi: &G::Algebra) -> G::Operator {
        G::dexp_left_inv(xi)
    }
    #[inline]
    fn dtau_right(xi: &G::Algebra) -> G::Operator {
        G::dexp_right(xi)
    }
    #[inline]
    fn dtau_right_inv(xi: &G::Algebra) -> G::Operator {
        G::dexp_right_inv(xi)
    }
    #[inline]
    fn tau_coadjoint_increment(xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        G::exp_coadjoint_increment(xi, mu)
    }
    #[inline]
    fn tau_adjoint_increment(xi: &G::Algebra, v: &G::Algebra) -> G::Algebra {
        G::exp_adjoint_increment(xi, v)
    }
    #[inline]
    fn compose_tau(g: &G, xi: &G::Algebra) -> G {
        G::exp_compose(g, xi)
    }
    /// `g exp(θξ) exp((1−θ)ξ) = g exp(ξ)`.
    #[inline(always)]
    fn compose_tau_split(g: &G, _theta: f64, xi: &G::Algebra) -> G {
        G::exp_compose(g, xi)
    }
    /// `exp(θξ) exp((1−θ)ξ) = exp ξ`: one increment.
    #[inline]
    fn tau_split_coadjoint_increment(_theta: f64, xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        G::exp_coadjoint_increment(xi, mu)
    }
    #[inline]
    fn dtau_left_dual_apply(xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        G::dexp_left_dual_apply(xi, mu)
    }
    #[inline]
    fn dtau_left_dual_derivative(xi: &G::Algebra, mu: &G::Algebra) -> G::Operator {
        G::dexp_left_dual_derivative(xi, mu)
    }
}

/// A group with a Cayley map `cay(ξ) = (I − ξ̂/2)⁻¹ (I + ξ̂/2)` (quadratic matrix groups: SO(n),
/// SE(n), and GL(n) away from eigenvalue −2 of ξ̂).
///
/// The left-trivialized tangent and its inverse, as maps of algebra matrices, are
/// `d^L cay_ξ (η) = (I + ξ̂/2)⁻¹ η̂ (I − ξ̂/2)⁻¹` and
/// `(d^L cay_ξ)⁻¹ (η) = η̂ + [ξ̂, η̂]/2 − ξ̂ η̂ ξ̂/4`; groups implement closed forms in coordinates
/// and [`crate::matrix_path`] gives the generic matrix evaluation they are tested against.
pub trait CayleyGroup: LieGroup {
    /// cay(ξ). Infallible like [`LieGroup::exp`]: non-finite for a non-finite ξ (or where
    /// `I − ξ̂/2` is singular, which no skew ξ makes); [`CayleyGroup::try_cay`] checks.
    fn cay(xi: &Self::Algebra) -> Self;
    /// `cay` checked: [`LieError::NonFinite`] for a ξ holding NaN or an infinity,
    /// [`LieError::Overflow`] when a finite ξ gives a non-finite element.
    fn try_cay(xi: &Self::Algebra) -> Result<Self, LieError> {
        if !xi.is_finite() {
            return Err(LieError::NonFinite {
                what: "algebra element ξ",
            });
        }
        let g = Self::cay(xi);
        if g.is_finite() {
            Ok(g)
        } else {
            Err(LieError::Overflow {
                map: crate::GroupMap::Cay,
                size: xi.norm_max(),
            })
        }
    }
    /// cay⁻¹(g) = 2 (g − I)(g + I)⁻¹ read back through `vee`; an error where g + I is singular.
    fn cay_inv(&self) -> Result<Self::Algebra, LieError>;
    /// A radius r such that `cay⁻¹(cay ξ) = ξ` holds to round-off (relative error ≤ 1e-8) for
    /// every ‖ξ‖ ≤ r; 0 where no such bound is known. On SO(3) cay is a diffeomorphism onto the
    /// rotations by less than π, and the round trip loses accuracy only as (g + I) nears
    /// singularity: relative error ≈ ε ‖ξ‖²/16, far below 1e-8 up to r = 1000.
    const CAY_INVERTIBLE_RADIUS: f64 = 0.0;
    /// `d^L cay_ξ`.
    fn dcay_left(xi: &Self::Algebra) -> Self::Operator;
    /// `(d^L cay_ξ)⁻¹`.
    fn dcay_left_inv(xi: &Self::Algebra) -> Self::Operator;
    /// `(Ad*_{cay ξ} − I) μ`; groups override it as for [`LieGroup::exp_coadjoint_increment`].
    fn cay_coadjoint_increment(xi: &Self::Algebra, mu: &Self::Algebra) -> Self::Algebra {
        Self::cay(xi).coadjoint_apply(mu).sub(mu)
    }
    /// `(Ad_{cay ξ} − I) v`; groups override it as for [`LieGroup::exp_adjoint_increment`].
    fn cay_adjoint_increment(xi: &Self::Algebra, v: &Self::Algebra) -> Self::Algebra {
        Self::cay(xi).adjoint_apply(v).sub(v)
    }
    /// `g cay ξ`; groups override it with the increment form of [`LieGroup::exp_compose`].
    fn cay_compose(g: &Self, xi: &Self::Algebra) -> Self {
        g.compose(&Self::cay(xi))
    }
    /// `g cay(θξ) cay((1−θ)ξ)`; groups with a composition formula for parallel arguments override
    /// it (SO(3)).
    fn cay_split_compose(g: &Self, theta: f64, xi: &Self::Algebra) -> Self {
        Self::cay_compose(
            &Self::cay_compose(g, &xi.scale(theta)),
            &xi.scale(1.0 - theta),
        )
    }
    /// `(Ad*_{cay((1−θ)ξ)} Ad*_{cay(θξ)} − I) μ` ([`Tau::tau_split_coadjoint_increment`]);
    /// groups with a composition formula for parallel arguments override it as
    /// [`CayleyGroup::cay_split_compose`] (SO(3)).
    fn cay_split_coadjoint_increment(
        theta: f64,
        xi: &Self::Algebra,
        mu: &Self::Algebra,
    ) -> Self::Algebra {
        split_increment_of_factors::<Self, Cayley>(theta, xi, mu)
    }
    /// `½ d^{L*}cay_{−a} (μ + Ad*_{cay(a)} μ)` ([`Tau::midpoint_base_momentum`]); the provided
    /// form composes the two maps, SO(3) has a closed form.
    fn cay_midpoint_base_momentum(a: &Self::Algebra, mu: &Self::Algebra) -> Self::Algebra {
        let x = mu.add(mu).add(&Self::cay_coadjoint_increment(a, mu));
        Self::dcay_left_dual_apply(&a.neg(), &x).scale(0.5)
    }
    /// `d^{L*}cay_ξ μ = (d^L cay_ξ)ᵀ μ`. The provided form builds d^L cay_ξ; groups override it
    /// with a closed form that skips the operator.
    fn dcay_left_dual_apply(xi: &Self::Algebra, mu: &Self::Algebra) -> Self::Algebra {
        Self::dcay_left(xi).apply_transpose(mu)
    }
    /// `D cay(ξ; μ) := ∂/∂ξ (d^{L*}cay_ξ μ)`, the operator `δ ↦ (d/ds) d^{L*}cay_{ξ+sδ} μ |_{s=0}`.
    ///
    /// The provided form is the first-order approximation `δ ↦ −½ ad*_δ μ`: from
    /// `d^{L*}cay_ξ = I − ½ ad*_ξ + O(ξ²)` it is exact at ξ = 0 and off by O(|ξ| |μ|) elsewhere.
    /// Groups with a closed form override it with the exact derivative.
    fn dcay_left_dual_derivative(_xi: &Self::Algebra, mu: &Self::Algebra) -> Self::Operator {
        crate::group::half_ad_dual_operator::<Self>(mu)
    }
}

/// τ = cay, the Cayley map, on every [`CayleyGroup`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Cayley;

impl<G: CayleyGroup> Tau<G> for Cayley {
    const NAME: &'static str = "cayley";
    /// cay(ξ) = (I − ξ̂/2)⁻¹(I + ξ̂/2) commutes with ξ̂.
    const COMMUTES_WITH_ARGUMENT: bool = true;
    const INVERTIBLE_RADIUS: f64 = G::CAY_INVERTIBLE_RADIUS;
    #[inline]
    fn tau(xi: &G::Algebra) -> G {
        G::cay(xi)
    }
    #[inline]
    fn tau_inv(g: &G) -> Result<G::Algebra, LieError> {
        g.cay_inv()
    }
    #[inline]
    fn dtau_left(xi: &G::Algebra) -> G::Operator {
        G::dcay_left(xi)
    }
    #[inline]
    fn dtau_left_inv(xi: &G::Algebra) -> G::Operator {
        G::dcay_left_inv(xi)
    }
    #[inline]
    fn tau_coadjoint_increment(xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        G::cay_coadjoint_increment(xi, mu)
    }
    #[inline]
    fn tau_adjoint_increment(xi: &G::Algebra, v: &G::Algebra) -> G::Algebra {
        G::cay_adjoint_increment(xi, v)
    }
    #[inline]
    fn compose_tau(g: &G, xi: &G::Algebra) -> G {
        G::cay_compose(g, xi)
    }
    #[inline(always)]
    fn compose_tau_split(g: &G, theta: f64, xi: &G::Algebra) -> G {
        G::cay_split_compose(g, theta, xi)
    }
    #[inline]
    fn tau_split_coadjoint_increment(theta: f64, xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        G::cay_split_coadjoint_increment(theta, xi, mu)
    }
    #[inline(always)]
    fn midpoint_base_momentum(a: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        G::cay_midpoint_base_momentum(a, mu)
    }
    #[inline]
    fn dtau_left_dual_apply(xi: &G::Algebra, mu: &G::Algebra) -> G::Algebra {
        G::dcay_left_dual_apply(xi, mu)
    }
    #[inline]
    fn dtau_left_dual_derivative(xi: &G::Algebra, mu: &G::Algebra) -> G::Operator {
        G::dcay_left_dual_derivative(xi, mu)
    }
}
