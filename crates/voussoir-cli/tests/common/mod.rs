//! Helpers shared by the CLI's integration tests (`mod common;` in a test file): run the
//! binary in a directory, expect success or a one-line refusal, a fresh scratch directory,
//! parse JSON. One copy instead of one per test file.
#![allow(dead_code)]

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Run `voussoir ARGS` in `dir`.
pub fn voussoir(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_voussoir"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run voussoir")
}

/// Run and expect success; stdout.
pub fn run(dir: &Path, args: &[&str]) -> String {
    let o = voussoir(dir, args);
    assert!(
        o.status.success(),
        "voussoir {args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Run and expect a one-line refusal (`error: …`) containing `needle`, nothing on stdout.
pub fn refused(dir: &Path, args: &[&str], needle: &str) {
    let o = voussoir(dir, args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!o.status.success(), "voussoir {args:?} succeeded");
    assert!(o.stdout.is_empty(), "voussoir {args:?} printed to stdout");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 1, "voussoir {args:?}: not one line: {err}");
    assert!(
        lines[0].starts_with("error: ") && lines[0].contains(needle),
        "voussoir {args:?}: {err}"
    );
}

/// A fresh scratch directory, unique per test binary (`tag`) and test (`name`).
pub fn tmpdir(tag: &str, name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-{tag}-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

pub fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap()
}
