//! Outputs written like `cp`, and never at the cost of what was there: symbolic links followed,
//! FIFOs and devices written directly, inputs and repeated outputs refused, a full device, a full
//! filesystem and a read-only one refused in one line with the old file intact, and no debris
//! after an interrupted run (SIGINT, SIGTERM) or a killed one. Work bounded by what was asked:
//! limits checked up front, a shard costing only its own members (time and memory).

use crate::common::*;
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

/// Every file under `dir`, sorted, as names relative to it.
fn files(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

const SCENE: &str = r#"
[system]
kind = "free-rigid-body"
inertia = [1.0, 2.0, 3.0]

[initial]
momentum = [0.1, 1.0, 0.1]

[integrator]
method = "splitting"
step = 0.1
duration = 0.3
"#;

/// The directory's entries with the contents of its regular files (a FIFO is not read: that
/// would wait for a writer).
fn snapshot(dir: &Path) -> Vec<(String, Vec<u8>)> {
    files(dir)
        .into_iter()
        .map(|f| {
            let p = dir.join(&f);
            let regular = std::fs::symlink_metadata(&p).is_ok_and(|m| m.is_file());
            let bytes = if regular {
                std::fs::read(&p).unwrap()
            } else {
                vec![]
            };
            (f, bytes)
        })
        .collect()
}

/// A refused command: exit 1, one line naming the path and why, the directory as it was.
fn assert_refused(dir: &Path, args: &[&str], needles: &[&str]) {
    let before = snapshot(dir);
    let o = lie_sim(args, dir);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    for n in needles {
        assert!(err.contains(n), "`{n}` missing from: {err}");
    }
    assert_eq!(before, snapshot(dir), "{args:?} changed the directory");
}

#[test]
fn an_output_that_is_an_input_is_refused() {
    let dir = temp_dir("input");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    std::os::unix::fs::symlink("s.toml", dir.join("link.toml")).unwrap();
    assert_refused(
        &dir,
        &["run", "s.toml", "--out", "s.toml"],
        &["s.toml", "input"],
    );
    assert_refused(&dir, &["run", "s.toml", "--out", "link.toml"], &["input"]);
    assert_refused(
        &dir,
        &["trade", "s.toml", "--out", "s.toml", "--levels", "2"],
        &["input"],
    );
    assert!(lie_sim(&["run", "s.toml", "--out", "t.csv"], &dir)
        .status
        .success());
    assert_refused(
        &dir,
        &["plot", "t.csv", "--out", "t.csv"],
        &["t.csv", "input"],
    );
    assert_refused(&dir, &["merge", "t.csv", "--out", "t.csv"], &["input"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn plot_equal_to_out_is_refused() {
    let dir = temp_dir("plot-out");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    assert_refused(
        &dir,
        &["run", "s.toml", "--out", "x.csv", "--plot", "./x.csv"],
        &["x.csv", "also the output"],
    );
    assert_refused(
        &dir,
        &[
            "trade", "s.toml", "--out", "x.csv", "--plot", "x.csv", "--levels", "2",
        ],
        &["also the output"],
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_directory_output_is_refused() {
    let dir = temp_dir("dir");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    std::fs::create_dir(dir.join("d")).unwrap();
    assert_refused(&dir, &["run", "s.toml", "--out", "d"], &["directory"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_symlink_output_is_written_through_and_stays_a_link() {
    let dir = temp_dir("symlink");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    std::fs::write(dir.join("real.csv"), "old").unwrap();
    std::os::unix::fs::symlink("real.csv", dir.join("link.csv")).unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "link.csv"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let meta = std::fs::symlink_metadata(dir.join("link.csv")).unwrap();
    assert!(meta.file_type().is_symlink());
    assert!(std::fs::read_to_string(dir.join("real.csv"))
        .unwrap()
        .starts_with("t,"));
    assert_eq!(files(&dir), ["link.csv", "real.csv", "s.toml"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_fifo_and_a_device_are_written_directly() {
    use std::os::unix::fs::FileTypeExt;
    let dir = temp_dir("fifo");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    let fifo = dir.join("pipe");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    let o = lie_sim(&["run", "s.toml", "--out", "pipe"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = reader.join().unwrap();
    assert!(text.starts_with("t,mu1,mu2,mu3"), "{text}");
    assert_eq!(text.lines().count(), 5, "{text}");
    assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
    let o = lie_sim(&["run", "s.toml", "--out", "/dev/null"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    // --plot must read the trajectory back: not from a device.
    assert_refused(
        &dir,
        &["run", "s.toml", "--out", "/dev/null", "--plot", "p.svg"],
        &["regular file"],
    );
    assert_eq!(files(&dir), ["pipe", "s.toml"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `/dev/full` (every write fails with ENOSPC), written directly as a character device: exit 1,
/// one line naming the path and the cause.
#[test]
fn a_full_device_is_one_line() {
    let dir = temp_dir("dev-full");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "/dev/full"], &dir);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("/dev/full") && err.contains("No space left on device"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Runs `script` (sh) in a private mount namespace (`unshare -rm`) with a fresh 64 KiB tmpfs
/// mounted at `$D` and the working directory there; `$BIN` is lie-sim, `$OUT` the test's own
/// directory (outside the tmpfs, where the script leaves what the test reads). `None` where this
/// machine allows no such mount (no user namespaces, no unshare): the caller says it was skipped.
fn in_small_filesystem(dir: &Path, script: &str) -> Option<std::process::Output> {
    let mount = dir.join("mnt");
    std::fs::create_dir_all(&mount).unwrap();
    let full = format!(
        "mount -t tmpfs -o size=64k lie-sim-test \"$D\" || exit 97\ncd \"$D\" || exit 97\n{script}"
    );
    let o = Command::new("unshare")
        .args(["-rm", "sh", "-c", &full])
        .env("D", &mount)
        .env("BIN", BIN)
        .env("OUT", dir)
        .output()
        .ok()?;
    (o.status.code() != Some(97) && !stderr(&o).contains("unshare:")).then_some(o)
}

/// A full filesystem (a 64 KiB tmpfs) and a read-only one: the run fails with one line naming
/// the output and the cause (ENOSPC, EROFS), the old file there is intact and no temporary file
/// is left. Skipped (and said so) where no tmpfs can be mounted.
#[test]
fn a_full_or_read_only_filesystem_keeps_the_old_file_and_leaves_no_debris() {
    let dir = temp_dir("small-fs");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    // A trajectory of 20 001 rows (~1.4 MB) into 64 KiB; then the same into the tmpfs remounted
    // read-only. Each case records its exit status, stderr, the directory and the old file.
    let script = r#"
printf old > t.csv
"$BIN" run "$OUT/s.toml" --out t.csv --duration 2000 --step 0.1 2> "$OUT/full.err"
echo $? > "$OUT/full.code"
ls -A > "$OUT/full.ls"
cat t.csv > "$OUT/full.kept"
mount -o remount,ro "$D" || exit 98
"$BIN" run "$OUT/s.toml" --out t.csv 2> "$OUT/ro.err"
echo $? > "$OUT/ro.code"
ls -A > "$OUT/ro.ls"
cat t.csv > "$OUT/ro.kept"
"#;
    let Some(o) = in_small_filesystem(&dir, script) else {
        println!("skipped: this machine mounts no tmpfs for the test (unshare -rm)");
        std::fs::remove_dir_all(&dir).unwrap();
        return;
    };
    assert!(o.status.success(), "{}", stderr(&o));
    let read = |f: &str| std::fs::read_to_string(dir.join(f)).unwrap();
    for (case, cause) in [
        ("full", "No space left on device"),
        ("ro", "Read-only file system"),
    ] {
        assert_eq!(read(&format!("{case}.code")).trim(), "1", "{case}");
        let err = read(&format!("{case}.err"));
        assert_eq!(err.lines().count(), 1, "{case}: {err}");
        assert!(
            err.contains("t.csv") && err.contains(cause),
            "{case}: {err}"
        );
        assert_eq!(
            read(&format!("{case}.kept")),
            "old",
            "{case}: the old file changed"
        );
        assert_eq!(
            read(&format!("{case}.ls")).trim(),
            "t.csv",
            "{case}: debris left"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A long run interrupted by `signal` while it writes: exit 128 + signal, the old output intact, no
/// temporary file left.
fn interrupted(signal: &str, code: i32) {
    let dir = temp_dir(&format!("signal-{signal}"));
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    std::fs::write(dir.join("t.csv"), "old").unwrap();
    let mut child = Command::new(BIN)
        .args([
            "run",
            "s.toml",
            "--out",
            "t.csv",
            "--duration",
            "1e7",
            "--step",
            "1e-3",
            "--allow-large",
        ])
        .current_dir(&dir)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let temp = |d: &Path| files(d).into_iter().find(|f| f.starts_with(".t.csv."));
    while temp(&dir).is_none() {
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "no temporary file"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    std::thread::sleep(Duration::from_millis(100)); // let it write some rows
    let pid = child.id().to_string();
    assert!(Command::new("kill")
        .args([signal, &pid])
        .status()
        .unwrap()
        .success());
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(code), "{signal}");
    assert_eq!(std::fs::read_to_string(dir.join("t.csv")).unwrap(), "old");
    assert_eq!(files(&dir), ["s.toml", "t.csv"], "{signal}: debris left");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn sigint_and_sigterm_leave_the_old_output_and_no_debris() {
    interrupted("-INT", 130);
    interrupted("-TERM", 143);
}

/// A run killed with SIGKILL leaves its temporary file; the next run into the directory removes it.
#[test]
fn temporary_files_of_dead_runs_are_cleaned_by_the_next_run() {
    let dir = temp_dir("stale");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    std::fs::write(dir.join(".t.csv.4194305.tmp"), "debris").unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "t.csv"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(files(&dir), ["s.toml", "t.csv"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A 1000-member shard of a sweep of N = 10¹² members draws only its own members: it runs in a
/// fraction of a second and within 256 MiB of address space (`ulimit -v`; materialising N momenta
/// would need 24 TB; the same command under 16 MiB fails, so the limit does apply) and writes
/// rows 0–999; a sweep of 2⁶⁴ − 1 members is accepted too.
#[test]
fn a_small_shard_of_a_huge_sweep_costs_only_its_own_members() {
    let dir = temp_dir("huge-sweep");
    let scene = scenes_dir().join("sweep.toml");
    let limited = |kib: u32| {
        Command::new("sh")
            .args([
                "-c",
                &format!(
                    "ulimit -v {kib} && exec \"$BIN\" sweep \"$SCENE\" --out s.csv --count \
                     1000000000000 --shard 0/1000000000 --duration 0.05"
                ),
            ])
            .env("BIN", BIN)
            .env("SCENE", &scene)
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    assert!(
        !limited(16 * 1024).status.success(),
        "16 MiB: the limit does not bite"
    );
    assert!(!dir.join("s.csv").exists());
    let start = Instant::now();
    let o = limited(256 * 1024);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(start.elapsed() < Duration::from_secs(20));
    let text = std::fs::read_to_string(dir.join("s.csv")).unwrap();
    assert!(text.starts_with("# lie-sim sweep: members = 1000000000000, shard = 0/1000000000"));
    let rows: Vec<&str> = text.lines().skip(2).collect();
    assert_eq!(rows.len(), 1000);
    assert!(rows[999].starts_with("999,completed"), "{}", rows[999]);
    let o = lie_sim(
        &[
            "sweep",
            scene.to_str().unwrap(),
            "--out",
            "m.csv",
            "--count",
            "18446744073709551615",
            "--shard",
            "18446744073709551614/18446744073709551615",
            "--duration",
            "0.05",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("m.csv")).unwrap();
    assert!(text
        .lines()
        .nth(2)
        .unwrap()
        .starts_with("18446744073709551614,completed"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Work beyond the limits (10⁹ steps, 1 GiB of output) is refused before it starts, with the
/// figures and the way around; nothing is written.
#[test]
fn work_beyond_the_limits_is_refused_up_front() {
    let dir = temp_dir("bounds");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    assert_refused(
        &dir,
        &[
            "run",
            "s.toml",
            "--out",
            "t.csv",
            "--duration",
            "1e7",
            "--step",
            "1e-3",
        ],
        &["run", "1.000e10 integrator steps", "--allow-large"],
    );
    assert_refused(
        &dir,
        &[
            "run",
            "s.toml",
            "--out",
            "t.csv",
            "--duration",
            "5e5",
            "--step",
            "1e-3",
        ],
        &["GiB of output", "--stride", "--allow-large"],
    );
    assert_refused(
        &dir,
        &[
            "trade",
            "s.toml",
            "--out",
            "t.csv",
            "--duration",
            "1e5",
            "--levels",
            "12",
        ],
        &["trade", "integrator steps"],
    );
    assert_refused(
        &dir,
        &[
            "trade",
            "s.toml",
            "--out",
            "t.csv",
            "--duration",
            "1e3",
            "--steps",
            "1e-5",
        ],
        &["trade", "integrator steps"],
    );
    let scene = scenes_dir().join("sweep.toml");
    assert_refused(
        &dir,
        &[
            "sweep",
            scene.to_str().unwrap(),
            "--out",
            "w.csv",
            "--count",
            "1000000000000",
        ],
        &["sweep", "integrator steps"],
    );
    assert_eq!(files(&dir), ["s.toml"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--quiet` prints nothing on stdout (the outputs are still written).
#[test]
fn quiet_prints_nothing() {
    let dir = temp_dir("quiet");
    std::fs::write(dir.join("s.toml"), SCENE).unwrap();
    let o = lie_sim(&["--quiet", "run", "s.toml", "--out", "t.csv"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(o.stdout.is_empty() && o.stderr.is_empty());
    assert!(dir.join("t.csv").exists());
    let o = lie_sim(&["run", "s.toml", "--out", "u.csv"], &dir);
    assert!(!o.stdout.is_empty());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// In a Slurm job array, `sweep` without `--shard` runs task (ID − MIN) of COUNT; a malformed
/// variable is an error naming it.
#[test]
fn sweep_shard_defaults_from_a_slurm_job_array() {
    let dir = temp_dir("slurm");
    let scene = scenes_dir().join("sweep.toml");
    let run = |id: &str| {
        Command::new(BIN)
            .args([
                "sweep",
                scene.to_str().unwrap(),
                "--out",
                "w.csv",
                "--count",
                "8",
            ])
            .args(["--duration", "0.05"])
            .env("SLURM_ARRAY_TASK_ID", id)
            .env("SLURM_ARRAY_TASK_MIN", "1")
            .env("SLURM_ARRAY_TASK_COUNT", "4")
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    let o = run("3");
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(dir.join("w.csv")).unwrap();
    assert!(text.contains("shard = 2/4"), "{text}");
    let rows: Vec<&str> = text.lines().skip(2).collect();
    assert_eq!(rows.len(), 2);
    assert!(
        rows[0].starts_with("4,") && rows[1].starts_with("5,"),
        "{text}"
    );
    let o = run("three");
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("SLURM_ARRAY_TASK_ID"), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
}
