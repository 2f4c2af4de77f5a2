//! Sweeps of settlement analyses, task by task, so that Python can hand the tasks to any
//! `concurrent.futures.Executor` (a Dask cluster, a process pool) or run them here on rayon.
//! The engine — motions per task, the analysis, the record, the CSV — is the library's
//! [`voussoir::sweep`], the one behind `voussoir sweep`, so a Python sweep's JSON lines are
//! byte-identical to the CLI's `--jsonl`.

use crate::analysis3d::Common3d;
use crate::detached;
use crate::options::{Common, Fail, Settle};
use pyo3::prelude::*;
use voussoir::analysis::settlement::SettlementForm;
use voussoir::model3d::{AnyModel, Model3d};
use voussoir::request::{Names, SupportMotion};
use voussoir::sweep::{self, SweepKind, SweepRecord, SweepSpec};
use voussoir::{BuildOptions, Model, Structure};

fn spec_kind(kind: &str, n: usize, cov: f64, seed: u64) -> Result<SweepKind, Fail> {
    Ok(match kind {
        "steps" => SweepKind::Scale(n),
        "directions" => SweepKind::Direction(n),
        "samples" => SweepKind::Sample {
            count: n,
            cov,
            seed,
        },
        k => {
            return Err(Fail::Model(format!(
                "sweep kind {k}: expected steps, directions or samples"
            )))
        }
    })
}

fn spec(common: &Common, kind: &str, n: usize, cov: f64, seed: u64) -> Result<SweepSpec, Fail> {
    Ok(SweepSpec {
        kind: spec_kind(kind, n, cov, seed)?,
        build: BuildOptions {
            tolerance: common.tolerance,
        },
        solver: common.solver()?,
        form: common.settlement_form()?,
        capacity: None,
    })
}

fn lines(records: &[SweepRecord]) -> Result<Vec<String>, Fail> {
    records
        .iter()
        .map(|r| {
            serde_json::to_string(r).map_err(|e| Fail::Model(format!("cannot serialise: {e}")))
        })
        .collect()
}

/// Validate a sweep (the library's checks, on no task) and return its base model (materials
/// overridden, base motions applied) as JSON: what every task starts from.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn sweep_base(
    py: Python<'_>,
    model: String,
    common: Common,
    settle: Settle,
    kind: String,
    n: usize,
    cov: f64,
    seed: u64,
) -> PyResult<String> {
    detached(py, || {
        let spec = spec(&common, &kind, n, cov, seed)?;
        let m = common.model(&model, Some(&settle))?;
        sweep::run(&m, &spec, &[], &|| {})?;
        Ok(voussoir_io::files::to_json(&m)?)
    })
}

/// One task of a sweep on its base model: its record as one JSON line (no newline).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn sweep_task(
    py: Python<'_>,
    base: String,
    common: Common,
    kind: String,
    n: usize,
    k: usize,
    cov: f64,
    seed: u64,
) -> PyResult<String> {
    detached(py, || {
        let spec = spec(&common, &kind, n, cov, seed)?;
        let m: Model = voussoir_io::files::parse_model(&base)?;
        if k >= n {
            return Err(Fail::Model(format!(
                "task {k} is beyond the sweep's {n} analyses"
            )));
        }
        let st = Structure::new(&m, spec.build)?;
        let r = sweep::analyse(&st, &spec, k, &sweep::base_motions(&st))?;
        Ok(lines(std::slice::from_ref(&r))?.remove(0))
    })
}

/// Tasks `tasks` of a sweep on `threads` rayon threads (0: one per core), in task order.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn sweep_run(
    py: Python<'_>,
    base: String,
    common: Common,
    kind: String,
    n: usize,
    tasks: Vec<usize>,
    cov: f64,
    seed: u64,
    threads: usize,
) -> PyResult<Vec<String>> {
    detached(py, || {
        let spec = spec(&common, &kind, n, cov, seed)?;
        let m = voussoir_io::files::parse_model(&base)?;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| Fail::Model(format!("cannot start worker threads: {e}")))?;
        let records = pool.install(|| sweep::run(&m, &spec, &tasks, &|| {}))?;
        lines(&records)
    })
}

/// The CSV table of records given as JSON lines (the CLI's `voussoir sweep` CSV).
#[pyfunction]
pub fn sweep_csv(lines: Vec<String>) -> PyResult<String> {
    let records = lines
        .iter()
        .map(|l| {
            serde_json::from_str(l).map_err(|e| Fail::Model(format!("not a sweep record: {e}")))
        })
        .collect::<Result<Vec<SweepRecord>, Fail>>()?;
    Ok(sweep::csv(&records))
}

// 3D sweeps: the same engine ([`sweep::run_assembly`], [`sweep::analyse`]) on a 3D structure.
// The options are a 3D analysis's ([`Common3d`]: materials, the friction pyramid, the 3D
// default solver); the support motion is read by the request layer's parser, as for `settle`.

fn form_of(form: &str) -> Result<SettlementForm, Fail> {
    match form {
        "both" => Ok(SettlementForm::Both),
        "force-only" => Ok(SettlementForm::ForceOnly),
        f => Err(Fail::Model(format!(
            "settlement_form={f}: expected both or force-only"
        ))),
    }
}

#[allow(clippy::too_many_arguments)]
fn spec3d(
    c: &Common3d,
    form: &str,
    kind: &str,
    n: usize,
    cov: f64,
    seed: u64,
) -> Result<SweepSpec, Fail> {
    if c.friction_cone != "pyramid" {
        return Err(Fail::Model(format!(
            "friction_cone={}: a sweep solves the friction pyramid (friction_facets); the exact cone is solved by settle",
            c.friction_cone
        )));
    }
    Ok(SweepSpec {
        kind: spec_kind(kind, n, cov, seed)?,
        build: BuildOptions {
            tolerance: c.tolerance,
        },
        solver: c.solver()?,
        form: form_of(form)?,
        capacity: None,
    })
}

/// A 3D sweep's base model: the model with materials overridden and the base motions applied
/// (split supports included), validated with the sweep (the library's checks, on no task), as
/// JSON.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn sweep3d_base(
    py: Python<'_>,
    model: String,
    common: Common3d,
    form: String,
    kind: String,
    n: usize,
    cov: f64,
    seed: u64,
) -> PyResult<String> {
    detached(py, || {
        let spec = spec3d(&common, &form, &kind, n, cov, seed)?;
        let mut m: Model3d = match crate::model3d::parse_any(&model)? {
            AnyModel::Spatial(m) => m,
            AnyModel::Planar(_) => {
                return Err(Fail::Model(
                    "internal: a 2D model reached the 3D sweep".into(),
                ))
            }
        };
        let motion = SupportMotion::parse(
            &common.moves,
            &common.fixed,
            common.profile.as_deref(),
            &common.splits,
            Names::Keywords,
        )?;
        motion.apply(&mut m, Names::Keywords)?;
        let text = voussoir_io::files::to_json(&m)?;
        let st = common.structure(&text)?;
        sweep::run_assembly(&st, &spec, &[], &|| {})?;
        // The materials as overridden by the options (the tasks override them again: the same).
        Ok(voussoir_io::files::to_json(&m)?)
    })
}

/// One task of a 3D sweep on its base model: its record as one JSON line (no newline).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn sweep3d_task(
    py: Python<'_>,
    base: String,
    common: Common3d,
    form: String,
    kind: String,
    n: usize,
    k: usize,
    cov: f64,
    seed: u64,
) -> PyResult<String> {
    detached(py, || {
        let spec = spec3d(&common, &form, &kind, n, cov, seed)?;
        if k >= n {
            return Err(Fail::Model(format!(
                "task {k} is beyond the sweep's {n} analyses"
            )));
        }
        let st = common.structure(&base)?;
        let r = sweep::analyse(&st, &spec, k, &sweep::base_motions(&st))?;
        Ok(lines(std::slice::from_ref(&r))?.remove(0))
    })
}

/// Tasks `tasks` of a 3D sweep on `threads` rayon threads (0: one per core), in task order.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn sweep3d_run(
    py: Python<'_>,
    base: String,
    common: Common3d,
    form: String,
    kind: String,
    n: usize,
    tasks: Vec<usize>,
    cov: f64,
    seed: u64,
    threads: usize,
) -> PyResult<Vec<String>> {
    detached(py, || {
        let spec = spec3d(&common, &form, &kind, n, cov, seed)?;
        let st = common.structure(&base)?;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| Fail::Model(format!("cannot start worker threads: {e}")))?;
        let records = pool.install(|| sweep::run_assembly(&st, &spec, &tasks, &|| {}))?;
        lines(&records)
    })
}
