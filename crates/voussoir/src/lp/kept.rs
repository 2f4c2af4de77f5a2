//! A kept simplex basis looked at on the next program of a sequence before any backend run
//! ([`super::solve_warm_kept`]): the basic solution of that basis on the new program, and its
//! duals, by the solver layer's own sparse LU ([`super::lu`]). Where that point and those duals
//! are primal and dual feasible within the backend's own feasibility tolerance, and the answer
//! certifies on the program as written ([`super::policy::check`], as every answer), it is the
//! optimum the simplex would return from that basis after zero iterations, and no backend
//! runs. Where the basis is dual feasible but some basic variables are outside their bounds,
//! a few textbook bounded dual simplex pivots are taken from it here ([`pivoted_solution`]:
//! at most [`MAX_PIVOTS`], each new basis refactorised by the same LU), and the basis reached
//! answers under the same acceptance. Otherwise nothing is answered here and the warm simplex
//! runs as before.
//!
//! Why: HiGHS, handed a starting basis through its C interface, factorises it twice (once to
//! check the "alien" basis in `Highs_setBasis`, once when the simplex starts), and where a
//! pivot is needed computes its dual steepest-edge weights from scratch (one solve per row).
//! On a capacity curve's steps (the 0.5 m running-bond façade: 8,016 rows, 30,641 columns)
//! most steps take no pivot, and those runs were 0.9–1.9 s each (docs/performance.md,
//! "`capacity` on the 0.5 m façades (session 26)"); the steps that take one pivot were
//! 0.8–3.6 s each (HiGHS factorises three times and computes its dual steepest-edge weights
//! from scratch; "Capacity's one-pivot steps from the kept basis (session 27)").

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

/// The most dual simplex pivots [`answer_pivoting`] takes from a kept basis; a program that
/// needs more goes to the backend.
pub const MAX_PIVOTS: usize = 20;

/// A basis of `lp` factorised, with its basic solution and duals (HiGHS's convention: `c − Aᵀy
/// − z = 0` in the program's own sense). The variables are `lp`'s columns `0..n` and its rows
/// `n..n + m` (a row's variable is its activity, with column `−e_i`, as HiGHS models rows).
struct Vertex {
    /// The basic variables in the basis matrix's column order.
    order: Vec<usize>,
    lu: Lu,
    x: Vec<f64>,
    activity: Vec<f64>,
    y: Vec<f64>,
    col_dual: Vec<f64>,
}

impl Vertex {
    /// The factorised basis and its point and duals; `None` where the basis does not fit `lp`
    /// or its matrix is singular.
    fn of(lp: &LinearProgram, basis: &Basis) -> Option<Vertex> {
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
        let activity = lp.row_activity(&x);
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
        Some(Vertex {
            order,
            lu,
            x,
            activity,
            y,
            col_dual,
        })
    }

    /// The primal infeasibility of basic variable `v`: its value less its lower bound where
    /// below it (negative), less its upper bound where above it (positive), 0 within them;
    /// NaN where the value is not finite.
    fn infeasibility(&self, lp: &LinearProgram, v: usize) -> f64 {
        let n = lp.num_cols();
        let (value, lo, hi) = if v < n {
            (self.x[v], lp.col_lower[v], lp.col_upper[v])
        } else {
            let i = v - n;
            (self.activity[i], lp.row_lower[i], lp.row_upper[i])
        };
        if !value.is_finite() {
            f64::NAN
        } else if value < lo {
            value - lo
        } else if value > hi {
            value - hi
        } else {
            0.0
        }
    }

    /// The basic variable (its position in `order`) of the largest primal infeasibility above
    /// `tol`, with that infeasibility (ties: the lowest variable index); `Ok(None)` where every
    /// basic variable is within its bounds to `tol`; `Err(())` where a value is not finite.
    fn worst(&self, lp: &LinearProgram, tol: f64) -> Result<Option<(usize, f64)>, ()> {
        let mut worst: Option<(usize, f64)> = None;
        for (k, &v) in self.order.iter().enumerate() {
            let d = self.infeasibility(lp, v);
            if d.is_nan() {
                return Err(());
            }
            if d.abs() > tol {
                let better = match worst {
                    None => true,
                    Some((w, e)) => d.abs() > e.abs() || (d.abs() == e.abs() && v < self.order[w]),
                };
                if better {
                    worst = Some((k, d));
                }
            }
        }
        Ok(worst)
    }

    /// The reduced cost of variable `v` as a minimisation (`σ·d`; a row's is its dual).
    fn reduced_cost(&self, lp: &LinearProgram, v: usize) -> f64 {
        let sigma = if lp.maximise { -1.0 } else { 1.0 };
        let n = lp.num_cols();
        sigma
            * if v < n {
                self.col_dual[v]
            } else {
                self.y[v - n]
            }
    }

    /// Whether every nonbasic reduced cost has its sign within `tol`.
    fn dual_feasible(&self, lp: &LinearProgram, basis: &Basis, tol: f64) -> bool {
        let n = lp.num_cols();
        let ok = |v: usize, s: BasisStatus, lo: f64, hi: f64| {
            let d = self.reduced_cost(lp, v);
            d.is_finite() && dual_sign_ok(s, lo, hi, d, tol)
        };
        (0..n).all(|j| ok(j, basis.cols[j], lp.col_lower[j], lp.col_upper[j]))
            && (0..lp.num_rows())
                .all(|i| ok(n + i, basis.rows[i], lp.row_lower[i], lp.row_upper[i]))
    }

    fn solution(self, lp: &LinearProgram, iterations: i64) -> LpSolution {
        LpSolution {
            status: LpStatus::Optimal,
            objective: lp.objective(&self.x),
            x: self.x,
            row_dual: self.y,
            col_dual: self.col_dual,
            iterations,
            dual_objective: f64::NAN,
            reduced_accuracy: false,
            method: super::Method::DualSimplex,
            tried: Vec::new(),
        }
    }
}

/// The basic solution of `lp` at `basis` and its duals (HiGHS's convention: `c − Aᵀy − z = 0`
/// in the program's own sense), where the basis matrix is nonsingular and the solution is
/// primal and dual feasible within `tol` (absolute, on `lp`'s own numbers, as a simplex
/// judges them); `None` otherwise.
pub fn basic_solution(lp: &LinearProgram, basis: &Basis, tol: f64) -> Option<LpSolution> {
    let v = Vertex::of(lp, basis)?;
    (v.worst(lp, tol) == Ok(None) && v.dual_feasible(lp, basis, tol)).then(|| v.solution(lp, 0))
}

/// The entering variable of a dual simplex pivot on the row of basic position `p`, whose
/// variable is `infeasibility` outside its bounds (below: negative): the bounded dual ratio
/// test over row `p` of `B⁻¹[A −I]`, the smallest ratio `d_j / α̃_j` (ties: the largest
/// `|α_j|`, then the lowest index) among the nonbasic variables that can move the leaving
/// one towards its bound without losing their reduced cost's sign; fixed variables never
/// enter, and pivot elements below 1e-9 of the row's largest (at least 1e-9) are not taken.
/// `None`: no variable can enter (the program is primal infeasible, or the row is round-off).
fn entering(
    lp: &LinearProgram,
    basis: &Basis,
    v: &Vertex,
    p: usize,
    infeasibility: f64,
) -> Option<usize> {
    let (n, m) = (lp.num_cols(), lp.num_rows());
    let mut e = vec![0.0; m];
    e[p] = 1.0;
    let rho = v.lu.solve_transpose(&e);
    if rho.iter().any(|r| !r.is_finite()) {
        return None;
    }
    // α_j for every nonbasic variable that is not fixed (`α̃ = −α` where the leaving variable
    // rises to its lower bound, `α` where it falls to its upper one).
    let sign = if infeasibility < 0.0 { -1.0 } else { 1.0 };
    let mut row: Vec<(usize, BasisStatus, f64)> = Vec::new();
    for j in 0..n {
        let s = basis.cols[j];
        if s == BasisStatus::Basic || lp.col_lower[j] == lp.col_upper[j] {
            continue;
        }
        let a: f64 = lp.column(j).map(|(i, a)| a * rho[i]).sum();
        if a != 0.0 {
            row.push((j, s, sign * a));
        }
    }
    for i in 0..m {
        let s = basis.rows[i];
        if s == BasisStatus::Basic || lp.row_lower[i] == lp.row_upper[i] || rho[i] == 0.0 {
            continue;
        }
        row.push((n + i, s, -sign * rho[i]));
    }
    let largest = row.iter().fold(0.0f64, |a, r| a.max(r.2.abs()));
    if !largest.is_finite() {
        return None;
    }
    let threshold = 1e-9 * largest.max(1.0);
    let mut best: Option<(f64, f64, usize)> = None;
    for &(k, s, a) in &row {
        let moves = match s {
            BasisStatus::Lower => a > threshold,
            BasisStatus::Upper => a < -threshold,
            BasisStatus::Zero => a.abs() > threshold,
            BasisStatus::Basic => false,
        };
        if !moves {
            continue;
        }
        let d = v.reduced_cost(lp, k);
        // Within the tolerance a reduced cost may have the wrong sign: its ratio is 0.
        let ratio = if s == BasisStatus::Zero {
            (d / a).abs()
        } else {
            (d / a).max(0.0)
        };
        let better = match best {
            None => true,
            Some((r, b, q)) => {
                ratio < r || (ratio == r && (a.abs() > b || (a.abs() == b && k < q)))
            }
        };
        if better {
            best = Some((ratio, a.abs(), k));
        }
    }
    best.map(|(_, _, k)| k)
}

/// The optimum of `lp` reached from `basis` by at most `max_pivots` bounded dual simplex
/// pivots (each basis refactorised by [`Lu`]), where `basis` is dual feasible within `tol` and
/// the basis reached is primal and dual feasible within `tol`: that solution (its iterations
/// the pivots taken), the basis reached, and the number of pivots. The leaving variable is the
/// basic one of the largest primal infeasibility (ties: the lowest index), the entering one by
/// the bounded dual ratio test ([`entering`]). `None`: a basis on the way is singular or
/// dual infeasible, no variable can enter, or more pivots would be needed.
pub fn pivoted_solution(
    lp: &LinearProgram,
    basis: &Basis,
    tol: f64,
    max_pivots: usize,
) -> Option<(LpSolution, Basis, usize)> {
    let n = lp.num_cols();
    let mut basis = basis.clone();
    let mut pivots = 0;
    loop {
        let v = Vertex::of(lp, &basis)?;
        if !v.dual_feasible(lp, &basis, tol) {
            return None;
        }
        let Some((p, infeasibility)) = v.worst(lp, tol).ok()? else {
            let s = v.solution(lp, pivots as i64);
            return Some((s, basis, pivots));
        };
        if pivots == max_pivots {
            return None;
        }
        let q = entering(lp, &basis, &v, p, infeasibility)?;
        let leaving = v.order[p];
        let to = if infeasibility < 0.0 {
            BasisStatus::Lower
        } else {
            BasisStatus::Upper
        };
        if leaving < n {
            basis.cols[leaving] = to;
        } else {
            basis.rows[leaving - n] = to;
        }
        if q < n {
            basis.cols[q] = BasisStatus::Basic;
        } else {
            basis.rows[q - n] = BasisStatus::Basic;
        }
        pivots += 1;
    }
}

/// A program answered from a kept basis ([`answer_pivoting`]).
#[derive(Clone, Debug)]
pub struct KeptAnswer {
    pub solution: LpSolution,
    /// The basis of `solution` (the kept one where no pivot was taken).
    pub basis: Basis,
    /// The dual simplex pivots taken from the kept basis.
    pub pivots: usize,
}

/// The optimum of `lp` at the kept `basis` (already [`Basis::adapted`] to `lp`'s bounds), where
/// it is one: the basic solution of the program as the backend would be handed it (equilibrated
/// where [`Scaling::needed`]), feasible in both senses within `opts.feasibility_tolerance`,
/// in the user's units, and certified on `lp` as written by [`policy::check`]. Stated as
/// `opts.method`'s (a simplex method: the answer it returns from this basis after zero
/// iterations). `None`: the backend must run. ([`answer_pivoting`] without pivots.)
pub fn answer(lp: &LinearProgram, opts: &SolverOptions, basis: &Basis) -> Option<LpSolution> {
    answer_pivoting(lp, opts, basis, 0).map(|a| a.solution)
}

/// The optimum of `lp` from the kept `basis` (already [`Basis::adapted`] to `lp`'s bounds)
/// after at most `max_pivots` bounded dual simplex pivots ([`pivoted_solution`]) on the
/// program as the backend would be handed it (equilibrated where [`Scaling::needed`]), where
/// the kept basis is dual feasible and the basis reached is primal and dual feasible, both
/// within `opts.feasibility_tolerance`, and the answer, in the user's units, is certified on
/// `lp` as written by [`policy::check`]. Stated as `opts.method`'s (a simplex method), with
/// the pivots as its iterations. `None`: the backend must run.
pub fn answer_pivoting(
    lp: &LinearProgram,
    opts: &SolverOptions,
    basis: &Basis,
    max_pivots: usize,
) -> Option<KeptAnswer> {
    if !opts.method.is_simplex() {
        return None;
    }
    let tol = opts.feasibility_tolerance;
    let (solution, basis, pivots) = match Scaling::needed(lp, &[]) {
        None => pivoted_solution(lp, basis, tol, max_pivots)?,
        Some(s) => {
            let (solution, basis, pivots) = pivoted_solution(&s.apply(lp), basis, tol, max_pivots)?;
            (s.unscale(solution), basis, pivots)
        }
    };
    let solution = LpSolution {
        method: opts.method,
        ..solution
    };
    policy::check(lp, &solution)
        .is_none()
        .then_some(KeptAnswer {
            solution,
            basis,
            pivots,
        })
}
