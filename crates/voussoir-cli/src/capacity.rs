//! `voussoir capacity`: load capacity after a settlement (limit analysis on the deformed
//! geometry), λ–settlement curve and the settlement at which λ reaches zero.

use crate::common::{Fail, ModelArgs, OutArgs, SettleArgs};
use clap::Args;
use std::fmt::Write as _;
use voussoir::analysis::capacity::{capacity, CapacityOptions, CapacityResult};
use voussoir::model3d::AnyModel;
use voussoir::Assembly;
use voussoir_io::draw::capacity::LinearFitText;

#[derive(Args)]
pub struct CapacityArgs {
    /// The settlement: `--move NAME=u,v[,θ]` gives its direction and its largest value (m;
    /// θ in degrees), `--fixed NAME` ties the blocks to that support for the settlement
    /// analysis, `--profile` as for `settle`.
    #[command(flatten)]
    pub settle: SettleArgs,
    /// Number of intervals of the curve (it has N + 1 points from 0 to the largest
    /// settlement).
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
    pub model: ModelArgs,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub draw: crate::draw_args::DrawArgs,
}

pub fn run(a: CapacityArgs) -> Result<(), Fail> {
    if a.settle.moves.is_empty() && a.settle.profile.is_none() {
        return Err(Fail(
            "capacity needs a settlement: give --move NAME=u,v (or --profile)".into(),
        ));
    }
    if a.steps == 0 {
        return Err(Fail(
            "--steps 0: the curve needs at least one interval".into(),
        ));
    }
    a.draw.check()?;
    let input = a.model.resolve()?;
    let motion = a.settle.resolve()?;
    let nonassociative = a.crushing.non_associative_settlement();
    let solver = if nonassociative.is_some() {
        crate::common::iteration_solver(&a.model, &input.solver)
    } else {
        input.solver
    };
    let (crushing, facets) = a.crushing.resolve()?;
    let opts = CapacityOptions {
        crushing,
        facets,
        nonassociative,
        steps: a.steps,
        hot_start: !a.cold,
        mechanisms: !a.no_mechanisms,
        release_fixed: !a.keep_fixed,
        solver,
        ..CapacityOptions::default()
    };
    match input.load_any()? {
        AnyModel::Planar(model) => {
            a.draw.check_2d()?;
            let st = input.structure_of(model, Some(&motion))?;
            let r = capacity(&st, &opts)?;
            a.draw.emit_capacity(&r, &input.path)?;
            a.out.emit(&r, || summary(&st, &r))
        }
        AnyModel::Spatial(model) => {
            a.draw.refuse_3d()?;
            if a.crushing.given() {
                return Err(Fail(
                    "--crushing and --facets describe finite compressive strength, which is modelled in 2D only".into(),
                ));
            }
            let st = input.structure3d(model, Some(&motion))?;
            let opts = CapacityOptions {
                solver: if nonassociative.is_some() {
                    crate::common::iteration_solver(&a.model, &input.solver3d)
                } else {
                    input.solver3d
                },
                ..opts
            };
            let r = capacity(&st, &opts)?;
            a.out.emit(&r, || summary(&st, &r))
        }
    }
}

fn summary<S: Assembly>(st: &S, r: &CapacityResult<S::D>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", crate::common::structure_line(st));
    let _ = writeln!(s, "{}", r.message);
    if r.curve.is_empty() {
        return s;
    }
    let moving: Vec<String> = r
        .direction
        .iter()
        .map(|d| {
            let m: Vec<String> = d.motion.iter().map(|x| format!("{x:.3}")).collect();
            // The translation: (u, v) in 2D, (u, v, w) in 3D.
            let n = if m.len() == 3 { 2 } else { 3 };
            format!("{} ({})", d.support, m[..n].join(", "))
        })
        .collect();
    let _ = writeln!(
        s,
        "settlement direction: {}; largest settlement {:.4} cm",
        moving.join(", "),
        r.max_settlement * 100.0
    );
    let hinges: Vec<String> = r
        .settlement_hinges
        .iter()
        .map(|h| h.joint.to_string())
        .collect();
    let _ = writeln!(
        s,
        "hinges opened by the settlement: joints {}",
        hinges.join(", ")
    );
    if let Some(z) = r.zero_capacity_settlement {
        let _ = writeln!(
            s,
            "zero-capacity settlement: {:.5} m ({:.3} cm)",
            z,
            z * 100.0
        );
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
    let _ = writeln!(s, "{:>12}  {:>12}  valid", "s (cm)", "λ");
    let every = (r.curve.len() / 20).max(1);
    for (i, p) in r.curve.iter().enumerate() {
        if i % every != 0 && i + 1 != r.curve.len() {
            continue;
        }
        let l = p
            .load_multiplier
            .map_or("—".to_string(), |l| format!("{l:.6}"));
        let v = if p.valid {
            "yes".to_string()
        } else {
            format!("no (closes joints {:?})", p.closing_joints)
        };
        let _ = writeln!(s, "{:>12.5}  {:>12}  {}", p.settlement * 100.0, l, v);
    }
    let _ = writeln!(
        s,
        "{} LP solves, {} simplex iterations",
        r.solves, r.iterations
    );
    s
}
