//! `voussoir import`: a DXF drawing (2D) or an OBJ/PLY mesh (3D) to a JSON model; `voussoir
//! export`: a 3D model to OBJ; and the DXF and OBJ/PLY flags every model-reading command
//! accepts, so that a `.dxf`, `.obj` or `.ply` can be analysed directly.

use crate::common::Fail;
use clap::{Args, ValueEnum};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use voussoir::model3d::AnyModel;
use voussoir::{BuildOptions, Model, Structure, Structure3d};
use voussoir_io::dxf::{read_dxf, DxfOptions, ImportLive, ImportReport, Units};
use voussoir_io::mesh::{is_mesh, read_mesh, MeshOptions, MeshReport};

/// The analyses' default geometric tolerance, relative to the bounding-box diagonal (the
/// default weld of `voussoir import`).
const DEFAULT_REL_TOLERANCE: f64 = 1e-7;

/// The drawing unit of a `--units`-like flag.
pub fn units(u: UnitsArg) -> Units {
    match u {
        UnitsArg::Mm => Units::Mm,
        UnitsArg::Cm => Units::Cm,
        UnitsArg::M => Units::M,
    }
}

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

// How to read a `.dxf` model (and, flattened in, a `.obj`/`.ply` one). Refused with a JSON
// model (a JSON model carries its own units, weights and supports).
#[derive(Args, Clone, Debug, Default)]
#[command(next_help_heading = "DXF import")]
pub struct DxfArgs {
    /// Units of the drawing or mesh (DXF default: the drawing's $INSUNITS, which must then be
    /// mm, cm or m; OBJ/PLY default: m).
    #[arg(long, value_enum, ignore_case = true)]
    pub units: Option<UnitsArg>,
    /// Unit weight γ of the blocks in kN/m³, DXF or OBJ/PLY [default: 18].
    #[arg(long, value_name = "KN_M3")]
    pub unit_weight: Option<f64>,
    /// Out-of-plane width of the blocks in m [default: 1].
    #[arg(long, value_name = "M")]
    pub dxf_width: Option<f64>,
    /// Polygons on this layer are supports (repeatable). Default: the lowest, widest polygon
    /// is the one support `base`.
    #[arg(long = "support-layer", value_name = "LAYER")]
    pub support_layers: Vec<String>,
    /// The lines (LWPOLYLINE, POLYLINE, LINE) on this layer are the model's existing cracks
    /// (case-insensitive; PREFIX*; repeatable), each with the width of the TEXT/MTEXT label
    /// next to it (a bare number is in mm) or in its layer's name (CRACK-2mm); as `identify
    /// --survey` reads a survey (docs/import.md). The layer gives no blocks.
    #[arg(long = "crack-layer", value_name = "LAYER")]
    pub crack_layers: Vec<String>,
    /// The polygon with this handle (hex) is a support (repeatable).
    #[arg(long = "support-handle", value_name = "HANDLE")]
    pub support_handles: Vec<String>,
    /// Vertices closer than this are welded (merged), in metres (absolute, after --units)
    /// [default: DXF 1e-6 of the drawing's size; OBJ/PLY 1e-7 of the model's bounding-box
    /// diagonal]. (`--merge-tolerance` is another name of this flag.)
    #[arg(long, alias = "merge-tolerance", value_name = "M")]
    pub weld: Option<f64>,
    /// Live load added to the model (drawings and meshes carry none) [default: horizontal].
    /// (`--dxf-live` and `--mesh-live` are other names of this flag.)
    #[arg(
        long = "live",
        alias = "dxf-live",
        alias = "mesh-live",
        value_enum,
        ignore_case = true
    )]
    pub live: Option<DxfLiveArg>,
    #[command(flatten)]
    pub mesh: MeshArgs,
}

// How to read a `.obj` or `.ply` model (3D). `--units` and `--unit-weight` are shared with DXF.
#[derive(Args, Clone, Debug, Default)]
#[command(next_help_heading = "OBJ/PLY import")]
pub struct MeshArgs {
    /// Bodies that are supports: OBJ object/group names, PLY parts `part_K` (comma-separated,
    /// repeatable). Default: objects named `support_…` (as `voussoir export` writes them), else
    /// every body standing on the ground plane (the model's lowest z).
    #[arg(long = "supports", value_name = "NAME,…", value_delimiter = ',')]
    pub supports: Vec<String>,
    /// Bodies whose name starts with PREFIX are supports.
    #[arg(long = "support-prefix", value_name = "PREFIX")]
    pub support_prefix: Option<String>,
}

impl MeshArgs {
    /// The first OBJ/PLY-only flag given, if any.
    pub fn given(&self) -> Option<&'static str> {
        [
            (!self.supports.is_empty(), "--supports"),
            (self.support_prefix.is_some(), "--support-prefix"),
        ]
        .into_iter()
        .find(|(given, _)| *given)
        .map(|(_, flag)| flag)
    }
}

/// The report of the last mesh read, to name OBJ objects in later errors about "block N".
static MESH_REPORT: Mutex<Option<MeshReport>> = Mutex::new(None);

/// `msg` with the OBJ object or PLY part of every "block N" it names, if a mesh was read.
pub fn annotate_mesh(msg: &str) -> String {
    match MESH_REPORT.lock().ok().as_ref().and_then(|r| r.as_ref()) {
        Some(rep) => rep.annotate(msg),
        None => msg.to_string(),
    }
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
            crack_layers: self.crack_layers.clone(),
            merge_tolerance: self.weld,
            live: match self.live.unwrap_or_default() {
                DxfLiveArg::None => ImportLive::None,
                DxfLiveArg::Horizontal => ImportLive::Horizontal,
            },
        }
    }

    pub fn mesh_options(&self) -> MeshOptions {
        let d = MeshOptions::default();
        MeshOptions {
            units: match self.units {
                Some(UnitsArg::Mm) => Units::Mm,
                Some(UnitsArg::Cm) => Units::Cm,
                Some(UnitsArg::M) | None => Units::M,
            },
            unit_weight: self.unit_weight.unwrap_or(d.unit_weight),
            supports: self.mesh.supports.clone(),
            support_prefix: self.mesh.support_prefix.clone(),
            weld: self.weld,
            live: match self.live.unwrap_or_default() {
                DxfLiveArg::None => ImportLive::None,
                DxfLiveArg::Horizontal => ImportLive::Horizontal,
            },
        }
    }

    /// The first import flag given on the command line, if any (to refuse it for a JSON model).
    pub fn given(&self) -> Option<&'static str> {
        [
            (self.units.is_some(), "--units"),
            (self.unit_weight.is_some(), "--unit-weight"),
            (self.weld.is_some(), "--weld"),
            (self.live.is_some(), "--live"),
        ]
        .into_iter()
        .find(|(given, _)| *given)
        .map(|(_, flag)| flag)
        .or_else(|| self.dxf_given())
        .or_else(|| self.mesh.given())
    }

    /// Refuse the flags that do not apply to the format of `path`: DXF-only flags unless it is
    /// a `.dxf`, OBJ/PLY flags unless it is a `.obj`/`.ply`, any import flag for JSON.
    pub fn refuse_foreign(&self, path: &Path) -> Result<(), Fail> {
        let (flag, what) = if voussoir_io::dxf::is_dxf(path) {
            (
                self.mesh.given(),
                "OBJ/PLY meshes only, and this is a DXF drawing",
            )
        } else if is_mesh(path) {
            (
                self.dxf_given(),
                "DXF drawings only, and it is not a .dxf file",
            )
        } else {
            (
                self.given(),
                "imported DXF drawings and OBJ/PLY meshes only",
            )
        };
        match flag {
            Some(f) => Err(Fail(format!("{f} applies to {what}: {}", path.display()))),
            None => Ok(()),
        }
    }

    /// The first DXF-only flag given.
    fn dxf_given(&self) -> Option<&'static str> {
        [
            (self.dxf_width.is_some(), "--dxf-width"),
            (!self.support_layers.is_empty(), "--support-layer"),
            (!self.support_handles.is_empty(), "--support-handle"),
            (!self.crack_layers.is_empty(), "--crack-layer"),
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
            ("--weld", self.weld),
        ] {
            if let Some(x) = v {
                if !(x.is_finite() && x > 0.0) {
                    return Err(Fail(format!("{flag} {x}: must be a finite number > 0")));
                }
            }
        }
        Ok(())
    }

    /// Read `path` as a model of either dimension: DXF (2D) or OBJ/PLY (3D) by extension, JSON
    /// otherwise.
    pub fn read_any(&self, path: &Path) -> Result<(AnyModel, Option<ImportReport>), Fail> {
        crate::outputs::input(path);
        if voussoir_io::dxf::is_dxf(path) {
            let (m, rep) = read_dxf(path, &self.options())?;
            for w in &rep.warnings {
                eprintln!("warning: {w}");
            }
            for (i, e) in rep.crack_entities.iter().enumerate() {
                crate::common::note_crack_source(i, e.clone());
            }
            Ok((AnyModel::Planar(m), Some(rep)))
        } else if is_mesh(path) {
            let (m, rep) = read_mesh(path, &self.mesh_options())?;
            for n in &rep.notes {
                eprintln!("note: {n}");
            }
            if let Ok(mut slot) = MESH_REPORT.lock() {
                *slot = Some(rep);
            }
            Ok((AnyModel::Spatial(m), None))
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
    /// The drawing or mesh: a .dxf (closed LWPOLYLINE/POLYLINE entities are the 2D blocks), a
    /// .obj (each object or group is a 3D block) or a .ply (each connected closed part is a 3D
    /// block).
    pub drawing: PathBuf,
    /// Geometric tolerance of the validation run after import, relative to the drawing's size
    /// (dimensionless; default 1e-7).
    #[arg(long, value_name = "REL")]
    pub tolerance: Option<f64>,
    /// Where to write the model JSON (stdout if absent).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Cut every support into N parts of equal x extent, named NAME@0 … NAME@(N-1) from the
    /// left, so that each can be moved on its own (`settle model.json --move base@2=0,-1cm`).
    /// N ≥ 2; a 3D support must be convex.
    #[arg(long = "split-support", value_name = "N")]
    pub split_support: Option<usize>,
    // Last: the flattened groups set the help heading of what follows them.
    #[command(flatten)]
    pub dxf: DxfArgs,
}

pub fn run(a: ImportArgs) -> Result<(), Fail> {
    a.dxf.check()?;
    if !voussoir_io::dxf::is_dxf(&a.drawing) && !is_mesh(&a.drawing) {
        return Err(Fail(format!(
            "{}: import reads .dxf drawings and .obj/.ply meshes (a JSON model needs no import)",
            a.drawing.display()
        )));
    }
    a.dxf.refuse_foreign(&a.drawing)?;
    if is_mesh(&a.drawing) {
        return run_mesh(a);
    }
    let (mut model, rep) = read_dxf(&a.drawing, &a.dxf.options())?;
    let splits = split_equally(&mut model, a.split_support)?;
    // Validate now (overlaps, isolated blocks), so that a bad drawing fails at import.
    let st = structure_of(
        &model,
        BuildOptions {
            tolerance: a.tolerance,
        },
        Some(&rep),
    )?;
    let json = voussoir_io::files::to_json(&model)?;
    emit(a.output.as_deref(), &json)?;
    eprintln!("{}; {} joints", rep.summary(), st.joints.len());
    eprint!("{}", crate::common::split_summary(&splits));
    for n in &rep.notes {
        eprintln!("note: {n}");
    }
    for w in &rep.warnings {
        eprintln!("warning: {w}");
    }
    Ok(())
}

/// `--split-support N`: every support cut into N equal parts along x.
fn split_equally<M: voussoir::settlement_input::ModelSupports>(
    model: &mut M,
    n: Option<usize>,
) -> Result<Vec<voussoir::settlement_input::SupportSplit>, Fail> {
    let Some(n) = n else { return Ok(Vec::new()) };
    if n < 2 {
        return Err(Fail(format!(
            "--split-support {n}: give the number of equal parts, 2 or more"
        )));
    }
    voussoir::settlement_input::split_supports_equally(model, n).map_err(|e| {
        Fail(format!(
            "--split-support {n}: {}",
            e.to_string().trim_start_matches("invalid request: ")
        ))
    })
}

/// Write the model JSON to `output` (committed now, so that the summary printed after it is
/// only printed once the file is written) or to stdout.
fn emit(output: Option<&Path>, json: &str) -> Result<(), Fail> {
    match output {
        Some(p) => {
            crate::outputs::stage(p, json.as_bytes())?;
            crate::outputs::commit()
        }
        None => {
            print!("{json}");
            Ok(())
        }
    }
}

/// `voussoir import model.obj|model.ply`: read, validate (overlaps and isolated blocks are
/// found now, named by OBJ object), write the JSON model.
fn run_mesh(a: ImportArgs) -> Result<(), Fail> {
    crate::outputs::input(&a.drawing);
    let (mut model, rep) = read_mesh(&a.drawing, &a.dxf.mesh_options())?;
    let splits = split_equally(&mut model, a.split_support)?;
    let st = Structure3d::new(
        &model,
        BuildOptions {
            tolerance: a.tolerance,
        },
    )
    .map_err(|e| Fail(rep.annotate(&e.to_string())))?;
    let json = voussoir_io::files::to_json(&model)?;
    emit(a.output.as_deref(), &json)?;
    eprintln!("{}; {} joints", rep.summary(), st.joints.len());
    eprint!("{}", crate::common::split_summary(&splits));
    for n in &rep.notes {
        eprintln!("note: {n}");
    }
    for w in model.warnings() {
        eprintln!("warning: {w}");
    }
    Ok(())
}

#[derive(Args)]
pub struct ExportArgs {
    /// The 3D model: JSON (or .obj/.ply, read with the OBJ/PLY import flags).
    pub model: PathBuf,
    /// Where to write the OBJ (stdout if absent): each block the object `block_i`, each support
    /// `support_NAME`; coordinates in metres, written exactly.
    #[arg(short = 'o', long = "output", value_name = "FILE.obj")]
    pub output: Option<PathBuf>,
    #[command(flatten)]
    pub dxf: DxfArgs,
}

/// `voussoir export model.json -o model.obj`: validated as every reader validates it (the model
/// as the analyses build it, then the OBJ text as `voussoir import` reads it back), so that what
/// is written is read; a refusal is one line naming the block, and nothing is written.
pub fn export(a: ExportArgs) -> Result<(), Fail> {
    a.dxf.check()?;
    a.dxf.refuse_foreign(&a.model)?;
    if let Some(p) = &a.output {
        if !p.extension().is_some_and(|e| e.eq_ignore_ascii_case("obj")) {
            return Err(Fail(format!(
                "{}: export writes Wavefront OBJ; name the output .obj",
                p.display()
            )));
        }
    }
    let model = match a.dxf.read_any(&a.model)?.0 {
        AnyModel::Spatial(m) => m,
        AnyModel::Planar(_) => {
            return Err(Fail(format!(
                "{} is a 2D model: export writes 3D models (blocks with vertices and faces) as OBJ",
                a.model.display()
            )))
        }
    };
    let refuse = |why: String| {
        Fail(format!(
            "{}: not exported: {}",
            a.model.display(),
            annotate_mesh(&why)
        ))
    };
    voussoir_io::mesh::check_exportable(&model).map_err(|e| refuse(e.0))?;
    // The model as every analysis reads it.
    Structure3d::new(&model, BuildOptions::default()).map_err(|e| refuse(e.to_string()))?;
    let obj = voussoir_io::mesh::model_to_obj(&model);
    // The OBJ as `voussoir import` reads it: with the model's own tolerance as the weld if it
    // is wider than the default (said in the summary line), else with the defaults.
    let weld = model
        .tolerance
        .filter(|&t| t > DEFAULT_REL_TOLERANCE)
        .map(|t| {
            let all: Vec<[f64; 3]> = model
                .blocks
                .iter()
                .flat_map(|b| b.vertices.iter())
                .chain(model.supports.iter().flat_map(|s| s.vertices.iter()))
                .copied()
                .collect();
            let [lo, hi] = voussoir::geometry3d::bbox3(&all);
            let d: f64 = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
            t * d
        });
    let opts = voussoir_io::mesh::MeshOptions {
        weld,
        ..Default::default()
    };
    let back = voussoir_io::mesh::parse_obj(obj.as_bytes(), &opts, "the exported OBJ")
        .map_err(|e| e.0)
        .and_then(|(m, rep)| {
            Structure3d::new(&m, BuildOptions::default())
                .map_err(|e| rep.annotate(&e.to_string()))
                .map(|_| m)
        })
        .map_err(|e| refuse(format!("the OBJ would not read back: {e}")))?;
    if back.blocks.len() != model.blocks.len() || back.supports.len() != model.supports.len() {
        return Err(refuse(format!(
            "the OBJ would read back as {} blocks and {} supports, not {} and {}",
            back.blocks.len(),
            back.supports.len(),
            model.blocks.len(),
            model.supports.len()
        )));
    }
    match &a.output {
        Some(p) => {
            crate::outputs::stage(p, obj.as_bytes())?;
            // Written before it is reported.
            crate::outputs::commit()?;
        }
        None => print!("{obj}"),
    }
    let hint = match weld {
        Some(w) => format!("; import it with --weld {w:.3e} (the model's tolerance)"),
        None => String::new(),
    };
    eprintln!(
        "{} blocks, {} supports written as OBJ objects (materials, loads and support motions are not part of OBJ){hint}",
        model.blocks.len(),
        model.supports.len()
    );
    Ok(())
}
