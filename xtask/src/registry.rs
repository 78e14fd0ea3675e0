//! Every generated table and figure of README.md and docs/, in one list: the generator's name
//! (`cargo xtask docs --only NAME`), the command of the repository it runs, and the regions and
//! files it writes. A region in a Markdown file names its generator in its marker
//! ([`crate::region`]); `cargo xtask docs --check` fails on a marker this list does not hold, and
//! on a region this list declares that its file lacks.

use crate::criterion::{Ratio, Table};

/// A generator: what `cargo xtask docs --only NAME` runs and writes.
pub struct Generator {
    pub name: &'static str,
    /// What it produces, in words.
    pub about: &'static str,
    /// Roughly how long it takes on the 2-core development machine, builds not counted (the
    /// trades and benches scale with the machine's speed and load).
    pub takes: &'static str,
    pub how: How,
}

/// A region of a Markdown file: the file (from the repository root) and the part's name (`""`
/// when the generator writes one region in that file).
#[derive(Debug, Clone, Copy)]
pub struct At {
    pub file: &'static str,
    pub part: &'static str,
}

/// What a generator runs, and how its output becomes regions and files.
pub enum How {
    /// `lie-sim trade ARGS --out CSV` (the SVG beside it), and tables read off the CSV.
    Trade(Trade),
    /// One criterion run of a bench binary, and tables of it.
    Bench(Bench),
    /// Instruction counts of `examples/step_cost.rs` under callgrind.
    Callgrind(&'static [CallgrindTable]),
    /// One `cargo test --release -p CRATE --test BINARY -- --nocapture --test-threads 1` run over
    /// the parts' test-name prefixes; each part gets the lines its tests print.
    Tests(Tests),
    /// Commands' stdout into one region (`{out}` in an argument: a scratch file moved to `out`).
    Output(Output),
    /// The machine the figures were measured on: `lscpu`, `rustc --version`, the load average.
    Machine(At),
    /// This list itself, as a table (README.md's Documentation section).
    List(At),
    /// A source file of the repository shown whole in a ```rust block, so that a page shows the
    /// code CI compiles and runs; `--check` fails when the block and the file differ.
    Source { file: &'static str, at: At },
}

pub struct Trade {
    /// The CSV in the repository (the SVG has the same stem).
    pub csv: &'static str,
    /// The scene and options after `trade`.
    pub args: &'static [&'static str],
    /// The CSV column the summaries pick runs by: `error` (at T) or `max_energy_error`.
    pub metric: &'static str,
    pub targets: &'static [f64],
    pub parts: &'static [(At, TradePart)],
}

/// A region made from a trade.
#[derive(Debug, Clone, Copy)]
pub enum TradePart {
    /// The command, the ladder and the reference it printed, and the fitted orders.
    Run,
    /// The cheapest baseline against the cheapest geometric run per target, `exclude`d methods
    /// left out.
    Summary { exclude: &'static [&'static str] },
    /// The cheapest run of each family per target.
    Families,
    /// Plain Lie–Poisson τ = exp against Cayley at θ, step by step.
    Tau { theta: &'static str },
    /// The cheapest geometric run on fixed steps, baseline run to a tolerance and run with
    /// reversible steps per target (its own `targets`: those of issue #27 among them), and their
    /// cost ratios.
    Steppers { targets: &'static [f64] },
}

pub struct Bench {
    /// The bench target of the `lie-integrators` package (`benches/NAME.rs`).
    pub bench: &'static str,
    /// A criterion filter (a regular expression on the benchmark ids).
    pub filter: Option<&'static str>,
    /// `--measurement-time` in seconds.
    pub measurement_time: u32,
    pub tables: &'static [(At, Table)],
}

pub struct CallgrindTable {
    pub at: At,
    /// The `step_cost` method the others are divided by.
    pub competitor: &'static str,
    pub rows: &'static [&'static str],
}

pub struct Tests {
    pub krate: &'static str,
    pub binary: &'static str,
    /// Each region, and the test-name prefixes whose output it holds.
    pub parts: &'static [(At, &'static [&'static str])],
}

pub struct Output {
    /// Each command's cargo arguments.
    pub runs: &'static [&'static [&'static str]],
    pub at: At,
    /// How the output is set: as a text block (with each command line when several), or as
    /// Markdown the command writes itself.
    pub markdown: bool,
    /// Lines starting with one of these are left out (a path, a wall-clock total).
    pub drop: &'static [&'static str],
    /// A file the command writes to `{out}`, moved here when every command succeeded.
    pub out: Option<&'static str>,
}

impl Generator {
    /// Every region the generator writes.
    pub fn regions(&self) -> Vec<At> {
        match &self.how {
            How::Trade(t) => t.parts.iter().map(|(a, _)| *a).collect(),
            How::Bench(b) => b.tables.iter().map(|(a, _)| *a).collect(),
            How::Callgrind(tables) => tables.iter().map(|t| t.at).collect(),
            How::Tests(t) => t.parts.iter().map(|(a, _)| *a).collect(),
            How::Output(o) => vec![o.at],
            How::Machine(a) | How::List(a) | How::Source { at: a, .. } => vec![*a],
        }
    }

    /// Every other file it writes (CSV, SVG).
    pub fn files(&self) -> Vec<String> {
        match &self.how {
            How::Trade(t) => vec![t.csv.to_string(), svg_of(t.csv)],
            How::Output(o) => o.out.iter().map(|s| s.to_string()).collect(),
            _ => Vec::new(),
        }
    }
}

/// The SVG beside a trade CSV.
pub fn svg_of(csv: &str) -> String {
    format!("{}.svg", csv.strip_suffix(".csv").unwrap_or(csv))
}

const WP: &str = "docs/work-precision.md";
const BENCH: &str = "docs/benchmarks.md";
const RESULTS: &str = "docs/results.md";
const VEHICLES: &str = "docs/vehicles.md";
const CHOOSING: &str = "docs/choosing.md";

/// The methods that are the free body's exact flow when there is no potential.
const EXACT: &[&str] = &["exact", "kinetic-kick", "processed-kinetic-kick"];
const ERROR_TARGETS: &[f64] = &[1e-4, 1e-6, 1e-8, 1e-10];
const ENERGY_TARGETS: &[f64] = &[1e-3, 1e-5, 1e-7, 1e-9];
/// The embedded pairs' fixed steps and accepted steps under error control (`examples/step_cost.rs`).
const ADAPTIVE_FREE: &[&str] = &[
    "free/fixed/dopri5",
    "free/adaptive/dopri5",
    "free/adaptive/dop853",
    "free/fixed/rkmk-dopri5",
    "free/adaptive/rkmk-dopri5",
    "free/fixed/rkmk-dop853",
    "free/adaptive/rkmk-dop853",
];
const ADAPTIVE_TOP: &[&str] = &[
    "top/fixed/dopri5",
    "top/adaptive/dopri5",
    "top/adaptive/dop853",
    "top/fixed/rkmk-dopri5",
    "top/adaptive/rkmk-dopri5",
    "top/fixed/rkmk-dop853",
    "top/adaptive/rkmk-dop853",
];

/// `lie-sim sweep examples/scenes/sweep-rotors.toml --threads 1` with more arguments, as the
/// cargo arguments of one run of the `sweep-batched` generator.
macro_rules! sweep_rotors {
    ($($arg:literal),* $(,)?) => {
        &[
            "run",
            "--release",
            "-q",
            "-p",
            "lie-sim",
            "--",
            "sweep",
            "examples/scenes/sweep-rotors.toml",
            "--threads",
            "1",
            $($arg),*
        ]
    };
}

/// A vehicle scene's trade on its automatic ladder: its run and its summary in work-precision.md.
macro_rules! vehicle {
    ($name:literal, $csv:literal, $args:expr, $takes:literal, $run:literal, $summary:literal $(,)?) => {
        Generator {
            name: $name,
            about: "a vehicle scene's trade on its automatic ladder",
            takes: $takes,
            how: How::Trade(Trade {
                csv: $csv,
                args: $args,
                metric: "error",
                targets: ERROR_TARGETS,
                parts: &[
                    (
                        At {
                            file: WP,
                            part: $run,
                        },
                        TradePart::Run,
                    ),
                    (
                        At {
                            file: WP,
                            part: $summary,
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                ],
            }),
        }
    };
}

/// The generators, in the order `cargo xtask docs` runs them (cheap first).
pub fn all() -> Vec<Generator> {
    vec![
        Generator {
            name: "generators",
            about: "this list, as README.md's table of generators",
            takes: "instant",
            how: How::List(At {
                file: "README.md",
                part: "",
            }),
        },
        Generator {
            name: "default-scene",
            about: "the default scene's summary (README's quick tour)",
            takes: "1 s",
            how: How::Output(Output {
                runs: &[&["run", "--release", "-q", "-p", "lie-sim"]],
                at: At {
                    file: "README.md",
                    part: "",
                },
                markdown: false,
                drop: &[],
                out: None,
            }),
        },
        Generator {
            name: "slew-run",
            about: "the reaction-wheel slew's run summary: the angle the platform turns, the \
                    energy change and the motors' work (docs/vehicles.md)",
            takes: "1 s",
            how: How::Output(Output {
                runs: &[&[
                    "run",
                    "--release",
                    "-q",
                    "-p",
                    "lie-sim",
                    "--",
                    "run",
                    "examples/scenes/reaction-wheel-slew.toml",
                ]],
                at: At {
                    file: VEHICLES,
                    part: "",
                },
                markdown: false,
                drop: &["  wall time"],
                out: None,
            }),
        },
        Generator {
            name: "tolerance-run",
            about: "a run to a tolerance: the separatrix tumble with DOP853 at 1e-9, its accepted \
                    and rejected steps and its smallest and largest step (docs/tolerances.md)",
            takes: "1 s",
            how: How::Output(Output {
                runs: &[&[
                    "run",
                    "--release",
                    "-q",
                    "-p",
                    "lie-sim",
                    "--",
                    "run",
                    "examples/scenes/separatrix-tumble-tolerance.toml",
                ]],
                at: At {
                    file: "docs/tolerances.md",
                    part: "",
                },
                markdown: false,
                drop: &["  wall time"],
                out: None,
            }),
        },
        Generator {
            name: "methods",
            about: "`lie-sim methods --markdown`: the method registry, each configuration's \
                    MethodInfo on the example scenes, and the systems",
            takes: "1 s",
            how: How::Output(Output {
                runs: &[&[
                    "run",
                    "--release",
                    "-q",
                    "-p",
                    "lie-sim",
                    "--",
                    "methods",
                    "--markdown",
                ]],
                at: At {
                    file: "docs/choosing.md",
                    part: "methods",
                },
                markdown: true,
                drop: &[],
                out: None,
            }),
        },
        Generator {
            name: "custom-system",
            about: "the magnetic satellite's derivative check and run",
            takes: "1 s",
            how: How::Output(Output {
                runs: &[&[
                    "run",
                    "--release",
                    "-q",
                    "-p",
                    "lie-integrators",
                    "--example",
                    "custom_system",
                ]],
                at: At {
                    file: "docs/custom-systems.md",
                    part: "",
                },
                markdown: false,
                drop: &[],
                out: None,
            }),
        },
        Generator {
            name: "custom-system-source",
            about: "the magnetic satellite's source, shown whole on its page",
            takes: "instant",
            how: How::Source {
                file: "examples/custom_system.rs",
                at: At {
                    file: "docs/custom-systems.md",
                    part: "source",
                },
            },
        },
        Generator {
            name: "long-run",
            about: "10⁷-step Lie–Poisson runs: orthogonality, Casimir, energy",
            takes: "3 s",
            how: How::Output(Output {
                runs: &[&[
                    "run",
                    "--release",
                    "-q",
                    "-p",
                    "lie-integrators",
                    "--example",
                    "long_run",
                ]],
                at: At {
                    file: "docs/long-runs.md",
                    part: "",
                },
                markdown: true,
                drop: &[],
                out: None,
            }),
        },
        Generator {
            name: "machine",
            about: "the CPU, compiler and load the benchmarks ran with",
            takes: "instant",
            how: How::Machine(At {
                file: BENCH,
                part: "",
            }),
        },
        Generator {
            name: "tests-integrators",
            about: "orders, invariants and lifted-map checks printed by the integrators' tests",
            takes: "20 s",
            how: How::Tests(Tests {
                krate: "lieflow-integrators",
                binary: "methods",
                parts: &[
                    (
                        At {
                            file: RESULTS,
                            part: "orders",
                        },
                        &["order::"],
                    ),
                    (
                        At {
                            file: RESULTS,
                            part: "potential",
                        },
                        &["potential::"],
                    ),
                    (
                        At {
                            file: RESULTS,
                            part: "invariants",
                        },
                        &["invariants::"],
                    ),
                    (
                        At {
                            file: RESULTS,
                            part: "lifted-maps",
                        },
                        &["lifted_maps::", "assembled_step::"],
                    ),
                    (
                        At {
                            file: "docs/long-runs.md",
                            part: "casimir-drift",
                        },
                        &["casimir_drift::"],
                    ),
                    (
                        At {
                            file: VEHICLES,
                            part: "control-input",
                        },
                        &["control_input::"],
                    ),
                    (
                        At {
                            file: "docs/custom-systems.md",
                            part: "derivative-check",
                        },
                        &["derivative_check::"],
                    ),
                ],
            }),
        },
        Generator {
            name: "tests-mechanics",
            about: "orders and invariants printed by the models' tests",
            takes: "20 s",
            how: How::Tests(Tests {
                krate: "lieflow-mechanics",
                binary: "models",
                parts: &[
                    (
                        At {
                            file: RESULTS,
                            part: "systems",
                        },
                        &[
                            "systems_heavy_top::",
                            "systems_se3::",
                            "systems_se2::",
                            "systems_so_n::",
                        ],
                    ),
                    (
                        At {
                            file: VEHICLES,
                            part: "gyrostat",
                        },
                        &["systems_gyrostat::"],
                    ),
                    (
                        At {
                            file: VEHICLES,
                            part: "underwater-vehicle",
                        },
                        &["systems_underwater_vehicle::"],
                    ),
                    (
                        At {
                            file: VEHICLES,
                            part: "quadrotor",
                        },
                        &["systems_quadrotor::"],
                    ),
                    (
                        At {
                            file: VEHICLES,
                            part: "pendulum-3d",
                        },
                        &["systems_pendulum_3d::"],
                    ),
                    (
                        At {
                            file: VEHICLES,
                            part: "coupled-bodies",
                        },
                        &["systems_coupled_bodies::"],
                    ),
                ],
            }),
        },
        Generator {
            name: "work-precision-example",
            about: "the library-level work-precision table (examples/work_precision.rs)",
            takes: "2 min",
            how: How::Output(Output {
                runs: &[&[
                    "run",
                    "--release",
                    "-q",
                    "-p",
                    "lie-integrators",
                    "--example",
                    "work_precision",
                    "--",
                    "{out}",
                ]],
                at: At {
                    file: WP,
                    part: "library",
                },
                markdown: true,
                drop: &[],
                out: Some("docs/work-precision.csv"),
            }),
        },
        Generator {
            name: "trade-free-rigid-body",
            about: "the free body's trade over T = 10",
            takes: "40 s",
            how: How::Trade(Trade {
                csv: "docs/trade-free-rigid-body.csv",
                args: &[
                    "examples/scenes/free-rigid-body.toml",
                    "--duration",
                    "10",
                    "--steps",
                    "0.4,0.2,0.1,0.05,0.025,0.0125,0.00625",
                ],
                metric: "error",
                targets: ERROR_TARGETS,
                parts: &[
                    (
                        At {
                            file: WP,
                            part: "free-body-run",
                        },
                        TradePart::Run,
                    ),
                    (
                        At {
                            file: WP,
                            part: "free-body",
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                    (
                        At {
                            file: WP,
                            part: "free-body-stepping",
                        },
                        TradePart::Summary { exclude: EXACT },
                    ),
                    (
                        At {
                            file: "README.md",
                            part: "free-body",
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                    (
                        At {
                            file: "README.md",
                            part: "free-body-stepping",
                        },
                        TradePart::Summary { exclude: EXACT },
                    ),
                    (
                        At {
                            file: CHOOSING,
                            part: "families",
                        },
                        TradePart::Families,
                    ),
                    (
                        At {
                            file: CHOOSING,
                            part: "tau",
                        },
                        TradePart::Tau { theta: "0.5" },
                    ),
                ],
            }),
        },
        Generator {
            name: "trade-free-rigid-body-coarse",
            about: "the free body's trade with steps up to 1.6",
            takes: "50 s",
            how: How::Trade(Trade {
                csv: "docs/trade-free-rigid-body-coarse.csv",
                args: &[
                    "examples/scenes/free-rigid-body.toml",
                    "--duration",
                    "10",
                    "--steps",
                    "1.6,0.8,0.4,0.2,0.1,0.05,0.025,0.0125,0.00625",
                ],
                metric: "error",
                targets: ERROR_TARGETS,
                parts: &[
                    (
                        At {
                            file: WP,
                            part: "coarse-run",
                        },
                        TradePart::Run,
                    ),
                    (
                        At {
                            file: WP,
                            part: "coarse-stepping",
                        },
                        TradePart::Summary { exclude: EXACT },
                    ),
                    (
                        At {
                            file: WP,
                            part: "coarse",
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                ],
            }),
        },
        Generator {
            name: "trade-fast-heavy-top",
            about: "the fast asymmetric heavy top's trade over T = 5",
            takes: "1 min",
            how: How::Trade(Trade {
                csv: "docs/trade-fast-heavy-top.csv",
                args: &[
                    "examples/scenes/fast-heavy-top.toml",
                    "--steps",
                    "0.08,0.04,0.02,0.01,0.005,0.0025,0.00125,0.000625,0.0003125",
                ],
                metric: "error",
                targets: ERROR_TARGETS,
                parts: &[
                    (
                        At {
                            file: WP,
                            part: "heavy-top-run",
                        },
                        TradePart::Run,
                    ),
                    (
                        At {
                            file: WP,
                            part: "heavy-top",
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                    (
                        At {
                            file: "README.md",
                            part: "heavy-top",
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                ],
            }),
        },
        Generator {
            name: "trade-fast-heavy-top-ratio",
            about: "the fast heavy top on the automatic ladder at ratio √2",
            takes: "1.5 min",
            how: How::Trade(Trade {
                csv: "docs/trade-fast-heavy-top-ratio.csv",
                args: &[
                    "examples/scenes/fast-heavy-top.toml",
                    "--ratio",
                    "1.41421356",
                ],
                metric: "error",
                targets: ERROR_TARGETS,
                parts: &[
                    (
                        At {
                            file: WP,
                            part: "heavy-top-ratio-run",
                        },
                        TradePart::Run,
                    ),
                    (
                        At {
                            file: WP,
                            part: "heavy-top-ratio",
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                ],
            }),
        },
        Generator {
            name: "trade-free-rigid-body-energy",
            about: "the free body's maximum energy error over T = 1000",
            takes: "1 min",
            how: How::Trade(Trade {
                csv: "docs/trade-free-rigid-body-energy.csv",
                args: &[
                    "examples/scenes/free-rigid-body.toml",
                    "--duration",
                    "1000",
                    "--steps",
                    "0.4,0.2,0.1,0.05,0.025",
                    "--metric",
                    "energy",
                ],
                metric: "max_energy_error",
                targets: ENERGY_TARGETS,
                parts: &[
                    (
                        At {
                            file: WP,
                            part: "energy-run",
                        },
                        TradePart::Run,
                    ),
                    (
                        At {
                            file: WP,
                            part: "energy",
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                    (
                        At {
                            file: WP,
                            part: "energy-stepping",
                        },
                        TradePart::Summary { exclude: EXACT },
                    ),
                ],
            }),
        },
        Generator {
            name: "trade-free-rigid-body-energy-coarse",
            about: "the free body's energy over T = 1000 with steps up to 1.6",
            takes: "1.5 min",
            how: How::Trade(Trade {
                csv: "docs/trade-free-rigid-body-energy-coarse.csv",
                args: &[
                    "examples/scenes/free-rigid-body.toml",
                    "--duration",
                    "1000",
                    "--steps",
                    "1.6,0.8,0.4,0.2,0.1,0.05,0.025",
                    "--metric",
                    "energy",
                ],
                metric: "max_energy_error",
                targets: ENERGY_TARGETS,
                parts: &[
                    (
                        At {
                            file: WP,
                            part: "energy-coarse-run",
                        },
                        TradePart::Run,
                    ),
                    (
                        At {
                            file: WP,
                            part: "energy-coarse-stepping",
                        },
                        TradePart::Summary { exclude: EXACT },
                    ),
                ],
            }),
        },
        vehicle!(
            "trade-reaction-wheel-slew",
            "docs/trade-reaction-wheel-slew.csv",
            &[
                "examples/scenes/reaction-wheel-slew.toml",
                "--horizon",
                "60"
            ],
            "2 min",
            "reaction-wheel-slew-run",
            "reaction-wheel-slew",
        ),
        vehicle!(
            "trade-underwater-vehicle",
            "docs/trade-underwater-vehicle.csv",
            &["examples/scenes/underwater-vehicle.toml", "--horizon", "30"],
            "2 min",
            "underwater-vehicle-run",
            "underwater-vehicle",
        ),
        vehicle!(
            "trade-quadrotor",
            "docs/trade-quadrotor.csv",
            &["examples/scenes/quadrotor.toml", "--horizon", "5"],
            "30 s",
            "quadrotor-run",
            "quadrotor",
        ),
        vehicle!(
            "trade-pendulum-3d",
            "docs/trade-pendulum-3d.csv",
            &["examples/scenes/pendulum-3d.toml", "--horizon", "5"],
            "30 s",
            "pendulum-3d-run",
            "pendulum-3d",
        ),
        vehicle!(
            "trade-coupled-bodies",
            "docs/trade-coupled-bodies.csv",
            &["examples/scenes/coupled-bodies.toml", "--horizon", "5"],
            "1.5 min",
            "coupled-bodies-run",
            "coupled-bodies",
        ),
        Generator {
            name: "trade-eccentric-orbit",
            about: "a vehicle scene's trade on its automatic ladder of ratio √2 (twice the points: the reversible runs' ε rungs are the ladder's)",
            takes: "6 min",
            how: How::Trade(Trade {
                csv: "docs/trade-eccentric-orbit.csv",
                args: &[
                    "examples/scenes/eccentric-orbit.toml",
                    "--ratio",
                    "1.4142135623730951",
                ],
                metric: "error",
                targets: ERROR_TARGETS,
                parts: &[
                    (
                        At {
                            file: WP,
                            part: "eccentric-orbit-run",
                        },
                        TradePart::Run,
                    ),
                    (
                        At {
                            file: WP,
                            part: "eccentric-orbit",
                        },
                        TradePart::Summary { exclude: &[] },
                    ),
                    (
                        At {
                            file: WP,
                            part: "eccentric-orbit-steppers",
                        },
                        TradePart::Steppers {
                            targets: &[1e-4, 1e-6, 1e-8, 1e-9, 1e-10],
                        },
                    ),
                ],
            }),
        },
        Generator {
            name: "choose-examples",
            about: "`lie-sim choose` on the free body and the fast heavy top",
            takes: "1.5 min",
            how: How::Output(Output {
                runs: &[
                    &[
                        "run",
                        "--release",
                        "-q",
                        "-p",
                        "lie-sim",
                        "--",
                        "choose",
                        "examples/scenes/free-rigid-body.toml",
                        "--duration",
                        "10",
                        "--target",
                        "1e-10",
                    ],
                    &[
                        "run",
                        "--release",
                        "-q",
                        "-p",
                        "lie-sim",
                        "--",
                        "choose",
                        "examples/scenes/fast-heavy-top.toml",
                        "--target",
                        "1e-6",
                    ],
                    &[
                        "run",
                        "--release",
                        "-q",
                        "-p",
                        "lie-sim",
                        "--",
                        "choose",
                        "examples/scenes/fast-heavy-top.toml",
                        "--target",
                        "1e-6",
                        "--step",
                        "0.08",
                    ],
                ],
                at: At {
                    file: CHOOSING,
                    part: "choose",
                },
                markdown: false,
                drop: &[],
                out: None,
            }),
        },
        Generator {
            name: "bench-lie-groups",
            about: "SO(3) and SE(3) operations against nalgebra's",
            takes: "2 min",
            how: How::Bench(Bench {
                bench: "lie_groups",
                filter: None,
                measurement_time: 2,
                tables: &[
                    (
                        At {
                            file: BENCH,
                            part: "lie-groups",
                        },
                        Table::Pivot {
                            groups: &[
                                "so3/compose",
                                "so3/inverse",
                                "so3/exp",
                                "so3/log",
                                "so3/act",
                                "se3/compose",
                                "se3/inverse",
                                "se3/act",
                            ],
                            ratio: Some((
                                &["So3", "Se3"],
                                &["UnitQuaternion", "Rotation3", "Isometry3"],
                            )),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "lie-groups-maps",
                        },
                        Table::Pivot {
                            groups: &[
                                "so3/adjoint",
                                "so3/tangent",
                                "se3/exp_log",
                                "se3/adjoint",
                                "se3/tangent",
                            ],
                            ratio: None,
                        },
                    ),
                ],
            }),
        },
        Generator {
            name: "bench-matrix-groups",
            about: "SO(2), SE(2) and SO(n) operations",
            takes: "1 min",
            how: How::Bench(Bench {
                bench: "matrix_groups",
                filter: None,
                measurement_time: 2,
                tables: &[(
                    At {
                        file: BENCH,
                        part: "matrix-groups",
                    },
                    Table::List {
                        prefix: "",
                        competitor: None,
                    },
                )],
            }),
        },
        Generator {
            name: "bench-bundles",
            about: "TG and TTG products against their parts",
            takes: "1 min",
            how: How::Bench(Bench {
                bench: "bundles",
                filter: None,
                measurement_time: 2,
                tables: &[(
                    At {
                        file: BENCH,
                        part: "bundles",
                    },
                    Table::Pivot {
                        groups: &[""],
                        ratio: Some((&["TG"], &["G parts of TG"])),
                    },
                )],
            }),
        },
        Generator {
            name: "bench-discretization",
            about: "the discretization maps and their lifts",
            takes: "2 min",
            how: How::Bench(Bench {
                bench: "discretization",
                filter: None,
                measurement_time: 1,
                tables: &[(
                    At {
                        file: BENCH,
                        part: "discretization",
                    },
                    Table::Pivot {
                        groups: &[""],
                        ratio: None,
                    },
                )],
            }),
        },
        Generator {
            name: "bench-integrators",
            about:
                "one step of every integrator on the free body and the heavy top, the solver kinds",
            takes: "4 min",
            how: How::Bench(Bench {
                bench: "integrators",
                filter: Some("rigid_body|heavy_top"),
                measurement_time: 2,
                tables: &[
                    (
                        At {
                            file: BENCH,
                            part: "integrators-targets",
                        },
                        Table::Ratios(&[
                            Ratio {
                                what: "Lie–Poisson Cayley θ = 0 with R",
                                id: "rigid_body/step/lp/cayley/0+g",
                                against: "rigid_body/step/rk4-hand-written+g",
                                bound: Some(1.3),
                            },
                            Ratio {
                                what: "Lie–Poisson Cayley θ = ½ with R",
                                id: "rigid_body/step/lp/cayley/0.5+g",
                                against: "rigid_body/step/rk4-hand-written+g",
                                bound: Some(1.5),
                            },
                            Ratio {
                                what: "`QuaternionRk4`, free body",
                                id: "rigid_body/step/rk4-quaternion+g",
                                against: "rigid_body/step/rk4-hand-written+g",
                                bound: None,
                            },
                            Ratio {
                                what: "`QuaternionRk4`, heavy top",
                                id: "heavy_top/step/rk4-quaternion+g",
                                against: "heavy_top/step/rk4-hand-written+g",
                                bound: None,
                            },
                        ]),
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "integrators-free-body",
                        },
                        Table::List {
                            prefix: "rigid_body/step/",
                            competitor: Some("rigid_body/step/rk4-hand-written+g"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "integrators-solver",
                        },
                        Table::List {
                            prefix: "rigid_body/solver/",
                            competitor: Some("rigid_body/step/rk4-hand-written+g"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "integrators-heavy-top",
                        },
                        Table::List {
                            prefix: "heavy_top/step/",
                            competitor: Some("heavy_top/step/rk4-hand-written+g"),
                        },
                    ),
                ],
            }),
        },
        Generator {
            name: "bench-so-n",
            about: "one step on SO(n), n = 10, 20, 50",
            takes: "5 min",
            how: How::Bench(Bench {
                bench: "integrators",
                filter: Some("so_n"),
                measurement_time: 2,
                tables: &[(
                    At {
                        file: BENCH,
                        part: "so-n",
                    },
                    Table::List {
                        prefix: "so_n/step/",
                        competitor: None,
                    },
                )],
            }),
        },
        Generator {
            name: "bench-splitting",
            about: "the trade's methods per step against the hand-written RK4",
            takes: "5 min",
            how: How::Bench(Bench {
                bench: "splitting",
                filter: Some("trade/"),
                measurement_time: 2,
                tables: &[
                    (
                        At {
                            file: BENCH,
                            part: "splitting-targets",
                        },
                        Table::Ratios(&[
                            Ratio {
                                what:
                                    "the exact flow to T = 1000, with R, in hand-written RK4 steps",
                                id: "trade/exact_flow/advance/T=1000+g",
                                against: "trade/free_body/rk4-hand-written+g",
                                bound: Some(20.0),
                            },
                            Ratio {
                                what: "a Strang step with R, free body",
                                id: "trade/free_body/splitting-strang+g",
                                against: "trade/free_body/rk4-hand-written+g",
                                bound: Some(1.2),
                            },
                            Ratio {
                                what: "a Strang step, heavy top",
                                id: "trade/heavy_top/splitting-strang+g",
                                against: "trade/heavy_top/rk4-hand-written+g",
                                bound: Some(1.2),
                            },
                            Ratio {
                                what: "Lie–Poisson Cayley θ = 0 with R",
                                id: "trade/free_body/lp/cayley/0+g",
                                against: "trade/free_body/rk4-hand-written+g",
                                bound: Some(1.3),
                            },
                            Ratio {
                                what: "Lie–Poisson Cayley θ = ½ with R",
                                id: "trade/free_body/lp/cayley/0.5+g",
                                against: "trade/free_body/rk4-hand-written+g",
                                bound: Some(1.5),
                            },
                        ]),
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "splitting-free-body",
                        },
                        Table::List {
                            prefix: "trade/free_body/",
                            competitor: Some("trade/free_body/rk4-hand-written+g"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "splitting-exact-flow",
                        },
                        Table::List {
                            prefix: "trade/exact_flow/",
                            competitor: Some("trade/free_body/rk4-hand-written+g"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "splitting-heavy-top",
                        },
                        Table::List {
                            prefix: "trade/heavy_top/",
                            competitor: Some("trade/heavy_top/rk4-hand-written+g"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "splitting-satellite",
                        },
                        Table::List {
                            prefix: "trade/satellite/",
                            competitor: Some("trade/satellite/rkmk4+g"),
                        },
                    ),
                ],
            }),
        },
        Generator {
            name: "bench-run-loop",
            about: "`lie-sim run`'s loop against the same steps as `trade` times them",
            takes: "1 min",
            how: How::Bench(Bench {
                bench: "run_loop",
                filter: None,
                measurement_time: 4,
                tables: &[(
                    At {
                        file: BENCH,
                        part: "run-loop",
                    },
                    Table::Ratios(&[
                        Ratio {
                            what: "Lie–Poisson Cayley θ = ½ with R",
                            id: "run_loop/lie_poisson_cayley_half/run",
                            against: "run_loop/lie_poisson_cayley_half/steps",
                            bound: Some(1.2),
                        },
                        Ratio {
                            what: "RK4 on (q, Π)",
                            id: "run_loop/rk4/run",
                            against: "run_loop/rk4/steps",
                            bound: Some(1.2),
                        },
                        Ratio {
                            what: "the Strang splitting with R",
                            id: "run_loop/splitting/run",
                            against: "run_loop/splitting/steps",
                            bound: Some(1.2),
                        },
                    ]),
                )],
            }),
        },
        Generator {
            name: "callgrind-step-cost",
            about: "instructions per step of the trade's methods (valgrind)",
            takes: "5 min",
            how: How::Callgrind(&[
                CallgrindTable {
                    at: At {
                        file: BENCH,
                        part: "callgrind-free-body",
                    },
                    competitor: "free/rk4-hand",
                    rows: &[
                        "free/rk4",
                        "free/rkmk4",
                        "free/strang",
                        "free/lp-cayley-0.5",
                        "free/lp-cayley-0",
                        "free/modified/cayley/0.5/4",
                        "free/modified/cayley/0.5/6",
                        "free/modified/cayley/0/4",
                        "free/modified/cayley/0/6",
                        "free/modified/exp/0.5/4",
                        "free/modified/exp/0.5/6",
                        "free/modified/exp/0/4",
                        "free/modified/exp/0/6",
                        "free/processed/blanes-6",
                        "free/processed/blanes-casas-murua-6-11",
                        "free/processed/blanes-casas-murua-6-13",
                        "free/processed-read/blanes-6",
                        "free/processed-read/blanes-casas-murua-6-11",
                        "free/processed-read/blanes-casas-murua-6-13",
                    ],
                },
                CallgrindTable {
                    at: At {
                        file: BENCH,
                        part: "callgrind-heavy-top",
                    },
                    competitor: "top/rk4-hand",
                    rows: &[
                        "top/rk4",
                        "top/rkmk4",
                        "top/strang",
                        "top/lp-cayley-0.5",
                        "top/lp-cayley-0",
                        "top/kinetic-kick/strang",
                        "top/kinetic-kick/blanes-moan-4",
                        "top/processed/blanes-6",
                        "top/processed/blanes-casas-murua-6-11",
                        "top/processed/blanes-casas-murua-6-13",
                        "top/processed-kk/blanes-6",
                        "top/processed-kk/blanes-casas-murua-6-11",
                    ],
                },
            ]),
        },
        Generator {
            name: "callgrind-adaptive",
            about: "instructions per accepted step of the embedded pairs, fixed against adaptive (valgrind)",
            takes: "2 min",
            how: How::Callgrind(&[
                CallgrindTable {
                    at: At {
                        file: BENCH,
                        part: "callgrind-adaptive-free-body",
                    },
                    competitor: "free/fixed/dop853",
                    rows: ADAPTIVE_FREE,
                },
                CallgrindTable {
                    at: At {
                        file: BENCH,
                        part: "callgrind-adaptive-heavy-top",
                    },
                    competitor: "top/fixed/dop853",
                    rows: ADAPTIVE_TOP,
                },
            ]),
        },
        Generator {
            name: "bench-forces",
            about: "the cost of an external force per step",
            takes: "1 min",
            how: How::Bench(Bench {
                bench: "forces",
                filter: None,
                measurement_time: 2,
                tables: &[
                    (
                        At {
                            file: BENCH,
                            part: "forces-targets",
                        },
                        Table::Ratios(&[
                            Ratio {
                                what: "Lie–Poisson, constant body torque, cold",
                                id: "forces/free_body/lp-cayley-0.5/torque",
                                against: "forces/free_body/lp-cayley-0.5/unforced",
                                bound: Some(1.2),
                            },
                            Ratio {
                                what: "Lie–Poisson, torque and damping, cold",
                                id: "forces/free_body/lp-cayley-0.5/torque+damping",
                                against: "forces/free_body/lp-cayley-0.5/unforced",
                                bound: None,
                            },
                            Ratio {
                                what: "Lie–Poisson, constant body torque, warm",
                                id: "forces/free_body/lp-cayley-0.5/torque/warm",
                                against: "forces/free_body/lp-cayley-0.5/unforced/warm",
                                bound: None,
                            },
                            Ratio {
                                what: "RK4, constant body torque",
                                id: "forces/free_body/rk4/torque",
                                against: "forces/free_body/rk4/unforced",
                                bound: None,
                            },
                        ]),
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "forces",
                        },
                        Table::List {
                            prefix: "forces/free_body/",
                            competitor: None,
                        },
                    ),
                ],
            }),
        },
        Generator {
            name: "bench-adaptive",
            about:
                "tolerance-driven runs: the embedded pairs against ode_solvers' Dopri5 and DOP853",
            takes: "4 min",
            how: How::Bench(Bench {
                bench: "adaptive",
                filter: None,
                measurement_time: 2,
                tables: &[
                    (
                        At {
                            file: BENCH,
                            part: "adaptive-free-body-1e-6",
                        },
                        Table::List {
                            prefix: "adaptive/free_body/1e-6/",
                            competitor: Some("adaptive/free_body/1e-6/ode_solvers::Dop853"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "adaptive-free-body-1e-9",
                        },
                        Table::List {
                            prefix: "adaptive/free_body/1e-9/",
                            competitor: Some("adaptive/free_body/1e-9/ode_solvers::Dop853"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "adaptive-free-body-1e-12",
                        },
                        Table::List {
                            prefix: "adaptive/free_body/1e-12/",
                            competitor: Some("adaptive/free_body/1e-12/ode_solvers::Dop853"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "adaptive-overhead-free-body",
                        },
                        Table::List {
                            prefix: "adaptive/overhead/free_body/",
                            competitor: Some(
                                "adaptive/overhead/free_body/dop853(quaternion)/fixed",
                            ),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "adaptive-heavy-top-1e-6",
                        },
                        Table::List {
                            prefix: "adaptive/fast_heavy_top/1e-6/",
                            competitor: Some("adaptive/fast_heavy_top/1e-6/ode_solvers::Dop853"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "adaptive-heavy-top-1e-9",
                        },
                        Table::List {
                            prefix: "adaptive/fast_heavy_top/1e-9/",
                            competitor: Some("adaptive/fast_heavy_top/1e-9/ode_solvers::Dop853"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "adaptive-heavy-top-1e-12",
                        },
                        Table::List {
                            prefix: "adaptive/fast_heavy_top/1e-12/",
                            competitor: Some("adaptive/fast_heavy_top/1e-12/ode_solvers::Dop853"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "adaptive-overhead-heavy-top",
                        },
                        Table::List {
                            prefix: "adaptive/overhead/fast_heavy_top/",
                            competitor: Some(
                                "adaptive/overhead/fast_heavy_top/dop853(quaternion)/fixed",
                            ),
                        },
                    ),
                ],
            }),
        },
        Generator {
            name: "bench-ensemble",
            about: "256 trajectories × 1000 steps on 1 and 2 threads",
            takes: "1 min",
            how: How::Bench(Bench {
                bench: "ensemble",
                filter: None,
                measurement_time: 5,
                tables: &[(
                    At {
                        file: BENCH,
                        part: "ensemble",
                    },
                    Table::List {
                        prefix: "ensemble_rigid_body_256x1000/",
                        competitor: Some("ensemble_rigid_body_256x1000/threads_1"),
                    },
                )],
            }),
        },
        Generator {
            name: "sweep-batched",
            about: "`lie-sim sweep` of rotors on one thread, batched and `--scalar`: 10⁶ × 200 steps, 20 000 × 2000 steps",
            takes: "1 min",
            how: How::Output(Output {
                runs: &[
                    sweep_rotors!(
                        "--count",
                        "1000000",
                        "--out",
                        "target/lie-sim/rotors-batched.csv"
                    ),
                    sweep_rotors!(
                        "--count",
                        "1000000",
                        "--scalar",
                        "--out",
                        "target/lie-sim/rotors-scalar.csv"
                    ),
                    sweep_rotors!(
                        "--count",
                        "20000",
                        "--duration",
                        "100",
                        "--out",
                        "target/lie-sim/rotors-long-batched.csv"
                    ),
                    sweep_rotors!(
                        "--count",
                        "20000",
                        "--duration",
                        "100",
                        "--scalar",
                        "--out",
                        "target/lie-sim/rotors-long-scalar.csv"
                    ),
                ],
                at: At {
                    file: "docs/ensembles.md",
                    part: "",
                },
                markdown: false,
                drop: &["  wrote"],
                out: None,
            }),
        },
        Generator {
            name: "many-dipoles",
            about: "`lie-sim many-bodies` of 10⁵ polar rotors in a field on one thread, batched and `--scalar`: statistics every 20 steps",
            takes: "1 min",
            how: How::Output(Output {
                runs: &[
                    &[
                        "run",
                        "--release",
                        "-q",
                        "-p",
                        "lie-sim",
                        "--",
                        "many-bodies",
                        "examples/scenes/many-dipoles.toml",
                        "--threads",
                        "1",
                        "--out",
                        "{out}",
                    ],
                    &[
                        "run",
                        "--release",
                        "-q",
                        "-p",
                        "lie-sim",
                        "--",
                        "many-bodies",
                        "examples/scenes/many-dipoles.toml",
                        "--threads",
                        "1",
                        "--scalar",
                        "--out",
                        "target/lie-sim/many-dipoles-scalar.csv",
                    ],
                ],
                at: At {
                    file: "docs/ensembles.md",
                    part: "",
                },
                markdown: false,
                drop: &["  statistics   "],
                out: Some("docs/many-dipoles.csv"),
            }),
        },
        Generator {
            name: "bench-batch",
            about: "16 steps of each of 1024 bodies, scalar against batched (Strang, RK4, RKMK4, the exact flow; per instruction set) and the hand-written NO_SQUISH and RK4",
            takes: "2 min",
            how: How::Bench(Bench {
                bench: "batch",
                filter: Some("batch/free_body|batch/field"),
                measurement_time: 2,
                tables: &[
                    (
                        At {
                            file: BENCH,
                            part: "batch-targets",
                        },
                        Table::Ratios(&[
                            Ratio {
                                what: "batched Strang with R, AVX-512 (target ≥ 6× the scalar step)",
                                id: "batch/free_body/batch/strang/avx512",
                                against: "batch/free_body/scalar/strang",
                                bound: Some(0.167),
                            },
                            Ratio {
                                what: "batched Strang with R, AVX2 forced (target ≥ 3×)",
                                id: "batch/free_body/batch/strang/avx2",
                                against: "batch/free_body/scalar/strang",
                                bound: Some(0.333),
                            },
                            Ratio {
                                what: "batched RK4, AVX-512 (target ≥ 4×)",
                                id: "batch/free_body/batch/rk4/avx512",
                                against: "batch/free_body/scalar/rk4",
                                bound: Some(0.25),
                            },
                            Ratio {
                                what: "batched RKMK4, AVX-512 (target ≥ 4×)",
                                id: "batch/free_body/batch/rkmk4/avx512",
                                against: "batch/free_body/scalar/rkmk4",
                                bound: Some(0.25),
                            },
                            Ratio {
                                what: "batched exact flow, AVX-512 (target ≥ 4×)",
                                id: "batch/free_body/batch/exact/avx512",
                                against: "batch/free_body/scalar/exact",
                                bound: Some(0.25),
                            },
                            Ratio {
                                what: "batched Strang, AVX-512, against the hand-written NO_SQUISH",
                                id: "batch/free_body/batch/strang/avx512",
                                against: "batch/free_body/hand/no_squish",
                                bound: None,
                            },
                            Ratio {
                                what: "batched RK4, AVX-512, against the hand-written RK4",
                                id: "batch/free_body/batch/rk4/avx512",
                                against: "batch/free_body/hand/rk4",
                                bound: None,
                            },
                        ]),
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "batch-free-body",
                        },
                        Table::List {
                            prefix: "batch/free_body/",
                            competitor: Some("batch/free_body/scalar/strang"),
                        },
                    ),
                    (
                        At {
                            file: BENCH,
                            part: "batch-field",
                        },
                        Table::List {
                            prefix: "batch/field/",
                            competitor: Some("batch/field/scalar/strang"),
                        },
                    ),
                ],
            }),
        },
        Generator {
            name: "bench-batch-size",
            about: "the batched Strang step for N = 64 … 4·10⁶ bodies: one step of all per call (through the caches to memory) and 64 steps per call (compute-bound)",
            takes: "2 min",
            how: How::Bench(Bench {
                bench: "batch",
                filter: Some("batch/size"),
                measurement_time: 2,
                tables: &[(
                    At {
                        file: BENCH,
                        part: "batch-size",
                    },
                    Table::Throughput {
                        prefix: "batch/size",
                        element: "body-step",
                    },
                )],
            }),
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_each_region_has_one_owner() {
        let gens = all();
        let mut names: Vec<&str> = gens.iter().map(|g| g.name).collect();
        names.sort_unstable();
        let n = names.len();
        names.dedup();
        assert_eq!(names.len(), n, "a generator name appears twice");
        let mut regions: Vec<(&str, String)> = gens
            .iter()
            .flat_map(|g| {
                g.regions()
                    .into_iter()
                    .map(move |a| (a.file, format!("{} {}", g.name, a.part)))
            })
            .collect();
        regions.sort();
        let n = regions.len();
        regions.dedup();
        assert_eq!(regions.len(), n, "a region is declared twice");
    }
}
