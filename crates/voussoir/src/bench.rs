//! The benchmark engine behind `voussoir bench`: timings of the whole pipeline on running-bond
//! walls of growing size. The command line parses flags and prints; the work is here, so any
//! front end can run it.
//!
//! Each size is a wall of 0.25 × 0.055 m bricks with about twice as many units per course as
//! courses, on one foundation segment per base unit. Two analyses:
//! * settlement: the foundation segments under the right 40 % of the wall settle uniformly by
//!   1 cm;
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
use crate::{BuildOptions, Structure};
use std::time::Instant;

/// How the benchmark picks the LP method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BenchMethod {
    /// Per size: dual simplex up to 2,000 blocks (vertex mechanisms), Clarabel above.
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
}

impl Default for BenchConfig {
    fn default() -> Self {
        BenchConfig {
            method: BenchMethod::Auto,
            form: BenchForm::Force,
            presolve: true,
            tolerance: 1e-9,
            time_limit: None,
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

fn method_for(m: BenchMethod, blocks: usize) -> Method {
    match m {
        BenchMethod::Auto => {
            if blocks <= 2000 {
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
    }
}

/// One timed run.
pub struct Row {
    pub analysis: &'static str,
    pub units: usize,
    pub joints: usize,
    pub rows: usize,
    pub cols: usize,
    pub nnz: usize,
    pub method: String,
    pub t_gen: f64,
    pub t_build: f64,
    pub t_detect: f64,
    pub t_assemble: f64,
    pub t_solve: f64,
    pub t_output: f64,
    pub gap: f64,
    pub violation: f64,
    pub outcome: String,
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

/// Build and validate the structure (timed), time its interface detection alone, and choose
/// the solver settings for its size.
fn prepare(
    model: &crate::Model,
    a: &BenchConfig,
) -> Result<(Structure, f64, f64, Method, SolverOptions)> {
    let t = Instant::now();
    let st = Structure::new(model, BuildOptions::default())?;
    let t_build = secs(t);
    let t_detect = time_detection(&st);
    let method = method_for(a.method, st.blocks.len());
    let opts = SolverOptions {
        method,
        presolve: a.presolve,
        feasibility_tolerance: a.tolerance,
        time_limit: a.time_limit,
        ..SolverOptions::default()
    };
    Ok((st, t_build, t_detect, method, opts))
}

/// Time one settlement analysis of a wall of about `n` units.
pub fn bench_settle(n: usize, a: &BenchConfig) -> Result<Row> {
    let t = Instant::now();
    let spec = wall_of(n, LiveLoad::None);
    let mut model = generate::wall(&spec)?;
    let t_gen = secs(t);
    let width = spec.units as f64 * spec.unit[0];
    apply_profile(
        &mut model,
        &Profile::Uniform {
            x0: 0.6 * width,
            x1: width,
            v: -0.01,
        },
    )?;
    let (st, t_build, t_detect, method, opts) = prepare(&model, a)?;
    let t = Instant::now();
    let map = KinematicMap::new(&st);
    let (s, lp_size, t_assemble, t_solve) = match a.form {
        BenchForm::Force => {
            let fp = programs::settlement_force_program(&map, &st.load_vector(false));
            let t_assemble = secs(t);
            let size = (fp.lp.num_rows(), fp.lp.num_cols(), fp.lp.num_nonzeros());
            let t = Instant::now();
            let sol = fp.solve(&opts)?;
            let t_solve = secs(t);
            (
                settlement_from_force_solution(&st, &map, &fp, &sol, opts.info()),
                size,
                t_assemble,
                t_solve,
            )
        }
        BenchForm::Motion => {
            let dead = st.load_vector(false);
            let mp = programs::settlement_motion_program(&map, &dead)?;
            let t_assemble = secs(t);
            let size = (mp.lp.num_rows(), mp.lp.num_cols(), mp.lp.num_nonzeros());
            let t = Instant::now();
            let sol = crate::lp::solve(&mp.lp, &opts)?;
            let t_solve = secs(t);
            // Forces from the motion LP's duals are not mapped back here: the motion form is timed
            // only (its certificate is the full two-LP settle run).
            let status = match sol.status {
                LpStatus::Optimal => SettlementStatus::Mechanism,
                LpStatus::Unbounded => SettlementStatus::CannotStand,
                LpStatus::Infeasible => SettlementStatus::Incompatible,
            };
            let np = map.num_points();
            let s = crate::analysis::settlement::SettlementSolution {
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
            };
            (s, size, t_assemble, t_solve)
        }
    };
    let t = Instant::now();
    let r = settlement_result_checked(&st, &map, &s);
    let json = serde_json::to_string_pretty(&r)
        .map_err(|e| Error::Request(format!("cannot serialise the result: {e}")))?;
    std::hint::black_box(json.len());
    let t_output = secs(t);
    let violation = if s.mechanism.is_empty() {
        f64::NAN
    } else {
        kinematic_violation(&map, &s.mechanism) / 0.01
    };
    Ok(Row {
        analysis: "settlement",
        units: st.blocks.len(),
        joints: st.joints.len(),
        rows: lp_size.0,
        cols: lp_size.1,
        nnz: lp_size.2,
        method: method_name(method).to_string(),
        t_gen,
        t_build: t_build - t_detect.min(t_build),
        t_detect,
        t_assemble,
        t_solve,
        t_output,
        // |primal − dual| relative to the larger of the two and of the work scale W·u (total
        // weight times the settlement): the optimum here is 0 (the wall bridges the settled
        // segments), where a gap relative to the values alone measures round-off.
        gap: {
            let w: f64 = st.blocks.iter().map(|b| b.weight).sum();
            (s.primal - s.dual).abs() / s.primal.abs().max(s.dual.abs()).max(w * 0.01)
        },
        violation,
        outcome: format!(
            "{:?}, work {:.3e} kN·m",
            r.status,
            r.work_dead_loads.unwrap_or(f64::NAN)
        ),
    })
}

/// Time one limit analysis (tilting-table load) of a wall of about `n` units. The certificate:
/// λ of the static LP against the kinematic multiplier `−F_D·d` of the mechanism read from its
/// duals (normalised to `F_L·d = 1`), and the mechanism's admissibility.
pub fn bench_limit(n: usize, a: &BenchConfig) -> Result<Row> {
    let t = Instant::now();
    let spec = wall_of(n, LiveLoad::Horizontal);
    let model = generate::wall(&spec)?;
    let t_gen = secs(t);
    let (st, t_build, t_detect, method, opts) = prepare(&model, a)?;
    let t = Instant::now();
    let map = KinematicMap::new(&st);
    let dead = st.load_vector(false);
    let live = st.load_vector(true);
    let fp = programs::limit_force_program(&map, &dead, &live);
    let t_assemble = secs(t);
    let t = Instant::now();
    let sol = fp.solve(&opts)?;
    let t_solve = secs(t);
    let t = Instant::now();
    let ls = limit_solution(&map, &fp, &live, &sol, opts.info());
    let (status, lambda, mechanism) = (ls.status, ls.lambda, ls.mechanism.clone());
    let r = limit_result(&st, &map, &ls);
    let json = serde_json::to_string_pretty(&r)
        .map_err(|e| Error::Request(format!("cannot serialise the result: {e}")))?;
    std::hint::black_box(json.len());
    let t_output = secs(t);
    let (gap, violation) = match lambda {
        Some(l) if !mechanism.is_empty() => {
            let kin: f64 = -dead.iter().zip(&mechanism).map(|(f, d)| f * d).sum::<f64>();
            // Admissibility relative to the mechanism's size (largest point displacement).
            let (open, _) = map.jumps(&mechanism, 0.0);
            let scale = open.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(1e-300);
            let mut v = 0.0f64;
            let (o, s) = map.jumps(&mechanism, 0.0);
            for k in 0..map.num_points() {
                v = v.max((-o[k]).max(0.0)).max(s[k].abs());
            }
            ((l - kin).abs() / l.abs().max(1e-12), v / scale)
        }
        _ => (f64::NAN, f64::NAN),
    };
    Ok(Row {
        analysis: "limit",
        units: st.blocks.len(),
        joints: st.joints.len(),
        rows: fp.lp.num_rows(),
        cols: fp.lp.num_cols(),
        nnz: fp.lp.num_nonzeros(),
        method: method_name(method).to_string(),
        t_gen,
        t_build: t_build - t_detect.min(t_build),
        t_detect,
        t_assemble,
        t_solve,
        t_output,
        gap,
        violation,
        outcome: match lambda {
            Some(l) => format!("λ = {l:.6}"),
            None => format!("{status:?}"),
        },
    })
}

pub fn header() -> String {
    "| analysis | units | joints | LP rows × cols (nnz) | method | generate | validate | detect | assemble | solve | output | total | gap | admissibility | result |\n\
     |---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n"
        .to_string()
}

pub fn line(r: &Row) -> String {
    format!(
        "| {} | {} | {} | {} × {} ({}) | {} | {:.3} | {:.3} | {:.3} | {:.3} | {:.2} | {:.3} | {:.2} | {:.1e} | {:.1e} | {} |\n",
        r.analysis,
        r.units,
        r.joints,
        r.rows,
        r.cols,
        r.nnz,
        r.method,
        r.t_gen,
        r.t_build,
        r.t_detect,
        r.t_assemble,
        r.t_solve,
        r.t_output,
        r.total(),
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
