//! Issue 28, items 5, 7 and 10 (b) through the CLI: `voussoir export` refuses, in one line naming
//! the block and writing nothing, every model a reader refuses (and what the OBJ importer would
//! not read back); a hollow block goes out and back with the hollow block's λ; the VTK pieces
//! declare signed connectivity; `export`/`import` report success only once the file is written.
//! References: hand calculations on boxes (in the tests).

use crate::common;
use crate::common::{cwd::fails, cwd::ok};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("issue28io", name)
}

fn lambda(model: &str) -> f64 {
    let o = ok(&["limit", model, "--json"]);
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    v["load_multiplier"].as_f64().unwrap()
}

type Shape = (Vec<[f64; 3]>, Vec<Vec<usize>>);

/// The box [lo, hi]: vertices and faces counter-clockwise seen from outside (turned round if
/// `inward`).
fn cuboid(lo: [f64; 3], hi: [f64; 3], inward: bool) -> Shape {
    let v = (0..8)
        .map(|i| {
            [
                if i & 1 == 0 { lo[0] } else { hi[0] },
                if i & 2 == 0 { lo[1] } else { hi[1] },
                if i & 4 == 0 { lo[2] } else { hi[2] },
            ]
        })
        .collect();
    let mut f = vec![
        vec![0, 2, 3, 1],
        vec![4, 5, 7, 6],
        vec![0, 1, 5, 4],
        vec![2, 6, 7, 3],
        vec![0, 4, 6, 2],
        vec![1, 3, 7, 5],
    ];
    if inward {
        for g in f.iter_mut() {
            g.reverse();
        }
    }
    (v, f)
}

fn join((mut v, mut f): Shape, (v2, f2): Shape) -> Shape {
    let off = v.len();
    v.extend(v2);
    f.extend(
        f2.into_iter()
            .map(|g| g.into_iter().map(|i| i + off).collect()),
    );
    (v, f)
}

fn body((v, f): &Shape) -> Value {
    json!({ "vertices": v, "faces": f })
}

/// Blocks on the base [−1, 2]² × [−0.5, 0], γ = 20 kN/m³, tilting load W·[1, 0, 0].
fn model(blocks: &[Shape]) -> Value {
    let mut base = body(&cuboid([-1.0, -1.0, -0.5], [2.0, 2.0, 0.0], false));
    base["name"] = json!("base");
    json!({
        "materials": { "default": { "unit_weight": 20.0 } },
        "blocks": blocks.iter().map(body).collect::<Vec<_>>(),
        "supports": [base],
        "loads": { "live": [ { "type": "body", "coefficients": [1, 0, 0] } ] }
    })
}

fn write(dir: &Path, name: &str, v: &Value) -> String {
    let p = dir.join(name);
    std::fs::write(&p, serde_json::to_string(v).unwrap()).unwrap();
    p.to_string_lossy().into_owned()
}

fn tall() -> Shape {
    cuboid([0.0, 0.0, 0.0], [1.0, 1.0, 1.5], false)
}

/// The block 1 × 1 × 1.5 with the cube cavity [0.25, 0.75]² × [0.75, 1.25]; the cavity's faces
/// face into it if `cavity_inward`, else outwards like the block's (counted twice).
fn hollow(cavity_inward: bool) -> Shape {
    join(
        tall(),
        cuboid([0.25, 0.25, 0.75], [0.75, 0.75, 1.25], cavity_inward),
    )
}

#[test]
fn issue28_item5_export_refuses_what_no_reader_accepts() {
    let d = tmpdir("refuse");
    let mut open = tall();
    open.1.pop();
    let flat = cuboid([0.0, 0.0, 0.0], [1.0, 1.0, 0.0], false);
    let mut empty = model(&[]);
    empty["blocks"] = json!([]);
    let huge = {
        let mut m = model(&[cuboid([0.0, 0.0, 0.0], [1e308, 1.0, 1.5], false)]);
        m["supports"][0] = body(&cuboid([-1e308, -1.0, -0.5], [1e308, 2.0, 0.0], false));
        m["supports"][0]["name"] = json!("base");
        m
    };
    // (model, what the one-line refusal names); each is refused by `limit` too.
    let cases: Vec<(&str, Value, Vec<&str>)> = vec![
        ("open", model(&[open]), vec!["block 0", "open"]),
        (
            "overlap",
            model(&[tall(), cuboid([0.5, 0.0, 0.0], [1.5, 1.0, 1.5], false)]),
            vec!["block 0 and block 1 overlap"],
        ),
        ("zero_volume", model(&[flat]), vec!["block 0", "degenerate"]),
        (
            "floating",
            model(&[tall(), cuboid([0.0, 0.0, 3.0], [1.0, 1.0, 4.0], false)]),
            vec!["block 1 touches nothing"],
        ),
        ("empty", empty, vec!["no blocks"]),
        ("huge", huge, vec!["overflows"]),
        (
            "nested",
            model(&[hollow(false)]),
            vec!["block 0", "faces 6–11", "count its volume twice"],
        ),
        (
            "two_pieces",
            model(&[join(
                tall(),
                cuboid([3.0, 0.0, 0.0], [4.0, 1.0, 1.5], false),
            )]),
            vec!["block 0", "separate closed surfaces"],
        ),
    ];
    for (name, m, needles) in cases {
        let js = write(&d, &format!("{name}.json"), &m);
        let obj = d.join(format!("{name}.obj"));
        let mut want = needles.clone();
        want.push("not exported");
        fails(&["export", &js, "-o", obj.to_str().unwrap()], &want);
        assert!(!obj.exists(), "{name}: an OBJ was written");
        fails(&["limit", &js], &needles);
    }
    // No stray temporary files either.
    let left: Vec<_> = std::fs::read_dir(&d)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".json"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
}

#[test]
fn issue28_item5_export_refuses_an_obj_that_would_not_read_back() {
    let d = tmpdir("readback");
    // Valid for the analyses, but two supports would be one OBJ object `support_a_b`.
    let mut m = model(&[tall()]);
    let mut lower = body(&cuboid([-1.0, -1.0, -1.5], [2.0, 2.0, -0.5], false));
    lower["name"] = json!("a_b");
    m["supports"][0]["name"] = json!("a b");
    m["supports"].as_array_mut().unwrap().push(lower);
    let js = write(&d, "names.json", &m);
    assert!((lambda(&js) - 1.0 / 1.5).abs() < 1e-9);
    let obj = d.join("names.obj");
    fails(
        &["export", &js, "-o", obj.to_str().unwrap()],
        &["not exported", "'a b'", "'a_b'", "support_a_b"],
    );
    assert!(!obj.exists());
    // Valid at the model's own tolerance 1e-10, but a plate 1e-8 m thin has degenerate sides
    // at the tolerance `voussoir import` reads an OBJ with (1e-7 of the diagonal).
    let mut m = model(&[
        tall(),
        cuboid([0.0, 0.0, 1.5], [1.0, 1.0, 1.5 + 1e-8], false),
    ]);
    m["tolerance"] = json!(1e-10);
    let js = write(&d, "thin.json", &m);
    assert!((lambda(&js) - 1.0 / 1.5).abs() < 1e-6);
    let obj = d.join("thin.obj");
    fails(
        &["export", &js, "-o", obj.to_str().unwrap()],
        &["not exported", "would not read back", "block_1"],
    );
    assert!(!obj.exists());
}

#[test]
fn issue28_item5_a_hollow_block_goes_out_and_back_with_the_hollow_lambda() {
    // By hand: V = 1.5 − 0.125 = 1.375, z̄ = (1.5·0.75 − 0.125·1)/1.375 = 1/1.375, tipping about
    // x = 1: λ = 0.5/z̄ = 0.6875 (0.65 if the cavity were counted as solid a second time).
    let d = tmpdir("hollow");
    let js = write(&d, "hollow.json", &model(&[hollow(true)]));
    let obj = d.join("hollow.obj");
    let back = d.join("back.json");
    let (o, b) = (obj.to_str().unwrap(), back.to_str().unwrap());
    ok(&["export", &js, "-o", o]);
    ok(&["import", o, "-o", b]);
    for m in [js.as_str(), o, b] {
        let l = lambda(m);
        assert!((l - 0.6875).abs() < 1e-9, "{m}: λ = {l}");
    }
    // The same block as a modeller writes it (the cavity's faces as an outward box): the OBJ
    // importer orients it as the cavity it is, with a note, and λ is the hollow block's.
    let text = std::fs::read_to_string(&obj).unwrap();
    let mut lines: Vec<String> = Vec::new();
    let mut face = 0;
    for l in text.lines() {
        if let Some(rest) = l.strip_prefix("f ") {
            face += 1;
            // Faces 7–12 of block_0 are the cavity's.
            if (7..=12).contains(&face) {
                let mut idx: Vec<&str> = rest.split_whitespace().collect();
                idx.reverse();
                lines.push(format!("f {}", idx.join(" ")));
                continue;
            }
        }
        lines.push(l.to_string());
    }
    let outward = d.join("outward.obj");
    std::fs::write(&outward, lines.join("\n") + "\n").unwrap();
    let ow = outward.to_str().unwrap();
    let o2 = ok(&["limit", ow, "--json"]);
    let err = String::from_utf8_lossy(&o2.stderr);
    assert!(err.contains("read as cavities"), "{err}");
    let v: Value = serde_json::from_slice(&o2.stdout).unwrap();
    let l = v["load_multiplier"].as_f64().unwrap();
    assert!((l - 0.6875).abs() < 1e-9, "λ = {l}");
}

#[test]
fn issue28_item10_export_and_import_report_success_only_after_writing() {
    let d = tmpdir("order");
    let js = write(&d, "box.json", &model(&[tall()]));
    let obj = d.join("box.obj");
    let o = obj.to_str().unwrap();
    // Success: the line comes, and the file is there.
    let out = ok(&["export", &js, "-o", o]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("written as OBJ objects"));
    assert!(obj.exists());
    let before = std::fs::read(&obj).unwrap();
    // The output is the input: only the refusal, no success line, the file untouched.
    let e = fails(
        &["export", o, "-o", o],
        &["refusing to write", "it is the input"],
    );
    assert!(!e.contains("written"), "{e}");
    let e = fails(
        &["import", o, "-o", o],
        &["refusing to write", "it is the input"],
    );
    assert!(!e.contains("joints"), "{e}");
    assert_eq!(std::fs::read(&obj).unwrap(), before);
    // The output is a directory.
    let dir = d.join("dir.obj");
    std::fs::create_dir(&dir).unwrap();
    let e = fails(
        &["export", &js, "-o", dir.to_str().unwrap()],
        &["refusing to write", "not a regular file"],
    );
    assert!(!e.contains("written as OBJ"), "{e}");
    let dirj = d.join("dir.json");
    std::fs::create_dir(&dirj).unwrap();
    let e = fails(
        &["import", o, "-o", dirj.to_str().unwrap()],
        &["refusing to write", "not a regular file"],
    );
    assert!(!e.contains("joints"), "{e}");
}

/// The `(file, declared type)` of each cells array of a `.vtu`.
fn cell_array_types(vtu: &str) -> Vec<(String, String)> {
    ["connectivity", "offsets", "types"]
        .iter()
        .map(|name| {
            let key = format!("Name=\"{name}\"");
            let at = vtu.find(&key).unwrap_or_else(|| panic!("no {name} array"));
            let head = &vtu[..at];
            let t = head.rfind("type=\"").unwrap();
            let ty = head[t + 6..].split('"').next().unwrap().to_string();
            (name.to_string(), ty)
        })
        .collect()
}

#[test]
fn issue28_item7_every_vtk_piece_declares_signed_connectivity_and_reads_back() {
    use vtkio::model::{DataSet, Vtk};
    let d = tmpdir("vtk");
    let js = write(
        &d,
        "box.json",
        &model(&[tall(), cuboid([0.0, 0.0, 1.5], [1.0, 1.0, 2.5], false)]),
    );
    let vtm = d.join("out.vtm");
    ok(&["limit", &js, "--vtk", vtm.to_str().unwrap()]);
    // Two boxes tipping: 2 × 8 vertices and 2 × 6 faces; 2 joints × 4 corners; the base.
    let want = [
        ("out_blocks.vtu", 16, 12),
        ("out_contacts.vtu", 8, 8),
        ("out_supports.vtu", 8, 6),
    ];
    let listed = std::fs::read_to_string(&vtm).unwrap();
    for (file, points, cells) in want {
        assert!(listed.contains(&format!("file=\"{file}\"")), "{listed}");
        let text = std::fs::read_to_string(d.join(file)).unwrap();
        assert_eq!(
            cell_array_types(&text),
            [
                ("connectivity".into(), "Int64".into()),
                ("offsets".into(), "Int64".into()),
                ("types".into(), "UInt8".into())
            ],
            "{file}"
        );
        assert!(text.contains(&format!(
            "<Piece NumberOfPoints=\"{points}\" NumberOfCells=\"{cells}\">"
        )));
        let v = Vtk::parse_xml(text.as_bytes()).unwrap();
        let DataSet::UnstructuredGrid { pieces, .. } = v.data else {
            panic!("{file}: not an unstructured grid")
        };
        let p = pieces
            .into_iter()
            .next()
            .unwrap()
            .into_loaded_piece_data(None)
            .unwrap();
        assert_eq!(
            (p.num_points(), p.cells.types.len()),
            (points, cells),
            "{file}"
        );
    }
    // The cracks: at least the joint the mechanism opens, with the same declared types.
    let cracks = std::fs::read_to_string(d.join("out_cracks.vtu")).unwrap();
    assert_eq!(cell_array_types(&cracks)[0].1, "Int64");
    // A settlement without cracks (the base moves down rigidly): the cracks block is listed
    // without a file, and none is written.
    let vtm2 = d.join("still.vtm");
    ok(&[
        "settle",
        &js,
        "--move",
        "base=0,0,-0.01",
        "--vtk",
        vtm2.to_str().unwrap(),
    ]);
    let listed = std::fs::read_to_string(&vtm2).unwrap();
    assert!(
        listed.contains("<DataSet index=\"2\" name=\"cracks\"/>"),
        "{listed}"
    );
    assert!(!d.join("still_cracks.vtu").exists());
    assert!(d.join("still_supports.vtu").exists());
}
