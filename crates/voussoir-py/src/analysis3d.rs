//! Analyses of 3D models for Python, and `safety` / `least_thickness` of either dimension.
//! Limit, settle and capacity go through the library's request layer ([`run_request`]); tilt,
//! safety and least thickness (not yet in the request layer) make the same library calls as the
//! CLI's commands (crates/voussoir-cli/src/{tilt,safety}.rs). Results are serialised by the
//! CLI's serialiser, so that `to_json()` is byte-identical to `--json`.
//!
//! Support motions arrive in the request's JSON in the CLI's own syntax
//! (`NAME=u,v,w[,θx,θy,θz]`, lengths with or without a unit, angles in degrees; profiles
//! `uniform:…`) and are read by the request layer's parser, so Python and the CLI accept the
//! same motions. The model options are validated by the request layer too.

use crate::detached;
use crate::options::Fail;
use pyo3::prelude::*;
use serde::Serialize;
use voussoir::analysis::safety::{least_thickness, safety, LeastThickness, SafetyOptions};
use voussoir::generate::RadiusAt;
use voussoir::lp::{Method, SolverOptions};
use voussoir::model3d::AnyModel;
use voussoir::request::{AnyResult, FrictionCone, ModelOptions, Names, Output, Request};
use voussoir::settlement_input::SupportSplit;
use voussoir::{BuildOptions, Structure, Structure3d};

/// The options of a 3D analysis (the CLI's `ModelArgs` for a 3D model), from a Python dict.
#[derive(FromPyObject, Clone, Debug)]
#[pyo3(from_item_all)]
pub struct Common3d {
    pub tolerance: Option<f64>,
    /// None: the solver policy's 3D method, as the CLI.
    pub method: Option<String>,
    pub friction: Option<f64>,
    pub compressive_strength: Option<f64>,
    pub friction_facets: Option<usize>,
    /// "pyramid" or "exact".
    pub friction_cone: String,
    /// The support motion in the CLI's syntax.
    pub moves: Vec<String>,
    pub fixed: Vec<String>,
    pub profile: Option<String>,
    pub splits: Vec<String>,
}

fn method_of(m: &str) -> Result<Method, Fail> {
    Ok(match m {
        "dual-simplex" => Method::DualSimplex,
        "primal-simplex" => Method::PrimalSimplex,
        "ipm" => Method::Ipm,
        "choose" => Method::Choose,
        "ipm-no-crossover" => Method::IpmNoCrossover,
        "pdlp" => Method::Pdlp,
        "clarabel" => Method::Clarabel,
        m => {
            return Err(Fail::Model(format!(
                "method={m}: expected dual-simplex, primal-simplex, ipm, choose, ipm-no-crossover, pdlp or clarabel"
            )))
        }
    })
}

/// The solver of a model of `dims` dimensions: `method`, else the request layer's default of
/// the dimension ([`voussoir::request::default_method`], the solver policy's, as the CLI).
fn solver_of(method: Option<&str>, dims: usize) -> Result<SolverOptions, Fail> {
    let method = match method {
        Some(m) => method_of(m)?,
        None => voussoir::request::default_method(dims),
    };
    Ok(SolverOptions {
        method,
        ..SolverOptions::default()
    })
}

impl Common3d {
    fn exact(&self) -> Result<bool, Fail> {
        match self.friction_cone.as_str() {
            "pyramid" => Ok(false),
            "exact" | "cone" | "socp" => Ok(true),
            c => Err(Fail::Model(format!(
                "friction_cone={c}: expected pyramid or exact"
            ))),
        }
    }

    /// The model options, validated by the request layer (messages name the keywords).
    fn check(&self) -> Result<(), Fail> {
        let options = ModelOptions {
            tolerance: self.tolerance,
            friction: self.friction,
            compressive_strength: self.compressive_strength,
            friction_facets: self.friction_facets,
            friction_cone: if self.exact()? {
                FrictionCone::Exact
            } else {
                FrictionCone::Pyramid
            },
        };
        Ok(options.validate(Names::Keywords)?)
    }

    pub(crate) fn solver(&self) -> Result<SolverOptions, Fail> {
        solver_of(self.method.as_deref(), 3)
    }

    fn has_motion(&self) -> bool {
        !(self.moves.is_empty()
            && self.fixed.is_empty()
            && self.profile.is_none()
            && self.splits.is_empty())
    }

    /// The 3D model with materials overridden, and its structure (tilt and safety take no
    /// support motion: [`refuse_motion`] first).
    pub(crate) fn structure(&self, model: &str) -> Result<Structure3d, Fail> {
        self.check()?;
        let mut m = match crate::model3d::parse_any(model)? {
            AnyModel::Spatial(m) => m,
            AnyModel::Planar(_) => {
                return Err(Fail::Model(
                    "internal: a 2D model reached the 3D analyses".into(),
                ))
            }
        };
        m.override_joint_laws(self.friction, self.compressive_strength);
        let mut st = Structure3d::new(
            &m,
            BuildOptions {
                tolerance: self.tolerance,
            },
        )?;
        if let Some(k) = self.friction_facets {
            st.friction_facets = k;
        }
        Ok(st)
    }
}

fn json<T: Serialize>(v: &T) -> Result<String, Fail> {
    Ok(voussoir_io::files::to_json(v)?)
}

fn json_split<T: Serialize>(v: &T, splits: &[SupportSplit]) -> Result<String, Fail> {
    if splits.is_empty() {
        return json(v);
    }
    json(&voussoir_io::motion::WithSplits {
        result: v,
        split_supports: splits,
    })
}

fn refuse_motion(c: &Common3d, what: &str) -> Result<(), Fail> {
    if c.has_motion() {
        return Err(Fail::Model(format!(
            "{what} takes no support motion (move, fixed, profile)"
        )));
    }
    Ok(())
}

/// Run a request of the library's request layer ([`voussoir::request`]: limit, settle,
/// capacity; the options as the request's JSON, built by python/voussoir/_analysis3d.py from
/// the keywords) on a model of either dimension. Every choice — the variant of the analysis,
/// the default solver of the dimension, the support motion's meaning and whether one is
/// needed — is the request layer's; this only serialises the result as the CLI does.
#[pyfunction]
pub fn run_request(py: Python<'_>, model: String, request: String) -> PyResult<String> {
    detached(py, || {
        let mut req = Request::from_json(&request)?;
        req.names = Names::Keywords;
        let any = crate::model3d::parse_any(&model)?;
        match voussoir::request::run(&any, &req)? {
            AnyResult::Planar(r) => output_json(&r.output, &r.setup.splits),
            AnyResult::Spatial(r) => output_json(&r.output, &r.setup.splits),
        }
    })
}

fn output_json<D: voussoir::result::Spatial>(
    o: &Output<D>,
    splits: &[SupportSplit],
) -> Result<String, Fail> {
    match o {
        Output::Limit(r) => json_split(r, splits),
        Output::Settlement(r) => json_split(r, splits),
        Output::Capacity(r) => json_split(r, splits),
        Output::Tilt(r) => json_split(r, splits),
        Output::Safety(r) => json_split(r, splits),
    }
}

/// `voussoir tilt` of a 3D model towards `azimuth` (degrees from +x towards +y).
#[pyfunction]
pub fn tilt3d(py: Python<'_>, model: String, common: Common3d, azimuth: f64) -> PyResult<String> {
    detached(py, || {
        refuse_motion(&common, "tilt")?;
        if !azimuth.is_finite() {
            return Err(Fail::Model(format!(
                "direction={azimuth}: must be a finite number of degrees"
            )));
        }
        // As the CLI: the azimuth taken into [0, 360).
        let r = azimuth.rem_euclid(360.0);
        let az = if r >= 360.0 || r == 0.0 { 0.0 } else { r };
        let st = common.structure(&model)?;
        let solver = common.solver()?;
        let r = if common.exact()? {
            voussoir::analysis::tilt::tilt_azimuth_exact(&st, az, &solver)?
        } else {
            voussoir::analysis::tilt::tilt_azimuth(&st, az, &solver)?
        };
        json(&r)
    })
}

/// `voussoir safety` of a model of either dimension: whether it stands under its dead loads,
/// its geometric safety factor and the ranges of its support reactions.
#[pyfunction]
pub fn safety_any(
    py: Python<'_>,
    model: String,
    common: Common3d,
    bisection_tolerance: f64,
    ranges: bool,
) -> PyResult<String> {
    detached(py, || {
        let tol = bisection_tolerance;
        if !(tol.is_finite() && tol > 0.0 && tol < 1.0) {
            return Err(Fail::Model(format!(
                "bisection_tolerance={tol}: must be a number between 0 and 1"
            )));
        }
        refuse_motion(&common, "safety")?;
        if common.exact()? {
            return Err(Fail::Model(
                "friction_cone=exact does not apply to safety (its programs are LPs: the inscribed pyramid)".into(),
            ));
        }
        let opts = |solver| SafetyOptions {
            tolerance: tol,
            reactions: ranges,
            solver,
        };
        match crate::model3d::parse_any(&model)? {
            AnyModel::Planar(mut m) => {
                common.check()?;
                if common.friction_facets.is_some() {
                    return Err(Fail::Model(
                        "friction_facets and friction_cone apply to 3D models (a 2D joint's friction is exact)".into(),
                    ));
                }
                m.override_joint_laws(common.friction, common.compressive_strength);
                let st = Structure::new(
                    &m,
                    BuildOptions {
                        tolerance: common.tolerance,
                    },
                )?;
                json(&safety(
                    &st,
                    &opts(solver_of(common.method.as_deref(), 2)?),
                )?)
            }
            AnyModel::Spatial(_) => {
                let st = common.structure(&model)?;
                json(&safety(&st, &opts(common.solver()?))?)
            }
        }
    })
}

/// What `voussoir least-thickness --json` reports (crates/voussoir-cli/src/safety.rs, same
/// fields in the same order).
#[derive(Serialize)]
struct LeastThicknessResult {
    generator: &'static str,
    #[serde(flatten)]
    found: LeastThickness,
    centreline_radius: f64,
    thickness_over_radius: f64,
    solver: voussoir::lp::SolverInfo,
}

fn centreline(radius: f64, at: RadiusAt, t: f64) -> f64 {
    match at {
        RadiusAt::Intrados => radius + t / 2.0,
        RadiusAt::Centreline => radius,
        RadiusAt::Extrados => radius - t / 2.0,
    }
}

/// The arguments of `gen_arch` (shape, radius, radius_at, thickness, voussoirs, unit_weight,
/// width, live, live_load, half_angle, offset).
type ArchArgs = (
    String,
    f64,
    String,
    f64,
    usize,
    f64,
    f64,
    String,
    f64,
    f64,
    f64,
);
/// The arguments of `gen_dome` (radius, radius_at, thickness, courses, segments, half_angle,
/// oculus, unit_weight, crown_load).
type DomeArgs = (f64, String, f64, usize, usize, f64, Option<f64>, f64, f64);

/// `voussoir least-thickness arch|dome`: the least thickness at which the generated arch
/// (`arch`: the arguments of `gen_arch` as JSON-able tuple) or dome stands under its own
/// weight. Returns (result JSON, model JSON at the least thickness).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (generator, arch, dome, lower, upper, bisection_tolerance, method))]
pub fn least_thickness_any(
    py: Python<'_>,
    generator: String,
    arch: Option<ArchArgs>,
    dome: Option<DomeArgs>,
    lower: Option<f64>,
    upper: Option<f64>,
    bisection_tolerance: f64,
    method: Option<String>,
) -> PyResult<(String, String)> {
    detached(py, || {
        let rel = bisection_tolerance;
        let build = BuildOptions::default();
        let (radius, at_text) = match (&arch, &dome) {
            (Some(a), _) => (a.1, a.2.clone()),
            (_, Some(d)) => (d.0, d.1.clone()),
            _ => return Err(Fail::Model("least_thickness: no generator".into())),
        };
        if !(radius.is_finite() && radius > 0.0) {
            return Err(Fail::Model(format!(
                "radius={radius}: must be a number > 0"
            )));
        }
        if !(rel.is_finite() && rel > 0.0 && rel < 1.0) {
            return Err(Fail::Model(format!(
                "bisection_tolerance={rel}: must be a number between 0 and 1"
            )));
        }
        let lo = lower.unwrap_or(radius / 1000.0);
        let hi = upper.unwrap_or(radius / 2.0);
        let at = match at_text.as_str() {
            "intrados" => RadiusAt::Intrados,
            "centreline" | "centerline" => RadiusAt::Centreline,
            "extrados" => RadiusAt::Extrados,
            s => {
                return Err(Fail::Model(format!(
                    "radius_at={s}: expected intrados, centreline or extrados"
                )))
            }
        };
        let (generator, found, model, solver) = match (generator.as_str(), arch, dome) {
            ("arch", Some(a), _) => {
                let solver = solver_of(method.as_deref(), 2)?;
                let spec = crate::model3d::arch_spec(
                    &a.0, a.1, &a.2, a.3, a.4, a.5, a.6, &a.7, a.8, a.9, a.10,
                )?;
                let make = |t: f64| {
                    voussoir::generate::arch(&voussoir::generate::ArchSpec {
                        thickness: t,
                        ..spec.clone()
                    })
                };
                let found = least_thickness(
                    |t| Structure::new(&make(t)?, build),
                    lo,
                    hi,
                    rel * radius,
                    &solver,
                )?;
                let m = json(&make(found.thickness)?)?;
                ("arch", found, m, solver)
            }
            ("dome", _, Some(d)) => {
                let solver = solver_of(method.as_deref(), 3)?;
                let spec = crate::model3d::dome_spec(d.0, &d.1, d.2, d.3, d.4, d.5, d.6, d.7, d.8)?;
                let make = |t: f64| {
                    voussoir::generate3d::dome(&voussoir::generate3d::DomeSpec {
                        thickness: t,
                        ..spec.clone()
                    })
                };
                let found = least_thickness(
                    |t| Structure3d::new(&make(t)?, build),
                    lo,
                    hi,
                    rel * radius,
                    &solver,
                )?;
                let m = json(&make(found.thickness)?)?;
                ("dome", found, m, solver)
            }
            (g, _, _) => {
                return Err(Fail::Model(format!(
                    "least_thickness {g}: expected arch or dome"
                )))
            }
        };
        let rc = centreline(radius, at, found.thickness);
        let r = LeastThicknessResult {
            generator,
            centreline_radius: rc,
            thickness_over_radius: found.thickness / rc,
            found,
            solver: solver.info(),
        };
        Ok((json(&r)?, model))
    })
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run_request, m)?)?;
    m.add_function(wrap_pyfunction!(tilt3d, m)?)?;
    m.add_function(wrap_pyfunction!(safety_any, m)?)?;
    m.add_function(wrap_pyfunction!(least_thickness_any, m)?)?;
    Ok(())
}
