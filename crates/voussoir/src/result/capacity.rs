//! Result of a capacity analysis: the curve λ(s) and the zero-capacity settlement.

use super::limit::LimitStatus;
use super::Spatial;
use super::{BlockMotion, Hinge};
use crate::dim::Two;
use crate::lp::SolverInfo;
use serde::{Deserialize, Serialize};

/// One point of the capacity curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct CapacityPoint<D: Spatial = Two> {
    /// Settlement magnitude s (m; rad when the supports only rotate: [`SettlementUnit`]).
    pub settlement: f64,
    /// λ(s): collapse multiplier on the deformed geometry; negative when the dead loads alone
    /// cannot be carried; `null` when locked or without any equilibrium.
    pub load_multiplier: Option<f64>,
    pub status: LimitStatus,
    /// False when the collapse mechanism closes points opened by the settlement (standard limit
    /// analysis is then not valid: use the incremental analysis).
    pub valid: bool,
    /// Joints with an open point that the collapse mechanism would close.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub closing_joints: Vec<usize>,
    /// Hinges of the collapse mechanism (positions on the deformed geometry).
    pub hinges: Vec<Hinge<D>>,
    /// Points of the model's existing cracks still open at this settlement (absent when the
    /// model has none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub existing_cracks_open: Option<usize>,
    /// The certificate of this step's answer ([`StepCertificate`]); absent where the joint
    /// laws have none (cohesion, crushing, non-associative friction) or the step is locked.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub certificate: Option<StepCertificate>,
}

/// What a step's certificate certifies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StepCertificateKind {
    /// λ (of either sign) against the kinematic multiplier of the mechanism read from the
    /// duals, and that mechanism's admissibility: the certificate `limit` reports
    /// ([`super::limit::LimitCertificate`]).
    Multiplier,
    /// No equilibrium for any λ: the elastic program's least violation of the equilibrium
    /// rows, bounded away from zero by its duals (a Farkas certificate of infeasibility:
    /// [`crate::lp::sequence::decide_feasibility`]).
    NoEquilibrium,
}

/// The certificate of one step of a capacity curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StepCertificate {
    pub kind: StepCertificateKind,
    /// `multiplier`: `|λ − λ_kin| / max(|λ|, 1e-3 λ_unit)`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gap: Option<f64>,
    /// `multiplier`: the mechanism's largest violation of the joints, relative to its largest
    /// opening.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub admissibility: Option<f64>,
    /// `no_equilibrium`: the least total violation of the equilibrium rows, relative to the
    /// largest row bound (the Farkas certificate proves it positive).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub violation: Option<f64>,
    /// Certified: gap and admissibility within [`super::limit::CERTIFICATE_TOLERANCE`], or
    /// the infeasibility decided with its certificate.
    pub ok: bool,
}

/// The certificates of a whole curve: every step's, summed up (what the benchmark and the
/// text summary read).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CapacityCertificate {
    /// Steps of the curve.
    pub steps: usize,
    /// Of those, the ones answered with a certificate that holds.
    pub certified: usize,
    /// The steps (indices into `curve`) without a certificate that holds.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub uncertified_steps: Vec<usize>,
    /// The largest gap and admissibility over the steps' multiplier certificates (0 when
    /// there is none).
    pub gap: f64,
    pub admissibility: f64,
    /// Every step certified.
    pub ok: bool,
}

/// The collapse mechanism at one settlement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct CapacityMechanism<D: Spatial = Two> {
    pub settlement: f64,
    /// Block motion rates, normalised to unit work of the live loads.
    pub blocks: Vec<BlockMotion<D>>,
}

/// A support's motion per unit settlement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SupportDirection {
    pub support: String,
    /// `[u, v, θ]` in 2D, `[u, v, w, θx, θy, θz]` in 3D, per unit settlement (per metre, or
    /// per radian when the supports only rotate; θ in radians).
    pub motion: Vec<f64>,
}

/// What the settlement magnitude `s` of a capacity analysis measures, and how it is shown.
///
/// `s` is the largest support translation, in metres; when no support translates (the
/// settlement is a rotation of the supports), the largest support rotation, in radians. A
/// translation is shown in cm and a rotation in mrad (the drawings, the tables and the messages
/// all follow this choice).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SettlementUnit {
    /// `s` is a translation (m), shown in cm.
    Translation,
    /// `s` is a rotation (rad), shown in mrad.
    Rotation,
}

impl SettlementUnit {
    /// How many of a support motion's `n` components are translations: 2 of `[u, v, θ]`, 3 of
    /// `[u, v, w, θx, θy, θz]`.
    pub fn translations(n: usize) -> usize {
        if n >= 6 {
            3
        } else {
            n.min(2)
        }
    }

    /// The kind of settlement whose directions per unit settlement are `direction` (a rotation
    /// when no moving support translates).
    pub fn of(direction: &[SupportDirection]) -> SettlementUnit {
        let translates = direction.iter().any(|d| {
            let n = SettlementUnit::translations(d.motion.len());
            d.motion[..n].iter().any(|&x| x != 0.0)
        });
        if direction.is_empty() || translates {
            SettlementUnit::Translation
        } else {
            SettlementUnit::Rotation
        }
    }
    /// The SI unit of `s`: "m" or "rad".
    pub fn si(self) -> &'static str {
        match self {
            SettlementUnit::Translation => "m",
            SettlementUnit::Rotation => "rad",
        }
    }
    /// The unit `s` is shown in: "cm" or "mrad".
    pub fn shown(self) -> &'static str {
        match self {
            SettlementUnit::Translation => "cm",
            SettlementUnit::Rotation => "mrad",
        }
    }
    /// Factor from the SI unit to the shown one (100 or 1000).
    pub fn factor(self) -> f64 {
        match self {
            SettlementUnit::Translation => 100.0,
            SettlementUnit::Rotation => 1000.0,
        }
    }
    /// What `s` is called: "settlement" or "support rotation".
    pub fn noun(self) -> &'static str {
        match self {
            SettlementUnit::Translation => "settlement",
            SettlementUnit::Rotation => "support rotation",
        }
    }
    /// `s` written in the shown unit with `decimals` decimals: "1.4142 cm", "8.7266 mrad"; a
    /// settlement too small for them in significant digits, as every length
    /// ([`crate::lengths`]: the arch at micrometre size printed "0.0000 cm", session 25).
    pub fn show(self, s: f64, decimals: usize) -> String {
        match self {
            SettlementUnit::Translation => format!(
                "{} {}",
                crate::lengths::Length::Motion.number_to(s, decimals),
                self.shown()
            ),
            SettlementUnit::Rotation => {
                format!("{:.*} {}", decimals, s * self.factor(), self.shown())
            }
        }
    }
}

/// Overall outcome.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CapacityStatus {
    /// The curve was computed.
    Curve,
    /// The settlement analysis found no mechanism (see the message): no curve.
    NoSettlementMechanism,
}

/// Result of a capacity analysis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct CapacityResult<D: Spatial = Two> {
    pub status: CapacityStatus,
    pub message: String,
    /// The solver and method that produced the result.
    pub solver: SolverInfo,
    /// Largest settlement (m, or rad for pure rotations: [`CapacityResult::unit`]).
    pub max_settlement: f64,
    /// Motion of each moving support per unit settlement.
    pub direction: Vec<SupportDirection>,
    /// `{settlement, load_multiplier, valid, …}` for s = 0 … max.
    pub curve: Vec<CapacityPoint<D>>,
    /// The certificates of the curve's steps, summed up (absent when there is no curve).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub certificate: Option<CapacityCertificate>,
    /// Which method answered each kind of program, as `safety` reports it (the request layer
    /// gathers it; empty, and not written, where it was not gathered).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub answered: Vec<crate::lp::ProgramAnswers>,
    /// The settlement at which λ reaches 0 (`null` if λ does not change sign in the range).
    pub zero_capacity_settlement: Option<f64>,
    /// Where the zero is known only to a bracket wider than a tenth of it (every settlement
    /// tried next to 0 without equilibrium, to the root tolerance): that bracket `[from, to]`
    /// (m), the answer; `zero_capacity_settlement` is then a point of it. Not written otherwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zero_capacity_bracket: Option<[f64; 2]>,
    /// The settlement at which the last point of the model's existing cracks closes (to the
    /// root tolerance), when it happens within the range.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub existing_cracks_closed_at: Option<f64>,
    /// Least-squares line `λ ≈ intercept + slope·s` through the valid points with s > 0, and the
    /// largest deviation from it relative to λ(0) (a measure of linearity).
    pub linear_fit: Option<LinearFit>,
    /// Settlement mechanism per unit settlement and its hinges.
    pub settlement_mechanism: Vec<BlockMotion<D>>,
    pub settlement_hinges: Vec<Hinge<D>>,
    /// The cracks the settlement opens at its largest value `max_settlement` (the settlement
    /// mechanism per unit settlement times `max_settlement`; m): [`super::cracks`].
    #[serde(default)]
    pub cracks: Vec<D::Crack>,
    /// Collapse mechanism per step (empty unless requested).
    pub mechanisms: Vec<CapacityMechanism<D>>,
    /// LP solves and simplex iterations spent (curve and root finding).
    pub solves: usize,
    pub iterations: i64,
    /// The undeformed geometry.
    pub geometry: D::Shapes,
    /// The canonical selection (docs/canonical.md): how the settlement mechanism and the
    /// steps' collapse mechanisms were selected; absent without it (`raw`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub canonical: Option<CapacityCanonical>,
    /// The settlement cannot stand (`no_settlement_mechanism` with `cannot_stand`): the
    /// certificate that the dead loads have no equilibrium ([`super::NoEquilibriumCertificate`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub no_equilibrium: Option<super::NoEquilibriumCertificate>,
}

/// The canonical selection of a capacity curve: the settlement mechanism that deforms the
/// structure (its hinges and cracks, the deformed geometry) is the canonical one, so that it
/// does not depend on the LP method; with `canonical_steps`, each step's collapse mechanism
/// (hinges, closing joints, drawn mechanism) too. λ is the solver's (the selection only picks
/// among the optimal mechanisms).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CapacityCanonical {
    /// How the settlement mechanism was selected (`null`: not reached, the solver's stands).
    pub settlement: Option<super::canonical::CanonicalMechanism>,
    /// The steps' collapse mechanisms (where the selection was not reached, the solver's
    /// mechanism is reported); `solves` includes the settlement's.
    #[serde(flatten)]
    pub selection: super::canonical::StepSelection,
}

impl<D: Spatial> CapacityResult<D> {
    /// What `s` measures (a translation in m or a rotation in rad) and how it is shown.
    pub fn unit(&self) -> SettlementUnit {
        SettlementUnit::of(&self.direction)
    }

    /// Whether λ reaches zero at the onset of settlement: positive at no settlement and zero at
    /// once (`zero_capacity_settlement` 0; docs/capacity.md, "A zero at the onset of
    /// settlement"). The summaries and the figure say so instead of "at 0 cm".
    pub fn zero_at_onset(&self) -> bool {
        self.zero_capacity_settlement == Some(0.0)
            && self
                .curve
                .first()
                .and_then(|p| p.load_multiplier)
                .is_some_and(|l| l > 0.0)
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LinearFit {
    pub intercept: f64,
    pub slope: f64,
    pub max_relative_deviation: f64,
}
