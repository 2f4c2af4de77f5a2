//! `voussoir identify`: which support motions caused the observed cracks (inverse settlement
//! analysis, docs/identify.md).

use crate::common::{Fail, FormArgs, ModelArgs, OutArgs, SettleArgs};
use crate::draw_args::{write_drawing, DrawArgs};
use clap::Args;
use std::fmt::Write as _;
use std::path::PathBuf;
use voussoir::analysis::identify::{
    identify, Component, IdentifyOptions, IdentifyResult, Observations, Unknown,
};
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
    /// Form of the forward settlement analysis (the certificate).
    #[command(flatten)]
    pub form: FormArgs,
    /// Skip the identifiability ranges (two LPs per unknown).
    #[arg(long)]
    pub no_ranges: bool,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub draw: DrawArgs,
}

pub fn run(a: IdentifyArgs) -> Result<(), Fail> {
    a.draw.check()?;
    let input = a.model.resolve()?;
    let motion = a.settle.resolve()?;
    let mut model = input.load()?;
    let mut splits = motion.apply(&mut model)?;
    // Unknown profiles act on the foundations as drawn, as `--profile` does: a support that
    // spans one of their breakpoints is cut there first.
    let xs: Vec<f64> = a
        .unknowns
        .iter()
        .flat_map(|spec| profile_unknown_breakpoints(spec))
        .collect();
    if !xs.is_empty() {
        splits.extend(
            voussoir::settlement_input::split_supports_at(&mut model, &xs)
                .map_err(|e| Fail(format!("--unknown: {e}")))?,
        );
        voussoir::settlement_input::refresh_motions(&model, &mut splits);
    }
    let st = input.structure_of(model, None)?;
    let solver = input.solver;
    crate::outputs::input(&a.cracks);
    let text = std::fs::read_to_string(&a.cracks)
        .map_err(|e| Fail(format!("cannot read {}: {e}", a.cracks.display())))?;
    let obs: Observations = serde_json::from_str(&text)
        .map_err(|e| Fail(format!("{}: invalid observations: {e}", a.cracks.display())))?;
    let mut unknowns = Vec::new();
    for spec in &a.unknowns {
        unknowns.extend(parse_unknown(spec, &st)?);
    }
    let r = identify(
        &st,
        &obs,
        &unknowns,
        &IdentifyOptions {
            solver,
            ranges: !a.no_ranges,
            form: a.form.settlement_form.form(),
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
        crate::outputs::stage(path, rep.to_html().as_bytes())?;
    }
    a.out.emit_split(&r, &splits, || summary(&st, &r))
}

fn summary(st: &Structure, r: &IdentifyResult) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", crate::common::structure_line(st));
    let _ = writeln!(s, "{}", r.message);
    let _ = writeln!(s, "unknowns:");
    for u in &r.unknowns {
        let range = match (u.range_min, u.range_max) {
            (Some(lo), Some(hi)) => format!("range [{lo:.6e}, {hi:.6e}]"),
            _ if u.range_computed => "range unbounded or empty".to_string(),
            _ => "range not computed".to_string(),
        };
        let _ = writeln!(
            s,
            "  {:<20} = {:>14.6e}  {range}  — {}",
            u.name, u.value, u.note
        );
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
    for o in r
        .observations
        .iter()
        .filter(|o| o.observed > 0.0 || o.misfit.abs() > o.tolerance)
    {
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
        .map(|c| {
            format!(
                "joint {} point {} ({}, {:.3e} m)",
                c.joint, c.point, c.observed, c.opening
            )
        })
        .collect();
    if !odd.is_empty() {
        let _ = writeln!(s, "predicted cracks not observed open: {}", odd.join("; "));
    }
    if r.minima.len() > 1 || r.minima.first().is_some_and(|m| m.flat) {
        let _ = writeln!(
            s,
            "minima of the misfit ({} found{}):",
            r.minima.len(),
            if r.landscape_explored {
                ""
            } else {
                ", landscape not explored"
            }
        );
        for (i, m) in r.minima.iter().enumerate() {
            let values: Vec<String> = r
                .unknowns
                .iter()
                .zip(&m.values)
                .map(|(u, v)| format!("{} = {:.6e}", u.name, v))
                .collect();
            let mut notes = Vec::new();
            if i == 0 {
                notes.push("reported");
            }
            if m.flat {
                notes.push("flat: not unique");
            }
            if m.opens_pattern {
                notes.push("opens the observed pattern");
            }
            if m.within_tolerance {
                notes.push("every width within tolerance");
            }
            let _ = writeln!(
                s,
                "  misfit {:>10.4} tolerances at {}{}",
                m.misfit,
                values.join(", "),
                if notes.is_empty() {
                    String::new()
                } else {
                    format!("  ({})", notes.join("; "))
                }
            );
        }
    }
    if let Some(c) = &r.certificate {
        let _ = writeln!(
            s,
            "certificate: {} — {}",
            if c.reproduces {
                "REPRODUCED"
            } else {
                "NOT reproduced"
            },
            c.message
        );
    }
    s
}

/// Split `[LO:HI]` bounds (either side may be empty).
fn parse_bounds(s: &str, spec: &str) -> Result<(Option<f64>, Option<f64>), Fail> {
    let bad = || {
        Fail(format!(
            "--unknown {spec}: bounds are written [LO:HI] (either side may be empty)"
        ))
    };
    let inner = s
        .strip_prefix('[')
        .and_then(|t| t.strip_suffix(']'))
        .ok_or_else(bad)?;
    let (lo, hi) = inner.split_once(':').ok_or_else(bad)?;
    let num = |t: &str| -> Result<Option<f64>, Fail> {
        let t = t.trim();
        if t.is_empty() {
            return Ok(None);
        }
        t.parse::<f64>().map(Some).map_err(|_| bad())
    };
    Ok((num(lo)?, num(hi)?))
}

/// `f22` → ("f", 22).
fn split_number(name: &str) -> Option<(&str, u64)> {
    let i = name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    if i == name.len() {
        return None;
    }
    Some((&name[..i], name[i..].parse().ok()?))
}

/// One `--unknown` specification (see docs/identify.md):
/// `NAME=COMP[,COMP…]`, `A..B=COMP` (supports A to B sharing one value), or a profile with one
/// value written `?` (`uniform:X0,X1,?`, `linear:X0,V0,X1,?`, `table:X,V;X,?;…`); each component
/// or `?` may carry bounds `[LO:HI]`.
pub fn parse_unknown(spec: &str, st: &Structure) -> Result<Vec<Unknown>, Fail> {
    let spec = spec.trim();
    if let Some((kind, _)) = spec.split_once(':') {
        if matches!(kind, "uniform" | "linear" | "table") {
            return parse_profile_unknown(spec, st).map(|u| vec![u]);
        }
    }
    let (names, comps) = spec.split_once('=').ok_or_else(|| {
        Fail(format!("--unknown {spec}: expected NAME=u,v,theta, A..B=v or a profile with a '?' (uniform:X0,X1,?)"))
    })?;
    let label = names.trim();
    let names: Vec<String> = if let Some((a, b)) = label.split_once("..") {
        let (Some((pa, na)), Some((pb, nb))) = (split_number(a.trim()), split_number(b.trim()))
        else {
            return Err(Fail(format!("--unknown {spec}: a range A..B needs numbered names with one prefix, e.g. f22..f43")));
        };
        if pa != pb || na > nb {
            return Err(Fail(format!(
                "--unknown {spec}: a range A..B needs one prefix and A's number ≤ B's"
            )));
        }
        (na..=nb).map(|n| format!("{pa}{n}")).collect()
    } else {
        vec![label.to_string()]
    };
    let mut out = Vec::new();
    for c in comps.split(',') {
        let c = c.trim();
        let (c, lo, hi) = match c.find('[') {
            Some(i) => {
                let (lo, hi) = parse_bounds(&c[i..], spec)?;
                (&c[..i], lo, hi)
            }
            None => (c, None, None),
        };
        let comp = match c.trim() {
            "u" => Component::U,
            "v" => Component::V,
            "theta" | "θ" => Component::Theta,
            other => {
                return Err(Fail(format!(
                    "--unknown {spec}: component '{other}' is not u, v or theta"
                )));
            }
        };
        out.push(Unknown::supports(st, label, &names, comp, lo, hi)?);
    }
    Ok(out)
}

/// The breakpoints of an unknown profile (`uniform:X0,X1,?`, …; its positions are known), or
/// none when `spec` is not one or cannot be read (its own parse reports why).
fn profile_unknown_breakpoints(spec: &str) -> Vec<f64> {
    let spec = spec.trim();
    let Some(q) = spec.find('?') else {
        return Vec::new();
    };
    if !matches!(
        spec.split_once(':'),
        Some(("uniform" | "linear" | "table", _))
    ) {
        return Vec::new();
    }
    let rest = &spec[q + 1..];
    let tail = match rest.strip_prefix('[') {
        Some(r) => r.find(']').map_or("", |end| &r[end + 1..]),
        None => rest,
    };
    crate::common::parse_profile(&format!("{}0{tail}", &spec[..q]))
        .map(|p| p.breakpoints())
        .unwrap_or_default()
}

fn parse_profile_unknown(spec: &str, st: &Structure) -> Result<Unknown, Fail> {
    let bad = |m: &str| Fail(format!("--unknown {spec}: {m}"));
    let q = spec
        .find('?')
        .ok_or_else(|| bad("a profile unknown needs one value written '?'"))?;
    if spec[q + 1..].contains('?') {
        return Err(bad("only one '?' per profile"));
    }
    let rest = &spec[q + 1..];
    let (tail, lo, hi) = if rest.starts_with('[') {
        let end = rest.find(']').ok_or_else(|| bad("unclosed bounds"))?;
        let (lo, hi) = parse_bounds(&rest[..=end], spec)?;
        (&rest[end + 1..], lo, hi)
    } else {
        (rest, None, None)
    };
    let head = &spec[..q];
    // The '?' must be a value, not a position: count the numbers before it.
    let (kind, nums) = head.split_once(':').unwrap_or((head, ""));
    let before = nums.split([',', ';']).count() - 1;
    let is_value = match kind {
        "uniform" => before == 2,
        "linear" => before == 1 || before == 3,
        "table" => before % 2 == 1,
        _ => false,
    };
    if !is_value {
        return Err(bad(
            "the '?' must stand for a settlement value v, not a position x",
        ));
    }
    let p0 = crate::common::parse_profile(&format!("{head}0{tail}"))?;
    let p1 = crate::common::parse_profile(&format!("{head}1{tail}"))?;
    let name = format!("{head}?{tail}");
    Ok(Unknown::profile(st, &name, &p0, &p1, lo, hi)?)
}
