//! Drawing flags shared by the analysis commands (`--svg`, `--png`, `--report`, `--scale`,
//! `--title`; `--forces` in [`ForcesArgs`], only where the figure is a structure). Flatten
//! [`DrawArgs`] into a command and call one of its `emit_*` methods.

use crate::common::Fail;
use clap::Args;
use std::path::{Path, PathBuf};
use voussoir::analysis::tilt::TiltResult;
use voussoir::analysis::{CapacityResult, IncrementalResult, LimitResult, SettlementResult};
use voussoir_io::draw::{self, DrawOptions, Report, ReportOptions, Scene};

// Figures and reports. The figure is the structure (deformed configuration, hinges, cracks,
// thrust line) for `limit`, `settle` and `tilt`, and the λ curve for `capacity` and
// `incremental`; the report holds every figure.
#[derive(Args, Clone, Debug, Default)]
#[command(next_help_heading = "Drawing")]
pub struct DrawArgs {
    /// Draw the result as SVG: the mechanism for limit, settle and tilt; the λ curve for
    /// capacity and incremental.
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
    /// Draw the same figure as PNG (rendered from the SVG, bundled font).
    #[arg(long, value_name = "FILE")]
    pub png: Option<PathBuf>,
    /// Write a self-contained HTML report (key numbers, tables, every figure).
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Displacement scale factor of the deformed drawing (dimensionless; default: automatic,
    /// shown in the figure). Limit mechanisms are normalised, settlement mechanisms are in m;
    /// for capacity and incremental, the mechanism figures of the report.
    #[arg(long, value_name = "S")]
    pub scale: Option<f64>,
    /// Contact-force arrows: set from [`ForcesArgs`] by the commands whose figure is a structure
    /// (limit, settle, tilt); the curve figures of capacity and incremental have none.
    #[arg(skip)]
    pub forces: bool,
    /// What the report states beyond the result (materials, joint laws, tolerances): set by
    /// the command through [`DrawArgs::with_inputs`].
    #[arg(skip)]
    pub inputs: Option<voussoir_io::report_parts::ReportInputs>,
    /// Title of the drawing (default: by analysis).
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
    /// 3D models: write the result for ParaView: `.vtu` (the blocks, with their displacement
    /// and rotation) or `.vtm` (a multiblock of blocks, contact points, cracked interfaces and
    /// supports, written beside it as FILE_blocks.vtu, …). A directory, or a path ending in
    /// `/`, is refused before the analysis runs.
    #[arg(long, value_name = "FILE")]
    pub vtk: Option<PathBuf>,
    /// 3D models: the view of --svg/--png: `axonometric` (default: elevation 30°, the azimuth
    /// turned to show the largest motions), `plan`, `elevation` (from −y), or `AZ[,EL]` in
    /// degrees: azimuth from the front (−y), counter-clockwise seen from above (−35 looks from
    /// the front left), and elevation above the horizon (default 30, −89 … 89).
    #[arg(long, value_name = "VIEW", value_parser = parse_view, allow_hyphen_values = true)]
    pub view: Option<ViewArg>,
    /// Centres of pressure as dots: set from [`ForcesArgs`] by limit, settle and tilt.
    #[arg(skip)]
    pub pressure_points: Option<PressureArg>,
}

/// The view of a 3D drawing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ViewArg {
    /// Axonometric, turned to show the largest motions (azimuth −35°, elevation 30° when
    /// nothing moves).
    Axonometric,
    /// Seen from above: x right, y up the page.
    Plan,
    /// Seen from the front (−y): x right, z up the page.
    Elevation,
    /// Axonometric from this azimuth and elevation (degrees).
    Angles(f64, f64),
}

impl ViewArg {
    /// The drawing's view.
    pub fn view(self) -> voussoir_io::draw3d::View {
        use voussoir_io::draw3d::View;
        match self {
            ViewArg::Axonometric => View::Auto,
            ViewArg::Plan => View::Plan,
            ViewArg::Elevation => View::Elevation,
            ViewArg::Angles(azimuth, elevation) => View::Axonometric { azimuth, elevation },
        }
    }
}

/// `--view`: axonometric | plan | elevation | AZ[,EL] (degrees, finite; EL in −89 … 89).
pub fn parse_view(s: &str) -> Result<ViewArg, String> {
    let t = s.trim();
    match t.to_ascii_lowercase().as_str() {
        "axonometric" | "auto" => return Ok(ViewArg::Axonometric),
        "plan" => return Ok(ViewArg::Plan),
        "elevation" => return Ok(ViewArg::Elevation),
        _ => {}
    }
    let expected =
        "expected axonometric, plan, elevation or AZ[,EL]: azimuth and elevation in degrees";
    let parts: Vec<&str> = t.split(',').map(str::trim).collect();
    if parts.len() > 2 {
        return Err(format!("{expected} (two numbers at most)"));
    }
    let mut v = [0.0, voussoir_io::draw3d::DEFAULT_ELEVATION];
    for (i, p) in parts.iter().enumerate() {
        let x: f64 = p
            .trim_end_matches('°')
            .parse()
            .map_err(|_| format!("{expected} ('{p}' is not a number)"))?;
        if !x.is_finite() {
            return Err(format!("{expected} ('{p}' is not a finite number)"));
        }
        v[i] = x;
    }
    if !(-89.0..=89.0).contains(&v[1]) {
        return Err(format!(
            "elevation {}°: expected −89 … 89 (`--view plan` looks from straight above)",
            v[1]
        ));
    }
    Ok(ViewArg::Angles(v[0], v[1]))
}

/// Whether the centres of pressure are drawn as dots.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum PressureArg {
    /// Dots along a 2D thrust line (an arch); dots on their own (walls, façades, 3D) only
    /// when there are at most 60.
    Auto,
    /// Every centre of pressure.
    On,
    /// None (a 2D thrust line is still drawn).
    Off,
}

impl PressureArg {
    pub fn points(self) -> voussoir_io::draw::PressurePoints {
        use voussoir_io::draw::PressurePoints;
        match self {
            PressureArg::Auto => PressurePoints::Auto,
            PressureArg::On => PressurePoints::On,
            PressureArg::Off => PressurePoints::Off,
        }
    }
}

// `--forces`: only on the commands whose figure is the structure (limit, settle, tilt).
#[derive(Args, Clone, Debug, Default)]
#[command(next_help_heading = "Drawing")]
pub struct ForcesArgs {
    /// Also draw contact-force resultants as arrows (length ∝ magnitude, kN).
    #[arg(long)]
    pub forces: bool,
    /// Centres of pressure as dots in --svg/--png: auto (default: along a 2D thrust line; dots
    /// on their own — walls, façades, 3D — only when there are at most 60), on or off.
    #[arg(long, value_enum, value_name = "WHEN")]
    pub pressure_points: Option<PressureArg>,
}

impl ForcesArgs {
    /// `--forces` draws on the --svg/--png figure only (a report draws its own figures):
    /// refused without one, before any work (it was accepted and ignored; session 24).
    pub fn check(&self, draw: &DrawArgs) -> Result<(), Fail> {
        if self.forces && draw.svg.is_none() && draw.png.is_none() {
            return Err(Fail(
                "--forces draws arrows on the --svg/--png drawing; give --svg or --png (a report draws its own figures)".into(),
            ));
        }
        Ok(())
    }
}

impl DrawArgs {
    /// These drawing flags with `--forces`.
    pub fn with(&self, f: &ForcesArgs) -> DrawArgs {
        DrawArgs {
            forces: f.forces,
            pressure_points: f.pressure_points,
            ..self.clone()
        }
    }

    /// These flags with the report's inputs, computed only when a report is asked for.
    pub fn with_inputs(
        self,
        f: impl FnOnce() -> voussoir_io::report_parts::ReportInputs,
    ) -> DrawArgs {
        let inputs = self.report.is_some().then(f);
        DrawArgs { inputs, ..self }
    }

    /// Flags that draw 3D results only, refused on a 2D one (before any work).
    pub fn check_2d(&self) -> Result<(), Fail> {
        if self.view.is_some() {
            return Err(Fail(
                "--view applies to 3D models (this model is 2D)".into(),
            ));
        }
        if self.vtk.is_some() {
            return Err(Fail("--vtk applies to 3D models (this model is 2D)".into()));
        }
        Ok(())
    }

    /// Flags of a 3D structure drawing that a capacity result (its figure is the λ(s) curve)
    /// does not take: `--vtk` and `--view`.
    pub fn refuse_3d_curve(&self) -> Result<(), Fail> {
        if self.vtk.is_some() {
            return Err(Fail(
                "--vtk writes the structure of a limit, settle or tilt result; a capacity result is the λ(s) curve (--svg, --png, --report; the settlement mechanism: `settle --vtk`)".into(),
            ));
        }
        if self.view.is_some() {
            return Err(Fail(
                "--view chooses the view of a 3D structure drawing; the capacity figure is the λ(s) curve".into(),
            ));
        }
        Ok(())
    }

    /// The SVG/PNG axonometric drawing and the VTK files of a 3D result.
    pub fn emit_3d(
        &self,
        r: &impl voussoir_io::result3d::Result3d,
        source: &Path,
    ) -> Result<(), Fail> {
        // The 3D drawing shows contact points by state, not force arrows: refused, not ignored.
        if self.forces && (self.svg.is_some() || self.png.is_some()) {
            return Err(Fail(
                "--forces draws contact-force arrows on 2D drawings only; a 3D result's forces are in -o/--json and in --vtk (the contact points' forces)".into(),
            ));
        }
        self.refuse_without_figure()?;
        if let Some(path) = &self.report {
            let title = self.title.clone().unwrap_or_else(|| r.title());
            let html = voussoir_io::report3d::report3d_html_with(
                r,
                &title,
                &source.display().to_string(),
                self.inputs.as_ref(),
            )?;
            crate::outputs::stage(path, html.as_bytes())?;
        }
        if self.svg.is_some() || self.png.is_some() {
            use voussoir_io::draw3d::{draw3d, Draw3dOptions};
            let opts = Draw3dOptions {
                view: self.view.map_or(Default::default(), ViewArg::view),
                pressure_points: self
                    .pressure_points
                    .map_or(Default::default(), PressureArg::points),
                scale: self.scale,
                title: self.title.clone(),
                ..Draw3dOptions::default()
            };
            let d = draw3d(r, &opts)?;
            write_drawing(&d.svg, self.svg.as_deref(), self.png.as_deref())?;
        }
        if let Some(path) = &self.vtk {
            match vtk_kind(path)? {
                VtkKind::Blocks => crate::outputs::stage(path, &voussoir_io::vtk::blocks_vtu(r)?)?,
                VtkKind::Multiblock(name) => {
                    let dir = path.parent().unwrap_or(Path::new(""));
                    for (file, bytes) in voussoir_io::vtk::multiblock(r, &name, true)? {
                        crate::outputs::stage(&dir.join(file), &bytes)?;
                    }
                }
            }
        }
        Ok(())
    }

    /// Whether any drawing output was asked for.
    pub fn any(&self) -> bool {
        self.svg.is_some() || self.png.is_some() || self.report.is_some()
    }

    /// `--view` and `--pressure-points` shape the --svg/--png drawing; a report draws its own
    /// figures (the 3D report's viewer turns): refused without --svg or --png.
    fn refuse_without_figure(&self) -> Result<(), Fail> {
        if self.svg.is_none() && self.png.is_none() {
            for (given, flag) in [
                (self.view.is_some(), "--view"),
                (self.pressure_points.is_some(), "--pressure-points"),
            ] {
                if given {
                    return Err(Fail(format!(
                        "{flag} shapes the --svg/--png drawing; give --svg or --png (a report draws its own figures)"
                    )));
                }
            }
        }
        Ok(())
    }

    /// Check the flags (before any work).
    pub fn check(&self) -> Result<(), Fail> {
        if let Some(s) = self.scale {
            if !(s.is_finite() && s >= 0.0) {
                return Err(Fail(format!("--scale {s}: expected a finite number ≥ 0")));
            }
        }
        // Without a figure or a report they were accepted and ignored (session 24).
        if !self.any() {
            for (given, flag) in [
                (self.scale.is_some(), "--scale"),
                (self.title.is_some(), "--title"),
            ] {
                if given {
                    return Err(Fail(format!(
                        "{flag} shapes the --svg/--png drawing and the --report; give one of them"
                    )));
                }
            }
        }
        if let Some(p) = &self.vtk {
            vtk_kind(p)?;
        }
        check_format("--svg", self.svg.as_deref(), &["svg"])?;
        check_format("--png", self.png.as_deref(), &["png"])?;
        check_format("--report", self.report.as_deref(), &["html", "htm"])?;
        Ok(())
    }

    pub fn options(&self) -> Result<DrawOptions, Fail> {
        self.check()?;
        Ok(DrawOptions {
            scale: self.scale,
            forces: self.forces,
            pressure_points: self
                .pressure_points
                .map_or(Default::default(), PressureArg::points),
            ..DrawOptions::default()
        })
    }

    fn report_options(&self, source: &Path) -> ReportOptions {
        ReportOptions {
            title: self.title.clone(),
            source: source.display().to_string(),
            scale: self.scale,
            inputs: self.inputs.clone(),
        }
    }

    /// Write the SVG/PNG of a scene and the report (built only if asked for).
    pub fn emit_scene(&self, scene: Scene, report: impl FnOnce() -> Report) -> Result<(), Fail> {
        self.refuse_without_figure()?;
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
            crate::outputs::stage(path, report().to_html().as_bytes())?;
        }
        Ok(())
    }

    pub fn emit_limit(&self, r: &LimitResult, source: &Path) -> Result<(), Fail> {
        self.emit_scene(Scene::limit(r), || {
            draw::limit_report(r, &self.report_options(source))
        })
    }

    /// Tilting table: the collapse mechanism at the critical tilt (the live load is the
    /// horizontal λ·W of every block, λ = tan α); the report is the limit analysis' report.
    pub fn emit_tilt(&self, r: &TiltResult, source: &Path) -> Result<(), Fail> {
        self.emit_scene(draw::tilt_scene(r), || {
            draw::tilt_report(r, &self.report_options(source))
        })
    }

    /// Capacity analysis: the figure is the λ–settlement curve; the report adds the settlement
    /// mechanism and the table of steps.
    pub fn emit_capacity<D: draw::capacity::CapacityFigures>(
        &self,
        r: &CapacityResult<D>,
        source: &Path,
    ) -> Result<(), Fail> {
        self.emit_curve(
            draw::CAPACITY_TITLE,
            |title| draw::capacity_plot(&[("λ(s)", r)], title).svg,
            || draw::capacity_report(r, &self.report_options(source)).to_html(),
        )
    }

    /// Incremental analysis: the figure is the λ–control-displacement curve; the report adds
    /// the mechanisms and the events.
    pub fn emit_incremental(&self, r: &IncrementalResult, source: &Path) -> Result<(), Fail> {
        self.emit_curve(
            draw::INCREMENTAL_TITLE,
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
            crate::outputs::stage(path, html().as_bytes())?;
        }
        Ok(())
    }

    pub fn emit_settlement(&self, r: &SettlementResult, source: &Path) -> Result<(), Fail> {
        self.emit_scene(Scene::settlement(r), || {
            draw::settlement_report(r, &self.report_options(source))
        })
    }
}

/// The formats the commands read or write, by file extension, and their names.
const FORMATS: &[(&str, &str)] = &[
    ("svg", "SVG"),
    ("png", "PNG"),
    ("html", "HTML"),
    ("htm", "HTML"),
    ("json", "JSON"),
    ("pdf", "PDF"),
    ("csv", "CSV"),
    ("vtu", "VTK"),
    ("vtm", "VTK"),
    ("dxf", "DXF"),
    ("obj", "OBJ"),
    ("ply", "PLY"),
];

/// `flag PATH` checked before any work: a name ending in the extension of another format than
/// the one the flag writes (`accepted`, the first the usual one) is refused, since the file
/// would not be what its name says (`--report out.pdf` wrote HTML into a .pdf; session 23).
/// Other extensions, or none, are the user's choice.
pub fn check_format(flag: &str, path: Option<&Path>, accepted: &[&str]) -> Result<(), Fail> {
    let Some(path) = path else { return Ok(()) };
    let Some(ext) = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
    else {
        return Ok(());
    };
    if accepted.contains(&ext.as_str()) {
        return Ok(());
    }
    let Some((_, other)) = FORMATS.iter().find(|(e, _)| *e == ext) else {
        return Ok(());
    };
    let writes = FORMATS
        .iter()
        .find(|(e, _)| *e == accepted[0])
        .map_or(accepted[0], |(_, n)| n);
    let hint = if ext == "pdf" && accepted[0] == "html" {
        "; print the HTML report to PDF from a browser (docs/report3d.md)"
    } else {
        ""
    };
    Err(Fail(format!(
        "{flag} {}: {flag} writes {writes}, not {other}; give a name ending in .{}{hint}",
        path.display(),
        accepted[0]
    )))
}

/// What `--vtk PATH` writes.
enum VtkKind {
    /// `.vtu`: the blocks.
    Blocks,
    /// `.vtm` (its file name): the multiblock and its pieces beside it.
    Multiblock(String),
}

/// `--vtk PATH` checked before any work: a file name (not a directory, no trailing slash)
/// ending in .vtu or .vtm.
fn vtk_kind(path: &Path) -> Result<VtkKind, Fail> {
    let shown = path.display();
    let text = path.as_os_str().to_string_lossy();
    let name = path.file_name().and_then(|n| n.to_str());
    // The last component as typed: "out.vtm/", "out/." and ".." name directories.
    let last = text
        .rsplit(['/', std::path::MAIN_SEPARATOR])
        .next()
        .unwrap_or("");
    if matches!(last, "" | "." | "..") || path.is_dir() {
        return Err(Fail(format!(
            "--vtk {shown}: names a directory; give a file, FILE.vtu or FILE.vtm"
        )));
    }
    let Some(name) = name else {
        return Err(Fail(format!(
            "--vtk {shown}: not a file name; give FILE.vtu or FILE.vtm"
        )));
    };
    match path.extension().and_then(|e| e.to_str()) {
        Some("vtu") => Ok(VtkKind::Blocks),
        Some("vtm") => Ok(VtkKind::Multiblock(name.to_string())),
        _ => Err(Fail(format!(
            "--vtk {shown}: the file must end in .vtu (blocks) or .vtm (blocks, contacts, cracks, supports)"
        ))),
    }
}

/// Write an SVG and/or its PNG rendering, atomically.
pub fn write_drawing(
    svg: &str,
    svg_path: Option<&Path>,
    png_path: Option<&Path>,
) -> Result<(), Fail> {
    if let Some(p) = svg_path {
        crate::outputs::stage(p, svg.as_bytes())?;
    }
    if let Some(p) = png_path {
        let png = draw::svg_to_png(svg, draw::PNG_ZOOM)?;
        crate::outputs::stage(p, &png)?;
    }
    Ok(())
}
