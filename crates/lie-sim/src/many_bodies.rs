//! `lie-sim many-bodies`: N independent rigid rotors — free, or rigid molecules and dipoles in a
//! uniform external field — and their statistics over time, not N rows.
//!
//! A scene with a `[many_bodies]` table names N bodies of its system (a rigid body in principal
//! axes, free or in a uniform field, unforced: the body a `batch::Batch` carries). Body i starts
//! from the scene's attitude g₀ with the momentum drawn from (seed, i) alone, as a `[sweep]`
//! member is (`crate::sweep::member_draw`: on the sphere |Π| = |Π₀| or on the kinetic energy
//! level of Π₀), and takes n = ⌈T/h⌉ steps of T/n with the scene's method. At t = 0, every
//! `stride` steps and at T the running bodies are read and folded into one CSV row of statistics
//! (`crate::body_stats`: energy and Casimir errors — mean, maximum, median and 99th percentile —,
//! the order parameters ⟨cos θ⟩ and ⟨P₂(cos θ)⟩ of the body axis against the field, the mean
//! kinetic energy per principal axis and the rotational temperature).
//!
//! ```toml
//! [many_bodies]
//! count = 100000                    # N bodies
//! seed = 1                          # body i depends only on (seed, i) (default 0)
//! kind = "momenta-on-energy-level"  # or "momenta-on-sphere", as [sweep]
//! stride = 10                       # a row every 10 steps (default ⌈n/100⌉), and at 0 and T
//! ```
//!
//! **Paths.** Where the method has a batched version (`crate::batched`: the Strang splitting and
//! its compositions, quaternion RK4, RKMK4) the bodies are stepped a chunk at a time by the batch, read
//! between the stretches of steps; otherwise (or with `--scalar`) each body by the scalar method,
//! built as `lie-sim sweep` builds a member. Batched RK4 is the scalar RK4 bit for bit on (q, Π), so
//! the columns read from Π (kinetic energies, temperature) are the same on both paths; R is
//! published from q with different roundings (an ulp or so), so the columns that read it (the
//! energy in a field, the order parameters) agree to round-off. The batched Strang step is within
//! a few ulps of the scalar one.
//!
//! **Bit-identical.** The bodies share nothing, each trajectory is the same bits whatever its lane,
//! chunk or thread (`batch`, `integrators::ensemble`), and the rows are sums folded in index order
//! after each chunk: the CSV does not depend on `--threads`. Shards are refused: a shard's sums
//! would be added to the others' in a different order than the unsharded run adds them, so the
//! merged rows would not be the unsharded rows' bits.
//!
//! **Memory.** The bodies go through in chunks (batched: `crate::sweep::CHUNK`; scalar: as many
//! as keep the chunk's observations — bodies × rows — under 2²⁰) and only the rows' accumulators
//! stay, a few kilobytes each (at most `crate::scene::MAX_MANY_BODY_ROWS` rows): memory does not grow with N.

use crate::attitude::Attitudes as _;
use crate::batched::{Plan, PlanBatch};
use crate::body_stats::{Observation, Observer, RowStats};
use crate::error::SimError;
use crate::methods::spec::SolverOptions;
use crate::methods::wrap::BuildError;
use crate::methods::{build as build_method, MethodSpec};
use crate::model::{Alg, Job, Missing, Model};
use crate::scene::{steps_for, ManyBodiesSpec, Scene};
use crate::sweep::{member_draw, on, SweepPath, CHUNK};
use integrators::ensemble::Execution;
use integrators::{Clock, Integrator as _, IntegratorError};
use lie_groups::Vector as _;
use nalgebra::Vector3;
use std::time::{Duration, Instant};

/// The scalar path's chunk holds at most this many observations (bodies × rows).
const SCALAR_OBSERVATIONS: usize = 1 << 20;

/// The steps at which rows are written: 0, stride, 2 stride, …, and n.
pub fn marks(n: u64, stride: u64) -> Vec<u64> {
    let mut m: Vec<u64> = (0..n).step_by(stride.max(1) as usize).collect();
    m.push(n);
    m
}

/// What a many-body run produced.
#[derive(Debug, Clone)]
pub struct ManyBodiesOutput {
    /// The table.
    pub spec: ManyBodiesSpec,
    /// The steps n and the step h = T/n.
    pub steps: u64,
    /// The step h.
    pub h: f64,
    /// How the bodies were stepped.
    pub path: SweepPath,
    /// One row per output time.
    pub rows: Vec<RowStats>,
    /// The wall time.
    pub wall: Duration,
}

impl ManyBodiesOutput {
    /// The CSV: a line naming the run, the header of `RowStats::csv_header`, one row per output
    /// time. Read it with e.g. `pandas.read_csv(path, comment="#")`.
    pub fn csv(&self, scene: &Scene) -> String {
        let mut s = format!(
            "# lie-sim many-bodies: bodies = {}, {} (seed {}), {} with {}, {} steps of h = {:?}, \
             path = {}\n{}\n",
            self.spec.count,
            self.spec.kind.name(),
            self.spec.seed,
            scene.system.kind(),
            scene.method,
            self.steps,
            self.h,
            self.path,
            RowStats::csv_header()
        );
        for row in &self.rows {
            row.write_csv_row(&mut s);
            s.push('\n');
        }
        s
    }
}

/// The scene's `[many_bodies]` table, its steps n = ⌈T/h⌉ and the step T/n.
pub fn plan(scene: &Scene) -> Result<(ManyBodiesSpec, u64, f64), SimError> {
    let spec = scene.many_bodies.ok_or_else(|| SimError::ManyBodies {
        message: format!(
            "{} has no [many_bodies] table (count, seed, kind, stride; see \
             examples/scenes/many-dipoles.toml)",
            scene.source
        ),
    })?;
    if scene.variable.is_some() {
        return Err(SimError::ManyBodies {
            message: format!(
                "the bodies are read together at the same times, and {} runs with variable \
                 steps: give a fixed-step method and its step",
                scene.method
            ),
        });
    }
    let n = steps_for(scene.duration, scene.step);
    Ok((spec, n, scene.duration / n as f64))
}

/// The work of a run before it starts, as `crate::sweep::estimate` counts a sweep's.
pub fn estimate(
    spec: &ManyBodiesSpec,
    steps: u64,
    stages: usize,
    step_cost: u128,
) -> crate::bounds::Estimate {
    crate::bounds::Estimate {
        steps: (spec.count as u128)
            .saturating_mul(steps as u128)
            .saturating_mul(stages as u128),
        bytes: crate::bounds::Estimate::csv(marks(steps, spec.stride).len() as u128 + 2, 16),
        step_cost,
    }
}

/// Runs the scene's bodies on `threads` threads (1: sequentially on this thread; `None`: one per
/// core); `progress` counts the bodies done.
pub fn run(
    scene: &Scene,
    threads: Option<usize>,
    scalar: bool,
    progress: Option<&indicatif::ProgressBar>,
) -> Result<ManyBodiesOutput, SimError> {
    let (spec, steps, h) = plan(scene)?;
    let pool =
        crate::sweep::thread_pool(threads).map_err(|message| SimError::ManyBodies { message })?;
    let job = ManyJob {
        spec,
        h,
        end: scene.duration,
        marks: marks(steps, spec.stride),
        pool: pool.as_ref(),
        method: &scene.method,
        solver: &scene.solver,
        scalar,
        progress,
        what: format!("{} with {}", scene.system.kind(), scene.method),
    };
    let start = Instant::now();
    // The bodies carry R whatever the scene says: the order parameters read it.
    let (path, rows) = scene.system.dispatch(true, job)?;
    Ok(ManyBodiesOutput {
        spec,
        steps,
        h,
        path,
        rows,
        wall: start.elapsed(),
    })
}

/// The [`Job`] of a run: draws the bodies, steps them a chunk at a time and folds the rows.
struct ManyJob<'a> {
    spec: ManyBodiesSpec,
    h: f64,
    /// T: the last step is T − t, t the time before it, so that the run lands on T as a sweep's
    /// members do (`integrators::ensemble::Ensemble`, `batch::Batch::run_to`).
    end: f64,
    /// The steps at which rows are written.
    marks: Vec<u64>,
    pool: Option<&'a rayon::ThreadPool>,
    method: &'a MethodSpec,
    solver: &'a SolverOptions,
    scalar: bool,
    progress: Option<&'a indicatif::ProgressBar>,
    /// `<kind> with <method>`, for errors.
    what: String,
}

impl Job for ManyJob<'_> {
    type Out = (SweepPath, Vec<RowStats>);
    fn run<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<Self::Out, SimError> {
        let what = self.what.clone();
        let failed = |e: IntegratorError| SimError::Build {
            what: what.clone(),
            message: e.to_string(),
        };
        let (body, _) = model
            .batch_body(g0.as_ref())
            .map_err(|m| SimError::ManyBodies {
                message: format!(
                "the bodies of a many-body scene are rigid bodies in principal axes, free or in a \
                 uniform field, without forces; this {} is not one{}",
                model.kind(),
                m.0.map(|why| format!(": {why}")).unwrap_or_default()
            ),
            })?;
        let observer = Observer::new(&body);
        let draw = member_draw(model, &mu0, self.spec.kind, self.spec.seed).map_err(&failed)?;
        let plan = if self.scalar {
            Err(Missing::because("--scalar"))
        } else {
            Plan::new(self.method, model, g0.as_ref())
        };
        let path = match &plan {
            Ok(plan) => SweepPath::Batched(plan.level()),
            Err(missing) => SweepPath::Scalar(missing.0.clone()),
        };
        let mut clock = Clock::at(0.0);
        let mut taken = 0;
        let last = self.marks.last().copied().unwrap_or(0);
        let mut rows: Vec<RowStats> = self
            .marks
            .iter()
            .map(|&m| {
                for _ in taken..m {
                    clock.advance(self.h);
                }
                taken = m;
                let t = if m == last { self.end } else { clock.now() };
                RowStats::new(t, m, observer.has_casimir())
            })
            .collect();
        let chunk = match plan {
            Ok(_) => CHUNK,
            Err(_) => (SCALAR_OBSERVATIONS / rows.len()).clamp(1, CHUNK),
        };
        let config = self.solver.config();
        let build = |mu: &Alg<M::G>| {
            build_method(self.method, &config, model, mu.clone(), g0.clone()).map_err(|e| match e {
                BuildError::Integrator(e) => e,
                other => IntegratorError::InvalidParameter {
                    reason: other.to_string(),
                },
            })
        };
        let mut members: Vec<Alg<M::G>> = Vec::new();
        let mut momenta: Vec<Vector3<f64>> = Vec::new();
        let mut batch: Option<PlanBatch> = None;
        let mut seen: Vec<Option<Observation>> = Vec::new();
        let mut initial: Vec<Option<Observation>> = Vec::new();
        let mut start = 0;
        while start < self.spec.count {
            let end = (start + chunk).min(self.spec.count);
            members.clear();
            on(self.pool, |execution| match execution {
                Execution::Sequential => (start..end).try_for_each(|i| {
                    members.push(draw(i)?);
                    Ok(())
                }),
                Execution::Parallel => {
                    use rayon::prelude::*;
                    let drawn: Result<Vec<_>, _> =
                        (start..end).into_par_iter().map(&draw).collect();
                    drawn.map(|d| members.extend(d))
                }
            })
            .map_err(&failed)?;
            match &plan {
                Ok(plan) => {
                    momenta.clear();
                    momenta.extend(members.iter().map(|mu| Vector3::from_fn(|i, _| mu.get(i))));
                    let execution = match self.pool {
                        None => Execution::Sequential,
                        Some(_) => Execution::Parallel,
                    };
                    let batch_failed = |e: batch::BatchError| SimError::ManyBodies {
                        message: format!("batched bodies: {e}"),
                    };
                    let b = match batch.as_mut() {
                        Some(b) => {
                            plan.refill(b, &momenta).map_err(batch_failed)?;
                            b
                        }
                        None => {
                            batch.insert(plan.new_batch(&momenta, execution).map_err(batch_failed)?)
                        }
                    };
                    for (k, row) in rows.iter_mut().enumerate() {
                        if k > 0 {
                            let stretch = self.marks[k] - self.marks[k - 1];
                            let (h, end) = (self.h, self.end);
                            on(self.pool, |_| {
                                if self.marks[k] == last {
                                    b.run_landing(h, stretch, end)
                                } else {
                                    b.run(h, stretch)
                                }
                            })
                            .map_err(batch_failed)?;
                        }
                        let read = |i: usize| {
                            b.running_state(i)
                                .map(|(pi, r)| observer.observe(&pi, r.as_matrix()))
                        };
                        on(self.pool, |execution| match execution {
                            Execution::Sequential => {
                                seen.clear();
                                seen.extend((0..b.len()).map(read));
                            }
                            Execution::Parallel => {
                                use rayon::prelude::*;
                                (0..b.len())
                                    .into_par_iter()
                                    .map(read)
                                    .collect_into_vec(&mut seen);
                            }
                        });
                        if k == 0 {
                            initial.clone_from(&seen);
                        }
                        for (o, o0) in seen.iter().zip(&initial) {
                            row.fold(o.as_ref(), o0.as_ref());
                        }
                    }
                }
                Err(_) => {
                    let r = rows.len();
                    seen.clear();
                    seen.resize(members.len() * r, None);
                    let marks = &self.marks;
                    let (h, end) = (self.h, self.end);
                    let one = |(mu, out): (&Alg<M::G>, &mut [Option<Observation>])| {
                        let Ok(mut integ) = build(mu) else {
                            return;
                        };
                        let read = |integ: &crate::sim::Boxed<M::G>| {
                            let mu = integ.momentum();
                            let g = integ.configuration()?;
                            let pi = Vector3::from_fn(|i, _| mu.get(i));
                            Some(observer.observe(&pi, g.attitude(0).as_matrix()))
                        };
                        out[0] = read(&integ);
                        for (k, slot) in out.iter_mut().enumerate().skip(1) {
                            for j in marks[k - 1]..marks[k] {
                                let h = if j + 1 == last { end - integ.time() } else { h };
                                if integ.step(h).is_err() {
                                    return;
                                }
                            }
                            *slot = read(&integ);
                        }
                    };
                    on(self.pool, |execution| match execution {
                        Execution::Sequential => {
                            members.iter().zip(seen.chunks_mut(r)).for_each(one);
                        }
                        Execution::Parallel => {
                            use rayon::prelude::*;
                            members
                                .par_iter()
                                .zip(seen.par_chunks_mut(r))
                                .with_max_len(1)
                                .for_each(one);
                        }
                    });
                    for (k, row) in rows.iter_mut().enumerate() {
                        for body in seen.chunks(r) {
                            row.fold(body[k].as_ref(), body[0].as_ref());
                        }
                    }
                }
            }
            if let Some(bar) = self.progress {
                bar.inc((end - start) as u64);
            }
            start = end;
        }
        Ok((path, rows))
    }
}
