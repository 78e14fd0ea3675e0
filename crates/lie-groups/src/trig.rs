//! `sin` and `cos` of one angle in [0, π/2], and `asin` / `acos` on [−½, ½], without a libm call,
//! for the hot paths of `So3::exp` and `So3::log`.
//!
//! The polynomials are the fdlibm kernels `__kernel_sin` / `__kernel_cos` (Sun Microsystems,
//! 1993, as kept in musl's `__sin.c` / `__cos.c`: "Permission to use, copy, modify, and
//! distribute this software is freely granted, provided that this notice is preserved"):
//! minimax fits on |x| ≤ π/4 whose approximation error is below 2⁻⁵⁸, so that each result is
//! within 1 ulp of the exact value. Angles in (π/4, π/2] are reduced by `r = π/2 − x` with
//! π/2 split in two (Cody–Waite: the first part has 33 bits, so `π/2₁ − x` is exact by Sterbenz'
//! lemma for x ∈ [π/4, π/2]); the reduced argument carries its rounding tail into the kernels,
//! as in fdlibm, and its absolute error is below 1e-26.
//!
//! `asin x = x + x R(x²)` and `acos x = π/2 − asin x` on |x| ≤ ½ use fdlibm's rational fit
//! R = P/Q of `(asin x − x)/x`, from the same source (`e_asin.c`, `e_acos.c`), error below 2⁻⁵⁸
//! relative; π/2 is split in two so that `acos` is also within 1 ulp.
//!
//! Below 2⁻⁵ `sin_cos` takes the Taylor series to x⁷ and x⁸ instead (`small_sin_cos`: the
//! omitted terms are below 0.2 ulp), half the kernels' flops for the splittings' small angles.
//!
//! The Taylor series of sin θ/θ, (1 − cos θ)/θ² and (θ − sin θ)/θ³ in θ², which SO(3) and SE(2)
//! take below θ = 0.1, are evaluated here too, by [`quartic`].
//!
//! Why: glibc's `sincos` is a call (with range reduction for any argument and the caller's
//! vector registers spilled around it) that costs about as much as the whole rest of `So3::exp`;
//! the kernels are short polynomials that inline and overlap with the rest.

/// `c₀ + c₁x + c₂x² + c₃x³ + c₄x⁴` in Estrin's form `(c₀ + c₁x) + x²((c₂ + c₃x) + c₄x²)`:
/// three dependent multiply-adds where Horner's form takes four, and products by the
/// coefficients rather than divisions by their reciprocals (a division's latency is three
/// multiply-adds). The small-angle series below (SO(3)'s and SE(2)'s exp coefficients and their
/// derivatives' below θ = 0.1) are on the critical path of every stage or residual that
/// evaluates exp or its derivatives.
#[inline(always)]
pub(crate) fn quartic(x: f64, c: [f64; 5]) -> f64 {
    let x2 = x * x;
    (c[0] + c[1] * x) + x2 * ((c[2] + c[3] * x) + c[4] * x2)
}

/// `sin θ/θ = 1 − θ²/6 + θ⁴/120 − θ⁶/5040 + θ⁸/362880 − …` in θ².
pub(crate) const SINC_SERIES: [f64; 5] =
    [1.0, -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0];
/// `(1 − cos θ)/θ² = 1/2 − θ²/24 + θ⁴/720 − θ⁶/40320 + θ⁸/3628800 − …` in θ².
pub(crate) const COSC_SERIES: [f64; 5] = [
    0.5,
    -1.0 / 24.0,
    1.0 / 720.0,
    -1.0 / 40320.0,
    1.0 / 3628800.0,
];
/// `(θ − sin θ)/θ³ = 1/6 − θ²/120 + θ⁴/5040 − θ⁶/362880 + θ⁸/39916800 − …` in θ².
pub(crate) const SINC3_SERIES: [f64; 5] = [
    1.0 / 6.0,
    -1.0 / 120.0,
    1.0 / 5040.0,
    -1.0 / 362880.0,
    1.0 / 39916800.0,
];

/// sin x ≈ x + S₁x³ + … + S₆x¹³ on |x| ≤ π/4 (fdlibm `__kernel_sin`).
const S1: f64 = f64::from_bits(0xBFC5_5555_5555_5549); // −1.66666666666666324348e-01
const S2: f64 = f64::from_bits(0x3F81_1111_1110_F8A6); //  8.33333333332248946124e-03
const S3: f64 = f64::from_bits(0xBF2A_01A0_19C1_61D5); // −1.98412698298579493134e-04
const S4: f64 = f64::from_bits(0x3EC7_1DE3_57B1_FE7D); //  2.75573137070700676789e-06
const S5: f64 = f64::from_bits(0xBE5A_E5E6_8A2B_9CEB); // −2.50507602534068634195e-08
const S6: f64 = f64::from_bits(0x3DE5_D93A_5ACF_D57C); //  1.58969099521155010221e-10

/// cos x ≈ 1 − x²/2 + C₁x⁴ + … + C₆x¹⁴ on |x| ≤ π/4 (fdlibm `__kernel_cos`).
const C1: f64 = f64::from_bits(0x3FA5_5555_5555_554C); //  4.16666666666666019037e-02
const C2: f64 = f64::from_bits(0xBF56_C16C_16C1_5177); // −1.38888888888741095749e-03
const C3: f64 = f64::from_bits(0x3EFA_01A0_19CB_1590); //  2.48015872894767294178e-05
const C4: f64 = f64::from_bits(0xBE92_7E4F_809C_52AD); // −2.75573143513906633035e-07
const C5: f64 = f64::from_bits(0x3E21_EE9E_BDB4_B1C4); //  2.08757232129817482790e-09
const C6: f64 = f64::from_bits(0xBDA8_FAE9_BE88_38D4); // −1.13596475577881948265e-11

/// π/2 = PIO2_1 + PIO2_1T + O(2⁻⁸⁸): the first 33 bits, and the next 53.
const PIO2_1: f64 = f64::from_bits(0x3FF9_21FB_5440_0000); // 1.57079632673412561417e+00
const PIO2_1T: f64 = f64::from_bits(0x3DD0_B461_1A62_6331); // 6.07710050650619224932e-11

/// R(z) = P(z)/Q(z) ≈ (asin x − x)/x with z = x², |x| ≤ ½ (fdlibm `e_asin.c`).
const PS0: f64 = f64::from_bits(0x3FC5_5555_5555_5555); //  1.66666666666666657415e-01
const PS1: f64 = f64::from_bits(0xBFD4_D612_03EB_6F7D); // −3.25565818622400915405e-01
const PS2: f64 = f64::from_bits(0x3FC9_C155_0E88_4455); //  2.01212532134862925881e-01
const PS3: f64 = f64::from_bits(0xBFA4_8228_B568_8F3B); // −4.00555345006794114027e-02
const PS4: f64 = f64::from_bits(0x3F49_EFE0_7501_B288); //  7.91534994289814532176e-04
const PS5: f64 = f64::from_bits(0x3F02_3DE1_0DFD_F709); //  3.47933107596021167570e-05
const QS1: f64 = f64::from_bits(0xC003_3A27_1C8A_2D4B); // −2.40339491173441421878e+00
const QS2: f64 = f64::from_bits(0x4000_2AE5_9C59_8AC8); //  2.02094576023350569471e+00
const QS3: f64 = f64::from_bits(0xBFE6_066C_1B8D_0159); // −6.88283971605453293030e-01
const QS4: f64 = f64::from_bits(0x3FB3_B8C5_B12E_9282); //  7.70381505559019352791e-02

/// π/2 = PIO2_HI + PIO2_LO + O(2⁻¹⁰⁶).
const PIO2_HI: f64 = f64::from_bits(0x3FF9_21FB_5444_2D18); // 1.57079632679489655800e+00
const PIO2_LO: f64 = f64::from_bits(0x3C91_A626_3314_5C07); // 6.12323399573676603587e-17

/// `R(z) = asin x / x − 1` for z = x², |x| ≤ ½ (so `asin x / x` needs no square root).
#[inline(always)]
pub(crate) fn asin_ratio(z: f64) -> f64 {
    // Estrin's scheme (pairs of coefficients combined with z², z⁴) rather than fdlibm's Horner:
    // the same polynomials with half the dependency depth, so the division starts sooner.
    let z2 = z * z;
    let z4 = z2 * z2;
    let p = z * ((PS0 + z * PS1) + z2 * (PS2 + z * PS3) + z4 * (PS4 + z * PS5));
    let q = (1.0 + z * QS1) + z2 * (QS2 + z * QS3) + z4 * QS4;
    p / q
}

/// `asin x` for |x| ≤ ½, within 1 ulp: `x + x R(x²)` (exact 0 at 0; tiny x give x).
#[inline(always)]
pub(crate) fn asin_half(x: f64) -> f64 {
    x + x * asin_ratio(x * x)
}

/// `acos x` for |x| ≤ ½, within 1 ulp: `π/2 − (x + x R(x²))` with π/2 in two parts.
#[inline(always)]
pub(crate) fn acos_half(x: f64) -> f64 {
    PIO2_HI - (x - (PIO2_LO - x * asin_ratio(x * x)))
}

/// sin(x + y) for |x| ≤ π/4, |y| ≤ ulp(x)/2 (fdlibm `__kernel_sin` with its tail y).
#[inline(always)]
fn kernel_sin(x: f64, y: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
    let v = z * x;
    x - ((z * (0.5 * y - v * r) - y) - v * S1)
}

/// cos(x + y) for |x| ≤ π/4, |y| ≤ ulp(x)/2 (fdlibm `__kernel_cos` with its tail y).
#[inline(always)]
fn kernel_cos(x: f64, y: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    w + (((1.0 - w) - hz) + (z * r - x * y))
}

/// The small angles of [`small_sin_cos`]: |x| ≤ 2⁻⁵ (a rotation by one step's angle at the
/// usual steps).
const SMALL_ANGLE: f64 = 0.03125;

/// `(sin x, cos x)` for 0 ≤ x ≤ 2⁻⁵ from their Taylor series, each within 1 ulp: the first
/// omitted terms, x⁹/9! and x⁸/8!, are below 2.5e-18 |x| and 2.3e-17 (≤ 0.2 ulp of cos); the
/// corrections are small against x and 1, so their roundings are too; cos keeps the kernel's
/// `w + ((1 − w) − x²/2)` for the rounding of 1 − x²/2. Half the flops of the kernels.
#[inline(always)]
fn small_sin_cos(x: f64) -> (f64, f64) {
    let z = x * x;
    let v = z * x;
    let sin = x + v * (-1.0 / 6.0 + z * (1.0 / 120.0 + z * (-1.0 / 5040.0)));
    let r = z * (1.0 / 24.0 + z * (-1.0 / 720.0 + z * (1.0 / 40320.0)));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    (sin, w + (((1.0 - w) - hz) + z * r))
}

/// `(sin h/(2h), cos h)` from z = h² alone, for |h| ≤ π/4 (z ≤ π²/16): the kernels divided by
/// x, `sin h/h = 1 + z (S₁ + z r(z))`, so that `So3::exp` needs neither √(θ²) nor 1/θ for
/// θ = 2h ≤ π/2. Within 2 ulp of `sin h/(2h)` and 1 ulp of `cos h`.
#[inline(always)]
pub(crate) fn half_sinc_cos(z: f64) -> (f64, f64) {
    let w = z * z;
    let rs = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
    let half_sinc = 0.5 + 0.5 * (z * (S1 + z * rs));
    let rc = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    let hz = 0.5 * z;
    let wc = 1.0 - hz;
    (half_sinc, wc + (((1.0 - wc) - hz) + z * rc))
}

/// `(sin x, cos x)` for x ∈ [0, π/2], each within 1 ulp, without a call; other x (negative,
/// beyond π/2, NaN) go to libm's `sin_cos` out of line.
#[inline(always)]
pub(crate) fn sin_cos_quadrant(x: f64) -> (f64, f64) {
    use core::f64::consts::{FRAC_PI_2, FRAC_PI_4};
    if (0.0..=SMALL_ANGLE).contains(&x) {
        small_sin_cos(x)
    } else if x > SMALL_ANGLE && x <= FRAC_PI_4 {
        (kernel_sin(x, 0.0), kernel_cos(x, 0.0))
    } else if x > FRAC_PI_4 && x <= FRAC_PI_2 {
        // r = π/2 − x = r0 + r1 with |r| ≤ π/4: sin x = cos r, cos x = sin r.
        let z = PIO2_1 - x; // exact (Sterbenz)
        let r0 = z + PIO2_1T;
        let r1 = (z - r0) + PIO2_1T;
        (kernel_cos(r0, r1), kernel_sin(r0, r1))
    } else {
        sin_cos_libm(x)
    }
}

/// `(sin x, cos x)` for any x, each within 1 ulp: Taylor series of half the kernels' length for
/// |x| ≤ 2⁻⁵ and the fdlibm kernels up to |x| ≤ π/2 (the common case of a rotation by one step's
/// angle), without a libm call; libm's `sin_cos` beyond.
#[inline(always)]
pub fn sin_cos(x: f64) -> (f64, f64) {
    if x >= 0.0 {
        sin_cos_quadrant(x)
    } else {
        let (s, c) = sin_cos_quadrant(-x);
        (-s, c)
    }
}

#[cold]
#[inline(never)]
fn sin_cos_libm(x: f64) -> (f64, f64) {
    x.sin_cos()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distance in units in the last place between two finite doubles of the same sign.
    fn ulps(a: f64, b: f64) -> u64 {
        (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
    }

    /// The public `sin_cos`: odd and even symmetry on negative angles, libm beyond π/2, NaN kept.
    #[test]
    fn sin_cos_matches_libm_on_every_sign_and_range() {
        for x in [
            -1e-300,
            -0.3,
            -1.2,
            -core::f64::consts::FRAC_PI_2,
            0.7,
            2.0,
            -3.0,
            1e6,
            -1e6,
        ] {
            let (s, c) = sin_cos(x);
            let (s0, c0) = x.sin_cos();
            assert!(
                (s - s0).abs() <= 2.0 * f64::EPSILON * s0.abs()
                    && (c - c0).abs() <= 2.0 * f64::EPSILON,
                "{x}: ({s}, {c}) against ({s0}, {c0})"
            );
        }
        assert!(sin_cos(f64::NAN).0.is_nan() && sin_cos(f64::INFINITY).1.is_nan());
    }

    #[test]
    fn kernels_match_libm_within_one_ulp_on_the_quadrant() {
        // 2·10⁶ points on [0, π/2] (plus the end points and both sides of π/4); glibc's sin
        // and cos are correctly rounded in practice, so 1 ulp here is the kernels' own bound.
        let n = 2_000_000;
        let mut worst = (0u64, 0u64);
        let mut xs: Vec<f64> = (0..=n)
            .map(|i| core::f64::consts::FRAC_PI_2 * i as f64 / n as f64)
            .collect();
        let q = core::f64::consts::FRAC_PI_4;
        xs.extend([
            q,
            f64::from_bits(q.to_bits() + 1),
            f64::from_bits(q.to_bits() - 1),
            core::f64::consts::FRAC_PI_2,
            f64::from_bits(core::f64::consts::FRAC_PI_2.to_bits() - 1),
            1e-300,
            1e-8,
        ]);
        for x in xs {
            let (s, c) = sin_cos_quadrant(x);
            let (s0, c0) = x.sin_cos();
            worst.0 = worst.0.max(ulps(s, s0));
            // cos near π/2 is tiny: there the absolute error (≤ 1e-26 from the reduction plus
            // 1 ulp) is what matters, so compare in ulps of the result only where cos x ≥ 1e-8.
            if c0 >= 1e-8 {
                worst.1 = worst.1.max(ulps(c, c0));
            } else {
                assert!((c - c0).abs() <= 1e-24, "x = {x:e}: cos {c:e} vs {c0:e}");
            }
        }
        assert!(
            worst.0 <= 1 && worst.1 <= 1,
            "worst ulps (sin, cos) = {worst:?}"
        );
    }

    /// The small-angle series, densely on [0, 2⁻⁵] and at both sides of its end.
    #[test]
    fn small_angles_match_libm_within_one_ulp() {
        let n = 1_000_000;
        let mut worst = (0u64, 0u64);
        let mut xs: Vec<f64> = (0..=n).map(|i| SMALL_ANGLE * i as f64 / n as f64).collect();
        xs.extend([
            f64::from_bits(SMALL_ANGLE.to_bits() + 1),
            f64::from_bits(SMALL_ANGLE.to_bits() - 1),
            5e-324,
            1e-200,
            1e-9,
        ]);
        for x in xs {
            let (s, c) = sin_cos_quadrant(x);
            let (s0, c0) = x.sin_cos();
            worst = (worst.0.max(ulps(s, s0)), worst.1.max(ulps(c, c0)));
        }
        assert!(
            worst.0 <= 1 && worst.1 <= 1,
            "worst ulps (sin, cos) = {worst:?}"
        );
    }

    #[test]
    fn asin_and_acos_match_libm_within_one_ulp_on_half_interval() {
        let n = 2_000_000;
        let mut worst = (0u64, 0u64);
        let mut xs: Vec<f64> = (0..=n).map(|i| -0.5 + i as f64 / n as f64).collect();
        xs.extend([0.0, -0.0, 1e-300, 1e-20, 1e-8, 0.5, -0.5]);
        for x in xs {
            let (a, a0) = (asin_half(x), x.asin());
            if a0 == 0.0 {
                assert_eq!(a, 0.0);
            } else {
                worst.0 = worst.0.max(ulps(a, a0));
            }
            worst.1 = worst.1.max(ulps(acos_half(x), x.acos()));
        }
        assert!(
            worst.0 <= 1 && worst.1 <= 1,
            "worst ulps (asin, acos) = {worst:?}"
        );
    }

    #[test]
    fn half_sinc_cos_matches_libm_from_the_square_alone() {
        let n = 1_000_000;
        let mut worst = (0u64, 0u64);
        for i in 1..=n {
            let h = core::f64::consts::FRAC_PI_4 * i as f64 / n as f64;
            let (q, c) = half_sinc_cos(h * h);
            // h·h is rounded: compare with the h that z represents, √z (≤ ½ ulp of h away).
            let hz = (h * h).sqrt();
            worst.0 = worst.0.max(ulps(q, hz.sin() / (2.0 * hz)));
            worst.1 = worst.1.max(ulps(c, hz.cos()));
        }
        assert_eq!(half_sinc_cos(0.0), (0.5, 1.0));
        // libm's sin h/(2h) is itself two roundings from the exact ratio
        assert!(
            worst.0 <= 2 && worst.1 <= 1,
            "worst ulps (sin h/2h, cos h) = {worst:?}"
        );
    }

    #[test]
    fn outside_the_quadrant_falls_back_to_libm() {
        for x in [-0.5, 2.0, 3.0, 10.0, 1e6] {
            assert_eq!(sin_cos_quadrant(x), x.sin_cos());
        }
        let (s, c) = sin_cos_quadrant(f64::NAN);
        assert!(s.is_nan() && c.is_nan());
        let (s, c) = sin_cos_quadrant(f64::INFINITY);
        assert!(s.is_nan() && c.is_nan());
    }
}
