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

pub use super::laws::kinematic_violation;
use super::laws::{check_facets, Crushing};
use crate::discretize::KinematicMap;
use crate::error::Result;
use crate::lp::{self, LpStatus, SolverOptions};
use crate::programs::{self, ForceProgram};
use crate::reporting::report;
pub use crate::result::settlement::*;
use crate::structure::Assembly;
use serde::{Deserialize, Serialize};

/// Raw vectors of a settlement analysis.
#[derive(Clone, Debug)]
pub struct SettlementSolution {
    pub status: SettlementStatus,
    pub mechanism: Vec<f64>,
    pub pn: Vec<f64>,
    pub pt: Vec<f64>,
    pub primal: f64,
    pub dual: f64,
    /// The solver and method that produced it.
    pub solver: lp::SolverInfo,
}

impl SettlementSolution {
    /// A solution whose status is not a mechanism: no motion, no forces.
    fn without_mechanism(
        status: SettlementStatus,
        map: &KinematicMap,
        solver: lp::SolverInfo,
    ) -> SettlementSolution {
        SettlementSolution {
            status,
            mechanism: vec![],
            pn: vec![0.0; map.num_points()],
            pt: vec![0.0; map.num_tangent_rows()],
            primal: f64::NAN,
            dual: f64::NAN,
            solver,
        }
    }
}

/// Solve both LPs.
pub fn solve_settlement<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<SettlementSolution> {
    let dead = st.load_vector(false);
    let mp = programs::settlement_motion_program(map, &dead)?;
    let primal = lp::solve(&mp.lp, opts)?;
    let status = match primal.status {
        LpStatus::Optimal => SettlementStatus::Mechanism,
        LpStatus::Unbounded => SettlementStatus::CannotStand,
        LpStatus::Infeasible => SettlementStatus::Incompatible,
    };
    let n = map.num_points();
    if status != SettlementStatus::Mechanism {
        return Ok(SettlementSolution::without_mechanism(
            status,
            map,
            primal.solver_info(),
        ));
    }
    let fp = programs::settlement_force_program(map, &dead);
    let dual = fp.solve(opts)?;
    let solver = primal.solver_info().merged(&dual.solver_info());
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
        solver,
    })
}

/// The settlement analysis with the exact crushing domain (second-order cones; Clarabel)
/// instead of its inscribed polygon ([`programs::settlement_force_program_conic`]). The forces
/// come from the program's primal, the mechanism from its equilibrium duals; the value on the
/// mechanism's side is the solver's dual objective, which includes the crushing dissipation
/// (as the motion LP's optimum does with the polygon), so the duality gap still certifies the
/// pair. Without finite strength it is the settlement LP solved by an interior point.
pub fn solve_settlement_conic<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<SettlementSolution> {
    let fp = programs::settlement_force_program_conic(map, &st.load_vector(false));
    let o = SolverOptions {
        feasibility_tolerance: opts.feasibility_tolerance.min(1e-10),
        ..*opts
    };
    let sol = fp.solve(&o)?;
    let solver = lp::SolverInfo {
        solver: lp::cone_backend(&o).name().to_string(),
        method: lp::Method::Clarabel,
        tried: Vec::new(),
    };
    let mut s = settlement_from_force_solution(st, map, &fp, &sol, solver);
    if s.status == SettlementStatus::Mechanism && sol.dual_objective.is_finite() {
        s.primal = sol.dual_objective;
    }
    Ok(s)
}

/// The settlement solution under a choice of crushing model: the inscribed polygon of
/// `facets` chords (the LP pair) or the exact cone.
pub fn solve_settlement_crushing<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
    crushing: Crushing,
) -> Result<SettlementSolution> {
    match crushing {
        Crushing::Linear => solve_settlement(st, map, opts),
        Crushing::Conic => solve_settlement_conic(st, map, opts),
    }
}

/// [`settle`] with a choice of crushing model and facet count (as [`crate::analysis::limit::limit_with`]).
pub fn settle_crushing<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    crushing: Crushing,
    facets: usize,
) -> Result<SettlementResult<S::D>> {
    check_facets(facets)?;
    let mut map = KinematicMap::new(st);
    map.facets = facets;
    let s = solve_settlement_crushing(st, &map, opts, crushing)?;
    let r = settlement_result(st, &map, &s);
    if crushing == Crushing::Conic {
        // Only Clarabel takes the cone: no other method to ask.
        return Ok(r);
    }
    recertify(
        opts,
        &s,
        r,
        |o| solve_settlement(st, &map, o),
        |s| settlement_result(st, &map, s),
    )
}

/// Settlement analysis of a structure whose supports carry their prescribed motions.
pub fn settle<S: Assembly>(st: &S, opts: &SolverOptions) -> Result<SettlementResult<S::D>> {
    let map = KinematicMap::new(st);
    let s = solve_settlement(st, &map, opts)?;
    let r = settlement_result(st, &map, &s);
    recertify(
        opts,
        &s,
        r,
        |o| solve_settlement(st, &map, o),
        |s| settlement_result(st, &map, s),
    )
}

/// A "cannot stand" settlement result given its certificate: the dead loads' equilibrium on
/// the supports (the settlement's force program, whose infeasibility is the motion program's
/// unboundedness) decided infeasible by its elastic program
/// ([`crate::analysis::limit::dead_loads_certificate`]); the message says whether it holds.
/// Other results unchanged.
pub fn certify_cannot_stand<S: Assembly>(
    st: &S,
    r: &mut SettlementResult<S::D>,
    solver: &SolverOptions,
    facets: usize,
) -> Result<()> {
    if r.status != SettlementStatus::CannotStand || r.no_equilibrium.is_some() {
        return Ok(());
    }
    r.no_equilibrium =
        crate::analysis::limit::dead_loads_certificate(st, solver, Some(facets), &mut r.message)?;
    Ok(())
}

pub fn settlement_result<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    s: &SettlementSolution,
) -> SettlementResult<S::D> {
    if s.status != SettlementStatus::Mechanism {
        return SettlementResult {
            status: s.status,
            message: s.status.sentence().to_string(),
            solver: s.solver.clone(),
            work_dead_loads: None,
            work_reactions: None,
            duality_gap: None,
            certificate: None,
            blocks: vec![],
            joints: vec![],
            hinges: vec![],
            cracks: vec![],
            thrust_line: vec![],
            reactions: vec![],
            friction_iteration: None,
            geometry: st.shapes(),
            canonical: None,
            no_equilibrium: None,
        };
    }
    let rep = report(st, map, &s.mechanism, 1.0, &s.pn, &s.pt);
    let cracks = rep.cracks(st);
    // The gap on the problem's own work scale (crate::scale): the total dead load times the
    // largest displacement the support motions give a contact point.
    let wscale = crate::scale::settlement_work_scale(map, &st.load_vector(false));
    let gap = crate::scale::relative_gap(s.primal, s.dual, wscale);
    // Works of round-off size on that scale (a rigid settlement's) are reported as zero.
    let (primal, dual) = (
        crate::result::clean(s.primal, wscale),
        crate::result::clean(s.dual, wscale),
    );
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
    if let Some(n) = s.solver.fallback_note() {
        message = format!("{message} ({n})");
    }
    if !ok {
        message = format!(
            "WARNING: the duality gap {gap:.3e} exceeds {GAP_TOLERANCE:.0e}: the result is not certified; {message}"
        );
    }
    SettlementResult {
        status: s.status,
        message,
        solver: s.solver.clone(),
        work_dead_loads: Some(primal),
        work_reactions: Some(dual),
        duality_gap: Some(gap),
        certificate: Some(Certificate {
            primal,
            dual,
            relative_gap: gap,
            complementarity,
            equilibrium_residual,
            ok,
        }),
        blocks: rep.blocks,
        joints: rep.joints,
        hinges: rep.hinges,
        cracks,
        thrust_line: rep.thrust_line,
        reactions: rep.reactions,
        friction_iteration: None,
        geometry: st.shapes(),
        canonical: None,
        no_equilibrium: None,
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

/// Turn a solved settlement force LP into a settlement solution: forces from its primal, the
/// mechanism from its row duals (`d = −y`: HiGHS's duals of `min cᵀx, A x = b` satisfy
/// `c − Aᵀy ≥ 0`, which for `d = −y` reads `N d + g_n ≥ 0`, `T d + g_t = 0`). The primal value is
/// recomputed as the dead loads' work on that mechanism, not copied from the solver.
pub fn settlement_from_force_solution<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    fp: &ForceProgram,
    sol: &lp::LpSolution,
    solver: lp::SolverInfo,
) -> SettlementSolution {
    // The method that answered, where the requested one failed (lp::fallback_chain).
    let solver = if sol.tried.is_empty() {
        solver
    } else {
        sol.solver_info()
    };
    let status = match sol.status {
        LpStatus::Optimal => SettlementStatus::Mechanism,
        // No equilibrium under the dead loads: the primal is unbounded.
        LpStatus::Infeasible => SettlementStatus::CannotStand,
        // The work on the supports can be made arbitrarily negative: the primal is infeasible.
        LpStatus::Unbounded => SettlementStatus::Incompatible,
    };
    if status != SettlementStatus::Mechanism {
        return SettlementSolution::without_mechanism(status, map, solver);
    }
    let dead = st.load_vector(false);
    let d: Vec<f64> = sol.row_dual[..map.num_dofs].iter().map(|y| -y).collect();
    let primal: f64 = dead.iter().zip(&d).map(|(f, x)| f * x).sum();
    let (pn, pt) = fp.forces(&sol.x);
    let dual: f64 = dot(&map.support_normal, &pn) + dot(&map.support_tangent, &pt);
    SettlementSolution {
        status,
        mechanism: d,
        pn,
        pt,
        primal,
        dual,
        solver,
    }
}

/// Settlement analysis in the chosen form.
pub fn solve_settlement_with<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
    form: SettlementForm,
) -> Result<SettlementSolution> {
    if form == SettlementForm::Both || map.has_joint_laws() {
        return solve_settlement(st, map, opts);
    }
    let fp = programs::settlement_force_program(map, &st.load_vector(false));
    let sol = fp.solve(opts)?;
    Ok(settlement_from_force_solution(
        st,
        map,
        &fp,
        &sol,
        opts.info(),
    ))
}

/// The reported result of a solution, with the mechanism's admissibility checked: a mechanism
/// read from duals that violates the joint constraints by more than 1e-6 of the largest
/// prescribed motion fails the certificate.
pub fn settlement_result_checked<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    s: &SettlementSolution,
) -> SettlementResult<S::D> {
    let mut r = settlement_result(st, map, s);
    if s.status == SettlementStatus::Mechanism {
        let umax = crate::scale::motion_scale(map, &s.mechanism, 1.0);
        let v = kinematic_violation(map, &s.mechanism, 1.0);
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
pub fn settle_with<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    form: SettlementForm,
) -> Result<SettlementResult<S::D>> {
    let map = KinematicMap::new(st);
    let s = solve_settlement_with(st, &map, opts, form)?;
    let r = settlement_result_checked(st, &map, &s);
    recertify(
        opts,
        &s,
        r,
        |o| solve_settlement_with(st, &map, o, form),
        |s| settlement_result_checked(st, &map, s),
    )
}

/// A settlement whose certificate fails (duality gap above [`GAP_TOLERANCE`], or a mechanism
/// that violates the joints) is solved again: first by the method that answered at the
/// feasibility tolerance [`lp::policy::RETRY_FEASIBILITY_TOLERANCE`] (where the one asked was
/// looser), then by the methods after it along [`lp::fallback_chain`], and the first certified
/// answer is reported, its `tried` naming the uncertified one. The solver layer's own check
/// ([`lp::policy::check`], each LP alone to 1e-6) can accept both LPs of an interior point and
/// still leave their two works 1e-6 apart: the 610-block wall with μ = 0.6 under `--method
/// clarabel` ended at a gap of 2.2e-6 where HiGHS's interior point with crossover certifies it
/// (docs/tolerances.md). Where no later method certifies, the first answer stands with its
/// warning.
fn recertify<D: crate::result::Spatial>(
    opts: &SolverOptions,
    s: &SettlementSolution,
    r: SettlementResult<D>,
    solve: impl Fn(&SolverOptions) -> Result<SettlementSolution>,
    result: impl Fn(&SettlementSolution) -> SettlementResult<D>,
) -> Result<SettlementResult<D>> {
    let certified = r.certificate.as_ref().is_none_or(|c| c.ok);
    if certified || s.status != SettlementStatus::Mechanism {
        return Ok(r);
    }
    let chain = lp::fallback_chain(opts.method);
    let from = chain
        .iter()
        .position(|&m| m == s.solver.method)
        .unwrap_or(0);
    let why = match &r.certificate {
        Some(c) if c.relative_gap > GAP_TOLERANCE => format!(
            "{} at feasibility tolerance {:.0e}: the settlement's duality gap {:.1e} exceeds {GAP_TOLERANCE:.0e}",
            s.solver.method.name(),
            opts.feasibility_tolerance,
            c.relative_gap
        ),
        _ => format!(
            "{}: the mechanism violates the joint constraints",
            s.solver.method.name()
        ),
    };
    // First the same method at a tighter feasibility tolerance (the works of two LPs each
    // optimal to 1e-9 can differ by more than 1e-7 of a small work), then the methods after it.
    let tight = lp::policy::RETRY_FEASIBILITY_TOLERANCE;
    let attempts = (opts.feasibility_tolerance > tight)
        .then_some(SolverOptions {
            method: s.solver.method,
            feasibility_tolerance: tight,
            ..*opts
        })
        .into_iter()
        .chain(
            chain[from + 1..]
                .iter()
                .map(|&method| SolverOptions { method, ..*opts }),
        );
    for o in attempts {
        let Ok(mut s2) = solve(&o) else {
            continue;
        };
        if s2.status != SettlementStatus::Mechanism {
            continue;
        }
        let mut tried = s.solver.tried.clone();
        tried.push(why.clone());
        tried.append(&mut s2.solver.tried);
        s2.solver.tried = tried;
        let r2 = result(&s2);
        if r2.certificate.as_ref().is_some_and(|c| c.ok) {
            return Ok(r2);
        }
    }
    Ok(r)
}

use crate::vector::dot_n as dot;
