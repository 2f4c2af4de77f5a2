//! The LP dual of a [`LinearProgram`], formed mechanically.
//!
//! voussoir builds every program once, in its force (static) form; the kinematic form of the
//! same problem is its dual, constructed here. So the paper's primal (62)–(66) is the dual of
//! its (69)–(71), and with friction or finite compressive strength the extra rows of the force
//! form become the sliding and crushing variables of the kinematic form automatically.
//!
//! For `min cᵀx  s.t.  a_iᵀx {=, ≤, ≥} b_i,  x_j {free, ≥ 0, ≤ 0}` the dual is
//! `max bᵀy  s.t.  A_jᵀy {=, ≤, ≥} c_j` with `y_i` {free, ≤ 0, ≥ 0} respectively. A maximisation
//! is first turned into the minimisation of `−cᵀx`; its dual objective is then the negated one.

use crate::error::{Error, Result};
use crate::lp::{Basis, BasisStatus, Direction, LinearProgram};

const INF: f64 = f64::INFINITY;

/// The dual LP and how to read it.
pub struct DualProgram {
    pub lp: LinearProgram,
    /// Sign to apply to the dual's objective value to get the primal's optimum.
    pub objective_sign: f64,
}

/// Form the dual. Rows must be equalities or one-sided; columns free, non-negative or
/// non-positive (what the force programs produce).
pub fn dual(p: &LinearProgram) -> Result<DualProgram> {
    let s = if p.maximise { -1.0 } else { 1.0 };
    let mut d = LinearProgram::new(Direction::Maximise);
    // Dual rows = primal columns.
    for j in 0..p.num_cols() {
        let c = s * p.cost[j];
        let (lo, hi) = (p.col_lower[j], p.col_upper[j]);
        let (rl, ru) = if lo == -INF && hi == INF {
            (c, c)
        } else if lo == 0.0 && hi == INF {
            (-INF, c)
        } else if lo == -INF && hi == 0.0 {
            (c, INF)
        } else {
            return Err(Error::Solver(format!(
                "cannot dualise column {j} with bounds [{lo}, {hi}]"
            )));
        };
        d.add_row(rl, ru);
    }
    // Dual columns = primal rows; gather the primal's columns row by row.
    let mut rows: Vec<Vec<(usize, f64)>> = vec![Vec::new(); p.num_rows()];
    for j in 0..p.num_cols() {
        for (i, v) in p.column(j) {
            rows[i].push((j, v));
        }
    }
    for (i, entries) in rows.into_iter().enumerate() {
        let (lo, hi) = (p.row_lower[i], p.row_upper[i]);
        let (b, yl, yu) = if lo == hi {
            (lo, -INF, INF)
        } else if lo == -INF && hi < INF {
            (hi, -INF, 0.0)
        } else if hi == INF && lo > -INF {
            (lo, 0.0, INF)
        } else {
            return Err(Error::Solver(format!(
                "cannot dualise ranged row {i} [{lo}, {hi}]"
            )));
        };
        d.add_column(b, yl, yu, entries);
    }
    Ok(DualProgram {
        lp: d,
        objective_sign: s,
    })
}

/// The basis of [`dual`]`(p)` complementary to a basis `b` of `p`: a dual column (a primal
/// row) is basic where the primal row is not, and a dual row (a primal column) is nonbasic, at
/// its bound, where the primal column is basic. An optimal basis of `p` gives an optimal basis
/// of its dual (primal feasibility of one is dual feasibility of the other), so a simplex
/// started from it ends at once: the limit's kinematic program after its static one
/// (`analysis::canonical::limit_mechanism`), which was solved a second time from scratch (73 s
/// of the 0.25 m façade in running bond's `tilt`; docs/performance.md, "The kinematic program
/// from the static program's basis (session 29)"). `None` where `b` does not fit `p`.
pub fn dual_basis(p: &LinearProgram, b: &Basis) -> Option<Basis> {
    if b.cols.len() != p.num_cols() || b.rows.len() != p.num_rows() {
        return None;
    }
    // Dual rows = primal columns: `(−∞, c]` for `x ≥ 0`, `[c, ∞)` for `x ≤ 0`, `[c, c]` free.
    let rows = (0..p.num_cols())
        .map(|j| {
            if b.cols[j] != BasisStatus::Basic {
                BasisStatus::Basic
            } else if p.col_lower[j] == 0.0 && p.col_upper[j] == INF {
                BasisStatus::Upper
            } else {
                BasisStatus::Lower
            }
        })
        .collect();
    // Dual columns = primal rows: `y` free for an equation, `≤ 0` for a `≤` row, `≥ 0` for `≥`.
    let cols = (0..p.num_rows())
        .map(|i| {
            if b.rows[i] != BasisStatus::Basic {
                BasisStatus::Basic
            } else if p.row_lower[i] == p.row_upper[i] {
                BasisStatus::Zero
            } else if p.row_lower[i] == -INF {
                BasisStatus::Upper
            } else {
                BasisStatus::Lower
            }
        })
        .collect();
    Some(Basis { cols, rows })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lp::{solve, LpStatus, SolverOptions};

    /// max x + y  s.t. x + 2y ≤ 4, 3x + y ≤ 6, x − y = 0.5, x ≥ 0, y free.
    fn small_lp() -> LinearProgram {
        let mut lp = LinearProgram::new(Direction::Maximise);
        let r0 = lp.add_row(-INF, 4.0);
        let r1 = lp.add_row(-INF, 6.0);
        let r2 = lp.add_row(0.5, 0.5);
        lp.add_column(1.0, 0.0, INF, [(r0, 1.0), (r1, 3.0), (r2, 1.0)]);
        lp.add_column(1.0, -INF, INF, [(r0, 2.0), (r1, 1.0), (r2, -1.0)]);
        lp
    }

    #[test]
    fn dual_of_a_small_lp_has_the_same_optimum() {
        let lp = small_lp();
        let o = SolverOptions::default();
        let p = solve(&lp, &o).unwrap();
        let dp = dual(&lp).unwrap();
        let q = solve(&dp.lp, &o).unwrap();
        assert_eq!(p.status, LpStatus::Optimal);
        assert_eq!(q.status, LpStatus::Optimal);
        // By hand: x = y + 0.5; x + 2y ≤ 4 → y ≤ 7/6; 3x + y ≤ 6 → y ≤ 9/8; obj = 2y + 0.5 = 2.75.
        assert!((p.objective - 2.75).abs() < 1e-9);
        assert!(
            (dp.objective_sign * q.objective - 2.75).abs() < 1e-9,
            "{}",
            q.objective
        );
    }

    #[test]
    fn the_complementary_basis_of_an_optimal_basis_is_optimal_for_the_dual() {
        // The program above, solved by the dual simplex for its optimal basis; its dual from
        // the complementary basis by the primal simplex: no pivot, the same optimum (2.75, by
        // hand above).
        let lp = small_lp();
        let o = SolverOptions {
            method: crate::lp::Method::DualSimplex,
            ..SolverOptions::default()
        };
        let mut basis = None;
        let p = crate::lp::solve_warm(&lp, &o, &mut basis).unwrap();
        assert_eq!(p.status, LpStatus::Optimal);
        let dp = dual(&lp).unwrap();
        let mut start = Some(dual_basis(&lp, basis.as_ref().unwrap()).unwrap());
        let po = SolverOptions {
            method: crate::lp::Method::PrimalSimplex,
            ..SolverOptions::default()
        };
        let q = crate::lp::solve_warm(&dp.lp, &po, &mut start).unwrap();
        assert_eq!(q.status, LpStatus::Optimal);
        assert_eq!(q.iterations, 0, "pivots from the complementary basis");
        assert!((dp.objective_sign * q.objective - 2.75).abs() < 1e-9);
        // A basis of another program is refused.
        let other = Basis {
            cols: vec![BasisStatus::Basic],
            rows: vec![],
        };
        assert!(dual_basis(&lp, &other).is_none());
    }
}
