//! `lie-sim sweep` and `lie-sim merge`: ensembles of trajectories, on every core and across
//! machines.
//!
//! A scene with a `[sweep]` table names N initial momenta μ₀⁽ⁱ⁾, i = 0 … N−1, drawn around the
//! scene's μ₀ by `integrators::ensemble` (on the sphere |μ| = |μ₀| or on the kinetic energy level
//! h(μ) = h(μ₀)); member i depends only on (seed, i). Each member starts from the scene's g₀ and
//! takes n = ⌈T/h⌉ steps of T/n with the scene's method, the last one landing on T exactly; its summary (final μ, maximum
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
//!
//! **Memory.** The members go through in chunks of [`CHUNK`]: a chunk is drawn, stepped and its
//! rows written ([`CsvRows`], a [`Sink`]) before the next is drawn, so that a sweep holds one
//! chunk whatever N.

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
use nalgebra::Vector3;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The prefix of the first line of a sweep CSV.
pub const MAGIC: &str = "# lie-sim sweep: ";

/// What one sweep (or shard of one) produced, besides its rows (which went to a [`Sink`]).
#[derive(Debug, Clone)]
pub struct SweepOutput {
    /// The members of the shard (rows written).
    pub members: usize,
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

/// Where a sweep's member summaries go: [`Sink::begin`] once the path is known, then
/// [`Sink::take`] with the members in index order, [`CHUNK`] at a time, so that nothing of the
/// sweep is kept that grows with N.
pub trait Sink: Send {
    /// Before the first chunk: the path the members take and the algebra's dimension.
    fn begin(&mut self, path: &SweepPath, dim: usize) -> Result<(), SimError>;
    /// The next members' summaries, in index order (`Execution::Parallel`: on the current rayon
    /// pool, which the sink may use as long as the order it writes in stays the index order).
    fn take<A: Vector>(
        &mut self,
        chunk: &[Summary<A>],
        dim: usize,
        execution: Execution,
    ) -> Result<(), SimError>;
}

/// Members per chunk: the batch's state, the summaries and the rows of a chunk are all that a
/// sweep holds, whatever N.
pub const CHUNK: usize = 1 << 16;

/// Rows formatted per task when a chunk is formatted on the pool.
const ROWS_PER_TASK: usize = 1024;

/// The sweep CSV (module page), written as the chunks come.
pub struct CsvRows<W> {
    out: W,
    /// The first line for the scalar and the batched path (the fingerprint holds the path).
    magic: [String; 2],
    buf: String,
    /// The file the rows go to, named in write errors.
    path: PathBuf,
}

impl<W: std::io::Write + Send> CsvRows<W> {
    /// The CSV of `shard` of the scene's sweep (`plan`: its spec, steps and step), to `out`, the
    /// file at `path`.
    pub fn new(
        out: W,
        scene: &Scene,
        (spec, steps, h): (&SweepSpec, usize, f64),
        shard: Shard,
        path: &Path,
    ) -> Self {
        let magic = |batched| {
            magic_line(
                spec.count,
                shard,
                fingerprint(scene, spec, steps, h, batched),
            )
        };
        Self {
            out,
            magic: [magic(false), magic(true)],
            buf: String::new(),
            path: path.to_path_buf(),
        }
    }

    /// The writer, once every chunk went through.
    pub fn into_inner(self) -> W {
        self.out
    }

    fn write(&mut self, bytes: &[u8]) -> Result<(), SimError> {
        self.out.write_all(bytes).map_err(|source| SimError::Write {
            path: self.path.clone(),
            source,
        })
    }
}

impl<W: std::io::Write + Send> Sink for CsvRows<W> {
    fn begin(&mut self, path: &SweepPath, dim: usize) -> Result<(), SimError> {
        let magic = &self.magic[usize::from(path.is_batched())];
        let head = format!("{magic}\n{}\n", Summary::<Vector3<f64>>::csv_header(dim));
        self.write(head.as_bytes())
    }

    fn take<A: Vector>(
        &mut self,
        chunk: &[Summary<A>],
        dim: usize,
        execution: Execution,
    ) -> Result<(), SimError> {
        let rows = |part: &[Summary<A>], buf: &mut String| {
            for s in part {
                s.write_csv_row(dim, buf);
                buf.push('\n');
            }
        };
        match execution {
            Execution::Sequential => {
                self.buf.clear();
                let mut buf = std::mem::take(&mut self.buf);
                rows(chunk, &mut buf);
                let written = self.write(buf.as_bytes());
                self.buf = buf;
                written
            }
            Execution::Parallel => {
                use rayon::prelude::*;
                // `collect` on an indexed parallel iterator keeps the order of the parts.
                let parts: Vec<String> = chunk
                    .par_chunks(ROWS_PER_TASK)
                    .map(|part| {
                        let mut buf = String::with_capacity(160 * part.len());
                        rows(part, &mut buf);
                        buf
                    })
                    .collect();
                parts.iter().try_for_each(|p| self.write(p.as_bytes()))
            }
        }
    }
}

/// The statistics of [`SweepOutput`], folded over the chunks.
#[derive(Debug, Default)]
struct Tally {
    members: usize,
    completed: usize,
    max_energy_error: f64,
    max_casimir_error: Option<f64>,
    first_failure: Option<String>,
}

impl Tally {
    fn fold<A>(&mut self, chunk: &[Summary<A>]) {
        use integrators::ensemble::Status;
        self.members += chunk.len();
        for s in chunk {
            match &s.status {
                Status::Completed => {
                    self.completed += 1;
                    self.max_energy_error = self.max_energy_error.max(s.max_energy_error);
                    if let Some(c) = s.max_casimir_error {
                        self.max_casimir_error =
                            Some(self.max_casimir_error.map_or(c, |m| m.max(c)));
                    }
                }
                Status::StepFailed { step, error } => {
                    self.first_failure
                        .get_or_insert_with(|| format!("member {}: step {step}: {error}", s.index));
                }
                Status::BuildFailed(e) => {
                    self.first_failure
                        .get_or_insert_with(|| format!("member {}: {e}", s.index));
                }
            }
        }
    }

    fn output(self, path: SweepPath) -> SweepOutput {
        SweepOutput {
            members: self.members,
            completed: self.completed,
            max_energy_error: self.max_energy_error,
            max_casimir_error: self.max_casimir_error,
            first_failure: self.first_failure,
            path,
        }
    }
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

/// The [`Job`] of a sweep: draws the members around μ₀ and runs one shard of the ensemble, a
/// chunk at a time, into a [`Sink`].
struct SweepJob<'a, K> {
    spec: SweepSpec,
    /// The end time T every member lands on.
    end: f64,
    steps: usize,
    shard: Shard,
    pool: Option<&'a rayon::ThreadPool>,
    method: &'a MethodSpec,
    solver: &'a SolverOptions,
    /// The scalar path even where a batched one exists (`--scalar`).
    scalar: bool,
    sink: &'a mut K,
    progress: Option<&'a indicatif::ProgressBar>,
    /// `<kind> with <method>`, for errors.
    what: String,
}

impl<K: Sink> Job for SweepJob<'_, K> {
    type Out = SweepOutput;
    fn run<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<SweepOutput, SimError> {
        self.members(model, mu0, g0)
    }
}

/// Runs `f` sequentially on this thread, or on `pool`.
pub(crate) fn on<R: Send>(
    pool: Option<&rayon::ThreadPool>,
    f: impl FnOnce(Execution) -> R + Send,
) -> R {
    match pool {
        None => f(Execution::Sequential),
        Some(pool) => pool.install(|| f(Execution::Parallel)),
    }
}

/// Member i of an ensemble around μ₀, drawn from (seed, i) alone (module page): on the sphere
/// |μ| = |μ₀| or on the kinetic energy level h(μ) = h(μ₀) of `model`'s system. Member i depends
/// only on (seed, i), so a chunk draws only its own members and a shard costs in proportion to
/// its size whatever N is. Errors: the sphere around μ₀ = 0.
#[allow(clippy::type_complexity)]
pub fn member_draw<'m, M: Model>(
    model: &'m M,
    mu0: &Alg<M::G>,
    kind: SweepKind,
    seed: u64,
) -> Result<impl Fn(usize) -> Result<Alg<M::G>, IntegratorError> + Sync + 'm, IntegratorError> {
    let system = model.system();
    let dim = <M::G as lie_groups::LieGroup>::dim();
    let (radius, e0) = (mu0.norm(), system.hamiltonian(mu0));
    if kind == SweepKind::MomentaOnSphere && radius == 0.0 {
        return Err(IntegratorError::InvalidParameter {
            reason: "momenta-on-sphere around μ₀ = 0: the sphere |μ| = |μ₀| is a point".into(),
        });
    }
    Ok(move |i: usize| match kind {
        SweepKind::MomentaOnSphere => sphere_point(dim, radius, seed, i as u64),
        SweepKind::MomentaOnEnergyLevel => {
            energy_level_point::<M::G, M::S>(system, e0, seed, i as u64)
        }
    })
}

impl<K: Sink> SweepJob<'_, K> {
    fn members<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<SweepOutput, SimError> {
        type G<M> = <M as Model>::G;
        let what = self.what.clone();
        let failed = |e: IntegratorError| SimError::Build {
            what: what.clone(),
            message: e.to_string(),
        };
        let config = self.solver.config();
        let dim = <G<M> as lie_groups::LieGroup>::dim();
        let n = self.spec.count;
        let draw = member_draw(model, &mu0, self.spec.kind, self.spec.seed).map_err(&failed)?;
        let plan = if self.scalar {
            Err(crate::model::Missing::because("--scalar"))
        } else {
            Plan::new(self.method, model, g0.as_ref())
        };
        let path = match &plan {
            Ok(plan) => SweepPath::Batched(plan.level()),
            Err(missing) => SweepPath::Scalar(missing.0.clone()),
        };
        let sink = self.sink;
        sink.begin(&path, dim)?;
        let method = self.method;
        let build = |_i: usize, mu: &Alg<G<M>>| {
            build_method(method, &config, model, mu.clone(), g0.clone()).map_err(|e| match e {
                BuildError::Integrator(e) => e,
                other => IntegratorError::InvalidParameter {
                    reason: other.to_string(),
                },
            })
        };
        let mut tally = Tally::default();
        let mut all = self.shard.iter(n);
        // Reused from one chunk to the next, so that the chunks after the first allocate
        // (almost) nothing.
        let mut scratch = crate::batched::Scratch::default();
        let mut indices: Vec<usize> = Vec::new();
        let mut members: Vec<Alg<G<M>>> = Vec::new();
        loop {
            indices.clear();
            indices.extend(all.by_ref().take(CHUNK));
            if indices.is_empty() {
                break;
            }
            members.clear();
            on(self.pool, |execution| match execution {
                Execution::Sequential => indices.iter().try_for_each(|&i| {
                    members.push(draw(i)?);
                    Ok(())
                }),
                Execution::Parallel => {
                    use rayon::prelude::*;
                    let drawn: Result<Vec<_>, _> = indices.par_iter().map(|&i| draw(i)).collect();
                    drawn.map(|d| members.extend(d))
                }
            })
            .map_err(&failed)?;
            match &plan {
                Ok(plan) => {
                    let summaries = on(self.pool, |execution| {
                        plan.run(
                            &mut scratch,
                            &members,
                            &indices,
                            self.end,
                            self.steps,
                            self.spec.monitor_every,
                            execution,
                        )
                    })
                    .map_err(|e| {
                        failed(IntegratorError::InvalidParameter {
                            reason: format!("batched sweep: {e}"),
                        })
                    })?;
                    tally.fold(summaries);
                    on(self.pool, |execution| sink.take(summaries, dim, execution))?;
                }
                Err(_) => {
                    let ensemble =
                        Ensemble::new(std::mem::take(&mut members), self.end, self.steps)
                            .map_err(&failed)?
                            .monitor_every(self.spec.monitor_every);
                    let mut summaries: Vec<Summary<Alg<G<M>>>> = on(self.pool, |execution| {
                        ensemble.run_shard(Shard::all(), execution, &build)
                    });
                    // The ensemble numbered the chunk's members from 0: give them their sweep
                    // indices.
                    for (summary, &index) in summaries.iter_mut().zip(&indices) {
                        summary.index = index;
                    }
                    tally.fold(&summaries);
                    on(self.pool, |execution| sink.take(&summaries, dim, execution))?;
                }
            }
            if let Some(bar) = self.progress {
                bar.inc(indices.len() as u64);
            }
        }
        Ok(tally.output(path))
    }
}

/// The process's peak resident memory so far, in KiB (Linux: `VmHWM` of `/proc/self/status`;
/// `None` elsewhere), so that a sweep shows that its memory does not grow with N.
pub fn peak_resident_kib() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find_map(|l| l.strip_prefix("VmHWM:"))?;
    line.trim().strip_suffix("kB")?.trim().parse().ok()
}

/// The work of one shard of a sweep before it starts: its members × the steps of each (a
/// composite step counts its stages), each at `step_cost` ([`crate::scene::Scene::step_cost`]),
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
        "{:?}|{:?}|{:?}|{}|{:?}|{:?}|{:?}|{:?}{}",
        scene.system,
        scene.method,
        scene.solver,
        scene.reconstruct,
        h,
        // The last step lands on T: two sweeps of the same h and n but different T differ there.
        scene.duration,
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

/// The rows of a sweep as `lie-sim sweep` writes them: to a buffered file.
pub type FileRows = CsvRows<std::io::BufWriter<std::fs::File>>;

/// Runs `shard` of the scene's sweep on `threads` threads (1: sequentially on this thread; `None`:
/// rayon's default, one per core), its members' summaries going to `sink` a chunk at a time;
/// `progress` counts the members done.
///
/// The sink is the concrete [`FileRows`], not any [`Sink`]: the sweep is generic over every
/// system and method, and a generic entry point would be compiled again (all of it) in every
/// crate that calls it — the command, each test binary — where this one is compiled once, here.
pub fn run(
    scene: &Scene,
    shard: Shard,
    threads: Option<usize>,
    scalar: bool,
    sink: &mut FileRows,
    progress: Option<&indicatif::ProgressBar>,
) -> Result<(SweepOutput, SweepSpec, Duration), SimError> {
    let (spec, steps, _) = plan(scene)?;
    let pool = thread_pool(threads).map_err(|message| SimError::Sweep { message })?;
    let job = SweepJob {
        spec,
        end: scene.duration,
        steps,
        shard,
        pool: pool.as_ref(),
        method: &scene.method,
        solver: &scene.solver,
        scalar,
        sink,
        progress,
        what: format!("{} with {}", scene.system.kind(), scene.method),
    };
    let start = Instant::now();
    let out = scene.system.dispatch(scene.reconstruct, job)?;
    Ok((out, spec, start.elapsed()))
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

/// The pool of `threads` workers (all cores for `None`), or none for one thread: the sweep and
/// the many-body runs then step on the calling thread. The error says why the pool did not start.
pub(crate) fn thread_pool(threads: Option<usize>) -> Result<Option<rayon::ThreadPool>, String> {
    match threads {
        Some(1) => Ok(None),
        _ => rayon::ThreadPoolBuilder::new()
            .num_threads(threads.unwrap_or(0))
            .build()
            .map(Some)
            .map_err(|e| format!("cannot start the thread pool: {e}")),
    }
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
