//! 3D models through the binary: `limit vault.json --vtk v.vtu` read back with vtkio equal to the
//! JSON result; a vault and a dome made by the generators, exported to OBJ and re-imported,
//! give the same blocks, interfaces, λ and settlement results; a 3D capacity run.

use crate::common;
use crate::common::{gen_model, json_file as json, run};
use std::path::PathBuf;
use vtkio::model::{Attribute, DataSet, Vtk};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("3dcli", name)
}

fn array(attrs: &[Attribute], name: &str) -> Vec<f64> {
    match attrs.iter().find(|a| a.name() == name) {
        Some(Attribute::DataArray(d)) => d.data.clone().cast_into::<f64>().unwrap(),
        _ => panic!("no data array {name}"),
    }
}

#[test]
fn a_vault_limit_result_reads_back_from_vtk_equal_to_the_json() {
    let d = tmpdir("vtk");
    gen_model(&d, "vault --live full --rings 2 -o v.json");
    run(&d, &["limit", "v.json", "--vtk", "v.vtu", "-o", "r.json"]);
    run(&d, &["limit", "v.json", "--vtk", "m.vtm"]);
    let r = json(&d.join("r.json"));
    let blocks = r["blocks"].as_array().unwrap();
    let shapes = r["geometry"]["blocks"].as_array().unwrap();
    assert_eq!(blocks.len(), 128);
    let vtk = Vtk::import(d.join("v.vtu")).expect("vtkio reads the file");
    let DataSet::UnstructuredGrid { pieces, .. } = vtk.data else {
        panic!("not an unstructured grid")
    };
    let piece = pieces[0].clone().into_loaded_piece_data(None).unwrap();
    // One polygon cell per block face, a `block` id per cell: every block is there.
    let ids = array(&piece.data.cell, "block");
    let faces: usize = shapes
        .iter()
        .map(|s| s["faces"].as_array().unwrap().len())
        .sum();
    assert_eq!(ids.len(), faces);
    let mut distinct: Vec<i64> = ids.iter().map(|x| *x as i64).collect();
    distinct.dedup();
    assert_eq!(distinct.len(), 128);
    // Block 40's translation in the VTK equals the JSON's, and the displacement of the block's
    // first vertex is u + θ × (x − c) with the JSON's values.
    let tr = array(&piece.data.cell, "translation");
    let cell = ids.iter().position(|x| *x as usize == 40).unwrap();
    let b = &blocks[40];
    for (k, key) in ["u", "v", "w"].iter().enumerate() {
        let want = b[*key].as_f64().unwrap();
        assert!(
            (tr[3 * cell + k] - want).abs() <= 1e-12 * want.abs().max(1.0),
            "{key}"
        );
    }
    let pts: Vec<f64> = match &piece.points {
        vtkio::model::IOBuffer::F64(v) => v.clone(),
        other => other.clone().cast_into::<f64>().unwrap(),
    };
    let disp = array(&piece.data.point, "displacement");
    let c = r["geometry"]["centroids"][40].as_array().unwrap();
    let c: Vec<f64> = c.iter().map(|x| x.as_f64().unwrap()).collect();
    let theta = [
        b["theta_x"].as_f64().unwrap(),
        b["theta_y"].as_f64().unwrap(),
        b["theta_z"].as_f64().unwrap(),
    ];
    let u = [
        b["u"].as_f64().unwrap(),
        b["v"].as_f64().unwrap(),
        b["w"].as_f64().unwrap(),
    ];
    // The first vertex of block 40 in the VTK: find a point equal to the JSON's vertex 0.
    let v0: Vec<f64> = shapes[40]["vertices"][0]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let p = (0..pts.len() / 3)
        .find(|&p| (0..3).all(|k| (pts[3 * p + k] - v0[k]).abs() < 1e-12))
        .expect("vertex 0 of block 40 in the VTK");
    let r_ = [v0[0] - c[0], v0[1] - c[1], v0[2] - c[2]];
    let want = [
        u[0] + theta[1] * r_[2] - theta[2] * r_[1],
        u[1] + theta[2] * r_[0] - theta[0] * r_[2],
        u[2] + theta[0] * r_[1] - theta[1] * r_[0],
    ];
    for k in 0..3 {
        assert!(
            (disp[3 * p + k] - want[k]).abs() < 1e-9,
            "{k}: {} vs {}",
            disp[3 * p + k],
            want[k]
        );
    }
    // The multiblock's contact part: the opening of one point equals the JSON's.
    let vtk = Vtk::import(d.join("m_contacts.vtu")).expect("vtkio reads the contacts");
    let DataSet::UnstructuredGrid { pieces, .. } = vtk.data else {
        panic!("not an unstructured grid")
    };
    let piece = pieces[0].clone().into_loaded_piece_data(None).unwrap();
    let openings = array(&piece.data.point, "opening");
    let json_openings: Vec<f64> = r["joints"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|j| {
            j["points"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| p["opening"].as_f64().unwrap())
        })
        .collect();
    assert_eq!(openings.len(), json_openings.len());
    let k = json_openings
        .iter()
        .position(|o| *o > 0.0)
        .expect("an opened point");
    assert!((openings[k] - json_openings[k]).abs() < 1e-12);
}

fn number(text: &str, after: &str) -> f64 {
    let i = text
        .find(after)
        .unwrap_or_else(|| panic!("'{after}' not in {text}"))
        + after.len();
    text[i..]
        .split(|c: char| c.is_whitespace() || c == ',' || c == ')')
        .find(|t| !t.is_empty())
        .unwrap()
        .parse()
        .unwrap()
}

#[test]
fn generated_vault_and_dome_round_trip_through_obj() {
    let d = tmpdir("obj");
    gen_model(&d, "vault --live left --rings 2 -o v.json");
    gen_model(
        &d,
        "dome --courses 6 --segments 12 --thickness 0.4 --crown-load 10 -o d.json",
    );
    for (model, mv) in [("v", "right=1cm,0,0"), ("d", "base0=0,0,-1cm")] {
        run(
            &d,
            &[
                "export",
                &format!("{model}.json"),
                "-o",
                &format!("{model}.obj"),
            ],
        );
        // An OBJ carries no loads: compare the tilting-table analysis, whose live load (the
        // blocks' weights, horizontal) both models define alike.
        let a = run(&d, &["tilt", &format!("{model}.json"), "--azimuth", "30"]);
        let b = run(&d, &["tilt", &format!("{model}.obj"), "--azimuth", "30"]);
        // Same blocks, joints (interfaces) and supports: the first summary line.
        assert_eq!(a.lines().next(), b.lines().next(), "{model}");
        let (la, lb) = (number(&a, "λ = "), number(&b, "λ = "));
        assert!(
            (la - lb).abs() <= 1e-6 * la.abs(),
            "{model}: λ {la} vs {lb}"
        );
        let a = run(
            &d,
            &[
                "settle",
                &format!("{model}.json"),
                "--move",
                mv,
                "--friction",
                "0.6",
            ],
        );
        let b = run(
            &d,
            &[
                "settle",
                &format!("{model}.obj"),
                "--move",
                mv,
                "--friction",
                "0.6",
            ],
        );
        let (wa, wb) = (
            number(&a, "work of dead loads "),
            number(&b, "work of dead loads "),
        );
        assert!(
            (wa - wb).abs() <= 1e-6 * wa.abs().max(1e-9),
            "{model}: work {wa} vs {wb}"
        );
    }
}

#[test]
fn a_vault_capacity_after_spreading_equals_the_arch_s() {
    // Stack bond: every ring follows the 2D arch, so the λ–settlement curve and its zero are
    // the 2D ones (finite rotations in 3D through the rotation vector's exponential map).
    let d = tmpdir("capacity");
    gen_model(&d, "arch --live full -o a.json");
    gen_model(&d, "vault --live full --rings 2 -o v.json");
    run(
        &d,
        &[
            "capacity",
            "a.json",
            "--move",
            "right=2cm,0",
            "--steps",
            "10",
            "-o",
            "a.out.json",
        ],
    );
    run(
        &d,
        &[
            "capacity",
            "v.json",
            "--move",
            "right=2cm,0,0",
            "--steps",
            "10",
            "-o",
            "v.out.json",
        ],
    );
    let (a, v) = (json(&d.join("a.out.json")), json(&d.join("v.out.json")));
    let za = a["zero_capacity_settlement"].as_f64().unwrap();
    let zv = v["zero_capacity_settlement"].as_f64().unwrap();
    assert!((za - zv).abs() < 1e-5, "zero capacity 2D {za} vs 3D {zv}");
    for (p, q) in a["curve"]
        .as_array()
        .unwrap()
        .iter()
        .zip(v["curve"].as_array().unwrap())
    {
        let (la, lv) = (
            p["load_multiplier"].as_f64().unwrap(),
            q["load_multiplier"].as_f64().unwrap(),
        );
        assert!((la - lv).abs() < 1e-6, "λ(s) 2D {la} vs 3D {lv}");
        assert_eq!(p["valid"], q["valid"]);
    }
    // Byte-identical output for the same input.
    run(
        &d,
        &[
            "capacity",
            "v.json",
            "--move",
            "right=2cm,0,0",
            "--steps",
            "10",
            "-o",
            "v2.out.json",
        ],
    );
    assert_eq!(
        std::fs::read(d.join("v.out.json")).unwrap(),
        std::fs::read(d.join("v2.out.json")).unwrap()
    );
    let _ = std::fs::remove_dir_all(&d);
}
