//! `voussoir limit`: classic limit analysis, with a choice of crushing model.

use crate::common::{CrushingArgs, Fail, Input, ModelArgs, OutArgs};
use crate::draw_args::DrawArgs;
use clap::Args;
use voussoir::analysis::canonical::limit_canonical;
use voussoir::analysis::limit::{limit_with, Crushing, DEFAULT_FACETS};
use voussoir::model3d::AnyModel;

#[derive(Args)]
pub struct LimitArgs {
    #[command(flatten)]
    pub crushing: CrushingArgs,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub draw: DrawArgs,
    #[command(flatten)]
    pub forces: crate::draw_args::ForcesArgs,
    #[command(flatten)]
    pub canonical: crate::canonical::LimitCanonicalArgs,
}

/// `limit`'s flags, resolved.
pub struct LimitConfig {
    pub input: Input,
    pub crushing: Crushing,
    pub facets: usize,
}

impl LimitArgs {
    pub fn resolve(&self) -> Result<LimitConfig, Fail> {
        let (crushing, facets) = self.crushing.resolve()?;
        self.draw.check()?;
        Ok(LimitConfig {
            input: self.model.resolve()?,
            crushing,
            facets,
        })
    }
}

pub fn run(a: LimitArgs) -> Result<(), Fail> {
    let c = a.resolve()?;
    match c.input.load_any()? {
        AnyModel::Planar(model) => {
            a.draw.check_2d()?;
            let facts = crate::report_inputs::facts_2d(&model);
            let st = c.input.structure_of(model, None)?;
            a.crushing.check_strength(&st)?;
            let r = match (
                a.crushing.non_associative(),
                a.canonical.options(),
                c.crushing,
            ) {
                (Some(_), _, Crushing::Conic) => {
                    return Err(Fail(
                        "--non-associative goes with --crushing linear (each iterate is an LP)"
                            .into(),
                    ))
                }
                (Some(o), _, _) => voussoir::analysis::nonassociative::limit_nonassociative_result(
                    &st,
                    &c.input.solver_for(&st),
                    &o,
                )?,
                // The canonical selection is among LP optima (the conic model's optimum is an
                // interior point of a cone program: reported as solved).
                (None, Some(o), Crushing::Linear) => {
                    limit_canonical(&st, &c.input.solver_for(&st), c.facets, &o)?
                }
                _ => limit_with(&st, &c.input.solver_for(&st), c.crushing, c.facets)?,
            };
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "limit",
                        facts,
                        &st,
                        &c.input,
                        &c.input.solver_for(&st),
                        crate::report_inputs::Laws {
                            cone: None,
                            crushing: Some(match c.crushing {
                                Crushing::Linear => {
                                    voussoir_io::report_parts::CrushingModel::Linear(c.facets)
                                }
                                Crushing::Conic => voussoir_io::report_parts::CrushingModel::Conic,
                            }),
                            non_associative: a.crushing.non_associative,
                        },
                        Vec::new(),
                    )
                })
                .emit_limit(&r, &c.input.path)?;
            a.out.emit(&r, || {
                crate::common::limit_summary(&st, &r) + &crate::canonical::summary(&r.canonical)
            })
        }
        AnyModel::Spatial(model) => {
            if a.crushing.given() {
                return Err(Fail(
                    "--crushing and --facets describe finite compressive strength, which is modelled in 2D only (3D: --friction-cone exact for the exact friction cone)".into(),
                ));
            }
            let facts = crate::report_inputs::facts_3d(&model);
            let st = c.input.structure3d_any_cone(model, None)?;
            let cone = if c.input.exact_friction_cone {
                Crushing::Conic
            } else {
                Crushing::Linear
            };
            let r = match (a.crushing.non_associative(), a.canonical.options(), cone) {
                (Some(o), _, Crushing::Linear) => {
                    voussoir::analysis::nonassociative::limit_nonassociative_result(
                        &st,
                        &c.input.solver_for(&st),
                        &o,
                    )?
                }
                (Some(_), _, _) => return Err(Fail(
                    "--non-associative goes with the friction pyramid, not --friction-cone exact"
                        .into(),
                )),
                (None, Some(o), Crushing::Linear) => {
                    limit_canonical(&st, &c.input.solver_for(&st), DEFAULT_FACETS, &o)?
                }
                _ => limit_with(&st, &c.input.solver_for(&st), cone, DEFAULT_FACETS)?,
            };
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "limit",
                        facts,
                        &st,
                        &c.input,
                        &c.input.solver_for(&st),
                        crate::report_inputs::Laws {
                            cone: Some(crate::settle::friction_cone(&c.input, &st)),
                            crushing: None,
                            non_associative: a.crushing.non_associative,
                        },
                        Vec::new(),
                    )
                })
                .emit_3d(&r, &c.input.path)?;
            a.out.emit(&r, || {
                crate::common::limit_summary(&st, &r) + &crate::canonical::summary(&r.canonical)
            })
        }
    }
}
