//! `rigid-body-se3`: a rigid body on SE(3), free or a satellite in the central gravity field of
//! a point mass at the origin (`mechanics::RigidBodySe3`, MacCullagh's potential).
//!
//! `[system]`: `inertia` (about the centre of mass), `mass`, `gravitational_parameter` GM ≥ 0
//! (default 0: free). `[initial]`: `momentum` (Π, P) (6, in the basis of lie-groups' SE(3)
//! `vee`, rotation first), `attitude`, `position` x (default the origin; away from it when
//! GM > 0).

use super::common::{build_error, SceneSystem, Tag};
use super::free_rigid_body::so3;
use crate::error::SimError;
use crate::fields::{
    attitude3, inertia3, momentum_of_len, non_negative, position3, positive, FieldError,
    RawAttitude, RawInertia,
};
use crate::model::{Has, Job, KineticVisitor, Model, SplitVisitor};
use integrators::splitting::SplitSystem;
use lie_groups::Se3;
use mechanics::exact::FreeBodySe3Flow;
use mechanics::RigidBodySe3 as Body;
use nalgebra::{Matrix3, Vector3, Vector6};
use serde::Deserialize;

/// `[system]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The tag (read first, to choose this type).
    #[serde(rename = "kind")]
    _kind: Tag,
    /// 𝕀 about the centre of mass.
    pub inertia: RawInertia,
    /// Accept principal moments that break the triangle inequality of a rigid body
    /// (`fields::inertia3`); false by default.
    #[serde(default)]
    pub generalized_inertia: bool,
    /// m > 0.
    pub mass: f64,
    /// GM ≥ 0 of a central body at the origin (default 0: the free body).
    pub gravitational_parameter: Option<f64>,
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

/// The checked body and its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidBodySe3 {
    /// Inertia tensor about the centre of mass.
    pub inertia: Matrix3<f64>,
    /// Mass m.
    pub mass: f64,
    /// GM of the central body (0: free body).
    pub gravitational_parameter: f64,
    /// Initial body momentum μ₀ ∈ 𝔰𝔢(3)* in the basis of `lie_groups`' SE(3) `vee`.
    pub momentum: Vector6<f64>,
    /// Initial attitude R₀.
    pub attitude: Matrix3<f64>,
    /// Initial position x₀.
    pub position: Vector3<f64>,
}

impl SceneSystem for RigidBodySe3 {
    const KIND: &'static str = "rigid-body-se3";
    const SUMMARY: &'static str = "A rigid body on SE(3), free or a satellite in a central \
                                   gravity field (mechanics::RigidBodySe3)";
    const EXAMPLE: &'static str = include_str!("../../../../examples/scenes/rigid-body-se3.toml");
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        let mass = positive("system.mass", params.mass)?;
        let gm = non_negative(
            "system.gravitational_parameter",
            params.gravitational_parameter.unwrap_or(0.0),
        )?;
        momentum_of_len(Self::KIND, &initial.momentum, 6)?;
        let position = position3("initial.position", &initial.position)?;
        if gm > 0.0 && position.norm() == 0.0 {
            return Err((
                "initial.position".into(),
                "must be away from the centre of attraction when gravitational_parameter > 0"
                    .into(),
            ));
        }
        Ok(Self {
            inertia: inertia3("system.inertia", &params.inertia, params.generalized_inertia)?,
            mass,
            gravitational_parameter: gm,
            momentum: Vector6::from_column_slice(&initial.momentum),
            attitude: attitude3(&initial.attitude)?,
            position,
        })
    }
    fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError> {
        let built = |e| build_error(Self::KIND, e);
        let body = if self.gravitational_parameter > 0.0 {
            Body::satellite(self.mass, self.inertia, self.gravitational_parameter)
        } else {
            Body::free(self.mass, self.inertia)
        }
        .map_err(built)?;
        let g0 = so3(Self::KIND, &self.attitude, reconstruct)?
            .map(|r| Se3::from_parts(r, self.position));
        let flow = FreeBodySe3Flow::new(&body);
        job.run(&Se3Body::new(Self::KIND, body, flow), self.momentum, g0)
    }
}

/// A rigid body on SE(3) as the methods see it: its system S splits, and the free body's flow on
/// SE(3) is its kinetic flow.
pub struct Se3Body<S> {
    kind: &'static str,
    system: S,
    flow: FreeBodySe3Flow,
}

impl<S> Se3Body<S> {
    /// The system S whose kinetic energy's flow is `flow`.
    pub fn new(kind: &'static str, system: S, flow: FreeBodySe3Flow) -> Self {
        Self { kind, system, flow }
    }
}

impl<S: SplitSystem<Se3> + Clone + Sync + 'static> Model for Se3Body<S> {
    type G = Se3;
    type S = S;
    fn kind(&self) -> &'static str {
        self.kind
    }
    fn system(&self) -> &S {
        &self.system
    }
    fn split<V: SplitVisitor<Se3>>(&self, v: V, mu0: Vector6<f64>, g0: Option<Se3>) -> Has<V::Out> {
        Ok(v.visit(&self.system, mu0, g0))
    }
    fn kinetic_flow<V: KineticVisitor<Se3>>(
        &self,
        v: V,
        mu0: Vector6<f64>,
        g0: Option<Se3>,
    ) -> Has<V::Out> {
        Ok(v.visit(&self.system, self.flow.clone(), mu0, g0))
    }
}
