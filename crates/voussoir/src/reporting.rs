//! The results stage of the pipeline, written once over [`Assembly`]: from a mechanism and
//! forces on a structure to its joints, hinges, thrust line, reactions and cracks. It stands
//! above `structure`, `discretize` and `result` (whose types it fills), so that none of those
//! three imports another in a circle.

use crate::dim::Dim;
use crate::discretize::{Body, ContactJoint, KinematicMap};
use crate::result::cracks::{trace, Crack, JointPoints};
use crate::result::*;
use crate::structure::{Assembly, Structure};

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

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// The cracks a deformed structure carries: its points with a gap (the final state of an
/// incremental analysis, the settled structure of a capacity curve). Widths are the gaps (m).
pub fn cracks_of_gaps(st: &Structure) -> Vec<Crack> {
    let name = |b: Body| match b {
        Body::Block(i) => BodyName::Block(i),
        Body::Support(s) => BodyName::Support(st.supports[s].name.clone()),
    };
    let input: Vec<JointPoints> = st
        .joints
        .iter()
        .enumerate()
        .filter(|(_, j)| j.points.iter().any(|p| p.gap > 0.0))
        .map(|(j, jt)| JointPoints {
            joint: j,
            faces: [name(jt.a), name(jt.b)],
            tangent: jt.tangent(),
            points: jt
                .points
                .iter()
                .map(|p| (p.x, p.gap, p.gap > 0.0))
                .collect(),
        })
        .collect();
    trace(input, &CrackGeometry::of_structure(st))
}
