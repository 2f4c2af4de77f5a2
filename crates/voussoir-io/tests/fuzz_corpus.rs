//! The fuzz corpus replayed on stable: every file of `fuzz/corpus/<target>/` and of
//! `fuzz/regressions/<target>/` (the crashes the fuzzer found, kept after their fix) goes
//! through the code path of its fuzz target (`fuzz/src/lib.rs`, included here as it is), which
//! panics on a panic inside voussoir or on an error that is not one line. An `Err` is fine.
//! The corpus must be there: a missing or empty corpus folder fails the test.
//! See docs/fuzzing.md.

#[path = "../../../fuzz/src/lib.rs"]
#[allow(dead_code)]
mod targets;

use std::path::{Path, PathBuf};

fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz")
}

fn files(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.is_file())
        .collect();
    v.sort();
    v
}

/// Run `target` on every file of `dir`; the files that panicked, with the panic's message.
fn replay(target: fn(&[u8]), dir: &Path) -> Vec<String> {
    let mut failed = Vec::new();
    for f in files(dir) {
        let data = std::fs::read(&f).expect("readable corpus file");
        if let Err(e) = std::panic::catch_unwind(|| target(&data)) {
            let msg = e
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            failed.push(format!("{}: {msg}", f.display()));
        }
    }
    failed
}

fn target(name: &str) -> fn(&[u8]) {
    targets::TARGETS
        .iter()
        .find(|(n, _)| *n == name)
        .unwrap_or_else(|| panic!("no fuzz target {name}"))
        .1
}

/// Replay the corpus (required, non-empty) and the regressions (if any) of one target.
fn corpus(name: &str) {
    let dir = fuzz_dir().join("corpus").join(name);
    assert!(
        dir.is_dir(),
        "the fuzz corpus {} is missing (see docs/fuzzing.md)",
        dir.display()
    );
    let n = files(&dir).len();
    assert!(n > 0, "the fuzz corpus {} is empty", dir.display());
    let mut failed = replay(target(name), &dir);
    let crashes = fuzz_dir().join("regressions").join(name);
    if crashes.is_dir() {
        failed.extend(replay(target(name), &crashes));
    }
    assert!(
        failed.is_empty(),
        "{} of the {n} corpus files of '{name}' (and its regressions) panic:\n{}",
        failed.len(),
        failed.join("\n")
    );
}

#[test]
fn fuzz_corpus_model_replays_without_panic() {
    corpus("model");
}

#[test]
fn fuzz_corpus_dxf_replays_without_panic() {
    corpus("dxf");
}

#[test]
fn fuzz_corpus_mesh_replays_without_panic() {
    corpus("mesh");
}

#[test]
fn fuzz_corpus_motion_replays_without_panic() {
    corpus("motion");
}

#[test]
fn every_fuzz_target_has_a_corpus() {
    for (name, _) in targets::TARGETS {
        assert!(
            fuzz_dir().join("corpus").join(name).is_dir(),
            "fuzz target {name} has no corpus folder"
        );
    }
}

// ── One test per finding (docs/fuzzing.md, "Findings") ─────────────────────────────────────

fn regression(target: &str, file: &str) -> Vec<u8> {
    let p = fuzz_dir().join("regressions").join(target).join(file);
    std::fs::read(&p).unwrap_or_else(|e| panic!("cannot read {}: {e}", p.display()))
}

#[test]
fn dxf_bulge_of_a_near_full_circle_does_not_exhaust_memory() {
    // A bulge of 776979 (359.9997° of arc) makes one voussoir of the LACT3 arch a polygon of
    // radius ~10⁷ m; the overlap check's grid then needed ~10¹⁸ cells (out of memory).
    let d = regression("dxf", "oom-bulge-near-full-circle-giant-block.dxf");
    targets::dxf(&d);
    let opts = voussoir_io::dxf::DxfOptions {
        units: Some(voussoir_io::dxf::Units::Mm),
        ..Default::default()
    };
    let (m, _) = voussoir_io::dxf::parse_dxf(&d, &opts, "t.dxf").expect("the drawing reads");
    let e = voussoir::Structure::new(&m, voussoir::BuildOptions::default())
        .expect_err("the giant arc overlaps its neighbours")
        .to_string();
    assert!(e.contains("overlap") && !e.contains('\n'), "{e}");
}

#[test]
fn dxf_error_quoting_a_code_pair_with_a_line_break_is_one_line() {
    // A binary DXF whose section name holds a line feed: the dxf crate's message quotes it.
    let d = regression("dxf", "crash-binary-dxf-error-quotes-a-line-break.dxf");
    targets::dxf(&d);
    let e = voussoir_io::dxf::parse_dxf(&d, &Default::default(), "t.dxf")
        .unwrap_err()
        .0;
    assert!(
        e.starts_with("cannot read t.dxf as DXF: ")
            && e.contains("0SECTION\\n4B")
            && !e.contains('\n'),
        "{e}"
    );
}

#[test]
fn json_unknown_field_with_a_line_break_is_named_on_one_line() {
    // Found while fixing the one above: serde quotes an unknown field as written.
    let text = r#"{"blocks": [], "supports": [], "a\nb": 1}"#;
    targets::model(text.as_bytes());
    let e = voussoir::model3d::AnyModel::from_json(text).unwrap_err();
    assert!(
        e.starts_with("unknown field `a\\nb`") && !e.contains('\n'),
        "{e}"
    );
}

#[test]
fn obj_relative_texture_index_out_of_range_is_ignored_not_an_overflow() {
    // `f 2/1/1 3/-11 7/1/1` with one `vt`: tobj 4.0.5 turns the relative index into a huge
    // one and multiplies it unchecked (a panic with overflow checks, as in the fuzz build; in
    // release "face texcoord index out of bounds", about data voussoir does not use). Texture
    // coordinates are dropped before tobj: the file is judged on its geometry.
    let d = regression(
        "mesh",
        "crash-obj-relative-texture-index-overflows-in-tobj.obj",
    );
    targets::mesh(&d);
    let e = voussoir_io::mesh::parse_obj(&d, &Default::default(), "t.obj")
        .unwrap_err()
        .0;
    assert!(
        e.starts_with("OBJ object 'support_slab': not a manifold surface") && !e.contains('\n'),
        "{e}"
    );
}
