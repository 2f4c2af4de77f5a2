//! `voussoir settle`: the mechanism and contact forces for prescribed support motions.

use crate::common::{self, Fail, FormArgs, Input, ModelArgs, Motion, OutArgs, SettleArgs};
use crate::draw_args::DrawArgs;
use clap::Args;
use voussoir::analysis::canonical::settle_canonical;
use voussoir::analysis::settlement::{settle, settle_with, SettlementForm};
use voussoir::model3d::{AnyModel, Model3d};

#[derive(Args)]
pub struct SettleCmdArgs {
    #[command(flatten)]
    pub settle: SettleArgs,
    #[command(flatten)]
    pub form: FormArgs,
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
}

impl SettleCmdArgs {
    pub fn resolve(&self) -> Result<SettleConfig, Fail> {
        self.draw.check()?;
        Ok(SettleConfig {
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
    c.motion.apply(&mut model)?;
    // The model is validated first, so that a bad model is named before a missing motion.
    let st = voussoir::Structure::new(&model, c.input.build)?;
    if !common::has_support_motion(&model) {
        return Err(Fail(
            "settle needs a support motion: give --move NAME=u,v[,θ] or --profile (the model's supports do not move)"
                .into(),
        ));
    }
    let r = match (a.canonical.options(), c.form) {
        (Some(o), form) => settle_canonical(&st, &c.input.solver, form, &o)?,
        (None, SettlementForm::Both) => settle(&st, &c.input.solver)?,
        (None, form) => settle_with(&st, &c.input.solver, form)?,
    };
    a.draw.with(&a.forces).emit_settlement(&r, &c.input.path)?;
    a.out.emit(&r, || {
        common::settle_summary(&st, &r) + &crate::canonical::summary(&r.canonical)
    })
}

fn run3d(a: &SettleCmdArgs, c: &SettleConfig, mut model: Model3d) -> Result<(), Fail> {
    c.motion.apply(&mut model)?;
    let st = voussoir::Structure3d::new(&model, c.input.build)?;
    for w in model.warnings() {
        eprintln!("warning: {w}");
    }
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
    let r = match c.form {
        SettlementForm::Both => settle(&st, &c.input.solver3d)?,
        form => settle_with(&st, &c.input.solver3d, form)?,
    };
    a.draw.emit_3d(&r, &c.input.path)?;
    a.out.emit(&r, || {
        common::settle_summary(&st, &r) + &crate::canonical::summary(&r.canonical)
    })
}
