//! Pictures of the capacity analysis (limit analysis after a settlement, the paper's Figs 7, 10
//! and 12): the λ–settlement curve with the zero-capacity settlement marked, the settlement
//! mechanism, and a report.

use super::plot::{plot, Mark, Plot, PlotSpec, Series, SERIES_COLOURS};
use super::report::{model_summary, Report, ReportOptions};
use super::scene::{draw, DrawOptions, MotionUnits, Scene};
use super::svg::{fmt_fixed, human};
use voussoir::analysis::LimitStatus;
use voussoir::dim::{Three, Two};
use voussoir::result::{BlockMotion, Spatial};
use voussoir::result::{CapacityResult, CapacityStatus, SettlementUnit, SupportDirection};

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
pub fn linear_fit_text<D: Spatial>(r: &CapacityResult<D>) -> Option<LinearFitText> {
    let f = r.linear_fit.as_ref()?;
    let dev = human(100.0 * f.max_relative_deviation, 3);
    if f.max_relative_deviation <= LINEAR_FIT_TOLERANCE {
        // s in the unit of the curve's axis and of the summaries (cm, or mrad for rotations).
        Some(LinearFitText::Fits(format!(
            "λ ≈ {} {} {}·s (s in {}); largest deviation {} % of λ(0)",
            // λ(0) below 1e-3 in significant digits, as the summaries' λ (session 25: the arch
            // at micrometre size printed "λ ≈ 0 − 0.2941·s").
            if f.intercept != 0.0 && f.intercept.abs() < 1e-3 {
                voussoir::analysis::limit::show_multiplier(f.intercept)
            } else {
                fmt_fixed(f.intercept, 4)
            },
            if f.slope < 0.0 { "−" } else { "+" },
            human(f.slope.abs() / r.unit().factor(), 4),
            r.unit().shown(),
            dev
        )))
    } else {
        Some(LinearFitText::DoesNotFit(format!(
            "λ(s) is not linear: a straight line deviates from it by up to {dev} % of λ(0) (more than {} %), so no linear fit is given",
            human(100.0 * LINEAR_FIT_TOLERANCE, 3)
        )))
    }
}

/// The curve λ(s) of one result as plot series (a settlement in cm, a support rotation in mrad:
/// [`SettlementUnit`]): the valid points as a solid line with markers and, if any, the points
/// where the collapse mechanism would close settlement cracks (standard limit analysis not valid
/// there) dashed.
pub fn capacity_series<D: Spatial>(
    r: &CapacityResult<D>,
    label: &str,
    colour: &str,
) -> Vec<Series> {
    let n = r.curve.len();
    let k = r.unit().factor();
    let xy = |i: usize| -> [f64; 2] {
        let p = &r.curve[i];
        match p.load_multiplier {
            Some(l) if l.is_finite() && p.settlement.is_finite() => [p.settlement * k, l],
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
    // The steps without equilibrium at any λ (no λ to draw; a negative λ, the reversed live
    // load the dead loads would need, is on the curve): markers on the axis, each on its own
    // (no line between them), so that the figure spans the settlements analysed and shows
    // where the structure cannot stand (a grid façade that has no equilibrium after any
    // settlement drew a lone point at s = 0 on an axis from −1 to 1 cm).
    let without: Vec<[f64; 2]> = r
        .curve
        .iter()
        .filter(|p| {
            p.status == LimitStatus::NoEquilibrium
                && p.load_multiplier.is_none()
                && p.settlement.is_finite()
        })
        .flat_map(|p| [[p.settlement * k, 0.0], [f64::NAN, f64::NAN]])
        .collect();
    if !without.is_empty() {
        out.push(Series {
            label: format!("{label}: no equilibrium"),
            points: without,
            markers: true,
            dashed: false,
            colour: Some(NO_EQUILIBRIUM_COLOUR.to_string()),
        });
    }
    out
}

/// The markers of the steps without equilibrium: grey, apart from the curves' palette.
const NO_EQUILIBRIUM_COLOUR: &str = "#8c8c8c";

/// What a capacity figure draws of a result, whatever its dimension: the curve's series and
/// marks, and the unit of its settlement axis.
pub struct CapacityCurve {
    pub series: Vec<Series>,
    pub marks: Vec<Mark>,
    pub unit: SettlementUnit,
}

impl CapacityCurve {
    /// The curve of `r` (the `i`-th of `of` curves on one plot: its colour, and the λ₀ mark
    /// when it is alone).
    pub fn of<D: Spatial>(r: &CapacityResult<D>, label: &str, i: usize, of: usize) -> Self {
        let colour = SERIES_COLOURS[i % SERIES_COLOURS.len()];
        let unit = r.unit();
        let (k, u) = (unit.factor(), unit.shown());
        let series = capacity_series(r, label, colour);
        let mut marks = Vec::new();
        if let Some(s0) = r.zero_capacity_settlement {
            if s0.is_finite() {
                marks.push(Mark::new(
                    s0 * k,
                    0.0,
                    if r.zero_at_onset() {
                        "λ = 0 from the onset of settlement".to_string()
                    } else {
                        format!("λ = 0 at s = {} {u}", fmt_fixed(s0 * k, 3))
                    },
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
                    sc * k,
                    l,
                    format!("existing cracks closed, s = {} {u}", fmt_fixed(sc * k, 3)),
                ));
            }
        }
        if let Some(first) = r.curve.first().and_then(|p| p.load_multiplier) {
            if r.curve.len() > 1 && of == 1 {
                marks.push(Mark::new(
                    0.0,
                    first,
                    format!("λ₀ = {}", fmt_fixed(first, 3)),
                ));
            }
        }
        CapacityCurve {
            series,
            marks,
            unit,
        }
    }
}

/// The label of the settlement axis: "settlement s (cm)" or "support rotation s (mrad)".
pub fn settlement_axis_label(unit: SettlementUnit) -> String {
    format!("{} s ({})", unit.noun(), unit.shown())
}

/// λ–settlement curves of one or more capacity results on one plot, with the settlement at
/// which λ reaches zero marked on each. The settlement axis is in cm, or in mrad when the
/// supports only rotate ([`SettlementUnit`]).
pub fn capacity_plot<D: Spatial>(curves: &[(&str, &CapacityResult<D>)], title: &str) -> Plot {
    let n = curves.len();
    let c: Vec<CapacityCurve> = curves
        .iter()
        .enumerate()
        .map(|(i, (label, r))| CapacityCurve::of(r, label, i, n))
        .collect();
    capacity_curves_plot(&c, title)
}

/// [`capacity_plot`] of curves of either dimension. Curves of both kinds of settlement (a
/// translation and a rotation) do not share an axis: the label then names both units (the CLI
/// refuses to mix them).
pub fn capacity_curves_plot(curves: &[CapacityCurve], title: &str) -> Plot {
    let mut series = Vec::new();
    let mut marks = Vec::new();
    for c in curves {
        series.extend(c.series.iter().cloned());
        marks.extend(c.marks.iter().cloned());
    }
    let first = curves
        .first()
        .map_or(SettlementUnit::Translation, |c| c.unit);
    let x_label = if curves.iter().all(|c| c.unit == first) {
        settlement_axis_label(first)
    } else {
        "settlement s (cm) · support rotation s (mrad)".to_string()
    };
    plot(
        &series,
        &PlotSpec {
            title: title.to_string(),
            x_label,
            y_label: "collapse load multiplier λ".into(),
            marks,
            id: "cap".into(),
            ..PlotSpec::default()
        },
    )
}

/// The settlement mechanism at the largest settlement, in metres (blocks and supports).
pub fn settlement_motions(r: &CapacityResult) -> Vec<BlockMotion> {
    let s = largest(r);
    r.settlement_mechanism
        .iter()
        .map(|b| BlockMotion::planar(b.id, b.u * s, b.v * s, b.theta * s))
        .collect()
}

fn largest<D: Spatial>(r: &CapacityResult<D>) -> f64 {
    if r.max_settlement.is_finite() {
        r.max_settlement
    } else {
        0.0
    }
}

/// What the capacity report draws and lists in each dimension: the model's key numbers, a
/// support's direction, and the figure of the settlement mechanism (2D: the scene; 3D: the
/// axonometric drawing of [`crate::draw3d`]).
pub trait CapacityFigures: Spatial + Sized {
    fn model_rows(r: &CapacityResult<Self>, source: &str) -> Vec<(String, String)>;
    /// The geometry, loads and supports of the result for the report's inputs.
    fn echo(r: &CapacityResult<Self>) -> crate::report_parts::ModelEcho;
    fn direction_text(d: &SupportDirection, unit: SettlementUnit) -> String;
    /// The settlement mechanism at the largest settlement and its caption, if anything moves.
    fn mechanism_figure(r: &CapacityResult<Self>, scale: Option<f64>) -> Option<(String, String)>;
}

/// Components of a support's direction: "(u, v, θ)" with the non-zero ones named.
fn direction_parts(d: &SupportDirection, names: &[&str], unit: SettlementUnit) -> String {
    let per = match unit {
        SettlementUnit::Translation => "per m",
        SettlementUnit::Rotation => "per rad",
    };
    let parts: Vec<String> = names
        .iter()
        .zip(&d.motion)
        .filter(|(_, x)| **x != 0.0)
        .map(|(n, x)| format!("{n} = {}", human(*x, 4)))
        .collect();
    format!("{} ({}) {per}", d.support, parts.join(", "))
}

impl CapacityFigures for Two {
    fn echo(r: &CapacityResult<Two>) -> crate::report_parts::ModelEcho {
        crate::report_parts::ModelEcho::of_2d(&r.geometry, 0)
    }
    fn model_rows(r: &CapacityResult<Two>, source: &str) -> Vec<(String, String)> {
        model_summary(&r.geometry, 0, source)
    }
    fn direction_text(d: &SupportDirection, unit: SettlementUnit) -> String {
        direction_parts(d, &["u", "v", "θ"], unit)
    }
    fn mechanism_figure(r: &CapacityResult<Two>, scale: Option<f64>) -> Option<(String, String)> {
        let motions = settlement_motions(r);
        if motions.is_empty() {
            return None;
        }
        let mut scene = Scene::geometry(
            &r.geometry,
            "Settlement mechanism at the largest settlement",
        );
        scene.blocks = &motions;
        scene.hinges = &r.settlement_hinges;
        scene.cracks = &r.cracks;
        scene.units = MotionUnits::Metres;
        let d = draw(
            &scene,
            &DrawOptions {
                scale,
                interactive: true,
                thrust_line: false,
                id: "fig-cap-mech".into(),
                ..DrawOptions::default()
            },
        );
        d.deformed.then(|| {
            (
                d.svg,
                format!(
                    "Settlement mechanism for s = {} (displacements × {}; slider to change), hinges as dots.",
                    r.unit().show(r.max_settlement, 4),
                    human(d.scale, 4)
                ),
            )
        })
    }
}

impl CapacityFigures for Three {
    fn echo(r: &CapacityResult<Three>) -> crate::report_parts::ModelEcho {
        crate::report_parts::ModelEcho::of_3d(&r.geometry, 0)
    }
    fn model_rows(r: &CapacityResult<Three>, source: &str) -> Vec<(String, String)> {
        crate::result3d::model_rows_3d(&r.geometry, source)
    }
    fn direction_text(d: &SupportDirection, unit: SettlementUnit) -> String {
        direction_parts(d, &["u", "v", "w", "θx", "θy", "θz"], unit)
    }
    fn mechanism_figure(r: &CapacityResult<Three>, scale: Option<f64>) -> Option<(String, String)> {
        let fig = crate::result3d::Figure3d::capacity_settlement(r);
        if fig.blocks.is_empty() {
            return None;
        }
        let d = crate::draw3d::draw3d(
            &fig,
            &crate::draw3d::Draw3dOptions {
                scale,
                id: "fig-cap-mech".into(),
                ..crate::draw3d::Draw3dOptions::default()
            },
        )
        .ok()?;
        d.deformed.then(|| {
            (
                d.svg,
                format!(
                    "Settlement mechanism for s = {} (displacements × {}), hinges as dots.",
                    r.unit().show(r.max_settlement, 4),
                    human(d.scale, 4)
                ),
            )
        })
    }
}

/// Report of a capacity analysis (2D or 3D): key numbers, the curve, the settlement mechanism,
/// the table.
pub fn capacity_report<D: CapacityFigures>(r: &CapacityResult<D>, opts: &ReportOptions) -> Report {
    let unit = r.unit();
    let (k, u) = (unit.factor(), unit.shown());
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Capacity after settlement".to_string()),
    );
    rep.subtitle = r.message.clone();
    rep.source = opts.source.clone();
    rep.command = "capacity".into();
    let echo = D::echo(r);
    let analysis = crate::report_parts::Analysis::Capacity;
    rep.sections.push(crate::report_parts::hypotheses(
        &echo,
        opts.inputs.as_ref(),
        analysis,
        None,
    ));
    rep.sections.push(crate::report_parts::inputs(
        &echo,
        opts.inputs.as_ref(),
        analysis,
        &opts.source,
        Some(&r.solver),
        Vec::new(),
    ));
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
        .map(|d| D::direction_text(d, unit))
        .collect();
    kv.push((format!("{} direction", unit.noun()), dir.join("; ")));
    kv.push((
        format!("largest {}", unit.noun()),
        format!("{} {u}", human(r.max_settlement * k, 4)),
    ));
    if let Some(l0) = r.curve.first().and_then(|p| p.load_multiplier) {
        kv.push(("λ without settlement".into(), fmt_fixed(l0, 6)));
    }
    kv.push((
        format!("{} at which λ = 0", unit.noun()),
        r.zero_capacity_settlement
            .map(|s| format!("{} {u}", fmt_fixed(s * k, 4)))
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
    rep.section("Results").key_values(kv);
    let sec = rep.section("Figures");
    let p = capacity_plot(&[("λ(s)", r)], "Collapse load multiplier after settlement");
    sec.figure(
        p.svg,
        format!(
            "Collapse load multiplier λ against the {} s (limit analysis on the deformed geometry).",
            unit.noun()
        ),
    );
    if let Some((svg, caption)) = D::mechanism_figure(r, opts.scale) {
        sec.figure(svg, caption);
    }
    let rows = r
        .curve
        .iter()
        .map(|p| {
            vec![
                fmt_fixed(p.settlement * k, 4),
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
        [
            format!("s ({u})"),
            "λ".into(),
            "status".into(),
            "valid".into(),
            "hinges".into(),
        ]
        .to_vec(),
        rows,
    );
    rep
}
