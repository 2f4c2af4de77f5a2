//! Typed results: one submodule per analysis ([`limit`], [`settlement`], [`capacity`],
//! [`incremental`], [`tilt`], [`nonassociative`], [`safety`] with least thickness, [`identify`],
//! [`sweep`], [`canonical`]) over the pieces they share here — block
//! motions, joints with their points, hinges, the thrust line and support reactions. Every
//! result serialises to the JSON the CLI prints. Drawings and other front ends read results
//! from this module only, never from the algorithms in [`crate::analysis`].

pub mod adapt;
pub mod canonical;
pub mod capacity;
pub mod cracks;
pub mod identify;
pub mod incremental;
pub mod limit;
pub mod nonassociative;
pub mod safety;
pub mod settlement;
pub mod sweep;
pub mod tilt;

pub use adapt::{AdaptIteration, AdaptRecord, Adapted, Objective};
pub use canonical::*;
pub use capacity::*;
pub use cracks::{Crack, Crack3d, CrackEnd, CrackFront, CrackGeometry, CrackText};
pub use incremental::*;
pub use limit::*;
pub use nonassociative::*;
pub use safety::*;
pub use settlement::*;
pub use sweep::*;
pub use tilt::*;

pub mod spatial;

pub use spatial::{PlanarMotion, PlanarPoint, PlanarWrench, Spatial};

use crate::dim::Two;
use serde::{Deserialize, Serialize};

/// A body as named in results: a block index (number) or a support name (string).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum BodyName {
    Block(usize),
    Support(String),
}

/// The non-associative friction iteration behind a result (absent with associative friction).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrictionIteration {
    /// The value with associative friction (dilatant sliding): λ, or the settlement work.
    pub associative: Option<f64>,
    /// The value per iteration (λ, or the work of the dead loads less the sliding dissipation).
    pub history: Vec<f64>,
    pub converged: bool,
}

impl FrictionIteration {
    /// The iteration attached to a result: `message` (the result's summary line) starts with a
    /// warning when the iteration did not converge, and the record goes in `slot`.
    pub fn attach(self, message: &mut String, slot: &mut Option<FrictionIteration>) {
        if !self.converged {
            *message = format!(
                "WARNING: the non-associative friction iteration did not converge in {} iterations (the last iterate is reported); {}",
                self.history.len(),
                message
            );
        }
        *slot = Some(self);
    }
}

/// Generic result types deref to their components, so that `block.u` or `hinge.x` read as
/// fields in every dimension.
macro_rules! deref_to {
    ($t:ident, $field:ident, $target:ident) => {
        impl<D: Spatial> std::ops::Deref for $t<D> {
            type Target = D::$target;
            fn deref(&self) -> &D::$target {
                &self.$field
            }
        }
    };
}

/// Motion of a block's centroid: translation (m, or per unit of the normalisation) and rotation
/// (rad; counter-clockwise in 2D, a rotation vector in 3D).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct BlockMotion<D: Spatial = Two> {
    pub id: usize,
    #[serde(flatten)]
    pub motion: D::Motion,
}
deref_to!(BlockMotion, motion, Motion);

impl BlockMotion<Two> {
    pub fn planar(id: usize, u: f64, v: f64, theta: f64) -> Self {
        BlockMotion {
            id,
            motion: PlanarMotion { u, v, theta },
        }
    }
}

/// A collocation point: position, opening (≥ 0), sliding, compressive normal force (kN, ≥ 0
/// except on fixed supports) and shear force (kN, along the joint's tangent; one value per
/// tangent in 3D).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct PointResult<D: Spatial = Two> {
    #[serde(flatten)]
    pub position: D::Position,
    pub opening: f64,
    pub sliding: D::Tangential,
    pub normal_force: f64,
    pub shear_force: D::Tangential,
    /// Gap before the analysis (only after deformation; 0 otherwise).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub gap: f64,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// Kinematic state of a joint in the mechanism.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JointState {
    /// No relative motion at any point.
    Closed,
    /// Some points open, at least one closed: the blocks rotate about the closed point.
    Hinge,
    /// Every point open: the blocks separate.
    Open,
    /// Relative tangential motion (only with friction).
    Sliding,
}

deref_to!(PointResult, position, Position);

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct JointResult<D: Spatial = Two> {
    pub id: usize,
    /// The two bodies; the normal points from `a` into `b`.
    pub a: BodyName,
    pub b: BodyName,
    pub normal: D::Vector,
    pub points: Vec<PointResult<D>>,
    /// Resultant compressive force N (kN) and shear V (kN).
    pub normal_force: f64,
    pub shear_force: D::Tangential,
    /// Signed distance (m) of the centre of pressure from the joint's midpoint along the
    /// tangent(s); `null` where the joint carries no compression.
    pub eccentricity: Option<D::Tangential>,
    pub state: JointState,
    /// Depth of the compressed zone N/(f_c w) (m), with finite compressive strength only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compressed_depth: Option<f64>,
}

/// A hinge: joint and the point it rotates about.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Hinge<D: Spatial = Two> {
    pub joint: usize,
    #[serde(flatten)]
    pub at: D::Position,
}
deref_to!(Hinge, at, Position);

/// A point of the thrust line: the centre of pressure of a joint.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct ThrustPoint<D: Spatial = Two> {
    pub joint: usize,
    #[serde(flatten)]
    pub at: D::Position,
}
deref_to!(ThrustPoint, at, Position);

/// Force exerted by a support on the structure (kN) and its moment (kN·m) about the support's
/// centroid (`fx, fy, m, cx, cy` in 2D).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Reaction<D: Spatial = Two> {
    pub support: String,
    #[serde(flatten)]
    pub wrench: D::Wrench,
}
deref_to!(Reaction, wrench, Wrench);

/// The geometry a result refers to, so that a saved result can be drawn on its own.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Geometry {
    /// Block polygons (counter-clockwise), by block id.
    pub blocks: Vec<Vec<[f64; 2]>>,
    pub supports: Vec<SupportShape>,
    /// Applied loads (dead and live) at their points.
    pub loads: Vec<LoadArrow>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SupportShape {
    pub name: String,
    pub polygon: Vec<[f64; 2]>,
    /// Prescribed motion `[u, v, θ]` about the centroid.
    pub motion: [f64; 3],
    pub fixed: bool,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LoadArrow {
    pub block: usize,
    pub x: f64,
    pub y: f64,
    pub fx: f64,
    pub fy: f64,
    pub live: bool,
}

/// Round values that are pure round-off to zero so that output is stable and readable.
pub(crate) fn clean(v: f64, scale: f64) -> f64 {
    if v.abs() <= 1e-12 * scale {
        0.0
    } else {
        v
    }
}

/// Everything about joints and reactions that a mechanism `d` and forces `p` imply.
pub struct JointReport<D: Spatial = Two> {
    pub blocks: Vec<BlockMotion<D>>,
    pub joints: Vec<JointResult<D>>,
    pub hinges: Vec<Hinge<D>>,
    pub thrust_line: Vec<ThrustPoint<D>>,
    pub reactions: Vec<Reaction<D>>,
    pub openings: Vec<f64>,
    /// Per joint and point (in the order of `joints[j].points`): whether the point is open
    /// (on the motion's scale, [`crate::scale`]), and its opening — for a finite motion
    /// (`support_scale > 0`) the gap it had before plus the opening, else the opening rate.
    /// What [`Assembly::cracks`] traces the cracks from.
    pub open: Vec<Vec<bool>>,
    pub widths: Vec<Vec<f64>>,
}
