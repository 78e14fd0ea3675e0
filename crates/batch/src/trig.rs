//! `sin` and `cos` of every lane at once, and the coefficients of the Rodrigues formula, without a
//! branch on a lane's value (a lane-wise select instead), so that each lane's bits depend on its
//! own argument alone.
//!
//! **Polynomials.** The fdlibm kernels `__kernel_sin` / `__kernel_cos` (Sun Microsystems, 1993,
//! as kept in musl's `__sin.c` / `__cos.c`: "Permission to use, copy, modify, and distribute this
//! software is freely granted, provided that this notice is preserved"): minimax fits on
//! |r| ≤ π/4 with approximation errors below 2⁻⁵⁸, evaluated here by Horner's rule in fused
//! multiply-adds (the same coefficients as `lie_groups`' scalar `sin_cos`). Where
//! |r| ≤ [`SHORT_KERNEL_LIMIT`] = 1/16 (every turn and Rodrigues half angle of a usual step) the
//! kernels stop two terms (sin) and three terms (cos) early: what they drop is below 0.003 ulp
//! there, five fused multiply-adds fewer per sin/cos pair.
//!
//! **Reduction.** `n = rint(x · 2/π)` (by adding and subtracting 1.5·2⁵², exact for
//! |x · 2/π| < 2⁵¹) and `r = x − n·π/2` with π/2 = P₁ + P₂ + P₃ split in three doubles (Cody–Waite
//! with fused multiply-adds): `fma(−n, P₁, x)` is exact (x − nP₁ is a multiple of 2⁻⁵³ below 1 in
//! magnitude), the two later terms round once each, so r carries a relative error of about two
//! roundings while |n P₃| stays far below the smallest |r| a double reaches, which holds for
//! |x| ≤ [`REDUCTION_LIMIT`] = 2²⁸. The quadrant n mod 4 then swaps and negates the kernels.
//! Beyond the limit (and for ±∞, NaN) the result is NaN: a body whose step turns it by more than
//! 2²⁸ rad about one axis fails (its status says so) instead of being handed to libm — a call
//! in the middle of the step would make the compiler keep the whole state in memory around it.
//! The scalar library takes libm there; no physical step turns a body 4·10⁷ times.
//!
//! **Accuracy** (test `sin_cos_matches_libm_over_the_whole_range`): within 1 ulp of glibc's
//! (correctly rounded in practice) sin and cos on [−2²⁸, 2²⁸], sampled densely near 0, on the
//! short kernels' range and on [−2π, 2π], within 3 ulps of the multiples of π/2 up to 1000π, and
//! logarithmically from 10⁻³⁰⁰ to 2²⁸; sin(±0) = ±0.
//!
//! **One path, every width.** A lane's kernels follow from its own argument: the short ones for
//! |x| ≤ 1/16, the full ones on x itself up to π/4 (where n = 0), the full ones on the reduced
//! argument beyond. A vector whose lanes all take the short ones evaluates only those, one whose
//! lanes all have n = 0 only the full ones on x; on the other paths the lanes with n = 0 take x
//! itself as the reduced argument (a select, and the quadrant step leaves them alone) and the
//! short lanes their short kernels (a select), so a lane's bits are the same whichever path its
//! neighbours sent the vector on (tests `a_lane_does_not_depend_on_its_neighbours`,
//! `the_short_kernels_do_not_depend_on_the_neighbours`).
//!
//! **atan** ([`atan_lane`]): fdlibm's `s_atan.c` (Sun Microsystems, 1993, as kept in musl and the
//! `libm` crate; the notice above), made branch-free. |x| is reduced to |r| ≤ 7/16 by one of
//! `atan x = atan c + atan((x − c)/(1 + cx))` for c = 0, ½, 1, 3/2, ∞ (breakpoints 7/16, 11/16,
//! 19/16, 39/16), the reduced argument formed as one quotient whose numerator and denominator
//! each lane selects, then `atan r ≈ r − r³ P(r²)`, P of degree 10 (fdlibm's minimax fit), and
//! `atan c` added as a head and a tail (hi + lo, far below an ulp from atan c); below 2⁻²⁷
//! atan x = x (±0 and subnormals kept). Each lane performs fdlibm's operations for
//! its own x, so the result is fdlibm's bit for bit, below 1 ulp of the true value. **Accuracy**
//! (test `atan_matches_libm_over_the_whole_range`): within 1 ulp of glibc's atan (correctly
//! rounded in practice) from 10⁻³⁰⁰ to 10³⁰⁰, both signs, densely on [−4, 4] and a few ulps about
//! each breakpoint; atan(±∞) = ±π/2 rounded, NaN gives NaN.

use crate::lanes::{k, F, M};
use crate::{BatchError, Level};
use pulp::{Simd, WithSimd};

/// sin r ≈ r + S₁r³ + … + S₆r¹³ on |r| ≤ π/4 (fdlibm `__kernel_sin`).
pub(crate) const S1: f64 = f64::from_bits(0xBFC5_5555_5555_5549);
pub(crate) const S2: f64 = f64::from_bits(0x3F81_1111_1110_F8A6);
pub(crate) const S3: f64 = f64::from_bits(0xBF2A_01A0_19C1_61D5);
pub(crate) const S4: f64 = f64::from_bits(0x3EC7_1DE3_57B1_FE7D);
pub(crate) const S5: f64 = f64::from_bits(0xBE5A_E5E6_8A2B_9CEB);
pub(crate) const S6: f64 = f64::from_bits(0x3DE5_D93A_5ACF_D57C);
/// cos r ≈ 1 − r²/2 + C₁r⁴ + … + C₆r¹⁴ on |r| ≤ π/4 (fdlibm `__kernel_cos`).
pub(crate) const C1: f64 = f64::from_bits(0x3FA5_5555_5555_554C);
pub(crate) const C2: f64 = f64::from_bits(0xBF56_C16C_16C1_5177);
pub(crate) const C3: f64 = f64::from_bits(0x3EFA_01A0_19CB_1590);
pub(crate) const C4: f64 = f64::from_bits(0xBE92_7E4F_809C_52AD);
pub(crate) const C5: f64 = f64::from_bits(0x3E21_EE9E_BDB4_B1C4);
pub(crate) const C6: f64 = f64::from_bits(0xBDA8_FAE9_BE88_38D4);

/// 2/π rounded.
const INV_PIO2: f64 = f64::from_bits(0x3FE4_5F30_6DC9_C883);
/// π/2 = P₁ + P₂ + P₃ + O(2⁻¹⁶⁰): π/2 rounded, then the roundings of the remainders.
const P1: f64 = f64::from_bits(0x3FF9_21FB_5444_2D18);
const P2: f64 = f64::from_bits(0x3C91_A626_3314_5C07);
const P3: f64 = f64::from_bits(0xB91F_1976_B7ED_8FBC);
/// 1.5·2⁵²: `(t + ROUNDER) − ROUNDER` rounds |t| < 2⁵¹ to the nearest integer (ties to even), and
/// the low bits of `t + ROUNDER` are that integer modulo 2⁵¹ (two's complement for t < 0).
const ROUNDER: f64 = 6_755_399_441_055_744.0;

/// 2⁻²⁷: below it sin r = r to within half an ulp.
const TINY: f64 = 7.450_580_596_923_828e-9;

/// |x| up to which the lanes reduce the argument themselves; beyond, libm does (see the module
/// page).
pub const REDUCTION_LIMIT: f64 = 268_435_456.0;

/// |r| up to which the kernels drop their highest terms: sin r ≈ r + S₁r³ + … + S₄r⁹ and
/// cos r ≈ 1 − r²/2 + C₁r⁴ + C₂r⁶ + C₃r⁸. The terms dropped, S₅r¹¹ + S₆r¹³ and C₄r¹⁰ + …, are
/// below 3·10⁻⁴ ulp of sin r and 3·10⁻³ ulp of cos r there (|S₅| r¹⁰ < 2.3·10⁻²⁰ relative,
/// |C₄| r¹⁰ < 2.6·10⁻¹⁹, an ulp at least 1.1·10⁻¹⁶ relative), so the short kernels are as
/// accurate as the full ones.
pub const SHORT_KERNEL_LIMIT: f64 = 0.0625;

/// `(sin r, cos r)` for |r| ≤ π/4 (a little beyond is harmless: the kernels' error grows
/// slowly); with `SHORT`, for |r| ≤ [`SHORT_KERNEL_LIMIT`] by the short polynomials.
#[inline(always)]
fn kernels<S: Simd, const SHORT: bool>(r: F<S>) -> (F<S>, F<S>) {
    let s = r.s;
    let z = r * r;
    let sin = (z * r).mul_add(z.mul_add(sin_tail::<S, SHORT>(z), k(s, S1)), r);
    // Below 2⁻²⁷, sin r = r correctly rounded; taking r there also keeps sin(−0) = −0 (the sum
    // above gives +0).
    let tiny = r.abs().lt(k(s, TINY));
    (tiny.select(r, sin), cos_kernel::<S, SHORT>(z))
}

/// `S₂ + S₃z + … + S₆z⁴` (with `SHORT`, up to S₄z²) by Horner's rule in fused multiply-adds.
#[inline(always)]
fn sin_tail<S: Simd, const SHORT: bool>(z: F<S>) -> F<S> {
    let s = z.s;
    let high = if SHORT {
        k(s, S4)
    } else {
        z.mul_add(z.mul_add(k(s, S6), k(s, S5)), k(s, S4))
    };
    z.mul_add(z.mul_add(high, k(s, S3)), k(s, S2))
}

/// `cos r` from z = r² for |r| ≤ π/4 (with `SHORT`, |r| ≤ [`SHORT_KERNEL_LIMIT`], the terms up
/// to C₃r⁸): `w + ((1 − w − r²/2) + r⁴ C(r²))`, w = 1 − r²/2, the rounding of w carried as in
/// fdlibm.
#[inline(always)]
fn cos_kernel<S: Simd, const SHORT: bool>(z: F<S>) -> F<S> {
    let s = z.s;
    let high = if SHORT {
        k(s, C3)
    } else {
        z.mul_add(z.mul_add(z.mul_add(k(s, C6), k(s, C5)), k(s, C4)), k(s, C3))
    };
    let pc = z.mul_add(z.mul_add(high, k(s, C2)), k(s, C1));
    let hz = z * 0.5;
    let w = k(s, 1.0) - hz;
    let tail = (k(s, 1.0) - w) - hz;
    w + (z * z).mul_add(pc, tail)
}

/// `(sin x, cos x)` of every lane (module page: accuracy, range, NaN beyond it).
#[inline(always)]
pub(crate) fn sin_cos<S: Simd>(x: F<S>) -> (F<S>, F<S>) {
    let s = x.s;
    let ax = x.abs();
    // Every lane within the short kernels' range (false for NaN): they are the result.
    let short = ax.le(k(s, SHORT_KERNEL_LIMIT));
    if short.all() {
        return kernels::<S, true>(x);
    }
    let (sin, cos) = sin_cos_full(x, ax);
    // The lanes within the short kernels' range take them on every path.
    if short.any() {
        let (ss, sc) = kernels::<S, true>(x);
        return (short.select(ss, sin), short.select(sc, cos));
    }
    (sin, cos)
}

/// [`sin_cos`] with the full kernels (`ax` = |x|).
#[inline(always)]
fn sin_cos_full<S: Simd>(x: F<S>, ax: F<S>) -> (F<S>, F<S>) {
    let s = x.s;
    // n = 0 (below) exactly where |x| ≤ π/4 rounded: fl(x · 2/π) ≤ ½ there, and above ½ at the
    // next double. Every lane there (false for NaN, ±∞): nothing to reduce, nothing out of
    // range, so the kernels on x are the result.
    if ax.le(k(s, core::f64::consts::FRAC_PI_4)).all() {
        return kernels::<S, false>(x);
    }
    let nb = x * INV_PIO2 + ROUNDER;
    let n = nb - ROUNDER;
    let zero = k(s, 0.0);
    let r = n.mul_add(k(s, -P1), x);
    let r = n.mul_add(k(s, -P2), r);
    let r = n.mul_add(k(s, -P3), r);
    // Lanes with n = 0 take x itself: the same bits as the path without reduction (the
    // terms above would turn x = −0 into +0, P₃ being negative).
    let r = n.eq(zero).select(x, r);
    let (ks, kc) = kernels::<S, false>(r);
    // n mod 4: odd quadrants swap sin and cos; sin is negated in quadrants 2, 3 and cos in
    // 1, 2.
    let even = nb.bits_clear(1);
    let (sa, ca) = (even.select(ks, kc), even.select(kc, ks));
    let q_low = nb.bits_clear(2);
    let q_next = (nb + 1.0).bits_clear(2);
    let (sin, cos) = (q_low.select(sa, -sa), q_next.select(ca, -ca));
    // Beyond the reduction's range (and for ±∞, NaN): NaN, so that the body fails there.
    let wild = ax.le(k(s, REDUCTION_LIMIT)).not();
    let nan = k(s, f64::NAN);
    (wild.select(nan, sin), wild.select(nan, cos))
}

// |x| ≤ π/4 rounded is where the reduction's n = rint(fl(x · 2/π)) is 0 (ties to even at ½).
const _: () = assert!(
    core::f64::consts::FRAC_PI_4 * INV_PIO2 <= 0.5
        && f64::from_bits(core::f64::consts::FRAC_PI_4.to_bits() + 1) * INV_PIO2 > 0.5
);

/// `(q, cos h)` of [`rodrigues_coefficients`] from z = h² (|h| ≤ π/4), `q = ½ sin h/h`:
/// the fdlibm kernels as polynomials in z (with `SHORT`, |h| ≤ [`SHORT_KERNEL_LIMIT`]).
#[inline(always)]
fn half_angle<S: Simd, const SHORT: bool>(z: F<S>) -> (F<S>, F<S>) {
    let s = z.s;
    let q = z.mul_add(z.mul_add(sin_tail::<S, SHORT>(z), k(s, S1)), k(s, 1.0)) * 0.5;
    (q, cos_kernel::<S, SHORT>(z))
}

/// The Rodrigues coefficients `(a, b) = (sin θ/θ, (1 − cos θ)/θ²)` of `exp(ω) = I + aω̂ + bω̂²`
/// from θ² = |ω|² alone, lane by lane: with h = θ/2, `a = 2q cos h`, `b = 2q²`, `q = sin h/θ`
/// (products only: no cancellation at any θ, as in `lie_groups::So3::exp`).
///
/// For θ ≤ π/2 (h ≤ π/4, every lane of a usual step) `q = ½ sin h/h` and `cos h` are the fdlibm
/// kernels as polynomials in h² = θ²/4 — no square root, no division, exact at θ = 0 (a = 1,
/// b = ½) — the short ones where h ≤ [`SHORT_KERNEL_LIMIT`]. Only if some lane is beyond π/2 is
/// `q = sin h/θ` formed with √ and ÷ (and taken for those lanes alone). A non-finite θ² gives
/// NaN.
#[inline(always)]
pub(crate) fn rodrigues_coefficients<S: Simd>(t2: F<S>) -> (F<S>, F<S>) {
    let s = t2.s;
    let z = t2 * 0.25;
    let short = z.le(k(s, SHORT_KERNEL_LIMIT * SHORT_KERNEL_LIMIT));
    let (q, ch) = if short.all() {
        half_angle::<S, true>(z)
    } else {
        let (q, ch) = half_angle::<S, false>(z);
        let near = z.le(k(
            s,
            core::f64::consts::FRAC_PI_4 * core::f64::consts::FRAC_PI_4,
        ));
        let (q, ch) = if near.not().any() {
            let t = t2.sqrt();
            let (sh, chg) = sin_cos(t * 0.5);
            (near.select(q, sh / t), near.select(ch, chg))
        } else {
            (q, ch)
        };
        if short.any() {
            let (qs, cs) = half_angle::<S, true>(z);
            (short.select(qs, q), short.select(cs, ch))
        } else {
            (q, ch)
        }
    };
    let q2 = q + q;
    (q2 * ch, q2 * q)
}

/// The lanes' `sin_cos` over slices on a given level: `sin[i], cos[i] = sin_cos(x[i])`, the last vector
/// padded. The lane kernel made callable on its own, for its tests against libm.
///
/// Errors: unequal lengths, or a level this CPU lacks.
pub fn sin_cos_slices(
    level: Level,
    x: &[f64],
    sin: &mut [f64],
    cos: &mut [f64],
) -> Result<(), BatchError> {
    struct SinCos;
    impl PairKernel for SinCos {
        const NAMES: [&'static str; 2] = ["sin", "cos"];
        #[inline(always)]
        fn apply<S: Simd>(x: F<S>) -> (F<S>, F<S>) {
            sin_cos(x)
        }
    }
    map_pairs::<SinCos>(level, x, sin, cos)
}

/// The lanes' Rodrigues coefficients over slices on a given level: `a[i], b[i]` are
/// [`rodrigues_coefficients_lane`]`(t2[i])`, the last vector padded. Made callable on its own
/// for its tests (a lane's bits whatever its neighbours). Errors: unequal lengths, or a level
/// this CPU lacks.
pub fn rodrigues_coefficients_slices(
    level: Level,
    t2: &[f64],
    a: &mut [f64],
    b: &mut [f64],
) -> Result<(), BatchError> {
    struct Rodrigues;
    impl PairKernel for Rodrigues {
        const NAMES: [&'static str; 2] = ["a", "b"];
        #[inline(always)]
        fn apply<S: Simd>(t2: F<S>) -> (F<S>, F<S>) {
            rodrigues_coefficients(t2)
        }
    }
    map_pairs::<Rodrigues>(level, t2, a, b)
}

/// A lane kernel of one argument and two results, for [`map_pairs`].
trait PairKernel {
    /// The names of the two results, for a length error.
    const NAMES: [&'static str; 2];
    fn apply<S: Simd>(x: F<S>) -> (F<S>, F<S>);
}

/// `(p[i], q[i]) = K::apply(x[i])` vector by vector on `level`, the last vector padded.
/// Errors: unequal lengths, or a level this CPU lacks.
fn map_pairs<K: PairKernel>(
    level: Level,
    x: &[f64],
    p: &mut [f64],
    q: &mut [f64],
) -> Result<(), BatchError> {
    for (what, len) in K::NAMES.into_iter().zip([p.len(), q.len()]) {
        if len != x.len() {
            return Err(BatchError::LengthMismatch {
                what,
                got: len,
                expected: x.len(),
            });
        }
    }
    struct Op<'a, K>(
        &'a [f64],
        &'a mut [f64],
        &'a mut [f64],
        core::marker::PhantomData<K>,
    );
    impl<K: PairKernel> WithSimd for Op<'_, K> {
        type Output = ();
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) {
            let w = S::F64_LANES;
            for ((x, p), q) in self
                .0
                .chunks(w)
                .zip(self.1.chunks_mut(w))
                .zip(self.2.chunks_mut(w))
            {
                let (a, b) = K::apply(F::load(s, x));
                a.store(p);
                b.store(q);
            }
        }
    }
    level.dispatch(Op::<K>(x, p, q, core::marker::PhantomData))
}

/// `(sin x, cos x)` on one lane: the bits every lane of every level computes for x (the scalar
/// reference of the batch kernels; within 1 ulp of libm up to 2²⁸, NaN beyond: module page).
pub fn sin_cos_lane(x: f64) -> (f64, f64) {
    let (s, c) = sin_cos(F::splat(pulp::Scalar, x));
    (s.v, c.v)
}

/// The Rodrigues coefficients `(sin θ/θ, (1 − cos θ)/θ²)` from θ² on one lane, as every lane
/// computes them.
pub fn rodrigues_coefficients_lane(t2: f64) -> (f64, f64) {
    let (a, b) = rodrigues_coefficients(F::splat(pulp::Scalar, t2));
    (a.v, b.v)
}

/// atan of the fdlibm breakpoints c = ½, 1, 3/2, ∞: heads (rounded) and tails.
const ATAN_HI: [f64; 4] = [
    f64::from_bits(0x3FDD_AC67_0561_BB4F),
    f64::from_bits(0x3FE9_21FB_5444_2D18),
    f64::from_bits(0x3FEF_730B_D281_F69B),
    f64::from_bits(0x3FF9_21FB_5444_2D18),
];
const ATAN_LO: [f64; 4] = [
    f64::from_bits(0x3C7A_2B7F_222F_65E2),
    f64::from_bits(0x3C81_A626_3314_5C07),
    f64::from_bits(0x3C70_0788_7AF0_CBBD),
    f64::from_bits(0x3C91_A626_3314_5C07),
];
/// atan r ≈ r − r·(z·P_even(z²) + z²·P_odd(z²)), z = r² (fdlibm `aT`).
const AT: [f64; 11] = [
    f64::from_bits(0x3FD5_5555_5555_550D),
    f64::from_bits(0xBFC9_9999_9998_EBC4),
    f64::from_bits(0x3FC2_4924_9200_83FF),
    f64::from_bits(0xBFBC_71C6_FE23_1671),
    f64::from_bits(0x3FB7_45CD_C54C_206E),
    f64::from_bits(0xBFB3_B0F2_AF74_9A6D),
    f64::from_bits(0x3FB1_0D66_A0D0_3D51),
    f64::from_bits(0xBFAD_DE2D_52DE_FD9A),
    f64::from_bits(0x3FA9_7B4B_2476_0DEB),
    f64::from_bits(0xBFA2_B444_2C6A_6C2F),
    f64::from_bits(0x3F90_AD3A_E322_DA11),
];

/// `t[j]` in the lanes of interval j (the last one that holds of i3, i2, i1; else t[0]).
#[inline(always)]
fn by_interval<S: Simd>(i3: M<S>, i2: M<S>, i1: M<S>, t: [f64; 4]) -> F<S> {
    let s = i3.s;
    i3.select(
        k(s, t[3]),
        i2.select(k(s, t[2]), i1.select(k(s, t[1]), k(s, t[0]))),
    )
}

/// `atan x` of every lane (module page: fdlibm's operations, branch-free; within 1 ulp of libm,
/// NaN for NaN).
#[inline(always)]
pub(crate) fn atan<S: Simd>(x: F<S>) -> F<S> {
    let s = x.s;
    let ax = x.abs();
    // The interval of |x| (false for NaN: it takes the unreduced path and stays NaN).
    let i3 = k(s, 2.4375).le(ax);
    let i2 = k(s, 1.1875).le(ax);
    let i1 = k(s, 0.6875).le(ax);
    let i0 = k(s, 0.4375).le(ax);
    // r = num/den: −1/|x|, (|x| − 1.5)/(1 + 1.5|x|), (|x| − 1)/(|x| + 1), (2|x| − 1)/(2 + |x|),
    // or |x|/1 = |x| exactly.
    let num = i3.select(
        k(s, -1.0),
        i2.select(ax - 1.5, i1.select(ax - 1.0, i0.select(ax * 2.0 - 1.0, ax))),
    );
    let den = i3.select(
        ax,
        i2.select(
            k(s, 1.0) + ax * 1.5,
            i1.select(ax + 1.0, i0.select(k(s, 2.0) + ax, k(s, 1.0))),
        ),
    );
    let r = num / den;
    let (hi, lo) = (
        by_interval(i3, i2, i1, ATAN_HI),
        by_interval(i3, i2, i1, ATAN_LO),
    );
    let z = r * r;
    let w = z * z;
    let s1 = z
        * (k(s, AT[0])
            + w * (k(s, AT[2])
                + w * (k(s, AT[4]) + w * (k(s, AT[6]) + w * (k(s, AT[8]) + w * AT[10])))));
    let s2 =
        w * (k(s, AT[1]) + w * (k(s, AT[3]) + w * (k(s, AT[5]) + w * (k(s, AT[7]) + w * AT[9]))));
    let sum = s1 + s2;
    let reduced = hi - ((r * sum - lo) - r);
    let direct = r - r * sum;
    let z = i0.select(reduced, direct).copysign(x);
    // Below 2⁻²⁷ atan x = x correctly rounded (±0 and subnormals kept).
    ax.lt(k(s, TINY)).select(x, z)
}

/// The lanes' `atan` over slices on a given level (`out[i] = atan(x[i])`), the kernel made
/// callable on its own for its tests against libm. Errors: unequal lengths, or a level this CPU
/// lacks.
pub fn atan_slices(level: Level, x: &[f64], out: &mut [f64]) -> Result<(), BatchError> {
    if out.len() != x.len() {
        return Err(BatchError::LengthMismatch {
            what: "atan",
            got: out.len(),
            expected: x.len(),
        });
    }
    struct Op<'a>(&'a [f64], &'a mut [f64]);
    impl WithSimd for Op<'_> {
        type Output = ();
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) {
            let w = S::F64_LANES;
            for (x, o) in self.0.chunks(w).zip(self.1.chunks_mut(w)) {
                atan(F::load(s, x)).store(o);
            }
        }
    }
    level.dispatch(Op(x, out))
}

/// `atan x` on one lane: the bits every lane of every level computes for x.
pub fn atan_lane(x: f64) -> f64 {
    atan(F::splat(pulp::Scalar, x)).v
}
