//! Result of a tilting-table analysis.

use super::limit::LimitResult;
use super::Spatial;
use crate::dim::Two;
use serde::{Deserialize, Serialize};

/// Result of a tilting-table analysis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct TiltResult<D: Spatial = Two> {
    /// Critical tilt angle in degrees (towards +x for direction +1, towards −x for −1);
    /// `null` when the structure never collapses (locked) or cannot stand untilted.
    pub tilt_angle: Option<f64>,
    /// +1 or −1 (2D).
    pub direction: f64,
    /// Azimuth of the tilt in degrees from x towards y (3D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub azimuth: Option<f64>,
    /// The underlying limit analysis (λ = tan α) with its mechanism.
    pub limit: LimitResult<D>,
}
