//! The generic test suite that every group, τ map and bundle of the workspace must pass
//! (behind the `testing` feature). A new group is one line:
//!
//! ```ignore
//! lie_groups::lie_group_suite!(so3, lie_groups::So3, 2.5);
//! lie_groups::tau_suite!(so3_cayley, lie_groups::So3, lie_groups::Cayley, 2.5);
//! lie_groups::cayley_group_suite!(so3_cayley_closed_forms, lie_groups::So3, 2.5);
//! lie_groups::action_suite!(so3_action, lie_groups::So3, nalgebra::Vector3<f64>, 3, 2.5);
//! ```
//!
//! Each check takes algebra elements (random ones come from proptest through [`algebra`]) and
//! panics with a message that names the property and the size of the violation. Every reference
//! used here is computed independently of the code under test: matrix exponentials by a Taylor
//! series with scaling and squaring, tangent maps by central finite differences, Ad and ad on the
//! matrix representation.

use crate::linalg::max_abs_diff;
use crate::{matrix_path, CayleyGroup, DenseMatrix, LieGroup, Operator, Tau, Vector};
use nalgebra::{DMatrix, DMatrixView};
pub use proptest;

mod allocations;
mod cases;
pub use allocations::{allocations, CountingAllocator};
pub use cases::check_cases;
use proptest::prelude::*;

/// A proptest strategy for algebra elements with components uniform in [−scale, scale].
pub fn algebra<G: LieGroup>(scale: f64) -> impl Strategy<Value = G::Algebra> {
    proptest::collection::vec(-scale..scale, G::dim())
        .prop_map(|v| G::Algebra::from_fn(v.len(), |i| v[i]))
}

/// e^A by a Taylor series on A/2ˢ (‖A/2ˢ‖₁ ≤ 1/2, 40 terms) and s squarings: a reference
/// independent of the Padé approximant in [`crate::linalg::expm`].
pub fn expm_taylor(a: DMatrixView<'_, f64>) -> DMatrix<f64> {
    let n = a.nrows();
    let norm = crate::linalg::norm1(a);
    let s = if norm > 0.5 {
        (norm / 0.5).log2().ceil() as i32
    } else {
        0
    };
    let x = a * 0.5f64.powi(s);
    let mut term = DMatrix::<f64>::identity(n, n);
    let mut sum = term.clone();
    for k in 1..40 {
        term = &term * &x / k as f64;
        sum += &term;
    }
    for _ in 0..s {
        sum = &sum * &sum;
    }
    sum
}

fn dm<M: DenseMatrix>(m: &M) -> DMatrix<f64> {
    m.to_dmatrix()
}

fn mat_diff<A: DenseMatrix, B: DenseMatrix>(a: &A, b: &B) -> f64 {
    max_abs_diff(dm(a).as_view(), dm(b).as_view())
}

fn op_diff<G: LieGroup>(a: &G::Operator, b: &G::Operator) -> f64 {
    mat_diff(a, b)
}

fn vec_diff<V: Vector>(a: &V, b: &V) -> f64 {
    a.sub(b).norm_max()
}

fn scale_of<G: LieGroup>(g: &G) -> f64 {
    1.0 + dm(&g.matrix()).amax()
}

/// Asserts `x ≤ tol`, naming the property.
#[track_caller]
pub fn assert_small(what: &str, x: f64, tol: f64) {
    assert!(
        x <= tol,
        "{what}: error {x:.3e} exceeds tolerance {tol:.1e}"
    );
}

/// Associativity, identity and inverse on g = exp(a), h = exp(b), k = exp(c).
pub fn check_group_axioms<G: LieGroup>(a: &G::Algebra, b: &G::Algebra, c: &G::Algebra) {
    let (g, h, k) = (G::exp(a), G::exp(b), G::exp(c));
    let s = scale_of(&g) * scale_of(&h) * scale_of(&k);
    let e = G::identity();
    assert_small(
        "associativity (gh)k = g(hk)",
        g.compose(&h)
            .compose(&k)
            .matrix_distance(&g.compose(&h.compose(&k))),
        1e-13 * s,
    );
    assert_small(
        "left identity e g = g",
        e.compose(&g).matrix_distance(&g),
        1e-14 * s,
    );
    assert_small(
        "right identity g e = g",
        g.compose(&e).matrix_distance(&g),
        1e-14 * s,
    );
    assert_small(
        "g g⁻¹ = e",
        g.compose(&g.inverse()).matrix_distance(&e),
        1e-13 * s,
    );
    assert_small(
        "g⁻¹ g = e",
        g.inverse().compose(&g).matrix_distance(&e),
        1e-13 * s,
    );
    // the product is the matrix product of the representation
    let prod = dm(&g.matrix()) * dm(&h.matrix());
    assert_small(
        "matrix(gh) = matrix(g) matrix(h)",
        max_abs_diff(dm(&g.compose(&h).matrix()).as_view(), prod.as_view()),
        1e-13 * s,
    );
}

/// exp/log round trips (for |a| inside the injectivity radius), hat/vee and matrix round trips,
/// and exp against the Taylor-series matrix exponential of hat(a).
pub fn check_exp_log<G: LieGroup>(a: &G::Algebra) {
    let g = G::exp(a);
    let s = scale_of(&g);
    let back = g.log().expect("log of exp(ξ) exists");
    assert_small(
        "log(exp ξ) = ξ",
        vec_diff(&back, a),
        1e-12 * (1.0 + a.norm()) * s,
    );
    assert_small(
        "exp(log g) = g",
        G::exp(&back).matrix_distance(&g),
        1e-12 * s,
    );
    let reference = expm_taylor(dm(&G::hat(a)).as_view());
    assert_small(
        "exp ξ = Taylor series of e^{ξ̂}",
        max_abs_diff(dm(&g.matrix()).as_view(), reference.as_view()),
        1e-12 * s,
    );
    assert_small(
        "vee(hat ξ) = ξ",
        vec_diff(&G::vee(&G::hat(a)), a),
        1e-15 * (1.0 + a.norm()),
    );
    let rebuilt = G::from_matrix(&g.matrix()).expect("matrix of a group element is accepted");
    assert_small(
        "from_matrix(matrix g) = g",
        rebuilt.matrix_distance(&g),
        1e-15 * s,
    );
    assert!(g.is_finite(), "exp ξ is finite");
}

/// Ad and ad: Ad_{gh} = Ad_g Ad_h, Ad_g ξ = (g ξ̂ g⁻¹)ˇ, Ad_{exp ξ} = e^{ad_ξ}, ad_ξ η = [ξ̂, η̂]ˇ,
/// antisymmetry and the Jacobi identity, and the duality of Ad* and ad* under the pairing.
pub fn check_adjoint<G: LieGroup>(a: &G::Algebra, b: &G::Algebra, c: &G::Algebra) {
    let (g, h) = (G::exp(a), G::exp(b));
    let s = scale_of(&g) * scale_of(&h);
    let s2 = s * s * (1.0 + c.norm());
    let adg = g.adjoint();
    assert_small(
        "Ad_{gh} = Ad_g Ad_h",
        op_diff::<G>(&g.compose(&h).adjoint(), &adg.compose(&h.adjoint())),
        1e-12 * s2,
    );
    assert_small(
        "Ad_g = matrix conjugation",
        op_diff::<G>(&adg, &matrix_path::adjoint(&g)),
        1e-12 * s2,
    );
    let exp_ad = expm_taylor(dm(&G::ad(a)).as_view());
    assert_small(
        "Ad_{exp ξ} = exp(ad_ξ)",
        max_abs_diff(dm(&adg).as_view(), exp_ad.as_view()),
        1e-11 * s2,
    );
    assert_small(
        "Ad_g ξ (apply) = Ad_g · ξ",
        vec_diff(&g.adjoint_apply(c), &adg.apply(c)),
        1e-13 * s2,
    );
    assert_small(
        "Ad_{g⁻¹} ξ (apply) = Ad_g⁻¹ · ξ",
        vec_diff(&g.adjoint_inverse_apply(c), &g.inverse().adjoint().apply(c)),
        1e-13 * s2,
    );
    assert_small(
        "ad_ξ = matrix commutator",
        op_diff::<G>(&G::ad(a), &matrix_path::ad::<G>(a)),
        1e-13 * s2,
    );
    let ab = G::bracket(a, b);
    assert_small(
        "[ξ, η] = −[η, ξ]",
        vec_diff(&ab, &G::bracket(b, a).neg()),
        1e-13 * s2,
    );
    let jacobi = G::bracket(a, &G::bracket(b, c))
        .add(&G::bracket(b, &G::bracket(c, a)))
        .add(&G::bracket(c, &ab));
    assert_small(
        "Jacobi identity",
        jacobi.norm_max(),
        1e-12 * s2 * (1.0 + a.norm() + b.norm()),
    );
    // duality: ⟨Ad*_g μ, ξ⟩ = ⟨μ, Ad_g ξ⟩ and ⟨ad*_ξ μ, η⟩ = ⟨μ, ad_ξ η⟩ with μ = c
    let lhs = g.coadjoint_apply(c).dot(b);
    let rhs = c.dot(&g.adjoint_apply(b));
    assert_small(
        "⟨Ad*_g μ, ξ⟩ = ⟨μ, Ad_g ξ⟩",
        (lhs - rhs).abs(),
        1e-12 * s2 * (1.0 + b.norm()),
    );
    let lhs = G::ad_dual_apply(a, c).dot(b);
    let rhs = c.dot(&G::bracket(a, b));
    assert_small(
        "⟨ad*_ξ μ, η⟩ = ⟨μ, ad_ξ η⟩",
        (lhs - rhs).abs(),
        1e-12 * s2 * (1.0 + b.norm()),
    );
    // M(μ) δ = ad*_δ μ
    assert_small(
        "ad_dual_operator(μ) δ = ad*_δ μ",
        vec_diff(&G::ad_dual_operator(c).apply(a), &G::ad_dual_apply(a, c)),
        1e-12 * s2 * (1.0 + a.norm()) * (1.0 + c.norm()),
    );
}

/// The left-trivialized tangent of η ↦ f(ξ + η) by central differences:
/// column j = (log(f(ξ)⁻¹ f(ξ + h eⱼ)) − log(f(ξ)⁻¹ f(ξ − h eⱼ))) / 2h.
pub fn fd_left<G: LieGroup>(f: impl Fn(&G::Algebra) -> G, xi: &G::Algebra) -> G::Operator {
    let h = 1e-5;
    let base_inv = f(xi).inverse();
    matrix_path::operator_from_columns::<G>(|e| {
        let plus = base_inv
            .compose(&f(&xi.axpy(h, e)))
            .log()
            .expect("log near e");
        let minus = base_inv
            .compose(&f(&xi.axpy(-h, e)))
            .log()
            .expect("log near e");
        plus.sub(&minus).scale(0.5 / h)
    })
}

/// The right-trivialized tangent by central differences: log(f(ξ ± h eⱼ) f(ξ)⁻¹).
pub fn fd_right<G: LieGroup>(f: impl Fn(&G::Algebra) -> G, xi: &G::Algebra) -> G::Operator {
    let h = 1e-5;
    let base_inv = f(xi).inverse();
    matrix_path::operator_from_columns::<G>(|e| {
        let plus = f(&xi.axpy(h, e))
            .compose(&base_inv)
            .log()
            .expect("log near e");
        let minus = f(&xi.axpy(-h, e))
            .compose(&base_inv)
            .log()
            .expect("log near e");
        plus.sub(&minus).scale(0.5 / h)
    })
}

fn check_inverse_pair<G: LieGroup>(what: &str, a: &G::Operator, a_inv: &G::Operator, tol: f64) {
    let id = G::Operator::identity(G::dim());
    assert_small(what, op_diff::<G>(&a.compose(a_inv), &id), tol);
    assert_small(what, op_diff::<G>(&a_inv.compose(a), &id), tol);
}

/// d^L exp against finite differences and the Van Loan block-exponential path, and times its
/// inverse.
pub fn check_dexp<G: LieGroup>(a: &G::Algebra) {
    let s = scale_of(&G::exp(a));
    let j = G::dexp_left(a);
    assert_small(
        "d^L exp_ξ = finite differences",
        op_diff::<G>(&j, &fd_left::<G>(|x| G::exp(x), a)),
        1e-7 * s * s,
    );
    assert_small(
        "d^L exp_ξ = Van Loan block exponential",
        op_diff::<G>(&j, &matrix_path::dexp_left::<G>(a)),
        1e-12 * s * s,
    );
    check_inverse_pair::<G>(
        "d^L exp_ξ (d^L exp_ξ)⁻¹ = I",
        &j,
        &G::dexp_left_inv(a),
        1e-11 * s * s,
    );
}

/// `τ⁻¹(τ(ξ)) = ξ` to `1e-8 (1 + ‖ξ‖_max)` (the integrators' domain criterion) at
/// `ξ = u r dir/‖dir‖`, r = [`Tau::INVERTIBLE_RADIUS`], and at the radius itself (u = 1): the
/// radius must be conservative, since integrators skip the round trip inside it.
pub fn check_invertible_radius<G: LieGroup, T: Tau<G>>(dir: &G::Algebra, u: f64) {
    let r = T::INVERTIBLE_RADIUS;
    let n = dir.norm();
    if r == 0.0 || n < 1e-3 {
        return;
    }
    for s in [u, 1.0] {
        let xi = dir.scale(s * r / n);
        let back = T::tau_inv(&T::tau(&xi))
            .unwrap_or_else(|e| panic!("τ⁻¹(τ(ξ)) fails inside the radius, ‖ξ‖ = {}: {e}", s * r));
        assert_small(
            "τ⁻¹(τ(ξ)) = ξ inside INVERTIBLE_RADIUS",
            vec_diff(&back, &xi),
            1e-8 * (1.0 + xi.norm_max()),
        );
    }
}

/// A τ map: τ(ξ)τ(−ξ) = e, τ⁻¹(τ(ξ)) = ξ, d^L τ and d^R τ against finite differences, their
/// inverses, and the duals as transposes.
pub fn check_tau<G: LieGroup, T: Tau<G>>(a: &G::Algebra, mu: &G::Algebra) {
    let t = T::tau(a);
    let s = scale_of(&t);
    assert_small(
        "τ(ξ) τ(−ξ) = e",
        t.compose(&T::tau(&a.neg())).matrix_distance(&G::identity()),
        1e-13 * s * s,
    );
    let back = T::tau_inv(&t).expect("τ⁻¹ of τ(ξ) exists");
    assert_small(
        "τ⁻¹(τ(ξ)) = ξ",
        vec_diff(&back, a),
        1e-12 * (1.0 + a.norm()) * s,
    );
    let dl = T::dtau_left(a);
    assert_small(
        "d^L τ_ξ = finite differences",
        op_diff::<G>(&dl, &fd_left::<G>(|x| T::tau(x), a)),
        1e-7 * s * s,
    );
    let dr = T::dtau_right(a);
    assert_small(
        "d^R τ_ξ = finite differences",
        op_diff::<G>(&dr, &fd_right::<G>(|x| T::tau(x), a)),
        1e-7 * s * s,
    );
    assert_small(
        "d^R τ_ξ = Ad_{τ(ξ)} d^L τ_ξ",
        op_diff::<G>(&dr, &t.adjoint().compose(&dl)),
        1e-12 * s * s,
    );
    check_inverse_pair::<G>(
        "d^L τ (d^L τ)⁻¹ = I",
        &dl,
        &T::dtau_left_inv(a),
        1e-11 * s * s,
    );
    check_inverse_pair::<G>(
        "d^R τ (d^R τ)⁻¹ = I",
        &dr,
        &T::dtau_right_inv(a),
        1e-11 * s * s,
    );
    assert_small(
        "d^{L*} τ_ξ μ = (d^L τ_ξ)ᵀ μ",
        vec_diff(&T::dtau_left_dual_apply(a, mu), &dl.apply_transpose(mu)),
        1e-13 * s * s * (1.0 + mu.norm()),
    );
    assert_small(
        "d^{R*} τ_ξ μ = (d^R τ_ξ)ᵀ μ",
        vec_diff(&T::dtau_right_dual_apply(a, mu), &dr.apply_transpose(mu)),
        1e-13 * s * s * (1.0 + mu.norm()),
    );
}

/// Step of the central differences of the Jacobian checks below.
const FD_STEP: f64 = 1e-5;

/// The left-trivialized Jacobian of a map F: G → G at g by central differences: column j =
/// `(log(F(g)⁻¹ F(g e^{h eⱼ})) − log(F(g)⁻¹ F(g e^{−h eⱼ}))) / 2h`.
pub fn fd_map_left<G: LieGroup>(f: impl Fn(&G) -> G, g: &G) -> G::Operator {
    let base_inv = f(g).inverse();
    matrix_path::operator_from_columns::<G>(|e| {
        let side = |s: f64| {
            base_inv
                .compose(&f(&g.compose(&G::exp(&e.scale(s * FD_STEP)))))
                .log()
                .expect("log near e")
        };
        side(1.0).sub(&side(-1.0)).scale(0.5 / FD_STEP)
    })
}

/// The right-trivialized Jacobian of F: G → G at g by central differences: column j =
/// `(log(F(e^{h eⱼ} g) F(g)⁻¹) − log(F(e^{−h eⱼ} g) F(g)⁻¹)) / 2h`.
pub fn fd_map_right<G: LieGroup>(f: impl Fn(&G) -> G, g: &G) -> G::Operator {
    let base_inv = f(g).inverse();
    matrix_path::operator_from_columns::<G>(|e| {
        let side = |s: f64| {
            f(&G::exp(&e.scale(s * FD_STEP)).compose(g))
                .compose(&base_inv)
                .log()
                .expect("log near e")
        };
        side(1.0).sub(&side(-1.0)).scale(0.5 / FD_STEP)
    })
}

/// The Jacobian of a map f: G → 𝔤 at g by central differences, perturbing g on the right
/// (`left = true`: g e^{±h eⱼ}, the left-trivialized Jacobian) or on the left (e^{±h eⱼ} g).
pub fn fd_to_algebra<G: LieGroup>(f: impl Fn(&G) -> G::Algebra, g: &G, left: bool) -> G::Operator {
    matrix_path::operator_from_columns::<G>(|e| {
        let side = |s: f64| {
            let d = G::exp(&e.scale(s * FD_STEP));
            f(&if left { g.compose(&d) } else { d.compose(g) })
        };
        side(1.0).sub(&side(-1.0)).scale(0.5 / FD_STEP)
    })
}

/// ⊕/⊖ on both sides, `between` and interpolation on g = exp(a), h = exp(b) with increment ξ = c
/// (all inside the domain of log, as for [`check_exp_log`]):
/// - `(g ⊕ ξ) ⊖ g = ξ` and `g ⊕ (h ⊖ g) = h`, and the same for the right-trivialized pair;
/// - `between(g, g) = e`, `g · between(g, h) = h`;
/// - the interpolation `γ(t) = g exp(t log(g⁻¹ h))` has `γ(0) = g`, `γ(1) = h`, and constant body
///   velocity: `log(γ(s)⁻¹ γ(t)) = (t − s) log(g⁻¹ h)`.
pub fn check_plus_minus_between_interpolate<G: LieGroup>(
    a: &G::Algebra,
    b: &G::Algebra,
    c: &G::Algebra,
) {
    let (g, h) = (G::exp(a), G::exp(b));
    let s = scale_of(&g) * scale_of(&h) * scale_of(&G::exp(c));
    let tol = 1e-11 * s * s * (1.0 + c.norm());
    let back = g.plus_left(c).minus_left(&g).expect("(g ⊕ ξ) ⊖ g exists");
    assert_small("(g ⊕ ξ) ⊖ g = ξ", vec_diff(&back, c), tol);
    let back = g
        .plus_right(c)
        .minus_right(&g)
        .expect("log((exp(ξ) g) g⁻¹) exists");
    assert_small("log((exp(ξ) g) g⁻¹) = ξ", vec_diff(&back, c), tol);
    let d = h.minus_left(&g).expect("h ⊖ g exists");
    assert_small(
        "g ⊕ (h ⊖ g) = h",
        g.plus_left(&d).matrix_distance(&h),
        1e-12 * s * s,
    );
    let d = h.minus_right(&g).expect("log(h g⁻¹) exists");
    assert_small(
        "exp(log(h g⁻¹)) g = h",
        g.plus_right(&d).matrix_distance(&h),
        1e-12 * s * s,
    );
    assert_small(
        "between(g, g) = e",
        g.between(&g).matrix_distance(&G::identity()),
        1e-13 * s * s,
    );
    assert_small(
        "g · between(g, h) = h",
        g.compose(&g.between(&h)).matrix_distance(&h),
        1e-12 * s * s,
    );
    let at = |t: f64| g.interpolate(&h, t).expect("log(g⁻¹ h) exists");
    assert_small(
        "interpolate(g, h, 0) = g",
        at(0.0).matrix_distance(&g),
        1e-13 * s * s,
    );
    assert_small(
        "interpolate(g, h, 1) = h",
        at(1.0).matrix_distance(&h),
        1e-12 * s * s,
    );
    let tau = h.minus_left(&g).expect("log(g⁻¹ h) exists");
    for (t0, t1) in [(0.0, 0.25), (0.25, 0.5), (0.5, 1.0), (0.3, 0.9)] {
        let step = at(t0)
            .between(&at(t1))
            .log()
            .expect("log along the curve exists");
        assert_small(
            "log(γ(s)⁻¹ γ(t)) = (t − s) log(g⁻¹ h) (constant speed)",
            vec_diff(&step, &tau.scale(t1 - t0)),
            1e-11 * s * s * (1.0 + tau.norm()),
        );
    }
}

/// Every Jacobian of the group against central finite differences, at g = exp(a), h = exp(b) and
/// increment ξ = c, in both trivializations: exp (`d^L exp`, `d^R exp` and their inverses), log,
/// compose, inverse, between, ⊕ and ⊖. The differences have truncation error O(h²) = O(1e-10)
/// times the third derivatives and rounding O(ε/h) = O(1e-11), hence the tolerance
/// 1e-7 (1 + ‖matrix‖)⁴.
pub fn check_jacobians<G: LieGroup>(a: &G::Algebra, b: &G::Algebra, c: &G::Algebra) {
    let (g, h) = (G::exp(a), G::exp(b));
    let s = scale_of(&g) * scale_of(&h) * scale_of(&G::exp(c));
    let tol = 1e-7 * s * s;
    // Every Jacobian is compared before the check fails, so that one run names all that are wrong.
    let failures = core::cell::RefCell::new(Vec::new());
    let check_to = |what: &str, ours: &G::Operator, want: &G::Operator, tol: f64| {
        let e = op_diff::<G>(ours, want);
        // a NaN error fails too
        if e.is_nan() || e > tol {
            failures
                .borrow_mut()
                .push(format!("{what}: error {e:.3e} exceeds tolerance {tol:.1e}"));
        }
    };
    let check = |what: &str, ours: &G::Operator, fd: &G::Operator| check_to(what, ours, fd, tol);
    // exp
    check(
        "d^L exp_ξ = finite differences (manif rjac)",
        &G::dexp_left(c),
        &fd_left::<G>(|x| G::exp(x), c),
    );
    check(
        "d^R exp_ξ = finite differences (manif ljac)",
        &G::dexp_right(c),
        &fd_right::<G>(|x| G::exp(x), c),
    );
    let id = G::Operator::identity(G::dim());
    check_to(
        "d^R exp_ξ (d^R exp_ξ)⁻¹ = I",
        &G::dexp_right(c).compose(&G::dexp_right_inv(c)),
        &id,
        1e-11 * s * s,
    );
    // log
    check(
        "log Jacobian (left) = finite differences",
        &g.log_jacobian_left().expect("log g exists"),
        &fd_to_algebra::<G>(|x| x.log().expect("log exists"), &g, true),
    );
    check(
        "log Jacobian (right) = finite differences",
        &g.log_jacobian_right().expect("log g exists"),
        &fd_to_algebra::<G>(|x| x.log().expect("log exists"), &g, false),
    );
    // compose
    let (jg, jh) = g.compose_jacobians_left(&h);
    check(
        "∂(gh)/∂g (left) = finite differences",
        &jg,
        &fd_map_left::<G>(|x| x.compose(&h), &g),
    );
    check(
        "∂(gh)/∂h (left) = finite differences",
        &jh,
        &fd_map_left::<G>(|x| g.compose(x), &h),
    );
    let (jg, jh) = g.compose_jacobians_right(&h);
    check(
        "∂(gh)/∂g (right) = finite differences",
        &jg,
        &fd_map_right::<G>(|x| x.compose(&h), &g),
    );
    check(
        "∂(gh)/∂h (right) = finite differences",
        &jh,
        &fd_map_right::<G>(|x| g.compose(x), &h),
    );
    // inverse
    check(
        "∂(g⁻¹)/∂g (left) = finite differences",
        &g.inverse_jacobian_left(),
        &fd_map_left::<G>(|x| x.inverse(), &g),
    );
    check(
        "∂(g⁻¹)/∂g (right) = finite differences",
        &g.inverse_jacobian_right(),
        &fd_map_right::<G>(|x| x.inverse(), &g),
    );
    // between
    let (jg, jh) = g.between_jacobians_left(&h);
    check(
        "∂(g⁻¹h)/∂g (left) = finite differences",
        &jg,
        &fd_map_left::<G>(|x| x.between(&h), &g),
    );
    check(
        "∂(g⁻¹h)/∂h (left) = finite differences",
        &jh,
        &fd_map_left::<G>(|x| g.between(x), &h),
    );
    let (jg, jh) = g.between_jacobians_right(&h);
    check(
        "∂(g⁻¹h)/∂g (right) = finite differences",
        &jg,
        &fd_map_right::<G>(|x| x.between(&h), &g),
    );
    check(
        "∂(g⁻¹h)/∂h (right) = finite differences",
        &jh,
        &fd_map_right::<G>(|x| g.between(x), &h),
    );
    // ⊕
    let (jg, jx) = g.plus_left_jacobians(c);
    check(
        "∂(g ⊕ ξ)/∂g (left) = finite differences",
        &jg,
        &fd_map_left::<G>(|x| x.plus_left(c), &g),
    );
    check(
        "∂(g ⊕ ξ)/∂ξ (left) = finite differences",
        &jx,
        &fd_left::<G>(|x| g.plus_left(x), c),
    );
    let (jg, jx) = g.plus_right_jacobians(c);
    check(
        "∂(exp(ξ) g)/∂g (left) = finite differences (manif lplus J_mout_m)",
        &jg,
        &fd_map_left::<G>(|x| x.plus_right(c), &g),
    );
    check(
        "∂(exp(ξ) g)/∂ξ (left) = finite differences (manif lplus J_mout_t)",
        &jx,
        &fd_left::<G>(|x| g.plus_right(x), c),
    );
    // ⊖
    let (jh, jg) = h.minus_left_jacobians(&g).expect("h ⊖ g exists");
    check(
        "∂(h ⊖ g)/∂h (left) = finite differences",
        &jh,
        &fd_to_algebra::<G>(|x| x.minus_left(&g).expect("⊖ exists"), &h, true),
    );
    check(
        "∂(h ⊖ g)/∂g (left) = finite differences",
        &jg,
        &fd_to_algebra::<G>(|x| h.minus_left(x).expect("⊖ exists"), &g, true),
    );
    let (jh, jg) = h.minus_right_jacobians(&g).expect("log(h g⁻¹) exists");
    check(
        "∂log(h g⁻¹)/∂h (left) = finite differences (manif lminus J_t_ma)",
        &jh,
        &fd_to_algebra::<G>(|x| x.minus_right(&g).expect("exists"), &h, true),
    );
    check(
        "∂log(h g⁻¹)/∂g (left) = finite differences (manif lminus J_t_mb)",
        &jg,
        &fd_to_algebra::<G>(|x| h.minus_right(x).expect("exists"), &g, true),
    );
    let failures = failures.into_inner();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The distances from the identity at which [`check_operations_near_zero`] evaluates: where the
/// closed forms switch to their Taylor branches (|ξ| ≲ 1e-3 for most) and far inside them.
pub const NEAR_ZERO: [f64; 3] = [1e-9, 1e-6, 1e-3];

/// [`check_plus_minus_between_interpolate`] and [`check_jacobians`] with a = r u, b = r v and
/// c = r w for the unit directions u, v, w of the given ones and every r in [`NEAR_ZERO`].
/// (Near rotation angle π the groups differ in which coordinates rotate; `tests/suite/so3.rs` and
/// `se3.rs` run the same checks there.)
pub fn check_operations_near_zero<G: LieGroup>(u: &G::Algebra, v: &G::Algebra, w: &G::Algebra) {
    let unit = |x: &G::Algebra| x.scale(1.0 / x.norm().max(f64::MIN_POSITIVE));
    let (u, v, w) = (unit(u), unit(v), unit(w));
    if u.norm() < 0.5 || v.norm() < 0.5 || w.norm() < 0.5 {
        return; // a zero direction: nothing to scale
    }
    for r in NEAR_ZERO {
        let (a, b, c) = (u.scale(r), v.scale(r), w.scale(r));
        check_plus_minus_between_interpolate::<G>(&a, &b, &c);
        check_jacobians::<G>(&a, &b, &c);
    }
}

/// The action's Jacobians against central finite differences at g = exp(a) and the point p:
/// `∂(g·p)/∂p`, the left- and right-trivialized `∂(g·p)/∂g`, and `J^R = J^L Ad_{g⁻¹}`.
pub fn check_action<G, P>(a: &G::Algebra, p: &P)
where
    G: LieGroup + crate::Action<P>,
    P: Vector,
{
    let g = G::exp(a);
    let s = scale_of(&g) * (1.0 + p.norm());
    let (m, n) = (p.dim(), G::dim());
    let fd = |cols: usize, f: &dyn Fn(usize, f64) -> P| {
        DMatrix::from_fn(m, cols, |i, j| {
            (f(j, FD_STEP).get(i) - f(j, -FD_STEP).get(i)) * (0.5 / FD_STEP)
        })
    };
    let e = |j: usize, h: f64| G::Algebra::basis(n, j).scale(h);
    let point = fd(m, &|j, h| g.act(&p.add(&P::basis(m, j).scale(h))));
    let left = fd(n, &|j, h| g.compose(&G::exp(&e(j, h))).act(p));
    let right = fd(n, &|j, h| G::exp(&e(j, h)).compose(&g).act(p));
    let tol = 1e-7 * s * s;
    let jl = dm(&g.act_jacobian_left(p));
    assert_small(
        "∂(g·p)/∂p = finite differences",
        max_abs_diff(dm(&g.act_jacobian_point(p)).as_view(), point.as_view()),
        tol,
    );
    assert_small(
        "∂(g·p)/∂g (left) = finite differences",
        max_abs_diff(jl.as_view(), left.as_view()),
        tol,
    );
    let jr = dm(&g.act_jacobian_right(p));
    assert_small(
        "∂(g·p)/∂g (right) = finite differences",
        max_abs_diff(jr.as_view(), right.as_view()),
        tol,
    );
    let via_ad = &jl * dm(&g.inverse().adjoint());
    assert_small(
        "J^R = J^L Ad_{g⁻¹}",
        max_abs_diff(jr.as_view(), via_ad.as_view()),
        1e-12 * s * s,
    );
}

/// The closed forms of a group agree with the generic matrix-group path: exp, log, cay, cay⁻¹,
/// d^L cay and its inverse.
pub fn check_cayley_closed_forms<G: CayleyGroup>(a: &G::Algebra) {
    let c = G::cay(a);
    let s = scale_of(&c);
    assert_small(
        "cay ξ = (I − ξ̂/2)⁻¹(I + ξ̂/2)",
        c.matrix_distance(&matrix_path::cay::<G>(a)),
        1e-13 * s,
    );
    let back = c.cay_inv().expect("cay⁻¹ of cay(ξ) exists");
    let generic = matrix_path::cay_inv(&c).expect("cay⁻¹ of cay(ξ) exists");
    assert_small(
        "cay⁻¹ = generic path",
        vec_diff(&back, &generic),
        1e-12 * s * (1.0 + a.norm()),
    );
    assert_small(
        "d^L cay = generic path",
        op_diff::<G>(&G::dcay_left(a), &matrix_path::dcay_left::<G>(a)),
        1e-13 * s * s,
    );
    assert_small(
        "(d^L cay)⁻¹ = generic path",
        op_diff::<G>(&G::dcay_left_inv(a), &matrix_path::dcay_left_inv::<G>(a)),
        1e-12 * s * s * (1.0 + a.norm() * a.norm()),
    );
    let g = G::exp(a);
    assert_small(
        "exp = generic path",
        g.matrix_distance(&matrix_path::exp::<G>(a)),
        1e-12 * s,
    );
    let l = g.log().expect("log exists");
    let lg = matrix_path::log(&g).expect("generic log exists");
    assert_small(
        "log = generic path",
        vec_diff(&l, &lg),
        1e-10 * s * (1.0 + a.norm()),
    );
}

/// Instantiates the group checks for one group: `lie_group_suite!(module, Type, scale)`, with
/// algebra components drawn uniformly from [−scale, scale]. Each test runs through
/// [`check_cases`], so that the tests of one group share two compiled runners (one for a single
/// algebra element, one for three).
#[macro_export]
macro_rules! lie_group_suite {
    ($name:ident, $G:ty, $scale:expr) => {
        mod $name {
            #[allow(unused_imports)]
            use super::*;
            use $crate::testing::{
                algebra, check_adjoint, check_cases, check_dexp, check_exp_log, check_group_axioms,
                check_jacobians, check_operations_near_zero, check_plus_minus_between_interpolate,
            };
            type G = $G;
            #[test]
            fn group_axioms_hold() {
                check_cases(
                    concat!(module_path!(), "::group_axioms_hold"),
                    file!(),
                    48,
                    &(
                        algebra::<G>($scale),
                        algebra::<G>($scale),
                        algebra::<G>($scale),
                    ),
                    &|(a, b, c)| check_group_axioms::<G>(&a, &b, &c),
                );
            }
            #[test]
            fn exp_log_round_trip_and_match_matrix_series() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::exp_log_round_trip_and_match_matrix_series"
                    ),
                    file!(),
                    48,
                    &algebra::<G>($scale),
                    &|a| check_exp_log::<G>(&a),
                );
            }
            #[test]
            fn adjoint_is_homomorphism_dual_and_jacobi_holds() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::adjoint_is_homomorphism_dual_and_jacobi_holds"
                    ),
                    file!(),
                    48,
                    &(
                        algebra::<G>($scale),
                        algebra::<G>($scale),
                        algebra::<G>($scale),
                    ),
                    &|(a, b, c)| check_adjoint::<G>(&a, &b, &c),
                );
            }
            #[test]
            fn dexp_matches_finite_differences_and_inverts() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::dexp_matches_finite_differences_and_inverts"
                    ),
                    file!(),
                    48,
                    &algebra::<G>($scale),
                    &|a| check_dexp::<G>(&a),
                );
            }
            #[test]
            fn plus_minus_invert_and_interpolation_has_constant_speed() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::plus_minus_invert_and_interpolation_has_constant_speed"
                    ),
                    file!(),
                    48,
                    &(
                        algebra::<G>($scale),
                        algebra::<G>($scale),
                        algebra::<G>($scale),
                    ),
                    &|(a, b, c)| check_plus_minus_between_interpolate::<G>(&a, &b, &c),
                );
            }
            #[test]
            fn jacobians_match_finite_differences() {
                check_cases(
                    concat!(module_path!(), "::jacobians_match_finite_differences"),
                    file!(),
                    48,
                    &(
                        algebra::<G>($scale),
                        algebra::<G>($scale),
                        algebra::<G>($scale),
                    ),
                    &|(a, b, c)| check_jacobians::<G>(&a, &b, &c),
                );
            }
            #[test]
            fn operations_and_jacobians_hold_near_zero() {
                check_cases(
                    concat!(module_path!(), "::operations_and_jacobians_hold_near_zero"),
                    file!(),
                    8,
                    &(algebra::<G>(1.0), algebra::<G>(1.0), algebra::<G>(1.0)),
                    &|(u, v, w)| check_operations_near_zero::<G>(&u, &v, &w),
                );
            }
        }
    };
}

/// Instantiates the action checks: `action_suite!(module, Group, Point, point_dim, scale)`.
#[macro_export]
macro_rules! action_suite {
    ($name:ident, $G:ty, $P:ty, $pdim:expr, $scale:expr) => {
        mod $name {
            #[allow(unused_imports)]
            use super::*;
            use $crate::testing::{algebra, check_action, check_cases};
            #[test]
            fn action_jacobians_match_finite_differences() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::action_jacobians_match_finite_differences"
                    ),
                    file!(),
                    48,
                    &(
                        algebra::<$G>($scale),
                        $crate::testing::proptest::collection::vec(-2.0..2.0f64, $pdim),
                    ),
                    &|(a, p)| {
                        let p = <$P as $crate::Vector>::from_fn($pdim, |i| p[i]);
                        check_action::<$G, $P>(&a, &p);
                    },
                );
            }
        }
    };
}

/// Instantiates the τ-map checks: `tau_suite!(module, Group, TauType, scale)`. The runners are
/// those of the group's other suites where the strategies agree (two algebra elements are not
/// three: one more runner per group, shared by every τ map on it).
#[macro_export]
macro_rules! tau_suite {
    ($name:ident, $G:ty, $T:ty, $scale:expr) => {
        mod $name {
            #[allow(unused_imports)]
            use super::*;
            use $crate::testing::{algebra, check_cases, check_invertible_radius, check_tau};
            #[test]
            fn tau_inverts_and_tangents_match_finite_differences() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::tau_inverts_and_tangents_match_finite_differences"
                    ),
                    file!(),
                    48,
                    &(algebra::<$G>($scale), algebra::<$G>(1.0)),
                    &|(a, mu)| check_tau::<$G, $T>(&a, &mu),
                );
            }
            #[test]
            fn tau_round_trips_inside_its_invertible_radius() {
                check_cases(
                    concat!(
                        module_path!(),
                        "::tau_round_trips_inside_its_invertible_radius"
                    ),
                    file!(),
                    48,
                    &(algebra::<$G>(1.0), 0.0..=1.0f64),
                    &|(dir, u)| check_invertible_radius::<$G, $T>(&dir, u),
                );
            }
        }
    };
}

/// Instantiates the closed-form-versus-generic-path checks for a [`CayleyGroup`].
#[macro_export]
macro_rules! cayley_group_suite {
    ($name:ident, $G:ty, $scale:expr) => {
        mod $name {
            #[allow(unused_imports)]
            use super::*;
            use $crate::testing::{algebra, check_cases, check_cayley_closed_forms};
            #[test]
            fn closed_forms_match_generic_matrix_path() {
                check_cases(
                    concat!(module_path!(), "::closed_forms_match_generic_matrix_path"),
                    file!(),
                    48,
                    &algebra::<$G>($scale),
                    &|a| check_cayley_closed_forms::<$G>(&a),
                );
            }
        }
    };
}
