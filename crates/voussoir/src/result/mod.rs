//! Typed results: one submodule per analysis ([`limit`], [`settlement`], [`capacity`],
//! [`incremental`], [`tilt`], [`nonassociative`]) over the pieces they share here — block
//! motions, joints with their points, hinges, the thrust line and support reactions. Every
//! result serialises to the JSON the CLI prints. Drawings and other front ends read results
//! from this module only, never from the algorithms in [`crate::analysis`].

pub mod capacity;
pub mod incremental;
pub mod limit;
pub mod nonassociative;
pub mod settlement;
pub mod tilt;

pub use capacity::*;
pub use incremental::*;
pub use limit::*;
pub use nonassociative::*;
pub use settlement::*;
pub use tilt::*;

pub mod spatial;

pub use spatial::{PlanarMotion, PlanarPoint, PlanarWrench, Spatial};

use crate::dim::Two;
use crate::discretize::KinematicMap;
use crate::structure::{Body, Structure};
use serde::{Deserialize, Serialize};

/// A body as named in results: a block index (number) or a support name (string).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum BodyName {
    Block(usize),
    Support(String),
}

impl BodyName {
    pub fn of(st: &Structure, b: Body) -> BodyName {
        match b {
            Body::Block(i) => BodyName::Block(i),
            Body::Support(s) => BodyName::Support(st.supports[s].name.clone()),
        }
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

impl Geometry {
    pub fn of(st: &Structure) -> Geometry {
        Geometry {
            blocks: st.blocks.iter().map(|b| b.polygon.clone()).collect(),
            supports: st
                .supports
                .iter()
                .map(|s| SupportShape {
                    name: s.name.clone(),
                    polygon: s.polygon.clone(),
                    motion: s.motion,
                    fixed: s.connection == crate::model::Connection::Fixed,
                })
                .collect(),
            loads: st
                .loads
                .iter()
                .map(|l| LoadArrow {
                    block: l.block,
                    x: l.at[0],
                    y: l.at[1],
                    fx: l.force[0],
                    fy: l.force[1],
                    live: l.live,
                })
                .collect(),
        }
    }
}

/// Round values that are pure round-off to zero so that output is stable and readable.
pub(crate) fn clean(v: f64, scale: f64) -> f64 {
    if v.abs() <= 1e-12 * scale {
        0.0
    } else {
        v
    }
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// Everything about joints and reactions that a mechanism `d` and forces `p` imply.
pub struct JointReport {
    pub blocks: Vec<BlockMotion>,
    pub joints: Vec<JointResult>,
    pub hinges: Vec<Hinge>,
    pub thrust_line: Vec<ThrustPoint>,
    pub reactions: Vec<Reaction>,
    pub openings: Vec<f64>,
}

/// Build joints, hinges, thrust line and reactions from block motions `d` (with the prescribed
/// support motions scaled by `support_scale`) and point forces.
pub fn report(
    st: &Structure,
    map: &KinematicMap,
    d: &[f64],
    support_scale: f64,
    pn: &[f64],
    pt: &[f64],
) -> JointReport {
    let (open, slide) = map.jumps(d, support_scale);
    let mscale = max_abs(&open).max(max_abs(&slide)).max(1e-300);
    let fscale = max_abs(pn).max(max_abs(pt)).max(1e-300);
    let open_tol = 1e-7 * mscale;
    let dscale = max_abs(d).max(1e-300);
    let blocks = (0..st.blocks.len())
        .map(|i| {
            BlockMotion::planar(
                i,
                clean(d[3 * i], dscale),
                clean(d[3 * i + 1], dscale),
                clean(d[3 * i + 2], dscale),
            )
        })
        .collect();
    let mut joints = Vec::with_capacity(st.joints.len());
    let mut hinges = Vec::new();
    let mut thrust_line = Vec::new();
    for (j, joint) in st.joints.iter().enumerate() {
        let range = map.joint_start[j]..map.joint_start[j + 1];
        let t = joint.tangent();
        let mid = joint.midpoint();
        let (mut nf, mut sf, mut mom, mut cx, mut cy) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let mut points: Vec<PointResult> = Vec::new();
        let (mut n_open, mut n_closed, mut sliding) = (0, 0, false);
        for k in range {
            let p = joint.points[map.points[k].index];
            let o = clean(open[k], mscale);
            let s = clean(slide[k], mscale);
            if o > open_tol || p.gap > 0.0 {
                n_open += 1;
            } else {
                n_closed += 1;
            }
            sliding |= s.abs() > open_tol;
            let (fn_, fs) = (clean(pn[k], fscale), clean(pt[k], fscale));
            nf += fn_;
            sf += fs;
            mom += fn_ * ((p.x[0] - mid[0]) * t[0] + (p.x[1] - mid[1]) * t[1]);
            cx += fn_ * p.x[0];
            cy += fn_ * p.x[1];
            points.push(PointResult {
                position: PlanarPoint {
                    x: p.x[0],
                    y: p.x[1],
                },
                opening: o,
                sliding: s,
                normal_force: fn_,
                shear_force: fs,
                gap: p.gap,
            });
        }
        let state = if sliding {
            JointState::Sliding
        } else if n_open == 0 {
            JointState::Closed
        } else if n_closed == 0 {
            JointState::Open
        } else {
            JointState::Hinge
        };
        if state == JointState::Hinge {
            // The hinge is the closed point (the one with the smallest opening).
            if let Some(p) = points.iter().min_by(|a, b| a.opening.total_cmp(&b.opening)) {
                hinges.push(Hinge {
                    joint: j,
                    at: PlanarPoint { x: p.x, y: p.y },
                });
            }
        }
        let eccentricity = if nf > 1e-9 * fscale {
            thrust_line.push(ThrustPoint {
                joint: j,
                at: PlanarPoint {
                    x: cx / nf,
                    y: cy / nf,
                },
            });
            Some(mom / nf)
        } else {
            None
        };
        joints.push(JointResult {
            id: j,
            a: BodyName::of(st, joint.a),
            b: BodyName::of(st, joint.b),
            normal: joint.normal,
            points,
            normal_force: clean(nf, fscale),
            shear_force: clean(sf, fscale),
            eccentricity,
            state,
            compressed_depth: map.laws[j]
                .strength
                .map(|f| clean(nf, fscale).max(0.0) / (f * map.laws[j].width)),
        });
    }
    let reactions = reactions(st, map, pn, pt);
    JointReport {
        blocks,
        joints,
        hinges,
        thrust_line,
        reactions,
        openings: open,
    }
}

/// Reactions: force of each support on the structure and moment about the support centroid.
pub fn reactions(st: &Structure, map: &KinematicMap, pn: &[f64], pt: &[f64]) -> Vec<Reaction> {
    let mut acc = vec![[0.0f64; 3]; st.supports.len()];
    for (k, pr) in map.points.iter().enumerate() {
        let joint = &st.joints[pr.joint];
        let t = joint.tangent();
        let x = joint.points[pr.index].x;
        // Force on b along +n and +t; on a the opposite.
        let f = [
            pn[k] * joint.normal[0] + pt[k] * t[0],
            pn[k] * joint.normal[1] + pt[k] * t[1],
        ];
        for (body, sign) in [(joint.a, 1.0), (joint.b, -1.0)] {
            // The support is `body`; the structure is the other side, which receives +f if the
            // support is a, −f if the support is b.
            if let Body::Support(s) = body {
                let c = st.supports[s].centroid;
                let r = [sign * f[0], sign * f[1]];
                acc[s][0] += r[0];
                acc[s][1] += r[1];
                acc[s][2] += (x[0] - c[0]) * r[1] - (x[1] - c[1]) * r[0];
            }
        }
    }
    let scale = acc
        .iter()
        .flat_map(|a| a.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()))
        .max(1e-300);
    st.supports
        .iter()
        .zip(acc)
        .map(|(s, a)| Reaction {
            support: s.name.clone(),
            wrench: PlanarWrench {
                fx: clean(a[0], scale),
                fy: clean(a[1], scale),
                m: clean(a[2], scale),
                cx: s.centroid[0],
                cy: s.centroid[1],
            },
        })
        .collect()
}
