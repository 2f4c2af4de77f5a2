//! Issue 30, item 1, on the command line: `voussoir gen wall --outline FILE` (a DXF drawing's
//! closed polylines or a JSON outline) meshed as a grid, a running bond or triangles on
//! foundation segments, and `voussoir gen facade --mesh triangles` settled.
//!
//! References: areas from closed forms; the physical bound of a settlement's work (W·v: no
//! element drops further than the 20 cm the foundation does); byte-identical output twice.

use crate::common::{json, refused, run, tmpdir, voussoir};
use serde_json::Value;
use std::path::Path;

const TAG: &str = "i30meshes";

fn area(p: &Value) -> f64 {
    let v: Vec<[f64; 2]> = p
        .as_array()
        .unwrap()
        .iter()
        .map(|q| [q[0].as_f64().unwrap(), q[1].as_f64().unwrap()])
        .collect();
    let n = v.len();
    0.5 * (0..n)
        .map(|i| v[i][0] * v[(i + 1) % n][1] - v[(i + 1) % n][0] * v[i][1])
        .sum::<f64>()
}

fn blocks_area(m: &Value) -> f64 {
    m["blocks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| area(&b["polygon"]))
        .sum()
}

/// A closed LWPOLYLINE (flag 70 = 1).
fn closed(handle: u32, layer: &str, pts: &[[f64; 2]]) -> String {
    let mut e = format!(
        "0\nLWPOLYLINE\n5\n{handle:X}\n8\n{layer}\n90\n{}\n70\n1\n",
        pts.len()
    );
    for p in pts {
        e.push_str(&format!("10\n{}\n20\n{}\n", p[0], p[1]));
    }
    e
}

/// A 6 × 4 m wall drawn in millimetres: outline with a 1 × 2 m door notch on layer WALL, two
/// 1 × 1 m windows on layer OPENINGS, and a stray closed polyline on layer NOTES.
fn drawing(dir: &Path) -> std::path::PathBuf {
    let mm =
        |p: &[[f64; 2]]| -> Vec<[f64; 2]> { p.iter().map(|q| [q[0] * 1e3, q[1] * 1e3]).collect() };
    let ents = [
        closed(
            0x10,
            "WALL",
            &mm(&[
                [0.0, 0.0],
                [2.5, 0.0],
                [2.5, 2.0],
                [3.5, 2.0],
                [3.5, 0.0],
                [6.0, 0.0],
                [6.0, 4.0],
                [0.0, 4.0],
            ]),
        ),
        closed(
            0x11,
            "OPENINGS",
            &mm(&[[0.8, 2.0], [1.8, 2.0], [1.8, 3.0], [0.8, 3.0]]),
        ),
        closed(
            0x12,
            "OPENINGS",
            &mm(&[[4.2, 2.0], [5.2, 2.0], [5.2, 3.0], [4.2, 3.0]]),
        ),
        closed(
            0x13,
            "NOTES",
            &mm(&[[10.0, 10.0], [11.0, 10.0], [11.0, 11.0]]),
        ),
    ];
    let text = format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{}0\nENDSEC\n0\nEOF\n",
        ents.concat()
    );
    let p = dir.join("wall.dxf");
    std::fs::write(&p, text).unwrap();
    p
}

const WALL_AREA: f64 = 6.0 * 4.0 - 1.0 * 2.0 - 2.0 * 1.0;

#[test]
fn issue30_item1_gen_wall_outline_from_dxf_layers_every_mesh() {
    let dir = tmpdir(TAG, "dxf");
    drawing(&dir);
    for (mesh, extra) in [
        ("grid", vec![]),
        ("running-bond", vec![]),
        ("triangles", vec!["--min-angle", "28"]),
    ] {
        let out = format!("{mesh}.json");
        let mut args = vec![
            "gen",
            "wall",
            "--outline",
            "wall.dxf",
            "--outer-layer",
            "wall",
            "--hole-layer",
            "OPENINGS",
            "--mesh",
            mesh,
            "--size",
            "0.4,0.2",
            "--segments",
            "3",
            "--unit-weight",
            "20",
            "--width",
            "0.5",
            "-o",
            &out,
        ];
        args.extend(extra);
        let o = voussoir(&dir, &args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "{mesh}: {err}");
        // The import line names what it used and what it did not.
        assert!(
            err.contains(
                "outer boundary LWPOLYLINE handle 10 (layer WALL), 2 opening(s), units mm"
            ) && err.contains("1 closed polylines on other layers"),
            "{err}"
        );
        let m = json(&std::fs::read_to_string(dir.join(&out)).unwrap());
        let a = blocks_area(&m);
        assert!((a - WALL_AREA).abs() <= 1e-9 * WALL_AREA, "{mesh}: {a} m²");
        let names: Vec<&str> = m["supports"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["name"].as_str().unwrap())
            .collect();
        assert_eq!(names, ["f0", "f1", "f2"], "{mesh}");
        assert_eq!(
            m["materials"]["default"]["unit_weight"].as_f64(),
            Some(20.0)
        );
        assert_eq!(m["materials"]["default"]["width"].as_f64(), Some(0.5));
        // It is a valid structure (plot builds it: simple polygons, no overlaps, joints).
        let png = format!("{mesh}.png");
        let c = voussoir(&dir, &["plot", &out, "-o", &png]);
        assert!(
            c.status.success(),
            "{mesh}: {}",
            String::from_utf8_lossy(&c.stderr)
        );
    }
}

#[test]
fn issue30_item1_gen_wall_outline_from_json_is_byte_identical_twice() {
    let dir = tmpdir(TAG, "json");
    std::fs::write(
        dir.join("o.json"),
        r#"{"outer": [[0, 0], [3, 0], [3, 2], [0, 2]], "holes": [[[1, 0.8], [2, 0.8], [2, 1.4], [1, 1.4]]]}"#,
    )
    .unwrap();
    for mesh in ["grid", "running-bond", "triangles"] {
        let a = run(
            &dir,
            &[
                "gen",
                "wall",
                "--outline",
                "o.json",
                "--mesh",
                mesh,
                "--size",
                "0.3",
            ],
        );
        let b = run(
            &dir,
            &[
                "gen",
                "wall",
                "--outline",
                "o.json",
                "--mesh",
                mesh,
                "--size",
                "0.3",
            ],
        );
        assert_eq!(a, b, "{mesh}: two runs differ");
        let m = json(&a);
        let want = 6.0 - 0.6;
        assert!((blocks_area(&m) - want).abs() <= 1e-9 * want, "{mesh}");
        assert_eq!(m["supports"][0]["name"], "base");
    }
}

#[test]
fn issue30_item1_outline_flags_are_refused_in_one_line() {
    let dir = tmpdir(TAG, "refuse");
    drawing(&dir);
    std::fs::write(
        dir.join("o.json"),
        r#"{"outer": [[0, 0], [3, 0], [3, 2], [0, 2]]}"#,
    )
    .unwrap();
    refused(
        &dir,
        &[
            "gen",
            "wall",
            "--outline",
            "o.json",
            "--mesh",
            "grid",
            "--min-angle",
            "20",
        ],
        "--min-angle 20: applies to --mesh triangles",
    );
    refused(
        &dir,
        &[
            "gen",
            "wall",
            "--outline",
            "o.json",
            "--mesh",
            "triangles",
            "--min-piece",
            "0.1",
        ],
        "--min-piece 0.1",
    );
    refused(
        &dir,
        &["gen", "wall", "--outline", "o.json", "--live", "full"],
        "--live full",
    );
    refused(
        &dir,
        &[
            "gen",
            "wall",
            "--outline",
            "o.json",
            "--outer-layer",
            "WALL",
        ],
        "apply to a DXF drawing",
    );
    refused(
        &dir,
        &[
            "gen",
            "wall",
            "--outline",
            "wall.dxf",
            "--outer-layer",
            "OPENINGS",
        ],
        "2 closed polylines",
    );
    refused(
        &dir,
        &[
            "gen",
            "wall",
            "--outline",
            "wall.dxf",
            "--outer-layer",
            "nothing",
        ],
        "no closed polyline on that layer",
    );
    // Without --hole-layer the NOTES polyline is a hole, outside the wall: named by entity.
    refused(
        &dir,
        &[
            "gen",
            "wall",
            "--outline",
            "wall.dxf",
            "--outer-layer",
            "WALL",
        ],
        "hole 2 (LWPOLYLINE handle 13 (layer NOTES)) lies outside the outer boundary",
    );
    refused(
        &dir,
        &["gen", "facade", "--mesh", "grid", "--min-angle", "25"],
        "--min-angle 25: applies to --mesh triangles",
    );
    // --outline and the courses of a generated wall exclude each other (clap's message).
    let o = voussoir(
        &dir,
        &["gen", "wall", "--outline", "o.json", "--courses", "4"],
    );
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot be used with"));
}

/// `gen facade --mesh triangles` (elements of at most 0.5 × 0.25 m²) with the right half
/// settling 20 cm: certified, a positive work below W·v, and a drawing.
#[test]
fn issue30_item1_facade_of_triangles_settles_certified_with_a_picture() {
    let dir = tmpdir(TAG, "facade");
    run(
        &dir,
        &["gen", "facade", "--mesh", "triangles", "-o", "tri.json"],
    );
    let again = run(&dir, &["gen", "facade", "--mesh", "triangles"]);
    assert_eq!(
        std::fs::read_to_string(dir.join("tri.json")).unwrap(),
        again
    );
    let m = json(&again);
    let gamma = m["materials"]["default"]["unit_weight"].as_f64().unwrap();
    let w_total = gamma * blocks_area(&m);
    let o = voussoir(
        &dir,
        &[
            "settle",
            "tri.json",
            "--profile",
            "uniform:11,22,-0.2",
            "-o",
            "s.json",
            "--png",
            "s.png",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = json(&std::fs::read_to_string(dir.join("s.json")).unwrap());
    assert_eq!(r["status"], "mechanism", "{}", r["message"]);
    let gap = r["certificate"]["relative_gap"].as_f64().unwrap();
    assert!(
        r["certificate"]["ok"].as_bool().unwrap() && gap < 1e-7,
        "{}",
        r["certificate"]
    );
    let work = r["work_dead_loads"].as_f64().unwrap();
    assert!(
        work > 0.0 && work <= w_total * 0.2,
        "work {work}, W·v = {}",
        w_total * 0.2
    );
    assert!(std::fs::metadata(dir.join("s.png")).unwrap().len() > 10_000);
}
