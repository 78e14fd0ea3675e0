//! The exact free rigid body flow as an integrator.

use super::FreeBodyFlow;
use crate::systems::RigidBody;
use integrators::checks::check_state;
use integrators::compose::{StateSnapshot, SymmetricMethod};
use integrators::{Integrator, IntegratorError, MethodInfo, System};
use lie_groups::So3;
use nalgebra::Vector3;

/// Steps the free rigid body with its exact flow ([`FreeBodyFlow`]): every step, of any size,
/// lands on the solution to round-off, and costs the same whatever h is, so the whole horizon can
/// be one step. Keeps everything the flow keeps.
///
/// ```
/// use integrators::{Integrator};
/// use mechanics::{exact::ExactFreeBody, systems::RigidBody};
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal(1.0, 2.0, 3.0)?;
/// let mut exact = ExactFreeBody::new(body, Vector3::new(0.4, 1.0, 0.3), Some(So3::identity()))?;
/// let e0 = exact.energy();
/// exact.step(1000.0)?; // one step to T = 1000
/// assert!((exact.energy() - e0).abs() < 1e-13 * e0);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct ExactFreeBody {
    body: RigidBody,
    flow: FreeBodyFlow,
    t: f64,
    pi: Vector3<f64>,
    r: Option<So3>,
}

impl ExactFreeBody {
    /// The integrator at t = 0 from Π₀ and optionally R₀ (non-finite values are refused).
    pub fn new(
        body: RigidBody,
        pi0: Vector3<f64>,
        r0: Option<So3>,
    ) -> Result<Self, IntegratorError> {
        check_state(&body, &pi0, "momentum Π", r0.as_ref())?;
        Ok(Self {
            flow: FreeBodyFlow::new(&body),
            body,
            t: 0.0,
            pi: pi0,
            r: r0,
        })
    }
    /// Resets the state to (t, Π, R), with the checks of [`ExactFreeBody::new`].
    pub fn reset(
        &mut self,
        t: f64,
        pi: Vector3<f64>,
        r: Option<So3>,
    ) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        check_state(&self.body, &pi, "momentum Π", r.as_ref())?;
        self.t = t;
        self.pi = pi;
        self.r = r;
        Ok(())
    }
    /// The flow.
    pub fn flow(&self) -> &FreeBodyFlow {
        &self.flow
    }
}

impl Integrator for ExactFreeBody {
    type Group = So3;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let (pi, r) = self.flow.advance(h, &self.pi, self.r.as_ref())?;
        self.pi = pi;
        self.r = r;
        self.t += h;
        Ok(())
    }
    fn time(&self) -> f64 {
        self.t
    }
    fn momentum(&self) -> Vector3<f64> {
        self.pi
    }
    fn velocity(&self) -> Vector3<f64> {
        self.body.velocity(&self.pi)
    }
    fn momentum_rate(&self) -> Vector3<f64> {
        integrators::dense_output::momentum_rate(
            &self.body,
            self.time(),
            &self.momentum(),
            self.configuration(),
        )
    }
    fn configuration(&self) -> Option<&So3> {
        self.r.as_ref()
    }
    fn energy(&self) -> f64 {
        self.body.hamiltonian(&self.pi)
    }
    fn casimir(&self) -> Option<f64> {
        self.body.casimir(&self.pi)
    }
    fn method_name(&self) -> String {
        "exact".into()
    }
    /// The flow itself: no truncation error, symmetric, explicit, and it keeps everything.
    fn info(&self) -> MethodInfo {
        MethodInfo {
            order: MethodInfo::EXACT,
            symmetric: true,
            explicit: true,
            poisson: true,
            casimirs: true,
            momentum_map: true,
            energy: true,
            on_group: true,
        }
    }
}

impl SymmetricMethod for ExactFreeBody {
    /// Always: φ_{−h} = φ_h⁻¹.
    fn is_symmetric(&self) -> bool {
        true
    }
}

impl StateSnapshot for ExactFreeBody {
    /// (t, Π, R).
    type State = (f64, Vector3<f64>, Option<So3>);
    fn snapshot(&self) -> Self::State {
        (self.t, self.pi, self.r)
    }
    fn restore(&mut self, (t, pi, r): Self::State) -> Result<(), IntegratorError> {
        self.reset(t, pi, r)
    }
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        self.t = t;
        Ok(())
    }
}
