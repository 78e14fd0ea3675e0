//! The generic matrix-group path: exp, log, cay, cay⁻¹ and the left-trivialized tangents evaluated
//! on the matrix representation with dense linear algebra (nalgebra's [`DMatrix`],
//! [`crate::linalg`]), for any [`LieGroup`].
//!
//! SO(n) and GL(n) use these as their implementation; for SO(3), SE(3) and SE(2) they are the
//! independent reference the closed forms are tested against. None of these are hot paths.

use crate::linalg::{expm, logm, try_inverse, try_solve};
use crate::{DenseMatrix, DomainReason, LieError, LieGroup, Operator, Vector};
use nalgebra::{DMatrix, DMatrixView};

fn hat_mat<G: LieGroup>(xi: &G::Algebra) -> DMatrix<f64> {
    G::hat(xi).to_dmatrix()
}

fn vee_mat<G: LieGroup>(m: &DMatrix<f64>) -> G::Algebra {
    G::vee(&G::Matrix::from_dmatrix(m.as_view()).expect("matrix of the group's size"))
}

fn from_mat<G: LieGroup>(m: &DMatrix<f64>) -> G {
    G::from_matrix_unchecked(
        &G::Matrix::from_dmatrix(m.as_view()).expect("matrix of the group's size"),
    )
}

/// Builds the n×n operator whose j-th column is `f(eⱼ)`.
pub fn operator_from_columns<G: LieGroup>(
    mut f: impl FnMut(&G::Algebra) -> G::Algebra,
) -> G::Operator {
    let n = G::dim();
    operator_from_column_fn::<G>(|j| f(&G::Algebra::basis(n, j)))
}

/// Builds the n×n operator (n = dim 𝔤) whose j-th column is `col(j)`, through a stack buffer for
/// n ≤ 8 (no heap allocation for the fixed-size groups: this sits in integrators' Newton
/// iterations) and a heap matrix above.
pub fn operator_from_column_fn<G: LieGroup>(col: impl FnMut(usize) -> G::Algebra) -> G::Operator {
    /// Fills an `M`-entry buffer column-major; `M` ≥ n² (zeroing a larger buffer than needed costs as
    /// much as filling it, hence two sizes).
    fn buffered<G: LieGroup, const M: usize>(
        n: usize,
        mut col: impl FnMut(usize) -> G::Algebra,
    ) -> G::Operator {
        let mut buf = [0.0f64; M];
        for j in 0..n {
            let c = col(j);
            for i in 0..n {
                buf[j * n + i] = c.get(i);
            }
        }
        let view = DMatrixView::from_slice(&buf[..n * n], n, n);
        G::Operator::from_dmatrix(view).expect("an n×n operator of the group")
    }
    let n = G::dim();
    match n {
        0..=3 => buffered::<G, 9>(n, col),
        4..=8 => buffered::<G, 64>(n, col),
        _ => {
            let cols: Vec<G::Algebra> = (0..n).map(col).collect();
            let m = DMatrix::from_fn(n, n, |i, j| cols[j].get(i));
            G::Operator::from_dmatrix(m.as_view()).expect("an n×n operator of the group")
        }
    }
}

/// exp(ξ) = e^{ξ̂} by Padé scaling and squaring ([`crate::linalg::expm`]).
pub fn exp<G: LieGroup>(xi: &G::Algebra) -> G {
    from_mat::<G>(&expm(hat_mat::<G>(xi).as_view()))
}

/// log(g) = (log_m g)ˇ, the principal matrix logarithm by inverse scaling and squaring.
pub fn log<G: LieGroup>(g: &G) -> Result<G::Algebra, LieError> {
    let l = logm(g.matrix().to_dmatrix().as_view())?;
    Ok(vee_mat::<G>(&l))
}

/// cay(ξ) = (I − ξ̂/2)⁻¹ (I + ξ̂/2); a matrix of NaN where I − ξ̂/2 is singular.
pub fn cay<G: LieGroup>(xi: &G::Algebra) -> G {
    let a = hat_mat::<G>(xi);
    let m = a.nrows();
    let id = DMatrix::<f64>::identity(m, m);
    let minus = &id - &a * 0.5;
    let plus = &id + &a * 0.5;
    match try_solve(minus.as_view(), plus.as_view()) {
        Some(x) => from_mat::<G>(&x),
        None => from_mat::<G>(&DMatrix::from_element(m, m, f64::NAN)),
    }
}

/// cay⁻¹(g) = (2 (g − I)(g + I)⁻¹)ˇ; an error where g + I is singular (a rotation by π).
pub fn cay_inv<G: LieGroup>(g: &G) -> Result<G::Algebra, LieError> {
    let gm = g.matrix().to_dmatrix();
    let m = gm.nrows();
    let id = DMatrix::<f64>::identity(m, m);
    let inv = try_inverse((&gm + &id).as_view())
        .ok_or(LieError::OutOfDomain(DomainReason::EigenvalueMinusOne))?;
    Ok(vee_mat::<G>(&((&gm - &id) * inv * 2.0)))
}

/// `d^L cay_ξ (η) = ((I + ξ̂/2)⁻¹ η̂ (I − ξ̂/2)⁻¹)ˇ`.
pub fn dcay_left<G: LieGroup>(xi: &G::Algebra) -> G::Operator {
    let a = hat_mat::<G>(xi);
    let m = a.nrows();
    let id = DMatrix::<f64>::identity(m, m);
    let plus = &id + &a * 0.5;
    let minus = &id - &a * 0.5;
    let (Some(pi), Some(mi)) = (try_inverse(plus.as_view()), try_inverse(minus.as_view())) else {
        return crate::group::nan_operator::<G>();
    };
    operator_from_columns::<G>(|e| vee_mat::<G>(&(&pi * hat_mat::<G>(e) * &mi)))
}

/// `(d^L cay_ξ)⁻¹ (η) = (η̂ + [ξ̂, η̂]/2 − ξ̂ η̂ ξ̂/4)ˇ`.
pub fn dcay_left_inv<G: LieGroup>(xi: &G::Algebra) -> G::Operator {
    let a = hat_mat::<G>(xi);
    operator_from_columns::<G>(|e| {
        let b = hat_mat::<G>(e);
        let ab = &a * &b;
        let ba = &b * &a;
        let aba = &ab * &a;
        vee_mat::<G>(&(&b + (ab - ba) * 0.5 - aba * 0.25))
    })
}

/// `d^L exp_ξ (η) = (e^{−ξ̂} · (d/ds) e^{ξ̂ + s η̂})ˇ`, the derivative taken exactly as the top-right
/// block of `exp([[ξ̂, η̂], [0, ξ̂]])` (Van Loan). Independent of the ad-series form.
pub fn dexp_left<G: LieGroup>(xi: &G::Algebra) -> G::Operator {
    let a = hat_mat::<G>(xi);
    let m = a.nrows();
    let e_neg = expm((-&a).as_view());
    operator_from_columns::<G>(|e| {
        let b = hat_mat::<G>(e);
        let block = DMatrix::from_fn(2 * m, 2 * m, |i, j| match (i < m, j < m) {
            (true, true) => a[(i, j)],
            (true, false) => b[(i, j - m)],
            (false, false) => a[(i - m, j - m)],
            (false, true) => 0.0,
        });
        let big = expm(block.as_view());
        vee_mat::<G>(&(&e_neg * big.view((0, m), (m, m))))
    })
}

/// `(d^L exp_ξ)⁻¹` by inverting [`dexp_left`]; non-finite where it is singular.
pub fn dexp_left_inv<G: LieGroup>(xi: &G::Algebra) -> G::Operator {
    dexp_left::<G>(xi)
        .try_inverse()
        .unwrap_or_else(|| crate::group::nan_operator::<G>())
}

/// Ad_g as the operator ξ ↦ (g ξ̂ g⁻¹)ˇ.
pub fn adjoint<G: LieGroup>(g: &G) -> G::Operator {
    let gm = g.matrix().to_dmatrix();
    let gi = g.inverse().matrix().to_dmatrix();
    operator_from_columns::<G>(|e| vee_mat::<G>(&(&gm * hat_mat::<G>(e) * &gi)))
}

/// ad_ξ as the operator η ↦ (ξ̂ η̂ − η̂ ξ̂)ˇ.
pub fn ad<G: LieGroup>(xi: &G::Algebra) -> G::Operator {
    let a = hat_mat::<G>(xi);
    operator_from_columns::<G>(|e| {
        let b = hat_mat::<G>(e);
        vee_mat::<G>(&(&a * &b - &b * &a))
    })
}
