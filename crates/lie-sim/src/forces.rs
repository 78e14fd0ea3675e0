//! The `[forces]` table of a scene: external torques, forces, thrust and wheel torques as
//! constant or piecewise-linear schedules, linear damping (drag) and quadratic drag, applied in
//! the discrete Lagrange–d'Alembert way (`integrators::forces`).
//!
//! ```toml
//! [forces]
//! torque = [0.0, 0.0, 0.1]            # body torque: constant, or a schedule:
//! # torque = { times = [0.0, 5.0], values = [[0.0, 0.0, 0.1], [0.0, 0.0, 0.0]] }
//! force = [10.0, 0.0, 0.0]            # body force (underwater-vehicle: thrusters)
//! thrust = 14.7                       # thrust along the body's third axis (quadrotor)
//! # thrust = { times = [0.0, 1.0], values = [14.7, 16.0] }
//! wheel_torque = [0.0, 0.01, 0.0]     # one motor torque per wheel (gyrostat)
//! damping = 0.05                      # F = −D ξ: a number c (D = c I), n entries, or n×n symmetric
//! quadratic_drag = [0, 0, 0, 5, 20, 20]   # Fᵢ = −dᵢ|ξᵢ|ξᵢ: a number or n entries, each ≥ 0
//! ```
//!
//! Which keys a system takes (its [`ForceSlots`], declared by its module in [`crate::systems`])
//! and the dimension n of its algebra (3 on SO(3),
//! 6 on SE(3)) are checked; a schedule holds its first value before `times[0]` and its last after
//! the end. Every malformed entry is a one-line error naming the field.

use crate::fields::{FieldError, RawInertia, RawNumbers};
use integrators::forces::{LinearDamping, QuadraticDrag, Schedule};
use lie_groups::{Se3, So3};
use nalgebra::{Matrix3, Matrix6, Vector6};
use serde::Deserialize;

/// `[forces]` as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawForces {
    /// Body torque: `[τ₁, τ₂, τ₃]`, or `{ times = [...], values = [[...], ...] }`.
    pub torque: Option<RawSchedule>,
    /// Body force (SE(3)): `[f₁, f₂, f₃]` or a schedule.
    pub force: Option<RawSchedule>,
    /// Thrust along the body's third axis (quadrotor): a number or a schedule of numbers.
    pub thrust: Option<RawSchedule>,
    /// Wheel-motor torques (gyrostat): one per wheel, or a schedule.
    pub wheel_torque: Option<RawSchedule>,
    /// Damping D: a number c (D = c I), n diagonal entries, or a symmetric n×n matrix.
    pub damping: Option<RawInertia>,
    /// Quadratic drag coefficients: a number (every component) or n entries.
    pub quadratic_drag: Option<RawNumbers>,
}

/// A constant (a number or a vector) or a piecewise-linear schedule.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum RawSchedule {
    /// A constant number (one input).
    Scalar(f64),
    /// A constant vector.
    Constant(Vec<f64>),
    /// `values[i]` at `times[i]`, linear in between, held outside.
    Table(RawScheduleTable),
}

/// `{ times = [...], values = [...] }`: one value (a number or a vector) per time.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScheduleTable {
    /// Strictly increasing times.
    pub times: Vec<f64>,
    /// One value per time.
    pub values: Vec<RawNumbers>,
}

/// The checked `[forces]` table; each entry optional, at least one present.
#[derive(Debug, Clone, PartialEq)]
pub struct Forces {
    /// Body torque τ(t).
    pub torque: Option<Schedule>,
    /// Body force f(t) (SE(3)).
    pub force: Option<Schedule>,
    /// Thrust f(t) along the body's third axis (quadrotor).
    pub thrust: Option<Schedule>,
    /// Wheel-motor torques u(t), one per wheel (gyrostat).
    pub wheel_torque: Option<Schedule>,
    /// Damping D (F = −D ξ), n×n row-major: symmetric, finite, nonnegative diagonal.
    pub damping: Option<Vec<f64>>,
    /// Quadratic drag coefficients dᵢ ≥ 0, n of them.
    pub quadratic_drag: Option<Vec<f64>>,
}

/// The `[forces]` keys a system takes and the sizes they must have.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceSlots {
    /// The keys, in the order of the error messages.
    pub keys: &'static [&'static str],
    /// n, the dimension of the algebra (of `damping` and `quadratic_drag`).
    pub dim: usize,
    /// The number of wheels (of `wheel_torque`).
    pub wheels: usize,
}

impl Forces {
    /// One line for the run's summary: which forces act.
    pub fn describe(&self) -> String {
        let scheduled = |s: &Option<Schedule>, what: &str| {
            s.as_ref().map(|s| match s.knots() {
                1 => format!("constant {what}"),
                n => format!("{what} on a {n}-knot schedule"),
            })
        };
        let terms: Vec<String> = [
            scheduled(&self.torque, "body torque"),
            scheduled(&self.force, "body force"),
            scheduled(&self.thrust, "thrust"),
            scheduled(&self.wheel_torque, "wheel torques"),
            self.damping.as_ref().map(|_| "damping −D ξ".to_string()),
            self.quadratic_drag
                .as_ref()
                .map(|_| "quadratic drag −dᵢ|ξᵢ|ξᵢ".to_string()),
        ]
        .into_iter()
        .flatten()
        .collect();
        format!(
            "{} (discrete Lagrange–d'Alembert; energy and Casimir change by their work)",
            terms.join(" + ")
        )
    }
    /// The damping as a 3×3 matrix (SO(3) systems).
    pub fn damping3(&self) -> Option<Matrix3<f64>> {
        self.damping.as_ref().map(|d| Matrix3::from_row_slice(d))
    }
    /// The damping as a 6×6 matrix (SE(3) systems).
    pub fn damping6(&self) -> Option<Matrix6<f64>> {
        self.damping.as_ref().map(|d| Matrix6::from_row_slice(d))
    }
    /// The quadratic drag coefficients on 𝔰𝔢(3) (SE(3) systems).
    pub fn quadratic_drag6(&self) -> Option<Vector6<f64>> {
        self.quadratic_drag
            .as_ref()
            .map(|d| Vector6::from_column_slice(d))
    }
}

/// Checks `raw` for a system that takes `slots` (`kind`: its name, for messages).
pub fn check_forces(raw: &RawForces, slots: ForceSlots, kind: &str) -> Result<Forces, FieldError> {
    let present = [
        ("torque", raw.torque.is_some()),
        ("force", raw.force.is_some()),
        ("thrust", raw.thrust.is_some()),
        ("wheel_torque", raw.wheel_torque.is_some()),
        ("damping", raw.damping.is_some()),
        ("quadratic_drag", raw.quadratic_drag.is_some()),
    ];
    if let Some((key, _)) = present
        .iter()
        .find(|(key, given)| *given && !slots.keys.contains(key))
    {
        return Err((
            format!("forces.{key}"),
            format!(
                "is not a force of {kind} (its forces: {})",
                slots.keys.join(", ")
            ),
        ));
    }
    if !present.iter().any(|(_, given)| *given) {
        return Err((
            "forces".into(),
            format!(
                "an empty [forces] table: give one of {}",
                slots.keys.join(", ")
            ),
        ));
    }
    let n = slots.dim;
    Ok(Forces {
        torque: schedule(
            &raw.torque,
            "forces.torque",
            3,
            "a body torque has 3 components",
        )?,
        force: schedule(
            &raw.force,
            "forces.force",
            3,
            "a body force has 3 components",
        )?,
        thrust: schedule(&raw.thrust, "forces.thrust", 1, "the thrust is one number")?,
        wheel_torque: schedule(
            &raw.wheel_torque,
            "forces.wheel_torque",
            slots.wheels,
            &format!(
                "the wheel torque has one component per wheel ({})",
                slots.wheels
            ),
        )?,
        damping: raw.damping.as_ref().map(|d| damping(d, n)).transpose()?,
        quadratic_drag: raw
            .quadratic_drag
            .as_ref()
            .map(|d| quadratic_drag(d, n))
            .transpose()?,
    })
}

/// A checked schedule of `dim` components (`what`: the rule, for a wrong length).
fn schedule(
    raw: &Option<RawSchedule>,
    field: &str,
    dim: usize,
    what: &str,
) -> Result<Option<Schedule>, FieldError> {
    let Some(raw) = raw else {
        return Ok(None);
    };
    let numbers = |v: &RawNumbers| match v {
        RawNumbers::Scalar(x) => vec![*x],
        RawNumbers::List(v) => v.clone(),
    };
    let s = match raw {
        RawSchedule::Scalar(x) => Schedule::constant(vec![*x]),
        RawSchedule::Constant(v) => Schedule::constant(v.clone()),
        RawSchedule::Table(t) => {
            Schedule::new(t.times.clone(), t.values.iter().map(numbers).collect())
        }
    }
    .map_err(|e| (field.to_string(), e.to_string()))?;
    if s.dim() != dim {
        return Err((field.into(), format!("{what}, got {}", s.dim())));
    }
    Ok(Some(s))
}

/// D from a number c (c I), n diagonal entries or an n×n matrix, checked by
/// `integrators::forces::LinearDamping` (finite, symmetric, nonnegative diagonal).
fn damping(raw: &RawInertia, n: usize) -> Result<Vec<f64>, FieldError> {
    let field = "forces.damping";
    let d: Vec<f64> = match raw {
        RawInertia::Scalar(c) => (0..n * n)
            .map(|k| if k / n == k % n { *c } else { 0.0 })
            .collect(),
        RawInertia::Diagonal(v) if v.len() == n => (0..n * n)
            .map(|k| if k / n == k % n { v[k / n] } else { 0.0 })
            .collect(),
        RawInertia::Matrix(rows) if rows.len() == n && rows.iter().all(|r| r.len() == n) => {
            rows.iter().flatten().copied().collect()
        }
        _ => {
            return Err((
                field.into(),
                format!("give a number c (D = c I), {n} diagonal entries or a {n}×{n} matrix"),
            ))
        }
    };
    let checked = match n {
        3 => LinearDamping::<So3>::new(Matrix3::from_row_slice(&d)).map(|_| ()),
        _ => LinearDamping::<Se3>::new(Matrix6::from_row_slice(&d)).map(|_| ()),
    };
    checked.map_err(|e| (field.to_string(), e.to_string()))?;
    Ok(d)
}

/// dᵢ from a number (every component) or n entries, each finite and ≥ 0.
fn quadratic_drag(raw: &RawNumbers, n: usize) -> Result<Vec<f64>, FieldError> {
    let field = "forces.quadratic_drag";
    let d = match raw {
        RawNumbers::Scalar(x) => vec![*x; n],
        RawNumbers::List(v) if v.len() == n => v.clone(),
        RawNumbers::List(v) => {
            return Err((
                field.into(),
                format!("give a number or {n} coefficients, got {}", v.len()),
            ))
        }
    };
    QuadraticDrag::<Se3>::new(Vector6::from_column_slice(&d))
        .map_err(|e| (field.to_string(), e.to_string()))?;
    Ok(d)
}
