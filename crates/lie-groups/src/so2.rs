//! SO(2), the rotations of the plane, on nalgebra stack types.
//!
//! - Element: the unit complex number `z = cos θ + i sin θ`, stored as `(cos θ, sin θ)`.
//!   Storing the pair rather than the angle makes `compose` and `act` (the integrators' hot paths)
//!   trig-free and wrap-free; only `exp`/`log` pay for `sin_cos`/`atan2`.
//! - Algebra 𝔰𝔬(2) ≅ ℝ: `ξ = (ω)` with `ξ̂ = ω J`, `J = [[0, −1], [1, 0]]`.
//! - The group is abelian: `Ad_g = 1`, `ad_ξ = 0`, `d^L exp_ξ = 1`.

use crate::{Action, CayleyGroup, DomainReason, LieError, LieGroup};
use core::f64::consts::PI;
use nalgebra::{Matrix1, Matrix2, SVector, UnitComplex, Vector1, Vector2};

/// A rotation of the plane by θ, stored as `(cos θ, sin θ)` (see the module page).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct So2 {
    c: f64,
    s: f64,
}

/// Cayley-map domain guard: `cay⁻¹` refuses rotations with `1 + cos θ` below this (θ within
/// about 2·10⁻⁶ of π, where `ω = 2 tan(θ/2)` exceeds 10⁶).
const CAY_INV_MIN: f64 = 1e-12;

impl So2 {
    /// Default tolerance of [`LieGroup::from_matrix`]: `‖RᵀR − I‖_max ≤ 1e-9` and `|det R − 1| ≤
    /// 1e-9`. Loose enough for products of ~10⁷ exactly-rounded rotations, tight enough to refuse
    /// anything that is not a rotation up to round-off.
    pub const TOLERANCE: f64 = 1e-9;

    /// The rotation by `theta` radians.
    #[inline]
    pub fn from_angle(theta: f64) -> Self {
        let (s, c) = theta.sin_cos();
        Self { c, s }
    }

    /// The rotation with the given cosine and sine, not checked (`c² + s² = 1` is assumed).
    #[inline]
    pub fn from_cos_sin_unchecked(c: f64, s: f64) -> Self {
        Self { c, s }
    }

    /// `cos θ`.
    #[inline]
    pub fn cos(&self) -> f64 {
        self.c
    }

    /// `sin θ`.
    #[inline]
    pub fn sin(&self) -> f64 {
        self.s
    }

    /// The angle θ ∈ (−π, π] (exactly π, never −π, at the half turn).
    #[inline]
    pub fn angle(&self) -> f64 {
        let theta = self.s.atan2(self.c);
        // atan2(−0, −1) = −π: fold the half turn onto π so log is single-valued there.
        if theta == -PI {
            PI
        } else {
            theta
        }
    }

    /// The 2×2 rotation matrix `[[c, −s], [s, c]]`.
    #[inline]
    pub fn rotation_matrix(&self) -> Matrix2<f64> {
        Matrix2::new(self.c, -self.s, self.s, self.c)
    }

    /// Checked constructor with an explicit tolerance: refuses non-finite entries
    /// ([`LieError::NonFinite`]), `‖RᵀR − I‖_max > tol` ([`LieError::NotOrthogonal`]) and
    /// `|det R − 1| > tol` ([`LieError::WrongDeterminant`]).
    pub fn from_matrix_with_tolerance(m: &Matrix2<f64>, tol: f64) -> Result<Self, LieError> {
        check_rotation2(m, tol)?;
        Ok(Self::from_rotation_block(m))
    }

    /// The nearest rotation in the Frobenius norm to any finite 2×2 matrix `M` (the orthogonal
    /// polar factor for det M > 0): maximizing `tr(Rᵀ M)` gives
    /// `(cos θ, sin θ) ∝ (m₀₀ + m₁₁, m₁₀ − m₀₁)`. An error if `M` is non-finite or that vector is 0
    /// (no unique nearest rotation).
    pub fn project(m: &Matrix2<f64>) -> Result<Self, LieError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite { what: "matrix" });
        }
        let (a, b) = (m[(0, 0)] + m[(1, 1)], m[(1, 0)] - m[(0, 1)]);
        let r = a.hypot(b);
        if r <= f64::MIN_POSITIVE {
            return Err(LieError::Singular { rcond: 0.0 });
        }
        Ok(Self { c: a / r, s: b / r })
    }

    /// Reads `(cos θ, sin θ)` from a (checked) rotation block, averaging the redundant entries.
    fn from_rotation_block(m: &Matrix2<f64>) -> Self {
        Self {
            c: 0.5 * (m[(0, 0)] + m[(1, 1)]),
            s: 0.5 * (m[(1, 0)] - m[(0, 1)]),
        }
    }

    /// `R v` for a plane vector.
    #[inline]
    pub fn rotate(&self, v: &Vector2<f64>) -> Vector2<f64> {
        Vector2::new(self.c * v.x - self.s * v.y, self.s * v.x + self.c * v.y)
    }
}

/// Checks that a 2×2 matrix is a rotation within `tol` (finite, orthogonal, det +1).
pub(crate) fn check_rotation2(m: &Matrix2<f64>, tol: f64) -> Result<(), LieError> {
    if !m.iter().all(|x| x.is_finite()) {
        return Err(LieError::NonFinite { what: "matrix" });
    }
    let err = (m.transpose() * m - Matrix2::identity()).abs().max();
    if err > tol {
        return Err(LieError::NotOrthogonal {
            error: err,
            tolerance: tol,
        });
    }
    let det = m.determinant();
    if (det - 1.0).abs() > tol {
        return Err(LieError::WrongDeterminant {
            det,
            tolerance: tol,
        });
    }
    Ok(())
}

impl LieGroup for So2 {
    /// The principal log inverts exp for |ω| < π; 3 keeps clear of the cut at π.
    const EXP_INVERTIBLE_RADIUS: f64 = 3.0;
    /// Rescales (cos θ, sin θ) to unit length.
    #[inline]
    fn normalize(&self) -> Self {
        let n = self.c.hypot(self.s);
        Self {
            c: self.c / n,
            s: self.s / n,
        }
    }
    type Algebra = SVector<f64, 1>;
    type Operator = Matrix1<f64>;
    type Matrix = Matrix2<f64>;

    fn name() -> String {
        "SO(2)".into()
    }
    fn dim() -> usize {
        1
    }
    #[inline]
    fn identity() -> Self {
        Self { c: 1.0, s: 0.0 }
    }
    /// Complex multiplication `z₁ z₂`.
    #[inline]
    fn compose(&self, o: &Self) -> Self {
        Self {
            c: self.c * o.c - self.s * o.s,
            s: self.s * o.c + self.c * o.s,
        }
    }
    /// The conjugate `z̄`.
    #[inline]
    fn inverse(&self) -> Self {
        Self {
            c: self.c,
            s: -self.s,
        }
    }
    /// `exp(ω) = cos ω + i sin ω`.
    #[inline]
    fn exp(xi: &Vector1<f64>) -> Self {
        Self::from_angle(xi[0])
    }
    /// `log(z) = atan2(sin θ, cos θ) ∈ (−π, π]`: exactly π at the half turn (never −π, never NaN).
    /// Never fails for a finite element; non-finite entries give [`LieError::NonFinite`].
    fn log(&self) -> Result<Vector1<f64>, LieError> {
        if !(self.c.is_finite() && self.s.is_finite()) {
            return Err(LieError::NonFinite {
                what: "SO(2) element",
            });
        }
        Ok(Vector1::new(self.angle()))
    }
    /// `ω ↦ ω J`.
    #[inline]
    fn hat(xi: &Vector1<f64>) -> Matrix2<f64> {
        Matrix2::new(0.0, -xi[0], xi[0], 0.0)
    }
    /// `(m₁₀ − m₀₁)/2` (the skew part's coordinate).
    #[inline]
    fn vee(m: &Matrix2<f64>) -> Vector1<f64> {
        Vector1::new(0.5 * (m[(1, 0)] - m[(0, 1)]))
    }
    #[inline]
    fn matrix(&self) -> Matrix2<f64> {
        self.rotation_matrix()
    }
    /// Checked with [`So2::TOLERANCE`]; see [`So2::from_matrix_with_tolerance`].
    fn from_matrix(m: &Matrix2<f64>) -> Result<Self, LieError> {
        Self::from_matrix_with_tolerance(m, Self::TOLERANCE)
    }
    fn from_matrix_unchecked(m: &Matrix2<f64>) -> Self {
        Self::from_rotation_block(m)
    }
    /// `Ad_g = 1` (abelian).
    #[inline]
    fn adjoint(&self) -> Matrix1<f64> {
        Matrix1::new(1.0)
    }
    /// `ad_ξ = 0` (abelian).
    #[inline]
    fn ad(_xi: &Vector1<f64>) -> Matrix1<f64> {
        Matrix1::new(0.0)
    }
    #[inline]
    fn adjoint_apply(&self, xi: &Vector1<f64>) -> Vector1<f64> {
        *xi
    }
    #[inline]
    fn coadjoint_apply(&self, mu: &Vector1<f64>) -> Vector1<f64> {
        *mu
    }
    #[inline]
    fn bracket(_xi: &Vector1<f64>, _eta: &Vector1<f64>) -> Vector1<f64> {
        Vector1::new(0.0)
    }
    #[inline]
    fn ad_dual_apply(_xi: &Vector1<f64>, _mu: &Vector1<f64>) -> Vector1<f64> {
        Vector1::new(0.0)
    }
    /// `d^L exp_ξ = 1` (abelian).
    #[inline]
    fn dexp_left(_xi: &Vector1<f64>) -> Matrix1<f64> {
        Matrix1::new(1.0)
    }
    #[inline]
    fn dexp_left_inv(_xi: &Vector1<f64>) -> Matrix1<f64> {
        Matrix1::new(1.0)
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.c.is_finite() && self.s.is_finite()
    }
}

impl CayleyGroup for So2 {
    /// cay is a diffeomorphism onto the elements whose rotation part is not a rotation by π; the
    /// round trip loses ≈ ε‖ξ‖² relative accuracy as g + I nears singularity (checked up to r).
    const CAY_INVERTIBLE_RADIUS: f64 = 1000.0;
    /// `cay(ω) = (1 + iω/2)/(1 − iω/2) = ((1 − ω²/4) + iω)/(1 + ω²/4)`.
    #[inline]
    fn cay(xi: &Vector1<f64>) -> Self {
        let w = xi[0];
        let k = 1.0 / (1.0 + 0.25 * w * w);
        Self {
            c: (1.0 - 0.25 * w * w) * k,
            s: w * k,
        }
    }
    /// `cay⁻¹(z) = 2 (z − 1)/(z + 1) = i · 2 sin θ/(1 + cos θ) = i · 2 tan(θ/2)`; an
    /// [`LieError::OutOfDomain`] error where `1 + cos θ < 1e-12` (the half turn).
    fn cay_inv(&self) -> Result<Vector1<f64>, LieError> {
        let d = 1.0 + self.c;
        if !self.is_finite() || d < CAY_INV_MIN {
            return Err(LieError::OutOfDomain(DomainReason::CayleyHalfTurn {
                one_plus_cos: d,
            }));
        }
        Ok(Vector1::new(2.0 * self.s / d))
    }
    /// `d^L cay_ω = (1 + iω/2)⁻¹ (1 − iω/2)⁻¹ = 1/(1 + ω²/4)` (everything commutes).
    #[inline]
    fn dcay_left(xi: &Vector1<f64>) -> Matrix1<f64> {
        Matrix1::new(1.0 / (1.0 + 0.25 * xi[0] * xi[0]))
    }
    /// `(d^L cay_ω)⁻¹ = 1 + ω²/4`.
    #[inline]
    fn dcay_left_inv(xi: &Vector1<f64>) -> Matrix1<f64> {
        Matrix1::new(1.0 + 0.25 * xi[0] * xi[0])
    }
}

/// Rotation of plane vectors: `g · p = R p`.
impl Action<Vector2<f64>> for So2 {
    type PointJacobian = nalgebra::Matrix2<f64>;
    type GroupJacobian = nalgebra::Vector2<f64>;
    #[inline]
    fn act(&self, p: &Vector2<f64>) -> Vector2<f64> {
        self.rotate(p)
    }
    /// `R`.
    #[inline]
    fn act_jacobian_point(&self, _p: &Vector2<f64>) -> nalgebra::Matrix2<f64> {
        self.matrix()
    }
    /// `R exp(δ) p ≈ R (p + δ J p)`, J the rotation by π/2: `R J p` (2×1).
    #[inline]
    fn act_jacobian_left(&self, p: &Vector2<f64>) -> Vector2<f64> {
        self.rotate(&Vector2::new(-p.y, p.x))
    }
    /// `exp(δ) R p ≈ R p + δ J R p`: `J R p` (equal to the left one: SO(2) is abelian).
    #[inline]
    fn act_jacobian_right(&self, p: &Vector2<f64>) -> Vector2<f64> {
        let q = self.rotate(p);
        Vector2::new(-q.y, q.x)
    }
}

impl From<UnitComplex<f64>> for So2 {
    fn from(z: UnitComplex<f64>) -> Self {
        Self { c: z.re, s: z.im }
    }
}

impl From<So2> for UnitComplex<f64> {
    fn from(g: So2) -> Self {
        UnitComplex::from_cos_sin_unchecked(g.c, g.s)
    }
}
