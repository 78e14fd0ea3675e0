//! Instructions per step, which the machine's load does not change: `examples/step_cost.rs` steps
//! one method n times, and `valgrind --tool=callgrind` counts the instructions of the whole
//! process for n = N and 2N; their difference over N is the cost of one step, start-up and set-up
//! cancelled.

use crate::error::{Error, Result};
use crate::exec;
use std::path::Path;

/// The two step counts of each measurement.
pub const STEPS: usize = 2000;

/// The total instruction count `Ir` of a callgrind output file (its `summary:` or `totals:` line).
pub fn total_instructions(text: &str) -> Option<u64> {
    text.lines()
        .find_map(|l| {
            l.strip_prefix("summary:")
                .or_else(|| l.strip_prefix("totals:"))
        })
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|n| n.parse().ok())
}

/// Instructions per step of `method` (a `step_cost` method id, e.g. `free/rk4`).
pub fn per_step(root: &Path, scratch: &Path, binary: &Path, method: &str) -> Result<f64> {
    let count = |n: usize| -> Result<u64> {
        let out = scratch.join(format!("callgrind.{}.{n}", method.replace('/', "_")));
        let args = vec![
            "--tool=callgrind".to_string(),
            format!("--callgrind-out-file={}", out.display()),
            binary.display().to_string(),
            method.to_string(),
            n.to_string(),
        ];
        exec::stdout_of(root, "valgrind", &args)?;
        let text = std::fs::read_to_string(&out).map_err(|e| Error::io(&out, e))?;
        total_instructions(&text)
            .ok_or_else(|| Error::parse(out.display().to_string(), "no summary line"))
    };
    let (a, b) = (count(STEPS)?, count(2 * STEPS)?);
    Ok((b as f64 - a as f64) / STEPS as f64)
}

/// | step | instructions / step | × competitor |, every method of `rows` counted now.
pub fn table(
    root: &Path,
    scratch: &Path,
    binary: &Path,
    competitor: &str,
    rows: &[&str],
) -> Result<String> {
    let base = per_step(root, scratch, binary, competitor)?;
    let mut out = format!(
        "| `step_cost` method | instructions / step | × `{competitor}` |\n|---|---:|---:|\n| `{competitor}` | {base:.0} | 1 |\n"
    );
    for m in rows {
        let n = per_step(root, scratch, binary, m)?;
        out.push_str(&format!("| `{m}` | {n:.0} | {:.2} |\n", n / base));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_total_is_read_off_the_summary_line() {
        let text = "version: 1\ncreator: callgrind\nevents: Ir\nsummary: 1234567\n";
        assert_eq!(total_instructions(text), Some(1_234_567));
        assert_eq!(total_instructions("totals: 42 7\n"), Some(42));
        assert_eq!(total_instructions("events: Ir\n"), None);
    }
}
