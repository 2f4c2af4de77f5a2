//! `voussoir sweep` and `voussoir merge`: flags in, files out. The engine (motions per task,
//! parallel analyses, records, CSV and JSON lines) is [`voussoir::sweep`].
//!
//! `--shard i/n` runs only the tasks with index ≡ i (mod n), so that an array job can split a
//! sweep; `voussoir merge` joins the shards' JSON lines.

use crate::common::{Fail, SettleArgs, SettleModelArgs};
use clap::Args;
use std::io::IsTerminal;
use std::path::PathBuf;
use voussoir::request::{Analysis, AnyResult, Hooks, SweepRequest};
use voussoir::sweep::{self, csv, jsonl, SweepRecord};
use voussoir::Assembly;

#[derive(Args)]
pub struct SweepArgs {
    /// The base settlement: moves, fixed supports, profile (as for `settle`).
    #[command(flatten)]
    pub settle: SettleArgs,
    #[command(flatten)]
    pub canonical: crate::canonical::RawArgs,
    /// Magnitude sweep: N analyses, the base motions scaled by k/N, k = 1 … N. (`--steps` is
    /// another name of this flag.)
    #[arg(long, alias = "steps", value_name = "N")]
    pub magnitudes: Option<usize>,
    /// Direction sweep: N analyses, the `--move` vectors (u, v) rotated through the N angles
    /// 360°·k/N; in 3D (u, w) and (θx, θz) in the vertical x–z plane. (`--directions` is
    /// another name of this flag.)
    #[arg(long, alias = "directions", value_name = "N")]
    pub angles: Option<usize>,
    /// Monte Carlo: N analyses, random settlement fields around the base motions.
    #[arg(long, value_name = "N")]
    pub samples: Option<usize>,
    /// Monte Carlo: coefficient of variation of each support's motion (dimensionless)
    /// [default: 0.3]; refused without --samples.
    #[arg(long, value_name = "COV")]
    pub cov: Option<f64>,
    /// Monte Carlo: random seed (the same seed gives the same samples on any machine)
    /// [default: 1]; refused without --samples.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Run only the tasks with index ≡ I (mod N): `--shard I/N`, I from 0.
    #[arg(long, value_name = "I/N")]
    pub shard: Option<String>,
    /// After each settlement, the capacity analysis of the same settlement (as `voussoir
    /// capacity`): λ after the settlement, the zero-capacity settlement and the validity flag
    /// per record; quantiles of λ on stderr (docs/sweep.md). The model needs live loads.
    #[arg(long)]
    pub capacity: bool,
    /// --capacity: intervals of each capacity curve (as `capacity --steps`) [default: 40];
    /// refused without --capacity.
    #[arg(long, value_name = "N")]
    pub capacity_steps: Option<usize>,
    /// Worker threads (default: one per core).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Model input, DXF import, solver, and --settlement-form.
    #[command(flatten)]
    pub model: SettleModelArgs,
    /// Write the results as JSON lines here (one analysis per line; lengths in m).
    #[arg(long, value_name = "FILE", help_heading = "Output")]
    pub jsonl: Option<PathBuf>,
    /// Write the results as a CSV table here (default: stdout when no --jsonl is given).
    #[arg(long, value_name = "FILE", help_heading = "Output")]
    pub csv: Option<PathBuf>,
    /// --capacity: write the distribution of λ after the settlement (count, mean, quantiles) as
    /// JSON here.
    #[arg(long, value_name = "FILE", help_heading = "Output")]
    pub summary: Option<PathBuf>,
    /// --capacity: draw the histogram and the exceedance curve of λ as SVG.
    #[arg(long, value_name = "FILE", help_heading = "Drawing")]
    pub svg: Option<PathBuf>,
    /// --capacity: the same figure as PNG.
    #[arg(long, value_name = "FILE", help_heading = "Drawing")]
    pub png: Option<PathBuf>,
    /// --capacity: an HTML report (key numbers, quantiles, both figures, every record).
    #[arg(long, value_name = "FILE", help_heading = "Drawing")]
    pub report: Option<PathBuf>,
}

#[derive(Args)]
pub struct MergeArgs {
    /// Shard results (JSON lines) to merge.
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// Merged JSON lines.
    #[arg(long, value_name = "FILE")]
    pub jsonl: Option<PathBuf>,
    /// Merged CSV table (default: stdout when no --jsonl is given).
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
}

fn parse_shard(s: &str) -> Result<(usize, usize), Fail> {
    let bad = || Fail(format!("--shard {s}: expected I/N with 0 ≤ I < N"));
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    let (i, n): (usize, usize) = (
        i.trim().parse().map_err(|_| bad())?,
        n.trim().parse().map_err(|_| bad())?,
    );
    if n == 0 || i >= n {
        return Err(bad());
    }
    Ok((i, n))
}

fn write_outputs(
    records: &[SweepRecord],
    jl: &Option<PathBuf>,
    cv: &Option<PathBuf>,
) -> Result<(), Fail> {
    if let Some(p) = jl {
        crate::outputs::stage(p, jsonl(records)?.as_bytes())?;
    }
    match cv {
        Some(p) => crate::outputs::stage(p, csv(records).as_bytes())?,
        None if jl.is_none() => print!("{}", csv(records)),
        None => {}
    }
    Ok(())
}

pub fn run(a: SweepArgs) -> Result<(), Fail> {
    // Flags resolved before any work (a DXF flag on a JSON model, bad numbers).
    let input = a.model.resolve()?;
    {
        use crate::draw_args::check_format;
        check_format("--svg", a.svg.as_deref(), &["svg"])?;
        check_format("--png", a.png.as_deref(), &["png"])?;
        check_format("--report", a.report.as_deref(), &["html", "htm"])?;
        check_format("--csv", a.csv.as_deref(), &["csv"])?;
        check_format("--summary", a.summary.as_deref(), &["json"])?;
    }
    let drawn = a.summary.is_some() || a.svg.is_some() || a.png.is_some() || a.report.is_some();
    if drawn && !a.capacity {
        return Err(Fail(
            "--summary, --svg, --png and --report describe the distribution of λ after the settlement: give --capacity".into(),
        ));
    }
    let shard = match &a.shard {
        Some(s) => Some(parse_shard(s)?),
        None => None,
    };
    let sweep = SweepRequest {
        magnitudes: a.magnitudes,
        angles: a.angles,
        samples: a.samples,
        cov: a.cov,
        seed: a.seed,
        settlement_form: a.model.settlement_form(),
        capacity: a.capacity,
        capacity_steps: a.capacity_steps,
        shard: shard.map(|(i, n)| [i, n]),
        tasks: None,
        raw: a.canonical.raw,
    };
    let req = a
        .model
        .base
        .request(Analysis::Sweep(sweep.clone()), a.settle.motion()?)?;
    let model = input.read_any()?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(a.threads.unwrap_or(0))
        .build()
        .map_err(|e| Fail(format!("cannot start worker threads: {e}")))?;
    let tasks = sweep.task_list().len();
    let count = sweep.kind().map_or(0, |k| k.count());
    let bar = if std::io::stderr().is_terminal() {
        let b = indicatif::ProgressBar::new(tasks as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{bar:40} {pos}/{len} analyses, {elapsed} elapsed, ETA {eta}",
        ) {
            b.set_style(style);
        }
        Some(b)
    } else {
        None
    };
    let progress = || {
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    let result = pool.install(|| {
        input.run_with(
            &model,
            &req,
            &mut Hooks {
                step: None,
                task: Some(&progress),
                adapted: None,
            },
        )
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let (records, splits, inputs) = match result? {
        AnyResult::Planar(run) => {
            let st = &run.setup.structure;
            // The report's inputs: the model with the base settlement, as every analysis
            // builds it.
            let inputs = (a.report.is_some() && a.capacity).then(|| {
                let mut i = crate::report_inputs::report_inputs_tol(
                    "sweep",
                    crate::report_inputs::facts_2d(&run.setup.model),
                    st,
                    a.model.tolerance,
                    &run.solver,
                    crate::report_inputs::Laws::default(),
                    settings(&a, count),
                );
                i.model = Some(voussoir_io::report_parts::ModelEcho::of_2d(
                    &Assembly::shapes(st),
                    Assembly::contact_joints(st).len(),
                ));
                i
            });
            (
                run.output.sweep().map(<[_]>::to_vec),
                run.setup.splits,
                inputs,
            )
        }
        AnyResult::Spatial(run) => {
            let st = &run.setup.structure;
            let inputs = (a.report.is_some() && a.capacity).then(|| {
                let mut i = crate::report_inputs::report_inputs_tol(
                    "sweep",
                    crate::report_inputs::facts_3d(&run.setup.model),
                    st,
                    a.model.tolerance,
                    &run.solver,
                    crate::report_inputs::Laws {
                        cone: Some(crate::settle::friction_cone(&input, st)),
                        crushing: None,
                        non_associative: false,
                    },
                    settings(&a, count),
                );
                i.model = Some(voussoir_io::report_parts::ModelEcho::of_3d(
                    &Assembly::shapes(st),
                    Assembly::contact_joints(st).len(),
                ));
                i
            });
            (
                run.output.sweep().map(<[_]>::to_vec),
                run.setup.splits,
                inputs,
            )
        }
    };
    let records = records.ok_or_else(|| Fail("internal: not a sweep".into()))?;
    // The sweep's records carry no model: the supports cut are told on stderr.
    eprint!("{}", crate::common::split_summary(&splits));
    write_outputs(&records, &a.jsonl, &a.csv)?;
    let certified = records.iter().filter(|r| r.certified).count();
    let (i, n) = shard.unwrap_or((0, 1));
    eprintln!(
        "{} analyses (shard {}/{} of {}) on {} threads; {certified} certified",
        records.len(),
        i,
        n,
        count,
        pool.current_num_threads()
    );
    if a.capacity {
        write_distribution(&a, &records, inputs)?;
    }
    Ok(())
}

/// The distribution of λ after the settlement: quantiles on stderr, and the summary, figure and
/// report files asked for.
fn write_distribution(
    a: &SweepArgs,
    records: &[SweepRecord],
    inputs: Option<voussoir_io::report_parts::ReportInputs>,
) -> Result<(), Fail> {
    use voussoir_io::draw::distribution;
    let Some(s) = sweep::capacity_summary(records) else {
        return Ok(());
    };
    for (k, v) in distribution::summary_rows(&s) {
        eprintln!("{k}: {v}");
    }
    let q: Vec<String> = s
        .quantiles
        .iter()
        .map(|q| format!("{:.0} % {:.6}", q.probability * 100.0, q.value))
        .collect();
    eprintln!("quantiles of λ after the settlement: {}", q.join(", "));
    if let Some(p) = &a.summary {
        crate::outputs::stage(p, voussoir_io::files::to_json(&s)?.as_bytes())?;
    }
    let title = "Load multiplier after the settlement";
    if a.svg.is_some() || a.png.is_some() {
        let svg = distribution::capacity_distribution_svg(records, title);
        if let Some(p) = &a.svg {
            crate::outputs::stage(p, svg.as_bytes())?;
        }
        if let Some(p) = &a.png {
            let png = voussoir_io::draw::svg_to_png(&svg, voussoir_io::draw::PNG_ZOOM)?;
            crate::outputs::stage(p, &png)?;
        }
    }
    if let Some(p) = &a.report {
        let rep = distribution::sweep_capacity_report(
            records,
            &voussoir_io::draw::ReportOptions {
                title: None,
                source: a.model.model.display().to_string(),
                scale: None,
                inputs,
            },
        );
        crate::outputs::stage(p, rep.to_html().as_bytes())?;
    }
    Ok(())
}

/// The settings of the sweep as given, for its report (the base motions are in the supports'
/// table).
fn settings(a: &SweepArgs, n: usize) -> Vec<(String, String)> {
    let mode = match (a.magnitudes, a.angles, a.samples) {
        (Some(k), _, _) => {
            format!("magnitudes (--magnitudes {k}): the base motions × k/{k}, k = 1 … {k}")
        }
        (_, Some(k), _) => {
            format!("angles (--angles {k}): the --move vectors rotated through 360°·k/{k}")
        }
        (_, _, Some(k)) => format!(
            "Monte Carlo (--samples {k}): coefficient of variation {} (--cov), seed {} (--seed)",
            a.cov.unwrap_or(voussoir::request::DEFAULT_COV),
            a.seed.unwrap_or(voussoir::request::DEFAULT_SEED)
        ),
        _ => String::new(),
    };
    let mut kv = vec![
        ("sweep".to_string(), mode),
        ("analyses".to_string(), n.to_string()),
        (
            "capacity curve of each analysis (--capacity-steps)".to_string(),
            format!(
                "{} intervals",
                a.capacity_steps
                    .unwrap_or(voussoir::request::DEFAULT_CAPACITY_STEPS)
            ),
        ),
    ];
    if !a.settle.moves.is_empty() {
        kv.push((
            "base motions (--move)".to_string(),
            a.settle.moves.join("; "),
        ));
    }
    if let Some(p) = &a.settle.profile {
        kv.push(("base settlement profile (--profile)".to_string(), p.clone()));
    }
    if let Some(s) = &a.shard {
        kv.push(("shard (--shard)".to_string(), s.clone()));
    }
    kv
}

pub fn merge(a: MergeArgs) -> Result<(), Fail> {
    let mut records: Vec<SweepRecord> = Vec::new();
    for p in &a.inputs {
        crate::outputs::input(p);
        let text = std::fs::read_to_string(p)
            .map_err(|e| Fail(format!("cannot read {}: {e}", p.display())))?;
        for (i, line) in text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty())
        {
            let r: SweepRecord = serde_json::from_str(line).map_err(|e| {
                Fail(format!(
                    "{}:{}: not a sweep record: {e}",
                    p.display(),
                    i + 1
                ))
            })?;
            records.push(r);
        }
    }
    let (records, missing) = sweep::merge(records)?;
    if missing > 0 {
        eprintln!(
            "warning: {missing} task(s) below index {} are missing",
            records.last().map_or(0, |r| r.index)
        );
    }
    write_outputs(&records, &a.jsonl, &a.csv)?;
    eprintln!(
        "merged {} records from {} file(s)",
        records.len(),
        a.inputs.len()
    );
    Ok(())
}
