//! Limit analysis with non-associative Coulomb friction (sliding without dilatancy).
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

use super::limit::{limit_result, solve_limit, LimitStatus};
use crate::discretize::KinematicMap;
use crate::error::Result;
use crate::lp::SolverOptions;
pub use crate::result::nonassociative::*;
use crate::structure::Structure;

/// Settings of the iteration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NonAssociativeOptions {
    pub max_iterations: usize,
    /// Relaxation α in (0, 1].
    pub relaxation: f64,
    /// Convergence: relative change of λ and of the normal forces.
    pub tolerance: f64,
}

impl Default for NonAssociativeOptions {
    fn default() -> Self {
        NonAssociativeOptions {
            max_iterations: 200,
            relaxation: 0.5,
            tolerance: 1e-7,
        }
    }
}

pub fn limit_nonassociative(
    st: &Structure,
    opts: &SolverOptions,
    o: &NonAssociativeOptions,
) -> Result<NonAssociativeResult> {
    let mut map = KinematicMap::new(st);
    let first = solve_limit(st, &map, opts)?;
    let associative = first.lambda;
    if first.status != LimitStatus::Collapse || !map.laws.iter().any(|l| l.friction.is_some()) {
        let limit = limit_result(st, &map, &first);
        return Ok(NonAssociativeResult {
            associative_multiplier: associative,
            history: vec![],
            converged: true,
            limit,
        });
    }
    let alpha = o.relaxation.clamp(1e-3, 1.0);
    let mut nbar = first.pn.clone();
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
        let s = solve_limit(st, &map, opts)?;
        let Some(lam) = s.lambda else {
            last = s;
            break;
        };
        let prev = history.last().copied();
        history.push(lam);
        let scale = nbar.iter().fold(1e-12f64, |m, x| m.max(x.abs()));
        let dn = nbar
            .iter()
            .zip(&s.pn)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
            / scale;
        for (a, b) in nbar.iter_mut().zip(&s.pn) {
            *a = (1.0 - alpha) * *a + alpha * b;
        }
        last = s;
        if let Some(p) = prev {
            if (lam - p).abs() <= o.tolerance * lam.abs().max(1e-12) && dn <= o.tolerance.sqrt() {
                converged = true;
                break;
            }
        }
    }
    let limit = limit_result(st, &map, &last);
    Ok(NonAssociativeResult {
        associative_multiplier: associative,
        history,
        converged,
        limit,
    })
}
