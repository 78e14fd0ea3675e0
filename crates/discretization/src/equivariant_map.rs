//! [`Discretization`]: a left-equivariant discretization map given by its two factors,
//! `R̃_d(g, ξ) = (g a(ξ), g b(ξ))` — what a user implements to get Lie–Poisson and Euler–Poincaré
//! integrators of their own map.
//!
//! ## The map and what its lifts need
//! Every discretization map `R̃_d: G ⋉ 𝔤 → G × G` that commutes with left translation,
//! `R̃_d(hg, ξ) = h R̃_d(g, ξ)`, is `R̃_d(g, ξ) = (g a(ξ), g b(ξ))` for two maps a, b: 𝔤 → G, its
//! points over the identity. The axioms of §3.2 read `a(0) = b(0) = e` (i) and
//! `d^L b_0 − d^L a_0 = id` (ii). The θ-family of the paper is `a(ξ) = τ(−θξ)`, `b(ξ) = τ((1−θ)ξ)`.
//! Its tangent map in trivialized form (`crate::tangent_map`) needs only a, b and their
//! left-trivialized tangents `d^L a_ξ(v) = a(ξ)⁻¹ (d/ds) a(ξ + s v)|_{s=0}`, `d^L b_ξ`: the body
//! velocity of `g a(ξ)` along a curve `(g, ξ)` with `g⁻¹δg = ξ̄` is `Ad_{a(ξ)⁻¹} ξ̄ + d^L a_ξ δξ`.
//! From these, [`crate::LiftedMap`] provides every component a step of eq. (18) or (19) evaluates,
//! composed from κ̃, α̃, Φ̃ and the products of TG and T*G.
//!
//! ## Descriptors, and the adjoint map
//! The adjoint of R̃_d swaps its points and reverses ξ: `R̃_d*(g, ξ) = (R̃_d²(g, −ξ), R̃_d¹(g, −ξ))`,
//! the factors `a*(ξ) = b(−ξ)`, `b*(ξ) = a(−ξ)` ([`crate::Adjoint`]; for the θ-family the adjoint
//! of θ is 1 − θ). Stepping the lifted integrator of R̃_d by h and that of R̃_d* by −h returns to
//! the start: at η* = −η the base point `g_{k+1} a*(η*)⁻¹ = g_{k+1} b(η)⁻¹` is ḡ again, the
//! impulse is −ν, the base momentum `−d^{L*}a*_{η*} μ_{k+1} + d^{L*}b*_{η*} μ_k` is μ̄ again
//! (`d^L a*_{−η} = −d^L b_η`), and so on component by component (`tests/adjoint.rs` checks it to
//! round-off). So the integrators of a map are symmetric when the map equals its adjoint,
//! `a(ξ) = b(−ξ)` ([`Discretization::symmetric`]).
//!
//! Order: write `a(ξ) = exp(−θξ + α₂(ξ) + O(|ξ|³))`, `b(ξ) = exp((1−θ)ξ + β₂(ξ) + O(|ξ|³))` with
//! α₂, β₂ quadratic. The integrator of eq. (11) steps `g_k⁻¹ g_{k+1} = a⁻¹b = exp(η + β₂ − α₂ + O(η³))`
//! with `η = h X(ḡ)` at `ḡ = g_k exp(θη − α₂ + …)`: against the exact `exp(hX + ½h² X'X + O(h³))` it
//! has order 2 iff θ = ½ and α₂ = β₂, i.e. iff `log(b(−ξ)⁻¹ a(ξ)) = (1−2θ)ξ + α₂ − β₂ + O(|ξ|³)`
//! vanishes to second order — iff the map agrees with its adjoint to second order (a symmetric
//! map does; so does no map with θ ≠ ½). The lifts keep that order ([`Discretization::order`];
//! the fitted orders of `tests/user_map.rs` confirm it for maps outside the θ-family).
//!
//! Without a potential or force the Lie–Poisson step sees only the increment
//! `c(ξ) = a(ξ)⁻¹ b(ξ) = g_k⁻¹ g_{k+1}`: from `c⁻¹δc = d^L b δη − Ad_{c⁻¹} d^L a δη` and
//! `Ad*_{c⁻¹} μ_{k+1} = μ_k`, the step is `μ_{k+1} = Ad*_{c(η)} μ_k`, `μ̄ = d^{L*}c_η μ_{k+1}`,
//! `g_{k+1} = g_k c(η)`. It is symmetric when c is reversible, `c(−ξ) = c(ξ)⁻¹`
//! ([`Discretization::reversible_increment`]: then η ↦ −η solves the step backwards, as for a τ
//! map), and of order 2 when `c(ξ) = exp(ξ + O(|ξ|³))`, i.e. `c(ξ) c(−ξ) = e + O(|ξ|³)`
//! ([`Discretization::increment_order`]). Every θ-map on exp or Cayley has a reversible increment
//! (its factors commute); a map whose factors do not commute need not.
//!
//! The provided descriptors measure these defects at two fixed probe directions and two sizes
//! (`probe_*` below), so a user's map reports what it is; maps that know override them (the
//! θ-family does, exactly).

use crate::finite_differences;
use crate::DiscretizationError;
use core::fmt::Debug;
use lie_groups::{LieGroup, Operator, Vector};

/// Which translation trivializes TG and T*G for a map and its integrators.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Side {
    /// Left (body frame, the paper's default): `ġ = g ξ`, and a left-invariant system moves by
    /// `μ̇ = ad*_ξ μ + F`.
    #[default]
    Left,
    /// Right (spatial frame, "defined analogously" in §3): `ġ = ξ g`, and a right-invariant
    /// system moves by `μ̇ = −ad*_ξ μ`.
    Right,
}

impl Side {
    /// The sign of `ad*_ξ μ` in the reduced equations: +1 left, −1 right.
    pub fn ad_dual_sign(self) -> f64 {
        match self {
            Self::Left => 1.0,
            Self::Right => -1.0,
        }
    }
}

/// A discretization map `R̃_d(g, ξ) = (g a(ξ), g b(ξ))` (§3.2), left-equivariant, given by its
/// factors a and b with `a(0) = b(0) = e` and `d^L b_0 − d^L a_0 = id`.
///
/// A user implements [`Self::first_factor`] and [`Self::second_factor`]; everything else is
/// provided — the tangents of the factors by finite differences (error ≈ 3·10⁻¹³ relative; a map
/// with closed forms overrides them), the descriptors by measuring the map (see the module page).
/// Then `impl LiftedMap<G> for MyMap {}` gives every component an integrator needs, composed
/// from the paper's lifts ([`crate::LiftedMap`]), and `integrators::CotangentLiftIntegrator` /
/// `integrators::TangentLiftIntegrator` integrate with it.
///
/// With [`Side::Right`] the same factors describe the right-trivialized map
/// `R̃_d^R(g, ξ) = (a(−ξ)⁻¹ g, b(−ξ)⁻¹ g) = ι × ι (R̃_d(g⁻¹, −ξ))`, ι(g) = g⁻¹ (for the θ-family,
/// `(τ(−θξ) g, τ((1−θ)ξ) g)`; see [`crate::RightDiscretizationMap`]).
///
/// ```
/// use discretization::{Discretization, LiftedMap};
/// use lie_groups::{CayleyGroup, LieGroup, So3, Vector};
/// use nalgebra::Vector3;
///
/// /// `R̃_d(g, ξ) = (g exp(−ξ/3), g cay(2ξ/3))`: not a θ-map (two different τ).
/// #[derive(Debug, Clone, Copy)]
/// struct ExpCayley;
/// impl Discretization<So3> for ExpCayley {
///     fn first_factor(&self, xi: &Vector3<f64>) -> So3 {
///         So3::exp(&(xi / -3.0))
///     }
///     fn second_factor(&self, xi: &Vector3<f64>) -> So3 {
///         So3::cay(&(xi * (2.0 / 3.0)))
///     }
/// }
/// impl LiftedMap<So3> for ExpCayley {}
///
/// let m = ExpCayley;
/// assert!((m.theta() - 1.0 / 3.0).abs() < 1e-10); // read off d^L a_0 = −θ I
/// assert!(!m.symmetric() && m.order() == 1);
/// // without a potential the Lie–Poisson step sees only c = exp(ξ/3) cay(2ξ/3), reversible
/// assert!(m.reversible_increment() && m.increment_order() == 2);
/// // the composed components: g_{k+1} = g_k a(η)⁻¹ b(η), μ_{k+1} = Ad*_{a⁻¹b} μ_k
/// let (gk, eta, mu) = (So3::identity(), Vector3::new(0.1, -0.2, 0.05), Vector3::new(1.0, 2.0, 3.0));
/// let step = m.next_point(&gk, &eta);
/// let update = m.momentum_update(&eta, &mu, None);
/// assert!((update.next - step.coadjoint_apply(&mu)).norm() < 1e-14);
/// ```
pub trait Discretization<G: LieGroup>: Clone + Debug + Send + Sync {
    /// `a(ξ)`: the first point of `R̃_d(e, ξ)`, so that `R̃_d(g, ξ)₁ = g a(ξ)`.
    fn first_factor(&self, xi: &G::Algebra) -> G;
    /// `b(ξ)`: the second point of `R̃_d(e, ξ)`, so that `R̃_d(g, ξ)₂ = g b(ξ)`.
    fn second_factor(&self, xi: &G::Algebra) -> G;

    /// `d^L a_ξ`, the left-trivialized tangent of a: `v ↦ a(ξ)⁻¹ (d/ds) a(ξ + s v)|_{s=0}`.
    /// Provided by five-point central differences of a's matrix (≈ 3·10⁻¹³ relative); a map with
    /// a closed form overrides it.
    fn first_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        finite_differences::left_tangent::<G>(|x| self.first_factor(x), xi)
    }
    /// `d^L b_ξ`, as [`Self::first_factor_tangent`].
    fn second_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        finite_differences::left_tangent::<G>(|x| self.second_factor(x), xi)
    }

    /// How the map names itself in a method name. Provided: the type's name.
    fn label(&self) -> String {
        let name = core::any::type_name::<Self>();
        let plain = name.split('<').next().unwrap_or(name);
        format!("map={}", plain.rsplit("::").next().unwrap_or(plain))
    }
    /// Which translation the map and its lifts are trivialized by ([`Side::Left`] unless
    /// overridden): integrators take the sign of ad* in their vector fields from it.
    fn side(&self) -> Side {
        Side::Left
    }
    /// The offset θ of the base point: `a(ξ) = exp(−θξ + O(|ξ|²))`, so that the base point
    /// `ḡ = g_k a(η)⁻¹` of a step lies at the time `t_k + θh` to first order (where integrators
    /// evaluate an external force) and `d^L b_0 = (1−θ) id`. Provided: read off
    /// `d^L a_0 = −θ id` as `−tr(d^L a_0)/n`; the θ-family returns its parameter.
    fn theta(&self) -> f64 {
        let n = G::dim();
        let zero = G::Algebra::zeros(n);
        let da = self.first_factor_tangent(&zero);
        let trace: f64 = (0..n)
            .map(|i| da.apply(&G::Algebra::basis(n, i)).get(i))
            .sum();
        -trace / n as f64
    }
    /// Whether the map equals its adjoint, `a(ξ) = b(−ξ)` (see the module page): then its
    /// Lie–Poisson and Euler–Poincaré integrators are symmetric. Provided by [`probe_symmetric`].
    fn symmetric(&self) -> bool {
        probe_symmetric::<G, Self>(self)
    }
    /// The order of the map as a discretization: 2 where it agrees with its adjoint to second
    /// order (every symmetric map), else 1 (see the module page). The order of its integrators
    /// with a potential or force; a map of higher order overrides it. Provided by
    /// [`probe_order`].
    fn order(&self) -> u32 {
        probe_order::<G, Self>(self)
    }
    /// Whether the increment `c(ξ) = a(ξ)⁻¹ b(ξ)` is reversible, `c(−ξ) = c(ξ)⁻¹`: then the
    /// Lie–Poisson step of a system without potential or force, which sees only c, is symmetric.
    /// Provided by [`probe_reversible_increment`].
    fn reversible_increment(&self) -> bool {
        probe_reversible_increment::<G, Self>(self)
    }
    /// The order of the Lie–Poisson step of a system without potential or force, which sees only
    /// c: 2 where `c(ξ) = exp(ξ + O(|ξ|³))` (every reversible c), else 1. Provided by
    /// [`probe_increment_order`].
    fn increment_order(&self) -> u32 {
        probe_increment_order::<G, Self>(self)
    }
    /// Whether `a ≡ e`, so that the base point is the first point and the Euler–Poincaré step
    /// is explicit. Provided: a(ξ) is e to 4ε at the probe directions.
    fn base_is_first_point(&self) -> bool {
        probe_directions::<G>(0.1)
            .iter()
            .all(|v| self.first_factor(v).matrix_distance(&G::identity()) <= 4.0 * f64::EPSILON)
    }
    /// Whether a step's η lies where the map can be inverted (R̃_d⁻¹ recovers η); an error names
    /// why not. Provided: η finite. Maps invertible on a smaller domain override it.
    fn check_domain(&self, eta: &G::Algebra) -> Result<(), DiscretizationError> {
        if eta.is_finite() {
            Ok(())
        } else {
            Err(DiscretizationError::NonFinite {
                what: "the step's η",
            })
        }
    }
}

/// Two fixed directions of 𝔤 (no symmetry a map could share by accident), scaled to max-norm s.
fn probe_directions<G: LieGroup>(s: f64) -> [G::Algebra; 2] {
    let n = G::dim();
    let unit = |v: G::Algebra| v.scale(s / v.norm_max());
    [
        unit(G::Algebra::from_fn(n, |i| (1.3 + 0.7 * i as f64).sin())),
        unit(G::Algebra::from_fn(n, |i| (0.4 + 1.9 * i as f64).cos())),
    ]
}

/// A defect that vanishes exactly (to round-off) at the probes.
const EXACT: f64 = 1e-12;

/// `max_v ‖a(sv) − b(−sv)‖` over the probe directions: the map against its adjoint.
fn adjoint_defect<G: LieGroup, M: Discretization<G>>(map: &M, s: f64) -> f64 {
    probe_directions::<G>(s)
        .iter()
        .map(|v| {
            map.first_factor(v)
                .matrix_distance(&map.second_factor(&v.neg()))
        })
        .fold(0.0, f64::max)
}

/// `max_v ‖c(sv) c(−sv) − e‖`, c(ξ) = a(ξ)⁻¹ b(ξ): the increment against its reverse.
fn increment_defect<G: LieGroup, M: Discretization<G>>(map: &M, s: f64) -> f64 {
    let c = |x: &G::Algebra| map.first_factor(x).inverse().compose(&map.second_factor(x));
    probe_directions::<G>(s)
        .iter()
        .map(|v| c(v).compose(&c(&v.neg())).matrix_distance(&G::identity()))
        .fold(0.0, f64::max)
}

/// A defect's order in s from its values at 2s and s: above 6 it falls like s³ (ratio 8) rather
/// than s² (ratio 4) or s (ratio 2).
fn vanishes_to_second_order(at_2s: f64, at_s: f64) -> bool {
    at_2s <= EXACT || at_2s > 6.0 * at_s
}

/// [`Discretization::symmetric`] measured: `‖a(ξ) − b(−ξ)‖ ≤ 10⁻¹²` at the two probe
/// directions, |ξ|_max = 0.1 (a map that is not symmetric differs there by O(|ξ|) or O(|ξ|²)).
pub fn probe_symmetric<G: LieGroup, M: Discretization<G>>(map: &M) -> bool {
    adjoint_defect::<G, M>(map, 0.1) <= EXACT
}

/// [`Discretization::order`] measured: 2 where the defect `‖a(ξ) − b(−ξ)‖` is zero or falls
/// like |ξ|³ between |ξ|_max = 0.04 and 0.02 (second-order agreement with the adjoint), else 1.
pub fn probe_order<G: LieGroup, M: Discretization<G>>(map: &M) -> u32 {
    let (d2, d1) = (
        adjoint_defect::<G, M>(map, 0.04),
        adjoint_defect::<G, M>(map, 0.02),
    );
    if vanishes_to_second_order(d2, d1) {
        2
    } else {
        1
    }
}

/// [`Discretization::reversible_increment`] measured: `‖c(ξ) c(−ξ) − e‖ ≤ 10⁻¹²` at the probe
/// directions, |ξ|_max = 0.2.
pub fn probe_reversible_increment<G: LieGroup, M: Discretization<G>>(map: &M) -> bool {
    increment_defect::<G, M>(map, 0.2) <= EXACT
}

/// [`Discretization::increment_order`] measured: 2 where `‖c(ξ) c(−ξ) − e‖` is zero or falls
/// faster than |ξ|² between |ξ|_max = 0.2 and 0.1 (`c(ξ) c(−ξ) = exp(2c₂(ξ) + O(|ξ|³))` for
/// `c(ξ) = exp(ξ + c₂(ξ) + …)`), else 1.
pub fn probe_increment_order<G: LieGroup, M: Discretization<G>>(map: &M) -> u32 {
    let (d2, d1) = (
        increment_defect::<G, M>(map, 0.2),
        increment_defect::<G, M>(map, 0.1),
    );
    if vanishes_to_second_order(d2, d1) {
        2
    } else {
        1
    }
}
