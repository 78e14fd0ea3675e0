//! Results a user can read: the attitude columns of `lie-sim run` (unit quaternion and rotation
//! vector beside the matrix) and `plot`'s attitude panel; with forces, the energy change, the
//! forces' work and the balance between them; `run --reference` / `--check` reporting the error at
//! T exactly as `trade` measures it.

use crate::common::*;

/// The attitude columns against the matrix they come from, computed here independently: the
/// angle θ = atan2(|vee(R − Rᵀ)|/2, (tr R − 1)/2), the axis vee(R − Rᵀ)/(2 sin θ), and
/// qw = cos(θ/2). The reaction-wheel slew over T = 25 turns the platform by about 1 rad.
#[test]
fn attitude_columns_are_the_quaternion_and_rotation_vector_of_the_matrix() {
    let (csv, _) = run_example("reaction-wheel-slew.toml", "25");
    let r = |i: usize, j: usize| csv.col(&format!("g{i}{j}"));
    let (r11, r22, r33) = (r(1, 1), r(2, 2), r(3, 3));
    let (r32, r23, r13, r31, r21, r12) = (r(3, 2), r(2, 3), r(1, 3), r(3, 1), r(2, 1), r(1, 2));
    let (rv1, rv2, rv3) = (csv.col("rv1"), csv.col("rv2"), csv.col("rv3"));
    let (qw, qx, qy, qz) = (csv.col("qw"), csv.col("qx"), csv.col("qy"), csv.col("qz"));
    let mut turned = 0.0f64;
    for k in 0..csv.rows.len() {
        let s = [r32[k] - r23[k], r13[k] - r31[k], r21[k] - r12[k]];
        let sn = 0.5 * s.iter().map(|x| x * x).sum::<f64>().sqrt();
        let theta = sn.atan2(0.5 * (r11[k] + r22[k] + r33[k] - 1.0));
        let phi = [rv1[k], rv2[k], rv3[k]];
        let norm = phi.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!(
            (norm - theta).abs() < 1e-12,
            "row {k}: |φ| = {norm}, θ = {theta}"
        );
        if sn > 1e-6 {
            for i in 0..3 {
                let want = theta * s[i] / (2.0 * sn);
                assert!((phi[i] - want).abs() < 1e-10, "row {k}: φ = {phi:?}");
            }
        }
        assert!((qw[k] - (theta / 2.0).cos()).abs() < 1e-12, "row {k}");
        let q = [qw[k], qx[k], qy[k], qz[k]];
        assert!((q.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-14);
        for i in 0..3 {
            // q = (cos θ/2, sin θ/2 · φ/θ)
            let want = if theta > 0.0 {
                (theta / 2.0).sin() * phi[i] / theta
            } else {
                0.0
            };
            assert!((q[i + 1] - want).abs() < 1e-12, "row {k}: q = {q:?}");
        }
        turned = turned.max(theta);
    }
    assert!(turned > 0.8, "the platform turned only {turned} rad");
}

/// With forces the energy is not conserved: the summary reports its change as such, with the
/// forces' work and the balance between them. The work column integrates the power column by the
/// trapezoid rule (recomputed here from the rows at stride 1), and E − E₀ − W stays far below the
/// energy change itself: on the slew the wheel motors put ~10⁴ times E₀ into the wheels.
#[test]
fn with_forces_the_energy_change_is_balanced_by_the_work() {
    let dir = temp_dir("work");
    let scene = scenes_dir().join("reaction-wheel-slew.toml");
    let o = lie_sim(
        &[
            "run",
            scene.to_str().unwrap(),
            "--out",
            "t.csv",
            "--duration",
            "25",
            "--stride",
            "1",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let summary = stdout(&o);
    assert!(
        summary.contains("change E(T) − E₀") && summary.contains("not an error"),
        "{summary}"
    );
    assert!(summary.contains("work         W = "), "{summary}");
    assert!(!summary.contains("max |E − E₀|/|E₀|"), "{summary}");
    let csv = Csv::read(&dir.join("t.csv"));
    let (t, p, w, e) = (
        csv.col("t"),
        csv.col("power"),
        csv.col("work"),
        csv.col("energy"),
    );
    let mut trapezoid = 0.0;
    for k in 1..t.len() {
        trapezoid += 0.5 * (t[k] - t[k - 1]) * (p[k] + p[k - 1]);
        assert!(
            (w[k] - trapezoid).abs() <= 1e-12 * trapezoid.abs().max(1.0),
            "row {k}"
        );
    }
    let change = e[e.len() - 1] - e[0];
    assert!(change > 1e3 * e[0].abs(), "E₀ = {}, change {change}", e[0]);
    let scale = e.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let balance = e
        .iter()
        .zip(&w)
        .map(|(x, w)| (x - e[0] - w).abs() / scale)
        .fold(0.0f64, f64::max);
    assert!(balance < 1e-4, "energy balance error {balance:e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `plot` draws an attitude panel (the angle and the quaternion, by their legend labels) and, for
/// a run with forces, the energy balance instead of the energy "error"; the same CSV without the
/// attitude and work columns gets neither.
#[test]
fn plot_draws_the_attitude_panel_from_the_attitude_columns() {
    let dir = temp_dir("attitude-plot");
    let scene = scenes_dir().join("reaction-wheel-slew.toml");
    let o = lie_sim(
        &[
            "run",
            scene.to_str().unwrap(),
            "--out",
            "t.csv",
            "--duration",
            "5",
            "--plot",
            "p.svg",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(dir.join("p.svg")).unwrap();
    // plotters writes each text on a line of its own.
    let has_text = |svg: &str, t: &str| svg.lines().any(|l| l.trim() == t);
    assert!(svg.contains("attitude: rotation angle") && svg.contains("energy balance error"));
    for label in ["θ (rad)", "qw", "qz"] {
        assert!(has_text(&svg, label), "legend `{label}` missing");
    }
    // The same trajectory without the attitude and work columns.
    let text = std::fs::read_to_string(dir.join("t.csv")).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let keep: Vec<usize> = (0..header.len())
        .filter(|&j| {
            !["qw", "qx", "qy", "qz", "rv1", "rv2", "rv3", "power", "work"].contains(&header[j])
        })
        .collect();
    let stripped: String = text
        .lines()
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            keep.iter().map(|&j| f[j]).collect::<Vec<_>>().join(",") + "\n"
        })
        .collect();
    std::fs::write(dir.join("s.csv"), stripped).unwrap();
    let o = lie_sim(&["plot", "s.csv", "--out", "s.svg"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let plain = std::fs::read_to_string(dir.join("s.svg")).unwrap();
    assert!(!plain.contains("attitude") && !has_text(&plain, "qw"));
    assert!(plain.contains("relative energy error"));
    assert!(
        svg.matches("<polyline").count() > plain.matches("<polyline").count(),
        "the attitude panel adds curves"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The number after `error at T` in a run's summary.
fn error_at_t(summary: &str) -> f64 {
    let line = summary
        .lines()
        .find(|l| l.trim_start().starts_with("error at T"))
        .unwrap_or_else(|| panic!("no error line in {summary}"));
    line.split_whitespace()
        .nth(3)
        .and_then(|x| x.parse().ok())
        .unwrap_or_else(|| panic!("no number in {line}"))
}

/// `run --reference FILE` reports the error at T that `trade` reports for the same run against
/// the same reference (the trade's own, written by `--write-reference`), and `run --check` the
/// same against the reference it computes (the exact flow on the free body, as the trade's). The
/// scene's method is the default's, Lie–Poisson Cayley θ = 0, at h = 0.1 over T = 2.
#[test]
fn run_reference_reports_the_trade_error_of_the_same_run() {
    let dir = temp_dir("run-reference");
    let o = lie_sim(
        &[
            "trade",
            "--horizon",
            "2",
            "--steps",
            "0.1",
            "--repeats",
            "1",
            "--out",
            "w.csv",
            "--write-reference",
            "ref.csv",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("w.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let j = header.iter().position(|h| *h == "error").unwrap();
    let row: Vec<&str> = lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .find(|r| r[..4].join(",") == "lie-poisson,cayley,0,-")
        .expect("the trade ran the default scene's method");
    let traded: f64 = row[j].parse().unwrap();
    assert!(traded > 1e-6, "a resolved error: {traded:e}");
    for extra in [&["--reference", "ref.csv"][..], &["--check"][..]] {
        let mut args = vec!["run", "--duration", "2", "--step", "0.1", "--out", "r.csv"];
        args.extend_from_slice(extra);
        let o = lie_sim(&args, &dir);
        assert!(o.status.success(), "{extra:?}: {}", stderr(&o));
        let e = error_at_t(&stdout(&o));
        assert!(
            (e / traded - 1.0).abs() < 1e-6,
            "{extra:?}: run {e:e}, trade {traded:e}"
        );
    }
    // A run to another T is refused by the reference (its last row is at T = 2).
    let o = lie_sim(
        &[
            "run",
            "--duration",
            "1",
            "--out",
            "r.csv",
            "--reference",
            "ref.csv",
        ],
        &dir,
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("not at the horizon"), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
}
