//! `voussoir incremental`: nonlinear kinematic analysis (evolving mechanism, hinges that close),
//! λ against the displacement of a control point.

use crate::common::{Fail, ModelArgs, OutArgs, SettleArgs};
use clap::Args;
use std::fmt::Write as _;
use std::io::IsTerminal;
use voussoir::analysis::incremental::{
    incremental_with, settled, Control, EventKind, IncrementalOptions, IncrementalResult,
};
use voussoir_io::lengths::Length;

#[derive(Args)]
pub struct IncrementalArgs {
    /// Control point x,y (m): the block containing it, or the nearest one, carries it.
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    pub control: String,
    /// Direction along which the control displacement is measured: +x, -x, +y, -y, an angle
    /// in degrees from +x towards +y, or a vector DX,DY (any length).
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
    /// `right=0,-2.5mm`; θ in degrees), repeatable, as `--move` of `settle`; the analysis starts
    /// from the settled geometry with the settlement's cracks open. (`--settle` is another name
    /// of this flag.)
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

fn pair(flag: &str, s: &str) -> Result<[f64; 2], Fail> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| Fail(format!("--{flag} {s}: expected two numbers X,Y")))?;
    match v.as_slice() {
        [x, y] if x.is_finite() && y.is_finite() => Ok([*x, *y]),
        _ => Err(Fail(format!(
            "--{flag} {s}: expected two finite numbers X,Y"
        ))),
    }
}

pub fn run(a: IncrementalArgs) -> Result<(), Fail> {
    let x = pair("control", &a.control)?;
    let dir = a.direction.planar("--direction").map_err(Fail)?;
    if a.moves.is_empty() && !a.fixed.is_empty() {
        return Err(Fail("--fixed only applies with --move".into()));
    }
    if a.moves.is_empty() && a.keep_fixed {
        return Err(Fail("--keep-fixed only applies with --move".into()));
    }
    if a.step > a.max {
        return Err(Fail(format!(
            "--step {} mm is larger than --max {} mm",
            a.step * 1e3,
            a.max * 1e3
        )));
    }
    a.draw.check()?;
    a.draw.check_2d()?;
    let input = a.model.resolve()?;
    let motion = SettleArgs {
        moves: a.moves.clone(),
        fixed: a.fixed.clone(),
        profile: None,
        split: a.split.clone(),
    }
    .resolve()?;
    let solver = input.solver;
    let st = input.structure(Some(&motion))?;
    let start = if a.moves.is_empty() {
        st.clone()
    } else {
        settled(&st, &solver, !a.keep_fixed)?
    };
    // The block that carries the control point is chosen on the undeformed structure, so that
    // a point on a joint (the crown) names the same block with and without --move.
    let block = Control::nearest(&st, x, dir)?.block;
    let control = Control::new(&start, block, x, dir)?;
    let opts = IncrementalOptions {
        step: a.step,
        max_displacement: a.max,
        stop_after_peak: !a.no_stop,
        snapshot_every: a.snapshot_every,
        solver,
        ..IncrementalOptions::default()
    };
    let r = if std::io::stderr().is_terminal() {
        let scale = 1e6; // µm
        let bar = indicatif::ProgressBar::new((a.max * scale).ceil().max(1.0) as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        let r = incremental_with(&start, &control, &opts, &mut |p| {
            bar.set_position((p.displacement.abs() * scale) as u64);
            bar.set_message(format!(
                "{}  λ = {:.5}",
                Length::Motion.show(p.displacement),
                p.load_multiplier
            ));
        });
        bar.finish_and_clear();
        r?
    } else {
        incremental_with(&start, &control, &opts, &mut |_| {})?
    };
    a.draw.emit_incremental(&r, &input.path)?;
    a.out
        .emit_split(&r, &input.splits(), || summary(&start, &r))
}

fn summary(st: &voussoir::Structure, r: &IncrementalResult) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", crate::common::structure_line(st));
    let _ = writeln!(
        s,
        "control: block {} at ({}, {}) m, direction ({:.3}, {:.3})",
        r.control.block,
        Length::Position.number(r.control.point[0]),
        Length::Position.number(r.control.point[1]),
        r.control.direction[0],
        r.control.direction[1]
    );
    if !r.initial_open_joints.is_empty() {
        let _ = writeln!(s, "joints open at the start: {:?}", r.initial_open_joints);
    }
    let _ = writeln!(s, "{}", r.message);
    if let Some(p) = r.curve.first() {
        let _ = writeln!(
            s,
            "λ at the start {:.6} (by virtual work {:.6})",
            p.load_multiplier, p.equilibrium_multiplier
        );
    }
    for e in &r.events {
        let kind = match e.kind {
            EventKind::Opened => "opened",
            EventKind::Closed => "closed",
        };
        let _ = writeln!(
            s,
            "  step {:>5}  {:>9}  joint {:>4} point {} {kind} at ({}, {}) m",
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
                "{:>12}  {:>10.6}",
                Length::Motion.number(p.displacement),
                p.load_multiplier
            );
        }
    }
    let _ = writeln!(
        s,
        "{} LP solves, {} simplex iterations",
        r.solves, r.iterations
    );
    s
}
