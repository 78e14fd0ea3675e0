//! The lanes' sin and cos against libm (glibc's, correctly rounded in practice) over the whole
//! range, on every level, and the Rodrigues coefficients against their closed forms.

use batch::trig::{
    atan_lane, atan_slices, rodrigues_coefficients_lane, rodrigues_coefficients_slices,
    sin_cos_lane, sin_cos_slices, REDUCTION_LIMIT, SHORT_KERNEL_LIMIT,
};
use batch::Level;

/// Distance in ulps between two doubles of the same sign (∞ for different signs).
fn ulps(a: f64, b: f64) -> u64 {
    if a == b {
        return 0;
    }
    if a.is_sign_negative() != b.is_sign_negative() {
        return u64::MAX;
    }
    (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
}

/// Arguments: dense near 0, on the short kernels' range and on [−2π, 2π], a few ulps about the
/// short range's ends, near multiples of π/2, and logarithmic to 2²⁸ (the reduction's range).
fn arguments() -> Vec<f64> {
    let mut xs = Vec::new();
    let n = 400_000;
    for i in 0..=n {
        let t = -1.0 + 2.0 * i as f64 / n as f64;
        xs.push(t * core::f64::consts::TAU);
        xs.push(t * SHORT_KERNEL_LIMIT);
        xs.push(t * 1e-3);
    }
    for d in -4i64..=4 {
        let x = f64::from_bits((SHORT_KERNEL_LIMIT.to_bits() as i64 + d) as u64);
        xs.extend([x, -x]);
    }
    // logarithmic, both signs, up to the reduction limit
    let m = 200_000;
    for i in 0..=m {
        let x = 10f64.powf(-300.0 + 309.0 * i as f64 / m as f64);
        if x <= REDUCTION_LIMIT {
            xs.push(x);
            xs.push(-x);
        }
    }
    // a few ulps around multiples of π/2
    // (k = 0 is left out: the bits below +0 are NaN, the ones above subnormals, taken below)
    for k in (-2000i64..=2000).filter(|&k| k != 0) {
        let c = k as f64 * core::f64::consts::FRAC_PI_2;
        for d in -3i64..=3 {
            xs.push(f64::from_bits((c.to_bits() as i64 + d) as u64));
        }
    }
    xs.extend([
        0.0,
        -0.0,
        5e-324,
        -5e-324,
        f64::MIN_POSITIVE,
        REDUCTION_LIMIT,
    ]);
    xs
}

#[test]
fn sin_cos_matches_libm_over_the_whole_range() {
    let xs = arguments();
    let (mut s, mut c) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
    sin_cos_slices(Level::Scalar, &xs, &mut s, &mut c).unwrap();
    let (mut worst_s, mut worst_c, mut worst_abs) = (0u64, 0u64, 0f64);
    for ((&x, &si), &ci) in xs.iter().zip(&s).zip(&c) {
        let (s0, c0) = x.sin_cos();
        // Tiny results (the argument near a multiple of π/2): the reduction's absolute error.
        for (got, want, worst) in [(si, s0, &mut worst_s), (ci, c0, &mut worst_c)] {
            if want == 0.0 {
                worst_abs = worst_abs.max((got - want).abs());
            } else {
                *worst = (*worst).max(ulps(got, want));
            }
        }
    }
    println!("worst ulps: sin {worst_s}, cos {worst_c}; worst absolute near zeros {worst_abs:e}");
    assert!(
        worst_s <= 1 && worst_c <= 1,
        "sin {worst_s}, cos {worst_c} ulps"
    );
    assert!(
        worst_abs == 0.0,
        "absolute {worst_abs:e} where libm gives 0"
    );
    // signed zeros kept: sin(−0) = −0
    assert!(sin_cos_lane(-0.0).0.is_sign_negative() && sin_cos_lane(0.0).0.is_sign_positive());
}

#[test]
fn every_level_gives_the_bits_of_the_scalar_lane() {
    let xs = arguments();
    let (mut s0, mut c0) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
    sin_cos_slices(Level::Scalar, &xs, &mut s0, &mut c0).unwrap();
    for level in Level::available() {
        let (mut s, mut c) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
        sin_cos_slices(level, &xs, &mut s, &mut c).unwrap();
        for i in 0..xs.len() {
            assert_eq!(s[i].to_bits(), s0[i].to_bits(), "{level}: sin({:e})", xs[i]);
            assert_eq!(c[i].to_bits(), c0[i].to_bits(), "{level}: cos({:e})", xs[i]);
        }
    }
}

/// A lane's bits do not depend on what its neighbours hold: one argument beyond the range (NaN) or
/// one that needs the reduction next to small ones leaves the small ones' bits alone.
#[test]
fn a_lane_does_not_depend_on_its_neighbours() {
    let small = [0.1, -0.3, 0.7, 1e-9, 0.0, -0.7, 0.25, 0.5];
    for level in Level::available() {
        let (mut s, mut c) = ([0.0; 8], [0.0; 8]);
        sin_cos_slices(level, &small, &mut s, &mut c).unwrap();
        for wild in [3.0, 1e12, f64::NAN, f64::INFINITY] {
            for pos in 0..8 {
                let mut xs = small;
                xs[pos] = wild;
                let (mut s1, mut c1) = ([0.0; 8], [0.0; 8]);
                sin_cos_slices(level, &xs, &mut s1, &mut c1).unwrap();
                for i in (0..8).filter(|&i| i != pos) {
                    assert_eq!(s1[i].to_bits(), s[i].to_bits());
                    assert_eq!(c1[i].to_bits(), c[i].to_bits());
                }
                let (ws, wc) = (s1[pos], c1[pos]);
                if wild.abs() <= REDUCTION_LIMIT {
                    let (e_s, e_c) = wild.sin_cos();
                    assert!((ws - e_s).abs() <= 4e-16 && (wc - e_c).abs() <= 4e-16);
                } else {
                    assert!(ws.is_nan() && wc.is_nan(), "{wild}: NaN beyond the range");
                }
            }
        }
    }
}

/// Dense arguments `0 < xᵢ ≤ limit`, both signs, and the same with every eighth (from lane
/// `first`) replaced by `wild`.
fn with_a_wild_neighbour(limit: f64, first: usize, wild: f64) -> (Vec<f64>, Vec<f64>) {
    let n = 40_000;
    let xs: Vec<f64> = (1..=n)
        .map(|i| limit * i as f64 / n as f64 * if i % 3 == 0 { -1.0 } else { 1.0 })
        .collect();
    let mut mixed = xs.clone();
    for x in mixed.iter_mut().skip(first).step_by(8) {
        *x = wild;
    }
    (xs, mixed)
}

/// The short kernels' lanes keep their bits next to a lane that needs the full kernels, the
/// reduction or is NaN, on every level: sin and cos over the short range, and the Rodrigues
/// coefficients where the half angle is in it (θ² ≤ 4·limit²) next to θ² = 0.1 (the full
/// kernels), 9 (beyond π/2: √ and ÷) and NaN.
#[test]
fn the_short_kernels_do_not_depend_on_the_neighbours() {
    for level in Level::available() {
        for (first, wild) in [(0, 0.3), (3, 3.0), (7, f64::NAN)] {
            let (xs, mixed) = with_a_wild_neighbour(SHORT_KERNEL_LIMIT, first, wild);
            let run = |xs: &[f64]| {
                let (mut s, mut c) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
                sin_cos_slices(level, xs, &mut s, &mut c).unwrap();
                (s, c)
            };
            let ((s, c), (s1, c1)) = (run(&xs), run(&mixed));
            for i in (0..xs.len()).filter(|i| i % 8 != first) {
                assert_eq!(s1[i].to_bits(), s[i].to_bits(), "{level}: sin({:e})", xs[i]);
                assert_eq!(c1[i].to_bits(), c[i].to_bits(), "{level}: cos({:e})", xs[i]);
            }
        }
        for (first, wild) in [(0, 0.1), (3, 9.0), (7, f64::NAN)] {
            let limit = 4.0 * SHORT_KERNEL_LIMIT * SHORT_KERNEL_LIMIT;
            let (t2, mixed) = with_a_wild_neighbour(limit, first, wild);
            let t2: Vec<f64> = t2.iter().map(|x| x.abs()).collect();
            let mixed: Vec<f64> = mixed.iter().map(|x| x.abs()).collect();
            let run = |t2: &[f64]| {
                let (mut a, mut b) = (vec![0.0; t2.len()], vec![0.0; t2.len()]);
                rodrigues_coefficients_slices(level, t2, &mut a, &mut b).unwrap();
                (a, b)
            };
            let ((a, b), (a1, b1)) = (run(&t2), run(&mixed));
            for i in (0..t2.len()).filter(|i| i % 8 != first) {
                assert_eq!(a1[i].to_bits(), a[i].to_bits(), "{level}: a({:e})", t2[i]);
                assert_eq!(b1[i].to_bits(), b[i].to_bits(), "{level}: b({:e})", t2[i]);
                let lane = rodrigues_coefficients_lane(t2[i]);
                assert_eq!(
                    (a[i].to_bits(), b[i].to_bits()),
                    (lane.0.to_bits(), lane.1.to_bits())
                );
            }
        }
    }
}

/// NaN and ±∞ give NaN (as libm), and so does an argument beyond the reduction's range, so
/// that a body turned that far fails instead of carrying a wrong angle.
#[test]
fn nan_infinities_and_arguments_beyond_the_range_give_nan() {
    let beyond = f64::from_bits(REDUCTION_LIMIT.to_bits() + 1);
    assert!(!sin_cos_lane(REDUCTION_LIMIT).0.is_nan());
    for x in [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        beyond,
        -beyond,
        1e300,
    ] {
        let (s, c) = sin_cos_lane(x);
        assert!(s.is_nan() && c.is_nan(), "{x}");
    }
    let (a, b) = rodrigues_coefficients_lane(f64::NAN);
    assert!(a.is_nan() && b.is_nan());
}

#[test]
fn rodrigues_coefficients_match_their_closed_forms() {
    let mut worst = (0u64, 0u64);
    // θ up to 6, and densely up to 2·SHORT_KERNEL_LIMIT (the half angle's short kernels)
    let thetas = (1..=200_000)
        .map(|i| 6.0 * i as f64 / 200_000.0)
        .chain((1..=100_000).map(|i| 2.0 * SHORT_KERNEL_LIMIT * i as f64 / 100_000.0));
    for theta in thetas {
        let t2 = theta * theta;
        let th = t2.sqrt();
        let (a, b) = rodrigues_coefficients_lane(t2);
        let (s, c) = th.sin_cos();
        let a0 = s / th;
        // (1 − cos θ)/θ² = 2 sin²(θ/2)/θ² without cancellation
        let b0 = 2.0 * ((0.5 * th).sin() / th).powi(2);
        if a0.abs() > 1e-3 {
            worst.0 = worst.0.max(ulps(a, a0));
        } else {
            assert!((a - a0).abs() < 1e-18, "θ = {theta}: {a:e} vs {a0:e}");
        }
        worst.1 = worst.1.max(ulps(b, b0));
        let _ = c;
    }
    println!("rodrigues ulps (a, b): {worst:?}");
    assert!(worst.0 <= 8 && worst.1 <= 8, "{worst:?}");
    assert_eq!(rodrigues_coefficients_lane(0.0), (1.0, 0.5));
}

/// atan's arguments: dense on [−4, 4] (the reduction's five intervals), logarithmic from 10⁻³⁰⁰ to
/// 10³⁰⁰ both signs, a few ulps about each breakpoint (7/16, 11/16, 19/16, 39/16, 2⁻²⁷, 2⁶⁶), the
/// subnormals, ±0 and ±∞.
fn atan_arguments() -> Vec<f64> {
    let mut xs = Vec::new();
    let n = 400_000;
    for i in 0..=n {
        xs.push(-4.0 + 8.0 * i as f64 / n as f64);
    }
    let m = 300_000;
    for i in 0..=m {
        let x = 10f64.powf(-300.0 + 600.0 * i as f64 / m as f64);
        xs.push(x);
        xs.push(-x);
    }
    for c in [
        0.4375,
        0.6875,
        1.1875,
        2.4375,
        2f64.powi(-27),
        2f64.powi(66),
    ] {
        for d in -4i64..=4 {
            let x = f64::from_bits((c.to_bits() as i64 + d) as u64);
            xs.push(x);
            xs.push(-x);
        }
    }
    xs.extend([
        0.0,
        -0.0,
        5e-324,
        -5e-324,
        f64::MIN_POSITIVE,
        f64::MAX,
        -f64::MAX,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ]);
    xs
}

/// The lanes' atan is fdlibm's bit for bit (the `libm` crate's) and within 1 ulp of the system
/// libm's (glibc's, correctly rounded in practice; measured: 97 % of the arguments equal) over
/// the whole range, keeps ±0 and the sign, gives ±π/2 at ±∞ and NaN for NaN; and every level
/// gives the scalar lane's bits.
#[test]
fn atan_matches_libm_over_the_whole_range() {
    let xs = atan_arguments();
    let mut got = vec![0.0; xs.len()];
    atan_slices(Level::Scalar, &xs, &mut got).unwrap();
    let mut worst = 0u64;
    let mut exact = 0usize;
    for (&x, &a) in xs.iter().zip(&got) {
        let u = ulps(a, x.atan());
        worst = worst.max(u);
        exact += (u == 0) as usize;
        // fdlibm's operations, lane by lane: the `libm` crate's atan (its Rust port) bit for bit
        assert_eq!(
            a.to_bits(),
            libm::atan(x).to_bits(),
            "atan({x:e}) against fdlibm"
        );
    }
    println!(
        "atan: worst {worst} ulp against libm; {exact} of {} equal",
        xs.len()
    );
    assert!(worst <= 1, "atan: {worst} ulps");
    assert!(atan_lane(-0.0).is_sign_negative() && atan_lane(0.0).is_sign_positive());
    assert_eq!(atan_lane(f64::INFINITY), core::f64::consts::FRAC_PI_2);
    assert_eq!(atan_lane(f64::NEG_INFINITY), -core::f64::consts::FRAC_PI_2);
    assert!(atan_lane(f64::NAN).is_nan());
    for level in Level::available() {
        let mut other = vec![0.0; xs.len()];
        atan_slices(level, &xs, &mut other).unwrap();
        for i in 0..xs.len() {
            assert_eq!(
                other[i].to_bits(),
                got[i].to_bits(),
                "{level}: atan({:e})",
                xs[i]
            );
        }
        // NaN next to finite lanes: NaN there, the others untouched
        let mut mixed = [0.3, f64::NAN, -2.0, 1e10, 0.5, f64::NAN, 7.0, -0.6];
        let mut out = [0.0; 8];
        atan_slices(level, &mixed, &mut out).unwrap();
        for (i, x) in mixed.iter_mut().enumerate() {
            if x.is_nan() {
                assert!(out[i].is_nan());
            } else {
                assert_eq!(out[i].to_bits(), atan_lane(*x).to_bits());
            }
        }
    }
    assert!(matches!(
        atan_slices(Level::Scalar, &[1.0, 2.0], &mut [0.0]),
        Err(batch::BatchError::LengthMismatch { .. })
    ));
}
