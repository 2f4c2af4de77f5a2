//! Safety under the dead loads: does the structure stand, its geometric safety factor, the
//! ranges of its support reactions.

use super::{invalid, Request};
use crate::analysis::safety::SafetyOptions;
use crate::error::Result;
use crate::lp::SolverOptions;
use serde::{Deserialize, Serialize};

/// Options of a safety assessment. Defaults: bisection tolerance 1e-6 on the joint fraction,
/// the reaction ranges computed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SafetyRequest {
    /// Absolute tolerance of the bisection on the joint fraction (the geometric safety factor
    /// is 1 / that fraction); between 0 and 1.
    pub bisection_tolerance: f64,
    /// Leave out the ranges of the support reactions.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub no_ranges: bool,
}

impl Default for SafetyRequest {
    fn default() -> Self {
        SafetyRequest {
            bisection_tolerance: 1e-6,
            no_ranges: false,
        }
    }
}

impl SafetyRequest {
    pub(super) fn validate(&self, req: &Request) -> Result<()> {
        let n = req.names;
        let tol = self.bisection_tolerance;
        if !(tol.is_finite() && tol > 0.0 && tol < 1.0) {
            return invalid(format!(
                "{}: must be a number between 0 and 1",
                n.given("bisection_tolerance", tol)
            ));
        }
        if tol < super::MIN_BISECTION_TOLERANCE {
            // Finer than a double resolves in [0, 1]: the bisection never ended (session 24:
            // 1e-300 ran for minutes until killed).
            return invalid(format!(
                "{}: below {:e}, finer than the bisection can resolve (it would never end)",
                n.given("bisection_tolerance", tol),
                super::MIN_BISECTION_TOLERANCE
            ));
        }
        req.model.refuse_exact_cone(
            n,
            " does not apply to `safety` (its programs are LPs: the inscribed pyramid)",
        )
    }

    /// The analysis's options: `solver` for every program, the bisection's decisions by
    /// `decisions` where given.
    pub fn options(
        &self,
        solver: SolverOptions,
        decisions: Option<SolverOptions>,
    ) -> SafetyOptions {
        SafetyOptions {
            tolerance: self.bisection_tolerance,
            reactions: !self.no_ranges,
            solver,
            decisions,
        }
    }
}
