//! Ensembles: many trajectories (initial conditions, or parameter sets) integrated at once, on
//! every core through rayon, with results bit-identical to the sequential run.
//!
//! An [`Ensemble`] is a sweep: a `Vec` of members `P` (an initial momentum μ₀, a parameter set, …)
//! whose position is the member's **index**, an end time T and a step count n (n steps from the
//! member's t₀, the last one landing on T). A builder closure
//! `(index, &P) → integrator` turns a member into any [`Integrator`]; each trajectory is integrated
//! on its own and reduced to a [`Summary`] (index, final μ, max energy and Casimir errors, status).
//!
//! **Determinism.** Trajectories share nothing, and each one is a fixed sequence of floating-point
//! operations, so a trajectory's summary does not depend on the thread that computed it, on the
//! number of threads, or on the shard it belongs to. Rayon's indexed `collect` keeps the index
//! order. Hence `run_parallel == run_sequential` exactly (test `parallel_run_is_bit_identical_…`).
//!
//! **Sharding** (scaling beyond one machine). A [`Shard`] `i/n` selects a subset of the indices —
//! contiguous blocks or a stride — so that the n shards partition 0..N. Shards can run on different
//! machines; [`merge_shards`] puts their summaries back in index order and checks that every index
//! appears exactly once, giving exactly the full run (test `merged_shards_equal_the_full_run`).
//! Initial conditions drawn with [`sphere_point`] depend only on (seed, index), so a shard can
//! generate its own members without the others.
//!
//! ```
//! use integrators::ensemble::{momenta_on_sphere, merge_shards, Ensemble, Execution, Shard};
//! use integrators::{LiePoisson};
//! use mechanics::RigidBody;
//! use lie_groups::{Cayley, So3};
//! use nalgebra::Vector3;
//!
//! let body = RigidBody::principal([1.0, 2.0, 3.0])?;
//! let mu0: Vec<Vector3<f64>> = momenta_on_sphere(3, 1.0, 8, 42)?;
//! let sweep = Ensemble::new(mu0, 1.0, 100)?;
//! let build = |_i: usize, mu: &Vector3<f64>| {
//!     LiePoisson::<So3, Cayley, _>::new(body.clone(), 0.5, *mu, None)
//! };
//! let full = sweep.run_parallel(&build);
//! assert!(full.iter().all(|s| s.status.is_completed() && s.time == 1.0));
//! assert!(full.iter().all(|s| s.max_casimir_error.unwrap() < 1e-14));
//! // Two shards, run separately (e.g. on two machines), merged back.
//! let parts = (0..2).map(|i| sweep.run_shard(Shard::new(i, 2).unwrap(), Execution::Sequential, &build));
//! assert_eq!(merge_shards(parts, sweep.len())?, full);
//! # Ok::<(), integrators::IntegratorError>(())
//! ```

use crate::{Integrator, IntegratorError, System};
use core::fmt;
use core::str::FromStr;
use lie_groups::{LieGroup, Vector};
use rayon::prelude::*;

/// How the indices 0..N of a sweep are dealt to the n shards.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ShardLayout {
    /// Shard i gets the block `⌊iN/n⌋ .. ⌊(i+1)N/n⌋` (sizes differ by at most one).
    Contiguous,
    /// Shard i gets `i, i + n, i + 2n, …` (balances sweeps whose cost grows with the index).
    Strided,
}

/// Shard `index` of `count` (0-based: `0 ≤ index < count`), written `i/n`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Shard {
    index: usize,
    count: usize,
    layout: ShardLayout,
}

impl Shard {
    /// The contiguous shard `index/count`. Errors unless `index < count`.
    pub fn new(index: usize, count: usize) -> Result<Self, IntegratorError> {
        Self::with_layout(index, count, ShardLayout::Contiguous)
    }
    /// The strided shard `index/count`. Errors unless `index < count`.
    pub fn strided(index: usize, count: usize) -> Result<Self, IntegratorError> {
        Self::with_layout(index, count, ShardLayout::Strided)
    }
    /// Shard `index/count` with the given layout. Errors unless `index < count`.
    pub fn with_layout(
        index: usize,
        count: usize,
        layout: ShardLayout,
    ) -> Result<Self, IntegratorError> {
        if index >= count {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("shard {index}/{count}: need 0 ≤ i < n"),
            });
        }
        Ok(Self {
            index,
            count,
            layout,
        })
    }
    /// The whole sweep, `0/1`.
    pub fn all() -> Self {
        Self {
            index: 0,
            count: 1,
            layout: ShardLayout::Contiguous,
        }
    }
    /// i.
    pub fn index(&self) -> usize {
        self.index
    }
    /// n.
    pub fn count(&self) -> usize {
        self.count
    }
    /// The layout.
    pub fn layout(&self) -> ShardLayout {
        self.layout
    }
    /// The indices of a sweep of `len` members that belong to this shard, increasing.
    pub fn indices(&self, len: usize) -> Vec<usize> {
        self.iter(len).collect()
    }
    /// The indices of [`Shard::indices`], one at a time (a sweep that goes through its members in
    /// chunks holds none of them in memory).
    pub fn iter(&self, len: usize) -> core::iter::StepBy<core::ops::Range<usize>> {
        match self.layout {
            ShardLayout::Contiguous => {
                // u128 so that i·N cannot overflow for any usize N.
                let bound = |i: usize| (i as u128 * len as u128 / self.count as u128) as usize;
                (bound(self.index)..bound(self.index + 1)).step_by(1)
            }
            ShardLayout::Strided => (self.index..len).step_by(self.count),
        }
    }
}

impl fmt::Display for Shard {
    /// `i/n`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = IntegratorError;
    /// Parses `i/n` (0-based, contiguous layout), as given to a `--shard i/n` option.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let bad = || IntegratorError::InvalidParameter {
            reason: format!("shard {s:?} is not of the form i/n with 0 ≤ i < n"),
        };
        let (i, n) = s.split_once('/').ok_or_else(bad)?;
        let i = i.trim().parse().map_err(|_| bad())?;
        let n = n.trim().parse().map_err(|_| bad())?;
        Self::new(i, n).map_err(|_| bad())
    }
}

/// Sequential or parallel (rayon, on the current thread pool) execution. Both give the same bits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Execution {
    /// One trajectory after the other on the calling thread.
    Sequential,
    /// Trajectories spread over the threads of the current rayon pool (`ThreadPool::install` to
    /// choose one).
    Parallel,
}

/// How a trajectory ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Status {
    /// All steps taken.
    Completed,
    /// Step number `step` (0-based) failed; the summary describes the state before it.
    StepFailed {
        /// The step that failed.
        step: usize,
        /// Its error.
        error: IntegratorError,
    },
    /// The builder refused the member (bad initial condition or parameter).
    BuildFailed(IntegratorError),
}

impl Status {
    /// Whether all steps were taken.
    pub fn is_completed(&self) -> bool {
        matches!(self, Status::Completed)
    }
    /// A one-word label for tables: `completed`, `step-failed`, `build-failed`.
    pub fn label(&self) -> &'static str {
        match self {
            Status::Completed => "completed",
            Status::StepFailed { .. } => "step-failed",
            Status::BuildFailed(_) => "build-failed",
        }
    }
}

/// What one trajectory of a sweep produced.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary<A> {
    /// The member's index in the sweep.
    pub index: usize,
    /// How the trajectory ended.
    pub status: Status,
    /// Steps taken successfully.
    pub steps: usize,
    /// The final time (0 if the integrator could not be built).
    pub time: f64,
    /// The final momentum μ ∈ 𝔤*; `None` iff the integrator could not be built.
    pub momentum: Option<A>,
    /// E₀ = h(μ₀) + V(g₀) (NaN if the integrator could not be built).
    pub initial_energy: f64,
    /// max_k |E_k − E₀| over the monitored steps (every `monitor_every`-th and the last one).
    pub max_energy_error: f64,
    /// max_k |C(μ_k) − C(μ₀)| likewise, for systems with a Casimir.
    pub max_casimir_error: Option<f64>,
}

impl<A: Vector> Summary<A> {
    /// The CSV header matching [`Summary::csv_row`] for an algebra of dimension `dim`:
    /// `index,status,steps,time,mu_0,…,mu_{dim−1},initial_energy,max_energy_error,max_casimir_error`.
    pub fn csv_header(dim: usize) -> String {
        let mut s = String::from("index,status,steps,time");
        for i in 0..dim {
            s.push_str(&format!(",mu_{i}"));
        }
        s.push_str(",initial_energy,max_energy_error,max_casimir_error");
        s
    }
    /// One CSV line (no newline); floats with `{:e}` (shortest round-trip form, so a CSV written
    /// and parsed back gives the same bits); missing values as empty fields.
    pub fn csv_row(&self, dim: usize) -> String {
        let mut s = String::with_capacity(48 + 25 * (dim + 3));
        self.write_csv_row(dim, &mut s);
        s
    }
    /// Appends [`Summary::csv_row`] to `out` (a sweep of 10⁶ members formats 10⁶ rows: into one
    /// buffer, without a string per row).
    pub fn write_csv_row(&self, dim: usize, out: &mut String) {
        use core::fmt::Write as _;
        // Writing into a String cannot fail.
        let _ = write!(
            out,
            "{},{},{},",
            self.index,
            self.status.label(),
            self.steps
        );
        push_exp(out, self.time);
        for i in 0..dim {
            out.push(',');
            if let Some(m) = self.momentum.as_ref().filter(|m| i < m.dim()) {
                push_exp(out, m.get(i));
            }
        }
        out.push(',');
        push_exp(out, self.initial_energy);
        out.push(',');
        push_exp(out, self.max_energy_error);
        out.push(',');
        if let Some(c) = self.max_casimir_error {
            push_exp(out, c);
        }
    }
}

/// Whether |x| = (d + ½)·10^q exactly. With x = m·2^k (m odd) and (d + ½)·10^q =
/// (2d + 1)·5^q·2^(q−1), both sides' odd parts and powers of two must agree.
fn is_tie_above(x: f64, d: u64, q: i32) -> bool {
    let bits = x.abs().to_bits();
    let (fraction, biased) = (bits & ((1 << 52) - 1), (bits >> 52) as i32);
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | 1 << 52, biased - 1075)
    };
    if m == 0 {
        return false;
    }
    let t = m.trailing_zeros() as i32;
    let (m, odd) = (u128::from(m >> t), 2 * u128::from(d) + 1);
    // m < 2⁵³ and 2d + 1 < 2⁵⁸: beyond these powers of five the two cannot be equal, and below
    // them the products stay under 2¹²⁰.
    e + t == q - 1
        && if q >= 0 {
            q <= 25 && odd * 5u128.pow(q as u32) == m
        } else {
            -q <= 27 && m * 5u128.pow((-q) as u32) == odd
        }
}

/// Appends x as `format!("{x:e}")` writes it — the shortest decimal that reads back as x, in
/// the form `d[.ddd]e<exp>` (`-1.5e-3`, `2e0`, `-0e0`, `NaN`, `inf`) — with the digits from `ryu`
/// (Adams 2018: the shortest, closest digits, as the standard library's Grisu/Dragon finds them,
/// at a fraction of the cost; where two are equally close, the standard library's choice; test
/// `push_exp_writes_what_format_e_writes`), so that the rows of a sweep of 10⁶ members do not
/// spend their time in the formatter.
pub fn push_exp(out: &mut String, x: f64) {
    if !x.is_finite() {
        use core::fmt::Write as _;
        let _ = write!(out, "{x:e}");
        return;
    }
    let mut buffer = ryu::Buffer::new();
    let text = buffer.format_finite(x);
    let (sign, body) = match text.strip_prefix('-') {
        Some(body) => ("-", body),
        None => ("", text),
    };
    // ryu writes `d[.ddd]e<exp>` for large and small magnitudes and `int.frac` otherwise: take
    // the significant digits and the decimal exponent of the first one from either.
    let mut digits = [0u8; 24];
    let mut n = 0;
    let exp = match body.split_once('e') {
        Some((mantissa, exp)) => {
            for b in mantissa.bytes().filter(|&b| b != b'.') {
                digits[n] = b;
                n += 1;
            }
            // ryu writes a plain integer exponent; it always parses.
            exp.parse::<i32>().unwrap_or(0)
        }
        None => {
            let (int, frac) = body.split_once('.').unwrap_or((body, ""));
            let mut leading = 0i32;
            for b in int.bytes().chain(frac.bytes()) {
                if n == 0 && b == b'0' {
                    leading += 1;
                } else {
                    digits[n] = b;
                    n += 1;
                }
            }
            int.len() as i32 - 1 - leading
        }
    };
    while n > 1 && digits[n - 1] == b'0' {
        n -= 1;
    }
    // Where x lies exactly halfway between two shortest decimals, ryu takes the one with the even
    // last digit and the standard library the larger: a tie needs 16 or 17 digits (with fewer, the
    // two are not both within half an ulp of x), and the even digit then becomes the odd one above
    // (no carry).
    if n >= 16 && (digits[n - 1] - b'0').is_multiple_of(2) {
        let d = digits[..n]
            .iter()
            .fold(0u64, |d, &b| 10 * d + u64::from(b - b'0'));
        if is_tie_above(x, d, exp - (n as i32 - 1)) {
            digits[n - 1] += 1;
        }
    }
    out.push_str(sign);
    if n == 0 {
        out.push_str("0e0");
        return;
    }
    out.push(digits[0] as char);
    if n > 1 {
        out.push('.');
        // ASCII digits.
        out.push_str(core::str::from_utf8(&digits[1..n]).unwrap_or_default());
    }
    out.push('e');
    let mut itoa = [0u8; 12];
    let mut k = itoa.len();
    let mut e = exp.unsigned_abs();
    loop {
        k -= 1;
        itoa[k] = b'0' + (e % 10) as u8;
        e /= 10;
        if e == 0 {
            break;
        }
    }
    if exp < 0 {
        out.push('-');
    }
    out.push_str(core::str::from_utf8(&itoa[k..]).unwrap_or_default());
}

/// A sweep: members `P` (index = position), end time T, number of steps n.
#[derive(Debug, Clone, PartialEq)]
pub struct Ensemble<P> {
    members: Vec<P>,
    end: f64,
    steps: usize,
    monitor_every: usize,
}

/// The momentum-space type of an integrator.
type Algebra<I> = <<I as Integrator>::Group as LieGroup>::Algebra;

impl<P: Sync> Ensemble<P> {
    /// A sweep over `members`, each integrated from its initial time t₀ (the time of the
    /// integrator its builder makes) to the end time T in `steps` = n ≥ 1 steps: n − 1 steps of
    /// h = (T − t₀)/n, then the last one of T − t, t the member's time before it, so that the
    /// trajectory lands on T (its summary's `time` is T, not the n·h that n equal steps would
    /// sum to: with T = 0.7 and n = 70, 0.7000000000000001). T < t₀ integrates backwards.
    /// Energy and Casimir are monitored after every step.
    ///
    /// Errors: T not finite, or n = 0.
    pub fn new(members: Vec<P>, end: f64, steps: usize) -> Result<Self, IntegratorError> {
        if !end.is_finite() || steps == 0 {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "ensemble to T = {end} in {steps} steps: T must be finite and the steps at \
                     least one"
                ),
            });
        }
        Ok(Self {
            members,
            end,
            steps,
            monitor_every: 1,
        })
    }
    /// Monitors energy and Casimir only every `every` steps (and after the last one), for
    /// systems where evaluating them costs as much as a step. `every = 0` is taken as 1.
    pub fn monitor_every(mut self, every: usize) -> Self {
        self.monitor_every = every.max(1);
        self
    }
    /// The members.
    pub fn members(&self) -> &[P] {
        &self.members
    }
    /// The number of members N.
    pub fn len(&self) -> usize {
        self.members.len()
    }
    /// Whether the sweep is empty.
    pub fn is_empty(&self) -> bool {
        self.members.is_empty()
    }
    /// The end time T.
    pub fn end(&self) -> f64 {
        self.end
    }
    /// The number of steps per trajectory.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// Integrates member `index` (< N, else a `BuildFailed` summary) with the integrator `build`
    /// makes of it.
    pub fn run_one<I, F>(&self, index: usize, build: &F) -> Summary<Algebra<I>>
    where
        I: Integrator,
        F: Fn(usize, &P) -> Result<I, IntegratorError>,
    {
        let built = match self.members.get(index) {
            Some(p) => build(index, p),
            None => Err(IntegratorError::InvalidParameter {
                reason: format!("member {index} of a sweep of {}", self.members.len()),
            }),
        };
        let mut integ = match built {
            Ok(integ) => integ,
            Err(e) => {
                return Summary {
                    index,
                    status: Status::BuildFailed(e),
                    steps: 0,
                    time: 0.0,
                    momentum: None,
                    initial_energy: f64::NAN,
                    max_energy_error: 0.0,
                    max_casimir_error: None,
                }
            }
        };
        let e0 = integ.energy();
        let c0 = integ.casimir();
        let (mut de, mut dc) = (0.0f64, c0.map(|_| 0.0f64));
        let mut monitor = |integ: &I| {
            de = de.max((integ.energy() - e0).abs());
            if let (Some(dc), Some(c0), Some(c)) = (dc.as_mut(), c0, integ.casimir()) {
                *dc = dc.max((c - c0).abs());
            }
        };
        let mut status = Status::Completed;
        let mut taken = 0;
        let n = self.steps;
        let h = (self.end - integ.time()) / n as f64;
        for k in 0..n {
            // The last step from where the member's clock stands to T. T − t is exact where
            // T/2 ≤ t ≤ 2T (Sterbenz; so for t₀ = 0 and n ≥ 2), and the clock adds it to t and
            // its carried error, below half an ulp of t: the sum rounds to T.
            let step = if k + 1 < n {
                h
            } else {
                self.end - integ.time()
            };
            if let Err(error) = integ.step(step) {
                status = Status::StepFailed { step: k, error };
                break;
            }
            taken += 1;
            if taken % self.monitor_every == 0 {
                monitor(&integ);
            }
        }
        if taken % self.monitor_every != 0 {
            monitor(&integ);
        }
        Summary {
            index,
            status,
            steps: taken,
            time: integ.time(),
            momentum: Some(integ.momentum()),
            initial_energy: e0,
            max_energy_error: de,
            max_casimir_error: dc,
        }
    }

    /// The members of `shard`, in index order, sequentially or on the current rayon pool.
    pub fn run_shard<I, F>(
        &self,
        shard: Shard,
        execution: Execution,
        build: &F,
    ) -> Vec<Summary<Algebra<I>>>
    where
        I: Integrator,
        F: Fn(usize, &P) -> Result<I, IntegratorError> + Sync,
    {
        let indices = shard.indices(self.len());
        match execution {
            Execution::Sequential => indices.iter().map(|&i| self.run_one(i, build)).collect(),
            // `collect` on an indexed parallel iterator keeps the order of `indices`.
            Execution::Parallel => indices
                .par_iter()
                .with_max_len(1)
                .map(|&i| self.run_one(i, build))
                .collect(),
        }
    }

    /// All members, one after the other.
    pub fn run_sequential<I, F>(&self, build: &F) -> Vec<Summary<Algebra<I>>>
    where
        I: Integrator,
        F: Fn(usize, &P) -> Result<I, IntegratorError> + Sync,
    {
        self.run_shard(Shard::all(), Execution::Sequential, build)
    }

    /// All members on the current rayon pool; bit-identical to [`Ensemble::run_sequential`].
    pub fn run_parallel<I, F>(&self, build: &F) -> Vec<Summary<Algebra<I>>>
    where
        I: Integrator,
        F: Fn(usize, &P) -> Result<I, IntegratorError> + Sync,
    {
        self.run_shard(Shard::all(), Execution::Parallel, build)
    }
}

/// Merges the summaries of the shards of a sweep of `len` members into index order. Errors if an
/// index is ≥ `len`, appears twice, or is missing — so a successful merge is exactly the full run.
pub fn merge_shards<A>(
    shards: impl IntoIterator<Item = Vec<Summary<A>>>,
    len: usize,
) -> Result<Vec<Summary<A>>, IntegratorError> {
    let mut slots: Vec<Option<Summary<A>>> = (0..len).map(|_| None).collect();
    for summary in shards.into_iter().flatten() {
        let index = summary.index;
        match slots.get_mut(index) {
            None => {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!("merge: index {index} outside a sweep of {len}"),
                })
            }
            Some(Some(_)) => {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!("merge: index {index} appears in two shards"),
                })
            }
            Some(slot) => *slot = Some(summary),
        }
    }
    slots
        .into_iter()
        .enumerate()
        .map(|(i, s)| {
            s.ok_or_else(|| IntegratorError::InvalidParameter {
                reason: format!("merge: index {i} is missing"),
            })
        })
        .collect()
}

/// SplitMix64 (Steele, Lea & Flood 2014): a 64-bit generator with a full period whose output
/// passes BigCrush; used here only to seed initial conditions reproducibly.
#[derive(Debug, Clone)]
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform on (0, 1]: 53 random bits, shifted away from 0 so that ln is finite.
    fn uniform(&mut self) -> f64 {
        ((self.next() >> 11) + 1) as f64 * (1.0 / (1u64 << 53) as f64)
    }
    /// A standard normal deviate (Box–Muller, cosine branch).
    fn normal(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (core::f64::consts::TAU * u2).cos()
    }
}

/// Point number `index` of the seeded uniform distribution on the sphere |μ| = `radius` in ℝ^dim:
/// a vector of independent standard normals, normalised (its direction is uniform, Muller 1959).
/// Depends only on (dim, radius, seed, index): the same bits on every run of the same build.
/// Errors: dim = 0, radius not finite or negative.
pub fn sphere_point<A: Vector>(
    dim: usize,
    radius: f64,
    seed: u64,
    index: u64,
) -> Result<A, IntegratorError> {
    if dim == 0 || !radius.is_finite() || radius < 0.0 {
        return Err(IntegratorError::InvalidParameter {
            reason: format!("sphere of dimension {dim} and radius {radius}"),
        });
    }
    // One independent stream per (seed, index): mix the index through one SplitMix64 round.
    let mut rng = SplitMix64(seed ^ SplitMix64(index).next());
    loop {
        let v = A::from_fn(dim, |_| rng.normal());
        let n = v.norm();
        // |v| = 0 has probability 0 (and |v| > 1e-150 never underflows the division).
        if n > 1e-150 {
            return Ok(v.scale(radius / n));
        }
    }
}

/// `count` momenta uniform on the sphere |μ| = `radius` in ℝ^dim: [`sphere_point`] for the
/// indices 0..count.
pub fn momenta_on_sphere<A: Vector>(
    dim: usize,
    radius: f64,
    count: usize,
    seed: u64,
) -> Result<Vec<A>, IntegratorError> {
    (0..count as u64)
        .map(|i| sphere_point(dim, radius, seed, i))
        .collect()
}

/// `count` momenta on the energy level h(μ) = `energy` of a system with quadratic (kinetic)
/// Hamiltonian: [`energy_level_point`] for the indices 0..count.
pub fn momenta_on_energy_level<G: LieGroup, S: System<G>>(
    system: &S,
    energy: f64,
    count: usize,
    seed: u64,
) -> Result<Vec<G::Algebra>, IntegratorError> {
    (0..count as u64)
        .map(|i| energy_level_point::<G, S>(system, energy, seed, i))
        .collect()
}

/// Point number `index` on the energy level h(μ) = `energy` of a system with quadratic (kinetic)
/// Hamiltonian `h(sμ) = s² h(μ)`: the sphere point u of [`sphere_point`] scaled radially,
/// μ = u √(E / h(u)). Directions are uniform; the density on the ellipsoid is the radial
/// projection of the uniform one, not its surface measure. Depends only on (system, E, seed,
/// index), so a shard of a sweep draws its own members and nothing else.
///
/// Errors: E not finite and positive; h(u) ≤ 0 or not finite; or h not quadratic (the scaled
/// point misses the level by more than 1e-12 relative).
pub fn energy_level_point<G: LieGroup, S: System<G>>(
    system: &S,
    energy: f64,
    seed: u64,
    index: u64,
) -> Result<G::Algebra, IntegratorError> {
    if !energy.is_finite() || energy <= 0.0 {
        return Err(IntegratorError::InvalidParameter {
            reason: format!("energy level E = {energy} must be finite and positive"),
        });
    }
    let u: G::Algebra = sphere_point(G::dim(), 1.0, seed, index)?;
    let hu = system.hamiltonian(&u);
    if !hu.is_finite() || hu <= 0.0 {
        return Err(IntegratorError::InvalidParameter {
            reason: format!("h(u) = {hu} on the unit sphere: not a positive kinetic energy"),
        });
    }
    let mu = u.scale((energy / hu).sqrt());
    let e = system.hamiltonian(&mu);
    if (e - energy).abs() > 1e-12 * energy {
        return Err(IntegratorError::InvalidParameter {
            reason: format!("h is not quadratic: scaling to E = {energy} gave {e}"),
        });
    }
    Ok(mu)
}
