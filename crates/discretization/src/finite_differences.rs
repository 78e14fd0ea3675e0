//! Five-point central differences: the provided tangents of a map's factors and the provided
//! Newton derivatives of the composed lift components, for maps that give nothing better.
//!
//! `f'(0) ≈ (f(−2s) − 8 f(−s) + 8 f(s) − f(2s)) / 12s` has truncation error `s⁴ |f⁽⁵⁾| / 30` and
//! rounding error about `1.5 ε |f| / s`; for functions that vary on the scale 1 (τ of a multiple of
//! ξ, and what is composed from them) the two balance near s = 10⁻³ at ≈ 3·10⁻¹³ relative. A
//! derivative of a function that itself carries such errors (the Newton derivatives of the
//! composed components, whose factor tangents come from here) is accurate to ≈ 10⁻⁹: enough for
//! Newton's matrix, whose error only slows the contraction by that factor.

use lie_groups::matrix_path::operator_from_column_fn;
use lie_groups::{DenseMatrix, LieGroup, Vector};

/// The step s of both differences (in the coordinates of ξ; the factors vary on the scale 1).
pub(crate) const STEP: f64 = 1e-3;

/// Five-point difference of a vector-valued function of one real variable at 0.
fn five_point<T>(f: impl Fn(f64) -> T, combine: impl Fn(T, T, T, T) -> T) -> T {
    combine(f(-2.0 * STEP), f(-STEP), f(STEP), f(2.0 * STEP))
}

/// `d^L f_ξ`: the operator `v ↦ f(ξ)⁻¹ (d/ds) f(ξ + s v)|_{s=0}` of a map f: 𝔤 → G, column by
/// column, differencing the matrix representation of f and reading the algebra element of
/// `f(ξ)⁻¹ ∂f` by `vee` (which drops the O(s⁴) part outside 𝔤).
pub(crate) fn left_tangent<G: LieGroup>(
    f: impl Fn(&G::Algebra) -> G,
    xi: &G::Algebra,
) -> G::Operator {
    let n = G::dim();
    let base_inv = f(xi).inverse().matrix().to_mat();
    operator_from_column_fn::<G>(|j| {
        let e = G::Algebra::basis(n, j);
        let d = five_point(
            |t| f(&xi.axpy(t, &e)).matrix().to_mat(),
            |m2, m1, p1, p2| {
                ((&m2 - &p2) + (&p1 - &m1) * faer::Scale(8.0)) * faer::Scale(1.0 / (12.0 * STEP))
            },
        );
        let body = &base_inv * &d;
        G::vee(&G::Matrix::from_mat(body.as_ref()).expect("a matrix of the group's size"))
    })
}

/// `∂f/∂x` of a map f: 𝔤 → 𝔤 (or 𝔤*), column by column.
pub(crate) fn jacobian<G: LieGroup>(
    f: impl Fn(&G::Algebra) -> G::Algebra,
    x: &G::Algebra,
) -> G::Operator {
    let n = G::dim();
    operator_from_column_fn::<G>(|j| {
        let e = G::Algebra::basis(n, j);
        five_point(
            |t| f(&x.axpy(t, &e)),
            |m2, m1, p1, p2| {
                m2.sub(&p2)
                    .axpy(8.0, &p1.sub(&m1))
                    .scale(1.0 / (12.0 * STEP))
            },
        )
    })
}
