//! Issue 32 item 2 from the command line: observations in millimetres, crack lines in JSON and
//! a survey drawing (DXF) of the paper arch's settlement cracks, written from its forward run.
//! References: the forward settlement's motion (identify's own tests' tolerance, 1e-6
//! relative) and the same survey in metres.

use crate::common::cwd::run;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::process::Output;

fn ok(o: &Output) -> String {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8(o.stdout.clone()).unwrap()
}

/// The one `error:` line of a failed run.
fn one_error(o: &Output) -> String {
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr).to_string();
    let errors: Vec<&str> = e.lines().filter(|l| l.starts_with("error:")).collect();
    assert_eq!(errors.len(), 1, "{e}");
    errors[0].to_string()
}

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-issue32s-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The paper's arch (docs/identify.md): intrados radius 2.86 m, 0.33 m, 64 voussoirs.
fn paper_arch(dir: &Path) -> PathBuf {
    let p = dir.join("arch.json");
    ok(&run(&[
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
        s(&p),
    ]));
    p
}

/// The forward settlement: the right springing, tied to the arch, settles 1 cm.
const SETTLE: [&str; 4] = ["--move", "right=0,-0.01", "--fixed", "right"];

/// Open points of a saved settlement result: (joint, point, mouth [x, y], other end, width).
type Open = (u64, usize, [f64; 2], [f64; 2], f64);

fn open_points(result: &str) -> Vec<Open> {
    let v: Value = serde_json::from_str(result).unwrap();
    let mut all = Vec::new();
    for j in v["joints"].as_array().unwrap() {
        let pts = j["points"].as_array().unwrap();
        for (k, p) in pts.iter().enumerate() {
            let q = &pts[1 - k];
            all.push((
                j["id"].as_u64().unwrap(),
                k,
                [p["x"].as_f64().unwrap(), p["y"].as_f64().unwrap()],
                [q["x"].as_f64().unwrap(), q["y"].as_f64().unwrap()],
                p["opening"].as_f64().unwrap(),
            ));
        }
    }
    let omax = all.iter().fold(0.0f64, |m, o| m.max(o.4));
    all.retain(|o| o.4 > 1e-7 * omax);
    all
}

/// A crack line as a surveyor draws it: from the mouth along the joint, 40 % of the way.
fn line(o: &Open) -> [[f64; 2]; 2] {
    let (p, q) = (o.2, o.3);
    [p, [p[0] + 0.4 * (q[0] - p[0]), p[1] + 0.4 * (q[1] - p[1])]]
}

/// An ASCII DXF in millimetres ($INSUNITS 4, or none) of the given entities.
fn dxf(entities: &[String], insunits: Option<i32>) -> String {
    let header = match insunits {
        Some(u) => format!("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n{u}\n0\nENDSEC\n"),
        None => String::new(),
    };
    format!(
        "{header}0\nSECTION\n2\nENTITIES\n{}0\nENDSEC\n0\nEOF\n",
        entities.concat()
    )
}

fn lwpolyline(handle: u32, layer: &str, pts: &[[f64; 2]]) -> String {
    let mut e = format!(
        "0\nLWPOLYLINE\n5\n{handle:X}\n8\n{layer}\n90\n{}\n70\n0\n",
        pts.len()
    );
    for p in pts {
        e.push_str(&format!("10\n{}\n20\n{}\n", p[0], p[1]));
    }
    e
}

fn line_entity(handle: u32, layer: &str, a: [f64; 2], b: [f64; 2]) -> String {
    format!(
        "0\nLINE\n5\n{handle:X}\n8\n{layer}\n10\n{}\n20\n{}\n30\n0\n11\n{}\n21\n{}\n31\n0\n",
        a[0], a[1], b[0], b[1]
    )
}

fn text(handle: u32, layer: &str, at: [f64; 2], height: f64, value: &str) -> String {
    format!(
        "0\nTEXT\n5\n{handle:X}\n8\n{layer}\n10\n{}\n20\n{}\n30\n0\n40\n{height}\n1\n{value}\n",
        at[0], at[1]
    )
}

fn mm(p: [f64; 2]) -> [f64; 2] {
    [p[0] * 1000.0, p[1] * 1000.0]
}

/// The survey drawing of the forward run's cracks: one line per crack (the first as a LINE,
/// the others LWPOLYLINEs) on layer CRACKS, each with a TEXT label of its width in mm at full
/// precision 2 cm beside its end; a title on the layer and an outline on another layer.
fn survey_drawing(open: &[Open]) -> String {
    let mut e = Vec::new();
    let mut h = 0x100;
    for (i, o) in open.iter().enumerate() {
        let [a, b] = line(o);
        let (a, b) = (mm(a), mm(b));
        h += 2;
        e.push(if i == 0 {
            line_entity(h, "CRACKS", a, b)
        } else {
            lwpolyline(h, "CRACKS", &[a, b])
        });
        e.push(text(
            h + 1,
            "CRACKS",
            [b[0] + 20.0, b[1]],
            25.0,
            &format!("{:.12} mm", o.4 * 1000.0),
        ));
    }
    e.push(text(
        0x90,
        "CRACKS",
        [0.0, 5000.0],
        50.0,
        "Crack survey 2026",
    ));
    e.push(lwpolyline(
        0x91,
        "OUTLINE",
        &[[-3500.0, 0.0], [3500.0, 0.0]],
    ));
    dxf(&e, Some(4))
}

fn identify_json(args: &[&str]) -> Value {
    let mut all = vec!["identify"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--json"]);
    serde_json::from_str(&ok(&run(&all))).unwrap()
}

/// identify's criterion in its tests: the motion to 1e-6 relative, reproduced, no misfit.
fn assert_recovers(r: &Value, truth: f64) {
    assert_eq!(r["status"], "identified", "{}", r["message"]);
    let v = r["unknowns"][0]["value"].as_f64().unwrap();
    assert!((v - truth).abs() <= 1e-6 * truth.abs(), "{v} vs {truth}");
    assert_eq!(r["certificate"]["reproduces"], true, "{}", r["certificate"]);
    assert!(r["total_misfit"].as_f64().unwrap() < 1e-4);
}

/// The observed points of an identify result: (joint, point, observed width).
fn observed(r: &Value) -> Vec<(u64, usize, f64)> {
    r["observations"]
        .as_array()
        .unwrap()
        .iter()
        .map(|o| {
            (
                o["joint"].as_u64().unwrap(),
                o["point"].as_u64().unwrap() as usize,
                o["observed"].as_f64().unwrap(),
            )
        })
        .collect()
}

#[test]
fn issue32_item2_a_survey_drawing_identifies_the_paper_arch_settlement() {
    let d = tmpdir("dxf");
    let arch = paper_arch(&d);
    let fwd = ok(&run(
        &[&["settle", s(&arch)][..], &SETTLE, &["--json"]].concat()
    ));
    let open = open_points(&fwd);
    assert_eq!(
        open.iter().map(|o| o.0).collect::<Vec<_>>(),
        vec![1, 13, 32]
    );
    let survey = d.join("survey.dxf");
    std::fs::write(&survey, survey_drawing(&open)).unwrap();
    let o = run(&[
        "identify",
        s(&arch),
        "--survey",
        s(&survey),
        "--unknown",
        "right=v",
        "--fixed",
        "right",
        "--json",
    ]);
    let r: Value = serde_json::from_str(&ok(&o)).unwrap();
    assert_recovers(&r, -0.01);
    // The lines caught exactly the forward open points, with their widths.
    let got = observed(&r);
    assert_eq!(got.len(), open.len());
    for (g, o) in got.iter().zip(&open) {
        assert_eq!((g.0, g.1), (o.0, o.1));
        assert!((g.2 - o.4).abs() <= 1e-12 * o.4, "{} vs {}", g.2, o.4);
    }
    // What was read is said on stderr: three lines, the title is not a width.
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("survey: 3 crack line(s) on layer(s) CRACKS, coordinates in mm"),
        "{err}"
    );
    assert!(err.contains("'Crack survey 2026' is not a width"), "{err}");
    // The survey layer named explicitly, and the layer's case does not matter.
    let r = identify_json(&[
        s(&arch),
        "--survey",
        s(&survey),
        "--survey-layer",
        "cracks",
        "--unknown",
        "right=v",
        "--fixed",
        "right",
    ]);
    assert_recovers(&r, -0.01);
}

#[test]
fn issue32_item2_crack_lines_in_json_identify_the_paper_arch_settlement() {
    let d = tmpdir("json-lines");
    let arch = paper_arch(&d);
    let open = open_points(&ok(&run(&[
        &["settle", s(&arch)][..],
        &SETTLE,
        &["--json"],
    ]
    .concat())));
    // Coordinates in mm as read off the drawing, widths in mm.
    let cracks: Vec<Value> = open
        .iter()
        .map(|o| {
            let [a, b] = line(o);
            json!({"polyline": [mm(a), mm(b)], "opening": o.4 * 1000.0})
        })
        .collect();
    let obs = d.join("lines.json");
    std::fs::write(
        &obs,
        json!({"units": "mm", "coordinate_units": "mm", "tolerance": 0.1, "cracks": cracks})
            .to_string(),
    )
    .unwrap();
    let r = identify_json(&[
        s(&arch),
        "--cracks",
        s(&obs),
        "--unknown",
        "right=v",
        "--fixed",
        "right",
    ]);
    assert_recovers(&r, -0.01);
    let got: Vec<(u64, usize)> = observed(&r).iter().map(|g| (g.0, g.1)).collect();
    let want: Vec<(u64, usize)> = open.iter().map(|o| (o.0, o.1)).collect();
    assert_eq!(got, want);
}

/// Every number equal within 1e-12 relative (both below 1e-9: round-off zeros, as the misfits
/// of exact widths), everything else identical; messages compared word by word.
fn assert_same(a: &Value, b: &Value, path: &str) {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(y.abs()) || (x.abs() < 1e-9 && y.abs() < 1e-9),
                "{path}: {x} vs {y}"
            );
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "{path}");
            for (i, (p, q)) in x.iter().zip(y).enumerate() {
                assert_same(p, q, &format!("{path}[{i}]"));
            }
        }
        (Value::Object(x), Value::Object(y)) => {
            assert_eq!(x.keys().collect::<Vec<_>>(), y.keys().collect::<Vec<_>>());
            for (k, p) in x {
                assert_same(p, &y[k], &format!("{path}.{k}"));
            }
        }
        (Value::String(x), Value::String(y)) => {
            let words = |t: &str| -> Vec<String> {
                t.split(|c: char| c.is_whitespace() || c == ',' || c == '(' || c == ')')
                    .map(|w| w.trim_end_matches(['.', ';', ':']).to_string())
                    .collect()
            };
            let (wx, wy) = (words(x), words(y));
            assert_eq!(wx.len(), wy.len(), "{path}: {x} vs {y}");
            for (p, q) in wx.iter().zip(&wy) {
                match (p.parse::<f64>(), q.parse::<f64>()) {
                    (Ok(u), Ok(v)) => assert_same(&json!(u), &json!(v), path),
                    _ => assert_eq!(p, q, "{path}: {x} vs {y}"),
                }
            }
        }
        _ => assert_eq!(a, b, "{path}"),
    }
}

#[test]
fn issue32_item2_units_mm_equals_metres_from_the_command_line() {
    let d = tmpdir("units");
    let arch = paper_arch(&d);
    let open = open_points(&ok(&run(&[
        &["settle", s(&arch)][..],
        &SETTLE,
        &["--json"],
    ]
    .concat())));
    let write = |name: &str, v: Value| {
        let p = d.join(name);
        std::fs::write(&p, v.to_string()).unwrap();
        p
    };
    // The crack at joint 13 is under plaster: left out, its surroundings unobserved.
    let listed: Vec<&Open> = open.iter().filter(|o| o.0 != 13).collect();
    let metres = write(
        "m.json",
        json!({"tolerance": 1e-4,
            "cracks": listed.iter().map(|o| json!({"at": o.2, "opening": o.4})).collect::<Vec<_>>(),
            "unobserved": [{"region": [-2.7, 1.8, -2.4, 2.0]}]}),
    );
    let millimetres = write(
        "mm.json",
        json!({"units": "mm", "tolerance": 0.1, "coordinate_units": "mm",
            "cracks": listed.iter().map(|o| json!({"at": mm(o.2), "opening": o.4 * 1000.0})).collect::<Vec<_>>(),
            "unobserved": [{"region": [-2700.0, 1800.0, -2400.0, 2000.0]}]}),
    );
    let answer = |obs: &Path| {
        identify_json(&[
            s(&arch),
            "--cracks",
            s(obs),
            "--unknown",
            "right=v",
            "--fixed",
            "right",
        ])
    };
    let (a, b) = (answer(&metres), answer(&millimetres));
    assert_recovers(&a, -0.01);
    assert_same(&a, &b, "result");
    // Joint 13 predicted open where it was not observed, in both (the region was scaled).
    for r in [&a, &b] {
        let c13: Vec<&Value> = r["predicted_cracks"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["joint"] == 13)
            .collect();
        assert_eq!(c13.len(), 1, "{}", r["predicted_cracks"]);
        assert_eq!(c13[0]["observed"], "unobserved");
    }
}

#[test]
fn issue32_item2_layer_name_widths_units_and_refusals() {
    let d = tmpdir("layers");
    let arch = paper_arch(&d);
    let open = open_points(&ok(&run(&[
        &["settle", s(&arch)][..],
        &SETTLE,
        &["--json"],
    ]
    .concat())));
    // Widths in the layer names, rounded to 0.1 mm as a surveyor's classes; no $INSUNITS.
    let classes = ["CRACK-1.9mm", "CRACK-4.1mm", "CRACK-2.2mm"];
    let e: Vec<String> = open
        .iter()
        .zip(classes)
        .enumerate()
        .map(|(i, (o, layer))| {
            let [a, b] = line(o);
            lwpolyline(0x200 + i as u32, layer, &[mm(a), mm(b)])
        })
        .collect();
    let survey = d.join("layers.dxf");
    std::fs::write(&survey, dxf(&e, None)).unwrap();
    let args = |extra: &[&'static str]| -> Vec<String> {
        let mut v: Vec<String> = vec![
            "identify".into(),
            s(&arch).into(),
            "--survey".into(),
            s(&survey).into(),
            "--unknown".into(),
            "right=v".into(),
            "--fixed".into(),
            "right".into(),
        ];
        v.extend(extra.iter().map(|x| x.to_string()));
        v
    };
    let refs = |v: &[String]| -> Output { run(&v.iter().map(|x| x.as_str()).collect::<Vec<_>>()) };
    // The drawing declares no units: asked for, in one line.
    let e = one_error(&refs(&args(&[])));
    assert!(e.contains("pass --units mm|cm|m"), "{e}");
    // --units (a JSON model: the survey's) and --survey-units both honoured.
    for flag in [["--units", "mm"], ["--survey-units", "mm"]] {
        let o = refs(&args(&[flag[0], flag[1], "--json"]));
        let r: Value = serde_json::from_str(&ok(&o)).unwrap();
        assert_eq!(r["status"], "identified", "{}", r["message"]);
        let widths: Vec<f64> = observed(&r).iter().map(|g| g.2).collect();
        for (w, want) in widths.iter().zip([1.9e-3, 4.1e-3, 2.2e-3]) {
            assert!((w - want).abs() <= 1e-15, "{w} vs {want}");
        }
        // Rounded widths: the settlement within the identifiability range, near 1 cm.
        let v = r["unknowns"][0]["value"].as_f64().unwrap();
        assert!((v + 0.01).abs() < 0.02 * 0.01, "{v}");
    }
    // A line with no width anywhere is refused naming its entity; no output file.
    let bare = d.join("bare.dxf");
    std::fs::write(
        &bare,
        dxf(
            &[lwpolyline(0x2F, "CRACKS", &[[0.0, 2860.0], [0.0, 2990.0]])],
            Some(4),
        ),
    )
    .unwrap();
    let out = d.join("never.json");
    let e = one_error(&run(&[
        "identify",
        s(&arch),
        "--survey",
        s(&bare),
        "--unknown",
        "right=v",
        "-o",
        s(&out),
    ]));
    assert!(
        e.contains("LWPOLYLINE handle 2F (layer CRACKS): no width"),
        "{e}"
    );
    assert!(!out.exists());
    // A line far from every joint: refused naming the crack and its entity.
    let far = d.join("far.dxf");
    std::fs::write(
        &far,
        dxf(
            &[lwpolyline(
                0x30,
                "CRACK-1mm",
                &[[0.0, 9000.0], [10.0, 9000.0]],
            )],
            Some(4),
        ),
    )
    .unwrap();
    let e = one_error(&run(&[
        "identify",
        s(&arch),
        "--survey",
        s(&far),
        "--unknown",
        "right=v",
    ]));
    assert!(
        e.contains("cracks[0] (LWPOLYLINE handle 30 (layer CRACK-1mm) of")
            && e.contains("catches no joint point"),
        "{e}"
    );
    // Survey flags without a survey, no observations at all, unknown units in a file.
    let e = one_error(&run(&[
        "identify",
        s(&arch),
        "--survey-layer",
        "CRACKS",
        "--unknown",
        "right=v",
    ]));
    assert!(
        e.contains("--survey-layer applies to a survey drawing"),
        "{e}"
    );
    let e = one_error(&run(&["identify", s(&arch), "--unknown", "right=v"]));
    assert!(
        e.contains("--cracks OBS.json, --survey SURVEY.dxf, or both"),
        "{e}"
    );
    let bad = d.join("bad.json");
    std::fs::write(&bad, r#"{"units": "inches", "cracks": []}"#).unwrap();
    let e = one_error(&run(&[
        "identify",
        s(&arch),
        "--cracks",
        s(&bad),
        "--unknown",
        "right=v",
    ]));
    assert!(e.contains(r#""units": unknown unit "inches""#), "{e}");
}

/// An existing crack given as a line (width in mm) is the same crack as given by joint: the
/// settlement of the cracked arch is the same.
#[test]
fn issue32_item2_existing_crack_polyline_from_the_command_line() {
    let d = tmpdir("existing");
    let arch = paper_arch(&d);
    let model: Value = serde_json::from_str(&std::fs::read_to_string(&arch).unwrap()).unwrap();
    let with = |cracks: Value, name: &str| {
        let mut m = model.clone();
        m["cracks"] = cracks;
        let p = d.join(name);
        std::fs::write(&p, m.to_string()).unwrap();
        p
    };
    // The crown's intrados: joint 32, point 0 (0, 2.86).
    let by_joint = with(
        json!([{"joint": 32, "opening": [0.003, 0.0]}]),
        "joint.json",
    );
    let by_line = with(
        json!([{"polyline": [[0.0, 2.86], [0.0, 2.98]], "opening": 3, "units": "mm"}]),
        "line.json",
    );
    let settle = |p: &Path| -> Value {
        serde_json::from_str(&ok(&run(&[
            "settle",
            s(p),
            "--move",
            "right=-0.01,0",
            "--json",
        ])))
        .unwrap()
    };
    let (a, b) = (settle(&by_joint), settle(&by_line));
    assert_eq!(a["joints"][32]["points"][0]["gap"].as_f64(), Some(0.003));
    assert_same(&a, &b, "settle");
}
