//! `[output] times` and `[[events]]`: rows at requested times between steps and located
//! crossings, checked on the symmetric top 𝕀 = diag(1, 1, 2), Π₀ = (1, 0, 1), whose motion is
//! Π = (cos(t/2), sin(t/2), 1) in closed form; malformed tables are one-line errors naming the
//! field, with no output left.

use crate::common::*;

const TOP: &str = r#"
name = "symmetric top"
[system]
kind = "free-rigid-body"
inertia = [1.0, 1.0, 2.0]
[initial]
momentum = [1.0, 0.0, 1.0]
[integrator]
method = "lie-poisson"
tau = "cayley"
theta = 0.5
step = 0.01
duration = 20.0
"#;

/// Rows at exactly the requested times (t = 0 included when asked), between steps, within the
/// method's error of the closed form (its O(h²) phase error is 1.5e-5 t at h = 0.01: ≤ 3e-4
/// over T = 20), and the group columns on SO(3).
#[test]
fn output_times_give_rows_at_exactly_those_times() {
    let times = [0.0, 0.005, 1.0, 3.5, 12.3456, 20.0];
    let scene = format!("{TOP}\n[output]\ntimes = {times:?}\n");
    let (ok, out, err, rows, _) = run_text("times", &scene);
    assert!(ok, "{err}");
    assert!(out.contains("(6 rows)"), "{out}");
    assert_eq!(rows.len(), times.len());
    for (row, t) in rows.iter().zip(times) {
        assert_eq!(row[0], t);
        let (c, s) = ((t / 2.0).cos(), (t / 2.0).sin());
        assert!(
            (row[1] - c).abs() < 3e-4 && (row[2] - s).abs() < 3e-4,
            "t = {t}: {row:?}"
        );
        assert!((row[3] - 1.0).abs() < 1e-12);
        // R's columns orthonormal
        let r = |i: usize, j: usize| row[4 + 3 * i + j];
        for a in 0..3 {
            for b in 0..3 {
                let dot: f64 = (0..3).map(|k| r(k, a) * r(k, b)).sum();
                assert!((dot - f64::from(u8::from(a == b))).abs() < 1e-12);
            }
        }
    }
}

/// Events: Π₁ crosses 0 at π, 3π, 5π (falling, rising, falling); Π₂ falls through −½ at 7π/3,
/// where `stop = true` ends the run with a last row at that time. Located within the method's
/// phase error (3e-5 t here) of the closed form.
#[test]
fn events_are_reported_and_stop_the_run() {
    let pi = std::f64::consts::PI;
    let scene = format!(
        "{TOP}\n[[events]]\nquantity = \"mu1\"\n\n[[events]]\nquantity = \"mu2\"\nvalue = -0.5\ndirection = \"falling\"\nstop = {}\n",
        "false"
    );
    let (ok, out, err, _, _) = run_text("events", &scene);
    assert!(ok, "{err}");
    let times: Vec<f64> = out
        .lines()
        .filter(|l| l.trim_start().starts_with("event"))
        .map(|l| l.rsplit("t = ").next().unwrap().trim().parse().unwrap())
        .collect();
    // Π₁ at π, 3π, 5π; Π₂ = −½ falling at 7π/3 and 7π/3 + 4π = 19π/3 ≈ 19.9
    let mut want = vec![pi, 3.0 * pi, 5.0 * pi, 7.0 * pi / 3.0, 19.0 * pi / 3.0];
    want.sort_by(f64::total_cmp);
    assert_eq!(times.len(), want.len(), "{out}");
    for (t, w) in times.iter().zip(&want) {
        assert!((t - w).abs() < 1e-3, "{t} vs {w}: {out}");
    }
    assert!(
        out.contains("mu1 = 0 (falling)") && out.contains("mu1 = 0 (rising)"),
        "{out}"
    );

    let stop = scene.replace("stop = false", "stop = true");
    let (ok, out, err, rows, _) = run_text("stop", &stop);
    assert!(ok, "{err}");
    assert!(out.contains("stopped"), "{out}");
    let last = rows.last().unwrap();
    assert!(
        (last[0] - 7.0 * pi / 3.0).abs() < 1e-3,
        "last row at {}",
        last[0]
    );
    assert!((last[2] + 0.5).abs() < 1e-10, "Π₂ at the stop: {}", last[2]);
    // only the crossings before the stop are reported
    assert_eq!(
        out.lines()
            .filter(|l| l.trim_start().starts_with("event"))
            .count(),
        2,
        "{out}"
    );
}

#[test]
fn malformed_output_times_and_events_are_errors_naming_the_field() {
    let cases: [(&str, String, &[&str]); 8] = [
        (
            "unsorted",
            format!("{TOP}\n[output]\ntimes = [1.0, 0.5]\n"),
            &["output.times", "increase"],
        ),
        (
            "beyond",
            format!("{TOP}\n[output]\ntimes = [1.0, 25.0]\n"),
            &["output.times", "outside"],
        ),
        (
            "empty",
            format!("{TOP}\n[output]\ntimes = []\n"),
            &["output.times"],
        ),
        (
            "both",
            format!("{TOP}\n[output]\ntimes = [1.0]\nstride = 2\n"),
            &["output.times", "stride"],
        ),
        (
            "direction",
            format!("{TOP}\n[[events]]\nquantity = \"mu1\"\ndirection = \"up\"\n"),
            &["events[0].direction", "up"],
        ),
        (
            "column",
            format!("{TOP}\n[[events]]\nquantity = \"omega\"\n"),
            &["events[0].quantity", "omega", "mu1"],
        ),
        (
            "nan",
            format!("{TOP}\n[[events]]\nquantity = \"mu1\"\nvalue = nan\n"),
            &["events[0].value", "finite"],
        ),
        (
            "key",
            format!("{TOP}\n[[events]]\nquantity = \"mu1\"\nwhen = 3\n"),
            &["events", "when"],
        ),
    ];
    for (name, scene, needles) in cases {
        let (ok, _, err, _, files) = run_text(name, &scene);
        assert!(!ok, "{name}: accepted");
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
        for n in needles {
            assert!(err.contains(n), "{name}: `{n}` missing from {err}");
        }
        assert_eq!(files, 1, "{name}: output left behind");
    }
}
