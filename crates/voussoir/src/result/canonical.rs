//! What the canonical selection among optimal solutions reports (settlement and limit
//! analyses; see `docs/canonical.md`).

use super::Spatial;
use crate::dim::Two;
use serde::{Deserialize, Serialize};

/// Which criterion fixed the reported mechanism.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Selection {
    /// The optimum itself: the optimal mechanism is unique.
    Optimum,
    /// The least crack area `Σ w_k o_k` among the optimal mechanisms, which is unique.
    LeastCrackArea,
    /// Among the mechanisms of least crack area (not unique), the vertex of least value of a
    /// fixed generic linear functional of the block motions (a documented, reproducible
    /// tie-break; `docs/canonical.md`).
    GenericVertex,
}

/// The canonical mechanism: how it was selected among the optimal mechanisms.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CanonicalMechanism {
    /// Whether the optimal mechanism is unique (the optimal face is a single point: a generic
    /// linear functional takes one value on it, see `docs/canonical.md`).
    pub unique: bool,
    /// The criterion that fixed the reported mechanism.
    pub selected_by: Selection,
    /// Crack area `Σ w_k o_k` (openings times tributary joint size: m² in 2D per unit of the
    /// mechanism's normalisation) of the solver's own optimal mechanism and of the reported one.
    pub crack_area_solver: f64,
    pub crack_area: f64,
    /// Whether the reported mechanism differs from the solver's own.
    pub changed: bool,
    /// Programs solved for the selection (beyond the analysis's own).
    pub solves: usize,
}

/// A support's reaction over the physical optimal force fields: componentwise least and
/// largest value (each a separate LP).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct ReactionRange<D: Spatial = Two> {
    pub support: String,
    /// Whether every component is the same in every physical optimal field (range below
    /// tolerance).
    pub unique: bool,
    pub min: D::Wrench,
    pub max: D::Wrench,
}

/// The canonical force field: physical (open points unloaded, Coulomb's cone at every point)
/// and of least complementary energy among the optimal ones.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct CanonicalForces<D: Spatial = Two> {
    /// The least friction coefficient μ for which an optimal field with unloaded open points
    /// has `|p_t| ≤ μ p_n` at every point of the joints without friction of their own, from
    /// above to the relative precision `friction_precision`: an optimal field needs no more,
    /// and none admits `least_friction · (1 − friction_precision)` (`null` when every joint has
    /// its own friction, or when no μ ≤ 100 admits one). Not certified where `selected_by` is
    /// `force_program`: no field at that μ certified with the mechanism (the summary says so).
    pub least_friction: Option<f64>,
    /// Where the search stopped above its limit (the default, 2: above masonry's friction;
    /// docs/canonical.md "The forces"): the largest μ shown inadmissible. The least μ then lies
    /// above it and at most `least_friction`, the admissible field's own ratio; absent
    /// otherwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub least_friction_above: Option<f64>,
    /// The relative precision to which `least_friction` is shown to be the least: `1 − lo /
    /// least_friction`, `lo` the largest μ a program showed inadmissible. At most the request's
    /// `least_friction_precision` (default 0.05) when every trial of the bisection was decided;
    /// more where Clarabel left one undecided; 0 when the least is 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction_precision: Option<f64>,
    /// The μ imposed on those joints in the reported field: the least one the bisection tried
    /// and found admissible (`least_friction` up to the bisection's precision); `null` when
    /// none was imposed.
    pub friction: Option<f64>,
    /// The largest `|p_t|/p_n` of the reported field on the joints without friction of their
    /// own: the friction coefficient this field needs (at least `least_friction`); `null` when
    /// every joint has its own friction.
    #[serde(default)]
    pub friction_demand: Option<f64>,
    /// What fixed the reported field: `least_energy` (the least complementary energy);
    /// `admissible` when the energy QP did not end optimal, or its field did not certify, and
    /// the admissible field of the last feasibility program at the imposed μ stands instead;
    /// `force_program` when neither certified (see `rejected`).
    #[serde(default)]
    pub selected_by: ForceSelection,
    /// Whether the open points carry nothing at all. False when every optimal field needs
    /// shear at some open points (Heyman's no-sliding rule holds at open joints too, and a
    /// mechanism may lean on it): their normal force is still zero, their shear is kept as
    /// small as the optimal set allows (weighted 10³ in the energy) and reported in
    /// `largest_open_force`, and Coulomb's rule is imposed on the other points.
    pub physical: bool,
    /// Largest force (normal or shear, kN) at a point open in the mechanism, and largest
    /// `|p_t| − μ p_n` (kN) over all points, in the reported field: both ~0.
    pub largest_open_force: f64,
    pub largest_friction_excess: f64,
    /// The range of every support's reaction over the physical optimal fields.
    pub reaction_ranges: Vec<ReactionRange<D>>,
    /// Programs solved for the selection.
    pub solves: usize,
    /// Trials of the least-μ bisection decided by a bounded elastic program instead of a
    /// feasibility program (large 2D models, docs/canonical.md "The forces").
    #[serde(default, skip_serializing_if = "is_zero")]
    pub elastic_trials: usize,
    /// The candidate fields not reported, in the order they were tried: least energy,
    /// admissible, the force program's own optimum. Each either with its relative duality gap
    /// (its certificate failed) or with the reason it was not computed (the energy QP stopped
    /// at its iteration cap, or did not end optimal). Empty when the first candidate certified.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub rejected: Vec<RejectedField>,
}

/// A candidate force field not reported: its certificate failed, or its program gave no
/// field to certify.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RejectedField {
    pub field: ForceSelection,
    /// Its relative duality gap with the reported mechanism (above the tolerance, 1e-7);
    /// `None` (absent in JSON) when no field was computed (`reason`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gap: Option<f64>,
    /// Why no field was computed, e.g. "the energy QP stopped at its cap of 100 iterations"
    /// (absent when `gap` is given).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

/// What fixed the canonical force field among the admissible ones.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ForceSelection {
    /// The least complementary energy (unique).
    #[default]
    LeastEnergy,
    /// The energy QP did not end optimal: an admissible field (the solution of the feasibility
    /// program at the imposed μ), physical by the same rules but not the least-energy one, nor
    /// unique.
    Admissible,
    /// Neither canonical field certified (its duality gap with the mechanism above 1e-7): the
    /// optimum of the force program itself, solved through the solver layer's fallback chain
    /// (an optimal field, not a canonical one: friction at the least μ not imposed).
    ForceProgram,
}

impl ForceSelection {
    /// A few words naming the field.
    pub fn name(self) -> &'static str {
        match self {
            ForceSelection::LeastEnergy => "the least-energy field",
            ForceSelection::Admissible => "the admissible field",
            ForceSelection::ForceProgram => "the force program's optimum",
        }
    }
}

impl<D: Spatial> CanonicalForces<D> {
    /// The summary's line on the reported field: what fixed it, its open points, and the least
    /// admissible μ with the precision shown. Where no canonical field certified (the force
    /// program's own optimum is reported) that μ, the bisection's, is said to be uncertified
    /// instead of printed as the least (session 25: it read as a certified bound).
    pub fn summary_line(&self) -> String {
        // What fixed the field: the least energy, or (that program not optimal) admissibility.
        let crit = match self.selected_by {
            ForceSelection::LeastEnergy => "least complementary energy",
            ForceSelection::Admissible => {
                if self
                    .rejected
                    .iter()
                    .any(|r| r.field == ForceSelection::LeastEnergy && r.gap.is_some())
                {
                    "an admissible field (the least-energy field did not certify: not the least-energy field, nor unique)"
                } else {
                    "an admissible field (the least-energy program did not end optimal: not the least-energy field, nor unique)"
                }
            }
            ForceSelection::ForceProgram => {
                "the force program's own optimum (no canonical field certified: not canonical, μ not imposed)"
            }
        };
        let precision = || {
            self.friction_precision
                .map(|p| {
                    if p >= 1.0 - 1e-12 {
                        return " (an admissible μ: no smaller one was shown inadmissible)"
                            .to_string();
                    }
                    let pc = if p >= 0.01 {
                        format!("{:.1}", 100.0 * p)
                    } else {
                        format!("{:.4}", 100.0 * p)
                    };
                    let pc = pc.trim_end_matches('0').trim_end_matches('.');
                    format!(" (to {pc} %)")
                })
                .unwrap_or_default()
        };
        match (self.least_friction, self.friction) {
            (Some(l), _) if self.selected_by == ForceSelection::ForceProgram => {
                let open = if self.physical {
                    "open points unloaded".to_string()
                } else {
                    format!(
                        "open points carry up to {} kN of shear",
                        crate::lengths::force(self.largest_open_force, 4, false)
                    )
                };
                format!(
                    "canonical forces: {crit}, {open}; the least μ is not certified: the bisection's least admissible μ ({l:.4}) has no certified field"
                )
            }
            (Some(l), m) if let Some(above) = self.least_friction_above => {
                // Masonry joints: μ about 0.6–0.8, rough stone about 1.
                let masonry = if above >= 1.0 {
                    ": more than masonry's friction, so Heyman's no-sliding rule carries this field"
                } else {
                    ""
                };
                format!(
                    "canonical forces: {crit}, open points unloaded, |shear| ≤ μ·normal with μ = {:.4}; the least μ lies between {above:.4} (shown inadmissible) and {l:.4}{masonry} (the default search stops there; --least-friction-precision searches on)",
                    m.unwrap_or(l)
                )
            }
            (Some(l), _) => format!(
                "canonical forces: {crit}, open points unloaded, |shear| ≤ μ·normal with the least admissible μ = {l:.4}{}",
                precision()
            ),
            (None, None) if self.physical => {
                format!("canonical forces: {crit}, open points unloaded")
            }
            _ => format!(
                "canonical forces: open points carry no normal force, but every optimal field needs shear at some of them (up to {} kN: the no-sliding rule holds at open joints); {crit}",
                crate::lengths::force(self.largest_open_force, 4, false)
            ),
        }
    }
}

/// The canonical selection of a result.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Canonical<D: Spatial = Two> {
    pub mechanism: CanonicalMechanism,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub forces: Option<CanonicalForces<D>>,
}

/// The canonical selection of the collapse mechanisms of a sequence of steps (a capacity
/// curve's, an incremental analysis's): flattened into [`super::capacity::CapacityCanonical`]
/// and [`super::incremental::IncrementalCanonical`], so that its fields stand in their JSON
/// records as their own. Filled in step by step by `StepSelection::select`
/// (`crate::analysis::canonical`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StepSelection {
    /// Whether the steps' collapse mechanisms were selected (else they are the solver's).
    pub steps: bool,
    /// Steps whose collapse mechanism was selected, and of those the ones where it differs from
    /// the solver's.
    pub steps_selected: usize,
    pub steps_changed: usize,
    /// Steps with a multiplier where the selection was not reached (the solver's mechanism
    /// stands there).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub steps_not_reached: Vec<usize>,
    /// Programs solved for the selection (the settlement's included).
    pub solves: usize,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}
