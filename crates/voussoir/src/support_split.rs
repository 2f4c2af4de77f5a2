//! Cutting a support into parts by vertical planes `x = c` (foundations as drawn): the geometry.
//!
//! A planar support (a simple polygon, convex or not) is cut with the `i_overlay` crate (the
//! polygon intersected with the vertical strip between two consecutive cuts, on its 64-bit
//! integer grid), then every vertex of the result is put back exactly where it belongs: on an
//! original vertex, or on the cut line at the ordinate where an original edge crosses it. A
//! strip of a non-convex polygon may hold several pieces; each is a part.
//!
//! A 3D support (a closed polyhedron) is cut only when it is convex: each face is clipped by the
//! half-space and the section is closed by a cap polygon (convex, as the section of a convex
//! solid). A non-convex support is refused with a line that says so.

use crate::error::{Error, Result};
use crate::model::Point;
use crate::model3d::Point3;
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;

/// Relative tolerance (of the body's diagonal) within which a vertex found by the clipper is
/// the original vertex or a point of a cut line.
const SNAP: f64 = 1e-9;

/// A cut nearer to a support's end than this fraction of its width is no cut (the analyses'
/// default geometric tolerance, 1e-7, so that no part is too thin to carry a joint).
const INSIDE: f64 = 1e-7;

fn bbox2(p: &[Point]) -> [f64; 4] {
    p.iter().fold(
        [f64::INFINITY, f64::INFINITY, -f64::INFINITY, -f64::INFINITY],
        |b, q| {
            [
                b[0].min(q[0]),
                b[1].min(q[1]),
                b[2].max(q[0]),
                b[3].max(q[1]),
            ]
        },
    )
}

/// The x range of a polygon.
pub fn x_range2(p: &[Point]) -> [f64; 2] {
    let b = bbox2(p);
    [b[0], b[2]]
}

/// The x range of a polyhedron's vertices.
pub fn x_range3(v: &[Point3]) -> [f64; 2] {
    v.iter().fold([f64::INFINITY, -f64::INFINITY], |r, q| {
        [r[0].min(q[0]), r[1].max(q[0])]
    })
}

/// Whether `c` lies strictly inside the x range `r` (by more than a relative tolerance, so
/// that a cut on a support's edge is no cut).
pub fn strictly_inside(r: [f64; 2], c: f64) -> bool {
    let tol = INSIDE * (r[1] - r[0]).abs().max(f64::MIN_POSITIVE);
    c > r[0] + tol && c < r[1] - tol
}

/// The ordinate where a polygon's edge crosses `x = c` nearest to `y` (`None` if none does).
fn y_crossing(p: &[Point], c: f64, y: f64) -> Option<f64> {
    let n = p.len();
    let mut best: Option<f64> = None;
    for i in 0..n {
        let (mut a, mut b) = (p[i], p[(i + 1) % n]);
        if (a[0] - c) * (b[0] - c) > 0.0 || a[0] == b[0] {
            continue;
        }
        // The same crossing whichever way the edge runs.
        if (a[0], a[1]) > (b[0], b[1]) {
            std::mem::swap(&mut a, &mut b);
        }
        let t = (c - a[0]) / (b[0] - a[0]);
        let yc = a[1] + t * (b[1] - a[1]);
        if best.is_none_or(|q| (yc - y).abs() < (q - y).abs()) {
            best = Some(yc);
        }
    }
    best
}

/// Cut a simple polygon by the vertical lines `x = c` of `cuts` (increasing, each strictly
/// inside the polygon's x range). Returns, for each strip between consecutive cuts (from the
/// left), its pieces: counter-clockwise polygons, ordered by their lowest vertex.
pub fn split_polygon(poly: &[Point], cuts: &[f64]) -> Result<Vec<Vec<Vec<Point>>>> {
    let b = bbox2(poly);
    let diag = (b[2] - b[0]).hypot(b[3] - b[1]);
    if !(diag.is_finite() && diag > 0.0) {
        return Err(Error::Request(
            "its polygon has no finite, non-zero extent".into(),
        ));
    }
    let eps = SNAP * diag;
    // The original vertices by x, to find the one a clipped vertex stands for.
    let mut by_x: Vec<Point> = poly.to_vec();
    by_x.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let original = |q: [f64; 2]| -> Option<Point> {
        let start = by_x.partition_point(|o| o[0] < q[0] - eps);
        by_x[start..]
            .iter()
            .take_while(|o| o[0] <= q[0] + eps)
            .copied()
            .filter(|o| (o[0] - q[0]).hypot(o[1] - q[1]) <= eps)
            .min_by(|o, r| {
                let d = |o: &Point| (o[0] - q[0]).hypot(o[1] - q[1]);
                d(o).total_cmp(&d(r))
            })
    };
    let (ylo, yhi) = (b[1] - diag, b[3] + diag);
    let mut edges = vec![b[0] - diag];
    edges.extend_from_slice(cuts);
    edges.push(b[2] + diag);
    let subj: Vec<[f64; 2]> = poly.to_vec();
    let mut strips = Vec::with_capacity(edges.len() - 1);
    for w in edges.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        let rect = vec![[lo, ylo], [hi, ylo], [hi, yhi], [lo, yhi]];
        let shapes = subj.overlay_as::<i64>(&rect, OverlayRule::Intersect, FillRule::NonZero);
        let mut pieces = Vec::new();
        for shape in shapes {
            if shape.len() > 1 {
                // A strip of a simple polygon is simply connected: a hole means a bad polygon.
                return Err(Error::Request(
                    "the support's polygon is not simple (a cut of it has a hole)".into(),
                ));
            }
            let Some(outer) = shape.first() else { continue };
            let mut ring: Vec<Point> = Vec::with_capacity(outer.len());
            for q in outer {
                let snapped = original(*q)
                    .or_else(|| {
                        [lo, hi]
                            .into_iter()
                            .find(|c| (q[0] - c).abs() <= eps)
                            .and_then(|c| y_crossing(poly, c, q[1]).map(|y| [c, y]))
                    })
                    .unwrap_or(*q);
                if ring.last() != Some(&snapped) {
                    ring.push(snapped);
                }
            }
            while ring.len() > 1 && ring.first() == ring.last() {
                ring.pop();
            }
            let area = crate::geometry::signed_area(&ring);
            if ring.len() < 3 || area.abs() <= eps * diag {
                continue;
            }
            if area < 0.0 {
                ring.reverse();
            }
            // Start at the lexicographically smallest vertex: the same ring whatever the
            // clipper's starting point.
            let first = (0..ring.len())
                .min_by(|&i, &j| {
                    (ring[i][0], ring[i][1])
                        .partial_cmp(&(ring[j][0], ring[j][1]))
                        .unwrap_or(std::cmp::Ordering::Equal)
                })
                .unwrap_or(0);
            ring.rotate_left(first);
            pieces.push(ring);
        }
        pieces.sort_by(|p, q| {
            let (a, b) = (bbox2(p), bbox2(q));
            (a[1], a[0])
                .partial_cmp(&(b[1], b[0]))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        strips.push(pieces);
    }
    Ok(strips)
}

use crate::vector::{self, dot3, sub3, V3};

/// Newell's normal (twice the vector area) and the mean of a face's vertices.
fn newell(v: &[V3], f: &[usize]) -> (V3, V3) {
    (
        vector::newell(f.len(), |k| v[f[k]]),
        vector::mean3(f.len(), |k| v[f[k]]),
    )
}

/// A polyhedron: vertices and faces (counter-clockwise seen from outside).
pub type Polyhedron = (Vec<Point3>, Vec<Vec<usize>>);

/// Whether a closed polyhedron is convex: every vertex on the inner side of every face's
/// plane, within `tol`.
fn convex(v: &[V3], faces: &[Vec<usize>], tol: f64) -> bool {
    faces.iter().all(|f| {
        let (n, c) = newell(v, f);
        let len = dot3(n, n).sqrt();
        len > 0.0 && v.iter().all(|p| dot3(n, sub3(*p, c)) / len <= tol)
    })
}

/// The part of a convex polyhedron where `side · (x − c) ≤ 0`, closed by a cap on `x = c`.
fn clip_convex(v: &[V3], faces: &[Vec<usize>], c: f64, side: f64, eps: f64) -> Polyhedron {
    let mut verts: Vec<V3> = Vec::new();
    let mut index = std::collections::HashMap::<[u64; 3], usize>::new();
    let mut id = |p: V3, verts: &mut Vec<V3>| -> usize {
        let key = [p[0].to_bits(), p[1].to_bits(), p[2].to_bits()];
        *index.entry(key).or_insert_with(|| {
            verts.push(p);
            verts.len() - 1
        })
    };
    let d = |p: V3| {
        let s = side * (p[0] - c);
        if s.abs() <= eps {
            0.0
        } else {
            s
        }
    };
    // The crossing of an edge with the plane, the same whichever way the edge runs.
    let cross = |a: V3, b: V3| -> V3 {
        let (a, b) = if (a[0], a[1], a[2]) <= (b[0], b[1], b[2]) {
            (a, b)
        } else {
            (b, a)
        };
        let t = (c - a[0]) / (b[0] - a[0]);
        [c, a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]
    };
    let mut out_faces = Vec::new();
    let mut on_plane: Vec<usize> = Vec::new();
    for f in faces {
        let mut poly: Vec<usize> = Vec::new();
        for k in 0..f.len() {
            let (a, b) = (v[f[k]], v[f[(k + 1) % f.len()]]);
            let (da, db) = (d(a), d(b));
            if da <= 0.0 {
                let p = if da == 0.0 { [c, a[1], a[2]] } else { a };
                let i = id(p, &mut verts);
                poly.push(i);
                if da == 0.0 {
                    on_plane.push(i);
                }
            }
            if (da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0) {
                let i = id(cross(a, b), &mut verts);
                poly.push(i);
                on_plane.push(i);
            }
        }
        poly.dedup();
        while poly.len() > 1 && poly.first() == poly.last() {
            poly.pop();
        }
        // A face lying in the plane (the cap's place) or cut down to an edge is dropped.
        let in_plane = poly.iter().all(|&i| (verts[i][0] - c).abs() <= eps);
        if poly.len() >= 3 && !in_plane {
            out_faces.push(poly);
        }
    }
    on_plane.sort_unstable();
    on_plane.dedup();
    if on_plane.len() >= 3 {
        // The cap: the section of a convex solid is convex; its vertices in angular order
        // about their mean in the (y, z) plane, counter-clockwise seen from outside (+x side
        // when the part keeps x ≤ c).
        let m = on_plane.iter().fold([0.0, 0.0], |s, &i| {
            [
                s[0] + verts[i][1] / on_plane.len() as f64,
                s[1] + verts[i][2] / on_plane.len() as f64,
            ]
        });
        let angle = |i: usize| (verts[i][2] - m[1]).atan2(verts[i][1] - m[0]);
        on_plane.sort_by(|&i, &j| angle(i).total_cmp(&angle(j)));
        // Counter-clockwise in (y, z) seen from +x.
        if side < 0.0 {
            on_plane.reverse();
        }
        out_faces.push(on_plane);
    }
    // Keep only the vertices used, in first-use order.
    let mut used = vec![usize::MAX; verts.len()];
    let mut vs = Vec::new();
    for f in &mut out_faces {
        for i in f.iter_mut() {
            if used[*i] == usize::MAX {
                used[*i] = vs.len();
                vs.push(verts[*i]);
            }
            *i = used[*i];
        }
    }
    (vs, out_faces)
}

/// Cut a convex polyhedron by the planes `x = c` of `cuts` (increasing, each strictly inside
/// its x range): the parts from the left. A non-convex polyhedron is refused.
pub fn split_polyhedron(
    v: &[Point3],
    faces: &[Vec<usize>],
    cuts: &[f64],
) -> Result<Vec<Polyhedron>> {
    let lo = v.iter().fold([f64::INFINITY; 3], |m, p| {
        [m[0].min(p[0]), m[1].min(p[1]), m[2].min(p[2])]
    });
    let hi = v.iter().fold([-f64::INFINITY; 3], |m, p| {
        [m[0].max(p[0]), m[1].max(p[1]), m[2].max(p[2])]
    });
    let diag = dot3(sub3(hi, lo), sub3(hi, lo)).sqrt();
    if !(diag.is_finite() && diag > 0.0) {
        return Err(Error::Request(
            "its polyhedron has no finite, non-zero extent".into(),
        ));
    }
    let eps = SNAP * diag;
    if !convex(v, faces, eps) {
        return Err(Error::Request(
            "it is not convex: a 3D support is cut only when convex (cut it in the model)".into(),
        ));
    }
    let mut parts = Vec::with_capacity(cuts.len() + 1);
    let mut rest: Polyhedron = (v.to_vec(), faces.to_vec());
    for &c in cuts {
        parts.push(clip_convex(&rest.0, &rest.1, c, 1.0, eps));
        rest = clip_convex(&rest.0, &rest.1, c, -1.0, eps);
    }
    parts.push(rest);
    Ok(parts)
}
