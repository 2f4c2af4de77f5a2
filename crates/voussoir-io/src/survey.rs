//! Crack surveys drawn in CAD: the crack lines of a DXF layer as `identify` observations
//! (docs/identify.md, "A survey drawing").
//!
//! * The survey layers: [`SurveyOptions::layers`] (a name, case-insensitive as in CAD, or a
//!   prefix followed by `*`); none given, every layer whose name contains `CRACK`.
//! * Crack lines: every `LWPOLYLINE`, 2D `POLYLINE` (open or closed; arcs as chords of at most
//!   5°) and `LINE` of those layers in model space.
//! * The width of a line: the `TEXT`/`MTEXT` width labels of the survey layers (a number with
//!   an optional unit: `2`, `2 mm`, `0,5mm`, `w = 1.5 mm`; a bare number is in
//!   [`SurveyOptions::width_units`], default mm). Each label belongs to the line nearest to its
//!   insertion point, if within ten text heights of it (farther labels are notes, not widths).
//!   One label gives the line's width; two, the widths at the ends they are nearest to (the
//!   width in between interpolated along the line). A line without a label takes the width in
//!   its layer's name (`CRACK-2mm`, `cracks_0.5 mm`: a number and a unit at the end).
//! * Coordinates are scaled to metres from [`SurveyOptions::units`], else the header's
//!   `$INSUNITS` (mm, cm or m), as for models.

use crate::dxf::{expand_bulges, units_of, Units};
use crate::files::IoError;
use dxf::entities::EntityType;
use dxf::Drawing;
use std::collections::BTreeMap;
use std::path::Path;
use voussoir::analysis::identify::{Crack, Width};
use voussoir::model::{ExistingCrack, Point};

/// How to read a survey drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct SurveyOptions {
    /// Survey layers (case-insensitive; `PREFIX*` for every layer starting with PREFIX). Empty:
    /// every layer whose name contains "crack".
    pub layers: Vec<String>,
    /// Drawing units (None: from `$INSUNITS`, which must then be mm, cm or m).
    pub units: Option<Units>,
    /// Unit of a width label written without one (default mm).
    pub width_units: Units,
    /// Catch distance of every crack line, m (None: a quarter of each joint's length).
    pub snap: Option<f64>,
}

impl Default for SurveyOptions {
    fn default() -> Self {
        SurveyOptions {
            layers: Vec::new(),
            units: None,
            width_units: Units::Mm,
            snap: None,
        }
    }
}

/// One crack line read.
#[derive(Clone, Debug, PartialEq)]
pub struct SurveyLine {
    /// The entity: type, handle and layer.
    pub entity: String,
    /// Widths (m) at the start and end (equal for one width).
    pub widths: [f64; 2],
    /// Where the width came from: `label '2 mm'` or `layer CRACK-2mm`.
    pub source: String,
}

/// What the survey reading found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SurveyReport {
    /// Units of the drawing's coordinates and metres per unit.
    pub units: String,
    pub scale: f64,
    /// The layers read, sorted.
    pub layers: Vec<String>,
    /// The crack lines, in the order of the cracks returned.
    pub lines: Vec<SurveyLine>,
    /// Entities skipped, by kind.
    pub ignored: BTreeMap<String, usize>,
    /// Labels that are not widths or are far from every line (one line each).
    pub notes: Vec<String>,
}

impl SurveyReport {
    /// One line: what was read.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "survey: {} crack line(s) on layer(s) {}, coordinates in {}",
            self.lines.len(),
            self.layers.join(", "),
            self.units
        );
        if !self.ignored.is_empty() {
            let list: Vec<String> = self
                .ignored
                .iter()
                .map(|(k, n)| format!("{n} {k}"))
                .collect();
            s.push_str(&format!("; ignored: {}", list.join(", ")));
        }
        s
    }
}

/// A width label: the number in metres (None: not a width), read from label text. The first
/// number followed by a length unit (`Crack 3: 2 mm` is 2 mm); else a number alone (with at
/// most a leading `w`, `w =`), in `bare` units.
fn label_width(text: &str, bare: Units) -> Option<f64> {
    let t = strip_mtext(text);
    let chars: Vec<char> = t.chars().collect();
    // Every number: (start, end, value).
    let mut numbers = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        if !chars[i].is_ascii_digit() {
            i += 1;
            continue;
        }
        let start = i;
        while i < chars.len()
            && (chars[i].is_ascii_digit()
                || ((chars[i] == '.' || chars[i] == ',')
                    && chars.get(i + 1).is_some_and(|c| c.is_ascii_digit())))
        {
            i += 1;
        }
        let number: String = chars[start..i]
            .iter()
            .map(|&c| if c == ',' { '.' } else { c })
            .collect();
        numbers.push((start, i, number.parse::<f64>().ok()?));
    }
    for &(_, end, value) in &numbers {
        let rest: String = chars[end..].iter().collect();
        let word: String = rest
            .trim_start()
            .chars()
            .take_while(|c| c.is_alphabetic())
            .collect();
        if let Ok(u) = word.parse::<Units>() {
            return Some(value * u.scale());
        }
    }
    if let [(start, end, value)] = numbers[..] {
        let before: String = chars[..start].iter().collect();
        let after: String = chars[end..].iter().collect();
        let letters = |s: &str| s.chars().filter(|c| c.is_alphabetic()).collect::<String>();
        let lb = letters(&before).to_ascii_lowercase();
        if (lb.is_empty() || lb == "w") && letters(&after).is_empty() {
            return Some(value * bare.scale());
        }
    }
    None
}

/// MTEXT content without its formatting codes (`\A1;`, `\fArial|b0;`, `{`, `}`, `\P`).
fn strip_mtext(s: &str) -> String {
    let mut out = String::new();
    let mut it = s.chars().peekable();
    while let Some(c) = it.next() {
        match c {
            '{' | '}' => {}
            '\\' => match it.next() {
                // Codes with an argument up to ';'.
                Some(
                    'A' | 'C' | 'c' | 'F' | 'f' | 'H' | 'h' | 'Q' | 'q' | 'T' | 't' | 'W' | 'w',
                ) => {
                    for d in it.by_ref() {
                        if d == ';' {
                            break;
                        }
                    }
                }
                Some('P') | Some('~') => out.push(' '),
                Some(d) if "LlOoKk".contains(d) => {}
                Some(d) => out.push(d),
                None => {}
            },
            c => out.push(c),
        }
    }
    out
}

/// A width in the name of a layer: a number and a unit at its end (`CRACK-2mm`, `c_0.5 MM`).
fn layer_width(layer: &str) -> Option<f64> {
    let t = layer.trim().to_ascii_lowercase();
    let unit: String = {
        let mut u: Vec<char> = t.chars().rev().take_while(|c| c.is_alphabetic()).collect();
        u.reverse();
        u.into_iter().collect()
    };
    if unit.is_empty() {
        return None;
    }
    let head = &t[..t.len() - unit.len()];
    let scale = unit.parse::<Units>().ok()?.scale();
    let head = head.trim_end();
    let num_len = head
        .chars()
        .rev()
        .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == ',')
        .count();
    let number = head[head.len() - num_len..].replace(',', ".");
    let number = number.trim_start_matches(['.', ',']);
    if !number.chars().next().is_some_and(|c| c.is_ascii_digit()) {
        return None;
    }
    number.parse::<f64>().ok().map(|v| v * scale)
}

/// Whether `layer` is one of `wanted` (case-insensitive, `PREFIX*`); none wanted: a layer
/// whose name contains "crack".
pub(crate) fn on_layer(layer: &str, wanted: &[String]) -> bool {
    if wanted.is_empty() {
        return layer.to_ascii_lowercase().contains("crack");
    }
    let l = layer.to_ascii_lowercase();
    wanted.iter().any(|w| {
        let w = w.to_ascii_lowercase();
        match w.strip_suffix('*') {
            Some(prefix) => l.starts_with(prefix),
            None => l == w,
        }
    })
}

/// Distance from `p` to a polyline and the arc length (fraction 0–1) of its projection.
fn project(line: &[Point], p: Point) -> (f64, f64) {
    if line.len() == 1 {
        return ((p[0] - line[0][0]).hypot(p[1] - line[0][1]), 0.0);
    }
    let total: f64 = line
        .windows(2)
        .map(|s| (s[1][0] - s[0][0]).hypot(s[1][1] - s[0][1]))
        .sum();
    let (mut best, mut at, mut run) = (f64::INFINITY, 0.0, 0.0);
    for s in line.windows(2) {
        let d = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
        let l2 = d[0] * d[0] + d[1] * d[1];
        let t = if l2 > 0.0 {
            (((p[0] - s[0][0]) * d[0] + (p[1] - s[0][1]) * d[1]) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let q = [s[0][0] + t * d[0], s[0][1] + t * d[1]];
        let dist = (p[0] - q[0]).hypot(p[1] - q[1]);
        if dist < best {
            best = dist;
            at = run + t * l2.sqrt();
        }
        run += l2.sqrt();
    }
    (best, if total > 0.0 { at / total } else { 0.0 })
}

struct RawLine {
    what: String,
    layer: String,
    points: Vec<Point>,
}

struct Label {
    what: String,
    text: String,
    at: Point,
    height: f64,
}

/// Read the crack lines of a loaded drawing as observations (coordinates and widths in m).
pub fn drawing_to_survey(
    drawing: &Drawing,
    opts: &SurveyOptions,
) -> Result<(Vec<Crack>, SurveyReport), IoError> {
    if let Some(d) = opts.snap {
        if !(d.is_finite() && d > 0.0) {
            return Err(IoError(format!(
                "snap distance {d} must be a finite number > 0 (m)"
            )));
        }
    }
    let units = units_of(drawing, opts.units)?;
    let scale = units.scale();
    let mut ignored: BTreeMap<String, usize> = BTreeMap::new();
    let mut lines: Vec<RawLine> = Vec::new();
    let mut labels: Vec<Label> = Vec::new();
    let mut layers: Vec<String> = Vec::new();
    let mut all_layers: Vec<String> = Vec::new();
    for e in drawing.entities() {
        let layer = e.common.layer.clone();
        if !all_layers.contains(&layer) {
            all_layers.push(layer.clone());
        }
        if e.common.is_in_paper_space {
            *ignored.entry("paper-space entities".into()).or_default() += 1;
            continue;
        }
        if !on_layer(&layer, &opts.layers) {
            *ignored
                .entry("entities on other layers".into())
                .or_default() += 1;
            continue;
        }
        if !layers.contains(&layer) {
            layers.push(layer.clone());
        }
        let handle = format!("{:X}", e.common.handle.0);
        let what = |kind: &str| format!("{kind} handle {handle} (layer {layer})");
        match &e.specific {
            EntityType::LwPolyline(p) => {
                let mirror = p.extrusion_direction.z < 0.0;
                let v: Vec<(Point, f64)> = p
                    .vertices
                    .iter()
                    .map(|q| {
                        let x = if mirror { -q.x } else { q.x };
                        ([x, q.y], if mirror { -q.bulge } else { q.bulge })
                    })
                    .collect();
                let mut pts = expand_bulges(&v, p.is_closed());
                if p.is_closed() && !pts.is_empty() {
                    pts.push(pts[0]);
                }
                lines.push(RawLine {
                    what: what("LWPOLYLINE"),
                    layer: layer.clone(),
                    points: pts,
                });
            }
            EntityType::Polyline(p) => {
                if p.is_polyface_mesh() || p.is_3d_polygon_mesh() {
                    *ignored.entry("3D meshes".into()).or_default() += 1;
                    continue;
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
                let mut pts = expand_bulges(&v, p.is_closed());
                if p.is_closed() && !pts.is_empty() {
                    pts.push(pts[0]);
                }
                lines.push(RawLine {
                    what: what("POLYLINE"),
                    layer: layer.clone(),
                    points: pts,
                });
            }
            EntityType::Line(l) => lines.push(RawLine {
                what: what("LINE"),
                layer: layer.clone(),
                points: vec![[l.p1.x, l.p1.y], [l.p2.x, l.p2.y]],
            }),
            EntityType::Text(t) => {
                use dxf::enums::{
                    HorizontalTextJustification as H, VerticalTextJustification as V,
                };
                let aligned = !(t.horizontal_text_justification == H::Left
                    && t.vertical_text_justification == V::Baseline);
                let p = if aligned {
                    &t.second_alignment_point
                } else {
                    &t.location
                };
                labels.push(Label {
                    what: what("TEXT"),
                    text: t.value.clone(),
                    at: [p.x, p.y],
                    height: t.text_height,
                });
            }
            EntityType::MText(t) => {
                let mut text: String = t.extended_text.concat();
                text.push_str(&t.text);
                labels.push(Label {
                    what: what("MTEXT"),
                    text,
                    at: [t.insertion_point.x, t.insertion_point.y],
                    height: t.initial_text_height,
                });
            }
            other => {
                let name = format!("{other:?}");
                let name = name
                    .split(['(', ' ', '{'])
                    .next()
                    .unwrap_or("entity")
                    .to_ascii_uppercase();
                *ignored
                    .entry(format!("{name} on the survey layers"))
                    .or_default() += 1;
            }
        }
    }
    if lines.is_empty() {
        let wanted = if opts.layers.is_empty() {
            "no layer name contains CRACK".to_string()
        } else {
            format!("layer(s) {}", opts.layers.join(", "))
        };
        let have = if all_layers.is_empty() {
            "the drawing has no entities".to_string()
        } else {
            format!("its layers: {}", all_layers.join(", "))
        };
        // With no layer named, say how to name one; a named layer without lines is the error.
        let hint = if opts.layers.is_empty() {
            ": pass --survey-layer NAME"
        } else {
            ""
        };
        return Err(IoError(format!(
            "no crack line (LWPOLYLINE, POLYLINE or LINE) on the survey layers ({wanted}; {have}){hint}"
        )));
    }
    for l in &mut lines {
        for p in &mut l.points {
            if !(p[0].is_finite() && p[1].is_finite()) {
                return Err(IoError(format!(
                    "DXF entity {}: a vertex coordinate is not a finite number",
                    l.what
                )));
            }
            *p = [p[0] * scale, p[1] * scale];
        }
        l.points.dedup();
    }
    // Width labels, each to its nearest line.
    let mut notes = Vec::new();
    let mut by_line: Vec<Vec<(f64, f64, String)>> = vec![Vec::new(); lines.len()];
    for lab in &labels {
        let Some(w) = label_width(&lab.text, opts.width_units) else {
            notes.push(format!(
                "{}: '{}' is not a width; ignored",
                lab.what,
                lab.text.trim()
            ));
            continue;
        };
        let at = [lab.at[0] * scale, lab.at[1] * scale];
        let (mut best, mut which, mut pos) = (f64::INFINITY, 0, 0.0);
        for (i, l) in lines.iter().enumerate() {
            let (d, s) = project(&l.points, at);
            if d < best {
                (best, which, pos) = (d, i, s);
            }
        }
        let reach = 10.0 * lab.height.abs() * scale;
        if best > reach {
            notes.push(format!(
                "{}: '{}' is {:.3} m from the nearest crack line (more than ten text heights); ignored",
                lab.what,
                lab.text.trim(),
                best
            ));
            continue;
        }
        by_line[which].push((pos, w, format!("{} '{}'", lab.what, lab.text.trim())));
    }
    let mut cracks = Vec::new();
    let mut out_lines = Vec::new();
    for (l, mut labs) in lines.into_iter().zip(by_line) {
        labs.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (widths, source) = match labs.len() {
            0 => match layer_width(&l.layer) {
                Some(w) => ([w, w], format!("layer {}", l.layer)),
                None => {
                    return Err(IoError(format!(
                        "DXF entity {}: no width: put a width label (TEXT or MTEXT, e.g. \"2 mm\") next to it, or draw it on a layer named after its width (e.g. CRACK-2mm)",
                        l.what
                    )))
                }
            },
            1 => ([labs[0].1, labs[0].1], labs[0].2.clone()),
            2 => (
                [labs[0].1, labs[1].1],
                format!("{} and {}", labs[0].2, labs[1].2),
            ),
            n => {
                return Err(IoError(format!(
                    "DXF entity {}: {n} width labels are nearest to it ({}); give one, or two (its widths at its ends)",
                    l.what,
                    labs.iter().map(|x| x.2.clone()).collect::<Vec<_>>().join(", ")
                )))
            }
        };
        if l.points.is_empty() {
            continue;
        }
        cracks.push(Crack {
            polyline: Some(l.points),
            snap: opts.snap,
            opening: if widths[0] == widths[1] {
                Width::One(widths[0])
            } else {
                Width::PerPoint(widths.to_vec())
            },
            ..Default::default()
        });
        out_lines.push(SurveyLine {
            entity: l.what,
            widths,
            source,
        });
    }
    layers.sort();
    Ok((
        cracks,
        SurveyReport {
            units: units.name().to_string(),
            scale,
            layers,
            lines: out_lines,
            ignored,
            notes,
        },
    ))
}

/// A surveyed crack line as one of a model's existing cracks (same line, catch distance and
/// widths, in metres).
pub fn existing_crack(c: Crack) -> ExistingCrack {
    ExistingCrack {
        // A survey line has no `at` (it is a polyline); a 2D point is kept as such.
        at: c.at.as_deref().and_then(|p| <[f64; 2]>::try_from(p).ok()),
        joint: c.joint,
        polyline: c.polyline,
        snap: c.snap,
        opening: c.opening,
        units: c.units,
        ..Default::default()
    }
}

/// Read a survey drawing (see the module documentation).
pub fn read_survey(
    path: &Path,
    opts: &SurveyOptions,
) -> Result<(Vec<Crack>, SurveyReport), IoError> {
    let drawing = Drawing::load_file(path)
        .map_err(|e| IoError(format!("cannot read {} as DXF: {e}", path.display())))?;
    drawing_to_survey(&drawing, opts)
        .map_err(|e| IoError(format!("{}: {}", path.display(), e.0)).one_line())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widths_from_labels_and_layer_names() {
        let mm = Units::Mm;
        let close = |a: Option<f64>, b: f64| a.is_some_and(|a| (a - b).abs() <= 1e-15);
        assert!(close(label_width("2 mm", mm), 0.002));
        assert!(close(label_width("w = 1,5mm", mm), 0.0015));
        assert!(close(label_width("0.3", mm), 0.0003));
        assert!(close(label_width("0.3", Units::Cm), 0.003));
        assert!(close(label_width("{\\fArial|b0;\\H2.5;3 mm}", mm), 0.003));
        assert!(close(label_width("Crack 3: 2 mm", mm), 0.002));
        assert_eq!(label_width("Crack 3", mm), None);
        assert_eq!(label_width("crack A", mm), None);
        assert_eq!(label_width("2 inches", mm), None);
        assert!(close(layer_width("CRACK-2mm"), 0.002));
        assert!(close(layer_width("cracks_0,5 MM"), 0.0005));
        assert_eq!(layer_width("fissure-é"), None);
        assert_eq!(layer_width("2é"), None);
        assert_eq!(layer_width("CRACK-2"), None);
        assert_eq!(layer_width("CRACKS"), None);
    }
}
