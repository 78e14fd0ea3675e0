//! The import graph of lie-sim's source files, drawn from the code, and the check that it has no
//! cycle.
//!
//! A node per file of `src/`; an edge A → B when A names something of B: a `use` of a path into
//! B (`crate::…`, `super::…`, `self::…`, use trees expanded), such a path in code, or a child
//! module of A's named bare (`common::SceneSystem`, or a registry row `Variant => module` whose
//! macro declares and calls the module). A `mod` declaration alone is structure, not an import.
//! Each path resolves to the deepest file it reaches (`crate::methods::spec::check` to
//! `methods/spec.rs`, `crate::methods::MethodSpec` to `methods/mod.rs`).
//!
//! The graph is written as Graphviz DOT to `<target>/tmp/lie-sim-imports.dot`
//! (`dot -Tsvg … > imports.svg` draws it).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A source file and the module path it defines (`[]` for main.rs, `["methods"]` for
/// methods/mod.rs, `["methods", "spec"]` for methods/spec.rs).
struct Source {
    name: String,
    module: Vec<String>,
    code: String,
    dir_children: Vec<String>,
}

fn sources(src: &Path) -> Vec<Source> {
    fn walk(dir: &Path, prefix: &[String], out: &mut Vec<(PathBuf, Vec<String>, bool)>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for p in entries {
            let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
            if p.is_dir() {
                let mut m = prefix.to_vec();
                m.push(stem);
                walk(&p, &m, out);
            } else if p.extension().is_some_and(|e| e == "rs") {
                let (module, is_mod) = match stem.as_str() {
                    "main" | "lib" if prefix.is_empty() => (vec![], true),
                    "mod" => (prefix.to_vec(), true),
                    _ => {
                        let mut m = prefix.to_vec();
                        m.push(stem);
                        (m, false)
                    }
                };
                out.push((p, module, is_mod));
            }
        }
    }
    let mut files = Vec::new();
    walk(src, &[], &mut files);
    files
        .iter()
        .map(|(path, module, is_mod)| {
            let dir_children = if *is_mod {
                files
                    .iter()
                    .filter(|(_, m, _)| {
                        m.len() == module.len() + 1 && m[..module.len()] == module[..]
                    })
                    .map(|(_, m, _)| m[m.len() - 1].clone())
                    .collect()
            } else {
                Vec::new()
            };
            Source {
                name: path
                    .strip_prefix(src)
                    .unwrap()
                    .to_string_lossy()
                    .replace('\\', "/"),
                module: module.clone(),
                code: inline_super(&strip_comments(&std::fs::read_to_string(path).unwrap())),
                dir_children,
            }
        })
        .collect()
}

/// The text without `//` comments (doc comments included) and without string literals.
fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    let mut in_string = false;
    while let Some(c) = chars.next() {
        if in_string {
            if c == '\\' {
                chars.next();
            } else if c == '"' {
                in_string = false;
                out.push('"');
            }
            continue;
        }
        match c {
            '"' => {
                in_string = true;
                out.push('"');
            }
            '\'' => {
                // a char literal ('x', '\n') or a lifetime ('a): skip a char literal whole
                let rest: String = chars.clone().take(3).collect();
                if rest.starts_with('\\') || rest.chars().nth(1) == Some('\'') {
                    for d in chars.by_ref() {
                        if d == '\'' {
                            break;
                        }
                    }
                    out.push_str("' '");
                } else {
                    out.push('\'');
                }
            }
            '/' if chars.peek() == Some(&'/') => {
                for d in chars.by_ref() {
                    if d == '\n' {
                        out.push('\n');
                        break;
                    }
                }
            }
            _ => out.push(c),
        }
    }
    out
}

/// The code with `super::` inside an inline module (`mod tests { use super::*; }`) read as the
/// file's own module (`self::`): there `super` is the file, not its parent.
fn inline_super(code: &str) -> String {
    let mut out = code.to_string();
    let mut from = 0;
    while let Some(i) = out[from..].find("mod ").map(|i| i + from) {
        from = i + 4;
        if i > 0 && is_ident(out[..i].chars().last().unwrap()) {
            continue;
        }
        let rest = &out[i + 4..];
        let name_len = rest.chars().take_while(|&c| is_ident(c)).count();
        let after = rest[name_len..].trim_start();
        if name_len == 0 || !after.starts_with('{') {
            continue;
        }
        let open = i + 4 + rest.len() - after.len();
        let mut depth = 0;
        let mut close = out.len();
        for (k, c) in out[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        close = open + k;
                        break;
                    }
                }
                _ => {}
            }
        }
        let body = out[open..close].replace("super::", "self::");
        out.replace_range(open..close, &body);
    }
    out
}

/// `a::{b, c::{d, e}}` as `[a::b, a::c::d, a::c::e]`.
fn expand_use(tree: &str) -> Vec<String> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    fn go(prefix: &str, t: &str, out: &mut Vec<String>) {
        match t.find('{') {
            None => out.push(format!("{prefix}{t}")),
            Some(i) => {
                let head = &t[..i];
                let inner = &t[i + 1..t.rfind('}').unwrap()];
                let mut depth = 0;
                let mut start = 0;
                let bytes: Vec<char> = inner.chars().collect();
                let mut parts = Vec::new();
                for (k, &ch) in bytes.iter().enumerate() {
                    match ch {
                        '{' => depth += 1,
                        '}' => depth -= 1,
                        ',' if depth == 0 => {
                            parts.push(bytes[start..k].iter().collect::<String>());
                            start = k + 1;
                        }
                        _ => {}
                    }
                }
                parts.push(bytes[start..].iter().collect());
                for p in parts.iter().filter(|p| !p.is_empty()) {
                    go(&format!("{prefix}{head}"), p, out);
                }
            }
        }
    }
    let mut out = Vec::new();
    go("", &tree, &mut out);
    out
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Every path starting with `crate`, `super` or `self` in the code (use trees expanded).
fn paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find("use ") {
        let before_ok = i == 0 || !is_ident(rest[..i].chars().last().unwrap());
        let after = &rest[i + 4..];
        if before_ok {
            if let Some(end) = after.find(';') {
                out.extend(expand_use(&after[..end]));
            }
        }
        rest = &rest[i + 4..];
    }
    let chars: Vec<char> = code.chars().collect();
    let mut k = 0;
    while k < chars.len() {
        if (k == 0 || !is_ident(chars[k - 1])) && chars[k].is_ascii_lowercase() {
            let mut j = k;
            let mut path = String::new();
            loop {
                let start = j;
                while j < chars.len() && is_ident(chars[j]) {
                    j += 1;
                }
                path.extend(&chars[start..j]);
                if j + 2 < chars.len()
                    && chars[j] == ':'
                    && chars[j + 1] == ':'
                    && is_ident(chars[j + 2])
                {
                    path.push_str("::");
                    j += 2;
                } else {
                    break;
                }
            }
            if ["crate::", "super::", "self::"]
                .iter()
                .any(|p| path.starts_with(p))
            {
                out.push(path);
            }
            k = j.max(k + 1);
        } else {
            k += 1;
        }
    }
    out
}

/// The file a path from `from` reaches: the deepest module on it that has a file.
fn resolve(from: &Source, path: &str, files: &BTreeMap<Vec<String>, String>) -> Option<String> {
    let segs: Vec<&str> = path.split("::").collect();
    let mut module: Vec<String> = Vec::new();
    let mut i = 0;
    match segs[0] {
        "crate" => i = 1,
        "self" => {
            module = from.module.clone();
            i = 1;
        }
        "super" => {
            // super of a file module is its parent; of a mod.rs (or main.rs) module its parent too
            module = from.module.clone();
            while i < segs.len() && segs[i] == "super" {
                module.pop();
                i += 1;
            }
        }
        _ => return None,
    }
    let mut best = files.get(&module).cloned();
    for s in &segs[i..] {
        module.push((*s).to_string());
        match files.get(&module) {
            Some(f) => best = Some(f.clone()),
            None => break,
        }
    }
    best
}

/// The edges of the graph (see the module page).
fn graph(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let sources = sources(src);
    let files: BTreeMap<Vec<String>, String> = sources
        .iter()
        .map(|s| (s.module.clone(), s.name.clone()))
        .collect();
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for s in &sources {
        let out = edges.entry(s.name.clone()).or_default();
        for p in paths(&s.code) {
            if let Some(f) = resolve(s, &p, &files) {
                out.insert(f);
            }
        }
        // Bare names of this module's children: `child::item`, or a registry row `=> child`.
        for child in &s.dir_children {
            let named = s.code.match_indices(child.as_str()).any(|(i, _)| {
                let before = s.code[..i].chars().last().unwrap_or(' ');
                let after = &s.code[i + child.len()..];
                let bare = !is_ident(before) && before != ':';
                let row = s.code[..i].trim_end().ends_with("=>");
                bare && (after.starts_with("::")
                    || (row && !after.starts_with(|c: char| is_ident(c))))
            });
            if named {
                let mut m = s.module.clone();
                m.push(child.clone());
                out.insert(files[&m].clone());
            }
        }
        out.remove(&s.name);
    }
    edges
}

/// A cycle of the graph, if it has one.
fn cycle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        n: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(n.to_string(), 1);
        stack.push(n.to_string());
        for m in edges.get(n).into_iter().flatten() {
            match state.get(m.as_str()).copied().unwrap_or(0) {
                1 => {
                    let i = stack.iter().position(|x| x == m).unwrap();
                    let mut c = stack[i..].to_vec();
                    c.push(m.clone());
                    return Some(c);
                }
                0 => {
                    if let Some(c) = visit(m, edges, state, stack) {
                        return Some(c);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(n.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for n in edges.keys() {
        if state.get(n.as_str()).copied().unwrap_or(0) == 0 {
            if let Some(c) = visit(n, edges, &mut state, &mut Vec::new()) {
                return Some(c);
            }
        }
    }
    None
}

fn dot(edges: &BTreeMap<String, BTreeSet<String>>) -> String {
    let mut s = String::from("digraph lie_sim_imports {\n  rankdir=BT;\n  node [shape=box];\n");
    for (a, bs) in edges {
        for b in bs {
            s.push_str(&format!("  \"{a}\" -> \"{b}\";\n"));
        }
    }
    s.push_str("}\n");
    s
}

#[test]
fn lie_sim_source_files_import_one_another_without_a_cycle() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let edges = graph(&src);
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("lie-sim-imports.dot");
    std::fs::write(&out, dot(&edges)).unwrap();
    eprintln!("import graph: {} ({} files)", out.display(), edges.len());
    // The graph is drawn from the code: the registries reach their rows, the scene reaches both
    // registries, and the parts of the old circles are there.
    for (a, b) in [
        ("methods/mod.rs", "methods/lie_poisson.rs"),
        ("systems/mod.rs", "systems/heavy_top.rs"),
        ("systems/mod.rs", "systems/common.rs"),
        ("scene.rs", "systems/mod.rs"),
        ("scene.rs", "methods/spec.rs"),
        ("trade.rs", "reference.rs"),
        ("methods/spec.rs", "methods/mod.rs"),
    ] {
        assert!(edges[a].contains(b), "no edge {a} → {b}: {edges:?}");
    }
    if let Some(c) = cycle(&edges) {
        panic!("an import cycle: {}", c.join(" → "));
    }
}

/// The checker finds a cycle where there is one, including through a use tree and a bare child
/// name, and none in a chain.
#[test]
fn the_cycle_check_finds_a_planted_cycle() {
    let dir = std::env::temp_dir().join(format!("lie-sim-imports-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("src/reg")).unwrap();
    let write = |p: &str, t: &str| std::fs::write(dir.join("src").join(p), t).unwrap();
    write("main.rs", "mod a;\nmod reg;\nfn main() { a::f(); }\n");
    write(
        "a.rs",
        "use crate::{reg::{row::Row}, b};\n// use crate::c;\n",
    );
    write("b.rs", "pub fn g() { let s = \"crate::a\"; }\n");
    write(
        "reg/mod.rs",
        "mod row;\nmacro_rules! m { () => {} }\nrows! { X => one, }\n",
    );
    write("reg/row.rs", "pub struct Row;\n");
    write(
        "reg/two.rs",
        "use super::row::Row;\n#[cfg(test)]\nmod tests {\n    use super::*;\n}\n",
    );
    write("reg/one.rs", "use super::row::Row;\n");
    let edges = graph(&dir.join("src"));
    assert!(edges["a.rs"].contains("reg/row.rs") && edges["a.rs"].contains("b.rs"));
    assert!(edges["main.rs"].contains("a.rs"));
    assert!(edges["reg/mod.rs"].contains("reg/one.rs"), "{edges:?}");
    assert!(!edges["b.rs"].contains("a.rs"), "a string is not an import");
    assert!(
        !edges["reg/two.rs"].contains("reg/mod.rs"),
        "super in an inline module is the file itself"
    );
    assert_eq!(cycle(&edges), None);
    write("reg/one.rs", "use super::row::Row;\nuse super::m;\n");
    let c = cycle(&graph(&dir.join("src"))).expect("reg/mod.rs ↔ reg/one.rs");
    assert!(c.contains(&"reg/one.rs".to_string()), "{c:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}
