//! The Strang splitting of the free rigid body and of a body in a uniform field, on lanes.

use crate::engine::{self, Kernel, Schedule};
use crate::lanes::{load_n, scale_n, select_n, splat_n, store_n, F, M};
use crate::trig::{rodrigues_coefficients, sin_cos};
use crate::{BatchError, BodyModel, Level};
use integrators::ensemble::Execution;
use integrators::IntegratorError;
use pulp::Simd;

/// The Strang splitting of `integrators::splitting::Splitting` for a [`BodyModel`], lane by
/// lane: the free body's pieces of [`mechanics::RigidBody`]'s `SplitSystem` impl (Fassò 2003:
/// one principal-axis rotation φ⁰ about a_p and the axisymmetric body φ¹ with the reference
/// moment I_r), and for a body in a field the gravity kick `K_t: Π ↦ Π + t F(R)`,
/// `F(R) = Γ × m g χ` outside them (McLachlan 1993; Dullweber–Leimkuhler–McLachlan 1997):
///
/// ```text
/// free:     Ψ_h = φ⁰_{h/2} ∘ φ¹_h ∘ φ⁰_{h/2}
/// field:    Ψ_h = K_{h/2} ∘ φ⁰_{h/2} ∘ φ¹_h ∘ φ⁰_{h/2} ∘ K_{h/2}
/// φ⁰_t:     Π ← exp(−α ê_p) Π,  R ← R exp(α ê_p),        α = t (1/I_p − 1/I_r) Π_p
/// φ¹_t:     R ← R exp(t Π̂/I_r) exp(β ê_s),  Π ← exp(−β ê_s) Π,  β = t (1/I_s − 1/I_r) Π_s
/// ```
///
/// Order 2, symmetric, explicit, Poisson; the free body keeps |Π|² and the spatial momentum RΠ to
/// round-off, the body in a field its vertical momentum `Γ·Π`.
///
/// **First same as last**, as the scalar `Splitting`: a lane stores the state before the last
/// step's closing outer flow (φ⁰ or the kick) and that flow's time (its *lag*), which the next
/// step merges with its own opening one; the published state (what is read and monitored) applies
/// the lag on reading. The attitude is brought back onto SO(3) every
/// [`crate::RENORMALIZE_EVERY`] steps (one Newton–Schulz step, as `So3::normalize`).
///
/// **Accuracy against the scalar `Splitting`.** The same flows in the same order; the lanes take
/// their sines and cosines from [`crate::trig`] (within 1 ulp of libm, as the scalar
/// `lie_groups::sin_cos`, but not the same bits) and round with fused multiply-adds, so one step
/// differs from the scalar step by a few ulps of |Π| and of R (test
/// `strang_step_matches_the_scalar_splitting`), and trajectories agree to round-off times the
/// growth of perturbations.
#[derive(Debug, Clone)]
pub struct Strang {
    body: BodyModel,
}

impl Strang {
    /// The Strang splitting of `body`.
    pub fn new(body: BodyModel) -> Self {
        Self { body }
    }
    /// The body.
    pub fn body(&self) -> &BodyModel {
        &self.body
    }
}

/// Π, R (row-major) and the lag of one vector of lanes.
#[derive(Clone, Copy, Debug)]
pub struct StrangState<S: Simd> {
    pi: [F<S>; 3],
    r: [F<S>; 9],
    lag: F<S>,
}

/// `(j, k)` of the plane turned by a rotation about axis i: `(i + 1, i + 2) mod 3`.
#[inline(always)]
const fn plane(i: usize) -> (usize, usize) {
    match i {
        0 => (1, 2),
        1 => (2, 0),
        _ => (0, 1),
    }
}

/// `Π ← exp(−α êᵢ) Π`, `R ← R exp(α êᵢ)` for `α = (t Πᵢ) rate`: the plane rotation of
/// `(Πⱼ, Πₖ)` by −α and of columns j, k of R by +α.
#[inline(always)]
fn turn<S: Simd, const I: usize>(st: &mut StrangState<S>, rate: f64, t: F<S>) {
    let (j, k) = plane(I);
    let (s, c) = sin_cos((t * st.pi[I]) * rate);
    let (pj, pk) = (st.pi[j], st.pi[k]);
    st.pi[j] = c.mul_add(pj, s * pk);
    st.pi[k] = c.mul_add(pk, -(s * pj));
    for row in 0..3 {
        let (rj, rk) = (st.r[3 * row + j], st.r[3 * row + k]);
        st.r[3 * row + j] = c.mul_add(rj, s * rk);
        st.r[3 * row + k] = c.mul_add(rk, -(s * rj));
    }
}

/// `R ← R exp(ω̂)` by Rodrigues, `exp(ω̂) = I + aω̂ + bω̂²` with ω̂² = ωωᵀ − |ω|²I entry by entry.
#[inline(always)]
fn compose_exp<S: Simd>(r: &mut [F<S>; 9], w: [F<S>; 3]) {
    let [x, y, z] = w;
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let t2 = xx + yy + zz;
    let (a, b) = rodrigues_coefficients(t2);
    let one = F::splat(x.s, 1.0);
    let (bxy, bxz, byz) = (b * (x * y), b * (x * z), b * (y * z));
    let (ax, ay, az) = (a * x, a * y, a * z);
    let e = [
        (-b).mul_add(yy + zz, one),
        bxy - az,
        bxz + ay,
        bxy + az,
        (-b).mul_add(xx + zz, one),
        byz - ax,
        bxz - ay,
        byz + ax,
        (-b).mul_add(xx + yy, one),
    ];
    for row in 0..3 {
        let (r0, r1, r2) = (r[3 * row], r[3 * row + 1], r[3 * row + 2]);
        for col in 0..3 {
            r[3 * row + col] = r2.mul_add(e[6 + col], r1.mul_add(e[3 + col], r0 * e[col]));
        }
    }
}

/// One Newton–Schulz step of the polar decomposition, `R ← R (3I − RᵀR)/2` (as
/// `So3::normalize`): R leaves SO(3) only by a walk of roundings, which this removes to second
/// order.
#[inline(always)]
fn normalize<S: Simd>(r: &mut [F<S>; 9]) {
    let (c0, c1, c2) = ([r[0], r[3], r[6]], [r[1], r[4], r[7]], [r[2], r[5], r[8]]);
    let h = F::splat(r[0].s, -0.5);
    let t = F::splat(r[0].s, 1.5);
    let (d01, d02, d12) = (h * dot(c0, c1), h * dot(c0, c2), h * dot(c1, c2));
    let corr = [
        h.mul_add(dot(c0, c0), t),
        d01,
        d02,
        d01,
        h.mul_add(dot(c1, c1), t),
        d12,
        d02,
        d12,
        h.mul_add(dot(c2, c2), t),
    ];
    compose_matrix(r, &corr);
}

/// `u · v` in fused multiply-adds.
#[inline(always)]
fn dot<S: Simd>(u: [F<S>; 3], v: [F<S>; 3]) -> F<S> {
    u[2].mul_add(v[2], u[1].mul_add(v[1], u[0] * v[0]))
}

/// `R ← R M`.
#[inline(always)]
fn compose_matrix<S: Simd>(r: &mut [F<S>; 9], m: &[F<S>; 9]) {
    for row in 0..3 {
        let (r0, r1, r2) = (r[3 * row], r[3 * row + 1], r[3 * row + 2]);
        for col in 0..3 {
            r[3 * row + col] = r2.mul_add(m[6 + col], r1.mul_add(m[3 + col], r0 * m[col]));
        }
    }
}

/// The kick `Π ← Π + t F(R)`, `F = Γ × m g χ`, Γ = Rᵀe₃ (the third row of R).
#[inline(always)]
fn kick<S: Simd>(st: &mut StrangState<S>, arm: [f64; 3], t: F<S>) {
    let s = t.s;
    let m = splat_n(s, arm);
    let g = [st.r[6], st.r[7], st.r[8]];
    let f = [
        g[1].mul_add(m[2], -(g[2] * m[1])),
        g[2].mul_add(m[0], -(g[0] * m[2])),
        g[0].mul_add(m[1], -(g[1] * m[0])),
    ];
    for (p, f) in st.pi.iter_mut().zip(f) {
        *p = f.mul_add(t, *p);
    }
}

/// One Strang step with the split axes p, s and the presence of a field as constants (their
/// plane coordinates are then fixed offsets, and the step one straight line of code).
#[inline(always)]
fn strang_step<S: Simd, const P: usize, const Q: usize, const FIELD: bool>(
    body: &BodyModel,
    st: &mut StrangState<S>,
    h: f64,
    renormalize: bool,
) {
    let s = st.lag.s;
    let [inv_r, rate_p, rate_s] = body.split_rates;
    let arm = body.field.unwrap_or([0.0; 3]);
    let half = F::splat(s, 0.5 * h);
    let opening = st.lag + half;
    let full = F::splat(s, h);
    if FIELD {
        kick(st, arm, opening);
        turn::<S, P>(st, rate_p, half);
    } else {
        turn::<S, P>(st, rate_p, opening);
    }
    // φ¹_h: R exp(hΠ/I_r) from the Π before the turn about a_s, then the turn.
    let w = scale_n(&st.pi, h * inv_r);
    compose_exp(&mut st.r, w);
    turn::<S, Q>(st, rate_s, full);
    if FIELD {
        turn::<S, P>(st, rate_p, half);
    }
    st.lag = half;
    if renormalize {
        normalize(&mut st.r);
    }
}

/// [`Strang`] with its axes and field fixed at compile time: what the step loop runs
/// ([`Kernel::run_schedule`] picks the variant once per run).
#[derive(Debug, Clone)]
pub struct StrangFixed<const P: usize, const Q: usize, const FIELD: bool>(Strang);

impl Strang {
    /// One step, the variant chosen at run time (reads and tests; the loop runs
    /// [`StrangFixed`]).
    #[inline(always)]
    fn step_any<S: Simd>(&self, st: &mut StrangState<S>, h: f64, renormalize: bool) {
        let b = &self.body;
        macro_rules! arms {
            ($($p:literal, $q:literal);*) => {
                match (b.split_axes[1], b.split_axes[2], b.field.is_some()) {
                    $(
                        ($p, $q, false) => strang_step::<S, $p, $q, false>(b, st, h, renormalize),
                        ($p, $q, true) => strang_step::<S, $p, $q, true>(b, st, h, renormalize),
                    )*
                    (_, _, false) => strang_step::<S, 2, 1, false>(b, st, h, renormalize),
                    (_, _, true) => strang_step::<S, 2, 1, true>(b, st, h, renormalize),
                }
            };
        }
        arms!(0, 1; 0, 2; 1, 0; 1, 2; 2, 0)
    }

    /// The published state: the stored one advanced by the closing outer flow of its lag.
    #[inline(always)]
    fn publish<S: Simd>(&self, st: &StrangState<S>) -> StrangState<S> {
        let mut out = *st;
        match self.body.field {
            Some(arm) => kick(&mut out, arm, st.lag),
            None => {
                let rate_p = self.body.split_rates[1];
                match self.body.split_axes[1] {
                    0 => turn::<S, 0>(&mut out, rate_p, st.lag),
                    1 => turn::<S, 1>(&mut out, rate_p, st.lag),
                    _ => turn::<S, 2>(&mut out, rate_p, st.lag),
                }
            }
        }
        out
    }
}

impl Kernel for Strang {
    const COMPONENTS: usize = 13;
    /// True: every flow of the step maps a state with a non-finite entry of Π or R to one with
    /// a non-finite entry (IEEE arithmetic: ∞ · 0, ∞ − ∞ and every operation on a NaN are NaN,
    /// ∞ plus a finite number is ∞).
    /// - A turn about axis i leaves Πᵢ and column i of R as they are, and rotates each other
    ///   pair `(u, v)` (of Π, or of a row of R) into `(c u + s v, c v − s u)` with (s, c) finite
    ///   and not both zero, or both NaN (a non-finite angle: `trig::sin_cos` gives NaN beyond
    ///   its range): a non-finite u or v gives a non-finite result.
    /// - `R ← R M` (Rodrigues, the Newton–Schulz step) sums in entry (r, j) every entry (r, m)
    ///   times M's entry (m, j): a non-finite entry of row r makes the whole row non-finite
    ///   (times a zero it is NaN); Π is left as it is.
    /// - The kick `Π ← Π + t F(R)` leaves R as it is, and a non-finite Πᵢ stays non-finite.
    const NON_FINITE_PERSISTS: bool = true;
    type State<S: Simd> = StrangState<S>;

    fn name(&self) -> String {
        "splitting(strang)".into()
    }
    fn init_lane(&self, pi: [f64; 3], r: [f64; 9]) -> Option<Vec<f64>> {
        if !pi.iter().chain(&r).all(|x| x.is_finite()) {
            return None;
        }
        let mut v = Vec::with_capacity(13);
        v.extend(pi);
        v.extend(r);
        v.push(0.0);
        Some(v)
    }
    #[inline(always)]
    fn load<S: Simd>(&self, s: S, group: &[f64], off: usize) -> StrangState<S> {
        let [lag] = load_n(s, group, 12, off);
        StrangState {
            pi: load_n(s, group, 0, off),
            r: load_n(s, group, 3, off),
            lag,
        }
    }
    #[inline(always)]
    fn store<S: Simd>(&self, st: &StrangState<S>, group: &mut [f64], off: usize) {
        store_n(&st.pi, group, 0, off);
        store_n(&st.r, group, 3, off);
        store_n(&[st.lag], group, 12, off);
    }
    #[inline(always)]
    fn step<S: Simd>(
        &self,
        st: &mut StrangState<S>,
        _group: &[f64],
        _off: usize,
        h: f64,
        renormalize: bool,
    ) {
        self.step_any(st, h, renormalize)
    }
    fn run_schedule(
        &self,
        level: Level,
        groups: &mut [f64],
        schedule: &Schedule<'_>,
        execution: Execution,
    ) -> Result<(), BatchError> {
        let b = &self.body;
        macro_rules! arms {
            ($($p:literal, $q:literal);*) => {
                match (b.split_axes[1], b.split_axes[2], b.field.is_some()) {
                    $(
                        ($p, $q, false) => engine::run(level, &StrangFixed::<$p, $q, false>(self.clone()), groups, schedule, execution),
                        ($p, $q, true) => engine::run(level, &StrangFixed::<$p, $q, true>(self.clone()), groups, schedule, execution),
                    )*
                    (_, _, false) => engine::run(level, &StrangFixed::<2, 1, false>(self.clone()), groups, schedule, execution),
                    (_, _, true) => engine::run(level, &StrangFixed::<2, 1, true>(self.clone()), groups, schedule, execution),
                }
            };
        }
        arms!(0, 1; 0, 2; 1, 0; 1, 2; 2, 0)
    }
    #[inline(always)]
    fn select<S: Simd>(m: M<S>, a: &StrangState<S>, b: &StrangState<S>) -> StrangState<S> {
        StrangState {
            pi: select_n(m, &a.pi, &b.pi),
            r: select_n(m, &a.r, &b.r),
            lag: m.select(a.lag, b.lag),
        }
    }
    #[inline(always)]
    fn finite<S: Simd>(&self, st: &StrangState<S>) -> M<S> {
        finite_all(&st.pi, &st.r)
    }
    #[inline(always)]
    fn published<S: Simd>(&self, st: &StrangState<S>) -> ([F<S>; 3], [F<S>; 9]) {
        let p = self.publish(st);
        (p.pi, p.r)
    }
    #[inline(always)]
    fn observe<S: Simd>(&self, st: &StrangState<S>) -> (F<S>, Option<F<S>>) {
        let p = self.publish(st);
        let inv = self.body.inv_moments;
        let pi = p.pi;
        let two_h = pi[2].mul_add(
            pi[2] * inv[2],
            pi[1].mul_add(pi[1] * inv[1], pi[0] * (pi[0] * inv[0])),
        );
        let kinetic = two_h * 0.5;
        match self.body.field {
            Some(m) => {
                let m = splat_n(p.r[0].s, m);
                let v = p.r[8].mul_add(m[2], p.r[7].mul_add(m[1], p.r[6] * m[0]));
                (kinetic + v, None)
            }
            None => {
                let c = pi[2].mul_add(pi[2], pi[1].mul_add(pi[1], pi[0] * pi[0]));
                (kinetic, Some(c))
            }
        }
    }
    fn has_casimir(&self) -> bool {
        self.body.field.is_none()
    }
    fn renormalizes(&self) -> bool {
        true
    }
    fn symmetric(&self) -> bool {
        true
    }
    fn build_error(&self) -> IntegratorError {
        IntegratorError::NonFinite {
            what: "momentum μ"
        }
    }
    fn step_error(&self) -> IntegratorError {
        IntegratorError::NonFinite {
            what: "momentum μ_{k+1}",
        }
    }
}

/// Lanes where every entry of `a` and `b` is finite: `x · 0 = 0` exactly for finite x and NaN
/// otherwise, summed in two chains (fixed-length loops, unrolled: the state stays in registers).
#[inline(always)]
pub(crate) fn finite_all<S: Simd, const A: usize, const B: usize>(
    a: &[F<S>; A],
    b: &[F<S>; B],
) -> M<S> {
    let s = a[0].s;
    let zero = F::splat(s, 0.0);
    let mut x = zero;
    for v in a {
        x = v.mul_add(zero, x);
    }
    let mut y = zero;
    for v in b {
        y = v.mul_add(zero, y);
    }
    (x + y).eq(zero)
}

impl<const P: usize, const Q: usize, const FIELD: bool> Kernel for StrangFixed<P, Q, FIELD> {
    const COMPONENTS: usize = Strang::COMPONENTS;
    const NON_FINITE_PERSISTS: bool = Strang::NON_FINITE_PERSISTS;
    type State<S: Simd> = StrangState<S>;
    fn name(&self) -> String {
        self.0.name()
    }
    fn init_lane(&self, pi: [f64; 3], r: [f64; 9]) -> Option<Vec<f64>> {
        self.0.init_lane(pi, r)
    }
    #[inline(always)]
    fn load<S: Simd>(&self, s: S, group: &[f64], off: usize) -> StrangState<S> {
        self.0.load(s, group, off)
    }
    #[inline(always)]
    fn store<S: Simd>(&self, st: &StrangState<S>, group: &mut [f64], off: usize) {
        self.0.store(st, group, off)
    }
    #[inline(always)]
    fn step<S: Simd>(
        &self,
        st: &mut StrangState<S>,
        _group: &[f64],
        _off: usize,
        h: f64,
        renormalize: bool,
    ) {
        strang_step::<S, P, Q, FIELD>(&self.0.body, st, h, renormalize)
    }
    #[inline(always)]
    fn select<S: Simd>(m: M<S>, a: &StrangState<S>, b: &StrangState<S>) -> StrangState<S> {
        Strang::select(m, a, b)
    }
    #[inline(always)]
    fn finite<S: Simd>(&self, st: &StrangState<S>) -> M<S> {
        self.0.finite(st)
    }
    #[inline(always)]
    fn published<S: Simd>(&self, st: &StrangState<S>) -> ([F<S>; 3], [F<S>; 9]) {
        self.0.published(st)
    }
    #[inline(always)]
    fn observe<S: Simd>(&self, st: &StrangState<S>) -> (F<S>, Option<F<S>>) {
        self.0.observe(st)
    }
    fn has_casimir(&self) -> bool {
        self.0.has_casimir()
    }
    fn symmetric(&self) -> bool {
        true
    }
    fn renormalizes(&self) -> bool {
        true
    }
    fn build_error(&self) -> IntegratorError {
        self.0.build_error()
    }
    fn step_error(&self) -> IntegratorError {
        self.0.step_error()
    }
}
