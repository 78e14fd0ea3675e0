//! `lie-sim sweep` on the batched path (`crate::batched`): the rows do not depend on the thread
//! count or the shard, agree with the scalar path to round-off (bit for bit for RK4 and RKMK4, to a
//! few ulps for the exact flow), and a sweep
//! that cannot be batched says why and runs scalar.

use crate::common::{lie_sim, scenes_dir, stderr, stdout, temp_dir};
use std::path::Path;

/// `lie-sim sweep SCENE --out OUT --count N --duration T EXTRA…` in `dir`; panics on failure.
fn sweep(
    dir: &Path,
    scene: &str,
    out: &str,
    count: usize,
    duration: &str,
    extra: &[&str],
) -> String {
    let count = count.to_string();
    let mut args = vec![
        "sweep",
        scene,
        "--out",
        out,
        "--count",
        &count,
        "--duration",
        duration,
    ];
    args.extend_from_slice(extra);
    let o = lie_sim(&args, dir);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    stdout(&o)
}

/// The CSV's rows (after the naming line and the header), split into fields.
fn rows(dir: &Path, file: &str) -> Vec<Vec<String>> {
    std::fs::read_to_string(dir.join(file))
        .unwrap()
        .lines()
        .skip(2)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

fn rotors() -> String {
    scenes_dir()
        .join("sweep-rotors.toml")
        .to_str()
        .unwrap()
        .to_string()
}

/// 37 rotors (four full vectors of eight and a remainder): on one thread and on two, and as
/// three shards merged, byte for byte the same file; the summary names the batched path.
#[test]
fn batched_rows_do_not_depend_on_threads_or_shards() {
    let dir = temp_dir("batched-sweep");
    let scene = rotors();
    let out = sweep(&dir, &scene, "one.csv", 37, "0.5", &["--threads", "1"]);
    assert!(out.contains("path         batched ("), "{out}");
    sweep(&dir, &scene, "two.csv", 37, "0.5", &["--threads", "2"]);
    for i in 0..3 {
        sweep(
            &dir,
            &scene,
            &format!("p{i}.csv"),
            37,
            "0.5",
            &["--shard", &format!("{i}/3")],
        );
    }
    let o = lie_sim(
        &["merge", "p1.csv", "p2.csv", "p0.csv", "--out", "merged.csv"],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let one = std::fs::read(dir.join("one.csv")).unwrap();
    assert_eq!(std::fs::read(dir.join("two.csv")).unwrap(), one);
    assert_eq!(std::fs::read(dir.join("merged.csv")).unwrap(), one);
    assert_eq!(rows(&dir, "one.csv").len(), 37);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The batched Strang rows against the scalar path's (`--scalar`), 40 steps: the same statuses,
/// steps and times, the momenta within 1e-13 |Π| and the initial energies within an ulp or two,
/// the maxima of the energy and Casimir errors alike (the energy error to a few ulps of E₀, the
/// rounding of the energies it is the difference of; the Casimir error, round-off itself, below
/// 1e-14); the files' fingerprints differ, so `merge`
/// refuses to mix the paths.
#[test]
fn batched_and_scalar_strang_rows_agree_to_round_off() {
    let dir = temp_dir("batched-vs-scalar");
    let scene = rotors();
    sweep(&dir, &scene, "b.csv", 29, "2.0", &["--shard", "0/2"]);
    let out = sweep(
        &dir,
        &scene,
        "s.csv",
        29,
        "2.0",
        &["--shard", "1/2", "--scalar"],
    );
    assert!(out.contains("path         scalar (--scalar)"), "{out}");
    let o = lie_sim(&["merge", "b.csv", "s.csv", "--out", "m.csv"], &dir);
    assert!(!o.status.success(), "batched and scalar shards were merged");
    assert!(stderr(&o).contains("different sweeps"), "{}", stderr(&o));

    sweep(&dir, &scene, "batched.csv", 29, "2.0", &[]);
    sweep(&dir, &scene, "scalar.csv", 29, "2.0", &["--scalar"]);
    let (b, s) = (rows(&dir, "batched.csv"), rows(&dir, "scalar.csv"));
    assert_eq!(b.len(), 29);
    let num = |x: &str| x.parse::<f64>().unwrap();
    for (rb, rs) in b.iter().zip(&s) {
        assert_eq!(rb[..4], rs[..4], "index, status, steps, time");
        let norm = (4..7).map(|c| num(&rs[c]).powi(2)).sum::<f64>().sqrt();
        for c in 4..7 {
            assert!(
                (num(&rb[c]) - num(&rs[c])).abs() <= 1e-13 * norm,
                "Π: {rb:?} {rs:?}"
            );
        }
        let (e_b, e_s) = (num(&rb[7]), num(&rs[7]));
        assert!(
            (e_b - e_s).abs() <= 4.0 * f64::EPSILON * e_s,
            "E₀: {rb:?} {rs:?}"
        );
        let (de_b, de_s) = (num(&rb[8]), num(&rs[8]));
        // Each maximum is a difference of two energies, so it carries their rounding.
        assert!(
            (de_b - de_s).abs() <= 16.0 * f64::EPSILON * e_s,
            "max |E − E₀|: {rb:?} {rs:?}"
        );
        assert!(
            num(&rb[9]) < 1e-14 && num(&rs[9]) < 1e-14,
            "Casimir: {rb:?} {rs:?}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A heavy top's sweep with RK4: batched RK4 is the scalar step bit for bit, so the rows of the
/// batched and the scalar path are the same bytes.
#[test]
fn batched_rk4_rows_are_the_scalar_rows_bit_for_bit() {
    let dir = temp_dir("batched-rk4");
    let top = std::fs::read_to_string(scenes_dir().join("heavy-top.toml")).unwrap();
    let scene = top
        .replace("method = \"lie-poisson\"", "method = \"rk4\"")
        .replace("tau = \"cayley\"\n", "")
        .replace("theta = 0.5\n", "")
        + "\n[sweep]\ncount = 19\nseed = 3\nkind = \"momenta-on-sphere\"\nmonitor_every = 7\n";
    std::fs::write(dir.join("top.toml"), scene).unwrap();
    let out = sweep(&dir, "top.toml", "b.csv", 19, "0.3", &[]);
    assert!(out.contains("path         batched ("), "{out}");
    sweep(&dir, "top.toml", "s.csv", 19, "0.3", &["--scalar"]);
    assert_eq!(rows(&dir, "b.csv"), rows(&dir, "s.csv"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// RKMK4 on heavy tops and on free rotors: batched RKMK4 is the scalar step bit for bit at these
/// steps (rotations far below π/2), so the rows of the batched and the scalar path are the same
/// bytes.
#[test]
fn batched_rkmk4_rows_are_the_scalar_rows_bit_for_bit() {
    let dir = temp_dir("batched-rkmk4");
    let top = std::fs::read_to_string(scenes_dir().join("heavy-top.toml")).unwrap();
    let scene = top
        .replace("method = \"lie-poisson\"", "method = \"rkmk4\"")
        .replace("tau = \"cayley\"\n", "")
        .replace("theta = 0.5\n", "")
        + "\n[sweep]\ncount = 19\nseed = 3\nkind = \"momenta-on-sphere\"\nmonitor_every = 7\n";
    std::fs::write(dir.join("top.toml"), scene).unwrap();
    let out = sweep(&dir, "top.toml", "b.csv", 19, "0.3", &[]);
    assert!(out.contains("path         batched ("), "{out}");
    sweep(&dir, "top.toml", "s.csv", 19, "0.3", &["--scalar"]);
    assert_eq!(rows(&dir, "b.csv"), rows(&dir, "s.csv"));
    let rotors = std::fs::read_to_string(rotors()).unwrap();
    let rkmk = rotors.replace("method = \"splitting\"", "method = \"rkmk4\"");
    std::fs::write(dir.join("rotors.toml"), rkmk).unwrap();
    let out = sweep(&dir, "rotors.toml", "rb.csv", 37, "0.5", &[]);
    assert!(out.contains("path         batched ("), "{out}");
    sweep(&dir, "rotors.toml", "rs.csv", 37, "0.5", &["--scalar"]);
    assert_eq!(rows(&dir, "rb.csv"), rows(&dir, "rs.csv"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The exact flow on 37 free rotors (duration 2: 40 steps of 0.05): the batched path (`ExactFlow`,
/// the lanes' elliptic functions) and the scalar one (`ExactFreeBody`) write the same statuses,
/// steps and times, momenta within 16 ulps of |Π| (the lanes are the scalar flow to a few ulps:
/// `batch`'s `exact_lanes_follow_the_scalar_exact_flow`), initial energies within 4 ulps, and
/// energy and Casimir errors at round-off on both paths (the flow keeps both exactly); the rows
/// do not depend on the thread count.
#[test]
fn batched_and_scalar_exact_rows_agree_to_a_few_ulps() {
    let dir = temp_dir("batched-exact");
    let rotors = std::fs::read_to_string(rotors()).unwrap();
    let exact = rotors.replace("method = \"splitting\"", "method = \"exact\"");
    std::fs::write(dir.join("exact.toml"), exact).unwrap();
    let out = sweep(&dir, "exact.toml", "b.csv", 37, "2.0", &["--threads", "1"]);
    assert!(out.contains("path         batched ("), "{out}");
    sweep(&dir, "exact.toml", "b2.csv", 37, "2.0", &["--threads", "2"]);
    assert_eq!(
        std::fs::read(dir.join("b.csv")).unwrap(),
        std::fs::read(dir.join("b2.csv")).unwrap()
    );
    sweep(&dir, "exact.toml", "s.csv", 37, "2.0", &["--scalar"]);
    let (b, s) = (rows(&dir, "b.csv"), rows(&dir, "s.csv"));
    assert_eq!(b.len(), 37);
    let num = |x: &str| x.parse::<f64>().unwrap();
    let mut worst = 0.0f64;
    for (rb, rs) in b.iter().zip(&s) {
        assert_eq!(rb[..4], rs[..4], "index, status, steps, time");
        let norm = (4..7).map(|c| num(&rs[c]).powi(2)).sum::<f64>().sqrt();
        for c in 4..7 {
            worst = worst.max((num(&rb[c]) - num(&rs[c])).abs() / (f64::EPSILON * norm));
        }
        let (e_b, e_s) = (num(&rb[7]), num(&rs[7]));
        assert!(
            (e_b - e_s).abs() <= 4.0 * f64::EPSILON * e_s,
            "E₀: {rb:?} {rs:?}"
        );
        for r in [rb, rs] {
            assert!(
                num(&r[8]) <= 8.0 * f64::EPSILON * e_s,
                "max |E − E₀|: {r:?}"
            );
            assert!(num(&r[9]) < 1e-14, "Casimir: {r:?}");
        }
    }
    println!("batched exact rows: Π within {worst:.2} ulps of |Π| of the scalar rows");
    assert!(worst <= 16.0, "{worst} ulps");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Sweeps the batch does not cover run scalar and say why: a method without a batched version,
/// and a rotor with an external torque.
#[test]
fn a_sweep_that_cannot_be_batched_says_why_and_runs_scalar() {
    let dir = temp_dir("not-batched");
    let lp = scenes_dir().join("sweep.toml");
    let out = sweep(&dir, lp.to_str().unwrap(), "lp.csv", 5, "0.2", &[]);
    assert!(
        out.contains("path         scalar (lie-poisson has no batched version)"),
        "{out}"
    );
    let rotors = std::fs::read_to_string(rotors()).unwrap();
    let forced = rotors.replace(
        "[integrator]",
        "[forces]\ntorque = [0.0, 0.0, 0.1]\n\n[integrator]",
    );
    std::fs::write(dir.join("forced.toml"), forced).unwrap();
    let out = sweep(&dir, "forced.toml", "f.csv", 5, "0.2", &[]);
    assert!(
        out.contains("path         scalar (a batch carries rigid bodies"),
        "{out}"
    );
    assert_eq!(rows(&dir, "f.csv").len(), 5);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Across the chunks the rows stream in (65 536 members each): 70 001 rotors over one step on
/// one thread and on two, and as two shards whose boundary is not a chunk's, merged, are byte for
/// byte the same file, with every index once and in order — on the batched and the scalar path.
#[test]
fn rows_stream_across_chunks_in_index_order() {
    let dir = temp_dir("sweep-chunks");
    let scene = rotors();
    let n = 70_001;
    for (path, extra) in [("b", &[][..]), ("s", &["--scalar"][..])] {
        let file = |name: &str| format!("{path}-{name}.csv");
        let with = |more: &[&'static str]| [extra, more].concat();
        sweep(
            &dir,
            &scene,
            &file("one"),
            n,
            "0.05",
            &with(&["--threads", "1"]),
        );
        sweep(
            &dir,
            &scene,
            &file("two"),
            n,
            "0.05",
            &with(&["--threads", "2"]),
        );
        for i in 0..2 {
            let shard = format!("{i}/2");
            let args: Vec<&str> = [extra, &["--shard", &shard]].concat();
            sweep(&dir, &scene, &file(&format!("p{i}")), n, "0.05", &args);
        }
        let o = lie_sim(
            &["merge", &file("p1"), &file("p0"), "--out", &file("merged")],
            &dir,
        );
        assert!(o.status.success(), "{}", stderr(&o));
        let one = std::fs::read(dir.join(file("one"))).unwrap();
        assert_eq!(std::fs::read(dir.join(file("two"))).unwrap(), one);
        assert_eq!(std::fs::read(dir.join(file("merged"))).unwrap(), one);
        let rows = rows(&dir, &file("one"));
        assert_eq!(rows.len(), n);
        for (i, row) in rows.iter().enumerate() {
            assert_eq!(row[0], i.to_string());
            assert_eq!(row[1], "completed");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
