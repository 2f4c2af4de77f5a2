//! The user's description of a structure: blocks, supports, materials and loads.
//!
//! Units are SI throughout: metres, kilonewtons, kN/m³, kPa. `x` points right, `y` up,
//! gravity acts along −y. Angles are radians inside the library.
//!
//! The JSON schema is the serde form of [`Model`]; unknown fields are rejected.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A 2D point or vector `[x, y]`.
pub type Point = [f64; 2];

/// A rigid, no-tension block structure.
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Model {
    /// Free text: what this model is.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub description: String,
    /// Materials by name. A block without a `material` uses `"default"`, and if no material of that
    /// name is given, `unit_weight` 18 kN/m³ and `width` 1 m.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub materials: BTreeMap<String, Material>,
    /// The blocks (rigid bodies with three degrees of freedom each). A block's id is its index.
    pub blocks: Vec<Block>,
    /// Foundations: rigid bodies whose motion is prescribed.
    pub supports: Vec<Support>,
    /// Dead and live loads.
    #[serde(default)]
    pub loads: Loads,
    /// Geometric tolerance for interface detection, relative to the model's bounding-box
    /// diagonal (default 1e-7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Cracks the structure already has (a survey): each point they name starts with that gap
    /// and carries no force until it closes (the paper's initial gap Δ, equations 42 and 58).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub cracks: Vec<ExistingCrack>,
}

/// A crack width: one number (a point, or every point of a joint) or one per joint point.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Width {
    One(f64),
    PerPoint(Vec<f64>),
}

impl Default for Width {
    fn default() -> Self {
        Width::One(0.0)
    }
}

impl Width {
    /// Every width finite and ≥ 0, else the one-line reason (in `unit`).
    pub fn check(&self, unit: &str) -> Result<(), String> {
        let all = match self {
            Width::One(w) => std::slice::from_ref(w),
            Width::PerPoint(v) => v.as_slice(),
        };
        match all.iter().find(|w| !(w.is_finite() && **w >= 0.0)) {
            Some(w) => Err(format!("width {w} must be a finite number ≥ 0 ({unit})")),
            None => Ok(()),
        }
    }

    /// The crack as `(joint, point, width × scale)` over every point of joint `j`, which has
    /// `points` points (`None`: there is no joint `j` among `joints`): one width for all, or
    /// one per point, counted against the joint's. 2D and 3D cracks given by `joint` alike.
    pub fn on_joint(
        &self,
        j: usize,
        points: Option<usize>,
        joints: usize,
        scale: f64,
    ) -> Result<Vec<(usize, usize, f64)>, String> {
        let Some(n) = points else {
            return Err(format!(
                "joint {j} does not exist (the structure has {joints} joints)"
            ));
        };
        match self {
            Width::One(w) => Ok((0..n).map(|k| (j, k, *w * scale)).collect()),
            Width::PerPoint(v) if v.len() != n => Err(format!(
                "joint {j} has {n} points, {} widths given",
                v.len()
            )),
            Width::PerPoint(v) => Ok(v
                .iter()
                .enumerate()
                .map(|(k, &w)| (j, k, w * scale))
                .collect()),
        }
    }
}

/// Metres per unit of a length unit named in a crack survey: `"m"`, `"cm"` or `"mm"` (also
/// spelt out: `"millimetres"`, …). `None` for anything else.
pub fn length_unit(name: &str) -> Option<f64> {
    match name.trim().to_ascii_lowercase().as_str() {
        "m" | "metre" | "metres" | "meter" | "meters" => Some(1.0),
        "cm" | "centimetre" | "centimetres" | "centimeter" | "centimeters" => Some(1e-2),
        "mm" | "millimetre" | "millimetres" | "millimeter" | "millimeters" => Some(1e-3),
        _ => None,
    }
}

/// Metres per unit of the optional unit `name` given in `field` of `what` (default metres);
/// an unknown unit is refused in one line naming the field.
pub fn length_unit_of(what: &str, field: &str, name: Option<&str>) -> Result<f64, String> {
    match name {
        None => Ok(1.0),
        Some(n) => length_unit(n).ok_or_else(|| {
            format!("{what}: \"{field}\": unknown unit \"{n}\" (give \"m\", \"cm\" or \"mm\")")
        }),
    }
}

crack_record! {
    /// A crack measured in the structure as it stands. Exactly one of `at` (the nearest
    /// collocation point of any joint: the surveyor's coordinates, in m), `joint` (a joint id:
    /// widths at its points in order, start then end, or one width for all of them) and
    /// `polyline` (a crack line as drawn: every joint point within `snap` of it, default a quarter
    /// of the point's joint length; one width, or two at its start and end, interpolated along it).
    #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct ExistingCrack {
        {
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub at: Option<[f64; 2]>,
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub joint: Option<usize>,
            /// A crack line `[[x, y], …]` (m).
            #[serde(default, alias = "points", skip_serializing_if = "Option::is_none")]
            pub polyline: Option<Vec<[f64; 2]>>,
            /// Catch distance of a `polyline` (m); default a quarter of each point's joint length.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub snap: Option<f64>,
            /// Width (≥ 0), in `units`.
            #[serde(alias = "openings")]
            pub opening: Width,
        }
        {
            /// Unit of the width: `"m"` (default), `"cm"` or `"mm"`. Coordinates stay in metres.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub units: Option<String>,
        }
    }
}

/// Material of a block.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Unit weight γ in kN/m³.
    pub unit_weight: f64,
    /// Out-of-plane width in m (default 1).
    #[serde(default = "one")]
    pub width: f64,
    /// Compressive strength f_c in kPa (absent: infinite, Heyman's hypothesis).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compressive_strength: Option<f64>,
    /// Coulomb friction coefficient μ (absent: infinite, no sliding).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction: Option<f64>,
    /// Cohesion c in kPa (default 0).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub cohesion: f64,
}

fn one() -> f64 {
    1.0
}
fn is_zero(x: &f64) -> bool {
    *x == 0.0
}
fn is_true(b: &bool) -> bool {
    *b
}
fn yes() -> bool {
    true
}

impl Default for Material {
    fn default() -> Self {
        Material {
            unit_weight: 18.0,
            width: 1.0,
            compressive_strength: None,
            friction: None,
            cohesion: 0.0,
        }
    }
}

/// A rigid block: a simple polygon (convex or not).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Block {
    /// Vertices, counter-clockwise (a clockwise list is reversed on loading).
    pub polygon: Vec<Point>,
    /// Material name (default `"default"`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<String>,
}

/// How a support is connected to the blocks resting on it.
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum Connection {
    /// A unilateral joint like any other: no tension, no sliding (Heyman).
    #[default]
    Contact,
    /// Bilateral: the blocks' faces follow the support (the paper's essential boundary condition).
    Fixed,
}

/// A foundation: a rigid body with a prescribed motion.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Support {
    /// Unique name, used on the command line (`--move NAME=u,v`).
    pub name: String,
    /// Vertices, counter-clockwise.
    pub polygon: Vec<Point>,
    /// Prescribed motion `[u, v, θ]`: translation in m of the polygon's centroid and rotation in
    /// radians (counter-clockwise) about it. Default: no motion.
    #[serde(default, skip_serializing_if = "is_still")]
    pub motion: [f64; 3],
    /// `contact` (default) or `fixed`.
    #[serde(default, skip_serializing_if = "is_contact")]
    pub connection: Connection,
}

fn is_still(m: &[f64; 3]) -> bool {
    m.iter().all(|&x| x == 0.0)
}
fn is_contact(c: &Connection) -> bool {
    *c == Connection::Contact
}

/// Dead loads (always present) and live loads (multiplied by the load multiplier λ).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Loads {
    /// Self-weight of every block as a dead load (default true).
    #[serde(default = "yes", skip_serializing_if = "is_true")]
    pub self_weight: bool,
    /// Extra dead loads.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub dead: Vec<Load>,
    /// Live loads, multiplied by λ.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub live: Vec<Load>,
}

impl Default for Loads {
    fn default() -> Self {
        Loads {
            self_weight: true,
            dead: Vec::new(),
            live: Vec::new(),
        }
    }
}

/// How a distributed edge load is measured.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "lowercase")]
pub enum Per {
    /// Per unit horizontal projection of the edge (kN/m² × width).
    #[default]
    Horizontal,
    /// Per unit length of the edge.
    Length,
}

/// One load.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
pub enum Load {
    /// A force `[fx, fy]` in kN applied at point `at` of block `block`.
    Point {
        block: usize,
        at: Point,
        force: Point,
    },
    /// A vertical pressure `q` (kN/m², positive downwards) on edge `edge` of block `block`
    /// (edge k runs from vertex k to vertex k+1 of the block's counter-clockwise polygon),
    /// per unit horizontal projection or per unit length, times the block's width.
    Edge {
        block: usize,
        edge: usize,
        q: f64,
        #[serde(default)]
        per: Per,
    },
    /// A force proportional to each block's weight W, at its centroid: `W·[cx, cy]`
    /// (`[1, 0]` is the tilting-table horizontal load). `blocks` absent: every block.
    Body {
        coefficients: Point,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        blocks: Option<Vec<usize>>,
    },
}

impl Model {
    /// The material of block `i` (the named one, `"default"`, or the built-in default).
    pub fn material_of(&self, i: usize) -> Material {
        let name = self.blocks[i].material.as_deref().unwrap_or("default");
        self.materials.get(name).cloned().unwrap_or_default()
    }

    /// Things in a valid model that an engineer should know, one line each: today, blocks that
    /// take the built-in default material (18 kN/m³, width 1 m) because the model defines no
    /// material named `"default"`.
    pub fn warnings(&self) -> Vec<String> {
        let implicit = self
            .blocks
            .iter()
            .filter(|b| b.material.as_deref().unwrap_or("default") == "default")
            .count();
        if implicit > 0 && !self.materials.contains_key("default") {
            let d = Material::default();
            vec![format!(
                "{implicit} block(s) use the material 'default', which the model does not define: they weigh {} kN/m³ with width {} m (voussoir's built-in default); give materials.default to say so",
                d.unit_weight, d.width
            )]
        } else {
            vec![]
        }
    }

    /// Give every material (the implicit `"default"` included) the friction μ and/or the
    /// compressive strength f_c given (the front ends' `--friction`, `--compressive-strength`);
    /// `None` leaves the model's values.
    pub fn override_joint_laws(
        &mut self,
        friction: Option<f64>,
        compressive_strength: Option<f64>,
    ) {
        override_joint_laws(&mut self.materials, friction, compressive_strength);
    }

    /// Index of the support named `name`.
    pub fn support_index(&self, name: &str) -> Option<usize> {
        self.supports.iter().position(|s| s.name == name)
    }
}

/// Give every material of `materials` (the implicit `"default"` included) the friction μ and/or
/// the compressive strength f_c given; `None` leaves the values (2D and 3D models alike).
pub fn override_joint_laws(
    materials: &mut BTreeMap<String, Material>,
    friction: Option<f64>,
    compressive_strength: Option<f64>,
) {
    if friction.is_none() && compressive_strength.is_none() {
        return;
    }
    materials.entry("default".to_string()).or_default();
    for mat in materials.values_mut() {
        if friction.is_some() {
            mat.friction = friction;
        }
        if compressive_strength.is_some() {
            mat.compressive_strength = compressive_strength;
        }
    }
}
