//! Dense linear algebra on faer matrices shared by every generic path: inverse with a singularity
//! check, the matrix exponential by scaling and squaring with a [13/13] Padé approximant, and the
//! φ₁ function that gives d^L exp.

use faer::{
    linalg::solvers::{DenseSolveCore, Solve},
    Mat, MatRef,
};

/// Reciprocal-condition threshold below which a matrix is treated as singular.
const SINGULAR_RCOND: f64 = 1e-14;

/// `‖A‖₁`, the maximum absolute column sum; NaN if any entry is NaN (`f64::max` alone would
/// silently drop NaN columns and make a singular matrix look well conditioned).
pub fn norm1(a: MatRef<'_, f64>) -> f64 {
    let mut best = 0.0f64;
    for j in 0..a.ncols() {
        let s = (0..a.nrows()).map(|i| a[(i, j)].abs()).sum::<f64>();
        if s.is_nan() {
            return f64::NAN;
        }
        best = best.max(s);
    }
    best
}

/// A⁻¹ by LU with partial pivoting, or `None` when A is singular to working precision
/// (estimated reciprocal condition `1 / (‖A‖₁ ‖A⁻¹‖₁)` below 1e-14, or non-finite entries).
pub fn try_inverse(a: MatRef<'_, f64>) -> Option<Mat<f64>> {
    let n = a.nrows();
    if n != a.ncols() {
        return None;
    }
    if n == 0 {
        return Some(Mat::zeros(0, 0));
    }
    let inv = a.partial_piv_lu().inverse();
    let finite = (0..n).all(|j| (0..n).all(|i| inv[(i, j)].is_finite()));
    let rcond = 1.0 / (norm1(a) * norm1(inv.as_ref()));
    (finite && rcond > SINGULAR_RCOND).then_some(inv)
}

/// Solves `A X = B`, or `None` when A is singular to working precision (same test as
/// [`try_inverse`]).
pub fn try_solve(a: MatRef<'_, f64>, b: MatRef<'_, f64>) -> Option<Mat<f64>> {
    let n = a.nrows();
    if n != a.ncols() || n != b.nrows() {
        return None;
    }
    let lu = a.partial_piv_lu();
    let inv = lu.inverse();
    let rcond = 1.0 / (norm1(a) * norm1(inv.as_ref()));
    let x = lu.solve(b);
    let finite = (0..x.ncols()).all(|j| (0..x.nrows()).all(|i| x[(i, j)].is_finite()));
    (finite && rcond > SINGULAR_RCOND).then_some(x)
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

fn lin(terms: &[(f64, &Mat<f64>)], n: usize) -> Mat<f64> {
    Mat::from_fn(n, n, |i, j| terms.iter().map(|(c, m)| c * m[(i, j)]).sum())
}

/// e^A by scaling and squaring: A/2ˢ with ‖A/2ˢ‖₁ ≤ θ₁₃, the [13/13] Padé approximant, then s
/// squarings. Non-finite input gives non-finite output (no panic).
pub fn expm(a: MatRef<'_, f64>) -> Mat<f64> {
    let n = a.nrows();
    let norm = norm1(a);
    if !norm.is_finite() {
        return Mat::from_fn(n, n, |_, _| f64::NAN);
    }
    let s = if norm > THETA13 {
        (norm / THETA13).log2().ceil() as i32
    } else {
        0
    };
    let scale = 0.5f64.powi(s);
    let a: Mat<f64> = Mat::from_fn(n, n, |i, j| scale * a[(i, j)]);
    let id = Mat::<f64>::identity(n, n);
    let a2 = &a * &a;
    let a4 = &a2 * &a2;
    let a6 = &a4 * &a2;
    let b = &PADE13;
    let u_inner = lin(&[(b[13], &a6), (b[11], &a4), (b[9], &a2)], n);
    let u_outer = lin(&[(b[7], &a6), (b[5], &a4), (b[3], &a2), (b[1], &id)], n);
    let u = &a * (&(&a6 * &u_inner) + &u_outer);
    let v_inner = lin(&[(b[12], &a6), (b[10], &a4), (b[8], &a2)], n);
    let v_outer = lin(&[(b[6], &a6), (b[4], &a4), (b[2], &a2), (b[0], &id)], n);
    let v = &(&a6 * &v_inner) + &v_outer;
    let p = &v + &u;
    let q = &v - &u;
    let mut r = q.partial_piv_lu().solve(&p);
    for _ in 0..s {
        r = &r * &r;
    }
    r
}

/// φ₁(−X) = (I − e^{−X}) X⁻¹ = Σ_k (−X)^k / (k+1)!, evaluated exactly as the top-right block of
/// `exp([[−X, I], [0, 0]])` (no division by X, so no 0/0 at X = 0). With X = ad_ξ this is d^L exp_ξ.
pub fn phi1_of_neg(x: MatRef<'_, f64>) -> Mat<f64> {
    let n = x.nrows();
    let block = Mat::from_fn(2 * n, 2 * n, |i, j| match (i < n, j < n) {
        (true, true) => -x[(i, j)],
        (true, false) if i == j - n => 1.0,
        _ => 0.0,
    });
    let e = expm(block.as_ref());
    Mat::from_fn(n, n, |i, j| e[(i, j + n)])
}

/// The largest absolute entry of `A − B`.
pub fn max_abs_diff(a: MatRef<'_, f64>, b: MatRef<'_, f64>) -> f64 {
    let mut best = 0.0f64;
    for j in 0..a.ncols() {
        for i in 0..a.nrows() {
            best = best.max((a[(i, j)] - b[(i, j)]).abs());
        }
    }
    best
}
