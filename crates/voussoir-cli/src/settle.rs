//! `voussoir settle`: the mechanism and contact forces for prescribed support motions.

use crate::common::{
    self, CrushingArgs, Fail, FormArgs, Input, ModelArgs, Motion, OutArgs, SettleArgs,
};
use crate::draw_args::DrawArgs;
use clap::Args;
use voussoir::analysis::canonical::settle_canonical;
use voussoir::analysis::limit::{Crushing, DEFAULT_FACETS};
use voussoir::analysis::nonassociative::settle_nonassociative;
use voussoir::analysis::settlement::{settle, settle_crushing, settle_with, SettlementForm};
use voussoir::model3d::{AnyModel, Model3d};

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
}

/// `settle`'s flags, resolved.
pub struct SettleConfig {
    pub input: Input,
    pub motion: Motion,
    pub form: SettlementForm,
    pub crushing: Crushing,
    pub facets: usize,
}

impl SettleCmdArgs {
    pub fn resolve(&self) -> Result<SettleConfig, Fail> {
        self.draw.check()?;
        let (crushing, facets) = self.crushing.resolve()?;
        if (self.crushing.given() || self.crushing.non_associative)
            && self.form.settlement_form.form() != SettlementForm::Both
        {
            return Err(Fail(
                "--crushing, --facets and --non-associative go with --settlement-form both (the default)"
                    .into(),
            ));
        }
        if self.model.friction_cone == Some(crate::common::FrictionConeArg::Exact) {
            if self.crushing.non_associative {
                return Err(Fail(
                    "--non-associative goes with the friction pyramid, not --friction-cone exact"
                        .into(),
                ));
            }
            if self.form.settlement_form.form() != SettlementForm::Both {
                return Err(Fail(
                    "--friction-cone exact goes with --settlement-form both (the default): the cone program is solved whole".into(),
                ));
            }
        }
        Ok(SettleConfig {
            crushing,
            facets,
            input: self.model.resolve()?,
            motion: self.settle.resolve()?,
            form: self.form.settlement_form.form(),
        })
    }
}

pub fn run(a: SettleCmdArgs) -> Result<(), Fail> {
    let c = a.resolve()?;
    let mut model = match c.input.load_any()? {
        AnyModel::Planar(m) => m,
        AnyModel::Spatial(m) => return run3d(&a, &c, m),
    };
    a.draw.check_2d()?;
    let splits = c.motion.apply(&mut model)?;
    // The model is validated first, so that a bad model is named before a missing motion.
    let st = c.input.structure_of(model.clone(), None)?;
    a.crushing.check_strength(&st)?;
    if !common::has_support_motion(&model) {
        return Err(Fail(
            "settle needs a support motion: give --move NAME=u,v[,θ] or --profile (the model's supports do not move)"
                .into(),
        ));
    }
    // Joint laws beyond the defaults (non-associative iteration, exact cone, other facet
    // counts) are solved as such; otherwise the canonical selection unless --raw.
    let plain = c.crushing == Crushing::Linear && c.facets == DEFAULT_FACETS;
    let r = match (
        c.form,
        a.crushing.non_associative_settlement(),
        a.canonical.options(),
    ) {
        (SettlementForm::Both, Some(o), _) => settle_nonassociative(
            &st,
            &common::iteration_solver(&a.model, &c.input.solver_for(&st)),
            c.crushing,
            c.facets,
            &o,
        )?,
        (form, None, Some(o)) if plain => {
            settle_canonical(&st, &c.input.solver_for(&st), form, &o)?
        }
        (SettlementForm::Both, None, _) => {
            settle_crushing(&st, &c.input.solver_for(&st), c.crushing, c.facets)?
        }
        (form, _, _) => settle_with(&st, &c.input.solver_for(&st), form)?,
    };
    let solver = if a.crushing.non_associative_settlement().is_some() {
        common::iteration_solver(&a.model, &c.input.solver_for(&st))
    } else {
        c.input.solver
    };
    a.draw
        .with(&a.forces)
        .with_inputs(|| {
            crate::report_inputs::report_inputs(
                "settle",
                crate::report_inputs::facts_2d(&model),
                &st,
                &c.input,
                &solver,
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
        .emit_settlement(&r, &c.input.path)?;
    a.out.emit_split(&r, &splits, || {
        common::settle_summary(&st, &r) + &crate::canonical::summary(&r.canonical)
    })
}

fn run3d(a: &SettleCmdArgs, c: &SettleConfig, mut model: Model3d) -> Result<(), Fail> {
    if a.crushing.given() {
        return Err(Fail(
            "--crushing and --facets describe finite compressive strength, which is modelled in 2D only".into(),
        ));
    }
    // --friction-facets and --friction-cone are honoured here (as by limit and tilt).
    let splits = c.motion.apply(&mut model)?;
    let st = c.input.structure3d_any_cone(model.clone(), None)?;
    if !model
        .supports
        .iter()
        .any(|s| s.motion.iter().any(|x| *x != 0.0))
    {
        return Err(Fail(
            "settle needs a support motion: give --move NAME=u,v,w[,θx,θy,θz] or --profile (the model's supports do not move)"
                .into(),
        ));
    }
    // 3D: the solver's own solution (the canonical selection is not yet fast enough on 3D
    // models; docs/canonical.md).
    let r = match (c.form, a.crushing.non_associative_settlement()) {
        (SettlementForm::Both, Some(o)) => settle_nonassociative(
            &st,
            &common::iteration_solver(&a.model, &c.input.solver_for(&st)),
            Crushing::Linear,
            DEFAULT_FACETS,
            &o,
        )?,
        // The exact friction cone: the force program with a second-order cone per frictional
        // point (Clarabel), the mechanism from its equilibrium duals.
        (SettlementForm::Both, None) if c.input.exact_friction_cone => settle_crushing(
            &st,
            &c.input.solver_for(&st),
            Crushing::Conic,
            DEFAULT_FACETS,
        )?,
        (SettlementForm::Both, None) => settle(&st, &c.input.solver_for(&st))?,
        (form, _) => settle_with(&st, &c.input.solver_for(&st), form)?,
    };
    let solver = if a.crushing.non_associative_settlement().is_some() {
        common::iteration_solver(&a.model, &c.input.solver_for(&st))
    } else {
        c.input.solver3d
    };
    a.draw
        .with(&a.forces)
        .with_inputs(|| {
            crate::report_inputs::report_inputs(
                "settle",
                crate::report_inputs::facts_3d(&model),
                &st,
                &c.input,
                &solver,
                crate::report_inputs::Laws {
                    cone: Some(friction_cone(&c.input, &st)),
                    crushing: None,
                    non_associative: a.crushing.non_associative,
                },
                vec![(
                    "mechanism selection".into(),
                    "the solver's own optimum (3D)".into(),
                )],
            )
        })
        .emit_3d(&r, &c.input.path)?;
    a.out.emit_split(&r, &splits, || {
        common::settle_summary(&st, &r) + &crate::canonical::summary(&r.canonical)
    })
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
