//! A validated, discretised structure: bodies, joints with collocation points, applied loads.
//!
//! [`Structure::new`] turns a user [`Model`] into this form (validation + interface detection).
//! [`Structure::deformed`] moves it by a finite rigid motion per block and returns a new one:
//! deformation is a geometry operation, so every analysis runs unchanged on a deformed structure.

pub mod assembly;
pub mod deform;
pub mod solid;
pub use crate::discretize::Body;
pub use assembly::Assembly;
pub use deform::OPEN_TOLERANCE;
pub use solid::Structure3d;

use crate::dim::{Dim, Two};
use crate::discretize::{ContactBodies, ContactJoint, JointLaw};
use crate::error::Error;
use crate::error::{model_err, Result};
use crate::geometry::{self, area_centroid, bbox, RigidMotion};
use crate::model::{Connection, Load, Material, Model, Per, Point};
use crate::result::{Geometry, LoadArrow, SupportShape};

/// Most cells of the overlap check's grid (cells of the median block's size) a body is put in;
/// a larger body is compared with every other body directly.
const MAX_CELLS_PER_BODY: f64 = 64.0;

#[derive(Clone, Debug, PartialEq)]
pub struct BlockGeom {
    pub polygon: Vec<Point>,
    pub centroid: Point,
    pub area: f64,
    /// Self-weight in kN (γ · area · width).
    pub weight: f64,
    pub material: Material,
}

#[derive(Clone, Debug, PartialEq)]
pub struct SupportGeom {
    pub name: String,
    pub polygon: Vec<Point>,
    pub centroid: Point,
    /// Prescribed motion `[u, v, θ]` about `centroid`.
    pub motion: [f64; 3],
    pub connection: Connection,
}

/// A collocation point of a joint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPoint {
    pub x: Point,
    /// Current gap (≥ 0). A point with a gap carries no force until it closes.
    pub gap: f64,
}

/// A joint between bodies `a` and `b` along a straight segment.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    pub a: Body,
    pub b: Body,
    /// Unit normal from `a` into `b`.
    pub normal: Point,
    /// Collocation points (the two ends of the contact segment, fewer after deformation).
    pub points: Vec<ContactPoint>,
    /// Original contact length (m) and out-of-plane width (m).
    pub length: f64,
    pub width: f64,
    /// Bilateral joint (block tied to a `fixed` support): tension allowed, no opening.
    pub bilateral: bool,
}

/// Where a crack is and how wide: one of `at`, `joint` and `polyline` (see
/// [`Structure::crack_site_points`]), with the scales of its units.
#[derive(Clone, Copy, Debug)]
pub struct CrackSite<'a> {
    pub at: Option<[f64; 2]>,
    pub joint: Option<usize>,
    pub polyline: Option<&'a [[f64; 2]]>,
    /// Catch distance of a polyline, in the coordinate unit.
    pub snap: Option<f64>,
    pub opening: &'a crate::model::Width,
    /// Metres per unit of the widths, and that unit's name (for messages).
    pub width_scale: f64,
    pub width_unit: &'a str,
    /// Metres per unit of the coordinates (`at`, `polyline`, `snap`).
    pub coordinate_scale: f64,
}

impl Default for CrackSite<'_> {
    fn default() -> Self {
        static ZERO: crate::model::Width = crate::model::Width::One(0.0);
        CrackSite {
            at: None,
            joint: None,
            polyline: None,
            snap: None,
            opening: &ZERO,
            width_scale: 1.0,
            width_unit: "m",
            coordinate_scale: 1.0,
        }
    }
}

impl Joint {
    /// Unit tangent `t = (−n_y, n_x)`.
    pub fn tangent(&self) -> Point {
        [-self.normal[1], self.normal[0]]
    }
    /// Midpoint of the original contact segment (mean of the points).
    pub fn midpoint(&self) -> Point {
        let n = self.points.len().max(1) as f64;
        let s = self
            .points
            .iter()
            .fold([0.0, 0.0], |s, p| [s[0] + p.x[0], s[1] + p.x[1]]);
        [s[0] / n, s[1] / n]
    }
}

/// A force applied to a block at a point; live loads are multiplied by λ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AppliedLoad {
    pub block: usize,
    pub at: Point,
    pub force: Point,
    pub live: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Structure {
    pub blocks: Vec<BlockGeom>,
    pub supports: Vec<SupportGeom>,
    pub joints: Vec<Joint>,
    pub loads: Vec<AppliedLoad>,
    /// Absolute geometric tolerance (m).
    pub tolerance: f64,
}

/// Options for building a structure.
#[derive(Clone, Copy, Debug, Default)]
pub struct BuildOptions {
    /// Override of the model's relative tolerance.
    pub tolerance: Option<f64>,
}

fn finite(p: &[Point]) -> bool {
    p.iter().all(|q| q[0].is_finite() && q[1].is_finite())
}

/// Check a polygon and return it counter-clockwise.
fn clean_polygon(what: &str, p: &[Point], tol: f64) -> Result<Vec<Point>> {
    if p.len() < 3 {
        return model_err(format!(
            "{what}: polygon has {} vertices, needs at least 3",
            p.len()
        ));
    }
    if !finite(p) {
        return model_err(format!(
            "{what}: polygon has a coordinate that is not a finite number"
        ));
    }
    // Drop a closing vertex equal to the first (as CAD exports often have).
    let mut q: Vec<Point> = p.to_vec();
    while q.len() > 3 && geometry::norm(geometry::sub(q[0], q[q.len() - 1])) <= tol {
        q.pop();
    }
    for i in 0..q.len() {
        let j = (i + 1) % q.len();
        if geometry::norm(geometry::sub(q[i], q[j])) <= tol {
            return model_err(format!(
                "{what}: vertices {i} and {j} coincide (zero-length edge)"
            ));
        }
    }
    if let Some((i, j)) = geometry::self_intersection(&q, tol) {
        return model_err(format!(
            "{what}: polygon is self-intersecting (edges {i} and {j} cross or touch)"
        ));
    }
    let a = geometry::signed_area(&q);
    let b = bbox(&q);
    let scale = (b[2] - b[0]).max(b[3] - b[1]);
    if a.abs() <= tol * scale {
        return model_err(format!("{what}: polygon is degenerate (zero area)"));
    }
    if a < 0.0 {
        q.reverse();
    }
    Ok(q)
}

impl Structure {
    /// Validate `model` and find its joints.
    pub fn new(model: &Model, opts: BuildOptions) -> Result<Structure> {
        if model.blocks.is_empty() {
            return model_err("the model has no blocks");
        }
        if model.supports.is_empty() {
            return model_err("the model has no supports: at least one foundation is needed");
        }
        // Tolerance from the overall size.
        let mut all = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        for p in model
            .blocks
            .iter()
            .map(|b| &b.polygon)
            .chain(model.supports.iter().map(|s| &s.polygon))
        {
            if finite(p) && !p.is_empty() {
                let b = bbox(p);
                all = [
                    all[0].min(b[0]),
                    all[1].min(b[1]),
                    all[2].max(b[2]),
                    all[3].max(b[3]),
                ];
            }
        }
        let rel = relative_tolerance(opts.tolerance.or(model.tolerance))?;
        let diag = (all[2] - all[0]).hypot(all[3] - all[1]);
        let tol = rel
            * if diag.is_finite() && diag > 0.0 {
                diag
            } else {
                1.0
            };

        check_materials(&model.materials)?;

        let mut blocks = Vec::with_capacity(model.blocks.len());
        for (i, b) in model.blocks.iter().enumerate() {
            let what = format!("block {i}");
            if let Some(m) = &b.material {
                if m != "default" && !model.materials.contains_key(m) {
                    return model_err(format!("{what}: unknown material '{m}'"));
                }
            }
            let polygon = clean_polygon(&what, &b.polygon, tol)?;
            let (area, centroid) = area_centroid(&polygon);
            let material = model.material_of(i);
            blocks.push(BlockGeom {
                weight: material.unit_weight * area * material.width,
                polygon,
                centroid,
                area,
                material,
            });
        }
        let mut supports = Vec::with_capacity(model.supports.len());
        for (i, s) in model.supports.iter().enumerate() {
            let what = format!("support '{}'", s.name);
            check_support(
                i,
                &s.name,
                model.supports[..i].iter().map(|t| t.name.as_str()),
                &s.motion,
            )?;
            let polygon = clean_polygon(&what, &s.polygon, tol)?;
            let (_, centroid) = area_centroid(&polygon);
            supports.push(SupportGeom {
                name: s.name.clone(),
                polygon,
                centroid,
                motion: s.motion,
                connection: s.connection,
            });
        }

        let mut st = Structure {
            blocks,
            supports,
            joints: Vec::new(),
            loads: Vec::new(),
            tolerance: tol,
        };
        st.check_overlaps()?;
        st.find_joints()?;
        st.loads = resolve_loads(model, &st)?;
        st.open_existing_cracks(&model.cracks)?;
        Ok(st)
    }

    /// The collocation points a crack names, as `(joint, point index, width)`: by `at`, the
    /// nearest point of any joint (ties to the lowest joint and point), or by `joint`, its
    /// points with one width each or one for all. `what` names the crack in errors.
    pub fn crack_points(
        &self,
        what: &str,
        at: Option<[f64; 2]>,
        joint: Option<usize>,
        opening: &crate::model::Width,
    ) -> Result<Vec<(usize, usize, f64)>> {
        self.crack_site_points(
            what,
            &CrackSite {
                at,
                joint,
                opening,
                ..CrackSite::default()
            },
        )
    }

    /// The collocation points a crack names, as `(joint, point index, width in m)`: by `at`,
    /// the nearest point of any joint (ties to the lowest joint and point); by `joint`, its
    /// points with one width each or one for all; by `polyline`, every joint point within the
    /// snap distance of the line (default a quarter of that point's joint length), with one
    /// width or two (at the line's start and end, interpolated along its length at the point's
    /// projection). Widths are scaled by `width_scale`, coordinates and snap by
    /// `coordinate_scale`. `what` names the crack in errors.
    pub fn crack_site_points(&self, what: &str, c: &CrackSite) -> Result<Vec<(usize, usize, f64)>> {
        use crate::model::Width;
        let bad = |m: String| Err(Error::Request(format!("{what}: {m}")));
        let (ws, fc) = (c.width_scale, c.coordinate_scale);
        let unit = c.width_unit;
        c.opening
            .check(unit)
            .map_err(|m| Error::Request(format!("{what}: {m}")))?;
        if c.snap.is_some() && c.polyline.is_none() {
            return bad("\"snap\" applies to a crack given by \"polyline\"".into());
        }
        let points = match (c.at, c.joint, c.polyline, c.opening) {
            (Some(p), None, None, Width::One(w)) => {
                if !(p[0].is_finite() && p[1].is_finite()) {
                    return bad("\"at\" must be two finite coordinates".into());
                }
                let p = [p[0] * fc, p[1] * fc];
                let mut best: Option<(f64, usize, usize)> = None;
                for (j, jt) in self.joints.iter().enumerate() {
                    for (k, q) in jt.points.iter().enumerate() {
                        let dd = (q.x[0] - p[0]).hypot(q.x[1] - p[1]);
                        if best.is_none_or(|(b, _, _)| dd < b) {
                            best = Some((dd, j, k));
                        }
                    }
                }
                match best {
                    Some((_, j, k)) => vec![(j, k, *w * ws)],
                    None => return bad("the structure has no joints".into()),
                }
            }
            (Some(_), None, None, Width::PerPoint(_)) => {
                return bad("a crack located by \"at\" takes one width".into())
            }
            (None, Some(j), None, w) => {
                let n = self.joints.get(j).map(|jt| jt.points.len());
                w.on_joint(j, n, self.joints.len(), ws)
                    .map_err(|m| Error::Request(format!("{what}: {m}")))?
            }
            (None, None, Some(line), w) => self.polyline_points(what, line, c.snap, w, ws, fc)?,
            _ => return bad("give exactly one of \"at\", \"joint\" and \"polyline\"".into()),
        };
        Ok(points)
    }

    /// The joint points a crack line catches (see [`Structure::crack_site_points`]).
    fn polyline_points(
        &self,
        what: &str,
        line: &[[f64; 2]],
        snap: Option<f64>,
        w: &crate::model::Width,
        ws: f64,
        fc: f64,
    ) -> Result<Vec<(usize, usize, f64)>> {
        use crate::model::Width;
        let bad = |m: String| Err(Error::Request(format!("{what}: {m}")));
        if line.is_empty() {
            return bad("\"polyline\" needs at least one point [x, y]".into());
        }
        if line.iter().any(|p| !(p[0].is_finite() && p[1].is_finite())) {
            return bad("\"polyline\": every point must be two finite coordinates".into());
        }
        if let Some(d) = snap {
            if !(d.is_finite() && d > 0.0) {
                return bad(format!("\"snap\" {d} must be a finite number > 0"));
            }
        }
        let line: Vec<[f64; 2]> = line.iter().map(|p| [p[0] * fc, p[1] * fc]).collect();
        // Cumulative length at each vertex.
        let mut cum = vec![0.0];
        for s in line.windows(2) {
            let l = (s[1][0] - s[0][0]).hypot(s[1][1] - s[0][1]);
            cum.push(cum.last().unwrap() + l);
        }
        let total = *cum.last().unwrap();
        // The width at arc length s: one width; two, at the start and the end, linear between;
        // or one per vertex (a result's crack record: `points` and `openings`), piecewise
        // linear between the vertices.
        let width_at: Box<dyn Fn(f64) -> f64> = match w {
            Width::One(w) => {
                let w = *w * ws;
                Box::new(move |_| w)
            }
            Width::PerPoint(v) if v.len() == line.len() && line.len() >= 2 => {
                let (v, cum) = (v.clone(), cum.clone());
                Box::new(move |s: f64| {
                    let i = cum.partition_point(|&c| c <= s).clamp(1, cum.len() - 1);
                    let (c0, c1) = (cum[i - 1], cum[i]);
                    let f = if c1 > c0 { ((s - c0) / (c1 - c0)).clamp(0.0, 1.0) } else { 0.0 };
                    (v[i - 1] + (v[i] - v[i - 1]) * f) * ws
                })
            }
            Width::PerPoint(v) if v.len() == 2 => {
                let (w0, w1) = (v[0] * ws, v[1] * ws);
                Box::new(move |s: f64| {
                    let f = if total > 0.0 { s / total } else { 0.0 };
                    w0 + (w1 - w0) * f
                })
            }
            Width::PerPoint(v) => {
                return bad(format!(
                    "a crack given by \"polyline\" takes one width, two (at its start and end) or one per vertex ({}); {} given",
                    line.len(),
                    v.len()
                ))
            }
        };
        // Distance from p to the line and the arc length of its projection.
        let project = |p: [f64; 2]| -> (f64, f64) {
            if line.len() == 1 {
                return ((p[0] - line[0][0]).hypot(p[1] - line[0][1]), 0.0);
            }
            let mut best = (f64::INFINITY, 0.0);
            for (i, s) in line.windows(2).enumerate() {
                let d = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
                let l2 = d[0] * d[0] + d[1] * d[1];
                let t = if l2 > 0.0 {
                    (((p[0] - s[0][0]) * d[0] + (p[1] - s[0][1]) * d[1]) / l2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let q = [s[0][0] + t * d[0], s[0][1] + t * d[1]];
                let dist = (p[0] - q[0]).hypot(p[1] - q[1]);
                if dist < best.0 {
                    best = (dist, cum[i] + t * l2.sqrt());
                }
            }
            best
        };
        let mut out = Vec::new();
        for (j, jt) in self.joints.iter().enumerate() {
            let reach = snap.map(|d| d * fc).unwrap_or(0.25 * jt.length);
            for (k, q) in jt.points.iter().enumerate() {
                let (dist, s) = project(q.x);
                if dist <= reach {
                    out.push((j, k, width_at(s)));
                }
            }
        }
        if out.is_empty() {
            let reach = match snap {
                Some(d) => format!("within \"snap\" {d} of it"),
                None => "within a quarter of its joint's length of it".to_string(),
            };
            let (a, b) = (line[0], line[line.len() - 1]);
            return bad(format!(
                "the polyline from ({:.4}, {:.4}) to ({:.4}, {:.4}) m catches no joint point (none {reach}): draw it along a joint or give a larger \"snap\"",
                a[0], a[1], b[0], b[1]
            ));
        }
        Ok(out)
    }

    /// Give the points of the model's existing cracks their gaps.
    fn open_existing_cracks(&mut self, cracks: &[crate::model::ExistingCrack]) -> Result<()> {
        let mut seen: std::collections::HashMap<(usize, usize), usize> = Default::default();
        for (i, c) in cracks.iter().enumerate() {
            let what = format!("cracks[{i}]");
            let scale = crate::model::length_unit_of(&what, "units", c.units.as_deref())
                .map_err(Error::Model)?;
            let points = self
                .crack_site_points(
                    &what,
                    &CrackSite {
                        at: c.at,
                        joint: c.joint,
                        polyline: c.polyline.as_deref(),
                        snap: c.snap,
                        opening: &c.opening,
                        width_scale: scale,
                        width_unit: c.units.as_deref().unwrap_or("m"),
                        coordinate_scale: 1.0,
                    },
                )
                .map_err(|e| match e {
                    Error::Request(m) => Error::Model(m),
                    e => e,
                })?;
            for (j, k, w) in points {
                if let Some(other) = seen.insert((j, k), i) {
                    return Err(Error::Model(format!(
                        "cracks[{i}] and cracks[{other}] name the same point of joint {j}"
                    )));
                }
                if self.joints[j].bilateral && w > 0.0 {
                    return Err(Error::Model(format!(
                        "{what}: joint {j} is tied (a fixed support) and cannot be cracked"
                    )));
                }
                self.joints[j].points[k].gap = w;
            }
        }
        Ok(())
    }

    fn body_name(&self, k: usize) -> String {
        let nb = self.blocks.len();
        if k < nb {
            format!("block {k}")
        } else {
            format!("support '{}'", self.supports[k - nb].name)
        }
    }

    fn polygons(&self) -> Vec<&[Point]> {
        self.blocks
            .iter()
            .map(|b| b.polygon.as_slice())
            .chain(self.supports.iter().map(|s| s.polygon.as_slice()))
            .collect()
    }

    /// Reject overlapping bodies (support–support overlaps are allowed). Candidate pairs come
    /// from a uniform grid of bounding boxes, so this is linear in the number of bodies for
    /// models of similar-sized blocks.
    fn check_overlaps(&self) -> Result<()> {
        let polys = self.polygons();
        let tol = self.tolerance;
        let boxes: Vec<[f64; 4]> = polys
            .iter()
            .map(|p| {
                let b = bbox(p);
                [b[0] + tol, b[1] + tol, b[2] - tol, b[3] - tol]
            })
            .collect();
        let nb = self.blocks.len();
        let mut sizes: Vec<f64> = boxes[..nb]
            .iter()
            .map(|b| (b[2] - b[0]).max(b[3] - b[1]))
            .collect();
        sizes.sort_by(f64::total_cmp);
        let cell = sizes[sizes.len() / 2].max(tol * 10.0);
        let mut entries: Vec<(i64, i64, usize)> = Vec::new();
        let mut pairs: Vec<(usize, usize)> = Vec::new();
        let meet =
            |p: [f64; 4], q: [f64; 4]| p[0] < q[2] && q[0] < p[2] && p[1] < q[3] && q[1] < p[3];
        for (k, b) in boxes.iter().enumerate() {
            let (i0, j0) = ((b[0] / cell).floor(), (b[1] / cell).floor());
            let (i1, j1) = ((b[2] / cell).floor(), (b[3] / cell).floor());
            // A body much larger than the median block (a long foundation, or a block drawn
            // at the wrong scale) would fill more cells than the model has bodies: it is
            // compared with every other body instead, so that memory stays linear.
            if (i1 - i0 + 1.0) * (j1 - j0 + 1.0) > MAX_CELLS_PER_BODY {
                pairs.extend(
                    (0..boxes.len())
                        .filter(|&q| q != k && meet(*b, boxes[q]))
                        .map(|q| (k.min(q), k.max(q))),
                );
                continue;
            }
            for i in i0 as i64..=i1 as i64 {
                for j in j0 as i64..=j1 as i64 {
                    entries.push((i, j, k));
                }
            }
        }
        entries.sort_unstable();
        let mut s = 0;
        while s < entries.len() {
            let mut e = s + 1;
            while e < entries.len() && entries[e].0 == entries[s].0 && entries[e].1 == entries[s].1
            {
                e += 1;
            }
            for x in s..e {
                for y in x + 1..e {
                    // Supports are checked against each other too: two overlapping foundations
                    // would give a block's face two joints.
                    let (p, q) = (entries[x].2, entries[y].2);
                    if meet(boxes[p], boxes[q]) {
                        pairs.push((p.min(q), p.max(q)));
                    }
                }
            }
            s = e;
        }
        pairs.sort_unstable();
        pairs.dedup();
        for (p, q) in pairs {
            if geometry::polygons_overlap(polys[p], polys[q], tol) {
                return model_err(format!(
                    "{} and {} overlap",
                    self.body_name(p),
                    self.body_name(q)
                ));
            }
        }
        Ok(())
    }

    fn find_joints(&mut self) -> Result<()> {
        let nb = self.blocks.len();
        let (ifs, clashes) = {
            let polys = self.polygons();
            geometry::detect_interfaces(&polys, self.tolerance)
        };
        if let Some(c) = clashes.iter().find(|c| c.a < nb || c.b < nb) {
            return model_err(format!(
                "{} and {} overlap",
                self.body_name(c.a),
                self.body_name(c.b)
            ));
        }
        let to_body = |k: usize| {
            if k < nb {
                Body::Block(k)
            } else {
                Body::Support(k - nb)
            }
        };
        let mut touched = vec![false; nb];
        for it in ifs {
            if it.a >= nb && it.b >= nb {
                continue; // support–support: nothing moves relative to anything
            }
            let (a, b) = (to_body(it.a), to_body(it.b));
            let mut bilateral = false;
            let mut width = f64::INFINITY;
            for body in [a, b] {
                match body {
                    Body::Block(i) => {
                        touched[i] = true;
                        width = width.min(self.blocks[i].material.width);
                    }
                    Body::Support(s) => {
                        bilateral = self.supports[s].connection == Connection::Fixed
                    }
                }
            }
            self.joints.push(Joint {
                a,
                b,
                normal: it.normal,
                length: geometry::norm(geometry::sub(it.ends[1], it.ends[0])),
                width,
                points: it
                    .ends
                    .iter()
                    .map(|&x| ContactPoint { x, gap: 0.0 })
                    .collect(),
                bilateral,
            });
        }
        if let Some(i) = touched.iter().position(|t| !t) {
            return model_err(format!(
                "block {i} touches nothing: it shares no edge with another block or a support"
            ));
        }
        Ok(())
    }

    pub fn num_blocks(&self) -> usize {
        self.blocks.len()
    }

    /// Reference point of a body.
    pub fn center(&self, b: Body) -> Point {
        match b {
            Body::Block(i) => self.blocks[i].centroid,
            Body::Support(s) => self.supports[s].centroid,
        }
    }

    /// Display name of a body: the block index or the support name.
    pub fn name(&self, b: Body) -> String {
        match b {
            Body::Block(i) => i.to_string(),
            Body::Support(s) => self.supports[s].name.clone(),
        }
    }

    /// Load resultants per block `[Fx, Fy, M]` (M about the block's centroid), dead or live.
    pub fn load_vector(&self, live: bool) -> Vec<f64> {
        let mut f = vec![0.0; 3 * self.blocks.len()];
        for l in self.loads.iter().filter(|l| l.live == live) {
            let c = self.blocks[l.block].centroid;
            let r = geometry::sub(l.at, c);
            f[3 * l.block] += l.force[0];
            f[3 * l.block + 1] += l.force[1];
            f[3 * l.block + 2] += geometry::cross(r, l.force);
        }
        f
    }

    /// Whether the structure has any live load.
    pub fn has_live_loads(&self) -> bool {
        self.loads
            .iter()
            .any(|l| l.live && (l.force[0] != 0.0 || l.force[1] != 0.0))
    }
}

impl Assembly for Structure {
    type D = Two;

    assembly_parts!();

    fn contact_bodies(&self) -> ContactBodies<Two> {
        ContactBodies {
            blocks: self.blocks.iter().map(|b| b.centroid).collect(),
            supports: self
                .supports
                .iter()
                .map(|s| (s.centroid, s.motion.to_vec()))
                .collect(),
        }
    }

    fn contact_joints(&self) -> Vec<ContactJoint<Two>> {
        self.joints
            .iter()
            .map(|joint| {
                let t = joint.tangent();
                let mid = joint.midpoint();
                let mats = joint_materials([joint.a, joint.b], |i| &self.blocks[i].material);
                ContactJoint {
                    a: joint.a,
                    b: joint.b,
                    normal: joint.normal,
                    tangents: Two::tangents(joint.normal),
                    points: joint.points.iter().map(|p| (p.x, p.gap)).collect(),
                    bilateral: joint.bilateral,
                    law: JointLaw::between(
                        &mats,
                        joint.length,
                        joint.width,
                        joint.length * joint.width,
                        joint.points.len(),
                    ),
                    along: joint
                        .points
                        .iter()
                        .map(|p| (p.x[0] - mid[0]) * t[0] + (p.x[1] - mid[1]) * t[1])
                        .collect(),
                }
            })
            .collect()
    }

    fn load_vector(&self, live: bool) -> Vec<f64> {
        Structure::load_vector(self, live)
    }
    fn has_live_loads(&self) -> bool {
        Structure::has_live_loads(self)
    }

    fn with_weight_as_live_load(&self, direction: Point) -> Result<Structure> {
        let mut s = self.clone();
        s.loads.retain(|l| !l.live);
        let live: Vec<AppliedLoad> = s
            .blocks
            .iter()
            .enumerate()
            .filter(|(_, b)| b.weight > 0.0)
            .map(|(i, b)| AppliedLoad {
                block: i,
                at: b.centroid,
                force: [direction[0] * b.weight, direction[1] * b.weight],
                live: true,
            })
            .collect();
        if live.is_empty() {
            return Err(crate::error::Error::Request(
                "tilt analysis needs blocks with weight".into(),
            ));
        }
        s.loads.extend(live);
        Ok(s)
    }

    fn shapes(&self) -> crate::result::Geometry {
        crate::result::Geometry::of(self)
    }

    fn cracks(
        &self,
        joints: &[crate::result::JointResult],
        open: &[Vec<bool>],
        widths: &[Vec<f64>],
    ) -> Vec<crate::result::Crack> {
        crate::result::cracks::trace_cracks(
            joints,
            open,
            widths,
            &crate::result::CrackGeometry::of_structure(self),
        )
    }

    fn settlement_magnitude(&self) -> f64 {
        Structure::settlement_magnitude(self)
    }

    fn release_fixed(&mut self) {
        Structure::release_fixed(self)
    }

    /// Move every block by the finite rigid motion `s·d_i` and every support by `s·motion`;
    /// points of each joint take their new position (mean of the images on both sides) and
    /// their gap `s·opening` (`openings[j][k]` for point `k` of joint `j`). Points whose gap
    /// exceeds `gap_tol` stay in the structure with that gap (they carry no force until they
    /// close); joints move with their bodies; loads move with their blocks (directions kept).
    fn deformed(&self, d: &[f64], s: f64, openings: &[Vec<f64>], gap_tol: f64) -> Structure {
        let motion = |b: Body| -> RigidMotion {
            match b {
                Body::Block(i) => RigidMotion::scaled(
                    self.blocks[i].centroid,
                    [d[3 * i], d[3 * i + 1], d[3 * i + 2]],
                    s,
                ),
                Body::Support(k) => {
                    RigidMotion::scaled(self.supports[k].centroid, self.supports[k].motion, s)
                }
            }
        };
        let mut out = self.clone();
        for (i, b) in out.blocks.iter_mut().enumerate() {
            let m = motion(Body::Block(i));
            b.polygon = b.polygon.iter().map(|&p| m.apply(p)).collect();
            b.centroid = m.apply(b.centroid);
        }
        for (k, sp) in out.supports.iter_mut().enumerate() {
            let m = motion(Body::Support(k));
            sp.polygon = sp.polygon.iter().map(|&p| m.apply(p)).collect();
            sp.centroid = m.apply(sp.centroid);
            sp.motion = [0.0; 3];
        }
        for (j, joint) in out.joints.iter_mut().enumerate() {
            let (ma, mb) = (motion(joint.a), motion(joint.b));
            let mean = RigidMotion {
                center: [0.0, 0.0],
                translation: [0.0, 0.0],
                theta: 0.5 * (ma.theta + mb.theta),
            };
            joint.normal = mean.rotate(joint.normal);
            for (k, p) in joint.points.iter_mut().enumerate() {
                let (xa, xb) = (ma.apply(p.x), mb.apply(p.x));
                p.x = [0.5 * (xa[0] + xb[0]), 0.5 * (xa[1] + xb[1])];
                p.gap = moved_gap(p.gap, s, openings, (j, k), gap_tol);
            }
        }
        for l in out.loads.iter_mut() {
            l.at = motion(Body::Block(l.block)).apply(l.at);
        }
        out
    }
}

/// The accessors of [`Assembly`] that read the same fields of a 2D and a 3D structure
/// (`blocks`, `supports` with `name` and `motion`, `joints` with `a` and `b`).
macro_rules! assembly_parts {
    () => {
        fn num_blocks(&self) -> usize {
            self.blocks.len()
        }
        fn num_supports(&self) -> usize {
            self.supports.len()
        }
        fn num_joints(&self) -> usize {
            self.joints.len()
        }
        fn joint_bodies(&self, j: usize) -> (Body, Body) {
            (self.joints[j].a, self.joints[j].b)
        }
        fn support_name(&self, s: usize) -> &str {
            &self.supports[s].name
        }
        fn support_motion(&self, s: usize) -> &[f64] {
            &self.supports[s].motion
        }
        /// The first components of `motion`, as many as the support's motion has.
        fn set_support_motion(&mut self, s: usize, motion: &[f64]) {
            let m = &mut self.supports[s].motion;
            let n = m.len();
            m.copy_from_slice(&motion[..n]);
        }
    };
}
use assembly_parts;

/// The materials of a joint's blocks, in the order of `bodies` (a support has none).
pub(crate) fn joint_materials<'a>(
    bodies: [Body; 2],
    material: impl Fn(usize) -> &'a Material,
) -> Vec<&'a Material> {
    bodies
        .iter()
        .filter_map(|b| match b {
            Body::Block(i) => Some(material(*i)),
            Body::Support(_) => None,
        })
        .collect()
}

/// The gap of point `k` of joint `j` after a deformation scaled by `s`: `gap + s·openings[j][k]`
/// (no opening where `openings` has none), closed (0) up to `gap_tol`.
pub(crate) fn moved_gap(
    gap: f64,
    s: f64,
    openings: &[Vec<f64>],
    (j, k): (usize, usize),
    gap_tol: f64,
) -> f64 {
    let g = gap
        + s * openings
            .get(j)
            .and_then(|o| o.get(k))
            .copied()
            .unwrap_or(0.0);
    if g > gap_tol {
        g
    } else {
        0.0
    }
}

/// The relative geometric tolerance asked for (default 1e-7), checked.
pub(crate) fn relative_tolerance(asked: Option<f64>) -> Result<f64> {
    let rel = asked.unwrap_or(1e-7);
    if !(rel.is_finite() && rel > 0.0 && rel < 0.1) {
        return model_err(format!(
            "tolerance {rel} must be a positive number below 0.1"
        ));
    }
    Ok(rel)
}

/// Every material's values are finite and in range.
pub(crate) fn check_materials(
    materials: &std::collections::BTreeMap<String, Material>,
) -> Result<()> {
    for (name, m) in materials {
        let ok = m.unit_weight.is_finite()
            && m.unit_weight >= 0.0
            && m.width.is_finite()
            && m.width > 0.0
            && m.compressive_strength
                .is_none_or(|f| f.is_finite() && f > 0.0)
            && m.friction.is_none_or(|f| f.is_finite() && f >= 0.0)
            && m.cohesion.is_finite()
            && m.cohesion >= 0.0;
        if !ok {
            return model_err(format!(
            "material '{name}': unit_weight ≥ 0, width > 0, compressive_strength > 0, friction ≥ 0 and cohesion ≥ 0 must be finite numbers"
        ));
        }
        if let Some(mu) = m.friction.filter(|&f| f > crate::discretize::MAX_FRICTION) {
            return model_err(format!(
                "material '{name}': friction {mu} is above {}, which no joint has; for joints that do not slide leave friction out (Heyman's law)",
                crate::discretize::MAX_FRICTION
            ));
        }
    }
    Ok(())
}

/// A load's block exists among the model's `nb` blocks (`what` names the load).
pub(crate) fn check_load_block(what: &str, b: usize, nb: usize) -> Result<()> {
    if b < nb {
        Ok(())
    } else {
        model_err(format!(
            "{what}: block {b} does not exist (the model has {nb} blocks)"
        ))
    }
}

/// The blocks a body load acts on (every block when the list is absent), each checked.
pub(crate) fn body_load_blocks(
    what: &str,
    blocks: &Option<Vec<usize>>,
    nb: usize,
) -> Result<Vec<usize>> {
    let list: Vec<usize> = match blocks {
        Some(v) => v.clone(),
        None => (0..nb).collect(),
    };
    for &b in &list {
        check_load_block(what, b, nb)?;
    }
    Ok(list)
}

/// A support's name is non-empty and unique, its motion finite.
pub(crate) fn check_support<'a>(
    i: usize,
    name: &str,
    mut earlier: impl Iterator<Item = &'a str>,
    motion: &[f64],
) -> Result<()> {
    if name.is_empty() {
        return model_err(format!("support {i} has an empty name"));
    }
    if earlier.any(|t| t == name) {
        return model_err(format!("support '{name}': name used twice"));
    }
    if !motion.iter().all(|x| x.is_finite()) {
        return model_err(format!(
            "support '{name}': motion has a value that is not a finite number"
        ));
    }
    Ok(())
}

fn resolve_loads(model: &Model, st: &Structure) -> Result<Vec<AppliedLoad>> {
    let nb = st.blocks.len();
    let mut out = Vec::new();
    if model.loads.self_weight {
        for (i, b) in st.blocks.iter().enumerate() {
            if b.weight > 0.0 {
                out.push(AppliedLoad {
                    block: i,
                    at: b.centroid,
                    force: [0.0, -b.weight],
                    live: false,
                });
            }
        }
    }
    for (live, list) in [(false, &model.loads.dead), (true, &model.loads.live)] {
        let kind = if live { "live" } else { "dead" };
        for (n, l) in list.iter().enumerate() {
            let what = format!("{kind} load {n}");
            match l {
                Load::Point { block, at, force } => {
                    check_load_block(&what, *block, nb)?;
                    if !finite(&[*at, *force]) {
                        return model_err(format!("{what}: a value is not a finite number"));
                    }
                    out.push(AppliedLoad {
                        block: *block,
                        at: *at,
                        force: *force,
                        live,
                    });
                }
                Load::Edge {
                    block,
                    edge,
                    q,
                    per,
                } => {
                    check_load_block(&what, *block, nb)?;
                    let b = &st.blocks[*block];
                    // Edge numbering refers to the block's polygon as given; the polygon was
                    // possibly reversed, so find the edge by its end points.
                    let given = &model.blocks[*block].polygon;
                    if *edge >= given.len() {
                        return model_err(format!("{what}: block {block} has no edge {edge}"));
                    }
                    if !q.is_finite() {
                        return model_err(format!("{what}: q is not a finite number"));
                    }
                    let (p0, p1) = (given[*edge], given[(*edge + 1) % given.len()]);
                    let len = match per {
                        Per::Horizontal => (p1[0] - p0[0]).abs(),
                        Per::Length => geometry::norm(geometry::sub(p1, p0)),
                    };
                    let fy = -q * len * b.material.width;
                    out.push(AppliedLoad {
                        block: *block,
                        at: [(p0[0] + p1[0]) / 2.0, (p0[1] + p1[1]) / 2.0],
                        force: [0.0, fy],
                        live,
                    });
                }
                Load::Body {
                    coefficients,
                    blocks,
                } => {
                    if !finite(&[*coefficients]) {
                        return model_err(format!("{what}: a coefficient is not a finite number"));
                    }
                    for b in body_load_blocks(&what, blocks, nb)? {
                        let w = st.blocks[b].weight;
                        out.push(AppliedLoad {
                            block: b,
                            at: st.blocks[b].centroid,
                            force: [w * coefficients[0], w * coefficients[1]],
                            live,
                        });
                    }
                }
            }
        }
    }
    Ok(out)
}

// Constructors of result types from a 2D structure (here, so that `result` needs no
// structure).
impl crate::result::BodyName {
    pub fn of(st: &Structure, b: Body) -> crate::result::BodyName {
        match b {
            Body::Block(i) => crate::result::BodyName::Block(i),
            Body::Support(s) => crate::result::BodyName::Support(st.supports[s].name.clone()),
        }
    }
}

impl crate::result::Geometry {
    pub fn of(st: &Structure) -> Geometry {
        Geometry {
            blocks: st.blocks.iter().map(|b| b.polygon.clone()).collect(),
            supports: st
                .supports
                .iter()
                .map(|s| SupportShape {
                    name: s.name.clone(),
                    polygon: s.polygon.clone(),
                    motion: s.motion,
                    fixed: s.connection == crate::model::Connection::Fixed,
                })
                .collect(),
            loads: st
                .loads
                .iter()
                .map(|l| LoadArrow {
                    block: l.block,
                    x: l.at[0],
                    y: l.at[1],
                    fx: l.force[0],
                    fy: l.force[1],
                    live: l.live,
                })
                .collect(),
        }
    }
}

impl<'a> crate::result::CrackGeometry<'a> {
    /// The shapes of a 2D structure, and its tolerance.
    pub fn of_structure(st: &'a Structure) -> Self {
        crate::result::CrackGeometry {
            blocks: st.blocks.iter().map(|b| b.polygon.as_slice()).collect(),
            supports: st.supports.iter().map(|s| s.polygon.as_slice()).collect(),
            tolerance: st.tolerance,
        }
    }
}
