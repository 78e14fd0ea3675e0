//! The crate page's name table, pinned: each method named there as manif's counterpart equals
//! manif's formula for it, written out from manif's sources (`LieGroupBase::rplus`, `lplus`,
//! `rminus`, `lminus`; `SO3Tangent::rjac`; `SO3::act`, `SE3::act`, `SE2::act`), not from our
//! derivations. The finite-difference checks of the generic suite (`testing::check_jacobians`)
//! prove the Jacobians correct; these prove that the names in the table point at the right ones.

use lie_groups::testing::proptest::prelude::*;
use lie_groups::testing::{algebra, assert_small};
use lie_groups::{Action, LieGroup, Operator, Se2, Se3, So2, So3, Vector};
use nalgebra::{Matrix2, Matrix3, SMatrix, Vector2, Vector3};

fn op_diff<G: LieGroup>(a: &G::Operator, b: &G::Operator) -> f64 {
    a.add(&b.scale(-1.0)).norm_max()
}

/// manif's generic ⊕/⊖ Jacobians (lie_group_base.h), with manif's `t.rjac()` = our `dexp_left`,
/// `t.rjacinv()` = `dexp_left_inv`, `m.adj()` = `adjoint`:
/// - `rplus`: `J_mout_t = rjac(t)`, `J_mout_m = J_mc_ma` of `compose(m, exp t)` = Ad_{exp(t)⁻¹};
/// - `lplus`: `J_mout_t = m⁻¹.adj() rjac(t)`, `J_mout_m = I`;
/// - `rminus`: `J_t_ma = rjacinv(t)`, `J_t_mb = −rjacinv(−t)`;
/// - `lminus`: `J = rjacinv(t) m.adj()`, `(J, −J)`.
fn check_plus_minus_are_manifs<G: LieGroup>(a: &G::Algebra, b: &G::Algebra, c: &G::Algebra) {
    let (g, h) = (G::exp(a), G::exp(b));
    let tol = 1e-12 * (1.0 + G::exp(a).adjoint().norm_max()).powi(2);
    let id = G::Operator::identity(G::dim());
    let (jm, jt) = g.plus_left_jacobians(c);
    assert_small(
        "rplus J_mout_m",
        op_diff::<G>(&jm, &G::exp(c).inverse().adjoint()),
        tol,
    );
    assert_small("rplus J_mout_t", op_diff::<G>(&jt, &G::dexp_left(c)), tol);
    let (jm, jt) = g.plus_right_jacobians(c);
    assert_small("lplus J_mout_m", op_diff::<G>(&jm, &id), tol);
    let want = g.inverse().adjoint().compose(&G::dexp_left(c));
    assert_small("lplus J_mout_t", op_diff::<G>(&jt, &want), tol);
    let t = h.minus_left(&g).unwrap();
    let (ja, jb) = h.minus_left_jacobians(&g).unwrap();
    assert_small(
        "rminus J_t_ma",
        op_diff::<G>(&ja, &G::dexp_left_inv(&t)),
        tol,
    );
    let want = G::dexp_left_inv(&t.neg()).scale(-1.0);
    assert_small("rminus J_t_mb", op_diff::<G>(&jb, &want), tol);
    let t = h.minus_right(&g).unwrap();
    let (ja, jb) = h.minus_right_jacobians(&g).unwrap();
    let j = G::dexp_left_inv(&t).compose(&g.adjoint());
    assert_small("lminus J_t_ma", op_diff::<G>(&ja, &j), tol);
    assert_small("lminus J_t_mb", op_diff::<G>(&jb, &j.scale(-1.0)), tol);
}

/// manif's SO3Tangent::rjac: `J_r = I − (1 − cos θ)/θ² W + (θ − sin θ)/θ³ W²`, W = [θ]×.
fn manif_so3_rjac(w: &Vector3<f64>) -> Matrix3<f64> {
    let (wx, t) = (w.cross_matrix(), w.norm());
    Matrix3::identity() - wx * ((1.0 - t.cos()) / (t * t)) + wx * wx * ((t - t.sin()) / (t * t * t))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn plus_minus_jacobians_are_manifs_on_so3_and_se3(a in algebra::<Se3>(1.0), b in algebra::<Se3>(1.0), c in algebra::<Se3>(1.0)) {
        check_plus_minus_are_manifs::<Se3>(&a, &b, &c);
        let r = |x: &nalgebra::Vector6<f64>| x.fixed_rows::<3>(0).into_owned();
        check_plus_minus_are_manifs::<So3>(&r(&a), &r(&b), &r(&c));
    }

    #[test]
    fn plus_minus_jacobians_are_manifs_on_so2_and_se2(a in algebra::<Se2>(2.0), b in algebra::<Se2>(2.0), c in algebra::<Se2>(2.0)) {
        check_plus_minus_are_manifs::<Se2>(&a, &b, &c);
        let r = |x: &Vector3<f64>| nalgebra::Vector1::new(x[0]);
        check_plus_minus_are_manifs::<So2>(&r(&a), &r(&b), &r(&c));
    }

    /// `dexp_left` is manif's right Jacobian `rjac` (J_r) and `dexp_right` its `ljac` (J_l =
    /// J_r(−θ)), away from the Taylor branch (θ ≥ 1e-3, where manif's closed form is accurate).
    #[test]
    fn left_trivialized_dexp_is_manifs_right_jacobian(w in algebra::<So3>(1.8)) {
        prop_assume!(w.norm() > 1e-3);
        assert_small("dexp_left = manif rjac", (So3::dexp_left(&w) - manif_so3_rjac(&w)).amax(), 1e-12);
        assert_small("dexp_right = manif ljac", (So3::dexp_right(&w) - manif_so3_rjac(&-w)).amax(), 1e-12);
    }

    /// The action's Jacobians are manif's `act(v, J_vout_m, J_vout_v)`, reordered to our
    /// rotation-first algebra coordinates: SO(3) `J_vout_m = −R [v]×`; SE(3) `[R, −R [v]×]` in
    /// manif's (v, ω) order; SE(2) `[R, R [1]× v]` in (x, y, θ) order, [1]× v = (−v_y, v_x);
    /// `J_vout_v = R` for all three.
    #[test]
    fn action_jacobians_are_manifs(a in algebra::<Se3>(1.5), p in algebra::<Se3>(2.0)) {
        let v = Vector3::new(p[0], p[1], p[2]);
        let g = Se3::exp(&a);
        let r = g.rotation().matrix();
        let manif = SMatrix::<f64, 3, 6>::from_fn(|i, j| if j < 3 { (-r * v.cross_matrix())[(i, j)] } else { r[(i, j - 3)] });
        assert_small("SE(3) J_vout_m", (g.act_jacobian_left(&v) - manif).amax(), 1e-13);
        assert_small("SE(3) J_vout_v", (g.act_jacobian_point(&v) - r).amax(), 1e-15);
        let rot = g.rotation();
        assert_small("SO(3) J_vout_m", (rot.act_jacobian_left(&v) - (-r * v.cross_matrix())).amax(), 1e-13);
        let g2 = Se2::exp(&Vector3::new(a[0], a[3], a[4]));
        let v2 = Vector2::new(p[0], p[1]);
        let r2: Matrix2<f64> = g2.act_jacobian_point(&v2);
        let col = r2 * Vector2::new(-v2.y, v2.x);
        let manif2 = SMatrix::<f64, 2, 3>::from_fn(|i, j| if j == 0 { col[i] } else { r2[(i, j - 1)] });
        assert_small("SE(2) J_vout_m", (g2.act_jacobian_left(&v2) - manif2).amax(), 1e-13);
    }
}
