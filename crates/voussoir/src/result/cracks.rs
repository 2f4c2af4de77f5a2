//! Cracks as an engineer draws them (issue 30, item 3; docs/cracks.md).
//!
//! **2D**: a crack is a polyline through consecutive open joints ([`Crack`]). Each joint with
//! open points gives a segment along the joint: its open points (open as [`crate::scale`]
//! decides, never round-off) with the closed point next to them on either side, where the
//! crack closes (a hinge opens a wedge: the crack runs along the joint from the hinge to the
//! open end). Segments whose ends meet (within the structure's geometric tolerance) chain into
//! one polyline, unless both ends there are closed (two crack tips that touch are two
//! cracks). Where three or more segments meet, the crack continues along the widest one (the
//! largest opening at the meeting point; ties by the seed order below) and the others start
//! cracks of their own, whose end there is marked `junction`. Cracks are traced from the
//! widest segment first and listed by largest opening (descending; openings equal to 1e-9 of
//! the largest are equal), then by the lower-left point of their start, then by their first
//! joint. A crack runs from its wider end to its narrower one (ties: from the lower-left end),
//! so that a wedge is written from its mouth to its tip.
//!
//! **3D**: one record per cracked joint, or per connected set of coplanar cracked joints (they
//! share an edge: a hinge line across several blocks) ([`Crack3d`]): its position (the centroid
//! of the joints' polygons: with rigid blocks the opening is linear over a face and
//! non-negative, so once a point opens the whole face opens but for the hinge), the largest
//! opening, and the length of the crack front: the hinge line when two or more points stay
//! closed, else the largest extent of the faces.
//!
//! Widths are metres for a settlement (the finite motion; a point's gap before the analysis is
//! added), and the mechanism's opening rates (per unit of its normalisation) for a collapse
//! mechanism, whose amplitude is arbitrary.

use super::{BodyName, Geometry, JointResult};
use crate::dim::Three;
use serde::{Deserialize, Serialize};

/// One end of a 2D crack.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CrackEnd {
    /// Opening at this end (m for a settlement).
    pub opening: f64,
    /// The crack closes here: the end is a closed point of its joint (a hinge, the crack's tip).
    pub hinge: bool,
    /// The end lies on the free surface of the structure (the crack opens to the outside).
    pub free_edge: bool,
    /// The end lies on a support.
    pub support: bool,
    /// Another crack meets this end (a branch point where this crack was not the widest
    /// continuation).
    pub junction: bool,
}

/// A 2D crack: a polyline through consecutive open joints.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Crack {
    /// Vertices `[x, y]` (m), from the wider end to the narrower one.
    pub points: Vec<[f64; 2]>,
    /// Opening at each vertex (m for a settlement; the largest of the two joints' where two
    /// joints meet).
    pub openings: Vec<f64>,
    /// Length of the polyline (m).
    pub length: f64,
    /// Largest opening along the crack.
    pub max_opening: f64,
    /// The joints it runs along, in order.
    pub joints: Vec<usize>,
    /// The two bodies of each of those joints (block index or support name): the faces the
    /// crack separates.
    pub faces: Vec<[BodyName; 2]>,
    pub start: CrackEnd,
    pub end: CrackEnd,
    /// The polyline closes on itself (a block cut loose all round); its first and last points
    /// are then the same.
    #[serde(default, skip_serializing_if = "is_false")]
    pub closed_loop: bool,
    /// The chord between the polyline's end points (m): `rise` = |Δy|, `run` = |Δx|. Its
    /// slope `rise / run` is how steeply the crack climbs as a whole (a stepped crack through
    /// a running bond of units `L × h` climbs at most `h / (L/2)` per step); 0 and 0 for a
    /// closed loop.
    #[serde(default)]
    pub rise: f64,
    #[serde(default)]
    pub run: f64,
}

impl Crack {
    /// The chord's slope `rise / run` (None for a vertical chord or a closed loop).
    pub fn slope(&self) -> Option<f64> {
        (self.run > 0.0).then(|| self.rise / self.run)
    }
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// What the crack front of a 3D joint is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CrackFront {
    /// Two or more points stay closed: the face rotates about a hinge line.
    HingeLine,
    /// One point stays closed: the face pivots about it.
    Pivot,
    /// Every point opens: the faces separate.
    Separation,
}

/// A 3D crack: a cracked joint, or a connected set of coplanar cracked joints.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Crack3d {
    /// The joints, in increasing order.
    pub joints: Vec<usize>,
    /// The two bodies of each joint (block index or support name).
    pub faces: Vec<[BodyName; 2]>,
    /// Centroid of the opened faces `[x, y, z]` (m).
    pub position: [f64; 3],
    /// Largest opening (m for a settlement).
    pub max_opening: f64,
    /// Length of the hinge line (its extreme closed points), or the faces' largest extent for
    /// a pivot or a separation (m).
    pub length: f64,
    /// Area of the opened faces (m²).
    pub area: f64,
    pub front: CrackFront,
}

/// The bodies a 2D crack's ends are classified against, and the geometric tolerance of
/// chaining.
pub struct CrackGeometry<'a> {
    pub blocks: Vec<&'a [[f64; 2]]>,
    pub supports: Vec<&'a [[f64; 2]]>,
    /// Absolute tolerance (m): two joint ends closer than this are one point.
    pub tolerance: f64,
}

impl<'a> CrackGeometry<'a> {
    /// From a saved result's geometry; the tolerance is 1e-9 of the geometry's size (the
    /// default relative tolerance of a model).
    pub fn of_geometry(g: &'a Geometry) -> Self {
        let mut bb = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        for p in g
            .blocks
            .iter()
            .chain(g.supports.iter().map(|s| &s.polygon))
            .flatten()
        {
            bb = [
                bb[0].min(p[0]),
                bb[1].min(p[1]),
                bb[2].max(p[0]),
                bb[3].max(p[1]),
            ];
        }
        let size = ((bb[2] - bb[0]).powi(2) + (bb[3] - bb[1]).powi(2)).sqrt();
        CrackGeometry {
            blocks: g.blocks.iter().map(|b| b.as_slice()).collect(),
            supports: g.supports.iter().map(|s| s.polygon.as_slice()).collect(),
            tolerance: if size.is_finite() && size > 0.0 {
                1e-9 * size
            } else {
                0.0
            },
        }
    }
}

/// A joint's points as the tracer reads them: position, opening, open or not.
pub(crate) struct JointPoints {
    pub joint: usize,
    pub faces: [BodyName; 2],
    pub tangent: [f64; 2],
    pub points: Vec<([f64; 2], f64, bool)>,
}

/// The cracks of a 2D result's joints. `open[j][k]` says whether point `k` of joint `j` is open
/// (as the report decided it, on the motion's scale) and `widths[j][k]` its opening.
pub fn trace_cracks(
    joints: &[JointResult],
    open: &[Vec<bool>],
    widths: &[Vec<f64>],
    geo: &CrackGeometry,
) -> Vec<Crack> {
    let input: Vec<JointPoints> = joints
        .iter()
        .enumerate()
        .filter(|(j, _)| open.get(*j).is_some_and(|o| o.iter().any(|&x| x)))
        .map(|(j, jr)| JointPoints {
            joint: jr.id,
            faces: [jr.a.clone(), jr.b.clone()],
            tangent: [-jr.normal[1], jr.normal[0]],
            points: jr
                .points
                .iter()
                .enumerate()
                .map(|(k, p)| {
                    (
                        [p.x, p.y],
                        widths[j].get(k).copied().unwrap_or(0.0).max(0.0),
                        open[j].get(k).copied().unwrap_or(false),
                    )
                })
                .collect(),
        })
        .collect();
    trace(input, geo)
}

/// The cracks of a saved 2D result (one without its `cracks`): a point is open where its
/// opening (plus its gap, for a settlement: `finite`) exceeds [`crate::scale::OPEN_TOLERANCE`]
/// of the largest. The analyses decide on the motion's own scale, which may be larger; a
/// result's own `cracks` are the reference.
pub fn cracks_of_result(joints: &[JointResult], geometry: &Geometry, finite: bool) -> Vec<Crack> {
    let width = |p: &super::PointResult| {
        if finite {
            (p.opening + p.gap).max(0.0)
        } else {
            p.opening.max(0.0)
        }
    };
    let largest = joints
        .iter()
        .flat_map(|j| j.points.iter())
        .map(width)
        .fold(0.0f64, f64::max);
    let tol = crate::scale::OPEN_TOLERANCE * largest;
    let widths: Vec<Vec<f64>> = joints
        .iter()
        .map(|j| j.points.iter().map(width).collect())
        .collect();
    let open: Vec<Vec<bool>> = widths
        .iter()
        .map(|w| w.iter().map(|&x| largest > 0.0 && x > tol).collect())
        .collect();
    trace_cracks(
        joints,
        &open,
        &widths,
        &CrackGeometry::of_geometry(geometry),
    )
}

/// A segment along one joint: its points in order along the joint.
struct Segment {
    joint: usize,
    faces: [BodyName; 2],
    points: Vec<[f64; 2]>,
    widths: Vec<f64>,
    /// Whether the first and the last point are open.
    open_ends: [bool; 2],
    max: f64,
    /// Node of the first and of the last point.
    nodes: [usize; 2],
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

fn lex(a: [f64; 2], b: [f64; 2]) -> std::cmp::Ordering {
    a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1]))
}

fn segments_of(input: Vec<JointPoints>, tol: f64) -> Vec<Segment> {
    let mut out = Vec::new();
    for jp in input {
        let t = jp.tangent;
        let mut pts: Vec<([f64; 2], f64, bool)> = jp
            .points
            .into_iter()
            .filter(|p| p.0[0].is_finite() && p.0[1].is_finite() && p.1.is_finite())
            .collect();
        pts.sort_by(|a, b| {
            (a.0[0] * t[0] + a.0[1] * t[1])
                .total_cmp(&(b.0[0] * t[0] + b.0[1] * t[1]))
                .then(lex(a.0, b.0))
        });
        let n = pts.len();
        let mut k = 0;
        while k < n {
            if !pts[k].2 {
                k += 1;
                continue;
            }
            let mut e = k;
            while e + 1 < n && pts[e + 1].2 {
                e += 1;
            }
            // The open run k..=e, with the closed point on either side where the crack closes.
            let lo = k.saturating_sub(1);
            let hi = (e + 1).min(n - 1);
            let run = &pts[lo..=hi];
            let points: Vec<[f64; 2]> = run.iter().map(|p| p.0).collect();
            let length: f64 = points.windows(2).map(|w| dist(w[0], w[1])).sum();
            if points.len() >= 2 && length > tol {
                let widths: Vec<f64> = run.iter().map(|p| p.1).collect();
                out.push(Segment {
                    joint: jp.joint,
                    faces: jp.faces.clone(),
                    max: widths.iter().fold(0.0f64, |m, w| m.max(*w)),
                    open_ends: [run[0].2, run[run.len() - 1].2],
                    points,
                    widths,
                    nodes: [0, 0],
                });
            }
            k = e + 1;
        }
    }
    out
}

/// Give every segment end a node: ends within `tol` of each other are one node.
fn cluster(segs: &mut [Segment], tol: f64) -> usize {
    let ends: Vec<[f64; 2]> = segs
        .iter()
        .flat_map(|s| [s.points[0], s.points[s.points.len() - 1]])
        .collect();
    let mut order: Vec<usize> = (0..ends.len()).collect();
    order.sort_by(|&a, &b| lex(ends[a], ends[b]).then(a.cmp(&b)));
    let mut parent: Vec<usize> = (0..ends.len()).collect();
    fn find(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    for (ii, &i) in order.iter().enumerate() {
        for &j in &order[ii + 1..] {
            if ends[j][0] - ends[i][0] > tol {
                break;
            }
            if dist(ends[i], ends[j]) <= tol {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                if a != b {
                    parent[a.max(b)] = a.min(b);
                }
            }
        }
    }
    let mut id = vec![usize::MAX; ends.len()];
    let mut n = 0;
    for &i in &order {
        let r = find(&mut parent, i);
        if id[r] == usize::MAX {
            id[r] = n;
            n += 1;
        }
        id[i] = id[r];
    }
    for (k, s) in segs.iter_mut().enumerate() {
        s.nodes = [id[2 * k], id[2 * k + 1]];
    }
    n
}

/// Openings on a common integer scale (1e-9 of the largest), so that sorting by width is a
/// total order that ignores round-off.
fn quantise(w: f64, largest: f64) -> i64 {
    if largest > 0.0 {
        (w / largest * 1e9).round() as i64
    } else {
        0
    }
}

pub(crate) fn trace(input: Vec<JointPoints>, geo: &CrackGeometry) -> Vec<Crack> {
    let tol = geo.tolerance.max(0.0);
    let mut segs = segments_of(input, tol);
    if segs.is_empty() {
        return vec![];
    }
    let nodes = cluster(&mut segs, tol);
    let largest = segs.iter().fold(0.0f64, |m, s| m.max(s.max));
    let q = |w: f64| quantise(w, largest);
    // Seed order: widest first, then lower-left, then joint.
    let mut order: Vec<usize> = (0..segs.len()).collect();
    let low = |s: &Segment| {
        s.points
            .iter()
            .copied()
            .min_by(|a, b| lex(*a, *b))
            .unwrap_or([0.0, 0.0])
    };
    order.sort_by(|&a, &b| {
        q(segs[b].max)
            .cmp(&q(segs[a].max))
            .then(lex(low(&segs[a]), low(&segs[b])))
            .then(segs[a].joint.cmp(&segs[b].joint))
            .then(a.cmp(&b))
    });
    let mut rank = vec![0usize; segs.len()];
    for (r, &s) in order.iter().enumerate() {
        rank[s] = r;
    }
    let mut at: Vec<Vec<(usize, usize)>> = vec![vec![]; nodes];
    for (k, s) in segs.iter().enumerate() {
        at[s.nodes[0]].push((k, 0));
        at[s.nodes[1]].push((k, 1));
    }
    let end_open = |s: &Segment, e: usize| s.open_ends[e];
    let end_width = |s: &Segment, e: usize| {
        if e == 0 {
            s.widths[0]
        } else {
            s.widths[s.widths.len() - 1]
        }
    };
    let mut used = vec![false; segs.len()];
    let mut cracks = Vec::new();
    for &seed in &order {
        if used[seed] {
            continue;
        }
        used[seed] = true;
        // The chain: (segment, reversed), in order along the crack.
        let mut chain: std::collections::VecDeque<(usize, bool)> = [(seed, false)].into();
        let next = |node: usize, open_here: bool, used: &mut Vec<bool>| -> Option<(usize, usize)> {
            let best = at[node]
                .iter()
                .filter(|(k, e)| !used[*k] && (open_here || end_open(&segs[*k], *e)))
                .max_by(|(a, ea), (b, eb)| {
                    q(end_width(&segs[*a], *ea))
                        .cmp(&q(end_width(&segs[*b], *eb)))
                        .then(rank[*b].cmp(&rank[*a]))
                })
                .copied();
            if let Some((k, _)) = best {
                used[k] = true;
            }
            best
        };
        // Forward from the seed's last point.
        let start_node = segs[seed].nodes[0];
        let mut node = segs[seed].nodes[1];
        let mut open_here = end_open(&segs[seed], 1);
        let mut closed_loop = false;
        loop {
            if node == start_node && (open_here || end_open(&segs[seed], 0)) {
                closed_loop = true;
                break;
            }
            match next(node, open_here, &mut used) {
                Some((k, e)) => {
                    chain.push_back((k, e == 1));
                    let far = 1 - e;
                    node = segs[k].nodes[far];
                    open_here = end_open(&segs[k], far);
                }
                None => break,
            }
        }
        if !closed_loop {
            let mut node = start_node;
            let mut open_here = end_open(&segs[seed], 0);
            while let Some((k, e)) = next(node, open_here, &mut used) {
                // Reaching `node` through segment k's end e: k runs towards node, so it is
                // reversed when its matching end is its first point.
                chain.push_front((k, e == 0));
                let far = 1 - e;
                node = segs[k].nodes[far];
                open_here = end_open(&segs[k], far);
            }
        }
        cracks.push(build(&segs, &chain, closed_loop, &at, geo));
    }
    cracks.sort_by(|a, b| {
        q(b.max_opening)
            .cmp(&q(a.max_opening))
            .then(lex(a.points[0], b.points[0]))
            .then(a.joints[0].cmp(&b.joints[0]))
    });
    cracks
}

fn build(
    segs: &[Segment],
    chain: &std::collections::VecDeque<(usize, bool)>,
    closed_loop: bool,
    at: &[Vec<(usize, usize)>],
    geo: &CrackGeometry,
) -> Crack {
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut openings: Vec<f64> = Vec::new();
    let mut joints = Vec::new();
    let mut faces = Vec::new();
    let (mut first_open, mut last_open) = (false, false);
    let (mut first_node, mut last_node) = (0, 0);
    for (i, &(k, rev)) in chain.iter().enumerate() {
        let s = &segs[k];
        let mut p = s.points.clone();
        let mut w = s.widths.clone();
        let (mut o, mut nd) = (s.open_ends, s.nodes);
        if rev {
            p.reverse();
            w.reverse();
            o.reverse();
            nd.reverse();
        }
        if i == 0 {
            first_open = o[0];
            first_node = nd[0];
            points.extend_from_slice(&p);
            openings.extend_from_slice(&w);
        } else {
            // The shared point: the previous segment's position, the wider opening.
            if let Some(l) = openings.last_mut() {
                *l = l.max(w[0]);
            }
            points.extend_from_slice(&p[1..]);
            openings.extend_from_slice(&w[1..]);
        }
        last_open = o[1];
        last_node = nd[1];
        joints.push(s.joint);
        faces.push(s.faces.clone());
    }
    let length: f64 = points.windows(2).map(|w| dist(w[0], w[1])).sum();
    let max_opening = openings.iter().fold(0.0f64, |m, w| m.max(*w));
    let in_chain: Vec<usize> = chain.iter().map(|c| c.0).collect();
    let ends = |node: usize, p: [f64; 2], w: f64, open: bool, seg_len: f64| {
        let junction = !closed_loop && at[node].iter().any(|(k, _)| !in_chain.contains(k));
        let r = (1e-3 * seg_len).max(100.0 * geo.tolerance);
        CrackEnd {
            opening: w,
            hinge: !open,
            free_edge: !closed_loop && on_free_edge(p, r, geo),
            support: !closed_loop && on_support(p, geo),
            junction,
        }
    };
    let seg_len = |k: usize| {
        segs[k]
            .points
            .windows(2)
            .map(|w| dist(w[0], w[1]))
            .sum::<f64>()
    };
    let n = points.len();
    let mut crack = Crack {
        start: ends(
            first_node,
            points[0],
            openings[0],
            first_open,
            seg_len(chain[0].0),
        ),
        end: ends(
            last_node,
            points[n - 1],
            openings[n - 1],
            last_open,
            seg_len(chain[chain.len() - 1].0),
        ),
        points,
        openings,
        length,
        max_opening,
        joints,
        faces,
        closed_loop,
        rise: 0.0,
        run: 0.0,
    };
    if !closed_loop {
        let (a, b) = (crack.points[0], crack.points[n - 1]);
        crack.rise = (b[1] - a[1]).abs();
        crack.run = (b[0] - a[0]).abs();
    }
    // From the wider end to the narrower one (ties: from the lower-left end).
    let largest = max_opening;
    let (ws, we) = (
        quantise(crack.start.opening, largest),
        quantise(crack.end.opening, largest),
    );
    let flip = we > ws
        || (we == ws && lex(crack.points[n - 1], crack.points[0]) == std::cmp::Ordering::Less);
    if flip && !closed_loop {
        crack.points.reverse();
        crack.openings.reverse();
        crack.joints.reverse();
        crack.faces.reverse();
        std::mem::swap(&mut crack.start, &mut crack.end);
    }
    crack
}

fn bbox_near(poly: &[[f64; 2]], p: [f64; 2], r: f64) -> bool {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for v in poly {
        lo = [lo[0].min(v[0]), lo[1].min(v[1])];
        hi = [hi[0].max(v[0]), hi[1].max(v[1])];
    }
    p[0] >= lo[0] - r && p[0] <= hi[0] + r && p[1] >= lo[1] - r && p[1] <= hi[1] + r
}

/// Inside `poly` (even-odd) or within `tol` of its boundary.
fn covers(poly: &[[f64; 2]], q: [f64; 2], tol: f64) -> bool {
    let n = poly.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        if crate::geometry::point_segment_distance(q, a, b) <= tol {
            return true;
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

/// Whether some point at distance `r` around `p` lies outside every body: `p` is on the free
/// surface of the structure. 32 directions, offset from the axes and the diagonals.
fn on_free_edge(p: [f64; 2], r: f64, geo: &CrackGeometry) -> bool {
    let near: Vec<&[[f64; 2]]> = geo
        .blocks
        .iter()
        .chain(&geo.supports)
        .copied()
        .filter(|poly| poly.len() >= 3 && bbox_near(poly, p, 2.0 * r))
        .collect();
    let tol = geo.tolerance;
    (0..32).any(|k| {
        let a = (k as f64 + 0.5) * std::f64::consts::TAU / 32.0;
        let q = [p[0] + r * a.cos(), p[1] + r * a.sin()];
        !near.iter().any(|poly| covers(poly, q, tol))
    })
}

fn on_support(p: [f64; 2], geo: &CrackGeometry) -> bool {
    let tol = 10.0 * geo.tolerance;
    geo.supports.iter().any(|poly| {
        let n = poly.len();
        n >= 2
            && bbox_near(poly, p, tol)
            && (0..n).any(|i| {
                crate::geometry::point_segment_distance(p, poly[i], poly[(i + 1) % n]) <= tol
            })
    })
}

/// The 3D crack records of a result's joints (`open`, `widths` as for [`trace_cracks`]): the
/// cracked joints grouped into connected coplanar sets (two cracked joints whose polygons share
/// an edge, within `tolerance`, in one plane are one crack: a hinge line across several
/// blocks), widest first (then by first joint).
pub fn crack_records_3d(
    joints: &[JointResult<Three>],
    open: &[Vec<bool>],
    widths: &[Vec<f64>],
    tolerance: f64,
) -> Vec<Crack3d> {
    struct Cj {
        id: usize,
        faces: [BodyName; 2],
        pts: Vec<[f64; 3]>,
        closed: Vec<[f64; 3]>,
        normal: [f64; 3],
        max: f64,
    }
    let mut cj: Vec<Cj> = Vec::new();
    for (j, jr) in joints.iter().enumerate() {
        let Some(o) = open.get(j).filter(|o| o.iter().any(|&x| x)) else {
            continue;
        };
        let pts: Vec<[f64; 3]> = jr.points.iter().map(|p| [p.x, p.y, p.z]).collect();
        let closed: Vec<[f64; 3]> = pts
            .iter()
            .zip(o)
            .filter(|(_, &op)| !op)
            .map(|(p, _)| *p)
            .collect();
        cj.push(Cj {
            id: jr.id,
            faces: [jr.a.clone(), jr.b.clone()],
            pts,
            closed,
            normal: jr.normal,
            max: widths
                .get(j)
                .map_or(0.0, |w| w.iter().fold(0.0f64, |m, x| m.max(*x))),
        });
    }
    let d3 = |a: [f64; 3], b: [f64; 3]| {
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    };
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    // Union of cracked joints sharing an edge in one plane.
    let n = cj.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    let tol = tolerance.max(0.0);
    let bbs: Vec<[[f64; 3]; 2]> = cj
        .iter()
        .map(|c| crate::geometry3d::bbox3(&c.pts))
        .collect();
    for i in 0..n {
        for k in i + 1..n {
            let (a, b) = (&cj[i], &cj[k]);
            if (0..3)
                .any(|m| bbs[i][0][m] > bbs[k][1][m] + tol || bbs[k][0][m] > bbs[i][1][m] + tol)
            {
                continue;
            }
            if dot(a.normal, b.normal).abs() < 1.0 - 1e-9 {
                continue;
            }
            if dot(
                a.normal,
                [
                    b.pts[0][0] - a.pts[0][0],
                    b.pts[0][1] - a.pts[0][1],
                    b.pts[0][2] - a.pts[0][2],
                ],
            )
            .abs()
                > tol
            {
                continue;
            }
            let shared = a
                .pts
                .iter()
                .filter(|p| b.pts.iter().any(|q| d3(**p, *q) <= tol))
                .count();
            if shared >= 2 {
                let (x, y) = (find(&mut parent, i), find(&mut parent, k));
                if x != y {
                    parent[x.max(y)] = x.min(y);
                }
            }
        }
    }
    let mut groups: std::collections::BTreeMap<usize, Vec<usize>> = Default::default();
    for i in 0..n {
        let r = find(&mut parent, i);
        groups.entry(r).or_default().push(i);
    }
    let diameter = |ps: &[[f64; 3]]| {
        let mut m = 0.0f64;
        for (i, a) in ps.iter().enumerate() {
            for b in &ps[i + 1..] {
                m = m.max(d3(*a, *b));
            }
        }
        m
    };
    let mut out = Vec::new();
    for members in groups.values() {
        let (mut area, mut c) = (0.0, [0.0; 3]);
        let (mut all, mut closed) = (Vec::new(), Vec::new());
        let mut max_opening = 0.0f64;
        for &i in members {
            let (a, x) = polygon_area_centroid(&cj[i].pts, cj[i].normal);
            area += a;
            for m in 0..3 {
                c[m] += a * x[m];
            }
            all.extend_from_slice(&cj[i].pts);
            closed.extend_from_slice(&cj[i].closed);
            max_opening = max_opening.max(cj[i].max);
        }
        let position = if area > 0.0 {
            [c[0] / area, c[1] / area, c[2] / area]
        } else {
            polygon_area_centroid(&all, cj[members[0]].normal).1
        };
        // The closed points of one hinge line, counted once.
        let mut distinct: Vec<[f64; 3]> = Vec::new();
        for p in closed {
            if !distinct.iter().any(|q| d3(p, *q) <= tol) {
                distinct.push(p);
            }
        }
        let (front, length) = match distinct.len() {
            0 => (CrackFront::Separation, diameter(&all)),
            1 => (CrackFront::Pivot, diameter(&all)),
            _ => (CrackFront::HingeLine, diameter(&distinct)),
        };
        out.push(Crack3d {
            joints: members.iter().map(|&i| cj[i].id).collect(),
            faces: members.iter().map(|&i| cj[i].faces.clone()).collect(),
            position,
            max_opening,
            length,
            area,
            front,
        });
    }
    let largest = out.iter().fold(0.0f64, |m, c| m.max(c.max_opening));
    out.sort_by(|a, b| {
        quantise(b.max_opening, largest)
            .cmp(&quantise(a.max_opening, largest))
            .then(a.joints[0].cmp(&b.joints[0]))
    });
    out
}

/// Area and centroid of a planar polygon in 3D with unit normal `n` (fan triangulation about
/// the first vertex); the mean of the vertices when the area vanishes.
fn polygon_area_centroid(p: &[[f64; 3]], n: [f64; 3]) -> (f64, [f64; 3]) {
    let mean = {
        let k = p.len().max(1) as f64;
        let s = p
            .iter()
            .fold([0.0; 3], |s, q| [s[0] + q[0], s[1] + q[1], s[2] + q[2]]);
        [s[0] / k, s[1] / k, s[2] / k]
    };
    if p.len() < 3 {
        return (0.0, mean);
    }
    let (mut area, mut c) = (0.0, [0.0; 3]);
    for i in 1..p.len() - 1 {
        let (a, b, d) = (p[0], p[i], p[i + 1]);
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let v = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
        let x = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        let t = 0.5 * (x[0] * n[0] + x[1] * n[1] + x[2] * n[2]);
        area += t;
        for m in 0..3 {
            c[m] += t * (a[m] + b[m] + d[m]) / 3.0;
        }
    }
    if area.abs() > 0.0 {
        (area.abs(), [c[0] / area, c[1] / area, c[2] / area])
    } else {
        (0.0, mean)
    }
}

/// How summaries write a crack, in either dimension.
pub trait CrackText {
    /// The largest opening (m for a settlement).
    fn max_opening(&self) -> f64;
    /// One line without the leading "crack N: ": with `widths`, the width in mm (a settlement);
    /// without, the opening relative to `largest` (a collapse mechanism, whose amplitude is
    /// arbitrary).
    fn describe(&self, widths: bool, largest: f64) -> String;
    /// A 2D crack's length and the rise and run of its chord (m); None in 3D.
    fn chord(&self) -> Option<(f64, f64, f64)> {
        None
    }
}

/// A width in mm (the summaries' unit for openings, [`crate::lengths`]: below half a
/// micrometre in significant digits, "< 0.001 mm" only within the round-off of the structure's
/// size, session 25), or an opening relative to the largest.
fn width_text(w: f64, widths: bool, largest: f64) -> String {
    use crate::lengths::{scale, Length, ROUND_OFF};
    if widths {
        if w * 1000.0 < 0.0005 && w <= ROUND_OFF * scale() {
            "< 0.001 mm wide".to_string()
        } else {
            format!("{} wide", Length::Opening.show(w))
        }
    } else if largest > 0.0 {
        format!("relative opening {:.3}", w / largest)
    } else {
        "relative opening 0".to_string()
    }
}

/// A position `(x, y[, z])` in the summaries' unit for positions (m, without the unit).
fn xy(p: &[f64]) -> String {
    let c: Vec<String> = p
        .iter()
        .map(|v| crate::lengths::Length::Position.number(*v))
        .collect();
    format!("({})", c.join(", "))
}

fn long(l: f64) -> String {
    crate::lengths::Length::Position.show(l)
}

fn body_text(b: &BodyName) -> String {
    match b {
        BodyName::Block(i) => i.to_string(),
        BodyName::Support(s) => s.clone(),
    }
}

impl CrackText for Crack {
    fn max_opening(&self) -> f64 {
        self.max_opening
    }
    fn chord(&self) -> Option<(f64, f64, f64)> {
        (!self.closed_loop).then_some((self.length, self.rise, self.run))
    }
    fn describe(&self, widths: bool, largest: f64) -> String {
        let n = self.joints.len();
        let joints = if n == 1 {
            let f = &self.faces[0];
            format!(
                "joint {} ({} | {})",
                self.joints[0],
                body_text(&f[0]),
                body_text(&f[1])
            )
        } else {
            format!("{n} joints")
        };
        let first = self.points.first().copied().unwrap_or([0.0; 2]);
        let last = self.points.last().copied().unwrap_or([0.0; 2]);
        let mut s = format!(
            "{}, {} long, {joints}, from {} to {} m",
            width_text(self.max_opening, widths, largest),
            long(self.length),
            xy(&first),
            xy(&last)
        );
        if self.closed_loop {
            s.push_str(" (a closed loop)");
        } else if self.end.hinge {
            s.push_str(" (closing at a hinge)");
        }
        s
    }
}

impl CrackText for Crack3d {
    fn max_opening(&self) -> f64 {
        self.max_opening
    }
    fn describe(&self, widths: bool, largest: f64) -> String {
        let what = match self.front {
            CrackFront::HingeLine => "hinge line",
            CrackFront::Pivot => "pivot, face",
            CrackFront::Separation => "separation, face",
        };
        let joints = if self.joints.len() == 1 {
            let f = &self.faces[0];
            format!(
                "joint {} ({} | {})",
                self.joints[0],
                body_text(&f[0]),
                body_text(&f[1])
            )
        } else {
            format!("{} joints", self.joints.len())
        };
        format!(
            "{}, {what} {} long, {joints}, centre {} m",
            width_text(self.max_opening, widths, largest),
            long(self.length),
            xy(&self.position)
        )
    }
}
