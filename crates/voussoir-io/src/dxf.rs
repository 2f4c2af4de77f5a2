//! DXF import: closed polylines become blocks, some of them supports.
//!
//! * Every closed `LWPOLYLINE` and 2D `POLYLINE` of model space is one rigid block. A polyline
//!   whose closing flag is not set but whose last vertex repeats its first (within the merge
//!   tolerance) counts as closed, as many CAD exports draw blocks that way. Arc segments (bulges)
//!   are replaced by chords of at most 5°.
//! * Supports are the polygons on the layers given in [`DxfOptions::support_layers`] or with the
//!   handles in [`DxfOptions::support_handles`]; with neither, the lowest polygon (smallest y),
//!   and among those the widest, is the one support `base` (the LACT3 convention).
//! * Coordinates are scaled to metres from the drawing units: [`DxfOptions::units`] if given,
//!   else the header's `$INSUNITS` when it is mm, cm or m; any other declared unit is an error
//!   asking for `--units`, because CAD templates often declare inches for drawings made in mm.
//! * Vertices closer than the merge tolerance are snapped together (grid hashing, linear time),
//!   so that the faces of neighbouring blocks coincide exactly.
//! * An open or self-intersecting polyline is an error naming the entity by its handle.
//!
//! * The lines of the layers in [`DxfOptions::crack_layers`] are the model's existing cracks,
//!   read as a crack survey ([`crate::survey`]: a width per line from its label or its layer's
//!   name); those layers give no blocks.
//!
//! DXF carries no loads: the model gets self-weight with the given unit weight and, if asked,
//! the tilting-table live load (a horizontal force equal to each block's weight).

use crate::files::IoError;
use dxf::entities::{Entity, EntityType};
use dxf::enums::Units as DxfUnits;
use dxf::Drawing;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;
use voussoir::geometry::{bbox, self_intersection, signed_area};
use voussoir::model::{Block, Load, Loads, Material, Model, Point, Support};

/// Length unit of the drawing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Units {
    Mm,
    Cm,
    M,
}

impl Units {
    /// Metres per drawing unit.
    pub fn scale(self) -> f64 {
        match self {
            Units::Mm => 1e-3,
            Units::Cm => 1e-2,
            Units::M => 1.0,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            Units::Mm => "mm",
            Units::Cm => "cm",
            Units::M => "m",
        }
    }
}

impl std::str::FromStr for Units {
    type Err = IoError;
    fn from_str(s: &str) -> Result<Units, IoError> {
        match s.trim().to_ascii_lowercase().as_str() {
            "mm" | "millimetres" | "millimeters" => Ok(Units::Mm),
            "cm" | "centimetres" | "centimeters" => Ok(Units::Cm),
            "m" | "metres" | "meters" => Ok(Units::M),
            _ => Err(IoError(format!(
                "unknown drawing unit '{s}': expected mm, cm or m"
            ))),
        }
    }
}

/// Live load added to an imported model.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum ImportLive {
    /// No live load.
    None,
    /// The tilting-table load: a horizontal force equal to each block's weight, along +x.
    #[default]
    Horizontal,
}

/// How to read a drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct DxfOptions {
    /// Drawing units (None: from `$INSUNITS`, which must then be mm, cm or m).
    pub units: Option<Units>,
    /// Unit weight γ of the blocks, kN/m³.
    pub unit_weight: f64,
    /// Out-of-plane width, m.
    pub width: f64,
    /// Layers whose polygons are supports.
    pub support_layers: Vec<String>,
    /// Handles (hexadecimal, as in the DXF) of polygons that are supports.
    pub support_handles: Vec<String>,
    /// Vertex merging tolerance in metres (None: 1e-6 of the drawing's bounding-box diagonal).
    pub merge_tolerance: Option<f64>,
    pub live: ImportLive,
    /// Layers of crack lines, the model's existing cracks (case-insensitive; `PREFIX*`).
    pub crack_layers: Vec<String>,
}

impl Default for DxfOptions {
    fn default() -> Self {
        DxfOptions {
            units: None,
            unit_weight: 18.0,
            width: 1.0,
            support_layers: Vec::new(),
            support_handles: Vec::new(),
            merge_tolerance: None,
            live: ImportLive::Horizontal,
            crack_layers: Vec::new(),
        }
    }
}

/// What the import found, beside the model.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ImportReport {
    /// Units used and metres per drawing unit.
    pub units: String,
    pub scale: f64,
    /// Entity type and handle of each block (by block index) and of each support.
    pub block_entities: Vec<String>,
    pub support_entities: Vec<String>,
    /// Entity of each existing crack (by index in the model's cracks), from the crack layers.
    pub crack_entities: Vec<String>,
    /// Entities of other types that were skipped, by type.
    pub ignored: BTreeMap<String, usize>,
    /// Number of vertices moved by merging, and the tolerance used (m).
    pub merged_vertices: usize,
    pub merge_tolerance: f64,
    /// Repairs made while reading (one line each).
    pub notes: Vec<String>,
    /// Things that look wrong but are not errors (one line each): units whose blocks come out
    /// of masonry size.
    pub warnings: Vec<String>,
}

impl ImportReport {
    /// Append the DXF entity to every "block N" that a message names, so that an error found
    /// later (an overlap, a block that touches nothing) points into the drawing.
    pub fn annotate(&self, msg: &str) -> String {
        let mut out = crate::dxf::annotate_blocks(msg, &self.block_entities);
        for (i, e) in self.crack_entities.iter().enumerate().rev() {
            out = out.replace(&format!("cracks[{i}]"), &format!("cracks[{i}] ({e})"));
        }
        out
    }

    /// One line: what was imported.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "{} blocks, {} support(s) [{}], units {} ({} m per unit), {} vertices merged within {:.1e} m",
            self.block_entities.len(),
            self.support_entities.len(),
            self.support_entities.join(", "),
            self.units,
            self.scale,
            self.merged_vertices,
            self.merge_tolerance
        );
        if !self.ignored.is_empty() {
            let list: Vec<String> = self
                .ignored
                .iter()
                .map(|(k, n)| format!("{n} {k}"))
                .collect();
            s.push_str(&format!("; ignored: {}", list.join(", ")));
        }
        if !self.crack_entities.is_empty() {
            s.push_str(&format!(
                "; {} existing crack line(s)",
                self.crack_entities.len()
            ));
        }
        s
    }
}

/// A polygon read from the drawing, before scaling.
pub(crate) struct RawPolygon {
    pub(crate) what: String,
    pub(crate) handle: String,
    pub(crate) layer: String,
    pub(crate) points: Vec<Point>,
    /// Whether the closing flag is set.
    pub(crate) closed: bool,
}

fn handle_hex(e: &Entity) -> String {
    format!("{:X}", e.common.handle.0)
}

/// Vertices of a polyline with bulges replaced by chords (at most 5° of arc each).
pub(crate) fn expand_bulges(v: &[(Point, f64)], closed: bool) -> Vec<Point> {
    let n = v.len();
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let (p, bulge) = v[i];
        out.push(p);
        let last = i + 1 == n;
        if bulge == 0.0 || !bulge.is_finite() || (last && !closed) {
            continue;
        }
        let q = v[(i + 1) % n].0;
        // Included angle 4·atan(bulge), counter-clockwise when positive.
        let angle = 4.0 * bulge.atan();
        let chord = [q[0] - p[0], q[1] - p[1]];
        let c = chord[0].hypot(chord[1]);
        if c == 0.0 {
            continue;
        }
        let r = c / (2.0 * (angle / 2.0).sin()).abs();
        // Centre: midpoint plus the perpendicular offset.
        let mid = [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
        let h = (r * r - c * c / 4.0).max(0.0).sqrt();
        let nrm = [-chord[1] / c, chord[0] / c];
        // For |angle| < π the centre lies on the left of p→q for a ccw (positive) bulge.
        let s = if (angle > 0.0) == (angle.abs() < std::f64::consts::PI) {
            1.0
        } else {
            -1.0
        };
        let centre = [mid[0] + s * h * nrm[0], mid[1] + s * h * nrm[1]];
        let a0 = (p[1] - centre[1]).atan2(p[0] - centre[0]);
        let steps = ((angle.abs() / 5f64.to_radians()).ceil() as usize).max(1);
        for k in 1..steps {
            let a = a0 + angle * k as f64 / steps as f64;
            out.push([centre[0] + r * a.cos(), centre[1] + r * a.sin()]);
        }
    }
    out
}

pub(crate) fn collect(
    drawing: &Drawing,
    ignored: &mut BTreeMap<String, usize>,
    crack_layers: &[String],
) -> Result<Vec<RawPolygon>, IoError> {
    let mut out = Vec::new();
    for e in drawing.entities() {
        if e.common.is_in_paper_space {
            *ignored.entry("paper-space entities".into()).or_default() += 1;
            continue;
        }
        // The crack layers are read as a survey, not as blocks.
        if !crack_layers.is_empty() && crate::survey::on_layer(&e.common.layer, crack_layers) {
            continue;
        }
        let handle = handle_hex(e);
        let layer = e.common.layer.clone();
        match &e.specific {
            EntityType::LwPolyline(p) => {
                let mirror = p.extrusion_direction.z < 0.0;
                let v: Vec<(Point, f64)> = p
                    .vertices
                    .iter()
                    .map(|q| {
                        (
                            [if mirror { -q.x } else { q.x }, q.y],
                            if mirror { -q.bulge } else { q.bulge },
                        )
                    })
                    .collect();
                out.push(RawPolygon {
                    what: format!("LWPOLYLINE handle {handle} (layer {layer})"),
                    handle,
                    layer,
                    points: expand_bulges(&v, p.is_closed()),
                    closed: p.is_closed(),
                });
            }
            EntityType::Polyline(p) => {
                let what = format!("POLYLINE handle {handle} (layer {layer})");
                if p.is_polyface_mesh() || p.is_3d_polygon_mesh() {
                    return Err(IoError(format!(
                        "DXF entity {what}: a 3D mesh, not a 2D outline; draw blocks as closed 2D polylines"
                    )));
                }
                let mirror = !p.is_3d_polyline() && p.normal.z < 0.0;
                let v: Vec<(Point, f64)> = p
                    .vertices()
                    .map(|q| {
                        let x = q.location.x;
                        (
                            [if mirror { -x } else { x }, q.location.y],
                            if mirror { -q.bulge } else { q.bulge },
                        )
                    })
                    .collect();
                out.push(RawPolygon {
                    what,
                    handle,
                    layer,
                    points: expand_bulges(&v, p.is_closed()),
                    closed: p.is_closed(),
                });
            }
            other => {
                let name = format!("{other:?}");
                let name = match name.split(['(', ' ', '{']).next().unwrap_or("entity") {
                    "ModelPoint" => "POINT".to_string(),
                    "Face3D" => "3DFACE".to_string(),
                    "Solid3D" => "3DSOLID".to_string(),
                    other => other.to_ascii_uppercase(),
                };
                *ignored.entry(name).or_default() += 1;
            }
        }
    }
    Ok(out)
}

/// Snap vertices closer than `tol` to one representative (the first one seen). Linear time:
/// each vertex looks only at the 3×3 grid cells around it.
fn merge_vertices(polys: &mut [Vec<Point>], tol: f64) -> usize {
    if tol <= 0.0 {
        return 0;
    }
    let key = |p: Point| ((p[0] / tol).floor() as i64, (p[1] / tol).floor() as i64);
    let mut grid: HashMap<(i64, i64), Vec<Point>> = HashMap::new();
    let mut moved = 0;
    for poly in polys.iter_mut() {
        for p in poly.iter_mut() {
            let (i, j) = key(*p);
            let mut found: Option<Point> = None;
            'search: for di in -1..=1 {
                for dj in -1..=1 {
                    if let Some(list) = grid.get(&(i + di, j + dj)) {
                        for q in list {
                            if (q[0] - p[0]).hypot(q[1] - p[1]) <= tol {
                                found = Some(*q);
                                break 'search;
                            }
                        }
                    }
                }
            }
            match found {
                Some(q) => {
                    if q != *p {
                        moved += 1;
                        *p = q;
                    }
                }
                None => grid.entry((i, j)).or_default().push(*p),
            }
        }
    }
    moved
}

pub(crate) fn units_of(drawing: &Drawing, over: Option<Units>) -> Result<Units, IoError> {
    if let Some(u) = over {
        return Ok(u);
    }
    match drawing.header.default_drawing_units {
        DxfUnits::Millimeters => Ok(Units::Mm),
        DxfUnits::Centimeters => Ok(Units::Cm),
        DxfUnits::Meters => Ok(Units::M),
        DxfUnits::Unitless => Err(IoError(
            "the drawing declares no units ($INSUNITS = 0): pass --units mm|cm|m".into(),
        )),
        other => Err(IoError(format!(
            "the drawing declares its units as {other:?} ($INSUNITS); voussoir reads mm, cm or m: pass --units mm|cm|m to say what the coordinates are"
        ))),
    }
}

/// Turn a loaded drawing into a model.
pub fn drawing_to_model(
    drawing: &Drawing,
    opts: &DxfOptions,
    name: &str,
) -> Result<(Model, ImportReport), IoError> {
    if !(opts.unit_weight.is_finite() && opts.unit_weight >= 0.0) {
        return Err(IoError(format!(
            "unit weight {} must be a finite number ≥ 0",
            opts.unit_weight
        )));
    }
    if !(opts.width.is_finite() && opts.width > 0.0) {
        return Err(IoError(format!(
            "width {} must be a positive number",
            opts.width
        )));
    }
    if let Some(t) = opts.merge_tolerance {
        if !(t.is_finite() && t >= 0.0) {
            return Err(IoError(format!(
                "merge tolerance {t} must be a finite number ≥ 0"
            )));
        }
    }
    let units = units_of(drawing, opts.units)?;
    let scale = units.scale();
    let mut ignored = BTreeMap::new();
    for layer in &opts.support_layers {
        if !opts.crack_layers.is_empty() && crate::survey::on_layer(layer, &opts.crack_layers) {
            return Err(IoError(format!(
                "layer '{layer}' is named both a support layer and a crack layer"
            )));
        }
    }
    let mut raw = collect(drawing, &mut ignored, &opts.crack_layers)?;
    if raw.is_empty() {
        let found = if ignored.is_empty() {
            "the drawing has no entities".to_string()
        } else {
            format!(
                "found only {}",
                ignored
                    .iter()
                    .map(|(k, n)| format!("{n} {k}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        return Err(IoError(format!(
            "no LWPOLYLINE or POLYLINE in the drawing ({found}): every block must be a closed polyline"
        )));
    }
    for r in raw.iter_mut() {
        for p in r.points.iter_mut() {
            if !(p[0].is_finite() && p[1].is_finite()) {
                return Err(IoError(format!(
                    "DXF entity {}: a vertex coordinate is not a finite number",
                    r.what
                )));
            }
            *p = [p[0] * scale, p[1] * scale];
        }
    }
    let mut all = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for r in &raw {
        if !r.points.is_empty() {
            let b = bbox(&r.points);
            all = [
                all[0].min(b[0]),
                all[1].min(b[1]),
                all[2].max(b[2]),
                all[3].max(b[3]),
            ];
        }
    }
    let diag = (all[2] - all[0]).hypot(all[3] - all[1]);
    let tol = opts.merge_tolerance.unwrap_or(1e-6 * diag);
    let mut polys: Vec<Vec<Point>> = raw.iter().map(|r| r.points.clone()).collect();
    let merged = merge_vertices(&mut polys, tol);

    // Clean each polygon: drop repeated vertices, close, check.
    let check_tol = tol.max(1e-12 * diag.max(1.0));
    let mut cleaned: Vec<Vec<Point>> = Vec::with_capacity(polys.len());
    let mut notes = Vec::new();
    for (r, mut p) in raw.iter().zip(polys) {
        p.dedup();
        // A polyline that returns to its first vertex and then retraces its first edges (an
        // "overdrawn" closure, as in LACT3's arch_1.dxf) is the polygon up to that return.
        if let Some(k) = (3..p.len()).find(|&k| p[k] == p[0]) {
            if k + 1 < p.len() && (k..p.len()).all(|i| p[i] == p[i - k]) {
                notes.push(format!(
                    "{}: the vertices after the return to the start retrace the first edge; ignored",
                    r.what
                ));
                p.truncate(k + 1);
            }
        }
        let ends_meet = p.len() >= 2 && p[0] == p[p.len() - 1];
        if ends_meet {
            p.pop();
        } else if !r.closed {
            let gap = if p.len() >= 2 {
                let (a, b) = (p[0], p[p.len() - 1]);
                (a[0] - b[0]).hypot(a[1] - b[1]) / scale
            } else {
                0.0
            };
            return Err(IoError(format!(
                "DXF entity {}: the polyline is open (its ends are {gap:.6} {} apart); blocks must be closed polylines (crack lines: read their layer with --crack-layer)",
                r.what,
                units.name()
            )));
        }
        if p.len() < 3 {
            return Err(IoError(format!(
                "DXF entity {}: the polyline has {} distinct vertices; a block needs at least 3",
                r.what,
                p.len()
            )));
        }
        if let Some((i, j)) = self_intersection(&p, check_tol) {
            return Err(IoError(format!(
                "DXF entity {}: the polyline is self-intersecting (segments {i} and {j} cross or touch)",
                r.what
            )));
        }
        let b = bbox(&p);
        let size = (b[2] - b[0]).max(b[3] - b[1]);
        if signed_area(&p).abs() <= check_tol * size {
            return Err(IoError(format!(
                "DXF entity {}: the polyline encloses no area",
                r.what
            )));
        }
        if signed_area(&p) < 0.0 {
            p.reverse();
        }
        cleaned.push(p);
    }

    // Which polygons are supports.
    let mut is_support = vec![false; raw.len()];
    for layer in &opts.support_layers {
        let mut any = false;
        for (k, r) in raw.iter().enumerate() {
            if &r.layer == layer {
                is_support[k] = true;
                any = true;
            }
        }
        if !any {
            let mut layers: Vec<&str> = raw.iter().map(|r| r.layer.as_str()).collect();
            layers.sort_unstable();
            layers.dedup();
            return Err(IoError(format!(
                "no polyline on layer '{layer}' (the drawing's polylines are on layers: {})",
                layers.join(", ")
            )));
        }
    }
    for h in &opts.support_handles {
        let h = h.trim().trim_start_matches("0x").to_ascii_uppercase();
        match raw.iter().position(|r| r.handle == h) {
            Some(k) => is_support[k] = true,
            None => {
                return Err(IoError(format!(
                    "no polyline with handle {h} in the drawing"
                )))
            }
        }
    }
    let chose_default = opts.support_layers.is_empty() && opts.support_handles.is_empty();
    if chose_default {
        // The lowest polygon, and among those within the tolerance of the lowest, the widest.
        let boxes: Vec<[f64; 4]> = cleaned.iter().map(|p| bbox(p)).collect();
        let ymin = boxes.iter().fold(f64::INFINITY, |m, b| m.min(b[1]));
        let pick = (0..boxes.len())
            .filter(|&k| boxes[k][1] <= ymin + check_tol.max(1e-9 * diag))
            .max_by(|&a, &b| (boxes[a][2] - boxes[a][0]).total_cmp(&(boxes[b][2] - boxes[b][0])));
        if let Some(k) = pick {
            is_support[k] = true;
        }
    }
    if is_support.iter().all(|s| *s) {
        return Err(IoError(
            "every polygon of the drawing is a support: there is no block to analyse".into(),
        ));
    }

    // Support names: `base` for the default choice; else the layer name (numbered left to
    // right when a layer has several), or `h<handle>` for a support chosen by handle.
    let mut supports = Vec::new();
    let mut support_entities = Vec::new();
    let mut blocks = Vec::new();
    let mut block_entities = Vec::new();
    let mut by_name: BTreeMap<String, Vec<usize>> = BTreeMap::new();
    for (k, r) in raw.iter().enumerate() {
        if !is_support[k] {
            continue;
        }
        let name = if chose_default {
            "base".to_string()
        } else if opts.support_layers.contains(&r.layer) {
            r.layer.clone()
        } else {
            format!("h{}", r.handle)
        };
        by_name.entry(name).or_default().push(k);
    }
    for (name, mut list) in by_name {
        list.sort_by(|&a, &b| bbox(&cleaned[a])[0].total_cmp(&bbox(&cleaned[b])[0]));
        let many = list.len() > 1;
        for (n, k) in list.into_iter().enumerate() {
            supports.push(Support {
                name: if many {
                    format!("{name}-{n}")
                } else {
                    name.clone()
                },
                polygon: cleaned[k].clone(),
                motion: [0.0; 3],
                connection: Default::default(),
            });
            support_entities.push(raw[k].what.clone());
        }
    }
    for (k, r) in raw.iter().enumerate() {
        if !is_support[k] {
            blocks.push(Block {
                polygon: cleaned[k].clone(),
                material: None,
            });
            block_entities.push(r.what.clone());
        }
    }
    let mut materials = BTreeMap::new();
    materials.insert(
        "default".to_string(),
        Material {
            unit_weight: opts.unit_weight,
            width: opts.width,
            ..Material::default()
        },
    );
    let live = match opts.live {
        ImportLive::None => vec![],
        ImportLive::Horizontal => vec![Load::Body {
            coefficients: [1.0, 0.0],
            blocks: None,
        }],
    };
    let model = Model {
        description: format!(
            "imported from {name}: {} blocks, {} support(s), units {}",
            blocks.len(),
            supports.len(),
            units.name()
        ),
        materials,
        blocks,
        supports,
        loads: Loads {
            self_weight: true,
            dead: vec![],
            live,
        },
        tolerance: None,
        cracks: Vec::new(),
    };
    let mut model = model;
    let mut crack_entities = Vec::new();
    if !opts.crack_layers.is_empty() {
        let (cracks, survey) = crate::survey::drawing_to_survey(
            drawing,
            &crate::survey::SurveyOptions {
                layers: opts.crack_layers.clone(),
                units: Some(units),
                ..Default::default()
            },
        )?;
        model.cracks = cracks
            .into_iter()
            .map(crate::survey::existing_crack)
            .collect();
        crack_entities = survey.lines.into_iter().map(|l| l.entity).collect();
        notes.extend(survey.notes);
    }
    Ok((
        model,
        ImportReport {
            units: units.name().to_string(),
            scale,
            block_entities,
            support_entities,
            crack_entities,
            ignored,
            merged_vertices: merged,
            merge_tolerance: tol,
            notes,
            warnings: units_warning(&cleaned, &is_support, units, opts.units.is_some())
                .into_iter()
                .collect(),
        },
    ))
}

/// Block sizes (the median of the blocks' larger bounding-box side, in m) that masonry has:
/// outside them a drawing's declared units are probably not its real ones.
pub const PLAUSIBLE_BLOCK_SIZE: (f64, f64) = (0.005, 20.0);

/// One line when the units taken from `$INSUNITS` make the blocks' median size implausible
/// for masonry (a drawing in millimetres whose header says metres gives 400 m voussoirs),
/// naming the units that would make it plausible. Nothing when the units were given.
fn units_warning(
    polys: &[Vec<Point>],
    is_support: &[bool],
    units: Units,
    given: bool,
) -> Option<String> {
    if given {
        return None;
    }
    let mut sizes: Vec<f64> = polys
        .iter()
        .zip(is_support)
        .filter(|(_, s)| !**s)
        .map(|(p, _)| {
            let b = bbox(p);
            (b[2] - b[0]).max(b[3] - b[1])
        })
        .collect();
    if sizes.is_empty() {
        return None;
    }
    sizes.sort_by(f64::total_cmp);
    let median = sizes[sizes.len() / 2];
    let (lo, hi) = PLAUSIBLE_BLOCK_SIZE;
    if (lo..=hi).contains(&median) {
        return None;
    }
    let raw = median / units.scale();
    // The plausible units that bring the median closest to a typical 0.3 m block.
    let better = [Units::Mm, Units::Cm, Units::M]
        .into_iter()
        .filter(|u| (lo..=hi).contains(&(raw * u.scale())) && *u != units)
        .min_by(|a, b| {
            let d = |u: &Units| (raw * u.scale() / 0.3).ln().abs();
            d(a).total_cmp(&d(b))
        });
    let hint = match better {
        Some(u) => format!("if it is drawn in {}, pass --units {}", u.name(), u.name()),
        None => "pass --units mm|cm|m if its coordinates are in other units".to_string(),
    };
    Some(format!(
        "the drawing's header says its units are {} ($INSUNITS), which makes its blocks {median:.4} m across (median), not masonry-sized; {hint}",
        units.name()
    ))
}

/// Read a DXF file (ASCII or binary) into a model.
pub fn read_dxf(path: &Path, opts: &DxfOptions) -> Result<(Model, ImportReport), IoError> {
    read_dxf_inner(path, opts).map_err(IoError::one_line)
}

fn read_dxf_inner(path: &Path, opts: &DxfOptions) -> Result<(Model, ImportReport), IoError> {
    let drawing = Drawing::load_file(path)
        .map_err(|e| IoError(format!("cannot read {} as DXF: {e}", path.display())))?;
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    drawing_to_model(&drawing, opts, &name)
        .map_err(|e| IoError(format!("{}: {}", path.display(), e.0)))
}

/// Read DXF text or bytes already in memory.
pub fn parse_dxf(
    bytes: &[u8],
    opts: &DxfOptions,
    name: &str,
) -> Result<(Model, ImportReport), IoError> {
    parse_dxf_inner(bytes, opts, name).map_err(IoError::one_line)
}

fn parse_dxf_inner(
    bytes: &[u8],
    opts: &DxfOptions,
    name: &str,
) -> Result<(Model, ImportReport), IoError> {
    let mut cursor = std::io::Cursor::new(bytes);
    let drawing = Drawing::load(&mut cursor)
        .map_err(|e| IoError(format!("cannot read {name} as DXF: {e}")))?;
    drawing_to_model(&drawing, opts, name)
}

/// Whether a path names a DXF file (by its extension).
pub fn is_dxf(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("dxf"))
}

/// `msg` with `sources[N]` after every "block N" it names ("block 3 (LWPOLYLINE #12)"), so that
/// an error found after import points into the file the model came from (DXF, OBJ, PLY).
pub(crate) fn annotate_blocks(msg: &str, sources: &[String]) -> String {
    let mut out = String::with_capacity(msg.len() + 32);
    let mut rest = msg;
    while let Some(pos) = rest.find("block ") {
        let (head, tail) = rest.split_at(pos + 6);
        out.push_str(head);
        let digits: String = tail.chars().take_while(|c| c.is_ascii_digit()).collect();
        rest = &tail[digits.len()..];
        out.push_str(&digits);
        if let Some(e) = digits.parse::<usize>().ok().and_then(|i| sources.get(i)) {
            out.push_str(&format!(" ({e})"));
        }
    }
    out.push_str(rest);
    out
}
