//! The trade's reference (`lie-sim trade`, `choose`): its reported error bounds its true error on
//! scenes with closed forms (the exact flow on the free symmetric top; Gragg–Bulirsch–Stoer on the
//! free symmetric body in SE(3), on a rotation under a scheduled torque and damping, whose knots
//! the reference's steps end on, and on a spherical satellite on an orbit of eccentricity 0.7); a
//! reference that cannot reach its tolerance within the budget is one line, exit 0, and no error
//! below its estimate is printed or written as a number;
//! `--reference FILE.csv` reproduces the computed reference's errors, and a wrong file is one line
//! with no output.

use crate::common::*;
use std::path::Path;

/// The trade's error measure: `max(‖μ − μ_r‖∞ / ‖μ_r‖∞, ‖g − g_r‖∞ / max(1, ‖g_r‖∞))`.
fn trade_error(mu: &[f64], g: &[f64], mu_r: &[f64], g_r: &[f64]) -> f64 {
    let amax = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let diff = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
    };
    (diff(mu, mu_r) / amax(mu_r)).max(diff(g, g_r) / amax(g_r).max(1.0))
}

/// One case of `data/closed_forms.txt` (see `data/closed_forms.py`).
struct ClosedForm {
    kind: String,
    name: String,
    duration: f64,
    params: Vec<f64>,
    r0: Vec<f64>,
    mu: Vec<f64>,
    g: Vec<f64>,
}

fn closed_forms() -> Vec<ClosedForm> {
    let text = include_str!("../data/closed_forms.txt");
    text.lines()
        .map(|line| {
            let parts: Vec<&str> = line.split(" | ").collect();
            let head: Vec<&str> = parts[0].split(' ').collect();
            let nums = |s: &str| -> Vec<f64> { s.split(' ').map(|x| x.parse().unwrap()).collect() };
            ClosedForm {
                kind: head[0].into(),
                name: head[1].into(),
                duration: head[2].parse().unwrap(),
                params: nums(parts[1]),
                r0: nums(parts[2]),
                mu: nums(parts[3]),
                g: nums(parts[4]),
            }
        })
        .collect()
}

/// The scene of a closed-form case (see `data/closed_forms.py`).
fn scene_of(c: &ClosedForm) -> String {
    let r = &c.r0;
    let attitude = format!(
        "attitude = {{ matrix = [[{:?}, {:?}, {:?}], [{:?}, {:?}, {:?}], [{:?}, {:?}, {:?}]] }}",
        r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]
    );
    let p = &c.params;
    let integrator = format!(
        "[integrator]\nmethod = \"lie-poisson\"\ntau = \"cayley\"\ntheta = 0.5\nstep = 0.1\n\
         duration = {:?}\n",
        c.duration
    );
    match c.kind.as_str() {
        "top" => format!(
            "[system]\nkind = \"free-rigid-body\"\ninertia = [{:?}, {:?}, {:?}]\ngeneralized_inertia = true\n[initial]\n\
             momentum = [{:?}, {:?}, {:?}]\n{attitude}\n{integrator}",
            p[0], p[0], p[1], p[2], p[3], p[4]
        ),
        "se3" => format!(
            "[system]\nkind = \"rigid-body-se3\"\ninertia = [{:?}, {:?}, {:?}]\ngeneralized_inertia = true\nmass = {:?}\n\
             gravitational_parameter = 0.0\n[initial]\n\
             momentum = [{:?}, {:?}, {:?}, {:?}, {:?}, {:?}]\n{attitude}\n\
             position = [{:?}, {:?}, {:?}]\n{integrator}",
            p[0], p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], p[9], p[10], p[11]
        ),
        "torque" => {
            let (i3, d3, pi30) = (p[0], p[1], p[2]);
            let k = (p.len() - 3) / 2;
            let times: Vec<String> = p[3..3 + k].iter().map(|x| format!("{x:?}")).collect();
            let values: Vec<String> = p[3 + k..]
                .iter()
                .map(|x| format!("[0.0, 0.0, {x:?}]"))
                .collect();
            format!(
                "[system]\nkind = \"free-rigid-body\"\ninertia = [1.0, 2.0, {i3:?}]\n\
                 [initial]\nmomentum = [0.0, 0.0, {pi30:?}]\n{attitude}\n{integrator}\
                 [forces]\ntorque = {{ times = [{}], values = [{}] }}\n\
                 damping = [0.2, 0.3, {d3:?}]\n",
                times.join(", "),
                values.join(", ")
            )
        }
        other => panic!("unknown case kind {other}"),
    }
}

/// The header and the one row of a CSV.
fn last_row(path: &Path) -> (Vec<String>, Vec<f64>) {
    let text = std::fs::read_to_string(path).unwrap();
    let header = text
        .lines()
        .next()
        .unwrap()
        .split(',')
        .map(String::from)
        .collect();
    let row = text
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    (header, row)
}

/// A trade CSV as (header, rows of cells).
fn table(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    (
        header,
        lines
            .map(|l| l.split(',').map(String::from).collect())
            .collect(),
    )
}

fn col(header: &[String], name: &str) -> usize {
    header.iter().position(|h| h == name).unwrap()
}

/// Runs a trade of `scene` (`--steps 0.5`, one repeat) writing the reference to `r.csv`; returns
/// the reference's state (μ, g row-major) and its estimated error (the CSV's `reference_error`).
fn traded_reference(dir: &Path, scene: &str, extra: &[&str]) -> (Vec<f64>, Vec<f64>, f64) {
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let mut args = vec![
        "trade",
        "s.toml",
        "--out",
        "w.csv",
        "--repeats",
        "1",
        "--steps",
        "0.5",
        "--write-reference",
        "r.csv",
    ];
    args.extend_from_slice(extra);
    let o = lie_sim(&args, dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, row) = last_row(&dir.join("r.csv"));
    let n = header.iter().filter(|h| h.starts_with("mu")).count();
    let m2 = header.iter().filter(|h| h.starts_with('g')).count();
    let (th, trows) = table(&dir.join("w.csv"));
    let floor: f64 = trows[0][col(&th, "reference_error")].parse().unwrap();
    (
        row[1..1 + n].to_vec(),
        row[1 + n..1 + n + m2].to_vec(),
        floor,
    )
}

/// The reference's reported (estimated) error is at least its true error, measured against the
/// closed forms of `data/closed_forms.txt` (mpmath, 30 digits, from exactly the scene's initial
/// state): the exact flow on five free symmetric tops (SO(3)); Gragg–Bulirsch–Stoer on five free
/// symmetric bodies in SE(3) (Π, R as the top's, P = Rᵀp, x = x₀ + tp/m) and on two rotations
/// about e₃ under a piecewise-linear torque (kinks the reference's steps end on) and damping −DΩ;
/// T from 1 to 30.
#[test]
fn the_reported_error_bounds_the_true_one_on_closed_forms() {
    let dir = temp_dir("closed-forms");
    let mut worst: f64 = 0.0;
    for c in closed_forms() {
        let (mu, g, reported) = traded_reference(&dir, &scene_of(&c), &[]);
        let truth = trade_error(&mu, &g, &c.mu, &c.g);
        println!(
            "{:>8} (T = {:>4}): true error {truth:.2e}, reported {reported:.2e} ({:.2})",
            c.name,
            c.duration,
            truth / reported
        );
        worst = worst.max(truth / reported);
        assert!(
            truth <= reported,
            "{}: true {truth:e} > reported {reported:e}",
            c.name
        );
    }
    println!("largest true / reported: {worst:.2}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The heavy top over T = 50 (ωT = 1000) with a reference budget of 1 ms: the two runs the
/// reference always takes (on its mesh and with every step split in two) already exceed it and
/// differ by more than the tolerance, so the refinement stops there. One line says so
/// (naming the budget), the trade goes on (exit 0) with the floor at the agreement reached, and
/// no error below that floor appears as a number in the table, the CSV or the plot.
#[test]
fn a_reference_short_of_its_tolerance_is_one_line_and_nothing_below_it_is_measured() {
    let dir = temp_dir("budget");
    let scene = scenes_dir().join("heavy-top.toml");
    let o = lie_sim(
        &[
            "trade",
            scene.to_str().unwrap(),
            "--out",
            "w.csv",
            "--repeats",
            "1",
            "--steps",
            "0.05,0.025,0.0125",
            "--horizon",
            "50",
            "--reference-budget",
            "0.001s",
        ],
        &dir,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let short: Vec<&str> = out.lines().filter(|l| l.contains("not met")).collect();
    assert_eq!(short.len(), 1, "{out}");
    assert!(
        short[0].contains("--reference-budget") && short[0].contains("unresolved"),
        "{}",
        short[0]
    );
    let (h, rows) = table(&dir.join("w.csv"));
    let (e, status, floor) = (
        col(&h, "error"),
        col(&h, "error_status"),
        col(&h, "reference_error"),
    );
    let floor: f64 = rows[0][floor].parse().unwrap();
    println!("{}\nfloor {floor:.3e}", short[0]);
    assert!(floor > 1e-13, "the tolerance was met after all: {floor:e}");
    let mut unresolved = 0;
    for r in &rows {
        match r[status].as_str() {
            "measured" => assert!(r[e].parse::<f64>().unwrap() >= floor, "{r:?}"),
            "unresolved" => {
                assert!(r[e].is_empty(), "{r:?}");
                unresolved += 1;
            }
            s => assert_eq!(s, "failed", "{r:?}"),
        }
    }
    assert!(
        unresolved > 0,
        "no run reached the floor: the test shows nothing"
    );
    // The table: the error column (the 8th field of a row that did not fail) is `unresolved` or
    // a number at the floor or above (printed to 4 digits).
    let mut seen = 0;
    for line in out.lines() {
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.len() != 14 || f[4].parse::<f64>().is_err() {
            continue;
        }
        seen += 1;
        if f[7] != "unresolved" {
            let v: f64 = f[7].parse().unwrap();
            assert!(v >= floor * (1.0 - 1e-3), "{line}");
        }
    }
    assert_eq!(seen, rows.iter().filter(|r| r[status] != "failed").count());
    let svg = std::fs::read_to_string(dir.join("w.svg")).unwrap();
    assert!(
        svg.contains(&format!("▽: {unresolved} runs below it, unresolved")),
        "the plot does not mark the unresolved runs"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A tolerance below what double precision allows (1e-17) on the heavy top over T = 2: the
/// refinement stops where it stalls at the rounding level (long before the default budget), says
/// so in one line, and the trade goes on with that floor.
#[test]
fn a_tolerance_below_rounding_stops_where_refinement_stalls() {
    let dir = temp_dir("stall");
    let scene = scenes_dir().join("heavy-top.toml");
    let start = std::time::Instant::now();
    let o = lie_sim(
        &[
            "trade",
            scene.to_str().unwrap(),
            "--out",
            "w.csv",
            "--repeats",
            "1",
            "--steps",
            "0.05",
            "--horizon",
            "2",
            "--reference-tolerance",
            "1e-17",
        ],
        &dir,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(start.elapsed().as_secs_f64() < 10.0);
    let out = stdout(&o);
    let short: Vec<&str> = out.lines().filter(|l| l.contains("not met")).collect();
    assert_eq!(short.len(), 1, "{out}");
    assert!(
        short[0].contains("stalled at the rounding level"),
        "{}",
        short[0]
    );
    println!("{}", short[0]);
    let (h, rows) = table(&dir.join("w.csv"));
    let floor: f64 = rows[0][col(&h, "reference_error")].parse().unwrap();
    assert!(floor > 1e-17 && floor < 1e-13, "{floor:e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--reference FILE.csv`: the reference `--write-reference` wrote gives every run the same error
/// (bit for bit: the CSV round-trips the doubles), with the tolerance as its estimated error; a
/// trajectory of `lie-sim run` ending at T is accepted as it is.
#[test]
fn a_user_reference_reproduces_the_computed_one() {
    let dir = temp_dir("user");
    let scene = scenes_dir().join("heavy-top.toml");
    let scene = scene.to_str().unwrap();
    let trade = |extra: &[&str], out: &str| {
        let mut args = vec![
            "trade",
            scene,
            "--out",
            out,
            "--repeats",
            "1",
            "--steps",
            "0.02,0.01",
            "--horizon",
            "1",
        ];
        args.extend_from_slice(extra);
        let o = lie_sim(&args, &dir);
        assert!(o.status.success(), "{}", stderr(&o));
        (stdout(&o), table(&dir.join(out)))
    };
    let (_, (h, computed)) = trade(&["--write-reference", "r.csv"], "a.csv");
    let (out, (_, user)) = trade(&["--reference", "r.csv"], "b.csv");
    assert!(out.contains("r.csv (its last row, t = 1)"), "{out}");
    let (e, floor, status) = (
        col(&h, "error"),
        col(&h, "reference_error"),
        col(&h, "error_status"),
    );
    assert_eq!(computed.len(), user.len());
    let mut compared = 0;
    for (a, b) in computed.iter().zip(&user) {
        assert_eq!(b[floor], "1e-13");
        if a[status] == "measured" && b[status] == "measured" {
            assert_eq!(a[e], b[e], "{a:?}");
            compared += 1;
        }
    }
    assert!(compared > 20, "{compared}");
    // A run's trajectory as the reference: the order-8 composition at h = 1e-3 to T = 1.
    let o = lie_sim(
        &[
            "run",
            scene,
            "--out",
            "run.csv",
            "--duration",
            "1",
            "--step",
            "0.001",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let (out, _) = trade(&["--reference", "run.csv"], "c.csv");
    assert!(out.contains("run.csv (its last row, t = 1"), "{out}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A reference file of the wrong shape, at the wrong T, of the wrong dimension, with a NaN, or
/// that is also an output: one line naming the file and what is wrong, exit 1, no output file.
#[test]
fn a_wrong_reference_file_is_one_line_and_no_output() {
    let dir = temp_dir("wrong");
    let top = scenes_dir().join("heavy-top.toml");
    let se3 = scenes_dir().join("rigid-body-se3.toml");
    let run = |scene: &Path, out: &str, duration: &str| {
        let args = [
            "run",
            scene.to_str().unwrap(),
            "--out",
            out,
            "--duration",
            duration,
        ];
        let o = lie_sim(&args, &dir);
        assert!(o.status.success(), "{}", stderr(&o));
    };
    run(&top, "top.csv", "1");
    run(&top, "short.csv", "0.5");
    run(&se3, "se3.csv", "1");
    let text = std::fs::read_to_string(dir.join("top.csv")).unwrap();
    let header = text.lines().next().unwrap();
    let last = text.lines().last().unwrap();
    let cells: Vec<&str> = last.split(',').collect();
    let nan = [&cells[..2], &["NaN"], &cells[3..]].concat().join(",");
    std::fs::write(dir.join("nan.csv"), format!("{header}\n{nan}\n")).unwrap();
    std::fs::write(dir.join("shape.csv"), "time,x\n1,2\n").unwrap();
    let no_g: Vec<&str> = header.split(',').filter(|h| !h.starts_with('g')).collect();
    let keep: Vec<usize> = header
        .split(',')
        .enumerate()
        .filter(|(_, h)| !h.starts_with('g'))
        .map(|(i, _)| i)
        .collect();
    let row: Vec<&str> = keep.iter().map(|&i| cells[i]).collect();
    std::fs::write(
        dir.join("nog.csv"),
        format!("{}\n{}\n", no_g.join(","), row.join(",")),
    )
    .unwrap();
    let before = |d: &Path| {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    };
    let files = before(&dir);
    for (reference, out, needles) in [
        ("shape.csv", "w.csv", vec!["shape.csv", "no `t` column"]),
        ("short.csv", "w.csv", vec!["short.csv", "t = 0.5", "T = 1"]),
        (
            "se3.csv",
            "w.csv",
            vec!["se3.csv", "6 momentum columns", "has 3"],
        ),
        (
            "nog.csv",
            "w.csv",
            vec!["nog.csv", "0 group columns", "3×3"],
        ),
        ("nan.csv", "w.csv", vec!["nan.csv", "mu2", "not finite"]),
        ("missing.csv", "w.csv", vec!["missing.csv"]),
        ("top.csv", "top.csv", vec!["top.csv", "input"]),
    ] {
        let o = lie_sim(
            &[
                "trade",
                top.to_str().unwrap(),
                "--out",
                out,
                "--steps",
                "0.1",
                "--horizon",
                "1",
                "--reference",
                reference,
            ],
            &dir,
        );
        assert_eq!(o.status.code(), Some(1), "{reference}");
        let err = stderr(&o);
        assert_eq!(err.lines().count(), 1, "{reference}: {err}");
        for n in needles {
            assert!(err.contains(n), "{reference}: {err}");
        }
        assert_eq!(before(&dir), files, "{reference}: an output was written");
    }
    let kept = std::fs::read_to_string(dir.join("top.csv")).unwrap();
    assert_eq!(kept, text, "the reference given as --out was overwritten");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The state at t of the eccentric-orbit scene's body made a sphere (𝕀 = 4e-3·I): MacCullagh's
/// term vanishes, so the centre of mass is on the Kepler orbit (GM = m = a = 1, e = 0.7, released
/// at apoapsis x = (1.7, 0, 0) with velocity along y) and the body spins at the constant body
/// rate Ω = 𝕀⁻¹Π₀ = (0, 0, 5.5): Π = Π₀, R = R₀ exp(tΩ̂) with R₀ the rotation by 0.3 about y,
/// P = Rᵀ v. Returns (μ, g row-major).
fn kepler_sphere(t: f64) -> (Vec<f64>, Vec<f64>) {
    let e: f64 = 0.7;
    // Mean anomaly from apoapsis (E = M = π there), n = 1; Kepler's equation by Newton.
    let m = std::f64::consts::PI + t.rem_euclid(2.0 * std::f64::consts::PI);
    let mut ea = m;
    for _ in 0..50 {
        ea -= (ea - e * ea.sin() - m) / (1.0 - e * ea.cos());
    }
    let b = (1.0 - e * e).sqrt();
    // Perifocal frame: periapsis along −x, the motion at apoapsis along +y (q̂ = −ŷ).
    let (px, py) = (ea.cos() - e, b * ea.sin());
    let rate = 1.0 / (1.0 - e * ea.cos());
    let (vx, vy) = (-ea.sin() * rate, b * ea.cos() * rate);
    let x = [-px, -py, 0.0];
    let v = [-vx, -vy, 0.0];
    let (c0, s0) = (0.3f64.cos(), 0.3f64.sin());
    let r0 = [[c0, 0.0, s0], [0.0, 1.0, 0.0], [-s0, 0.0, c0]];
    let (c, s) = ((5.5 * t).cos(), (5.5 * t).sin());
    let rz = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] = (0..3).map(|k| r0[i][k] * rz[k][j]).sum();
        }
    }
    let p: Vec<f64> = (0..3)
        .map(|j| (0..3).map(|i| r[i][j] * v[i]).sum())
        .collect();
    let mu = vec![0.0, 0.0, 2.2e-2, p[0], p[1], p[2]];
    let mut g = Vec::new();
    for i in 0..3 {
        g.extend_from_slice(&r[i]);
        g.push(x[i]);
    }
    g.extend_from_slice(&[0.0, 0.0, 0.0, 1.0]);
    (mu, g)
}

/// On the satellite on an orbit of eccentricity 0.7 (five orbits, `eccentric-orbit.toml`) the
/// reference — Gragg–Bulirsch–Stoer on the mesh of an error-controlled run — reaches an estimated
/// error of 1e-12 within its default budget (a uniform step stalled near 1e-4 on such an orbit).
/// On the same scene with a spherical body, whose centre of mass then follows the Kepler orbit
/// and whose spin is steady (`kepler_sphere`, Kepler's equation solved by Newton), its true error
/// is within the estimate and within 1e-12.
#[test]
fn the_reference_converges_on_the_eccentric_orbit() {
    let dir = temp_dir("eccentric");
    let text = std::fs::read_to_string(scenes_dir().join("eccentric-orbit.toml")).unwrap();
    let start = std::time::Instant::now();
    let (_, _, reported) = traded_reference(&dir, &text, &[]);
    let took = start.elapsed().as_secs_f64();
    println!("eccentric orbit: estimated error {reported:.2e} ({took:.2} s with the trade)");
    assert!(reported <= 1e-12, "{reported:e}");
    assert!(took < 30.0, "{took}");
    let sphere = text.replace(
        "inertia = [4.0e-3, 4.0e-3, 4.4e-3]",
        "inertia = [4.0e-3, 4.0e-3, 4.0e-3]",
    );
    assert_ne!(sphere, text);
    let (mu, g, reported) = traded_reference(&dir, &sphere, &[]);
    let (mu_k, g_k) = kepler_sphere(10.0 * std::f64::consts::PI);
    let truth = trade_error(&mu, &g, &mu_k, &g_k);
    println!("sphere on the Kepler orbit: true error {truth:.2e}, estimated {reported:.2e}");
    assert!(truth <= reported, "true {truth:e} > estimated {reported:e}");
    // The target, on the true error (the estimate, the spread of its runs with the run at twice
    // the step, is a few times above it: 1.2e-12 against a true 2.5e-13 when measured).
    assert!(truth <= 1e-12, "{truth:e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The eccentric-orbit scene's run has the orbit its comment states: apsides 0.3 and 1.7
/// (e = 0.7) and periapsis passages 2π apart, to what the body's MacCullagh term perturbs
/// (it turns the periapsis a little at each passage: passages measured 6.268 to 6.282 apart,
/// r_p 0.2992) and the output's sampling (every 0.002) resolves.
#[test]
fn the_eccentric_orbit_has_its_stated_eccentricity_and_period() {
    let dir = temp_dir("eccentric-run");
    let scene = scenes_dir().join("eccentric-orbit.toml");
    let o = lie_sim(
        &[
            "run",
            scene.to_str().unwrap(),
            "--out",
            "o.csv",
            "--stride",
            "1",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("o.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |n: &str| header.iter().position(|h| *h == n).unwrap();
    let (t, x, y, z) = (at("t"), at("g14"), at("g24"), at("g34"));
    let rows: Vec<(f64, f64)> = lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|c| c.parse().unwrap()).collect();
            (v[t], (v[x] * v[x] + v[y] * v[y] + v[z] * v[z]).sqrt())
        })
        .collect();
    let r_min = rows.iter().map(|r| r.1).fold(f64::INFINITY, f64::min);
    let r_max = rows.iter().map(|r| r.1).fold(0.0, f64::max);
    let e = (r_max - r_min) / (r_max + r_min);
    let periapses: Vec<f64> = rows
        .windows(3)
        .filter(|w| w[1].1 < w[0].1 && w[1].1 < w[2].1)
        .map(|w| w[1].0)
        .collect();
    println!("r in [{r_min:.5}, {r_max:.5}], e = {e:.5}, periapses at {periapses:?}");
    assert!((e - 0.7).abs() < 2e-3, "e = {e}");
    assert!((r_min - 0.3).abs() < 2e-3 && (r_max - 1.7).abs() < 2e-3);
    assert_eq!(periapses.len(), 5, "{periapses:?}");
    for w in periapses.windows(2) {
        let period = w[1] - w[0];
        assert!(
            (period - 2.0 * std::f64::consts::PI).abs() < 3e-2,
            "{period}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The other scenes with fast and slow phases: the free body tumbling near its separatrix flips
/// four times over T = 200 (Π₂ changes sign, seen in the run's output) and its reference (the
/// exact flow) reaches 1e-12; the quadrotor's thrust pulses have a reference that lands on the
/// schedules' 14 knots and reaches 1e-12.
#[test]
fn the_fast_and_slow_phase_scenes_have_converged_references() {
    let dir = temp_dir("phases");
    let tumble = scenes_dir().join("separatrix-tumble.toml");
    let o = lie_sim(&["run", tumble.to_str().unwrap(), "--out", "t.csv"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("t.csv")).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let j = header.iter().position(|h| *h == "mu2").unwrap();
    let pi2: Vec<f64> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(j).unwrap().parse().unwrap())
        .collect();
    let flips = pi2.windows(2).filter(|w| w[0] * w[1] < 0.0).count();
    assert_eq!(flips, 4, "Π₂ changed sign {flips} times");
    for file in ["separatrix-tumble.toml", "quadrotor-pulses.toml"] {
        let text = std::fs::read_to_string(scenes_dir().join(file)).unwrap();
        let (_, _, reported) = traded_reference(&dir, &text, &[]);
        println!("{file}: estimated error {reported:.2e}");
        assert!(reported <= 1e-12, "{file}: {reported:e}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
