//! Result of the non-associative friction iteration.

use super::limit::LimitResult;
use super::Spatial;
use crate::dim::Two;
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct NonAssociativeResult<D: Spatial = Two> {
    /// λ of the associative problem (an upper bound in practice).
    pub associative_multiplier: Option<f64>,
    /// λ per iteration.
    pub history: Vec<f64>,
    pub converged: bool,
    /// The final limit analysis (forces, mechanism without dilatancy).
    pub limit: LimitResult<D>,
}

/// The non-associative friction iteration behind a result (absent with associative friction).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrictionIteration {
    /// The value with associative friction (dilatant sliding): λ, or the settlement work.
    pub associative: Option<f64>,
    /// The value per iteration (λ, or the work of the dead loads less the sliding dissipation).
    pub history: Vec<f64>,
    pub converged: bool,
}
