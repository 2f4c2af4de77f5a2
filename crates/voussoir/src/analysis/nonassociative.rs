//! Limit, settlement and capacity analyses with non-associative Coulomb friction (sliding
//! without dilatancy).
//!
//! Associative friction (the LP of [`super::limit`]) lets joints dilate as they slide, which
//! overestimates the strength of frictional masonry. Following the idea of Gilbert, Casapulla and
//! Ahmed (2006), the non-associative problem is approached by a sequence of LPs in which the
//! shear capacity of every frictional point is a fixed value `μ n̄_k + c` (a Tresca-like,
//! dilatancy-free law) computed from the normal forces `n̄` of the previous solution:
//!
//! 1. solve the associative problem; `n̄ ← p_n`;
//! 2. solve with capacities `μ n̄_k + c`, giving `λ_i`, `p_n^i`;
//! 3. `n̄ ← (1 − α) n̄ + α p_n^i` (relaxation `α`), repeat until λ and `n̄` settle.
//!
//! At a converged point the forces satisfy equilibrium, no tension, and Coulomb's inequality
//! with the actual normal forces, and the mechanism has no dilatancy: a statically and
//! kinematically consistent non-associative solution. The scheme is a heuristic (the
//! non-associative problem is not convex): the result reports whether it converged, and the
//! multiplier is never above the associative one in our tests.
//!
//! The settlement analysis iterates the same way on its pair of LPs: with the capacities fixed,
//! the motion LP lets a joint slide without opening, against the dissipation
//! `(μ n̄_k + c)·|slip|` of each point, so a frictional wall no longer dilates where its blocks
//! slide. The converged value is the work of the dead loads less that dissipation.

pub use super::laws::NonAssociativeOptions;
use super::limit::{limit_result, solve_limit, LimitResult, LimitSolution, LimitStatus};
use super::settlement::{
    settlement_result, solve_settlement_crushing, SettlementResult, SettlementSolution,
    SettlementStatus,
};
use super::Crushing;
use crate::discretize::KinematicMap;
use crate::error::Result;
use crate::lp::SolverOptions;
pub use crate::result::nonassociative::*;
use crate::result::FrictionIteration;
use crate::structure::Assembly;

/// Where the fixed-point iteration ended.
pub struct Iterated<T> {
    /// The last solution (of the program with fixed shear capacities).
    pub last: T,
    /// The value (λ or work) per iteration.
    pub history: Vec<f64>,
    pub converged: bool,
}

/// The fixed-point iteration on the normal forces shared by every analysis: solve the
/// associative problem (`solve`; `read` gives the value and normal forces of a solution, or
/// None when it has none), then repeatedly fix the shear capacities `μ n̄ + c` on `map`,
/// solve, and relax `n̄` towards the new normal forces, until value and forces settle.
/// Returns the associative value and the iteration (none without friction or without an
/// associative solution).
pub fn iterate<T>(
    map: &mut KinematicMap,
    o: &NonAssociativeOptions,
    mut solve: impl FnMut(&KinematicMap) -> Result<T>,
    read: impl Fn(&T) -> Option<(f64, &[f64])>,
) -> Result<(Option<f64>, Iterated<T>)> {
    let trace = std::env::var_os("VOUSSOIR_TRACE").is_some();
    let t0 = std::time::Instant::now();
    map.shear_limits = None;
    let first = solve(map)?;
    if trace {
        eprintln!(
            "trace: non-associative: associative program {:?} {:.3} s",
            read(&first).map(|(v, _)| v),
            t0.elapsed().as_secs_f64()
        );
    }
    let Some((associative, first_pn)) = read(&first).map(|(v, p)| (v, p.to_vec())) else {
        return Ok((None, Iterated::done(first)));
    };
    if !map.laws.iter().any(|l| l.friction.is_some()) {
        return Ok((Some(associative), Iterated::done(first)));
    }
    let alpha = o.relaxation.clamp(1e-3, 1.0);
    let mut nbar = first_pn;
    let mut history = Vec::new();
    let mut last = first;
    let mut converged = false;
    for _ in 0..o.max_iterations {
        let limits: Vec<f64> = (0..map.num_points())
            .map(|k| {
                let law = &map.laws[map.points[k].joint];
                law.friction
                    .map_or(f64::INFINITY, |mu| mu * nbar[k].max(0.0) + law.cohesion)
            })
            .collect();
        map.shear_limits = Some(limits);
        let t0 = std::time::Instant::now();
        let s = solve(map)?;
        let Some((value, pn)) = read(&s) else {
            last = s;
            break;
        };
        let prev = history.last().copied();
        history.push(value);
        let scale = nbar.iter().fold(1e-12f64, |m, x| m.max(x.abs()));
        let dn = nbar
            .iter()
            .zip(pn)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
            / scale;
        if trace {
            eprintln!(
                "trace: non-associative: iterate {} value {value:.10} normal forces moved {dn:.2e} {:.3} s",
                history.len(),
                t0.elapsed().as_secs_f64()
            );
        }
        for (a, b) in nbar.iter_mut().zip(pn) {
            *a = (1.0 - alpha) * *a + alpha * b;
        }
        last = s;
        if o.window <= 2 {
            if let Some(p) = prev {
                let vscale = value.abs().max(p.abs()).max(1e-12);
                if (value - p).abs() <= o.tolerance * vscale && dn <= o.tolerance.sqrt() {
                    converged = true;
                    break;
                }
            }
        } else if settled(&history, o.window, o.tolerance) {
            converged = true;
            break;
        }
        // The band: where the normal forces keep wandering over a large optimal face (the
        // façades), the value settles within a band long before consecutive values agree.
        if o.window <= 2 && settled(&history, o.band_window, o.band_tolerance) {
            converged = true;
            break;
        }
    }
    Ok((
        Some(associative),
        Iterated {
            last,
            history,
            converged,
        },
    ))
}

/// Whether the last `window` values of `history` lie within `tolerance` of the largest of them
/// (relative); never for a window below 3 or a history shorter than the window.
fn settled(history: &[f64], window: usize, tolerance: f64) -> bool {
    if window < 3 || history.len() < window {
        return false;
    }
    let w = &history[history.len() - window..];
    let (lo, hi) = w
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    hi - lo <= tolerance * hi.abs().max(lo.abs()).max(1e-12)
}

impl<T> Iterated<T> {
    /// No iteration: the associative solution stands.
    fn done(last: T) -> Iterated<T> {
        Iterated {
            last,
            history: vec![],
            converged: true,
        }
    }
}

/// The limit solution with non-associative friction, on `map` (whose shear capacities it
/// sets): the associative λ, and the iteration.
pub fn solve_limit_nonassociative<S: Assembly>(
    st: &S,
    map: &mut KinematicMap,
    opts: &SolverOptions,
    o: &NonAssociativeOptions,
) -> Result<(Option<f64>, Iterated<LimitSolution>)> {
    // No cleanup pass inside the iteration: each step is a fixed-point update, and a vertex in
    // place of the interior point changes the path the iteration takes (it no longer reached a
    // multiplier in one settled capacity step); the final result is certified as a whole.
    let opts = &SolverOptions {
        cleanup: false,
        ..*opts
    };
    iterate(
        map,
        o,
        |m| solve_limit(st, m, opts),
        |s| {
            (s.status == LimitStatus::Collapse)
                .then_some(())
                .and(s.lambda.map(|l| (l, s.pn.as_slice())))
        },
    )
}

pub fn limit_nonassociative<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    o: &NonAssociativeOptions,
) -> Result<NonAssociativeResult<S::D>> {
    let mut map = KinematicMap::new(st);
    let (associative, it) = solve_limit_nonassociative(st, &mut map, opts, o)?;
    let limit = limit_result(st, &map, &it.last);
    Ok(NonAssociativeResult {
        associative_multiplier: associative,
        history: it.history,
        converged: it.converged,
        limit,
    })
}

/// The settlement solution with non-associative friction, on `map` (whose shear capacities
/// it sets): the associative work, and the iteration.
pub fn solve_settlement_nonassociative<S: Assembly>(
    st: &S,
    map: &mut KinematicMap,
    opts: &SolverOptions,
    crushing: Crushing,
    o: &NonAssociativeOptions,
) -> Result<(Option<f64>, Iterated<SettlementSolution>)> {
    // The iterates need the normal forces and the work, which the force program alone gives
    // (its optimum is the work, equal to the motion program's within the duality gap): the
    // motion program, whose only product is the mechanism, is solved for the associative
    // solution and for the last iterate only (with the last iterate's capacities, so the forces
    // and the path are those of solving both programs every time). Half the programs of the
    // iteration on the 1.0 m running-bond façade (docs/performance.md, "Non-associative façade
    // (session 24)"). Conic crushing, or a force program without an optimum (no equilibrium,
    // or the settlement incompatible), takes both programs as before.
    let first = std::cell::Cell::new(true);
    let (associative, mut it) = iterate(
        map,
        o,
        |m| {
            if crushing == Crushing::Linear && !first.replace(false) {
                if let Some(s) = settlement_forces(st, m, opts)? {
                    return Ok((s, false));
                }
            }
            Ok((solve_settlement_crushing(st, m, opts, crushing)?, true))
        },
        |(s, _)| (s.status == SettlementStatus::Mechanism).then_some((s.primal, s.pn.as_slice())),
    )?;
    if !it.last.1 {
        it.last = (solve_settlement_crushing(st, map, opts, crushing)?, true);
        // The last value as the pair gives it (the motion program's optimum), as before.
        if let (Some(v), SettlementStatus::Mechanism) = (it.history.last_mut(), it.last.0.status) {
            *v = it.last.0.primal;
        }
    }
    Ok((
        associative,
        Iterated {
            last: it.last.0,
            history: it.history,
            converged: it.converged,
        },
    ))
}

/// The settlement's force program alone (polygonal statics), solved: the normal and shear
/// forces and the optimal work, without a mechanism; `None` where it has no optimum.
fn settlement_forces<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<Option<SettlementSolution>> {
    let dead = st.load_vector(false);
    let fp = crate::programs::settlement_force_program(map, &dead);
    let s = fp.solve(opts)?;
    if s.status != crate::lp::LpStatus::Optimal {
        return Ok(None);
    }
    let (pn, pt) = fp.forces(&s.x);
    Ok(Some(SettlementSolution {
        status: SettlementStatus::Mechanism,
        mechanism: vec![],
        pn,
        pt,
        primal: s.objective,
        dual: s.objective,
        solver: s.solver_info(),
    }))
}

/// Settlement analysis with non-associative friction: the settlement result of the last
/// iterate, with the iteration (`friction_iteration`) and a warning when it did not converge.
pub fn settle_nonassociative<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    crushing: Crushing,
    facets: usize,
    o: &NonAssociativeOptions,
) -> Result<SettlementResult<S::D>> {
    super::limit::check_facets(facets)?;
    let mut map = KinematicMap::new(st);
    map.facets = facets;
    let (associative, it) = solve_settlement_nonassociative(st, &mut map, opts, crushing, o)?;
    let mut settlement = settlement_result(st, &map, &it.last);
    FrictionIteration {
        associative,
        history: it.history,
        converged: it.converged,
    }
    .attach(&mut settlement.message, &mut settlement.friction_iteration);
    Ok(settlement)
}

/// [`limit_nonassociative`] as a limit result with its `friction_iteration`.
pub fn limit_nonassociative_result<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    o: &NonAssociativeOptions,
) -> Result<LimitResult<S::D>> {
    let r = limit_nonassociative(st, opts, o)?;
    let mut limit = r.limit;
    FrictionIteration {
        associative: r.associative_multiplier,
        history: r.history,
        converged: r.converged,
    }
    .attach(&mut limit.message, &mut limit.friction_iteration);
    Ok(limit)
}
