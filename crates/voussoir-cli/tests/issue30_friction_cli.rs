//! Issue 30, item 4 through the command line: `settle --non-associative` reports the
//! canonical mechanism of the friction iteration's last program (least crack area, openings and
//! slips), `--raw` the iteration's own; `limit --non-associative --canonical` likewise.

use crate::common;
use crate::common::{cwd::ok, cwd::ok_json, cwd::run};
use std::path::PathBuf;

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i30f-cli", name)
}

/// An 8 × 5 running-bond wall of 0.4 × 0.2 m units (`gen wall`), with `extra` flags.
fn wall(dir: &std::path::Path, extra: &[&str]) -> String {
    let m = dir.join("wall.json").to_string_lossy().into_owned();
    let mut a = vec![
        "gen",
        "wall",
        "--courses",
        "5",
        "--units",
        "8",
        "--unit",
        "0.4,0.2",
    ];
    a.extend(extra);
    a.extend(["-o", &m]);
    ok(&a);
    m
}

#[test]
fn issue30_item4_cli_settle_non_associative_reports_the_canonical_mechanism() {
    let d = tmpdir("settle");
    let w = wall(&d, &[]);
    let png = d.join("wall.png").to_string_lossy().into_owned();
    let args = [
        "settle",
        &w,
        "--friction",
        "0.6",
        "--non-associative",
        "--profile",
        "uniform:2.1,3.3,-0.01",
    ];
    let r = ok_json(&args);
    let m = &r["canonical"]["mechanism"];
    let (area, solver) = (
        m["crack_area"].as_f64().unwrap(),
        m["crack_area_solver"].as_f64().unwrap(),
    );
    assert!(area <= solver * (1.0 + 1e-9), "{area} > {solver}");
    assert_eq!(r["certificate"]["ok"], true);
    assert_eq!(r["friction_iteration"]["converged"], true);
    // --raw: the iteration's own mechanism, no canonical record, the same work (the optimum of
    // the same program, by Clarabel and by the simplex: 1e-6 relative).
    let mut raw_args = args.to_vec();
    raw_args.push("--raw");
    let raw = ok_json(&raw_args);
    assert!(raw.get("canonical").is_none());
    let (a, b) = (
        r["work_dead_loads"].as_f64().unwrap(),
        raw["work_dead_loads"].as_f64().unwrap(),
    );
    assert!((a - b).abs() <= 1e-6 * b, "{a} vs {b}");
    // Deterministic output; the summary names the selection; the picture is written.
    let mut j = args.to_vec();
    j.push("--json");
    assert!(ok(&j).stdout == ok(&j).stdout, "two runs differ");
    let mut p = args.to_vec();
    p.extend(["--png", &png]);
    let text = String::from_utf8_lossy(&ok(&p).stdout).into_owned();
    assert!(text.contains("\ncanonical: "), "{text}");
    let bytes = std::fs::read(&png).unwrap();
    assert!(bytes.starts_with(b"\x89PNG"), "not a PNG");
    // --ranges asks for what the frictional selection does not compute: refused in one line.
    let mut rg = args.to_vec();
    rg.push("--ranges");
    let o = run(&rg);
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(e.trim_end().lines().count(), 1, "{e}");
    assert!(
        e.contains("--ranges") && e.contains("--non-associative"),
        "{e}"
    );
}

#[test]
fn issue30_item4_cli_limit_non_associative_canonical() {
    let d = tmpdir("limit");
    let w = wall(&d, &["--live", "horizontal"]);
    // Pushed by its own weight, the wall slides on its base at λ = μ (closed form).
    let r = ok_json(&[
        "limit",
        &w,
        "--friction",
        "0.6",
        "--non-associative",
        "--canonical",
    ]);
    let l = r["load_multiplier"].as_f64().unwrap();
    assert!((l - 0.6).abs() < 1e-6, "λ = {l}");
    assert!(r["canonical"]["mechanism"]["crack_area"].is_f64());
    let plain = ok_json(&["limit", &w, "--friction", "0.6", "--non-associative"]);
    assert!(plain.get("canonical").is_none());
    assert!((plain["load_multiplier"].as_f64().unwrap() - l).abs() < 1e-9);
}
