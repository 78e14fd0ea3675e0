//! The left trivialization tr_TG: TG → G ⋉ 𝔤 of §1.1 for matrix groups, where a tangent vector
//! u_g ∈ T_g G is a matrix u with g⁻¹ u ∈ 𝔤.
//!
//! The canonical (untrivialized) group structure of TG is
//! `u_g v_h = (u h + g v)_{gh}` and `(u_g)⁻¹ = (−g⁻¹ u g⁻¹)_{g⁻¹}`, and
//! `tr_TG(u_g) = (g, (g⁻¹ u)ˇ)` is a group isomorphism onto [`TangentBundle`]:
//! `tr_TG(u_g v_h) = tr_TG(u_g) tr_TG(v_h)`.

use crate::TangentBundle;
use faer::Mat;
use lie_groups::{DenseMatrix, LieError, LieGroup, StructureCheck, Vector};

/// Relative tolerance for `g⁻¹ u ∈ 𝔤` in [`tr_tg`]: `‖(g⁻¹u)ˇ^ − g⁻¹u‖_max ≤ TOL · (1 + ‖u‖_max)`.
const IN_ALGEBRA_TOL: f64 = 1e-9;

/// A tangent vector u_g ∈ T_g G of a matrix group: the pair of m×m matrices (g, u).
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixTangent {
    /// The base point g.
    pub g: Mat<f64>,
    /// The tangent vector u ∈ T_g G (so g⁻¹ u ∈ 𝔤).
    pub u: Mat<f64>,
}

impl MatrixTangent {
    /// The canonical product of TG: `u_g v_h = (u h + g v)_{gh}` (the tangent of the group product).
    pub fn compose(&self, other: &Self) -> Self {
        Self {
            g: &self.g * &other.g,
            u: &self.u * &other.g + &self.g * &other.u,
        }
    }
    /// The canonical inverse of TG: `(u_g)⁻¹ = (−g⁻¹ u g⁻¹)_{g⁻¹}`, or `None` if g is singular.
    pub fn inverse(&self) -> Option<Self> {
        let g_inv = lie_groups::matrix::dense::try_inverse(self.g.as_ref())?;
        let u = &(&g_inv * &self.u) * &g_inv;
        Some(Self {
            u: Mat::from_fn(u.nrows(), u.ncols(), |i, j| -u[(i, j)]),
            g: g_inv,
        })
    }
}

/// `tr_TG(u_g) = (g, (g⁻¹ u)ˇ)`: checks that g lies on G (`G::from_matrix`) and that g⁻¹ u ∈ 𝔤.
pub fn tr_tg<G: LieGroup>(v: &MatrixTangent) -> Result<TangentBundle<G>, LieError> {
    let gm = G::Matrix::from_mat(v.g.as_ref()).ok_or(LieError::DimensionMismatch {
        expected: G::identity().matrix().to_mat().nrows(),
        got: v.g.nrows(),
    })?;
    let g = G::from_matrix(&gm)?;
    if v.u.nrows() != v.g.nrows() || v.u.ncols() != v.g.ncols() {
        return Err(LieError::DimensionMismatch {
            expected: v.g.nrows(),
            got: v.u.nrows(),
        });
    }
    let x = g.inverse().matrix().to_mat() * &v.u;
    let xm = G::Matrix::from_mat(x.as_ref()).ok_or(LieError::DimensionMismatch {
        expected: v.g.nrows(),
        got: x.nrows(),
    })?;
    let xi = G::vee(&xm);
    if !xi.is_finite() {
        return Err(LieError::NonFinite { what: "u_g" });
    }
    let off = lie_groups::matrix::dense::max_abs_diff(G::hat(&xi).to_mat().as_ref(), x.as_ref());
    let tol = IN_ALGEBRA_TOL * (1.0 + v.u.as_ref().norm_max());
    if off > tol {
        return Err(LieError::NotStructured {
            check: StructureCheck::TrivializationNotInAlgebra,
            error: off,
            tolerance: tol,
        });
    }
    Ok(TangentBundle::from_parts(g, xi))
}

/// `tr_TG⁻¹(g, ξ) = (g, g ξ̂)_g`.
pub fn tr_tg_inv<G: LieGroup>(x: &TangentBundle<G>) -> MatrixTangent {
    let g = x.base().matrix().to_mat();
    let u = &g * G::hat(x.fiber()).to_mat();
    MatrixTangent { g, u }
}
