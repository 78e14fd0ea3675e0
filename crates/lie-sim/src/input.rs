//! Input files read the one way every command reads them: a regular file (its symbolic links
//! followed), at most [`MAX_INPUT_BYTES`] of it. A character device (`/dev/zero`), a FIFO, a
//! socket or a directory is refused before it is opened — reading one would wait for a writer or
//! never end — and a file beyond the cap is refused, not read into memory.

use crate::error::SimError;
use std::io::{Error, ErrorKind, Read};
use std::os::unix::fs::FileTypeExt;
use std::path::Path;

/// The largest input read, in bytes: [`crate::bounds::MAX_BYTES`], what a command writes
/// without `--allow-large` (so every file `lie-sim` writes by default can be read back: a
/// trajectory to plot, a shard to merge, a reference); a scene is far smaller.
pub const MAX_INPUT_BYTES: u64 = crate::bounds::MAX_BYTES as u64;

/// What the file at `path` is, when it is not a regular file.
fn kind(m: &std::fs::Metadata) -> Option<&'static str> {
    let t = m.file_type();
    if t.is_file() {
        None
    } else if t.is_dir() {
        Some("a directory")
    } else if t.is_fifo() {
        Some("a FIFO")
    } else if t.is_char_device() {
        Some("a character device")
    } else if t.is_block_device() {
        Some("a block device")
    } else if t.is_socket() {
        Some("a socket")
    } else {
        Some("not a regular file")
    }
}

/// The text of the regular file at `path`, refused ([`SimError::Read`], naming the path) when it
/// is not a regular file, exceeds [`MAX_INPUT_BYTES`], or is not UTF-8.
pub fn read_text(path: &Path) -> Result<String, SimError> {
    let refuse = |source: Error| SimError::Read {
        path: path.to_path_buf(),
        source,
    };
    let check = |m: &std::fs::Metadata| -> Result<(), SimError> {
        if let Some(k) = kind(m) {
            return Err(refuse(Error::new(
                ErrorKind::InvalidInput,
                format!("it is {k}, not a regular file"),
            )));
        }
        if m.len() > MAX_INPUT_BYTES {
            return Err(too_large(path, m.len()));
        }
        Ok(())
    };
    // Before opening: opening a FIFO waits for a writer.
    check(&std::fs::metadata(path).map_err(refuse)?)?;
    let file = std::fs::File::open(path).map_err(refuse)?;
    // Again on the opened file (the path may have been replaced in between).
    check(&file.metadata().map_err(refuse)?)?;
    let mut text = String::new();
    file.take(MAX_INPUT_BYTES + 1)
        .read_to_string(&mut text)
        .map_err(refuse)?;
    if text.len() as u64 > MAX_INPUT_BYTES {
        return Err(too_large(path, text.len() as u64));
    }
    Ok(text)
}

fn too_large(path: &Path, len: u64) -> SimError {
    SimError::Read {
        path: path.to_path_buf(),
        source: Error::new(
            ErrorKind::InvalidInput,
            format!(
                "{len} bytes or more, beyond the input limit of {MAX_INPUT_BYTES} bytes ({} GiB)",
                MAX_INPUT_BYTES >> 30
            ),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_regular_files_are_refused_by_name() {
        for (p, k) in [("/dev/zero", "character device"), ("/", "directory")] {
            let e = read_text(Path::new(p)).unwrap_err().to_string();
            assert!(e.contains(p) && e.contains(k), "{e}");
        }
    }
}
