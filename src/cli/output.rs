//! Text → a file or standard output (a closed pipe downstream is not an error).

use super::error::CliError;
use super::format::is_std;
use std::io::{ErrorKind, Write};
use std::path::Path;

/// Write `text` to `path` (`None` or `-`: standard output).
pub fn write_text(path: Option<&Path>, text: &str) -> Result<(), CliError> {
    write_bytes(path, text.as_bytes())
}

/// Write `bytes` to `path` (`None` or `-`: standard output).
pub fn write_bytes(path: Option<&Path>, bytes: &[u8]) -> Result<(), CliError> {
    let (name, written) = match path.filter(|p| !is_std(p)) {
        Some(p) => (format!("`{}`", p.display()), std::fs::write(p, bytes)),
        None => {
            let mut out = std::io::stdout().lock();
            let written = out.write_all(bytes).and_then(|()| out.flush());
            let ignore_closed_pipe = match written {
                Err(e) if e.kind() == ErrorKind::BrokenPipe => Ok(()),
                other => other,
            };
            ("standard output".to_string(), ignore_closed_pipe)
        }
    };
    written.map_err(|source| CliError::Write { name, source })
}
