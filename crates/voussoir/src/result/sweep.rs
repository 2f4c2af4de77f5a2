//! Records of a sweep ([`crate::sweep`]): one per analysis, and the distribution of the
//! capacity after the settlements of a capacity sweep.

use crate::error::Error;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

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
    /// The prescribed motion of every moving support: `[u, v, θ]` in 2D, `[u, v, w, θx, θy,
    /// θz]` in 3D (m, rad).
    pub motions: BTreeMap<String, Vec<f64>>,
    /// The solver and method that produced the analysis.
    pub solver: crate::lp::SolverInfo,
    /// The capacity after this settlement (sweeps with [`SweepSpec::capacity`] only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub capacity: Option<CapacityRecord>,
}

/// The capacity analysis after one settlement of a sweep: what `voussoir capacity` gives for the
/// same support motions.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct CapacityRecord {
    /// `curve` or `no_settlement_mechanism`, as in `voussoir capacity`.
    pub status: String,
    /// The settlement magnitude (m): the largest support translation (`null` if failed).
    pub max_settlement: Option<f64>,
    /// λ without settlement (the plain limit analysis) and after the whole settlement (the
    /// curve's last point); `null` if locked or without equilibrium.
    pub load_multiplier_before: Option<f64>,
    pub load_multiplier_after: Option<f64>,
    /// The settlement at which λ reaches 0 (m), `null` if not reached within this settlement.
    pub zero_capacity_settlement: Option<f64>,
    /// Whether limit analysis on the deformed geometry is valid at every step of the curve
    /// (the collapse mechanism closes no crack opened by the settlement), and at how many steps
    /// it is not.
    pub valid: bool,
    pub invalid_steps: usize,
    /// Whether it is valid at the last step (where `load_multiplier_after` is computed).
    pub valid_after: bool,
    /// Why the capacity analysis failed (status `failed`; every number is then `null`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

impl CapacityRecord {
    /// The record of a capacity analysis that failed with `e`.
    pub fn failed(e: &Error) -> CapacityRecord {
        CapacityRecord {
            status: "failed".into(),
            max_settlement: None,
            load_multiplier_before: None,
            load_multiplier_after: None,
            zero_capacity_settlement: None,
            valid: false,
            invalid_steps: 0,
            valid_after: false,
            error: Some(e.to_string()),
        }
    }
}

/// A quantile of a distribution.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Quantile {
    pub probability: f64,
    pub value: f64,
}

/// The distribution of the capacity after the settlements of a capacity sweep.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct CapacitySummary {
    /// Records with a capacity analysis, and among them those with a finite λ after the
    /// settlement (the distribution's sample).
    pub analyses: usize,
    pub with_load_multiplier: usize,
    /// λ without settlement (the same for every record of a sweep of one model).
    pub load_multiplier_before: Option<f64>,
    /// λ after the settlement: mean, least, largest and quantiles (at [`QUANTILES`]).
    pub mean: Option<f64>,
    pub min: Option<f64>,
    pub max: Option<f64>,
    pub quantiles: Vec<Quantile>,
    /// Records whose λ after the settlement is ≤ 0 (the settlement alone exhausts the
    /// capacity), and their fraction of `with_load_multiplier`.
    pub exhausted: usize,
    pub exhausted_fraction: Option<f64>,
    /// Records whose capacity curve is not valid at some step / at the last step (failed
    /// analyses included).
    pub invalid: usize,
    pub invalid_after: usize,
    /// Records whose capacity analysis failed (`status: failed`, with the error).
    pub failed: usize,
}

/// Quantile `p` in `[0, 1]` of sorted values: linear interpolation between order statistics
/// (Hyndman and Fan's definition 7, the default of R and NumPy).
pub fn quantile(sorted: &[f64], p: f64) -> Option<f64> {
    if sorted.is_empty() || !(0.0..=1.0).contains(&p) {
        return None;
    }
    let h = (sorted.len() - 1) as f64 * p;
    let (i, f) = (h.floor() as usize, h - h.floor());
    let next = sorted.get(i + 1).copied().unwrap_or(sorted[i]);
    Some(sorted[i] + f * (next - sorted[i]))
}

/// The probabilities at which [`capacity_summary`] gives quantiles.
pub const QUANTILES: [f64; 9] = [0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 0.95, 0.99];

/// Quantiles and counts of λ after the settlement over the records of a capacity sweep; `None`
/// if no record has a capacity analysis.
pub fn capacity_summary(records: &[SweepRecord]) -> Option<CapacitySummary> {
    let caps: Vec<&CapacityRecord> = records.iter().filter_map(|r| r.capacity.as_ref()).collect();
    if caps.is_empty() {
        return None;
    }
    let mut lam: Vec<f64> = caps
        .iter()
        .filter_map(|c| c.load_multiplier_after)
        .filter(|l| l.is_finite())
        .collect();
    lam.sort_by(f64::total_cmp);
    let n = lam.len();
    let quantiles: Vec<Quantile> = QUANTILES
        .iter()
        .filter_map(|&p| {
            quantile(&lam, p).map(|value| Quantile {
                probability: p,
                value,
            })
        })
        .collect();
    let exhausted = lam.iter().filter(|l| **l <= 0.0).count();
    Some(CapacitySummary {
        analyses: caps.len(),
        with_load_multiplier: n,
        load_multiplier_before: caps.iter().find_map(|c| c.load_multiplier_before),
        mean: (n > 0).then(|| lam.iter().sum::<f64>() / n as f64),
        min: lam.first().copied(),
        max: lam.last().copied(),
        quantiles,
        exhausted,
        exhausted_fraction: (n > 0).then_some(exhausted as f64 / n as f64),
        invalid: caps.iter().filter(|c| !c.valid).count(),
        invalid_after: caps.iter().filter(|c| !c.valid_after).count(),
        failed: caps.iter().filter(|c| c.error.is_some()).count(),
    })
}
