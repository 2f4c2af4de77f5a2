//! A wall's outline (outer boundary and openings) from a DXF drawing's closed polylines or
//! from JSON, for [`voussoir::outline_mesh`].
//!
//! * DXF: every closed `LWPOLYLINE` / 2D `POLYLINE` of model space (bulges as chords of at
//!   most 5°, as for `import`). The outer boundary is the one closed polyline on the outer
//!   layers (`--outer-layer`), or, with none named, the closed polyline of largest area. The
//!   holes are the closed polylines on the hole layers (`--hole-layer`), or, with none named,
//!   every other closed polyline not on an outer layer. Open polylines and other entities are
//!   counted in the report, never used. Layer names are case-insensitive, `PREFIX*` matches a
//!   prefix.
//! * JSON: `{"outer": [[x, y], …], "holes": [[[x, y], …], …]}` in metres.

use crate::dxf::{collect, units_of, Units};
use crate::files::IoError;
use dxf::Drawing;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::Path;
use voussoir::geometry::signed_area;
use voussoir::model::Point;
use voussoir::outline_mesh::Outline;

/// Which polylines of a drawing make the outline.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OutlineOptions {
    /// Drawing units (None: from `$INSUNITS`, which must then be mm, cm or m).
    pub units: Option<Units>,
    /// Layers of the outer boundary (one closed polyline in all).
    pub outer_layers: Vec<String>,
    /// Layers of the openings.
    pub hole_layers: Vec<String>,
}

/// What was read, beside the outline.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OutlineReport {
    /// The entity of the outer boundary and of each hole (in order).
    pub outer_entity: String,
    pub hole_entities: Vec<String>,
    /// Units and metres per drawing unit.
    pub units: String,
    pub scale: f64,
    /// Entities not used, by kind.
    pub ignored: BTreeMap<String, usize>,
}

impl OutlineReport {
    /// One line: what was read.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "outline: outer boundary {}, {} opening(s), units {} ({} m per unit)",
            self.outer_entity,
            self.hole_entities.len(),
            self.units,
            self.scale
        );
        if !self.ignored.is_empty() {
            let list: Vec<String> = self
                .ignored
                .iter()
                .map(|(k, n)| format!("{n} {k}"))
                .collect();
            s.push_str(&format!("; not used: {}", list.join(", ")));
        }
        s
    }

    /// A message about "hole k" or "the outer boundary" with the drawing's entity added.
    pub fn annotate(&self, msg: &str) -> String {
        let mut out = msg.replace(
            "the outer boundary",
            &format!("the outer boundary ({})", self.outer_entity),
        );
        // From the highest index down, so that "hole 1" does not match inside "hole 12".
        for (k, e) in self.hole_entities.iter().enumerate().rev() {
            let key = format!("hole {k}");
            let mut res = String::with_capacity(out.len());
            let mut rest = out.as_str();
            while let Some(pos) = rest.find(&key) {
                let after = &rest[pos + key.len()..];
                res.push_str(&rest[..pos + key.len()]);
                if !after.starts_with(|c: char| c.is_ascii_digit()) && !after.starts_with(" (") {
                    res.push_str(&format!(" ({e})"));
                }
                rest = after;
            }
            res.push_str(rest);
            out = res;
        }
        out
    }
}

fn on_layer(layer: &str, wanted: &[String]) -> bool {
    let l = layer.to_ascii_lowercase();
    wanted.iter().any(|w| {
        let w = w.to_ascii_lowercase();
        match w.strip_suffix('*') {
            Some(prefix) => l.starts_with(prefix),
            None => l == w,
        }
    })
}

/// The outline of a loaded drawing.
pub fn drawing_outline(
    drawing: &Drawing,
    opts: &OutlineOptions,
) -> Result<(Outline, OutlineReport), IoError> {
    let units = units_of(drawing, opts.units)?;
    let scale = units.scale();
    let mut ignored = BTreeMap::new();
    let raw = collect(drawing, &mut ignored, &[])?;
    for l in &opts.outer_layers {
        if on_layer(l, &opts.hole_layers) {
            return Err(IoError(format!(
                "layer '{l}' is named both an outer layer and a hole layer"
            )));
        }
    }
    // Closed polylines, scaled.
    let mut closed: Vec<(String, String, Vec<Point>)> = Vec::new();
    for r in raw {
        let mut p: Vec<Point> = r
            .points
            .iter()
            .map(|q| [q[0] * scale, q[1] * scale])
            .collect();
        if let Some(q) = p.iter().find(|q| !(q[0].is_finite() && q[1].is_finite())) {
            return Err(IoError(format!(
                "DXF entity {}: a vertex coordinate is not a finite number ({}, {})",
                r.what, q[0], q[1]
            )));
        }
        let returns = p.len() > 3 && p.first() == p.last();
        if returns {
            p.pop();
        }
        if r.closed || returns {
            closed.push((r.what, r.layer, p));
        } else {
            *ignored.entry("open polylines".into()).or_default() += 1;
        }
    }
    if closed.is_empty() {
        return Err(IoError(
            "no closed LWPOLYLINE or POLYLINE in the drawing: draw the wall's outline and its openings as closed polylines".into(),
        ));
    }
    let outer_idx = if opts.outer_layers.is_empty() {
        (0..closed.len())
            .max_by(|&a, &b| {
                signed_area(&closed[a].2)
                    .abs()
                    .total_cmp(&signed_area(&closed[b].2).abs())
                    .then(b.cmp(&a))
            })
            .unwrap_or(0)
    } else {
        let on: Vec<usize> = (0..closed.len())
            .filter(|&i| on_layer(&closed[i].1, &opts.outer_layers))
            .collect();
        match on[..] {
            [i] => i,
            [] => {
                return Err(IoError(format!(
                    "--outer-layer {}: no closed polyline on that layer",
                    opts.outer_layers.join(",")
                )))
            }
            _ => {
                return Err(IoError(format!(
                    "--outer-layer {}: {} closed polylines ({}); a wall has one outer boundary (draw an opening that reaches it as a notch of it)",
                    opts.outer_layers.join(","),
                    on.len(),
                    on.iter().map(|&i| closed[i].0.as_str()).collect::<Vec<_>>().join("; ")
                )))
            }
        }
    };
    let mut holes = Vec::new();
    let mut hole_entities = Vec::new();
    for (i, (what, layer, p)) in closed.iter().enumerate() {
        if i == outer_idx {
            continue;
        }
        let take = if opts.hole_layers.is_empty() {
            !on_layer(layer, &opts.outer_layers)
        } else {
            on_layer(layer, &opts.hole_layers)
        };
        if take {
            holes.push(p.clone());
            hole_entities.push(what.clone());
        } else {
            *ignored
                .entry("closed polylines on other layers".into())
                .or_default() += 1;
        }
    }
    if !opts.hole_layers.is_empty() && holes.is_empty() {
        return Err(IoError(format!(
            "--hole-layer {}: no closed polyline on that layer",
            opts.hole_layers.join(",")
        )));
    }
    let report = OutlineReport {
        outer_entity: closed[outer_idx].0.clone(),
        hole_entities,
        units: units.name().into(),
        scale,
        ignored,
    };
    Ok((Outline::new(closed[outer_idx].2.clone(), holes), report))
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct OutlineJson {
    outer: Vec<[f64; 2]>,
    #[serde(default)]
    holes: Vec<Vec<[f64; 2]>>,
}

/// Read an outline from a DXF drawing (`.dxf`) or a JSON file.
pub fn read_outline(
    path: &Path,
    opts: &OutlineOptions,
) -> Result<(Outline, OutlineReport), IoError> {
    let at = |e: IoError| IoError::one_line(IoError(format!("{}: {}", path.display(), e.0)));
    if crate::dxf::is_dxf(path) {
        let drawing = Drawing::load_file(path)
            .map_err(|e| IoError(format!("cannot read {} as DXF: {e}", path.display())))?;
        return drawing_outline(&drawing, opts).map_err(at);
    }
    if opts.units.is_some() || !opts.outer_layers.is_empty() || !opts.hole_layers.is_empty() {
        return Err(IoError(format!(
            "{}: --units, --outer-layer and --hole-layer apply to a DXF drawing; a JSON outline is in metres with \"outer\" and \"holes\"",
            path.display()
        )));
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| IoError(format!("cannot read {}: {e}", path.display())))?;
    let j: OutlineJson = serde_json::from_str(&text).map_err(|e| {
        at(IoError(format!(
            "not an outline ({{\"outer\": [[x, y], …], \"holes\": [[[x, y], …], …]}}): {e}"
        )))
    })?;
    let report = OutlineReport {
        outer_entity: "\"outer\"".into(),
        hole_entities: (0..j.holes.len())
            .map(|k| format!("\"holes\"[{k}]"))
            .collect(),
        units: "m".into(),
        scale: 1.0,
        ignored: BTreeMap::new(),
    };
    Ok((Outline::new(j.outer, j.holes), report))
}
