//! OBJ/PLY import (mesh.rs): triangulated faces merged back, supports found, the limit
//! multiplier of the imported structure against hand calculations, OBJ round trip, and one-line
//! errors naming the object. Fixtures: tests/fixtures/mesh/, written by make_fixtures.py there
//! (geometry by hand, described in the script).

use std::path::Path;
use voussoir::analysis::limit::{limit, LimitStatus};
use voussoir::lp::SolverOptions;
use voussoir::model3d::Model3d;
use voussoir::{BuildOptions, Structure3d};
use voussoir_io::mesh::{model_to_obj, parse_obj, read_mesh, MeshOptions};

fn fixture(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/mesh")
        .join(name)
}

fn lambda(m: &Model3d) -> (f64, Structure3d) {
    let st = Structure3d::new(m, BuildOptions::default()).expect("the imported model is valid");
    let r = limit(&st, &SolverOptions::default()).expect("limit analysis solves");
    assert_eq!(r.status, LimitStatus::Collapse, "{}", r.message);
    (r.load_multiplier.expect("a collapse has λ"), st)
}

/// tower.obj: a base (support, z ∈ [−0.5, 0]) and three boxes b × d × h = 0.5 × 0.5 × 1
/// stacked on it, every face triangulated (the base's top is a fan of four triangles around an
/// extra centre vertex; the middle box has an extra vertex half-way up one vertical edge).
///
/// Live load λ·W·[1, 0, 0] at each block's centroid, W its weight; friction infinite.
/// Hand calculation. Overturning of the top k blocks about the +x edge of the joint under them:
/// the horizontal forces act at heights h/2, 3h/2, …, (2k−1)h/2 above the pivot, so the
/// overturning moment is λW·h·(1 + 3 + … + (2k−1))/2 = λW·h·k²/2; the weights resist with
/// kW·b/2. Hence λ_k = (k·b/2)/(h·k²/2) = b/(k·h), least for k = n = 3:
///   λ = b/(n·h) = 0.5/(3·1) = 1/6.
/// It is also the static bound: at λ = 1/6 the resultant on the joint under the top k blocks
/// has eccentricity λ·h·k/2 = k/12 ≤ b/2 = 0.25 (= b/2 only at the base, k = 3), so every joint
/// is admissible; lower and upper bounds coincide. Tolerance 1e-7 (LP round-off).
#[test]
fn triangulated_tower_merges_faces_and_overturns_at_b_over_nh() {
    let (m, rep) = read_mesh(&fixture("tower.obj"), &MeshOptions::default()).unwrap();
    assert_eq!(m.blocks.len(), 3);
    assert_eq!(m.supports.len(), 1);
    assert_eq!(m.supports[0].name, "base");
    assert_eq!(
        rep.block_sources,
        [
            "OBJ object 'tower_1'",
            "OBJ object 'tower_2'",
            "OBJ object 'tower_3'"
        ]
    );
    // Every triangulated box is back to 6 quadrilaterals on 8 vertices: the fan's centre and the
    // mid-edge vertex are gone (the latter was on a straight edge between two merged faces).
    for b in &m.blocks {
        assert_eq!(b.faces.len(), 6);
        assert!(b.faces.iter().all(|f| f.len() == 4), "{:?}", b.faces);
        assert_eq!(b.vertices.len(), 8);
    }
    assert_eq!(m.supports[0].faces.len(), 6);
    assert_eq!(m.supports[0].vertices.len(), 8);
    // Input faces: base 14 (12 + 2 for the fan), tower 12 + 14 + 12; written: 4 × 6.
    assert_eq!((rep.faces_read, rep.faces_written), (52, 24));
    let (l, st) = lambda(&m);
    // Volumes 0.25 m³ each (hand: 0.5 × 0.5 × 1).
    for b in &st.blocks {
        assert!((b.shape.volume - 0.25).abs() < 1e-12, "{}", b.shape.volume);
    }
    // One joint per stacked pair and one on the base: 3 joints, each the full 0.5 × 0.5 square.
    assert_eq!(st.joints.len(), 3);
    for j in &st.joints {
        assert!((j.area - 0.25).abs() < 1e-12, "{}", j.area);
    }
    assert!((l - 1.0 / 6.0).abs() < 1e-7, "λ = {l}, hand 1/6");
}

/// Units: the same tower read as centimetres is 100 times smaller; λ = b/(n·h) is
/// scale-free, the volumes scale by 1e-6.
#[test]
fn units_scale_to_metres() {
    let opts = MeshOptions {
        units: voussoir_io::dxf::Units::Cm,
        ..Default::default()
    };
    let (m, _) = read_mesh(&fixture("tower.obj"), &opts).unwrap();
    let (l, st) = lambda(&m);
    assert!((st.blocks[0].shape.volume - 0.25e-6).abs() < 1e-18);
    assert!((l - 1.0 / 6.0).abs() < 1e-7, "λ = {l}");
}

/// two.ply (ASCII, quads) and two_binary.ply (binary, triangles): a base 1 × 1 × 0.2 and one
/// block b × d × h = 0.4 × 0.6 × 1.2 on it. Each connected component is a body; the lower one
/// stands on the ground plane and is the support. Hand: a single block overturns about its +x
/// bottom edge when λW·h/2 = W·b/2, λ = b/h = 0.4/1.2 = 1/3 (tolerance 1e-7).
#[test]
fn ply_two_boxes_ascii_and_binary() {
    for name in ["two.ply", "two_binary.ply"] {
        let (m, rep) = read_mesh(&fixture(name), &MeshOptions::default()).unwrap();
        assert_eq!(rep.block_sources, ["PLY part 'part_1'"], "{name}");
        assert_eq!(rep.support_sources, ["PLY part 'part_0'"], "{name}");
        assert_eq!(m.blocks[0].faces.len(), 6, "{name}");
        let (l, st) = lambda(&m);
        assert!((st.blocks[0].shape.volume - 0.288).abs() < 1e-12, "{name}");
        assert!((l - 1.0 / 3.0).abs() < 1e-7, "{name}: λ = {l}, hand 1/3");
    }
}

/// Round trip: the tower exported as OBJ and read again has the same blocks (volumes to 1e-12
/// relative; in fact the same vertices and faces, since coordinates are written exactly) and the
/// same λ; the support keeps its name through the `support_` convention.
#[test]
fn obj_export_round_trips() {
    let (m, _) = read_mesh(&fixture("tower.obj"), &MeshOptions::default()).unwrap();
    let text = model_to_obj(&m);
    assert!(text.contains("\no block_0\n") && text.contains("\no support_base\n"));
    let (m2, rep2) = parse_obj(text.as_bytes(), &MeshOptions::default(), "t.obj").unwrap();
    assert_eq!(rep2.support_rule, "objects named 'support_…'");
    assert_eq!(m2.supports[0].name, "base");
    assert_eq!(m2.blocks, m.blocks);
    let (l1, s1) = lambda(&m);
    let (l2, s2) = lambda(&m2);
    for (a, b) in s1.blocks.iter().zip(&s2.blocks) {
        assert!((a.shape.volume - b.shape.volume).abs() <= 1e-12 * a.shape.volume);
    }
    assert!((l1 - l2).abs() < 1e-12, "{l1} vs {l2}");
    // Exporting again gives the same bytes.
    assert_eq!(
        model_to_obj(&m2).lines().skip(2).collect::<Vec<_>>(),
        text.lines().skip(2).collect::<Vec<_>>()
    );
}

/// A generated model (the vault fixture, written as JSON with quadrilateral faces) round-trips
/// through OBJ too: same vertices and faces, same λ.
#[test]
fn json_model_round_trips_through_obj() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/vault3d.json"),
    )
    .unwrap();
    let voussoir::model3d::AnyModel::Spatial(m) =
        voussoir::model3d::AnyModel::from_json(&text).unwrap()
    else {
        panic!("the vault fixture is 3D")
    };
    let obj = model_to_obj(&m);
    let (m2, _) = parse_obj(obj.as_bytes(), &MeshOptions::default(), "v.obj").unwrap();
    assert_eq!(m2.blocks.len(), m.blocks.len());
    let names: Vec<&str> = m2.supports.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["right", "left"]);
    let (l1, s1) = lambda(&m);
    let (l2, s2) = lambda(&m2);
    for (a, b) in s1.blocks.iter().zip(&s2.blocks) {
        assert!((a.shape.volume - b.shape.volume).abs() <= 1e-12 * a.shape.volume);
    }
    assert!((l1 - l2).abs() <= 1e-9 * l1, "{l1} vs {l2}");
}

#[test]
fn open_mesh_names_the_object() {
    let e = read_mesh(&fixture("open.obj"), &MeshOptions::default()).unwrap_err();
    let msg = e.to_string();
    assert!(!msg.contains('\n'));
    assert!(
        msg.contains("OBJ object 'cracked_box'") && msg.contains("open"),
        "{msg}"
    );
}

#[test]
fn non_manifold_mesh_names_the_object() {
    let e = read_mesh(&fixture("nonmanifold.obj"), &MeshOptions::default()).unwrap_err();
    let msg = e.to_string();
    assert!(!msg.contains('\n'));
    assert!(
        msg.contains("OBJ object 'bowtie'") && msg.contains("not a manifold surface"),
        "{msg}"
    );
    assert!(msg.contains("shared by 4 faces"), "{msg}");
}

#[test]
fn self_intersecting_mesh_names_the_object() {
    let e = read_mesh(&fixture("selfintersecting.obj"), &MeshOptions::default()).unwrap_err();
    let msg = e.to_string();
    assert!(!msg.contains('\n'));
    assert!(
        msg.contains("OBJ object 'folded': the surface intersects itself"),
        "{msg}"
    );
}

#[test]
fn supports_by_name_and_prefix_and_bad_names() {
    let path = fixture("tower.obj");
    // The bottom box as a second support: two supports, two blocks.
    let o = MeshOptions {
        supports: vec!["base".into(), "tower_1".into()],
        ..Default::default()
    };
    let (m, _) = read_mesh(&path, &o).unwrap();
    assert_eq!((m.blocks.len(), m.supports.len()), (2, 2));
    // λ for the two remaining boxes: b/(2h) = 0.25 (same hand calculation, n = 2).
    let (l, _) = lambda(&m);
    assert!((l - 0.25).abs() < 1e-7, "λ = {l}");
    let o = MeshOptions {
        support_prefix: Some("ba".into()),
        ..Default::default()
    };
    assert_eq!(read_mesh(&path, &o).unwrap().0.supports.len(), 1);
    let o = MeshOptions {
        supports: vec!["nope".into()],
        ..Default::default()
    };
    let msg = read_mesh(&path, &o).unwrap_err().to_string();
    assert!(
        msg.contains("no OBJ object is named 'nope'") && msg.contains("'tower_2'"),
        "{msg}"
    );
}

#[test]
fn garbage_is_refused_in_one_line() {
    let o = MeshOptions::default();
    for (bytes, ply) in [
        (
            &b"ply\nformat ascii 1.0\nelement vertex 2\nend_header\n1 2\n"[..],
            true,
        ),
        (&b"not a ply"[..], true),
        (&b"v 0 0 0\nf 1 2 3\n"[..], false),
        (&b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"[..], false),
        (
            &b"v nan 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n"[..],
            false,
        ),
        (&b""[..], false),
    ] {
        let r = if ply {
            voussoir_io::mesh::parse_ply(bytes, &o, "x.ply")
        } else {
            parse_obj(bytes, &o, "x.obj")
        };
        let msg = r.unwrap_err().to_string();
        assert!(!msg.is_empty() && !msg.contains('\n'), "{msg}");
        eprintln!("{msg}");
    }
}
