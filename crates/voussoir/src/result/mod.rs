//! Typed results: one submodule per analysis ([`limit`], [`settlement`], [`capacity`],
//! [`incremental`], [`tilt`], [`nonassociative`]) over the pieces they share here — block
//! motions, joints with their points, hinges, the thrust line and support reactions. Every
//! result serialises to the JSON the CLI prints. Drawings and other front ends read results
//! from this module only, never from the algorithms in [`crate::analysis`].

pub mod canonical;
pub mod capacity;
pub mod cracks;
pub mod identify;
pub mod incremental;
pub mod limit;
pub mod nonassociative;
pub mod safety;
pub mod settlement;
pub mod tilt;

pub use canonical::*;
pub use capacity::*;
pub use cracks::{Crack, Crack3d, CrackEnd, CrackFront, CrackGeometry, CrackText};
pub use incremental::*;
pub use limit::*;
pub use nonassociative::*;
pub use safety::*;
pub use settlement::*;
pub use tilt::*;

pub mod spatial;

pub use spatial::{PlanarMotion, PlanarPoint, PlanarWrench, Spatial};

use crate::dim::{Dim, Two};
use crate::discretize::{ContactJoint, KinematicMap};
use crate::structure::{Assembly, Body, Structure};
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

impl<D: Spatial> JointReport<D> {
    /// The cracks of this report on structure `st` ([`crate::result::cracks`]).
    pub fn cracks<S: Assembly<D = D>>(&self, st: &S) -> Vec<D::Crack> {
        st.cracks(&self.joints, &self.open, &self.widths)
    }
}

/// Build joints, hinges, thrust line and reactions from block motions `d` (with the prescribed
/// support motions scaled by `support_scale`) and point forces, in either dimension.
///
/// A joint is a *hinge* when some of its points open and some stay closed; its closed points
/// are the hinge's points (one in 2D; in 3D one point is a pivot, two or more a hinge line).
/// The centre of pressure is the force-weighted mean of the points; the eccentricity its
/// offset from the joint's midpoint along each tangent.
pub fn report<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    d: &[f64],
    support_scale: f64,
    pn: &[f64],
    pt: &[f64],
) -> JointReport<S::D> {
    let (nd, nt) = (<S::D as Dim>::DOFS, <S::D as Dim>::TANGENTS);
    let (open, slide) = map.jumps(d, support_scale);
    // Open, sliding and round-off are judged on the motion's own scale (crate::scale): a
    // rigid motion of the whole structure opens nothing, however small its round-off.
    let mscale = crate::scale::motion_scale(map, d, support_scale)
        .max(max_abs(&open))
        .max(max_abs(&slide))
        .max(1e-300);
    let fscale = max_abs(pn).max(max_abs(pt)).max(1e-300);
    let open_tol = crate::scale::OPEN_TOLERANCE * mscale;
    let dscale = max_abs(d).max(1e-300);
    let blocks = (0..st.num_blocks())
        .map(|i| {
            let m: Vec<f64> = d[nd * i..nd * (i + 1)]
                .iter()
                .map(|&x| clean(x, dscale))
                .collect();
            BlockMotion {
                id: i,
                motion: S::D::motion(&m),
            }
        })
        .collect();
    let contact = st.contact_joints();
    let mut joints = Vec::with_capacity(contact.len());
    let mut hinges = Vec::new();
    let mut thrust_line = Vec::new();
    let mut open_flags = Vec::with_capacity(contact.len());
    let mut widths = Vec::with_capacity(contact.len());
    for (j, joint) in contact.iter().enumerate() {
        let range = map.joint_start[j]..map.joint_start[j + 1];
        let ts = joint.tangents.as_ref();
        let npts = joint.points.len().max(1) as f64;
        let mut mid = vec![0.0; <S::D as Dim>::N];
        for (x, _) in &joint.points {
            for (m, c) in mid.iter_mut().zip(x.as_ref()) {
                *m += c;
            }
        }
        let mid: Vec<f64> = mid.iter().map(|m| m / npts).collect();
        let mut nf = 0.0;
        let mut sf = [0.0f64; 2];
        let mut mom = [0.0f64; 2];
        let mut centre = [0.0f64; 3];
        let mut points: Vec<PointResult<S::D>> = Vec::new();
        let mut closed = Vec::new();
        let mut jopen = Vec::new();
        let mut jwidth = Vec::new();
        let (mut n_open, mut sliding) = (0, false);
        for k in range {
            let (x, gap) = joint.points[map.points[k].index];
            let o = clean(open[k], mscale);
            let mut s = [0.0f64; 2];
            for (m, sm) in s.iter_mut().enumerate().take(nt) {
                *sm = clean(slide[k * nt + m], mscale);
                sliding |= sm.abs() > open_tol;
            }
            // A finite motion (a settlement) adds to the gap a point had before, and may close
            // it; a rate (a collapse mechanism) leaves a gapped point open.
            let is_open = if support_scale > 0.0 && gap > 0.0 {
                gap + o > open_tol
            } else {
                o > open_tol || gap > 0.0
            };
            if is_open {
                n_open += 1;
            } else {
                closed.push(x);
            }
            jopen.push(is_open);
            jwidth.push(if !is_open {
                0.0
            } else if support_scale > 0.0 {
                (gap + o).max(0.0)
            } else {
                o.max(0.0)
            });
            let fn_ = clean(pn[k], fscale);
            let mut fs = [0.0f64; 2];
            for (m, f) in fs.iter_mut().enumerate().take(nt) {
                *f = clean(pt[k * nt + m], fscale);
                sf[m] += *f;
            }
            nf += fn_;
            let xs = x.as_ref();
            for (m, t) in ts.iter().enumerate() {
                let arm: f64 = xs
                    .iter()
                    .zip(&mid)
                    .zip(t.as_ref())
                    .map(|((a, b), e)| (a - b) * e)
                    .sum();
                mom[m] += fn_ * arm;
            }
            for (c, xc) in centre.iter_mut().zip(xs) {
                *c += fn_ * xc;
            }
            points.push(PointResult {
                position: S::D::position(x),
                opening: o,
                sliding: S::D::tangential(&s[..nt]),
                normal_force: fn_,
                shear_force: S::D::tangential(&fs[..nt]),
                gap,
            });
        }
        let state = if sliding {
            JointState::Sliding
        } else if n_open == 0 {
            JointState::Closed
        } else if closed.is_empty() {
            JointState::Open
        } else {
            JointState::Hinge
        };
        if state == JointState::Hinge {
            for x in closed {
                hinges.push(Hinge {
                    joint: j,
                    at: S::D::position(x),
                });
            }
        }
        let eccentricity = if nf > 1e-9 * fscale {
            let mut c = joint.points[0].0;
            for (ci, v) in c.as_mut().iter_mut().zip(&centre) {
                *ci = v / nf;
            }
            thrust_line.push(ThrustPoint {
                joint: j,
                at: S::D::position(c),
            });
            let e: Vec<f64> = mom[..nt].iter().map(|m| m / nf).collect();
            Some(S::D::tangential(&e))
        } else {
            None
        };
        open_flags.push(jopen);
        widths.push(jwidth);
        let sfc: Vec<f64> = sf[..nt].iter().map(|v| clean(*v, fscale)).collect();
        joints.push(JointResult {
            id: j,
            a: st.body_name(joint.a),
            b: st.body_name(joint.b),
            normal: joint.normal,
            points,
            normal_force: clean(nf, fscale),
            shear_force: S::D::tangential(&sfc),
            eccentricity,
            state,
            compressed_depth: map.laws[j]
                .strength
                .map(|f| clean(nf, fscale).max(0.0) / (f * map.laws[j].width)),
        });
    }
    let reactions = reactions_of(st, &contact, map, pn, pt);
    JointReport {
        blocks,
        joints,
        hinges,
        thrust_line,
        reactions,
        openings: open,
        open: open_flags,
        widths,
    }
}

/// How each point force enters the reactions: `visit(support, point, which, row)` for every
/// point on a support, with `which = 0` for the normal force and `1 + m` for the shear along
/// tangent `m`, and `row` the support's reaction (force, then moment about its reference point)
/// per unit of that force. Reactions are linear in the forces: `Σ force × row`.
pub fn reaction_terms<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    visit: impl FnMut(usize, usize, usize, &[f64]),
) {
    reaction_terms_of(st, &st.contact_joints(), map, visit)
}

fn reaction_terms_of<S: Assembly>(
    st: &S,
    contact: &[ContactJoint<S::D>],
    map: &KinematicMap,
    mut visit: impl FnMut(usize, usize, usize, &[f64]),
) {
    let (nd, n) = (<S::D as Dim>::DOFS, <S::D as Dim>::N);
    let centres = st.contact_bodies().supports;
    let mut row = [0.0f64; 6];
    for (k, pr) in map.points.iter().enumerate() {
        let joint = &contact[pr.joint];
        let x = joint.points[pr.index].0;
        let dirs = std::iter::once(joint.normal).chain(joint.tangents.as_ref().iter().copied());
        for (which, e) in dirs.enumerate() {
            for (body, sign) in [(joint.a, 1.0), (joint.b, -1.0)] {
                // A force along e on b (and −e on a): the structure receives +e from a support
                // a, −e from a support b.
                if let Body::Support(s) = body {
                    let c = centres[s].0;
                    let mut r = e;
                    for v in r.as_mut()[..n].iter_mut() {
                        *v *= sign;
                    }
                    S::D::dof_row(S::D::sub(x, c), r, &mut row[..nd]);
                    visit(s, k, which, &row[..nd]);
                }
            }
        }
    }
}

/// Reactions: force of each support on the structure and moment about the support's reference
/// point (the generalised force of the point forces on the support's DOFs, [`Dim::dof_row`]).
pub fn reactions<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    pn: &[f64],
    pt: &[f64],
) -> Vec<Reaction<S::D>> {
    reactions_of(st, &st.contact_joints(), map, pn, pt)
}

fn reactions_of<S: Assembly>(
    st: &S,
    contact: &[ContactJoint<S::D>],
    map: &KinematicMap,
    pn: &[f64],
    pt: &[f64],
) -> Vec<Reaction<S::D>> {
    let (nd, nt, n) = (
        <S::D as Dim>::DOFS,
        <S::D as Dim>::TANGENTS,
        <S::D as Dim>::N,
    );
    let centres = st.contact_bodies().supports;
    let mut acc = vec![vec![0.0f64; nd]; st.num_supports()];
    let mut row = [0.0f64; 6];
    for (k, pr) in map.points.iter().enumerate() {
        let joint = &contact[pr.joint];
        let x = joint.points[pr.index].0;
        // Force on b along +n and +t; on a the opposite.
        let mut f = joint.normal;
        for (fi, ni) in f.as_mut().iter_mut().zip(joint.normal.as_ref()) {
            *fi = pn[k] * ni;
        }
        for (m, t) in joint.tangents.as_ref().iter().enumerate() {
            for (fi, ti) in f.as_mut().iter_mut().zip(t.as_ref()) {
                *fi += pt[k * nt + m] * ti;
            }
        }
        for (body, sign) in [(joint.a, 1.0), (joint.b, -1.0)] {
            // The support is `body`; the structure is the other side, which receives +f if the
            // support is a, −f if the support is b.
            if let Body::Support(s) = body {
                let c = centres[s].0;
                let mut r = f;
                for v in r.as_mut()[..n].iter_mut() {
                    *v *= sign;
                }
                S::D::dof_row(S::D::sub(x, c), r, &mut row[..nd]);
                for (a, v) in acc[s].iter_mut().zip(&row[..nd]) {
                    *a += v;
                }
            }
        }
    }
    let scale = acc
        .iter()
        .flat_map(|a| a.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()))
        .max(1e-300);
    acc.into_iter()
        .enumerate()
        .map(|(s, a)| {
            let a: Vec<f64> = a.iter().map(|v| clean(*v, scale)).collect();
            Reaction {
                support: st.support_name(s).to_string(),
                wrench: S::D::wrench(&a, centres[s].0),
            }
        })
        .collect()
}
