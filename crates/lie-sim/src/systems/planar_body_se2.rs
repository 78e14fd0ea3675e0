//! `planar-body-se2`: a planar rigid body on SE(2) (`mechanics::PlanarBody`), free, on a spring
//! from the origin to a body point, in uniform gravity.
//!
//! `[system]`: `inertia` J (one number, about the centre of mass), `mass`, `stiffness` k ≥ 0
//! (default 0), `attachment` c (body frame, default the centre), `gravity` γ ∈ ℝ² (space frame,
//! default 0). `[initial]`: `momentum` (L, Pₓ, P_y), `attitude = { angle = φ }`, `position` (2).

use super::common::{build_error, SceneSystem, Splits, Tag};
use crate::error::SimError;
use crate::fields::{
    finite_all, momentum_of_len, non_negative, positive, FieldError, RawAttitude, RawInertia,
    RawNumbers,
};
use crate::model::Job;
use lie_groups::{Se2, So2};
use mechanics::PlanarBody;
use nalgebra::{Vector2, Vector3};
use serde::Deserialize;

/// `[system]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The tag (read first, to choose this type).
    #[serde(rename = "kind")]
    _kind: Tag,
    /// J about the centre of mass: one number.
    pub inertia: RawInertia,
    /// m > 0.
    pub mass: f64,
    /// k ≥ 0 (default 0: no spring).
    pub stiffness: Option<f64>,
    /// c, body frame (default: the centre of mass).
    pub attachment: Option<[f64; 2]>,
    /// γ ∈ ℝ², space frame (default 0).
    pub gravity: Option<RawNumbers>,
}

/// `[initial]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Initial {
    /// (L, Pₓ, P_y).
    pub momentum: Vec<f64>,
    /// `{ angle = φ }` (default 0).
    pub attitude: Option<RawAttitude>,
    /// x₀ (default: the origin).
    pub position: Option<Vec<f64>>,
}

/// The checked planar body and its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarBodySe2 {
    /// Moment of inertia about the centre of mass.
    pub inertia: f64,
    /// Mass m.
    pub mass: f64,
    /// Spring stiffness k ≥ 0 (0: no spring).
    pub stiffness: f64,
    /// Spring attachment point c, body frame.
    pub attachment: Vector2<f64>,
    /// Uniform gravitational acceleration γ, space frame.
    pub gravity: Vector2<f64>,
    /// Initial body momentum μ₀ ∈ 𝔰𝔢(2)* in the basis of `lie_groups`' SE(2) `vee`.
    pub momentum: Vector3<f64>,
    /// Initial angle.
    pub angle: f64,
    /// Initial position.
    pub position: Vector2<f64>,
}

impl SceneSystem for PlanarBodySe2 {
    const KIND: &'static str = "planar-body-se2";
    const SUMMARY: &'static str = "A planar rigid body on SE(2): free, on a spring, in uniform \
                                   gravity (mechanics::PlanarBody)";
    const EXAMPLE: &'static str = include_str!("../../../../examples/scenes/planar-body-se2.toml");
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        let mass = positive("system.mass", params.mass)?;
        let inertia = match &params.inertia {
            RawInertia::Scalar(j) => positive("system.inertia", *j)?,
            _ => {
                return Err((
                    "system.inertia".into(),
                    "must be one number (the moment about the centre of mass) for \
                     planar-body-se2"
                        .into(),
                ))
            }
        };
        let stiffness = non_negative("system.stiffness", params.stiffness.unwrap_or(0.0))?;
        let c = params.attachment.unwrap_or([0.0; 2]);
        finite_all("system.attachment", &c)?;
        let gravity = match &params.gravity {
            None => Vector2::zeros(),
            Some(RawNumbers::List(v)) if v.len() == 2 => {
                finite_all("system.gravity", v)?;
                Vector2::new(v[0], v[1])
            }
            Some(_) => {
                return Err((
                    "system.gravity".into(),
                    "must be the planar acceleration [γx, γy] for planar-body-se2".into(),
                ))
            }
        };
        let angle = match &initial.attitude {
            None => 0.0,
            Some(RawAttitude::Angle(a)) if a.is_finite() => *a,
            Some(RawAttitude::Angle(a)) => {
                return Err((
                    "initial.attitude.angle".into(),
                    format!("must be finite, got {a}"),
                ))
            }
            Some(_) => {
                return Err((
                    "initial.attitude".into(),
                    "must be { angle = … } for planar-body-se2".into(),
                ))
            }
        };
        let pos = initial.position.clone().unwrap_or_else(|| vec![0.0; 2]);
        if pos.len() != 2 {
            return Err((
                "initial.position".into(),
                format!("needs 2 components for {}, got {}", Self::KIND, pos.len()),
            ));
        }
        finite_all("initial.position", &pos)?;
        momentum_of_len(Self::KIND, &initial.momentum, 3)?;
        Ok(Self {
            inertia,
            mass,
            stiffness,
            attachment: Vector2::from(c),
            gravity,
            momentum: Vector3::from_column_slice(&initial.momentum),
            angle,
            position: Vector2::new(pos[0], pos[1]),
        })
    }
    fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError> {
        let body = PlanarBody::free(self.mass, self.inertia)
            .and_then(|s| s.with_spring(self.stiffness, self.attachment))
            .and_then(|s| s.with_gravity(self.gravity))
            .map_err(|e| build_error(Self::KIND, e))?;
        let g0 = reconstruct.then(|| Se2::new(So2::from_angle(self.angle), self.position));
        job.run(&Splits::new(Self::KIND, body, Ok(())), self.momentum, g0)
    }
}
