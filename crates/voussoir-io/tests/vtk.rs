//! VTK output of 3D results: written with vtkio, read back with vtkio's XML reader, and the
//! values compared with the JSON result and with motions computed by hand.

use voussoir::analysis::{LimitResult, SettlementResult};
use voussoir::dim::Three;
use voussoir_io::vtk::{blocks_vtu, contacts_vtu, cracks_vtu, multiblock, supports_vtu};
use vtkio::model::{Attribute, CellType, DataSet, UnstructuredGridPiece, VertexNumbers, Vtk};

fn fixture() -> SettlementResult<Three> {
    let text = include_str!("fixtures/settlement3d_two_cubes.json");
    serde_json::from_str(text).expect("fixture parses as a 3D settlement result")
}

fn read(bytes: &[u8]) -> UnstructuredGridPiece {
    let vtk = Vtk::parse_xml(bytes).expect("vtkio reads what we wrote");
    match vtk.data {
        DataSet::UnstructuredGrid { pieces, .. } => {
            assert_eq!(pieces.len(), 1);
            pieces
                .into_iter()
                .next()
                .unwrap()
                .into_loaded_piece_data(None)
                .unwrap()
        }
        other => panic!("expected an unstructured grid, got {other:?}"),
    }
}

fn array(attrs: &[Attribute], name: &str) -> (u32, Vec<f64>) {
    let a = attrs
        .iter()
        .find(|a| a.name() == name)
        .unwrap_or_else(|| panic!("no array {name}"));
    match a {
        Attribute::DataArray(d) => (d.elem.num_comp(), d.data.cast_into::<f64>().unwrap()),
        _ => panic!("{name} is not a data array"),
    }
}

fn cells(p: &UnstructuredGridPiece) -> (Vec<u64>, Vec<u64>) {
    match &p.cells.cell_verts {
        VertexNumbers::XML {
            connectivity,
            offsets,
        } => (connectivity.clone(), offsets.clone()),
        VertexNumbers::Legacy { .. } => panic!("expected XML cells"),
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12
}

#[test]
fn blocks_read_back_with_the_rigid_displacement_of_each_vertex() {
    let r = fixture();
    let piece = read(&blocks_vtu(&r).unwrap());
    // Two cubes of 6 faces, 8 vertices each (vertices are not shared between blocks).
    assert_eq!(piece.cells.types.len(), 12);
    assert!(piece.cells.types.iter().all(|t| *t == CellType::Polygon));
    assert_eq!(piece.num_points(), 16);
    let pts = piece.points.cast_into::<f64>().unwrap();
    let (nc, disp) = array(&piece.data.point, "displacement");
    assert_eq!(nc, 3);
    // Vertex 6 of block 1 is (1, 1, 2); block 1 moves by u = (0.003, 0, −0.009),
    // θ = (0, 0.002, 0) about c = (0.5, 0.5, 1.5). By hand, r = x − c = (0.5, 0.5, 0.5):
    // θ × r = (θy rz − θz ry, θz rx − θx rz, θx ry − θy rx) = (0.001, 0, −0.001),
    // so the displacement is (0.004, 0, −0.010).
    let k = 8 + 6;
    assert_eq!(&pts[3 * k..3 * k + 3], &[1.0, 1.0, 2.0]);
    let want = [0.004, 0.0, -0.010];
    for c in 0..3 {
        assert!(
            close(disp[3 * k + c], want[c]),
            "{:?}",
            &disp[3 * k..3 * k + 3]
        );
    }
    // Vertex 0 of block 0, (0, 0, 0): r = (−0.5, −0.5, −0.5), θ × r = (−0.001, 0, 0.001),
    // displacement (0, 0, −0.008): 2 mm above the base, which settles by 10 mm.
    let want = [0.0, 0.0, -0.008];
    for c in 0..3 {
        assert!(close(disp[c], want[c]), "{:?}", &disp[0..3]);
    }
    // Cell data: block ids, translations and rotations per face.
    let (_, block) = array(&piece.data.cell, "block");
    assert_eq!(
        block,
        [0.0; 6]
            .iter()
            .chain(&[1.0; 6])
            .copied()
            .collect::<Vec<_>>()
    );
    let (nc, tr) = array(&piece.data.cell, "translation");
    assert_eq!(nc, 3);
    assert_eq!(&tr[3 * 6..3 * 6 + 3], &[0.003, 0.0, -0.009]);
    let (_, rot) = array(&piece.data.cell, "rotation");
    assert_eq!(&rot[0..3], &[0.0, 0.002, 0.0]);
    // The first face of block 1 is [0, 3, 2, 1] shifted by block 0's 8 vertices.
    let (conn, offsets) = cells(&piece);
    assert_eq!(offsets.len(), 12);
    assert_eq!(&conn[24..28], &[8, 11, 10, 9]);
}

#[test]
fn contact_points_carry_the_json_values() {
    let r = fixture();
    let piece = read(&contacts_vtu(&r).unwrap());
    assert_eq!(piece.cells.types.len(), 8);
    assert!(piece.cells.types.iter().all(|t| *t == CellType::Vertex));
    let (_, opening) = array(&piece.data.point, "opening");
    let (_, nf) = array(&piece.data.point, "normal_force");
    let (nc, sliding) = array(&piece.data.point, "sliding");
    assert_eq!(nc, 2);
    let (nc, shear) = array(&piece.data.point, "shear_force");
    assert_eq!(nc, 2);
    let (nc, normal) = array(&piece.data.point, "normal");
    assert_eq!(nc, 3);
    assert_eq!(sliding.len(), 16);
    assert_eq!(shear.len(), 16);
    let mut k = 0;
    for j in &r.joints {
        for p in &j.points {
            assert!(close(opening[k], p.opening), "point {k}");
            assert!(close(nf[k], p.normal_force), "point {k}");
            assert!(close(sliding[2 * k], p.sliding[0]) && close(sliding[2 * k + 1], p.sliding[1]));
            assert_eq!(&normal[3 * k..3 * k + 3], &j.normal);
            k += 1;
        }
    }
    // The first point of joint 0 opens by 2 mm (the JSON value).
    assert!(close(opening[0], 0.002));
    // Its displacement moves with body a, the base: the prescribed settlement w = −10 mm.
    let (_, disp) = array(&piece.data.point, "displacement");
    assert!(close(disp[2], -0.01));
}

#[test]
fn cracks_are_the_joints_that_are_not_closed() {
    let r = fixture();
    let piece = read(&cracks_vtu(&r).unwrap());
    // Joint 0 (hinge) only: one quadrilateral.
    assert_eq!(piece.cells.types, vec![CellType::Polygon]);
    assert_eq!(piece.num_points(), 4);
    let (_, state) = array(&piece.data.cell, "state");
    assert_eq!(state, vec![1.0]);
    let (_, maxo) = array(&piece.data.cell, "max_opening");
    assert!(close(maxo[0], 0.002));
    // The polygon goes round the joint (counter-clockwise about +z): consecutive points are
    // adjacent corners of the unit square, never its diagonal.
    let pts = piece.points.cast_into::<f64>().unwrap();
    let (conn, _) = cells(&piece);
    for k in 0..4 {
        let (a, b) = (conn[k] as usize, conn[(k + 1) % 4] as usize);
        let d: f64 = (0..3)
            .map(|c| (pts[3 * a + c] - pts[3 * b + c]).powi(2))
            .sum();
        assert!(close(d, 1.0), "edge {k}: {d}");
    }
}

#[test]
fn supports_move_by_their_prescribed_motion() {
    let r = fixture();
    let piece = read(&supports_vtu(&r).unwrap());
    assert_eq!(piece.cells.types.len(), 6);
    let (_, disp) = array(&piece.data.point, "displacement");
    assert_eq!(disp.len(), 24);
    for v in disp.chunks(3) {
        assert!(close(v[0], 0.0) && close(v[1], 0.0) && close(v[2], -0.01));
    }
}

#[test]
fn multiblock_names_its_pieces_and_is_deterministic() {
    let r = fixture();
    let files = multiblock(&r, "arch.vtm", true).unwrap();
    let names: Vec<&str> = files.iter().map(|f| f.0.as_str()).collect();
    assert_eq!(
        names,
        [
            "arch.vtm",
            "arch_blocks.vtu",
            "arch_contacts.vtu",
            "arch_cracks.vtu",
            "arch_supports.vtu"
        ]
    );
    let vtm = std::str::from_utf8(&files[0].1).unwrap();
    let doc = roxmltree::Document::parse(vtm).unwrap();
    let sets: Vec<(String, String)> = doc
        .descendants()
        .filter(|n| n.has_tag_name("DataSet"))
        .map(|n| {
            (
                n.attribute("name").unwrap().to_string(),
                n.attribute("file").unwrap().to_string(),
            )
        })
        .collect();
    assert_eq!(sets.len(), 4);
    assert_eq!(sets[0], ("blocks".into(), "arch_blocks.vtu".into()));
    assert_eq!(sets[3], ("supports".into(), "arch_supports.vtu".into()));
    // Each piece is the part function's output, and every piece reads back.
    assert_eq!(files[1].1, blocks_vtu(&r).unwrap());
    for (_, bytes) in &files[1..] {
        read(bytes);
    }
    // Same input, same bytes.
    assert_eq!(files, multiblock(&r, "arch.vtm", true).unwrap());
    // Without supports: three pieces.
    assert_eq!(multiblock(&r, "arch.vtm", false).unwrap().len(), 4);
    // A path is refused (the caller writes the pieces beside the .vtm).
    assert!(multiblock(&r, "out/arch.vtm", true).is_err());
    assert!(multiblock(&r, "", true).is_err());
}

#[test]
fn a_closed_structure_writes_no_crack_file() {
    let mut r = fixture();
    for j in &mut r.joints {
        j.state = voussoir::result::JointState::Closed;
    }
    let piece = read(&cracks_vtu(&r).unwrap());
    assert_eq!(piece.cells.types.len(), 0);
    assert_eq!(piece.num_points(), 0);
    // The piece states its zero counts, as the format requires.
    let bytes = cracks_vtu(&r).unwrap();
    let text = std::str::from_utf8(&bytes).unwrap();
    assert!(text.contains("<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\">"));
    // In a multiblock the empty block is listed without a file, and no file is written.
    let files = multiblock(&r, "arch.vtm", true).unwrap();
    let names: Vec<&str> = files.iter().map(|f| f.0.as_str()).collect();
    assert_eq!(
        names,
        [
            "arch.vtm",
            "arch_blocks.vtu",
            "arch_contacts.vtu",
            "arch_supports.vtu"
        ]
    );
    let vtm = std::str::from_utf8(&files[0].1).unwrap();
    assert!(
        vtm.contains("<DataSet index=\"2\" name=\"cracks\"/>"),
        "{vtm}"
    );
    assert!(vtm.contains("<DataSet index=\"3\" name=\"supports\" file=\"arch_supports.vtu\"/>"));
}

#[test]
fn a_corrupt_face_is_an_error_not_a_panic() {
    let mut r = fixture();
    r.geometry.blocks[1].faces[2] = vec![0, 1, 99];
    let e = blocks_vtu(&r).unwrap_err();
    assert!(e.0.contains("block 1") && e.0.contains("vertex 99"), "{e}");
    r.geometry.blocks[1].faces[2] = vec![0, 1];
    assert!(contacts_vtu(&r).is_err());
}

#[test]
fn limit_results_write_too() {
    // The same shapes as a limit result: supports stay at rest.
    let s = fixture();
    let mut v = serde_json::to_value(&s).unwrap();
    let o = v.as_object_mut().unwrap();
    for k in ["work_reactions", "duality_gap", "certificate"] {
        o.remove(k);
    }
    o.insert("status".into(), "collapse".into());
    o.insert("load_multiplier".into(), 0.5.into());
    o.insert("work_live_loads".into(), 1.0.into());
    o.insert("iterations".into(), 3.into());
    let r: LimitResult<Three> = serde_json::from_value(v).unwrap();
    let piece = read(&supports_vtu(&r).unwrap());
    let (_, disp) = array(&piece.data.point, "displacement");
    assert!(disp.iter().all(|x| *x == 0.0));
    assert_eq!(read(&blocks_vtu(&r).unwrap()).cells.types.len(), 12);
}
