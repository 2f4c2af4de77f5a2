//! Settlement analysis: the paper's two dual LPs (Section 5).
//!
//! Primal (62)–(66), the mechanism:
//! ```text
//!   max F_Dᵀ d   s.t.  N d + g_n ≥ 0 (contact),  N d + g_n = 0 (fixed supports),  T d + g_t = 0
//! ```
//! Dual (69)–(71), the contact forces and reactions:
//! ```text
//!   min g_nᵀ p_n + g_tᵀ p_t   s.t.  F_D + Nᵀ p_n + Tᵀ p_t = 0,  p_n ≥ 0 (free on fixed supports)
//! ```
//! `g` is the opening/sliding that the prescribed support motions cause at each point, so the
//! dual objective is the work of the forces the structure exerts on its supports along their
//! prescribed motions (the paper's `û0ᵀ r`, with `r` the forces on the supports). Both LPs are
//! solved on their own; at the optimum their values are equal (strong duality) and every
//! point satisfies `opening × compression = 0` (complementarity): both are reported.
//!
//! Both LPs are homogeneous of degree one in the prescribed motions, so every displacement of
//! the result is proportional to the settlement magnitude and the forces do not depend on it.

use crate::discretize::KinematicMap;
use crate::error::Result;
use crate::lp::{self, Direction, LpStatus, SolverOptions};
use crate::programs::{ForceProgram, MotionProgram};
use crate::result::{report, BlockMotion, Geometry, Hinge, JointResult, Reaction, ThrustPoint};
use crate::structure::Structure;
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
pub struct SettlementResult {
    pub status: SettlementStatus,
    pub message: String,
    /// Work of the dead loads on the mechanism (primal optimum), kN·m.
    pub work_dead_loads: Option<f64>,
    /// Work of the structure's forces on the moving supports (dual optimum), kN·m.
    pub work_reactions: Option<f64>,
    /// Relative duality gap.
    pub duality_gap: Option<f64>,
    pub certificate: Option<Certificate>,
    /// Block motions (m, rad) for the prescribed settlement.
    pub blocks: Vec<BlockMotion>,
    pub joints: Vec<JointResult>,
    pub hinges: Vec<Hinge>,
    pub thrust_line: Vec<ThrustPoint>,
    pub reactions: Vec<Reaction>,
    /// The geometry analysed (for drawing a saved result).
    pub geometry: Geometry,
}

/// Raw vectors of a settlement analysis.
#[derive(Clone, Debug)]
pub struct SettlementSolution {
    pub status: SettlementStatus,
    pub mechanism: Vec<f64>,
    pub pn: Vec<f64>,
    pub pt: Vec<f64>,
    pub primal: f64,
    pub dual: f64,
}

/// Tolerance on the relative duality gap.
pub const GAP_TOLERANCE: f64 = 1e-7;

/// Solve both LPs.
pub fn solve_settlement(
    st: &Structure,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<SettlementSolution> {
    let dead = st.load_vector(false);
    let mp = MotionProgram::new(map, &dead)?;
    let primal = lp::solve(&mp.lp, opts)?;
    let status = match primal.status {
        LpStatus::Optimal => SettlementStatus::Mechanism,
        LpStatus::Unbounded => SettlementStatus::CannotStand,
        LpStatus::Infeasible => SettlementStatus::Incompatible,
    };
    let n = map.num_points();
    if status != SettlementStatus::Mechanism {
        return Ok(SettlementSolution {
            status,
            mechanism: vec![],
            pn: vec![0.0; n],
            pt: vec![0.0; n],
            primal: f64::NAN,
            dual: f64::NAN,
        });
    }
    let fp = ForceProgram::new(map, &dead, None, Direction::Minimise, |k| {
        (map.support_normal[k], map.support_tangent[k])
    });
    let dual = lp::solve(&fp.lp, opts)?;
    let (pn, pt, dval) = if dual.status == LpStatus::Optimal {
        let (pn, pt) = fp.forces(&dual.x);
        (pn, pt, dual.objective)
    } else {
        (vec![0.0; n], vec![0.0; n], f64::NAN)
    };
    Ok(SettlementSolution {
        status,
        mechanism: mp.motion(&primal.x),
        pn,
        pt,
        primal: mp.objective_sign * primal.objective,
        dual: dval,
    })
}

/// Settlement analysis of a structure whose supports carry their prescribed motions.
pub fn settle(st: &Structure, opts: &SolverOptions) -> Result<SettlementResult> {
    let map = KinematicMap::new(st);
    let s = solve_settlement(st, &map, opts)?;
    Ok(settlement_result(st, &map, &s))
}

pub fn settlement_result(
    st: &Structure,
    map: &KinematicMap,
    s: &SettlementSolution,
) -> SettlementResult {
    if s.status != SettlementStatus::Mechanism {
        return SettlementResult {
            status: s.status,
            message: s.status.sentence().to_string(),
            work_dead_loads: None,
            work_reactions: None,
            duality_gap: None,
            certificate: None,
            blocks: vec![],
            joints: vec![],
            hinges: vec![],
            thrust_line: vec![],
            reactions: vec![],
            geometry: Geometry::of(st),
        };
    }
    let rep = report(st, map, &s.mechanism, 1.0, &s.pn, &s.pt);
    // Scale for the gap: total dead load times the largest prescribed motion.
    let wtot: f64 = st.load_vector(false).iter().map(|f| f.abs()).sum();
    let umax = st
        .supports
        .iter()
        .flat_map(|sp| sp.motion.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let floor = (1e-9 * wtot * umax).max(1e-300);
    let gap = (s.primal - s.dual).abs() / s.primal.abs().max(s.dual.abs()).max(floor);
    let gap = if gap.is_nan() { f64::INFINITY } else { gap };
    let complementarity = rep
        .openings
        .iter()
        .zip(&s.pn)
        .fold(0.0f64, |m, (o, p)| m.max((o * p).abs()));
    let dead = st.load_vector(false);
    let res = map.resultants(&s.pn, &s.pt);
    let equilibrium_residual = dead
        .iter()
        .zip(&res)
        .fold(0.0f64, |m, (a, b)| m.max((a + b).abs()));
    let ok = gap <= GAP_TOLERANCE;
    let mut message = s.status.sentence().to_string();
    if !ok {
        message = format!(
            "WARNING: the duality gap {gap:.3e} exceeds {GAP_TOLERANCE:.0e}: the result is not certified; {message}"
        );
    }
    SettlementResult {
        status: s.status,
        message,
        work_dead_loads: Some(s.primal),
        work_reactions: Some(s.dual),
        duality_gap: Some(gap),
        certificate: Some(Certificate {
            primal: s.primal,
            dual: s.dual,
            relative_gap: gap,
            complementarity,
            equilibrium_residual,
            ok,
        }),
        blocks: rep.blocks,
        joints: rep.joints,
        hinges: rep.hinges,
        thrust_line: rep.thrust_line,
        reactions: rep.reactions,
        geometry: Geometry::of(st),
    }
}

// --- Solving one LP only (large models) ----------------------------------------------------

/// Which of the two LPs a settlement analysis hands to the solver.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SettlementForm {
    /// Solve the motion LP and the force LP separately (the default; small models).
    #[default]
    Both,
    /// Solve only the force LP (3 rows per block instead of 2 per collocation point) and read
    /// the mechanism from its equilibrium duals. The certificate is still computed from both
    /// sides: the work of the dead loads on that mechanism, the work of the forces on the
    /// supports, the mechanism's admissibility and the forces' equilibrium. Falls back to
    /// [`SettlementForm::Both`] when joint laws (friction, finite strength) are present.
    ForceOnly,
}

/// The force LP of a settlement analysis: `min g·p` over forces in equilibrium with the dead
/// loads (the paper's (69)–(71)).
pub fn settlement_force_program(st: &Structure, map: &KinematicMap) -> ForceProgram {
    let dead = st.load_vector(false);
    ForceProgram::new(map, &dead, None, Direction::Minimise, |k| {
        (map.support_normal[k], map.support_tangent[k])
    })
}

/// Largest violation of kinematic admissibility of block motions `d` (with the prescribed
/// support motions): interpenetration `max(0, −(N d + g_n))` at contact points, `|N d + g_n|`
/// at bilateral points, and sliding `|T d + g_t|`, over points that carry force.
pub fn kinematic_violation(map: &KinematicMap, d: &[f64]) -> f64 {
    let (open, slide) = map.jumps(d, 1.0);
    let mut v = 0.0f64;
    for k in 0..map.num_points() {
        if map.gap[k] > 0.0 {
            continue;
        }
        let o = if map.bilateral[k] {
            open[k].abs()
        } else {
            (-open[k]).max(0.0)
        };
        v = v.max(o).max(slide[k].abs());
    }
    v
}

/// Turn a solved settlement force LP into a settlement solution: forces from its primal, the
/// mechanism from its row duals (`d = −y`: HiGHS's duals of `min cᵀx, A x = b` satisfy
/// `c − Aᵀy ≥ 0`, which for `d = −y` reads `N d + g_n ≥ 0`, `T d + g_t = 0`). The primal value is
/// recomputed as the dead loads' work on that mechanism, not copied from the solver.
pub fn settlement_from_force_solution(
    st: &Structure,
    map: &KinematicMap,
    fp: &ForceProgram,
    sol: &lp::LpSolution,
) -> SettlementSolution {
    let n = map.num_points();
    let status = match sol.status {
        LpStatus::Optimal => SettlementStatus::Mechanism,
        // No equilibrium under the dead loads: the primal is unbounded.
        LpStatus::Infeasible => SettlementStatus::CannotStand,
        // The work on the supports can be made arbitrarily negative: the primal is infeasible.
        LpStatus::Unbounded => SettlementStatus::Incompatible,
    };
    if status != SettlementStatus::Mechanism {
        return SettlementSolution {
            status,
            mechanism: vec![],
            pn: vec![0.0; n],
            pt: vec![0.0; n],
            primal: f64::NAN,
            dual: f64::NAN,
        };
    }
    let dead = st.load_vector(false);
    let d: Vec<f64> = sol.row_dual[..map.num_dofs].iter().map(|y| -y).collect();
    let primal: f64 = dead.iter().zip(&d).map(|(f, x)| f * x).sum();
    let (pn, pt) = fp.forces(&sol.x);
    let dual: f64 = (0..n)
        .map(|k| map.support_normal[k] * pn[k] + map.support_tangent[k] * pt[k])
        .sum();
    SettlementSolution {
        status,
        mechanism: d,
        pn,
        pt,
        primal,
        dual,
    }
}

/// Whether the map has joint laws (friction, finite strength) that the force-only form does not
/// handle.
fn has_joint_laws(map: &KinematicMap) -> bool {
    map.laws
        .iter()
        .any(|l| l.friction.is_some() || l.strength.is_some())
        || map.shear_limits.is_some()
}

/// Settlement analysis in the chosen form.
pub fn solve_settlement_with(
    st: &Structure,
    map: &KinematicMap,
    opts: &SolverOptions,
    form: SettlementForm,
) -> Result<SettlementSolution> {
    if form == SettlementForm::Both || has_joint_laws(map) {
        return solve_settlement(st, map, opts);
    }
    let fp = settlement_force_program(st, map);
    let sol = lp::solve(&fp.lp, opts)?;
    Ok(settlement_from_force_solution(st, map, &fp, &sol))
}

/// The reported result of a solution, with the mechanism's admissibility checked: a mechanism
/// read from duals that violates the joint constraints by more than 1e-6 of the largest
/// prescribed motion fails the certificate.
pub fn settlement_result_checked(
    st: &Structure,
    map: &KinematicMap,
    s: &SettlementSolution,
) -> SettlementResult {
    let mut r = settlement_result(st, map, s);
    if s.status == SettlementStatus::Mechanism {
        let umax = st
            .supports
            .iter()
            .flat_map(|sp| sp.motion.iter())
            .fold(0.0f64, |m, x| m.max(x.abs()));
        let v = kinematic_violation(map, &s.mechanism);
        if v > 1e-6 * umax.max(1e-300) {
            if let Some(c) = r.certificate.as_mut() {
                c.ok = false;
            }
            r.message = format!(
                "WARNING: the mechanism violates the joint constraints by {v:.3e} m: the result is not certified; {}",
                r.message
            );
        }
    }
    r
}

/// [`settle`] in the chosen form.
pub fn settle_with(
    st: &Structure,
    opts: &SolverOptions,
    form: SettlementForm,
) -> Result<SettlementResult> {
    let map = KinematicMap::new(st);
    let s = solve_settlement_with(st, &map, opts, form)?;
    Ok(settlement_result_checked(st, &map, &s))
}
