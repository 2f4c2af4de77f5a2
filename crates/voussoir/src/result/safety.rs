//! Result of a safety assessment ([`crate::analysis::safety`]): does the structure stand under
//! its dead loads, with what geometric margin, and between which extreme states its support
//! reactions can move.

use crate::lp::{self, SolverInfo};
use serde::{Deserialize, Serialize};

/// The range of one component of a support's reaction over the statically admissible states.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ComponentRange {
    /// `fx`, `fy` (2D) or `fx`, `fy`, `fz` (3D, z up): the force the support exerts on the
    /// structure.
    pub component: String,
    /// Least and largest value (kN); `null`: unbounded on that side (e.g. the thrust of a flat
    /// lintel with infinite compressive strength).
    pub min: Option<f64>,
    pub max: Option<f64>,
}

/// The ranges of a support's reaction components.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AdmissibleReactionRange {
    pub support: String,
    pub components: Vec<ComponentRange>,
}

impl AdmissibleReactionRange {
    /// The range of a component by name (`"fx"`, …).
    pub fn component(&self, name: &str) -> Option<&ComponentRange> {
        self.components.iter().find(|c| c.component == name)
    }
}

/// Result of `voussoir safety`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SafetyResult {
    /// Whether an equilibrium state exists under the dead loads alone (contact forces in
    /// equilibrium that respect the joint laws: no tension, no sliding or Coulomb friction,
    /// finite strength where given).
    pub stands: bool,
    pub message: String,
    /// The solver and method that produced the result.
    pub solver: SolverInfo,
    /// Heyman's geometric safety factor: every joint's thickness divided by the least
    /// thickness, joints shrunk about their centres by one common fraction, at which an
    /// equilibrium state still exists (`1 / least_joint_fraction`). `null` if the structure
    /// does not stand, or stands with every joint shrunk to its centre (unbounded factor).
    pub geometric_safety_factor: Option<f64>,
    /// The least fraction of every joint's extent (about its centre) through which the dead
    /// loads can still be carried, to `tolerance`; `null` if the structure does not stand.
    pub least_joint_fraction: Option<f64>,
    /// Absolute tolerance of the bisection on the joint fraction.
    pub tolerance: f64,
    /// Range of every support's reaction force components over the statically admissible
    /// states (empty if the structure does not stand): for an arch, the least and the largest
    /// horizontal thrust, the two states between which a settlement moves it.
    pub reactions: Vec<AdmissibleReactionRange>,
    /// LP solves spent.
    pub solves: usize,
    /// Reaction range ends given by a symmetry of the structure without a program of their
    /// own: the image of an end solved for another support (a mirror in 2D; a rotation about a
    /// vertical axis or a mirror in a vertical plane in 3D), each certified on its own program
    /// (docs/safety.md).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub reaction_ends_by_symmetry: usize,
    /// Which method answered each kind of program, and why where it is not the one asked for
    /// (a warm start, a fallback, or a kind that goes to a method of its own by design:
    /// docs/safety.md); empty (and not written) where it was not gathered.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub answered: Vec<lp::ProgramAnswers>,
}

/// A least thickness found by bisection on a generator's thickness.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LeastThickness {
    /// The least thickness at which the structure stands, to `tolerance` (the upper end of the
    /// final bracket: the structure stands there).
    pub thickness: f64,
    /// The final bracket: does not stand at `below`, stands at `thickness`.
    pub below: f64,
    pub tolerance: f64,
    /// Bisection steps (one equilibrium LP each, after the two ends).
    pub steps: usize,
}

/// What the least-thickness analysis reports (`voussoir least-thickness --json`;
/// [`crate::request::least_thickness`]).
#[derive(Clone, Debug, Serialize)]
pub struct LeastThicknessResult {
    pub generator: &'static str,
    /// The least thickness (m) at which the structure stands, and the bracket.
    #[serde(flatten)]
    pub found: LeastThickness,
    /// The radius of the centreline at the least thickness (m), and thickness / that radius
    /// (Milankovitch's t/R = 0.1075 for a semicircular arch, Heyman's 0.042 for a hemisphere).
    pub centreline_radius: f64,
    pub thickness_over_radius: f64,
    pub solver: SolverInfo,
    /// How each decision of the bisection was answered, as `safety` reports it
    /// ([`SafetyResult::answered`]): per kind of program and method, the answers and their
    /// outcome (`certified`: an equilibrium state checked on the program, or a feasibility
    /// decided by the elastic program with its certificate either way; `infeasible`: the dual
    /// simplex's proof of infeasibility).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub answered: Vec<lp::ProgramAnswers>,
    /// Every decision answered with a certificate (each line of `answered` `certified` or
    /// `infeasible`, a `not certified` answer counting only where a later line of its kind
    /// decided it again).
    pub certified: bool,
}

/// The reaction ranges and what they cost ([`crate::analysis::safety::reaction_ranges_by`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ReactionRanges {
    pub ranges: Vec<AdmissibleReactionRange>,
    /// LP solves.
    pub solves: usize,
    /// Of those, started from the basis of the one before ([`lp::sequence`]).
    pub warm: usize,
    /// Warm solves that failed or did not certify and were solved again from scratch.
    pub restarts: usize,
    /// Endpoints given by statics without a program of their own (one support: the total
    /// load; two supports: the other support's optimum).
    pub from_statics: usize,
    /// The largest relative primal violation, dual violation and duality gap of the
    /// endpoints' certificates ([`lp::sequence::certify`]).
    pub worst: lp::sequence::Certificate,
    /// Endpoints certified unbounded by a ray ([`lp::sequence::certify_ray`]).
    pub unbounded: usize,
    /// Recession programs solved to find those rays (one ray certifies every endpoint it
    /// improves).
    pub ray_programs: usize,
    /// Endpoints certified unbounded by a ray along the free columns, found without a program
    /// (the objective projected onto their lineality space: [`lp::sequence::Lineality`]).
    pub lineality_rays: usize,
    /// The largest relative violation of the recession cone by the rays used.
    pub worst_ray: f64,
    /// Endpoints given by the mirror image of another support's optimum (a structure
    /// symmetric about a vertical line), certified on their own program without solving it.
    pub mirrored: usize,
    /// Endpoints certified unbounded by a ray found on the blocks around the support (a small
    /// recession program of a few blocks' rows; the ray certified on the side's own program).
    pub local_rays: usize,
    /// The small recession programs solved to look for them (counted in `solves` too).
    pub local_ray_programs: usize,
    /// Endpoints of a component with no column (a support without a contact point): 0, no
    /// program.
    pub without_columns: usize,
    /// Columns left out of the sequence's program as twins of another (the same bounds,
    /// entries to round-off and coefficient in every objective: in 2D the two shear forces of a
    /// joint); every answer is expanded and certified on the whole program.
    pub twin_columns: usize,
}

impl ReactionRanges {
    /// Every endpoint certified ([`lp::sequence::CERTIFICATE_TOLERANCE`]).
    pub fn certified(&self) -> bool {
        self.worst.ok() && self.worst_ray <= lp::sequence::CERTIFICATE_TOLERANCE
    }
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}
