//! Self-contained HTML reports: one file, inline SVG figures, inline CSS and a few lines of
//! JavaScript for the displacement-scale slider; nothing is fetched from the network.
//!
//! Build one with [`Report`] (any analysis can add sections, tables and figures), or take the
//! ready-made [`limit_report`] and [`settlement_report`].

use super::scene::{draw, DrawOptions, Scene};
use super::svg::{esc, fmt_fixed, human};
use std::fmt::Write as _;
use voussoir::result::{BodyName, Geometry, JointResult, JointState};
use voussoir::result::{LimitResult, LimitStatus, SettlementResult};

/// One item of a report section.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A paragraph of plain text.
    Text(String),
    /// A sub-heading.
    Heading(String),
    /// A bulleted list of plain-text sentences.
    List(Vec<String>),
    /// A two-column table of names and values.
    KeyValues(Vec<(String, String)>),
    /// A table with a header row and footer rows (totals); `collapsed` puts it in a
    /// `<details>` element (not printed).
    Table {
        caption: String,
        head: Vec<String>,
        rows: Vec<Vec<String>>,
        foot: Vec<Vec<String>>,
        collapsed: bool,
    },
    /// An inline SVG figure with its caption. A drawing made with `interactive: true` gets a
    /// displacement-scale slider.
    Figure { svg: String, caption: String },
    /// HTML written as is (our own markup only).
    Html(String),
}

impl Item {
    /// A table that is not collapsed and has no footer.
    pub fn table(caption: impl Into<String>, head: Vec<String>, rows: Vec<Vec<String>>) -> Item {
        Item::Table {
            caption: caption.into(),
            head,
            rows,
            foot: Vec::new(),
            collapsed: false,
        }
    }
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
        self.items.push(Item::table(caption, head, rows));
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
            foot: Vec::new(),
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
    /// The model file and the analysis, shown in the title block and the page footer.
    pub source: String,
    pub command: String,
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
        let _ = writeln!(
            o,
            "<style>\n{CSS}{}</style>\n</head>\n<body>\n<main>",
            crate::report_parts::print_css(&self.title, &self.source)
        );
        let _ = writeln!(o, "<h1>{}</h1>", esc(&self.title));
        if !self.subtitle.is_empty() {
            let _ = writeln!(o, "<p class=\"subtitle\">{}</p>", esc(&self.subtitle));
        }
        o.push_str(&crate::report_parts::title_block(
            &self.source,
            &self.command,
        ));
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
            section_html(&mut o, s, &format!("s{}", i + 1), &mut fig);
        }
        o.push_str(crate::report_parts::sign_off());
        let _ = writeln!(
            o,
            "<footer>voussoir {} — rigid no-tension blocks in unilateral contact. Units: m, kN, kN·m.</footer>",
            env!("CARGO_PKG_VERSION")
        );
        let _ = writeln!(o, "</main>\n<script>\n{JS}</script>\n</body>\n</html>");
        o
    }
}

/// Tables of up to this many rows are not broken across printed pages.
const KEEP_ROWS: usize = 30;

/// One section as HTML (`id`: its anchor); figures are numbered on from `fig`.
pub(crate) fn section_html(o: &mut String, s: &Section, id: &str, fig: &mut usize) {
    let _ = writeln!(o, "<section id=\"{id}\">\n<h2>{}</h2>", esc(&s.heading));
    for item in &s.items {
        match item {
            Item::Text(t) => {
                let _ = writeln!(o, "<p>{}</p>", esc(t));
            }
            Item::Heading(t) => {
                let _ = writeln!(o, "<h3>{}</h3>", esc(t));
            }
            Item::Html(h) => o.push_str(h),
            Item::List(v) => {
                o.push_str("<ul class=\"hyp\">\n");
                for t in v {
                    let _ = writeln!(o, "<li>{}</li>", esc(t));
                }
                o.push_str("</ul>\n");
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
                foot,
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
                // A table that fits on a printed page is kept whole; a longer one breaks
                // between rows, its header repeated.
                o.push_str(if rows.len() + foot.len() <= KEEP_ROWS {
                    "<div class=\"scroll keep\"><table class=\"grid\">\n<thead><tr>"
                } else {
                    "<div class=\"scroll\"><table class=\"grid\">\n<thead><tr>"
                });
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
                o.push_str("</tbody>");
                if !foot.is_empty() {
                    o.push_str("\n<tfoot>\n");
                    for r in foot {
                        o.push_str("<tr class=\"total\">");
                        for c in r {
                            let _ = write!(o, "<td>{}</td>", esc(c));
                        }
                        o.push_str("</tr>\n");
                    }
                    o.push_str("</tfoot>");
                }
                o.push_str("</table></div>\n");
                if *collapsed {
                    o.push_str("</details>\n");
                    // On paper the folded table is left out: say so, rather than a bare heading.
                    let _ = writeln!(
                        o,
                        "<p class=\"print-only note\">{}: {} {}, folded on screen and not printed (the result files hold them).</p>",
                        esc(caption),
                        rows.len(),
                        if rows.len() == 1 { "row" } else { "rows" }
                    );
                }
            }
            Item::Figure { svg, caption } => {
                *fig += 1;
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

pub(crate) const CSS: &str = r#"body{margin:0;background:#f4f3ef;color:#1d1d1d;font:15px/1.5 "DejaVu Sans",Verdana,Arial,sans-serif}
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
    /// What the model and the command add (materials, joint laws, tolerances); `None`: the
    /// report says that the joint laws were not recorded.
    pub inputs: Option<crate::report_parts::ReportInputs>,
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

fn strings(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
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
                "{what}: deformed configuration (displacements × {}; on screen the slider changes the scale), undeformed outline dashed, hinges as dots, cracks as red wedges, thrust line in blue.",
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

/// The crack table (mm) and the reaction table (with the total force) of a 2D result, and the
/// check of the vertical reactions against the total weight.
fn result_tables(
    sec: &mut Section,
    (joints, polylines): (&[JointResult], &[voussoir::result::Crack]),
    reactions: &[voussoir::result::Reaction],
    echo: &crate::report_parts::ModelEcho,
    settlement: bool,
) {
    use crate::report_parts as rp;
    let cracks = rp::crack_rows_2d(joints);
    if cracks.is_empty() {
        sec.items.push(Item::Heading("Cracks".into()));
        sec.text("No joint opens or slides.");
    } else {
        if !polylines.is_empty() {
            // A settlement's widths are mm; a limit mechanism is a rate (relative openings).
            let (head, rows) = rp::crack_polyline_table(polylines, settlement);
            sec.table(rp::CRACK_POLYLINES_CAPTION, head, rows);
        }
        let (head, rows) = rp::crack_table(&cracks, 2);
        sec.table(
            "Cracked joints (position: centroid of the opened part; width: largest opening; length: of the opened part)",
            head,
            rows,
        );
    }
    let rows: Vec<_> = reactions
        .iter()
        .map(|re| {
            (
                re.support.clone(),
                vec![re.fx, re.fy],
                vec![re.m],
                vec![re.cx, re.cy],
            )
        })
        .collect();
    let (head, rows, foot) = rp::reaction_table(&rows, 2);
    sec.items.push(Item::Table {
        caption: "Support reactions (forces of each support on the structure)".into(),
        head,
        rows,
        foot,
        collapsed: false,
    });
    if settlement && !reactions.is_empty() {
        let fy: f64 = reactions.iter().map(|r| r.fy).sum();
        let w = echo.total_weight();
        sec.text(format!(
            "Check: the vertical reactions sum to {} kN; the total weight W is {} kN (difference {} kN).",
            human(fy, 8),
            human(w, 8),
            human(fy - w, 2)
        ));
    }
}

fn hinges_and_joints(
    sec: &mut Section,
    r: (&[voussoir::result::Hinge], &[JointResult]),
    title: &str,
) {
    let (hinges, joints) = r;
    if !hinges.is_empty() {
        sec.table(
            title,
            strings(&["joint", "body a", "body b", "x (m)", "y (m)", "N (kN)"]),
            hinge_rows(hinges, joints),
        );
    }
    sec.collapsed_table(
        "All joints",
        strings(&[
            "joint",
            "body a",
            "body b",
            "state",
            "N (kN)",
            "V (kN)",
            "e (m)",
            "max opening (m)",
        ]),
        joint_rows(joints),
    );
}

/// Report of a limit analysis.
pub fn limit_report(r: &LimitResult, opts: &ReportOptions) -> Report {
    use crate::report_parts::{self as rp, Analysis, ModelEcho};
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Limit analysis".to_string()),
    );
    rep.subtitle = r.message.clone();
    rep.source = opts.source.clone();
    rep.command = opts
        .inputs
        .as_ref()
        .map(|i| i.command.clone())
        .unwrap_or_else(|| "limit".into());
    let echo = ModelEcho::of_2d(&r.geometry, r.joints.len());
    let analysis = Analysis::Limit(r.load_multiplier);
    rep.sections.push(rp::hypotheses(
        &echo,
        opts.inputs.as_ref(),
        analysis,
        r.friction_iteration.as_ref(),
    ));
    let mut cert = Vec::new();
    match &r.certificate {
        Some(c) => cert.push((
            "certificate of λ".to_string(),
            format!(
                "gap |λ − λ_kin|/|λ| = {}, admissibility {} — {}",
                human(c.gap, 3),
                human(c.admissibility, 3),
                if c.ok {
                    "certified (≤ 1e-6)"
                } else {
                    "NOT certified"
                }
            ),
        )),
        None => cert.push((
            "certificate of λ".to_string(),
            "not computed for this outcome or joint law".to_string(),
        )),
    }
    rep.sections.push(rp::inputs(
        &echo,
        opts.inputs.as_ref(),
        analysis,
        &opts.source,
        Some(&r.solver),
        cert,
    ));
    let mut kv = vec![(
        "outcome".to_string(),
        match r.status {
            LimitStatus::Collapse => "collapse".to_string(),
            LimitStatus::Locked => "locked (no finite collapse load)".to_string(),
            LimitStatus::NoEquilibrium => "no equilibrium under the dead loads".to_string(),
        },
    )];
    if let Some(l) = r.load_multiplier {
        kv.push((
            "collapse load multiplier λ (safety factor on the live loads)".into(),
            fmt_fixed(l, 6),
        ));
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
    let res = rep.section("Results");
    res.key_values(kv);
    res.text("The mechanism of a limit analysis is a rate (normalised to unit work of the live loads): its crack widths compare the joints' openings with each other, they are not millimetres of a real displacement; the positions and lengths are geometric.");
    result_tables(res, (&r.joints, &r.cracks), &r.reactions, &echo, false);
    figures(
        rep.section("Figures"),
        Scene::limit(r),
        &r.geometry,
        opts.scale,
        "Collapse mechanism",
    );
    hinges_and_joints(
        rep.section("Hinges and joints"),
        (&r.hinges, &r.joints),
        "Hinges of the collapse mechanism",
    );
    rep
}

/// Report of a settlement analysis.
pub fn settlement_report(r: &SettlementResult, opts: &ReportOptions) -> Report {
    use crate::report_parts::{self as rp, Analysis, ModelEcho};
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Settlement analysis".to_string()),
    );
    rep.subtitle = r.message.clone();
    rep.source = opts.source.clone();
    rep.command = opts
        .inputs
        .as_ref()
        .map(|i| i.command.clone())
        .unwrap_or_else(|| "settle".into());
    let echo = ModelEcho::of_2d(&r.geometry, r.joints.len());
    rep.sections.push(rp::hypotheses(
        &echo,
        opts.inputs.as_ref(),
        Analysis::Settlement,
        r.friction_iteration.as_ref(),
    ));
    let mut cert = Vec::new();
    if let Some(c) = &r.certificate {
        cert.push((
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
        cert.push((
            "complementarity, max |opening × N|".into(),
            format!("{} kN·m", human(c.complementarity, 3)),
        ));
        cert.push((
            "equilibrium residual".into(),
            format!("{} kN", human(c.equilibrium_residual, 3)),
        ));
    } else {
        cert.push(("duality certificate".into(), "none (no mechanism)".into()));
    }
    rep.sections.push(rp::inputs(
        &echo,
        opts.inputs.as_ref(),
        Analysis::Settlement,
        &opts.source,
        Some(&r.solver),
        cert,
    ));
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
    let res = rep.section("Results");
    res.key_values(kv);
    result_tables(res, (&r.joints, &r.cracks), &r.reactions, &echo, true);
    figures(
        rep.section("Figures"),
        Scene::settlement(r),
        &r.geometry,
        opts.scale,
        "Settlement mechanism",
    );
    hinges_and_joints(
        rep.section("Hinges and joints"),
        (&r.hinges, &r.joints),
        "Hinges",
    );
    rep
}
