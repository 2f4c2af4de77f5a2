//! `voussoir gen`: model generators.

use crate::common::Fail;
use clap::{Args, Subcommand, ValueEnum};
use std::path::PathBuf;
use voussoir::generate::{self, ArchSpec, FirstCourse, LintelSpec, LiveLoad, RadiusAt, WallSpec};
use voussoir::generate3d::{self, Bond, DomeSpec, Plan, WallsLive, WallsSpec};
use voussoir::model3d::Model3d;
use voussoir::request::{ArchRequest, Names, ShapeName};
use voussoir::Model;

#[derive(Subcommand)]
pub enum Gen {
    /// A semicircular, segmental or pointed arch of voussoirs with radial joints on two
    /// supports named `left` and `right`.
    Arch(ArchArgs),
    /// A flat lintel: one course of bricks between supports `left` and `right`.
    Lintel(LintelArgs),
    /// A running-bond wall on foundation segments f0, f1, … (one per base unit), or a wall of
    /// any outline (--outline: a DXF drawing or JSON) meshed as a grid, a running bond or
    /// triangles.
    Wall(WallArgs),
    /// A façade with pointed doors, rose and rectangular windows (default: the paper's Fig 18
    /// church façade, 22 m × 19 m), meshed as a grid, a running bond or triangles on segments
    /// f0, f1, ….
    #[command(alias = "façade")]
    Facade(FacadeArgs),
    /// 3D: a barrel vault, the arch of `gen arch` (every arch flag) extruded along +y over
    /// --depth in --rings rings, stack or running bond; supports `left` and `right`.
    Vault(VaultArgs),
    /// 3D: a hemispherical or segmental dome of --courses × --segments blocks with planar faces,
    /// closed by a cap or open (--oculus), on supports base0 … base{segments-1}.
    Dome(DomeArgs),
    /// 3D: one box b×d×h on a support `base`, with a horizontal live load equal to its weight
    /// along --direction.
    Block(BlockArgs),
    /// 3D: brick walls in running bond, plan I, L or U with bonded corners, on a support
    /// `ground`; live load W·[0, 1, 0] (out of plane) on the main wall.
    Walls(WallsArgs),
}

#[derive(Args)]
pub struct Output {
    /// Where to write the model JSON (stdout if absent).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<PathBuf>,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum ShapeArg {
    /// Half a circle: springings at the level of the centre.
    #[value(alias = "semi-circular", alias = "round")]
    Semicircular,
    /// A circular arc of less than 180° (see --half-angle).
    #[value(alias = "segmented", alias = "segment")]
    Segmental,
    /// Two circular arcs meeting at the crown (see --offset).
    #[value(alias = "gothic", alias = "ogival")]
    Pointed,
}
#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum RadiusAtArg {
    /// The inner (lower) face of the ring.
    #[value(alias = "inner", alias = "soffit")]
    Intrados,
    /// The middle of the ring's thickness (also spelled centerline, centre-line, center).
    #[value(
        alias = "centerline",
        alias = "centre-line",
        alias = "center-line",
        alias = "centre",
        alias = "center",
        alias = "middle",
        alias = "midline"
    )]
    Centreline,
    /// The outer (upper) face of the ring.
    #[value(alias = "outer")]
    Extrados,
}
#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum LiveArg {
    /// No live load.
    None,
    /// Vertical, on the whole span (arch: the extrados; wall: 1 kN/m² on the top course).
    #[value(alias = "uniform", alias = "all")]
    Full,
    /// Vertical, on the left half of the span (arch).
    Left,
    /// Vertical, on the right half of the span (arch).
    Right,
    /// Horizontal, equal to each block's weight, along +x (tilting table).
    #[value(alias = "tilt", alias = "seismic")]
    Horizontal,
}
/// The live loads of `gen wall`: a wall has no halves of a span.
#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum WallLiveArg {
    /// No live load.
    None,
    /// Vertical, 1 kN/m² on the top course.
    #[value(alias = "uniform", alias = "all")]
    Full,
    /// Horizontal, equal to each block's weight, along +x (tilting table).
    #[value(alias = "tilt", alias = "seismic")]
    Horizontal,
}
impl From<WallLiveArg> for LiveLoad {
    fn from(l: WallLiveArg) -> Self {
        match l {
            WallLiveArg::None => LiveLoad::None,
            WallLiveArg::Full => LiveLoad::Full,
            WallLiveArg::Horizontal => LiveLoad::Horizontal,
        }
    }
}

/// The live loads of `gen facade`: none or the tilting table's. (`left` is not a horizontal
/// load towards −x: for an arch it is a vertical load on the left half; a façade's loads go
/// along +x, and `voussoir tilt --direction -x` tilts it the other way.)
#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum FacadeLiveArg {
    /// No live load.
    None,
    /// Horizontal, equal to each block's weight, along +x (tilting table).
    #[value(alias = "tilt", alias = "seismic")]
    Horizontal,
}
impl From<FacadeLiveArg> for LiveLoad {
    fn from(l: FacadeLiveArg) -> Self {
        match l {
            FacadeLiveArg::None => LiveLoad::None,
            FacadeLiveArg::Horizontal => LiveLoad::Horizontal,
        }
    }
}

impl From<LiveArg> for LiveLoad {
    fn from(l: LiveArg) -> Self {
        match l {
            LiveArg::None => LiveLoad::None,
            LiveArg::Full => LiveLoad::Full,
            LiveArg::Left => LiveLoad::Left,
            LiveArg::Right => LiveLoad::Right,
            LiveArg::Horizontal => LiveLoad::Horizontal,
        }
    }
}

#[derive(Args)]
pub struct ArchArgs {
    /// Shape of the arch.
    #[arg(long, value_enum, ignore_case = true, default_value = "semicircular")]
    pub shape: ShapeArg,
    /// Radius in m (where: see --radius-at).
    #[arg(long, default_value_t = 2.86)]
    pub radius: f64,
    /// Where the radius is measured.
    #[arg(long, value_enum, ignore_case = true, default_value = "intrados")]
    pub radius_at: RadiusAtArg,
    /// Ring thickness in m.
    #[arg(long, default_value_t = 0.33)]
    pub thickness: f64,
    /// Number of voussoirs.
    #[arg(long, default_value_t = 64)]
    pub voussoirs: usize,
    /// Unit weight γ in kN/m³.
    #[arg(long, default_value_t = 18.0)]
    pub unit_weight: f64,
    /// Out-of-plane width in m.
    #[arg(long, default_value_t = 1.0)]
    pub width: f64,
    /// Live load: none, full span, left or right half (vertical, on the extrados), or
    /// horizontal (equal to each block's weight).
    #[arg(long, value_enum, ignore_case = true, default_value = "none")]
    pub live: LiveArg,
    /// Live load intensity q in kN/m² per unit horizontal projection of the extrados, for
    /// `--live full|left|right` [default: 1] (refused with `none` or `horizontal`, which have
    /// no intensity).
    #[arg(long)]
    pub live_load: Option<f64>,
    /// Segmental arch: half of the angle the arch subtends, in degrees [default: 60]; refused
    /// with another --shape.
    #[arg(long)]
    pub half_angle: Option<f64>,
    /// Pointed arch: distance of each arc's centre from the middle, as a fraction of the
    /// intrados radius (0.5: equilateral) [default: 0.5]; refused with another --shape.
    #[arg(long)]
    pub offset: Option<f64>,
    #[command(flatten)]
    pub out: Output,
}

#[derive(Args)]
pub struct LintelArgs {
    /// Clear span in m.
    #[arg(long, default_value_t = 1.5)]
    pub span: f64,
    /// Depth (thickness) in m.
    #[arg(long, default_value_t = 0.24)]
    pub thickness: f64,
    /// Number of bricks.
    #[arg(long, default_value_t = 6)]
    pub bricks: usize,
    /// Unit weight γ in kN/m³.
    #[arg(long, default_value_t = 18.0)]
    pub unit_weight: f64,
    /// Out-of-plane width in m.
    #[arg(long, default_value_t = 1.0)]
    pub width: f64,
    /// Live load on the top face in kN/m.
    #[arg(long, default_value_t = 1.0)]
    pub live_load: f64,
    /// Compressive strength f_c in kPa (absent: infinite).
    #[arg(long)]
    pub compressive_strength: Option<f64>,
    #[command(flatten)]
    pub out: Output,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum FirstCourseArg {
    /// The first course is made of full units.
    Full,
    /// The first course starts with a half unit.
    Half,
}

#[derive(Args)]
pub struct WallArgs {
    /// Number of courses.
    #[arg(long, default_value_t = 6)]
    pub courses: usize,
    /// Units per full course.
    #[arg(long, default_value_t = 5)]
    pub units: usize,
    /// Unit size LENGTH,HEIGHT in m.
    #[arg(long, default_value = "0.4,0.175")]
    pub unit: String,
    /// Whether the first course is made of full units or starts with half units.
    #[arg(long, value_enum, ignore_case = true, default_value = "full")]
    pub first_course: FirstCourseArg,
    /// Unit weight γ in kN/m³.
    #[arg(long, default_value_t = 18.0)]
    pub unit_weight: f64,
    /// Out-of-plane width in m.
    #[arg(long, default_value_t = 1.0)]
    pub width: f64,
    /// Live load: none, horizontal (tilting table: each block's weight, along +x) or full
    /// (1 kN/m² on the top course).
    #[arg(long, value_enum, ignore_case = true, default_value = "none")]
    pub live: WallLiveArg,
    /// A wall of any outline instead of courses of units: a DXF drawing (closed polylines: the
    /// outer boundary and the openings) or a JSON file {"outer": [[x, y], …], "holes":
    /// [[[x, y], …], …]} in m; meshed by --mesh on a foundation along its base (docs/meshes.md).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["courses", "units", "unit", "first_course"])]
    pub outline: Option<PathBuf>,
    /// --outline: the layer(s) of the outer boundary, one closed polyline (default: the
    /// largest closed polyline). Case-insensitive, PREFIX* matches a prefix.
    #[arg(
        long = "outer-layer",
        value_name = "LAYER",
        value_delimiter = ',',
        requires = "outline"
    )]
    pub outer_layer: Vec<String>,
    /// --outline: the layer(s) of the openings (default: every other closed polyline not on an
    /// outer layer).
    #[arg(
        long = "hole-layer",
        value_name = "LAYER",
        value_delimiter = ',',
        requires = "outline"
    )]
    pub hole_layer: Vec<String>,
    /// --outline: the drawing's units, mm|cm|m (default: its header's $INSUNITS).
    #[arg(long = "drawing-units", value_name = "UNIT", requires = "outline")]
    pub drawing_units: Option<String>,
    /// --outline: the mesh: grid, running-bond or triangles [default: running-bond].
    #[arg(long, value_enum, ignore_case = true, requires = "outline")]
    pub mesh: Option<MeshArg>,
    /// --outline: element (unit) size LENGTH[,HEIGHT] in m, height default half the length
    /// [default: 0.5]. Triangles: at most LENGTH·HEIGHT m² each unless --max-area.
    #[arg(long, value_name = "LENGTH[,HEIGHT]", requires = "outline")]
    pub size: Option<String>,
    /// --outline, triangles: the largest triangle area in m² [default: LENGTH·HEIGHT of --size].
    #[arg(long = "max-area", value_name = "M2", requires = "outline")]
    pub max_area: Option<f64>,
    /// --outline, triangles: the smallest angle in degrees, at most 33 [default: 30].
    #[arg(long = "min-angle", value_name = "DEG", requires = "outline")]
    pub min_angle: Option<f64>,
    /// --outline, grid and running bond: a piece of an element cut by the outline smaller than
    /// this fraction of an element is merged into its neighbour [default: 0.05].
    #[arg(long = "min-piece", value_name = "FRACTION", requires = "outline")]
    pub min_piece: Option<f64>,
    /// --outline: the base cut into N equal foundation segments f0 … f{N−1} (default 1: one
    /// support named `base`).
    #[arg(long, value_name = "N", requires = "outline")]
    pub segments: Option<usize>,
    /// --outline: depth of the foundation below the base, m [default: 0.5].
    #[arg(long = "foundation-depth", value_name = "M", requires = "outline")]
    pub foundation_depth: Option<f64>,
    #[command(flatten)]
    pub out: Output,
}

/// The mesh of a wall given by its outline.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshArg {
    /// A grid of rectangular elements (continuous head joints).
    Grid,
    /// Courses of units, head joints staggered by half a unit.
    #[value(
        alias = "running",
        alias = "bond",
        alias = "runningbond",
        alias = "stretcher-bond"
    )]
    RunningBond,
    /// Unstructured triangles (refined constrained Delaunay).
    #[value(alias = "triangle", alias = "tri", alias = "delaunay")]
    Triangles,
}

impl WallArgs {
    /// The model of `gen wall --outline`.
    fn outline_model(&self, path: &std::path::Path) -> Result<Model, Fail> {
        use voussoir::outline_mesh::{mesh_wall, Foundation, MeshKind, MeshOptions};
        let units = match &self.drawing_units {
            None => None,
            Some(u) => Some(
                u.parse::<voussoir_io::dxf::Units>()
                    .map_err(|e| Fail(format!("--drawing-units {u}: {}", e.0)))?,
            ),
        };
        let (outline, rep) = voussoir_io::outline::read_outline(
            path,
            &voussoir_io::outline::OutlineOptions {
                units,
                outer_layers: self.outer_layer.clone(),
                hole_layers: self.hole_layer.clone(),
            },
        )
        .map_err(|e| Fail(e.0))?;
        let size = self.size.as_deref().unwrap_or("0.5");
        let v: Vec<f64> = size
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| Fail(format!("--size {size}: expected LENGTH[,HEIGHT] in metres")))?;
        let [l, h] = match v[..] {
            [l] => [l, l / 2.0],
            [l, h] => [l, h],
            _ => {
                return Err(Fail(format!(
                    "--size {size}: expected LENGTH[,HEIGHT] in metres"
                )))
            }
        };
        if !(l.is_finite() && l > 0.0 && h.is_finite() && h > 0.0) {
            return Err(Fail(format!(
                "--size {size}: the length and height must be positive"
            )));
        }
        let mesh = self.mesh.unwrap_or(MeshArg::RunningBond);
        if mesh != MeshArg::Triangles {
            if let Some(a) = self.max_area {
                return Err(Fail(format!("--max-area {a}: applies to --mesh triangles")));
            }
            if let Some(a) = self.min_angle {
                return Err(Fail(format!(
                    "--min-angle {a}: applies to --mesh triangles"
                )));
            }
        } else if let Some(p) = self.min_piece {
            return Err(Fail(format!(
                "--min-piece {p}: applies to --mesh grid or running-bond (triangles are never cut)"
            )));
        }
        let kind = match mesh {
            MeshArg::Grid => MeshKind::Grid {
                length: l,
                height: h,
            },
            MeshArg::RunningBond => MeshKind::RunningBond {
                length: l,
                height: h,
            },
            MeshArg::Triangles => MeshKind::Triangles {
                max_area: self.max_area.unwrap_or(l * h),
                min_angle_deg: self.min_angle.unwrap_or(30.0),
            },
        };
        let segments = self.segments.unwrap_or(1);
        if segments == 0 {
            return Err(Fail(
                "--segments 0: give at least one foundation segment".into(),
            ));
        }
        let depth = self.foundation_depth.unwrap_or(0.5);
        let foundation = if segments == 1 {
            Foundation::single("base", depth)
        } else {
            Foundation::segments(segments, "f", depth)
        };
        let opts = MeshOptions {
            min_piece: if mesh == MeshArg::Triangles {
                0.0
            } else {
                self.min_piece.unwrap_or(0.05)
            },
            ..MeshOptions::default()
        };
        let mut m = mesh_wall(
            &outline,
            &kind,
            self.unit_weight,
            self.width,
            &foundation,
            &opts,
        )
        .map_err(|e| Fail(rep.annotate(&e.to_string())))?;
        match self.live {
            WallLiveArg::None => {}
            WallLiveArg::Horizontal => m.loads.live.push(voussoir::model::Load::Body {
                coefficients: [1.0, 0.0],
                blocks: None,
            }),
            WallLiveArg::Full => {
                return Err(Fail(
                    "--live full: a load on the top course of a wall of courses; with --outline give --live none or horizontal".into(),
                ))
            }
        }
        if let Some(name) = path.file_name() {
            m.description = format!("{} ({})", m.description, name.to_string_lossy());
        }
        eprintln!("{}", rep.summary());
        Ok(m)
    }
}

fn write(model: &Model, out: &Output) -> Result<(), Fail> {
    write_json(model, model.blocks.len(), model.supports.len(), out)
}

fn write3d(model: &Model3d, out: &Output) -> Result<(), Fail> {
    write_json(model, model.blocks.len(), model.supports.len(), out)
}

fn write_json<T: serde::Serialize>(
    model: &T,
    blocks: usize,
    supports: usize,
    out: &Output,
) -> Result<(), Fail> {
    let json = voussoir_io::files::to_json(model)?;
    match &out.output {
        Some(p) => {
            // Written now, so that the line saying so is printed only once it is true.
            crate::outputs::stage(p, json.as_bytes())?;
            crate::outputs::commit()?;
            eprintln!(
                "wrote {} ({blocks} blocks, {supports} supports)",
                p.display()
            );
        }
        None => crate::common::out(&json),
    }
    Ok(())
}

impl ArchArgs {
    /// The library's generator request checks it ([`voussoir::request::ArchRequest`]: a
    /// shape's own parameter or the live load's intensity given where it does nothing is
    /// refused), for the CLI and Python alike.
    pub fn spec(&self) -> Result<ArchSpec, Fail> {
        let shape = match self.shape {
            ShapeArg::Semicircular => ShapeName::Semicircular,
            ShapeArg::Segmental => ShapeName::Segmental,
            ShapeArg::Pointed => ShapeName::Pointed,
        };
        Ok(ArchRequest {
            shape,
            radius: self.radius,
            radius_at: self.radius_at.into(),
            thickness: self.thickness,
            voussoirs: self.voussoirs,
            unit_weight: self.unit_weight,
            width: self.width,
            live: self.live.into(),
            live_load: self.live_load,
            half_angle: self.half_angle,
            offset: self.offset,
        }
        .spec(Names::Flags)?)
    }
}

impl From<RadiusAtArg> for RadiusAt {
    fn from(r: RadiusAtArg) -> Self {
        match r {
            RadiusAtArg::Intrados => RadiusAt::Intrados,
            RadiusAtArg::Centreline => RadiusAt::Centreline,
            RadiusAtArg::Extrados => RadiusAt::Extrados,
        }
    }
}

/// Comma-separated numbers of flag `flag`, exactly `n` of them (`what` names them).
fn numbers(flag: &str, text: &str, n: usize, what: &str) -> Result<Vec<f64>, Fail> {
    let v: Vec<f64> = text
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| Fail(format!("{flag} {text}: expected {what}")))?;
    if v.len() != n {
        return Err(Fail(format!("{flag} {text}: expected {what}")));
    }
    Ok(v)
}

pub fn run(g: Gen) -> Result<(), Fail> {
    match g {
        Gen::Arch(a) => {
            let m = generate::arch(&a.spec()?)?;
            write(&m, &a.out)
        }
        Gen::Vault(v) => {
            if v.arch.width != 1.0 {
                return Err(Fail(
                    "--width does not apply to `gen vault`: its depth along y is --depth".into(),
                ));
            }
            let m = generate3d::vault(&v.arch.spec()?, v.depth, v.rings, v.bond.into())?;
            write3d(&m, &v.arch.out)
        }
        Gen::Dome(d) => {
            let m = generate3d::dome(&d.spec())?;
            write3d(&m, &d.out)
        }
        Gen::Block(b) => {
            let v = numbers("--size", &b.size, 3, "B,D,H in metres")?;
            let az = b.direction.azimuth("--direction").map_err(Fail)?;
            let m = generate3d::block([v[0], v[1], v[2]], az, b.unit_weight)?;
            write3d(&m, &b.out)
        }
        Gen::Walls(w) => {
            let m = generate3d::walls(&WallsSpec {
                plan: match w.plan {
                    PlanArg::I => Plan::I,
                    PlanArg::L => Plan::L,
                    PlanArg::U => Plan::U,
                },
                length: w.length,
                return_length: w.return_length,
                height: w.height,
                thickness: w.thickness,
                courses: w.courses,
                units: w.units,
                unit_weight: w.unit_weight,
                live: match w.live {
                    WallsLiveArg::None => WallsLive::None,
                    WallsLiveArg::Main => WallsLive::Main,
                    WallsLiveArg::All => WallsLive::All,
                },
            })?;
            write3d(&m, &w.out)
        }
        Gen::Lintel(l) => {
            let m = generate::lintel(&LintelSpec {
                span: l.span,
                thickness: l.thickness,
                bricks: l.bricks,
                unit_weight: l.unit_weight,
                width: l.width,
                live_load: l.live_load,
                compressive_strength: l.compressive_strength,
            })?;
            write(&m, &l.out)
        }
        Gen::Facade(f) => {
            let m = voussoir::generate_facade::facade(&f.spec()?)?;
            write(&m, &f.out)
        }
        Gen::Wall(w) if w.outline.is_some() => {
            let path = w.outline.clone().unwrap_or_default();
            let m = w.outline_model(&path)?;
            write(&m, &w.out)
        }
        Gen::Wall(w) => {
            let unit: Vec<f64> = w
                .unit
                .split(',')
                .map(|x| x.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map_err(|_| {
                    Fail(format!(
                        "--unit {}: expected LENGTH,HEIGHT in metres",
                        w.unit
                    ))
                })?;
            let [ul, uh] = unit[..] else {
                return Err(Fail(format!(
                    "--unit {}: expected LENGTH,HEIGHT in metres",
                    w.unit
                )));
            };
            let m = generate::wall(&WallSpec {
                courses: w.courses,
                units: w.units,
                unit: [ul, uh],
                first_course: match w.first_course {
                    FirstCourseArg::Full => FirstCourse::Full,
                    FirstCourseArg::Half => FirstCourse::Half,
                },
                unit_weight: w.unit_weight,
                width: w.width,
                live: w.live.into(),
            })?;
            write(&m, &w.out)
        }
    }
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum FacadeMeshArg {
    /// A grid of rectangular elements (continuous head joints).
    Grid,
    /// A running bond (head joints staggered by half an element).
    #[value(
        alias = "running",
        alias = "bond",
        alias = "runningbond",
        alias = "stretcher-bond"
    )]
    RunningBond,
    /// Unstructured triangles (refined constrained Delaunay) of at most one element's area
    /// (LENGTH·HEIGHT of --element), no angle below --min-angle.
    #[value(alias = "triangle", alias = "tri", alias = "delaunay")]
    Triangles,
}

#[derive(Args)]
pub struct FacadeArgs {
    /// Element size in m: LENGTH[,HEIGHT] (height default: half the length).
    #[arg(long, default_value = "0.5", value_name = "LENGTH[,HEIGHT]")]
    pub element: String,
    /// Mesh of the wall.
    #[arg(long, value_enum, ignore_case = true, default_value = "grid")]
    pub mesh: FacadeMeshArg,
    /// Wall width in m (default: the paper's façade).
    #[arg(long, default_value_t = 22.0, value_name = "M")]
    pub width: f64,
    /// Eaves height in m.
    #[arg(long, default_value_t = 14.0, value_name = "M")]
    pub height: f64,
    /// Gable height above the eaves in m.
    #[arg(long, default_value_t = 5.0, value_name = "M")]
    pub gable: f64,
    /// Openings replacing the default ones (repeatable): door:X,WIDTH,SPRINGING[,OFFSET,RING] |
    /// rose:X,Y,RADIUS[,RING] | rect:X0,Y0,X1,Y1 (metres).
    #[arg(long = "opening", value_name = "SPEC")]
    pub openings: Vec<String>,
    /// Number of foundation segments.
    #[arg(long, default_value_t = 44)]
    pub segments: usize,
    /// Unit weight γ in kN/m³.
    #[arg(long, default_value_t = 18.0, value_name = "KN_M3")]
    pub unit_weight: f64,
    /// Out-of-plane thickness in m.
    #[arg(long, default_value_t = 1.0, value_name = "M")]
    pub thickness: f64,
    /// Live load: none or horizontal (tilting table: each block's weight, along +x; `voussoir
    /// tilt --direction -x` loads the façade the other way).
    #[arg(long, value_enum, ignore_case = true, default_value = "none")]
    pub live: FacadeLiveArg,
    /// --mesh triangles: the smallest angle of a triangle in degrees, at most 33 [default: 30].
    #[arg(long = "min-angle", value_name = "DEG")]
    pub min_angle: Option<f64>,
    #[command(flatten)]
    pub out: Output,
}

impl FacadeArgs {
    pub fn spec(&self) -> Result<voussoir::generate_facade::FacadeSpec, Fail> {
        use voussoir::generate_facade::{bondeno, FacadeMesh, Opening};
        let nums = |what: &str, t: &str| -> Result<Vec<f64>, Fail> {
            t.split(',')
                .map(|x| x.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map_err(|_| Fail(format!("{what} {t}: expected numbers separated by commas")))
        };
        let e = nums("--element", &self.element)?;
        let element = match e[..] {
            [l] => [l, l / 2.0],
            [l, h] => [l, h],
            _ => {
                return Err(Fail(format!(
                    "--element {}: expected LENGTH[,HEIGHT]",
                    self.element
                )))
            }
        };
        let mesh = match self.mesh {
            FacadeMeshArg::Grid => FacadeMesh::Grid,
            FacadeMeshArg::RunningBond => FacadeMesh::RunningBond,
            FacadeMeshArg::Triangles => FacadeMesh::Triangles,
        };
        if let (Some(a), false) = (self.min_angle, mesh == FacadeMesh::Triangles) {
            return Err(Fail(format!(
                "--min-angle {a}: applies to --mesh triangles"
            )));
        }
        let mut s = bondeno(element[0], mesh);
        s.element = element;
        s.width = self.width;
        s.height = self.height;
        s.gable = self.gable;
        s.segments = self.segments;
        s.unit_weight = self.unit_weight;
        s.thickness = self.thickness;
        s.live = self.live.into();
        if let Some(a) = self.min_angle {
            s.min_angle = a;
        }
        if !self.openings.is_empty() {
            s.openings.clear();
            for o in &self.openings {
                let (kind, rest) = o
                    .split_once(':')
                    .ok_or_else(|| Fail(format!("--opening {o}: expected KIND:NUMBERS")))?;
                let v = nums("--opening", rest)?;
                s.openings.push(match (kind, &v[..]) {
                    ("door", [x, w, sp]) => Opening::PointedDoor { x: *x, width: *w, springing: *sp, offset: 0.5, ring: 0.4 },
                    ("door", [x, w, sp, off, ring]) => Opening::PointedDoor { x: *x, width: *w, springing: *sp, offset: *off, ring: *ring },
                    ("rose", [x, y, r]) => Opening::Round { x: *x, y: *y, radius: *r, ring: 0.35 },
                    ("rose", [x, y, r, ring]) => Opening::Round { x: *x, y: *y, radius: *r, ring: *ring },
                    ("rect", [x0, y0, x1, y1]) => Opening::Rect { x0: *x0, y0: *y0, x1: *x1, y1: *y1 },
                    _ => return Err(Fail(format!("--opening {o}: expected door:X,WIDTH,SPRINGING[,OFFSET,RING], rose:X,Y,RADIUS[,RING] or rect:X0,Y0,X1,Y1"))),
                });
            }
        }
        Ok(s)
    }
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum BondArg {
    /// Every ring is the same arch: joints straight through the depth.
    #[value(alias = "stacked")]
    Stack,
    /// Odd rings have their joints shifted by half a voussoir (half-voussoirs at the springings).
    #[value(alias = "runningbond", alias = "running-bond", alias = "staggered")]
    Running,
}
impl From<BondArg> for Bond {
    fn from(b: BondArg) -> Self {
        match b {
            BondArg::Stack => Bond::Stack,
            BondArg::Running => Bond::Running,
        }
    }
}

#[derive(Args)]
pub struct VaultArgs {
    #[command(flatten)]
    pub arch: ArchArgs,
    /// Length of the vault along y in m (the arch is in the plane x, z).
    #[arg(long, default_value_t = 1.0, value_name = "M")]
    pub depth: f64,
    /// Number of rings of voussoirs along the depth.
    #[arg(long, default_value_t = 1)]
    pub rings: usize,
    /// How the rings are bonded.
    #[arg(long, value_enum, ignore_case = true, default_value = "stack")]
    pub bond: BondArg,
}

#[derive(Args)]
pub struct DomeArgs {
    /// Radius of the sphere in m (where: see --radius-at); the centre is the origin.
    #[arg(long, default_value_t = 5.0, value_name = "M")]
    pub radius: f64,
    /// Where the radius is measured.
    #[arg(long, value_enum, ignore_case = true, default_value = "intrados")]
    pub radius_at: RadiusAtArg,
    /// Shell thickness in m.
    #[arg(long, default_value_t = 0.3, value_name = "M")]
    pub thickness: f64,
    /// Courses (rings of blocks) from the springing to the crown; without --oculus the last
    /// one is the cap, a single block.
    #[arg(long, default_value_t = 8)]
    pub courses: usize,
    /// Blocks per course (meridian divisions).
    #[arg(long, default_value_t = 16)]
    pub segments: usize,
    /// Springing half-angle from the vertical axis in degrees (90: hemisphere; less: segmental).
    #[arg(long, default_value_t = 90.0, value_name = "DEG")]
    pub half_angle: f64,
    /// Oculus half-angle from the vertical axis in degrees (absent: closed by a cap).
    #[arg(long, value_name = "DEG")]
    pub oculus: Option<f64>,
    /// Unit weight γ in kN/m³.
    #[arg(long, default_value_t = 18.0, value_name = "KN_M3")]
    pub unit_weight: f64,
    /// Live vertical load at the crown in kN (downwards; with an oculus, shared by the top
    /// course's blocks). 0: no live load.
    #[arg(long, default_value_t = 0.0, value_name = "KN")]
    pub crown_load: f64,
    #[command(flatten)]
    pub out: Output,
}

impl DomeArgs {
    pub fn spec(&self) -> DomeSpec {
        DomeSpec {
            radius: self.radius,
            radius_at: self.radius_at.into(),
            thickness: self.thickness,
            courses: self.courses,
            segments: self.segments,
            half_angle: self.half_angle.to_radians(),
            oculus: self.oculus.map(f64::to_radians),
            unit_weight: self.unit_weight,
            crown_load: self.crown_load,
        }
    }
}

#[derive(Args)]
pub struct BlockArgs {
    /// Box size B,D,H in m along x, y, z.
    #[arg(long, default_value = "1,1,2", value_name = "B,D,H")]
    pub size: String,
    /// Direction of the horizontal live load: +x, -x, +y, -y, an azimuth in degrees from +x
    /// towards +y, or a horizontal vector DX,DY. (`--azimuth` is another name of this flag.)
    #[arg(
        long,
        alias = "azimuth",
        default_value = "+x",
        value_name = "DIR",
        allow_hyphen_values = true,
        value_parser = crate::direction::parse
    )]
    pub direction: crate::direction::Direction,
    /// Unit weight γ in kN/m³.
    #[arg(long, default_value_t = 18.0, value_name = "KN_M3")]
    pub unit_weight: f64,
    #[command(flatten)]
    pub out: Output,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum PlanArg {
    /// A free-standing straight wall along x.
    #[value(alias = "i", alias = "straight")]
    I,
    /// The main wall and a return along +y at its left end (x = 0).
    #[value(alias = "l")]
    L,
    /// The main wall and returns along +y at both ends.
    #[value(alias = "u")]
    U,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum WallsLiveArg {
    /// No live load.
    None,
    /// W·[0, 1, 0] on the main wall's blocks.
    Main,
    /// W·[0, 1, 0] on every block.
    All,
}

#[derive(Args)]
pub struct WallsArgs {
    /// Plan: I (straight), L (one return) or U (two returns).
    #[arg(long, value_enum, ignore_case = true, default_value = "I")]
    pub plan: PlanArg,
    /// Length of the main wall along x in m (outer dimension).
    #[arg(long, default_value_t = 2.0, value_name = "M")]
    pub length: f64,
    /// Length of each return along +y in m, from the main wall's outer face (plans L, U).
    #[arg(long, default_value_t = 1.0, value_name = "M")]
    pub return_length: f64,
    /// Height in m.
    #[arg(long, default_value_t = 1.2, value_name = "M")]
    pub height: f64,
    /// Thickness (one brick) in m.
    #[arg(long, default_value_t = 0.2, value_name = "M")]
    pub thickness: f64,
    /// Number of courses.
    #[arg(long, default_value_t = 6)]
    pub courses: usize,
    /// Bricks per course along the main wall (brick length = length / units).
    #[arg(long, default_value_t = 5)]
    pub units: usize,
    /// Unit weight γ in kN/m³.
    #[arg(long, default_value_t = 18.0, value_name = "KN_M3")]
    pub unit_weight: f64,
    /// Live load: W·[0, 1, 0] (out of plane) on the main wall, on every block, or none.
    #[arg(long, value_enum, ignore_case = true, default_value = "main")]
    pub live: WallsLiveArg,
    #[command(flatten)]
    pub out: Output,
}
