//! `voussoir tilt`: critical tilt angle of a tilting-table test.

use crate::common::{Fail, ModelArgs, OutArgs};
use crate::direction::Direction;
use clap::Args;
use std::fmt::Write as _;
use voussoir::model3d::AnyModel;

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
    pub model: ModelArgs,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub draw: crate::draw_args::DrawArgs,
    #[command(flatten)]
    pub forces: crate::draw_args::ForcesArgs,
}

pub fn run(a: TiltArgs) -> Result<(), Fail> {
    a.draw.check()?;
    let input = a.model.resolve()?;
    let given = a
        .direction
        .clone()
        .unwrap_or(Direction::Axis { axis: 0, sign: 1.0 });
    let azimuth = normalise_azimuth(given.azimuth("--direction").map_err(Fail)?)?;
    let model = match input.load_any()? {
        AnyModel::Planar(m) => m,
        AnyModel::Spatial(m) => {
            let facts = crate::report_inputs::facts_3d(&m);
            let st = input.structure3d_any_cone(m, None)?;
            // In 3D every direction is an azimuth: +x is 0°, -x 180°, +y 90°.
            let az = azimuth;
            let towards = match given.axis_name() {
                Some(axis) => format!("{axis} (azimuth {az}°)"),
                None => format!("azimuth {az}°"),
            };
            let r = if input.exact_friction_cone {
                voussoir::analysis::tilt::tilt_azimuth_exact(&st, az, &input.solver_for(&st))?
            } else {
                voussoir::analysis::tilt::tilt_azimuth(&st, az, &input.solver_for(&st))?
            };
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "tilt",
                        facts,
                        &st,
                        &input,
                        &input.solver_for(&st),
                        crate::report_inputs::Laws {
                            cone: Some(crate::settle::friction_cone(&input, &st)),
                            ..Default::default()
                        },
                        vec![("tilt towards".into(), towards.clone())],
                    )
                })
                .emit_3d(&r, &input.path)?;
            return a.out.emit(&r, || {
                let mut s = String::new();
                let _ = writeln!(s, "{}", crate::common::structure_line(&st));
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
                s
            });
        }
    };
    // A 2D model tilts along its x axis: azimuth 0° (+x) or 180° (-x).
    let dir = if azimuth == 0.0 {
        1.0
    } else if azimuth == 180.0 {
        -1.0
    } else {
        return Err(Fail(format!(
            "--direction {}: a 2D model tilts along x: +x or -x (azimuth 0 or 180)",
            given.text()
        )));
    };
    a.draw.check_2d()?;
    let facts = crate::report_inputs::facts_2d(&model);
    let st = input.structure_of(model, None)?;
    let r = voussoir::analysis::tilt::tilt(&st, dir, &input.solver_for(&st))?;
    a.draw
        .with(&a.forces)
        .with_inputs(|| {
            crate::report_inputs::report_inputs(
                "tilt",
                facts,
                &st,
                &input,
                &input.solver_for(&st),
                crate::report_inputs::Laws::default(),
                vec![(
                    "tilt towards".into(),
                    if dir > 0.0 { "+x" } else { "−x" }.to_string(),
                )],
            )
        })
        .emit_tilt(&r, &input.path)?;
    a.out.emit(&r, || {
        let mut s = String::new();
        let _ = writeln!(s, "blocks {}, joints {}", st.blocks.len(), st.joints.len());
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
        s
    })
}

/// The azimuth of `--direction` checked (finite) and taken into [0, 360).
fn normalise_azimuth(az: f64) -> Result<f64, Fail> {
    if !az.is_finite() {
        return Err(Fail(format!(
            "--direction {az}: must be a finite number of degrees"
        )));
    }
    let r = az.rem_euclid(360.0);
    // rem_euclid rounds a tiny negative angle up to 360 itself; -0 prints as "-0".
    Ok(if r >= 360.0 || r == 0.0 { 0.0 } else { r })
}
