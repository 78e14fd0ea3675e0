//! `heavy-top` (also read as `pendulum-3d`): a rigid body on SO(3) with a fixed point in uniform
//! gravity −g e₃, centre of mass χ in the body frame (`mechanics::HeavyTop`; the 3D pendulum —
//! J about the pivot, ρ = χ — is the same system, `mechanics::Pendulum3d`); with `[forces]` a
//! body torque schedule and damping.
//!
//! `[system]`: `inertia` (about the fixed point), `mass`, `center_of_mass` χ, `gravity` g ≥ 0
//! (g, or `[0, 0, -g]`). `[initial]`: `momentum` Π (3), `attitude`.

use super::common::{build_error, SceneSystem, Tag};
use super::free_rigid_body::{so3, so3_forces, So3Body};
use crate::error::SimError;
use crate::fields::{
    attitude3, finite_all, gravity_down, inertia3, positive, vec3, FieldError, RawAttitude,
    RawInertia, RawNumbers,
};
use crate::forces::Forces;
use crate::model::Job;
use integrators::forces::Forced;
use mechanics::HeavyTop as Top;
use nalgebra::{Matrix3, Vector3};
use serde::Deserialize;

/// `[system]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The tag (read first, to choose this type).
    #[serde(rename = "kind")]
    _kind: Tag,
    /// 𝕀 about the fixed point.
    pub inertia: RawInertia,
    /// Accept principal moments that break the triangle inequality of a rigid body
    /// (`fields::inertia3`); false by default.
    #[serde(default)]
    pub generalized_inertia: bool,
    /// m > 0.
    pub mass: f64,
    /// χ, body frame.
    #[serde(alias = "centre_of_mass")]
    pub center_of_mass: [f64; 3],
    /// g ≥ 0 along −e₃: a number or `[0, 0, -g]`.
    pub gravity: RawNumbers,
}

/// `[initial]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Initial {
    /// Π₀.
    pub momentum: Vec<f64>,
    /// R₀ (default: the identity).
    pub attitude: Option<RawAttitude>,
}

/// The checked heavy top and its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct HeavyTop {
    /// Inertia tensor about the fixed point.
    pub inertia: Matrix3<f64>,
    /// Mass m.
    pub mass: f64,
    /// Centre of mass χ in the body frame.
    pub center_of_mass: Vector3<f64>,
    /// g ≥ 0: gravity is −g e₃ in space.
    pub gravity: f64,
    /// Initial body angular momentum Π₀.
    pub momentum: Vector3<f64>,
    /// Initial attitude R₀.
    pub attitude: Matrix3<f64>,
    /// External torque and damping (`[forces]`).
    pub forces: Option<Forces>,
}

impl SceneSystem for HeavyTop {
    const KIND: &'static str = "heavy-top";
    const ALIASES: &'static [&'static str] = &["pendulum-3d"];
    const SUMMARY: &'static str = "The heavy top (= the 3D pendulum) on SO(3): a body on a fixed \
                                   point in uniform gravity (mechanics::HeavyTop)";
    const EXAMPLE: &'static str = include_str!("../../../../examples/scenes/heavy-top.toml");
    const FORCE_KEYS: &'static [&'static str] = &["torque", "damping"];
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        let mass = positive("system.mass", params.mass)?;
        finite_all("system.center_of_mass", &params.center_of_mass)?;
        let gravity = gravity_down(Self::KIND, &params.gravity)?;
        Ok(Self {
            inertia: inertia3("system.inertia", &params.inertia, params.generalized_inertia)?,
            mass,
            center_of_mass: Vector3::from(params.center_of_mass),
            gravity,
            momentum: vec3("initial.momentum", &initial.momentum)?,
            attitude: attitude3(&initial.attitude)?,
            forces: None,
        })
    }
    fn force_sizes(&self) -> (usize, usize) {
        (3, 0)
    }
    fn forces(&self) -> Option<&Forces> {
        self.forces.as_ref()
    }
    fn set_forces(&mut self, forces: Forces) {
        self.forces = Some(forces);
    }
    fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError> {
        let built = |e| build_error(Self::KIND, e);
        let top = Top::new(self.inertia, self.mass, self.gravity, self.center_of_mass).map_err(built)?;
        let body = top.body().clone();
        let g0 = so3(Self::KIND, &self.attitude, reconstruct)?;
        match &self.forces {
            None => {
                let batch = batch::BodyModel::heavy_top(&top);
                let model = So3Body::new(Self::KIND, top, body).batched(batch);
                job.run(&model, self.momentum, g0)
            }
            Some(f) => {
                let forced = Forced::new(top, so3_forces(f).map_err(built)?);
                job.run(&So3Body::new(Self::KIND, forced, body), self.momentum, g0)
            }
        }
    }
}
