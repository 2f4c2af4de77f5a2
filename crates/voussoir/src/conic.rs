//! Exact finite compressive strength as a second-order cone program (Clarabel).
//!
//! The force program is assembled as usual but without the inscribed chords of the crushing
//! domain; each joint of finite strength instead gets the two rotated cones
//! ```text
//!   N² ≤ 2 f_c w · (N t/2 ∓ M)      ⇔      ‖(N, (r − f_c w)/√2)‖ ≤ (r + f_c w)/√2,  r = N t/2 ∓ M
//! ```
//! which is `|M| ≤ N (t/2 − N/(2 f_c w))` exactly.

use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::Direction;
use crate::programs::ForceProgram;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettings, DefaultSolver, IPSolver, SolverStatus, SupportedConeT};

const INF: f64 = f64::INFINITY;

/// Outcome of a conic solve.
pub struct ConicSolution {
    pub status: crate::lp::LpStatus,
    pub objective: f64,
    pub x: Vec<f64>,
    /// Duals of the LP's rows (same sign convention as HiGHS's for a minimisation).
    pub row_dual: Vec<f64>,
}

/// Solve a force program with the exact crushing cones of `map`'s joints.
pub fn solve_force_conic(map: &KinematicMap, fp: &ForceProgram) -> Result<ConicSolution> {
    let lp = &fp.lp;
    let sign = if lp.maximise { -1.0 } else { 1.0 };
    // Rows of A (as lists), right-hand sides, cone kinds.
    let mut zero: Vec<(Vec<(usize, f64)>, f64, usize)> = Vec::new(); // (row, b, lp row)
    let mut nonneg: Vec<(Vec<(usize, f64)>, f64)> = Vec::new();
    let mut rows: Vec<Vec<(usize, f64)>> = vec![Vec::new(); lp.num_rows()];
    for j in 0..lp.num_cols() {
        for (i, v) in lp.column(j) {
            rows[i].push((j, v));
        }
    }
    for (i, r) in rows.into_iter().enumerate() {
        let (lo, hi) = (lp.row_lower[i], lp.row_upper[i]);
        if lo == hi {
            zero.push((r, hi, i));
        } else {
            if hi < INF {
                nonneg.push((r.clone(), hi));
            }
            if lo > -INF {
                nonneg.push((r.iter().map(|&(j, v)| (j, -v)).collect(), -lo));
            }
        }
    }
    for j in 0..lp.num_cols() {
        if lp.col_lower[j] == 0.0 {
            nonneg.push((vec![(j, -1.0)], 0.0));
        } else if lp.col_lower[j] > -INF {
            nonneg.push((vec![(j, -1.0)], -lp.col_lower[j]));
        }
        if lp.col_upper[j] < INF {
            nonneg.push((vec![(j, 1.0)], lp.col_upper[j]));
        }
    }
    // Cones per joint of finite strength.
    let mut socs: Vec<[(Vec<(usize, f64)>, f64); 3]> = Vec::new();
    let r2 = std::f64::consts::SQRT_2;
    for (j, law) in map.laws.iter().enumerate() {
        let Some(nmax) = law.max_normal_force() else {
            continue;
        };
        let range = map.joint_start[j]..map.joint_start[j + 1];
        if range.clone().any(|k| map.bilateral[k]) || nmax <= 0.0 {
            continue;
        }
        let t = law.depth;
        let fw = nmax / t;
        let cols: Vec<(usize, f64)> = range
            .filter_map(|k| fp.pn[k].map(|c| (c, map.along[k])))
            .collect();
        for s in [1.0, -1.0] {
            // r = Σ (t/2 − s·s_k) p_k ; slack = b − A x.
            let r_row: Vec<(usize, f64)> = cols
                .iter()
                .map(|&(c, a)| (c, -(t / 2.0 - s * a) / r2))
                .collect();
            let n_row: Vec<(usize, f64)> = cols.iter().map(|&(c, _)| (c, -1.0)).collect();
            socs.push([(r_row.clone(), fw / r2), (n_row, 0.0), (r_row, -fw / r2)]);
        }
    }
    // Assemble A by triplets.
    let (mut ii, mut jj, mut vv, mut b) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut push = |row: &[(usize, f64)], rhs: f64, b: &mut Vec<f64>| {
        let r = b.len();
        for &(j, v) in row {
            ii.push(r);
            jj.push(j);
            vv.push(v);
        }
        b.push(rhs);
    };
    for (r, rhs, _) in &zero {
        push(r, *rhs, &mut b);
    }
    for (r, rhs) in &nonneg {
        push(r, *rhs, &mut b);
    }
    for cone in &socs {
        for (r, rhs) in cone {
            push(r, *rhs, &mut b);
        }
    }
    let n = lp.num_cols();
    let m = b.len();
    let a = CscMatrix::new_from_triplets(m, n, ii, jj, vv);
    let p = CscMatrix::<f64>::zeros((n, n));
    let q: Vec<f64> = lp.cost.iter().map(|c| sign * c).collect();
    let mut cones: Vec<SupportedConeT<f64>> = Vec::new();
    if !zero.is_empty() {
        cones.push(SupportedConeT::ZeroConeT(zero.len()));
    }
    if !nonneg.is_empty() {
        cones.push(SupportedConeT::NonnegativeConeT(nonneg.len()));
    }
    for _ in &socs {
        cones.push(SupportedConeT::SecondOrderConeT(3));
    }
    let settings = DefaultSettings {
        verbose: false,
        tol_gap_abs: 1e-10,
        tol_gap_rel: 1e-10,
        tol_feas: 1e-10,
        ..DefaultSettings::default()
    };
    let mut solver = DefaultSolver::new(&p, &q, &a, &b, &cones, settings)
        .map_err(|e| Error::Solver(format!("Clarabel setup: {e:?}")))?;
    solver.solve();
    let sol = &solver.solution;
    let status = match sol.status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => crate::lp::LpStatus::Optimal,
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => {
            crate::lp::LpStatus::Infeasible
        }
        SolverStatus::DualInfeasible | SolverStatus::AlmostDualInfeasible => {
            crate::lp::LpStatus::Unbounded
        }
        other => return Err(Error::Solver(format!("Clarabel stopped: {other:?}"))),
    };
    // Duals of the equality rows (Clarabel's z for `Ax + s = b`); map back to LP rows.
    let mut row_dual = vec![0.0; lp.num_rows()];
    for (slot, (_, _, i)) in zero.iter().enumerate() {
        row_dual[*i] = sol.z[slot];
    }
    Ok(ConicSolution {
        status,
        objective: sign * sol.obj_val,
        x: sol.x.clone(),
        row_dual,
    })
}

/// The force program for a limit analysis with the crushing chords left out (the cones
/// replace them).
pub fn limit_force_program(map: &KinematicMap, dead: &[f64], live: &[f64]) -> ForceProgram {
    let mut m = map.clone();
    m.facets = 0;
    ForceProgram::new(&m, dead, Some(live), Direction::Maximise, |_| (0.0, 0.0))
}
