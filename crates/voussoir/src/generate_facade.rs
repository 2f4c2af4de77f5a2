//! Façade generator: a wall (optionally gabled) with openings, meshed into rigid elements.
//!
//! * Openings: pointed-arch doors, round (rose) windows and rectangular windows. Arched openings
//!   get a ring of radial voussoirs (their joints point to the arcs' centres); the wall's
//!   elements are clipped against each opening and its ring, so every element stays a simple
//!   polygon whose cut edges lie on the ring's extrados chords (joints with the ring are found
//!   like any other). Pieces smaller than `min_piece` of an element are dropped.
//! * Mesh: a running bond (courses of `element` units, alternate courses offset by half a unit)
//!   or a structured grid (stack bond). Course lines are moved onto the doors' springings so that
//!   no element straddles a springing.
//! * Foundation: `segments` equal segments `f0 … f{n−1}` from left to right, `foundation_depth`
//!   deep, so that a settlement profile can move part of it.
//!
//! [`bondeno`] is the paper's case (Fig 18): about 22 m × 19 m, three rose windows, three pointed
//! doors.
//!
//! Clipping is exact polygon arithmetic on convex pieces: an element minus a convex hole is the
//! union of `element ∩ outside(edge i) ∩ inside(edges < i)`; the pieces are then merged back by
//! cancelling shared edges, so the result is one simple polygon per connected part.

use crate::error::{Error, Result};
use crate::generate::{self, ArchShape, ArchSpec, LiveLoad, RadiusAt};
use crate::geometry::{area_centroid, bbox, signed_area};
use crate::model::{Block, Load, Loads, Material, Model, Point, Support};
use std::collections::{BTreeMap, HashMap};
use std::f64::consts::PI;

/// An opening in the façade (metres; y = 0 at the foundation's top).
#[derive(Clone, Debug, PartialEq)]
pub enum Opening {
    /// A door with a pointed arch: clear `width`, jambs from the ground to `springing`, arcs
    /// centred on the springing line at ±`offset`·R from the axis (0.5: equilateral), ring of
    /// voussoirs `ring` thick.
    PointedDoor {
        x: f64,
        width: f64,
        springing: f64,
        offset: f64,
        ring: f64,
    },
    /// A round (rose) window of clear `radius` centred at (x, y), ring `ring` thick.
    Round {
        x: f64,
        y: f64,
        radius: f64,
        ring: f64,
    },
    /// A rectangular window.
    Rect { x0: f64, y0: f64, x1: f64, y1: f64 },
}

/// How the wall is meshed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FacadeMesh {
    /// Courses of units, alternate courses offset by half a unit.
    RunningBond,
    /// Aligned rows and columns of elements (stack bond).
    #[default]
    Grid,
    /// Unstructured triangles (constrained Delaunay, refined: [`crate::outline_mesh`]) of at
    /// most one element's area (`element[0]·element[1]`), no angle below `min_angle`.
    Triangles,
}

/// Parameters of a façade.
#[derive(Clone, Debug, PartialEq)]
pub struct FacadeSpec {
    pub width: f64,
    /// Height at the eaves (top of the rectangular part).
    pub height: f64,
    /// Extra height of a symmetric gable above the eaves (0: flat top).
    pub gable: f64,
    /// Element (unit) length and height.
    pub element: [f64; 2],
    pub mesh: FacadeMesh,
    pub openings: Vec<Opening>,
    /// Number of foundation segments.
    pub segments: usize,
    pub foundation_depth: f64,
    pub unit_weight: f64,
    /// Out-of-plane thickness of the façade (m).
    pub thickness: f64,
    /// Pieces of an element smaller than this fraction of its area are dropped.
    pub min_piece: f64,
    pub live: LiveLoad,
    /// Triangles: the smallest angle allowed (degrees).
    pub min_angle: f64,
}

impl Default for FacadeSpec {
    fn default() -> Self {
        bondeno(0.5, FacadeMesh::Grid)
    }
}

/// The paper's façade (Fig 18), after the Romanesque church of Bondeno: 22 m wide, eaves at
/// 14 m and a gable to 19 m, three pointed doors and three rose windows; elements of
/// `element` × `element`/2 m; 44 foundation segments of 0.5 m.
pub fn bondeno(element: f64, mesh: FacadeMesh) -> FacadeSpec {
    FacadeSpec {
        width: 22.0,
        height: 14.0,
        gable: 5.0,
        element: [element, element / 2.0],
        mesh,
        openings: vec![
            Opening::PointedDoor {
                x: 11.0,
                width: 2.6,
                springing: 3.5,
                offset: 0.5,
                ring: 0.5,
            },
            Opening::PointedDoor {
                x: 4.5,
                width: 1.6,
                springing: 2.5,
                offset: 0.5,
                ring: 0.4,
            },
            Opening::PointedDoor {
                x: 17.5,
                width: 1.6,
                springing: 2.5,
                offset: 0.5,
                ring: 0.4,
            },
            Opening::Round {
                x: 11.0,
                y: 10.0,
                radius: 2.0,
                ring: 0.5,
            },
            Opening::Round {
                x: 4.5,
                y: 8.0,
                radius: 1.0,
                ring: 0.35,
            },
            Opening::Round {
                x: 17.5,
                y: 8.0,
                radius: 1.0,
                ring: 0.35,
            },
        ],
        segments: 44,
        foundation_depth: 0.5,
        unit_weight: 18.0,
        thickness: 1.0,
        min_piece: 0.05,
        live: LiveLoad::None,
        min_angle: 30.0,
    }
}

fn bad(msg: String) -> Error {
    Error::Request(format!("façade: {msg}"))
}

// --- convex clipping ------------------------------------------------------------------------

/// A half-plane `n·x ≤ c` (inside).
#[derive(Clone, Copy, Debug)]
struct Half {
    n: Point,
    c: f64,
}

impl Half {
    /// The left side of the directed edge a→b (the inside of a counter-clockwise polygon).
    fn left_of(a: Point, b: Point) -> Half {
        let d = [b[0] - a[0], b[1] - a[1]];
        let l = d[0].hypot(d[1]);
        let n = [d[1] / l, -d[0] / l];
        Half {
            n,
            c: n[0] * a[0] + n[1] * a[1],
        }
    }
    fn flip(self) -> Half {
        Half {
            n: [-self.n[0], -self.n[1]],
            c: -self.c,
        }
    }
    fn dist(&self, p: Point) -> f64 {
        self.n[0] * p[0] + self.n[1] * p[1] - self.c
    }
}

/// Sutherland–Hodgman: `poly ∩ {h ≤ 0}`.
fn clip(poly: &[Point], h: Half) -> Vec<Point> {
    let n = poly.len();
    let mut out = Vec::with_capacity(n + 2);
    for i in 0..n {
        let (p, q) = (poly[i], poly[(i + 1) % n]);
        let (dp, dq) = (h.dist(p), h.dist(q));
        if dp <= 0.0 {
            out.push(p);
        }
        if (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0) {
            let t = dp / (dp - dq);
            out.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
        }
    }
    out
}

fn convex_halves(poly: &[Point]) -> Vec<Half> {
    let n = poly.len();
    (0..n)
        .map(|i| Half::left_of(poly[i], poly[(i + 1) % n]))
        .collect()
}

/// `piece ∖ hole` (both convex, counter-clockwise) as disjoint convex pieces.
fn subtract(piece: &[Point], hole: &[Point], eps: f64) -> Vec<Vec<Point>> {
    let hs = convex_halves(hole);
    // Entirely outside one edge of the hole: untouched.
    if hs.iter().any(|h| piece.iter().all(|&p| h.dist(p) >= -eps)) {
        return vec![piece.to_vec()];
    }
    let mut out = Vec::new();
    for (i, h) in hs.iter().enumerate() {
        let mut p = clip(piece, h.flip());
        for g in &hs[..i] {
            if p.len() < 3 {
                break;
            }
            p = clip(&p, *g);
        }
        if p.len() >= 3 && signed_area(&p).abs() > eps * eps {
            out.push(p);
        }
    }
    out
}

/// Merge disjoint pieces that tile a region into simple polygons (one per connected part), by
/// cancelling shared edges. Vertices are snapped to a grid of `eps`.
fn merge(pieces: &[Vec<Point>], eps: f64) -> Vec<Vec<Point>> {
    if pieces.len() == 1 {
        return pieces.to_vec();
    }
    let key = |p: Point| ((p[0] / eps).round() as i64, (p[1] / eps).round() as i64);
    let mut pts: Vec<Point> = Vec::new();
    let mut index: HashMap<(i64, i64), usize> = HashMap::new();
    let mut id = |p: Point, pts: &mut Vec<Point>| -> usize {
        *index.entry(key(p)).or_insert_with(|| {
            pts.push(p);
            pts.len() - 1
        })
    };
    let mut edges: Vec<(usize, usize)> = Vec::new();
    for poly in pieces {
        let ids: Vec<usize> = poly.iter().map(|&p| id(p, &mut pts)).collect();
        for i in 0..ids.len() {
            let (a, b) = (ids[i], ids[(i + 1) % ids.len()]);
            if a != b {
                edges.push((a, b));
            }
        }
    }
    // Split edges at vertices lying on them (T-junctions between pieces).
    let mut split: Vec<(usize, usize)> = Vec::new();
    for &(a, b) in &edges {
        let (pa, pb) = (pts[a], pts[b]);
        let d = [pb[0] - pa[0], pb[1] - pa[1]];
        let l2 = d[0] * d[0] + d[1] * d[1];
        let mut on: Vec<(f64, usize)> = Vec::new();
        for (k, &q) in pts.iter().enumerate() {
            if k == a || k == b {
                continue;
            }
            let t = ((q[0] - pa[0]) * d[0] + (q[1] - pa[1]) * d[1]) / l2;
            if t <= 0.0 || t >= 1.0 {
                continue;
            }
            let dist = ((q[0] - pa[0]) * d[1] - (q[1] - pa[1]) * d[0]).abs() / l2.sqrt();
            if dist <= 2.0 * eps {
                on.push((t, k));
            }
        }
        on.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut prev = a;
        for (_, k) in on {
            split.push((prev, k));
            prev = k;
        }
        split.push((prev, b));
    }
    // Cancel opposite pairs.
    let mut count: HashMap<(usize, usize), i32> = HashMap::new();
    for &(a, b) in &split {
        *count.entry((a, b)).or_default() += 1;
    }
    let mut boundary: Vec<(usize, usize)> = Vec::new();
    for &(a, b) in &split {
        let back = count.get(&(b, a)).copied().unwrap_or(0);
        if back == 0 {
            boundary.push((a, b));
        }
    }
    boundary.sort_unstable();
    boundary.dedup();
    let mut next: HashMap<usize, Vec<usize>> = HashMap::new();
    for &(a, b) in &boundary {
        next.entry(a).or_default().push(b);
    }
    let mut used: HashMap<(usize, usize), bool> = HashMap::new();
    let mut out = Vec::new();
    for &(a0, b0) in &boundary {
        if used.contains_key(&(a0, b0)) {
            continue;
        }
        let mut cycle = vec![a0];
        used.insert((a0, b0), true);
        let mut cur = b0;
        let mut guard = 0;
        while cur != a0 && guard < boundary.len() + 2 {
            guard += 1;
            cycle.push(cur);
            let Some(list) = next.get(&cur) else { break };
            // At a vertex where two parts touch, stay in the same part: take the sharpest left
            // turn (the interior is on the left).
            let prev = cycle[cycle.len() - 2];
            let din = [pts[cur][0] - pts[prev][0], pts[cur][1] - pts[prev][1]];
            let turn = |n: usize| {
                let d = [pts[n][0] - pts[cur][0], pts[n][1] - pts[cur][1]];
                (din[0] * d[1] - din[1] * d[0]).atan2(din[0] * d[0] + din[1] * d[1])
            };
            let Some(&nx) = list
                .iter()
                .filter(|&&n| !used.contains_key(&(cur, n)))
                .max_by(|&&x, &&y| turn(x).total_cmp(&turn(y)))
            else {
                break;
            };
            used.insert((cur, nx), true);
            cur = nx;
        }
        if cur == a0 && cycle.len() >= 3 {
            let poly: Vec<Point> = cycle.iter().map(|&k| pts[k]).collect();
            let poly = drop_collinear(&poly, eps);
            if poly.len() >= 3 && signed_area(&poly) > 0.0 {
                out.push(poly);
            }
        }
    }
    out
}

fn drop_collinear(p: &[Point], eps: f64) -> Vec<Point> {
    let mut q: Vec<Point> = p.to_vec();
    loop {
        let n = q.len();
        if n <= 3 {
            return q;
        }
        let mut removed = false;
        for i in 0..n {
            let (a, b, c) = (q[(i + n - 1) % n], q[i], q[(i + 1) % n]);
            let ac = [c[0] - a[0], c[1] - a[1]];
            let l = ac[0].hypot(ac[1]);
            let d = ((b[0] - a[0]) * ac[1] - (b[1] - a[1]) * ac[0]).abs() / l.max(1e-300);
            let dup = (b[0] - a[0]).hypot(b[1] - a[1]) <= eps;
            if dup || d <= eps {
                q.remove(i);
                removed = true;
                break;
            }
        }
        if !removed {
            return q;
        }
    }
}

// --- openings ---------------------------------------------------------------------------------

/// What an opening contributes: voussoir blocks and the convex regions removed from the wall.
struct Cut {
    voussoirs: Vec<Vec<Point>>,
    holes: Vec<Vec<Point>>,
    /// Heights at which course lines are placed.
    levels: Vec<f64>,
}

fn voussoir_count(length: f64, element: f64, min: usize) -> usize {
    ((length / element).round() as usize).max(min)
}

fn cut_of(o: &Opening, element: f64) -> Result<Cut> {
    match *o {
        Opening::Round { x, y, radius, ring } => {
            if !(radius > 0.0 && ring > 0.0) {
                return Err(bad("a round window needs radius > 0 and ring > 0".into()));
            }
            let re = radius + ring;
            let n = voussoir_count(2.0 * PI * re, element, 8).div_ceil(4) * 4;
            let at = |r: f64, k: usize| {
                let a = -PI / 2.0 + 2.0 * PI * k as f64 / n as f64;
                [x + r * a.cos(), y + r * a.sin()]
            };
            let voussoirs = (0..n)
                .map(|k| vec![at(radius, k), at(radius, k + 1), at(re, k + 1), at(re, k)])
                .collect();
            let hole = (0..n).map(|k| at(re, k)).collect();
            Ok(Cut {
                voussoirs,
                holes: vec![hole],
                levels: vec![],
            })
        }
        Opening::Rect { x0, y0, x1, y1 } => {
            if !(x1 > x0 && y1 > y0) {
                return Err(bad("a rectangular window needs x1 > x0 and y1 > y0".into()));
            }
            Ok(Cut {
                voussoirs: vec![],
                holes: vec![vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]],
                levels: vec![y0, y1],
            })
        }
        Opening::PointedDoor {
            x,
            width,
            springing,
            offset,
            ring,
        } => {
            if !(width > 0.0 && springing > 0.0 && ring > 0.0 && (0.0..1.0).contains(&offset)) {
                return Err(bad(
                    "a pointed door needs width, springing, ring > 0 and offset in [0, 1)".into(),
                ));
            }
            let ri = width / (2.0 * (1.0 - offset));
            let e = offset * ri;
            let re = ri + ring;
            // Voussoirs along the extrados of one half: from the springing (angle π) to the
            // crown angle acos(−e/re) about the half's centre.
            let arc = (PI - (-e / ri).acos()) * re;
            let half = voussoir_count(arc, element, 3);
            let m = generate::arch(&ArchSpec {
                shape: ArchShape::Pointed { offset },
                radius: ri,
                radius_at: RadiusAt::Intrados,
                thickness: ring,
                voussoirs: 2 * half,
                live: LiveLoad::None,
                ..ArchSpec::default()
            })?;
            let shift = |p: &Point| [p[0] + x, p[1] + springing];
            let voussoirs: Vec<Vec<Point>> = m
                .blocks
                .iter()
                .map(|b| b.polygon.iter().map(shift).collect())
                .collect();
            // The lens above the springing: the extrados joint points exactly as the arch
            // generator places them (radial joints at angles stepped to the intrados crown
            // angle), left springing → crown → right springing, closed along the springing line.
            let top = (-e / ri).acos();
            let mut left: Vec<Point> = (0..=half)
                .map(|k| {
                    if k == half {
                        [0.0, (re * re - e * e).sqrt()]
                    } else {
                        let a = PI - (PI - top) * k as f64 / half as f64;
                        [e + re * a.cos(), re * a.sin()]
                    }
                })
                .collect();
            let right: Vec<Point> = left[..half].iter().rev().map(|p| [-p[0], p[1]]).collect();
            left.extend(right);
            // Left → crown → right runs clockwise: reverse to counter-clockwise.
            let lens: Vec<Point> = left.iter().rev().map(shift).collect();
            let jamb = vec![
                [x - width / 2.0, -1.0],
                [x + width / 2.0, -1.0],
                [x + width / 2.0, springing],
                [x - width / 2.0, springing],
            ];
            Ok(Cut {
                voussoirs,
                holes: vec![jamb, lens],
                levels: vec![springing],
            })
        }
    }
}

/// Course (row) lines from 0 to `top`: multiples of `h`, with each level in `levels` replacing
/// the nearest regular line.
fn course_lines(top: f64, h: f64, levels: &[f64]) -> Vec<f64> {
    let n = (top / h).round().max(1.0) as usize;
    let mut ys: Vec<f64> = (0..=n).map(|k| top * k as f64 / n as f64).collect();
    for &l in levels {
        if l <= 0.0 || l >= top {
            continue;
        }
        if let Some(k) = (1..n).min_by(|&a, &b| (ys[a] - l).abs().total_cmp(&(ys[b] - l).abs())) {
            if (ys[k] - l).abs() <= 0.5 * h + 1e-9 {
                ys[k] = l;
            }
        }
    }
    ys.sort_by(f64::total_cmp);
    ys.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    ys
}

/// The wall of the façade (the gabled rectangle less the openings with their rings) as an
/// outline: doors are notches of the outer boundary, windows holes. Every vertex is exactly a
/// vertex of the wall or of an opening, or where an opening's side crosses the base.
fn wall_outline(s: &FacadeSpec, holes: &[Vec<Point>]) -> Result<crate::outline_mesh::Outline> {
    use i_overlay::core::fill_rule::FillRule;
    use i_overlay::core::overlay_rule::OverlayRule;
    use i_overlay::float::single::SingleFloatOverlay;
    let top = s.height + s.gable;
    let mut outer = vec![[0.0, 0.0], [s.width, 0.0], [s.width, s.height]];
    if s.gable > 0.0 {
        outer.push([s.width / 2.0, top]);
    }
    outer.push([0.0, s.height]);
    let shapes =
        outer.overlay_as::<i64>(&holes.to_vec(), OverlayRule::Difference, FillRule::NonZero);
    // Where a vertex may be: a vertex of the wall or of an opening, or a crossing of an
    // opening's edge with the wall's edges.
    let mut cand: Vec<Point> = outer.clone();
    cand.extend(holes.iter().flatten().copied());
    for h in holes {
        for i in 0..h.len() {
            let (a, b) = (h[i], h[(i + 1) % h.len()]);
            for j in 0..outer.len() {
                let (c, d) = (outer[j], outer[(j + 1) % outer.len()]);
                let r = [b[0] - a[0], b[1] - a[1]];
                let q = [d[0] - c[0], d[1] - c[1]];
                let den = r[0] * q[1] - r[1] * q[0];
                if den == 0.0 {
                    continue;
                }
                let t = ((c[0] - a[0]) * q[1] - (c[1] - a[1]) * q[0]) / den;
                let u = ((c[0] - a[0]) * r[1] - (c[1] - a[1]) * r[0]) / den;
                if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
                    // Exactly on an axis-parallel wall edge when it is one.
                    let mut p = [a[0] + t * r[0], a[1] + t * r[1]];
                    if c[1] == d[1] {
                        p[1] = c[1];
                    }
                    if a[0] == b[0] {
                        p[0] = a[0];
                    }
                    cand.push(p);
                }
            }
        }
    }
    let tol = 1e-7 * s.width.hypot(top);
    let snap = |q: &Point| -> Point {
        cand.iter()
            .copied()
            .filter(|c| (c[0] - q[0]).hypot(c[1] - q[1]) <= tol)
            .min_by(|a, b| {
                (a[0] - q[0])
                    .hypot(a[1] - q[1])
                    .total_cmp(&(b[0] - q[0]).hypot(b[1] - q[1]))
            })
            .unwrap_or(*q)
    };
    if shapes.len() != 1 {
        return Err(bad(format!(
            "the openings cut the wall into {} separate parts",
            shapes.len()
        )));
    }
    let rings: Vec<Vec<Point>> = shapes[0]
        .iter()
        .map(|r| {
            let mut v: Vec<Point> = Vec::with_capacity(r.len());
            for q in r {
                let p = snap(q);
                if v.last() != Some(&p) {
                    v.push(p);
                }
            }
            while v.len() > 1 && v.first() == v.last() {
                v.pop();
            }
            v
        })
        .collect();
    let mut it = rings.into_iter();
    Ok(crate::outline_mesh::Outline {
        outer: it.next().unwrap_or_default(),
        holes: it.collect(),
    })
}

/// Generate a façade.
pub fn facade(s: &FacadeSpec) -> Result<Model> {
    if !matches!(s.live, LiveLoad::None | LiveLoad::Horizontal) {
        return Err(Error::Request(
            "a façade's live load is none or horizontal (each block's weight along +x); full, left and right are vertical loads on an arch's span".into(),
        ));
    }
    let [ex, ey] = s.element;
    let ok = s.width > 0.0
        && s.height > 0.0
        && s.gable >= 0.0
        && ex > 0.0
        && ey > 0.0
        && s.segments >= 1
        && s.foundation_depth > 0.0
        && s.unit_weight >= 0.0
        && s.thickness > 0.0
        && (0.0..1.0).contains(&s.min_piece)
        && [
            s.width,
            s.height,
            s.gable,
            ex,
            ey,
            s.foundation_depth,
            s.unit_weight,
            s.thickness,
        ]
        .iter()
        .all(|v| v.is_finite());
    if !ok {
        return Err(bad("width, height, element, segments, foundation depth and thickness must be positive finite numbers, gable ≥ 0, min piece in [0, 1)".into()));
    }
    if ex > s.width / 2.0 || ey > s.height / 2.0 {
        return Err(bad(format!(
            "element {ex} × {ey} m is too large for a {} × {} m wall",
            s.width, s.height
        )));
    }
    let count = (s.width / ex) * ((s.height + s.gable) / ey);
    if count > 2.0e6 {
        return Err(bad(format!(
            "about {count:.0} elements: choose a larger element size"
        )));
    }
    let eps = 1e-9 * (s.width + s.height + s.gable);
    // The model's relative tolerance and, above it, the length under which vertices merge.
    let rel_tol = 1e-6;
    let diag = s.width.hypot(s.height + s.gable + s.foundation_depth);
    let clean = 1.5 * rel_tol * diag;
    let mut cuts = Vec::new();
    for o in &s.openings {
        let c = cut_of(o, ex.max(ey))?;
        for h in &c.holes {
            let b = bbox(h);
            if b[0] < 0.0
                || b[2] > s.width
                || b[3]
                    > s.height
                        + s.gable
                            * (1.0 - 2.0 * ((b[0] + b[2]) / 2.0 - s.width / 2.0).abs() / s.width)
            {
                return Err(bad(format!(
                    "opening {o:?} (with its ring) does not fit inside the wall"
                )));
            }
        }
        cuts.push(c);
    }
    // Openings and their rings must not overlap one another.
    for i in 0..cuts.len() {
        for j in i + 1..cuts.len() {
            for a in &cuts[i].holes {
                for b in &cuts[j].holes {
                    let (ba, bb) = (bbox(a), bbox(b));
                    if ba[0] < bb[2] && bb[0] < ba[2] && ba[1] < bb[3] && bb[1] < ba[3] {
                        return Err(bad(format!(
                            "openings {i} and {j} overlap (with their rings)"
                        )));
                    }
                }
            }
        }
    }
    let levels: Vec<f64> = cuts.iter().flat_map(|c| c.levels.iter().copied()).collect();
    let top = s.height + s.gable;
    let ys = course_lines(top, ey, &levels);
    let holes: Vec<(&Vec<Point>, [f64; 4])> = cuts
        .iter()
        .flat_map(|c| c.holes.iter())
        .map(|h| (h, bbox(h)))
        .collect();
    // The gable: two half-planes through the eaves corners and the ridge.
    let ridge = [s.width / 2.0, top];
    let roof = if s.gable > 0.0 {
        vec![
            Half::left_of([s.width, s.height], ridge),
            Half::left_of(ridge, [0.0, s.height]),
        ]
    } else {
        vec![]
    };
    let nx = ((s.width / ex).round() as usize).max(1);
    let dx = s.width / nx as f64;
    let mut polys: Vec<Vec<Point>> = Vec::new();
    if s.mesh == FacadeMesh::Triangles {
        let all: Vec<Vec<Point>> = holes.iter().map(|(h, _)| (*h).clone()).collect();
        let outline = wall_outline(s, &all)?;
        // Foundation segment ends on the base, so that no triangle straddles two segments.
        let sw = s.width / s.segments as f64;
        let cuts: Vec<f64> = (1..s.segments).map(|k| k as f64 * sw).collect();
        let outline = crate::outline_mesh::base_cuts(&outline, &cuts)?;
        polys = crate::outline_mesh::mesh_polygons(
            &outline,
            &crate::outline_mesh::MeshKind::Triangles {
                max_area: ex * ey,
                min_angle_deg: s.min_angle,
            },
            &Default::default(),
        )
        .map_err(|e| bad(e.to_string()))?;
    }
    for (c, w) in ys.windows(2).enumerate() {
        if s.mesh == FacadeMesh::Triangles {
            break;
        }
        let (y0, y1) = (w[0], w[1]);
        if s.gable == 0.0 && y0 >= s.height - eps {
            break;
        }
        let offset = s.mesh == FacadeMesh::RunningBond && c % 2 == 1;
        let mut xs: Vec<f64> = Vec::new();
        if offset {
            xs.push(0.0);
            xs.extend((0..nx).map(|k| (k as f64 + 0.5) * dx));
            xs.push(s.width);
        } else {
            xs.extend((0..=nx).map(|k| k as f64 * dx));
        }
        for xw in xs.windows(2) {
            let cell = vec![[xw[0], y0], [xw[1], y0], [xw[1], y1], [xw[0], y1]];
            let area0 = (xw[1] - xw[0]) * (y1 - y0);
            let mut pieces = vec![cell];
            for h in &roof {
                pieces = pieces
                    .into_iter()
                    .map(|p| clip(&p, *h))
                    .filter(|p| p.len() >= 3 && signed_area(p) > eps * eps)
                    .collect();
            }
            let cb = [xw[0], y0, xw[1], y1];
            for (hole, hb) in &holes {
                if !(cb[0] < hb[2] && hb[0] < cb[2] && cb[1] < hb[3] && hb[1] < cb[3]) {
                    continue;
                }
                pieces = pieces
                    .into_iter()
                    .flat_map(|p| subtract(&p, hole, eps))
                    .collect();
            }
            for p in merge(&pieces, eps) {
                // Vertices closer than the joint-detection tolerance would be one vertex.
                let p = drop_collinear(&p, clean);
                if p.len() < 3 {
                    continue;
                }
                let (a, _) = area_centroid(&p);
                if a >= s.min_piece * area0 {
                    polys.push(p);
                }
            }
        }
    }
    for c in &cuts {
        polys.extend(c.voussoirs.iter().cloned());
    }
    let blocks: Vec<Block> = polys
        .into_iter()
        .map(|mut p| {
            if signed_area(&p) < 0.0 {
                p.reverse();
            }
            Block {
                polygon: p,
                material: None,
            }
        })
        .collect();
    let sw = s.width / s.segments as f64;
    let d = s.foundation_depth;
    let supports = (0..s.segments)
        .map(|k| {
            let (x0, x1) = (
                k as f64 * sw,
                if k + 1 == s.segments {
                    s.width
                } else {
                    (k + 1) as f64 * sw
                },
            );
            Support {
                name: format!("f{k}"),
                polygon: vec![[x0, -d], [x1, -d], [x1, 0.0], [x0, 0.0]],
                motion: [0.0; 3],
                connection: Default::default(),
            }
        })
        .collect();
    let mut materials = BTreeMap::new();
    materials.insert(
        "default".to_string(),
        Material {
            unit_weight: s.unit_weight,
            width: s.thickness,
            ..Material::default()
        },
    );
    let live = match s.live {
        LiveLoad::Horizontal => vec![Load::Body {
            coefficients: [1.0, 0.0],
            blocks: None,
        }],
        _ => vec![],
    };
    Ok(Model {
        description: format!(
            "façade {} × {} m (gable {} m), {:?} mesh of {} × {} m elements, {} openings, {} foundation segments",
            s.width,
            s.height,
            s.gable,
            s.mesh,
            ex,
            ey,
            s.openings.len(),
            s.segments
        ),
        materials,
        blocks,
        supports,
        loads: Loads {
            self_weight: true,
            dead: vec![],
            live,
        },
        tolerance: Some(rel_tol),
        cracks: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_minus_its_inscribed_diamond_is_four_corner_triangles() {
        let sq = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let hole = vec![[0.5, 0.0], [1.0, 0.5], [0.5, 1.0], [0.0, 0.5]];
        let pieces = subtract(&sq, &hole, 1e-12);
        let m = merge(&pieces, 1e-12);
        let total: f64 = m.iter().map(|p| signed_area(p)).sum();
        // Four corner triangles of 1/8 each.
        assert_eq!(m.len(), 4);
        assert!((total - 0.5).abs() < 1e-12);
    }

    #[test]
    fn a_notch_keeps_one_simple_polygon() {
        let sq = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
        let hole = vec![[0.5, -1.0], [1.5, -1.0], [1.5, 0.5], [0.5, 0.5]];
        let m = merge(&subtract(&sq, &hole, 1e-12), 1e-12);
        assert_eq!(m.len(), 1);
        assert_eq!(m[0].len(), 8);
        assert!((signed_area(&m[0]) - 1.5).abs() < 1e-12);
    }
}
