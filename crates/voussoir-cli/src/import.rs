//! `voussoir import`: a DXF drawing to a JSON model; and the DXF flags every model-reading
//! command accepts, so that a `.dxf` can be analysed directly.

use crate::common::Fail;
use clap::{Args, ValueEnum};
use std::path::{Path, PathBuf};
use voussoir::{BuildOptions, Model, Structure};
use voussoir_io::dxf::{read_dxf, DxfOptions, ImportLive, ImportReport, Units};

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum UnitsArg {
    Mm,
    Cm,
    M,
}

#[derive(ValueEnum, Clone, Copy, Debug, Default)]
pub enum DxfLiveArg {
    /// No live load.
    None,
    /// Tilting table: a horizontal force (+x) equal to each block's weight.
    #[default]
    Horizontal,
}

/// How to read a `.dxf` model (ignored for JSON models).
#[derive(Args, Clone, Debug, Default)]
pub struct DxfArgs {
    /// DXF: drawing units (default: the drawing's $INSUNITS, which must then be mm, cm or m).
    #[arg(long, value_enum)]
    pub units: Option<UnitsArg>,
    /// DXF: unit weight γ of the blocks in kN/m³.
    #[arg(long, default_value_t = 18.0)]
    pub unit_weight: f64,
    /// DXF: out-of-plane width of the blocks in m.
    #[arg(long, default_value_t = 1.0)]
    pub dxf_width: f64,
    /// DXF: polygons on this layer are supports (repeatable). Default: the lowest, widest
    /// polygon is the one support `base`.
    #[arg(long = "support-layer", value_name = "LAYER")]
    pub support_layers: Vec<String>,
    /// DXF: the polygon with this handle (hex) is a support (repeatable).
    #[arg(long = "support-handle", value_name = "HANDLE")]
    pub support_handles: Vec<String>,
    /// DXF: vertices closer than this (m) are merged (default: 1e-6 of the drawing's size).
    #[arg(long)]
    pub merge_tolerance: Option<f64>,
    /// DXF: live load added to the model (drawings carry none).
    #[arg(long = "dxf-live", value_enum, default_value = "horizontal")]
    pub live: DxfLiveArg,
}

impl DxfArgs {
    pub fn options(&self) -> DxfOptions {
        DxfOptions {
            units: self.units.map(|u| match u {
                UnitsArg::Mm => Units::Mm,
                UnitsArg::Cm => Units::Cm,
                UnitsArg::M => Units::M,
            }),
            unit_weight: self.unit_weight,
            width: self.dxf_width,
            support_layers: self.support_layers.clone(),
            support_handles: self.support_handles.clone(),
            merge_tolerance: self.merge_tolerance,
            live: match self.live {
                DxfLiveArg::None => ImportLive::None,
                DxfLiveArg::Horizontal => ImportLive::Horizontal,
            },
        }
    }

    /// Read `path` as a model: DXF by extension, JSON otherwise. The report is there for DXF.
    pub fn read(&self, path: &Path) -> Result<(Model, Option<ImportReport>), Fail> {
        if voussoir_io::dxf::is_dxf(path) {
            let (m, rep) = read_dxf(path, &self.options())?;
            Ok((m, Some(rep)))
        } else {
            Ok((voussoir_io::read_model(path)?, None))
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
    /// Relative geometric tolerance for the validation run after import (default 1e-7).
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// Where to write the model JSON (stdout if absent).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<PathBuf>,
}

pub fn run(a: ImportArgs) -> Result<(), Fail> {
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
        Some(p) => voussoir_io::write_atomic(p, json.as_bytes())?,
        None => print!("{json}"),
    }
    eprintln!("{}; {} joints", rep.summary(), st.joints.len());
    for n in &rep.notes {
        eprintln!("note: {n}");
    }
    Ok(())
}
