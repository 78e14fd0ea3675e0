//! Scenes: what to simulate, read from TOML.
//!
//! A scene has these tables (every table and key is checked: an unknown key is an error):
//!
//! ```toml
//! name = "tumbling book"            # optional, shown in the summary
//!
//! [system]
//! kind = "free-rigid-body"          # a system of `crate::systems` (`lie-sim methods` lists them)
//! inertia = [1.0, 2.0, 3.0]         # the kind's own keys (its module's page)
//! # generalized_inertia = true      # every 3×3 inertia must be a rigid body's (each principal
//! #                                   #   moment at most the sum of the other two); this accepts
//! #                                   #   any positive definite one (crate::fields::inertia3)
//!
//! [initial]
//! momentum = [0.01, 1.0, 0.01]      # body momentum μ ∈ 𝔤* (Π for SO(3)), and the kind's state:
//! attitude = { rotation_vector = [0.0, 0.0, 0.0] }   # or { quaternion = [w, x, y, z] }, { matrix = [[..], ..] }
//!
//! [integrator]
//! method = "lie-poisson"            # a method of the registry: `lie-sim methods` lists each with
//!                                   #   the options it takes and the systems it applies to
//! tau = "cayley"                    # τ map, for the methods that take one
//! theta = 0.5                       # θ ∈ [0, 1] of the discretization map, where taken
//! step = 0.01                       # h > 0, for a fixed-step method
//! # tolerance = 1e-8                # or, for a tolerance-driven method (rkmk-dop853, dop853, …):
//! # rtol = 1e-8                     #   rtol = atol = tolerance, or rtol and atol apart (as
//! # atol = 1e-10                    #   scipy and diffsol name them; crate::stepping)
//! # epsilon = 0.05                  # or, for a symmetric method (splitting, compositions,
//!                                   #   kinetic-kick, θ = 0.5): reversible variable steps
//!                                   #   h = ε/ρ, ρ the motion's rate (crate::stepping)
//! duration = 100.0                  # T > 0; ⌈T/h⌉ steps, the last one shortened to land on T
//! reconstruct = true                # integrate g as well as μ (default true)
//! # solver = "simplified-newton"    # implicit solver: simplified-newton (default) | newton |
//! #                                   #   newton-fd | fixed-point
//! # solver_tolerance = 1e-14        # implicit solver options (default: the integrators crate's)
//! # max_iterations = 50
//! # composition = "kahan-li-6"      # compose a symmetric base to order 4, 6, 8, … (below)
//! # processing = "blanes-casas-murua-6-11"  # the processed method P ∘ Kⁿ ∘ P⁻¹ of a symmetric
//!                                   #   base, effective order 6 (below)
//! # splitting = "blanes-moan-4"     # the coefficients of a method that takes them: strang
//!                                   #   (default) | blanes-moan-4 | blanes-moan-6
//! # modified = true                 # the free body's modified Hamiltonian: order 4 or 6 at the
//!                                   #   cost of order 2 (θ = 0.5 or 0)
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
//! [many_bodies]                     # optional: the bodies run by `lie-sim many-bodies`
//! count = 100000                    # N rotors (a rigid body in principal axes, free or in a
//! seed = 1                          #   uniform field), momenta drawn as [sweep] draws them;
//! kind = "momenta-on-sphere"        #   statistics every `stride` steps (crate::many_bodies)
//! # stride = 10
//!
//! [forces]                          # optional: external forces (keys by kind: crate::forces)
//! torque = [0.0, 0.0, 0.1]          # constant body torque, or a piecewise-linear schedule:
//! # torque = { times = [0.0, 5.0], values = [[0.0, 0.0, 0.1], [0.0, 0.0, 0.0]] }
//! damping = 0.05                    # F = −D ξ: a number c (D = c I), n entries, or n×n symmetric
//! # force, thrust, wheel_torque: schedules; quadratic_drag: Fᵢ = −dᵢ|ξᵢ|ξᵢ
//! ```
//!
//! **Systems.** `[system]` and `[initial]` are the kind's own tables: each system's module in
//! [`crate::systems`] reads them as its own serde types (so that a key of another kind is an
//! unknown field, named with its line) and checks them. `[forces]` takes the keys the kind
//! declares ([`crate::forces`]); forces are applied in the discrete Lagrange–d'Alembert way
//! (`integrators::forces`) by the methods that take them (a method built on the free body alone
//! refuses them). A schedule holds its first value before `times[0]` and its last after the end.
//!
//! **Methods.** `method` names a row of the registry ([`crate::methods`]); the row says which of
//! `tau`, `theta`, `splitting`, `modified`, `composition` and `processing` the method takes, and
//! anything else given is an error naming the key. Whether it applies to the scene's system is
//! decided by building it on the system's model (the capabilities it needs: pieces with exact
//! flows, an exact kinetic flow, SO(3), the free body itself, a purely kinetic Lagrangian).
//!
//! `composition` names a scheme of `integrators::CompositionScheme` (`triple-jump-4|6|8|10`,
//! `suzuki-4|6|8|10`, `mclachlan-4`, `kahan-li-6`, `kahan-li-8`, `mclachlan-8`,
//! `sofroniou-spaletta-10`): one step of size h is the steps γ₁h, …, γ_s h of the base method.
//! `processing` names a scheme of `integrators::processing::ProcessingScheme` (`blanes-6`: 7
//! base steps a step; `blanes-casas-murua-6-11`: 11; `blanes-casas-murua-6-13`: 13): the
//! processed method `P ∘ Kⁿ ∘ P⁻¹` of effective order 6, whose kernel K is a composition of the
//! base method and whose processor P (10–12 base steps) runs only when the state is read, never as
//! part of a step. `lie-sim run` reads energy and Casimir after every step, so there a processed
//! method pays P every step; `trade` reads every 8 steps and at T, `sweep` every
//! `monitor_every` steps. Both need a base the integrators crate reports symmetric
//! (`SymmetricMethod`: Lie–Poisson with θ = ½, or θ = 0 and 1 without a potential or force;
//! Euler–Poincaré with θ = ½; the splittings) and do not go together, nor with `modified`.
//!
//! `[sweep]` draws N momenta: on the sphere |μ| = |μ₀| or on the kinetic energy level
//! h(μ) = h(μ₀) of the scene's μ₀, every member starting from the scene's g₀ (see `lie-sim sweep`).
//!
//! A rotation is `{ rotation_vector = [x, y, z] }` (R = exp(ω̂)), `{ quaternion = [w, x, y, z] }`
//! (scalar first, unit norm to 10⁻⁶, then normalised) or `{ matrix = [[…], […], […]] }` (checked by
//! `lie_groups::So3::from_matrix`); the default is the identity. Momenta are body momenta in the
//! basis of lie-groups' `vee`, rotation first for SE(2) and SE(3). Systems with a potential
//! need `reconstruct = true`.
//!
//! Parsing is in three stages: the kind is read first, then serde reads the text into the kind's
//! raw types and the common tables (types, unknown keys), then the values are checked
//! (positivity, orthogonality, lengths) and the method built once on the system to see that it
//! applies. Each stage reports one error naming the field.

use crate::build::{build_with, probe, refusal};
use crate::error::SimError;
use crate::fields::{positive, FieldError};
use crate::forces::{check_forces, RawForces};
use crate::methods::spec::{check as check_method, RawIntegrator, SolverOptions};
use crate::methods::wrap::BuildError;
use crate::methods::MethodSpec;
use crate::stepping::{check as check_stepping, RawStepping, StepChoice, VariableSteps};
use crate::systems::common::SceneSystem;
use crate::systems::{with_kind, KindVisitor, System, SystemKind};
use serde::de::DeserializeOwned;
use serde::Deserialize;
use std::path::Path;

/// The scene run by `lie-sim` with no arguments: a rigid body tumbling near its unstable
/// intermediate axis.
pub const DEFAULT_SCENE: &str = include_str!("../../../examples/scenes/default.toml");

/// Label used in error messages for the embedded default scene.
pub const DEFAULT_SCENE_LABEL: &str = "<default scene>";

/// Largest number of steps a scene may ask for (T/h), so that a typo cannot start a run of years.
pub const MAX_STEPS: f64 = 1e11;

// ---------------------------------------------------------------------------------------------
// Raw (serde) form
// ---------------------------------------------------------------------------------------------

/// A scene as written, with the `[system]` and `[initial]` tables of its kind (`P`, `I`).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScene<P, I> {
    /// Optional display name.
    name: Option<String>,
    /// `[system]`.
    system: P,
    /// `[initial]`.
    initial: I,
    /// `[integrator]`.
    integrator: RawIntegrator,
    /// `[output]` (optional).
    #[serde(default)]
    output: RawOutput,
    /// `[sweep]` (optional): the ensemble run by `lie-sim sweep`.
    sweep: Option<RawSweep>,
    /// `[many_bodies]` (optional): the bodies run by `lie-sim many-bodies`.
    many_bodies: Option<RawManyBodies>,
    /// `[forces]` (optional): external torques, forces, thrust, wheel torques, damping and drag
    /// (`crate::forces`).
    forces: Option<RawForces>,
    /// `[[events]]` (optional): zero crossings of a trajectory column to locate.
    #[serde(default)]
    events: Vec<RawEvent>,
}

/// The tables every kind shares.
#[derive(Debug, Clone)]
struct Common {
    name: Option<String>,
    integrator: RawIntegrator,
    output: RawOutput,
    sweep: Option<RawSweep>,
    many_bodies: Option<RawManyBodies>,
    forces: Option<RawForces>,
    events: Vec<RawEvent>,
}

/// What is read before anything else: the kind, which chooses the types of `[system]` and
/// `[initial]`.
#[derive(Deserialize)]
struct Peek {
    system: PeekSystem,
}

#[derive(Deserialize)]
struct PeekSystem {
    kind: SystemKind,
}

/// One `[[events]]` entry: the times where a column of the trajectory crosses a value.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawEvent {
    /// A column of the trajectory CSV: `mu1`…, `g11`…, `energy`, `casimir`.
    quantity: String,
    /// The value it crosses (default 0).
    value: Option<f64>,
    /// `rising`, `falling` or `either` (default).
    direction: Option<String>,
    /// End the run at the first crossing (default false).
    stop: Option<bool>,
}

/// `[sweep]`: many initial momenta drawn around the scene's μ₀, for `lie-sim sweep`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSweep {
    /// Number of trajectories N ≥ 1.
    count: usize,
    /// Seed of the initial momenta (default 0); member i depends only on (seed, i).
    seed: Option<u64>,
    /// Where the momenta lie.
    kind: SweepKind,
    /// Monitor energy and Casimir every this many steps (default 1; the last step always).
    monitor_every: Option<usize>,
}

/// `[output]`.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawOutput {
    /// Write every `stride`-th step (default 1).
    stride: Option<u64>,
    /// Write rows at these times only (interpolated between steps), instead of every stride.
    times: Option<Vec<f64>>,
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

/// The most rows a `lie-sim many-bodies` run keeps (their accumulators stay until the last body ran).
pub const MAX_MANY_BODY_ROWS: u64 = 10_001;

/// `[many_bodies]` as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawManyBodies {
    /// N ≥ 1.
    count: usize,
    /// The seed (default 0).
    seed: Option<u64>,
    /// Where the momenta are drawn.
    kind: SweepKind,
    /// Steps between rows (default ⌈n/100⌉).
    stride: Option<u64>,
}

/// A checked `[many_bodies]` table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ManyBodiesSpec {
    /// N ≥ 1.
    pub count: usize,
    /// The seed.
    pub seed: u64,
    /// Where the momenta are drawn.
    pub kind: SweepKind,
    /// Steps between rows, ≥ 1.
    pub stride: u64,
}

/// Checks `raw` for a run of n steps: the field at fault and what is wrong with it.
pub fn check_many_bodies(
    raw: &RawManyBodies,
    n: u64,
) -> Result<ManyBodiesSpec, (&'static str, String)> {
    if raw.count == 0 {
        return Err(("many_bodies.count", "must be at least 1, got 0".into()));
    }
    let stride = match raw.stride {
        Some(0) => return Err(("many_bodies.stride", "must be at least 1, got 0".into())),
        Some(s) => s,
        None => n.div_ceil(100).max(1),
    };
    let rows = n.div_ceil(stride) + 1;
    if rows > MAX_MANY_BODY_ROWS {
        return Err((
            "many_bodies.stride",
            format!(
                "{stride} gives {rows} rows over the {n} steps, more than the {MAX_MANY_BODY_ROWS} a run \
                 keeps: give a stride of at least {}",
                n.div_ceil(MAX_MANY_BODY_ROWS - 1)
            ),
        ));
    }
    Ok(ManyBodiesSpec {
        count: raw.count,
        seed: raw.seed.unwrap_or(0),
        kind: raw.kind,
        stride,
    })
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

// ---------------------------------------------------------------------------------------------
// Checked form
// ---------------------------------------------------------------------------------------------

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
    /// Step h; for a run with variable steps, the duration T (its controller chooses its steps,
    /// none longer than the run).
    pub step: f64,
    /// How a run with variable steps chooses them: to a tolerance, or reversibly with ε
    /// (`crate::stepping`); `None` for fixed steps.
    pub variable: Option<VariableSteps>,
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
    /// The `[many_bodies]` table, if the scene has one.
    pub many_bodies: Option<ManyBodiesSpec>,
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
    /// The flag that gave `duration` (`--duration`, `--horizon`), named in messages about it in
    /// place of `integrator.duration`.
    pub duration_flag: Option<&'static str>,
    /// Replaces `integrator.step`.
    pub step: Option<f64>,
    /// Replaces `output.stride`.
    pub stride: Option<u64>,
}

/// The serde stage for the kind's module `T`: the scene's tables read, the kind's checked.
struct ReadAs<'a> {
    text: &'a str,
    label: &'a str,
}

impl KindVisitor for ReadAs<'_> {
    type Out = Result<(Result<System, FieldError>, Common), SimError>;
    fn visit<T: SceneSystem + Into<System>>(self) -> Self::Out {
        let raw: RawScene<T::Params, T::Initial> =
            read(self.text, self.label).map_err(|e| match e {
                // A key of another kind (or a typo) in the kind's own tables.
                SimError::Field {
                    path,
                    line,
                    field,
                    message,
                } if message.starts_with("unknown field")
                    && (field.starts_with("system.") || field.starts_with("initial.")) =>
                {
                    SimError::Field {
                        path,
                        line,
                        field,
                        message: format!("{message}: not a parameter of {}", T::KIND),
                    }
                }
                e => e,
            })?;
        let system = T::check(&raw.system, &raw.initial).map(Into::into);
        let common = Common {
            name: raw.name,
            integrator: raw.integrator,
            output: raw.output,
            sweep: raw.sweep,
            many_bodies: raw.many_bodies,
            forces: raw.forces,
            events: raw.events,
        };
        Ok((system, common))
    }
}

/// `text` read as `T`, a serde error named by its line and dotted field.
fn read<T: DeserializeOwned>(text: &str, label: &str) -> Result<T, SimError> {
    toml::from_str(text).map_err(|e| {
        let (line, field) = e
            .span()
            .map_or((1, String::new()), |s| locate_field(text, s.start));
        SimError::Field {
            path: label.into(),
            line,
            field: if field.is_empty() {
                "scene".into()
            } else {
                field
            },
            message: one_line(e.message()),
        }
    })
}

impl Scene {
    /// The cost of a step of the scene's own method on its system relative to one on SO(3)
    /// ([`crate::bounds::stage_cost`]), the simulation built once to read the group's sizes;
    /// `implicit`: counted as implicit whatever the method (an upper figure for `trade`, whose
    /// candidates include implicit methods).
    pub fn step_cost(&self, implicit: bool) -> Result<u128, SimError> {
        let sim = crate::build::build(&self.system, &self.method, self.reconstruct, &self.solver)?;
        let explicit = sim.info().explicit && !implicit;
        Ok(crate::bounds::stage_cost(
            sim.momentum_dim(),
            sim.group_side(),
            crate::bounds::Solve::of(explicit, self.solver.config().kind),
            crate::bounds::dynamic_group(self.system.kind()),
        ))
    }

    /// Reads and checks a scene file.
    pub fn load(path: &Path, overrides: Overrides) -> Result<Self, SimError> {
        let text = crate::input::read_text(path)?;
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
        let kind = read::<Peek>(text, label)?.system.kind;
        let (system, mut common) = with_kind(kind, ReadAs { text, label })?;
        let mut duration_name = "integrator.duration";
        if let Some(d) = overrides.duration {
            common.integrator.duration = d;
            duration_name = overrides.duration_flag.unwrap_or("--duration");
        }
        if let Some(h) = overrides.step {
            common.integrator.step = Some(h);
        }
        if let Some(s) = overrides.stride {
            common.output.stride = Some(s);
        }
        let bad = |(field, message): FieldError| SimError::Invalid {
            path: label.into(),
            field,
            message,
        };
        Self::checked(system.map_err(bad)?, common, label, stem, duration_name)
    }

    /// Checks the values of the common tables against the checked system.
    /// `duration_name`: where the duration T came from (`integrator.duration`, or the flag that
    /// replaced it), for messages.
    fn checked(
        mut system: System,
        raw: Common,
        label: &str,
        stem: &str,
        duration_name: &str,
    ) -> Result<Self, SimError> {
        let bad = |field: &str, message: String| SimError::Invalid {
            path: label.into(),
            field: field.into(),
            message,
        };
        let name = raw.name.clone().unwrap_or_else(|| stem.to_string());
        if let Some(f) = &raw.forces {
            let Some(slots) = system.force_slots() else {
                return Err(bad(
                    "forces",
                    format!(
                        "[forces] applies to {} scenes, not {}",
                        SystemKind::forced_kinds(),
                        system.kind()
                    ),
                ));
            };
            let forces =
                check_forces(f, slots, system.kind().name()).map_err(|(f, m)| bad(&f, m))?;
            system.set_forces(forces);
        }

        let it = &raw.integrator;
        let duration = positive(duration_name, it.duration).map_err(|(f, m)| bad(&f, m))?;
        let stepping = RawStepping {
            step: it.step,
            tolerance: it.tolerance,
            rtol: it.rtol,
            atol: it.atol,
            epsilon: it.epsilon,
        };
        let (step, variable) = match check_stepping(&stepping, it.method, duration, duration_name)
            .map_err(|(f, m)| bad(&f, m))?
        {
            StepChoice::Fixed(h) => (h, None),
            StepChoice::Variable(v) => (duration, Some(v)),
        };
        if duration / step > MAX_STEPS {
            return Err(bad(
                duration_name,
                format!(
                    "duration / step = {:.3e} steps exceeds the limit {MAX_STEPS:.0e}",
                    duration / step
                ),
            ));
        }
        let method = MethodSpec {
            reversible: matches!(variable, Some(VariableSteps::Reversible(_))),
            ..check_method(it).map_err(|(f, m)| bad(&f, m))?
        };
        if let Some(tol) = it.solver_tolerance {
            positive("integrator.solver_tolerance", tol).map_err(|(f, m)| bad(&f, m))?;
        }
        if it.max_iterations == Some(0) {
            return Err(bad(
                "integrator.max_iterations",
                "must be at least 1, got 0".into(),
            ));
        }
        let solver = SolverOptions {
            kind: it.solver,
            tolerance: it.solver_tolerance,
            max_iterations: it.max_iterations,
        };
        let reconstruct = it.reconstruct.unwrap_or(true);
        // The method built once on the system: the library says whether the system has a
        // potential, whether the method applies, and whether a composition's base is symmetric.
        let probed = probe(&system, &method, reconstruct, &solver)?;
        if !reconstruct && probed.has_potential {
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
        match probed.built {
            Ok(()) => {}
            Err(BuildError::NotSymmetric { field, message }) => return Err(bad(field, message)),
            Err(BuildError::Missing {
                need,
                why,
                unavailable: false,
            }) => return Err(bad("integrator.method", BuildError::reason(&need, &why))),
            Err(e) => return Err(refusal(system.kind(), &method, e)),
        }
        if let Some(v @ VariableSteps::Reversible(_)) = variable {
            // Whether the method is symmetric on this system, and ρ(y₀) > 0, is known once built.
            if let Err(e) = build_with(&system, &method, reconstruct, &solver, Some(v)) {
                let message = match e {
                    SimError::Build { message, .. } => message,
                    e => e.to_string(),
                };
                return Err(bad("integrator.epsilon", message));
            }
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
        let many_bodies = match &raw.many_bodies {
            None => None,
            Some(m) => {
                Some(check_many_bodies(m, steps_for(duration, step)).map_err(|(f, m)| bad(f, m))?)
            }
        };
        Ok(Scene {
            name,
            source: label.into(),
            system,
            method,
            solver,
            reconstruct,
            step,
            variable,
            duration,
            stride,
            output_times,
            events,
            sweep,
            many_bodies,
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

    /// A key of another kind is an unknown field of this kind's table, named with its line; a
    /// mistyped inertia says what an inertia may be.
    #[test]
    fn each_kind_reads_its_own_keys() {
        let good = Scene::default_scene(Overrides::default()).unwrap();
        assert_eq!(good.system.kind().name(), "free-rigid-body");
        let text = DEFAULT_SCENE.replace("[system]", "[system]\nmass = 2.0");
        let e = Scene::parse(&text, "s", "s", Overrides::default())
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("system.mass") && e.contains("unknown field"),
            "{e}"
        );
        let inertia = DEFAULT_SCENE
            .lines()
            .find(|l| l.starts_with("inertia"))
            .unwrap();
        let text = DEFAULT_SCENE.replace(inertia, "inertia = \"heavy\"");
        let e = Scene::parse(&text, "s", "s", Overrides::default())
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("system.inertia")
                && e.contains("principal moments")
                && !e.contains("untagged"),
            "{e}"
        );
    }
}
