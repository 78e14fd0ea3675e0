//! The Strang splitting of the free rigid body and of a body in a uniform field, on lanes.

use crate::engine::Kernel;
use crate::lanes::{F, M};
use crate::trig::{rodrigues_coefficients, sin_cos};
use crate::BodyModel;
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
    let col = |j: usize| [r[j], r[3 + j], r[6 + j]];
    let dot = |u: [F<S>; 3], v: [F<S>; 3]| u[2].mul_add(v[2], u[1].mul_add(v[1], u[0] * v[0]));
    let (c0, c1, c2) = (col(0), col(1), col(2));
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
    let m = arm.map(|x| F::splat(s, x));
    let g = [st.r[6], st.r[7], st.r[8]];
    let f = [
        g[1].mul_add(m[2], -(g[2] * m[1])),
        g[2].mul_add(m[0], -(g[0] * m[2])),
        g[0].mul_add(m[1], -(g[1] * m[0])),
    ];
    for i in 0..3 {
        st.pi[i] = f[i].mul_add(t, st.pi[i]);
    }
}

impl Strang {
    /// One step with the split axes p, s as constants (their plane coordinates are then fixed
    /// offsets).
    #[inline(always)]
    fn step_axes<S: Simd, const P: usize, const Q: usize>(
        &self,
        st: &mut StrangState<S>,
        h: f64,
        renormalize: bool,
    ) {
        let s = st.lag.s;
        let [inv_r, rate_p, rate_s] = self.body.split_rates;
        let half = F::splat(s, 0.5 * h);
        let opening = st.lag + half;
        let full = F::splat(s, h);
        match self.body.field {
            Some(arm) => {
                kick(st, arm, opening);
                turn::<S, P>(st, rate_p, half);
            }
            None => turn::<S, P>(st, rate_p, opening),
        }
        // φ¹_h: R exp(hΠ/I_r) from the Π before the turn about a_s, then the turn.
        let w = st.pi.map(|p| p * (h * inv_r));
        compose_exp(&mut st.r, w);
        turn::<S, Q>(st, rate_s, full);
        if self.body.field.is_some() {
            turn::<S, P>(st, rate_p, half);
        }
        st.lag = half;
        if renormalize {
            normalize(&mut st.r);
        }
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
        let c = |i: usize| F::load(s, &group[i * crate::engine::GROUP + off..]);
        StrangState {
            pi: [c(0), c(1), c(2)],
            r: core::array::from_fn(|i| c(3 + i)),
            lag: c(12),
        }
    }
    #[inline(always)]
    fn store<S: Simd>(&self, st: &StrangState<S>, group: &mut [f64], off: usize) {
        let w = S::F64_LANES;
        let mut put = |i: usize, v: F<S>| {
            let at = i * crate::engine::GROUP + off;
            v.store(&mut group[at..at + w])
        };
        for i in 0..3 {
            put(i, st.pi[i]);
        }
        for i in 0..9 {
            put(3 + i, st.r[i]);
        }
        put(12, st.lag);
    }
    #[inline(always)]
    fn step<S: Simd>(&self, st: &mut StrangState<S>, h: f64, renormalize: bool) {
        match (self.body.split_axes[1], self.body.split_axes[2]) {
            (0, 1) => self.step_axes::<S, 0, 1>(st, h, renormalize),
            (0, 2) => self.step_axes::<S, 0, 2>(st, h, renormalize),
            (1, 0) => self.step_axes::<S, 1, 0>(st, h, renormalize),
            (1, 2) => self.step_axes::<S, 1, 2>(st, h, renormalize),
            (2, 0) => self.step_axes::<S, 2, 0>(st, h, renormalize),
            _ => self.step_axes::<S, 2, 1>(st, h, renormalize),
        }
    }
    #[inline(always)]
    fn select<S: Simd>(m: M<S>, a: &StrangState<S>, b: &StrangState<S>) -> StrangState<S> {
        StrangState {
            pi: core::array::from_fn(|i| m.select(a.pi[i], b.pi[i])),
            r: core::array::from_fn(|i| m.select(a.r[i], b.r[i])),
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
                let m = m.map(|x| F::splat(p.r[0].s, x));
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

/// Lanes where every entry of Π and R is finite: `x · 0 = 0` exactly for finite x and NaN
/// otherwise, summed in two chains.
#[inline(always)]
pub(crate) fn finite_all<S: Simd>(pi: &[F<S>], r: &[F<S>]) -> M<S> {
    let s = pi[0].s;
    let zero = F::splat(s, 0.0);
    let mut a = zero;
    let mut b = zero;
    for (i, &x) in pi.iter().chain(r).enumerate() {
        if i % 2 == 0 {
            a = x.mul_add(zero, a);
        } else {
            b = x.mul_add(zero, b);
        }
    }
    (a + b).eq(zero)
}
