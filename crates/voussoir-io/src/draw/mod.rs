//! Pictures of models and results: SVG drawings, PNG rendering, x–y plots, HTML reports.
//!
//! - [`scene`]: structures and mechanisms ([`Scene`] from a result, [`draw`] to SVG).
//! - [`plot`]: x–y curves with axes, grid, legend and labelled points ([`plot_curves`]).
//! - [`png`]: PNG from any of these SVGs with `resvg` and the bundled font ([`svg_to_png`]).
//! - [`report`]: a self-contained HTML report ([`Report`], [`limit_report`], [`settlement_report`]).
//!
//! All output is deterministic: the same input gives the same bytes.

// `!(x > 0.0)` is how these modules reject NaN along with non-positive values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod capacity;
pub(crate) mod chrome;
pub mod distribution;
pub mod identify;
pub mod incremental;
pub(crate) mod legend;
pub mod plot;
pub mod png;
pub mod report;
pub mod safety;
pub mod scene;
pub mod svg;

pub use capacity::{capacity_plot, capacity_report, capacity_series};
pub use identify::{draw_identify, identify_report, identify_scene};
pub use incremental::{incremental_plot, incremental_report, incremental_series};
pub use plot::{plot, plot_curves, Mark, Plot, PlotSpec, Series};
pub use png::svg_to_png;
pub use report::{limit_report, settlement_report, Report, ReportOptions, Section};
pub use safety::{safety_figure, safety_report};
pub use scene::{draw, DrawOptions, Drawing, Frame, MotionUnits, PressurePoints, Scene};

use crate::draw3d::{draw3d, Draw3dOptions, View};
use crate::result3d::{Figure3d, Result3d};
use crate::IoError;
use voussoir::dim::Three;
use voussoir::model3d::AnyModel;
use voussoir::result::identify::IdentifyResult;
use voussoir::result::spatial::SpatialShapes;
use voussoir::result::Geometry;
use voussoir::result::SafetyResult;
use voussoir::result::TiltResult;
use voussoir::result::{CapacityResult, IncrementalResult, LimitResult, SettlementResult};
use voussoir::{Assembly, BuildOptions, Structure, Structure3d};

/// Zoom used for PNG output: 1.5 device pixels per SVG pixel.
pub const PNG_ZOOM: f32 = 1.5;

/// A saved JSON file that can be drawn, recognised by its fields; the dimension (2D or 3D) by
/// its geometry (3D blocks are polyhedra with `vertices` and `faces`).
#[derive(Clone, Debug)]
pub enum Saved {
    /// A limit-analysis result (has `load_multiplier`).
    Limit(Box<LimitResult>),
    Limit3d(Box<LimitResult<Three>>),
    /// A settlement result (has `work_reactions` / `certificate`).
    Settlement(Box<SettlementResult>),
    Settlement3d(Box<SettlementResult<Three>>),
    /// A capacity result (has `curve` and `zero_capacity_settlement`): drawn as its λ–s curve.
    Capacity(Box<CapacityResult>),
    Capacity3d(Box<CapacityResult<Three>>),
    /// An incremental result (has `curve` and `peak_load_multiplier`): drawn as its λ–dx curve.
    Incremental(Box<IncrementalResult>),
    /// A 3D incremental result (a control point `[x, y, z]`): drawn as its λ–dx curve.
    Incremental3d(Box<IncrementalResult<Three>>),
    /// A tilting-table result (has `tilt_angle` and `limit`): the mechanism at the critical tilt.
    Tilt(Box<TiltResult>),
    Tilt3d(Box<TiltResult<Three>>),
    /// An inverse settlement analysis (has `unknowns`, `observations` and `forward`): observed
    /// and predicted cracks on the forward settlement.
    Identify(Box<IdentifyResult>),
    /// A safety assessment (has `stands` and `reactions`): the reaction ranges as a chart.
    Safety(Box<SafetyResult>),
    /// A model (has `blocks` of polygons and `supports`, no `status`): drawn with its loads.
    Model(Box<Geometry>),
    /// A 3D model (blocks of `vertices` and `faces`).
    Model3d(Box<SpatialShapes>),
}

impl Saved {
    /// Which kind of file this is, for messages.
    pub fn kind(&self) -> &'static str {
        match self {
            Saved::Limit(_) => "limit result",
            Saved::Limit3d(_) => "3D limit result",
            Saved::Settlement(_) => "settlement result",
            Saved::Settlement3d(_) => "3D settlement result",
            Saved::Capacity(_) => "capacity result",
            Saved::Capacity3d(_) => "3D capacity result",
            Saved::Incremental(_) => "incremental result",
            Saved::Incremental3d(_) => "3D incremental result",
            Saved::Tilt(_) => "tilt result",
            Saved::Tilt3d(_) => "3D tilt result",
            Saved::Identify(_) => "identify result",
            Saved::Safety(_) => "safety result",
            Saved::Model(_) => "model",
            Saved::Model3d(_) => "3D model",
        }
    }

    /// Whether the file is drawn as a curve or chart (capacity, incremental, safety) rather
    /// than as the structure.
    pub fn is_chart(&self) -> bool {
        matches!(
            self,
            Saved::Capacity(_)
                | Saved::Capacity3d(_)
                | Saved::Incremental(_)
                | Saved::Incremental3d(_)
                | Saved::Safety(_)
        )
    }

    /// Whether the structure is drawn in 3D.
    pub fn is_3d(&self) -> bool {
        matches!(
            self,
            Saved::Limit3d(_)
                | Saved::Settlement3d(_)
                | Saved::Capacity3d(_)
                | Saved::Tilt3d(_)
                | Saved::Model3d(_)
        )
    }
}

/// Whether a result's `geometry` (or a tilt's limit's) is 3D: polyhedra, centroids.
fn shapes_are_3d(g: Option<&serde_json::Value>) -> bool {
    let Some(g) = g else { return false };
    let first_is_object = |k: &str| {
        g.get(k)
            .and_then(|b| b.as_array())
            .and_then(|a| a.first())
            .is_some_and(|b| b.get("vertices").is_some())
    };
    g.get("centroids").is_some() || first_is_object("blocks") || first_is_object("supports")
}

fn parse<T: serde::de::DeserializeOwned>(
    v: serde_json::Value,
    what: &str,
) -> Result<Box<T>, IoError> {
    serde_json::from_value(v)
        .map(Box::new)
        .map_err(|e| IoError(format!("invalid {what}: {e}")))
}

/// A side of a reaction range the canonical selection found unbounded is ±∞, which JSON writes
/// as `null` (docs/canonical.md): read back as ±`f64::MAX`, so that a result is read as it was
/// written (`voussoir plot` refused the adapted door panel's settlement: "invalid type: null,
/// expected f64").
fn unbounded_ranges(v: &mut serde_json::Value) {
    let Some(ranges) = v
        .pointer_mut("/canonical/forces/reaction_ranges")
        .and_then(|r| r.as_array_mut())
    else {
        return;
    };
    for r in ranges {
        for (side, big) in [("min", -f64::MAX), ("max", f64::MAX)] {
            if let Some(w) = r.get_mut(side).and_then(|w| w.as_object_mut()) {
                for x in w.values_mut().filter(|x| x.is_null()) {
                    *x = serde_json::json!(big);
                }
            }
        }
    }
}

/// Recognise and parse a saved result or model, 2D or 3D.
pub fn parse_saved(text: &str) -> Result<Saved, IoError> {
    // Duplicate keys are refused as the analyses' readers refuse them (a `Value` would keep the
    // last one silently).
    crate::files::unique_keys(text).map_err(|e| IoError(format!("invalid JSON: {e}")))?;
    let v: serde_json::Value = serde_json::from_str(text).map_err(|e| {
        let lines = text.lines().filter(|l| !l.trim().is_empty()).count();
        let first = text.lines().next().unwrap_or("");
        if lines > 1 && serde_json::from_str::<serde_json::Map<_, _>>(first).is_ok() {
            IoError(
                "JSON lines (as `sweep --jsonl` writes): voussoir plot draws one result per file; a sweep's distribution of λ is drawn by `sweep --capacity --svg/--png/--report`".into(),
            )
        } else {
            IoError(format!("not JSON: {e}"))
        }
    })?;
    let mut v = v;
    unbounded_ranges(&mut v);
    let obj = v
        .as_object()
        .ok_or_else(|| IoError("expected a JSON object (a saved result or a model)".into()))?;
    let has = |k: &str| obj.contains_key(k);
    let three = shapes_are_3d(obj.get("geometry"));
    if has("tilt_angle") && has("limit") {
        let three = shapes_are_3d(obj.get("limit").and_then(|l| l.get("geometry")));
        return Ok(if three {
            Saved::Tilt3d(parse(v, "3D tilt result")?)
        } else {
            Saved::Tilt(parse(v, "tilt result")?)
        });
    }
    if has("unknowns") && has("observations") && has("forward") {
        return Ok(Saved::Identify(parse(v, "identify result")?));
    }
    if has("stands") && has("reactions") && has("geometric_safety_factor") {
        return Ok(Saved::Safety(parse(v, "safety result")?));
    }
    if has("status") && has("geometry") && has("load_multiplier") {
        return Ok(if three {
            Saved::Limit3d(parse(v, "3D limit result")?)
        } else {
            Saved::Limit(parse(v, "limit result")?)
        });
    }
    // A capacity result before a settlement's: it carries a `certificate` too (its steps').
    if has("status") && has("geometry") && has("curve") && has("zero_capacity_settlement") {
        return Ok(if three {
            Saved::Capacity3d(parse(v, "3D capacity result")?)
        } else {
            Saved::Capacity(parse(v, "capacity result")?)
        });
    }
    if has("status") && has("geometry") && (has("work_reactions") || has("certificate")) {
        return Ok(if three {
            Saved::Settlement3d(parse(v, "3D settlement result")?)
        } else {
            Saved::Settlement(parse(v, "settlement result")?)
        });
    }
    if has("status") && has("curve") && has("peak_load_multiplier") {
        // The control point's dimension tells a 3D result ([x, y, z]) from a 2D one.
        let point = obj
            .get("control")
            .and_then(|c| c.get("point"))
            .and_then(|p| p.as_array());
        return Ok(if point.is_some_and(|p| p.len() == 3) {
            Saved::Incremental3d(parse(v, "3D incremental result")?)
        } else {
            Saved::Incremental(parse(v, "incremental result")?)
        });
    }
    if has("blocks") && has("supports") && !has("status") {
        return match AnyModel::from_json(text)
            .map_err(|e| IoError(format!("invalid model JSON: {e}")))?
        {
            AnyModel::Planar(m) => {
                let st = Structure::new(&m, BuildOptions { tolerance: None })?;
                Ok(Saved::Model(Box::new(Geometry::of(&st))))
            }
            AnyModel::Spatial(m) => {
                let st = Structure3d::new(&m, BuildOptions { tolerance: None })?;
                Ok(Saved::Model3d(Box::new(st.shapes())))
            }
        };
    }
    const WHAT: &str = "voussoir plot draws the results that limit, settle, capacity, tilt, incremental, identify and safety write with -o, and models";
    if has("status") && has("geometry") {
        return Err(IoError(format!(
            "this result kind cannot be drawn ({WHAT})"
        )));
    }
    Err(IoError(format!("not a voussoir result or model ({WHAT})")))
}

/// A drawing of a saved file: the SVG and, for deformed drawings, the displacement scale used.
#[derive(Clone, Debug)]
pub struct SavedFigure {
    pub svg: String,
    pub scale: Option<f64>,
}

/// The tilting-table scene: the collapse mechanism at the critical tilt (the live load is the
/// horizontal λ·W of every block, λ = tan α).
pub fn tilt_scene(r: &TiltResult) -> Scene<'_> {
    let mut scene = Scene::limit(&r.limit);
    let towards = if r.direction > 0.0 { "+x" } else { "−x" };
    if let Some(a) = r.tilt_angle {
        scene.title = format!("Tilting table: collapse mechanism towards {towards}");
        scene.info.insert(
            0,
            format!("critical tilt angle α = {a:.3}°   ·   live load: horizontal, λ = tan α"),
        );
        scene.tilt = Some((a, format!("towards {towards}")));
    }
    scene
}

/// The report of a tilting-table result: the limit analysis' report, titled as its figure.
pub fn tilt_report(r: &TiltResult, opts: &ReportOptions) -> Report {
    let mut ro = opts.clone();
    if ro.title.is_none() {
        ro.title = Some(tilt_scene(r).title);
    }
    limit_report(&r.limit, &ro)
}

/// Draw a saved file in the default 3D view: see [`draw_saved_view`].
pub fn draw_saved(
    saved: &Saved,
    opts: &DrawOptions,
    title: Option<&str>,
) -> Result<SavedFigure, IoError> {
    draw_saved_view(saved, opts, View::default(), title)
}

/// Draw a saved file, with an optional title: a structure (2D scene, or the 3D drawing of
/// [`crate::draw3d`] seen from `view`), a capacity or incremental result as its curve, a
/// safety result as its chart of reaction ranges. Of `opts`, 3D drawings use the scale, the
/// width, `deformed`, `dead_loads` and `pressure_points`. Fails only on a 3D result whose shapes cannot be drawn.
pub fn draw_saved_view(
    saved: &Saved,
    opts: &DrawOptions,
    view: View,
    title: Option<&str>,
) -> Result<SavedFigure, IoError> {
    let with = |mut scene: Scene, t: Option<&str>| {
        if let Some(t) = t {
            scene.title = t.to_string();
        }
        let d = draw(&scene, opts);
        SavedFigure {
            svg: d.svg,
            scale: d.deformed.then_some(d.scale),
        }
    };
    let with3d = |r: &dyn Result3dRef| -> Result<SavedFigure, IoError> {
        let o = Draw3dOptions {
            view,
            scale: opts.scale,
            width: opts.width,
            deformed: opts.deformed,
            dead_loads: opts.dead_loads,
            pressure_points: opts.pressure_points,
            title: title.map(str::to_string),
            ..Draw3dOptions::default()
        };
        let d = r.draw(&o)?;
        Ok(SavedFigure {
            svg: d.svg,
            scale: d.deformed.then_some(d.scale),
        })
    };
    let chart = |svg: String| SavedFigure { svg, scale: None };
    Ok(match saved {
        Saved::Limit(r) => with(Scene::limit(r), title),
        Saved::Settlement(r) => with(Scene::settlement(r), title),
        Saved::Tilt(r) => with(tilt_scene(r), title),
        Saved::Model(g) => with(Scene::geometry(g, "Model and loads"), title),
        Saved::Identify(r) => {
            let d = draw_identify(r, opts, title);
            SavedFigure {
                svg: d.svg,
                scale: d.deformed.then_some(d.scale),
            }
        }
        Saved::Limit3d(r) => with3d(r.as_ref())?,
        Saved::Settlement3d(r) => with3d(r.as_ref())?,
        Saved::Tilt3d(r) => with3d(r.as_ref())?,
        Saved::Model3d(g) => with3d(&Figure3d::model(g.as_ref().clone()))?,
        Saved::Capacity(r) => {
            chart(capacity_plot(&[("λ(s)", r.as_ref())], title.unwrap_or(CAPACITY_TITLE)).svg)
        }
        Saved::Capacity3d(r) => {
            chart(capacity_plot(&[("λ(s)", r.as_ref())], title.unwrap_or(CAPACITY_TITLE)).svg)
        }
        Saved::Incremental(r) => chart(
            incremental_plot(&[("λ(dx)", r.as_ref())], title.unwrap_or(INCREMENTAL_TITLE)).svg,
        ),
        Saved::Incremental3d(r) => chart(
            incremental_plot(&[("λ(dx)", r.as_ref())], title.unwrap_or(INCREMENTAL_TITLE)).svg,
        ),
        Saved::Safety(r) => chart(safety_figure(
            r,
            &title.map_or_else(|| safety::safety_title(r), str::to_string),
        )),
    })
}

/// Default title of a capacity curve.
pub const CAPACITY_TITLE: &str = "Collapse load multiplier after settlement";
/// Default title of an incremental curve.
pub const INCREMENTAL_TITLE: &str = "Load multiplier against control displacement";

/// A 3D result behind a reference, drawn (object-safe: [`Result3d`] is used generically).
trait Result3dRef {
    fn draw(&self, o: &Draw3dOptions) -> Result<crate::draw3d::Drawing3d, IoError>;
    fn report(&self, title: &str, source: &str) -> Result<String, IoError>;
}

impl<T: Result3d> Result3dRef for T {
    fn draw(&self, o: &Draw3dOptions) -> Result<crate::draw3d::Drawing3d, IoError> {
        draw3d(self, o)
    }
    fn report(&self, title: &str, source: &str) -> Result<String, IoError> {
        crate::report3d::report3d_html(self, title, source)
    }
}

/// The HTML report of a saved file (3D structures: the report of [`crate::report3d`] with its
/// 3D viewer). Fails only on a 3D result whose shapes cannot be drawn.
pub fn report_saved(saved: &Saved, opts: &ReportOptions) -> Result<String, IoError> {
    let title = opts.title.clone().unwrap_or_default();
    let r3 = |r: &dyn Result3dRef| r.report(&title, &opts.source);
    Ok(match saved {
        Saved::Limit(r) => limit_report(r, opts).to_html(),
        Saved::Settlement(r) => settlement_report(r, opts).to_html(),
        Saved::Capacity(r) => capacity_report(r.as_ref(), opts).to_html(),
        Saved::Capacity3d(r) => capacity_report(r.as_ref(), opts).to_html(),
        Saved::Incremental(r) => incremental_report(r, opts).to_html(),
        Saved::Incremental3d(_) => return Err(IoError(
            "a 3D incremental result has no report (.html): draw its λ(dx) curve as .svg or .png"
                .into(),
        )),
        Saved::Tilt(r) => tilt_report(r, opts).to_html(),
        Saved::Identify(r) => identify_report(r, opts).to_html(),
        Saved::Safety(r) => safety_report(r, opts).to_html(),
        Saved::Limit3d(r) => r3(r.as_ref())?,
        Saved::Settlement3d(r) => r3(r.as_ref())?,
        Saved::Tilt3d(r) => r3(r.as_ref())?,
        Saved::Model3d(g) => r3(&Figure3d::model(g.as_ref().clone()))?,
        Saved::Model(g) => {
            let mut rep = Report::new(opts.title.clone().unwrap_or_else(|| "Model".to_string()));
            rep.section("Model")
                .key_values(report::model_summary(g, 0, &opts.source));
            let d = draw(
                &Scene::geometry(g, "Model and loads"),
                &DrawOptions {
                    id: "fig-model".into(),
                    ..DrawOptions::default()
                },
            );
            rep.section("Figure")
                .figure(d.svg, "The model: blocks, hatched supports and live loads.");
            rep.to_html()
        }
    })
}
