//! What can go wrong on the command line, each naming what and where, and its exit status.

use crate::io::mesh::MeshError;
use crate::io::stl::NotF32;
use crate::io::wkb::WkbError;
use crate::io::{ParseError, WriteError};
use std::process::ExitCode;

/// The kernel's reason why an input is not a Yin set (a 2D `YinError` or a 3D `Yin3Error`).
pub type Reason = Box<dyn std::error::Error + Send + Sync>;

/// A failure of the `yinset` command.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Wrong usage: conflicting or incomplete options.
    #[error("{0}")]
    Usage(String),
    /// A file or standard input could not be read.
    #[error("cannot read {name}: {source}")]
    Read {
        /// The file or stream, as the user named it.
        name: String,
        /// The underlying error.
        source: std::io::Error,
    },
    /// An input longer than `--max-bytes`.
    #[error("{name} is larger than {limit} bytes, the limit of --max-bytes: not read")]
    TooLarge {
        /// The file or stream, as the user named it.
        name: String,
        /// The limit in force.
        limit: u64,
    },
    /// A file or standard output could not be written.
    #[error("cannot write {name}: {source}")]
    Write {
        /// The file or stream, as the user named it.
        name: String,
        /// The underlying error.
        source: std::io::Error,
    },
    /// Malformed text.
    #[error("{name}: {source}")]
    Parse {
        /// The file or stream, as the user named it.
        name: String,
        /// The underlying error.
        source: ParseError,
    },
    /// Malformed WKB (binary or hex).
    #[error("{name}: {format}: {source}")]
    Wkb {
        /// The file or stream, as the user named it.
        name: String,
        /// The format concerned.
        format: &'static str,
        /// The underlying error.
        source: WkbError,
    },
    /// A malformed mesh file (text or binary).
    #[error("{name}: {source}")]
    Mesh {
        /// The file or stream, as the user named it.
        name: String,
        /// The underlying error.
        source: MeshError,
    },
    /// A set that the output format cannot hold exactly.
    #[error(transparent)]
    NotF32(#[from] NotF32),
    /// Well-formed text whose curves (or faces) do not bound a Yin set.
    #[error("{name} is not a Yin set: {source}{note}")]
    Invalid {
        /// The file or stream, as the user named it.
        name: String,
        /// The underlying error.
        source: Reason,
        /// What to do about it, or empty.
        note: String,
    },
    /// Float mode: an input that the tolerance asked for cannot serve (too fine for the
    /// coordinates' magnitude, or so coarse that the input vanishes on its grid): ε is at fault,
    /// not the input.
    #[error("{name} cannot be read with this tolerance: {source}{hint}")]
    Tolerance {
        /// The input, as the user named it.
        name: String,
        /// What the kernel found.
        source: Reason,
        /// What ε would serve, or empty.
        hint: String,
    },
    /// An operation without a valid result in the chosen mode (3D float mode: the exact result
    /// rounded to `f64` is not a valid boundary).
    #[error("{0}")]
    Operation(String),
    /// An unbounded set asked for in a format of bounded polygons.
    #[error("the set is unbounded (it contains everything far enough out), so it cannot be written as {format} polygons: write yin2 instead (--to yin2)")]
    Unbounded {
        /// The format concerned.
        format: &'static str,
    },
    /// A result the output format cannot spell in the asked number style.
    #[error("cannot write the result as {format}: {source}")]
    Unwritable {
        /// The format concerned.
        format: &'static str,
        /// The underlying error.
        source: WriteError,
    },
    /// Some random axiom checks failed.
    #[error("{failed} of {total} axiom checks failed")]
    AxiomsFailed {
        /// The checks that failed.
        failed: u64,
        /// The checks run.
        total: u64,
    },
}

impl CliError {
    /// The exit status: 2 for wrong usage, 1 for everything else.
    pub fn exit_code(&self) -> ExitCode {
        match self {
            CliError::Usage(_) => ExitCode::from(2),
            _ => ExitCode::FAILURE,
        }
    }
}
