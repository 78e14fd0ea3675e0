//! `free-rigid-body`: the free rigid body on SO(3) (`mechanics::RigidBody`): Π' = Π × Ω,
//! Ω = 𝕀⁻¹Π, R' = R Ω̂; with `[forces]` a body torque schedule and damping −D Ω.
//!
//! `[system]`: `inertia` (3 principal moments or a symmetric 3×3 matrix, a rigid body's unless
//! `generalized_inertia = true`). `[initial]`: `momentum` Π (3), `attitude` (a rotation; the
//! identity by default).

use super::common::{build_error, SceneSystem, Tag};
use crate::error::SimError;
use crate::fields::{attitude3, inertia3, vec3, FieldError, RawAttitude, RawInertia};
use crate::forces::Forces;
use crate::model::{
    Alg, FreeBodyVisitor, Has, Job, KineticVisitor, Missing, Model, So3Visitor, SplitVisitor,
};
use batch::BodyModel;
use integrators::forces::{BodyTorque, Forced, LinearDamping};
use integrators::splitting::SplitSystem;
use integrators::IntegratorError;
use lie_groups::{LieGroup, So3};
use mechanics::exact::FreeBodyFlow;
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};
use serde::Deserialize;

/// `[system]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The tag (read first, to choose this type).
    #[serde(rename = "kind")]
    _kind: Tag,
    /// 𝕀: principal moments or a symmetric positive definite matrix.
    pub inertia: RawInertia,
    /// Accept principal moments that break the triangle inequality of a rigid body
    /// (`fields::inertia3`); false by default.
    #[serde(default)]
    pub generalized_inertia: bool,
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

/// The checked free rigid body and its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeRigidBody {
    /// Inertia tensor 𝕀 (symmetric positive definite).
    pub inertia: Matrix3<f64>,
    /// Initial body momentum Π₀.
    pub momentum: Vector3<f64>,
    /// Initial attitude R₀ ∈ SO(3).
    pub attitude: Matrix3<f64>,
    /// External torque and damping (`[forces]`).
    pub forces: Option<Forces>,
}

impl SceneSystem for FreeRigidBody {
    const KIND: &'static str = "free-rigid-body";
    const SUMMARY: &'static str =
        "The free rigid body on SO(3): Π' = Π × Ω, Ω = 𝕀⁻¹Π, R' = R Ω̂ (mechanics::RigidBody)";
    const EXAMPLE: &'static str = include_str!("../../../../examples/scenes/free-rigid-body.toml");
    const FORCE_KEYS: &'static [&'static str] = &["torque", "damping"];
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        Ok(Self {
            inertia: inertia3("system.inertia", &params.inertia, params.generalized_inertia)?,
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
        let body = RigidBody::new(self.inertia).map_err(|e| build_error(Self::KIND, e))?;
        let g0 = so3(Self::KIND, &self.attitude, reconstruct)?;
        match &self.forces {
            None => job.run(&So3Body::free(Self::KIND, body), self.momentum, g0),
            Some(f) => {
                let forced = Forced::new(body.clone(), so3_forces(f).map_err(|e| build_error(Self::KIND, e))?);
                job.run(&So3Body::new(Self::KIND, forced, body), self.momentum, g0)
            }
        }
    }
}

/// R₀ when the run reconstructs g.
pub fn so3(kind: &str, r: &Matrix3<f64>, reconstruct: bool) -> Result<Option<So3>, SimError> {
    if reconstruct {
        So3::from_matrix(r)
            .map(Some)
            .map_err(|e| build_error(kind, e))
    } else {
        Ok(None)
    }
}

/// The `[forces]` of a system on SO(3): a body torque schedule u(t) and damping −D Ω, each
/// optional.
pub type So3Forces = (Option<BodyTorque<So3>>, Option<LinearDamping<So3>>);

/// The checked `[forces]` as the integrators' forces on SO(3).
pub fn so3_forces(f: &Forces) -> Result<So3Forces, IntegratorError> {
    Ok((
        f.torque.clone().map(BodyTorque::new).transpose()?,
        f.damping3().map(LinearDamping::new).transpose()?,
    ))
}

/// A rigid body on SO(3) as the methods see it: its system S (the body, the heavy top, either one
/// with forces) splits and has the exact flow of its body `body` as its kinetic flow; the
/// unforced free body is also itself (`free`).
pub struct So3Body<S> {
    kind: &'static str,
    system: S,
    body: RigidBody,
    free: bool,
    /// The batch's copy of the system, where a batch carries it (unforced, 𝕀 diagonal).
    batch: Has<BodyModel>,
}

impl So3Body<RigidBody> {
    /// The unforced free body.
    pub fn free(kind: &'static str, body: RigidBody) -> Self {
        Self {
            kind,
            system: body.clone(),
            batch: BodyModel::free(&body).map_err(|e| Missing::because(e.to_string())),
            body,
            free: true,
        }
    }
}

impl<S> So3Body<S> {
    /// The system S on the body `body` (not the free body itself).
    pub fn new(kind: &'static str, system: S, body: RigidBody) -> Self {
        Self {
            kind,
            system,
            body,
            free: false,
            batch: Err(Missing::default()),
        }
    }
    /// With the batch's copy of the system (`batch::BodyModel`), or why a batch cannot carry it.
    pub fn batched(mut self, batch: Result<BodyModel, batch::BatchError>) -> Self {
        self.batch = batch.map_err(|e| Missing::because(e.to_string()));
        self
    }
}

impl<S: SplitSystem<So3> + Clone + Sync + 'static> Model for So3Body<S> {
    type G = So3;
    type S = S;
    fn kind(&self) -> &'static str {
        self.kind
    }
    fn system(&self) -> &S {
        &self.system
    }
    fn split<V: SplitVisitor<So3>>(&self, v: V, mu0: Vector3<f64>, g0: Option<So3>) -> Has<V::Out> {
        Ok(v.visit(&self.system, mu0, g0))
    }
    fn kinetic_flow<V: KineticVisitor<So3>>(
        &self,
        v: V,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Has<V::Out> {
        Ok(v.visit(&self.system, FreeBodyFlow::new(&self.body), mu0, g0))
    }
    fn so3<V: So3Visitor>(&self, v: V, mu0: Vector3<f64>, g0: Option<So3>) -> Has<V::Out<So3>> {
        Ok(v.visit(&self.system, mu0, g0))
    }
    fn batch_body(&self, g0: Option<&So3>) -> Has<(BodyModel, So3)> {
        let model = self.batch.clone()?;
        Ok((model, g0.copied().unwrap_or_else(So3::identity)))
    }
    fn free_body<V: FreeBodyVisitor>(
        &self,
        v: V,
        mu0: Alg<So3>,
        g0: Option<So3>,
    ) -> Has<V::Out<So3>> {
        if self.free {
            Ok(v.visit(&self.body, mu0, g0))
        } else if self.system.is_forced() {
            Err(Missing::because(format!(
                "this {} has external forces ([forces]), which the free body's own flow and \
                 Hamiltonian do not take",
                self.kind
            )))
        } else {
            Err(Missing::default())
        }
    }
}
