//! The `voussoir` command: parse flags, call the library, write results. Nothing else.

mod adapt_args;
mod bench;
mod bench_realistic;
mod canonical;
mod capacity;
mod common;
mod direction;
mod draw_args;
mod gen;
mod identify;
mod import;
mod incremental;
mod limit;
mod outputs;
mod plot;
mod report_inputs;
mod safety;
mod settle;
mod sweep;
mod tilt;

use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use common::Fail;

#[derive(Parser)]
#[command(
    name = "voussoir",
    version,
    about = "Masonry as rigid no-tension blocks in unilateral contact: settlement, limit analysis, capacity.",
    long_about = "Masonry as rigid no-tension blocks in unilateral contact (Heyman's hypotheses).\n\
        Units: metres, kilonewtons, kN/m³, kPa; angles in degrees on the command line.\n\
        Models are JSON files (see the README for the schema) or DXF drawings; `voussoir gen` \
        writes JSON models.\n\
        Each command lists its own flags first, then the shared groups (model input, DXF import, \
        solver, output, drawing); a flag that does not apply to a command is refused."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Generate a model (arch, lintel, wall, facade) as JSON.
    #[command(subcommand)]
    Gen(gen::Gen),
    /// Import a DXF drawing (closed polylines = 2D blocks) or an OBJ/PLY mesh (closed meshes =
    /// 3D blocks) as a JSON model.
    Import(import::ImportArgs),
    /// Export a 3D model as Wavefront OBJ (each block the object `block_i`, each support
    /// `support_NAME`), for Blender, Rhino, MeshLab; `voussoir import` reads it back.
    Export(import::ExportArgs),
    /// Classic limit analysis: collapse load multiplier λ of the live loads and the mechanism.
    Limit(limit::LimitArgs),
    /// Settlement analysis: mechanism (crack pattern) and contact forces for prescribed support
    /// motions, by the paper's primal and dual LPs, with the duality gap as a certificate.
    Settle(settle::SettleCmdArgs),
    /// Tilting-table analysis: the critical tilt angle (degrees) at which the structure
    /// collapses when its base is tilted (gravity rotated).
    Tilt(tilt::TiltArgs),
    /// Load capacity after a settlement: λ against the settlement (limit analysis on the
    /// deformed geometry), the settlement at which λ reaches zero, validity of each step.
    Capacity(capacity::CapacityArgs),
    /// Does the structure stand under its dead loads, its geometric safety factor (Heyman) and
    /// the range of each support's reaction over the statically admissible states
    /// (docs/safety.md).
    Safety(safety::SafetyArgs),
    /// The least thickness at which a generated arch or dome stands under its own weight:
    /// bisection on the generator's --thickness, every other generator flag kept (live loads
    /// play no part; docs/safety.md).
    #[command(subcommand)]
    LeastThickness(safety::Generated),
    /// Incremental (nonlinear kinematic) analysis: λ against the displacement of a control
    /// point as the mechanism evolves and cracks close.
    Incremental(incremental::IncrementalArgs),
    /// Inverse settlement analysis: the support motions whose settlement mechanism opens the
    /// observed cracks, with misfits, a forward-analysis certificate and identifiability.
    Identify(identify::IdentifyArgs),
    /// Draw what an analysis wrote with -o (limit, settle, capacity, tilt, incremental, identify,
    /// safety; 2D or 3D; several curves on one plot) or a model: `-o fig.svg`, `fig.png` or
    /// `report.html`.
    Plot(plot::PlotArgs),
    /// Many settlement analyses in parallel: magnitudes, directions or Monte Carlo samples of
    /// the support motions, with --capacity the capacity after each (distribution of λ); JSON
    /// lines and CSV; --shard I/N for array jobs (docs/sweep.md).
    Sweep(sweep::SweepArgs),
    /// Merge the JSON-lines results of sweep shards (docs/sweep.md).
    Merge(sweep::MergeArgs),
    /// Time the pipeline (generation, detection, assembly, solve, output) on running-bond
    /// walls of growing size (docs/performance.md).
    Bench(bench::BenchArgs),
}

/// `matches`: the parsed command line, for the flags whose check needs to know whether they
/// were typed (not only their value: a default's value typed where it does nothing is refused
/// as any other value is).
fn run(cli: Cli, matches: &clap::ArgMatches) -> Result<(), Fail> {
    match cli.command {
        Command::Gen(g) => gen::run(g),
        Command::Import(a) => import::run(a),
        Command::Export(a) => import::export(a),
        Command::Sweep(a) => sweep::run(a),
        Command::Merge(a) => sweep::merge(a),
        Command::Bench(a) => bench::run(
            a,
            matches
                .subcommand_matches("bench")
                .expect("the bench command's matches"),
        ),
        Command::Limit(a) => limit::run(a),
        Command::Settle(a) => settle::run(a),
        Command::Capacity(a) => capacity::run(a),
        Command::Safety(a) => safety::run(a),
        Command::LeastThickness(g) => safety::run_least(g),
        Command::Incremental(a) => incremental::run(a),
        Command::Plot(a) => plot::run(a),
        Command::Tilt(a) => tilt::run(a),
        Command::Identify(a) => identify::run(a),
    }
}

/// The commands (`gen arch`, `limit`, …) that accept the long flag `--name`.
fn commands_with_flag(cmd: &clap::Command, prefix: &str, name: &str, found: &mut Vec<String>) {
    for sub in cmd.get_subcommands() {
        let path = if prefix.is_empty() {
            sub.get_name().to_string()
        } else {
            format!("{prefix} {}", sub.get_name())
        };
        // A renamed flag's old name (a hidden alias) counts too.
        if sub.get_arguments().any(|a| {
            a.get_long() == Some(name) || a.get_all_aliases().is_some_and(|v| v.contains(&name))
        }) {
            found.push(path.clone());
        }
        commands_with_flag(sub, &path, name, found);
    }
}

/// A command-line error as one line: clap's message without the usage block, and for a flag of
/// another command, which commands take it.
fn one_line(e: &clap::Error) -> String {
    let args: Vec<String> = std::env::args().collect();
    let mut sub = args.get(1).cloned().unwrap_or_default();
    if sub == "gen" {
        if let Some(kind) = args.get(2).filter(|k| !k.starts_with('-')) {
            sub = format!("gen {kind}");
        }
    }
    if e.kind() == ErrorKind::UnknownArgument {
        if let Some(ContextValue::String(bad)) = e.get(ContextKind::InvalidArg) {
            let flag = bad.split('=').next().unwrap_or(bad);
            // `sweep` and `merge` write --jsonl/--csv, not -o: clap's tip ("to pass '-o' as a
            // value, use '-- -o'") sent the user the wrong way (session 24).
            if flag == "-o" || flag == "--output" {
                let takes_jsonl = Cli::command()
                    .find_subcommand(&sub)
                    .is_some_and(|c| c.get_arguments().any(|a| a.get_long() == Some("jsonl")));
                if takes_jsonl {
                    return format!(
                        "error: {flag} does not apply to `voussoir {sub}`: its results go to --jsonl FILE (JSON lines) and --csv FILE (see `voussoir {sub} --help`)"
                    );
                }
            }
            if let Some(name) = flag.strip_prefix("--") {
                let mut found = Vec::new();
                commands_with_flag(&Cli::command(), "", name, &mut found);
                if !found.is_empty() {
                    return format!(
                        "error: {flag} does not apply to `voussoir {sub}`; it is a flag of {} (see `voussoir {sub} --help`)",
                        found
                            .iter()
                            .map(|c| format!("`{c}`"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    );
                }
            }
        }
    }
    let text = e.to_string();
    let mut parts: Vec<String> = Vec::new();
    for line in text.lines() {
        let l = line.trim();
        if l.starts_with("Usage:") || l.starts_with("For more information") {
            break;
        }
        if !l.is_empty() {
            parts.push(l.to_string());
        }
    }
    let mut s = parts.join(" ").replace(" tip: ", "; tip: ");
    if !sub.is_empty() && !sub.starts_with('-') {
        s.push_str(&format!(" (see `voussoir {sub} --help`)"));
    }
    s
}

fn main() {
    let parsed = Cli::command()
        .try_get_matches()
        .and_then(|m| Cli::from_arg_matches(&m).map(|c| (c, m)));
    let (cli, matches) = match parsed {
        Ok(c) => c,
        Err(e) => match e.kind() {
            ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => e.exit(),
            _ => {
                eprintln!("{}", one_line(&e));
                std::process::exit(2);
            }
        },
    };
    if let Err(e) = run(cli, &matches).and_then(|()| outputs::commit()) {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
