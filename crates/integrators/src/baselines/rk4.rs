//! The classical explicit Runge–Kutta method of order 4 on (unit quaternion, body momentum): the
//! textbook way of integrating a rigid body, kept as an honest baseline.
//!
//! The equations integrated, for any [`System<So3>`] (free rigid body, heavy top, …), are the
//! Lie–Poisson equations of [`crate::system`] with the attitude written as a quaternion
//! q = (w, x, y, z), R = R(q):
//!
//! ```text
//! q̇ = ½ q ⊗ (0, Ω),              Ω = ∂h/∂Π(Π)
//! Π̇ = ad*_Ω Π + F(R(q/|q|)),     ad*_Ω Π = Π × Ω,  F = −T*_e L_R dV(R)
//! ```
//!
//! (`q̇ = ½ q ⊗ (0, Ω)` is `Ṙ = R Ω̂` for the body angular velocity Ω.) Each step is one classical
//! RK4 step of this ODE in ℝ⁴ × ℝ³, followed by the renormalisation q ← q/|q|, so the rotation
//! stays orthogonal to round-off. Nothing else is preserved: the energy and the Casimir |Π|² drift
//! linearly in t (on the free rigid body 𝕀 = diag(1, 2, 3) the measured drift rate falls 32× when
//! h halves, see docs/work-precision.md), the price of its order 4 and its low cost. Stack only,
//! no heap allocation per step.

use super::quaternion_state::{momentum_rate, quaternion_rate, QuaternionState};
use crate::carried_state;
use crate::checks::check_state;
use crate::step_state::state_accessors;
use crate::{Integrator, IntegratorError, System};
use lie_groups::{So3, Vector};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// Explicit RK4 on (q, Π) with quaternion renormalisation after each step, for any system on SO(3).
///
/// State: time t, body momentum Π, and the attitude (q, R(q)) when it is reconstructed (`None`
/// integrates Π alone, only allowed without a potential).
///
/// ```
/// use integrators::{baselines::QuaternionRk4, Integrator};
/// use mechanics::RigidBody;
/// use lie_groups::{LieGroup, So3, Vector};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([1.0, 2.0, 3.0])?;
/// let mut rk4 = QuaternionRk4::new(body, Vector3::new(0.5, 1.0, 0.2), Some(So3::identity()))?;
/// integrators::integrate(&mut rk4, 0.01, 100, |_| {})?;
/// assert!((rk4.time() - 1.0).abs() < 1e-12);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct QuaternionRk4<S: System<So3>> {
    system: S,
    pi: Vector3<f64>,
    /// t, q and R(q) on demand.
    state: QuaternionState,
}

impl<S: System<So3>> QuaternionRk4<S> {
    /// Builds the integrator at t = 0 from Π₀ and optionally R₀. Errors: non-finite Π₀ or R₀, R₀
    /// missing for a system with a potential.
    pub fn new(system: S, pi0: Vector3<f64>, r0: Option<So3>) -> Result<Self, IntegratorError> {
        check_state(&system, &pi0, "momentum Π", r0.as_ref())?;
        Ok(Self {
            system,
            pi: pi0,
            state: QuaternionState::new(r0),
        })
    }
    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }
    /// The unit quaternion of the attitude, where it is reconstructed.
    pub fn quaternion(&self) -> Option<UnitQuaternion<f64>> {
        self.state.quaternion()
    }

    /// The RK4 step of Π alone (nothing reads R: the momentum equation does not involve it), out
    /// of line so that the attitude's step, the common case, is the step function's own body.
    #[inline(never)]
    fn momentum_step(&self, h: f64) -> Vector3<f64> {
        let (pi, half) = (self.pi, 0.5 * h);
        let (t0, tm, t1) = (
            self.state.now(),
            self.state.now() + half,
            self.state.now() + h,
        );
        let v = |pi: &Vector3<f64>| self.system.velocity(pi);
        let [_, k1] = self.momentum_rate(&v, t0, None, &pi);
        let [_, k2] = self.momentum_rate(&v, tm, None, &(pi + k1 * half));
        let [_, k3] = self.momentum_rate(&v, tm, None, &(pi + k2 * half));
        let [_, k4] = self.momentum_rate(&v, t1, None, &(pi + k3 * h));
        pi + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0)
    }

    /// The RK4 step of (q, Π) from (t, q, Π), the body velocity Ω = ∂h/∂Π evaluated by `v`; the
    /// four stages are always inlined (a stage left out of line, as the compiler chose for one of
    /// four, cost the step a third; as a function of their own they cost the step ~10 %, the
    /// state going through memory to and from the call).
    #[inline(always)]
    fn attitude_step(
        &self,
        v: &impl Fn(&Vector3<f64>) -> Vector3<f64>,
        h: f64,
        q: Quaternion<f64>,
        pi: Vector3<f64>,
    ) -> (Quaternion<f64>, Vector3<f64>) {
        let half = 0.5 * h;
        let (t0, tm, t1) = (
            self.state.now(),
            self.state.now() + half,
            self.state.now() + h,
        );
        let (l1, k1) = self.rate(v, t0, &q, &pi);
        let (l2, k2) = self.rate(v, tm, &(q + l1 * half), &(pi + k1 * half));
        let (l3, k3) = self.rate(v, tm, &(q + l2 * half), &(pi + k2 * half));
        let (l4, k4) = self.rate(v, t1, &(q + l3 * h), &(pi + k3 * h));
        (
            q + (l1 + (l2 + l3) * 2.0 + l4) * (h / 6.0),
            pi + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0),
        )
    }

    /// [`Self::attitude_step`] with Ω = ∂h/∂Π from [`System::velocity`]: the step of a system
    /// that declares no diagonal h, out of line so that the common step stays small enough for
    /// the compiler to inline the system's force into its stages (inlined here, it makes the
    /// common step too large for that).
    #[inline(never)]
    fn general_attitude_step(
        &self,
        h: f64,
        q: Quaternion<f64>,
        pi: Vector3<f64>,
    ) -> (Quaternion<f64>, Vector3<f64>) {
        self.attitude_step(&|pi| self.system.velocity(pi), h, q, pi)
    }

    /// `(q̇, Π̇)` at a stage, Ω = `v(Π)`.
    #[inline(always)]
    fn rate(
        &self,
        v: &impl Fn(&Vector3<f64>) -> Vector3<f64>,
        t: f64,
        q: &Quaternion<f64>,
        pi: &Vector3<f64>,
    ) -> (Quaternion<f64>, Vector3<f64>) {
        let [w, dpi] = self.momentum_rate(v, t, Some(q), pi);
        (quaternion_rate(q, &w), dpi)
    }

    /// `Π̇ = ad*_Ω Π + F(R) + F_ext(t, R, Ω)`, Ω = `v(Π)` = ∂h/∂Π; returns (Ω, Π̇).
    #[inline(always)]
    fn momentum_rate(
        &self,
        v: &impl Fn(&Vector3<f64>) -> Vector3<f64>,
        t: f64,
        q: Option<&Quaternion<f64>>,
        pi: &Vector3<f64>,
    ) -> [Vector3<f64>; 2] {
        let omega = v(pi);
        let dpi = momentum_rate(&self.system, t, q, pi, &omega);
        [omega, dpi]
    }
}

impl<S: System<So3>> Integrator for QuaternionRk4<S> {
    type Group = So3;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        // Π and q as the last step stored them, entry by entry (crate::carried_state).
        let pi = carried_state::read(&self.pi);
        match self
            .state
            .q
            .map(|q| Quaternion::from(carried_state::read(&q.coords)))
        {
            None => {
                let pi1 = self.momentum_step(h);
                if !Vector::is_finite(&pi1) {
                    return Err(IntegratorError::NonFinite {
                        what: "momentum Π_{k+1}",
                    });
                }
                self.pi = pi1;
                self.state.commit(None, 1.0, h, None);
            }
            Some(q) => {
                // The system's shape is tested once per step, not in each stage: a diagonal
                // quadratic h (a body in principal axes) steps with Ω = a ∘ Π (a test inside the
                // stages would keep both arms of the branch alive in every stage).
                let (q1, pi1) = match self.system.diagonal_velocity() {
                    Some(a) => self.attitude_step(&|pi| pi.component_mul(&a), h, q, pi),
                    None => self.general_attitude_step(h, q, pi),
                };
                // Renormalisation: the one projection this baseline makes.
                let norm = QuaternionState::check(Some(&q1), &pi1)?;
                self.pi = pi1;
                self.state.commit(Some(q1), norm, h, None);
            }
        }
        Ok(())
    }
    state_accessors!(pi);
    fn method_name(&self) -> String {
        "rk4(quaternion)".into()
    }
    /// Classical RK4: order 4, explicit; q is renormalised every step, so R stays on SO(3), and
    /// nothing else is kept.
    fn info(&self) -> crate::MethodInfo {
        crate::MethodInfo::plain(4)
    }
}
