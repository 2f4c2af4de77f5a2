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
pub mod distribution;
pub mod identify;
pub mod incremental;
pub mod plot;
pub mod png;
pub mod report;
pub mod scene;
pub mod svg;

pub use capacity::{capacity_plot, capacity_report, capacity_series};
pub use identify::{draw_identify, identify_report, identify_scene};
pub use incremental::{incremental_plot, incremental_report, incremental_series};
pub use plot::{plot, plot_curves, Mark, Plot, PlotSpec, Series};
pub use png::svg_to_png;
pub use report::{limit_report, settlement_report, Report, ReportOptions, Section};
pub use scene::{draw, DrawOptions, Drawing, Frame, MotionUnits, Scene};

use crate::IoError;
use voussoir::analysis::{CapacityResult, IncrementalResult, LimitResult, SettlementResult};
use voussoir::result::Geometry;
use voussoir::{BuildOptions, Model, Structure};

/// Zoom used for PNG output: 1.5 device pixels per SVG pixel.
pub const PNG_ZOOM: f32 = 1.5;

/// A saved JSON file that can be drawn, recognised by its fields.
#[derive(Clone, Debug)]
pub enum Saved {
    /// A limit-analysis result (has `load_multiplier`).
    Limit(Box<LimitResult>),
    /// A settlement result (has `work_reactions` / `certificate`).
    Settlement(Box<SettlementResult>),
    /// A capacity result (has `curve` and `zero_capacity_settlement`): drawn as its λ–s curve.
    Capacity(Box<CapacityResult>),
    /// An incremental result (has `curve` and `peak_load_multiplier`): drawn as its λ–dx curve.
    Incremental(Box<IncrementalResult>),
    /// A model (has `blocks` of polygons and `supports`, no `status`): drawn with its loads.
    Model(Box<Geometry>),
}

impl Saved {
    /// Which kind of file this is, for messages.
    pub fn kind(&self) -> &'static str {
        match self {
            Saved::Limit(_) => "limit result",
            Saved::Settlement(_) => "settlement result",
            Saved::Capacity(_) => "capacity result",
            Saved::Incremental(_) => "incremental result",
            Saved::Model(_) => "model",
        }
    }
}

/// Recognise and parse a saved result or model.
pub fn parse_saved(text: &str) -> Result<Saved, IoError> {
    // Duplicate keys are refused as the analyses' readers refuse them (a `Value` would keep the
    // last one silently).
    crate::files::unique_keys(text).map_err(|e| IoError(format!("invalid JSON: {e}")))?;
    let v: serde_json::Value =
        serde_json::from_str(text).map_err(|e| IoError(format!("not JSON: {e}")))?;
    let obj = v
        .as_object()
        .ok_or_else(|| IoError("expected a JSON object (a saved result or a model)".into()))?;
    let has = |k: &str| obj.contains_key(k);
    if has("status") && has("geometry") && has("load_multiplier") {
        let r: LimitResult =
            serde_json::from_value(v).map_err(|e| IoError(format!("invalid limit result: {e}")))?;
        return Ok(Saved::Limit(Box::new(r)));
    }
    if has("status") && has("geometry") && (has("work_reactions") || has("certificate")) {
        let r: SettlementResult = serde_json::from_value(v)
            .map_err(|e| IoError(format!("invalid settlement result: {e}")))?;
        return Ok(Saved::Settlement(Box::new(r)));
    }
    if has("status") && has("geometry") && has("curve") && has("zero_capacity_settlement") {
        let r: CapacityResult = serde_json::from_value(v)
            .map_err(|e| IoError(format!("invalid capacity result: {e}")))?;
        return Ok(Saved::Capacity(Box::new(r)));
    }
    if has("status") && has("curve") && has("peak_load_multiplier") {
        let r: IncrementalResult = serde_json::from_value(v)
            .map_err(|e| IoError(format!("invalid incremental result: {e}")))?;
        return Ok(Saved::Incremental(Box::new(r)));
    }
    if has("blocks") && has("supports") && !has("status") {
        let m: Model =
            serde_json::from_value(v).map_err(|e| IoError(format!("invalid model JSON: {e}")))?;
        let st = Structure::new(&m, BuildOptions { tolerance: None })?;
        return Ok(Saved::Model(Box::new(Geometry::of(&st))));
    }
    if has("status") && has("geometry") {
        return Err(IoError(
            "this result kind cannot be drawn yet (voussoir plot draws limit, settlement, capacity and incremental results and models)"
                .into(),
        ));
    }
    Err(IoError("not a voussoir result or model (expected `geometry` and `status`, or `blocks` and `supports`)".into()))
}

/// A drawing of a saved file: the SVG and, for deformed drawings, the displacement scale used.
#[derive(Clone, Debug)]
pub struct SavedFigure {
    pub svg: String,
    pub scale: Option<f64>,
}

/// Draw a saved file (a capacity result as its λ–s curve), with an optional title.
pub fn draw_saved(saved: &Saved, opts: &DrawOptions, title: Option<&str>) -> SavedFigure {
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
    match saved {
        Saved::Limit(r) => with(Scene::limit(r), title),
        Saved::Settlement(r) => with(Scene::settlement(r), title),
        Saved::Model(g) => with(Scene::geometry(g, "Model and loads"), title),
        Saved::Capacity(r) => {
            let t = title.unwrap_or("Collapse load multiplier after settlement");
            SavedFigure {
                svg: capacity_plot(&[("λ(s)", r)], t).svg,
                scale: None,
            }
        }
        Saved::Incremental(r) => {
            let t = title.unwrap_or("Load multiplier against control displacement");
            SavedFigure {
                svg: incremental_plot(&[("λ(dx)", r)], t).svg,
                scale: None,
            }
        }
    }
}

/// The report of a saved file.
pub fn report_saved(saved: &Saved, opts: &ReportOptions) -> Report {
    match saved {
        Saved::Limit(r) => limit_report(r, opts),
        Saved::Settlement(r) => settlement_report(r, opts),
        Saved::Capacity(r) => capacity_report(r, opts),
        Saved::Incremental(r) => incremental_report(r, opts),
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
            rep
        }
    }
}
