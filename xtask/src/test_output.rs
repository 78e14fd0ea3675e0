//! What tests print with `--nocapture --test-threads 1`, grouped by test: the figures of
//! docs/results.md and docs/vehicles.md are the tests' own printed lines.

/// Each test that printed something, with its lines, in the order the tests ran.
pub fn by_test(stdout: &str) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    for line in stdout.lines() {
        if let Some(rest) = line.strip_prefix("test ") {
            if let Some((name, after)) = rest.split_once(" ... ") {
                out.push((name.trim().to_string(), Vec::new()));
                push_output(&mut out, after);
                continue;
            }
        }
        if line.starts_with("running ")
            || line.starts_with("test result:")
            || line.starts_with("successes:")
            || line.starts_with("failures:")
        {
            continue;
        }
        push_output(&mut out, line);
    }
    out.retain(|(_, lines)| !lines.is_empty());
    out
}

/// One line of a test's output. A test's printed lines end with a newline, so libtest's verdict
/// (`ok`, `ignored`, `FAILED`) comes on a line of its own, or right after `test NAME ... ` when
/// the test printed nothing; either way it is dropped.
fn push_output(out: &mut [(String, Vec<String>)], line: &str) {
    let Some((_, lines)) = out.last_mut() else {
        return;
    };
    let line = line.trim_end();
    if line.is_empty() || ["ok", "ignored", "FAILED"].contains(&line) {
        return;
    }
    lines.push(line.to_string());
}

/// The tests' lines as a text block: each test's name, then its lines indented.
pub fn render(tests: &[(String, Vec<String>)]) -> String {
    let mut out = String::from("```text\n");
    for (name, lines) in tests {
        out.push_str(name);
        out.push('\n');
        for l in lines {
            out.push_str("  ");
            out.push_str(l);
            out.push('\n');
        }
    }
    out.push_str("```\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_grouped_under_the_test_that_printed_them() {
        let out = "\nrunning 3 tests\n\
            test order::a ... a: order 2.000\n\
            b: order 1.001\n\
            ok\n\
            test order::quiet ... ok\n\
            test order::c ... c: error 1e-3\n\
            ok\n\
            \n\
            test result: ok. 3 passed; 0 failed\n";
        let t = by_test(out);
        assert_eq!(t.len(), 2);
        assert_eq!(t[0].0, "order::a");
        assert_eq!(t[0].1, ["a: order 2.000", "b: order 1.001"]);
        assert_eq!(t[1].1, ["c: error 1e-3"]);
        assert_eq!(render(&t[1..]), "```text\norder::c\n  c: error 1e-3\n```\n");
    }

    #[test]
    fn a_line_ending_in_ok_is_kept_whole() {
        let t = by_test("test a ... the outlook\nok\n");
        assert_eq!(t[0].1, ["the outlook"]);
    }
}
