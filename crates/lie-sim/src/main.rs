//! `lie-sim`: simulate mechanical systems on Lie groups from TOML scenes, plot trajectories, and
//! measure the speed–accuracy trade of the integrators.
//!
//! ```text
//! lie-sim                                   run the embedded default scene (tumbling rigid body)
//! lie-sim run SCENE.toml --out traj.csv     run a scene, write its trajectory as CSV
//! lie-sim run SCENE.toml --reference r.csv  … and its error at T as `trade` measures it
//! lie-sim plot traj.csv --out plot.svg      energy error, Casimir error, momentum and attitude
//!                                           against time
//! lie-sim trade SCENE.toml                  work-precision table of every method, CSV and SVG
//! lie-sim sweep SCENE.toml --out s.csv      the scene's [sweep] ensemble on every core, one row
//!         [--shard i/n] [--threads k]       per trajectory; shard i of n only (0-based)
//! lie-sim merge s0.csv s1.csv … --out s.csv merge shard outputs into the full table
//! lie-sim many-bodies SCENE.toml --out m.csv the scene's [many_bodies] rotors: one row of
//!         [--threads k]                     statistics per output time, not one per body
//! lie-sim default-scene                     print the embedded default scene, a starting point
//! lie-sim methods [--markdown]              the method registry: options, systems, descriptors
//! ```
//!
//! The scene format is documented in the library's `scene` module (`cargo doc -p lie-sim`);
//! examples live in `examples/scenes/`.

/// `println!` to stdout that ignores a closed pipe (`lie-sim run … | head`) instead of panicking.
/// `--quiet`: no summary on stdout and no progress bar (errors still go to stderr).
static QUIET: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

fn quiet() -> bool {
    QUIET.load(std::sync::atomic::Ordering::Relaxed)
}

macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        if !quiet() {
            let _ = writeln!(std::io::stdout(), $($arg)*);
        }
    }};
}

/// Progress is drawn on stderr, only when it is a terminal and `--quiet` is not given.
fn show_progress() -> bool {
    !quiet() && std::io::stderr().is_terminal()
}

use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use integrators::ensemble::Shard;
use lie_sim::error::SimError;
use lie_sim::{
    choose, input, ladder, listing, many_bodies, methods, output, plot, reference, run, scene,
    stepping, sweep, trade,
};
use scene::{Overrides, Scene};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Where outputs go when no path is given.
const DEFAULT_OUT_DIR: &str = "target/lie-sim";

#[derive(Parser, Debug)]
#[command(
    name = "lie-sim",
    version,
    about = "Simulate mechanical systems on Lie groups with structure-preserving integrators.",
    long_about = "Simulate mechanical systems on Lie groups (rigid bodies on SO(3), SE(3), SE(2), \
                  geodesics on SO(n)) with the Lie–Poisson, Euler–Poincaré and Euler–Arnold \
                  integrators, and compare them with RK4 and RKMK4.\n\nWith no command, runs the \
                  embedded default scene: a rigid body tumbling near its unstable intermediate axis."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Print nothing but errors (no summary, no progress bar).
    #[arg(short, long, global = true)]
    quiet: bool,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run a scene and write its trajectory as CSV (and optionally an SVG plot).
    ///
    /// The CSV's columns: t, mu1 … muN (body momentum μ), g11 … (the group element's matrix,
    /// row-major, where g is reconstructed), energy, casimir (where the system has one), power and
    /// work (with [forces]: P = ⟨F, ξ⟩ and W = ∫P dt by the trapezoid rule over the steps), then
    /// each body's attitude: the unit quaternion qw, qx, qy, qz (scalar first, R = R(q) maps body
    /// to space, qw ≥ 0) and the rotation vector rv1, rv2, rv3 (φ = θ n, θ ∈ [0, π] the rotation
    /// angle, R = exp(φ̂)); `_k` suffixes for several bodies. Columns before power keep their
    /// names and places.
    ///
    /// The summary reports, without forces, the energy error max |E − E₀|/|E₀|; with forces, the
    /// energy change E(T) − E₀ (not an error: the forces' work), the work W, and the energy
    /// balance error max |E − E₀ − W|/max|E| (the method's error plus the quadrature's O(h²)).
    ///
    /// With --reference FILE or --check, it also reports the error at T exactly as `lie-sim
    /// trade` measures it: max(‖μ − μ_ref‖_∞ / ‖μ_ref‖_∞, ‖g − g_ref‖_∞ / max(1, ‖g_ref‖_∞)), the
    /// group term where both reconstruct g; below the reference's estimated error it is
    /// unresolved.
    Run {
        /// The scene file (TOML); the embedded default scene when left out.
        scene: Option<PathBuf>,
        /// Trajectory CSV (default: `target/lie-sim/<scene>.csv`).
        #[arg(short, long)]
        out: Option<PathBuf>,
        /// Also draw the trajectory plot to this SVG.
        #[arg(long)]
        plot: Option<PathBuf>,
        /// Also compare the state at T with the trade's own reference (the exact flow on the
        /// free rigid body without forces, Gragg–Bulirsch–Stoer elsewhere; see `lie-sim trade
        /// --help`) and report the error at T; implied by --reference.
        #[arg(long)]
        check: bool,
        #[command(flatten)]
        reference: ReferenceArgs,
        #[command(flatten)]
        overrides: OverrideArgs,
    },
    /// Plot a trajectory CSV written by `run`: energy error (with forces: the energy balance
    /// E − E₀ − W), Casimir error, momentum and attitude (rotation angle, quaternion) against t.
    Plot {
        /// The trajectory CSV.
        csv: PathBuf,
        /// The SVG to write [default: the CSV's path with extension .svg].
        #[arg(short, long)]
        out: Option<PathBuf>,
    },
    /// Work-precision trade: every applicable method over a ladder of steps against a reference.
    ///
    /// The ladder: with --steps, exactly those steps; otherwise from the scene's time scale ω (the
    /// initial body angular velocity |ξ₀| = |𝕀⁻¹Π₀|, or the potential's frequency when larger:
    /// the heavy top's pendulum, the satellite's orbit, the planar body's spring, the vehicle's
    /// righting moment and drag, the springs between bodies; with [forces] also the torques' spin-up
    /// rate and 1/Δt of a schedule's shortest gap between knots): h = 1/ω (hω = 1,
    /// near the stability edge; at most T), halved (or divided by --ratio) down to where an
    /// order-8 method reaches the 1e-13 reference floor over T, at most 10 levels at ratio 2
    /// (--levels fixes the count); finest levels are dropped when the work limit would be
    /// exceeded. Each run reports the error at T and the
    /// maximum relative energy, Casimir and spatial momentum-map errors over the run. The error
    /// at T: max(‖μ − μ_ref‖_∞ / ‖μ_ref‖_∞, ‖g − g_ref‖_∞ / max(1, ‖g_ref‖_∞)), the group term
    /// where both reconstruct g (`lie-sim run --reference` reports the same for one run).
    ///
    /// The reference, made independently of every method in the table: the exact flow on the free
    /// rigid body without forces; elsewhere Gragg–Bulirsch–Stoer extrapolation (order 12) on the
    /// steps of an error-controlled RKMK DOP853 run (short where the motion is fast, landing on the
    /// force schedules' knots), then on them split in 2, 4, … until two successive runs agree to
    /// --reference-tolerance, within
    /// --reference-budget (if not, one line says so and the trade goes on with the agreement
    /// reached); or your own with --reference. Its estimated error (the spread of its runs at its
    /// step and at twice it, plus 2ε(1 + ωT) for the rounding of the scene's data) is printed and
    /// is the floor: errors below it are shown as `unresolved`, not as numbers, in the table, the
    /// CSV and the plot, and count as twice the floor when a run is picked for a target.
    #[command(mut_arg("step", |a| a.hide(true)))]
    Trade {
        /// The scene file (TOML); the embedded default scene when left out.
        scene: Option<PathBuf>,
        /// Table CSV (default: `target/lie-sim/<scene>-trade.csv`).
        #[arg(short, long)]
        out: Option<PathBuf>,
        /// Metric-against-cost SVG [default: the table's path with extension .svg].
        #[arg(long)]
        plot: Option<PathBuf>,
        /// Explicit steps, comma-separated (e.g. 0.1,0.05,0.02): each finite, positive, ≤ T.
        #[arg(long, value_name = "H,H,…", allow_hyphen_values = true,
              value_parser = parse_steps, conflicts_with = "levels")]
        steps: Option<ladder::StepList>,
        /// Number of levels of the automatic ladder 1/ω, 1/(Rω), 1/(R²ω), … (R = --ratio)
        /// [default: down to the reference floor, at most 10 at ratio 2, 19 at √2].
        #[arg(long, value_parser = clap::value_parser!(u32).range(2..=12))]
        levels: Option<u32>,
        /// The ratio of successive steps of the automatic ladder, in [1.1, 16]: between two of
        /// its points an order-p method's error moves by ratio^p, so the cheapest run that meets
        /// a target may overshoot it by that much; 1.41 (√2) samples every method twice as finely
        /// for about twice the runs (the level cap grows to span the same range).
        #[arg(long, value_name = "R", default_value_t = ladder::DEFAULT_RATIO,
              allow_hyphen_values = true, value_parser = parse_ratio,
              conflicts_with = "steps")]
        ratio: f64,
        /// What the plot draws against cost: the error at T, or the maximum relative energy,
        /// Casimir (|Π|² on SO(3)) or spatial momentum-map (R Π; the heavy top: e₃·R Π) error
        /// over the run. Every one is in the table and the CSV.
        #[arg(long, value_enum, default_value_t = trade::Metric::Error)]
        metric: trade::Metric,
        /// The horizon T of the trade (replaces the scene's duration).
        #[arg(long, value_name = "T", allow_hyphen_values = true,
              value_parser = parse_horizon, conflicts_with = "duration")]
        horizon: Option<f64>,
        /// Repeat each run this many times and keep the fastest (timings on a busy machine).
        #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=100))]
        repeats: u32,
        #[command(flatten)]
        reference: ReferenceArgs,
        /// Also write the reference's state at T here, as a one-row trajectory CSV (the shape
        /// --reference reads back).
        #[arg(long, value_name = "FILE.csv")]
        write_reference: Option<PathBuf>,
        #[command(flatten)]
        overrides: OverrideArgs,
    },
    /// Run the scene's [sweep] ensemble (rayon) and write one summary row per trajectory as CSV.
    ///
    /// Bit-identical whatever the thread count or shard split. Where the method has a batched
    /// (SIMD) version and the system is a rigid body in principal axes, free or in a uniform
    /// field, the members are stepped N at a time (`batch` crate). See docs/ensembles.md.
    Sweep {
        /// The scene file (TOML) with a [sweep] table.
        scene: PathBuf,
        /// Summary CSV (default: `target/lie-sim/<scene>-sweep.csv`; for shard i of n,
        /// `<scene>-sweep-shard-i-of-n.csv`, so that shards never share a default file).
        #[arg(short, long)]
        out: Option<PathBuf>,
        /// Run only shard i of n, 0-based (0 ≤ i < n): the members ⌊iN/n⌋ … ⌊(i+1)N/n⌋ − 1.
        /// Merge the n outputs with `lie-sim merge`.
        #[arg(long, value_name = "i/n", value_parser = parse_shard)]
        shard: Option<Shard>,
        /// Worker threads (1: sequential) [default: one per core, or RAYON_NUM_THREADS].
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096))]
        threads: Option<u32>,
        /// Replace the sweep's count N.
        #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
        count: Option<u64>,
        /// Replace the sweep's seed.
        #[arg(long)]
        seed: Option<u64>,
        /// Step every member with the scalar method, even where a batched one exists (the two
        /// agree to a few ulps; the path is part of the sweep's fingerprint).
        #[arg(long)]
        scalar: bool,
        #[command(flatten)]
        overrides: OverrideArgs,
    },
    /// Run the scene's [many_bodies] rotors and write one row of statistics per output time.
    ///
    /// N rigid bodies, free or in a uniform field, drawn as [sweep] draws its members; every
    /// `stride` steps their energy and Casimir errors (mean, max, median, 99th percentile), the
    /// order parameters ⟨cos θ⟩ and ⟨P₂(cos θ)⟩ against the field, the mean kinetic energy per
    /// axis and the rotational temperature. Batched (SIMD) where the method has a batched
    /// version; bit-identical whatever the thread count; memory independent of N. See
    /// docs/ensembles.md.
    ManyBodies {
        /// The scene file (TOML) with a [many_bodies] table.
        scene: PathBuf,
        /// Statistics CSV (default: `target/lie-sim/<scene>-many-bodies.csv`).
        #[arg(short, long)]
        out: Option<PathBuf>,
        /// Worker threads (1: sequential) [default: one per core, or RAYON_NUM_THREADS].
        #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096))]
        threads: Option<u32>,
        /// Replace the table's count N.
        #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
        count: Option<u64>,
        /// Replace the table's seed.
        #[arg(long)]
        seed: Option<u64>,
        /// Step every body with the scalar method, even where a batched one exists.
        #[arg(long)]
        scalar: bool,
        /// Refused: the statistics are sums in index order over all N bodies, which shards
        /// cannot add up to the same bits; run the bodies on one machine's threads.
        #[arg(long, value_name = "i/n", value_parser = parse_shard)]
        shard: Option<Shard>,
        #[command(flatten)]
        overrides: OverrideArgs,
    },
    /// Merge the shard CSVs of one sweep (`lie-sim sweep --shard i/n`) into the full table.
    ///
    /// The result is byte for byte the unsharded sweep's CSV. Refuses shards of different sweeps,
    /// a missing or repeated shard, and a missing or repeated member index.
    Merge {
        /// The shard CSVs, in any order.
        #[arg(required = true)]
        shards: Vec<PathBuf>,
        /// The merged CSV.
        #[arg(short, long)]
        out: PathBuf,
    },
    /// The cheapest method and step meeting an accuracy target on this scene, measured by a
    /// bounded trade (breadth first over the steps), with the runner-up.
    Choose {
        /// The scene file (TOML); the embedded default scene when left out.
        scene: Option<PathBuf>,
        /// The accuracy to meet (relative), e.g. 1e-8.
        #[arg(long, allow_hyphen_values = true)]
        target: f64,
        /// What must meet it: the error at T against the reference, or the maximum relative
        /// energy error over the run.
        #[arg(long, value_enum, default_value_t = choose::Metric::Error)]
        metric: choose::Metric,
        /// The horizon T (replaces the scene's duration).
        #[arg(long, value_name = "T", allow_hyphen_values = true,
              value_parser = parse_horizon, conflicts_with = "duration")]
        horizon: Option<f64>,
        /// Wall-clock budget of the search: seconds, or with a unit (`30s`, `2m`, `1h`).
        #[arg(long, default_value = "30s", value_parser = parse_budget)]
        budget: std::time::Duration,
        /// Number of step sizes h, h/2, … (h/R, h/R², … with --ratio), from the scene's step.
        #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u32).range(1..=12))]
        levels: u32,
        /// The ratio of successive steps, in [1.1, 16]: the chosen step is a point of this
        /// ladder, so a finer one (1.41 = √2) lands closer to the cheapest step that meets the
        /// target, over a shorter range of steps for the same --levels.
        #[arg(long, value_name = "R", default_value_t = ladder::DEFAULT_RATIO,
              allow_hyphen_values = true, value_parser = parse_ratio)]
        ratio: f64,
        /// Write the scene with the chosen method and step here.
        #[arg(long)]
        write: Option<PathBuf>,
        #[command(flatten)]
        reference: ReferenceArgs,
        #[command(flatten)]
        overrides: OverrideArgs,
    },
    /// Print the embedded default scene (a commented starting point for your own).
    DefaultScene,
    /// List the methods: what each is, the options it takes, the systems it applies to; with
    /// --markdown, the docs' tables (with what each configuration of `trade` is, as the
    /// integrators crate reports it) and the systems.
    Methods {
        /// Print Markdown tables (the docs' method table).
        #[arg(long)]
        markdown: bool,
    },
}

/// How the reference of `trade`, `choose` (`--metric error`) and `run --check` is made (see
/// `lie-sim trade --help`).
#[derive(Args, Debug, Clone)]
struct ReferenceArgs {
    /// The relative agreement two successive refinements of the reference must reach (in the
    /// trade's error measure); also the accuracy a --reference file is taken to have.
    #[arg(long, value_name = "TOL", default_value = "1e-13",
          value_parser = parse_tolerance, allow_hyphen_values = true)]
    reference_tolerance: f64,
    /// The time the reference's refinement may take beyond its first two runs: seconds, or with
    /// a unit (30s, 2m, 1h). When it runs out before the tolerance is met, one line says so and
    /// the errors below the agreement reached are unresolved.
    #[arg(long, value_name = "TIME", default_value = reference::DEFAULT_BUDGET,
          value_parser = parse_budget, allow_hyphen_values = true)]
    reference_budget: std::time::Duration,
    /// Your own reference instead: the last row of a trajectory CSV as `lie-sim run` (or
    /// `trade --write-reference`) writes it, at t = T, with the scene's μ and g columns; taken to
    /// be accurate to --reference-tolerance.
    #[arg(long, value_name = "FILE.csv")]
    reference: Option<PathBuf>,
}

impl ReferenceArgs {
    fn options(&self) -> reference::Options {
        reference::Options {
            tolerance: self.reference_tolerance,
            budget: self.reference_budget,
            file: self.reference.clone(),
        }
    }
}

fn parse_tolerance(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(t) if t.is_finite() && t > 0.0 && t < 1.0 => Ok(t),
        Ok(t) => Err(format!("{t} is not a relative tolerance in (0, 1)")),
        Err(_) => Err(format!("{s:?} is not a number")),
    }
}

fn parse_budget(s: &str) -> Result<std::time::Duration, String> {
    let s = s.trim();
    let (num, unit) = match s.find(|c: char| c.is_ascii_alphabetic()) {
        Some(i) => (&s[..i], &s[i..]),
        None => (s, "s"),
    };
    let scale = match unit {
        "s" => 1.0,
        "m" | "min" => 60.0,
        "h" => 3600.0,
        _ => return Err(format!("{s:?}: the unit must be s, m or h")),
    };
    let x: f64 = num
        .trim()
        .parse()
        .map_err(|_| format!("{s:?} is not a duration like 30s, 2m or 1h"))?;
    if !(x.is_finite() && x > 0.0) {
        return Err(format!("{s:?}: the budget must be positive"));
    }
    std::time::Duration::try_from_secs_f64(x * scale).map_err(|e| format!("{s:?}: {e}"))
}

fn parse_steps(s: &str) -> Result<ladder::StepList, String> {
    ladder::parse_steps(s).map(ladder::StepList)
}

fn parse_horizon(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(t) if t.is_finite() && t > 0.0 => Ok(t),
        Ok(_) => Err("the horizon must be finite and positive".into()),
        Err(_) => Err("not a number".into()),
    }
}

fn parse_ratio(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(r) if ladder::RATIO_RANGE.contains(&r) => Ok(r),
        Ok(r) => Err(format!(
            "the ratio of successive steps must be in [{}, {}], got {r}",
            ladder::RATIO_RANGE.start(),
            ladder::RATIO_RANGE.end()
        )),
        Err(_) => Err("not a number".into()),
    }
}

fn parse_shard(s: &str) -> Result<Shard, String> {
    s.parse::<Shard>()
        .map_err(|_| format!("{s:?} is not a shard i/n with 0 ≤ i < n (0-based)"))
}

/// Overrides of the scene's values, checked like the scene's own.
#[derive(Args, Debug, Clone, Copy)]
struct OverrideArgs {
    /// Replace the scene's duration T.
    #[arg(long)]
    duration: Option<f64>,
    /// The flag that set `duration` (`--horizon` sets it too), for messages.
    #[arg(skip)]
    duration_flag: Option<&'static str>,
    /// Replace the scene's step h.
    #[arg(long)]
    step: Option<f64>,
    /// Replace the scene's output stride.
    #[arg(long)]
    stride: Option<u64>,
    /// Go ahead beyond the work limits (10⁹ steps, 1 GiB of output) that a command checks
    /// before it starts.
    #[arg(long)]
    allow_large: bool,
}

impl From<OverrideArgs> for Overrides {
    fn from(a: OverrideArgs) -> Self {
        Overrides {
            duration: a.duration,
            duration_flag: a.duration_flag.or(a.duration.map(|_| "--duration")),
            step: a.step,
            stride: a.stride,
        }
    }
}

fn load(scene: Option<&Path>, overrides: OverrideArgs) -> Result<(Scene, String), SimError> {
    match scene {
        Some(p) => {
            let stem = p
                .file_stem()
                .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
            Ok((Scene::load(p, overrides.into())?, stem))
        }
        None => Ok((Scene::default_scene(overrides.into())?, "default".into())),
    }
}

fn default_path(stem: &str, suffix: &str) -> PathBuf {
    Path::new(DEFAULT_OUT_DIR).join(format!("{stem}{suffix}"))
}

fn human_duration(d: std::time::Duration) -> String {
    let s = d.as_secs_f64();
    if s >= 1.0 {
        format!("{s:.2} s")
    } else if s >= 1e-3 {
        format!("{:.1} ms", s * 1e3)
    } else {
        format!("{:.0} µs", s * 1e6)
    }
}

fn cmd_run(
    scene_path: Option<&Path>,
    out: Option<PathBuf>,
    plot_path: Option<PathBuf>,
    check: Option<&ReferenceArgs>,
    overrides: OverrideArgs,
) -> Result<(), SimError> {
    let (scene, stem) = load(scene_path, overrides)?;
    let out = out.unwrap_or_else(|| default_path(&stem, ".csv"));
    let outputs: Vec<&Path> = std::iter::once(out.as_path())
        .chain(plot_path.as_deref())
        .collect();
    let inputs: Vec<&Path> = scene_path
        .into_iter()
        .chain(check.and_then(|r| r.reference.as_deref()))
        .collect();
    output::refuse_clobbering(&outputs, &inputs)?;
    if plot_path.is_some() && !output::is_file_or_new(&out) {
        return Err(SimError::Output {
            path: out,
            why: "--plot reads the trajectory back from --out, which must then be a regular file"
                .into(),
        });
    }
    let progress = show_progress();
    let summary = run::run_scene(&scene, &out, progress, overrides.allow_large)?;
    let plotted = match plot_path {
        Some(p) => {
            let traj = plot::read_csv(&out)?;
            plot::plot_trajectory(&traj, &p, &scene.name)?;
            Some(p)
        }
        None => None,
    };

    let m = &scene.method;
    say!("lie-sim: {} ({})", scene.name, scene.source);
    say!("  system       {}", scene.system.kind());
    say!("  method       {}", m.method);
    say!("  tau          {}", m.tau_label());
    say!("  theta        {}", m.theta_label());
    if let Some(c) = &m.composition {
        say!(
            "  composition  {} (order {} from {} steps of the symmetric base method per step)",
            c.name(),
            c.order(),
            c.stages()
        );
    }
    if let Some(p) = &m.processing {
        say!(
            "  processing   {} (effective order {}: {} base steps per step, a processor of {} \
             at each output)",
            p.name(),
            p.order(),
            p.kernel_stages(),
            p.processor_stages()
        );
    }
    if let Some(order) = m.modified {
        say!(
            "  modified     H − h²H₂{} (order {order} at the cost of one step)",
            if order == 6 { " − h⁴H₄" } else { "" }
        );
    }
    say!("  properties   {}", summary.info);
    if let Some(f) = scene.system.forces() {
        say!("  forces       {}", f.describe());
    }
    if let Some(s) = &m.splitting {
        say!(
            "  splitting    {} (order {}: exact kinetic flows between potential kicks)",
            s.name(),
            s.order()
        );
    }
    let reconstructs = if scene.reconstruct {
        ""
    } else {
        " (momentum only, no reconstruction)"
    };
    match (&scene.variable, &summary.stats) {
        (Some(variable), Some(stats)) => {
            match variable {
                stepping::VariableSteps::Tolerance(tol) => say!(
                    "  tolerance    rtol = {:e}, atol = {:e}",
                    tol.rtol,
                    tol.atol
                ),
                stepping::VariableSteps::Reversible(epsilon) => {
                    say!("  epsilon      {epsilon:e} (reversible steps h = ε/ρ, Hairer–Söderlind)")
                }
            }
            say!(
                "  steps        {} accepted, {} rejected, h in [{:.3e}, {:.3e}] to T = {}{}",
                stats.accepted,
                stats.rejected,
                stats.min_step,
                stats.max_step,
                scene.duration,
                reconstructs
            );
        }
        _ => say!(
            "  steps        {} × h = {} to T = {}{}",
            summary.steps,
            scene.step,
            scene.duration,
            reconstructs
        ),
    }
    say!(
        "  wall time    {} ({:.0} ns per step, output included)",
        human_duration(summary.wall),
        summary.wall.as_nanos() as f64 / summary.steps as f64
    );
    match &summary.work {
        // Unforced: the flow conserves E, and its drift is the method's error.
        None => say!(
            "  energy       max |E − E₀|/|E₀| = {:.3e}",
            summary.max_energy_error
        ),
        // Forced: E changes by the forces' work; what the work does not account for is the error.
        Some(w) => {
            say!(
                "  energy       change E(T) − E₀ = {:.6e} (the forces' work; not an error)",
                summary.energy_change
            );
            say!(
                "  work         W = ∫⟨F, ξ⟩dt = {:.6e} (trapezoid rule over the steps, O(h²))",
                w.work
            );
            say!(
                "  balance      max |E − E₀ − W|/max|E| = {:.3e} (the energy error: method and \
                 quadrature)",
                w.max_balance_error
            );
        }
    }
    match summary.max_casimir_error {
        Some(c) => say!("  casimir      max |C − C₀|/|C₀| = {c:.3e}"),
        None => say!(
            "  casimir      (none monitored for this {})",
            scene.system.kind()
        ),
    }
    if !summary.turned.is_empty() {
        let angles: Vec<String> = summary.turned.iter().map(|a| format!("{a:.4}")).collect();
        say!(
            "  attitude     turned {} rad from R₀ by the end (the angle of R₀ᵀR{})",
            angles.join(", "),
            if angles.len() > 1 {
                ", body by body"
            } else {
                ""
            }
        );
    }
    for e in &summary.events {
        say!(
            "  event        {} = {} ({}) at t = {:.12}",
            e.quantity,
            e.value,
            if e.rising { "rising" } else { "falling" },
            e.t
        );
    }
    if let Some(t) = summary.stopped_at {
        say!("  stopped      at t = {t:.12} by an event with stop = true");
    }
    say!(
        "  trajectory   {} ({} rows)",
        summary.out.display(),
        summary.rows
    );
    if let Some(p) = plotted {
        say!("  plot         {}", p.display());
    }
    if let Some(args) = check {
        report_error_at_t(&scene, &summary, args)?;
    }
    Ok(())
}

/// `run --reference` / `--check`: the run's error at T against the reference, in the trade's
/// measure ([`lie_sim::measure::FinalState::error`]), unresolved below the reference's estimated error.
fn report_error_at_t(
    scene: &Scene,
    summary: &run::RunSummary,
    args: &ReferenceArgs,
) -> Result<(), SimError> {
    if let Some(t) = summary.stopped_at {
        return Err(SimError::Usage {
            flag: if args.reference.is_some() {
                "--reference".into()
            } else {
                "--check".into()
            },
            message: format!(
                "an event stopped the run at t = {t}: there is no state at T = {} to compare",
                scene.duration
            ),
        });
    }
    let reference = reference::reference(scene, &args.options())?;
    let error = summary.final_state.error(&reference.state);
    say!(
        "  reference    {}; estimated error {:.1e}",
        reference.description,
        reference.estimated_error
    );
    if let Some(line) = &reference.shortfall {
        say!("  reference    {line}");
    }
    if error < reference.estimated_error {
        say!(
            "  error at T   unresolved (below the reference's estimated error {:.1e}; the \
             trade's measure)",
            reference.estimated_error
        );
    } else {
        say!(
            "  error at T   {error:.6e} (max(‖μ − μ_ref‖∞/‖μ_ref‖∞, ‖g − g_ref‖∞/max(1, \
             ‖g_ref‖∞)), the trade's measure)"
        );
    }
    Ok(())
}

fn cmd_plot(csv: &Path, out: Option<PathBuf>) -> Result<(), SimError> {
    let out = out.unwrap_or_else(|| csv.with_extension("svg"));
    output::refuse_clobbering(&[&out], &[csv])?;
    let traj = plot::read_csv(csv)?;
    let title = csv
        .file_stem()
        .map_or_else(|| "trajectory".into(), |s| s.to_string_lossy().into_owned());
    plot::plot_trajectory(&traj, &out, &title)?;
    say!(
        "lie-sim: plotted {} ({} rows) to {}",
        csv.display(),
        traj.rows(),
        out.display()
    );
    Ok(())
}

#[allow(clippy::too_many_arguments)] // one per command-line option
fn cmd_trade(
    scene_path: Option<&Path>,
    out: Option<PathBuf>,
    plot_path: Option<PathBuf>,
    steps: Option<ladder::StepList>,
    levels: Option<u32>,
    ratio: f64,
    metric: trade::Metric,
    repeats: u32,
    reference_args: &ReferenceArgs,
    write_reference: Option<PathBuf>,
    overrides: OverrideArgs,
) -> Result<(), SimError> {
    if overrides.step.is_some() {
        return Err(SimError::Usage {
            flag: "--step".into(),
            message: "the trade does not run the scene's step: give its steps with --steps".into(),
        });
    }
    let (scene, stem) = load(scene_path, overrides)?;
    let csv = out.unwrap_or_else(|| default_path(&stem, "-trade.csv"));
    let svg = plot_path.unwrap_or_else(|| csv.with_extension("svg"));
    let outputs: Vec<&Path> = [csv.as_path(), svg.as_path()]
        .into_iter()
        .chain(write_reference.as_deref())
        .collect();
    let inputs: Vec<&Path> = scene_path
        .into_iter()
        .chain(reference_args.reference.as_deref())
        .collect();
    output::refuse_clobbering(&outputs, &inputs)?;
    trade::check_metric(&scene, metric)?;
    let mut ladder = match steps {
        Some(list) => ladder::explicit(list.0, scene.duration)?,
        None => ladder::automatic(&scene, levels.map(|l| l as usize), ratio)?,
    };
    let dropped =
        trade::fit_to_limits(&scene, &mut ladder, repeats as usize, overrides.allow_large);
    trade::estimate(&scene, &ladder.steps, repeats as usize)
        .check("trade", overrides.allow_large)?;
    say!(
        "lie-sim trade: {} ({}), T = {}, {} steps: {}",
        scene.name,
        scene.system.kind(),
        scene.duration,
        ladder.steps.len(),
        ladder
            .steps
            .iter()
            .map(|h| format!("{h:.4e}"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    say!("  ladder: {}", ladder.rule);
    if dropped > 0 {
        say!(
            "  ladder: the {dropped} finest levels dropped to stay within the work limit \
             (--allow-large keeps them)"
        );
    }
    let spinner = show_progress().then(|| {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_message(format!(
            "reference: refining (budget {:?})",
            reference_args.reference_budget
        ));
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        b
    });
    let made = reference::reference(&scene, &reference_args.options());
    if let Some(b) = spinner {
        b.finish_and_clear();
    }
    let reference = made?;
    say!(
        "reference: {}; estimated error {:.1e}",
        reference.description,
        reference.estimated_error
    );
    if let Some(line) = &reference.shortfall {
        say!("reference: {line}");
    }
    say!("{}", trade::table_header());
    let bar = show_progress().then(|| {
        let runs: usize = methods::candidates()
            .iter()
            .map(|m| {
                if trade::tolerance_driven(m) {
                    trade::TOLERANCES.len()
                } else {
                    ladder.steps.len()
                }
            })
            .sum();
        let b = indicatif::ProgressBar::new(runs as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} runs (eta {eta})",
        ) {
            b.set_style(style);
        }
        b
    });
    let report = trade::trade(
        &scene,
        &ladder.steps,
        repeats as usize,
        reference,
        &mut |r| match &bar {
            Some(b) => {
                b.inc(1);
                b.suspend(|| say!("{}", trade::table_line(r)));
            }
            None => say!("{}", trade::table_line(r)),
        },
    );
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let report = report?;
    say!(
        "observed orders (slope of log error against log h, over errors between {:.0} × the \
         reference's and {}):",
        trade::ORDER_FIT_REFERENCE_MARGIN,
        trade::ORDER_FIT_MAX_ERROR
    );
    let groups = trade::by_method(&report.rows);
    for (m, rows) in groups.iter().filter(|(m, _)| !trade::tolerance_driven(m)) {
        match trade::fitted_order(rows, report.reference.estimated_error) {
            Some(p) => say!("  {:<52} {p:.2}", m.to_string()),
            None => say!("  {:<52} -", m.to_string()),
        }
    }
    say!(
        "tolerance proportionality (error at T / tolerance, over the resolved runs; 1 would \
         be exact):"
    );
    for (m, rows) in groups.iter().filter(|(m, _)| trade::tolerance_driven(m)) {
        let ratios: Vec<f64> = rows.iter().filter_map(|r| r.proportionality()).collect();
        if ratios.is_empty() {
            say!("  {:<52} -", m.to_string());
            continue;
        }
        let (lo, hi) = ratios
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
        say!(
            "  {:<52} {lo:.2} … {hi:.2} over {} tolerances",
            m.to_string(),
            ratios.len()
        );
    }
    let picks = trade::cheapest_per_target(&report.rows, metric, report.reference.estimated_error);
    if !picks.is_empty() {
        say!("cheapest run per target ({}):", metric.describe());
        let floor = report.reference.estimated_error;
        for (target, r) in picks {
            let value = metric.of(r).unwrap_or(f64::NAN);
            say!(
                "  ≤ {target:.0e}  {} at {}: {} in {}",
                r.method,
                trade::run_label(r),
                if metric == trade::Metric::Error && value < floor {
                    format!("unresolved (below the reference's estimated error {floor:.1e})")
                } else {
                    format!("{value:.2e}")
                },
                human_duration(std::time::Duration::from_secs_f64(r.seconds))
            );
        }
    }
    let mut reasons: Vec<String> = Vec::new();
    for (m, why) in &report.inapplicable {
        let line = format!("not applicable: {}: {why}", m.method);
        if !reasons.contains(&line) {
            reasons.push(line);
        }
    }
    for line in reasons {
        say!("{line}");
    }
    if !report.unavailable.is_empty() {
        let names: Vec<String> = report.unavailable.iter().map(|m| m.to_string()).collect();
        say!("not yet available: {}", names.join(", "));
    }
    if report.rows.is_empty() {
        return Err(SimError::NotYetAvailable {
            what: format!("every method for {}", scene.system.kind()),
            why: "the integrators crate provides none of them yet".into(),
        });
    }
    trade::write_outputs(&report, &scene, &csv, &svg, metric)?;
    say!("table: {}\nplot:  {}", csv.display(), svg.display());
    if let Some(path) = write_reference {
        output::write_atomic(&path, &report.reference.to_csv())?;
        say!("reference state: {}", path.display());
    }
    Ok(())
}

#[allow(clippy::too_many_arguments)] // one per command-line option
fn cmd_sweep(
    scene_path: &Path,
    out: Option<PathBuf>,
    shard: Option<Shard>,
    threads: Option<u32>,
    count: Option<u64>,
    seed: Option<u64>,
    scalar: bool,
    overrides: OverrideArgs,
) -> Result<(), SimError> {
    let (mut scene, stem) = load(Some(scene_path), overrides)?;
    if let Some(spec) = scene.sweep.as_mut() {
        if let Some(c) = count {
            spec.count = usize::try_from(c).map_err(|_| SimError::Sweep {
                message: format!("--count {c} does not fit this machine"),
            })?;
        }
        if let Some(s) = seed {
            spec.seed = s;
        }
    }
    let shard = match shard {
        Some(s) => s,
        None => slurm_shard()?.unwrap_or_else(Shard::all),
    };
    // A shard's default name carries the shard, so that shards run side by side without --out
    // do not replace each other's file.
    let out = out.unwrap_or_else(|| {
        if shard.count() == 1 {
            default_path(&stem, "-sweep.csv")
        } else {
            default_path(
                &stem,
                &format!("-sweep-shard-{}-of-{}.csv", shard.index(), shard.count()),
            )
        }
    });
    output::refuse_clobbering(&[&out], &[scene_path])?;
    let (spec, steps, h) = sweep::plan(&scene)?;
    let cost = scene.step_cost(false)?;
    sweep::estimate(&spec, shard, steps, scene.method.stages(), cost)
        .check("sweep", overrides.allow_large)?;
    let members = shard.iter(spec.count).len();
    let bar = show_progress().then(|| {
        let b = indicatif::ProgressBar::new(members as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} members (eta {eta})",
        ) {
            b.set_style(style);
        }
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        b
    });
    // The rows go to the file a chunk at a time, as they come: memory does not grow with N.
    let file = output::AtomicFile::new(&out)?;
    let mut rows = sweep::CsvRows::new(file.create()?, &scene, (&spec, steps, h), shard, &out);
    let ran = sweep::run(
        &scene,
        shard,
        threads.map(|t| t as usize),
        scalar,
        &mut rows,
        bar.as_ref(),
    );
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let (result, spec2, wall) = ran?;
    debug_assert_eq!(spec, spec2);
    file.commit_writer(rows.into_inner())?;

    let k = result.members;
    say!("lie-sim sweep: {} ({})", scene.name, scene.source);
    say!("  system       {}", scene.system.kind());
    say!("  method       {}", scene.method);
    say!("  path         {}", result.path);
    say!(
        "  members      {} {} (seed {}); shard {shard} (0-based): {k} trajectories",
        spec.count,
        spec.kind.name(),
        spec.seed
    );
    say!("  steps        {steps} × h = {h} to T = {}", scene.duration);
    say!(
        "  threads      {}",
        match threads {
            Some(1) => "1 (sequential)".to_string(),
            Some(t) => t.to_string(),
            None => format!("{} (one per core)", rayon::current_num_threads()),
        }
    );
    say!(
        "  wall time    {} ({:.1} trajectories/s)",
        human_duration(wall),
        k as f64 / wall.as_secs_f64().max(1e-9)
    );
    say!("  completed    {} / {k}", result.completed);
    if let Some(f) = &result.first_failure {
        say!("  first failure {f}");
    }
    say!(
        "  energy       max |E − E₀| = {:.3e} (over completed trajectories)",
        result.max_energy_error
    );
    if let Some(c) = result.max_casimir_error {
        say!("  casimir      max |C − C₀| = {c:.3e}");
    }
    say!("  summary      {} ({k} rows)", out.display());
    if let Some(kib) = sweep::peak_resident_kib() {
        say!("  peak memory  {:.1} MiB resident", kib as f64 / 1024.0);
    }
    Ok(())
}

#[allow(clippy::too_many_arguments)] // one per command-line option
fn cmd_many_bodies(
    scene_path: &Path,
    out: Option<PathBuf>,
    threads: Option<u32>,
    count: Option<u64>,
    seed: Option<u64>,
    scalar: bool,
    shard: Option<Shard>,
    overrides: OverrideArgs,
) -> Result<(), SimError> {
    if let Some(shard) = shard {
        return Err(SimError::ManyBodies {
            message: format!(
                "--shard {}/{}: a many-body run is not sharded — its statistics are sums over all \
                 N bodies in index order, which shards cannot add up to the same bits; run it on \
                 one machine (--threads), or split the bodies into scenes of their own seeds",
                shard.index(),
                shard.count()
            ),
        });
    }
    let (mut scene, stem) = load(Some(scene_path), overrides)?;
    if let Some(spec) = scene.many_bodies.as_mut() {
        if let Some(c) = count {
            spec.count = usize::try_from(c).map_err(|_| SimError::ManyBodies {
                message: format!("--count {c} does not fit this machine"),
            })?;
        }
        if let Some(s) = seed {
            spec.seed = s;
        }
    }
    let out = out.unwrap_or_else(|| default_path(&stem, "-many-bodies.csv"));
    output::refuse_clobbering(&[&out], &[scene_path])?;
    let (spec, steps, _) = many_bodies::plan(&scene)?;
    let cost = scene.step_cost(false)?;
    many_bodies::estimate(&spec, steps, scene.method.stages(), cost)
        .check("many-bodies", overrides.allow_large)?;
    let bar = show_progress().then(|| {
        let b = indicatif::ProgressBar::new(spec.count as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} bodies (eta {eta})",
        ) {
            b.set_style(style);
        }
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        b
    });
    let ran = many_bodies::run(&scene, threads.map(|t| t as usize), scalar, bar.as_ref());
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let result = ran?;
    output::write_atomic(&out, &result.csv(&scene))?;

    let n = spec.count;
    say!("lie-sim many-bodies: {} ({})", scene.name, scene.source);
    say!("  system       {}", scene.system.kind());
    say!("  method       {}", scene.method);
    say!("  path         {}", result.path);
    say!(
        "  bodies       {n} {} (seed {})",
        spec.kind.name(),
        spec.seed
    );
    say!(
        "  steps        {steps} × h = {} to T = {}; a row every {} steps",
        result.h,
        scene.duration,
        spec.stride
    );
    say!(
        "  threads      {}",
        match threads {
            Some(1) => "1 (sequential)".to_string(),
            Some(t) => t.to_string(),
            None => format!("{} (one per core)", rayon::current_num_threads()),
        }
    );
    say!(
        "  wall time    {} ({:.3e} body-steps/s)",
        human_duration(result.wall),
        n as f64 * steps as f64 / result.wall.as_secs_f64().max(1e-9)
    );
    let show = |x: Option<f64>| x.map_or_else(|| "—".to_string(), |x| format!("{x:.4e}"));
    for row in [result.rows.first(), result.rows.last()]
        .into_iter()
        .flatten()
    {
        say!(
            "  t = {:<9} running {} / {n}; |E − E₀| mean {} max {} p99 ≤ {}; ⟨cos θ⟩ {} ⟨P₂⟩ {}; T_rot {}",
            row.time,
            row.running(),
            show(row.energy_error_mean()),
            show(Some(row.energy_error_max())),
            show(row.energy_error_quantile(0.99)),
            show(row.cos_mean()),
            show(row.p2_mean()),
            show(row.temperature()),
        );
    }
    say!(
        "  statistics   {} ({} rows)",
        out.display(),
        result.rows.len()
    );
    if let Some(kib) = sweep::peak_resident_kib() {
        say!("  peak memory  {:.1} MiB resident", kib as f64 / 1024.0);
    }
    Ok(())
}

#[allow(clippy::too_many_arguments)] // one per command-line option
fn cmd_choose(
    scene_path: Option<&Path>,
    target: f64,
    metric: choose::Metric,
    budget: std::time::Duration,
    levels: u32,
    ratio: f64,
    write: Option<PathBuf>,
    reference_args: &ReferenceArgs,
    overrides: OverrideArgs,
) -> Result<(), SimError> {
    if let Some(w) = &write {
        let inputs: Vec<&Path> = scene_path
            .into_iter()
            .chain(reference_args.reference.as_deref())
            .collect();
        output::refuse_clobbering(&[w], &inputs)?;
    }
    let (scene, _) = load(scene_path, overrides)?;
    let spinner = show_progress().then(|| {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_message(format!("choose: measuring (budget {budget:?})"));
        b.enable_steady_tick(std::time::Duration::from_millis(200));
        b
    });
    let choice = choose::choose(
        &scene,
        target,
        metric,
        levels as usize,
        ratio,
        budget,
        &reference_args.options(),
    );
    if let Some(b) = spinner {
        b.finish_and_clear();
    }
    let choice = choice?;
    let what = match metric {
        choose::Metric::Error => "error at T",
        choose::Metric::Energy => "max |dE/E|",
    };
    let floor = choice.floor.unwrap_or(0.0);
    let Some(best) = &choice.best else {
        let reached = choice.most_accurate.as_ref().map_or_else(
            || "no run completed".to_string(),
            |c| {
                if c.value < floor {
                    format!(
                        "the best run ({} at {}) is below the reference's estimated error \
                         {floor:.1e} (unresolved)",
                        c.method,
                        c.setting()
                    )
                } else {
                    format!(
                        "the best run reached {:.2e} ({} at {})",
                        c.value,
                        c.method,
                        c.setting()
                    )
                }
            },
        );
        return Err(SimError::Choose {
            message: format!(
                "no method meets {what} ≤ {target:e} on {} within the budget ({} runs{}); {reached}",
                scene.name,
                choice.runs,
                if choice.truncated { ", budget exhausted" } else { "" }
            ),
        });
    };
    say!(
        "lie-sim choose: {} ({}), T = {}",
        scene.name,
        scene.system.kind(),
        scene.duration
    );
    say!("  target       {what} ≤ {target:e}");
    if let Some(r) = &choice.reference {
        say!("  reference    {r}");
    }
    if let Some(line) = &choice.shortfall {
        say!("  reference    {line}");
    }
    let show = |c: &choose::Candidate| {
        format!(
            "{} at {}: {what} {}, {} ({:.0} ns per unit of time)",
            c.method,
            c.setting(),
            if c.value < floor {
                format!("unresolved (below the reference's estimated error {floor:.1e})")
            } else {
                format!("{:.2e}", c.value)
            },
            human_duration(std::time::Duration::from_secs_f64(c.seconds)),
            c.seconds * 1e9 / scene.duration
        )
    };
    say!("  chosen       {}", show(best));
    match &choice.runner_up {
        Some(r) => say!("  runner-up    {}", show(r)),
        None => say!("  runner-up    (no other method met the target)"),
    }
    say!(
        "  searched     {} runs{}",
        choice.runs,
        if choice.truncated {
            " (budget exhausted before the finest steps)"
        } else {
            ""
        }
    );
    if let Some(w) = write {
        let text = match scene_path {
            Some(p) => input::read_text(p)?,
            None => scene::DEFAULT_SCENE.to_string(),
        };
        let chosen_text = choose::scene_with(&text, best, scene.duration)?;
        output::write_atomic(&w, &chosen_text)?;
        say!("  scene        {}", w.display());
    }
    Ok(())
}

/// The shard of a Slurm job-array task: `SLURM_ARRAY_TASK_ID − SLURM_ARRAY_TASK_MIN` of
/// `SLURM_ARRAY_TASK_COUNT` (`None` outside a job array; an error naming the variable when one is
/// set but not a valid shard).
fn slurm_shard() -> Result<Option<Shard>, SimError> {
    let var = |name: &str| std::env::var(name).ok();
    let (Some(id), Some(count)) = (var("SLURM_ARRAY_TASK_ID"), var("SLURM_ARRAY_TASK_COUNT"))
    else {
        return Ok(None);
    };
    let num = |name: &str, v: &str| {
        v.trim().parse::<usize>().map_err(|_| SimError::Sweep {
            message: format!("{name} = {v:?} is not a non-negative integer"),
        })
    };
    let id = num("SLURM_ARRAY_TASK_ID", &id)?;
    let count = num("SLURM_ARRAY_TASK_COUNT", &count)?;
    let min = match var("SLURM_ARRAY_TASK_MIN") {
        Some(m) => num("SLURM_ARRAY_TASK_MIN", &m)?,
        None => 0,
    };
    let index = id.checked_sub(min).ok_or_else(|| SimError::Sweep {
        message: format!("SLURM_ARRAY_TASK_ID = {id} is below SLURM_ARRAY_TASK_MIN = {min}"),
    })?;
    Shard::new(index, count)
        .map(Some)
        .map_err(|e| SimError::Sweep {
            message: format!("the Slurm array task {index} of {count}: {e}"),
        })
}

fn cmd_merge(shards: &[PathBuf], out: &Path) -> Result<(), SimError> {
    let inputs: Vec<&Path> = shards.iter().map(PathBuf::as_path).collect();
    output::refuse_clobbering(&[out], &inputs)?;
    let (text, files, members) = sweep::merge(shards)?;
    sweep::write(out, &text)?;
    say!(
        "lie-sim merge: {files} shard files, {members} members, to {}",
        out.display()
    );
    Ok(())
}

fn main() -> ExitCode {
    output::install_signal_cleanup();
    // The help lists the registry's methods and systems, derived from them.
    let matches = Cli::command()
        .after_long_help(listing::help())
        .get_matches();
    let cli = match Cli::from_arg_matches(&matches) {
        Ok(cli) => cli,
        Err(e) => e.exit(),
    };
    QUIET.store(cli.quiet, std::sync::atomic::Ordering::Relaxed);
    let result = match cli.command {
        None => cmd_run(
            None,
            None,
            Some(default_path("default", ".svg")),
            None,
            OverrideArgs {
                duration: None,
                duration_flag: None,
                step: None,
                stride: None,
                allow_large: false,
            },
        ),
        Some(Command::Run {
            scene,
            out,
            plot,
            check,
            reference,
            overrides,
        }) => {
            let check = (check || reference.reference.is_some()).then_some(&reference);
            cmd_run(scene.as_deref(), out, plot, check, overrides)
        }
        Some(Command::Plot { csv, out }) => cmd_plot(&csv, out),
        Some(Command::Trade {
            scene,
            out,
            plot,
            steps,
            levels,
            ratio,
            metric,
            horizon,
            repeats,
            reference,
            write_reference,
            mut overrides,
        }) => {
            if horizon.is_some() {
                overrides.duration = horizon;
                overrides.duration_flag = Some("--horizon");
            }
            cmd_trade(
                scene.as_deref(),
                out,
                plot,
                steps,
                levels,
                ratio,
                metric,
                repeats,
                &reference,
                write_reference,
                overrides,
            )
        }
        Some(Command::Sweep {
            scene,
            out,
            shard,
            threads,
            count,
            seed,
            scalar,
            overrides,
        }) => cmd_sweep(&scene, out, shard, threads, count, seed, scalar, overrides),
        Some(Command::Merge { shards, out }) => cmd_merge(&shards, &out),
        Some(Command::ManyBodies {
            scene,
            out,
            threads,
            count,
            seed,
            scalar,
            shard,
            overrides,
        }) => cmd_many_bodies(&scene, out, threads, count, seed, scalar, shard, overrides),
        Some(Command::Choose {
            scene,
            target,
            metric,
            horizon,
            budget,
            levels,
            ratio,
            write,
            reference,
            mut overrides,
        }) => {
            if horizon.is_some() {
                overrides.duration = horizon;
                overrides.duration_flag = Some("--horizon");
            }
            cmd_choose(
                scene.as_deref(),
                target,
                metric,
                budget,
                levels,
                ratio,
                write,
                &reference,
                overrides,
            )
        }
        Some(Command::Methods { markdown }) => listing::listing(markdown).map(|text| {
            use std::io::Write as _;
            let _ = write!(std::io::stdout(), "{text}");
        }),
        Some(Command::DefaultScene) => {
            {
                use std::io::Write as _;
                let _ = write!(std::io::stdout(), "{}", scene::DEFAULT_SCENE);
            }
            Ok(())
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("lie-sim: error: {e}");
            ExitCode::FAILURE
        }
    }
}
