//! 3D model generators: extruded 2D models, barrel vaults, domes, a box on a base, bonded walls.
//!
//! Conventions (those of [`crate::model3d`]): z up, gravity along −z, faces counter-clockwise
//! seen from outside. Every face a generator writes is exactly planar (rectangles, prisms of
//! planar polygons, symmetric trapezoids of a dome) and oriented outward; neighbouring blocks
//! share their vertices bit for bit, so their faces coincide exactly. See `docs/generators3d.md`.
//!
//! ## Extrusion of a 2D model
//! The 2D plane (x, y) becomes the vertical plane (x, z) — 3D `x` = 2D `x`, 3D `z` = 2D `y` —
//! and every polygon is extruded along +y, from y = 0 to y = `depth`, in `rings` rings of equal
//! depth. Block `i` of ring `r` is 3D block `r·n + i` (`n` the number of 2D blocks). Its faces
//! are numbered: 0 the front face (y = ring start), 1 the back face, `2 + k` the face swept by
//! edge `k` of the counter-clockwise 2D polygon.
//!
//! **Loads.** A 2D model describes a slice of thickness `width` (its material's): its weights
//! are γ·A·width and its loads are totals on that width. The 3D model is scaled so that its
//! load *per metre of depth* equals the 2D model's load *per metre of width*; dead and live
//! loads then keep their ratio and the load multiplier λ of the extruded model is that of the
//! 2D one (for a mechanism that does not vary along y):
//! * self-weight → self-weight (γ·volume = γ·A per metre of depth);
//! * a point load `[fx, fy]` at `[x, y]` on block `i` → on each ring's copy of `i`, a point load
//!   `(d_r / w_i)·[fx, 0, fy]` at `[x, middle of the ring, y]`, with `d_r` the ring's depth and
//!   `w_i` the 2D width of block `i`'s material;
//! * an edge load `q` on edge `k` → a face load of the same `q` on face `2 + k` (per horizontal
//!   projection stays per horizontal projection, per length becomes per area): `q·ℓ·d_r` in 3D
//!   against `q·ℓ·w_i` in 2D;
//! * a body load `[cx, cy]` → a body load `[cx, 0, cy]` on every ring's copies of its blocks.
//!
//! Supports are extruded once over the full depth, with their name and connection; a 2D
//! motion `[u, v, θ]` becomes `[u, 0, v, 0, −θ, 0]`: a counter-clockwise rotation θ in the 2D
//! plane (x, y) is, with z = y, a rotation of −θ about +y (the 3D rotation vector is
//! right-handed, and +y points *into* the (x, z) picture seen with x right and z up).

use crate::error::{Error, Result};
use crate::generate::{self, ArchSpec, LiveLoad, RadiusAt};
use crate::geometry::signed_area;
use crate::model::{Connection, Load, Material, Model, Per, Point};
use crate::model3d::{Block3d, Load3d, Loads3d, Model3d, PerArea, Point3, Support3d};
use crate::vector::{self, add3, cross, dot3, scale3, sub3};
use std::collections::BTreeMap;
use std::f64::consts::PI;

/// The most blocks a generator makes (a guard against a mistyped count).
pub const MAX_BLOCKS: usize = 1_000_000;

fn req(ok: bool, msg: &str) -> Result<()> {
    if ok {
        Ok(())
    } else {
        Err(Error::Request(msg.to_string()))
    }
}

fn count_ok(what: &str, n: Option<usize>) -> Result<usize> {
    match n {
        Some(n) if n <= MAX_BLOCKS => Ok(n),
        _ => Err(Error::Request(format!(
            "{what} would have more than {MAX_BLOCKS} blocks"
        ))),
    }
}

/// How the rings of an extruded model are bonded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Bond {
    /// Every ring is the same 2D model: joints run straight through the depth.
    #[default]
    Stack,
    /// Alternate rings are staggered by half a block (vault: odd rings are the arch with its
    /// joints shifted by half a voussoir, half-voussoirs at the springings).
    Running,
}

// ---------------------------------------------------------------------------------------------
// Small vector algebra and a polyhedron builder that orients each face outward.

fn unit3(a: Point3) -> Point3 {
    let l = dot3(a, a).sqrt();
    scale3(a, 1.0 / l)
}
fn mean3(ps: &[Point3]) -> Point3 {
    vector::mean3(ps.len(), |i| ps[i])
}

/// Newell's normal of a planar polygon (length twice its area).
fn newell(ps: &[Point3]) -> Point3 {
    vector::newell(ps.len(), |i| ps[i])
}

#[derive(Default)]
struct Poly {
    v: Vec<Point3>,
    f: Vec<Vec<usize>>,
}

impl Poly {
    /// Add face `idx`, turned round if its normal does not point along `outward`.
    fn face(&mut self, mut idx: Vec<usize>, outward: Point3) {
        let pts: Vec<Point3> = idx.iter().map(|&i| self.v[i]).collect();
        if dot3(newell(&pts), outward) < 0.0 {
            idx.reverse();
        }
        self.f.push(idx);
    }
    fn block(self) -> Block3d {
        Block3d {
            vertices: self.v,
            faces: self.f,
            material: None,
        }
    }
    fn support(self, name: &str) -> Support3d {
        Support3d {
            name: name.to_string(),
            vertices: self.v,
            faces: self.f,
            motion: [0.0; 6],
            connection: Connection::Contact,
        }
    }
}

/// The box `[x0, x1] × [y0, y1] × [z0, z1]`.
fn cuboid([x0, x1]: [f64; 2], [y0, y1]: [f64; 2], [z0, z1]: [f64; 2]) -> Poly {
    let mut p = Poly::default();
    for z in [z0, z1] {
        p.v.extend([[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]]);
    }
    p.face(vec![0, 1, 2, 3], [0.0, 0.0, -1.0]);
    p.face(vec![4, 5, 6, 7], [0.0, 0.0, 1.0]);
    p.face(vec![0, 1, 5, 4], [0.0, -1.0, 0.0]);
    p.face(vec![1, 2, 6, 5], [1.0, 0.0, 0.0]);
    p.face(vec![2, 3, 7, 6], [0.0, 1.0, 0.0]);
    p.face(vec![3, 0, 4, 7], [-1.0, 0.0, 0.0]);
    p
}

fn materials(unit_weight: f64) -> BTreeMap<String, Material> {
    let mut m = BTreeMap::new();
    m.insert(
        "default".to_string(),
        Material {
            unit_weight,
            ..Material::default()
        },
    );
    m
}

// ---------------------------------------------------------------------------------------------
// Extrusion.

/// A 2D polygon made ready for extrusion: counter-clockwise, without a closing duplicate, and
/// the map from the given edge numbers to the oriented polygon's (None: a zero-length edge).
struct Section {
    poly: Vec<Point>,
    edge: Vec<Option<usize>>,
}

fn section(what: &str, given: &[Point]) -> Result<Section> {
    if given.iter().any(|p| !p[0].is_finite() || !p[1].is_finite()) {
        return Err(Error::Model(format!(
            "{what}: a coordinate is not a finite number"
        )));
    }
    let mut q: Vec<Point> = given.to_vec();
    while q.len() > 3 && q[q.len() - 1] == q[0] {
        q.pop();
    }
    let n = q.len();
    if n < 3 {
        return Err(Error::Model(format!(
            "{what}: a polygon needs at least 3 vertices"
        )));
    }
    if (0..n).any(|i| q[i] == q[(i + 1) % n]) {
        return Err(Error::Model(format!(
            "{what}: two consecutive vertices coincide"
        )));
    }
    let a = signed_area(&q);
    if a == 0.0 || !a.is_finite() {
        return Err(Error::Model(format!("{what}: the polygon has no area")));
    }
    let reversed = a < 0.0;
    if reversed {
        q.reverse();
    }
    let edge = (0..given.len())
        .map(|k| (k < n).then(|| if reversed { (2 * n - 2 - k) % n } else { k }))
        .collect();
    Ok(Section { poly: q, edge })
}

/// The prism swept by the counter-clockwise polygon `p` of the (x, z) plane from y0 to y1:
/// face 0 at y0, face 1 at y1, face 2 + k swept by edge k.
fn prism(p: &[Point], y0: f64, y1: f64) -> Poly {
    let n = p.len();
    let mut out = Poly::default();
    out.v.extend(p.iter().map(|q| [q[0], y0, q[1]]));
    out.v.extend(p.iter().map(|q| [q[0], y1, q[1]]));
    out.face((0..n).collect(), [0.0, -1.0, 0.0]);
    out.face((n..2 * n).rev().collect(), [0.0, 1.0, 0.0]);
    for k in 0..n {
        let k1 = (k + 1) % n;
        let (a, b) = (p[k], p[k1]);
        // Outward normal of a counter-clockwise polygon's edge: (dy, −dx) in 2D.
        let outward = [b[1] - a[1], 0.0, -(b[0] - a[0])];
        out.face(vec![k, n + k, n + k1, k1], outward);
    }
    out
}

fn ring_bounds(depth: f64, rings: usize) -> Vec<f64> {
    (0..=rings)
        .map(|r| {
            if r == rings {
                depth
            } else {
                depth * r as f64 / rings as f64
            }
        })
        .collect()
}

/// Extrude ring `r` of the result from `ring_models[r]`; supports, materials, tolerance and the
/// self-weight flag come from the first.
fn extrude_rings(ring_models: &[&Model], depth: f64, description: String) -> Result<Model3d> {
    req(
        depth.is_finite() && depth > 0.0,
        "depth must be a positive number of metres",
    )?;
    req(!ring_models.is_empty(), "rings must be at least 1")?;
    let first = ring_models[0];
    if first.supports.is_empty() {
        return Err(Error::Model(
            "the 2D model has no supports: at least one foundation is needed".into(),
        ));
    }
    let total = ring_models
        .iter()
        .try_fold(0usize, |acc, m| acc.checked_add(m.blocks.len()));
    count_ok("the extruded model", total)?;
    let ys = ring_bounds(depth, ring_models.len());
    let mut blocks = Vec::new();
    let mut dead = Vec::new();
    let mut live = Vec::new();
    // Body loads, merged over the rings: (live, k-th body load of a ring) → coefficients, blocks.
    let mut bodies: Vec<((bool, usize), Point3, Vec<usize>)> = Vec::new();
    for (r, m) in ring_models.iter().enumerate() {
        let (y0, y1) = (ys[r], ys[r + 1]);
        let offset = blocks.len();
        let nb = m.blocks.len();
        let mut sections = Vec::with_capacity(nb);
        for (i, b) in m.blocks.iter().enumerate() {
            let s = section(&format!("block {i}"), &b.polygon)?;
            let mut blk = prism(&s.poly, y0, y1).block();
            blk.material = b.material.clone();
            blocks.push(blk);
            sections.push(s);
        }
        for (is_live, list) in [(false, &m.loads.dead), (true, &m.loads.live)] {
            let kind = if is_live { "live" } else { "dead" };
            let mut kth_body = 0;
            for (l, load) in list.iter().enumerate() {
                let what = format!("{kind} load {l}");
                let check = |b: usize| {
                    if b < nb {
                        Ok(())
                    } else {
                        Err(Error::Model(format!(
                            "{what}: block {b} does not exist (the model has {nb} blocks)"
                        )))
                    }
                };
                let out = if is_live { &mut live } else { &mut dead };
                match load {
                    Load::Point { block, at, force } => {
                        check(*block)?;
                        let w = m.material_of(*block).width;
                        req(
                            w.is_finite() && w > 0.0,
                            "a material's width must be positive",
                        )?;
                        let s = (y1 - y0) / w;
                        out.push(Load3d::Point {
                            block: offset + block,
                            at: [at[0], (y0 + y1) / 2.0, at[1]],
                            force: [force[0] * s, 0.0, force[1] * s],
                            moment: [0.0; 3],
                        });
                    }
                    Load::Edge {
                        block,
                        edge,
                        q,
                        per,
                    } => {
                        check(*block)?;
                        let Some(e) = sections[*block].edge.get(*edge) else {
                            return Err(Error::Model(format!(
                                "{what}: block {block} has no edge {edge}"
                            )));
                        };
                        if let Some(e) = e {
                            out.push(Load3d::Face {
                                block: offset + block,
                                face: 2 + e,
                                q: *q,
                                per: match per {
                                    Per::Horizontal => PerArea::Horizontal,
                                    Per::Length => PerArea::Area,
                                },
                            });
                        }
                    }
                    Load::Body {
                        coefficients,
                        blocks: which,
                    } => {
                        let list: Vec<usize> = match which {
                            Some(v) => {
                                for &b in v {
                                    check(b)?;
                                }
                                v.iter().map(|b| offset + b).collect()
                            }
                            None => (offset..offset + nb).collect(),
                        };
                        let c = [coefficients[0], 0.0, coefficients[1]];
                        let key = (is_live, kth_body);
                        kth_body += 1;
                        match bodies.iter_mut().find(|b| b.0 == key && b.1 == c) {
                            Some(b) => b.2.extend(list),
                            None => bodies.push((key, c, list)),
                        }
                    }
                }
            }
        }
    }
    let nb_total = blocks.len();
    for (key, c, mut list) in bodies {
        // Sorted, not deduplicated: a block listed twice in 2D is loaded twice there too.
        list.sort_unstable();
        let which = (list.len() != nb_total || (0..nb_total).any(|i| list[i] != i)).then_some(list);
        let load = Load3d::Body {
            coefficients: c,
            blocks: which,
        };
        if key.0 {
            live.push(load);
        } else {
            dead.push(load);
        }
    }
    let mut supports = Vec::with_capacity(first.supports.len());
    for s in &first.supports {
        let sec = section(&format!("support '{}'", s.name), &s.polygon)?;
        let mut sup = prism(&sec.poly, 0.0, depth).support(&s.name);
        let [u, v, t] = s.motion;
        sup.motion = [u, 0.0, v, 0.0, -t, 0.0];
        sup.connection = s.connection;
        supports.push(sup);
    }
    Ok(Model3d {
        description,
        materials: first.materials.clone(),
        blocks,
        supports,
        loads: Loads3d {
            self_weight: first.loads.self_weight,
            dead,
            live,
        },
        tolerance: first.tolerance,
    })
}

/// Extrude a 2D model along +y over `depth` m in `rings` rings (see the module's notes for the
/// mapping of geometry, loads and support motions). Only [`Bond::Stack`] is possible for an
/// arbitrary model; a running bond needs the generator's geometry ([`vault`]).
pub fn extrude(model: &Model, depth: f64, rings: usize, bond: Bond) -> Result<Model3d> {
    req(rings >= 1, "rings must be at least 1")?;
    req(
        rings <= MAX_BLOCKS,
        &format!("rings must be at most {MAX_BLOCKS}"),
    )?;
    req(
        bond == Bond::Stack,
        "extrude: a running bond needs the generator's own geometry (use `gen vault --bond running`); an arbitrary 2D model extrudes with --bond stack",
    )?;
    count_ok("the extruded model", model.blocks.len().checked_mul(rings))?;
    let rs = vec![model; rings];
    let what = if model.description.is_empty() {
        "2D model".to_string()
    } else {
        model.description.clone()
    };
    extrude_rings(
        &rs,
        depth,
        format!("{what}; extruded over {depth} m in {rings} ring(s), stack bond"),
    )
}

// ---------------------------------------------------------------------------------------------
// Barrel vault.

/// Index of the edge of `p` from `a` to `b` or from `b` to `a`.
fn edge_of(p: &[Point], a: Point, b: Point) -> usize {
    let n = p.len();
    (0..n)
        .find(|&i| {
            let (x, y) = (p[i], p[(i + 1) % n]);
            (x == a && y == b) || (x == b && y == a)
        })
        .unwrap_or(0)
}

/// The 2D arch of `s` with its joints shifted by half a voussoir: half-voussoirs at the
/// springings, `voussoirs − 1` whole ones between (joints of the arch with twice as many
/// voussoirs: 0, 1, 3, …, 2n − 1, 2n). Supports and materials are those of `plain`. Live loads
/// as the arch's; a block across the crown under a left/right load carries the load of the part
/// of its extrados on that side, as a point load.
fn shifted_arch(s: &ArchSpec, plain: &Model) -> Result<Model> {
    let n = s.voussoirs;
    let twice = ArchSpec {
        voussoirs: n
            .checked_mul(2)
            .ok_or_else(|| Error::Request("too many voussoirs".into()))?,
        ..s.clone()
    };
    let (j2, _) = generate::arch_joints(&twice)?;
    let mut joints = vec![j2[0]];
    joints.extend((1..2 * n).step_by(2).map(|k| j2[k]));
    joints.push(j2[2 * n]);
    let mut blocks = Vec::with_capacity(n + 1);
    let mut live = Vec::new();
    for (k, w) in joints.windows(2).enumerate() {
        let ((i0, e0), (i1, e1)) = (w[0], w[1]);
        let mut poly = vec![i0, i1, e1, e0];
        if signed_area(&poly) < 0.0 {
            poly.reverse();
        }
        let edge = edge_of(&poly, e0, e1);
        let whole = |live: &mut Vec<Load>| {
            live.push(Load::Edge {
                block: k,
                edge,
                q: s.live_load,
                per: Per::Horizontal,
            })
        };
        // The part of the extrados chord e0–e1 (e0 left of e1) on one side of x = 0.
        let part = |live: &mut Vec<Load>, left: bool| {
            let t = -e0[0] / (e1[0] - e0[0]);
            let mid = [0.0, e0[1] + t * (e1[1] - e0[1])];
            let (a, b) = if left { (e0, mid) } else { (mid, e1) };
            live.push(Load::Point {
                block: k,
                at: [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0],
                force: [0.0, -s.live_load * (b[0] - a[0]) * s.width],
            });
        };
        if s.live_load != 0.0 {
            let across = e0[0] < 0.0 && e1[0] > 0.0;
            match s.live {
                LiveLoad::Full => whole(&mut live),
                LiveLoad::Left if across => part(&mut live, true),
                LiveLoad::Right if across => part(&mut live, false),
                LiveLoad::Left if e1[0] <= 0.0 => whole(&mut live),
                LiveLoad::Right if e0[0] >= 0.0 => whole(&mut live),
                _ => {}
            }
        }
        blocks.push(crate::model::Block {
            polygon: poly,
            material: None,
        });
    }
    let mut loads = plain.loads.clone();
    loads.live = live;
    loads.live.extend(
        plain
            .loads
            .live
            .iter()
            .filter(|l| matches!(l, Load::Body { .. }))
            .cloned(),
    );
    Ok(Model {
        description: format!("{} (joints shifted by half a voussoir)", plain.description),
        materials: plain.materials.clone(),
        blocks,
        supports: plain.supports.clone(),
        loads,
        tolerance: plain.tolerance,
        cracks: Vec::new(),
    })
}

/// A barrel vault: the 2D arch of `spec` (every arch option; supports `left` and `right`)
/// extruded along +y over `depth` m in `rings` rings. [`Bond::Stack`]: every ring is the arch
/// ([`extrude`]). [`Bond::Running`]: even rings (0, 2, …) are the arch, odd rings the arch with
/// its joints shifted by half a voussoir (half-voussoirs at the springings, `voussoirs + 1`
/// blocks). `spec.width` has no effect (the depth is `depth`).
pub fn vault(spec: &ArchSpec, depth: f64, rings: usize, bond: Bond) -> Result<Model3d> {
    req(rings >= 1, "rings must be at least 1")?;
    req(
        depth.is_finite() && depth > 0.0,
        "depth must be a positive number of metres",
    )?;
    count_ok(
        "the vault",
        (spec.voussoirs.saturating_add(1)).checked_mul(rings),
    )?;
    let plain = generate::arch(spec)?;
    let describe = |b: &str| {
        format!(
            "barrel vault: {}; depth {depth} m in {rings} ring(s), {b} bond",
            plain.description
        )
    };
    match bond {
        Bond::Stack => extrude_rings(&vec![&plain; rings], depth, describe("stack")),
        Bond::Running => {
            let shifted = shifted_arch(spec, &plain)?;
            let rs: Vec<&Model> = (0..rings)
                .map(|r| if r % 2 == 0 { &plain } else { &shifted })
                .collect();
            extrude_rings(&rs, depth, describe("running"))
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Dome.

/// Parameters of `gen dome`.
#[derive(Clone, Debug)]
pub struct DomeSpec {
    /// Radius in m, measured where `radius_at` says (default: intrados).
    pub radius: f64,
    pub radius_at: RadiusAt,
    pub thickness: f64,
    /// Courses from the springing to the crown; without an oculus the last is the cap (one block).
    pub courses: usize,
    /// Blocks per course (meridian divisions).
    pub segments: usize,
    /// Springing half-angle from the vertical axis, radians (π/2: hemisphere).
    pub half_angle: f64,
    /// Oculus half-angle from the vertical axis, radians (None: closed by a cap).
    pub oculus: Option<f64>,
    pub unit_weight: f64,
    /// Live vertical load at the crown, kN, downwards (0: no live load). With an oculus, shared
    /// equally by the top course's blocks.
    pub crown_load: f64,
}

impl Default for DomeSpec {
    fn default() -> Self {
        DomeSpec {
            radius: 5.0,
            radius_at: RadiusAt::Intrados,
            thickness: 0.3,
            courses: 8,
            segments: 16,
            half_angle: PI / 2.0,
            oculus: None,
            unit_weight: 18.0,
            crown_load: 0.0,
        }
    }
}

/// (sin, cos) with the exact values at 0 and π/2 (a hemisphere's springing bed is exactly level).
fn sin_cos(a: f64) -> (f64, f64) {
    if a == 0.0 {
        (0.0, 1.0)
    } else if a == PI / 2.0 {
        (1.0, 0.0)
    } else {
        a.sin_cos()
    }
}

/// A dome of revolution about the z axis, centre of the sphere at the origin: `courses` rings
/// of `segments` blocks bounded by cones of latitude (polar angle ψ from +z, equal steps from
/// the springing `half_angle` to the crown) and by meridian planes (θ = 2πj/segments from +x).
/// Each block's corners lie on the intrados and extrados spheres; its faces are planar: the
/// inner and outer faces and the beds are symmetric trapezoids, the beds and the sides lie in
/// planes through the centre. Without an oculus the top course is one cap block (pyramidal
/// inner and outer faces to the poles). Supports `base0` … `base{segments−1}`: under each
/// block of the first course, a prism whose top face is that block's bottom bed face, extruded
/// away from it by max(thickness, 0.1·intrados radius). Blocks are numbered course by course
/// from the springing, segment by segment from θ = 0.
pub fn dome(s: &DomeSpec) -> Result<Model3d> {
    req(
        s.radius.is_finite() && s.radius > 0.0,
        "dome radius must be positive",
    )?;
    req(
        s.thickness.is_finite() && s.thickness > 0.0,
        "dome thickness must be positive",
    )?;
    req(s.courses >= 1, "a dome needs at least 1 course")?;
    req(s.segments >= 3, "a dome needs at least 3 segments")?;
    req(
        s.half_angle.is_finite() && s.half_angle > 0.0 && s.half_angle <= PI / 2.0,
        "dome half-angle must be in (0°, 90°]",
    )?;
    if let Some(o) = s.oculus {
        req(
            o.is_finite() && o > 0.0 && o < s.half_angle,
            "oculus half-angle must be in (0°, springing half-angle)",
        )?;
    }
    req(
        s.unit_weight.is_finite() && s.unit_weight >= 0.0,
        "unit weight must be ≥ 0",
    )?;
    req(
        s.crown_load.is_finite(),
        "crown load must be a finite number",
    )?;
    let ri = match s.radius_at {
        RadiusAt::Intrados => s.radius,
        RadiusAt::Centreline => s.radius - s.thickness / 2.0,
        RadiusAt::Extrados => s.radius - s.thickness,
    };
    req(ri > 0.0, "the thickness is larger than the radius allows")?;
    let re = ri + s.thickness;
    let (nc, n) = (s.courses, s.segments);
    count_ok("the dome", nc.checked_mul(n))?;
    let top = s.oculus.unwrap_or(0.0);
    let cap = s.oculus.is_none();
    // Latitudes ψ_k, k = 0 (springing) … nc (crown or oculus).
    let psi: Vec<f64> = (0..=nc)
        .map(|k| {
            if k == 0 {
                s.half_angle
            } else if k == nc {
                top
            } else {
                s.half_angle - (s.half_angle - top) * k as f64 / nc as f64
            }
        })
        .collect();
    let sc_psi: Vec<(f64, f64)> = psi.iter().map(|&a| sin_cos(a)).collect();
    let theta: Vec<f64> = (0..n).map(|j| 2.0 * PI * j as f64 / n as f64).collect();
    let sc_theta: Vec<(f64, f64)> = theta.iter().map(|&t| t.sin_cos()).collect();
    let dir = |k: usize, j: usize| -> Point3 {
        let ((sp, cp), (st, ct)) = (sc_psi[k], sc_theta[j % n]);
        [sp * ct, sp * st, cp]
    };
    let at = |r: f64, k: usize, j: usize| scale3(dir(k, j), r);
    // Directions at the middle of a block: radial, increasing ψ, increasing θ.
    let mid = |ka: f64, kb: f64, j: usize| {
        let p = (ka + kb) / 2.0;
        let t = 2.0 * PI * (j as f64 + 0.5) / n as f64;
        (
            [p.sin() * t.cos(), p.sin() * t.sin(), p.cos()],
            [p.cos() * t.cos(), p.cos() * t.sin(), -p.sin()],
        )
    };
    let t_theta = |j: usize| {
        let (st, ct) = sc_theta[j % n];
        [-st, ct, 0.0]
    };
    let mut blocks = Vec::new();
    let rings = if cap { nc - 1 } else { nc };
    for k in 0..rings {
        for j in 0..n {
            let j1 = (j + 1) % n;
            let mut p = Poly::default();
            p.v.extend([
                at(ri, k, j),
                at(ri, k, j1),
                at(ri, k + 1, j1),
                at(ri, k + 1, j),
                at(re, k, j),
                at(re, k, j1),
                at(re, k + 1, j1),
                at(re, k + 1, j),
            ]);
            let (radial, down) = mid(psi[k], psi[k + 1], j);
            p.face(vec![0, 1, 2, 3], scale3(radial, -1.0));
            p.face(vec![4, 5, 6, 7], radial);
            p.face(vec![0, 1, 5, 4], down);
            p.face(vec![3, 2, 6, 7], scale3(down, -1.0));
            p.face(vec![0, 3, 7, 4], scale3(t_theta(j), -1.0));
            p.face(vec![1, 2, 6, 5], t_theta(j1));
            blocks.push(p.block());
        }
    }
    if cap {
        let k = nc - 1;
        let mut p = Poly::default();
        p.v.extend((0..n).map(|j| at(ri, k, j)));
        p.v.extend((0..n).map(|j| at(re, k, j)));
        p.v.push([0.0, 0.0, ri]);
        p.v.push([0.0, 0.0, re]);
        for j in 0..n {
            let j1 = (j + 1) % n;
            let (radial, down) = mid(psi[k], psi[k + 1], j);
            p.face(vec![2 * n, j, j1], scale3(radial, -1.0));
            p.face(vec![2 * n + 1, n + j, n + j1], radial);
            p.face(vec![j, j1, n + j1, n + j], down);
        }
        blocks.push(p.block());
    }
    // Supports under the first course's bottom bed faces.
    let depth = s.thickness.max(0.1 * ri);
    let mut supports = Vec::with_capacity(n);
    for j in 0..n {
        let j1 = (j + 1) % n;
        let top_face = [at(ri, 0, j), at(ri, 0, j1), at(re, 0, j1), at(re, 0, j)];
        let (_, down) = mid(psi[0], psi[1], j);
        let mut nrm = unit3(cross(dir(0, j), dir(0, j1)));
        if dot3(nrm, down) < 0.0 {
            nrm = scale3(nrm, -1.0);
        }
        let mut p = Poly::default();
        p.v.extend(top_face);
        p.v.extend(top_face.iter().map(|&q| add3(q, scale3(nrm, depth))));
        p.face(vec![0, 1, 2, 3], scale3(nrm, -1.0));
        p.face(vec![4, 5, 6, 7], nrm);
        let c = mean3(&top_face);
        for e in 0..4 {
            let e1 = (e + 1) % 4;
            let out = sub3(mean3(&[top_face[e], top_face[e1]]), c);
            p.face(vec![e, e1, 4 + e1, 4 + e], out);
        }
        supports.push(p.support(&format!("base{j}")));
    }
    let mut live = Vec::new();
    if s.crown_load != 0.0 {
        if cap {
            live.push(Load3d::Point {
                block: blocks.len() - 1,
                at: [0.0, 0.0, re],
                force: [0.0, 0.0, -s.crown_load],
                moment: [0.0; 3],
            });
        } else {
            let k = nc - 1;
            for j in 0..n {
                let j1 = (j + 1) % n;
                let c = mean3(&[
                    at(ri, k + 1, j),
                    at(ri, k + 1, j1),
                    at(re, k + 1, j1),
                    at(re, k + 1, j),
                ]);
                live.push(Load3d::Point {
                    block: k * n + j,
                    at: c,
                    force: [0.0, 0.0, -s.crown_load / n as f64],
                    moment: [0.0; 3],
                });
            }
        }
    }
    let shape = if s.half_angle == PI / 2.0 {
        "hemispherical".to_string()
    } else {
        format!(
            "segmental ({}° springing half-angle)",
            s.half_angle.to_degrees()
        )
    };
    let crown = match s.oculus {
        Some(o) => format!("oculus of {}° half-angle", o.to_degrees()),
        None => "closed by a cap".to_string(),
    };
    Ok(Model3d {
        description: format!(
            "{shape} dome, intrados radius {ri} m, thickness {} m, {nc} courses of {n} segments, {crown}, γ = {} kN/m³, crown load {} kN",
            s.thickness, s.unit_weight, s.crown_load
        ),
        materials: materials(s.unit_weight),
        blocks,
        supports,
        loads: Loads3d {
            self_weight: true,
            dead: vec![],
            live,
        },
        tolerance: None,
    })
}

// ---------------------------------------------------------------------------------------------
// One block on a base.

/// (cos, sin) of an angle in degrees, exact at multiples of 90°.
fn cos_sin_deg(a: f64) -> (f64, f64) {
    let r = a.rem_euclid(360.0);
    if r == 0.0 {
        (1.0, 0.0)
    } else if r == 90.0 {
        (0.0, 1.0)
    } else if r == 180.0 {
        (-1.0, 0.0)
    } else if r == 270.0 {
        (0.0, -1.0)
    } else {
        let (s, c) = a.to_radians().sin_cos();
        (c, s)
    }
}

/// One box `b × d × h` (along x, y, z), `[−b/2, b/2] × [−d/2, d/2] × [0, h]`, on a support
/// `base`: a slab `[−b/2 − m, b/2 + m] × [−d/2 − m, d/2 + m] × [−t, 0]` with m = max(b, d)/2
/// and t = min(b, d, h)/2. Live load: a horizontal body force equal to the box's weight along
/// azimuth `azimuth_deg` (from +x towards +y): coefficients `[cos a, sin a, 0]`.
pub fn block(size: [f64; 3], azimuth_deg: f64, unit_weight: f64) -> Result<Model3d> {
    let [b, d, h] = size;
    req(
        size.iter().all(|x| x.is_finite() && *x > 0.0),
        "block size b,d,h must be three positive numbers of metres",
    )?;
    req(azimuth_deg.is_finite(), "azimuth must be a finite number")?;
    req(
        unit_weight.is_finite() && unit_weight >= 0.0,
        "unit weight must be ≥ 0",
    )?;
    let (c, s) = cos_sin_deg(azimuth_deg);
    let m = b.max(d) / 2.0;
    let t = b.min(d).min(h) / 2.0;
    let bx = cuboid([-b / 2.0, b / 2.0], [-d / 2.0, d / 2.0], [0.0, h]);
    let base = cuboid(
        [-b / 2.0 - m, b / 2.0 + m],
        [-d / 2.0 - m, d / 2.0 + m],
        [-t, 0.0],
    );
    Ok(Model3d {
        description: format!(
            "box {b} × {d} × {h} m on a base, horizontal live load equal to its weight along azimuth {azimuth_deg}°"
        ),
        materials: materials(unit_weight),
        blocks: vec![bx.block()],
        supports: vec![base.support("base")],
        loads: Loads3d {
            self_weight: true,
            dead: vec![],
            live: vec![Load3d::Body {
                coefficients: [c, s, 0.0],
                blocks: None,
            }],
        },
        tolerance: None,
    })
}

// ---------------------------------------------------------------------------------------------
// Walls.

/// Plan of `gen walls`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Plan {
    /// A free-standing straight wall.
    #[default]
    I,
    /// The main wall and a return at its left end (x = 0).
    L,
    /// The main wall and returns at both ends.
    U,
}

/// Which blocks carry the live load of `gen walls`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum WallsLive {
    None,
    /// The main wall's blocks (out of plane, +y).
    #[default]
    Main,
    /// Every block.
    All,
}

/// Parameters of `gen walls`.
#[derive(Clone, Debug)]
pub struct WallsSpec {
    pub plan: Plan,
    /// Length of the main wall along x, m (outer dimension, corners included).
    pub length: f64,
    /// Length of each return along y, m, from the main wall's outer face y = 0 (corner
    /// included).
    pub return_length: f64,
    pub height: f64,
    /// Wall thickness (one brick), m.
    pub thickness: f64,
    pub courses: usize,
    /// Bricks per course along the main wall (brick length = length / units).
    pub units: usize,
    pub unit_weight: f64,
    pub live: WallsLive,
}

impl Default for WallsSpec {
    fn default() -> Self {
        WallsSpec {
            plan: Plan::I,
            length: 2.0,
            return_length: 1.0,
            height: 1.2,
            thickness: 0.2,
            courses: 6,
            units: 5,
            unit_weight: 18.0,
            live: WallsLive::Main,
        }
    }
}

/// Bricks of length `l` laid from `start` to `end` with head joints at `origin + k·l`; a first
/// or last piece shorter than l/4 is merged into its neighbour.
fn lay(start: f64, end: f64, origin: f64, l: f64) -> Vec<[f64; 2]> {
    let eps = 1e-9 * l;
    let mut xs = vec![start];
    let k0 = ((start - origin) / l).floor() as i64;
    let mut k = k0;
    loop {
        let x = origin + k as f64 * l;
        if x >= end - eps {
            break;
        }
        if x > start + eps {
            xs.push(x);
        }
        k += 1;
    }
    xs.push(end);
    if xs.len() > 2 && xs[1] - xs[0] < l / 4.0 {
        xs.remove(1);
    }
    let m = xs.len();
    if m > 2 && xs[m - 1] - xs[m - 2] < l / 4.0 {
        xs.remove(m - 2);
    }
    xs.windows(2).map(|w| [w[0], w[1]]).collect()
}

/// Brick walls one brick thick in running bond on one support `ground`. The main wall runs
/// along x over `[0, length] × [0, thickness]`; returns (plans L and U) run along +y over
/// `[0, thickness] × [0, return_length]` (left) and `[length − thickness, length] ×
/// [0, return_length]` (right). Courses (height/courses each) alternate: even courses (0, 2, …)
/// have the main wall running through the corners, head joints at `k·ℓ` from x = 0, and the
/// returns butting against it from y = thickness with joints at `thickness + k·ℓ`; odd courses
/// have the returns running through (joints at `k·ℓ` from y = 0) and the main wall butting
/// against them, joints at `thickness + k·ℓ`. The I wall's odd courses are shifted by half a
/// brick (half bricks at the ends). ℓ = length/units; a piece shorter than ℓ/4 at the end of a
/// course is merged into its neighbour. Blocks are numbered course by course from the bottom:
/// main wall (x increasing), left return, right return (y increasing). `ground` is a slab
/// `[−t, length + t] × [−t, y_max + t] × [−h_course, 0]`.
pub fn walls(s: &WallsSpec) -> Result<Model3d> {
    for (v, name) in [
        (s.length, "length"),
        (s.height, "height"),
        (s.thickness, "thickness"),
    ] {
        req(
            v.is_finite() && v > 0.0,
            &format!("walls: {name} must be a positive number of metres"),
        )?;
    }
    req(
        s.courses >= 1 && s.units >= 1,
        "walls need at least one course and one unit per course",
    )?;
    req(
        s.unit_weight.is_finite() && s.unit_weight >= 0.0,
        "unit weight must be ≥ 0",
    )?;
    let (l, t, big_l, r) = (
        s.length / s.units as f64,
        s.thickness,
        s.length,
        s.return_length,
    );
    if s.plan != Plan::I {
        req(
            r.is_finite() && r > t,
            "walls: the return length must be larger than the thickness",
        )?;
        let min = if s.plan == Plan::U { 2.0 * t } else { t };
        req(
            big_l > min,
            "walls: the main wall is too short for its returns (length ≤ thickness per return)",
        )?;
    } else {
        req(
            t < big_l,
            "walls: the thickness must be smaller than the length",
        )?;
    }
    // Bricks per course at most: units + 2 along the main wall, r/ℓ + 3 per return.
    let returns = match s.plan {
        Plan::I => 0.0,
        Plan::L => 1.0,
        Plan::U => 2.0,
    };
    let estimate = s.courses as f64 * (s.units as f64 + 2.0 + returns * (r / l + 3.0));
    req(
        estimate <= MAX_BLOCKS as f64,
        &format!("the walls would have more than {MAX_BLOCKS} blocks"),
    )?;
    let hc = s.height / s.courses as f64;
    let mut blocks = Vec::new();
    let mut main = Vec::new();
    for c in 0..s.courses {
        let z = [
            c as f64 * hc,
            if c + 1 == s.courses {
                s.height
            } else {
                (c + 1) as f64 * hc
            },
        ];
        let through = c % 2 == 0; // the main wall runs through the corners
        let main_pieces = match (s.plan, through) {
            (Plan::I, true) => lay(0.0, big_l, 0.0, l),
            (Plan::I, false) => lay(0.0, big_l, l / 2.0, l),
            (Plan::L, true) | (Plan::U, true) => lay(0.0, big_l, 0.0, l),
            (Plan::L, false) => lay(t, big_l, t, l),
            (Plan::U, false) => lay(t, big_l - t, t, l),
        };
        for x in main_pieces {
            main.push(blocks.len());
            blocks.push(cuboid(x, [0.0, t], z).block());
        }
        let ret = if through {
            lay(t, r, t, l)
        } else {
            lay(0.0, r, 0.0, l)
        };
        let mut returns = Vec::new();
        if s.plan != Plan::I {
            returns.push([0.0, t]);
        }
        if s.plan == Plan::U {
            returns.push([big_l - t, big_l]);
        }
        for x in returns {
            for y in &ret {
                blocks.push(cuboid(x, *y, z).block());
            }
        }
    }
    let ymax = if s.plan == Plan::I { t } else { r };
    let ground = cuboid([-t, big_l + t], [-t, ymax + t], [-hc, 0.0]).support("ground");
    let live = match s.live {
        WallsLive::None => vec![],
        WallsLive::Main => vec![Load3d::Body {
            coefficients: [0.0, 1.0, 0.0],
            blocks: Some(main),
        }],
        WallsLive::All => vec![Load3d::Body {
            coefficients: [0.0, 1.0, 0.0],
            blocks: None,
        }],
    };
    let plan = match s.plan {
        Plan::I => "I (free-standing)".to_string(),
        Plan::L => format!("L (return {r} m)"),
        Plan::U => format!("U (returns {r} m)"),
    };
    Ok(Model3d {
        description: format!(
            "brick walls, plan {plan}, length {big_l} m, height {} m, thickness {t} m, {} courses of {} units; live load W·[0, 1, 0] on {:?}",
            s.height, s.courses, s.units, s.live
        ),
        materials: materials(s.unit_weight),
        blocks,
        supports: vec![ground],
        loads: Loads3d {
            self_weight: true,
            dead: vec![],
            live,
        },
        tolerance: None,
    })
}
