//! The one error type of `lie-sim`. Every variant prints as one line that names what was wrong
//! (the scene field, the file, the method) and the value that was given.

use std::path::PathBuf;
use thiserror::Error;

/// Everything that can stop `lie-sim`: bad input, a combination the integrators crate does not
/// provide, a step that fails, or an output that cannot be written.
#[derive(Debug, Error)]
pub enum SimError {
    /// The scene file (or a CSV to plot) cannot be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file that was asked for.
        path: PathBuf,
        /// Why it could not be read.
        source: std::io::Error,
    },
    /// The file is not valid TOML.
    #[error("{path}:{line}: malformed TOML: {message}")]
    MalformedToml {
        /// The scene file.
        path: String,
        /// 1-based line of the error.
        line: usize,
        /// The parser's message.
        message: String,
    },
    /// The TOML is valid but a field is unknown, missing or of the wrong type.
    #[error("{path}:{line}: {field}: {message}")]
    Field {
        /// The scene file.
        path: String,
        /// 1-based line of the error.
        line: usize,
        /// Dotted path of the field, e.g. `integrator.step`.
        field: String,
        /// What was wrong.
        message: String,
    },
    /// A field parsed but its value is not acceptable (non-positive inertia, non-orthogonal
    /// attitude, zero step, …).
    #[error("{path}: {field}: {message}")]
    Invalid {
        /// The scene file (`<default scene>` for the embedded one).
        path: String,
        /// Dotted path of the field, e.g. `system.inertia`.
        field: String,
        /// What was wrong, with the value given.
        message: String,
    },
    /// The scene names a (system, method, τ) the integrators crate does not provide (yet).
    #[error("not yet available: {what}: {why}")]
    NotYetAvailable {
        /// The combination, e.g. `heavy-top with lie-poisson (τ = exp, θ = 0)`.
        what: String,
        /// What is missing.
        why: String,
    },
    /// The method does not apply to the system (Euler–Arnold on a system with a potential).
    #[error("{what}: {why}")]
    Inapplicable {
        /// The combination, e.g. `heavy-top with euler-arnold (τ = exp, θ = 0.5)`.
        what: String,
        /// Why it does not apply.
        why: String,
    },
    /// `lie-sim sweep` cannot run: no `[sweep]` table, a bad `--shard`, an initial momentum the
    /// sweep cannot be drawn around.
    #[error("sweep: {message}")]
    Sweep {
        /// What was wrong.
        message: String,
    },
    /// `lie-sim many-bodies` cannot run: no `[many_bodies]` table, a system whose bodies a
    /// many-body scene does not carry, a shard asked for.
    #[error("many-bodies: {message}")]
    ManyBodies {
        /// What was wrong.
        message: String,
    },
    /// `lie-sim merge` refused its inputs: different sweeps, a shard missing or given twice, an
    /// index missing or duplicated, a file that is not a shard written by `lie-sim sweep`.
    #[error("merge: {message}")]
    Merge {
        /// What was wrong, naming the file where there is one.
        message: String,
    },
    /// The integrators crate refused the scene's system or initial state.
    #[error("cannot build {what}: {message}")]
    Build {
        /// The combination, e.g. `free-rigid-body with lie-poisson (τ = exp, θ = 0)`.
        what: String,
        /// The integrators crate's message.
        message: String,
    },
    /// An integrator step failed (Newton did not converge, the state left the τ map's domain).
    #[error("step {step} at t = {time}: {message}")]
    Step {
        /// Index of the failing step (0-based).
        step: u64,
        /// Time at the start of the failing step.
        time: f64,
        /// The integrator's error.
        message: String,
    },
    /// The integrator returned a non-finite state.
    #[error("step {step} at t = {time}: the state is no longer finite")]
    NonFinite {
        /// Index of the step that produced the non-finite state.
        step: u64,
        /// Time at the start of that step.
        time: f64,
    },
    /// A trajectory CSV given to `plot` is not what `run` writes.
    #[error("{path}:{line}: {message}")]
    Csv {
        /// The CSV file.
        path: String,
        /// 1-based line of the error.
        line: usize,
        /// What was wrong.
        message: String,
    },
    /// An output path that must not be written: one of the command's inputs, another of its
    /// outputs, a directory, a socket or block device.
    #[error("refusing to write {path}: {why}")]
    Output {
        /// The output path as given.
        path: PathBuf,
        /// Why.
        why: String,
    },
    /// `lie-sim choose` found nothing meeting the target, or cannot write the chosen scene.
    #[error("choose: {message}")]
    Choose {
        /// What happened, with the best value reached.
        message: String,
    },
    /// A command-line value that parses but does not fit the scene (a step longer than T).
    #[error("{flag}: {message}")]
    Usage {
        /// The flag, e.g. `--steps`.
        flag: String,
        /// What is wrong with its value.
        message: String,
    },
    /// The command would take more steps or write more bytes than the limits of `bounds`.
    #[error("{what}: {message}; pass --allow-large to run it anyway")]
    TooLarge {
        /// The command, e.g. `run`.
        what: String,
        /// The estimate and the limit it exceeds.
        message: String,
    },
    /// An output file cannot be created, written or renamed into place.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The output file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// plotters failed to draw.
    #[error("cannot draw {path}: {message}")]
    Plot {
        /// The SVG file.
        path: PathBuf,
        /// plotters' message.
        message: String,
    },
}
