//! The layers of a 2D drawing, painted in order by a [`Painter`] that holds the projection
//! (the world → pixel frame and each group's pixel-frame motion at the drawing's scale): the
//! faint undeformed outline, the bodies, the crack wedges, the crack lines, the arrows (loads
//! and contact forces), the thrust line and the hinges. Each layer writes its SVG and returns
//! what the legend needs to know of it.

use super::{
    nearest_block, px_apply, px_matrix, px_motion, thrust_chains, Bodies, DrawOptions, Frame,
    LoadArrow, Motion, MotionUnits, PressurePoints, Scene, CRACK, CRACK_LINE, EDGE, FAINT,
    HAIRLINE, HINGE, PALETTE, STILL, STONE, THRUST,
};
use crate::draw::svg::{arrow, esc, fmt_fixed, num, points_attr, polygon_path};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use voussoir::result::{JointResult, JointState};

/// Paints the layers of one drawing.
pub(super) struct Painter<'a> {
    scene: &'a Scene<'a>,
    opts: &'a DrawOptions,
    mo: &'a Motion,
    b: &'a Bodies,
    fr: &'a Frame,
    joint_by_id: &'a BTreeMap<usize, &'a JointResult>,
    /// Pixel-frame motion of each group, unscaled.
    pxm: Vec<[f64; 5]>,
    /// The drawing's displacement scale (0 when nothing moves).
    s_eff: f64,
    stroke: f64,
    hinge_r: f64,
    /// The drawing's id, escaped.
    pub(super) id: String,
    /// The slider's data is written (an interactive drawing of a motion).
    interactive: bool,
}

/// What the crack-line layer drew.
pub(super) struct CrackLines {
    pub(super) drawn: usize,
}

/// The hinges a drawing shows, each with the body it moves with: every hinge of the scene but
/// a closed point a crack runs through (a bend of that crack, not a hinge) and the points of a
/// settlement's hairlines (cracks narrower than [`HAIRLINE`] of the widest, left out of the
/// drawing with their hinges; a collapse mechanism's hinges are all drawn: each is part of the
/// mechanism). The drawing's title counts these, so that its count is the dots drawn.
pub(super) fn visible_hinges(
    scene: &Scene,
    opts: &DrawOptions,
    b: &Bodies,
    joint_by_id: &BTreeMap<usize, &JointResult>,
) -> Vec<(usize, [f64; 2])> {
    let mut out = Vec::new();
    if !(opts.hinges && !scene.hinges.is_empty()) {
        return out;
    }
    let mut skip: Vec<[f64; 2]> = Vec::new();
    if opts.cracks && !scene.cracks.is_empty() {
        let widest = scene
            .cracks
            .iter()
            .fold(0.0f64, |m, c| m.max(c.max_opening));
        for c in scene.cracks {
            if c.points.len() > 2 {
                skip.extend_from_slice(&c.points[1..c.points.len() - 1]);
            }
            if !(c.max_opening >= HAIRLINE * widest) && scene.units == MotionUnits::Metres {
                skip.extend(c.points.iter().copied());
            }
        }
    }
    let tol = 1e-9 * b.size;
    for h in scene.hinges {
        if !h.x.is_finite() || !h.y.is_finite() {
            continue;
        }
        if skip.iter().any(|p| (p[0] - h.x).hypot(p[1] - h.y) <= tol) {
            continue;
        }
        // The hinge moves with body a of its joint; results without joints (capacity
        // curves) use the block nearest to the hinge.
        let a = match joint_by_id.get(&h.joint).and_then(|j| b.body_of(&j.a)) {
            Some(a) => a,
            None => match nearest_block(b, [h.x, h.y]) {
                Some(a) => a,
                None => continue,
            },
        };
        out.push((a, [h.x, h.y]));
    }
    out
}

impl<'a> Painter<'a> {
    pub(super) fn new(
        scene: &'a Scene<'a>,
        opts: &'a DrawOptions,
        mo: &'a Motion,
        fr: &'a Frame,
        joint_by_id: &'a BTreeMap<usize, &'a JointResult>,
        interactive: bool,
    ) -> Painter<'a> {
        let b = &mo.b;
        Painter {
            scene,
            opts,
            mo,
            b,
            fr,
            joint_by_id,
            pxm: b.groups.iter().map(|g| px_motion(fr, g)).collect(),
            s_eff: mo.scale,
            stroke: (0.03 * b.mean_block * fr.k).clamp(0.25, 1.1),
            hinge_r: (0.22 * b.mean_block * fr.k).clamp(2.0, 5.5),
            id: esc(&opts.id),
            interactive,
        }
    }

    /// The slider's data on the `<svg>` element: the scale and each group's pixel motion.
    pub(super) fn motion_data(&self, o: &mut String, scale: f64) {
        let mut m = String::new();
        for (i, g) in self.pxm.iter().enumerate() {
            if i > 0 {
                m.push(';');
            }
            let _ = write!(
                m,
                "{},{},{},{},{}",
                num(g[0]),
                num(g[1]),
                fmt_fixed(g[2], 5),
                fmt_fixed(g[3], 5),
                fmt_fixed(g[4], 9)
            );
        }
        let _ = write!(
            o,
            " data-scale=\"{}\" data-motions=\"{}\"",
            fmt_fixed(scale, 9),
            m
        );
    }

    /// A point that moves with body `body`: its static pixel position and, for the slider, the
    /// data `g,x,y` (group and undeformed pixel position).
    fn at(&self, body: usize, p: [f64; 2]) -> ([f64; 2], String) {
        let gi = self.b.bodies[body].group;
        let p0 = self.fr.px(p);
        let p1 = if self.b.groups[gi].moving && self.mo.has_motion {
            px_apply(&self.pxm[gi], self.s_eff, p0)
        } else {
            p0
        };
        (p1, format!("{},{},{}", gi, num(p0[0]), num(p0[1])))
    }

    /// The undeformed outline, faint and dashed, under a motion.
    pub(super) fn undeformed(&self, o: &mut String) {
        if !(self.mo.has_motion && self.opts.undeformed) {
            return;
        }
        let mut d = String::new();
        for body in &self.b.bodies {
            polygon_path(&mut d, body.poly.iter().map(|p| self.fr.px(*p)));
        }
        let _ = writeln!(
            o,
            "<path class=\"undeformed\" d=\"{d}\" fill=\"none\" stroke=\"{FAINT}\" stroke-width=\"{}\" stroke-dasharray=\"4 3\"/>",
            num((self.stroke * 0.9).max(0.4))
        );
    }

    /// The bodies by group: supports hatched, blocks filled (a macro-block's colour, stone grey
    /// at rest).
    pub(super) fn bodies(&self, o: &mut String) {
        let (b, has_motion, stroke) = (self.b, self.mo.has_motion, self.stroke);
        for (gi, g) in b.groups.iter().enumerate() {
            let mut d = String::new();
            for &m in &g.members {
                polygon_path(&mut d, b.bodies[m].poly.iter().map(|p| self.fr.px(*p)));
            }
            if d.is_empty() {
                continue;
            }
            let fill = if g.support {
                format!("url(#{}-hatch)", self.id)
            } else if !has_motion {
                STONE.to_string()
            } else if !g.moving {
                STILL.to_string()
            } else {
                PALETTE[g.colour % PALETTE.len()].to_string()
            };
            let _ = write!(
                o,
                "<path class=\"{}\" d=\"{d}\" fill=\"{fill}\" stroke=\"{EDGE}\" stroke-width=\"{}\" stroke-linejoin=\"round\"",
                if g.support { "support" } else { "blocks" },
                num(if g.support { stroke.max(0.8) } else { stroke })
            );
            if g.moving && has_motion {
                let _ = write!(o, " transform=\"{}\"", px_matrix(&self.pxm[gi], self.s_eff));
                if self.interactive {
                    let _ = write!(o, " data-g=\"{gi}\"");
                }
            }
            o.push_str("/>\n");
        }
    }

    /// The crack wedges: the wedge between the two faces of every open joint. Returns how many.
    pub(super) fn crack_wedges(&self, o: &mut String) -> usize {
        let mut n_cracks = 0;
        if !(self.mo.has_motion && self.opts.cracks) {
            return n_cracks;
        }
        let b = self.b;
        let mut static_d = String::new();
        let mut items = String::new();
        for j in self.scene.joints {
            if !matches!(
                j.state,
                JointState::Open | JointState::Hinge | JointState::Sliding
            ) || j.points.len() < 2
            {
                continue;
            }
            let (Some(a), Some(bb_)) = (b.body_of(&j.a), b.body_of(&j.b)) else {
                continue;
            };
            let t = [-j.normal[1], j.normal[0]];
            let along = |p: &voussoir::result::PointResult| p.x * t[0] + p.y * t[1];
            let (Some(p0), Some(p1)) = (
                j.points
                    .iter()
                    .filter(|p| p.x.is_finite() && p.y.is_finite())
                    .min_by(|x, y| along(x).total_cmp(&along(y))),
                j.points
                    .iter()
                    .filter(|p| p.x.is_finite() && p.y.is_finite())
                    .max_by(|x, y| along(x).total_cmp(&along(y))),
            ) else {
                continue;
            };
            let (q0, q1) = ([p0.x, p0.y], [p1.x, p1.y]);
            let corners = [
                self.at(a, q0),
                self.at(a, q1),
                self.at(bb_, q1),
                self.at(bb_, q0),
            ];
            n_cracks += 1;
            let pts: Vec<[f64; 2]> = corners.iter().map(|c| c.0).collect();
            if self.interactive {
                let data: Vec<&str> = corners.iter().map(|c| c.1.as_str()).collect();
                let _ = writeln!(
                    items,
                    "<polygon points=\"{}\" data-pts=\"{}\"/>",
                    points_attr(&pts),
                    data.join(" ")
                );
            } else {
                polygon_path(&mut static_d, pts);
            }
        }
        if !static_d.is_empty() {
            let _ = writeln!(o, "<path class=\"cracks\" d=\"{static_d}\" fill=\"{CRACK}\" fill-opacity=\"0.85\" stroke=\"{CRACK}\" stroke-width=\"0.6\" stroke-linejoin=\"round\"/>");
        }
        if !items.is_empty() {
            let _ = writeln!(o, "<g class=\"cracks\" fill=\"{CRACK}\" fill-opacity=\"0.85\" stroke=\"{CRACK}\" stroke-width=\"0.6\" stroke-linejoin=\"round\">\n{items}</g>");
        }
        n_cracks
    }

    /// The body a point of a crack moves with: the first body of the nearest of the crack's
    /// joints (the face the wedge opens from), else the nearest block.
    fn crack_body(&self, on: &[&JointResult], p: [f64; 2]) -> Option<usize> {
        let b = self.b;
        let mut best: Option<(f64, usize)> = None;
        for j in on {
            let Some(a) = b.body_of(&j.a) else { continue };
            let d = j
                .points
                .windows(2)
                .map(|w| {
                    voussoir::geometry::point_segment_distance(
                        p,
                        [w[0].x, w[0].y],
                        [w[1].x, w[1].y],
                    )
                })
                .fold(f64::INFINITY, f64::min);
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, a));
            }
        }
        best.map(|(_, a)| a).or_else(|| nearest_block(b, p))
    }

    /// The crack lines: each crack's polyline, its points carried by the body of the joint
    /// they lie on; the first ten numbered as in the summaries.
    pub(super) fn crack_lines(&self, o: &mut String) -> CrackLines {
        let scene = self.scene;
        let mut out = CrackLines { drawn: 0 };
        if !(self.opts.cracks && !scene.cracks.is_empty()) {
            return out;
        }
        let mut lines = String::new();
        let mut labels = String::new();
        let lw = (self.stroke * 2.4).clamp(1.4, 2.6);
        // Line width grows with the square root of the opening; cracks narrower than 1 % of the
        // widest (hairlines) are left out of the drawing (the summaries and the JSON list them).
        let widest = scene
            .cracks
            .iter()
            .fold(0.0f64, |m, c| m.max(c.max_opening));
        let fs = 11.0;
        for (n, c) in scene.cracks.iter().enumerate() {
            if !(c.max_opening >= HAIRLINE * widest) {
                // Left out with its hinges (visible_hinges).
                continue;
            }
            let on: Vec<&JointResult> = c
                .joints
                .iter()
                .filter_map(|j| self.joint_by_id.get(j).copied())
                .collect();
            let pts: Vec<([f64; 2], String)> = c
                .points
                .iter()
                .filter(|p| p[0].is_finite() && p[1].is_finite())
                .filter_map(|p| self.crack_body(&on, *p).map(|a| self.at(a, *p)))
                .collect();
            if pts.len() < 2 {
                continue;
            }
            out.drawn += 1;
            let xy: Vec<[f64; 2]> = pts.iter().map(|p| p.0).collect();
            let _ = write!(lines, "<polyline points=\"{}\"", points_attr(&xy));
            if widest > 0.0 && c.max_opening < widest {
                let w = (lw * (c.max_opening / widest).sqrt()).max(0.6);
                let _ = write!(lines, " stroke-width=\"{}\"", num(w));
            }
            if self.interactive {
                let data: Vec<&str> = pts.iter().map(|p| p.1.as_str()).collect();
                let _ = write!(lines, " data-pts=\"{}\"", data.join(" "));
            }
            lines.push_str("/>\n");
            if n < 10 {
                self.crack_label(&mut labels, &on, &c.points, n + 1);
            }
        }
        if !lines.is_empty() {
            let _ = writeln!(
                o,
                "<g class=\"crack-lines\" fill=\"none\" stroke=\"{CRACK_LINE}\" stroke-width=\"{}\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n{lines}</g>",
                num(lw)
            );
        }
        if !labels.is_empty() {
            let _ = writeln!(
                o,
                "<g class=\"crack-labels\" font-size=\"{fs}\" font-weight=\"bold\" fill=\"{CRACK_LINE}\" stroke=\"#ffffff\" stroke-width=\"3\" paint-order=\"stroke\">\n{labels}</g>"
            );
        }
        out
    }

    /// The number of a crack at its middle (by length, in the undeformed geometry), carried by
    /// the body there, offset off the line.
    fn crack_label(&self, labels: &mut String, on: &[&JointResult], points: &[[f64; 2]], n: usize) {
        let w: Vec<[f64; 2]> = points
            .iter()
            .copied()
            .filter(|p| p[0].is_finite() && p[1].is_finite())
            .collect();
        let half = 0.5
            * w.windows(2)
                .map(|s| (s[1][0] - s[0][0]).hypot(s[1][1] - s[0][1]))
                .sum::<f64>();
        let mut acc = 0.0;
        let mut mw = w[0];
        for s in w.windows(2) {
            let l = (s[1][0] - s[0][0]).hypot(s[1][1] - s[0][1]);
            if acc + l >= half && l > 0.0 {
                let t = (half - acc) / l;
                mw = [
                    s[0][0] + t * (s[1][0] - s[0][0]),
                    s[0][1] + t * (s[1][1] - s[0][1]),
                ];
                break;
            }
            acc += l;
        }
        let Some(a) = self.crack_body(on, mw) else {
            return;
        };
        let (p1, data) = self.at(a, mw);
        if self.interactive {
            // Written at its undeformed place and moved by the slider (data-at).
            let p0 = self.fr.px(mw);
            let _ = writeln!(
                labels,
                "<text x=\"{}\" y=\"{}\" transform=\"translate({} {})\" data-at=\"{data}\">{}</text>",
                num(p0[0] + 4.0),
                num(p0[1] - 4.0),
                num(p1[0] - p0[0]),
                num(p1[1] - p0[1]),
                n
            );
        } else {
            let _ = writeln!(
                labels,
                "<text x=\"{}\" y=\"{}\">{}</text>",
                num(p1[0] + 4.0),
                num(p1[1] - 4.0),
                n
            );
        }
    }

    /// Arrows (loads, contact forces), kept in their direction and carried by their body.
    pub(super) fn arrows(
        &self,
        o: &mut String,
        class: &str,
        colour: &str,
        list: &[LoadArrow],
        head: f64,
    ) {
        if list.is_empty() {
            return;
        }
        let fr = self.fr;
        let sw = (self.stroke * 1.6).clamp(1.0, 1.8);
        let _ = writeln!(
            o,
            "<g class=\"{class}\" stroke=\"{colour}\" fill=\"{colour}\" stroke-width=\"{}\">",
            num(sw)
        );
        if self.interactive && list.len() <= 2000 {
            for (body, tip, d, _) in list {
                let (p1, data) = self.at(*body, *tip);
                let p0 = fr.px(*tip);
                let tail = fr.px([tip[0] - d[0], tip[1] - d[1]]);
                let (mut sh, mut hd) = (String::new(), String::new());
                arrow(&mut sh, &mut hd, tail, p0, head);
                let _ = writeln!(
                    o,
                    "<g transform=\"translate({} {})\" data-at=\"{}\" data-ref=\"{},{}\"><path d=\"{sh}\" fill=\"none\"/><path d=\"{hd}\" stroke=\"none\"/></g>",
                    num(p1[0] - p0[0]),
                    num(p1[1] - p0[1]),
                    data,
                    num(p0[0]),
                    num(p0[1])
                );
            }
        } else {
            let (mut sh, mut hd) = (String::new(), String::new());
            for (body, tip, d, _) in list {
                let t = self.mo.moved(*body, *tip);
                arrow(
                    &mut sh,
                    &mut hd,
                    fr.px([t[0] - d[0], t[1] - d[1]]),
                    fr.px(t),
                    head,
                );
            }
            let _ = writeln!(
                o,
                "<path d=\"{sh}\" fill=\"none\"/>\n<path d=\"{hd}\" stroke=\"none\"/>"
            );
        }
        o.push_str("</g>\n");
    }

    /// The thrust line: centres of pressure joined along chains of bodies, with dots. Returns
    /// the legend's label of what was drawn (a line, or centres of pressure alone).
    pub(super) fn thrust(&self, o: &mut String) -> Option<&'static str> {
        let (scene, opts) = (self.scene, self.opts);
        if !(opts.thrust_line && !scene.thrust_line.is_empty()) {
            return None;
        }
        let chains = thrust_chains(scene, self.b, self.joint_by_id);
        // Dots on a thrust line (up to 400 a chain) unless --pressure-points off; dots on their
        // own (walls, façades) by the rule of PressurePoints.
        let lone = chains.iter().filter(|c| c.len() == 1).count();
        let lone_dots = opts.pressure_points.lone(lone);
        let mut lines = String::new();
        let mut dots = String::new();
        let dot_r = (self.hinge_r * 0.45).max(1.2);
        for chain in &chains {
            let pts: Vec<([f64; 2], String)> =
                chain.iter().map(|(body, p)| self.at(*body, *p)).collect();
            if pts.len() >= 2 {
                let xy: Vec<[f64; 2]> = pts.iter().map(|p| p.0).collect();
                let _ = write!(lines, "<polyline points=\"{}\"", points_attr(&xy));
                if self.interactive {
                    let data: Vec<&str> = pts.iter().map(|p| p.1.as_str()).collect();
                    let _ = write!(lines, " data-pts=\"{}\"", data.join(" "));
                }
                lines.push_str("/>\n");
            }
            let dots_here = match (chain.len(), opts.pressure_points) {
                (1, _) => lone_dots,
                (_, PressurePoints::Off) => false,
                (n, PressurePoints::Auto) => n <= 400,
                (_, PressurePoints::On) => true,
            };
            if dots_here {
                for p in &pts {
                    let _ = write!(
                        dots,
                        "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"",
                        num(p.0[0]),
                        num(p.0[1]),
                        num(dot_r)
                    );
                    if self.interactive {
                        let _ = write!(dots, " data-at=\"{}\"", p.1);
                    }
                    dots.push_str("/>\n");
                }
            }
        }
        if lines.is_empty() && dots.is_empty() {
            return None;
        }
        let _ = writeln!(
            o,
            "<g class=\"thrust-line\" fill=\"none\" stroke=\"{THRUST}\" stroke-width=\"{}\" stroke-linejoin=\"round\">\n{lines}</g>",
            num((self.stroke * 2.2).clamp(1.2, 2.2))
        );
        if !dots.is_empty() {
            let _ = writeln!(
                o,
                "<g class=\"pressure-centres\" fill=\"{THRUST}\">\n{dots}</g>"
            );
        }
        Some(if lines.is_empty() {
            "centre of pressure"
        } else {
            "thrust line"
        })
    }

    /// The hinges, on top: those of [`visible_hinges`]. Returns how many were drawn.
    pub(super) fn hinges(&self, o: &mut String, visible: &[(usize, [f64; 2])]) -> usize {
        if !(self.opts.hinges && !self.scene.hinges.is_empty()) {
            return 0;
        }
        let _ = writeln!(
            o,
            "<g class=\"hinges\" fill=\"{HINGE}\" stroke=\"#ffffff\" stroke-width=\"{}\">",
            num((self.hinge_r * 0.3).clamp(0.8, 1.5))
        );
        for &(a, q) in visible {
            let (p, data) = self.at(a, q);
            let _ = write!(
                o,
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"",
                num(p[0]),
                num(p[1]),
                num(self.hinge_r)
            );
            if self.interactive {
                let _ = write!(o, " data-at=\"{data}\"");
            }
            o.push_str("/>\n");
        }
        o.push_str("</g>\n");
        visible.len()
    }
}
