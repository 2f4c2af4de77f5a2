//! Spatial geometry: closed polyhedra (validation, volume, centroid), contact interfaces between
//! them, and the overlap check.
//!
//! * [`clean_polyhedron`] validates a block or support given as vertices and faces (vertex index
//!   lists, counter-clockwise seen from outside) and computes its volume and centroid by the
//!   divergence theorem.
//! * [`detect_interfaces3`] finds every pair of coplanar, facing faces of different bodies and
//!   intersects them. It never compares all pairs: faces are bucketed by normal direction
//!   (hashed cells, with neighbour cells checked so values on a cell edge are not missed), then
//!   sorted by plane offset, then paired on a uniform grid inside each plane. The cost is
//!   O(F log F) in the number of faces for bodies of similar size.
//! * [`find_overlap3`] finds candidate pairs on a uniform grid of bounding boxes and tests them
//!   exactly (non-convex bodies included); bodies touching along faces do not overlap.
//!
//! Polygon intersection inside a contact plane uses the `i_overlay` crate (the engine behind
//! `geo`'s boolean operations; maintained, robust for non-convex polygons with holes, no
//! further dependencies), called directly rather than through `geo` to avoid `geo`'s large
//! dependency tree for one operation. Its 64-bit integer engine is used: coordinates are
//! snapped to a grid of about 1e-18 of the pair's extent, far below any model tolerance.

use crate::error::{model_err, Result};
use crate::geometry::{point_segment_distance, signed_area, strictly_inside};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::core::solver::Solver;
use i_overlay::float::overlay::{FloatOverlay, OverlayOptions};
use rayon::prelude::*;
use std::collections::HashMap;

use crate::vector::{add3, cross, dot3, norm3, scale3, sub3, V3};
type P2 = [f64; 2];

/// A validated polyhedron: faces outward (counter-clockwise seen from outside), mass properties.
#[derive(Clone, Debug, PartialEq)]
pub struct Solid {
    /// The vertices as given (unused ones are kept, so indices keep their meaning).
    pub vertices: Vec<[f64; 3]>,
    /// The faces in the order given, each counter-clockwise seen from outside.
    pub faces: Vec<Vec<usize>>,
    pub volume: f64,
    pub centroid: [f64; 3],
}

/// `a > b`, false when either is NaN (so `!exceeds(a, b)` rejects NaN).
#[inline]
fn exceeds(a: f64, b: f64) -> bool {
    a.partial_cmp(&b) == Some(std::cmp::Ordering::Greater)
}

/// Twice the vector area of a face (Newell's normal: Σ (vᵢ − v₀) × (vᵢ₊₁ − v₀), which is exact
/// for planar non-convex faces), and the mean of its vertices.
fn newell(vertices: &[V3], face: &[usize]) -> (V3, V3) {
    let o = vertices[face[0]];
    let nv = crate::vector::newell(face.len(), |i| vertices[face[i]]);
    let c = crate::vector::mean3(face.len(), |i| sub3(vertices[face[i]], o));
    (nv, add3(o, c))
}

/// Diameter of a face's vertex set (diagonal of its bounding box).
fn face_diameter(vertices: &[V3], face: &[usize]) -> f64 {
    let b = bbox3_iter(face.iter().map(|&i| vertices[i]));
    norm3(sub3(b[1], b[0]))
}

/// Axis-aligned bounding box [min, max] of points (min = +∞, max = −∞ when empty).
pub fn bbox3(points: &[[f64; 3]]) -> [[f64; 3]; 2] {
    bbox3_iter(points.iter().copied())
}

fn bbox3_iter(points: impl Iterator<Item = V3>) -> [V3; 2] {
    let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
    for p in points {
        for k in 0..3 {
            b[0][k] = b[0][k].min(p[k]);
            b[1][k] = b[1][k].max(p[k]);
        }
    }
    b
}

/// Validate and clean a polyhedron. `what` names it in errors ("block 12", "support 'left'").
/// `tol` is an absolute length (m).
///
/// Checks, each failing with a one-line error naming `what`: at least 4 vertices and 4 faces,
/// finite coordinates, face indices in range, faces of at least 3 distinct vertices, no
/// degenerate face (area ≤ `tol` × the face's diameter), planar faces (every vertex within `tol`
/// of the plane through the vertices' mean with Newell's normal), a closed surface (every edge
/// used by two faces) that is manifold and consistently oriented (the two faces of an edge run
/// along it in opposite directions), and a volume above `tol` × the surface area. A
/// consistently inward surface is turned outward by reversing every face. Vertices are not
/// merged (faces are connected by index) and unused vertices are kept.
///
/// Faces that form several closed shells (sets of faces connected through edges) are a block
/// with cavities, and accepted, only if the largest shell is the outer surface and every other
/// one is a cavity: oriented opposite to the outer surface (its faces face into the cavity, out
/// of the material), strictly inside it (vertices farther than `tol` inside, no edge crossing a
/// face), apart from the other cavities, enclosing a volume. The signed volumes then add up to
/// the hollow block's, and so do the moments (centroid). Two shells facing the same way (a
/// second piece, or an inner shell that would count its volume twice) are refused.
pub fn clean_polyhedron(
    what: &str,
    vertices: &[[f64; 3]],
    faces: &[Vec<usize>],
    tol: f64,
) -> Result<Solid> {
    let nv = vertices.len();
    if nv < 4 {
        return model_err(format!(
            "{what}: polyhedron has {nv} vertices, needs at least 4"
        ));
    }
    if faces.len() < 4 {
        return model_err(format!(
            "{what}: polyhedron has {} faces, needs at least 4",
            faces.len()
        ));
    }
    if let Some(i) = vertices
        .iter()
        .position(|v| !v.iter().all(|x| x.is_finite()))
    {
        return model_err(format!(
            "{what}: vertex {i} has a coordinate that is not a finite number"
        ));
    }
    let mut sorted: Vec<usize> = Vec::new();
    for (k, f) in faces.iter().enumerate() {
        if f.len() < 3 {
            return model_err(format!(
                "{what}: face {k} has {} vertices, needs at least 3",
                f.len()
            ));
        }
        if let Some(&i) = f.iter().find(|&&i| i >= nv) {
            return model_err(format!(
                "{what}: face {k} refers to vertex {i}, but there are only {nv} vertices"
            ));
        }
        sorted.clear();
        sorted.extend_from_slice(f);
        sorted.sort_unstable();
        if let Some(w) = sorted.windows(2).find(|w| w[0] == w[1]) {
            return model_err(format!("{what}: face {k} lists vertex {} twice", w[0]));
        }
    }
    let mut surface = 0.0;
    let mut face_area = Vec::with_capacity(faces.len());
    for (k, f) in faces.iter().enumerate() {
        let (nvec, c) = newell(vertices, f);
        let twice = norm3(nvec);
        let diam = face_diameter(vertices, f);
        if !(twice.is_finite() && diam.is_finite()) {
            return model_err(format!(
                "{what}: face {k}'s size overflows (coordinates too large for f64 arithmetic)"
            ));
        }
        if !exceeds(0.5 * twice, tol * diam) {
            return model_err(format!("{what}: face {k} is degenerate (zero area)"));
        }
        surface += 0.5 * twice;
        face_area.push(0.5 * twice);
        let n = scale3(nvec, 1.0 / twice);
        for &i in f {
            let d = dot3(n, sub3(vertices[i], c)).abs();
            if d > tol {
                return model_err(format!(
                    "{what}: face {k} is not planar (vertex {i} is {d:.3e} m off the face's plane, tolerance {tol:.3e} m)"
                ));
            }
        }
    }
    // Edges: (low, high, face, forward), sorted, so each edge's faces are adjacent.
    let mut edges: Vec<(usize, usize, usize, bool)> = Vec::new();
    for (k, f) in faces.iter().enumerate() {
        for i in 0..f.len() {
            let (p, q) = (f[i], f[(i + 1) % f.len()]);
            edges.push((p.min(q), p.max(q), k, p < q));
        }
    }
    edges.sort_unstable();
    let mut i = 0;
    while i < edges.len() {
        let mut j = i + 1;
        while j < edges.len() && (edges[j].0, edges[j].1) == (edges[i].0, edges[i].1) {
            j += 1;
        }
        let (lo, hi, k, fwd) = edges[i];
        let (from, to) = if fwd { (lo, hi) } else { (hi, lo) };
        match j - i {
            1 => {
                return model_err(format!(
                    "{what}: the surface is open (edge {from}–{to} of face {k} belongs to no other face)"
                ))
            }
            2 => {
                if edges[i + 1].3 == fwd {
                    return model_err(format!(
                        "{what}: faces {k} and {} are oriented inconsistently (both run along edge {from}→{to})",
                        edges[i + 1].2
                    ));
                }
            }
            _ => {
                let list: Vec<String> = edges[i..j].iter().map(|e| e.2.to_string()).collect();
                return model_err(format!(
                    "{what}: the surface is not manifold (edge {lo}–{hi} is shared by faces {})",
                    list.join(", ")
                ));
            }
        }
        i = j;
    }
    // Shells: the faces connected through shared edges (every edge has exactly two faces now).
    let mut parent: Vec<u32> = (0..faces.len() as u32).collect();
    for pair in edges.chunks_exact(2) {
        let (ra, rb) = (
            find(&mut parent, pair[0].2 as u32),
            find(&mut parent, pair[1].2 as u32),
        );
        if ra != rb {
            parent[ra.max(rb) as usize] = ra.min(rb);
        }
    }
    let mut shell_of = vec![0usize; faces.len()];
    let mut shells: Vec<Vec<usize>> = Vec::new();
    let mut index_of_root: HashMap<u32, usize> = HashMap::new();
    for (k, s) in shell_of.iter_mut().enumerate() {
        let r = find(&mut parent, k as u32);
        *s = *index_of_root.entry(r).or_insert_with(|| {
            shells.push(Vec::new());
            shells.len() - 1
        });
        shells[*s].push(k);
    }
    // Divergence theorem: signed tetrahedra (o, v₀, vᵢ, vᵢ₊₁) of each face's fan, summed per
    // shell. The fan of a planar non-convex face covers it with signed triangles, so this is
    // exact for it too.
    let o = vertices[faces[0][0]];
    let mut vol6 = vec![0.0; shells.len()];
    let mut mom = vec![[0.0; 3]; shells.len()];
    let mut area = vec![0.0; shells.len()];
    for (k, f) in faces.iter().enumerate() {
        let s = shell_of[k];
        area[s] += face_area[k];
        let a = sub3(vertices[f[0]], o);
        for i in 1..f.len() - 1 {
            let b = sub3(vertices[f[i]], o);
            let c = sub3(vertices[f[i + 1]], o);
            let v6 = dot3(a, cross(b, c));
            vol6[s] += v6;
            mom[s] = add3(mom[s], scale3(add3(add3(a, b), c), v6));
        }
    }
    if shells.len() > 1 {
        check_cavities(what, vertices, faces, &shells, &vol6, &area, tol)?;
    }
    let outer_sign = shells_outer(&vol6).map_or(1.0, |k| vol6[k].signum());
    let total6: f64 = vol6.iter().sum();
    let mom = mom.iter().fold([0.0; 3], |s, m| add3(s, *m));
    let volume = total6 / 6.0;
    if !exceeds(volume.abs(), tol * surface) {
        return model_err(format!("{what}: the polyhedron has zero volume"));
    }
    // Σ V_t (a + b + c)/4 / Σ V_t, with V_t = v6/6: the sixths cancel.
    let centroid = add3(o, scale3(mom, 1.0 / (4.0 * total6)));
    let faces: Vec<Vec<usize>> = if outer_sign < 0.0 {
        // Consistently inward: turn every face round (keeping its first vertex).
        faces.iter().map(|f| reversed(f)).collect()
    } else {
        faces.to_vec()
    };
    Ok(Solid {
        vertices: vertices.to_vec(),
        faces,
        volume: volume.abs(),
        centroid,
    })
}

/// A face turned round, keeping its first vertex.
fn reversed(f: &[usize]) -> Vec<usize> {
    let mut g = Vec::with_capacity(f.len());
    g.push(f[0]);
    g.extend(f[1..].iter().rev());
    g
}

/// The shell of largest enclosed volume (the outer surface of a block with cavities).
fn shells_outer(vol6: &[f64]) -> Option<usize> {
    (0..vol6.len()).max_by(|&i, &j| vol6[i].abs().total_cmp(&vol6[j].abs()).then(j.cmp(&i)))
}

/// "faces 6–11" or "faces 2, 5, 9, … (12 faces)".
fn faces_label(list: &[usize]) -> String {
    let contiguous = list.windows(2).all(|w| w[1] == w[0] + 1);
    match list {
        [one] => format!("face {one}"),
        [first, .., last] if contiguous => format!("faces {first}–{last}"),
        _ => {
            let head: Vec<String> = list.iter().take(4).map(|k| k.to_string()).collect();
            if list.len() > 4 {
                format!("faces {}, … ({} faces)", head.join(", "), list.len())
            } else {
                format!("faces {}", head.join(", "))
            }
        }
    }
}

/// A polyhedron whose faces form several closed shells is a block with cavities only if one
/// shell (the largest) is the outer surface and every other one is a cavity: oriented opposite
/// to it (its faces face into the cavity, i.e. out of the material, so that the signed volumes
/// add up to the hollow block's), strictly inside it, and apart from the other cavities. Each
/// shell must enclose a volume.
fn check_cavities(
    what: &str,
    vertices: &[V3],
    faces: &[Vec<usize>],
    shells: &[Vec<usize>],
    vol6: &[f64],
    area: &[f64],
    tol: f64,
) -> Result<()> {
    let n = shells.len();
    for s in 0..n {
        if !exceeds(vol6[s].abs() / 6.0, tol * area[s]) {
            return model_err(format!(
                "{what}: the faces form {n} closed surfaces and the one of {} encloses no volume",
                faces_label(&shells[s])
            ));
        }
    }
    let Some(outer) = shells_outer(vol6) else {
        return Ok(());
    };
    // Each shell as a solid of its own, faces outward, for the containment tests.
    let solid_of = |s: usize| -> Solid {
        let fs = shells[s]
            .iter()
            .map(|&k| {
                if vol6[s] < 0.0 {
                    reversed(&faces[k])
                } else {
                    faces[k].clone()
                }
            })
            .collect();
        Solid {
            vertices: vertices.to_vec(),
            faces: fs,
            volume: vol6[s].abs() / 6.0,
            centroid: [0.0; 3],
        }
    };
    let outer_solid = solid_of(outer);
    let outer_q = QBody::new(&outer_solid, tol);
    let outer_label = faces_label(&shells[outer]);
    let mut cavities: Vec<(usize, QBody)> = Vec::new();
    for s in (0..n).filter(|&s| s != outer) {
        let solid = solid_of(s);
        let q = QBody::new(&solid, tol);
        let mut used: Vec<usize> = shells[s].iter().flat_map(|&k| faces[k].clone()).collect();
        used.sort_unstable();
        used.dedup();
        let inside = used
            .iter()
            .all(|&i| outer_q.strictly_contains(vertices[i], tol))
            && !q
                .edges
                .iter()
                .any(|&(p, r)| outer_q.is_crossed_by(p, r, tol))
            && !outer_q
                .edges
                .iter()
                .any(|&(p, r)| q.is_crossed_by(p, r, tol));
        let label = faces_label(&shells[s]);
        let cavity = (vol6[s] < 0.0) != (vol6[outer] < 0.0);
        if cavity && !inside {
            return model_err(format!(
                "{what}: the closed surface of {label} faces the other way to the outer surface ({outer_label}), as a cavity does, but is not strictly inside it"
            ));
        }
        if !cavity && inside {
            return model_err(format!(
                "{what}: the closed surface of {label} lies inside the outer surface ({outer_label}) and faces the same way, which would count its volume twice: a cavity's faces face into the cavity (counter-clockwise seen from inside it), so turn them round, or give the inner body its own block"
            ));
        }
        if !cavity {
            return model_err(format!(
                "{what}: the faces form {n} separate closed surfaces ({outer_label}; {label}): a block is one piece, so give each piece its own block"
            ));
        }
        for (t, other) in &cavities {
            if bodies_overlap(&q, other, tol) {
                return model_err(format!(
                    "{what}: the cavities of {label} and {} overlap",
                    faces_label(&shells[*t])
                ));
            }
        }
        cavities.push((s, q));
    }
    Ok(())
}

/// One contact interface: a face of body `a` and a face of body `b` coplanar and facing each other.
#[derive(Clone, Debug, PartialEq)]
pub struct Interface3 {
    /// Lower body index (into the `bodies` slice).
    pub a: usize,
    /// Higher body index.
    pub b: usize,
    /// Unit outward normal of a's face (from a into b).
    pub normal: [f64; 3],
    /// Contact polygon (outer ring), counter-clockwise about `normal`, collinear and duplicate
    /// vertices (within tol) removed, starting at its lexicographically smallest vertex.
    pub polygon: Vec<[f64; 3]>,
    pub area: f64,
}

/// An orthonormal frame (u, v) of the plane normal to unit `n`, with u × v = n.
fn plane_frame(n: V3) -> (V3, V3) {
    let ax = n.map(f64::abs);
    let e = if ax[0] <= ax[1] && ax[0] <= ax[2] {
        [1.0, 0.0, 0.0]
    } else if ax[1] <= ax[2] {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let u = cross(e, n);
    let u = scale3(u, 1.0 / norm3(u));
    (u, cross(n, u))
}

/// A face of some body, as interface detection sees it.
struct FaceRec {
    body: u32,
    face: u32,
    /// Unit outward normal, vector area ×2, vertex mean, diameter.
    n: V3,
    nvec: V3,
    c: V3,
    diam: f64,
    /// Angle by which the face may tilt and still stay within tol (tol / diameter, capped).
    theta: f64,
}

/// Union-find with path halving.
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let p = parent[parent[x as usize] as usize];
        parent[x as usize] = p;
        x = p;
    }
    x
}

/// Cell index of `x` for cells of size `h` centred on multiples of `h`.
#[inline]
fn cell(x: f64, h: f64) -> i64 {
    (x / h + 0.5).floor() as i64
}

/// All interfaces between bodies; deterministic order (by a, b, then polygon). Several per pair
/// are possible (e.g. a block on one support at two separate feet).
///
/// Two faces face each other when their outward normals are opposite within an angle
/// `tol/d₁ + tol/d₂ + tol/D` (dᵢ the faces' diameters, D the model's: a face tilted by
/// `tol/d` moves by `tol` across itself) and the smaller face's vertex mean is within `tol` of
/// the larger face's plane. All facing faces of `a` and of `b` in one plane are intersected at
/// once (so faces split into several coplanar polygons are handled). Each connected region of
/// the intersection is an interface; of a region with holes the outer ring is kept (statics
/// needs the convex hull of the contact points, which the outer ring has). A region is kept
/// when its area exceeds `tol` × half its perimeter, i.e. when it is wider than `tol`: a strip
/// narrower than that is an edge or corner contact, not a face contact.
pub fn detect_interfaces3(bodies: &[&Solid], tol: f64) -> Vec<Interface3> {
    let bb = bbox3_iter(bodies.iter().flat_map(|s| s.vertices.iter().copied()));
    if bodies.is_empty() || !bb[0][0].is_finite() {
        return Vec::new();
    }
    let origin = scale3(add3(bb[0], bb[1]), 0.5);
    let size = norm3(sub3(bb[1], bb[0])).max(tol).max(f64::MIN_POSITIVE);

    let mut faces: Vec<FaceRec> = Vec::new();
    for (bi, s) in bodies.iter().enumerate() {
        for (fi, f) in s.faces.iter().enumerate() {
            if f.len() < 3 || f.iter().any(|&i| i >= s.vertices.len()) {
                continue;
            }
            let (nvec, c) = newell(&s.vertices, f);
            let l = norm3(nvec);
            if !exceeds(l, 0.0) {
                continue;
            }
            let diam = face_diameter(&s.vertices, f);
            faces.push(FaceRec {
                body: bi as u32,
                face: fi as u32,
                n: scale3(nvec, 1.0 / l),
                nvec,
                c,
                diam,
                theta: tol / diam.max(tol),
            });
        }
    }
    if faces.is_empty() {
        return Vec::new();
    }
    // Direction cells: four times the largest face tolerance, at most 0.05 rad; a face's own
    // tolerance is capped at the cell size so that it spans at most the neighbouring cells.
    let theta_max = faces.iter().map(|f| f.theta).fold(0.0, f64::max);
    let h = (4.0 * theta_max + tol / size).clamp(1e-9, 0.05);
    for f in faces.iter_mut() {
        f.theta = (f.theta + tol / size).min(h);
    }
    let mut cells: HashMap<[i64; 3], u32> = HashMap::new();
    let mut face_cell: Vec<u32> = Vec::with_capacity(faces.len());
    for f in &faces {
        let key = f.n.map(|x| cell(x, h));
        let next = cells.len() as u32;
        face_cell.push(*cells.entry(key).or_insert(next));
    }
    // Join each face's cell with the cells around its opposite direction.
    let mut parent: Vec<u32> = (0..cells.len() as u32).collect();
    for (k, f) in faces.iter().enumerate() {
        let m = f.n.map(|x| -x);
        let lo = m.map(|x| cell(x - f.theta, h));
        let hi = m.map(|x| cell(x + f.theta, h));
        for i in lo[0]..=hi[0] {
            for j in lo[1]..=hi[1] {
                for l in lo[2]..=hi[2] {
                    if let Some(&c) = cells.get(&[i, j, l]) {
                        let (ra, rb) = (find(&mut parent, face_cell[k]), find(&mut parent, c));
                        if ra != rb {
                            parent[ra.max(rb) as usize] = ra.min(rb);
                        }
                    }
                }
            }
        }
    }
    // Faces grouped by direction component (in face order within a component).
    let mut order: Vec<(u32, u32)> = (0..faces.len() as u32)
        .map(|k| (find(&mut parent, face_cell[k as usize]), k))
        .collect();
    order.sort_unstable();

    // Candidate pairs of facing faces: [a, b, plane id, side of a, face of a, face of b], the
    // faces as face-record indices.
    let mut cands: Vec<[u32; 6]> = Vec::new();
    let mut plane_id = 0u32;
    let mut i = 0;
    while i < order.len() {
        let mut j = i + 1;
        while j < order.len() && order[j].0 == order[i].0 {
            j += 1;
        }
        let comp: Vec<u32> = order[i..j].iter().map(|x| x.1).collect();
        i = j;
        if comp.len() < 2 {
            continue;
        }
        let nbar = faces[comp[0] as usize].n;
        // Spread of the directions, for the plane-offset chaining tolerance.
        let mut spread: f64 = 0.0;
        let mut dmax: f64 = 0.0;
        let mut pos = false;
        let mut neg = false;
        for &k in &comp {
            let f = &faces[k as usize];
            let s = if dot3(f.n, nbar) >= 0.0 { 1.0 } else { -1.0 };
            pos |= s > 0.0;
            neg |= s < 0.0;
            spread = spread.max(norm3(sub3(scale3(f.n, s), nbar)));
            dmax = dmax.max(f.diam);
        }
        if !(pos && neg) {
            continue;
        }
        let dtol = 2.0 * tol + spread * dmax;
        let mut by_offset: Vec<(f64, u32)> = comp
            .iter()
            .map(|&k| (dot3(nbar, sub3(faces[k as usize].c, origin)), k))
            .collect();
        by_offset.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        let mut a = 0;
        while a < by_offset.len() {
            let mut b = a + 1;
            while b < by_offset.len() && by_offset[b].0 - by_offset[b - 1].0 <= dtol {
                b += 1;
            }
            // A plane with faces on both sides (e.g. not a wall's face plane).
            let both = {
                let s0 = dot3(faces[by_offset[a].1 as usize].n, nbar) >= 0.0;
                by_offset[a + 1..b]
                    .iter()
                    .any(|x| (dot3(faces[x.1 as usize].n, nbar) >= 0.0) != s0)
            };
            if both {
                let plane: Vec<u32> = by_offset[a..b].iter().map(|x| x.1).collect();
                pair_in_plane(
                    bodies, &faces, &plane, nbar, origin, tol, size, plane_id, &mut cands,
                );
                plane_id += 1;
            }
            a = b;
        }
    }
    cands.sort_unstable();
    cands.dedup();

    // One polygon intersection per (a, b, plane, side of a): the groups' faces, flat.
    struct Group {
        a: u32,
        b: u32,
        fa: std::ops::Range<usize>,
        fb: std::ops::Range<usize>,
    }
    let mut groups: Vec<Group> = Vec::new();
    let (mut flat_a, mut flat_b): (Vec<u32>, Vec<u32>) = (Vec::new(), Vec::new());
    let mut i = 0;
    while i < cands.len() {
        let key = &cands[i][..4];
        let mut j = i + 1;
        while j < cands.len() && &cands[j][..4] == key {
            j += 1;
        }
        let (sa, sb) = (flat_a.len(), flat_b.len());
        // Faces of a are sorted within the group; those of b are sorted here.
        for c in &cands[i..j] {
            if flat_a.len() == sa || flat_a[flat_a.len() - 1] != c[4] {
                flat_a.push(c[4]);
            }
        }
        flat_b.extend(cands[i..j].iter().map(|c| c[5]));
        flat_b[sb..].sort_unstable();
        let mut w = sb;
        for r in sb..flat_b.len() {
            if w == sb || flat_b[w - 1] != flat_b[r] {
                flat_b[w] = flat_b[r];
                w += 1;
            }
        }
        flat_b.truncate(w);
        groups.push(Group {
            a: cands[i][0],
            b: cands[i][1],
            fa: sa..flat_a.len(),
            fb: sb..flat_b.len(),
        });
        i = j;
    }
    // Groups are independent: clip them in parallel (rayon), each worker reusing one overlay
    // engine (its buffers) across its groups; the result is sorted below, so the order in
    // which workers finish does not matter.
    let mut out: Vec<Interface3> = groups
        .par_chunks(256)
        .map_init(
            || FloatOverlay::<P2, i64>::new_empty(OverlayOptions::default(), Solver::default(), 64),
            |ov, chunk| {
                let mut out = Vec::new();
                for g in chunk {
                    intersect_group(
                        bodies,
                        &faces,
                        (g.a as usize, g.b as usize),
                        (&flat_a[g.fa.clone()], &flat_b[g.fb.clone()]),
                        tol,
                        ov,
                        &mut out,
                    );
                }
                out
            },
        )
        .flatten_iter()
        .collect();
    out.sort_by(|x, y| {
        (x.a, x.b).cmp(&(y.a, y.b)).then_with(|| {
            for (p, q) in x.polygon.iter().zip(&y.polygon) {
                for k in 0..3 {
                    let o = p[k].total_cmp(&q[k]);
                    if o.is_ne() {
                        return o;
                    }
                }
            }
            x.polygon.len().cmp(&y.polygon.len())
        })
    });
    out
}

/// Pair the faces of one plane (face record indices `plane`, normals ±`nbar`) whose projections
/// overlap, on a uniform grid in the plane; push facing pairs of different bodies to `cands`.
#[allow(clippy::too_many_arguments)]
fn pair_in_plane(
    bodies: &[&Solid],
    faces: &[FaceRec],
    plane: &[u32],
    nbar: V3,
    origin: V3,
    tol: f64,
    size: f64,
    plane_id: u32,
    cands: &mut Vec<[u32; 6]>,
) {
    let (u, v) = plane_frame(nbar);
    // 2D boxes of the projected faces, grown by tol.
    let boxes: Vec<[f64; 4]> = plane
        .iter()
        .map(|&k| {
            let f = &faces[k as usize];
            let s = bodies[f.body as usize];
            let mut b = [
                f64::INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::NEG_INFINITY,
            ];
            for &vi in &s.faces[f.face as usize] {
                let r = sub3(s.vertices[vi], origin);
                let (x, y) = (dot3(r, u), dot3(r, v));
                b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
            }
            [b[0] - tol, b[1] - tol, b[2] + tol, b[3] + tol]
        })
        .collect();
    let m = plane.len();
    let all = boxes.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |a, b| {
            [
                a[0].min(b[0]),
                a[1].min(b[1]),
                a[2].max(b[2]),
                a[3].max(b[3]),
            ]
        },
    );
    // Cell: the mean face extent, enlarged if the grid would have more than 4m + 16 cells.
    let mean = boxes
        .iter()
        .map(|b| (b[2] - b[0]).max(b[3] - b[1]))
        .sum::<f64>()
        / m as f64;
    let (w, hgt) = (all[2] - all[0], all[3] - all[1]);
    let mut hc = mean.max(tol).max(f64::MIN_POSITIVE);
    if (w / hc + 1.0) * (hgt / hc + 1.0) > 4.0 * m as f64 + 16.0 {
        hc = hc.max((w * hgt / (4.0 * m as f64)).sqrt());
    }
    let at = |x: f64, lo: f64| ((x - lo) / hc).floor() as i64;
    let mut entries: Vec<(i64, i64, u32)> = Vec::new();
    for (l, b) in boxes.iter().enumerate() {
        for cx in at(b[0], all[0])..=at(b[2], all[0]) {
            for cy in at(b[1], all[1])..=at(b[3], all[1]) {
                entries.push((cx, cy, l as u32));
            }
        }
    }
    entries.sort_unstable();
    let mut i = 0;
    while i < entries.len() {
        let mut j = i + 1;
        while j < entries.len() && (entries[j].0, entries[j].1) == (entries[i].0, entries[i].1) {
            j += 1;
        }
        let (cx, cy) = (entries[i].0, entries[i].1);
        for p in i..j {
            for q in p + 1..j {
                let (lp, lq) = (entries[p].2 as usize, entries[q].2 as usize);
                let (fp, fq) = (&faces[plane[lp] as usize], &faces[plane[lq] as usize]);
                if fp.body == fq.body || dot3(fp.n, fq.n) >= 0.0 {
                    continue;
                }
                let (bp, bq) = (boxes[lp], boxes[lq]);
                let lo = [bp[0].max(bq[0]), bp[1].max(bq[1])];
                let hi = [bp[2].min(bq[2]), bp[3].min(bq[3])];
                // Overlap wider than the 2·tol growth; counted in the cell holding its corner.
                if hi[0] - lo[0] <= 3.0 * tol
                    || hi[1] - lo[1] <= 3.0 * tol
                    || at(lo[0], all[0]) != cx
                    || at(lo[1], all[1]) != cy
                {
                    continue;
                }
                // Exact facing test: opposite normals, and coincident planes.
                let ang = tol / size + fp.theta + fq.theta;
                if norm3(add3(fp.n, fq.n)) > ang {
                    continue;
                }
                let (small, big) = if fp.diam <= fq.diam {
                    (fp, fq)
                } else {
                    (fq, fp)
                };
                if dot3(big.n, sub3(small.c, big.c)).abs() > tol {
                    continue;
                }
                let (ka, kb) = if fp.body < fq.body {
                    (plane[lp], plane[lq])
                } else {
                    (plane[lq], plane[lp])
                };
                // The side of a's face (a body flat at this plane may have faces on both).
                let side = u32::from(dot3(faces[ka as usize].n, nbar) >= 0.0);
                cands.push([
                    faces[ka as usize].body,
                    faces[kb as usize].body,
                    plane_id,
                    side,
                    ka,
                    kb,
                ]);
            }
        }
        i = j;
    }
}

/// Intersect the faces `fa` of body `a` with the faces `fb` of body `b` (one plane, facing) and
/// push one interface per connected region.
fn intersect_group(
    bodies: &[&Solid],
    faces: &[FaceRec],
    (a, b): (usize, usize),
    (fa, fb): (&[u32], &[u32]),
    tol: f64,
    ov: &mut FloatOverlay<P2, i64>,
    out: &mut Vec<Interface3>,
) {
    if fa.is_empty() || fb.is_empty() {
        return;
    }
    // a's outward normal: the direction of the summed vector areas of its faces.
    let nsum = fa
        .iter()
        .fold([0.0; 3], |s, &k| add3(s, faces[k as usize].nvec));
    let n = scale3(nsum, 1.0 / norm3(nsum));
    let (u, v) = plane_frame(n);
    let o = faces[fa[0] as usize].c;
    let project = |k: u32| -> Vec<P2> {
        let f = &faces[k as usize];
        let s = bodies[f.body as usize];
        s.faces[f.face as usize]
            .iter()
            .map(|&i| {
                let r = sub3(s.vertices[i], o);
                [dot3(r, u), dot3(r, v)]
            })
            .collect()
    };
    let subj: Vec<Vec<P2>> = fa.iter().map(|&k| project(k)).collect();
    let clip: Vec<Vec<P2>> = fb.iter().map(|&k| project(k)).collect();
    ov.reinit_with_subj_and_clip(&subj, &clip);
    let shapes = ov.overlay(OverlayRule::Intersect, FillRule::NonZero);
    for shape in shapes {
        let Some(outer) = shape.first() else { continue };
        let mut ring = clean_ring(outer, tol);
        if ring.len() < 3 {
            continue;
        }
        // i_overlay returns outer rings counter-clockwise; made sure of, not assumed.
        let mut area = signed_area(&ring);
        if area < 0.0 {
            ring.reverse();
            area = -area;
        }
        let perimeter: f64 = (0..ring.len())
            .map(|i| {
                let (p, q) = (ring[i], ring[(i + 1) % ring.len()]);
                (q[0] - p[0]).hypot(q[1] - p[1])
            })
            .sum();
        if !exceeds(area, 0.5 * tol * perimeter) {
            continue;
        }
        let mut polygon: Vec<V3> = ring
            .iter()
            .map(|p| add3(o, add3(scale3(u, p[0]), scale3(v, p[1]))))
            .collect();
        let first = (0..polygon.len())
            .min_by(|&i, &j| {
                let (p, q) = (polygon[i], polygon[j]);
                p[0].total_cmp(&q[0])
                    .then(p[1].total_cmp(&q[1]))
                    .then(p[2].total_cmp(&q[2]))
            })
            .unwrap_or(0);
        polygon.rotate_left(first);
        out.push(Interface3 {
            a,
            b,
            normal: n,
            polygon,
            area,
        });
    }
}

/// Remove duplicate and nearly collinear vertices of a closed ring, keeping the ring within
/// `tol` of the one given: a run of vertices is replaced by the segment joining its ends only if
/// every vertex of the run lies within `tol` of that segment (so a finely divided curve, say a
/// 20,000-gon, is not shortened by more than `tol` anywhere, however many vertices go).
///
/// One pass, O(n): from each kept vertex A the run grows while the next vertex's direction from
/// A lies in the intersection of the cones of half-angle asin(tol/|p − A|) around the vertices p
/// already in the run (a "sleeve"), and is no nearer to A than they are (so they project onto
/// the segment). It starts at the lexicographically smallest vertex (a corner of the convex
/// hull, always kept) and ends back at it.
fn clean_ring(p: &[P2], tol: f64) -> Vec<P2> {
    let n = p.len();
    if n < 3 {
        return p.to_vec();
    }
    let start = (0..n)
        .min_by(|&i, &j| {
            p[i][0]
                .total_cmp(&p[j][0])
                .then(p[i][1].total_cmp(&p[j][1]))
        })
        .unwrap_or(0);
    let ring: Vec<P2> = (0..=n).map(|k| p[(start + k) % n]).collect();
    let m = n; // ring[m] is ring[0] again
    let mut out = vec![ring[0]];
    let mut a = 0;
    while a < m {
        let o = ring[a];
        let (mut lo, mut hi) = (-std::f64::consts::PI, std::f64::consts::PI);
        let mut rmax: f64 = 0.0;
        let mut dir: Option<P2> = None;
        let mut last = None;
        for (j, q) in ring.iter().enumerate().skip(a + 1) {
            let v = [q[0] - o[0], q[1] - o[1]];
            let d = v[0].hypot(v[1]);
            if !exceeds(d, tol) {
                continue; // within tol of A: within tol of any segment from A
            }
            let r = *dir.get_or_insert([v[0] / d, v[1] / d]);
            let phi = (r[0] * v[1] - r[1] * v[0]).atan2(r[0] * v[0] + r[1] * v[1]);
            if phi < lo || phi > hi || d < rmax {
                break;
            }
            last = Some(j);
            let w = (tol / d).min(1.0).asin();
            lo = lo.max(phi - w);
            hi = hi.min(phi + w);
            rmax = d;
        }
        let Some(l) = last else { break };
        if l < m {
            out.push(ring[l]);
        }
        a = l;
    }
    // A last kept vertex within tol of the first is a duplicate of it.
    while out.len() > 1 && {
        let (x, y) = (out[out.len() - 1], out[0]);
        !exceeds((x[0] - y[0]).hypot(x[1] - y[1]), tol)
    } {
        out.pop();
    }
    out
}

/// A face prepared for point queries: plane, in-plane frame and projected polygon.
struct QFace {
    n: V3,
    o: V3,
    u: V3,
    v: V3,
    poly: Vec<P2>,
}

impl QFace {
    fn new(s: &Solid, f: &[usize]) -> Option<QFace> {
        let (nvec, c) = newell(&s.vertices, f);
        let l = norm3(nvec);
        if !exceeds(l, 0.0) {
            return None;
        }
        let n = scale3(nvec, 1.0 / l);
        let (u, v) = plane_frame(n);
        let poly = f
            .iter()
            .map(|&i| {
                let r = sub3(s.vertices[i], c);
                [dot3(r, u), dot3(r, v)]
            })
            .collect();
        Some(QFace {
            n,
            o: c,
            u,
            v,
            poly,
        })
    }
    fn height(&self, q: V3) -> f64 {
        dot3(self.n, sub3(q, self.o))
    }
    fn project(&self, q: V3) -> P2 {
        let r = sub3(q, self.o);
        [dot3(r, self.u), dot3(r, self.v)]
    }
    fn lift(&self, p: P2) -> V3 {
        add3(self.o, add3(scale3(self.u, p[0]), scale3(self.v, p[1])))
    }
    /// Distance from `q` to the face (plane distance over the face, else to its boundary).
    fn distance(&self, q: V3) -> f64 {
        let h = self.height(q);
        let p = self.project(q);
        let k = self.poly.len();
        let mut inside = false;
        let mut e = f64::INFINITY;
        for i in 0..k {
            let (a, b) = (self.poly[i], self.poly[(i + 1) % k]);
            e = e.min(point_segment_distance(p, a, b));
            if (a[1] > p[1]) != (b[1] > p[1]) {
                let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if p[0] < x {
                    inside = !inside;
                }
            }
        }
        if inside {
            h.abs()
        } else {
            h.hypot(e)
        }
    }
    /// A point inside the (possibly non-convex) face: its vertex mean if strictly inside,
    /// else the middle of the widest interval of a horizontal line through the mean.
    fn interior_point(&self, tol: f64) -> Option<V3> {
        let k = self.poly.len();
        let c = self.poly.iter().fold([0.0, 0.0], |s, p| {
            [s[0] + p[0] / k as f64, s[1] + p[1] / k as f64]
        });
        if strictly_inside(c, &self.poly, tol) {
            return Some(self.lift(c));
        }
        let mut xs: Vec<f64> = Vec::new();
        for i in 0..k {
            let (a, b) = (self.poly[i], self.poly[(i + 1) % k]);
            if (a[1] > c[1]) != (b[1] > c[1]) {
                xs.push(a[0] + (c[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
            }
        }
        xs.sort_unstable_by(f64::total_cmp);
        let best = xs
            .chunks_exact(2)
            .max_by(|p, q| (p[1] - p[0]).total_cmp(&(q[1] - q[0])))?;
        let p = [(best[0] + best[1]) / 2.0, c[1]];
        strictly_inside(p, &self.poly, tol).then(|| self.lift(p))
    }
}

/// Signed solid angle of triangle `t` seen from `q` (Van Oosterom and Strackee).
fn solid_angle(t: &[V3; 3], q: V3) -> f64 {
    let (a, b, c) = (sub3(t[0], q), sub3(t[1], q), sub3(t[2], q));
    let (la, lb, lc) = (norm3(a), norm3(b), norm3(c));
    let num = dot3(a, cross(b, c));
    let den = la * lb * lc + dot3(a, b) * lc + dot3(a, c) * lb + dot3(b, c) * la;
    2.0 * num.atan2(den)
}

/// Generalised winding number of point `q` with respect to the closed surface `faces` (vertex
/// index lists into `vertices`): 1 inside a counter-clockwise (outward) surface, −1 inside an
/// inward one, 0 outside; faces of fewer than 3 vertices or with indices out of range are
/// skipped.
pub fn winding_number(vertices: &[[f64; 3]], faces: &[Vec<usize>], q: [f64; 3]) -> f64 {
    let mut w = 0.0;
    for f in faces {
        if f.len() < 3 || f.iter().any(|&i| i >= vertices.len()) {
            continue;
        }
        for i in 1..f.len() - 1 {
            w += solid_angle(&[vertices[f[0]], vertices[f[i]], vertices[f[i + 1]]], q);
        }
    }
    w / (4.0 * std::f64::consts::PI)
}

/// A body prepared for the exact overlap test.
struct QBody {
    faces: Vec<QFace>,
    /// Fan triangles of every face, for the winding number.
    tris: Vec<[V3; 3]>,
    /// Edges (each once) as endpoint pairs.
    edges: Vec<(V3, V3)>,
    /// Points of the body: vertices, edge midpoints, face interior points, an interior point.
    probes: Vec<V3>,
    bbox: [V3; 2],
}

impl QBody {
    fn new(s: &Solid, tol: f64) -> QBody {
        let mut faces = Vec::new();
        let mut tris = Vec::new();
        let mut edges = Vec::new();
        let mut probes = Vec::new();
        let mut used = vec![false; s.vertices.len()];
        for f in &s.faces {
            if f.len() < 3 || f.iter().any(|&i| i >= s.vertices.len()) {
                continue;
            }
            for i in 0..f.len() {
                let (p, q) = (f[i], f[(i + 1) % f.len()]);
                used[p] = true;
                if p < q {
                    let (a, b) = (s.vertices[p], s.vertices[q]);
                    edges.push((a, b));
                    probes.push(scale3(add3(a, b), 0.5));
                }
            }
            for i in 1..f.len() - 1 {
                tris.push([s.vertices[f[0]], s.vertices[f[i]], s.vertices[f[i + 1]]]);
            }
            if let Some(q) = QFace::new(s, f) {
                if let Some(p) = q.interior_point(tol) {
                    probes.push(p);
                }
                faces.push(q);
            }
        }
        probes.extend(s.vertices.iter().zip(&used).filter(|x| *x.1).map(|x| *x.0));
        let bbox = bbox3_iter(probes.iter().copied());
        let mut body = QBody {
            faces,
            tris,
            edges,
            probes,
            bbox,
        };
        // An interior point: from a face's interior point inward, halfway to the next face.
        if let Some(f0) = body.faces.first() {
            if let Some(p) = f0.interior_point(tol) {
                let d = scale3(f0.n, -1.0);
                let mut best = f64::INFINITY;
                for g in &body.faces {
                    let dn = dot3(g.n, d);
                    if dn.abs() < 1e-12 {
                        continue;
                    }
                    let t = -g.height(p) / dn;
                    if t > tol && t < best {
                        let x = add3(p, scale3(d, t));
                        if g.distance(x) <= tol {
                            best = t;
                        }
                    }
                }
                if best.is_finite() {
                    body.probes.push(add3(p, scale3(d, 0.5 * best)));
                }
            }
        }
        body
    }

    /// Generalised winding number of `q` (1 inside, 0 outside): the signed solid angles of the
    /// fan triangles (Van Oosterom and Strackee) over 4π.
    fn winding(&self, q: V3) -> f64 {
        self.tris.iter().map(|t| solid_angle(t, q)).sum::<f64>() / (4.0 * std::f64::consts::PI)
    }

    /// Whether `q` lies inside, farther than `tol` from the surface.
    fn strictly_contains(&self, q: V3, tol: f64) -> bool {
        (0..3).all(|k| q[k] > self.bbox[0][k] + tol && q[k] < self.bbox[1][k] - tol)
            && self.faces.iter().all(|f| f.distance(q) > tol)
            && self.winding(q) > 0.5
    }

    /// Whether segment `p`–`q` properly crosses a face: ends on strictly opposite sides, the
    /// crossing strictly inside the face.
    fn is_crossed_by(&self, p: V3, q: V3, tol: f64) -> bool {
        self.faces.iter().any(|f| {
            let (hp, hq) = (f.height(p), f.height(q));
            if !((hp > tol && hq < -tol) || (hp < -tol && hq > tol)) {
                return false;
            }
            let x = add3(p, scale3(sub3(q, p), hp / (hp - hq)));
            strictly_inside(f.project(x), &f.poly, tol)
        })
    }
}

fn bodies_overlap(a: &QBody, b: &QBody, tol: f64) -> bool {
    a.probes.iter().any(|&p| b.strictly_contains(p, tol))
        || b.probes.iter().any(|&p| a.strictly_contains(p, tol))
        || a.edges.iter().any(|&(p, q)| b.is_crossed_by(p, q, tol))
        || b.edges.iter().any(|&(p, q)| a.is_crossed_by(p, q, tol))
}

/// First pair (i, j), i < j, of bodies whose interiors overlap by more than `tol`, skipping
/// pairs for which `skip(i, j)` is true (the caller skips support–support pairs).
///
/// Candidates are the pairs whose bounding boxes overlap by more than `tol` on every axis,
/// found on a uniform grid (cell: the median body extent, so linear for bodies of similar
/// size). Each candidate is tested exactly: a point of one body (vertex, edge midpoint, face
/// interior point, interior point) strictly inside the other (winding number, and farther than
/// `tol` from its surface), or an edge of one properly crossing a face of the other. Bodies
/// that only touch (within `tol`) do not overlap.
pub fn find_overlap3(
    bodies: &[&Solid],
    tol: f64,
    skip: &dyn Fn(usize, usize) -> bool,
) -> Option<(usize, usize)> {
    let n = bodies.len();
    if n < 2 {
        return None;
    }
    let boxes: Vec<[V3; 2]> = bodies.iter().map(|s| bbox3(&s.vertices)).collect();
    let valid = |b: &[V3; 2]| (0..3).all(|k| b[0][k].is_finite() && b[1][k] >= b[0][k]);
    let mut ext: Vec<f64> = boxes
        .iter()
        .filter(|b| valid(b))
        .map(|b| (0..3).map(|k| b[1][k] - b[0][k]).fold(0.0, f64::max))
        .collect();
    if ext.is_empty() {
        return None;
    }
    let mid = ext.len() / 2;
    let (_, &mut median, _) = ext.select_nth_unstable_by(mid, f64::total_cmp);
    let all = bbox3_iter(boxes.iter().filter(|b| valid(b)).flat_map(|b| [b[0], b[1]]));
    let mut hc = median.max(tol).max(f64::MIN_POSITIVE);
    // Keep the number of (cell, body) entries linear: grow the cell while a few huge bodies
    // would cover more than 16 cells per body on average.
    let count = |hc: f64| -> f64 {
        boxes
            .iter()
            .filter(|b| valid(b))
            .map(|b| {
                (0..3)
                    .map(|k| {
                        ((b[1][k] - all[0][k]) / hc).floor() - ((b[0][k] - all[0][k]) / hc).floor()
                            + 1.0
                    })
                    .product::<f64>()
            })
            .sum()
    };
    while count(hc) > 16.0 * n as f64 {
        hc *= 2.0;
    }
    let at = |x: f64, k: usize| ((x - all[0][k]) / hc).floor() as i64;
    let mut entries: Vec<([i64; 3], u32)> = Vec::new();
    for (i, b) in boxes.iter().enumerate() {
        if !valid(b) {
            continue;
        }
        for cx in at(b[0][0], 0)..=at(b[1][0], 0) {
            for cy in at(b[0][1], 1)..=at(b[1][1], 1) {
                for cz in at(b[0][2], 2)..=at(b[1][2], 2) {
                    entries.push(([cx, cy, cz], i as u32));
                }
            }
        }
    }
    entries.sort_unstable();
    let mut cands: Vec<(u32, u32)> = Vec::new();
    let mut i = 0;
    while i < entries.len() {
        let mut j = i + 1;
        while j < entries.len() && entries[j].0 == entries[i].0 {
            j += 1;
        }
        let c = entries[i].0;
        for p in i..j {
            for q in p + 1..j {
                let (bi, bj) = (entries[p].1 as usize, entries[q].1 as usize);
                let (x, y) = (&boxes[bi], &boxes[bj]);
                let lo: V3 = std::array::from_fn(|k| x[0][k].max(y[0][k]));
                let hi: V3 = std::array::from_fn(|k| x[1][k].min(y[1][k]));
                if (0..3).all(|k| hi[k] - lo[k] > tol && at(lo[k], k) == c[k]) {
                    cands.push((bi.min(bj) as u32, bi.max(bj) as u32));
                }
            }
        }
        i = j;
    }
    cands.sort_unstable();
    cands.dedup();
    for (i, j) in cands {
        let (i, j) = (i as usize, j as usize);
        if skip(i, j) {
            continue;
        }
        let (a, b) = (QBody::new(bodies[i], tol), QBody::new(bodies[j], tol));
        if bodies_overlap(&a, &b, tol) {
            return Some((i, j));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cuboid(lo: V3, hi: V3) -> Solid {
        let v = vec![
            [lo[0], lo[1], lo[2]],
            [hi[0], lo[1], lo[2]],
            [hi[0], hi[1], lo[2]],
            [lo[0], hi[1], lo[2]],
            [lo[0], lo[1], hi[2]],
            [hi[0], lo[1], hi[2]],
            [hi[0], hi[1], hi[2]],
            [lo[0], hi[1], hi[2]],
        ];
        let f = vec![
            vec![0, 3, 2, 1],
            vec![4, 5, 6, 7],
            vec![0, 1, 5, 4],
            vec![1, 2, 6, 5],
            vec![2, 3, 7, 6],
            vec![3, 0, 4, 7],
        ];
        clean_polyhedron("box", &v, &f, 1e-9).unwrap()
    }

    #[test]
    fn clean_ring_drops_collinear_and_duplicates() {
        let r = clean_ring(
            &[
                [0.0, 0.0],
                [1.0, 0.0],
                [2.0, 0.0],
                [2.0, 1.0],
                [2.0, 1.0],
                [0.0, 1.0],
                [0.0, 0.5],
            ],
            1e-9,
        );
        assert_eq!(r, vec![[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]);
    }

    #[test]
    fn frame_is_right_handed() {
        for n in [
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
            [0.6, 0.0, 0.8],
            [0.0, -1.0, 0.0],
        ] {
            let (u, v) = plane_frame(n);
            let w = cross(u, v);
            assert!(norm3(sub3(w, n)) < 1e-15, "{n:?}");
            assert!(dot3(u, n).abs() < 1e-15 && dot3(v, n).abs() < 1e-15);
        }
    }

    #[test]
    fn winding_number_of_a_cube() {
        let c = QBody::new(&cuboid([0.0; 3], [1.0; 3]), 1e-9);
        assert!((c.winding([0.3, 0.4, 0.5]) - 1.0).abs() < 1e-12);
        assert!(c.winding([1.3, 0.4, 0.5]).abs() < 1e-12);
        // The interior probe lies halfway through the cube along face 0's inward normal.
        let last = *c.probes.last().unwrap();
        assert!(c.strictly_contains(last, 1e-9));
    }

    #[test]
    fn half_shifted_cubes_overlap() {
        // No vertex of either is strictly inside the other; face interior points are.
        let a = cuboid([0.0; 3], [1.0; 3]);
        let b = cuboid([0.5, 0.0, 0.0], [1.5, 1.0, 1.0]);
        assert_eq!(find_overlap3(&[&a, &b], 1e-9, &|_, _| false), Some((0, 1)));
    }
}
