//! Classical RK4 on (unit quaternion, body momentum), on lanes: the bits of the scalar
//! `integrators::baselines::QuaternionRk4`.

use crate::engine::Kernel;
use crate::lanes::{axpy_n, load_n, scale_n, select_n, splat_n, store_n, F, M};
use crate::splitting::finite_all;
use crate::BodyModel;
use integrators::IntegratorError;
use lie_groups::{LieGroup, So3};
use nalgebra::{Matrix3, UnitQuaternion};
use pulp::Simd;

/// `integrators::baselines::QuaternionRk4` for a [`BodyModel`], lane by lane: classical RK4 on
///
/// ```text
/// q̇ = ½ q ⊗ (0, Ω),   Π̇ = Π × Ω + F(R(q)),   Ω = 𝕀⁻¹Π,   F = Γ × m g χ (in a field)
/// ```
///
/// with q renormalised after each step. Order 4, explicit; keeps R on SO(3) and nothing else.
///
/// **The same bits as the scalar method.** Each lane performs the scalar step's operations in its
/// order — nalgebra's quaternion product, cross product and 4-vector norm, the homogeneous
/// rotation `R(q/|q|)` of the stages, the division by |q| — with no fused multiply-add (the scalar
/// library is compiled without contraction), so a lane's trajectory, energy and Casimir errors are
/// bit for bit those of `QuaternionRk4` (test `rk4_lanes_are_the_scalar_quaternion_rk4`).
#[derive(Debug, Clone)]
pub struct QuaternionRk4 {
    body: BodyModel,
}

impl QuaternionRk4 {
    /// RK4 on (q, Π) for `body`.
    pub fn new(body: BodyModel) -> Self {
        Self { body }
    }
    /// The body.
    pub fn body(&self) -> &BodyModel {
        &self.body
    }
}

/// q = (w, x, y, z) and Π of one vector of lanes.
#[derive(Clone, Copy, Debug)]
pub struct Rk4State<S: Simd> {
    q: [F<S>; 4],
    pi: [F<S>; 3],
}

/// `a × b` as nalgebra writes it.
#[inline(always)]
pub(crate) fn cross<S: Simd>(a: [F<S>; 3], b: [F<S>; 3]) -> [F<S>; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `(R₂₀, R₂₁, R₂₂)` of the homogeneous rotation `R(q/|q|)` of the scalar step's `rotation`:
/// Γ = Rᵀe₃.
#[inline(always)]
fn vertical<S: Simd>(q: [F<S>; 4]) -> [F<S>; 3] {
    let [w, x, y, z] = q;
    let s = F::splat(w.s, 2.0) / (w * w + x * x + y * y + z * z);
    let (wx, wy) = (w * x, w * y);
    let (xx, xz) = (x * x, x * z);
    let (yy, yz) = (y * y, y * z);
    [
        (xz - wy) * s,
        (yz + wx) * s,
        F::splat(w.s, 1.0) - (xx + yy) * s,
    ]
}

/// `Γ × m g χ` as the scalar step forms it: `−(m g χ × Γ)`.
#[inline(always)]
fn field_force<S: Simd>(arm: [f64; 3], g: [F<S>; 3]) -> [F<S>; 3] {
    let f = cross(splat_n(g[0].s, arm), g);
    [-f[0], -f[1], -f[2]]
}

impl QuaternionRk4 {
    /// `(q̇, Π̇)` at a stage.
    #[inline(always)]
    fn rate<S: Simd>(&self, q: [F<S>; 4], pi: [F<S>; 3]) -> ([F<S>; 4], [F<S>; 3]) {
        let a = self.body.inv_moments;
        let om = [pi[0] * a[0], pi[1] * a[1], pi[2] * a[2]];
        let mut dpi = cross(pi, om);
        if let Some(arm) = self.body.field {
            let f = field_force(arm, vertical(q));
            dpi = [dpi[0] + f[0], dpi[1] + f[1], dpi[2] + f[2]];
        }
        // q ⊗ (0, Ω) in nalgebra's order, the zero scalar part multiplied as it is there.
        let [w, x, y, z] = q;
        let zero = F::splat(w.s, 0.0);
        let (rw, rx, ry, rz) = (zero, om[0], om[1], om[2]);
        let p = [
            w * rw - x * rx - y * ry - z * rz,
            w * rx + x * rw + y * rz - z * ry,
            w * ry - x * rz + y * rw + z * rx,
            w * rz + x * ry - y * rx + z * rw,
        ];
        (scale_n(&p, 0.5), dpi)
    }
    /// The energy and Casimir of the body ([`body_energy`]).
    #[inline(always)]
    fn energy<S: Simd>(&self, pi: [F<S>; 3], g: Option<[F<S>; 3]>) -> (F<S>, Option<F<S>>) {
        body_energy(&self.body, pi, g)
    }
}

/// The energy `½ Π·Ω (+ m g χ·Γ)` and Casimir |Π|² of `body` at Π and Γ = Rᵀe₃ as the scalar
/// `System` forms them (no fused multiply-add).
#[inline(always)]
pub(crate) fn body_energy<S: Simd>(
    body: &BodyModel,
    pi: [F<S>; 3],
    g: Option<[F<S>; 3]>,
) -> (F<S>, Option<F<S>>) {
    let a = body.inv_moments;
    let om = [pi[0] * a[0], pi[1] * a[1], pi[2] * a[2]];
    let kinetic = (pi[0] * om[0] + pi[1] * om[1] + pi[2] * om[2]) * 0.5;
    match (body.field, g) {
        (Some(m), Some(g)) => (kinetic + (g[0] * m[0] + g[1] * m[1] + g[2] * m[2]), None),
        (Some(_), None) => (kinetic, None),
        (None, _) => (kinetic, Some(pi[0] * pi[0] + pi[1] * pi[1] + pi[2] * pi[2])),
    }
}

impl Kernel for QuaternionRk4 {
    const COMPONENTS: usize = 7;
    type State<S: Simd> = Rk4State<S>;

    fn name(&self) -> String {
        "rk4(quaternion)".into()
    }
    fn init_lane(&self, pi: [f64; 3], r: [f64; 9]) -> Option<Vec<f64>> {
        if !pi.iter().chain(&r).all(|x| x.is_finite()) {
            return None;
        }
        // q₀ exactly as the scalar method makes it from R₀.
        let rot = So3::from_matrix_unchecked(&Matrix3::from_row_slice(&r));
        let q = UnitQuaternion::from(rot).into_inner();
        Some(vec![q.w, q.i, q.j, q.k, pi[0], pi[1], pi[2]])
    }
    #[inline(always)]
    fn load<S: Simd>(&self, s: S, group: &[f64], off: usize) -> Rk4State<S> {
        Rk4State {
            q: load_n(s, group, 0, off),
            pi: load_n(s, group, 4, off),
        }
    }
    #[inline(always)]
    fn store<S: Simd>(&self, st: &Rk4State<S>, group: &mut [f64], off: usize) {
        store_n(&st.q, group, 0, off);
        store_n(&st.pi, group, 4, off);
    }
    #[inline(always)]
    fn step<S: Simd>(
        &self,
        st: &mut Rk4State<S>,
        _group: &[f64],
        _off: usize,
        h: f64,
        _renormalize: bool,
    ) {
        let half = 0.5 * h;
        let (q, pi) = (st.q, st.pi);
        let (l1, k1) = self.rate(q, pi);
        let (l2, k2) = self.rate(axpy_n(&q, &l1, half), axpy_n(&pi, &k1, half));
        let (l3, k3) = self.rate(axpy_n(&q, &l2, half), axpy_n(&pi, &k2, half));
        let (l4, k4) = self.rate(axpy_n(&q, &l3, h), axpy_n(&pi, &k3, h));
        let h6 = h / 6.0;
        let mut q1 = q;
        for i in 0..4 {
            q1[i] = q[i] + (l1[i] + (l2[i] + l3[i]) * 2.0 + l4[i]) * h6;
        }
        let mut pi1 = pi;
        for i in 0..3 {
            pi1[i] = pi[i] + (k1[i] + (k2[i] + k3[i]) * 2.0 + k4[i]) * h6;
        }
        // |q| as nalgebra's 4-vector norm: coordinates (x, y, z, w), (x² + z²) + (y² + w²).
        let [w, x, y, z] = q1;
        let n = ((x * x + z * z) + (y * y + w * w)).sqrt();
        for c in q1.iter_mut() {
            *c = *c / n;
        }
        st.q = q1;
        st.pi = pi1;
    }
    #[inline(always)]
    fn select<S: Simd>(m: M<S>, a: &Rk4State<S>, b: &Rk4State<S>) -> Rk4State<S> {
        Rk4State {
            q: select_n(m, &a.q, &b.q),
            pi: select_n(m, &a.pi, &b.pi),
        }
    }
    #[inline(always)]
    fn finite<S: Simd>(&self, st: &Rk4State<S>) -> M<S> {
        finite_all(&st.pi, &st.q)
    }
    #[inline(always)]
    fn published<S: Simd>(&self, st: &Rk4State<S>) -> ([F<S>; 3], [F<S>; 9]) {
        let [w, x, y, z] = st.q;
        let s = F::splat(w.s, 2.0) / (w * w + x * x + y * y + z * z);
        let (wx, wy, wz) = (w * x, w * y, w * z);
        let (xx, xy, xz) = (x * x, x * y, x * z);
        let (yy, yz, zz) = (y * y, y * z, z * z);
        let one = F::splat(w.s, 1.0);
        let r = [
            one - (yy + zz) * s,
            (xy - wz) * s,
            (xz + wy) * s,
            (xy + wz) * s,
            one - (xx + zz) * s,
            (yz - wx) * s,
            (xz - wy) * s,
            (yz + wx) * s,
            one - (xx + yy) * s,
        ];
        (st.pi, r)
    }
    #[inline(always)]
    fn observe<S: Simd>(&self, st: &Rk4State<S>) -> (F<S>, Option<F<S>>) {
        let g = if self.body.field.is_some() {
            Some(vertical(st.q))
        } else {
            None
        };
        self.energy(st.pi, g)
    }
    fn has_casimir(&self) -> bool {
        self.body.field.is_none()
    }
    fn renormalizes(&self) -> bool {
        false
    }
    fn symmetric(&self) -> bool {
        false
    }
    /// With the attitude R₀ as given: the scalar method reads V at R₀ itself before its first
    /// step, not at R(q₀).
    fn initial_observation(&self, pi: [f64; 3], r: [f64; 9]) -> (f64, Option<f64>) {
        let s = pulp::Scalar;
        let p = splat_n(s, pi);
        let g = splat_n(s, [r[6], r[7], r[8]]);
        let (e, c) = self.energy(p, Some(g));
        (e.v, c.map(|c| c.v))
    }
    fn build_error(&self) -> IntegratorError {
        IntegratorError::NonFinite {
            what: "momentum Π"
        }
    }
    fn step_error(&self) -> IntegratorError {
        IntegratorError::NonFinite {
            what: "RK4 state (q, Π)_{k+1}",
        }
    }
}
