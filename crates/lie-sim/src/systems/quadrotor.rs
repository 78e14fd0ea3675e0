//! `quadrotor`: a quadrotor on SE(3) in gravity (`mechanics::Quadrotor`); with `[forces]` the
//! thrust along its third axis, body torques, damping and drag.
//!
//! `[system]`: `mass`, `inertia`, `gravity` g. `[initial]`: `momentum` (Π, P) (6), `attitude`,
//! `position`.

use super::common::{build_error, SceneSystem, Tag};
use super::free_rigid_body::so3;
use super::rigid_body_se3::Se3Body;
use super::underwater_vehicle::se3_forces;
use crate::error::SimError;
use crate::fields::{
    attitude3, gravity_down, inertia3, momentum_of_len, position3, positive, FieldError,
    RawAttitude, RawInertia, RawNumbers,
};
use crate::forces::Forces;
use crate::model::Job;
use integrators::forces::Forced;
use integrators::IntegratorError;
use lie_groups::Se3;
use mechanics::exact::FreeBodySe3Flow;
use mechanics::Quadrotor as Model;
use nalgebra::{Matrix3, Vector3, Vector6};
use serde::Deserialize;

/// `[system]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The tag (read first, to choose this type).
    #[serde(rename = "kind")]
    _kind: Tag,
    /// m > 0.
    pub mass: f64,
    /// 𝕀 about the centre of mass.
    pub inertia: RawInertia,
    /// Accept principal moments that break the triangle inequality of a rigid body
    /// (`fields::inertia3`); false by default.
    #[serde(default)]
    pub generalized_inertia: bool,
    /// g ≥ 0 along −e₃.
    pub gravity: RawNumbers,
}

/// `[initial]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Initial {
    /// (Π₀, P₀).
    pub momentum: Vec<f64>,
    /// R₀ (default: the identity).
    pub attitude: Option<RawAttitude>,
    /// x₀ (default: the origin).
    pub position: Option<Vec<f64>>,
}

/// The checked quadrotor and its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct Quadrotor {
    /// Mass m.
    pub mass: f64,
    /// Inertia about the centre of mass.
    pub inertia: Matrix3<f64>,
    /// g ≥ 0 (gravity −g e₃).
    pub gravity: f64,
    /// Initial (Π, P).
    pub momentum: Vector6<f64>,
    /// Initial attitude.
    pub attitude: Matrix3<f64>,
    /// Initial position.
    pub position: Vector3<f64>,
    /// Thrust, torques, drag (`[forces]`).
    pub forces: Option<Forces>,
}

impl SceneSystem for Quadrotor {
    const KIND: &'static str = "quadrotor";
    const SUMMARY: &'static str = "A quadrotor on SE(3): gravity, thrust along its third axis, \
                                   body torques (mechanics::Quadrotor)";
    const EXAMPLE: &'static str = include_str!("../../../../examples/scenes/quadrotor.toml");
    const FORCE_KEYS: &'static [&'static str] = &["thrust", "torque", "damping", "quadratic_drag"];
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        momentum_of_len(Self::KIND, &initial.momentum, 6)?;
        Ok(Self {
            mass: positive("system.mass", params.mass)?,
            inertia: inertia3("system.inertia", &params.inertia, params.generalized_inertia)?,
            gravity: gravity_down(Self::KIND, &params.gravity)?,
            momentum: Vector6::from_column_slice(&initial.momentum),
            attitude: attitude3(&initial.attitude)?,
            position: position3("initial.position", &initial.position)?,
            forces: None,
        })
    }
    fn force_sizes(&self) -> (usize, usize) {
        (6, 0)
    }
    fn forces(&self) -> Option<&Forces> {
        self.forces.as_ref()
    }
    fn set_forces(&mut self, forces: Forces) {
        self.forces = Some(forces);
    }
    fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError> {
        let built = |e: IntegratorError| build_error(Self::KIND, e);
        let quad = Model::new(self.mass, self.inertia, self.gravity).map_err(built)?;
        let g0 = so3(Self::KIND, &self.attitude, reconstruct)?
            .map(|r| Se3::from_parts(r, self.position));
        let flow = FreeBodySe3Flow::new(quad.body());
        match &self.forces {
            None => job.run(&Se3Body::new(Self::KIND, quad, flow), self.momentum, g0),
            Some(f) => {
                let forced = Forced::new(quad, se3_forces(f, Some(Model::thrust)).map_err(built)?);
                job.run(&Se3Body::new(Self::KIND, forced, flow), self.momentum, g0)
            }
        }
    }
}
