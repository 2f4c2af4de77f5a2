//! Drawings of 3D results: the deformed structure in an orthographic view (axonometric by
//! default; plan and front elevation on request) over the undeformed outline, with hinges,
//! opened cracks, centres of pressure, loads, a title, a legend and a scale bar in the style
//! of the 2D drawings ([`crate::draw::scene`]). PNG is the same SVG rendered by
//! [`crate::draw::png`].
//!
//! - **View.** An axonometric camera at azimuth `az`, elevation `el`: the direction from the
//!   model to the camera is `(sin az · cos el, −cos az · cos el, sin el)`, azimuth measured from
//!   the front (−y) counter-clockwise seen from above, so −35° looks from the front-left and
//!   above (the front, left and top faces of a box are seen), z up on the page.
//! - **Automatic view** ([`View::Auto`], the default; [`auto_view`]). A model that does not move
//!   is seen from azimuth −35°, elevation 30°. Otherwise the camera turns to show the largest
//!   motions: for each azimuth −35° + 15°·k (k = 0 … 23) at elevation 30°, every body that moves
//!   by at least a fifth of the largest displacement (the 48 that move most) scores the area of
//!   its faces seen from there and not hidden by another body (tested at each face's centre),
//!   times its displacement (relative to the largest) and the part of that displacement in the
//!   picture plane; the azimuth with the largest sum wins, and among azimuths within 2 % of it the
//!   one nearest −35° (then the first in the order −35°, −20°, −50°, …), so the choice is
//!   deterministic and a symmetric mechanism keeps the usual view. A dome's settling sector
//!   comes to the front; the legend states the view.
//! - **Deformation.** Each body is moved by the finite rigid motion whose small motion is the
//!   result's (translation `s·u` of its centroid and rotation by the angle `s·|θ|` about `θ`), so
//!   blocks stay undistorted; `s` is chosen as in 2D ([`crate::draw::scene::auto_scale`]: the
//!   largest displacement drawn is about 7 % of the model's size) unless given.
//! - **Shading.** Faces are filled with their block's colour (a macro-block's colour as in 2D)
//!   times a Lambert factor `0.64 + 0.36 · max(0, n·l)` for a light fixed relative to the camera
//!   (from the upper left, behind the viewer), so faces read as solids whatever the view.
//! - **Hidden faces.** Back faces are culled; the visible faces are ordered far to near by the
//!   mean depth of their vertices, then every pair whose pictures overlap is ordered by a plane
//!   test (the one wholly behind the other's plane is drawn first) and the faces are sorted
//!   topologically (ties and cycles broken by the depth order, so the result is deterministic).
//!
//! Numbers are written with fixed precision: the same result gives the same bytes.

// `!(x > 0.0)` is how this module rejects NaN along with non-positive values (as in `draw`).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::draw::chrome::{Page, MARGIN};
use crate::draw::scene::PressurePoints;
use crate::draw::svg::{esc, human, num};
use crate::result3d::{
    add, cross, dot, norm, scale as vscale, small_displacement, sub, validate, Motions, Result3d,
    V3,
};
use crate::IoError;

mod camera;
mod layers;
mod layout;
mod legend;
use std::collections::BTreeSet;
use std::fmt::Write as _;

/// Which way the camera looks.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum View {
    /// Axonometric, turned to show the largest motions ([`auto_view`]); −35°, 30° when nothing
    /// moves.
    #[default]
    Auto,
    /// Orthographic view from azimuth and elevation in degrees (see the module documentation).
    Axonometric { azimuth: f64, elevation: f64 },
    /// Seen from above: x right, y up the page.
    Plan,
    /// Seen from the front (−y): x right, z up the page.
    Elevation,
}

/// The view of a model that does not move (and the azimuth [`View::Auto`] prefers on ties).
pub const DEFAULT_AZIMUTH: f64 = -35.0;
/// The elevation of the automatic view.
pub const DEFAULT_ELEVATION: f64 = 30.0;

impl View {
    /// `(right, up, toward the camera)`: an orthonormal, right-handed triple.
    fn basis(&self) -> (V3, V3, V3) {
        match *self {
            View::Plan => ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
            View::Elevation => ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]),
            View::Auto => View::Axonometric {
                azimuth: DEFAULT_AZIMUTH,
                elevation: DEFAULT_ELEVATION,
            }
            .basis(),
            View::Axonometric { azimuth, elevation } => {
                let az = if azimuth.is_finite() { azimuth } else { -35.0 };
                // Elevations of ±90° would make "up" undefined: seen from (almost) above.
                let el = if elevation.is_finite() {
                    elevation.clamp(-89.0, 89.0)
                } else {
                    30.0
                };
                let (az, el) = (az.to_radians(), el.to_radians());
                let e = [az.sin() * el.cos(), -az.cos() * el.cos(), el.sin()];
                let r = cross([-e[0], -e[1], -e[2]], [0.0, 0.0, 1.0]);
                let r = vscale(r, 1.0 / norm(r));
                let u = cross(e, r);
                (r, u, e)
            }
        }
    }

    fn describe(&self) -> String {
        match *self {
            View::Auto => View::Axonometric {
                azimuth: DEFAULT_AZIMUTH,
                elevation: DEFAULT_ELEVATION,
            }
            .describe(),
            View::Plan => "plan (seen from above)".to_string(),
            View::Elevation => "front elevation (seen from −y)".to_string(),
            View::Axonometric { azimuth, elevation } => format!(
                "axonometric view: azimuth {}°, elevation {}°",
                human(azimuth, 3),
                human(elevation, 3)
            ),
        }
    }
}

/// The world → pixel map of a drawing: orthographic projection on `(right, up)`,
/// `px = (ox + k·(x·right), oy − k·(x·up))`; `depth = x·toward` grows toward the viewer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub right: V3,
    pub up: V3,
    pub toward: V3,
    /// Pixels per metre.
    pub k: f64,
    pub ox: f64,
    pub oy: f64,
}

impl Camera {
    /// Pixel position (SVG units) of world point `p`.
    pub fn px(&self, p: V3) -> [f64; 2] {
        [
            self.ox + self.k * dot(p, self.right),
            self.oy - self.k * dot(p, self.up),
        ]
    }
    /// Distance toward the viewer.
    pub fn depth(&self, p: V3) -> f64 {
        dot(p, self.toward)
    }
}

/// How to draw a 3D result.
#[derive(Clone, Debug)]
pub struct Draw3dOptions {
    pub view: View,
    /// Displacement scale factor; `None`: automatic (as in 2D).
    pub scale: Option<f64>,
    /// Width of the figure in pixels.
    pub width: f64,
    /// Largest height of the drawing area in pixels.
    pub max_height: f64,
    /// Draw the deformed configuration (when the result has motions).
    pub deformed: bool,
    /// Draw the undeformed edges, thin and grey, behind the deformed solids.
    pub undeformed: bool,
    pub supports: bool,
    pub hinges: bool,
    pub cracks: bool,
    /// Centres of pressure (the thrust points) as dots: [`PressurePoints::Auto`] draws them
    /// when there are at most [`crate::draw::scene::PRESSURE_POINTS_AUTO`].
    pub pressure_points: PressurePoints,
    pub live_loads: bool,
    pub dead_loads: bool,
    pub legend: bool,
    /// Prefix for element ids (the hatch pattern), unique per figure in one HTML page.
    pub id: String,
    /// Title of the figure (default: by analysis).
    pub title: Option<String>,
}

impl Default for Draw3dOptions {
    fn default() -> Self {
        Draw3dOptions {
            view: View::default(),
            scale: None,
            width: 1000.0,
            max_height: 700.0,
            deformed: true,
            undeformed: true,
            supports: true,
            hinges: true,
            cracks: true,
            pressure_points: PressurePoints::Auto,
            live_loads: true,
            dead_loads: false,
            legend: true,
            id: "v3".to_string(),
            title: None,
        }
    }
}

/// A finished 3D drawing.
#[derive(Clone, Debug)]
pub struct Drawing3d {
    pub svg: String,
    pub width: f64,
    pub height: f64,
    /// The displacement scale factor used (0 when nothing moves).
    pub scale: f64,
    /// Where world points land (undeformed positions; a block's points move with it).
    pub camera: Camera,
    /// Whether a deformed configuration was drawn.
    pub deformed: bool,
    /// The view drawn ([`View::Auto`] resolved to its azimuth and elevation).
    pub view: View,
}

/// A finite rigid motion: `x ↦ c + t + R (x − c)`.
#[derive(Clone, Copy)]
struct Rigid {
    c: V3,
    t: V3,
    /// Unit axis and angle.
    axis: V3,
    angle: f64,
}

impl Rigid {
    fn new(c: V3, d: &[f64; 6], s: f64) -> Rigid {
        let th = [s * d[3], s * d[4], s * d[5]];
        let angle = norm(th);
        let axis = if angle > 0.0 {
            vscale(th, 1.0 / angle)
        } else {
            [0.0, 0.0, 1.0]
        };
        Rigid {
            c,
            t: [s * d[0], s * d[1], s * d[2]],
            axis,
            angle,
        }
    }
    fn rotate(&self, v: V3) -> V3 {
        if self.angle == 0.0 {
            return v;
        }
        let (sn, cs) = self.angle.sin_cos();
        let k = self.axis;
        add(
            add(vscale(v, cs), vscale(cross(k, v), sn)),
            vscale(k, dot(k, v) * (1.0 - cs)),
        )
    }
    fn apply(&self, x: V3) -> V3 {
        add(add(self.c, self.t), self.rotate(sub(x, self.c)))
    }
}

/// One body (block or support) as drawn.
struct Body<'a> {
    vertices: &'a [V3],
    faces: &'a [Vec<usize>],
    support: bool,
    moving: bool,
    /// Fill colour (blocks) — supports are hatched.
    colour: &'static str,
    motion: Rigid,
}

/// A visible face, projected.
struct Face {
    body: usize,
    index: usize,
    /// Deformed world vertices and their pixels.
    world: Vec<V3>,
    px: Vec<[f64; 2]>,
    /// Unit outward normal (deformed), toward the viewer.
    normal: V3,
    depth: f64,
    bbox: [f64; 4],
}

/// `#rrggbb` scaled by `f` (≤ 1 darkens).
fn shade(hex: &str, f: f64) -> String {
    let h = hex.trim_start_matches('#');
    let c = |i: usize| u8::from_str_radix(h.get(i..i + 2).unwrap_or("80"), 16).unwrap_or(128);
    let s = |v: u8| ((v as f64 * f).round().clamp(0.0, 255.0)) as u8;
    format!("#{:02x}{:02x}{:02x}", s(c(0)), s(c(2)), s(c(4)))
}

/// Newell's normal of a polygon (not normalised; zero for a degenerate one).
fn newell(p: &[V3]) -> V3 {
    voussoir::vector::newell(p.len(), |i| p[i])
}

/// Whether two projected polygons overlap by more than `tol` pixels (separating axes of their
/// edges; exact for convex faces, conservative otherwise).
fn overlap(a: &[[f64; 2]], b: &[[f64; 2]], tol: f64) -> bool {
    for poly in [a, b] {
        for i in 0..poly.len() {
            let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
            let n = [q[1] - p[1], p[0] - q[0]];
            let l = n[0].hypot(n[1]);
            if !(l > 1e-12) {
                continue;
            }
            let proj = |s: &[[f64; 2]]| {
                s.iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                        let x = (v[0] * n[0] + v[1] * n[1]) / l;
                        (lo.min(x), hi.max(x))
                    })
            };
            let (a0, a1) = proj(a);
            let (b0, b1) = proj(b);
            if a1 <= b0 + tol || b1 <= a0 + tol {
                return false;
            }
        }
    }
    true
}

/// Signed distances of `pts` from the plane of `f` (positive toward the viewer).
fn side(f: &Face, pts: &[V3], eps: f64) -> (bool, bool) {
    let mut behind = true;
    let mut front = true;
    for p in pts {
        let s = dot(f.normal, sub(*p, f.world[0]));
        if s > eps {
            behind = false;
        }
        if s < -eps {
            front = false;
        }
    }
    (behind, front)
}

/// Whether pixel `q` is inside polygon `poly` (even–odd rule).
fn inside(poly: &[[f64; 2]], q: [f64; 2]) -> bool {
    let mut c = false;
    let n = poly.len();
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + n - 1) % n]);
        if (a[1] > q[1]) != (b[1] > q[1]) {
            let x = a[0] + (q[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if q[0] < x {
                c = !c;
            }
        }
    }
    c
}

/// Whether the (deformed) world point `p` is hidden by a face nearer the camera than `p` by
/// more than `eps` along the line of sight.
fn hidden(faces: &[Face], cam: &Camera, p: V3, eps: f64) -> bool {
    let q = cam.px(p);
    faces.iter().any(|f| {
        if q[0] < f.bbox[0] || q[0] > f.bbox[2] || q[1] < f.bbox[1] || q[1] > f.bbox[3] {
            return false;
        }
        let ne = dot(f.normal, cam.toward);
        if !(ne > 1e-9) {
            return false;
        }
        // The line of sight p + t·toward meets the face's plane at t.
        let t = -dot(f.normal, sub(p, f.world[0])) / ne;
        t > eps && inside(&f.px, q)
    })
}

/// Path data of segment `a`–`b` (world points, deformed) split into pieces that are visible
/// and pieces that are hidden, appended to `vis` and `hid`.
#[allow(clippy::too_many_arguments)]
fn split_segment(
    vis: &mut String,
    hid: &mut String,
    faces: &[Face],
    cam: &Camera,
    a: V3,
    b: V3,
    eps: f64,
    pieces: usize,
) {
    let at = |t: f64| add(a, vscale(sub(b, a), t));
    let mut start = 0;
    let state = |k: usize| hidden(faces, cam, at((k as f64 + 0.5) / pieces as f64), eps);
    let mut cur = state(0);
    for k in 1..=pieces {
        let next = if k < pieces { state(k) } else { !cur };
        if next != cur || k == pieces {
            let (p, q) = (
                cam.px(at(start as f64 / pieces as f64)),
                cam.px(at(k as f64 / pieces as f64)),
            );
            let out = if cur { &mut *hid } else { &mut *vis };
            let _ = write!(
                out,
                "M{} {}L{} {}",
                num(p[0]),
                num(p[1]),
                num(q[0]),
                num(q[1])
            );
            start = k;
            cur = next;
        }
    }
}

/// Above this many visible faces only the depth order is used (the pairwise test is
/// quadratic).
const PAIRWISE_LIMIT: usize = 6000;

/// Order the faces for painting: far to near.
fn paint_order(faces: &[Face], eps: f64) -> Vec<usize> {
    let n = faces.len();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| {
        faces[a]
            .depth
            .total_cmp(&faces[b].depth)
            .then(faces[a].body.cmp(&faces[b].body))
            .then(faces[a].index.cmp(&faces[b].index))
    });
    if !(2..=PAIRWISE_LIMIT).contains(&n) {
        return order;
    }
    // rank[i]: position of face i in the depth order.
    let mut rank = vec![0; n];
    for (r, &i) in order.iter().enumerate() {
        rank[i] = r;
    }
    // Edges "a before b" between overlapping faces, from the plane tests.
    let mut succ: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut indeg = vec![0usize; n];
    // Sweep in x to skip pairs whose boxes are apart.
    let mut by_x: Vec<usize> = (0..n).collect();
    by_x.sort_by(|&a, &b| {
        faces[a].bbox[0]
            .total_cmp(&faces[b].bbox[0])
            .then(a.cmp(&b))
    });
    for (ia, &a) in by_x.iter().enumerate() {
        for &b in &by_x[ia + 1..] {
            if faces[b].bbox[0] >= faces[a].bbox[2] {
                break;
            }
            let (fa, fb) = (&faces[a], &faces[b]);
            if fa.body == fb.body
                || fb.bbox[1] >= fa.bbox[3]
                || fa.bbox[1] >= fb.bbox[3]
                || !overlap(&fa.px, &fb.px, 0.5)
            {
                continue;
            }
            let (a_behind_b, a_front_b) = side(fb, &fa.world, eps);
            let (b_behind_a, b_front_a) = side(fa, &fb.world, eps);
            let a_first = a_behind_b || b_front_a;
            let b_first = b_behind_a || a_front_b;
            let (first, second) = match (a_first, b_first) {
                (true, false) => (a, b),
                (false, true) => (b, a),
                _ => continue,
            };
            succ[first].push(second);
            indeg[second] += 1;
        }
    }
    // Kahn's algorithm, always taking the ready face that is farthest in the depth order; on a
    // cycle, the farthest remaining face.
    let mut ready: BTreeSet<usize> = (0..n).filter(|&i| indeg[i] == 0).map(|i| rank[i]).collect();
    let mut done = vec![false; n];
    let mut out = Vec::with_capacity(n);
    let mut next_far = 0; // scan position in `order` for cycle breaking
    while out.len() < n {
        let i = if let Some(&r) = ready.iter().next() {
            ready.remove(&r);
            order[r]
        } else {
            while done[order[next_far]] {
                next_far += 1;
            }
            order[next_far]
        };
        if done[i] {
            continue;
        }
        done[i] = true;
        out.push(i);
        for &j in &succ[i] {
            if indeg[j] > 0 {
                indeg[j] -= 1;
                if indeg[j] == 0 && !done[j] {
                    ready.insert(rank[j]);
                }
            }
        }
    }
    out
}

/// The azimuths [`View::Auto`] tries, in the order that settles ties: −35°, −20°, −50°, −5°,
/// … (nearest −35° first), in (−180°, 180°].
fn auto_azimuths() -> Vec<f64> {
    let wrap180 = |a: f64| {
        if a <= -180.0 {
            a + 360.0
        } else if a > 180.0 {
            a - 360.0
        } else {
            a
        }
    };
    let mut v = vec![DEFAULT_AZIMUTH];
    for k in 1..=12 {
        v.push(wrap180(DEFAULT_AZIMUTH + 15.0 * k as f64));
        if k < 12 {
            v.push(wrap180(DEFAULT_AZIMUTH - 15.0 * k as f64));
        }
    }
    v
}

/// Bodies that [`view_scores`] weighs: at most this many, those that move most.
const AUTO_BODIES: usize = 48;

/// How well each azimuth of [`View::Auto`] (elevation 30°) shows the motions of `r`, in the
/// order that settles ties (see the module documentation): `(azimuth in degrees, score)`. The
/// score of an azimuth sums, over the bodies that move by at least a fifth of the largest
/// displacement (the [`AUTO_BODIES`] that move most), the projected area (m²) of the body's faces
/// that face the camera and whose centre no other face hides, times the body's largest
/// displacement over the model's, times the fraction of that displacement in the picture plane.
/// Empty when nothing moves (or the shapes are invalid).
pub fn view_scores(r: &(impl Result3d + ?Sized)) -> Vec<(f64, f64)> {
    if validate(r).is_err() {
        return Vec::new();
    }
    let g = r.shapes();
    let motions = Motions::of(r);
    type Shape<'b> = (&'b [V3], &'b [Vec<usize>], (V3, [f64; 6]));
    let bodies: Vec<Shape> = g
        .blocks
        .iter()
        .zip(&motions.blocks)
        .map(|(b, m)| (b.vertices.as_slice(), b.faces.as_slice(), *m))
        .chain(
            g.supports
                .iter()
                .zip(&motions.supports)
                .map(|(s, m)| (s.vertices.as_slice(), s.faces.as_slice(), *m)),
        )
        .collect();
    // The largest displacement of each body and its vector.
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let moves: Vec<(f64, V3)> = bodies
        .iter()
        .map(|(vs, _, (c, d))| {
            let mut best = (0.0f64, [0.0; 3]);
            for v in vs.iter() {
                for k in 0..3 {
                    lo[k] = lo[k].min(v[k]);
                    hi[k] = hi[k].max(v[k]);
                }
                let u = small_displacement(*c, d, *v);
                let m = norm(u);
                if m > best.0 {
                    best = (m, u);
                }
            }
            best
        })
        .collect();
    let dmax = moves.iter().map(|m| m.0).fold(0.0f64, f64::max);
    if !(dmax > 0.0 && dmax.is_finite()) {
        return Vec::new();
    }
    let size = (0..3)
        .map(|k| hi[k] - lo[k])
        .fold(0.0f64, f64::max)
        .max(1e-9);
    let mut movers: Vec<usize> = (0..bodies.len())
        .filter(|&i| moves[i].0 >= 0.2 * dmax)
        .collect();
    movers.sort_by(|&a, &b| moves[b].0.total_cmp(&moves[a].0).then(a.cmp(&b)));
    movers.truncate(AUTO_BODIES);
    let eps = 1e-6 * size;
    auto_azimuths()
        .into_iter()
        .map(|az| {
            let cam = Camera::of_view(View::Axonometric {
                azimuth: az,
                elevation: DEFAULT_ELEVATION,
            });
            let toward = cam.toward;
            let mut faces: Vec<Face> = Vec::new();
            for (bi, (vs, fs, _)) in bodies.iter().enumerate() {
                for (fi, f) in fs.iter().enumerate() {
                    let world: Vec<V3> = f.iter().map(|&i| vs[i]).collect();
                    // The scores test visibility by planes, not by depth.
                    if let Some(face) = Face::project(bi, fi, world, &cam) {
                        faces.push(Face { depth: 0.0, ..face });
                    }
                }
            }
            let mut score = 0.0;
            for &i in &movers {
                let (m, u) = moves[i];
                let in_plane = norm(sub(u, vscale(toward, dot(u, toward)))) / m;
                let mut area = 0.0;
                for f in faces.iter().filter(|f| f.body == i) {
                    let c = vscale(
                        f.world.iter().fold([0.0; 3], |a, p| add(a, *p)),
                        1.0 / f.world.len() as f64,
                    );
                    if !hidden(&faces, &cam, c, eps) {
                        let n = f.px.len();
                        area += (0..n)
                            .map(|k| {
                                let (p, q) = (f.px[k], f.px[(k + 1) % n]);
                                p[0] * q[1] - q[0] * p[1]
                            })
                            .sum::<f64>()
                            .abs()
                            / 2.0;
                    }
                }
                score += m / dmax * area * in_plane;
            }
            (az, score)
        })
        .collect()
}

/// The axonometric view that [`View::Auto`] draws `r` from: the azimuth of [`view_scores`] that
/// shows the largest motions best (within 2 % of the best, the one nearest −35°), elevation 30°;
/// azimuth −35° when nothing moves.
pub fn auto_view(r: &(impl Result3d + ?Sized)) -> View {
    let scores = view_scores(r);
    let best = scores.iter().map(|s| s.1).fold(0.0f64, f64::max);
    let azimuth = if best > 0.0 && best.is_finite() {
        scores
            .iter()
            .find(|s| s.1 >= 0.98 * best)
            .map_or(DEFAULT_AZIMUTH, |s| s.0)
    } else {
        DEFAULT_AZIMUTH
    };
    View::Axonometric {
        azimuth,
        elevation: DEFAULT_ELEVATION,
    }
}

/// Draw a 3D result as SVG.
pub fn draw3d(r: &(impl Result3d + ?Sized), opts: &Draw3dOptions) -> Result<Drawing3d, IoError> {
    validate(r)?;
    let g = r.shapes();
    let motions = Motions::of(r);
    // Layout: sizes, motions and colours, loads (world coordinates).
    let lay = layout::layout(r, g, &motions, opts);
    // Camera: the view and the extent of the drawing.
    let frame = camera::frame(r, &lay, opts);
    let view = frame.view;

    // The page (as in 2D).
    let page = Page::new(opts.width, opts.max_height, 700.0, &r.info());
    let (width, max_h, margin, title_h) = (page.width, page.max_height, MARGIN, page.title_h);
    let k = ((width - 2.0 * margin) / frame.bw).min(max_h / frame.bh);
    let draw_h = frame.bh * k;
    // The legend: entries flowed and wrapped within the figure (crate::draw::legend). Its height
    // is that of the entries that may be drawn (a superset of those drawn below).
    let labels = legend::labels(r, g, &lay, opts, view, k);
    let legend_h = legend::height(&labels, opts, margin, width);
    let height = (title_h + margin + draw_h + margin + legend_h).ceil();
    let cam = frame.camera(k, width, title_h + margin);
    let pens = layers::Pens::new(lay.mean_size, k);

    // Visible faces (deformed), with their depth and picture, in paint order.
    let (faces, order) = camera::visible_faces(&lay, &cam);

    let id = esc(&opts.id);
    let mut o = String::with_capacity(4096 + 160 * faces.len());
    page.open(&mut o, height);
    o.push_str(">\n");
    let title = opts.title.clone().unwrap_or_else(|| r.title());
    page.head(&mut o, &id, height, &title);

    // Layers, back to front.
    let m = layers::Marks::new(r, g, &lay, &cam, &faces, &order, pens);
    layers::undeformed(&mut o, &m, opts);
    layers::solids(&mut o, &m, &id);
    let cracks = layers::cracks(&mut o, &m, opts);
    let (live, dead) = layers::loads(&mut o, &m, width);
    let thrust = layers::pressure(&mut o, &m, labels.show_pressure);
    let hinges = layers::hinges(&mut o, &m, opts);
    if lay.bodies.is_empty() {
        page.nothing_to_draw(&mut o, draw_h);
    }
    layers::axes(
        &mut o,
        &m,
        [width - margin - 34.0, title_h + margin + draw_h - 6.0],
    );

    if opts.legend {
        let labels = labels.drawn(&legend::Drawn {
            hinges,
            cracks,
            thrust,
            live,
            dead,
        });
        crate::draw::legend::write(
            &mut o,
            &labels.entries(),
            margin,
            width - margin,
            height - legend_h,
        );
    }
    o.push_str("</svg>\n");
    Ok(Drawing3d {
        svg: o,
        width,
        height,
        scale: lay.scale,
        camera: cam,
        deformed: lay.has_motion,
        view,
    })
}

/// The drawing as PNG ([`crate::draw::PNG_ZOOM`] pixels per SVG pixel), with the drawing used.
pub fn draw3d_png(
    r: &(impl Result3d + ?Sized),
    opts: &Draw3dOptions,
) -> Result<(Vec<u8>, Drawing3d), IoError> {
    let d = draw3d(r, opts)?;
    let png = crate::draw::svg_to_png(&d.svg, crate::draw::PNG_ZOOM)?;
    Ok((png, d))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_view_looks_from_front_left_above() {
        let (r, u, e) = View::default().basis();
        // Right-handed orthonormal triple.
        let c = cross(r, u);
        assert!(norm(sub(c, e)) < 1e-12);
        assert!((norm(r) - 1.0).abs() < 1e-12 && dot(r, u).abs() < 1e-12);
        // The camera is in front (−y), to the left (−x) and above (+z).
        assert!(e[0] < 0.0 && e[1] < 0.0 && e[2] > 0.0);
        // z is up on the page.
        assert!(u[2] > 0.0 && r[2].abs() < 1e-12);
    }

    #[test]
    fn finite_rotation_keeps_distances() {
        let m = Rigid::new([0.5, 0.5, 0.5], &[0.1, 0.0, 0.0, 0.3, -0.2, 0.4], 1.0);
        let (a, b) = (m.apply([0.0, 0.0, 0.0]), m.apply([1.0, 1.0, 1.0]));
        assert!((norm(sub(a, b)) - 3f64.sqrt()).abs() < 1e-12);
        // The centroid moves by the translation.
        let c = m.apply([0.5, 0.5, 0.5]);
        assert!(norm(sub(c, [0.6, 0.5, 0.5])) < 1e-12);
    }

    #[test]
    fn shading_darkens_hex_colours() {
        assert_eq!(shade("#ffffff", 0.5), "#808080");
        assert_eq!(shade("#f6c97f", 1.0), "#f6c97f");
    }
}
