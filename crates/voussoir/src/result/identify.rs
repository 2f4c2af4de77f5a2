//! Result of an inverse settlement analysis ([`crate::analysis::identify`]): the identified
//! support motions, the misfit of every observation, the predicted cracks, the certificate and
//! the minima of the misfit.

use super::{SettlementResult, Spatial};
use crate::dim::Two;
use serde::{Deserialize, Serialize};

/// Whether a motion reproducing the pattern exists.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum IdentifyStatus {
    /// A motion whose settlement mechanism opens exactly the observed pattern was found.
    Identified,
    /// No motion within the bounds makes the observed pattern a settlement mechanism; the
    /// closest motion is reported.
    Inconsistent,
}

/// One unknown's identified value and identifiability.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct UnknownResult {
    pub name: String,
    pub value: f64,
    pub lower_bound: Option<f64>,
    pub upper_bound: Option<f64>,
    /// Smallest and largest value over every motion reproducing the pattern with each width
    /// within its tolerance (None: the range LPs were not run, or no motion is within
    /// tolerance). Unbounded ends are `null` in `range_min`/`range_max`.
    pub range_min: Option<f64>,
    pub range_max: Option<f64>,
    pub range_computed: bool,
    pub identifiable: bool,
    /// One sentence on identifiability.
    pub note: String,
}

/// A support's identified motion (base plus unknowns): `u, v, theta` in 2D, `u, v, w,
/// theta_x, theta_y, theta_z` in 3D (m and rad); it derefs to the motion, so `m.u` reads.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct SupportMotion<D: Spatial = Two> {
    pub support: String,
    #[serde(flatten)]
    pub motion: D::Motion,
}

impl<D: Spatial> std::ops::Deref for SupportMotion<D> {
    type Target = D::Motion;
    fn deref(&self) -> &D::Motion {
        &self.motion
    }
}

/// One observed point against the prediction.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ObservationResult {
    /// Index in `cracks`.
    pub crack: usize,
    pub joint: usize,
    /// Point of the joint (0: start, 1: end).
    pub point: usize,
    pub x: f64,
    pub y: f64,
    /// The point's `z` (3D models; absent in 2D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z: Option<f64>,
    pub observed: f64,
    pub predicted: f64,
    /// predicted − observed (m).
    pub misfit: f64,
    pub tolerance: f64,
    pub within_tolerance: bool,
}

/// A predicted crack (a point that opens).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PredictedCrack {
    pub joint: usize,
    pub point: usize,
    pub x: f64,
    pub y: f64,
    /// The point's `z` (3D models; absent in 2D).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z: Option<f64>,
    pub opening: f64,
    /// `open`, `closed` (observed closed: a contradiction) or `unobserved`.
    pub observed: String,
}

/// The check that the forward settlement analysis of the identified motion reproduces the
/// prediction.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Reproduction {
    /// Forward analysis certified (status mechanism, duality gap within tolerance).
    pub forward_certified: bool,
    /// Work of the dead loads: forward optimum and on the predicted mechanism (kN·m).
    pub forward_work: Option<f64>,
    pub predicted_work: f64,
    /// |forward − predicted| / max(|forward|, floor).
    pub work_relative_difference: Option<f64>,
    /// Largest |forward opening − predicted opening| over all points (m).
    pub max_opening_difference: Option<f64>,
    /// Whether the forward analysis opens exactly the predicted points.
    pub same_open_points: bool,
    /// Forward certified, same work, same open points and openings within 1e-6 of the largest.
    pub reproduces: bool,
    pub message: String,
}

/// Result of an inverse settlement analysis (2D or 3D: the support motions and the forward
/// settlement are those of the model's dimension).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct IdentifyResult<D: Spatial = Two> {
    pub status: IdentifyStatus,
    pub message: String,
    pub unknowns: Vec<UnknownResult>,
    /// Support motions (m, rad) of the identified (or closest) motion; moving supports only.
    pub support_motions: Vec<SupportMotion<D>>,
    pub observations: Vec<ObservationResult>,
    /// Σ |misfit| / tolerance over the observations.
    pub total_misfit: f64,
    /// The same over every observed point, the implicitly closed ones included (equal to
    /// `total_misfit` when identified: closed points are closed by construction).
    pub misfit_all_points: f64,
    pub max_misfit: f64,
    pub predicted_cracks: Vec<PredictedCrack>,
    /// Whether the active set at unobserved points or Coulomb rows had to be fixed after a
    /// first solve.
    pub active_set_fixed: bool,
    pub certificate: Option<Reproduction>,
    /// The local minima of the misfit found (the reported motion first, then separate minima,
    /// least misfit first; at most five).
    #[serde(default)]
    pub minima: Vec<Minimum>,
    /// Whether the misfit landscape was explored beyond the LP candidates (a scan of
    /// directions and a compass search on forward analyses; not on very large models).
    #[serde(default)]
    pub landscape_explored: bool,
    /// The forward settlement analysis of the identified (or closest) motion.
    pub forward: SettlementResult<D>,
}

/// A local minimum of the misfit (Σ |forward opening − observed| / tolerance over every
/// observed point).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Minimum {
    /// The unknowns' values, in the order of `unknowns`.
    pub values: Vec<f64>,
    pub misfit: f64,
    /// Its forward settlement opens exactly the observed crack pattern.
    pub opens_pattern: bool,
    /// Every observed point within its tolerance.
    pub within_tolerance: bool,
    /// The misfit is equally low over a range of motions around it (not unique).
    pub flat: bool,
}
