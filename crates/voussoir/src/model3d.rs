//! The user's description of a 3D structure: blocks and supports as closed polyhedra.
//!
//! Units are SI as in 2D (m, kN, kN/m³, kPa, rad). In 3D **z is up** and gravity acts along −z
//! (COMPAS's and Rhino's convention). A model is 3D when its blocks have `vertices` and `faces`
//! instead of a `polygon` ([`AnyModel::from_json`]); every 2D model reads as before.
//!
//! A polyhedron is a list of `vertices` `[[x, y, z], …]` and `faces`, each a list of vertex
//! indices, counter-clockwise seen from outside (a consistently inward list is turned round on
//! loading, like 2D's clockwise polygons). Faces must be planar (within the tolerance), the
//! surface closed and manifold; the block may be convex or not. Volume, centroid and weight
//! come from the divergence theorem. A material's `width` has no meaning in 3D and is ignored.

use crate::model::{Connection, Material};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A 3D point or vector `[x, y, z]`.
pub type Point3 = [f64; 3];

/// A closed polyhedral surface.
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Polyhedron {
    pub vertices: Vec<Point3>,
    /// Faces as vertex index lists, counter-clockwise seen from outside.
    pub faces: Vec<Vec<usize>>,
}

/// A rigid, no-tension block structure in 3D.
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Model3d {
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub description: String,
    /// Materials by name (as in 2D; `width` is ignored).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub materials: BTreeMap<String, Material>,
    /// The blocks (rigid bodies with six degrees of freedom each). A block's id is its index.
    pub blocks: Vec<Block3d>,
    /// Foundations: rigid bodies whose motion is prescribed.
    pub supports: Vec<Support3d>,
    #[serde(default)]
    pub loads: Loads3d,
    /// Geometric tolerance, relative to the model's bounding-box diagonal (default 1e-7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

/// A block: a closed polyhedron.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Block3d {
    pub vertices: Vec<Point3>,
    /// Faces as vertex index lists, counter-clockwise seen from outside.
    pub faces: Vec<Vec<usize>>,
    /// Material name (default `"default"`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<String>,
}

/// A foundation: a closed polyhedron with a prescribed motion.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Support3d {
    /// Unique name (`--move NAME=u,v,w[,θx,θy,θz]`).
    pub name: String,
    pub vertices: Vec<Point3>,
    pub faces: Vec<Vec<usize>>,
    /// Prescribed motion `[u, v, w, θx, θy, θz]`: translation (m) of the support's centroid and
    /// rotation vector (rad, right-handed) about it. Default: no motion.
    #[serde(default, skip_serializing_if = "is_still")]
    pub motion: [f64; 6],
    /// `contact` (default) or `fixed`.
    #[serde(default, skip_serializing_if = "is_contact")]
    pub connection: Connection,
}

fn is_still(m: &[f64; 6]) -> bool {
    m.iter().all(|&x| x == 0.0)
}
fn is_contact(c: &Connection) -> bool {
    *c == Connection::Contact
}
fn is_true(b: &bool) -> bool {
    *b
}
fn yes() -> bool {
    true
}
fn is_zero3(v: &Point3) -> bool {
    v.iter().all(|&x| x == 0.0)
}

/// Dead loads (always present) and live loads (multiplied by λ).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Loads3d {
    /// Self-weight of every block as a dead load along −z (default true).
    #[serde(default = "yes", skip_serializing_if = "is_true")]
    pub self_weight: bool,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub dead: Vec<Load3d>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub live: Vec<Load3d>,
}

impl Default for Loads3d {
    fn default() -> Self {
        Loads3d {
            self_weight: true,
            dead: Vec::new(),
            live: Vec::new(),
        }
    }
}

/// How a face pressure is measured.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "lowercase")]
pub enum PerArea {
    /// Per unit horizontal projection of the face (snow, fill).
    #[default]
    Horizontal,
    /// Per unit area of the face.
    Area,
}

/// One load on a 3D model.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
pub enum Load3d {
    /// A force `[fx, fy, fz]` (kN) at point `at` of block `block`, and optionally a moment
    /// `[mx, my, mz]` (kN·m).
    Point {
        block: usize,
        at: Point3,
        force: Point3,
        #[serde(default, skip_serializing_if = "is_zero3")]
        moment: Point3,
    },
    /// A vertical pressure `q` (kN/m², positive downwards) on face `face` of block `block`
    /// (faces numbered as given), per unit horizontal projection or per unit area; its
    /// resultant acts at the face's centroid.
    Face {
        block: usize,
        face: usize,
        q: f64,
        #[serde(default)]
        per: PerArea,
    },
    /// A force `W·[cx, cy, cz]` proportional to each block's weight `W`, at its centroid
    /// (`[cos a, sin a, 0]` is the tilting-table load along azimuth `a`). `blocks` absent:
    /// every block.
    Body {
        coefficients: Point3,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        blocks: Option<Vec<usize>>,
    },
}

impl Model3d {
    /// The material of block `i` (the named one, `"default"`, or the built-in default).
    pub fn material_of(&self, i: usize) -> Material {
        let name = self.blocks[i].material.as_deref().unwrap_or("default");
        self.materials.get(name).cloned().unwrap_or_default()
    }

    /// Index of the support named `name`.
    pub fn support_index(&self, name: &str) -> Option<usize> {
        self.supports.iter().position(|s| s.name == name)
    }

    /// One-line notes about a valid model (as [`crate::Model::warnings`]).
    pub fn warnings(&self) -> Vec<String> {
        let implicit = self
            .blocks
            .iter()
            .filter(|b| b.material.as_deref().unwrap_or("default") == "default")
            .count();
        if implicit > 0 && !self.materials.contains_key("default") {
            vec![format!(
                "{implicit} block(s) use the material 'default', which the model does not define: they weigh {} kN/m³ (voussoir's built-in default); give materials.default to say so",
                Material::default().unit_weight
            )]
        } else {
            vec![]
        }
    }

    /// As [`crate::Model::override_joint_laws`].
    pub fn override_joint_laws(
        &mut self,
        friction: Option<f64>,
        compressive_strength: Option<f64>,
    ) {
        crate::model::override_joint_laws(&mut self.materials, friction, compressive_strength);
    }
}

/// A model of either dimension, as read from JSON.
#[derive(Clone, Debug, PartialEq)]
pub enum AnyModel {
    Planar(crate::Model),
    Spatial(Model3d),
}

impl AnyModel {
    /// Parse a JSON model: 3D if its first block (or, without blocks, first support) has
    /// `vertices`, 2D otherwise. Unknown fields are rejected in both.
    pub fn from_json(text: &str) -> std::result::Result<AnyModel, String> {
        // serde's messages quote the unknown field as written: one line whatever it holds.
        let err = |e: serde_json::Error| crate::error::one_line(&e.to_string()).into_owned();
        let v: serde_json::Value = serde_json::from_str(text).map_err(err)?;
        let has_vertices = |key: &str| {
            v.get(key)
                .and_then(|b| b.as_array())
                .and_then(|a| a.first())
                .is_some_and(|b| b.get("vertices").is_some())
        };
        // Parsed again from the text (not from the value) so that errors keep their line and
        // column.
        if has_vertices("blocks") || has_vertices("supports") {
            serde_json::from_str::<Model3d>(text)
                .map(AnyModel::Spatial)
                .map_err(err)
        } else {
            serde_json::from_str::<crate::Model>(text)
                .map(AnyModel::Planar)
                .map_err(err)
        }
    }
}
