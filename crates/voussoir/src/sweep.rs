//! The sweep engine behind `voussoir sweep` and `voussoir merge`: many independent settlement
//! analyses of one model, in parallel.
//!
//! A sweep varies the prescribed support motions of one model:
//! * magnitudes: the base motions scaled by k/steps, k = 1 … steps;
//! * directions: the base motion vectors (u, v) rotated through equally spaced angles;
//! * Monte Carlo: random settlement fields: each support's motion times (1 + cov·ξ), ξ standard
//!   normal, independent per support, from a seed (one stream per sample, so a sample's numbers
//!   do not depend on sharding or threads).
//!
//! Each analysis is a rayon task with its own structure and solver, run on the caller's thread
//! pool; records come back ordered by task index whatever the order of completion. Front ends
//! (the command line, Python) parse their flags, pick the tasks (shards) and write the records.

use crate::analysis::settlement::{settle_with, SettlementForm};
use crate::error::{Error, Result};
use crate::lp::SolverOptions;
use crate::result::JointState;
use crate::{BuildOptions, Model, Structure};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// What a sweep varies, and how many analyses it has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SweepKind {
    /// The base motions scaled by k/count, k = 1 … count.
    Scale(usize),
    /// The base motion vectors rotated through `count` angles 360°·k/count.
    Direction(usize),
    /// `count` random fields with coefficient of variation `cov` from `seed`.
    Sample { count: usize, cov: f64, seed: u64 },
}

impl SweepKind {
    /// Number of analyses.
    pub fn count(&self) -> usize {
        match *self {
            SweepKind::Scale(n) | SweepKind::Direction(n) => n,
            SweepKind::Sample { count, .. } => count,
        }
    }
    fn name(&self) -> &'static str {
        match self {
            SweepKind::Scale(_) => "scale",
            SweepKind::Direction(_) => "angle_deg",
            SweepKind::Sample { .. } => "sample",
        }
    }
}

/// Everything a sweep's analyses share.
#[derive(Clone, Copy, Debug)]
pub struct SweepSpec {
    pub kind: SweepKind,
    pub build: BuildOptions,
    pub solver: SolverOptions,
    pub form: SettlementForm,
}

/// One analysis of a sweep.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SweepRecord {
    pub index: usize,
    /// What varies: "scale", "angle_deg" or "sample".
    pub kind: String,
    /// The scale factor, the angle in degrees, or the sample number.
    pub parameter: f64,
    pub status: String,
    pub work_dead_loads: Option<f64>,
    pub work_reactions: Option<f64>,
    pub duality_gap: Option<f64>,
    pub certified: bool,
    pub hinges: usize,
    pub hinge_joints: Vec<usize>,
    pub open_joints: usize,
    /// Largest block translation (m) and rotation (rad).
    pub max_displacement: f64,
    pub max_rotation: f64,
    /// The prescribed motion of every moving support, `[u, v, θ]`.
    pub motions: BTreeMap<String, [f64; 3]>,
    /// The solver and method that produced the analysis.
    pub solver: crate::lp::SolverInfo,
}

/// Deterministic random numbers (SplitMix64), so that a seed means the same samples everywhere.
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

/// The motions of task `k` from the base motions.
pub fn motions_of(kind: &SweepKind, k: usize, base: &[[f64; 3]]) -> (f64, Vec<[f64; 3]>) {
    match *kind {
        SweepKind::Scale(n) => {
            let s = (k + 1) as f64 / n as f64;
            (
                s,
                base.iter()
                    .map(|m| [m[0] * s, m[1] * s, m[2] * s])
                    .collect(),
            )
        }
        SweepKind::Direction(n) => {
            let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            let (sn, cs) = a.sin_cos();
            (
                a.to_degrees(),
                base.iter()
                    .map(|m| [cs * m[0] - sn * m[1], sn * m[0] + cs * m[1], m[2]])
                    .collect(),
            )
        }
        SweepKind::Sample { cov, seed, .. } => {
            // One stream per sample: the sample's numbers do not depend on sharding or threads.
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

/// Analysis `k` of the sweep: the model with the motions of task `k` (from the base motions
/// `base`, one per support).
pub fn analyse(
    model: &Model,
    spec: &SweepSpec,
    k: usize,
    base: &[[f64; 3]],
) -> Result<SweepRecord> {
    let kind = &spec.kind;
    let (parameter, motions) = motions_of(kind, k, base);
    let mut m = model.clone();
    for (s, mo) in m.supports.iter_mut().zip(&motions) {
        s.motion = *mo;
    }
    let st = Structure::new(&m, spec.build)?;
    let r = settle_with(&st, &spec.solver, spec.form)?;
    let max_displacement = r.blocks.iter().fold(0.0f64, |x, b| x.max(b.u.hypot(b.v)));
    let max_rotation = r.blocks.iter().fold(0.0f64, |x, b| x.max(b.theta.abs()));
    Ok(SweepRecord {
        index: k,
        kind: kind.name().into(),
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
        solver: r.solver.clone(),
    })
}

/// Most analyses one run (one shard) of a sweep takes: its records are kept in memory (about
/// 1 kB each, more with many hinges), so a million is about a gigabyte. Larger sweeps are split
/// with `--shard I/N` (array jobs) and merged.
pub const MAX_ANALYSES_PER_RUN: usize = 1_000_000;

/// Most analyses a sweep may have in all (its shards together).
pub const MAX_ANALYSES: usize = 1_000_000_000;

/// Refuse, before any work, a sweep of `count` analyses whose runs (`shards` of them) would
/// take more than [`MAX_ANALYSES_PER_RUN`] each, or that has more than [`MAX_ANALYSES`].
pub fn check_size(count: usize, shards: usize) -> Result<()> {
    if count == 0 {
        return Err(Error::Request(
            "the number of analyses must be at least 1".into(),
        ));
    }
    if count > MAX_ANALYSES {
        return Err(Error::Request(format!(
            "{count} analyses: a sweep has at most {MAX_ANALYSES}"
        )));
    }
    let per_run = count.div_ceil(shards.max(1));
    if per_run > MAX_ANALYSES_PER_RUN {
        return Err(Error::Request(format!(
            "{count} analyses in {} run(s): at most {MAX_ANALYSES_PER_RUN} per run (their results are kept in memory); split it with --shard I/N (at least {} shards)",
            shards.max(1),
            count.div_ceil(MAX_ANALYSES_PER_RUN)
        )));
    }
    Ok(())
}

/// Run the tasks `tasks` (indices below `spec.kind.count()`) in parallel on the current rayon
/// pool, calling `progress` after each; the records come back sorted by index. The model is
/// validated once first, so that a bad model fails with one message.
pub fn run(
    model: &Model,
    spec: &SweepSpec,
    tasks: &[usize],
    progress: &(dyn Fn() + Sync),
) -> Result<Vec<SweepRecord>> {
    let n = spec.kind.count();
    check_size(n, n.div_ceil(tasks.len().max(1)))?;
    if let SweepKind::Sample { cov, .. } = spec.kind {
        if !(cov.is_finite() && cov >= 0.0) {
            return Err(Error::Request(format!(
                "cov {cov}: must be a finite number ≥ 0"
            )));
        }
    }
    if let Some(k) = tasks.iter().find(|&&k| k >= n) {
        return Err(Error::Request(format!(
            "task {k} is beyond the sweep's {n} analyses"
        )));
    }
    let base: Vec<[f64; 3]> = model.supports.iter().map(|s| s.motion).collect();
    if base.iter().all(|m| m.iter().all(|x| *x == 0.0)) {
        return Err(Error::Request(
            "the sweep needs a base settlement: no support has a prescribed motion".into(),
        ));
    }
    Structure::new(model, spec.build)?;
    let results: Vec<Result<SweepRecord>> = tasks
        .par_iter()
        .map(|&k| {
            let r = analyse(model, spec, k, &base);
            progress();
            r
        })
        .collect();
    let mut records = Vec::with_capacity(results.len());
    for r in results {
        records.push(r?);
    }
    records.sort_by_key(|r| r.index);
    Ok(records)
}

/// The tasks of shard `shard` of `shards`: indices ≡ shard (mod shards).
pub fn shard_tasks(count: usize, shard: usize, shards: usize) -> Vec<usize> {
    (0..count).filter(|k| k % shards.max(1) == shard).collect()
}

/// Merge shards' records: sorted by index; an error if an index appears twice; the number of
/// indices missing below the largest.
pub fn merge(mut records: Vec<SweepRecord>) -> Result<(Vec<SweepRecord>, usize)> {
    records.sort_by_key(|r| r.index);
    if let Some(w) = records.windows(2).find(|w| w[0].index == w[1].index) {
        return Err(Error::Request(format!(
            "task {} appears in more than one shard",
            w[0].index
        )));
    }
    let missing = records.last().map_or(0, |l| l.index + 1 - records.len());
    Ok((records, missing))
}

fn num(x: Option<f64>) -> String {
    x.map_or(String::new(), |v| format!("{v:e}"))
}

/// The CSV table of records.
pub fn csv(records: &[SweepRecord]) -> String {
    let mut s = String::from(
        "index,kind,parameter,status,work_dead_loads,work_reactions,duality_gap,certified,hinges,open_joints,max_displacement,max_rotation,hinge_joints\n",
    );
    for r in records {
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
    s
}

/// The records as JSON lines.
pub fn jsonl(records: &[SweepRecord]) -> Result<String> {
    let mut s = String::new();
    for r in records {
        s.push_str(
            &serde_json::to_string(r)
                .map_err(|e| Error::Request(format!("cannot serialise: {e}")))?,
        );
        s.push('\n');
    }
    Ok(s)
}
