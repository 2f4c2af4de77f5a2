//! Meshes of any wall: an outline with holes (the outer boundary and the openings) cut into
//! rigid elements, standing on foundation segments along its base. No I/O.
//!
//! * [`MeshKind::Grid`]: rows and columns of `length` × `height` elements (stack bond), cut by
//!   the outline and the holes. Row lines move onto the horizontal edges of the outline and the
//!   holes (sills, lintels, springings) and column lines onto their vertical edges (jambs) when
//!   they lie within half an element, so that no element straddles them.
//! * [`MeshKind::RunningBond`]: courses of `length` × `height` units, alternate courses offset
//!   by half a unit (the row lines move as for the grid).
//! * [`MeshKind::Triangles`]: a constrained Delaunay triangulation of the region (outline and
//!   holes as constraint edges), refined (Ruppert/Chew, the `spade` crate) until no triangle is
//!   larger than `max_area` and none has an angle below `min_angle_deg` (except where the
//!   outline itself has a sharper corner). An optional size field ([`MeshOptions::size`]) gives
//!   a local maximum area, for local refinement.
//!
//! Cells of the grid and the bond are clipped with the `i_overlay` crate on its 64-bit integer
//! grid, then every vertex is put back exactly where it belongs (an outline vertex, a cell
//! corner, or the crossing of a cell side with an outline edge), so the elements tile the
//! region exactly: their areas add up to the outline's area minus the holes' to rounding.
//!
//! The foundation ([`Foundation`]): the outline's lowest horizontal edges are its base; the
//! base's x range is cut into equal parts, one support rectangle of depth `depth` below each,
//! named as given (left to right).

use crate::error::{Error, Result};
use crate::geometry::{
    area_centroid, bbox, point_segment_distance, segment_meets_box, signed_area,
};
use crate::model::{Block, Loads, Material, Model, Point, Support};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use spade::{
    AngleLimit, ConstrainedDelaunayTriangulation, Point2, RefinementParameters, Triangulation,
};
use std::collections::BTreeMap;

/// A wall's outline: the outer boundary and the openings (holes), each a simple polygon in
/// metres, either orientation. An opening that reaches the outer boundary (a door) is part of
/// the outer boundary (a notch), not a hole.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Outline {
    pub outer: Vec<Point>,
    pub holes: Vec<Vec<Point>>,
}

/// How the wall is cut into elements.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MeshKind {
    /// Aligned rows and columns of `length` × `height` elements (stack bond).
    Grid { length: f64, height: f64 },
    /// Courses of `length` × `height` units, alternate courses offset by half a unit.
    RunningBond { length: f64, height: f64 },
    /// Triangles no larger than `max_area` (m²) with no angle below `min_angle_deg` (at most
    /// 33°: Delaunay refinement is guaranteed to end below about 30°). `min_angle_deg` 0: no
    /// quality refinement, the outline's own constrained Delaunay triangulation with the
    /// triangles larger than `max_area` split at their centroids.
    Triangles { max_area: f64, min_angle_deg: f64 },
}

/// A local maximum triangle area (m²) at a point of the wall.
pub type SizeField<'a> = &'a (dyn Fn(Point) -> f64 + Sync);

/// Options of a mesh beyond its kind. Build with `..MeshOptions::default()`: fields may be
/// added.
#[derive(Clone, Copy)]
pub struct MeshOptions<'a> {
    /// Triangles only: the largest triangle area allowed at a point (m²), on top of
    /// `max_area` (the smaller of the two applies). A triangle larger than the value at its
    /// centroid is split. For local refinement (along cracks, in a region).
    pub size: Option<SizeField<'a>>,
    /// Grid and running bond: a piece of an element cut by the outline that is smaller than
    /// this fraction of a whole element is merged into the neighbour with which it shares the
    /// longest edge (0: keep every piece). The area of the wall is kept exactly.
    pub min_piece: f64,
    /// The most elements allowed (a guard against a mistyped size).
    pub max_elements: usize,
}

impl Default for MeshOptions<'_> {
    fn default() -> Self {
        MeshOptions {
            size: None,
            min_piece: 0.0,
            max_elements: 2_000_000,
        }
    }
}

impl std::fmt::Debug for MeshOptions<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MeshOptions")
            .field("size", &self.size.map(|_| "fn"))
            .field("min_piece", &self.min_piece)
            .field("max_elements", &self.max_elements)
            .finish()
    }
}

/// The foundation the wall stands on: its base (the outline's lowest horizontal edges) cut
/// into `names.len()` equal parts from left to right, each a support rectangle `depth` deep.
#[derive(Clone, Debug, PartialEq)]
pub struct Foundation {
    pub depth: f64,
    pub names: Vec<String>,
}

impl Foundation {
    /// `segments` parts named `{prefix}0 … {prefix}{segments−1}` (the façade's `f0 …`).
    pub fn segments(segments: usize, prefix: &str, depth: f64) -> Foundation {
        Foundation {
            depth,
            names: (0..segments).map(|k| format!("{prefix}{k}")).collect(),
        }
    }
    /// One support called `name`.
    pub fn single(name: &str, depth: f64) -> Foundation {
        Foundation {
            depth,
            names: vec![name.to_string()],
        }
    }
}

fn bad(msg: impl Into<String>) -> Error {
    Error::Request(format!("outline: {}", msg.into()))
}

/// Name of polygon `k` of an outline for messages: `outer boundary` or `hole k` (from 0).
fn ring_name(k: usize) -> String {
    if k == 0 {
        "the outer boundary".into()
    } else {
        format!("hole {}", k - 1)
    }
}

// --- geometry helpers ---------------------------------------------------------------------

fn seg_distance(a0: Point, a1: Point, b0: Point, b1: Point) -> f64 {
    if segments_properly_cross(a0, a1, b0, b1) {
        return 0.0;
    }
    point_segment_distance(a0, b0, b1)
        .min(point_segment_distance(a1, b0, b1))
        .min(point_segment_distance(b0, a0, a1))
        .min(point_segment_distance(b1, a0, a1))
}

fn orient(a: Point, b: Point, c: Point) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

fn segments_properly_cross(a0: Point, a1: Point, b0: Point, b1: Point) -> bool {
    let (o1, o2) = (orient(a0, a1, b0), orient(a0, a1, b1));
    let (o3, o4) = (orient(b0, b1, a0), orient(b0, b1, a1));
    ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0))
        && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0))
}

/// Even-odd point in polygon (boundary points count either way).
fn inside(q: Point, p: &[Point]) -> bool {
    let n = p.len();
    let mut c = false;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        if (a[1] > q[1]) != (b[1] > q[1]) {
            let x = a[0] + (q[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if q[0] < x {
                c = !c;
            }
        }
    }
    c
}

/// The smallest interior angle of a polygon, in degrees (for triangles: the mesh quality).
pub fn min_angle_deg(p: &[Point]) -> f64 {
    let n = p.len();
    let ccw = signed_area(p) >= 0.0;
    (0..n)
        .map(|i| {
            let (a, b, c) = (p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
            let u = [a[0] - b[0], a[1] - b[1]];
            let v = [c[0] - b[0], c[1] - b[1]];
            let cr = u[0] * v[1] - u[1] * v[0];
            let ang = cr.atan2(u[0] * v[0] + u[1] * v[1]).to_degrees();
            // Interior angle: from the next edge round to the previous one, inside.
            let ang = if ccw { -ang } else { ang };
            if ang < 0.0 {
                ang + 360.0
            } else {
                ang
            }
        })
        .fold(f64::INFINITY, f64::min)
}

impl Outline {
    pub fn new(outer: Vec<Point>, holes: Vec<Vec<Point>>) -> Outline {
        Outline { outer, holes }
    }

    /// Area of the outer boundary minus the holes (m²).
    pub fn area(&self) -> f64 {
        signed_area(&self.outer).abs()
            - self.holes.iter().map(|h| signed_area(h).abs()).sum::<f64>()
    }

    /// `[xmin, ymin, xmax, ymax]` of the outer boundary.
    pub fn bbox(&self) -> [f64; 4] {
        bbox(&self.outer)
    }

    /// Whether a point lies inside the outer boundary and outside every hole.
    pub fn contains(&self, q: Point) -> bool {
        inside(q, &self.outer) && !self.holes.iter().any(|h| inside(q, h))
    }

    fn diag(&self) -> f64 {
        let b = bbox(&self.outer);
        (b[2] - b[0]).hypot(b[3] - b[1])
    }

    /// A checked copy: finite coordinates; repeated vertices (and a closing vertex equal to
    /// the first) dropped; every polygon simple, of non-zero area, counter-clockwise; every
    /// hole strictly inside the outer boundary; no two holes touching. An error names the
    /// polygon in one line.
    pub fn validated(&self) -> Result<Outline> {
        let mut rings: Vec<Vec<Point>> = Vec::with_capacity(1 + self.holes.len());
        for (k, r) in std::iter::once(&self.outer).chain(&self.holes).enumerate() {
            if let Some(p) = r.iter().find(|p| !(p[0].is_finite() && p[1].is_finite())) {
                return Err(bad(format!(
                    "{} has a vertex that is not a finite number: [{}, {}]",
                    ring_name(k),
                    p[0],
                    p[1]
                )));
            }
            rings.push(r.clone());
        }
        let b = bbox(&rings[0]);
        let diag = (b[2] - b[0]).hypot(b[3] - b[1]);
        if !(diag.is_finite() && diag > 0.0) {
            return Err(bad("the outer boundary has no extent"));
        }
        let tol = 1e-9 * diag;
        for (k, r) in rings.iter_mut().enumerate() {
            let mut q: Vec<Point> = Vec::with_capacity(r.len());
            for &p in r.iter() {
                if q.last()
                    .is_none_or(|l: &Point| (l[0] - p[0]).hypot(l[1] - p[1]) > tol)
                {
                    q.push(p);
                }
            }
            while q.len() > 1 && {
                let (f, l) = (q[0], q[q.len() - 1]);
                (f[0] - l[0]).hypot(f[1] - l[1]) <= tol
            } {
                q.pop();
            }
            if q.len() < 3 {
                return Err(bad(format!(
                    "{} has fewer than 3 distinct vertices",
                    ring_name(k)
                )));
            }
            let a = signed_area(&q);
            if let Some((i, j)) = crate::geometry::self_intersection(&q, tol) {
                if a.abs() > tol * diag || q.len() > 3 {
                    return Err(bad(format!(
                        "{} intersects itself (its edges {i} and {j} cross or touch)",
                        ring_name(k)
                    )));
                }
            }
            if a.abs() <= tol * diag {
                return Err(bad(format!("{} has no area", ring_name(k))));
            }
            if a < 0.0 {
                q.reverse();
            }
            *r = q;
        }
        let boxes: Vec<[f64; 4]> = rings.iter().map(|r| bbox(r)).collect();
        let near = |a: usize, b: usize| -> Option<(usize, usize)> {
            let (ba, bb) = (boxes[a], boxes[b]);
            if ba[0] > bb[2] + tol
                || bb[0] > ba[2] + tol
                || ba[1] > bb[3] + tol
                || bb[1] > ba[3] + tol
            {
                return None;
            }
            let (p, q) = (&rings[a], &rings[b]);
            for i in 0..p.len() {
                for j in 0..q.len() {
                    if seg_distance(p[i], p[(i + 1) % p.len()], q[j], q[(j + 1) % q.len()]) <= tol {
                        return Some((i, j));
                    }
                }
            }
            None
        };
        for h in 1..rings.len() {
            if let Some((i, _)) = near(0, h) {
                return Err(bad(format!(
                    "{} crosses or touches the outer boundary (at its edge {i}); an opening that reaches the boundary belongs to the outer boundary",
                    ring_name(h)
                )));
            }
            if !inside(rings[h][0], &rings[0]) {
                return Err(bad(format!(
                    "{} lies outside the outer boundary",
                    ring_name(h)
                )));
            }
            for g in 1..h {
                if near(g, h).is_some() {
                    return Err(bad(format!(
                        "{} and {} cross or touch (draw them as one opening)",
                        ring_name(g),
                        ring_name(h)
                    )));
                }
                if inside(rings[h][0], &rings[g]) || inside(rings[g][0], &rings[h]) {
                    return Err(bad(format!(
                        "{} and {} overlap (one lies inside the other)",
                        ring_name(g),
                        ring_name(h)
                    )));
                }
            }
        }
        let mut it = rings.into_iter();
        let outer = it.next().unwrap_or_default();
        Ok(Outline {
            outer,
            holes: it.collect(),
        })
    }

    fn rings(&self) -> impl Iterator<Item = &Vec<Point>> {
        std::iter::once(&self.outer).chain(&self.holes)
    }
}

// --- the mesh ------------------------------------------------------------------------------

/// The elements of a wall: counter-clockwise polygons that tile the outline minus its holes,
/// ordered by rows (bottom to top, then left to right).
pub fn mesh_polygons(
    outline: &Outline,
    kind: &MeshKind,
    opts: &MeshOptions,
) -> Result<Vec<Vec<Point>>> {
    let o = outline.validated()?;
    check_kind(&o, kind, opts)?;
    let mut polys = match *kind {
        MeshKind::Grid { length, height } => cells(&o, length, height, false, opts)?,
        MeshKind::RunningBond { length, height } => cells(&o, length, height, true, opts)?,
        MeshKind::Triangles {
            max_area,
            min_angle_deg,
        } => triangles(&o, max_area, min_angle_deg, opts)?,
    };
    sort_rows(&mut polys, 1e-9 * o.diag());
    Ok(polys)
}

fn check_kind(o: &Outline, kind: &MeshKind, opts: &MeshOptions) -> Result<()> {
    let area = o.area();
    let element = match *kind {
        MeshKind::Grid { length, height } | MeshKind::RunningBond { length, height } => {
            if !(length.is_finite() && length > 0.0 && height.is_finite() && height > 0.0) {
                return Err(bad(format!(
                    "element length {length} and height {height} must be positive numbers"
                )));
            }
            if opts.size.is_some() {
                return Err(bad(
                    "a size field refines triangles only; a grid or a running bond has one element size",
                ));
            }
            length * height
        }
        MeshKind::Triangles {
            max_area,
            min_angle_deg,
        } => {
            if !(max_area.is_finite() && max_area > 0.0) {
                return Err(bad(format!(
                    "the triangles' max area {max_area} must be a positive number (m²)"
                )));
            }
            if !(min_angle_deg.is_finite() && (0.0..=33.0).contains(&min_angle_deg)) {
                return Err(bad(format!(
                    "the triangles' min angle {min_angle_deg}° must lie in [0, 33] (Delaunay refinement ends surely below about 30°)"
                )));
            }
            // Triangles of a refined mesh average about half the largest allowed.
            max_area / 2.0
        }
    };
    if !(0.0..1.0).contains(&opts.min_piece) {
        return Err(bad(format!(
            "min piece {} must lie in [0, 1) (a fraction of an element)",
            opts.min_piece
        )));
    }
    let count = area / element;
    if count > opts.max_elements as f64 {
        return Err(bad(format!(
            "about {count:.0} elements (more than {}): choose a larger element",
            opts.max_elements
        )));
    }
    Ok(())
}

/// Sort polygons by rows: the lowest vertex's y (to `eps`), then the centroid's x.
fn sort_rows(polys: &mut [Vec<Point>], eps: f64) {
    let key = |p: &Vec<Point>| {
        let (_, c) = area_centroid(p);
        let ylow = p.iter().map(|q| q[1]).fold(f64::INFINITY, f64::min);
        (
            (ylow / eps).round(),
            (c[0] / eps).round(),
            (c[1] / eps).round(),
        )
    };
    polys.sort_by(|a, b| {
        let (ka, kb) = (key(a), key(b));
        ka.0.total_cmp(&kb.0)
            .then(ka.1.total_cmp(&kb.1))
            .then(ka.2.total_cmp(&kb.2))
    });
}

// --- triangles -------------------------------------------------------------------------------

fn triangles(
    o: &Outline,
    max_area: f64,
    min_angle: f64,
    opts: &MeshOptions,
) -> Result<Vec<Vec<Point>>> {
    let mut vertices: Vec<Point2<f64>> = Vec::new();
    let mut edges: Vec<[usize; 2]> = Vec::new();
    for r in o.rings() {
        let s = vertices.len();
        vertices.extend(r.iter().map(|p| Point2::new(p[0], p[1])));
        edges.extend((0..r.len()).map(|i| [s + i, s + (i + 1) % r.len()]));
    }
    let n0 = vertices.len();
    let mut conflicts = Vec::new();
    let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(
        || -> Result<Vec<Vec<Point>>> {
            let mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>> =
                ConstrainedDelaunayTriangulation::try_bulk_load_cdt(vertices, edges, |e| {
                    conflicts.push(e)
                })
                .map_err(|e| bad(format!("cannot triangulate: {e:?}")))?;
            if !conflicts.is_empty() {
                return Err(bad("two edges of the outline cross: cannot triangulate it"));
            }
            // Enough Steiner points for the area bound, with room for the angle bound.
            let budget = (8.0 * o.area() / max_area) as usize + 20 * n0 + 1000;
            let budget = budget.min(4 * opts.max_elements);
            let params = || {
                RefinementParameters::<f64>::new()
                    .exclude_outer_faces(true)
                    .with_angle_limit(AngleLimit::from_deg(min_angle))
                    .with_max_allowed_area(max_area)
                    .with_max_additional_vertices(budget)
            };
            let incomplete = || {
                bad(format!(
                "the triangle refinement ran out of vertices ({budget} added): choose a larger max area or a smaller min angle than {min_angle}°"
            ))
            };
            // Min angle 0: no quality refinement (no Steiner points on the outline): triangles
            // larger than the max area are split at their centroids, below.
            let quality = min_angle > 0.0;
            if quality && !cdt.refine(params()).refinement_complete {
                return Err(incomplete());
            }
            let unbounded = |_: Point| f64::INFINITY;
            let size: Option<&(dyn Fn(Point) -> f64 + Sync)> = match opts.size {
                Some(f) => Some(f),
                None if !quality => Some(&unbounded),
                None => None,
            };
            if let Some(size) = size {
                // Split every triangle larger than the local size at its centroid, then refine
                // again for the angles; until none is too large.
                let mut rounds = 0;
                loop {
                    let mut split: Vec<Point2<f64>> = Vec::new();
                    for f in cdt.inner_faces() {
                        let p = f.positions();
                        let tri = [[p[0].x, p[0].y], [p[1].x, p[1].y], [p[2].x, p[2].y]];
                        let (a, c) = area_centroid(&tri);
                        if !o.contains(c) {
                            continue;
                        }
                        let s = size(c);
                        if !(s > 0.0 && (s.is_finite() || opts.size.is_none())) {
                            return Err(bad(format!(
                            "the size field gives {s} at ({:.6}, {:.6}): expected a positive area (m²)",
                            c[0], c[1]
                        )));
                        }
                        if a > s.min(max_area) {
                            split.push(Point2::new(c[0], c[1]));
                        }
                    }
                    if split.is_empty() {
                        break;
                    }
                    rounds += 1;
                    if rounds > 60 || cdt.num_vertices() + split.len() > 4 * opts.max_elements {
                        return Err(bad(
                        "the size field asks for more triangles than allowed: give larger areas",
                    ));
                    }
                    for p in split {
                        cdt.insert(p)
                            .map_err(|e| bad(format!("cannot insert a vertex: {e:?}")))?;
                    }
                    if quality && !cdt.refine(params()).refinement_complete {
                        return Err(incomplete());
                    }
                }
            }
            let mut out = Vec::new();
            for f in cdt.inner_faces() {
                let p = f.positions();
                let tri = vec![[p[0].x, p[0].y], [p[1].x, p[1].y], [p[2].x, p[2].y]];
                let (_, c) = area_centroid(&tri);
                if o.contains(c) {
                    let mut tri = tri;
                    if signed_area(&tri) < 0.0 {
                        tri.reverse();
                    }
                    out.push(tri);
                }
            }
            if out.len() > opts.max_elements {
                return Err(bad(format!(
                    "{} triangles (more than {}): choose a larger max area",
                    out.len(),
                    opts.max_elements
                )));
            }
            Ok(out)
        },
    ));
    match run {
        Ok(r) => r,
        Err(_) => Err(bad(
            "the triangulation failed (loss of precision): simplify the outline or choose a larger max area",
        )),
    }
}

// --- grid and running bond -----------------------------------------------------------------

/// Regular lines from `lo` to `hi` about `h` apart, each of `levels` replacing the nearest
/// inner line when within half a spacing.
fn lines(lo: f64, hi: f64, h: f64, levels: &[f64], eps: f64) -> Vec<f64> {
    let n = ((hi - lo) / h).round().max(1.0) as usize;
    let mut ys: Vec<f64> = (0..=n)
        .map(|k| {
            if k == n {
                hi
            } else {
                lo + (hi - lo) * k as f64 / n as f64
            }
        })
        .collect();
    let step = (hi - lo) / n as f64;
    let mut levels: Vec<f64> = levels
        .iter()
        .copied()
        .filter(|&l| l > lo + eps && l < hi - eps)
        .collect();
    levels.sort_by(f64::total_cmp);
    levels.dedup_by(|a, b| (*a - *b).abs() <= eps);
    for l in levels {
        if let Some(k) = (1..n).min_by(|&a, &b| (ys[a] - l).abs().total_cmp(&(ys[b] - l).abs())) {
            if (ys[k] - l).abs() <= 0.5 * step + eps {
                ys[k] = l;
            }
        }
    }
    ys.sort_by(f64::total_cmp);
    ys.dedup_by(|a, b| (*a - *b).abs() <= eps);
    ys
}

/// The coordinates of the outline's edges parallel to an axis (`axis` 1: horizontal edges'
/// y; 0: vertical edges' x).
fn axis_levels(o: &Outline, axis: usize, eps: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for r in o.rings() {
        for i in 0..r.len() {
            let (a, b) = (r[i], r[(i + 1) % r.len()]);
            if (a[axis] - b[axis]).abs() <= eps && (a[1 - axis] - b[1 - axis]).abs() > eps {
                out.push(a[axis]);
            }
        }
    }
    out
}

struct Region<'a> {
    o: &'a Outline,
    /// Every edge of every ring.
    edges: Vec<(Point, Point)>,
    eps: f64,
}

impl Region<'_> {
    /// The ordinate where an outline edge crosses `x = c` nearest to `y` (or x at `y = c`).
    fn axis_crossing(&self, axis: usize, c: f64, near: f64) -> Option<f64> {
        let other = 1 - axis;
        let mut best: Option<f64> = None;
        for &(mut a, mut b) in &self.edges {
            if (a[axis] - c) * (b[axis] - c) > 0.0 || a[axis] == b[axis] {
                continue;
            }
            if (a[0], a[1]) > (b[0], b[1]) {
                std::mem::swap(&mut a, &mut b);
            }
            let t = (c - a[axis]) / (b[axis] - a[axis]);
            let v = a[other] + t * (b[other] - a[other]);
            if best.is_none_or(|w| (v - near).abs() < (w - near).abs()) {
                best = Some(v);
            }
        }
        best.filter(|v| (v - near).abs() <= 1e3 * self.eps)
    }

    /// The cell `[x0, y0, x1, y1]` inside the region: its pieces (simple polygons).
    fn clip(&self, cell: [f64; 4], depth: usize) -> Vec<Vec<Point>> {
        let eps = self.eps;
        let rect = vec![
            [cell[0], cell[1]],
            [cell[2], cell[1]],
            [cell[2], cell[3]],
            [cell[0], cell[3]],
        ];
        let cut = self.edges.iter().any(|&(a, b)| {
            segment_meets_box(
                a,
                b,
                [cell[0] - eps, cell[1] - eps, cell[2] + eps, cell[3] + eps],
            )
        });
        if !cut {
            let c = [(cell[0] + cell[2]) / 2.0, (cell[1] + cell[3]) / 2.0];
            return if self.o.contains(c) {
                vec![rect]
            } else {
                vec![]
            };
        }
        let region: Vec<Vec<Point>> = self.o.rings().cloned().collect();
        let shapes = rect.overlay_as::<i64>(&region, OverlayRule::Intersect, FillRule::EvenOdd);
        // The original vertices within the cell, to snap to.
        let verts: Vec<Point> = self
            .o
            .rings()
            .flatten()
            .copied()
            .filter(|p| {
                p[0] >= cell[0] - 2.0 * eps
                    && p[0] <= cell[2] + 2.0 * eps
                    && p[1] >= cell[1] - 2.0 * eps
                    && p[1] <= cell[3] + 2.0 * eps
            })
            .collect();
        let mut out = Vec::new();
        for shape in shapes {
            if shape.len() > 1 && depth < 12 {
                // The cell holds a whole hole: cut it in two and try again.
                let xm = (cell[0] + cell[2]) / 2.0;
                let ym = (cell[1] + cell[3]) / 2.0;
                let halves = if cell[2] - cell[0] >= cell[3] - cell[1] {
                    [
                        [cell[0], cell[1], xm, cell[3]],
                        [xm, cell[1], cell[2], cell[3]],
                    ]
                } else {
                    [
                        [cell[0], cell[1], cell[2], ym],
                        [cell[0], ym, cell[2], cell[3]],
                    ]
                };
                return halves
                    .iter()
                    .flat_map(|h| self.clip(*h, depth + 1))
                    .collect();
            }
            let Some(ring) = shape.first() else { continue };
            let mut poly: Vec<Point> = Vec::with_capacity(ring.len());
            for q in ring {
                let s = self.snap(*q, cell, &verts);
                if poly.last() != Some(&s) {
                    poly.push(s);
                }
            }
            while poly.len() > 1 && poly.first() == poly.last() {
                poly.pop();
            }
            if poly.len() < 3 || signed_area(&poly).abs() <= eps * eps {
                continue;
            }
            if signed_area(&poly) < 0.0 {
                poly.reverse();
            }
            out.push(poly);
        }
        out
    }

    fn snap(&self, q: Point, cell: [f64; 4], verts: &[Point]) -> Point {
        let eps = self.eps;
        let tol = 1e3 * eps;
        for x in [cell[0], cell[2]] {
            for y in [cell[1], cell[3]] {
                if (q[0] - x).abs() <= tol && (q[1] - y).abs() <= tol {
                    // A cell corner unless an outline vertex is there.
                    if let Some(v) = verts
                        .iter()
                        .find(|v| (v[0] - x).abs() <= eps && (v[1] - y).abs() <= eps)
                    {
                        return *v;
                    }
                    return [x, y];
                }
            }
        }
        if let Some(v) = verts
            .iter()
            .filter(|v| (v[0] - q[0]).hypot(v[1] - q[1]) <= tol)
            .min_by(|a, b| {
                (a[0] - q[0])
                    .hypot(a[1] - q[1])
                    .total_cmp(&(b[0] - q[0]).hypot(b[1] - q[1]))
            })
        {
            return *v;
        }
        for x in [cell[0], cell[2]] {
            if (q[0] - x).abs() <= tol {
                if let Some(y) = self.axis_crossing(0, x, q[1]) {
                    return [x, y];
                }
            }
        }
        for y in [cell[1], cell[3]] {
            if (q[1] - y).abs() <= tol {
                if let Some(x) = self.axis_crossing(1, y, q[0]) {
                    return [x, y];
                }
            }
        }
        q
    }
}

fn cells(
    o: &Outline,
    length: f64,
    height: f64,
    bond: bool,
    opts: &MeshOptions,
) -> Result<Vec<Vec<Point>>> {
    let b = o.bbox();
    let eps = 1e-9 * o.diag();
    let ys = lines(b[1], b[3], height, &axis_levels(o, 1, eps), eps);
    let xs_grid = lines(
        b[0],
        b[2],
        length,
        &if bond { vec![] } else { axis_levels(o, 0, eps) },
        eps,
    );
    let region = Region {
        o,
        edges: o
            .rings()
            .flat_map(|r| (0..r.len()).map(move |i| (r[i], r[(i + 1) % r.len()])))
            .collect(),
        eps,
    };
    let mut polys: Vec<Vec<Point>> = Vec::new();
    // Per element: its whole area, for the small-piece rule.
    let mut whole: Vec<f64> = Vec::new();
    for (c, w) in ys.windows(2).enumerate() {
        let (y0, y1) = (w[0], w[1]);
        let xs: Vec<f64> = if bond && c % 2 == 1 {
            let mut v = vec![xs_grid[0]];
            v.extend(xs_grid.windows(2).map(|p| (p[0] + p[1]) / 2.0));
            v.push(xs_grid[xs_grid.len() - 1]);
            v
        } else {
            xs_grid.clone()
        };
        for xw in xs.windows(2) {
            let cell = [xw[0], y0, xw[1], y1];
            for p in region.clip(cell, 0) {
                polys.push(p);
                whole.push((xw[1] - xw[0]) * (y1 - y0));
            }
        }
    }
    if opts.min_piece > 0.0 {
        merge_small(&mut polys, &whole, opts.min_piece, eps);
    }
    Ok(polys)
}

/// Length of the shared boundary of two polygons (collinear overlapping edges of opposite
/// direction).
fn shared_length(p: &[Point], q: &[Point], eps: f64) -> f64 {
    let mut total = 0.0;
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let l = d[0].hypot(d[1]);
        if l <= eps {
            continue;
        }
        let e = [d[0] / l, d[1] / l];
        for j in 0..q.len() {
            let (c, f) = (q[j], q[(j + 1) % q.len()]);
            let off = |r: Point| (r[0] - a[0]) * e[1] - (r[1] - a[1]) * e[0];
            if off(c).abs() > eps || off(f).abs() > eps {
                continue;
            }
            let s = |r: Point| (r[0] - a[0]) * e[0] + (r[1] - a[1]) * e[1];
            let (s0, s1) = (s(c).min(s(f)), s(c).max(s(f)));
            let ov = s1.min(l) - s0.max(0.0);
            if ov > eps {
                total += ov;
            }
        }
    }
    total
}

/// Merge each piece smaller than `frac` of its element into the neighbour with which it
/// shares the longest boundary (when their union is one simple polygon).
fn merge_small(polys: &mut Vec<Vec<Point>>, whole: &[f64], frac: f64, eps: f64) {
    let mut alive: Vec<bool> = vec![true; polys.len()];
    let small: Vec<usize> = (0..polys.len())
        .filter(|&i| signed_area(&polys[i]).abs() < frac * whole[i])
        .collect();
    for i in small {
        if !alive[i] {
            continue;
        }
        let bi = bbox(&polys[i]);
        let best = (0..polys.len())
            .filter(|&j| j != i && alive[j])
            .filter(|&j| {
                let bj = bbox(&polys[j]);
                bi[0] <= bj[2] + eps
                    && bj[0] <= bi[2] + eps
                    && bi[1] <= bj[3] + eps
                    && bj[1] <= bi[3] + eps
            })
            .map(|j| (j, shared_length(&polys[i], &polys[j], eps)))
            .filter(|&(_, l)| l > 0.0)
            .max_by(|a, b| a.1.total_cmp(&b.1).then(b.0.cmp(&a.0)));
        let Some((j, _)) = best else { continue };
        let verts: Vec<Point> = polys[i].iter().chain(&polys[j]).copied().collect();
        let shapes = polys[j].overlay_as::<i64>(&polys[i], OverlayRule::Union, FillRule::NonZero);
        if shapes.len() != 1 || shapes[0].len() != 1 {
            continue;
        }
        let mut ring: Vec<Point> = Vec::new();
        for q in &shapes[0][0] {
            let s = verts
                .iter()
                .copied()
                .min_by(|a, b| {
                    (a[0] - q[0])
                        .hypot(a[1] - q[1])
                        .total_cmp(&(b[0] - q[0]).hypot(b[1] - q[1]))
                })
                .unwrap_or(*q);
            if ring.last() != Some(&s) {
                ring.push(s);
            }
        }
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        let want = signed_area(&polys[i]).abs() + signed_area(&polys[j]).abs();
        if ring.len() < 3 || (signed_area(&ring).abs() - want).abs() > 1e-9 * want.max(eps) {
            continue;
        }
        if crate::geometry::self_intersection(&ring, eps).is_some() {
            continue;
        }
        if signed_area(&ring) < 0.0 {
            ring.reverse();
        }
        polys[j] = ring;
        alive[i] = false;
    }
    let mut k = 0;
    polys.retain(|_| {
        k += 1;
        alive[k - 1]
    });
}

// --- foundation and model ----------------------------------------------------------------

/// The base of the outline: the x range of its outer boundary's horizontal edges at the
/// lowest y, and that y.
fn base(o: &Outline) -> Result<(f64, f64, f64)> {
    let b = o.bbox();
    let eps = 1e-9 * o.diag();
    let r = &o.outer;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..r.len() {
        let (a, c) = (r[i], r[(i + 1) % r.len()]);
        if (a[1] - b[1]).abs() <= eps && (c[1] - b[1]).abs() <= eps && (a[0] - c[0]).abs() > eps {
            lo = lo.min(a[0].min(c[0]));
            hi = hi.max(a[0].max(c[0]));
        }
    }
    if lo >= hi {
        return Err(bad(format!(
            "the outer boundary has no horizontal edge at its lowest level (y = {}) to stand on",
            b[1]
        )));
    }
    Ok((lo, hi, b[1]))
}

/// The supports under the outline's base: equal parts of its x range, left to right.
pub fn foundation_supports(outline: &Outline, f: &Foundation) -> Result<Vec<Support>> {
    let o = outline.validated()?;
    if !(f.depth.is_finite() && f.depth > 0.0) {
        return Err(bad(format!(
            "the foundation depth {} must be a positive number (m)",
            f.depth
        )));
    }
    if f.names.is_empty() {
        return Err(bad("the foundation needs at least one support name"));
    }
    let mut seen = std::collections::BTreeSet::new();
    for n in &f.names {
        if n.trim().is_empty() {
            return Err(bad("a foundation support has an empty name"));
        }
        if !seen.insert(n) {
            return Err(bad(format!(
                "the foundation support name '{n}' is repeated"
            )));
        }
    }
    let (lo, hi, y) = base(&o)?;
    let n = f.names.len();
    let at = |k: usize| {
        if k == n {
            hi
        } else {
            lo + (hi - lo) * k as f64 / n as f64
        }
    };
    Ok(f.names
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let (x0, x1) = (at(k), at(k + 1));
            Support {
                name: name.clone(),
                polygon: vec![[x0, y - f.depth], [x1, y - f.depth], [x1, y], [x0, y]],
                motion: [0.0; 3],
                connection: Default::default(),
            }
        })
        .collect())
}

/// The outline with the foundation's part boundaries added as vertices of its base edges
/// (so that triangles end where supports do).
fn with_base_cuts(o: &Outline, f: &Foundation) -> Result<Outline> {
    let (lo, hi, _) = base(o)?;
    let n = f.names.len();
    let cuts: Vec<f64> = (1..n)
        .map(|k| lo + (hi - lo) * k as f64 / n as f64)
        .collect();
    base_cuts(o, &cuts)
}

/// The outline with vertices added on its lowest horizontal edges at the abscissas `cuts`.
pub(crate) fn base_cuts(o: &Outline, cuts: &[f64]) -> Result<Outline> {
    let (_, _, y) = base(o)?;
    let eps = 1e-9 * o.diag();
    let r = &o.outer;
    let mut out = Vec::with_capacity(r.len() + cuts.len());
    for i in 0..r.len() {
        let (a, b) = (r[i], r[(i + 1) % r.len()]);
        out.push(a);
        if (a[1] - y).abs() <= eps && (b[1] - y).abs() <= eps {
            let mut inner: Vec<f64> = cuts
                .iter()
                .copied()
                .filter(|&c| c > a[0].min(b[0]) + eps && c < a[0].max(b[0]) - eps)
                .collect();
            inner.sort_by(f64::total_cmp);
            if b[0] < a[0] {
                inner.reverse();
            }
            out.extend(inner.into_iter().map(|c| [c, y]));
        }
    }
    Ok(Outline {
        outer: out,
        holes: o.holes.clone(),
    })
}

/// A wall model: the outline meshed as `kind`, of unit weight `unit_weight` (kN/m³) and
/// out-of-plane `thickness` (m), self-weight as its dead load, no live load, standing on the
/// foundation `f`.
pub fn mesh_wall(
    outline: &Outline,
    kind: &MeshKind,
    unit_weight: f64,
    thickness: f64,
    f: &Foundation,
    opts: &MeshOptions,
) -> Result<Model> {
    if !(unit_weight.is_finite() && unit_weight >= 0.0) {
        return Err(bad(format!(
            "unit weight {unit_weight} must be a finite number ≥ 0 (kN/m³)"
        )));
    }
    if !(thickness.is_finite() && thickness > 0.0) {
        return Err(bad(format!(
            "thickness {thickness} must be a positive number (m)"
        )));
    }
    let o = outline.validated()?;
    let supports = foundation_supports(&o, f)?;
    let o = if matches!(kind, MeshKind::Triangles { .. }) {
        with_base_cuts(&o, f)?
    } else {
        o
    };
    let polys = mesh_polygons(&o, kind, opts)?;
    let mut materials = BTreeMap::new();
    materials.insert(
        "default".to_string(),
        Material {
            unit_weight,
            width: thickness,
            ..Material::default()
        },
    );
    let b = o.bbox();
    // Numbers as typed (0.4·0.2 is 0.08, not 0.08000000000000002).
    let num = |x: f64| format!("{}", (x * 1e9).round() / 1e9);
    let what = match *kind {
        MeshKind::Grid { length, height } => {
            format!("grid of {} × {} m elements", num(length), num(height))
        }
        MeshKind::RunningBond { length, height } => {
            format!("running bond of {} × {} m units", num(length), num(height))
        }
        MeshKind::Triangles {
            max_area,
            min_angle_deg,
        } => format!(
            "triangles of at most {} m², angles ≥ {}°",
            num(max_area),
            num(min_angle_deg)
        ),
    };
    Ok(Model {
        description: format!(
            "wall outline {:.3} × {:.3} m with {} opening(s), {}: {} elements on {} foundation segment(s)",
            b[2] - b[0],
            b[3] - b[1],
            o.holes.len(),
            what,
            polys.len(),
            supports.len()
        ),
        materials,
        blocks: polys
            .into_iter()
            .map(|polygon| Block {
                polygon,
                material: None,
            })
            .collect(),
        supports,
        loads: Loads {
            self_weight: true,
            dead: vec![],
            live: vec![],
        },
        tolerance: None,
        cracks: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_with_hole() -> Outline {
        Outline::new(
            vec![[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]],
            vec![vec![[1.0, 1.0], [1.0, 2.0], [2.5, 2.0], [2.5, 1.0]]],
        )
    }

    #[test]
    fn every_kind_tiles_the_region() {
        let o = square_with_hole();
        for kind in [
            MeshKind::Grid {
                length: 0.7,
                height: 0.4,
            },
            MeshKind::RunningBond {
                length: 0.7,
                height: 0.4,
            },
            MeshKind::Triangles {
                max_area: 0.2,
                min_angle_deg: 28.0,
            },
        ] {
            let p = mesh_polygons(&o, &kind, &MeshOptions::default()).unwrap();
            let a: f64 = p.iter().map(|q| signed_area(q)).sum();
            assert!((a - 10.5).abs() < 1e-9 * 10.5, "{kind:?}: {a}");
        }
    }

    #[test]
    fn a_hole_that_touches_the_outer_boundary_is_refused() {
        let o = Outline::new(
            vec![[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]],
            vec![vec![[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]],
        );
        let e = o.validated().unwrap_err().to_string();
        assert!(e.contains("hole 0"), "{e}");
    }
}
