//! Exact at the edges (issue #29): runs that land on T and meet the times asked for, inputs read
//! only from regular files of bounded size, no output lost or written half, work limits that
//! count what a step costs on its group, messages that name the field and the value given, and
//! physical checks at load (the triangle inequality of a rigid body's moments, springs whose
//! attachment points coincide).

use crate::common::*;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const BODY: &str = r#"
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
duration = 1.0
"#;

/// Runs the binary with `args` in `cwd`, killed (and the test failed) after 60 s: a read that
/// never ends must fail the test, not hang it.
fn bounded(args: &[&str], cwd: &Path) -> Output {
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(cwd)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            panic!("{args:?} still running after 60 s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// Exit 1 with one line containing every needle.
fn assert_refused(o: &Output, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    for n in needles {
        assert!(err.contains(n), "`{n}` missing from: {err}");
    }
}

/// `[output] times` containing T gives that row, and a run of T/h steps ends at T exactly.
/// (Reported: with t += h the run ended at 0.9999999999999999 and the CSV had no row.)
#[test]
fn run_meets_output_times_at_t_and_ends_on_t() {
    let dir = temp_dir("edges-times");
    std::fs::write(
        dir.join("s.toml"),
        format!("{BODY}\n[output]\ntimes = [0.3, 0.7, 1.0]\n"),
    )
    .unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "t.csv", "-q"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(Csv::read(&dir.join("t.csv")).col("t"), [0.3, 0.7, 1.0]);
    // 5000 steps of 0.01: the last row at 50 exactly (49.99999999999862 with t += h)
    std::fs::write(
        dir.join("u.toml"),
        format!("{BODY}\n[output]\nstride = 2000\n"),
    )
    .unwrap();
    let o = lie_sim(
        &[
            "run",
            "u.toml",
            "--out",
            "u.csv",
            "-q",
            "--step",
            "0.01",
            "--duration",
            "50",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let t = Csv::read(&dir.join("u.csv")).col("t");
    assert_eq!(t.last(), Some(&50.0));
    assert_eq!(t.len(), 4);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The symmetric top 𝕀 = diag(1, 1, 2), Π₀ = (1, 0, 1) (Π = (cos(t/2), sin(t/2), 1)), to
/// T = 20 with the stepping `integrator` gives (a method and its step, tolerance or ε).
fn top(integrator: &str) -> String {
    format!(
        "[system]\nkind = \"free-rigid-body\"\ninertia = [1.0, 1.0, 2.0]\n\
         [initial]\nmomentum = [1.0, 0.0, 1.0]\n\
         [integrator]\n{integrator}\nduration = 20.0\n"
    )
}

/// On every kind of stepping — fixed steps whose last one is shortened (h = 0.03: T/h =
/// 666.7), steps to a tolerance, reversible steps with ε — a run lands on T exactly (its last
/// row), writes its `[output] times` rows at exactly those times (0.3 and 1.0 step boundaries
/// of fixed steps of 0.1, the rest between steps) with `[[events]]` located alongside, and a
/// `stop = true` event ends it with its last row at the located time: Π₂ = −½ there to the
/// event tolerance, t within the method's phase error of 7π/3, no row after it. (The values and
/// the located times are checked against the closed form within a bound on the method's phase
/// error in the angle t/2 — Lie–Poisson's is 1.5e-5 (h/0.01)² t: 2.7e-3 at T = 20 with
/// h = 0.03, 3e-2 with h = 0.1 — and twice that in t.)
#[test]
fn events_and_output_times_land_exactly_with_every_kind_of_step() {
    let pi = std::f64::consts::PI;
    let times = [0.0, 0.3, 1.0, 7.0, 12.3456, 20.0];
    for (integrator, phase) in [
        (
            "method = \"lie-poisson\"\ntau = \"cayley\"\ntheta = 0.5\nstep = 0.03",
            5e-3,
        ),
        (
            "method = \"lie-poisson\"\ntau = \"cayley\"\ntheta = 0.5\nstep = 0.1",
            5e-2,
        ),
        ("method = \"rkmk-dop853\"\ntolerance = 1e-9", 5e-3),
        ("method = \"splitting\"\nepsilon = 0.01", 5e-3),
    ] {
        let scene = top(integrator);
        // the stride's rows: the last one at T
        let (ok, _, err, rows, _) = run_text("edges-events-t", &scene);
        assert!(ok, "{integrator}: {err}");
        assert_eq!(rows.last().unwrap()[0], 20.0, "{integrator}");
        // rows at the requested times, events located between
        let with_times =
            format!("{scene}\n[output]\ntimes = {times:?}\n\n[[events]]\nquantity = \"mu1\"\n");
        let (ok, out, err, rows, _) = run_text("edges-events-times", &with_times);
        assert!(ok, "{integrator}: {err}");
        let t: Vec<f64> = rows.iter().map(|r| r[0]).collect();
        assert_eq!(t, times, "{integrator}");
        for row in &rows {
            let (c, s) = ((row[0] / 2.0).cos(), (row[0] / 2.0).sin());
            assert!(
                (row[1] - c).abs() < phase && (row[2] - s).abs() < phase,
                "{integrator}: {row:?}"
            );
        }
        let events: Vec<f64> = out
            .lines()
            .filter(|l| l.trim_start().starts_with("event"))
            .map(|l| l.rsplit("t = ").next().unwrap().trim().parse().unwrap())
            .collect();
        assert_eq!(events.len(), 3, "{integrator}: {out}");
        for (t, want) in events.iter().zip([pi, 3.0 * pi, 5.0 * pi]) {
            assert!(
                (t - want).abs() < 2.0 * phase,
                "{integrator}: {t} vs {want}"
            );
        }
        // a terminal event: the last row at its time
        let stop = format!(
            "{scene}\n[[events]]\nquantity = \"mu2\"\nvalue = -0.5\ndirection = \"falling\"\n\
             stop = true\n"
        );
        let (ok, out, err, rows, _) = run_text("edges-events-stop", &stop);
        assert!(ok, "{integrator}: {err}");
        assert!(out.contains("stopped"), "{integrator}: {out}");
        let last = rows.last().unwrap();
        assert!(
            (last[0] - 7.0 * pi / 3.0).abs() < 2.0 * phase,
            "{integrator}: {last:?}"
        );
        assert!((last[2] + 0.5).abs() < 1e-9, "{integrator}: {last:?}");
        assert!(
            rows.windows(2).all(|w| w[0][0] < w[1][0]),
            "{integrator}: times increase, none after the stop"
        );
        let reported: f64 = out
            .lines()
            .find(|l| l.contains("stopped"))
            .and_then(|l| l.split("t = ").nth(1))
            .and_then(|l| l.split_whitespace().next())
            .unwrap()
            .parse()
            .unwrap();
        assert!(
            (reported - last[0]).abs() < 1e-11,
            "{integrator}: {reported} vs {last:?}"
        );
    }
}

/// Every input — scene, `--reference`, `merge` shards, `plot` CSV — is refused when it is a
/// character device, a FIFO or a directory, in one line naming the path, at once: nothing is
/// read from it. (Reported: `lie-sim run /dev/zero` grew ~2 GB/s until memory ran out.)
#[test]
fn non_regular_inputs_are_refused_naming_the_path() {
    let dir = temp_dir("edges-inputs");
    std::fs::write(dir.join("s.toml"), BODY).unwrap();
    let fifo = dir.join("fifo");
    let made = Command::new("mkfifo").arg(&fifo).status();
    std::fs::create_dir(dir.join("sub")).unwrap();
    let mut cases = vec![("/dev/zero", "character device"), ("sub", "directory")];
    if made.is_ok_and(|s| s.success()) {
        cases.push(("fifo", "FIFO"));
    }
    for (input, kind) in cases {
        for args in [
            vec!["run", input, "--out", "o.csv"],
            vec!["plot", input, "--out", "o.svg"],
            vec!["merge", input, "--out", "o.csv"],
            vec!["trade", "s.toml", "--reference", input, "--out", "o.csv"],
        ] {
            let o = bounded(&args, &dir);
            assert_refused(&o, &[input, kind]);
        }
    }
    assert!(!dir.join("o.csv").exists() && !dir.join("o.svg").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A regular file beyond the input limit (1 GiB; sparse here, so it costs no disk) is refused
/// before it is read.
#[test]
fn an_input_beyond_the_cap_is_refused_unread() {
    let dir = temp_dir("edges-cap");
    let big = std::fs::File::create(dir.join("big.toml")).unwrap();
    big.set_len((1u64 << 30) + 1).unwrap();
    let o = bounded(&["run", "big.toml", "--out", "o.csv"], &dir);
    assert_refused(&o, &["big.toml", "input limit"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `sweep --shard i/n` without `--out` writes a file of its own per shard, and merging them
/// gives the unsharded sweep. (Reported: every shard wrote `<scene>-sweep.csv`, shard 1/4
/// replacing shard 0/4's file.)
#[test]
fn shards_without_out_do_not_share_a_default_file() {
    let dir = temp_dir("edges-shards");
    let scene = scenes_dir().join("sweep.toml");
    let scene = scene.to_str().unwrap();
    let sweep = |extra: &[&str]| {
        let mut args = vec!["sweep", scene, "--count", "8", "--duration", "0.05", "-q"];
        args.extend_from_slice(extra);
        let o = lie_sim(&args, &dir);
        assert!(o.status.success(), "{}", stderr(&o));
    };
    sweep(&["--shard", "0/2"]);
    sweep(&["--shard", "1/2"]);
    sweep(&[]);
    let out = dir.join("target/lie-sim");
    let shard = |i: usize| out.join(format!("sweep-sweep-shard-{i}-of-2.csv"));
    assert!(
        shard(0).exists() && shard(1).exists(),
        "{:?}",
        std::fs::read_dir(&out)
    );
    let o = lie_sim(
        &[
            "merge",
            shard(1).to_str().unwrap(),
            shard(0).to_str().unwrap(),
            "--out",
            "merged.csv",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        std::fs::read(dir.join("merged.csv")).unwrap(),
        std::fs::read(out.join("sweep-sweep.csv")).unwrap()
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every member of a sweep ends at exactly T, on the scalar path, the batched one and a shard:
/// `--duration 0.7 --step 0.01` takes 70 steps of 0.7/70, which sum to 0.7000000000000001; the
/// last one lands on T. (Reported: every row's time was 0.7000000000000001 where `run` ends at
/// 0.7.) The batched and scalar splitting agree on the time to the bit.
#[test]
fn sweeps_end_at_exactly_t_on_every_path() {
    let dir = temp_dir("edges-sweep-t");
    let times = |scene: &str, out: &str, extra: &[&str]| -> Vec<String> {
        let scene = scenes_dir().join(scene);
        let mut args = vec![
            "sweep",
            scene.to_str().unwrap(),
            "--out",
            out,
            "--count",
            "11",
            "--duration",
            "0.7",
            "--step",
            "0.01",
            "-q",
        ];
        args.extend_from_slice(extra);
        let o = lie_sim(&args, &dir);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        let text = std::fs::read_to_string(dir.join(out)).unwrap();
        let header = text.lines().nth(1).unwrap();
        assert!(header.starts_with("index,status,steps,time,"), "{header}");
        text.lines()
            .skip(2)
            .map(|l| l.split(',').nth(3).unwrap().to_string())
            .collect()
    };
    for (scene, out, extra) in [
        ("sweep.toml", "scalar.csv", &[][..]),
        ("sweep.toml", "shard.csv", &["--shard", "1/3"][..]),
        ("sweep-rotors.toml", "batched.csv", &[][..]),
        (
            "sweep-rotors.toml",
            "batched-shard.csv",
            &["--shard", "2/3"][..],
        ),
        ("sweep-rotors.toml", "rotors-scalar.csv", &["--scalar"][..]),
    ] {
        let t = times(scene, out, extra);
        assert!(!t.is_empty(), "{out}");
        for cell in &t {
            assert_eq!(cell.parse::<f64>().unwrap(), 0.7, "{out}: {cell}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// An existing output the caller may not write (0444, owned by someone else) is refused as `cp`
/// refuses it, and left as it was, although the directory would let a temporary file be renamed
/// over it. (Reported: it was replaced.) As root, the run is made as `nobody` (setpriv).
#[test]
fn a_read_only_output_is_refused_and_left_untouched() {
    use std::os::unix::fs::PermissionsExt;
    let dir = temp_dir("edges-readonly");
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o777)).unwrap();
    std::fs::write(dir.join("s.toml"), BODY).unwrap();
    std::fs::set_permissions(dir.join("s.toml"), std::fs::Permissions::from_mode(0o644)).unwrap();
    let target = dir.join("ro.csv");
    std::fs::write(&target, "theirs").unwrap();
    std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o444)).unwrap();
    let root = std::fs::metadata(&dir).map(|m| std::os::unix::fs::MetadataExt::uid(&m) == 0);
    let mut cmd = if root.unwrap_or(false) {
        let mut c = Command::new("setpriv");
        c.args(["--reuid=65534", "--regid=65534", "--clear-groups", BIN]);
        c
    } else {
        Command::new(BIN)
    };
    let o = match cmd
        .args(["run", "s.toml", "--out", "ro.csv", "-q"])
        .current_dir(&dir)
        .output()
    {
        Ok(o) => o,
        Err(e) => {
            eprintln!("skipped: cannot run as another user ({e})");
            return;
        }
    };
    if stderr(&o).contains("setpriv") {
        eprintln!("skipped: {}", stderr(&o));
        return;
    }
    assert_refused(&o, &["ro.csv", "ermission denied"]);
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "theirs");
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 2, "debris: {names:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `run --plot <dir>` is refused before anything is written. (Reported: the CSV was written,
/// then the plot failed.)
#[test]
fn plot_into_a_directory_is_refused_before_the_csv_is_written() {
    let dir = temp_dir("edges-plotdir");
    std::fs::write(dir.join("s.toml"), BODY).unwrap();
    std::fs::create_dir(dir.join("pd")).unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "t.csv", "--plot", "pd"], &dir);
    assert_refused(&o, &["pd", "directory"]);
    assert!(!dir.join("t.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The work limit counts a step's cost on its group: 10⁵ implicit steps on SO(50), far below
/// the 10⁹-step limit but hours of Newton solves on a 1225×1225 matrix, are refused up front
/// with the estimate and the limit. (Reported: accepted; such runs would take years.)
#[test]
fn the_work_limit_counts_the_cost_on_the_group() {
    let dir = temp_dir("edges-cost");
    let n = 50;
    let inertia = vec!["1.0"; n].join(", ");
    let momentum = vec!["0.01"; n * (n - 1) / 2].join(", ");
    let scene = format!(
        "[system]\nkind = \"geodesic-so-n\"\nn = {n}\ninertia = [{inertia}]\n[initial]\n\
         momentum = [{momentum}]\n[integrator]\nmethod = \"lie-poisson\"\ntau = \"cayley\"\n\
         theta = 0.5\nstep = 0.01\nduration = 1000.0\n[output]\nstride = 100000\n"
    );
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = bounded(&["run", "s.toml", "--out", "o.csv"], &dir);
    assert_refused(
        &o,
        &[
            "1.000e5 integrator steps",
            "SO(3)-step equivalents",
            "limit 1e9",
        ],
    );
    assert!(!dir.join("o.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Messages name the field and the value written: a mistyped inertia, a horizon shorter than
/// the step, an inertia of 1e308·I (accepted: it is a valid inertia, not "singular").
#[test]
fn messages_name_the_field_and_the_value_given() {
    let dir = temp_dir("edges-messages");
    std::fs::write(
        dir.join("typo.toml"),
        BODY.replace("[1.0, 2.0, 3.0]", "\"1,2,3\""),
    )
    .unwrap();
    let o = lie_sim(&["run", "typo.toml", "--out", "o.csv"], &dir);
    assert_refused(&o, &["system.inertia", "\"1,2,3\"", "principal moments"]);
    assert!(!stderr(&o).contains("untagged"), "{}", stderr(&o));
    std::fs::write(dir.join("s.toml"), BODY).unwrap();
    for cmd in ["trade", "choose"] {
        let mut args = vec![cmd, "s.toml", "--horizon", "1e-300"];
        if cmd == "choose" {
            args.extend(["--target", "1e-6"]);
        }
        let o = lie_sim(&args, &dir);
        assert_refused(&o, &["--horizon", "1e-300", "0.1"]);
        assert!(
            !stderr(&o).contains("integrator.duration"),
            "{}",
            stderr(&o)
        );
    }
    std::fs::write(
        dir.join("huge.toml"),
        BODY.replace("[1.0, 2.0, 3.0]", "[1e308, 1e308, 1e308]"),
    )
    .unwrap();
    let o = lie_sim(&["run", "huge.toml", "--out", "o.csv", "-q"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Principal moments that no rigid body has (I₃ > I₁ + I₂), as moments or as a matrix, are
/// refused naming the field, the moments and the opt-out; `generalized_inertia = true` accepts
/// them. (Reported: (1, 1, 5) was accepted.)
#[test]
fn inertia_breaking_the_triangle_inequality_is_refused_unless_generalized() {
    let dir = temp_dir("edges-triangle");
    for inertia in [
        "[1.0, 1.0, 5.0]",
        "[[5.0, 0.0, 0.0], [0.0, 1.0, 0.5], [0.0, 0.5, 1.0]]",
    ] {
        let bad = BODY.replace("[1.0, 2.0, 3.0]", inertia);
        std::fs::write(dir.join("s.toml"), &bad).unwrap();
        let o = lie_sim(&["run", "s.toml", "--out", "o.csv"], &dir);
        assert_refused(
            &o,
            &[
                "system.inertia",
                "triangle inequality",
                "generalized_inertia",
            ],
        );
        let opted = bad.replace(
            &format!("inertia = {inertia}"),
            &format!("inertia = {inertia}\ngeneralized_inertia = true"),
        );
        std::fs::write(dir.join("g.toml"), opted).unwrap();
        let o = lie_sim(&["run", "g.toml", "--out", "o.csv", "-q"], &dir);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    // a flat plate (I₃ = I₁ + I₂) is a rigid body
    std::fs::write(
        dir.join("p.toml"),
        BODY.replace("[1.0, 2.0, 3.0]", "[0.1, 0.2, 0.3]"),
    )
    .unwrap();
    let o = lie_sim(&["run", "p.toml", "--out", "o.csv", "-q"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Coupled bodies with a spring (rest length > 0) whose attachment points coincide are refused
/// at load with the cause. (Reported: "step h too large" at every h.)
#[test]
fn coincident_spring_attachments_are_refused_at_load() {
    let dir = temp_dir("edges-springs");
    let scene = std::fs::read_to_string(scenes_dir().join("coupled-bodies.toml"))
        .unwrap()
        .replace(
            "attachments = [[0.2, 0.0, 0.0], [-0.1, 0.1, 0.0]]",
            "attachments = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]",
        )
        .replace("position = [1.3, 0.2, 0.1]", "position = [0.0, 0.0, 0.0]");
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "o.csv"], &dir);
    assert_refused(
        &o,
        &[
            "system.springs[0].attachments",
            "coincide",
            "bodies 0 and 1",
        ],
    );
    assert!(!dir.join("o.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
