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
use crate::lp::{Direction, LinearProgram};

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lp::{solve, LpStatus, SolverOptions};

    #[test]
    fn dual_of_a_small_lp_has_the_same_optimum() {
        // max x + y  s.t. x + 2y ≤ 4, 3x + y ≤ 6, x − y = 0.5, x ≥ 0, y free.
        let mut lp = LinearProgram::new(Direction::Maximise);
        let r0 = lp.add_row(-INF, 4.0);
        let r1 = lp.add_row(-INF, 6.0);
        let r2 = lp.add_row(0.5, 0.5);
        lp.add_column(1.0, 0.0, INF, [(r0, 1.0), (r1, 3.0), (r2, 1.0)]);
        lp.add_column(1.0, -INF, INF, [(r0, 2.0), (r1, 1.0), (r2, -1.0)]);
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
}
