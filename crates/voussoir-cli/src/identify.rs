//! `voussoir identify`: which support motions caused the observed cracks (inverse settlement
//! analysis, docs/identify.md).

use crate::common::{Fail, ModelArgs, OutArgs, SettleArgs};
use crate::draw_args::{write_drawing, DrawArgs};
use clap::Args;
use std::fmt::Write as _;
use std::path::PathBuf;
use voussoir::analysis::identify::{identify, IdentifyOptions, IdentifyResult, Observations, Unknown};
use voussoir::structure::Structure;
use voussoir_io::draw::{self, ReportOptions};

#[derive(Args)]
pub struct IdentifyArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    /// The observed cracks (JSON, see docs/identify.md): `{"tolerance": m, "cracks": [{"at":
    /// [x, y], "opening": w} | {"joint": j, "opening": [w0, w1]}], "unobserved": [{"joint": j}
    /// | {"region": [x0, y0, x1, y1]}]}`; every other joint point is observed closed.
    #[arg(long, value_name = "OBS.json")]
    pub cracks: PathBuf,
    /// An unknown support motion: NAME=u,v,theta | A..B=v (segments sharing one value) |
    /// a profile with one value '?' (uniform:X0,X1,? | linear:X0,V0,X1,?). Bounds: u[LO:HI].
    /// Metres and radians. Repeatable.
    #[arg(long = "unknown", value_name = "SPEC", required = true)]
    pub unknowns: Vec<String>,
    /// Known motions and fixed supports (added to the unknowns).
    #[command(flatten)]
    pub settle: SettleArgs,
    /// Skip the identifiability ranges (two LPs per unknown).
    #[arg(long)]
    pub no_ranges: bool,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub draw: DrawArgs,
}

pub fn run(a: IdentifyArgs) -> Result<(), Fail> {
    let (st, solver) = a.model.structure(Some(&a.settle))?;
    let text = std::fs::read_to_string(&a.cracks)
        .map_err(|e| Fail(format!("cannot read {}: {e}", a.cracks.display())))?;
    let obs: Observations = serde_json::from_str(&text)
        .map_err(|e| Fail(format!("{}: invalid observations: {e}", a.cracks.display())))?;
    let mut unknowns = Vec::new();
    for spec in &a.unknowns {
        unknowns.extend(Unknown::parse(spec, &st)?);
    }
    let r = identify(
        &st,
        &obs,
        &unknowns,
        &IdentifyOptions {
            solver,
            ranges: !a.no_ranges,
            form: a.model.settlement_form(),
        },
    )?;
    if a.draw.svg.is_some() || a.draw.png.is_some() {
        let d = draw::draw_identify(&r, &a.draw.options()?, a.draw.title.as_deref());
        write_drawing(&d.svg, a.draw.svg.as_deref(), a.draw.png.as_deref())?;
    }
    if let Some(path) = &a.draw.report {
        let rep = draw::identify_report(
            &r,
            &ReportOptions {
                title: a.draw.title.clone(),
                source: a.model.model.display().to_string(),
                scale: a.draw.scale,
            },
        );
        voussoir_io::write_atomic(path, rep.to_html().as_bytes())?;
    }
    a.out.emit(&r, || summary(&st, &r))
}

fn summary(st: &Structure, r: &IdentifyResult) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "blocks {}, joints {}, supports {}",
        st.blocks.len(),
        st.joints.len(),
        st.supports.len()
    );
    let _ = writeln!(s, "{}", r.message);
    let _ = writeln!(s, "unknowns:");
    for u in &r.unknowns {
        let range = match (u.range_min, u.range_max) {
            (Some(lo), Some(hi)) => format!("range [{lo:.6e}, {hi:.6e}]"),
            _ if u.range_computed => "range unbounded or empty".to_string(),
            _ => "range not computed".to_string(),
        };
        let _ = writeln!(s, "  {:<20} = {:>14.6e}  {range}  — {}", u.name, u.value, u.note);
    }
    if !r.support_motions.is_empty() {
        let _ = writeln!(s, "support motions (u, v in m, θ in rad):");
        for m in &r.support_motions {
            let _ = writeln!(
                s,
                "  {:>8}: u {:>12.6e}  v {:>12.6e}  θ {:>12.6e}",
                m.support, m.u, m.v, m.theta
            );
        }
    }
    let _ = writeln!(
        s,
        "observations ({} points), misfit {:.4} tolerances in total, largest {:.3e} m:",
        r.observations.len(),
        r.total_misfit,
        r.max_misfit
    );
    for o in r.observations.iter().filter(|o| o.observed > 0.0 || o.misfit.abs() > o.tolerance) {
        let _ = writeln!(
            s,
            "  crack {:>3} joint {:>5} point {} at ({:.4}, {:.4}): observed {:.4e} m, predicted {:.4e} m, misfit {:+.2e} m{}",
            o.crack,
            o.joint,
            o.point,
            o.x,
            o.y,
            o.observed,
            o.predicted,
            o.misfit,
            if o.within_tolerance { "" } else { "  (outside tolerance)" }
        );
    }
    let odd: Vec<String> = r
        .predicted_cracks
        .iter()
        .filter(|c| c.observed != "open")
        .map(|c| format!("joint {} point {} ({}, {:.3e} m)", c.joint, c.point, c.observed, c.opening))
        .collect();
    if !odd.is_empty() {
        let _ = writeln!(s, "predicted cracks not observed open: {}", odd.join("; "));
    }
    if let Some(c) = &r.certificate {
        let _ = writeln!(
            s,
            "certificate: {} — {}",
            if c.reproduces { "REPRODUCED" } else { "NOT reproduced" },
            c.message
        );
    }
    s
}
