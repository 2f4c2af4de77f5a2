//! The record of an adaptation of the crack lines ([`crate::analysis::adapt`], `--adapt`):
//! what was optimised, the value per iteration and the lines cut into the mesh.

use crate::model::Point;
use serde::{Deserialize, Serialize};

/// What the adaptation optimises.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Objective {
    /// The work of the dead loads of a settlement (maximised, as by the paper's program).
    SettlementWork,
    /// The collapse load multiplier λ (minimised).
    LoadMultiplier,
}

/// One iteration of the adaptation (0: the model as given).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AdaptIteration {
    pub iteration: usize,
    /// Blocks of the mesh solved.
    pub blocks: usize,
    /// Crack lines inserted.
    pub lines: usize,
    /// Work of the dead loads (kN·m) or load multiplier λ of the full solve.
    pub value: f64,
    /// Whether that solve is certified (duality gap within tolerance).
    pub certified: bool,
    /// Search solves of this iteration.
    pub evaluations: usize,
    /// The global stage (candidate lines from the outline's corners and the settling zone's
    /// ends, chosen greedily), not a local iteration; written only when true.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub global: bool,
    /// Wall-clock seconds from the start of the adaptation to the end of this iteration (in the
    /// summary only: the JSON stays byte-identical for the same input).
    #[serde(skip)]
    pub time: f64,
}

/// The record of an adaptation (the `adapt` field of an adapted result).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AdaptRecord {
    /// One sentence: what was done.
    pub method: String,
    pub objective: Objective,
    /// The relative change of the last two iterations was below `tolerance` (or no new crack
    /// line appeared).
    pub converged: bool,
    pub tolerance: f64,
    pub iterations: Vec<AdaptIteration>,
    /// The crack lines inserted, each from one point of the outline to another (m).
    pub lines: Vec<[Point; 2]>,
}

/// A result together with its adaptation record (serialised as the result's fields plus
/// `adapt`).
#[derive(Serialize)]
pub struct Adapted<'a, R: Serialize> {
    #[serde(flatten)]
    pub result: &'a R,
    pub adapt: &'a AdaptRecord,
}
