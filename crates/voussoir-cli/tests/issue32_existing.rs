//! Issue 32 item 2: a DXF crack survey as a model's EXISTING cracks — `--existing-cracks
//! SURVEY.dxf` on a JSON model, `--crack-layer NAME` on a `.dxf` model (import and every
//! analysis reading a drawing).
//!
//! The case is docs/joint-laws.md's (crates/voussoir/tests/existing_cracks.rs): the paper's arch
//! (intrados radius 2.86 m, 64 voussoirs) made 0.45 m thick, a live load on its left half, a
//! 3 mm crack at the crown's intrados (0, 2.86). References: the same crack written in the
//! model JSON (results byte-identical), and the hand calculation of the closing supports: the
//! crown's intrados closes at 0.45·s/3.31, so the 3 mm crack closes at s = 0.003·3.31/0.45.

use crate::common::cwd::run;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

fn ok(args: &[&str]) -> String {
    let o = run(args);
    assert!(
        o.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8(o.stdout).unwrap()
}

/// The one `error:` line of a failed run (and nothing on stdout).
fn one_error(args: &[&str]) -> String {
    let o = run(args);
    assert!(!o.status.success(), "{args:?} succeeded");
    assert!(o.stdout.is_empty(), "{args:?}");
    let e = String::from_utf8_lossy(&o.stderr).to_string();
    let errors: Vec<&str> = e.lines().filter(|l| l.starts_with("error:")).collect();
    assert_eq!(errors.len(), 1, "{e}");
    errors[0].to_string()
}

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-issue32e-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// An ASCII DXF in millimetres ($INSUNITS 4) of the given entities, written to `dir/name`.
fn dxf(dir: &Path, name: &str, entities: &[String]) -> PathBuf {
    let text = format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n{}0\nENDSEC\n0\nEOF\n",
        entities.concat()
    );
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// An LWPOLYLINE (closed or open) of points in metres, written in mm.
fn lwpolyline(handle: &str, layer: &str, pts: &[[f64; 2]], closed: bool) -> String {
    let mut e = format!(
        "0\nLWPOLYLINE\n5\n{handle}\n8\n{layer}\n90\n{}\n70\n{}\n",
        pts.len(),
        u8::from(closed)
    );
    for p in pts {
        e.push_str(&format!("10\n{}\n20\n{}\n", p[0] * 1e3, p[1] * 1e3));
    }
    e
}

/// A TEXT label at a point in metres (written in mm), 20 mm high.
fn text(handle: &str, layer: &str, at: [f64; 2], value: &str) -> String {
    format!(
        "0\nTEXT\n5\n{handle}\n8\n{layer}\n10\n{}\n20\n{}\n30\n0\n40\n20\n1\n{value}\n",
        at[0] * 1e3,
        at[1] * 1e3
    )
}

/// The thick arch of docs/joint-laws.md, without cracks.
fn thick_arch(dir: &Path) -> PathBuf {
    let p = dir.join("arch.json");
    ok(&[
        "gen",
        "arch",
        "--radius",
        "2.86",
        "--radius-at",
        "intrados",
        "--thickness",
        "0.45",
        "--voussoirs",
        "64",
        "--live",
        "left",
        "-o",
        s(&p),
    ]);
    p
}

fn with_cracks(model: &Path, cracks: Value, name: &str) -> PathBuf {
    let mut m: Value = serde_json::from_str(&std::fs::read_to_string(model).unwrap()).unwrap();
    m["cracks"] = cracks;
    let p = model.with_file_name(name);
    std::fs::write(&p, m.to_string()).unwrap();
    p
}

/// The crack as a surveyor draws it: from the crown's intrados up the joint, 12 cm.
const CRACK: [[f64; 2]; 2] = [[0.0, 2.86], [0.0, 2.98]];

fn json_of(args: &[&str]) -> Value {
    serde_json::from_str(&ok(args)).unwrap()
}

#[test]
fn issue32_item2_existing_cracks_from_a_survey_drawing_equal_the_model_json() {
    let d = tmpdir("same");
    let arch = thick_arch(&d);
    // The test case of docs/joint-laws.md: the crack by its point, in metres.
    let by_point = with_cracks(
        &arch,
        json!([{"at": [0.0, 2.86], "opening": 0.003}]),
        "at.json",
    );
    // The survey: the width as a label, or in the layer's name.
    let labelled = dxf(
        &d,
        "labelled.dxf",
        &[
            lwpolyline("A1", "CRACKS", &CRACK, false),
            text("A2", "CRACKS", [0.02, 2.90], "3 mm"),
        ],
    );
    let layer_named = dxf(
        &d,
        "layer.dxf",
        &[lwpolyline("B1", "CRACK-3mm", &CRACK, false)],
    );
    let a = s(&arch);
    for cmd in [
        vec!["limit"],
        vec!["settle", "--move", "right=-0.01,0"],
        vec!["capacity", "--move", "right=-0.04,0", "--steps", "20"],
        vec!["tilt"],
        vec!["safety"],
    ] {
        let mut reference = cmd.clone();
        reference.extend([s(&by_point), "--json"]);
        let reference = ok(&reference);
        for survey in [&labelled, &layer_named] {
            let mut args = cmd.clone();
            args.extend([a, "--existing-cracks", s(survey), "--json"]);
            assert!(
                ok(&args) == reference,
                "{cmd:?} with {}: not the same result JSON as the crack in the model",
                survey.display()
            );
        }
    }
    // The survey is not ignored: the sound arch's λ is more than twice the cracked one's.
    let sound = json_of(&["limit", a, "--json"])["load_multiplier"]
        .as_f64()
        .unwrap();
    let cracked = json_of(&["limit", a, "--existing-cracks", s(&labelled), "--json"])
        ["load_multiplier"]
        .as_f64()
        .unwrap();
    assert!(cracked < 0.5 * sound, "cracked {cracked} vs sound {sound}");
    // Hand calculation: closing supports close the crown's intrados at 0.45·s/3.31.
    let rate = 0.45 / 3.31;
    let r = json_of(&[
        "settle",
        a,
        "--existing-cracks",
        s(&labelled),
        "--move",
        "right=-0.01,0",
        "--json",
    ]);
    let p = &r["joints"][32]["points"][0];
    assert!(
        (p["x"].as_f64().unwrap()).abs() < 1e-9 && (p["y"].as_f64().unwrap() - 2.86).abs() < 1e-9
    );
    assert_eq!(p["gap"].as_f64(), Some(0.003));
    let opening = p["opening"].as_f64().unwrap();
    assert!((opening + rate * 0.01).abs() < 1e-9, "{opening}");
    let c = json_of(&[
        "capacity",
        a,
        "--existing-cracks",
        s(&layer_named),
        "--move",
        "right=-0.04,0",
        "--steps",
        "20",
        "--json",
    ]);
    let closed = c["existing_cracks_closed_at"].as_f64().unwrap();
    let hand = 0.003 / rate;
    assert!(
        (closed - hand).abs() < 2e-6,
        "closed at {closed}, hand {hand}"
    );
}

/// The arch of `thick_arch` as a drawing: blocks on layer 0, supports on layer SUPPORTS, and
/// crack lines on `cracks`.
fn arch_drawing(d: &Path, arch: &Path, name: &str, cracks: &[String]) -> PathBuf {
    let m: Value = serde_json::from_str(&std::fs::read_to_string(arch).unwrap()).unwrap();
    let poly = |v: &Value| -> Vec<[f64; 2]> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|p| [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()])
            .collect()
    };
    let mut ents = Vec::new();
    for (i, b) in m["blocks"].as_array().unwrap().iter().enumerate() {
        ents.push(lwpolyline(
            &format!("{:X}", 0x100 + i),
            "0",
            &poly(&b["polygon"]),
            true,
        ));
    }
    for (i, b) in m["supports"].as_array().unwrap().iter().enumerate() {
        ents.push(lwpolyline(
            &format!("{:X}", 0x200 + i),
            "SUPPORTS",
            &poly(&b["polygon"]),
            true,
        ));
    }
    ents.extend(cracks.iter().cloned());
    dxf(d, name, &ents)
}

/// The extrados point of joint k of the 64-voussoir arch and a point 12 cm down the joint.
fn radial(k: f64) -> [[f64; 2]; 2] {
    let t = std::f64::consts::PI * (1.0 - k / 64.0);
    [
        [3.31 * t.cos(), 3.31 * t.sin()],
        [3.19 * t.cos(), 3.19 * t.sin()],
    ]
}

#[test]
fn issue32_item2_a_drawing_with_a_crack_layer_imports_with_its_cracks() {
    let d = tmpdir("import");
    let arch = thick_arch(&d);
    let j12 = radial(12.0);
    let drawing = arch_drawing(
        &d,
        &arch,
        "arch.dxf",
        &[
            lwpolyline("C1", "CRACK-3mm", &CRACK, false),
            lwpolyline("C2", "CRACKS", &j12, false),
            text("C3", "CRACKS", [j12[0][0] - 0.03, j12[0][1]], "w = 2"),
        ],
    );
    let out = d.join("imported.json");
    let o = run(&[
        "import",
        s(&drawing),
        "--support-layer",
        "SUPPORTS",
        "--crack-layer",
        "CRACK*",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("64 blocks, 2 support(s)") && err.contains("2 existing crack line(s)"),
        "{err}"
    );
    let m: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(m["blocks"].as_array().unwrap().len(), 64);
    let cracks = m["cracks"].as_array().unwrap();
    assert_eq!(cracks.len(), 2, "{cracks:?}");
    for (c, (line, width)) in cracks.iter().zip([(CRACK, 0.003), (j12, 0.002)]) {
        let pl = c["polyline"].as_array().unwrap();
        assert_eq!(pl.len(), 2);
        for (p, q) in pl.iter().zip(line) {
            for k in 0..2 {
                assert!((p[k].as_f64().unwrap() - q[k]).abs() < 1e-12, "{c}");
            }
        }
        let w = c["opening"].as_f64().unwrap();
        assert!((w - width).abs() < 1e-15, "{c}");
    }
    // The model's points get their gaps: the crown's intrados 3 mm, joint 12's extrados 2 mm;
    // the other ends are sound (no gap written).
    let r = json_of(&["settle", s(&out), "--move", "SUPPORTS-1=-0.01,0", "--json"]);
    let gap = |j: usize, k: usize| {
        let p = &r["joints"][j]["points"][k];
        let at = [p["x"].as_f64().unwrap(), p["y"].as_f64().unwrap()];
        (at, p["gap"].as_f64().unwrap_or(0.0))
    };
    let near = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) < 1e-9;
    let (crown, j12x) = (gap(32, 0), gap(12, 1));
    assert!(
        near(crown.0, CRACK[0]) && (crown.1 - 0.003).abs() < 1e-15,
        "{crown:?}"
    );
    assert!(
        near(j12x.0, j12[0]) && (j12x.1 - 0.002).abs() < 1e-15,
        "{j12x:?}"
    );
    assert_eq!((gap(32, 1).1, gap(12, 0).1), (0.0, 0.0));
    // Every analysis reading the drawing takes the flag: the same result as the imported JSON.
    let direct = ok(&[
        "limit",
        s(&drawing),
        "--support-layer",
        "SUPPORTS",
        "--crack-layer",
        "CRACK*",
        "--json",
    ]);
    assert!(direct == ok(&["limit", s(&out), "--json"]));
    // And the same λ as the same cracks written by hand in the imported model (the drawing's
    // loads: self-weight and the horizontal live load), to the mm round trip of the lines.
    let written = with_cracks(
        &out,
        json!([
            {"polyline": CRACK, "opening": 3, "units": "mm"},
            {"polyline": j12, "opening": 2, "units": "mm"}
        ]),
        "written.json",
    );
    let l1 = json_of(&["limit", s(&written), "--json"])["load_multiplier"]
        .as_f64()
        .unwrap();
    let l2: Value = serde_json::from_str(&direct).unwrap();
    let l2 = l2["load_multiplier"].as_f64().unwrap();
    assert!((l1 - l2).abs() <= 1e-9 * l1, "{l1} vs {l2}");
}

#[test]
fn issue32_item2_existing_crack_refusals_name_the_entity() {
    let d = tmpdir("refusals");
    let arch = thick_arch(&d);
    let a = s(&arch);
    let notes = dxf(
        &d,
        "notes.dxf",
        &[
            lwpolyline("E1", "NOTES", &CRACK, false),
            text("E2", "CRACKS", [0.02, 2.9], "3 mm"),
        ],
    );
    // A layer with no lines.
    let e = one_error(&[
        "limit",
        a,
        "--existing-cracks",
        s(&notes),
        "--survey-layer",
        "CRACKS",
    ]);
    assert!(
        e.contains("--existing-cracks")
            && e.contains("no crack line")
            && e.contains("layer(s) CRACKS"),
        "{e}"
    );
    let drawing = arch_drawing(&d, &arch, "arch.dxf", &[]);
    let e = one_error(&["import", s(&drawing), "--crack-layer", "CRACKS"]);
    assert!(
        e.contains("no crack line") && e.contains("layer(s) CRACKS"),
        "{e}"
    );
    // A line catching no joint: named by its entity, and no output file written.
    let far = dxf(
        &d,
        "far.dxf",
        &[lwpolyline(
            "D1",
            "CRACK-3mm",
            &[[5.0, 5.0], [5.0, 5.1]],
            false,
        )],
    );
    let out = d.join("r.json");
    let e = one_error(&[
        "settle",
        a,
        "--move",
        "right=0,-0.01",
        "--existing-cracks",
        s(&far),
        "-o",
        s(&out),
    ]);
    assert!(
        e.contains("cracks[0] (LWPOLYLINE handle D1 (layer CRACK-3mm) of")
            && e.contains("catches no joint point"),
        "{e}"
    );
    assert!(!out.exists());
    let far_drawing = arch_drawing(
        &d,
        &arch,
        "far-arch.dxf",
        &[lwpolyline(
            "D2",
            "CRACK-3mm",
            &[[5.0, 5.0], [5.0, 5.1]],
            false,
        )],
    );
    for cmd in ["import", "limit"] {
        let e = one_error(&[cmd, s(&far_drawing), "--crack-layer", "CRACK-3mm"]);
        assert!(
            e.contains("cracks[0] (LWPOLYLINE handle D2 (layer CRACK-3mm))")
                && e.contains("catches no joint point"),
            "{e}"
        );
    }
    // A line with no width.
    let bare = dxf(&d, "bare.dxf", &[lwpolyline("F1", "CRACKS", &CRACK, false)]);
    let e = one_error(&["limit", a, "--existing-cracks", s(&bare)]);
    assert!(
        e.contains("LWPOLYLINE handle F1 (layer CRACKS): no width"),
        "{e}"
    );
    // A survey flag without its file; the DXF flag on a JSON model; identify; a 3D model.
    let e = one_error(&["limit", a, "--survey-layer", "CRACKS"]);
    assert!(
        e.contains("--survey-layer") && e.contains("--existing-cracks FILE.dxf"),
        "{e}"
    );
    let e = one_error(&["tilt", a, "--survey-snap", "0.1"]);
    assert!(
        e.contains("--survey-snap") && e.contains("--existing-cracks FILE.dxf"),
        "{e}"
    );
    let e = one_error(&["limit", a, "--crack-layer", "CRACKS"]);
    assert!(
        e.contains("--crack-layer") && e.contains("--existing-cracks"),
        "{e}"
    );
    let e = one_error(&[
        "identify",
        a,
        "--survey",
        s(&far),
        "--existing-cracks",
        s(&far),
        "--unknown",
        "right=v",
    ]);
    assert!(
        e.contains("--existing-cracks") && e.contains("sound structure"),
        "{e}"
    );
    let block = d.join("block.json");
    ok(&["gen", "block", "-o", s(&block)]);
    let e = one_error(&["limit", s(&block), "--existing-cracks", s(&far)]);
    assert!(e.contains("--existing-cracks applies to 2D models"), "{e}");
}
