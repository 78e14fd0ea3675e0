//! The plain competitor of the trade, shared by `benches/splitting.rs`, `benches/integrators.rs`,
//! `examples/step_cost.rs` and `tests/hand_rk4.rs`: classical RK4 on (q, Π) written as anyone
//! would with nalgebra.

use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};

/// The plain competitor: classical RK4 on (q, Π) ∈ ℝ⁴ × ℝ³ for a body with principal moments
/// `1/inv_i` and a constant body-frame gravity arm `mgchi` (zero for the free body), written as
/// anyone would with nalgebra: `q̇ = ½ q ⊗ (0, Ω)`, `Π̇ = Π × Ω + Rᵀe₃ × mgχ` (the heavy top's
/// `Π̇ = Π × Ω + m g Γ × χ`, Γ = Rᵀe₃), q renormalised once per step. `tests/hand_rk4.rs` checks
/// that it follows `QuaternionRk4`'s trajectory.
///
/// `GRAVITY` is a compile-time switch, as a hand-written free-body step simply has no gravity
/// code: a run-time `mgχ ≠ 0` test in each stage costs the free-body step ~40 % (it was
/// measured at 1.45× the branch-free step) and would flatter every ratio against it.
#[derive(Clone)]
pub struct HandRk4<const GRAVITY: bool> {
    /// 1/Iᵢ.
    pub inv_i: Vector3<f64>,
    /// The body-frame gravity arm mgχ (read only with `GRAVITY`).
    pub mgchi: Vector3<f64>,
    /// The attitude quaternion.
    pub q: Quaternion<f64>,
    /// Π.
    pub pi: Vector3<f64>,
}

impl<const GRAVITY: bool> HandRk4<GRAVITY> {
    /// The body with principal moments `moments` and gravity arm `mgchi` at Π₀ and attitude R₀.
    pub fn new(
        moments: [f64; 3],
        mgchi: Vector3<f64>,
        pi0: Vector3<f64>,
        r0: &Matrix3<f64>,
    ) -> Self {
        let r = Rotation3::from_matrix_unchecked(*r0);
        Self {
            inv_i: Vector3::from(moments).map(|i| 1.0 / i),
            mgchi,
            q: UnitQuaternion::from_rotation_matrix(&r).into_inner(),
            pi: pi0,
        }
    }
    #[inline]
    fn rate(&self, q: &Quaternion<f64>, pi: &Vector3<f64>) -> (Quaternion<f64>, Vector3<f64>) {
        let omega = pi.component_mul(&self.inv_i);
        let dq = (q * Quaternion::from_imag(omega)) * 0.5;
        let mut dpi = pi.cross(&omega);
        if GRAVITY {
            // Rᵀe₃ for R = R(q/|q|): the third row of the rotation matrix.
            let (w, x, y, z) = (q.w, q.i, q.j, q.k);
            let s = 1.0 / q.norm_squared();
            let up = Vector3::new(
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                w * w - x * x - y * y + z * z,
            ) * s;
            dpi += up.cross(&self.mgchi);
        }
        (dq, dpi)
    }
    /// One classical RK4 step of size h, q renormalised.
    #[inline]
    pub fn step(&mut self, h: f64) {
        let (q, pi) = (self.q, self.pi);
        let (l1, k1) = self.rate(&q, &pi);
        let (l2, k2) = self.rate(&(q + l1 * (0.5 * h)), &(pi + k1 * (0.5 * h)));
        let (l3, k3) = self.rate(&(q + l2 * (0.5 * h)), &(pi + k2 * (0.5 * h)));
        let (l4, k4) = self.rate(&(q + l3 * h), &(pi + k3 * h));
        let q1 = q + (l1 + (l2 + l3) * 2.0 + l4) * (h / 6.0);
        self.pi = pi + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0);
        self.q = q1 / q1.norm();
    }
}
