//! Inverse settlement analysis: the observed cracks over the predicted ones.
//!
//! The figure is the settlement drawing of the identified motion's forward analysis (same
//! conventions: deformed blocks, undeformed outline dashed, hinges as dots, predicted cracks as
//! red wedges) with every observed crack drawn on top as a ring at its point, radius growing with
//! the measured width, and an observed-closed point that the prediction opens marked with a
//! cross. A key for the two overlay symbols sits in the top-right corner.

use super::report::{settlement_report, Report, ReportOptions};
use super::scene::{centroid, draw, DrawOptions, Drawing, Scene};
use super::svg::{esc, fmt_fixed, human, num, text_width};
use crate::lengths::Length;
use std::fmt::Write as _;
use voussoir::result::identify::{IdentifyResult, IdentifyStatus};
use voussoir::result::BodyName;

/// Colour of observed cracks (distinct from the red of predicted cracks and the blue thrust).
const OBSERVED: &str = "#0a7f6f";
/// Colour of contradictions (predicted open where observed closed).
const CONTRADICTION: &str = "#e08a00";

/// The scene: the forward settlement mechanism of the identified (or closest) motion.
pub fn identify_scene(r: &IdentifyResult) -> Scene<'_> {
    let mut scene = Scene::settlement(&r.forward);
    scene.title = match r.status {
        IdentifyStatus::Identified => "Identified settlement: observed and predicted cracks",
        IdentifyStatus::Inconsistent => "Inconsistent pattern: closest settlement",
    }
    .to_string();
    let mut line = String::new();
    for (i, u) in r.unknowns.iter().enumerate() {
        if i > 0 {
            line.push_str("   ·   ");
        }
        if u.name.ends_with(".theta") {
            let _ = write!(line, "{} = {} rad", u.name, human(u.value, 5));
        } else {
            let _ = write!(line, "{} = {} mm", u.name, human(u.value * 1000.0, 5));
        }
        if !u.identifiable && r.status == IdentifyStatus::Identified {
            line.push_str(" (not identifiable)");
        }
    }
    scene.info.insert(0, line);
    scene.info.insert(
        1,
        format!(
            "{} crack observation{}, misfit {} tolerances over every observed point{}",
            r.observations.len(),
            if r.observations.len() == 1 { "" } else { "s" },
            human(tiny(r.misfit_all_points), 3),
            match r.status {
                IdentifyStatus::Identified => "",
                IdentifyStatus::Inconsistent => " (closed ones included)",
            }
        ),
    );
    scene
}

/// Round-off misfits (below 1e-9) shown as 0.
fn tiny(x: f64) -> f64 {
    if x.abs() < 1e-9 {
        0.0
    } else {
        x
    }
}

/// Displacement of a joint point: mean of the two sides' small displacements.
fn point_motion(r: &IdentifyResult, joint: usize, p: [f64; 2]) -> [f64; 2] {
    let Some(j) = r.forward.joints.get(joint) else {
        return [0.0, 0.0];
    };
    let side = |b: &BodyName| -> [f64; 2] {
        match b {
            BodyName::Block(i) => {
                let (Some(m), Some(g)) =
                    (r.forward.blocks.get(*i), r.forward.geometry.blocks.get(*i))
                else {
                    return [0.0, 0.0];
                };
                let c = centroid(g);
                [m.u - m.theta * (p[1] - c[1]), m.v + m.theta * (p[0] - c[0])]
            }
            BodyName::Support(name) => {
                match r.forward.geometry.supports.iter().find(|g| &g.name == name) {
                    Some(g) => {
                        let (c, s) = (centroid(&g.polygon), g.motion);
                        [s[0] - s[2] * (p[1] - c[1]), s[1] + s[2] * (p[0] - c[0])]
                    }
                    None => [0.0, 0.0],
                }
            }
        }
    };
    let (a, b) = (side(&j.a), side(&j.b));
    [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]
}

/// The figure: the settlement drawing with the observations on top.
pub fn draw_identify(r: &IdentifyResult, opts: &DrawOptions, title: Option<&str>) -> Drawing {
    let mut scene = identify_scene(r);
    if let Some(t) = title {
        scene.title = t.to_string();
    }
    let mut d = draw(&scene, opts);
    let s = if d.deformed { d.scale } else { 0.0 };
    let wmax = r.observations.iter().fold(0.0f64, |m, o| m.max(o.observed));
    let mut o = String::new();
    let _ = writeln!(
        o,
        "<g class=\"observed-cracks\" fill=\"none\" stroke=\"{OBSERVED}\" stroke-width=\"2\">"
    );
    for ob in r.observations.iter().filter(|ob| ob.observed > 0.0) {
        let u = point_motion(r, ob.joint, [ob.x, ob.y]);
        let p = d.frame.px([ob.x + s * u[0], ob.y + s * u[1]]);
        let rad = 4.0 + 8.0 * (ob.observed / wmax.max(1e-300)).sqrt();
        let _ = writeln!(
            o,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"><title>observed {} mm, predicted {} mm</title></circle>",
            num(p[0]),
            num(p[1]),
            num(rad),
            esc(&human(ob.observed * 1000.0, 4)),
            esc(&human(ob.predicted * 1000.0, 4))
        );
    }
    o.push_str("</g>\n");
    let contradictions: Vec<_> = r
        .predicted_cracks
        .iter()
        .filter(|c| c.observed == "closed")
        .collect();
    if !contradictions.is_empty() {
        let _ = writeln!(
            o,
            "<g class=\"contradictions\" stroke=\"{CONTRADICTION}\" stroke-width=\"2.2\" fill=\"none\">"
        );
        for c in &contradictions {
            let u = point_motion(r, c.joint, [c.x, c.y]);
            let p = d.frame.px([c.x + s * u[0], c.y + s * u[1]]);
            let h = 6.0;
            let _ = writeln!(
                o,
                "<path d=\"M{} {}L{} {}M{} {}L{} {}\"/>",
                num(p[0] - h),
                num(p[1] - h),
                num(p[0] + h),
                num(p[1] + h),
                num(p[0] - h),
                num(p[1] + h),
                num(p[0] + h),
                num(p[1] - h)
            );
        }
        o.push_str("</g>\n");
    }
    // Key of the overlay, top right.
    let fs = 12.5;
    let mut items = vec![(
        format!("<circle cx=\"11\" cy=\"0\" r=\"7\" fill=\"none\" stroke=\"{OBSERVED}\" stroke-width=\"2\"/>"),
        "observed crack (ring grows with width)".to_string(),
    )];
    items.push((
        "<path d=\"M2 6L22 -6L22 6Z\" fill=\"#d7301f\" fill-opacity=\"0.85\"/>".to_string(),
        "predicted crack".to_string(),
    ));
    if !contradictions.is_empty() {
        items.push((
            format!("<path d=\"M5 -6L17 6M5 6L17 -6\" stroke=\"{CONTRADICTION}\" stroke-width=\"2.2\"/>"),
            "predicted open, observed closed".to_string(),
        ));
    }
    let wtext = items
        .iter()
        .map(|(_, l)| text_width(l, fs))
        .fold(0.0f64, f64::max);
    let x0 = d.width - 28.0 - 30.0 - wtext;
    for (i, (sym, label)) in items.iter().enumerate() {
        let y = 24.0 + 20.0 * i as f64;
        let _ = writeln!(
            o,
            "<g transform=\"translate({} {})\">{sym}</g><text x=\"{}\" y=\"{}\" font-size=\"{fs}\" fill=\"#333333\">{}</text>",
            num(x0),
            num(y),
            num(x0 + 30.0),
            num(y + 4.5),
            esc(label)
        );
    }
    if let Some(end) = d.svg.rfind("</svg>") {
        d.svg.insert_str(end, &o);
    }
    d
}

/// The report: key numbers of the identification, its figure, the unknowns and observations,
/// then the forward settlement report of the identified motion.
pub fn identify_report(r: &IdentifyResult, opts: &ReportOptions) -> Report {
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Inverse settlement analysis".to_string()),
    );
    rep.subtitle = r.message.clone();
    rep.source = opts.source.clone();
    rep.command = "identify".into();
    let echo = crate::report_parts::ModelEcho::of_2d(&r.forward.geometry, r.forward.joints.len());
    let cert = vec![(
        "forward settlement analysis".to_string(),
        r.certificate
            .as_ref()
            .map_or("not run".to_string(), |c| c.message.clone()),
    )];
    rep.sections.extend(crate::report_parts::front_matter(
        Some(&echo),
        opts.inputs.as_ref(),
        crate::report_parts::Analysis::Identify,
        &opts.source,
        Some(&r.forward.solver),
        cert,
    ));
    let mut kv = vec![(
        "outcome".to_string(),
        format!("{:?}", r.status).to_lowercase(),
    )];
    // Each unknown in the summaries' unit (cm, or mrad for a rotation) when the command said
    // which it is; else in the units of --unknown (m, rad).
    let kinds = opts
        .inputs
        .as_ref()
        .map(|i| i.unknown_lengths.clone())
        .unwrap_or_default();
    for (k, u) in r.unknowns.iter().enumerate() {
        let show = |x: f64| match kinds.get(k) {
            Some(l) => l.show(x),
            None => format!("{} (m or rad)", human(x, 6)),
        };
        let range = match (u.range_min, u.range_max) {
            (Some(a), Some(b)) => format!(", range [{}, {}]", show(a), show(b)),
            _ if u.range_computed => ", range unbounded or empty".to_string(),
            _ => String::new(),
        };
        kv.push((
            format!("unknown {}", u.name),
            format!("{}{range} — {}", show(u.value), u.note),
        ));
    }
    kv.push((
        "misfit".into(),
        format!(
            "{} tolerances in total, largest {}",
            fmt_fixed(r.total_misfit, 4),
            Length::Opening.show(r.max_misfit)
        ),
    ));
    if let Some(c) = &r.certificate {
        kv.push(("forward analysis".into(), c.message.clone()));
    }
    let res = rep.section("Results");
    res.key_values(kv);
    let motions = r
        .support_motions
        .iter()
        .map(|m| {
            vec![
                m.support.clone(),
                Length::Motion.number(m.u),
                Length::Motion.number(m.v),
                Length::Rotation.number(m.theta),
            ]
        })
        .collect();
    res.table(
        "Identified support motions (base plus unknowns)",
        vec![
            "support".to_string(),
            format!("u ({})", Length::Motion.unit()),
            format!("v ({})", Length::Motion.unit()),
            format!("θ ({})", Length::Rotation.unit()),
        ],
        motions,
    );
    let d = draw_identify(
        r,
        &DrawOptions {
            scale: opts.scale,
            id: "fig-identify".into(),
            ..DrawOptions::default()
        },
        None,
    );
    rep.section("Observed and predicted cracks").figure(
        d.svg,
        format!(
            "Forward settlement mechanism of the identified motion (displacements × {}), predicted cracks as red wedges, observed cracks as green rings.",
            human(d.scale, 4)
        ),
    );
    let rows = r
        .observations
        .iter()
        .map(|o| {
            vec![
                o.crack.to_string(),
                o.joint.to_string(),
                o.point.to_string(),
                format!(
                    "({}, {})",
                    Length::Position.number(o.x),
                    Length::Position.number(o.y)
                ),
                Length::Opening.number(o.observed),
                Length::Opening.number(o.predicted),
                Length::Opening.number(o.misfit),
                Length::Opening.number(o.tolerance),
            ]
        })
        .collect();
    rep.section("Observations (mm)").table(
        "Observed against predicted widths (mm)",
        [
            "crack",
            "joint",
            "point",
            "at (m)",
            "observed",
            "predicted",
            "misfit",
            "tolerance",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
        rows,
    );
    let fwd = settlement_report(&r.forward, opts);
    for mut s in fwd.sections {
        // The hypotheses and inputs are the identification's own, above.
        if s.heading == "Hypotheses" || s.heading == "Inputs" {
            continue;
        }
        s.heading = format!("Forward analysis — {}", s.heading);
        rep.sections.push(s);
    }
    rep
}
