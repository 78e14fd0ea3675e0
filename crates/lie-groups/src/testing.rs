//! The generic test suite that every group, τ map and bundle of the workspace must pass
//! (behind the `testing` feature). A new group is one line:
//!
//! ```ignore
//! lie_groups::lie_group_suite!(so3, lie_groups::So3, 2.5);
//! lie_groups::tau_suite!(so3_cayley, lie_groups::So3, lie_groups::Cayley, 2.5);
//! lie_groups::cayley_group_suite!(so3_cayley_closed_forms, lie_groups::So3, 2.5);
//! ```
//!
//! Each check takes algebra elements (random ones come from proptest through [`algebra`]) and
//! panics with a message that names the property and the size of the violation. Every reference
//! used here is computed independently of the code under test: matrix exponentials by a Taylor
//! series with scaling and squaring, tangent maps by central finite differences, Ad and ad on the
//! matrix representation.

use crate::matrix::dense::max_abs_diff;
use crate::{matrix_path, CayleyGroup, DenseMatrix, LieGroup, Operator, Tau, Vector};
use faer::{Mat, MatRef};
pub use proptest;

mod allocations;
pub use allocations::{allocations, CountingAllocator};
use proptest::prelude::*;

/// A proptest strategy for algebra elements with components uniform in [−scale, scale].
pub fn algebra<G: LieGroup>(scale: f64) -> impl Strategy<Value = G::Algebra> {
    proptest::collection::vec(-scale..scale, G::dim())
        .prop_map(|v| G::Algebra::from_fn(v.len(), |i| v[i]))
}

/// e^A by a Taylor series on A/2ˢ (‖A/2ˢ‖₁ ≤ 1/2, 40 terms) and s squarings: a reference
/// independent of the Padé approximant in [`crate::matrix::dense::expm`].
pub fn expm_taylor(a: MatRef<'_, f64>) -> Mat<f64> {
    let n = a.nrows();
    let norm = crate::matrix::dense::norm1(a);
    let s = if norm > 0.5 {
        (norm / 0.5).log2().ceil() as i32
    } else {
        0
    };
    let scale = 0.5f64.powi(s);
    let x = Mat::from_fn(n, n, |i, j| scale * a[(i, j)]);
    let mut term = Mat::<f64>::identity(n, n);
    let mut sum = term.clone();
    for k in 1..40 {
        term = Mat::from_fn(n, n, |i, j| {
            (0..n).map(|l| term[(i, l)] * x[(l, j)]).sum::<f64>() / k as f64
        });
        sum = &sum + &term;
    }
    for _ in 0..s {
        sum = &sum * &sum;
    }
    sum
}

fn op_diff<G: LieGroup>(a: &G::Operator, b: &G::Operator) -> f64 {
    max_abs_diff(a.to_mat().as_ref(), b.to_mat().as_ref())
}

fn vec_diff<V: Vector>(a: &V, b: &V) -> f64 {
    a.sub(b).norm_max()
}

fn scale_of<G: LieGroup>(g: &G) -> f64 {
    1.0 + g.matrix().to_mat().as_ref().norm_max()
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
    let prod = &g.matrix().to_mat() * &h.matrix().to_mat();
    assert_small(
        "matrix(gh) = matrix(g) matrix(h)",
        max_abs_diff(g.compose(&h).matrix().to_mat().as_ref(), prod.as_ref()),
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
    let reference = expm_taylor(G::hat(a).to_mat().as_ref());
    assert_small(
        "exp ξ = Taylor series of e^{ξ̂}",
        max_abs_diff(g.matrix().to_mat().as_ref(), reference.as_ref()),
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
    let exp_ad = crate::matrix::dense::expm(G::ad(a).to_mat().as_ref());
    assert_small(
        "Ad_{exp ξ} = exp(ad_ξ)",
        max_abs_diff(adg.to_mat().as_ref(), exp_ad.as_ref()),
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
/// algebra components drawn uniformly from [−scale, scale].
#[macro_export]
macro_rules! lie_group_suite {
    ($name:ident, $G:ty, $scale:expr) => {
        mod $name {
            #[allow(unused_imports)]
            use super::*;
            use $crate::testing::proptest::prelude::*;
            use $crate::testing::{algebra, check_adjoint, check_dexp, check_exp_log, check_group_axioms};
            type G = $G;
            $crate::testing::proptest::proptest! {
                #![proptest_config(ProptestConfig::with_cases(48))]
                #[test]
                fn group_axioms_hold(a in algebra::<G>($scale), b in algebra::<G>($scale), c in algebra::<G>($scale)) {
                    check_group_axioms::<G>(&a, &b, &c);
                }
                #[test]
                fn exp_log_round_trip_and_match_matrix_series(a in algebra::<G>($scale)) {
                    check_exp_log::<G>(&a);
                }
                #[test]
                fn adjoint_is_homomorphism_dual_and_jacobi_holds(a in algebra::<G>($scale), b in algebra::<G>($scale), c in algebra::<G>($scale)) {
                    check_adjoint::<G>(&a, &b, &c);
                }
                #[test]
                fn dexp_matches_finite_differences_and_inverts(a in algebra::<G>($scale)) {
                    check_dexp::<G>(&a);
                }
            }
        }
    };
}

/// Instantiates the τ-map checks: `tau_suite!(module, Group, TauType, scale)`.
#[macro_export]
macro_rules! tau_suite {
    ($name:ident, $G:ty, $T:ty, $scale:expr) => {
        mod $name {
            #[allow(unused_imports)]
            use super::*;
            use $crate::testing::proptest::prelude::*;
            use $crate::testing::{algebra, check_invertible_radius, check_tau};
            $crate::testing::proptest::proptest! {
                #![proptest_config(ProptestConfig::with_cases(48))]
                #[test]
                fn tau_inverts_and_tangents_match_finite_differences(a in algebra::<$G>($scale), mu in algebra::<$G>(1.0)) {
                    check_tau::<$G, $T>(&a, &mu);
                }
                #[test]
                fn tau_round_trips_inside_its_invertible_radius(dir in algebra::<$G>(1.0), u in 0.0..=1.0f64) {
                    check_invertible_radius::<$G, $T>(&dir, u);
                }
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
            use $crate::testing::proptest::prelude::*;
            use $crate::testing::{algebra, check_cayley_closed_forms};
            $crate::testing::proptest::proptest! {
                #![proptest_config(ProptestConfig::with_cases(48))]
                #[test]
                fn closed_forms_match_generic_matrix_path(a in algebra::<$G>($scale)) {
                    check_cayley_closed_forms::<$G>(&a);
                }
            }
        }
    };
}
