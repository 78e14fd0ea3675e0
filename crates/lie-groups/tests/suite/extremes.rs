//! SO(3) and SE(3) at the edges: tiny and zero angles, angles at and near π and beyond, large
//! translations, bad input to the checked constructors, projection, nalgebra round trips.
//!
//! References are evaluated independently of the closed forms: truncated power series in ad_ξ
//! (which converge to round-off for |ξ| ≤ 1.5 with 25 terms), the generic matrix path
//! (`lie_groups::matrix_path`, Padé / LU on the matrix representation), nalgebra's own geometry.

use lie_groups::testing::{assert_small, expm_taylor};
use lie_groups::{
    matrix_path, Action, CayleyGroup, DenseMatrix, GroupMap, LieError, LieGroup, Se3, So3,
};
use nalgebra::{
    Isometry3, Matrix3, Matrix4, Matrix6, Point3, Quaternion, Rotation3, SMatrix, SVector,
    UnitQuaternion, Vector3, Vector6,
};
use proptest::prelude::*;
use std::f64::consts::PI;

/// Σ_{k<25} (−A)^k/(k+1)!: d^L exp_ξ with A = ad_ξ.
fn dexp_series<const N: usize>(ad: &SMatrix<f64, N, N>) -> SMatrix<f64, N, N> {
    let mut term = SMatrix::<f64, N, N>::identity();
    let mut sum = term;
    for k in 1..25 {
        term = -term * ad / (k as f64 + 1.0);
        sum += term;
    }
    sum
}

/// Σ_{k<25} A^k/k!: e^A.
fn exp_series<const N: usize>(a: &SMatrix<f64, N, N>) -> SMatrix<f64, N, N> {
    let mut term = SMatrix::<f64, N, N>::identity();
    let mut sum = term;
    for k in 1..25 {
        term = term * a / k as f64;
        sum += term;
    }
    sum
}

fn unit(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z).normalize()
}

/// Axes with zero and negative components.
fn axes() -> Vec<Vector3<f64>> {
    vec![
        unit(1.0, 0.0, 0.0),
        unit(0.0, 1.0, 0.0),
        unit(0.0, 0.0, 1.0),
        unit(-1.0, 0.0, 0.0),
        unit(0.0, 0.0, -1.0),
        unit(1.0, -1.0, 0.0),
        unit(0.0, -1.0, 1.0),
        unit(-0.6, -0.8, 0.0),
        unit(-1.0, 2.0, -3.0),
        unit(0.3, 0.3, 0.3),
        unit(1e-9, -1.0, 1e-9),
    ]
}

/// Small and branch-boundary magnitudes: 0, 1e-12, 1e-8, and just either side of the Taylor
/// switches at θ = 0.1 (SO(3) coefficients) and θ = 0.5 (SE(3) coupling block).
const SMALL: [f64; 8] = [
    0.0,
    1e-12,
    1e-8,
    1e-4,
    0.1 - 1e-12,
    0.1 + 1e-12,
    0.5 - 1e-12,
    0.5 + 1e-12,
];

#[test]
fn so3_exp_log_dexp_near_zero_match_series_to_round_off() {
    for n in axes() {
        for &t in &SMALL {
            let w = n * t;
            let k = So3::hat(&w);
            let r = So3::exp(&w);
            // exp: entries are O(1), so 2 ulp of 1 is the bar.
            assert_small(
                "exp ω = series",
                (r.matrix() - exp_series(&k)).amax(),
                4e-16,
            );
            // log: relative accuracy in ω itself, including ω = 0 exactly.
            let back = r.log().unwrap();
            assert_small(
                "log exp ω = ω",
                (back - w).norm(),
                2e-16 * t.max(1e-300) * 4.0 + 0.0,
            );
            let j = So3::dexp_left(&w);
            assert_small("d^L exp = series", (j - dexp_series(&k)).amax(), 3e-16);
            let ji = So3::dexp_left_inv(&w);
            let series_inv = dexp_series(&k).try_inverse().unwrap();
            assert_small(
                "(d^L exp)⁻¹ = inverse of series",
                (ji - series_inv).amax(),
                4e-16,
            );
            assert_small(
                "d^L cay = matrix path",
                (So3::dcay_left(&w) - matrix_path::dcay_left::<So3>(&w)).amax(),
                4e-16,
            );
            assert_small(
                "(d^L cay)⁻¹ = matrix path",
                (So3::dcay_left_inv(&w) - matrix_path::dcay_left_inv::<So3>(&w)).amax(),
                4e-16,
            );
            let c = So3::cay(&w);
            assert_small(
                "cay = matrix path",
                c.matrix_distance(&matrix_path::cay::<So3>(&w)),
                4e-16,
            );
            assert_small(
                "cay⁻¹ cay ω = ω",
                (c.cay_inv().unwrap() - w).norm(),
                4e-16 * t,
            );
        }
    }
}

#[test]
fn so3_log_of_exactly_identity_is_exactly_zero() {
    assert_eq!(So3::identity().log().unwrap(), Vector3::zeros());
    assert_eq!(So3::exp(&Vector3::zeros()), So3::identity());
    assert_eq!(So3::dexp_left(&Vector3::zeros()), Matrix3::identity());
    assert_eq!(So3::dexp_left_inv(&Vector3::zeros()), Matrix3::identity());
}

#[test]
fn se3_exp_log_dexp_near_zero_match_series_to_round_off() {
    for n in axes() {
        for &t in &SMALL {
            let w = n * t;
            // translation of unit size, so the coupling block Q is exercised at full size.
            let xi = Vector6::new(w.x, w.y, w.z, 0.3, -1.0, 0.7);
            let ad = Se3::ad(&xi);
            let g = Se3::exp(&xi);
            assert_small(
                "exp ξ = series",
                (g.matrix() - exp_series(&Se3::hat(&xi))).amax(),
                1e-15,
            );
            assert_small("log exp ξ = ξ", (g.log().unwrap() - xi).amax(), 1e-15);
            let j = Se3::dexp_left(&xi);
            assert_small("d^L exp = series", (j - dexp_series(&ad)).amax(), 1e-15);
            let ji = Se3::dexp_left_inv(&xi);
            let series_inv = dexp_series(&ad).try_inverse().unwrap();
            assert_small(
                "(d^L exp)⁻¹ = inverse of series",
                (ji - series_inv).amax(),
                1e-15,
            );
            assert_small(
                "d^L cay = matrix path",
                (Se3::dcay_left(&xi) - matrix_path::dcay_left::<Se3>(&xi)).amax(),
                1e-15,
            );
            assert_small(
                "(d^L cay)⁻¹ = matrix path",
                (Se3::dcay_left_inv(&xi) - matrix_path::dcay_left_inv::<Se3>(&xi)).amax(),
                1e-15,
            );
            assert_small(
                "cay⁻¹ cay ξ = ξ",
                (Se3::cay(&xi).cay_inv().unwrap() - xi).amax(),
                1e-15,
            );
        }
    }
}

#[test]
fn so3_log_near_pi_is_accurate_on_every_axis() {
    // θ = π − δ: the axis comes from the symmetric part, the sign from the skew part.
    for n in axes() {
        for &delta in &[1e-3, 1e-6, 1e-8, 1e-10, 1e-12] {
            let w = n * (PI - delta);
            let r = So3::exp(&w);
            let back = r.log().unwrap();
            assert!(back.iter().all(|x| x.is_finite()));
            // R itself carries ~1e-16 rounding, which moves the angle and axis by as much;
            // 1e-14 leaves a margin of ~30 ulp of π.
            assert_small("log exp ω = ω near π", (back - w).norm(), 1e-14);
        }
    }
}

#[test]
fn so3_log_at_pi_returns_a_valid_half_turn_without_nan() {
    for n in axes() {
        let r = So3::exp(&(n * PI));
        let back = r.log().unwrap();
        assert!(back.iter().all(|x| x.is_finite()), "no NaN at θ = π");
        assert_small("|log R| = π", (back.norm() - PI).abs(), 1e-14);
        // ±π n are both logarithms of the half turn.
        assert_small("axis is ±n", back.normalize().cross(&n).norm(), 1e-14);
        assert_small("exp log R = R", So3::exp(&back).matrix_distance(&r), 1e-15);
    }
    // exact half turns built from integers: diag(1, −1, −1) etc.
    for (m, axis) in [
        (
            Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0)),
            Vector3::x(),
        ),
        (
            Matrix3::from_diagonal(&Vector3::new(-1.0, 1.0, -1.0)),
            Vector3::y(),
        ),
        (
            Matrix3::from_diagonal(&Vector3::new(-1.0, -1.0, 1.0)),
            Vector3::z(),
        ),
    ] {
        let r = So3::from_matrix(&m).unwrap();
        let back = r.log().unwrap();
        assert_small(
            "log of an exact half turn",
            (back - axis * PI).norm(),
            1e-15,
        );
    }
}

#[test]
fn so3_exp_beyond_pi_matches_matrix_series_and_log_returns_principal_value() {
    for n in axes() {
        for &t in &[
            PI + 1e-8,
            PI + 0.5,
            4.0,
            2.0 * PI - 0.1,
            2.0 * PI + 0.3,
            7.0,
            10.0 * PI + 0.2,
        ] {
            let w = n * t;
            let r = So3::exp(&w);
            let reference = expm_taylor(So3::hat(&w).to_dmatrix().as_view());
            let reference = Matrix3::from_fn(|i, j| reference[(i, j)]);
            assert_small(
                "exp = Taylor e^{ω̂} beyond π",
                (r.matrix() - reference).amax(),
                1e-13 * t,
            );
            // principal value: θ' = t − 2πk ∈ (−π, π], same axis
            let k = ((t + PI) / (2.0 * PI)).floor();
            let principal = n * (t - 2.0 * PI * k);
            let back = r.log().unwrap();
            assert!(back.norm() <= PI + 1e-15);
            assert_small(
                "log returns the principal value",
                (back - principal).norm(),
                4e-15 * t,
            );
        }
    }
}

#[test]
fn se3_large_translations_keep_relative_accuracy() {
    let t = 1e6;
    let a = Vector6::new(0.4, -1.1, 0.3, t, -2.0 * t, 0.5 * t);
    let b = Vector6::new(-0.9, 0.2, 1.3, -t, 0.3 * t, 3.0 * t);
    let (g, h) = (Se3::exp(&a), Se3::exp(&b));
    // entries of size ~3e6: relative 1e-15 is ~3e-9 absolute
    assert_small("log exp ξ = ξ", (g.log().unwrap() - a).amax() / t, 1e-14);
    assert_small(
        "g g⁻¹ = e",
        g.compose(&g.inverse()).matrix_distance(&Se3::identity()) / t,
        1e-15,
    );
    let ad_gh = g.compose(&h).adjoint();
    assert_small(
        "Ad_{gh} = Ad_g Ad_h",
        (ad_gh - g.adjoint() * h.adjoint()).amax() / (t * t),
        1e-14,
    );
    // The translation of exp(ω, v) is linear in v, so the reference is the matrix path at unit
    // translation scaled up (the Padé path itself loses ~1e-10 to scaling and squaring at 1e6).
    let unit_a = Vector6::new(a[0], a[1], a[2], a[3] / t, a[4] / t, a[5] / t);
    let reference = matrix_path::exp::<Se3>(&unit_a);
    let reference = Se3::from_parts(*reference.rotation(), reference.translation() * t);
    assert_small(
        "exp = matrix path",
        g.matrix_distance(&reference) / t,
        1e-14,
    );
    let c = Se3::cay(&a);
    assert_small(
        "cay⁻¹ cay ξ = ξ",
        (c.cay_inv().unwrap() - a).amax() / t,
        1e-14,
    );
    let p = Vector3::new(t, t, -t);
    assert_small(
        "g⁻¹ (g p) = p",
        (g.inverse().act(&g.act(&p)) - p).amax() / t,
        1e-14,
    );
}

#[test]
fn checked_constructors_refuse_bad_rotations() {
    let r = So3::exp(&Vector3::new(0.3, -0.4, 1.2)).matrix();
    assert!(So3::from_matrix(&r).is_ok());
    // within the documented 1e-9 tolerance
    assert!(So3::from_matrix(&(r * (1.0 + 1e-11))).is_ok());
    assert!(matches!(
        So3::from_matrix(&(r * 1.001)),
        Err(LieError::NotOrthogonal { .. })
    ));
    let mut shear = Matrix3::identity();
    shear[(0, 1)] = 0.1;
    assert!(matches!(
        So3::from_matrix(&shear),
        Err(LieError::NotOrthogonal { .. })
    ));
    let reflection = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
    assert!(matches!(
        So3::from_matrix(&reflection),
        Err(LieError::WrongDeterminant { .. })
    ));
    let mut nan = r;
    nan[(1, 2)] = f64::NAN;
    assert!(matches!(
        So3::from_matrix(&nan),
        Err(LieError::NonFinite { .. })
    ));
    let mut inf = r;
    inf[(0, 0)] = f64::INFINITY;
    assert!(matches!(
        So3::from_matrix(&inf),
        Err(LieError::NonFinite { .. })
    ));
    // explicit tolerance
    assert!(So3::from_matrix_with_tolerance(&(r * (1.0 + 1e-7)), 1e-6).is_ok());
    assert!(So3::from_matrix_with_tolerance(&(r * (1.0 + 1e-7)), 1e-9).is_err());
    // logs of non-finite elements are errors, not NaN
    assert!(So3::from_matrix_unchecked(&nan).log().is_err());
    assert!(So3::from_matrix_unchecked(&nan).cay_inv().is_err());
}

#[test]
fn checked_constructors_refuse_bad_rigid_motions() {
    let g = Se3::exp(&Vector6::new(0.3, -0.4, 1.2, 1.0, 2.0, 3.0)).matrix();
    assert_eq!(Se3::from_matrix(&g).unwrap().matrix(), g);
    let mut bottom = g;
    bottom[(3, 1)] = 1e-3;
    assert!(matches!(
        Se3::from_matrix(&bottom),
        Err(LieError::NotHomogeneous { .. })
    ));
    let mut corner = g;
    corner[(3, 3)] = 2.0;
    assert!(matches!(
        Se3::from_matrix(&corner),
        Err(LieError::NotHomogeneous { .. })
    ));
    let mut skewed = g;
    skewed[(0, 0)] += 1e-3;
    assert!(matches!(
        Se3::from_matrix(&skewed),
        Err(LieError::NotOrthogonal { .. })
    ));
    let mut reflected = g;
    for i in 0..3 {
        reflected[(i, 2)] = -reflected[(i, 2)];
    }
    assert!(matches!(
        Se3::from_matrix(&reflected),
        Err(LieError::WrongDeterminant { .. })
    ));
    let mut nan = g;
    nan[(2, 3)] = f64::NAN;
    assert!(matches!(
        Se3::from_matrix(&nan),
        Err(LieError::NonFinite { .. })
    ));
    assert!(matches!(
        Se3::project(&nan),
        Err(LieError::NonFinite { .. })
    ));
    assert!(Se3::from_matrix_unchecked(&nan).log().is_err());
}

/// The orthogonal polar factor by an independent route: M (MᵀM)^{−1/2} from the symmetric
/// eigen-decomposition of MᵀM (valid when det M > 0).
fn polar_factor(m: &Matrix3<f64>) -> Matrix3<f64> {
    let eig = (m.transpose() * m).symmetric_eigen();
    let inv_sqrt = Matrix3::from_diagonal(&eig.eigenvalues.map(|l| 1.0 / l.sqrt()));
    m * eig.eigenvectors * inv_sqrt * eig.eigenvectors.transpose()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn projection_gives_a_rotation_and_equals_the_polar_factor(
        entries in proptest::collection::vec(-2.0f64..2.0, 9)
    ) {
        let m = Matrix3::from_column_slice(&entries);
        let s = m.singular_values();
        prop_assume!(s[2] > 1e-3 * s[0]);
        let r = So3::project(&m).unwrap();
        // a valid rotation to round-off
        prop_assert!(So3::from_matrix_with_tolerance(r.as_matrix(), 1e-14).is_ok());
        if m.determinant() > 0.0 {
            // conditioning of the polar factor is ~1/σ_min; 1e-12 covers σ_min ≥ 1e-3 σ_max
            let q = polar_factor(&m);
            prop_assert!((r.as_matrix() - q).amax() < 1e-10);
        }
    }

    #[test]
    fn projection_fixes_rotations_and_repairs_small_drift(
        w in proptest::collection::vec(-3.0f64..3.0, 3),
        e in proptest::collection::vec(-1e-6f64..1e-6, 9),
    ) {
        let r = So3::exp(&Vector3::from_column_slice(&w));
        // the SVD is backward stable: a few ulp
        prop_assert!(So3::project(r.as_matrix()).unwrap().matrix_distance(&r) < 2e-15);
        let drifted = So3::from_matrix_unchecked(&(r.matrix() + Matrix3::from_column_slice(&e)));
        let fixed = drifted.renormalize();
        prop_assert!(So3::from_matrix_with_tolerance(fixed.as_matrix(), 1e-14).is_ok());
        // the nearest rotation moves by at most the size of the drift
        prop_assert!(fixed.matrix_distance(&r) < 3e-6);
    }
}

#[test]
fn projection_of_a_reflection_has_determinant_plus_one_and_bad_input_is_refused() {
    let m = Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, -3.0));
    let r = So3::project(&m).unwrap();
    assert_small("det = +1", (r.as_matrix().determinant() - 1.0).abs(), 1e-15);
    let mut nan = Matrix3::identity();
    nan[(0, 0)] = f64::NAN;
    assert!(matches!(
        So3::project(&nan),
        Err(LieError::NonFinite { .. })
    ));
    assert!(matches!(
        So3::project(&Matrix3::zeros()),
        Err(LieError::Singular { .. })
    ));
    let rank_one = Vector3::new(1.0, 2.0, 3.0) * Vector3::new(0.0, 1.0, 1.0).transpose();
    assert!(matches!(
        So3::project(&rank_one),
        Err(LieError::Singular { .. })
    ));
    // SE(3): rotation block repaired, translation kept
    let mut g = Se3::exp(&Vector6::new(0.3, 0.2, 0.1, 5.0, 6.0, 7.0)).matrix();
    g[(0, 1)] += 1e-7;
    let p = Se3::project(&g).unwrap();
    assert!(Se3::from_matrix_with_tolerance(&p.matrix(), 1e-14).is_ok());
    assert_eq!(
        p.translation(),
        &Vector3::new(g[(0, 3)], g[(1, 3)], g[(2, 3)])
    );
}

#[test]
fn so3_round_trips_with_nalgebra_rotation_and_quaternion() {
    for n in axes() {
        for &t in &[0.0, 1e-8, 0.5, 2.0, PI - 1e-9] {
            let w = n * t;
            let r = So3::exp(&w);
            let q = UnitQuaternion::from_scaled_axis(w);
            assert_small(
                "exp = nalgebra from_scaled_axis",
                (So3::from(q).matrix() - r.matrix()).amax(),
                1e-15,
            );
            let q2 = UnitQuaternion::from(r);
            assert_small(
                "So3 → quaternion → So3",
                So3::from(q2).matrix_distance(&r),
                1e-15,
            );
            assert_small(
                "log = nalgebra scaled_axis",
                (q2.scaled_axis() - r.log().unwrap()).norm(),
                1e-9,
            );
            let rot: Rotation3<f64> = r.into();
            assert_eq!(So3::from(rot), r);
            let p = Vector3::new(1.0, -2.0, 0.5);
            assert_small("act = nalgebra rotation", (r.act(&p) - q * p).amax(), 1e-15);
        }
    }
}

#[test]
fn so3_from_quaternion_is_checked_and_normalises() {
    let q = Quaternion::new(2.0, 0.0, 0.0, 0.0);
    assert_eq!(So3::from_quaternion(&q).unwrap(), So3::identity());
    let big = Quaternion::new(1e200, 1e200, 0.0, 0.0);
    let r = So3::from_quaternion(&big).unwrap();
    assert_small(
        "huge quaternion is a quarter... half-angle π/4 rotation",
        (r.log().unwrap() - Vector3::x() * (PI / 2.0)).norm(),
        1e-15,
    );
    assert!(matches!(
        So3::from_quaternion(&Quaternion::new(0.0, 0.0, 0.0, 0.0)),
        Err(LieError::ZeroQuaternion { .. })
    ));
    assert!(matches!(
        So3::from_quaternion(&Quaternion::new(f64::NAN, 0.0, 0.0, 1.0)),
        Err(LieError::NonFinite { .. })
    ));
    assert!(matches!(
        So3::from_quaternion(&Quaternion::new(1.0, f64::INFINITY, 0.0, 1.0)),
        Err(LieError::NonFinite { .. })
    ));
}

#[test]
fn se3_round_trips_with_nalgebra_isometry() {
    let a = Vector6::new(0.4, -1.1, 0.3, 1.0, -2.0, 0.5);
    let b = Vector6::new(-0.9, 0.2, 1.3, -1.0, 0.3, 3.0);
    let (g, h) = (Se3::exp(&a), Se3::exp(&b));
    let (gi, hi): (Isometry3<f64>, Isometry3<f64>) = (g.into(), h.into());
    assert_small(
        "Se3 → Isometry3 → Se3",
        Se3::from(gi).matrix_distance(&g),
        1e-15,
    );
    assert_small(
        "compose = isometry product",
        Se3::from(gi * hi).matrix_distance(&g.compose(&h)),
        1e-14,
    );
    assert_small(
        "inverse = isometry inverse",
        Se3::from(gi.inverse()).matrix_distance(&g.inverse()),
        1e-14,
    );
    let p = Point3::new(0.5, 1.5, -2.0);
    assert_small(
        "act = transform_point",
        (g.act(&p.coords) - (gi * p).coords).amax(),
        1e-14,
    );
    assert_small(
        "matrix = to_homogeneous",
        (g.matrix() - gi.to_homogeneous()).amax(),
        1e-15,
    );
}

#[test]
fn cayley_inverse_is_refused_at_half_turns_on_se3() {
    let g = Se3::from_parts(
        So3::exp(&(unit(1.0, -2.0, 0.5) * PI)),
        Vector3::new(1.0, 2.0, 3.0),
    );
    assert!(matches!(g.cay_inv(), Err(LieError::OutOfDomain { .. })));
}

#[test]
fn se3_adjoint_is_block_lower_triangular_in_omega_v_order() {
    let g = Se3::exp(&Vector6::new(0.4, -1.1, 0.3, 1.0, -2.0, 0.5));
    let ad: Matrix6<f64> = g.adjoint();
    assert_eq!(ad.fixed_view::<3, 3>(0, 3).into_owned(), Matrix3::zeros());
    let r = g.rotation().matrix();
    let t = *g.translation();
    assert_small(
        "lower-left block = t̂ R",
        (ad.fixed_view::<3, 3>(3, 0) - So3::hat(&t) * r).amax(),
        1e-15,
    );
    let _unused: SVector<f64, 6> = Vector6::zeros();
    let _m: Matrix4<f64> = g.matrix();
}

/// `normalize` pulls a drifted rotation back onto SO(3) to round-off and leaves an exact one
/// unchanged to round-off; 10⁶ products with it stay orthogonal to round-off.
#[test]
fn so3_normalize_removes_drift_without_moving_the_rotation() {
    use lie_groups::{LieGroup, So3};
    use nalgebra::{Matrix3, Vector3};
    let r = So3::exp(&Vector3::new(0.4, -1.1, 2.0));
    let drifted = r.as_matrix()
        * (Matrix3::identity()
            + Matrix3::new(1.0, 2.0, -1.0, 0.5, -2.0, 1.0, 3.0, 0.0, 1.0) * 1e-9);
    let fixed = So3::from_matrix_with_tolerance(&drifted, 1e-6)
        .unwrap()
        .normalize();
    let orth = (fixed.as_matrix().transpose() * fixed.as_matrix() - Matrix3::identity()).amax();
    assert!(
        orth < 1e-15,
        "orthogonality error {orth:.2e} after one normalize"
    );
    assert!(
        (fixed.as_matrix() - drifted).amax() < 1e-8,
        "normalize moved R by more than the drift"
    );
    let exact = r.normalize();
    assert!((exact.as_matrix() - r.as_matrix()).amax() < 1e-15);
    let step = So3::exp(&Vector3::new(0.01, -0.02, 0.015));
    let mut g = So3::identity();
    for _ in 0..1_000_000 {
        g = g.compose(&step).normalize();
    }
    let orth = (g.as_matrix().transpose() * g.as_matrix() - Matrix3::identity()).amax();
    assert!(
        orth < 1e-15,
        "orthogonality error {orth:.2e} after 10⁶ normalized products"
    );
}

/// `SoN::log` keeps its relative accuracy at every angle below π/3, down to subnormal rotations
/// (the issue measured 1.6e-5 relative at |ξ| = 1e-12 and a result of size 6e-33 for 1e-100 before
/// the near-identity path): log(exp ξ) = ξ within a few ulps of |ξ|, on SO(3), SO(4), SO(5), and
/// SoN<3> agrees with `So3` (coordinates (ω_z, −ω_y, ω_x)).
#[cfg(feature = "faer")]
#[test]
fn so_n_log_is_relatively_accurate_down_to_subnormal_angles() {
    fn check<const N: usize>(dir: &[f64]) -> f64 {
        let norm = dir.iter().map(|x| x * x).sum::<f64>().sqrt();
        let mut worst = 0.0f64;
        for size in [1.0, 0.5, 1e-3, 1e-8, 1e-12, 1e-100, 1e-300, 1e-310] {
            let xi = faer::Col::from_fn(dir.len(), |p| dir[p] / norm * size);
            let back = lie_groups::SoN::<N>::exp(&xi).log().unwrap();
            let abs = (0..dir.len())
                .map(|p| (back[p] - xi[p]).abs())
                .fold(0.0, f64::max);
            // A few ulps of |ξ|; subnormal entries have an absolute grain of 4.9e-324.
            let grain = 8.0 * f64::from_bits(1);
            assert!(
                abs <= 2e-15 * size + grain,
                "SO({N}), |ξ| = {size:e}: error {abs:e}"
            );
            if size > 1e-300 {
                worst = worst.max(abs / size);
            }
        }
        worst
    }
    let w3 = check::<3>(&[0.3, -0.5, 0.8]);
    let w4 = check::<4>(&[0.3, -0.5, 0.8, 0.1, 0.7, -0.2]);
    let w5 = check::<5>(&[0.3, -0.5, 0.8, 0.1, 0.7, -0.2, 0.4, 0.6, -0.9, 0.25]);
    println!("worst relative errors: SO(3) {w3:.1e}, SO(4) {w4:.1e}, SO(5) {w5:.1e}");
    for size in [1e-12, 1e-300] {
        let w = Vector3::new(0.3, -0.5, 0.8) * size;
        let so3 = So3::exp(&w).log().unwrap();
        let son = lie_groups::SoN::<3>::exp(&faer::Col::from_fn(3, |p| [w.z, -w.y, w.x][p]))
            .log()
            .unwrap();
        let e = (so3.z - son[0])
            .abs()
            .max((so3.y + son[1]).abs())
            .max((so3.x - son[2]).abs());
        assert!(e < 4e-16 * size, "|ω| = {size:e}: {e:e}");
    }
}

/// exp and Cayley on SO(3) beyond |ω| ≈ 1.3e154, where θ² overflows: a rotation about the axis
/// (orthogonal to round-off, det 1, the axis fixed), never NaN; Cayley tends to the half turn
/// I + 2n̂² about the axis. (Before, both returned NaN matrices without an error.)
#[test]
fn so3_exp_and_cayley_of_huge_vectors_are_rotations_about_the_axis() {
    let n = Vector3::new(0.3, -0.5, 0.8).normalize();
    for s in [2e154, 1e200, 1e300, f64::MAX / 4.0] {
        let w = n * s;
        for (name, r) in [("exp", So3::exp(&w)), ("cay", So3::cay(&w))] {
            let m = r.as_matrix();
            assert!(m.iter().all(|x| x.is_finite()), "{name} at {s:e}");
            assert_small(
                "RᵀR = I",
                (m.transpose() * m - nalgebra::Matrix3::identity()).amax(),
                1e-15,
            );
            assert_small("det R = 1", (m.determinant() - 1.0).abs(), 1e-15);
            assert_small("R n = n", (m * n - n).amax(), 1e-15);
        }
        let half_turn = nalgebra::Matrix3::identity() + n.cross_matrix() * n.cross_matrix() * 2.0;
        assert_small(
            "cay → half turn",
            (So3::cay(&w).as_matrix() - half_turn).amax(),
            1e-15,
        );
    }
    assert!(!So3::exp(&Vector3::new(f64::NAN, 0.0, 0.0)).is_finite());
}

/// |ω| beyond f64::MAX (every component f64::MAX: |ω| = √3·f64::MAX is not a float): exp and
/// Cayley still give a rotation about the axis, as their docs promise. (Before, exp's angle was
/// infinite and the matrix NaN.)
#[test]
fn so3_exp_and_cayley_beyond_f64_max_are_rotations_about_the_axis() {
    for w in [
        Vector3::new(f64::MAX, f64::MAX, f64::MAX),
        Vector3::new(-f64::MAX, f64::MAX, 0.0),
    ] {
        let n = (w / f64::MAX).normalize();
        for (name, r) in [("exp", So3::exp(&w)), ("cay", So3::cay(&w))] {
            let m = r.as_matrix();
            assert!(m.iter().all(|x| x.is_finite()), "{name} at {w:?}: {m}");
            // the products of the rounded matrix, themselves rounded in ~12 operations each: a
            // few ulps (5 measured)
            assert_small(
                "RᵀR = I",
                (m.transpose() * m - nalgebra::Matrix3::identity()).amax(),
                4e-15,
            );
            assert_small("det R = 1", (m.determinant() - 1.0).abs(), 4e-15);
            assert_small("R n = n", (m * n - n).amax(), 1e-15);
        }
    }
}

/// try_exp / try_cay: a non-finite ξ is `NonFinite`, a finite ξ whose image overflows is
/// `Overflow` (SE(3)'s translation beyond f64::MAX, GL(2)'s e^800), and elsewhere they are exp and
/// cay themselves (SO(3) at |ω| = 1e300 included: a rotation).
#[test]
fn try_exp_and_try_cay_turn_non_finite_results_into_errors() {
    use nalgebra::Vector6;
    let nan = Vector3::new(f64::NAN, 0.0, 0.0);
    assert!(matches!(
        So3::try_exp(&nan),
        Err(LieError::NonFinite { .. })
    ));
    assert!(matches!(
        So3::try_cay(&nan),
        Err(LieError::NonFinite { .. })
    ));
    let inf = Vector6::new(0.0, 0.0, 0.0, f64::INFINITY, 0.0, 0.0);
    assert!(matches!(
        Se3::try_exp(&inf),
        Err(LieError::NonFinite { .. })
    ));
    let w = Vector3::new(0.3, -0.5, 0.8);
    assert_eq!(So3::try_exp(&w).unwrap(), So3::exp(&w));
    assert_eq!(So3::try_cay(&w).unwrap(), So3::cay(&w));
    let huge = w * 1e300;
    assert!(So3::try_exp(&huge).unwrap().is_finite());
    let far = Vector6::new(0.0, 0.0, 2.0, f64::MAX, f64::MAX, 0.0);
    assert!(!Se3::exp(&far).is_finite());
    assert!(matches!(
        Se3::try_exp(&far),
        Err(LieError::Overflow {
            map: GroupMap::Exp,
            ..
        })
    ));
    #[cfg(feature = "faer")]
    {
        use lie_groups::GlN;
        let big = faer::col::Col::from_fn(4, |i| if i == 0 { 800.0 } else { 0.0 });
        assert!(matches!(
            GlN::<2>::try_exp(&big),
            Err(LieError::Overflow {
                map: GroupMap::Exp,
                ..
            })
        ));
        let msg = GlN::<2>::try_exp(&big).unwrap_err().to_string();
        assert!(msg.contains("exp") && msg.contains("overflow"), "{msg}");
    }
}
