//! A batch of N independent bodies stepped together by one batched method.

use crate::engine::{self, book_index, group_len, Book, GroupFn, Kernel, Schedule, GROUP};
use crate::lanes::F;
use crate::{BatchError, Level};
use integrators::ensemble::{Execution, Status, Summary};
use integrators::{Clock, CompositionScheme};
use lie_groups::{LieGroup, So3};
use nalgebra::{Matrix3, Vector3};
use pulp::Simd;

/// How one body of a batch stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LaneStatus {
    /// Every step so far was taken.
    Running,
    /// Step `step` (0-based, counted over the batch's life) left the body non-finite; the body
    /// keeps the state before it and takes no further step.
    Failed {
        /// The step that failed.
        step: u64,
    },
    /// The initial state was not finite; the body never stepped.
    Invalid,
}

/// N bodies with one [`crate::BodyModel`], stepped by the batched method `K` ([`crate::Strang`],
/// [`crate::QuaternionRk4`]) on a [`Level`]: lanes = bodies, every lane the same arithmetic
/// whatever its position, the batch size, the level and the number of threads.
///
/// A body whose state is not finite at the start is [`LaneStatus::Invalid`]; one whose step goes
/// non-finite is [`LaneStatus::Failed`] and keeps its last finite state; the other bodies run on
/// as if it were not there. Energy and Casimir errors are monitored on request
/// ([`Batch::monitor_every`]) and reported per body by [`Batch::summaries`].
#[derive(Debug, Clone)]
pub struct Batch<K: Kernel> {
    kernel: K,
    level: Level,
    len: usize,
    groups: Vec<f64>,
    composition: Option<CompositionScheme>,
    inner_steps: u64,
    outer_steps: u64,
    /// The steps taken, summed on the scalar integrators' compensated clock (each lane's time
    /// while it runs).
    clock: Clock,
    monitor_every: Option<u64>,
    execution: Execution,
}

/// A row-major rotation matrix as its nine entries.
/// Checks a batch's bodies (some momenta; one attitude per body or one for all) and returns body
/// i's attitude rows.
fn bodies<'a>(
    momenta: &[Vector3<f64>],
    attitudes: &'a [So3],
) -> Result<impl Fn(usize) -> [f64; 9] + 'a, BatchError> {
    if momenta.is_empty() {
        return Err(BatchError::Empty { what: "momenta" });
    }
    if attitudes.len() != momenta.len() && attitudes.len() != 1 {
        return Err(BatchError::LengthMismatch {
            what: "attitudes",
            got: attitudes.len(),
            expected: momenta.len(),
        });
    }
    Ok(move |i: usize| rows(&attitudes[if attitudes.len() == 1 { 0 } else { i }]))
}

fn rows(r: &So3) -> [f64; 9] {
    let m = r.as_matrix();
    core::array::from_fn(|i| m[(i / 3, i % 3)])
}

impl<K: Kernel> Batch<K> {
    /// N bodies with momenta `momenta` and attitudes `attitudes` (one per body, or one for all),
    /// stepped by `kernel` on `level`.
    ///
    /// Errors: no body, `attitudes` of a length other than N or 1, a level the CPU lacks. A body
    /// with a non-finite Π or R is no error: it is [`LaneStatus::Invalid`].
    pub fn new(
        kernel: K,
        momenta: &[Vector3<f64>],
        attitudes: &[So3],
        level: Level,
    ) -> Result<Self, BatchError> {
        let r = bodies(momenta, attitudes)?;
        Self::build(kernel, momenta.len(), |i| (momenta[i].into(), r(i)), level)
    }

    /// Starts the batch over with the bodies `momenta`, `attitudes` (as [`Batch::new`]: one
    /// attitude per body or one for all), keeping its method, level, composition, monitoring
    /// and execution, and its storage: a caller that steps many batches one after the other
    /// (`lie-sim sweep`, a chunk at a time) allocates once instead of once a batch. The bodies
    /// then have the bits [`Batch::new`] would give them.
    ///
    /// Errors: as [`Batch::new`]; on an error the batch is left as it was.
    pub fn refill(
        &mut self,
        momenta: &[Vector3<f64>],
        attitudes: &[So3],
    ) -> Result<(), BatchError> {
        let r = bodies(momenta, attitudes)?;
        fill(&self.kernel, &mut self.groups, momenta.len(), |i| {
            (momenta[i].into(), r(i))
        })?;
        self.len = momenta.len();
        self.inner_steps = 0;
        self.outer_steps = 0;
        self.clock = Clock::at(0.0);
        Ok(())
    }

    /// N bodies from structure-of-arrays input: `pi[c][i]` is Πc of body i and `r[e][i]` entry e
    /// (row-major) of its attitude. Errors: no body, arrays of different lengths, a level the CPU
    /// lacks.
    pub fn from_soa(
        kernel: K,
        pi: [&[f64]; 3],
        r: [&[f64]; 9],
        level: Level,
    ) -> Result<Self, BatchError> {
        let n = pi[0].len();
        if n == 0 {
            return Err(BatchError::Empty { what: "Π₀" });
        }
        const PI: [&str; 3] = ["Π₁", "Π₂", "Π₃"];
        const R: [&str; 9] = [
            "R₁₁", "R₁₂", "R₁₃", "R₂₁", "R₂₂", "R₂₃", "R₃₁", "R₃₂", "R₃₃",
        ];
        for (what, a) in PI.iter().zip(&pi).chain(R.iter().zip(&r)) {
            if a.len() != n {
                return Err(BatchError::LengthMismatch {
                    what,
                    got: a.len(),
                    expected: n,
                });
            }
        }
        Self::build(kernel, n, |i| (pi.map(|a| a[i]), r.map(|a| a[i])), level)
    }

    fn build(
        kernel: K,
        len: usize,
        lane: impl Fn(usize) -> ([f64; 3], [f64; 9]),
        level: Level,
    ) -> Result<Self, BatchError> {
        level.check()?;
        let mut groups = Vec::new();
        fill(&kernel, &mut groups, len, lane)?;
        Ok(Self {
            kernel,
            level,
            len,
            groups,
            composition: None,
            inner_steps: 0,
            outer_steps: 0,
            clock: Clock::at(0.0),
            monitor_every: None,
            execution: Execution::Sequential,
        })
    }

    /// Each step becomes the composition `Ψ_{γ_s h} ∘ … ∘ Ψ_{γ₁h}` of the method (as
    /// `integrators::Composition`: order 4 to 10 from the symmetric order-2 splitting; the
    /// merged closing and opening flows run across the sub-steps as in the scalar composition).
    /// Errors: a method that is not symmetric.
    pub fn with_composition(mut self, scheme: CompositionScheme) -> Result<Self, BatchError> {
        if !self.kernel.symmetric() {
            return Err(BatchError::Unsupported {
                reason: format!(
                    "composition {} needs a symmetric method, {} is not",
                    scheme.name(),
                    self.kernel.name()
                ),
            });
        }
        self.composition = Some(scheme);
        Ok(self)
    }
    /// Monitors energy and Casimir after every `every` steps (counted from the first; and the
    /// state read by [`Batch::summaries`]). 0 turns monitoring off (the default).
    pub fn monitor_every(mut self, every: u64) -> Self {
        self.monitor_every = (every > 0).then_some(every);
        self
    }
    /// Runs the blocks of lanes on the current rayon pool (the same bits as sequentially).
    pub fn parallel(mut self, execution: Execution) -> Self {
        self.execution = execution;
        self
    }

    /// The number of bodies N.
    pub fn len(&self) -> usize {
        self.len
    }
    /// Always false (a batch has at least one body).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// The level the batch runs on.
    pub fn level(&self) -> Level {
        self.level
    }
    /// The method.
    pub fn kernel(&self) -> &K {
        &self.kernel
    }
    /// Steps taken (by the bodies that did not fail).
    pub fn steps(&self) -> u64 {
        self.outer_steps
    }
    /// The time of the running bodies: the steps summed as the scalar integrators sum them
    /// ([`integrators::Clock`]: n steps of h end at the correctly rounded n·h).
    pub fn time(&self) -> f64 {
        self.clock.now()
    }

    /// One step of size h for every running body.
    pub fn step(&mut self, h: f64) -> Result<(), BatchError> {
        self.run(h, 1)
    }

    /// `steps` steps of size h for every running body (h finite and non-zero).
    pub fn run(&mut self, h: f64, steps: u64) -> Result<(), BatchError> {
        if !h.is_finite() || h == 0.0 {
            return Err(BatchError::InvalidParameter {
                reason: format!("step h = {h} must be finite and non-zero"),
            });
        }
        let subs: Vec<f64> = match &self.composition {
            Some(c) => c.gammas().iter().map(|&g| g * h).collect(),
            None => vec![h],
        };
        let schedule = Schedule {
            subs: &subs,
            h,
            steps,
            inner_before: self.inner_steps,
            monitor_every: self.monitor_every,
            outer_before: self.outer_steps,
            clock_before: self.clock,
        };
        self.kernel
            .run_schedule(self.level, &mut self.groups, &schedule, self.execution)?;
        self.outer_steps += steps;
        self.inner_steps += steps * subs.len() as u64;
        for _ in 0..steps {
            self.clock.advance(h);
        }
        Ok(())
    }

    /// `steps` = n ≥ 1 steps from the batch's time t₀ to the end time T: n − 1 steps of
    /// h = (T − t₀)/n, then one of T − t, t the time before it, so that the batch lands on T —
    /// the steps `integrators::ensemble::Ensemble` takes for each of its members, so that a
    /// batched sweep and the scalar one end at the same T by the same last step.
    pub fn run_to(&mut self, end: f64, steps: u64) -> Result<(), BatchError> {
        if !end.is_finite() || steps == 0 {
            return Err(BatchError::InvalidParameter {
                reason: format!(
                    "run to T = {end} in {steps} steps: T must be finite and the steps at least one"
                ),
            });
        }
        let h = (end - self.time()) / steps as f64;
        if steps > 1 {
            self.run(h, steps - 1)?;
        }
        // As the ensemble's last step: T − t exact where T/2 ≤ t ≤ 2T (Sterbenz), added to the
        // clock's t and its carried error (below half an ulp of t), rounds to T.
        self.run(end - self.time(), 1)
    }

    /// The stored group and lane of body i (< N).
    fn lane(&self, i: usize) -> Result<(&[f64], usize), BatchError> {
        if i >= self.len {
            return Err(BatchError::InvalidParameter {
                reason: format!("body {i} of a batch of {}", self.len),
            });
        }
        let glen = group_len::<K>();
        Ok((&self.groups[(i / GROUP) * glen..][..glen], i % GROUP))
    }

    /// The published state (Π, R) of body i, computed by the same lane arithmetic as the vectors
    /// (one scalar lane).
    pub fn state(&self, i: usize) -> Result<(Vector3<f64>, So3), BatchError> {
        let (group, l) = self.lane(i)?;
        Ok(published(&self.kernel, group, l))
    }
    /// The published momentum Π of body i.
    pub fn momentum(&self, i: usize) -> Result<Vector3<f64>, BatchError> {
        Ok(self.state(i)?.0)
    }
    /// The published momenta of every body, in order.
    pub fn momenta(&self) -> Vec<Vector3<f64>> {
        self.lanes()
            .map(|(g, l)| published(&self.kernel, g, l).0)
            .collect()
    }
    /// How body i stands.
    pub fn status(&self, i: usize) -> Result<LaneStatus, BatchError> {
        let (group, l) = self.lane(i)?;
        Ok(lane_status::<K>(group, l))
    }
    /// How every body stands, in order.
    pub fn statuses(&self) -> Vec<LaneStatus> {
        self.lanes().map(|(g, l)| lane_status::<K>(g, l)).collect()
    }
    /// (group, lane) of every body, in order.
    fn lanes(&self) -> impl Iterator<Item = (&[f64], usize)> {
        self.groups
            .chunks_exact(group_len::<K>())
            .flat_map(|g| (0..GROUP).map(move |l| (g, l)))
            .take(self.len)
    }

    /// One [`Summary`] per body, in order, as `integrators::ensemble::Ensemble` writes it for the
    /// scalar method: steps taken, time, final momentum, initial energy, and the largest energy
    /// and Casimir errors over the monitored states and the current one (which this folds into
    /// the maxima). `index` numbers the bodies (the ensemble passes their sweep indices).
    pub fn summaries(&mut self, index: impl Fn(usize) -> usize) -> Vec<Summary<Vector3<f64>>> {
        let mut out = Vec::with_capacity(self.len);
        self.summaries_into(index, &mut out);
        out
    }

    /// [`Batch::summaries`] into `out` (cleared first, its allocation kept): a caller stepping
    /// batch after batch reuses one vector.
    pub fn summaries_into(
        &mut self,
        index: impl Fn(usize) -> usize,
        out: &mut Vec<Summary<Vector3<f64>>>,
    ) {
        struct Fold;
        impl<K: Kernel> GroupFn<K> for Fold {
            #[inline(always)]
            fn apply<S: Simd>(&self, s: S, kernel: &K, group: &mut [f64], off: usize) {
                let st = kernel.load(s, group, off);
                let alive = F::load(s, &group[book_index::<K>(Book::Alive, off)..]);
                let valid = alive.lt(F::splat(s, -0.5)).not();
                engine::monitor_lanes(s, kernel, &st, valid, group, off);
            }
        }
        // Cannot fail: the level was checked when the batch was built.
        let _ = engine::for_each_vector(self.level, &self.kernel, &mut self.groups, Fold);
        out.clear();
        out.extend(self.lanes().enumerate().map(|(i, (group, l))| {
            let book = |b: Book| group[book_index::<K>(b, l)];
            let status = match lane_status::<K>(group, l) {
                LaneStatus::Running => Status::Completed,
                LaneStatus::Failed { step } => Status::StepFailed {
                    step: step as usize,
                    error: self.kernel.step_error(),
                },
                LaneStatus::Invalid => Status::BuildFailed(self.kernel.build_error()),
            };
            let built = !matches!(status, Status::BuildFailed(_));
            let (steps, time) = match status {
                Status::Completed => (self.outer_steps as usize, self.clock.now()),
                _ => (book(Book::Taken) as usize, book(Book::Time)),
            };
            Summary {
                index: index(i),
                status,
                steps,
                time,
                momentum: built.then(|| published(&self.kernel, group, l).0),
                initial_energy: if built { book(Book::E0) } else { f64::NAN },
                max_energy_error: book(Book::De),
                max_casimir_error: (built && self.kernel.has_casimir()).then(|| book(Book::Dc)),
            }
        }));
    }
}

/// Lays out `len` bodies (`lane(i)`: Π and row-major R of body i) in `groups`, its old contents
/// overwritten and its allocation kept where it is large enough: each lane's state, its status
/// and the energy and Casimir of its initial state; the padding of the last group is the benign
/// body at rest. `groups` is left as it was on an error.
fn fill<K: Kernel>(
    kernel: &K,
    groups: &mut Vec<f64>,
    len: usize,
    lane: impl Fn(usize) -> ([f64; 3], [f64; 9]),
) -> Result<(), BatchError> {
    let glen = group_len::<K>();
    let ngroups = len.div_ceil(GROUP);
    let identity = rows(&So3::identity());
    let benign =
        kernel
            .init_lane([0.0; 3], identity)
            .ok_or_else(|| BatchError::InvalidParameter {
                reason: "the method refuses the body at rest".into(),
            })?;
    groups.clear();
    groups.resize(ngroups * glen, 0.0);
    for i in 0..ngroups * GROUP {
        let (g, l) = (i / GROUP, i % GROUP);
        let group = &mut groups[g * glen..(g + 1) * glen];
        let state = (i < len).then(|| lane(i));
        let init = state.and_then(|(pi, r)| kernel.init_lane(pi, r));
        let alive = match (&state, &init) {
            (Some(_), Some(_)) => 1.0,
            _ => -1.0,
        };
        for (c, x) in init.as_ref().unwrap_or(&benign).iter().enumerate() {
            group[c * GROUP + l] = *x;
        }
        group[book_index::<K>(Book::Alive, l)] = alive;
        if let (Some((pi, r)), Some(_)) = (state, &init) {
            let (e0, c0) = kernel.initial_observation(pi, r);
            group[book_index::<K>(Book::E0, l)] = e0;
            group[book_index::<K>(Book::C0, l)] = c0.unwrap_or(f64::NAN);
        }
    }
    Ok(())
}

/// The published (Π, R) of lane l of a group, on one scalar lane.
fn published<K: Kernel>(kernel: &K, group: &[f64], l: usize) -> (Vector3<f64>, So3) {
    let st = kernel.load(pulp::Scalar, group, l);
    let (pi, r) = kernel.published(&st);
    let m = Matrix3::from_row_slice(&r.map(|x| x.v));
    (
        Vector3::new(pi[0].v, pi[1].v, pi[2].v),
        So3::from_matrix_unchecked(&m),
    )
}

/// The status of lane l of a group.
fn lane_status<K: Kernel>(group: &[f64], l: usize) -> LaneStatus {
    let alive = group[book_index::<K>(Book::Alive, l)];
    if alive == 1.0 {
        LaneStatus::Running
    } else if alive == 0.0 {
        LaneStatus::Failed {
            step: group[book_index::<K>(Book::Taken, l)] as u64,
        }
    } else {
        LaneStatus::Invalid
    }
}
