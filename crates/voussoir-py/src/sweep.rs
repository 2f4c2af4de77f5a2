//! Sweeps of settlement analyses, task by task, so that Python can hand the tasks to any
//! `concurrent.futures.Executor` (a Dask cluster, a process pool) or run them here on rayon.
//! The engine — motions per task, the analysis, the record, the CSV — is the library's
//! [`voussoir::sweep`], the one behind `voussoir sweep`, so a Python sweep's JSON lines are
//! byte-identical to the CLI's `--jsonl`.

use crate::detached;
use crate::options::{Common, Fail, Settle};
use pyo3::prelude::*;
use voussoir::sweep::{self, SweepKind, SweepRecord, SweepSpec};
use voussoir::{BuildOptions, Model};

fn spec(common: &Common, kind: &str, n: usize, cov: f64, seed: u64) -> Result<SweepSpec, Fail> {
    let kind = match kind {
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
    };
    Ok(SweepSpec {
        kind,
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
        let motions: Vec<[f64; 3]> = m.supports.iter().map(|s| s.motion).collect();
        let r = sweep::analyse(&m, &spec, k, &motions)?;
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
