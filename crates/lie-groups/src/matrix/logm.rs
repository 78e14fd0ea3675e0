//! The principal matrix logarithm by inverse scaling and squaring (Higham, "Functions of Matrices",
//! §11.5): take square roots until A is near I, evaluate log(I + X) by Gauss–Legendre quadrature
//! of ∫₀¹ X (I + tX)⁻¹ dt (the [m/m] Padé approximant in partial fractions), then scale back by 2ᵏ.

use super::dense::{norm1, try_inverse};
use crate::{DomainReason, LieError};
use faer::{Mat, MatRef};

/// Number of Gauss–Legendre nodes: for ‖X‖₁ ≤ 0.25 the quadrature error is below 1e-19.
const NODES: usize = 8;
/// Square roots are taken until ‖A − I‖₁ ≤ this.
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
fn sqrtm(a: MatRef<'_, f64>) -> Result<Mat<f64>, LieError> {
    let n = a.nrows();
    let mut y = a.to_owned();
    let mut z = Mat::<f64>::identity(n, n);
    for _ in 0..100 {
        let yi = try_inverse(y.as_ref()).ok_or(singular())?;
        let zi = try_inverse(z.as_ref()).ok_or(singular())?;
        let y_next = Mat::from_fn(n, n, |i, j| 0.5 * (y[(i, j)] + zi[(i, j)]));
        let z_next = Mat::from_fn(n, n, |i, j| 0.5 * (z[(i, j)] + yi[(i, j)]));
        let change = super::dense::max_abs_diff(y_next.as_ref(), y.as_ref());
        let size = y_next.as_ref().norm_max().max(1.0);
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

/// The principal logarithm of a real matrix with no eigenvalue on the closed negative real axis;
/// an error otherwise (or for non-finite input).
pub fn logm(a: MatRef<'_, f64>) -> Result<Mat<f64>, LieError> {
    let n = a.nrows();
    if !(0..n).all(|j| (0..n).all(|i| a[(i, j)].is_finite())) {
        return Err(LieError::NonFinite { what: "matrix" });
    }
    let id = Mat::<f64>::identity(n, n);
    let mut y = a.to_owned();
    let mut k = 0;
    while norm1((&y - &id).as_ref()) > NEAR_IDENTITY {
        if k == MAX_SQRTS {
            return Err(singular());
        }
        y = sqrtm(y.as_ref())?;
        k += 1;
    }
    let x = &y - &id;
    let mut sum = Mat::<f64>::zeros(n, n);
    for (t, w) in gauss_legendre_01(NODES) {
        let m = Mat::from_fn(n, n, |i, j| id[(i, j)] + t * x[(i, j)]);
        let mi = try_inverse(m.as_ref()).ok_or(singular())?;
        let term = &x * &mi;
        sum = Mat::from_fn(n, n, |i, j| sum[(i, j)] + w * term[(i, j)]);
    }
    let scale = (1u64 << k) as f64;
    Ok(Mat::from_fn(n, n, |i, j| scale * sum[(i, j)]))
}
