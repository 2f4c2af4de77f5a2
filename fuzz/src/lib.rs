//! The code paths of the fuzz targets, one function per target. Each takes the fuzzer's bytes,
//! runs them through what the command line does with a file or a flag of that kind, and
//! panics only on a bug: a panic inside voussoir, or an error message that is not one line.
//!
//! This file is compiled twice: as the library of the fuzz crate (nightly, cargo-fuzz) and, with
//! `#[path]`, into the stable test `crates/voussoir-io/tests/fuzz_corpus.rs`, which replays the
//! corpus `fuzz/corpus/<target>/` and every crash `fuzz/regressions/<target>/` through the same
//! functions. So it names only the crates `voussoir` and `voussoir_io`, never `crate::`.

use voussoir::discretize::KinematicMap;
use voussoir::model3d::AnyModel;
use voussoir::{Assembly, BuildOptions, Structure, Structure3d};
use voussoir_io::dxf::{parse_dxf, DxfOptions, Units};
use voussoir_io::mesh::{parse_obj, parse_ply, MeshOptions};
use voussoir_io::motion::{parse_move, parse_profile, signed_length, Motion};

/// The targets, by name (the folders of the corpus).
pub const TARGETS: [(&str, fn(&[u8])); 4] = [
    ("model", model),
    ("dxf", dxf),
    ("mesh", mesh),
    ("motion", motion),
];

/// An error for the user must be one line (and say something).
fn one_line(what: &str, e: &str) {
    assert!(
        !e.trim().is_empty() && !e.contains('\n'),
        "{what}: error is not one line: {e:?}"
    );
}

/// What every command does once it has a model: validate it and find its joints (the
/// structure), warn, and build the kinematic map and the load vectors the programs start from.
fn analyse_structure<S: Assembly>(st: &S) {
    let map = KinematicMap::new(st);
    let _ = map.num_points();
    let _ = st.load_vector(false);
    let _ = st.load_vector(true);
}

fn build_2d(m: &voussoir::Model) {
    let _ = m.warnings();
    match Structure::new(m, BuildOptions::default()) {
        Ok(st) => analyse_structure(&st),
        Err(e) => one_line("structure", &e.to_string()),
    }
}

fn build_3d(m: &voussoir::model3d::Model3d) {
    let _ = m.warnings();
    match Structure3d::new(m, BuildOptions::default()) {
        Ok(st) => analyse_structure(&st),
        Err(e) => one_line("structure3d", &e.to_string()),
    }
}

/// `model`: bytes as a JSON model of either dimension (`voussoir_io::read_any_model`), then
/// validation, joint detection and the kinematic map (`Input::structure_of`/`structure3d`).
pub fn model(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match AnyModel::from_json(text) {
        Err(e) => one_line("model JSON", &e),
        Ok(AnyModel::Planar(m)) => build_2d(&m),
        Ok(AnyModel::Spatial(m)) => build_3d(&m),
    }
}

/// `dxf`: bytes as a DXF drawing (ASCII or binary), imported with the default options and with
/// `--units mm --dxf-live none`, then validated as `voussoir import` does.
pub fn dxf(data: &[u8]) {
    let with_units = DxfOptions {
        units: Some(Units::Mm),
        live: voussoir_io::dxf::ImportLive::None,
        ..DxfOptions::default()
    };
    for opts in [DxfOptions::default(), with_units] {
        match parse_dxf(data, &opts, "fuzz.dxf") {
            Ok((m, rep)) => {
                let _ = rep.summary();
                build_2d(&m);
            }
            Err(e) => one_line("DXF", &e.0),
        }
    }
}

/// `mesh`: bytes as a PLY file if they start with `ply`, else as OBJ text (`read_mesh` picks by
/// extension), then validated as `voussoir import model.obj` does.
pub fn mesh(data: &[u8]) {
    let opts = MeshOptions::default();
    let r = if data.starts_with(b"ply") {
        parse_ply(data, &opts, "fuzz.ply")
    } else {
        parse_obj(data, &opts, "fuzz.obj")
    };
    match r {
        Ok((m, rep)) => {
            let _ = rep.summary();
            build_3d(&m);
        }
        Err(e) => one_line("mesh", &e.0),
    }
}

/// `motion`: text lines as flags. The first line is a `--profile` (unless empty), each further
/// line a `--move` or, starting with `!`, a `--fixed` name. Parsed as `settle` does, then
/// applied to a 2D lintel (supports `left`, `right`) and a 3D block (support `base`). Each
/// line also goes through the single parsers.
pub fn motion(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut lines = text.split('\n');
    let profile = lines.next().filter(|l| !l.is_empty());
    let (mut moves, mut fixed) = (Vec::new(), Vec::new());
    for l in lines {
        match l.strip_prefix('!') {
            Some(name) => fixed.push(name.to_string()),
            None => moves.push(l.to_string()),
        }
        let _ = signed_length(l);
        if let Err(e) = parse_move(l) {
            one_line("--move", &e.0);
        }
    }
    if let Some(p) = profile {
        if let Err(e) = parse_profile(p) {
            one_line("--profile", &e.0);
        }
    }
    let m = match Motion::parse(&moves, &fixed, profile) {
        Ok(m) => m,
        Err(e) => return one_line("motion", &e.0),
    };
    let mut planar = voussoir::generate::lintel(&voussoir::generate::LintelSpec {
        bricks: 3,
        ..Default::default()
    })
    .expect("the lintel generator's defaults are valid");
    if let Err(e) = m.apply(&mut planar) {
        one_line("motion 2D", &e.0);
    }
    let mut spatial = voussoir::generate3d::block([0.4, 0.4, 1.0], 0.0, 18.0)
        .expect("the block generator's defaults are valid");
    if let Err(e) = m.apply(&mut spatial) {
        one_line("motion 3D", &e.0);
    }
}
