//! `lie-sim trade`: the ladder (`--steps` exactly, or from the scene's time scale), the
//! long-horizon measures (energy, Casimir and momentum-map errors, checked against a `run`'s CSV
//! and against what the methods are known to keep), `--metric` and `--horizon`, and bad flags.

use crate::common::*;
use std::path::Path;

/// A trade CSV: the header and the rows as fields.
struct Table {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Table {
    fn read(path: &Path) -> Self {
        let text = std::fs::read_to_string(path).unwrap();
        let mut lines = text.lines();
        let header = lines.next().unwrap().split(',').map(String::from).collect();
        let rows = lines
            .map(|l| l.split(',').map(String::from).collect())
            .collect();
        Self { header, rows }
    }

    fn col(&self, name: &str) -> usize {
        self.header.iter().position(|h| h == name).unwrap()
    }

    /// The rows of `method` (the first four fields joined by commas, e.g. `rk4,-,-,-`) with
    /// fixed steps or a tolerance: the same method's runs with reversible steps (their `epsilon`
    /// filled) are tests/cli/reversible_steps.rs's.
    fn of(&self, method: &str) -> Vec<&Vec<String>> {
        let epsilon = self.col("epsilon");
        self.rows
            .iter()
            .filter(|r| r[..4].join(",") == method && r[epsilon].is_empty())
            .collect()
    }

    /// Column `name` of the rows of `method`, as numbers (NaN for an empty cell).
    fn values(&self, method: &str, name: &str) -> Vec<f64> {
        let j = self.col(name);
        self.of(method)
            .iter()
            .map(|r| r[j].parse().unwrap_or(f64::NAN))
            .collect()
    }
}

fn trade(dir: &Path, args: &[&str]) -> Table {
    let mut all = vec!["trade", "--out", "w.csv", "--repeats", "1"];
    all.extend_from_slice(args);
    let o = lie_sim(&all, dir);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    Table::read(&dir.join("w.csv"))
}

/// `--steps` is run exactly: every method has one row per listed step, in the listed order (the
/// exact flow one more, its one step to T first).
#[test]
fn explicit_steps_are_run_exactly() {
    let dir = temp_dir("steps");
    let t = trade(
        &dir,
        &[
            "--steps",
            "0.1,0.05,0.02",
            "--horizon",
            "0.4",
            "--metric",
            "energy",
        ],
    );
    // The configurations with a step or a tolerance (a configuration run only with reversible
    // steps, such as Kahan–Li 8 ∘ splitting, runs its ε ladder: `reversible_steps`).
    let epsilon = t.col("epsilon");
    let mut methods: Vec<String> = t
        .rows
        .iter()
        .filter(|r| r[epsilon].is_empty())
        .map(|r| r[..4].join(","))
        .collect();
    methods.dedup();
    assert!(methods.len() > 20, "{methods:?}");
    let (h, tolerance) = (t.col("h"), t.col("tolerance"));
    for m in &methods {
        if !t.of(m)[0][tolerance].is_empty() {
            // A tolerance-driven method runs its tolerances, not the steps.
            assert_eq!(t.of(m).len(), 10, "{m}");
            continue;
        }
        let hs: Vec<&str> = t.of(m).iter().map(|r| r[h].as_str()).collect();
        let expected: &[&str] = if m == "exact,-,-,-" {
            &["0.4", "0.1", "0.05", "0.02"]
        } else {
            &["0.1", "0.05", "0.02"]
        };
        assert_eq!(hs, expected, "{m}");
    }
    // 0.4 / 0.02 = 20 steps.
    assert_eq!(t.of("rk4,-,-,-")[2][t.col("steps")], "20");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A free body with |Ω₀| = |𝕀⁻¹Π₀| = |(3, 0, −4)| = 5, and the same with Π₀ ten times larger:
/// the automatic ladders start at hω = 1 (h = 0.2 and 0.02) and halve down to the documented
/// floor, the first h with (hω)⁸ max(1, ωT) ≤ 1e-13.
#[test]
fn the_automatic_ladder_starts_at_h_omega_one_on_either_time_scale() {
    let dir = temp_dir("ladder");
    for (scale, top) in [(1.0, 0.2), (10.0, 0.02)] {
        let scene = format!(
            r#"
[system]
kind = "free-rigid-body"
inertia = [2.0, 4.0, 5.0]
[initial]
momentum = [{}, 0.0, {}]
[integrator]
method = "lie-poisson"
tau = "exp"
theta = 0.5
step = 0.1
duration = 0.5
"#,
            6.0 * scale,
            -20.0 * scale
        );
        std::fs::write(dir.join("s.toml"), scene).unwrap();
        let mut halving_levels = 0;
        // The default ratio 2, then √2: the same span in twice the divisions.
        for ratio in [None, Some(std::f64::consts::SQRT_2)] {
            let r = ratio.map(|r: f64| r.to_string());
            let mut args = vec!["trade", "s.toml", "--out", "w.csv", "--repeats", "1"];
            if let Some(r) = &r {
                args.extend(["--ratio", r.as_str()]);
            }
            let o = lie_sim(&args, &dir);
            assert!(o.status.success(), "{}", stderr(&o));
            assert!(stdout(&o).contains("hω = 1.00"), "{}", stdout(&o));
            let t = Table::read(&dir.join("w.csv"));
            let hs = t.values("rk4,-,-,-", "h");
            let omega = 1.0 / top;
            let at_floor = |h: f64| (h * omega).powi(8) * (omega * 0.5f64).max(1.0) <= 1e-13;
            assert!(at_floor(hs[hs.len() - 1]), "{hs:?}");
            assert!(!at_floor(hs[hs.len() - 2]), "{hs:?}");
            assert!((hs[0] - top).abs() < 1e-15 * top, "{hs:?}");
            match ratio {
                None => {
                    for w in hs.windows(2) {
                        assert_eq!(w[1], w[0] / 2.0);
                    }
                    halving_levels = hs.len();
                }
                Some(r) => {
                    for (k, h) in hs.iter().enumerate() {
                        let want = top / r.powi(k as i32);
                        assert!((h - want).abs() < 1e-14 * want, "{hs:?}");
                    }
                    let n = hs.len();
                    assert!(n == 2 * halving_levels - 2 || n == 2 * halving_levels - 1);
                }
            }
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The least-squares slope of log y against log x.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = x.iter().zip(y).map(|(a, b)| (a.ln(), b.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = lx.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

/// On the free body over T = 10: the θ = ½ Lie–Poisson methods keep |Π|² and R Π to round-off
/// (≤ 1e-12), RK4 does not, and its Casimir error falls at order 4 in h; `--metric casimir` puts
/// the Casimir on the plot's axis.
#[test]
fn lie_poisson_keeps_casimir_and_momentum_map_and_rk4_drifts_at_order_4() {
    let dir = temp_dir("metrics");
    let scene = scenes_dir().join("free-rigid-body.toml");
    let t = trade(
        &dir,
        &[
            scene.to_str().unwrap(),
            "--steps",
            "0.2,0.1,0.05",
            "--horizon",
            "10",
            "--metric",
            "casimir",
        ],
    );
    for m in ["lie-poisson,exp,0.5,-", "lie-poisson,cayley,0.5,-"] {
        for name in ["max_casimir_error", "max_momentum_map_error"] {
            let v = t.values(m, name);
            assert_eq!(v.len(), 3);
            assert!(
                v.iter().all(|&e| (0.0..=1e-12).contains(&e)),
                "{m} {name}: {v:?}"
            );
        }
    }
    let h = t.values("rk4,-,-,-", "h");
    let c = t.values("rk4,-,-,-", "max_casimir_error");
    let j = t.values("rk4,-,-,-", "max_momentum_map_error");
    // 4.1e-9, 2.3e-10, 1.5e-11 (the Lie–Poisson values: 3e-16).
    assert!(c.iter().all(|&e| e > 1e-11), "{c:?}");
    assert!(j.iter().all(|&e| e > 1e-10), "{j:?}");
    let p = slope(&h, &c);
    assert!((p - 4.0).abs() < 0.1, "rk4 Casimir order {p:.3}: {c:?}");
    let svg = std::fs::read_to_string(dir.join("w.svg")).unwrap();
    assert!(svg.contains("max relative Casimir error"), "the axis");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The CSV of `lie-sim run` as columns.
fn run_columns(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let mut cols = vec![Vec::new(); header.len()];
    for l in lines {
        for (j, x) in l.split(',').enumerate() {
            cols[j].push(x.parse::<f64>().unwrap());
        }
    }
    (header, cols)
}

/// The trade samples every 8 steps and at T: the rows of `lie-sim run` at stride 8 are the same
/// states. Its energy and Casimir columns equal the run's maxima exactly; its momentum-map column
/// equals |R Π − R₀Π₀| / |R₀Π₀| (free body) and |e₃·(R Π − R₀Π₀)| / |R₀Π₀| (heavy top), computed
/// here from the CSV's Π and row-major R (to 1e-14: the two computations round differently).
#[test]
fn the_sampled_measures_are_those_of_the_run_at_stride_8() {
    let dir = temp_dir("sampled");
    for (name, system, vertical) in [
        (
            "body",
            "kind = \"free-rigid-body\"\ninertia = [2.0, 3.0, 4.0]\n[initial]\n\
             momentum = [1.0, 0.5, -0.3]",
            false,
        ),
        (
            "top",
            "kind = \"heavy-top\"\ninertia = [1.0, 1.0, 0.5]\nmass = 1.0\n\
             center_of_mass = [0.0, 0.0, 1.0]\ngravity = 9.81\n[initial]\n\
             momentum = [0.0, 1.0, 3.0]",
            true,
        ),
    ] {
        let scene = format!(
            "[system]\n{system}\nattitude = {{ rotation_vector = [0.3, -0.2, 0.1] }}\n\
             [integrator]\nmethod = \"rk4\"\nstep = 0.2\nduration = 8.0\n[output]\nstride = 8\n"
        );
        let file = format!("{name}.toml");
        std::fs::write(dir.join(&file), scene).unwrap();
        let o = lie_sim(&["run", &file, "--out", "r.csv"], &dir);
        assert!(o.status.success(), "{}", stderr(&o));
        let (header, cols) = run_columns(&dir.join("r.csv"));
        assert_eq!(cols[0].len(), 6, "t = 0 and every 8 of 40 steps");
        let col = |n: &str| &cols[header.iter().position(|h| h == n).unwrap()];
        let rel = |x: &[f64]| {
            x.iter()
                .map(|v| (v - x[0]).abs() / x[0].abs())
                .fold(0.0, f64::max)
        };
        let j: Vec<[f64; 3]> = (0..cols[0].len())
            .map(|k| {
                let r = |i: usize, c: usize| col(&format!("g{i}{c}"))[k];
                let pi = [col("mu1")[k], col("mu2")[k], col("mu3")[k]];
                [1, 2, 3].map(|i| (1..=3).map(|c| r(i, c) * pi[c - 1]).sum())
            })
            .collect();
        let j0 = (j[0].iter().map(|x| x * x).sum::<f64>()).sqrt();
        let j_err = j
            .iter()
            .map(|v| {
                let d: Vec<f64> = (0..3).map(|i| v[i] - j[0][i]).collect();
                if vertical {
                    d[2].abs()
                } else {
                    d.iter().map(|x| x * x).sum::<f64>().sqrt()
                }
            })
            .fold(0.0, f64::max)
            / j0;

        let t = trade(&dir, &[&file, "--steps", "0.2"]);
        let energy = t.values("rk4,-,-,-", "max_energy_error")[0];
        assert_eq!(energy, rel(col("energy")), "{name}: energy");
        if vertical {
            let j = t.col("max_casimir_error");
            assert_eq!(t.of("rk4,-,-,-")[0][j], "", "the heavy top has no Casimir");
        } else {
            let casimir = t.values("rk4,-,-,-", "max_casimir_error")[0];
            assert_eq!(casimir, rel(col("casimir")), "{name}: Casimir");
        }
        let jm = t.values("rk4,-,-,-", "max_momentum_map_error")[0];
        assert!(j_err > 1e-8, "{name}: rk4 drifts: {j_err:e}");
        // J computed two ways agrees to a few roundings of |J₀|.
        assert!(
            (jm - j_err).abs() <= 1e-14,
            "{name}: momentum map {jm:e} against {j_err:e}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Where the momentum map is not monitored (no reconstruction) the column is empty.
#[test]
fn the_momentum_map_is_empty_without_reconstruction() {
    let dir = temp_dir("nog");
    let scene = "[system]\nkind = \"free-rigid-body\"\ninertia = [2.0, 3.0, 4.0]\n[initial]\n\
                 momentum = [1.0, 0.5, -0.3]\n[integrator]\nmethod = \"rk4\"\nstep = 0.05\n\
                 duration = 0.2\nreconstruct = false\n";
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let t = trade(&dir, &["s.toml", "--steps", "0.1"]);
    let j = t.col("max_momentum_map_error");
    assert!(t.rows.iter().all(|r| r[j].is_empty()));
    let c = t.col("max_casimir_error");
    assert!(t.rows.iter().all(|r| !r[c].is_empty()));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Bad flags: a usage error whose first line names the flag, nothing written.
#[test]
fn bad_trade_flags_are_refused_naming_the_flag() {
    let dir = temp_dir("bad");
    let nog = "[system]\nkind = \"free-rigid-body\"\ninertia = [2.0, 3.0, 4.0]\n[initial]\n\
               momentum = [1.0, 0.5, -0.3]\n[integrator]\nmethod = \"rk4\"\nstep = 0.05\n\
               duration = 0.2\nreconstruct = false\n";
    std::fs::write(dir.join("nog.toml"), nog).unwrap();
    let top = scenes_dir().join("heavy-top.toml");
    let top = top.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--steps", ""], "--steps"),
        (vec!["--steps", ","], "--steps"),
        (vec!["--steps", "0.1,-0.05"], "--steps"),
        (vec!["--steps", "0"], "--steps"),
        (vec!["--steps", "0.1,NaN"], "--steps"),
        (vec!["--steps", "inf"], "--steps"),
        (vec!["--steps", "0.1,x"], "--steps"),
        (vec!["--steps", "0.1,0.25", "--horizon", "0.2"], "--steps"),
        (vec!["--steps", "0.1", "--levels", "3"], "--levels"),
        (vec!["--steps", "0.1", "--ratio", "1.5"], "--ratio"),
        (vec!["--ratio", "1"], "--ratio"),
        (vec!["--ratio", "1.05"], "--ratio"),
        (vec!["--ratio", "17"], "--ratio"),
        (vec!["--ratio", "-2"], "--ratio"),
        (vec!["--ratio", "NaN"], "--ratio"),
        (vec!["--ratio", "inf"], "--ratio"),
        (vec!["--ratio", "half"], "--ratio"),
        (vec!["--step", "0.1"], "--step"),
        (vec!["--horizon", "0"], "--horizon"),
        (vec!["--horizon", "-1"], "--horizon"),
        (vec!["--horizon", "NaN"], "--horizon"),
        (vec!["--horizon", "ten"], "--horizon"),
        (vec!["--metric", "speed"], "--metric"),
        (vec!["--reference-tolerance", "0"], "--reference-tolerance"),
        (vec!["--reference-tolerance", "1"], "--reference-tolerance"),
        (
            vec!["--reference-tolerance", "-1e-13"],
            "--reference-tolerance",
        ),
        (
            vec!["--reference-tolerance", "NaN"],
            "--reference-tolerance",
        ),
        (vec!["--reference-budget", "0s"], "--reference-budget"),
        (vec!["--reference-budget", "-3s"], "--reference-budget"),
        (vec!["--reference-budget", "soon"], "--reference-budget"),
        (vec!["--reference", "missing.csv"], "missing.csv"),
        (vec!["--write-reference", "x.csv"], "x.csv"),
        (vec![top, "--metric", "casimir"], "--metric casimir"),
        (
            vec!["nog.toml", "--metric", "momentum-map"],
            "--metric momentum-map",
        ),
    ];
    for (args, flag) in cases {
        let mut all = vec!["trade", "--out", "x.csv", "--plot", "x.svg"];
        all.extend_from_slice(&args);
        let o = lie_sim(&all, &dir);
        assert!(matches!(o.status.code(), Some(1 | 2)), "{args:?}");
        let err = stderr(&o);
        let first = err.lines().next().unwrap_or("");
        assert!(
            first.contains("error") && first.contains(flag),
            "{args:?}: {err}"
        );
        // One line of its own; clap adds only its hint lines.
        let other: Vec<&str> = err
            .lines()
            .skip(1)
            .filter(|l| {
                !l.trim().is_empty()
                    && !l.starts_with("For more information")
                    && !l.trim_start().starts_with("[possible values")
                    && !l.starts_with("Usage:")
            })
            .collect();
        assert!(other.is_empty(), "{args:?}: {err}");
        assert!(!dir.join("x.csv").exists() && !dir.join("x.svg").exists());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The conserved part of the momentum map on every group: the θ = ½ Lie–Poisson method keeps it
/// to round-off (≤ 1e-13) and RKMK4 does not (> 1e-11): the free body on SE(3) (all of J), the
/// satellite (the angular momentum about the centre), the planar body on a spring attached at the
/// origin (its angular momentum about the origin) and the SO(4) geodesic (all of J).
#[test]
fn the_conserved_part_of_the_momentum_map_is_kept_by_lie_poisson_on_every_group() {
    let dir = temp_dir("groups");
    let se3 = std::fs::read_to_string(scenes_dir().join("rigid-body-se3.toml")).unwrap();
    let se2 = std::fs::read_to_string(scenes_dir().join("planar-body-se2.toml")).unwrap();
    let son = std::fs::read_to_string(scenes_dir().join("geodesic-so-n.toml")).unwrap();
    let scenes = [
        ("se3", se3.clone()),
        (
            "satellite",
            se3.replace(
                "gravitational_parameter = 0.0 ",
                "gravitational_parameter = 10.0 ",
            )
            .replace("position = [0.0, 0.0, 0.0]", "position = [3.0, 0.5, 0.0]"),
        ),
        (
            "spring",
            se2.replace(
                "mass = 1.0",
                "mass = 1.0\nstiffness = 4.0\nattachment = [0.3, 0.1]",
            )
            .replace("position = [0.0, 0.0]", "position = [1.0, 0.5]"),
        ),
        ("son", son),
    ];
    assert!(scenes[1].1.contains("= 10.0") && scenes[2].1.contains("stiffness"));
    for (name, text) in scenes {
        let file = format!("{name}.toml");
        std::fs::write(dir.join(&file), text).unwrap();
        let t = trade(&dir, &[&file, "--steps", "0.05", "--horizon", "2"]);
        let lp = t.values("lie-poisson,exp,0.5,-", "max_momentum_map_error")[0];
        let rkmk = t.values("rkmk4,exp,-,-", "max_momentum_map_error")[0];
        assert!(lp <= 1e-13, "{name}: lie-poisson {lp:e}");
        assert!(rkmk > 1e-11, "{name}: rkmk4 {rkmk:e}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The plot marks the reference floor (error at T only), rings and labels the cheapest run per
/// target, and the summary lists them.
#[test]
fn the_plot_marks_the_floor_and_labels_the_cheapest_runs() {
    let dir = temp_dir("plot");
    let scene = scenes_dir().join("free-rigid-body.toml");
    let scene = scene.to_str().unwrap();
    for (metric, floor, axis) in [
        ("error", true, "error at T"),
        ("energy", false, "max relative energy error"),
    ] {
        let o = lie_sim(
            &[
                "trade",
                scene,
                "--out",
                "w.csv",
                "--repeats",
                "1",
                "--steps",
                "0.2,0.1",
                "--horizon",
                "2",
                "--metric",
                metric,
            ],
            &dir,
        );
        assert!(o.status.success(), "{}", stderr(&o));
        let out = stdout(&o);
        assert!(out.contains("cheapest run per target"), "{out}");
        let svg = std::fs::read_to_string(dir.join("w.svg")).unwrap();
        assert_eq!(svg.contains("reference floor"), floor, "{metric}");
        assert!(svg.contains(axis), "{metric}: the axis");
        assert!(svg.contains("≤ 1e-"), "{metric}: no labelled run");
        // The legend names the series.
        for m in [
            "lie-poisson (τ = cayley, θ = 1)",
            "rkmk4 (τ = exp)",
            "exact",
        ] {
            assert!(svg.contains(m), "{m} not in the legend");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
