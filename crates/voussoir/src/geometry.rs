//! Planar geometry: polygons, finite rigid motions, interface detection.
//!
//! Interface detection never compares all pairs: edges are bucketed by their supporting line
//! (sorted by direction, then by offset), and within a line the edges are swept in order, so the
//! cost is O(E log E) in the number of edges.

use crate::model::Point;

/// Signed area of a polygon (positive when counter-clockwise).
pub fn signed_area(p: &[Point]) -> f64 {
    let n = p.len();
    let mut a = 0.0;
    for i in 0..n {
        let [x0, y0] = p[i];
        let [x1, y1] = p[(i + 1) % n];
        a += x0 * y1 - x1 * y0;
    }
    0.5 * a
}

/// Area and centroid of a simple polygon (either orientation; area returned positive).
pub fn area_centroid(p: &[Point]) -> (f64, Point) {
    // Shift to the first vertex for accuracy far from the origin.
    let o = p[0];
    let n = p.len();
    let (mut a, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let (x0, y0) = (p[i][0] - o[0], p[i][1] - o[1]);
        let j = (i + 1) % n;
        let (x1, y1) = (p[j][0] - o[0], p[j][1] - o[1]);
        let cr = x0 * y1 - x1 * y0;
        a += cr;
        cx += (x0 + x1) * cr;
        cy += (y0 + y1) * cr;
    }
    let area = 0.5 * a;
    if area == 0.0 {
        return (0.0, o);
    }
    (
        area.abs(),
        [o[0] + cx / (6.0 * area), o[1] + cy / (6.0 * area)],
    )
}

/// The plane's vector operations under their short names (defined once, in [`crate::vector`]).
pub use crate::vector::{dot2 as dot, norm2 as norm, perp_dot as cross, sub2 as sub};

/// Axis-aligned bounding box `[xmin, ymin, xmax, ymax]`.
pub fn bbox(p: &[Point]) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for q in p {
        b[0] = b[0].min(q[0]);
        b[1] = b[1].min(q[1]);
        b[2] = b[2].max(q[0]);
        b[3] = b[3].max(q[1]);
    }
    b
}

/// Whether two closed segments properly cross (interiors intersect at a single point, not
/// merely touching within `tol`).
fn segments_cross(a0: Point, a1: Point, b0: Point, b1: Point, tol: f64) -> bool {
    let da = sub(a1, a0);
    let db = sub(b1, b0);
    let la = norm(da);
    let lb = norm(db);
    if la == 0.0 || lb == 0.0 {
        return false;
    }
    // Signed distances of b's ends from line a, and of a's ends from line b.
    let s0 = cross(da, sub(b0, a0)) / la;
    let s1 = cross(da, sub(b1, a0)) / la;
    let t0 = cross(db, sub(a0, b0)) / lb;
    let t1 = cross(db, sub(a1, b0)) / lb;
    ((s0 > tol && s1 < -tol) || (s0 < -tol && s1 > tol))
        && ((t0 > tol && t1 < -tol) || (t0 < -tol && t1 > tol))
}

/// First pair of non-adjacent edges of a polygon that cross or touch, if any.
pub fn self_intersection(p: &[Point], tol: f64) -> Option<(usize, usize)> {
    let n = p.len();
    for i in 0..n {
        let (a0, a1) = (p[i], p[(i + 1) % n]);
        for j in i + 1..n {
            if j == i + 1 || (i == 0 && j == n - 1) {
                continue;
            }
            let (b0, b1) = (p[j], p[(j + 1) % n]);
            if segments_cross(a0, a1, b0, b1, tol) || touches(a0, a1, b0, b1, tol) {
                return Some((i, j));
            }
        }
    }
    None
}

/// Distance from point `q` to segment `a`–`b`.
pub fn point_segment_distance(q: Point, a: Point, b: Point) -> f64 {
    let d = sub(b, a);
    let l2 = dot(d, d);
    let t = if l2 == 0.0 {
        0.0
    } else {
        (dot(sub(q, a), d) / l2).clamp(0.0, 1.0)
    };
    norm(sub(q, [a[0] + t * d[0], a[1] + t * d[1]]))
}

/// Whether two non-adjacent edges touch (an end of one lies on the other).
fn touches(a0: Point, a1: Point, b0: Point, b1: Point, tol: f64) -> bool {
    point_segment_distance(b0, a0, a1) <= tol
        || point_segment_distance(b1, a0, a1) <= tol
        || point_segment_distance(a0, b0, b1) <= tol
        || point_segment_distance(a1, b0, b1) <= tol
}

/// Whether segment a–b meets the closed box `[x0, y0, x1, y1]` (Liang–Barsky clipping; the
/// drawings' label placement and the outline mesher both ask it).
pub fn segment_meets_box(a: Point, b: Point, bx: [f64; 4]) -> bool {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d[0], a[0] - bx[0]),
        (d[0], bx[2] - a[0]),
        (-d[1], a[1] - bx[1]),
        (d[1], bx[3] - a[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

/// Whether `q` lies strictly inside polygon `p`, farther than `tol` from its boundary.
pub fn strictly_inside(q: Point, p: &[Point], tol: f64) -> bool {
    let n = p.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        if point_segment_distance(q, a, b) <= tol {
            return false;
        }
        if (a[1] > q[1]) != (b[1] > q[1]) {
            let x = a[0] + (q[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if q[0] < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Whether the interiors of two simple polygons overlap (beyond `tol`).
pub fn polygons_overlap(p: &[Point], q: &[Point], tol: f64) -> bool {
    let (n, m) = (p.len(), q.len());
    for i in 0..n {
        for j in 0..m {
            if segments_cross(p[i], p[(i + 1) % n], q[j], q[(j + 1) % m], tol) {
                return true;
            }
        }
    }
    // No proper crossing: one may contain the other, or they share edges. Test vertices and
    // edge midpoints of each against the other, and the centroids.
    let probe = |a: &[Point], b: &[Point]| {
        let k = a.len();
        (0..k).any(|i| {
            let v = a[i];
            let w = a[(i + 1) % k];
            strictly_inside(v, b, tol)
                || strictly_inside([(v[0] + w[0]) / 2.0, (v[1] + w[1]) / 2.0], b, tol)
        })
    };
    if probe(p, q) || probe(q, p) {
        return true;
    }
    let (_, cp) = area_centroid(p);
    let (_, cq) = area_centroid(q);
    (strictly_inside(cp, p, tol) && strictly_inside(cp, q, tol))
        || (strictly_inside(cq, q, tol) && strictly_inside(cq, p, tol))
}

/// A finite rigid motion of a body: rotation `theta` about the body's reference point `c`,
/// followed by translation `[u, v]`: `x ↦ c + [u, v] + R(θ)(x − c)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidMotion {
    pub center: Point,
    pub translation: Point,
    pub theta: f64,
}

impl RigidMotion {
    /// The motion `(u, v, θ)·s` of a body with reference point `center`.
    pub fn scaled(center: Point, d: [f64; 3], s: f64) -> Self {
        RigidMotion {
            center,
            translation: [d[0] * s, d[1] * s],
            theta: d[2] * s,
        }
    }
    pub fn apply(&self, x: Point) -> Point {
        let (sn, cs) = self.theta.sin_cos();
        let r = sub(x, self.center);
        [
            self.center[0] + self.translation[0] + cs * r[0] - sn * r[1],
            self.center[1] + self.translation[1] + sn * r[0] + cs * r[1],
        ]
    }
    /// Rotate a direction (free vector).
    pub fn rotate(&self, v: Point) -> Point {
        let (sn, cs) = self.theta.sin_cos();
        [cs * v[0] - sn * v[1], sn * v[0] + cs * v[1]]
    }
    /// The inverse motion.
    pub fn inverse(&self) -> Self {
        RigidMotion {
            center: [
                self.center[0] + self.translation[0],
                self.center[1] + self.translation[1],
            ],
            translation: [-self.translation[0], -self.translation[1]],
            theta: -self.theta,
        }
    }
}

/// Small-displacement field of a body: displacement of point `x` for DOFs `(u, v, θ)` at `c`.
#[inline]
pub fn small_displacement(c: Point, d: [f64; 3], x: Point) -> Point {
    [d[0] - d[2] * (x[1] - c[1]), d[1] + d[2] * (x[0] - c[0])]
}

/// One interface found between two bodies.
#[derive(Clone, Debug, PartialEq)]
pub struct Interface {
    /// Lower body index (in the caller's numbering).
    pub a: usize,
    pub b: usize,
    /// Unit normal from `a` into `b`.
    pub normal: Point,
    /// The two ends of the overlap.
    pub ends: [Point; 2],
}

/// An overlap of two bodies along a shared line with the same orientation, which means their
/// interiors overlap.
#[derive(Clone, Debug, PartialEq)]
pub struct Clash {
    pub a: usize,
    pub b: usize,
}

struct EdgeRec {
    body: usize,
    /// Direction angle of the supporting line, canonicalised into (−tol, π − tol].
    angle: f64,
    /// Whether the edge runs along the canonical direction (+1) or against it (−1).
    sense: i8,
    offset: f64,
    s0: f64,
    s1: f64,
}

/// Find all interfaces between `bodies` (polygons, counter-clockwise). `tol` is a length.
/// Returns the interfaces sorted by `(a, b, position)` and any same-orientation overlaps.
pub fn detect_interfaces(bodies: &[&[Point]], tol: f64) -> (Vec<Interface>, Vec<Clash>) {
    // Reference origin: centre of everything, so offsets are well conditioned.
    let mut bb = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in bodies {
        let b = bbox(p);
        bb = [
            bb[0].min(b[0]),
            bb[1].min(b[1]),
            bb[2].max(b[2]),
            bb[3].max(b[3]),
        ];
    }
    let o = [(bb[0] + bb[2]) / 2.0, (bb[1] + bb[3]) / 2.0];
    let size = (bb[2] - bb[0]).hypot(bb[3] - bb[1]).max(tol);
    // Angular tolerance: an edge of the model's size deviates by tol at its end.
    let atol = (tol / size).max(1e-12);

    let mut edges: Vec<EdgeRec> = Vec::new();
    for (bi, p) in bodies.iter().enumerate() {
        let n = p.len();
        for i in 0..n {
            let a = p[i];
            let b = p[(i + 1) % n];
            let d = sub(b, a);
            let l = norm(d);
            if l <= tol {
                continue;
            }
            let mut ang = d[1].atan2(d[0]); // (−π, π]
            let mut sense = 1i8;
            if ang <= -atol {
                ang += std::f64::consts::PI;
                sense = -1;
            }
            if ang > std::f64::consts::PI - atol {
                ang -= std::f64::consts::PI;
                sense = -sense;
            }
            let e = [ang.cos(), ang.sin()];
            let m = [-e[1], e[0]];
            let ra = sub(a, o);
            let rb = sub(b, o);
            let offset = 0.5 * (dot(m, ra) + dot(m, rb));
            let (sa, sb) = (dot(e, ra), dot(e, rb));
            edges.push(EdgeRec {
                body: bi,
                angle: ang,
                sense,
                offset,
                s0: sa.min(sb),
                s1: sa.max(sb),
            });
        }
    }
    edges.sort_by(|x, y| {
        x.angle
            .total_cmp(&y.angle)
            .then(x.offset.total_cmp(&y.offset))
    });

    let mut found: Vec<Interface> = Vec::new();
    let mut clashes: Vec<Clash> = Vec::new();
    // Group by angle (chains of near-equal angles), then by offset.
    let mut i = 0;
    while i < edges.len() {
        let mut j = i + 1;
        while j < edges.len() && edges[j].angle - edges[j - 1].angle <= atol {
            j += 1;
        }
        let group = &mut edges[i..j];
        group.sort_by(|x, y| x.offset.total_cmp(&y.offset));
        let mut k = 0;
        while k < group.len() {
            let mut l = k + 1;
            while l < group.len() && group[l].offset - group[l - 1].offset <= tol {
                l += 1;
            }
            if l - k > 1 {
                sweep_line(&mut group[k..l], o, tol, &mut found, &mut clashes);
            }
            k = l;
        }
        i = j;
    }
    found.sort_by(|x, y| {
        (x.a, x.b)
            .cmp(&(y.a, y.b))
            .then(x.ends[0][0].total_cmp(&y.ends[0][0]))
            .then(x.ends[0][1].total_cmp(&y.ends[0][1]))
    });
    clashes.sort_by_key(|c| (c.a, c.b));
    clashes.dedup();
    (found, clashes)
}

/// Edges on one line: sweep by start coordinate, pairing overlapping edges of different bodies.
fn sweep_line(
    line: &mut [EdgeRec],
    o: Point,
    tol: f64,
    found: &mut Vec<Interface>,
    clashes: &mut Vec<Clash>,
) {
    line.sort_by(|x, y| x.s0.total_cmp(&y.s0));
    // Line geometry from the mean angle and offset of the group.
    let n = line.len() as f64;
    let ang = line.iter().map(|e| e.angle).sum::<f64>() / n;
    let off = line.iter().map(|e| e.offset).sum::<f64>() / n;
    let e = [ang.cos(), ang.sin()];
    let m = [-e[1], e[0]];
    let at = |s: f64| [o[0] + s * e[0] + off * m[0], o[1] + s * e[1] + off * m[1]];
    let mut active: Vec<usize> = Vec::new();
    for idx in 0..line.len() {
        let s0 = line[idx].s0;
        active.retain(|&k| line[k].s1 > s0 + tol);
        for &k in &active {
            let (p, q) = (&line[k], &line[idx]);
            if p.body == q.body {
                continue;
            }
            let lo = p.s0.max(q.s0);
            let hi = p.s1.min(q.s1);
            if hi - lo <= tol {
                continue;
            }
            let (a, b, sa) = if p.body < q.body {
                (p.body, q.body, p.sense)
            } else {
                (q.body, p.body, q.sense)
            };
            if p.sense == q.sense {
                clashes.push(Clash { a, b });
                continue;
            }
            // Body a's edge runs along `sa·e` with a's interior on its left, so the outward
            // normal of a (pointing into b) is the right-hand normal of that direction.
            let dir = [sa as f64 * e[0], sa as f64 * e[1]];
            let normal = [dir[1], -dir[0]];
            found.push(Interface {
                a,
                b,
                normal,
                ends: [at(lo), at(hi)],
            });
        }
        active.push(idx);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centroid_of_unit_square() {
        let sq = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
        let (a, c) = area_centroid(&sq);
        assert!((a - 2.0).abs() < 1e-15);
        assert!((c[0] - 1.0).abs() < 1e-15 && (c[1] - 0.5).abs() < 1e-15);
    }

    #[test]
    fn two_stacked_squares_share_one_interface() {
        let a = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let b = [[0.5, 1.0], [1.5, 1.0], [1.5, 2.0], [0.5, 2.0]];
        let (ifs, cl) = detect_interfaces(&[&a, &b], 1e-9);
        assert!(cl.is_empty());
        assert_eq!(ifs.len(), 1);
        let i = &ifs[0];
        assert_eq!((i.a, i.b), (0, 1));
        assert!((i.normal[1] - 1.0).abs() < 1e-12);
        let xs = [i.ends[0][0], i.ends[1][0]];
        assert!((xs[0].min(xs[1]) - 0.5).abs() < 1e-12 && (xs[0].max(xs[1]) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn rigid_motion_round_trip() {
        let m = RigidMotion::scaled([1.0, 2.0], [0.3, -0.2, 0.7], 1.0);
        let x = [3.5, -1.25];
        let y = m.inverse().apply(m.apply(x));
        assert!((x[0] - y[0]).abs() < 1e-14 && (x[1] - y[1]).abs() < 1e-14);
    }
}
