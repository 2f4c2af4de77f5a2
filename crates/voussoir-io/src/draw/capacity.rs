//! Pictures of the capacity analysis (limit analysis after a settlement, the paper's Figs 7, 10
//! and 12): the λ–settlement curve with the zero-capacity settlement marked, the settlement
//! mechanism, and a report.

use super::plot::{plot, Mark, Plot, PlotSpec, Series, SERIES_COLOURS};
use super::report::{model_summary, Report, ReportOptions};
use super::scene::{draw, DrawOptions, MotionUnits, Scene};
use super::svg::{fmt_fixed, human};
use voussoir::analysis::capacity::{CapacityResult, CapacityStatus};
use voussoir::result::BlockMotion;

/// Largest deviation from the least-squares line, relative to λ(0), up to which λ(s) is called
/// linear and its fit is shown (5 %: within the scatter engineers accept for a straight-line
/// reading of a curve; the paper's arches deviate by well under 1 %).
pub const LINEAR_FIT_TOLERANCE: f64 = 0.05;

/// The linear fit of a capacity curve as one line of text: the fit where it fits, else a
/// warning stating the deviation (no fit printed as if it described the curve).
#[derive(Clone, Debug, PartialEq)]
pub enum LinearFitText {
    Fits(String),
    DoesNotFit(String),
}

/// See [`LinearFitText`]; `None` without a fit (fewer than two valid points).
pub fn linear_fit_text<D: voussoir::result::Spatial>(
    r: &CapacityResult<D>,
) -> Option<LinearFitText> {
    let f = r.linear_fit.as_ref()?;
    let dev = human(100.0 * f.max_relative_deviation, 3);
    if f.max_relative_deviation <= LINEAR_FIT_TOLERANCE {
        Some(LinearFitText::Fits(format!(
            "λ ≈ {} {} {}·s (s in m); largest deviation {} % of λ(0)",
            fmt_fixed(f.intercept, 4),
            if f.slope < 0.0 { "−" } else { "+" },
            human(f.slope.abs(), 4),
            dev
        )))
    } else {
        Some(LinearFitText::DoesNotFit(format!(
            "λ(s) is not linear: a straight line deviates from it by up to {dev} % of λ(0) (more than {} %), so no linear fit is given",
            human(100.0 * LINEAR_FIT_TOLERANCE, 3)
        )))
    }
}

/// The curve λ(s) of one result as plot series (settlement in cm): the valid points as a solid
/// line with markers and, if any, the points where the collapse mechanism would close
/// settlement cracks (standard limit analysis not valid there) dashed.
pub fn capacity_series(r: &CapacityResult, label: &str, colour: &str) -> Vec<Series> {
    let n = r.curve.len();
    let xy = |i: usize| -> [f64; 2] {
        let p = &r.curve[i];
        match p.load_multiplier {
            Some(l) if l.is_finite() && p.settlement.is_finite() => [p.settlement * 100.0, l],
            _ => [f64::NAN, f64::NAN],
        }
    };
    let mut valid = Vec::with_capacity(n);
    let mut invalid = Vec::new();
    for i in 0..n {
        if r.curve[i].valid {
            valid.push(xy(i));
        } else {
            valid.push([f64::NAN, f64::NAN]);
        }
    }
    // Invalid runs, joined to their valid neighbours so the curve reads continuous.
    for i in 0..n {
        let bad = !r.curve[i].valid;
        let touches_bad =
            bad || (i > 0 && !r.curve[i - 1].valid) || (i + 1 < n && !r.curve[i + 1].valid);
        invalid.push(if touches_bad {
            xy(i)
        } else {
            [f64::NAN, f64::NAN]
        });
    }
    let mut out = vec![Series {
        label: label.to_string(),
        points: valid,
        markers: true,
        dashed: false,
        colour: Some(colour.to_string()),
    }];
    if r.curve.iter().any(|p| !p.valid) {
        out.push(Series {
            label: format!("{label}: not valid (closes settlement cracks)"),
            points: invalid,
            markers: false,
            dashed: true,
            colour: Some(colour.to_string()),
        });
    }
    out
}

/// λ–settlement curves of one or more capacity results on one plot, with the settlement at
/// which λ reaches zero marked on each.
pub fn capacity_plot(curves: &[(&str, &CapacityResult)], title: &str) -> Plot {
    let mut series = Vec::new();
    let mut marks = Vec::new();
    for (i, (label, r)) in curves.iter().enumerate() {
        let colour = SERIES_COLOURS[i % SERIES_COLOURS.len()];
        series.extend(capacity_series(r, label, colour));
        if let Some(s0) = r.zero_capacity_settlement {
            if s0.is_finite() {
                marks.push(Mark::new(
                    s0 * 100.0,
                    0.0,
                    format!("λ = 0 at s = {} cm", fmt_fixed(s0 * 100.0, 3)),
                ));
            }
        }
        // The model's existing cracks close here: the curve's step up or down.
        if let Some(sc) = r.existing_cracks_closed_at {
            let after = r
                .curve
                .iter()
                .find(|p| p.settlement >= sc)
                .and_then(|p| p.load_multiplier);
            if let Some(l) = after {
                marks.push(Mark::new(
                    sc * 100.0,
                    l,
                    format!(
                        "existing cracks closed, s = {} cm",
                        fmt_fixed(sc * 100.0, 3)
                    ),
                ));
            }
        }
        if let Some(first) = r.curve.first().and_then(|p| p.load_multiplier) {
            if r.curve.len() > 1 && curves.len() == 1 {
                marks.push(Mark::new(
                    0.0,
                    first,
                    format!("λ₀ = {}", fmt_fixed(first, 3)),
                ));
            }
        }
    }
    plot(
        &series,
        &PlotSpec {
            title: title.to_string(),
            x_label: "settlement s (cm)".into(),
            y_label: "collapse load multiplier λ".into(),
            marks,
            id: "cap".into(),
            ..PlotSpec::default()
        },
    )
}

/// The settlement mechanism at the largest settlement, in metres (blocks and supports).
pub fn settlement_motions(r: &CapacityResult) -> Vec<BlockMotion> {
    let s = if r.max_settlement.is_finite() {
        r.max_settlement
    } else {
        0.0
    };
    r.settlement_mechanism
        .iter()
        .map(|b| BlockMotion::planar(b.id, b.u * s, b.v * s, b.theta * s))
        .collect()
}

/// Report of a capacity analysis: key numbers, the curve, the settlement mechanism, the table.
pub fn capacity_report(r: &CapacityResult, opts: &ReportOptions) -> Report {
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Capacity after settlement".to_string()),
    );
    rep.subtitle = r.message.clone();
    let mut kv = vec![(
        "outcome".to_string(),
        match r.status {
            CapacityStatus::Curve => "curve computed".to_string(),
            CapacityStatus::NoSettlementMechanism => {
                "no settlement mechanism: no curve".to_string()
            }
        },
    )];
    let dir: Vec<String> = r
        .direction
        .iter()
        .map(|d| {
            format!(
                "{} ({}, {}) per m",
                d.support,
                human(d.motion[0], 4),
                human(d.motion[1], 4)
            )
        })
        .collect();
    kv.push(("settlement direction".into(), dir.join("; ")));
    kv.push((
        "largest settlement".into(),
        format!("{} cm", human(r.max_settlement * 100.0, 4)),
    ));
    if let Some(l0) = r.curve.first().and_then(|p| p.load_multiplier) {
        kv.push(("λ without settlement".into(), fmt_fixed(l0, 6)));
    }
    kv.push((
        "settlement at which λ = 0".into(),
        r.zero_capacity_settlement
            .map(|s| format!("{} cm", fmt_fixed(s * 100.0, 4)))
            .unwrap_or_else(|| "not reached in the range".into()),
    ));
    match linear_fit_text(r) {
        Some(LinearFitText::Fits(t)) => kv.push(("linear fit".into(), t)),
        Some(LinearFitText::DoesNotFit(t)) => kv.push(("linear fit (warning)".into(), t)),
        None => {}
    }
    let invalid = r.curve.iter().filter(|p| !p.valid).count();
    kv.push((
        "validity".into(),
        if invalid == 0 {
            "standard limit analysis valid at every step".to_string()
        } else {
            format!("{invalid} of {} steps not valid: the collapse mechanism closes settlement cracks (use the incremental analysis)", r.curve.len())
        },
    ));
    kv.push((
        "LP solves / simplex iterations".into(),
        format!("{} / {}", r.solves, r.iterations),
    ));
    rep.section("Key numbers").key_values(kv);
    rep.section("Model")
        .key_values(model_summary(&r.geometry, 0, &opts.source));
    let sec = rep.section("Figures");
    let p = capacity_plot(&[("λ(s)", r)], "Collapse load multiplier after settlement");
    sec.figure(p.svg, "Collapse load multiplier λ against the settlement s (limit analysis on the deformed geometry).");
    let motions = settlement_motions(r);
    if !motions.is_empty() {
        let mut scene = Scene::geometry(
            &r.geometry,
            "Settlement mechanism at the largest settlement",
        );
        scene.blocks = &motions;
        scene.hinges = &r.settlement_hinges;
        scene.units = MotionUnits::Metres;
        let d = draw(
            &scene,
            &DrawOptions {
                scale: opts.scale,
                interactive: true,
                thrust_line: false,
                id: "fig-cap-mech".into(),
                ..DrawOptions::default()
            },
        );
        if d.deformed {
            sec.figure(
                d.svg,
                format!("Settlement mechanism for s = {} cm (displacements × {}; slider to change), hinges as dots.", human(r.max_settlement * 100.0, 4), human(d.scale, 4)),
            );
        }
    }
    let rows = r
        .curve
        .iter()
        .map(|p| {
            vec![
                fmt_fixed(p.settlement * 100.0, 4),
                p.load_multiplier
                    .map(|l| fmt_fixed(l, 6))
                    .unwrap_or_else(|| "—".into()),
                format!("{:?}", p.status).to_lowercase(),
                if p.valid { "yes".into() } else { "no".into() },
                p.hinges.len().to_string(),
            ]
        })
        .collect();
    rep.section("Curve").collapsed_table(
        "λ(s) at every step",
        ["s (cm)", "λ", "status", "valid", "hinges"]
            .iter()
            .map(|s| s.to_string())
            .collect(),
        rows,
    );
    rep
}
