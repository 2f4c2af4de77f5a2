//! Reading models and writing outputs. Outputs are written to a temporary file beside the
//! target and renamed into place, so a failed run never leaves a partial file behind; several
//! outputs of one run are committed all or nothing ([`write_all_or_nothing`]).

use std::path::{Path, PathBuf};
use voussoir::Model;

/// An I/O or format error, one line.
#[derive(Debug)]
pub struct IoError(pub String);

impl std::fmt::Display for IoError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&voussoir::error::one_line(&self.0))
    }
}

impl IoError {
    /// The message on one line (control characters from the user's file written as escapes):
    /// every public reader returns its errors through this.
    pub fn one_line(self) -> IoError {
        match voussoir::error::one_line(&self.0) {
            std::borrow::Cow::Borrowed(_) => self,
            std::borrow::Cow::Owned(s) => IoError(s),
        }
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
    parse_model(&text).map_err(|e| IoError(format!("{}: {}", path.display(), e.0)).one_line())
}

/// Read a JSON model of either dimension (3D when its blocks have `vertices`).
pub fn read_any_model(path: &Path) -> Result<voussoir::model3d::AnyModel, IoError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| IoError(format!("cannot read {}: {e}", path.display())))?;
    unique_keys(&text)
        .map_err(|e| IoError(format!("{}: invalid model JSON: {e}", path.display())))?;
    voussoir::model3d::AnyModel::from_json(&text)
        .map_err(|e| IoError(format!("{}: invalid model JSON: {e}", path.display())).one_line())
}

/// Parse a JSON model (unknown fields and duplicate keys are rejected).
pub fn parse_model(text: &str) -> Result<Model, IoError> {
    unique_keys(text).map_err(|e| IoError(format!("invalid model JSON: {e}")).one_line())?;
    serde_json::from_str::<Model>(text)
        .map_err(|e| IoError(format!("invalid model JSON: {e}")).one_line())
}

/// Check that no JSON object in `text` has a key twice (at any depth: a material named twice
/// as well as a field given twice), so that every reader — `limit`, `plot`, the 3D reader —
/// refuses what one refuses; the error names the key, line and column.
pub fn unique_keys(text: &str) -> Result<(), serde_json::Error> {
    use serde::de::{Deserializer, MapAccess, SeqAccess, Visitor};
    struct Unique;
    impl<'de> serde::Deserialize<'de> for Unique {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            d.deserialize_any(UniqueVisitor)
        }
    }
    struct UniqueVisitor;
    impl<'de> Visitor<'de> for UniqueVisitor {
        type Value = Unique;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("any JSON value")
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Unique, A::Error> {
            let mut seen = std::collections::HashSet::new();
            while let Some(key) = map.next_key::<String>()? {
                if !seen.insert(key.clone()) {
                    return Err(serde::de::Error::custom(format!("duplicate key `{key}`")));
                }
                map.next_value::<Unique>()?;
            }
            Ok(Unique)
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Unique, A::Error> {
            while seq.next_element::<Unique>()?.is_some() {}
            Ok(Unique)
        }
        fn visit_bool<E>(self, _: bool) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_i64<E>(self, _: i64) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_u64<E>(self, _: u64) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_f64<E>(self, _: f64) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_str<E>(self, _: &str) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_unit<E>(self) -> Result<Unique, E> {
            Ok(Unique)
        }
    }
    let mut d = serde_json::Deserializer::from_str(text);
    serde::Deserialize::deserialize(&mut d).map(|_: Unique| ())
}

/// Where the bytes for `path` really go: a symbolic link is written through (its target is
/// replaced, the link stays), and an existing target that is not a regular file (a device such
/// as `/dev/full`, a directory, a pipe) is refused — replacing it by a regular file would
/// damage the system.
fn resolve_target(path: &Path) -> Result<PathBuf, IoError> {
    let mut target = path.to_path_buf();
    // Follow a chain of links (bounded, against loops).
    for _ in 0..40 {
        match std::fs::symlink_metadata(&target) {
            Ok(m) if m.file_type().is_symlink() => {
                let link = std::fs::read_link(&target).map_err(|e| {
                    IoError(format!("cannot read the link {}: {e}", target.display()))
                })?;
                target = match target.parent() {
                    Some(dir) if link.is_relative() => dir.join(link),
                    _ => link,
                };
            }
            Ok(m) if !m.file_type().is_file() => {
                return Err(IoError(format!(
                    "refusing to write {}: it exists and is not a regular file",
                    path.display()
                )))
            }
            _ => return Ok(target),
        }
    }
    Err(IoError(format!(
        "cannot write {}: too many levels of links",
        path.display()
    )))
}

/// A temporary file beside a target, removed unless it was renamed into place.
struct Staged {
    tmp: PathBuf,
    target: PathBuf,
    shown: PathBuf,
    done: bool,
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.done {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

/// Write `bytes` to a temporary file beside the (resolved) target, with the target's
/// permissions if it exists.
fn stage(path: &Path, bytes: &[u8]) -> Result<Staged, IoError> {
    let target = resolve_target(path)?;
    let dir = target
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = target
        .file_name()
        .ok_or_else(|| IoError(format!("{} is not a file path", path.display())))?;
    let tmp = dir.join(format!(
        ".{}.tmp{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let staged = Staged {
        tmp,
        target: target.clone(),
        shown: path.to_path_buf(),
        done: false,
    };
    let fail = |e: std::io::Error| IoError(format!("cannot write {}: {e}", path.display()));
    {
        use std::io::Write;
        let mut f = std::fs::File::create(&staged.tmp).map_err(fail)?;
        f.write_all(bytes).map_err(fail)?;
        f.sync_all().map_err(fail)?;
    }
    if let Ok(m) = std::fs::metadata(&target) {
        std::fs::set_permissions(&staged.tmp, m.permissions()).map_err(fail)?;
    }
    Ok(staged)
}

/// Write `bytes` to `path` atomically (temporary file + rename): a failed run leaves neither a
/// partial file nor a temporary one, a link is written through, a file keeps its permissions,
/// and a device or directory is never replaced.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), IoError> {
    write_all_or_nothing(&[(path, bytes)], &[])
}

/// Write several outputs all or nothing: every one is staged first, and only when all are
/// staged are they renamed into place. An output that names one of `inputs` (the same file,
/// through links too) is refused before anything is written.
pub fn write_all_or_nothing(outputs: &[(&Path, &[u8])], inputs: &[&Path]) -> Result<(), IoError> {
    let same = |a: &Path, b: &Path| match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    };
    for (p, _) in outputs {
        if let Some(i) = inputs.iter().find(|i| same(p, i)) {
            return Err(IoError(format!(
                "refusing to write {}: it is the input {}",
                p.display(),
                i.display()
            )));
        }
    }
    for (k, (p, _)) in outputs.iter().enumerate() {
        if outputs[..k].iter().any(|(q, _)| q == p || same(p, q)) {
            return Err(IoError(format!("{} is named as two outputs", p.display())));
        }
    }
    let mut staged = Vec::with_capacity(outputs.len());
    for (p, bytes) in outputs {
        staged.push(stage(p, bytes)?);
    }
    for s in staged.iter_mut() {
        std::fs::rename(&s.tmp, &s.target)
            .map_err(|e| IoError(format!("cannot write {}: {e}", s.shown.display())))?;
        s.done = true;
    }
    Ok(())
}

/// Pretty JSON with a trailing newline (deterministic for the same value).
pub fn to_json<T: serde::Serialize>(value: &T) -> Result<String, IoError> {
    let mut s = serde_json::to_string_pretty(value)
        .map_err(|e| IoError(format!("cannot serialise: {e}")))?;
    s.push('\n');
    Ok(s)
}
