//! Flags shared by the analysis commands, model loading, output and human summaries.

use clap::Args;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::PathBuf;
use voussoir::analysis::limit::Crushing;
use voussoir::analysis::{LimitResult, SettlementResult};
use voussoir::lp::{Method, SolverOptions};
use voussoir::model3d::AnyModel;
use voussoir::result::{CrackText, Hinge, Spatial};
use voussoir::structure::Body;
use voussoir::Assembly;
use voussoir::{BuildOptions, Model};
use voussoir_io::lengths::Length;

/// A failure: one line for the user.
#[derive(Debug)]
pub struct Fail(pub String);

impl std::fmt::Display for Fail {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // One line whatever names or values from the user it quotes.
        f.write_str(&voussoir::error::one_line(&self.0))
    }
}
impl From<voussoir::Error> for Fail {
    fn from(e: voussoir::Error) -> Self {
        Fail(e.to_string())
    }
}
impl From<voussoir_io::IoError> for Fail {
    fn from(e: voussoir_io::IoError) -> Self {
        Fail(e.0)
    }
}

// Model input: every analysis command reads one model.
#[derive(Args, Clone, Debug)]
#[command(next_help_heading = "Model input")]
pub struct ModelArgs {
    /// The model: a JSON file (see README, "Model format"), a DXF drawing (`.dxf`, read with
    /// the "DXF import" flags below) or an OBJ/PLY mesh (3D, "OBJ/PLY import" flags).
    pub model: PathBuf,
    /// Geometric tolerance for joint detection, relative to the model's size (dimensionless;
    /// default 1e-7).
    #[arg(long, value_name = "REL")]
    pub tolerance: Option<f64>,
    /// Coulomb friction coefficient μ = tan φ for every joint (dimensionless; overrides the
    /// model's materials; default: the model's, else no sliding).
    #[arg(long, value_name = "MU")]
    pub friction: Option<f64>,
    /// Compressive strength f_c for every joint, in kPa (overrides the model's materials;
    /// default: the model's, else infinite).
    #[arg(long, value_name = "KPA")]
    pub compressive_strength: Option<f64>,
    /// 3D models: facets of the pyramid inscribed in each friction cone (conservative; the
    /// sliding resistance is between μ·cos(π/K) and μ; default 8).
    #[arg(long, value_name = "K")]
    pub friction_facets: Option<usize>,
    /// 3D models (limit, settle, tilt, capacity): `exact` replaces the inscribed pyramid by the
    /// exact friction cone (a second-order cone program, Clarabel).
    #[arg(long, value_enum, value_name = "CONE")]
    pub friction_cone: Option<FrictionConeArg>,
    /// Existing cracks from a crack survey drawing (DXF), added to the 2D model's cracks
    /// (docs/joint-laws.md, "Existing cracks"): the lines of the survey layers, each with the
    /// width of its label or of its layer's name (CRACK-2mm), read as `identify --survey` reads
    /// them (the "Crack survey drawing" flags).
    #[arg(long = "existing-cracks", value_name = "SURVEY.dxf")]
    pub existing_cracks: Option<PathBuf>,
    #[command(flatten)]
    pub dxf: crate::import::DxfArgs,
    #[command(flatten)]
    pub solver: SolverArgs,
    #[command(flatten)]
    pub survey: SurveyArgs,
}

/// How to read a crack survey drawing (DXF): `identify --survey` (observed cracks) and
/// `--existing-cracks` (a model's existing cracks); docs/identify.md, "A survey drawing".
#[derive(Args, Clone, Debug, Default)]
#[command(next_help_heading = "Crack survey drawing")]
pub struct SurveyArgs {
    /// A survey layer (case-insensitive; PREFIX* for every layer starting with PREFIX;
    /// repeatable) [default: every layer whose name contains CRACK].
    #[arg(long = "survey-layer", value_name = "LAYER")]
    pub layers: Vec<String>,
    /// Units of the survey drawing's coordinates [default: --units, else the drawing's
    /// $INSUNITS, which must then be mm, cm or m].
    #[arg(long = "survey-units", value_enum, ignore_case = true)]
    pub units: Option<crate::import::UnitsArg>,
    /// Unit of a width label written without one ("2") [default: mm].
    #[arg(long = "survey-width-units", value_enum, ignore_case = true)]
    pub width_units: Option<crate::import::UnitsArg>,
    /// A joint point is on a crack line when it is within this distance of it, in m [default:
    /// a quarter of the point's joint length].
    #[arg(long = "survey-snap", value_name = "M")]
    pub snap: Option<f64>,
}

impl SurveyArgs {
    /// Refuse the survey flags without the survey drawing (`file_flag`, e.g. `--survey`), and a
    /// bad snap distance.
    pub fn check(&self, given: bool, file_flag: &str) -> Result<(), Fail> {
        if !given {
            let flag = [
                (!self.layers.is_empty(), "--survey-layer"),
                (self.units.is_some(), "--survey-units"),
                (self.width_units.is_some(), "--survey-width-units"),
                (self.snap.is_some(), "--survey-snap"),
            ]
            .into_iter()
            .find(|(given, _)| *given);
            if let Some((_, f)) = flag {
                return Err(Fail(format!(
                    "{f} applies to a survey drawing: give {file_flag} FILE.dxf"
                )));
            }
        }
        if let Some(d) = self.snap {
            if !(d.is_finite() && d > 0.0) {
                return Err(Fail(format!(
                    "--survey-snap {d}: must be a finite number > 0 (m)"
                )));
            }
        }
        Ok(())
    }

    /// The reading options; `drawing_units` (the `--units` of the command) is the coordinates'
    /// unit unless --survey-units is given.
    pub fn options(
        &self,
        drawing_units: Option<crate::import::UnitsArg>,
    ) -> voussoir_io::survey::SurveyOptions {
        use voussoir_io::dxf::Units;
        voussoir_io::survey::SurveyOptions {
            layers: self.layers.clone(),
            units: self.units.or(drawing_units).map(crate::import::units),
            width_units: self
                .width_units
                .map(crate::import::units)
                .unwrap_or(Units::Mm),
            snap: self.snap,
        }
    }
}

/// The drawing entity of each existing crack read from a drawing (crack layers, a survey), by
/// index in the model's cracks, for messages.
static CRACK_SOURCES: std::sync::Mutex<Vec<(usize, String)>> = std::sync::Mutex::new(Vec::new());

/// Remember the drawing entity of the model's crack `index`.
pub fn note_crack_source(index: usize, entity: String) {
    if let Ok(mut v) = CRACK_SOURCES.lock() {
        v.push((index, entity));
    }
}

/// `msg` with the drawing entity after every `cracks[i]` that came from a drawing.
pub fn annotate_cracks(msg: &str) -> String {
    let mut out = msg.to_string();
    if let Ok(v) = CRACK_SOURCES.lock() {
        for (i, name) in v.iter().rev() {
            out = out.replace(&format!("cracks[{i}]"), &format!("cracks[{i}] ({name})"));
        }
    }
    out
}

/// The friction cone of a 3D joint.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrictionConeArg {
    /// The pyramid of --friction-facets facets inscribed in the cone (an LP).
    Pyramid,
    /// The exact cone (second-order cone program, Clarabel).
    #[value(alias = "cone", alias = "socp")]
    Exact,
}

/// Fewest and most facets of the friction pyramid.
pub const FRICTION_FACETS: std::ops::RangeInclusive<usize> = 3..=1024;

// The LP solver.
#[derive(Args, Clone, Debug)]
#[command(next_help_heading = "Solver")]
pub struct SolverArgs {
    /// LP method [default: the solver policy's (docs/performance.md, "Solver policy"):
    /// dual-simplex for 2D models of up to 2,000 blocks (300 with frictional joints), ipm
    /// (HiGHS's interior point with crossover) above and for 3D models; in 3D, capacity curves
    /// by dual-simplex up to 300 blocks and clarabel above; clarabel for cones and the
    /// non-associative iteration. A method that fails or answers uncertified is followed by
    /// the next of its fallback chain, and the result says so].
    #[arg(long, value_enum, ignore_case = true)]
    pub method: Option<MethodArg>,
}

/// Finite-strength (crushing) model of a limit analysis.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CrushingArg {
    /// Inscribed polygon of the crushing domain with --facets chords: a linear program
    /// (HiGHS), slightly safe.
    #[value(alias = "polygon", alias = "lp")]
    Linear,
    /// The exact crushing cone: a second-order cone program (Clarabel).
    #[value(alias = "cone", alias = "socp", alias = "exact")]
    Conic,
}

/// The finite-strength flags of `limit`, `settle` and `capacity`.
#[derive(clap::Args, Clone, Copy, Debug)]
#[command(next_help_heading = "Joint laws")]
pub struct CrushingArgs {
    /// Finite-strength (crushing) model [default: linear]; matters only where a compressive
    /// strength is given (--compressive-strength or the model's materials): refused elsewhere,
    /// and in 3D.
    #[arg(long, value_enum, ignore_case = true)]
    pub crushing: Option<CrushingArg>,
    /// Facets (chords) of the inscribed crushing polygon of --crushing linear; more facets,
    /// closer to the exact cone [default: 16].
    #[arg(long, value_name = "N")]
    pub facets: Option<usize>,
    /// Non-associative Coulomb friction: joints slide without opening (no dilatancy), by the
    /// fixed-point iteration on the normal forces (docs/joint-laws.md); its convergence is
    /// reported. Matters only where friction is given (--friction or the model's materials).
    #[arg(long)]
    pub non_associative: bool,
}

impl CrushingArgs {
    /// The request's crushing model, as given (`None`: not given).
    pub fn crushing(&self) -> Option<Crushing> {
        self.crushing.map(|c| match c {
            CrushingArg::Linear => Crushing::Linear,
            CrushingArg::Conic => Crushing::Conic,
        })
    }
}

/// Which LPs a settlement analysis solves.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FormArg {
    /// The kinematic LP and the force LP; the certificate compares their optima.
    #[default]
    #[value(alias = "primal-dual")]
    Both,
    /// Only the force LP (3 rows per block); the mechanism from its duals, the certificate from
    /// both sides. For large models, with --method clarabel.
    #[value(alias = "force", alias = "forces-only", alias = "dual-only")]
    ForceOnly,
}

impl FormArg {
    pub fn form(self) -> voussoir::analysis::settlement::SettlementForm {
        match self {
            FormArg::Both => voussoir::analysis::settlement::SettlementForm::Both,
            FormArg::ForceOnly => voussoir::analysis::settlement::SettlementForm::ForceOnly,
        }
    }
}

// `--settlement-form`: only on the commands that run settlement LPs (`settle`, `sweep`).
#[derive(Args, Clone, Debug)]
pub struct FormArgs {
    /// Which programs a settlement analysis solves.
    #[arg(long, value_enum, default_value = "both", ignore_case = true)]
    pub settlement_form: FormArg,
}

// A model input with the settlement form (`sweep`): reads as [`ModelArgs`] (the sweep engine
// uses `a.model.tolerance`, `a.model.solver()`, …) plus [`SettleModelArgs::settlement_form`].
#[derive(Args, Clone, Debug)]
pub struct SettleModelArgs {
    #[command(flatten)]
    pub base: ModelArgs,
    #[command(flatten)]
    pub form: FormArgs,
}

impl std::ops::Deref for SettleModelArgs {
    type Target = ModelArgs;
    fn deref(&self) -> &ModelArgs {
        &self.base
    }
}

impl SettleModelArgs {
    /// The settlement form chosen by `--settlement-form`.
    pub fn settlement_form(&self) -> voussoir::analysis::settlement::SettlementForm {
        self.form.settlement_form.form()
    }
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum MethodArg {
    /// HiGHS dual simplex (default): an exact vertex, so crisp mechanisms and hinges.
    #[value(alias = "dual", alias = "simplex")]
    DualSimplex,
    /// HiGHS primal simplex: an exact vertex too; sometimes faster on settlement LPs.
    #[value(alias = "primal")]
    PrimalSimplex,
    /// HiGHS interior point with crossover to a vertex: for large models.
    #[value(alias = "interior-point", alias = "barrier")]
    Ipm,
    /// HiGHS chooses between simplex and interior point by the problem's size.
    #[value(alias = "auto")]
    Choose,
    /// HiGHS interior point without crossover: faster, the solution may not be a vertex.
    IpmNoCrossover,
    /// HiGHS first-order PDLP: low accuracy, for experiments on very large models.
    Pdlp,
    /// Clarabel's interior point: fastest on large models (see docs/performance.md).
    Clarabel,
    /// Clarabel's interior point, then HiGHS's crossover from its point to an optimal vertex
    /// (measured, not a default: docs/performance.md, "Clarabel with crossover").
    ClarabelVertex,
}

// The support motion of a settlement: moves, fixed supports, a profile.
#[derive(Args, Clone, Debug, Default)]
pub struct SettleArgs {
    /// Prescribed motion of a support: in 2D NAME=u,v[,θ] with u, v in m or with a unit (v up;
    /// `right=0,-5mm`) and θ in degrees counter-clockwise about the support's centroid; in 3D
    /// NAME=u,v,w[,θx,θy,θz] (w up; rotations in degrees, right-handed). Repeatable.
    #[arg(long = "move", value_name = "NAME=U,V[,W|THETA][,...]")]
    pub moves: Vec<String>,
    /// Declare a support `fixed` (bilateral: the blocks on it follow it). Repeatable.
    #[arg(long = "fixed", value_name = "NAME")]
    pub fixed: Vec<String>,
    /// Vertical settlement profile along x: uniform:X0,X1,V | linear:X0,V0,X1,V1 |
    /// table:X,V;X,V;…  (in m, or each with a unit: `uniform:1,3,-5mm`; v up, so a settlement
    /// is < 0). A support that spans a breakpoint (X0, X1, a table's X) is first cut there into
    /// parts NAME@0, NAME@1, … from the left (reported); each support or part then moves by the
    /// profile at its centroid.
    #[arg(long, value_name = "KIND:NUMBERS")]
    pub profile: Option<String>,
    #[command(flatten)]
    pub split: SplitArgs,
}

// `--split`: on every command that takes support motions (settle, capacity, identify, sweep,
// incremental).
#[derive(Args, Clone, Debug, Default)]
pub struct SplitArgs {
    /// Cut support NAME by vertical lines x = X (m or with a unit) into parts NAME@0, NAME@1, …
    /// from the left, before any --move or --fixed (which may then name a part:
    /// `--split base@1.25 --move base@1=0,-1cm`). Repeatable, one per support.
    #[arg(long = "split", value_name = "NAME@X[,X...]")]
    pub splits: Vec<String>,
}

pub use voussoir::settlement_input::SupportSplit;
pub use voussoir_io::motion::signed_length;

impl SettleArgs {
    /// The request's support motion: every `--split`, `--move` and `--profile` parsed by the
    /// library (before any work).
    pub fn motion(&self) -> Result<voussoir::request::SupportMotion, Fail> {
        Ok(voussoir::request::SupportMotion::parse(
            &self.moves,
            &self.fixed,
            self.profile.as_deref(),
            &self.split.splits,
            voussoir::request::Names::Flags,
        )?)
    }
}

/// The supports cut by `--split` or at a profile's breakpoints, for a summary: one line per
/// support, one per part (x range in m, motion in mm and rad).
pub fn split_summary(splits: &[SupportSplit]) -> String {
    let mut s = String::new();
    for sp in splits {
        let cuts: Vec<String> = sp.cuts.iter().map(|c| format!("{c:.4}")).collect();
        let _ = writeln!(
            s,
            "support {} cut at x = {} m into {} parts:",
            sp.support,
            cuts.join(", "),
            sp.parts.len()
        );
        for p in &sp.parts {
            let labels: &[&str] = if p.motion.len() == 3 {
                &["u", "v", "θ"]
            } else {
                &["u", "v", "w", "θx", "θy", "θz"]
            };
            let lengths = if p.motion.len() == 3 { 2 } else { 3 };
            let m: Vec<String> = p
                .motion
                .iter()
                .zip(labels)
                .enumerate()
                .map(|(k, (v, l))| {
                    let kind = if k < lengths {
                        voussoir::lengths::Length::Motion
                    } else {
                        voussoir::lengths::Length::Rotation
                    };
                    format!("{l} {}", kind.show(*v))
                })
                .collect();
            let _ = writeln!(
                s,
                "  {:<12} x {} … {} m  {}",
                p.name,
                voussoir::lengths::Length::Position.number(p.x_range[0]),
                voussoir::lengths::Length::Position.number(p.x_range[1]),
                m.join(", ")
            );
        }
    }
    s
}

/// The model input resolved from the flags: every value checked, before any work.
#[derive(Clone, Debug)]
pub struct Input {
    pub path: PathBuf,
    pub build: BuildOptions,
    pub dxf: crate::import::DxfArgs,
    /// `--existing-cracks`: the survey drawing and how to read it.
    pub existing_cracks: Option<(PathBuf, voussoir_io::survey::SurveyOptions)>,
    /// 3D: the exact friction cone asked for.
    pub exact_friction_cone: bool,
}

impl ModelArgs {
    /// Check every model-input flag: numbers in range; DXF flags only with a `.dxf` model.
    pub fn resolve(&self) -> Result<Input, Fail> {
        self.resolve_with(None)
    }

    /// [`ModelArgs::resolve`]; `identify_survey`: for `identify`, whether its `--survey` was
    /// given (the survey flags are then its, and the model must be sound).
    pub fn resolve_with(&self, identify_survey: Option<bool>) -> Result<Input, Fail> {
        let drawn =
            voussoir_io::dxf::is_dxf(&self.model) || voussoir_io::mesh::is_mesh(&self.model);
        let mut dxf = self.dxf.clone();
        match identify_survey {
            Some(given) => {
                if self.existing_cracks.is_some() || !self.dxf.crack_layers.is_empty() {
                    let f = if self.existing_cracks.is_some() {
                        "--existing-cracks"
                    } else {
                        "--crack-layer"
                    };
                    return Err(Fail(format!(
                        "{f}: identify starts from the sound structure; give the cracks as observations (--survey FILE.dxf --survey-layer LAYER)"
                    )));
                }
                self.survey.check(given, "--survey")?;
            }
            None => {
                self.survey
                    .check(self.existing_cracks.is_some(), "--existing-cracks")?;
                // With a JSON model, --units is the survey drawing's.
                if self.existing_cracks.is_some() && !drawn {
                    dxf.units = None;
                }
            }
        }
        if !drawn && !self.dxf.crack_layers.is_empty() {
            return Err(Fail(format!(
                "--crack-layer reads a layer of a .dxf model, and {} is not one: give the crack survey drawing with --existing-cracks FILE.dxf (--survey-layer LAYER)",
                self.model.display()
            )));
        }
        if let Some(t) = self.tolerance {
            if !(t.is_finite() && t > 0.0) {
                return Err(Fail(format!(
                    "--tolerance {t}: must be a finite number > 0"
                )));
            }
        }
        check_materials(self.friction, self.compressive_strength)?;
        dxf.refuse_foreign(&self.model)?;
        dxf.check()?;
        if let Some(k) = self.friction_facets {
            if !FRICTION_FACETS.contains(&k) {
                return Err(Fail(format!(
                    "--friction-facets {k}: the friction pyramid needs between {} and {} facets",
                    FRICTION_FACETS.start(),
                    FRICTION_FACETS.end()
                )));
            }
            if self.friction_cone == Some(FrictionConeArg::Exact) {
                return Err(Fail(
                    "--friction-facets applies to the pyramid, not to --friction-cone exact".into(),
                ));
            }
        }
        Ok(Input {
            exact_friction_cone: self.friction_cone == Some(FrictionConeArg::Exact),
            path: self.model.clone(),
            build: BuildOptions {
                tolerance: self.tolerance,
            },
            dxf,
            existing_cracks: self
                .existing_cracks
                .clone()
                .map(|p| (p, self.survey.options(self.dxf.units))),
        })
    }

    /// A request for `analysis` with `motion`, the model options and the solver of these
    /// flags; its messages name the flags. Validated.
    pub fn request(
        &self,
        analysis: voussoir::request::Analysis,
        motion: voussoir::request::SupportMotion,
    ) -> Result<voussoir::request::Request, Fail> {
        use voussoir::request::{FrictionCone, ModelOptions, Names, Request, SolverRequest};
        let r = Request {
            model: ModelOptions {
                tolerance: self.tolerance,
                friction: self.friction,
                compressive_strength: self.compressive_strength,
                friction_facets: self.friction_facets,
                friction_cone: self.friction_cone.map(|c| match c {
                    FrictionConeArg::Exact => FrictionCone::Exact,
                    FrictionConeArg::Pyramid => FrictionCone::Pyramid,
                }),
            },
            solver: SolverRequest {
                method: self.solver.method.map(method),
                log: solver_log(),
            },
            motion,
            analysis,
            names: Names::Flags,
        };
        r.validate()?;
        Ok(r)
    }
}

/// The library's method of `--method`.
pub fn method(m: MethodArg) -> Method {
    match m {
        MethodArg::DualSimplex => Method::DualSimplex,
        MethodArg::PrimalSimplex => Method::PrimalSimplex,
        MethodArg::Ipm => Method::Ipm,
        MethodArg::Choose => Method::Choose,
        MethodArg::IpmNoCrossover => Method::IpmNoCrossover,
        MethodArg::Pdlp => Method::Pdlp,
        MethodArg::Clarabel => Method::Clarabel,
        MethodArg::ClarabelVertex => Method::ClarabelVertex,
    }
}

/// Diagnostics: VOUSSOIR_HIGHS_LOG=1 prints the solver's own log on stdout (read here, in the
/// binary; the library takes it as a setting).
fn solver_log() -> bool {
    std::env::var_os("VOUSSOIR_HIGHS_LOG").is_some_and(|v| v == "1")
}

impl SolverArgs {
    /// The solver options of these flags, for the commands not on the request layer yet: the
    /// solver policy's method of a 2D model (`voussoir::request::default_method(2)`) unless
    /// --method says otherwise.
    pub fn options(&self) -> SolverOptions {
        SolverOptions {
            method: self
                .method
                .map(method)
                .unwrap_or(SolverOptions::default().method),
            log: solver_log(),
            ..SolverOptions::default()
        }
    }
}

fn check_materials(friction: Option<f64>, fc: Option<f64>) -> Result<(), Fail> {
    if let Some(mu) = friction {
        if !(mu.is_finite() && mu >= 0.0) {
            return Err(Fail(format!(
                "--friction {mu}: must be a finite number ≥ 0"
            )));
        }
    }
    if let Some(f) = fc {
        if !(f.is_finite() && f > 0.0) {
            return Err(Fail(format!(
                "--compressive-strength {f}: must be a finite number > 0 (kPa)"
            )));
        }
    }
    Ok(())
}

impl Input {
    /// Read a model of either dimension (with `--existing-cracks`), as given: the request
    /// layer applies the material overrides.
    pub fn read_any(&self) -> Result<AnyModel, Fail> {
        let mut m = self.dxf.read_any(&self.path)?.0;
        match &mut m {
            AnyModel::Planar(p) => self.add_existing_cracks(p)?,
            AnyModel::Spatial(_) if self.existing_cracks.is_some() => {
                return Err(Fail(format!(
                    "--existing-cracks applies to 2D models, and {} is a 3D model",
                    self.path.display()
                )))
            }
            AnyModel::Spatial(_) => {}
        }
        Ok(m)
    }

    /// Run a request on a model through the library's one entry (`voussoir::request`): the
    /// model's warnings printed once its structure is built, errors naming the drawing entity
    /// of a crack or a mesh face.
    pub fn run(
        &self,
        model: &AnyModel,
        req: &voussoir::request::Request,
    ) -> Result<voussoir::request::AnyResult, Fail> {
        self.run_with(model, req, &mut voussoir::request::Hooks::default())
    }

    /// [`Input::run`], telling `hooks` of the analysis's progress (a progress bar).
    pub fn run_with(
        &self,
        model: &AnyModel,
        req: &voussoir::request::Request,
        hooks: &mut voussoir::request::Hooks,
    ) -> Result<voussoir::request::AnyResult, Fail> {
        let prepared = self.prepare(model, req)?;
        Ok(voussoir::request::solve_with(prepared, req, hooks)?)
    }

    /// The first half of [`Input::run`]: the request's model options and support motion
    /// applied and the structure built (errors naming the drawing entity of a crack or a mesh
    /// face), the model's warnings printed.
    pub fn prepare(
        &self,
        model: &AnyModel,
        req: &voussoir::request::Request,
    ) -> Result<voussoir::request::Prepared, Fail> {
        let annotate = |e: voussoir::Error| {
            let m = e.to_string();
            Fail(match model {
                AnyModel::Planar(_) => annotate_cracks(&m),
                AnyModel::Spatial(_) => crate::import::annotate_mesh(&m),
            })
        };
        let prepared = voussoir::request::prepare(model, req).map_err(annotate)?;
        let warnings = match &prepared {
            voussoir::request::Prepared::Planar(s) => &s.warnings,
            voussoir::request::Prepared::Spatial(s) => &s.warnings,
        };
        for w in warnings {
            eprintln!("warning: {w}");
        }
        Ok(prepared)
    }

    /// `--existing-cracks`: the survey drawing's crack lines added to the model's cracks
    /// (after its own), each remembered by its entity for messages.
    pub fn add_existing_cracks(&self, m: &mut Model) -> Result<(), Fail> {
        let Some((path, opts)) = &self.existing_cracks else {
            return Ok(());
        };
        crate::outputs::input(path);
        let (cracks, report) = voussoir_io::survey::read_survey(path, opts)
            .map_err(|e| Fail(format!("--existing-cracks {}", e.0)))?;
        eprintln!("existing cracks from {}", report.summary());
        for n in &report.notes {
            eprintln!("note: {n}");
        }
        for (c, line) in cracks.into_iter().zip(report.lines) {
            note_crack_source(
                m.cracks.len(),
                format!("{} of {}", line.entity, path.display()),
            );
            m.cracks.push(voussoir_io::survey::existing_crack(c));
        }
        Ok(())
    }
}

// Output of an analysis: the summary or the JSON result on stdout, the JSON result in a file.
#[derive(Args, Clone, Debug)]
#[command(next_help_heading = "Output")]
pub struct OutArgs {
    /// Print the full result as JSON on stdout instead of the human summary. The rule: stdout
    /// gets the summary, or the JSON with --json; -o writes the JSON to a file in either case
    /// (so `--json -o r.json` gives the same JSON on stdout and in r.json).
    #[arg(long)]
    pub json: bool,
    /// Also write the full JSON result to FILE (read back by `voussoir plot`).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<PathBuf>,
}

impl OutArgs {
    /// `-o FILE` checked before any work: the result is JSON, so a name ending in another
    /// format's extension (`-o r.png`) is refused ([`crate::draw_args::check_format`]).
    pub fn check(&self) -> Result<(), Fail> {
        crate::draw_args::check_format("-o", self.output.as_deref(), &["json"])
    }

    /// The one rule of --json and -o: the file (if any) gets the JSON; stdout gets the JSON with
    /// --json, else the summary.
    /// [`OutArgs::emit`] for a result whose model had supports cut (`--split`, a profile's
    /// breakpoints): the JSON gets `split_supports`, the summary their lines. With none cut,
    /// exactly [`OutArgs::emit`].
    pub fn emit_split<T: Serialize>(
        &self,
        result: &T,
        splits: &[SupportSplit],
        summary: impl Fn() -> String,
    ) -> Result<(), Fail> {
        if splits.is_empty() {
            return self.emit(result, summary);
        }
        self.emit(
            &voussoir_io::motion::WithSplits {
                result,
                split_supports: splits,
            },
            || summary() + &split_summary(splits),
        )
    }

    pub fn emit<T: Serialize>(&self, result: &T, summary: impl Fn() -> String) -> Result<(), Fail> {
        let json = voussoir_io::files::to_json(result)?;
        if let Some(path) = &self.output {
            crate::outputs::stage(path, json.as_bytes())?;
        }
        if self.json {
            out(&json);
        } else {
            out(&summary());
        }
        Ok(())
    }
}

/// Write to stdout; a closed pipe (`voussoir … | head`) ends the output quietly.
pub fn out(text: &str) {
    use std::io::Write;
    let mut o = std::io::stdout().lock();
    let _ = o.write_all(text.as_bytes()).and_then(|_| o.flush());
}

/// The hinges of a result, one line per hinged joint with its hinge points (one in 2D; in 3D
/// one is a pivot, two or more a hinge line), under a heading that counts joints as the
/// figures do ("9 hinged joints") and, where they differ, the points.
fn hinges_section<S: Assembly>(st: &S, heading: &str, hinges: &[Hinge<S::D>]) -> String {
    let mut s = String::new();
    if hinges.is_empty() {
        return s;
    }
    let mut groups: std::collections::BTreeMap<usize, Vec<&Hinge<S::D>>> = Default::default();
    for h in hinges {
        groups.entry(h.joint).or_default().push(h);
    }
    let joints = groups.len();
    let plural = |n: usize, what: &str| format!("{n} {what}{}", if n == 1 { "" } else { "s" });
    let _ = write!(s, "{heading}: {}", plural(joints, "hinged joint"));
    if hinges.len() != joints {
        let _ = write!(s, " ({})", plural(hinges.len(), "hinge point"));
    }
    s.push('\n');
    for (joint, pts) in &groups {
        let (a, b) = st.joint_bodies(*joint);
        let at: Vec<String> = pts
            .iter()
            .map(|h| {
                let c: Vec<String> = <S::D as Spatial>::coords(&h.at)
                    .iter()
                    .map(|x| Length::Position.number(*x))
                    .collect();
                format!("({})", c.join(", "))
            })
            .collect();
        let _ = writeln!(
            s,
            "  joint {:>4} ({} | {}) at {} m",
            joint,
            name(st, a),
            name(st, b),
            at.join(", ")
        );
    }
    s
}

/// Cracks listed in a summary: at most this many lines, then "… and N more".
pub const CRACK_LINES: usize = 10;

/// The cracks of a result, widest first: `crack 1: 2.41 mm wide, 1.30 m long, …` (`widths`:
/// a settlement's widths in mm; otherwise openings relative to the largest), at most
/// [`CRACK_LINES`] lines then "… and N more".
pub fn cracks_section<C: CrackText>(
    heading: &str,
    note: &str,
    cracks: &[C],
    widths: bool,
) -> String {
    let mut s = String::new();
    if cracks.is_empty() {
        return s;
    }
    let largest = cracks.iter().fold(0.0f64, |m, c| m.max(c.max_opening()));
    let _ = writeln!(s, "{heading}: {} ({note})", cracks.len());
    for (i, c) in cracks.iter().take(CRACK_LINES).enumerate() {
        let _ = writeln!(s, "  crack {:>2}: {}", i + 1, c.describe(widths, largest));
    }
    if cracks.len() > CRACK_LINES {
        let _ = writeln!(
            s,
            "  … and {} more (all in the result's \"cracks\")",
            cracks.len() - CRACK_LINES
        );
    }
    // 2D: the longest crack's chord, how steeply it climbs as a whole (first of equal lengths).
    let mut longest: Option<(usize, (f64, f64, f64))> = None;
    for (i, c) in cracks.iter().enumerate() {
        if let Some(ch) = c.chord() {
            if longest.is_none_or(|(_, l)| ch.0 > l.0 * (1.0 + 1e-9)) {
                longest = Some((i, ch));
            }
        }
    }
    if let Some((i, (len, rise, run))) = longest {
        // A run of round-off beside the rise is a vertical crack (the paper arch's crown
        // joint: run 2e-17 m printed "slope 16331239353195370.000" before session 23).
        let slope = if run > 1e-9 * len.max(rise.abs()) {
            format!("slope {:.3}", rise / run)
        } else {
            "vertical".to_string()
        };
        let _ = writeln!(
            s,
            "  longest: crack {}, {} long; its ends rise {} over {} ({slope})",
            i + 1,
            Length::Position.show(len),
            Length::Position.show(rise),
            Length::Position.show(run)
        );
    }
    s
}

/// The prescribed motion of every moving support, one line each, in the summaries' units
/// (README, "Units in the summaries"): translations in cm, rotations in mrad.
pub fn motions_section<S: Assembly>(st: &S) -> String {
    let mut s = String::new();
    for k in 0..st.num_supports() {
        let m = st.support_motion(k);
        if m.iter().all(|x| *x == 0.0) {
            continue;
        }
        // 2D: u, v, θ; 3D: u, v, w, θx, θy, θz.
        let labels: &[&str] = if m.len() == 3 {
            &["u", "v", "θ"]
        } else {
            &["u", "v", "w", "θx", "θy", "θz"]
        };
        let translations = if m.len() == 3 { 2 } else { 3 };
        let parts: Vec<String> = m
            .iter()
            .zip(labels)
            .enumerate()
            .map(|(i, (x, l))| {
                let len = if i < translations {
                    Length::Motion
                } else {
                    Length::Rotation
                };
                format!("{l} {}", len.show(*x))
            })
            .collect();
        let _ = writeln!(
            s,
            "motion   {:>8}: {}",
            st.support_name(k),
            parts.join("  ")
        );
    }
    s
}

fn name<S: Assembly>(st: &S, b: Body) -> String {
    match b {
        Body::Block(i) => i.to_string(),
        Body::Support(k) => st.support_name(k).to_string(),
    }
}

/// The first line of every summary: the structure's size.
pub fn structure_line<S: Assembly>(st: &S) -> String {
    format!(
        "blocks {}, joints {}, supports {}",
        st.num_blocks(),
        st.num_joints(),
        st.num_supports()
    )
}

pub fn limit_summary<S: Assembly>(st: &S, r: &LimitResult<S::D>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", structure_line(st));
    let _ = writeln!(s, "{}", r.message);
    s.push_str(&hinges_section(
        st,
        "hinges of the collapse mechanism",
        &r.hinges,
    ));
    s.push_str(&cracks_section(
        "cracks of the collapse mechanism",
        "openings relative to the largest: a mechanism's amplitude is arbitrary",
        &r.cracks,
        false,
    ));
    s
}

pub fn settle_summary<S: Assembly>(st: &S, r: &SettlementResult<S::D>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", structure_line(st));
    let _ = writeln!(s, "{}", r.message);
    if let (Some(p), Some(d), Some(g)) = (r.work_dead_loads, r.work_reactions, r.duality_gap) {
        let _ = writeln!(
            s,
            "work of dead loads {p:.6e} kN·m, work on supports {d:.6e} kN·m, relative gap {g:.2e}"
        );
    }
    s.push_str(&motions_section(st));
    s.push_str(&hinges_section(st, "hinges", &r.hinges));
    s.push_str(&cracks_section(
        "cracks",
        "widths in mm, widest first",
        &r.cracks,
        true,
    ));
    let open = r
        .joints
        .iter()
        .filter(|j| j.state == voussoir::result::JointState::Open)
        .count();
    if open > 0 {
        let _ = writeln!(s, "fully open joints: {open}");
    }
    for re in &r.reactions {
        let parts: Vec<String> = <S::D as Spatial>::wrench_components(&re.wrench)
            .iter()
            .map(|(label, v, unit)| {
                let v = voussoir::lengths::force(*v, 4, *unit != "kN");
                format!("{label} {v:>10} {unit}")
            })
            .collect();
        let _ = writeln!(s, "reaction {:>8}: {}", re.support, parts.join("  "));
    }
    s
}
