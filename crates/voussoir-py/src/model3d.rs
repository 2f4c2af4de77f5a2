//! Models of either dimension for Python: JSON of a 2D or 3D model (3D when its blocks have
//! `vertices`), OBJ and PLY meshes (the CLI's readers, `voussoir_io::mesh`), and the 3D
//! generators of `voussoir gen vault|dome|block|walls` (crates/voussoir-cli/src/gen.rs), with
//! the same specs and messages naming the Python keyword.

use crate::detached;
use crate::options::Fail;
use pyo3::prelude::*;
use std::path::PathBuf;
use voussoir::generate::{ArchSpec, LiveLoad, RadiusAt};
use voussoir::generate3d::{self, Bond, DomeSpec, Plan, WallsLive, WallsSpec};
use voussoir::model3d::AnyModel;
use voussoir::{BuildOptions, Structure, Structure3d};
use voussoir_io::dxf::{ImportLive, Units};
use voussoir_io::files::{to_json, unique_keys};
use voussoir_io::mesh::{read_mesh, MeshOptions};

/// Parse model JSON text of either dimension (unknown fields and duplicate keys refused).
pub fn parse_any(text: &str) -> Result<AnyModel, Fail> {
    unique_keys(text).map_err(|e| {
        Fail::Model(voussoir::error::one_line(&format!("invalid model JSON: {e}")).into())
    })?;
    AnyModel::from_json(text).map_err(|e| Fail::Model(format!("invalid model JSON: {e}")))
}

fn any_json(m: &AnyModel) -> Result<(u8, String), Fail> {
    Ok(match m {
        AnyModel::Planar(p) => (2, to_json(p)?),
        AnyModel::Spatial(s) => (3, to_json(s)?),
    })
}

/// Parse model JSON text of either dimension: (2 or 3, canonical JSON as `voussoir gen` writes).
#[pyfunction]
pub fn model_any_from_text(py: Python<'_>, text: String) -> PyResult<(u8, String)> {
    detached(py, || any_json(&parse_any(&text)?))
}

/// Read a model JSON file of either dimension (errors name the file, as the CLI's do).
#[pyfunction]
pub fn model_any_from_path(py: Python<'_>, path: PathBuf) -> PyResult<(u8, String)> {
    detached(py, || any_json(&voussoir_io::files::read_any_model(&path)?))
}

fn units_of(units: Option<&str>) -> Result<Option<Units>, Fail> {
    match units {
        None => Ok(None),
        Some("mm") => Ok(Some(Units::Mm)),
        Some("cm") => Ok(Some(Units::Cm)),
        Some("m") => Ok(Some(Units::M)),
        Some(u) => Err(Fail::Model(format!("units={u}: expected mm, cm or m"))),
    }
}

/// Read an OBJ or PLY mesh as a 3D model (`voussoir import model.obj`): (model JSON, import
/// summary, notes). The model is validated, errors naming the OBJ object or PLY part.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (path, units, unit_weight, supports, support_prefix, weld, live))]
pub fn model_from_mesh(
    py: Python<'_>,
    path: PathBuf,
    units: Option<String>,
    unit_weight: f64,
    supports: Vec<String>,
    support_prefix: Option<String>,
    weld: Option<f64>,
    live: String,
) -> PyResult<(String, String, Vec<String>)> {
    detached(py, || {
        let live = match live.as_str() {
            "none" => ImportLive::None,
            "horizontal" => ImportLive::Horizontal,
            l => {
                return Err(Fail::Model(format!(
                    "live={l}: expected none or horizontal"
                )))
            }
        };
        if let Some(w) = weld {
            if !(w.is_finite() && w >= 0.0) {
                return Err(Fail::Model(format!(
                    "weld={w}: must be a finite number ≥ 0 (m)"
                )));
            }
        }
        let opts = MeshOptions {
            units: units_of(units.as_deref())?.unwrap_or(Units::M),
            unit_weight,
            supports,
            support_prefix,
            weld,
            live,
        };
        let (m, rep) = read_mesh(&path, &opts)?;
        Structure3d::new(&m, BuildOptions { tolerance: None })
            .map_err(|e| Fail::Model(rep.annotate(&e.to_string())))?;
        Ok((to_json(&m)?, rep.summary(), rep.notes.clone()))
    })
}

/// Validate a model of either dimension: (blocks, joints, supports) of its structure.
#[pyfunction]
#[pyo3(signature = (model, tolerance=None))]
pub fn model_any_check(
    py: Python<'_>,
    model: String,
    tolerance: Option<f64>,
) -> PyResult<(usize, usize, usize)> {
    detached(py, || {
        let b = BuildOptions { tolerance };
        Ok(match parse_any(&model)? {
            AnyModel::Planar(m) => {
                let st = Structure::new(&m, b)?;
                (st.blocks.len(), st.joints.len(), st.supports.len())
            }
            AnyModel::Spatial(m) => {
                let st = Structure3d::new(&m, b)?;
                (st.blocks.len(), st.joints.len(), st.supports.len())
            }
        })
    })
}

/// The OBJ text of a 3D model (`voussoir export`): each block the object `block_i`, each
/// support `support_NAME`, read back by [`model_from_mesh`].
#[pyfunction]
pub fn model_to_obj(py: Python<'_>, model: String) -> PyResult<String> {
    detached(py, || match parse_any(&model)? {
        AnyModel::Spatial(m) => {
            voussoir_io::mesh::check_exportable(&m)?;
            Ok(voussoir_io::mesh::model_to_obj(&m))
        }
        AnyModel::Planar(_) => Err(Fail::Model(
            "to_obj: the model is 2D (OBJ export is for 3D models)".into(),
        )),
    })
}

// ---------------------------------------------------------------------------------------------
// Generators

pub fn live_of(l: &str) -> Result<LiveLoad, Fail> {
    Ok(match l {
        "none" => LiveLoad::None,
        "full" => LiveLoad::Full,
        "left" => LiveLoad::Left,
        "right" => LiveLoad::Right,
        "horizontal" => LiveLoad::Horizontal,
        _ => {
            return Err(Fail::Model(format!(
                "live={l}: expected none, full, left, right or horizontal"
            )))
        }
    })
}

fn radius_at_of(r: &str) -> Result<RadiusAt, Fail> {
    Ok(match r {
        "intrados" => RadiusAt::Intrados,
        "centreline" | "centerline" => RadiusAt::Centreline,
        "extrados" => RadiusAt::Extrados,
        s => {
            return Err(Fail::Model(format!(
                "radius_at={s}: expected intrados, centreline or extrados"
            )))
        }
    })
}

/// The arch of `gen arch` (and of `gen vault`), as the CLI's `ArchArgs::spec`.
#[allow(clippy::too_many_arguments)]
pub fn arch_spec(
    shape: &str,
    radius: f64,
    radius_at: &str,
    thickness: f64,
    voussoirs: usize,
    unit_weight: f64,
    width: f64,
    live: &str,
    live_load: Option<f64>,
    half_angle: Option<f64>,
    offset: Option<f64>,
) -> Result<ArchSpec, Fail> {
    // Checked by the library's generator request, in Python's words (the CLI's `gen arch`
    // asks the same request).
    let n = voussoir::request::Names::Keywords;
    Ok(voussoir::request::ArchRequest {
        shape: voussoir::request::ShapeName::parse(shape, n)?,
        radius,
        radius_at: radius_at_of(radius_at)?,
        thickness,
        voussoirs,
        unit_weight,
        width,
        live: live_of(live)?,
        live_load,
        half_angle,
        offset,
    }
    .spec(n)?)
}

/// `voussoir gen vault`: the arch extruded along +y over `depth` in `rings` rings.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (shape, radius, radius_at, thickness, voussoirs, unit_weight, live, live_load, half_angle, offset, depth, rings, bond))]
pub fn gen_vault(
    shape: &str,
    radius: f64,
    radius_at: &str,
    thickness: f64,
    voussoirs: usize,
    unit_weight: f64,
    live: &str,
    live_load: Option<f64>,
    half_angle: Option<f64>,
    offset: Option<f64>,
    depth: f64,
    rings: usize,
    bond: &str,
) -> PyResult<String> {
    let spec = arch_spec(
        shape,
        radius,
        radius_at,
        thickness,
        voussoirs,
        unit_weight,
        1.0,
        live,
        live_load,
        half_angle,
        offset,
    )?;
    let bond = match bond {
        "stack" | "stacked" => Bond::Stack,
        "running" | "running-bond" | "staggered" => Bond::Running,
        b => return Err(Fail::Model(format!("bond={b}: expected stack or running")).into()),
    };
    let m = generate3d::vault(&spec, depth, rings, bond).map_err(Fail::from)?;
    Ok(to_json(&m).map_err(Fail::from)?)
}

/// The dome spec of `gen dome` (angles in degrees), shared with `least_thickness`.
#[allow(clippy::too_many_arguments)]
pub fn dome_spec(
    radius: f64,
    radius_at: &str,
    thickness: f64,
    courses: usize,
    segments: usize,
    half_angle: f64,
    oculus: Option<f64>,
    unit_weight: f64,
    crown_load: f64,
) -> Result<DomeSpec, Fail> {
    Ok(DomeSpec {
        radius,
        radius_at: radius_at_of(radius_at)?,
        thickness,
        courses,
        segments,
        half_angle: half_angle.to_radians(),
        oculus: oculus.map(f64::to_radians),
        unit_weight,
        crown_load,
    })
}

/// `voussoir gen dome`.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (radius, radius_at, thickness, courses, segments, half_angle, oculus, unit_weight, crown_load))]
pub fn gen_dome(
    radius: f64,
    radius_at: &str,
    thickness: f64,
    courses: usize,
    segments: usize,
    half_angle: f64,
    oculus: Option<f64>,
    unit_weight: f64,
    crown_load: f64,
) -> PyResult<String> {
    let s = dome_spec(
        radius,
        radius_at,
        thickness,
        courses,
        segments,
        half_angle,
        oculus,
        unit_weight,
        crown_load,
    )?;
    let m = generate3d::dome(&s).map_err(Fail::from)?;
    Ok(to_json(&m).map_err(Fail::from)?)
}

/// `voussoir gen block`: a box b×d×h on support `base`, live load its weight along `azimuth`
/// (degrees from +x towards +y).
#[pyfunction]
pub fn gen_block(size: (f64, f64, f64), azimuth: f64, unit_weight: f64) -> PyResult<String> {
    let m =
        generate3d::block([size.0, size.1, size.2], azimuth, unit_weight).map_err(Fail::from)?;
    Ok(to_json(&m).map_err(Fail::from)?)
}

/// `voussoir gen walls`.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn gen_walls(
    plan: &str,
    length: f64,
    return_length: f64,
    height: f64,
    thickness: f64,
    courses: usize,
    units: usize,
    unit_weight: f64,
    live: &str,
) -> PyResult<String> {
    let plan = match plan {
        "I" | "i" | "straight" => Plan::I,
        "L" | "l" => Plan::L,
        "U" | "u" => Plan::U,
        p => return Err(Fail::Model(format!("plan={p}: expected I, L or U")).into()),
    };
    let live = match live {
        "none" => WallsLive::None,
        "main" => WallsLive::Main,
        "all" => WallsLive::All,
        l => return Err(Fail::Model(format!("live={l}: expected none, main or all")).into()),
    };
    let m = generate3d::walls(&WallsSpec {
        plan,
        length,
        return_length,
        height,
        thickness,
        courses,
        units,
        unit_weight,
        live,
    })
    .map_err(Fail::from)?;
    Ok(to_json(&m).map_err(Fail::from)?)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(model_any_from_text, m)?)?;
    m.add_function(wrap_pyfunction!(model_any_from_path, m)?)?;
    m.add_function(wrap_pyfunction!(model_from_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(model_any_check, m)?)?;
    m.add_function(wrap_pyfunction!(model_to_obj, m)?)?;
    m.add_function(wrap_pyfunction!(gen_vault, m)?)?;
    m.add_function(wrap_pyfunction!(gen_dome, m)?)?;
    m.add_function(wrap_pyfunction!(gen_block, m)?)?;
    m.add_function(wrap_pyfunction!(gen_walls, m)?)?;
    Ok(())
}
