//! `voussoir plot FILE -o fig.svg|fig.png|report.html`: draw a saved limit or settlement result
//! (or a model with its loads), recognised by its fields.

use crate::common::Fail;
use crate::draw_args::write_drawing;
use clap::Args;
use std::path::PathBuf;
use voussoir_io::draw::{self, DrawOptions, ReportOptions};

#[derive(Args, Clone, Debug)]
pub struct PlotArgs {
    /// A saved result (`limit … -o r.json`, `settle … -o r.json`) or a model JSON.
    pub input: PathBuf,
    /// Output file; the format follows the extension: .svg, .png or .html (report).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: PathBuf,
    /// Displacement scale factor (default: automatic, shown in the figure).
    #[arg(long, value_name = "S")]
    pub scale: Option<f64>,
    /// Draw contact-force resultants as arrows.
    #[arg(long)]
    pub forces: bool,
    /// Draw the undeformed configuration only (the thrust line and forces stay).
    #[arg(long)]
    pub undeformed: bool,
    /// Draw the dead loads (self-weight) as arrows too.
    #[arg(long)]
    pub dead_loads: bool,
    /// Title of the drawing.
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
    /// Width of the figure in pixels (PNG: × 1.5).
    #[arg(long, default_value_t = 1000.0, value_name = "PX")]
    pub width: f64,
}

pub fn run(a: PlotArgs) -> Result<(), Fail> {
    let text = std::fs::read_to_string(&a.input)
        .map_err(|e| Fail(format!("cannot read {}: {e}", a.input.display())))?;
    let saved =
        draw::parse_saved(&text).map_err(|e| Fail(format!("{}: {}", a.input.display(), e.0)))?;
    if let Some(s) = a.scale {
        if !(s.is_finite() && s >= 0.0) {
            return Err(Fail(format!("--scale {s}: expected a finite number ≥ 0")));
        }
    }
    if !(a.width.is_finite() && (200.0..=20000.0).contains(&a.width)) {
        return Err(Fail(format!(
            "--width {}: expected 200 … 20000 pixels",
            a.width
        )));
    }
    let ext = a
        .output
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    match ext.as_str() {
        "svg" | "png" => {
            let opts = DrawOptions {
                scale: a.scale,
                forces: a.forces,
                deformed: !a.undeformed,
                dead_loads: a.dead_loads,
                width: a.width,
                ..DrawOptions::default()
            };
            let d = draw::draw_saved(&saved, &opts, a.title.as_deref());
            if ext == "svg" {
                write_drawing(&d.svg, Some(&a.output), None)?;
            } else {
                write_drawing(&d.svg, None, Some(&a.output))?;
            }
            println!(
                "drew {} {} → {}{}",
                saved.kind(),
                a.input.display(),
                a.output.display(),
                d.scale
                    .map(|s| format!(" (displacements × {s})"))
                    .unwrap_or_default()
            );
        }
        "html" | "htm" => {
            let opts = ReportOptions {
                title: a.title.clone(),
                source: a.input.display().to_string(),
                scale: a.scale,
            };
            let html = draw::report_saved(&saved, &opts).to_html();
            voussoir_io::write_atomic(&a.output, html.as_bytes())?;
            println!(
                "wrote report of {} {} → {}",
                saved.kind(),
                a.input.display(),
                a.output.display()
            );
        }
        _ => {
            return Err(Fail(format!(
                "-o {}: the output format follows the extension: .svg, .png or .html",
                a.output.display()
            )))
        }
    }
    Ok(())
}
