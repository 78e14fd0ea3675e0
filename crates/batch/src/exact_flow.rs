//! The exact flow of the free rigid body on lanes: the t-dependent part of
//! `mechanics::exact::FreeBodyFlow`'s evaluation, for the orbits of the generic elliptic kind.

use crate::engine::{Kernel, GROUP};
use crate::lanes::{k, load_n, select_n, store_n, F, M};
use crate::rk4::body_energy;
use crate::rkmk4::normalize;
use crate::splitting::finite_all;
use crate::trig::{atan, sin_cos, REDUCTION_LIMIT};
use crate::{BatchError, BodyModel};
use core::f64::consts::FRAC_PI_2;
use integrators::IntegratorError;
use lie_groups::{LieGroup, So3};
use mechanics::exact::{AxisymmetricFlow, EllipticOrbit, FreeBodyFlow};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};
use pulp::Simd;

/// The exact free-body flow `mechanics::exact::ExactFreeBody` on lanes: each body keeps the
/// constants of its orbit, computed once at build by the scalar `FreeBodyFlow` from its initial
/// (Π₀, R₀), and its elapsed time summed as the scalar integrator sums it (a compensated sum,
/// `integrators::Clock`); each step evaluates the orbit at the new elapsed time, the
/// t-dependent part of `FreeBodyFlow::advance` (notation there and in
/// `mechanics::exact::EllipticOrbit`):
///
/// ```text
/// u = u₀ + λτ = nK + w (τ = 2ᵉt),  (S, C) = Bulirsch's sn, cn of |w| (sign of w), D = √(C² + k'²S²),
/// (sn, cn, dn)(u) = (±S, ±C, D) for even n,  (±C/D, ∓k'S/D, k'/D) for odd n,
/// Π(t) = 2ᵉ P (A₁ cn u, σA₂ sn u, A₃ dn u),
/// Δψ = |q|τ/I₃ + (I₃ − I₁)/(I₁I₃λ) · [|q| ΔΛ − A₃ ΔG],   R(t) = R₀ P B(n₀) exp(Δψ ê₃) B(n(t))ᵀ Pᵀ,
/// ```
///
/// then R normalized by one Newton–Schulz step, as the scalar evaluation does — Legendre's third
/// integral by Carlson's R_F and R_J (with R_C(1, 1 + e) = atan √e/√e), the atan and the
/// sin, cos of Δψ by the lanes' own [`crate::trig`].
///
/// **The same operations as the scalar evaluation**, in its order, without fused multiply-adds,
/// with every branch of the scalar code a lane-wise select: the quarter-period reduction and its
/// quadrant, Bulirsch's descending AGM (a property of k' alone: its means are computed once per
/// body, at build, by the scalar loop) and its ascent over each lane's own number of levels,
/// the duplication of R_F and R_J stopped for each lane where the scalar stops it (the lane's
/// values frozen by a select while its neighbours iterate on). What differs is only the
/// elementary functions — the lanes' sin/cos (within 1 ulp of libm) and atan (fdlibm's, within
/// 1 ulp of libm) where the scalar takes libm's — so a lane is the scalar `ExactFreeBody` to a
/// few ulps: measured within 1.6 ulps of |Π| for Π and 6.8 ulps for R, four bodies in five bit for
/// bit, in every regime of the scalar tests (test `exact_lanes_follow_the_scalar_exact_flow`).
///
/// **The scalar path per body.** A body whose orbit is not of the generic elliptic kind is
/// evaluated, lane by lane, by the scalar `FreeBodyFlow::advance` from its initial state at its
/// elapsed time — the same bits as `ExactFreeBody`, decided by the orbit's kind at build (a
/// property of the body: never of its lane, its neighbours or the level):
/// - an axisymmetric body (every lane: `AxisymmetricFlow`'s closed form, no elliptic functions);
/// - Π along a principal axis (a steady rotation, `So3::exp` of an angle that may be large);
/// - k' < 2⁻⁶⁰, within ~10⁻³⁶ of the separatrix or on it (the k = 1 limits through tanh, sech and
///   ln k' of the scalar `Modulus`, which no lane needs otherwise).
///
/// Π = 0 (the body at rest, and the padding of the last group) stays (Π₀, R₀) on the lanes, as
/// the scalar flow leaves it. A generic lane also takes the scalar path for a step whose
/// precession angle |Δψ| exceeds the lanes' sine range [`REDUCTION_LIMIT`] = 2²⁸ rad (libm's
/// reduction then), or where an R_C argument of the duplication falls below −10⁻³ (it cannot in
/// exact arithmetic: every R_J here has p above or between its other arguments) — conditions on
/// the lane's own state alone.
///
/// **Where it differs from `ExactFreeBody`.** Beyond the phase limit |t|·|Π|/I_min ≥ 2⁵² rad
/// from the start of the orbit the scalar integrator starts a new orbit from its current state;
/// a lane fails there ([`crate::LaneStatus::Failed`], its last state kept). The free body only
/// (no field): [`ExactFlow::new`] refuses a [`BodyModel`] in a field.
#[derive(Debug, Clone)]
pub struct ExactFlow {
    body: BodyModel,
    flow: FreeBodyFlow,
    axisymmetric: bool,
}

impl ExactFlow {
    /// The exact flow of the free body `body`. Errors: a body in a field.
    pub fn new(body: BodyModel) -> Result<Self, BatchError> {
        if body.field.is_some() {
            return Err(BatchError::Unsupported {
                reason: "the exact flow is the free rigid body's; this body is in a field".into(),
            });
        }
        // The body `BodyModel::free` was read from: its moments, exactly, in principal axes.
        let rigid = RigidBody::principal(body.moments).map_err(|e| BatchError::Unsupported {
            reason: format!("the body's moments {:?}: {e}", body.moments),
        })?;
        Ok(Self {
            flow: FreeBodyFlow::new(&rigid),
            axisymmetric: AxisymmetricFlow::new(&rigid).is_ok(),
            body,
        })
    }
    /// The body.
    pub fn body(&self) -> &BodyModel {
        &self.body
    }
}

/// Levels of Bulirsch's descending AGM kept per lane: k'² ≥ 2⁻¹²⁰ (the generic kind) takes at
/// most 9 (`sn_cn_dn` stops at a relative gap of 10⁻⁸); a body that needs more takes the scalar
/// path.
const LEVELS: usize = 10;

/// How a lane is evaluated.
const REST: f64 = 0.0;
const ELLIPTIC: f64 = 1.0;
const SCALAR: f64 = 2.0;

/// The lane layout: the published (Π, R), the initial (Π₀, R₀), the elapsed time and its carry,
/// the mode, then the orbit's constants (`EllipticOrbit`, and the products of them the scalar
/// third-kind part forms at every call, formed once here by the same operations).
mod at {
    pub const PI: usize = 0;
    pub const R: usize = 3;
    pub const PI0: usize = 12;
    pub const R0: usize = 15;
    pub const T: usize = 24;
    pub const CARRY: usize = 25;
    pub const MODE: usize = 26;
    pub const RATE: usize = 27;
    pub const SCALE: usize = 28;
    pub const PMAT: usize = 29;
    pub const AMP: usize = 38;
    pub const LAMBDA: usize = 41;
    pub const KC2: usize = 42;
    pub const KC: usize = 43;
    pub const QUARTER: usize = 44;
    pub const N0: usize = 45;
    pub const W0: usize = 46;
    pub const START: usize = 47;
    pub const NORM: usize = 56;
    pub const INV_NORM: usize = 57;
    pub const I3: usize = 58;
    pub const FACTOR: usize = 59;
    pub const BETA: usize = 60;
    pub const SB: usize = 61;
    pub const LQ: usize = 62;
    pub const PART0: usize = 63;
    pub const ATAN0: usize = 64;
    /// The slope c of Λ: 1 for β < 1, 0 otherwise.
    pub const SLOPE: usize = 65;
    /// k² = 1 − k'².
    pub const K2: usize = 66;
    /// q = √((1 + β)(1 + k²/β)).
    pub const Q: usize = 67;
    /// ν/3, ν = (k² + β)/(1 + β).
    pub const NU3: usize = 68;
    /// 1 + β.
    pub const OPB: usize = 69;
    /// β k'².
    pub const BK: usize = 70;
    /// (1 + β)(k² + β).
    pub const DEN: usize = 71;
    /// −β/3.
    pub const MB3: usize = 72;
    /// k²/(3β).
    pub const K3B: usize = 73;
    /// k² + β.
    pub const K2B: usize = 74;
    /// The AGM's last mean c of `sn_cn_dn`, and its last level l.
    pub const AGM_C: usize = 75;
    pub const AGM_L: usize = 76;
    /// The means a_i and b_i of the levels 0..LEVELS.
    pub const EM: usize = 77;
    pub const EN: usize = EM + super::LEVELS;
    pub const END: usize = EN + super::LEVELS;
}

/// One vector of lanes: the published state and the elapsed time, what a step changes (the
/// orbit's constants stay in the lanes' group, where the step reads them).
#[derive(Clone, Copy, Debug)]
pub struct ExactFlowState<S: Simd> {
    pi: [F<S>; 3],
    r: [F<S>; 9],
    t: F<S>,
    carry: F<S>,
}

/// The constants of one vector of lanes, read from their group where the step uses them (the
/// group is not written during a step): a copy of all of them into the state would cost each
/// step as much as a good part of its arithmetic.
#[derive(Clone, Copy)]
struct Consts<'a, S: Simd> {
    s: S,
    group: &'a [f64],
    off: usize,
}

impl<S: Simd> Consts<'_, S> {
    /// Component `i` of the lanes.
    #[inline(always)]
    fn at(&self, i: usize) -> F<S> {
        F::load(self.s, &self.group[i * GROUP + self.off..])
    }
    /// Components `first .. first + N`.
    #[inline(always)]
    fn n<const N: usize>(&self, first: usize) -> [F<S>; N] {
        load_n(self.s, self.group, first, self.off)
    }
}

/// 2⁵²: the phase limit of `FreeBodyFlow` (t·|Π|/I_min).
const PHASE_LIMIT: f64 = 4_503_599_627_370_496.0;
/// Carlson's stopping spread (`mechanics::exact::elliptic`).
const SPREAD: f64 = 2e-3;
/// 1.5·2⁵²: `(x + ROUNDER) − ROUNDER` rounds |x| < 2⁵¹ to an integer, ties to even, and the low
/// bits of `x + ROUNDER` are that integer (two's complement).
const ROUNDER: f64 = 6_755_399_441_055_744.0;
/// 2⁵²: every double beyond it is an integer.
const INTEGRAL: f64 = 4_503_599_627_370_496.0;

/// Bulirsch's descending AGM of `sn_cn_dn` for k'², as the scalar loop runs it: the means
/// (a_i, b_i) of each level, the last c and the last level l; `None` beyond [`LEVELS`].
fn descent(kc2: f64) -> Option<([f64; LEVELS], [f64; LEVELS], f64, usize)> {
    let (mut em, mut en) = ([1.0; LEVELS], [1.0; LEVELS]);
    let (mut a, mut emc) = (1.0f64, kc2);
    for i in 0..16 {
        if i >= LEVELS {
            return None;
        }
        em[i] = a;
        emc = emc.sqrt();
        en[i] = emc;
        let c = 0.5 * (a + emc);
        if (a - emc).abs() <= 1e-8 * a {
            return Some((em, en, c, i));
        }
        emc *= a;
        a = c;
    }
    None
}

/// `f64::round` (half away from zero) lane by lane.
#[inline(always)]
fn round<S: Simd>(x: F<S>) -> F<S> {
    let s = x.s;
    let a = x.abs();
    let r = (a + ROUNDER) - ROUNDER;
    // A tie rounded down to even goes up instead (a − r is exact).
    let r = (a - r).eq(k(s, 0.5)).select(r + 1.0, r);
    let r = a.lt(k(s, INTEGRAL)).select(r, a);
    r.copysign(x)
}

/// The compensated sum of `integrators::Clock::advance`: (t, carry) + h.
#[inline(always)]
fn clock_advance<S: Simd>(t: F<S>, carry: F<S>, h: f64) -> (F<S>, F<S>) {
    let s = t + h;
    let b = s - t;
    let e = (t - (s - b)) + (k(t.s, h) - b);
    let lo = carry + e;
    let t = s + lo;
    (t, lo - (t - s))
}

/// `R_C(1, 1 + e)` of `elliptic`'s `carlson_rc_one` for the lanes of `mask`: its series below
/// |e| = 10⁻³, atan √e/√e above (the atan only evaluated where some lane needs it); the lanes
/// with e ≤ −10⁻³ (atanh: never in this flow) are returned for the scalar path.
#[inline(always)]
fn rc_one<S: Simd>(e: F<S>, mask: M<S>) -> (F<S>, M<S>) {
    let s = e.s;
    let series = k(s, 1.0)
        + e * (k(s, -1.0 / 3.0) + e * (k(s, 1.0 / 5.0) + e * (k(s, -1.0 / 7.0) + e / 9.0)));
    let small = e.abs().lt(k(s, 1e-3));
    let big = small.not().and(mask);
    if !big.any() {
        return (series, big);
    }
    let positive = k(s, 0.0).lt(e);
    let r = e.sqrt();
    let v = atan(r) / r;
    (small.select(series, v), big.and(positive.not()))
}

/// Carlson's `R_F(x, y, z)` (for the lanes of `need_f`) and `R_J(x, y, z, p)` (for the lanes of
/// `need_j`) by the duplication of `elliptic`'s `carlson_rf` and `carlson_rj`, operation for
/// operation: the two share their (x, y, z) sequence, and each lane stops where the scalar loop
/// stops for it (NaN after 64, as the scalar). A lane's arguments are frozen there by a select
/// while its neighbours iterate on, and each truncated series is evaluated once, after the loop,
/// on every lane's frozen arguments — the scalar's operations on the scalar's values, whatever
/// the iteration at which each lane stopped. Also the lanes that need the scalar path (`rc_one`).
#[inline(always)]
fn carlson<S: Simd>(xyzp: [F<S>; 4], need_f: M<S>, need_j: M<S>) -> (F<S>, F<S>, M<S>) {
    let [mut x, mut y, mut z, mut p] = xyzp;
    let s = x.s;
    let one = k(s, 1.0);
    let delta = ((p - x) * (p - y)) * (p - z);
    let (mut sum, mut fac) = (k(s, 0.0), one);
    let (mut pend_f, mut pend_j) = (need_f, need_j);
    let none = need_j.and(need_j.not());
    let (mut bad, mut done_f_all, mut done_j_all) = (none, none, none);
    // Each lane's arguments where its R_F and its R_J stop (R_J's p, 4⁻ᵐ and sum stop changing
    // there by themselves).
    let (mut xf, mut yf, mut af) = (x, y, one);
    let (mut xj, mut yj, mut zj, mut aj) = (x, y, z, one);
    for _ in 0..64 {
        // R_F's test.
        if pend_f.any() {
            let a = ((x + y) + z) / 3.0;
            let spread = (a - x).abs().max((a - y).abs()).max((a - z).abs());
            let done = pend_f.and(spread.le(a.abs() * SPREAD));
            xf = done.select(x, xf);
            yf = done.select(y, yf);
            af = done.select(a, af);
            done_f_all = done_f_all.or(done);
            pend_f = pend_f.and(done.not());
        }
        // R_J's.
        if pend_j.any() {
            let a = (((x + y) + z) + p * 2.0) / 5.0;
            let spread = (a - x)
                .abs()
                .max((a - y).abs())
                .max((a - z).abs())
                .max((a - p).abs());
            let done = pend_j.and(spread.le(a.abs() * SPREAD));
            xj = done.select(x, xj);
            yj = done.select(y, yj);
            zj = done.select(z, zj);
            aj = done.select(a, aj);
            done_j_all = done_j_all.or(done);
            pend_j = pend_j.and(done.not());
        }
        let active = pend_f.or(pend_j);
        if !active.any() {
            break;
        }
        // One duplication.
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lam = (sx * sy + sx * sz) + sy * sz;
        let sp = p.sqrt();
        let d = ((sp + sx) * (sp + sy)) * (sp + sz);
        let e = (((fac * fac) * fac) * delta) / (d * d);
        let (rc, rc_bad) = rc_one(e, pend_j);
        bad = bad.or(rc_bad);
        sum = pend_j.select(sum + (fac * rc) / d, sum);
        fac = pend_j.select(fac * 0.25, fac);
        x = active.select(k(s, 0.25) * (x + lam), x);
        y = active.select(k(s, 0.25) * (y + lam), y);
        z = active.select(k(s, 0.25) * (z + lam), z);
        p = pend_j.select(k(s, 0.25) * (p + lam), p);
    }
    let nan = k(s, f64::NAN);
    let rf = if done_f_all.any() {
        let (dx, dy) = (one - xf / af, one - yf / af);
        let dz = -dx - dy;
        let e2 = dx * dy - dz * dz;
        let e3 = (dx * dy) * dz;
        let v = ((((one - e2 / 10.0) + e3 / 14.0) + (e2 * e2) / 24.0) - ((e2 * 3.0) * e3) / 44.0)
            / af.sqrt();
        done_f_all.select(v, nan)
    } else {
        nan
    };
    let rj = if done_j_all.any() {
        let (dx, dy, dz) = (one - xj / aj, one - yj / aj, one - zj / aj);
        let dp = k(s, -0.5) * ((dx + dy) + dz);
        let e2 = ((dx * dy + dx * dz) + dy * dz) - (dp * 3.0) * dp;
        let e3 = ((dx * dy) * dz + (e2 * 2.0) * dp) + ((dp * 4.0) * dp) * dp;
        let e4 = ((((dx * 2.0) * dy) * dz + e2 * dp) + ((dp * 3.0) * dp) * dp) * dp;
        let e5 = (((dx * dy) * dz) * dp) * dp;
        let series = (((((one - (e2 * 3.0) / 14.0) + e3 / 6.0) + ((e2 * 9.0) * e2) / 88.0)
            - (e4 * 3.0) / 22.0)
            - ((e2 * 9.0) * e3) / 52.0)
            + (e5 * 3.0) / 26.0;
        let v = (fac * series) / (aj * aj.sqrt()) + sum * 6.0;
        done_j_all.select(v, nan)
    } else {
        nan
    };
    (rf, rj, bad)
}

/// Row-major `a b` (3 × 3), each entry summed in index order.
#[inline(always)]
fn mul3<S: Simd>(a: &[F<S>; 9], b: &[F<S>; 9]) -> [F<S>; 9] {
    let mut o = *a;
    for i in 0..3 {
        for j in 0..3 {
            o[3 * i + j] = (a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j]) + a[3 * i + 2] * b[6 + j];
        }
    }
    o
}

impl ExactFlow {
    /// The elliptic evaluation at the lanes' elapsed time t: (Π, R) and the lanes that need the
    /// scalar path for this step (`FreeBodyFlow::evaluate`'s elliptic branch, line by line).
    #[inline(always)]
    fn elliptic<S: Simd>(
        &self,
        st: &ExactFlowState<S>,
        c: Consts<'_, S>,
        lanes: M<S>,
    ) -> ([F<S>; 3], [F<S>; 9], M<S>) {
        let t = st.t;
        let s = t.s;
        let one = k(s, 1.0);
        // u = u₀ + λ·t·2ᵉ, reduced to the nearest quarter period (`Modulus::advance`).
        let tau = t * c.at(at::SCALE);
        let du = c.at(at::LAMBDA) * tau;
        let x = c.at(at::W0) + du;
        let m = round(x / c.at(at::QUARTER));
        let zero = k(s, 0.0);
        let keep = m.eq(zero).or(m.eq(m).not());
        let n = keep.select(c.at(at::N0), c.at(at::N0) + m);
        let w = keep.select(x, x - m * c.at(at::QUARTER));
        // n mod 4 from the low bits of n + 1.5·2⁵² (n is an integer, |n| < 2⁵¹).
        let nb = n + ROUNDER;
        let odd = nb.bits_clear(1).not();
        let sign = nb.bits_clear(2).select(one, k(s, -1.0));
        // Bulirsch's sn, cn of |w| (`sn_cn_dn`): sin, cos of u·c, then the ascent over the
        // lane's own levels.
        let u = w.abs();
        let (sn0, cn0) = sin_cos(u * c.at(at::AGM_C));
        let mut a = cn0 / sn0;
        let mut cc = c.at(at::AGM_C) * a;
        let mut dn = one;
        for ii in (0..LEVELS).rev() {
            let active = k(s, ii as f64).le(c.at(at::AGM_L)).and(lanes);
            if !active.any() {
                continue;
            }
            let b = c.at(at::EM + ii);
            let a1 = a * cc;
            let c1 = cc * dn;
            let d1 = (c.at(at::EN + ii) + a1) / (b + a1);
            a = active.select(c1 / b, a);
            cc = active.select(c1, cc);
            dn = active.select(d1, dn);
        }
        let r = one / (cc * cc + 1.0).sqrt();
        let sn1 = zero.le(sn0).select(r, -r);
        let nonzero = sn0.eq(zero).not();
        let big_s = nonzero.select(sn1, sn0).copysign(w);
        let big_c = nonzero.select(cc * sn1, cn0);
        // `Modulus::jacobi`.
        let (kc2, kc) = (c.at(at::KC2), c.at(at::KC));
        let big_d = (big_c * big_c + (kc2 * big_s) * big_s).sqrt();
        let ksc = (kc * big_s) / big_c;
        let sn = odd.select((sign * big_c) / big_d, sign * big_s);
        let cn = odd.select(((-sign * kc) * big_s) / big_d, sign * big_c);
        let dn = odd.select(kc / big_d, big_d);
        // Π(t) = 2ᵉ P q(t).
        let qt = [
            c.at(at::AMP) * cn,
            c.at(at::AMP + 1) * sn,
            c.at(at::AMP + 2) * dn,
        ];
        let p: [F<S>; 9] = c.n(at::PMAT);
        let mut pi = [zero; 3];
        for i in 0..3 {
            pi[i] = ((p[3 * i] * qt[0] + p[3 * i + 1] * qt[1]) + p[3 * i + 2] * qt[2])
                * c.at(at::SCALE);
        }
        // ΔΛ (`Modulus::third_kind_part`, the slope form for β < 1) and ΔG.
        let slope = c.at(at::SLOPE).eq(one);
        let (part, bad) = self.third_kind_part(c, w, odd, slope, [big_s, big_c, big_d], lanes);
        let dnq = n - c.at(at::N0);
        let d_lambda = c.at(at::SLOPE) * du + (part - c.at(at::PART0));
        let d_lambda = dnq.eq(zero).select(d_lambda, d_lambda + dnq * c.at(at::LQ));
        let sb = c.at(at::SB);
        let g_arg = odd.select(ksc / sb, (sb * big_s) / big_c);
        let d_g = (dnq * FRAC_PI_2 + (atan(g_arg) - c.at(at::ATAN0))) / sb;
        let dpsi = (c.at(at::NORM) * tau) / c.at(at::I3)
            + c.at(at::FACTOR) * (c.at(at::NORM) * d_lambda - c.at(at::AMP + 2) * d_g);
        // B(n(t)) for n = q/|q|: I + v̂ + v̂²/(1 + n₃), v = e₃ × n.
        let inv = c.at(at::INV_NORM);
        let (nx, ny, nz) = (qt[0] * inv, qt[1] * inv, qt[2] * inv);
        let den = one + nz;
        let nxy = -(nx * ny) / den;
        let b = [
            one - (nx * nx) / den,
            nxy,
            nx,
            nxy,
            one - (ny * ny) / den,
            ny,
            -nx,
            -ny,
            one - (nx * nx + ny * ny) / den,
        ];
        let bt = mul3(&p, &b);
        // R₀ P B(n₀) exp(Δψ ê₃): its first two columns turned by Δψ.
        let (sin, cos) = sin_cos(dpsi);
        let st0: [F<S>; 9] = c.n(at::START);
        let mut rot = [zero; 9];
        for i in 0..3 {
            let (c0, c1) = (st0[3 * i], st0[3 * i + 1]);
            rot[3 * i] = c0 * cos + c1 * sin;
            rot[3 * i + 1] = c1 * cos - c0 * sin;
            rot[3 * i + 2] = st0[3 * i + 2];
        }
        // rot · btᵀ.
        let mut g = [zero; 9];
        for i in 0..3 {
            for j in 0..3 {
                g[3 * i + j] = (rot[3 * i] * bt[3 * j] + rot[3 * i + 1] * bt[3 * j + 1])
                    + rot[3 * i + 2] * bt[3 * j + 2];
            }
        }
        normalize(&mut g);
        // Beyond the lanes' sine range: libm's reduction, on the scalar path.
        let wide = k(s, REDUCTION_LIMIT).lt(dpsi.abs());
        (pi, g, bad.or(wide).and(lanes))
    }

    /// `Modulus::third_kind_part` for the non-asymptotic modulus, its four branches (odd or even
    /// n, β < 1 or not) each lane's own by a select; and the lanes that need the scalar path.
    #[inline(always)]
    fn third_kind_part<S: Simd>(
        &self,
        c: Consts<'_, S>,
        w: F<S>,
        odd: M<S>,
        slope: M<S>,
        [big_s, big_c, big_d]: [F<S>; 3],
        lanes: M<S>,
    ) -> (F<S>, M<S>) {
        let s = w.s;
        let one = k(s, 1.0);
        let (c2, d2) = (big_c * big_c, big_d * big_d);
        let s3 = (big_s * big_s) * big_s;
        let beta = c.at(at::BETA);
        let p_odd = c2 + ((c.at(at::KC2) * big_s) * big_s) / c.at(at::OPB);
        let p_slope = one + (beta * big_s) * big_s;
        let p_even = one + ((c.at(at::K2) * big_s) * big_s) / beta;
        let p = odd.select(p_odd, slope.select(p_slope, p_even));
        let need_f = odd.and(slope.not()).and(lanes);
        let (rf, rj, bad) = carlson([c2, d2, one, p], need_f, lanes);
        // odd n
        let rj_odd = (c.at(at::NU3) * s3) * rj;
        let odd_slope = ((-beta) * w) / c.at(at::OPB) + (c.at(at::BK) * rj_odd) / c.at(at::DEN);
        let pi_nu = big_s * rf + rj_odd;
        let odd_full = (c.at(at::K2) * w + (c.at(at::BK) * pi_nu) / c.at(at::OPB)) / c.at(at::K2B);
        // even n
        let even_slope = (c.at(at::MB3) * s3) * rj;
        let full = odd.not().and(slope.not()).and(lanes);
        let even_full = if full.any() {
            let q = c.at(at::Q);
            atan((q * big_s) / (big_c * big_d)) / q + (c.at(at::K3B) * s3) * rj
        } else {
            even_slope
        };
        let v = odd.select(
            slope.select(odd_slope, odd_full),
            slope.select(even_slope, even_full),
        );
        (v, bad)
    }

    /// The lanes of `mask` by the scalar flow: `FreeBodyFlow::advance` from the lane's (Π₀, R₀)
    /// at its elapsed time, NaN where it fails (a cold path: out of line).
    #[cold]
    #[inline(never)]
    fn scalar_lanes<S: Simd>(&self, st: &mut ExactFlowState<S>, c: Consts<'_, S>, mask: M<S>) {
        let w = S::F64_LANES;
        let s = st.t.s;
        let flags = mask.select(k(s, 1.0), k(s, 0.0));
        let mut out = [[0.0f64; 8]; 12];
        for (o, v) in out.iter_mut().zip(st.pi.iter().chain(&st.r)) {
            o[..w].copy_from_slice(&v.lanes()[..w]);
        }
        for l in (0..w).filter(|&l| flags.lanes()[l] == 1.0) {
            let lane = |i: usize| c.at(i).lanes()[l];
            let pi0 = Vector3::new(lane(at::PI0), lane(at::PI0 + 1), lane(at::PI0 + 2));
            let r0 = So3::from_matrix_unchecked(&Matrix3::from_fn(|i, j| lane(at::R0 + 3 * i + j)));
            let got = match self.flow.advance(st.t.lanes()[l], &pi0, Some(&r0)) {
                Ok((pi, Some(r))) => {
                    let m = r.as_matrix();
                    core::array::from_fn(|i| {
                        if i < 3 {
                            pi[i]
                        } else {
                            m[((i - 3) / 3, (i - 3) % 3)]
                        }
                    })
                }
                _ => [f64::NAN; 12],
            };
            for (o, v) in out.iter_mut().zip(got) {
                o[l] = v;
            }
        }
        for (i, o) in out.iter().enumerate() {
            let v = F::load(s, &o[..w]);
            if i < 3 {
                st.pi[i] = v;
            } else {
                st.r[i - 3] = v;
            }
        }
    }
}

impl Kernel for ExactFlow {
    const COMPONENTS: usize = at::END;
    type State<S: Simd> = ExactFlowState<S>;

    fn name(&self) -> String {
        "exact".into()
    }
    fn init_lane(&self, pi: [f64; 3], r: [f64; 9]) -> Option<Vec<f64>> {
        if !pi.iter().chain(&r).all(|x| x.is_finite()) {
            return None;
        }
        let mut v = vec![0.0; at::END];
        v[at::PI..at::PI + 3].copy_from_slice(&pi);
        v[at::R..at::R + 9].copy_from_slice(&r);
        v[at::PI0..at::PI0 + 3].copy_from_slice(&pi);
        v[at::R0..at::R0 + 9].copy_from_slice(&r);
        let pi_v = Vector3::from(pi);
        let r0 = So3::from_matrix_unchecked(&Matrix3::from_row_slice(&r));
        let orbit = if self.axisymmetric {
            None
        } else {
            self.flow.elliptic_orbit(&pi_v, &r0).ok()?
        };
        let descended = orbit.as_ref().and_then(|o| descent(o.kc2).map(|d| (o, d)));
        let Some((o, (em, en, agm_c, l))) = descended else {
            v[at::MODE] = if !self.axisymmetric && pi == [0.0; 3] {
                REST
            } else {
                SCALAR
            };
            return Some(v);
        };
        let EllipticOrbit {
            rate,
            scale,
            pmat,
            amplitudes,
            lambda,
            kc2,
            kc,
            quarter,
            phase0,
            start,
            norm,
            inv_norm,
            i3,
            factor,
            beta,
            sb,
            lambda_quarter,
            part0,
            atan0,
        } = *o;
        v[at::MODE] = ELLIPTIC;
        v[at::RATE] = rate;
        v[at::SCALE] = scale;
        for i in 0..9 {
            v[at::PMAT + i] = pmat[(i / 3, i % 3)];
            v[at::START + i] = start[(i / 3, i % 3)];
        }
        v[at::AMP..at::AMP + 3].copy_from_slice(&amplitudes);
        let k2 = 1.0 - kc2;
        for (i, x) in [
            (at::LAMBDA, lambda),
            (at::KC2, kc2),
            (at::KC, kc),
            (at::QUARTER, quarter),
            (at::N0, phase0.n),
            (at::W0, phase0.w),
            (at::NORM, norm),
            (at::INV_NORM, inv_norm),
            (at::I3, i3),
            (at::FACTOR, factor),
            (at::BETA, beta),
            (at::SB, sb),
            (at::LQ, lambda_quarter),
            (at::PART0, part0),
            (at::ATAN0, atan0),
            // `third_kind_slope` (non-asymptotic) and the constants of `third_kind_part`, as it
            // forms them.
            (at::SLOPE, if beta < 1.0 { 1.0 } else { 0.0 }),
            (at::K2, k2),
            (at::Q, ((1.0 + beta) * (1.0 + k2 / beta)).sqrt()),
            (at::NU3, (k2 + beta) / (1.0 + beta) / 3.0),
            (at::OPB, 1.0 + beta),
            (at::BK, beta * kc2),
            (at::DEN, (1.0 + beta) * (k2 + beta)),
            (at::MB3, -beta / 3.0),
            (at::K3B, k2 / (3.0 * beta)),
            (at::K2B, k2 + beta),
            (at::AGM_C, agm_c),
            (at::AGM_L, l as f64),
        ] {
            v[i] = x;
        }
        v[at::EM..at::EM + LEVELS].copy_from_slice(&em);
        v[at::EN..at::EN + LEVELS].copy_from_slice(&en);
        Some(v)
    }
    #[inline(always)]
    fn load<S: Simd>(&self, s: S, group: &[f64], off: usize) -> ExactFlowState<S> {
        let [t] = load_n(s, group, at::T, off);
        let [carry] = load_n(s, group, at::CARRY, off);
        ExactFlowState {
            pi: load_n(s, group, at::PI, off),
            r: load_n(s, group, at::R, off),
            t,
            carry,
        }
    }
    #[inline(always)]
    fn store<S: Simd>(&self, st: &ExactFlowState<S>, group: &mut [f64], off: usize) {
        store_n(&st.pi, group, at::PI, off);
        store_n(&st.r, group, at::R, off);
        store_n(&[st.t], group, at::T, off);
        store_n(&[st.carry], group, at::CARRY, off);
    }
    #[inline(always)]
    fn step<S: Simd>(
        &self,
        st: &mut ExactFlowState<S>,
        group: &[f64],
        off: usize,
        h: f64,
        _renormalize: bool,
    ) {
        let (t, carry) = clock_advance(st.t, st.carry, h);
        st.t = t;
        st.carry = carry;
        let s = t.s;
        let c = Consts { s, group, off };
        let mode = c.at(at::MODE);
        let scalar = mode.eq(k(s, SCALAR));
        if self.axisymmetric {
            // Every body of an axisymmetric model is of that kind.
            self.scalar_lanes(st, c, scalar);
            return;
        }
        let elliptic = mode.eq(k(s, ELLIPTIC));
        let pi0: [F<S>; 3] = c.n(at::PI0);
        let r0: [F<S>; 9] = c.n(at::R0);
        let (pi, r, fallback) = if elliptic.any() {
            self.elliptic(st, c, elliptic)
        } else {
            (pi0, r0, elliptic)
        };
        // `FreeBodyFlow::evaluate`'s order: t = 0 returns (Π₀, R₀); then beyond the phase limit
        // (or a NaN phase) an error, NaN here; then the body at rest keeps (Π₀, R₀).
        let at_start = t.eq(k(s, 0.0));
        let in_phase = (t.abs() * c.at(at::RATE)).lt(k(s, PHASE_LIMIT));
        let rest = mode.eq(k(s, REST));
        let nan = k(s, f64::NAN);
        for i in 0..3 {
            let later = in_phase.select(rest.select(pi0[i], pi[i]), nan);
            st.pi[i] = at_start.select(pi0[i], later);
        }
        for i in 0..9 {
            let later = in_phase.select(rest.select(r0[i], r[i]), nan);
            st.r[i] = at_start.select(r0[i], later);
        }
        let fallback = scalar.or(fallback.and(at_start.not()).and(in_phase));
        if fallback.any() {
            self.scalar_lanes(st, c, fallback);
        }
    }
    #[inline(always)]
    fn select<S: Simd>(m: M<S>, a: &ExactFlowState<S>, b: &ExactFlowState<S>) -> ExactFlowState<S> {
        ExactFlowState {
            pi: select_n(m, &a.pi, &b.pi),
            r: select_n(m, &a.r, &b.r),
            t: m.select(a.t, b.t),
            carry: m.select(a.carry, b.carry),
        }
    }
    #[inline(always)]
    fn finite<S: Simd>(&self, st: &ExactFlowState<S>) -> M<S> {
        finite_all(&st.pi, &st.r)
    }
    #[inline(always)]
    fn published<S: Simd>(&self, st: &ExactFlowState<S>) -> ([F<S>; 3], [F<S>; 9]) {
        (st.pi, st.r)
    }
    #[inline(always)]
    fn observe<S: Simd>(&self, st: &ExactFlowState<S>) -> (F<S>, Option<F<S>>) {
        body_energy(&self.body, st.pi, None)
    }
    fn has_casimir(&self) -> bool {
        true
    }
    /// The flow itself: φ_{−h} = φ_h⁻¹.
    fn symmetric(&self) -> bool {
        true
    }
    /// Each evaluation normalizes R itself, from the orbit's constants: nothing accumulates.
    fn renormalizes(&self) -> bool {
        false
    }
    fn build_error(&self) -> IntegratorError {
        IntegratorError::NonFinite {
            what: "momentum Π"
        }
    }
    fn step_error(&self) -> IntegratorError {
        IntegratorError::NonFinite {
            what: "phase |Π|t/I of the exact flow (beyond 2⁵² rad, no digit of the phase left)",
        }
    }
}
