//! `voussoir._native`: the Python extension module. Thin: every function takes the model as the
//! JSON text of a [`voussoir::Model`] and plain option values, calls the same library functions
//! as the CLI (`crates/voussoir-cli`), and returns the result as the JSON text the CLI writes
//! with `--json` (same serialiser, [`voussoir_io::files::to_json`]), so that the Python result's
//! `to_json()` is byte-identical to the CLI's. The Python package (`python/voussoir`) turns that
//! JSON into typed objects with numpy arrays.
//!
//! The GIL is released for everything that solves (`Python::detach`), and panics are caught and
//! turned into `voussoir.VoussoirError`, so a failure never takes the interpreter down.

mod analysis3d;
mod model3d;
mod options;
mod sweep;

use options::Fail;
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use std::path::PathBuf;
use voussoir::generate::{self, FirstCourse, LintelSpec, WallSpec};
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

/// `voussoir.OptionError`: an option (a keyword) out of range or in conflict with another or
/// with the model; both a `ModelError` and a `ValueError`, as Python's own checks of keywords
/// raise `ValueError`.
static OPTION_ERROR: pyo3::sync::PyOnceLock<Py<pyo3::types::PyType>> =
    pyo3::sync::PyOnceLock::new();

fn option_error(py: Python<'_>) -> PyResult<&Bound<'_, pyo3::types::PyType>> {
    OPTION_ERROR
        .get_or_try_init(py, || {
            let bases = (
                py.get_type::<ModelError>(),
                py.get_type::<pyo3::exceptions::PyValueError>(),
            );
            let ns = pyo3::types::PyDict::new(py);
            ns.set_item("__module__", "voussoir")?;
            ns.set_item(
                "__doc__",
                "An option (keyword) out of range or in conflict with another or with the model: a ModelError and a ValueError.",
            )?;
            let t = py
                .get_type::<pyo3::types::PyType>()
                .call1(("OptionError", bases, ns))?;
            Ok::<_, PyErr>(t.cast_into::<pyo3::types::PyType>()?.unbind())
        })
        .map(|t| t.bind(py))
}

impl From<Fail> for PyErr {
    fn from(f: Fail) -> PyErr {
        match f {
            Fail::Model(m) => ModelError::new_err(m),
            Fail::Solver(m) => SolverError::new_err(m),
            Fail::Option(m) => Python::attach(|py| match option_error(py) {
                Ok(t) => PyErr::from_type(t.clone(), m),
                Err(e) => e,
            }),
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

#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (shape, radius, radius_at, thickness, voussoirs, unit_weight, width, live, live_load, half_angle, offset))]
fn gen_arch(
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
) -> PyResult<String> {
    let spec = model3d::arch_spec(
        shape,
        radius,
        radius_at,
        thickness,
        voussoirs,
        unit_weight,
        width,
        live,
        live_load,
        half_angle,
        offset,
    )?;
    let m = generate::arch(&spec).map_err(Fail::from)?;
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
        live: model3d::live_of(live)?,
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
    let live = model3d::live_of(live)?;
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

/// Parse a support motion as Python's keywords give it: `moves` each the text `NAME=u,v[,θ]`
/// (lengths in m or with a unit) or the JSON of a `Move` (`{"support", "values"}`), `profile`
/// the text `uniform:X0,X1,V` (…) or the JSON of a `Profile`. Returns the library's
/// `SupportMotion` JSON (every value in m and degrees): the one parser of the CLI and Python.
#[pyfunction]
#[pyo3(signature = (moves, fixed, profile=None, splits=Vec::new()))]
fn motion(
    py: Python<'_>,
    moves: Vec<String>,
    fixed: Vec<String>,
    profile: Option<String>,
    splits: Vec<String>,
) -> PyResult<String> {
    use voussoir::request::{parse_profile, Move, Names, Split, SupportMotion};
    detached(py, || {
        let n = Names::Keywords;
        let moves = moves
            .iter()
            .map(|m| {
                if m.trim_start().starts_with('{') {
                    #[derive(serde::Deserialize)]
                    struct Parts {
                        support: String,
                        values: Vec<f64>,
                    }
                    let p: Parts = serde_json::from_str(m)
                        .map_err(|e| Fail::Model(format!("move {m}: {e}")))?;
                    let m = Move {
                        support: p.support,
                        values: p.values,
                        third_with_unit: false,
                    };
                    m.check(n)?;
                    Ok(m)
                } else {
                    Ok(Move::parse(m, n)?)
                }
            })
            .collect::<Result<Vec<_>, Fail>>()?;
        let profile = match profile {
            None => None,
            Some(p) if p.trim_start().starts_with('{') => {
                let p: voussoir::settlement_input::Profile = serde_json::from_str(&p)
                    .map_err(|e| Fail::Model(format!("invalid settlement profile: {e}")))?;
                p.validate()?;
                Some(p)
            }
            Some(p) => Some(parse_profile(&p)?),
        };
        let splits = splits
            .iter()
            .map(|s| Split::parse(s, n))
            .collect::<Result<Vec<_>, _>>()?;
        let m = SupportMotion {
            moves,
            fixed,
            profile,
            splits,
        };
        m.validate(n)?;
        json(&m)
    })
}

/// Run a request (the JSON of `voussoir::request::Request`, as `python/voussoir/_options.py`
/// builds it from the keywords) on a model (JSON, 2D or 3D): the library's one entry, the
/// result as the CLI's JSON (a sweep's records as JSON lines). Messages name Python's keywords.
#[pyfunction]
#[pyo3(signature = (model, request, threads=None))]
fn run(py: Python<'_>, model: String, request: String, threads: Option<usize>) -> PyResult<String> {
    detached(py, || analysis3d::run_json(&model, &request, threads))
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
    m.add("OptionError", option_error(m.py())?)?;
    m.add_function(wrap_pyfunction!(model_from_text, m)?)?;
    m.add_function(wrap_pyfunction!(model_from_path, m)?)?;
    m.add_function(wrap_pyfunction!(model_from_dxf, m)?)?;
    m.add_function(wrap_pyfunction!(model_check, m)?)?;
    m.add_function(wrap_pyfunction!(gen_arch, m)?)?;
    m.add_function(wrap_pyfunction!(gen_lintel, m)?)?;
    m.add_function(wrap_pyfunction!(gen_wall, m)?)?;
    m.add_function(wrap_pyfunction!(gen_facade, m)?)?;
    m.add_function(wrap_pyfunction!(motion, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_csv, m)?)?;
    m.add_function(wrap_pyfunction!(draw_svg, m)?)?;
    m.add_function(wrap_pyfunction!(report_html, m)?)?;
    m.add_function(wrap_pyfunction!(svg_to_png, m)?)?;
    model3d::register(m)?;
    analysis3d::register(m)?;
    Ok(())
}
