//! `lie-sim choose`: the chosen method, re-run from the scene it writes, meets the target; a target
//! nothing meets is said so; bad input is one line and no file.

mod common;

use common::*;
use std::path::Path;

/// The last CSV row of a trajectory, as numbers.
fn last_row(path: &Path) -> Vec<f64> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect()
}

/// The free body at 1e-8 over T = 10, the chosen scene re-run against the exact flow in one step
/// (an independent run of the closed form): Π and R within the target (the trade's error measure:
/// Π relative to |Π|, R absolutely).
#[test]
fn the_chosen_method_meets_the_target_when_re_run() {
    let dir = temp_dir("meets");
    let scene = scenes_dir().join("free-rigid-body.toml");
    let o = lie_sim(
        &[
            "choose",
            scene.to_str().unwrap(),
            "--target",
            "1e-8",
            "--horizon",
            "10",
            "--write",
            "chosen.toml",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("chosen") && out.contains("runner-up"), "{out}");
    let o = lie_sim(&["run", "chosen.toml", "--out", "c.csv"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(scene)
        .unwrap()
        .replace("method = \"lie-poisson\"", "method = \"exact\"")
        .replace("tau = \"exp\"", "")
        .replace("theta = 0.5", "")
        .replace("step = 0.05", "step = 10.0")
        .replace("duration = 50.0", "duration = 10.0");
    std::fs::write(dir.join("exact.toml"), text).unwrap();
    let o = lie_sim(&["run", "exact.toml", "--out", "e.csv"], &dir);
    assert!(o.status.success(), "{}", stderr(&o));
    let (c, e) = (last_row(&dir.join("c.csv")), last_row(&dir.join("e.csv")));
    assert_eq!(c[0], 10.0);
    let scale = e[1..4].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mu = (1..4).fold(0.0f64, |m, i| m.max((c[i] - e[i]).abs())) / scale;
    let g = (4..13).fold(0.0f64, |m, i| m.max((c[i] - e[i]).abs()));
    assert!(mu.max(g) <= 1e-8, "re-run misses the target: {mu:e}, {g:e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The energy metric on the heavy top: the chosen scene, re-run, keeps the energy within the target
/// at every step (the summary's maximum over all steps).
#[test]
fn the_chosen_energy_method_meets_the_target_at_every_step() {
    let dir = temp_dir("energy");
    let scene = scenes_dir().join("heavy-top.toml");
    let o = lie_sim(
        &[
            "choose",
            scene.to_str().unwrap(),
            "--target",
            "1e-6",
            "--metric",
            "energy",
            "--horizon",
            "1",
            "--step",
            "0.004",
            "--write",
            "e.toml",
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let o = lie_sim(&["run", "e.toml", "--out", "e.csv"], &dir);
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    let line = out
        .lines()
        .find(|l| l.contains("max |E − E₀|/|E₀|"))
        .unwrap();
    let value: f64 = line.rsplit(' ').next().unwrap().parse().unwrap();
    assert!(value <= 1e-6, "{line}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A target nothing reaches: one line saying so, with the best value reached, exit 1, no file.
#[test]
fn a_target_nothing_meets_is_said_so() {
    let dir = temp_dir("none");
    let scene = scenes_dir().join("heavy-top.toml");
    let o = lie_sim(
        &[
            "choose",
            scene.to_str().unwrap(),
            "--target",
            "1e-30",
            "--horizon",
            "0.2",
            "--levels",
            "2",
            "--write",
            "x.toml",
        ],
        &dir,
    );
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("no method meets") && err.contains("best run reached"),
        "{err}"
    );
    assert!(!dir.join("x.toml").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_is_one_line_and_no_file() {
    let dir = temp_dir("bad");
    for args in [
        &["choose", "--target", "0", "--write", "x.toml"][..],
        &["choose", "--target", "NaN", "--write", "x.toml"],
        &[
            "choose",
            "--target",
            "1e-8",
            "--horizon",
            "-1",
            "--write",
            "x.toml",
        ],
        &[
            "choose", "--target", "1e-8", "--budget", "0s", "--write", "x.toml",
        ],
        &["choose", "--target", "1e-8", "--budget", "3 fortnights"],
    ] {
        let o = lie_sim(args, &dir);
        assert_ne!(o.status.code(), Some(0), "{args:?}");
        let err = stderr(&o);
        assert!(!err.is_empty(), "{args:?}");
        assert!(!dir.join("x.toml").exists(), "{args:?}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
