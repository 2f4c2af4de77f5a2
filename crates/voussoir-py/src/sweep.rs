//! The CSV table of a sweep's records (the sweep itself is a request: `_native.run`, task by
//! task on any `concurrent.futures.Executor` or all tasks on rayon threads). The engine is the
//! library's [`voussoir::sweep`], the one behind `voussoir sweep`, so a Python sweep's JSON
//! lines are byte-identical to the CLI's `--jsonl`.

use crate::options::Fail;
use pyo3::prelude::*;
use voussoir::sweep::{self, SweepRecord};

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
