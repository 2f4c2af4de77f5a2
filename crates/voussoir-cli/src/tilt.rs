//! `voussoir tilt`: critical tilt angle of a tilting-table test.

use crate::common::{Fail, ModelArgs, OutArgs};
use crate::direction::Direction;
use clap::Args;
use std::fmt::Write as _;
use voussoir::model3d::AnyModel;
use voussoir::request::{Analysis, AnyResult, SupportMotion, TiltRequest};

#[derive(Args)]
pub struct TiltArgs {
    /// Direction the table tilts towards (the structure tends to fall that way) [default: +x]:
    /// +x, -x, +y, -y, an azimuth in degrees from +x towards +y (any finite angle, taken
    /// modulo 360°) or a horizontal vector DX,DY. A 2D model tilts along x: +x or -x (0 or 180).
    /// (`--azimuth` is another name of this flag.)
    #[arg(
        long,
        alias = "azimuth",
        value_name = "DIR",
        allow_hyphen_values = true,
        value_parser = crate::direction::parse
    )]
    pub direction: Option<Direction>,
    #[command(flatten)]
    pub canonical: crate::canonical::RawArgs,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub draw: crate::draw_args::DrawArgs,
    #[command(flatten)]
    pub forces: crate::draw_args::ForcesArgs,
}

pub fn run(a: TiltArgs) -> Result<(), Fail> {
    a.out.check()?;
    a.draw.check()?;
    a.forces.check(&a.draw)?;
    let input = a.model.resolve()?;
    let given = a
        .direction
        .clone()
        .unwrap_or(Direction::Axis { axis: 0, sign: 1.0 });
    let tilt = TiltRequest {
        azimuth: given.azimuth("--direction").map_err(Fail)?,
        label: Some(given.text()),
        raw: a.canonical.raw,
    };
    // In 3D every direction is an azimuth: +x is 0°, -x 180°, +y 90°.
    let az = tilt.normalised();
    let req = a
        .model
        .request(Analysis::Tilt(tilt), SupportMotion::default())?;
    let model = input.read_any()?;
    if let AnyModel::Planar(_) = model {
        a.draw.check_2d()?;
    }
    let internal = || Fail("internal: not a tilt result".into());
    match input.run(&model, &req)? {
        AnyResult::Spatial(run) => {
            let st = &run.setup.structure;
            let r = run.output.tilt().ok_or_else(internal)?;
            let towards = match given.axis_name() {
                Some(axis) => format!("{axis} (azimuth {az}°)"),
                None => format!("azimuth {az}°"),
            };
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "tilt",
                        crate::report_inputs::facts_3d(&run.setup.model),
                        st,
                        &input,
                        &run.solver,
                        crate::report_inputs::Laws {
                            cone: Some(crate::settle::friction_cone(&input, st)),
                            ..Default::default()
                        },
                        vec![("tilt towards".into(), towards.clone())],
                    )
                })
                .emit_3d(r, &input.path)?;
            a.out.emit(r, || {
                let mut s = String::new();
                let _ = writeln!(s, "{}", crate::common::structure_line(st));
                match r.tilt_angle {
                    Some(t) => {
                        let _ = writeln!(
                            s,
                            "critical tilt angle {t:.4}° towards {towards} (tan α = λ = {:.6})",
                            t.to_radians().tan()
                        );
                    }
                    None => {
                        let _ = writeln!(s, "{}", r.limit.message);
                    }
                }
                s.push_str(&crate::canonical::summary(&r.limit.canonical));
                s
            })
        }
        AnyResult::Planar(run) => {
            let st = &run.setup.structure;
            let r = run.output.tilt().ok_or_else(internal)?;
            let dir = r.direction;
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "tilt",
                        crate::report_inputs::facts_2d(&run.setup.model),
                        st,
                        &input,
                        &run.solver,
                        crate::report_inputs::Laws::default(),
                        vec![(
                            "tilt towards".into(),
                            if dir > 0.0 { "+x" } else { "−x" }.to_string(),
                        )],
                    )
                })
                .emit_tilt(r, &input.path)?;
            a.out.emit(r, || {
                let mut s = String::new();
                let _ = writeln!(s, "{}", crate::common::structure_line(st));
                match r.tilt_angle {
                    Some(t) => {
                        let _ = writeln!(
                            s,
                            "critical tilt angle {t:.4}° towards {}x (tan α = λ = {:.6})",
                            if dir > 0.0 { "+" } else { "−" },
                            t.to_radians().tan()
                        );
                    }
                    None => {
                        let _ = writeln!(s, "{}", r.limit.message);
                    }
                }
                s.push_str(&crate::canonical::summary(&r.limit.canonical));
                s
            })
        }
    }
}
