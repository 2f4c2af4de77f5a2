//! `voussoir identify` end to end: a forward settlement's cracks written as an observation file
//! (by coordinates, as a surveyor would) give back the settlement; JSON, drawings, bad input.

use crate::common::cwd::run;
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-identify-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn paper_arch(dir: &Path) -> String {
    let p = dir.join("arch.json");
    let o = run(&[
        "gen",
        "arch",
        "--radius",
        "2.86",
        "--radius-at",
        "intrados",
        "--thickness",
        "0.33",
        "--voussoirs",
        "64",
        "--unit-weight",
        "18",
        "--live",
        "none",
        "-o",
        p.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    p.to_str().unwrap().to_string()
}

/// The open points of a saved settlement result as `{"at": [x, y], "opening": w}` cracks.
fn observations(settle_json: &[u8]) -> String {
    let v: serde_json::Value = serde_json::from_slice(settle_json).unwrap();
    let mut cracks = Vec::new();
    for j in v["joints"].as_array().unwrap() {
        for p in j["points"].as_array().unwrap() {
            let w = p["opening"].as_f64().unwrap();
            if w > 1e-9 {
                cracks.push(serde_json::json!({"at": [p["x"], p["y"]], "opening": w}));
            }
        }
    }
    serde_json::json!({ "tolerance": 1e-4, "cracks": cracks }).to_string()
}

#[test]
fn identify_recovers_the_spreading_from_the_command_line() {
    let d = tmpdir("roundtrip");
    let arch = paper_arch(&d);
    let f = run(&["settle", &arch, "--move", "right=0.01,0", "--json"]);
    assert!(f.status.success());
    let obs = d.join("obs.json");
    std::fs::write(&obs, observations(&f.stdout)).unwrap();
    let (svg, png, html, out) = (
        d.join("id.svg"),
        d.join("id.png"),
        d.join("id.html"),
        d.join("id.json"),
    );
    let o = run(&[
        "identify",
        &arch,
        "--cracks",
        obs.to_str().unwrap(),
        "--unknown",
        "right=u[0:]",
        "--svg",
        svg.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
        "--report",
        html.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("REPRODUCED"), "{text}");
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!(v["status"], "identified");
    let u = v["unknowns"][0]["value"].as_f64().unwrap();
    assert!((u - 0.01).abs() <= 1e-6 * 0.01, "u = {u}");
    assert_eq!(v["unknowns"][0]["identifiable"], true);
    assert_eq!(v["certificate"]["reproduces"], true);
    let svg_text = std::fs::read_to_string(&svg).unwrap();
    assert!(svg_text.matches("<circle cx=").count() >= 3);
    assert!(svg_text.contains("observed-cracks"));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    let html_text = std::fs::read_to_string(&html).unwrap();
    assert!(html_text.contains("Observed and predicted cracks"));
    // Deterministic: the same input gives byte-identical JSON.
    let a = run(&[
        "identify",
        &arch,
        "--cracks",
        obs.to_str().unwrap(),
        "--unknown",
        "right=u",
        "--json",
    ]);
    let b = run(&[
        "identify",
        &arch,
        "--cracks",
        obs.to_str().unwrap(),
        "--unknown",
        "right=u",
        "--json",
    ]);
    assert!(a.status.success());
    assert_eq!(a.stdout, b.stdout);
}

#[test]
fn identify_refuses_bad_input_in_one_line() {
    let d = tmpdir("bad");
    let arch = paper_arch(&d);
    let obs = d.join("obs.json");
    let out = d.join("never.json");
    let cases: [(&str, &[&str], &str); 4] = [
        (
            r#"{"cracks": [{"joint": 999, "opening": 0.001}]}"#,
            &["right=u"],
            "joint 999",
        ),
        (
            r#"{"cracks": [{"joint": 13, "opening": -1}]}"#,
            &["right=u"],
            "cracks[0]",
        ),
        (
            r#"{"cracks": [], "bogus": 1}"#,
            &["right=u"],
            "invalid observations",
        ),
        (
            r#"{"cracks": []}"#,
            &["middle=u"],
            "no support named 'middle'",
        ),
    ];
    for (text, unknowns, needle) in cases {
        std::fs::write(&obs, text).unwrap();
        let mut args = vec![
            "identify",
            &arch,
            "--cracks",
            obs.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ];
        for u in unknowns {
            args.push("--unknown");
            args.push(u);
        }
        let o = run(&args);
        assert!(!o.status.success(), "{text} should fail");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
        assert!(err.contains(needle), "{err}");
        assert!(!out.exists());
    }
}

#[test]
fn identify_recovers_a_linear_settlement_profile_with_unknown_end_value() {
    // A running-bond wall (6 courses × 8 units of 0.4 m) whose foundation settles linearly from
    // 0 at x = 1.6 m to −2 cm at x = 3.2 m; the survey gives every cracked joint by number.
    let d = tmpdir("profile");
    let wall = d.join("wall.json");
    let o = run(&[
        "gen",
        "wall",
        "--courses",
        "6",
        "--units",
        "8",
        "-o",
        wall.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let wall = wall.to_str().unwrap();
    let f = run(&[
        "settle",
        wall,
        "--profile",
        "linear:1.6,0,3.2,-0.02",
        "--json",
    ]);
    assert!(f.status.success(), "{}", String::from_utf8_lossy(&f.stderr));
    let v: serde_json::Value = serde_json::from_slice(&f.stdout).unwrap();
    let mut cracks = Vec::new();
    for j in v["joints"].as_array().unwrap() {
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
    assert!(cracks.len() > 3, "{} cracked joints", cracks.len());
    let obs = d.join("obs.json");
    std::fs::write(&obs, serde_json::json!({ "cracks": cracks }).to_string()).unwrap();
    let o = run(&[
        "identify",
        wall,
        "--cracks",
        obs.to_str().unwrap(),
        "--unknown",
        "linear:1.6,0,3.2,?",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let a = r["unknowns"][0]["value"].as_f64().unwrap();
    assert!((a + 0.02).abs() <= 1e-6 * 0.02, "end value {a}");
    assert_eq!(r["certificate"]["reproduces"], true);
    // A '?' in a position, or a reversed range, is refused in one line.
    for bad in ["linear:?,0,3.2,1", "f7..f3=v"] {
        let o = run(&[
            "identify",
            wall,
            "--cracks",
            obs.to_str().unwrap(),
            "--unknown",
            bad,
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
}
