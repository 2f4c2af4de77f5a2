//! A validated 3D structure: polyhedral blocks and supports, joints found on coplanar facing
//! faces with their contact polygons, applied loads. Built from a [`Model3d`] by
//! [`Structure3d::new`]; analysed through [`Assembly`] by the same analyses as 2D.
//!
//! The geometry is in [`crate::geometry3d`] (validation, mass properties, interface detection);
//! this module turns it into bodies, joints with their laws, and loads. Each block has six DOFs
//! `(u, v, w, θx, θy, θz)` at its centroid; each vertex of a contact polygon is a collocation
//! point (an opening and two slips), so a joint carries torsion through its vertices.

use super::{
    assembly_parts, body_load_blocks, check_load_block, check_materials, check_support,
    joint_materials, moved_gap, relative_tolerance, Assembly, Body, BuildOptions,
};
use crate::dim::{Dim, Three};
use crate::discretize::{ContactBodies, ContactJoint, JointLaw};
use crate::error::{model_err, Error, Result};
use crate::geometry3d::{self, Solid};
use crate::model::{Connection, Material};
use crate::model3d::{Load3d, Model3d, PerArea, Point3, Polyhedron};
use crate::result::spatial::{LoadArrow3d, SpatialShapes, SupportSolid};
use crate::vector::cross;
use nalgebra::{Rotation3, Vector3};

#[derive(Clone, Debug, PartialEq)]
pub struct SolidBlock {
    pub shape: Solid,
    /// Self-weight in kN (γ · volume).
    pub weight: f64,
    pub material: Material,
}

#[derive(Clone, Debug, PartialEq)]
pub struct SolidSupport {
    pub name: String,
    pub shape: Solid,
    /// Prescribed motion `[u, v, w, θx, θy, θz]` about the centroid.
    pub motion: [f64; 6],
    pub connection: Connection,
}

/// A collocation point of a 3D joint: a vertex of the contact polygon.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidPoint {
    pub x: Point3,
    /// Current gap (≥ 0): a point with a gap carries no force until it closes.
    pub gap: f64,
}

/// A planar joint between bodies `a` and `b`.
#[derive(Clone, Debug, PartialEq)]
pub struct SolidJoint {
    pub a: Body,
    pub b: Body,
    /// Unit normal from `a` into `b`.
    pub normal: Point3,
    /// The vertices of the contact polygon (counter-clockwise about the normal).
    pub points: Vec<SolidPoint>,
    /// Contact area (m²) as found.
    pub area: f64,
    /// Tied to a `fixed` support: tension allowed, no opening.
    pub bilateral: bool,
}

/// A force (and moment) on a block at a point; live loads are multiplied by λ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AppliedLoad3d {
    pub block: usize,
    pub at: Point3,
    pub force: Point3,
    pub moment: Point3,
    pub live: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Structure3d {
    pub blocks: Vec<SolidBlock>,
    pub supports: Vec<SolidSupport>,
    pub joints: Vec<SolidJoint>,
    pub loads: Vec<AppliedLoad3d>,
    /// Absolute geometric tolerance (m).
    pub tolerance: f64,
    /// Facets of the pyramid inscribed in each friction cone (default 8).
    pub friction_facets: usize,
}

/// Facets of the friction pyramid unless asked otherwise: within cos(π/8) = 92.4 % of the cone.
pub const DEFAULT_FRICTION_FACETS: usize = 8;

fn finite3(p: &[Point3]) -> bool {
    p.iter().all(|q| q.iter().all(|x| x.is_finite()))
}

impl Structure3d {
    /// Validate `model` and find its joints.
    pub fn new(model: &Model3d, opts: BuildOptions) -> Result<Structure3d> {
        if model.blocks.is_empty() {
            return model_err("the model has no blocks");
        }
        if model.supports.is_empty() {
            return model_err("the model has no supports: at least one foundation is needed");
        }
        let rel = relative_tolerance(opts.tolerance.or(model.tolerance))?;
        let all: Vec<Point3> = model
            .blocks
            .iter()
            .map(|b| &b.vertices)
            .chain(model.supports.iter().map(|s| &s.vertices))
            .filter(|v| finite3(v))
            .flatten()
            .copied()
            .collect();
        let diag = if all.is_empty() {
            1.0
        } else {
            let [lo, hi] = geometry3d::bbox3(&all);
            let d = Three::sub(hi, lo);
            Three::dot(d, d).sqrt()
        };
        if diag.is_infinite() {
            // Every coordinate is finite but the model's size is not: no length, area or
            // volume of it could be computed.
            return model_err(
                "the model's bounding-box diagonal overflows (coordinates too large for f64 arithmetic): scale the model",
            );
        }
        let tol = rel
            * if diag.is_finite() && diag > 0.0 {
                diag
            } else {
                1.0
            };
        check_materials(&model.materials)?;
        if let Some((name, _)) = model
            .materials
            .iter()
            .find(|(_, m)| m.compressive_strength.is_some())
        {
            return model_err(format!(
                "material '{name}': finite compressive strength is modelled in 2D only; remove compressive_strength from the 3D model"
            ));
        }

        let mut blocks = Vec::with_capacity(model.blocks.len());
        for (i, b) in model.blocks.iter().enumerate() {
            let what = format!("block {i}");
            if let Some(m) = &b.material {
                if m != "default" && !model.materials.contains_key(m) {
                    return model_err(format!("{what}: unknown material '{m}'"));
                }
            }
            let shape = geometry3d::clean_polyhedron(&what, &b.vertices, &b.faces, tol)?;
            let material = model.material_of(i);
            blocks.push(SolidBlock {
                weight: material.unit_weight * shape.volume,
                shape,
                material,
            });
        }
        let mut supports = Vec::with_capacity(model.supports.len());
        for (i, s) in model.supports.iter().enumerate() {
            check_support(
                i,
                &s.name,
                model.supports[..i].iter().map(|t| t.name.as_str()),
                &s.motion,
            )?;
            let what = format!("support '{}'", s.name);
            let shape = geometry3d::clean_polyhedron(&what, &s.vertices, &s.faces, tol)?;
            supports.push(SolidSupport {
                name: s.name.clone(),
                shape,
                motion: s.motion,
                connection: s.connection,
            });
        }
        let mut st = Structure3d {
            blocks,
            supports,
            joints: Vec::new(),
            loads: Vec::new(),
            tolerance: tol,
            friction_facets: DEFAULT_FRICTION_FACETS,
        };
        st.find_joints()?;
        st.loads = st.resolve_loads(model)?;
        Ok(st)
    }

    fn solids(&self) -> Vec<&Solid> {
        self.blocks
            .iter()
            .map(|b| &b.shape)
            .chain(self.supports.iter().map(|s| &s.shape))
            .collect()
    }

    fn body_label(&self, k: usize) -> String {
        let nb = self.blocks.len();
        if k < nb {
            format!("block {k}")
        } else {
            format!("support '{}'", self.supports[k - nb].name)
        }
    }

    fn find_joints(&mut self) -> Result<()> {
        let nb = self.blocks.len();
        let solids = self.solids();
        if let Some((p, q)) = geometry3d::find_overlap3(&solids, self.tolerance, &|_, _| false) {
            return model_err(format!(
                "{} and {} overlap",
                self.body_label(p),
                self.body_label(q)
            ));
        }
        let interfaces = geometry3d::detect_interfaces3(&solids, self.tolerance);
        let to_body = |k: usize| {
            if k < nb {
                Body::Block(k)
            } else {
                Body::Support(k - nb)
            }
        };
        let mut touched = vec![false; nb];
        let mut joints = Vec::with_capacity(interfaces.len());
        for it in interfaces {
            if it.a >= nb && it.b >= nb {
                continue; // support–support: nothing moves relative to anything
            }
            let (a, b) = (to_body(it.a), to_body(it.b));
            let mut bilateral = false;
            for body in [a, b] {
                match body {
                    Body::Block(i) => touched[i] = true,
                    Body::Support(s) => {
                        bilateral = self.supports[s].connection == Connection::Fixed
                    }
                }
            }
            joints.push(SolidJoint {
                a,
                b,
                normal: it.normal,
                points: it
                    .polygon
                    .iter()
                    .map(|&x| SolidPoint { x, gap: 0.0 })
                    .collect(),
                area: it.area,
                bilateral,
            });
        }
        if let Some(i) = touched.iter().position(|t| !t) {
            return model_err(format!(
                "block {i} touches nothing: it shares no face with another block or a support"
            ));
        }
        self.joints = joints;
        Ok(())
    }

    fn resolve_loads(&self, model: &Model3d) -> Result<Vec<AppliedLoad3d>> {
        let nb = self.blocks.len();
        let mut out = Vec::new();
        if model.loads.self_weight {
            for (i, b) in self.blocks.iter().enumerate() {
                if b.weight > 0.0 {
                    out.push(AppliedLoad3d {
                        block: i,
                        at: b.shape.centroid,
                        force: [0.0, 0.0, -b.weight],
                        moment: [0.0; 3],
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
                    Load3d::Point {
                        block,
                        at,
                        force,
                        moment,
                    } => {
                        check_load_block(&what, *block, nb)?;
                        if !finite3(&[*at, *force, *moment]) {
                            return model_err(format!("{what}: a value is not a finite number"));
                        }
                        out.push(AppliedLoad3d {
                            block: *block,
                            at: *at,
                            force: *force,
                            moment: *moment,
                            live,
                        });
                    }
                    Load3d::Face {
                        block,
                        face,
                        q,
                        per,
                    } => {
                        check_load_block(&what, *block, nb)?;
                        let given = &model.blocks[*block];
                        let Some(f) = given.faces.get(*face) else {
                            return model_err(format!("{what}: block {block} has no face {face}"));
                        };
                        if !q.is_finite() {
                            return model_err(format!("{what}: q is not a finite number"));
                        }
                        let pts: Vec<Point3> = f.iter().map(|&v| given.vertices[v]).collect();
                        let (area, centroid) = face_area_centroid(&pts);
                        let measure = match per {
                            PerArea::Area => Three::dot(area, area).sqrt(),
                            PerArea::Horizontal => area[2].abs(),
                        };
                        out.push(AppliedLoad3d {
                            block: *block,
                            at: centroid,
                            force: [0.0, 0.0, -q * measure],
                            moment: [0.0; 3],
                            live,
                        });
                    }
                    Load3d::Body {
                        coefficients,
                        blocks,
                    } => {
                        if !finite3(&[*coefficients]) {
                            return model_err(format!(
                                "{what}: a coefficient is not a finite number"
                            ));
                        }
                        for b in body_load_blocks(&what, blocks, nb)? {
                            let w = self.blocks[b].weight;
                            out.push(AppliedLoad3d {
                                block: b,
                                at: self.blocks[b].shape.centroid,
                                force: coefficients.map(|c| w * c),
                                moment: [0.0; 3],
                                live,
                            });
                        }
                    }
                }
            }
        }
        Ok(out)
    }

    /// The finite rigid motion of a body for mechanism `d` scaled by `s`: rotation by the
    /// rotation vector `s·θ` (exact, `nalgebra`'s exponential map) about the body's centroid,
    /// then translation by `s·u`.
    fn rigid_motion(&self, b: Body, d: &[f64], s: f64) -> (Point3, Rotation3<f64>, Point3) {
        let (c, m): (Point3, &[f64]) = match b {
            Body::Block(i) => (self.blocks[i].shape.centroid, &d[6 * i..6 * i + 6]),
            Body::Support(k) => (self.supports[k].shape.centroid, &self.supports[k].motion),
        };
        let rot = Rotation3::from_scaled_axis(Vector3::new(s * m[3], s * m[4], s * m[5]));
        (c, rot, [s * m[0], s * m[1], s * m[2]])
    }
}

/// Vector area (Newell: `½ Σ xᵢ × xᵢ₊₁`, its length the area, its direction the normal) and
/// centroid of a planar polygon in 3D (fan triangles weighted by their signed areas along the
/// normal, exact for non-convex polygons).
fn face_area_centroid(p: &[Point3]) -> (Point3, Point3) {
    let n = p.len();
    let mut area = [0.0; 3];
    for k in 0..n {
        let c = cross(p[k], p[(k + 1) % n]);
        for i in 0..3 {
            area[i] += 0.5 * c[i];
        }
    }
    let len = Three::dot(area, area).sqrt();
    if !(len > 0.0) {
        return (area, p[0]);
    }
    let unit = area.map(|a| a / len);
    let o = p[0];
    let (mut centroid, mut total) = ([0.0; 3], 0.0);
    for k in 1..n.saturating_sub(1) {
        let a = 0.5 * Three::dot(cross(Three::sub(p[k], o), Three::sub(p[k + 1], o)), unit);
        for c in 0..3 {
            centroid[c] += a * (o[c] + p[k][c] + p[k + 1][c]) / 3.0;
        }
        total += a;
    }
    (area, centroid.map(|c| c / total))
}

fn apply(c: Point3, rot: &Rotation3<f64>, t: Point3, x: Point3) -> Point3 {
    let r = rot * Vector3::new(x[0] - c[0], x[1] - c[1], x[2] - c[2]);
    [c[0] + t[0] + r[0], c[1] + t[1] + r[1], c[2] + t[2] + r[2]]
}

fn polyhedron(s: &Solid) -> Polyhedron {
    Polyhedron {
        vertices: s.vertices.clone(),
        faces: s.faces.clone(),
    }
}

impl Assembly for Structure3d {
    type D = Three;

    assembly_parts!();

    fn kinematic_map(&self) -> crate::discretize::KinematicMap {
        let mut map = crate::discretize::KinematicMap::assemble(
            &self.contact_bodies(),
            &self.contact_joints(),
        );
        map.friction_facets = self.friction_facets;
        map
    }

    fn contact_bodies(&self) -> ContactBodies<Three> {
        ContactBodies {
            blocks: self.blocks.iter().map(|b| b.shape.centroid).collect(),
            supports: self
                .supports
                .iter()
                .map(|s| (s.shape.centroid, s.motion.to_vec()))
                .collect(),
        }
    }

    fn contact_joints(&self) -> Vec<ContactJoint<Three>> {
        self.joints
            .iter()
            .map(|joint| {
                let mats = joint_materials([joint.a, joint.b], |i| &self.blocks[i].material);
                ContactJoint {
                    a: joint.a,
                    b: joint.b,
                    normal: joint.normal,
                    tangents: Three::tangents(joint.normal),
                    points: joint.points.iter().map(|p| (p.x, p.gap)).collect(),
                    bilateral: joint.bilateral,
                    // Depth and width describe the 2D crushing domain only.
                    law: JointLaw::between(&mats, 0.0, 0.0, joint.area, joint.points.len()),
                    along: vec![],
                }
            })
            .collect()
    }

    fn load_vector(&self, live: bool) -> Vec<f64> {
        let mut f = vec![0.0; 6 * self.blocks.len()];
        let mut row = [0.0; 6];
        for l in self.loads.iter().filter(|l| l.live == live) {
            let c = self.blocks[l.block].shape.centroid;
            let r = Three::sub(l.at, c);
            let m = cross(r, l.force);
            for k in 0..3 {
                row[k] = l.force[k];
                row[3 + k] = m[k] + l.moment[k];
            }
            for (k, v) in row.iter().enumerate() {
                f[6 * l.block + k] += v;
            }
        }
        f
    }

    fn has_live_loads(&self) -> bool {
        self.loads
            .iter()
            .any(|l| l.live && l.force.iter().chain(&l.moment).any(|&x| x != 0.0))
    }

    fn with_weight_as_live_load(&self, direction: Point3) -> Result<Structure3d> {
        let mut s = self.clone();
        s.loads.retain(|l| !l.live);
        let live: Vec<AppliedLoad3d> = s
            .blocks
            .iter()
            .enumerate()
            .filter(|(_, b)| b.weight > 0.0)
            .map(|(i, b)| AppliedLoad3d {
                block: i,
                at: b.shape.centroid,
                force: direction.map(|x| x * b.weight),
                moment: [0.0; 3],
                live: true,
            })
            .collect();
        if live.is_empty() {
            return Err(Error::Request(
                "tilt analysis needs blocks with weight".into(),
            ));
        }
        s.loads.extend(live);
        Ok(s)
    }

    fn cracks(
        &self,
        joints: &[crate::result::JointResult<crate::dim::Three>],
        open: &[Vec<bool>],
        widths: &[Vec<f64>],
    ) -> Vec<crate::result::Crack3d> {
        crate::result::cracks::crack_records_3d(joints, open, widths, self.tolerance)
    }

    fn shapes(&self) -> SpatialShapes {
        SpatialShapes {
            blocks: self.blocks.iter().map(|b| polyhedron(&b.shape)).collect(),
            centroids: self.blocks.iter().map(|b| b.shape.centroid).collect(),
            supports: self
                .supports
                .iter()
                .map(|s| SupportSolid {
                    name: s.name.clone(),
                    vertices: s.shape.vertices.clone(),
                    faces: s.shape.faces.clone(),
                    motion: s.motion,
                    fixed: s.connection == Connection::Fixed,
                })
                .collect(),
            loads: self
                .loads
                .iter()
                .map(|l| LoadArrow3d {
                    block: l.block,
                    x: l.at[0],
                    y: l.at[1],
                    z: l.at[2],
                    fx: l.force[0],
                    fy: l.force[1],
                    fz: l.force[2],
                    live: l.live,
                })
                .collect(),
        }
    }

    fn settlement_magnitude(&self) -> f64 {
        let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
        let t = self
            .supports
            .iter()
            .fold(0.0f64, |m, s| m.max(norm(&s.motion[..3])));
        if t > 0.0 {
            t
        } else {
            self.supports
                .iter()
                .fold(0.0f64, |m, s| m.max(norm(&s.motion[3..])))
        }
    }

    /// Blocks and supports move by their exact finite rigid motions; each contact point goes
    /// to the mean of its images on the two sides, the joint's normal turns by the mean of the
    /// two rotation vectors, and loads move with their blocks (directions kept).
    fn deformed(&self, d: &[f64], s: f64, openings: &[Vec<f64>], gap_tol: f64) -> Structure3d {
        let mut out = self.clone();
        let move_solid = |shape: &mut Solid, (c, rot, t): (Point3, Rotation3<f64>, Point3)| {
            for v in shape.vertices.iter_mut() {
                *v = apply(c, &rot, t, *v);
            }
            shape.centroid = apply(c, &rot, t, shape.centroid);
        };
        for i in 0..out.blocks.len() {
            move_solid(
                &mut out.blocks[i].shape,
                self.rigid_motion(Body::Block(i), d, s),
            );
        }
        for k in 0..out.supports.len() {
            move_solid(
                &mut out.supports[k].shape,
                self.rigid_motion(Body::Support(k), d, s),
            );
            out.supports[k].motion = [0.0; 6];
        }
        for (j, joint) in out.joints.iter_mut().enumerate() {
            let (ca, ra, ta) = self.rigid_motion(joint.a, d, s);
            let (cb, rb, tb) = self.rigid_motion(joint.b, d, s);
            let mean = Rotation3::from_scaled_axis(0.5 * (ra.scaled_axis() + rb.scaled_axis()));
            let n = mean * Vector3::from(joint.normal);
            joint.normal = [n[0], n[1], n[2]];
            for (k, p) in joint.points.iter_mut().enumerate() {
                let (xa, xb) = (apply(ca, &ra, ta, p.x), apply(cb, &rb, tb, p.x));
                p.x = [0, 1, 2].map(|c| 0.5 * (xa[c] + xb[c]));
                p.gap = moved_gap(p.gap, s, openings, (j, k), gap_tol);
            }
        }
        for l in out.loads.iter_mut() {
            let (c, rot, t) = self.rigid_motion(Body::Block(l.block), d, s);
            l.at = apply(c, &rot, t, l.at);
        }
        out
    }

    fn release_fixed(&mut self) {
        for j in self.joints.iter_mut() {
            if [j.a, j.b].iter().any(
                |b| matches!(b, Body::Support(k) if self.supports[*k].connection == Connection::Fixed),
            ) {
                j.bilateral = false;
            }
        }
        for sp in self.supports.iter_mut() {
            sp.connection = Connection::Contact;
        }
    }
}
