//! `voussoir settle`: the mechanism and contact forces for prescribed support motions. The
//! flags become a `voussoir::request::SettleRequest`; the library chooses the variant
//! (canonical or not, associative or not, crushing model, friction cone) and the dimension.

use crate::common::{self, CrushingArgs, Fail, FormArgs, Input, ModelArgs, OutArgs, SettleArgs};
use crate::draw_args::DrawArgs;
use clap::Args;
use voussoir::analysis::limit::Crushing;
use voussoir::model3d::AnyModel;
use voussoir::request::{Analysis, AnyResult, Request, SettleRequest};

#[derive(Args)]
pub struct SettleCmdArgs {
    #[command(flatten)]
    pub settle: SettleArgs,
    #[command(flatten)]
    pub form: FormArgs,
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
    pub canonical: crate::canonical::CanonicalArgs,
    #[command(flatten)]
    pub adapt: crate::adapt_args::AdaptArgs,
}

/// `settle`'s flags, resolved.
pub struct SettleConfig {
    pub input: Input,
    pub request: Request,
    pub settle: SettleRequest,
}

impl SettleCmdArgs {
    pub fn resolve(&self) -> Result<SettleConfig, Fail> {
        self.draw.check()?;
        self.forces.check(&self.draw)?;
        let input = self.model.resolve()?;
        let settle = SettleRequest {
            settlement_form: self.form.settlement_form.form(),
            crushing: self.crushing.crushing(),
            facets: self.crushing.facets,
            non_associative: self.crushing.non_associative,
            raw: self.canonical.raw,
            least_friction_precision: self.canonical.least_friction_precision,
            ranges: match (self.canonical.ranges, self.canonical.no_ranges) {
                (true, _) => Some(true),
                (_, true) => Some(false),
                _ => None,
            },
            adapt: self.adapt.options()?,
        };
        let request = self
            .model
            .request(Analysis::Settle(settle), self.settle.motion()?)?;
        Ok(SettleConfig {
            input,
            request,
            settle,
        })
    }
}

pub fn run(a: SettleCmdArgs) -> Result<(), Fail> {
    a.out.check()?;
    let c = a.resolve()?;
    let model = c.input.read_any()?;
    if let AnyModel::Planar(_) = model {
        a.draw.check_2d()?;
    }
    let sr = c.settle;
    let internal = || Fail("internal: not a settlement result".into());
    match crate::adapt_args::run(
        &c.input,
        &model,
        &c.request,
        a.adapt.adapted_model.as_deref(),
    )? {
        AnyResult::Planar(run) => {
            let st = &run.setup.structure;
            let r = run.output.settlement().ok_or_else(internal)?;
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "settle",
                        crate::report_inputs::facts_2d(&run.setup.model),
                        st,
                        &c.input,
                        &run.solver,
                        crate::report_inputs::Laws {
                            cone: None,
                            crushing: Some(match sr.laws().crushing() {
                                Crushing::Linear => {
                                    voussoir_io::report_parts::CrushingModel::Linear(
                                        sr.laws().facets(),
                                    )
                                }
                                Crushing::Conic => voussoir_io::report_parts::CrushingModel::Conic,
                            }),
                            non_associative: sr.non_associative,
                        },
                        vec![(
                            "mechanism selection".into(),
                            if r.canonical.is_some() {
                                "canonical (docs/canonical.md)".into()
                            } else {
                                "the solver's own optimum".into()
                            },
                        )],
                    )
                })
                .emit_settlement(r, &c.input.path)?;
            if let Some(rec) = &run.adapt {
                return a.out.emit_split(
                    &voussoir::analysis::adapt::Adapted {
                        result: r,
                        adapt: rec,
                    },
                    &run.setup.splits,
                    || {
                        common::settle_summary(st, r)
                            + &crate::canonical::summary(&r.canonical)
                            + &crate::adapt_args::summary(rec)
                    },
                );
            }
            a.out.emit_split(r, &run.setup.splits, || {
                common::settle_summary(st, r) + &crate::canonical::summary(&r.canonical)
            })
        }
        AnyResult::Spatial(run) => {
            let st = &run.setup.structure;
            let r = run.output.settlement().ok_or_else(internal)?;
            a.draw
                .with(&a.forces)
                .with_inputs(|| {
                    crate::report_inputs::report_inputs(
                        "settle",
                        crate::report_inputs::facts_3d(&run.setup.model),
                        st,
                        &c.input,
                        &run.solver,
                        crate::report_inputs::Laws {
                            cone: Some(friction_cone(&c.input, st)),
                            crushing: None,
                            non_associative: sr.non_associative,
                        },
                        vec![(
                            "mechanism selection".into(),
                            if r.canonical.is_some() {
                                "canonical (docs/canonical.md)".into()
                            } else {
                                "the solver's own optimum".into()
                            },
                        )],
                    )
                })
                .emit_3d(r, &c.input.path)?;
            a.out.emit_split(r, &run.setup.splits, || {
                common::settle_summary(st, r) + &crate::canonical::summary(&r.canonical)
            })
        }
    }
}

/// The friction cone of a 3D analysis, for its report.
pub fn friction_cone(
    input: &common::Input,
    st: &voussoir::Structure3d,
) -> voussoir_io::report_parts::FrictionCone {
    if input.exact_friction_cone {
        voussoir_io::report_parts::FrictionCone::Exact
    } else {
        voussoir_io::report_parts::FrictionCone::Pyramid(st.friction_facets)
    }
}
