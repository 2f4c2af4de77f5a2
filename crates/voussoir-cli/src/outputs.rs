//! Every file a command writes is staged here and committed once, after the command has
//! succeeded: several outputs (`-o`, `--svg`, `--png`, `--report`, `--jsonl`, `--csv`) are
//! written all or nothing, and an output that names one of the command's inputs is refused
//! before anything is written ([`voussoir_io::write_all_or_nothing`]).

use crate::common::Fail;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

static PENDING: Mutex<Vec<(PathBuf, Vec<u8>)>> = Mutex::new(Vec::new());
static INPUTS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Stage `bytes` for `path`.
pub fn stage(path: &Path, bytes: &[u8]) -> Result<(), Fail> {
    PENDING
        .lock()
        .map_err(|_| Fail("internal error: output list poisoned".into()))?
        .push((path.to_path_buf(), bytes.to_vec()));
    Ok(())
}

/// Remember that the command reads `path`.
pub fn input(path: &Path) {
    if let Ok(mut v) = INPUTS.lock() {
        v.push(path.to_path_buf());
    }
}

/// Write every staged output, all or nothing.
pub fn commit() -> Result<(), Fail> {
    let pending = std::mem::take(
        &mut *PENDING
            .lock()
            .map_err(|_| Fail("internal error: output list poisoned".into()))?,
    );
    let inputs = INPUTS.lock().map(|v| v.clone()).unwrap_or_default();
    let outs: Vec<(&Path, &[u8])> = pending
        .iter()
        .map(|(p, b)| (p.as_path(), b.as_slice()))
        .collect();
    let ins: Vec<&Path> = inputs.iter().map(|p| p.as_path()).collect();
    voussoir_io::write_all_or_nothing(&outs, &ins).map_err(|e| Fail(e.0))
}
