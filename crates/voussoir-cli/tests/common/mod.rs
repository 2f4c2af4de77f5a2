//! Helpers shared by the CLI's integration tests (`mod common;` in `it.rs`, once for the test
//! binary; a test file says `use crate::common::…`): run the binary in a directory or in the
//! test's own ([`cwd`]), expect success or a one-line refusal, a fresh scratch directory, parse
//! JSON. One copy instead of one per test file.
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

/// A command line's words (none of them has a space).
pub fn w(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}

/// Run `voussoir gen WORDS` in `dir` and expect success; stdout. `words` is the command line
/// after `gen`, its words apart at white space (none of them has a space).
pub fn gen_model(dir: &Path, words: &str) -> String {
    let args: Vec<&str> = std::iter::once("gen")
        .chain(words.split_whitespace())
        .collect();
    run(dir, &args)
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

/// A JSON file.
pub fn json_file(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Run in `dir` and expect a one-line refusal (any text); stderr.
pub fn refusal(dir: &Path, args: &[&str]) -> String {
    let o = voussoir(dir, args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!o.status.success(), "voussoir {args:?} succeeded");
    assert_eq!(err.trim_end().lines().count(), 1, "not one line: {err}");
    err
}

/// Run `voussoir ARGS` in the test process's own working directory (the files named by
/// absolute paths), as most test files do.
pub mod cwd {
    use serde_json::Value;
    use std::process::{Command, Output};

    /// Run; the output, whatever the status.
    pub fn run(args: &[&str]) -> Output {
        Command::new(env!("CARGO_BIN_EXE_voussoir"))
            .args(args)
            .output()
            .expect("run voussoir")
    }

    /// Run and expect success.
    pub fn ok(args: &[&str]) -> Output {
        let o = run(args);
        assert!(
            o.status.success(),
            "voussoir {args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        o
    }

    /// Run and expect success; stdout.
    pub fn ok_text(args: &[&str]) -> String {
        String::from_utf8_lossy(&ok(args).stdout).into_owned()
    }

    /// Run with `--json` and expect success; the JSON on stdout.
    pub fn ok_json(args: &[&str]) -> Value {
        let mut a = args.to_vec();
        a.push("--json");
        serde_json::from_slice(&ok(&a).stdout).unwrap()
    }

    /// Run and expect a failure with one line on stderr containing every needle; stderr.
    pub fn fails(args: &[&str], needles: &[&str]) -> String {
        let o = run(args);
        assert!(!o.status.success(), "{args:?} succeeded");
        let e = String::from_utf8_lossy(&o.stderr).into_owned();
        assert_eq!(e.trim_end().lines().count(), 1, "{args:?}: {e}");
        for n in needles {
            assert!(e.contains(n), "{args:?}: {e} (expected {n})");
        }
        e
    }
}
