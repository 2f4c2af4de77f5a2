//! The request layer: one front door to every analysis, for a model of either dimension.
//!
//! A [`Request`] says what to run and how: the model options ([`ModelOptions`]: joint
//! detection, material overrides, the 3D friction cone), the solver ([`SolverRequest`]), the
//! support motion ([`SupportMotion`], parsed with units in [`motion`]) and the analysis with its
//! own options ([`Analysis`]: [`LimitRequest`], [`SettleRequest`], …). Every field has a
//! documented default, so `{"analysis": {"type": "limit"}}` is a complete request. The request
//! is checked once ([`Request::validate`]: each error one line naming the field), then [`run`]
//! makes every choice a front end used to make: which variant of the analysis runs
//! (associative or not, canonical or the solver's own optimum, crushing model, exact friction
//! cone), the default solver of each dimension, whether a support motion is needed, and the
//! 2D/3D dispatch — written once here. The CLI turns its flags into a request, Python its
//! keywords; neither decides anything else.
//!
//! Messages name the option in the words of the front end that made the request
//! ([`Names`]: `--crushing conic` on the command line, `crushing=conic` in Python and in a
//! request's JSON).
//!
//! [`run`] is [`prepare`] (model options and support motion applied, structure built; its
//! warnings) then [`solve`], for front ends that print the model's warnings before solving.

pub mod generate;
pub mod motion;

mod capacity;
mod identify;
mod incremental;
mod least;
mod limit;
mod safety;
mod settle;
mod sweep;
mod tilt;

pub use capacity::CapacityRequest;
pub use generate::{ArchRequest, ShapeName};
pub use identify::{parse_unknown, IdentifyRequest, UnknownSpec};
pub use incremental::{IncrementalRequest, Toward};
pub use least::{
    least_thickness, Generator, LeastThicknessRequest, LeastThicknessResult, LeastThicknessRun,
};
pub use limit::LimitRequest;
pub use motion::{parse_profile, signed_length, Move, Split, SupportMotion};
pub use safety::SafetyRequest;
pub use settle::SettleRequest;
pub use sweep::{SweepRequest, DEFAULT_CAPACITY_STEPS, DEFAULT_COV, DEFAULT_SEED};
pub use tilt::TiltRequest;

use crate::analysis::canonical::CanonicalOptions;
use crate::analysis::identify::{IdentifyGeometry, Unknown};
use crate::analysis::incremental::{IncrementalGeometry, IncrementalPoint};
use crate::analysis::limit::{Crushing, DEFAULT_FACETS, MAX_FACETS, MIN_FACETS};
use crate::analysis::safety::SafetyResult;
use crate::analysis::tilt::TiltResult;
use crate::analysis::{CapacityResult, LimitResult, SettlementResult};
use crate::error::{Error, Result};
use crate::lp::policy::{self, ProblemClass, Purpose};
use crate::lp::{Method, SolverOptions};
use crate::model3d::{AnyModel, Model3d};
use crate::result::identify::IdentifyResult;
use crate::result::incremental::IncrementalResult;
use crate::result::Spatial;
use crate::settlement_input::{ModelSupports, SupportSplit};
use crate::structure::{Assembly, BuildOptions, Structure, Structure3d};
use crate::sweep::{MotionSize, SweepRecord};
use crate::Model;
use serde::{Deserialize, Serialize};

/// How messages name a request's options: after the front end that made the request.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Names {
    /// The request's own field names: `crushing=conic` (a request read from JSON).
    #[default]
    Fields,
    /// The command line's flags: `--crushing conic`, `--compressive-strength KPA`.
    Flags,
    /// Python's keywords: `crushing=conic`, `compressive_strength=KPA`.
    Keywords,
}

impl Names {
    /// The option's name: `--friction-cone` or `friction_cone`.
    pub fn name(self, field: &str) -> String {
        match self {
            Names::Flags => format!("--{}", field.replace('_', "-")),
            Names::Fields | Names::Keywords => field.to_string(),
        }
    }

    /// The option with a value: `--facets 32` or `facets=32`.
    pub fn given(self, field: &str, value: impl std::fmt::Display) -> String {
        match self {
            Names::Flags => format!("{} {value}", self.name(field)),
            Names::Fields | Names::Keywords => format!("{field}={value}"),
        }
    }

    /// The option with a placeholder for its value: `--compressive-strength KPA` or
    /// `compressive_strength=KPA`.
    pub fn ask(self, field: &str, what: &str) -> String {
        self.given(field, what)
    }

    /// How to give a support motion, for "needs a support motion" messages.
    fn motion_hint(self, dims: usize) -> String {
        match (self, dims) {
            (Names::Flags, 2) => "give --move NAME=u,v[,θ] or --profile".into(),
            (Names::Flags, _) => "give --move NAME=u,v,w[,θx,θy,θz] or --profile".into(),
            (_, 2) => "give move={NAME: (u, v)} or profile=...".into(),
            _ => "give move={NAME: (u, v, w)} or profile=...".into(),
        }
    }
}

fn invalid<T>(msg: String) -> Result<T> {
    Err(Error::Invalid(msg))
}

/// The 3D friction cone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrictionCone {
    /// The pyramid of `friction_facets` facets inscribed in the cone (an LP). The default.
    #[default]
    Pyramid,
    /// The exact cone (a second-order cone program, Clarabel).
    Exact,
}

/// Fewest and most facets of the 3D friction pyramid.
pub const FRICTION_FACETS: std::ops::RangeInclusive<usize> = 3..=1024;

/// How the model is read into a structure. Defaults: every field absent.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ModelOptions {
    /// Geometric tolerance for joint detection, relative to the model's size (default 1e-7).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Coulomb μ for every joint, overriding the model's materials (default: the model's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<f64>,
    /// Compressive strength f_c in kPa for every joint, overriding the model's materials
    /// (default: the model's, else infinite).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compressive_strength: Option<f64>,
    /// 3D: facets of the friction pyramid (default 8). Refused for a 2D model.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_facets: Option<usize>,
    /// 3D: the friction cone (default the pyramid), as given. Given (either value) for a 2D
    /// model, refused (session 25: `pyramid`, the default's value, passed where `exact` was
    /// refused).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_cone: Option<FrictionCone>,
}

impl ModelOptions {
    pub fn validate(&self, names: Names) -> Result<()> {
        if let Some(t) = self.tolerance {
            if !(t.is_finite() && t > 0.0) {
                return invalid(format!(
                    "{}: must be a finite number > 0",
                    names.given("tolerance", t)
                ));
            }
        }
        if let Some(mu) = self.friction {
            if !(mu.is_finite() && mu >= 0.0) {
                return invalid(format!(
                    "{}: must be a finite number ≥ 0",
                    names.given("friction", mu)
                ));
            }
            if mu > crate::discretize::MAX_FRICTION {
                return invalid(format!(
                    "{}: above {}, which no joint has; for joints that do not slide leave {} out (Heyman's law)",
                    names.given("friction", mu),
                    crate::discretize::MAX_FRICTION,
                    names.name("friction")
                ));
            }
        }
        if let Some(f) = self.compressive_strength {
            if !(f.is_finite() && f > 0.0) {
                return invalid(format!(
                    "{}: must be a finite number > 0 (kPa)",
                    names.given("compressive_strength", f)
                ));
            }
        }
        if let Some(k) = self.friction_facets {
            if !FRICTION_FACETS.contains(&k) {
                return invalid(format!(
                    "{}: the friction pyramid needs between {} and {} facets",
                    names.given("friction_facets", k),
                    FRICTION_FACETS.start(),
                    FRICTION_FACETS.end()
                ));
            }
            if self.exact_cone() {
                return invalid(format!(
                    "{} applies to the pyramid, not to {}",
                    names.name("friction_facets"),
                    names.given("friction_cone", "exact")
                ));
            }
        }
        Ok(())
    }

    fn exact_cone(&self) -> bool {
        self.friction_cone == Some(FrictionCone::Exact)
    }

    /// `friction_cone=exact` refused in one line by an analysis that solves the inscribed
    /// pyramid only (safety, sweep, incremental): `why` follows the option as given.
    fn refuse_exact_cone(&self, names: Names, why: &str) -> Result<()> {
        if self.exact_cone() {
            return invalid(format!("{}{why}", names.given("friction_cone", "exact")));
        }
        Ok(())
    }
}

/// The solver. Default: the solver policy's method for the program's class
/// ([`crate::lp::policy`]: dimension, size, friction, cones, analysis).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SolverRequest {
    /// The LP method; absent: the solver policy's method ([`crate::lp::policy::default_method`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub method: Option<Method>,
    /// Print the solver's own log on stdout (diagnostics).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub log: bool,
}

/// The LP method when none is asked for, for a model of `dims` dimensions whose size is not
/// known: the solver policy's ([`crate::lp::policy::default_method`]). The request layer itself
/// asks the policy with the whole class of the program ([`class`]).
pub fn default_method(dims: usize) -> Method {
    policy::default_method(&ProblemClass::of_dim(if dims == 3 { 3 } else { 2 }))
}

/// The class of the programs `req` solves on structure `st`, for the solver policy: the
/// dimension, blocks and friction of the structure; cones where the request asks for the exact
/// friction cone or conic crushing; the purpose of the analysis (`safety`'s bisection is a
/// feasibility question; the non-associative iteration a sequence of iterates).
pub fn class<S: Assembly>(st: &S, req: &Request) -> ProblemClass {
    let purpose = match &req.analysis {
        Analysis::Safety(_) => Purpose::Feasibility,
        a if joint_laws(a).is_some_and(|l| l.non_associative) => Purpose::Iteration,
        Analysis::Capacity(_) => Purpose::Curve,
        _ => Purpose::Optimise,
    };
    let conic = joint_laws(&req.analysis).is_some_and(|l| l.crushing == Some(Crushing::Conic));
    ProblemClass {
        cones: req.model.exact_cone() || conic,
        ..policy::class_of(st, purpose)
    }
}

impl SolverRequest {
    /// The solver options for a program of `class`: the method asked for, else the solver
    /// policy's ([`policy::options`]).
    pub fn options(&self, class: &ProblemClass) -> SolverOptions {
        policy::options(
            class,
            self.method,
            &SolverOptions {
                log: self.log,
                ..SolverOptions::default()
            },
        )
    }

    /// The solver of a non-associative iteration: the policy's method for iterates unless a
    /// method is asked for (Clarabel's interior point: its solutions are the centres of the
    /// optimal faces, so the normal forces move smoothly from one iterate to the next, where a
    /// simplex jumps between vertices and the iteration wanders; measured on a 20 × 10 wall:
    /// docs/joint-laws.md), to a tolerance tight enough that every iterate is certified.
    pub fn iteration(&self, class: &ProblemClass) -> SolverOptions {
        self.options(&ProblemClass {
            purpose: Purpose::Iteration,
            ..*class
        })
    }
}

/// The finest bisection tolerance accepted (`safety`, `least-thickness`): some thousand times a
/// double's resolution on [0, 1], so that the interval can still halve.
pub const MIN_BISECTION_TOLERANCE: f64 = 1e-12;

/// Non-associative friction needs a joint that can slide: without any friction coefficient
/// (`--friction`, or a material's) nothing slides and the iteration would return the
/// associative answer under a heuristic's name. Refused, naming the flag.
pub(crate) fn check_sliding<S: Assembly>(st: &S, n: Names) -> Result<()> {
    let map = crate::discretize::KinematicMap::new(st);
    if map.laws.iter().all(|l| l.friction.is_none()) {
        return invalid(format!(
            "{} needs friction: no joint has a friction coefficient ({}, or a material's `friction`), so nothing slides",
            n.name("non_associative"),
            n.ask("friction", "MU")
        ));
    }
    Ok(())
}

/// One sentence after a non-associative result's message: what the number is (the fixed point
/// of the heuristic iteration of Gilbert, Casapulla and Ahmed, not a certified bound), how the
/// iteration ended, and the associative value, which bounds the true non-associative one from
/// above (Radenkovic's first theorem).
pub(crate) fn nonassociative_note(it: &crate::result::FrictionIteration, what: &str) -> String {
    let n = it.history.len();
    // No iteration ran: the dead loads have no statically admissible field at all (Coulomb's
    // cone bounds the forces whatever the flow rule), and that answer is certified on its own.
    // Calling it "the fixed point of a heuristic iteration (0 LPs)" contradicted it (the μ = 0.6
    // grid façade's `limit`, session 28).
    if n == 0 {
        return "; non-associative friction: no iteration ran (without a field in Coulomb's cone under the dead loads, the flow rule plays no part)".to_string();
    }
    let lps = format!("{n} LP{}", if n == 1 { "" } else { "s" });
    let mut s = if it.converged {
        format!("; non-associative friction: the fixed point of a heuristic iteration ({lps}), not a certified bound")
    } else {
        format!("; non-associative friction: the last iterate of a heuristic fixed-point iteration that did not converge ({lps}), not a certified bound")
    };
    if let Some(a) = it.associative {
        s.push_str(&format!(
            "; the associative {what} = {a:.6} bounds the true one from above"
        ));
    }
    s
}

/// Finite compressive strength and non-associative friction: the joint-law options of limit,
/// settle and capacity. Defaults: the inscribed polygon of 16 facets, associative friction.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct JointLaws {
    /// As given (`None`: not given, the inscribed polygon).
    pub crushing: Option<Crushing>,
    pub facets: Option<usize>,
    pub non_associative: bool,
}

impl JointLaws {
    pub fn validate(&self, names: Names) -> Result<()> {
        match (self.crushing, self.facets) {
            (Some(Crushing::Conic), Some(_)) => invalid(format!(
                "{} applies to {} (the conic model is the exact cone)",
                names.name("facets"),
                names.given("crushing", "linear")
            )),
            (_, Some(n)) if !(MIN_FACETS..=MAX_FACETS).contains(&n) => invalid(format!(
                "{}: the crushing polygon needs between {MIN_FACETS} and {MAX_FACETS} facets",
                names.given("facets", n)
            )),
            _ => Ok(()),
        }
    }

    /// The facet count (default 16).
    pub fn facets(&self) -> usize {
        self.facets.unwrap_or(DEFAULT_FACETS)
    }

    /// The crushing model (given or the default, the inscribed polygon).
    pub fn crushing(&self) -> Crushing {
        self.crushing.unwrap_or_default()
    }

    /// Whether a finite-strength option was given (they are refused in 3D), whatever its value
    /// (session 25: `crushing: linear`, the default's value, passed where `conic` was refused).
    pub fn strength_given(&self) -> bool {
        self.crushing.is_some() || self.facets.is_some()
    }

    /// Refuse `crushing` (either value) and `facets` on a structure none of whose blocks has a
    /// compressive strength: its joints cannot crush, so the crushing model would play no part.
    fn check_strength(&self, st: &Structure, names: Names) -> Result<()> {
        if st
            .blocks
            .iter()
            .any(|b| b.material.compressive_strength.is_some())
        {
            return Ok(());
        }
        let flag = match (self.crushing, self.facets) {
            (Some(Crushing::Conic), _) => names.given("crushing", "conic"),
            (Some(Crushing::Linear), _) => names.given("crushing", "linear"),
            (_, Some(n)) => names.given("facets", n),
            _ => return Ok(()),
        };
        invalid(format!(
            "{flag} needs a compressive strength: give {} or compressive_strength in the model's materials (without one no joint can crush)",
            names.ask("compressive_strength", "KPA")
        ))
    }
}

/// A relative precision of the least friction coefficient: in (0, 1).
fn check_friction_precision(n: Names, p: Option<f64>) -> Result<()> {
    match p {
        Some(p) if !(p > 0.0 && p < 1.0) => invalid(format!(
            "{} must be a relative precision in (0, 1) (e.g. 1e-4), not {p}",
            n.name("least_friction_precision")
        )),
        _ => Ok(()),
    }
}

/// The reaction ranges of a canonical selection: `None` on 2D models of at most 500 blocks
/// (never in 3D: 2 programs per component of six per support, each a full solve of the 3D force
/// program — 42 CPU s on the README's 192-block vault where the rest of the selection takes 2;
/// docs/canonical.md), `Some(true)` always, `Some(false)` never.
/// `friction_precision`: the relative precision of the least friction coefficient (default
/// [`crate::analysis::canonical::FRICTION_PRECISION`]).
fn canonical_options(
    ranges: Option<bool>,
    friction_precision: Option<f64>,
    dims: usize,
) -> CanonicalOptions {
    let d = CanonicalOptions::default();
    CanonicalOptions {
        friction_precision: friction_precision.unwrap_or(d.friction_precision),
        // A precision asked for is searched to at any μ; the default stops above masonry's
        // friction (`FRICTION_SEARCH_LIMIT`, docs/canonical.md "The forces").
        friction_search_limit: if friction_precision.is_some() {
            None
        } else {
            d.friction_search_limit
        },
        reaction_ranges: ranges.unwrap_or(dims == 2),
        ranges_max_blocks: if ranges == Some(true) {
            usize::MAX
        } else {
            d.ranges_max_blocks
        },
        ..d
    }
}

/// The canonical selection of the mechanism alone (no force stage, no reaction ranges): what
/// capacity curves and sweeps report of it (hinges, open joints, drawn mechanisms; their forces
/// are not reported, or are the force program's: docs/canonical.md).
fn mechanism_options() -> CanonicalOptions {
    CanonicalOptions {
        forces: false,
        reaction_ranges: false,
        ..CanonicalOptions::default()
    }
}

/// The analysis to run, with its options.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "kebab-case")]
pub enum Analysis {
    Limit(LimitRequest),
    Settle(SettleRequest),
    Capacity(CapacityRequest),
    Tilt(TiltRequest),
    Safety(SafetyRequest),
    Incremental(IncrementalRequest),
    Identify(IdentifyRequest),
    Sweep(SweepRequest),
}

impl Analysis {
    /// Whether the analysis takes a support motion (settle, capacity; incremental: a
    /// settlement first; identify: the known motions; sweep: the base settlement).
    pub fn takes_motion(&self) -> bool {
        matches!(
            self,
            Analysis::Settle(_)
                | Analysis::Capacity(_)
                | Analysis::Incremental(_)
                | Analysis::Identify(_)
                | Analysis::Sweep(_)
        )
    }

    /// The command's name (`limit`, `settle`, …).
    pub fn name(&self) -> &'static str {
        match self {
            Analysis::Limit(_) => "limit",
            Analysis::Settle(_) => "settle",
            Analysis::Capacity(_) => "capacity",
            Analysis::Tilt(_) => "tilt",
            Analysis::Safety(_) => "safety",
            Analysis::Incremental(_) => "incremental",
            Analysis::Identify(_) => "identify",
            Analysis::Sweep(_) => "sweep",
        }
    }
}

/// One analysis of one model: everything a front end decides, as data.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Request {
    #[serde(default)]
    pub model: ModelOptions,
    #[serde(default)]
    pub solver: SolverRequest,
    /// The support motion (settle and capacity need one; the others refuse one).
    #[serde(default, skip_serializing_if = "SupportMotion::is_empty")]
    pub motion: SupportMotion,
    pub analysis: Analysis,
    /// How messages name the options (not part of the request's JSON).
    #[serde(skip)]
    pub names: Names,
}

impl Request {
    /// A request for `analysis` with every other option at its default.
    pub fn new(analysis: Analysis) -> Request {
        Request {
            model: ModelOptions::default(),
            solver: SolverRequest::default(),
            motion: SupportMotion::default(),
            analysis,
            names: Names::default(),
        }
    }

    /// Read a request from JSON (unknown fields refused; each error one line).
    pub fn from_json(text: &str) -> Result<Request> {
        serde_json::from_str(text).map_err(|e| {
            Error::Invalid(format!(
                "request: {}",
                crate::error::one_line(&e.to_string())
            ))
        })
    }

    /// Check every option that does not need the model, once, before any work: numbers in
    /// range, options that exclude each other. Each error is one line naming the option.
    pub fn validate(&self) -> Result<()> {
        let n = self.names;
        self.model.validate(n)?;
        self.motion.validate(n)?;
        match &self.analysis {
            Analysis::Limit(r) => r.validate(self),
            Analysis::Settle(r) => r.validate(self),
            Analysis::Capacity(r) => r.validate(self),
            Analysis::Tilt(r) => r.validate(self),
            Analysis::Safety(r) => r.validate(self),
            Analysis::Incremental(r) => r.validate(self),
            Analysis::Identify(r) => r.validate(self),
            Analysis::Sweep(r) => r.validate(self),
        }?;
        if !self.motion.is_empty() && !self.analysis.takes_motion() {
            return invalid(format!(
                "{} takes no support motion ({}, {}, {}, {}): the analysis of a settled structure is capacity",
                self.analysis.name(),
                n.name("move"),
                n.name("fixed"),
                n.name("profile"),
                n.name("split")
            ));
        }
        Ok(())
    }
}

/// What [`prepare`] made of a model: the model with the request's material overrides and
/// support motion applied, its structure, the supports cut by the motion, and the model's
/// warnings (for the front end to show).
#[derive(Clone, Debug)]
pub struct Setup<M, S> {
    pub model: M,
    pub structure: S,
    pub splits: Vec<SupportSplit>,
    pub warnings: Vec<String>,
}

/// A prepared model of either dimension.
#[derive(Clone, Debug)]
pub enum Prepared {
    Planar(Setup<Model, Structure>),
    Spatial(Setup<Model3d, Structure3d>),
}

/// The result of an analysis, of a dimension. (One per run: the variants' sizes do not matter.)
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
pub enum Output<D: Spatial> {
    Limit(LimitResult<D>),
    Settlement(SettlementResult<D>),
    Capacity(CapacityResult<D>),
    Tilt(TiltResult<D>),
    Safety(SafetyResult),
    Incremental(IncrementalResult<D>),
    /// The identification and its unknowns as read on the structure.
    Identify(IdentifyResult<D>, Vec<Unknown>),
    /// The records of the sweep's tasks, in task order.
    Sweep(Vec<SweepRecord>),
}

impl<D: Spatial> Output<D> {
    pub fn limit(&self) -> Option<&LimitResult<D>> {
        match self {
            Output::Limit(r) => Some(r),
            _ => None,
        }
    }
    pub fn settlement(&self) -> Option<&SettlementResult<D>> {
        match self {
            Output::Settlement(r) => Some(r),
            _ => None,
        }
    }
    pub fn capacity(&self) -> Option<&CapacityResult<D>> {
        match self {
            Output::Capacity(r) => Some(r),
            _ => None,
        }
    }
    pub fn tilt(&self) -> Option<&TiltResult<D>> {
        match self {
            Output::Tilt(r) => Some(r),
            _ => None,
        }
    }
    pub fn safety(&self) -> Option<&SafetyResult> {
        match self {
            Output::Safety(r) => Some(r),
            _ => None,
        }
    }
    pub fn incremental(&self) -> Option<&IncrementalResult<D>> {
        match self {
            Output::Incremental(r) => Some(r),
            _ => None,
        }
    }
    pub fn identify(&self) -> Option<(&IdentifyResult<D>, &[Unknown])> {
        match self {
            Output::Identify(r, u) => Some((r, u)),
            _ => None,
        }
    }
    pub fn sweep(&self) -> Option<&[SweepRecord]> {
        match self {
            Output::Sweep(r) => Some(r),
            _ => None,
        }
    }

    /// The result's JSON value (a sweep: the array of its records).
    pub fn to_value(&self) -> serde_json::Value {
        let v = match self {
            Output::Limit(x) => serde_json::to_value(x),
            Output::Settlement(x) => serde_json::to_value(x),
            Output::Capacity(x) => serde_json::to_value(x),
            Output::Tilt(x) => serde_json::to_value(x),
            Output::Safety(x) => serde_json::to_value(x),
            Output::Incremental(x) => serde_json::to_value(x),
            Output::Identify(x, _) => serde_json::to_value(x),
            Output::Sweep(x) => serde_json::to_value(x),
        };
        v.unwrap_or(serde_json::Value::Null)
    }
}

/// An analysis run: its setup, its result, and the solver options it ran with.
#[derive(Clone, Debug)]
pub struct Run<M, S: Assembly> {
    pub setup: Setup<M, S>,
    pub output: Output<S::D>,
    pub solver: SolverOptions,
    /// The adaptation of the crack lines, when the request asked for one (2D).
    pub adapt: Option<crate::analysis::adapt::AdaptRecord>,
}

/// The result of [`run`] for a model of either dimension.
#[derive(Clone, Debug)]
pub enum AnyResult {
    Planar(Run<Model, Structure>),
    Spatial(Run<Model3d, Structure3d>),
}

impl AnyResult {
    /// The result's JSON value, as the front ends write it (with `split_supports` when the
    /// motion cut supports).
    pub fn to_value(&self) -> serde_json::Value {
        fn of<M, S: Assembly>(r: &Run<M, S>) -> serde_json::Value {
            let mut v = r.output.to_value();
            if let (Some(a), Some(o)) = (&r.adapt, v.as_object_mut()) {
                o.insert("adapt".into(), serde_json::to_value(a).unwrap_or_default());
            }
            if !r.setup.splits.is_empty() {
                if let Some(o) = v.as_object_mut() {
                    o.insert(
                        "split_supports".into(),
                        serde_json::to_value(&r.setup.splits).unwrap_or_default(),
                    );
                }
            }
            v
        }
        match self {
            AnyResult::Planar(r) => of(r),
            AnyResult::Spatial(r) => of(r),
        }
    }
}

/// Checks of the request against the model's dimension, before the model is touched.
fn check_dimension(req: &Request, dims: usize) -> Result<()> {
    match &req.analysis {
        Analysis::Limit(r) => r.check_dimension(req, dims),
        Analysis::Settle(r) => r.check_dimension(req, dims),
        Analysis::Capacity(r) => r.check_dimension(req, dims),
        Analysis::Incremental(r) => r.check_dimension(req, dims),
        Analysis::Identify(r) => r.check_dimension(req, dims),
        Analysis::Tilt(_) | Analysis::Safety(_) | Analysis::Sweep(_) => Ok(()),
    }
}

/// Validate the request, check it against the model's dimension, apply its material
/// overrides and support motion to a model and build the structure.
/// The summaries print forces at this structure's own load (crate::lengths::force): its dead
/// loads' total, or its live loads' where it has no weight.
fn set_force_scale<S: Assembly>(st: &S) {
    let dofs = <S::D as crate::dim::Dim>::DOFS;
    let dead = crate::scale::force_scale(dofs, &st.load_vector(false));
    let load = if dead > 0.0 {
        dead
    } else {
        crate::scale::force_scale(dofs, &st.load_vector(true))
    };
    crate::lengths::set_force_scale(load);
}

pub fn prepare(model: &AnyModel, req: &Request) -> Result<Prepared> {
    req.validate()?;
    let n = req.names;
    match model {
        AnyModel::Planar(m) => {
            check_dimension(req, 2)?;
            let mut model = m.clone();
            model.override_joint_laws(req.model.friction, req.model.compressive_strength);
            let mut splits = req.motion.apply(&mut model, n)?;
            if let Analysis::Identify(r) = &req.analysis {
                splits.extend(r.split_profiles(&mut model, n)?);
            }
            if req.model.friction_facets.is_some() || req.model.friction_cone.is_some() {
                return invalid(format!(
                    "{} and {} apply to 3D models (a 2D joint's friction is exact)",
                    n.name("friction_facets"),
                    n.name("friction_cone")
                ));
            }
            let structure = Structure::new(
                &model,
                BuildOptions {
                    tolerance: req.model.tolerance,
                },
            )?;
            let warnings = model.warnings();
            // The summaries and messages print lengths at this structure's own scale
            // (crate::lengths), whichever front end asked.
            crate::lengths::set_scale(crate::settlement_input::ModelSupports::extent(&model));
            set_force_scale(&structure);
            Ok(Prepared::Planar(Setup {
                model,
                structure,
                splits,
                warnings,
            }))
        }
        AnyModel::Spatial(m) => {
            check_dimension(req, 3)?;
            let mut model = m.clone();
            model.override_joint_laws(req.model.friction, req.model.compressive_strength);
            let splits = req.motion.apply(&mut model, n)?;
            let mut structure = Structure3d::new(
                &model,
                BuildOptions {
                    tolerance: req.model.tolerance,
                },
            )?;
            if let Some(k) = req.model.friction_facets {
                structure.friction_facets = k;
            }
            let warnings = model.warnings();
            // The summaries and messages print lengths at this structure's own scale
            // (crate::lengths), whichever front end asked.
            crate::lengths::set_scale(crate::settlement_input::ModelSupports::extent(&model));
            set_force_scale(&structure);
            Ok(Prepared::Spatial(Setup {
                model,
                structure,
                splits,
                warnings,
            }))
        }
    }
}

/// Support motions whose largest displacement is below this fraction of the structure's size
/// are refused by `settle` and `capacity`: within about fifty times the round-off of the
/// coordinates themselves (2.2e-16 of the size), they cannot be resolved, and the programs'
/// floors then decide instead of the structure (the paper's arch at 1e-30 m: its energy QP
/// failed; at 1e-60 m the mechanism was reported uncertified with zero work; session 24).
pub const MOTION_FLOOR: f64 = 1e-14;

/// Refuse a settlement (or a capacity curve) whose support motions are too small to be
/// resolved against the structure's own coordinates ([`MOTION_FLOOR`]).
fn check_motion_size(req: &Request, size: f64, largest: f64) -> Result<()> {
    let what = match &req.analysis {
        Analysis::Settle(_) => "settle",
        Analysis::Capacity(_) => "capacity",
        _ => return Ok(()),
    };
    if largest > 0.0 && size > 0.0 && largest < MOTION_FLOOR * size {
        return invalid(format!(
            "{what}: the support motions (largest displacement {largest:.3e} m) are below {MOTION_FLOOR:e} of the structure's size ({}), within the round-off of its coordinates: give a motion large enough to resolve (1mm, say)",
            crate::lengths::Length::Position.show(size)
        ));
    }
    Ok(())
}

/// The checks of a model's supports before an analysis (a motion where one is needed, one not
/// too small to resolve against the model's size, a fixed support where `keep_fixed` asks for
/// one). Returns whether any support moves. `dims` translations lead each motion; the rotations
/// after them count times the model's size.
fn check_supports<M: ModelSupports>(req: &Request, m: &M, dims: usize) -> Result<bool> {
    let n = m.support_names().len();
    let moves = (0..n).any(|i| m.motion(i).iter().any(|x| *x != 0.0));
    check_motion(req, dims, moves)?;
    let size = m.extent();
    let largest = (0..n)
        .flat_map(|i| m.motion(i).iter().enumerate())
        .map(|(k, x)| if k < dims { x.abs() } else { x.abs() * size })
        .fold(0.0f64, f64::max);
    check_motion_size(req, size, largest)?;
    check_keep_fixed(req, (0..n).any(|i| m.is_fixed(i)))?;
    Ok(moves)
}

/// Refuse `keep_fixed` (capacity, incremental) on a model none of whose supports is fixed
/// (`--fixed` or a `fixed` connection in the model): it would change nothing (session 24).
fn check_keep_fixed(req: &Request, any_fixed: bool) -> Result<()> {
    let keep = match &req.analysis {
        Analysis::Capacity(c) => c.keep_fixed,
        Analysis::Incremental(i) => i.keep_fixed,
        _ => false,
    };
    if keep && !any_fixed {
        let n = req.names;
        return invalid(format!(
            "{} keeps fixed supports fixed, but no support is fixed (give {} or a support with connection \"fixed\" in the model)",
            n.name("keep_fixed"),
            n.name("fixed")
        ));
    }
    Ok(())
}

/// Refuse an analysis that needs a support motion on a model whose supports do not move.
fn check_motion(req: &Request, dims: usize, moving: bool) -> Result<()> {
    let n = req.names;
    let needs_motion = match &req.analysis {
        Analysis::Settle(_) => Some("settle"),
        _ => None,
    };
    if let (Some(what), false) = (needs_motion, moving) {
        return invalid(format!(
            "{what} needs a support motion: {} (the model's supports do not move)",
            n.motion_hint(dims)
        ));
    }
    Ok(())
}

/// Refuse an analysis whose answer is made of the dead loads on a model that has none: a
/// weightless model settles by every mechanism at zero work (nothing to certify), and tilts or
/// carries a settlement by nothing.
fn check_dead_loads<S: Assembly>(req: &Request, st: &S) -> Result<()> {
    let needs_weight = match &req.analysis {
        Analysis::Settle(_) => Some("settle"),
        Analysis::Capacity(_) => Some("capacity"),
        Analysis::Tilt(_) => Some("tilt"),
        _ => None,
    };
    if let Some(what) = needs_weight {
        if st.load_vector(false).iter().all(|x| *x == 0.0) {
            return invalid(format!(
                "{what} needs dead loads: the model's blocks weigh nothing (unit_weight 0) and it has no dead loads, so every mechanism would do zero work"
            ));
        }
    }
    Ok(())
}

fn joint_laws(a: &Analysis) -> Option<JointLaws> {
    match a {
        Analysis::Limit(r) => Some(r.laws()),
        Analysis::Settle(r) => Some(r.laws()),
        Analysis::Capacity(r) => Some(r.laws()),
        _ => None,
    }
}

/// The adaptation a request asks for (limit and settle).
fn adapt_of(a: &Analysis) -> Option<crate::analysis::adapt::AdaptOptions> {
    match a {
        Analysis::Limit(r) => r.adapt,
        Analysis::Settle(r) => r.adapt,
        _ => None,
    }
}

/// `--adapt`: the crack lines cut into the 2D mesh and moved to their optimal position; the
/// analysis then runs on the adapted mesh (docs/cracks.md).
fn adapted(
    mut setup: Setup<Model, Structure>,
    req: &Request,
    hooks: &mut Hooks,
) -> Result<(
    Setup<Model, Structure>,
    Option<crate::analysis::adapt::AdaptRecord>,
)> {
    let Some(o) = adapt_of(&req.analysis) else {
        return Ok((setup, None));
    };
    let build = BuildOptions {
        tolerance: req.model.tolerance,
    };
    let solver = req.solver.options(&class(&setup.structure, req));
    let ad = match &req.analysis {
        Analysis::Limit(r) => {
            let laws = r.laws();
            crate::analysis::adapt::limit_adapt(
                &setup.model,
                build,
                &solver,
                laws.crushing(),
                laws.facets(),
                &o,
            )?
        }
        _ => crate::analysis::adapt::settle_adapt(&setup.model, build, &solver, &o)?,
    };
    if let Some(f) = hooks.adapted.as_mut() {
        f(&ad.model, &ad.record);
    }
    setup.model = ad.model;
    setup.structure = ad.structure;
    Ok((setup, Some(ad.record)))
}

/// What a front end may watch while an analysis runs: each new point of an incremental
/// analysis's curve, each finished task of a sweep (called from the worker threads), the
/// adapted model of `--adapt` (its mesh with the crack lines cut in and its supports' motions,
/// given once the adaptation ends and before the final analysis runs on it). Default: nothing.
#[derive(Default)]
pub struct Hooks<'a> {
    pub step: Option<&'a mut dyn FnMut(&IncrementalPoint)>,
    pub task: Option<&'a (dyn Fn() + Sync)>,
    pub adapted: Option<&'a mut AdaptedHook<'a>>,
}

/// The hook told of the adapted model and its record ([`Hooks::adapted`]).
pub type AdaptedHook<'a> = dyn FnMut(&Model, &crate::analysis::adapt::AdaptRecord) + 'a;

/// [`solve_with`] without hooks.
pub fn solve(prepared: Prepared, req: &Request) -> Result<AnyResult> {
    solve_with(prepared, req, &mut Hooks::default())
}

/// Check what needs the structure (a compressive strength for the crushing options, a support
/// motion where one is needed), choose the analysis's variant and run it; `hooks` are told
/// of its progress. A sweep runs its tasks on the current rayon pool.
pub fn solve_with(prepared: Prepared, req: &Request, hooks: &mut Hooks) -> Result<AnyResult> {
    match prepared {
        Prepared::Planar(setup) => {
            if let Some(laws) = joint_laws(&req.analysis) {
                laws.check_strength(&setup.structure, req.names)?;
            }
            let moves = check_supports(req, &setup.model, 2)?;
            check_dead_loads(req, &setup.structure)?;
            let (setup, adapt) = adapted(setup, req, hooks)?;
            let (output, solver) = match &req.analysis {
                Analysis::Tilt(t) => {
                    let (r, solver) = t.solve_2d(&setup.structure, req)?;
                    (Output::Tilt(r), solver)
                }
                _ => solve_more(&setup.structure, req, 2, moves, hooks)?,
            };
            Ok(AnyResult::Planar(Run {
                setup,
                output,
                solver,
                adapt,
            }))
        }
        Prepared::Spatial(setup) => {
            if adapt_of(&req.analysis).is_some() {
                return invalid(format!(
                    "{} moves crack lines of 2D walls; it is not available for 3D models",
                    req.names.name("adapt")
                ));
            }
            let moves = check_supports(req, &setup.model, 3)?;
            check_dead_loads(req, &setup.structure)?;
            let (output, solver) = match &req.analysis {
                Analysis::Tilt(t) => {
                    let (r, solver) = t.solve_3d(&setup.structure, req)?;
                    (Output::Tilt(r), solver)
                }
                _ => solve_more(&setup.structure, req, 3, moves, hooks)?,
            };
            Ok(AnyResult::Spatial(Run {
                setup,
                output,
                solver,
                adapt: None,
            }))
        }
    }
}

/// The analyses that need more of the structure than [`Assembly`] (incremental, identify,
/// sweep), then the others.
fn solve_more<S>(
    st: &S,
    req: &Request,
    dims: usize,
    moves: bool,
    hooks: &mut Hooks,
) -> Result<(Output<S::D>, SolverOptions)>
where
    S: IncrementalGeometry + IdentifyGeometry,
    <S::D as Spatial>::Motion: MotionSize,
{
    match &req.analysis {
        Analysis::Incremental(r) => {
            let mut nothing = |_: &IncrementalPoint| {};
            let progress: &mut dyn FnMut(&IncrementalPoint) = match hooks.step.as_mut() {
                Some(f) => &mut **f,
                None => &mut nothing,
            };
            r.solve(st, req, dims, moves, progress)
        }
        Analysis::Identify(r) => r.solve(st, req, dims),
        Analysis::Sweep(r) => r.solve(st, req, dims, hooks.task.unwrap_or(&|| {})),
        _ => solve_any(st, req, dims),
    }
}

fn solve_any<S: Assembly>(
    st: &S,
    req: &Request,
    dims: usize,
) -> Result<(Output<S::D>, SolverOptions)> {
    match &req.analysis {
        Analysis::Limit(r) => r.solve(st, req, dims),
        Analysis::Settle(r) => r.solve(st, req, dims),
        Analysis::Capacity(r) => r.solve(st, req, dims),
        Analysis::Safety(r) => {
            let c = class(st, req);
            let solver = req.solver.options(&c);
            // The bisection's decisions by a method of their own where the policy gives one
            // and the user named none (large frictional 2D programs: Clarabel).
            let decisions = req
                .solver
                .method
                .is_none()
                .then(|| policy::decision_method(&c))
                .flatten()
                .map(|method| SolverOptions { method, ..solver });
            // Its many programs (bisection, reaction ranges): the result states the method
            // that answered them and every fallback taken.
            let (out, solves) = crate::lp::collecting(|| {
                crate::analysis::safety::safety(st, &r.options(solver, decisions))
            });
            let mut out = out?;
            out.solver = crate::lp::SolverInfo::of_solves(&solver, &solves);
            out.answered = crate::lp::SolverInfo::by_programs(&solver, &solves);
            Ok((Output::Safety(out), solver))
        }
        // Tilt is dispatched by dimension in `solve` (a 2D sign, a 3D azimuth), the others in
        // `solve_more`.
        Analysis::Tilt(_)
        | Analysis::Incremental(_)
        | Analysis::Identify(_)
        | Analysis::Sweep(_) => Err(Error::Request(format!(
            "internal: {} is not solved here",
            req.analysis.name()
        ))),
    }
}

/// The one entry: run `req` on a model of either dimension.
pub fn run(model: &AnyModel, req: &Request) -> Result<AnyResult> {
    solve(prepare(model, req)?, req)
}

/// [`run`], telling `hooks` of the analysis's progress.
pub fn run_with(model: &AnyModel, req: &Request, hooks: &mut Hooks) -> Result<AnyResult> {
    solve_with(prepare(model, req)?, req, hooks)
}
