//! Sequences of programs solved as sequences: one constraint matrix, a changing objective or
//! changing bounds, one solver instance.
//!
//! The reaction ranges of `safety` are 2·N programs per support over one feasible set (the
//! statically admissible states), differing only in their objective. Solved one by one, each
//! is built, presolved and factorised from scratch. A [`Sequence`] keeps one HiGHS instance
//! ([`super::highs::Persistent`]): the first program is solved with the requested method
//! (interior point with crossover, or a simplex), and every later one starts from the optimal
//! basis and the factorisation the previous one left — after a change of objective the basis
//! is still primal feasible, so the primal simplex goes on from it; after a change of bounds
//! (a bisection's right-hand side) it is still dual feasible, so the dual simplex does.
//!
//! Nothing is taken on trust from the warm start: each optimum is checked by its
//! [`Certificate`] (primal feasibility, dual feasibility and the duality gap, recomputed from
//! the solution on the program as written), and a program whose warm run fails or does not
//! certify is solved from scratch through [`super::solve_warm`] with the method's whole
//! fallback chain ([`super::fallback_chain`]); the sequence then goes on warm from the basis
//! that solve left. Backends without a basis (Clarabel) solve every program from scratch.

use super::highs::Persistent;
use super::{
    solve_warm, Basis, Direction, LinearProgram, LpSolution, LpStatus, Scaling, SolverOptions,
};
use crate::error::{Error, Result};

/// Largest relative primal violation, dual violation and duality gap of a certified optimum.
pub const CERTIFICATE_TOLERANCE: f64 = 1e-7;

/// The optimality certificate of a solution, recomputed on the program as written: how far
/// `x` is from feasible, how far the duals are from feasible, and the gap between the primal
/// objective and the dual bound the duals give. Each is relative to its own scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Certificate {
    /// The largest violation of a row or bound by `x`, relative to the row's own size
    /// (`Σ |a_ij x_j|` and its bounds) but never to less than a thousandth of the largest row's
    /// (a friction row whose terms are round-off is not judged by its round-off).
    pub primal: f64,
    /// The largest reduced cost of the wrong sign on a column without the bound it would
    /// price, relative to the size of the terms that make it up (`|c_j| + Σ|a_ij y_i|`) but
    /// never to less than a thousandth of the largest column's (a reduced cost of 1e-13 made
    /// of duals of 1e-13 is round-off, not a violation).
    pub dual: f64,
    /// `|cᵀx − dual bound|` relative to `Σ |c_j x_j|` (and the two values).
    pub gap: f64,
}

impl Certificate {
    /// All three within [`CERTIFICATE_TOLERANCE`].
    pub fn ok(&self) -> bool {
        self.primal <= CERTIFICATE_TOLERANCE
            && self.dual <= CERTIFICATE_TOLERANCE
            && self.gap <= CERTIFICATE_TOLERANCE
    }
}

/// The certificate of an optimal solution `s` of `lp` (`None` for another status or a
/// solution without duals). HiGHS's and Clarabel's convention: `c − Aᵀy − z = 0` in the
/// program's own sense.
pub fn certify(lp: &LinearProgram, s: &LpSolution) -> Option<Certificate> {
    certify_with_bound(lp, s).map(|(c, _)| c)
}

/// [`certify`], and the dual bound the duals give (the objective value no feasible point of
/// `lp` can beat where the duals are feasible), in the program's own sense.
pub(crate) fn certify_with_bound(lp: &LinearProgram, s: &LpSolution) -> Option<(Certificate, f64)> {
    let (n, m) = (lp.num_cols(), lp.num_rows());
    if s.status != LpStatus::Optimal || s.x.len() != n || s.row_dual.len() != m {
        return None;
    }
    // As a minimisation: c̃ = σc, ỹ = σy (σ = −1 for a maximisation).
    let sigma = if lp.maximise { -1.0 } else { 1.0 };
    // Row duals of the wrong sign on a side without a bound are dropped (round-off of the
    // solver's own tolerances; what they would have priced shows in the reduced costs).
    let y: Vec<f64> = (0..m)
        .map(|i| {
            let v = sigma * s.row_dual[i];
            if (v > 0.0 && lp.row_lower[i] == f64::NEG_INFINITY)
                || (v < 0.0 && lp.row_upper[i] == f64::INFINITY)
            {
                0.0
            } else {
                v
            }
        })
        .collect();
    let mut dual_bound = 0.0;
    for i in 0..m {
        if y[i] > 0.0 {
            dual_bound += y[i] * lp.row_lower[i];
        } else if y[i] < 0.0 {
            dual_bound += y[i] * lp.row_upper[i];
        }
    }
    // Each column's reduced cost `z_j = c̃_j − Σ a_ij ỹ_i` and the size of the terms that
    // make it up. A column whose terms are all round-off (no cost, duals of 1e-13 on its rows)
    // is judged against a thousandth of the largest column's size, as the primal rows are:
    // otherwise a reduced cost of 1e-13 made of terms of 1e-13 would count as a violation of 1.
    let mut reduced = Vec::with_capacity(n);
    let mut primal_size = 0.0;
    let mut primal_objective = 0.0;
    for j in 0..n {
        let c = sigma * lp.cost[j];
        let (mut aty, mut size) = (0.0, c.abs());
        for (i, a) in lp.column(j) {
            aty += a * y[i];
            size += (a * y[i]).abs();
        }
        primal_objective += c * s.x[j];
        primal_size += (c * s.x[j]).abs();
        reduced.push((c - aty, size));
    }
    let floor = 1e-3 * reduced.iter().fold(0.0f64, |m, r| m.max(r.1));
    let relative = |z: f64, size: f64| {
        let size = size.max(floor);
        if size > 0.0 {
            z.abs() / size
        } else {
            f64::INFINITY
        }
    };
    let mut dual = 0.0f64;
    for (j, &(z, size)) in reduced.iter().enumerate() {
        let (lo, hi) = (lp.col_lower[j], lp.col_upper[j]);
        if z > 0.0 {
            if lo == f64::NEG_INFINITY {
                dual = dual.max(relative(z, size));
            } else {
                dual_bound += z * lo;
            }
        } else if z < 0.0 {
            if hi == f64::INFINITY {
                dual = dual.max(relative(z, size));
            } else {
                dual_bound += z * hi;
            }
        }
    }
    let den = primal_size
        .max(primal_objective.abs())
        .max(dual_bound.abs());
    let gap = if den > 0.0 {
        (primal_objective - dual_bound).abs() / den
    } else {
        0.0
    };
    Some((
        Certificate {
            primal: primal_violation(lp, &s.x),
            dual,
            gap: if gap.is_nan() { f64::INFINITY } else { gap },
        },
        sigma * dual_bound,
    ))
}

/// The least relative decrease of the objective along a ray that certifies an unbounded
/// optimum ([`certify_ray`]): `−σ cᵀd ≥ RAY_DECREASE · ‖c‖₁ ‖d‖∞`, so that round-off of a
/// direction along which the objective is constant does not pass for a decrease.
pub const RAY_DECREASE: f64 = 1e-6;

/// The recession program of `lp`: its rows and columns with every finite bound moved to 0 —
/// the directions `d` along which a feasible point stays feasible (`x + t d` for every
/// `t ≥ 0`) — within the box `|d_j| ≤ 1`, which makes it feasible (`d = 0`) and bounded. Its
/// optimum is below 0 exactly when the objective of `lp` (over a nonempty feasible set) is
/// unbounded, and its solution is then a ray that certifies it ([`certify_ray`]).
pub fn recession_program(lp: &LinearProgram) -> LinearProgram {
    let mut r = lp.clone();
    let rec = |b: f64| if b.is_finite() { 0.0 } else { b };
    for i in 0..r.num_rows() {
        r.row_lower[i] = rec(r.row_lower[i]);
        r.row_upper[i] = rec(r.row_upper[i]);
    }
    for j in 0..r.num_cols() {
        r.col_lower[j] = rec(r.col_lower[j]).max(-1.0);
        r.col_upper[j] = rec(r.col_upper[j]).min(1.0);
    }
    r
}

/// The certificate of a ray `d` of `lp`: how far it is from a recession direction and how
/// much the objective improves along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayCertificate {
    /// The largest relative violation of the recession program's rows and bounds by `d`
    /// (measured as [`Certificate::primal`]).
    pub violation: f64,
    /// `−σ cᵀd / (‖c‖₁ ‖d‖∞)` (σ = −1 for a maximisation): at most 1, 0 or less where `d`
    /// does not improve the objective.
    pub decrease: f64,
}

impl RayCertificate {
    /// `d` is a recession direction within [`CERTIFICATE_TOLERANCE`] and improves the
    /// objective by at least [`RAY_DECREASE`]: with any feasible point, the objective of `lp`
    /// is unbounded.
    pub fn ok(&self) -> bool {
        self.violation <= CERTIFICATE_TOLERANCE && self.decrease >= RAY_DECREASE
    }
}

/// The certificate of the ray `d` for the objective of `lp` ([`RayCertificate`]).
pub fn certify_ray(lp: &LinearProgram, d: &[f64]) -> RayCertificate {
    if d.len() != lp.num_cols() || d.iter().any(|v| !v.is_finite()) {
        return RayCertificate {
            violation: f64::INFINITY,
            decrease: 0.0,
        };
    }
    RayCertificate {
        violation: ray_violation(lp, d),
        decrease: ray_decrease(lp, d),
    }
}

/// How much the objective of `lp` improves along `d` ([`RayCertificate::decrease`]).
pub fn ray_decrease(lp: &LinearProgram, d: &[f64]) -> f64 {
    if d.len() != lp.num_cols() || d.iter().any(|v| !v.is_finite()) {
        return 0.0;
    }
    let sigma = if lp.maximise { -1.0 } else { 1.0 };
    // Relative to the objective's size times the ray's (not to `Σ |c_j d_j|`: a ray whose
    // entries on the objective's columns are round-off, 1e-16, would improve it by 100 %).
    let (mut cd, mut c1, mut dmax) = (0.0, 0.0, 0.0f64);
    for (c, v) in lp.cost.iter().zip(d) {
        cd += sigma * c * v;
        c1 += c.abs();
        dmax = dmax.max(v.abs());
    }
    let size = c1 * dmax;
    if size > 0.0 {
        -cd / size
    } else {
        0.0
    }
}

/// How far `d` is from a recession direction of `lp` ([`RayCertificate::violation`]: the
/// largest relative violation of the rows and bounds of [`recession_program`], computed without
/// building it). It depends on the matrix and the bounds only, not on the objective, so a ray
/// kept for a sequence of objectives is measured once.
pub fn ray_violation(lp: &LinearProgram, d: &[f64]) -> f64 {
    let rec = |b: f64| if b.is_finite() { 0.0 } else { b };
    violation_with(lp, d, rec, |b, lo| {
        let r = rec(b);
        if lo {
            r.max(-1.0)
        } else {
            r.min(1.0)
        }
    })
}

/// The directions along the program's free columns that keep every row with a bound as it
/// is — `d` with `d_j = 0` on every column with a finite bound and `A_i d = 0` on every row
/// with a finite bound: rays of the program both ways (a lineality space of its recession
/// cone; in the force programs of no-sliding joints, self-equilibrated shear) — and the
/// projection of an objective onto them, factorised once for many objectives.
///
/// The projection `d = P c` of a cost vector `c` (on the free columns) is the least-squares
/// solution of `min ‖d − c‖²` subject to `A_F d = 0`, from the quasi-definite system
/// `[I A_Fᵀ; A_F −δI]` (rows scaled to a largest entry of 1, `δ` = 1e-8, four steps of
/// iterative refinement on the system with `δ = 0`). Where `c` has a component in that space,
/// `cᵀd = ‖d‖² > 0`: `−d` decreases the objective without end and `d` increases it, each
/// certified by [`certify_ray`] as any ray. Where it has none (a bounded side) `d` is
/// round-off, and the certificate refuses it.
pub struct Lineality {
    /// The free columns of the program.
    free: Vec<usize>,
    /// Per free column: its entries on the rows with a bound, `(row position, scaled value)`.
    entries: Vec<Vec<(usize, f64)>>,
    /// The rows with a bound.
    rows: usize,
    columns: usize,
    factor: super::clarabel::QuasiDefinite,
}

impl Lineality {
    /// The factorisation for `lp`; `None` where it has no free column or the factorisation is
    /// refused.
    pub fn new(lp: &LinearProgram) -> Option<Lineality> {
        let free: Vec<usize> = (0..lp.num_cols())
            .filter(|&j| lp.col_lower[j] == f64::NEG_INFINITY && lp.col_upper[j] == f64::INFINITY)
            .collect();
        if free.is_empty() {
            return None;
        }
        // Rows with a bound, numbered 0.. in order; each scaled to a largest free entry of 1.
        let mut position = vec![usize::MAX; lp.num_rows()];
        let mut rows = 0;
        for (i, p) in position.iter_mut().enumerate() {
            if lp.row_lower[i].is_finite() || lp.row_upper[i].is_finite() {
                *p = rows;
                rows += 1;
            }
        }
        let mut largest = vec![0.0f64; rows];
        for &j in &free {
            for (i, v) in lp.column(j) {
                if position[i] != usize::MAX {
                    largest[position[i]] = largest[position[i]].max(v.abs());
                }
            }
        }
        let entries: Vec<Vec<(usize, f64)>> = free
            .iter()
            .map(|&j| {
                let mut e: Vec<(usize, f64)> = lp
                    .column(j)
                    .filter(|&(i, v)| position[i] != usize::MAX && v != 0.0)
                    .map(|(i, v)| (position[i], v / largest[position[i]]))
                    .collect();
                e.sort_by_key(|&(r, _)| r);
                e
            })
            .collect();
        let nf = free.len();
        // The upper triangle by columns: the identity on the free columns, then per row its
        // free entries above the diagonal −δ.
        let mut upper: Vec<Vec<(usize, f64)>> = (0..nf).map(|k| vec![(k, 1.0)]).collect();
        let mut by_row: Vec<Vec<(usize, f64)>> = vec![Vec::new(); rows];
        for (k, e) in entries.iter().enumerate() {
            for &(r, v) in e {
                by_row[r].push((k, v));
            }
        }
        for (r, mut col) in by_row.into_iter().enumerate() {
            col.push((nf + r, -LINEALITY_DELTA));
            upper.push(col);
        }
        let signs: Vec<i8> = (0..nf + rows)
            .map(|k| if k < nf { 1 } else { -1 })
            .collect();
        let factor = super::clarabel::QuasiDefinite::new(&upper, signs)?;
        Some(Lineality {
            free,
            entries,
            rows,
            columns: lp.num_cols(),
            factor,
        })
    }

    /// `P c`: the projection of the cost vector `cost` (one entry per column of the program)
    /// onto the lineality space, as a vector of the program's columns (0 off the free ones).
    pub fn project(&mut self, cost: &[f64]) -> Vec<f64> {
        let nf = self.free.len();
        let c: Vec<f64> = self
            .free
            .iter()
            .map(|&j| cost.get(j).copied().unwrap_or(0.0))
            .collect();
        let mut d = vec![0.0; nf];
        let mut y = vec![0.0; self.rows];
        // Residual of `[I Aᵀ; A 0][d; y] = [c; 0]`, solved with the regularised factor and
        // refined.
        for _ in 0..4 {
            let mut r = vec![0.0; nf + self.rows];
            for k in 0..nf {
                let mut aty = 0.0;
                for &(i, v) in &self.entries[k] {
                    aty += v * y[i];
                    r[nf + i] -= v * d[k];
                }
                r[k] = c[k] - d[k] - aty;
            }
            self.factor.solve(&mut r);
            for k in 0..nf {
                d[k] += r[k];
            }
            for i in 0..self.rows {
                y[i] += r[nf + i];
            }
        }
        let mut out = vec![0.0; self.columns];
        for (k, &j) in self.free.iter().enumerate() {
            out[j] = d[k];
        }
        out
    }
}

/// The regularisation of [`Lineality`]'s quasi-definite system (rows scaled to a largest entry
/// of 1); the iterative refinement removes its effect.
const LINEALITY_DELTA: f64 = 1e-8;

/// The elastic program of `lp`: its objective dropped, every row with a bound given a pair
/// of slacks `s⁺ − s⁻` (each ≥ 0, cost 1), so that it is always feasible and its optimum is the
/// least total violation of `lp`'s rows (its columns' bounds are kept).
pub fn elastic_program(lp: &LinearProgram) -> LinearProgram {
    let mut e = lp.clone();
    e.maximise = false;
    e.cost.iter_mut().for_each(|c| *c = 0.0);
    for i in 0..lp.num_rows() {
        if lp.row_lower[i].is_finite() || lp.row_upper[i].is_finite() {
            e.add_column(1.0, 0.0, f64::INFINITY, [(i, 1.0)]);
            e.add_column(1.0, 0.0, f64::INFINITY, [(i, -1.0)]);
        }
    }
    e
}

/// The least total violation, relative to the largest finite row bound, up to which
/// [`decide_feasibility`] calls a program feasible (an interior point's resolution).
pub const FEASIBLE_RESOLUTION: f64 = 1e-7;

/// The least violation that [`decide_feasibility`]'s dual bound must exceed, relative to the
/// largest finite row bound, to call a program infeasible.
pub const INFEASIBLE_MARGIN: f64 = 1e-6;

/// The least violation, relative to the largest finite row bound, above which
/// [`decide_feasibility`] accepts a Farkas certificate whose halves (the elastic point, the
/// duals) and gap hold only to the solver layer's answer tolerance
/// ([`super::policy::CERTIFICATE_TOLERANCE`]): a program that far from feasible is not made
/// feasible by round-off.
pub const FAR_INFEASIBLE: f64 = 1e-3;

/// A decision of feasibility with its certificate, either way ([`decide_feasibility`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FeasibilityDecision {
    /// Whether `lp` has a point within the tolerance.
    pub feasible: bool,
    /// The least total violation of the rows, relative to the largest finite row bound.
    pub violation: f64,
    /// The certificate of the elastic program's optimum ([`certify`]): its duals are, where
    /// the violation is positive, a Farkas certificate of infeasibility (row multipliers that
    /// combine the rows into a contradiction with the columns' bounds).
    pub certificate: Certificate,
}

/// Decide whether `lp` (its objective ignored) is feasible, with a certificate either way: the
/// elastic program ([`elastic_program`]) solved with `opts`. Feasible: its point holds the
/// elastic rows (primal certificate) with a least total violation, relative to the largest
/// finite row bound, of at most `tolerance.max(FEASIBLE_RESOLUTION)`. Infeasible: its duals are
/// dual feasible (dual certificate) and bound that violation from below by more than
/// `tolerance.max(INFEASIBLE_MARGIN)` (a Farkas certificate); far from feasible (a bound above
/// [`FAR_INFEASIBLE`]), duals feasible to the solver layer's answer tolerance with the primal
/// half and the gap agreeing are enough. `None` in between, where neither
/// half certifies, or where the method fails: `opts.method` alone is run, without its
/// fallback chain (the caller chains methods; a chain that ended in HiGHS's simplex stalled for
/// minutes in phase 1 on the 24 × 24 dome's elastic programs).
pub fn decide_feasibility(
    lp: &LinearProgram,
    opts: &SolverOptions,
    tolerance: f64,
) -> Result<Option<FeasibilityDecision>> {
    // Decided on the nondimensional program ([`Scaling`]): a violation is measured against
    // the largest bound only where every row is in the same unit — as written, a moment row's
    // violation (kN·m) set against the largest force (kN) turned a stack of boxes ×0.003 into
    // "stands" at a fraction 2e-4 short of the hand value 3/7 (`tests/solver_fallback.rs`).
    let scaled = Scaling::of(lp, &[]).apply(lp);
    let lp = &scaled;
    let e = elastic_program(lp);
    super::check_numbers(&e)?;
    let Ok(s) = super::solve_once(&e, opts) else {
        return Ok(None);
    };
    let Some((certificate, bound)) = certify_with_bound(&e, &s) else {
        return Ok(None);
    };
    let scale = lp
        .row_lower
        .iter()
        .chain(&lp.row_upper)
        .filter(|b| b.is_finite())
        .fold(0.0f64, |m, b| m.max(b.abs()));
    let violation = if scale > 0.0 {
        s.objective.max(0.0) / scale
    } else if s.objective > 0.0 {
        f64::INFINITY
    } else {
        0.0
    };
    // Each side needs only its half of the certificate: "feasible" a point (the elastic
    // program's, its rows held) whose total violation is within the tolerance; "infeasible"
    // duals that are dual feasible and bound the least violation above the tolerance (a
    // Farkas certificate). Near the threshold the optimum is 0 or nearly so, and a duality
    // gap between two vanishing numbers says nothing (it failed to certify on the 24 × 24
    // dome where both sides were decided).
    let relative = |v: f64| {
        if scale > 0.0 {
            v / scale
        } else if v > 0.0 {
            f64::INFINITY
        } else {
            0.0
        }
    };
    // An interior point resolves the least violation to about 1e-8 of the largest load
    // (Clarabel's elastic optimum of a feasible 24 × 24 dome program: 4e-8–7e-8), and its
    // duals bound it only to that resolution: "feasible" within FEASIBLE_RESOLUTION,
    // "infeasible" only with a bound INFEASIBLE_MARGIN above 0 (a bound of 1e-9 with duals
    // certified to 1e-7 once declared a feasible program infeasible); in between, undecided.
    let decided = decision(&certificate, violation, relative(bound), tolerance);
    if decided.is_some() {
        super::record_run(opts.method, &[], false, || super::Outcome::Certified);
    } else if std::env::var_os("VOUSSOIR_TRACE").is_some() {
        // Which half of the certificate failed (docs/performance.md, "Façade capacity
        // (session 22)").
        eprintln!(
            "trace: feasibility undecided by {}: primal {:.1e}, violation {:.3e} (feasible up to {:.0e}); dual {:.1e}, bound {:.3e} (infeasible above {:.0e}); reduced accuracy {}",
            opts.method.name(),
            certificate.primal,
            violation,
            tolerance.max(FEASIBLE_RESOLUTION),
            certificate.dual,
            relative(bound),
            tolerance.max(INFEASIBLE_MARGIN),
            s.reduced_accuracy
        );
    }
    Ok(decided.map(|feasible| FeasibilityDecision {
        feasible,
        violation,
        certificate,
    }))
}

/// [`decide_feasibility`]'s rule: feasible (`Some(true)`), infeasible (`Some(false)`) or
/// undecided, from the elastic optimum's certificate `c`, its least violation and the dual
/// bound on it (both relative to the largest finite row bound) and the caller's `tolerance`.
fn decision(c: &Certificate, violation: f64, bound: f64, tolerance: f64) -> Option<bool> {
    if c.primal <= CERTIFICATE_TOLERANCE && violation <= tolerance.max(FEASIBLE_RESOLUTION) {
        Some(true)
    } else if c.dual <= CERTIFICATE_TOLERANCE && bound > tolerance.max(INFEASIBLE_MARGIN) {
        Some(false)
    } else if c.dual <= super::policy::CERTIFICATE_TOLERANCE
        && c.primal <= super::policy::CERTIFICATE_TOLERANCE
        && c.gap <= super::policy::CERTIFICATE_TOLERANCE
        && bound > tolerance.max(FAR_INFEASIBLE)
    {
        // Far from feasible, both halves agreeing: the elastic point and the duals feasible
        // to the solver layer's certificate tolerance (1e-6, that of every answer,
        // `policy::check`) rather than 1e-7, where the bound the duals give and the point's
        // own violation agree and exceed a thousandth of the largest load. Clarabel's answers
        // on the 0.5 m grid façade's settled capacity steps stop at primal 5e-8–3.4e-7 and
        // dual 1.2e-7–1.9e-7 at reduced accuracy with a violation and a bound of 217–267
        // times the largest load (undecided before: the chain went on to the simplex, 35–107
        // s a step, to decide the same), docs/
        // performance.md "Capacity of the 0.5 m grid façade (session 27)". Duals off by 1e-6
        // of their terms move a bound by about 1e-6 of the forces' size, not by a thousandth
        // of the load, unless the forces were a thousand million times the load.
        Some(false)
    } else {
        None
    }
}

/// How far `x` is from a point of `lp` (its objective ignored), measured as
/// [`decide_feasibility`] measures a violation: on the nondimensional program ([`Scaling`]),
/// with `x` clamped onto its column bounds (a simplex leaves basic values up to its tolerance
/// outside them: a force of −1e-13 where `p_n ≥ 0`), the largest violation of a row relative to
/// the largest finite row bound (in a force program the largest load). Each row on its own
/// scale ([`LinearProgram::relative_violation`]) is not a measure of a simplex's vertex: a
/// block's horizontal equilibrium row with no horizontal load, whose forces are round-off
/// (1e-13), is "violated" by 1 (measured: every warm decision of `safety` on the 0.5 m façade,
/// docs/performance.md, "Façade safety and capacity (session 18)").
pub fn point_violation(lp: &LinearProgram, x: &[f64]) -> f64 {
    if x.len() != lp.num_cols() || x.iter().any(|v| !v.is_finite()) {
        return f64::INFINITY;
    }
    let scaling = Scaling::of(lp, &[]);
    let scaled = scaling.apply(lp);
    let xs: Vec<f64> = x.iter().zip(&scaling.col).map(|(v, c)| v / c).collect();
    let xs = scaled.clamped(&xs);
    let act = scaled.row_activity(&xs);
    let scale = scaled
        .row_lower
        .iter()
        .chain(&scaled.row_upper)
        .filter(|b| b.is_finite())
        .fold(0.0f64, |m, b| m.max(b.abs()));
    let worst = (0..scaled.num_rows())
        .map(|i| {
            (scaled.row_lower[i] - act[i])
                .max(act[i] - scaled.row_upper[i])
                .max(0.0)
        })
        .fold(0.0f64, f64::max);
    if worst == 0.0 {
        0.0
    } else if scale > 0.0 {
        worst / scale
    } else {
        f64::INFINITY
    }
}

/// Whether `lp` (its objective ignored) is feasible by one run of `opts.method` alone on the
/// program itself (its zero-objective form, no elastic slacks; Clarabel answers it on the
/// 24 × 24 dome in 0.3–0.5 s where the elastic program takes 0.7–1 s): `Some` decision
/// "feasible" where its point holds `lp` to `tolerance` ([`point_violation`], the check of
/// every "stands"); `None` otherwise — this
/// never decides "infeasible" (the caller goes on to the elastic program).
pub fn decide_directly(
    lp: &LinearProgram,
    opts: &SolverOptions,
    tolerance: f64,
) -> Result<Option<FeasibilityDecision>> {
    let mut zero = lp.clone();
    zero.cost.iter_mut().for_each(|c| *c = 0.0);
    zero.maximise = false;
    let Ok(s) = super::solve_without_fallback(&zero, opts) else {
        return Ok(None);
    };
    if s.status != LpStatus::Optimal || s.x.len() != lp.num_cols() {
        return Ok(None);
    }
    let v = point_violation(lp, &s.x);
    Ok((v <= tolerance).then_some(FeasibilityDecision {
        feasible: true,
        violation: v,
        certificate: Certificate {
            primal: v,
            dual: 0.0,
            gap: 0.0,
        },
    }))
}

/// [`Certificate::primal`].
pub(crate) fn primal_violation(lp: &LinearProgram, x: &[f64]) -> f64 {
    violation_with(lp, x, |b| b, |b, _| b)
}

/// [`primal_violation`] of `x` on `lp` with its row bounds mapped by `row` and its column
/// bounds by `col` (`true` for a lower bound).
fn violation_with(
    lp: &LinearProgram,
    x: &[f64],
    row: impl Fn(f64) -> f64,
    col: impl Fn(f64, bool) -> f64,
) -> f64 {
    if x.len() != lp.num_cols() {
        return f64::INFINITY;
    }
    let finite = |b: f64| if b.is_finite() { b.abs() } else { 0.0 };
    let mut act = vec![0.0; lp.num_rows()];
    let mut size = vec![0.0; lp.num_rows()];
    for (j, &xj) in x.iter().enumerate() {
        for (i, v) in lp.column(j) {
            act[i] += v * xj;
            size[i] += (v * xj).abs();
        }
    }
    let rows: Vec<(f64, f64)> = (0..lp.num_rows())
        .map(|i| {
            let (lo, hi) = (row(lp.row_lower[i]), row(lp.row_upper[i]));
            let d = (lo - act[i]).max(act[i] - hi).max(0.0);
            (d, size[i].max(finite(lo)).max(finite(hi)))
        })
        .collect();
    let cols: Vec<(f64, f64)> = (0..lp.num_cols())
        .map(|j| {
            let (lo, hi) = (col(lp.col_lower[j], true), col(lp.col_upper[j], false));
            let d = (lo - x[j]).max(x[j] - hi).max(0.0);
            (d, x[j].abs().max(finite(lo)).max(finite(hi)))
        })
        .collect();
    let floor = 1e-3 * rows.iter().fold(0.0f64, |m, r| m.max(r.1));
    let col_floor = 1e-3 * cols.iter().fold(0.0f64, |m, c| m.max(c.1));
    let worst = |v: &[(f64, f64)], floor: f64| {
        v.iter()
            .map(|&(d, s)| {
                if d == 0.0 {
                    0.0
                } else if s.max(floor) > 0.0 {
                    d / s.max(floor)
                } else {
                    f64::INFINITY
                }
            })
            .fold(0.0f64, f64::max)
    };
    worst(&rows, floor).max(worst(&cols, col_floor))
}

/// What a sequence spent.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SequenceStats {
    /// Programs solved.
    pub solves: usize,
    /// Of those, solved from the basis the previous one left.
    pub warm: usize,
    /// Warm runs that failed or did not certify, solved again from scratch.
    pub restarts: usize,
    /// Simplex and interior-point iterations.
    pub iterations: i64,
}

/// A sequence of programs with one constraint matrix, solved with one solver instance where
/// the backend keeps one (module documentation).
pub struct Sequence {
    /// The current program, in the user's units.
    lp: LinearProgram,
    opts: SolverOptions,
    /// The row and column factors of the first program (fixed for the sequence: the matrix
    /// does not change); the objective factor follows each objective.
    scaling: Option<Scaling>,
    session: Option<Persistent>,
    /// A basis to start the next session from (of a solve from scratch, or of the program
    /// replaced).
    basis: Option<Basis>,
    /// The basis the last solve ended with.
    last_basis: Option<Basis>,
    /// The basis of the last certified optimum (a warm run that fails or ends elsewhere starts
    /// again from it).
    optimal_basis: Option<Basis>,
    /// The primal ray of the last run, where it ended "unbounded" and HiGHS gave one (in the
    /// user's units).
    ray: Option<Vec<f64>>,
    costs_changed: bool,
    bounds_changed: bool,
    /// Simplex iterations allowed to a warm run ([`Sequence::limit_warm_iterations`]).
    warm_limit: Option<usize>,
    /// Whether the next solve starts with the dual simplex from a handed-over basis (the
    /// program was replaced or its bounds changed), rather than the primal simplex (only the
    /// objective changed).
    dual_start: bool,
    pub stats: SequenceStats,
}

/// The power of two nearest to `x` in the logarithm (as [`Scaling`]'s factors).
fn pow2(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    2f64.powi(x.log2().round().clamp(-1000.0, 1000.0) as i32)
}

impl Sequence {
    /// A sequence starting with `lp`, solved with `opts` (the first program with its method;
    /// HiGHS's simplex from the kept basis after it).
    pub fn new(lp: LinearProgram, opts: &SolverOptions) -> Result<Sequence> {
        if lp.cost.iter().chain(&lp.value).any(|v| !v.is_finite())
            || lp
                .row_lower
                .iter()
                .chain(&lp.row_upper)
                .chain(&lp.col_lower)
                .chain(&lp.col_upper)
                .any(|b| b.is_nan())
        {
            return Err(Error::Solver(
                "the LP has a NaN bound or a coefficient that is not finite".into(),
            ));
        }
        let scaling = Scaling::needed(&lp, &[]);
        Ok(Sequence {
            lp,
            opts: *opts,
            scaling,
            session: None,
            basis: None,
            last_basis: None,
            optimal_basis: None,
            ray: None,
            costs_changed: false,
            bounds_changed: false,
            warm_limit: None,
            dual_start: true,
            stats: SequenceStats::default(),
        })
    }

    /// The current program.
    pub fn program(&self) -> &LinearProgram {
        &self.lp
    }

    /// Let a run from a kept basis take at most `n` simplex iterations; one that needs more
    /// counts as a failed warm run (the program is then solved otherwise: [`Sequence::solve`]).
    /// On the 24 × 24 dome a warm dual simplex of the bisection ran for minutes where the ones
    /// before it took 1,800 iterations.
    pub fn limit_warm_iterations(&mut self, n: Option<usize>) {
        self.warm_limit = n;
        if let Some(s) = &mut self.session {
            s.limit_warm_iterations(n);
        }
    }

    /// The basis the last solve ended with, if it left one.
    pub fn basis(&self) -> Option<&Basis> {
        self.last_basis.as_ref()
    }

    /// Start the next run from `b`, a basis of this program that is primal feasible (the
    /// optimum of another objective over the same constraints: an earlier sequence's), with
    /// the primal simplex, in place of the requested method from scratch.
    pub fn start_from(&mut self, b: Basis) {
        if b.cols.len() == self.lp.num_cols() && b.rows.len() == self.lp.num_rows() {
            self.session = None;
            self.basis = Some(b.clone());
            self.last_basis = Some(b.clone());
            self.optimal_basis = Some(b);
            self.dual_start = false;
        }
    }

    /// Drop the solver instance; the next run starts a new one from the basis of the last
    /// certified optimum with the primal simplex (after a warm run that ended "unbounded"
    /// without a ray to show for it: a fresh factorisation of a basis known to be good).
    /// `false` where there is no such basis.
    pub fn restart_from_optimal(&mut self) -> bool {
        let Some(b) = self.optimal_basis.clone() else {
            return false;
        };
        self.session = None;
        self.basis = Some(b);
        self.dual_start = false;
        self.stats.restarts += 1;
        true
    }

    /// The primal ray of the last run, where it ended "unbounded" and HiGHS gave one: a
    /// candidate certificate of unboundedness, to be checked ([`certify_ray`]).
    pub fn last_ray(&self) -> Option<&[f64]> {
        self.ray.as_deref()
    }

    /// Replace the whole program by `lp` (another matrix: a bisection on geometry). Where it
    /// has the same shape, the next solve starts from the last basis (a new instance, the
    /// basis handed over); otherwise from scratch.
    pub fn replace(&mut self, lp: LinearProgram) -> Result<()> {
        let same = lp.num_cols() == self.lp.num_cols() && lp.num_rows() == self.lp.num_rows();
        let last = if same { self.last_basis.take() } else { None };
        // (`Sequence::new` below starts with the dual simplex from the basis handed over.)
        *self = Sequence {
            stats: self.stats,
            warm_limit: self.warm_limit,
            ..Sequence::new(lp, &self.opts)?
        };
        self.basis = last;
        Ok(())
    }

    /// A new objective (`cost` per column) and sense.
    pub fn set_objective(&mut self, cost: &[f64], direction: Direction) -> Result<()> {
        if cost.len() != self.lp.num_cols() || cost.iter().any(|c| !c.is_finite()) {
            return Err(Error::Solver(
                "the new objective does not fit the program".into(),
            ));
        }
        self.lp.cost.copy_from_slice(cost);
        self.lp.maximise = direction == Direction::Maximise;
        self.costs_changed = true;
        Ok(())
    }

    /// New bounds of column `j`.
    pub fn set_col_bounds(&mut self, j: usize, lo: f64, hi: f64) -> Result<()> {
        if j >= self.lp.num_cols() || lo.is_nan() || hi.is_nan() {
            return Err(Error::Solver(
                "new column bounds do not fit the program".into(),
            ));
        }
        self.lp.col_lower[j] = lo;
        self.lp.col_upper[j] = hi;
        self.bounds_changed = true;
        Ok(())
    }

    /// New bounds of row `i`.
    pub fn set_row_bounds(&mut self, i: usize, lo: f64, hi: f64) -> Result<()> {
        if i >= self.lp.num_rows() || lo.is_nan() || hi.is_nan() {
            return Err(Error::Solver(
                "new row bounds do not fit the program".into(),
            ));
        }
        self.lp.row_lower[i] = lo;
        self.lp.row_upper[i] = hi;
        self.bounds_changed = true;
        Ok(())
    }

    /// The scaling of the current program: the sequence's row and column factors with the
    /// objective factor of the current objective.
    fn current_scaling(&self) -> Option<Scaling> {
        self.scaling.as_ref().map(|s| {
            let cmax = self
                .lp
                .cost
                .iter()
                .zip(&s.col)
                .fold(0.0f64, |m, (c, f)| m.max((c * f).abs()));
            Scaling {
                objective: if cmax > 0.0 { pow2(1.0 / cmax) } else { 1.0 },
                ..s.clone()
            }
        })
    }

    /// The program as HiGHS's instance holds it: scaled, and always minimised (a maximisation
    /// is the minimisation of `−c`), so that a change of sense is a change of costs.
    fn instance_program(&self, scaling: &Option<Scaling>) -> LinearProgram {
        let mut p = match scaling {
            Some(s) => s.apply(&self.lp),
            None => self.lp.clone(),
        };
        if p.maximise {
            p.cost.iter_mut().for_each(|c| *c = -*c);
            p.maximise = false;
        }
        p
    }

    /// One run of the kept instance on the current program (making it if there is none);
    /// the solution in the user's units and sense.
    fn run_session(&mut self) -> Result<LpSolution> {
        let scaling = self.current_scaling();
        let p = self.instance_program(&scaling);
        match &mut self.session {
            Some(session) => {
                if self.costs_changed {
                    session.set_costs(&p.cost)?;
                }
                if self.bounds_changed {
                    session.set_col_bounds(&p.col_lower, &p.col_upper)?;
                    session.set_row_bounds(&p.row_lower, &p.row_upper)?;
                }
            }
            None => {
                let mut session = Persistent::new(&p, &self.opts)?;
                session.limit_warm_iterations(self.warm_limit);
                if let Some(b) = self.basis.take() {
                    session.set_basis(&b.adapted(&p), self.dual_start)?;
                }
                self.session = Some(session);
            }
        }
        self.costs_changed = false;
        self.bounds_changed = false;
        let session = self.session.as_mut().expect("made above");
        let warm = session.is_warm();
        self.ray = None;
        let solved = session.run()?;
        self.stats.warm += usize::from(warm);
        self.last_basis = solved.basis;
        if solved.solution.status == LpStatus::Unbounded {
            self.ray = session.primal_ray().map(|mut d| {
                if let Some(sc) = &scaling {
                    d.iter_mut().zip(&sc.col).for_each(|(v, c)| *v *= c);
                }
                d
            });
        }
        let mut s = solved.solution;
        if self.lp.maximise && s.status == LpStatus::Optimal {
            s.objective = -s.objective;
            s.row_dual.iter_mut().for_each(|v| *v = -*v);
            s.col_dual.iter_mut().for_each(|v| *v = -*v);
        }
        Ok(match scaling {
            Some(sc) => sc.unscale(s),
            None => s,
        })
    }

    /// Solve the current program. Optimal solutions come certified ([`certify`]). A warm run
    /// that fails or does not certify is tried once more in a new instance from the last good
    /// basis (a fresh factorisation), then solved from scratch with the method's fallback
    /// chain; whatever that gives is returned (the caller certifies it again where it needs
    /// to: [`certify`]).
    pub fn solve(&mut self) -> Result<LpSolution> {
        self.stats.solves += 1;
        self.choose_start();
        if let Some(s) = self.try_warm() {
            return Ok(s);
        }
        self.solve_cold()
    }

    /// Solve the current program without the fallback chain from scratch: the warm runs of
    /// [`Sequence::solve`] (a certified optimum, or an infeasible or unbounded status), or for
    /// a backend without a basis one solve with the method's chain; `None` where they fail or
    /// do not certify (the caller then decides what the failure means — an unbounded program
    /// fails in every method — before [`Sequence::solve_cold`]).
    pub fn try_solve(&mut self) -> Option<LpSolution> {
        self.stats.solves += 1;
        self.choose_start();
        if self.keeps_basis() {
            self.try_warm()
        } else {
            self.solve_cold().ok()
        }
    }

    fn keeps_basis(&self) -> bool {
        self.opts.method.backend().name() == "highs"
    }

    fn choose_start(&mut self) {
        if self.costs_changed && !self.bounds_changed && self.session.is_some() {
            self.dual_start = false;
        } else if self.bounds_changed {
            self.dual_start = true;
        }
    }

    /// The warm runs of [`Sequence::solve`]: `None` where they fail or do not certify.
    fn try_warm(&mut self) -> Option<LpSolution> {
        if !self.keeps_basis() {
            return None;
        }
        let good = self
            .optimal_basis
            .clone()
            .or_else(|| self.last_basis.clone());
        for attempt in 0..2 {
            let before = self.stats.warm;
            match self.run_session() {
                Ok(s) if s.status != LpStatus::Optimal => {
                    self.stats.iterations += s.iterations;
                    let o = if s.status == LpStatus::Infeasible {
                        super::Outcome::Infeasible
                    } else {
                        super::Outcome::Unbounded
                    };
                    super::record_run(s.method, &[], self.stats.warm > before, || o);
                    return Some(s);
                }
                Ok(s) if certify(&self.lp, &s).is_some_and(|c| c.ok()) => {
                    self.stats.iterations += s.iterations;
                    self.optimal_basis = self.last_basis.clone();
                    let warm = self.stats.warm > before;
                    super::record_run(s.method, &[], warm, || super::Outcome::Certified);
                    return Some(s);
                }
                _ => {
                    self.session = None;
                    self.stats.restarts += 1;
                    match (&good, attempt) {
                        // A new instance from the last good basis.
                        (Some(b), 0) => self.basis = Some(b.clone()),
                        _ => break,
                    }
                }
            }
        }
        None
    }

    /// Solve the current program from scratch with the method's fallback chain
    /// ([`super::solve_warm`]); the next run starts a new instance from its basis.
    pub fn solve_cold(&mut self) -> Result<LpSolution> {
        let mut basis = None;
        let s = solve_warm(&self.lp, &self.opts, &mut basis)?;
        self.stats.iterations += s.iterations;
        self.session = None;
        self.basis = basis.clone();
        if s.status == LpStatus::Optimal && certify(&self.lp, &s).is_some_and(|c| c.ok()) {
            self.optimal_basis = basis.clone();
        }
        self.last_basis = basis;
        self.costs_changed = false;
        self.bounds_changed = false;
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cert(primal: f64, dual: f64, gap: f64) -> Certificate {
        Certificate { primal, dual, gap }
    }

    /// The rule of [`decision`], case by case: the numbers of the 0.5 m grid façade's settled
    /// capacity steps (Clarabel at reduced accuracy: primal 4.8e-8, dual 1.6e-7, violation and
    /// bound 216.9 times the largest load; primal 3.4e-7, dual 1.2e-7, 266.6) decide
    /// "infeasible"; duals that far off do not where the bound is small, nor halves beyond
    /// 1e-6, nor a gap beyond it.
    #[test]
    fn far_infeasible_needs_both_halves_and_a_large_bound() {
        let grid = cert(4.8e-8, 1.6e-7, 1e-9);
        assert_eq!(decision(&grid, 216.9, 216.9, 0.0), Some(false));
        // Certified duals (1e-7) decide at any bound above the margin, as before.
        assert_eq!(
            decision(&cert(1.0, 5e-8, 1.0), 1e-5, 2e-6, 0.0),
            Some(false)
        );
        // Duals between 1e-7 and 1e-6: only far from feasible, with both halves agreeing.
        assert_eq!(decision(&grid, 5e-4, 5e-4, 0.0), None);
        assert_eq!(
            decision(&cert(3.4e-7, 1.2e-7, 1e-9), 266.6, 266.6, 0.0),
            Some(false)
        );
        assert_eq!(decision(&cert(2e-6, 1.6e-7, 1e-9), 216.9, 216.9, 0.0), None);
        assert_eq!(
            decision(&cert(4.8e-8, 1.6e-7, 2e-6), 216.9, 216.9, 0.0),
            None
        );
        assert_eq!(decision(&cert(4.8e-8, 2e-6, 1e-9), 216.9, 216.9, 0.0), None);
        // The caller's tolerance raises the threshold (here above the bound: then within it).
        assert_eq!(decision(&grid, 216.9, 216.9, 300.0), Some(true));
        // Feasible: the primal half and a violation within the resolution.
        assert_eq!(decision(&cert(1e-8, 1.0, 1.0), 5e-8, 0.0, 0.0), Some(true));
    }
}
