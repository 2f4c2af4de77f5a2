//! `--adapted-model FILE` (issue 30, the façade's must-show, session 17): the adapted mesh of
//! `settle --adapt` / `limit --adapt` written as a model JSON before the final analysis runs on
//! it. Refused without `--adapt` and when it names the input; the file written is a model that
//! `settle` accepts as it is (its supports carry the profile's motions) and gives the adapted
//! run's work.

use crate::common;
use crate::common::{refused, run};
use serde_json::Value;
use std::path::PathBuf;

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i30am", name)
}

fn json_file(d: &std::path::Path, f: &str) -> Value {
    serde_json::from_str(&std::fs::read_to_string(d.join(f)).unwrap()).unwrap()
}

/// The 6 × 4 m panel with a door over a settling zone (docs/cracks.md), 0.5 m grid.
fn door(d: &std::path::Path) {
    run(
        d,
        &[
            "gen",
            "facade",
            "--width",
            "6",
            "--height",
            "4",
            "--gable",
            "0",
            "--element",
            "0.5",
            "--opening",
            "rect:2.5,0,3.5,2.2",
            "--segments",
            "12",
            "-o",
            "door.json",
        ],
    );
}

/// The area of a polygon (shoelace), by hand.
fn area(poly: &Value) -> f64 {
    let p: Vec<[f64; 2]> = poly
        .as_array()
        .unwrap()
        .iter()
        .map(|v| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()])
        .collect();
    let mut a = 0.0;
    for i in 0..p.len() {
        let (q, r) = (p[i], p[(i + 1) % p.len()]);
        a += q[0] * r[1] - r[0] * q[1];
    }
    a.abs() / 2.0
}

fn total_area(m: &Value) -> f64 {
    m["blocks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| area(&b["polygon"]))
        .sum()
}

#[test]
fn issue30_adapted_model_is_refused_without_adapt_and_over_the_input() {
    let d = tmpdir("refused");
    door(&d);
    for cmd in ["settle", "limit"] {
        let mut args = vec![cmd, "door.json"];
        if cmd == "settle" {
            args.extend(["--profile", "uniform:3,6,-0.02"]);
        }
        args.extend(["--adapted-model", "a.json"]);
        refused(&d, &args, "--adapted-model goes with --adapt");
    }
    refused(
        &d,
        &[
            "settle",
            "door.json",
            "--profile",
            "uniform:3,6,-0.02",
            "--adapt",
            "--adapted-model",
            "door.json",
        ],
        "it is the input",
    );
    assert!(!d.join("a.json").exists());
}

#[test]
fn issue30_adapted_model_is_a_model_that_settle_takes_and_gives_the_same_work() {
    let d = tmpdir("written");
    door(&d);
    let out = common::voussoir(
        &d,
        &[
            "settle",
            "door.json",
            "--profile",
            "uniform:3,6,-0.02",
            "--adapt",
            "--adapt-iterations",
            "1",
            "--adapt-global",
            "0",
            "--adapted-model",
            "adapted.json",
            "-o",
            "r.json",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("wrote adapted.json (the adapted model:"),
        "{err}"
    );
    let r = json_file(&d, "r.json");
    let adapted = json_file(&d, "adapted.json");
    let original = json_file(&d, "door.json");
    let its = r["adapt"]["iterations"].as_array().unwrap();
    let last = its.last().unwrap();
    // The mesh of the adapted run's last iteration, with its lines cut in: more blocks than
    // the grid's, the same wall (the cuts conserve the area: 6 × 4 − 1 × 2.2 = 21.8 m²).
    let blocks = adapted["blocks"].as_array().unwrap().len();
    assert_eq!(blocks as u64, last["blocks"].as_u64().unwrap());
    assert!(blocks > original["blocks"].as_array().unwrap().len());
    assert!(!r["adapt"]["lines"].as_array().unwrap().is_empty());
    let (a0, a1) = (total_area(&original), total_area(&adapted));
    assert!(
        (a0 - 21.8).abs() < 1e-9 && (a1 - a0).abs() < 1e-9,
        "{a0} {a1}"
    );
    // The profile's motions are in the model: `settle` needs no motion flag, and the analysis
    // of the written model is the adapted run's final analysis.
    let w = r["work_dead_loads"].as_f64().unwrap();
    assert!((w - last["value"].as_f64().unwrap()).abs() <= 1e-7 * w);
    run(&d, &["settle", "adapted.json", "-o", "again.json"]);
    let again = json_file(&d, "again.json");
    let w2 = again["work_dead_loads"].as_f64().unwrap();
    assert!((w2 - w).abs() <= 1e-9 * w, "{w2} vs {w}");
    assert_eq!(
        again["canonical"]["mechanism"]["crack_area"],
        r["canonical"]["mechanism"]["crack_area"]
    );
    // The hand value of the door panel (docs/cracks.md): W = γ·δ·(5.5 + 6.3·1.75/3.5) =
    // 3.114 kN·m on the grid; the adapted mesh can only do better.
    assert!(w >= 3.114 * (1.0 - 1e-6), "{w}");
}
