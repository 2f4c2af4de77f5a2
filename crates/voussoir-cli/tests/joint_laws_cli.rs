//! Issue #17, items 3–5 through the command line: `--crushing conic` and `--facets` on
//! `settle` and `capacity`, `--non-associative` friction, and a model's existing `cracks`.

use crate::common;
use crate::common::{cwd::ok_json, cwd::run};
use std::path::PathBuf;

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("jl-cli", name)
}

fn gen(dir: &std::path::Path, name: &str, args: &[&str]) -> String {
    let m = dir.join(name).to_string_lossy().into_owned();
    let mut a = vec!["gen"];
    a.extend(args);
    a.extend(["-o", &m]);
    assert!(run(&a).status.success());
    m
}

#[test]
fn settle_with_the_exact_crushing_cone_is_certified_and_near_the_fine_polygon() {
    let d = tmpdir("cone");
    let l = gen(
        &d,
        "lintel.json",
        &["lintel", "--compressive-strength", "2400"],
    );
    let mv = ["--move", "right=0.02,0"];
    let cone = ok_json(&["settle", &l, mv[0], mv[1], "--crushing", "conic"]);
    assert_eq!(cone["solver"]["solver"], "clarabel");
    assert_eq!(cone["certificate"]["ok"], true);
    let poly = ok_json(&["settle", &l, mv[0], mv[1], "--facets", "64"]);
    let (a, b) = (
        cone["work_dead_loads"].as_f64().unwrap(),
        poly["work_dead_loads"].as_f64().unwrap(),
    );
    assert!((a - b).abs() <= 0.01 * a, "{a} vs {b}");
    // The conic settlement solves the force program only: not with --settlement-form.
    let o = run(&[
        "settle",
        &l,
        mv[0],
        mv[1],
        "--crushing",
        "conic",
        "--settlement-form",
        "force-only",
    ]);
    assert!(!o.status.success());
    assert_eq!(
        String::from_utf8_lossy(&o.stderr)
            .trim_end()
            .lines()
            .count(),
        1
    );
}

/// The 8 × 5 running-bond wall of docs/joint-laws.md (units 0.4 × 0.2 m) with live load `live`.
fn wall_8x5(d: &std::path::Path, live: &str) -> String {
    gen(
        d,
        "wall.json",
        &[
            "wall",
            "--courses",
            "5",
            "--units",
            "8",
            "--unit",
            "0.4,0.2",
            "--live",
            live,
        ],
    )
}

#[test]
fn non_associative_settlement_reports_its_iteration() {
    let w = wall_8x5(&tmpdir("nonassoc"), "none");
    let r = ok_json(&[
        "settle",
        &w,
        "--friction",
        "0.6",
        "--non-associative",
        "--profile",
        "uniform:2.1,3.3,-0.01",
    ]);
    let it = &r["friction_iteration"];
    assert_eq!(it["converged"], true, "{it}");
    assert!(it["history"].as_array().unwrap().len() >= 8);
    assert_eq!(r["certificate"]["ok"], true);
    assert_eq!(r["solver"]["solver"], "clarabel");
    // Without the flag the field is absent (the JSON of an associative run is unchanged).
    let r = ok_json(&[
        "settle",
        &w,
        "--friction",
        "0.6",
        "--profile",
        "uniform:2.1,3.3,-0.01",
    ]);
    assert!(r.get("friction_iteration").is_none());
}

#[test]
fn a_cracked_model_warns_when_the_collapse_mechanism_closes_its_crack() {
    let d = tmpdir("cracks");
    let a = gen(
        &d,
        "arch.json",
        &["arch", "--live", "left", "--thickness", "0.45"],
    );
    let mut m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&a).unwrap()).unwrap();
    m["cracks"] = serde_json::json!([{"at": [0.0, 2.86], "opening": 0.003}]);
    let c = d.join("cracked.json").to_string_lossy().into_owned();
    std::fs::write(&c, serde_json::to_string(&m).unwrap()).unwrap();
    let sound = ok_json(&["limit", &a]);
    let cracked = ok_json(&["limit", &c]);
    let (ls, lc) = (
        sound["load_multiplier"].as_f64().unwrap(),
        cracked["load_multiplier"].as_f64().unwrap(),
    );
    assert!(lc < 0.5 * ls, "{lc} vs {ls}");
    assert!(cracked["message"]
        .as_str()
        .unwrap()
        .contains("closes the open crack of joint 32"));
    // A crack the model cannot place is a one-line error naming it.
    m["cracks"] = serde_json::json!([{"joint": 5000, "opening": 0.003}]);
    std::fs::write(&c, serde_json::to_string(&m).unwrap()).unwrap();
    let o = run(&["limit", &c]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && e.contains("cracks[0]") && e.contains("joint 5000"),
        "{e}"
    );
    assert_eq!(e.trim_end().lines().count(), 1);
}

/// Session 23: a non-associative capacity curve has no certificate at any step (the iteration
/// is a heuristic). Its summary said "NOT CERTIFIED … (largest gap 0.0e0, admissibility
/// 0.0e0)", which reads as a certificate that holds; it now says the steps have none and why.
/// The wall of docs/joint-laws.md (8 × 5, μ = 0.6, pushed sideways by its own weight): λ(0)
/// is the base sliding at λ = μ = 0.6 (hand calculation), on either law.
#[test]
fn a_non_associative_capacity_says_its_steps_have_no_certificate() {
    let w = wall_8x5(&tmpdir("nonassoc-capacity"), "horizontal");
    let args = [
        "capacity",
        &w,
        "--friction",
        "0.6",
        "--non-associative",
        "--profile",
        "uniform:2.1,3.3,-0.01",
        "--steps",
        "1",
    ];
    let o = run(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("NOT CERTIFIED at 2 of 2 steps (no certificate: the non-associative friction iteration is a heuristic"),
        "{text}"
    );
    assert!(
        text.contains("without a certificate: see the first line") && !text.contains("largest gap"),
        "{text}"
    );
    let r = ok_json(&args);
    let l0 = r["curve"][0]["load_multiplier"].as_f64().unwrap();
    assert!((l0 - 0.6).abs() < 1e-6, "λ(0) = {l0}");
    assert_eq!(r["certificate"]["certified"], 0);
}
