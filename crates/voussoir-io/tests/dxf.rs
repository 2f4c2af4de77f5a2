//! DXF import on the LACT3 sample drawings (copied into `tests/fixtures/lact3/`, source and
//! licence in its README; a missing fixture fails the test) and on small drawings written here.
//!
//! Independent references:
//! * block counts: `tests/fixtures/lact3/README.md` (41, 183 and 26 polygons including the base);
//! * joint counts: a brute-force count of facing, collinear, overlapping edge pairs over all
//!   pairs of edges, written separately in Python (see docs/import.md): Portal 87, wall 391;
//!   arch_1 is a chain of 25 voussoirs between two springings of one base: 24 + 2 = 26;
//! * collapse multipliers: LACT3's own solver test (`LACT3_SolverTest.m`) gives the collapse
//!   tilt angles θ = 17.10° (arch_1), 27.30° (Portal), 16.73° (wall) with Mohr–Coulomb joints
//!   (φ = 30°, 30°, 26°). A tilting table at θ is our horizontal live load at λ = tan θ. The arch
//!   fails by hinges alone, so its λ must match tan 17.10° (± the 0.01° the angle is given to);
//!   Portal and wall fail with sliding there, so with Heyman's no-sliding joints λ must lie above
//!   tan θ and below the overturning of the whole structure about its right-most base contact.
//!   With Mohr–Coulomb joints of the same φ all three match LACT3's angles (last test).

use std::path::PathBuf;
use voussoir::analysis::{limit, LimitStatus};
use voussoir::lp::SolverOptions;
use voussoir::model::Model;
use voussoir::{BuildOptions, Structure};
use voussoir_io::dxf::{parse_dxf, read_dxf, DxfOptions, ImportLive, Units};

/// A LACT3 drawing from the repository's fixtures; panics (fails the test) if it is missing.
fn lact3(name: &str) -> PathBuf {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/lact3")
        .join(name);
    assert!(
        p.is_file(),
        "fixture {} is missing (see tests/fixtures/lact3/README.md)",
        p.display()
    );
    p
}

fn mm() -> DxfOptions {
    DxfOptions {
        units: Some(Units::Mm),
        ..DxfOptions::default()
    }
}

/// λ of the whole structure overturning as one rigid body about the right-most point where the
/// blocks rest on the support (an admissible mechanism, so an upper bound).
fn whole_overturning(st: &Structure) -> f64 {
    let sp = &st.supports[0];
    let top = sp
        .polygon
        .iter()
        .fold(f64::NEG_INFINITY, |m, p| m.max(p[1]));
    let mut toe = [f64::NEG_INFINITY, top];
    for j in &st.joints {
        for p in &j.points {
            if matches!(j.b, voussoir::structure::Body::Support(_)) && p.x[0] > toe[0] {
                toe = p.x;
            }
        }
    }
    let (mut resist, mut drive) = (0.0, 0.0);
    for b in &st.blocks {
        resist += b.weight * (toe[0] - b.centroid[0]);
        drive += b.weight * (b.centroid[1] - toe[1]);
    }
    resist / drive
}

fn check(file: &str, blocks: usize, joints: usize) -> (Model, Structure, f64) {
    let p = lact3(file);
    let (m, rep) = read_dxf(&p, &mm()).unwrap();
    assert_eq!(
        m.blocks.len() + m.supports.len(),
        blocks,
        "{file}: polygons incl. base"
    );
    assert_eq!(m.supports.len(), 1, "{file}: one base");
    assert_eq!(m.supports[0].name, "base");
    assert_eq!(rep.block_entities.len(), m.blocks.len());
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    assert_eq!(st.joints.len(), joints, "{file}: joints");
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::Collapse, "{file}");
    let l = r.load_multiplier.unwrap();
    println!(
        "{file}: {}; joints {}; λ = {l:.6}",
        rep.summary(),
        st.joints.len()
    );
    (m, st, l)
}

#[test]
fn lact3_arch_matches_lact3_collapse_angle() {
    let (m, _, l) = check("arch_1.dxf", 26, 26);
    assert_eq!(m.blocks.len(), 25);
    // LACT3 gives the angle to 0.01°.
    let theta = l.atan().to_degrees();
    assert!(
        (theta - 17.10).abs() <= 0.01,
        "λ = {l}: tilt {theta}°, LACT3: 17.10°"
    );
}

#[test]
fn lact3_portal_imports_and_collapses_between_bounds() {
    let (_, st, l) = check("Portal.dxf", 41, 87);
    let up = whole_overturning(&st);
    assert!(
        l >= 27.30f64.to_radians().tan() && l <= up + 1e-9,
        "λ = {l}, bounds {} … {up}",
        27.30f64.to_radians().tan()
    );
}

#[test]
fn lact3_wall_imports_and_collapses_between_bounds() {
    let (m, st, l) = check("wall.dxf", 183, 391);
    // Units 55.6 mm high: every block is one course high.
    for b in &m.blocks {
        let bb = voussoir::geometry::bbox(&b.polygon);
        assert!(((bb[3] - bb[1]) - 0.0555556).abs() < 1e-6, "{bb:?}");
    }
    let up = whole_overturning(&st);
    assert!(
        l >= 16.73f64.to_radians().tan() && l <= up + 1e-9,
        "λ = {l}, bounds {} … {up}",
        16.73f64.to_radians().tan()
    );
}

#[test]
fn declared_units_are_used_and_inches_need_an_override() {
    // Portal declares mm ($INSUNITS = 4): no override needed.
    let (m, rep) = read_dxf(&lact3("Portal.dxf"), &DxfOptions::default()).unwrap();
    assert_eq!(rep.units, "mm");
    let bb = voussoir::geometry::bbox(&m.supports[0].polygon);
    assert!((bb[2] - bb[0] - 2.5).abs() < 1e-12, "base 2500 mm = 2.5 m");
    // wall.dxf declares inches although drawn in mm: refuse and ask for --units.
    let e = read_dxf(&lact3("wall.dxf"), &DxfOptions::default())
        .unwrap_err()
        .0;
    assert!(
        e.contains("--units") && e.contains("Inches") && !e.contains('\n'),
        "{e}"
    );
}

// --- small drawings written here -------------------------------------------------------------

fn lw(handle: &str, layer: &str, closed: bool, pts: &[[f64; 2]]) -> String {
    let mut s = format!(
        "0\nLWPOLYLINE\n5\n{handle}\n8\n{layer}\n90\n{}\n70\n{}\n",
        pts.len(),
        closed as i32
    );
    for p in pts {
        s.push_str(&format!("10\n{}\n20\n{}\n", p[0], p[1]));
    }
    s
}

fn drawing(insunits: i32, entities: &[String]) -> Vec<u8> {
    let mut s = format!(
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n{insunits}\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
    );
    for e in entities {
        s.push_str(e);
    }
    s.push_str("0\nENDSEC\n0\nEOF\n");
    s.into_bytes()
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

#[test]
fn one_block_on_a_support_layer_in_cm_tips_at_b_over_h() {
    // A 40 cm × 100 cm block on a base drawn on layer BASE; units cm from the header.
    let d = drawing(
        5,
        &[
            lw("B1", "BLOCKS", true, &rect(0.0, 0.0, 40.0, 100.0)),
            lw("F1", "BASE", true, &rect(-50.0, -20.0, 90.0, 0.0)),
        ],
    );
    let opts = DxfOptions {
        support_layers: vec!["BASE".into()],
        unit_weight: 20.0,
        ..DxfOptions::default()
    };
    let (m, rep) = parse_dxf(&d, &opts, "t.dxf").unwrap();
    assert_eq!(rep.units, "cm");
    assert_eq!(m.supports.len(), 1);
    assert_eq!(m.supports[0].name, "BASE");
    assert_eq!(m.blocks[0].polygon[2], [0.4, 1.0]);
    assert_eq!(m.materials["default"].unit_weight, 20.0);
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    // Closed form: λ = b/h = 0.4.
    assert!(
        (r.load_multiplier.unwrap() - 0.4).abs() < 1e-9,
        "{:?}",
        r.load_multiplier
    );
}

#[test]
fn open_and_self_intersecting_polylines_are_named_in_one_line() {
    let base = lw("F1", "0", true, &rect(-1.0, -1.0, 3.0, 0.0));
    let open = drawing(
        6,
        &[
            base.clone(),
            lw(
                "2AF",
                "0",
                false,
                &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            ),
        ],
    );
    let e = parse_dxf(&open, &DxfOptions::default(), "t.dxf")
        .unwrap_err()
        .0;
    assert!(
        e.contains("LWPOLYLINE handle 2AF") && e.contains("open") && !e.contains('\n'),
        "{e}"
    );
    let bow = drawing(
        6,
        &[
            base,
            lw(
                "2B0",
                "0",
                true,
                &[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]],
            ),
        ],
    );
    let e = parse_dxf(&bow, &DxfOptions::default(), "t.dxf")
        .unwrap_err()
        .0;
    assert!(
        e.contains("LWPOLYLINE handle 2B0") && e.contains("self-intersecting") && !e.contains('\n'),
        "{e}"
    );
    let none = drawing(6, &[]);
    let e = parse_dxf(&none, &DxfOptions::default(), "t.dxf")
        .unwrap_err()
        .0;
    assert!(e.contains("no LWPOLYLINE"), "{e}");
    let layer = drawing(6, &[lw("1", "0", true, &rect(0.0, 0.0, 1.0, 1.0))]);
    let opts = DxfOptions {
        support_layers: vec!["GROUND".into()],
        ..DxfOptions::default()
    };
    let e = parse_dxf(&layer, &opts, "t.dxf").unwrap_err().0;
    assert!(e.contains("'GROUND'") && e.contains("layers: 0"), "{e}");
}

#[test]
fn nearby_vertices_are_merged_and_an_unclosed_but_returning_polyline_is_closed() {
    // Two stacked blocks (m) whose shared corners differ by 0.3 µm, the top one drawn without
    // the closing flag but ending on its first vertex; the base is the lowest, widest polygon.
    let e = 3e-7;
    let mut top = rect(0.0 + e, 1.0 - e, 1.0, 2.0);
    top.push(top[0]);
    let d = drawing(
        6,
        &[
            lw("A", "0", true, &rect(0.0, 0.0, 1.0, 1.0)),
            lw("B", "0", false, &top),
            lw("C", "0", true, &rect(-0.5, -0.5, 1.5, 0.0)),
        ],
    );
    let opts = DxfOptions {
        merge_tolerance: Some(1e-6),
        live: ImportLive::None,
        ..DxfOptions::default()
    };
    let (m, rep) = parse_dxf(&d, &opts, "t.dxf").unwrap();
    assert_eq!(rep.merged_vertices, 3); // two corners, and the repeated first vertex
    assert_eq!(m.blocks[1].polygon[0], [0.0, 1.0]);
    assert_eq!(m.blocks[1].polygon.len(), 4);
    assert!(m.loads.live.is_empty());
    assert_eq!(
        rep.support_entities,
        vec!["LWPOLYLINE handle C (layer 0)".to_string()]
    );
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    assert_eq!(st.joints.len(), 2);
    assert_eq!(
        rep.annotate("block 1 touches nothing"),
        "block 1 (LWPOLYLINE handle B (layer 0)) touches nothing"
    );
}

#[test]
fn old_style_polyline_with_an_arc_is_read() {
    // POLYLINE/VERTEX/SEQEND: a half-disc of radius 1 m (one bulge of 1 = 180°) on a base.
    let mut s = String::from("0\nPOLYLINE\n5\nD1\n8\n0\n66\n1\n70\n1\n");
    for (x, y, b) in [(1.0, 0.0, 1.0), (-1.0, 0.0, 0.0)] {
        s.push_str(&format!("0\nVERTEX\n8\n0\n10\n{x}\n20\n{y}\n42\n{b}\n"));
    }
    s.push_str("0\nSEQEND\n8\n0\n");
    let d = drawing(6, &[s, lw("F", "0", true, &rect(-2.0, -1.0, 2.0, 0.0))]);
    let (m, _) = parse_dxf(&d, &DxfOptions::default(), "t.dxf").unwrap();
    let p = &m.blocks[0].polygon;
    // 180° in chords of at most 5°: 36 chords, 37 vertices; every vertex on the unit circle.
    assert_eq!(p.len(), 37);
    assert!(p.iter().all(|q| (q[0].hypot(q[1]) - 1.0).abs() < 1e-12));
    let (area, c) = voussoir::geometry::area_centroid(p);
    let exact = 0.5 * 36.0 * (5f64.to_radians()).sin();
    assert!(
        (area - exact).abs() < 1e-12 && c[1] > 0.4 && c[1] < 0.43,
        "{area} {c:?}"
    );
}

#[test]
fn lact3_with_mohr_coulomb_joints_matches_lact3_tilt_angles() {
    // LACT3's solver test: cohesionless joints with friction angle φ collapse at tilt θ. A tilt
    // θ rotates gravity, W(sin θ, −cos θ) = cos θ · W(tan θ, −1): with no cohesion and no
    // crushing the collapse state is scale-free, so λ = tan θ. LACT3 steps the tilt to 0.01°;
    // we allow 0.02°.
    for (file, phi, theta) in [
        ("Portal.dxf", 30.0f64, 27.30f64),
        ("wall.dxf", 26.0, 16.73),
        ("arch_1.dxf", 30.0, 17.10),
    ] {
        let (mut m, _) = read_dxf(&lact3(file), &mm()).unwrap();
        m.materials.get_mut("default").unwrap().friction = Some(phi.to_radians().tan());
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let r = limit(&st, &SolverOptions::default()).unwrap();
        let got = r.load_multiplier.unwrap().atan().to_degrees();
        assert!(
            (got - theta).abs() <= 0.02,
            "{file}: collapse tilt {got}°, LACT3 {theta}°"
        );
    }
}
