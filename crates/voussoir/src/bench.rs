//! The benchmark engine behind `voussoir bench`: timings of the whole pipeline on structures
//! of growing size ([`Scenario`]: the no-sliding and the frictional running-bond walls in 2D, a
//! barrel vault, a dome and a wall with returns in 3D), one engine for both dimensions (generic
//! over [`Assembly`]). The command line parses flags, measures memory and prints; the work is
//! here, so any front end can run it.
//!
//! The walls are of 0.25 × 0.055 m bricks with about twice as many units per course as
//! courses, on one foundation segment per base unit. Two analyses:
//! * settlement: the foundation segments under the right 40 % of the wall (a third with
//!   friction) settle uniformly by 1 cm;
//! * limit: the tilting-table live load (a horizontal force equal to each block's weight).
//!
//! Phases are timed separately: model generation, structure building (validation and overlap
//! check), interface detection (timed on its own, on the same polygons), assembly (kinematic
//! map and LP, by the builders of [`crate::programs`]), solve, and output (result with joints
//! and hinges, serialised to JSON). Every run reports its certificate: the relative duality
//! gap, and the admissibility of the mechanism and the equilibrium of the forces.

use crate::analysis::limit::{limit_result, limit_solution};
use crate::analysis::settlement::{
    kinematic_violation, settlement_from_force_solution, settlement_result_checked,
    SettlementStatus,
};
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::generate::{self, LiveLoad, WallSpec};
use crate::lp::{LpStatus, Method, SolverOptions};
use crate::programs;
use crate::settlement_input::{apply_profile, Profile};
use crate::structure::Assembly;
use crate::{BuildOptions, Structure};
use std::time::Instant;

/// How the benchmark picks the LP method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BenchMethod {
    /// Dual simplex for no-sliding models up to 2,000 blocks (vertex mechanisms), Clarabel
    /// above and for every frictional model (the simplex took 47 s on the 979-unit friction
    /// wall that Clarabel settles in 1 s).
    Auto,
    Fixed(Method),
}

/// Which LP of a settlement analysis the benchmark hands to the solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BenchForm {
    /// Force LP only (3 rows per block); the mechanism from its duals.
    Force,
    /// Motion LP only (2 rows per point); the forces from its duals (settlement only).
    Motion,
}

/// Benchmark settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BenchConfig {
    pub method: BenchMethod,
    pub form: BenchForm,
    pub presolve: bool,
    /// Primal/dual feasibility (and, for Clarabel, gap) tolerance of the solver.
    pub tolerance: f64,
    /// Solver time limit per LP, seconds.
    pub time_limit: Option<f64>,
    /// Limit analyses of frictional 3D models with the exact Coulomb cone (a second-order cone
    /// per point, Clarabel) instead of the inscribed pyramid.
    pub exact_cone: bool,
}

impl Default for BenchConfig {
    fn default() -> Self {
        BenchConfig {
            method: BenchMethod::Auto,
            form: BenchForm::Force,
            presolve: true,
            tolerance: 1e-9,
            time_limit: None,
            exact_cone: false,
        }
    }
}

/// A wall of about `n` units: `c` courses of `2c` units.
pub fn wall_of(n: usize, live: LiveLoad) -> WallSpec {
    let c = ((n as f64 / 2.0).sqrt().round() as usize).max(1);
    WallSpec {
        courses: c,
        units: 2 * c,
        unit: [0.25, 0.055],
        live,
        ..WallSpec::default()
    }
}

fn method_for(m: BenchMethod, blocks: usize, frictional: bool) -> Method {
    match m {
        BenchMethod::Auto => {
            if blocks <= 2000 && !frictional {
                Method::DualSimplex
            } else {
                Method::Clarabel
            }
        }
        BenchMethod::Fixed(m) => m,
    }
}

fn method_name(m: Method) -> &'static str {
    match m {
        Method::DualSimplex => "dual simplex",
        Method::PrimalSimplex => "primal simplex",
        Method::Ipm => "IPM + crossover",
        Method::IpmNoCrossover => "IPM",
        Method::Pdlp => "PDLP",
        Method::Choose => "HiGHS choice",
        Method::Clarabel => "Clarabel IPM",
        Method::ClarabelVertex => "Clarabel IPM + crossover",
    }
}

/// One timed run.
#[derive(Debug)]
pub struct Row {
    pub scenario: &'static str,
    pub analysis: &'static str,
    pub units: usize,
    pub joints: usize,
    pub rows: usize,
    pub cols: usize,
    pub nnz: usize,
    pub method: String,
    pub t_gen: f64,
    pub t_build: f64,
    /// Interface detection alone (2D; in 3D it is part of `t_build`).
    pub t_detect: Option<f64>,
    pub t_assemble: f64,
    pub t_solve: f64,
    pub t_output: f64,
    pub gap: f64,
    pub violation: f64,
    pub outcome: String,
    /// Peak resident memory of the run, MiB (measured by the front end: the library does no
    /// I/O).
    pub peak_mib: Option<f64>,
}

impl Row {
    pub fn total(&self) -> f64 {
        self.t_gen + self.t_build + self.t_assemble + self.t_solve + self.t_output
    }
}

fn secs(t: Instant) -> f64 {
    t.elapsed().as_secs_f64()
}

pub fn time_detection(st: &Structure) -> f64 {
    let polys: Vec<&[[f64; 2]]> = st
        .blocks
        .iter()
        .map(|b| b.polygon.as_slice())
        .chain(st.supports.iter().map(|s| s.polygon.as_slice()))
        .collect();
    let t = Instant::now();
    let (ifs, _) = crate::geometry::detect_interfaces(&polys, st.tolerance);
    std::hint::black_box(ifs.len());
    secs(t)
}

/// The benchmark structures of `voussoir bench --scenario` (issue 18, item 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scenario {
    /// (a) Running-bond walls with Heyman's no-sliding joints: settlement of the right 40 %
    /// of the foundation (an optimum of exactly 0: the bond bridges it) and the tilting-table
    /// load.
    Wall,
    /// (b) The same walls with associative Coulomb friction μ = 0.6 and the right third of the
    /// foundation settling 1 cm: a non-zero optimum (a stepped crack); limit under the same
    /// tilting-table load.
    FrictionWall,
    /// (c) The paper's arch as a barrel vault of 64 voussoirs per ring, as many rings (running
    /// bond, μ = 0.6) as the size asks: the right springing spreads 1 cm; limit under the live
    /// load on the whole span.
    Vault,
    /// (c) A hemispherical dome (R = 5 m, t = 0.3 m) of `c` courses of `2c` blocks on one
    /// support per segment, μ = 0.5: the supports of a quarter of the ring settle 2 cm; limit
    /// under a vertical crown load.
    Dome,
    /// (c) A U-shaped wall (main wall and two returns, bonded at the corners) on one ground
    /// slab: limit under an out-of-plane load on the main wall (settlement: one support only,
    /// nothing to settle relative to).
    WallReturns,
}

impl Scenario {
    pub fn name(self) -> &'static str {
        match self {
            Scenario::Wall => "wall",
            Scenario::FrictionWall => "friction wall",
            Scenario::Vault => "vault",
            Scenario::Dome => "dome",
            Scenario::WallReturns => "wall with returns",
        }
    }
}

/// Which analysis of a benchmark run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Analysis {
    Settle,
    Limit,
}

/// A generated model of about `n` blocks for `scenario` and `analysis`, with its settlement
/// applied; `None` when the scenario has no such analysis.
enum Built {
    Planar(crate::Model),
    Spatial(crate::model3d::Model3d),
}

fn build_model(scenario: Scenario, analysis: Analysis, n: usize) -> Result<Option<Built>> {
    use crate::generate3d::{self, Bond, DomeSpec, Plan, WallsLive, WallsSpec};
    use crate::settlement_input::move_support;
    let settle = analysis == Analysis::Settle;
    Ok(Some(match scenario {
        Scenario::Wall | Scenario::FrictionWall => {
            let friction = scenario == Scenario::FrictionWall;
            let live = if settle {
                LiveLoad::None
            } else {
                LiveLoad::Horizontal
            };
            let spec = wall_of(n, live);
            let mut model = generate::wall(&spec)?;
            if friction {
                model
                    .materials
                    .entry("default".into())
                    .or_default()
                    .friction = Some(0.6);
            }
            if settle {
                let width = spec.units as f64 * spec.unit[0];
                let x0 = if friction { 2.0 / 3.0 } else { 0.6 } * width;
                apply_profile(
                    &mut model,
                    &Profile::Uniform {
                        x0,
                        x1: width,
                        v: -0.01,
                    },
                )?;
            }
            Built::Planar(model)
        }
        Scenario::Vault => {
            let spec = generate::ArchSpec {
                voussoirs: 64,
                live: if settle {
                    LiveLoad::None
                } else {
                    LiveLoad::Full
                },
                ..generate::ArchSpec::default()
            };
            let rings = n.div_ceil(64).max(1);
            // Rings 0.5 m deep: the vault's depth grows with the size.
            let mut m = generate3d::vault(&spec, 0.5 * rings as f64, rings, Bond::Running)?;
            // With Heyman's no-sliding joints a running bond locks the rings together (no
            // collapse load); with friction they can slide on each other.
            m.materials.entry("default".into()).or_default().friction = Some(0.6);
            if settle {
                move_support(&mut m, "right", &[0.01, 0.0, 0.0, 0.0, 0.0, 0.0])?;
            }
            Built::Spatial(m)
        }
        Scenario::Dome => {
            let c = ((n as f64 / 2.0).sqrt().round() as usize).max(2);
            let spec = DomeSpec {
                courses: c,
                segments: 2 * c,
                crown_load: if settle { 0.0 } else { 10.0 },
                ..DomeSpec::default()
            };
            let mut m = generate3d::dome(&spec)?;
            m.materials.entry("default".into()).or_default().friction = Some(0.5);
            if settle {
                for j in 0..(2 * c).div_ceil(4) {
                    move_support(
                        &mut m,
                        &format!("base{j}"),
                        &[0.0, 0.0, -0.02, 0.0, 0.0, 0.0],
                    )?;
                }
            }
            Built::Spatial(m)
        }
        Scenario::WallReturns => {
            if settle {
                return Ok(None);
            }
            // 2c courses of a main wall of 2c units and two returns of c: about 8c² blocks.
            let c = ((n as f64 / 8.0).sqrt().round() as usize).max(2);
            let u = 2 * c;
            let spec = WallsSpec {
                plan: Plan::U,
                length: 0.25 * u as f64,
                return_length: 0.125 * u as f64,
                height: 0.055 * c as f64 * 2.0,
                thickness: 0.12,
                courses: 2 * c,
                units: u,
                live: WallsLive::Main,
                ..WallsSpec::default()
            };
            Built::Spatial(generate3d::walls(&spec)?)
        }
    }))
}

/// Time one analysis of a `scenario` structure of about `n` blocks; `None` when the scenario
/// has no such analysis.
pub fn bench_run(
    scenario: Scenario,
    analysis: Analysis,
    n: usize,
    a: &BenchConfig,
) -> Result<Option<Row>> {
    let t = Instant::now();
    let Some(model) = build_model(scenario, analysis, n)? else {
        return Ok(None);
    };
    let t_gen = secs(t);
    let t = Instant::now();
    let mut row = match model {
        Built::Planar(m) => {
            let st = Structure::new(&m, BuildOptions::default())?;
            let t_build = secs(t);
            let t_detect = time_detection(&st);
            let phases = (t_gen, t_build - t_detect.min(t_build), Some(t_detect));
            run_on(&st, analysis, phases, scenario != Scenario::Wall, a)?
        }
        Built::Spatial(m) => {
            let st = crate::Structure3d::new(&m, BuildOptions::default())?;
            run_on(&st, analysis, (t_gen, secs(t), None), true, a)?
        }
    };
    row.scenario = scenario.name();
    Ok(Some(row))
}

fn run_on<S: Assembly>(
    st: &S,
    analysis: Analysis,
    phases: (f64, f64, Option<f64>),
    frictional: bool,
    a: &BenchConfig,
) -> Result<Row> {
    let method = method_for(a.method, st.num_blocks(), frictional);
    let opts = SolverOptions {
        method,
        presolve: a.presolve,
        feasibility_tolerance: a.tolerance,
        time_limit: a.time_limit,
        ..SolverOptions::default()
    };
    let mut row = match analysis {
        Analysis::Settle => settle_on(st, a, &opts)?,
        Analysis::Limit => limit_on(st, &opts, a.exact_cone)?,
    };
    row.method = method_name(method).to_string();
    (row.t_gen, row.t_build, row.t_detect) = phases;
    Ok(row)
}

fn empty_row<S: Assembly>(st: &S, analysis: &'static str) -> Row {
    Row {
        scenario: "",
        analysis,
        units: st.num_blocks(),
        joints: st.num_joints(),
        rows: 0,
        cols: 0,
        nnz: 0,
        method: String::new(),
        t_gen: 0.0,
        t_build: 0.0,
        t_detect: None,
        t_assemble: 0.0,
        t_solve: 0.0,
        t_output: 0.0,
        gap: f64::NAN,
        violation: f64::NAN,
        outcome: String::new(),
        peak_mib: None,
    }
}

fn settle_on<S: Assembly>(st: &S, a: &BenchConfig, opts: &SolverOptions) -> Result<Row> {
    let mut row = empty_row(st, "settlement");
    let u = st.settlement_magnitude();
    let t = Instant::now();
    let map = KinematicMap::new(st);
    let dead = st.load_vector(false);
    let s = match a.form {
        BenchForm::Force => {
            let fp = programs::settlement_force_program(&map, &dead);
            row.t_assemble = secs(t);
            (row.rows, row.cols, row.nnz) =
                (fp.lp.num_rows(), fp.lp.num_cols(), fp.lp.num_nonzeros());
            let t = Instant::now();
            let sol = fp.solve(opts)?;
            row.t_solve = secs(t);
            settlement_from_force_solution(st, &map, &fp, &sol, opts.info())
        }
        BenchForm::Motion => {
            let mp = programs::settlement_motion_program(&map, &dead)?;
            row.t_assemble = secs(t);
            (row.rows, row.cols, row.nnz) =
                (mp.lp.num_rows(), mp.lp.num_cols(), mp.lp.num_nonzeros());
            let t = Instant::now();
            let sol = crate::lp::solve(&mp.lp, opts)?;
            row.t_solve = secs(t);
            // Forces from the motion LP's duals are not mapped back here: the motion form is
            // timed only (its certificate is the full two-LP settle run).
            let status = match sol.status {
                LpStatus::Optimal => SettlementStatus::Mechanism,
                LpStatus::Unbounded => SettlementStatus::CannotStand,
                LpStatus::Infeasible => SettlementStatus::Incompatible,
            };
            let np = map.num_points();
            crate::analysis::settlement::SettlementSolution {
                status,
                mechanism: if status == SettlementStatus::Mechanism {
                    mp.motion(&sol.x)
                } else {
                    vec![]
                },
                pn: vec![0.0; np],
                pt: vec![0.0; np],
                primal: mp.objective_sign * sol.objective,
                dual: f64::NAN,
                solver: opts.info(),
            }
        }
    };
    let t = Instant::now();
    let r = settlement_result_checked(st, &map, &s);
    let json = serde_json::to_string_pretty(&r)
        .map_err(|e| Error::Request(format!("cannot serialise the result: {e}")))?;
    std::hint::black_box(json.len());
    row.t_output = secs(t);
    row.violation = if s.mechanism.is_empty() {
        f64::NAN
    } else {
        kinematic_violation(&map, &s.mechanism, 1.0) / u
    };
    // |primal − dual| relative to the larger of the two and of the work scale W·u (total
    // weight times the settlement): where the optimum is 0 (scenario (a): the wall bridges the
    // settled segments) a gap relative to the values alone measures round-off.
    let w: f64 = dead.iter().map(|f| f.abs()).sum();
    row.gap = (s.primal - s.dual).abs() / s.primal.abs().max(s.dual.abs()).max(w * u);
    row.outcome = format!(
        "{:?}, work {:.6e} kN·m",
        r.status,
        r.work_dead_loads.unwrap_or(f64::NAN)
    );
    Ok(row)
}

/// The certificate is the result's own ([`crate::result::LimitCertificate`]): λ of the static
/// LP against the kinematic multiplier `−F_D·d` of the mechanism read from its duals, and the
/// mechanism's admissibility relative to its largest opening.
fn limit_on<S: Assembly>(st: &S, opts: &SolverOptions, exact_cone: bool) -> Result<Row> {
    let mut row = empty_row(st, "limit");
    let t = Instant::now();
    let map = KinematicMap::new(st);
    let dead = st.load_vector(false);
    let live = st.load_vector(true);
    let fp = if exact_cone {
        programs::limit_force_program_exact(&map, &dead, &live)
    } else {
        programs::limit_force_program(&map, &dead, &live)
    };
    row.t_assemble = secs(t);
    (row.rows, row.cols, row.nnz) = (fp.lp.num_rows(), fp.lp.num_cols(), fp.lp.num_nonzeros());
    let t = Instant::now();
    let sol = fp.solve(opts)?;
    row.t_solve = secs(t);
    let t = Instant::now();
    let ls = limit_solution(&map, &fp, &live, &sol, opts.info());
    let (status, lambda) = (ls.status, ls.lambda);
    let r = limit_result(st, &map, &ls);
    let json = serde_json::to_string_pretty(&r)
        .map_err(|e| Error::Request(format!("cannot serialise the result: {e}")))?;
    std::hint::black_box(json.len());
    row.t_output = secs(t);
    if let Some(c) = &r.certificate {
        (row.gap, row.violation) = (c.gap, c.admissibility);
    }
    row.outcome = match lambda {
        Some(l) => format!("λ = {l:.6}"),
        None => format!("{status:?}"),
    };
    Ok(row)
}

pub fn header() -> String {
    "| structure | analysis | blocks | joints | LP rows × cols (nnz) | method | generate | validate | detect | assemble | solve | output | total | peak memory | gap | admissibility | result |\n\
     |---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n"
        .to_string()
}

pub fn line(r: &Row) -> String {
    let detect = r
        .t_detect
        .map_or("(in validate)".to_string(), |t| format!("{t:.3}"));
    let peak = r
        .peak_mib
        .map_or("—".to_string(), |m| format!("{m:.0} MiB"));
    format!(
        "| {} | {} | {} | {} | {} × {} ({}) | {} | {:.3} | {:.3} | {} | {:.3} | {:.2} | {:.3} | {:.2} | {} | {:.1e} | {:.1e} | {} |\n",
        r.scenario,
        r.analysis,
        r.units,
        r.joints,
        r.rows,
        r.cols,
        r.nnz,
        r.method,
        r.t_gen,
        r.t_build,
        detect,
        r.t_assemble,
        r.t_solve,
        r.t_output,
        r.total(),
        peak,
        r.gap,
        r.violation,
        r.outcome
    )
}

/// Times of the geometry phases alone at one size (no solve).
pub struct GeometryRow {
    pub units: usize,
    pub joints: usize,
    pub t_gen: f64,
    pub t_build: f64,
    pub t_detect: f64,
    pub t_map: f64,
}

/// Generate, validate (with the overlap check), detect interfaces and assemble the kinematic
/// map of a wall of about `n` units.
pub fn bench_geometry(n: usize) -> Result<GeometryRow> {
    let t = Instant::now();
    let model = generate::wall(&wall_of(n, LiveLoad::None))?;
    let t_gen = secs(t);
    let t = Instant::now();
    let st = Structure::new(&model, BuildOptions::default())?;
    let t_build = secs(t);
    let t_detect = time_detection(&st);
    let t = Instant::now();
    let map = KinematicMap::new(&st);
    std::hint::black_box(map.num_points());
    let t_map = secs(t);
    Ok(GeometryRow {
        units: st.blocks.len(),
        joints: st.joints.len(),
        t_gen,
        t_build: t_build - t_detect.min(t_build),
        t_detect,
        t_map,
    })
}
