//! `voussoir tilt`: critical tilt angle of a tilting-table test.

use crate::common::{Fail, ModelArgs, OutArgs};
use clap::{Args, ValueEnum};
use std::fmt::Write as _;
use voussoir::model3d::AnyModel;

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum TiltDirection {
    /// Towards +x (to the right): the horizontal load λ·W points along +x.
    #[value(name = "+x", alias = "x", alias = "right", alias = "positive")]
    PlusX,
    /// Towards −x (to the left).
    #[value(name = "-x", alias = "left", alias = "negative")]
    MinusX,
}

#[derive(Args)]
pub struct TiltArgs {
    /// Direction the table tilts towards (the structure tends to fall that way) [default: +x].
    /// In 3D, +x is azimuth 0° and -x azimuth 180°.
    #[arg(
        long,
        value_enum,
        allow_hyphen_values = true,
        ignore_case = true,
        conflicts_with = "azimuth"
    )]
    pub direction: Option<TiltDirection>,
    /// 3D models: azimuth of the tilt in degrees from x towards y (the structure tends to fall
    /// that way; default 0, towards +x); any finite angle, taken modulo 360°.
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub azimuth: Option<f64>,
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
    let dir = match a.direction.unwrap_or(TiltDirection::PlusX) {
        TiltDirection::PlusX => 1.0,
        TiltDirection::MinusX => -1.0,
    };
    let azimuth = a.azimuth.map(normalise_azimuth).transpose()?;
    let model = match input.load_any()? {
        AnyModel::Planar(m) => m,
        AnyModel::Spatial(m) => {
            let facts = crate::report_inputs::facts_3d(&m);
            let st = input.structure3d_any_cone(m, None)?;
            // --direction in 3D: +x is azimuth 0°, -x azimuth 180°.
            let (az, towards) = match (azimuth, a.direction) {
                (Some(az), _) => (az, format!("azimuth {az}°")),
                (None, Some(TiltDirection::MinusX)) => (180.0, "−x (azimuth 180°)".to_string()),
                (None, _) => (0.0, "+x (azimuth 0°)".to_string()),
            };
            let r = if input.exact_friction_cone {
                voussoir::analysis::tilt::tilt_azimuth_exact(&st, az, &input.solver3d)?
            } else {
                voussoir::analysis::tilt::tilt_azimuth(&st, az, &input.solver3d)?
            };
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "tilt",
                        facts,
                        &st,
                        &input,
                        &input.solver3d,
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
    if a.azimuth.is_some() {
        return Err(Fail(
            "--azimuth applies to 3D models; a 2D tilt goes towards --direction +x or -x".into(),
        ));
    }
    a.draw.check_2d()?;
    let facts = crate::report_inputs::facts_2d(&model);
    let st = input.structure_of(model, None)?;
    let r = voussoir::analysis::tilt::tilt(&st, dir, &input.solver)?;
    a.draw
        .with(&a.forces)
        .with_inputs(|| {
            crate::report_inputs::report_inputs(
                "tilt",
                facts,
                &st,
                &input,
                &input.solver,
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

/// `--azimuth DEG` checked (finite) and taken into [0, 360).
fn normalise_azimuth(az: f64) -> Result<f64, Fail> {
    if !az.is_finite() {
        return Err(Fail(format!(
            "--azimuth {az}: must be a finite number of degrees"
        )));
    }
    let r = az.rem_euclid(360.0);
    // rem_euclid rounds a tiny negative angle up to 360 itself; -0 prints as "-0".
    Ok(if r >= 360.0 || r == 0.0 { 0.0 } else { r })
}
