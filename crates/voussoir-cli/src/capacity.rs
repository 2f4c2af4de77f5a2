//! `voussoir capacity`: load capacity after a settlement (limit analysis on the deformed
//! geometry), λ–settlement curve and the settlement at which λ reaches zero.

use crate::common::{Fail, ModelArgs, OutArgs, SettleArgs};
use clap::Args;
use std::fmt::Write as _;
use voussoir::analysis::capacity::{CapacityResult, SettlementUnit};
use voussoir::analysis::limit::Crushing;
use voussoir::model3d::AnyModel;
use voussoir::request::{Analysis, AnyResult, CapacityRequest};
use voussoir::Assembly;
use voussoir_io::draw::capacity::LinearFitText;
use voussoir_io::lengths::Length;

#[derive(Args)]
pub struct CapacityArgs {
    /// The settlement: `--move NAME=u,v[,θ]` gives its direction and its largest value (m;
    /// θ in degrees), `--fixed NAME` ties the blocks to that support for the settlement
    /// analysis, `--profile` as for `settle`.
    #[command(flatten)]
    pub settle: SettleArgs,
    /// Number of intervals of the curve (it has N + 1 points from 0 to the largest
    /// settlement). The summary prints every point up to 100 steps; beyond, every k-th (and
    /// the last), and says so; -o and --json hold them all.
    #[arg(long, default_value_t = 40, value_name = "N")]
    pub steps: usize,
    /// Keep `fixed` supports tied to their blocks after the settlement (default: they act as
    /// contact joints in the limit analyses that follow).
    #[arg(long)]
    pub keep_fixed: bool,
    /// Leave the collapse mechanism of each step out of the JSON.
    #[arg(long)]
    pub no_mechanisms: bool,
    /// Solve every step from scratch (no HiGHS hot start).
    #[arg(long)]
    pub cold: bool,
    #[command(flatten)]
    pub crushing: crate::common::CrushingArgs,
    #[command(flatten)]
    pub canonical: crate::canonical::RawArgs,
    /// Also select the canonical collapse mechanism of every step (by default only the
    /// settlement mechanism, which deforms the structure, is canonical; the steps' mechanisms
    /// are the solver's). Costly on 3D models: 37× the raw CPU time on the README's vault
    /// (docs/canonical.md).
    #[arg(long, help_heading = "Canonical solution")]
    pub canonical_steps: bool,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub draw: crate::draw_args::DrawArgs,
}

pub fn run(a: CapacityArgs) -> Result<(), Fail> {
    a.out.check()?;
    a.draw.check()?;
    let input = a.model.resolve()?;
    let cap = CapacityRequest {
        steps: a.steps,
        keep_fixed: a.keep_fixed,
        no_mechanisms: a.no_mechanisms,
        cold: a.cold,
        crushing: a.crushing.crushing(),
        facets: a.crushing.facets,
        non_associative: a.crushing.non_associative,
        raw: a.canonical.raw,
        canonical_steps: a.canonical_steps,
    };
    let req = a
        .model
        .request(Analysis::Capacity(cap), a.settle.motion()?)?;
    let model = input.read_any()?;
    match &model {
        AnyModel::Planar(_) => a.draw.check_2d()?,
        AnyModel::Spatial(_) => a.draw.refuse_3d_curve()?,
    }
    let internal = || Fail("internal: not a capacity result".into());
    let settings = vec![("steps".to_string(), a.steps.to_string())];
    match input.run(&model, &req)? {
        AnyResult::Planar(run) => {
            let st = &run.setup.structure;
            let r = run.output.capacity().ok_or_else(internal)?;
            a.draw
                .clone()
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "capacity",
                        crate::report_inputs::facts_2d(&run.setup.model),
                        st,
                        &input,
                        &run.solver,
                        crate::report_inputs::Laws {
                            cone: None,
                            crushing: Some(match cap.laws().crushing() {
                                Crushing::Linear => {
                                    voussoir_io::report_parts::CrushingModel::Linear(
                                        cap.laws().facets(),
                                    )
                                }
                                Crushing::Conic => voussoir_io::report_parts::CrushingModel::Conic,
                            }),
                            non_associative: cap.non_associative,
                        },
                        settings,
                    )
                })
                .emit_capacity(r, &input.path)?;
            a.out.emit_split(r, &run.setup.splits, || summary(st, r))
        }
        AnyResult::Spatial(run) => {
            let st = &run.setup.structure;
            let r = run.output.capacity().ok_or_else(internal)?;
            let exact = input.exact_friction_cone;
            a.draw
                .clone()
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "capacity",
                        crate::report_inputs::facts_3d(&run.setup.model),
                        st,
                        &input,
                        &run.solver,
                        crate::report_inputs::Laws {
                            cone: Some(crate::settle::friction_cone(&input, st)),
                            crushing: None,
                            non_associative: cap.non_associative,
                        },
                        settings,
                    )
                })
                .emit_capacity(r, &input.path)?;
            a.out.emit_split(r, &run.setup.splits, || {
                let mut s = summary(st, r);
                if exact {
                    s.push_str(
                        "friction: the exact Coulomb cone in every limit analysis (second-order cone programs)\n",
                    );
                }
                s
            })
        }
    }
}

/// Most rows of the summary's table: beyond, every k-th point is printed (and the last).
const MAX_ROWS: usize = 101;

/// "2nd", "3rd", "11th", "22nd".
fn ordinal(k: usize) -> String {
    let suffix = match (k % 10, k % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{k}{suffix}")
}

/// A support's direction per unit settlement: the translation, or the rotation when the
/// settlement is a rotation (2D: θ; 3D: θx, θy, θz; in rad per rad).
fn direction_text(motion: &[f64], unit: SettlementUnit) -> String {
    let n = SettlementUnit::translations(motion.len());
    let part = match unit {
        SettlementUnit::Translation => &motion[..n],
        SettlementUnit::Rotation => &motion[n..],
    };
    let m: Vec<String> = part.iter().map(|x| format!("{x:.3}")).collect();
    m.join(", ")
}

fn summary<S: Assembly>(st: &S, r: &CapacityResult<S::D>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", crate::common::structure_line(st));
    let _ = writeln!(s, "{}", r.message);
    if r.curve.is_empty() {
        return s;
    }
    let unit = r.unit();
    // Lengths by the README's rule (voussoir_io::lengths): settlements in cm, rotations in mrad.
    let len = match unit {
        SettlementUnit::Translation => Length::Motion,
        SettlementUnit::Rotation => Length::Rotation,
    };
    let u = len.unit();
    let moving: Vec<String> = r
        .direction
        .iter()
        .map(|d| format!("{} ({})", d.support, direction_text(&d.motion, unit)))
        .collect();
    let what = match unit {
        SettlementUnit::Translation => "settlement direction",
        SettlementUnit::Rotation => "support rotation direction (rad per rad)",
    };
    let _ = writeln!(
        s,
        "{what}: {}; largest {} {}",
        moving.join(", "),
        unit.noun(),
        len.show(r.max_settlement)
    );
    // One entry per hinged joint (a 3D hinge line has several points on one joint).
    let mut joints: Vec<usize> = r.settlement_hinges.iter().map(|h| h.joint).collect();
    joints.sort_unstable();
    joints.dedup();
    let hinges: Vec<String> = joints.iter().map(|j| j.to_string()).collect();
    if hinges.is_empty() {
        let _ = writeln!(s, "hinges opened by the settlement: none");
    } else {
        let _ = writeln!(
            s,
            "hinges opened by the settlement: joints {}",
            hinges.join(", ")
        );
    }
    if let Some(c) = &r.canonical {
        let how = match &c.settlement {
            Some(m) if m.unique => "the settlement mechanism is unique".to_string(),
            Some(m) => format!(
                "the settlement mechanism is not unique: the canonical one is used ({})",
                match m.selected_by {
                    voussoir::analysis::canonical::Selection::LeastCrackArea => "least crack area",
                    _ => "least crack area, then the generic tie-break",
                }
            ),
            None => "the settlement mechanism's selection was not reached".to_string(),
        };
        if c.selection.steps {
            let _ = writeln!(
                s,
                "canonical: {how}; collapse mechanisms selected at {} steps ({} differ from the solver's)",
                c.selection.steps_selected, c.selection.steps_changed
            );
        } else {
            let _ = writeln!(
                s,
                "canonical: {how}; the steps' collapse mechanisms are the solver's (--canonical-steps selects them)"
            );
        }
    }
    s.push_str(&crate::common::cracks_section(
        "cracks at the largest settlement",
        "widths in mm, widest first",
        &r.cracks,
        true,
    ));
    match (r.zero_capacity_settlement, r.zero_capacity_bracket) {
        (Some(_), Some([lo, hi])) => {
            let _ = writeln!(
                s,
                "zero-capacity {}: between {} and {} (the root tolerance)",
                unit.noun(),
                len.show(lo),
                len.show(hi)
            );
        }
        // The onset (the message says why).
        (Some(_), None) if r.zero_at_onset() => {
            let _ = writeln!(s, "zero-capacity {}: at its onset", unit.noun());
        }
        (Some(z), None) => {
            let _ = writeln!(s, "zero-capacity {}: {}", unit.noun(), len.show(z));
        }
        _ => {}
    }
    match voussoir_io::draw::capacity::linear_fit_text(r) {
        Some(LinearFitText::Fits(t)) => {
            let _ = writeln!(s, "linear fit: {t}");
        }
        Some(LinearFitText::DoesNotFit(t)) => {
            let _ = writeln!(s, "warning: {t}");
        }
        None => {}
    }
    let n = r.curve.len();
    let every = if n <= MAX_ROWS {
        1
    } else {
        (n - 1).div_ceil(MAX_ROWS - 1)
    };
    let head = format!("s ({u})");
    if every > 1 {
        let _ = writeln!(
            s,
            "(every {} of {} steps shown, and the last; all in -o/--json)",
            ordinal(every),
            n - 1
        );
    }
    let _ = writeln!(s, "{head:>12}  {:>12}  valid", "λ");
    for (i, p) in r.curve.iter().enumerate() {
        if i % every != 0 && i + 1 != n {
            continue;
        }
        let l = p
            .load_multiplier
            .map_or("—".to_string(), voussoir::analysis::limit::show_multiplier);
        let v = if p.valid {
            "yes".to_string()
        } else {
            format!("no (closes joints {:?})", p.closing_joints)
        };
        let _ = writeln!(
            s,
            "{:>12}  {:>12}  {}",
            len.number_to(p.settlement, 5),
            l,
            v
        );
    }
    let _ = writeln!(
        s,
        "{} LP solves, {} solver iterations",
        r.solves, r.iterations
    );
    // Each step's certificate (the JSON's `certificate` per step and summed up); the numbers
    // as 2.7×10^-13 (a summary prints no bare e-notation).
    let sci = |x: f64| format!("{x:.1e}").replacen('e', "×10^", 1);
    if let Some(c) = &r.certificate {
        if c.ok {
            let _ = writeln!(
                s,
                "certificates: every step certified ({} of {}; largest gap {}, admissibility {})",
                c.certified,
                c.steps,
                sci(c.gap),
                sci(c.admissibility)
            );
        } else if c
            .uncertified_steps
            .iter()
            .all(|&i| r.curve.get(i).is_some_and(|p| p.certificate.is_none()))
        {
            // No step has a certificate at all (the non-associative iteration, cone programs):
            // no gap to quote (a gap of 0 would read as one that holds).
            let _ = writeln!(
                s,
                "certificates: NOT every step certified ({} of {}; uncertified steps {:?}, without a certificate: see the first line)",
                c.certified, c.steps, c.uncertified_steps
            );
        } else {
            let _ = writeln!(
                s,
                "certificates: NOT every step certified ({} of {}; uncertified steps {:?}; largest gap {}, admissibility {})",
                c.certified,
                c.steps,
                c.uncertified_steps,
                sci(c.gap),
                sci(c.admissibility)
            );
        }
    }
    s
}
