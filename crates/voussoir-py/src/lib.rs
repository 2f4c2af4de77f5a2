//! `voussoir._native`: the Python extension module. Thin: every function takes the model as the
//! JSON text of a [`voussoir::Model`] and plain option values, calls the same library functions
//! as the CLI (`crates/voussoir-cli`), and returns the result as the JSON text the CLI writes
//! with `--json` (same serialiser, [`voussoir_io::files::to_json`]), so that the Python result's
//! `to_json()` is byte-identical to the CLI's. The Python package (`python/voussoir`) turns that
//! JSON into typed objects with numpy arrays.
//!
//! The GIL is released for everything that solves (`Python::detach`), and panics are caught and
//! turned into `voussoir.VoussoirError`, so a failure never takes the interpreter down.

mod identify;
mod options;
mod sweep;

use options::{Common, Fail, Settle};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use std::path::PathBuf;
use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions};
use voussoir::analysis::capacity::{capacity as capacity_analysis, CapacityOptions};
use voussoir::analysis::incremental::{incremental_with, settled, Control, IncrementalOptions};
use voussoir::analysis::settlement::{settle_with, SettlementForm};
use voussoir::generate::{
    self, ArchShape, ArchSpec, FirstCourse, LintelSpec, LiveLoad, RadiusAt, WallSpec,
};
use voussoir::generate_facade::{self, bondeno, FacadeMesh, Opening};
use voussoir::{BuildOptions, Structure};
use voussoir_io::draw::{self, DrawOptions, ReportOptions};
use voussoir_io::dxf::{read_dxf, DxfOptions, ImportLive, Units};
use voussoir_io::files::{parse_model, to_json};

create_exception!(
    voussoir,
    VoussoirError,
    PyException,
    "Base class of every error voussoir raises (one line naming the block, joint or field)."
);
create_exception!(
    voussoir,
    ModelError,
    VoussoirError,
    "The model or the request is invalid (bad polygon, overlap, unknown support, bad option)."
);
create_exception!(
    voussoir,
    SolverError,
    VoussoirError,
    "The LP/SOCP solver failed for a reason other than infeasibility or unboundedness."
);

impl From<Fail> for PyErr {
    fn from(f: Fail) -> PyErr {
        match f {
            Fail::Model(m) => ModelError::new_err(m),
            Fail::Solver(m) => SolverError::new_err(m),
        }
    }
}

/// Run `f` without the GIL; a panic becomes a `VoussoirError` instead of an abort.
fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, Fail> + Send) -> PyResult<T> {
    let out = py.detach(|| std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)));
    match out {
        Ok(r) => r.map_err(PyErr::from),
        Err(p) => {
            let msg = p
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "unknown panic".into());
            Err(VoussoirError::new_err(format!(
                "internal error (please report): {}",
                msg.lines().next().unwrap_or("")
            )))
        }
    }
}

fn json<T: serde::Serialize>(v: &T) -> Result<String, Fail> {
    Ok(to_json(v)?)
}

/// [`json`] of a result whose model had supports cut (a profile's breakpoints): with
/// `split_supports`, as the CLI writes it; without any, exactly [`json`].
fn json_split<T: serde::Serialize>(
    v: &T,
    splits: &[voussoir::settlement_input::SupportSplit],
) -> Result<String, Fail> {
    if splits.is_empty() {
        return json(v);
    }
    json(&voussoir_io::motion::WithSplits {
        result: v,
        split_supports: splits,
    })
}

// ---------------------------------------------------------------------------------------------
// Models

/// Parse model JSON text; returns the canonical JSON (as `voussoir gen` writes it).
#[pyfunction]
fn model_from_text(py: Python<'_>, text: String) -> PyResult<String> {
    detached(py, || json(&parse_model(&text)?))
}

/// Read a model JSON file (errors name the file, as the CLI's do).
#[pyfunction]
fn model_from_path(py: Python<'_>, path: PathBuf) -> PyResult<String> {
    detached(py, || json(&voussoir_io::read_model(&path)?))
}

/// Read a DXF drawing; returns (model JSON, import summary, notes).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (path, units, unit_weight, dxf_width, support_layers, support_handles, merge_tolerance, dxf_live))]
fn model_from_dxf(
    py: Python<'_>,
    path: PathBuf,
    units: Option<String>,
    unit_weight: f64,
    dxf_width: f64,
    support_layers: Vec<String>,
    support_handles: Vec<String>,
    merge_tolerance: Option<f64>,
    dxf_live: String,
) -> PyResult<(String, String, Vec<String>)> {
    detached(py, || {
        let units = match units.as_deref() {
            None => None,
            Some("mm") => Some(Units::Mm),
            Some("cm") => Some(Units::Cm),
            Some("m") => Some(Units::M),
            Some(u) => return Err(Fail::Model(format!("units={u}: expected mm, cm or m"))),
        };
        let live = match dxf_live.as_str() {
            "none" => ImportLive::None,
            "horizontal" => ImportLive::Horizontal,
            l => {
                return Err(Fail::Model(format!(
                    "dxf_live={l}: expected none or horizontal"
                )))
            }
        };
        let opts = DxfOptions {
            units,
            unit_weight,
            width: dxf_width,
            support_layers,
            support_handles,
            merge_tolerance,
            live,
            crack_layers: Vec::new(),
        };
        let (m, rep) = read_dxf(&path, &opts)?;
        // Validate now, naming the DXF entity of a bad block (as `voussoir import` does).
        Structure::new(&m, BuildOptions { tolerance: None })
            .map_err(|e| Fail::Model(rep.annotate(&e.to_string())))?;
        Ok((json(&m)?, rep.summary(), rep.notes.clone()))
    })
}

/// Validate a model: (blocks, joints, supports) of its structure.
#[pyfunction]
#[pyo3(signature = (model, tolerance=None))]
fn model_check(
    py: Python<'_>,
    model: String,
    tolerance: Option<f64>,
) -> PyResult<(usize, usize, usize)> {
    detached(py, || {
        let m = parse_model(&model)?;
        let st = Structure::new(&m, BuildOptions { tolerance })?;
        Ok((st.blocks.len(), st.joints.len(), st.supports.len()))
    })
}

// ---------------------------------------------------------------------------------------------
// Generators (the same specs `voussoir gen` builds; see crates/voussoir-cli/src/gen.rs)

fn live_of(l: &str) -> Result<LiveLoad, Fail> {
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

#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn gen_arch(
    shape: &str,
    radius: f64,
    radius_at: &str,
    thickness: f64,
    voussoirs: usize,
    unit_weight: f64,
    width: f64,
    live: &str,
    live_load: f64,
    half_angle: f64,
    offset: f64,
) -> PyResult<String> {
    let shape = match shape {
        "semicircular" => ArchShape::Semicircular,
        "segmental" => ArchShape::Segmental {
            half_angle: half_angle.to_radians(),
        },
        "pointed" => ArchShape::Pointed { offset },
        s => {
            return Err(Fail::Model(format!(
                "shape={s}: expected semicircular, segmental or pointed"
            ))
            .into())
        }
    };
    let radius_at = match radius_at {
        "intrados" => RadiusAt::Intrados,
        "centreline" | "centerline" => RadiusAt::Centreline,
        "extrados" => RadiusAt::Extrados,
        s => {
            return Err(Fail::Model(format!(
                "radius_at={s}: expected intrados, centreline or extrados"
            ))
            .into())
        }
    };
    let m = generate::arch(&ArchSpec {
        shape,
        radius,
        radius_at,
        thickness,
        voussoirs,
        unit_weight,
        width,
        live: live_of(live)?,
        live_load,
    })
    .map_err(Fail::from)?;
    Ok(json(&m)?)
}

#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (span, thickness, bricks, unit_weight, width, live_load, compressive_strength))]
fn gen_lintel(
    span: f64,
    thickness: f64,
    bricks: usize,
    unit_weight: f64,
    width: f64,
    live_load: f64,
    compressive_strength: Option<f64>,
) -> PyResult<String> {
    let m = generate::lintel(&LintelSpec {
        span,
        thickness,
        bricks,
        unit_weight,
        width,
        live_load,
        compressive_strength,
    })
    .map_err(Fail::from)?;
    Ok(json(&m)?)
}

#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn gen_wall(
    courses: usize,
    units: usize,
    unit: (f64, f64),
    first_course: &str,
    unit_weight: f64,
    width: f64,
    live: &str,
) -> PyResult<String> {
    let first_course = match first_course {
        "full" => FirstCourse::Full,
        "half" => FirstCourse::Half,
        s => return Err(Fail::Model(format!("first_course={s}: expected full or half")).into()),
    };
    let m = generate::wall(&WallSpec {
        courses,
        units,
        unit: [unit.0, unit.1],
        first_course,
        unit_weight,
        width,
        live: live_of(live)?,
    })
    .map_err(Fail::from)?;
    Ok(json(&m)?)
}

/// Parse `--opening` specs exactly as `voussoir gen facade` does (same defaults for OFFSET/RING).
fn opening_of(o: &str) -> Result<Opening, Fail> {
    let bad = || {
        Fail::Model(format!(
            "opening {o}: expected door:X,WIDTH,SPRINGING[,OFFSET,RING], rose:X,Y,RADIUS[,RING] or rect:X0,Y0,X1,Y1"
        ))
    };
    let (kind, rest) = o.split_once(':').ok_or_else(bad)?;
    let v: Vec<f64> = rest
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| bad())?;
    Ok(match (kind, &v[..]) {
        ("door", [x, w, sp]) => Opening::PointedDoor {
            x: *x,
            width: *w,
            springing: *sp,
            offset: 0.5,
            ring: 0.4,
        },
        ("door", [x, w, sp, off, ring]) => Opening::PointedDoor {
            x: *x,
            width: *w,
            springing: *sp,
            offset: *off,
            ring: *ring,
        },
        ("rose", [x, y, r]) => Opening::Round {
            x: *x,
            y: *y,
            radius: *r,
            ring: 0.35,
        },
        ("rose", [x, y, r, ring]) => Opening::Round {
            x: *x,
            y: *y,
            radius: *r,
            ring: *ring,
        },
        ("rect", [x0, y0, x1, y1]) => Opening::Rect {
            x0: *x0,
            y0: *y0,
            x1: *x1,
            y1: *y1,
        },
        _ => return Err(bad()),
    })
}

#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (element, mesh, width, height, gable, openings, segments, unit_weight, thickness, live))]
fn gen_facade(
    py: Python<'_>,
    element: (f64, Option<f64>),
    mesh: &str,
    width: f64,
    height: f64,
    gable: f64,
    openings: Option<Vec<String>>,
    segments: usize,
    unit_weight: f64,
    thickness: f64,
    live: &str,
) -> PyResult<String> {
    let mesh = match mesh {
        "grid" => FacadeMesh::Grid,
        "running-bond" => FacadeMesh::RunningBond,
        "triangles" => FacadeMesh::Triangles,
        s => {
            return Err(Fail::Model(format!(
                "mesh={s}: expected grid, running-bond or triangles"
            ))
            .into())
        }
    };
    let live = live_of(live)?;
    detached(py, || {
        let element = [element.0, element.1.unwrap_or(element.0 / 2.0)];
        let mut s = bondeno(element[0], mesh);
        s.element = element;
        s.width = width;
        s.height = height;
        s.gable = gable;
        s.segments = segments;
        s.unit_weight = unit_weight;
        s.thickness = thickness;
        s.live = live;
        if let Some(o) = openings {
            s.openings = o.iter().map(|o| opening_of(o)).collect::<Result<_, _>>()?;
        }
        json(&generate_facade::facade(&s)?)
    })
}

// ---------------------------------------------------------------------------------------------
// Analyses (each as the CLI command of the same name does it)

#[pyfunction]
fn limit(py: Python<'_>, model: String, common: Common) -> PyResult<String> {
    detached(py, || {
        let (st, opts) = common.structure(&model, None)?;
        json(&common.limit(&st, &opts)?)
    })
}

#[pyfunction]
fn settle(
    py: Python<'_>,
    model: String,
    common: Common,
    settle: Settle,
    raw: bool,
    ranges: Option<bool>,
) -> PyResult<String> {
    detached(py, || {
        let (m, splits) = common.model_split(&model, Some(&settle))?;
        // Validated first, so that a bad model is named before a missing motion (as the CLI).
        let st = Structure::new(
            &m,
            BuildOptions {
                tolerance: common.tolerance,
            },
        )?;
        let opts = common.solver()?;
        if m.supports
            .iter()
            .all(|s| s.motion.iter().all(|x| *x == 0.0))
        {
            return Err(Fail::Model(
                "settle needs a support motion: give move={NAME: (u, v)} or profile=... (the model's supports do not move)".into(),
            ));
        }
        // As the CLI: the canonical selection unless `raw` (docs/canonical.md); `ranges`
        // None = the reaction ranges on models of at most 500 blocks, True/False = always/never.
        let form = common.settlement_form()?;
        let r = if raw {
            match form {
                SettlementForm::Both => voussoir::analysis::settle(&st, &opts)?,
                form => settle_with(&st, &opts, form)?,
            }
        } else {
            let d = CanonicalOptions::default();
            let copts = CanonicalOptions {
                reaction_ranges: ranges != Some(false),
                ranges_max_blocks: if ranges == Some(true) {
                    usize::MAX
                } else {
                    d.ranges_max_blocks
                },
                ..d
            };
            settle_canonical(&st, &opts, form, &copts)?
        };
        json_split(&r, &splits)
    })
}

#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn capacity(
    py: Python<'_>,
    model: String,
    common: Common,
    settle: Settle,
    steps: usize,
    keep_fixed: bool,
    no_mechanisms: bool,
    cold: bool,
) -> PyResult<String> {
    detached(py, || {
        if settle.moves.is_empty() && settle.profile.is_none() {
            return Err(Fail::Model(
                "capacity needs a settlement: give move={NAME: (u, v)} (or profile=...)".into(),
            ));
        }
        let (st, solver, splits) = common.structure_split(&model, Some(&settle))?;
        let opts = CapacityOptions {
            steps,
            hot_start: !cold,
            mechanisms: !no_mechanisms,
            release_fixed: !keep_fixed,
            solver,
            ..CapacityOptions::default()
        };
        json_split(&capacity_analysis(&st, &opts)?, &splits)
    })
}

#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn incremental(
    py: Python<'_>,
    model: String,
    common: Common,
    control: (f64, f64),
    direction: (f64, f64),
    max: f64,
    step: f64,
    settle: Settle,
    keep_fixed: bool,
    snapshot_every: usize,
    no_stop: bool,
) -> PyResult<String> {
    detached(py, || {
        for (name, p) in [("control", control), ("direction", direction)] {
            if !(p.0.is_finite() && p.1.is_finite()) {
                return Err(Fail::Model(format!(
                    "{name}=({}, {}): expected two finite numbers",
                    p.0, p.1
                )));
            }
        }
        if settle.moves.is_empty() && !settle.fixed.is_empty() {
            return Err(Fail::Model("fixed only applies with settle".into()));
        }
        let (st, solver) = common.structure(&model, Some(&settle))?;
        let start = if settle.moves.is_empty() {
            st
        } else {
            settled(&st, &solver, !keep_fixed)?
        };
        let control = Control::nearest(&start, [control.0, control.1], [direction.0, direction.1])?;
        let opts = IncrementalOptions {
            step,
            max_displacement: max,
            stop_after_peak: !no_stop,
            snapshot_every,
            solver,
            ..IncrementalOptions::default()
        };
        json(&incremental_with(&start, &control, &opts, &mut |_| {})?)
    })
}

#[pyfunction]
fn tilt(py: Python<'_>, model: String, common: Common, direction: &str) -> PyResult<String> {
    let dir = match direction {
        "+x" => 1.0,
        "-x" => -1.0,
        d => return Err(Fail::Model(format!("direction={d}: expected +x or -x")).into()),
    };
    detached(py, || {
        let (st, opts) = common.structure(&model, None)?;
        json(&voussoir::analysis::tilt::tilt(&st, dir, &opts)?)
    })
}

// ---------------------------------------------------------------------------------------------
// Drawings (the CLI's `plot` path: any saved result or model JSON)

/// SVG of a saved result or model: the deformed configuration, or the curve of a capacity or
/// incremental result.
#[pyfunction]
#[pyo3(signature = (result, scale=None, forces=false, title=None))]
fn draw_svg(
    py: Python<'_>,
    result: String,
    scale: Option<f64>,
    forces: bool,
    title: Option<String>,
) -> PyResult<String> {
    detached(py, || {
        if let Some(s) = scale {
            if !(s.is_finite() && s >= 0.0) {
                return Err(Fail::Model(format!(
                    "scale={s}: expected a finite number ≥ 0"
                )));
            }
        }
        let saved = draw::parse_saved(&result)?;
        let opts = DrawOptions {
            scale,
            forces,
            ..DrawOptions::default()
        };
        if forces && saved.is_3d() {
            return Err(Fail::Model(
                "forces=True: the 3D drawing shows the centres of pressure, not force arrows"
                    .into(),
            ));
        }
        Ok(draw::draw_saved(&saved, &opts, title.as_deref())?.svg)
    })
}

/// The self-contained HTML report of a saved result or model.
#[pyfunction]
#[pyo3(signature = (result, title=None, source=String::new(), scale=None))]
fn report_html(
    py: Python<'_>,
    result: String,
    title: Option<String>,
    source: String,
    scale: Option<f64>,
) -> PyResult<String> {
    detached(py, || {
        let saved = draw::parse_saved(&result)?;
        Ok(draw::report_saved(
            &saved,
            &ReportOptions {
                title,
                source,
                scale,
                inputs: None,
            },
        )?)
    })
}

/// PNG bytes of an SVG (bundled font, the CLI's zoom).
#[pyfunction]
fn svg_to_png<'py>(py: Python<'py>, svg: String) -> PyResult<Bound<'py, PyBytes>> {
    let png = detached(py, || Ok(draw::svg_to_png(&svg, draw::PNG_ZOOM)?))?;
    Ok(PyBytes::new(py, &png))
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("VoussoirError", m.py().get_type::<VoussoirError>())?;
    m.add("ModelError", m.py().get_type::<ModelError>())?;
    m.add("SolverError", m.py().get_type::<SolverError>())?;
    m.add_function(wrap_pyfunction!(model_from_text, m)?)?;
    m.add_function(wrap_pyfunction!(model_from_path, m)?)?;
    m.add_function(wrap_pyfunction!(model_from_dxf, m)?)?;
    m.add_function(wrap_pyfunction!(model_check, m)?)?;
    m.add_function(wrap_pyfunction!(gen_arch, m)?)?;
    m.add_function(wrap_pyfunction!(gen_lintel, m)?)?;
    m.add_function(wrap_pyfunction!(gen_wall, m)?)?;
    m.add_function(wrap_pyfunction!(gen_facade, m)?)?;
    m.add_function(wrap_pyfunction!(limit, m)?)?;
    m.add_function(wrap_pyfunction!(settle, m)?)?;
    m.add_function(wrap_pyfunction!(capacity, m)?)?;
    m.add_function(wrap_pyfunction!(incremental, m)?)?;
    m.add_function(wrap_pyfunction!(tilt, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_base, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_task, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_run, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_csv, m)?)?;
    m.add_function(wrap_pyfunction!(identify::identify, m)?)?;
    m.add_function(wrap_pyfunction!(draw_svg, m)?)?;
    m.add_function(wrap_pyfunction!(report_html, m)?)?;
    m.add_function(wrap_pyfunction!(svg_to_png, m)?)?;
    Ok(())
}
