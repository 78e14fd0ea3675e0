//! Running a generator and writing what it made. Nothing is written until the generator's every
//! command has succeeded and every region it writes has been found in its file: the new Markdown
//! and the files the commands wrote (into `target/xtask-docs/NAME/`) are then moved into place,
//! each by a rename, so a failed generator leaves the docs as they were.

use crate::callgrind;
use crate::criterion;
use crate::error::{Error, Result};
use crate::exec::{self, shell_line, strings};
use crate::region::{self, Key};
use crate::registry::{self, At, Generator, How, TradePart};
use crate::test_output;
use crate::trade;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Where a run happens: the repository and its target directory.
pub struct Ctx {
    pub root: PathBuf,
    pub target_dir: PathBuf,
    /// Re-derive the trade tables from the CSVs in the repository instead of running the trades
    /// (their run regions stay as they are); other generators are skipped.
    pub reuse_csv: bool,
}

impl Ctx {
    fn scratch(&self, name: &str) -> Result<PathBuf> {
        let dir = self.target_dir.join("xtask-docs").join(name);
        if dir.exists() {
            std::fs::remove_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
        }
        std::fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
        Ok(dir)
    }
}

/// What a generator made: region contents, and files to move into the repository.
#[derive(Default)]
pub struct Made {
    pub regions: Vec<(At, String)>,
    pub files: Vec<(PathBuf, PathBuf)>,
}

/// The commands a generator runs, as a reader would type them.
pub fn commands(g: &Generator) -> Vec<String> {
    match &g.how {
        How::Trade(t) => vec![trade_command(t, t.csv)],
        How::Bench(b) => vec![shell_line(
            "cargo",
            &criterion::command(b.bench, b.filter, b.measurement_time),
        )],
        How::Callgrind(_) => vec![
            "cargo build --release -p lie-integrators --example step_cost".into(),
            format!(
                "valgrind --tool=callgrind target/release/examples/step_cost METHOD N (N = {}, {})",
                callgrind::STEPS,
                2 * callgrind::STEPS
            ),
        ],
        How::Tests(t) => vec![shell_line("cargo", &tests_args(t))],
        How::Output(o) => o
            .runs
            .iter()
            .map(|args| shell_line("cargo", &substitute(args, o.out.unwrap_or(""))))
            .collect(),
        How::Machine(_) => vec!["lscpu; rustc --version; cat /proc/loadavg".into()],
        How::List(_) => vec!["the registry (xtask/src/registry.rs)".into()],
        How::Source { file, .. } => vec![format!("cat {file}")],
    }
}

fn trade_args(t: &registry::Trade, csv: &str) -> Vec<String> {
    let mut args = strings(&["run", "--release", "-q", "-p", "lie-sim", "--", "trade"]);
    args.extend(strings(t.args));
    args.extend(["--out".to_string(), csv.to_string()]);
    args
}

fn trade_command(t: &registry::Trade, csv: &str) -> String {
    shell_line("cargo", &trade_args(t, csv))
}

fn tests_args(t: &registry::Tests) -> Vec<String> {
    let mut args = strings(&["test", "--release", "-p", t.krate, "--test", t.binary, "--"]);
    args.extend(strings(&["--nocapture", "--test-threads", "1"]));
    for (_, prefixes) in t.parts {
        args.extend(strings(prefixes));
    }
    args
}

fn substitute(args: &[&str], out: &str) -> Vec<String> {
    args.iter().map(|a| a.replace("{out}", out)).collect()
}

/// The path of `file` (from the repository root) as a link from the Markdown file `from`.
fn link(from: &str, file: &str) -> String {
    match Path::new(from).parent().and_then(|p| p.to_str()) {
        Some(dir) if !dir.is_empty() => file
            .strip_prefix(&format!("{dir}/"))
            .map_or_else(|| format!("../{file}"), str::to_string),
        _ => file.to_string(),
    }
}

/// Whether the generator runs under `--reuse-csv` (only the trades do).
pub fn reuses_csv(g: &Generator) -> bool {
    matches!(g.how, How::Trade(_))
}

/// The regions a trade derives from its CSV alone, read from the repository.
fn trade_tables(t: &registry::Trade, root: &Path) -> Result<Made> {
    let rows = trade::read(&root.join(t.csv))?;
    let mut made = Made::default();
    for (at, part) in t.parts {
        if let Some(content) = trade_table(t, &rows, *part) {
            made.regions.push((*at, content));
        }
    }
    Ok(made)
}

fn trade_table(t: &registry::Trade, rows: &[trade::Row], part: TradePart) -> Option<String> {
    match part {
        TradePart::Run => None,
        TradePart::Summary { exclude } => Some(trade::summary(rows, t.metric, t.targets, exclude)),
        TradePart::Families => Some(trade::families(rows, t.metric, t.targets)),
        TradePart::Tau { theta } => Some(trade::tau(rows, theta)),
        TradePart::Steppers { targets } => Some(trade::steppers(rows, t.metric, targets)),
    }
}

/// Runs the generator's commands and makes its regions and files, writing nothing yet.
pub fn make(ctx: &Ctx, g: &Generator) -> Result<Made> {
    if ctx.reuse_csv {
        return match &g.how {
            How::Trade(t) => trade_tables(t, &ctx.root),
            _ => Ok(Made::default()),
        };
    }
    let scratch = ctx.scratch(g.name)?;
    let mut made = Made::default();
    match &g.how {
        How::Trade(t) => {
            let csv = scratch.join(Path::new(t.csv).file_name().unwrap_or_default());
            let stdout = exec::cargo_stdout(&ctx.root, &trade_args(t, &csv.display().to_string()))?;
            let rows = trade::read(&csv)?;
            let svg = PathBuf::from(registry::svg_of(&csv.display().to_string()));
            if !svg.exists() {
                return Err(Error::parse(
                    g.name,
                    format!("{} was not written", svg.display()),
                ));
            }
            for (at, part) in t.parts {
                let content =
                    trade_table(t, &rows, *part).unwrap_or_else(|| trade_run(t, at.file, &stdout));
                made.regions.push((*at, content));
            }
            made.files.push((csv, ctx.root.join(t.csv)));
            made.files
                .push((svg, ctx.root.join(registry::svg_of(t.csv))));
        }
        How::Bench(b) => {
            let args = criterion::command(b.bench, b.filter, b.measurement_time);
            let run = criterion::run(&ctx.root, &ctx.target_dir, &args)?;
            for (at, shape) in b.tables {
                made.regions.push((*at, criterion::table(&run, shape)?));
            }
        }
        How::Callgrind(tables) => {
            exec::cargo_stdout(
                &ctx.root,
                &strings(&[
                    "build",
                    "--release",
                    "-q",
                    "-p",
                    "lie-integrators",
                    "--example",
                    "step_cost",
                ]),
            )?;
            let binary = ctx.target_dir.join("release/examples/step_cost");
            for t in *tables {
                let table = callgrind::table(&ctx.root, &scratch, &binary, t.competitor, t.rows)?;
                made.regions.push((t.at, table));
            }
        }
        How::Tests(t) => {
            let stdout = exec::cargo_stdout(&ctx.root, &tests_args(t))?;
            let tests = test_output::by_test(&stdout);
            for (at, prefixes) in t.parts {
                let mine: Vec<_> = tests
                    .iter()
                    .filter(|(name, _)| prefixes.iter().any(|p| name.starts_with(p)))
                    .cloned()
                    .collect();
                if mine.is_empty() {
                    return Err(Error::parse(
                        g.name,
                        format!("no test under {prefixes:?} printed anything"),
                    ));
                }
                made.regions.push((*at, test_output::render(&mine)));
            }
        }
        How::Output(o) => {
            let out = o
                .out
                .map(|f| scratch.join(Path::new(f).file_name().unwrap_or_default()));
            let out_arg = out
                .as_ref()
                .map(|p| p.display().to_string())
                .unwrap_or_default();
            let mut content = String::new();
            for args in o.runs {
                let stdout = exec::cargo_stdout(&ctx.root, &substitute(args, &out_arg))?;
                if !o.markdown && o.runs.len() > 1 {
                    content.push_str(&format!(
                        "$ {}\n",
                        shell_line("cargo", &substitute(args, ""))
                    ));
                }
                for line in stdout
                    .lines()
                    .filter(|l| !o.drop.iter().any(|d| l.starts_with(d)))
                {
                    content.push_str(line.trim_end());
                    content.push('\n');
                }
                if !o.markdown && o.runs.len() > 1 {
                    content.push('\n');
                }
            }
            let content = if o.markdown {
                content
            } else {
                format!("```text\n{}```\n", content.trim_end().to_string() + "\n")
            };
            made.regions.push((o.at, content));
            if let (Some(from), Some(to)) = (out, o.out) {
                if !from.exists() {
                    return Err(Error::parse(
                        g.name,
                        format!("{} was not written", from.display()),
                    ));
                }
                made.files.push((from, ctx.root.join(to)));
            }
        }
        How::Machine(at) => made.regions.push((*at, machine(&ctx.root)?)),
        How::List(at) => made.regions.push((*at, list_table(at.file))),
        How::Source { file, at } => made.regions.push((*at, source_block(&ctx.root, file)?)),
    }
    Ok(made)
}

/// The file's text in a ```rust block (the region `How::Source` writes and `--check` compares).
pub fn source_block(root: &Path, file: &str) -> Result<String> {
    let path = root.join(file);
    let text = std::fs::read_to_string(&path).map_err(|e| Error::io(&path, e))?;
    Ok(format!("```rust\n{}\n```\n", text.trim_end()))
}

/// The trade's command, its ladder and reference as it printed them, and its fitted orders.
fn trade_run(t: &registry::Trade, file: &str, stdout: &str) -> String {
    let csv = link(file, t.csv);
    let svg = link(file, &registry::svg_of(t.csv));
    let mut settings = Vec::new();
    let mut orders = Vec::new();
    let mut in_orders = false;
    for line in stdout.lines() {
        if line.starts_with("method ") {
            settings.push(None);
        }
        if line.starts_with("observed orders") {
            in_orders = true;
        } else if in_orders && !line.starts_with("  ") {
            in_orders = false;
        }
        if in_orders {
            orders.push(line.trim_end());
        } else if !settings.contains(&None) {
            settings.push(Some(line.trim_end()));
        }
    }
    let settings: Vec<&str> = settings.into_iter().flatten().collect();
    format!(
        "`{}` ([csv]({csv}), [plot]({svg})):\n\n```text\n{}\n```\n\n<details><summary>fitted orders</summary>\n\n```text\n{}\n```\n\n</details>\n",
        trade_command(t, t.csv),
        settings.join("\n"),
        orders.join("\n")
    )
}

/// The CPU (lscpu's main lines), the compiler and the load average now.
fn machine(root: &Path) -> Result<String> {
    const KEYS: &[&str] = &[
        "Architecture",
        "CPU(s)",
        "Model name",
        "Thread(s) per core",
        "Core(s) per socket",
        "Hypervisor vendor",
        "L1d cache",
        "L1i cache",
        "L2 cache",
        "L3 cache",
    ];
    let lscpu = exec::stdout_of(root, "lscpu", &[])?;
    let rustc = exec::stdout_of(root, "rustc", &strings(&["--version"]))?;
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    let mut out = String::from("```text\n");
    for line in lscpu.lines() {
        if KEYS.iter().any(|k| line.starts_with(&format!("{k}:"))) {
            out.push_str(line.trim_end());
            out.push('\n');
        }
    }
    out.push_str(rustc.trim_end());
    out.push('\n');
    let load: Vec<&str> = load.split_whitespace().take(3).collect();
    out.push_str(&format!(
        "load average when the machine generator ran: {}\n```\n",
        load.join(" ")
    ));
    Ok(out)
}

/// The registry as a table: generator, what it makes, its command, how long it takes, where it writes.
pub fn list_table(from: &str) -> String {
    let mut out =
        String::from("| generator | makes | command | takes | writes |\n|---|---|---|---|---|\n");
    for g in registry::all() {
        let mut writes: Vec<String> = Vec::new();
        for a in g.regions() {
            let f = link(from, a.file);
            if !writes
                .iter()
                .any(|w| w.starts_with(&format!("[{}]", a.file)))
            {
                writes.push(format!("[{}]({f})", a.file));
            }
        }
        for f in g.files() {
            writes.push(format!("`{f}`"));
        }
        out.push_str(&format!(
            "| `{}` | {} | {} | {} | {} |\n",
            g.name,
            g.about,
            commands(&g)
                .iter()
                .map(|c| format!("`{}`", c.replace('|', "\\|")))
                .collect::<Vec<_>>()
                .join("<br>"),
            g.takes,
            writes.join(", ")
        ));
    }
    out
}

/// Checks that every region `made` holds is declared by the generator and found in its file,
/// then writes the new files and moves the made files into place.
pub fn commit(ctx: &Ctx, g: &Generator, made: Made) -> Result<()> {
    let mut by_file: BTreeMap<&str, BTreeMap<Key, String>> = BTreeMap::new();
    for (at, content) in &made.regions {
        by_file
            .entry(at.file)
            .or_default()
            .insert(Key::new(g.name, at.part), content.clone());
    }
    // Every new text first, so a region missing in a later file writes nothing at all.
    let mut texts = Vec::new();
    for (file, contents) in &by_file {
        let path = ctx.root.join(file);
        let text = std::fs::read_to_string(&path).map_err(|e| Error::io(&path, e))?;
        let new = region::replace(&text, contents).map_err(|detail| Error::Markers {
            file: file.to_string(),
            detail,
        })?;
        texts.push((path, new));
    }
    for (path, text) in texts {
        let tmp = path.with_extension("md.xtask-tmp");
        std::fs::write(&tmp, text).map_err(|e| Error::io(&tmp, e))?;
        std::fs::rename(&tmp, &path).map_err(|e| Error::io(&path, e))?;
    }
    for (from, to) in made.files {
        std::fs::rename(&from, &to)
            .or_else(|_| std::fs::copy(&from, &to).map(|_| ()))
            .map_err(|e| Error::io(&to, e))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scratch repository under the target directory: two Markdown files, `a.md` with the
    /// generator's region and `b.md` without it.
    fn scratch_repo(name: &str) -> Ctx {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../target/xtask-tests")
            .join(name);
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(&root).unwrap();
        std::fs::write(
            root.join("a.md"),
            "x\n<!-- generated by: cargo xtask docs --only g -->\nold\n<!-- end generated -->\n",
        )
        .unwrap();
        std::fs::write(root.join("b.md"), "no region here\n").unwrap();
        std::fs::write(root.join("made.csv"), "new").unwrap();
        Ctx {
            target_dir: root.join("target"),
            root,
            reuse_csv: false,
        }
    }

    fn generator() -> Generator {
        Generator {
            name: "g",
            about: "",
            takes: "",
            how: How::List(At {
                file: "a.md",
                part: "",
            }),
        }
    }

    #[test]
    fn a_result_with_a_region_missing_in_one_file_writes_nothing() {
        let ctx = scratch_repo("partial");
        let made = Made {
            regions: vec![
                (
                    At {
                        file: "a.md",
                        part: "",
                    },
                    "new\n".into(),
                ),
                (
                    At {
                        file: "b.md",
                        part: "",
                    },
                    "new\n".into(),
                ),
            ],
            files: vec![(ctx.root.join("made.csv"), ctx.root.join("docs.csv"))],
        };
        let err = commit(&ctx, &generator(), made).unwrap_err().to_string();
        assert!(err.contains("b.md") && err.contains("no region g"), "{err}");
        let a = std::fs::read_to_string(ctx.root.join("a.md")).unwrap();
        assert!(
            a.contains("old") && !a.contains("new"),
            "a.md was written: {a}"
        );
        assert!(
            !ctx.root.join("docs.csv").exists(),
            "the made file was moved"
        );
    }

    #[test]
    fn a_complete_result_rewrites_the_region_and_moves_the_files() {
        let ctx = scratch_repo("complete");
        let made = Made {
            regions: vec![(
                At {
                    file: "a.md",
                    part: "",
                },
                "new\n".into(),
            )],
            files: vec![(ctx.root.join("made.csv"), ctx.root.join("docs.csv"))],
        };
        commit(&ctx, &generator(), made).unwrap();
        let a = std::fs::read_to_string(ctx.root.join("a.md")).unwrap();
        assert_eq!(
            a,
            "x\n<!-- generated by: cargo xtask docs --only g -->\nnew\n<!-- end generated -->\n"
        );
        assert_eq!(
            std::fs::read_to_string(ctx.root.join("docs.csv")).unwrap(),
            "new"
        );
    }

    #[test]
    fn links_are_relative_to_the_markdown_file() {
        assert_eq!(link("README.md", "docs/trade-x.csv"), "docs/trade-x.csv");
        assert_eq!(
            link("docs/work-precision.md", "docs/trade-x.csv"),
            "trade-x.csv"
        );
        assert_eq!(link("docs/work-precision.md", "README.md"), "../README.md");
    }

    #[test]
    fn the_trade_region_keeps_the_settings_and_the_orders_not_the_table() {
        let t = registry::Trade {
            csv: "docs/trade-x.csv",
            args: &["examples/scenes/x.toml"],
            metric: "error",
            targets: &[1e-4],
            parts: &[],
        };
        let stdout =
            "lie-sim trade: x (free-rigid-body), T = 10, 2 steps: 1e-1, 5e-2\n  ladder: given\n\
                      reference: exact flow; estimated error 1.0e-14\n\
                      method  tau theta\nrk4 - - 0.1 …\n\
                      observed orders (slope …):\n  rk4  4.00\n  exact  -\n\
                      cheapest run per target (error):\n  ≤ 1e-4 rk4\n";
        let r = trade_run(&t, "docs/work-precision.md", stdout);
        assert!(r.starts_with("`cargo run --release -q -p lie-sim -- trade examples/scenes/x.toml --out docs/trade-x.csv` ([csv](trade-x.csv), [plot](trade-x.svg))"), "{r}");
        assert!(r.contains("```text\nlie-sim trade: x (free-rigid-body), T = 10, 2 steps: 1e-1, 5e-2\n  ladder: given\nreference: exact flow; estimated error 1.0e-14\n```"), "{r}");
        assert!(
            r.contains("observed orders (slope …):\n  rk4  4.00\n  exact  -\n```"),
            "{r}"
        );
        assert!(!r.contains("cheapest run"), "{r}");
        assert!(!r.contains("rk4 - -"), "{r}");
    }
}
