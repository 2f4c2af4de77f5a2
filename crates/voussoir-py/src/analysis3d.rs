//! The one entry of the request layer for Python ([`run_request`], also `_native.run`), and
//! `least_thickness` of a generated arch or dome. Every analysis of either dimension — limit,
//! settle, capacity, tilt, safety, incremental, identify, sweep — is a request
//! (`voussoir::request::Request`, its JSON built by python/voussoir/_options.py and
//! _analysis3d.py from the keywords) run by `voussoir::request::run`, which makes every choice;
//! this only serialises the result with the CLI's serialiser, so that `to_json()` is
//! byte-identical to `--json`.
//!
//! Support motions arrive in the request's JSON in the CLI's own syntax
//! (`NAME=u,v,w[,θx,θy,θz]`, lengths with or without a unit, angles in degrees; profiles
//! `uniform:…`) and are read by the request layer's parser, so Python and the CLI accept the
//! same motions.

use crate::detached;
use crate::options::Fail;
use pyo3::prelude::*;
use serde::Serialize;
use voussoir::lp::Method;
use voussoir::model3d::AnyModel;
use voussoir::request::{AnyResult, Names, Output, Request};
use voussoir::settlement_input::SupportSplit;

fn method_of(m: &str) -> Result<Method, Fail> {
    Ok(match m {
        "dual-simplex" => Method::DualSimplex,
        "primal-simplex" => Method::PrimalSimplex,
        "ipm" => Method::Ipm,
        "choose" => Method::Choose,
        "ipm-no-crossover" => Method::IpmNoCrossover,
        "pdlp" => Method::Pdlp,
        "clarabel" => Method::Clarabel,
        "clarabel-vertex" => Method::ClarabelVertex,
        m => {
            return Err(Fail::Model(format!(
                "method={m}: expected dual-simplex, primal-simplex, ipm, choose, ipm-no-crossover, pdlp, clarabel or clarabel-vertex"
            )))
        }
    })
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

/// Run a request on a model (JSON, 2D or 3D) through the library's one entry; a sweep's tasks
/// on `threads` rayon threads (None or 0: one per core). Messages name Python's keywords.
pub(crate) fn run_json(model: &str, request: &str, threads: Option<usize>) -> Result<String, Fail> {
    let mut req = Request::from_json(request)?;
    req.names = Names::Keywords;
    let any = crate::model3d::parse_any(model)?;
    let result = match threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| Fail::Model(format!("cannot start worker threads: {e}")))?
            .install(|| voussoir::request::run(&any, &req)),
        None => voussoir::request::run(&any, &req),
    };
    match result? {
        AnyResult::Planar(r) => output_json(&r.output, &r.setup.splits),
        AnyResult::Spatial(r) => output_json(&r.output, &r.setup.splits),
    }
}

/// The result's JSON as the CLI writes it; a sweep's records as JSON lines (the CLI's
/// `--jsonl`), one per line.
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
        Output::Incremental(r) => json_split(r, splits),
        Output::Identify(r, _) => json_split(r, splits),
        Output::Sweep(records) => records
            .iter()
            .map(|r| {
                serde_json::to_string(r).map_err(|e| Fail::Model(format!("cannot serialise: {e}")))
            })
            .collect::<Result<Vec<_>, _>>()
            .map(|l| l.join("\n")),
    }
}

/// Run a request (`voussoir::request::Request` as JSON) on a model of either dimension.
#[pyfunction]
#[pyo3(signature = (model, request, threads=None))]
pub fn run_request(
    py: Python<'_>,
    model: String,
    request: String,
    threads: Option<usize>,
) -> PyResult<String> {
    detached(py, || run_json(&model, &request, threads))
}

/// The arguments of `gen_arch` (shape, radius, radius_at, thickness, voussoirs, unit_weight,
/// width, live, live_load, half_angle, offset; the last three `None` where not given).
type ArchArgs = (
    String,
    f64,
    String,
    f64,
    usize,
    f64,
    f64,
    String,
    Option<f64>,
    Option<f64>,
    Option<f64>,
);
/// The arguments of `gen_dome` (radius, radius_at, thickness, courses, segments, half_angle,
/// oculus, unit_weight, crown_load).
type DomeArgs = (f64, String, f64, usize, usize, f64, Option<f64>, f64, f64);

/// `voussoir least-thickness arch|dome`: the least thickness at which the generated arch
/// (`arch`: the arguments of `gen_arch` as JSON-able tuple) or dome stands under its own
/// weight, through the request layer's [`voussoir::request::least_thickness`]. Returns (result
/// JSON, model JSON at the least thickness).
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
        use voussoir::request::{least_thickness, Generator, LeastThicknessRequest, SolverRequest};
        let generator = match (generator.as_str(), arch, dome) {
            ("arch", Some(a), _) => Generator::Arch(crate::model3d::arch_spec(
                &a.0, a.1, &a.2, a.3, a.4, a.5, a.6, &a.7, a.8, a.9, a.10,
            )?),
            ("dome", _, Some(d)) => Generator::Dome(crate::model3d::dome_spec(
                d.0, &d.1, d.2, d.3, d.4, d.5, d.6, d.7, d.8,
            )?),
            (g, _, _) => {
                return Err(Fail::Model(format!(
                    "least_thickness {g}: expected arch or dome"
                )))
            }
        };
        let solver = SolverRequest {
            method: method.as_deref().map(method_of).transpose()?,
            log: false,
        };
        let req = LeastThicknessRequest {
            lower,
            upper,
            bisection_tolerance,
        };
        let run = least_thickness(&generator, &req, &solver, Names::Keywords)?;
        let model = match &run.model {
            AnyModel::Planar(m) => json(m)?,
            AnyModel::Spatial(m) => json(m)?,
        };
        Ok((json(&run.result)?, model))
    })
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(run_request, m)?)?;
    m.add_function(wrap_pyfunction!(least_thickness_any, m)?)?;
    Ok(())
}
