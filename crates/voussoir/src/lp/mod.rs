//! The solver layer: a solver-neutral sparse program, the [`Backend`] trait, and one file per
//! backend ([`highs`], [`clarabel`]). Every solve in voussoir goes through this module; nothing
//! outside the backend files names a solver crate.
//!
//! ```text
//!   optimise  cᵀx   (minimise or maximise)
//!   s.t.      row_lower ≤ A x ≤ row_upper
//!             col_lower ≤ x   ≤ col_upper
//!             (optionally) second-order cones over affine rows
//! ```
//! `A` is stored by columns (CSC). The programs of the paper are built in
//! [`crate::programs`]; the analyses hand them to [`solve`], [`solve_warm`] or
//! [`solve_with_cones`], which pick the backend from [`SolverOptions::method`]:
//! HiGHS for the simplex, interior-point and PDLP methods (dual simplex by default, so that
//! mechanisms are vertex solutions with crisp hinges), Clarabel for [`Method::Clarabel`] and for
//! every program with cones.

pub mod clarabel;
pub mod free_columns;
pub mod highs;
pub mod kept;
pub mod lu;
pub mod policy;
pub mod scale;
pub mod sequence;
pub mod vertex;

pub use scale::Scaling;

use crate::error::{Error, Result};
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
    /// A program of the same direction and rows (bounds) with no column yet: the start of a
    /// copy whose columns are chosen (a reduced program, a program with rows added).
    pub fn rows_only(&self) -> Self {
        LinearProgram {
            maximise: self.maximise,
            row_lower: self.row_lower.clone(),
            row_upper: self.row_upper.clone(),
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
    /// The objective `cᵀx` at `x`.
    pub fn objective(&self, x: &[f64]) -> f64 {
        self.cost.iter().zip(x).map(|(c, v)| c * v).sum()
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
    /// This program with one more row `lo ≤ Σ v·x_j ≤ hi` over `entries` `(column, v)` (the
    /// last row), for holding an optimal value while another objective is optimised.
    pub fn with_row(&self, entries: &[(usize, f64)], lo: f64, hi: f64) -> LinearProgram {
        let mut by_col: Vec<f64> = vec![0.0; self.num_cols()];
        for &(j, v) in entries {
            by_col[j] += v;
        }
        let mut out = LinearProgram {
            maximise: self.maximise,
            cost: self.cost.clone(),
            col_lower: self.col_lower.clone(),
            col_upper: self.col_upper.clone(),
            row_lower: self.row_lower.clone(),
            row_upper: self.row_upper.clone(),
            col_start: vec![0],
            row_index: Vec::with_capacity(self.num_nonzeros() + entries.len()),
            value: Vec::with_capacity(self.num_nonzeros() + entries.len()),
        };
        let r = out.add_row(lo, hi);
        for (j, &v) in by_col.iter().enumerate() {
            for (i, a) in self.column(j) {
                out.row_index.push(i);
                out.value.push(a);
            }
            if v != 0.0 {
                out.row_index.push(r);
                out.value.push(v);
            }
            out.col_start.push(out.row_index.len());
        }
        out
    }
    /// The largest violation of the rows and column bounds at `x`, each relative to its own
    /// scale (a row's `Σ |a_ij x_j|` and the size of its bounds; a column's size and bound):
    /// how far a point an interior-point method calls feasible is from being so.
    pub fn relative_violation(&self, x: &[f64]) -> f64 {
        if x.len() != self.num_cols() {
            return f64::INFINITY;
        }
        let mut act = vec![0.0; self.num_rows()];
        let mut size = vec![0.0; self.num_rows()];
        for (j, &xj) in x.iter().enumerate() {
            for (i, v) in self.column(j) {
                act[i] += v * xj;
                size[i] += (v * xj).abs();
            }
        }
        let over = |v: f64, lo: f64, hi: f64, scale: f64| -> f64 {
            let bound = |b: f64| if b.is_finite() { b.abs() } else { 0.0 };
            let s = scale.max(bound(lo)).max(bound(hi));
            let d = (lo - v).max(v - hi).max(0.0);
            if d == 0.0 {
                0.0
            } else if s > 0.0 {
                d / s
            } else {
                f64::INFINITY
            }
        };
        let rows = (0..self.num_rows())
            .map(|i| over(act[i], self.row_lower[i], self.row_upper[i], size[i]))
            .fold(0.0f64, f64::max);
        (0..self.num_cols())
            .map(|j| over(x[j], self.col_lower[j], self.col_upper[j], x[j].abs()))
            .fold(rows, f64::max)
    }

    /// `x` moved onto its column bounds (each value clamped to `[lower, upper]`): a simplex
    /// leaves basic values up to its feasibility tolerance outside their bounds (a force of
    /// −1e-13 where `p_n ≥ 0`), which [`LinearProgram::relative_violation`] measures against
    /// the value itself (a violation of 1). The clamped point satisfies every bound exactly and
    /// is the one to check and to use as the answer.
    pub fn clamped(&self, x: &[f64]) -> Vec<f64> {
        x.iter()
            .zip(self.col_lower.iter().zip(&self.col_upper))
            .map(|(&v, (&lo, &hi))| {
                if v < lo {
                    lo
                } else if v > hi {
                    hi
                } else {
                    v
                }
            })
            .collect()
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
    /// Clarabel's interior point, then HiGHS's crossover from its point ([`vertex`]): an
    /// optimal vertex with its basis, as [`Method::Ipm`] gives, without HiGHS's interior point
    /// (measured, not a default: docs/performance.md, "Clarabel with crossover (session 19)").
    ClarabelVertex,
}

impl Method {
    /// The backend that runs this method.
    pub fn backend(self) -> &'static dyn Backend {
        match self {
            Method::Clarabel => &clarabel::Clarabel,
            Method::ClarabelVertex => &vertex::ClarabelVertex,
            _ => &highs::Highs,
        }
    }
    /// The method's name as on the command line and in results.
    pub fn name(self) -> &'static str {
        match self {
            Method::DualSimplex => "dual-simplex",
            Method::PrimalSimplex => "primal-simplex",
            Method::Ipm => "ipm",
            Method::Choose => "choose",
            Method::IpmNoCrossover => "ipm-no-crossover",
            Method::Pdlp => "pdlp",
            Method::Clarabel => "clarabel",
            Method::ClarabelVertex => "clarabel-vertex",
        }
    }
    /// Whether the method returns vertex (basic) solutions and can start from a basis.
    pub fn is_simplex(self) -> bool {
        matches!(self, Method::DualSimplex | Method::PrimalSimplex)
    }
    /// Whether the method ends at an interior (non-vertex) point, without crossover.
    pub fn is_interior(self) -> bool {
        matches!(
            self,
            Method::IpmNoCrossover | Method::Pdlp | Method::Clarabel
        )
    }
}

/// Solver settings: one documented struct with defaults (Clarabel's habit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolverOptions {
    pub method: Method,
    pub presolve: bool,
    /// Seconds; `None` for no limit.
    pub time_limit: Option<f64>,
    /// Primal and dual feasibility tolerance.
    pub feasibility_tolerance: f64,
    pub threads: usize,
    /// Let the backend print its own log on standard output (diagnostics; off by default).
    pub log: bool,
    /// After an interior point whose result an analysis cannot certify, run the cleanup pass
    /// ([`crossover`] to an optimal vertex). On by default.
    pub cleanup: bool,
    /// Iterations allowed to the requested method (`None`: the backend's own limit). It holds
    /// for `method` only: where that method stops at the limit, the methods after it in its
    /// [`fallback_chain`] run with their own limits (diagnostics, and the test that a backend
    /// failure is recovered).
    pub iteration_limit: Option<usize>,
    /// The program is a yes/no question whose status is the answer (a trial of a bisection),
    /// not an optimum whose duals are read: Clarabel keeps its default regularisation and
    /// tolerance on large programs instead of the tighter ones of [`clarabel`] (with those,
    /// two trials of the least-μ bisection on the façade in running bond ended in Clarabel's
    /// numerical stop, where the defaults decide them in 6 s). Off by default.
    pub decision: bool,
    /// Where the program would be equilibrated ([`scale`]), solve it as written first and the
    /// equilibrated program only where that answer is not a certified optimum ([`policy::check`]):
    /// the canonical selection's extremes of `r·y` on an optimal face (`analysis::canonical`),
    /// whose equilibrated programs came out worse conditioned than as written (the 0.5 m grid
    /// façade's `tilt`: coefficients over 7e8 against 3e4; HiGHS's dual simplex and interior
    /// point failed on them after 4.2 and 13.3 s, then solved them as written in 2.9 and 2.1 s;
    /// docs/performance.md "Façade tilt, safety and capacity (session 25)"). Off by default;
    /// the canonical selection sets it (`analysis::canonical`, `Stages`). Its vertex differs
    /// from the equilibrated path's by round-off, which the settlement path removes before it
    /// deforms a structure (`scale::without_round_off`; docs/performance.md "Capacity step
    /// round-off and the as-written face extremes (session 26)").
    pub as_written_first: bool,
    /// Before a limit program by HiGHS's interior point, look with Clarabel for whether it has
    /// any equilibrium at all (its zero-objective form); where Clarabel says no and the elastic
    /// program certifies it, the answer is "no equilibrium" without the interior point. Set by
    /// the solver policy where no method is named ([`policy::infeasibility_first`]); off by
    /// default.
    pub infeasibility_first: bool,
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions {
            method: Method::DualSimplex,
            presolve: true,
            time_limit: None,
            feasibility_tolerance: 1e-9,
            threads: 1,
            log: false,
            cleanup: true,
            iteration_limit: None,
            decision: false,
            as_written_first: false,
            infeasibility_first: false,
        }
    }
}

impl SolverOptions {
    /// Which solver and method these options run, as stated in every result.
    pub fn info(&self) -> SolverInfo {
        SolverInfo {
            solver: self.method.backend().name().to_string(),
            method: self.method,
            tried: Vec::new(),
        }
    }
}

/// The solver and method that produced a result.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SolverInfo {
    /// `highs` or `clarabel`.
    pub solver: String,
    pub method: Method,
    /// The methods that failed before this one answered, each as `method: why`
    /// ([`fallback_chain`]); empty (and not written) when the requested method answered.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub tried: Vec<String>,
}

/// The answers of one method to one kind of program, in an analysis of many programs
/// ([`SolverInfo::by_programs`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ProgramAnswers {
    /// The kind of program (`bisection`, `reaction ranges`, `elastic decisions`, …).
    pub programs: String,
    pub method: Method,
    /// Programs of that kind the method answered with that outcome.
    pub answers: usize,
    /// `certified` (an optimum certified on the program as written, or a feasibility decided
    /// with its certificate), `not certified` (the analysis then solves the program otherwise:
    /// the next line of the same kind), `infeasible` or `unbounded`.
    pub outcome: String,
    /// Why a method other than the one asked for answered them: a warm start from the
    /// previous program's basis, a fallback, or the kind's design; absent for the method asked.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub why: Option<String>,
}

/// Whether every program of an analysis of many programs was answered with a certificate
/// ([`SolverInfo::by_programs`]'s lines): each line `certified`, `infeasible` or `unbounded`,
/// and every `not certified` answer decided again by a later line of the same kind.
pub fn answers_certified(lines: &[ProgramAnswers]) -> bool {
    outcomes_certified(
        lines
            .iter()
            .map(|l| (l.programs.as_str(), l.answers as u64, l.outcome.as_str())),
    )
}

/// [`answers_certified`] on lines given as (kind of program, answers, outcome): also for the
/// lines read back from a result's JSON (`voussoir bench --scenario realistic`).
pub fn outcomes_certified<'a>(lines: impl IntoIterator<Item = (&'a str, u64, &'a str)>) -> bool {
    let mut pending: Vec<(&str, u64)> = vec![];
    for (programs, answers, outcome) in lines {
        let at = match pending.iter().position(|(k, _)| *k == programs) {
            Some(i) => i,
            None => {
                pending.push((programs, 0));
                pending.len() - 1
            }
        };
        match outcome {
            "not certified" => pending[at].1 += answers,
            "certified" | "infeasible" | "unbounded" => {
                pending[at].1 = pending[at].1.saturating_sub(answers)
            }
            // A candidate's answer is used only after its own certificate on the whole program
            // (a ray by `sequence::certify_ray`): it neither certifies nor fails the result.
            CANDIDATE_WORDS => {}
            _ => return false,
        }
    }
    pending.iter().all(|(_, n)| *n == 0)
}

impl SolverInfo {
    /// One sentence on how the answer was obtained when the requested method failed
    /// ("dual-simplex, after ipm: HiGHS run failed: Error"), or `None`.
    pub fn fallback_note(&self) -> Option<String> {
        (!self.tried.is_empty()).then(|| {
            format!(
                "solved by {} after {} failed ({})",
                self.method.name(),
                self.tried
                    .iter()
                    .map(|t| t.split(':').next().unwrap_or(t))
                    .fold(Vec::<&str>::new(), |mut v, m| {
                        if !v.contains(&m) {
                            v.push(m);
                        }
                        v
                    })
                    .join(", "),
                self.tried.join("; ")
            )
        })
    }

    /// Which method answered each kind of program ([`ProgramKind`]), in order of first
    /// appearance: per kind and method, the answers and why the method is not the one asked
    /// for, where it is not (a warm run from the previous basis, a fallback, or the kind's
    /// design).
    pub fn by_programs(opts: &SolverOptions, solves: &[SolveRecord]) -> Vec<ProgramAnswers> {
        let mut out: Vec<ProgramAnswers> = Vec::new();
        for s in solves {
            let why = if s.method == opts.method {
                None
            } else if !s.tried.is_empty() {
                let failed: Vec<&str> = s
                    .tried
                    .iter()
                    .map(|t| t.split(':').next().unwrap_or(t))
                    .collect();
                Some(format!("fallback after {} failed", failed.join(", ")))
            } else if s.warm {
                Some("warm start from the previous program's basis".to_string())
            } else if !s.design.is_empty() {
                Some(format!("by design: {}", s.design))
            } else {
                None
            };
            let programs = if s.programs.is_empty() {
                "programs"
            } else {
                s.programs
            };
            let outcome = s.outcome.words();
            match out.iter_mut().find(|a| {
                a.programs == programs
                    && a.method == s.method
                    && a.why == why
                    && a.outcome == outcome
            }) {
                Some(a) => a.answers += 1,
                None => out.push(ProgramAnswers {
                    programs: programs.to_string(),
                    method: s.method,
                    answers: 1,
                    outcome: outcome.to_string(),
                    why,
                }),
            }
        }
        // Each kind's lines together, kinds in order of first appearance.
        let first = |p: &str| out.iter().position(|a| a.programs == p).unwrap_or(0);
        let mut keyed: Vec<(usize, ProgramAnswers)> = out
            .iter()
            .map(|a| (first(&a.programs), a.clone()))
            .collect();
        keyed.sort_by_key(|(k, _)| *k);
        keyed.into_iter().map(|(_, a)| a).collect()
    }

    /// How the programs of an analysis of many solves were solved with `opts`: the requested
    /// method where it answered any of them, else the one that answered most (the requested
    /// one where none was solved), and every distinct fallback note in order of first
    /// appearance, each with the method that answered after it (`clarabel: not certified (…)
    /// → ipm`). [`SolverInfo::by_programs`] tells which method answered which programs.
    pub fn of_solves(opts: &SolverOptions, solves: &[SolveRecord]) -> SolverInfo {
        let mut count: Vec<(Method, usize)> = Vec::new();
        let mut tried: Vec<String> = Vec::new();
        for s in solves {
            match count.iter_mut().find(|(m, _)| *m == s.method) {
                Some((_, n)) => *n += 1,
                None => count.push((s.method, 1)),
            }
            for t in &s.tried {
                // Which method answered after this failure (the programs may differ).
                let t = format!("{t} → {}", s.method.name());
                if !tried.contains(&t) {
                    tried.push(t);
                }
            }
        }
        // The requested method where it answered; else the first of the most frequent
        // (deterministic: in order of first appearance).
        let asked = count.iter().any(|(m, _)| *m == opts.method);
        let method = count
            .iter()
            .filter(|_| !asked)
            .fold(None::<(Method, usize)>, |best, &(m, n)| match best {
                Some((_, b)) if b >= n => best,
                _ => Some((m, n)),
            })
            .map_or(opts.method, |(m, _)| m);
        SolverInfo {
            solver: method.backend().name().to_string(),
            method,
            tried,
        }
    }

    /// The methods tried by both of two solves (a settlement's two programs), in order.
    pub fn merged(mut self, other: &SolverInfo) -> SolverInfo {
        for t in &other.tried {
            if !self.tried.contains(t) {
                self.tried.push(t.clone());
            }
        }
        if other.method != self.method && self.tried.is_empty() {
            return other.clone();
        }
        self
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
    /// The dual objective as the solver reports it, in the program's own sense (NaN when the
    /// solver gives none: HiGHS's simplex, whose optimal bases have no gap). For a program with
    /// cones it is the value the dual side certifies, cone terms included.
    pub dual_objective: f64,
    /// The solver stopped at reduced accuracy (Clarabel's "almost solved"): optimal only to a
    /// looser tolerance. The analyses certify such a solution themselves or say that it is
    /// not certified.
    pub reduced_accuracy: bool,
    /// The method that produced this solution (after any fallback).
    pub method: Method,
    /// The methods that failed before it, each as `method: why` ([`fallback_chain`]).
    pub tried: Vec<String>,
}

impl LpSolution {
    /// The solver and method that produced this solution, and what failed before it.
    pub fn solver_info(&self) -> SolverInfo {
        SolverInfo {
            solver: self.method.backend().name().to_string(),
            method: self.method,
            tried: self.tried.clone(),
        }
    }
}

/// A second-order cone over three affine rows `s_i = b_i − a_iᵀx`: `‖(s_1, s_2)‖ ≤ s_0`.
pub type Cone3 = [(Vec<(usize, f64)>, f64); 3];

/// Status of a column or row in a simplex basis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BasisStatus {
    /// Nonbasic at its lower bound.
    Lower,
    Basic,
    /// Nonbasic at its upper bound.
    Upper,
    /// Nonbasic free variable at zero.
    Zero,
}

/// A simplex basis: where the next solve of a program of the same shape starts.
#[derive(Clone, Debug, PartialEq)]
pub struct Basis {
    pub cols: Vec<BasisStatus>,
    pub rows: Vec<BasisStatus>,
}

impl Basis {
    /// Make nonbasic statuses consistent with (possibly changed) bounds of the next program.
    pub fn adapted(&self, lp: &LinearProgram) -> Basis {
        let fix = |s: &[BasisStatus], lo: &[f64], hi: &[f64]| -> Vec<BasisStatus> {
            s.iter()
                .zip(lo.iter().zip(hi))
                .map(|(&s, (&l, &h))| {
                    if s == BasisStatus::Basic {
                        BasisStatus::Basic
                    } else if l.is_finite() && (s == BasisStatus::Lower || !h.is_finite()) {
                        BasisStatus::Lower
                    } else if h.is_finite() {
                        BasisStatus::Upper
                    } else {
                        BasisStatus::Zero
                    }
                })
                .collect()
        };
        Basis {
            cols: fix(&self.cols, &lp.col_lower, &lp.col_upper),
            rows: fix(&self.rows, &lp.row_lower, &lp.row_upper),
        }
    }
}

/// What a backend returns: the solution and, where the backend has one, its final basis.
#[derive(Clone, Debug)]
pub struct Solved {
    pub solution: LpSolution,
    pub basis: Option<Basis>,
}

/// A solver backend. Implementations live in one file each and are the only code that talks
/// to the solver library.
pub trait Backend: Sync {
    /// `highs`, `clarabel`.
    fn name(&self) -> &'static str;
    /// Whether the backend takes second-order cones.
    fn supports_cones(&self) -> bool;
    /// Solve `lp` with the cones `cones` (empty for a plain LP), starting from `start` where the
    /// backend can (ignored otherwise). Infeasible and unbounded are statuses, not errors; a
    /// backend that cannot reach a conclusion returns [`Error::Solver`] with one line.
    fn solve(
        &self,
        lp: &LinearProgram,
        cones: &[Cone3],
        opts: &SolverOptions,
        start: Option<&Basis>,
    ) -> Result<Solved>;
    /// Whether the backend takes a convex quadratic objective term.
    fn supports_quadratic(&self) -> bool {
        false
    }
    /// Minimise `cᵀx + ½ xᵀPx` over the rows and bounds of `lp` (`lp.maximise` must be false);
    /// `quadratic` holds the upper triangle of `P` (positive semidefinite) as `(i, j, v)`,
    /// `i ≤ j`, repeated entries summed.
    fn solve_quadratic(
        &self,
        _lp: &LinearProgram,
        _quadratic: &[(usize, usize, f64)],
        _opts: &SolverOptions,
    ) -> Result<Solved> {
        Err(Error::Solver(format!(
            "{} does not take a quadratic objective",
            self.name()
        )))
    }
}

fn check_numbers(lp: &LinearProgram) -> Result<()> {
    if lp
        .row_lower
        .iter()
        .chain(&lp.row_upper)
        .chain(&lp.col_lower)
        .chain(&lp.col_upper)
        .any(|b| b.is_nan())
    {
        return Err(Error::Solver("the LP has a NaN bound".into()));
    }
    if lp.cost.iter().chain(&lp.value).any(|v| !v.is_finite()) {
        return Err(Error::Solver(
            "the LP has a coefficient that is not finite".into(),
        ));
    }
    Ok(())
}

/// Solve `lp` with the backend of `opts.method`. Infeasible and unbounded are statuses, not
/// errors.
/// The program is solved in nondimensional form ([`scale`]); the solution is in its units.
pub fn solve(lp: &LinearProgram, opts: &SolverOptions) -> Result<LpSolution> {
    check_numbers(lp)?;
    with_fallback(lp, opts, |o| solve_once(lp, o))
}

/// [`solve`] with `opts.method` alone, without the fallback chain (equilibrated where it needs
/// it, as every solve): for a caller that has its own next step where the method fails — the
/// trials of the canonical selection's least-μ bisection (a trial Clarabel cannot decide cost a
/// minute on HiGHS's interior point and is better left undecided), `safety`'s recession
/// programs and direct decisions.
pub fn solve_without_fallback(lp: &LinearProgram, opts: &SolverOptions) -> Result<LpSolution> {
    check_numbers(lp)?;
    let s = solve_once(lp, opts)?;
    record(lp, &s);
    Ok(s)
}

/// The methods tried, in order, when a solve with `method` fails (the backend's error, a
/// status other than optimal, infeasible or unbounded — HiGHS's "Error", an iteration or time
/// limit, Clarabel's numerical stops). Each later method is of another kind (simplex, HiGHS's
/// interior point, Clarabel's), so that one kind's numerical trouble is answered by another.
/// The requested method always comes first: where it answers, nothing changes.
pub fn fallback_chain(method: Method) -> &'static [Method] {
    use Method::*;
    match method {
        DualSimplex => &[DualSimplex, PrimalSimplex, Ipm, Clarabel],
        // The interior point before the dual simplex: on the 60 × 30 frictional wall, where
        // the primal simplex ends in HiGHS's "Solve error", the dual simplex took 349 CPU s and
        // the interior point with crossover 69 (docs/performance.md, session 15).
        PrimalSimplex => &[PrimalSimplex, Ipm, DualSimplex, Clarabel],
        Ipm => &[Ipm, DualSimplex, Clarabel],
        IpmNoCrossover => &[IpmNoCrossover, Ipm, DualSimplex, Clarabel],
        Choose => &[Choose, DualSimplex, Clarabel],
        Pdlp => &[Pdlp, Ipm, DualSimplex],
        Clarabel => &[Clarabel, Ipm, DualSimplex],
        // A crossover that fails or ends uncertified: HiGHS's own interior point with
        // crossover (a vertex too), then the dual simplex.
        ClarabelVertex => &[ClarabelVertex, Ipm, DualSimplex],
    }
}

/// Run `solve` with each method of [`fallback_chain`] until one answers with a certified
/// optimum ([`policy::check`]: rows satisfied and a duality gap within
/// [`policy::CERTIFICATE_TOLERANCE`]) or a status (infeasible, unbounded); the solution states
/// its method and what failed before it. An optimum that is not certified moves on along the
/// chain like a failure; where no later method does better, the first such answer is returned
/// (the analyses then report it as not certified). Only when every method fails: one line
/// naming them.
fn with_fallback(
    lp: &LinearProgram,
    opts: &SolverOptions,
    mut solve: impl FnMut(&SolverOptions) -> Result<LpSolution>,
) -> Result<LpSolution> {
    let mut tried = Vec::new();
    let mut uncertified: Option<(usize, LpSolution)> = None;
    let mut chain = fallback_chain(opts.method).to_vec();
    let mut k = 0;
    while k < chain.len() {
        let method = chain[k];
        k += 1;
        let o = SolverOptions {
            method,
            iteration_limit: if k == 1 { opts.iteration_limit } else { None },
            ..*opts
        };
        match solve(&o) {
            Ok(mut s) => {
                s.method = method;
                match policy::check(lp, &s) {
                    None => {
                        s.tried = tried;
                        record(lp, &s);
                        return Ok(s);
                    }
                    Some(why) => {
                        tried.push(format!("{}: {why}", method.name()));
                        if uncertified.is_none() {
                            uncertified = Some((tried.len() - 1, s));
                        }
                    }
                }
            }
            Err(e) => {
                let why = e.to_string();
                if e == Error::Undecided {
                    // Clarabel next: it decides infeasibility and unboundedness with a
                    // certificate, where HiGHS's simplex runs from scratch (24 s into "Solve
                    // error" on the README vault with μ = 0.3).
                    if let Some(c) = chain[k..].iter().position(|&m| m == Method::Clarabel) {
                        chain[k..=k + c].rotate_right(1);
                    }
                }
                tried.push(format!("{}: {}", method.name(), why.trim()))
            }
        }
    }
    if let Some((own, mut s)) = uncertified {
        tried.remove(own);
        s.tried = tried;
        record(lp, &s);
        return Ok(s);
    }
    Err(Error::Solver(format!(
        "every method failed: {}",
        tried.join("; ")
    )))
}

/// The method and fallbacks of one solve, as [`collecting`] gathers them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SolveRecord {
    pub method: Method,
    /// The methods that failed before `method` answered (`method: why`).
    pub tried: Vec<String>,
    /// The kind of program ([`ProgramKind`]; "" outside one).
    pub programs: &'static str,
    /// Why that kind of program goes to a method of its own, where it does ([`ProgramKind`]).
    pub design: &'static str,
    /// A warm run from the basis of the program before ([`sequence::Sequence`]).
    pub warm: bool,
    /// Answered from a kept basis by the solver layer itself, after this many dual simplex
    /// pivots ([`solve_warm_kept`]); `None` where a backend answered.
    pub kept_pivots: Option<usize>,
    pub outcome: Outcome,
}

thread_local! {
    static SOLVES: std::cell::RefCell<Option<Vec<SolveRecord>>> =
        const { std::cell::RefCell::new(None) };
    /// The kind of program being solved: its words, its design, and whether its answers are
    /// candidates ([`ProgramKind`]).
    static KIND: std::cell::Cell<(&'static str, &'static str, bool)> =
        const { std::cell::Cell::new(("", "", false)) };
}

/// Record the answer `s` to `lp` of the fallback chain for [`collecting`].
fn record(lp: &LinearProgram, s: &LpSolution) {
    record_run(s.method, &s.tried, false, || Outcome::of(lp, s));
}

/// [`record`] for an answer from a kept basis after `pivots` pivots ([`solve_warm_kept`]).
fn record_kept(lp: &LinearProgram, s: &LpSolution, pivots: usize) {
    push_record(s.method, &s.tried, false, Some(pivots), || {
        Outcome::of(lp, s)
    });
}

/// Record one answer for [`collecting`]: `method` answered (after `tried` failed), warm or not,
/// with its `outcome` (evaluated only while collecting).
pub(crate) fn record_run(
    method: Method,
    tried: &[String],
    warm: bool,
    outcome: impl FnOnce() -> Outcome,
) {
    push_record(method, tried, warm, None, outcome)
}

fn push_record(
    method: Method,
    tried: &[String],
    warm: bool,
    kept_pivots: Option<usize>,
    outcome: impl FnOnce() -> Outcome,
) {
    SOLVES.with(|c| {
        if let Some(v) = c.borrow_mut().as_mut() {
            let (programs, design, candidates) = KIND.with(|k| k.get());
            let outcome = match outcome() {
                Outcome::NotCertified if candidates => Outcome::Candidate,
                o => o,
            };
            v.push(SolveRecord {
                method,
                tried: tried.to_vec(),
                programs,
                design,
                warm,
                kept_pivots,
                outcome,
            });
        }
    });
}

/// What one answer was, as [`collecting`] records it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// An optimum certified on the program as written ([`sequence::certify`]: primal and dual
    /// feasibility and the duality gap), or a feasibility decided with its certificate
    /// ([`sequence::decide_feasibility`]).
    Certified,
    /// An optimum that does not certify (the analysis then solves the program otherwise).
    NotCertified,
    Infeasible,
    Unbounded,
    /// An optimum that does not certify, of a program whose answers are candidates
    /// ([`ProgramKind::candidates`]: a ray searched for on a recession program, used only once
    /// `sequence::certify_ray` accepts it on the whole program): it neither certifies nor
    /// fails the result. Found in session 22: `safety --friction 0.5` on the README vault
    /// listed 4 such answers "not certified", so the benchmark would have called a result
    /// whose every number is certified "not certified".
    Candidate,
}

/// [`Outcome::Candidate`] as the summaries print it.
pub const CANDIDATE_WORDS: &str = "a candidate, checked on the whole program";

impl Outcome {
    fn of(lp: &LinearProgram, s: &LpSolution) -> Outcome {
        match s.status {
            LpStatus::Infeasible => Outcome::Infeasible,
            LpStatus::Unbounded => Outcome::Unbounded,
            // A feasibility program (no objective): any point that holds its rows is an
            // optimum, certified by the primal half alone — by the point, whatever the duals,
            // to the solver layer's certificate tolerance (policy::CERTIFICATE_TOLERANCE, as
            // `policy::check` accepts an optimum). Regression: the 0.5 m running-bond façade's
            // `safety` stands at f = 0 by Clarabel's point on the merged program (3.6e-11 of
            // its largest bound, `sequence::decide_directly`), whose largest row violation
            // relative to the row's own terms is 2.6e-7: above the sequence's 1e-7, so the
            // realistic benchmark called the cell "not certified".
            LpStatus::Optimal if lp.cost.iter().all(|&c| c == 0.0) => {
                if sequence::primal_violation(lp, &s.x) <= policy::CERTIFICATE_TOLERANCE {
                    Outcome::Certified
                } else {
                    Outcome::NotCertified
                }
            }
            LpStatus::Optimal if sequence::certify(lp, s).is_some_and(|c| c.ok()) => {
                Outcome::Certified
            }
            LpStatus::Optimal => Outcome::NotCertified,
        }
    }

    /// As the summaries print it.
    pub fn words(self) -> &'static str {
        match self {
            Outcome::Certified => "certified",
            Outcome::NotCertified => "not certified",
            Outcome::Infeasible => "infeasible",
            Outcome::Unbounded => "unbounded",
            Outcome::Candidate => CANDIDATE_WORDS,
        }
    }
}

/// The kind of program the solves on this thread answer while it lives (for an analysis of
/// many programs that states which method answered each kind: [`SolverInfo::by_programs`]),
/// with the reason where that kind goes to a method of its own by design (empty: the method
/// asked for). Dropping it restores the kind before.
pub struct ProgramKind {
    before: (&'static str, &'static str, bool),
}

impl ProgramKind {
    pub fn set(programs: &'static str, design: &'static str) -> ProgramKind {
        Self::with(programs, design, false)
    }

    /// A kind whose answers are candidates, each checked on the whole program before it is
    /// used (a ray certified by `sequence::certify_ray`): an uncertified optimum of such a
    /// program is recorded [`Outcome::Candidate`], not "not certified".
    pub fn candidates(programs: &'static str, design: &'static str) -> ProgramKind {
        Self::with(programs, design, true)
    }

    fn with(programs: &'static str, design: &'static str, candidates: bool) -> ProgramKind {
        ProgramKind {
            before: KIND.with(|k| k.replace((programs, design, candidates))),
        }
    }
}

impl Drop for ProgramKind {
    fn drop(&mut self) {
        KIND.with(|k| k.set(self.before));
    }
}

/// Run `f`, gathering the method and fallbacks of every solve it makes on this thread (for an
/// analysis of many programs, whose result states how they were solved:
/// [`SolverInfo::of_solves`]). Nested calls gather for each level.
pub fn collecting<T>(f: impl FnOnce() -> T) -> (T, Vec<SolveRecord>) {
    let outer = SOLVES.with(|c| c.borrow_mut().replace(Vec::new()));
    let out = f();
    let mine = SOLVES.with(|c| c.replace(outer)).unwrap_or_default();
    SOLVES.with(|c| {
        if let Some(v) = c.borrow_mut().as_mut() {
            v.extend(mine.iter().cloned());
        }
    });
    (out, mine)
}

/// [`solve`] with `opts.method` alone.
fn solve_once(lp: &LinearProgram, opts: &SolverOptions) -> Result<LpSolution> {
    let backend = opts.method.backend();
    let scaling = Scaling::needed(lp, &[]);
    // As written first where asked (SolverOptions::as_written_first): kept where it is a
    // certified optimum; otherwise the equilibrated program as below, with this answer as the
    // one as written (not solved twice).
    let mut written = None;
    if scaling.is_some() && opts.as_written_first {
        let r = backend.solve(lp, &[], opts, None).map(|r| r.solution);
        if let Ok(s) = &r {
            if s.status == LpStatus::Optimal && policy::check(lp, s).is_none() {
                return r;
            }
        }
        written = Some(r);
    }
    let mut as_written = || match written.take() {
        Some(r) => r,
        None => backend.solve(lp, &[], opts, None).map(|r| r.solution),
    };
    Ok(match scaling {
        None => backend.solve(lp, &[], opts, None)?.solution,
        Some(s) => match backend.solve(&s.apply(lp), &[], opts, None) {
            Ok(solved) => as_written_if_better(lp, s.unscale(solved.solution), as_written).0,
            // The equilibrated program refused: once more as written.
            Err(_) => as_written()?,
        },
    })
}

/// Which of its two answers [`as_written_if_better`] returned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Answer {
    /// The equilibrated program's (the program as written was not solved, or did no better).
    Scaled,
    /// The program's as written: a certified optimum where the equilibrated one was not.
    AsWritten,
}

/// The solution of the equilibrated program (`scaled`, already in the user's units), or —
/// where it is not a certified optimum of the program as written ([`policy::check`]) — the
/// program solved as written (`as_written`, called only then), if that one is a certified
/// optimum; with which of the two it is, so that the caller keeps the basis that goes with it.
///
/// The backend's tolerances act on the equilibrated numbers: a column scaled by 2^36 (a
/// contact force whose entries are of round-off size) carries its 1e-7 to a bound violation of
/// 1e-3 of the largest force in the user's program. Measured on the non-associative capacity
/// curve of a settled 5 × 8 wall (`tests/nonassociative_settlement.rs`): normal forces of
/// −0.13 kN against 21 kN from HiGHS's dual simplex, and Clarabel stopping at reduced accuracy
/// (row violation 7.5e-4) on the equilibrated limit program at 1 cm; as written, every one of
/// its programs certifies. A status is not taken on trust either: on that program at 1 cm
/// HiGHS's dual simplex and interior point both said "infeasible" after equilibration, where
/// the program as written has a certified optimum (the curve then fell to a false zero at
/// 0.9855 cm). So an infeasible or unbounded answer is checked as written too, and a certified
/// optimum — a proof of feasibility and of a bound — replaces it; where the program as written
/// gives the same status, or nothing certified, the equilibrated answer stands.
pub fn as_written_if_better(
    lp: &LinearProgram,
    scaled: LpSolution,
    as_written: impl FnOnce() -> Result<LpSolution>,
) -> (LpSolution, Answer) {
    let settled = match scaled.status {
        LpStatus::Optimal => policy::check(lp, &scaled).is_none(),
        LpStatus::Infeasible | LpStatus::Unbounded => false,
    };
    if settled {
        return (scaled, Answer::Scaled);
    }
    match as_written() {
        Ok(s) if s.status == LpStatus::Optimal && policy::check(lp, &s).is_none() => {
            (s, Answer::AsWritten)
        }
        _ => (scaled, Answer::Scaled),
    }
}

/// The cleanup pass after an interior point that stopped short: a short primal simplex from
/// the interior point's active set. The `m` columns and rows (m = rows of `lp`) farthest from
/// their bounds relative to their duals start basic (free columns first), every other one
/// nonbasic at its nearer bound; HiGHS repairs a singular start and ends at an optimal vertex,
/// whose duals are exact to the simplex tolerances.
pub fn run_crossover(
    lp: &LinearProgram,
    start: &LpSolution,
    opts: &SolverOptions,
) -> Result<LpSolution> {
    let (n, m) = (lp.num_cols(), lp.num_rows());
    if start.x.len() != n || start.col_dual.len() != n || start.row_dual.len() != m {
        return Err(Error::Solver(
            "cleanup: the interior point does not fit the program".into(),
        ));
    }
    let activity = lp.row_activity(&start.x);
    // How basic a variable looks: its distance to the nearer bound over the size of its dual.
    let free = |lo: f64, hi: f64| lo == f64::NEG_INFINITY && hi == f64::INFINITY;
    let score = |v: f64, lo: f64, hi: f64, dual: f64| {
        if free(lo, hi) {
            return f64::INFINITY;
        }
        let gap = (v - lo).abs().min((hi - v).abs());
        gap / (dual.abs() + 1e-300)
    };
    let nearer = |v: f64, lo: f64, hi: f64| {
        if free(lo, hi) {
            BasisStatus::Zero
        } else if (v - lo).abs() <= (hi - v).abs() {
            BasisStatus::Lower
        } else {
            BasisStatus::Upper
        }
    };
    let mut order: Vec<(f64, usize)> = (0..n)
        .map(|j| {
            let x = start.x[j];
            (
                score(x, lp.col_lower[j], lp.col_upper[j], start.col_dual[j]),
                j,
            )
        })
        .chain((0..m).map(|i| {
            let r = activity[i];
            (
                score(r, lp.row_lower[i], lp.row_upper[i], start.row_dual[i]),
                n + i,
            )
        }))
        .collect();
    order.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut basis = Basis {
        cols: (0..n)
            .map(|j| nearer(start.x[j], lp.col_lower[j], lp.col_upper[j]))
            .collect(),
        rows: (0..m)
            .map(|i| nearer(activity[i], lp.row_lower[i], lp.row_upper[i]))
            .collect(),
    };
    for &(_, k) in order.iter().take(m) {
        if k < n {
            basis.cols[k] = BasisStatus::Basic;
        } else {
            basis.rows[k - n] = BasisStatus::Basic;
        }
    }
    let o = SolverOptions {
        method: Method::PrimalSimplex,
        ..*opts
    };
    let mut b = Some(basis);
    solve_warm(lp, &o, &mut b)
}

/// Solve `lp` starting from `basis` (a basis of the previous program of the same shape, if
/// any; backends without bases solve from scratch), and replace `basis` with the final one.
pub fn solve_warm(
    lp: &LinearProgram,
    opts: &SolverOptions,
    basis: &mut Option<Basis>,
) -> Result<LpSolution> {
    check_numbers(lp)?;
    with_fallback(lp, opts, |o| solve_warm_once(lp, o, basis))
}

/// [`solve_warm`] for the next program of a sequence whose kept basis may still be optimal or
/// nearly so (a capacity curve's steps: only coefficients changed): the basis is looked at on
/// `lp` first ([`kept::answer_pivoting`]: its basic solution and duals by the solver layer's
/// own LU and, where it is dual feasible but not primal feasible, at most
/// [`kept::MAX_PIVOTS`] bounded dual simplex pivots from it, each basis refactorised; the
/// basis reached feasible in both senses within the backend's tolerance and its answer
/// certified by [`policy::check`]); where that solves `lp`, it is the answer (stated as
/// `opts.method`'s, the pivots its iterations) and the basis reached is kept; otherwise
/// [`solve_warm`] as before, from the kept basis.
pub fn solve_warm_kept(
    lp: &LinearProgram,
    opts: &SolverOptions,
    basis: &mut Option<Basis>,
) -> Result<LpSolution> {
    check_numbers(lp)?;
    let kept = basis
        .as_ref()
        .filter(|b| b.cols.len() == lp.num_cols() && b.rows.len() == lp.num_rows())
        .map(|b| b.adapted(lp));
    if let Some(b) = kept {
        let clock = std::time::Instant::now();
        let answer = kept::answer_pivoting(lp, opts, &b, kept::MAX_PIVOTS);
        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
            let what = match &answer {
                Some(a) if a.pivots == 0 => "optimal, certified: no backend run".to_string(),
                Some(a) => format!(
                    "optimal after {} dual pivot{}, certified: no backend run",
                    a.pivots,
                    if a.pivots == 1 { "" } else { "s" }
                ),
                None => "not optimal within its pivots or not certified: the warm simplex runs"
                    .to_string(),
            };
            eprintln!(
                "trace: kept basis rows {} cols {}: {} in {:.3} s",
                lp.num_rows(),
                lp.num_cols(),
                what,
                clock.elapsed().as_secs_f64()
            );
        }
        if let Some(a) = answer {
            record_kept(lp, &a.solution, a.pivots);
            *basis = Some(a.basis);
            return Ok(a.solution);
        }
    }
    solve_warm(lp, opts, basis)
}

/// [`solve_warm`] with `opts.method` alone.
fn solve_warm_once(
    lp: &LinearProgram,
    opts: &SolverOptions,
    basis: &mut Option<Basis>,
) -> Result<LpSolution> {
    let start = basis
        .as_ref()
        .filter(|b| b.cols.len() == lp.num_cols() && b.rows.len() == lp.num_rows())
        .map(|b| b.adapted(lp));
    let backend = opts.method.backend();
    let scaling = Scaling::needed(lp, &[]);
    // As written first where asked (SolverOptions::as_written_first), from the same start:
    // kept with its basis where it is a certified optimum; otherwise the path below.
    if scaling.is_some() && opts.as_written_first {
        if let Ok(r) = backend.solve(lp, &[], opts, start.as_ref()) {
            if r.solution.status == LpStatus::Optimal && policy::check(lp, &r.solution).is_none() {
                *basis = r.basis;
                return Ok(r.solution);
            }
        }
    }
    let first = match &scaling {
        None => backend.solve(lp, &[], opts, start.as_ref()),
        Some(s) => backend.solve(&s.apply(lp), &[], opts, start.as_ref()),
    };
    let (solved, scaling) = match first {
        Ok(solved) => (solved, scaling),
        // A refusal with a starting basis or after scaling (HiGHS's "Error" on a basis that
        // does not suit the equilibrated program) is retried once from scratch as written.
        Err(_) if start.is_some() || scaling.is_some() => {
            (backend.solve(lp, &[], opts, None)?, None)
        }
        Err(e) => return Err(e),
    };
    *basis = solved.basis;
    Ok(match scaling {
        None => solved.solution,
        Some(s) => {
            let mut again = None;
            let (sol, answer) = as_written_if_better(lp, s.unscale(solved.solution), || {
                let r = backend.solve(lp, &[], opts, None)?;
                again = Some(r.basis);
                Ok(r.solution)
            });
            // The basis goes with the solution returned.
            if answer == Answer::AsWritten {
                *basis = again.flatten();
            }
            sol
        }
    })
}

/// Solve `lp` with second-order cones appended. Only a backend with cones takes them: with a
/// HiGHS method the program goes to Clarabel, whose name the result then states.
pub fn solve_with_cones(
    lp: &LinearProgram,
    cones: &[Cone3],
    opts: &SolverOptions,
) -> Result<LpSolution> {
    check_numbers(lp)?;
    let backend = cone_backend(opts);
    Ok(match Scaling::needed(lp, cones) {
        None => backend.solve(lp, cones, opts, None)?.solution,
        Some(s) => {
            let solved = backend.solve(&s.apply(lp), &s.apply_cones(cones), opts, None)?;
            s.unscale(solved.solution)
        }
    })
}

/// Minimise `cᵀx + ½ xᵀPx` (a convex quadratic program; `quadratic` is the upper triangle of
/// `P` as `(i, j, v)` with `i ≤ j`). Only a backend with quadratic objectives takes it: with a
/// HiGHS method the program goes to Clarabel. The reported objective includes the quadratic
/// term.
pub fn solve_quadratic(
    lp: &LinearProgram,
    quadratic: &[(usize, usize, f64)],
    opts: &SolverOptions,
) -> Result<LpSolution> {
    check_numbers(lp)?;
    if lp.maximise {
        return Err(Error::Solver(
            "a quadratic program must be a minimisation".into(),
        ));
    }
    if quadratic
        .iter()
        .any(|&(i, j, v)| i > j || j >= lp.num_cols() || !v.is_finite())
    {
        return Err(Error::Solver(
            "the quadratic term is not an upper triangle of finite numbers".into(),
        ));
    }
    let b = opts.method.backend();
    let backend: &dyn Backend = if b.supports_quadratic() {
        b
    } else {
        &clarabel::Clarabel
    };
    // Nondimensional, as every LP ([`scale`]): `x = C x̃`, so each quadratic coefficient takes
    // the product of its two columns' factors and the objective's factor σ. Without a linear
    // cost σ makes the largest quadratic coefficient about one (the minimiser does not depend
    // on it). As written, the canonical force stage's energy QP on the façade in running bond
    // (2,672 blocks, forces of thousands of kN) stopped at Clarabel's iteration limit after
    // 27 s; nondimensional it ends optimal in 5.6 s.
    match Scaling::needed(lp, &[]) {
        None => Ok(backend.solve_quadratic(lp, quadratic, opts)?.solution),
        Some(mut sc) => {
            if lp.cost.iter().all(|&c| c == 0.0) {
                let top = quadratic.iter().fold(0.0f64, |m, &(i, j, v)| {
                    m.max((v * sc.col[i] * sc.col[j]).abs())
                });
                sc.objective = if top > 0.0 && top.is_finite() {
                    2f64.powi(-(top.log2().round() as i32))
                } else {
                    1.0
                };
            }
            let slp = sc.apply(lp);
            let sq: Vec<(usize, usize, f64)> = quadratic
                .iter()
                .map(|&(i, j, v)| (i, j, v * sc.objective * sc.col[i] * sc.col[j]))
                .collect();
            let solved = backend.solve_quadratic(&slp, &sq, opts)?.solution;
            Ok(if solved.status == LpStatus::Optimal {
                sc.unscale(solved)
            } else {
                solved
            })
        }
    }
}

/// The backend that solves cone programs under `opts`.
pub fn cone_backend(opts: &SolverOptions) -> &'static dyn Backend {
    let b = opts.method.backend();
    if b.supports_cones() {
        b
    } else {
        &clarabel::Clarabel
    }
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

    /// Regression (session 21): a feasibility program's answer is certified by its point
    /// alone, with or without duals; a point off the rows is not.
    #[test]
    fn a_feasibility_answer_is_certified_by_its_point() {
        let mut lp = tiny_lp();
        lp.cost.iter_mut().for_each(|c| *c = 0.0);
        let answer = |x: Vec<f64>| LpSolution {
            status: LpStatus::Optimal,
            objective: 0.0,
            x,
            row_dual: vec![],
            col_dual: vec![],
            iterations: 1,
            dual_objective: f64::NAN,
            reduced_accuracy: false,
            method: Method::Clarabel,
            tried: vec![],
        };
        // Rows x0 + 2 x1 ≤ 4 and 3 x0 + x1 ≤ 6 at (1.6, 1.2): both tight.
        assert_eq!(
            Outcome::of(&lp, &answer(vec![1.6, 1.2])),
            Outcome::Certified
        );
        // Within the solver layer's tolerance (5e-7 of the row's terms), and 1 % over.
        assert_eq!(
            Outcome::of(&lp, &answer(vec![1.6, 1.2 + 1e-6])),
            Outcome::Certified
        );
        assert_eq!(
            Outcome::of(&lp, &answer(vec![1.6, 1.22])),
            Outcome::NotCertified
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
