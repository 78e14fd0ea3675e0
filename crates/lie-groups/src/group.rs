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
    /// The adjoint representation Ad_g as an n×n matrix (manif's `adj`, Sophus' `Adj`).
    #[doc(alias = "Adj")]
    #[doc(alias = "adj")]
    fn adjoint(&self) -> Self::Operator;
    /// ad_ξ as an n×n matrix: `ad_ξ η = [ξ, η]` (manif's `smallAdj`, Sophus' `ad`).
    #[doc(alias = "smallAdj")]
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
    /// `d^L exp_ξ = Σ_k (−ad_ξ)^k / (k+1)! = (I − e^{−ad_ξ}) / ad_ξ`: manif's right Jacobian
    /// `rjac` (J_r), the Jacobian of exp in the body frame (`exp(ξ + δ) = exp(ξ) exp(d^L exp_ξ δ)`
    /// to first order).
    ///
    /// The provided form evaluates the series exactly through one block matrix exponential,
    /// `exp([[−ad_ξ, I], [0, 0]])` (top-right block); groups override it with closed forms.
    #[doc(alias = "rjac")]
    #[doc(alias = "right_jacobian")]
    #[doc(alias = "Jr")]
    #[doc(alias = "J_r")]
    fn dexp_left(xi: &Self::Algebra) -> Self::Operator {
        let ad = Self::ad(xi).to_dmatrix();
        let j = crate::linalg::phi1_of_neg(ad.as_view());
        Self::Operator::from_dmatrix(j.as_view()).expect("dexp has the shape of ad")
    }
    /// `(d^L exp_ξ)⁻¹`; its entries are non-finite where d^L exp_ξ is singular (for compact groups
    /// at |ξ| = 2πk, k ≥ 1).
    #[doc(alias = "rjacinv")]
    #[doc(alias = "Jr_inv")]
    #[doc(alias = "J_r_inv")]
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
        self.matrix().to_dmatrix().iter().all(|x| x.is_finite())
    }
    /// `‖matrix(self) − matrix(other)‖_max`, a distance for comparisons in tests and checks.
    fn matrix_distance(&self, other: &Self) -> f64 {
        let a = self.matrix().to_dmatrix();
        let b = other.matrix().to_dmatrix();
        crate::linalg::max_abs_diff(a.as_view(), b.as_view())
    }

    // ---- The vocabulary of estimation and control (⊕, ⊖, between, interpolation) and the
    // ---- Jacobians of every operation, by trivialization. See the crate page for the table of
    // ---- manif / Sophus names.

    /// `g ⊕ ξ = g exp(ξ)`: moves g by ξ in its body frame (the increment is left-trivialized:
    /// `g⁻¹ (d/ds) (g exp(sξ))|₀ = ξ`). manif's right-plus `rplus`, jaxlie's `manifold.rplus`, the
    /// retraction of EKFs and factor graphs on manifolds. Computed by [`LieGroup::exp_compose`]
    /// (the increment form on SO(3), SE(3), SE(2)).
    #[doc(alias = "rplus")]
    #[doc(alias = "oplus")]
    #[doc(alias = "boxplus")]
    #[doc(alias = "retract")]
    #[doc(alias = "plus")]
    #[inline]
    fn plus_left(&self, xi: &Self::Algebra) -> Self {
        Self::exp_compose(self, xi)
    }
    /// `exp(ξ) g`: moves g by ξ in the fixed (spatial) frame (right-trivialized increment:
    /// `(d/ds) (exp(sξ) g)|₀ g⁻¹ = ξ`). manif's left-plus `lplus`.
    #[doc(alias = "lplus")]
    #[inline]
    fn plus_right(&self, xi: &Self::Algebra) -> Self {
        Self::exp(xi).compose(self)
    }
    /// `h ⊖ g = log(g⁻¹ h)` (h = `self`): the body-frame increment that takes g to h, the inverse
    /// of [`LieGroup::plus_left`] (`g ⊕ (h ⊖ g) = h`, and `(g ⊕ ξ) ⊖ g = ξ` inside the domain of
    /// log). manif's right-minus `rminus` (`h.rminus(g)`), jaxlie's `manifold.rminus(g, h)`. An
    /// error where log has none.
    #[doc(alias = "rminus")]
    #[doc(alias = "ominus")]
    #[doc(alias = "boxminus")]
    #[doc(alias = "local")]
    #[doc(alias = "minus")]
    fn minus_left(&self, g: &Self) -> Result<Self::Algebra, LieError> {
        g.between(self).log()
    }
    /// `log(h g⁻¹)` (h = `self`): the spatial increment that takes g to h, the inverse of
    /// [`LieGroup::plus_right`]. manif's left-minus `lminus`.
    #[doc(alias = "lminus")]
    fn minus_right(&self, g: &Self) -> Result<Self::Algebra, LieError> {
        self.compose(&g.inverse()).log()
    }
    /// `g⁻¹ h` (g = `self`): h seen from g, the relative pose of factor graphs. manif's and GTSAM's
    /// `between`; `between(g, g) = e`.
    #[doc(alias = "relative")]
    #[inline]
    fn between(&self, other: &Self) -> Self {
        self.inverse().compose(other)
    }
    /// The point at parameter t of the one-parameter-subgroup curve from g (t = 0) to h (t = 1),
    /// `γ(t) = g exp(t log(g⁻¹ h))` (g = `self`, h = `other`). Its body velocity
    /// `γ(t)⁻¹ γ̇(t) = log(g⁻¹ h)` is constant (constant speed), and it is a geodesic wherever the
    /// group's metric is bi-invariant (SO(2), SO(3), ℝⁿ: slerp on rotations); on SE(3) it is the
    /// screw motion. manif's `interpolate_slerp`, Sophus' `interpolate`. t outside [0, 1]
    /// extrapolates; an error where log(g⁻¹ h) does not exist.
    #[doc(alias = "interp")]
    #[doc(alias = "interpolate_slerp")]
    #[doc(alias = "slerp")]
    #[doc(alias = "geodesic")]
    fn interpolate(&self, other: &Self, t: f64) -> Result<Self, LieError> {
        Ok(self.plus_left(&other.minus_left(self)?.scale(t)))
    }

    /// `d^R exp_ξ = d^L exp_{−ξ} = Ad_{exp ξ} d^L exp_ξ = Σ_k ad_ξ^k / (k+1)!`, the
    /// right-trivialized tangent of exp: `(d/ds) exp(ξ + sη)|₀ exp(ξ)⁻¹ = d^R exp_ξ η`. manif's
    /// left Jacobian `ljac` (J_l), Sophus' `leftJacobian`.
    #[doc(alias = "ljac")]
    #[doc(alias = "left_jacobian")]
    #[doc(alias = "leftJacobian")]
    #[doc(alias = "Jl")]
    #[doc(alias = "J_l")]
    fn dexp_right(xi: &Self::Algebra) -> Self::Operator {
        Self::dexp_left(&xi.neg())
    }
    /// `(d^R exp_ξ)⁻¹ = (d^L exp_{−ξ})⁻¹`. manif's `ljacinv`, Sophus' `leftJacobianInverse`.
    #[doc(alias = "ljacinv")]
    #[doc(alias = "leftJacobianInverse")]
    #[doc(alias = "Jl_inv")]
    #[doc(alias = "J_l_inv")]
    fn dexp_right_inv(xi: &Self::Algebra) -> Self::Operator {
        Self::dexp_left_inv(&xi.neg())
    }
    /// The left-trivialized Jacobian of log at g: `log(g exp(δ)) = log g + J δ + O(δ²)`, with
    /// `J = (d^L exp_{log g})⁻¹`. manif's `J_t_m` of `log` (J_r⁻¹), jaxlie's `jlog`, Pinocchio's
    /// `Jlog3`/`Jlog6`. An error where log has none.
    #[doc(alias = "jlog")]
    #[doc(alias = "J_t_m")]
    fn log_jacobian_left(&self) -> Result<Self::Operator, LieError> {
        Ok(Self::dexp_left_inv(&self.log()?))
    }
    /// The right-trivialized Jacobian of log at g: `log(exp(δ) g) = log g + J δ + O(δ²)`, with
    /// `J = (d^R exp_{log g})⁻¹` (manif's J_l⁻¹ of the log).
    fn log_jacobian_right(&self) -> Result<Self::Operator, LieError> {
        Ok(Self::dexp_right_inv(&self.log()?))
    }
    /// The left-trivialized Jacobians of `c = g h` (g = `self`, h = `other`) with respect to g and
    /// to h: `(g e^δ) h = c exp(Ad_{h⁻¹} δ)` and `g (h e^δ) = c e^δ`, so `(Ad_{h⁻¹}, I)`. manif's
    /// `J_mc_ma`, `J_mc_mb` of `compose`.
    #[doc(alias = "J_mc_ma")]
    #[doc(alias = "J_mc_mb")]
    fn compose_jacobians_left(&self, other: &Self) -> (Self::Operator, Self::Operator) {
        (
            other.inverse().adjoint(),
            Self::Operator::identity(Self::dim()),
        )
    }
    /// The right-trivialized Jacobians of `c = g h` with respect to g and h:
    /// `(e^δ g) h = e^δ c` and `g (e^δ h) = exp(Ad_g δ) c`, so `(I, Ad_g)`.
    fn compose_jacobians_right(&self, _other: &Self) -> (Self::Operator, Self::Operator) {
        (Self::Operator::identity(Self::dim()), self.adjoint())
    }
    /// The left-trivialized Jacobian of `g ↦ g⁻¹`: `(g e^δ)⁻¹ = g⁻¹ exp(−Ad_g δ)`, so `−Ad_g`.
    /// manif's `J_minv_m`.
    #[doc(alias = "J_minv_m")]
    fn inverse_jacobian_left(&self) -> Self::Operator {
        self.adjoint().scale(-1.0)
    }
    /// The right-trivialized Jacobian of `g ↦ g⁻¹`: `(e^δ g)⁻¹ = exp(−Ad_{g⁻¹} δ) g⁻¹`, so
    /// `−Ad_{g⁻¹}`.
    fn inverse_jacobian_right(&self) -> Self::Operator {
        self.inverse().adjoint().scale(-1.0)
    }
    /// The left-trivialized Jacobians of `d = g⁻¹ h` ([`LieGroup::between`], g = `self`) with
    /// respect to g and h: `(g e^δ)⁻¹ h = d exp(−Ad_{d⁻¹} δ)` and `g⁻¹ (h e^δ) = d e^δ`, so
    /// `(−Ad_{h⁻¹ g}, I)`. manif's `J_mc_ma`, `J_mc_mb` of `between`.
    fn between_jacobians_left(&self, other: &Self) -> (Self::Operator, Self::Operator) {
        (
            other.between(self).adjoint().scale(-1.0),
            Self::Operator::identity(Self::dim()),
        )
    }
    /// The right-trivialized Jacobians of `d = g⁻¹ h` with respect to g and h:
    /// `(e^δ g)⁻¹ h = exp(−Ad_{g⁻¹} δ) d` and `g⁻¹ e^δ h = exp(Ad_{g⁻¹} δ) d`, so
    /// `(−Ad_{g⁻¹}, Ad_{g⁻¹})`.
    fn between_jacobians_right(&self, _other: &Self) -> (Self::Operator, Self::Operator) {
        let a = self.inverse().adjoint();
        (a.scale(-1.0), a)
    }
    /// The left-trivialized Jacobians of `g ⊕ ξ = g exp ξ` ([`LieGroup::plus_left`]) with respect
    /// to g and to ξ: `(Ad_{exp(−ξ)}, d^L exp_ξ)`. manif's `J_mout_m`, `J_mout_t` of `rplus`.
    #[doc(alias = "J_mout_m")]
    #[doc(alias = "J_mout_t")]
    fn plus_left_jacobians(&self, xi: &Self::Algebra) -> (Self::Operator, Self::Operator) {
        (Self::exp(&xi.neg()).adjoint(), Self::dexp_left(xi))
    }
    /// The left-trivialized Jacobians of `exp(ξ) g` ([`LieGroup::plus_right`]) with respect to g
    /// and to ξ: `exp(ξ) (g e^δ) = (exp(ξ) g) e^δ` and `exp(ξ + δ) g = exp(ξ) g exp(Ad_{g⁻¹}
    /// d^L exp_ξ δ)`, so `(I, Ad_{g⁻¹} d^L exp_ξ)`. Left-trivialized like every ⊕/⊖ Jacobian
    /// here (manif's convention on both sides): manif's `J_mout_m`, `J_mout_t` of `lplus`.
    fn plus_right_jacobians(&self, xi: &Self::Algebra) -> (Self::Operator, Self::Operator) {
        (
            Self::Operator::identity(Self::dim()),
            self.inverse().adjoint().compose(&Self::dexp_left(xi)),
        )
    }
    /// The left-trivialized Jacobians of `τ = h ⊖ g = log(g⁻¹ h)` ([`LieGroup::minus_left`],
    /// h = `self`) with respect to h and to g: `((d^L exp_τ)⁻¹, −(d^R exp_τ)⁻¹)`. manif's
    /// `J_t_ma`, `J_t_mb` of `rminus` (J_r⁻¹(τ), −J_l⁻¹(τ)).
    #[doc(alias = "J_t_ma")]
    #[doc(alias = "J_t_mb")]
    fn minus_left_jacobians(&self, g: &Self) -> Result<(Self::Operator, Self::Operator), LieError> {
        let tau = self.minus_left(g)?;
        Ok((
            Self::dexp_left_inv(&tau),
            Self::dexp_right_inv(&tau).scale(-1.0),
        ))
    }
    /// The left-trivialized Jacobians of `τ = log(h g⁻¹)` ([`LieGroup::minus_right`], h = `self`)
    /// with respect to h and to g: `log((h e^δ) g⁻¹) = log(h g⁻¹ exp(Ad_g δ))`, so with
    /// `J = (d^L exp_τ)⁻¹ Ad_g` they are `(J, −J)`. manif's `J_t_ma`, `J_t_mb` of `lminus`.
    fn minus_right_jacobians(
        &self,
        g: &Self,
    ) -> Result<(Self::Operator, Self::Operator), LieError> {
        let tau = self.minus_right(g)?;
        let j = Self::dexp_left_inv(&tau).compose(&g.adjoint());
        let minus = j.scale(-1.0);
        Ok((j, minus))
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
    let m = nalgebra::DMatrix::from_element(n, n, f64::NAN);
    G::Operator::from_dmatrix(m.as_view()).expect("n×n operator")
}

/// A left action of the group on points of type `P` (rotation of vectors, rigid motion of points),
/// with its Jacobians.
///
/// With `m = dim P` and `n = dim 𝔤`, the Jacobians of `q = g · p` are the m×m
/// `∂q/∂p` ([`Action::act_jacobian_point`]) and the m×n ones with respect to g, by
/// trivialization: `(g exp δ) · p = q + J^L δ + O(δ²)` ([`Action::act_jacobian_left`]) and
/// `(exp(δ) g) · p = q + J^R δ + O(δ²)` ([`Action::act_jacobian_right`]); `J^R = J^L Ad_{g⁻¹}`.
/// manif's `act(v, J_vout_m, J_vout_v)` gives `J^L` and `∂q/∂p`.
pub trait Action<P> {
    /// `∂(g·p)/∂p`, m×m.
    type PointJacobian: DenseMatrix;
    /// `∂(g·p)/∂g` in a trivialization, m×n.
    type GroupJacobian: DenseMatrix;
    /// `g · p`.
    fn act(&self, p: &P) -> P;
    /// `∂(g·p)/∂p`. manif's `J_vout_v`.
    #[doc(alias = "J_vout_v")]
    fn act_jacobian_point(&self, p: &P) -> Self::PointJacobian;
    /// `J^L = ∂/∂δ ((g exp δ) · p)|₀` (left-trivialized). manif's `J_vout_m`.
    #[doc(alias = "J_vout_m")]
    fn act_jacobian_left(&self, p: &P) -> Self::GroupJacobian;
    /// `J^R = ∂/∂δ ((exp(δ) g) · p)|₀` (right-trivialized): the generator of the action at
    /// `g · p`. At g = e both equal Sophus' `Dx_exp_x_times_point_at_0`.
    #[doc(alias = "dx_exp_x_times_point_at_0")]
    fn act_jacobian_right(&self, p: &P) -> Self::GroupJacobian;
}
