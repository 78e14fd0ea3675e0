//! The Lie group trait that everything above is generic over.

use crate::{DenseMatrix, LieError, Operator, Vector};
use core::fmt::Debug;

/// A Lie group G whose algebra 𝔤 is identified with ℝⁿ by `hat`/`vee` in a fixed basis, and whose
/// dual 𝔤* is identified with ℝⁿ by the Euclidean pairing ⟨μ, ξ⟩ = μ·ξ.
///
/// Conventions (see the crate page):
/// - `ad_ξ η = [ξ, η]`; the dual map `ad*_ξ := (ad_ξ)ᵀ`.
/// - `Ad_g ξ = (g ξ̂ g⁻¹)ˇ`; the dual map `Ad*_g := (Ad_g)ᵀ`, so the coadjoint *action* of g is
///   `Ad*_{g⁻¹}`.
/// - `d^L exp_ξ (η) = exp(ξ)⁻¹ · (d/ds) exp(ξ + s η)|_{s=0}` (left-trivialized tangent; manif's
///   right Jacobian J_r).
///
/// Required methods have closed forms per group; the provided ones derive from them and may be
/// overridden where a group has something faster (the cross product on 𝔰𝔬(3)).
pub trait LieGroup: Clone + Debug + Send + Sync + 'static {
    /// Algebra coordinates, ℝⁿ ≅ 𝔤 (and ℝⁿ ≅ 𝔤*).
    type Algebra: Vector;
    /// Linear maps of ℝⁿ (Ad_g, ad_ξ, tangent maps).
    type Operator: Operator<Self::Algebra>;
    /// The matrix representation (ℝ^{m×m}) used by `hat`, `matrix` and the generic matrix path.
    type Matrix: DenseMatrix;

    /// A short name, e.g. `"SO(3)"`.
    fn name() -> String;
    /// Dimension n of 𝔤.
    fn dim() -> usize;
    /// The identity e.
    fn identity() -> Self;
    /// The product `g h`.
    fn compose(&self, other: &Self) -> Self;
    /// The inverse `g⁻¹`.
    fn inverse(&self) -> Self;
    /// The group exponential exp: 𝔤 → G. Infallible: a non-finite ξ gives a non-finite element,
    /// and so does a finite ξ so large that the group's formulas overflow (SE(3)'s translation
    /// `V(ω) v` beyond f64::MAX, GL(n)'s entries; SO(3) stays a rotation for every finite ξ).
    /// [`LieGroup::try_exp`] turns both into errors.
    fn exp(xi: &Self::Algebra) -> Self;
    /// `exp` checked: [`LieError::NonFinite`] for a ξ holding NaN or an infinity,
    /// [`LieError::Overflow`] when a finite ξ gives a non-finite element.
    fn try_exp(xi: &Self::Algebra) -> Result<Self, LieError> {
        if !xi.is_finite() {
            return Err(LieError::NonFinite {
                what: "algebra element ξ",
            });
        }
        let g = Self::exp(xi);
        if g.is_finite() {
            Ok(g)
        } else {
            Err(LieError::Overflow {
                map: crate::GroupMap::Exp,
                size: xi.norm_max(),
            })
        }
    }
    /// The principal logarithm, the local inverse of `exp` (an error where none exists).
    fn log(&self) -> Result<Self::Algebra, LieError>;
    /// A radius r such that `log(exp ξ) = ξ` holds to round-off (relative error ≤ 1e-8) for every
    /// ‖ξ‖ ≤ r (Euclidean norm of the algebra coordinates); 0 where no such bound is known.
    ///
    /// It lets callers skip the round trip where it is known to succeed: e.g. r = 3 < π on SO(3),
    /// whose principal log inverts exp for rotation angles below π. The generic test suite checks
    /// the bound on random directions up to the radius.
    const EXP_INVERTIBLE_RADIUS: f64 = 0.0;
    /// ξ ↦ ξ̂, algebra coordinates to the algebra matrix.
    fn hat(xi: &Self::Algebra) -> Self::Matrix;
    /// ξ̂ ↦ ξ, the inverse of `hat` (the part of the matrix outside 𝔤 is ignored).
    fn vee(m: &Self::Matrix) -> Self::Algebra;
    /// The group element as a matrix.
    fn matrix(&self) -> Self::Matrix;
    /// Builds an element from its matrix, checking that it lies on the group.
    fn from_matrix(m: &Self::Matrix) -> Result<Self, LieError>;
    /// Builds an element from its matrix without any check (for matrices known to be on the group).
    fn from_matrix_unchecked(m: &Self::Matrix) -> Self;
    /// The adjoint representation Ad_g as an n×n matrix.
    fn adjoint(&self) -> Self::Operator;
    /// ad_ξ as an n×n matrix: `ad_ξ η = [ξ, η]`.
    fn ad(xi: &Self::Algebra) -> Self::Operator;

    /// `Ad_g ξ`.
    fn adjoint_apply(&self, xi: &Self::Algebra) -> Self::Algebra {
        self.adjoint().apply(xi)
    }
    /// `Ad_{g⁻¹} ξ`, without forming g⁻¹ where the group has a closed form (the product of
    /// G ⋉ 𝔤 needs it).
    fn adjoint_inverse_apply(&self, xi: &Self::Algebra) -> Self::Algebra {
        self.inverse().adjoint_apply(xi)
    }
    /// `Ad*_g μ = (Ad_g)ᵀ μ` (the dual map, not the coadjoint action).
    fn coadjoint_apply(&self, mu: &Self::Algebra) -> Self::Algebra {
        self.adjoint().apply_transpose(mu)
    }
    /// The bracket `[ξ, η] = ad_ξ η`.
    fn bracket(xi: &Self::Algebra, eta: &Self::Algebra) -> Self::Algebra {
        Self::ad(xi).apply(eta)
    }
    /// `ad*_ξ μ = (ad_ξ)ᵀ μ`.
    fn ad_dual_apply(xi: &Self::Algebra, mu: &Self::Algebra) -> Self::Algebra {
        Self::ad(xi).apply_transpose(mu)
    }
    /// The operator `M(μ): δ ↦ ad*_δ μ` (linear in δ), the derivative in ξ of ad*_ξ μ that
    /// Newton Jacobians of the Lie–Poisson step are built from. The provided form applies
    /// [`LieGroup::ad_dual_apply`] to the basis vectors; groups override it with a closed form
    /// (on SO(3), `ad*_δ μ = μ × δ`, so M(μ) = μ̂).
    fn ad_dual_operator(mu: &Self::Algebra) -> Self::Operator {
        let n = Self::dim();
        crate::matrix_path::operator_from_column_fn::<Self>(|j| {
            Self::ad_dual_apply(&Self::Algebra::basis(n, j), mu)
        })
    }
    /// `d^L exp_ξ = Σ_k (−ad_ξ)^k / (k+1)! = (I − e^{−ad_ξ}) / ad_ξ`.
    ///
    /// The provided form evaluates the series exactly through one block matrix exponential,
    /// `exp([[−ad_ξ, I], [0, 0]])` (top-right block); groups override it with closed forms.
    fn dexp_left(xi: &Self::Algebra) -> Self::Operator {
        let ad = Self::ad(xi).to_mat();
        let j = crate::matrix::dense::phi1_of_neg(ad.as_ref());
        Self::Operator::from_mat(j.as_ref()).expect("dexp has the shape of ad")
    }
    /// `(d^L exp_ξ)⁻¹`; its entries are non-finite where d^L exp_ξ is singular (for compact groups
    /// at |ξ| = 2πk, k ≥ 1).
    fn dexp_left_inv(xi: &Self::Algebra) -> Self::Operator {
        Self::dexp_left(xi)
            .try_inverse()
            .unwrap_or_else(|| nan_operator::<Self>())
    }
    /// The increment `(Ad*_{exp ξ} − I) μ`, linear in μ. The provided form is
    /// `Ad*_{exp ξ} μ − μ`; groups override it with a form computed from ξ directly, whose relative
    /// accuracy does not depend on the rounding of the entries `1 − O(|ξ|²)` of exp ξ, so that the
    /// Lie–Poisson step can add it to μ once and |μ|² does not drift at small steps.
    fn exp_coadjoint_increment(xi: &Self::Algebra, mu: &Self::Algebra) -> Self::Algebra {
        Self::exp(xi).coadjoint_apply(mu).sub(mu)
    }
    /// The increment `(Ad_{exp ξ} − I) v`, linear in v: the adjoint counterpart of
    /// [`LieGroup::exp_coadjoint_increment`], what the Euler–Poincaré step adds to its velocity
    /// (`discretization`'s `LiftedMap::first_velocity_increment`). The provided form is
    /// `Ad_{exp ξ} v − v`, rounded at ε|v| however small ξ is; groups override it with a form
    /// computed from ξ directly whose rounding is relative to its own size O(|ξ||v|) (SO(3),
    /// SE(3), SE(2), and the composite groups factor by factor).
    fn exp_adjoint_increment(xi: &Self::Algebra, v: &Self::Algebra) -> Self::Algebra {
        Self::exp(xi).adjoint_apply(v).sub(v)
    }
    /// `g exp ξ`. The provided form composes with exp ξ; groups override it with the increment
    /// form `g + g (exp ξ − I)` (see [`LieGroup::exp_coadjoint_increment`]).
    fn exp_compose(g: &Self, xi: &Self::Algebra) -> Self {
        g.compose(&Self::exp(xi))
    }
    /// `d^{L*}exp_ξ μ = (d^L exp_ξ)ᵀ μ`. The provided form builds d^L exp_ξ; groups override it
    /// with a closed form that skips the operator (the Lie–Poisson step applies it every
    /// iteration).
    fn dexp_left_dual_apply(xi: &Self::Algebra, mu: &Self::Algebra) -> Self::Algebra {
        Self::dexp_left(xi).apply_transpose(mu)
    }
    /// `D exp(ξ; μ) := ∂/∂ξ (d^{L*}exp_ξ μ)`, the derivative in ξ of the dual tangent map at a fixed
    /// covector μ, as the operator `δ ↦ (d/ds) d^{L*}exp_{ξ+sδ} μ |_{s=0}` (the second derivative
    /// of exp that Newton Jacobians of the Lie–Poisson step need).
    ///
    /// The provided form is exact, from the series `d^{L*}exp_ξ μ = Σ_{k≥0} cₖ Pᵏ μ`,
    /// `cₖ = (−1)ᵏ/(k+1)!`, `P = ad*_ξ`: differentiating each power,
    ///
    /// ```text
    /// D = Σ_{k≥1} cₖ Sₖ,   S₁ = M(μ),   S_{k+1} = P Sₖ + M(Pᵏ μ),
    /// ```
    ///
    /// with `M(ν): δ ↦ ad*_δ ν` ([`LieGroup::ad_dual_operator`]), summed until two consecutive
    /// terms fall below ε‖D‖ (at most [`DEXP_DERIVATIVE_MAX_TERMS`]; the terms decay like
    /// ‖ad_ξ‖ᵏ/k!, so ~20–40 terms for |ξ| ≲ π) — operator products only, no allocation for
    /// fixed-size groups. Its first term is the first-order form `−½ M(μ)`. Groups with a
    /// closed form override it (SO(3)).
    fn dexp_left_dual_derivative(xi: &Self::Algebra, mu: &Self::Algebra) -> Self::Operator {
        dexp_dual_derivative_series::<Self>(xi, mu)
    }
    /// Removes the round-off drift off the group that long products accumulate (RᵀR − I for
    /// rotations grows like √N ε over N products) by a correction of the size of that drift, so that
    /// an element reconstructed over 10⁷ steps stays on the group to round-off. The provided form is
    /// the identity, for representations that cannot drift; integrators call it after each
    /// reconstruction step.
    fn normalize(&self) -> Self {
        self.clone()
    }
    /// Whether every entry of the element is finite.
    fn is_finite(&self) -> bool {
        let m = self.matrix().to_mat();
        (0..m.ncols()).all(|j| (0..m.nrows()).all(|i| m[(i, j)].is_finite()))
    }
    /// `‖matrix(self) − matrix(other)‖_max`, a distance for comparisons in tests and checks.
    fn matrix_distance(&self, other: &Self) -> f64 {
        let a = self.matrix().to_mat();
        let b = other.matrix().to_mat();
        let mut best = 0.0f64;
        for j in 0..a.ncols() {
            for i in 0..a.nrows() {
                best = best.max((a[(i, j)] - b[(i, j)]).abs());
            }
        }
        best
    }
}

/// The operator `δ ↦ −½ ad*_δ μ`: the leading term of `∂/∂ξ (d^{L*}τ_ξ μ)` at ξ = 0 for every τ
/// with `τ(ξ) = exp(ξ) + O(ξ³)` (exp and Cayley), the default of
/// [`LieGroup::dexp_left_dual_derivative`] and [`crate::CayleyGroup::dcay_left_dual_derivative`].
/// The most terms [`LieGroup::dexp_left_dual_derivative`]'s series sums (reached only for
/// ‖ad_ξ‖ ≳ 15, far outside the steps the integrators take).
pub const DEXP_DERIVATIVE_MAX_TERMS: usize = 80;

/// `D exp(ξ; μ)` by the series of [`LieGroup::dexp_left_dual_derivative`].
pub fn dexp_dual_derivative_series<G: LieGroup>(xi: &G::Algebra, mu: &G::Algebra) -> G::Operator {
    let p = G::ad(xi).transpose();
    let mut nu = p.apply(mu); // Pᵏ μ for the next S
    let mut s = G::ad_dual_operator(mu); // S₁
    let mut c = -0.5; // c₁
    let mut d = s.scale(c);
    let mut small = 0;
    for k in 1..DEXP_DERIVATIVE_MAX_TERMS {
        // S_{k+1} = P Sₖ + M(Pᵏ μ), c_{k+1} = −cₖ/(k+2).
        s = p.compose(&s).add(&G::ad_dual_operator(&nu));
        nu = p.apply(&nu);
        c = -c / (k as f64 + 2.0);
        let term = s.scale(c);
        let size = term.norm_max();
        d = d.add(&term);
        if size <= f64::EPSILON * d.norm_max() || size == 0.0 {
            small += 1;
            if small == 2 {
                break;
            }
        } else {
            small = 0;
        }
    }
    d
}

pub(crate) fn half_ad_dual_operator<G: LieGroup>(mu: &G::Algebra) -> G::Operator {
    G::ad_dual_operator(mu).scale(-0.5)
}

/// An n×n operator of NaNs: what a tangent-map inverse returns outside its domain.
pub fn nan_operator<G: LieGroup>() -> G::Operator {
    let n = G::dim();
    let m = faer::Mat::from_fn(n, n, |_, _| f64::NAN);
    G::Operator::from_mat(m.as_ref()).expect("n×n operator")
}

/// A left action of the group on points of type `P` (rotation of vectors, rigid motion of points).
pub trait Action<P> {
    /// `g · p`.
    fn act(&self, p: &P) -> P;
}
