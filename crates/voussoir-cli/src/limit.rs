//! `voussoir limit`: classic limit analysis, with a choice of crushing model.

use crate::common::{CrushingArg, Fail, Input, ModelArgs, OutArgs};
use crate::draw_args::DrawArgs;
use clap::Args;
use voussoir::analysis::canonical::limit_canonical;
use voussoir::analysis::limit::{limit_with, Crushing, MAX_FACETS, MIN_FACETS};
use voussoir::model3d::AnyModel;

/// Facets of the inscribed crushing polygon when --facets is not given.
const DEFAULT_FACETS: usize = 16;

#[derive(Args)]
pub struct LimitArgs {
    /// Finite-strength (crushing) model; matters only where a compressive strength is given
    /// (--compressive-strength or the model's materials).
    #[arg(long, value_enum, default_value = "linear", ignore_case = true)]
    pub crushing: CrushingArg,
    /// Facets (chords) of the inscribed crushing polygon of --crushing linear; more facets,
    /// closer to the exact cone [default: 16].
    #[arg(long, value_name = "N")]
    pub facets: Option<usize>,
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
        let crushing = match self.crushing {
            CrushingArg::Linear => Crushing::Linear,
            CrushingArg::Conic => Crushing::Conic,
        };
        let facets = match (self.crushing, self.facets) {
            (CrushingArg::Conic, Some(_)) => {
                return Err(Fail(
                    "--facets applies to --crushing linear (the conic model is the exact cone)"
                        .into(),
                ))
            }
            (_, Some(n)) if !(MIN_FACETS..=MAX_FACETS).contains(&n) => {
                return Err(Fail(format!(
                    "--facets {n}: the crushing polygon needs between {MIN_FACETS} and {MAX_FACETS} facets"
                )))
            }
            (_, Some(n)) => n,
            (_, None) => DEFAULT_FACETS,
        };
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
            let st = c.input.structure_of(model, None)?;
            // The canonical selection is among LP optima (the conic model's optimum is an
            // interior point of a cone program: reported as solved).
            let r = match (a.canonical.options(), c.crushing) {
                (Some(o), Crushing::Linear) => limit_canonical(&st, &c.input.solver, c.facets, &o)?,
                _ => limit_with(&st, &c.input.solver, c.crushing, c.facets)?,
            };
            a.draw.with(&a.forces).emit_limit(&r, &c.input.path)?;
            a.out.emit(&r, || {
                crate::common::limit_summary(&st, &r) + &crate::canonical::summary(&r.canonical)
            })
        }
        AnyModel::Spatial(model) => {
            if c.crushing == Crushing::Conic || a.facets.is_some() {
                return Err(Fail(
                    "--crushing and --facets describe finite compressive strength, which is modelled in 2D only (3D: --friction-cone exact for the exact friction cone)".into(),
                ));
            }
            let st = c.input.structure3d(model, None)?;
            let cone = if c.input.exact_friction_cone {
                Crushing::Conic
            } else {
                Crushing::Linear
            };
            let r = match (a.canonical.options(), cone) {
                (Some(o), Crushing::Linear) => {
                    limit_canonical(&st, &c.input.solver3d, DEFAULT_FACETS, &o)?
                }
                _ => limit_with(&st, &c.input.solver3d, cone, DEFAULT_FACETS)?,
            };
            a.draw.emit_3d(&r, &c.input.path)?;
            a.out.emit(&r, || {
                crate::common::limit_summary(&st, &r) + &crate::canonical::summary(&r.canonical)
            })
        }
    }
}
