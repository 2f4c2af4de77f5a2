//! What the limit, settlement and capacity analyses share, below all of them: the crushing
//! model and its facets, the settings of the non-associative iteration, and two kinematic checks
//! of a mechanism. Keeping them here lets `limit`, `settlement`, `nonassociative`, `paths` and
//! `capacity` depend on each other in one direction only.

use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::structure::{Assembly, OPEN_TOLERANCE};
use serde::{Deserialize, Serialize};

/// How finite compressive strength enters the limit analysis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Crushing {
    /// Inscribed polygon with `facets` chords: an LP (HiGHS). The default.
    #[default]
    Linear,
    /// The exact parabola as second-order cones (Clarabel).
    Conic,
}

/// Fewest and most facets of the inscribed crushing polygon. Two chords are the coarsest
/// polygon that still allows an eccentric thrust; 4,096 chords put the polygon within
/// (t/2)·(1/4096)² of the parabola, far below any tolerance of the solvers, while bounding the
/// program's size (two rows per facet and joint).
pub const MIN_FACETS: usize = 2;
pub const MAX_FACETS: usize = 4096;
/// Facets of the inscribed crushing polygon unless told otherwise.
pub const DEFAULT_FACETS: usize = 16;

/// A one-line error unless `facets` is within [`MIN_FACETS`]..=[`MAX_FACETS`].
pub fn check_facets(facets: usize) -> Result<()> {
    if !(MIN_FACETS..=MAX_FACETS).contains(&facets) {
        return Err(Error::Request(format!(
            "facets {facets}: the crushing polygon needs between {MIN_FACETS} and {MAX_FACETS} facets"
        )));
    }
    Ok(())
}

/// Settings of the iteration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NonAssociativeOptions {
    pub max_iterations: usize,
    /// Relaxation α in (0, 1].
    pub relaxation: f64,
    /// Convergence: relative change of the value (λ or the work) and of the normal forces.
    pub tolerance: f64,
    /// Iterations over which the value must stay within `tolerance` (2: consecutive values,
    /// with the normal forces within `√tolerance` too; more: a window of values only).
    pub window: usize,
    /// With `window` 2, the iteration also ends, converged, once the value has stayed within
    /// `band_tolerance` (relative) over the last `band_window` iterations (below 3: never):
    /// where the normal forces wander over a large optimal face, consecutive values never agree
    /// to `tolerance` (the 1.0 m running-bond façade: λ within ±0.15 % for 170 iterations,
    /// docs/performance.md, "Non-associative façade (session 24)").
    pub band_window: usize,
    pub band_tolerance: f64,
}

impl Default for NonAssociativeOptions {
    fn default() -> Self {
        NonAssociativeOptions {
            max_iterations: 200,
            relaxation: 0.5,
            tolerance: 1e-7,
            window: 2,
            band_window: 8,
            band_tolerance: 1e-3,
        }
    }
}

impl NonAssociativeOptions {
    /// The settings of the settlement and capacity analyses: the optimal force fields of a
    /// settlement are rarely unique, so the normal forces wander on the optimal face while the
    /// work settles; convergence is a spread of the work below 1e-3 over 8 iterations.
    pub fn settlement() -> Self {
        NonAssociativeOptions {
            max_iterations: 120,
            relaxation: 0.5,
            tolerance: 1e-3,
            window: 8,
            band_window: 0,
            band_tolerance: 0.0,
        }
    }
}

/// Largest violation of kinematic admissibility of block motions `d` (with the prescribed
/// support motions scaled by `support_scale`: 1 for a settlement, 0 for a collapse mechanism,
/// which is a rate with the supports held still): interpenetration `max(0, −(N d + g_n))` at
/// contact points, `|N d + g_n|` at bilateral points, and sliding `|T d + g_t|` on joints
/// without friction, over points that carry force (for a collapse mechanism, not the points of
/// an existing crack, which carry nothing until they close).
pub fn kinematic_violation(map: &KinematicMap, d: &[f64], support_scale: f64) -> f64 {
    let (open, slide) = map.jumps(d, support_scale);
    let mut v = 0.0f64;
    for k in 0..map.num_points() {
        // A point with a gap (an existing crack) may close it, not pass through it. A collapse
        // mechanism (`support_scale` 0) is a rate: an open crack carries nothing and its rate
        // of opening or closing is free (the limit programs leave it so), whatever the width.
        if support_scale == 0.0 && map.gap[k] > 0.0 {
            continue;
        }
        let o = if map.bilateral[k] {
            open[k].abs()
        } else {
            (-(open[k] + map.gap[k])).max(0.0)
        };
        // Sliding is a violation only where the joint law forbids it (Heyman's joints); a
        // frictional joint may slide (its dilatancy is in the opening rows).
        let nt = map.tangents_per_point;
        let s = if map.laws[map.points[k].joint].friction.is_some() || map.gap[k] > 0.0 {
            0.0
        } else {
            slide[k * nt..(k + 1) * nt]
                .iter()
                .fold(0.0f64, |m, x| m.max(x.abs()))
        };
        v = v.max(o).max(s);
    }
    v
}

/// Open points whose opening rate under mechanism `d` is negative: the joints whose settlement
/// cracks the mechanism would close.
pub fn closing_joints<S: Assembly>(st: &S, map: &KinematicMap, d: &[f64]) -> Vec<usize> {
    if d.is_empty() {
        return vec![];
    }
    let (rate, _) = map.jumps(d, 0.0);
    let tol = OPEN_TOLERANCE * crate::scale::motion_scale(map, d, 0.0);
    let mut out: Vec<usize> = map
        .points
        .iter()
        .enumerate()
        .filter(|(k, _)| map.gap[*k] > 0.0 && rate[*k] < -tol)
        .map(|(_, p)| p.joint)
        .collect();
    out.dedup();
    let _ = st;
    out
}
