//! Drawing flags shared by the analysis commands (`--svg`, `--png`, `--report`, `--scale`,
//! `--forces`). Flatten [`DrawArgs`] into a command and call one of its `emit_*` methods.

use crate::common::Fail;
use clap::Args;
use std::path::{Path, PathBuf};
use voussoir::analysis::{CapacityResult, IncrementalResult, LimitResult, SettlementResult};
use voussoir_io::draw::{self, DrawOptions, Report, ReportOptions, Scene};

#[derive(Args, Clone, Debug, Default)]
pub struct DrawArgs {
    /// Draw the result (deformed configuration, hinges, cracks, thrust line) as SVG.
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
    /// Draw the result as PNG (rendered from the same SVG, bundled font).
    #[arg(long, value_name = "FILE")]
    pub png: Option<PathBuf>,
    /// Write a self-contained HTML report (key numbers, tables, every figure).
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Displacement scale factor of the deformed drawing (default: automatic, shown in the
    /// figure). Limit mechanisms are normalised, settlement mechanisms are in metres.
    #[arg(long, value_name = "S")]
    pub scale: Option<f64>,
    /// Also draw contact-force resultants as arrows (length ∝ magnitude).
    #[arg(long)]
    pub forces: bool,
    /// Title of the drawing (default: by analysis).
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
}

impl DrawArgs {
    /// Whether any drawing output was asked for.
    pub fn any(&self) -> bool {
        self.svg.is_some() || self.png.is_some() || self.report.is_some()
    }

    pub fn options(&self) -> Result<DrawOptions, Fail> {
        if let Some(s) = self.scale {
            if !(s.is_finite() && s >= 0.0) {
                return Err(Fail(format!("--scale {s}: expected a finite number ≥ 0")));
            }
        }
        Ok(DrawOptions {
            scale: self.scale,
            forces: self.forces,
            ..DrawOptions::default()
        })
    }

    fn report_options(&self, source: &Path) -> ReportOptions {
        ReportOptions {
            title: self.title.clone(),
            source: source.display().to_string(),
            scale: self.scale,
        }
    }

    /// Write the SVG/PNG of a scene and the report (built only if asked for).
    pub fn emit_scene(&self, scene: Scene, report: impl FnOnce() -> Report) -> Result<(), Fail> {
        if !self.any() {
            return Ok(());
        }
        let mut scene = scene;
        if let Some(t) = &self.title {
            scene.title = t.clone();
        }
        let opts = self.options()?;
        if self.svg.is_some() || self.png.is_some() {
            let d = draw::draw(&scene, &opts);
            write_drawing(&d.svg, self.svg.as_deref(), self.png.as_deref())?;
        }
        if let Some(path) = &self.report {
            voussoir_io::write_atomic(path, report().to_html().as_bytes())?;
        }
        Ok(())
    }

    pub fn emit_limit(&self, r: &LimitResult, source: &Path) -> Result<(), Fail> {
        self.emit_scene(Scene::limit(r), || {
            draw::limit_report(r, &self.report_options(source))
        })
    }

    /// Capacity analysis: the figure is the λ–settlement curve; the report adds the settlement
    /// mechanism and the table of steps.
    pub fn emit_capacity(&self, r: &CapacityResult, source: &Path) -> Result<(), Fail> {
        self.emit_curve(
            "Collapse load multiplier after settlement",
            |title| draw::capacity_plot(&[("λ(s)", r)], title).svg,
            || draw::capacity_report(r, &self.report_options(source)).to_html(),
        )
    }

    /// Incremental analysis: the figure is the λ–control-displacement curve; the report adds
    /// the mechanisms and the events.
    pub fn emit_incremental(&self, r: &IncrementalResult, source: &Path) -> Result<(), Fail> {
        self.emit_curve(
            "Load multiplier against control displacement",
            |title| draw::incremental_plot(&[("λ(dx)", r)], title).svg,
            || draw::incremental_report(r, &self.report_options(source)).to_html(),
        )
    }

    /// A curve figure (SVG/PNG) and a report, each only when asked for.
    fn emit_curve(
        &self,
        default_title: &str,
        svg: impl FnOnce(&str) -> String,
        html: impl FnOnce() -> String,
    ) -> Result<(), Fail> {
        if self.svg.is_some() || self.png.is_some() {
            let title = self.title.as_deref().unwrap_or(default_title);
            write_drawing(&svg(title), self.svg.as_deref(), self.png.as_deref())?;
        }
        if let Some(path) = &self.report {
            voussoir_io::write_atomic(path, html().as_bytes())?;
        }
        Ok(())
    }

    pub fn emit_settlement(&self, r: &SettlementResult, source: &Path) -> Result<(), Fail> {
        self.emit_scene(Scene::settlement(r), || {
            draw::settlement_report(r, &self.report_options(source))
        })
    }
}

/// Write an SVG and/or its PNG rendering, atomically.
pub fn write_drawing(
    svg: &str,
    svg_path: Option<&Path>,
    png_path: Option<&Path>,
) -> Result<(), Fail> {
    if let Some(p) = svg_path {
        voussoir_io::write_atomic(p, svg.as_bytes())?;
    }
    if let Some(p) = png_path {
        let png = draw::svg_to_png(svg, draw::PNG_ZOOM)?;
        voussoir_io::write_atomic(p, &png)?;
    }
    Ok(())
}
