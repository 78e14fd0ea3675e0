//! `lie-sim many-bodies` (`lie_sim::many_bodies`): the statistics rows do not depend on the thread
//! count, agree between the batched and scalar paths (RK4: the momenta's columns bit for bit), they
//! are the statistics of the
//! per-member rows of the equivalent `sweep`, the order parameters start at those of g₀, and a
//! malformed table, a system it does not carry and a shard are refused, naming what is wrong.

use crate::common::{lie_sim, scenes_dir, stderr, stdout, temp_dir};
use std::path::Path;

/// `lie-sim many-bodies SCENE --out OUT EXTRA…` in `dir`; panics on failure; returns stdout.
fn many(dir: &Path, scene: &str, out: &str, extra: &[&str]) -> String {
    let mut args = vec!["many-bodies", scene, "--out", out];
    args.extend_from_slice(extra);
    let o = lie_sim(&args, dir);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    stdout(&o)
}

/// The statistics CSV: its header and its rows (after the naming line), as text.
fn table(dir: &Path, file: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(dir.join(file)).unwrap();
    let mut lines = text.lines();
    assert!(lines.next().unwrap().starts_with("# lie-sim many-bodies: "));
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (header, rows)
}

/// Column `name` of a row.
fn cell(header: &[String], row: &[String], name: &str) -> f64 {
    let j = header.iter().position(|h| h == name).unwrap();
    row[j]
        .parse()
        .unwrap_or_else(|_| panic!("{name} = `{}`", row[j]))
}

fn dipoles() -> String {
    std::fs::read_to_string(scenes_dir().join("many-dipoles.toml")).unwrap()
}

/// The example's dipoles, 37 of them (four vectors of eight and a remainder) over 0.7 time units
/// with a row every 5 steps, on one thread and on two: the same file, byte for byte; the same
/// with RK4 on the scalar path. The run names the batched path. Both end at T = 0.7 exactly,
/// where 70 steps of h = 0.01 end at 0.7000000000000001.
#[test]
fn many_body_rows_do_not_depend_on_threads() {
    let dir = temp_dir("many-threads");
    let scene = dipoles()
        .replace("count = 100000", "count = 37")
        .replace("duration = 20.0", "duration = 0.7")
        .replace("stride = 20 ", "stride = 5 ");
    std::fs::write(dir.join("d.toml"), &scene).unwrap();
    std::fs::write(
        dir.join("r.toml"),
        scene.replace("method = \"splitting\"", "method = \"rk4\""),
    )
    .unwrap();
    let out = many(&dir, "d.toml", "one.csv", &["--threads", "1"]);
    assert!(out.contains("path         batched ("), "{out}");
    many(&dir, "d.toml", "two.csv", &["--threads", "2"]);
    let one = std::fs::read(dir.join("one.csv")).unwrap();
    assert_eq!(std::fs::read(dir.join("two.csv")).unwrap(), one);
    let (header, rows) = table(&dir, "one.csv");
    assert_eq!(rows.len(), 15, "rows at 0, 5, …, 70 steps");
    assert_eq!(cell(&header, &rows[14], "time"), 0.7);
    let out = many(&dir, "r.toml", "s1.csv", &["--threads", "1", "--scalar"]);
    assert!(out.contains("path         scalar (--scalar)"), "{out}");
    many(&dir, "r.toml", "s2.csv", &["--threads", "2", "--scalar"]);
    let (header, rows) = table(&dir, "s1.csv");
    assert_eq!(cell(&header, &rows[14], "time"), 0.7);
    assert_eq!(
        std::fs::read(dir.join("s1.csv")).unwrap(),
        std::fs::read(dir.join("s2.csv")).unwrap()
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// RK4 batched is the scalar RK4 bit for bit on (q, Π): the columns read from the momenta
/// (`running`, `failed`, the kinetic energies per axis, the temperature) are the same text on both
/// paths. R is published from q by the batch and by the scalar method with different roundings
/// (an ulp or so per entry, at t = 0 already), so the columns that read R — the energy in a field,
/// hence its errors, and the order parameters — agree to round-off: the energy errors within
/// 1e-15 (a few ulps of E ≈ 2), ⟨cos θ⟩ and ⟨P₂⟩ within 4e-16.
#[test]
fn batched_and_scalar_rk4_write_the_same_rows() {
    let dir = temp_dir("many-rk4");
    let scene = dipoles()
        .replace("count = 100000", "count = 21")
        .replace("duration = 20.0", "duration = 0.5")
        .replace("stride = 20 ", "stride = 10 ")
        .replace("method = \"splitting\"", "method = \"rk4\"");
    std::fs::write(dir.join("r.toml"), scene).unwrap();
    many(&dir, "r.toml", "b.csv", &[]);
    many(&dir, "r.toml", "s.csv", &["--scalar"]);
    let (hb, b) = table(&dir, "b.csv");
    let (hs, s) = table(&dir, "s.csv");
    assert_eq!(hb, hs);
    assert_eq!(b.len(), 6);
    assert_eq!(b.len(), s.len());
    for (rb, rs) in b.iter().zip(&s) {
        for name in [
            "time",
            "steps",
            "running",
            "failed",
            "kinetic_1",
            "kinetic_2",
            "kinetic_3",
            "temperature",
        ] {
            let j = hb.iter().position(|h| h == name).unwrap();
            assert_eq!(rb[j], rs[j], "{name}");
        }
        for (name, tolerance) in [
            ("energy_error_mean", 1e-15),
            ("energy_error_max", 1e-15),
            ("cos_mean", 4e-16),
            ("p2_mean", 4e-16),
        ] {
            let (x, y) = (cell(&hb, rb, name), cell(&hs, rs, name));
            assert!((x - y).abs() <= tolerance, "{name}: {x:e} against {y:e}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A free rigid body with both a `[sweep]` that monitors the energy at T only and a
/// `[many_bodies]` of the same N, seed and kind with rows at 0 and T: the row at T is the
/// statistics of the sweep's per-member rows — the mean and maximum of `max_energy_error` and
/// `max_casimir_error` (sums in index order: the same bits), the mean kinetic energy per axis
/// Πᵢ²/(2Iᵢ) of the final momenta and the temperature ⅔ Σ ⟨Kᵢ⟩ (the same bits), and the
/// reported median and 99th percentile of the energy error are upper bounds within 10^(1/20)
/// of the rows' own.
#[test]
fn statistics_equal_those_of_the_sweep_rows() {
    let dir = temp_dir("many-vs-sweep");
    let n = 100;
    let inertia = [1.0, 2.0, 3.0];
    let scene = format!(
        "[system]\nkind = \"free-rigid-body\"\ninertia = {inertia:?}\n\
         [initial]\nmomentum = [0.3, 1.0, 0.2]\n\
         [integrator]\nmethod = \"splitting\"\nstep = 0.05\nduration = 2.0\nreconstruct = true\n\
         [sweep]\ncount = {n}\nseed = 5\nkind = \"momenta-on-energy-level\"\nmonitor_every = 40\n\
         [many_bodies]\ncount = {n}\nseed = 5\nkind = \"momenta-on-energy-level\"\nstride = 40\n"
    );
    std::fs::write(dir.join("f.toml"), scene).unwrap();
    let o = lie_sim(&["sweep", "f.toml", "--out", "sweep.csv"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    many(&dir, "f.toml", "many.csv", &[]);
    let text = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    let mut lines = text.lines().skip(1);
    let sh: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| sh.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| {
            l.split(',')
                .map(|x| x.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    assert_eq!(rows.len(), n);
    let (de, dc) = (col("max_energy_error"), col("max_casimir_error"));
    let mu = [col("mu_0"), col("mu_1"), col("mu_2")];
    let mean =
        |f: &dyn Fn(&[f64]) -> f64| rows.iter().map(|r| f(r.as_slice())).sum::<f64>() / n as f64;
    let max = |j: usize| rows.iter().map(|r| r[j]).fold(0.0f64, f64::max);

    let (h, m) = table(&dir, "many.csv");
    assert_eq!(m.len(), 2, "rows at 0 and T");
    let at_t = &m[1];
    let got = |name: &str| cell(&h, at_t, name);
    assert_eq!(got("time"), 2.0);
    assert_eq!(got("running"), n as f64);
    assert_eq!(got("energy_error_mean"), mean(&|r| r[de]));
    assert_eq!(got("energy_error_max"), max(de));
    assert_eq!(got("casimir_error_mean"), mean(&|r| r[dc]));
    assert_eq!(got("casimir_error_max"), max(dc));
    let mut k = [0.0; 3];
    for (i, k) in k.iter_mut().enumerate() {
        *k = mean(&|r| 0.5 * (r[mu[i]] * (r[mu[i]] * (1.0 / inertia[i]))));
        assert_eq!(got(&format!("kinetic_{}", i + 1)), *k, "axis {}", i + 1);
    }
    assert_eq!(got("temperature"), 2.0 / 3.0 * (k[0] + k[1] + k[2]));
    let mut sorted: Vec<f64> = rows.iter().map(|r| r[de]).collect();
    sorted.sort_by(f64::total_cmp);
    for (q, name) in [(0.5, "energy_error_p50"), (0.99, "energy_error_p99")] {
        let exact = sorted[(q * n as f64).ceil() as usize - 1];
        let bound = got(name);
        assert!(
            exact <= bound && bound <= exact * 10f64.powf(0.05) * (1.0 + 1e-12),
            "{name}: {bound:e} against the rows' {exact:e}"
        );
    }
    // At t = 0 every error is 0 and the kinetic energies are those of the drawn momenta.
    assert_eq!(cell(&h, &m[0], "energy_error_max"), 0.0);
    assert_eq!(cell(&h, &m[0], "casimir_error_max"), 0.0);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every dipole starts at the tilt 0.35 rad from the field (R₀ = rotation by π − 0.35 about
/// e₁, χ = e₃): the row at t = 0 has ⟨cos θ⟩ = cos 0.35 and ⟨P₂⟩ = (3 cos² 0.35 − 1)/2 to
/// round-off, no energy error, and every body running; in the field the bodies have no Casimir
/// (empty cells).
#[test]
fn order_parameters_start_at_those_of_the_initial_attitude() {
    let dir = temp_dir("many-order");
    let scene = dipoles()
        .replace("count = 100000", "count = 50")
        .replace("duration = 20.0", "duration = 1.0");
    std::fs::write(dir.join("d.toml"), scene).unwrap();
    many(&dir, "d.toml", "d.csv", &[]);
    let (h, rows) = table(&dir, "d.csv");
    assert_eq!(rows.len(), 6, "rows every 20 steps over 100");
    let c = 0.35f64.cos();
    let r0 = &rows[0];
    assert!((cell(&h, r0, "cos_mean") - c).abs() < 1e-15);
    assert!((cell(&h, r0, "p2_mean") - (1.5 * c * c - 0.5)).abs() < 1e-15);
    assert_eq!(cell(&h, r0, "energy_error_max"), 0.0);
    assert_eq!(cell(&h, r0, "running"), 50.0);
    let j = h.iter().position(|x| x == "casimir_error_mean").unwrap();
    assert!(rows.iter().all(|r| r[j].is_empty()));
    // The bodies turn away from their common start: the order decays.
    assert!(cell(&h, &rows[5], "cos_mean") < c - 0.01);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `lie-sim many-bodies` on `scene` (text) with `extra` arguments fails with one line on stderr
/// holding every needle, and writes nothing.
fn refused(name: &str, scene: &str, extra: &[&str], needles: &[&str]) {
    let dir = temp_dir(name);
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let mut args = vec!["many-bodies", "s.toml", "--out", "m.csv"];
    args.extend_from_slice(extra);
    let o = lie_sim(&args, &dir);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{name}: {err}");
    assert_eq!(err.lines().count(), 1, "{name}: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: `{n}` missing from: {err}");
    }
    assert!(!dir.join("m.csv").exists(), "{name}: wrote its output");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Malformed tables are refused with the field named: N = 0, a stride of 0, a stride giving more
/// rows than a run keeps (with the least stride that fits), an unknown key, an unknown kind; and
/// a scene without the table, a body a batch does not carry (the rigid body on SE(3)), variable
/// steps and a shard.
#[test]
fn malformed_many_body_runs_are_refused_naming_the_field() {
    let d = dipoles();
    refused(
        "count",
        &d.replace("count = 100000", "count = 0"),
        &[],
        &["many_bodies.count", "at least 1, got 0"],
    );
    refused(
        "stride",
        &d.replace("stride = 20 ", "stride = 0 "),
        &[],
        &["many_bodies.stride", "at least 1, got 0"],
    );
    refused(
        "rows",
        &d.replace("duration = 20.0", "duration = 200.0")
            .replace("stride = 20 ", "stride = 1 "),
        &[],
        &["many_bodies.stride", "20001 rows", "at least 2"],
    );
    refused(
        "unknown",
        &d.replace("seed = 1\n", "seed = 1\nbodies = 3\n"),
        &[],
        &["many_bodies", "unknown field `bodies`"],
    );
    refused(
        "kind",
        &d.replace("kind = \"momenta-on-sphere\"", "kind = \"thermal\""),
        &[],
        &["many_bodies.kind", "thermal"],
    );
    let no_table = &d[..d.find("[many_bodies]").unwrap()];
    refused("no-table", no_table, &[], &["no [many_bodies] table"]);
    refused(
        "shard",
        &d,
        &["--shard", "0/2"],
        &["--shard 0/2", "not sharded"],
    );
    let se3 = std::fs::read_to_string(scenes_dir().join("rigid-body-se3.toml")).unwrap();
    let se3 = format!(
        "{}\n[many_bodies]\ncount = 3\nkind = \"momenta-on-sphere\"\n",
        se3.split("[output]").next().unwrap()
    );
    refused(
        "se3",
        &se3,
        &[],
        &["rigid bodies in principal axes", "rigid-body-se3"],
    );
    let reversible = d.replace("step = 0.01\n", "epsilon = 0.05\n");
    refused("variable", &reversible, &[], &["variable steps"]);
}

/// The statistics' histogram: a value lands in the bin whose edges hold it (the upper edge
/// included), so the quantile of one value is the upper edge of its bin: at or above the value,
/// within 10^(1/20) of it; zero and values below the lowest edge go to the lowest edge, values
/// above the highest edge (and NaN) to +∞.
#[test]
fn histogram_quantiles_are_the_upper_edges_of_their_bins() {
    use lie_sim::body_stats::LogHistogram as H;
    let one = |x: f64| {
        let mut h = H::default();
        h.add(x);
        h.quantile(1.0).unwrap()
    };
    for k in 1..=H::BINS {
        let (lo, hi) = (H::edge(k - 1), H::edge(k));
        for x in [hi, lo.next_up(), (lo * hi).sqrt()] {
            assert_eq!(one(x), hi, "{x:e} between {lo:e} and {hi:e}");
        }
    }
    assert_eq!(one(0.0), H::edge(0));
    assert_eq!(one(1e-300), H::edge(0));
    assert_eq!(one(1e3), f64::INFINITY);
    assert_eq!(one(f64::NAN), f64::INFINITY);
    let mut h = H::default();
    for x in [3e-16, 1e-15, 2e-15, 5e-12] {
        h.add(x);
    }
    let q = h.quantile(0.5).unwrap();
    assert!(
        1e-15 <= q && q <= 1e-15 * 10f64.powf(0.05) * (1.0 + 1e-12),
        "{q:e}"
    );
    assert_eq!(H::default().quantile(0.5), None);
}
