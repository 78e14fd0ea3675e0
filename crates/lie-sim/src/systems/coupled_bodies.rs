//! `coupled-bodies`: N rigid bodies on SE(3)ᴺ joined by springs between attachment points
//! (`mechanics::CoupledBodies`), for the N of [`BODY_COUNTS`].
//!
//! `[system]`: `bodies = [{ mass, inertia }, …]`, `springs = [{ between = [i, j], attachments =
//! [a, b], stiffness, rest_length }, …]`. `[initial]`: `bodies = [{ momentum (6), position,
//! attitude }, …]`.

use super::common::{build_error, SceneSystem, Splits, Tag};
use crate::error::SimError;
use crate::fields::{
    attitude3_at, finite_all, inertia3, position3, positive, FieldError, RawAttitude,
    RawInertia,
};
use crate::model::Job;
use lie_groups::{LieGroup, Power, PowerAlgebra, Se3, So3};
use mechanics::{CoupledBodies as Chain, RigidBodySe3, Spring};
use nalgebra::{Matrix3, Vector3, Vector6};
use serde::Deserialize;

/// The body counts N compiled into lie-sim.
pub const BODY_COUNTS: [usize; 3] = [2, 3, 4];

/// `[system]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The tag (read first, to choose this type).
    #[serde(rename = "kind")]
    _kind: Tag,
    /// The bodies.
    pub bodies: Vec<RawBody>,
    /// The springs (default: none).
    pub springs: Option<Vec<RawSpring>>,
}

/// `[initial]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Initial {
    /// Each body's initial state.
    pub bodies: Vec<RawBodyState>,
}

/// `{ mass, inertia }`: a body.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    /// m > 0.
    pub mass: f64,
    /// Principal moments or a 3×3 matrix, about the centre of mass.
    pub inertia: RawInertia,
    /// Accept principal moments that break the triangle inequality of a rigid body
    /// (`fields::inertia3`); false by default.
    #[serde(default)]
    pub generalized_inertia: bool,
}

/// `{ between = [i, j], attachments = [a, b], stiffness, rest_length }`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSpring {
    /// The two bodies (0-based).
    pub between: [usize; 2],
    /// The attachment points in the two bodies' frames (default: their centres).
    pub attachments: Option<[[f64; 3]; 2]>,
    /// κ ≥ 0.
    pub stiffness: f64,
    /// L ≥ 0 (default 0).
    pub rest_length: Option<f64>,
}

/// `{ momentum, position, attitude }`: a body's initial state.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBodyState {
    /// (Π, P), 6 components.
    pub momentum: Vec<f64>,
    /// x₀ (default 0).
    pub position: Option<Vec<f64>>,
    /// R₀ (default identity).
    pub attitude: Option<RawAttitude>,
}

/// A checked spring.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringSpec {
    /// The bodies (i, j) it joins, i ≠ j, both < N.
    pub between: [usize; 2],
    /// The attachment points a (body i) and b (body j), body frames.
    pub attachments: [Vector3<f64>; 2],
    /// κ ≥ 0.
    pub stiffness: f64,
    /// L ≥ 0.
    pub rest_length: f64,
}

/// One body's checked initial state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// (Π, P).
    pub momentum: Vector6<f64>,
    /// R₀.
    pub attitude: Matrix3<f64>,
    /// x₀.
    pub position: Vector3<f64>,
}

/// The checked bodies, springs and initial states.
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledBodies {
    /// Each body's (mass, inertia about its centre of mass).
    pub bodies: Vec<(f64, Matrix3<f64>)>,
    /// The springs.
    pub springs: Vec<SpringSpec>,
    /// Each body's initial state.
    pub initial: Vec<BodyState>,
}

impl SceneSystem for CoupledBodies {
    const KIND: &'static str = "coupled-bodies";
    const SUMMARY: &'static str = "N rigid bodies on SE(3)ᴺ joined by springs \
                                   (mechanics::CoupledBodies)";
    const EXAMPLE: &'static str = include_str!("../../../../examples/scenes/coupled-bodies.toml");
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        let n = params.bodies.len();
        if !BODY_COUNTS.contains(&n) {
            return Err((
                "system.bodies".into(),
                format!("gives {n} bodies; lie-sim is compiled for {BODY_COUNTS:?} bodies"),
            ));
        }
        let bodies = params
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| {
                let field = format!("system.bodies[{i}].inertia");
                Ok((
                    positive(&format!("system.bodies[{i}].mass"), b.mass)?,
                    inertia3(&field, &b.inertia, b.generalized_inertia)?,
                ))
            })
            .collect::<Result<Vec<_>, FieldError>>()?;
        let springs = params
            .springs
            .as_deref()
            .unwrap_or_default()
            .iter()
            .enumerate()
            .map(|(i, sp)| {
                let at = |key: &str| format!("system.springs[{i}].{key}");
                let [a, b] = sp.between;
                if a == b || a >= n || b >= n {
                    return Err((
                        at("between"),
                        format!("must name two different bodies among 0..{n}, got [{a}, {b}]"),
                    ));
                }
                let att = sp.attachments.unwrap_or([[0.0; 3]; 2]);
                finite_all(&at("attachments"), &[att[0], att[1]].concat())?;
                let nonneg = |key: &str, x: f64| {
                    if x.is_finite() && x >= 0.0 {
                        Ok(x)
                    } else {
                        Err((at(key), format!("must be finite and ≥ 0, got {x}")))
                    }
                };
                Ok(SpringSpec {
                    between: [a, b],
                    attachments: [Vector3::from(att[0]), Vector3::from(att[1])],
                    stiffness: nonneg("stiffness", sp.stiffness)?,
                    rest_length: nonneg("rest_length", sp.rest_length.unwrap_or(0.0))?,
                })
            })
            .collect::<Result<Vec<_>, FieldError>>()?;
        let states = &initial.bodies;
        if states.len() != n {
            return Err((
                "initial.bodies".into(),
                format!("needs one state per body ({n}), got {}", states.len()),
            ));
        }
        let initial = states
            .iter()
            .enumerate()
            .map(|(i, st)| {
                let at = |key: &str| format!("initial.bodies[{i}].{key}");
                if st.momentum.len() != 6 {
                    return Err((
                        at("momentum"),
                        format!("needs 6 components (Π, P), got {}", st.momentum.len()),
                    ));
                }
                finite_all(&at("momentum"), &st.momentum)?;
                Ok(BodyState {
                    momentum: Vector6::from_column_slice(&st.momentum),
                    attitude: attitude3_at(&at("attitude"), &st.attitude)?,
                    position: position3(&at("position"), &st.position)?,
                })
            })
            .collect::<Result<Vec<_>, FieldError>>()?;
        // A spring of rest length L > 0 whose two attachment points coincide: its force
        // κ (|d| − L) d/|d| has no direction at d = 0, and every step fails there whatever h.
        for (k, sp) in springs.iter().enumerate() {
            let [i, j] = sp.between;
            let point = |b: usize, a: &Vector3<f64>| initial[b].position + initial[b].attitude * a;
            let (pi, pj) = (point(i, &sp.attachments[0]), point(j, &sp.attachments[1]));
            // to 12 digits of the positions: nearer, κL/|d| (the stiffness across d) is beyond
            // what a step resolves
            let scale = pi.norm().max(pj.norm()).max(sp.rest_length);
            if sp.stiffness > 0.0 && sp.rest_length > 0.0 && (pi - pj).norm() <= 1e-12 * scale {
                return Err((
                    format!("system.springs[{k}].attachments"),
                    format!(
                        "the attachment points of bodies {i} and {j} coincide in the initial \
                         state (at {:?}): the spring's direction, and so its force with \
                         rest_length = {:?} > 0, is undefined there; move a body or an \
                         attachment point",
                        pi.as_slice(),
                        sp.rest_length
                    ),
                ));
            }
        }
        Ok(Self {
            bodies,
            springs,
            initial,
        })
    }
    fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError> {
        fn go<const N: usize, J: Job>(
            p: &CoupledBodies,
            reconstruct: bool,
            job: J,
        ) -> Result<J::Out, SimError> {
            let built = |e: &dyn std::fmt::Display| build_error(CoupledBodies::KIND, e);
            let bodies: Vec<RigidBodySe3> = p
                .bodies
                .iter()
                .map(|(m, i)| RigidBodySe3::free(*m, *i))
                .collect::<Result<_, _>>()
                .map_err(|e| built(&e))?;
            let bodies: [RigidBodySe3; N] = bodies
                .try_into()
                .map_err(|_| built(&"the body count"))?;
            let springs = p
                .springs
                .iter()
                .map(|s| Spring::new(s.between, s.attachments, s.stiffness, s.rest_length))
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| built(&e))?;
            let system = Chain::new(bodies, springs).map_err(|e| built(&e))?;
            let mu0 = PowerAlgebra::<Se3, N>::from_parts_fn(|k| p.initial[k].momentum);
            let g0 = if reconstruct {
                let parts: Vec<Se3> = p
                    .initial
                    .iter()
                    .map(|st| {
                        So3::from_matrix(&st.attitude).map(|r| Se3::from_parts(r, st.position))
                    })
                    .collect::<Result<_, _>>()
                    .map_err(|e| built(&e))?;
                let parts: [Se3; N] = parts.try_into().map_err(|_| built(&"the body count"))?;
                Some(Power::new(parts))
            } else {
                None
            };
            job.run(&Splits::new(CoupledBodies::KIND, system, Ok(())), mu0, g0)
        }
        match self.bodies.len() {
            2 => go::<2, J>(self, reconstruct, job),
            3 => go::<3, J>(self, reconstruct, job),
            4 => go::<4, J>(self, reconstruct, job),
            n => Err(SimError::NotYetAvailable {
                what: Self::KIND.into(),
                why: format!("{n} bodies are not compiled into lie-sim (counts: {BODY_COUNTS:?})"),
            }),
        }
    }
}
