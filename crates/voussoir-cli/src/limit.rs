//! `voussoir limit`: classic limit analysis, with a choice of crushing model. The flags become
//! a `voussoir::request::LimitRequest`; the library chooses the variant and the dimension.

use crate::common::{CrushingArgs, Fail, Input, ModelArgs, OutArgs};
use crate::draw_args::DrawArgs;
use clap::Args;
use voussoir::analysis::limit::Crushing;
use voussoir::model3d::AnyModel;
use voussoir::request::{Analysis, AnyResult, LimitRequest, Request, SupportMotion};

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
    #[command(flatten)]
    pub adapt: crate::adapt_args::AdaptArgs,
}

/// `limit`'s flags, resolved.
pub struct LimitConfig {
    pub input: Input,
    pub request: Request,
    pub limit: LimitRequest,
}

impl LimitArgs {
    pub fn resolve(&self) -> Result<LimitConfig, Fail> {
        self.draw.check()?;
        self.forces.check(&self.draw)?;
        let input = self.model.resolve()?;
        let limit = LimitRequest {
            crushing: self.crushing.crushing(),
            facets: self.crushing.facets,
            non_associative: self.crushing.non_associative,
            canonical: self.canonical.canonical,
            least_friction_precision: self.canonical.least_friction_precision,
            ranges: self.canonical.no_ranges.then_some(false),
            adapt: {
                if self.adapt.adapt_global.is_some() || self.adapt.adapt_fan.is_some() {
                    return Err(Fail(
                        "--adapt-global and --adapt-fan apply to settle --adapt only (limit --adapt has no global stage)".into(),
                    ));
                }
                self.adapt.options()?
            },
        };
        let request = self
            .model
            .request(Analysis::Limit(limit), SupportMotion::default())?;
        Ok(LimitConfig {
            input,
            request,
            limit,
        })
    }
}

pub fn run(a: LimitArgs) -> Result<(), Fail> {
    a.out.check()?;
    let c = a.resolve()?;
    let model = c.input.read_any()?;
    if let AnyModel::Planar(_) = model {
        a.draw.check_2d()?;
    }
    let lr = c.limit;
    match crate::adapt_args::run(
        &c.input,
        &model,
        &c.request,
        a.adapt.adapted_model.as_deref(),
    )? {
        AnyResult::Planar(run) => {
            let st = &run.setup.structure;
            let r = run
                .output
                .limit()
                .ok_or_else(|| Fail("internal: not a limit result".into()))?;
            let facts = crate::report_inputs::facts_2d(&run.setup.model);
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "limit",
                        facts,
                        st,
                        &c.input,
                        &run.solver,
                        crate::report_inputs::Laws {
                            cone: None,
                            crushing: Some(match lr.laws().crushing() {
                                Crushing::Linear => {
                                    voussoir_io::report_parts::CrushingModel::Linear(
                                        lr.laws().facets(),
                                    )
                                }
                                Crushing::Conic => voussoir_io::report_parts::CrushingModel::Conic,
                            }),
                            non_associative: lr.non_associative,
                        },
                        Vec::new(),
                    )
                })
                .emit_limit(r, &c.input.path)?;
            if let Some(rec) = &run.adapt {
                return a.out.emit(
                    &voussoir::analysis::adapt::Adapted {
                        result: r,
                        adapt: rec,
                    },
                    || {
                        crate::common::limit_summary(st, r)
                            + &crate::canonical::summary(&r.canonical)
                            + &crate::adapt_args::summary(rec)
                    },
                );
            }
            a.out.emit(r, || {
                crate::common::limit_summary(st, r) + &crate::canonical::summary(&r.canonical)
            })
        }
        AnyResult::Spatial(run) => {
            let st = &run.setup.structure;
            let r = run
                .output
                .limit()
                .ok_or_else(|| Fail("internal: not a limit result".into()))?;
            let facts = crate::report_inputs::facts_3d(&run.setup.model);
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "limit",
                        facts,
                        st,
                        &c.input,
                        &run.solver,
                        crate::report_inputs::Laws {
                            cone: Some(crate::settle::friction_cone(&c.input, st)),
                            crushing: None,
                            non_associative: lr.non_associative,
                        },
                        Vec::new(),
                    )
                })
                .emit_3d(r, &c.input.path)?;
            a.out.emit(r, || {
                crate::common::limit_summary(st, r) + &crate::canonical::summary(&r.canonical)
            })
        }
    }
}
