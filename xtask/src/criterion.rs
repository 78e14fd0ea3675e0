//! Criterion runs and the tables made from them. Every figure of a table comes from one run of
//! one bench binary: the benchmarks it ran are read off its stdout (`--output-format bencher`),
//! their means off `target/criterion/**/new/estimates.json`, and a file older than the run is an
//! error, so a ratio never mixes two runs.

use crate::error::{Error, Result};
use crate::exec;
use crate::format::time_ns;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// One run of a bench binary: the benchmarks in the order they ran, their mean times (ns), and
/// the elements per iteration of those that declare a criterion throughput.
#[derive(Debug, Default, Clone)]
pub struct Run {
    pub order: Vec<String>,
    pub mean_ns: HashMap<String, f64>,
    pub elements: HashMap<String, u64>,
}

impl Run {
    fn mean(&self, id: &str) -> Result<f64> {
        self.mean_ns.get(id).copied().ok_or_else(|| {
            Error::parse(
                "criterion run",
                format!("benchmark {id:?} was not in this run (filter, or a renamed benchmark)"),
            )
        })
    }
}

/// The benchmark ids a `--output-format bencher` run printed (`test ID ... bench: …`), in order.
pub fn ids_in_output(stdout: &str) -> Vec<String> {
    stdout
        .lines()
        .filter_map(|l| l.strip_prefix("test "))
        .filter_map(|l| l.rsplit_once(" ... ").map(|(id, _)| id.trim().to_string()))
        .collect()
}

/// `cargo bench -p lie-integrators --bench NAME -- --warm-up-time 1 --measurement-time T
/// --output-format bencher [FILTER]`.
pub fn command(bench: &str, filter: Option<&str>, measurement_time: u32) -> Vec<String> {
    let mut args = exec::strings(&["bench", "-p", "lie-integrators", "--bench", bench, "--"]);
    args.extend(exec::strings(&[
        "--warm-up-time",
        "1",
        "--measurement-time",
    ]));
    args.push(measurement_time.to_string());
    args.extend(exec::strings(&["--output-format", "bencher"]));
    if let Some(f) = filter {
        args.push(f.to_string());
    }
    args
}

/// Runs the bench and collects its results.
pub fn run(root: &Path, target_dir: &Path, args: &[String]) -> Result<Run> {
    let start = SystemTime::now();
    let stdout = exec::cargo_stdout(root, args)?;
    let order = ids_in_output(&stdout);
    if order.is_empty() {
        return Err(Error::parse(
            exec::shell_line("cargo", args),
            "no benchmark ran (a filter that matches nothing?)",
        ));
    }
    let estimates = estimates_by_id(&target_dir.join("criterion"))?;
    let mut mean_ns = HashMap::new();
    let mut elements = HashMap::new();
    for id in &order {
        let (path, mean, count) = estimates.get(id).ok_or_else(|| {
            Error::parse(
                "target/criterion",
                format!("no estimates.json for benchmark {id:?}"),
            )
        })?;
        let modified = std::fs::metadata(path)
            .and_then(|m| m.modified())
            .map_err(|e| Error::io(path, e))?;
        // Coarse file-system clocks: allow a second.
        if modified + std::time::Duration::from_secs(1) < start {
            return Err(Error::parse(
                path.display().to_string(),
                format!("older than this run of {id:?}: not written by it"),
            ));
        }
        mean_ns.insert(id.clone(), *mean);
        if let Some(n) = count {
            elements.insert(id.clone(), *n);
        }
    }
    Ok(Run {
        order,
        mean_ns,
        elements,
    })
}

/// Every `new/estimates.json` under `dir`, by the benchmark's title (its full id): its path, the
/// mean, and the elements per iteration if the benchmark declares them.
type Estimate = (PathBuf, f64, Option<u64>);
fn estimates_by_id(dir: &Path) -> Result<HashMap<String, Estimate>> {
    let mut out = HashMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let entries = std::fs::read_dir(&d).map_err(|e| Error::io(&d, e))?;
        for entry in entries {
            let path = entry.map_err(|e| Error::io(&d, e))?.path();
            if path.is_dir() {
                if path.file_name().is_some_and(|n| n == "new") {
                    if let Some((id, mean, count)) = read_new(&path)? {
                        out.insert(id, (path.join("estimates.json"), mean, count));
                    }
                } else {
                    stack.push(path);
                }
            }
        }
    }
    Ok(out)
}

fn read_json(path: &Path) -> Result<serde_json::Value> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    serde_json::from_str(&text).map_err(|e| Error::parse(path.display().to_string(), e.to_string()))
}

/// The benchmark id, mean (ns) and elements per iteration (criterion's `Throughput::Elements`)
/// of one `new/` directory (`None` without both files).
fn read_new(dir: &Path) -> Result<Option<(String, f64, Option<u64>)>> {
    let (bench, est) = (dir.join("benchmark.json"), dir.join("estimates.json"));
    if !bench.exists() || !est.exists() {
        return Ok(None);
    }
    let b = read_json(&bench)?;
    let id = b["title"]
        .as_str()
        .or_else(|| b["full_id"].as_str())
        .ok_or_else(|| Error::parse(bench.display().to_string(), "no title"))?;
    let mean = read_json(&est)?["mean"]["point_estimate"]
        .as_f64()
        .ok_or_else(|| Error::parse(est.display().to_string(), "no mean.point_estimate"))?;
    let count = b["throughput"]["Elements"].as_u64();
    Ok(Some((id.to_string(), mean, count)))
}

/// A ratio of two benchmarks of the run, and the bound it is held to, if any.
#[derive(Debug, Clone, Copy)]
pub struct Ratio {
    /// What the row compares, in words.
    pub what: &'static str,
    pub id: &'static str,
    pub against: &'static str,
    pub bound: Option<f64>,
}

/// The shape of a table made from one run.
#[derive(Debug, Clone, Copy)]
pub enum Table {
    /// Every benchmark whose id starts with `prefix`, in run order: its mean, and its ratio to
    /// the benchmark `competitor` (a full id) of the same run.
    List {
        prefix: &'static str,
        competitor: Option<&'static str>,
    },
    /// One row per criterion group starting with one of `groups`, one column per benchmark name
    /// (in run order); `ratio = Some((ours, against))`: the first of `ours` present in the row
    /// over the fastest of `against` present.
    Pivot {
        groups: &'static [&'static str],
        ratio: Option<(&'static [&'static str], &'static [&'static str])>,
    },
    /// Chosen ratios, each against its bound (met or not).
    Ratios(&'static [Ratio]),
    /// The benchmarks `PREFIX/NAME/N` as a table of time per element (criterion's throughput
    /// in elements, named `element`): one row per N (ascending), two columns per NAME (in run
    /// order): the mean over the elements of an iteration, and the elements per second.
    Throughput {
        prefix: &'static str,
        element: &'static str,
    },
}

/// The table of `run` in Markdown.
pub fn table(run: &Run, shape: &Table) -> Result<String> {
    match *shape {
        Table::List { prefix, competitor } => list(run, prefix, competitor),
        Table::Pivot { groups, ratio } => pivot(run, groups, ratio),
        Table::Ratios(rows) => ratios(run, rows),
        Table::Throughput { prefix, element } => throughput(run, prefix, element),
    }
}

fn list(run: &Run, prefix: &str, competitor: Option<&str>) -> Result<String> {
    let ids: Vec<&String> = run
        .order
        .iter()
        .filter(|id| id.starts_with(prefix))
        .collect();
    if ids.is_empty() {
        return Err(Error::parse(
            "criterion run",
            format!("no benchmark under {prefix:?}"),
        ));
    }
    let base = match competitor {
        Some(c) => Some((c, run.mean(c)?)),
        None => None,
    };
    let head = if prefix.is_empty() {
        "benchmark".to_string()
    } else {
        format!("`{prefix}…`")
    };
    let mut out = format!("| {head} | mean |");
    if let Some((c, _)) = base {
        out.push_str(&format!(" × `{c}` |"));
    }
    out.push_str(if base.is_some() {
        "\n|---|---:|---:|\n"
    } else {
        "\n|---|---:|\n"
    });
    for id in ids {
        let t = run.mean(id)?;
        out.push_str(&format!("| `{}` | {} |", &id[prefix.len()..], time_ns(t)));
        if let Some((_, b)) = base {
            out.push_str(&format!(" {:.2} |", t / b));
        }
        out.push('\n');
    }
    Ok(out)
}

fn pivot(run: &Run, prefixes: &[&str], ratio: Option<(&[&str], &[&str])>) -> Result<String> {
    let mut groups: Vec<String> = Vec::new();
    let mut columns: Vec<String> = Vec::new();
    for id in &run.order {
        let (group, name) = id.rsplit_once('/').unwrap_or(("", id));
        if !prefixes.iter().any(|p| group.starts_with(p)) {
            continue;
        }
        if !groups.iter().any(|g| g == group) {
            groups.push(group.to_string());
        }
        if !columns.iter().any(|c| c == name) {
            columns.push(name.to_string());
        }
    }
    if groups.is_empty() {
        return Err(Error::parse(
            "criterion run",
            format!("no benchmark in the groups {prefixes:?}"),
        ));
    }
    // The order the registry lists the groups in, where it lists them one by one.
    groups.sort_by_key(|g| prefixes.iter().position(|p| g.starts_with(p)));
    let mut out = String::from("| |");
    for c in &columns {
        out.push_str(&format!(" {c} |"));
    }
    if let Some((ours, against)) = ratio {
        out.push_str(&format!(
            " {} ÷ fastest of {} |",
            ours.join(", "),
            against.join(", ")
        ));
    }
    out.push_str(&format!("\n|---|{}", "---:|".repeat(columns.len())));
    if ratio.is_some() {
        out.push_str("---:|");
    }
    out.push('\n');
    for g in &groups {
        out.push_str(&format!("| {g} |"));
        let cell = |c: &str| run.mean_ns.get(&format!("{g}/{c}")).copied();
        for c in &columns {
            match cell(c) {
                Some(t) => out.push_str(&format!(" {} |", time_ns(t))),
                None => out.push_str(" – |"),
            }
        }
        if let Some((ours, against)) = ratio {
            let mine = ours.iter().find_map(|c| cell(c));
            let best = against.iter().filter_map(|c| cell(c)).reduce(f64::min);
            match (mine, best) {
                (Some(m), Some(b)) => out.push_str(&format!(" {:.2} |", m / b)),
                _ => out.push_str(" – |"),
            }
        }
        out.push('\n');
    }
    Ok(out)
}

fn throughput(run: &Run, prefix: &str, element: &str) -> Result<String> {
    let mut names: Vec<&str> = Vec::new();
    let mut sizes: Vec<u64> = Vec::new();
    for id in &run.order {
        let Some(rest) = id.strip_prefix(prefix).and_then(|r| r.strip_prefix('/')) else {
            continue;
        };
        let (name, n) = rest.rsplit_once('/').ok_or_else(|| {
            Error::parse("criterion run", format!("{id:?} is not {prefix}/NAME/N"))
        })?;
        let n: u64 = n.parse().map_err(|_| {
            Error::parse("criterion run", format!("{id:?}: N = {n:?} is not a count"))
        })?;
        if !names.contains(&name) {
            names.push(name);
        }
        if !sizes.contains(&n) {
            sizes.push(n);
        }
    }
    if names.is_empty() {
        return Err(Error::parse(
            "criterion run",
            format!("no benchmark under {prefix:?}"),
        ));
    }
    sizes.sort_unstable();
    let mut out = String::from("| N |");
    for name in &names {
        out.push_str(&format!(" `{name}`: per {element} | {element}s/s |"));
    }
    out.push_str(&format!("\n|---:|{}\n", "---:|---:|".repeat(names.len())));
    for n in &sizes {
        out.push_str(&format!("| {n} |"));
        for name in &names {
            let id = format!("{prefix}/{name}/{n}");
            match (run.mean_ns.get(&id), run.elements.get(&id)) {
                (Some(t), Some(&e)) if e > 0 => {
                    let per = t / e as f64;
                    out.push_str(&format!(" {} | {} |", time_ns(per), rate(1e9 / per)));
                }
                (Some(_), _) => {
                    return Err(Error::parse(
                        "criterion run",
                        format!("{id:?} declares no throughput in elements"),
                    ))
                }
                (None, _) => out.push_str(" – | – |"),
            }
        }
        out.push('\n');
    }
    Ok(out)
}

/// A rate per second with an SI prefix and three significant digits.
fn rate(per_second: f64) -> String {
    let (x, unit) = if per_second >= 1e9 {
        (per_second / 1e9, "G")
    } else if per_second >= 1e6 {
        (per_second / 1e6, "M")
    } else if per_second >= 1e3 {
        (per_second / 1e3, "k")
    } else {
        (per_second, "")
    };
    format!("{}{unit}", crate::format::g3(x))
}

fn ratios(run: &Run, rows: &[Ratio]) -> Result<String> {
    let mut out = String::from("| | step | against | ratio | bound |\n|---|---:|---:|---:|---|\n");
    for r in rows {
        let (a, b) = (run.mean(r.id)?, run.mean(r.against)?);
        let q = a / b;
        let bound = match r.bound {
            Some(x) if q <= x => format!("≤ {x}: **met**"),
            Some(x) => format!("≤ {x}: **not met**"),
            None => "–".into(),
        };
        out.push_str(&format!(
            "| {} (`{}` against `{}`) | {} | {} | {:.2} | {bound} |\n",
            r.what,
            r.id,
            r.against,
            time_ns(a),
            time_ns(b),
            q
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run() -> Run {
        let ids = [
            ("so3/exp/So3", 9.0),
            ("so3/exp/UnitQuaternion", 13.0),
            ("so3/exp/Rotation3", 45.0),
            ("se3/compose/Se3", 5.2),
            ("se3/compose/Isometry3", 5.1),
            ("trade/free_body/rk4-hand-written+g", 42.0),
            ("trade/free_body/rkmk4+g", 37.8),
        ];
        Run {
            order: ids.iter().map(|(i, _)| i.to_string()).collect(),
            mean_ns: ids.iter().map(|(i, t)| (i.to_string(), *t)).collect(),
            elements: HashMap::new(),
        }
    }

    #[test]
    fn a_throughput_table_has_a_row_per_size_and_the_time_per_element() {
        let ids = [
            ("batch/size/step/1024", 8_899.0, 1024),
            ("batch/size/run/1024", 569_068.0, 65_536),
            ("batch/size/step/64", 574.0, 64),
        ];
        let run = Run {
            order: ids.iter().map(|(i, _, _)| i.to_string()).collect(),
            mean_ns: ids.iter().map(|(i, t, _)| (i.to_string(), *t)).collect(),
            elements: ids.iter().map(|(i, _, n)| (i.to_string(), *n)).collect(),
        };
        let t = table(
            &run,
            &Table::Throughput {
                prefix: "batch/size",
                element: "body-step",
            },
        )
        .unwrap();
        assert!(t.starts_with("| N | `step`: per body-step | body-steps/s | `run`: per body-step | body-steps/s |"), "{t}");
        // N ascending; 64 has no `run`.
        assert!(t.contains("| 64 | 8.97 ns | 111M | – | – |"), "{t}");
        assert!(
            t.contains("| 1024 | 8.69 ns | 115M | 8.68 ns | 115M |"),
            "{t}"
        );
        assert!(
            t.find("| 64 |").unwrap() < t.find("| 1024 |").unwrap(),
            "{t}"
        );
        // A benchmark without a throughput is an error, not a silent per-iteration figure.
        let mut bare = run.clone();
        bare.elements.clear();
        assert!(table(
            &bare,
            &Table::Throughput {
                prefix: "batch/size",
                element: "body-step"
            }
        )
        .is_err());
    }

    #[test]
    fn the_benchmarks_of_a_run_are_read_off_the_bencher_output_in_order() {
        let out = "\nrunning\ntest so3/exp/So3 ... bench:           9 ns/iter (+/- 0)\n\
                   test SO(3)/compose/G parts of TG ... bench:  8 ns/iter (+/- 0)\n\
                   Warning: something\n";
        assert_eq!(
            ids_in_output(out),
            ["so3/exp/So3", "SO(3)/compose/G parts of TG"]
        );
    }

    #[test]
    fn a_list_divides_by_the_competitor_of_the_same_run() {
        let t = table(
            &run(),
            &Table::List {
                prefix: "trade/free_body/",
                competitor: Some("trade/free_body/rk4-hand-written+g"),
            },
        )
        .unwrap();
        assert!(t.contains("| `rkmk4+g` | 37.8 ns | 0.90 |"), "{t}");
        assert!(
            t.contains("| `rk4-hand-written+g` | 42.0 ns | 1.00 |"),
            "{t}"
        );
        let missing = table(
            &run(),
            &Table::List {
                prefix: "trade/free_body/",
                competitor: Some("trade/free_body/rk4"),
            },
        );
        assert!(missing.is_err());
    }

    #[test]
    fn a_pivot_has_a_row_per_group_and_the_ratio_to_the_fastest_other() {
        let t = table(
            &run(),
            &Table::Pivot {
                groups: &["se3", "so3"],
                ratio: Some((
                    &["So3", "Se3"],
                    &["UnitQuaternion", "Rotation3", "Isometry3"],
                )),
            },
        )
        .unwrap();
        assert!(
            t.contains("| so3/exp | 9.00 ns | 13.0 ns | 45.0 ns | – | – | 0.69 |"),
            "{t}"
        );
        assert!(
            t.contains("| se3/compose | – | – | – | 5.20 ns | 5.10 ns | 1.02 |"),
            "{t}"
        );
        // Rows in the order of the listed groups, not of the run.
        assert!(
            t.find("se3/compose").unwrap() < t.find("so3/exp").unwrap(),
            "{t}"
        );
    }

    #[test]
    fn a_ratio_says_whether_it_meets_its_bound() {
        let rows = [
            Ratio {
                what: "a",
                id: "so3/exp/So3",
                against: "so3/exp/UnitQuaternion",
                bound: Some(1.0),
            },
            Ratio {
                what: "b",
                id: "so3/exp/Rotation3",
                against: "so3/exp/UnitQuaternion",
                bound: Some(1.2),
            },
        ];
        let leaked: &'static [Ratio] = Box::leak(Box::new(rows));
        let t = table(&run(), &Table::Ratios(leaked)).unwrap();
        assert!(t.contains("| 0.69 | ≤ 1: **met** |"), "{t}");
        assert!(t.contains("| 3.46 | ≤ 1.2: **not met** |"), "{t}");
    }
}
