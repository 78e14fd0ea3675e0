//! The plain baseline a scipy user would pick instead of a geometric method: an embedded
//! explicit Runge–Kutta pair (Dormand–Prince 5(4), DOP853) on (unit quaternion, body momentum)
//! with error control, the quaternion renormalized after each step.
//!
//! The equations are those of [`crate::baselines::QuaternionRk4`] (`q̇ = ½ q ⊗ (0, Ω)`,
//! `Π̇ = ad*_Ω Π + F(R(q/|q|)) + F_ext`, Ω = ∂h/∂Π) for any system on SO(3), as an ODE in
//! ℝ⁴ × ℝ³; each step is one step of the pair ([`crate::adaptive::ButcherPair`]), and q ← q/|q|
//! after it. The error is measured as scipy's `solve_ivp` and Hairer's codes measure it on this
//! 7-vector: `‖(êᵢ / (atol + rtol·max(|yᵢ|, |y₁ᵢ|)))ᵢ‖_rms` ([`crate::adaptive::Tolerance`]) — so
//! that it can be compared run for run with `ode_solvers::{Dopri5, Dop853}` on the same
//! right-hand side (`benches/adaptive.rs`).
//!
//! First same as last with renormalization: the last stage of Dormand–Prince is evaluated at
//! the unnormalized (q₁, Π₁); the quaternion rate is linear in q and the momentum rate reads R(q)
//! through q/|q|, so the next step's first stage is (q̇/|q₁|, Π̇), exactly, without an
//! evaluation. Stack only, no heap allocation per step.

use super::quaternion_state::{momentum_rate, quaternion_rate, QuaternionState};
use crate::adaptive::embedded_pair::check_end_time;
use crate::adaptive::{
    starting_step, ButcherPair, Controller, Dop853, DormandPrince54, EmbeddedPair, Tolerance,
};
use crate::carried_state;
use crate::checks::check_state;
use crate::step_state::state_accessors;
use crate::unroll::unroll;
use crate::{Integrator, IntegratorError, MethodInfo, System};
use core::marker::PhantomData;
use lie_groups::So3;
use nalgebra::{Quaternion, UnitQuaternion, Vector3, Vector4};

/// Dormand–Prince 5(4) on (q, Π), scipy's `RK45` on the quaternion equations.
pub type QuaternionDopri5<S> = QuaternionPair<S, DormandPrince54, 7>;
/// DOP853 on (q, Π), scipy's `DOP853` on the quaternion equations.
pub type QuaternionDop853<S> = QuaternionPair<S, Dop853, 12>;

/// An embedded explicit pair on (q, Π) with renormalization, for any system on SO(3) (see the
/// module page).
///
/// ```
/// use integrators::adaptive::{Adaptive, Tolerance};
/// use integrators::baselines::QuaternionDop853;
/// use integrators::Integrator;
/// use mechanics::RigidBody;
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([2.0, 3.0, 4.0])?;
/// let method = QuaternionDop853::new(body, Vector3::new(1.0, 0.5, -0.3), Some(So3::identity()))?;
/// let mut run = Adaptive::new(method, Tolerance::new(1e-10, 1e-10)?);
/// run.advance_to(10.0)?;
/// assert_eq!(run.method().time(), 10.0);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct QuaternionPair<S: System<So3>, P: ButcherPair<N>, const N: usize> {
    system: S,
    pi: Vector3<f64>,
    /// t, q and R(q) on demand.
    state: QuaternionState,
    /// (q̇, Π̇) at the current state where already evaluated (q̇ = 0 without the attitude).
    first: Option<(Quaternion<f64>, Vector3<f64>)>,
    pair: PhantomData<P>,
}

/// A step computed but not yet taken.
struct Candidate {
    q1: Option<Quaternion<f64>>,
    pi1: Vector3<f64>,
    /// Σ (estimate/scale)² of the estimators E and E_LOW, and the components counted.
    sum: f64,
    sum_low: f64,
    n: usize,
    /// (q̇, Π̇) of a last stage at (t + h, q₁, Π₁).
    last: Option<(Quaternion<f64>, Vector3<f64>)>,
}

impl<S: System<So3>, P: ButcherPair<N>, const N: usize> QuaternionPair<S, P, N> {
    /// Builds the method at t = 0 from Π₀ and optionally R₀. Errors: non-finite Π₀ or R₀, R₀
    /// missing for a system that needs it.
    pub fn new(system: S, pi0: Vector3<f64>, r0: Option<So3>) -> Result<Self, IntegratorError> {
        check_state(&system, &pi0, "momentum Π", r0.as_ref())?;
        Ok(Self {
            system,
            pi: pi0,
            state: QuaternionState::new(r0),
            first: None,
            pair: PhantomData,
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

    /// (q̇, Π̇) at a stage, Ω = `v(Π)`; q̇ = 0 without the attitude.
    #[inline(always)]
    fn rates(
        &self,
        v: &impl Fn(&Vector3<f64>) -> Vector3<f64>,
        t: f64,
        q: Option<&Quaternion<f64>>,
        pi: &Vector3<f64>,
    ) -> (Quaternion<f64>, Vector3<f64>) {
        let omega = v(pi);
        let dpi = momentum_rate(&self.system, t, q, pi, &omega);
        let dq = q.map_or(Quaternion::new(0.0, 0.0, 0.0, 0.0), |q| {
            quaternion_rate(q, &omega)
        });
        (dq, dpi)
    }

    /// The stages of a step of size h with the weights b, from the first stage's rates.
    #[inline(always)]
    fn stages(
        &self,
        v: &impl Fn(&Vector3<f64>) -> Vector3<f64>,
        h: f64,
        first: (Quaternion<f64>, Vector3<f64>),
        b: &[f64; N],
        tolerance: Option<&Tolerance>,
    ) -> Candidate {
        let pi = carried_state::read(&self.pi);
        let q = self
            .state
            .q
            .map(|q| Quaternion::from(carried_state::read(&q.coords)));
        let mut ls = [Quaternion::<f64>::new(0.0, 0.0, 0.0, 0.0); N];
        let mut ks = [Vector3::<f64>::zeros(); N];
        (ls[0], ks[0]) = first;
        let mut last = None;
        // Written out stage by stage (crate::unroll): the aᵢⱼ are literals, the zero ones gone.
        unroll!(I in 1..N => {
            let mut dq = Vector4::<f64>::zeros();
            let mut dpi = Vector3::<f64>::zeros();
            unroll!(J < I => {
                let a = P::A[I][J];
                if a != 0.0 {
                    dq += ls[J].coords * a;
                    dpi += ks[J] * a;
                }
            });
            let q_i = q.map(|q| Quaternion::from(q.coords + dq * h));
            let pi_i = pi + dpi * h;
            let (l, k) = self.rates(v, self.state.now() + P::C[I] * h, q_i.as_ref(), &pi_i);
            if P::FSAL && I == N - 1 && *b == P::B {
                last = Some((l, k));
            }
            ls[I] = l;
            ks[I] = k;
        });
        let mut dq = Vector4::<f64>::zeros();
        let mut dpi = Vector3::<f64>::zeros();
        let mut eq = Vector4::<f64>::zeros();
        let mut epi = Vector3::<f64>::zeros();
        let mut lq = Vector4::<f64>::zeros();
        let mut lpi = Vector3::<f64>::zeros();
        unroll!(I < N => {
            if b[I] != 0.0 {
                dq += ls[I].coords * b[I];
                dpi += ks[I] * b[I];
            }
            if tolerance.is_some() {
                if P::E[I] != 0.0 {
                    eq += ls[I].coords * P::E[I];
                    epi += ks[I] * P::E[I];
                }
                if let Some(e_low) = P::E_LOW {
                    if e_low[I] != 0.0 {
                        lq += ls[I].coords * e_low[I];
                        lpi += ks[I] * e_low[I];
                    }
                }
            }
        });
        let q1 = q.map(|q| Quaternion::from(q.coords + dq * h));
        let pi1 = pi + dpi * h;
        let (mut sum, mut sum_low, mut n) = (0.0, 0.0, 3);
        if let Some(tol) = tolerance {
            for i in 0..3 {
                let w = h / tol.scale(pi[i], pi1[i]);
                sum += (epi[i] * w).powi(2);
                if P::E_LOW.is_some() {
                    sum_low += (lpi[i] * w).powi(2);
                }
            }
            if let (Some(q), Some(q1)) = (q, q1) {
                for i in 0..4 {
                    let w = h / tol.scale(q.coords[i], q1.coords[i]);
                    sum += (eq[i] * w).powi(2);
                    if P::E_LOW.is_some() {
                        sum_low += (lq[i] * w).powi(2);
                    }
                }
                n += 4;
            }
        }
        Candidate {
            q1,
            pi1,
            sum,
            sum_low,
            n,
            last,
        }
    }

    /// (q̇, Π̇) at the current state, from the cache where a stage already evaluated it.
    #[inline(always)]
    fn first_stage(&mut self) -> (Quaternion<f64>, Vector3<f64>) {
        if let Some(first) = self.first {
            return first;
        }
        let first = self.rates(
            &|pi: &Vector3<f64>| self.system.velocity(pi),
            self.state.now(),
            self.state.q.as_ref(),
            &self.pi,
        );
        self.first = Some(first);
        first
    }

    /// The candidate step of size h with the weights b.
    #[inline(always)]
    fn candidate(&mut self, h: f64, b: &[f64; N], tolerance: Option<&Tolerance>) -> Candidate {
        let first = self.first_stage();
        // The system's shape is tested once per step, not in each stage.
        match self.system.diagonal_velocity() {
            Some(a) => self.stages(&|pi| pi.component_mul(&a), h, first, b, tolerance),
            None => self.general_stages(h, first, b, tolerance),
        }
    }

    /// [`Self::stages`] with Ω from [`System::velocity`], out of line so that the common step
    /// stays small enough for the compiler to inline the system's force into its stages.
    #[inline(never)]
    fn general_stages(
        &self,
        h: f64,
        first: (Quaternion<f64>, Vector3<f64>),
        b: &[f64; N],
        tolerance: Option<&Tolerance>,
    ) -> Candidate {
        self.stages(&|pi| self.system.velocity(pi), h, first, b, tolerance)
    }

    /// Takes the candidate of size h (q renormalized), the time becoming `t1` (an adaptive
    /// step's chosen end) or advanced by h on the clock (a fixed step); `Err` where it is not
    /// finite (state untouched).
    #[inline(always)]
    fn commit(&mut self, c: Candidate, h: f64, t1: Option<f64>) -> Result<(), IntegratorError> {
        let norm = QuaternionState::check(c.q1.as_ref(), &c.pi1)?;
        self.state.commit(c.q1, norm, h, t1);
        self.pi = c.pi1;
        // The last stage's rates at the unnormalized q₁: q̇ is linear in q, Π̇ reads q/|q|.
        self.first = c.last.map(|(l, k)| (l / norm, k));
        Ok(())
    }

    /// A fixed step of the embedded solution (weights b − e, or b − e_low with `low`), for
    /// measuring the embedded orders (`tests/methods/adaptive_orders.rs`).
    pub fn step_embedded(&mut self, h: f64, low: bool) -> Result<(), IntegratorError> {
        let b_hat = P::embedded_weights(low)?;
        let c = self.candidate(h, &b_hat, None);
        self.commit(c, h, None)
    }
}

impl<S: System<So3>, P: ButcherPair<N>, const N: usize> Integrator for QuaternionPair<S, P, N> {
    type Group = So3;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let c = self.candidate(h, &P::B, None);
        self.commit(c, h, None)
    }
    state_accessors!(pi);
    fn method_name(&self) -> String {
        format!("{}(quaternion)", P::NAME)
    }
    /// Order p of the pair, explicit; q is renormalized every step, so R stays on SO(3), and
    /// nothing else is kept.
    fn info(&self) -> MethodInfo {
        MethodInfo::plain(P::ORDER)
    }
}

impl<S: System<So3> + Clone, P: ButcherPair<N>, const N: usize> EmbeddedPair
    for QuaternionPair<S, P, N>
{
    fn orders(&self) -> (u32, u32) {
        (P::ORDER, P::EMBEDDED_ORDER)
    }
    fn controller(&self) -> Controller {
        P::controller()
    }
    fn error_exponent(&self) -> u32 {
        P::ERROR_EXPONENT
    }
    #[inline]
    fn try_step_to(&mut self, t1: f64, tolerance: &Tolerance) -> Result<f64, IntegratorError> {
        let h = check_end_time(self.state.now(), t1)?;
        let c = self.candidate(h, &P::B, Some(tolerance));
        let err = P::error_norm(c.sum, c.sum_low, c.n);
        if !err.is_finite() {
            return Ok(f64::INFINITY);
        }
        if err <= 1.0 && self.commit(c, h, Some(t1)).is_err() {
            return Ok(f64::INFINITY);
        }
        Ok(err)
    }
    fn step_to(&mut self, t1: f64) -> Result<(), IntegratorError> {
        let h = check_end_time(self.state.now(), t1)?;
        let c = self.candidate(h, &P::B, None);
        self.commit(c, h, Some(t1))
    }
    fn starting_step(&mut self, direction: f64, tolerance: &Tolerance) -> f64 {
        let (l0, k0) = self.first_stage();
        let (pi0, q0) = (self.pi, self.state.q);
        let count = if q0.is_some() { 7.0 } else { 3.0 };
        let norm = |y_pi: &Vector3<f64>, y_q: Option<Vector4<f64>>| {
            let mut s = (0..3)
                .map(|i| (y_pi[i] / tolerance.scale(pi0[i], 0.0)).powi(2))
                .sum::<f64>();
            if let (Some(q0), Some(y_q)) = (q0, y_q) {
                s += (0..4)
                    .map(|i| (y_q[i] / tolerance.scale(q0.coords[i], 0.0)).powi(2))
                    .sum::<f64>();
            }
            (s / count).sqrt()
        };
        let d0 = norm(&pi0, q0.map(|q| q.coords));
        let d1 = norm(&k0, q0.map(|_| l0.coords));
        let sign = if direction < 0.0 { -1.0 } else { 1.0 };
        let d2 = |h0: f64| {
            let h = sign * h0;
            let q1 = q0.map(|q| Quaternion::from(q.coords + l0.coords * h));
            let (l1, k1) = self.rates(
                &|pi: &Vector3<f64>| self.system.velocity(pi),
                self.state.now() + h,
                q1.as_ref(),
                &(pi0 + k0 * h),
            );
            norm(&(k1 - k0), q0.map(|_| l1.coords - l0.coords)) / h0
        };
        starting_step(P::ERROR_EXPONENT, d0, d1, d2)
    }
}
