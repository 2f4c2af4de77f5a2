//! Settlement analysis: the mechanism and contact forces for prescribed support motions.

use super::{canonical_options, invalid, JointLaws, Output, Request};
use crate::analysis::canonical::settle_canonical;
use crate::analysis::canonical_friction::settle_nonassociative_canonical;
use crate::analysis::limit::{Crushing, DEFAULT_FACETS};
use crate::analysis::nonassociative::{settle_nonassociative, NonAssociativeOptions};
use crate::analysis::settlement::{
    certify_cannot_stand, settle, settle_crushing, settle_with, SettlementForm,
};
use crate::error::Result;
use crate::lp::SolverOptions;
use crate::structure::Assembly;
use serde::{Deserialize, Serialize};

/// Options of a settlement analysis. Defaults: both LPs, the inscribed crushing polygon of 16
/// facets, associative friction, the canonical selection (docs/canonical.md) with the
/// reaction ranges on 2D models of at most 500 blocks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SettleRequest {
    /// Which programs are solved (default both).
    pub settlement_form: SettlementForm,
    /// The crushing model (2D; matters only where a compressive strength is given; default
    /// linear). Given (either value) on a model without a compressive strength, or in 3D,
    /// refused.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crushing: Option<Crushing>,
    /// Facets of the inscribed crushing polygon of `crushing: linear` (default 16).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub facets: Option<usize>,
    /// Non-associative Coulomb friction (the fixed-point iteration; docs/joint-laws.md).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub non_associative: bool,
    /// Report the solver's own optimum instead of the canonical selection.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub raw: bool,
    /// The ranges of the support reactions of the canonical selection — absent: on 2D models
    /// of at most 500 blocks (not in 3D); true: always; false: never.
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

impl SettleRequest {
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
        self.laws().validate(n)?;
        if (self.laws().strength_given() || self.non_associative)
            && self.settlement_form != SettlementForm::Both
        {
            return invalid(format!(
                "{}, {} and {} go with {} (the default)",
                n.name("crushing"),
                n.name("facets"),
                n.name("non_associative"),
                n.given("settlement_form", "both")
            ));
        }
        if self.non_associative && self.ranges == Some(true) {
            // The frictional selection keeps the iteration's forces: no reaction ranges.
            return invalid(format!(
                "{} is not computed with {} (the forces are the friction iteration's)",
                n.name("ranges"),
                n.name("non_associative")
            ));
        }
        if self.non_associative && self.least_friction_precision.is_some() {
            return invalid(format!(
                "{} is not computed with {} (the forces are the friction iteration's)",
                n.name("least_friction_precision"),
                n.name("non_associative")
            ));
        }
        if req.model.exact_cone() {
            if self.non_associative {
                return invalid(format!(
                    "{} goes with the friction pyramid, not {}",
                    n.name("non_associative"),
                    n.given("friction_cone", "exact")
                ));
            }
            if self.settlement_form != SettlementForm::Both {
                return invalid(format!(
                    "{} goes with {} (the default): the cone program is solved whole",
                    n.given("friction_cone", "exact"),
                    n.given("settlement_form", "both")
                ));
            }
        }
        Ok(())
    }

    pub(super) fn check_dimension(&self, req: &Request, dims: usize) -> Result<()> {
        let n = req.names;
        // The ranges and the least μ's precision belong to the canonical selection: without it
        // they would be silently left out.
        let stage = if self.ranges == Some(true) {
            Some("ranges")
        } else if self.least_friction_precision.is_some() {
            Some("least_friction_precision")
        } else {
            None
        };
        if let (Some(flag), false) = (stage, self.non_associative || self.canonical(req, dims)) {
            let why = if self.raw {
                n.name("raw")
            } else if dims == 3 {
                n.given("friction_cone", "exact")
            } else {
                format!("{} or {}", n.name("crushing"), n.name("facets"))
            };
            return invalid(format!(
                "{} applies to the canonical selection, which {why} leaves out",
                n.name(flag)
            ));
        }
        if dims == 3 && self.laws().strength_given() {
            return invalid(format!(
                "{} and {} describe finite compressive strength, which is modelled in 2D only",
                n.name("crushing"),
                n.name("facets"),
            ));
        }
        Ok(())
    }

    /// Whether the canonical selection runs: unless `raw`, with the default joint laws (joint
    /// laws beyond the defaults — exact crushing, other facet counts in 2D, the exact friction
    /// cone in 3D, whose optimum is an interior point of a cone program — are solved as such;
    /// the non-associative iteration has its own selection in 2D unless `raw`,
    /// `analysis::canonical_friction`). In 2D and 3D alike (docs/canonical.md).
    pub fn canonical(&self, req: &Request, dims: usize) -> bool {
        !self.raw
            && !self.non_associative
            && if dims == 3 {
                !req.model.exact_cone()
            } else {
                self.laws().crushing() == Crushing::Linear && self.facets() == DEFAULT_FACETS
            }
    }

    fn facets(&self) -> usize {
        self.laws().facets()
    }

    /// The variant: the non-associative iteration (both programs only), else the canonical
    /// selection ([`SettleRequest::canonical`]), else both programs with the crushing model
    /// (2D) or the exact friction cone (3D), else the programs of the form asked for.
    pub(super) fn solve<S: Assembly>(
        &self,
        st: &S,
        req: &Request,
        dims: usize,
    ) -> Result<(Output<S::D>, SolverOptions)> {
        let solver = req.solver.options(&super::class(st, req));
        let both = self.settlement_form == SettlementForm::Both;
        let (crushing, facets) = if dims == 3 {
            let cone = if req.model.exact_cone() {
                Crushing::Conic
            } else {
                Crushing::Linear
            };
            (cone, DEFAULT_FACETS)
        } else {
            (self.laws().crushing(), self.facets())
        };
        if self.non_associative && both {
            // Without any friction nothing slides: the iteration would be pointless (as
            // `limit` and `capacity` refuse it).
            super::check_sliding(st, req.names)?;
            let solver = req.solver.iteration(&super::class(st, req));
            // In 2D (unless `raw`) the canonical mechanism of the last iterate's program
            // (least crack area; analysis::canonical_friction), as for Heyman's rules.
            let mut r = if dims == 2 && !self.raw && crushing == Crushing::Linear {
                settle_nonassociative_canonical(
                    st,
                    &solver,
                    crushing,
                    facets,
                    &NonAssociativeOptions::settlement(),
                    &canonical_options(self.ranges, self.least_friction_precision, dims),
                )?
            } else {
                settle_nonassociative(
                    st,
                    &solver,
                    crushing,
                    facets,
                    &NonAssociativeOptions::settlement(),
                )?
            };
            if crushing == Crushing::Linear {
                certify_cannot_stand(st, &mut r, &solver, facets)?;
            }
            return Ok((Output::Settlement(r), solver));
        }
        let mut r = if self.canonical(req, dims) {
            settle_canonical(
                st,
                &solver,
                self.settlement_form,
                &canonical_options(self.ranges, self.least_friction_precision, dims),
            )?
        } else if both && (dims == 2 || crushing == Crushing::Conic) {
            settle_crushing(st, &solver, crushing, facets)?
        } else if both {
            settle(st, &solver)?
        } else {
            settle_with(st, &solver, self.settlement_form)?
        };
        // "Cannot stand" certified (the polygonal statics the answer came from).
        if crushing == Crushing::Linear {
            certify_cannot_stand(st, &mut r, &solver, facets)?;
        }
        Ok((Output::Settlement(r), solver))
    }
}
