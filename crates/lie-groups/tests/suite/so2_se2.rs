//! SO(2) and SE(2): the generic suite, the Cayley closed forms against the generic matrix path, and
//! the extremes (ω → 0 series, the half turn, refused matrices, nalgebra conversions).

use approx::assert_relative_eq;
use core::f64::consts::PI;
use lie_groups::testing::{check_dexp, check_exp_log, check_tau};
use lie_groups::{
    matrix_path, Action, Cayley, CayleyGroup, ExpMap, LieError, LieGroup, Operator, Se2, So2,
};
use nalgebra::{Isometry2, Matrix2, Matrix3, UnitComplex, Vector1, Vector2, Vector3};

lie_groups::lie_group_suite!(so2, lie_groups::So2, 3.0);
lie_groups::lie_group_suite!(se2, lie_groups::Se2, 3.0);
lie_groups::tau_suite!(so2_exp, lie_groups::So2, lie_groups::ExpMap, 3.0);
lie_groups::tau_suite!(so2_cayley, lie_groups::So2, lie_groups::Cayley, 3.0);
lie_groups::tau_suite!(se2_exp, lie_groups::Se2, lie_groups::ExpMap, 3.0);
lie_groups::tau_suite!(se2_cayley, lie_groups::Se2, lie_groups::Cayley, 3.0);
lie_groups::cayley_group_suite!(so2_cayley_closed_forms, lie_groups::So2, 3.0);
lie_groups::cayley_group_suite!(se2_cayley_closed_forms, lie_groups::Se2, 3.0);

fn max_diff3(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).abs().max()
}

/// At ω = 1e-8 (and exactly 0) the Taylor branches of exp, log, d^L exp and its inverse must agree
/// with the exact block-exponential reference to full double precision (1e-15 absolute on O(1)
/// entries; the reference itself is accurate to a few ulps there). On both sides of the branch
/// switch at |ω| = 0.1 the direct forms lose up to ~ε/ω ≈ 2e-15 (cancellation in 1 − α), hence
/// the 1e-14 bound there.
#[test]
fn se2_series_branches_are_full_precision_near_zero_rotation() {
    for (w, tol) in [
        (1e-8, 1e-15),
        (-1e-8, 1e-15),
        (0.0, 1e-15),
        (0.09999, 1e-14),
        (0.10001, 1e-14),
    ] {
        let xi = Vector3::new(w, 0.7, -1.3);
        let g = Se2::exp(&xi);
        let reference = matrix_path::exp::<Se2>(&xi);
        assert!(g.matrix_distance(&reference) < tol, "exp at ω = {w}");
        let back = g.log().unwrap();
        assert!(
            (back - xi).abs().max() < 2.0 * tol,
            "log at ω = {w}: {back:?}"
        );
        let j = Se2::dexp_left(&xi);
        let jr = matrix_path::dexp_left::<Se2>(&xi);
        assert!(max_diff3(&j, &jr) < tol, "dexp at ω = {w}");
        let ji = Se2::dexp_left_inv(&xi);
        assert!(
            max_diff3(&(ji * j), &Matrix3::identity()) < tol,
            "dexp_inv at ω = {w}"
        );
        assert!(ji.iter().all(|x| x.is_finite()));
    }
}

#[test]
fn so2_log_at_half_turn_is_plus_pi_for_both_signs_of_zero_sine() {
    let a = So2::from_cos_sin_unchecked(-1.0, 0.0);
    let b = So2::from_cos_sin_unchecked(-1.0, -0.0);
    assert_eq!(a.log().unwrap()[0], PI);
    assert_eq!(b.log().unwrap()[0], PI);
    let c = So2::exp(&Vector1::new(PI));
    assert_relative_eq!(c.log().unwrap()[0].abs(), PI, epsilon = 1e-15);
    let d = So2::exp(&Vector1::new(-PI));
    assert!(d.log().unwrap()[0].is_finite());
}

#[test]
fn se2_log_at_half_turn_is_finite_and_inverts_exp() {
    for xi in [Vector3::new(PI, 1.0, 2.0), Vector3::new(-PI, -0.5, 0.25)] {
        let g = Se2::exp(&xi);
        let l = g.log().unwrap();
        assert!(l.iter().all(|x| x.is_finite()));
        assert_relative_eq!(l[0].abs(), PI, epsilon = 1e-15);
        // exp(log g) = g even where ±π are both logarithms
        assert!(Se2::exp(&l).matrix_distance(&g) < 1e-14);
    }
    let exact = Se2::new(
        So2::from_cos_sin_unchecked(-1.0, 0.0),
        Vector2::new(3.0, -1.0),
    );
    let l = exact.log().unwrap();
    assert_eq!(l[0], PI);
    assert!(Se2::exp(&l).matrix_distance(&exact) < 1e-14);
}

#[test]
fn cayley_inverse_is_refused_at_the_half_turn() {
    let g = So2::from_cos_sin_unchecked(-1.0, 0.0);
    assert!(matches!(g.cay_inv(), Err(LieError::OutOfDomain { .. })));
    let h = Se2::new(g, Vector2::new(1.0, 0.0));
    assert!(matches!(h.cay_inv(), Err(LieError::OutOfDomain { .. })));
}

#[test]
fn checked_constructors_refuse_non_rotations() {
    let scaled = Matrix2::new(1.1, 0.0, 0.0, 1.1);
    assert!(matches!(
        So2::from_matrix(&scaled),
        Err(LieError::NotOrthogonal { .. })
    ));
    let reflection = Matrix2::new(1.0, 0.0, 0.0, -1.0);
    assert!(matches!(
        So2::from_matrix(&reflection),
        Err(LieError::WrongDeterminant { .. })
    ));
    let nan = Matrix2::new(f64::NAN, 0.0, 0.0, 1.0);
    assert!(matches!(
        So2::from_matrix(&nan),
        Err(LieError::NonFinite { .. })
    ));
    // a 1e-12 perturbation passes the default 1e-9 tolerance but not an explicit 1e-13
    let near = Matrix2::new(1.0 + 1e-12, 0.0, 0.0, 1.0);
    assert!(So2::from_matrix(&near).is_ok());
    assert!(So2::from_matrix_with_tolerance(&near, 1e-13).is_err());

    let mut m = Se2::exp(&Vector3::new(0.4, 1.0, 2.0)).matrix();
    assert!(Se2::from_matrix(&m).is_ok());
    m[(2, 0)] = 1e-3;
    assert!(matches!(
        Se2::from_matrix(&m),
        Err(LieError::NotHomogeneous { .. })
    ));
    let mut r = Matrix3::identity();
    r[(1, 1)] = -1.0;
    assert!(matches!(
        Se2::from_matrix(&r),
        Err(LieError::WrongDeterminant { .. })
    ));
    r[(0, 2)] = f64::INFINITY;
    assert!(matches!(
        Se2::from_matrix(&r),
        Err(LieError::NonFinite { .. })
    ));
    assert!(So2::log(&So2::from_cos_sin_unchecked(f64::NAN, 0.0)).is_err());
}

#[test]
fn projection_returns_the_nearest_rotation() {
    let g = So2::from_angle(0.7);
    let noisy = g.matrix() * 1.3 + Matrix2::new(0.0, 1e-3, -1e-3, 0.0);
    let p = So2::project(&noisy).unwrap();
    // the skew perturbation shifts the angle by atan(1e-3/1.3)
    // as complex numbers noisy = 1.3 e^{0.7 i} − 10⁻³ i; the nearest rotation is its phase
    let expected = (1.3 * 0.7f64.sin() - 1e-3).atan2(1.3 * 0.7f64.cos());
    assert_relative_eq!(p.angle(), expected, epsilon = 1e-15);
    assert!(So2::from_matrix(&p.matrix()).is_ok());
    assert!(So2::project(&Matrix2::zeros()).is_err());
    let h = Se2::project(&(Se2::exp(&Vector3::new(1.0, 2.0, 3.0)).matrix() * 2.0)).unwrap();
    assert!(Se2::from_matrix(&h.matrix()).is_ok());
    assert_relative_eq!(h.rotation().angle(), 1.0, epsilon = 1e-15);
}

#[test]
fn actions_match_the_matrix_representation() {
    let p = Vector2::new(0.3, -2.0);
    let g = So2::from_angle(1.1);
    assert_relative_eq!(g.act(&p), g.matrix() * p, epsilon = 1e-15);
    let h = Se2::exp(&Vector3::new(-0.8, 1.0, 0.5));
    let hp = h.matrix() * Vector3::new(p.x, p.y, 1.0);
    assert_relative_eq!(h.act(&p), Vector2::new(hp.x, hp.y), epsilon = 1e-15);
}

#[test]
fn nalgebra_conversions_round_trip_and_agree_on_action() {
    let g = So2::from_angle(2.2);
    let z: UnitComplex<f64> = g.into();
    assert_relative_eq!(z.angle(), 2.2, epsilon = 1e-15);
    assert_eq!(So2::from(z), g);
    let h = Se2::exp(&Vector3::new(0.9, -1.0, 4.0));
    let iso: Isometry2<f64> = h.into();
    let p = Vector2::new(1.5, 0.5);
    let ip = iso * nalgebra::Point2::from(p);
    assert_relative_eq!(ip.coords, h.act(&p), epsilon = 1e-14);
    assert_relative_eq!(Se2::from(iso).matrix(), h.matrix(), epsilon = 0.0);
    // composition is nalgebra's isometry product
    let k = Se2::exp(&Vector3::new(-2.0, 0.3, 0.1));
    let prod: Isometry2<f64> = h.compose(&k).into();
    let iso_k: Isometry2<f64> = k.into();
    assert_relative_eq!(
        prod.to_homogeneous(),
        (iso * iso_k).to_homogeneous(),
        epsilon = 1e-14
    );
}

/// Direct checks at the origin of the algebra and near the boundary of the principal domain,
/// where proptest's uniform draws rarely land.
#[test]
fn se2_checks_hold_at_fixed_extreme_points() {
    for xi in [
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(1e-8, 1.0, -1.0),
        Vector3::new(3.1, 2.0, -3.0),
        Vector3::new(-3.1, -1.0, 0.5),
    ] {
        check_exp_log::<Se2>(&xi);
        check_dexp::<Se2>(&xi);
        check_tau::<Se2, ExpMap>(&xi, &Vector3::new(0.5, -1.0, 2.0));
        check_tau::<Se2, Cayley>(&xi, &Vector3::new(0.5, -1.0, 2.0));
    }
    // the duals of Ad and ad for SE(2) are the transposes
    let xi = Vector3::new(0.4, -1.2, 0.8);
    let mu = Vector3::new(1.0, 2.0, -0.5);
    let g = Se2::exp(&xi);
    assert_relative_eq!(
        g.coadjoint_apply(&mu),
        g.adjoint().transpose() * mu,
        epsilon = 1e-15
    );
    assert_relative_eq!(
        Se2::ad_dual_apply(&xi, &mu),
        Operator::apply_transpose(&Se2::ad(&xi), &mu),
        epsilon = 1e-15
    );
}
