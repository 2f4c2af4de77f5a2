//! Issue 31 item 4: the incremental and the inverse analyses on 3D models, written once over
//! `Assembly`. References: the 2D arch (a barrel vault in stack bond, extruded from it, carries
//! per metre of depth what the arch carries per metre of width, so its λ curve against the
//! crown's displacement is the arch's), and the forward settlement whose cracks are observed.

use crate::common::{json, refused, run, tmpdir};
use serde_json::Value;
use std::path::Path;

/// The paper's arch (README defaults: R = 2.86 m at the intrados, t = 0.33 m, 64 voussoirs)
/// and its vault of `depth` m in `rings` rings, both with the live load `live`.
fn arch_and_vault(dir: &Path, live: &str, depth: &str, rings: &str) {
    run(dir, &["gen", "arch", "--live", live, "-o", "arch.json"]);
    run(
        dir,
        &[
            "gen",
            "vault",
            "--live",
            live,
            "--depth",
            depth,
            "--rings",
            rings,
            "-o",
            "vault.json",
        ],
    );
}

fn curve(r: &Value) -> Vec<(f64, f64)> {
    r["curve"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            (
                p["displacement"].as_f64().unwrap(),
                p["load_multiplier"].as_f64().unwrap(),
            )
        })
        .collect()
}

/// The 3D curve equals the 2D one point by point: displacements within 1e-9 m, λ within 1e-7
/// (both computed by the same steps: the vault's mechanism is the arch's in every ring).
fn assert_same_curve(r2: &Value, r3: &Value, what: &str) {
    assert_eq!(r3["status"], r2["status"], "{what}: {}", r3["message"]);
    let (c2, c3) = (curve(r2), curve(r3));
    assert!(c2.len() >= 5, "{what}: a curve of {} points", c2.len());
    assert_eq!(c3.len(), c2.len(), "{what}: {c3:?} vs {c2:?}");
    for (i, ((d2, l2), (d3, l3))) in c2.iter().zip(&c3).enumerate() {
        assert!(
            (d3 - d2).abs() <= 1e-9 && (l3 - l2).abs() <= 1e-7,
            "{what}, point {i}: 3D ({d3}, {l3}) vs 2D ({d2}, {l2})"
        );
    }
    let (p2, p3) = (
        r2["peak_load_multiplier"].as_f64().unwrap(),
        r3["peak_load_multiplier"].as_f64().unwrap(),
    );
    assert!((p3 - p2).abs() <= 1e-7, "{what}: peak {p3} vs {p2}");
}

#[test]
fn issue31_item4_incremental_on_the_half_loaded_vault_equals_the_2d_arch_curve() {
    let dir = tmpdir("issue31-inc3d", "incremental");
    for (depth, rings, mid) in [("1", "1", "0.5"), ("1", "2", "0.5")] {
        arch_and_vault(&dir, "left", depth, rings);
        // The crown's extrados, horizontally (the paper's Fig. 14); in 3D at mid-depth.
        let r2 = json(&run(
            &dir,
            &[
                "incremental",
                "arch.json",
                "--control",
                "0,3.19",
                "--step",
                "0.2mm",
                "--max",
                "20mm",
                "--json",
            ],
        ));
        let control3 = format!("0,{mid},3.19");
        let r3 = json(&run(
            &dir,
            &[
                "incremental",
                "vault.json",
                "--control",
                &control3,
                "--direction",
                "+x",
                "--step",
                "0.2mm",
                "--max",
                "20mm",
                "--json",
            ],
        ));
        assert_same_curve(&r2, &r3, &format!("depth {depth}, {rings} rings"));
        // λ at the start is the limit analysis's (README: 0.2189 for the half-loaded arch).
        let l0 = curve(&r3)[0].1;
        assert!((l0 - 0.2189).abs() < 5e-5, "λ(0) = {l0}");
        // The control point is the 3D one, and the hinges open at the 2D joints' (x, y) as
        // (x, ·, z) through the depth.
        assert_eq!(r3["control"]["point"][1].as_f64(), mid.parse().ok());
        let first2: Vec<(f64, f64)> = r2["events"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|e| e["step"] == 0)
            .map(|e| (e["x"].as_f64().unwrap(), e["y"].as_f64().unwrap()))
            .collect();
        let first3: Vec<&Value> = r3["events"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|e| e["step"] == 0)
            .collect();
        assert!(!first2.is_empty() && !first3.is_empty());
        for e in &first3 {
            let (x, z) = (e["x"].as_f64().unwrap(), e["z"].as_f64().unwrap());
            assert!(
                first2
                    .iter()
                    .any(|(x2, y2)| (x - x2).abs() < 1e-6 && (z - y2).abs() < 1e-6),
                "3D hinge at ({x}, {z}) is not a 2D one: {first2:?}"
            );
        }
        // 2D results have no z (written as before).
        assert!(r2["events"][0].get("z").is_none());
    }
}

#[test]
fn issue31_item4_incremental_after_a_settlement_in_3d_equals_2d() {
    // The right springing settled by 2.5 mm first (tied for the settlement), then the live
    // load: the 2D `--move right=0,-2.5mm` is the 3D `right=0,0,-2.5mm` (z up).
    let dir = tmpdir("issue31-inc3d", "settled");
    arch_and_vault(&dir, "left", "1", "1");
    let r2 = json(&run(
        &dir,
        &[
            "incremental",
            "arch.json",
            "--control",
            "0,3.19",
            "--step",
            "0.5mm",
            "--max",
            "20mm",
            "--move",
            "right=0,-2.5mm",
            "--fixed",
            "right",
            "--json",
        ],
    ));
    let r3 = json(&run(
        &dir,
        &[
            "incremental",
            "vault.json",
            "--control",
            "0,0.5,3.19",
            "--direction",
            "1,0,0",
            "--step",
            "0.5mm",
            "--max",
            "20mm",
            "--move",
            "right=0,0,-2.5mm",
            "--fixed",
            "right",
            "--json",
        ],
    ));
    assert_same_curve(&r2, &r3, "settled");
    assert!(!r3["initial_open_joints"].as_array().unwrap().is_empty());
    // The final cracks are 3D records (joints, position, largest opening).
    let c = &r3["cracks"][0];
    assert!(c["joints"].is_array() && c["position"].as_array().unwrap().len() == 3);
}

/// Forward settlement of the vault by `right = (u, 0, w)`, its cracks written as observations
/// (`by_point`: each open point by its coordinates `at: [x, y, z]`, as a surveyor would; else
/// each cracked joint with its widths per point), identified with `--unknown right=u,w`.
fn identify_round_trip(dir: &Path, u: f64, w: f64, by_point: bool) -> Value {
    run(
        dir,
        &[
            "gen", "vault", "--depth", "1", "--rings", "1", "-o", "v.json",
        ],
    );
    let mv = format!("right={u},0,{w}");
    let f = json(&run(dir, &["settle", "v.json", "--move", &mv, "--json"]));
    assert_eq!(f["status"], "mechanism");
    let mut cracks = Vec::new();
    for (j, joint) in f["joints"].as_array().unwrap().iter().enumerate() {
        let pts = joint["points"].as_array().unwrap();
        let widths: Vec<f64> = pts.iter().map(|p| p["opening"].as_f64().unwrap()).collect();
        if widths.iter().all(|w| *w <= 1e-9) {
            continue;
        }
        if by_point {
            for (p, w) in pts.iter().zip(&widths).filter(|(_, w)| **w > 1e-9) {
                cracks.push(serde_json::json!({
                    "at": [p["x"], p["y"], p["z"]],
                    "opening": w,
                }));
            }
        } else {
            cracks.push(serde_json::json!({"joint": j, "opening": widths}));
        }
    }
    assert!(cracks.len() >= 3, "{cracks:?}");
    let obs = serde_json::json!({"tolerance": 1e-5, "cracks": cracks});
    std::fs::write(dir.join("obs.json"), obs.to_string()).unwrap();
    json(&run(
        dir,
        &[
            "identify",
            "v.json",
            "--cracks",
            "obs.json",
            "--unknown",
            "right=u,w",
            "--json",
        ],
    ))
}

#[test]
fn issue31_item4_identify_recovers_a_vault_settlement_from_its_forward_cracks() {
    let dir = tmpdir("issue31-inc3d", "identify");
    for (u, w, by_point) in [(0.004, -0.003, false), (0.002, -0.005, true)] {
        let r = identify_round_trip(&dir, u, w, by_point);
        assert_eq!(r["status"], "identified", "{}", r["message"]);
        let value = |i: usize| r["unknowns"][i]["value"].as_f64().unwrap();
        assert_eq!(r["unknowns"][0]["name"], "right.u");
        assert_eq!(r["unknowns"][1]["name"], "right.w");
        assert!(
            (value(0) - u).abs() <= 1e-6 * u.abs() && (value(1) - w).abs() <= 1e-6 * w.abs(),
            "identified ({}, {}) vs ({u}, {w})",
            value(0),
            value(1)
        );
        // The support motion in the 3D components, the forward settlement reproduces it.
        let m = &r["support_motions"][0];
        assert_eq!(m["support"], "right");
        assert!(m["theta_y"].as_f64() == Some(0.0) && m.get("theta").is_none());
        assert_eq!(r["certificate"]["reproduces"], true);
        assert!(r["observations"][0]["z"].is_number());
    }
}

#[test]
fn issue31_item4_3d_flags_are_honoured_or_refused_in_one_line() {
    let dir = tmpdir("issue31-inc3d", "refusals");
    arch_and_vault(&dir, "left", "1", "1");
    let inc = |extra: &[&str], needle: &str| {
        let mut a = vec!["incremental", "vault.json", "--step", "1mm", "--max", "5mm"];
        a.extend_from_slice(extra);
        refused(&dir, &a, needle);
    };
    inc(
        &["--control", "0,3.19"],
        "--control 0,3.19: expected three finite numbers X,Y,Z",
    );
    inc(
        &["--control", "0,0.5,3.19", "--direction", "1,0"],
        "three components DX,DY,DZ",
    );
    inc(
        &["--control", "0,0.5,3.19", "--report", "r.html"],
        "--report applies to 2D",
    );
    inc(&["--control", "0,0.5,30"], "from the nearest block");
    refused(
        &dir,
        &["incremental", "arch.json", "--control", "0,3.19,0"],
        "expected two finite numbers X,Y (the model is 2D)",
    );
    // A horizontal angle is a 3D direction too (90° from +x towards +y: along the depth, where
    // the mechanism does not move the crown).
    let r = json(&run(
        &dir,
        &[
            "incremental",
            "vault.json",
            "--control",
            "0,0.5,3.19",
            "--direction",
            "90",
            "--step",
            "1mm",
            "--max",
            "5mm",
            "--json",
        ],
    ));
    assert_eq!(r["status"], "control_still");
    // identify: components of the dimension, no profiles or crack lines in 3D.
    std::fs::write(
        dir.join("obs.json"),
        r#"{"cracks": [{"at": [0, 0.5, 3.19], "opening": 0.001}]}"#,
    )
    .unwrap();
    let id = |unknown: &str, needle: &str| {
        refused(
            &dir,
            &[
                "identify",
                "vault.json",
                "--cracks",
                "obs.json",
                "--unknown",
                unknown,
            ],
            needle,
        );
    };
    id("right=theta", "is not u, v, w, theta_x, theta_y or theta_z");
    id("uniform:0,3,?", "applies to 2D models");
    std::fs::write(
        dir.join("line.json"),
        r#"{"cracks": [{"polyline": [[0, 3], [0, 3.2]], "opening": 0.001}]}"#,
    )
    .unwrap();
    refused(
        &dir,
        &[
            "identify",
            "vault.json",
            "--cracks",
            "line.json",
            "--unknown",
            "right=u",
        ],
        "\"polyline\" and \"snap\" (a crack line as drawn) apply to 2D models",
    );
    refused(
        &dir,
        &[
            "identify",
            "arch.json",
            "--cracks",
            "obs.json",
            "--unknown",
            "right=u",
        ],
        "\"at\" must be two finite coordinates [x, y] (the model is 2D)",
    );
    refused(
        &dir,
        &[
            "identify",
            "arch.json",
            "--cracks",
            "obs.json",
            "--unknown",
            "right=w",
        ],
        "component 'w' is not u, v or theta",
    );
}
