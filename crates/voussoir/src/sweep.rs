//! The sweep engine behind `voussoir sweep` and `voussoir merge`: many independent settlement
//! analyses of one model, in parallel.
//!
//! A sweep varies the prescribed support motions of one model:
//! * magnitudes: the base motions scaled by k/steps, k = 1 … steps;
//! * directions: the base motion vectors rotated through equally spaced angles: in 2D (u, v)
//!   in the plane (θ unchanged); in 3D the vertical x–z plane's components, (u, w) and
//!   (θx, θz), with v and θy unchanged — the 2D rotation of a model extruded along y
//!   ([`crate::generate3d`] maps 2D `[u, v, θ]` to 3D `[u, 0, v, 0, −θ, 0]`);
//! * Monte Carlo: random settlement fields: each support's motion times (1 + cov·ξ), ξ standard
//!   normal, independent per support, from a seed (one stream per sample, so a sample's numbers
//!   do not depend on sharding or threads).
//!
//! With [`SweepSpec::capacity`] every analysis is followed by the capacity analysis of the same
//! settlement ([`crate::analysis::capacity`]): λ after the settlement, the zero-capacity
//! settlement and the validity flag per record, so that a Monte Carlo of settlement fields gives
//! the distribution of the residual capacity ([`capacity_summary`]: quantiles).
//!
//! Each analysis is a rayon task with its own structure and solver, run on the caller's thread
//! pool; records come back ordered by task index whatever the order of completion. Front ends
//! (the command line, Python) parse their flags, pick the tasks (shards) and write the records.
//!
//! The engine is written once over [`Assembly`]: a 2D [`Structure`] or a 3D
//! [`crate::Structure3d`]; a support motion has `D::DOFS` components (`[u, v, θ]` in 2D,
//! `[u, v, w, θx, θy, θz]` in 3D), and so do the records' `motions`.

use crate::analysis::capacity::{capacity, CapacityOptions, CapacityStatus};
use crate::analysis::settlement::{settle_with, SettlementForm};
use crate::error::{Error, Result};
use crate::lp::SolverOptions;
use crate::result::spatial::SpatialMotion;
pub use crate::result::sweep::{
    capacity_summary, quantile, CapacityRecord, CapacitySummary, Quantile, SweepRecord, QUANTILES,
};
use crate::result::{JointState, PlanarMotion, Spatial};
use crate::structure::Assembly;
use crate::{BuildOptions, Model, Structure};
use rayon::prelude::*;

/// What a sweep varies, and how many analyses it has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SweepKind {
    /// The base motions scaled by k/count, k = 1 … count.
    Scale(usize),
    /// The base motion vectors rotated through `count` angles 360°·k/count (in 3D in the
    /// vertical x–z plane, about the y axis).
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
    /// Also run the capacity analysis after each settlement, with these options (their solver
    /// and canonical selection are replaced by `solver` and `canonical`); `None`: settlement
    /// analyses only.
    pub capacity: Option<CapacityOptions>,
    /// The canonical selection (docs/canonical.md) of each settlement's mechanism (and of the
    /// capacity curves' mechanisms): hinges and open joints that do not depend on the LP
    /// method; `None`: the solver's own. The mechanism stages only (the forces are the force
    /// program's: work and certificate unchanged).
    pub canonical: Option<crate::analysis::canonical::CanonicalOptions>,
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

/// A motion `[u, v, θ]` (2D) or `[u, v, w, θx, θy, θz]` (3D) rotated by the angle of sine `sn`
/// and cosine `cs`: in 2D (u, v) in the plane; in 3D (u, w) and (θx, θz) in the vertical x–z
/// plane (the rotation about −y, which is the 2D plane's of a model extruded along y).
fn rotated(m: &[f64], sn: f64, cs: f64) -> Vec<f64> {
    let mut r = m.to_vec();
    let pairs: &[(usize, usize)] = if m.len() == 6 {
        &[(0, 2), (3, 5)]
    } else {
        &[(0, 1)]
    };
    for &(a, b) in pairs {
        r[a] = cs * m[a] - sn * m[b];
        r[b] = sn * m[a] + cs * m[b];
    }
    r
}

/// The motions of task `k` from the base motions (one per support, `D::DOFS` values each).
pub fn motions_of(kind: &SweepKind, k: usize, base: &[Vec<f64>]) -> (f64, Vec<Vec<f64>>) {
    match *kind {
        SweepKind::Scale(n) => {
            let s = (k + 1) as f64 / n as f64;
            (
                s,
                base.iter()
                    .map(|m| m.iter().map(|x| x * s).collect())
                    .collect(),
            )
        }
        SweepKind::Direction(n) => {
            let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            let (sn, cs) = a.sin_cos();
            (
                a.to_degrees(),
                base.iter().map(|m| rotated(m, sn, cs)).collect(),
            )
        }
        SweepKind::Sample { cov, seed, .. } => {
            // One stream per sample: the sample's numbers do not depend on sharding or threads.
            let mut rng = SplitMix(seed ^ (k as u64).wrapping_mul(0xD1B5_4A32_D192_ED03));
            let m = base
                .iter()
                .map(|m| {
                    let f = 1.0 + cov * rng.normal();
                    m.iter().map(|x| x * f).collect()
                })
                .collect();
            (k as f64, m)
        }
    }
}

/// The sizes of a block motion a sweep record reports: its translation (m) and its rotation
/// (rad), each the Euclidean norm of its components.
pub trait MotionSize {
    fn translation(&self) -> f64;
    fn rotation(&self) -> f64;
}

impl MotionSize for PlanarMotion {
    fn translation(&self) -> f64 {
        self.u.hypot(self.v)
    }
    fn rotation(&self) -> f64 {
        self.theta.abs()
    }
}

impl MotionSize for SpatialMotion {
    fn translation(&self) -> f64 {
        (self.u * self.u + self.v * self.v + self.w * self.w).sqrt()
    }
    fn rotation(&self) -> f64 {
        (self.theta_x * self.theta_x + self.theta_y * self.theta_y + self.theta_z * self.theta_z)
            .sqrt()
    }
}

/// The base motions of a structure's supports (one per support, `D::DOFS` values each).
pub fn base_motions<S: Assembly>(st: &S) -> Vec<Vec<f64>> {
    (0..st.num_supports())
        .map(|s| st.support_motion(s).to_vec())
        .collect()
}

/// Analysis `k` of the sweep: the structure `st` with the motions of task `k` (from the base
/// motions `base`, one per support, [`base_motions`]).
pub fn analyse<S: Assembly>(
    st: &S,
    spec: &SweepSpec,
    k: usize,
    base: &[Vec<f64>],
) -> Result<SweepRecord>
where
    <S::D as Spatial>::Motion: MotionSize,
{
    let kind = &spec.kind;
    let (parameter, motions) = motions_of(kind, k, base);
    if motions.len() != st.num_supports() {
        return Err(Error::Request(format!(
            "{} base motions for {} supports",
            motions.len(),
            st.num_supports()
        )));
    }
    let mut st = st.clone();
    for (s, mo) in motions.iter().enumerate() {
        if mo.len() != <S::D as crate::dim::Dim>::DOFS {
            return Err(Error::Request(format!(
                "support '{}': a motion of {} values, expected {}",
                st.support_name(s),
                mo.len(),
                <S::D as crate::dim::Dim>::DOFS
            )));
        }
        if !mo.iter().all(|x| x.is_finite()) {
            return Err(Error::Request(format!(
                "support '{}': motion has a value that is not a finite number",
                st.support_name(s)
            )));
        }
        st.set_support_motion(s, mo);
    }
    let r = match &spec.canonical {
        Some(c) => crate::analysis::canonical::settle_canonical(&st, &spec.solver, spec.form, c)?,
        None => settle_with(&st, &spec.solver, spec.form)?,
    };
    // A capacity analysis that fails (a solver failure on one deformed geometry) is recorded
    // as such, so that one sample does not stop a Monte Carlo of hundreds.
    let capacity = spec.capacity.as_ref().map(|o| {
        let o = CapacityOptions {
            solver: spec.solver,
            canonical: spec.canonical,
            ..*o
        };
        capacity_record(&st, &o).unwrap_or_else(|e| CapacityRecord::failed(&e))
    });
    let max_displacement = r
        .blocks
        .iter()
        .fold(0.0f64, |x, b| x.max(b.motion.translation()));
    let max_rotation = r
        .blocks
        .iter()
        .fold(0.0f64, |x, b| x.max(b.motion.rotation()));
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
        motions: motions
            .iter()
            .enumerate()
            .filter(|(_, m)| m.iter().any(|x| *x != 0.0))
            .map(|(s, m)| (st.support_name(s).to_string(), m.clone()))
            .collect(),
        solver: r.solver.clone(),
        capacity,
    })
}

/// The capacity analysis of `st` (its supports carrying the settlement) as a sweep record.
pub fn capacity_record<S: Assembly>(st: &S, opts: &CapacityOptions) -> Result<CapacityRecord> {
    let c = capacity(st, opts)?;
    let invalid_steps = c.curve.iter().filter(|p| !p.valid).count();
    Ok(CapacityRecord {
        status: match c.status {
            CapacityStatus::Curve => "curve",
            CapacityStatus::NoSettlementMechanism => "no_settlement_mechanism",
        }
        .to_string(),
        max_settlement: Some(c.max_settlement),
        load_multiplier_before: c.curve.first().and_then(|p| p.load_multiplier),
        load_multiplier_after: c.curve.last().and_then(|p| p.load_multiplier),
        zero_capacity_settlement: c.zero_capacity_settlement,
        valid: invalid_steps == 0 && !c.curve.is_empty(),
        invalid_steps,
        valid_after: c.curve.last().is_some_and(|p| p.valid),
        error: None,
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

/// Check a sweep before any work: its size, its numbers, its tasks (indices below
/// `spec.kind.count()`) and that its base motions (one per support) move something.
pub fn check(spec: &SweepSpec, tasks: &[usize], base: &[Vec<f64>]) -> Result<()> {
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
    if base.iter().all(|m| m.iter().all(|x| *x == 0.0)) {
        return Err(Error::Request(
            "the sweep needs a base settlement: no support has a prescribed motion".into(),
        ));
    }
    Ok(())
}

/// Run the tasks `tasks` (indices below `spec.kind.count()`) of a 2D model's sweep in parallel
/// on the current rayon pool, calling `progress` after each; the records come back sorted by
/// index. The model is validated once first, so that a bad model fails with one message.
pub fn run(
    model: &Model,
    spec: &SweepSpec,
    tasks: &[usize],
    progress: &(dyn Fn() + Sync),
) -> Result<Vec<SweepRecord>> {
    let base: Vec<Vec<f64>> = model.supports.iter().map(|s| s.motion.to_vec()).collect();
    check(spec, tasks, &base)?;
    let st = Structure::new(model, spec.build)?;
    run_assembly(&st, spec, tasks, progress)
}

/// [`run`] on a structure of either dimension whose supports carry the base motions (a 3D
/// structure with its friction pyramid as the caller wants it).
pub fn run_assembly<S: Assembly>(
    st: &S,
    spec: &SweepSpec,
    tasks: &[usize],
    progress: &(dyn Fn() + Sync),
) -> Result<Vec<SweepRecord>>
where
    <S::D as Spatial>::Motion: MotionSize,
{
    let base = base_motions(st);
    check(spec, tasks, &base)?;
    if spec.capacity.is_some() && !st.has_live_loads() {
        return Err(Error::Request(
            "a capacity sweep needs live loads (the model has none): λ is their multiplier".into(),
        ));
    }
    let results: Vec<Result<SweepRecord>> = tasks
        .par_iter()
        .map(|&k| {
            let r = analyse(st, spec, k, &base);
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

/// The CSV table of records; with capacity records, their columns follow (`capacity_status`,
/// `max_settlement`, `lambda_before`, `lambda_after`, `zero_capacity_settlement`,
/// `capacity_valid`, `invalid_steps`, `valid_after`).
pub fn csv(records: &[SweepRecord]) -> String {
    let with_capacity = records.iter().any(|r| r.capacity.is_some());
    let mut s = String::from(
        "index,kind,parameter,status,work_dead_loads,work_reactions,duality_gap,certified,hinges,open_joints,max_displacement,max_rotation,hinge_joints",
    );
    if with_capacity {
        s.push_str(",capacity_status,max_settlement,lambda_before,lambda_after,zero_capacity_settlement,capacity_valid,invalid_steps,valid_after");
    }
    s.push('\n');
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
        if with_capacity {
            s.pop();
            match &r.capacity {
                Some(c) => s.push_str(&format!(
                    ",{},{},{},{},{},{},{},{}",
                    c.status,
                    num(c.max_settlement),
                    num(c.load_multiplier_before),
                    num(c.load_multiplier_after),
                    num(c.zero_capacity_settlement),
                    c.valid,
                    c.invalid_steps,
                    c.valid_after
                )),
                None => s.push_str(",,,,,,,,"),
            }
            s.push('\n');
        }
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
