//! The layers of [`super::draw3d`], back to front: the undeformed outline, the solids (faces
//! far to near), opened cracks, loads, centres of pressure, hinges, and the axes' triad. Each
//! writes its SVG group and returns how many marks it drew (the legend shows only what was).

use super::layout::Layout;
use super::{hidden, shade, split_segment, Camera, Draw3dOptions, Face};
use crate::draw::chrome::{CRACK, EDGE, FAINT, HINGE, LOAD, THRUST};
use crate::draw::svg::{arrow, num, polygon_path};
use crate::result3d::{add, dot, norm, polygon_order, scale as vscale, sub, Result3d, V3};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use voussoir::dim::Three;
use voussoir::result::spatial::SpatialShapes;
use voussoir::result::{BodyName, JointResult, JointState};

/// Line widths and marker sizes of a drawing, from the blocks' size on the page.
#[derive(Clone, Copy)]
pub(super) struct Pens {
    pub stroke: f64,
    pub hinge_r: f64,
    /// Markers hidden behind a face by more than this (m along the line of sight) are drawn
    /// faint: a hinge point is carried by one body and lies on the other's faces, which the
    /// finite motions of the drawing separate by second-order amounts.
    pub hide_eps: f64,
}

impl Pens {
    pub fn new(mean_size: f64, k: f64) -> Pens {
        Pens {
            stroke: (0.012 * mean_size * k).clamp(0.35, 1.1),
            hinge_r: (0.06 * mean_size * k).clamp(2.5, 5.5),
            hide_eps: 0.03 * mean_size,
        }
    }
}

/// What the layers draw on: the result, its layout, the camera, the visible faces, the pens.
pub(super) struct Marks<'a, R: Result3d + ?Sized> {
    pub r: &'a R,
    pub g: &'a SpatialShapes,
    pub lay: &'a Layout<'a>,
    pub cam: &'a Camera,
    pub faces: &'a [Face],
    pub order: &'a [usize],
    pub pens: Pens,
    joint_by_id: BTreeMap<usize, &'a JointResult<Three>>,
}

impl<'a, R: Result3d + ?Sized> Marks<'a, R> {
    pub fn new(
        r: &'a R,
        g: &'a SpatialShapes,
        lay: &'a Layout<'a>,
        cam: &'a Camera,
        faces: &'a [Face],
        order: &'a [usize],
        pens: Pens,
    ) -> Self {
        Marks {
            r,
            g,
            lay,
            cam,
            faces,
            order,
            pens,
            joint_by_id: r.joints().iter().map(|j| (j.id, j)).collect(),
        }
    }

    fn body_index(&self, b: &BodyName) -> Option<usize> {
        let nb = self.lay.nb;
        match b {
            BodyName::Block(i) if *i < nb => Some(*i),
            BodyName::Block(_) => None,
            BodyName::Support(s) => self
                .g
                .supports
                .iter()
                .position(|x| &x.name == s)
                .map(|k| nb + k),
        }
    }

    /// A point carried by body a of joint `joint` (unmoved if the joint is unknown).
    fn carried(&self, joint: usize, p: V3) -> V3 {
        match self
            .joint_by_id
            .get(&joint)
            .and_then(|j| self.body_index(&j.a))
        {
            Some(a) => self.lay.moved(a, p),
            None => p,
        }
    }

    fn hidden_at(&self, p: V3) -> bool {
        hidden(self.faces, self.cam, p, self.pens.hide_eps)
    }
}

/// Undeformed edges, faint, behind the solids.
pub(super) fn undeformed<R: Result3d + ?Sized>(o: &mut String, m: &Marks<R>, opts: &Draw3dOptions) {
    if m.lay.has_motion && opts.undeformed {
        let mut d = String::new();
        for (bi, b) in m.lay.bodies.iter().enumerate() {
            if !m.lay.drawn(bi) || !b.moving {
                continue;
            }
            let mut edges = BTreeSet::new();
            for f in b.faces {
                for k in 0..f.len() {
                    let (a, c) = (f[k], f[(k + 1) % f.len()]);
                    edges.insert((a.min(c), a.max(c)));
                }
            }
            for (a, c) in edges {
                let (p, q) = (m.cam.px(b.vertices[a]), m.cam.px(b.vertices[c]));
                let _ = write!(
                    d,
                    "M{} {}L{} {}",
                    num(p[0]),
                    num(p[1]),
                    num(q[0]),
                    num(q[1])
                );
            }
        }
        if !d.is_empty() {
            let _ = writeln!(
                o,
                "<path class=\"undeformed\" d=\"{d}\" fill=\"none\" stroke=\"{FAINT}\" stroke-width=\"{}\" stroke-dasharray=\"4 3\"/>",
                num((m.pens.stroke * 0.9).max(0.5))
            );
        }
    }
}

/// The solids: faces far to near, shaded; supports hatched.
pub(super) fn solids<R: Result3d + ?Sized>(o: &mut String, m: &Marks<R>, id: &str) {
    let light = {
        let l = add(
            add(vscale(m.cam.right, -0.45), vscale(m.cam.up, 0.6)),
            vscale(m.cam.toward, 0.66),
        );
        vscale(l, 1.0 / norm(l))
    };
    let _ = writeln!(
        o,
        "<g class=\"solids\" stroke=\"{EDGE}\" stroke-width=\"{}\" stroke-linejoin=\"round\">",
        num(m.pens.stroke)
    );
    for &fi in m.order {
        let f = &m.faces[fi];
        let lambert = 0.64 + 0.36 * dot(f.normal, light).max(0.0);
        let mut d = String::new();
        polygon_path(&mut d, f.px.iter().copied());
        let b = &m.lay.bodies[f.body];
        if b.support {
            let _ = writeln!(
                o,
                "<path class=\"support\" d=\"{d}\" fill=\"url(#{id}-hatch)\"/><path d=\"{d}\" fill=\"#000000\" fill-opacity=\"{}\" stroke=\"none\"/>",
                crate::draw::svg::fmt_fixed(0.55 * (1.0 - lambert), 3)
            );
        } else {
            let _ = writeln!(
                o,
                "<path class=\"block\" data-block=\"{}\" d=\"{d}\" fill=\"{}\"/>",
                f.body,
                shade(b.colour, lambert)
            );
        }
    }
    o.push_str("</g>\n");
}

/// Opened cracks: the joint's polygon on both sides and the wedge between them; the parts
/// behind solids faint. Returns how many.
pub(super) fn cracks<R: Result3d + ?Sized>(
    o: &mut String,
    m: &Marks<R>,
    opts: &Draw3dOptions,
) -> usize {
    let mut n_cracks = 0;
    if opts.cracks {
        let (mut wedge, mut wedge_h) = (String::new(), String::new());
        let (mut outline, mut outline_h) = (String::new(), String::new());
        for j in m.r.joints() {
            if j.state == JointState::Closed || j.points.len() < 2 {
                continue;
            }
            let (Some(a), Some(b)) = (m.body_index(&j.a), m.body_index(&j.b)) else {
                continue;
            };
            let pts: Vec<V3> = j.points.iter().map(|p| [p.x, p.y, p.z]).collect();
            if pts.iter().any(|p| !crate::result3d::finite(*p)) {
                continue;
            }
            let ord = polygon_order(&pts, j.normal);
            let wa: Vec<V3> = ord.iter().map(|&k| m.lay.moved(a, pts[k])).collect();
            let wb: Vec<V3> = ord.iter().map(|&k| m.lay.moved(b, pts[k])).collect();
            n_cracks += 1;
            let npts = ord.len();
            let edges = if npts == 2 { 1 } else { npts };
            for k in 0..edges {
                let k1 = (k + 1) % npts;
                let mid = vscale(add(add(wa[k], wa[k1]), add(wb[k], wb[k1])), 0.25);
                let target = if m.hidden_at(mid) {
                    &mut wedge_h
                } else {
                    &mut wedge
                };
                polygon_path(
                    target,
                    [
                        m.cam.px(wa[k]),
                        m.cam.px(wa[k1]),
                        m.cam.px(wb[k1]),
                        m.cam.px(wb[k]),
                    ],
                );
                for w in [&wa, &wb] {
                    split_segment(
                        &mut outline,
                        &mut outline_h,
                        m.faces,
                        m.cam,
                        w[k],
                        w[k1],
                        m.pens.hide_eps,
                        12,
                    );
                }
            }
        }
        if n_cracks > 0 {
            let sw = num((m.pens.stroke * 1.8).clamp(1.2, 2.0));
            let _ = writeln!(
                o,
                "<g class=\"cracks\" stroke=\"{CRACK}\" stroke-linejoin=\"round\" stroke-linecap=\"round\"><path class=\"hidden\" d=\"{wedge_h}\" fill=\"{CRACK}\" fill-opacity=\"0.15\" stroke=\"none\"/><path class=\"hidden\" d=\"{outline_h}\" fill=\"none\" stroke-opacity=\"0.4\" stroke-width=\"1\" stroke-dasharray=\"3 3\"/><path d=\"{wedge}\" fill=\"{CRACK}\" fill-opacity=\"0.55\" stroke-width=\"0.6\"/><path d=\"{outline}\" fill=\"none\" stroke-width=\"{sw}\"/></g>"
            );
        }
    }
    n_cracks
}

/// Load arrows, dead then live. Returns how many of each (live, dead).
pub(super) fn loads<R: Result3d + ?Sized>(
    o: &mut String,
    m: &Marks<R>,
    width: f64,
) -> (usize, usize) {
    let head = (0.018 * width).clamp(6.0, 11.0);
    let sw = (m.pens.stroke * 1.6).clamp(1.0, 1.8);
    let mut n_live = 0;
    let mut n_dead = 0;
    for (live, colour, class) in [(false, "#555555", "dead-loads"), (true, LOAD, "live-loads")] {
        let (mut sh, mut hd) = (String::new(), String::new());
        for (blk, at, d, l) in &m.lay.loads {
            if *l != live {
                continue;
            }
            let t = m.lay.moved(*blk, *at);
            arrow(&mut sh, &mut hd, m.cam.px(sub(t, *d)), m.cam.px(t), head);
            if live {
                n_live += 1;
            } else {
                n_dead += 1;
            }
        }
        if !sh.is_empty() || !hd.is_empty() {
            let _ = writeln!(
                o,
                "<g class=\"{class}\" stroke=\"{colour}\" fill=\"{colour}\" stroke-width=\"{}\"><path d=\"{sh}\" fill=\"none\"/><path d=\"{hd}\" stroke=\"none\"/></g>",
                num(sw)
            );
        }
    }
    (n_live, n_dead)
}

/// Centres of pressure, each carried by its joint's first body. Returns how many.
pub(super) fn pressure<R: Result3d + ?Sized>(
    o: &mut String,
    m: &Marks<R>,
    show_pressure: bool,
) -> usize {
    let mut n_thrust = 0;
    if show_pressure {
        let dot_r = (m.pens.hinge_r * 0.55).max(1.8);
        let mut dots = String::new();
        for t in m.r.thrust_line() {
            let p = [t.x, t.y, t.z];
            if !crate::result3d::finite(p) {
                continue;
            }
            let w = m.carried(t.joint, p);
            let q = m.cam.px(w);
            n_thrust += 1;
            let _ = writeln!(
                dots,
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"{}/>",
                num(q[0]),
                num(q[1]),
                num(dot_r),
                if m.hidden_at(w) {
                    " opacity=\"0.35\""
                } else {
                    ""
                }
            );
        }
        if n_thrust > 0 {
            let _ = writeln!(
                o,
                "<g class=\"pressure-centres\" fill=\"{THRUST}\" stroke=\"#ffffff\" stroke-width=\"0.8\">\n{dots}</g>"
            );
        }
    }
    n_thrust
}

/// Hinges: points, and hinge lines where a joint has two or more. Returns how many points.
pub(super) fn hinges<R: Result3d + ?Sized>(
    o: &mut String,
    m: &Marks<R>,
    opts: &Draw3dOptions,
) -> usize {
    let mut n_hinges = 0;
    if opts.hinges && !m.r.hinges().is_empty() {
        let mut by_joint: BTreeMap<usize, Vec<V3>> = BTreeMap::new();
        for h in m.r.hinges() {
            let p = [h.x, h.y, h.z];
            if crate::result3d::finite(p) {
                by_joint.entry(h.joint).or_default().push(p);
            }
        }
        let (mut lines, mut lines_h) = (String::new(), String::new());
        let mut dots = String::new();
        for (&j, pts) in &by_joint {
            let w: Vec<V3> = pts.iter().map(|p| m.carried(j, *p)).collect();
            if w.len() >= 2 {
                // The two points farthest apart (first pair on ties).
                let mut best = (0, 1, -1.0);
                for a in 0..pts.len() {
                    for b in a + 1..pts.len() {
                        let d = norm(sub(pts[a], pts[b]));
                        if d > best.2 {
                            best = (a, b, d);
                        }
                    }
                }
                split_segment(
                    &mut lines,
                    &mut lines_h,
                    m.faces,
                    m.cam,
                    w[best.0],
                    w[best.1],
                    m.pens.hide_eps,
                    24,
                );
            }
            for p in &w {
                n_hinges += 1;
                let q = m.cam.px(*p);
                let _ = writeln!(
                    dots,
                    "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"{}/>",
                    num(q[0]),
                    num(q[1]),
                    num(m.pens.hinge_r),
                    if m.hidden_at(*p) {
                        " opacity=\"0.35\""
                    } else {
                        ""
                    }
                );
            }
        }
        let lw = num((m.pens.hinge_r * 0.75).clamp(2.0, 3.5));
        if !lines_h.is_empty() {
            let _ = writeln!(
                o,
                "<path class=\"hinge-lines hidden\" d=\"{lines_h}\" fill=\"none\" stroke=\"{HINGE}\" stroke-opacity=\"0.35\" stroke-width=\"{lw}\" stroke-dasharray=\"5 4\"/>"
            );
        }
        if !lines.is_empty() {
            let _ = writeln!(
                o,
                "<path class=\"hinge-lines\" d=\"{lines}\" fill=\"none\" stroke=\"{HINGE}\" stroke-width=\"{lw}\" stroke-linecap=\"round\"/>"
            );
        }
        if n_hinges > 0 {
            let _ = writeln!(
                o,
                "<g class=\"hinges\" fill=\"{HINGE}\" stroke=\"#ffffff\" stroke-width=\"{}\">\n{dots}</g>",
                num((m.pens.hinge_r * 0.3).clamp(0.8, 1.5))
            );
        }
    }
    n_hinges
}

/// The axes: a small triad in the lower right corner of the drawing area (`base`).
pub(super) fn axes<R: Result3d + ?Sized>(o: &mut String, m: &Marks<R>, base: [f64; 2]) {
    {
        let len = 24.0;
        let mut s = String::new();
        for (axis, name) in [
            ([1.0, 0.0, 0.0], "x"),
            ([0.0, 1.0, 0.0], "y"),
            ([0.0, 0.0, 1.0], "z"),
        ] {
            let v = [dot(axis, m.cam.right), -dot(axis, m.cam.up)];
            let l = v[0].hypot(v[1]);
            if l < 0.15 {
                // Seen end-on: a dot.
                let _ = write!(
                    s,
                    "<circle cx=\"{}\" cy=\"{}\" r=\"2\" fill=\"#555555\"/><text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#555555\">{name}</text>",
                    num(base[0]),
                    num(base[1]),
                    num(base[0] + 4.0),
                    num(base[1] + 12.0)
                );
                continue;
            }
            let tip = [base[0] + len * v[0], base[1] + len * v[1]];
            let (mut sh, mut hd) = (String::new(), String::new());
            arrow(&mut sh, &mut hd, base, tip, 6.0);
            let lab = [
                base[0] + (len + 9.0) * v[0] / l.max(1e-9) * l.min(1.0),
                base[1] + (len + 9.0) * v[1] / l.max(1e-9) * l.min(1.0),
            ];
            let _ = write!(
                s,
                "<path d=\"{sh}\" stroke=\"#555555\" stroke-width=\"1.2\" fill=\"none\"/><path d=\"{hd}\" fill=\"#555555\"/><text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#555555\" text-anchor=\"middle\">{name}</text>",
                num(lab[0]),
                num(lab[1] + 4.0)
            );
        }
        let _ = writeln!(o, "<g class=\"axes\">{s}</g>");
    }
}
