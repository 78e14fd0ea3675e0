//! SO(n) for any n, on faer.
//!
//! - Element: an n×n rotation matrix R (`RᵀR = I`, det R = +1), stored as `faer::Mat<f64>`.
//! - Algebra 𝔰𝔬(n) ≅ ℝ^{n(n−1)/2}, basis in **lexicographic pair order** (0,1), (0,2), …, (0,n−1),
//!   (1,2), …, (n−2,n−1): coordinate p of the pair (i, j), i < j, is `ξ̂_{ji} = ξ_p = −ξ̂_{ij}`, so
//!   the generator `E_{ij} = e_j e_iᵀ − e_i e_jᵀ` turns e_i towards e_j. For n = 3 this gives
//!   `(ξ₀, ξ₁, ξ₂) = (ω_z, −ω_y, ω_x)` relative to the cross-product convention of `So3`.
//! - The Euclidean pairing of coordinates is `⟨μ, ξ⟩ = ½ tr(μ̂ᵀ ξ̂)`, for which Ad_g is orthogonal
//!   and ad_ξ skew: `Ad*_g = Ad_{g⁻¹}`, `ad*_ξ μ = [μ, ξ]`. The overridden `adjoint_apply`,
//!   `coadjoint_apply`, `bracket` and `ad_dual_apply` use these O(n³) matrix formulas and never form
//!   the n(n−1)/2-square operator.
//! - `exp` is the [13/13] Padé scaling-and-squaring `expm`; `log` uses the symmetric eigenproblem
//!   of `R + Rᵀ` (see [`SoN::log`]), which stays exact at rotation angle π where the square-root
//!   iteration of `logm` breaks down.

use crate::matrix::dense::{expm, logm, max_abs_diff};
use crate::{matrix_path, Action, CayleyGroup, DomainReason, LieError, LieGroup};
use core::f64::consts::PI;
use faer::linalg::solvers::{DenseSolveCore, Solve};
use faer::{Col, Mat, MatRef, Side};

/// A rotation of ℝᴺ (see the module page for the conventions).
#[derive(Debug, Clone, PartialEq)]
pub struct SoN<const N: usize> {
    m: Mat<f64>,
}

/// Eigenvalues of `R + Rᵀ` closer than this are one cluster (one block of the log).
const CLUSTER_GAP: f64 = 1e-3;

/// Index of the pair (i, j), i < j, in the lexicographic order.
#[inline]
fn pair(n: usize, i: usize, j: usize) -> usize {
    debug_assert!(i < j && j < n);
    i * n - i * (i + 1) / 2 + (j - i - 1)
}

/// `ξ ↦ ξ̂` for 𝔰𝔬(n) with n = `n` (lexicographic pairs, `ξ̂_{ji} = ξ_p`).
pub fn so_hat(n: usize, xi: &Col<f64>) -> Mat<f64> {
    let mut m = Mat::zeros(n, n);
    let mut p = 0;
    for i in 0..n {
        for j in i + 1..n {
            m[(j, i)] = xi[p];
            m[(i, j)] = -xi[p];
            p += 1;
        }
    }
    m
}

/// `ξ̂ ↦ ξ` for 𝔰𝔬(n): `ξ_p = (m_{ji} − m_{ij})/2` (the skew part; the symmetric part is ignored).
pub fn so_vee(m: MatRef<'_, f64>) -> Col<f64> {
    let n = m.nrows();
    let mut xi = Col::zeros(n * (n - 1) / 2);
    let mut p = 0;
    for i in 0..n {
        for j in i + 1..n {
            xi[p] = 0.5 * (m[(j, i)] - m[(i, j)]);
            p += 1;
        }
    }
    xi
}

/// The operator `ξ ↦ (h ξ̂ hᵀ)ˇ` on 𝔰𝔬(n) for any n×n matrix h, the second compound matrix of h:
/// entry `((i,j),(k,l)) = h_{ik} h_{jl} − h_{il} h_{jk}`. O(n⁴) = O(dim²) work, the size of the
/// output. With h = g it is Ad_g; with `h = (I ± ξ̂/2)^{∓1}` the Cayley tangents.
pub fn so_compound(h: MatRef<'_, f64>) -> Mat<f64> {
    let n = h.nrows();
    let d = n * (n - 1) / 2;
    let mut out = Mat::zeros(d, d);
    let mut q = 0;
    for k in 0..n {
        for l in k + 1..n {
            let mut p = 0;
            for i in 0..n {
                let (hik, hil) = (h[(i, k)], h[(i, l)]);
                for j in i + 1..n {
                    out[(p, q)] = hik * h[(j, l)] - hil * h[(j, k)];
                    p += 1;
                }
            }
            q += 1;
        }
    }
    out
}

/// `(A − Aᵀ)/2`: removes the round-off symmetric part of a computed skew matrix.
fn skew_part(a: MatRef<'_, f64>) -> Mat<f64> {
    let n = a.nrows();
    Mat::from_fn(n, n, |i, j| 0.5 * (a[(i, j)] - a[(j, i)]))
}

fn out_of_domain(reason: DomainReason) -> LieError {
    LieError::OutOfDomain(reason)
}

/// `g(x) = asin(√x)/√x` for x ∈ [0, 3/4]: its Maclaurin series below 10⁻³ (the first omitted
/// term, 63x⁵/2816, is below 2.3e-17 there), else the closed form.
fn asin_sqrt_ratio(x: f64) -> f64 {
    if x < 1e-3 {
        1.0 + x * (1.0 / 6.0 + x * (3.0 / 40.0 + x * (5.0 / 112.0 + x * 35.0 / 1152.0)))
    } else {
        let s = x.sqrt();
        s.asin() / s
    }
}

/// log R for a rotation whose angles all satisfy cos θₖ > ½ (|θₖ| < π/3), to a few ulps relative
/// at any size down to subnormal: with `S = (R − Rᵀ)/2 = Σ sin θₖ Jₖ` (entries as accurate as R's
/// off-diagonal, however small) and `−S² = SᵀS = Σ sin²θₖ Pₖ`,
/// `log R = Σ θₖ Jₖ = S · g(SᵀS)`, g(x) = asin(√x)/√x applied through the symmetric eigenproblem
/// of SᵀS (g ≈ 1 + x/6: no cancellation). The general path reads θ off R + Rᵀ, whose entries
/// near I carry θ only as 1 − θ²/2, and loses relative accuracy as θ → 0.
fn log_near_identity(r: MatRef<'_, f64>) -> Result<Mat<f64>, LieError> {
    let n = r.nrows();
    let s = Mat::from_fn(n, n, |i, j| 0.5 * (r[(i, j)] - r[(j, i)]));
    let scale = s.as_ref().norm_max();
    if scale == 0.0 {
        return Ok(Mat::zeros(n, n));
    }
    // Scale S to unit size before forming SᵀS (no underflow for subnormal angles).
    let u = Mat::from_fn(n, n, |i, j| s[(i, j)] / scale);
    let x = u.transpose() * &u;
    let eig = x
        .self_adjoint_eigen(Side::Lower)
        .map_err(|_| out_of_domain(DomainReason::EigensolverNoConvergence))?;
    let w = eig.U();
    let sig = eig.S().column_vector();
    let gdiag = Mat::from_fn(n, n, |i, j| {
        if i == j {
            asin_sqrt_ratio((sig[i].max(0.0) * scale * scale).min(0.75))
        } else {
            0.0
        }
    });
    let g = w * (&gdiag * w.transpose());
    Ok(skew_part((&s * &g).as_ref()))
}

/// The principal logarithm of a rotation matrix (see [`SoN::log`]).
fn log_rotation(r: MatRef<'_, f64>) -> Result<Mat<f64>, LieError> {
    let n = r.nrows();
    if n < 2 {
        return Ok(Mat::zeros(n, n));
    }
    let s = Mat::from_fn(n, n, |i, j| r[(i, j)] + r[(j, i)]);
    let eig = s
        .self_adjoint_eigen(Side::Lower)
        .map_err(|_| out_of_domain(DomainReason::EigensolverNoConvergence))?;
    let v = eig.U();
    let lam = eig.S().column_vector();
    if (0..n).all(|i| lam[i] > 1.0) {
        return log_near_identity(r);
    }
    // R in the eigenbasis of R + Rᵀ: block diagonal, one block per cluster of equal cos θ.
    let b = v.transpose() * (r * v);
    let mut lt = Mat::<f64>::zeros(n, n);
    let mut start = 0;
    while start < n {
        let mut end = start + 1;
        while end < n && lam[end] - lam[end - 1] <= CLUSTER_GAP {
            end += 1;
        }
        let d = end - start;
        let cos_mean = (start..end).map(|i| lam[i]).sum::<f64>() / (2.0 * d as f64);
        let blk = b.as_ref().submatrix(start, start, d, d);
        match d {
            1 if cos_mean > 0.0 => {} // a fixed axis: log is 0 there
            1 => return Err(out_of_domain(DomainReason::LoneEigenvalueMinusOne)),
            2 => {
                // one rotation plane: read θ off the 2×2 block by atan2 (well conditioned
                // everywhere, including θ = π where either sign is a valid logarithm)
                let th =
                    (0.5 * (blk[(1, 0)] - blk[(0, 1)])).atan2(0.5 * (blk[(0, 0)] + blk[(1, 1)]));
                lt[(start + 1, start)] = th;
                lt[(start, start + 1)] = -th;
            }
            _ if cos_mean > -0.5 => {
                // several planes with (nearly) equal angles < 2π/3: no eigenvalue near −1, so the
                // inverse scaling-and-squaring logm is accurate on the block
                let l = logm(blk)?;
                lt.as_mut()
                    .submatrix_mut(start, start, d, d)
                    .copy_from(skew_part(l.as_ref()));
            }
            _ => {
                // several planes with angles near π: −B has eigenvalues near +1, K = log(−B) holds
                // the deviations φₖ = θₖ − π, and log B = K − π·polar(K) (polar(K) = Σ sign(φₖ) Jₖ
                // is the complex structure of the planes, oriented to keep θ in (−π, π]).
                if d % 2 == 1 {
                    return Err(out_of_domain(DomainReason::OddEigenspaceAtPi));
                }
                let neg = Mat::from_fn(d, d, |i, j| -blk[(i, j)]);
                let k = skew_part(logm(neg.as_ref())?.as_ref());
                let kmax = k.as_ref().norm_max();
                let jmat = if kmax <= 1e-15 {
                    // B = −I: every complex structure gives a logarithm; take the standard one.
                    Mat::from_fn(d, d, |i, j| {
                        if i == j + 1 && j % 2 == 0 {
                            1.0
                        } else if j == i + 1 && i % 2 == 0 {
                            -1.0
                        } else {
                            0.0
                        }
                    })
                } else {
                    let svd = k
                        .svd()
                        .map_err(|_| out_of_domain(DomainReason::LogSvdNoConvergence))?;
                    let sv = svd.S().column_vector();
                    let smin = (0..d).map(|i| sv[i]).fold(f64::INFINITY, f64::min);
                    if smin < 1e-8 * kmax {
                        return Err(out_of_domain(DomainReason::IllConditionedAtPi));
                    }
                    skew_part((svd.U() * svd.V().transpose()).as_ref())
                };
                lt.as_mut()
                    .submatrix_mut(start, start, d, d)
                    .copy_from(Mat::from_fn(d, d, |i, j| k[(i, j)] - PI * jmat[(i, j)]));
            }
        }
        start = end;
    }
    let l = v * (&lt * v.transpose());
    Ok(skew_part(l.as_ref()))
}

impl<const N: usize> SoN<N> {
    /// Default tolerance of [`LieGroup::from_matrix`]: `‖RᵀR − I‖_max ≤ 1e-9` and
    /// `|det R − 1| ≤ N · 1e-9` (orthogonality within tol bounds `|det| − 1` by about N·tol/2).
    pub const TOLERANCE: f64 = 1e-9;

    /// Dimension `N(N−1)/2` of 𝔰𝔬(N).
    pub const DIM: usize = N * (N.saturating_sub(1)) / 2;

    /// The matrix R (borrowed).
    pub fn as_mat(&self) -> MatRef<'_, f64> {
        self.m.as_ref()
    }

    /// Checked constructor with an explicit tolerance: refuses a shape other than N×N
    /// ([`LieError::DimensionMismatch`]), non-finite entries, `‖RᵀR − I‖_max > tol`
    /// ([`LieError::NotOrthogonal`]) and `|det R − 1| > N·tol` ([`LieError::WrongDeterminant`]).
    pub fn from_matrix_with_tolerance(m: &Mat<f64>, tol: f64) -> Result<Self, LieError> {
        check_shape::<N>(m)?;
        let err = max_abs_diff(
            (m.transpose() * m).as_ref(),
            Mat::<f64>::identity(N, N).as_ref(),
        );
        if err > tol {
            return Err(LieError::NotOrthogonal {
                error: err,
                tolerance: tol,
            });
        }
        let det = m.determinant();
        if (det - 1.0).abs() > N as f64 * tol {
            return Err(LieError::WrongDeterminant {
                det,
                tolerance: N as f64 * tol,
            });
        }
        Ok(Self { m: m.clone() })
    }

    /// The nearest rotation to M in the Frobenius norm: with the SVD `M = U Σ Vᵀ`,
    /// `R = U diag(1, …, 1, sign det(U Vᵀ)) Vᵀ` (the special orthogonal polar factor). An error for
    /// a wrong shape, non-finite entries, or an SVD that does not converge.
    pub fn project(m: &Mat<f64>) -> Result<Self, LieError> {
        check_shape::<N>(m)?;
        let svd = m
            .svd()
            .map_err(|_| LieError::OutOfDomain(DomainReason::ProjectSvdNoConvergence))?;
        let (u, v) = (svd.U(), svd.V());
        let det = (u * v.transpose()).determinant();
        let mut u = u.to_owned();
        if det < 0.0 {
            // flip the direction of the smallest singular value (faer sorts them decreasingly)
            for i in 0..N {
                u[(i, N - 1)] = -u[(i, N - 1)];
            }
        }
        Ok(Self {
            m: &u * v.transpose(),
        })
    }

    /// `(I + ξ̂/2)`, whose transpose is `I − ξ̂/2`.
    fn cayley_factor(xi: &Col<f64>) -> Mat<f64> {
        let a = so_hat(N, xi);
        Mat::from_fn(
            N,
            N,
            |i, j| if i == j { 1.0 } else { 0.0 } + 0.5 * a[(i, j)],
        )
    }
}

fn check_shape<const N: usize>(m: &Mat<f64>) -> Result<(), LieError> {
    if m.nrows() != N || m.ncols() != N {
        return Err(LieError::DimensionMismatch {
            expected: N,
            got: if m.nrows() != N { m.nrows() } else { m.ncols() },
        });
    }
    if !(0..N).all(|j| (0..N).all(|i| m[(i, j)].is_finite())) {
        return Err(LieError::NonFinite { what: "matrix" });
    }
    Ok(())
}

impl<const N: usize> LieGroup for SoN<N> {
    type Algebra = Col<f64>;
    type Operator = Mat<f64>;
    type Matrix = Mat<f64>;

    fn name() -> String {
        format!("SO({N})")
    }
    fn dim() -> usize {
        Self::DIM
    }
    fn identity() -> Self {
        Self {
            m: Mat::identity(N, N),
        }
    }
    fn compose(&self, other: &Self) -> Self {
        Self {
            m: &self.m * &other.m,
        }
    }
    /// `R⁻¹ = Rᵀ`.
    fn inverse(&self) -> Self {
        Self {
            m: self.m.transpose().to_owned(),
        }
    }
    /// `exp(ξ) = e^{ξ̂}` by [13/13] Padé scaling and squaring.
    fn exp(xi: &Col<f64>) -> Self {
        Self {
            m: expm(so_hat(N, xi).as_ref()),
        }
    }
    /// The principal logarithm (all rotation angles θₖ in [−π, π]). When every angle is below
    /// π/3 (all eigenvalues of R + Rᵀ above 1), `log R = S·g(SᵀS)` with `S = (R − Rᵀ)/2` and
    /// g(x) = asin(√x)/√x, accurate to a few ulps relative down to subnormal angles. Otherwise by
    /// the symmetric eigenproblem `R + Rᵀ = V diag(2 cos θₖ) Vᵀ`: in the eigenbasis R is block diagonal with one block per
    /// cluster of equal cos θ. A 2×2 block (one plane) gives θ = atan2 of its entries, exact up to
    /// round-off for every θ including π (there either sign is returned: both are logarithms);
    /// larger clusters use `logm` on the block (angles < 2π/3) or on minus the block (angles near
    /// π, with the complex structure taken as the polar factor of that log).
    ///
    /// Errors ([`LieError::OutOfDomain`]): non-finite input; a lone eigenvalue −1 (det R = −1); and
    /// the degenerate case of several planes at angle exactly π mixed in one cluster with planes
    /// within about 10⁻⁸ of π, where no logarithm is well conditioned.
    fn log(&self) -> Result<Col<f64>, LieError> {
        if !self.is_finite() {
            return Err(LieError::NonFinite {
                what: "SO(n) element",
            });
        }
        Ok(so_vee(log_rotation(self.m.as_ref())?.as_ref()))
    }
    fn hat(xi: &Col<f64>) -> Mat<f64> {
        so_hat(N, xi)
    }
    fn vee(m: &Mat<f64>) -> Col<f64> {
        so_vee(m.as_ref())
    }
    fn matrix(&self) -> Mat<f64> {
        self.m.clone()
    }
    /// Checked with [`SoN::TOLERANCE`]; see [`SoN::from_matrix_with_tolerance`].
    fn from_matrix(m: &Mat<f64>) -> Result<Self, LieError> {
        Self::from_matrix_with_tolerance(m, Self::TOLERANCE)
    }
    fn from_matrix_unchecked(m: &Mat<f64>) -> Self {
        Self { m: m.clone() }
    }
    /// `Ad_g`, the second compound matrix of g: entry `((i,j),(k,l)) = g_{ik} g_{jl} − g_{il} g_{jk}`
    /// (O(dim²) work, no column-by-column conjugation).
    fn adjoint(&self) -> Mat<f64> {
        so_compound(self.m.as_ref())
    }
    /// `ad_ξ`, filled entry by entry from `[ξ̂, E_{kl}]_{ji} = A_{jl}δ_{ki} − A_{jk}δ_{li} − δ_{jl}A_{ki}
    /// + δ_{jk}A_{li}` (A = ξ̂): column (k, l) has nonzeros only on pairs touching k or l, O(n³) total.
    fn ad(xi: &Col<f64>) -> Mat<f64> {
        let a = so_hat(N, xi);
        let d = Self::DIM;
        let mut out = Mat::zeros(d, d);
        let kd = |x: usize, y: usize| if x == y { 1.0 } else { 0.0 };
        let mut q = 0;
        for k in 0..N {
            for l in k + 1..N {
                for m in 0..N {
                    for &c in &[k, l] {
                        if m == c {
                            continue;
                        }
                        let (i, j) = if m < c { (m, c) } else { (c, m) };
                        out[(pair(N, i, j), q)] =
                            a[(j, l)] * kd(k, i) - a[(j, k)] * kd(l, i) - kd(j, l) * a[(k, i)]
                                + kd(j, k) * a[(l, i)];
                    }
                }
                q += 1;
            }
        }
        out
    }
    /// `Ad_g ξ = (g ξ̂ gᵀ)ˇ`, O(n³).
    fn adjoint_apply(&self, xi: &Col<f64>) -> Col<f64> {
        let x = so_hat(N, xi);
        so_vee((&self.m * (&x * self.m.transpose())).as_ref())
    }
    /// `Ad*_g μ = (gᵀ μ̂ g)ˇ = Ad_{g⁻¹} μ` (Ad_g is orthogonal for the pairing ½ tr(μ̂ᵀ ξ̂)), O(n³).
    fn coadjoint_apply(&self, mu: &Col<f64>) -> Col<f64> {
        let x = so_hat(N, mu);
        so_vee((self.m.transpose() * (&x * &self.m)).as_ref())
    }
    /// `[ξ, η] = (ξ̂ η̂ − η̂ ξ̂)ˇ`, O(n³).
    fn bracket(xi: &Col<f64>, eta: &Col<f64>) -> Col<f64> {
        let (a, b) = (so_hat(N, xi), so_hat(N, eta));
        let ab = &a * &b;
        // (AB − BA) = AB − (AB)ᵀ for skew A, B: one product instead of two
        so_vee(Mat::from_fn(N, N, |i, j| ab[(i, j)] - ab[(j, i)]).as_ref())
    }
    /// `ad*_ξ μ = [μ, ξ]` (ad_ξ is skew for the pairing ½ tr(μ̂ᵀ ξ̂)), O(n³).
    fn ad_dual_apply(xi: &Col<f64>, mu: &Col<f64>) -> Col<f64> {
        Self::bracket(mu, xi)
    }
    fn is_finite(&self) -> bool {
        (0..N).all(|j| (0..N).all(|i| self.m[(i, j)].is_finite()))
    }
}

impl<const N: usize> CayleyGroup for SoN<N> {
    /// `cay(ξ) = (I − ξ̂/2)⁻¹ (I + ξ̂/2)` by one LU solve (I − ξ̂/2 is always invertible: ξ̂ has
    /// imaginary eigenvalues).
    fn cay(xi: &Col<f64>) -> Self {
        let p = Self::cayley_factor(xi);
        let q = p.transpose().to_owned();
        Self {
            m: q.partial_piv_lu().solve(&p),
        }
    }
    /// `cay⁻¹(g) = (2 (g − I)(g + I)⁻¹)ˇ` (generic matrix path); an error where g has eigenvalue −1.
    fn cay_inv(&self) -> Result<Col<f64>, LieError> {
        if !self.is_finite() {
            return Err(LieError::NonFinite {
                what: "SO(n) element",
            });
        }
        matrix_path::cay_inv(self)
    }
    /// `d^L cay_ξ (η) = ((I + ξ̂/2)⁻¹ η̂ (I − ξ̂/2)⁻¹)ˇ = (h η̂ hᵀ)ˇ` with `h = (I + ξ̂/2)⁻¹`: the
    /// second compound of h ([`so_compound`]).
    fn dcay_left(xi: &Col<f64>) -> Mat<f64> {
        let p = Self::cayley_factor(xi);
        let h = p.partial_piv_lu().inverse();
        so_compound(h.as_ref())
    }
    /// `d^{L*}cay_ξ μ = (hᵀ μ̂ h)ˇ`, h = (I + ξ̂/2)⁻¹: the transpose of [`CayleyGroup::dcay_left`]
    /// under the coordinate pairing (for skew M, `⟨μ̂, M⟩_F = 2 μ·M̌`, so
    /// `μ·(h η̂ hᵀ)ˇ = ½⟨hᵀ μ̂ h, η̂⟩_F = (hᵀ μ̂ h)ˇ·η`). O(n³), where forming the dim 𝔤 × dim 𝔤
    /// operator costs O(n⁴) memory and its transpose-apply O(n⁴) time.
    fn dcay_left_dual_apply(xi: &Col<f64>, mu: &Col<f64>) -> Col<f64> {
        let h = Self::cayley_factor(xi).partial_piv_lu().inverse();
        let m = so_hat(N, mu);
        let mh = &m * &h;
        so_vee((h.transpose() * &mh).as_ref())
    }
    /// `(d^L cay_ξ)⁻¹ (η) = (η̂ + [ξ̂, η̂]/2 − ξ̂ η̂ ξ̂/4)ˇ = ((I + ξ̂/2) η̂ (I − ξ̂/2))ˇ`: the second
    /// compound of `I + ξ̂/2`.
    fn dcay_left_inv(xi: &Col<f64>) -> Mat<f64> {
        so_compound(Self::cayley_factor(xi).as_ref())
    }
}

/// Rotation of points of ℝᴺ: `g · p = R p`.
impl<const N: usize> Action<Col<f64>> for SoN<N> {
    type PointJacobian = Mat<f64>;
    type GroupJacobian = Mat<f64>;
    fn act(&self, p: &Col<f64>) -> Col<f64> {
        &self.m * p
    }
    /// `R`.
    fn act_jacobian_point(&self, _p: &Col<f64>) -> Mat<f64> {
        self.m.clone()
    }
    /// Column k: `R Ê_k p` (Ê_k the k-th basis generator).
    fn act_jacobian_left(&self, p: &Col<f64>) -> Mat<f64> {
        generator_columns(Self::DIM, |k| {
            &self.m * (so_hat(N, &unit(Self::DIM, k)) * p)
        })
    }
    /// Column k: `Ê_k (R p)`.
    fn act_jacobian_right(&self, p: &Col<f64>) -> Mat<f64> {
        let q = &self.m * p;
        generator_columns(Self::DIM, |k| so_hat(N, &unit(Self::DIM, k)) * &q)
    }
}

/// The unit vector e_k of ℝᵈ.
pub(crate) fn unit(d: usize, k: usize) -> Col<f64> {
    Col::from_fn(d, |i| if i == k { 1.0 } else { 0.0 })
}

/// The matrix whose k-th column (k < d) is `col(k)`.
pub(crate) fn generator_columns(d: usize, col: impl Fn(usize) -> Col<f64>) -> Mat<f64> {
    let cols: Vec<Col<f64>> = (0..d).map(col).collect();
    let rows = cols.first().map_or(0, |c| c.nrows());
    Mat::from_fn(rows, d, |i, k| cols[k][i])
}
