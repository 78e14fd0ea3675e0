//! Dense linear algebra on nalgebra's dynamic matrices, shared by every generic path (the
//! provided [`crate::LieGroup::dexp_left`], the composite groups' operators, [`crate::matrix_path`],
//! and, through copies, SO(n) and GL(n)): inverse and solve with a singularity check, the matrix
//! exponential by scaling and squaring with a [13/13] Padé approximant, the φ₁ function that gives
//! d^L exp, and the principal logarithm by inverse scaling and squaring.
//!
//! None of these are hot paths for the fixed-size groups, whose closed forms they are tested
//! against.

use crate::{DomainReason, LieError};
use nalgebra::{DMatrix, DMatrixView};

/// Reciprocal-condition threshold below which a matrix is treated as singular.
const SINGULAR_RCOND: f64 = 1e-14;

/// `‖A‖₁`, the maximum absolute column sum; NaN if any entry is NaN (`f64::max` alone would
/// silently drop NaN columns and make a singular matrix look well conditioned).
pub fn norm1(a: DMatrixView<'_, f64>) -> f64 {
    let mut best = 0.0f64;
    for col in a.column_iter() {
        let s = col.iter().map(|x| x.abs()).sum::<f64>();
        if s.is_nan() {
            return f64::NAN;
        }
        best = best.max(s);
    }
    best
}

fn all_finite(a: &DMatrix<f64>) -> bool {
    a.iter().all(|x| x.is_finite())
}

/// A⁻¹ by LU with partial pivoting, or `None` when A is singular to working precision
/// (estimated reciprocal condition `1 / (‖A‖₁ ‖A⁻¹‖₁)` below 1e-14, or non-finite entries).
pub fn try_inverse(a: DMatrixView<'_, f64>) -> Option<DMatrix<f64>> {
    let n = a.nrows();
    if n != a.ncols() {
        return None;
    }
    if n == 0 {
        return Some(DMatrix::zeros(0, 0));
    }
    let inv = a.clone_owned().lu().try_inverse()?;
    let rcond = 1.0 / (norm1(a) * norm1(inv.as_view()));
    (all_finite(&inv) && rcond > SINGULAR_RCOND).then_some(inv)
}

/// Solves `A X = B`, or `None` when A is singular to working precision (same test as
/// [`try_inverse`]).
pub fn try_solve(a: DMatrixView<'_, f64>, b: DMatrixView<'_, f64>) -> Option<DMatrix<f64>> {
    let n = a.nrows();
    if n != a.ncols() || n != b.nrows() {
        return None;
    }
    let lu = a.clone_owned().lu();
    let inv = lu.try_inverse()?;
    let rcond = 1.0 / (norm1(a) * norm1(inv.as_view()));
    let x = lu.solve(&b.clone_owned())?;
    (all_finite(&x) && rcond > SINGULAR_RCOND).then_some(x)
}

/// Padé [13/13] coefficients b₀ … b₁₃ (Higham 2005, "The scaling and squaring method for the
/// matrix exponential revisited").
const PADE13: [f64; 14] = [
    64764752532480000.0,
    32382376266240000.0,
    7771770303897600.0,
    1187353796428800.0,
    129060195264000.0,
    10559470521600.0,
    670442572800.0,
    33522128640.0,
    1323241920.0,
    40840800.0,
    960960.0,
    16380.0,
    182.0,
    1.0,
];
/// θ₁₃: the largest ‖A‖₁ for which the [13/13] approximant is accurate to unit roundoff.
const THETA13: f64 = 5.371920351148152;

/// e^A by scaling and squaring: A/2ˢ with ‖A/2ˢ‖₁ ≤ θ₁₃, the [13/13] Padé approximant, then s
/// squarings. Non-finite input gives non-finite output (no panic).
pub fn expm(a: DMatrixView<'_, f64>) -> DMatrix<f64> {
    let n = a.nrows();
    let norm = norm1(a);
    if !norm.is_finite() {
        return DMatrix::from_element(n, n, f64::NAN);
    }
    let s = if norm > THETA13 {
        (norm / THETA13).log2().ceil() as i32
    } else {
        0
    };
    let a = a * 0.5f64.powi(s);
    let id = DMatrix::<f64>::identity(n, n);
    let a2 = &a * &a;
    let a4 = &a2 * &a2;
    let a6 = &a4 * &a2;
    let b = &PADE13;
    let u_inner = &a6 * b[13] + &a4 * b[11] + &a2 * b[9];
    let u_outer = &a6 * b[7] + &a4 * b[5] + &a2 * b[3] + &id * b[1];
    let u = &a * (&a6 * u_inner + u_outer);
    let v_inner = &a6 * b[12] + &a4 * b[10] + &a2 * b[8];
    let v_outer = &a6 * b[6] + &a4 * b[4] + &a2 * b[2] + &id * b[0];
    let v = &a6 * v_inner + v_outer;
    let p = &v + &u;
    let q = &v - &u;
    let Some(mut r) = q.lu().solve(&p) else {
        return DMatrix::from_element(n, n, f64::NAN);
    };
    for _ in 0..s {
        r = &r * &r;
    }
    r
}

/// φ₁(−X) = (I − e^{−X}) X⁻¹ = Σ_k (−X)^k / (k+1)!, evaluated exactly as the top-right block of
/// `exp([[−X, I], [0, 0]])` (no division by X, so no 0/0 at X = 0). With X = ad_ξ this is d^L exp_ξ.
pub fn phi1_of_neg(x: DMatrixView<'_, f64>) -> DMatrix<f64> {
    let n = x.nrows();
    let block = DMatrix::from_fn(2 * n, 2 * n, |i, j| match (i < n, j < n) {
        (true, true) => -x[(i, j)],
        (true, false) if i == j - n => 1.0,
        _ => 0.0,
    });
    expm(block.as_view()).view((0, n), (n, n)).clone_owned()
}

/// The largest absolute entry of `A − B`.
pub fn max_abs_diff(a: DMatrixView<'_, f64>, b: DMatrixView<'_, f64>) -> f64 {
    a.iter()
        .zip(b.iter())
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

/// The block-diagonal `diag(A, B)`.
pub fn block_diag(a: DMatrixView<'_, f64>, b: DMatrixView<'_, f64>) -> DMatrix<f64> {
    let (ra, ca) = a.shape();
    let mut out = DMatrix::zeros(ra + b.nrows(), ca + b.ncols());
    out.view_mut((0, 0), (ra, ca)).copy_from(&a);
    out.view_mut((ra, ca), b.shape()).copy_from(&b);
    out
}

/// Number of Gauss–Legendre nodes of [`logm`]: for ‖X‖₁ ≤ 0.25 the quadrature error is below
/// 1e-19.
const NODES: usize = 8;
/// [`logm`] takes square roots until ‖A − I‖₁ ≤ this.
const NEAR_IDENTITY: f64 = 0.25;
const MAX_SQRTS: usize = 60;

/// Gauss–Legendre nodes and weights on [0, 1], by Newton's method on P_m.
fn gauss_legendre_01(m: usize) -> Vec<(f64, f64)> {
    (0..m)
        .map(|i| {
            let mut x = (core::f64::consts::PI * (i as f64 + 0.75) / (m as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=m {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = m as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            let w = 2.0 / ((1.0 - x * x) * dp * dp);
            (0.5 * (x + 1.0), 0.5 * w)
        })
        .collect()
}

/// The principal square root by the scaled Denman–Beavers iteration.
fn sqrtm(a: DMatrix<f64>) -> Result<DMatrix<f64>, LieError> {
    let n = a.nrows();
    let mut y = a;
    let mut z = DMatrix::<f64>::identity(n, n);
    for _ in 0..100 {
        let yi = try_inverse(y.as_view()).ok_or(singular())?;
        let zi = try_inverse(z.as_view()).ok_or(singular())?;
        let y_next = (&y + zi) * 0.5;
        let z_next = (&z + yi) * 0.5;
        let change = max_abs_diff(y_next.as_view(), y.as_view());
        let size = y_next.amax().max(1.0);
        y = y_next;
        z = z_next;
        if change <= 1e-15 * size {
            return Ok(y);
        }
    }
    Err(LieError::OutOfDomain(DomainReason::SqrtNoConvergence))
}

fn singular() -> LieError {
    LieError::OutOfDomain(DomainReason::NegativeRealEigenvalue)
}

/// The principal logarithm of a real matrix with no eigenvalue on the closed negative real axis
/// (Higham, "Functions of Matrices", §11.5: take square roots until A is near I, evaluate
/// log(I + X) by Gauss–Legendre quadrature of ∫₀¹ X (I + tX)⁻¹ dt — the [m/m] Padé approximant in
/// partial fractions — then scale back by 2ᵏ); an error otherwise (or for non-finite input).
pub fn logm(a: DMatrixView<'_, f64>) -> Result<DMatrix<f64>, LieError> {
    let n = a.nrows();
    if !a.iter().all(|x| x.is_finite()) {
        return Err(LieError::NonFinite { what: "matrix" });
    }
    let id = DMatrix::<f64>::identity(n, n);
    let mut y = a.clone_owned();
    let mut k = 0;
    while norm1((&y - &id).as_view()) > NEAR_IDENTITY {
        if k == MAX_SQRTS {
            return Err(singular());
        }
        y = sqrtm(y)?;
        k += 1;
    }
    let x = &y - &id;
    let mut sum = DMatrix::<f64>::zeros(n, n);
    for (t, w) in gauss_legendre_01(NODES) {
        let mi = try_inverse((&id + &x * t).as_view()).ok_or(singular())?;
        sum += (&x * mi) * w;
    }
    Ok(sum * (1u64 << k) as f64)
}
