//! `voussoir safety`: does the structure stand under its dead loads, its geometric safety factor
//! and the range of its support reactions; `voussoir least-thickness arch|dome`: the least
//! thickness of a generated arch or dome (bisection, regenerating the model).

use crate::common::{Fail, ModelArgs, OutArgs, SolverArgs};
use crate::gen::{ArchArgs, DomeArgs};
use clap::{Args, Subcommand};
use std::fmt::Write as _;
use std::path::PathBuf;
use voussoir::analysis::safety::SafetyResult;
use voussoir::model3d::AnyModel;
use voussoir::request::{
    least_thickness, Analysis, AnyResult, Generator, LeastThicknessRequest, Names, SafetyRequest,
    SolverRequest, SupportMotion,
};
use voussoir::Assembly;

#[derive(Args)]
pub struct SafetyArgs {
    /// Absolute tolerance of the bisection on the joint fraction (the geometric safety factor
    /// is 1 / that fraction).
    #[arg(long, default_value_t = 1e-6, value_name = "TOL")]
    pub bisection_tolerance: f64,
    /// Leave out the ranges of the support reactions (two LPs per support and component), as
    /// `settle --no-ranges`. (`--no-reactions` is another name of this flag.)
    #[arg(long, alias = "no-reactions")]
    pub no_ranges: bool,
    /// Write a self-contained HTML report: hypotheses, inputs (geometry, materials, loads,
    /// supports, solver, tolerances), the safety factor with its definition, the reaction
    /// ranges (table and chart). Prints to PDF (docs/report3d.md).
    #[arg(long, value_name = "FILE", help_heading = "Drawing")]
    pub report: Option<PathBuf>,
    /// Title of the report (default: "Safety assessment").
    #[arg(
        long,
        value_name = "TEXT",
        help_heading = "Drawing",
        requires = "report"
    )]
    pub title: Option<String>,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub out: OutArgs,
}

#[derive(Subcommand)]
pub enum Generated {
    /// An arch of `voussoir gen arch` (every flag of it; -o writes the model at the least
    /// thickness).
    Arch(LeastArch),
    /// A dome of `voussoir gen dome` (every flag of it; -o writes the model at the least
    /// thickness).
    Dome(LeastDome),
}

#[derive(Args)]
pub struct LeastArch {
    #[command(flatten)]
    pub arch: ArchArgs,
    #[command(flatten)]
    pub bracket: Bracket,
}

#[derive(Args)]
pub struct LeastDome {
    #[command(flatten)]
    pub dome: DomeArgs,
    #[command(flatten)]
    pub bracket: Bracket,
}

#[derive(Args)]
#[command(next_help_heading = "Bisection")]
pub struct Bracket {
    /// Thickness (m) at which the structure must not stand [default: radius / 1000].
    #[arg(long, value_name = "M")]
    pub lower: Option<f64>,
    /// Thickness (m) at which the structure must stand [default: radius / 2].
    #[arg(long, value_name = "M")]
    pub upper: Option<f64>,
    /// Tolerance of the bisection, relative to the radius. (`--relative-tolerance` is another
    /// name of this flag.)
    #[arg(
        long,
        alias = "relative-tolerance",
        default_value_t = 1e-6,
        value_name = "REL"
    )]
    pub bisection_tolerance: f64,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub solver: SolverArgs,
}

pub fn run(a: SafetyArgs) -> Result<(), Fail> {
    a.out.check()?;
    crate::draw_args::check_format("--report", a.report.as_deref(), &["html", "htm"])?;
    let input = a.model.resolve()?;
    let req = a.model.request(
        Analysis::Safety(SafetyRequest {
            bisection_tolerance: a.bisection_tolerance,
            no_ranges: a.no_ranges,
        }),
        SupportMotion::default(),
    )?;
    use crate::report_inputs::{facts_2d, facts_3d, report_inputs, Laws};
    use voussoir_io::report_parts::ModelEcho;
    let internal = || Fail("internal: not a safety result".into());
    match input.run(&input.read_any()?, &req)? {
        AnyResult::Planar(run) => {
            let st = &run.setup.structure;
            let r = run.output.safety().ok_or_else(internal)?;
            if a.report.is_some() {
                let mut i = report_inputs(
                    "safety",
                    facts_2d(&run.setup.model),
                    st,
                    &input,
                    &run.solver,
                    Laws::default(),
                    settings(&a),
                );
                i.model = Some(ModelEcho::of_2d(&st.shapes(), st.contact_joints().len()));
                write_report(&a, r, i, &input.path)?;
            }
            a.out.emit(r, || summary(st, r))
        }
        AnyResult::Spatial(run) => {
            let st = &run.setup.structure;
            let r = run.output.safety().ok_or_else(internal)?;
            if a.report.is_some() {
                let mut i = report_inputs(
                    "safety",
                    facts_3d(&run.setup.model),
                    st,
                    &input,
                    &run.solver,
                    Laws {
                        cone: Some(crate::settle::friction_cone(&input, st)),
                        ..Laws::default()
                    },
                    settings(&a),
                );
                i.model = Some(ModelEcho::of_3d(&st.shapes(), st.contact_joints().len()));
                write_report(&a, r, i, &input.path)?;
            }
            a.out.emit(r, || summary(st, r))
        }
    }
}

/// The settings of `safety` as given, for its report.
fn settings(a: &SafetyArgs) -> Vec<(String, String)> {
    vec![
        (
            "bisection tolerance (--bisection-tolerance)".into(),
            format!(
                "{} (absolute, on the joint fraction)",
                voussoir_io::report_parts::sci(a.bisection_tolerance)
            ),
        ),
        (
            "reaction ranges".into(),
            if a.no_ranges {
                "not computed (--no-ranges)".into()
            } else {
                "computed (two LPs per support and component)".into()
            },
        ),
    ]
}

fn write_report(
    a: &SafetyArgs,
    r: &SafetyResult,
    inputs: voussoir_io::report_parts::ReportInputs,
    source: &std::path::Path,
) -> Result<(), Fail> {
    let Some(path) = &a.report else {
        return Ok(());
    };
    let rep = voussoir_io::draw::safety_report(
        r,
        &voussoir_io::draw::ReportOptions {
            title: a.title.clone(),
            source: source.display().to_string(),
            scale: None,
            inputs: Some(inputs),
        },
    );
    crate::outputs::stage(path, rep.to_html().as_bytes())
}

pub fn run_least(g: Generated) -> Result<(), Fail> {
    let (generator, bracket, output) = match &g {
        Generated::Arch(x) => (
            Generator::Arch(x.arch.spec()?),
            &x.bracket,
            x.arch.out.output.clone(),
        ),
        Generated::Dome(x) => (
            Generator::Dome(x.dome.spec()),
            &x.bracket,
            x.dome.out.output.clone(),
        ),
    };
    let req = LeastThicknessRequest {
        lower: bracket.lower,
        upper: bracket.upper,
        bisection_tolerance: bracket.bisection_tolerance,
    };
    let solver = SolverRequest {
        method: bracket.solver.method.map(crate::common::method),
        log: bracket.solver.options().log,
    };
    let run = least_thickness(&generator, &req, &solver, Names::Flags)?;
    if let Some(path) = &output {
        let json = match &run.model {
            AnyModel::Planar(m) => voussoir_io::files::to_json(m)?,
            AnyModel::Spatial(m) => voussoir_io::files::to_json(m)?,
        };
        crate::outputs::stage(path, json.as_bytes())?;
    }
    let r = &run.result;
    if bracket.json {
        crate::common::out(&voussoir_io::files::to_json(r)?);
    } else {
        crate::common::out(&format!(
            "least thickness of the {}: {} m (t/R = {:.6} with R = {} m at the centreline); it does not stand at {} m; {} bisection steps\n",
            r.generator,
            voussoir::lengths::fine(r.found.thickness, 8),
            r.thickness_over_radius,
            voussoir::lengths::fine(r.centreline_radius, 6),
            voussoir::lengths::fine(r.found.below, 8),
            r.found.steps
        ));
        // How each decision was answered (the JSON's `answered`), as `safety` prints it.
        let mut s = format!(
            "decisions: {} ({})\n",
            if r.certified {
                "every one certified (an equilibrium state, or a certificate of infeasibility)"
            } else {
                "NOT every one certified"
            },
            r.solver.method.name()
        );
        for a in &r.answered {
            let _ = writeln!(
                s,
                "  {}: {} by {} ({}{})",
                a.programs,
                a.answers,
                a.method.name(),
                a.outcome,
                a.why.as_ref().map_or(String::new(), |w| format!("; {w}"))
            );
        }
        crate::common::out(&s);
    }
    Ok(())
}

fn summary<S: Assembly>(st: &S, r: &SafetyResult) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", crate::common::structure_line(st));
    let _ = writeln!(
        s,
        "stands under its dead loads: {}",
        if r.stands { "yes" } else { "no" }
    );
    let _ = writeln!(s, "{}", r.message);
    let show = |v: Option<f64>, side: &str| {
        v.map_or(format!("unbounded {side}"), |x| {
            voussoir::lengths::force(x, 4, false)
        })
    };
    for re in &r.reactions {
        let parts: Vec<String> = re
            .components
            .iter()
            .map(|c| {
                format!(
                    "{} [{}, {}] kN",
                    c.component,
                    show(c.min, "below"),
                    show(c.max, "above")
                )
            })
            .collect();
        let _ = writeln!(s, "reaction {:>8}: {}", re.support, parts.join("  "));
    }
    if r.reaction_ends_by_symmetry > 0 {
        let _ = writeln!(
            s,
            "reaction ranges: {} ends given by the structure's symmetry (images of ends solved for other supports, each certified on its own program)",
            r.reaction_ends_by_symmetry
        );
    }
    // The method that stands for the run (the one asked for where it answered), every
    // fallback taken, then which method answered each kind of program and why where it is
    // not the one asked for (the JSON's `solver` and `answered`).
    let _ = writeln!(
        s,
        "{} LP solves ({}{})",
        r.solves,
        r.solver.method.name(),
        if r.solver.tried.is_empty() {
            String::new()
        } else {
            format!("; fallbacks: {}", r.solver.tried.join("; "))
        }
    );
    for a in &r.answered {
        let _ = writeln!(
            s,
            "  {}: {} by {} ({}{})",
            a.programs,
            a.answers,
            a.method.name(),
            a.outcome,
            a.why.as_ref().map_or(String::new(), |w| format!("; {w}"))
        );
    }
    s
}
