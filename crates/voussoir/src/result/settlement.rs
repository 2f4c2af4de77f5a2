//! Result of a settlement analysis and its duality certificate.

use super::Spatial;
use super::{BlockMotion, Hinge, JointResult, Reaction, ThrustPoint};
use crate::dim::Two;
use crate::lp::SolverInfo;
use serde::{Deserialize, Serialize};

/// Outcome of a settlement analysis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SettlementStatus {
    /// A mechanism that accommodates the settlement, with forces in equilibrium.
    Mechanism,
    /// The primal is unbounded: the structure cannot stand under its own weight.
    CannotStand,
    /// The primal is infeasible: the prescribed motions cannot be accommodated.
    Incompatible,
}

impl SettlementStatus {
    pub fn sentence(&self) -> &'static str {
        match self {
            SettlementStatus::Mechanism => "the structure accommodates the settlement by the mechanism below",
            SettlementStatus::CannotStand => "the structure cannot stand under its own weight: a mechanism exists in which the dead loads do unbounded work",
            SettlementStatus::Incompatible => "the prescribed support motions cannot be accommodated by any admissible mechanism (they would need interpenetration or sliding)",
        }
    }
}

/// The duality certificate of a settlement result.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Certificate {
    /// Optimum of the primal (work of dead loads) and of the dual (work on the supports).
    pub primal: f64,
    pub dual: f64,
    /// |primal − dual| / max(|primal|, |dual|, floor).
    pub relative_gap: f64,
    /// Largest opening × compression over all points (kN·m).
    pub complementarity: f64,
    /// Largest equilibrium residual of the dual's forces (kN or kN·m).
    pub equilibrium_residual: f64,
    /// Whether the gap is within tolerance (1e-7).
    pub ok: bool,
}

/// Result of a settlement analysis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct SettlementResult<D: Spatial = Two> {
    pub status: SettlementStatus,
    pub message: String,
    /// The solver and method that produced the result.
    pub solver: SolverInfo,
    /// Work of the dead loads on the mechanism (primal optimum), kN·m.
    pub work_dead_loads: Option<f64>,
    /// Work of the structure's forces on the moving supports (dual optimum), kN·m.
    pub work_reactions: Option<f64>,
    /// Relative duality gap.
    pub duality_gap: Option<f64>,
    pub certificate: Option<Certificate>,
    /// Block motions (m, rad) for the prescribed settlement.
    pub blocks: Vec<BlockMotion<D>>,
    pub joints: Vec<JointResult<D>>,
    pub hinges: Vec<Hinge<D>>,
    /// The cracks ([`super::cracks`]): polylines through consecutive open joints in 2D
    /// (`points`, `length` m, `max_opening` m), one record per cracked joint in 3D; widest first.
    #[serde(default)]
    pub cracks: Vec<D::Crack>,
    pub thrust_line: Vec<ThrustPoint<D>>,
    pub reactions: Vec<Reaction<D>>,
    /// The non-associative friction iteration, when one was run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction_iteration: Option<super::FrictionIteration>,
    /// The geometry analysed (for drawing a saved result).
    pub geometry: D::Shapes,
    /// The canonical selection among optimal solutions (absent for the solver's own
    /// solution, e.g. with `--raw`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub canonical: Option<super::Canonical<D>>,
    /// `cannot_stand`: the certificate that the dead loads have no equilibrium (the force
    /// program infeasible, decided by its elastic program; [`super::NoEquilibriumCertificate`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub no_equilibrium: Option<super::NoEquilibriumCertificate>,
}

/// Tolerance on the relative duality gap.
pub const GAP_TOLERANCE: f64 = 1e-7;
