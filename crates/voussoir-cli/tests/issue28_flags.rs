//! Issue 28, items 1, 4 and 11 through the binary: flags that were accepted and ignored are now
//! honoured (checked against hand calculations) or refused in one line with no output file, and
//! the summaries and drawings count and join what they show consistently.

use crate::common;
use crate::common::{gen_model, run, voussoir};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// Run and expect a refusal: non-zero exit, nothing on stdout, stderr one `error:` line that
/// contains `needle`, and none of `outputs` written. Returns the line.
fn refused(dir: &Path, args: &[&str], needle: &str, outputs: &[&str]) -> String {
    let o = voussoir(dir, args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!o.status.success(), "voussoir {args:?} succeeded");
    assert!(o.stdout.is_empty(), "voussoir {args:?} printed to stdout");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 1, "voussoir {args:?}: not one line: {err}");
    assert!(lines[0].starts_with("error: "), "{err}");
    assert!(lines[0].contains(needle), "voussoir {args:?}: {err}");
    for f in outputs {
        assert!(!dir.join(f).exists(), "voussoir {args:?} wrote {f}");
    }
    lines[0].to_string()
}

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i28flags", name)
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn write_json(path: &Path, v: &Value) {
    std::fs::write(path, serde_json::to_string_pretty(v).unwrap()).unwrap();
}

/// A prism of the polygon `section` (x, z) extruded over y ∈ [y0, y1], rotated about z by
/// `rot` degrees: 3D vertices and outward faces.
fn prism(section: &[[f64; 2]], y0: f64, y1: f64, rot: f64) -> Value {
    let (s, c) = rot.to_radians().sin_cos();
    let n = section.len();
    let mut v = Vec::new();
    for y in [y0, y1] {
        for p in section {
            v.push([c * p[0] - s * y, s * p[0] + c * y, p[1]]);
        }
    }
    // The section is counter-clockwise in (x, z); seen from −y (the y0 face) it is
    // counter-clockwise, so that face is listed in reverse.
    let mut faces: Vec<Vec<usize>> = vec![(0..n).collect(), (n..2 * n).rev().collect()];
    for i in 0..n {
        let j = (i + 1) % n;
        faces.push(vec![i, n + i, n + j, j]);
    }
    json!({"vertices": v, "faces": faces})
}

/// A box [x0, x1] × [y0, y1] × [z0, z1] rotated about z by `rot` degrees.
fn cuboid(x: [f64; 2], y: [f64; 2], z: [f64; 2], rot: f64) -> Value {
    let section = [[x[0], z[0]], [x[1], z[0]], [x[1], z[1]], [x[0], z[1]]];
    prism(&section, y[0], y[1], rot)
}

fn with_name(mut v: Value, name: &str) -> Value {
    v["name"] = json!(name);
    v
}

/// The right trapezoid of the tilt tests in (x, z): base [0, 1] at z = 0, top [0, 0.5] at
/// z = 1 (the +x side sloped). Area 0.75, centroid x_c = 7/18, z_c = 4/9, so the block
/// overturns about its +x edge at tan α = (1 − x_c)/z_c = 1.375 and about its −x edge at
/// tan α = x_c/z_c = 0.875.
const TRAPEZOID: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [0.5, 1.0], [0.0, 1.0]];
const TAN_PLUS_X: f64 = 1.375;
const TAN_MINUS_X: f64 = 0.875;

fn tilt_json(dir: &Path, model: &str, extra: &[&str]) -> Value {
    let mut args = vec!["tilt", model, "--json"];
    args.extend_from_slice(extra);
    serde_json::from_str(&run(dir, &args)).unwrap()
}

fn angle(r: &Value) -> f64 {
    r["tilt_angle"].as_f64().expect("a tilt angle")
}

#[test]
fn issue28_item1_tilt_direction_in_3d() {
    let d = tmpdir("tilt3d");
    // Hand calculation: the trapezoidal prism overturns about the edge it tilts towards.
    let m = json!({
        "materials": {"default": {"unit_weight": 18.0, "width": 1.0}},
        "blocks": [prism(&TRAPEZOID, 0.0, 1.0, 0.0)],
        "supports": [with_name(cuboid([-1.0, 2.0], [-1.0, 2.0], [-0.5, 0.0], 0.0), "base")],
        "loads": {}
    });
    write_json(&d.join("t.json"), &m);
    let minus = tilt_json(&d, "t.json", &["--direction=-x"]);
    let plus = tilt_json(&d, "t.json", &["--direction", "+x"]);
    let default = tilt_json(&d, "t.json", &[]);
    let az180 = tilt_json(&d, "t.json", &["--azimuth", "180"]);
    let expect = |tan: f64| tan.atan().to_degrees();
    assert!(
        (angle(&minus) - expect(TAN_MINUS_X)).abs() < 1e-6,
        "{}",
        angle(&minus)
    );
    assert!(
        (angle(&plus) - expect(TAN_PLUS_X)).abs() < 1e-6,
        "{}",
        angle(&plus)
    );
    assert_eq!(angle(&default), angle(&plus));
    assert!((angle(&minus) - angle(&az180)).abs() < 1e-9);
    assert_eq!(minus["azimuth"].as_f64(), Some(180.0));
    // The summary names the direction used.
    let text = run(&d, &["tilt", "t.json", "--direction", "-x"]);
    assert!(text.contains("towards −x (azimuth 180°)"), "{text}");

    // The issue's L-shaped walls: −x is the --azimuth 180 answer (51.07°), not the +x one.
    gen_model(&d, "walls --plan L -o walls.json");
    let minus = angle(&tilt_json(&d, "walls.json", &["--direction=-x"]));
    let az180 = angle(&tilt_json(&d, "walls.json", &["--azimuth", "180"]));
    let plus = angle(&tilt_json(&d, "walls.json", &[]));
    assert!((minus - az180).abs() < 1e-9, "{minus} against {az180}");
    assert!((minus - plus).abs() > 1.0, "{minus} against {plus}");
    assert!((minus - 51.07).abs() < 0.01, "{minus}");
}

#[test]
fn issue28_item1_tilt_direction_with_azimuth_refused() {
    let d = tmpdir("tiltconflict");
    gen_model(&d, "block -o b.json");
    // Issue 32: `--azimuth` is another name of `--direction`; both at once is one flag twice.
    for dir in ["-x", "+x"] {
        refused(
            &d,
            &[
                "tilt",
                "b.json",
                "--direction",
                dir,
                "--azimuth",
                "0",
                "-o",
                "r.json",
            ],
            "--direction",
            &["r.json"],
        );
    }
    for bad in ["inf", "NaN", "-inf"] {
        refused(
            &d,
            &["tilt", "b.json", "--azimuth", bad, "-o", "r.json"],
            "--direction",
            &["r.json"],
        );
    }
}

#[test]
fn issue28_item1_tilt_azimuth_normalised() {
    let d = tmpdir("tiltaz");
    let m = json!({
        "materials": {"default": {"unit_weight": 18.0, "width": 1.0}},
        "blocks": [prism(&TRAPEZOID, 0.0, 1.0, 0.0)],
        "supports": [with_name(cuboid([-1.0, 2.0], [-1.0, 2.0], [-0.5, 0.0], 0.0), "base")],
        "loads": {}
    });
    write_json(&d.join("t.json"), &m);
    let expect = TAN_MINUS_X.atan().to_degrees();
    for (given, normal) in [
        ("180", 180.0),
        ("540", 180.0),
        ("-180", 180.0),
        ("-900", 180.0),
    ] {
        let r = tilt_json(&d, "t.json", &["--azimuth", given]);
        assert_eq!(r["azimuth"].as_f64(), Some(normal), "--azimuth {given}");
        assert!((angle(&r) - expect).abs() < 1e-6, "--azimuth {given}");
    }
    // 1e300 is a whole number of turns (1e300 mod 360 = 0 exactly): the +x answer, printed
    // as azimuth 0°, not with 300 digits.
    let text = run(&d, &["tilt", "t.json", "--azimuth", "1e300"]);
    assert!(text.contains("towards azimuth 0°"), "{text}");
    assert!(text.lines().all(|l| l.len() < 120), "{text}");
    let r = tilt_json(&d, "t.json", &["--azimuth", "1e300"]);
    assert!((angle(&r) - TAN_PLUS_X.atan().to_degrees()).abs() < 1e-6);
    // A tiny negative angle is 0, not 360.
    let r = tilt_json(&d, "t.json", &["--azimuth", "-1e-20"]);
    assert_eq!(r["azimuth"].as_f64(), Some(0.0));
}

#[test]
fn issue28_item1_tilt_2d_unchanged() {
    let d = tmpdir("tilt2d");
    let m = json!({
        "materials": {"default": {"unit_weight": 18.0, "width": 1.0}},
        "blocks": [{"polygon": TRAPEZOID}],
        "supports": [{"name": "base", "polygon": [[-1.0, -0.5], [2.0, -0.5], [2.0, 0.0], [-1.0, 0.0]]}],
        "loads": {}
    });
    write_json(&d.join("t.json"), &m);
    let plus = tilt_json(&d, "t.json", &[]);
    let minus = tilt_json(&d, "t.json", &["--direction", "-x"]);
    assert!((angle(&plus) - TAN_PLUS_X.atan().to_degrees()).abs() < 1e-6);
    assert!((angle(&minus) - TAN_MINUS_X.atan().to_degrees()).abs() < 1e-6);
    assert_eq!(plus["direction"].as_f64(), Some(1.0));
    assert_eq!(minus["direction"].as_f64(), Some(-1.0));
    assert!(plus["azimuth"].is_null());
    // Issue 32: `--azimuth` is another name of `--direction`; in 2D, 180° is -x and an angle off
    // the x axis is refused.
    let az180 = tilt_json(&d, "t.json", &["--azimuth", "180"]);
    assert_eq!(az180, minus);
    refused(
        &d,
        &["tilt", "t.json", "--direction", "30"],
        "a 2D model tilts along x",
        &[],
    );
}

/// A block 2 × 1 × 0.5 m (W = 10 kN) bridging two supports s1, s2 under its ends, μ = 0.5,
/// the whole rotated about z by `rot` degrees.
fn bridge(rot: f64) -> Value {
    json!({
        "materials": {"default": {"unit_weight": 10.0, "width": 1.0, "friction": 0.5}},
        "blocks": [cuboid([0.0, 2.0], [0.0, 1.0], [0.0, 0.5], rot)],
        "supports": [
            with_name(cuboid([0.0, 0.5], [0.0, 1.0], [-0.3, 0.0], rot), "s1"),
            with_name(cuboid([1.5, 2.0], [0.0, 1.0], [-0.3, 0.0], rot), "s2")
        ]
    })
}

fn settle_work(dir: &Path, model: &str, mv: &str, extra: &[&str]) -> (f64, Value) {
    let mut args = vec!["settle", model, "--move", mv, "--json"];
    args.extend_from_slice(extra);
    let r: Value = serde_json::from_str(&run(dir, &args)).unwrap();
    (r["work_dead_loads"].as_f64().expect("a work"), r)
}

#[test]
fn issue28_item4a_settle_exact_friction_cone() {
    // s2 moves away horizontally by u along the block. Associative Coulomb friction: a joint
    // slides by s only while opening by μ·|s| (exact cone) — by μ·|s|·cos(π/8) for a slide
    // along a facet normal of the inscribed 8-facet pyramid, by μ·|s| halfway between two
    // (along the joint's x tangent). The least rise of the block's centroid is reached by
    // sliding u/2 on each support and rising μu/2: the work of the dead loads is −W μ u / 2
    // with the cone in any direction. Rotating the model by 22.5° puts the slide on a facet
    // normal of the pyramid (the joints' tangents stay along x and y): −W μ u cos(π/8) / 2.
    let d = tmpdir("cone");
    let (w, mu, u) = (10.0, 0.5, 0.01);
    let cone = -w * mu * u / 2.0;
    let pyramid_on_facet = cone * (std::f64::consts::PI / 8.0).cos();
    write_json(&d.join("b0.json"), &bridge(0.0));
    write_json(&d.join("b22.json"), &bridge(22.5));
    let (s, c) = 22.5f64.to_radians().sin_cos();
    let along22 = format!("s2={},{},0", u * c, u * s);
    let along0 = format!("s2={u},0,0");
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * b.abs();

    let (exact0, _) = settle_work(&d, "b0.json", &along0, &["--friction-cone", "exact"]);
    let (exact22, r) = settle_work(&d, "b22.json", &along22, &["--friction-cone", "exact"]);
    let (pyr0, _) = settle_work(&d, "b0.json", &along0, &[]);
    let (pyr22, rp) = settle_work(&d, "b22.json", &along22, &[]);
    assert!(close(exact0, cone), "{exact0} against {cone}");
    assert!(close(exact22, cone), "{exact22} against {cone}");
    assert!(close(pyr0, cone), "{pyr0} against {cone}");
    assert!(
        close(pyr22, pyramid_on_facet),
        "{pyr22} against {pyramid_on_facet}"
    );
    assert_eq!(r["solver"]["solver"].as_str(), Some("clarabel"));
    assert_eq!(rp["solver"]["solver"].as_str(), Some("highs"));
    assert!(r["certificate"]["ok"].as_bool().unwrap());
    // --friction-facets is honoured by settle too. A slide at angle ψ from the nearest facet
    // normal of a K-facet pyramid opens the joint by μ·|s|·cos(π/K − ψ): at 22.5°, K = 12
    // (normals at 15°, 45°, …) gives cos 7.5°, K = 16 (normals at 11.25°, 33.75°, …) cos 0.
    let (pyr12, _) = settle_work(&d, "b22.json", &along22, &["--friction-facets", "12"]);
    let (pyr16, _) = settle_work(&d, "b22.json", &along22, &["--friction-facets", "16"]);
    let k12 = cone * 7.5f64.to_radians().cos();
    assert!(close(pyr12, k12), "{pyr12} against {k12}");
    assert!(close(pyr16, cone), "{pyr16} against {cone}");

    // What the exact cone cannot go with is refused in one line.
    refused(
        &d,
        &[
            "settle",
            "b0.json",
            "--move",
            &along0,
            "--friction-cone",
            "exact",
            "--settlement-form",
            "force-only",
            "-o",
            "r.json",
        ],
        "--friction-cone exact goes with --settlement-form both",
        &["r.json"],
    );
    refused(
        &d,
        &[
            "settle",
            "b0.json",
            "--move",
            &along0,
            "--friction-cone",
            "exact",
            "--non-associative",
            "-o",
            "r.json",
        ],
        "--non-associative",
        &["r.json"],
    );
}

/// A 2D block b × h = 1 × 2 m, γ = 10 kN/m³ (W = 20 kN), horizontal live load equal to its
/// weight, on a base.
fn block2d() -> Value {
    json!({
        "materials": {"default": {"unit_weight": 10.0, "width": 1.0}},
        "blocks": [{"polygon": [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0], [0.0, 2.0]]}],
        "supports": [{"name": "base", "polygon": [[-1.0, -0.5], [2.0, -0.5], [2.0, 0.0], [-1.0, 0.0]]}],
        "loads": {"live": [{"type": "body", "coefficients": [1.0, 0.0]}]}
    })
}

#[test]
fn issue28_item4b_crushing_conic_needs_a_compressive_strength() {
    let d = tmpdir("crushing");
    write_json(&d.join("b.json"), &block2d());
    refused(
        &d,
        &["limit", "b.json", "--crushing", "conic", "-o", "r.json"],
        "--crushing conic needs a compressive strength",
        &["r.json"],
    );
    refused(
        &d,
        &["limit", "b.json", "--facets", "32", "-o", "r.json"],
        "--facets 32 needs a compressive strength",
        &["r.json"],
    );
    refused(
        &d,
        &[
            "settle",
            "b.json",
            "--move",
            "base=0.01,0",
            "--crushing",
            "conic",
            "-o",
            "r.json",
        ],
        "--crushing conic needs a compressive strength",
        &["r.json"],
    );
    // With a strength it is honoured: the exact crushing cone gives the closed form
    // λ = (b − W/(f_c w))/h = (1 − 20/100)/2 = 0.4 (a compressed zone of 0.2 m at the edge).
    let lambda = |extra: &[&str]| -> f64 {
        let mut args = vec!["limit", "b.json", "--json"];
        args.extend_from_slice(extra);
        let r: Value = serde_json::from_str(&run(&d, &args)).unwrap();
        r["load_multiplier"].as_f64().unwrap()
    };
    let conic = lambda(&["--crushing", "conic", "--compressive-strength", "100"]);
    assert!((conic - 0.4).abs() < 1e-6, "{conic}");
    // The strength may come from the model's materials as well.
    let mut m = block2d();
    m["materials"]["default"]["compressive_strength"] = json!(100.0);
    write_json(&d.join("b.json"), &m);
    let conic = lambda(&["--crushing", "conic"]);
    assert!((conic - 0.4).abs() < 1e-6, "{conic}");
    // Without the flag, the rigid block overturns at b/h = 0.5 (the flags change the answer).
    write_json(&d.join("b.json"), &block2d());
    assert!((lambda(&[]) - 0.5).abs() < 1e-9);
}

#[test]
fn issue28_item4c_gen_live_values_checked() {
    let d = tmpdir("genlive");
    for (kind, bad, possible) in [
        ("facade", "left", "[possible values: none, horizontal]"),
        ("facade", "full", "[possible values: none, horizontal]"),
        ("wall", "left", "[possible values: none, full, horizontal]"),
        ("wall", "right", "[possible values: none, full, horizontal]"),
        ("walls", "left", "[possible values: none, main, all]"),
    ] {
        refused(
            &d,
            &["gen", kind, "--live", bad, "-o", "m.json"],
            possible,
            &["m.json"],
        );
    }
    // The accepted values do what they say: the façade's horizontal load is each block's
    // weight along +x; the wall's full load is 1 kN/m² on each of the top course's units.
    gen_model(&d, "facade --element 2 --live horizontal -o f.json");
    let f = read_json(&d.join("f.json"));
    assert_eq!(
        f["loads"]["live"],
        json!([{"type": "body", "coefficients": [1.0, 0.0]}])
    );
    gen_model(&d, "facade --element 2 -o f0.json");
    let f0 = read_json(&d.join("f0.json"));
    assert!(f0["loads"]["live"].as_array().is_none_or(|l| l.is_empty()));
    gen_model(&d, "wall --courses 3 --units 4 --live full -o w.json");
    let w = read_json(&d.join("w.json"));
    let live = w["loads"]["live"].as_array().unwrap();
    // Course 3 (odd courses full): 4 whole units.
    assert_eq!(live.len(), 4, "{live:?}");
    assert!(live.iter().all(|l| l["type"] == "edge" && l["q"] == 1.0));
    // The arch keeps its left/right half-span loads.
    gen_model(&d, "arch --live left -o a.json");
    let a = read_json(&d.join("a.json"));
    assert!(!a["loads"]["live"].as_array().unwrap().is_empty());
}

#[test]
fn issue28_item4d_mesh_live_on_obj() {
    let d = tmpdir("meshlive");
    // A 1 × 1 × 2 box on a base: the tilting-table load W·[1, 0, 0] overturns it at
    // λ = b/h = 0.5.
    gen_model(&d, "block -o b.json");
    run(&d, &["export", "b.json", "-o", "b.obj"]);
    let lambda = |extra: &[&str]| -> f64 {
        let mut args = vec!["limit", "b.obj", "--json"];
        args.extend_from_slice(extra);
        let r: Value = serde_json::from_str(&run(&d, &args)).unwrap();
        r["load_multiplier"].as_f64().unwrap()
    };
    assert!((lambda(&[]) - 0.5).abs() < 1e-7);
    assert!((lambda(&["--mesh-live", "horizontal"]) - 0.5).abs() < 1e-7);
    // `none` adds no live load: nothing for a limit analysis to multiply.
    refused(
        &d,
        &["limit", "b.obj", "--mesh-live", "none", "-o", "r.json"],
        "needs live loads",
        &["r.json"],
    );
    run(
        &d,
        &["import", "b.obj", "--mesh-live", "none", "-o", "n.json"],
    );
    let n = read_json(&d.join("n.json"));
    assert!(n["loads"]["live"].as_array().is_none_or(|l| l.is_empty()));
    run(
        &d,
        &[
            "import",
            "b.obj",
            "--mesh-live",
            "horizontal",
            "-o",
            "h.json",
        ],
    );
    let h = read_json(&d.join("h.json"));
    assert_eq!(
        h["loads"]["live"],
        json!([{"type": "body", "coefficients": [1.0, 0.0, 0.0]}])
    );
    // Issue 32: `--dxf-live` and `--mesh-live` are both other names of `--live`, which applies
    // to drawings and meshes alike (was: each refused on the other format).
    run(
        &d,
        &["import", "b.obj", "--dxf-live", "none", "-o", "x.json"],
    );
    assert_eq!(read_json(&d.join("x.json")), n);
    let dxf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../voussoir-io/tests/fixtures/lact3/arch_1.dxf");
    let dxf = dxf.to_str().unwrap();
    run(
        &d,
        &[
            "import",
            dxf,
            "--units",
            "mm",
            "--mesh-live",
            "none",
            "-o",
            "x.json",
        ],
    );
    let x = read_json(&d.join("x.json"));
    assert!(x["loads"]["live"].as_array().is_none_or(|l| l.is_empty()));
    // Named where it does not apply (a JSON model carries its own loads).
    refused(
        &d,
        &["limit", "b.json", "--mesh-live", "none", "-o", "r2.json"],
        "--live applies to imported DXF drawings and OBJ/PLY meshes only",
        &["r2.json"],
    );
}

#[test]
fn issue28_item4e_vtk_directory_refused() {
    let d = tmpdir("vtkdir");
    gen_model(&d, "block -o b.json");
    std::fs::create_dir_all(d.join("sub")).unwrap();
    for target in ["out.vtm/", "out.vtu/", "sub", "sub/.", "sub/..", "."] {
        refused(
            &d,
            &["limit", "b.json", "--vtk", target, "-o", "r.json"],
            "names a directory",
            &["r.json", "out.vtm", "out.vtu", "out_blocks.vtu"],
        );
    }
    refused(
        &d,
        &["limit", "b.json", "--vtk", "out.txt", "-o", "r.json"],
        "must end in .vtu",
        &["r.json", "out.txt"],
    );
    // Refused before any analysis, on a 2D model too.
    gen_model(&d, "arch --live full -o a.json");
    refused(
        &d,
        &["limit", "a.json", "--vtk", "out.vtm/", "-o", "r.json"],
        "names a directory",
        &["r.json"],
    );
    // A file in a directory is written there.
    run(&d, &["limit", "b.json", "--vtk", "sub/m.vtm"]);
    for f in [
        "m.vtm",
        "m_blocks.vtu",
        "m_contacts.vtu",
        "m_cracks.vtu",
        "m_supports.vtu",
    ] {
        assert!(d.join("sub").join(f).is_file(), "{f}");
    }
}

/// The number in "N hinged joint(s)" of `text`.
fn hinged_joints_in(text: &str) -> Option<usize> {
    let i = text.find(" hinged joint")?;
    text[..i]
        .rsplit(|c: char| !c.is_ascii_digit())
        .next()?
        .parse()
        .ok()
}

fn count_state(r: &Value, state: &str) -> usize {
    r["joints"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|j| j["state"] == state)
        .count()
}

#[test]
fn issue28_item11a_summary_counts_hinged_joints() {
    let d = tmpdir("hinges");
    // 3D: a vault under a full live load: a four-hinge mechanism, each hinge a line of two
    // points across the vault's depth.
    gen_model(&d, "vault --live full -o v.json");
    let text = run(&d, &["limit", "v.json", "-o", "r.json", "--svg", "r.svg"]);
    let r = read_json(&d.join("r.json"));
    let joints = count_state(&r, "hinge");
    let points = r["hinges"].as_array().unwrap().len();
    assert_eq!(joints, 4);
    assert_eq!(points, 8);
    assert!(
        text.contains("hinges of the collapse mechanism: 4 hinged joints (8 hinge points)"),
        "{text}"
    );
    let svg = std::fs::read_to_string(d.join("r.svg")).unwrap();
    assert_eq!(hinged_joints_in(&svg), Some(joints));
    // One line per hinged joint.
    assert_eq!(
        text.lines().filter(|l| l.starts_with("  joint")).count(),
        joints
    );

    // 3D settlement: the spreading vault opens three hinge lines.
    let text = run(
        &d,
        &[
            "settle",
            "v.json",
            "--move",
            "right=0.01,0,0",
            "-o",
            "s.json",
            "--svg",
            "s.svg",
        ],
    );
    let s = read_json(&d.join("s.json"));
    let joints = count_state(&s, "hinge");
    let points = s["hinges"].as_array().unwrap().len();
    assert_eq!(joints, 3);
    assert_eq!(points, 6);
    assert!(
        text.contains(&format!(
            "hinges: {joints} hinged joints ({points} hinge points)"
        )),
        "{text}"
    );
    let svg = std::fs::read_to_string(d.join("s.svg")).unwrap();
    assert_eq!(hinged_joints_in(&svg), Some(joints));

    // 2D: the paper's arch under a load on its left half: Heyman's four-hinge mechanism, one
    // point each (no separate point count).
    gen_model(&d, "arch --live left -o a.json");
    let text = run(&d, &["limit", "a.json", "-o", "ra.json", "--svg", "ra.svg"]);
    let ra = read_json(&d.join("ra.json"));
    assert_eq!(count_state(&ra, "hinge"), 4);
    assert_eq!(ra["hinges"].as_array().unwrap().len(), 4);
    assert!(
        text.contains("hinges of the collapse mechanism: 4 hinged joints\n"),
        "{text}"
    );
    let svg = std::fs::read_to_string(d.join("ra.svg")).unwrap();
    assert!(
        svg.contains("4 hinges"),
        "the 2D figure counts the same four"
    );
}

/// The vertices of every `<polyline>` of the thrust-line group of an SVG.
fn thrust_polylines(svg: &str) -> Vec<Vec<[f64; 2]>> {
    let start = svg.find("class=\"thrust-line\"").expect("a thrust line");
    let end = start + svg[start..].find("</g>").unwrap();
    svg[start..end]
        .split("<polyline points=\"")
        .skip(1)
        .map(|p| {
            p[..p.find('"').unwrap()]
                .split_whitespace()
                .map(|xy| {
                    let (x, y) = xy.split_once(',').unwrap();
                    [x.parse().unwrap(), y.parse().unwrap()]
                })
                .collect()
        })
        .collect()
}

#[test]
fn issue28_item11b_thrust_line_not_across_an_opening() {
    // LACT3's arch_1: both springings stand on the one support `base`. The thrust line runs
    // along the ring from one springing to the other; it used to close the loop through the
    // support with a straight line across the opening.
    let d = tmpdir("thrust");
    let dxf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../voussoir-io/tests/fixtures/lact3/arch_1.dxf");
    run(
        &d,
        &[
            "limit",
            dxf.to_str().unwrap(),
            "--units",
            "mm",
            "--svg",
            "a.svg",
            "-o",
            "r.json",
        ],
    );
    let r = read_json(&d.join("r.json"));
    let thrust_points = r["thrust_line"].as_array().unwrap().len();
    let joints = r["joints"].as_array().unwrap();
    assert_eq!(thrust_points, joints.len());
    let svg = std::fs::read_to_string(d.join("a.svg")).unwrap();
    let lines = thrust_polylines(&svg);
    assert_eq!(lines.len(), 1, "one chain of blocks");
    let line = &lines[0];
    assert_eq!(line.len(), thrust_points);
    // Its ends are the two springings: the leftmost and rightmost points of the line.
    let xs: Vec<f64> = line.iter().map(|p| p[0]).collect();
    let (xmin, xmax) = xs
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    let first = line[0][0];
    let last = line[line.len() - 1][0];
    assert!(
        (first.min(last) - xmin).abs() < 1e-9 && (first.max(last) - xmax).abs() < 1e-9,
        "the line ends at x = {first}, {last}; its extent is {xmin} … {xmax}"
    );
    // Consecutive points are one voussoir apart (25 voussoirs over a half circle): no segment
    // spans the opening.
    let span = xmax - xmin;
    let longest = line
        .windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .fold(0.0f64, f64::max);
    assert!(
        longest < span / 10.0,
        "a segment of {longest} px across {span} px"
    );
}
