//! Load capacity after a settlement: λ against the settlement, limit analysis on the deformed
//! geometry.

use super::{invalid, JointLaws, Names, Output, Request};
use crate::analysis::capacity::{capacity, CapacityOptions};
use crate::analysis::limit::Crushing;
use crate::analysis::nonassociative::NonAssociativeOptions;
use crate::error::Result;
use crate::lp::SolverOptions;
use crate::structure::Assembly;
use serde::{Deserialize, Serialize};

/// Options of a capacity analysis. Defaults: 40 intervals, `fixed` supports released after
/// the settlement, every step's mechanism kept, hot starts, the joint laws of
/// [`super::LimitRequest`], the canonical settlement and collapse mechanisms
/// (docs/canonical.md).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct CapacityRequest {
    /// Intervals of the curve (it has `steps + 1` points from 0 to the largest settlement).
    pub steps: usize,
    /// Keep `fixed` supports tied to their blocks after the settlement.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub keep_fixed: bool,
    /// Leave each step's collapse mechanism out of the result.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub no_mechanisms: bool,
    /// Solve every step from scratch (no hot start).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub cold: bool,
    /// The crushing model (2D; default linear). Given (either value) on a model without a
    /// compressive strength, or in 3D, refused.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crushing: Option<Crushing>,
    /// Facets of the inscribed crushing polygon of `crushing: linear` (default 16).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub facets: Option<usize>,
    /// Non-associative Coulomb friction in the settlement and every limit analysis.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub non_associative: bool,
    /// Report the solver's own settlement and collapse mechanisms instead of the canonical
    /// ones (which the exact cones and non-associative friction do anyway).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub raw: bool,
    /// Also the canonical collapse mechanism of every step (costly on deformed 3D geometry:
    /// docs/canonical.md); by default only the settlement mechanism is selected.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub canonical_steps: bool,
}

impl Default for CapacityRequest {
    fn default() -> Self {
        CapacityRequest {
            steps: 40,
            keep_fixed: false,
            no_mechanisms: false,
            cold: false,
            crushing: None,
            facets: None,
            non_associative: false,
            raw: false,
            canonical_steps: false,
        }
    }
}

impl CapacityRequest {
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
        if req.motion.moves.is_empty() && req.motion.profile.is_none() {
            let hint = match n {
                Names::Flags => "give --move NAME=u,v (or --profile)",
                _ => "give move={NAME: (u, v)} (or profile=...)",
            };
            return invalid(format!("capacity needs a settlement: {hint}"));
        }
        if self.steps == 0 {
            return invalid(format!(
                "{}: the curve needs at least one interval",
                n.given("steps", 0)
            ));
        }
        self.laws().validate(n)
    }

    pub(super) fn check_dimension(&self, req: &Request, dims: usize) -> Result<()> {
        let n = req.names;
        if self.canonical_steps && !self.canonical(req, dims) {
            // The steps' selection is a stage of the canonical selection: without it, it would
            // be silently left out.
            let why = if self.raw {
                n.name("raw")
            } else if self.non_associative {
                n.name("non_associative")
            } else if dims == 3 {
                n.given("friction_cone", "exact")
            } else {
                n.given("crushing", "conic")
            };
            return invalid(format!(
                "{} applies to the canonical selection, which {why} leaves out",
                n.name("canonical_steps")
            ));
        }
        if dims == 3 {
            if self.laws().strength_given() {
                return invalid(format!(
                    "{} and {} describe finite compressive strength, which is modelled in 2D only",
                    n.name("crushing"),
                    n.name("facets"),
                ));
            }
            if req.model.exact_cone() && self.non_associative {
                return invalid(format!(
                    "{} goes with the friction pyramid, not {}",
                    n.name("non_associative"),
                    n.given("friction_cone", "exact")
                ));
            }
        }
        Ok(())
    }

    /// The analysis's options: in 3D the conic joint law of every limit analysis is the exact
    /// Coulomb cone when asked for (and the settlement that deforms the geometry the conic
    /// settlement program); the solver policy's method for the programs of `class`, the
    /// iteration's for non-associative friction.
    pub fn options(
        &self,
        req: &Request,
        dims: usize,
        class: &crate::lp::policy::ProblemClass,
    ) -> CapacityOptions {
        let nonassociative = self.non_associative.then(NonAssociativeOptions::settlement);
        CapacityOptions {
            crushing: if dims == 3 {
                if req.model.exact_cone() {
                    Crushing::Conic
                } else {
                    Crushing::Linear
                }
            } else {
                self.laws().crushing()
            },
            facets: self.laws().facets(),
            nonassociative,
            steps: self.steps,
            hot_start: !self.cold,
            mechanisms: !self.no_mechanisms,
            release_fixed: !self.keep_fixed,
            solver: if self.non_associative {
                req.solver.iteration(class)
            } else {
                req.solver.options(class)
            },
            // The policy's warm method for the steps after the first settled one, unless a
            // method is named (then every step by it).
            warm_method: if self.non_associative || req.solver.method.is_some() {
                None
            } else {
                crate::lp::policy::curve_warm_method(class)
            },
            // A step after one certified without equilibrium decided by its certificate
            // first, unless a method is named (then every step's limit program by it).
            no_equilibrium_first: req.solver.method.is_none(),
            canonical: self.canonical(req, dims).then(super::mechanism_options),
            canonical_steps: self.canonical_steps,
            ..CapacityOptions::default()
        }
    }

    /// Whether the canonical selection runs: unless `raw`, with the inscribed polygons and
    /// associative friction (a cone program's optimum is an interior point; the non-associative
    /// iteration's last iterate is reported as is), in 2D and 3D alike.
    pub fn canonical(&self, req: &Request, dims: usize) -> bool {
        !self.raw
            && !self.non_associative
            && if dims == 3 {
                !req.model.exact_cone()
            } else {
                self.laws().crushing() == Crushing::Linear
            }
    }

    pub(super) fn solve<S: Assembly>(
        &self,
        st: &S,
        req: &Request,
        dims: usize,
    ) -> Result<(Output<S::D>, SolverOptions)> {
        if self.non_associative {
            super::check_sliding(st, req.names)?;
        }
        let opts = self.options(req, dims, &super::class(st, req));
        // Only Heyman's joints are hot-started: with friction, finite strength or the conic
        // programs every step is solved from scratch already, and `cold` would change nothing.
        if self.cold
            && (self.non_associative
                || opts.crushing == Crushing::Conic
                || crate::discretize::KinematicMap::new(st).has_joint_laws())
        {
            return invalid(format!(
                "{}: the steps of a curve with friction or finite strength are solved from scratch already (only no-sliding, rigid joints are hot-started)",
                req.names.name("cold")
            ));
        }
        // Its many programs: the result states which method answered each kind of them (the
        // first limit analysis, the warm-started steps, the certificates of no equilibrium).
        let (out, solves) = crate::lp::collecting(|| capacity(st, &opts));
        let mut out = out?;
        out.answered = crate::lp::SolverInfo::by_programs(&opts.solver, &solves);
        Ok((Output::Capacity(out), opts.solver))
    }
}
