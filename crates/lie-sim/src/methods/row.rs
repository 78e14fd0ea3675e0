//! What a method's row in the registry declares: its name, the options it takes, what `trade`
//! runs of it, and how it is drawn.

use super::families::Family;
use super::options::Options;
use crate::plot::Marker;
use crate::taus::TauKind;

/// Which τ a method takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TauRule {
    /// None (the method composes exact flows, or is not built on a retraction).
    None,
    /// Any of [`TauKind::ALL`], named in the scene.
    Any,
    /// This one only (the default when the scene names none).
    Only(TauKind),
}

/// How a method steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stepping {
    /// A fixed step h (`integrator.step`).
    Fixed,
    /// Steps chosen by the error estimate of an embedded pair to meet a tolerance
    /// (`integrator.tolerance`, or `rtol` and `atol`; `integrators::adaptive::Adaptive`).
    Tolerance,
}

/// The batched method (SIMD, lanes = bodies; the `batch` crate) that `lie-sim sweep` steps a
/// method's ensemble with, where the model is a body the batch carries (`crate::batched`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Batched {
    /// `batch::Strang` (the Strang splitting, under a composition too).
    Strang,
    /// `batch::QuaternionRk4` (RK4 on (q, Π), bit for bit the scalar step).
    Rk4,
    /// `batch::Rkmk4` (RKMK4 on SO(3) × so(3)*, bit for bit the scalar step wherever a step
    /// rotates a body by at most π/2).
    Rkmk4,
    /// `batch::ExactFlow` (the exact free-body flow, to a few ulps of the scalar one; the free
    /// body only).
    Exact,
}

/// The options a method takes in `[integrator]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Takes {
    /// `tau`.
    pub tau: TauRule,
    /// `theta`, θ ∈ [0, 1] of the discretization map.
    pub theta: bool,
    /// `splitting`: the method's coefficients (the Strang and Blanes–Moan schemes).
    pub coefficients: bool,
    /// `modified` and `order`: the free rigid body's modified Hamiltonian.
    pub modified: bool,
    /// `composition` and `processing` around it (when the built method is symmetric).
    pub wrappers: bool,
    /// How it steps.
    pub stepping: Stepping,
}

/// Which configurations of a method `trade` (and `choose`) run, expanded by `candidates` over
/// the τ the method takes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trade {
    /// θ values, for a method that takes θ.
    pub thetas: &'static [f64],
    /// Compositions of the symmetric configuration (θ = ½ where the method takes θ).
    pub compositions: &'static [&'static str],
    /// Modified Hamiltonians, as (θ, order).
    pub modified: &'static [(f64, u32)],
    /// Every built-in processing scheme around the symmetric configuration.
    pub processing: bool,
    /// Run once in one step to T (an exact flow: its error does not depend on h, nor its cost
    /// per step).
    pub one_step: bool,
    /// Configurations also run with reversible variable steps (`integrator.epsilon`, over a
    /// ladder of ε): the symmetric configuration (`None`; for a method that takes coefficients,
    /// each set of them) and compositions of it, by name.
    pub reversible: &'static [Option<&'static str>],
}

/// One method of the registry (see the module page).
#[derive(Debug)]
pub struct Row {
    /// The name in scene files (`method = "…"`).
    pub name: &'static str,
    /// What it is, in one line with its source.
    pub summary: &'static str,
    /// The options it takes.
    pub takes: Takes,
    /// What `trade` runs of it.
    pub trade: Trade,
    /// Its family in the plot, for a configuration that is not processed (processed methods are
    /// `families::PROCESSED`).
    pub family: fn(&Options) -> &'static Family,
    /// Drawn dashed with hollow markers, as the second of a pair (kinetic–kick beside splitting,
    /// rkmk4 beside rk4), as τ = cayley is beside τ = exp.
    pub second: bool,
    /// Its marker when neither θ nor a scheme sets one (the exact flow's ◆).
    pub marker: Option<Marker>,
    /// The batched method its sweeps run with, where there is one.
    pub batch: Option<Batched>,
    /// The largest step it takes on every valid state without refusing, as hω with ω the
    /// system's characteristic rate |∂h/∂μ| (`integrators::System::characteristic_rate`; |Ω| on
    /// a rigid body), for every configuration `trade` runs of it (its compositions' largest
    /// substep included); `None`: any step. Beyond it a step may be refused
    /// (`StepTooLarge`, `NoConvergence`), leaving the state as it was. A configuration whose
    /// limit the state sets beyond this one declares it where it is computed and refused
    /// (the modified Hamiltonian's, `super::MethodSpec::state_step_limit`). Checked by the
    /// extremes harness (`crate::extremes`).
    // Read by that harness only, a test, until a command warns of a step beyond it.
    #[cfg_attr(not(test), allow(dead_code))]
    pub step_limit: Option<f64>,
}

/// The θ values `trade` sweeps for a method that takes θ.
pub const THETAS: &[f64] = &[0.0, 0.5, 1.0];

/// The symmetric θ: what compositions and processing wrap, for a method that takes θ.
pub const SYMMETRIC_THETA: f64 = 0.5;
