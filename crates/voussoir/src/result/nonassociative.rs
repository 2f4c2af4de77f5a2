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
