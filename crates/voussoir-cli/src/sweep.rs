//! `voussoir sweep` and `voussoir merge`: many independent settlement analyses in parallel.
//!
//! A sweep varies the prescribed support motions of one model:
//! * magnitudes: the motions given by `--move`/`--profile` scaled by k/steps, k = 1 … steps;
//! * directions: the `--move` vectors rotated through `--directions` equally spaced angles;
//! * Monte Carlo: `--samples` random settlement fields: each support's motion from the profile
//!   times (1 + cov·ξ), ξ standard normal, independent per support, from `--seed`.
//!
//! Each analysis is a task for rayon with its own structure and solver. Results are written as
//! JSON lines (one object per analysis) and as a CSV table, ordered by task index whatever the
//! order of completion. `--shard i/n` runs only the tasks with index ≡ i (mod n), so that an
//! array job can split a sweep; `voussoir merge` joins the shards' JSON lines.

use crate::common::{Fail, SettleArgs, SettleModelArgs};
use clap::Args;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::io::IsTerminal;
use std::path::PathBuf;
use voussoir::analysis::settlement::settle_with;
use voussoir::result::JointState;
use voussoir::{BuildOptions, Model, Structure};

#[derive(Args)]
pub struct SweepArgs {
    /// The base settlement: moves, fixed supports, profile (as for `settle`).
    #[command(flatten)]
    pub settle: SettleArgs,
    /// Magnitude sweep: the base motions scaled by k/STEPS, k = 1 … STEPS.
    #[arg(long, value_name = "STEPS")]
    pub steps: Option<usize>,
    /// Direction sweep: the `--move` vectors (u, v) rotated through N angles 360°·k/N.
    #[arg(long, value_name = "N")]
    pub directions: Option<usize>,
    /// Monte Carlo: N random settlement fields around the base motions.
    #[arg(long, value_name = "N")]
    pub samples: Option<usize>,
    /// Monte Carlo: coefficient of variation of each support's motion (dimensionless).
    #[arg(long, default_value_t = 0.3, value_name = "COV")]
    pub cov: f64,
    /// Monte Carlo: random seed (the same seed gives the same samples on any machine).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Run only the tasks with index ≡ I (mod N): `--shard I/N`, I from 0.
    #[arg(long, value_name = "I/N")]
    pub shard: Option<String>,
    /// Worker threads (default: one per core).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Model input, DXF import, solver, and --settlement-form.
    #[command(flatten)]
    pub model: SettleModelArgs,
    /// Write the results as JSON lines here (one analysis per line; lengths in m).
    #[arg(long, value_name = "FILE", help_heading = "Output")]
    pub jsonl: Option<PathBuf>,
    /// Write the results as a CSV table here (default: stdout when no --jsonl is given).
    #[arg(long, value_name = "FILE", help_heading = "Output")]
    pub csv: Option<PathBuf>,
}

#[derive(Args)]
pub struct MergeArgs {
    /// Shard results (JSON lines) to merge.
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// Merged JSON lines.
    #[arg(long, value_name = "FILE")]
    pub jsonl: Option<PathBuf>,
    /// Merged CSV table (default: stdout when no --jsonl is given).
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
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

enum Kind {
    Scale(usize),
    Direction(usize),
    Sample(usize),
}

fn parse_shard(s: &str) -> Result<(usize, usize), Fail> {
    let bad = || Fail(format!("--shard {s}: expected I/N with 0 ≤ I < N"));
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    let (i, n): (usize, usize) = (
        i.trim().parse().map_err(|_| bad())?,
        n.trim().parse().map_err(|_| bad())?,
    );
    if n == 0 || i >= n {
        return Err(bad());
    }
    Ok((i, n))
}

/// The motions of task `k` from the base motions.
fn motions_of(
    kind: &Kind,
    k: usize,
    base: &[[f64; 3]],
    cov: f64,
    seed: u64,
) -> (f64, Vec<[f64; 3]>) {
    match *kind {
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
        Kind::Sample(_) => {
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

fn analyse(
    model: &Model,
    a: &SweepArgs,
    kind: &Kind,
    k: usize,
    base: &[[f64; 3]],
) -> Result<SweepRecord, Fail> {
    let (parameter, motions) = motions_of(kind, k, base, a.cov, a.seed);
    let mut m = model.clone();
    for (s, mo) in m.supports.iter_mut().zip(&motions) {
        s.motion = *mo;
    }
    let st = Structure::new(
        &m,
        BuildOptions {
            tolerance: a.model.tolerance,
        },
    )?;
    let opts = a.model.solver();
    let r = settle_with(&st, &opts, a.model.settlement_form())?;
    let max_displacement = r.blocks.iter().fold(0.0f64, |x, b| x.max(b.u.hypot(b.v)));
    let max_rotation = r.blocks.iter().fold(0.0f64, |x, b| x.max(b.theta.abs()));
    Ok(SweepRecord {
        index: k,
        kind: match kind {
            Kind::Scale(_) => "scale",
            Kind::Direction(_) => "angle_deg",
            Kind::Sample(_) => "sample",
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

fn jsonl(records: &[SweepRecord]) -> Result<String, Fail> {
    let mut s = String::new();
    for r in records {
        s.push_str(&serde_json::to_string(r).map_err(|e| Fail(format!("cannot serialise: {e}")))?);
        s.push('\n');
    }
    Ok(s)
}

fn write_outputs(
    records: &[SweepRecord],
    jl: &Option<PathBuf>,
    cv: &Option<PathBuf>,
) -> Result<(), Fail> {
    if let Some(p) = jl {
        voussoir_io::write_atomic(p, jsonl(records)?.as_bytes())?;
    }
    match cv {
        Some(p) => voussoir_io::write_atomic(p, csv(records).as_bytes())?,
        None if jl.is_none() => print!("{}", csv(records)),
        None => {}
    }
    Ok(())
}

pub fn run(a: SweepArgs) -> Result<(), Fail> {
    // Flags resolved before any work (a DXF flag on a JSON model, bad numbers).
    a.model.resolve()?;
    let modes = [
        a.steps.is_some(),
        a.directions.is_some(),
        a.samples.is_some(),
    ]
    .iter()
    .filter(|x| **x)
    .count();
    if modes != 1 {
        return Err(Fail(
            "give exactly one of --steps, --directions, --samples".into(),
        ));
    }
    let kind = match (a.steps, a.directions, a.samples) {
        (Some(n), _, _) => Kind::Scale(n),
        (_, Some(n), _) => Kind::Direction(n),
        (_, _, Some(n)) => Kind::Sample(n),
        _ => unreachable!("exactly one mode"),
    };
    let n = match kind {
        Kind::Scale(n) | Kind::Direction(n) | Kind::Sample(n) => n,
    };
    if n == 0 {
        return Err(Fail("the number of analyses must be at least 1".into()));
    }
    if !(a.cov.is_finite() && a.cov >= 0.0) {
        return Err(Fail(format!(
            "--cov {}: must be a finite number ≥ 0",
            a.cov
        )));
    }
    let (mut model, _) = a.model.dxf.read(&a.model.model)?;
    a.model.override_materials(&mut model)?;
    a.settle.apply(&mut model)?;
    let base: Vec<[f64; 3]> = model.supports.iter().map(|s| s.motion).collect();
    if base.iter().all(|m| m.iter().all(|x| *x == 0.0)) {
        return Err(Fail(
            "the sweep needs a base settlement: give --move or --profile".into(),
        ));
    }
    // Validate once before fanning out, so that a bad model fails with one message.
    Structure::new(
        &model,
        BuildOptions {
            tolerance: a.model.tolerance,
        },
    )?;
    let (shard, shards) = match &a.shard {
        Some(s) => parse_shard(s)?,
        None => (0, 1),
    };
    let tasks: Vec<usize> = (0..n).filter(|k| k % shards == shard).collect();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(a.threads.unwrap_or(0))
        .build()
        .map_err(|e| Fail(format!("cannot start worker threads: {e}")))?;
    let bar = if std::io::stderr().is_terminal() {
        let b = indicatif::ProgressBar::new(tasks.len() as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{bar:40} {pos}/{len} analyses, {elapsed} elapsed, ETA {eta}",
        ) {
            b.set_style(style);
        }
        Some(b)
    } else {
        None
    };
    let results: Vec<Result<SweepRecord, Fail>> = pool.install(|| {
        tasks
            .par_iter()
            .map(|&k| {
                let r = analyse(&model, &a, &kind, k, &base);
                if let Some(b) = &bar {
                    b.inc(1);
                }
                r
            })
            .collect()
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let mut records = Vec::with_capacity(results.len());
    for r in results {
        records.push(r?);
    }
    records.sort_by_key(|r| r.index);
    write_outputs(&records, &a.jsonl, &a.csv)?;
    let certified = records.iter().filter(|r| r.certified).count();
    eprintln!(
        "{} analyses (shard {}/{} of {n}) on {} threads; {certified} certified",
        records.len(),
        shard,
        shards,
        pool.current_num_threads()
    );
    Ok(())
}

pub fn merge(a: MergeArgs) -> Result<(), Fail> {
    let mut records: Vec<SweepRecord> = Vec::new();
    for p in &a.inputs {
        let text = std::fs::read_to_string(p)
            .map_err(|e| Fail(format!("cannot read {}: {e}", p.display())))?;
        for (i, line) in text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty())
        {
            let r: SweepRecord = serde_json::from_str(line).map_err(|e| {
                Fail(format!(
                    "{}:{}: not a sweep record: {e}",
                    p.display(),
                    i + 1
                ))
            })?;
            records.push(r);
        }
    }
    records.sort_by_key(|r| r.index);
    if let Some(w) = records.windows(2).find(|w| w[0].index == w[1].index) {
        return Err(Fail(format!(
            "task {} appears in more than one shard",
            w[0].index
        )));
    }
    if let Some(last) = records.last() {
        let missing = last.index + 1 - records.len();
        if missing > 0 {
            eprintln!(
                "warning: {missing} task(s) below index {} are missing",
                last.index
            );
        }
    }
    write_outputs(&records, &a.jsonl, &a.csv)?;
    eprintln!(
        "merged {} records from {} file(s)",
        records.len(),
        a.inputs.len()
    );
    Ok(())
}
