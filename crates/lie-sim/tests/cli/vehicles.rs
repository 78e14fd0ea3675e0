//! End-to-end tests of the vehicle scenes (`gyrostat`, `underwater-vehicle`, `quadrotor`,
//! `pendulum-3d`, `coupled-bodies`) and their `[forces]`: each example scene runs and writes its
//! documented CSV with what it keeps intact; `lie-sim trade` runs on each, with the conserved part
//! of the momentum map where the system keeps one; malformed tables are one-line errors naming the
//! field, with no output left.

use crate::common::*;
use std::path::Path;

/// The column of the trade table's `name` (its first columns are text).
fn text_col(path: &Path, name: &str) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let j = header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').nth(j).unwrap_or("").to_string())
        .collect()
}

/// The trajectory columns: μ, g (side × side), energy, the Casimir, `power, work` with forces,
/// and the attitudes of `bodies` bodies (quaternion and rotation vector, `_k` for several).
fn header(n_mu: usize, side: usize, casimir: bool, forced: bool, bodies: usize) -> Vec<String> {
    let mut h = vec!["t".to_string()];
    h.extend((1..=n_mu).map(|i| format!("mu{i}")));
    for i in 1..=side {
        for j in 1..=side {
            h.push(if side >= 10 {
                format!("g{i}_{j}")
            } else {
                format!("g{i}{j}")
            });
        }
    }
    h.push("energy".into());
    if casimir {
        h.push("casimir".into());
    }
    if forced {
        h.extend(["power".into(), "work".into()]);
    }
    for k in 1..=bodies {
        for n in ["qw", "qx", "qy", "qz", "rv1", "rv2", "rv3"] {
            h.push(if bodies == 1 {
                n.to_string()
            } else {
                format!("{n}_{k}")
            });
        }
    }
    h
}

/// max over rows of ‖RᵀR − I‖ for the 3×3 block at (r0, r0) of g (side `side`).
fn orthogonality(csv: &Csv, side: usize, r0: usize) -> f64 {
    let j0 = 1 + csv.header.iter().filter(|h| h.starts_with("mu")).count();
    let mut worst = 0.0f64;
    for row in &csv.rows {
        let g = |i: usize, j: usize| row[j0 + (r0 + i) * side + r0 + j];
        for a in 0..3 {
            for b in 0..3 {
                let dot: f64 = (0..3).map(|k| g(k, a) * g(k, b)).sum();
                worst = worst.max((dot - if a == b { 1.0 } else { 0.0 }).abs());
            }
        }
    }
    worst
}

/// The reaction-wheel slew: (Π, p) and the 7×7 block-diagonal (R, φ) matrix; |Π|² (the casimir
/// column) is kept to round-off while the wheel spins up, and the platform turns (R leaves I).
#[test]
fn reaction_wheel_scene_keeps_the_casimir_while_the_wheel_spins_up() {
    let (csv, summary) = run_example("reaction-wheel-slew.toml", "25");
    assert_eq!(csv.header, header(6, 7, true, true, 1));
    assert!(summary.contains("wheel torques"), "{summary}");
    let c = csv.col("casimir");
    let drift = c.iter().map(|x| (x / c[0] - 1.0).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-13, "|Π|² drifted by {drift:e}");
    // Wheel 3's momentum p₃ = ∫u: +0.3 for 20 s, the ramp to −0.3 over 0.05 s (no net impulse),
    // −0.3 for 4.95 s: 4.515 at t = 25. The knots fall on step boundaries, where the midpoint
    // impulses integrate the linear pieces exactly: to round-off.
    let p3 = csv.col("mu6");
    let last = p3[p3.len() - 1];
    assert!((last - 4.515).abs() < 1e-12, "p₃ = {last}");
    assert!(orthogonality(&csv, 7, 0) < 1e-13);
    let g11 = csv.col("g11");
    // Turned by ≈ 0.9 rad about e₃ at t = 25 (R₁₁ = 0.64).
    assert!(
        g11[g11.len() - 1] < 0.8,
        "the platform did not turn: R₁₁ = {}",
        g11[g11.len() - 1]
    );
}

/// The underwater vehicle: 6 momenta and the 4×4 (R, x); finless, the Munk moment pitches its
/// nose down past 30° (|g31| > 0.5; measured 0.9 at t ≈ 6) while the thrust drives it forwards
/// (x grows); R stays a rotation.
#[test]
fn underwater_vehicle_scene_porpoises_under_the_munk_moment() {
    let (csv, summary) = run_example("underwater-vehicle.toml", "10");
    assert_eq!(csv.header, header(6, 4, false, true, 1));
    assert!(summary.contains("quadratic drag"), "{summary}");
    let nose = csv.col("g31");
    let dip = nose.iter().fold(0.0f64, |m, x| m.max(-x));
    assert!(dip > 0.5, "the nose dipped only to {dip}");
    let x = csv.col("g14");
    assert!(x[x.len() - 1] > 2.0, "x(10) = {}", x[x.len() - 1]);
    assert!(orthogonality(&csv, 4, 0) < 1e-13);
}

/// The quadrotor: hovering for the first second (within the 5e-3 N by which the scene's thrust
/// exceeds m g: 0.6 mm), then climbing; the roll doublet tilts it.
#[test]
fn quadrotor_scene_hovers_then_climbs() {
    let (csv, summary) = run_example("quadrotor.toml", "5");
    assert_eq!(csv.header, header(6, 4, false, true, 1));
    assert!(
        summary.contains("thrust") && summary.contains("order 4"),
        "{summary}"
    );
    let (t, z) = (csv.col("t"), csv.col("g34"));
    let at = |s: f64| z[t.iter().position(|&x| (x - s).abs() < 1e-9).unwrap()];
    assert!((at(1.0) - 2.0).abs() < 1e-3, "z(1) = {}", at(1.0));
    assert!(at(5.0) > 2.3, "z(5) = {}", at(5.0));
    let roll = csv.col("g32");
    assert!(roll.iter().any(|r| r.abs() > 0.01), "no roll");
    assert!(orthogonality(&csv, 4, 0) < 1e-13);
}

/// `pendulum-3d` is the heavy top: its energy is kept to O(h²) (h = 0.005) and R to round-off.
#[test]
fn pendulum_3d_scene_is_the_heavy_top() {
    let (csv, summary) = run_example("pendulum-3d.toml", "5");
    assert_eq!(csv.header, header(3, 3, false, false, 1));
    assert!(summary.contains("heavy-top"), "{summary}");
    let e = csv.col("energy");
    let drift = e.iter().map(|x| (x / e[0] - 1.0).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-4, "energy drift {drift:e}");
    assert!(orthogonality(&csv, 3, 0) < 1e-13);
}

/// Three bodies on springs: 18 momenta and the 12×12 matrix of three 4×4 blocks; the energy is
/// kept to O(h²) and each attitude block stays a rotation.
#[test]
fn coupled_bodies_scene_keeps_the_energy() {
    let (csv, _) = run_example("coupled-bodies.toml", "2");
    assert_eq!(csv.header, header(18, 12, false, false, 3));
    let e = csv.col("energy");
    let drift = e.iter().map(|x| (x / e[0] - 1.0).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-4, "energy drift {drift:e}");
    for k in 0..3 {
        assert!(orthogonality(&csv, 12, 4 * k) < 1e-13, "body {k}");
    }
}

/// `lie-sim trade` runs on every vehicle scene (two steps, a short horizon): every applicable
/// method has a row, and the conserved part of the momentum map is reported — kept to round-off
/// by Lie–Poisson where the system keeps one (the gyrostat's R Π under its wheel torques; the
/// coupled bodies' total momentum; the pendulum's vertical momentum), and left empty under thrust
/// and drag.
#[test]
fn trade_runs_on_every_vehicle_scene_with_its_momentum_map() {
    for (file, steps, kept) in [
        ("reaction-wheel-slew.toml", "0.05,0.025", true),
        ("underwater-vehicle.toml", "0.1,0.05", false),
        ("quadrotor.toml", "0.02,0.01", false),
        ("pendulum-3d.toml", "0.02,0.01", true),
        ("coupled-bodies.toml", "0.05,0.025", true),
    ] {
        let dir = temp_dir(&format!("trade-{file}"));
        let out = dir.join("w.csv");
        let o = lie_sim(
            &[
                "trade",
                scenes_dir().join(file).to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
                "--horizon",
                "0.5",
                "--steps",
                steps,
            ],
            &dir,
        );
        assert!(o.status.success(), "{file}: {}", stderr(&o));
        let methods = text_col(&out, "method");
        let maps = text_col(&out, "max_momentum_map_error");
        let failures = text_col(&out, "failure");
        assert!(
            methods.iter().any(|m| m == "lie-poisson"),
            "{file}: {methods:?}"
        );
        for ((m, j), f) in methods.iter().zip(&maps).zip(&failures) {
            if !f.is_empty() {
                continue;
            }
            if kept && m == "lie-poisson" {
                let j: f64 = j.parse().unwrap_or_else(|_| panic!("{file}: {m}: {j:?}"));
                assert!(j < 1e-12, "{file}: {m}: momentum map {j:e}");
            } else if !kept {
                assert!(j.is_empty(), "{file}: {m}: {j}");
            }
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// [`assert_rejected`] for each (name, scene text, needles).
fn assert_all_rejected(prefix: &str, cases: Vec<(&str, String, Vec<&str>)>) {
    for (name, text, needles) in cases {
        assert_rejected(&format!("{prefix}-{name}"), &text, &needles);
    }
}

fn scene(file: &str) -> String {
    std::fs::read_to_string(scenes_dir().join(file)).unwrap()
}

/// `scene` with the line starting `key =` replaced by `key = value` (the first such line).
fn with(scene: &str, key: &str, value: &str) -> String {
    let mut done = false;
    scene
        .lines()
        .map(|l| {
            if !done && l.trim_start().starts_with(&format!("{key} =")) {
                done = true;
                format!("{key} = {value}")
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// `scene` without its `[forces]` table, with `forces` as the new one.
fn with_forces(scene: &str, forces: &str) -> String {
    let base = match scene.find("\n[forces]") {
        Some(i) => {
            let rest = &scene[i + 1..];
            let end = rest[1..].find("\n[").map_or(rest.len(), |j| j + 1);
            format!("{}{}", &scene[..i + 1], &rest[end..])
        }
        None => scene.to_string(),
    };
    format!("{base}\n[forces]\n{forces}\n")
}

#[test]
fn malformed_gyrostat_tables_are_errors_naming_the_field() {
    let s = scene("reaction-wheel-slew.toml");
    let cases: Vec<(&str, String, Vec<&str>)> = vec![
        (
            "zero-axis",
            with(
                &s,
                "wheel_axes",
                "[[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]]",
            ),
            vec!["system.wheel_axes[1]", "zero vector"],
        ),
        (
            "inertia-count",
            with(&s, "wheel_inertia", "[0.05, 0.05]"),
            vec!["system.wheel_inertia", "one inertia per wheel (3)"],
        ),
        (
            "heavy-wheels",
            with(&s, "wheel_inertia", "[0.05, 0.05, 95.0]"),
            vec!["system.wheel_inertia", "not positive definite"],
        ),
        (
            "five-wheels",
            with(
                &s,
                "wheel_axes",
                "[[1,0,0],[0,1,0],[0,0,1],[1,1,0],[0,1,1]]",
            ),
            vec!["system.wheel_axes", "5 wheels"],
        ),
        (
            "momentum",
            with(&s, "momentum", "[0.2, -0.1, 0.3]"),
            vec!["initial.momentum", "6 components"],
        ),
        (
            "angles",
            with(&s, "wheel_angles", "[0.0]"),
            vec!["initial.wheel_angles", "one angle per wheel"],
        ),
        (
            "wheel-torque-count",
            with_forces(&s, "wheel_torque = [0.1, 0.0]"),
            vec!["forces.wheel_torque", "one component per wheel (3)"],
        ),
        (
            "unsorted",
            with_forces(
                &s,
                "wheel_torque = { times = [0.0, 2.0, 1.0], values = [[0,0,1],[0,0,0],[0,0,1]] }",
            ),
            vec!["forces.wheel_torque", "increase"],
        ),
        (
            "thrust",
            with_forces(&s, "thrust = 1.0"),
            vec![
                "forces.thrust",
                "is not a force of gyrostat",
                "wheel_torque",
            ],
        ),
        (
            "foreign-key",
            with(&s, "wheel_inertia", "[0.05, 0.05, 0.05]\nbuoyancy = 3.0"),
            vec!["system.buoyancy", "not a parameter of gyrostat"],
        ),
    ];
    assert_all_rejected("gyro", cases);
}

#[test]
fn malformed_underwater_vehicle_tables_are_errors_naming_the_field() {
    let s = scene("underwater-vehicle.toml");
    let cases: Vec<(&str, String, Vec<&str>)> = vec![
        (
            "added-mass-shape",
            with(&s, "added_mass", "[1.0, 2.0]\n#").replace("              [", "#              ["),
            vec!["system.added_mass", "6 diagonal entries"],
        ),
        (
            "added-mass-negative",
            with(&s, "added_mass", "[0.1, 1.0, 1.0, -40.0, 1.0, 1.0]\n#")
                .replace("              [", "#              ["),
            vec!["system.added_mass", "≥ 0"],
        ),
        (
            "buoyancy",
            with(&s, "buoyancy", "-1.0"),
            vec!["system.buoyancy", "≥ 0"],
        ),
        (
            "gravity",
            with(&s, "gravity", "[0.0, 1.0, 0.0]"),
            vec!["system.gravity", "−e₃"],
        ),
        (
            "splitting",
            s.replace("method = \"lie-poisson\"", "method = \"splitting\"")
                .replace("tau = \"cayley\"\n", "")
                .replace("theta = 0.5\n", ""),
            vec!["integrator.method", "couples rotation and translation"],
        ),
        (
            "drag-negative",
            with_forces(&s, "quadratic_drag = [0, 0, -1, 0, 0, 0]"),
            vec!["forces.quadratic_drag", "d[2]"],
        ),
        (
            "drag-count",
            with_forces(&s, "quadratic_drag = [1.0, 2.0, 3.0]"),
            vec!["forces.quadratic_drag", "6 coefficients"],
        ),
        (
            "damping-shape",
            with_forces(&s, "damping = [1.0, 2.0, 3.0]"),
            vec!["forces.damping", "6×6"],
        ),
        (
            "force-nan",
            with_forces(&s, "force = [9.0, nan, 0.0]"),
            vec!["forces.force", "finite"],
        ),
        (
            "wheel-torque",
            with_forces(&s, "wheel_torque = [1.0]"),
            vec![
                "forces.wheel_torque",
                "is not a force of underwater-vehicle",
            ],
        ),
    ];
    assert_all_rejected("auv", cases);
}

#[test]
fn malformed_quadrotor_and_coupled_tables_are_errors_naming_the_field() {
    let q = scene("quadrotor.toml");
    let c = scene("coupled-bodies.toml");
    let cases: Vec<(&str, String, Vec<&str>)> = vec![
        (
            "thrust-vector",
            with_forces(&q, "thrust = [1.0, 2.0]"),
            vec!["forces.thrust", "one number"],
        ),
        (
            "thrust-times",
            with_forces(&q, "thrust = { times = [0.0, 1.0], values = [42.0] }"),
            vec!["forces.thrust", "as many values as times"],
        ),
        (
            "empty-forces",
            with_forces(&q, ""),
            vec!["forces", "empty", "thrust"],
        ),
        (
            "gravity",
            with(&q, "gravity", "-9.81"),
            vec!["system.gravity", "g ≥ 0"],
        ),
        (
            "same-body",
            c.replace("between = [1, 2]", "between = [1, 1]"),
            vec!["system.springs[1].between", "two different bodies"],
        ),
        (
            "no-such-body",
            c.replace("between = [1, 2]", "between = [1, 7]"),
            vec!["system.springs[1].between", "[1, 7]"],
        ),
        (
            "stiffness",
            c.replace("stiffness = 5.0", "stiffness = -5.0"),
            vec!["system.springs[1].stiffness", "≥ 0"],
        ),
        (
            "body-mass",
            c.replace("{ mass = 2.0,", "{ mass = 0.0,"),
            vec!["system.bodies[1].mass", "positive"],
        ),
        (
            "states",
            c.replace(
                "    { momentum = [0.02, 0.06, -0.05, 0.1, -0.3, 0.2], position = [1.5, 1.3, -0.2] },\n",
                "",
            ),
            vec!["initial.bodies", "one state per body (3)"],
        ),
        (
            "state-momentum",
            c.replace("[-0.1, 0.04, 0.0, -0.4, 0.5, 0.0]", "[-0.1, 0.04, 0.0]"),
            vec!["initial.bodies[1].momentum", "6 components"],
        ),
        (
            "state-attitude",
            c.replace("rotation_vector = [0.1, 0.5, -0.2]", "quaternion = [1.0, 1.0, 0.0, 0.0]"),
            vec!["initial.bodies[1].attitude.quaternion", "unit norm"],
        ),
        (
            "momentum-key",
            c.replace("[initial]\n", "[initial]\nmomentum = [0.0, 0.0, 0.0]\n"),
            vec!["initial.momentum", "not a parameter of coupled-bodies"],
        ),
        (
            "forces",
            format!("{c}\n[forces]\ntorque = [0.0, 0.0, 1.0]\n"),
            vec!["forces", "quadrotor", "not coupled-bodies"],
        ),
    ];
    assert_all_rejected("q-c", cases);
}
