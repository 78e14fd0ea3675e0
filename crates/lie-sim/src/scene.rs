//! Scenes: what to simulate, read from TOML.
//!
//! A scene has four tables (every table and key is checked: an unknown key is an error):
//!
//! ```toml
//! name = "tumbling book"            # optional, shown in the summary
//!
//! [system]
//! kind = "free-rigid-body"          # free-rigid-body | heavy-top (= pendulum-3d) | rigid-body-se3 |
//!                                   #   planar-body-se2 | geodesic-so-n | gyrostat |
//!                                   #   underwater-vehicle | quadrotor | coupled-bodies
//! inertia = [1.0, 2.0, 3.0]         # principal moments, or a symmetric 3×3 matrix [[..], [..], [..]]
//!
//! [initial]
//! momentum = [0.01, 1.0, 0.01]      # body momentum μ ∈ 𝔤* (Π for SO(3))
//! attitude = { rotation_vector = [0.0, 0.0, 0.0] }   # or { quaternion = [w, x, y, z] }, { matrix = [[..], ..] }
//!
//! [integrator]
//! method = "lie-poisson"            # lie-poisson | euler-poincare | euler-arnold | rk4 | rkmk4 |
//!                                   #   splitting | kinetic-kick | exact
//! tau = "cayley"                    # exp | cayley (rk4, splitting, kinetic-kick, exact: none;
//!                                   #   rkmk4: exp only)
//! theta = 0.5                       # θ ∈ [0, 1] of the discretization map (Lie methods only)
//! step = 0.01                       # h > 0
//! duration = 100.0                  # T > 0; ⌈T/h⌉ steps, the last one shortened to land on T
//! reconstruct = true                # integrate g as well as μ (default true)
//! # solver = "simplified-newton"    # implicit solver: simplified-newton (default) | newton |
//! #                                   #   newton-fd | fixed-point
//! # tolerance = 1e-14               # implicit solver options (default: the integrators crate's)
//! # max_iterations = 50
//! # composition = "kahan-li-6"      # optional: compose the θ = ½ method to order 4, 6, 8, … (below)
//! # processing = "blanes-casas-murua-6-11"  # optional: the processed method P ∘ Kⁿ ∘ P⁻¹ of a
//!                                   #   symmetric base, effective order 6 (below)
//! # splitting = "blanes-moan-4"     # kinetic-kick only: strang (default) | blanes-moan-4 | blanes-moan-6
//! # modified = true                 # lie-poisson (θ = 0.5 or 0) on the modified Hamiltonian:
//!                                   #   order 4 or 6 at the cost of order 2 (free-rigid-body)
//! # order = 6                       # modified only: 4 (H − h²H₂, default) or 6 (− h⁴H₄ too)
//!
//! [output]
//! stride = 10                       # write every 10th step (default 1); t = 0 and t = T always
//! # times = [0.5, 1.0, 2.5]         # or: rows at exactly these times in [0, T] (interpolated
//!                                   #   between steps by a cubic Hermite on G × 𝔤*; the step
//!                                   #   is not changed)
//!
//! [[events]]                        # optional, repeatable: where a trajectory column crosses a value
//! quantity = "mu1"                  # mu1…, g11…, energy, casimir
//! value = 0.0                       # default 0
//! direction = "falling"             # rising | falling | either (default)
//! stop = true                       # end the run at the first crossing (default false)
//!
//! [sweep]                           # optional: the ensemble run by `lie-sim sweep`
//! count = 10000                     # N trajectories
//! seed = 1                          # member i depends only on (seed, i) (default 0)
//! kind = "momenta-on-energy-level"  # or "momenta-on-sphere"
//! # monitor_every = 1               # energy/Casimir sampled every k steps (and the last)
//!
//! [forces]                          # optional: external forces (keys by kind: crate::forces)
//! torque = [0.0, 0.0, 0.1]          # constant body torque, or a piecewise-linear schedule:
//! # torque = { times = [0.0, 5.0], values = [[0.0, 0.0, 0.1], [0.0, 0.0, 0.0]] }
//! damping = 0.05                    # F = −D ξ: a number c (D = c I), n entries, or n×n symmetric
//! # force, thrust, wheel_torque: schedules; quadratic_drag: Fᵢ = −dᵢ|ξᵢ|ξᵢ
//! ```
//!
//! `[forces]` ([`crate::forces`]: `torque` and `damping` for free-rigid-body and heavy-top;
//! `torque` and `wheel_torque` for gyrostat; `torque`, `force`, `damping`, `quadratic_drag` for
//! underwater-vehicle; `thrust`, `torque`, `damping`, `quadratic_drag` for quadrotor) is applied
//! in the discrete Lagrange–d'Alembert way (`integrators::forces`) by `lie-poisson`,
//! `euler-poincare`, `rk4` and `rkmk4`, and in the kicks of `splitting` and `kinetic-kick`
//! (exactly for torques, forces, thrust and wheel torques, by the implicit midpoint rule for
//! damping and drag: order 2); `exact`, `euler-arnold` and `modified` refuse it. A schedule holds
//! its first value before `times[0]` and its last after the end.
//!
//! `composition` names a scheme of `integrators::CompositionScheme` (`triple-jump-4|6|8|10`,
//! `suzuki-4|6|8|10`, `mclachlan-4`, `kahan-li-6`, `kahan-li-8`, `mclachlan-8`,
//! `sofroniou-spaletta-10`): one step of size h is the steps γ₁h, …, γ_s h of the base method.
//! It needs a symmetric base: `lie-poisson`, `euler-poincare` or `euler-arnold` with θ = 0.5.
//!
//! `processing` names a scheme of `integrators::processing::ProcessingScheme` (`blanes-6`: 7
//! base steps a step; `blanes-casas-murua-6-11`: 11; `blanes-casas-murua-6-13`: 13): the
//! processed method `P ∘ Kⁿ ∘ P⁻¹` of effective order 6, whose kernel K is a composition of the
//! symmetric base method and whose processor P (10–12 base steps) runs only when the state is
//! read, never as part of a step. `lie-sim run` reads the state after every step (its energy
//! monitor and events), so there a processed method pays P every step; `trade` reads every 8
//! steps and at T, `sweep` every `monitor_every` steps. It needs a symmetric base as
//! `composition` does, or `splitting` / `kinetic-kick`, and does not go with `composition` or
//! `modified`.
//!
//! `modified = true` runs `lie-poisson` (θ = 0.5 or θ = 0; τ = exp or cayley) on the modified
//! Hamiltonian `H − h²H₂` (`order = 4`, the default) or `H − h²H₂ − h⁴H₄` (`order = 6`) of
//! `mechanics::modified`: order 4 or 6 at the cost of one order-2 step, free rigid body only.
//!
//! The explicit methods of `integrators::splitting` and `mechanics::exact`:
//! - `splitting`: Strang splitting of h into pieces with exact flows (the free body's
//!   axisymmetric body and one principal-axis rotation — on SE(3) with the translation joined to
//!   the axisymmetric piece —, the SE(2) body's rotation and translation) and the
//!   potential's kick; order 2, symmetric (so `composition` applies), Casimirs to round-off. Every
//!   system but `geodesic-so-n` has one.
//! - `kinetic-kick`: the exact free-body flow (Jacobi elliptic functions) between kicks of the
//!   potential, with the coefficients `splitting` (order 2, 4, 6): `heavy-top`, `free-rigid-body`
//!   and `rigid-body-se3` (the satellite; free, it is the exact motion). The kinetic flow is exact, so a fast spin costs no accuracy.
//! - `exact`: the exact free rigid body flow, any step, cost independent of the step
//!   (`free-rigid-body` only).
//!
//! `euler-arnold` is the Euler–Poincaré integrator of the quadratic Lagrangian l(ξ) = ½⟨𝕀ξ, ξ⟩,
//! with 𝕀 = (∂²h/∂μ²)⁻¹ taken from the system: only for systems without a potential.
//!
//! `[sweep]` draws N momenta: on the sphere |μ| = |μ₀| or on the kinetic energy level
//! h(μ) = h(μ₀) of the scene's μ₀, every member starting from the scene's g₀ (see `lie-sim sweep`).
//!
//! Keys of `[system]` and `[initial]` by kind (a key another kind uses is an error, not ignored):
//!
//! | kind | `[system]` | `momentum` μ | `attitude` | `position` |
//! |---|---|---|---|---|
//! | `free-rigid-body` | `inertia` (3 moments or 3×3) | Π, 3 | rotation | — |
//! | `heavy-top` | `inertia`, `mass`, `center_of_mass` χ (body), `gravity` g ≥ 0 (along −e₃) | Π, 3 | rotation | — |
//! | `rigid-body-se3` | `inertia`, `mass`, `gravitational_parameter` GM ≥ 0 (0: free) | (Π, P), 6 | rotation | x, 3 |
//! | `planar-body-se2` | `inertia` J (one number), `mass`, `stiffness` k, `attachment` c, `gravity` γ (2) | (L, Pₓ, P_y), 3 | `{ angle = φ }` | x, 2 |
//! | `geodesic-so-n` | `n`, `inertia` (n diagonal entries of J) | n(n−1)/2 | `{ matrix = … }` n×n | — |
//! | `gyrostat`, `underwater-vehicle`, `quadrotor`, `coupled-bodies` | see [`crate::vehicles`] | | | |
//!
//! `pendulum-3d` is read as `heavy-top`: the 3D pendulum (a rigid body on a fixed pivot, J about
//! the pivot, ρ = `center_of_mass`) is the heavy top (`mechanics::systems::Pendulum3d`).
//!
//! A rotation is `{ rotation_vector = [x, y, z] }` (R = exp(ω̂)), `{ quaternion = [w, x, y, z] }`
//! (scalar first, unit norm to 10⁻⁶, then normalised) or `{ matrix = [[…], […], […]] }` (checked by
//! `lie_groups::So3::from_matrix`); the default is the identity. Momenta are body momenta in the
//! basis of lie-groups' `vee`, rotation first for SE(2) and SE(3). Systems with a potential
//! (heavy top, satellite, planar spring or gravity) need `reconstruct = true`.
//!
//! Parsing is in two stages: serde reads the text into `Raw*` structs (types, unknown keys), then
//! [`Scene::from_raw`] checks values (positivity, orthogonality, lengths) and builds the typed
//! [`Scene`]. Each stage reports one error naming the field.

use crate::error::SimError;
use crate::forces::{check_forces, ForceSlots, FORCED_KINDS};
pub use crate::forces::{Forces, RawForces};
pub use crate::vehicles::{
    CoupledBodies, Gyrostat, Quadrotor, RawBody, RawBodyState, RawSpring, UnderwaterVehicle,
};
use integrators::processing::ProcessingScheme;
use integrators::splitting::SplittingScheme;
use integrators::CompositionScheme;
use lie_groups::{LieGroup, So3};
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector2, Vector3, Vector6};
use serde::Deserialize;
use std::fmt;
use std::path::Path;

/// The scene run by `lie-sim` with no arguments: a rigid body tumbling near its unstable
/// intermediate axis.
pub const DEFAULT_SCENE: &str = include_str!("../../../examples/scenes/default.toml");

/// Label used in error messages for the embedded default scene.
pub const DEFAULT_SCENE_LABEL: &str = "<default scene>";

/// Largest number of steps a scene may ask for (T/h), so that a typo cannot start a run of years.
pub const MAX_STEPS: f64 = 1e11;

// ---------------------------------------------------------------------------------------------
// Names
// ---------------------------------------------------------------------------------------------

/// Which mechanical system the scene simulates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SystemKind {
    /// Free rigid body on SO(3): Π' = Π × Ω, Ω = I⁻¹Π, R' = R Ω̂.
    FreeRigidBody,
    /// Heavy top: rigid body on SO(3) in uniform gravity with a body-fixed centre of mass. Also
    /// read as `pendulum-3d`: the 3D pendulum is the heavy top (`mechanics::systems::Pendulum3d`).
    #[serde(alias = "pendulum-3d")]
    HeavyTop,
    /// Rigid body on SE(3): free, or a satellite in a central gravity field.
    RigidBodySe3,
    /// Planar rigid body on SE(2).
    PlanarBodySe2,
    /// Euler–Arnold geodesic on SO(n) (the generalised rigid body).
    GeodesicSoN,
    /// A spacecraft with reaction wheels on SO(3) × ℝᴷ.
    Gyrostat,
    /// An underwater vehicle on SE(3): full mass matrix with added mass, restoring force.
    UnderwaterVehicle,
    /// A quadrotor on SE(3): gravity, body-axis thrust, body torques.
    Quadrotor,
    /// N rigid bodies on SE(3)ᴺ coupled by springs.
    CoupledBodies,
}

impl SystemKind {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Self::FreeRigidBody => "free-rigid-body",
            Self::HeavyTop => "heavy-top",
            Self::RigidBodySe3 => "rigid-body-se3",
            Self::PlanarBodySe2 => "planar-body-se2",
            Self::GeodesicSoN => "geodesic-so-n",
            Self::Gyrostat => "gyrostat",
            Self::UnderwaterVehicle => "underwater-vehicle",
            Self::Quadrotor => "quadrotor",
            Self::CoupledBodies => "coupled-bodies",
        }
    }
}

impl fmt::Display for SystemKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Which integrator advances the scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Cotangent-lift Lie–Poisson integrator (eq. 19 of the paper; §4 at θ = 0).
    LiePoisson,
    /// Tangent-lift Euler–Poincaré integrator (eq. 18).
    EulerPoincare,
    /// Euler–Arnold integrator (quadratic Lagrangian from an inertia operator).
    EulerArnold,
    /// Explicit RK4 baseline (quaternion + momentum, renormalised).
    Rk4,
    /// Runge–Kutta–Munthe-Kaas of order 4 on the group.
    Rkmk4,
    /// Explicit Strang splitting of h into pieces with exact flows (one-parameter subgroups) and
    /// the potential's kick (`integrators::splitting::Splitting`): order 2, symmetric, Poisson.
    Splitting,
    /// The exact free-body flow with potential kicks (`integrators::splitting::KineticKick` with
    /// `mechanics::exact::FreeBodyFlow`), coefficients from `splitting`: order 2, 4 or 6.
    KineticKick,
    /// The exact free rigid body flow (`mechanics::exact::ExactFreeBody`): Jacobi elliptic
    /// functions, any step, cost independent of h.
    Exact,
}

impl Method {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Self::LiePoisson => "lie-poisson",
            Self::EulerPoincare => "euler-poincare",
            Self::EulerArnold => "euler-arnold",
            Self::Rk4 => "rk4",
            Self::Rkmk4 => "rkmk4",
            Self::Splitting => "splitting",
            Self::KineticKick => "kinetic-kick",
            Self::Exact => "exact",
        }
    }

    /// Whether the method is one of the paper's discretization-map integrators, which take τ and θ.
    pub fn is_lie_method(self) -> bool {
        matches!(
            self,
            Self::LiePoisson | Self::EulerPoincare | Self::EulerArnold
        )
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The iteration that solves the implicit step equations (`integrators::SolverKind`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SolverChoice {
    /// Simplified Newton: one analytic Jacobian per step (the default).
    SimplifiedNewton,
    /// Newton with the analytic Jacobian at every iterate.
    Newton,
    /// Newton with a finite-difference Jacobian.
    NewtonFd,
    /// Fixed-point iteration.
    FixedPoint,
}

/// The τ map of the retraction g τ(ξ).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TauKind {
    /// τ = exp (`lie_groups::ExpMap`).
    Exp,
    /// τ = cay (`lie_groups::Cayley`).
    Cayley,
}

impl TauKind {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Self::Exp => "exp",
            Self::Cayley => "cayley",
        }
    }
}

impl fmt::Display for TauKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A fully specified method: the integrator, its τ map and θ where they apply, and optionally a
/// composition scheme Ψ_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ₁ h} wrapped around it (symmetric base only).
#[derive(Debug, Clone, PartialEq)]
pub struct MethodSpec {
    /// The integrator (the base method Φ when `composition` is set).
    pub method: Method,
    /// τ (Lie methods and rkmk4; `None` for rk4).
    pub tau: Option<TauKind>,
    /// θ ∈ [0, 1] (Lie methods only).
    pub theta: Option<f64>,
    /// The composition scheme raising the symmetric (θ = ½) base method to order 4, 6, 8, ….
    pub composition: Option<CompositionScheme>,
    /// The coefficients of `kinetic-kick` (Strang, Blanes–Moan 4 or 6).
    pub splitting: Option<SplittingScheme>,
    /// The processed method P ∘ Kⁿ ∘ P⁻¹ of the symmetric base method (effective order 6).
    pub processing: Option<ProcessingScheme>,
    /// Lie–Poisson (θ = ½ or 0) on the modified Hamiltonian, of this order (4: H − h²H₂; 6:
    /// H − h²H₂ − h⁴H₄; free rigid body).
    pub modified: Option<u32>,
}

impl MethodSpec {
    /// The method's name for tables: its scene name, `modified-lie-poisson` for the modified
    /// Hamiltonian, `processed-<base>` for a processed method.
    pub fn method_label(&self) -> String {
        if self.modified.is_some() {
            format!("modified-{}", self.method.name())
        } else if self.processing.is_some() {
            format!("processed-{}", self.method.name())
        } else {
            self.method.name().into()
        }
    }
    /// τ as a string for tables (`-` where it does not apply).
    pub fn tau_label(&self) -> String {
        self.tau.map_or_else(|| "-".into(), |t| t.name().into())
    }
    /// θ as a string for tables (`-` where it does not apply).
    pub fn theta_label(&self) -> String {
        self.theta.map_or_else(|| "-".into(), |t| format!("{t}"))
    }
    /// The composition or processing scheme's name for tables, the modified Hamiltonian's order
    /// (`order-4`, `order-6`), or the kinetic–kick coefficients' (`-` without any).
    pub fn composition_label(&self) -> String {
        if let Some(p) = &self.processing {
            return p.name().into();
        }
        if let Some(order) = self.modified {
            return format!("order-{order}");
        }
        match (&self.composition, &self.splitting) {
            (Some(c), _) => c.name().into(),
            (None, Some(s)) => s.name().into(),
            (None, None) => "-".into(),
        }
    }
    /// Base-method steps per step: the composition's or the processing kernel's stages, 1
    /// otherwise (a processed method also pays its processor's stages at each read).
    pub fn stages(&self) -> usize {
        match (&self.composition, &self.processing) {
            (Some(c), _) => c.stages(),
            (None, Some(p)) => p.kernel_stages(),
            (None, None) => 1,
        }
    }
    /// A method without τ, θ or composition (rk4), or with the given τ (rkmk4).
    pub fn plain(method: Method, tau: Option<TauKind>) -> Self {
        Self {
            method,
            tau,
            theta: None,
            composition: None,
            splitting: None,
            processing: None,
            modified: None,
        }
    }
}

impl fmt::Display for MethodSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(c) = &self.composition {
            write!(f, "{} ∘ ", c.name())?;
        }
        if let Some(p) = &self.processing {
            write!(f, "processed {} ∘ ", p.name())?;
        }
        if let Some(order) = self.modified {
            write!(f, "modified (order {order}) ")?;
        }
        write!(f, "{}", self.method)?;
        if let Some(s) = &self.splitting {
            write!(f, " ({})", s.name())?;
        }
        match (self.tau, self.theta) {
            (Some(t), Some(th)) => write!(f, " (τ = {t}, θ = {th})"),
            (Some(t), None) => write!(f, " (τ = {t})"),
            _ => Ok(()),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Raw (serde) form
// ---------------------------------------------------------------------------------------------

/// A scene as written, before its values are checked.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScene {
    /// Optional display name.
    pub name: Option<String>,
    /// `[system]`.
    pub system: RawSystem,
    /// `[initial]`.
    pub initial: RawInitial,
    /// `[integrator]`.
    pub integrator: RawIntegrator,
    /// `[output]` (optional).
    #[serde(default)]
    pub output: RawOutput,
    /// `[sweep]` (optional): the ensemble run by `lie-sim sweep`.
    pub sweep: Option<RawSweep>,
    /// `[forces]` (optional): external torques, forces, thrust, wheel torques, damping and drag
    /// (`crate::forces`).
    pub forces: Option<RawForces>,
    /// `[[events]]` (optional): zero crossings of a trajectory column to locate.
    #[serde(default)]
    pub events: Vec<RawEvent>,
}

/// One `[[events]]` entry: the times where a column of the trajectory crosses a value.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawEvent {
    /// A column of the trajectory CSV: `mu1`…, `g11`…, `energy`, `casimir`.
    pub quantity: String,
    /// The value it crosses (default 0).
    pub value: Option<f64>,
    /// `rising`, `falling` or `either` (default).
    pub direction: Option<String>,
    /// End the run at the first crossing (default false).
    pub stop: Option<bool>,
}

/// `[system]`: the kind and its physical parameters; which parameters apply depends on the kind.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSystem {
    /// The system.
    pub kind: SystemKind,
    /// Inertia: principal moments, a matrix, or (SE(2)) one moment.
    pub inertia: Option<RawInertia>,
    /// Mass m > 0 (heavy top, SE(3), SE(2)).
    pub mass: Option<f64>,
    /// Centre of mass χ in the body frame (heavy top).
    #[serde(alias = "centre_of_mass")]
    pub center_of_mass: Option<[f64; 3]>,
    /// Gravity: the heavy top's g ≥ 0 along −e₃ in space (a number, or `[0, 0, -g]`); the planar
    /// body's acceleration γ ∈ ℝ² (space frame).
    pub gravity: Option<RawNumbers>,
    /// Spring stiffness k ≥ 0 from the origin to a body point (planar body).
    pub stiffness: Option<f64>,
    /// The body point c (body frame) the spring is attached to (planar body).
    pub attachment: Option<[f64; 2]>,
    /// Gravitational parameter GM of a central body at the origin (SE(3) satellite; 0 = free).
    pub gravitational_parameter: Option<f64>,
    /// n of SO(n) (geodesic-so-n).
    pub n: Option<usize>,
    /// The wheels' unit axes aᵢ, body frame, one `[x, y, z]` per wheel (gyrostat).
    pub wheel_axes: Option<Vec<[f64; 3]>>,
    /// The wheels' axial inertias Jᵢ > 0 (gyrostat).
    pub wheel_inertia: Option<Vec<f64>>,
    /// The added-mass matrix M_A, (ω, v) ordering: 6 diagonal entries or a symmetric 6×6
    /// (underwater-vehicle).
    pub added_mass: Option<RawInertia>,
    /// The buoyancy B ≥ 0, a force (underwater-vehicle).
    pub buoyancy: Option<f64>,
    /// The centre of buoyancy r_B, body frame (underwater-vehicle).
    #[serde(alias = "centre_of_buoyancy")]
    pub center_of_buoyancy: Option<[f64; 3]>,
    /// The bodies, `{ mass, inertia }` each (coupled-bodies).
    pub bodies: Option<Vec<RawBody>>,
    /// The springs, `{ between = [i, j], attachments, stiffness, rest_length }` each
    /// (coupled-bodies).
    pub springs: Option<Vec<RawSpring>>,
}

/// One number or a list of numbers.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum RawNumbers {
    /// One number.
    Scalar(f64),
    /// A list.
    List(Vec<f64>),
}

/// An inertia given as one number, a list of principal moments, or a matrix.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum RawInertia {
    /// One moment (SE(2)).
    Scalar(f64),
    /// Principal moments (a diagonal inertia).
    Diagonal(Vec<f64>),
    /// A full symmetric matrix, row by row.
    Matrix(Vec<Vec<f64>>),
}

/// `[initial]`: the initial state.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawInitial {
    /// Body momentum μ ∈ 𝔤* in the basis of the group's `vee` (every kind but coupled-bodies).
    pub momentum: Option<Vec<f64>>,
    /// Attitude (default: the identity).
    pub attitude: Option<RawAttitude>,
    /// Position of the body frame's origin in space (SE(3): 3 numbers, SE(2): 2).
    pub position: Option<Vec<f64>>,
    /// The wheels' angles φᵢ (gyrostat; default 0).
    pub wheel_angles: Option<Vec<f64>>,
    /// Each body's `{ momentum, position, attitude }` (coupled-bodies).
    pub bodies: Option<Vec<RawBodyState>>,
}

/// An attitude, in one of several forms.
#[derive(Debug, Clone, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum RawAttitude {
    /// A rotation matrix, row by row (n×n for SO(n)); must be orthogonal with det +1.
    Matrix(Vec<Vec<f64>>),
    /// A rotation vector ω: R = exp(ω̂), rotation by |ω| radians about ω/|ω|.
    RotationVector([f64; 3]),
    /// A unit quaternion, scalar first: [w, x, y, z].
    Quaternion([f64; 4]),
    /// A planar angle in radians (SE(2)).
    Angle(f64),
}

/// `[integrator]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawIntegrator {
    /// The method.
    pub method: Method,
    /// τ map (Lie methods, rkmk4).
    pub tau: Option<TauKind>,
    /// θ ∈ [0, 1] (Lie methods).
    pub theta: Option<f64>,
    /// Step h > 0.
    pub step: f64,
    /// Duration T > 0.
    pub duration: f64,
    /// Integrate the group element too (default true).
    pub reconstruct: Option<bool>,
    /// The iteration of the implicit solver (default: the integrators crate's).
    pub solver: Option<SolverChoice>,
    /// Tolerance of the implicit solver (default: the integrators crate's).
    pub tolerance: Option<f64>,
    /// Iteration limit of the implicit solver (default: the integrators crate's).
    pub max_iterations: Option<usize>,
    /// Composition scheme around a symmetric base method (any name
    /// `integrators::CompositionScheme` parses, e.g. `kahan-li-6`).
    pub composition: Option<String>,
    /// Coefficients of `kinetic-kick`: `strang`, `blanes-moan-4` or `blanes-moan-6`.
    pub splitting: Option<String>,
    /// Processing scheme around a symmetric base method (a name
    /// `integrators::processing::ProcessingScheme` parses, e.g. `blanes-casas-murua-6-11`).
    pub processing: Option<String>,
    /// `lie-poisson` with θ = 0.5 or 0 on the modified Hamiltonian (free rigid body).
    pub modified: Option<bool>,
    /// The order of the modified Hamiltonian: 4 (default) or 6.
    pub order: Option<u32>,
}

/// `[sweep]`: many initial momenta drawn around the scene's μ₀, for `lie-sim sweep`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSweep {
    /// Number of trajectories N ≥ 1.
    pub count: usize,
    /// Seed of the initial momenta (default 0); member i depends only on (seed, i).
    pub seed: Option<u64>,
    /// Where the momenta lie.
    pub kind: SweepKind,
    /// Monitor energy and Casimir every this many steps (default 1; the last step always).
    pub monitor_every: Option<usize>,
}

/// Where the initial momenta of a sweep are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SweepKind {
    /// Uniform directions on the sphere |μ| = |μ₀| (`integrators::ensemble::momenta_on_sphere`).
    MomentaOnSphere,
    /// Uniform directions scaled onto the kinetic energy level h(μ) = h(μ₀)
    /// (`integrators::ensemble::momenta_on_energy_level`).
    MomentaOnEnergyLevel,
}

impl SweepKind {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Self::MomentaOnSphere => "momenta-on-sphere",
            Self::MomentaOnEnergyLevel => "momenta-on-energy-level",
        }
    }
}

/// A checked `[sweep]` table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SweepSpec {
    /// N ≥ 1.
    pub count: usize,
    /// The seed.
    pub seed: u64,
    /// Where the momenta lie.
    pub kind: SweepKind,
    /// Monitoring stride ≥ 1.
    pub monitor_every: usize,
}

/// `[output]`.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawOutput {
    /// Write every `stride`-th step (default 1).
    pub stride: Option<u64>,
    /// Write rows at these times only (interpolated between steps), instead of every stride.
    pub times: Option<Vec<f64>>,
}

// ---------------------------------------------------------------------------------------------
// Checked form
// ---------------------------------------------------------------------------------------------

/// Free rigid body on SO(3).
#[derive(Debug, Clone, PartialEq)]
pub struct RigidBody {
    /// Inertia tensor I (symmetric positive definite).
    pub inertia: Matrix3<f64>,
    /// Initial body momentum Π₀.
    pub momentum: Vector3<f64>,
    /// Initial attitude R₀ ∈ SO(3).
    pub attitude: Matrix3<f64>,
    /// External torque and damping (`[forces]`).
    pub forces: Option<Forces>,
}

/// Heavy top on SO(3).
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

/// Rigid body on SE(3), free or in a central gravity field.
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

/// Planar rigid body on SE(2).
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarBody {
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

/// Euler–Arnold geodesic on SO(n).
#[derive(Debug, Clone, PartialEq)]
pub struct GeodesicSoN {
    /// n.
    pub n: usize,
    /// The diagonal mass matrix J = diag(j₁, …, jₙ), all positive.
    pub inertia: Vec<f64>,
    /// Initial body momentum μ₀ ∈ 𝔰𝔬(n)*, n(n−1)/2 components in `lie_groups`' SO(n) basis.
    pub momentum: Vec<f64>,
    /// Initial attitude, n×n row-major.
    pub attitude: Vec<f64>,
}

/// A checked system with its initial state.
#[derive(Debug, Clone, PartialEq)]
pub enum System {
    /// See [`RigidBody`].
    FreeRigidBody(RigidBody),
    /// See [`HeavyTop`].
    HeavyTop(HeavyTop),
    /// See [`RigidBodySe3`].
    RigidBodySe3(RigidBodySe3),
    /// See [`PlanarBody`].
    PlanarBodySe2(PlanarBody),
    /// See [`GeodesicSoN`].
    GeodesicSoN(GeodesicSoN),
    /// See [`Gyrostat`].
    Gyrostat(Gyrostat),
    /// See [`UnderwaterVehicle`] (boxed: its 6×6 added mass makes it the largest by far).
    UnderwaterVehicle(Box<UnderwaterVehicle>),
    /// See [`Quadrotor`].
    Quadrotor(Quadrotor),
    /// See [`CoupledBodies`].
    CoupledBodies(CoupledBodies),
}

impl System {
    /// Whether the system has a potential V(g), so that g must be integrated.
    pub fn has_potential(&self) -> bool {
        match self {
            // The integrators crate treats the heavy top as having a potential even at g = 0.
            Self::HeavyTop(_) => true,
            Self::RigidBodySe3(p) => p.gravitational_parameter > 0.0,
            Self::PlanarBodySe2(p) => p.stiffness != 0.0 || p.gravity != Vector2::zeros(),
            Self::UnderwaterVehicle(p) => p.weight() != 0.0 || p.buoyancy != 0.0,
            Self::Quadrotor(p) => p.gravity != 0.0,
            Self::CoupledBodies(p) => !p.springs.is_empty(),
            Self::FreeRigidBody(_) | Self::GeodesicSoN(_) | Self::Gyrostat(_) => false,
        }
    }

    /// The external forces of the scene, if any.
    pub fn forces(&self) -> Option<&Forces> {
        match self {
            Self::FreeRigidBody(p) => p.forces.as_ref(),
            Self::HeavyTop(p) => p.forces.as_ref(),
            Self::Gyrostat(p) => p.forces.as_ref(),
            Self::UnderwaterVehicle(p) => p.forces.as_ref(),
            Self::Quadrotor(p) => p.forces.as_ref(),
            _ => None,
        }
    }

    /// Attaches checked forces to the kinds of [`ForceSlots::of`]; `false` for the others.
    fn set_forces(&mut self, forces: Forces) -> bool {
        match self {
            Self::FreeRigidBody(p) => p.forces = Some(forces),
            Self::HeavyTop(p) => p.forces = Some(forces),
            Self::Gyrostat(p) => p.forces = Some(forces),
            Self::UnderwaterVehicle(p) => p.forces = Some(forces),
            Self::Quadrotor(p) => p.forces = Some(forces),
            _ => return false,
        }
        true
    }

    /// The kind of system.
    pub fn kind(&self) -> SystemKind {
        match self {
            Self::FreeRigidBody(_) => SystemKind::FreeRigidBody,
            Self::HeavyTop(_) => SystemKind::HeavyTop,
            Self::RigidBodySe3(_) => SystemKind::RigidBodySe3,
            Self::PlanarBodySe2(_) => SystemKind::PlanarBodySe2,
            Self::GeodesicSoN(_) => SystemKind::GeodesicSoN,
            Self::Gyrostat(_) => SystemKind::Gyrostat,
            Self::UnderwaterVehicle(_) => SystemKind::UnderwaterVehicle,
            Self::Quadrotor(_) => SystemKind::Quadrotor,
            Self::CoupledBodies(_) => SystemKind::CoupledBodies,
        }
    }
}

/// Options of the implicit solver, passed to the integrators crate where it takes them.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SolverOptions {
    /// The iteration.
    pub kind: Option<SolverChoice>,
    /// Residual tolerance.
    pub tolerance: Option<f64>,
    /// Iteration limit.
    pub max_iterations: Option<usize>,
}

/// A checked scene, ready to run.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// Display name (the `name` key, else the file stem).
    pub name: String,
    /// Where the scene came from (a path or [`DEFAULT_SCENE_LABEL`]).
    pub source: String,
    /// The system and its initial state.
    pub system: System,
    /// The method.
    pub method: MethodSpec,
    /// Solver options.
    pub solver: SolverOptions,
    /// Whether the group element is integrated.
    pub reconstruct: bool,
    /// Step h.
    pub step: f64,
    /// Duration T.
    pub duration: f64,
    /// Output stride.
    pub stride: u64,
    /// Output times (`[output] times`): rows at exactly these times, interpolated between steps
    /// (`integrators::dense_output`), instead of every `stride` steps.
    pub output_times: Option<Vec<f64>>,
    /// Events (`[[events]]`) to locate.
    pub events: Vec<EventSpec>,
    /// The `[sweep]` table, if the scene has one.
    pub sweep: Option<SweepSpec>,
}

/// A checked `[[events]]` entry: where the trajectory column `quantity` crosses `value`.
#[derive(Debug, Clone, PartialEq)]
pub struct EventSpec {
    /// The trajectory column (`mu1`, `g23`, `energy`, …).
    pub quantity: String,
    /// The value crossed.
    pub value: f64,
    /// Which crossings count.
    pub direction: integrators::events::Direction,
    /// Whether the run ends at the first crossing.
    pub stop: bool,
}

/// Command-line overrides applied to the raw scene before it is checked.
#[derive(Debug, Clone, Copy, Default)]
pub struct Overrides {
    /// Replaces `integrator.duration`.
    pub duration: Option<f64>,
    /// Replaces `integrator.step`.
    pub step: Option<f64>,
    /// Replaces `output.stride`.
    pub stride: Option<u64>,
}

impl Scene {
    /// Reads and checks a scene file.
    pub fn load(path: &Path, overrides: Overrides) -> Result<Self, SimError> {
        let text = std::fs::read_to_string(path).map_err(|source| SimError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        let label = path.display().to_string();
        let stem = path
            .file_stem()
            .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
        Self::parse(&text, &label, &stem, overrides)
    }

    /// The embedded default scene.
    pub fn default_scene(overrides: Overrides) -> Result<Self, SimError> {
        Self::parse(DEFAULT_SCENE, DEFAULT_SCENE_LABEL, "default", overrides)
    }

    /// Parses and checks scene text; `label` names the source in errors, `stem` is the fallback
    /// name.
    pub fn parse(
        text: &str,
        label: &str,
        stem: &str,
        overrides: Overrides,
    ) -> Result<Self, SimError> {
        // Syntax first, so that malformed TOML is reported as such and not as a field error.
        if let Err(e) = text.parse::<toml::Table>() {
            let line = e.span().map_or(1, |s| line_of(text, s.start));
            return Err(SimError::MalformedToml {
                path: label.into(),
                line,
                message: one_line(e.message()),
            });
        }
        let mut raw: RawScene = toml::from_str(text).map_err(|e| {
            let (line, field) = e
                .span()
                .map_or((1, String::new()), |s| locate_field(text, s.start));
            let message = one_line(e.message());
            SimError::Field {
                path: label.into(),
                line,
                field: if field.is_empty() {
                    "scene".into()
                } else {
                    field
                },
                message,
            }
        })?;
        if let Some(d) = overrides.duration {
            raw.integrator.duration = d;
        }
        if let Some(h) = overrides.step {
            raw.integrator.step = h;
        }
        if let Some(s) = overrides.stride {
            raw.output.stride = Some(s);
        }
        Self::from_raw(raw, label, stem)
    }

    /// Checks the values of a raw scene.
    pub fn from_raw(raw: RawScene, label: &str, stem: &str) -> Result<Self, SimError> {
        let bad = |field: &str, message: String| SimError::Invalid {
            path: label.into(),
            field: field.into(),
            message,
        };
        let name = raw.name.clone().unwrap_or_else(|| stem.to_string());
        let mut system = check_system(&raw.system, &raw.initial).map_err(|(f, m)| bad(&f, m))?;
        if let Some(f) = &raw.forces {
            let Some(slots) = ForceSlots::of(&system) else {
                return Err(bad(
                    "forces",
                    format!(
                        "[forces] applies to {FORCED_KINDS} scenes, not {}",
                        system.kind()
                    ),
                ));
            };
            let forces =
                check_forces(f, slots, system.kind().name()).map_err(|(f, m)| bad(&f, m))?;
            if !system.set_forces(forces) {
                return Err(bad(
                    "forces",
                    format!("{} takes no [forces]", system.kind()),
                ));
            }
        }

        let it = &raw.integrator;
        let step = positive("integrator.step", it.step).map_err(|(f, m)| bad(&f, m))?;
        let duration = positive("integrator.duration", it.duration).map_err(|(f, m)| bad(&f, m))?;
        if step > duration {
            return Err(bad(
                "integrator.step",
                format!(
                    "h = {step} exceeds the duration T = {duration}: give a step no longer than \
                     the run (one step to T is step = duration)"
                ),
            ));
        }
        if duration / step > MAX_STEPS {
            return Err(bad(
                "integrator.duration",
                format!(
                    "duration / step = {:.3e} steps exceeds the limit {MAX_STEPS:.0e}",
                    duration / step
                ),
            ));
        }
        let method = check_method(it).map_err(|(f, m)| bad(&f, m))?;
        if let Some(tol) = it.tolerance {
            positive("integrator.tolerance", tol).map_err(|(f, m)| bad(&f, m))?;
        }
        if it.max_iterations == Some(0) {
            return Err(bad(
                "integrator.max_iterations",
                "must be at least 1, got 0".into(),
            ));
        }
        let reconstruct = it.reconstruct.unwrap_or(true);
        if !reconstruct && system.has_potential() {
            return Err(bad(
                "integrator.reconstruct",
                format!(
                    "must be true for this {}: its potential V(g) depends on the configuration g",
                    system.kind()
                ),
            ));
        }
        let stride = raw.output.stride.unwrap_or(1);
        if stride == 0 {
            return Err(bad("output.stride", "must be at least 1, got 0".into()));
        }
        if let Some(why) = inapplicable(&method, &system) {
            return Err(bad("integrator.method", why));
        }
        let output_times = match &raw.output.times {
            None => None,
            Some(times) => {
                if raw.output.stride.is_some() {
                    return Err(bad(
                        "output.times",
                        "give either output.times or output.stride, not both".into(),
                    ));
                }
                check_output_times(times, duration).map_err(|m| bad("output.times", m))?;
                Some(times.clone())
            }
        };
        let events = raw
            .events
            .iter()
            .enumerate()
            .map(|(i, e)| check_event(e).map_err(|(f, m)| bad(&format!("events[{i}].{f}"), m)))
            .collect::<Result<Vec<_>, _>>()?;
        let sweep = match &raw.sweep {
            None => None,
            Some(sw) => {
                if sw.count == 0 {
                    return Err(bad("sweep.count", "must be at least 1, got 0".into()));
                }
                if sw.monitor_every == Some(0) {
                    return Err(bad(
                        "sweep.monitor_every",
                        "must be at least 1, got 0".into(),
                    ));
                }
                Some(SweepSpec {
                    count: sw.count,
                    seed: sw.seed.unwrap_or(0),
                    kind: sw.kind,
                    monitor_every: sw.monitor_every.unwrap_or(1),
                })
            }
        };
        Ok(Scene {
            name,
            source: label.into(),
            system,
            method,
            solver: SolverOptions {
                kind: it.solver,
                tolerance: it.tolerance,
                max_iterations: it.max_iterations,
            },
            reconstruct,
            step,
            duration,
            stride,
            output_times,
            events,
            sweep,
        })
    }

    /// Number of steps: ⌈T/h⌉, ignoring a remainder below 10⁻⁹ h (so that T = 10, h = 0.1 gives
    /// 100 steps despite rounding in T/h).
    pub fn steps(&self) -> u64 {
        steps_for(self.duration, self.step)
    }
}

/// ⌈T/h⌉ steps, ignoring a remainder below 10⁻⁹ h; at least 1.
pub fn steps_for(duration: f64, step: f64) -> u64 {
    let ratio = duration / step;
    let n = (ratio - 1e-9).ceil().max(1.0);
    n as u64
}

/// A check's failure: the dotted field and the message.
pub(crate) type FieldError = (String, String);

pub(crate) fn positive(field: &str, v: f64) -> Result<f64, FieldError> {
    if !v.is_finite() {
        Err((field.into(), format!("must be a finite number, got {v}")))
    } else if v <= 0.0 {
        Err((field.into(), format!("must be positive, got {v}")))
    } else {
        Ok(v)
    }
}

pub(crate) fn finite_all(field: &str, v: &[f64]) -> Result<(), FieldError> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(x) => Err((field.into(), format!("must be finite, got {x}"))),
        None => Ok(()),
    }
}

fn check_method(it: &RawIntegrator) -> Result<MethodSpec, FieldError> {
    let m = it.method;
    let tau = match (m, it.tau) {
        (Method::Rk4, Some(t)) => {
            return Err((
                "integrator.tau".into(),
                format!("rk4 integrates quaternions and takes no τ map (got \"{t}\")"),
            ))
        }
        (Method::Splitting | Method::KineticKick | Method::Exact, Some(t)) => {
            return Err((
                "integrator.tau".into(),
                format!("{m} composes exact flows and takes no τ map (got \"{t}\")"),
            ))
        }
        (Method::Rk4 | Method::Splitting | Method::KineticKick | Method::Exact, None) => None,
        (Method::Rkmk4, None | Some(TauKind::Exp)) => Some(TauKind::Exp),
        (Method::Rkmk4, Some(t)) => {
            return Err((
                "integrator.tau".into(),
                format!("rkmk4 is built on τ = exp (got \"{t}\")"),
            ))
        }
        (_, None) => {
            return Err((
                "integrator.tau".into(),
                format!("{m} needs a τ map: \"exp\" or \"cayley\""),
            ))
        }
        (_, Some(t)) => Some(t),
    };
    let theta = if m.is_lie_method() {
        let th = it.theta.ok_or_else(|| {
            (
                "integrator.theta".to_string(),
                format!("{m} needs θ ∈ [0, 1] (0, 0.5 or 1 are the usual choices)"),
            )
        })?;
        if !(0.0..=1.0).contains(&th) {
            return Err((
                "integrator.theta".into(),
                format!("must lie in [0, 1], got {th}"),
            ));
        }
        Some(th)
    } else {
        if let Some(th) = it.theta {
            return Err((
                "integrator.theta".into(),
                format!("{m} takes no θ (got {th})"),
            ));
        }
        None
    };
    let composition = match &it.composition {
        None => None,
        Some(name) => {
            let field = "integrator.composition";
            let scheme: CompositionScheme = name.parse().map_err(|_| {
                // The built-in list, and the order-10 recursive schemes (81 and 625 stages)
                // that parse too but are left out of it.
                let known: Vec<String> = CompositionScheme::builtin()
                    .iter()
                    .map(|c| c.name().to_string())
                    .chain(["triple-jump-10".to_string(), "suzuki-10".to_string()])
                    .filter(|n| n.parse::<CompositionScheme>().is_ok())
                    .collect();
                (
                    field.to_string(),
                    format!(
                        "unknown composition scheme \"{name}\" (known: {})",
                        known.join(", ")
                    ),
                )
            })?;
            let symmetric_base = (matches!(
                m,
                Method::LiePoisson | Method::EulerPoincare | Method::EulerArnold
            ) && theta == Some(0.5))
                || m == Method::Splitting;
            if !symmetric_base {
                let base = match theta {
                    Some(th) => format!("{m} with θ = {th}"),
                    None => m.to_string(),
                };
                return Err((
                    field.into(),
                    format!(
                        "{} needs a symmetric base method (lie-poisson, euler-poincare or \
                         euler-arnold with θ = 0.5, or splitting), got {base}",
                        scheme.name()
                    ),
                ));
            }
            Some(scheme)
        }
    };
    let splitting = match (&it.splitting, m) {
        (None, Method::KineticKick) => Some(SplittingScheme::strang()),
        (None, _) => None,
        (Some(name), Method::KineticKick) => {
            Some(SplittingScheme::by_name(name).map_err(|_| {
                let known: Vec<&str> = SplittingScheme::builtin()
                    .iter()
                    .map(|s| s.name())
                    .collect();
                (
                    "integrator.splitting".to_string(),
                    format!(
                        "unknown splitting scheme \"{name}\" (known: {})",
                        known.join(", ")
                    ),
                )
            })?)
        }
        (Some(name), _) => {
            return Err((
                "integrator.splitting".into(),
                format!(
                    "the coefficients \"{name}\" are for method = \"kinetic-kick\"; {m} takes \
                     none (method = \"splitting\" is Strang, composed with `composition`)"
                ),
            ))
        }
    };
    let modified = match (it.modified.unwrap_or(false), it.order) {
        (false, None) => None,
        (false, Some(order)) => {
            return Err((
                "integrator.order".into(),
                format!("order = {order} is the order of the modified Hamiltonian: it needs modified = true"),
            ))
        }
        (true, order) => {
            let order = order.unwrap_or(4);
            if order != 4 && order != 6 {
                return Err((
                    "integrator.order".into(),
                    format!("the modified Hamiltonian is derived to order 4 and 6, got {order}"),
                ));
            }
            let theta_ok = matches!(theta, Some(t) if t == 0.5 || t == 0.0);
            if !(m == Method::LiePoisson && theta_ok && composition.is_none()) {
                return Err((
                    "integrator.modified".into(),
                    format!(
                        "the modified Hamiltonian is derived for lie-poisson with θ = 0.5 or 0 and no \
                         composition (it is order {order} on its own), got {m}{}",
                        theta.map_or_else(String::new, |t| format!(" with θ = {t}"))
                    ),
                ));
            }
            Some(order)
        }
    };
    let processing = match &it.processing {
        None => None,
        Some(name) => {
            let field = "integrator.processing";
            let scheme: ProcessingScheme = name.parse().map_err(|_| {
                let known: Vec<&str> = ProcessingScheme::builtin()
                    .iter()
                    .map(|p| p.name())
                    .collect();
                (
                    field.to_string(),
                    format!(
                        "unknown processing scheme \"{name}\" (known: {})",
                        known.join(", ")
                    ),
                )
            })?;
            if composition.is_some() || modified.is_some() {
                return Err((
                    field.into(),
                    format!(
                        "{} processes a composition of the base method itself: it does not go \
                         with `composition` or `modified`",
                        scheme.name()
                    ),
                ));
            }
            let symmetric_base = (matches!(
                m,
                Method::LiePoisson | Method::EulerPoincare | Method::EulerArnold
            ) && theta == Some(0.5))
                || matches!(m, Method::Splitting | Method::KineticKick);
            if !symmetric_base {
                let base = match theta {
                    Some(th) => format!("{m} with θ = {th}"),
                    None => m.to_string(),
                };
                return Err((
                    field.into(),
                    format!(
                        "{} needs a symmetric base method (lie-poisson, euler-poincare or \
                         euler-arnold with θ = 0.5, splitting or kinetic-kick), got {base}",
                        scheme.name()
                    ),
                ));
            }
            Some(scheme)
        }
    };
    Ok(MethodSpec {
        method: m,
        tau,
        theta,
        composition,
        splitting,
        processing,
        modified,
    })
}

/// Why `spec` does not apply to `system` (`None` when it does): Euler–Arnold with a potential,
/// a splitting of the SO(n) geodesic, the kinetic–kick off the rigid body, the exact flow or the
/// modified Hamiltonian off the free body. The one place these rules live: the scene check and `sim::dispatch` both ask here.
pub fn inapplicable(spec: &MethodSpec, system: &System) -> Option<String> {
    if system.forces().is_some()
        && (spec.modified.is_some() || matches!(spec.method, Method::Exact | Method::EulerArnold))
    {
        return Some(format!(
            "{} does not take external forces ([forces]); use lie-poisson, euler-poincare, \
             splitting, kinetic-kick, rk4 or rkmk4",
            spec.method_label()
        ));
    }
    if spec.modified.is_some() && !matches!(system, System::FreeRigidBody(_)) {
        return Some(
            "the modified Hamiltonian (modified = true) is derived for the free rigid body only"
                .into(),
        );
    }
    match spec.method {
        Method::EulerArnold if system.has_potential() => {
            Some(euler_arnold_needs_kinetic(system.kind()))
        }
        Method::Splitting if matches!(system, System::GeodesicSoN(_)) => Some(
            "splitting needs h = Σ hᵢ with each piece's flow exact and explicit; the SO(n) \
             geodesic h = ½⟨M, J⁻¹M⟩ has no such splitting here (use lie-poisson or rkmk4)"
                .into(),
        ),
        Method::Splitting if matches!(system, System::UnderwaterVehicle(p) if !p.is_decoupled()) => {
            Some(
                "splitting needs h = Σ hᵢ with each piece's flow exact and explicit; this \
                 vehicle's mass matrix couples rotation and translation (M_ωv ≠ 0: the centre \
                 of gravity or the added mass off the body origin), so its pieces' velocities \
                 are not constant along their flows (use lie-poisson or rkmk4)"
                    .into(),
            )
        }
        Method::KineticKick
            if !matches!(
                system,
                System::FreeRigidBody(_)
                    | System::HeavyTop(_)
                    | System::RigidBodySe3(_)
                    | System::Quadrotor(_)
            ) =>
        {
            Some(
                "kinetic-kick needs the exact flow of the kinetic energy, known here for the \
                 rigid body (free-rigid-body, heavy-top, rigid-body-se3, quadrotor) only; use \
                 splitting"
                    .into(),
            )
        }
        Method::Exact if !matches!(system, System::FreeRigidBody(_)) => Some(
            "the exact flow is known in closed form only for the free rigid body; with a \
             potential use kinetic-kick (heavy-top) or splitting"
                .into(),
        ),
        _ => None,
    }
}

/// The refusal of `euler-arnold` on a system with a potential.
pub fn euler_arnold_needs_kinetic(kind: SystemKind) -> String {
    format!(
        "euler-arnold needs a purely kinetic Lagrangian l(ξ) = ½⟨𝕀ξ, ξ⟩, and this {kind} has a \
         potential V(g); use lie-poisson or euler-poincare"
    )
}

/// The optional `[system]` and `[initial]` keys each kind takes; any other one given is an error,
/// so that a misplaced key is not silently ignored.
fn allowed_keys(kind: SystemKind) -> &'static [&'static str] {
    match kind {
        SystemKind::FreeRigidBody => &["system.inertia", "initial.momentum", "initial.attitude"],
        SystemKind::HeavyTop => &[
            "system.inertia",
            "system.mass",
            "system.center_of_mass",
            "system.gravity",
            "initial.momentum",
            "initial.attitude",
        ],
        SystemKind::RigidBodySe3 => &[
            "system.inertia",
            "system.mass",
            "system.gravitational_parameter",
            "initial.momentum",
            "initial.attitude",
            "initial.position",
        ],
        SystemKind::PlanarBodySe2 => &[
            "system.inertia",
            "system.mass",
            "system.stiffness",
            "system.attachment",
            "system.gravity",
            "initial.momentum",
            "initial.attitude",
            "initial.position",
        ],
        SystemKind::GeodesicSoN => &[
            "system.inertia",
            "system.n",
            "initial.momentum",
            "initial.attitude",
        ],
        SystemKind::Gyrostat => &[
            "system.inertia",
            "system.wheel_axes",
            "system.wheel_inertia",
            "initial.momentum",
            "initial.attitude",
            "initial.wheel_angles",
        ],
        SystemKind::UnderwaterVehicle => &[
            "system.inertia",
            "system.mass",
            "system.center_of_mass",
            "system.gravity",
            "system.added_mass",
            "system.buoyancy",
            "system.center_of_buoyancy",
            "initial.momentum",
            "initial.attitude",
            "initial.position",
        ],
        SystemKind::Quadrotor => &[
            "system.inertia",
            "system.mass",
            "system.gravity",
            "initial.momentum",
            "initial.attitude",
            "initial.position",
        ],
        SystemKind::CoupledBodies => &["system.bodies", "system.springs", "initial.bodies"],
    }
}

fn check_keys(kind: SystemKind, s: &RawSystem, init: &RawInitial) -> Result<(), FieldError> {
    let given = [
        ("system.inertia", s.inertia.is_some()),
        ("system.mass", s.mass.is_some()),
        ("system.center_of_mass", s.center_of_mass.is_some()),
        ("system.gravity", s.gravity.is_some()),
        (
            "system.gravitational_parameter",
            s.gravitational_parameter.is_some(),
        ),
        ("system.n", s.n.is_some()),
        ("system.stiffness", s.stiffness.is_some()),
        ("system.attachment", s.attachment.is_some()),
        ("system.wheel_axes", s.wheel_axes.is_some()),
        ("system.wheel_inertia", s.wheel_inertia.is_some()),
        ("system.added_mass", s.added_mass.is_some()),
        ("system.buoyancy", s.buoyancy.is_some()),
        ("system.center_of_buoyancy", s.center_of_buoyancy.is_some()),
        ("system.bodies", s.bodies.is_some()),
        ("system.springs", s.springs.is_some()),
        ("initial.momentum", init.momentum.is_some()),
        ("initial.attitude", init.attitude.is_some()),
        ("initial.position", init.position.is_some()),
        ("initial.wheel_angles", init.wheel_angles.is_some()),
        ("initial.bodies", init.bodies.is_some()),
    ];
    let allowed = allowed_keys(kind);
    match given
        .iter()
        .find(|(key, present)| *present && !allowed.contains(key))
    {
        Some((key, _)) => Err(((*key).into(), format!("is not a parameter of {kind}"))),
        None => Ok(()),
    }
}

pub(crate) fn required<T: Clone>(
    kind: SystemKind,
    field: &str,
    v: &Option<T>,
) -> Result<T, FieldError> {
    v.clone()
        .ok_or_else(|| (field.into(), format!("is required for {kind}")))
}

pub(crate) fn momentum_of_len(kind: SystemKind, mu: &[f64], len: usize) -> Result<(), FieldError> {
    if mu.len() != len {
        return Err((
            "initial.momentum".into(),
            format!("needs {len} components for {kind}, got {}", mu.len()),
        ));
    }
    finite_all("initial.momentum", mu)
}

/// Output times: finite, within [0, T], increasing (strictly), at least one.
fn check_output_times(times: &[f64], duration: f64) -> Result<(), String> {
    if times.is_empty() {
        return Err("needs at least one time".into());
    }
    if let Some((i, t)) = times
        .iter()
        .enumerate()
        .find(|(_, t)| !t.is_finite() || **t < 0.0 || **t > duration)
    {
        return Err(format!("times[{i}] = {t} is outside [0, T = {duration}]"));
    }
    if let Some(i) = (1..times.len()).find(|&i| times[i] <= times[i - 1]) {
        return Err(format!(
            "times must increase strictly: times[{i}] = {} after {}",
            times[i],
            times[i - 1]
        ));
    }
    Ok(())
}

/// An `[[events]]` entry; the quantity's column is checked against the run's header when it
/// starts (it depends on the group and on reconstruction).
fn check_event(e: &RawEvent) -> Result<EventSpec, FieldError> {
    use integrators::events::Direction;
    let value = e.value.unwrap_or(0.0);
    if !value.is_finite() {
        return Err(("value".into(), format!("must be finite, got {value}")));
    }
    let direction = match e.direction.as_deref() {
        None | Some("either") => Direction::Either,
        Some("rising") => Direction::Rising,
        Some("falling") => Direction::Falling,
        Some(other) => {
            return Err((
                "direction".into(),
                format!("unknown direction \"{other}\" (rising | falling | either)"),
            ))
        }
    };
    if e.quantity == "t" {
        return Err((
            "quantity".into(),
            "t is not a quantity of the state; give a column such as mu1, g33 or energy".into(),
        ));
    }
    Ok(EventSpec {
        quantity: e.quantity.clone(),
        value,
        direction,
        stop: e.stop.unwrap_or(false),
    })
}

fn check_system(s: &RawSystem, init: &RawInitial) -> Result<System, FieldError> {
    let kind = s.kind;
    check_keys(kind, s, init)?;
    let mass = || positive("system.mass", required(kind, "system.mass", &s.mass)?);
    let momentum = || required(kind, "initial.momentum", &init.momentum);
    match kind {
        SystemKind::FreeRigidBody => Ok(System::FreeRigidBody(RigidBody {
            inertia: inertia3(kind, &s.inertia)?,
            momentum: vec3("initial.momentum", &momentum()?)?,
            attitude: attitude3(&init.attitude)?,
            forces: None,
        })),
        SystemKind::HeavyTop => {
            let mass = mass()?;
            let chi = required(kind, "system.center_of_mass", &s.center_of_mass)?;
            finite_all("system.center_of_mass", &chi)?;
            let g = gravity_down(kind, &s.gravity)?;
            Ok(System::HeavyTop(HeavyTop {
                inertia: inertia3(kind, &s.inertia)?,
                mass,
                center_of_mass: Vector3::from(chi),
                gravity: g,
                momentum: vec3("initial.momentum", &momentum()?)?,
                attitude: attitude3(&init.attitude)?,
                forces: None,
            }))
        }
        SystemKind::RigidBodySe3 => {
            let mass = mass()?;
            let gm = s.gravitational_parameter.unwrap_or(0.0);
            if !gm.is_finite() || gm < 0.0 {
                return Err((
                    "system.gravitational_parameter".into(),
                    format!("must be finite and non-negative, got {gm}"),
                ));
            }
            let mu = momentum()?;
            momentum_of_len(kind, &mu, 6)?;
            let pos = init.position.clone().unwrap_or_else(|| vec![0.0; 3]);
            let position = vec3("initial.position", &pos)?;
            if gm > 0.0 && position.norm() == 0.0 {
                return Err((
                    "initial.position".into(),
                    "must be away from the centre of attraction when gravitational_parameter > 0"
                        .into(),
                ));
            }
            Ok(System::RigidBodySe3(RigidBodySe3 {
                inertia: inertia3(kind, &s.inertia)?,
                mass,
                gravitational_parameter: gm,
                momentum: Vector6::from_column_slice(&mu),
                attitude: attitude3(&init.attitude)?,
                position,
            }))
        }
        SystemKind::PlanarBodySe2 => {
            let mass = mass()?;
            let inertia = match required(kind, "system.inertia", &s.inertia)? {
                RawInertia::Scalar(j) => positive("system.inertia", j)?,
                _ => {
                    return Err((
                        "system.inertia".into(),
                        "must be one number (the moment about the centre of mass) for \
                         planar-body-se2"
                            .into(),
                    ))
                }
            };
            let stiffness = s.stiffness.unwrap_or(0.0);
            if !stiffness.is_finite() || stiffness < 0.0 {
                return Err((
                    "system.stiffness".into(),
                    format!("must be finite and non-negative, got {stiffness}"),
                ));
            }
            let c = s.attachment.unwrap_or([0.0; 2]);
            finite_all("system.attachment", &c)?;
            let gravity = match &s.gravity {
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
            let angle = match &init.attitude {
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
            let pos = init.position.clone().unwrap_or_else(|| vec![0.0; 2]);
            if pos.len() != 2 {
                return Err((
                    "initial.position".into(),
                    format!("needs 2 components for {kind}, got {}", pos.len()),
                ));
            }
            finite_all("initial.position", &pos)?;
            let mu = momentum()?;
            momentum_of_len(kind, &mu, 3)?;
            Ok(System::PlanarBodySe2(PlanarBody {
                inertia,
                mass,
                stiffness,
                attachment: Vector2::from(c),
                gravity,
                momentum: Vector3::from_column_slice(&mu),
                angle,
                position: Vector2::new(pos[0], pos[1]),
            }))
        }
        SystemKind::GeodesicSoN => {
            let n = required(kind, "system.n", &s.n)?;
            if !crate::sim::SO_N_SIZES.contains(&n) {
                return Err((
                    "system.n".into(),
                    format!(
                        "SO({n}) is not compiled into lie-sim: n must be one of {:?}",
                        crate::sim::SO_N_SIZES
                    ),
                ));
            }
            let inertia = match required(kind, "system.inertia", &s.inertia)? {
                RawInertia::Diagonal(d) if d.len() == n => {
                    for &x in &d {
                        positive("system.inertia", x)?;
                    }
                    d
                }
                _ => {
                    return Err((
                        "system.inertia".into(),
                        format!("must be the {n} diagonal entries of the mass matrix J of SO({n})"),
                    ))
                }
            };
            let mu = momentum()?;
            momentum_of_len(kind, &mu, n * (n - 1) / 2)?;
            let attitude = match &init.attitude {
                None => identity_flat(n),
                Some(RawAttitude::Matrix(m)) => {
                    let flat = square("initial.attitude.matrix", m, n)?;
                    check_special_orthogonal("initial.attitude.matrix", &flat, n)?;
                    flat
                }
                Some(_) => {
                    return Err((
                        "initial.attitude".into(),
                        format!("must be {{ matrix = … }} ({n}×{n}) for geodesic-so-n"),
                    ))
                }
            };
            Ok(System::GeodesicSoN(GeodesicSoN {
                n,
                inertia,
                momentum: mu,
                attitude,
            }))
        }
        SystemKind::Gyrostat => crate::vehicles::check_gyrostat(s, init).map(System::Gyrostat),
        SystemKind::UnderwaterVehicle => crate::vehicles::check_underwater_vehicle(s, init)
            .map(|v| System::UnderwaterVehicle(Box::new(v))),
        SystemKind::Quadrotor => crate::vehicles::check_quadrotor(s, init).map(System::Quadrotor),
        SystemKind::CoupledBodies => {
            crate::vehicles::check_coupled_bodies(s, init).map(System::CoupledBodies)
        }
    }
}

/// `system.gravity` of the systems in uniform gravity along −e₃ (heavy top, quadrotor,
/// underwater vehicle): g ≥ 0, written g or `[0, 0, -g]`.
pub(crate) fn gravity_down(kind: SystemKind, raw: &Option<RawNumbers>) -> Result<f64, FieldError> {
    let field = "system.gravity";
    let g = match required(kind, field, raw)? {
        RawNumbers::Scalar(g) => g,
        RawNumbers::List(v) if v.len() == 3 && v[0] == 0.0 && v[1] == 0.0 => -v[2],
        RawNumbers::List(v) => {
            return Err((
                field.into(),
                format!("the {kind}'s gravity points along −e₃: give g or [0, 0, -g], got {v:?}"),
            ))
        }
    };
    if !g.is_finite() || g < 0.0 {
        return Err((
            field.into(),
            format!("must be a finite g ≥ 0 (gravity −g e₃), got g = {g}"),
        ));
    }
    Ok(g)
}

pub(crate) fn vec3(field: &str, v: &[f64]) -> Result<Vector3<f64>, FieldError> {
    if v.len() != 3 {
        return Err((field.into(), format!("needs 3 components, got {}", v.len())));
    }
    finite_all(field, v)?;
    Ok(Vector3::new(v[0], v[1], v[2]))
}

fn identity_flat(n: usize) -> Vec<f64> {
    (0..n * n)
        .map(|k| if k / n == k % n { 1.0 } else { 0.0 })
        .collect()
}

/// An n×n matrix given row by row, flattened row-major; finite entries.
pub(crate) fn square(field: &str, rows: &[Vec<f64>], n: usize) -> Result<Vec<f64>, FieldError> {
    if rows.len() != n || rows.iter().any(|r| r.len() != n) {
        return Err((
            field.into(),
            format!(
                "must be {n}×{n}, got {} rows of lengths {:?}",
                rows.len(),
                rows.iter().map(Vec::len).collect::<Vec<_>>()
            ),
        ));
    }
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    finite_all(field, &flat)?;
    Ok(flat)
}

/// Symmetric to 10⁻¹² relative, and positive definite (Cholesky succeeds).
pub(crate) fn symmetric_positive_definite(
    field: &str,
    a: &[f64],
    n: usize,
) -> Result<(), FieldError> {
    let scale = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for i in 0..n {
        for j in 0..i {
            if (a[i * n + j] - a[j * n + i]).abs() > 1e-12 * scale {
                return Err((
                    field.into(),
                    format!(
                        "must be symmetric: entry ({},{}) = {} but ({},{}) = {}",
                        i + 1,
                        j + 1,
                        a[i * n + j],
                        j + 1,
                        i + 1,
                        a[j * n + i]
                    ),
                ));
            }
        }
    }
    let m = nalgebra::DMatrix::from_row_slice(n, n, a);
    if m.cholesky().is_none() {
        return Err((
            field.into(),
            "must be positive definite (its Cholesky factorisation fails)".into(),
        ));
    }
    Ok(())
}

/// SO(n) attitudes typed in a scene are accepted when ‖RᵀR − I‖_max ≤ 10⁻⁹, the tolerance of
/// lie-groups' checked constructors (`lie_groups::so3::ORTHOGONALITY_TOLERANCE`): tight enough that
/// the invariants of the run start on the group, loose enough for ten typed digits.
pub const ATTITUDE_TOLERANCE: f64 = lie_groups::so3::ORTHOGONALITY_TOLERANCE;

fn check_special_orthogonal(field: &str, r: &[f64], n: usize) -> Result<(), FieldError> {
    let m = nalgebra::DMatrix::from_row_slice(n, n, r);
    let err = (m.transpose() * &m - nalgebra::DMatrix::identity(n, n)).amax();
    if err > ATTITUDE_TOLERANCE {
        return Err((
            field.into(),
            format!("is not orthogonal: ‖RᵀR − I‖_max = {err:.3e} > {ATTITUDE_TOLERANCE:.0e}"),
        ));
    }
    let det = m.determinant();
    if (det - 1.0).abs() > 1e-6 {
        return Err((
            field.into(),
            format!("is not a rotation: det R = {det:.6}, expected +1"),
        ));
    }
    Ok(())
}

fn inertia3(kind: SystemKind, raw: &Option<RawInertia>) -> Result<Matrix3<f64>, FieldError> {
    let field = "system.inertia";
    inertia3_at(field, &required(kind, field, raw)?)
}

/// A 3×3 inertia at `field`: 3 positive principal moments or a symmetric positive definite
/// matrix.
pub(crate) fn inertia3_at(field: &str, raw: &RawInertia) -> Result<Matrix3<f64>, FieldError> {
    match raw.clone() {
        RawInertia::Scalar(_) => Err((
            field.into(),
            "must be 3 principal moments or a 3×3 matrix".into(),
        )),
        RawInertia::Diagonal(d) => {
            if d.len() != 3 {
                return Err((
                    field.into(),
                    format!("needs 3 principal moments, got {}", d.len()),
                ));
            }
            for &x in &d {
                positive(field, x)?;
            }
            Ok(Matrix3::new(d[0], 0.0, 0.0, 0.0, d[1], 0.0, 0.0, 0.0, d[2]))
        }
        RawInertia::Matrix(m) => {
            let flat = square(field, &m, 3)?;
            symmetric_positive_definite(field, &flat, 3)?;
            Ok(Matrix3::from_row_slice(&flat))
        }
    }
}

/// Quaternions are accepted when | ‖q‖ − 1 | ≤ 10⁻⁶ (six typed digits) and then normalised.
pub const QUATERNION_TOLERANCE: f64 = 1e-6;

pub(crate) fn attitude3(raw: &Option<RawAttitude>) -> Result<Matrix3<f64>, FieldError> {
    attitude3_at("initial.attitude", raw)
}

/// An attitude at the field `prefix` (its forms at `prefix.matrix`, `prefix.quaternion`, …); the
/// identity when absent.
pub(crate) fn attitude3_at(
    prefix: &str,
    raw: &Option<RawAttitude>,
) -> Result<Matrix3<f64>, FieldError> {
    match raw {
        None => Ok(Matrix3::identity()),
        Some(RawAttitude::Matrix(m)) => {
            let field = &format!("{prefix}.matrix");
            let flat = square(field, m, 3)?;
            // lie-groups' checked constructor: ‖RᵀR − I‖_max and det R = +1 within
            // `lie_groups::so3::ORTHOGONALITY_TOLERANCE`.
            let r = Matrix3::from_row_slice(&flat);
            So3::from_matrix(&r)
                .map_err(|e| (field.to_string(), format!("is not a rotation: {e}")))?;
            Ok(r)
        }
        Some(RawAttitude::RotationVector(w)) => {
            finite_all(&format!("{prefix}.rotation_vector"), w)?;
            Ok(Rotation3::new(Vector3::from(*w)).into_inner())
        }
        Some(RawAttitude::Quaternion(q)) => {
            let field = &format!("{prefix}.quaternion");
            finite_all(field, q)?;
            let quat = Quaternion::new(q[0], q[1], q[2], q[3]);
            let norm = quat.norm();
            if (norm - 1.0).abs() > QUATERNION_TOLERANCE {
                return Err((
                    field.into(),
                    format!("must have unit norm (±{QUATERNION_TOLERANCE:.0e}), got ‖q‖ = {norm}"),
                ));
            }
            Ok(UnitQuaternion::from_quaternion(quat)
                .to_rotation_matrix()
                .into_inner())
        }
        Some(RawAttitude::Angle(_)) => Err((
            format!("{prefix}.angle"),
            "a planar angle is only an attitude of planar-body-se2".into(),
        )),
    }
}

// ---------------------------------------------------------------------------------------------
// Locating a serde error in the source, to name the field
// ---------------------------------------------------------------------------------------------

/// The parser's message on one line, with Rust type names replaced by what a scene author knows.
fn one_line(s: &str) -> String {
    s.trim()
        .replace('\n', "; ")
        .replace("expected f64", "expected a number")
        .replace("expected usize", "expected a non-negative integer")
        .replace("expected u64", "expected a non-negative integer")
}

fn line_of(text: &str, offset: usize) -> usize {
    let offset = offset.min(text.len());
    text[..offset].bytes().filter(|&b| b == b'\n').count() + 1
}

/// The 1-based line of `offset` and the dotted field it belongs to: the key of the nearest
/// `key = …` line at or above it, prefixed by the nearest `[table]` header above that. toml
/// reports spans of values and keys, not their paths, so this reads them back from the text.
fn locate_field(text: &str, offset: usize) -> (usize, String) {
    let line = line_of(text, offset);
    let lines: Vec<&str> = text.lines().collect();
    let mut key = None;
    let mut table = None;
    for i in (0..line.min(lines.len())).rev() {
        let l = strip_comment(lines[i]).trim();
        if let Some(h) = l.strip_prefix('[') {
            table = Some(
                h.trim_start_matches('[')
                    .trim_end_matches(']')
                    .trim()
                    .to_string(),
            );
            break;
        }
        if key.is_none() {
            if let Some((k, _)) = l.split_once('=') {
                key = Some(k.trim().trim_matches('"').to_string());
            }
        }
    }
    let field = match (table, key) {
        (Some(t), Some(k)) => format!("{t}.{k}"),
        (Some(t), None) => t,
        (None, Some(k)) => k,
        (None, None) => String::new(),
    };
    (line, field)
}

fn strip_comment(l: &str) -> &str {
    // Scene files put no '#' inside strings, so the first '#' starts a comment.
    l.split_once('#').map_or(l, |(a, _)| a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_scene_parses_and_is_a_free_rigid_body() {
        let s = Scene::default_scene(Overrides::default()).unwrap();
        assert_eq!(s.system.kind(), SystemKind::FreeRigidBody);
        assert!(s.steps() > 0);
    }

    #[test]
    fn steps_ignore_rounding_in_duration_over_step() {
        assert_eq!(steps_for(10.0, 0.1), 100);
        assert_eq!(steps_for(1.0, 0.3), 4);
        assert_eq!(steps_for(0.01, 1.0), 1);
    }

    #[test]
    fn locate_field_names_table_and_key() {
        let text = "[system]\nkind = \"x\"\n\n[integrator]\n# c\nstep = \"a\"\n";
        let off = text.find("\"a\"").unwrap();
        assert_eq!(locate_field(text, off), (6, "integrator.step".into()));
    }

    #[test]
    fn rotation_vector_gives_the_rotation_about_its_axis() {
        let r = attitude3(&Some(RawAttitude::RotationVector([
            0.0,
            0.0,
            core::f64::consts::FRAC_PI_2,
        ])))
        .unwrap();
        // R e₁ = e₂ for a quarter turn about e₃.
        let e2 = r * Vector3::x();
        assert!((e2 - Vector3::y()).amax() < 1e-15);
    }

    #[test]
    fn quaternion_scalar_first_matches_rotation_vector() {
        let a = 0.7f64;
        let q = [(a / 2.0).cos(), (a / 2.0).sin(), 0.0, 0.0];
        let rq = attitude3(&Some(RawAttitude::Quaternion(q))).unwrap();
        let rv = attitude3(&Some(RawAttitude::RotationVector([a, 0.0, 0.0]))).unwrap();
        assert!((rq - rv).amax() < 1e-15);
    }
}
