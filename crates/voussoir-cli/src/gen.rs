//! `voussoir gen`: model generators.

use crate::common::Fail;
use clap::{Args, Subcommand, ValueEnum};
use std::path::PathBuf;
use voussoir::generate::{
    self, ArchShape, ArchSpec, FirstCourse, LintelSpec, LiveLoad, RadiusAt, WallSpec,
};
use voussoir::Model;

#[derive(Subcommand)]
pub enum Gen {
    /// A semicircular, segmental or pointed arch of voussoirs with radial joints on two
    /// supports named `left` and `right`.
    Arch(ArchArgs),
    /// A flat lintel: one course of bricks between supports `left` and `right`.
    Lintel(LintelArgs),
    /// A running-bond wall on foundation segments f0, f1, … (one per base unit).
    Wall(WallArgs),
    /// A façade with pointed doors, rose and rectangular windows (default: the paper's Fig 18
    /// church façade, 22 m × 19 m), meshed as a grid or a running bond on segments f0, f1, ….
    #[command(alias = "façade")]
    Facade(FacadeArgs),
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
    /// Live load intensity q in kN/m² per unit horizontal projection of the extrados.
    #[arg(long, default_value_t = 1.0)]
    pub live_load: f64,
    /// Segmental arch: half of the angle the arch subtends, in degrees.
    #[arg(long, default_value_t = 60.0)]
    pub half_angle: f64,
    /// Pointed arch: distance of each arc's centre from the middle, as a fraction of the
    /// intrados radius (0.5: equilateral).
    #[arg(long, default_value_t = 0.5)]
    pub offset: f64,
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
    pub live: LiveArg,
    #[command(flatten)]
    pub out: Output,
}

fn write(model: &Model, out: &Output) -> Result<(), Fail> {
    let json = voussoir_io::files::to_json(model)?;
    match &out.output {
        Some(p) => {
            crate::outputs::stage(p, json.as_bytes())?;
            eprintln!(
                "wrote {} ({} blocks, {} supports)",
                p.display(),
                model.blocks.len(),
                model.supports.len()
            );
        }
        None => crate::common::out(&json),
    }
    Ok(())
}

pub fn run(g: Gen) -> Result<(), Fail> {
    match g {
        Gen::Arch(a) => {
            let shape = match a.shape {
                ShapeArg::Semicircular => ArchShape::Semicircular,
                ShapeArg::Segmental => ArchShape::Segmental {
                    half_angle: a.half_angle.to_radians(),
                },
                ShapeArg::Pointed => ArchShape::Pointed { offset: a.offset },
            };
            let m = generate::arch(&ArchSpec {
                shape,
                radius: a.radius,
                radius_at: match a.radius_at {
                    RadiusAtArg::Intrados => RadiusAt::Intrados,
                    RadiusAtArg::Centreline => RadiusAt::Centreline,
                    RadiusAtArg::Extrados => RadiusAt::Extrados,
                },
                thickness: a.thickness,
                voussoirs: a.voussoirs,
                unit_weight: a.unit_weight,
                width: a.width,
                live: a.live.into(),
                live_load: a.live_load,
            })?;
            write(&m, &a.out)
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
    /// Live load: none or horizontal (tilting table).
    #[arg(long, value_enum, ignore_case = true, default_value = "none")]
    pub live: LiveArg,
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
        };
        let mut s = bondeno(element[0], mesh);
        s.element = element;
        s.width = self.width;
        s.height = self.height;
        s.gable = self.gable;
        s.segments = self.segments;
        s.unit_weight = self.unit_weight;
        s.thickness = self.thickness;
        s.live = self.live.into();
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
