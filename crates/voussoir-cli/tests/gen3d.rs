//! `voussoir gen vault | dome | block | walls`: the written JSON reads back as a 3D model with
//! the counts and names the generators document; bad flags fail in one line without output.

use crate::common;
use crate::common::cwd::run;
use std::path::PathBuf;
use voussoir::model3d::{AnyModel, Load3d, Model3d};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("gen3d", name)
}

/// Run `gen ARGS -o FILE` and read FILE back as a 3D model.
fn generate(dir: &std::path::Path, name: &str, args: &[&str]) -> Model3d {
    let p = dir.join(format!("{name}.json"));
    let mut all = vec!["gen"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", p.to_str().unwrap()]);
    let o = run(&all);
    assert!(
        o.status.success(),
        "{all:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let text = std::fs::read_to_string(&p).unwrap();
    match AnyModel::from_json(&text).unwrap() {
        AnyModel::Spatial(m) => m,
        AnyModel::Planar(_) => panic!("{name}: read as a 2D model"),
    }
}

#[test]
fn gen_3d_models_read_back() {
    let d = tmpdir("ok");
    // Vault: 8 voussoirs; running bond over 3 rings: 8 + 9 + 8 blocks.
    let v = generate(
        &d,
        "vault",
        &[
            "vault",
            "--voussoirs",
            "8",
            "--radius",
            "2",
            "--thickness",
            "0.2",
            "--depth",
            "1.5",
            "--rings",
            "3",
            "--bond",
            "running",
            "--live",
            "left",
        ],
    );
    assert_eq!(v.blocks.len(), 25);
    let names: Vec<&str> = v.supports.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["left", "right"]);
    let ymax = v
        .blocks
        .iter()
        .flat_map(|b| b.vertices.iter().map(|p| p[1]))
        .fold(0.0, f64::max);
    assert_eq!(ymax, 1.5);
    assert!(!v.loads.live.is_empty());
    // Dome: 4 courses of 6 with an oculus, crown load shared by the top course.
    let m = generate(
        &d,
        "dome",
        &[
            "dome",
            "--radius",
            "3",
            "--thickness",
            "0.25",
            "--courses",
            "4",
            "--segments",
            "6",
            "--oculus",
            "15",
            "--crown-load",
            "6",
        ],
    );
    assert_eq!(m.blocks.len(), 24);
    assert_eq!(m.supports.len(), 6);
    assert_eq!(m.supports[5].name, "base5");
    let total: f64 = m
        .loads
        .live
        .iter()
        .map(|l| match l {
            Load3d::Point { force, .. } => force[2],
            _ => 0.0,
        })
        .sum();
    assert!((total + 6.0).abs() < 1e-12, "{total}");
    // Closed dome: (courses − 1)·segments + the cap.
    let m = generate(&d, "cap", &["dome", "--courses", "5", "--segments", "8"]);
    assert_eq!(m.blocks.len(), 33);
    assert!(m.loads.live.is_empty());
    // Block: azimuth 90° → [0, 1, 0] exactly.
    let b = generate(
        &d,
        "block",
        &["block", "--size", "0.5,0.4,1.2", "--azimuth", "90"],
    );
    assert_eq!(b.blocks.len(), 1);
    assert_eq!(b.supports[0].name, "base");
    assert!(matches!(
        &b.loads.live[..],
        [Load3d::Body { coefficients, .. }] if *coefficients == [0.0, 1.0, 0.0]
    ));
    let z: Vec<f64> = b.blocks[0].vertices.iter().map(|p| p[2]).collect();
    assert!(z.iter().all(|&z| z == 0.0 || z == 1.2));
    // Walls: U plan as in the library test (4 courses, 5 units of 0.4, t 0.2, R 1): 38 bricks.
    let w = generate(
        &d,
        "walls",
        &[
            "walls",
            "--plan",
            "U",
            "--length",
            "2",
            "--return-length",
            "1",
            "--thickness",
            "0.2",
            "--height",
            "1.2",
            "--courses",
            "4",
            "--units",
            "5",
            "--live",
            "all",
        ],
    );
    assert_eq!(w.blocks.len(), 38);
    assert_eq!(w.supports[0].name, "ground");
    assert!(matches!(
        &w.loads.live[..],
        [Load3d::Body { blocks: None, .. }]
    ));
    // Same flags, same bytes.
    let a = run(&["gen", "dome", "--courses", "3"]);
    let b = run(&["gen", "dome", "--courses", "3"]);
    assert!(a.status.success());
    assert_eq!(a.stdout, b.stdout);
}

#[test]
fn gen_3d_bad_flags_fail_in_one_line_without_output() {
    let d = tmpdir("bad");
    let out = d.join("out.json");
    let o = out.to_str().unwrap();
    for (args, needle) in [
        (vec!["dome", "--segments", "2"], "at least 3 segments"),
        (vec!["dome", "--oculus", "95"], "oculus half-angle"),
        (vec!["dome", "--half-angle", "120"], "half-angle must be in"),
        (vec!["vault", "--depth", "0"], "depth must be a positive"),
        (vec!["vault", "--rings", "0"], "rings must be at least 1"),
        (vec!["vault", "--width", "2"], "--width does not apply"),
        (
            vec!["vault", "--bond", "diagonal"],
            "invalid value 'diagonal'",
        ),
        (vec!["block", "--size", "1,2"], "expected B,D,H"),
        (vec!["block", "--size", "1,-2,3"], "three positive numbers"),
        (
            vec!["walls", "--plan", "L", "--return-length", "0.1"],
            "return length",
        ),
        (vec!["walls", "--plan", "Z"], "invalid value 'Z'"),
    ] {
        let mut all = vec!["gen"];
        all.extend_from_slice(&args);
        all.extend_from_slice(&["-o", o]);
        let r = run(&all);
        assert!(!r.status.success(), "{all:?} should fail");
        let err = String::from_utf8_lossy(&r.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
        assert!(
            err.starts_with("error: ") && err.contains(needle),
            "{all:?}: {err}"
        );
        assert!(!out.exists(), "no output file may be written");
    }
}
