//! What can go wrong while regenerating or checking the docs.

use std::path::PathBuf;

/// Every failure names what failed and the value or file involved.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A command of a generator exited unsuccessfully (its stderr went to the terminal).
    #[error("`{command}` failed: {status}")]
    Command { command: String, status: String },
    /// A file could not be read, written or renamed.
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    /// A command's output or a result file does not have the expected shape.
    #[error("{what}: {detail}")]
    Parse { what: String, detail: String },
    /// The generated-region markers of a Markdown file disagree with the registry.
    #[error("{file}: {detail}")]
    Markers { file: String, detail: String },
    /// `--only` named a generator the registry does not hold.
    #[error("no generator named {name:?} (`cargo xtask docs --list` lists them)")]
    UnknownGenerator { name: String },
}

impl Error {
    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Self::Io {
            path: path.into(),
            source,
        }
    }

    pub fn parse(what: impl Into<String>, detail: impl Into<String>) -> Self {
        Self::Parse {
            what: what.into(),
            detail: detail.into(),
        }
    }
}

pub type Result<T> = std::result::Result<T, Error>;
