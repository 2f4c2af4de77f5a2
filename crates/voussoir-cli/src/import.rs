//! `voussoir import`: a DXF drawing to a JSON model; and the DXF flags every model-reading
//! command accepts, so that a `.dxf` can be analysed directly.

use crate::common::Fail;
use clap::{Args, ValueEnum};
use std::path::{Path, PathBuf};
use voussoir::model3d::AnyModel;
use voussoir::{BuildOptions, Model, Structure};
use voussoir_io::dxf::{read_dxf, DxfOptions, ImportLive, ImportReport, Units};

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnitsArg {
    /// Millimetres.
    #[value(
        alias = "millimetre",
        alias = "millimetres",
        alias = "millimeter",
        alias = "millimeters"
    )]
    Mm,
    /// Centimetres.
    #[value(
        alias = "centimetre",
        alias = "centimetres",
        alias = "centimeter",
        alias = "centimeters"
    )]
    Cm,
    /// Metres.
    #[value(alias = "metre", alias = "metres", alias = "meter", alias = "meters")]
    M,
}

#[derive(ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DxfLiveArg {
    /// No live load.
    None,
    /// Tilting table: a horizontal force (+x) equal to each block's weight.
    #[default]
    #[value(alias = "tilt")]
    Horizontal,
}

// How to read a `.dxf` model. Refused with a JSON model (a JSON model carries its own units,
// weights and supports).
#[derive(Args, Clone, Debug, Default)]
#[command(next_help_heading = "DXF import")]
pub struct DxfArgs {
    /// Drawing units (default: the drawing's $INSUNITS, which must then be mm, cm or m).
    #[arg(long, value_enum, ignore_case = true)]
    pub units: Option<UnitsArg>,
    /// Unit weight γ of the blocks in kN/m³ [default: 18].
    #[arg(long, value_name = "KN_M3")]
    pub unit_weight: Option<f64>,
    /// Out-of-plane width of the blocks in m [default: 1].
    #[arg(long, value_name = "M")]
    pub dxf_width: Option<f64>,
    /// Polygons on this layer are supports (repeatable). Default: the lowest, widest polygon
    /// is the one support `base`.
    #[arg(long = "support-layer", value_name = "LAYER")]
    pub support_layers: Vec<String>,
    /// The polygon with this handle (hex) is a support (repeatable).
    #[arg(long = "support-handle", value_name = "HANDLE")]
    pub support_handles: Vec<String>,
    /// Vertices closer than this are merged, in m (default: 1e-6 of the drawing's size).
    #[arg(long, value_name = "M")]
    pub merge_tolerance: Option<f64>,
    /// Live load added to the model (drawings carry none) [default: horizontal].
    #[arg(long = "dxf-live", value_enum, ignore_case = true)]
    pub live: Option<DxfLiveArg>,
}

impl DxfArgs {
    pub fn options(&self) -> DxfOptions {
        let d = DxfOptions::default();
        DxfOptions {
            units: self.units.map(|u| match u {
                UnitsArg::Mm => Units::Mm,
                UnitsArg::Cm => Units::Cm,
                UnitsArg::M => Units::M,
            }),
            unit_weight: self.unit_weight.unwrap_or(d.unit_weight),
            width: self.dxf_width.unwrap_or(d.width),
            support_layers: self.support_layers.clone(),
            support_handles: self.support_handles.clone(),
            merge_tolerance: self.merge_tolerance,
            live: match self.live.unwrap_or_default() {
                DxfLiveArg::None => ImportLive::None,
                DxfLiveArg::Horizontal => ImportLive::Horizontal,
            },
        }
    }

    /// The first DXF flag given on the command line, if any (to refuse it for a JSON model).
    pub fn given(&self) -> Option<&'static str> {
        [
            (self.units.is_some(), "--units"),
            (self.unit_weight.is_some(), "--unit-weight"),
            (self.dxf_width.is_some(), "--dxf-width"),
            (!self.support_layers.is_empty(), "--support-layer"),
            (!self.support_handles.is_empty(), "--support-handle"),
            (self.merge_tolerance.is_some(), "--merge-tolerance"),
            (self.live.is_some(), "--dxf-live"),
        ]
        .into_iter()
        .find(|(given, _)| *given)
        .map(|(_, flag)| flag)
    }

    /// Check the numbers.
    pub fn check(&self) -> Result<(), Fail> {
        for (flag, v) in [
            ("--unit-weight", self.unit_weight),
            ("--dxf-width", self.dxf_width),
            ("--merge-tolerance", self.merge_tolerance),
        ] {
            if let Some(x) = v {
                if !(x.is_finite() && x > 0.0) {
                    return Err(Fail(format!("{flag} {x}: must be a finite number > 0")));
                }
            }
        }
        Ok(())
    }

    /// Read `path` as a 2D model: DXF by extension, JSON otherwise. The report is there for
    /// DXF. A 3D model is refused with a line that says where 3D models go.
    pub fn read(&self, path: &Path) -> Result<(Model, Option<ImportReport>), Fail> {
        match self.read_any(path)? {
            (AnyModel::Planar(m), rep) => Ok((m, rep)),
            (AnyModel::Spatial(_), _) => Err(Fail(format!(
                "{} is a 3D model: this command analyses 2D models only (3D models go to limit, settle, capacity and tilt)",
                path.display()
            ))),
        }
    }

    /// Read `path` as a model of either dimension: DXF (2D) by extension, JSON otherwise.
    pub fn read_any(&self, path: &Path) -> Result<(AnyModel, Option<ImportReport>), Fail> {
        crate::outputs::input(path);
        if voussoir_io::dxf::is_dxf(path) {
            let (m, rep) = read_dxf(path, &self.options())?;
            Ok((AnyModel::Planar(m), Some(rep)))
        } else {
            Ok((voussoir_io::read_any_model(path)?, None))
        }
    }
}

/// Build a structure, naming the DXF entity of any block an error mentions.
pub fn structure_of(
    model: &Model,
    opts: BuildOptions,
    report: Option<&ImportReport>,
) -> Result<Structure, Fail> {
    Structure::new(model, opts).map_err(|e| {
        let msg = e.to_string();
        Fail(report.map_or(msg.clone(), |r| r.annotate(&msg)))
    })
}

#[derive(Args)]
pub struct ImportArgs {
    /// The drawing: closed LWPOLYLINE/POLYLINE entities are the blocks.
    pub drawing: PathBuf,
    #[command(flatten)]
    pub dxf: DxfArgs,
    /// Geometric tolerance of the validation run after import, relative to the drawing's size
    /// (dimensionless; default 1e-7).
    #[arg(long, value_name = "REL")]
    pub tolerance: Option<f64>,
    /// Where to write the model JSON (stdout if absent).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<PathBuf>,
}

pub fn run(a: ImportArgs) -> Result<(), Fail> {
    a.dxf.check()?;
    let (model, rep) = read_dxf(&a.drawing, &a.dxf.options())?;
    // Validate now (overlaps, isolated blocks), so that a bad drawing fails at import.
    let st = structure_of(
        &model,
        BuildOptions {
            tolerance: a.tolerance,
        },
        Some(&rep),
    )?;
    let json = voussoir_io::files::to_json(&model)?;
    match &a.output {
        Some(p) => crate::outputs::stage(p, json.as_bytes())?,
        None => print!("{json}"),
    }
    eprintln!("{}; {} joints", rep.summary(), st.joints.len());
    for n in &rep.notes {
        eprintln!("note: {n}");
    }
    Ok(())
}
