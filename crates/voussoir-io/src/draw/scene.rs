//! Drawings of structures and mechanisms: blocks, hatched supports, load arrows, the deformed
//! configuration over the faint undeformed outline, hinges, crack wedges, the thrust line and
//! contact-force arrows.
//!
//! Blocks are moved by exact finite rigid motions ([`RigidMotion::scaled`]). Blocks whose small
//! motions are the same rigid field (a macro-block of the mechanism) share one reference point,
//! so each macro-block moves as one rigid piece and is drawn in one colour; a block at rest is
//! drawn in stone grey.

mod layers;

use super::legend::Entry;
use super::svg::{esc, fmt_fixed, human, nice, num};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use voussoir::geometry::{area_centroid, RigidMotion};
use voussoir::result::{
    BlockMotion, BodyName, Crack, Geometry, Hinge, JointResult, JointState, ThrustPoint,
};
use voussoir::result::{LimitResult, LimitStatus, SettlementResult};

/// What the block motions of a scene mean.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionUnits {
    /// A collapse mechanism normalised so that the live loads do unit work: the amplitude is
    /// arbitrary and only the shape matters.
    Normalised,
    /// Displacements in metres (settlement analyses): supports move by their prescribed motion.
    Metres,
}

/// Everything a structure drawing can show. Build it from a result with [`Scene::limit`],
/// [`Scene::settlement`] or [`Scene::geometry`], then adjust the title or info lines.
#[derive(Clone, Debug)]
pub struct Scene<'a> {
    pub title: String,
    /// Lines printed under the title (key numbers).
    pub info: Vec<String>,
    pub geometry: &'a Geometry,
    /// Block motions (u, v, θ) at the block centroids; empty: nothing moves.
    pub blocks: &'a [BlockMotion],
    pub joints: &'a [JointResult],
    pub hinges: &'a [Hinge],
    /// The cracks as polylines, widest first ([`voussoir::result::cracks`]): drawn as lines,
    /// the first ten numbered as the summaries number them.
    pub cracks: &'a [Crack],
    pub thrust_line: &'a [ThrustPoint],
    pub units: MotionUnits,
    /// Whether the analysis multiplies the live loads by λ (limit analyses, models). A
    /// settlement analysis has no λ and ignores live loads: they are not drawn.
    pub live_loads: bool,
    /// The collapse load multiplier the live loads are multiplied by (a limit analysis that
    /// found a mechanism): the legend states the factored load. `None`: drawn unfactored.
    pub load_multiplier: Option<f64>,
    /// A tilting table: the critical tilt angle α (degrees) and where the structure falls
    /// ("towards +x"), for the legend.
    pub tilt: Option<(f64, String)>,
}

impl<'a> Scene<'a> {
    /// The structure alone: blocks, supports, loads.
    pub fn geometry(geometry: &'a Geometry, title: &str) -> Self {
        let nl = geometry.loads.iter().filter(|l| l.live).count();
        let mut info = vec![format!(
            "{} blocks, {} supports, {} load{} ({} live)",
            geometry.blocks.len(),
            geometry.supports.len(),
            geometry.loads.len(),
            if geometry.loads.len() == 1 { "" } else { "s" },
            nl
        )];
        if let Some(m) = support_motion_text(geometry) {
            info.push(m);
        }
        Scene {
            title: title.to_string(),
            info,
            geometry,
            blocks: &[],
            joints: &[],
            hinges: &[],
            cracks: &[],
            thrust_line: &[],
            units: MotionUnits::Metres,
            live_loads: true,
            load_multiplier: None,
            tilt: None,
        }
    }

    /// A limit analysis: the collapse mechanism, hinges and thrust line at collapse.
    pub fn limit(r: &'a LimitResult) -> Self {
        let title = match r.status {
            LimitStatus::Collapse => "Collapse mechanism".to_string(),
            LimitStatus::Locked => "No collapse: locked".to_string(),
            LimitStatus::NoEquilibrium => "No equilibrium under the dead loads".to_string(),
        };
        let mut info = Vec::new();
        match r.load_multiplier {
            Some(l) if r.status == LimitStatus::Collapse => info.push(format!(
                "collapse load multiplier λ = {l:.4}   ·   {}",
                plural(hinged_joints(&r.hinges), "hinge")
            )),
            _ => info.push(r.message.clone()),
        }
        Scene {
            title,
            info,
            geometry: &r.geometry,
            blocks: &r.blocks,
            joints: &r.joints,
            hinges: &r.hinges,
            cracks: &r.cracks,
            thrust_line: &r.thrust_line,
            units: MotionUnits::Normalised,
            live_loads: true,
            load_multiplier: r
                .load_multiplier
                .filter(|l| l.is_finite() && r.status == LimitStatus::Collapse),
            tilt: None,
        }
    }

    /// A settlement analysis: the mechanism that accommodates the prescribed support motions.
    pub fn settlement(r: &'a SettlementResult) -> Self {
        let mut info = Vec::new();
        if let Some(m) = support_motion_text(&r.geometry) {
            info.push(m);
        }
        let open = r
            .joints
            .iter()
            .filter(|j| j.state == JointState::Open)
            .count();
        let mut line = plural(hinged_joints(&r.hinges), "hinge");
        if open > 0 {
            let _ = write!(line, ", {}", plural(open, "open joint"));
        }
        if let Some(c) = &r.certificate {
            let _ = write!(
                line,
                "   ·   duality gap {} ({})",
                human(c.relative_gap, 2),
                if c.ok { "certified" } else { "NOT certified" }
            );
        } else {
            line = r.message.clone();
        }
        info.push(line);
        Scene {
            title: "Settlement mechanism".to_string(),
            info,
            geometry: &r.geometry,
            blocks: &r.blocks,
            joints: &r.joints,
            hinges: &r.hinges,
            cracks: &r.cracks,
            thrust_line: &r.thrust_line,
            units: MotionUnits::Metres,
            live_loads: false,
            load_multiplier: None,
            tilt: None,
        }
    }
}

fn plural(n: usize, what: &str) -> String {
    format!("{n} {what}{}", if n == 1 { "" } else { "s" })
}

/// Supports listed one by one in a drawing's subtitle; more moving supports are summarised.
const LISTED_SUPPORTS: usize = 3;

/// "prescribed support motion: right u = 10 mm, v = 0 mm" for the supports that move; with more
/// than [`LISTED_SUPPORTS`] moving supports (a façade on 44 segments) one summary that fits on a
/// line: "44 supports (f0 … f43): u = 0 mm, v = −200 mm" or the range of each component.
pub fn support_motion_text(g: &Geometry) -> Option<String> {
    let moving: Vec<_> = g
        .supports
        .iter()
        .filter(|s| s.motion.iter().any(|&x| x != 0.0 && x.is_finite()))
        .collect();
    if moving.is_empty() {
        return None;
    }
    if moving.len() > LISTED_SUPPORTS {
        let range = |k: usize, scale: f64, unit: &str, name: &str| -> String {
            let lo = moving
                .iter()
                .map(|s| s.motion[k])
                .fold(f64::INFINITY, f64::min)
                * scale;
            let hi = moving
                .iter()
                .map(|s| s.motion[k])
                .fold(f64::NEG_INFINITY, f64::max)
                * scale;
            if lo == hi {
                format!("{name} = {}{unit}", human(lo, 3))
            } else {
                format!("{name} from {} to {}{unit}", human(lo, 3), human(hi, 3))
            }
        };
        let mut t = format!(
            "prescribed support motion: {} supports ({} … {}): {}, {}",
            moving.len(),
            moving[0].name,
            moving[moving.len() - 1].name,
            range(0, 1000.0, " mm", "u"),
            range(1, 1000.0, " mm", "v")
        );
        if moving.iter().any(|s| s.motion[2] != 0.0) {
            let _ = write!(t, ", {}", range(2, 180.0 / std::f64::consts::PI, "°", "θ"));
        }
        let fixed = moving.iter().filter(|s| s.fixed).count();
        if fixed > 0 {
            let _ = write!(t, " ({fixed} fixed)");
        }
        return Some(t);
    }
    let parts: Vec<String> = moving
        .iter()
        .map(|s| {
            let mut t = format!(
                "{} u = {} mm, v = {} mm",
                s.name,
                human(s.motion[0] * 1000.0, 3),
                human(s.motion[1] * 1000.0, 3)
            );
            if s.motion[2] != 0.0 {
                let _ = write!(t, ", θ = {}°", human(s.motion[2].to_degrees(), 3));
            }
            if s.fixed {
                t.push_str(" (fixed)");
            }
            t
        })
        .collect();
    Some(format!("prescribed support motion: {}", parts.join("; ")))
}

/// Whether the centres of pressure are drawn as dots (2D and 3D drawings).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PressurePoints {
    /// Dots on a 2D thrust line (an arch's chain of joints) always; dots on their own (walls,
    /// façades, every 3D drawing) only when there are at most [`PRESSURE_POINTS_AUTO`].
    #[default]
    Auto,
    /// Every centre of pressure.
    On,
    /// None (a 2D thrust line is still drawn).
    Off,
}

/// [`PressurePoints::Auto`] draws lone centres of pressure up to this many.
pub const PRESSURE_POINTS_AUTO: usize = 60;

impl PressurePoints {
    /// Whether `n` lone centres of pressure are drawn.
    pub fn lone(self, n: usize) -> bool {
        match self {
            PressurePoints::Auto => n <= PRESSURE_POINTS_AUTO,
            PressurePoints::On => true,
            PressurePoints::Off => false,
        }
    }
}

/// How to draw a scene.
#[derive(Clone, Debug)]
pub struct DrawOptions {
    /// Displacement scale factor; `None`: automatic (the largest displacement drawn is about 7 %
    /// of the structure's size, rounded to 1, 2 or 5 × 10ⁿ).
    pub scale: Option<f64>,
    /// Width of the figure in pixels.
    pub width: f64,
    /// Largest height of the drawing area in pixels (tall structures are narrowed to fit).
    pub max_height: f64,
    /// Draw the deformed configuration (when the scene has motions).
    pub deformed: bool,
    /// Draw the undeformed outline, faint, behind the deformed configuration.
    pub undeformed: bool,
    pub hinges: bool,
    pub cracks: bool,
    pub thrust_line: bool,
    /// The centres of pressure as dots.
    pub pressure_points: PressurePoints,
    /// Contact-force resultants as arrows (scaled by magnitude) at the centres of pressure.
    pub forces: bool,
    pub live_loads: bool,
    pub dead_loads: bool,
    pub legend: bool,
    /// Write the data the HTML report's displacement-scale slider needs.
    pub interactive: bool,
    /// Prefix for element ids (pattern, markers), unique per figure in one HTML page.
    pub id: String,
}

impl Default for DrawOptions {
    fn default() -> Self {
        DrawOptions {
            scale: None,
            width: 1000.0,
            max_height: 760.0,
            deformed: true,
            undeformed: true,
            hinges: true,
            cracks: true,
            thrust_line: true,
            pressure_points: PressurePoints::Auto,
            forces: false,
            live_loads: true,
            dead_loads: false,
            legend: true,
            interactive: false,
            id: "v".to_string(),
        }
    }
}

/// The world → pixel map of a drawing: `px = (ox + k·x, oy − k·y)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Pixels per metre.
    pub k: f64,
    pub ox: f64,
    pub oy: f64,
}

impl Frame {
    pub fn px(&self, p: [f64; 2]) -> [f64; 2] {
        [self.ox + self.k * p[0], self.oy - self.k * p[1]]
    }
}

/// A finished drawing.
#[derive(Clone, Debug)]
pub struct Drawing {
    pub svg: String,
    pub width: f64,
    pub height: f64,
    /// The displacement scale factor used (0 when nothing moves).
    pub scale: f64,
    /// Where world points land.
    pub frame: Frame,
    /// Whether a deformed configuration was drawn.
    pub deformed: bool,
}

use super::chrome::{Bbox, Page, MARGIN};
pub(crate) use super::chrome::{
    CRACK, CRACK_LINE, EDGE, FAINT, FORCE, HAIRLINE, HINGE, LOAD, PALETTE, STILL, STONE, THRUST,
};

/// One body (block or support).
struct Body {
    poly: Vec<[f64; 2]>,
    /// Index into `groups`.
    group: usize,
}

/// A set of bodies drawn with one rigid motion: each moving body is its own group (moved by
/// [`RigidMotion::scaled`] about its own centroid, as the library's `deform` does); the blocks at
/// rest share one group.
struct Group {
    /// Reference point (the body's centroid) and small motion (u, v, θ) there.
    center: [f64; 2],
    d: [f64; 3],
    moving: bool,
    support: bool,
    /// Colour class: moving blocks of one macro-block (the same small rigid field) share one.
    colour: usize,
    /// The bodies of the group.
    members: Vec<usize>,
}

fn finite3(d: [f64; 3]) -> [f64; 3] {
    if d.iter().all(|x| x.is_finite()) {
        d
    } else {
        [0.0; 3]
    }
}

pub(crate) fn centroid(p: &[[f64; 2]]) -> [f64; 2] {
    if p.is_empty() {
        return [0.0, 0.0];
    }
    let (a, c) = area_centroid(p);
    if a > 0.0 && c.iter().all(|x| x.is_finite()) {
        c
    } else {
        let n = p.len() as f64;
        [
            p.iter().map(|q| q[0]).sum::<f64>() / n,
            p.iter().map(|q| q[1]).sum::<f64>() / n,
        ]
    }
}

fn clean_poly(p: &[[f64; 2]]) -> Vec<[f64; 2]> {
    p.iter()
        .copied()
        .filter(|q| q[0].is_finite() && q[1].is_finite())
        .collect()
}

/// Everything computed about the bodies before layout.
struct Bodies {
    bodies: Vec<Body>,
    groups: Vec<Group>,
    nb: usize,
    support_index: BTreeMap<String, usize>,
    /// Largest small displacement of any vertex (m, or normalised units) and rotation (rad).
    dmax: f64,
    tmax: f64,
    size: f64,
    mean_block: f64,
}

fn build_bodies(scene: &Scene) -> Bodies {
    let g = scene.geometry;
    let nb = g.blocks.len();
    let mut motions = vec![[0.0; 3]; nb];
    for m in scene.blocks {
        if m.id < nb {
            motions[m.id] = finite3([m.u, m.v, m.theta]);
        }
    }
    let mut bbox = Bbox::new();
    let mut polys: Vec<Vec<[f64; 2]>> = Vec::with_capacity(nb + g.supports.len());
    let mut area_sum = 0.0;
    for p in &g.blocks {
        let q = clean_poly(p);
        for v in &q {
            bbox.add(*v);
        }
        if q.len() >= 3 {
            area_sum += area_centroid(&q).0;
        }
        polys.push(q);
    }
    for s in &g.supports {
        let q = clean_poly(&s.polygon);
        for v in &q {
            bbox.add(*v);
        }
        polys.push(q);
    }
    let size = if bbox.valid() {
        (bbox.0[2] - bbox.0[0]).max(bbox.0[3] - bbox.0[1]).max(1e-9)
    } else {
        1.0
    };
    let origin = if bbox.valid() {
        [(bbox.0[0] + bbox.0[2]) / 2.0, (bbox.0[1] + bbox.0[3]) / 2.0]
    } else {
        [0.0, 0.0]
    };
    let mean_block = if nb > 0 && area_sum > 0.0 {
        (area_sum / nb as f64).sqrt()
    } else {
        size / 10.0
    };

    // Small displacements: the largest vertex displacement.
    let mut dmax = 0.0f64;
    let mut centers = Vec::with_capacity(polys.len());
    let mut all_d = Vec::with_capacity(polys.len());
    for (i, p) in polys.iter().enumerate() {
        let c = centroid(p);
        // Supports move by their prescribed motion only in a settlement mechanism (not in a
        // drawing of the model, nor when the analysis found no mechanism).
        let d = if i < nb {
            motions[i]
        } else if scene.units == MotionUnits::Metres && !scene.blocks.is_empty() {
            finite3(g.supports[i - nb].motion)
        } else {
            [0.0; 3]
        };
        for v in p {
            let w = voussoir::geometry::small_displacement(c, d, *v);
            dmax = dmax.max(w[0].hypot(w[1]));
        }
        centers.push(c);
        all_d.push(d);
    }
    // Group the blocks by their rigid field: θ and the displacement of a common point.
    let tmax = all_d
        .iter()
        .fold(0.0f64, |m, d| m.max(d[2].abs()))
        .max(1e-300);
    let umax = dmax.max(1e-300);
    let key = |c: [f64; 2], d: [f64; 3]| -> (i64, i64, i64) {
        let w = voussoir::geometry::small_displacement(c, d, origin);
        let q = |x: f64, r: f64| ((x / r) * 1e7).round() as i64;
        (q(w[0], umax), q(w[1], umax), q(d[2], tmax))
    };
    let mut groups: Vec<Group> = Vec::new();
    let mut colours: BTreeMap<(i64, i64, i64), usize> = BTreeMap::new();
    let mut still: Option<usize> = None;
    let mut bodies = Vec::with_capacity(polys.len());
    let still_tol = 1e-9 * umax;
    let mut tmax_moving = 0.0f64;
    for (i, p) in polys.into_iter().enumerate() {
        let (c, d) = (centers[i], all_d[i]);
        let moving = p.iter().any(|v| {
            let w = voussoir::geometry::small_displacement(c, d, *v);
            w[0].hypot(w[1]) > still_tol
        }) && dmax > 0.0;
        let support = i >= nb;
        let group = if moving || support {
            if moving {
                tmax_moving = tmax_moving.max(d[2].abs());
            }
            let n = colours.len();
            let colour = if moving && !support {
                *colours.entry(key(c, d)).or_insert(n)
            } else {
                0
            };
            groups.push(Group {
                center: c,
                d: if moving { d } else { [0.0; 3] },
                moving,
                support,
                colour,
                members: vec![i],
            });
            groups.len() - 1
        } else {
            let gi = *still.get_or_insert_with(|| {
                groups.push(Group {
                    center: c,
                    d: [0.0; 3],
                    moving: false,
                    support: false,
                    colour: 0,
                    members: vec![],
                });
                groups.len() - 1
            });
            groups[gi].members.push(i);
            gi
        };
        bodies.push(Body { poly: p, group });
    }
    let support_index = g
        .supports
        .iter()
        .enumerate()
        .map(|(s, sp)| (sp.name.clone(), nb + s))
        .collect();
    Bodies {
        bodies,
        groups,
        nb,
        support_index,
        dmax,
        tmax: tmax_moving,
        size,
        mean_block,
    }
}

/// The block whose outline passes nearest to `p`.
fn nearest_block(b: &Bodies, p: [f64; 2]) -> Option<usize> {
    let mut best = None;
    let mut best_d = f64::INFINITY;
    for (i, body) in b.bodies.iter().enumerate().take(b.nb) {
        let n = body.poly.len();
        for k in 0..n {
            let d =
                voussoir::geometry::point_segment_distance(p, body.poly[k], body.poly[(k + 1) % n]);
            if d < best_d {
                best_d = d;
                best = Some(i);
            }
        }
    }
    best
}

impl Bodies {
    fn body_of(&self, b: &BodyName) -> Option<usize> {
        match b {
            BodyName::Block(i) if *i < self.nb => Some(*i),
            BodyName::Block(_) => None,
            BodyName::Support(s) => self.support_index.get(s).copied(),
        }
    }
}

/// Pixel-frame motion of a group, unscaled: `[cx, cy, u, v, φ]` with φ the pixel-frame angle.
fn px_motion(fr: &Frame, g: &Group) -> [f64; 5] {
    let c = fr.px(g.center);
    [c[0], c[1], fr.k * g.d[0], -fr.k * g.d[1], -g.d[2]]
}

/// Apply a pixel-frame motion at scale `s` to a pixel point (same formula as the report's JS).
fn px_apply(m: &[f64; 5], s: f64, p: [f64; 2]) -> [f64; 2] {
    let (sn, cs) = (s * m[4]).sin_cos();
    let (dx, dy) = (p[0] - m[0], p[1] - m[1]);
    [
        m[0] + s * m[2] + cs * dx - sn * dy,
        m[1] + s * m[3] + sn * dx + cs * dy,
    ]
}

fn px_matrix(m: &[f64; 5], s: f64) -> String {
    let (sn, cs) = (s * m[4]).sin_cos();
    let e = m[0] + s * m[2] - (cs * m[0] - sn * m[1]);
    let f = m[1] + s * m[3] - (sn * m[0] + cs * m[1]);
    format!(
        "matrix({} {} {} {} {} {})",
        fmt_fixed(cs, 7),
        fmt_fixed(sn, 7),
        fmt_fixed(-sn, 7),
        fmt_fixed(cs, 7),
        num(e),
        num(f)
    )
}

/// World-frame finite motion of a group at scale `s`.
fn world_motion(g: &Group, s: f64) -> RigidMotion {
    if g.moving {
        RigidMotion::scaled(g.center, g.d, s)
    } else {
        RigidMotion::scaled(g.center, [0.0; 3], 0.0)
    }
}

/// The automatic displacement scale: the largest displacement drawn is about 7 % of the size
/// `size`, and no block turns by much more than 0.15 rad (so that the second-order separation of
/// blocks moved about their own centroids stays below a pixel or so), rounded to 1, 2 or 5 × 10ⁿ.
/// `dmax` is the largest small displacement, `tmax` the largest rotation of the mechanism.
pub fn auto_scale(dmax: f64, tmax: f64, size: f64) -> f64 {
    if !(dmax > 0.0 && dmax.is_finite() && size > 0.0) {
        return 1.0;
    }
    let by_size = 0.07 * size / dmax;
    let by_rotation = if tmax > 0.0 && tmax.is_finite() {
        0.15 / tmax
    } else {
        f64::INFINITY
    };
    let s = nice(by_size.min(by_rotation), false);
    if s > 1.3 * by_rotation {
        nice(by_rotation, true)
    } else {
        s
    }
}

/// Draw a scene as SVG, in stages: the motion of the bodies at the drawing's scale
/// ([`Motion`]), the arrows to draw ([`Arrows`]), the layout of the page ([`Layout`]), the
/// layers painted in order ([`layers::Painter`]), and the legend of what was
/// drawn.
pub fn draw(scene: &Scene, opts: &DrawOptions) -> Drawing {
    let mo = Motion::new(scene, opts);
    let joint_by_id: BTreeMap<usize, &JointResult> =
        scene.joints.iter().map(|j| (j.id, j)).collect();
    let ar = Arrows::new(scene, opts, &mo, &joint_by_id);
    let visible = layers::visible_hinges(scene, opts, &mo.b, &joint_by_id);
    let mut info = if opts.hinges {
        hinge_info(&scene.info, hinged_joints(scene.hinges), visible.len())
    } else {
        scene.info.clone()
    };
    if opts.cracks {
        info.extend(hairline_info(scene));
    }
    let lay = Layout::new(scene, &info, opts, &mo, &ar);
    let b = &mo.b;
    let has_motion = mo.has_motion;
    let interactive = opts.interactive && has_motion;
    let p = layers::Painter::new(scene, opts, &mo, &lay.fr, &joint_by_id, interactive);

    let mut o = String::with_capacity(4096 + 120 * b.bodies.len());
    lay.page.open(&mut o, lay.height);
    if interactive {
        p.motion_data(&mut o, mo.scale);
    }
    o.push_str(">\n");
    lay.page.head(&mut o, &p.id, lay.height, &scene.title);

    p.undeformed(&mut o);
    p.bodies(&mut o);
    let n_cracks = p.crack_wedges(&mut o);
    let lines = p.crack_lines(&mut o);
    let head = (0.018 * lay.page.width).clamp(6.0, 11.0);
    let live: Vec<_> = ar.loads.iter().copied().filter(|l| l.3).collect();
    let dead: Vec<_> = ar.loads.iter().copied().filter(|l| !l.3).collect();
    p.arrows(&mut o, "dead-loads", "#555555", &dead, head);
    p.arrows(&mut o, "live-loads", LOAD, &live, head);
    // Contact forces: arrows centred on the centre of pressure.
    if !ar.forces.is_empty() {
        let centred: Vec<LoadArrow> = ar
            .forces
            .iter()
            .map(|(a, q, d)| (*a, [q[0] + d[0] / 2.0, q[1] + d[1] / 2.0], *d, true))
            .collect();
        p.arrows(&mut o, "contact-forces", FORCE, &centred, head);
    }
    let drew_thrust = p.thrust(&mut o);
    let n_hinges = p.hinges(&mut o, &visible);

    if b.bodies.is_empty() {
        lay.page.nothing_to_draw(&mut o, lay.draw_h);
    }
    let (width, margin) = (lay.page.width, MARGIN);
    if opts.legend {
        let items = LegendItems {
            undeformed: has_motion && opts.undeformed,
            hinges: n_hinges > 0,
            cracks: n_cracks > 0,
            crack_lines: lines.drawn > 0,
            thrust: drew_thrust,
            live: (!live.is_empty()).then_some(ar.live_max),
            dead: (!dead.is_empty()).then_some(ar.dead_max),
            forces: (!ar.forces.is_empty()).then_some(ar.force_max),
            supports: b.nb < b.bodies.len(),
        };
        let e = legend_entries(
            scene,
            &items,
            &p.id,
            lay.fr.k,
            b.size,
            has_motion,
            mo.scale,
            interactive,
        );
        super::legend::write(
            &mut o,
            &e,
            margin,
            width - margin,
            lay.height - lay.legend_h,
        );
    }
    o.push_str("</svg>\n");
    Drawing {
        svg: o,
        width,
        height: lay.height,
        scale: mo.scale,
        frame: lay.fr,
        deformed: has_motion,
    }
}

/// An arrow to draw: (body it moves with, tip, vector in m of drawing, live load).
type LoadArrow = (usize, [f64; 2], [f64; 2], bool);

/// Stage 1: the bodies, and their finite motions at the drawing's displacement scale (0 when
/// nothing moves or the undeformed configuration is asked for).
struct Motion {
    b: Bodies,
    has_motion: bool,
    /// The displacement scale (0 when nothing moves).
    scale: f64,
    motions: Vec<RigidMotion>,
}

impl Motion {
    fn new(scene: &Scene, opts: &DrawOptions) -> Motion {
        let b = build_bodies(scene);
        let has_motion = opts.deformed && b.dmax > 0.0 && b.groups.iter().any(|g| g.moving);
        let scale = if has_motion {
            match opts.scale {
                Some(s) if s.is_finite() && s >= 0.0 => s,
                _ => auto_scale(b.dmax, b.tmax, b.size),
            }
        } else {
            0.0
        };
        let motions = b.groups.iter().map(|g| world_motion(g, scale)).collect();
        Motion {
            b,
            has_motion,
            scale,
            motions,
        }
    }

    /// A point of body `body` in its moved position (world units).
    fn moved(&self, body: usize, p: [f64; 2]) -> [f64; 2] {
        self.motions[self.b.bodies[body].group].apply(p)
    }
}

/// Stage 2: the load arrows and the contact-force arrows to draw, with the largest of each
/// kind (the legend's reference arrows).
struct Arrows {
    loads: Vec<LoadArrow>,
    live_max: f64,
    dead_max: f64,
    /// (body a, centre of pressure, force vector in m of drawing).
    forces: Vec<(usize, [f64; 2], [f64; 2])>,
    force_max: f64,
}

impl Arrows {
    fn new(
        scene: &Scene,
        opts: &DrawOptions,
        mo: &Motion,
        joint_by_id: &BTreeMap<usize, &JointResult>,
    ) -> Arrows {
        let b = &mo.b;
        let largest = |live: bool| {
            scene
                .geometry
                .loads
                .iter()
                .filter(|l| l.live == live)
                .fold(0.0f64, |m, l| m.max(l.fx.hypot(l.fy)))
        };
        let (live_max, dead_max) = (largest(true), largest(false));
        let arrow_len = 0.09 * b.size;
        let mut loads = Vec::new();
        for l in &scene.geometry.loads {
            let (show, fmax) = if l.live {
                (opts.live_loads && scene.live_loads, live_max)
            } else {
                (opts.dead_loads, dead_max)
            };
            let f = l.fx.hypot(l.fy);
            if !show
                || !(f > 0.0)
                || !(fmax > 0.0)
                || l.block >= b.nb
                || !l.x.is_finite()
                || !l.y.is_finite()
            {
                continue;
            }
            let len = arrow_len * (f / fmax).max(0.25);
            loads.push((
                l.block,
                [l.x, l.y],
                [l.fx / f * len, l.fy / f * len],
                l.live,
            ));
        }
        let mut forces = Vec::new();
        let mut force_max = 0.0f64;
        if opts.forces {
            let fmax = scene
                .thrust_line
                .iter()
                .filter_map(|t| joint_by_id.get(&t.joint))
                .fold(0.0f64, |m, j| m.max(j.normal_force.hypot(j.shear_force)));
            force_max = fmax;
            for t in scene.thrust_line {
                let Some(j) = joint_by_id.get(&t.joint) else {
                    continue;
                };
                let Some(a) = b.body_of(&j.a) else { continue };
                let n = j.normal;
                let tg = [-n[1], n[0]];
                let f = [
                    j.normal_force * n[0] + j.shear_force * tg[0],
                    j.normal_force * n[1] + j.shear_force * tg[1],
                ];
                let mag = f[0].hypot(f[1]);
                if !(mag > 0.0) || !(fmax > 0.0) || !t.x.is_finite() || !t.y.is_finite() {
                    continue;
                }
                let len = 0.12 * b.size * mag / fmax;
                forces.push((a, [t.x, t.y], [f[0] / mag * len, f[1] / mag * len]));
            }
        }
        Arrows {
            loads,
            live_max,
            dead_max,
            forces,
            force_max,
        }
    }
}

/// Stage 3: the page: the bounding box of everything drawn, the world → pixel frame, the
/// legend's height (of the entries that may be drawn) and the page's height.
struct Layout {
    page: Page,
    fr: Frame,
    legend_h: f64,
    draw_h: f64,
    height: f64,
}

impl Layout {
    fn new(scene: &Scene, info: &[String], opts: &DrawOptions, mo: &Motion, ar: &Arrows) -> Layout {
        let b = &mo.b;
        let has_motion = mo.has_motion;
        // Bounding box of everything drawn, in world units.
        let mut bb = Bbox::new();
        for (i, body) in b.bodies.iter().enumerate() {
            for v in &body.poly {
                if !has_motion || opts.undeformed {
                    bb.add(*v);
                }
                bb.add(mo.moved(i, *v));
            }
        }
        for (blk, tip, d, _) in &ar.loads {
            let t = mo.moved(*blk, *tip);
            bb.add([t[0] - d[0], t[1] - d[1]]);
            bb.add(t);
        }
        for (a, p, d) in &ar.forces {
            let c = mo.moved(*a, *p);
            bb.add([c[0] - d[0] / 2.0, c[1] - d[1] / 2.0]);
            bb.add([c[0] + d[0] / 2.0, c[1] + d[1] / 2.0]);
        }
        if !bb.valid() {
            bb = Bbox([0.0, 0.0, 1.0, 1.0]);
        }
        let (bw, bh) = ((bb.0[2] - bb.0[0]).max(1e-9), (bb.0[3] - bb.0[1]).max(1e-9));

        let page = Page::new(opts.width, opts.max_height, 760.0, info);
        let (width, max_h, margin, title_h) = (page.width, page.max_height, MARGIN, page.title_h);
        let k = ((width - 2.0 * margin) / bw).min(max_h / bh);
        // The legend's height: the entries that may be drawn (a superset of those drawn),
        // flowed and wrapped within the figure (super::legend).
        let may = LegendItems {
            undeformed: has_motion && opts.undeformed,
            hinges: opts.hinges && !scene.hinges.is_empty(),
            cracks: opts.cracks && scene.joints.iter().any(|j| j.state != JointState::Closed),
            crack_lines: opts.cracks && !scene.cracks.is_empty(),
            thrust: (opts.thrust_line && !scene.thrust_line.is_empty())
                .then_some("centre of pressure"),
            live: ar.loads.iter().any(|l| l.3).then_some(ar.live_max),
            dead: ar.loads.iter().any(|l| !l.3).then_some(ar.dead_max),
            forces: (!ar.forces.is_empty()).then_some(ar.force_max),
            supports: b.nb < b.bodies.len(),
        };
        let legend_h = if opts.legend {
            let e = legend_entries(scene, &may, &opts.id, k, b.size, has_motion, 0.0, false);
            super::legend::height(super::legend::layout(&e, margin, width - margin).height)
        } else {
            8.0
        };
        let draw_w = bw * k;
        let draw_h = bh * k;
        let height = (title_h + margin + draw_h + margin + legend_h).ceil();
        let fr = Frame {
            k,
            ox: (width - draw_w) / 2.0 - k * bb.0[0],
            oy: title_h + margin + k * bb.0[3],
        };
        Layout {
            page,
            fr,
            legend_h,
            draw_h,
            height,
        }
    }
}

/// The info lines with their count of hinges (`listed`: "93 hinges", the result's hinged
/// joints) made the count of hinge dots drawn (`drawn`) where the two differ: "4 hinges drawn
/// of 93 hinged joints" (the others are bends of crack lines or ends of hairlines, which the
/// drawing does not mark; [`layers::visible_hinges`]).
fn hinge_info(info: &[String], listed: usize, drawn: usize) -> Vec<String> {
    let from = plural(listed, "hinge");
    let to = format!("{} drawn of {listed} hinged joints", plural(drawn, "hinge"));
    info.iter()
        .map(|line| {
            if drawn == listed {
                return line.clone();
            }
            let mut at = 0;
            while let Some(k) = line[at..].find(&from).map(|k| k + at) {
                let end = k + from.len();
                let before = line[..k].chars().next_back();
                let after = line[end..].chars().next();
                if before.is_none_or(|c| c == ' ') && after.is_none_or(|c| c == ' ' || c == ',') {
                    return format!("{}{to}{}", &line[..k], &line[end..]);
                }
                at = end;
            }
            line.clone()
        })
        .collect()
}

/// The line that says which cracks the drawing leaves out: those narrower than [`HAIRLINE`] of
/// the widest (the summary and the JSON list them), how many and the widest of them (mm for a
/// settlement, relative to the widest crack for a collapse mechanism).
fn hairline_info(scene: &Scene) -> Option<String> {
    let widest = scene
        .cracks
        .iter()
        .fold(0.0f64, |m, c| m.max(c.max_opening));
    let left: Vec<f64> = scene
        .cracks
        .iter()
        .map(|c| c.max_opening)
        .filter(|w| !(*w >= HAIRLINE * widest))
        .collect();
    if left.is_empty() || !(widest > 0.0) {
        return None;
    }
    let most = left.iter().fold(0.0f64, |m, w| m.max(*w));
    let pct = HAIRLINE * 100.0;
    let (n, s) = (left.len(), if left.len() == 1 { "" } else { "s" });
    Some(if scene.units == MotionUnits::Metres {
        format!(
            "{n} hairline crack{s} narrower than {pct} % of the widest not drawn (the widest of them {})",
            voussoir_io_opening(most)
        )
    } else {
        format!(
            "{n} hairline crack{s} narrower than {pct} % of the widest not drawn (relative opening at most {most_rel:.4})",
            most_rel = most / widest
        )
    })
}

/// An opening in mm as the summaries write it.
fn voussoir_io_opening(w: f64) -> String {
    voussoir::lengths::Length::Opening.show(w)
}

/// The number of hinged joints among `hinges` (a joint's hinge points counted once, as the
/// summaries and the 3D figures count them).
fn hinged_joints(hinges: &[voussoir::result::Hinge]) -> usize {
    hinges
        .iter()
        .map(|h| h.joint)
        .collect::<std::collections::BTreeSet<_>>()
        .len()
}

/// Chains of (body a, centre of pressure) ordered along the structure. A body touched by more
/// than two loaded joints (walls) gives no line: each centre of pressure is its own chain.
fn thrust_chains(
    scene: &Scene,
    b: &Bodies,
    joints: &BTreeMap<usize, &JointResult>,
) -> Vec<Vec<(usize, [f64; 2])>> {
    // Edges: (body a, body b, point, body to move it with).
    let mut edges: Vec<(usize, usize, [f64; 2])> = Vec::new();
    let mut carrier: Vec<usize> = Vec::new();
    for t in scene.thrust_line {
        let Some(j) = joints.get(&t.joint) else {
            continue;
        };
        let (Some(a), Some(c)) = (b.body_of(&j.a), b.body_of(&j.b)) else {
            continue;
        };
        if !t.x.is_finite() || !t.y.is_finite() {
            continue;
        }
        edges.push((a, c, [t.x, t.y]));
        carrier.push(a);
    }
    let n = b.bodies.len();
    let mut adj: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (e, (a, c, _)) in edges.iter().enumerate() {
        adj[*a].push(e);
        adj[*c].push(e);
    }
    if adj.iter().any(|v| v.len() > 2) {
        return edges
            .iter()
            .zip(&carrier)
            .map(|(e, c)| vec![(*c, e.2)])
            .collect();
    }
    // Two centres of pressure are joined only through a block they both bear on: a support
    // ends the chain (an arch whose two springings stand on one support is one chain from
    // springing to springing, not a loop closed by a line across the opening). Each joint's end
    // on a support becomes a node of its own.
    let mut n = n;
    for (e, (a, c, _)) in edges.iter_mut().enumerate() {
        for v in [a, c] {
            if *v >= b.nb {
                adj[*v].retain(|&x| x != e);
                *v = n;
                adj.push(vec![e]);
                n += 1;
            }
        }
    }
    let mut used = vec![false; edges.len()];
    let mut chains = Vec::new();
    // Start at chain ends (degree 1), then whatever is left (cycles).
    let starts: Vec<usize> = (0..n).filter(|&v| adj[v].len() == 1).chain(0..n).collect();
    for s in starts {
        let mut v = s;
        let mut chain = Vec::new();
        while let Some(&e) = adj[v].iter().find(|&&e| !used[e]) {
            used[e] = true;
            chain.push((carrier[e], edges[e].2));
            v = if edges[e].0 == v {
                edges[e].1
            } else {
                edges[e].0
            };
        }
        if !chain.is_empty() {
            chains.push(chain);
        }
    }
    chains
}

struct LegendItems {
    undeformed: bool,
    hinges: bool,
    cracks: bool,
    crack_lines: bool,
    /// The thrust line (a line through dots) or centres of pressure (dots): its label.
    thrust: Option<&'static str>,
    /// Largest arrow of each kind (kN), when drawn.
    live: Option<f64>,
    dead: Option<f64>,
    forces: Option<f64>,
    supports: bool,
}

/// The entries of a 2D legend (super::legend lays them out).
#[allow(clippy::too_many_arguments)]
fn legend_entries(
    scene: &Scene,
    it: &LegendItems,
    id: &str,
    k: f64,
    size: f64,
    has_motion: bool,
    scale: f64,
    interactive: bool,
) -> Vec<Entry> {
    let mut e = Vec::new();
    if it.undeformed {
        e.push(Entry::symbol(format!("<rect x=\"0\" y=\"-6\" width=\"22\" height=\"12\" fill=\"none\" stroke=\"{FAINT}\" stroke-dasharray=\"4 3\"/>"), "undeformed"));
    }
    if it.supports {
        e.push(Entry::symbol(format!("<rect x=\"0\" y=\"-6\" width=\"22\" height=\"12\" fill=\"url(#{id}-hatch)\" stroke=\"{EDGE}\" stroke-width=\"0.8\"/>"), "support"));
    }
    if it.hinges {
        e.push(Entry::symbol(format!("<circle cx=\"11\" cy=\"0\" r=\"5\" fill=\"{HINGE}\" stroke=\"#ffffff\" stroke-width=\"1.2\"/>"), "hinge"));
    }
    if it.cracks || it.crack_lines {
        // The wedge (the opening) and the line (the crack as traced, numbered by width) share
        // one legend entry.
        let mut sym = String::new();
        if it.cracks {
            let _ = write!(
                sym,
                "<path d=\"M2 6L22 -6L22 6Z\" fill=\"{CRACK}\" fill-opacity=\"0.85\"/>"
            );
        }
        if it.crack_lines {
            let _ = write!(
                sym,
                "<path d=\"M2 6L22 -6\" stroke=\"{CRACK_LINE}\" stroke-width=\"2\"/>"
            );
        }
        let label = match (it.cracks, it.crack_lines) {
            (true, true) => "crack, opening (1 = widest)",
            (false, true) => "crack (1 = widest)",
            _ => "crack (opening)",
        };
        e.push(Entry::symbol(sym, label));
    }
    if let Some(label) = it.thrust {
        let symbol = if label == "thrust line" {
            format!("<path d=\"M0 3L11 -3L22 2\" fill=\"none\" stroke=\"{THRUST}\" stroke-width=\"2\"/><circle cx=\"11\" cy=\"-3\" r=\"2\" fill=\"{THRUST}\"/>")
        } else {
            format!("<circle cx=\"11\" cy=\"0\" r=\"3\" fill=\"{THRUST}\"/>")
        };
        e.push(Entry::symbol(symbol, label));
    }
    let arrow_sym = |c: &str| {
        format!("<path d=\"M1 0L15 0\" stroke=\"{c}\" stroke-width=\"1.6\"/><path d=\"M22 0L13 -4.5L13 4.5Z\" fill=\"{c}\"/>")
    };
    if let Some(m) = it.live {
        e.push(Entry::symbol(
            arrow_sym(LOAD),
            super::legend::live_load_label(scene.load_multiplier, scene.tilt.clone(), m),
        ));
    }
    if let Some(m) = it.dead {
        e.push(Entry::symbol(
            arrow_sym("#555555"),
            format!("dead load (largest {} kN)", human(m, 3)),
        ));
    }
    if let Some(m) = it.forces {
        e.push(Entry::symbol(
            arrow_sym(FORCE),
            format!("contact force (largest {} kN)", human(m, 3)),
        ));
    }
    // Next row: scale bar and displacement scale.
    e.push(Entry::scale_bar(size, k));
    if has_motion {
        let (lead, tail) = match scene.units {
            MotionUnits::Metres => ("displacements drawn × ", ""),
            MotionUnits::Normalised => (
                "mechanism drawn × ",
                " (normalised: live loads do unit work)",
            ),
        };
        let value = human(scale, 4);
        let mut t = Entry::text(format!("{lead}{value}{tail}"), "#333333");
        t.markup = Some(format!(
            "{}<tspan class=\"scale-value\"{}>{}</tspan>{}",
            esc(lead),
            if interactive {
                " data-scale-label=\"1\""
            } else {
                ""
            },
            esc(&value),
            esc(tail)
        ));
        e.push(t);
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::draw::chrome::wrap;
    use crate::draw::svg::text_width;

    #[test]
    fn pixel_matrix_matches_the_world_rigid_motion() {
        let fr = Frame {
            k: 37.0,
            ox: 120.0,
            oy: 400.0,
        };
        let g = Group {
            center: [1.2, 0.7],
            d: [0.03, -0.02, 0.05],
            moving: true,
            support: false,
            colour: 0,
            members: vec![],
        };
        let pm = px_motion(&fr, &g);
        let s = 4.0;
        let wm = world_motion(&g, s);
        for p in [[0.0, 0.0], [2.0, 1.0], [-1.5, 3.0]] {
            let want = fr.px(wm.apply(p));
            let got = px_apply(&pm, s, fr.px(p));
            assert!(
                (want[0] - got[0]).abs() < 1e-9 && (want[1] - got[1]).abs() < 1e-9,
                "{want:?} {got:?}"
            );
            // The SVG matrix gives the same point.
            let (sn, cs) = (s * pm[4]).sin_cos();
            let e = pm[0] + s * pm[2] - (cs * pm[0] - sn * pm[1]);
            let f = pm[1] + s * pm[3] - (sn * pm[0] + cs * pm[1]);
            let q = fr.px(p);
            let m = [cs * q[0] - sn * q[1] + e, sn * q[0] + cs * q[1] + f];
            assert!((want[0] - m[0]).abs() < 1e-9 && (want[1] - m[1]).abs() < 1e-9);
        }
    }

    #[test]
    fn long_subtitles_wrap_within_the_width() {
        let line =
            "prescribed support motion: ".to_string() + &"f1 u = 0 mm, v = −200 mm; ".repeat(40);
        let lines = wrap(line.trim_end(), 13.0, 944.0);
        assert!(lines.len() > 5, "{lines:?}");
        for l in &lines {
            assert!(text_width(l, 13.0) <= 944.0, "{l}");
        }
        assert_eq!(lines.join(" "), line.trim_end());
        assert_eq!(wrap("short", 13.0, 944.0), vec!["short".to_string()]);
    }

    #[test]
    fn auto_scale_is_a_round_number() {
        // 7 % of 6.38 m over a 1 cm settlement: 44.66 → 50.
        assert_eq!(auto_scale(0.01, 0.001, 6.38), 50.0);
        // ... unless the rotations get large: 0.15 rad / 0.01 = 15 → 10.
        assert_eq!(auto_scale(0.01, 0.01, 6.38), 10.0);
        assert_eq!(auto_scale(0.0, 0.0, 6.38), 1.0);
    }
}
