//! The options every analysis shares (the CLI's `ModelArgs` and `SettleArgs`,
//! crates/voussoir-cli/src/common.rs), received from Python as dicts, and the one-line failure.
//!
//! The CLI's versions live in its binary crate and cannot be called from here; this is the same
//! sequence of library calls (load → override materials → apply settlement → `Structure::new`),
//! with messages naming the Python keyword instead of the flag.

use pyo3::prelude::*;
use voussoir::analysis::settlement::SettlementForm;
use voussoir::lp::{Method, SolverOptions};
use voussoir::request::{Move, Names, SupportMotion};
use voussoir::settlement_input::{Profile, SupportSplit};
use voussoir::{BuildOptions, Model, Structure};

/// A failure: one line; `Solver` for the solver's own failures, `Option` for an option of a
/// request out of range or in conflict (`voussoir.OptionError`, a `ModelError` and a
/// `ValueError`), `Model` for everything else.
#[derive(Debug)]
pub enum Fail {
    Model(String),
    Solver(String),
    Option(String),
}

impl From<voussoir::Error> for Fail {
    fn from(e: voussoir::Error) -> Self {
        match e {
            voussoir::Error::Solver(_) => Fail::Solver(e.to_string()),
            voussoir::Error::Invalid(_) => Fail::Option(e.to_string()),
            _ => Fail::Model(e.to_string()),
        }
    }
}
impl From<voussoir_io::IoError> for Fail {
    fn from(e: voussoir_io::IoError) -> Self {
        Fail::Model(e.0)
    }
}

/// `ModelArgs` of the CLI: how to read, build and solve.
#[derive(FromPyObject, Clone, Debug)]
#[pyo3(from_item_all)]
pub struct Common {
    pub tolerance: Option<f64>,
    pub method: String,
    pub friction: Option<f64>,
    pub compressive_strength: Option<f64>,
    pub settlement_form: String,
}

/// `SettleArgs` of the CLI: moves (as parsed by the library: name, values with θ in degrees,
/// whether a third value carried a length unit), fixed supports, a profile (as `Profile` JSON).
#[derive(FromPyObject, Clone, Debug, Default)]
#[pyo3(from_item_all)]
pub struct Settle {
    pub moves: Vec<(String, Vec<f64>, bool)>,
    pub fixed: Vec<String>,
    pub profile: Option<String>,
}

impl Settle {
    /// Apply the fixed supports, moves and profile (as drawn: a support spanning one of its
    /// breakpoints is cut there first), by the library's request layer, as the CLI does; the
    /// supports cut.
    pub fn apply(&self, model: &mut Model) -> Result<Vec<SupportSplit>, Fail> {
        Ok(self.motion()?.apply(model, Names::Keywords)?)
    }

    /// The request's support motion.
    pub fn motion(&self) -> Result<SupportMotion, Fail> {
        let profile = match &self.profile {
            // The profile arrives as the JSON of `Profile` (`_native.motion` parsed the text).
            Some(p) => {
                let profile: Profile = serde_json::from_str(p)
                    .map_err(|e| Fail::Model(format!("invalid settlement profile: {e}")))?;
                profile.validate()?;
                Some(profile)
            }
            None => None,
        };
        Ok(SupportMotion {
            moves: self
                .moves
                .iter()
                .map(|(support, values, third_with_unit)| Move {
                    support: support.clone(),
                    values: values.clone(),
                    third_with_unit: *third_with_unit,
                })
                .collect(),
            fixed: self.fixed.clone(),
            profile,
            splits: Vec::new(),
        })
    }
}

impl Common {
    pub fn solver(&self) -> Result<SolverOptions, Fail> {
        let method = match self.method.as_str() {
            "dual-simplex" => Method::DualSimplex,
            "primal-simplex" => Method::PrimalSimplex,
            "ipm" => Method::Ipm,
            "choose" => Method::Choose,
            "ipm-no-crossover" => Method::IpmNoCrossover,
            "pdlp" => Method::Pdlp,
            "clarabel" => Method::Clarabel,
            m => {
                return Err(Fail::Model(format!(
                    "method={m}: expected dual-simplex, primal-simplex, ipm, choose, ipm-no-crossover, pdlp or clarabel"
                )))
            }
        };
        Ok(SolverOptions {
            method,
            ..SolverOptions::default()
        })
    }

    pub fn settlement_form(&self) -> Result<SettlementForm, Fail> {
        match self.settlement_form.as_str() {
            "both" => Ok(SettlementForm::Both),
            "force-only" => Ok(SettlementForm::ForceOnly),
            f => Err(Fail::Model(format!(
                "settlement_form={f}: expected both or force-only"
            ))),
        }
    }

    /// Apply `friction` and `compressive_strength` to every material (the implicit `default`
    /// one included), as the CLI's `--friction` / `--compressive-strength` do.
    pub fn override_materials(&self, m: &mut Model) -> Result<(), Fail> {
        if let Some(mu) = self.friction {
            if !(mu.is_finite() && mu >= 0.0) {
                return Err(Fail::Model(format!(
                    "friction={mu}: must be a finite number ≥ 0"
                )));
            }
        }
        if let Some(f) = self.compressive_strength {
            if !(f.is_finite() && f > 0.0) {
                return Err(Fail::Model(format!(
                    "compressive_strength={f}: must be a finite number > 0 (kPa)"
                )));
            }
        }
        m.override_joint_laws(self.friction, self.compressive_strength);
        Ok(())
    }

    /// The model with materials overridden and the settlement applied.
    pub fn model(&self, model_json: &str, settle: Option<&Settle>) -> Result<Model, Fail> {
        Ok(self.model_split(model_json, settle)?.0)
    }

    /// [`Common::model`] and the supports the settlement cut.
    pub fn model_split(
        &self,
        model_json: &str,
        settle: Option<&Settle>,
    ) -> Result<(Model, Vec<SupportSplit>), Fail> {
        let mut model = voussoir_io::files::parse_model(model_json)?;
        self.override_materials(&mut model)?;
        let splits = match settle {
            Some(s) => s.apply(&mut model)?,
            None => Vec::new(),
        };
        Ok((model, splits))
    }

    /// Load, apply the settlement, validate and discretise (the CLI's `ModelArgs::structure`).
    pub fn structure(
        &self,
        model_json: &str,
        settle: Option<&Settle>,
    ) -> Result<(Structure, SolverOptions), Fail> {
        let (st, opts, _) = self.structure_split(model_json, settle)?;
        Ok((st, opts))
    }

    /// [`Common::structure`] and the supports the settlement cut.
    pub fn structure_split(
        &self,
        model_json: &str,
        settle: Option<&Settle>,
    ) -> Result<(Structure, SolverOptions, Vec<SupportSplit>), Fail> {
        let (model, splits) = self.model_split(model_json, settle)?;
        let st = Structure::new(
            &model,
            BuildOptions {
                tolerance: self.tolerance,
            },
        )?;
        Ok((st, self.solver()?, splits))
    }
}
