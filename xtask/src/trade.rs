//! Tables read off a `lie-sim trade` CSV: the cheapest plain baseline against the cheapest
//! structure-preserving run per target, with their cost ratio; the cheapest run of each family;
//! τ = exp against Cayley at equal steps.
//!
//! Cost is the stepping time of the whole run (`seconds`). For the error at T a run meets a target
//! as `lie-sim trade` and `choose` decide it: when its error plus the reference's estimated error
//! (`reference_error`) is within it, or, when its error is below that floor (`error_status` =
//! `unresolved`), when twice the floor is. A failed run meets nothing.

use crate::error::{Error, Result};
use crate::format::{g, g3, micros};
use std::collections::HashMap;
use std::path::Path;

/// The plain methods the structure-preserving ones are weighed against, for a CSV without the
/// `geometric` column (written before lie-sim had it).
pub const BASELINES: &[&str] = &["rk4", "rkmk4"];

/// One row of the CSV, by column name (the CSV's column order may change).
#[derive(Debug, Clone)]
pub struct Row(HashMap<String, String>);

impl Row {
    pub fn get(&self, column: &str) -> &str {
        self.0.get(column).map(String::as_str).unwrap_or("")
    }

    fn number(&self, column: &str) -> Option<f64> {
        self.get(column).parse().ok()
    }

    pub fn method(&self) -> &str {
        self.get("method")
    }

    pub fn seconds(&self) -> f64 {
        self.number("seconds").unwrap_or(f64::NAN)
    }

    pub fn h(&self) -> f64 {
        self.number("h").unwrap_or(f64::NAN)
    }

    pub fn failed(&self) -> bool {
        !self.get("failure").is_empty() || !self.seconds().is_finite()
    }

    /// Not geometric, as the CSV's `geometric` column says (read by lie-sim from the method's
    /// own descriptor); by name ([`BASELINES`]) in a CSV without it.
    pub fn is_baseline(&self) -> bool {
        match self.get("geometric") {
            "false" => true,
            "true" => false,
            _ => BASELINES.contains(&self.method()),
        }
    }

    /// The tolerance of a tolerance-driven run (`None` for a fixed step).
    pub fn tolerance(&self) -> Option<f64> {
        self.number("tolerance")
    }

    /// The ε of a run with reversible variable steps (`None` otherwise, and in a CSV written
    /// before lie-sim had the column).
    pub fn epsilon(&self) -> Option<f64> {
        self.number("epsilon")
    }

    /// `method [composition] [τ = …] [θ = …], h = …` as the tables name a run (`tolerance = …`
    /// or `reversible steps ε = …` for variable steps).
    pub fn label(&self) -> String {
        let mut parts = vec![self.method().to_string()];
        let composition = self.get("composition");
        if !composition.is_empty() && composition != "-" {
            parts.push(composition.into());
        }
        for (column, symbol) in [("tau", "τ"), ("theta", "θ")] {
            let v = self.get(column);
            if !v.is_empty() && v != "-" {
                parts.push(format!("{symbol} = {v}"));
            }
        }
        match (self.tolerance(), self.epsilon()) {
            (Some(t), _) => format!("{}, tolerance = {}", parts.join(" "), short(t)),
            (None, Some(e)) => format!("{}, reversible steps ε = {}", parts.join(" "), short(e)),
            (None, None) => format!("{}, h = {}", parts.join(" "), short(self.h())),
        }
    }

    /// Whether the run meets `target` in `metric` (a CSV column: `error`, `max_energy_error`, …).
    pub fn meets(&self, metric: &str, target: f64) -> bool {
        if self.failed() {
            return false;
        }
        if metric == "error" {
            let floor = self.number("reference_error").unwrap_or(0.0);
            return match self.get("error_status") {
                "unresolved" => 2.0 * floor <= target,
                "measured" => self.number("error").is_some_and(|e| e + floor <= target),
                _ => false,
            };
        }
        self.number(metric).is_some_and(|v| v <= target)
    }
}

/// A step as `%g` writes it (0.4, 0.0124955, 1.6e-5).
fn short(h: f64) -> String {
    g(h, 6)
}

/// The rows of a trade CSV (comma-separated, no quoting: lie-sim writes its failure reasons with
/// `;` for `,`).
pub fn read(path: &Path) -> Result<Vec<Row>> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    parse(&text).map_err(|detail| Error::parse(path.display().to_string(), detail))
}

pub fn parse(text: &str) -> std::result::Result<Vec<Row>, String> {
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().ok_or("empty CSV")?.split(',').collect();
    for needed in ["method", "h", "seconds", "error", "failure"] {
        if !header.contains(&needed) {
            return Err(format!("no column {needed:?} in the header {header:?}"));
        }
    }
    lines
        .filter(|l| !l.is_empty())
        .enumerate()
        .map(|(i, line)| {
            let cells: Vec<&str> = line.splitn(header.len(), ',').collect();
            if cells.len() != header.len() {
                return Err(format!(
                    "row {}: {} cells, the header has {}",
                    i + 2,
                    cells.len(),
                    header.len()
                ));
            }
            Ok(Row(header
                .iter()
                .zip(cells)
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect()))
        })
        .collect()
}

fn cheapest<'a>(rows: impl Iterator<Item = &'a Row>) -> Option<&'a Row> {
    rows.min_by(|a, b| a.seconds().total_cmp(&b.seconds()))
}

/// A target as the tables write it: `1e-04`.
fn target_label(t: f64) -> String {
    let s = format!("{t:.0e}");
    match s.split_once('e') {
        Some((m, e)) => {
            let e: i32 = e.parse().unwrap_or(0);
            let sign = if e < 0 { "-" } else { "" };
            format!("{m}e{sign}{:02}", e.abs())
        }
        None => s,
    }
}

/// | metric ≤ | cheapest baseline | cheapest geometric | geometric / baseline |, the methods in
/// `exclude` left out.
pub fn summary(rows: &[Row], metric: &str, targets: &[f64], exclude: &[&str]) -> String {
    let rows: Vec<&Row> = rows
        .iter()
        .filter(|r| !r.failed() && !exclude.contains(&r.method()))
        .collect();
    let mut out = format!(
        "| {metric} ≤ | cheapest baseline | cheapest geometric | geometric / baseline |\n|---|---|---|---|\n"
    );
    let show = |r: Option<&Row>| match r {
        Some(r) => format!("{}: {}", r.label(), micros(r.seconds())),
        None => "none in the ladder".into(),
    };
    for &t in targets {
        let ok = || rows.iter().copied().filter(|r| r.meets(metric, t));
        let b = cheapest(ok().filter(|r| r.is_baseline()));
        let g = cheapest(ok().filter(|r| !r.is_baseline()));
        let ratio = match (b, g) {
            (Some(b), Some(g)) => g3(g.seconds() / b.seconds()),
            _ => "—".into(),
        };
        out.push_str(&format!(
            "| {} | {} | {} | {ratio} |\n",
            target_label(t),
            show(b),
            show(g)
        ));
    }
    out
}

/// | metric ≤ | fixed steps, geometric | to a tolerance, baseline | reversible steps | reversible /
/// fixed | reversible / tolerance |: the cheapest run of each kind of stepping meeting each target
/// and the cost ratios of issue #27's variable-step targets (the cheapest reversible run against
/// the cheapest geometric run on fixed steps, and against the cheapest baseline run to a
/// tolerance).
pub fn steppers(rows: &[Row], metric: &str, targets: &[f64]) -> String {
    let mut out = format!(
        "| {metric} ≤ | fixed steps, geometric | to a tolerance, baseline | reversible steps | \
         reversible / fixed | reversible / tolerance |\n|---|---|---|---|---|---|\n"
    );
    let show = |r: Option<&Row>| match r {
        Some(r) => format!("{}: {}", r.label(), micros(r.seconds())),
        None => "none in the ladder".into(),
    };
    let ratio = |a: Option<&Row>, b: Option<&Row>| match (a, b) {
        (Some(a), Some(b)) => g3(a.seconds() / b.seconds()),
        _ => "—".into(),
    };
    for &t in targets {
        let ok = || rows.iter().filter(|r| r.meets(metric, t));
        let fixed = cheapest(
            ok().filter(|r| !r.is_baseline() && r.tolerance().is_none() && r.epsilon().is_none()),
        );
        let tolerance = cheapest(ok().filter(|r| r.is_baseline() && r.tolerance().is_some()));
        let reversible = cheapest(ok().filter(|r| r.epsilon().is_some()));
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} |\n",
            target_label(t),
            show(fixed),
            show(tolerance),
            show(reversible),
            ratio(reversible, fixed),
            ratio(reversible, tolerance)
        ));
    }
    out
}

/// The families of the per-family table; a method no family names falls into the last.
pub const FAMILIES: &[(&str, &[&str])] = &[
    ("RK4 / RKMK4", &["rk4", "rkmk4"]),
    (
        "to a tolerance: DOP853, Dormand–Prince",
        &["dop853", "dopri5", "rkmk-dop853", "rkmk-dopri5"],
    ),
    (
        "exact flow, kinetic–kick",
        &["exact", "kinetic-kick", "processed-kinetic-kick"],
    ),
    ("explicit splittings", &["splitting", "processed-splitting"]),
    ("implicit θ-methods and the rest", &[]),
];

fn family_of(method: &str) -> usize {
    FAMILIES
        .iter()
        .position(|(_, methods)| methods.contains(&method))
        .unwrap_or(FAMILIES.len() - 1)
}

/// | metric ≤ | the cheapest run of each family meeting it |.
pub fn families(rows: &[Row], metric: &str, targets: &[f64]) -> String {
    let mut out = format!("| {metric} ≤ |");
    for (name, _) in FAMILIES {
        out.push_str(&format!(" {name} |"));
    }
    out.push_str(&format!("\n|---|{}\n", "---|".repeat(FAMILIES.len())));
    for &t in targets {
        out.push_str(&format!("| {} |", target_label(t)));
        for f in 0..FAMILIES.len() {
            let best = cheapest(
                rows.iter()
                    .filter(|r| family_of(r.method()) == f && r.meets(metric, t)),
            );
            match best {
                Some(r) => out.push_str(&format!(" {}: {} |", r.label(), micros(r.seconds()))),
                None => out.push_str(" none in the ladder |"),
            }
        }
        out.push('\n');
    }
    out
}

/// Plain Lie–Poisson at θ, τ = exp against τ = Cayley at each step of the ladder: the error at T,
/// its ratio, and the cost per step.
pub fn tau(rows: &[Row], theta: &str) -> String {
    let find = |tau: &str, h: f64| {
        rows.iter().find(|r| {
            r.method() == "lie-poisson"
                && r.get("composition") == "-"
                && r.get("tau") == tau
                && r.get("theta") == theta
                && r.h() == h
                && !r.failed()
        })
    };
    let mut steps: Vec<f64> = rows
        .iter()
        .filter(|r| r.method() == "lie-poisson")
        .map(Row::h)
        .collect();
    steps.sort_by(|a, b| b.total_cmp(a));
    steps.dedup();
    let mut out = String::from(
        "| h | error, exp | error, Cayley | Cayley / exp | ns per step, exp | ns per step, Cayley |\n\
         |---:|---:|---:|---:|---:|---:|\n",
    );
    let error = |r: &Row| match r.get("error_status") {
        "measured" => r.get("error").parse::<f64>().ok(),
        _ => None,
    };
    let ns = |r: &Row| {
        r.number("ns_per_step")
            .map_or("—".into(), |v| format!("{v:.1}"))
    };
    for h in steps {
        let (Some(e), Some(c)) = (find("exp", h), find("cayley", h)) else {
            continue;
        };
        let cell = |r: &Row| error(r).map_or("unresolved".into(), |v| format!("{v:.1e}"));
        let ratio = match (error(e), error(c)) {
            (Some(a), Some(b)) => g3(b / a),
            _ => "—".into(),
        };
        out.push_str(&format!(
            "| {} | {} | {} | {ratio} | {} | {} |\n",
            short(h),
            cell(e),
            cell(c),
            ns(e),
            ns(c)
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const CSV: &str = "method,tau,theta,composition,h,steps,ns_per_step,seconds,error,error_status,reference_error,max_energy_error,max_casimir_error,max_momentum_map_error,failure
rk4,-,-,-,0.4,25,40,1.0e-6,2e-5,measured,1e-14,1e-4,,,
rk4,-,-,-,0.1,100,40,4.0e-6,1e-8,measured,1e-14,1e-6,,,
lie-poisson,exp,0.5,-,0.4,25,200,5.0e-6,1e-3,measured,1e-14,1e-3,1e-16,,
lie-poisson,cayley,0.5,-,0.4,25,150,3.75e-6,4e-3,measured,1e-14,1e-3,1e-16,,
exact,-,-,-,10,1,900,0.9e-6,,unresolved,1e-14,1e-15,1e-15,,
euler-poincare,exp,1,-,0.4,0,NaN,NaN,,failed,1e-14,NaN,,,step 5: no convergence; after 50
";

    #[test]
    fn the_summary_takes_the_cheapest_run_meeting_each_target_and_their_ratio() {
        let rows = parse(CSV).unwrap();
        let s = summary(&rows, "error", &[1e-4, 1e-6], &[]);
        assert!(
            s.contains("| 1e-04 | rk4, h = 0.4: 1.0 µs | exact, h = 10: 0.9 µs | 0.9 |"),
            "{s}"
        );
        assert!(
            s.contains("| 1e-06 | rk4, h = 0.1: 4.0 µs | exact, h = 10: 0.9 µs | 0.225 |"),
            "{s}"
        );
        // Without the exact flow no geometric run reaches 1e-4.
        let s = summary(&rows, "error", &[1e-4], &["exact"]);
        assert!(
            s.contains("| 1e-04 | rk4, h = 0.4: 1.0 µs | none in the ladder | — |"),
            "{s}"
        );
    }

    #[test]
    fn the_steppers_table_sets_reversible_steps_against_fixed_steps_and_tolerances() {
        let csv = "method,tau,theta,composition,tolerance,h,steps,ns_per_step,seconds,error,error_status,reference_error,max_energy_error,max_casimir_error,max_momentum_map_error,geometric,failure,epsilon
splitting,-,-,-,,0.1,100,40,8.0e-6,1e-7,measured,1e-14,1e-4,,,true,,
splitting,-,-,-,,0.2,50,40,4.0e-6,1e-5,measured,1e-14,1e-4,,,true,,
dop853,-,-,-,1e-9,0.3,30,100,3.0e-6,1e-7,measured,1e-14,1e-4,,,false,,
rk4,-,-,-,,0.3,30,100,1.0e-6,1e-7,measured,1e-14,1e-4,,,false,,
splitting,-,-,-,,0.25,40,40,1.5e-6,1e-7,measured,1e-14,1e-4,,,true,,0.5
splitting,-,-,-,,0.5,20,40,0.5e-6,1e-3,measured,1e-14,1e-4,,,true,,1
";
        let rows = parse(csv).unwrap();
        let s = steppers(&rows, "error", &[1e-6]);
        // The fixed-step baseline (rk4, cheaper still) is in neither column; the reversible run
        // at ε = 1 misses the target.
        assert!(
            s.contains("| 1e-06 | splitting, h = 0.1: 8.0 µs | dop853, tolerance = 1e-9: 3.0 µs | splitting, reversible steps ε = 0.5: 1.5 µs | 0.188 | 0.5 |"),
            "{s}"
        );
    }

    #[test]
    fn an_unresolved_error_counts_as_twice_the_reference_floor() {
        let rows = parse(CSV).unwrap();
        let exact = rows.iter().find(|r| r.method() == "exact").unwrap();
        assert!(exact.meets("error", 2e-14));
        assert!(!exact.meets("error", 1.9e-14));
        let rk4 = &rows[0];
        assert!(rk4.meets("error", 2e-5 + 1e-14));
        assert!(!rk4.meets("error", 2e-5));
    }

    #[test]
    fn failed_runs_meet_nothing_and_other_metrics_read_their_column() {
        let rows = parse(CSV).unwrap();
        assert!(rows[5].failed());
        assert!(!rows[5].meets("max_energy_error", 1.0));
        assert!(rows[1].meets("max_energy_error", 1e-6));
        assert!(!rows[0].meets("max_energy_error", 1e-5));
    }

    #[test]
    fn families_and_tau_tables_read_the_same_rows() {
        let rows = parse(CSV).unwrap();
        let f = families(&rows, "error", &[1e-2]);
        assert!(f.contains("| rk4, h = 0.4: 1.0 µs | none in the ladder | exact, h = 10: 0.9 µs | none in the ladder | lie-poisson τ = cayley θ = 0.5, h = 0.4: 3.8 µs |"), "{f}");
        let t = tau(&rows, "0.5");
        assert!(
            t.contains("| 0.4 | 1.0e-3 | 4.0e-3 | 4 | 200.0 | 150.0 |"),
            "{t}"
        );
    }

    #[test]
    fn a_csv_without_the_needed_columns_is_refused() {
        assert!(parse("method,h\nrk4,0.1\n")
            .unwrap_err()
            .contains("seconds"));
    }
}
