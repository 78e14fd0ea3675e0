//! End-to-end tests of the `lie-sim` binary: every example scene runs and writes the documented
//! CSV with its invariants intact, `plot` and `trade` write their files, and every kind of bad input
//! is a one-line error naming the field, with a non-zero exit status and no output file left.
//!
//! Runs are kept short (`--duration`) so that the suite is fast in debug builds.

use crate::common::*;
use std::path::Path;
use std::process::Output;

impl Csv {
    /// max_k |x_k − x₀| / |x₀| over a column.
    fn max_relative_drift(&self, name: &str) -> f64 {
        let c = self.col(name);
        c.iter()
            .map(|x| (x - c[0]).abs() / c[0].abs())
            .fold(0.0, f64::max)
    }
    /// max_k ‖g_kᵀ g_k − I‖_max over the rotation block (the top-left `r`×`r`) of g.
    fn max_orthogonality_defect(&self, side: usize, r: usize) -> f64 {
        let j0 = self.header.iter().position(|h| h == "g11").unwrap();
        let mut worst = 0.0f64;
        for row in &self.rows {
            let g = |i: usize, j: usize| row[j0 + i * side + j];
            for a in 0..r {
                for b in 0..r {
                    let dot: f64 = (0..r).map(|k| g(k, a) * g(k, b)).sum();
                    let id = if a == b { 1.0 } else { 0.0 };
                    worst = worst.max((dot - id).abs());
                }
            }
        }
        worst
    }
}

/// The trajectory columns: μ, g, energy, the Casimir, then the attitude (quaternion and rotation
/// vector) of `bodies` bodies (0 or 1 here).
fn expected_header(n_mu: usize, side: Option<usize>, casimir: bool, bodies: usize) -> Vec<String> {
    let mut h = vec!["t".to_string()];
    h.extend((1..=n_mu).map(|i| format!("mu{i}")));
    if let Some(m) = side {
        for i in 1..=m {
            for j in 1..=m {
                h.push(format!("g{i}{j}"));
            }
        }
    }
    h.push("energy".into());
    if casimir {
        h.push("casimir".into());
    }
    for _ in 0..bodies {
        h.extend(["qw", "qx", "qy", "qz", "rv1", "rv2", "rv3"].map(String::from));
    }
    h
}

/// Rows written for `steps` steps at `stride`: t = 0, every stride-th step, and the last step.
fn expected_rows(steps: usize, stride: usize) -> usize {
    // ⌈steps/stride⌉ rows after the first, the last one at T.
    1 + steps.div_ceil(stride)
}

/// Relative energy error accepted over T = 1 in the example-scene checks (see [`check_scene`]).
const ENERGY_TOL: f64 = 1e-5;

/// Runs an example scene for T = 1 and checks the CSV: header, row count, t(T) = 1, the Casimir
/// (where the system has one) to round-off and the energy to the method's accuracy, and g on its
/// group.
///
/// Tolerances: the Lie–Poisson and Euler–Poincaré integrators keep μ on its coadjoint orbit, so the
/// Casimir drifts only by round-off (10⁻¹² over ≤ 1000 steps leaves ~10³ ulps of slack); the energy
/// error of these second-order methods at the scenes' steps over T = 1 was measured ≤ 3·10⁻⁷ and is
/// checked at [`ENERGY_TOL`]; R stays orthogonal to round-off because every update multiplies by
/// τ(ξ) ∈ SO(n) (10⁻¹³ ≈ 500 ulps).
fn check_scene(
    file: &str,
    n_mu: usize,
    side: usize,
    rot: usize,
    step: f64,
    stride: usize,
    casimir: bool,
) {
    let energy_tol = ENERGY_TOL;
    let (csv, summary) = run_example(file, "1");
    assert_eq!(
        csv.header,
        // SO(3), SE(3) and SE(2) hold a body's attitude; SO(4) does not.
        expected_header(n_mu, Some(side), casimir, usize::from(rot <= 3)),
        "{file}"
    );
    let steps = (1.0 / step).round() as usize;
    assert_eq!(csv.rows.len(), expected_rows(steps, stride), "{file}");
    let t = csv.col("t");
    assert!(
        (t[t.len() - 1] - 1.0).abs() < 1e-12,
        "{file}: t(T) = {}",
        t[t.len() - 1]
    );
    if casimir {
        assert!(
            csv.max_relative_drift("casimir") < 1e-12,
            "{file}: Casimir drift {}",
            csv.max_relative_drift("casimir")
        );
    }
    assert!(
        csv.max_relative_drift("energy") < energy_tol,
        "{file}: energy drift {}",
        csv.max_relative_drift("energy")
    );
    assert!(
        csv.max_orthogonality_defect(side, rot) < 1e-13,
        "{file}: ‖RᵀR − I‖ = {}",
        csv.max_orthogonality_defect(side, rot)
    );
    for key in [
        "system",
        "method",
        "tau",
        "theta",
        "properties   order",
        "wall time",
        "energy",
        "casimir",
    ] {
        assert!(
            summary.contains(key),
            "{file}: summary lacks {key}: {summary}"
        );
    }
}

#[test]
fn free_rigid_body_scene_writes_documented_csv_with_invariants() {
    check_scene("free-rigid-body.toml", 3, 3, 3, 0.05, 2, true);
}

#[test]
fn default_scene_file_writes_documented_csv_with_invariants() {
    check_scene("default.toml", 3, 3, 3, 0.01, 10, true);
}

#[test]
fn rigid_body_se3_scene_writes_documented_csv_with_invariants() {
    check_scene("rigid-body-se3.toml", 6, 4, 3, 0.02, 5, true);
}

#[test]
fn planar_body_se2_scene_writes_documented_csv_with_invariants() {
    check_scene("planar-body-se2.toml", 3, 3, 2, 0.01, 5, true);
}

#[test]
fn geodesic_so_n_scene_writes_documented_csv_with_invariants() {
    check_scene("geodesic-so-n.toml", 6, 4, 4, 0.02, 5, true);
}

/// The heavy top has a potential, so no Casimir column; its energy h(Π) + m g χ·Γ is conserved to
/// O(h²) (h = 10⁻³ here).
#[test]
fn heavy_top_scene_writes_documented_csv_with_invariants() {
    check_scene("heavy-top.toml", 3, 3, 3, 0.001, 10, false);
}

#[test]
fn reconstruct_false_leaves_out_the_group_columns() {
    let dir = temp_dir("noreconstruct");
    let scene = dir.join("s.toml");
    let text = std::fs::read_to_string(scenes_dir().join("free-rigid-body.toml"))
        .unwrap()
        .replace("reconstruct = true", "reconstruct = false");
    std::fs::write(&scene, text).unwrap();
    let o = lie_sim(
        &["run", "s.toml", "--out", "t.csv", "--duration", "0.5"],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        Csv::read(&dir.join("t.csv")).header,
        expected_header(3, None, true, 0)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `lie-sim` with no arguments runs the embedded default scene, writes the CSV and the plot under
/// target/lie-sim/ of the working directory, and says so.
#[test]
fn no_arguments_runs_the_default_scene_and_reports_its_outputs() {
    let dir = temp_dir("noargs");
    let o = lie_sim(&[], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let s = stdout(&o);
    assert!(s.contains("free-rigid-body"), "{s}");
    assert!(s.contains("target/lie-sim/default.csv"), "{s}");
    assert!(s.contains("target/lie-sim/default.svg"), "{s}");
    let csv = Csv::read(&dir.join("target/lie-sim/default.csv"));
    // T = 100, h = 0.01, stride 10.
    assert_eq!(csv.rows.len(), expected_rows(10_000, 10));
    assert!(csv.max_relative_drift("casimir") < 1e-12);
    let svg = std::fs::read_to_string(dir.join("target/lie-sim/default.svg")).unwrap();
    assert!(svg.starts_with("<svg"), "not an SVG");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn plot_writes_an_svg_of_a_run() {
    let dir = temp_dir("plot");
    let scene = scenes_dir().join("planar-body-se2.toml");
    let o = lie_sim(
        &[
            "run",
            scene.to_str().unwrap(),
            "--out",
            "t.csv",
            "--duration",
            "0.5",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let o = lie_sim(&["plot", "t.csv", "--out", "p.svg"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(dir.join("p.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("Casimir") && svg.contains("mu3"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn plot_of_a_file_that_is_not_a_trajectory_fails_naming_the_line() {
    let dir = temp_dir("badplot");
    std::fs::write(dir.join("bad.csv"), "t,energy\n0,1\n0.1,oops\n").unwrap();
    let o = lie_sim(&["plot", "bad.csv", "--out", "p.svg"], &dir);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("bad.csv:3"), "{}", stderr(&o));
    assert!(!dir.join("p.svg").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The trade on a tiny horizon: one row per (available method, step), a CSV with the documented
/// columns and an SVG.
#[test]
fn trade_writes_a_work_precision_table_and_plot() {
    let dir = temp_dir("trade");
    let o = lie_sim(
        &[
            "trade",
            "--out",
            "w.csv",
            "--steps",
            "0.05,0.025",
            "--repeats",
            "1",
            "--duration",
            "0.2",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("w.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "method,tau,theta,composition,tolerance,h,steps,ns_per_step,seconds,error,error_status,\
         reference_error,max_energy_error,max_casimir_error,max_momentum_map_error,geometric,\
         failure,epsilon"
    );
    // Every configuration the registry lists as applying to the free body (`lie-sim methods
    // --markdown`: lie-poisson, euler-poincare and euler-arnold × 2 τ × 3 θ, their compositions,
    // the modified Hamiltonians, the processed methods, splitting, kinetic-kick, rk4, rkmk4) × 2
    // steps, and the exact flow in one step and at the 2 steps.
    let listing = lie_sim(&["methods", "--markdown"], &dir);
    assert!(listing.status.success(), "{}", stderr(&listing));
    let listing = String::from_utf8(listing.stdout).unwrap();
    let applicable = listing
        .lines()
        .skip_while(|l| !l.starts_with("| configuration | free-rigid-body |"))
        .skip(2)
        .take_while(|l| l.starts_with("| `"))
        .filter(|l| l.split(" | ").nth(1) != Some("—"))
        .count();
    assert!(applicable > 50, "{listing}");
    let rows: Vec<&str> = lines.collect();
    // The tolerance-driven configurations (a `tolerance` cell) run the 10 tolerances 1e-3 …
    // 1e-12 instead of the steps.
    let to_tolerance: Vec<&str> = rows
        .iter()
        .copied()
        .filter(|r| !r.split(',').nth(4).unwrap().is_empty())
        .collect();
    let mut adaptive: Vec<&str> = to_tolerance
        .iter()
        .map(|r| r.split(',').next().unwrap())
        .collect();
    adaptive.dedup();
    assert_eq!(
        adaptive,
        ["rkmk-dopri5", "rkmk-dop853", "dopri5", "dop853"],
        "{text}"
    );
    assert_eq!(to_tolerance.len(), 10 * adaptive.len(), "{text}");
    assert_eq!(
        rows.len() - to_tolerance.len(),
        2 * (applicable - adaptive.len()) + 1,
        "{text}"
    );
    for (prefix, n) in [
        ("modified-lie-poisson,cayley,0.5,order-4,", 2),
        ("modified-lie-poisson,exp,0,order-6,", 2),
        ("processed-lie-poisson,exp,0.5,blanes-casas-murua-6-11,", 2),
        ("processed-splitting,-,-,blanes-6,", 2),
        ("processed-kinetic-kick,-,-,blanes-casas-murua-6-13,", 2),
        // Two steps, and two ε of reversible steps (the row's `Trade::reversible`).
        ("splitting,-,-,-,", 4),
        ("splitting,-,-,kahan-li-6,", 4),
        // Kinetic–kick runs each of its coefficient sets with reversible steps too.
        ("kinetic-kick,-,-,blanes-moan-6,", 4),
        ("exact,-,-,-,,0.2,1,", 1),
    ] {
        assert_eq!(
            rows.iter().filter(|r| r.starts_with(prefix)).count(),
            n,
            "{prefix}: {text}"
        );
    }
    for name in ["triple-jump-4", "kahan-li-6", "kahan-li-8"] {
        let n = rows
            .iter()
            .filter(|r| r.starts_with(&format!("lie-poisson,exp,0.5,{name},")))
            .count();
        assert_eq!(n, 2, "{name} with τ = exp: {text}");
    }
    assert_eq!(
        rows.iter()
            .filter(|r| r.starts_with("euler-arnold,"))
            .count(),
        12,
        "{text}"
    );
    for r in &rows {
        let f: Vec<&str> = r.split(',').collect();
        // Second-order or first-order methods at h ≤ 0.05 over T = 0.2 on a body with |Ω| ≈ 1:
        // errors well below 10⁻², against a reference far more accurate than that; an error
        // below the reference's estimate (the exact flow's) is unresolved, its cell empty.
        // Columns: method, tau, theta, composition, tolerance, h, steps, ns, seconds, error,
        // error_status, …
        match f[10] {
            "measured" => {
                let err: f64 = f[9].parse().unwrap();
                assert!(err.is_finite() && err < 1e-2, "{r}");
            }
            status => assert!(status == "unresolved" && f[9].is_empty(), "{r}"),
        }
    }
    assert!(std::fs::read_to_string(dir.join("w.svg"))
        .unwrap()
        .starts_with("<svg"));
    assert!(
        stdout(&o).contains("reference: the exact free-body flow, the mean of its evaluations"),
        "{}",
        stdout(&o)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---------------------------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------------------------

const GOOD: &str = r#"
[system]
kind = "free-rigid-body"
inertia = [1.0, 2.0, 3.0]

[initial]
momentum = [0.1, 1.0, 0.1]

[integrator]
method = "lie-poisson"
tau = "cayley"
theta = 0.5
step = 0.1
duration = 0.3
"#;

#[test]
fn good_scene_used_by_the_rejection_tests_runs() {
    let dir = temp_dir("good");
    std::fs::write(dir.join("s.toml"), GOOD).unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "t.csv"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every `solver` choice runs and solves the same step equations to the same tolerance: the
/// CSVs agree entry by entry to 1e-12 (the solvers stop at 1e-14 relative in ξ).
#[test]
fn every_solver_choice_runs_and_the_trajectories_agree() {
    let dir = temp_dir("solvers");
    let mut runs = vec![];
    for s in ["simplified-newton", "newton", "newton-fd", "fixed-point"] {
        let scene = GOOD.replace(
            "duration = 0.3",
            &format!("duration = 0.3\nsolver = \"{s}\""),
        );
        std::fs::write(dir.join("s.toml"), scene).unwrap();
        let out = format!("{s}.csv");
        let o = lie_sim(&["run", "s.toml", "--out", &out], &dir);
        assert!(o.status.success(), "{s}: {}", stderr(&o));
        runs.push((s, Csv::read(&dir.join(out))));
    }
    let (_, reference) = &runs[0];
    for (s, csv) in &runs[1..] {
        assert_eq!(csv.header, reference.header, "{s}");
        assert_eq!(csv.rows.len(), reference.rows.len(), "{s}");
        for (a, b) in csv
            .rows
            .iter()
            .flatten()
            .zip(reference.rows.iter().flatten())
        {
            assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{s}: {a} vs {b}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn unknown_solver_is_an_error_naming_the_field() {
    let bad = GOOD.replace("duration = 0.3", "duration = 0.3\nsolver = \"bisection\"");
    assert_rejected("unknown-solver", &bad, &["integrator.solver", "bisection"]);
}

#[test]
fn missing_scene_file_is_an_error_naming_the_file() {
    let dir = temp_dir("missing");
    let o = lie_sim(&["run", "nope.toml", "--out", "t.csv"], &dir);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("cannot read nope.toml"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.join("t.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn malformed_toml_is_an_error_naming_the_line() {
    let bad = GOOD.replace("step = 0.1", "step = = 0.1");
    assert_rejected("malformed", &bad, &["s.toml:13", "malformed TOML"]);
}

#[test]
fn unknown_key_is_an_error_naming_it() {
    let bad = GOOD.replace("inertia =", "inertial =");
    assert_rejected("unknown-key", &bad, &["system.inertial", "unknown field"]);
}

#[test]
fn unknown_system_is_an_error_naming_the_field() {
    let bad = GOOD.replace("free-rigid-body", "bouncing-ball");
    assert_rejected("unknown-system", &bad, &["system.kind", "bouncing-ball"]);
}

#[test]
fn unknown_method_is_an_error_naming_the_field() {
    let bad = GOOD.replace("\"lie-poisson\"", "\"leapfrog\"");
    assert_rejected("unknown-method", &bad, &["integrator.method", "leapfrog"]);
}

#[test]
fn unknown_tau_is_an_error_naming_the_field() {
    let bad = GOOD.replace("\"cayley\"", "\"pade\"");
    assert_rejected("unknown-tau", &bad, &["integrator.tau", "pade"]);
}

#[test]
fn non_positive_inertia_is_an_error_naming_the_field() {
    let bad = GOOD.replace("[1.0, 2.0, 3.0]", "[1.0, -2.0, 3.0]");
    assert_rejected(
        "negative-inertia",
        &bad,
        &["system.inertia", "positive", "-2"],
    );
    let bad = GOOD.replace("[1.0, 2.0, 3.0]", "[1.0, 0.0, 3.0]");
    assert_rejected("zero-inertia", &bad, &["system.inertia", "positive"]);
}

#[test]
fn non_finite_inertia_is_an_error_naming_the_field() {
    let bad = GOOD.replace("[1.0, 2.0, 3.0]", "[1.0, nan, 3.0]");
    assert_rejected("nan-inertia", &bad, &["system.inertia", "finite"]);
    let bad = GOOD.replace("[1.0, 2.0, 3.0]", "[1.0, inf, 3.0]");
    assert_rejected("inf-inertia", &bad, &["system.inertia", "finite"]);
}

#[test]
fn non_symmetric_inertia_matrix_is_an_error_naming_the_field() {
    let bad = GOOD.replace(
        "[1.0, 2.0, 3.0]",
        "[[1.0, 0.5, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]]",
    );
    assert_rejected("asym-inertia", &bad, &["system.inertia", "symmetric"]);
}

#[test]
fn non_orthogonal_attitude_is_an_error_naming_the_field() {
    let bad = GOOD.replace(
        "momentum = [0.1, 1.0, 0.1]",
        "momentum = [0.1, 1.0, 0.1]\nattitude = { matrix = [[1.0, 0.1, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] }",
    );
    assert_rejected(
        "skew-attitude",
        &bad,
        &["initial.attitude.matrix", "orthogonal"],
    );
    let bad = GOOD.replace(
        "momentum = [0.1, 1.0, 0.1]",
        "momentum = [0.1, 1.0, 0.1]\nattitude = { matrix = [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] }",
    );
    assert_rejected(
        "reflection-attitude",
        &bad,
        &["initial.attitude.matrix", "determinant"],
    );
    let bad = GOOD.replace(
        "momentum = [0.1, 1.0, 0.1]",
        "momentum = [0.1, 1.0, 0.1]\nattitude = { quaternion = [1.0, 0.5, 0.0, 0.0] }",
    );
    assert_rejected(
        "quaternion-norm",
        &bad,
        &["initial.attitude.quaternion", "unit norm"],
    );
}

#[test]
fn zero_or_negative_step_is_an_error_naming_the_field() {
    assert_rejected(
        "zero-step",
        &GOOD.replace("step = 0.1", "step = 0.0"),
        &["integrator.step", "positive"],
    );
    assert_rejected(
        "negative-step",
        &GOOD.replace("step = 0.1", "step = -0.1"),
        &["integrator.step", "positive", "-0.1"],
    );
}

#[test]
fn duration_that_is_not_a_number_is_an_error_naming_the_field() {
    assert_rejected(
        "string-duration",
        &GOOD.replace("duration = 0.3", "duration = \"ten seconds\""),
        &["integrator.duration", "ten seconds"],
    );
    assert_rejected(
        "nan-duration",
        &GOOD.replace("duration = 0.3", "duration = nan"),
        &["integrator.duration", "finite"],
    );
}

#[test]
fn theta_outside_unit_interval_is_an_error_naming_the_field() {
    assert_rejected(
        "theta",
        &GOOD.replace("theta = 0.5", "theta = 1.5"),
        &["integrator.theta", "[0, 1]"],
    );
}

#[test]
fn missing_field_is_an_error_naming_it() {
    assert_rejected(
        "missing-step",
        &GOOD.replace("step = 0.1\n", ""),
        &[
            "integrator.step",
            "needs a step h > 0",
            "or name a method that takes a tolerance",
        ],
    );
}

#[test]
fn wrong_momentum_length_is_an_error_naming_the_field() {
    assert_rejected(
        "momentum-len",
        &GOOD.replace("[0.1, 1.0, 0.1]", "[0.1, 1.0]"),
        &["initial.momentum", "3 components"],
    );
}

#[test]
fn parameter_of_another_system_is_an_error_naming_it() {
    assert_rejected(
        "misplaced",
        &GOOD.replace(
            "inertia = [1.0, 2.0, 3.0]",
            "inertia = [1.0, 2.0, 3.0]\nmass = 2.0",
        ),
        &["system.mass", "not a parameter of free-rigid-body"],
    );
}

#[test]
fn command_line_override_that_is_not_a_number_is_a_usage_error() {
    let dir = temp_dir("cli-duration");
    let o = lie_sim(&["run", "--duration", "abc", "--out", "t.csv"], &dir);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--duration"), "{}", stderr(&o));
    assert!(!dir.join("t.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn command_line_override_is_checked_like_the_scene() {
    let dir = temp_dir("cli-step");
    let o = lie_sim(&["run", "--step=-1", "--out", "t.csv"], &dir);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("integrator.step"), "{}", stderr(&o));
    assert!(!dir.join("t.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn rkmk4_with_cayley_is_an_error_naming_the_field() {
    let bad = GOOD
        .replace("\"lie-poisson\"", "\"rkmk4\"")
        .replace("theta = 0.5\n", "");
    assert_rejected("rkmk4-cayley", &bad, &["integrator.tau", "rkmk4", "exp"]);
}

#[test]
fn rk4_with_a_tau_is_an_error_naming_the_field() {
    let bad = GOOD
        .replace("\"lie-poisson\"", "\"rk4\"")
        .replace("theta = 0.5\n", "");
    assert_rejected("rk4-tau", &bad, &["integrator.tau", "rk4"]);
}

#[test]
fn heavy_top_without_reconstruction_is_an_error_naming_the_field() {
    let text = std::fs::read_to_string(scenes_dir().join("heavy-top.toml"))
        .unwrap()
        .replace("[integrator]", "[integrator]\nreconstruct = false");
    assert_rejected(
        "top-noreconstruct",
        &text,
        &["integrator.reconstruct", "potential"],
    );
}

#[test]
fn euler_arnold_on_a_system_with_a_potential_is_refused_naming_the_method() {
    let text = std::fs::read_to_string(scenes_dir().join("heavy-top.toml"))
        .unwrap()
        .replace("\"lie-poisson\"", "\"euler-arnold\"");
    assert_rejected(
        "euler-arnold-top",
        &text,
        &[
            "integrator.method",
            "euler-arnold",
            "purely kinetic",
            "heavy-top",
        ],
    );
}

#[test]
fn rk4_on_a_group_other_than_so3_is_reported_as_not_available() {
    let text = std::fs::read_to_string(scenes_dir().join("planar-body-se2.toml"))
        .unwrap()
        .replace("\"euler-poincare\"", "\"rk4\"")
        .replace("tau = \"cayley\"\n", "")
        .replace("theta = 0.5\n", "");
    assert_rejected("rk4-se2", &text, &["not yet available", "rk4", "rkmk4"]);
}

#[test]
fn so_n_of_a_size_not_compiled_in_is_refused_naming_the_field_and_the_sizes() {
    let text = std::fs::read_to_string(scenes_dir().join("geodesic-so-n.toml"))
        .unwrap()
        .replace("n = 4", "n = 7")
        .replace("[1.0, 1.5, 2.0, 3.0]", "[1, 2, 3, 4, 5, 6, 7]")
        .replace(
            "[1.0, 0.2, -0.3, 0.5, 0.1, 0.4]",
            "[1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]",
        );
    assert_rejected(
        "so7",
        &text,
        &["system.n", "SO(7)", "[3, 4, 5, 6, 8, 10, 20, 50]"],
    );
}

#[test]
fn so_n_momentum_of_the_wrong_length_is_an_error_naming_the_field() {
    let text = std::fs::read_to_string(scenes_dir().join("geodesic-so-n.toml"))
        .unwrap()
        .replace("[1.0, 0.2, -0.3, 0.5, 0.1, 0.4]", "[1.0, 0.2, -0.3]");
    assert_rejected("so4-momentum", &text, &["initial.momentum", "6 components"]);
}

// ---------------------------------------------------------------------------------------------
// Euler–Arnold and compositions
// ---------------------------------------------------------------------------------------------

/// Runs `scene` (text) for its duration and returns the CSV and the summary printed.
fn run_text(name: &str, scene: &str) -> (Csv, String) {
    let dir = temp_dir(name);
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "t.csv"], &dir);
    assert!(o.status.success(), "{name}: {}", stderr(&o));
    let csv = Csv::read(&dir.join("t.csv"));
    std::fs::remove_dir_all(&dir).unwrap();
    (csv, stdout(&o))
}

/// Euler–Arnold on the free rigid body: the Euler–Poincaré integrator of l(ξ) = ½⟨𝕀ξ, ξ⟩, which
/// for this quadratic system is the same scheme as `euler-poincare` — so its final state, energy
/// and Casimir |Π|² (monitored like euler-poincare's) agree with euler-poincare's to round-off
/// (10⁻¹² over 3 implicit steps; they were seen to agree bit for bit).
#[test]
fn euler_arnold_runs_on_the_free_rigid_body_like_euler_poincare() {
    let ea = GOOD.replace("\"lie-poisson\"", "\"euler-arnold\"");
    let ep = GOOD.replace("\"lie-poisson\"", "\"euler-poincare\"");
    let (a, summary) = run_text("ea-frb", &ea);
    let (b, _) = run_text("ep-frb", &ep);
    assert!(summary.contains("euler-arnold"), "{summary}");
    assert_eq!(a.header, expected_header(3, Some(3), true, 1));
    assert_eq!(a.rows.len(), 4);
    let last = a.rows.len() - 1;
    for (x, y) in a.rows[last].iter().zip(&b.rows[last]) {
        assert!(
            (x - y).abs() < 1e-12,
            "{:?} vs {:?}",
            a.rows[last],
            b.rows[last]
        );
    }
}

/// A composition scene: kahan-li-6 on the θ = ½ Lie–Poisson method. The CSV has the documented
/// columns and rows, the Casimir is kept to round-off (inherited from the base method), and the
/// final state agrees with the base method at a 10× smaller step to its own O(h²) error
/// (≈ 10⁻³ at h = 0.1): a composition that did not sum its sub-steps to h would miss by O(1).
#[test]
fn composition_scene_runs_and_writes_a_valid_csv() {
    let comp = GOOD.replace("[integrator]", "[integrator]\ncomposition = \"kahan-li-6\"");
    let (c, summary) = run_text("compose", &comp);
    assert!(summary.contains("kahan-li-6"), "{summary}");
    assert_eq!(c.header, expected_header(3, Some(3), true, 1));
    assert_eq!(c.rows.len(), 4);
    let t = c.col("t");
    assert_eq!(t[t.len() - 1], 0.3);
    assert!(c.max_relative_drift("casimir") < 1e-13);
    assert!(c.max_relative_drift("energy") < 1e-8);
    assert!(c.max_orthogonality_defect(3, 3) < 1e-14);
    let fine = GOOD.replace("step = 0.1", "step = 0.01");
    let (f, _) = run_text("compose-ref", &fine);
    let (lc, lf) = (&c.rows[c.rows.len() - 1], &f.rows[f.rows.len() - 1]);
    for (x, y) in lc.iter().zip(lf) {
        assert!((x - y).abs() < 1e-3, "{lc:?} vs {lf:?}");
    }
}

/// A composition (or processing) needs a base the integrators crate reports symmetric — one rule,
/// the library's `SymmetricMethod`: Euler–Poincaré θ = 0 is not, nor Lie–Poisson θ = 0 with a
/// potential; Lie–Poisson θ = 0 without one is (θ = 0 and θ = 1 coincide), and so is the
/// kinetic–kick.
#[test]
fn composition_follows_the_librarys_symmetry_of_its_base() {
    let bad = GOOD
        .replace("\"lie-poisson\"", "\"euler-poincare\"")
        .replace("theta = 0.5", "theta = 0.0")
        .replace("[integrator]", "[integrator]\ncomposition = \"kahan-li-6\"");
    assert_rejected(
        "compose-theta",
        &bad,
        &["integrator.composition", "symmetric", "θ = 0"],
    );
    let top = std::fs::read_to_string(scenes_dir().join("heavy-top.toml"))
        .unwrap()
        .replace("theta = 0.5", "theta = 0.0")
        .replace(
            "[integrator]",
            "[integrator]\ncomposition = \"triple-jump-4\"",
        );
    assert_rejected(
        "compose-top-theta",
        &top,
        &["integrator.composition", "θ = 0", "heavy-top"],
    );
    let lp0 = GOOD.replace("theta = 0.5", "theta = 0.0").replace(
        "[integrator]",
        "[integrator]\ncomposition = \"triple-jump-4\"",
    );
    let (c, summary) = run_text("compose-lp0", &lp0);
    assert!(summary.contains("triple-jump-4"), "{summary}");
    assert!(c.max_relative_drift("casimir") < 1e-13);
    let kick = with_method(
        "free-rigid-body.toml",
        "kinetic-kick",
        "composition = \"triple-jump-4\"",
    );
    let (_, summary) = run_text("compose-kick", &kick);
    assert!(summary.contains("triple-jump-4"), "{summary}");
}

#[test]
fn composition_of_rk4_is_refused_naming_the_field() {
    let bad = GOOD
        .replace("\"lie-poisson\"", "\"rk4\"")
        .replace("tau = \"cayley\"\n", "")
        .replace("theta = 0.5\n", "")
        .replace(
            "[integrator]",
            "[integrator]\ncomposition = \"triple-jump-4\"",
        );
    assert_rejected("compose-rk4", &bad, &["integrator.composition", "rk4"]);
}

#[test]
fn unknown_composition_is_refused_listing_the_known_ones() {
    let bad = GOOD.replace("[integrator]", "[integrator]\ncomposition = \"yoshida-12\"");
    assert_rejected(
        "compose-unknown",
        &bad,
        &["integrator.composition", "yoshida-12", "kahan-li-8"],
    );
}

// ---------------------------------------------------------------------------------------------
// Splittings and the exact flow
// ---------------------------------------------------------------------------------------------

/// `scene` (an example file) with its `[integrator]` method replaced by `method` (no τ, θ).
fn with_method(file: &str, method: &str, extra: &str) -> String {
    let text = std::fs::read_to_string(scenes_dir().join(file)).unwrap();
    let mut out = String::new();
    for line in text.lines() {
        let key = line.split('=').next().unwrap_or("").trim();
        match key {
            "method" => out.push_str(&format!("method = \"{method}\"\n{extra}\n")),
            "tau" | "theta" | "composition" => {}
            _ => {
                out.push_str(line);
                out.push('\n');
            }
        }
    }
    out
}

/// Every scene file in examples/scenes runs (a short horizon) — the documented examples stay true.
#[test]
fn every_example_scene_runs() {
    let mut seen = 0;
    for e in std::fs::read_dir(scenes_dir()).unwrap() {
        let path = e.unwrap().path();
        if path.extension().and_then(|x| x.to_str()) != Some("toml") {
            continue;
        }
        let dir = temp_dir(&format!(
            "every-{}",
            path.file_stem().unwrap().to_str().unwrap()
        ));
        let o = lie_sim(
            &[
                "run",
                path.to_str().unwrap(),
                "--out",
                "t.csv",
                "--duration",
                "0.05",
            ],
            &dir,
        );
        assert!(o.status.success(), "{}: {}", path.display(), stderr(&o));
        std::fs::remove_dir_all(&dir).unwrap();
        seen += 1;
    }
    assert!(seen >= 8, "{seen} scenes");
}

/// `method = "splitting"` on every system that has one (free body, heavy top, SE(3) satellite,
/// SE(2) body), and its composition: the run completes, the Casimir (where monitored) is kept to
/// round-off, g stays on its group, and the energy error is that of a second-order method at the
/// scene's step (≤ 1e-3 over T = 1).
#[test]
fn splitting_runs_on_every_system_with_a_splitting() {
    for (file, side, rot, casimir) in [
        ("free-rigid-body.toml", 3, 3, true),
        ("heavy-top.toml", 3, 3, false),
        ("rigid-body-se3.toml", 4, 3, false),
        ("planar-body-se2.toml", 3, 2, false),
    ] {
        for extra in ["", "composition = \"triple-jump-4\""] {
            let text = with_method(file, "splitting", extra)
                .replace("[integrator]", "[integrator]\nduration = 1.0");
            let text = strip_key(&text, "duration", 1);
            let (c, summary) = run_text(&format!("split-{file}"), &text);
            assert!(summary.contains("splitting"), "{summary}");
            let t = c.col("t");
            assert!((t[t.len() - 1] - 1.0).abs() < 1e-12, "{file}");
            if casimir {
                assert!(c.max_relative_drift("casimir") < 1e-13, "{file}");
            }
            assert!(
                c.max_relative_drift("energy") < 1e-3,
                "{file} {extra}: {}",
                c.max_relative_drift("energy")
            );
            assert!(c.max_orthogonality_defect(side, rot) < 1e-13, "{file}");
        }
    }
}

/// Removes every `key = …` line after the first `keep` ones.
fn strip_key(text: &str, key: &str, keep: usize) -> String {
    let mut seen = 0;
    let mut out = String::new();
    for line in text.lines() {
        if line.split('=').next().unwrap_or("").trim() == key {
            seen += 1;
            if seen > keep {
                continue;
            }
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// The exact flow on the free body agrees with kinetic-kick (no potential: the same flow) and
/// with a fine Lie–Poisson run; energy and Casimir at round-off.
#[test]
fn exact_and_kinetic_kick_run_on_the_free_body() {
    let exact = with_method("free-rigid-body.toml", "exact", "");
    let kick = with_method(
        "free-rigid-body.toml",
        "kinetic-kick",
        "splitting = \"blanes-moan-4\"",
    );
    let (a, summary) = run_text("exact-frb", &exact);
    assert!(summary.contains("exact"), "{summary}");
    let (b, summary) = run_text("kick-frb", &kick);
    assert!(summary.contains("blanes-moan-4 (order 4"), "{summary}");
    assert!(a.max_relative_drift("energy") < 1e-13 && a.max_relative_drift("casimir") < 1e-13);
    let (la, lb) = (&a.rows[a.rows.len() - 1], &b.rows[b.rows.len() - 1]);
    for (x, y) in la.iter().zip(lb) {
        assert!((x - y).abs() < 1e-12, "{la:?} vs {lb:?}");
    }
}

/// The kinetic–kick splittings on the heavy top, orders 2, 4, 6: the higher orders land closer to
/// one another than Strang does to them.
#[test]
fn kinetic_kick_runs_on_the_heavy_top_with_every_scheme() {
    let mut last = vec![];
    for scheme in ["strang", "blanes-moan-4", "blanes-moan-6"] {
        let text = with_method(
            "heavy-top.toml",
            "kinetic-kick",
            &format!("splitting = \"{scheme}\""),
        )
        .replace("step = 0.001", "step = 0.01")
        .replace("duration = 5.0", "duration = 1.0");
        let (c, summary) = run_text(&format!("kick-top-{scheme}"), &text);
        assert!(summary.contains(scheme), "{summary}");
        assert!(c.max_relative_drift("energy") < 1e-4, "{scheme}");
        last.push(c.rows[c.rows.len() - 1].clone());
    }
    let d = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
    };
    assert!(
        d(&last[1], &last[2]) < 0.1 * d(&last[0], &last[2]),
        "{last:?}"
    );
}

#[test]
fn exact_flow_off_the_free_body_is_refused_naming_why() {
    let text = with_method("heavy-top.toml", "exact", "");
    assert_rejected(
        "exact-top",
        &text,
        &["integrator.method", "exact", "free rigid body"],
    );
}

#[test]
fn kinetic_kick_off_the_rigid_body_is_refused_naming_why() {
    let text = with_method("planar-body-se2.toml", "kinetic-kick", "");
    assert_rejected(
        "kick-se2",
        &text,
        &["integrator.method", "kinetic-kick", "exact flow"],
    );
}

/// The satellite on SE(3) with the exact free-body flow between gravity-gradient kicks: Blanes–Moan
/// 6 agrees with a fine Lie–Poisson run far better than Lie–Poisson at the scene's step does.
#[test]
fn kinetic_kick_runs_on_the_satellite() {
    let kick = with_method(
        "rigid-body-se3.toml",
        "kinetic-kick",
        "splitting = \"blanes-moan-6\"",
    )
    .replace("duration = 20.0", "duration = 2.0");
    let (k, summary) = run_text("kick-sat", &kick);
    assert!(summary.contains("blanes-moan-6"), "{summary}");
    let base = std::fs::read_to_string(scenes_dir().join("rigid-body-se3.toml"))
        .unwrap()
        .replace("duration = 20.0", "duration = 2.0");
    let (coarse, _) = run_text("lp-sat", &base);
    let (fine, _) = run_text("lp-sat-fine", &base.replace("step = 0.02", "step = 0.0025"));
    let last = |c: &Csv| c.rows[c.rows.len() - 1].clone();
    let d = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
    };
    let (dk, dc) = (d(&last(&k), &last(&fine)), d(&last(&coarse), &last(&fine)));
    assert!(dk < 0.1 * dc, "kick {dk:e}, coarse LP {dc:e}");
}

#[test]
fn splitting_of_the_so_n_geodesic_is_refused_naming_why() {
    let text = with_method("geodesic-so-n.toml", "splitting", "");
    assert_rejected(
        "split-son",
        &text,
        &["splitting", "SO(n)", "no such splitting"],
    );
}

#[test]
fn splitting_with_a_tau_or_coefficients_on_another_method_is_refused() {
    let bad = GOOD
        .replace("\"lie-poisson\"", "\"splitting\"")
        .replace("theta = 0.5\n", "");
    assert_rejected("split-tau", &bad, &["integrator.tau", "splitting"]);
    let bad = GOOD.replace(
        "[integrator]",
        "[integrator]\nsplitting = \"blanes-moan-4\"",
    );
    assert_rejected("split-lp", &bad, &["integrator.splitting", "kinetic-kick"]);
    let bad = with_method("heavy-top.toml", "kinetic-kick", "splitting = \"yoshida\"");
    assert_rejected(
        "kick-unknown",
        &bad,
        &["integrator.splitting", "yoshida", "blanes-moan-6"],
    );
}

// ---------------------------------------------------------------------------------------------
// Sweeps and shards
// ---------------------------------------------------------------------------------------------

/// `lie-sim sweep` on the example sweep scene, made small: N members, T = 0.5.
fn sweep(dir: &Path, out: &str, count: usize, extra: &[&str]) -> Output {
    let scene = scenes_dir().join("sweep.toml");
    let count = count.to_string();
    let mut args = vec![
        "sweep",
        scene.to_str().unwrap(),
        "--out",
        out,
        "--count",
        &count,
        "--duration",
        "0.5",
    ];
    args.extend_from_slice(extra);
    lie_sim(&args, dir)
}

/// A sweep writes the naming line, the summary header and `count` rows in index order, every
/// trajectory completed with its Casimir |Π|² kept to round-off and its energy on the level of
/// the scene's Π₀ (h(Π₀) = ½(0.09 + 1/2 + 0.04/3)).
#[test]
fn sweep_writes_one_row_per_member() {
    let dir = temp_dir("sweep");
    let o = sweep(&dir, "s.csv", 37, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("s.csv")).unwrap();
    let mut lines = text.lines();
    assert!(lines
        .next()
        .unwrap()
        .starts_with("# lie-sim sweep: members = 37, shard = 0/1, fingerprint = "));
    assert_eq!(
        lines.next().unwrap(),
        "index,status,steps,time,mu_0,mu_1,mu_2,initial_energy,max_energy_error,\
         max_casimir_error"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 37);
    let e0 = 0.5 * (0.09 + 1.0 / 2.0 + 0.04 / 3.0);
    for (i, r) in rows.iter().enumerate() {
        assert_eq!(r[0], i.to_string());
        assert_eq!(r[1], "completed");
        assert_eq!(r[2], "10");
        let e: f64 = r[7].parse().unwrap();
        assert!((e - e0).abs() < 1e-12 * e0, "{r:?}");
        let dc: f64 = r[9].parse().unwrap();
        assert!(dc < 1e-13, "{r:?}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The sweep of a processed (and of a modified) method: on one thread and on two byte for byte,
/// every member completed — the ensemble reads each member's processed state like any observer.
#[test]
fn sweeps_of_processed_and_modified_methods_run_and_are_thread_independent() {
    let dir = temp_dir("sweep-new");
    let base = std::fs::read_to_string(scenes_dir().join("sweep.toml")).unwrap();
    for (name, key) in [
        ("processed", "processing = \"blanes-casas-murua-6-11\""),
        ("modified", "modified = true\norder = 6"),
    ] {
        std::fs::write(
            dir.join(format!("{name}.toml")),
            base.replace("[integrator]", &format!("[integrator]\n{key}")),
        )
        .unwrap();
        for threads in ["1", "2"] {
            let o = lie_sim(
                &[
                    "sweep",
                    &format!("{name}.toml"),
                    "--out",
                    &format!("{name}-{threads}.csv"),
                    "--count",
                    "12",
                    "--duration",
                    "0.5",
                    "--threads",
                    threads,
                ],
                &dir,
            );
            assert!(o.status.success(), "{name}: {}", stderr(&o));
        }
        let one = std::fs::read_to_string(dir.join(format!("{name}-1.csv"))).unwrap();
        assert_eq!(
            one,
            std::fs::read_to_string(dir.join(format!("{name}-2.csv"))).unwrap(),
            "{name}"
        );
        assert_eq!(one.matches("completed").count(), 12, "{name}: {one}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Shards 0/3, 1/3, 2/3 merged (in any order) are the unsharded sweep byte for byte, and the
/// sweep on one thread is the sweep on two byte for byte.
#[test]
fn merged_shards_equal_the_unsharded_sweep_byte_for_byte() {
    let dir = temp_dir("shards");
    assert!(sweep(&dir, "full.csv", 20, &["--threads", "2"])
        .status
        .success());
    assert!(sweep(&dir, "seq.csv", 20, &["--threads", "1"])
        .status
        .success());
    for i in 0..3 {
        let shard = format!("{i}/3");
        let o = sweep(&dir, &format!("p{i}.csv"), 20, &["--shard", &shard]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let o = lie_sim(
        &["merge", "p2.csv", "p0.csv", "p1.csv", "--out", "merged.csv"],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let full = std::fs::read(dir.join("full.csv")).unwrap();
    assert_eq!(std::fs::read(dir.join("merged.csv")).unwrap(), full);
    assert_eq!(std::fs::read(dir.join("seq.csv")).unwrap(), full);
    let p1 = std::fs::read_to_string(dir.join("p1.csv")).unwrap();
    assert_eq!(p1.lines().count(), 2 + 7, "shard 1/3 of 20 is 6 … 12");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Merge refuses a missing shard, a repeated one, and shards of another sweep, with one line on
/// stderr and no output file.
#[test]
fn merge_refuses_missing_repeated_and_foreign_shards() {
    let dir = temp_dir("merge-bad");
    for i in 0..2 {
        let shard = format!("{i}/2");
        assert!(sweep(&dir, &format!("p{i}.csv"), 6, &["--shard", &shard])
            .status
            .success());
    }
    assert!(
        sweep(&dir, "other.csv", 6, &["--shard", "1/2", "--seed", "7"])
            .status
            .success()
    );
    for (files, needle) in [
        (vec!["p0.csv"], "shard 1/2 is missing"),
        (vec!["p0.csv", "p0.csv", "p1.csv"], "shard 0/2 given twice"),
        (vec!["p0.csv", "other.csv"], "different sweeps"),
    ] {
        let mut args = vec!["merge"];
        args.extend(files.iter().copied());
        args.extend(["--out", "m.csv"]);
        let o = lie_sim(&args, &dir);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{files:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{files:?}: {err}");
        assert!(!dir.join("m.csv").exists());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn sweep_of_a_scene_without_a_sweep_table_is_refused() {
    let dir = temp_dir("sweep-none");
    std::fs::write(dir.join("s.toml"), GOOD).unwrap();
    let o = lie_sim(&["sweep", "s.toml", "--out", "x.csv"], &dir);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("no [sweep] table"), "{}", stderr(&o));
    assert!(!dir.join("x.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn shard_index_out_of_range_is_a_usage_error() {
    let dir = temp_dir("shard-range");
    let o = sweep(&dir, "x.csv", 4, &["--shard", "2/2"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("0-based"), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `modified = true`: Lie–Poisson θ = ½ or 0 on the modified Hamiltonian, order 4 (`order = 6`:
/// 6) on the free body — at the same step it lands far closer to the exact flow than the plain
/// θ = ½ step, and order 6 closer still; refused off the free body, with θ ∉ {½, 0}, with a
/// composition, and `order` without `modified` or other than 4 and 6, naming the field.
#[test]
fn modified_lie_poisson_runs_on_the_free_body_and_is_refused_elsewhere() {
    let exact = GOOD
        .replace("\"lie-poisson\"", "\"exact\"")
        .replace("tau = \"cayley\"\n", "")
        .replace("theta = 0.5\n", "");
    let (e, _) = run_text("mod-exact", &exact);
    let (m, summary) = run_text(
        "mod",
        &GOOD.replace("[integrator]", "[integrator]\nmodified = true"),
    );
    assert!(summary.contains("order 4"), "{summary}");
    let (m6, summary6) = run_text(
        "mod6",
        &GOOD.replace("[integrator]", "[integrator]\nmodified = true\norder = 6"),
    );
    assert!(summary6.contains("order 6"), "{summary6}");
    let (m0, _) = run_text(
        "mod0",
        &GOOD
            .replace("theta = 0.5", "theta = 0.0")
            .replace("[integrator]", "[integrator]\nmodified = true"),
    );
    let (p, _) = run_text("mod-plain", GOOD);
    let last = |c: &Csv| c.rows[c.rows.len() - 1].clone();
    let d = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .fold(0.0f64, |x, (u, v)| x.max((u - v).abs()))
    };
    let (dm, dm6, dm0, dp) = (
        d(&last(&m), &last(&e)),
        d(&last(&m6), &last(&e)),
        d(&last(&m0), &last(&e)),
        d(&last(&p), &last(&e)),
    );
    assert!(dm < 0.05 * dp, "modified {dm:e}, plain {dp:e}");
    assert!(dm0 < 0.05 * dp, "modified θ = 0 {dm0:e}, plain {dp:e}");
    assert!(dm6 < 0.05 * dm, "order 6 {dm6:e}, order 4 {dm:e}");
    assert!(m.max_relative_drift("casimir") < 1e-14);
    let top = std::fs::read_to_string(scenes_dir().join("heavy-top.toml"))
        .unwrap()
        .replace("[integrator]", "[integrator]\nmodified = true");
    assert_rejected("mod-top", &top, &["integrator.method", "free rigid body"]);
    let theta1 = GOOD
        .replace("theta = 0.5", "theta = 1.0")
        .replace("[integrator]", "[integrator]\nmodified = true");
    assert_rejected(
        "mod-theta",
        &theta1,
        &["integrator.modified", "θ = 0.5 or 0", "θ = 1"],
    );
    let order5 = GOOD.replace("[integrator]", "[integrator]\nmodified = true\norder = 5");
    assert_rejected("mod-order", &order5, &["integrator.order", "4 and 6", "5"]);
    let lone = GOOD.replace("[integrator]", "[integrator]\norder = 6");
    assert_rejected(
        "mod-lone-order",
        &lone,
        &["integrator.order", "modified = true"],
    );
}

/// `processing = …`: the processed method of a symmetric base (here θ = ½ Lie–Poisson and the
/// Strang splitting) runs, says so in the summary, and at the same step lands far closer to the
/// exact flow than its base (effective order 6); refused with a non-symmetric base, with a
/// composition, with `modified`, and by an unknown name (listing the known ones).
#[test]
fn processing_runs_on_symmetric_bases_and_is_refused_elsewhere() {
    let exact = GOOD
        .replace("\"lie-poisson\"", "\"exact\"")
        .replace("tau = \"cayley\"\n", "")
        .replace("theta = 0.5\n", "");
    let (e, _) = run_text("proc-exact", &exact);
    let processed = GOOD.replace(
        "[integrator]",
        "[integrator]\nprocessing = \"blanes-casas-murua-6-11\"",
    );
    let (q, summary) = run_text("proc", &processed);
    assert!(summary.contains("effective order 6"), "{summary}");
    let (p, _) = run_text("proc-plain", GOOD);
    let splitting = GOOD
        .replace("\"lie-poisson\"", "\"splitting\"")
        .replace("tau = \"cayley\"\n", "")
        .replace("theta = 0.5\n", "");
    let (s, _) = run_text("proc-strang-plain", &splitting);
    let (sq, _) = run_text(
        "proc-strang",
        &splitting.replace("[integrator]", "[integrator]\nprocessing = \"blanes-6\""),
    );
    let last = |c: &Csv| c.rows[c.rows.len() - 1].clone();
    let d = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .fold(0.0f64, |x, (u, v)| x.max((u - v).abs()))
    };
    let (dq, dp) = (d(&last(&q), &last(&e)), d(&last(&p), &last(&e)));
    assert!(dq < 1e-3 * dp, "processed {dq:e}, plain {dp:e}");
    let (dsq, ds) = (d(&last(&sq), &last(&e)), d(&last(&s), &last(&e)));
    assert!(dsq < 1e-3 * ds, "processed Strang {dsq:e}, plain {ds:e}");
    assert!(q.max_relative_drift("casimir") < 1e-14);
    assert_rejected(
        "proc-theta",
        &processed
            .replace("\"lie-poisson\"", "\"euler-poincare\"")
            .replace("theta = 0.5", "theta = 0.0"),
        &["integrator.processing", "symmetric base", "θ = 0"],
    );
    assert_rejected(
        "proc-comp",
        &processed.replace("[integrator]", "[integrator]\ncomposition = \"kahan-li-6\""),
        &["integrator.processing", "composition"],
    );
    assert_rejected(
        "proc-mod",
        &processed.replace("[integrator]", "[integrator]\nmodified = true"),
        &["integrator.processing", "modified"],
    );
    assert_rejected(
        "proc-name",
        &GOOD.replace("[integrator]", "[integrator]\nprocessing = \"kahan-li-6\""),
        &[
            "integrator.processing",
            "unknown processing scheme",
            "blanes-casas-murua-6-11",
        ],
    );
}

// ---------------------------------------------------------------------------------------------
// [forces]: external torques and damping
// ---------------------------------------------------------------------------------------------

/// GOOD over T = 2 at h = 0.01 with `forces` appended as its `[forces]` table.
fn forced(method: &str, forces: &str) -> String {
    let base = GOOD
        .replace("step = 0.1", "step = 0.01")
        .replace("duration = 0.3", "duration = 2.0");
    let base = match method {
        "lie-poisson" => base,
        "rk4" => base
            .replace("\"lie-poisson\"", "\"rk4\"")
            .replace("tau = \"cayley\"\n", "")
            .replace("theta = 0.5\n", ""),
        "rkmk4" => base
            .replace("\"lie-poisson\"", "\"rkmk4\"")
            .replace("\"cayley\"", "\"exp\"")
            .replace("theta = 0.5\n", ""),
        m => base.replace("\"lie-poisson\"", &format!("\"{m}\"")),
    };
    format!("{base}\n[forces]\n{forces}\n")
}

/// Damping D = c 𝕀 is the force F = −c 𝕀Ω = −cΠ, so Π' = Π × Ω − cΠ and |Π|² = e^{−2ct}|Π₀|²
/// exactly: the Casimir column of a forced run follows it to the method's error (order 2 at
/// h = 0.01 over T = 2: measured 8.3e-7 / 8.0e-7 relative for Lie–Poisson / Euler–Poincaré,
/// 3.4e-12 for RK4 and RKMK4, 5.3e-7 for splitting and kinetic-kick, whose kicks solve the damping
/// by the implicit midpoint rule),
/// and the energy decreases at every output row.
#[test]
fn damping_in_a_scene_decays_the_casimir_at_the_exact_rate() {
    let c = 0.4;
    for (method, tol) in [
        ("lie-poisson", 4e-6),
        ("euler-poincare", 4e-6),
        ("rk4", 2e-11),
        ("rkmk4", 2e-11),
        ("splitting", 4e-6),
        ("kinetic-kick", 4e-6),
    ] {
        let scene = forced(
            method,
            &format!("damping = [{}, {}, {}]", c, 2.0 * c, 3.0 * c),
        );
        let scene = if matches!(method, "splitting" | "kinetic-kick") {
            scene
                .replace("tau = \"cayley\"\n", "")
                .replace("theta = 0.5\n", "")
        } else {
            scene
        };
        let (csv, summary) = run_text(&format!("damp-{method}"), &scene);
        assert!(summary.contains("forces"), "{method}: {summary}");
        let (t, cas, e) = (csv.col("t"), csv.col("casimir"), csv.col("energy"));
        let worst = t
            .iter()
            .zip(&cas)
            .map(|(t, x)| (x / (cas[0] * (-2.0 * c * t).exp()) - 1.0).abs())
            .fold(0.0, f64::max);
        println!("{method}: |Π|² off e^(−2ct) by {worst:.2e}");
        assert!(worst < tol, "{method}: |Π|² off e^(−2ct) by {worst:e}");
        assert!(
            e.windows(2).all(|w| w[1] < w[0]),
            "{method}: energy not decreasing"
        );
    }
}

/// A torque switched on for t < 1 and off after (a piecewise-linear table) on a body with equal
/// moments: Π' = u(t) (Π × Ω = 0), so Π(2) = Π₀ + ∫u = Π₀ + u·(1 + 0.01/2) and then stays. The
/// midpoint-sampled impulses integrate the piecewise-linear u exactly when the knots fall on step
/// boundaries.
#[test]
fn a_scheduled_torque_delivers_its_impulse() {
    let u = [0.3, -0.2, 0.5];
    let forces = format!(
        "torque = {{ times = [0.0, 1.0, 1.01], values = [{u:?}, {u:?}, [0.0, 0.0, 0.0]] }}"
    );
    let scene = forced("lie-poisson", &forces).replace("[1.0, 2.0, 3.0]", "[2.0, 2.0, 2.0]");
    let (csv, _) = run_text("torque-impulse", &scene);
    let last = csv.rows.len() - 1;
    let mu0 = [0.1, 1.0, 0.1];
    for (i, name) in ["mu1", "mu2", "mu3"].iter().enumerate() {
        let got = csv.col(name)[last];
        let want = mu0[i] + u[i] * 1.005;
        assert!((got - want).abs() < 1e-12, "{name}: {got} vs {want}");
    }
}

#[test]
fn malformed_forces_are_errors_naming_the_field() {
    let cases: [(&str, &str, &[&str]); 9] = [
        (
            "unsorted",
            "torque = { times = [0.0, 2.0, 1.0], values = [[0,0,0],[0,0,1],[0,0,0]] }",
            &["forces.torque", "increase"],
        ),
        (
            "mismatch",
            "torque = { times = [0.0, 1.0], values = [[0.0, 0.0, 1.0]] }",
            &["forces.torque"],
        ),
        (
            "nan",
            "torque = [0.0, nan, 1.0]",
            &["forces.torque", "finite"],
        ),
        (
            "two",
            "torque = [0.0, 1.0]",
            &["forces.torque", "3 components"],
        ),
        ("empty", "", &["forces", "empty"]),
        ("unknown", "drag = 1.0", &["forces", "drag"]),
        (
            "asymmetric",
            "damping = [[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]",
            &["forces.damping", "symmetric"],
        ),
        ("inf", "damping = inf", &["forces.damping", "finite"]),
        ("shape", "damping = [1.0, 2.0]", &["forces.damping", "3×3"]),
    ];
    for (name, forces, needles) in cases {
        assert_rejected(
            &format!("forces-{name}"),
            &forced("lie-poisson", forces),
            needles,
        );
    }
}

#[test]
fn forces_on_other_systems_or_methods_are_refused_naming_why() {
    let se3 = std::fs::read_to_string(scenes_dir().join("rigid-body-se3.toml")).unwrap()
        + "\n[forces]\ndamping = 1.0\n";
    assert_rejected(
        "forces-se3",
        &se3,
        &["forces", "free-rigid-body", "heavy-top"],
    );
    let modified = forced("lie-poisson", "damping = 1.0")
        .replace("theta = 0.5\n", "theta = 0.5\nmodified = true\n");
    assert_rejected("forces-modified", &modified, &["external forces"]);
    let exact = forced("exact", "damping = 1.0")
        .replace("tau = \"cayley\"\n", "")
        .replace("theta = 0.5\n", "");
    assert_rejected(
        "forces-exact",
        &exact,
        &["integrator.method", "external forces"],
    );
}
