//! Self-contained interactive HTML report of a 3D result (limit or settlement): key numbers, a
//! table of the cracked joints, a WebGL view (drag to rotate, right-drag or shift-drag to pan,
//! wheel to zoom, a displacement-scale slider, checkboxes for cracks, contact forces, supports
//! and the undeformed edges) and the static axonometric drawing of [`crate::draw3d`] for print.
//!
//! One file, nothing fetched: CSS, the viewer (hand-written WebGL 1, about 300 lines, see
//! docs/report3d.md for why not three.js) and the data (JSON in a
//! `<script type="application/json" id="voussoir-data">`) are inlined. The bytes depend only on
//! the result, the title and the source.
//!
//! The data: per block its vertices, faces (outward counter-clockwise), triangles of the faces
//! (ear clipping, done here so the page needs no polygon code), centroid and motion
//! `[u, v, w, θx, θy, θz]`; per support the same and whether it is fixed; per joint the bodies,
//! state, normal, points, the normal force and the centre of pressure. The view moves every
//! body by the finite rigid motion `x ↦ c + s·u + R(s·θ)(x − c)` at slider scale `s`, as the
//! static drawing does.

use crate::draw::report::{section_html, Item, Section};
use crate::draw::svg::{esc, human};
use crate::draw3d::{draw3d, Draw3dOptions};
use crate::report_parts::{self as rp, Analysis, ModelEcho, ReportInputs};
use crate::result3d::{self, polygon_order, tangents, validate, Motions, Result3d, V3};
use crate::IoError;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use voussoir::result::{BodyName, JointState};

/// The report as one HTML document. `title` empty: the result's own title; `source` names the
/// model (shown in the title block and the page footer; empty: not shown). The joint laws and
/// materials are not known here: see [`report3d_html_with`].
///
/// Fails (one line, naming the body) only when the result's shapes cannot be drawn: a vertex
/// that is not finite or a face that refers to a missing vertex.
pub fn report3d_html(
    r: &(impl Result3d + ?Sized),
    title: &str,
    source: &str,
) -> Result<String, IoError> {
    report3d_html_with(r, title, source, None)
}

/// [`report3d_html`] with what the model and the command add: materials, the joint laws in
/// force, the friction cone, tolerances and settings (the hypotheses and inputs sections).
pub fn report3d_html_with(
    r: &(impl Result3d + ?Sized),
    title: &str,
    source: &str,
    inputs: Option<&ReportInputs>,
) -> Result<String, IoError> {
    validate(r)?;
    let title = if title.trim().is_empty() {
        r.title()
    } else {
        title.to_string()
    };
    let drawing = draw3d(
        r,
        &Draw3dOptions {
            id: "r3".into(),
            ..Draw3dOptions::default()
        },
    )?;
    let data = scene_json(r, drawing.scale);
    let g = r.shapes();
    let echo = ModelEcho::of_3d(g, r.joints().len());
    let analysis = if r.live_loads() {
        Analysis::Limit(r.load_multiplier())
    } else {
        Analysis::Settlement
    };
    let command = inputs
        .map(|i| i.command.clone())
        .filter(|c| !c.is_empty())
        .unwrap_or_else(|| {
            match analysis {
                Analysis::Settlement => "settle",
                _ => "limit",
            }
            .to_string()
        });
    let mut o = String::with_capacity(64 * 1024 + drawing.svg.len());
    o.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    o.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    let _ = writeln!(o, "<title>{}</title>", esc(&title));
    let _ = writeln!(
        o,
        "<style>\n{CSS}{}</style>\n</head>\n<body>\n<main>",
        rp::print_css(&title, source)
    );
    let _ = writeln!(o, "<h1>{}</h1>", esc(&title));
    o.push_str(&rp::title_block(source, &command));
    let mut fig = 0;
    section_html(
        &mut o,
        &rp::hypotheses(&echo, inputs, analysis, r.friction_iteration()),
        "hypotheses",
        &mut fig,
    );
    section_html(
        &mut o,
        &rp::inputs(
            &echo,
            inputs,
            analysis,
            source,
            r.solver(),
            r.certificate_rows(),
        ),
        "inputs",
        &mut fig,
    );

    // Results: key numbers and the reactions.
    let mut res = Section {
        heading: "Results".into(),
        items: Vec::new(),
    };
    let mut rows = r.key_numbers();
    rows.push((
        "motions".into(),
        match r.units() {
            crate::draw::MotionUnits::Normalised => {
                "normalised mechanism (only the shape of the motion is meaningful)".into()
            }
            crate::draw::MotionUnits::Metres => "metres (the settlement's own size)".into(),
        },
    ));
    res.key_values(rows);
    if !r.reactions().is_empty() {
        let rows: Vec<_> = r
            .reactions()
            .iter()
            .map(|re| {
                (
                    re.support.clone(),
                    vec![re.fx, re.fy, re.fz],
                    vec![re.mx, re.my, re.mz],
                    vec![re.cx, re.cy, re.cz],
                )
            })
            .collect();
        let (head, rows, foot) = rp::reaction_table(&rows, 3);
        res.items.push(Item::Table {
            caption: "Support reactions (forces of each support on the structure)".into(),
            head,
            rows,
            foot,
            collapsed: false,
        });
        if analysis == Analysis::Settlement {
            let fz: f64 = r.reactions().iter().map(|re| re.fz).sum();
            let w = echo.total_weight();
            res.text(format!(
                "Check: the vertical reactions sum to {} kN; the total weight W is {} kN (difference {} kN).",
                human(fz, 8),
                human(w, 8),
                human(fz - w, 2)
            ));
        }
    }
    section_html(&mut o, &res, "numbers", &mut fig);

    // Cracked joints.
    let mut cr = Section {
        heading: "Cracked joints".into(),
        items: Vec::new(),
    };
    let cracks = rp::crack_rows_3d(r.joints());
    if cracks.is_empty() {
        cr.text("No joint opens or slides.");
    } else {
        if r.units() == crate::draw::MotionUnits::Normalised {
            cr.text("The mechanism of a limit analysis is a rate (normalised): its crack widths compare the joints' openings with each other, they are not millimetres of a real displacement; the positions and lengths are geometric.");
        }
        if !r.cracks().is_empty() {
            let (head, rows) = rp::crack_polyline_table(
                r.cracks(),
                r.units() != crate::draw::MotionUnits::Normalised,
            );
            cr.items
                .push(Item::table(rp::CRACK_POLYLINES_CAPTION, head, rows));
        }
        let (head, rows) = rp::crack_table(&cracks, 3);
        cr.items.push(Item::table(
            "Cracked joints (position: centroid of the opened part; width: largest opening; length: of the opened part, along the crack's line)",
            head,
            rows,
        ));
    }
    section_html(&mut o, &cr, "cracks", &mut fig);

    // The static drawing.
    o.push_str("<section id=\"drawing\">\n<h2>Static drawing</h2>\n<figure>\n");
    o.push_str(drawing.svg.trim_end());
    o.push_str(
        "\n<figcaption>Axonometric view of the mechanism (the printed counterpart of the interactive view).</figcaption>\n</figure>\n</section>\n",
    );

    // The interactive view (not printed).
    o.push_str("<section id=\"view\" class=\"screen-only\">\n<h2>Mechanism in 3D</h2>\n");
    o.push_str(
        "<div class=\"controls\"><label>displacement scale × <output id=\"v3-scale-out\">1</output> \
         <input id=\"v3-scale\" type=\"range\" min=\"0\" max=\"3\" step=\"0.01\" value=\"1\" aria-label=\"displacement scale\"></label>\
         <label><input id=\"v3-cracks\" type=\"checkbox\" checked> cracks</label>\
         <label><input id=\"v3-forces\" type=\"checkbox\" checked> contact forces</label>\
         <label><input id=\"v3-supports\" type=\"checkbox\" checked> supports</label>\
         <label><input id=\"v3-ghost\" type=\"checkbox\" checked> undeformed edges</label>\
         <button id=\"v3-reset\" type=\"button\">reset view</button></div>\n",
    );
    o.push_str(
        "<div class=\"viewer\"><canvas id=\"v3-canvas\" width=\"1000\" height=\"620\"></canvas>\
         <p id=\"v3-nogl\" hidden>WebGL is not available in this browser: the static drawing above shows the mechanism.</p></div>\n",
    );
    o.push_str(
        "<p class=\"hint\">Drag to rotate · right-drag or shift-drag to pan · wheel to zoom. \
         Red: cracks (the joint's outline on both faces). Blue: contact forces, an arrow along \
         the joint's normal at the centre of pressure, length proportional to the normal force.</p>\n</section>\n",
    );
    o.push_str(rp::sign_off());
    let _ = writeln!(
        o,
        "<footer>voussoir {} — rigid no-tension blocks in unilateral contact. Units: m, kN, kN·m.</footer>",
        env!("CARGO_PKG_VERSION")
    );
    o.push_str("</main>\n<script type=\"application/json\" id=\"voussoir-data\">");
    // `</` would end the script element: JSON allows `\/` for `/`.
    o.push_str(&data.to_string().replace("</", "<\\/"));
    o.push_str("</script>\n<script>\n");
    o.push_str(VIEWER_JS);
    o.push_str("</script>\n</body>\n</html>\n");
    Ok(o)
}

fn state_name(s: JointState) -> &'static str {
    match s {
        JointState::Closed => "closed",
        JointState::Hinge => "hinge",
        JointState::Open => "open",
        JointState::Sliding => "sliding",
    }
}

/// Centre of pressure of each joint that carries compression (the thrust points), by joint id.
fn centres_of_pressure(r: &(impl Result3d + ?Sized)) -> BTreeMap<usize, V3> {
    r.thrust_line()
        .iter()
        .filter(|t| t.x.is_finite() && t.y.is_finite() && t.z.is_finite())
        .map(|t| (t.joint, [t.x, t.y, t.z]))
        .collect()
}

/// A number rounded to 9 significant digits (far below anything visible; keeps the page small)
/// and written as the shortest decimal that reads back as it; 0 for anything not finite.
fn n9(x: f64) -> Value {
    if !x.is_finite() {
        return json!(0.0);
    }
    let r: f64 = format!("{x:.8e}").parse().unwrap_or(0.0);
    json!(r)
}

fn v3(p: V3) -> Value {
    Value::Array(p.iter().map(|&x| n9(x)).collect())
}

/// Triangles of a planar face (vertex indices into the body), by ear clipping in the face's
/// plane; a fan when the polygon is degenerate. Deterministic.
fn triangulate(v: &[V3], f: &[usize]) -> Vec<[usize; 3]> {
    if f.len() < 3 {
        return Vec::new();
    }
    if f.len() == 3 {
        return vec![[f[0], f[1], f[2]]];
    }
    // Newell normal.
    let mut n = [0.0; 3];
    for k in 0..f.len() {
        let (p, q) = (v[f[k]], v[f[(k + 1) % f.len()]]);
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    let fan = || (1..f.len() - 1).map(|k| [f[0], f[k], f[k + 1]]).collect();
    if result3d::norm(n) == 0.0 || !result3d::finite(n) {
        return fan();
    }
    let (t1, t2) = tangents(n);
    let p2: Vec<[f64; 2]> = f
        .iter()
        .map(|&i| [result3d::dot(v[i], t1), result3d::dot(v[i], t2)])
        .collect();
    let cross2 = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    let inside = |p: [f64; 2], a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        cross2(a, b, p) >= 0.0 && cross2(b, c, p) >= 0.0 && cross2(c, a, p) >= 0.0
    };
    let mut idx: Vec<usize> = (0..f.len()).collect();
    let mut out = Vec::with_capacity(f.len() - 2);
    let mut guard = 0;
    while idx.len() > 3 && guard < 4 * f.len() * f.len() {
        guard += 1;
        let m = idx.len();
        let mut clipped = false;
        for k in 0..m {
            let (ia, ib, ic) = (idx[(k + m - 1) % m], idx[k], idx[(k + 1) % m]);
            let (a, b, c) = (p2[ia], p2[ib], p2[ic]);
            if cross2(a, b, c) <= 0.0 {
                continue; // reflex or flat corner
            }
            if idx
                .iter()
                .any(|&j| j != ia && j != ib && j != ic && inside(p2[j], a, b, c))
            {
                continue;
            }
            out.push([f[ia], f[ib], f[ic]]);
            idx.remove(k);
            clipped = true;
            break;
        }
        if !clipped {
            return fan();
        }
    }
    if idx.len() == 3 {
        out.push([f[idx[0]], f[idx[1]], f[idx[2]]]);
    }
    out
}

fn body_json(
    v: &[V3],
    faces: &[Vec<usize>],
    c: V3,
    m: &[f64; 6],
) -> serde_json::Map<String, Value> {
    let tris: Vec<Value> = faces
        .iter()
        .flat_map(|f| triangulate(v, f))
        .map(|t| json!(t))
        .collect();
    let mut o = serde_json::Map::new();
    o.insert("v".into(), Value::Array(v.iter().map(|&p| v3(p)).collect()));
    o.insert("f".into(), json!(faces));
    o.insert("t".into(), Value::Array(tris));
    o.insert("c".into(), v3(c));
    o.insert("m".into(), Value::Array(m.iter().map(|&x| n9(x)).collect()));
    o
}

/// The data of the view.
fn scene_json(r: &(impl Result3d + ?Sized), scale: f64) -> Value {
    let g = r.shapes();
    let motions = Motions::of(r);
    let blocks: Vec<Value> = g
        .blocks
        .iter()
        .zip(&motions.blocks)
        .enumerate()
        .map(|(i, (b, (c, m)))| {
            let mut o = body_json(&b.vertices, &b.faces, *c, m);
            o.insert("id".into(), json!(i));
            Value::Object(o)
        })
        .collect();
    let supports: Vec<Value> = g
        .supports
        .iter()
        .zip(&motions.supports)
        .map(|(s, (c, m))| {
            let mut o = body_json(&s.vertices, &s.faces, *c, m);
            o.insert("name".into(), json!(s.name));
            o.insert("fixed".into(), json!(s.fixed));
            Value::Object(o)
        })
        .collect();
    let body_ref = |b: &BodyName| -> Value {
        match b {
            BodyName::Block(i) => json!(["b", i]),
            BodyName::Support(name) => match g.supports.iter().position(|s| &s.name == name) {
                Some(k) => json!(["s", k]),
                None => Value::Null,
            },
        }
    };
    let cp = centres_of_pressure(r);
    let joints: Vec<Value> = r
        .joints()
        .iter()
        .map(|j| {
            let pts: Vec<V3> = j.points.iter().map(|p| [p.x, p.y, p.z]).collect();
            let n = [j.normal[0], j.normal[1], j.normal[2]];
            // Outline in order around the normal (the points as found may be in any order).
            let order = polygon_order(&pts, n);
            json!({
                "id": j.id,
                "a": body_ref(&j.a),
                "b": body_ref(&j.b),
                "state": state_name(j.state),
                "n": v3(n),
                "p": order.iter().map(|&k| v3(pts[k])).collect::<Vec<_>>(),
                "N": n9(j.normal_force),
                "cp": cp.get(&j.id).map(|&p| v3(p)).unwrap_or(Value::Null),
            })
        })
        .collect();
    json!({
        "title": r.title(),
        "units": match r.units() {
            crate::draw::MotionUnits::Normalised => "normalised",
            crate::draw::MotionUnits::Metres => "metres",
        },
        "scale": n9(scale),
        "blocks": blocks,
        "supports": supports,
        "joints": joints,
    })
}

const CSS: &str = r#"body{margin:0;background:#f4f3ef;color:#1d1d1d;font:15px/1.5 "DejaVu Sans",Verdana,Arial,sans-serif}
main{max-width:1060px;margin:0 auto;padding:24px 28px 40px;background:#ffffff;box-shadow:0 0 12px rgba(0,0,0,.06)}
h1{font-size:26px;margin:4px 0 2px;font-weight:600}
h2{font-size:19px;margin:30px 0 10px;padding-bottom:4px;border-bottom:2px solid #e3dccb;font-weight:600}
.subtitle{color:#555;margin:0 0 12px}
table{border-collapse:collapse;font-size:14px}
table.kv th{text-align:left;font-weight:normal;color:#555;padding:3px 18px 3px 0;vertical-align:top}
table.kv td{padding:3px 0;font-variant-numeric:tabular-nums}
table.grid th,table.grid td{border:1px solid #ddd;padding:3px 9px;text-align:right;font-variant-numeric:tabular-nums}
table.grid th{background:#f2f0ea;text-align:center}
.scroll{max-width:100%;overflow-x:auto}
.controls{font-size:14px;margin:0 0 6px;display:flex;flex-wrap:wrap;gap:8px 16px;align-items:center}
.controls input[type=range]{width:260px;vertical-align:middle}
.controls output{display:inline-block;min-width:3.5em;font-variant-numeric:tabular-nums}
.viewer{position:relative;border:1px solid #e6e6e6;background:#fbfaf7}
.viewer canvas{display:block;width:100%;height:auto;cursor:grab;touch-action:none}
.hint{color:#555;font-size:13px;margin:6px 0 0}
figure{margin:18px 0 24px}
figure svg{max-width:100%;height:auto;display:block;border:1px solid #e6e6e6}
figcaption{color:#444;font-size:14px;margin-top:6px}
footer{margin-top:36px;color:#777;font-size:13px}
"#;

/// The viewer: WebGL 1, one shader (Lambert lighting of flat-shaded triangles; unlit lines),
/// an orbit camera about the model's centre with z up. Hooks for tests:
/// `window.__voussoirRotate(dx, dy)` rotates as a drag of (dx, dy) pixels would;
/// `document.body.dataset.ready` is "1" once drawn ("nogl" without WebGL).
const VIEWER_JS: &str = include_str!("report3d_viewer.js");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ear_clipping_of_an_l_shape() {
        // L-shaped face in the plane z = 0, counter-clockwise seen from +z: area 3.
        let v = vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
        ];
        let f = vec![0, 1, 2, 3, 4, 5];
        let t = triangulate(&v, &f);
        assert_eq!(t.len(), 4);
        let area: f64 = t
            .iter()
            .map(|[a, b, c]| {
                let (p, q, r) = (v[*a], v[*b], v[*c]);
                ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])) / 2.0
            })
            .sum();
        // Every triangle counter-clockwise, total area 3 (a fan from vertex 0 would cover the
        // notch and give a clockwise triangle).
        assert!((area - 3.0).abs() < 1e-12, "{area}");
        for [a, b, c] in &t {
            let (p, q, r) = (v[*a], v[*b], v[*c]);
            assert!((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]) > 0.0);
        }
    }
}
