//! Issue 32 item 1, foundations as drawn, through the CLI: `--profile` cuts a support that spans
//! its breakpoints (LACT3's Portal settles one pier, not the whole portal), `--split` cuts one
//! where asked so that `--move` may name a part, `import --split-support N` cuts into N equal
//! parts, and supports from a DXF layer settle one by one. References: weights by the shoelace
//! formula (18 kN/m³, 1 m wide) and hand calculations.

use crate::common;
use crate::common::{cwd::fails, cwd::ok, cwd::ok_json};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("issue32f", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn portal() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../voussoir-io/tests/fixtures/lact3/Portal.dxf")
}

fn area(p: &[Value]) -> f64 {
    let n = p.len();
    0.5 * (0..n)
        .map(|i| {
            let (a, b) = (&p[i], &p[(i + 1) % n]);
            a[0].as_f64().unwrap() * b[1].as_f64().unwrap()
                - b[0].as_f64().unwrap() * a[1].as_f64().unwrap()
        })
        .sum::<f64>()
        .abs()
}

fn xs(p: &[Value]) -> (f64, f64, f64) {
    let x: Vec<f64> = p.iter().map(|q| q[0].as_f64().unwrap()).collect();
    let y = p
        .iter()
        .map(|q| q[1].as_f64().unwrap())
        .fold(f64::MIN, f64::max);
    (
        x.iter().copied().fold(f64::MAX, f64::min),
        x.iter().copied().fold(f64::MIN, f64::max),
        y,
    )
}

const GAMMA: f64 = 18.0;
const V: f64 = 0.01;

/// Portal (mm; one foundation polygon `base` from x = 0 to 2.5 m, piers on 0.15–0.65 m and
/// 1.85–2.35 m). `uniform:1.25,2.5,-0.01` (x0 = 1.25 m, x1 = 2.5 m, v = −1 cm): the base is cut
/// at 1.25 m, the right pier settles and the left one does not; the work is strictly below
/// W·v (W the weight of all blocks), which a rigid settlement of the whole portal would give.
#[test]
fn issue32_item1_portal_settles_its_right_pier() {
    let d = tmpdir("portal");
    let json = d.join("Portal.json");
    ok(&["import", s(&portal()), "--units", "mm", "-o", s(&json)]);
    let model: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let blocks = model["blocks"].as_array().unwrap();
    let polys: Vec<&Vec<Value>> = blocks
        .iter()
        .map(|b| b["polygon"].as_array().unwrap())
        .collect();
    let w: f64 = polys.iter().map(|p| area(p) * GAMMA * 1.0).sum();
    let wv = w * V;

    let r = ok_json(&[
        "settle",
        s(&portal()),
        "--units",
        "mm",
        "--profile",
        "uniform:1.25,2.5,-0.01",
    ]);
    assert_eq!(r["certificate"]["ok"], true, "{}", r["certificate"]);
    let work = r["work_dead_loads"].as_f64().unwrap();
    assert!(
        work > 0.0 && work < 0.9 * wv,
        "work {work} against W·v {wv}"
    );
    // The work is the settled part's reaction times the drop (virtual work), and W·v is the
    // sum of both parts' reactions times v.
    let fy = |k: usize| r["reactions"][k]["fy"].as_f64().unwrap();
    assert_eq!(r["reactions"][1]["support"], "base@1");
    assert!((work - fy(1) * V).abs() <= 1e-9 * work);
    assert!(
        (fy(0) + fy(1) - w).abs() <= 1e-9 * w,
        "{} {}",
        fy(0) + fy(1),
        w
    );

    let split = &r["split_supports"][0];
    assert_eq!(split["support"], "base");
    assert_eq!(split["cuts"][0].as_f64(), Some(1.25));
    assert_eq!(split["parts"][0]["name"], "base@0");
    assert_eq!(split["parts"][1]["name"], "base@1");
    assert_eq!(split["parts"][1]["x_range"][0].as_f64(), Some(1.25));
    assert_eq!(split["parts"][1]["x_range"][1].as_f64(), Some(2.5));
    assert_eq!(split["parts"][0]["motion"][1].as_f64(), Some(0.0));
    assert_eq!(split["parts"][1]["motion"][1].as_f64(), Some(-V));

    // The piers below the lintel (tops at or below y = 0.9 m): the right one drops by v as a
    // rigid body, the left one stays.
    let (mut right, mut left) = (0, 0);
    for (k, p) in polys.iter().enumerate() {
        let (x0, x1, ytop) = xs(p);
        let b = &r["blocks"][k];
        let (u, v, t) = (
            b["u"].as_f64().unwrap(),
            b["v"].as_f64().unwrap(),
            b["theta"].as_f64().unwrap(),
        );
        if ytop <= 0.9 + 1e-9 && x0 >= 1.85 - 1e-9 {
            right += 1;
            assert!(
                u.abs() < 1e-9 && (v + V).abs() < 1e-9 && t.abs() < 1e-9,
                "{k}: {b}"
            );
        } else if ytop <= 0.9 + 1e-9 && x1 <= 0.65 + 1e-9 {
            left += 1;
            assert!(
                u.abs() < 1e-12 && v.abs() < 1e-12 && t.abs() < 1e-12,
                "{k}: {b}"
            );
        }
    }
    assert!(right >= 6 && left >= 6, "{right} {left}");

    // The same settlement by hand: --split base@1.25 and --move of the right part.
    let r2 = ok_json(&[
        "settle",
        s(&json),
        "--split",
        "base@1250mm",
        "--move",
        "base@1=0,-1cm",
    ]);
    let work2 = r2["work_dead_loads"].as_f64().unwrap();
    assert!((work2 - work).abs() <= 1e-9 * work, "{work2} {work}");

    // The summary names the cut and the parts.
    let o = ok(&["settle", s(&json), "--profile", "uniform:1.25,2.5,-0.01"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("support base cut at x = 1.2500 m into 2 parts"),
        "{text}"
    );
    assert!(
        text.contains("base@1       x 1.2500 … 2.5000 m  u 0.0000 cm, v -1.0000 cm"),
        "{text}"
    );
}

/// Refusals in one line: an unknown support, a cut outside the support, a malformed --split,
/// a support split twice, `--split-support` below 2.
#[test]
fn issue32_item1_split_refusals() {
    let d = tmpdir("refuse");
    let json = d.join("Portal.json");
    ok(&["import", s(&portal()), "--units", "mm", "-o", s(&json)]);
    let m = s(&json);
    fails(
        &["settle", m, "--split", "nope@1", "--move", "nope@1=0,-1cm"],
        &["--split nope@1", "no support named 'nope'"],
    );
    fails(
        &["settle", m, "--split", "base@3", "--move", "base@1=0,-1cm"],
        &["--split base@3", "x = 3 m is not inside", "0 … 2.5 m"],
    );
    fails(
        &["settle", m, "--split", "base@one"],
        &["--split base@one", "NAME@X"],
    );
    fails(
        &[
            "capacity",
            m,
            "--split",
            "base@1",
            "--split",
            "base@2",
            "--move",
            "base@1=0,-1cm",
        ],
        &["split twice"],
    );
    fails(
        &["settle", m, "--move", "base@1=0,-1cm"],
        &["no support named 'base@1'"],
    );
    fails(
        &[
            "import",
            s(&portal()),
            "--units",
            "mm",
            "--split-support",
            "1",
        ],
        &["--split-support 1", "2 or more"],
    );
    // The other commands that take support motions accept --split (identify, sweep, incremental).
    for cmd in [
        vec![
            "identify",
            m,
            "--split",
            "base@9",
            "--cracks",
            m,
            "--unknown",
            "base:v",
        ],
        vec!["sweep", m, "--split", "base@9", "--steps", "2"],
        vec!["incremental", m, "--split", "base@9", "--control", "1,1"],
    ] {
        fails(&cmd, &["--split base@9", "not inside"]);
    }
}

/// A DXF polygon written as text: a closed LWPOLYLINE on `layer` (mm).
fn lw(h: &str, layer: &str, x0: f64, y0: f64, x1: f64, y1: f64) -> String {
    let mut e = format!("0\nLWPOLYLINE\n5\n{h}\n8\n{layer}\n90\n4\n70\n1\n");
    for p in [[x0, y0], [x1, y0], [x1, y1], [x0, y1]] {
        e.push_str(&format!("10\n{}\n20\n{}\n", p[0], p[1]));
    }
    e
}

fn drawing(dir: &Path, name: &str, entities: &[String]) -> PathBuf {
    let text = format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{}0\nENDSEC\n0\nEOF\n",
        entities.concat()
    );
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Two piers (600 × 1000 mm and 600 × 800 mm) on two footings drawn on layer FOUND: imported
/// with --support-layer, both footings are supports (FOUND-0, FOUND-1 from the left); settling
/// the right one by 1 cm does the work of the right pier's weight, by hand
/// 0.6 × 0.8 × 18 × 0.01 = 0.0864 kN·m, and nothing else moves.
#[test]
fn issue32_item1_supports_from_a_dxf_layer_settle_one_by_one() {
    let d = tmpdir("layer");
    let dxf = drawing(
        &d,
        "piers.dxf",
        &[
            lw("B0", "0", 200.0, 300.0, 800.0, 1300.0),
            lw("B1", "0", 1700.0, 300.0, 2300.0, 1100.0),
            lw("F0", "FOUND", 0.0, 0.0, 1000.0, 300.0),
            lw("F1", "FOUND", 1500.0, 0.0, 2500.0, 300.0),
        ],
    );
    let json = d.join("piers.json");
    ok(&[
        "import",
        s(&dxf),
        "--support-layer",
        "FOUND",
        "-o",
        s(&json),
    ]);
    let model: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let names: Vec<&str> = model["supports"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["FOUND-0", "FOUND-1"]);
    let r = ok_json(&["settle", s(&json), "--move", "FOUND-1=0,-10mm"]);
    let expect = 0.6 * 0.8 * GAMMA * V;
    let work = r["work_dead_loads"].as_f64().unwrap();
    assert!(
        (work - expect).abs() <= 1e-9 * expect,
        "{work} against {expect}"
    );
    assert_eq!(r["blocks"][0]["v"].as_f64(), Some(0.0));
    assert!((r["blocks"][1]["v"].as_f64().unwrap() + V).abs() < 1e-12);
}

/// One base 2000 × 300 mm with two blocks apart on it, imported with --split-support 2: parts
/// base@0 (x 0–1 m) and base@1 (1–2 m); moving base@1 down 1 cm drops the right block only,
/// work = 0.7 × 0.8 × 18 × 0.01 = 0.1008 kN·m. The same from --profile on the unsplit model.
#[test]
fn issue32_item1_import_splits_the_foundation_into_equal_parts() {
    let d = tmpdir("equal");
    let dxf = drawing(
        &d,
        "two.dxf",
        &[
            lw("B0", "0", 200.0, 300.0, 900.0, 1300.0),
            lw("B1", "0", 1100.0, 300.0, 1800.0, 1100.0),
            lw("F", "0", 0.0, 0.0, 2000.0, 300.0),
        ],
    );
    let json = d.join("two.json");
    let o = ok(&["import", s(&dxf), "--split-support", "2", "-o", s(&json)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("support base cut at x = 1.0000 m into 2 parts"),
        "{err}"
    );
    let model: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let sup = model["supports"].as_array().unwrap();
    assert_eq!(sup.len(), 2);
    assert_eq!(sup[0]["name"], "base@0");
    assert_eq!(sup[1]["name"], "base@1");
    assert!((area(sup[0]["polygon"].as_array().unwrap()) - 0.3).abs() < 1e-12);
    let expect = 0.7 * 0.8 * GAMMA * V;
    let r = ok_json(&["settle", s(&json), "--move", "base@1=0,-1cm"]);
    let work = r["work_dead_loads"].as_f64().unwrap();
    assert!(
        (work - expect).abs() <= 1e-9 * expect,
        "{work} against {expect}"
    );
    let r = ok_json(&["settle", s(&dxf), "--profile", "uniform:1,2,-0.01"]);
    let work = r["work_dead_loads"].as_f64().unwrap();
    assert!(
        (work - expect).abs() <= 1e-9 * expect,
        "{work} against {expect}"
    );
}

/// `identify` reads an unknown profile on the foundations as drawn, as `settle --profile` does:
/// the cracks of Portal's right pier settling 1 cm (the base cut at x = 1.25 m) give back
/// v = −1 cm for the unknown `uniform:1.25,2.5,?` (the forward settlement is the reference).
#[test]
fn issue32_item1_identify_cuts_the_base_at_an_unknown_profile_s_ends() {
    let d = tmpdir("identify");
    let json = d.join("Portal.json");
    ok(&["import", s(&portal()), "--units", "mm", "-o", s(&json)]);
    let f = ok_json(&["settle", s(&json), "--profile", "uniform:1.25,2.5,-0.01"]);
    let mut cracks = Vec::new();
    for j in f["joints"].as_array().unwrap() {
        let ws: Vec<f64> = j["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["opening"].as_f64().unwrap())
            .map(|w| if w > 1e-9 { w } else { 0.0 })
            .collect();
        if ws.iter().any(|w| *w > 0.0) {
            cracks.push(serde_json::json!({"joint": j["id"], "opening": ws}));
        }
    }
    assert!(cracks.len() >= 4, "{} cracked joints", cracks.len());
    let obs = d.join("obs.json");
    std::fs::write(&obs, serde_json::json!({ "cracks": cracks }).to_string()).unwrap();
    let r = ok_json(&[
        "identify",
        s(&json),
        "--cracks",
        s(&obs),
        "--unknown",
        "uniform:1.25,2.5,?",
    ]);
    let v = r["unknowns"][0]["value"].as_f64().unwrap();
    assert!((v + V).abs() <= 1e-6 * V, "identified v = {v}");
    assert_eq!(r["certificate"]["reproduces"], true);
    assert_eq!(r["split_supports"][0]["parts"][1]["name"], "base@1");
}
