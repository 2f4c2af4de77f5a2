//! A kept simplex basis looked at on the next program of a sequence before any backend run
//! ([`super::solve_warm_kept`]): the basic solution of that basis on the new program, and its
//! duals, by the solver layer's own sparse LU ([`super::lu`]). Where that point and those duals
//! are primal and dual feasible within the backend's own feasibility tolerance, and the answer
//! certifies on the program as written ([`super::policy::check`], as every answer), it is the
//! optimum the simplex would return from that basis after zero iterations, and no backend
//! runs. Otherwise nothing is answered here and the warm simplex runs as before.
//!
//! Why: HiGHS, handed a starting basis through its C interface, factorises it twice (once to
//! check the "alien" basis in `Highs_setBasis`, once when the simplex starts), and where a
//! pivot is needed computes its dual steepest-edge weights from scratch (one solve per row).
//! On a capacity curve's steps (the 0.5 m running-bond façade: 8,016 rows, 30,641 columns)
//! most steps take no pivot, and those runs were 0.9–1.9 s each (docs/performance.md,
//! "`capacity` on the 0.5 m façades (session 26)").

// The loops run over several arrays indexed alike (rows, columns, pivots).
#![allow(clippy::needless_range_loop)]

use super::lu::{Csc, Lu};
use super::scale::Scaling;
use super::{policy, Basis, BasisStatus, LinearProgram, LpSolution, LpStatus, SolverOptions};

/// The value of a nonbasic variable with `status` between `lo` and `hi`.
fn nonbasic_value(status: BasisStatus, lo: f64, hi: f64) -> f64 {
    match status {
        BasisStatus::Lower => lo,
        BasisStatus::Upper => hi,
        BasisStatus::Zero | BasisStatus::Basic => 0.0,
    }
}

/// Whether a nonbasic variable's dual `d` (as a minimisation: `σ·d`) has the sign its status
/// allows, within `tol`: at a lower bound ≥ 0, at an upper bound ≤ 0, free at zero 0; either
/// sign where the bounds are equal.
fn dual_sign_ok(status: BasisStatus, lo: f64, hi: f64, d: f64, tol: f64) -> bool {
    if lo == hi {
        return true;
    }
    match status {
        BasisStatus::Lower => d >= -tol,
        BasisStatus::Upper => d <= tol,
        BasisStatus::Zero => d.abs() <= tol,
        BasisStatus::Basic => true,
    }
}

/// `z` improved by one step of iterative refinement: `z + solve(b − M z)` (`Mᵀ` where
/// `transpose`), the residual from the matrix as given.
fn refined(
    m: &Csc,
    b: &[f64],
    mut z: Vec<f64>,
    transpose: bool,
    solve: impl Fn(&[f64]) -> Vec<f64>,
) -> Vec<f64> {
    let mut r = b.to_vec();
    for j in 0..m.n {
        for p in m.col_start[j]..m.col_start[j + 1] {
            let (i, a) = (m.row_index[p], m.value[p]);
            if transpose {
                r[j] -= a * z[i];
            } else {
                r[i] -= a * z[j];
            }
        }
    }
    for (v, d) in z.iter_mut().zip(solve(&r)) {
        *v += d;
    }
    z
}

/// The basic solution of `lp` at `basis` and its duals (HiGHS's convention: `c − Aᵀy − z = 0`
/// in the program's own sense), where the basis matrix is nonsingular and the solution is
/// primal and dual feasible within `tol` (absolute, on `lp`'s own numbers, as a simplex
/// judges them); `None` otherwise.
pub fn basic_solution(lp: &LinearProgram, basis: &Basis, tol: f64) -> Option<LpSolution> {
    let (n, m) = (lp.num_cols(), lp.num_rows());
    if basis.cols.len() != n || basis.rows.len() != m || m == 0 {
        return None;
    }
    // The basis matrix: the basic columns of A and −e_i for each basic row.
    let mut order = Vec::with_capacity(m);
    let (mut col_start, mut row_index, mut value) = (vec![0usize], Vec::new(), Vec::new());
    for j in 0..n {
        if basis.cols[j] == BasisStatus::Basic {
            order.push(j);
            for (i, a) in lp.column(j) {
                row_index.push(i);
                value.push(a);
            }
            col_start.push(row_index.len());
        }
    }
    for i in 0..m {
        if basis.rows[i] == BasisStatus::Basic {
            order.push(n + i);
            row_index.push(i);
            value.push(-1.0);
            col_start.push(row_index.len());
        }
    }
    if order.len() != m {
        return None;
    }
    // Nonbasic values and the right-hand side `E r_N − A_N x_N`.
    let mut x = vec![0.0; n];
    let mut rhs = vec![0.0; m];
    for i in 0..m {
        if basis.rows[i] != BasisStatus::Basic {
            rhs[i] = nonbasic_value(basis.rows[i], lp.row_lower[i], lp.row_upper[i]);
        }
    }
    for j in 0..n {
        if basis.cols[j] != BasisStatus::Basic {
            let v = nonbasic_value(basis.cols[j], lp.col_lower[j], lp.col_upper[j]);
            x[j] = v;
            if v != 0.0 {
                for (i, a) in lp.column(j) {
                    rhs[i] -= a * v;
                }
            }
        }
    }
    if rhs.iter().chain(&x).any(|v| !v.is_finite()) {
        return None;
    }
    let matrix = Csc {
        n: m,
        col_start,
        row_index,
        value,
    };
    let lu = Lu::factor(&matrix)?;
    let z = refined(&matrix, &rhs, lu.solve(&rhs), false, |r| lu.solve(r));
    for (k, &v) in order.iter().enumerate() {
        if v < n {
            x[v] = z[k];
        }
    }
    // Primal feasibility of the basic variables: columns within their bounds, rows' activities
    // within theirs.
    let activity = lp.row_activity(&x);
    let within = |v: f64, lo: f64, hi: f64| v.is_finite() && v >= lo - tol && v <= hi + tol;
    for &v in &order {
        let ok = if v < n {
            within(x[v], lp.col_lower[v], lp.col_upper[v])
        } else {
            let i = v - n;
            within(activity[i], lp.row_lower[i], lp.row_upper[i])
        };
        if !ok {
            return None;
        }
    }
    // Duals: Mᵀy = c_B (a basic row's dual is zero), reduced costs z = c − Aᵀy.
    let cb: Vec<f64> = order
        .iter()
        .map(|&v| if v < n { lp.cost[v] } else { 0.0 })
        .collect();
    let y = refined(&matrix, &cb, lu.solve_transpose(&cb), true, |r| {
        lu.solve_transpose(r)
    });
    let col_dual: Vec<f64> = (0..n)
        .map(|j| lp.cost[j] - lp.column(j).map(|(i, a)| a * y[i]).sum::<f64>())
        .collect();
    let sigma = if lp.maximise { -1.0 } else { 1.0 };
    for j in 0..n {
        let d = sigma * col_dual[j];
        if !d.is_finite() || !dual_sign_ok(basis.cols[j], lp.col_lower[j], lp.col_upper[j], d, tol)
        {
            return None;
        }
    }
    for i in 0..m {
        let d = sigma * y[i];
        if !d.is_finite() || !dual_sign_ok(basis.rows[i], lp.row_lower[i], lp.row_upper[i], d, tol)
        {
            return None;
        }
    }
    Some(LpSolution {
        status: LpStatus::Optimal,
        objective: lp.objective(&x),
        x,
        row_dual: y,
        col_dual,
        iterations: 0,
        dual_objective: f64::NAN,
        reduced_accuracy: false,
        method: super::Method::DualSimplex,
        tried: Vec::new(),
    })
}

/// The optimum of `lp` at the kept `basis` (already [`Basis::adapted`] to `lp`'s bounds), where
/// it is one: the basic solution of the program as the backend would be handed it (equilibrated
/// where [`Scaling::needed`]), feasible in both senses within `opts.feasibility_tolerance`,
/// in the user's units, and certified on `lp` as written by [`policy::check`]. Stated as
/// `opts.method`'s (a simplex method: the answer it returns from this basis after zero
/// iterations). `None`: the backend must run.
pub fn answer(lp: &LinearProgram, opts: &SolverOptions, basis: &Basis) -> Option<LpSolution> {
    if !opts.method.is_simplex() {
        return None;
    }
    let scaling = Scaling::needed(lp, &[]);
    let solution = match &scaling {
        None => basic_solution(lp, basis, opts.feasibility_tolerance)?,
        Some(s) => s.unscale(basic_solution(
            &s.apply(lp),
            basis,
            opts.feasibility_tolerance,
        )?),
    };
    let solution = LpSolution {
        method: opts.method,
        ..solution
    };
    policy::check(lp, &solution).is_none().then_some(solution)
}
