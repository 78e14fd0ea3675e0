//! Output files that appear whole or not at all: written to a temporary file in the same directory,
//! renamed into place on success, removed on failure (including an early return or a panic that
//! unwinds through the guard).

use crate::error::SimError;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// A file being written to a temporary sibling of its final path.
pub struct AtomicFile {
    target: PathBuf,
    temp: PathBuf,
    committed: bool,
}

impl AtomicFile {
    /// Reserves `target`: creates its parent directories and returns the guard; the temporary path
    /// is `.<name>.<pid>.tmp` beside it.
    pub fn new(target: &Path) -> Result<Self, SimError> {
        let werr = |source| SimError::Write {
            path: target.to_path_buf(),
            source,
        };
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&parent).map_err(werr)?;
        let name = target
            .file_name()
            .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
        let temp = parent.join(format!(".{name}.{}.tmp", std::process::id()));
        Ok(Self {
            target: target.to_path_buf(),
            temp,
            committed: false,
        })
    }

    /// The temporary path to write to.
    pub fn temp_path(&self) -> &Path {
        &self.temp
    }

    /// Creates the temporary file for buffered writing.
    pub fn create(&self) -> Result<BufWriter<File>, SimError> {
        File::create(&self.temp)
            .map(BufWriter::new)
            .map_err(|source| self.write_error(source))
    }

    /// The error for a failed write to this file.
    pub fn write_error(&self, source: std::io::Error) -> SimError {
        SimError::Write {
            path: self.target.clone(),
            source,
        }
    }

    /// Flushes `writer` and renames the temporary file onto the target.
    pub fn commit_writer(self, mut writer: BufWriter<File>) -> Result<(), SimError> {
        writer.flush().map_err(|e| self.write_error(e))?;
        let file = writer
            .into_inner()
            .map_err(|e| self.write_error(e.into_error()))?;
        file.sync_all().map_err(|e| self.write_error(e))?;
        drop(file);
        self.commit()
    }

    /// Renames the (already closed) temporary file onto the target.
    pub fn commit(mut self) -> Result<(), SimError> {
        std::fs::rename(&self.temp, &self.target).map_err(|e| self.write_error(e))?;
        self.committed = true;
        Ok(())
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if !self.committed {
            // Nothing to report if the file was never created.
            let _ = std::fs::remove_file(&self.temp);
        }
    }
}

/// Writes `contents` to `path` atomically.
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

    #[test]
    fn uncommitted_file_leaves_nothing_behind() {
        let dir = std::env::temp_dir().join(format!("lie-sim-atomic-{}", std::process::id()));
        let target = dir.join("out.csv");
        {
            let f = AtomicFile::new(&target).unwrap();
            let mut w = f.create().unwrap();
            w.write_all(b"partial").unwrap();
            w.flush().unwrap();
            assert!(f.temp_path().exists());
        }
        assert!(!target.exists());
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
        write_atomic(&target, "whole").unwrap();
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "whole");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
