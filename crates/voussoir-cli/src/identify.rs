//! `voussoir identify`: which support motions caused the observed cracks (inverse settlement
//! analysis, docs/identify.md).

use crate::common::{Fail, FormArgs, ModelArgs, OutArgs, SettleArgs};
use crate::draw_args::{write_drawing, DrawArgs};
use crate::import::UnitsArg;
use clap::Args;
use std::fmt::Write as _;
use std::path::PathBuf;
use voussoir::analysis::identify::Observations;
use voussoir::model3d::AnyModel;
use voussoir::request::{Analysis, AnyResult, IdentifyRequest, UnknownSpec};
use voussoir::result::identify::IdentifyResult;
use voussoir::result::Spatial;
use voussoir::Assembly;
use voussoir_io::draw::{self, ReportOptions};
use voussoir_io::lengths::Length;
use voussoir_io::survey::read_survey;

#[derive(Args)]
pub struct IdentifyArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    /// The observed cracks (JSON, see docs/identify.md): `{"units": "mm", "tolerance": 0.1,
    /// "cracks": [{"at": [x, y], "opening": w} | {"joint": j, "opening": [w0, w1]} |
    /// {"polyline": [[x, y], …], "opening": w}], "unobserved": [{"joint": j} | {"region": [x0,
    /// y0, x1, y1]}]}`; every other joint point is observed closed. 3D models: `"at": [x, y,
    /// z]`, `"joint"` (a width per point of the joint's polygon, or one), regions `[x0, y0, z0,
    /// x1, y1, z1]`; no polylines.
    #[arg(long, value_name = "OBS.json")]
    pub cracks: Option<PathBuf>,
    /// A crack survey drawing (DXF): the lines (LWPOLYLINE, POLYLINE, LINE) of the survey
    /// layers are crack lines, each with the width of the TEXT/MTEXT label next to it or in its
    /// layer's name (CRACK-2mm); read with the "Crack survey drawing" flags. Added to the
    /// cracks of --cracks, if given.
    #[arg(long, value_name = "SURVEY.dxf")]
    pub survey: Option<PathBuf>,
    /// An unknown support motion: NAME=u,v,theta | A..B=v (segments sharing one value) |
    /// a profile with one value '?' (uniform:X0,X1,? | linear:X0,V0,X1,?). Bounds: u[LO:HI].
    /// Metres and radians. Repeatable. 3D models (z up): any of the six components
    /// NAME=u,v,w,theta_x,theta_y,theta_z (each one unknown), e.g. right=u,w; no profiles.
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

/// The observations: the JSON file's cracks, then the survey drawing's lines. Also the
/// description of each survey crack by its index, for messages.
fn observations(
    a: &IdentifyArgs,
    model_units: Option<UnitsArg>,
) -> Result<(Observations, Vec<(usize, String)>), Fail> {
    let mut obs = match &a.cracks {
        Some(path) => {
            crate::outputs::input(path);
            let text = std::fs::read_to_string(path)
                .map_err(|e| Fail(format!("cannot read {}: {e}", path.display())))?;
            serde_json::from_str(&text)
                .map_err(|e| Fail(format!("{}: invalid observations: {e}", path.display())))?
        }
        None => Observations::default(),
    };
    let mut names = Vec::new();
    if let Some(path) = &a.survey {
        crate::outputs::input(path);
        let opts = a.model.survey.options(model_units);
        let (cracks, report) = read_survey(path, &opts)?;
        eprintln!("{}", report.summary());
        for n in &report.notes {
            eprintln!("note: {n}");
        }
        // In the JSON file's coordinate unit; widths in metres, said per crack.
        let fc = match obs.coordinate_units.as_deref() {
            None => 1.0,
            Some(u) => voussoir::model::length_unit(u).ok_or_else(|| {
                Fail(format!(
                    "observations: \"coordinate_units\": unknown unit \"{u}\" (give \"m\", \"cm\" or \"mm\")"
                ))
            })?,
        };
        for (mut c, line) in cracks.into_iter().zip(&report.lines) {
            if let Some(p) = c.polyline.as_mut() {
                for q in p.iter_mut() {
                    *q = [q[0] / fc, q[1] / fc];
                }
            }
            c.snap = c.snap.map(|d| d / fc);
            c.units = Some("m".into());
            names.push((
                obs.cracks.len(),
                format!("{} of {}", line.entity, path.display()),
            ));
            obs.cracks.push(c);
        }
    }
    Ok((obs, names))
}

/// `msg` with the drawing entity after every `cracks[i]` that came from the survey.
fn annotate(msg: &str, names: &[(usize, String)]) -> String {
    let mut out = msg.to_string();
    for (i, name) in names.iter().rev() {
        out = out.replace(&format!("cracks[{i}]"), &format!("cracks[{i}] ({name})"));
    }
    out
}

pub fn run(a: IdentifyArgs) -> Result<(), Fail> {
    a.out.check()?;
    a.draw.check()?;
    a.model.survey.check(a.survey.is_some(), "--survey")?;
    if a.cracks.is_none() && a.survey.is_none() {
        return Err(Fail(
            "give the observed cracks: --cracks OBS.json, --survey SURVEY.dxf, or both".into(),
        ));
    }
    // `--units` is the drawings' unit: the model's when it is a drawing, and the survey's
    // (unless --survey-units); with a JSON model it is the survey's alone.
    let mut model = a.model.clone();
    let drawn = voussoir_io::dxf::is_dxf(&model.model) || voussoir_io::mesh::is_mesh(&model.model);
    let model_units = model.dxf.units;
    if a.survey.is_some() && !drawn {
        model.dxf.units = None;
    }
    let input = model.resolve_with(Some(a.survey.is_some()))?;
    let any = input.read_any()?;
    if let AnyModel::Spatial(_) = any {
        refuse_3d(&a)?;
    } else {
        a.draw.check_2d()?;
    }
    let mut identify = IdentifyRequest {
        observations: Observations::default(),
        unknowns: a.unknowns.iter().cloned().map(UnknownSpec::Text).collect(),
        no_ranges: a.no_ranges,
        settlement_form: a.form.settlement_form.form(),
    };
    // The model with the known motions first (their errors before the observations'), then
    // the observations read and the analysis run.
    let mut req = a
        .model
        .request(Analysis::Identify(identify.clone()), a.settle.motion()?)?;
    let prepared = input.prepare(&any, &req)?;
    let (obs, names) = observations(&a, model_units)?;
    identify.observations = obs.clone();
    req.analysis = Analysis::Identify(identify);
    let result = voussoir::request::solve(prepared, &req)
        .map_err(|e| Fail(annotate(&Fail::from(e).0, &names)))?;
    let internal = || Fail("internal: not an identification".into());
    match result {
        AnyResult::Planar(run) => {
            let st = &run.setup.structure;
            let (r, unknowns) = run.output.identify().ok_or_else(internal)?;
            if a.draw.svg.is_some() || a.draw.png.is_some() {
                let d = draw::draw_identify(r, &a.draw.options()?, a.draw.title.as_deref());
                write_drawing(&d.svg, a.draw.svg.as_deref(), a.draw.png.as_deref())?;
            }
            if let Some(path) = &a.draw.report {
                let facts = crate::report_inputs::facts_2d(&run.setup.model);
                let rep = draw::identify_report(
                    r,
                    &ReportOptions {
                        title: a.draw.title.clone(),
                        source: a.model.model.display().to_string(),
                        scale: a.draw.scale,
                        inputs: Some(voussoir_io::report_parts::ReportInputs {
                            // The model with the known motions (the identified ones are results).
                            model: Some(voussoir_io::report_parts::ModelEcho::of_2d(
                                &voussoir::Assembly::shapes(st),
                                voussoir::Assembly::contact_joints(st).len(),
                            )),
                            unknown_lengths: unknowns.iter().map(|u| u.length()).collect(),
                            ..crate::report_inputs::report_inputs(
                                "identify",
                                facts,
                                st,
                                &input,
                                &run.solver,
                                crate::report_inputs::Laws::default(),
                                settings(&a, &obs),
                            )
                        }),
                    },
                );
                crate::outputs::stage(path, rep.to_html().as_bytes())?;
            }
            // Each unknown's kind of length: a rotation (every support's θ only) or a motion.
            let kinds: Vec<Length> = unknowns.iter().map(|u| u.length()).collect();
            a.out
                .emit_split(r, &run.setup.splits, || summary(st, r, &kinds))
        }
        AnyResult::Spatial(run) => {
            let st = &run.setup.structure;
            let (r, unknowns) = run.output.identify().ok_or_else(internal)?;
            if a.draw.svg.is_some()
                || a.draw.png.is_some()
                || a.draw.vtk.is_some()
                || a.draw.view.is_some()
            {
                let draw = DrawArgs {
                    title: Some(a.draw.title.clone().unwrap_or_else(|| {
                        "Forward settlement of the identified support motion".to_string()
                    })),
                    ..a.draw.clone()
                };
                draw.emit_3d(&r.forward, &input.path)?;
            }
            let kinds: Vec<Length> = unknowns.iter().map(|u| u.length()).collect();
            a.out
                .emit_split(r, &run.setup.splits, || summary(st, r, &kinds))
        }
    }
}

/// A 3D model: the observations are points (`at: [x, y, z]`) or joints; `--svg`, `--png`,
/// `--vtk` and `--view` draw the forward settlement of the identified motion (a 3D structure
/// drawing), `--report` and `--survey` (2D) are refused.
fn refuse_3d(a: &IdentifyArgs) -> Result<(), Fail> {
    if a.survey.is_some() {
        return Err(Fail(
            "--survey reads a 2D crack survey drawing; on a 3D model give the observed cracks as --cracks OBS.json (\"at\": [x, y, z] or \"joint\", docs/identify.md)".into(),
        ));
    }
    if a.draw.report.is_some() {
        return Err(Fail(
            "--report applies to 2D identifications; on a 3D model --svg, --png, --vtk and --view draw the forward settlement of the identified motion".into(),
        ));
    }
    Ok(())
}

/// The settings of the identification as given, for the report.
fn settings(a: &IdentifyArgs, obs: &Observations) -> Vec<(String, String)> {
    let mut kv = vec![(
        "unknowns (--unknown; m and rad)".to_string(),
        a.unknowns.join("; "),
    )];
    let mut sources = Vec::new();
    if let Some(p) = &a.cracks {
        sources.push(format!("{} (--cracks)", p.display()));
    }
    if let Some(p) = &a.survey {
        sources.push(format!("{} (--survey)", p.display()));
    }
    kv.push((
        "observed cracks".to_string(),
        format!("{} cracks from {}", obs.cracks.len(), sources.join(" and ")),
    ));
    if !a.settle.moves.is_empty() {
        kv.push((
            "known motions (--move)".to_string(),
            a.settle.moves.join("; "),
        ));
    }
    kv.push((
        "identifiability ranges".to_string(),
        if a.no_ranges {
            "not computed (--no-ranges)".to_string()
        } else {
            "computed (two LPs per unknown)".to_string()
        },
    ));
    kv
}

/// The summary; lengths by the README's rule ([`voussoir_io::lengths`]): support motions in
/// cm, rotations in mrad, crack widths and misfits in mm, positions in m.
fn summary<S: Assembly>(st: &S, r: &IdentifyResult<S::D>, kinds: &[Length]) -> String
where
    S::D: Spatial,
{
    let kind = |i: usize| kinds.get(i).copied().unwrap_or(Length::Motion);
    let mut s = String::new();
    let _ = writeln!(s, "{}", crate::common::structure_line(st));
    let _ = writeln!(s, "{}", r.message);
    let _ = writeln!(s, "unknowns:");
    for (i, u) in r.unknowns.iter().enumerate() {
        let k = kind(i);
        let range = match (u.range_min, u.range_max) {
            (Some(lo), Some(hi)) => {
                format!("range [{}, {}] {}", k.number(lo), k.number(hi), k.unit())
            }
            _ if u.range_computed => "range unbounded or empty".to_string(),
            _ => "range not computed".to_string(),
        };
        let _ = writeln!(
            s,
            "  {:<20} = {:>14}  {range}  — {}",
            u.name,
            k.show(u.value),
            u.note
        );
    }
    if !r.support_motions.is_empty() {
        let _ = writeln!(s, "support motions:");
        for m in &r.support_motions {
            let _ = writeln!(s, "  {:>8}: {}", m.support, motion_text(&m.motion));
        }
    }
    let _ = writeln!(
        s,
        "observations ({} points), misfit {:.4} tolerances in total, largest {}:",
        r.observations.len(),
        r.total_misfit,
        Length::Opening.show(r.max_misfit)
    );
    for o in r
        .observations
        .iter()
        .filter(|o| o.observed > 0.0 || o.misfit.abs() > o.tolerance)
    {
        let z = o.z.map_or(String::new(), |z| {
            format!(", {}", Length::Position.number(z))
        });
        let _ = writeln!(
            s,
            "  crack {:>3} joint {:>5} point {} at ({}, {}{z}) m: observed {}, predicted {}, misfit {}{}",
            o.crack,
            o.joint,
            o.point,
            Length::Position.number(o.x),
            Length::Position.number(o.y),
            Length::Opening.show(o.observed),
            Length::Opening.show(o.predicted),
            Length::Opening.show_signed(o.misfit),
            if o.within_tolerance { "" } else { "  (outside tolerance)" }
        );
    }
    let odd: Vec<String> = r
        .predicted_cracks
        .iter()
        .filter(|c| c.observed != "open")
        .map(|c| {
            format!(
                "joint {} point {} ({}, {})",
                c.joint,
                c.point,
                c.observed,
                Length::Opening.show(c.opening)
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
                .enumerate()
                .map(|(i, (u, v))| format!("{} = {}", u.name, kind(i).show(*v)))
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

/// A support motion's components as the summary shows them (`u … v … θ …` in 2D, `u v w θx θy
/// θz` in 3D): translations in cm, rotations in mrad.
fn motion_text<M: serde::Serialize>(m: &M) -> String {
    let v = serde_json::to_value(m).unwrap_or_default();
    let mut parts = Vec::new();
    for (key, label, rotation) in [
        ("u", "u", false),
        ("v", "v", false),
        ("w", "w", false),
        ("theta", "θ", true),
        ("theta_x", "θx", true),
        ("theta_y", "θy", true),
        ("theta_z", "θz", true),
    ] {
        if let Some(x) = v.get(key).and_then(|x| x.as_f64()) {
            parts.push(if rotation {
                format!("{label} {:>14}", Length::Rotation.show(x))
            } else {
                format!("{label} {:>12}", Length::Motion.show(x))
            });
        }
    }
    parts.join("  ")
}
