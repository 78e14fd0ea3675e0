//! A vector of f64 lanes over a pulp instruction set, with the arithmetic operators, so that the
//! kernels read as the scalar formulas they implement.
//!
//! Every operation is lane-wise and IEEE 754: `+ − × ÷ √` are correctly rounded, and
//! [`F::mul_add`] is the fused multiply-add (one rounding) on every level, the scalar one
//! included (pulp's `Scalar` calls `f64::mul_add`). Nothing is left to the compiler: Rust does not
//! contract `a * b + c` into an FMA, so a formula written here rounds the same way in each lane of
//! each level — which is what makes a body's bits independent of its lane, the batch size and the
//! instruction set. No operation reads a neighbouring lane.

use core::ops::{Add, Div, Mul, Neg, Sub};
use pulp::Simd;

/// One vector of f64 lanes (1, 4 or 8 of them) of the instruction set `S`.
#[derive(Clone, Copy, Debug)]
pub struct F<S: Simd> {
    pub(crate) s: S,
    pub(crate) v: S::f64s,
}

/// A lane mask of the instruction set `S`.
#[derive(Clone, Copy, Debug)]
pub struct M<S: Simd> {
    pub(crate) s: S,
    pub(crate) m: S::m64s,
}

impl<S: Simd> F<S> {
    /// Every lane `x`.
    #[inline(always)]
    pub fn splat(s: S, x: f64) -> Self {
        Self {
            s,
            v: s.splat_f64s(x),
        }
    }
    /// The lanes of `lanes[..S::F64_LANES]`; missing entries (a shorter slice) are 0.
    #[inline(always)]
    pub fn load(s: S, lanes: &[f64]) -> Self {
        let w = S::F64_LANES;
        if lanes.len() >= w {
            // A fixed-size read: one unaligned vector load.
            return Self {
                s,
                v: bytemuck::pod_read_unaligned(bytemuck::cast_slice(&lanes[..w])),
            };
        }
        let mut v: S::f64s = bytemuck::Zeroable::zeroed();
        let dst: &mut [f64] = bytemuck::cast_slice_mut(core::slice::from_mut(&mut v));
        dst[..lanes.len()].copy_from_slice(lanes);
        Self { s, v }
    }
    /// Writes the first `out.len()` lanes (at most all of them) to `out`.
    #[inline(always)]
    pub fn store(self, out: &mut [f64]) {
        let src: &[f64] = bytemuck::cast_slice(core::slice::from_ref(&self.v));
        let w = S::F64_LANES;
        if out.len() >= w {
            // A fixed-size write: one unaligned vector store.
            out[..w].copy_from_slice(&src[..w]);
            return;
        }
        let n = out.len();
        out.copy_from_slice(&src[..n]);
    }
    /// The lanes as an array view.
    #[inline(always)]
    pub fn lanes(&self) -> &[f64] {
        bytemuck::cast_slice(core::slice::from_ref(&self.v))
    }
    /// `self · b + c` with one rounding (fused multiply-add).
    #[inline(always)]
    pub fn mul_add(self, b: Self, c: Self) -> Self {
        Self {
            s: self.s,
            v: self.s.mul_add_f64s(self.v, b.v, c.v),
        }
    }
    /// `√self`, correctly rounded.
    #[inline(always)]
    pub fn sqrt(self) -> Self {
        Self {
            s: self.s,
            v: self.s.sqrt_f64s(self.v),
        }
    }
    /// `|self|` (clears the sign bit).
    #[inline(always)]
    pub fn abs(self) -> Self {
        Self {
            s: self.s,
            v: self.s.abs_f64s(self.v),
        }
    }
    /// The larger of the two, lane by lane (for finite lanes, as `f64::max`).
    #[inline(always)]
    pub fn max(self, b: Self) -> Self {
        Self {
            s: self.s,
            v: self.s.max_f64s(self.v, b.v),
        }
    }
    /// Lanes where `self < b` (false for NaN).
    #[inline(always)]
    pub fn lt(self, b: Self) -> M<S> {
        M {
            s: self.s,
            m: self.s.less_than_f64s(self.v, b.v),
        }
    }
    /// Lanes where `self <= b` (false for NaN).
    #[inline(always)]
    pub fn le(self, b: Self) -> M<S> {
        M {
            s: self.s,
            m: self.s.less_than_or_equal_f64s(self.v, b.v),
        }
    }
    /// Lanes where `self == b` (false for NaN).
    #[inline(always)]
    pub fn eq(self, b: Self) -> M<S> {
        M {
            s: self.s,
            m: self.s.equal_f64s(self.v, b.v),
        }
    }
    /// |self| with the sign of `sign` (bit operations: exact, NaN kept).
    #[inline(always)]
    pub fn copysign(self, sign: Self) -> Self {
        let s = self.s;
        let magnitude = s.and_u64s(s.transmute_u64s_f64s(self.v), s.splat_u64s(!(1 << 63)));
        let sign = s.and_u64s(s.transmute_u64s_f64s(sign.v), s.splat_u64s(1 << 63));
        Self {
            s,
            v: s.transmute_f64s_u64s(s.or_u64s(magnitude, sign)),
        }
    }
    /// Lanes whose bits, as an unsigned integer, have `bits & mask == 0`.
    #[inline(always)]
    pub fn bits_clear(self, mask: u64) -> M<S> {
        let s = self.s;
        let u = s.and_u64s(s.transmute_u64s_f64s(self.v), s.splat_u64s(mask));
        M {
            s,
            m: s.equal_u64s(u, s.splat_u64s(0)),
        }
    }
}

impl<S: Simd> M<S> {
    /// `if self { a } else { b }`, lane by lane.
    #[inline(always)]
    pub fn select(self, a: F<S>, b: F<S>) -> F<S> {
        F {
            s: self.s,
            v: self.s.select_f64s(self.m, a.v, b.v),
        }
    }
    /// Whether any lane is set.
    #[inline(always)]
    pub fn any(self) -> bool {
        self.s.first_true_m64s(self.m) < S::F64_LANES
    }
    /// Whether every lane is set.
    #[inline(always)]
    pub fn all(self) -> bool {
        !self.not().any()
    }
    /// Lane-wise and.
    #[inline(always)]
    pub fn and(self, b: Self) -> Self {
        Self {
            s: self.s,
            m: self.s.and_m64s(self.m, b.m),
        }
    }
    /// Lane-wise or.
    #[inline(always)]
    pub fn or(self, b: Self) -> Self {
        Self {
            s: self.s,
            m: self.s.or_m64s(self.m, b.m),
        }
    }
    /// Lane-wise negation.
    #[inline(always)]
    pub fn not(self) -> Self {
        Self {
            s: self.s,
            m: self.s.not_m64s(self.m),
        }
    }
}

macro_rules! binop {
    ($tr:ident, $f:ident, $op:ident) => {
        impl<S: Simd> $tr for F<S> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, b: Self) -> Self {
                Self {
                    s: self.s,
                    v: self.s.$op(self.v, b.v),
                }
            }
        }
        impl<S: Simd> $tr<f64> for F<S> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, b: f64) -> Self {
                Self {
                    s: self.s,
                    v: self.s.$op(self.v, self.s.splat_f64s(b)),
                }
            }
        }
    };
}
binop!(Add, add, add_f64s);
binop!(Sub, sub, sub_f64s);
binop!(Mul, mul, mul_f64s);
binop!(Div, div, div_f64s);

impl<S: Simd> Neg for F<S> {
    type Output = Self;
    /// Flips the sign bit (exact; −0 for +0).
    #[inline(always)]
    fn neg(self) -> Self {
        let s = self.s;
        Self {
            s,
            v: s.transmute_f64s_u64s(
                s.xor_u64s(s.transmute_u64s_f64s(self.v), s.splat_u64s(1 << 63)),
            ),
        }
    }
}

/// Every lane `x` (shorthand of [`F::splat`] for the kernels' constants).
#[inline(always)]
pub fn k<S: Simd>(s: S, x: f64) -> F<S> {
    F::splat(s, x)
}

/// `[F::splat(s, aᵢ)]`.
#[inline(always)]
pub fn splat_n<S: Simd, const N: usize>(s: S, a: [f64; N]) -> [F<S>; N] {
    let mut o = [F::splat(s, 0.0); N];
    for i in 0..N {
        o[i] = F::splat(s, a[i]);
    }
    o
}

/// Components `first .. first + N` of the lanes `off ..` of a group (component c of lane l at
/// `c·8 + l`).
#[inline(always)]
pub fn load_n<S: Simd, const N: usize>(s: S, group: &[f64], first: usize, off: usize) -> [F<S>; N] {
    let mut o = [F::splat(s, 0.0); N];
    for i in 0..N {
        o[i] = F::load(s, &group[(first + i) * crate::engine::GROUP + off..]);
    }
    o
}

/// Writes components `first .. first + N` of the lanes `off ..` of a group.
#[inline(always)]
pub fn store_n<S: Simd, const N: usize>(
    a: &[F<S>; N],
    group: &mut [f64],
    first: usize,
    off: usize,
) {
    let w = S::F64_LANES;
    for (i, v) in a.iter().enumerate() {
        let at = (first + i) * crate::engine::GROUP + off;
        v.store(&mut group[at..at + w]);
    }
}

/// `if m { aᵢ } else { bᵢ }`.
#[inline(always)]
pub fn select_n<S: Simd, const N: usize>(m: M<S>, a: &[F<S>; N], b: &[F<S>; N]) -> [F<S>; N] {
    let mut o = *a;
    for i in 0..N {
        o[i] = m.select(a[i], b[i]);
    }
    o
}

/// `aᵢ + bᵢ t` (a product and a sum: no fused multiply-add).
#[inline(always)]
pub fn axpy_n<S: Simd, const N: usize>(a: &[F<S>; N], b: &[F<S>; N], t: f64) -> [F<S>; N] {
    let mut o = *a;
    for i in 0..N {
        o[i] = a[i] + b[i] * t;
    }
    o
}

/// `aᵢ t`.
#[inline(always)]
pub fn scale_n<S: Simd, const N: usize>(a: &[F<S>; N], t: f64) -> [F<S>; N] {
    let mut o = *a;
    for i in 0..N {
        o[i] = a[i] * t;
    }
    o
}
