//! Result of a limit analysis.

use super::Spatial;
use super::{BlockMotion, Hinge, JointResult, Reaction, ThrustPoint};
use crate::dim::Two;
use crate::lp::SolverInfo;
use serde::{Deserialize, Serialize};

/// Outcome of a limit analysis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LimitStatus {
    /// A finite collapse multiplier λ ≥ 0 and its mechanism.
    Collapse,
    /// No finite collapse load: equilibrium holds for every λ ("locked").
    Locked,
    /// No equilibrium under the dead loads alone (λ would have to be negative, or no λ works).
    NoEquilibrium,
}

impl LimitStatus {
    pub fn sentence(&self) -> &'static str {
        match self {
            LimitStatus::Collapse => "collapse: finite load multiplier with its mechanism",
            LimitStatus::Locked => "no finite collapse load: the structure is locked (equilibrium for every load multiplier)",
            LimitStatus::NoEquilibrium => "no equilibrium under the dead loads: the structure cannot stand even without live load",
        }
    }
}

/// The certificate of a "cannot stand" answer (issue 29 item 3): the equilibrium of the dead
/// loads with no tension and the joints' friction — the statics, the same set whether friction
/// is associative or not — decided infeasible again by its elastic program
/// ([`crate::lp::sequence::decide_feasibility`]), whose duals are a Farkas certificate: row
/// multipliers that bound the least total violation of the equilibrium rows from below.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NoEquilibriumCertificate {
    /// The least total violation of the equilibrium rows, relative to the largest row bound
    /// (of the nondimensional program); `null` where no method decided.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub violation: Option<f64>,
    /// The method whose elastic program decided; `null` where none did.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub method: Option<crate::lp::Method>,
    /// Decided infeasible with its certificate, as the result says. False where no method
    /// decided, or where the elastic program found an equilibrium after all.
    pub ok: bool,
}

/// The certificate of a collapse multiplier (issue 18: every result at any size states it):
/// the static λ of the force program against the kinematic multiplier of the mechanism read
/// from its duals, and that mechanism's admissibility. Computed for the joint laws whose
/// kinematic multiplier is the dead loads' work alone (no-tension joints, with or without
/// associative Coulomb friction without cohesion, rigid in compression); absent otherwise.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LimitCertificate {
    /// `|λ − λ_kin| / max(|λ|, 1e-12)` with `λ_kin = −F_D·d` for the mechanism `d`
    /// normalised to `F_L·d = 1`.
    pub gap: f64,
    /// The mechanism's largest violation of the joints (interpenetration, or sliding where
    /// the joint forbids it), relative to its largest joint opening.
    pub admissibility: f64,
    /// Both within [`CERTIFICATE_TOLERANCE`]. When false the message says that λ is not
    /// certified (the solver stopped short of the optimum).
    pub ok: bool,
}

/// The relative tolerance of [`LimitCertificate::ok`].
pub const CERTIFICATE_TOLERANCE: f64 = 1e-6;

/// Result of a limit analysis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct LimitResult<D: Spatial = Two> {
    pub status: LimitStatus,
    pub message: String,
    /// The solver and method that produced the result.
    pub solver: SolverInfo,
    /// λ: the collapse multiplier (negative when the dead loads alone cannot be carried and the
    /// live load, reversed, would be needed; `null` when locked or infeasible).
    pub load_multiplier: Option<f64>,
    /// The least multiplier in equilibrium (`null` when unbounded below): the structure stands
    /// under its dead loads alone only if it is ≤ 0. When it is positive the status is
    /// `no_equilibrium` and `[least_load_multiplier, load_multiplier]` is the range of λ in
    /// which it stands.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub least_load_multiplier: Option<f64>,
    /// The certificate of λ at collapse (absent for other statuses and for joint laws whose
    /// kinematic multiplier has more terms than the dead loads' work).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub certificate: Option<LimitCertificate>,
    /// Work of the dead loads and of the live loads on the mechanism (−λ and 1 at collapse).
    pub work_dead_loads: Option<f64>,
    pub work_live_loads: Option<f64>,
    /// The collapse mechanism (normalised: unit work of the live loads).
    pub blocks: Vec<BlockMotion<D>>,
    pub joints: Vec<JointResult<D>>,
    pub hinges: Vec<Hinge<D>>,
    /// The cracks ([`super::cracks`]): polylines through consecutive open joints in 2D
    /// (`points`, `length` m, `max_opening`: opening rates of the normalised mechanism, whose amplitude is arbitrary), one record per cracked joint in 3D; widest first.
    #[serde(default)]
    pub cracks: Vec<D::Crack>,
    pub thrust_line: Vec<ThrustPoint<D>>,
    pub reactions: Vec<Reaction<D>>,
    /// Simplex iterations spent.
    pub iterations: i64,
    /// The non-associative friction iteration, when one was run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction_iteration: Option<super::FrictionIteration>,
    /// The geometry analysed (for drawing a saved result).
    pub geometry: D::Shapes,
    /// The canonical selection among optimal solutions (absent for the solver's own
    /// solution, e.g. with `--raw`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub canonical: Option<super::Canonical<D>>,
    /// `no_equilibrium` without a multiplier: the certificate that no equilibrium exists.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub no_equilibrium: Option<NoEquilibriumCertificate>,
}
