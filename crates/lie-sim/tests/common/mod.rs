//! What every end-to-end test of the `lie-sim` binary needs: the binary, the example scenes, a
//! fresh directory, and the run's output as text.
#![allow(dead_code)] // each test file uses its own part

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The binary under test.
pub const BIN: &str = env!("CARGO_BIN_EXE_lie-sim");

/// `examples/scenes` of the repository.
pub fn scenes_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes")
}

/// A fresh empty directory for one test (unique per test binary and name).
pub fn temp_dir(name: &str) -> PathBuf {
    let exe = std::env::current_exe().ok();
    let binary = exe
        .as_deref()
        .and_then(Path::file_stem)
        .map_or_else(|| "test".into(), |s| s.to_string_lossy().into_owned());
    let d = std::env::temp_dir().join(format!("lie-sim-{binary}-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs the binary with `args` in `cwd`.
pub fn lie_sim(args: &[&str], cwd: &Path) -> Output {
    Command::new(BIN)
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("the lie-sim binary runs")
}

/// The run's stderr as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The run's stdout as text.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A trajectory CSV written by `lie-sim run`: its header and its rows of numbers.
pub struct Csv {
    /// The column names.
    pub header: Vec<String>,
    /// The rows.
    pub rows: Vec<Vec<f64>>,
}

impl Csv {
    /// Reads a trajectory CSV (every cell a number).
    pub fn read(path: &Path) -> Csv {
        let text = std::fs::read_to_string(path).unwrap();
        let mut lines = text.lines();
        let header = lines
            .next()
            .unwrap()
            .split(',')
            .map(String::from)
            .collect::<Vec<_>>();
        let rows = lines
            .map(|l| l.split(',').map(|x| x.parse::<f64>().unwrap()).collect())
            .collect();
        Csv { header, rows }
    }
    /// The column `name`.
    pub fn col(&self, name: &str) -> Vec<f64> {
        let j = self
            .header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name} in {:?}", self.header));
        self.rows.iter().map(|r| r[j]).collect()
    }
}

/// Writes `scene` to a fresh directory, runs `lie-sim run` on it with an output path there, and
/// checks: exit status 1, one line on stderr containing every one of `needles`, and no file left
/// besides the scene.
pub fn assert_rejected(name: &str, scene: &str, needles: &[&str]) {
    let dir = temp_dir(name);
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "out/t.csv"], &dir);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{name}: {err}");
    assert_eq!(err.lines().count(), 1, "{name}: not one line: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: `{n}` missing from: {err}");
    }
    let left: Vec<_> = walk(&dir);
    assert_eq!(left, vec![dir.join("s.toml")], "{name}: files left behind");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every file below `dir`.
pub fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut v = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            v.extend(walk(&p));
        } else {
            v.push(p);
        }
    }
    v
}

/// Runs `lie-sim run FILE --duration T` on a scene of examples/scenes; returns its trajectory
/// and its summary (stdout).
pub fn run_example(file: &str, duration: &str) -> (Csv, String) {
    let dir = temp_dir(file);
    let out = dir.join("traj.csv");
    let scene = scenes_dir().join(file);
    let o = lie_sim(
        &[
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--duration",
            duration,
        ],
        &dir,
    );
    assert!(o.status.success(), "{file}: {}", stderr(&o));
    let csv = Csv::read(&out);
    std::fs::remove_dir_all(&dir).unwrap();
    (csv, stdout(&o))
}

/// What `lie-sim run` of a scene's text did: (exit ok, stdout, stderr, the trajectory CSV's rows
/// as numbers, the files left in its fresh directory — 1, the scene, when it failed cleanly).
pub fn run_text(name: &str, scene: &str) -> (bool, String, String, Vec<Vec<f64>>, usize) {
    let dir = temp_dir(name);
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = lie_sim(&["run", "s.toml", "--out", "t.csv"], &dir);
    let rows = std::fs::read_to_string(dir.join("t.csv"))
        .map(|text| {
            text.lines()
                .skip(1)
                .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
                .collect()
        })
        .unwrap_or_default();
    let files = std::fs::read_dir(&dir).unwrap().count();
    std::fs::remove_dir_all(&dir).unwrap();
    (o.status.success(), stdout(&o), stderr(&o), rows, files)
}
