//! A solver-neutral sparse linear program and its HiGHS backend.
//!
//! ```text
//!   optimise  cᵀx   (minimise or maximise)
//!   s.t.      row_lower ≤ A x ≤ row_upper
//!             col_lower ≤ x   ≤ col_upper
//! ```
//! `A` is stored by columns (CSC). Every analysis in voussoir builds one of these and hands it to
//! [`solve`]; the backend is HiGHS (dual simplex by default, so that mechanisms are vertex
//! solutions with crisp hinges).

use crate::error::{Error, Result};
use highs::{ColProblem, HighsModelStatus, Sense};
use serde::{Deserialize, Serialize};

/// Optimisation sense.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    Minimise,
    Maximise,
}

/// A sparse LP in column form.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LinearProgram {
    pub maximise: bool,
    pub cost: Vec<f64>,
    pub col_lower: Vec<f64>,
    pub col_upper: Vec<f64>,
    pub row_lower: Vec<f64>,
    pub row_upper: Vec<f64>,
    pub col_start: Vec<usize>,
    pub row_index: Vec<usize>,
    pub value: Vec<f64>,
}

impl LinearProgram {
    pub fn new(direction: Direction) -> Self {
        LinearProgram {
            maximise: direction == Direction::Maximise,
            col_start: vec![0],
            ..Default::default()
        }
    }
    /// Add a row `lo ≤ a·x ≤ hi` (its entries come with the columns); returns its index.
    pub fn add_row(&mut self, lo: f64, hi: f64) -> usize {
        self.row_lower.push(lo);
        self.row_upper.push(hi);
        self.row_lower.len() - 1
    }
    /// Add a column with its cost, bounds and `(row, value)` entries; returns its index.
    pub fn add_column(
        &mut self,
        cost: f64,
        lo: f64,
        hi: f64,
        entries: impl IntoIterator<Item = (usize, f64)>,
    ) -> usize {
        self.cost.push(cost);
        self.col_lower.push(lo);
        self.col_upper.push(hi);
        for (r, v) in entries {
            if v != 0.0 {
                self.row_index.push(r);
                self.value.push(v);
            }
        }
        self.col_start.push(self.row_index.len());
        self.cost.len() - 1
    }
    pub fn num_cols(&self) -> usize {
        self.cost.len()
    }
    pub fn num_rows(&self) -> usize {
        self.row_lower.len()
    }
    pub fn num_nonzeros(&self) -> usize {
        self.value.len()
    }
    /// Entries of column `j`.
    pub fn column(&self, j: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        (self.col_start[j]..self.col_start[j + 1]).map(move |k| (self.row_index[k], self.value[k]))
    }
    /// `A x` (row activities).
    pub fn row_activity(&self, x: &[f64]) -> Vec<f64> {
        let mut r = vec![0.0; self.num_rows()];
        for (j, &xj) in x.iter().enumerate() {
            if xj != 0.0 {
                for (i, v) in self.column(j) {
                    r[i] += v * xj;
                }
            }
        }
        r
    }
}

/// What the solver concluded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LpStatus {
    Optimal,
    Infeasible,
    Unbounded,
}

/// The LP method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Dual simplex: vertex solutions (crisp hinges). The default.
    #[default]
    DualSimplex,
    /// Primal simplex.
    PrimalSimplex,
    /// Interior point followed by crossover to a vertex.
    Ipm,
    /// Let HiGHS choose.
    Choose,
    /// Interior point without crossover: an optimal, generally non-vertex, solution (faster on
    /// large models; the duality gap still certifies it).
    IpmNoCrossover,
    /// First-order primal-dual hybrid gradient (PDLP): low accuracy, for very large models.
    Pdlp,
    /// Clarabel's interior point (direct sparse LDLᵀ factorisation) instead of HiGHS: fast on
    /// large block structures; optimal, generally non-vertex solutions (tolerance:
    /// `feasibility_tolerance`).
    Clarabel,
}

/// Solver settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolverOptions {
    pub method: Method,
    pub presolve: bool,
    /// Seconds; `None` for no limit.
    pub time_limit: Option<f64>,
    /// Primal and dual feasibility tolerance.
    pub feasibility_tolerance: f64,
    pub threads: usize,
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions {
            method: Method::DualSimplex,
            presolve: true,
            time_limit: None,
            feasibility_tolerance: 1e-9,
            threads: 1,
        }
    }
}

/// A solution (primal values and duals); vectors are empty unless `status` is optimal.
#[derive(Clone, Debug, PartialEq)]
pub struct LpSolution {
    pub status: LpStatus,
    pub objective: f64,
    pub x: Vec<f64>,
    pub row_dual: Vec<f64>,
    pub col_dual: Vec<f64>,
    pub iterations: i64,
}

fn opt<V: highs::HighsOptionValue>(m: &mut highs::Model, k: &str, v: V) -> Result<()> {
    m.try_set_option(k, v)
        .map_err(|e| Error::Solver(format!("HiGHS option {k}: {e:?}")))
}

pub(crate) fn configure(m: &mut highs::Model, o: &SolverOptions) -> Result<()> {
    m.make_quiet();
    opt(m, "output_flag", false)?;
    opt(m, "presolve", if o.presolve { "on" } else { "off" })?;
    match o.method {
        Method::DualSimplex => {
            opt(m, "solver", "simplex")?;
            opt(m, "simplex_strategy", 1)?;
        }
        Method::PrimalSimplex => {
            opt(m, "solver", "simplex")?;
            opt(m, "simplex_strategy", 4)?;
        }
        Method::Ipm => {
            opt(m, "solver", "ipm")?;
            opt(m, "run_crossover", "on")?;
        }
        Method::Choose => opt(m, "solver", "choose")?,
        Method::IpmNoCrossover => {
            opt(m, "solver", "ipm")?;
            opt(m, "run_crossover", "off")?;
        }
        Method::Pdlp => opt(m, "solver", "pdlp")?,
        Method::Clarabel => opt(m, "solver", "ipm")?,
    }
    opt(m, "primal_feasibility_tolerance", o.feasibility_tolerance)?;
    opt(m, "dual_feasibility_tolerance", o.feasibility_tolerance)?;
    opt(m, "threads", o.threads.max(1) as i32)?;
    opt(m, "random_seed", 0)?;
    if let Some(t) = o.time_limit {
        opt(m, "time_limit", t)?;
    }
    // Diagnostics: VOUSSOIR_HIGHS_LOG=1 prints HiGHS's own log on stdout.
    if std::env::var_os("VOUSSOIR_HIGHS_LOG").is_some_and(|v| v == "1") {
        opt(m, "output_flag", true)?;
        opt(m, "log_to_console", true)?;
    }
    Ok(())
}

pub(crate) fn build(lp: &LinearProgram) -> highs::Model {
    let mut p = ColProblem::default();
    let rows: Vec<highs::Row> = (0..lp.num_rows())
        .map(|i| p.add_row(lp.row_lower[i]..=lp.row_upper[i]))
        .collect();
    for j in 0..lp.num_cols() {
        let entries: Vec<(highs::Row, f64)> = lp.column(j).map(|(i, v)| (rows[i], v)).collect();
        p.add_column(lp.cost[j], lp.col_lower[j]..=lp.col_upper[j], entries);
    }
    p.optimise(if lp.maximise {
        Sense::Maximise
    } else {
        Sense::Minimise
    })
}

/// Solve `lp`. Infeasible and unbounded are statuses, not errors. An "unbounded or infeasible"
/// answer from presolve is settled by solving again without presolve.
pub fn solve(lp: &LinearProgram, o: &SolverOptions) -> Result<LpSolution> {
    if o.method == Method::Clarabel {
        return solve_clarabel(lp, o);
    }
    for b in lp
        .row_lower
        .iter()
        .chain(&lp.row_upper)
        .chain(&lp.col_lower)
        .chain(&lp.col_upper)
    {
        if b.is_nan() {
            return Err(Error::Solver("the LP has a NaN bound".into()));
        }
    }
    if lp.cost.iter().chain(&lp.value).any(|v| !v.is_finite()) {
        return Err(Error::Solver(
            "the LP has a coefficient that is not finite".into(),
        ));
    }
    let mut opts = *o;
    loop {
        let mut m = build(lp);
        configure(&mut m, &opts)?;
        let solved = m
            .try_solve()
            .map_err(|e| Error::Solver(format!("HiGHS run failed: {e:?}")))?;
        let status = solved.status();
        let status = match status {
            HighsModelStatus::Optimal => LpStatus::Optimal,
            HighsModelStatus::Infeasible => LpStatus::Infeasible,
            HighsModelStatus::Unbounded => LpStatus::Unbounded,
            HighsModelStatus::UnboundedOrInfeasible if opts.presolve => {
                opts.presolve = false;
                continue;
            }
            HighsModelStatus::ModelEmpty => LpStatus::Optimal,
            other => {
                return Err(Error::Solver(format!(
                    "HiGHS stopped with status {other:?}"
                )))
            }
        };
        if status != LpStatus::Optimal {
            return Ok(LpSolution {
                status,
                objective: f64::NAN,
                x: vec![],
                row_dual: vec![],
                col_dual: vec![],
                iterations: solved.simplex_iteration_count(),
            });
        }
        let s = solved.get_solution();
        return Ok(LpSolution {
            status,
            objective: solved.objective_value(),
            x: s.columns().to_vec(),
            row_dual: s.dual_rows().to_vec(),
            col_dual: s.dual_columns().to_vec(),
            iterations: solved.simplex_iteration_count() + solved.ipm_iteration_count(),
        });
    }
}

/// Solve with Clarabel: `min cᵀx` with `A x + s = b`, `s` in the zero cone (equality rows and
/// fixed variables) or the non-negative cone (each finite side of a range row or bound). Row
/// duals are returned with HiGHS's convention (`c − Aᵀy` are the reduced costs of a
/// minimisation; negated for a maximisation).
fn solve_clarabel(lp: &LinearProgram, o: &SolverOptions) -> Result<LpSolution> {
    // Identical columns (same entries, cost and bounds, each free or non-negative) are one
    // variable for the solver: in the force LP the two shear forces of a straight joint have
    // the same column. The merged value goes to the first of them.
    let (reduced, map) = merge_duplicate_columns(lp);
    let mut sol = solve_clarabel_with_cones(&reduced, o, &[])?;
    if sol.status == LpStatus::Optimal {
        let mut x = vec![0.0; lp.num_cols()];
        let mut col_dual = vec![0.0; lp.num_cols()];
        let mut first = vec![true; reduced.num_cols()];
        for (j, &r) in map.iter().enumerate() {
            if first[r] {
                x[j] = sol.x[r];
                first[r] = false;
            }
            col_dual[j] = sol.col_dual[r];
        }
        sol.x = x;
        sol.col_dual = col_dual;
    }
    Ok(sol)
}

/// The LP with duplicate columns merged, and the reduced column of every original column.
fn merge_duplicate_columns(lp: &LinearProgram) -> (LinearProgram, Vec<usize>) {
    use std::collections::HashMap;
    let mergeable = |j: usize| {
        lp.col_upper[j] == f64::INFINITY
            && (lp.col_lower[j] == 0.0 || lp.col_lower[j] == f64::NEG_INFINITY)
    };
    let mut seen: HashMap<Vec<u64>, usize> = HashMap::new();
    let mut out = LinearProgram {
        maximise: lp.maximise,
        col_start: vec![0],
        ..Default::default()
    };
    out.row_lower = lp.row_lower.clone();
    out.row_upper = lp.row_upper.clone();
    let mut map = Vec::with_capacity(lp.num_cols());
    for j in 0..lp.num_cols() {
        let key: Option<Vec<u64>> = mergeable(j).then(|| {
            let mut k = vec![lp.cost[j].to_bits(), lp.col_lower[j].to_bits()];
            for (i, v) in lp.column(j) {
                k.push(i as u64);
                k.push(v.to_bits());
            }
            k
        });
        if let Some(&r) = key.as_ref().and_then(|k| seen.get(k)) {
            map.push(r);
            continue;
        }
        let r = out.add_column(lp.cost[j], lp.col_lower[j], lp.col_upper[j], lp.column(j));
        if let Some(k) = key {
            seen.insert(k, r);
        }
        map.push(r);
    }
    (out, map)
}

/// A second-order cone over three affine rows `s_i = b_i − a_iᵀx`: `‖(s_1, s_2)‖ ≤ s_0`.
pub type Cone3 = [(Vec<(usize, f64)>, f64); 3];

/// Solve `lp` with Clarabel, with extra second-order cones appended (none for a plain LP).
pub(crate) fn solve_clarabel_with_cones(
    lp: &LinearProgram,
    o: &SolverOptions,
    socs: &[Cone3],
) -> Result<LpSolution> {
    use clarabel::algebra::CscMatrix;
    use clarabel::solver::{
        DefaultSettings, DefaultSolver, IPSolver, SolverStatus, SupportedConeT,
    };
    let sign = if lp.maximise { -1.0 } else { 1.0 };
    let n = lp.num_cols();
    let mut rows: Vec<Vec<(usize, f64)>> = vec![Vec::new(); lp.num_rows()];
    for j in 0..n {
        for (i, v) in lp.column(j) {
            rows[i].push((j, v));
        }
    }
    // (entries, rhs, lp row or usize::MAX, sign of the row in the LP's A x)
    let mut zero: Vec<(Vec<(usize, f64)>, f64, usize)> = Vec::new();
    let mut nonneg: Vec<(Vec<(usize, f64)>, f64, usize, f64)> = Vec::new();
    for (i, r) in rows.into_iter().enumerate() {
        let (lo, hi) = (lp.row_lower[i], lp.row_upper[i]);
        if lo == hi {
            zero.push((r, hi, i));
            continue;
        }
        if hi < f64::INFINITY {
            nonneg.push((r.clone(), hi, i, 1.0));
        }
        if lo > f64::NEG_INFINITY {
            nonneg.push((r.iter().map(|&(j, v)| (j, -v)).collect(), -lo, i, -1.0));
        }
    }
    for j in 0..n {
        let (lo, hi) = (lp.col_lower[j], lp.col_upper[j]);
        if lo == hi {
            zero.push((vec![(j, 1.0)], lo, usize::MAX));
            continue;
        }
        if lo > f64::NEG_INFINITY {
            nonneg.push((vec![(j, -1.0)], -lo, usize::MAX, 0.0));
        }
        if hi < f64::INFINITY {
            nonneg.push((vec![(j, 1.0)], hi, usize::MAX, 0.0));
        }
    }
    let (mut ii, mut jj, mut vv, mut b) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (r, rhs) in zero
        .iter()
        .map(|z| (&z.0, z.1))
        .chain(nonneg.iter().map(|z| (&z.0, z.1)))
        .chain(socs.iter().flat_map(|c| c.iter().map(|(r, b)| (r, *b))))
    {
        let k = b.len();
        for &(j, v) in r {
            ii.push(k);
            jj.push(j);
            vv.push(v);
        }
        b.push(rhs);
    }
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
    cones.extend(socs.iter().map(|_| SupportedConeT::SecondOrderConeT(3)));
    let tol = o.feasibility_tolerance.clamp(1e-12, 1e-4);
    let settings = DefaultSettings {
        verbose: std::env::var_os("VOUSSOIR_HIGHS_LOG").is_some_and(|v| v == "1"),
        tol_gap_abs: tol,
        tol_gap_rel: tol,
        tol_feas: tol,
        time_limit: o.time_limit.unwrap_or(f64::INFINITY),
        max_iter: 500,
        direct_solve_method: "qdldl".to_string(),
        ..DefaultSettings::default()
    };
    let mut solver = DefaultSolver::new(&p, &q, &a, &b, &cones, settings)
        .map_err(|e| Error::Solver(format!("Clarabel setup: {e:?}")))?;
    solver.solve();
    let sol = &solver.solution;
    let status = match sol.status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => LpStatus::Optimal,
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => {
            LpStatus::Infeasible
        }
        SolverStatus::DualInfeasible | SolverStatus::AlmostDualInfeasible => LpStatus::Unbounded,
        other => return Err(Error::Solver(format!("Clarabel stopped: {other:?}"))),
    };
    let iterations = sol.iterations as i64;
    if status != LpStatus::Optimal {
        return Ok(LpSolution {
            status,
            objective: f64::NAN,
            x: vec![],
            row_dual: vec![],
            col_dual: vec![],
            iterations,
        });
    }
    // Clarabel's z ≥ 0 multiplies `A x + s = b` in `min qᵀx`: q + Aᵀz = 0 in its convention, so the
    // multiplier of LP row i (HiGHS: c − Aᵀy = reduced costs) is y = −z (rows as written) or +z
    // (rows negated for a lower bound).
    let mut row_dual = vec![0.0; lp.num_rows()];
    for (k, zr) in zero.iter().enumerate() {
        if zr.2 != usize::MAX {
            row_dual[zr.2] = -sign * sol.z[k];
        }
    }
    for (k, nr) in nonneg.iter().enumerate() {
        if nr.2 != usize::MAX {
            row_dual[nr.2] += -sign * nr.3 * sol.z[zero.len() + k];
        }
    }
    let x = sol.x.clone();
    let mut col_dual = lp.cost.clone();
    for j in 0..n {
        for (i, v) in lp.column(j) {
            col_dual[j] -= v * row_dual[i];
        }
    }
    let objective: f64 = lp.cost.iter().zip(&x).map(|(c, v)| c * v).sum();
    Ok(LpSolution {
        status,
        objective,
        x,
        row_dual,
        col_dual,
        iterations,
    })
}

/// max x + y  s.t. x + 2y ≤ 4, 3x + y ≤ 6, x, y ≥ 0  → x = 1.6, y = 1.2, obj 2.8 (by hand).
#[cfg(test)]
fn tiny_lp() -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Maximise);
    let r0 = lp.add_row(f64::NEG_INFINITY, 4.0);
    let r1 = lp.add_row(f64::NEG_INFINITY, 6.0);
    lp.add_column(1.0, 0.0, f64::INFINITY, [(r0, 1.0), (r1, 3.0)]);
    lp.add_column(1.0, 0.0, f64::INFINITY, [(r0, 2.0), (r1, 1.0)]);
    lp
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tiny_lp_and_duals() {
        let lp = tiny_lp();
        let s = solve(&lp, &SolverOptions::default()).unwrap();
        assert_eq!(s.status, LpStatus::Optimal);
        assert!((s.objective - 2.8).abs() < 1e-9);
        // Duals: y0 = 0.4, y1 = 0.2 (shadow prices), up to HiGHS's sign convention.
        assert!((s.row_dual[0].abs() - 0.4).abs() < 1e-9);
        assert!((s.row_dual[1].abs() - 0.2).abs() < 1e-9);
    }

    #[test]
    fn unbounded_and_infeasible_are_statuses() {
        let mut lp = LinearProgram::new(Direction::Maximise);
        let r = lp.add_row(0.0, f64::INFINITY);
        lp.add_column(1.0, 0.0, f64::INFINITY, [(r, 1.0)]);
        assert_eq!(
            solve(&lp, &SolverOptions::default()).unwrap().status,
            LpStatus::Unbounded
        );
        let mut lp = LinearProgram::new(Direction::Minimise);
        let r = lp.add_row(1.0, 1.0);
        lp.add_column(1.0, 0.0, f64::INFINITY, [(r, -1.0)]);
        assert_eq!(
            solve(&lp, &SolverOptions::default()).unwrap().status,
            LpStatus::Infeasible
        );
    }
}

#[cfg(test)]
mod clarabel_tests {
    use super::*;

    #[test]
    fn clarabel_matches_highs_on_a_tiny_lp_with_duals() {
        let lp = tiny_lp();
        let h = solve(&lp, &SolverOptions::default()).unwrap();
        let c = solve(
            &lp,
            &SolverOptions {
                method: Method::Clarabel,
                ..SolverOptions::default()
            },
        )
        .unwrap();
        assert_eq!(c.status, LpStatus::Optimal);
        assert!((c.objective - 2.8).abs() < 1e-7);
        for i in 0..2 {
            assert!(
                (c.row_dual[i] - h.row_dual[i]).abs() < 1e-6,
                "{:?} {:?}",
                c.row_dual,
                h.row_dual
            );
        }
        // An equality-constrained minimisation: min 2a + b, a + b = 1, a, b ≥ 0 → b = 1, y = 1.
        let mut lp = LinearProgram::new(Direction::Minimise);
        let r = lp.add_row(1.0, 1.0);
        lp.add_column(2.0, 0.0, f64::INFINITY, [(r, 1.0)]);
        lp.add_column(1.0, 0.0, f64::INFINITY, [(r, 1.0)]);
        let h = solve(&lp, &SolverOptions::default()).unwrap();
        let c = solve(
            &lp,
            &SolverOptions {
                method: Method::Clarabel,
                ..SolverOptions::default()
            },
        )
        .unwrap();
        assert!(
            (c.objective - 1.0).abs() < 1e-7 && (c.row_dual[0] - h.row_dual[0]).abs() < 1e-6,
            "{:?} {:?}",
            c.row_dual,
            h.row_dual
        );
    }
}
