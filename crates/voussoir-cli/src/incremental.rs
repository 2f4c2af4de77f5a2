//! `voussoir incremental`: nonlinear kinematic analysis (evolving mechanism, hinges that close),
//! λ against the displacement of a control point.

use crate::common::{Fail, ModelArgs, OutArgs, SettleArgs};
use clap::Args;
use std::fmt::Write as _;
use std::io::IsTerminal;
use voussoir::analysis::incremental::{EventKind, IncrementalPoint, IncrementalResult};
use voussoir::analysis::limit::show_multiplier;
use voussoir::model3d::AnyModel;
use voussoir::request::{Analysis, AnyResult, Hooks, IncrementalRequest};
use voussoir::result::Spatial;
use voussoir::Assembly;
use voussoir_io::lengths::Length;

#[derive(Args)]
pub struct IncrementalArgs {
    /// Control point x,y (m) of a 2D model, x,y,z of a 3D one: the block containing it, or the
    /// nearest one, carries it. A 3D model (JSON, OBJ, PLY) is analysed the same way
    /// (docs/capacity.md): its figure is the λ curve (--svg, --png; --report, --vtk, --view
    /// refused), its LP method the 2D default (a simplex warm-started from step to step).
    #[arg(long, value_name = "X,Y[,Z]", allow_hyphen_values = true)]
    pub control: String,
    /// Direction along which the control displacement is measured: +x, -x, +y, -y, an angle
    /// in degrees from +x towards +y, or a vector DX,DY (any length). 3D models (z up): also
    /// +z, -z and DX,DY,DZ; an angle is horizontal (from +x towards +y); DX,DY is refused.
    #[arg(
        long,
        value_name = "DIR",
        default_value = "+x",
        allow_hyphen_values = true,
        value_parser = crate::direction::parse
    )]
    pub direction: crate::direction::Direction,
    /// Largest control displacement: a length with its unit (50mm, 5cm, 0.05m; a bare number is
    /// in m). The summary prints displacements in cm (README, "Units in the summaries").
    #[arg(long, value_name = "LENGTH", default_value = "50mm", value_parser = length)]
    pub max: f64,
    /// Control displacement per step: a length with its unit (0.5mm; a bare number is in m).
    #[arg(long, value_name = "LENGTH", default_value = "0.5mm", value_parser = length)]
    pub step: f64,
    /// Settle first by this support motion: NAME=u,v[,θ] (u, v in m or with a unit,
    /// `right=0,-2.5mm`; θ in degrees), in 3D NAME=u,v,w[,θx,θy,θz], repeatable, as `--move` of
    /// `settle`; the analysis starts from the settled geometry with the settlement's cracks
    /// open. (`--settle` is another name of this flag.)
    #[arg(
        long = "move",
        alias = "settle",
        value_name = "NAME=U,V[,THETA]",
        allow_hyphen_values = true
    )]
    pub moves: Vec<String>,
    /// Tie the blocks to this support for the settlement analysis (with --move). Repeatable.
    #[arg(long = "fixed", value_name = "NAME")]
    pub fixed: Vec<String>,
    /// Keep `fixed` supports tied after the settlement (default: contact joints).
    #[arg(long)]
    pub keep_fixed: bool,
    /// Keep the mechanism every N steps in the JSON (besides the first step and events).
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub snapshot_every: usize,
    /// Go on after λ has fallen to zero (up to --max).
    #[arg(long)]
    pub no_stop: bool,
    /// With --move: settle by the solver's own settlement mechanism instead of the canonical
    /// one (the default: least crack area among the optimal mechanisms, then a generic
    /// tie-break; docs/canonical.md). Where the settlement's optimum is not unique the starting
    /// cracks then depend on --method.
    #[arg(long, help_heading = "Canonical solution")]
    pub raw: bool,
    /// Also follow the canonical collapse mechanism at every step (by default the solver's own:
    /// where a step's optimum is not unique the path, its hinges, events and cracks, then
    /// depend on --method; λ at each step is the same either way). Costs 5–10× the raw CPU
    /// time (docs/performance.md).
    #[arg(long, help_heading = "Canonical solution", conflicts_with = "raw")]
    pub canonical_steps: bool,
    #[command(flatten)]
    pub split: crate::common::SplitArgs,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub draw: crate::draw_args::DrawArgs,
}

/// A positive length on the command line: a number in metres, or with a unit `mm`, `cm` or `m`.
pub fn length(s: &str) -> Result<f64, String> {
    match crate::common::signed_length(s) {
        Some(x) if x.is_finite() && x > 0.0 => Ok(x),
        _ => Err(format!(
            "expected a positive length such as 50mm, 5cm or 0.05 (m), got '{s}'"
        )),
    }
}

/// The numbers of `--control` (checked against the model's dimension by the request layer).
fn numbers(s: &str) -> Result<Vec<f64>, Fail> {
    s.split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| {
            Fail(format!(
                "--control {s}: expected two numbers X,Y (2D) or three X,Y,Z (3D)"
            ))
        })
}

pub fn run(a: IncrementalArgs) -> Result<(), Fail> {
    a.out.check()?;
    let req = a.model.request(
        Analysis::Incremental(IncrementalRequest {
            control: numbers(&a.control)?,
            direction: a.direction.toward(),
            max: a.max,
            step: a.step,
            keep_fixed: a.keep_fixed,
            snapshot_every: a.snapshot_every,
            no_stop: a.no_stop,
            raw: a.raw,
            canonical_steps: a.canonical_steps,
        }),
        SettleArgs {
            moves: a.moves.clone(),
            fixed: a.fixed.clone(),
            profile: None,
            split: a.split.clone(),
        }
        .motion()?,
    )?;
    a.draw.check()?;
    let input = a.model.resolve()?;
    let model = input.read_any()?;
    match &model {
        AnyModel::Planar(_) => a.draw.check_2d()?,
        AnyModel::Spatial(_) => refuse_3d_drawing(&a)?,
    }
    // The progress bar on a terminal (µm of control displacement).
    let bar = std::io::stderr().is_terminal().then(|| {
        let scale = 1e6;
        let bar = indicatif::ProgressBar::new((a.max * scale).ceil().max(1.0) as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let mut step = |p: &IncrementalPoint| {
        if let Some(bar) = &bar {
            bar.set_position((p.displacement.abs() * 1e6) as u64);
            bar.set_message(format!(
                "{}  λ = {:.5}",
                Length::Motion.show(p.displacement),
                p.load_multiplier
            ));
        }
    };
    let result = input.run_with(
        &model,
        &req,
        &mut Hooks {
            step: Some(&mut step),
            task: None,
            adapted: None,
        },
    );
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let internal = || Fail("internal: not an incremental result".into());
    match result? {
        AnyResult::Planar(run) => {
            let st = &run.setup.structure;
            let r = run.output.incremental().ok_or_else(internal)?;
            // The model's materials for the report (read again only when one is asked for).
            let facts = match a.draw.report {
                Some(_) => crate::report_inputs::facts_2d(&run.setup.model),
                None => Default::default(),
            };
            a.draw
                .clone()
                .with_inputs(|| {
                    let mut i = crate::report_inputs::report_inputs(
                        "incremental",
                        facts,
                        st,
                        &input,
                        &run.solver,
                        crate::report_inputs::Laws::default(),
                        settings(&a, r),
                    );
                    // The model with the settlement given by --move (the result starts after it).
                    i.model = Some(voussoir_io::report_parts::ModelEcho::of_2d(
                        &voussoir::Assembly::shapes(st),
                        voussoir::Assembly::contact_joints(st).len(),
                    ));
                    i
                })
                .emit_incremental(r, &input.path)?;
            a.out.emit_split(r, &run.setup.splits, || summary(st, r))
        }
        AnyResult::Spatial(run) => {
            let st = &run.setup.structure;
            let r = run.output.incremental().ok_or_else(internal)?;
            if a.draw.svg.is_some() || a.draw.png.is_some() {
                let title = a
                    .draw
                    .title
                    .as_deref()
                    .unwrap_or(voussoir_io::draw::INCREMENTAL_TITLE);
                let svg = voussoir_io::draw::incremental_plot(&[("λ(dx)", r)], title).svg;
                crate::draw_args::write_drawing(
                    &svg,
                    a.draw.svg.as_deref(),
                    a.draw.png.as_deref(),
                )?;
            }
            a.out.emit_split(r, &run.setup.splits, || summary(st, r))
        }
    }
}

/// A 3D incremental result's figure is the λ curve (--svg, --png); the report, --vtk and
/// --view draw 2D incremental results or 3D structures and are refused.
fn refuse_3d_drawing(a: &IncrementalArgs) -> Result<(), Fail> {
    for (given, flag) in [
        (a.draw.report.is_some(), "--report"),
        (a.draw.vtk.is_some(), "--vtk"),
        (a.draw.view.is_some(), "--view"),
        (a.draw.scale.is_some(), "--scale"),
        (a.draw.pressure_points.is_some(), "--pressure-points"),
    ] {
        if given {
            return Err(Fail(format!(
                "{flag} applies to 2D incremental results; a 3D incremental result draws its λ curve (--svg, --png) and is written whole by -o/--json"
            )));
        }
    }
    Ok(())
}

/// The settings of the analysis as given (lengths by the README's rule: cm), for the report.
fn settings(a: &IncrementalArgs, r: &IncrementalResult) -> Vec<(String, String)> {
    let cm = |x: f64| Length::Motion.show(x);
    let mut kv = vec![
        (
            "control point (--control)".to_string(),
            format!(
                "({}, {}) m, carried by block {}",
                Length::Position.number(r.control.point[0]),
                Length::Position.number(r.control.point[1]),
                r.control.block
            ),
        ),
        (
            "control direction (--direction)".to_string(),
            format!(
                "({:.4}, {:.4})",
                r.control.direction[0], r.control.direction[1]
            ),
        ),
        (
            "largest control displacement (--max)".to_string(),
            cm(a.max),
        ),
        ("step (--step)".to_string(), cm(a.step)),
        (
            "after the peak".to_string(),
            if a.no_stop {
                "go on to --max (--no-stop)".to_string()
            } else {
                "stop when λ has fallen to zero".to_string()
            },
        ),
    ];
    if !a.moves.is_empty() {
        kv.push((
            "settlement first (--move)".to_string(),
            format!(
                "{} (the supports' motions below); the analysis starts from the settled geometry with its cracks open{}",
                a.moves.join("; "),
                if a.keep_fixed {
                    ", fixed supports kept tied (--keep-fixed)"
                } else {
                    ""
                }
            ),
        ));
    }
    kv
}

fn summary<S: Assembly>(st: &S, r: &IncrementalResult<S::D>) -> String
where
    S::D: Spatial,
{
    let mut s = String::new();
    let _ = writeln!(s, "{}", crate::common::structure_line(st));
    let point: Vec<String> = r
        .control
        .point
        .as_ref()
        .iter()
        .map(|c| Length::Position.number(*c))
        .collect();
    let direction: Vec<String> = r
        .control
        .direction
        .as_ref()
        .iter()
        .map(|c| format!("{c:.3}"))
        .collect();
    let _ = writeln!(
        s,
        "control: block {} at ({}) m, direction ({})",
        r.control.block,
        point.join(", "),
        direction.join(", ")
    );
    if !r.initial_open_joints.is_empty() {
        let _ = writeln!(s, "joints open at the start: {:?}", r.initial_open_joints);
    }
    let _ = writeln!(s, "{}", r.message);
    if let Some(p) = r.curve.first() {
        let _ = writeln!(
            s,
            "λ at the start {} (by virtual work {})",
            show_multiplier(p.load_multiplier),
            show_multiplier(p.equilibrium_multiplier)
        );
    }
    for e in &r.events {
        let kind = match e.kind {
            EventKind::Opened => "opened",
            EventKind::Closed => "closed",
        };
        let z = e.z.map_or(String::new(), |z| {
            format!(", {}", Length::Position.number(z))
        });
        let _ = writeln!(
            s,
            "  step {:>5}  {:>9}  joint {:>4} point {} {kind} at ({}, {}{z}) m",
            e.step,
            Length::Motion.show(e.displacement),
            e.joint,
            e.point,
            Length::Position.number(e.x),
            Length::Position.number(e.y)
        );
    }
    let head = format!("dx ({})", Length::Motion.unit());
    let _ = writeln!(s, "{head:>12}  {:>10}", "λ");
    let every = (r.curve.len() / 25).max(1);
    for (i, p) in r.curve.iter().enumerate() {
        if i % every == 0 || i + 1 == r.curve.len() || p.before_closure {
            let _ = writeln!(
                s,
                "{:>12}  {:>10}",
                Length::Motion.number(p.displacement),
                show_multiplier(p.load_multiplier)
            );
        }
    }
    let _ = writeln!(
        s,
        "{} LP solves, {} solver iterations",
        r.solves, r.iterations
    );
    if let Some(c) = &r.canonical {
        let _ = writeln!(s, "{}", canonical_line(c));
    }
    s
}

/// The summary's line on the canonical selection.
fn canonical_line(c: &voussoir::result::incremental::IncrementalCanonical) -> String {
    let settlement = match (&c.settlement, c.settlement_not_reached) {
        (Some(m), _) => format!(
            "the settlement mechanism is the canonical one ({})",
            if m.changed {
                "not the solver's"
            } else {
                "the solver's"
            }
        ),
        (None, true) => {
            "the settlement's canonical mechanism was not reached (the solver's settled the structure)".to_string()
        }
        (None, false) => "no settlement".to_string(),
    };
    let sel = &c.selection;
    let steps = if sel.steps {
        format!(
            "the collapse mechanism of {} step{} selected, {} of them not the solver's{}",
            sel.steps_selected,
            if sel.steps_selected == 1 { "" } else { "s" },
            sel.steps_changed,
            if sel.steps_not_reached.is_empty() {
                String::new()
            } else {
                format!(", not reached at {} steps", sel.steps_not_reached.len())
            }
        )
    } else {
        "the steps' collapse mechanisms are the solver's (--canonical-steps selects them)"
            .to_string()
    };
    format!("canonical: {settlement}; {steps} ({} programs)", sel.solves)
}
