//! The canonical mechanism of a result with non-associative friction (issue 30, item 4;
//! `docs/canonical.md`, `docs/joint-laws.md`).
//!
//! The non-associative iteration ([`super::nonassociative`]) ends on a linear program: the
//! settlement (or limit) program with the shear capacity of every frictional point fixed at
//! `μ n̄_k + c` from the last normal forces. Its optimal mechanisms — those of greatest work
//! of the dead loads less the sliding dissipation (least λ) — form a face, and the iteration's
//! interior-point solver (Clarabel) returns a point near the centre of that face, which
//! depends on the solver. Here, with those
//! capacities held, the optimal face is solved again by the simplex and, as for Heyman's rules
//! ([`super::canonical::canonical_mechanism`]), the mechanism of least crack area on it is
//! reported (then, if that is not unique, the vertex of least value of a fixed generic linear
//! functional). The crack area counts what a crack is with friction — the relative motion of
//! its two faces: `Σ w_k (o_k + |s_k|)`, openings and slips weighted by their tributary joint
//! size. (Openings alone would leave sliding free: a point whose capacity the last iterate set
//! to zero slides at no cost, and among the optimal mechanisms the one that opens least is then
//! one that slides wherever it can.) `|s_k|` is the sum of the two sliding variables of the
//! point's friction rows in the kinematic program, which equals it at any point the selection
//! picks.
//!
//! On the 20 × 10 running-bond wall of docs/joint-laws.md the selection leaves the crack area
//! as it was: the optimal mechanism of the last program is itself a band 2–3 units wide of
//! blocks that rotate and slide beside the stepped crack, not one crack line
//! (docs/cracks.md, "Bond with friction").
//!
//! The forces are the iteration's last ones (they fix the capacities): an optimal force field
//! of the same program, hence complementary to every optimal mechanism (the certificate
//! compares the two values as usual). The canonical force field of associative results
//! (`canonical.forces`) is not computed.

use super::canonical::{tributary_weights, CanonicalOptions};
use super::laws::check_facets;
use super::limit::{self, LimitResult, LimitStatus};
use super::nonassociative::{
    solve_limit_nonassociative, solve_settlement_nonassociative, NonAssociativeOptions,
};
use super::settlement::{
    settlement_result, settlement_result_checked, SettlementResult, SettlementSolution,
    SettlementStatus,
};
use super::Crushing;
use crate::discretize::KinematicMap;
use crate::error::Result;
use crate::lp::{self, Basis, BasisStatus, LinearProgram, LpStatus, Method, SolverOptions};
use crate::programs::{self, ForceProgram};
use crate::result::canonical::{Canonical, CanonicalMechanism, Selection};
use crate::result::FrictionIteration;
use crate::structure::Assembly;

/// The options of the selection's stages: a simplex (the selection is a vertex; after an
/// interior point the dual simplex), at a tight feasibility tolerance.
fn vertex_options(opts: &SolverOptions) -> SolverOptions {
    SolverOptions {
        method: if opts.method.is_simplex() {
            opts.method
        } else {
            Method::DualSimplex
        },
        feasibility_tolerance: opts.feasibility_tolerance.min(1e-9),
        ..*opts
    }
}

use super::canonical::{generic_functional, max_abs};

/// The crack area with slips, `Σ w_k (o_k + |s_k|)` over points without a gap that are not
/// bilateral, of mechanism `d` (support motions scaled by `support_scale`); round-off (below
/// the opening tolerance of the size of its terms) is zero.
pub fn crack_area_with_slips(
    map: &KinematicMap,
    d: &[f64],
    support_scale: f64,
    weights: &[f64],
) -> f64 {
    let (open, slide) = map.jumps(d, support_scale);
    let nt = map.tangents_per_point;
    let mut a = 0.0;
    let mut size = 0.0;
    for k in 0..map.num_points() {
        if map.gap[k] > 0.0 || map.bilateral[k] {
            continue;
        }
        let s: f64 = (0..nt)
            .map(|m| slide[k * nt + m].powi(2))
            .sum::<f64>()
            .sqrt();
        a += weights[k] * (open[k] + s);
        size += weights[k] * (open[k].abs() + s);
    }
    if a.abs() <= crate::scale::OPEN_TOLERANCE * size {
        0.0
    } else {
        a
    }
}

/// Runs the selection's programs from a warm basis, counting solves.
struct Stages {
    opts: SolverOptions,
    solves: usize,
}

impl Stages {
    fn solve(&mut self, lp: &LinearProgram, basis: &mut Option<Basis>) -> Result<lp::LpSolution> {
        self.solves += 1;
        if let Some(b) = basis.as_mut() {
            while b.rows.len() < lp.num_rows() {
                b.rows.push(BasisStatus::Basic);
            }
        }
        let keep = basis.clone();
        let s = lp::solve_warm(lp, &self.opts, basis)?;
        if basis.is_none() {
            *basis = keep;
        }
        Ok(s)
    }
}

/// The canonical mechanism among the optima of the kinematic program `klp` (the LP dual of the
/// force program `fp` of `map`; a maximisation whose first `map.num_dofs` columns are
/// `y = −d`), solved as `first` (with its basis `start`); `raw` is that solution's mechanism.
/// Openings are `N d + support_scale·g_n`. Returns the mechanism and how it was selected, or
/// None when a stage does not solve.
#[allow(clippy::too_many_arguments, clippy::needless_range_loop)]
fn select(
    map: &KinematicMap,
    fp: &ForceProgram,
    klp: &LinearProgram,
    first: &lp::LpSolution,
    raw: &[f64],
    start: Option<Basis>,
    support_scale: f64,
    weights: &[f64],
    opts: &SolverOptions,
    copts: &CanonicalOptions,
) -> Result<Option<(Vec<f64>, CanonicalMechanism)>> {
    let nd = map.num_dofs;
    let mut st = Stages {
        opts: *opts,
        solves: 0,
    };
    let face1 = programs::optimal_face_exact(
        klp,
        first.objective,
        copts.tolerance,
        &first.row_dual,
        &first.col_dual,
        copts.dual_threshold,
    );
    // The crack area: openings (on y) and the sliding variables of the friction rows (the
    // kinematic program's columns of the force program's rows, in order; each ≤ 0 and
    // `s_k = y₊ − y₋`, so `−y₊ − y₋ ≥ |s_k|`).
    let (mut cost, constant) = programs::crack_area_cost(map, weights, klp.num_cols());
    let equilibrium = nd;
    for k in 0..map.num_points() {
        if map.gap[k] > 0.0 || map.bilateral[k] {
            continue;
        }
        let nt = map.tangents_per_point;
        for ct in fp.pt[k * nt..(k + 1) * nt].iter().flatten() {
            for (i, _) in fp.lp.column(*ct) {
                if i >= equilibrium && fp.lp.row_lower[i] == f64::NEG_INFINITY {
                    cost[i] -= weights[k];
                }
            }
        }
    }
    let solver_area = crack_area_with_slips(map, raw, support_scale, weights);
    let mut stage2 = face1.clone();
    stage2.cost = cost.clone();
    let mut basis = start;
    let s2 = st.solve(&stage2, &mut basis)?;
    if s2.status != LpStatus::Optimal {
        return Ok(None);
    }
    let d2: Vec<f64> = s2.x[..nd].iter().map(|v| -v).collect();
    let area2 = s2.objective + constant;
    let scale = max_abs(raw)
        .max(max_abs(&d2))
        .max(support_scale * max_abs(&map.support_normal))
        .max(support_scale * max_abs(&map.support_tangent))
        .max(1e-300);
    let ptol = copts.point_tolerance * scale;
    let changed2 = raw.iter().zip(&d2).any(|(a, b)| (a - b).abs() > ptol);
    let entries: Vec<(usize, f64)> = cost
        .iter()
        .copied()
        .enumerate()
        .filter(|&(_, c)| c != 0.0)
        .collect();
    let slack = copts.tolerance * area2.abs().max(1e-9 * scale);
    let face2 = face1.with_row(&entries, f64::NEG_INFINITY, area2 - constant + slack);
    let r = generic_functional(nd);
    let extremes = |st: &mut Stages,
                    face: &LinearProgram,
                    basis: Option<Basis>|
     -> Result<Option<(Vec<f64>, f64)>> {
        let mut lp = face.clone();
        lp.cost.iter_mut().for_each(|c| *c = 0.0);
        lp.cost[..nd].copy_from_slice(&r);
        let mut b = basis;
        let lo = st.solve(&lp, &mut b)?;
        lp.maximise = true;
        let hi = st.solve(&lp, &mut b)?;
        Ok(
            (lo.status == LpStatus::Optimal && hi.status == LpStatus::Optimal).then(|| {
                (
                    lo.x[..nd].iter().map(|v| -v).collect(),
                    hi.objective - lo.objective,
                )
            }),
        )
    };
    let Some((d3, spread2)) = extremes(&mut st, &face2, basis.clone())? else {
        return Ok(None);
    };
    let face2_point = spread2 <= ptol;
    let (d, selected_by) = if face2_point {
        (d2, Selection::LeastCrackArea)
    } else {
        (d3, Selection::GenericVertex)
    };
    let changed = raw.iter().zip(&d).any(|(a, b)| (a - b).abs() > ptol);
    let unique = !changed2
        && face2_point
        && extremes(&mut st, &face1, basis)?.is_some_and(|(_, w)| w <= ptol);
    let selected_by = if unique {
        Selection::Optimum
    } else {
        selected_by
    };
    let d = if changed { d } else { raw.to_vec() };
    let crack_area = crack_area_with_slips(map, &d, support_scale, weights);
    Ok(Some((
        d,
        CanonicalMechanism {
            unique,
            selected_by,
            crack_area_solver: solver_area,
            crack_area,
            changed,
            solves: st.solves,
        },
    )))
}

/// The canonical mechanism of the settlement program on `map` (its shear capacities fixed),
/// with the value of the program: `(mechanism, motion LP optimum, record)`, or None when a
/// stage does not solve. `raw` is the iteration's own mechanism (the record compares with it).
fn select_settlement<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    raw: &[f64],
    opts: &SolverOptions,
    copts: &CanonicalOptions,
) -> Result<Option<(Vec<f64>, f64, CanonicalMechanism)>> {
    let dead = st.load_vector(false);
    let fp = programs::settlement_force_program(map, &dead);
    let kp = crate::duality::dual(&fp.lp)?;
    let o = vertex_options(opts);
    let mut basis = None;
    let first = lp::solve_warm(&kp.lp, &o, &mut basis)?;
    if first.status != LpStatus::Optimal {
        return Ok(None);
    }
    let weights = tributary_weights(st, map);
    let Some((d, mech)) = select(
        map, &fp, &kp.lp, &first, raw, basis, 1.0, &weights, &o, copts,
    )?
    else {
        return Ok(None);
    };
    Ok(Some((d, kp.objective_sign * first.objective, mech)))
}

/// Settlement analysis with non-associative friction and the canonical mechanism of its last
/// program (least crack area; module docs). Falls back to the iteration's own mechanism where
/// the selection does not solve, and with the exact crushing cone (not an LP).
pub fn settle_nonassociative_canonical<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    crushing: Crushing,
    facets: usize,
    o: &NonAssociativeOptions,
    copts: &CanonicalOptions,
) -> Result<SettlementResult<S::D>> {
    check_facets(facets)?;
    let mut map = KinematicMap::new(st);
    map.facets = facets;
    let (associative, it) = solve_settlement_nonassociative(st, &mut map, opts, crushing, o)?;
    let selected = if crushing == Crushing::Linear
        && it.last.status == SettlementStatus::Mechanism
        && map.shear_limits.is_some()
    {
        select_settlement(st, &map, &it.last.mechanism, opts, copts)?
    } else {
        None
    };
    let mut settlement = match selected {
        Some((d, value, mech)) => {
            let s = SettlementSolution {
                status: SettlementStatus::Mechanism,
                mechanism: d,
                pn: it.last.pn.clone(),
                pt: it.last.pt.clone(),
                primal: value,
                dual: it.last.dual,
                solver: it.last.solver.clone(),
            };
            let mut r = settlement_result_checked(st, &map, &s);
            r.canonical = Some(Canonical {
                mechanism: mech,
                forces: None,
            });
            r
        }
        None => settlement_result(st, &map, &it.last),
    };
    FrictionIteration {
        associative,
        history: it.history,
        converged: it.converged,
    }
    .attach(&mut settlement.message, &mut settlement.friction_iteration);
    Ok(settlement)
}

/// Limit analysis with non-associative friction and the canonical collapse mechanism of its
/// last program (least crack area among the mechanisms of least λ with the capacities held).
pub fn limit_nonassociative_canonical<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    o: &NonAssociativeOptions,
    copts: &CanonicalOptions,
) -> Result<LimitResult<S::D>> {
    let mut map = KinematicMap::new(st);
    let (associative, it) = solve_limit_nonassociative(st, &mut map, opts, o)?;
    let mut s = it.last;
    let mut canonical = None;
    if s.status == LimitStatus::Collapse && !s.mechanism.is_empty() && map.shear_limits.is_some() {
        let (dead, live) = (st.load_vector(false), st.load_vector(true));
        let fp = programs::limit_force_program(&map, &dead, &live);
        let kp = programs::kinematic_program(&fp)?;
        let vo = vertex_options(opts);
        let mut basis = None;
        let first = lp::solve_warm(&kp.lp, &vo, &mut basis)?;
        if first.status == LpStatus::Optimal {
            let weights = tributary_weights(st, &map);
            // A limit mechanism's openings are N d: support motions do not enter.
            if let Some((d, mech)) = select(
                &map,
                &fp,
                &kp.lp,
                &first,
                &s.mechanism,
                basis,
                0.0,
                &weights,
                &vo,
                copts,
            )? {
                if mech.changed {
                    s.mechanism = d;
                }
                canonical = Some(Canonical {
                    mechanism: mech,
                    forces: None,
                });
            }
        }
    }
    let mut r = limit::limit_result(st, &map, &s);
    r.canonical = canonical;
    FrictionIteration {
        associative,
        history: it.history,
        converged: it.converged,
    }
    .attach(&mut r.message, &mut r.friction_iteration);
    Ok(r)
}
