//! Every integration test of this crate, compiled as ONE test binary (`it`).
//!
//! Each file of this directory stays a file of its own (a regression test per defect, named after
//! its issue) and is a module here. One binary instead of one per file: the test binaries were
//! linked ~100 times against HiGHS, Clarabel and the library, 9 of the CI's 30 minutes; and the
//! tests of all files share the cores instead of waiting file by file. `autotests = false` in
//! Cargo.toml, so a new file must be listed below: `every_test_file_is_a_module`
//! (crates/voussoir/tests/it.rs, for every crate) fails otherwise.
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
