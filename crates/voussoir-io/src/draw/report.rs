//! Self-contained HTML reports: one file, inline SVG figures, inline CSS and a few lines of
//! JavaScript for the displacement-scale slider; nothing is fetched from the network.
//!
//! Build one with [`Report`] (any analysis can add sections, tables and figures), or take the
//! ready-made [`limit_report`] and [`settlement_report`].

use super::scene::{draw, DrawOptions, Scene};
use super::svg::{esc, fmt_fixed, human};
use std::fmt::Write as _;
use voussoir::analysis::{LimitResult, LimitStatus, SettlementResult};
use voussoir::result::{BodyName, Geometry, JointResult, JointState};

/// One item of a report section.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A paragraph of plain text.
    Text(String),
    /// A two-column table of names and values.
    KeyValues(Vec<(String, String)>),
    /// A table with a header row; `collapsed` puts it in a `<details>` element.
    Table {
        caption: String,
        head: Vec<String>,
        rows: Vec<Vec<String>>,
        collapsed: bool,
    },
    /// An inline SVG figure with its caption. A drawing made with `interactive: true` gets a
    /// displacement-scale slider.
    Figure { svg: String, caption: String },
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct Section {
    pub heading: String,
    pub items: Vec<Item>,
}

impl Section {
    pub fn text(&mut self, t: impl Into<String>) -> &mut Self {
        self.items.push(Item::Text(t.into()));
        self
    }
    pub fn key_values(&mut self, kv: Vec<(String, String)>) -> &mut Self {
        self.items.push(Item::KeyValues(kv));
        self
    }
    pub fn table(
        &mut self,
        caption: impl Into<String>,
        head: Vec<String>,
        rows: Vec<Vec<String>>,
    ) -> &mut Self {
        self.items.push(Item::Table {
            caption: caption.into(),
            head,
            rows,
            collapsed: false,
        });
        self
    }
    pub fn collapsed_table(
        &mut self,
        caption: impl Into<String>,
        head: Vec<String>,
        rows: Vec<Vec<String>>,
    ) -> &mut Self {
        self.items.push(Item::Table {
            caption: caption.into(),
            head,
            rows,
            collapsed: true,
        });
        self
    }
    pub fn figure(&mut self, svg: impl Into<String>, caption: impl Into<String>) -> &mut Self {
        self.items.push(Item::Figure {
            svg: svg.into(),
            caption: caption.into(),
        });
        self
    }
}

/// A report: a title, a subtitle and sections.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    pub title: String,
    pub subtitle: String,
    pub sections: Vec<Section>,
}

impl Report {
    pub fn new(title: impl Into<String>) -> Self {
        Report {
            title: title.into(),
            ..Report::default()
        }
    }

    /// Append a section and return it for filling.
    pub fn section(&mut self, heading: impl Into<String>) -> &mut Section {
        self.sections.push(Section {
            heading: heading.into(),
            items: Vec::new(),
        });
        self.sections.last_mut().expect("just pushed")
    }

    /// The whole report as one HTML document.
    pub fn to_html(&self) -> String {
        let mut o = String::with_capacity(64 * 1024);
        o.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
        o.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
        let _ = writeln!(o, "<title>{}</title>", esc(&self.title));
        let _ = writeln!(o, "<style>\n{CSS}</style>\n</head>\n<body>\n<main>");
        let _ = writeln!(o, "<h1>{}</h1>", esc(&self.title));
        if !self.subtitle.is_empty() {
            let _ = writeln!(o, "<p class=\"subtitle\">{}</p>", esc(&self.subtitle));
        }
        if self.sections.len() > 2 {
            o.push_str("<nav><ul>");
            for (i, s) in self.sections.iter().enumerate() {
                let _ = write!(
                    o,
                    "<li><a href=\"#s{}\">{}</a></li>",
                    i + 1,
                    esc(&s.heading)
                );
            }
            o.push_str("</ul></nav>\n");
        }
        let mut fig = 0;
        for (i, s) in self.sections.iter().enumerate() {
            let _ = writeln!(
                o,
                "<section id=\"s{}\">\n<h2>{}</h2>",
                i + 1,
                esc(&s.heading)
            );
            for item in &s.items {
                match item {
                    Item::Text(t) => {
                        let _ = writeln!(o, "<p>{}</p>", esc(t));
                    }
                    Item::KeyValues(kv) => {
                        o.push_str("<table class=\"kv\">\n");
                        for (k, v) in kv {
                            let _ = writeln!(o, "<tr><th>{}</th><td>{}</td></tr>", esc(k), esc(v));
                        }
                        o.push_str("</table>\n");
                    }
                    Item::Table {
                        caption,
                        head,
                        rows,
                        collapsed,
                    } => {
                        if *collapsed {
                            let _ = writeln!(
                                o,
                                "<details><summary>{} ({} rows)</summary>",
                                esc(caption),
                                rows.len()
                            );
                        } else if !caption.is_empty() {
                            let _ = writeln!(o, "<h3>{}</h3>", esc(caption));
                        }
                        o.push_str("<div class=\"scroll\"><table class=\"grid\">\n<thead><tr>");
                        for h in head {
                            let _ = write!(o, "<th>{}</th>", esc(h));
                        }
                        o.push_str("</tr></thead>\n<tbody>\n");
                        for r in rows {
                            o.push_str("<tr>");
                            for c in r {
                                let _ = write!(o, "<td>{}</td>", esc(c));
                            }
                            o.push_str("</tr>\n");
                        }
                        o.push_str("</tbody></table></div>\n");
                        if *collapsed {
                            o.push_str("</details>\n");
                        }
                    }
                    Item::Figure { svg, caption } => {
                        fig += 1;
                        let _ = writeln!(o, "<figure id=\"fig{fig}\">");
                        if svg.contains("data-motions=\"") {
                            let _ = writeln!(
                                o,
                                "<div class=\"slider\"><label>displacement scale × <output>1</output> <input type=\"range\" min=\"0\" max=\"3\" step=\"0.01\" value=\"1\" aria-label=\"displacement scale\"></label> <button type=\"button\">reset</button></div>"
                            );
                        }
                        // The SVG is our own output: written as is (no XML prolog).
                        o.push_str(svg.trim_end());
                        o.push('\n');
                        let _ = writeln!(
                            o,
                            "<figcaption>Figure {fig}. {}</figcaption>\n</figure>",
                            esc(caption)
                        );
                    }
                }
            }
            o.push_str("</section>\n");
        }
        let _ = writeln!(
            o,
            "<footer>voussoir {} — rigid no-tension blocks in unilateral contact. Units: m, kN, kN·m.</footer>",
            env!("CARGO_PKG_VERSION")
        );
        let _ = writeln!(o, "</main>\n<script>\n{JS}</script>\n</body>\n</html>");
        o
    }
}

const CSS: &str = r#"body{margin:0;background:#f4f3ef;color:#1d1d1d;font:15px/1.5 "DejaVu Sans",Verdana,Arial,sans-serif}
main{max-width:1060px;margin:0 auto;padding:24px 28px 40px;background:#ffffff;box-shadow:0 0 12px rgba(0,0,0,.06)}
h1{font-size:26px;margin:4px 0 2px;font-weight:600}
h2{font-size:19px;margin:30px 0 10px;padding-bottom:4px;border-bottom:2px solid #e3dccb;font-weight:600}
h3{font-size:15px;margin:16px 0 6px}
.subtitle{color:#555;margin:0 0 12px}
nav ul{list-style:none;padding:0;margin:8px 0 0;display:flex;flex-wrap:wrap;gap:6px 16px;font-size:14px}
nav a{color:#1f5fbf;text-decoration:none}
table{border-collapse:collapse;font-size:14px}
table.kv th{text-align:left;font-weight:normal;color:#555;padding:3px 18px 3px 0;vertical-align:top}
table.kv td{padding:3px 0;font-variant-numeric:tabular-nums}
table.grid th,table.grid td{border:1px solid #ddd;padding:3px 9px;text-align:right;font-variant-numeric:tabular-nums}
table.grid th{background:#f2f0ea;text-align:center}
.scroll{max-width:100%;overflow-x:auto}
details{margin:10px 0}
summary{cursor:pointer;color:#1f5fbf}
figure{margin:18px 0 24px}
figure svg{max-width:100%;height:auto;display:block;border:1px solid #e6e6e6}
figcaption{color:#444;font-size:14px;margin-top:6px}
.slider{font-size:14px;margin:0 0 6px;display:flex;gap:12px;align-items:center}
.slider input{width:320px;vertical-align:middle}
.slider output{display:inline-block;min-width:3.5em;font-variant-numeric:tabular-nums}
footer{margin-top:36px;color:#777;font-size:13px}
"#;

/// The slider: moves every element tagged by the drawing (see `scene.rs`) with the exact finite
/// rigid motion of its group at the chosen scale.
const JS: &str = r#"(function () {
  "use strict";
  function num(v) { return String(Math.round(v * 100) / 100); }
  function fmt(s) { return s >= 100 ? String(Math.round(s)) : String(Number(s.toPrecision(3))); }
  function mv(m, s, x, y) {
    var a = s * m[4], c = Math.cos(a), n = Math.sin(a), dx = x - m[0], dy = y - m[1];
    return [m[0] + s * m[2] + c * dx - n * dy, m[1] + s * m[3] + n * dx + c * dy];
  }
  function triple(t) { return t.split(",").map(Number); }
  function apply(svg, M, s) {
    svg.querySelectorAll("[data-g]").forEach(function (e) {
      var m = M[+e.getAttribute("data-g")], a = s * m[4], c = Math.cos(a), n = Math.sin(a);
      var f = [c, n, -n, c, m[0] + s * m[2] - (c * m[0] - n * m[1]), m[1] + s * m[3] - (n * m[0] + c * m[1])];
      e.setAttribute("transform", "matrix(" + f.map(function (v, i) { return i < 4 ? v.toFixed(7) : num(v); }).join(" ") + ")");
    });
    svg.querySelectorAll("[data-pts]").forEach(function (e) {
      var p = e.getAttribute("data-pts").split(" ").map(function (t) {
        var q = triple(t), r = mv(M[q[0]], s, q[1], q[2]);
        return num(r[0]) + "," + num(r[1]);
      });
      e.setAttribute("points", p.join(" "));
    });
    svg.querySelectorAll("[data-at]").forEach(function (e) {
      var q = triple(e.getAttribute("data-at")), r = mv(M[q[0]], s, q[1], q[2]);
      if (e.tagName.toLowerCase() === "circle") {
        e.setAttribute("cx", num(r[0])); e.setAttribute("cy", num(r[1]));
      } else {
        e.setAttribute("transform", "translate(" + num(r[0] - q[1]) + " " + num(r[1] - q[2]) + ")");
      }
    });
    svg.querySelectorAll("[data-scale-label]").forEach(function (e) { e.textContent = fmt(s); });
  }
  document.querySelectorAll("figure").forEach(function (fig) {
    var svg = fig.querySelector("svg[data-motions]"), input = fig.querySelector(".slider input");
    if (!svg || !input) { return; }
    var M = svg.getAttribute("data-motions").split(";").map(triple);
    var base = Number(svg.getAttribute("data-scale")) || 1;
    var out = fig.querySelector(".slider output"), button = fig.querySelector(".slider button");
    input.max = String(3 * base); input.step = String(base / 100); input.value = String(base);
    function update() { var s = Number(input.value); out.textContent = fmt(s); apply(svg, M, s); }
    input.addEventListener("input", update);
    button.addEventListener("click", function () { input.value = String(base); update(); });
    update();
  });
  document.body.setAttribute("data-ready", "1");
})();
"#;

/// What the ready-made reports show.
#[derive(Clone, Debug, Default)]
pub struct ReportOptions {
    /// Report title (default: by analysis).
    pub title: Option<String>,
    /// Where the model came from (shown in the summary).
    pub source: String,
    /// Displacement scale of the mechanism figure (`None`: automatic).
    pub scale: Option<f64>,
}

fn f4(x: f64) -> String {
    fmt_fixed(x, 4)
}

fn body(b: &BodyName) -> String {
    match b {
        BodyName::Block(i) => format!("block {i}"),
        BodyName::Support(s) => s.clone(),
    }
}

/// Model summary: sizes, loads and supports of a result's geometry (`joints` 0: not shown).
pub fn model_summary(g: &Geometry, joints: usize, source: &str) -> Vec<(String, String)> {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in g
        .blocks
        .iter()
        .flatten()
        .chain(g.supports.iter().flat_map(|s| s.polygon.iter()))
    {
        for k in 0..2 {
            if p[k].is_finite() {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    let (dead, live): (Vec<_>, Vec<_>) = g.loads.iter().partition(|l| !l.live);
    let total = |v: &[&voussoir::result::LoadArrow]| -> (f64, f64) {
        (v.iter().map(|l| l.fx).sum(), v.iter().map(|l| l.fy).sum())
    };
    let (dx, dy) = total(&dead);
    let (lx, ly) = total(&live);
    let mut kv = Vec::new();
    if !source.is_empty() {
        kv.push(("model".to_string(), source.to_string()));
    }
    kv.push(("blocks".into(), g.blocks.len().to_string()));
    if joints > 0 {
        kv.push(("joints".into(), joints.to_string()));
    }
    let sup: Vec<String> = g
        .supports
        .iter()
        .map(|s| {
            format!(
                "{}{}",
                s.name,
                if s.fixed { " (fixed)" } else { " (contact)" }
            )
        })
        .collect();
    kv.push((format!("supports ({})", g.supports.len()), sup.join(", ")));
    if lo[0].is_finite() {
        kv.push((
            "extent".into(),
            format!(
                "{} m wide × {} m high (x {} … {}, y {} … {})",
                f4(hi[0] - lo[0]),
                f4(hi[1] - lo[1]),
                f4(lo[0]),
                f4(hi[0]),
                f4(lo[1]),
                f4(hi[1])
            ),
        ));
    }
    kv.push((
        "dead loads".into(),
        format!(
            "{} forces, resultant ({}, {}) kN",
            dead.len(),
            f4(dx),
            f4(dy)
        ),
    ));
    kv.push((
        "live loads (× λ)".into(),
        if live.is_empty() {
            "none".to_string()
        } else {
            format!(
                "{} forces, resultant ({}, {}) kN",
                live.len(),
                f4(lx),
                f4(ly)
            )
        },
    ));
    if let Some(m) = super::scene::support_motion_text(g) {
        kv.push((
            "settlement".into(),
            m.trim_start_matches("prescribed support motion: ")
                .to_string(),
        ));
    }
    kv
}

fn hinge_rows(hinges: &[voussoir::result::Hinge], joints: &[JointResult]) -> Vec<Vec<String>> {
    hinges
        .iter()
        .map(|h| {
            let j = joints.iter().find(|j| j.id == h.joint);
            vec![
                h.joint.to_string(),
                j.map(|j| body(&j.a)).unwrap_or_default(),
                j.map(|j| body(&j.b)).unwrap_or_default(),
                f4(h.x),
                f4(h.y),
                j.map(|j| human(j.normal_force, 5)).unwrap_or_default(),
            ]
        })
        .collect()
}

fn joint_rows(joints: &[JointResult]) -> Vec<Vec<String>> {
    joints
        .iter()
        .take(5000)
        .map(|j| {
            let state = match j.state {
                JointState::Closed => "closed",
                JointState::Hinge => "hinge",
                JointState::Open => "open",
                JointState::Sliding => "sliding",
            };
            let max_open = j.points.iter().fold(0.0f64, |m, p| m.max(p.opening));
            vec![
                j.id.to_string(),
                body(&j.a),
                body(&j.b),
                state.to_string(),
                human(j.normal_force, 5),
                human(j.shear_force, 5),
                j.eccentricity.map(f4).unwrap_or_else(|| "—".into()),
                human(max_open, 4),
            ]
        })
        .collect()
}

fn reaction_rows(r: &[voussoir::result::Reaction]) -> Vec<Vec<String>> {
    r.iter()
        .map(|re| vec![re.support.clone(), f4(re.fx), f4(re.fy), f4(re.m)])
        .collect()
}

fn strings(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

/// Hinge, reaction and joint tables of a mechanism; `titles`: hinge table, reaction table,
/// opening column.
fn joint_sections(
    sec: &mut Section,
    (hinges, joints, reactions): (
        &[voussoir::result::Hinge],
        &[JointResult],
        &[voussoir::result::Reaction],
    ),
    titles: [&str; 3],
) {
    if !hinges.is_empty() {
        sec.table(
            titles[0],
            strings(&["joint", "body a", "body b", "x (m)", "y (m)", "N (kN)"]),
            hinge_rows(hinges, joints),
        );
    }
    sec.table(
        titles[1],
        strings(&["support", "Fx (kN)", "Fy (kN)", "M (kN·m)"]),
        reaction_rows(reactions),
    );
    sec.collapsed_table(
        "All joints",
        strings(&[
            "joint", "body a", "body b", "state", "N (kN)", "V (kN)", "e (m)", titles[2],
        ]),
        joint_rows(joints),
    );
}

fn figures(sec: &mut Section, scene: Scene, geometry: &Geometry, scale: Option<f64>, what: &str) {
    let mut model = Scene::geometry(geometry, "Model and loads");
    model.live_loads = scene.live_loads;
    let d0 = draw(
        &model,
        &DrawOptions {
            id: "fig-model".into(),
            ..DrawOptions::default()
        },
    );
    sec.figure(
        d0.svg,
        if scene.live_loads {
            "The model: blocks, hatched supports and live loads (arrows; multiplied by λ)."
        } else {
            "The model: blocks and hatched supports (a settlement analysis applies the dead loads only)."
        },
    );
    let d1 = draw(
        &scene,
        &DrawOptions {
            scale,
            interactive: true,
            id: "fig-mech".into(),
            ..DrawOptions::default()
        },
    );
    if d1.deformed {
        sec.figure(
            d1.svg,
            format!(
                "{what}: deformed configuration (displacements × {}; drag the slider to change), undeformed outline dashed, hinges as dots, cracks as red wedges, thrust line in blue.",
                human(d1.scale, 4)
            ),
        );
    }
    let mut forces_scene = scene.clone();
    forces_scene.title = "Thrust line and contact forces".into();
    let d2 = draw(
        &forces_scene,
        &DrawOptions {
            deformed: false,
            forces: true,
            live_loads: false,
            id: "fig-forces".into(),
            ..DrawOptions::default()
        },
    );
    sec.figure(
        d2.svg,
        "Thrust line (centres of pressure of the joints) and contact-force resultants (arrows, length ∝ magnitude) on the undeformed geometry.",
    );
}

/// Report of a limit analysis.
pub fn limit_report(r: &LimitResult, opts: &ReportOptions) -> Report {
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Limit analysis".to_string()),
    );
    rep.subtitle = r.message.clone();
    let mut kv = vec![(
        "outcome".to_string(),
        match r.status {
            LimitStatus::Collapse => "collapse".to_string(),
            LimitStatus::Locked => "locked (no finite collapse load)".to_string(),
            LimitStatus::NoEquilibrium => "no equilibrium under the dead loads".to_string(),
        },
    )];
    if let Some(l) = r.load_multiplier {
        kv.push(("collapse load multiplier λ".into(), fmt_fixed(l, 6)));
    }
    if let (Some(wd), Some(wl)) = (r.work_dead_loads, r.work_live_loads) {
        kv.push((
            "virtual work on the mechanism".into(),
            format!(
                "dead loads {} kN·m, live loads {} kN·m (λ = −W_D / W_L = {})",
                human(wd, 6),
                human(wl, 6),
                fmt_fixed(-wd / wl, 6)
            ),
        ));
    }
    kv.push(("hinges".into(), r.hinges.len().to_string()));
    kv.push(("simplex iterations".into(), r.iterations.to_string()));
    rep.section("Key numbers").key_values(kv);
    rep.section("Model")
        .key_values(model_summary(&r.geometry, r.joints.len(), &opts.source));
    figures(
        rep.section("Figures"),
        Scene::limit(r),
        &r.geometry,
        opts.scale,
        "Collapse mechanism",
    );
    joint_sections(
        rep.section("Hinges, reactions and joints"),
        (&r.hinges, &r.joints, &r.reactions),
        [
            "Hinges of the collapse mechanism",
            "Support reactions at collapse",
            "max opening",
        ],
    );
    rep
}

/// Report of a settlement analysis.
pub fn settlement_report(r: &SettlementResult, opts: &ReportOptions) -> Report {
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Settlement analysis".to_string()),
    );
    rep.subtitle = r.message.clone();
    let mut kv = Vec::new();
    if let Some(m) = super::scene::support_motion_text(&r.geometry) {
        kv.push((
            "prescribed motion".to_string(),
            m.trim_start_matches("prescribed support motion: ")
                .to_string(),
        ));
    }
    kv.push((
        "outcome".to_string(),
        format!("{:?}", r.status).to_lowercase(),
    ));
    if let Some(c) = &r.certificate {
        kv.push((
            "work of the dead loads (primal)".into(),
            format!("{} kN·m", human(c.primal, 10)),
        ));
        kv.push((
            "work on the supports (dual)".into(),
            format!("{} kN·m", human(c.dual, 10)),
        ));
        kv.push((
            "duality certificate".into(),
            format!(
                "relative gap {} — {}",
                human(c.relative_gap, 3),
                if c.ok {
                    "certified (≤ 1e-7)"
                } else {
                    "NOT certified"
                }
            ),
        ));
        kv.push((
            "complementarity, max |opening × N|".into(),
            format!("{} kN·m", human(c.complementarity, 3)),
        ));
        kv.push((
            "equilibrium residual".into(),
            format!("{} kN", human(c.equilibrium_residual, 3)),
        ));
    }
    let open = r
        .joints
        .iter()
        .filter(|j| j.state == JointState::Open)
        .count();
    kv.push((
        "hinges / fully open joints".into(),
        format!("{} / {}", r.hinges.len(), open),
    ));
    let dmax = r.blocks.iter().fold(0.0f64, |m, b| m.max(b.u.hypot(b.v)));
    kv.push((
        "largest block-centroid displacement".into(),
        format!("{} mm", human(dmax * 1000.0, 4)),
    ));
    rep.section("Key numbers").key_values(kv);
    // A settlement analysis has no λ: the model's live loads are listed as not applied.
    let model: Vec<(String, String)> = model_summary(&r.geometry, r.joints.len(), &opts.source)
        .into_iter()
        .map(|(k, v)| {
            if k == "live loads (× λ)" {
                let v = if v == "none" {
                    v
                } else {
                    format!("{v}; not applied (a settlement analysis has no λ)")
                };
                ("live loads".to_string(), v)
            } else {
                (k, v)
            }
        })
        .collect();
    rep.section("Model").key_values(model);
    figures(
        rep.section("Figures"),
        Scene::settlement(r),
        &r.geometry,
        opts.scale,
        "Settlement mechanism",
    );
    joint_sections(
        rep.section("Hinges, reactions and joints"),
        (&r.hinges, &r.joints, &r.reactions),
        ["Hinges", "Support reactions", "max opening (m)"],
    );
    rep
}
