//! `voussoir settle`: the mechanism and contact forces for prescribed support motions.

use crate::common::{self, Fail, FormArgs, Input, ModelArgs, Motion, OutArgs, SettleArgs};
use crate::draw_args::DrawArgs;
use clap::Args;
use voussoir::analysis::settlement::{settle, settle_with, SettlementForm};

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
    let mut model = c.input.load()?;
    c.motion.apply(&mut model)?;
    // The model is validated first, so that a bad model is named before a missing motion.
    let st = voussoir::Structure::new(&model, c.input.build)?;
    if !common::has_support_motion(&model) {
        return Err(Fail(
            "settle needs a support motion: give --move NAME=u,v[,θ] or --profile (the model's supports do not move)"
                .into(),
        ));
    }
    let r = match c.form {
        SettlementForm::Both => settle(&st, &c.input.solver)?,
        form => settle_with(&st, &c.input.solver, form)?,
    };
    a.draw.with(&a.forces).emit_settlement(&r, &c.input.path)?;
    a.out.emit(&r, || common::settle_summary(&st, &r))
}
