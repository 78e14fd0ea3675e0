//! `cargo xtask docs --check`: the docs state what holds now.
//!
//! - Every generated region of README.md and docs/*.md names a generator and region the registry
//!   holds, and every region the registry declares is in its file.
//! - No prose line dates a figure: no commit id (7–40 hex digits with a digit and a letter), no
//!   calendar date, no "this session", "at commit", "earlier the same day". History is in git.
//! - No comment line of the Rust sources quotes a timing (`54 ns`, `0.6 µs`) or an instruction
//!   count: the benches and docs/benchmarks.md hold the numbers, comments say why.
//! - No unit test sits in a target built without its test harness (`test = false`), where it
//!   would never run ([`crate::harnessless`]).

use crate::region;
use crate::registry;
use std::path::{Path, PathBuf};

/// Phrases that date a statement rather than state what holds.
const DIARY: &[&str] = &[
    "this session",
    "this round",
    "at commit",
    "earlier the same day",
    "the previous run",
    "re-measured on",
    "rerun on",
    "re-run on",
];

/// The Markdown files whose figures must be generated: README.md and docs/*.md.
pub fn markdown_files(root: &Path) -> Vec<PathBuf> {
    let mut files = vec![root.join("README.md")];
    if let Ok(entries) = std::fs::read_dir(root.join("docs")) {
        let mut docs: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|e| e == "md"))
            .collect();
        docs.sort();
        files.extend(docs);
    }
    files
}

/// Every problem of the repository's docs and comments, as `file:line: what` lines.
pub fn check(root: &Path) -> Vec<String> {
    let mut problems = Vec::new();
    let gens = registry::all();
    let declared: Vec<(&str, region::Key)> = gens
        .iter()
        .flat_map(|g| {
            g.regions()
                .into_iter()
                .map(move |a| (a.file, region::Key::new(g.name, a.part)))
        })
        .collect();
    for path in markdown_files(root) {
        let rel = path
            .strip_prefix(root)
            .unwrap_or(&path)
            .to_string_lossy()
            .replace('\\', "/");
        let Ok(text) = std::fs::read_to_string(&path) else {
            problems.push(format!("{rel}: cannot be read"));
            continue;
        };
        match region::parse(&text) {
            Err(e) => problems.push(format!("{rel}: {e}")),
            Ok(regions) => {
                for r in &regions {
                    if !declared.iter().any(|(f, k)| *f == rel && *k == r.key) {
                        let known = gens.iter().any(|g| g.name == r.key.name);
                        problems.push(format!(
                            "{rel}:{}: region {} names {}",
                            r.start + 1,
                            r.key,
                            if known {
                                "a region its generator does not write in this file"
                            } else {
                                "no generator (`cargo xtask docs --list`)"
                            }
                        ));
                    }
                }
                for r in &regions {
                    if let Some(problem) = stale_source(root, &gens, &text, r) {
                        problems.push(format!("{rel}:{}: {problem}", r.start + 1));
                    }
                }
                for (f, k) in declared.iter().filter(|(f, _)| *f == rel) {
                    if !regions.iter().any(|r| &r.key == k) {
                        problems.push(format!(
                            "{f}: the region {k} is missing (`{}`)",
                            region::start_marker(k)
                        ));
                    }
                }
            }
        }
        problems.extend(
            diary(&text)
                .into_iter()
                .map(|(line, what)| format!("{rel}:{line}: {what}")),
        );
    }
    for (rel, text) in rust_sources(root) {
        for (i, line) in text.lines().enumerate() {
            let t = line.trim_start();
            if t.starts_with("//") {
                if let Some(what) = timing(t) {
                    problems.push(format!("{rel}:{}: a comment quotes {what}", i + 1));
                }
            }
        }
    }
    problems.extend(crate::harnessless::problems(root));
    // Declared regions in files that do not exist.
    for (f, k) in &declared {
        if !root.join(f).exists() {
            problems.push(format!(
                "{f}: missing, but the registry writes its region {k}"
            ));
        }
    }
    problems
}

/// For a region that shows a source file (`How::Source`), what is wrong if it no longer shows the
/// file as it is.
fn stale_source(
    root: &Path,
    gens: &[registry::Generator],
    text: &str,
    r: &region::Region,
) -> Option<String> {
    let g = gens.iter().find(|g| g.name == r.key.name)?;
    let registry::How::Source { file, .. } = g.how else {
        return None;
    };
    let shown: Vec<&str> = text
        .lines()
        .skip(r.start + 1)
        .take(r.end - r.start - 1)
        .collect();
    match crate::generate::source_block(root, file) {
        Err(e) => Some(format!("{file} cannot be read: {e}")),
        Ok(block) if block.lines().eq(shown.iter().copied()) => None,
        Ok(_) => Some(format!(
            "region {} differs from {file} (`cargo xtask docs --only {}`)",
            r.key, g.name
        )),
    }
}

/// The prose of a Markdown text, line by line: fenced code blocks blanked, inline code spans and
/// HTML comments removed.
fn prose(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut fence = false;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim_start();
        if t.starts_with("```") || t.starts_with("~~~") {
            fence = !fence;
            continue;
        }
        if fence || t.starts_with("<!--") {
            continue;
        }
        let mut s = String::new();
        for (j, piece) in line.split('`').enumerate() {
            if j % 2 == 0 {
                s.push_str(piece);
                s.push(' ');
            }
        }
        out.push((i + 1, s));
    }
    out
}

/// A word that reads as a commit id: 7–40 lowercase hex digits, with a digit and a letter.
fn is_commit_id(w: &str) -> bool {
    (7..=40).contains(&w.len())
        && w.chars()
            .all(|c| c.is_ascii_digit() || ('a'..='f').contains(&c))
        && w.chars().any(|c| c.is_ascii_digit())
        && w.chars().any(|c| c.is_ascii_alphabetic())
}

/// `YYYY-MM-DD`.
fn is_date(w: &str) -> bool {
    let b = w.as_bytes();
    b.len() == 10
        && b[4] == b'-'
        && b[7] == b'-'
        && b.iter()
            .enumerate()
            .all(|(i, c)| i == 4 || i == 7 || c.is_ascii_digit())
}

/// The dated statements of a Markdown text: (line, what).
pub fn diary(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (n, line) in prose(text) {
        for w in line.split(|c: char| !c.is_ascii_alphanumeric()) {
            if is_commit_id(w) {
                found.push((
                    n,
                    format!(
                        "a commit id ({w}): history belongs in git, the docs state what holds now"
                    ),
                ));
            }
        }
        for w in line.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-')) {
            if is_date(w) {
                found.push((n, format!("a date ({w}): the docs state what holds now")));
            }
        }
        let lower = line.to_lowercase();
        for p in DIARY {
            if lower.contains(p) {
                found.push((n, format!("\"{p}\": the docs state what holds now")));
            }
        }
    }
    found
}

/// A timing or instruction count quoted in a comment line: `54 ns`, `0.6 µs`, `1065 instructions`.
pub fn timing(line: &str) -> Option<String> {
    let chars: Vec<char> = line.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if chars[i].is_ascii_digit() && (i == 0 || !chars[i - 1].is_alphanumeric()) {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            let number: String = chars[start..i].iter().collect();
            let mut j = i;
            if j < chars.len() && chars[j] == ' ' {
                j += 1;
            }
            let rest: String = chars[j..].iter().collect();
            for unit in ["ns", "µs", "instructions", "instruction"] {
                if let Some(after) = rest.strip_prefix(unit) {
                    if !after.starts_with(char::is_alphanumeric) {
                        return Some(format!("a measurement ({number} {unit})"));
                    }
                }
            }
        } else {
            i += 1;
        }
    }
    None
}

/// Every `.rs` file of the workspace's sources (crates, benches, examples, src, tests, xtask),
/// as (path from the root, text).
fn rust_sources(root: &Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut stack: Vec<PathBuf> = ["crates", "benches", "examples", "src", "tests"]
        .iter()
        .map(|d| root.join(d))
        .collect();
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                if let Ok(text) = std::fs::read_to_string(&p) {
                    let rel = p
                        .strip_prefix(root)
                        .unwrap_or(&p)
                        .to_string_lossy()
                        .replace('\\', "/");
                    out.push((rel, text));
                }
            }
        }
    }
    out.sort();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commit_dated_figures_and_dates_are_found_in_prose_only() {
        let text = "The ratio is 0.51 (0.70 at bb9bc95).\n\
                    Rerun on 2026-11-26 on the idle machine.\n\
                    In this session it moved.\n\
                    `git show 8c53dba` in code is not prose.\n\
                    ```text\n\
                    fingerprint = 4e1dfe5bd866db05\n\
                    ```\n\
                    1000000 steps and 3628800 are numbers; decade and facade are words.\n";
        let found = diary(text);
        let lines: Vec<usize> = found.iter().map(|(l, _)| *l).collect();
        assert_eq!(lines, [1, 2, 2, 3], "{found:?}");
        assert!(found[0].1.contains("bb9bc95"));
    }

    #[test]
    fn timings_in_comments_are_found_and_other_numbers_are_not() {
        assert!(timing("// 54 → 48 ns, θ = ½").is_some());
        assert!(timing("/// each exact flow costs 0.6 µs").is_some());
        assert!(timing("//! 1065 instructions per step").is_some());
        assert!(timing("// 10⁹ steps, order 4, 1e-13").is_none());
        assert!(timing("// a budget of 1 ms for the reference").is_none());
        assert!(timing("// h = 0.01 (ns per step: see the benches)").is_none());
        assert!(timing("// the v2ns field").is_none());
    }

    #[test]
    fn a_region_naming_no_generator_and_a_missing_declared_region_are_found() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/xtask-tests/check");
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(root.join("docs")).unwrap();
        std::fs::write(
            root.join("README.md"),
            "<!-- generated by: cargo xtask docs --only no-such-generator -->\n<!-- end generated -->\n\
             <!-- generated by: cargo xtask docs --only trade-fast-heavy-top (no-such-part) -->\n<!-- end generated -->\n",
        )
        .unwrap();
        let problems = check(&root).join("\n");
        assert!(
            problems.contains("README.md:1: region no-such-generator names no generator"),
            "{problems}"
        );
        assert!(problems.contains("README.md:3: region trade-fast-heavy-top (no-such-part) names a region its generator does not write"), "{problems}");
        assert!(
            problems.contains("README.md: the region trade-free-rigid-body (free-body) is missing"),
            "{problems}"
        );
        assert!(
            problems.contains("docs/work-precision.md: missing, but the registry writes"),
            "{problems}"
        );
    }

    /// The repository as it is: every region known, no dated figure, no timing in a comment.
    #[test]
    fn the_repository_docs_state_what_holds_now() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"))
            .parent()
            .expect("the workspace root");
        let problems = check(root);
        assert!(
            problems.is_empty(),
            "cargo xtask docs --check:\n{}",
            problems.join("\n")
        );
    }
}
