//! The HiGHS backend (through the `highs` crate; warm starts through `highs-sys`): dual and
//! primal simplex, interior point with or without crossover, PDLP. The only file that names
//! HiGHS.

use super::{
    Backend, Basis, BasisStatus, Cone3, LinearProgram, LpSolution, LpStatus, Method, Solved,
    SolverOptions,
};
use crate::error::{Error, Result};
use highs::{ColProblem, HighsModelStatus, Sense};

/// The HiGHS backend.
pub struct Highs;

fn opt<V: highs::HighsOptionValue>(m: &mut highs::Model, k: &str, v: V) -> Result<()> {
    m.try_set_option(k, v)
        .map_err(|e| Error::Solver(format!("HiGHS option {k}: {e:?}")))
}

/// The words of [`Error::Undecided`]: a HiGHS run that ended "unbounded or infeasible" without
/// presolve (its interior point's sign of a program without an optimum, not a decision between
/// the two); the fallback chain asks Clarabel next, whose answer comes with a certificate
/// either way ([`super::with_fallback`]).
pub const UNDECIDED: &str =
    "HiGHS found the program unbounded or infeasible without deciding which";

/// The settings every HiGHS run shares: quiet unless `o.log`, deterministic, `o.threads`, and
/// the feasibility tolerances `tol`.
fn common(m: &mut highs::Model, o: &SolverOptions, tol: f64) -> Result<()> {
    m.make_quiet();
    opt(m, "output_flag", o.log)?;
    if o.log {
        opt(m, "log_to_console", true)?;
    }
    opt(m, "random_seed", 0)?;
    opt(m, "threads", o.threads.max(1) as i32)?;
    opt(m, "primal_feasibility_tolerance", tol)?;
    opt(m, "dual_feasibility_tolerance", tol)
}

fn configure(m: &mut highs::Model, o: &SolverOptions) -> Result<()> {
    common(m, o, o.feasibility_tolerance)?;
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
            // Where the interior point finds the program primal or dual infeasible, HiGHS would
            // otherwise "clean up" with the simplex from scratch: on the README vault with μ =
            // 0.3 (unbounded: it cannot stand) IPX said so in 1.7 s and the clean-up then ran
            // 24 s into "Solve error". The answer is handed on instead ([`UNDECIDED`]).
            opt(m, "allow_unbounded_or_infeasible", true)?;
        }
        Method::Choose => opt(m, "solver", "choose")?,
        Method::IpmNoCrossover => {
            opt(m, "solver", "ipm")?;
            opt(m, "run_crossover", "off")?;
        }
        Method::Pdlp => opt(m, "solver", "pdlp")?,
        Method::Clarabel | Method::ClarabelVertex => {
            return Err(Error::Solver(
                "the HiGHS backend was handed a Clarabel method".into(),
            ))
        }
    }
    if let Some(t) = o.time_limit {
        opt(m, "time_limit", t)?;
    }
    if let Some(n) = o.iteration_limit {
        let n = n.min(i32::MAX as usize) as i32;
        opt(m, "simplex_iteration_limit", n)?;
        opt(m, "ipm_iteration_limit", n)?;
    }
    Ok(())
}

/// The HiGHS model of `lp`; HiGHS's refusal (for example a coefficient beyond its infinity,
/// 1e20) is a one-line error, never a panic.
fn build(lp: &LinearProgram) -> Result<highs::Model> {
    let mut p = ColProblem::default();
    let rows: Vec<highs::Row> = (0..lp.num_rows())
        .map(|i| p.add_row(lp.row_lower[i]..=lp.row_upper[i]))
        .collect();
    for j in 0..lp.num_cols() {
        let entries: Vec<(highs::Row, f64)> = lp.column(j).map(|(i, v)| (rows[i], v)).collect();
        p.add_column(lp.cost[j], lp.col_lower[j]..=lp.col_upper[j], entries);
    }
    p.try_optimise(if lp.maximise {
        Sense::Maximise
    } else {
        Sense::Minimise
    })
    .map_err(|e| {
        Error::Solver(format!(
            "HiGHS refused the program ({e:?}): a number in the model is too large for the solver"
        ))
    })
}

fn to_highs(s: BasisStatus) -> i32 {
    match s {
        BasisStatus::Lower => highs_sys::kHighsBasisStatusLower,
        BasisStatus::Basic => highs_sys::kHighsBasisStatusBasic,
        BasisStatus::Upper => highs_sys::kHighsBasisStatusUpper,
        BasisStatus::Zero => highs_sys::kHighsBasisStatusZero,
    }
}

fn from_highs(s: i32) -> BasisStatus {
    if s == highs_sys::kHighsBasisStatusBasic {
        BasisStatus::Basic
    } else if s == highs_sys::kHighsBasisStatusUpper {
        BasisStatus::Upper
    } else if s == highs_sys::kHighsBasisStatusZero {
        BasisStatus::Zero
    } else {
        BasisStatus::Lower
    }
}

impl Backend for Highs {
    fn name(&self) -> &'static str {
        "highs"
    }

    fn supports_cones(&self) -> bool {
        false
    }

    /// Infeasible and unbounded are statuses; an "unbounded or infeasible" answer from presolve
    /// is settled by solving again without presolve. With a starting basis, presolve is off
    /// (it would discard the basis), and a failed warm run is repeated from scratch.
    fn solve(
        &self,
        lp: &LinearProgram,
        cones: &[Cone3],
        o: &SolverOptions,
        start: Option<&Basis>,
    ) -> Result<Solved> {
        if !cones.is_empty() {
            return Err(Error::Solver("HiGHS does not take cone constraints".into()));
        }
        let mut opts = *o;
        let mut start = start.filter(|_| o.method.is_simplex());
        let mut spent = 0i64;
        loop {
            let mut m = build(lp)?;
            let warm = start.is_some();
            if warm {
                opts.presolve = false;
            }
            configure(&mut m, &opts)?;
            if let Some(b) = start {
                let cs: Vec<i32> = b.cols.iter().map(|&s| to_highs(s)).collect();
                let rs: Vec<i32> = b.rows.iter().map(|&s| to_highs(s)).collect();
                // SAFETY: the pointer is the live HiGHS instance owned by `m`; the arrays have
                // exactly num_col and num_row entries (checked by `lp::solve_warm`).
                let ok =
                    unsafe { highs_sys::Highs_setBasis(m.as_mut_ptr(), cs.as_ptr(), rs.as_ptr()) };
                if ok == highs_sys::kHighsStatusError {
                    start = None;
                    opts.presolve = o.presolve;
                    continue;
                }
            }
            let solved = match m.try_solve() {
                Ok(s) => s,
                Err(_) if warm => {
                    start = None;
                    opts.presolve = o.presolve;
                    continue;
                }
                Err(e) => return Err(Error::Solver(format!("HiGHS run failed: {e:?}"))),
            };
            let iterations =
                spent + solved.simplex_iteration_count() + solved.ipm_iteration_count();
            let status = match solved.status() {
                HighsModelStatus::Optimal => LpStatus::Optimal,
                HighsModelStatus::Infeasible => LpStatus::Infeasible,
                HighsModelStatus::Unbounded => LpStatus::Unbounded,
                HighsModelStatus::UnboundedOrInfeasible if opts.presolve => {
                    opts.presolve = false;
                    spent = iterations;
                    continue;
                }
                HighsModelStatus::ModelEmpty => LpStatus::Optimal,
                HighsModelStatus::UnboundedOrInfeasible if !warm => return Err(Error::Undecided),
                _ if warm => {
                    // Anything unusual from a warm start: solve again from scratch.
                    start = None;
                    opts.presolve = o.presolve;
                    spent = iterations;
                    continue;
                }
                other => {
                    return Err(Error::Solver(format!(
                        "HiGHS stopped with status {other:?}"
                    )))
                }
            };
            if status != LpStatus::Optimal {
                return Ok(Solved {
                    solution: LpSolution {
                        status,
                        objective: f64::NAN,
                        x: vec![],
                        row_dual: vec![],
                        col_dual: vec![],
                        iterations,
                        dual_objective: f64::NAN,
                        reduced_accuracy: false,
                        method: o.method,
                        tried: Vec::new(),
                    },
                    basis: None,
                });
            }
            let s = solved.get_solution();
            let solution = LpSolution {
                status,
                objective: solved.objective_value(),
                x: s.columns().to_vec(),
                row_dual: s.dual_rows().to_vec(),
                col_dual: s.dual_columns().to_vec(),
                iterations,
                dual_objective: f64::NAN,
                reduced_accuracy: false,
                method: o.method,
                tried: Vec::new(),
            };
            // The final basis: the simplex's, and the one HiGHS's interior point leaves after
            // crossover (a vertex: the next program of the same shape starts from it,
            // `analysis::canonical`). Only a basis HiGHS calls valid (none without crossover).
            let basis = if o.method.is_simplex() || matches!(o.method, Method::Ipm | Method::Choose)
            {
                let mut cs = vec![0i32; lp.num_cols()];
                let mut rs = vec![0i32; lp.num_rows()];
                let mut valid = 0 as highs_sys::HighsInt;
                // SAFETY: as above; HiGHS fills exactly num_col and num_row entries.
                let got = unsafe {
                    let mut m: highs::Model = solved.into();
                    let p = m.as_mut_ptr();
                    highs_sys::Highs_getIntInfoValue(p, c"basis_validity".as_ptr(), &mut valid);
                    highs_sys::Highs_getBasis(p, cs.as_mut_ptr(), rs.as_mut_ptr())
                };
                (got != highs_sys::kHighsStatusError
                    && valid == highs_sys::kHighsBasisValidityValid)
                    .then(|| Basis {
                        cols: cs.into_iter().map(from_highs).collect(),
                        rows: rs.into_iter().map(from_highs).collect(),
                    })
            } else {
                None
            };
            return Ok(Solved { solution, basis });
        }
    }
}

/// HiGHS's presolve as a service to a backend that has none (Clarabel): the reduced program,
/// and the way back from its solution to one of the original program (HiGHS's postsolve,
/// which takes a primal-dual pair without a basis, as from an interior point).
pub struct Presolved {
    model: highs::Model,
    /// The reduced program.
    pub lp: LinearProgram,
}

/// Presolve `lp` with HiGHS. `None` when presolve did not reduce it, or concluded on its own
/// (infeasible, unbounded, an error): the caller then solves `lp` as it is, so that such a
/// conclusion comes from the solver on the original program.
pub fn presolve(lp: &LinearProgram, o: &SolverOptions) -> Result<Option<Presolved>> {
    use highs_sys::*;
    let mut model = build(lp)?;
    // HiGHS takes tolerances of 1e-10 and more; the interior point after it may be asked for less.
    common(&mut model, o, o.feasibility_tolerance.clamp(1e-10, 1e-4))?;
    if o.log {
        opt(&mut model, "presolve_rule_logging", true)?;
    }
    opt(&mut model, "presolve", "on")?;
    let p = model.as_mut_ptr();
    // SAFETY: `p` is the live HiGHS instance owned by `model`; the arrays handed to
    // Highs_getPresolvedLp have the sizes HiGHS reports for the presolved program.
    unsafe {
        if Highs_presolve(p) != kHighsStatusOk || Highs_getModelStatus(p) != kHighsModelStatusNotset
        {
            return Ok(None);
        }
        let (nc, nr, nz) = (
            Highs_getPresolvedNumCol(p),
            Highs_getPresolvedNumRow(p),
            Highs_getPresolvedNumNz(p),
        );
        if nc <= 0 || (nc as usize == lp.num_cols() && nr as usize == lp.num_rows()) {
            return Ok(None);
        }
        let (ncu, nru, nzu) = (nc as usize, nr as usize, nz as usize);
        let (mut c, mut cl, mut cu) = (vec![0.0; ncu], vec![0.0; ncu], vec![0.0; ncu]);
        let (mut rl, mut ru) = (vec![0.0; nru], vec![0.0; nru]);
        let mut start = vec![0 as HighsInt; ncu + 1];
        let (mut index, mut value) = (vec![0 as HighsInt; nzu], vec![0.0; nzu]);
        let (mut gc, mut gr, mut gz, mut sense, mut offset) = (0, 0, 0, 0, 0.0);
        let got = Highs_getPresolvedLp(
            p,
            kHighsMatrixFormatColwise,
            &mut gc,
            &mut gr,
            &mut gz,
            &mut sense,
            &mut offset,
            c.as_mut_ptr(),
            cl.as_mut_ptr(),
            cu.as_mut_ptr(),
            rl.as_mut_ptr(),
            ru.as_mut_ptr(),
            start.as_mut_ptr(),
            index.as_mut_ptr(),
            value.as_mut_ptr(),
            std::ptr::null_mut(),
        );
        if got == kHighsStatusError || gc != nc || gr != nr || gz != nz {
            return Ok(None);
        }
        start[ncu] = nz;
        let reduced = LinearProgram {
            maximise: sense == kHighsObjSenseMaximize,
            cost: c,
            col_lower: cl,
            col_upper: cu,
            row_lower: rl,
            row_upper: ru,
            col_start: start.into_iter().map(|s| s as usize).collect(),
            row_index: index.into_iter().map(|i| i as usize).collect(),
            value,
        };
        Ok(Some(Presolved { model, lp: reduced }))
    }
}

impl Presolved {
    /// The solution of the original program from an optimal one of the reduced program (its
    /// objective recomputed on the original; no dual objective, as from HiGHS's own solves).
    /// `None` when HiGHS cannot postsolve it.
    pub fn postsolve(mut self, original: &LinearProgram, s: &LpSolution) -> Option<LpSolution> {
        use highs_sys::*;
        let p = self.model.as_mut_ptr();
        let (n, m) = (original.num_cols(), original.num_rows());
        let (mut x, mut cd, mut rv, mut rd) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; m], vec![0.0; m]);
        // SAFETY: `p` is the live HiGHS instance that presolved `original`; the solution has
        // the reduced program's sizes (checked) and the output arrays the original's.
        unsafe {
            if s.x.len() != self.lp.num_cols()
                || s.col_dual.len() != self.lp.num_cols()
                || s.row_dual.len() != self.lp.num_rows()
                || Highs_postsolve(p, s.x.as_ptr(), s.col_dual.as_ptr(), s.row_dual.as_ptr())
                    == kHighsStatusError
                || Highs_getSolution(
                    p,
                    x.as_mut_ptr(),
                    cd.as_mut_ptr(),
                    rv.as_mut_ptr(),
                    rd.as_mut_ptr(),
                ) == kHighsStatusError
            {
                return None;
            }
        }
        Some(LpSolution {
            status: LpStatus::Optimal,
            objective: original.objective(&x),
            x,
            row_dual: rd,
            col_dual: cd,
            iterations: s.iterations,
            dual_objective: f64::NAN,
            reduced_accuracy: s.reduced_accuracy,
            method: s.method,
            tried: s.tried.clone(),
        })
    }
}

/// One HiGHS instance kept across a sequence of programs with one constraint matrix
/// ([`crate::lp::sequence`]): the costs and the bounds change between runs, and each run
/// starts from the basis and factorisation the previous one left. After the first run
/// (`method` as requested, presolve as requested) HiGHS's simplex is left to choose its
/// strategy: primal simplex where the kept basis is still primal feasible (a changed
/// objective), dual simplex where it is not (changed bounds).
pub struct Persistent {
    model: highs::Model,
    cols: usize,
    rows: usize,
    /// Whether a run has left a basis to start from.
    warm: bool,
    method: Method,
    /// Whether bounds changed since the last run (the dual simplex then restarts; after a
    /// change of costs alone, the primal simplex).
    bounds_changed: bool,
    /// Simplex iterations allowed to a run from a kept basis (`None`: HiGHS's own limit).
    warm_limit: Option<usize>,
}

impl Persistent {
    /// The instance of `lp` (minimised or maximised as `lp` says), configured for `o`.
    pub fn new(lp: &LinearProgram, o: &SolverOptions) -> Result<Persistent> {
        if matches!(o.method, Method::Clarabel | Method::ClarabelVertex) {
            return Err(Error::Solver(
                "the HiGHS backend was handed the Clarabel method".into(),
            ));
        }
        let mut model = build(lp)?;
        configure(&mut model, o)?;
        Ok(Persistent {
            model,
            cols: lp.num_cols(),
            rows: lp.num_rows(),
            warm: false,
            method: o.method,
            bounds_changed: false,
            warm_limit: None,
        })
    }

    /// Stop a run from a kept basis after `n` simplex iterations (it then fails, and the
    /// caller goes on otherwise): a warm start is worth it only when it is short.
    pub fn limit_warm_iterations(&mut self, n: Option<usize>) {
        self.warm_limit = n;
    }

    /// Whether the next run starts from a kept basis.
    pub fn is_warm(&self) -> bool {
        self.warm
    }

    /// Start the next run from `b` (a basis of a program of this shape, its nonbasic statuses
    /// fitting the bounds: [`Basis::adapted`]) with HiGHS's simplex: the dual simplex with
    /// `dual` (a basis that is dual feasible: the program's bounds or matrix changed), the
    /// primal simplex otherwise (its objective changed). A basis HiGHS refuses is left out
    /// (the run is then from scratch).
    pub fn set_basis(&mut self, b: &Basis, dual: bool) -> Result<()> {
        if b.cols.len() != self.cols || b.rows.len() != self.rows {
            return Ok(());
        }
        let cs: Vec<i32> = b.cols.iter().map(|&s| to_highs(s)).collect();
        let rs: Vec<i32> = b.rows.iter().map(|&s| to_highs(s)).collect();
        // SAFETY: the live instance owned by `self.model`; the arrays have num_col and num_row
        // entries.
        let ok =
            unsafe { highs_sys::Highs_setBasis(self.model.as_mut_ptr(), cs.as_ptr(), rs.as_ptr()) };
        if ok != highs_sys::kHighsStatusError {
            opt(&mut self.model, "solver", "simplex")?;
            opt(&mut self.model, "presolve", "off")?;
            self.warm = true;
            self.bounds_changed = dual;
        }
        Ok(())
    }

    /// The primal ray HiGHS holds after a run that ended "unbounded" (a direction along which
    /// the objective decreases without end), in the instance's own (scaled) columns; `None`
    /// where it has none. Call it only after an unbounded run: otherwise HiGHS would solve
    /// another program to look for one.
    pub fn primal_ray(&mut self) -> Option<Vec<f64>> {
        let mut has = 0 as highs_sys::HighsInt;
        let mut ray = vec![0.0; self.cols];
        // SAFETY: the live instance owned by `self.model`; `ray` has num_col entries.
        let ok = unsafe {
            highs_sys::Highs_getPrimalRay(self.model.as_mut_ptr(), &mut has, ray.as_mut_ptr())
        };
        (ok != highs_sys::kHighsStatusError && has != 0 && ray.iter().all(|v| v.is_finite()))
            .then_some(ray)
    }

    fn check(&self, what: &str, status: i32) -> Result<()> {
        if status == highs_sys::kHighsStatusError {
            Err(Error::Solver(format!("HiGHS refused the change of {what}")))
        } else {
            Ok(())
        }
    }

    /// New costs for every column (the sense stays the one the program was built with).
    pub fn set_costs(&mut self, cost: &[f64]) -> Result<()> {
        if cost.len() != self.cols {
            return Err(Error::Solver("new costs do not fit the program".into()));
        }
        if self.cols == 0 {
            return Ok(());
        }
        // SAFETY: the pointer is the live instance owned by `self.model`; `cost` has num_col
        // entries.
        let s = unsafe {
            highs_sys::Highs_changeColsCostByRange(
                self.model.as_mut_ptr(),
                0,
                self.cols as highs_sys::HighsInt - 1,
                cost.as_ptr(),
            )
        };
        self.check("costs", s)
    }

    /// New bounds for every column.
    pub fn set_col_bounds(&mut self, lower: &[f64], upper: &[f64]) -> Result<()> {
        if lower.len() != self.cols || upper.len() != self.cols {
            return Err(Error::Solver("new bounds do not fit the program".into()));
        }
        if self.cols == 0 {
            return Ok(());
        }
        // SAFETY: as in `set_costs`.
        let s = unsafe {
            highs_sys::Highs_changeColsBoundsByRange(
                self.model.as_mut_ptr(),
                0,
                self.cols as highs_sys::HighsInt - 1,
                lower.as_ptr(),
                upper.as_ptr(),
            )
        };
        self.bounds_changed = true;
        self.check("column bounds", s)
    }

    /// New bounds for every row.
    pub fn set_row_bounds(&mut self, lower: &[f64], upper: &[f64]) -> Result<()> {
        if lower.len() != self.rows || upper.len() != self.rows {
            return Err(Error::Solver("new bounds do not fit the program".into()));
        }
        if self.rows == 0 {
            return Ok(());
        }
        // SAFETY: as in `set_costs`, with num_row entries.
        let s = unsafe {
            highs_sys::Highs_changeRowsBoundsByRange(
                self.model.as_mut_ptr(),
                0,
                self.rows as highs_sys::HighsInt - 1,
                lower.as_ptr(),
                upper.as_ptr(),
            )
        };
        self.bounds_changed = true;
        self.check("row bounds", s)
    }

    /// Run HiGHS on the program as it now stands. The first run uses the method the instance
    /// was made with; every later one HiGHS's simplex from the kept basis (presolve off: it
    /// would discard the basis). The solution states the method that produced it. A failed
    /// run, or a status other than optimal, infeasible or unbounded, is an error (the caller
    /// solves that program from scratch).
    pub fn run(&mut self) -> Result<Solved> {
        use highs_sys::*;
        // From a kept basis: the primal simplex after a new objective (the basis is still
        // primal feasible), the dual simplex after new bounds (still dual feasible where the
        // costs did not change).
        let method = match (self.warm, self.bounds_changed) {
            (false, _) => self.method,
            (true, false) => Method::PrimalSimplex,
            (true, true) => Method::DualSimplex,
        };
        if self.warm {
            let limit = self
                .warm_limit
                .map_or(i32::MAX, |n| n.min(i32::MAX as usize) as i32);
            opt(&mut self.model, "simplex_iteration_limit", limit)?;
            opt(
                &mut self.model,
                "simplex_strategy",
                if method == Method::PrimalSimplex {
                    4
                } else {
                    1
                },
            )?;
        }
        self.bounds_changed = false;
        let p = self.model.as_mut_ptr();
        // SAFETY: `p` is the live instance owned by `self.model`; every array handed to HiGHS
        // below has the program's num_col or num_row entries.
        unsafe {
            if Highs_run(p) == kHighsStatusError {
                self.warm = false;
                return Err(Error::Solver("HiGHS run failed: Error".into()));
            }
            let mut simplex = 0 as HighsInt;
            let mut ipm = 0 as HighsInt;
            Highs_getIntInfoValue(p, c"simplex_iteration_count".as_ptr(), &mut simplex);
            Highs_getIntInfoValue(p, c"ipm_iteration_count".as_ptr(), &mut ipm);
            let iterations = simplex.max(0) as i64 + ipm.max(0) as i64;
            let status = match Highs_getModelStatus(p) {
                s if s == kHighsModelStatusOptimal => LpStatus::Optimal,
                s if s == kHighsModelStatusInfeasible => LpStatus::Infeasible,
                s if s == kHighsModelStatusUnbounded => LpStatus::Unbounded,
                s if s == kHighsModelStatusModelEmpty => LpStatus::Optimal,
                s => {
                    self.warm = false;
                    return Err(Error::Solver(format!(
                        "HiGHS stopped with model status {s}"
                    )));
                }
            };
            let (n, m) = (self.cols, self.rows);
            let (mut cs, mut rs) = (vec![0 as HighsInt; n], vec![0 as HighsInt; m]);
            let basis = (Highs_getBasis(p, cs.as_mut_ptr(), rs.as_mut_ptr()) != kHighsStatusError)
                .then(|| Basis {
                    cols: cs.into_iter().map(from_highs).collect(),
                    rows: rs.into_iter().map(from_highs).collect(),
                });
            let mut valid = 0 as HighsInt;
            Highs_getIntInfoValue(p, c"basis_validity".as_ptr(), &mut valid);
            let had_basis = valid == kHighsBasisValidityValid;
            if !self.warm && had_basis {
                // From now on: HiGHS's simplex from the kept basis.
                opt(&mut self.model, "solver", "simplex")?;
                opt(&mut self.model, "presolve", "off")?;
            }
            self.warm = had_basis;
            let p = self.model.as_mut_ptr();
            let mut solution = LpSolution {
                status,
                objective: f64::NAN,
                x: vec![],
                row_dual: vec![],
                col_dual: vec![],
                iterations,
                dual_objective: f64::NAN,
                reduced_accuracy: false,
                method,
                tried: Vec::new(),
            };
            if status == LpStatus::Optimal {
                let (mut x, mut cd) = (vec![0.0; n], vec![0.0; n]);
                let (mut rv, mut rd) = (vec![0.0; m], vec![0.0; m]);
                if Highs_getSolution(
                    p,
                    x.as_mut_ptr(),
                    cd.as_mut_ptr(),
                    rv.as_mut_ptr(),
                    rd.as_mut_ptr(),
                ) == kHighsStatusError
                {
                    self.warm = false;
                    return Err(Error::Solver("HiGHS gave no solution".into()));
                }
                solution.objective = Highs_getObjectiveValue(p);
                solution.x = x;
                solution.col_dual = cd;
                solution.row_dual = rd;
            }
            Ok(Solved {
                solution,
                basis: basis.filter(|_| had_basis),
            })
        }
    }
}

/// Start HiGHS's task scheduler on this thread, as every `Highs::run` does first: HiGHS's
/// crossover from a point does not, and IPX's interrupt check then reads the scheduler of this
/// thread (a null pointer where no HiGHS run came before on it: measured, a segmentation
/// fault). A program of one row and one column, run once; the scheduler lives as long as the
/// instance returned (`Highs_destroy` stops it), which the caller keeps until its crossover
/// is done.
fn start_scheduler(o: &SolverOptions) -> Result<highs::SolvedModel> {
    let mut lp = LinearProgram::new(super::Direction::Minimise);
    let r = lp.add_row(0.0, 1.0);
    lp.add_column(1.0, 0.0, 1.0, [(r, 1.0)]);
    let mut m = build(&lp)?;
    common(&mut m, o, 1e-7)?;
    m.try_solve()
        .map_err(|e| Error::Solver(format!("HiGHS run failed: {e:?}")))
}

/// IPX's crossover (HiGHS's `Highs_crossover`) from the optimal duals of `lp` that another
/// method found (Clarabel's interior point, [`super::Method::ClarabelVertex`]), then HiGHS's
/// dual simplex from the basis it builds: an optimal vertex of `lp` with its basis, without
/// HiGHS's own interior point.
///
/// HiGHS's crossover from a point takes a point that is complementary to the last bit (a value
/// strictly inside its bounds with a dual of zero, or on a bound with a dual of the right sign)
/// and, in HiGHS 1.15, mis-sizes rows with two finite sides or none (it copies `num_col` values
/// where its model has one more column per such row). So the program handed to it has only
/// equations: every other row `lo ≤ aᵀx ≤ hi` becomes `aᵀx − s = 0` with a column
/// `lo ≤ s ≤ hi` (free rows are left out and come back basic). The point: every column at its
/// bound nearest zero (zero where it is free), its dual kept where it has the sign of that
/// bound, zero otherwise. IPX builds its crash basis from it (the columns with a dual
/// nonbasic) with no push to make, and ends "imprecise": the basis is dual feasible, not primal
/// feasible, and HiGHS's dual simplex goes on from it to an optimal vertex, its duals exact to
/// the simplex tolerances. Measured (docs/performance.md, "Clarabel with crossover (session
/// 19)"): on the 48 × 48 dome's limit program 1,888 dual simplex iterations from that basis;
/// Clarabel's own primal point instead needed 31,952 primal pushes, about twice the time.
pub fn crossover(lp: &LinearProgram, start: &LpSolution, o: &SolverOptions) -> Result<Solved> {
    use highs_sys::*;
    let (n, m) = (lp.num_cols(), lp.num_rows());
    if start.col_dual.len() != n || start.row_dual.len() != m {
        return Err(Error::Solver(
            "crossover: the duals do not fit the program".into(),
        ));
    }
    let free_row =
        |i: usize| lp.row_lower[i] == f64::NEG_INFINITY && lp.row_upper[i] == f64::INFINITY;
    // Rows of the program of equations (None: a free row, left out), and the slack column of
    // each row that is not an equation.
    let mut row_of = vec![None; m];
    let mut slack_of = vec![None; m];
    let mut eq = LinearProgram {
        maximise: lp.maximise,
        col_start: vec![0],
        ..Default::default()
    };
    for (i, row) in row_of.iter_mut().enumerate() {
        if free_row(i) {
            continue;
        }
        let rhs = if lp.row_lower[i] == lp.row_upper[i] {
            lp.row_lower[i]
        } else {
            0.0
        };
        *row = Some(eq.add_row(rhs, rhs));
    }
    for j in 0..n {
        eq.add_column(
            lp.cost[j],
            lp.col_lower[j],
            lp.col_upper[j],
            lp.column(j).filter_map(|(i, v)| row_of[i].map(|r| (r, v))),
        );
    }
    let mut z = start.col_dual.clone();
    let mut y = vec![0.0; eq.num_rows()];
    for i in 0..m {
        let Some(r) = row_of[i] else { continue };
        y[r] = start.row_dual[i];
        if lp.row_lower[i] != lp.row_upper[i] {
            slack_of[i] = Some(eq.add_column(0.0, lp.row_lower[i], lp.row_upper[i], [(r, -1.0)]));
            // Its reduced cost: 0 − (−1)·y.
            z.push(start.row_dual[i]);
        }
    }
    // IPX minimises: a maximisation's duals change sign on the way in (HiGHS turns them back
    // on the way out).
    let sense = if lp.maximise { -1.0 } else { 1.0 };
    y.iter_mut().for_each(|v| *v *= sense);
    let mut x = vec![0.0; eq.num_cols()];
    for j in 0..eq.num_cols() {
        let (lo, hi) = (eq.col_lower[j], eq.col_upper[j]);
        x[j] = if lo > 0.0 {
            lo
        } else if hi < 0.0 {
            hi
        } else {
            0.0
        };
        let zj = sense * z[j];
        z[j] = if (x[j] == lo && zj > 0.0) || (x[j] == hi && zj < 0.0) {
            zj
        } else {
            0.0
        };
    }
    let (ne, me) = (eq.num_cols(), eq.num_rows());
    let scheduler = start_scheduler(o)?;
    let mut model = build(&eq)?;
    common(&mut model, o, o.feasibility_tolerance.clamp(1e-10, 1e-4))?;
    opt(&mut model, "presolve", "off")?;
    if let Some(t) = o.time_limit {
        opt(&mut model, "time_limit", t)?;
    }
    let p = model.as_mut_ptr();
    // SAFETY: `p` is the live HiGHS instance owned by `model`, whose program has `ne` columns
    // and `me` rows; every array handed to HiGHS has those sizes. HiGHS's scheduler runs on
    // this thread while `scheduler` lives.
    unsafe {
        let status = Highs_crossover(
            p,
            ne as HighsInt,
            me as HighsInt,
            x.as_ptr(),
            z.as_ptr(),
            y.as_ptr(),
        );
        if status == kHighsStatusError {
            return Err(Error::Solver(
                "HiGHS's crossover from the point failed".into(),
            ));
        }
        let mut simplex = 0 as HighsInt;
        let model_status = Highs_getModelStatus(p);
        if model_status == kHighsModelStatusTimeLimit {
            return Err(Error::Solver(
                "HiGHS's crossover from the point reached the time limit".into(),
            ));
        }
        if model_status != kHighsModelStatusOptimal {
            // "Imprecise": HiGHS's simplex from the basis crossover left.
            opt(&mut model, "solver", "simplex")?;
            if let Some(n) = o.iteration_limit {
                opt(
                    &mut model,
                    "simplex_iteration_limit",
                    n.min(i32::MAX as usize) as i32,
                )?;
            }
            let p = model.as_mut_ptr();
            if Highs_run(p) == kHighsStatusError
                || Highs_getModelStatus(p) != kHighsModelStatusOptimal
            {
                return Err(Error::Solver(format!(
                    "HiGHS's simplex after crossover ended with model status {}",
                    Highs_getModelStatus(p)
                )));
            }
            Highs_getIntInfoValue(p, c"simplex_iteration_count".as_ptr(), &mut simplex);
        }
        let p = model.as_mut_ptr();
        let (mut xs, mut cd) = (vec![0.0; ne], vec![0.0; ne]);
        let (mut rv, mut rd) = (vec![0.0; me], vec![0.0; me]);
        if Highs_getSolution(
            p,
            xs.as_mut_ptr(),
            cd.as_mut_ptr(),
            rv.as_mut_ptr(),
            rd.as_mut_ptr(),
        ) == kHighsStatusError
        {
            return Err(Error::Solver(
                "HiGHS gave no solution after crossover".into(),
            ));
        }
        let (mut cs, mut rs) = (vec![0 as HighsInt; ne], vec![0 as HighsInt; me]);
        let got = Highs_getBasis(p, cs.as_mut_ptr(), rs.as_mut_ptr());
        // The basis of `lp`: a column's status as it is; a row's that of its slack column where
        // it has one (basic also where the equation `aᵀx − s = 0` itself is basic, `s` then
        // nonbasic: the basis matrix is the same up to signs), as it is for an equation, basic
        // for a free row; only where it has as many basic statuses as `lp` has rows. (HiGHS's
        // `basis_validity` reads "invalid" after a crossover that ends optimal without the
        // simplex: not asked.)
        let basis = (got != kHighsStatusError)
            .then(|| Basis {
                cols: cs[..n].iter().map(|&s| from_highs(s)).collect(),
                rows: (0..m)
                    .map(|i| match (row_of[i], slack_of[i]) {
                        (None, _) => BasisStatus::Basic,
                        (Some(r), Some(_)) if rs[r] == kHighsBasisStatusBasic => BasisStatus::Basic,
                        (Some(_), Some(c)) => from_highs(cs[c]),
                        (Some(r), None) => from_highs(rs[r]),
                    })
                    .collect(),
            })
            .filter(|b| {
                b.cols
                    .iter()
                    .chain(&b.rows)
                    .filter(|&&s| s == BasisStatus::Basic)
                    .count()
                    == m
            });
        let mut row_dual = vec![0.0; m];
        for i in 0..m {
            if let Some(r) = row_of[i] {
                row_dual[i] = rd[r];
            }
        }
        drop(model);
        drop(scheduler);
        xs.truncate(n);
        cd.truncate(n);
        Ok(Solved {
            solution: LpSolution {
                status: LpStatus::Optimal,
                objective: lp.objective(&xs),
                x: xs,
                row_dual,
                col_dual: cd,
                iterations: start.iterations + simplex.max(0) as i64,
                dual_objective: f64::NAN,
                reduced_accuracy: false,
                method: o.method,
                tried: Vec::new(),
            },
            basis,
        })
    }
}
