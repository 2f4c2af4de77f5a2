//! Sweeps of settlement analyses, task by task, so that Python can hand the tasks to any
//! `concurrent.futures.Executor` (a Dask cluster, a process pool) or run them here on rayon.
//!
//! The scenarios, the record and the CSV are those of `voussoir sweep`
//! (crates/voussoir-cli/src/sweep.rs): same SplitMix64 streams per sample, same fields, so a
//! Python sweep's JSON lines are byte-identical to the CLI's `--jsonl`. That code lives in the
//! CLI's binary crate and cannot be called from here, hence this copy; moving it into the
//! library would let both front ends share it (see the report of issue 15).

use crate::detached;
use crate::options::{Common, Fail, Settle};
use pyo3::prelude::*;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use voussoir::analysis::settlement::settle_with;
use voussoir::result::JointState;
use voussoir::{BuildOptions, Model, Structure};

/// One analysis of a sweep (the CLI's `SweepRecord`, field for field).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SweepRecord {
    pub index: usize,
    pub kind: String,
    pub parameter: f64,
    pub status: String,
    pub work_dead_loads: Option<f64>,
    pub work_reactions: Option<f64>,
    pub duality_gap: Option<f64>,
    pub certified: bool,
    pub hinges: usize,
    pub hinge_joints: Vec<usize>,
    pub open_joints: usize,
    pub max_displacement: f64,
    pub max_rotation: f64,
    pub motions: BTreeMap<String, [f64; 3]>,
}

/// Deterministic random numbers (SplitMix64), as in the CLI: a seed means the same samples.
struct SplitMix(u64);

impl SplitMix {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn normal(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
}

#[derive(Clone, Copy)]
enum Kind {
    Scale(usize),
    Direction(usize),
    Sample,
}

fn kind_of(kind: &str, n: usize) -> Result<Kind, Fail> {
    if n == 0 {
        return Err(Fail::Model(
            "the number of analyses must be at least 1".into(),
        ));
    }
    match kind {
        "steps" => Ok(Kind::Scale(n)),
        "directions" => Ok(Kind::Direction(n)),
        "samples" => Ok(Kind::Sample),
        k => Err(Fail::Model(format!(
            "sweep kind {k}: expected steps, directions or samples"
        ))),
    }
}

fn motions_of(
    kind: Kind,
    k: usize,
    base: &[[f64; 3]],
    cov: f64,
    seed: u64,
) -> (f64, Vec<[f64; 3]>) {
    match kind {
        Kind::Scale(n) => {
            let s = (k + 1) as f64 / n as f64;
            (
                s,
                base.iter()
                    .map(|m| [m[0] * s, m[1] * s, m[2] * s])
                    .collect(),
            )
        }
        Kind::Direction(n) => {
            let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            let (sn, cs) = a.sin_cos();
            (
                a.to_degrees(),
                base.iter()
                    .map(|m| [cs * m[0] - sn * m[1], sn * m[0] + cs * m[1], m[2]])
                    .collect(),
            )
        }
        Kind::Sample => {
            let mut rng = SplitMix(seed ^ (k as u64).wrapping_mul(0xD1B5_4A32_D192_ED03));
            let m = base
                .iter()
                .map(|m| {
                    let f = 1.0 + cov * rng.normal();
                    [m[0] * f, m[1] * f, m[2] * f]
                })
                .collect();
            (k as f64, m)
        }
    }
}

fn analyse(
    model: &Model,
    common: &Common,
    kind: Kind,
    k: usize,
    cov: f64,
    seed: u64,
) -> Result<SweepRecord, Fail> {
    let base: Vec<[f64; 3]> = model.supports.iter().map(|s| s.motion).collect();
    let (parameter, motions) = motions_of(kind, k, &base, cov, seed);
    let mut m = model.clone();
    for (s, mo) in m.supports.iter_mut().zip(&motions) {
        s.motion = *mo;
    }
    let st = Structure::new(
        &m,
        BuildOptions {
            tolerance: common.tolerance,
        },
    )?;
    let r = settle_with(&st, &common.solver()?, common.settlement_form()?)?;
    let max_displacement = r.blocks.iter().fold(0.0f64, |x, b| x.max(b.u.hypot(b.v)));
    let max_rotation = r.blocks.iter().fold(0.0f64, |x, b| x.max(b.theta.abs()));
    Ok(SweepRecord {
        index: k,
        kind: match kind {
            Kind::Scale(_) => "scale",
            Kind::Direction(_) => "angle_deg",
            Kind::Sample => "sample",
        }
        .into(),
        parameter,
        status: serde_json::to_value(r.status)
            .ok()
            .and_then(|v| v.as_str().map(String::from))
            .unwrap_or_default(),
        work_dead_loads: r.work_dead_loads,
        work_reactions: r.work_reactions,
        duality_gap: r.duality_gap,
        certified: r.certificate.as_ref().is_some_and(|c| c.ok),
        hinges: r.hinges.len(),
        hinge_joints: r.hinges.iter().map(|h| h.joint).collect(),
        open_joints: r
            .joints
            .iter()
            .filter(|j| j.state == JointState::Open)
            .count(),
        max_displacement,
        max_rotation,
        motions: m
            .supports
            .iter()
            .filter(|s| s.motion.iter().any(|x| *x != 0.0))
            .map(|s| (s.name.clone(), s.motion))
            .collect(),
    })
}

fn record_line(r: &SweepRecord) -> Result<String, Fail> {
    serde_json::to_string(r).map_err(|e| Fail::Model(format!("cannot serialise: {e}")))
}

/// Validate a sweep and return its base model (materials overridden, base motions applied) as
/// JSON: what every task starts from.
#[pyfunction]
pub fn sweep_base(
    py: Python<'_>,
    model: String,
    common: Common,
    settle: Settle,
    kind: String,
    n: usize,
    cov: f64,
) -> PyResult<String> {
    detached(py, || {
        kind_of(&kind, n)?;
        if !(cov.is_finite() && cov >= 0.0) {
            return Err(Fail::Model(format!(
                "cov={cov}: must be a finite number ≥ 0"
            )));
        }
        let m = common.model(&model, Some(&settle))?;
        if m.supports
            .iter()
            .all(|s| s.motion.iter().all(|x| *x == 0.0))
        {
            return Err(Fail::Model(
                "the sweep needs a base settlement: give move= or profile=".into(),
            ));
        }
        // Validate once before fanning out, so that a bad model fails with one message.
        Structure::new(
            &m,
            BuildOptions {
                tolerance: common.tolerance,
            },
        )?;
        common.solver()?;
        common.settlement_form()?;
        Ok(voussoir_io::files::to_json(&m)?)
    })
}

/// One task of a sweep: its record as one JSON line (no newline).
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
        let kind = kind_of(&kind, n)?;
        let m = voussoir_io::files::parse_model(&base)?;
        record_line(&analyse(&m, &common, kind, k, cov, seed)?)
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
        let kind = kind_of(&kind, n)?;
        let m = voussoir_io::files::parse_model(&base)?;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| Fail::Model(format!("cannot start worker threads: {e}")))?;
        let out: Vec<Result<String, Fail>> = pool.install(|| {
            tasks
                .par_iter()
                .map(|&k| record_line(&analyse(&m, &common, kind, k, cov, seed)?))
                .collect()
        });
        out.into_iter().collect()
    })
}

fn num(x: Option<f64>) -> String {
    x.map_or(String::new(), |v| format!("{v:e}"))
}

/// The CSV table of records given as JSON lines (the CLI's `voussoir sweep` CSV).
#[pyfunction]
pub fn sweep_csv(lines: Vec<String>) -> PyResult<String> {
    let mut s = String::from(
        "index,kind,parameter,status,work_dead_loads,work_reactions,duality_gap,certified,hinges,open_joints,max_displacement,max_rotation,hinge_joints\n",
    );
    for l in &lines {
        let r: SweepRecord =
            serde_json::from_str(l).map_err(|e| Fail::Model(format!("not a sweep record: {e}")))?;
        s.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{:e},{:e},{}\n",
            r.index,
            r.kind,
            r.parameter,
            r.status,
            num(r.work_dead_loads),
            num(r.work_reactions),
            num(r.duality_gap),
            r.certified,
            r.hinges,
            r.open_joints,
            r.max_displacement,
            r.max_rotation,
            r.hinge_joints
                .iter()
                .map(|j| j.to_string())
                .collect::<Vec<_>>()
                .join(" ")
        ));
    }
    Ok(s)
}
