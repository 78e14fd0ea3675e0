//! The left trivialization tr_TG: TG → G ⋉ 𝔤 of §1.1 for matrix groups, where a tangent vector
//! u_g ∈ T_g G is a matrix u with g⁻¹ u ∈ 𝔤.
//!
//! The canonical (untrivialized) group structure of TG is
//! `u_g v_h = (u h + g v)_{gh}` and `(u_g)⁻¹ = (−g⁻¹ u g⁻¹)_{g⁻¹}`, and
//! `tr_TG(u_g) = (g, (g⁻¹ u)ˇ)` is a group isomorphism onto [`TangentBundle`]:
//! `tr_TG(u_g v_h) = tr_TG(u_g) tr_TG(v_h)`.
//!
//! Likewise for T*G → G ⋉ 𝔤* ([`CotangentBundle`]): a covector p_g ∈ T*_g G is a matrix p paired
//! with T_g G by the Frobenius product `⟨p, u⟩ = tr(pᵀu)` (p matters up to the annihilator of
//! T_g G). The canonical structure is `p_g q_h = (p h⁻ᵀ + g⁻ᵀ q)_{gh}` — the covector
//! `T*R_{h⁻¹} p + T*L_{g⁻¹} q`, dual to TG's `u h + g v` — with inverse `(−gᵀ p gᵀ)_{g⁻¹}`, and the
//! left trivialization `tr_T*G(p_g) = (g, T*_e L_g p)`, `(T*_e L_g p)_i = ⟨p, g Êᵢ⟩`, is a group
//! isomorphism onto `(g, μ)(h, ν) = (gh, Ad*_h μ + ν)`: the first term pairs with ξ as
//! `tr(h⁻¹pᵀ g h ξ̂) = ⟨μ, Ad_h ξ⟩`, the second as `tr(qᵀ h ξ̂) = ⟨ν, ξ⟩`. (The paper prints
//! `Ad*_{h⁻¹}μ` for the coadjoint action; in the dual-map convention of this crate it is `Ad*_h μ`,
//! docs/conventions.md.)

use crate::{CotangentBundle, TangentBundle};
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

/// A covector p_g ∈ T*_g G of a matrix group: the pair (g, p) of m×m matrices, p acting on
/// u ∈ T_g G by `⟨p, u⟩ = tr(pᵀu)`; p is determined by these pairings, i.e. up to the annihilator
/// of T_g G ([`tr_tstar_g_inv`] returns the representative in g⁻ᵀ𝔤).
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixCotangent {
    /// The base point g.
    pub g: Mat<f64>,
    /// The covector p.
    pub p: Mat<f64>,
}

impl MatrixCotangent {
    /// The canonical product of T*G: `p_g q_h = (p h⁻ᵀ + g⁻ᵀ q)_{gh}`, or `None` if g or h is
    /// singular.
    pub fn compose(&self, other: &Self) -> Option<Self> {
        let g_inv = lie_groups::matrix::dense::try_inverse(self.g.as_ref())?;
        let h_inv = lie_groups::matrix::dense::try_inverse(other.g.as_ref())?;
        Some(Self {
            g: &self.g * &other.g,
            p: &self.p * h_inv.transpose() + g_inv.transpose() * &other.p,
        })
    }
    /// The canonical inverse of T*G: `(p_g)⁻¹ = (−gᵀ p gᵀ)_{g⁻¹}`, or `None` if g is singular.
    pub fn inverse(&self) -> Option<Self> {
        let g_inv = lie_groups::matrix::dense::try_inverse(self.g.as_ref())?;
        let p = &(self.g.transpose() * &self.p) * self.g.transpose();
        Some(Self {
            p: Mat::from_fn(p.nrows(), p.ncols(), |i, j| -p[(i, j)]),
            g: g_inv,
        })
    }
    /// `⟨p, u⟩ = tr(pᵀu)` for a tangent vector u ∈ T_g G given as a matrix.
    pub fn pair(&self, u: &Mat<f64>) -> f64 {
        frobenius(&self.p, u)
    }
}

/// `tr(aᵀb) = Σᵢⱼ aᵢⱼ bᵢⱼ`.
fn frobenius(a: &Mat<f64>, b: &Mat<f64>) -> f64 {
    (0..a.nrows())
        .flat_map(|i| (0..a.ncols()).map(move |j| (i, j)))
        .map(|(i, j)| a[(i, j)] * b[(i, j)])
        .sum()
}

/// `tr_T*G(p_g) = (g, μ)` with `μᵢ = ⟨p, g Êᵢ⟩ = tr(pᵀ g Êᵢ)` (`Êᵢ = hat(eᵢ)`), so that
/// `⟨μ, ξ⟩ = μ·ξ = ⟨p, g ξ̂⟩`; checks that g lies on G and that p is finite.
pub fn tr_tstar_g<G: LieGroup>(c: &MatrixCotangent) -> Result<CotangentBundle<G>, LieError> {
    let gm = G::Matrix::from_mat(c.g.as_ref()).ok_or(LieError::DimensionMismatch {
        expected: G::identity().matrix().to_mat().nrows(),
        got: c.g.nrows(),
    })?;
    let g = G::from_matrix(&gm)?;
    if c.p.nrows() != c.g.nrows() || c.p.ncols() != c.g.ncols() {
        return Err(LieError::DimensionMismatch {
            expected: c.g.nrows(),
            got: c.p.nrows(),
        });
    }
    let n = G::dim();
    let mu = G::Algebra::from_fn(n, |i| {
        c.pair(&(&c.g * G::hat(&G::Algebra::basis(n, i)).to_mat()))
    });
    if !mu.is_finite() {
        return Err(LieError::NonFinite { what: "p_g" });
    }
    Ok(CotangentBundle::from_parts(g, mu))
}

/// `tr_T*G⁻¹(g, μ) = (g, g⁻ᵀ M)_g` with `M = Σⱼ cⱼ Êⱼ ∈ 𝔤`, `c = Γ⁻¹ μ` for the Gram matrix
/// `Γᵢⱼ = ⟨Êᵢ, Êⱼ⟩` (so `⟨g⁻ᵀM, g Êᵢ⟩ = ⟨M, Êᵢ⟩ = μᵢ`): the representative of the covector in
/// g⁻ᵀ𝔤, orthogonal to the annihilator of T_g G.
pub fn tr_tstar_g_inv<G: LieGroup>(x: &CotangentBundle<G>) -> MatrixCotangent {
    let n = G::dim();
    let basis: Vec<Mat<f64>> = (0..n)
        .map(|i| G::hat(&G::Algebra::basis(n, i)).to_mat())
        .collect();
    let gram = Mat::from_fn(n, n, |i, j| frobenius(&basis[i], &basis[j]));
    let mu = Mat::from_fn(n, 1, |i, _| x.fiber().get(i));
    // Γ is symmetric positive definite (the Êᵢ are linearly independent).
    let c = gram.llt(faer::Side::Lower).map_or_else(
        |_| Mat::from_fn(n, 1, |_, _| f64::NAN),
        |llt| faer::linalg::solvers::Solve::solve(&llt, &mu),
    );
    let m = basis.iter().enumerate().fold(
        Mat::zeros(basis[0].nrows(), basis[0].ncols()),
        |acc, (j, e)| acc + e * faer::Scale(c[(j, 0)]),
    );
    let g = x.base().matrix().to_mat();
    let g_inv_t = lie_groups::matrix::dense::try_inverse(g.as_ref())
        .map(|gi| gi.transpose().to_owned())
        .unwrap_or_else(|| Mat::from_fn(g.nrows(), g.ncols(), |_, _| f64::NAN));
    MatrixCotangent { p: g_inv_t * m, g }
}
