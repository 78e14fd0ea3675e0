//! `lie-sim sweep` and `lie-sim merge`: ensembles of trajectories, on every core and across
//! machines.
//!
//! A scene with a `[sweep]` table names N initial momenta μ₀⁽ⁱ⁾, i = 0 … N−1, drawn around the
//! scene's μ₀ by `integrators::ensemble` (on the sphere |μ| = |μ₀| or on the kinetic energy level
//! h(μ) = h(μ₀)); member i depends only on (seed, i). Each member starts from the scene's g₀ and
//! takes n = ⌈T/h⌉ equal steps of T/n with the scene's method; its summary (final μ, maximum
//! energy and Casimir errors, status) is one CSV row.
//!
//! **Bit-identical.** Trajectories share nothing and each is a fixed sequence of floating-point
//! operations, so the rows do not depend on the number of threads, on the shard, or on the
//! machine of the same build (`integrators::ensemble`, "Determinism"). The `--threads` count and
//! the shard split change only the wall time.
//!
//! **Shards.** `--shard i/n` (0-based: 0 ≤ i < n, the library's convention) runs the contiguous
//! block of indices ⌊iN/n⌋ … ⌊(i+1)N/n⌋ − 1 only. `lie-sim merge` puts the n shard files back
//! into the file the unsharded sweep writes, byte for byte, and refuses shards of different
//! sweeps, a shard missing or given twice, and an index missing or duplicated.
//!
//! **File format.** Line 1 is a comment naming the sweep:
//! `# lie-sim sweep: members = N, shard = i/n, fingerprint = <16 hex digits>`; the fingerprint is a
//! hash of everything that determines the rows (system, initial state, method, step, count, seed,
//! kind), so that shards of different sweeps are not merged. Line 2 is the header of
//! `integrators::ensemble::Summary::csv_header`: `index,status,steps,time,mu_0,…,mu_{d−1},
//! initial_energy,max_energy_error,max_casimir_error`; then one row per member in index order,
//! floats in shortest round-trip form. Read it with e.g. `pandas.read_csv(path, comment="#")`.

use crate::batched::Plan;
use crate::error::SimError;
use crate::methods::spec::SolverOptions;
use crate::methods::wrap::BuildError;
use crate::methods::{build as build_method, MethodSpec};
use crate::model::{Alg, Job, Model};
use crate::output::write_atomic;
use crate::scene::{steps_for, Scene, SweepKind, SweepSpec};
use crate::stepping::VariableSteps;
use integrators::ensemble::{
    energy_level_point, sphere_point, Ensemble, Execution, Shard, Summary,
};
use integrators::{IntegratorError, System as _};
use lie_groups::Vector;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The prefix of the first line of a sweep CSV.
pub const MAGIC: &str = "# lie-sim sweep: ";

/// What one sweep (or shard of one) produced.
#[derive(Debug, Clone)]
pub struct SweepOutput {
    /// The CSV header (no newline).
    pub header: String,
    /// One row per member of the shard, in index order (no newlines).
    pub rows: Vec<String>,
    /// Members whose trajectory took every step.
    pub completed: usize,
    /// The largest `max_energy_error` over the completed members.
    pub max_energy_error: f64,
    /// The largest `max_casimir_error`, where the system has a Casimir.
    pub max_casimir_error: Option<f64>,
    /// The first failure, `index: message`, if any member failed.
    pub first_failure: Option<String>,
    /// How the members were stepped.
    pub path: SweepPath,
}

/// How a sweep's members were stepped (`crate::batched`).
#[derive(Debug, Clone, PartialEq)]
pub enum SweepPath {
    /// N at a time by the method's batched version, on this instruction set.
    Batched(batch::Level),
    /// One scalar integrator per member, and why not batched.
    Scalar(Option<String>),
}

impl SweepPath {
    /// Whether batched (part of the fingerprint: the paths agree to ulps, not bits).
    pub fn is_batched(&self) -> bool {
        matches!(self, Self::Batched(_))
    }
}

impl std::fmt::Display for SweepPath {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Batched(level) => write!(f, "batched ({level}, {} lanes)", level.lanes()),
            Self::Scalar(None) => f.write_str("scalar"),
            Self::Scalar(Some(why)) => write!(f, "scalar ({why})"),
        }
    }
}

/// The [`Job`] of a sweep: draws the members around μ₀ and runs one shard of the ensemble.
struct SweepJob<'a> {
    spec: SweepSpec,
    h: f64,
    steps: usize,
    shard: Shard,
    pool: Option<&'a rayon::ThreadPool>,
    method: &'a MethodSpec,
    solver: &'a SolverOptions,
    /// The scalar path even where a batched one exists (`--scalar`).
    scalar: bool,
    /// `<kind> with <method>`, for errors.
    what: String,
}

impl Job for SweepJob<'_> {
    type Out = SweepOutput;
    fn run<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<SweepOutput, SimError> {
        let what = self.what.clone();
        self.members(model, mu0, g0).map_err(|e| SimError::Build {
            what,
            message: e.to_string(),
        })
    }
}

impl SweepJob<'_> {
    fn members<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<SweepOutput, IntegratorError> {
        type G<M> = <M as Model>::G;
        let system = model.system();
        let config = self.solver.config();
        let dim = <G<M> as lie_groups::LieGroup>::dim();
        let (n, seed) = (self.spec.count, self.spec.seed);
        // Only this shard's members are drawn (each from (seed, index) alone), so a shard costs
        // in proportion to its size whatever N is.
        let indices = self.shard.indices(n);
        let members: Vec<Alg<G<M>>> = match self.spec.kind {
            SweepKind::MomentaOnSphere => {
                let radius = mu0.norm();
                if radius == 0.0 {
                    return Err(IntegratorError::InvalidParameter {
                        reason: "momenta-on-sphere around μ₀ = 0: the sphere |μ| = |μ₀| is a point"
                            .into(),
                    });
                }
                indices
                    .iter()
                    .map(|&i| sphere_point(dim, radius, seed, i as u64))
                    .collect::<Result<_, _>>()?
            }
            SweepKind::MomentaOnEnergyLevel => {
                let e0 = system.hamiltonian(&mu0);
                indices
                    .iter()
                    .map(|&i| energy_level_point::<G<M>, M::S>(system, e0, seed, i as u64))
                    .collect::<Result<_, _>>()?
            }
        };
        let plan = if self.scalar {
            Err(crate::model::Missing::because("--scalar"))
        } else {
            Plan::new(self.method, model, g0.as_ref())
        };
        let why_scalar = match plan {
            Ok(plan) => {
                let run = |execution| {
                    plan.run(
                        &members,
                        &indices,
                        self.h,
                        self.steps,
                        self.spec.monitor_every,
                        execution,
                    )
                };
                let summaries = match self.pool {
                    None => run(Execution::Sequential),
                    Some(pool) => pool.install(|| run(Execution::Parallel)),
                }
                .map_err(|e| IntegratorError::InvalidParameter {
                    reason: format!("batched sweep: {e}"),
                })?;
                return Ok(output(&summaries, dim, SweepPath::Batched(plan.level())));
            }
            Err(missing) => missing.0,
        };
        let ensemble =
            Ensemble::new(members, self.h, self.steps)?.monitor_every(self.spec.monitor_every);
        let method = self.method;
        let build = |_i: usize, mu: &Alg<G<M>>| {
            build_method(method, &config, model, mu.clone(), g0.clone()).map_err(|e| match e {
                BuildError::Integrator(e) => e,
                other => IntegratorError::InvalidParameter {
                    reason: other.to_string(),
                },
            })
        };
        let mut summaries: Vec<Summary<Alg<G<M>>>> = match self.pool {
            None => ensemble.run_shard(Shard::all(), Execution::Sequential, &build),
            Some(pool) => {
                pool.install(|| ensemble.run_shard(Shard::all(), Execution::Parallel, &build))
            }
        };
        // The ensemble numbered the shard's members from 0: give them their sweep indices.
        for (summary, &index) in summaries.iter_mut().zip(&indices) {
            summary.index = index;
        }
        Ok(output(&summaries, dim, SweepPath::Scalar(why_scalar)))
    }
}

/// The output of a shard from its members' summaries.
fn output<A: Vector>(summaries: &[Summary<A>], dim: usize, path: SweepPath) -> SweepOutput {
    let completed: Vec<&Summary<A>> = summaries
        .iter()
        .filter(|s| s.status.is_completed())
        .collect();
    let first_failure = summaries.iter().find_map(|s| match &s.status {
        integrators::ensemble::Status::Completed => None,
        integrators::ensemble::Status::StepFailed { step, error } => {
            Some(format!("member {}: step {step}: {error}", s.index))
        }
        integrators::ensemble::Status::BuildFailed(e) => Some(format!("member {}: {e}", s.index)),
    });
    SweepOutput {
        header: Summary::<A>::csv_header(dim),
        rows: summaries.iter().map(|s| s.csv_row(dim)).collect(),
        completed: completed.len(),
        max_energy_error: completed
            .iter()
            .fold(0.0f64, |m, s| m.max(s.max_energy_error)),
        max_casimir_error: completed
            .iter()
            .filter_map(|s| s.max_casimir_error)
            .reduce(f64::max),
        first_failure,
        path,
    }
}

/// The work of one shard of a sweep before it starts: its members × the steps of each (a
/// composite step counts its stages), each at `step_cost` ([`crate::bounds::scene_step_cost`]),
/// and its rows of the summary CSV.
pub fn estimate(
    spec: &SweepSpec,
    shard: Shard,
    steps: usize,
    stages: usize,
    step_cost: u128,
) -> crate::bounds::Estimate {
    let members = (spec.count / shard.count()) as u128 + 1;
    crate::bounds::Estimate {
        steps: members
            .saturating_mul(steps as u128)
            .saturating_mul(stages as u128),
        bytes: crate::bounds::Estimate::csv(members + 2, 12),
        step_cost,
    }
}

/// The sweep of a scene: its `[sweep]` table, the number n = ⌈T/h⌉ of steps and the step T/n.
pub fn plan(scene: &Scene) -> Result<(SweepSpec, usize, f64), SimError> {
    let spec = scene.sweep.ok_or_else(|| SimError::Sweep {
        message: format!(
            "{} has no [sweep] table (count, seed, kind; see examples/scenes/sweep.toml)",
            scene.source
        ),
    })?;
    if let Some(v) = scene.variable {
        let how = match v {
            VariableSteps::Tolerance(t) => format!("to a tolerance (rtol = {:e})", t.rtol),
            VariableSteps::Reversible(epsilon) => {
                format!("with reversible variable steps (epsilon = {epsilon:e})")
            }
        };
        return Err(SimError::Sweep {
            message: format!(
                "the ensemble steps its members in lockstep with one fixed step, and {} runs \
                 {how}: give the sweep a fixed-step method and its step",
                scene.method
            ),
        });
    }
    let n = steps_for(scene.duration, scene.step);
    let steps = usize::try_from(n).map_err(|_| SimError::Sweep {
        message: format!("{n} steps per trajectory do not fit this machine"),
    })?;
    Ok((spec, steps, scene.duration / n as f64))
}

/// FNV-1a (64 bits) of the description of everything that determines a sweep's rows, the path
/// included (the batched and scalar paths agree to ulps, not bits).
pub fn fingerprint(scene: &Scene, spec: &SweepSpec, steps: usize, h: f64, batched: bool) -> u64 {
    let text = format!(
        "{:?}|{:?}|{:?}|{}|{:?}|{:?}|{:?}{}",
        scene.system,
        scene.method,
        scene.solver,
        scene.reconstruct,
        h,
        steps,
        spec,
        if batched { "|batched" } else { "" }
    );
    text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The first line of a sweep CSV.
pub fn magic_line(members: usize, shard: Shard, fingerprint: u64) -> String {
    format!(
        "{MAGIC}members = {members}, shard = {}/{}, fingerprint = {fingerprint:016x}",
        shard.index(),
        shard.count()
    )
}

/// Runs `shard` of the scene's sweep on `threads` threads (1: sequentially on this thread; `None`:
/// rayon's default, one per core).
pub fn run(
    scene: &Scene,
    shard: Shard,
    threads: Option<usize>,
    scalar: bool,
) -> Result<(SweepOutput, SweepSpec, Duration), SimError> {
    let (spec, steps, h) = plan(scene)?;
    let pool = match threads {
        Some(1) => None,
        _ => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads.unwrap_or(0))
                .build()
                .map_err(|e| SimError::Sweep {
                    message: format!("cannot start the thread pool: {e}"),
                })?,
        ),
    };
    let job = SweepJob {
        spec,
        h,
        steps,
        shard,
        pool: pool.as_ref(),
        method: &scene.method,
        solver: &scene.solver,
        scalar,
        what: format!("{} with {}", scene.system.kind(), scene.method),
    };
    let start = Instant::now();
    let out = scene.system.dispatch(scene.reconstruct, job)?;
    Ok((out, spec, start.elapsed()))
}

/// The CSV text of a sweep (or shard) output.
pub fn to_csv(out: &SweepOutput, members: usize, shard: Shard, fingerprint: u64) -> String {
    let mut s = magic_line(members, shard, fingerprint);
    s.push('\n');
    s.push_str(&out.header);
    s.push('\n');
    for r in &out.rows {
        s.push_str(r);
        s.push('\n');
    }
    s
}

/// A shard file read back.
struct ShardFile {
    path: PathBuf,
    members: usize,
    shard: (usize, usize),
    fingerprint: String,
    header: String,
    /// (index, row).
    rows: Vec<(usize, String)>,
}

fn merge_error(message: String) -> SimError {
    SimError::Merge { message }
}

fn read_shard(path: &Path) -> Result<ShardFile, SimError> {
    let text = crate::input::read_text(path)?;
    let p = path.display();
    let not_a_shard = || {
        merge_error(format!(
            "{p}:1: not a shard written by `lie-sim sweep` (no `{MAGIC}…` line)"
        ))
    };
    let mut lines = text.lines();
    let magic = lines.next().ok_or_else(not_a_shard)?;
    let fields = magic.strip_prefix(MAGIC).ok_or_else(not_a_shard)?;
    let mut members = None;
    let mut shard = None;
    let mut fp = None;
    for kv in fields.split(", ") {
        match kv.split_once(" = ") {
            Some(("members", v)) => members = v.parse::<usize>().ok(),
            Some(("shard", v)) => {
                shard = v
                    .split_once('/')
                    .and_then(|(i, n)| Some((i.parse::<usize>().ok()?, n.parse::<usize>().ok()?)))
                    .filter(|(i, n)| i < n)
            }
            Some(("fingerprint", v)) => fp = Some(v.to_string()),
            _ => return Err(not_a_shard()),
        }
    }
    let (Some(members), Some(shard), Some(fingerprint)) = (members, shard, fp) else {
        return Err(not_a_shard());
    };
    let header = lines
        .next()
        .filter(|h| h.starts_with("index,"))
        .ok_or_else(|| merge_error(format!("{p}:2: missing the `index,…` header")))?
        .to_string();
    let mut rows = Vec::new();
    for (k, line) in lines.enumerate() {
        let index = line
            .split_once(',')
            .and_then(|(i, _)| i.parse::<usize>().ok())
            .ok_or_else(|| merge_error(format!("{p}:{}: no member index", k + 3)))?;
        rows.push((index, line.to_string()));
    }
    Ok(ShardFile {
        path: path.to_path_buf(),
        members,
        shard,
        fingerprint,
        header,
        rows,
    })
}

/// Merges the shard files of one sweep into the text the unsharded sweep writes (shard 0/1).
///
/// Refused: files of different sweeps (members, shard count, fingerprint or header differ), a
/// shard given twice or missing, a member index outside 0..N, given twice or missing.
pub fn merge(paths: &[PathBuf]) -> Result<(String, usize, usize), SimError> {
    let files: Vec<ShardFile> = paths
        .iter()
        .map(|p| read_shard(p))
        .collect::<Result<_, _>>()?;
    let Some(first) = files.first() else {
        return Err(merge_error("no shard files given".into()));
    };
    let (members, n) = (first.members, first.shard.1);
    for f in &files[1..] {
        let differ = |what: &str| {
            merge_error(format!(
                "{} and {} are shards of different sweeps ({what} differ)",
                first.path.display(),
                f.path.display()
            ))
        };
        if f.members != members {
            return Err(differ("member counts"));
        }
        if f.shard.1 != n {
            return Err(differ("shard counts"));
        }
        if f.fingerprint != first.fingerprint {
            return Err(differ("scene fingerprints"));
        }
        if f.header != first.header {
            return Err(differ("headers"));
        }
    }
    let mut owner: Vec<Option<&Path>> = vec![None; n];
    for f in &files {
        let i = f.shard.0;
        if let Some(prev) = owner[i] {
            return Err(merge_error(format!(
                "shard {i}/{n} given twice ({} and {})",
                prev.display(),
                f.path.display()
            )));
        }
        owner[i] = Some(&f.path);
    }
    if let Some(i) = owner.iter().position(Option::is_none) {
        return Err(merge_error(format!(
            "shard {i}/{n} is missing (shards are 0-based: 0/{n} … {}/{n})",
            n - 1
        )));
    }
    let mut slots: Vec<Option<&str>> = vec![None; members];
    for f in &files {
        for (index, row) in &f.rows {
            match slots.get_mut(*index) {
                None => {
                    return Err(merge_error(format!(
                        "{}: index {index} outside the sweep of {members} members",
                        f.path.display()
                    )))
                }
                Some(Some(_)) => {
                    return Err(merge_error(format!(
                        "{}: index {index} appears twice",
                        f.path.display()
                    )))
                }
                Some(slot) => *slot = Some(row),
            }
        }
    }
    if let Some(i) = slots.iter().position(Option::is_none) {
        return Err(merge_error(format!(
            "index {i} is missing (a shard file was cut short?)"
        )));
    }
    let mut s = format!(
        "{MAGIC}members = {members}, shard = 0/1, fingerprint = {}\n{}\n",
        first.fingerprint, first.header
    );
    for row in slots.into_iter().flatten() {
        s.push_str(row);
        s.push('\n');
    }
    Ok((s, files.len(), members))
}

/// Writes a merged table atomically.
pub fn write(path: &Path, text: &str) -> Result<(), SimError> {
    write_atomic(path, text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn magic_line_round_trips_through_the_reader() {
        let dir = std::env::temp_dir().join(format!("lie-sim-sweep-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("s.csv");
        let text = format!(
            "{}\nindex,status\n1,completed\n",
            magic_line(3, Shard::new(1, 3).unwrap(), 0xabc)
        );
        std::fs::write(&p, text).unwrap();
        let f = read_shard(&p).unwrap();
        assert_eq!((f.members, f.shard), (3, (1, 3)));
        assert_eq!(f.fingerprint, "0000000000000abc");
        assert_eq!(f.rows, vec![(1, "1,completed".to_string())]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
