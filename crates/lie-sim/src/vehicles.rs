//! The scene kinds of vehicles and coupled bodies: `gyrostat`, `underwater-vehicle`,
//! `quadrotor` and `coupled-bodies` — their checked parameters and the checks that make them from
//! the raw `[system]` and `[initial]` tables (the other kinds are in [`crate::scene`]).
//!
//! | kind | `[system]` | `[initial]` |
//! |---|---|---|
//! | `gyrostat` | `inertia` 𝕀 (locked, whole spacecraft), `wheel_axes` (K × 3), `wheel_inertia` (K) | `momentum` (Π, p): 3 + K; `attitude`; `wheel_angles` (K, default 0) |
//! | `underwater-vehicle` | `mass`, `inertia` (about the centre of gravity), `center_of_mass` r_G, `added_mass` M_A (6 or 6×6, (ω, v) ordering), `gravity` g, `buoyancy` B, `center_of_buoyancy` r_B | `momentum` (Π, P): 6; `attitude`; `position` |
//! | `quadrotor` | `mass`, `inertia`, `gravity` g | `momentum` (Π, P): 6; `attitude`; `position` |
//! | `coupled-bodies` | `bodies = [{ mass, inertia }, …]`, `springs = [{ between = [i, j], attachments = [a, b], stiffness, rest_length }, …]` | `bodies = [{ momentum (6), position, attitude }, …]` |
//!
//! K ∈ [`WHEEL_COUNTS`] and N ∈ [`BODY_COUNTS`] (each is a separate compiled system). The
//! vehicle's mass matrix is `M = M_RB + M_A` with M_RB from the mass, inertia and centre of
//! gravity (`mechanics::systems::UnderwaterVehicle::rigid_body_mass_matrix`), and must be
//! positive definite; its weight is W = m g.

use crate::forces::Forces;
use crate::scene::{
    attitude3, attitude3_at, finite_all, gravity_down, inertia3_at, momentum_of_len, positive,
    required, symmetric_positive_definite, vec3, FieldError, RawAttitude, RawInertia, RawInitial,
    RawSystem, SystemKind,
};
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};
use serde::Deserialize;

/// The wheel counts K of `gyrostat` compiled into lie-sim.
pub const WHEEL_COUNTS: [usize; 4] = [1, 2, 3, 4];

/// The body counts N of `coupled-bodies` compiled into lie-sim.
pub const BODY_COUNTS: [usize; 3] = [2, 3, 4];

/// A spacecraft with K reaction wheels (`mechanics::systems::Gyrostat`).
#[derive(Debug, Clone, PartialEq)]
pub struct Gyrostat {
    /// 𝕀, the whole spacecraft with the wheels locked.
    pub inertia: Matrix3<f64>,
    /// The unit wheel axes aᵢ (body frame).
    pub axes: Vec<Vector3<f64>>,
    /// The axial wheel inertias Jᵢ.
    pub wheel_inertia: Vec<f64>,
    /// Initial (Π, p), 3 + K components.
    pub momentum: Vec<f64>,
    /// Initial attitude R₀.
    pub attitude: Matrix3<f64>,
    /// Initial wheel angles φ₀.
    pub wheel_angles: Vec<f64>,
    /// Wheel torques and a platform torque (`[forces]`).
    pub forces: Option<Forces>,
}

/// An underwater vehicle on SE(3) (`mechanics::systems::UnderwaterVehicle`).
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
        mechanics::systems::UnderwaterVehicle::rigid_body_mass_matrix(
            self.mass,
            &self.inertia,
            &self.center_of_gravity,
        ) + self.added_mass
    }
    /// Whether M is block diagonal (M_ωv = 0), so that the vehicle splits.
    pub fn is_decoupled(&self) -> bool {
        self.mass_matrix()
            .fixed_view::<3, 3>(0, 3)
            .iter()
            .all(|&x| x == 0.0)
    }
}

/// A quadrotor on SE(3) (`mechanics::systems::Quadrotor`).
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

/// N bodies on SE(3)ᴺ joined by springs (`mechanics::systems::CoupledBodies`).
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledBodies {
    /// Each body's (mass, inertia about its centre of mass).
    pub bodies: Vec<(f64, Matrix3<f64>)>,
    /// The springs.
    pub springs: Vec<SpringSpec>,
    /// Each body's initial state.
    pub initial: Vec<BodyState>,
}

/// A checked spring of `coupled-bodies`.
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

/// One body's initial state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// (Π, P).
    pub momentum: Vector6<f64>,
    /// R₀.
    pub attitude: Matrix3<f64>,
    /// x₀.
    pub position: Vector3<f64>,
}

/// `{ mass, inertia }`: a body of `coupled-bodies`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    /// m > 0.
    pub mass: f64,
    /// Principal moments or a 3×3 matrix, about the centre of mass.
    pub inertia: RawInertia,
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

fn position3(field: &str, raw: &Option<Vec<f64>>) -> Result<Vector3<f64>, FieldError> {
    vec3(field, raw.as_deref().unwrap_or(&[0.0; 3]))
}

/// A `gyrostat` scene's system and initial state.
pub fn check_gyrostat(s: &RawSystem, init: &RawInitial) -> Result<Gyrostat, FieldError> {
    let kind = SystemKind::Gyrostat;
    let inertia = crate::scene::inertia3_at(
        "system.inertia",
        &required(kind, "system.inertia", &s.inertia)?,
    )?;
    let raw_axes = required(kind, "system.wheel_axes", &s.wheel_axes)?;
    let k = raw_axes.len();
    if !WHEEL_COUNTS.contains(&k) {
        return Err((
            "system.wheel_axes".into(),
            format!("gives {k} wheels; lie-sim is compiled for {WHEEL_COUNTS:?} wheels"),
        ));
    }
    let mut axes = Vec::with_capacity(k);
    for (i, a) in raw_axes.iter().enumerate() {
        let field = format!("system.wheel_axes[{i}]");
        finite_all(&field, a)?;
        let v = Vector3::from(*a);
        if v.norm() == 0.0 {
            return Err((
                field,
                "is the zero vector: a wheel axis needs a direction".into(),
            ));
        }
        axes.push(v.normalize());
    }
    let wheel_inertia = required(kind, "system.wheel_inertia", &s.wheel_inertia)?;
    if wheel_inertia.len() != k {
        return Err((
            "system.wheel_inertia".into(),
            format!(
                "needs one inertia per wheel ({k}), got {}",
                wheel_inertia.len()
            ),
        ));
    }
    for &j in &wheel_inertia {
        positive("system.wheel_inertia", j)?;
    }
    let platform = axes
        .iter()
        .zip(&wheel_inertia)
        .fold(inertia, |m, (a, j)| m - a * a.transpose() * *j);
    if platform.cholesky().is_none() {
        return Err((
            "system.wheel_inertia".into(),
            "exceeds the body: 𝕀 − Σ Jᵢ aᵢaᵢᵀ is not positive definite (𝕀 is the whole \
             spacecraft's inertia, wheels included)"
                .into(),
        ));
    }
    let momentum = required(kind, "initial.momentum", &init.momentum)?;
    momentum_of_len(kind, &momentum, 3 + k)?;
    let wheel_angles = init.wheel_angles.clone().unwrap_or_else(|| vec![0.0; k]);
    if wheel_angles.len() != k {
        return Err((
            "initial.wheel_angles".into(),
            format!(
                "needs one angle per wheel ({k}), got {}",
                wheel_angles.len()
            ),
        ));
    }
    finite_all("initial.wheel_angles", &wheel_angles)?;
    Ok(Gyrostat {
        inertia,
        axes,
        wheel_inertia,
        momentum,
        attitude: attitude3(&init.attitude)?,
        wheel_angles,
        forces: None,
    })
}

/// An `underwater-vehicle` scene's system and initial state.
pub fn check_underwater_vehicle(
    s: &RawSystem,
    init: &RawInitial,
) -> Result<UnderwaterVehicle, FieldError> {
    let kind = SystemKind::UnderwaterVehicle;
    let mass = positive("system.mass", required(kind, "system.mass", &s.mass)?)?;
    let inertia = inertia3_at(
        "system.inertia",
        &required(kind, "system.inertia", &s.inertia)?,
    )?;
    let center_of_gravity = Vector3::from(s.center_of_mass.unwrap_or([0.0; 3]));
    finite_all("system.center_of_mass", center_of_gravity.as_slice())?;
    let field = "system.added_mass";
    let added_mass = match required(kind, field, &s.added_mass)? {
        RawInertia::Diagonal(d) if d.len() == 6 => {
            finite_all(field, &d)?;
            if let Some(x) = d.iter().find(|x| **x < 0.0) {
                return Err((field.into(), format!("entries must be ≥ 0, got {x}")));
            }
            Matrix6::from_diagonal(&Vector6::from_column_slice(&d))
        }
        RawInertia::Matrix(rows) => {
            let flat = crate::scene::square(field, &rows, 6)?;
            Matrix6::from_row_slice(&flat)
        }
        _ => {
            return Err((
                field.into(),
                "must be 6 diagonal entries or a symmetric 6×6 matrix, (ω, v) ordering".into(),
            ))
        }
    };
    let gravity = gravity_down(kind, &s.gravity)?;
    let buoyancy = required(kind, "system.buoyancy", &s.buoyancy)?;
    if !(buoyancy.is_finite() && buoyancy >= 0.0) {
        return Err((
            "system.buoyancy".into(),
            format!("must be a finite force ≥ 0, got {buoyancy}"),
        ));
    }
    let center_of_buoyancy = Vector3::from(s.center_of_buoyancy.unwrap_or([0.0; 3]));
    finite_all("system.center_of_buoyancy", center_of_buoyancy.as_slice())?;
    let momentum = required(kind, "initial.momentum", &init.momentum)?;
    momentum_of_len(kind, &momentum, 6)?;
    let vehicle = UnderwaterVehicle {
        mass,
        inertia,
        center_of_gravity,
        added_mass,
        gravity,
        buoyancy,
        center_of_buoyancy,
        momentum: Vector6::from_column_slice(&momentum),
        attitude: attitude3(&init.attitude)?,
        position: position3("initial.position", &init.position)?,
        forces: None,
    };
    // M = M_RB + M_A symmetric positive definite (M_A symmetric, M_RB is).
    let m = vehicle.mass_matrix();
    symmetric_positive_definite(field, m.transpose().as_slice(), 6)
        .map_err(|(f, msg)| (f, format!("M_RB + M_A {msg}")))?;
    Ok(vehicle)
}

/// A `quadrotor` scene's system and initial state.
pub fn check_quadrotor(s: &RawSystem, init: &RawInitial) -> Result<Quadrotor, FieldError> {
    let kind = SystemKind::Quadrotor;
    let momentum = required(kind, "initial.momentum", &init.momentum)?;
    momentum_of_len(kind, &momentum, 6)?;
    Ok(Quadrotor {
        mass: positive("system.mass", required(kind, "system.mass", &s.mass)?)?,
        inertia: inertia3_at(
            "system.inertia",
            &required(kind, "system.inertia", &s.inertia)?,
        )?,
        gravity: gravity_down(kind, &s.gravity)?,
        momentum: Vector6::from_column_slice(&momentum),
        attitude: attitude3(&init.attitude)?,
        position: position3("initial.position", &init.position)?,
        forces: None,
    })
}

/// A `coupled-bodies` scene's system and initial state.
pub fn check_coupled_bodies(s: &RawSystem, init: &RawInitial) -> Result<CoupledBodies, FieldError> {
    let kind = SystemKind::CoupledBodies;
    let raw_bodies = required(kind, "system.bodies", &s.bodies)?;
    let n = raw_bodies.len();
    if !BODY_COUNTS.contains(&n) {
        return Err((
            "system.bodies".into(),
            format!("gives {n} bodies; lie-sim is compiled for {BODY_COUNTS:?} bodies"),
        ));
    }
    let bodies = raw_bodies
        .iter()
        .enumerate()
        .map(|(i, b)| {
            Ok((
                positive(&format!("system.bodies[{i}].mass"), b.mass)?,
                inertia3_at(&format!("system.bodies[{i}].inertia"), &b.inertia)?,
            ))
        })
        .collect::<Result<Vec<_>, FieldError>>()?;
    let springs = s
        .springs
        .clone()
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
    let states = required(kind, "initial.bodies", &init.bodies)?;
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
    Ok(CoupledBodies {
        bodies,
        springs,
        initial,
    })
}
