//! The documentation runs as written: the README's example session and the examples of
//! docs/sweep.md and docs/safety.md are taken from between their markers (`<!-- example: NAME begin … -->`,
//! `<!-- example: NAME end -->`) and run line by line with the built `voussoir` first on PATH,
//! in a temporary folder. Every line must succeed, every file a line names must be written, and
//! nothing may be written outside `out/` (which `.gitignore` covers). The README's claims about
//! the tool's flags are checked against `--help`.

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn bin() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_voussoir"))
}

/// The shell lines of the ```sh block(s) between the markers of example `name` in `file`,
/// with backslash continuations joined. Panics if the markers are missing.
fn example(file: &str, name: &str) -> Vec<String> {
    let text = std::fs::read_to_string(repo().join(file)).unwrap();
    let begin = format!("<!-- example: {name} begin");
    let end = format!("<!-- example: {name} end -->");
    let a = text
        .find(&begin)
        .unwrap_or_else(|| panic!("{file}: marker '{begin}' missing"));
    let b = text[a..]
        .find(&end)
        .unwrap_or_else(|| panic!("{file}: marker '{end}' missing"))
        + a;
    let mut lines = Vec::new();
    let mut cur = String::new();
    let mut in_code = false;
    for l in text[a..b].lines() {
        if l.trim_start().starts_with("```") {
            in_code = !in_code;
            continue;
        }
        if !in_code {
            continue;
        }
        let t = l.trim();
        if let Some(head) = t.strip_suffix('\\') {
            cur.push_str(head);
            cur.push(' ');
            continue;
        }
        cur.push_str(t);
        if !cur.trim().is_empty() && !cur.trim_start().starts_with('#') {
            lines.push(cur.trim().to_string());
        }
        cur.clear();
    }
    assert!(
        lines.len() >= 3,
        "{file}: example {name} has {} lines",
        lines.len()
    );
    lines
}

/// The files a line writes: the arguments of -o, --png, --svg, --report, --jsonl, --csv and `>`.
fn outputs(line: &str) -> Vec<String> {
    let code = line.split(" #").next().unwrap_or(line);
    let words: Vec<&str> = code.split_whitespace().collect();
    let mut out = Vec::new();
    for w in words.windows(2) {
        if [
            "-o", "--output", "--png", "--svg", "--report", "--jsonl", "--csv", "--vtk", ">",
        ]
        .contains(&w[0])
        {
            out.push(w[1].to_string());
        }
    }
    out
}

fn fresh_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-readme-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Run an example in a fresh folder; check every line, its outputs and the folder's contents.
fn run_example(file: &str, name: &str) {
    let dir = fresh_dir(name);
    let path = format!(
        "{}:{}",
        bin().parent().unwrap().display(),
        std::env::var("PATH").unwrap_or_default()
    );
    for line in example(file, name) {
        let o = Command::new("sh")
            .arg("-c")
            .arg(&line)
            .current_dir(&dir)
            .env("PATH", &path)
            .output()
            .expect("run sh");
        assert!(
            o.status.success(),
            "{file}, example {name}: `{line}` failed: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        for f in outputs(&line) {
            let p = dir.join(&f);
            let len = std::fs::metadata(&p).map(|m| m.len()).unwrap_or(0);
            assert!(len > 0, "{file}: `{line}` did not write {f}");
            assert!(
                f.starts_with("out/"),
                "{file}: `{line}` writes {f} outside out/"
            );
        }
    }
    let top: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        top,
        vec!["out".to_string()],
        "{file}: example {name} wrote {top:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

fn gitignore_covers_out() -> bool {
    std::fs::read_to_string(repo().join(".gitignore"))
        .unwrap()
        .lines()
        .any(|l| matches!(l.trim(), "/out" | "/out/" | "out" | "out/"))
}

#[test]
fn readme_example_session_runs_as_written_into_an_ignored_folder() {
    assert!(gitignore_covers_out(), ".gitignore must cover out/");
    run_example("README.md", "session");
}

#[test]
fn readme_3d_example_runs_as_written() {
    run_example("README.md", "3d");
}

#[test]
fn sweep_doc_example_runs_as_written() {
    run_example("docs/sweep.md", "sweep");
}

#[test]
fn safety_doc_example_runs_as_written() {
    run_example("docs/safety.md", "safety");
}

fn help(args: &[&str]) -> String {
    let o = Command::new(bin()).args(args).output().unwrap();
    assert!(o.status.success(), "{args:?}");
    String::from_utf8(o.stdout).unwrap()
}

#[test]
fn every_analysis_command_takes_the_drawing_and_output_flags_the_readme_claims() {
    let readme = std::fs::read_to_string(repo().join("README.md")).unwrap();
    assert!(readme.contains(
        "The analysis commands `limit`, `settle`, `tilt`, `capacity` and `incremental` all take `--svg`,"
    ));
    for cmd in ["limit", "settle", "tilt", "capacity", "incremental"] {
        let h = help(&[cmd, "--help"]);
        for flag in ["--svg", "--png", "--report", "--json", "--output"] {
            assert!(h.contains(flag), "`{cmd} --help` lacks {flag}");
        }
    }
}

#[test]
fn top_level_help_lists_every_gen_kind_and_the_sweep_doc() {
    let h = help(&["--help"]);
    assert!(h.contains("(arch, lintel, wall, facade)"), "{h}");
    assert!(h.contains("docs/sweep.md"), "{h}");
    let g = help(&["gen", "--help"]);
    for kind in ["arch", "lintel", "wall", "facade"] {
        assert!(g.contains(kind), "{g}");
    }
    assert!(Path::new(&repo().join("docs/sweep.md")).is_file());
}

#[test]
fn release_binary_is_at_most_25_mb() {
    // Tests run in the release profile (scripts/test.sh), so this is the quick start's binary.
    let len = std::fs::metadata(bin()).unwrap().len();
    assert!(
        len <= 25_000_000,
        "{} is {len} bytes (> 25 MB); tests must run with --release",
        bin().display()
    );
}
