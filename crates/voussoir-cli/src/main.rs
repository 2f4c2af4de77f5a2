//! The `voussoir` command: parse flags, call the library, write results. Nothing else.

mod bench;
mod capacity;
mod common;
mod draw_args;
mod gen;
mod identify;
mod import;
mod incremental;
mod plot;
mod sweep;
mod tilt;

use clap::{Parser, Subcommand};
use common::{Fail, ModelArgs, OutArgs, SettleArgs};
use voussoir::analysis::settle;

#[derive(Parser)]
#[command(
    name = "voussoir",
    version,
    about = "Masonry as rigid no-tension blocks in unilateral contact: settlement, limit analysis, capacity.",
    long_about = "Masonry as rigid no-tension blocks in unilateral contact (Heyman's hypotheses).\n\
        Units: metres, kilonewtons, kN/m³, kPa; angles in degrees on the command line.\n\
        Models are JSON files (see the README for the schema); `voussoir gen` writes them."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Generate a model (arch, lintel, wall) as JSON.
    #[command(subcommand)]
    Gen(gen::Gen),
    /// Time the pipeline (generation, detection, assembly, solve, output) on running-bond
    /// walls of growing size.
    Bench(bench::BenchArgs),
    /// Many settlement analyses in parallel: magnitudes, directions or Monte Carlo samples of
    /// the support motions; JSON lines and CSV; --shard I/N for array jobs.
    Sweep(sweep::SweepArgs),
    /// Merge the JSON-lines results of sweep shards.
    Merge(sweep::MergeArgs),
    /// Import a DXF drawing (closed polylines = blocks) as a JSON model.
    Import(import::ImportArgs),
    /// Classic limit analysis: collapse load multiplier λ of the live loads and the mechanism.
    Limit {
        #[command(flatten)]
        model: ModelArgs,
        #[command(flatten)]
        out: OutArgs,
        #[command(flatten)]
        draw: draw_args::DrawArgs,
    },
    /// Settlement analysis: mechanism (crack pattern) and contact forces for prescribed support
    /// motions, by the paper's primal and dual LPs, with the duality gap as a certificate.
    Settle {
        #[command(flatten)]
        model: ModelArgs,
        #[command(flatten)]
        settle: SettleArgs,
        #[command(flatten)]
        out: OutArgs,
        #[command(flatten)]
        draw: draw_args::DrawArgs,
    },
    /// Tilting-table analysis: the critical tilt angle (degrees) at which the structure
    /// collapses when its base is tilted (gravity rotated).
    Tilt(tilt::TiltArgs),
    /// Load capacity after a settlement: λ against the settlement (limit analysis on the
    /// deformed geometry), the settlement at which λ reaches zero, validity of each step.
    Capacity(capacity::CapacityArgs),
    /// Incremental (nonlinear kinematic) analysis: λ against the displacement of a control
    /// point as the mechanism evolves and cracks close.
    Incremental(incremental::IncrementalArgs),
    /// Inverse settlement analysis: the support motions whose settlement mechanism opens the
    /// observed cracks, with misfits, a forward-analysis certificate and identifiability.
    Identify(identify::IdentifyArgs),
    /// Draw a saved result (limit, settlement, capacity, incremental; several curves on one
    /// plot) or a model: `-o fig.svg`, `fig.png` or `report.html`.
    Plot(plot::PlotArgs),
}

fn run(cli: Cli) -> Result<(), Fail> {
    match cli.command {
        Command::Gen(g) => gen::run(g),
        Command::Import(a) => import::run(a),
        Command::Sweep(a) => sweep::run(a),
        Command::Merge(a) => sweep::merge(a),
        Command::Bench(a) => bench::run(a),
        Command::Limit { model, out, draw } => {
            let (st, opts) = model.structure(None)?;
            let r = model.limit(&st, &opts)?;
            draw.emit_limit(&r, &model.model)?;
            out.emit(&r, || common::limit_summary(&st, &r))
        }
        Command::Settle {
            model,
            settle: s,
            out,
            draw,
        } => {
            let (st, opts) = model.structure(Some(&s))?;
            let r = match model.settlement_form() {
                voussoir::analysis::settlement::SettlementForm::Both => settle(&st, &opts)?,
                form => voussoir::analysis::settlement::settle_with(&st, &opts, form)?,
            };
            draw.emit_settlement(&r, &model.model)?;
            out.emit(&r, || common::settle_summary(&st, &r))
        }
        Command::Capacity(a) => capacity::run(a),
        Command::Incremental(a) => incremental::run(a),
        Command::Plot(a) => plot::run(a),
        Command::Tilt(a) => tilt::run(a),
        Command::Identify(a) => identify::run(a),
    }
}

fn main() {
    let cli = Cli::parse();
    if let Err(e) = run(cli) {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
