//! ℝⁿ as an abelian Lie group under vector addition, on nalgebra stack types.
//!
//! - Element `x ∈ ℝⁿ`, product `x · y = x + y`, identity 0, inverse `−x`.
//! - Algebra ℝⁿ ≅ ℝⁿ (the standard basis), and 𝔤* ≅ ℝⁿ by the Euclidean pairing.
//! - The group is abelian, so `exp ξ = ξ` and `log x = x` (the identity map, defined on all of ℝⁿ),
//!   `Ad_x = I`, `ad_ξ = 0`, `[ξ, η] = 0`, `d^L exp_ξ = I`, and the coadjoint action is trivial:
//!   a Lie–Poisson system on ℝⁿ has μ̇ = F (the momentum changes only by forces).
//! - Matrix representation: the (n+1)×(n+1) affine matrix `[[I, x], [0, 1]]` (translations of
//!   ℝⁿ as homogeneous transforms), with `ξ̂ = [[0, ξ], [0, 0]]`. Since `ξ̂² = 0`,
//!   `e^{ξ̂} = I + ξ̂` and the Cayley map `(I − ξ̂/2)⁻¹(I + ξ̂/2) = (I + ξ̂/2)² = I + ξ̂` equal the
//!   identity map too, so `Rn` is a [`CayleyGroup`] with `cay = exp`.
//!
//! The matrix is a nalgebra [`DMatrix`] (a stack `SMatrix<N + 1, N + 1>` is not expressible for a
//! generic `N` on stable Rust); it only serves `hat`, `matrix` and the generic matrix path, never a step of
//! an integrator, which works on the stack vector alone.

use crate::{CayleyGroup, LieError, LieGroup, StructureCheck};
use nalgebra::{DMatrix, SMatrix, SVector};

/// A point of ℝᴺ as an element of the additive group (see the module page for the conventions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rn<const N: usize> {
    x: SVector<f64, N>,
}

impl<const N: usize> Rn<N> {
    /// Default tolerance of [`LieGroup::from_matrix`]: the entries of `[[I, ·], [0, 1]]` outside
    /// the translation column may deviate by at most this much.
    pub const TOLERANCE: f64 = 1e-9;

    /// The element x.
    #[inline]
    pub const fn new(x: SVector<f64, N>) -> Self {
        Self { x }
    }

    /// The vector x.
    #[inline]
    pub fn vector(&self) -> SVector<f64, N> {
        self.x
    }

    /// Checked constructor with an explicit tolerance: refuses a shape other than (N+1)×(N+1)
    /// ([`LieError::DimensionMismatch`]), non-finite entries ([`LieError::NonFinite`]), a bottom row
    /// farther than `tol` from `[0, …, 0, 1]` ([`LieError::NotHomogeneous`]) and a top-left block
    /// farther than `tol` from I ([`LieError::NotStructured`] with
    /// [`StructureCheck::TranslationLinearBlock`]).
    pub fn from_matrix_with_tolerance(m: &DMatrix<f64>, tol: f64) -> Result<Self, LieError> {
        if m.nrows() != N + 1 || m.ncols() != N + 1 {
            return Err(LieError::DimensionMismatch {
                expected: N + 1,
                got: if m.nrows() != N + 1 {
                    m.nrows()
                } else {
                    m.ncols()
                },
            });
        }
        if !(0..=N).all(|j| (0..=N).all(|i| m[(i, j)].is_finite())) {
            return Err(LieError::NonFinite { what: "matrix" });
        }
        let bottom = (0..=N).fold(0.0f64, |e, j| {
            let want = if j == N { 1.0 } else { 0.0 };
            e.max((m[(N, j)] - want).abs())
        });
        if bottom > tol {
            return Err(LieError::NotHomogeneous { error: bottom });
        }
        let block = (0..N).fold(0.0f64, |e, j| {
            (0..N).fold(e, |e, i| {
                let want = if i == j { 1.0 } else { 0.0 };
                e.max((m[(i, j)] - want).abs())
            })
        });
        if block > tol {
            return Err(LieError::NotStructured {
                check: StructureCheck::TranslationLinearBlock,
                error: block,
                tolerance: tol,
            });
        }
        Ok(Self::from_matrix_unchecked(m))
    }
}

impl<const N: usize> From<SVector<f64, N>> for Rn<N> {
    fn from(x: SVector<f64, N>) -> Self {
        Self::new(x)
    }
}

impl<const N: usize> LieGroup for Rn<N> {
    /// `log ∘ exp` is the identity on all of ℝᴺ; every finite radius is valid, and 1e100 keeps
    /// `r ξ` finite for unit-size directions.
    const EXP_INVERTIBLE_RADIUS: f64 = 1e100;
    type Algebra = SVector<f64, N>;
    type Operator = SMatrix<f64, N, N>;
    type Matrix = DMatrix<f64>;

    fn name() -> String {
        format!("R^{N}")
    }
    fn dim() -> usize {
        N
    }
    #[inline]
    fn identity() -> Self {
        Self::new(SVector::zeros())
    }
    /// `x · y = x + y`.
    #[inline]
    fn compose(&self, other: &Self) -> Self {
        Self::new(self.x + other.x)
    }
    /// `x⁻¹ = −x`.
    #[inline]
    fn inverse(&self) -> Self {
        Self::new(-self.x)
    }
    /// `exp ξ = ξ`.
    #[inline]
    fn exp(xi: &SVector<f64, N>) -> Self {
        Self::new(*xi)
    }
    /// `log x = x`; an error only for non-finite input.
    #[inline]
    fn log(&self) -> Result<SVector<f64, N>, LieError> {
        if self.is_finite() {
            Ok(self.x)
        } else {
            Err(LieError::NonFinite {
                what: "R^n element",
            })
        }
    }
    /// `ξ̂ = [[0, ξ], [0, 0]]`, (N+1)×(N+1).
    fn hat(xi: &SVector<f64, N>) -> DMatrix<f64> {
        DMatrix::from_fn(
            N + 1,
            N + 1,
            |i, j| if j == N && i < N { xi[i] } else { 0.0 },
        )
    }
    /// The last column's first N entries (the rest of the matrix is ignored).
    fn vee(m: &DMatrix<f64>) -> SVector<f64, N> {
        SVector::from_fn(|i, _| m[(i, N)])
    }
    /// `[[I, x], [0, 1]]`.
    fn matrix(&self) -> DMatrix<f64> {
        DMatrix::from_fn(N + 1, N + 1, |i, j| {
            if i == j {
                1.0
            } else if j == N {
                self.x[i]
            } else {
                0.0
            }
        })
    }
    /// Checked with [`Rn::TOLERANCE`]; see [`Rn::from_matrix_with_tolerance`].
    fn from_matrix(m: &DMatrix<f64>) -> Result<Self, LieError> {
        Self::from_matrix_with_tolerance(m, Self::TOLERANCE)
    }
    /// Reads x off the last column.
    fn from_matrix_unchecked(m: &DMatrix<f64>) -> Self {
        Self::new(Self::vee(m))
    }
    /// `Ad_x = I` (abelian).
    #[inline]
    fn adjoint(&self) -> SMatrix<f64, N, N> {
        SMatrix::identity()
    }
    /// `ad_ξ = 0` (abelian).
    #[inline]
    fn ad(_xi: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::zeros()
    }
    #[inline]
    fn adjoint_apply(&self, xi: &SVector<f64, N>) -> SVector<f64, N> {
        *xi
    }
    #[inline]
    fn adjoint_inverse_apply(&self, xi: &SVector<f64, N>) -> SVector<f64, N> {
        *xi
    }
    #[inline]
    fn coadjoint_apply(&self, mu: &SVector<f64, N>) -> SVector<f64, N> {
        *mu
    }
    #[inline]
    fn bracket(_xi: &SVector<f64, N>, _eta: &SVector<f64, N>) -> SVector<f64, N> {
        SVector::zeros()
    }
    #[inline]
    fn ad_dual_apply(_xi: &SVector<f64, N>, _mu: &SVector<f64, N>) -> SVector<f64, N> {
        SVector::zeros()
    }
    /// `M(μ) = 0`.
    #[inline]
    fn ad_dual_operator(_mu: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::zeros()
    }
    /// `d^L exp_ξ = I`.
    #[inline]
    fn dexp_left(_xi: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::identity()
    }
    /// `(d^L exp_ξ)⁻¹ = I`.
    #[inline]
    fn dexp_left_inv(_xi: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::identity()
    }
    /// `(Ad*_{exp ξ} − I) μ = 0`.
    #[inline]
    fn exp_coadjoint_increment(_xi: &SVector<f64, N>, _mu: &SVector<f64, N>) -> SVector<f64, N> {
        SVector::zeros()
    }
    /// `(Ad_{exp ξ} − I) v = 0`.
    #[inline]
    fn exp_adjoint_increment(_xi: &SVector<f64, N>, _v: &SVector<f64, N>) -> SVector<f64, N> {
        SVector::zeros()
    }
    /// `x exp ξ = x + ξ`.
    #[inline]
    fn exp_compose(g: &Self, xi: &SVector<f64, N>) -> Self {
        Self::new(g.x + xi)
    }
    /// `d^{L*}exp_ξ μ = μ`.
    #[inline]
    fn dexp_left_dual_apply(_xi: &SVector<f64, N>, mu: &SVector<f64, N>) -> SVector<f64, N> {
        *mu
    }
    /// `∂/∂ξ (d^{L*}exp_ξ μ) = 0` (exact: d^{L*}exp_ξ = I for every ξ).
    #[inline]
    fn dexp_left_dual_derivative(
        _xi: &SVector<f64, N>,
        _mu: &SVector<f64, N>,
    ) -> SMatrix<f64, N, N> {
        SMatrix::zeros()
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.x.iter().all(|v| v.is_finite())
    }
    /// `‖x − y‖_max`, the max-norm distance of the affine matrices.
    #[inline]
    fn matrix_distance(&self, other: &Self) -> f64 {
        (self.x - other.x).amax()
    }
}

impl<const N: usize> CayleyGroup for Rn<N> {
    /// `cay⁻¹ ∘ cay` is the identity on all of ℝᴺ (as for exp).
    const CAY_INVERTIBLE_RADIUS: f64 = 1e100;
    /// `cay ξ = (I − ξ̂/2)⁻¹(I + ξ̂/2) = I + ξ̂`, i.e. `cay ξ = ξ = exp ξ`.
    #[inline]
    fn cay(xi: &SVector<f64, N>) -> Self {
        Self::new(*xi)
    }
    /// `cay⁻¹ x = x`; an error only for non-finite input.
    #[inline]
    fn cay_inv(&self) -> Result<SVector<f64, N>, LieError> {
        self.log()
    }
    /// `d^L cay_ξ = I`.
    #[inline]
    fn dcay_left(_xi: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::identity()
    }
    /// `(d^L cay_ξ)⁻¹ = I`.
    #[inline]
    fn dcay_left_inv(_xi: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::identity()
    }
    /// `(Ad*_{cay ξ} − I) μ = 0`.
    #[inline]
    fn cay_coadjoint_increment(_xi: &SVector<f64, N>, _mu: &SVector<f64, N>) -> SVector<f64, N> {
        SVector::zeros()
    }
    /// `(Ad_{cay ξ} − I) v = 0`.
    #[inline]
    fn cay_adjoint_increment(_xi: &SVector<f64, N>, _v: &SVector<f64, N>) -> SVector<f64, N> {
        SVector::zeros()
    }
    /// `x cay ξ = x + ξ`.
    #[inline]
    fn cay_compose(g: &Self, xi: &SVector<f64, N>) -> Self {
        Self::new(g.x + xi)
    }
    /// `x cay(θξ) cay((1−θ)ξ) = x + ξ` (one sum, as for exp).
    #[inline]
    fn cay_split_compose(g: &Self, _theta: f64, xi: &SVector<f64, N>) -> Self {
        Self::new(g.x + xi)
    }
    /// `d^{L*}cay_ξ μ = μ`.
    #[inline]
    fn dcay_left_dual_apply(_xi: &SVector<f64, N>, mu: &SVector<f64, N>) -> SVector<f64, N> {
        *mu
    }
    /// `∂/∂ξ (d^{L*}cay_ξ μ) = 0`.
    #[inline]
    fn dcay_left_dual_derivative(
        _xi: &SVector<f64, N>,
        _mu: &SVector<f64, N>,
    ) -> SMatrix<f64, N, N> {
        SMatrix::zeros()
    }
}

/// Translation of points: `x · p = p + x`; every Jacobian is I.
impl<const N: usize> crate::Action<SVector<f64, N>> for Rn<N> {
    type PointJacobian = SMatrix<f64, N, N>;
    type GroupJacobian = SMatrix<f64, N, N>;
    #[inline]
    fn act(&self, p: &SVector<f64, N>) -> SVector<f64, N> {
        p + self.x
    }
    #[inline]
    fn act_jacobian_point(&self, _p: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::identity()
    }
    #[inline]
    fn act_jacobian_left(&self, _p: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::identity()
    }
    #[inline]
    fn act_jacobian_right(&self, _p: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        SMatrix::identity()
    }
}
