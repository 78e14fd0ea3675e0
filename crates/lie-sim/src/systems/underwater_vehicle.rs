//! `underwater-vehicle`: a vehicle on SE(3) with its full mass matrix M = M_RB + M_A (rigid body
//! and added mass) and restoring forces (`mechanics::UnderwaterVehicle`); with `[forces]` body
//! torques and forces (thrusters), linear damping and quadratic drag.
//!
//! `[system]`: `mass`, `inertia` (about the centre of gravity), `center_of_mass` r_G (default 0),
//! `added_mass` M_A (6 diagonal entries or a symmetric 6×6, (ω, v) ordering), `gravity` g,
//! `buoyancy` B ≥ 0, `center_of_buoyancy` r_B (default 0). `[initial]`: `momentum` (Π, P) (6),
//! `attitude`, `position`. M_RB comes from the mass, inertia and centre of gravity
//! (`mechanics::systems::UnderwaterVehicle::rigid_body_mass_matrix`); M must be positive
//! definite; the weight is W = m g.

use super::common::{build_error, SceneSystem, Splits, Tag};
use super::free_rigid_body::so3;
use crate::error::SimError;
use crate::fields::{
    attitude3, finite_all, gravity_down, inertia3, momentum_of_len, position3, positive, square,
    symmetric_positive_definite, FieldError, RawAttitude, RawInertia, RawNumbers,
};
use crate::forces::Forces;
use crate::model::Job;
use integrators::forces::{
    BodyInputMap, ControlInput, Forced, LinearDamping, QuadraticDrag, Schedule,
};
use integrators::IntegratorError;
use lie_groups::Se3;
use mechanics::UnderwaterVehicle as Vehicle;
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};
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
    /// 𝕀 about the centre of gravity.
    pub inertia: RawInertia,
    /// Accept principal moments that break the triangle inequality of a rigid body
    /// (`fields::inertia3`); false by default.
    #[serde(default)]
    pub generalized_inertia: bool,
    /// r_G, body frame (default 0).
    #[serde(alias = "centre_of_mass")]
    pub center_of_mass: Option<[f64; 3]>,
    /// M_A: 6 diagonal entries or a symmetric 6×6, (ω, v) ordering.
    pub added_mass: RawInertia,
    /// g ≥ 0 along −e₃.
    pub gravity: RawNumbers,
    /// B ≥ 0, a force.
    pub buoyancy: f64,
    /// r_B, body frame (default 0).
    #[serde(alias = "centre_of_buoyancy")]
    pub center_of_buoyancy: Option<[f64; 3]>,
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

/// The checked vehicle and its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct UnderwaterVehicle {
    /// The vehicle's mass m.
    pub mass: f64,
    /// Its inertia about the centre of gravity.
    pub inertia: Matrix3<f64>,
    /// The centre of gravity r_G (body frame).
    pub center_of_gravity: Vector3<f64>,
    /// The added-mass matrix M_A ((ω, v) ordering).
    pub added_mass: Matrix6<f64>,
    /// g ≥ 0 (gravity −g e₃).
    pub gravity: f64,
    /// The buoyancy B ≥ 0.
    pub buoyancy: f64,
    /// The centre of buoyancy r_B (body frame).
    pub center_of_buoyancy: Vector3<f64>,
    /// Initial (Π, P).
    pub momentum: Vector6<f64>,
    /// Initial attitude.
    pub attitude: Matrix3<f64>,
    /// Initial position of the body origin.
    pub position: Vector3<f64>,
    /// Thrust, drag (`[forces]`).
    pub forces: Option<Forces>,
}

impl UnderwaterVehicle {
    /// The weight W = m g.
    pub fn weight(&self) -> f64 {
        self.mass * self.gravity
    }
    /// `M = M_RB + M_A`.
    pub fn mass_matrix(&self) -> Matrix6<f64> {
        Vehicle::rigid_body_mass_matrix(self.mass, &self.inertia, &self.center_of_gravity)
            + self.added_mass
    }
}

impl SceneSystem for UnderwaterVehicle {
    const KIND: &'static str = "underwater-vehicle";
    const SUMMARY: &'static str = "An underwater vehicle on SE(3): full mass matrix with added \
                                   mass, restoring forces (mechanics::UnderwaterVehicle)";
    const EXAMPLE: &'static str =
        include_str!("../../../../examples/scenes/underwater-vehicle.toml");
    const FORCE_KEYS: &'static [&'static str] = &["torque", "force", "damping", "quadratic_drag"];
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        let mass = positive("system.mass", params.mass)?;
        let inertia = inertia3("system.inertia", &params.inertia, params.generalized_inertia)?;
        let center_of_gravity = Vector3::from(params.center_of_mass.unwrap_or([0.0; 3]));
        finite_all("system.center_of_mass", center_of_gravity.as_slice())?;
        let field = "system.added_mass";
        let added_mass = match &params.added_mass {
            RawInertia::Diagonal(d) if d.len() == 6 => {
                finite_all(field, d)?;
                if let Some(x) = d.iter().find(|x| **x < 0.0) {
                    return Err((field.into(), format!("entries must be ≥ 0, got {x}")));
                }
                Matrix6::from_diagonal(&Vector6::from_column_slice(d))
            }
            RawInertia::Matrix(rows) => Matrix6::from_row_slice(&square(field, rows, 6)?),
            _ => {
                return Err((
                    field.into(),
                    "must be 6 diagonal entries or a symmetric 6×6 matrix, (ω, v) ordering".into(),
                ))
            }
        };
        let gravity = gravity_down(Self::KIND, &params.gravity)?;
        let buoyancy = params.buoyancy;
        if !(buoyancy.is_finite() && buoyancy >= 0.0) {
            return Err((
                "system.buoyancy".into(),
                format!("must be a finite force ≥ 0, got {buoyancy}"),
            ));
        }
        let center_of_buoyancy = Vector3::from(params.center_of_buoyancy.unwrap_or([0.0; 3]));
        finite_all("system.center_of_buoyancy", center_of_buoyancy.as_slice())?;
        momentum_of_len(Self::KIND, &initial.momentum, 6)?;
        let vehicle = Self {
            mass,
            inertia,
            center_of_gravity,
            added_mass,
            gravity,
            buoyancy,
            center_of_buoyancy,
            momentum: Vector6::from_column_slice(&initial.momentum),
            attitude: attitude3(&initial.attitude)?,
            position: position3("initial.position", &initial.position)?,
            forces: None,
        };
        // M = M_RB + M_A symmetric positive definite (M_A symmetric, M_RB is).
        let m = vehicle.mass_matrix();
        symmetric_positive_definite(field, m.transpose().as_slice(), 6)
            .map_err(|(f, msg)| (f, format!("M_RB + M_A {msg}")))?;
        Ok(vehicle)
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
        let vehicle = Vehicle::new(self.mass_matrix())
            .and_then(|v| {
                v.with_restoring(
                    self.weight(),
                    self.center_of_gravity,
                    self.buoyancy,
                    self.center_of_buoyancy,
                )
            })
            .map_err(built)?;
        let g0 = so3(Self::KIND, &self.attitude, reconstruct)?
            .map(|r| Se3::from_parts(r, self.position));
        // The splitting's pieces need a block-diagonal M (their velocities constant along their
        // flows): the vehicle says whether it has one.
        let split = if vehicle.is_decoupled() {
            Ok(())
        } else {
            Err("this vehicle's mass matrix couples rotation and translation (M_ωv ≠ 0: the \
                 centre of gravity or the added mass off the body origin), so its pieces' \
                 velocities are not constant along their flows (use lie-poisson or rkmk4)"
                .to_string())
        };
        match &self.forces {
            None => job.run(&Splits::new(Self::KIND, vehicle, split), self.momentum, g0),
            Some(f) => {
                let forced = Forced::new(vehicle, se3_forces(f, None).map_err(built)?);
                job.run(&Splits::new(Self::KIND, forced, split), self.momentum, g0)
            }
        }
    }
}

/// The `[forces]` of a system on SE(3): a body torque (input map (I₃, 0)), a push — a body force
/// ((0, I₃)) or a thrust through its own input map —, linear damping `−D ξ` and quadratic drag,
/// each optional.
pub type Se3Forces = (
    Option<ControlInput<Se3>>,
    (
        Option<ControlInput<Se3>>,
        (Option<LinearDamping<Se3>>, Option<QuadraticDrag<Se3>>),
    ),
);

/// A system's maker of the thrust input from the `thrust` key's schedule.
pub type ThrustMaker = fn(Schedule) -> Result<ControlInput<Se3>, IntegratorError>;

/// The checked `[forces]` as the integrators' forces on SE(3); `thrust` is the system's thrust
/// maker for the `thrust` key.
pub fn se3_forces(
    f: &Forces,
    thrust: Option<ThrustMaker>,
) -> Result<Se3Forces, IntegratorError> {
    let input = |first: usize, count: usize, s: &Schedule| {
        ControlInput::new(BodyInputMap::<Se3>::components(first, count)?, s.clone())
    };
    let torque = f.torque.as_ref().map(|s| input(0, 3, s)).transpose()?;
    let push = match (&f.force, &f.thrust, thrust) {
        (Some(s), _, _) => Some(input(3, 3, s)?),
        (None, Some(s), Some(make)) => Some(make(s.clone())?),
        _ => None,
    };
    Ok((
        torque,
        (
            push,
            (
                f.damping6().map(LinearDamping::new).transpose()?,
                f.quadratic_drag6().map(QuadraticDrag::new).transpose()?,
            ),
        ),
    ))
}
