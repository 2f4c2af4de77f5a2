//! `voussoir plot FILE… -o fig.svg|fig.png|report.html`: draw a saved limit, settlement,
//! capacity or incremental result (or a model with its loads), recognised by its fields; several
//! capacity or incremental results are drawn as curves on one plot (the paper's Fig 17).

use crate::common::Fail;
use crate::draw_args::write_drawing;
use clap::Args;
use std::path::PathBuf;
use voussoir_io::draw::{self, DrawOptions, ReportOptions};

#[derive(Args, Clone, Debug)]
pub struct PlotArgs {
    /// A saved result (`limit … -o r.json`, `settle`, `capacity`, `incremental`) or a model
    /// JSON. Several capacity or incremental results: their curves on one plot.
    #[arg(required = true, num_args = 1..)]
    pub input: Vec<PathBuf>,
    /// Legend label of each curve when several results are plotted (repeatable, in order).
    #[arg(long = "label", value_name = "TEXT")]
    pub labels: Vec<String>,
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

fn read(path: &std::path::Path) -> Result<draw::Saved, Fail> {
    crate::outputs::input(path);
    let text = std::fs::read_to_string(path)
        .map_err(|e| Fail(format!("cannot read {}: {e}", path.display())))?;
    draw::parse_saved(&text).map_err(|e| Fail(format!("{}: {}", path.display(), e.0)))
}

/// Several capacity or incremental results: one plot with a curve each.
fn run_many(a: &PlotArgs) -> Result<(), Fail> {
    let saved: Vec<draw::Saved> = a.input.iter().map(|p| read(p)).collect::<Result<_, _>>()?;
    if !a.labels.is_empty() && a.labels.len() != a.input.len() {
        return Err(Fail(format!(
            "--label given {} times for {} inputs",
            a.labels.len(),
            a.input.len()
        )));
    }
    let labels: Vec<String> = (0..saved.len())
        .map(|i| {
            a.labels.get(i).cloned().unwrap_or_else(|| {
                a.input[i]
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default()
            })
        })
        .collect();
    let svg = if saved.iter().all(|s| matches!(s, draw::Saved::Capacity(_))) {
        let curves: Vec<(&str, &voussoir::analysis::CapacityResult)> = saved
            .iter()
            .zip(&labels)
            .filter_map(|(s, l)| match s {
                draw::Saved::Capacity(r) => Some((l.as_str(), r.as_ref())),
                _ => None,
            })
            .collect();
        let t = a
            .title
            .as_deref()
            .unwrap_or("Collapse load multiplier after settlement");
        draw::capacity_plot(&curves, t).svg
    } else if saved
        .iter()
        .all(|s| matches!(s, draw::Saved::Incremental(_)))
    {
        let curves: Vec<(&str, &voussoir::analysis::IncrementalResult)> = saved
            .iter()
            .zip(&labels)
            .filter_map(|(s, l)| match s {
                draw::Saved::Incremental(r) => Some((l.as_str(), r.as_ref())),
                _ => None,
            })
            .collect();
        let t = a
            .title
            .as_deref()
            .unwrap_or("Load multiplier against control displacement");
        draw::incremental_plot(&curves, t).svg
    } else {
        let kinds: Vec<&str> = saved.iter().map(|s| s.kind()).collect();
        return Err(Fail(format!(
            "several inputs must all be capacity or all incremental results (got {})",
            kinds.join(", ")
        )));
    };
    match ext_of(&a.output).as_str() {
        "svg" => write_drawing(&svg, Some(&a.output), None)?,
        "png" => write_drawing(&svg, None, Some(&a.output))?,
        _ => {
            return Err(Fail(format!(
                "-o {}: several results are drawn as one plot: .svg or .png",
                a.output.display()
            )))
        }
    }
    println!("drew {} curves → {}", saved.len(), a.output.display());
    Ok(())
}

fn ext_of(p: &std::path::Path) -> String {
    p.extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase()
}

pub fn run(a: PlotArgs) -> Result<(), Fail> {
    if a.input.len() > 1 {
        return run_many(&a);
    }
    let input = &a.input[0];
    let saved = read(input)?;
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
    let ext = ext_of(&a.output);
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
                input.display(),
                a.output.display(),
                d.scale
                    .map(|s| format!(" (displacements × {s})"))
                    .unwrap_or_default()
            );
        }
        "html" | "htm" => {
            let opts = ReportOptions {
                title: a.title.clone(),
                source: input.display().to_string(),
                scale: a.scale,
            };
            let html = draw::report_saved(&saved, &opts).to_html();
            crate::outputs::stage(&a.output, html.as_bytes())?;
            println!(
                "wrote report of {} {} → {}",
                saved.kind(),
                input.display(),
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
