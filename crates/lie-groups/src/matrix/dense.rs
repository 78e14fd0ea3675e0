//! The dense functions of [`crate::linalg`] on faer matrices, for the groups stored on faer
//! (SO(n), GL(n)) and the bundles built on faer operators: each copies the entries into a nalgebra
//! matrix, calls the one implementation in [`crate::linalg`], and copies the result back (none of
//! them is on a hot path of the fixed-size groups), with the conversions between the two types.

use crate::{linalg, LieError};
use faer::{Mat, MatRef};
use nalgebra::{DMatrix, DMatrixView};

/// The entries of a faer matrix as a nalgebra one.
pub fn to_dmatrix(a: MatRef<'_, f64>) -> DMatrix<f64> {
    DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| a[(i, j)])
}

/// The entries of a nalgebra matrix as a faer one.
pub fn from_dmatrix(a: DMatrixView<'_, f64>) -> Mat<f64> {
    Mat::from_fn(a.nrows(), a.ncols(), |i, j| a[(i, j)])
}

/// The principal logarithm ([`linalg::logm`]).
pub fn logm(a: MatRef<'_, f64>) -> Result<Mat<f64>, LieError> {
    let l = linalg::logm(to_dmatrix(a).as_view())?;
    Ok(from_dmatrix(l.as_view()))
}

/// `‖A‖₁`, the maximum absolute column sum; NaN if any entry is NaN ([`linalg::norm1`]).
pub fn norm1(a: MatRef<'_, f64>) -> f64 {
    linalg::norm1(to_dmatrix(a).as_view())
}

/// A⁻¹, or `None` when A is singular to working precision ([`linalg::try_inverse`]).
pub fn try_inverse(a: MatRef<'_, f64>) -> Option<Mat<f64>> {
    linalg::try_inverse(to_dmatrix(a).as_view()).map(|m| from_dmatrix(m.as_view()))
}

/// Solves `A X = B`, or `None` when A is singular to working precision ([`linalg::try_solve`]).
pub fn try_solve(a: MatRef<'_, f64>, b: MatRef<'_, f64>) -> Option<Mat<f64>> {
    linalg::try_solve(to_dmatrix(a).as_view(), to_dmatrix(b).as_view())
        .map(|m| from_dmatrix(m.as_view()))
}

/// e^A by scaling and squaring with a [13/13] Padé approximant ([`linalg::expm`]).
pub fn expm(a: MatRef<'_, f64>) -> Mat<f64> {
    from_dmatrix(linalg::expm(to_dmatrix(a).as_view()).as_view())
}

/// The largest absolute entry of `A − B` ([`linalg::max_abs_diff`]).
pub fn max_abs_diff(a: MatRef<'_, f64>, b: MatRef<'_, f64>) -> f64 {
    linalg::max_abs_diff(to_dmatrix(a).as_view(), to_dmatrix(b).as_view())
}
