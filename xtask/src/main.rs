//! Repository tasks, run as `cargo xtask …` (the alias is in `.cargo/config.toml`).
//!
//! ```sh
//! cargo xtask docs                      # regenerate every table and figure of README.md and docs/
//! cargo xtask docs --only NAME[,NAME]   # regenerate some (names: `cargo xtask docs --list`)
//! cargo xtask docs --list               # the generators: command, duration, what they write
//! cargo xtask docs --check              # regions known, no commit-dated figure, no ns in comments
//! cargo xtask docs --reuse-csv          # the trade tables again from docs/trade-*.csv, no run
//! cargo xtask trade-summary docs/trade-free-rigid-body.csv error 1e-4 1e-6 --exclude exact
//! ```
//!
//! Each generator runs a command of the repository (`lie-sim trade`, an example, a criterion
//! bench, tests with `--nocapture`, callgrind on `examples/step_cost.rs`) and rewrites the regions
//! of the Markdown files that name it (see `region.rs`), and the CSV and SVG files it makes. A
//! generator whose command fails writes nothing; the others still run, and the task exits with
//! an error naming the ones that failed.

mod callgrind;
mod check;
mod criterion;
mod error;
mod exec;
mod format;
mod generate;
mod harnessless;
mod region;
mod registry;
mod test_output;
mod trade;

use clap::{Parser, Subcommand};
use error::Error;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[derive(Parser)]
#[command(name = "cargo xtask", about = "Repository tasks.")]
struct Cli {
    #[command(subcommand)]
    command: Task,
}

#[derive(Subcommand)]
enum Task {
    /// Regenerate the tables and figures of README.md and docs/ (all of them by default).
    Docs {
        /// Only these generators (comma-separated or repeated).
        #[arg(long, value_delimiter = ',', value_name = "NAME")]
        only: Vec<String>,
        /// List the generators and exit.
        #[arg(long, conflicts_with_all = ["only", "check"])]
        list: bool,
        /// Check the docs instead of regenerating them: every region names a known generator,
        /// every declared region exists, no commit-dated figure, no timing in a source comment.
        #[arg(long, conflicts_with = "only")]
        check: bool,
        /// Re-derive the trade tables from the trade CSVs in docs/ without running the trades
        /// (their run regions stay as they are); the other generators are skipped.
        #[arg(long, conflicts_with_all = ["list", "check"])]
        reuse_csv: bool,
    },
    /// The cheapest baseline against the cheapest geometric run per target, from a trade CSV.
    TradeSummary {
        /// A `lie-sim trade` CSV.
        csv: PathBuf,
        /// The column runs are picked by: `error` (at T), `max_energy_error`, …
        metric: String,
        /// The targets, e.g. 1e-4 1e-6.
        #[arg(required = true)]
        targets: Vec<f64>,
        /// Methods to leave out (comma-separated), e.g. `exact,kinetic-kick`.
        #[arg(long, value_delimiter = ',')]
        exclude: Vec<String>,
    },
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_else(|| PathBuf::from("."))
}

fn target_dir(root: &Path) -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .map(|p| if p.is_absolute() { p } else { root.join(p) })
        .unwrap_or_else(|| root.join("target"))
}

fn docs(only: Vec<String>, list: bool, check: bool, reuse_csv: bool) -> Result<(), Error> {
    let root = root();
    if list {
        for g in registry::all() {
            println!("{:<38} {} ({})", g.name, g.about, g.takes);
            for c in generate::commands(&g) {
                println!("{:<38}   runs   {c}", "");
            }
            for a in g.regions() {
                let part = if a.part.is_empty() {
                    String::new()
                } else {
                    format!(" ({})", a.part)
                };
                println!("{:<38}   writes {}{part}", "", a.file);
            }
            for f in g.files() {
                println!("{:<38}   writes {f}", "");
            }
        }
        return Ok(());
    }
    if check {
        let problems = check::check(&root);
        for p in &problems {
            eprintln!("{p}");
        }
        if problems.is_empty() {
            println!("docs: every region is known and no figure is dated");
            return Ok(());
        }
        return Err(Error::parse(
            "cargo xtask docs --check",
            format!("{} problems", problems.len()),
        ));
    }
    let gens = registry::all();
    for name in &only {
        if !gens.iter().any(|g| g.name == name) {
            return Err(Error::UnknownGenerator { name: name.clone() });
        }
    }
    let ctx = generate::Ctx {
        target_dir: target_dir(&root),
        root,
        reuse_csv,
    };
    let mut failed = Vec::new();
    let chosen = gens
        .iter()
        .filter(|g| only.is_empty() || only.iter().any(|n| n == g.name))
        .filter(|g| !reuse_csv || generate::reuses_csv(g));
    for g in chosen {
        let start = Instant::now();
        let result = generate::make(&ctx, g).and_then(|made| generate::commit(&ctx, g, made));
        match result {
            Ok(()) => eprintln!(
                "xtask docs: {} regenerated in {:.0} s",
                g.name,
                start.elapsed().as_secs_f64()
            ),
            Err(e) => {
                eprintln!(
                    "xtask docs: {} failed, its regions and files left as they were: {e}",
                    g.name
                );
                failed.push(g.name);
            }
        }
    }
    if failed.is_empty() {
        Ok(())
    } else {
        Err(Error::parse(
            "cargo xtask docs",
            format!("failed: {}", failed.join(", ")),
        ))
    }
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Task::Docs {
            only,
            list,
            check,
            reuse_csv,
        } => docs(only, list, check, reuse_csv),
        Task::TradeSummary {
            csv,
            metric,
            targets,
            exclude,
        } => trade::read(&csv).map(|rows| {
            let exclude: Vec<&str> = exclude.iter().map(String::as_str).collect();
            print!("{}", trade::summary(&rows, &metric, &targets, &exclude));
        }),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask: {e}");
            ExitCode::FAILURE
        }
    }
}
