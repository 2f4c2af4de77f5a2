//! Every integration test of this crate, compiled as ONE test binary (`it`).
//!
//! Each file of this directory stays a file of its own (a regression test per defect, named after
//! its issue) and is a module here. One binary instead of one per file: the test binaries were
//! linked ~100 times against HiGHS, Clarabel and the library, 9 of the CI's 30 minutes; and the
//! tests of all files share the cores instead of waiting file by file. `autotests = false` in
//! Cargo.toml, so a new file must be listed below: `every_test_file_is_a_module` fails otherwise.
//! One file: `cargo test --release -p CRATE --test it -- FILE::`.

#[path = "draw.rs"]
mod draw;
#[path = "draw3d.rs"]
mod draw3d;
#[path = "dxf.rs"]
mod dxf;
#[path = "files.rs"]
mod files;
#[path = "fuzz_corpus.rs"]
mod fuzz_corpus;
#[path = "mesh.rs"]
mod mesh;
#[path = "report3d.rs"]
mod report3d;
#[path = "vtk.rs"]
mod vtk;

/// A test file not listed above would never be compiled nor run: refuse that.
#[test]
fn every_test_file_is_a_module() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let me = std::fs::read_to_string(dir.join("it.rs")).expect("tests/it.rs");
    let mut missing = Vec::new();
    for e in std::fs::read_dir(&dir).expect("the tests directory") {
        let name = e.unwrap().file_name().into_string().unwrap();
        if name.ends_with(".rs")
            && name != "it.rs"
            && !me.contains(&format!("#[path = \"{name}\"]"))
        {
            missing.push(name);
        }
    }
    assert!(
        missing.is_empty(),
        "test files not in tests/it.rs (never compiled): {missing:?}"
    );
}
