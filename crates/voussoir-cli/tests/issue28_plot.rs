//! Issue 28, item 6 (and the capacity parts of items 4, 10 and 11): `voussoir plot` re-draws
//! every result an analysis writes with `-o`, in 2D and 3D, and models; `capacity --png` draws
//! a 3D curve; the capacity axis and table follow the kind of settlement (cm or mrad); the
//! capacity table shows every step or says which; `capacity --friction-cone exact` solves the
//! exact cone.
//!
//! References are hand calculations: a box b × h under a horizontal live load equal to its weight
//! overturns at λ = b/h and slides at λ = μ (exact cone); a tilting table tips it at
//! α = atan(b/h); its weight is γ·b·h (·d); a rotation of 0.5° is 8.7266 mrad.

use crate::common;
use crate::common::{gen_model, json_file as json, refusal as refused, run};
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i28plot", name)
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap()
}

/// The values of attribute `name` on the elements whose opening tag contains `marker`.
fn attrs(svg: &str, marker: &str, name: &str) -> Vec<String> {
    let key = format!(" {name}=\"");
    svg.split('<')
        .filter(|tag| tag.contains(marker))
        .filter_map(|tag| {
            let i = tag.find(&key)? + key.len();
            let j = tag[i..].find('"')? + i;
            Some(tag[i..j].to_string())
        })
        .collect()
}

/// Blocks drawn in a 2D structure drawing: one closed subpath per block in the `blocks` paths.
fn blocks_2d(svg: &str) -> usize {
    attrs(svg, "class=\"blocks\"", "d")
        .iter()
        .map(|d| d.matches('M').count())
        .sum()
}

/// Blocks drawn in a 3D drawing: the distinct `data-block` ids of the faces.
fn blocks_3d(svg: &str) -> usize {
    let mut ids = attrs(svg, "class=\"block\"", "data-block");
    ids.sort();
    ids.dedup();
    ids.len()
}

/// The curve's point markers (the legend's marker has no white ring).
const MARKER: &str = "r=\"3.2\" fill=\"#1f5fbf\" stroke=\"#ffffff\"";

/// Width and height of a PNG (its IHDR chunk).
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "not a PNG");
    let be = |k: usize| u32::from_be_bytes([bytes[k], bytes[k + 1], bytes[k + 2], bytes[k + 3]]);
    (be(16), be(20))
}

/// The width and height the SVG declares.
fn svg_size(svg: &str) -> (f64, f64) {
    let head = &svg[..svg.find('>').unwrap()];
    let get = |k: &str| -> f64 {
        let key = format!(" {k}=\"");
        let i = head.find(&key).unwrap() + key.len();
        head[i..i + head[i..].find('"').unwrap()].parse().unwrap()
    };
    (get("width"), get("height"))
}

/// `plot r.json -o r.svg`, `-o r.png` and `-o r.html`: all succeed; the PNG is the SVG
/// rendered (same bytes as rendering it here), the report is HTML. Returns the SVG.
fn replot(d: &Path, result: &str) -> String {
    let stem = result.trim_end_matches(".json");
    let (svg, png, html) = (
        format!("{stem}.svg"),
        format!("{stem}.png"),
        format!("{stem}.html"),
    );
    run(d, &["plot", result, "-o", &svg]);
    run(d, &["plot", result, "-o", &png]);
    run(d, &["plot", result, "-o", &html]);
    let text = read(&d.join(&svg));
    let bytes = std::fs::read(d.join(&png)).unwrap();
    let (w, h) = svg_size(&text);
    let (pw, ph) = png_size(&bytes);
    let zoom = voussoir_io::draw::PNG_ZOOM as f64;
    assert_eq!(
        (pw, ph),
        ((w * zoom).ceil() as u32, (h * zoom).ceil() as u32),
        "{result}: PNG size"
    );
    assert_eq!(
        bytes,
        voussoir_io::draw::svg_to_png(&text, voussoir_io::draw::PNG_ZOOM).unwrap(),
        "{result}: the PNG is the SVG rendered"
    );
    let report = read(&d.join(&html));
    assert!(report.starts_with("<!DOCTYPE html>") && report.contains("<svg"));
    text
}

/// λ in "collapse load multiplier λ = 0.5000" of a figure.
fn lambda_in(svg: &str) -> f64 {
    let key = "collapse load multiplier λ = ";
    let i = svg.find(key).expect("λ in the figure") + key.len();
    let t: String = svg[i..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == '-')
        .collect();
    t.parse().unwrap()
}

const BOX_2D: &str = r#"{
  "materials": {"default": {"unit_weight": 18.0, "width": 1.0}},
  "blocks": [{"polygon": [[0, 0], [1, 0], [1, 2], [0, 2]]}],
  "supports": [{"name": "base", "polygon": [[-1, -0.5], [2, -0.5], [2, 0], [-1, 0]]}],
  "loads": {"live": [{"type": "body", "coefficients": [1.0, 0.0]}]}
}"#;

/// Every 2D analysis: -o, then plot to SVG, PNG and HTML; the figures show what r.json holds.
#[test]
fn issue28_item6_plot_redraws_every_2d_result() {
    let d = tmpdir("2d");
    std::fs::write(d.join("box.json"), BOX_2D).unwrap();
    gen_model(&d, "arch --voussoirs 16 --live left -o arch.json");

    // The model: 16 blocks.
    assert_eq!(blocks_2d(&replot(&d, "arch.json")), 16);

    // Limit: the box overturns at λ = b/h = 0.5; the figure's λ is r.json's.
    run(&d, &["limit", "box.json", "-o", "bl.json"]);
    let l = json(&d.join("bl.json"))["load_multiplier"]
        .as_f64()
        .unwrap();
    assert!((l - 0.5).abs() < 1e-6, "λ = {l}");
    let svg = replot(&d, "bl.json");
    assert!((lambda_in(&svg) - l).abs() <= 5e-5);
    assert_eq!(blocks_2d(&svg), 1);
    run(&d, &["limit", "arch.json", "-o", "al.json"]);
    let svg = replot(&d, "al.json");
    assert_eq!(blocks_2d(&svg), 16);
    let l = json(&d.join("al.json"))["load_multiplier"]
        .as_f64()
        .unwrap();
    assert!((lambda_in(&svg) - l).abs() <= 5e-5);

    // Settlement: 16 blocks; the figure states the 10 mm the command prescribed.
    run(
        &d,
        &[
            "settle",
            "arch.json",
            "--move",
            "right=0.01,0",
            "-o",
            "as.json",
        ],
    );
    let svg = replot(&d, "as.json");
    assert_eq!(blocks_2d(&svg), 16);
    assert!(svg.contains("right u = 10 mm"), "support motion not stated");

    // Tilt: the box tips at α = atan(1/2) = 26.565°.
    run(&d, &["tilt", "box.json", "-o", "bt.json"]);
    let a = json(&d.join("bt.json"))["tilt_angle"].as_f64().unwrap();
    assert!((a - 0.5f64.atan().to_degrees()).abs() < 1e-4, "α = {a}");
    let svg = replot(&d, "bt.json");
    assert_eq!(blocks_2d(&svg), 1);
    assert!(svg.contains(&format!("critical tilt angle α = {a:.3}°")));

    // Capacity: one marker per valid step; λ₀ marked with r.json's value.
    run(
        &d,
        &[
            "capacity",
            "arch.json",
            "--move",
            "right=0.01,0",
            "--steps",
            "8",
            "-o",
            "ac.json",
        ],
    );
    let r = json(&d.join("ac.json"));
    let curve = r["curve"].as_array().unwrap();
    assert_eq!(curve.len(), 9);
    let valid = curve.iter().filter(|p| p["valid"] == true).count();
    let svg = replot(&d, "ac.json");
    let markers = attrs(&svg, MARKER, "cx").len();
    assert_eq!(markers, valid);
    let l0 = curve[0]["load_multiplier"].as_f64().unwrap();
    assert!(svg.contains(&format!(
        "λ₀ = {}",
        voussoir_io::draw::svg::fmt_fixed(l0, 3)
    )));
    assert!(svg.contains("settlement s (cm)"));

    // Incremental: the peak is marked with r.json's value.
    run(
        &d,
        &[
            "incremental",
            "arch.json",
            "--control",
            "0,3",
            "--max",
            "4mm",
            "--step",
            "1mm",
            "-o",
            "ai.json",
        ],
    );
    let peak = json(&d.join("ai.json"))["peak_load_multiplier"]
        .as_f64()
        .unwrap();
    let svg = replot(&d, "ai.json");
    assert!(svg.contains(&format!(
        "peak λ = {}",
        voussoir_io::draw::svg::fmt_fixed(peak, 3)
    )));

    // Safety: the box's base carries its weight γ·b·h = 36 kN and no horizontal force.
    run(&d, &["safety", "box.json", "-o", "bs.json"]);
    let svg = replot(&d, "bs.json");
    assert_eq!(attrs(&svg, "class=\"range\"", "class").len(), 2);
    assert!(svg.contains("[36, 36] kN"), "fy range");
    assert!(svg.contains("[0, 0] kN"), "fx range");
    assert!(svg.contains("the structure stands"));

    // Identify (the issue's observations on the paper's arch): 64 blocks, 3 observed cracks.
    gen_model(&d, "arch --live none -o parch.json");
    std::fs::write(
        d.join("obs.json"),
        r#"{"tolerance": 1e-4, "cracks": [{"at": [-2.562, 1.9], "opening": 0.00125}, {"at": [0, 2.86], "opening": 0.0011}, {"at": [2.562, 1.9], "opening": 0.0004}]}"#,
    )
    .unwrap();
    run(
        &d,
        &[
            "identify",
            "parch.json",
            "--cracks",
            "obs.json",
            "--unknown",
            "right=u,v",
            "-o",
            "id.json",
        ],
    );
    let svg = replot(&d, "id.json");
    assert_eq!(blocks_2d(&svg), 64);
    let obs = svg.split("class=\"observed-cracks\"").nth(1).unwrap();
    let obs = &obs[..obs.find("</g>").unwrap()];
    assert_eq!(obs.matches("<circle").count(), 3);
}

/// Every 3D analysis: -o, then plot to SVG, PNG and HTML; the figures show what r.json holds.
#[test]
fn issue28_item6_plot_redraws_every_3d_result() {
    let d = tmpdir("3d");
    gen_model(&d, "block -o box.json");
    gen_model(&d, "vault --voussoirs 8 --rings 2 --live left -o v.json");

    // The models: 1 and 16 blocks (a 3D model was refused: "unknown field `faces`").
    assert_eq!(blocks_3d(&replot(&d, "box.json")), 1);
    assert_eq!(blocks_3d(&replot(&d, "v.json")), 16);

    // Limit: the 1 × 1 × 2 box overturns at λ = 0.5 (was: "missing field `theta`").
    run(&d, &["limit", "box.json", "-o", "bl.json"]);
    let l = json(&d.join("bl.json"))["load_multiplier"]
        .as_f64()
        .unwrap();
    assert!((l - 0.5).abs() < 1e-6, "λ = {l}");
    let svg = replot(&d, "bl.json");
    assert!((lambda_in(&svg) - l).abs() <= 5e-5);
    run(&d, &["limit", "v.json", "-o", "vl.json"]);
    let svg = replot(&d, "vl.json");
    assert_eq!(blocks_3d(&svg), 16);
    let l = json(&d.join("vl.json"))["load_multiplier"]
        .as_f64()
        .unwrap();
    assert!((lambda_in(&svg) - l).abs() <= 5e-5);
    // Every label of the legend lies within the figure (the live-load entry ran off its right
    // edge): a label at x of font size f ends before the width.
    let (w, _) = svg_size(&svg);
    for tag in svg.split("<text ").skip(1) {
        let num = |k: &str| -> Option<f64> {
            let key = format!("{k}=\"");
            let i = tag.find(&key)? + key.len();
            tag[i..i + tag[i..].find('"')?].parse().ok()
        };
        let (Some(x), Some(f)) = (num("x"), num("font-size")) else {
            continue;
        };
        if tag.contains("text-anchor") {
            continue;
        }
        let label = &tag[tag.find('>').unwrap() + 1..tag.find("</text>").unwrap()];
        let end = x + voussoir_io::draw::svg::text_width(label, f);
        assert!(end <= w, "{label:?} ends at {end} > {w}");
    }
    // Another view of the same result.
    run(&d, &["plot", "vl.json", "-o", "plan.svg", "--view", "plan"]);
    assert!(read(&d.join("plan.svg")).contains("plan (seen from above)"));

    // Settlement: 16 blocks, the prescribed 10 mm stated.
    run(
        &d,
        &[
            "settle",
            "v.json",
            "--move",
            "right=0.01,0,-0.01",
            "-o",
            "vs.json",
        ],
    );
    let svg = replot(&d, "vs.json");
    assert_eq!(blocks_3d(&svg), 16);
    assert!(
        svg.contains("right u = 10 mm, w = -10 mm"),
        "support motion"
    );

    // Tilt: the box tips at α = atan(1/2).
    run(&d, &["tilt", "box.json", "-o", "bt.json"]);
    let a = json(&d.join("bt.json"))["tilt_angle"].as_f64().unwrap();
    assert!((a - 0.5f64.atan().to_degrees()).abs() < 1e-4, "α = {a}");
    let svg = replot(&d, "bt.json");
    assert_eq!(blocks_3d(&svg), 1);
    assert!(svg.contains(&format!("critical tilt angle α = {a:.3}°")));

    // Safety: fz = γ·b·d·h = 36 kN, no horizontal reaction.
    run(&d, &["safety", "box.json", "-o", "bs.json"]);
    let svg = replot(&d, "bs.json");
    assert_eq!(attrs(&svg, "class=\"range\"", "class").len(), 3);
    assert!(svg.contains("base fz") && svg.contains("[36, 36] kN"));

    // Capacity (was: "expected a sequence"): one marker per valid step, λ₀ marked.
    run(
        &d,
        &[
            "capacity",
            "v.json",
            "--move",
            "right=0.01,0,-0.01",
            "--steps",
            "6",
            "-o",
            "vc.json",
        ],
    );
    let r = json(&d.join("vc.json"));
    let curve = r["curve"].as_array().unwrap();
    assert_eq!(curve.len(), 7);
    let valid = curve.iter().filter(|p| p["valid"] == true).count();
    assert!(valid >= 2);
    let svg = replot(&d, "vc.json");
    assert_eq!(attrs(&svg, MARKER, "cx").len(), valid);
    let l0 = curve[0]["load_multiplier"].as_f64().unwrap();
    assert!(svg.contains(&format!(
        "λ₀ = {}",
        voussoir_io::draw::svg::fmt_fixed(l0, 3)
    )));
    // The report draws the 3D settlement mechanism beside the curve.
    let html = read(&d.join("vc.html"));
    assert!(html.contains("Settlement mechanism at the largest settlement"));
    assert!(html.contains("data-block="));
}

/// `capacity --png/--svg/--report` on a 3D model (was refused): the curve is drawn, the same
/// figure as `plot` draws from its -o.
#[test]
fn issue28_item6_capacity_draws_a_3d_curve() {
    let d = tmpdir("cap3d");
    gen_model(&d, "vault --voussoirs 8 --rings 2 --live left -o v.json");
    let out = run(
        &d,
        &[
            "capacity",
            "v.json",
            "--move",
            "right=0.01,0,-0.01",
            "--steps",
            "5",
            "-o",
            "c.json",
            "--png",
            "c.png",
            "--svg",
            "c.svg",
            "--report",
            "c.html",
        ],
    );
    assert!(out.contains("largest settlement 1.4142 cm"), "{out}");
    let svg = read(&d.join("c.svg"));
    let png = std::fs::read(d.join("c.png")).unwrap();
    assert_eq!(png_size(&png), (1230, 780));
    // The curve's markers sit at the settlements of r.json (in cm) on the x axis.
    let r = json(&d.join("c.json"));
    let s: Vec<f64> = r["curve"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| p["valid"] == true)
        .map(|p| p["settlement"].as_f64().unwrap() * 100.0)
        .collect();
    let cx: Vec<f64> = attrs(&svg, MARKER, "cx")
        .iter()
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!(cx.len(), s.len());
    // Equal steps in s give equal steps in pixels (to the SVG's 0.01 px).
    for k in 2..cx.len() {
        let ratio = (cx[k] - cx[0]) / (cx[1] - cx[0]);
        let want = (s[k] - s[0]) / (s[1] - s[0]);
        assert!((ratio - want).abs() < 1e-2, "marker {k}: {ratio} vs {want}");
    }
    run(&d, &["plot", "c.json", "-o", "p.png"]);
    assert_eq!(std::fs::read(d.join("p.png")).unwrap(), png);
    assert!(read(&d.join("c.html")).contains("Capacity after settlement"));
    // What a 3D curve does not take, refused in one line.
    let e = refused(
        &d,
        &[
            "capacity",
            "v.json",
            "--move",
            "right=0.01,0,-0.01",
            "--steps",
            "2",
            "--vtk",
            "x.vtu",
        ],
    );
    assert!(e.contains("--vtk"), "{e}");
    assert!(!d.join("x.vtu").exists());
}

/// A capacity curve driven by a rotation is in mrad (was "cm"), in the drawing and the table.
#[test]
fn issue28_item10_a_rotation_driven_capacity_curve_is_in_mrad() {
    let d = tmpdir("rot");
    gen_model(&d, "arch --voussoirs 16 --live left -o arch.json");
    let out = run(
        &d,
        &[
            "capacity",
            "arch.json",
            "--move",
            "right=0,0,0.5",
            "--steps",
            "4",
            "-o",
            "r.json",
            "--svg",
            "r.svg",
        ],
    );
    // 0.5° = 8.7266 mrad.
    let mrad = 0.5f64.to_radians() * 1000.0;
    assert!(
        out.contains(&format!("largest support rotation {mrad:.4} mrad")),
        "{out}"
    );
    assert!(out.contains("s (mrad)"), "{out}");
    assert!(!out.contains("cm"), "a rotation labelled in cm: {out}");
    let r = json(&d.join("r.json"));
    assert!((r["max_settlement"].as_f64().unwrap() - mrad / 1000.0).abs() < 1e-12);
    let svg = read(&d.join("r.svg"));
    assert!(svg.contains("support rotation s (mrad)"));
    assert!(!svg.contains("(cm)"));
    // plot draws the same axis; a translation curve and this one do not share an axis.
    run(&d, &["plot", "r.json", "-o", "p.svg"]);
    assert!(read(&d.join("p.svg")).contains("support rotation s (mrad)"));
    run(
        &d,
        &[
            "capacity",
            "arch.json",
            "--move",
            "right=0.01,0",
            "--steps",
            "2",
            "-o",
            "t.json",
        ],
    );
    let e = refused(&d, &["plot", "t.json", "r.json", "-o", "both.svg"]);
    assert!(e.contains("do not share an axis"), "{e}");
    // 3D: a rotation about y of 0.5°.
    gen_model(&d, "vault --voussoirs 8 --rings 2 --live left -o v.json");
    let out = run(
        &d,
        &[
            "capacity",
            "v.json",
            "--move",
            "right=0,0,0,0,0.5,0",
            "--steps",
            "2",
            "--svg",
            "v.svg",
        ],
    );
    assert!(
        out.contains(&format!("largest support rotation {mrad:.4} mrad")),
        "{out}"
    );
    assert!(read(&d.join("v.svg")).contains("support rotation s (mrad)"));
}

/// `capacity --steps 40` prints all 41 points; above 100 steps it says which it prints.
#[test]
fn issue28_item11_capacity_prints_every_step_or_says_which() {
    let d = tmpdir("rows");
    gen_model(&d, "arch --voussoirs 16 --live left -o arch.json");
    let rows = |out: &str| -> Vec<f64> {
        let start = out.lines().position(|l| l.contains("s (cm)")).unwrap() + 1;
        out.lines()
            .skip(start)
            .take_while(|l| !l.contains("LP solves"))
            .map(|l| l.split_whitespace().next().unwrap().parse().unwrap())
            .collect()
    };
    let out = run(
        &d,
        &[
            "capacity",
            "arch.json",
            "--move",
            "right=0.01,0",
            "--steps",
            "40",
        ],
    );
    let s = rows(&out);
    assert_eq!(s.len(), 41, "{out}");
    // s = 1 cm · k/40, every k.
    for (k, x) in s.iter().enumerate() {
        assert!((x - k as f64 / 40.0).abs() < 1e-5, "row {k}: {x}");
    }
    assert!(!out.contains("shown"));
    let out = run(
        &d,
        &[
            "capacity",
            "arch.json",
            "--move",
            "right=0.01,0",
            "--steps",
            "150",
        ],
    );
    assert!(
        out.contains("(every 2nd of 150 steps shown, and the last; all in -o/--json)"),
        "{out}"
    );
    let s = rows(&out);
    assert_eq!(s.len(), 76);
    assert!((s[75] - 1.0).abs() < 1e-9 && (s[1] - 2.0 / 150.0).abs() < 1e-5);
}

/// `capacity --friction-cone exact` on a 3D model solves the exact cone (was: the pyramid,
/// silently): a 1 × 1 × 2 box with μ = 0.3 slides at λ = μ before it overturns (0.5).
#[test]
fn issue28_item4_capacity_honours_the_exact_friction_cone() {
    let d = tmpdir("cone");
    gen_model(&d, "block --azimuth 22.5 -o b.json");
    let lambda0 = |extra: &[&str]| -> f64 {
        let mut args = vec![
            "capacity",
            "b.json",
            "--friction",
            "0.3",
            "--move",
            "base=0,0,-0.01",
            "--steps",
            "2",
            "--json",
        ];
        args.extend_from_slice(extra);
        let r: serde_json::Value = serde_json::from_str(&run(&d, &args)).unwrap();
        r["curve"][0]["load_multiplier"].as_f64().unwrap()
    };
    let exact = lambda0(&["--friction-cone", "exact"]);
    let pyramid = lambda0(&[]);
    assert!((exact - 0.3).abs() < 1e-6, "exact cone λ = {exact}");
    // The inscribed pyramid of 8 facets resists between μ·cos(π/8) and μ.
    let lo = 0.3 * (std::f64::consts::PI / 8.0).cos();
    assert!(
        pyramid >= lo - 1e-6 && pyramid < exact - 1e-3,
        "pyramid λ = {pyramid}"
    );
    let e = refused(
        &d,
        &[
            "capacity",
            "b.json",
            "--friction",
            "0.3",
            "--move",
            "base=0,0,-0.01",
            "--friction-cone",
            "exact",
            "--non-associative",
        ],
    );
    assert!(e.contains("--non-associative"), "{e}");
}

/// plot refuses, in one line, the flags that do not apply to what it draws.
#[test]
fn issue28_item6_plot_refuses_flags_that_do_not_apply() {
    let d = tmpdir("flags");
    gen_model(&d, "block -o b3.json");
    std::fs::write(d.join("b2.json"), BOX_2D).unwrap();
    run(&d, &["limit", "b3.json", "-o", "l3.json"]);
    run(&d, &["limit", "b2.json", "-o", "l2.json"]);
    run(&d, &["safety", "b2.json", "-o", "s2.json"]);
    for (args, needle) in [
        (
            &["plot", "l3.json", "-o", "x.png", "--forces"][..],
            "--forces",
        ),
        (
            &["plot", "l2.json", "-o", "x.png", "--view", "plan"][..],
            "--view",
        ),
        (
            &["plot", "s2.json", "-o", "x.png", "--scale", "2"][..],
            "--scale",
        ),
        (
            &["plot", "l2.json", "-o", "x.html", "--width", "500"][..],
            "--width",
        ),
        (
            &["plot", "l3.json", "-o", "x.html", "--scale", "2"][..],
            "--scale",
        ),
        (
            &["plot", "b3.json", "-o", "x.png", "--undeformed"][..],
            "--undeformed",
        ),
        (
            &["plot", "l2.json", "-o", "x.png", "--label", "a"][..],
            "--label",
        ),
    ] {
        let e = refused(&d, args);
        assert!(e.contains(needle), "{args:?}: {e}");
        assert!(!d.join("x.png").exists() && !d.join("x.html").exists());
    }
    // --width on a curve or chart is honoured: the figure is scaled to it.
    run(&d, &["plot", "s2.json", "-o", "w.svg", "--width", "410"]);
    let (w, _) = svg_size(&read(&d.join("w.svg")));
    assert_eq!(w, 410.0);
}
