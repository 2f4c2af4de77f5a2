//! The Clarabel backend: an interior-point method (direct sparse LDLᵀ, QDLDL) for LPs and for
//! programs with second-order cones (exact crushing domains). The only file that names Clarabel.

use super::{
    Backend, Basis, Cone3, LinearProgram, LpSolution, LpStatus, Method, Solved, SolverOptions,
};
use crate::error::{Error, Result};

/// The Clarabel backend. It has no basis: warm starts solve from scratch.
pub struct Clarabel;

impl Backend for Clarabel {
    fn name(&self) -> &'static str {
        "clarabel"
    }

    fn supports_cones(&self) -> bool {
        true
    }

    fn solve(
        &self,
        lp: &LinearProgram,
        cones: &[Cone3],
        o: &SolverOptions,
        _start: Option<&Basis>,
    ) -> Result<Solved> {
        let solution = if cones.is_empty() && o.presolve && presolve_pays(lp) {
            solve_presolved(lp, o)?
        } else {
            solve_clarabel(lp, cones, o, large(lp, cones) && !o.decision)?
        };
        Ok(Solved {
            solution,
            basis: None,
        })
    }

    fn supports_quadratic(&self) -> bool {
        true
    }

    fn solve_quadratic(
        &self,
        lp: &LinearProgram,
        quadratic: &[(usize, usize, f64)],
        o: &SolverOptions,
    ) -> Result<Solved> {
        Ok(Solved {
            solution: solve_clarabel_with_cones(lp, o, &[], quadratic, false)?,
            basis: None,
        })
    }
}

/// The smallest LP that goes through HiGHS's presolve before Clarabel (about 5,000 wall units).
/// Presolve pays on large programs (measured from 4,000 units on); a small program is solved as
/// given, so that its duals are Clarabel's own: HiGHS's postsolve without a basis loosened the
/// duals of a small frictional settlement to a gap of 7e-6 (`tests/nonassociative_settlement`).
pub const PRESOLVE_MIN_COLUMNS: usize = 20_000;

/// Whether a program is a large plain LP (at least [`PRESOLVE_MIN_COLUMNS`] columns, no
/// cones), solved with the tighter settings of `solve_clarabel_with_cones`. Small programs keep
/// Clarabel's defaults: with the tighter ones the non-associative friction iteration on a
/// 40-block wall cycled among three values instead of converging (`tests/joint_laws_cli.rs`).
fn large(lp: &LinearProgram, cones: &[Cone3]) -> bool {
    cones.is_empty() && lp.num_cols() >= PRESOLVE_MIN_COLUMNS
}

/// Whether an LP goes through HiGHS's presolve before Clarabel: at least
/// [`PRESOLVE_MIN_COLUMNS`] columns, and every row an equation (the force LPs of no-sliding
/// joints: equilibrium rows only). With inequality rows (friction, crushing polygons) HiGHS's
/// postsolve without a basis returned duals whose mechanism violated the joints by 2e-5 at
/// 4,000 friction-wall units and 1e-2 at 16,000 (measured): those programs go to Clarabel as
/// they are.
pub fn presolve_pays(lp: &LinearProgram) -> bool {
    large(lp, &[])
        && lp
            .row_lower
            .iter()
            .zip(&lp.row_upper)
            .all(|(lo, hi)| lo == hi)
}

/// An LP through HiGHS's presolve: Clarabel solves the reduced program (at 16,000 wall units
/// less than half the rows and columns of the force LP: free shear forces substituted out by
/// the aggregator, duplicate shear columns, columns left empty), HiGHS's postsolve maps its
/// primal-dual pair back (docs/performance.md: 1.4–2.7× faster at 16,000–64,000 units). When presolve does not
/// reduce the program, or the reduced program is not solved to optimality, or the pair cannot
/// be mapped back, the original program is solved as it is (so statuses are the original's).
///
/// The postsolved pair is checked on the original program ([`super::policy::check`]): HiGHS's
/// postsolve without a basis can return duals that do not price it. Measured on the limit
/// program of the 48 × 48 dome (2,257 blocks, 13,542 rows × 54,721 columns, every row an
/// equation): the postsolved duals had a duality gap of 1.8e-1 (λ right to 1e-9), so the
/// fallback chain went on to HiGHS's interior point, about 95 CPU s, where Clarabel on the
/// program as it is certified in the same 4.4 CPU s as on the reduced one (gap 5.8e-9;
/// docs/performance.md, "Dome 48 × 48 (session 17)"). Such an answer is replaced by Clarabel's
/// on the program as it is.
fn solve_presolved(lp: &LinearProgram, o: &SolverOptions) -> Result<LpSolution> {
    // A presolve that fails is no reason not to solve: the program goes to Clarabel as it is.
    let tracing = std::env::var_os("VOUSSOIR_TRACE").is_some();
    let t0 = std::time::Instant::now();
    if let Ok(Some(pre)) = super::highs::presolve(lp, o) {
        let reduced = solve_clarabel(&pre.lp, &[], o, true)?;
        let (rows, cols) = (pre.lp.num_rows(), pre.lp.num_cols());
        let why = if reduced.status == LpStatus::Optimal {
            match pre.postsolve(lp, &reduced) {
                Some(s) => match super::policy::check(lp, &s) {
                    None => {
                        if tracing {
                            eprintln!(
                                "trace: clarabel on the presolved program ({rows} × {cols}): {} iterations, {:.3} s",
                                reduced.iterations,
                                t0.elapsed().as_secs_f64()
                            );
                        }
                        return Ok(s);
                    }
                    Some(why) => why,
                },
                None => "no postsolve".to_string(),
            }
        } else {
            format!("status {:?}", reduced.status)
        };
        if tracing {
            eprintln!(
                "trace: clarabel on the presolved program ({rows} × {cols}) not used after {:.3} s: {why}",
                t0.elapsed().as_secs_f64()
            );
        }
    }
    solve_clarabel(lp, &[], o, true)
}

/// Solve with Clarabel: `min cᵀx` with `A x + s = b`, `s` in the zero cone (equality rows and
/// fixed variables) or the non-negative cone (each finite side of a range row or bound). Row
/// duals are returned with HiGHS's convention (`c − Aᵀy` are the reduced costs of a
/// minimisation; negated for a maximisation).
fn solve_clarabel(
    lp: &LinearProgram,
    cones: &[Cone3],
    o: &SolverOptions,
    tight: bool,
) -> Result<LpSolution> {
    // Identical columns (same entries, cost and bounds, each free or non-negative, in no cone)
    // are one variable for the solver: in the force LP the two shear forces of a straight
    // joint have the same column (a singular KKT system otherwise, which the cones' extreme
    // curvature at high compressive strength does not forgive). The merged value goes to the
    // first of them.
    let mut in_cone = vec![false; lp.num_cols()];
    for c in cones {
        for (entries, _) in c {
            for &(j, _) in entries {
                in_cone[j] = true;
            }
        }
    }
    let (reduced, map) = merge_duplicate_columns(lp, &in_cone);
    let cones: Vec<Cone3> = cones
        .iter()
        .map(|c| {
            c.clone()
                .map(|(e, b)| (e.into_iter().map(|(j, v)| (map[j], v)).collect(), b))
        })
        .collect();
    let mut sol = solve_clarabel_with_cones(&reduced, o, &cones, &[], tight)?;
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
fn merge_duplicate_columns(lp: &LinearProgram, keep: &[bool]) -> (LinearProgram, Vec<usize>) {
    use std::collections::HashMap;
    let mergeable = |j: usize| {
        !keep[j]
            && lp.col_upper[j] == f64::INFINITY
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

/// Solve `lp` with Clarabel, with extra second-order cones appended (none for a plain LP) and
/// a quadratic term `½ xᵀPx` (upper triangle triplets; none for a plain LP or cone program);
/// `tight`: the settings of a large plain LP ([`large`]; never with cones or a quadratic term).
fn solve_clarabel_with_cones(
    lp: &LinearProgram,
    o: &SolverOptions,
    socs: &[Cone3],
    quadratic: &[(usize, usize, f64)],
    tight: bool,
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
    let p = if quadratic.is_empty() {
        CscMatrix::<f64>::zeros((n, n))
    } else {
        CscMatrix::new_from_triplets(
            n,
            n,
            quadratic.iter().map(|t| t.0).collect(),
            quadratic.iter().map(|t| t.1).collect(),
            quadratic.iter().map(|t| t.2).collect(),
        )
    };
    let q: Vec<f64> = lp.cost.iter().map(|c| sign * c).collect();
    let mut cones: Vec<SupportedConeT<f64>> = Vec::new();
    if !zero.is_empty() {
        cones.push(SupportedConeT::ZeroConeT(zero.len()));
    }
    if !nonneg.is_empty() {
        cones.push(SupportedConeT::NonnegativeConeT(nonneg.len()));
    }
    cones.extend(socs.iter().map(|_| SupportedConeT::SecondOrderConeT(3)));
    // A plain LP is stopped one decade below the feasibility tolerance asked for, with the
    // static regularisation of the KKT system at 1e-10 instead of Clarabel's 1e-8: the
    // mechanism is read from the duals, and with the default regularisation the 64,000-unit
    // limit LP ended after 73 iterations at a λ 1 % low with a mechanism violating the joints
    // by 3e-3; with these settings it ends after 16 iterations, certified (docs/performance.md).
    // Programs with cones and small LPs ([`large`]) keep Clarabel's defaults.
    let tol = if tight {
        0.1 * o.feasibility_tolerance
    } else {
        o.feasibility_tolerance
    }
    .clamp(1e-12, 1e-4);
    let settings = DefaultSettings {
        verbose: o.log,
        tol_gap_abs: tol,
        tol_gap_rel: tol,
        tol_feas: tol,
        time_limit: o.time_limit.unwrap_or(f64::INFINITY),
        max_iter: o
            .iteration_limit
            .map_or(500, |n| n.min(u32::MAX as usize) as u32),
        static_regularization_constant: if tight { 1e-10 } else { 1e-8 },
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
    let reduced_accuracy = sol.status == SolverStatus::AlmostSolved;
    if status != LpStatus::Optimal {
        return Ok(LpSolution {
            status,
            objective: f64::NAN,
            x: vec![],
            row_dual: vec![],
            col_dual: vec![],
            iterations,
            dual_objective: f64::NAN,
            reduced_accuracy: false,
            method: Method::Clarabel,
            tried: Vec::new(),
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
    let quad: f64 = quadratic
        .iter()
        .map(|&(i, j, v)| {
            if i == j {
                0.5 * v * x[i] * x[i]
            } else {
                v * x[i] * x[j]
            }
        })
        .sum();
    let objective = lp.objective(&x) + quad;
    Ok(LpSolution {
        status,
        objective,
        x,
        row_dual,
        col_dual,
        iterations,
        // Clarabel minimises `sign·cᵀx`; its dual cost is in that sense.
        dual_objective: sign * solver.info.cost_dual,
        reduced_accuracy,
        method: Method::Clarabel,
        tried: Vec::new(),
    })
}

/// A sparse `LDLᵀ` factorisation of a symmetric quasi-definite matrix (Clarabel's QDLDL, with
/// its AMD ordering), for [`super::sequence::Lineality`]: the projection onto the null space of
/// a program's free columns, factorised once and applied to many objectives.
pub struct QuasiDefinite {
    factor: clarabel::qdldl::QDLDLFactorisation<f64>,
}

impl QuasiDefinite {
    /// The factorisation of the `n × n` matrix whose upper triangle is given by columns
    /// (`upper[j]`: `(row, value)` with `row ≤ j`, sorted by row, the diagonal included), with
    /// the signs (+1 or −1) of its pivots. `None` where QDLDL refuses it.
    pub fn new(upper: &[Vec<(usize, f64)>], signs: Vec<i8>) -> Option<QuasiDefinite> {
        use clarabel::algebra::CscMatrix;
        use clarabel::qdldl::{QDLDLFactorisation, QDLDLSettingsBuilder};
        let n = upper.len();
        if signs.len() != n {
            return None;
        }
        let mut colptr = Vec::with_capacity(n + 1);
        let (mut rowval, mut nzval) = (Vec::new(), Vec::new());
        colptr.push(0);
        for col in upper {
            for &(i, v) in col {
                rowval.push(i);
                nzval.push(v);
            }
            colptr.push(rowval.len());
        }
        let k = CscMatrix::new(n, n, colptr, rowval, nzval);
        let settings = QDLDLSettingsBuilder::default().Dsigns(signs).build().ok()?;
        QDLDLFactorisation::new(&k, Some(settings))
            .ok()
            .map(|factor| QuasiDefinite { factor })
    }

    /// Solve in place (`b` becomes the solution).
    pub fn solve(&mut self, b: &mut [f64]) {
        if b.len() == self.factor.D.len() {
            self.factor.solve(b);
        }
    }
}
