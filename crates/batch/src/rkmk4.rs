//! The Runge–Kutta–Munthe-Kaas method of order 4 on SO(3) × so(3)*, on lanes: the operations of
//! the scalar `integrators::Rkmk4`, in its order.

use crate::engine::Kernel;
use crate::lanes::{k, load_n, scale_n, select_n, splat_n, store_n, F, M};
use crate::rk4::{body_energy, cross};
use crate::splitting::finite_all;
use crate::trig::{sin_cos, C1, C2, C3, C4, C5, C6, S1, S2, S3, S4, S5, S6};
use crate::BodyModel;
use integrators::IntegratorError;
use pulp::Simd;

/// `integrators::Rkmk4` for a [`BodyModel`], lane by lane: classical RK4 on the local coordinate
/// Θ of `R(t) = R_k exp(Θ(t))`, `Θ̇ = (d^L exp_Θ)⁻¹ Ω`, together with Π, with the two brackets of
/// Munthe-Kaas and Owren (Phil. Trans. R. Soc. A 357, 1999) that carry the dexp⁻¹ correction to
/// order 4 (derivation and signs on the scalar method's page): with `Ω_i = 𝕀⁻¹Π_i`,
///
/// ```text
/// L_i = Π_i × Ω_i + F(R_i),   R_i = R_k exp(Θ_i),   Π_i = Π_k + h Σ_j a_ij L_j,
/// Θ₂ = (h/2) Ω₁,   Θ₃ = (h/2) (Ω₂ + (h/4) Ω₁ × Ω₂),   Θ₄ = h Ω₃,
/// R_{k+1} = R_k + R_k (exp(Θ) − I),   Θ = (h/6) (Ω₁ + 2Ω₂ + 2Ω₃ + Ω₄ + (h/2) Ω₁ × Ω₄),
/// Π_{k+1} = Π_k + (h/6) (L₁ + 2L₂ + 2L₃ + L₄),
/// ```
///
/// F = Γ × m g χ, Γ = Rᵀe₃ in a field (the stage attitudes R_i only there: the free body's stages
/// never touch R), and the attitude renormalized every `integrators::RENORMALIZE_AFTER` steps as
/// the scalar method does. Order 4, explicit; keeps R on SO(3) and nothing else.
///
/// **The same operations as the scalar method.** Each lane performs the scalar step's products
/// and sums in its order, with no fused multiply-add (the scalar library is compiled without
/// contraction), and takes `exp`'s coefficients `(sin θ/θ, (1 − cos θ)/θ²)` as `So3::exp` does —
/// its Taylor series below θ = 0.1, its half-angle polynomials up to θ = π/2, chosen lane by lane
/// with a select instead of a branch. So wherever every rotation of a step is at most π/2
/// (h|Ω| ≲ π/2, every usual step) a lane's trajectory is the scalar `Rkmk4`'s bit for bit (test
/// `rkmk4_lanes_are_the_scalar_rkmk4`); beyond, the lanes' `sin`/`cos` of θ/2 ([`crate::trig`])
/// differ from the scalar's by up to an ulp, and so do the coefficients.
#[derive(Debug, Clone)]
pub struct Rkmk4 {
    body: BodyModel,
}

impl Rkmk4 {
    /// RKMK4 for `body`.
    pub fn new(body: BodyModel) -> Self {
        Self { body }
    }
    /// The body.
    pub fn body(&self) -> &BodyModel {
        &self.body
    }
}

/// Π and R (row-major) of one vector of lanes.
#[derive(Clone, Copy, Debug)]
pub struct Rkmk4State<S: Simd> {
    pi: [F<S>; 3],
    r: [F<S>; 9],
}

/// θ² below which `So3::exp` takes its Taylor series (`lie_groups::so3::SMALL_ANGLE`² = 0.1²).
const SERIES_SQ: f64 = 0.1 * 0.1;
/// (π/2)²: up to it `So3::exp` takes the half-angle polynomials in θ²/4.
const HALF_PI_SQ: f64 = core::f64::consts::FRAC_PI_2 * core::f64::consts::FRAC_PI_2;

/// `c₀ + c₁x + c₂x² + c₃x³ + c₄x⁴` as `lie_groups`' `quartic` forms it (Estrin).
#[inline(always)]
fn quartic<S: Simd>(x: F<S>, c: [f64; 5]) -> F<S> {
    let s = x.s;
    let x2 = x * x;
    (k(s, c[0]) + x * c[1]) + x2 * ((k(s, c[2]) + x * c[3]) + x2 * c[4])
}

/// The coefficients `(a, b) = (sin θ/θ, (1 − cos θ)/θ²)` of `exp(ω̂) = I + aω̂ + bω̂²` from
/// θ² = |ω|², with the operations of `So3::exp`'s `exp_coeffs`:
///
/// - θ < 0.1: `sin θ/θ = 1 − θ²/6 + θ⁴/120 − θ⁶/5040 + θ⁸/362880` and
///   `(1 − cos θ)/θ² = ½ − θ²/24 + θ⁴/720 − θ⁶/40320 + θ⁸/3628800` in θ²;
/// - θ ≤ π/2: with z = θ²/4 = h², `q = sin h/(2h)` and `cos h` from the fdlibm kernels as even
///   polynomials in z (`lie_groups`' `half_sinc_cos`), then `a = 2q cos h`, `b = 2q²`
///   (`sin θ = 2 sin h cos h`, `1 − cos θ = 2 sin² h`: products, no cancellation);
/// - beyond: `q = sin(θ/2)/θ` with the lanes' [`sin_cos`] (the scalar takes its own kernels or
///   libm: up to an ulp apart), only evaluated when some lane needs it.
///
/// Each lane selects its own branch, so its bits depend on its θ² alone. A non-finite θ² gives NaN.
#[inline(always)]
fn exp_coeffs<S: Simd>(t2: F<S>) -> (F<S>, F<S>) {
    let s = t2.s;
    let series = (
        quartic(
            t2,
            [1.0, -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0],
        ),
        quartic(
            t2,
            [
                0.5,
                -1.0 / 24.0,
                1.0 / 720.0,
                -1.0 / 40320.0,
                1.0 / 3628800.0,
            ],
        ),
    );
    let small = t2.lt(k(s, SERIES_SQ));
    // Every lane below θ = 0.1 (the usual step): the series alone. Otherwise each lane takes its
    // own branch by a select, so a lane's bits never depend on which path its neighbours took.
    if !small.not().any() {
        return series;
    }
    let (q, ch) = half_angle(t2);
    let q2 = q * 2.0;
    (
        small.select(series.0, q2 * ch),
        small.select(series.1, q2 * q),
    )
}

/// `(sin h/θ, cos h)` for h = θ/2 from θ² (the branches of `exp_coeffs` beyond the series): up to
/// θ = π/2 `lie_groups`' `half_sinc_cos(θ²/4)` operation for operation, beyond it from √θ² and
/// the lanes' [`sin_cos`] (only when some lane is there).
#[inline(always)]
fn half_angle<S: Simd>(t2: F<S>) -> (F<S>, F<S>) {
    let s = t2.s;
    let z = t2 * 0.25;
    let w = z * z;
    let rs = (k(s, S2) + z * (k(s, S3) + z * S4)) + (z * w) * (k(s, S5) + z * S6);
    let mut q = k(s, 0.5) + (z * (k(s, S1) + z * rs)) * 0.5;
    let rc =
        z * (k(s, C1) + z * (k(s, C2) + z * C3)) + (w * w) * (k(s, C4) + z * (k(s, C5) + z * C6));
    let hz = z * 0.5;
    let wc = k(s, 1.0) - hz;
    let mut ch = wc + (((k(s, 1.0) - wc) - hz) + z * rc);
    let mid = t2.le(k(s, HALF_PI_SQ));
    if mid.not().any() {
        let t = t2.sqrt();
        let inv_t = k(s, 1.0) / t;
        let (sh, chg) = sin_cos(t * 0.5);
        q = mid.select(q, sh * inv_t);
        ch = mid.select(ch, chg);
    }
    (q, ch)
}

/// `exp(ω̂) − I = aω̂ + bω̂²` entry by entry (row-major), as `So3`'s `rodrigues_increment`.
#[inline(always)]
fn increment<S: Simd>(w: [F<S>; 3]) -> [F<S>; 9] {
    let [x, y, z] = w;
    let (a, b) = exp_coeffs(x * x + y * y + z * z);
    let (xy, xz, yz) = (b * (x * y), b * (x * z), b * (y * z));
    let (ax, ay, az) = (a * x, a * y, a * z);
    let nb = -b;
    [
        nb * (y * y + z * z),
        xy - az,
        xz + ay,
        xy + az,
        nb * (x * x + z * z),
        yz - ax,
        xz - ay,
        yz + ax,
        nb * (x * x + y * y),
    ]
}

// No closures on the lanes' path (`array::from_fn`, `map`, `then`): a closure is compiled
// without the instruction set of the function that calls it unless it is inlined, and then
// passes its vectors through memory; the loops below are unrolled in place.

/// Row `i` of `R + R D` (`So3::exp_compose`: `R + mul3(R, D)`).
#[inline(always)]
fn compose_row<S: Simd>(r: &[F<S>; 9], d: &[F<S>; 9], i: usize) -> [F<S>; 3] {
    let (r0, r1, r2) = (r[3 * i], r[3 * i + 1], r[3 * i + 2]);
    let mut o = [r0; 3];
    for j in 0..3 {
        o[j] = r[3 * i + j] + ((r0 * d[j] + r1 * d[3 + j]) + r2 * d[6 + j]);
    }
    o
}

/// `a + b t` entry by entry (`Vector::axpy`: `a + b · t`).
#[inline(always)]
fn axpy<S: Simd>(a: [F<S>; 3], t: f64, b: [F<S>; 3]) -> [F<S>; 3] {
    let mut o = a;
    for i in 0..3 {
        o[i] = a[i] + b[i] * t;
    }
    o
}

/// `a + 2 (b + c) + d` entry by entry, as the scalar step sums its stages.
#[inline(always)]
fn stage_sum<S: Simd>(a: [F<S>; 3], b: [F<S>; 3], c: [F<S>; 3], d: [F<S>; 3]) -> [F<S>; 3] {
    let mut o = a;
    for i in 0..3 {
        o[i] = (a[i] + (b[i] + c[i]) * 2.0) + d[i];
    }
    o
}

/// The vertical Γ = Rᵀe₃ of the stage attitude `R exp(Θ)`: its third row.
#[inline(always)]
fn stage_vertical<S: Simd>(r: &[F<S>; 9], theta: [F<S>; 3]) -> [F<S>; 3] {
    compose_row(r, &increment(theta), 2)
}

/// `u · v` as nalgebra's `dot` sums it (in index order, no fused multiply-add).
#[inline(always)]
fn dot<S: Simd>(u: [F<S>; 3], v: [F<S>; 3]) -> F<S> {
    (u[0] * v[0] + u[1] * v[1]) + u[2] * v[2]
}

/// `So3::normalize`: one Newton–Schulz step `R ← R (3I − RᵀR)/2`, operation for operation.
#[inline(always)]
pub(crate) fn normalize<S: Simd>(r: &mut [F<S>; 9]) {
    let s = r[0].s;
    let (c0, c1, c2) = ([r[0], r[3], r[6]], [r[1], r[4], r[7]], [r[2], r[5], r[8]]);
    let (d01, d02, d12) = (dot(c0, c1) * -0.5, dot(c0, c2) * -0.5, dot(c1, c2) * -0.5);
    let m = [
        k(s, 1.5) - dot(c0, c0) * 0.5,
        d01,
        d02,
        d01,
        k(s, 1.5) - dot(c1, c1) * 0.5,
        d12,
        d02,
        d12,
        k(s, 1.5) - dot(c2, c2) * 0.5,
    ];
    let old = *r;
    for i in 0..3 {
        let (r0, r1, r2) = (old[3 * i], old[3 * i + 1], old[3 * i + 2]);
        for j in 0..3 {
            r[3 * i + j] = (r0 * m[j] + r1 * m[3 + j]) + r2 * m[6 + j];
        }
    }
}

impl Rkmk4 {
    /// `(Ω, Π̇)` at a stage: Ω = 𝕀⁻¹Π (`a_i Π_i`), `Π̇ = Π × Ω + F(Γ)` with
    /// `F = −(m g χ × Γ)` at the stage's vertical Γ in a field.
    #[inline(always)]
    fn rates<S: Simd>(&self, pi: [F<S>; 3], g: Option<[F<S>; 3]>) -> ([F<S>; 3], [F<S>; 3]) {
        let a = self.body.inv_moments;
        let om = [pi[0] * a[0], pi[1] * a[1], pi[2] * a[2]];
        let mut dpi = cross(pi, om);
        if let (Some(arm), Some(g)) = (self.body.field, g) {
            let f = cross(splat_n(g[0].s, arm), g);
            dpi = [dpi[0] + -f[0], dpi[1] + -f[1], dpi[2] + -f[2]];
        }
        (om, dpi)
    }

    /// One step: the stages, then `R_{k+1} = R_k + R_k (exp Θ − I)`.
    #[inline(always)]
    fn step_lanes<S: Simd, const FIELD: bool>(
        &self,
        st: &mut Rkmk4State<S>,
        h: f64,
        renormalize: bool,
    ) {
        let half = 0.5 * h;
        let (pi, r) = (st.pi, st.r);
        // Γᵢ = Rᵢᵀe₃ of the stage attitudes Rᵢ = R_k exp(Θᵢ), in a field only.
        let g1 = if FIELD {
            Some([r[6], r[7], r[8]])
        } else {
            None
        };
        let (x1, l1) = self.rates(pi, g1);
        let g2 = if FIELD {
            Some(stage_vertical(&r, scale_n(&x1, half)))
        } else {
            None
        };
        let (x2, l2) = self.rates(axpy(pi, half, l1), g2);
        let g3 = if FIELD {
            let t3 = scale_n(&axpy(x2, 0.25 * h, cross(x1, x2)), half);
            Some(stage_vertical(&r, t3))
        } else {
            None
        };
        let (x3, l3) = self.rates(axpy(pi, half, l2), g3);
        let g4 = if FIELD {
            Some(stage_vertical(&r, scale_n(&x3, h)))
        } else {
            None
        };
        let (x4, l4) = self.rates(axpy(pi, h, l3), g4);
        let h6 = h / 6.0;
        let sum = stage_sum(x1, x2, x3, x4);
        let theta = scale_n(&axpy(sum, 0.5 * h, cross(x1, x4)), h6);
        st.pi = axpy(pi, h6, stage_sum(l1, l2, l3, l4));
        let d = increment(theta);
        for i in 0..3 {
            let row = compose_row(&r, &d, i);
            st.r[3 * i] = row[0];
            st.r[3 * i + 1] = row[1];
            st.r[3 * i + 2] = row[2];
        }
        if renormalize {
            normalize(&mut st.r);
        }
    }
}

impl Kernel for Rkmk4 {
    const COMPONENTS: usize = 12;
    type State<S: Simd> = Rkmk4State<S>;

    fn name(&self) -> String {
        "rkmk4(exp)".into()
    }
    fn init_lane(&self, pi: [f64; 3], r: [f64; 9]) -> Option<Vec<f64>> {
        if !pi.iter().chain(&r).all(|x| x.is_finite()) {
            return None;
        }
        let mut v = Vec::with_capacity(12);
        v.extend(pi);
        v.extend(r);
        Some(v)
    }
    #[inline(always)]
    fn load<S: Simd>(&self, s: S, group: &[f64], off: usize) -> Rkmk4State<S> {
        Rkmk4State {
            pi: load_n(s, group, 0, off),
            r: load_n(s, group, 3, off),
        }
    }
    #[inline(always)]
    fn store<S: Simd>(&self, st: &Rkmk4State<S>, group: &mut [f64], off: usize) {
        store_n(&st.pi, group, 0, off);
        store_n(&st.r, group, 3, off);
    }
    #[inline(always)]
    fn step<S: Simd>(
        &self,
        st: &mut Rkmk4State<S>,
        _group: &[f64],
        _off: usize,
        h: f64,
        renormalize: bool,
    ) {
        if self.body.field.is_some() {
            self.step_lanes::<S, true>(st, h, renormalize)
        } else {
            self.step_lanes::<S, false>(st, h, renormalize)
        }
    }
    #[inline(always)]
    fn select<S: Simd>(m: M<S>, a: &Rkmk4State<S>, b: &Rkmk4State<S>) -> Rkmk4State<S> {
        Rkmk4State {
            pi: select_n(m, &a.pi, &b.pi),
            r: select_n(m, &a.r, &b.r),
        }
    }
    #[inline(always)]
    fn finite<S: Simd>(&self, st: &Rkmk4State<S>) -> M<S> {
        finite_all(&st.pi, &st.r)
    }
    #[inline(always)]
    fn published<S: Simd>(&self, st: &Rkmk4State<S>) -> ([F<S>; 3], [F<S>; 9]) {
        (st.pi, st.r)
    }
    #[inline(always)]
    fn observe<S: Simd>(&self, st: &Rkmk4State<S>) -> (F<S>, Option<F<S>>) {
        let g = if self.body.field.is_some() {
            Some([st.r[6], st.r[7], st.r[8]])
        } else {
            None
        };
        body_energy(&self.body, st.pi, g)
    }
    fn has_casimir(&self) -> bool {
        self.body.field.is_none()
    }
    fn renormalizes(&self) -> bool {
        true
    }
    /// Every `integrators::RENORMALIZE_AFTER` steps: one rounded product a step, as the scalar
    /// method counts them.
    fn renormalize_every(&self) -> u64 {
        integrators::RENORMALIZE_AFTER as u64
    }
    fn symmetric(&self) -> bool {
        false
    }
    fn build_error(&self) -> IntegratorError {
        IntegratorError::NonFinite {
            what: "momentum μ"
        }
    }
    fn step_error(&self) -> IntegratorError {
        IntegratorError::NonFinite {
            what: "RKMK4 stage (Θ, μ)",
        }
    }
}
