//! Result of a capacity analysis: the curve λ(s) and the zero-capacity settlement.

use super::limit::LimitStatus;
use super::Spatial;
use super::{BlockMotion, Hinge};
use crate::dim::Two;
use crate::lp::SolverInfo;
use serde::{Deserialize, Serialize};

/// One point of the capacity curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct CapacityPoint<D: Spatial = Two> {
    /// Settlement magnitude s (m).
    pub settlement: f64,
    /// λ(s): collapse multiplier on the deformed geometry; negative when the dead loads alone
    /// cannot be carried; `null` when locked or without any equilibrium.
    pub load_multiplier: Option<f64>,
    pub status: LimitStatus,
    /// False when the collapse mechanism closes points opened by the settlement (standard limit
    /// analysis is then not valid: use the incremental analysis).
    pub valid: bool,
    /// Joints with an open point that the collapse mechanism would close.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub closing_joints: Vec<usize>,
    /// Hinges of the collapse mechanism (positions on the deformed geometry).
    pub hinges: Vec<Hinge<D>>,
    /// Points of the model's existing cracks still open at this settlement (absent when the
    /// model has none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub existing_cracks_open: Option<usize>,
}

/// The collapse mechanism at one settlement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct CapacityMechanism<D: Spatial = Two> {
    pub settlement: f64,
    /// Block motion rates, normalised to unit work of the live loads.
    pub blocks: Vec<BlockMotion<D>>,
}

/// A support's motion per unit settlement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SupportDirection {
    pub support: String,
    /// `[u, v, θ]` per metre of settlement (θ in radians).
    pub motion: Vec<f64>,
}

/// Overall outcome.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CapacityStatus {
    /// The curve was computed.
    Curve,
    /// The settlement analysis found no mechanism (see the message): no curve.
    NoSettlementMechanism,
}

/// Result of a capacity analysis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct CapacityResult<D: Spatial = Two> {
    pub status: CapacityStatus,
    pub message: String,
    /// The solver and method that produced the result.
    pub solver: SolverInfo,
    /// Largest settlement (m, or rad for pure rotations).
    pub max_settlement: f64,
    /// Motion of each moving support per unit settlement.
    pub direction: Vec<SupportDirection>,
    /// `{settlement, load_multiplier, valid, …}` for s = 0 … max.
    pub curve: Vec<CapacityPoint<D>>,
    /// The settlement at which λ reaches 0 (`null` if λ does not change sign in the range).
    pub zero_capacity_settlement: Option<f64>,
    /// The settlement at which the last point of the model's existing cracks closes (to the
    /// root tolerance), when it happens within the range.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub existing_cracks_closed_at: Option<f64>,
    /// Least-squares line `λ ≈ intercept + slope·s` through the valid points with s > 0, and the
    /// largest deviation from it relative to λ(0) (a measure of linearity).
    pub linear_fit: Option<LinearFit>,
    /// Settlement mechanism per unit settlement and its hinges.
    pub settlement_mechanism: Vec<BlockMotion<D>>,
    pub settlement_hinges: Vec<Hinge<D>>,
    /// Collapse mechanism per step (empty unless requested).
    pub mechanisms: Vec<CapacityMechanism<D>>,
    /// LP solves and simplex iterations spent (curve and root finding).
    pub solves: usize,
    pub iterations: i64,
    /// The undeformed geometry.
    pub geometry: D::Shapes,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LinearFit {
    pub intercept: f64,
    pub slope: f64,
    pub max_relative_deviation: f64,
}
