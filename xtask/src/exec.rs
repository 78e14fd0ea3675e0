//! Running the repository's own commands: stdout captured, stderr (cargo's progress, a bench's
//! warnings) passed through to the terminal.

use crate::error::{Error, Result};
use std::path::Path;
use std::process::{Command, Stdio};

/// The cargo that runs this task (so `cargo +toolchain xtask` uses that toolchain throughout).
pub fn cargo() -> String {
    std::env::var("CARGO").unwrap_or_else(|_| "cargo".into())
}

/// Runs `program args…` in `dir` and returns its stdout; a non-zero exit is an error naming the
/// command.
pub fn stdout_of(dir: &Path, program: &str, args: &[String]) -> Result<String> {
    let shown = shell_line(program, args);
    eprintln!("xtask docs: running {shown}");
    let out = Command::new(program)
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stderr(Stdio::inherit())
        .output()
        .map_err(|e| Error::Command {
            command: shown.clone(),
            status: e.to_string(),
        })?;
    if !out.status.success() {
        return Err(Error::Command {
            command: shown,
            status: out.status.to_string(),
        });
    }
    String::from_utf8(out.stdout).map_err(|e| Error::parse(shown, e.to_string()))
}

/// `cargo args…` in `dir`.
pub fn cargo_stdout(dir: &Path, args: &[String]) -> Result<String> {
    stdout_of(dir, &cargo(), args)
}

/// The command as a reader would type it (arguments with spaces quoted).
pub fn shell_line(program: &str, args: &[String]) -> String {
    let program = if program == cargo() { "cargo" } else { program };
    std::iter::once(program.to_string())
        .chain(args.iter().map(|a| {
            if a.is_empty() || a.contains([' ', '|', '(', ')', '*', '\'']) {
                format!("'{a}'")
            } else {
                a.clone()
            }
        }))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Strings from string literals.
pub fn strings(args: &[&str]) -> Vec<String> {
    args.iter().map(|s| s.to_string()).collect()
}
