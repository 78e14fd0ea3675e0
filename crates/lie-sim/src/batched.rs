//! The sweep's batched path: where the scene's method has a batched version (its registry row's
//! `batch`: the Strang splitting, under a composition too, quaternion RK4, RKMK4 and the exact
//! free-body flow) and the model is a
//! body a batch carries (a rigid body in principal axes, free or in a uniform field, unforced:
//! `Model::batch_body`), `lie-sim sweep` steps the members N at a time with the `batch` crate —
//! eight bodies per vector operation on AVX-512, four on AVX2 — instead of one scalar step per
//! member per core.
//!
//! **Same rows, to the ulp.** The batched Strang step is within `4 (1 + θ)` ulps of the scalar
//! step (θ its largest rotation angle), batched RK4 is the scalar step bit for bit, and so is
//! batched RKMK4 wherever a step rotates a body by at most π/2; the batched exact flow is the
//! scalar `ExactFreeBody` to a few ulps of |Π| (bit for bit on the bodies it hands to the scalar
//! flow: axisymmetric bodies, steady rotations, the separatrix); each member's
//! trajectory has the same bits whatever its lane, the chunk, the instruction set, the thread
//! count and the shard (the `batch` crate's determinism), so the sweep's rows still do not depend
//! on how it is run. The path is part of the sweep's fingerprint: shards of the batched and the
//! scalar path are not merged. `lie-sim sweep --scalar` takes the scalar path.
//!
//! **Memory.** The sweep hands a [`Plan`] its members a chunk at a time (`crate::sweep::CHUNK`,
//! their state a few hundred bytes each), and writes each chunk's rows before the next is drawn,
//! so that nothing grows with N.

use crate::methods::row::Batched;
use crate::methods::MethodSpec;
use crate::model::{Missing, Model};
use batch::{Batch, BatchError, BodyModel, ExactFlow, Kernel, Level, QuaternionRk4, Rkmk4, Strang};
use integrators::ensemble::{Execution, Summary};
use lie_groups::{So3, Vector};
use nalgebra::Vector3;

/// A sweep's batched run: the kernel, the body, g₀ and the instruction set.
#[derive(Debug, Clone)]
pub struct Plan {
    kind: Batched,
    body: BodyModel,
    g0: So3,
    composition: Option<integrators::CompositionScheme>,
    level: Level,
}

impl Plan {
    /// The batched run of `spec` on `model` from g₀, or why there is none (`Missing` with the
    /// reason, or without one where the method has no batched version).
    pub fn new<M: Model>(spec: &MethodSpec, model: &M, g0: Option<&M::G>) -> Result<Self, Missing> {
        let Some(kind) = spec.method.row().batch else {
            return Err(Missing::because(format!(
                "{} has no batched version",
                spec.method
            )));
        };
        if spec.processing.is_some() || spec.modified.is_some() {
            return Err(Missing::because(
                "the batched splitting takes compositions, not processing or a modified \
                 Hamiltonian",
            ));
        }
        let (body, g0) = model.batch_body(g0).map_err(|m| {
            Missing::because(m.0.unwrap_or_else(|| {
                format!(
                    "a batch carries rigid bodies in principal axes, free or in a uniform field, \
                     without forces; this {} is not one",
                    model.kind()
                )
            }))
        })?;
        if kind == Batched::Exact {
            ExactFlow::new(body.clone()).map_err(|e| Missing::because(e.to_string()))?;
        }
        Ok(Self {
            kind,
            body,
            g0,
            composition: spec.composition.clone(),
            level: Level::detect(),
        })
    }

    /// The instruction set the batch runs on.
    pub fn level(&self) -> Level {
        self.level
    }

    /// One summary per member (momenta `members`, sweep indices `indices`) after `steps` steps
    /// from 0 to the end time T, the last one landing on T (`Batch::run_to`), energy and Casimir monitored every `monitor_every` steps, as
    /// `integrators::ensemble::Ensemble` reports them for the scalar method. The batch, the
    /// momenta and the summaries live in `scratch`, which the sweep hands every chunk, so that
    /// no chunk after the first allocates a large buffer (the same bits as a new batch per chunk).
    #[allow(clippy::too_many_arguments)]
    pub fn run<'s, A: Vector>(
        &self,
        scratch: &'s mut Scratch,
        members: &[A],
        indices: &[usize],
        end: f64,
        steps: usize,
        monitor_every: usize,
        execution: Execution,
    ) -> Result<&'s [Summary<Vector3<f64>>], BatchError> {
        let Scratch {
            strang,
            rk4,
            rkmk4,
            exact,
            momenta,
            summaries,
        } = scratch;
        momenta.clear();
        momenta.extend(members.iter().map(|mu| Vector3::from_fn(|i, _| mu.get(i))));
        let job = Job {
            momenta: momenta.as_slice(),
            indices,
            out: summaries,
        };
        match self.kind {
            Batched::Strang => self.batch(
                strang,
                || Ok(Strang::new(self.body.clone())),
                job,
                (end, steps, monitor_every),
                execution,
            )?,
            Batched::Rk4 => self.batch(
                rk4,
                || Ok(QuaternionRk4::new(self.body.clone())),
                job,
                (end, steps, monitor_every),
                execution,
            )?,
            Batched::Rkmk4 => self.batch(
                rkmk4,
                || Ok(Rkmk4::new(self.body.clone())),
                job,
                (end, steps, monitor_every),
                execution,
            )?,
            Batched::Exact => self.batch(
                exact,
                || ExactFlow::new(self.body.clone()),
                job,
                (end, steps, monitor_every),
                execution,
            )?,
        }
        Ok(scratch.summaries.as_slice())
    }

    fn batch<K: Kernel>(
        &self,
        slot: &mut Option<Batch<K>>,
        kernel: impl FnOnce() -> Result<K, BatchError>,
        Job {
            momenta,
            indices,
            out,
        }: Job<'_>,
        (end, steps, monitor_every): (f64, usize, usize),
        execution: Execution,
    ) -> Result<(), BatchError> {
        let b = match slot.take() {
            Some(mut b) => {
                b.refill(momenta, &[self.g0])?;
                b
            }
            None => {
                let mut b = Batch::new(kernel()?, momenta, &[self.g0], self.level)?
                    .monitor_every(monitor_every as u64);
                if let Some(c) = &self.composition {
                    b = b.with_composition(c.clone())?;
                }
                b
            }
        };
        let b = slot.insert(b.monitor_every(monitor_every as u64).parallel(execution));
        b.run_to(end, steps as u64)?;
        b.summaries_into(|i| indices[i], out);
        Ok(())
    }
}

/// One chunk's work: its members' momenta and sweep indices, and where their summaries go.
struct Job<'a> {
    momenta: &'a [Vector3<f64>],
    indices: &'a [usize],
    out: &'a mut Vec<Summary<Vector3<f64>>>,
}

/// What a sweep's batched chunks reuse, one chunk after the other: the batch (its storage of a
/// chunk's lanes), the chunk's momenta and its summaries. Empty until the first chunk.
#[derive(Debug, Default)]
pub struct Scratch {
    strang: Option<Batch<Strang>>,
    rk4: Option<Batch<QuaternionRk4>>,
    rkmk4: Option<Batch<Rkmk4>>,
    exact: Option<Batch<ExactFlow>>,
    momenta: Vec<Vector3<f64>>,
    summaries: Vec<Summary<Vector3<f64>>>,
}

/// A plan's batch as the caller steps it, for runs that read the bodies between steps (the
/// many-body scenes of `crate::many_bodies`): the method's batch, with the plan's body, g₀,
/// composition and level.
#[derive(Debug, Clone)]
pub enum PlanBatch {
    /// The Strang splitting (under the plan's composition, if any).
    Strang(Batch<Strang>),
    /// Quaternion RK4.
    Rk4(Batch<QuaternionRk4>),
    /// RKMK4.
    Rkmk4(Batch<Rkmk4>),
    /// The exact free-body flow (boxed: the kernel carries the scalar flow's constants).
    Exact(Box<Batch<ExactFlow>>),
}

impl Plan {
    /// The bodies with momenta `momenta`, each from g₀, on the plan's level, run on `execution`
    /// (no monitoring: the caller reads the states).
    pub fn new_batch(
        &self,
        momenta: &[Vector3<f64>],
        execution: Execution,
    ) -> Result<PlanBatch, BatchError> {
        fn made<K: Kernel>(
            plan: &Plan,
            kernel: K,
            momenta: &[Vector3<f64>],
            execution: Execution,
        ) -> Result<Batch<K>, BatchError> {
            let mut b = Batch::new(kernel, momenta, &[plan.g0], plan.level)?.parallel(execution);
            if let Some(c) = &plan.composition {
                b = b.with_composition(c.clone())?;
            }
            Ok(b)
        }
        Ok(match self.kind {
            Batched::Strang => PlanBatch::Strang(made(
                self,
                Strang::new(self.body.clone()),
                momenta,
                execution,
            )?),
            Batched::Rk4 => PlanBatch::Rk4(made(
                self,
                QuaternionRk4::new(self.body.clone()),
                momenta,
                execution,
            )?),
            Batched::Rkmk4 => PlanBatch::Rkmk4(made(
                self,
                Rkmk4::new(self.body.clone()),
                momenta,
                execution,
            )?),
            Batched::Exact => PlanBatch::Exact(Box::new(made(
                self,
                ExactFlow::new(self.body.clone())?,
                momenta,
                execution,
            )?)),
        })
    }

    /// Starts `batch` (made by [`Plan::new_batch`]) over with the bodies `momenta` from g₀, its storage
    /// kept (`Batch::refill`).
    pub fn refill(
        &self,
        batch: &mut PlanBatch,
        momenta: &[Vector3<f64>],
    ) -> Result<(), BatchError> {
        match batch {
            PlanBatch::Strang(b) => b.refill(momenta, &[self.g0]),
            PlanBatch::Rk4(b) => b.refill(momenta, &[self.g0]),
            PlanBatch::Rkmk4(b) => b.refill(momenta, &[self.g0]),
            PlanBatch::Exact(b) => b.refill(momenta, &[self.g0]),
        }
    }
}

impl PlanBatch {
    /// `steps` steps of h for every running body (`Batch::run`).
    pub fn run(&mut self, h: f64, steps: u64) -> Result<(), BatchError> {
        match self {
            Self::Strang(b) => b.run(h, steps),
            Self::Rk4(b) => b.run(h, steps),
            Self::Rkmk4(b) => b.run(h, steps),
            Self::Exact(b) => b.run(h, steps),
        }
    }
    /// `steps` ≥ 1 steps of which the last lands on T = `end`: `steps − 1` of h, then one of
    /// T − t, t the batch's time before it — the last step a sweep's members take
    /// (`Batch::run_to`), after steps of the run's own h.
    pub fn run_landing(&mut self, h: f64, steps: u64, end: f64) -> Result<(), BatchError> {
        if steps > 1 {
            self.run(h, steps - 1)?;
        }
        let t = match self {
            Self::Strang(b) => b.time(),
            Self::Rk4(b) => b.time(),
            Self::Rkmk4(b) => b.time(),
            Self::Exact(b) => b.time(),
        };
        self.run(end - t, 1)
    }
    /// The number of bodies.
    pub fn len(&self) -> usize {
        match self {
            Self::Strang(b) => b.len(),
            Self::Rk4(b) => b.len(),
            Self::Rkmk4(b) => b.len(),
            Self::Exact(b) => b.len(),
        }
    }
    /// Always false (a batch has at least one body).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The published (Π, R) of body i, or `None` if it failed or never ran
    /// (`Batch::state`, `Batch::status`).
    pub fn running_state(&self, i: usize) -> Option<(Vector3<f64>, So3)> {
        let (status, state) = match self {
            Self::Strang(b) => (b.status(i), b.state(i)),
            Self::Rk4(b) => (b.status(i), b.state(i)),
            Self::Rkmk4(b) => (b.status(i), b.state(i)),
            Self::Exact(b) => (b.status(i), b.state(i)),
        };
        match status {
            Ok(batch::LaneStatus::Running) => state.ok(),
            _ => None,
        }
    }
}
