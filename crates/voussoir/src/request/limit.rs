//! Limit analysis: the collapse multiplier of the live loads and the collapse mechanism.

use super::{canonical_options, invalid, JointLaws, Output, Request};
use crate::analysis::canonical::limit_canonical;
use crate::analysis::canonical_friction::limit_nonassociative_canonical;
use crate::analysis::limit::{limit_with, Crushing};
use crate::analysis::nonassociative::{limit_nonassociative_result, NonAssociativeOptions};
use crate::error::Result;
use crate::lp::SolverOptions;
use crate::structure::Assembly;
use serde::{Deserialize, Serialize};

/// Options of a limit analysis. Defaults: the inscribed crushing polygon of 16 facets,
/// associative friction, the solver's own optimum (no canonical selection).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LimitRequest {
    /// The crushing model (2D; matters only where a compressive strength is given; default
    /// linear, the inscribed polygon). Given (either value) on a model without a compressive
    /// strength, or in 3D, refused.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crushing: Option<Crushing>,
    /// Facets of the inscribed crushing polygon of `crushing: linear` (default 16).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub facets: Option<usize>,
    /// Non-associative Coulomb friction (the fixed-point iteration; docs/joint-laws.md).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub non_associative: bool,
    /// Report the canonical collapse mechanism and forces (docs/canonical.md) instead of the
    /// solver's own optimum.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub canonical: bool,
    /// With `canonical`: the ranges of the support reactions — absent: on 2D models of at most
    /// 500 blocks (not in 3D); true: always; false: never.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ranges: Option<bool>,
    /// With the canonical selection: the relative precision of the least friction coefficient
    /// of the joints without friction of their own (a bisection; default 0.05, in (0, 1)).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub least_friction_precision: Option<f64>,
    /// Mesh-independent cracks (2D): crack lines cut into the mesh and moved to their optimal
    /// position before the analysis runs on the adapted mesh (docs/cracks.md).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub adapt: Option<crate::analysis::adapt::AdaptOptions>,
}

impl LimitRequest {
    /// The joint-law options.
    pub fn laws(&self) -> JointLaws {
        JointLaws {
            crushing: self.crushing,
            facets: self.facets,
            non_associative: self.non_associative,
        }
    }

    pub(super) fn validate(&self, req: &Request) -> Result<()> {
        let n = req.names;
        super::check_friction_precision(n, self.least_friction_precision)?;
        if let (Some(r), false) = (self.ranges, self.canonical) {
            // The ranges are a stage of the canonical selection: without it they would be
            // silently ignored.
            use super::Names;
            let (flag, canonical) = match n {
                Names::Flags if r => (n.name("ranges"), n.name("canonical")),
                Names::Flags => (n.name("no_ranges"), n.name("canonical")),
                Names::Keywords => (
                    n.given("ranges", if r { "True" } else { "False" }),
                    n.given("canonical", "True"),
                ),
                Names::Fields => (n.given("ranges", r), n.given("canonical", true)),
            };
            return invalid(format!(
                "{flag} applies to the canonical selection: add {canonical} (limit reports the solver's own optimum by default)"
            ));
        }
        if self.least_friction_precision.is_some() && !self.canonical {
            return invalid(format!(
                "{} applies to the canonical selection: add {} (limit reports the solver's own optimum by default)",
                n.name("least_friction_precision"),
                match n {
                    super::Names::Keywords => n.given("canonical", "True"),
                    super::Names::Fields => n.given("canonical", true),
                    super::Names::Flags => n.name("canonical"),
                }
            ));
        }
        if self.least_friction_precision.is_some() && self.non_associative {
            return invalid(format!(
                "{} is not computed with {} (the forces are the friction iteration's)",
                n.name("least_friction_precision"),
                n.name("non_associative")
            ));
        }
        self.laws().validate(req.names)
    }

    pub(super) fn check_dimension(&self, req: &Request, dims: usize) -> Result<()> {
        let n = req.names;
        let conic = if dims == 3 {
            req.model.exact_cone()
        } else {
            self.crushing == Some(Crushing::Conic)
        };
        if self.canonical && conic && !self.non_associative {
            // A cone program's optimum is an interior point: no vertex to select among.
            return invalid(format!(
                "{} selects among the optima of an LP, not of the cone program of {}",
                n.name("canonical"),
                if dims == 3 {
                    n.given("friction_cone", "exact")
                } else {
                    n.given("crushing", "conic")
                }
            ));
        }
        if dims == 3 && self.laws().strength_given() {
            return invalid(format!(
                "{} and {} describe finite compressive strength, which is modelled in 2D only (3D: {} for the exact friction cone)",
                n.name("crushing"),
                n.name("facets"),
                n.given("friction_cone", "exact")
            ));
        }
        Ok(())
    }

    /// The variant: non-associative friction (an LP per iterate: the inscribed crushing
    /// polygon, the friction pyramid), else the canonical selection among LP optima when asked
    /// (not for a cone program, whose optimum is an interior point), else the plain analysis
    /// with the crushing model (2D) or the friction cone (3D).
    pub(super) fn solve<S: Assembly>(
        &self,
        st: &S,
        req: &Request,
        dims: usize,
    ) -> Result<(Output<S::D>, SolverOptions)> {
        let n = req.names;
        let solver = req.solver.options(&super::class(st, req));
        // The conic program of the dimension: exact crushing (2D), the exact friction cone (3D).
        let (crushing, facets) = if dims == 3 {
            let cone = if req.model.exact_cone() {
                Crushing::Conic
            } else {
                Crushing::Linear
            };
            (cone, crate::analysis::limit::DEFAULT_FACETS)
        } else {
            (self.laws().crushing(), self.laws().facets())
        };
        let mut r = if self.laws().non_associative {
            super::check_sliding(st, n)?;
            if crushing == Crushing::Conic {
                return invalid(if dims == 3 {
                    format!(
                        "{} goes with the friction pyramid, not {}",
                        n.name("non_associative"),
                        n.given("friction_cone", "exact")
                    )
                } else {
                    format!(
                        "{} goes with {} (each iterate is an LP)",
                        n.name("non_associative"),
                        n.given("crushing", "linear")
                    )
                });
            }
            if self.canonical {
                // The canonical mechanism of the last iterate's program (least crack area;
                // analysis::canonical_friction).
                limit_nonassociative_canonical(
                    st,
                    &solver,
                    &NonAssociativeOptions::default(),
                    &canonical_options(self.ranges, self.least_friction_precision, dims),
                )?
            } else {
                limit_nonassociative_result(st, &solver, &NonAssociativeOptions::default())?
            }
        } else if self.canonical && crushing == Crushing::Linear {
            limit_canonical(
                st,
                &solver,
                facets,
                &canonical_options(self.ranges, self.least_friction_precision, dims),
            )?
        } else {
            limit_with(st, &solver, crushing, facets)?
        };
        // "Cannot stand" certified (the polygonal statics the answer came from; a cone's
        // answer is Clarabel's alone).
        if crushing == Crushing::Linear {
            crate::analysis::limit::certify_no_equilibrium(st, &mut r, &solver, Some(facets))?;
        }
        if let Some(it) = &r.friction_iteration {
            // Say what the number is: the fixed point of a heuristic iteration, not a bound
            // certified as the associative multiplier is (regression: the summary read like the
            // associative one).
            r.message.push_str(&super::nonassociative_note(it, "λ"));
        }
        Ok((Output::Limit(r), solver))
    }
}
