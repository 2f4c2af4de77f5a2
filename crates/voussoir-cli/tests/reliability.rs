//! Issue 19 through the command line: one test per defect found by trying voussoir as a careful
//! user would, named after it (the library-level ones are in `crates/voussoir/tests/
//! regressions.rs`, the file-safety ones in `files.rs`). `scripts/reliability.sh` tries the
//! same classes of bad input many times over and writes docs/reliability.md.

use crate::common;
use crate::common::cwd::run;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("rel", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn arch(dir: &Path) -> PathBuf {
    let m = dir.join("arch.json");
    assert!(run(&["gen", "arch", "--live", "full", "-o", s(&m)])
        .status
        .success());
    m
}

/// A failed run: non-zero exit, not a panic (101), one line on stderr; returns it.
fn one_error_line(o: &Output) -> String {
    let e = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!o.status.success() && o.status.code() != Some(101), "{e}");
    assert!(!e.contains("panicked"), "{e}");
    assert_eq!(e.trim_end().lines().count(), 1, "{e}");
    e
}

#[test]
fn plot_refuses_a_duplicate_key_that_limit_refuses() {
    let d = tmpdir("dup");
    let m = arch(&d);
    let text = std::fs::read_to_string(&m).unwrap();
    let dup = d.join("dup.json");
    std::fs::write(
        &dup,
        text.replacen(
            "\"blocks\"",
            "\"tolerance\": 1e-7, \"tolerance\": 1e-6, \"blocks\"",
            1,
        ),
    )
    .unwrap();
    let svg = d.join("dup.svg");
    for args in [vec!["limit", s(&dup)], vec!["plot", s(&dup), "-o", s(&svg)]] {
        let e = one_error_line(&run(&args));
        assert!(
            e.contains("duplicate") && e.contains("tolerance"),
            "{args:?}: {e}"
        );
    }
    assert!(!svg.exists());
    // A saved result with a key twice: refused as well (a JSON value keeps the last silently).
    let res = d.join("limit.json");
    assert!(run(&["limit", s(&m), "-o", s(&res)]).status.success());
    let text = std::fs::read_to_string(&res).unwrap();
    std::fs::write(
        &res,
        text.replacen("\"status\"", "\"message\": \"x\", \"status\"", 1),
    )
    .unwrap();
    let e = one_error_line(&run(&["plot", s(&res), "-o", s(&svg)]));
    assert!(e.contains("duplicate key `message`"), "{e}");
}

/// A 400 mm × 1000 mm block on a base, drawn in millimetres, with `$INSUNITS` = 6 (metres).
fn mm_drawing_declared_in_metres(dir: &Path) -> PathBuf {
    let lw = |h: &str, pts: [[f64; 2]; 4]| {
        let mut e = format!("0\nLWPOLYLINE\n5\n{h}\n8\n0\n90\n4\n70\n1\n");
        for p in pts {
            e.push_str(&format!("10\n{}\n20\n{}\n", p[0], p[1]));
        }
        e
    };
    let text = format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n6\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{}{}0\nENDSEC\n0\nEOF\n",
        lw("B1", [[0.0, 0.0], [400.0, 0.0], [400.0, 1000.0], [0.0, 1000.0]]),
        lw("F1", [[-500.0, -200.0], [900.0, -200.0], [900.0, 0.0], [-500.0, 0.0]])
    );
    let p = dir.join("wall.dxf");
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn dxf_in_millimetres_declared_as_metres_is_warned_in_one_line() {
    let d = tmpdir("dxf");
    let p = mm_drawing_declared_in_metres(&d);
    let o = run(&["limit", s(&p)]);
    assert!(o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    let warnings: Vec<&str> = err.lines().filter(|l| l.starts_with("warning:")).collect();
    assert_eq!(warnings.len(), 1, "{err}");
    assert!(
        warnings[0].contains("1000.0000 m across") && warnings[0].contains("--units mm"),
        "{err}"
    );
    // Read as the millimetres it is drawn in: no warning, and λ = b/h = 0.4.
    let o = run(&["limit", s(&p), "--units", "mm", "--json"]);
    assert!(o.status.success() && !String::from_utf8_lossy(&o.stderr).contains("warning"));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!((v["load_multiplier"].as_f64().unwrap() - 0.4).abs() < 1e-9);
}

#[test]
fn facets_0_1_and_100000000_are_refused_in_one_line() {
    let d = tmpdir("facets");
    let m = arch(&d);
    for k in ["0", "1", "100000000"] {
        let e = one_error_line(&run(&[
            "limit",
            s(&m),
            "--compressive-strength",
            "1e4",
            "--facets",
            k,
        ]));
        assert!(
            e.contains(&format!("--facets {k}")) && e.contains("4096"),
            "{e}"
        );
    }
}

#[test]
fn huge_step_counts_and_sweep_sizes_are_refused_before_any_work() {
    let d = tmpdir("bounds");
    let m = arch(&d);
    let half = d.join("half.json");
    assert!(run(&["gen", "arch", "--live", "left", "-o", s(&half)])
        .status
        .success());
    let e = one_error_line(&run(&[
        "incremental",
        s(&half),
        "--control",
        "0,3.19",
        "--max",
        "5m",
        "--step",
        "0.001mm",
    ]));
    assert!(e.contains("5000000 steps") && e.contains("100000"), "{e}");
    let e = one_error_line(&run(&[
        "incremental",
        s(&half),
        "--control",
        "0,3.19",
        "--max",
        "5mm",
        "--step",
        "1e-12mm",
    ]));
    assert!(e.contains("too small for the geometry"), "{e}");
    let e = one_error_line(&run(&[
        "capacity",
        s(&m),
        "--move",
        "right=0.02,0",
        "--steps",
        "100000000",
    ]));
    assert!(e.contains("steps 100000000"), "{e}");
    let jsonl = d.join("sweep.jsonl");
    for kind in ["--steps", "--directions", "--samples"] {
        let e = one_error_line(&run(&[
            "sweep",
            s(&m),
            "--move",
            "right=0.01,0",
            kind,
            "100000000",
            "--jsonl",
            s(&jsonl),
        ]));
        assert!(e.contains("at most 1000000 per run"), "{e}");
        assert!(!jsonl.exists());
    }
}

#[test]
fn tilt_of_a_block_that_cannot_stand_reports_it_instead_of_an_angle() {
    let d = tmpdir("tilt");
    let p = d.join("over.json");
    std::fs::write(
        &p,
        r#"{ "materials": {"default": {"unit_weight": 20}},
  "blocks": [ { "polygon": [[0.5,0],[1.6,0],[1.6,1],[0.5,1]] } ],
  "supports": [ { "name": "base", "polygon": [[-1,-1],[1,-1],[1,0],[-1,0]] } ] }"#,
    )
    .unwrap();
    for dir in ["+x", "-x"] {
        let o = run(&["tilt", s(&p), "--direction", dir, "--json"]);
        assert!(o.status.success());
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert!(v["tilt_angle"].is_null(), "{dir}: {v}");
        assert_eq!(v["limit"]["status"], "no_equilibrium", "{dir}");
    }
    // Towards −x the table pushes it back: it stands for tan α between 0.1 and 1.1.
    let o = run(&["tilt", s(&p), "--direction", "-x"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("between 0.100000 and 1.100000"), "{out}");
}

#[test]
fn symlinked_and_mode_600_outputs_keep_their_link_and_mode() {
    use std::os::unix::fs::PermissionsExt;
    let d = tmpdir("links");
    let m = arch(&d);
    let real = d.join("real.json");
    std::fs::write(&real, "old").unwrap();
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o600)).unwrap();
    let link = d.join("link.json");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    assert!(run(&["limit", s(&m), "-o", s(&link)]).status.success());
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    let meta = std::fs::metadata(&real).unwrap();
    assert_eq!(meta.permissions().mode() & 0o777, 0o600);
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&real).unwrap()).unwrap();
    assert!((v["load_multiplier"].as_f64().unwrap() - 0.434645).abs() < 1e-6);
}

/// A few tries of every class of `scripts/reliability.sh` (the script that writes
/// docs/reliability.md): no panic, no wrong or silent answer, no partial file. Needs python3,
/// which the script is written in.
#[test]
fn reliability_script_quick_subset_has_no_panic_wrong_answer_or_partial_file() {
    if Command::new("python3").arg("--version").output().is_err() {
        eprintln!("python3 not found: the reliability script is not run");
        return;
    }
    let script = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scripts/reliability.sh");
    let o = Command::new("bash")
        .arg(script)
        .arg("--quick")
        .env("VOUSSOIR", env!("CARGO_BIN_EXE_voussoir"))
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{out}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let all = out.lines().find(|l| l.starts_with("| **all**")).unwrap();
    // tried, clean error, accepted, warned, panic, wrong/silent, partial file
    let n: Vec<u64> = all
        .split('|')
        .skip(2)
        .filter_map(|c| c.trim().trim_matches('*').parse().ok())
        .collect();
    assert_eq!(n.len(), 7, "{all}");
    assert!(n[0] >= 60 && n[4] == 0 && n[5] == 0 && n[6] == 0, "{out}");
}
