//! The machinery shared by the batched methods: lanes stored in groups of eight (structure of
//! arrays within a group), the step loop with each lane's failure and monitoring, sequential or
//! on the rayon pool, on any [`Level`].
//!
//! **Layout.** A lane's state is `K::COMPONENTS` doubles, followed by the bookkeeping of
//! [`Book`]; the batch stores `⌈N/8⌉` groups, each `(COMPONENTS + BOOK) × 8` doubles with
//! component c of lane l of the group at `c·8 + l`. Eight is the widest vector (AVX-512), so a
//! group is one vector there, two on AVX2 and eight scalar lanes on the scalar level; the last
//! group is padded with a benign body (Π = 0, R = I), whose results are never read. A remainder
//! is therefore no separate code path: every lane, padding included, is the same kernel.
//!
//! **Order of work.** Groups are dealt out in blocks of [`BLOCK_GROUPS`] (128 lanes); within a
//! block each vector of lanes takes all the steps of the call in a row, its state loaded once
//! before them and stored once after them (a failure and the monitoring write only the
//! bookkeeping), so that no step pays for moving the state through memory; blocks run one after
//! the other or on the rayon pool. None of this changes a lane's arithmetic.

use crate::lanes::{load_n, store_n, F, M};
use crate::{BatchError, Level};
use integrators::ensemble::Execution;
use integrators::Clock;
use pulp::{Simd, WithSimd};
use rayon::prelude::*;

/// Lanes per group: the widest vector.
pub(crate) const GROUP: usize = 8;
/// Groups per block of work.
pub(crate) const BLOCK_GROUPS: usize = 16;

/// The bookkeeping components of a lane, after its state.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Book {
    /// 1 while the lane steps, 0 after a failed step, −1 for a lane refused at build.
    Alive = 0,
    /// Steps taken successfully, once the lane failed (a running lane has taken the batch's).
    Taken,
    /// The lane's time once it failed (a running lane's is the batch's).
    Time,
    /// Energy and Casimir of the initial state.
    E0,
    C0,
    /// Max |E − E₀| and |C − C₀| over the monitored states.
    De,
    Dc,
}
/// The number of bookkeeping components.
pub(crate) const BOOK: usize = 7;

/// A batched method: the arithmetic of one step on a vector of lanes, and its state's layout.
/// Every function is applied lane-wise (no lane reads another).
pub trait Kernel: Sync + Send + Clone {
    /// Doubles of state per lane.
    const COMPONENTS: usize;
    /// The state of one vector of lanes, in registers.
    type State<S: Simd>: Copy;
    /// The method's name (as the scalar library names it).
    fn name(&self) -> String;
    /// A lane's stored state from its published momentum Π and attitude R (row-major); `None`
    /// when the values cannot start a trajectory.
    fn init_lane(&self, pi: [f64; 3], r: [f64; 9]) -> Option<Vec<f64>>;
    /// The state of the lanes `off..off + S::F64_LANES` of a group.
    fn load<S: Simd>(&self, s: S, group: &[f64], off: usize) -> Self::State<S>;
    /// Writes the state back.
    fn store<S: Simd>(&self, st: &Self::State<S>, group: &mut [f64], off: usize);
    /// One step of size h in place; `renormalize` on the steps where the attitude is brought
    /// back onto SO(3). `group` and `off` are the lanes' stored components as [`Kernel::load`]
    /// read them (the stored state there may be older than `st`; what a step never changes is
    /// as loaded): a kernel with many constants per lane reads them there, where it uses them,
    /// instead of carrying a copy in its state.
    fn step<S: Simd>(
        &self,
        st: &mut Self::State<S>,
        group: &[f64],
        off: usize,
        h: f64,
        renormalize: bool,
    );
    /// `if m { a } else { b }` lane by lane.
    fn select<S: Simd>(m: M<S>, a: &Self::State<S>, b: &Self::State<S>) -> Self::State<S>;
    /// Lanes whose state is finite.
    fn finite<S: Simd>(&self, st: &Self::State<S>) -> M<S>;
    /// Whether a lane whose state is not finite after a step is not finite after any later
    /// step either, whatever the step sizes (a non-finite entry stays, or spreads, and never
    /// rounds back to a finite one). The step loop then checks the lanes once per call instead
    /// of after every step (the engine's page, *Failures*). False unless the kernel proves it.
    const NON_FINITE_PERSISTS: bool = false;
    /// The published momentum Π and attitude R (row-major) of the state.
    fn published<S: Simd>(&self, st: &Self::State<S>) -> ([F<S>; 3], [F<S>; 9]);
    /// The energy and, where the system has one, the Casimir |Π|² of the published state.
    fn observe<S: Simd>(&self, st: &Self::State<S>) -> (F<S>, Option<F<S>>);
    /// Whether the system has a Casimir.
    fn has_casimir(&self) -> bool;
    /// Whether the method is symmetric (Ψ_{−h} = Ψ_h⁻¹), so that compositions raise its order.
    fn symmetric(&self) -> bool;
    /// The energy and Casimir of a lane's initial state, as the scalar method reads them before
    /// its first step (by default the published state of [`Kernel::init_lane`], on one lane).
    fn initial_observation(&self, pi: [f64; 3], r: [f64; 9]) -> (f64, Option<f64>) {
        let Some(v) = self.init_lane(pi, r) else {
            return (f64::NAN, None);
        };
        let mut group = vec![0.0; Self::COMPONENTS * GROUP];
        for (c, x) in v.iter().enumerate() {
            group[c * GROUP] = *x;
        }
        let st = self.load(pulp::Scalar, &group, 0);
        let (e, c) = self.observe(&st);
        (e.v, c.map(|c| c.v))
    }
    /// Whether the attitude is renormalized every [`crate::RENORMALIZE_EVERY`] steps (the
    /// splittings), or kept on the group by the method itself (a unit quaternion).
    fn renormalizes(&self) -> bool;
    /// The steps between renormalizations when [`Kernel::renormalizes`]: the scalar method's
    /// cadence (by default the splittings' [`crate::RENORMALIZE_EVERY`]).
    fn renormalize_every(&self) -> u64 {
        crate::RENORMALIZE_EVERY as u64
    }
    /// Runs the step loop of `schedule` over `groups` (the engine's `run`); a method with
    /// variants (axes, a field) picks the one with its constants fixed here, once per run.
    fn run_schedule(
        &self,
        level: Level,
        groups: &mut [f64],
        schedule: &Schedule<'_>,
        execution: Execution,
    ) -> Result<(), BatchError> {
        run(level, self, groups, schedule, execution)
    }
    /// The scalar library's error for a lane refused at build, and for a failed step.
    fn build_error(&self) -> integrators::IntegratorError;
    /// See [`Kernel::build_error`].
    fn step_error(&self) -> integrators::IntegratorError;
}

/// The layout of a batch's storage for kernel `K`.
pub(crate) fn group_len<K: Kernel>() -> usize {
    (K::COMPONENTS + BOOK) * GROUP
}

/// Index of bookkeeping component `b` of lane `l` in a group of kernel `K`.
pub(crate) fn book_index<K: Kernel>(b: Book, l: usize) -> usize {
    (K::COMPONENTS + b as usize) * GROUP + l
}

/// What one call of the step loop does.
#[derive(Debug, Clone)]
pub struct Schedule<'a> {
    /// The sub-steps of one step (a composition's γᵢh; `[h]` otherwise).
    pub subs: &'a [f64],
    /// The outer step h (added to each lane's time).
    pub h: f64,
    /// Steps to take.
    pub steps: u64,
    /// Inner steps taken before this call (the renormalization cadence runs over inner steps).
    pub inner_before: u64,
    /// Monitor energy and Casimir after every this many steps (counted from the first step of
    /// the batch: `outer_before`).
    pub monitor_every: Option<u64>,
    /// Outer steps taken before this call.
    pub outer_before: u64,
    /// The clock before this call.
    pub clock_before: Clock,
}

/// Runs `schedule` on one block of groups: each vector of lanes in one pass without a
/// finiteness check per step where the kernel allows it ([`Kernel::NON_FINITE_PERSISTS`]) and
/// no running lane failed, else in the checked pass.
#[inline(always)]
fn run_block<S: Simd, K: Kernel>(s: S, kernel: &K, block: &mut [f64], sch: &Schedule<'_>) {
    let w = S::F64_LANES;
    let glen = group_len::<K>();
    for group in block.chunks_exact_mut(glen) {
        for off in (0..GROUP).step_by(w) {
            if !(K::NON_FINITE_PERSISTS && run_unchecked(s, kernel, group, off, sch)) {
                run_checked(s, kernel, group, off, sch);
            }
        }
    }
}

/// The steps of `sch` on one vector of lanes, sub-step by sub-step.
#[inline(always)]
fn step_all_subs<S: Simd, K: Kernel>(
    kernel: &K,
    st: &mut K::State<S>,
    group: &[f64],
    off: usize,
    sch: &Schedule<'_>,
    k: u64,
) {
    let inner0 = sch.inner_before + k * sch.subs.len() as u64;
    let every = kernel.renormalize_every();
    let renorms = kernel.renormalizes();
    if let [h] = sch.subs {
        // One sub-step (no composition): straight-line code.
        let renorm = renorms && (inner0 + 1).is_multiple_of(every);
        kernel.step(st, group, off, *h, renorm);
    } else {
        for (j, &hs) in sch.subs.iter().enumerate() {
            let renorm = renorms && (inner0 + j as u64 + 1).is_multiple_of(every);
            kernel.step(st, group, off, hs, renorm);
        }
    }
}

/// Whether step `k` of the call is monitored.
#[inline(always)]
fn monitored(sch: &Schedule<'_>, k: u64) -> bool {
    let outer = sch.outer_before + k + 1;
    sch.monitor_every.is_some_and(|m| outer.is_multiple_of(m))
}

/// The steps of `sch` on one vector of lanes with one finiteness check after the last: a lane
/// whose state turned non-finite at some step is still non-finite there
/// ([`Kernel::NON_FINITE_PERSISTS`]). Stopped lanes step along and take back their stored state
/// at the end. When every running lane is finite at the end, stores the state and returns true:
/// no running lane failed at any step, so each step's result is what [`run_checked`] computes
/// (the same arithmetic, no blend). Otherwise leaves the group as it was (the state is stored
/// only here, the monitor's maxima are put back) and returns false, for [`run_checked`] to run
/// the call again and find the step where each lane failed.
#[inline(always)]
fn run_unchecked<S: Simd, K: Kernel>(
    s: S,
    kernel: &K,
    group: &mut [f64],
    off: usize,
    sch: &Schedule<'_>,
) -> bool {
    let c = K::COMPONENTS;
    let alive = F::load(s, &group[(c + Book::Alive as usize) * GROUP + off..]).eq(F::splat(s, 1.0));
    let all = !alive.not().any();
    let maxima: [F<S>; 2] = load_n(s, group, c + Book::De as usize, off);
    let mut st = kernel.load(s, group, off);
    for k in 0..sch.steps {
        step_all_subs(kernel, &mut st, group, off, sch, k);
        if monitored(sch, k) {
            if all {
                monitor_all(s, kernel, &st, group, off);
            } else {
                monitor_lanes(s, kernel, &st, alive, group, off);
            }
        }
    }
    let failed = alive.and(kernel.finite(&st).not());
    if failed.any() {
        store_n(&maxima, group, c + Book::De as usize, off);
        return false;
    }
    if !all {
        st = K::select(alive, &st, &kernel.load(s, group, off));
    }
    kernel.store(&st, group, off);
    true
}

/// The steps of `sch` on one vector of lanes, each lane checked after every step: a lane that
/// turns non-finite keeps its last finite state and records the step and time of its failure.
#[inline(always)]
fn run_checked<S: Simd, K: Kernel>(
    s: S,
    kernel: &K,
    group: &mut [f64],
    off: usize,
    sch: &Schedule<'_>,
) {
    let c = K::COMPONENTS;
    let one = F::splat(s, 1.0);
    // The time before each step, on the scalar integrators' clock.
    let mut clock = sch.clock_before;
    let mut st = kernel.load(s, group, off);
    for k in 0..sch.steps {
        let alive = F::load(s, &group[(c + Book::Alive as usize) * GROUP + off..]).eq(one);
        let mut new = st;
        step_all_subs(kernel, &mut new, group, off, sch, k);
        let ok = kernel.finite(&new).and(alive);
        // Every lane stepped (the usual case): the new state as it is, without the
        // blend that keeps a failed or stopped lane's old state; the same bits.
        let all = !ok.not().any();
        if !all {
            new = K::select(ok, &new, &st);
        }
        st = new;
        if !all {
            let failed = alive.and(ok.not());
            if failed.any() {
                record_failure(s, failed, group, c, off, sch.outer_before + k, clock.now());
            }
        }
        if monitored(sch, k) {
            if all {
                monitor_all(s, kernel, &st, group, off);
            } else {
                monitor_lanes(s, kernel, &st, ok, group, off);
            }
        }
        clock.advance(sch.h);
    }
    kernel.store(&st, group, off);
}

#[cold]
#[inline(never)]
fn record_failure<S: Simd>(
    s: S,
    failed: M<S>,
    group: &mut [f64],
    components: usize,
    off: usize,
    step: u64,
    time: f64,
) {
    let w = S::F64_LANES;
    let at = |b: Book| (components + b as usize) * GROUP;
    for (b, v) in [
        (Book::Alive, 0.0),
        (Book::Taken, step as f64),
        (Book::Time, time),
    ] {
        let i = at(b) + off;
        let old = F::load(s, &group[i..]);
        failed
            .select(F::splat(s, v), old)
            .store(&mut group[i..i + w]);
    }
}

/// Folds the published state's energy and Casimir errors into the lanes of `mask`.
#[inline(always)]
pub(crate) fn monitor_lanes<S: Simd, K: Kernel>(
    s: S,
    kernel: &K,
    st: &K::State<S>,
    mask: M<S>,
    group: &mut [f64],
    off: usize,
) {
    let c = K::COMPONENTS;
    let (e, cas) = kernel.observe(st);
    let [e0, _c0, de, dc] = load_n(s, group, c + Book::E0 as usize, off);
    let mut out = [de, dc];
    out[0] = mask.select(de.max((e - e0).abs()), de);
    if let Some(cas) = cas {
        let [c0] = load_n(s, group, c + Book::C0 as usize, off);
        out[1] = mask.select(dc.max((cas - c0).abs()), dc);
    }
    store_n(&out, group, c + Book::De as usize, off);
}

/// [`monitor_lanes`] on every lane of the vector (no blend: the same bits as an all-true mask).
#[inline(always)]
fn monitor_all<S: Simd, K: Kernel>(
    s: S,
    kernel: &K,
    st: &K::State<S>,
    group: &mut [f64],
    off: usize,
) {
    let c = K::COMPONENTS;
    let (e, cas) = kernel.observe(st);
    let [e0, _c0, de, dc] = load_n(s, group, c + Book::E0 as usize, off);
    let mut out = [de.max((e - e0).abs()), dc];
    if let Some(cas) = cas {
        let [c0] = load_n(s, group, c + Book::C0 as usize, off);
        out[1] = dc.max((cas - c0).abs());
    }
    store_n(&out, group, c + Book::De as usize, off);
}

/// The step loop over all groups, on `level`, sequentially or on the rayon pool.
pub(crate) fn run<K: Kernel>(
    level: Level,
    kernel: &K,
    groups: &mut [f64],
    schedule: &Schedule<'_>,
    execution: Execution,
) -> Result<(), BatchError> {
    struct Op<'a, 'b, K: Kernel> {
        kernel: &'a K,
        block: &'a mut [f64],
        schedule: &'a Schedule<'b>,
    }
    impl<K: Kernel> WithSimd for Op<'_, '_, K> {
        type Output = ();
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) {
            run_block(s, self.kernel, self.block, self.schedule)
        }
    }
    let block_len = BLOCK_GROUPS * group_len::<K>();
    let one = |block: &mut [f64]| {
        level.dispatch(Op {
            kernel,
            block,
            schedule,
        })
    };
    match execution {
        Execution::Sequential => groups.chunks_mut(block_len).try_for_each(one),
        Execution::Parallel => groups.par_chunks_mut(block_len).try_for_each(one),
    }
}

/// Applies `f` to every group on `level` (not in the hot loop: reads, the initial monitor).
pub(crate) fn for_each_vector<K: Kernel>(
    level: Level,
    kernel: &K,
    groups: &mut [f64],
    f: impl GroupFn<K>,
) -> Result<(), BatchError> {
    struct Op<'a, K: Kernel, G: GroupFn<K>> {
        kernel: &'a K,
        groups: &'a mut [f64],
        f: G,
    }
    impl<K: Kernel, G: GroupFn<K>> WithSimd for Op<'_, K, G> {
        type Output = ();
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) {
            for group in self.groups.chunks_exact_mut(group_len::<K>()) {
                for off in (0..GROUP).step_by(S::F64_LANES) {
                    self.f.apply(s, self.kernel, group, off);
                }
            }
        }
    }
    level.dispatch(Op { kernel, groups, f })
}

/// A function of one vector of lanes of a group (a generic closure).
pub(crate) trait GroupFn<K: Kernel> {
    fn apply<S: Simd>(&self, s: S, kernel: &K, group: &mut [f64], off: usize);
}
