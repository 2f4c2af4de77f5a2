//! Result of an incremental analysis: λ against the control displacement, events, snapshots.

use super::{BlockMotion, Hinge, Spatial};
use crate::dim::{Dim, Two};
use crate::lp::SolverInfo;
use serde::{Deserialize, Serialize};

/// The control point: a point of a block (in the start geometry) and a direction, `[x, y]` in
/// 2D and `[x, y, z]` in 3D.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Control<D: Spatial = Two> {
    pub block: usize,
    pub point: <D as Dim>::Vector,
    /// Unit direction along which the control displacement is measured.
    pub direction: <D as Dim>::Vector,
}

/// Why the analysis stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum IncrementalStatus {
    /// λ fell to zero after its peak: the structure can no longer carry its own weight.
    Collapsed,
    /// The maximum control displacement was reached.
    MaxDisplacement,
    /// The step cap was reached.
    MaxSteps,
    /// No finite collapse load on the current geometry.
    Locked,
    /// No equilibrium for any λ on the current geometry.
    NoEquilibrium,
    /// The mechanism does not move the control point along the control direction.
    ControlStill,
}

/// A point of the curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct IncrementalPoint {
    /// Step at which the point was computed.
    pub step: usize,
    /// Control displacement along the direction (m).
    pub displacement: f64,
    /// Live load needed: max(λ, 0).
    pub load_multiplier: f64,
    /// λ by virtual work (negative: the dead loads alone drive the mechanism).
    pub equilibrium_multiplier: f64,
    /// Evaluated at the end of a step in which a point closed, with the point still open: the
    /// value just before the jump (the next point, at the same displacement, is just after).
    #[serde(default, skip_serializing_if = "is_false")]
    pub before_closure: bool,
}

fn is_false(b: &bool) -> bool {
    !*b
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EventKind {
    /// A point in contact opened (a crack or hinge forms).
    Opened,
    /// An open point closed and carries force again.
    Closed,
}

/// A change of contact at a point.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Event {
    pub step: usize,
    pub displacement: f64,
    pub kind: EventKind,
    pub joint: usize,
    /// Index of the point in its joint.
    pub point: usize,
    pub x: f64,
    pub y: f64,
    /// The point's `z` (3D models; absent in 2D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z: Option<f64>,
}

/// The mechanism at one step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Snapshot<D: Spatial = Two> {
    pub step: usize,
    pub displacement: f64,
    pub load_multiplier: f64,
    /// Block motion rates per unit control displacement.
    pub blocks: Vec<BlockMotion<D>>,
    /// Joints with an open point, at their point in contact.
    pub hinges: Vec<Hinge<D>>,
    /// The current geometry.
    pub geometry: D::Shapes,
}

/// Result of an incremental analysis (2D or 3D: the control point, the snapshots' motions, the
/// cracks and the geometries are those of the model's dimension).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct IncrementalResult<D: Spatial = Two> {
    pub status: IncrementalStatus,
    pub message: String,
    /// The solver and method that produced the result.
    pub solver: SolverInfo,
    pub control: Control<D>,
    /// `{displacement, load_multiplier, …}` in the order computed.
    pub curve: Vec<IncrementalPoint>,
    pub events: Vec<Event>,
    pub snapshots: Vec<Snapshot<D>>,
    pub peak_load_multiplier: f64,
    pub peak_displacement: f64,
    /// Joints open at the start (e.g. opened by a settlement).
    pub initial_open_joints: Vec<usize>,
    /// The cracks of the final state: the open points of the final geometry, widths their gaps
    /// (m) ([`super::cracks`]): polylines in 2D, one record per cracked joint (or coplanar set)
    /// in 3D.
    #[serde(default)]
    pub cracks: Vec<D::Crack>,
    pub steps: usize,
    /// Steps without equilibrium for any λ in which the dead loads alone moved the structure
    /// until an open point closed (a hinge moving to the next joint); they add no curve point.
    pub snaps: usize,
    pub solves: usize,
    pub iterations: i64,
    /// Geometry at the start and at the end.
    pub initial_geometry: D::Shapes,
    pub final_geometry: D::Shapes,
    /// The canonical selection (docs/canonical.md): how the settlement mechanism and the
    /// steps' collapse mechanisms were selected; absent without it (`raw`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub canonical: Option<IncrementalCanonical>,
}

/// The canonical selection of an incremental analysis (docs/canonical.md): the settlement
/// mechanism of a settlement run first (which sets the starting geometry and its cracks) is the
/// canonical one, so that it does not depend on the LP method; with `steps`, every step's
/// collapse mechanism too (the motion that moves the structure: the path, its hinges, events
/// and cracks). λ is the solver's (the selection only picks among the optimal mechanisms).
/// Steps in which the dead loads alone move the structure (`snaps`) follow the ray of their
/// own program, not selected.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct IncrementalCanonical {
    /// How the settlement mechanism was selected (absent: no settlement, or its selection was
    /// not reached, `settlement_not_reached`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub settlement: Option<super::canonical::CanonicalMechanism>,
    /// A settlement ran first and its selection was not reached: the solver's own mechanism
    /// settled the structure.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub settlement_not_reached: bool,
    /// The steps' collapse mechanisms (where the selection was not reached, the solver's
    /// mechanism moved the structure); `solves` includes the settlement's.
    #[serde(flatten)]
    pub selection: super::canonical::StepSelection,
}
