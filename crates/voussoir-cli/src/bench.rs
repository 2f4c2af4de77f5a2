//! `voussoir bench`: flags in, table out. The engine (walls, timings, certificates) is
//! [`voussoir::bench`].

use crate::common::Fail;
use clap::{Args, ValueEnum};
use std::fmt::Write as _;
use voussoir::bench::{self, bench_run, header, line, Analysis, BenchConfig, Scenario};
use voussoir::lp::Method;

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum BenchMethod {
    /// Dual simplex for no-sliding walls up to 2,000 blocks (vertex mechanisms), Clarabel above
    /// and for every frictional or 3D model.
    Auto,
    /// HiGHS dual simplex: an exact vertex.
    DualSimplex,
    /// HiGHS primal simplex: an exact vertex.
    PrimalSimplex,
    /// HiGHS interior point with crossover to a vertex.
    Ipm,
    /// HiGHS interior point without crossover (not a vertex).
    IpmNoCrossover,
    /// HiGHS first-order PDLP (low accuracy).
    Pdlp,
    /// HiGHS chooses by the problem's size.
    Choose,
    /// Clarabel's interior point (direct sparse LDLᵀ factorisation), on the same force LP.
    Clarabel,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum BenchForm {
    /// Force LP only (3 rows per block); the mechanism from its duals.
    Force,
    /// Motion LP only (2 rows per point); the forces from its duals (settlement only).
    Motion,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum BenchAnalysis {
    /// Settlement analyses (prescribed settlement of the wall's base).
    Settle,
    /// Limit analyses (horizontal live load).
    Limit,
    /// Both.
    Both,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum BenchScenario {
    /// 2D running-bond walls, no-sliding joints: the right 40 % of the foundation settles 1 cm
    /// (an optimum of exactly 0); tilting-table load.
    Wall,
    /// 2D running-bond walls with associative friction μ = 0.6: the right third settles 1 cm
    /// (a stepped crack, a non-zero optimum); tilting-table load.
    FrictionWall,
    /// 3D barrel vault (the paper's arch, 64 voussoirs per ring, running bond, μ = 0.6): the
    /// right springing spreads 1 cm; live load on the whole span.
    Vault,
    /// 3D hemispherical dome, c courses of 2c blocks, μ = 0.5: a quarter of its supports settle
    /// 2 cm; a vertical crown load.
    Dome,
    /// 3D U-shaped wall with returns on one ground slab: out-of-plane load on the main wall
    /// (limit only).
    WallReturns,
    /// The models engineers build (the paper's arch, the LACT3 drawings, the façade, the vault,
    /// domes, U walls) × limit, settle, capacity, safety, least-thickness, tilt, each cell the
    /// command as a user runs it, in a child process (docs/performance.md). Alone; takes
    /// --models, --analyses, --max-blocks, --cell-time-limit, --lact3, --workdir, --output and
    /// --method.
    Realistic,
}

#[derive(Args)]
pub struct BenchArgs {
    /// Structures to time, comma-separated.
    #[arg(long, value_enum, default_value = "wall", value_delimiter = ',')]
    pub scenario: Vec<BenchScenario>,
    /// Approximate numbers of blocks, comma-separated.
    #[arg(long, default_value = "1000,4000,16000,64000", value_delimiter = ',')]
    pub sizes: Vec<usize>,
    /// Which analyses to time.
    #[arg(long, value_enum, default_value = "both")]
    pub analysis: BenchAnalysis,
    /// LP method.
    #[arg(long, value_enum, default_value = "auto")]
    pub method: BenchMethod,
    /// Which LP to hand to the solver.
    #[arg(long, value_enum, default_value = "force")]
    pub form: BenchForm,
    /// Switch HiGHS's presolve off.
    #[arg(long)]
    pub no_presolve: bool,
    /// Primal/dual feasibility (and, for Clarabel, gap) tolerance of the solver
    /// (dimensionless).
    #[arg(long, default_value_t = 1e-9, value_name = "TOL")]
    pub solver_tolerance: f64,
    /// Solver time limit per LP, in seconds.
    #[arg(long, value_name = "S")]
    pub time_limit: Option<f64>,
    /// Friction in the limit analyses of 3D models: the inscribed pyramid (LP, the default) or
    /// the exact Coulomb cone (a second-order cone per point, Clarabel).
    #[arg(long, value_enum, default_value = "pyramid")]
    pub friction_cone: crate::common::FrictionConeArg,
    /// Also time structure building and interface detection alone (no solve) at these sizes.
    #[arg(long, value_delimiter = ',', default_value = "100000")]
    pub geometry_sizes: Vec<usize>,
    /// --scenario realistic: the models to run, comma-separated (default: all; names in
    /// docs/performance.md, e.g. arch,lact3-arch,facade-rb-0.5,dome-24x24).
    #[arg(long, value_delimiter = ',')]
    pub models: Option<Vec<String>>,
    /// --scenario realistic: the analyses to run, comma-separated (default: limit, settle,
    /// capacity, safety, least-thickness, tilt).
    #[arg(long, value_delimiter = ',')]
    pub analyses: Option<Vec<String>>,
    /// --scenario realistic: skip (record as skipped) models with more blocks than this.
    #[arg(long, value_name = "N")]
    pub max_blocks: Option<usize>,
    /// --scenario realistic: seconds allowed to each cell; a cell still running then is killed
    /// and recorded as "timed out after S s" [default: 600].
    #[arg(long, value_name = "S")]
    pub cell_time_limit: Option<f64>,
    /// --scenario realistic: --cell-time-limit counts the cell's CPU seconds instead of the
    /// wall clock (on a machine shared with other work, the wall clock measures the others too).
    #[arg(long)]
    pub limit_cpu: bool,
    /// --scenario realistic: the folder of the LACT3 drawings (arch_1.dxf, Portal.dxf, wall.dxf)
    /// [default: crates/voussoir-io/tests/fixtures/lact3 of the repository the command runs in].
    #[arg(long, value_name = "DIR")]
    pub lact3: Option<std::path::PathBuf>,
    /// --scenario realistic: where the models and results of the cells are written [default: a
    /// new folder in the system's temporary directory].
    #[arg(long, value_name = "DIR")]
    pub workdir: Option<std::path::PathBuf>,
    /// --scenario realistic: also write every cell as JSON to FILE.
    #[arg(long, short = 'o', value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

impl BenchArgs {
    /// The engine's configuration from the flags.
    pub fn config(&self) -> BenchConfig {
        let fixed = |m| bench::BenchMethod::Fixed(m);
        BenchConfig {
            method: match self.method {
                BenchMethod::Auto => bench::BenchMethod::Auto,
                BenchMethod::DualSimplex => fixed(Method::DualSimplex),
                BenchMethod::PrimalSimplex => fixed(Method::PrimalSimplex),
                BenchMethod::Ipm => fixed(Method::Ipm),
                BenchMethod::IpmNoCrossover => fixed(Method::IpmNoCrossover),
                BenchMethod::Pdlp => fixed(Method::Pdlp),
                BenchMethod::Choose => fixed(Method::Choose),
                BenchMethod::Clarabel => fixed(Method::Clarabel),
            },
            form: match self.form {
                BenchForm::Force => bench::BenchForm::Force,
                BenchForm::Motion => bench::BenchForm::Motion,
            },
            presolve: !self.no_presolve,
            tolerance: self.solver_tolerance,
            time_limit: self.time_limit,
            exact_cone: self.friction_cone == crate::common::FrictionConeArg::Exact,
        }
    }
}

/// `m`: the bench command's matches (which flags were typed).
pub fn run(a: BenchArgs, m: &clap::ArgMatches) -> Result<(), Fail> {
    if a.scenario.contains(&BenchScenario::Realistic) {
        return run_realistic(a, m);
    }
    for (given, flag) in [
        (a.models.is_some(), "--models"),
        (a.analyses.is_some(), "--analyses"),
        (a.max_blocks.is_some(), "--max-blocks"),
        (a.cell_time_limit.is_some(), "--cell-time-limit"),
        (a.limit_cpu, "--limit-cpu"),
        (a.lact3.is_some(), "--lact3"),
        (a.workdir.is_some(), "--workdir"),
        (a.output.is_some(), "--output"),
    ] {
        if given {
            return Err(Fail(format!(
                "{flag}: applies to --scenario realistic only"
            )));
        }
    }
    println!("Times in seconds; peak memory = the largest resident set of the run; gap = relative duality gap; admissibility = largest joint violation of the mechanism, relative (docs/performance.md).\n");
    print!("{}", header());
    let cfg = a.config();
    let analyses: &[Analysis] = match a.analysis {
        BenchAnalysis::Settle => &[Analysis::Settle],
        BenchAnalysis::Limit => &[Analysis::Limit],
        BenchAnalysis::Both => &[Analysis::Settle, Analysis::Limit],
    };
    for &scenario in &a.scenario {
        let scenario = match scenario {
            BenchScenario::Wall => Scenario::Wall,
            BenchScenario::FrictionWall => Scenario::FrictionWall,
            BenchScenario::Vault => Scenario::Vault,
            BenchScenario::Dome => Scenario::Dome,
            BenchScenario::WallReturns => Scenario::WallReturns,
            BenchScenario::Realistic => unreachable!("run_realistic runs it"),
        };
        for &n in &a.sizes {
            for &analysis in analyses {
                reset_peak_memory();
                match bench_run(scenario, analysis, n, &cfg) {
                    Ok(Some(mut row)) => {
                        row.peak_mib = peak_memory_mib();
                        print!("{}", line(&row));
                    }
                    Ok(None) => {}
                    // A run that fails is a row of the table (what was reached), not the end
                    // of the benchmark.
                    Err(e) => println!(
                        "| {} | {} | ~{n} | | | | | | | | | | | {} | | | failed: {e} |",
                        scenario.name(),
                        match analysis {
                            Analysis::Settle => "settlement",
                            Analysis::Limit => "limit",
                        },
                        peak_memory_mib().map_or("—".into(), |m| format!("{m:.0} MiB"))
                    ),
                }
            }
        }
    }
    if !a.geometry_sizes.is_empty() {
        let mut s = String::from("\nGeometry alone (validation with overlap check, interface detection, kinematic map):\n\n| units | joints | generate | validate + overlap | detect | kinematic map |\n|---:|---:|---:|---:|---:|---:|\n");
        for &n in &a.geometry_sizes {
            let g = bench::bench_geometry(n)?;
            let _ = writeln!(
                s,
                "| {} | {} | {:.3} | {:.3} | {:.3} | {:.3} |",
                g.units, g.joints, g.t_gen, g.t_build, g.t_detect, g.t_map
            );
        }
        print!("{s}");
    }
    Ok(())
}

/// Reset the kernel's record of this process's peak resident set (Linux ≥ 4.0:
/// `/proc/self/clear_refs`, value 5), so that each run's peak is its own. Elsewhere, or where
/// the file cannot be written, the peak is the process's since its start.
fn reset_peak_memory() {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
}

/// The peak resident set (`VmHWM` of `/proc/self/status`), MiB; `None` where there is none.
fn peak_memory_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

/// `--scenario realistic` (crate::bench_realistic): alone, with its own flags; the wall
/// benchmark's flags other than --method are refused.
fn run_realistic(a: BenchArgs, m: &clap::ArgMatches) -> Result<(), Fail> {
    if a.scenario.len() > 1 {
        return Err(Fail(
            "--scenario realistic: runs alone (run the wall scenarios separately)".into(),
        ));
    }
    // Whether each flag was typed, not whether its value differs from the default (session 25:
    // `--sizes 1000,4000,16000,64000` or `--friction-cone pyramid`, the defaults' values,
    // passed where any other value was refused).
    let typed = |id: &str| m.value_source(id) == Some(clap::parser::ValueSource::CommandLine);
    for (id, flag) in [
        ("sizes", "--sizes"),
        ("analysis", "--analysis (use --analyses)"),
        ("form", "--form"),
        ("no_presolve", "--no-presolve"),
        ("solver_tolerance", "--solver-tolerance"),
        ("time_limit", "--time-limit (use --cell-time-limit)"),
        ("friction_cone", "--friction-cone"),
        ("geometry_sizes", "--geometry-sizes"),
    ] {
        if typed(id) {
            return Err(Fail(format!(
                "{flag}: does not apply to --scenario realistic (each cell runs the command with its own defaults)"
            )));
        }
    }
    let method = match a.method {
        BenchMethod::Auto => None,
        m => Some(
            m.to_possible_value()
                .expect("a named method")
                .get_name()
                .to_string(),
        ),
    };
    let cfg = crate::bench_realistic::Config {
        models: a.models,
        analyses: a.analyses,
        max_blocks: a.max_blocks,
        cell_time_limit: a.cell_time_limit.unwrap_or(600.0),
        limit_cpu: a.limit_cpu,
        method,
        lact3: a.lact3,
        workdir: a.workdir,
        output: a.output,
    };
    crate::bench_realistic::run(&cfg).map(|_| ())
}
