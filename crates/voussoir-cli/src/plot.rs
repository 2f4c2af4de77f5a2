//! `voussoir plot FILE… -o fig.svg|fig.png|report.html`: draw what an analysis wrote with `-o`
//! — a limit, settlement, capacity, tilt, incremental, identify or safety result — or a model,
//! in 2D or 3D (the dimension is read from the file). Several capacity or incremental results
//! are drawn as curves on one plot (the paper's Fig 17).

use crate::common::Fail;
use crate::draw_args::{parse_view, write_drawing, PressureArg, ViewArg};
use clap::Args;
use std::path::PathBuf;
use voussoir_io::draw::capacity::CapacityCurve;
use voussoir_io::draw::{self, DrawOptions, ReportOptions, Saved};

#[derive(Args, Clone, Debug)]
pub struct PlotArgs {
    /// A saved result (`-o r.json` of limit, settle, capacity, tilt, incremental, identify or
    /// safety) or a model JSON, 2D or 3D. Several capacity or incremental results: their curves
    /// on one plot.
    #[arg(required = true, num_args = 1..)]
    pub input: Vec<PathBuf>,
    /// Legend label of each curve (capacity, incremental; repeatable, in the order of the
    /// inputs).
    #[arg(long = "label", value_name = "TEXT")]
    pub labels: Vec<String>,
    /// Output file; the format follows the extension: .svg, .png or .html (report).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: PathBuf,
    /// Displacement scale factor of a structure drawing, or of the mechanism figures of a
    /// report (default: automatic, shown in the figure).
    #[arg(long, value_name = "S")]
    pub scale: Option<f64>,
    /// Draw contact-force resultants as arrows (2D structure drawings).
    #[arg(long)]
    pub forces: bool,
    /// Draw the undeformed configuration only (the thrust line and forces stay).
    #[arg(long)]
    pub undeformed: bool,
    /// Draw the dead loads (self-weight) as arrows too.
    #[arg(long)]
    pub dead_loads: bool,
    /// 3D structures: the view of the .svg/.png drawing: `axonometric` (default: elevation 30°,
    /// the azimuth turned to show the largest motions), `plan`, `elevation` (from −y), or
    /// `AZ[,EL]` in degrees (azimuth from the front −y, counter-clockwise seen from above;
    /// elevation −89 … 89, default 30).
    #[arg(long, value_name = "VIEW", value_parser = parse_view, allow_hyphen_values = true)]
    pub view: Option<ViewArg>,
    /// Centres of pressure as dots on a structure drawing: auto (default: along a 2D thrust
    /// line; dots on their own — walls, façades, 3D — only when there are at most 60), on or off.
    #[arg(long, value_enum, value_name = "WHEN")]
    pub pressure_points: Option<PressureArg>,
    /// Title of the drawing (of the report with .html).
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
    /// Width of the .svg/.png figure in pixels (PNG: × 1.5) [default: 1000 for a structure;
    /// 820 for a curve or chart].
    #[arg(long, value_name = "PX")]
    pub width: Option<f64>,
}

fn read(path: &std::path::Path) -> Result<Saved, Fail> {
    crate::outputs::input(path);
    let text = std::fs::read_to_string(path)
        .map_err(|e| Fail(format!("cannot read {}: {e}", path.display())))?;
    draw::parse_saved(&text).map_err(|e| Fail(format!("{}: {}", path.display(), e.0)))
}

fn ext_of(p: &std::path::Path) -> String {
    p.extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase()
}

/// The flags given that shape a structure drawing, by name.
fn structure_flags(a: &PlotArgs) -> Vec<&'static str> {
    let mut v = Vec::new();
    if a.scale.is_some() {
        v.push("--scale");
    }
    if a.forces {
        v.push("--forces");
    }
    if a.undeformed {
        v.push("--undeformed");
    }
    if a.dead_loads {
        v.push("--dead-loads");
    }
    if a.view.is_some() {
        v.push("--view");
    }
    if a.pressure_points.is_some() {
        v.push("--pressure-points");
    }
    v
}

/// A figure of `width` pixels: the SVG's size attributes scaled (its viewBox kept), so that a
/// curve or chart drawn at its own size is shown at the width asked for.
fn resized(svg: &str, width: Option<f64>) -> String {
    let Some(w) = width else {
        return svg.to_string();
    };
    let attr = |name: &str| -> Option<(usize, usize, f64)> {
        let key = format!(" {name}=\"");
        let head_end = svg.find('>')?;
        let i = svg[..head_end].find(&key)? + key.len();
        let j = i + svg[i..].find('"')?;
        Some((i, j, svg[i..j].parse().ok()?))
    };
    let (Some((wi, wj, w0)), Some((hi, hj, h0))) = (attr("width"), attr("height")) else {
        return svg.to_string();
    };
    if !(w0 > 0.0 && wi < hi) {
        return svg.to_string();
    }
    let h = h0 * w / w0;
    format!(
        "{}{}{}{}{}",
        &svg[..wi],
        voussoir_io::draw::svg::num(w),
        &svg[wj..hi],
        voussoir_io::draw::svg::num(h),
        &svg[hj..]
    )
}

/// Several capacity or incremental results: one plot with a curve each.
fn run_many(a: &PlotArgs) -> Result<(), Fail> {
    let saved: Vec<Saved> = a.input.iter().map(|p| read(p)).collect::<Result<_, _>>()?;
    if !a.labels.is_empty() && a.labels.len() != a.input.len() {
        return Err(Fail(format!(
            "--label given {} times for {} inputs",
            a.labels.len(),
            a.input.len()
        )));
    }
    if let Some(f) = structure_flags(a).first() {
        return Err(Fail(format!(
            "{f} shapes a structure drawing; several results are drawn as curves on one plot"
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
    let is_capacity = |s: &Saved| matches!(s, Saved::Capacity(_) | Saved::Capacity3d(_));
    let svg = if saved.iter().all(is_capacity) {
        let n = saved.len();
        let curves: Vec<CapacityCurve> = saved
            .iter()
            .zip(&labels)
            .enumerate()
            .filter_map(|(i, (s, l))| match s {
                Saved::Capacity(r) => Some(CapacityCurve::of(r.as_ref(), l, i, n)),
                Saved::Capacity3d(r) => Some(CapacityCurve::of(r.as_ref(), l, i, n)),
                _ => None,
            })
            .collect();
        if let Some(k) = curves.iter().position(|c| c.unit != curves[0].unit) {
            let says = |c: &CapacityCurve| format!("{} ({})", c.unit.noun(), c.unit.shown());
            return Err(Fail(format!(
                "{} is driven by a {} and {} by a {}: their curves do not share an axis",
                a.input[0].display(),
                says(&curves[0]),
                a.input[k].display(),
                says(&curves[k])
            )));
        }
        let t = a.title.as_deref().unwrap_or(draw::CAPACITY_TITLE);
        draw::capacity::capacity_curves_plot(&curves, t).svg
    } else if saved.iter().all(|s| matches!(s, Saved::Incremental(_))) {
        let curves: Vec<(&str, &voussoir::analysis::IncrementalResult)> = saved
            .iter()
            .zip(&labels)
            .filter_map(|(s, l)| match s {
                Saved::Incremental(r) => Some((l.as_str(), r.as_ref())),
                _ => None,
            })
            .collect();
        let t = a.title.as_deref().unwrap_or(draw::INCREMENTAL_TITLE);
        draw::incremental_plot(&curves, t).svg
    } else if saved.iter().all(|s| matches!(s, Saved::Incremental3d(_))) {
        let curves: Vec<(
            &str,
            &voussoir::analysis::IncrementalResult<voussoir::dim::Three>,
        )> = saved
            .iter()
            .zip(&labels)
            .filter_map(|(s, l)| match s {
                Saved::Incremental3d(r) => Some((l.as_str(), r.as_ref())),
                _ => None,
            })
            .collect();
        let t = a.title.as_deref().unwrap_or(draw::INCREMENTAL_TITLE);
        draw::incremental_plot(&curves, t).svg
    } else {
        let kinds: Vec<&str> = saved.iter().map(|s| s.kind()).collect();
        return Err(Fail(format!(
            "several inputs must all be capacity or all incremental results (got {})",
            kinds.join(", ")
        )));
    };
    let svg = resized(&svg, a.width);
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

/// Refuse, in one line, a flag that does not apply to this file and output.
fn check_flags(a: &PlotArgs, saved: &Saved, report: bool) -> Result<(), Fail> {
    let kind = saved.kind();
    if !a.labels.is_empty()
        && !matches!(
            saved,
            Saved::Capacity(_)
                | Saved::Capacity3d(_)
                | Saved::Incremental(_)
                | Saved::Incremental3d(_)
        )
    {
        return Err(Fail(format!(
            "--label names a curve of a capacity or incremental result; a {kind} has none"
        )));
    }
    if report {
        let shaping: Vec<&str> = [
            (a.forces, "--forces"),
            (a.undeformed, "--undeformed"),
            (a.dead_loads, "--dead-loads"),
            (a.view.is_some(), "--view"),
            (a.pressure_points.is_some(), "--pressure-points"),
            (a.width.is_some(), "--width"),
            (!a.labels.is_empty(), "--label"),
        ]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, f)| *f)
        .collect();
        if let Some(f) = shaping.first() {
            return Err(Fail(format!(
                "{f} shapes the .svg/.png drawing; a report (.html) draws its own figures"
            )));
        }
        let scaled = matches!(
            saved,
            Saved::Limit(_)
                | Saved::Settlement(_)
                | Saved::Tilt(_)
                | Saved::Identify(_)
                | Saved::Capacity(_)
                | Saved::Capacity3d(_)
                | Saved::Incremental(_)
        );
        if a.scale.is_some() && !scaled {
            return Err(Fail(format!(
                "--scale: the report of a {kind} has no displacement scale to set{}",
                if saved.is_3d() {
                    " (its 3D viewer has a slider)"
                } else {
                    ""
                }
            )));
        }
        return Ok(());
    }
    if saved.is_chart() {
        if let Some(f) = structure_flags(a).first() {
            let figure = match saved {
                Saved::Safety(_) => "its chart of reaction ranges",
                Saved::Incremental(_) | Saved::Incremental3d(_) => "its λ(dx) curve",
                _ => "its λ(s) curve",
            };
            return Err(Fail(format!(
                "{f} shapes a structure drawing; a {kind} is drawn as {figure}"
            )));
        }
        return Ok(());
    }
    if matches!(saved, Saved::Model(_) | Saved::Model3d(_)) && (a.scale.is_some() || a.undeformed) {
        return Err(Fail(format!(
            "{}: a model has no displacements to draw",
            if a.scale.is_some() {
                "--scale"
            } else {
                "--undeformed"
            }
        )));
    }
    if saved.is_3d() {
        if a.forces {
            return Err(Fail(
                "--forces: the 3D drawing shows the centres of pressure, not force arrows (the 3D report's viewer and --vtk carry the forces)".into(),
            ));
        }
    } else if a.view.is_some() {
        return Err(Fail(format!(
            "--view applies to 3D models (this {kind} is 2D)"
        )));
    }
    Ok(())
}

pub fn run(a: PlotArgs) -> Result<(), Fail> {
    if let Some(s) = a.scale {
        if !(s.is_finite() && s >= 0.0) {
            return Err(Fail(format!("--scale {s}: expected a finite number ≥ 0")));
        }
    }
    if let Some(w) = a.width {
        if !(w.is_finite() && (200.0..=20000.0).contains(&w)) {
            return Err(Fail(format!("--width {w}: expected 200 … 20000 pixels")));
        }
    }
    if a.input.len() > 1 {
        return run_many(&a);
    }
    let input = &a.input[0];
    let ext = ext_of(&a.output);
    if !matches!(ext.as_str(), "svg" | "png" | "html" | "htm") {
        return Err(Fail(format!(
            "-o {}: the output format follows the extension: .svg, .png or .html",
            a.output.display()
        )));
    }
    let saved = read(input)?;
    let report = matches!(ext.as_str(), "html" | "htm");
    check_flags(&a, &saved, report)?;
    if report {
        let opts = ReportOptions {
            title: a.title.clone(),
            source: input.display().to_string(),
            scale: a.scale,
            inputs: None,
        };
        let html = draw::report_saved(&saved, &opts)?;
        crate::outputs::stage(&a.output, html.as_bytes())?;
        println!(
            "wrote report of {} {} → {}",
            saved.kind(),
            input.display(),
            a.output.display()
        );
        return Ok(());
    }
    let label = a.labels.first().map(String::as_str);
    let (svg, scale) = match (&saved, label) {
        // A single curve with its legend label.
        (Saved::Capacity(r), Some(l)) => (
            draw::capacity_plot(
                &[(l, r.as_ref())],
                a.title.as_deref().unwrap_or(draw::CAPACITY_TITLE),
            )
            .svg,
            None,
        ),
        (Saved::Capacity3d(r), Some(l)) => (
            draw::capacity_plot(
                &[(l, r.as_ref())],
                a.title.as_deref().unwrap_or(draw::CAPACITY_TITLE),
            )
            .svg,
            None,
        ),
        (Saved::Incremental(r), Some(l)) => (
            draw::incremental_plot(
                &[(l, r.as_ref())],
                a.title.as_deref().unwrap_or(draw::INCREMENTAL_TITLE),
            )
            .svg,
            None,
        ),
        (Saved::Incremental3d(r), Some(l)) => (
            draw::incremental_plot(
                &[(l, r.as_ref())],
                a.title.as_deref().unwrap_or(draw::INCREMENTAL_TITLE),
            )
            .svg,
            None,
        ),
        _ => {
            let opts = DrawOptions {
                scale: a.scale,
                forces: a.forces,
                deformed: !a.undeformed,
                dead_loads: a.dead_loads,
                pressure_points: a
                    .pressure_points
                    .map_or(Default::default(), PressureArg::points),
                width: a.width.unwrap_or(1000.0),
                ..DrawOptions::default()
            };
            let view = a.view.map_or(Default::default(), ViewArg::view);
            let d = draw::draw_saved_view(&saved, &opts, view, a.title.as_deref())?;
            (d.svg, d.scale)
        }
    };
    let svg = if saved.is_chart() {
        resized(&svg, a.width)
    } else {
        svg
    };
    if ext == "svg" {
        write_drawing(&svg, Some(&a.output), None)?;
    } else {
        write_drawing(&svg, None, Some(&a.output))?;
    }
    println!(
        "drew {} {} → {}{}",
        saved.kind(),
        input.display(),
        a.output.display(),
        scale
            .map(|s| format!(" (displacements × {s})"))
            .unwrap_or_default()
    );
    Ok(())
}
