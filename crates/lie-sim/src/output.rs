//! Output files written the way `cp` writes them, and never at the cost of what was there.
//!
//! - A missing path or a regular file: the data go to a temporary sibling `.<name>.<pid>.tmp`,
//!   renamed into place only once complete (the old file, if any, stays intact until then, and
//!   keeps its permissions in the new one); the temporary file is removed on failure, on an early
//!   return, on a panic that unwinds, and on SIGINT, SIGTERM or SIGHUP ([`install_signal_cleanup`]).
//!   Temporary files of processes that no longer run (a `kill -9`, a power cut) are removed by the
//!   next write into that directory.
//! - A symbolic link is followed: its target is written, the link stays a link.
//! - A FIFO or a character device (`/dev/null`, `/dev/stdout`, a terminal) is written directly: it
//!   cannot be replaced, and there is nothing to keep intact.
//! - A directory, a socket or a block device is refused ([`SimError::Output`]), and so is an
//!   existing file the caller may not write (read-only to them): as `cp` does, it is left as it
//!   is, although the directory would let the temporary file be renamed over it.
//!
//! [`refuse_clobbering`] refuses, before any work is done, an output that is one of the command's
//! inputs (the same file, by device and inode, whatever the path: a symlink or hard link to the
//! scene is caught) or the same file as another of its outputs (`--plot` equal to `--out`), and
//! every output [`AtomicFile::new`] would refuse: no command writes one output and then fails on
//! the next.

use crate::error::SimError;
use std::fs::{File, OpenOptions};
use std::io::{BufWriter, Write};
use std::os::unix::fs::{FileTypeExt, MetadataExt};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Temporary files being written, removed by the signal handler.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    // A panic while holding the lock cannot leave the list inconsistent (push/retain only).
    PENDING.lock().unwrap_or_else(|e| e.into_inner())
}

/// Installs the handler that removes every pending temporary file on SIGINT, SIGTERM and SIGHUP,
/// then exits with 128 + the signal number (the shell's convention). Call once, first thing.
pub fn install_signal_cleanup() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return; // no handler: the default action (terminate) applies, as without this function
    };
    std::thread::spawn(move || {
        if let Some(sig) = signals.forever().next() {
            for p in pending().iter() {
                let _ = std::fs::remove_file(p);
            }
            std::process::exit(128 + sig);
        }
    });
}

/// Follows symbolic links (relative ones from their own directory), at most 40 of them as the
/// kernel does; a dangling link resolves to the path it names.
fn resolve(path: &Path) -> Result<PathBuf, SimError> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let link = std::fs::read_link(&p).map_err(|source| SimError::Write {
                    path: path.to_path_buf(),
                    source,
                })?;
                p = match p.parent() {
                    Some(dir) if link.is_relative() => dir.join(link),
                    _ => link,
                };
            }
            _ => return Ok(p),
        }
    }
    Err(SimError::Output {
        path: path.to_path_buf(),
        why: "too many levels of symbolic links".into(),
    })
}

/// (device, inode) of an existing file.
fn identity(path: &Path) -> Option<(u64, u64)> {
    std::fs::metadata(path).ok().map(|m| (m.dev(), m.ino()))
}

/// The absolute form of a path that may not exist yet: its parent canonicalized, its name kept.
fn normalized(path: &Path) -> PathBuf {
    let resolved = resolve(path).unwrap_or_else(|_| path.to_path_buf());
    let parent = match resolved.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let parent = std::fs::canonicalize(&parent).unwrap_or(parent);
    match resolved.file_name() {
        Some(name) => parent.join(name),
        None => parent,
    }
}

/// Whether `path` (its symbolic links followed) is a regular file or does not exist yet — a
/// file that can be read back after it is written.
pub fn is_file_or_new(path: &Path) -> bool {
    match resolve(path).map(std::fs::metadata) {
        Ok(Ok(m)) => m.is_file(),
        Ok(Err(e)) => e.kind() == std::io::ErrorKind::NotFound,
        Err(_) => false,
    }
}

/// Refuses outputs that would overwrite an input or each other (see the module page).
pub fn refuse_clobbering(outputs: &[&Path], inputs: &[&Path]) -> Result<(), SimError> {
    for (k, out) in outputs.iter().enumerate() {
        let target = resolve(out)?;
        if let Some(id) = identity(&target) {
            if let Some(input) = inputs.iter().find(|i| identity(i) == Some(id)) {
                return Err(SimError::Output {
                    path: out.to_path_buf(),
                    why: format!("it is the input {}", input.display()),
                });
            }
        }
        for other in &outputs[..k] {
            let same = match (identity(&target), identity(other)) {
                (Some(a), Some(b)) => a == b,
                _ => normalized(out) == normalized(other),
            };
            if same {
                return Err(SimError::Output {
                    path: out.to_path_buf(),
                    why: format!("it is also the output {}", other.display()),
                });
            }
        }
        how_to_write(out, &target)?;
    }
    Ok(())
}

/// How the output `given` (its symbolic links followed: `resolved`) is written: `Some(old
/// permissions)` through a temporary sibling (`Some(None)`: a new file), `None` directly (a FIFO
/// or a character device). Refuses a directory, a socket or a block device, and an existing file
/// the caller cannot open for writing (the check `cp` makes: it opens the file without
/// truncating it, which changes nothing).
fn how_to_write(
    given: &Path,
    resolved: &Path,
) -> Result<Option<Option<std::fs::Permissions>>, SimError> {
    let refuse = |why: &str| SimError::Output {
        path: given.to_path_buf(),
        why: why.into(),
    };
    match std::fs::metadata(resolved) {
        Ok(m) if m.is_file() => match OpenOptions::new().write(true).open(resolved) {
            Ok(_) => Ok(Some(Some(m.permissions()))),
            Err(source) => Err(SimError::Write {
                path: given.to_path_buf(),
                source,
            }),
        },
        Ok(m) if m.is_dir() => Err(refuse("it is a directory")),
        Ok(m) if m.file_type().is_fifo() || m.file_type().is_char_device() => Ok(None),
        Ok(_) => Err(refuse("it is a socket or a block device")),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Some(None)),
        Err(source) => Err(SimError::Write {
            path: given.to_path_buf(),
            source,
        }),
    }
}

/// How the target is written.
enum Mode {
    /// Through a temporary sibling renamed into place; the old file's permissions, if any.
    Atomic {
        temp: PathBuf,
        permissions: Option<std::fs::Permissions>,
    },
    /// Directly (a FIFO or a character device).
    Direct,
}

/// An output being written (see the module page).
pub struct AtomicFile {
    /// The path as given (for messages).
    given: PathBuf,
    /// The path written: `given` with its symbolic links followed.
    target: PathBuf,
    mode: Mode,
    committed: bool,
}

impl AtomicFile {
    /// Reserves `target`: follows symbolic links, decides how to write it (refusing a directory,
    /// a socket, a block device or a file the caller may not write), creates the missing parent
    /// directories, and removes stale temporary files of dead processes beside it.
    pub fn new(target: &Path) -> Result<Self, SimError> {
        let given = target.to_path_buf();
        let werr = |source| SimError::Write {
            path: given.clone(),
            source,
        };
        let resolved = resolve(target)?;
        // Some(old permissions) for a regular or missing file, None for a FIFO or device.
        let atomic = how_to_write(target, &resolved)?;
        let mode = match atomic {
            None => Mode::Direct,
            Some(permissions) => {
                let parent = match resolved.parent() {
                    Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
                    _ => PathBuf::from("."),
                };
                std::fs::create_dir_all(&parent).map_err(werr)?;
                let name = resolved
                    .file_name()
                    .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
                remove_stale_temps(&parent, &name);
                Mode::Atomic {
                    temp: parent.join(format!(".{name}.{}.tmp", std::process::id())),
                    permissions,
                }
            }
        };
        if let Mode::Atomic { temp, .. } = &mode {
            pending().push(temp.clone());
        }
        Ok(Self {
            given,
            target: resolved,
            mode,
            committed: false,
        })
    }

    /// The file the data are written to now: the temporary sibling, or the FIFO/device itself.
    pub fn temp_path(&self) -> &Path {
        match &self.mode {
            Mode::Atomic { temp, .. } => temp,
            Mode::Direct => &self.target,
        }
    }

    /// Opens the file to write, buffered.
    pub fn create(&self) -> Result<BufWriter<File>, SimError> {
        let file = match &self.mode {
            Mode::Atomic { temp, .. } => File::create(temp),
            Mode::Direct => OpenOptions::new().write(true).open(&self.target),
        };
        file.map(BufWriter::new)
            .map_err(|source| self.write_error(source))
    }

    /// The error for a failed write to this file.
    pub fn write_error(&self, source: std::io::Error) -> SimError {
        SimError::Write {
            path: self.given.clone(),
            source,
        }
    }

    /// Flushes `writer` and puts the file in place.
    pub fn commit_writer(self, mut writer: BufWriter<File>) -> Result<(), SimError> {
        writer.flush().map_err(|e| self.write_error(e))?;
        let file = writer
            .into_inner()
            .map_err(|e| self.write_error(e.into_error()))?;
        if matches!(self.mode, Mode::Atomic { .. }) {
            file.sync_all().map_err(|e| self.write_error(e))?;
        }
        drop(file);
        self.commit()
    }

    /// Puts the (already closed) file in place: renames the temporary sibling onto the target,
    /// with the old file's permissions; nothing to do for a FIFO or device.
    pub fn commit(mut self) -> Result<(), SimError> {
        if let Mode::Atomic { temp, permissions } = &self.mode {
            if let Some(perm) = permissions {
                std::fs::set_permissions(temp, perm.clone()).map_err(|e| self.write_error(e))?;
            }
            std::fs::rename(temp, &self.target).map_err(|e| self.write_error(e))?;
        }
        self.committed = true;
        Ok(())
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if let Mode::Atomic { temp, .. } = &self.mode {
            if !self.committed {
                // Nothing to report if the file was never created.
                let _ = std::fs::remove_file(temp);
            }
            pending().retain(|p| p != temp);
        }
    }
}

/// Removes `.<name>.<pid>.tmp` files in `dir` whose process no longer runs (Linux: no
/// `/proc/<pid>`); a file of a running process, or any other name, is left alone.
fn remove_stale_temps(dir: &Path, name: &str) {
    if !Path::new("/proc/self").exists() {
        return; // no way to tell a dead process from a live one here
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let prefix = format!(".{name}.");
    for e in entries.flatten() {
        let file = e.file_name();
        let Some(file) = file.to_str() else { continue };
        let Some(pid) = file
            .strip_prefix(&prefix)
            .and_then(|rest| rest.strip_suffix(".tmp"))
            .and_then(|pid| pid.parse::<u32>().ok())
        else {
            continue;
        };
        if pid != std::process::id() && !Path::new("/proc").join(pid.to_string()).exists() {
            let _ = std::fs::remove_file(e.path());
        }
    }
}

/// Writes `contents` to `path` (see the module page).
pub fn write_atomic(path: &Path, contents: &str) -> Result<(), SimError> {
    let file = AtomicFile::new(path)?;
    let mut w = file.create()?;
    w.write_all(contents.as_bytes())
        .map_err(|e| file.write_error(e))?;
    file.commit_writer(w)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("lie-sim-out-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn uncommitted_file_leaves_nothing_behind() {
        let dir = dir("atomic");
        let target = dir.join("out.csv");
        {
            let f = AtomicFile::new(&target).unwrap();
            let mut w = f.create().unwrap();
            w.write_all(b"partial").unwrap();
            w.flush().unwrap();
            assert!(f.temp_path().exists());
            assert!(pending().contains(&f.temp_path().to_path_buf()));
        }
        assert!(!target.exists());
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
        write_atomic(&target, "whole").unwrap();
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "whole");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn symlinks_are_written_through_and_stay_links() {
        let dir = dir("link");
        let real = dir.join("real.csv");
        std::fs::write(&real, "old").unwrap();
        let link = dir.join("link.csv");
        std::os::unix::fs::symlink("real.csv", &link).unwrap();
        write_atomic(&link, "new").unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read_to_string(&real).unwrap(), "new");
        // A dangling link: its target is created.
        let dangling = dir.join("dangling.csv");
        std::os::unix::fs::symlink("made.csv", &dangling).unwrap();
        write_atomic(&dangling, "made").unwrap();
        assert_eq!(
            std::fs::read_to_string(dir.join("made.csv")).unwrap(),
            "made"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn permissions_of_the_old_file_are_kept() {
        use std::os::unix::fs::PermissionsExt;
        let dir = dir("perm");
        let f = dir.join("f.csv");
        std::fs::write(&f, "old").unwrap();
        std::fs::set_permissions(&f, std::fs::Permissions::from_mode(0o640)).unwrap();
        write_atomic(&f, "new").unwrap();
        let mode = std::fs::metadata(&f).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o640);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn directories_are_refused_and_devices_written_directly() {
        let dir = dir("dev");
        assert!(matches!(
            write_atomic(&dir, "x"),
            Err(SimError::Output { .. })
        ));
        write_atomic(Path::new("/dev/null"), "gone").unwrap();
        assert!(std::fs::metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn inputs_and_repeated_outputs_are_refused() {
        let dir = dir("clobber");
        let input = dir.join("in.toml");
        std::fs::write(&input, "x").unwrap();
        let hard = dir.join("hard.toml");
        std::fs::hard_link(&input, &hard).unwrap();
        let soft = dir.join("soft.toml");
        std::os::unix::fs::symlink("in.toml", &soft).unwrap();
        for out in [&input, &hard, &soft] {
            assert!(
                matches!(
                    refuse_clobbering(&[out], &[&input]),
                    Err(SimError::Output { .. })
                ),
                "{}",
                out.display()
            );
        }
        let a = dir.join("a.csv");
        let also_a = dir.join(".").join("a.csv");
        assert!(refuse_clobbering(&[&a, &also_a], &[&input]).is_err());
        assert!(refuse_clobbering(&[&a, &dir.join("a.svg")], &[&input]).is_ok());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn stale_temps_of_dead_processes_are_removed_live_ones_kept() {
        let dir = dir("stale");
        // A pid above any the kernel hands out (pid_max ≤ 2²²).
        let dead = dir.join(".t.csv.4194305.tmp");
        let live = dir.join(".t.csv.1.tmp"); // pid 1 always runs
        let other = dir.join(".u.csv.4194305.tmp");
        for f in [&dead, &live, &other] {
            std::fs::write(f, "x").unwrap();
        }
        remove_stale_temps(&dir, "t.csv");
        assert!(!dead.exists() && live.exists() && other.exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
