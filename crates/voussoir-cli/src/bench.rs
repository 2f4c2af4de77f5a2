//! `voussoir bench`: flags in, table out. The engine (walls, timings, certificates) is
//! [`voussoir::bench`].

use crate::common::Fail;
use clap::{Args, ValueEnum};
use std::fmt::Write as _;
use voussoir::bench::{self, bench_limit, bench_settle, header, line, BenchConfig};
use voussoir::lp::Method;

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq)]
pub enum BenchMethod {
    /// Per size: dual simplex up to 2,000 blocks (vertex mechanisms), Clarabel above.
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

#[derive(Args)]
pub struct BenchArgs {
    /// Approximate numbers of units, comma-separated.
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
    /// Also time structure building and interface detection alone (no solve) at these sizes.
    #[arg(long, value_delimiter = ',', default_value = "100000")]
    pub geometry_sizes: Vec<usize>,
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
        }
    }
}

pub fn run(a: BenchArgs) -> Result<(), Fail> {
    println!("Running-bond walls of 0.25 × 0.055 m units (times in seconds; gap = relative duality gap; admissibility = largest joint violation of the mechanism, relative).\n");
    print!("{}", header());
    let cfg = a.config();
    for &n in &a.sizes {
        if matches!(a.analysis, BenchAnalysis::Settle | BenchAnalysis::Both) {
            print!("{}", line(&bench_settle(n, &cfg)?));
        }
        if matches!(a.analysis, BenchAnalysis::Limit | BenchAnalysis::Both) {
            print!("{}", line(&bench_limit(n, &cfg)?));
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
