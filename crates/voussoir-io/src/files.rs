//! Reading models and writing outputs. Outputs are written to a temporary file beside the
//! target and renamed into place, so a failed run never leaves a partial file behind.

use std::path::Path;
use voussoir::Model;

/// An I/O or format error, one line.
#[derive(Debug)]
pub struct IoError(pub String);

impl std::fmt::Display for IoError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}
impl std::error::Error for IoError {}

impl From<voussoir::Error> for IoError {
    fn from(e: voussoir::Error) -> Self {
        IoError(e.to_string())
    }
}

/// Read a JSON model.
pub fn read_model(path: &Path) -> Result<Model, IoError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| IoError(format!("cannot read {}: {e}", path.display())))?;
    parse_model(&text).map_err(|e| IoError(format!("{}: {}", path.display(), e.0)))
}

/// Parse a JSON model (unknown fields are rejected).
pub fn parse_model(text: &str) -> Result<Model, IoError> {
    serde_json::from_str::<Model>(text).map_err(|e| IoError(format!("invalid model JSON: {e}")))
}

/// Write `bytes` to `path` atomically (temporary file + rename).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), IoError> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .ok_or_else(|| IoError(format!("{} is not a file path", path.display())))?;
    let tmp = dir.join(format!(
        ".{}.tmp{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    std::fs::write(&tmp, bytes)
        .map_err(|e| IoError(format!("cannot write {}: {e}", path.display())))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        IoError(format!("cannot write {}: {e}", path.display()))
    })
}

/// Pretty JSON with a trailing newline (deterministic for the same value).
pub fn to_json<T: serde::Serialize>(value: &T) -> Result<String, IoError> {
    let mut s = serde_json::to_string_pretty(value)
        .map_err(|e| IoError(format!("cannot serialise: {e}")))?;
    s.push('\n');
    Ok(s)
}
