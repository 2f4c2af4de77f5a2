//! `voussoir import model.obj|.ply`, `voussoir export model.json -o model.obj`, and meshes read
//! directly by the analysis commands; OBJ/PLY flags refused where they do not apply; failures in
//! one line with nothing written. Fixtures: crates/voussoir-io/tests/fixtures/mesh
//! (make_fixtures.py there).

use crate::common;
use crate::common::{cwd::fails, cwd::ok_text as ok};
use std::path::{Path, PathBuf};

fn fixture(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../voussoir-io/tests/fixtures/mesh")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("import3d", name)
}

/// λ from `limit --json`.
fn lambda(model: &str) -> f64 {
    let out = ok(&["limit", model, "--json"]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    v["load_multiplier"].as_f64().unwrap()
}

/// Import, export, re-import; λ of the triangulated tower = b/(n·h) = 0.5/(3·1) = 1/6 (hand
/// calculation in crates/voussoir-io/tests/mesh.rs) whichever way the model is read.
#[test]
fn import_export_and_direct_analysis_agree() {
    let d = tmpdir("round");
    let json = d.join("tower.json");
    let obj = d.join("tower.obj");
    let json2 = d.join("tower2.json");
    let (js, ob, js2) = (
        json.to_str().unwrap(),
        obj.to_str().unwrap(),
        json2.to_str().unwrap(),
    );
    ok(&["import", &fixture("tower.obj"), "-o", js]);
    ok(&["export", js, "-o", ob]);
    ok(&["import", ob, "-o", js2]);
    let a: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let b: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json2).unwrap()).unwrap();
    assert_eq!(a["blocks"], b["blocks"]);
    assert_eq!(a["supports"], b["supports"]);
    for m in [js, js2, ob, &fixture("tower.obj")] {
        let l = lambda(m);
        assert!((l - 1.0 / 6.0).abs() < 1e-7, "{m}: λ = {l}");
    }
    // PLY read directly, in centimetres: λ = b/h = 1/3 is scale-free.
    let l = {
        let out = ok(&["limit", &fixture("two.ply"), "--units", "cm", "--json"]);
        serde_json::from_str::<serde_json::Value>(&out).unwrap()["load_multiplier"]
            .as_f64()
            .unwrap()
    };
    assert!((l - 1.0 / 3.0).abs() < 1e-7, "λ = {l}");
}

#[test]
fn flags_and_failures_are_one_line_and_write_nothing() {
    let d = tmpdir("fail");
    let out = d.join("x.json");
    let o = out.to_str().unwrap();
    fails(
        &["import", &fixture("open.obj"), "-o", o],
        &["OBJ object 'cracked_box'", "open"],
    );
    fails(
        &["import", &fixture("nonmanifold.obj"), "-o", o],
        &["OBJ object 'bowtie'"],
    );
    fails(
        &["import", &fixture("selfintersecting.obj"), "-o", o],
        &["OBJ object 'folded'"],
    );
    assert!(!out.exists(), "a failed import wrote its output");
    // OBJ/PLY flags with a JSON model or a DXF flag with a mesh.
    let d2 = tmpdir("flags");
    let js = d2.join("t.json");
    ok(&["import", &fixture("tower.obj"), "-o", js.to_str().unwrap()]);
    fails(
        &["limit", js.to_str().unwrap(), "--weld", "1e-6"],
        &["--weld"],
    );
    fails(
        &["limit", &fixture("tower.obj"), "--dxf-width", "2"],
        &["--dxf-width", "DXF"],
    );
    fails(
        &["limit", &fixture("tower.obj"), "--supports", "nope"],
        &["'nope'"],
    );
    fails(
        &[
            "export",
            js.to_str().unwrap(),
            "-o",
            d2.join("t.ply").to_str().unwrap(),
        ],
        &[".obj"],
    );
}
