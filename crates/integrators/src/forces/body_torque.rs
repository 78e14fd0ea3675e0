//! [`BodyTorque`]: a scheduled body-frame force or torque.

use crate::forces::{ExternalForce, Schedule};
use crate::IntegratorError;
use core::marker::PhantomData;
use lie_groups::{LieGroup, Vector};

/// `F_ext(t) = u(t)`: a body-frame covector (a torque on SO(3); torque and force on SE(3)) given by
/// a [`Schedule`] — a control input entering with the identity input map. It does not read g or ξ.
#[derive(Debug, Clone)]
pub struct BodyTorque<G> {
    schedule: Schedule,
    _group: PhantomData<fn() -> G>,
}

impl<G: LieGroup> BodyTorque<G> {
    /// The torque of `schedule`, whose values must have the algebra's dimension.
    pub fn new(schedule: Schedule) -> Result<Self, IntegratorError> {
        if schedule.dim() != G::dim() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "a body torque on this group has {} components, the schedule's values {}",
                    G::dim(),
                    schedule.dim()
                ),
            });
        }
        Ok(Self {
            schedule,
            _group: PhantomData,
        })
    }
    /// A constant torque.
    pub fn constant(value: G::Algebra) -> Result<Self, IntegratorError> {
        Self::new(Schedule::constant(value.to_vec())?)
    }
}

impl<G: LieGroup> ExternalForce<G> for BodyTorque<G> {
    #[inline]
    fn force(&self, t: f64, _g: Option<&G>, _xi: &G::Algebra) -> G::Algebra {
        self.schedule
            .eval_with(t, |u| G::Algebra::from_fn(G::dim(), |i| u[i]))
    }
    fn reads_velocity(&self) -> bool {
        false
    }
    /// `1/Δt` of the schedule's shortest gap between knots, or the spin-up rate
    /// ([`crate::System::torque_rate`]) of its largest value, whichever is larger.
    fn characteristic_rate<S: crate::System<G>>(
        &self,
        system: &S,
        _mu: &G::Algebra,
        _g: Option<&G>,
    ) -> f64 {
        let spin = super::external_force::peak_torque_rate::<G, S>(system, &self.schedule, |u| {
            G::Algebra::from_fn(G::dim(), |i| u[i])
        });
        super::external_force::knot_rate(&self.schedule).max(spin)
    }
}
