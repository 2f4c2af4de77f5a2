//! Pictures of the incremental (nonlinear kinematic) analysis: the λ–control-displacement
//! curve (the paper's Figs 14–17) with jumps where open hinges close, and its mechanisms.

use super::plot::{plot, Mark, Plot, PlotSpec, Series, SERIES_COLOURS};
use super::report::{Report, ReportOptions};
use super::scene::{draw, DrawOptions, MotionUnits, Scene};
use super::svg::{fmt_fixed, human};
use crate::lengths::Length;
use voussoir::result::incremental::{EventKind, IncrementalResult};

/// The curve of one result: control displacement in cm (the summaries' unit of displacements,
/// [`crate::lengths`]) against λ = max(λ, 0). Two points at
/// the same displacement (just before and just after a closure) draw the jump.
pub fn incremental_series<D: voussoir::result::Spatial>(
    r: &IncrementalResult<D>,
    label: &str,
    colour: &str,
) -> Series {
    Series {
        label: label.to_string(),
        points: r
            .curve
            .iter()
            .map(|p| {
                if p.displacement.is_finite() && p.load_multiplier.is_finite() {
                    [p.displacement * Length::Motion.factor(), p.load_multiplier]
                } else {
                    [f64::NAN, f64::NAN]
                }
            })
            .collect(),
        markers: false,
        dashed: false,
        colour: Some(colour.to_string()),
    }
}

/// λ–displacement curves of one or more incremental results on one plot (the paper's Fig 17),
/// each peak marked.
/// (2D or 3D: only the curves are drawn.)
pub fn incremental_plot<D: voussoir::result::Spatial>(
    curves: &[(&str, &IncrementalResult<D>)],
    title: &str,
) -> Plot {
    let mut series = Vec::new();
    let mut marks = Vec::new();
    for (i, (label, r)) in curves.iter().enumerate() {
        series.push(incremental_series(
            r,
            label,
            SERIES_COLOURS[i % SERIES_COLOURS.len()],
        ));
        if r.peak_load_multiplier.is_finite()
            && r.peak_displacement.is_finite()
            && r.peak_load_multiplier > 0.0
        {
            marks.push(Mark::new(
                r.peak_displacement * Length::Motion.factor(),
                r.peak_load_multiplier,
                format!("peak λ = {}", fmt_fixed(r.peak_load_multiplier, 3)),
            ));
        }
    }
    plot(
        &series,
        &PlotSpec {
            title: title.to_string(),
            x_label: format!("control displacement dx ({})", Length::Motion.unit()),
            y_label: "load multiplier λ".into(),
            marks,
            id: "inc".into(),
            ..PlotSpec::default()
        },
    )
}

/// Report of an incremental analysis: key numbers, the curve, the mechanisms at the first and
/// last snapshots, and the events.
pub fn incremental_report(r: &IncrementalResult, opts: &ReportOptions) -> Report {
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Incremental analysis".to_string()),
    );
    rep.subtitle = r.message.clone();
    rep.source = opts.source.clone();
    rep.command = "incremental".into();
    let echo = crate::report_parts::ModelEcho::of_2d(&r.initial_geometry, 0);
    rep.sections.extend(crate::report_parts::front_matter(
        Some(&echo),
        opts.inputs.as_ref(),
        crate::report_parts::Analysis::Incremental,
        &opts.source,
        Some(&r.solver),
        vec![(
            "check of λ at the start".to_string(),
            r.curve.first().map_or("no step".to_string(), |p| {
                format!(
                    "{} by the LP, {} by virtual work on its mechanism",
                    fmt_fixed(p.load_multiplier, 6),
                    fmt_fixed(p.equilibrium_multiplier, 6)
                )
            }),
        )],
    ));
    let c = &r.control;
    let kv = vec![
        (
            "outcome".to_string(),
            format!("{:?}", r.status).to_lowercase().replace('_', " "),
        ),
        (
            "control".into(),
            format!(
                "block {} at ({}, {}) m, direction ({}, {})",
                c.block,
                fmt_fixed(c.point[0], 4),
                fmt_fixed(c.point[1], 4),
                human(c.direction[0], 3),
                human(c.direction[1], 3)
            ),
        ),
        (
            "peak load multiplier".into(),
            fmt_fixed(r.peak_load_multiplier, 6),
        ),
        (
            "at control displacement".into(),
            format!(
                "{} {}",
                human(r.peak_displacement * Length::Motion.factor(), 4),
                Length::Motion.unit()
            ),
        ),
        (
            "λ at the start".into(),
            r.curve
                .first()
                .map_or("—".into(), |p| fmt_fixed(p.load_multiplier, 6)),
        ),
        (
            "final control displacement".into(),
            r.curve.last().map_or("—".into(), |p| {
                format!(
                    "{} {} (λ = {})",
                    Length::Motion.number(p.displacement),
                    Length::Motion.unit(),
                    fmt_fixed(p.load_multiplier, 6)
                )
            }),
        ),
        (
            "joints open at the start".into(),
            if r.initial_open_joints.is_empty() {
                "none".to_string()
            } else {
                format!(
                    "{} (joints {})",
                    r.initial_open_joints.len(),
                    r.initial_open_joints
                        .iter()
                        .map(|j| j.to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            },
        ),
        (
            "steps / snaps / events".into(),
            format!("{} / {} / {}", r.steps, r.snaps, r.events.len()),
        ),
        (
            "LP solves / simplex iterations".into(),
            format!("{} / {}", r.solves, r.iterations),
        ),
    ];
    rep.section("Results").key_values(kv);
    let sec = rep.section("Figures");
    let p = incremental_plot(
        &[("λ(dx)", r)],
        "Load multiplier against control displacement",
    );
    sec.figure(p.svg, "Load multiplier λ against the control displacement; vertical jumps where open hinges close.");
    let picks: Vec<_> = match (r.snapshots.first(), r.snapshots.last()) {
        (Some(a), Some(b)) if r.snapshots.len() > 1 => vec![a, b],
        (Some(a), _) => vec![a],
        _ => vec![],
    };
    for (k, s) in picks.into_iter().enumerate() {
        let title = format!(
            "Mechanism at dx = {} {} (λ = {})",
            human(s.displacement * Length::Motion.factor(), 4),
            Length::Motion.unit(),
            fmt_fixed(s.load_multiplier, 4)
        );
        let mut scene = Scene::geometry(&s.geometry, &title);
        scene.blocks = &s.blocks;
        scene.hinges = &s.hinges;
        scene.units = MotionUnits::Normalised;
        let d = draw(
            &scene,
            &DrawOptions {
                scale: opts.scale,
                interactive: true,
                thrust_line: false,
                id: format!("fig-inc-{k}"),
                ..DrawOptions::default()
            },
        );
        sec.figure(d.svg, format!("{title}: mechanism rate per unit control displacement, drawn × {}; current geometry.", human(d.scale, 4)));
    }
    let rows = r
        .events
        .iter()
        .map(|e| {
            vec![
                e.step.to_string(),
                Length::Motion.number(e.displacement),
                match e.kind {
                    EventKind::Opened => "opened".to_string(),
                    EventKind::Closed => "closed".to_string(),
                },
                e.joint.to_string(),
                fmt_fixed(e.x, 4),
                fmt_fixed(e.y, 4),
            ]
        })
        .collect();
    rep.section("Events").collapsed_table(
        "Contact changes",
        [
            "step".to_string(),
            format!("dx ({})", Length::Motion.unit()),
            "event".to_string(),
            "joint".to_string(),
            "x (m)".to_string(),
            "y (m)".to_string(),
        ]
        .to_vec(),
        rows,
    );
    rep
}
