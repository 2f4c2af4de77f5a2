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
    /// 3D models: the view of --svg/--png: axonometric (default), plan or elevation (from −y).
    #[arg(long, value_enum, value_name = "VIEW")]
    pub view: Option<ViewArg>,
}

/// The view of a 3D drawing.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewArg {
    /// Seen from azimuth −35°, elevation 30° (front left, above).
    Axonometric,
    /// Seen from above: x right, y up the page.
    Plan,
    /// Seen from the front (−y): x right, z up the page.
    Elevation,
}

// `--forces`: only on the commands whose figure is the structure (limit, settle, tilt).
#[derive(Args, Clone, Debug, Default)]
#[command(next_help_heading = "Drawing")]
pub struct ForcesArgs {
    /// Also draw contact-force resultants as arrows (length ∝ magnitude, kN).
    #[arg(long)]
    pub forces: bool,
}

impl DrawArgs {
    /// These drawing flags with `--forces`.
    pub fn with(&self, f: &ForcesArgs) -> DrawArgs {
        DrawArgs {
            forces: f.forces,
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
        if self.vtk.is_some() || self.view.is_some() {
            return Err(Fail(
                "--vtk and --view apply to 3D models (this model is 2D)".into(),
            ));
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
            use voussoir_io::draw3d::{draw3d, Draw3dOptions, View};
            let view = match self.view {
                None | Some(ViewArg::Axonometric) => View::default(),
                Some(ViewArg::Plan) => View::Plan,
                Some(ViewArg::Elevation) => View::Elevation,
            };
            let opts = Draw3dOptions {
                view,
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

    /// Check the flags (before any work).
    pub fn check(&self) -> Result<(), Fail> {
        if let Some(s) = self.scale {
            if !(s.is_finite() && s >= 0.0) {
                return Err(Fail(format!("--scale {s}: expected a finite number ≥ 0")));
            }
        }
        if let Some(p) = &self.vtk {
            vtk_kind(p)?;
        }
        Ok(())
    }

    pub fn options(&self) -> Result<DrawOptions, Fail> {
        self.check()?;
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
            inputs: self.inputs.clone(),
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
