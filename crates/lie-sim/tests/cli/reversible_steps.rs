//! `integrator.epsilon`: a symmetric method run with the reversible step-density controller of
//! Hairer–Söderlind (steps h = ε/ρ that follow the motion), from a scene, in `run` and `trade`;
//! refused, naming the key, where the method is not symmetric or steps otherwise.

use crate::common::*;

/// The symmetric top 𝕀 = diag(1, 1, 2), Π₀ = (1, 0, 1): Π = (cos(t/2), sin(t/2), 1) in closed
/// form, and |Ω| = √(1 + ¼) constant, so that ρ is constant and the steps are ε/ρ throughout.
fn top(method: &str, extra: &str) -> String {
    format!(
        r#"
name = "symmetric top"
[system]
kind = "free-rigid-body"
inertia = [1.0, 1.0, 2.0]
[initial]
momentum = [1.0, 0.0, 1.0]
[integrator]
method = "{method}"
{extra}
duration = 20.0
"#
    )
}

/// The summary's `h in [a, b]`.
fn step_range(out: &str) -> (f64, f64) {
    let range = out
        .split("h in [")
        .nth(1)
        .and_then(|s| s.split(']').next())
        .unwrap_or_else(|| panic!("no step range in {out}"));
    let (a, b) = range.split_once(", ").unwrap();
    (a.trim().parse().unwrap(), b.trim().parse().unwrap())
}

/// With ε the run lands on T exactly, writes the requested rows at exactly their times, and is
/// as accurate as the method at h = ε/ρ: Strang's O(h²) phase error at ε = 0.01 (h ≈ 0.009)
/// stays below 3e-4 over T = 20, and |Π|² is kept to round-off (a random walk of ~2200
/// roundings: 7e-14 measured, 1e-12 asserted). The summary names ε and the
/// steps taken; on this body ρ is constant, so every step but the last is ε/ρ.
#[test]
fn a_scene_with_epsilon_runs_reversible_steps_to_t_exactly() {
    let times = [0.0, 0.005, 1.0, 3.5, 12.3456, 20.0];
    let scene = format!(
        "{}\n[output]\ntimes = {times:?}\n",
        top("splitting", "epsilon = 0.01")
    );
    let (ok, out, err, rows, _) = run_text("times", &scene);
    assert!(ok, "{err}");
    assert!(out.contains("epsilon      1e-2"), "{out}");
    assert!(out.contains("reversible steps"), "{out}");
    assert_eq!(rows.len(), times.len());
    for (row, t) in rows.iter().zip(times) {
        assert_eq!(row[0], t);
        let (c, s) = ((t / 2.0).cos(), (t / 2.0).sin());
        assert!(
            (row[1] - c).abs() < 3e-4 && (row[2] - s).abs() < 3e-4,
            "t = {t}: {row:?}"
        );
        let casimir = row[1] * row[1] + row[2] * row[2] + row[3] * row[3];
        assert!((casimir - 2.0).abs() < 1e-12, "t = {t}: |Π|² = {casimir}");
    }
    // The summary prints 4 digits.
    let rho = 1.25f64.sqrt();
    let (lo, hi) = step_range(&out);
    assert!(
        (hi - 0.01 / rho).abs() < 1e-3 * hi,
        "h in [{lo}, {hi}], ε/ρ = {}",
        0.01 / rho
    );
    assert!(lo > 0.0 && lo <= hi);
}

/// On the eccentric orbit the steps follow the orbit: shorter at periapsis than at apoapsis
/// (ρ² = λ² + GM/r³, the spin about Π left out and the body's nutation frequency λ = 0.5 rad/s
/// counted: steps ranging √((37.04 + 0.25)/(0.2035 + 0.25)) = 9.1× from apoapsis r = 1.7 to
/// periapsis r = 0.3; with the spin |Ω| = 5 rad/s in ρ they ranged 1.6×), and the run still
/// ends at T = 10π exactly.
#[test]
fn on_the_eccentric_orbit_the_steps_follow_the_motion() {
    let text = std::fs::read_to_string(scenes_dir().join("eccentric-orbit.toml")).unwrap();
    let scene = text
        .replace("step = 0.002", "epsilon = 0.05")
        .replace("stride = 10", "stride = 1000000");
    let (ok, out, err, rows, _) = run_text("orbit", &scene);
    assert!(ok, "{err}");
    let (lo, hi) = step_range(&out);
    assert!(hi / lo > 8.5, "h in [{lo}, {hi}]: {out}");
    assert_eq!(rows.last().unwrap()[0], 31.41592653589793);
}

/// ε is refused, naming `integrator.epsilon` and why, where the method is not symmetric on the
/// system (RK4; Lie–Poisson θ = 0 under a potential; a processed method, whose processor is
/// applied at the ends of equal steps), where the method runs to a tolerance, and beside a step;
/// no output is left.
#[test]
fn epsilon_is_refused_where_the_steps_could_not_be_reversible() {
    let heavy_top = std::fs::read_to_string(scenes_dir().join("heavy-top.toml")).unwrap();
    let lp0 = heavy_top
        .lines()
        .map(|l| {
            if l.starts_with("step") {
                "epsilon = 0.05".to_string()
            } else if l.starts_with("method") {
                "method = \"lie-poisson\"\ntheta = 0.0\ntau = \"cayley\"".to_string()
            } else if l.starts_with("theta") || l.starts_with("tau") {
                String::new()
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let cases = [
        ("rk4", top("rk4", "epsilon = 0.05"), "not symmetric"),
        ("lp0", lp0, "not symmetric"),
        (
            "processed",
            top(
                "splitting",
                "epsilon = 0.05\nprocessing = \"blanes-casas-murua-6-11\"",
            ),
            "processed",
        ),
        ("dop853", top("dop853", "epsilon = 0.05"), "tolerance"),
        (
            "both",
            top("splitting", "epsilon = 0.05\nstep = 0.1"),
            "not both",
        ),
    ];
    for (name, scene, why) in cases {
        let (ok, _, err, _, files) = run_text(name, &scene);
        assert!(!ok, "{name}: accepted");
        assert!(
            err.contains("integrator.epsilon") || err.contains("integrator.step"),
            "{name}: {err}"
        );
        assert!(err.contains(why), "{name}: {err}");
        assert_eq!(files, 1, "{name}: output left behind");
    }
}

/// `trade` runs the configurations the registry declares for reversible steps over ε = h ρ₀
/// (ρ₀ ≥ ω here, so `epsilon_scale` is ρ₀)
/// (their `epsilon` column filled, `h` the mean step), next to the fixed-step runs: on an
/// asymmetric body (𝕀 = diag(1, 2, 3), Π₀ = (1, 0.2, 0.5), ρ₀ = |𝕀⁻¹Π₀|) Strang's error falls
/// as ε² (order within 0.2 of 2 between the ends of the ladder), and its Casimir stays at
/// round-off with variable steps.
#[test]
fn trade_runs_reversible_steps_over_a_ladder_of_epsilon() {
    let dir = temp_dir("trade");
    let scene = top("splitting", "step = 0.1")
        .replace("[1.0, 1.0, 2.0]", "[1.0, 2.0, 3.0]")
        .replace("[1.0, 0.0, 1.0]", "[1.0, 0.2, 0.5]");
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = lie_sim(
        &[
            "trade",
            "s.toml",
            "--steps",
            "0.2,0.1,0.05",
            "--repeats",
            "1",
            "--out",
            "t.csv",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("t.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (method, composition, epsilon, error, casimir) = (
        col("method"),
        col("composition"),
        col("epsilon"),
        col("error"),
        col("max_casimir_error"),
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let reversible: Vec<&Vec<&str>> = rows
        .iter()
        .filter(|r| r[method] == "splitting" && r[composition] == "-" && !r[epsilon].is_empty())
        .collect();
    assert_eq!(reversible.len(), 3, "{text}");
    let rho0 = (1.0f64 + 0.01 + (0.5f64 / 3.0).powi(2)).sqrt();
    for (r, h) in reversible.iter().zip([0.2, 0.1, 0.05]) {
        let eps: f64 = r[epsilon].parse().unwrap();
        assert!((eps - h * rho0).abs() < 1e-12, "{r:?}");
        let c: f64 = r[casimir].parse().unwrap();
        assert!(c < 1e-13, "Casimir {c:e}: {r:?}");
    }
    let errors: Vec<f64> = reversible
        .iter()
        .map(|r| r[error].parse().unwrap())
        .collect();
    let order = (errors[0] / errors[2]).log2() / 2.0;
    assert!(
        (order - 2.0).abs() < 0.2,
        "errors {errors:?}: order {order}"
    );
    for m in ["lie-poisson", "kinetic-kick"] {
        assert!(
            rows.iter()
                .any(|r| r[method] == m && !r[epsilon].is_empty()),
            "no reversible {m} row: {text}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
