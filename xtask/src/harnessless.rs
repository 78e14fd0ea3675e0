//! Targets built without a unit-test harness hold no unit tests.
//!
//! A library or binary whose `Cargo.toml` says `test = false` is not compiled a second time with
//! `cfg(test)` by `cargo test` (a release build of `lie-sim`'s command or of `mechanics` costs
//! minutes on the CI machine, for harnesses that held no test). The price is that a `#[test]`
//! added to such a target would compile away silently and never run; `cargo xtask docs --check`
//! refuses it instead.

use crate::error::{Error, Result};
use crate::exec;
use std::path::{Path, PathBuf};

/// A target of the workspace that `cargo test` builds without its harness.
#[derive(Debug, Clone, PartialEq)]
pub struct Harnessless {
    /// `package/target`.
    pub name: String,
    /// The files whose `#[test]`s would be lost: a library's whole source directory, a binary's
    /// own file (its library may share the directory and has a harness of its own).
    pub files: Vec<PathBuf>,
}

/// The workspace's targets with `test = false`, from `cargo metadata`.
pub fn targets(root: &Path) -> Result<Vec<Harnessless>> {
    let args = exec::strings(&["metadata", "--no-deps", "--format-version", "1"]);
    let text = exec::cargo_stdout(root, &args)?;
    let meta: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| Error::parse("cargo metadata", e.to_string()))?;
    Ok(from_metadata(&meta))
}

/// [`targets`] from parsed metadata.
fn from_metadata(meta: &serde_json::Value) -> Vec<Harnessless> {
    let mut out = Vec::new();
    for package in meta["packages"].as_array().into_iter().flatten() {
        for target in package["targets"].as_array().into_iter().flatten() {
            let kinds: Vec<&str> = target["kind"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(|k| k.as_str())
                .collect();
            let lib = kinds.iter().any(|k| k.ends_with("lib"));
            let bin = kinds.contains(&"bin");
            if target["test"].as_bool() != Some(false) || !(lib || bin) {
                continue;
            }
            let Some(src) = target["src_path"].as_str().map(PathBuf::from) else {
                continue;
            };
            let files = if lib {
                src.parent().map(rust_files).unwrap_or_default()
            } else {
                vec![src]
            };
            out.push(Harnessless {
                name: format!(
                    "{}/{}",
                    package["name"].as_str().unwrap_or("?"),
                    target["name"].as_str().unwrap_or("?")
                ),
                files,
            });
        }
    }
    out
}

/// The `.rs` files under `dir`, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for p in entries.flatten().map(|e| e.path()) {
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The lines of `text` that declare a unit test or a test-only module (1-based).
pub fn test_lines(text: &str) -> Vec<usize> {
    text.lines()
        .enumerate()
        .filter(|(_, l)| {
            let t = l.trim_start();
            t.starts_with("#[test]") || t.starts_with("#[cfg(test)]")
        })
        .map(|(i, _)| i + 1)
        .collect()
}

/// Every unit test in a harnessless target, as `file:line: what` (paths from `root`).
pub fn problems(root: &Path) -> Vec<String> {
    let targets = match targets(root) {
        Ok(t) => t,
        Err(e) => return vec![format!("cargo metadata: {e}")],
    };
    let mut out = Vec::new();
    for t in &targets {
        for f in &t.files {
            let Ok(text) = std::fs::read_to_string(f) else {
                continue;
            };
            let rel = f.strip_prefix(root).unwrap_or(f).display().to_string();
            for line in test_lines(&text) {
                out.push(format!(
                    "{rel}:{line}: a unit test in {}, which is built with `test = false` \
                     (it would never run: move it to the crate's tests/, or give the target \
                     its harness back)",
                    t.name
                ));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn harnessless_targets_are_read_off_the_metadata() {
        let dir = std::env::temp_dir().join(format!("xtask-harnessless-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::write(dir.join("lib.rs"), "mod sub;\n").unwrap();
        std::fs::write(dir.join("sub/a.rs"), "#[cfg(test)]\nmod t {}\n").unwrap();
        let lib = dir.join("lib.rs").display().to_string();
        let meta = serde_json::json!({"packages": [
            {"name": "p", "targets": [
                {"name": "p", "kind": ["lib"], "test": false, "src_path": lib},
                {"name": "p", "kind": ["bin"], "test": false, "src_path": "/x/main.rs"},
                {"name": "q", "kind": ["bin"], "test": true, "src_path": "/x/q.rs"},
                {"name": "b", "kind": ["bench"], "test": false, "src_path": "/x/b.rs"}
            ]}
        ]});
        let t = from_metadata(&meta);
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(t.len(), 2, "{t:?}");
        assert_eq!(t[0].name, "p/p");
        assert_eq!(t[0].files, [dir.join("lib.rs"), dir.join("sub/a.rs")]);
        assert_eq!(t[1].files, [PathBuf::from("/x/main.rs")]);
    }

    #[test]
    fn test_attributes_are_found_and_mentions_are_not() {
        let text = "fn a() {}\n    #[test]\nfn b() {}\n// #[test] in a comment\n#[cfg(test)]\n";
        assert_eq!(test_lines(text), [2, 5]);
    }

    /// The workspace as it is: every harnessless target is free of unit tests, and the targets
    /// this repository declares harnessless are found.
    #[test]
    fn the_workspace_loses_no_unit_test() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"))
            .parent()
            .expect("the workspace root");
        let names: Vec<String> = targets(root).unwrap().into_iter().map(|t| t.name).collect();
        assert!(names.contains(&"lie-sim/lie-sim".to_string()), "{names:?}");
        assert!(
            names.contains(&"lieflow-mechanics/mechanics".to_string()),
            "{names:?}"
        );
        assert_eq!(problems(root), Vec::<String>::new());
    }
}
