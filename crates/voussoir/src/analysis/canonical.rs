//! Canonical solutions: one documented choice among the optimal mechanisms and force fields,
//! so that the reported crack pattern and forces do not depend on the LP method
//! (`docs/canonical.md`).
//!
//! **Mechanism.** The optimal mechanisms of a settlement (or limit) analysis form a face of the
//! kinematic LP's polytope. With its optimal value held as a row ([`programs::optimal_face`],
//! relative tolerance [`CanonicalOptions::tolerance`]), a second LP minimises the crack area
//! `Σ w_k o_k` (openings weighted by their tributary joint size). If that still leaves a face
//! (tested by minimising and maximising a generic linear functional over it), a third program
//! picks the least `Σ w_k o_k²` — strictly convex in the openings, so unique — with Clarabel.
//!
//! **Forces.** Among the optimal force fields, the ones in which the points open in the
//! canonical mechanism carry nothing (normal and shear) and `|p_t| ≤ μ p_n` holds at every
//! point — μ the joint's friction, or on joints without friction the least μ for which such a
//! field exists (a bisection on LP feasibility). Of those, the field of least complementary
//! energy `Σ |p_k|²/w_k` (springs of equal stiffness per unit joint size; unique); each
//! support's reaction is reported with its range over the whole set (min/max LPs).

use crate::analysis::limit::{self, LimitResult, LimitSolution, LimitStatus};
use crate::analysis::settlement::{self, SettlementForm, SettlementResult, SettlementStatus};
use crate::dim::Dim;
use crate::discretize::KinematicMap;
use crate::error::Result;
use crate::lp::{self, Basis, BasisStatus, LinearProgram, LpStatus, Method, SolverOptions};
use crate::programs::{self, ForceProgram};
pub use crate::result::canonical::*;
use crate::result::Spatial;
use crate::structure::Assembly;

/// Largest row violation (the solver layer's certificate's, [`lp::policy::violation`], after
/// clamping onto the column bounds) at which the stage-2 vertex counts as a point of the
/// least-crack face in [`canonical_mechanism`] (the solver layer's certificate tolerance).
const INSIDE_TOLERANCE: f64 = lp::policy::CERTIFICATE_TOLERANCE;

/// The largest friction coefficient the bisection tries: beyond it, no finite μ is reported.
pub const MAX_FRICTION: f64 = 100.0;

/// The friction coefficient above which the default search of the least μ stops
/// ([`CanonicalOptions::friction_search_limit`]): twice the friction coefficient of rough stone
/// joints (about 1; mortar and brick joints 0.6–0.8). A field that needs more is carried by
/// Heyman's no-sliding rule, not by any masonry's friction: that it needs more is the answer,
/// and the μ to 5 % above it cost the 3,200-block stack-bond wall two thirds of its `settle`
/// (the bisection between 8 and 28.7, docs/performance.md "The least μ above masonry's
/// friction (session 28)").
pub const FRICTION_SEARCH_LIMIT: f64 = 2.0;

/// Default relative precision of the least friction coefficient: 5 %. At 1e-4 the 3,200-block
/// stack-bond wall's bisection took 18 programs and 89 s, most of it in programs at a μ just
/// short of the least (up to 20 s each); at 5 % it takes 8 programs and 13 s.
pub const FRICTION_PRECISION: f64 = 0.05;

/// Pivots allowed to the primal simplex in each warm-started program of the early uniqueness
/// test ([`canonical_mechanism`]; default of [`CanonicalOptions::unique_pivots`]); beyond them
/// the solver layer's fallback chain answers.
pub const UNIQUE_PIVOTS: usize = 500;

/// Pivots allowed to the primal simplex warm-started from the optimal vertex in stage 2 of the
/// mechanism selection (least crack area on the optimal face; default of
/// [`CanonicalOptions::stage2_pivots`]); beyond them the solver layer's fallback chain answers.
/// On the 0.25 m façade grid (10,062 blocks) stage 2 took 2,245 pivots (26 s); on the 0.5 m
/// façade in triangles adapted by `settle --adapt` (4,637 blocks, 28,901 rows) the same warm
/// primal simplex ran for more than 25 minutes (docs/cracks.md).
pub const STAGE2_PIVOTS: usize = 5000;

/// Iterations allowed to the energy QP of the force stage (default of
/// [`CanonicalOptions::energy_qp_iterations`]). Where the optimal fields wedge the bond (the
/// façade in running bond at 0.25 m: point forces of 4.4e7 kN near the least μ) Clarabel
/// iterated to its own limit of 500 at reduced accuracy (280–465 s) and its point then failed the
/// duality certificate; a QP that reaches this cap is not used (the admissible field stands, and
/// `rejected` says why). docs/performance.md, "Canonical force stage at 0.25 m (session 16)".
pub const ENERGY_QP_ITERATIONS: usize = 100;

/// The answer of one feasibility program of the force stage.
enum Trial {
    /// An optimal field exists; with the least μ it admits (its largest |p_t|/p_n in 2D, the μ
    /// imposed in 3D; infinite without one).
    Admissible(f64),
    /// None exists (the solver's certificate).
    Inadmissible,
    /// The solver did not decide.
    Undecided,
}

impl Trial {
    fn ratio(&self) -> Option<f64> {
        match self {
            Trial::Admissible(r) => Some(*r),
            _ => None,
        }
    }
}

/// Settings of the canonical selection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CanonicalOptions {
    /// Relative tolerance with which optimal values are held (work, λ, crack area).
    pub tolerance: f64,
    /// Relative size (of the largest dual value) above which a dual value is not zero: its row
    /// or column is held at its bound on the optimal face.
    pub dual_threshold: f64,
    /// Relative size (of the largest motion component) below which two mechanisms are the
    /// same and a face is a single point.
    pub point_tolerance: f64,
    /// Relative precision of the least friction coefficient (bisection; default
    /// [`FRICTION_PRECISION`]). Each halving costs a feasibility program, and the programs at
    /// a μ just short of the least are the costly ones (docs/canonical.md).
    pub friction_precision: f64,
    /// Compute the ranges of the support reactions (2 LPs per reaction component of every
    /// support that is not entirely open).
    pub reaction_ranges: bool,
    /// Select the canonical force field (and the least friction).
    pub forces: bool,
    /// Pivots allowed to the primal simplex in each program of the early uniqueness test
    /// (default [`UNIQUE_PIVOTS`]).
    pub unique_pivots: usize,
    /// Pivots allowed to the warm-started primal simplex of stage 2 (default
    /// [`STAGE2_PIVOTS`]); beyond them the fallback chain answers.
    pub stage2_pivots: usize,
    /// Reaction ranges only for models of at most this many blocks (each range LP is a full
    /// solve; on the 1,889-block façade, 132 of them take many minutes).
    pub ranges_max_blocks: usize,
    /// Testing: the least-crack face's two extremes of the generic functional as before session
    /// 21 — the maximum solved even where the stage-2 vertex already shows that face not to be
    /// a point, and by the dual simplex first where it does not (the independent reference of
    /// both shortcuts in [`canonical_mechanism`]). `false` by default.
    #[doc(hidden)]
    pub both_extremes: bool,
    /// Testing: the first this many candidate force fields (least energy, admissible) are
    /// treated as uncertified, to exercise the fallback of [`canonical_forces`]. 0 by default.
    #[doc(hidden)]
    pub reject_fields: usize,
    /// Iterations allowed to the energy QP (default [`ENERGY_QP_ITERATIONS`]; an iteration
    /// limit of the solver options, if smaller, holds too). A QP that reaches it is not used:
    /// the admissible field stands, and `rejected` names the cap.
    pub energy_qp_iterations: usize,
    /// How the least friction coefficient is searched (default [`FrictionSearch::Bisection`];
    /// [`FrictionSearch::Ratio`] is opt-in, 2D only — 3D models always bisect — until it is
    /// measured faster on the 0.25 m façade in running bond, docs/performance.md "Least μ by
    /// normalised elastic trials (session 17)").
    pub friction_search: FrictionSearch,
    /// Whether the bisection's trials (2D) are asked first as bounded elastic programs
    /// ([`canonical_forces`]): `Some(true)` from the first trial on, `Some(false)` never;
    /// `None` (the default): on a program of the size [`lp::policy::elastic_trials`] names,
    /// after the first trial Clarabel proved infeasible slowly.
    pub elastic_trials: Option<bool>,
    /// The bisection's least μ is searched to `friction_precision` up to this μ (default
    /// [`FRICTION_SEARCH_LIMIT`]). Where the limit itself is shown inadmissible, the search
    /// climbs to the first admissible μ (16× the limit, then [`MAX_FRICTION`]) and stops
    /// there: the reported field is the least-energy one at that admissible field's own ratio,
    /// and the result states the bracket (`least_friction_above`: the limit shown
    /// inadmissible; `least_friction`: the admissible ratio). `None`: to the precision at any
    /// μ, as before session 28 (the request layer's choice where a precision is asked for).
    /// Not used by [`FrictionSearch::Ratio`]. Only on force programs of at least
    /// `friction_limit_min_columns` columns.
    pub friction_search_limit: Option<f64>,
    /// Testing: the smallest force program (columns) on which `friction_search_limit` applies
    /// (default [`lp::policy::FRICTION_LIMIT_MIN_COLUMNS`]: the solver policy's).
    #[doc(hidden)]
    pub friction_limit_min_columns: usize,
    /// Testing: the smallest force program (columns) whose elastic trials are armed where
    /// `elastic_trials` is `None` (default [`lp::policy::ELASTIC_TRIAL_MIN_COLUMNS`]).
    #[doc(hidden)]
    pub elastic_trial_min_columns: usize,
    /// Testing: the iterations at which an armed trial turns into an elastic trial (default
    /// [`lp::policy::ELASTIC_SWITCH_ITERATIONS`]).
    #[doc(hidden)]
    pub elastic_switch_iterations: usize,
}

/// How the force stage searches the least friction coefficient (docs/canonical.md, "The
/// forces").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrictionSearch {
    /// Normalised elastic trials: at each trial θ, the least `s ≥ 0` with
    /// `|p_t,k| − θ p_n,k ≤ s·ḡ_k` over the optimal fields (`ḡ` the normal forces of the last
    /// field, as in Crouzeix, Ferland and Schaible's method for generalised fractional
    /// programs). Every trial is a feasible, bounded program: its field's own largest ratio is
    /// an admissible μ, and an optimum bounded above 0 by its duals shows θ inadmissible. On
    /// the façade in running bond a trial costs what a feasible one of the bisection does,
    /// where the bisection's infeasible trials cost 4–8 times as much. 2D only.
    Ratio,
    Bisection,
}

impl Default for CanonicalOptions {
    fn default() -> Self {
        CanonicalOptions {
            tolerance: 1e-9,
            dual_threshold: 1e-9,
            point_tolerance: 1e-6,
            friction_precision: FRICTION_PRECISION,
            unique_pivots: UNIQUE_PIVOTS,
            stage2_pivots: STAGE2_PIVOTS,
            reaction_ranges: true,
            forces: true,
            ranges_max_blocks: 500,
            reject_fields: 0,
            both_extremes: false,
            energy_qp_iterations: ENERGY_QP_ITERATIONS,
            friction_search: FrictionSearch::Bisection,
            elastic_trials: None,
            friction_search_limit: Some(FRICTION_SEARCH_LIMIT),
            friction_limit_min_columns: lp::policy::FRICTION_LIMIT_MIN_COLUMNS,
            elastic_trial_min_columns: lp::policy::ELASTIC_TRIAL_MIN_COLUMNS,
            elastic_switch_iterations: lp::policy::ELASTIC_SWITCH_ITERATIONS as usize,
        }
    }
}

/// Tributary size of every point: its joint's size (2D: length; 3D: area of the polygon of its
/// points) divided by the number of its points.
pub fn tributary_weights<S: Assembly>(st: &S, map: &KinematicMap) -> Vec<f64> {
    let contact = st.contact_joints();
    let sizes: Vec<f64> = contact
        .iter()
        .map(|j| {
            let pts: Vec<&[f64]> = j.points.iter().map(|(x, _)| x.as_ref()).collect();
            let n = pts.len();
            let size = match (n, <S::D as Dim>::N) {
                (0 | 1, _) => 0.0,
                (_, 2) | (2, _) => {
                    // The largest distance between points (2D: the joint's length).
                    let mut m = 0.0f64;
                    for a in &pts {
                        for b in &pts {
                            let d: f64 = a.iter().zip(*b).map(|(x, y)| (x - y).powi(2)).sum();
                            m = m.max(d.sqrt());
                        }
                    }
                    m
                }
                _ => {
                    // A polygon (points in order): half the norm of Σ (p_i − p_0) × (p_i+1 − p_0).
                    let mut s = [0.0f64; 3];
                    for i in 1..n - 1 {
                        let u: Vec<f64> = (0..3).map(|c| pts[i][c] - pts[0][c]).collect();
                        let v: Vec<f64> = (0..3).map(|c| pts[i + 1][c] - pts[0][c]).collect();
                        s[0] += u[1] * v[2] - u[2] * v[1];
                        s[1] += u[2] * v[0] - u[0] * v[2];
                        s[2] += u[0] * v[1] - u[1] * v[0];
                    }
                    0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt()
                }
            };
            size / n.max(1) as f64
        })
        .collect();
    let fallback = {
        let pos: Vec<f64> = sizes.iter().copied().filter(|s| *s > 0.0).collect();
        if pos.is_empty() {
            1.0
        } else {
            pos.iter().sum::<f64>() / pos.len() as f64
        }
    };
    map.points
        .iter()
        .map(|p| {
            let s = sizes[p.joint];
            if s > 0.0 {
                s
            } else {
                fallback
            }
        })
        .collect()
}

/// Deterministic weights in ±[0.5, 1.5] (splitmix64): the generic linear functional of the
/// uniqueness test (and of the frictional selection's tie-break, `canonical_friction`).
pub(crate) fn generic_functional(n: usize) -> Vec<f64> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    (0..n)
        .map(|_| {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            let u = (z >> 11) as f64 / (1u64 << 53) as f64;
            let sign = if z & 1 == 0 { 1.0 } else { -1.0 };
            sign * (0.5 + u)
        })
        .collect()
}

/// Runs the LPs of a selection: warm starts where the backend has bases (a basis of the program
/// before a row was appended starts the next one with that row basic), counts solves.
struct Stages {
    opts: SolverOptions,
    solves: usize,
}

impl Stages {
    fn new(opts: &SolverOptions) -> Stages {
        // A cost change keeps a basis primal feasible: primal simplex continues from it. After an
        // interior-point method the stages run on the simplex too (the tie-break is a vertex,
        // which an interior point only approaches): from a basis (the one HiGHS's interior
        // point leaves after crossover, or a previous stage's) by the primal simplex, without
        // one (Clarabel, no crossover) by the dual simplex ([`Stages::solve_inner`]).
        let method = if opts.method.is_simplex() {
            Method::PrimalSimplex
        } else {
            Method::DualSimplex
        };
        Stages {
            opts: SolverOptions {
                method,
                feasibility_tolerance: if method.is_simplex() {
                    1e-9
                } else {
                    opts.feasibility_tolerance
                },
                ..*opts
            },
            solves: 0,
        }
    }

    fn solve(&mut self, lp: &LinearProgram, basis: &mut Option<Basis>) -> Result<lp::LpSolution> {
        self.solves += 1;
        let t0 = std::time::Instant::now();
        let warm = basis.is_some();
        let r = self.solve_inner(lp, basis);
        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
            eprintln!(
                "trace: stage solve {} {:?} rows {} cols {} warm {} -> {:?} {:.3} s it {:?} tried {:?}",
                self.solves,
                r.as_ref().map_or(self.opts.method, |s| s.method),
                lp.num_rows(),
                lp.num_cols(),
                warm,
                r.as_ref().map(|s| s.status),
                t0.elapsed().as_secs_f64(),
                r.as_ref().map(|s| s.iterations),
                r.as_ref().map(|s| &s.tried)
            );
        }
        r
    }

    /// Solve with the stages' method alone, without the solver layer's fallback chain (the
    /// bisection's trials: one that Clarabel does not decide is left undecided); `decision`:
    /// the status is the answer ([`SolverOptions::decision`]).
    fn solve_single(&mut self, lp: &LinearProgram, decision: bool) -> Result<lp::LpSolution> {
        self.solve_single_capped(lp, decision, None)
    }

    /// [`Stages::solve_single`] with at most `cap` iterations (`None`: the method's own limit).
    fn solve_single_capped(
        &mut self,
        lp: &LinearProgram,
        decision: bool,
        cap: Option<usize>,
    ) -> Result<lp::LpSolution> {
        self.solves += 1;
        let t0 = std::time::Instant::now();
        // Without a chain behind it, the trial runs to Clarabel's own limit (an iteration
        // limit is the requested method's, SolverOptions::iteration_limit), or to `cap`.
        let o = SolverOptions {
            decision,
            iteration_limit: cap,
            ..self.opts
        };
        let r = lp::solve_without_fallback(lp, &o);
        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
            eprintln!(
                "trace: stage solve {} {:?} (no fallback) rows {} cols {} -> {:?} {:.3} s it {:?}",
                self.solves,
                self.opts.method,
                lp.num_rows(),
                lp.num_cols(),
                r.as_ref().map(|s| s.status),
                t0.elapsed().as_secs_f64(),
                r.as_ref().map(|s| s.iterations),
            );
        }
        r
    }

    /// Solve from scratch with `method` and presolve, and that method's fallback chain.
    fn solve_with(&mut self, lp: &LinearProgram, method: Method) -> Result<lp::LpSolution> {
        let saved = self.opts;
        self.opts = SolverOptions {
            method,
            presolve: true,
            as_written_first: true,
            ..saved
        };
        let mut none = None;
        let r = self.solve(lp, &mut none);
        self.opts = saved;
        r
    }

    /// Solve from scratch, with the dual simplex and presolve (the extremes of a face: most of
    /// its rows are held equalities). On a program of `dofs` degrees of freedom where the
    /// policy says so ([`lp::policy::extremes_fallback`]), an answer of the dual simplex that
    /// is not certified goes to that method (and its chain) instead of the dual simplex's own
    /// chain; the result's `tried` says why.
    fn solve_fresh(&mut self, lp: &LinearProgram, dofs: usize) -> Result<lp::LpSolution> {
        let saved = self.opts;
        // As written first: the face programs equilibrated came out worse conditioned than
        // as written on the 0.5 m grid façade's `tilt` (SolverOptions::as_written_first). Off
        // in session 25's merge, when the 1.0 m grid façade's settled capacity step changed
        // with it; that was the mechanism's round-off (1e-9 where this path has exact zeros)
        // turning the deformed joints and steering the step programs' scaling, now set to zero
        // by the settlement path (docs/performance.md, "Capacity step round-off and the
        // as-written face extremes (session 26)").
        self.opts = SolverOptions {
            method: Method::DualSimplex,
            presolve: true,
            as_written_first: true,
            ..saved
        };
        let r = match lp::policy::extremes_fallback(dofs) {
            None => {
                let mut none = None;
                self.solve(lp, &mut none)
            }
            Some(next) => {
                let first = self.solve_single(lp, false);
                let why = match &first {
                    Ok(s) => lp::policy::check(lp, s),
                    Err(e) => Some(e.to_string().trim().to_string()),
                };
                match (first, why) {
                    (Ok(s), None) => Ok(s),
                    (_, why) => {
                        self.opts.method = next;
                        let mut none = None;
                        self.solve(lp, &mut none).map(|mut s| {
                            s.tried
                                .insert(0, format!("dual-simplex: {}", why.unwrap_or_default()));
                            s
                        })
                    }
                }
            }
        };
        self.opts = saved;
        r
    }

    fn solve_inner(
        &mut self,
        lp: &LinearProgram,
        basis: &mut Option<Basis>,
    ) -> Result<lp::LpSolution> {
        if let Some(b) = basis.as_mut() {
            while b.rows.len() < lp.num_rows() {
                b.rows.push(BasisStatus::Basic);
            }
        }
        // Keep the last basis when a solve ends without one (infeasible): it still starts the
        // next program of the same shape.
        let keep = basis.clone();
        // Every program of a selection differs from the one before by its costs, by rows held
        // at values the previous solution satisfies and by guard rows (basic): a basis stays
        // primal feasible, and the primal simplex continues from it.
        let o = if basis.is_some() && self.opts.method == Method::DualSimplex {
            SolverOptions {
                method: Method::PrimalSimplex,
                ..self.opts
            }
        } else {
            self.opts
        };
        let s = lp::solve_warm(lp, &o, basis)?;
        if basis.is_none() {
            *basis = keep;
        }
        Ok(s)
    }
}

/// With the environment variable `VOUSSOIR_TRACE` set: the time of each part on stderr.
fn trace(what: &str, t0: std::time::Instant) {
    if std::env::var_os("VOUSSOIR_TRACE").is_some() {
        eprintln!("trace: {what} {:.3} s", t0.elapsed().as_secs_f64());
    }
}

pub(crate) fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The canonical mechanism among the optima of the kinematic program `klp` (a maximisation
/// whose first `map.num_dofs` columns are `y = −d`) of optimal value `value`; `raw` is the
/// solver's own mechanism `d`. Returns the mechanism `d` (in the normalisation of `klp`) and
/// how it was selected; `None` if a stage did not solve (the raw mechanism then stands).
pub fn canonical_mechanism(
    map: &KinematicMap,
    klp: &LinearProgram,
    first: &lp::LpSolution,
    raw: &[f64],
    start: Option<Basis>,
    weights: &[f64],
    opts: &SolverOptions,
    copts: &CanonicalOptions,
) -> Result<Option<(Vec<f64>, CanonicalMechanism)>> {
    let nd = map.num_dofs;
    let mut st = Stages::new(opts);
    let face1 = programs::optimal_face_exact(
        klp,
        first.objective,
        copts.tolerance,
        &first.row_dual,
        &first.col_dual,
        copts.dual_threshold,
    );
    let (area_cost, area_const) = programs::crack_area_cost(map, weights, klp.num_cols());
    // The crack area of a mechanism, with round-off (below the opening tolerance of the sum of
    // its terms' magnitudes, crate::scale) reported as zero: a rigid motion cracks nothing.
    let area_of = |d: &[f64]| -> f64 {
        let y: Vec<f64> = d.iter().map(|v| -v).collect();
        let a = dot(&area_cost[..nd], &y) + area_const;
        let size: f64 = area_cost[..nd]
            .iter()
            .zip(&y)
            .map(|(c, v)| (c * v).abs())
            .sum::<f64>()
            + area_const.abs();
        if a.abs() <= crate::scale::OPEN_TOLERANCE * size {
            0.0
        } else {
            a
        }
    };
    let crack_area_solver = area_of(raw);
    // Stage 2: least crack area on the optimal face.
    let mut stage2 = face1.clone();
    stage2.cost = area_cost.clone();
    let mut basis = start;
    // Warm-started (a cost change keeps the optimal vertex primal feasible) the primal simplex
    // usually needs few pivots; capped, so that a stalling one (the adapted 0.5 m façade in
    // triangles: more than 25 min) is answered by the next method of the fallback chain.
    let s2 = if basis.is_some() {
        let saved = st.opts;
        st.opts = SolverOptions {
            iteration_limit: Some(copts.stage2_pivots),
            ..saved
        };
        let s = st.solve(&stage2, &mut basis);
        st.opts = saved;
        s?
    } else {
        st.solve(&stage2, &mut basis)?
    };
    if s2.status != LpStatus::Optimal {
        return Ok(None);
    }
    let d2: Vec<f64> = s2.x[..nd].iter().map(|v| -v).collect();
    let area2 = s2.objective + area_const;
    // Motions are compared with the largest block motion or prescribed support motion.
    let scale = max_abs(raw)
        .max(max_abs(&d2))
        .max(max_abs(&map.support_normal))
        .max(max_abs(&map.support_tangent))
        .max(1e-300);
    let ptol = copts.point_tolerance * scale;
    let changed2 = raw.iter().zip(&d2).any(|(a, b)| (a - b).abs() > ptol);
    // Is the least-crack face a single point?
    let area_entries: Vec<(usize, f64)> = area_cost
        .iter()
        .copied()
        .enumerate()
        .filter(|&(_, c)| c != 0.0)
        .collect();
    let slack = copts.tolerance * area2.abs().max(1e-9 * scale);
    let mut face2 = face1.with_row(&area_entries, -f64::INFINITY, area2 - area_const + slack);
    // The least-crack face exactly, as the optimal face: the rows and columns with non-zero
    // stage-2 duals held at their bounds. Only the rows of the kinematic program itself: the
    // work row of the optimal face is a guard at W*(1 − tolerance), and holding it there (where
    // the held rows already fix W = W*) would leave an empty face. The area row stays as a
    // guard too.
    hold_complementary(
        &mut face2,
        &s2.row_dual[..klp.num_rows().min(s2.row_dual.len())],
        &s2.col_dual,
        copts.dual_threshold,
    );
    // Stage 3 (only if the least-crack face is not a point): the least value of a fixed generic
    // linear functional `r·y` on it — a unique vertex, exact with every method. Its maximum
    // tells whether the face is a point. These programs are solved from scratch with presolve:
    // most rows of an exact face are equalities, which presolve removes, where a primal simplex
    // warm-started from stage 2 took thousands of pivots on the façade (346 s for one).
    //
    // `inside`: a point known to lie on the face (the stage-2 vertex, on the least-crack face).
    // Where its `r·y` exceeds the minimum by more than the point tolerance, the face is not a
    // point, the spread is at least that, and the maximum is not solved (the façade's `settle`:
    // 1.3e-2 above the minimum, where the point tolerance is 2.5e-7; its maximum by the dual
    // simplex cost 5 CPU s, docs/performance.md "Tilt and the least-crack face's extremes
    // (session 21)"). The point is checked on the face first (clamped onto the column bounds,
    // its violation by the certificate's measure within INSIDE_TOLERANCE); where it is not,
    // the maximum is solved as before.
    let r = generic_functional(nd);
    let extremes = |st: &mut Stages,
                    face: &LinearProgram,
                    warm: Option<&Basis>,
                    inside: Option<&[f64]>|
     -> Result<Option<(Vec<f64>, f64)>> {
        let mut lp = face.clone();
        lp.cost[..nd].copy_from_slice(&r);
        let mut lo = st.solve_fresh(&lp, nd)?;
        let mut likely_point = false;
        if lo.status == LpStatus::Optimal {
            let known = inside.map(|x| lp.clamped(x)).map(|x| {
                let v = lp::policy::violation(&lp, &x);
                (x, v)
            });
            if std::env::var_os("VOUSSOIR_TRACE").is_some() {
                if let Some((x, v)) = &known {
                    eprintln!(
                        "trace: extremes: the stage-2 vertex {:.3e} above the minimum (point tolerance {ptol:.3e}), violation {v:.1e}",
                        lp.objective(x) - lo.objective
                    );
                }
            }
            if let Some((x, _)) = known.filter(|(_, v)| *v <= INSIDE_TOLERANCE) {
                let above = lp.objective(&x) - lo.objective;
                if above > ptol {
                    return Ok(Some((lo.x[..nd].iter().map(|v| -v).collect(), above)));
                }
                likely_point = true;
            }
        }
        lp.maximise = true;
        // Where the stage-2 vertex is at the minimum too, the face is likely a point. On a
        // large program its maximum then goes to the method that answers an extreme after the
        // dual simplex (lp::policy::extremes_fallback) straight away: on the 0.5 m grid
        // façade's `tilt` (a point) the dual simplex's maximum took 10,944 iterations, about
        // 13 CPU s, and was not certified, before the interior point answered. Not where the
        // face is not a point: the same interior point on the settled façade's maximum (a
        // segment) had not answered after 400 CPU s, where the dual simplex took 5.
        let direct = if likely_point {
            lp::policy::extremes_fallback(nd)
        } else {
            None
        };
        let mut hi = match direct {
            Some(m) => st.solve_with(&lp, m)?,
            None => st.solve_fresh(&lp, nd)?,
        };
        // From scratch, the dual simplex can find a face of nearly dependent held rows
        // empty to its tolerances where the stage-2 vertex lies in it (the 30 × 20 wall with
        // μ = 0.6: both extremes "infeasible"). Then from that vertex's basis, by the primal
        // simplex, which stays on the face.
        if let (Some(b), false) = (
            warm,
            lo.status == LpStatus::Optimal && hi.status == LpStatus::Optimal,
        ) {
            let mut b1 = Some(b.clone());
            lp.maximise = false;
            lo = st.solve(&lp, &mut b1)?;
            lp.maximise = true;
            hi = st.solve(&lp, &mut b1)?;
        }
        Ok(
            (lo.status == LpStatus::Optimal && hi.status == LpStatus::Optimal).then(|| {
                (
                    lo.x[..nd].iter().map(|v| -v).collect(),
                    hi.objective - lo.objective,
                )
            }),
        )
    };
    // A unique optimum, tested first where it is likely (the solver's mechanism is of least
    // crack area): the extremes of `r·y` on the optimal face, warm-started from the stage-2
    // vertex by primal simplex and capped at UNIQUE_PIVOTS pivots each. On a point they take a
    // few pivots (the façade in running bond at 0.5 m: 0–7); where the cap is reached the
    // fallback chain's answer is used (the 3,200-block wall: 466 dual simplex iterations, where
    // the extremes of both faces from scratch took 27 s).
    let mut face1_spread: Option<f64> = None;
    if !changed2 {
        let mut lp = face1.clone();
        lp.cost[..nd].copy_from_slice(&r);
        let mut b = basis.clone();
        let saved = st.opts;
        st.opts = SolverOptions {
            method: Method::PrimalSimplex,
            iteration_limit: Some(copts.unique_pivots),
            ..saved
        };
        // An optimum counts whichever method of the fallback chain reached it (the primal
        // simplex within its cap, or the next method after it): the chain has spent that time
        // already, and its answer is certified like any other (lp::policy).
        let capped = |s: &Result<lp::LpSolution>| {
            s.as_ref()
                .is_ok_and(|s| s.status == LpStatus::Optimal && !s.reduced_accuracy)
        };
        let lo = st.solve(&lp, &mut b);
        if capped(&lo) {
            lp.maximise = true;
            let hi = st.solve(&lp, &mut b);
            if let (true, Ok(lo), Ok(hi)) = (capped(&hi), &lo, &hi) {
                face1_spread = Some(hi.objective - lo.objective);
            }
        }
        st.opts = saved;
        if face1_spread.is_some_and(|w| w <= ptol) {
            return Ok(Some((
                raw.to_vec(),
                CanonicalMechanism {
                    unique: true,
                    selected_by: Selection::Optimum,
                    crack_area_solver,
                    crack_area: area_of(raw),
                    changed: false,
                    solves: st.solves,
                },
            )));
        }
    }
    let inside = (!copts.both_extremes).then_some(s2.x.as_slice());
    let Some((d3, spread2)) = extremes(&mut st, &face2, basis.as_ref(), inside)? else {
        return Ok(None);
    };
    let face2_point = spread2 <= ptol;
    let (d, selected_by) = if face2_point {
        (d2, Selection::LeastCrackArea)
    } else {
        (d3, Selection::GenericVertex)
    };
    let changed = raw.iter().zip(&d).any(|(a, b)| (a - b).abs() > ptol);
    // The optimal face is a point only if the least-crack one is and the solver's mechanism
    // is in it; then one more test on the optimal face itself.
    let unique = !changed2
        && face2_point
        && face1_spread.is_none()
        && extremes(&mut st, &face1, None, None)?.is_some_and(|(_, w)| w <= ptol);
    let selected_by = if unique {
        Selection::Optimum
    } else {
        selected_by
    };
    let d = if changed { d } else { raw.to_vec() };
    let crack_area = area_of(&d);
    Ok(Some((
        d,
        CanonicalMechanism {
            unique,
            selected_by,
            crack_area_solver,
            crack_area,
            changed,
            solves: st.solves,
        },
    )))
}

/// Hold every row whose dual exceeds `rel_tau` of the largest dual at its finite bound, and
/// every column whose reduced cost does (complementary slackness with an optimal dual
/// solution: what [`programs::optimal_face_exact`] does for the first stage). Rows beyond the
/// duals' length (appended guards) are left alone.
fn hold_complementary(lp: &mut LinearProgram, row_dual: &[f64], col_dual: &[f64], rel_tau: f64) {
    let tau = rel_tau * max_abs(row_dual).max(max_abs(col_dual));
    let hold = |lo: &mut f64, hi: &mut f64| {
        if hi.is_finite() && !lo.is_finite() {
            *lo = *hi;
        } else if lo.is_finite() && !hi.is_finite() {
            *hi = *lo;
        }
    };
    for (i, y) in row_dual.iter().enumerate().take(lp.num_rows()) {
        if y.abs() > tau {
            hold(&mut lp.row_lower[i], &mut lp.row_upper[i]);
        }
    }
    for (j, z) in col_dual.iter().enumerate().take(lp.num_cols()) {
        if z.abs() > tau {
            hold(&mut lp.col_lower[j], &mut lp.col_upper[j]);
        }
    }
}

/// Points open in mechanism `d` (with the support motions scaled by `support_scale`): opening
/// above 1e-7 of the largest jump, as the report counts them.
pub fn open_points(map: &KinematicMap, d: &[f64], support_scale: f64) -> Vec<bool> {
    let (open, slide) = map.jumps(d, support_scale);
    let tol = 1e-7 * max_abs(&open).max(max_abs(&slide)).max(1e-300);
    open.iter()
        .zip(&map.gap)
        .map(|(&o, &g)| g > 0.0 || o > tol)
        .collect()
}

/// Whether the least-μ bisection asks its trials as elastic programs ([`canonical_forces`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ElasticTrials {
    Off,
    Armed,
    On,
}

/// The least dual bound on an elastic trial's optimum `s` (relative to θ) that shows θ
/// inadmissible in the bisection's elastic trials ([`canonical_forces`]).
const ELASTIC_MARGIN: f64 = 1e-3;

/// Trials allowed to the ratio search ([`FrictionSearch::Ratio`]); it stops with the bracket
/// it has (the precision shown says how wide) where they run out.
pub const RATIO_TRIALS: usize = 30;

/// What the ratio search found: the least admissible μ shown (a field's own largest ratio), the
/// μ to impose (`least` widened by half the precision, at least 5e-4, so that the energy QP
/// has an interior), the largest μ shown inadmissible, and the field of the least ratio (the
/// force program's columns).
struct RatioSearch {
    least: Option<f64>,
    friction: Option<f64>,
    shown: f64,
    field: Option<Vec<f64>>,
}

/// The largest `|p_t| / p_n` of field `x` of `fp` over the points of joints without friction of
/// their own (not bilateral, not open under the relaxation), with the tolerance of
/// `friction_demand`: shears within 1e-8 of the largest force count as nothing. Infinite where
/// a point carries shear without compression. 2D.
fn field_ratio(
    map: &KinematicMap,
    fp: &ForceProgram,
    x: &[f64],
    relaxed: bool,
    open: &[bool],
) -> f64 {
    let (pn, pt) = fp.forces(x);
    let eps = 1e-8 * max_abs(&pn).max(max_abs(&pt));
    let mut r = 0.0f64;
    for k in 0..map.num_points() {
        let law = &map.laws[map.points[k].joint];
        if law.friction.is_some() || map.bilateral[k] || (relaxed && open[k]) {
            continue;
        }
        if pt[k].abs() > eps {
            r = r.max(if pn[k] > 0.0 {
                (pt[k].abs() - eps) / pn[k]
            } else {
                f64::INFINITY
            });
        }
    }
    r
}

/// The trial program of the ratio search at `theta`: the physical force program `fp` at
/// μ = θ with one more column `s` (the last; cost 1, `s ≥ 0`) in the Coulomb rows of the points
/// without friction of their own: `±p_t − θ p_n − s·ḡ_k ≤ 0`. `ḡ` is `normal` (the normal
/// forces of the previous field, Crouzeix, Ferland and Schaible's normalisation: `s` is then
/// the largest excess of a ratio over θ, to first order); a point where it carries nothing (at
/// most 1e-9 of its largest) keeps Coulomb's rows at θ as they are. Without `normal` every
/// `ḡ_k` is the mean point load.
fn ratio_program(
    fp: &ForceProgram,
    map: &KinematicMap,
    open: &[bool],
    theta: f64,
    normal: Option<&[f64]>,
) -> (LinearProgram, usize) {
    let lp0 = &fp.lp;
    let big = normal.map_or(0.0, max_abs);
    let mean = fp.force_scale.abs().max(1e-300) / map.num_points().max(1) as f64;
    let mut entries = Vec::new();
    for k in 0..map.num_points() {
        let law = &map.laws[map.points[k].joint];
        if law.friction.is_some() || map.bilateral[k] || open[k] {
            continue;
        }
        let (Some(cn), Some(ct)) = (fp.pn[k], fp.pt[k]) else {
            continue;
        };
        let g = match normal {
            Some(n) if n[k] > 1e-9 * big => n[k],
            Some(_) => continue,
            None => mean,
        };
        // Coulomb's rows of point k: `±p_t − θ p_n ≤ 0` (the law rows, after equilibrium).
        let rows_n: Vec<(usize, f64)> =
            lp0.column(cn).filter(|&(i, _)| i >= map.num_dofs).collect();
        for (i, v) in lp0.column(ct) {
            if i < map.num_dofs || v.abs() != 1.0 || lp0.row_upper[i] != 0.0 {
                continue;
            }
            if rows_n.iter().any(|&(r, a)| r == i && a == -theta) {
                entries.push((i, -g));
            }
        }
    }
    let mut lp = lp0.clone();
    lp.cost.iter_mut().for_each(|c| *c = 0.0);
    lp.maximise = false;
    let s = lp.add_column(1.0, 0.0, f64::INFINITY, entries);
    (lp, s)
}

/// The least μ admitting a physical optimal field, by the ratio search
/// ([`FrictionSearch::Ratio`], docs/canonical.md "The forces"). Each trial at θ minimises `s`
/// over [`ratio_program`]; its answer gives
/// * an upper bound: its field's own largest ratio (an optimal field, admissible at that μ);
/// * a lower bound where θ is shown inadmissible: the program infeasible (Clarabel's
///   certificate), or its optimum bounded above 1e-6·θ by duals that are dual feasible (no field
///   has every `|p_t| − θ p_n ≤ 0`).
///
/// θ: 0.5, then 4× the last inadmissible θ until a field's ratio is within 16× of it, then the
/// geometric mean of the bracket; once the bracket is within 4× the precision, a decisive trial
/// at the upper bound less 0.9 of the precision (inadmissible, it ends the search).
#[allow(clippy::too_many_arguments)]
fn least_by_ratio(
    stages: &mut Stages,
    map: &KinematicMap,
    build: &impl Fn(&KinematicMap) -> ForceProgram,
    value: f64,
    tol: f64,
    open: &[bool],
    relaxed: bool,
    precision: f64,
    start: Option<Vec<f64>>,
) -> Result<RatioSearch> {
    let mut normal = start;
    let (mut lo, mut shown) = (0.0f64, 0.0f64);
    let mut least = f64::INFINITY;
    // The least θ at which a trial's field held Coulomb's rows.
    let mut hi = f64::INFINITY;
    let mut field: Option<Vec<f64>> = None;
    for _ in 0..RATIO_TRIALS {
        if (least.is_finite() && least - lo <= precision * least) || lo >= MAX_FRICTION {
            break;
        }
        let theta = if !least.is_finite() {
            if lo == 0.0 {
                0.5
            } else {
                4.0 * lo
            }
        } else if least - lo <= 4.0 * precision * least {
            // Close: a decisive trial (inadmissible, it ends the search).
            least * (1.0 - 0.9 * precision)
        } else if lo > 0.0 {
            // The geometric mean (the bracket's ratio halves in logarithm), at most 4·lo as
            // the bracket's growth: a field's ratio can be far above the least (10¹⁰ on the
            // façade in running bond, where a point carries shear on next to no compression).
            (lo * least).sqrt().min(4.0 * lo)
        } else {
            0.5 * least
        }
        .min(MAX_FRICTION);
        let fp =
            programs::physical_force_program(map, build, value, tol, open, Some(theta), relaxed);
        let (lp, scol) = ratio_program(&fp, map, open, theta, normal.as_deref());
        let solved = stages.solve_single(&lp, true);
        let before = least;
        let what = match solved {
            Ok(s) if s.status == LpStatus::Infeasible => {
                (lo, shown) = (lo.max(theta), shown.max(theta));
                "infeasible".to_string()
            }
            Ok(s) if s.status == LpStatus::Optimal && s.x.len() == lp.num_cols() => {
                let x = &s.x[..fp.lp.num_cols()];
                let r = field_ratio(map, &fp, x, relaxed, open);
                let bound = lp::sequence::certify_with_bound(&lp, &s)
                    .filter(|(c, _)| c.dual <= lp::sequence::CERTIFICATE_TOLERANCE)
                    .map(|(_, b)| b);
                let inadmissible = bound.is_some_and(|b| b > 1e-6 * theta);
                if inadmissible {
                    (lo, shown) = (lo.max(theta), shown.max(theta));
                } else if r <= theta * (1.0 + 1e-9) {
                    hi = hi.min(theta);
                } else {
                    lo = lo.max(theta);
                }
                if r < least {
                    least = r;
                    field = Some(x.to_vec());
                }
                normal = Some(fp.forces(x).0);
                format!(
                    "s {:.3e}, bound {}, field ratio {r:.6}{}",
                    s.x[scol],
                    bound.map_or("none".into(), |b| format!("{b:.3e}")),
                    if inadmissible { ": inadmissible" } else { "" }
                )
            }
            // Undecided: the search moves on as if θ were inadmissible, but `shown` stays.
            Ok(s) => {
                lo = lo.max(theta);
                format!("undecided ({:?})", s.status)
            }
            Err(e) => {
                lo = lo.max(theta);
                format!("undecided (failed: {e})")
            }
        };
        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
            eprintln!(
                "trace: least-μ ratio trial θ {theta:.6}: {what}; bracket [{lo:.6}, {least:.6}] (was {before:.6}), shown {shown:.6}"
            );
        }
    }
    if !least.is_finite() || least > MAX_FRICTION {
        return Ok(RatioSearch {
            least: None,
            friction: None,
            shown,
            field: None,
        });
    }
    let friction = hi.min(least * (1.0 + 0.5 * precision.max(1e-3)));
    Ok(RatioSearch {
        least: Some(least),
        friction: Some(friction),
        shown,
        field,
    })
}

/// Relative duality gap above which a candidate force field is not reported while another
/// certifies ([`canonical_forces`]): the settlement certificate's tolerance.
pub const FIELD_GAP_TOLERANCE: f64 = crate::result::settlement::GAP_TOLERANCE;

/// The canonical force field among the optima of the force program `build(map)` of optimal
/// value `value`, with the points in `open` unloaded. Returns `(p_n, p_t, report)`.
///
/// `certify(p_n, p_t)` is the relative duality gap of a field with the reported mechanism (the
/// result's certificate). A candidate whose gap exceeds [`FIELD_GAP_TOLERANCE`] is not
/// reported while another certifies: the least-energy field, else the admissible one, else
/// the force program's own optimum (solved through the solver layer's fallback chain with
/// `opts`); if none certifies, the one of least gap. The rejected ones are listed in the
/// report (`rejected`).
#[allow(clippy::too_many_arguments)]
pub fn canonical_forces<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    build: impl Fn(&KinematicMap) -> ForceProgram,
    value: f64,
    open: &[bool],
    weights: &[f64],
    opts: &SolverOptions,
    copts: &CanonicalOptions,
    certify: &dyn Fn(&[f64], &[f64]) -> f64,
) -> Result<Option<(Vec<f64>, Vec<f64>, CanonicalForces<S::D>)>> {
    // The feasibility LPs of the bisection go to Clarabel: on large models its interior point
    // decides feasibility in a few dozen iterations where a warm simplex needs thousands.
    let copts_lp = SolverOptions {
        method: Method::Clarabel,
        feasibility_tolerance: opts.feasibility_tolerance.min(1e-10),
        ..*opts
    };
    let mut stages = Stages {
        opts: copts_lp,
        solves: 0,
    };
    let tol = copts.tolerance;
    let needs_mu = map.laws.iter().enumerate().any(|(j, l)| {
        l.friction.is_none()
            && !(map.joint_start[j]..map.joint_start[j + 1]).all(|k| map.bilateral[k])
    });
    // The last admissible field found at the μ finally imposed (a program's feasible point): the
    // reported field if the energy QP does not end optimal.
    let mut admissible: Option<(Option<f64>, bool, Vec<f64>)> = None;
    // Feasibility at μ (None: the model's own laws), with a warm basis shared by all μ.
    let mut basis: Option<Basis> = None;
    // The size of the force program (its columns; the same under every μ and relaxation, which
    // change bounds and rows only): the solver policy's size classes of the elastic trials and
    // of the least-μ search's limit. Built once, where one of them asks.
    let columns = std::cell::OnceCell::new();
    let columns = || {
        *columns.get_or_init(|| {
            programs::physical_force_program(map, &build, value, tol, open, None, false)
                .lp
                .num_cols()
        })
    };
    // The elastic trials (2D): `Off` for good, `Armed` (a large program, lp::policy::
    // elastic_trials: on after the first slow proof of infeasibility) or `On`; and how many
    // trials they decided.
    let elastic_on = std::cell::Cell::new(match copts.elastic_trials {
        Some(true) => ElasticTrials::On,
        Some(false) => ElasticTrials::Off,
        None if map.tangents_per_point == 1 && columns() >= copts.elastic_trial_min_columns => {
            ElasticTrials::Armed
        }
        None => ElasticTrials::Off,
    });
    let elastic_count = std::cell::Cell::new(0usize);
    let feasible = |stages: &mut Stages,
                    mu: Option<f64>,
                    basis: &mut Option<Basis>,
                    relaxed: bool,
                    admissible: &mut Option<(Option<f64>, bool, Vec<f64>)>|
     -> Result<Trial> {
        let fp = programs::physical_force_program(map, &build, value, tol, open, mu, relaxed);
        // The bisection's trials (μ > 0) go to Clarabel alone: one it does not decide is left
        // undecided (HiGHS's interior point took 45–70 s to decide each of two such trials on
        // the façade in running bond, where Clarabel decides the others in 1–8 s). The other
        // programs go along the fallback chain; one that reaches no conclusion there counts as
        // infeasible (that μ is not imposed).
        let single = mu.is_some_and(|m| m > 0.0);
        // On a large 2D program, once Clarabel has proved a trial infeasible slowly (more than
        // lp::policy::ELASTIC_SWITCH_ITERATIONS iterations: it is slow where a trial is nearly
        // feasible, 83–101 iterations against 23–37 for a feasible one on the 0.5 m façade in
        // running bond), every later trial is asked first as the bounded elastic program of the
        // ratio search (`ratio_program`, normalised by the last admissible field's normal
        // forces), which answers the same question in the time of a feasible trial: `s = 0`
        // (its field's own ratio at most θ) is admissible, an optimum bounded above 0 by
        // certified duals is inadmissible. Otherwise the feasibility trial decides, as on small
        // programs, and the elastic trials stop for this search.
        // At most two passes: an Armed trial that reaches its cap switches the elastic trials
        // on and is asked again as one (below).
        loop {
            if single && elastic_on.get() == ElasticTrials::On && map.tangents_per_point == 1 {
                if let Some(normal) = admissible.as_ref().map(|(m0, r0, x)| {
                    programs::physical_force_program(map, &build, value, tol, open, *m0, *r0)
                        .forces(x)
                        .0
                }) {
                    let theta = mu.unwrap_or(0.0);
                    let (lp, scol) = ratio_program(&fp, map, open, theta, Some(&normal));
                    // Clarabel's default settings first (`decision`), then its tighter ones for
                    // large programs where the duals do not certify: each fails on some trials
                    // the other decides (the 3,200-block wall at θ = 8: dual violation 3.7e-6
                    // with the defaults, 2.2e-8 tight; the 0.5 m façade in running bond at
                    // θ = 0.5, 3.49 and 3.68: 3.5e-5 to 9.3e-4 tight, certified with the
                    // defaults, which decide all its trials).
                    let settings: &[bool] = if lp.num_cols() >= lp::clarabel::PRESOLVE_MIN_COLUMNS {
                        &[true, false]
                    } else {
                        &[true]
                    };
                    for &decision in settings {
                        match stages.solve_single(&lp, decision) {
                            Ok(s)
                                if s.status == LpStatus::Optimal && s.x.len() == lp.num_cols() =>
                            {
                                let x = &s.x[..fp.lp.num_cols()];
                                let r = field_ratio(map, &fp, x, relaxed, open);
                                let cert = lp::sequence::certify_with_bound(&lp, &s);
                                if std::env::var_os("VOUSSOIR_TRACE").is_some() {
                                    eprintln!(
                                    "trace: elastic trial θ {theta:.6}: s {:.3e}, certificate {:?}, field ratio {r:.6}",
                                    s.x[scol], cert
                                );
                                }
                                // Duals dual feasible to the solver layer's certificate tolerance,
                                // and a bound well above what that tolerance leaves uncertain:
                                // `s` is the excess of a ratio over θ, so 1e-3·θ. (At 1e-6·θ, a
                                // tight trial at θ = 4.2378 on the 0.5 m façade in running bond,
                                // s = 6.1e-6 and bound 4.4e-6 where s = 0 is the optimum, counted
                                // a μ inadmissible that a field of ratio 3.8653 admits.)
                                let bound = cert
                                    .filter(|(c, _)| c.dual <= lp::policy::CERTIFICATE_TOLERANCE)
                                    .map(|(_, b)| b);
                                if bound.is_some_and(|b| b > ELASTIC_MARGIN * theta) {
                                    elastic_count.set(elastic_count.get() + 1);
                                    return Ok(Trial::Inadmissible);
                                }
                                if r <= theta * (1.0 + 1e-9) {
                                    elastic_count.set(elastic_count.get() + 1);
                                    *admissible = Some((mu, relaxed, x.to_vec()));
                                    return Ok(Trial::Admissible(r));
                                }
                            }
                            // The elastic program relaxes the trial's rows: without a point,
                            // neither has one (Clarabel's certificate, as for a feasibility trial).
                            Ok(s) if s.status == LpStatus::Infeasible => {
                                elastic_count.set(elastic_count.get() + 1);
                                return Ok(Trial::Inadmissible);
                            }
                            _ => {}
                        }
                    }
                    elastic_on.set(ElasticTrials::Off);
                }
            }
            // Armed (a large 2D program, no slow proof yet): the trial runs to at most
            // lp::policy::ELASTIC_SWITCH_ITERATIONS iterations; one that reaches them is the slow
            // proof that switches the elastic trials on, and is asked again as one, at the same μ,
            // instead of being run to its end (the 0.5 m façade in running bond: its trial at
            // μ = 2 took 101 iterations, 9.4 s, where its elastic program decides in 33, 1.8 s;
            // docs/performance.md, "The force stage's trials in the size class (session 29)").
            let cap = (single
                && elastic_on.get() == ElasticTrials::Armed
                && map.tangents_per_point == 1
                && admissible.is_some())
            .then_some(copts.elastic_switch_iterations);
            let solved = if single {
                stages.solve_single_capped(&fp.lp, true, cap)
            } else {
                stages.solve(&fp.lp, basis)
            };
            if cap.is_some() && matches!(&solved, Err(e) if e.to_string().contains("MaxIterations"))
            {
                elastic_on.set(ElasticTrials::On);
                continue;
            }
            return match solved {
                Ok(s) if s.status == LpStatus::Infeasible => {
                    if single
                        && elastic_on.get() == ElasticTrials::Armed
                        && s.iterations > copts.elastic_switch_iterations as i64
                    {
                        elastic_on.set(ElasticTrials::On);
                    }
                    Ok(Trial::Inadmissible)
                }
                Ok(s) if s.status == LpStatus::Optimal => {
                    // In 2D the field's own largest |p_t|/p_n (with the tolerance of
                    // `friction_demand` below) is an admissible μ too, often well below the one
                    // imposed; in 3D the rows are the pyramid's facets, not |p_t|, so μ stands.
                    let mut ratio = mu.unwrap_or(f64::INFINITY);
                    if let (1, Some(_)) = (map.tangents_per_point, mu) {
                        ratio = ratio.min(field_ratio(map, &fp, &s.x, relaxed, open));
                    }
                    *admissible = Some((mu, relaxed, s.x));
                    Ok(Trial::Admissible(ratio))
                }
                _ if single => Ok(Trial::Undecided),
                _ => Ok(Trial::Inadmissible),
            };
        }
    };
    // The energy QP's iterations: at most `energy_qp_iterations` (and the solver options' own
    // limit, if smaller).
    let qp_cap = copts
        .energy_qp_iterations
        .min(opts.iteration_limit.unwrap_or(usize::MAX))
        .max(1);
    let qp_opts = SolverOptions {
        iteration_limit: Some(qp_cap),
        ..copts_lp
    };
    // The energy QP over the optimal fields at μ (relaxed: shear allowed at open points, at 10³
    // times the energy).
    let energy_qp = |mu: Option<f64>, relaxed: bool| {
        let fp = programs::physical_force_program(map, &build, value, tol, open, mu, relaxed);
        let w: Vec<f64> = weights
            .iter()
            .zip(open)
            .map(|(&w, &o)| if relaxed && o { w * 1e-3 } else { w })
            .collect();
        let p = programs::force_energy_quadratic(&fp, &w);
        let t0 = std::time::Instant::now();
        let q = lp::solve_quadratic(&fp.lp, &p, &qp_opts);
        trace("energy QP", t0);
        (fp, q)
    };
    let optimal = |q: &Result<lp::LpSolution>| matches!(q, Ok(q) if q.status == LpStatus::Optimal);
    let mut solves;
    let (least, mu, relaxed, fp, qs);
    let precision_shown: Option<f64>;
    let least_above: Option<f64>;
    let precision = copts.friction_precision;
    {
        // Without a physical optimal field under the model's own laws (open points unloaded),
        // there is nothing to select from: the solver's forces stand.
        let mut rel = false;
        if feasible(&mut stages, None, &mut None, false, &mut admissible)?
            .ratio()
            .is_none()
        {
            rel = true;
            if feasible(&mut stages, None, &mut None, true, &mut admissible)?
                .ratio()
                .is_none()
            {
                return Ok(None);
            }
        }
        // The least μ: bisection on LP feasibility (the least μ is the least value of a
        // largest ratio |p_t|/p_n over a polyhedron, a generalised fractional program: no
        // single LP gives it, docs/canonical.md). The admissible field at the upper bracket
        // is kept.
        // `shown`: the largest μ shown inadmissible (the precision the result states is
        // measured from it; an undecided trial moves `lo` but not `shown`).
        let mut shown = 0.0f64;
        // The search stopped above its limit (`friction_search_limit`): the largest μ shown
        // inadmissible, which the least exceeds.
        let mut beyond: Option<f64> = None;
        let (l, m) = if !needs_mu {
            (None, None)
        } else if map.tangents_per_point == 1 && copts.friction_search == FrictionSearch::Ratio {
            // The ratio search (2D), started from the normal forces of the field just found
            // under the model's own laws.
            let start = admissible.as_ref().map(|(_, _, x)| {
                programs::physical_force_program(map, &build, value, tol, open, None, rel)
                    .forces(x)
                    .0
            });
            let r = least_by_ratio(
                &mut stages,
                map,
                &build,
                value,
                tol,
                open,
                rel,
                precision,
                start,
            )?;
            shown = r.shown;
            match (r.least, r.friction, r.field) {
                (Some(l), Some(m), Some(x)) => {
                    admissible = Some((Some(m), rel, x));
                    (Some(l), Some(m))
                }
                _ => (None, None),
            }
        } else {
            // The policy's size class (`lp::policy::FRICTION_LIMIT_MIN_COLUMNS`; a test may
            // lower it).
            let limit = copts
                .friction_search_limit
                .filter(|_| columns() >= copts.friction_limit_min_columns);
            // μ = 0 is tried first, except with a limit: there the limit's trial comes first,
            // and μ = 0 only where it is admissible (the admissible sets are nested in μ, so a
            // limit shown inadmissible shows 0 inadmissible too; the same trials and answers
            // otherwise, in another order). A trial at μ = 0 cost 11.2 s of wall clock on the
            // 0.25 m façade in running bond, whose least μ lies above the limit
            // (docs/performance.md, "The force stage's trials in the size class (session 29)").
            let zero = |stages: &mut Stages,
                        basis: &mut Option<Basis>,
                        admissible: &mut Option<(Option<f64>, bool, Vec<f64>)>|
             -> Result<bool> {
                Ok(feasible(stages, Some(0.0), basis, rel, admissible)?
                    .ratio()
                    .is_some())
            };
            if limit.is_none() && zero(&mut stages, &mut basis, &mut admissible)? {
                (Some(0.0), Some(0.0))
            } else {
                // `hi` the least μ imposed on a feasible program, `least` the least admissible μ
                // shown (a feasible field's own largest ratio, ≤ hi), `lo` the largest μ not
                // shown admissible.
                let (mut lo, mut hi) = (0.0, 0.5);
                let mut least = f64::INFINITY;
                let mut found = false;
                // With a limit the climb starts at it (μ = 0 after it): a trial at 0.5 brackets
                // nothing the limit's trial does not, where the least μ is above the limit (the
                // case the limit is for), and costs a program (1.2 s on the 3,200-block wall).
                if let Some(l) = limit {
                    hi = l.min(MAX_FRICTION);
                }
                while hi <= MAX_FRICTION {
                    match feasible(&mut stages, Some(hi), &mut basis, rel, &mut admissible)? {
                        Trial::Admissible(r) => {
                            least = r;
                            found = true;
                            break;
                        }
                        Trial::Inadmissible => shown = hi,
                        Trial::Undecided => {}
                    }
                    lo = hi;
                    // Past the search's limit the climb only looks for an admissible field: 16×,
                    // past the trials just above the limit, which are the slow ones where the
                    // least μ lies near them (the 3,200-block wall's at 8: 80 iterations, 11 s).
                    hi *= if limit.is_some_and(|l| lo >= l) {
                        16.0
                    } else {
                        4.0
                    };
                }
                // With a limit, μ = 0 where no trial of the climb has shown its μ inadmissible
                // (a trial that does not admit its μ leaves `admissible` as it was).
                if limit.is_some()
                    && shown == 0.0
                    && zero(&mut stages, &mut basis, &mut admissible)?
                {
                    (Some(0.0), Some(0.0))
                } else if found {
                    let mut at_hi = admissible.clone();
                    // Above the limit (shown inadmissible there, or undecided) the bracket is the
                    // answer: no bisection.
                    if limit.is_some_and(|l| lo >= l && least > l) {
                        beyond = Some(shown);
                    }
                    while beyond.is_none() && least - lo > precision * least {
                        let mid = 0.5 * (lo + least);
                        match feasible(&mut stages, Some(mid), &mut basis, rel, &mut admissible)? {
                            Trial::Admissible(r) => {
                                hi = mid;
                                least = least.min(r);
                                at_hi = admissible.clone();
                            }
                            Trial::Inadmissible => {
                                shown = mid;
                                lo = mid;
                            }
                            Trial::Undecided => lo = mid,
                        }
                    }
                    admissible = at_hi;
                    (Some(least), Some(hi))
                } else {
                    (None, None)
                }
            }
        };
        least_above = beyond.filter(|_| l.is_some());
        precision_shown = l.map(|l| {
            if l > 0.0 {
                (1.0 - shown / l).max(0.0)
            } else {
                0.0
            }
        });
        let (mut f, mut q) = energy_qp(m, rel);
        solves = stages.solves + 1;
        // At the least μ itself the admissible set can be too thin for the interior point
        // (the LACT3 portal: "infeasible" at the μ its bisection had just found feasible).
        // Once more at μ widened by the bisection's precision (at least 1e-3); the field then holds
        // |shear| ≤ μ'·normal with that μ' (reported as `friction`; `least_friction` stays
        // the bisection's).
        let mut m = m;
        if matches!(&q, Ok(q) if q.status == LpStatus::Infeasible) {
            if let Some(mm) = m.filter(|m| *m > 0.0) {
                let wider = mm * (1.0 + precision.max(1e-3));
                let (f2, q2) = energy_qp(Some(wider), rel);
                solves += 1;
                if optimal(&q2) {
                    (f, q, m) = (f2, q2, Some(wider));
                }
            }
        }
        (least, mu, relaxed, fp, qs) = (l, m, rel, f, q);
    }
    // The admissible field kept for the fallback must be one of the set finally used.
    let admissible = admissible
        .filter(|(m, r, _)| *m == mu && *r == relaxed)
        .map(|(_, _, x)| x);
    // The QP's point must hold the force program (equilibrium, the optimal value, Coulomb)
    // to 1e-7 of the program's scale (its largest bound or row term): Clarabel's "almost
    // solved" counts as optimal. Such a point is not the selected field: the admissible one
    // stands. This check is global, so it does not catch everything: on the façade in running
    // bond at 0.25 m the QP point passed it and left the result uncertified (gap 5.7e-2), the
    // cause found below (each candidate's certificate is checked before it is reported).
    let holds = |x: &[f64]| -> bool {
        let lp = &fp.lp;
        if x.len() != lp.num_cols() {
            return false;
        }
        let act = lp.row_activity(x);
        let mut size = vec![0.0f64; lp.num_rows()];
        for (j, &xj) in x.iter().enumerate() {
            for (i, v) in lp.column(j) {
                size[i] += (v * xj).abs();
            }
        }
        let fin = |b: f64| if b.is_finite() { b.abs() } else { 0.0 };
        let scale = (0..lp.num_rows())
            .map(|i| size[i].max(fin(lp.row_lower[i])).max(fin(lp.row_upper[i])))
            .fold(0.0f64, f64::max)
            .max(1e-300);
        let rows = (0..lp.num_rows())
            .map(|i| (lp.row_lower[i] - act[i]).max(act[i] - lp.row_upper[i]))
            .fold(0.0f64, f64::max);
        let cols = (0..lp.num_cols())
            .map(|j| (lp.col_lower[j] - x[j]).max(x[j] - lp.col_upper[j]))
            .fold(0.0f64, f64::max);
        rows.max(cols) <= 1e-7 * scale
    };
    if let (Some(_), Ok(q)) = (std::env::var_os("VOUSSOIR_TRACE"), &qs) {
        eprintln!(
            "trace: energy QP {:?} (reduced accuracy {}) after {} iterations",
            q.status, q.reduced_accuracy, q.iterations
        );
    }
    // Why the QP's point is not a candidate (listed in `rejected`). A QP that reaches its
    // iteration cap is not used even where Clarabel calls its point "almost solved" (reduced
    // accuracy): on the façade in running bond at 0.25 m that point, after 500 iterations,
    // failed the duality certificate (gap 5.7e-2). A point solved to full accuracy at the cap's
    // last iteration is used.
    let capped = |q: &Result<lp::LpSolution>| match q {
        Ok(q) => {
            q.status == LpStatus::Optimal
                && q.reduced_accuracy
                && q.iterations.max(0) as usize >= qp_cap
        }
        Err(e) => e.to_string().contains("MaxIterations"),
    };
    let qp_reason: Option<String> = match &qs {
        _ if capped(&qs) => Some(format!(
            "the energy QP stopped at its cap of {qp_cap} iteration{}{}",
            if qp_cap == 1 { "" } else { "s" },
            if matches!(&qs, Ok(q) if q.reduced_accuracy) {
                ", at reduced accuracy"
            } else {
                ""
            }
        )),
        Ok(q) if q.status == LpStatus::Optimal && !holds(&q.x) => {
            Some("the energy QP's point does not hold the force program to 1e-7".into())
        }
        Ok(q) if q.status == LpStatus::Optimal => None,
        Ok(q) => Some(format!(
            "the energy QP ended {}",
            format!("{:?}", q.status).to_lowercase()
        )),
        Err(e) => Some(format!("the energy QP failed: {e}")),
    };
    let qs = match (qs, &qp_reason) {
        (Ok(q), None) => Ok(q),
        (_, r) => Err(crate::error::Error::Solver(r.clone().unwrap_or_default())),
    };
    // The candidates, in order of preference. Each must also certify the result: on the façade
    // in running bond at 0.35 and 0.25 m the QP ends at Clarabel's reduced accuracy among
    // self-stresses of 1.5e6 and 4.4e7 kN (the fields near the least μ wedge the bond), its
    // equilibrium rows off by up to 0.12 and 1.2 kN — within the check above, 1e-7 of that
    // scale — which sum to 2.3 and 10.2 kN·m of work on the mechanism: gaps 1.3e-2 and 5.7e-2,
    // where the admissible field (an LP trial's point) certifies (gaps 5e-10 and 9.1e-9).
    let mut candidates: Vec<(ForceSelection, Vec<f64>)> = Vec::new();
    match qs {
        Ok(qs) if qs.status == LpStatus::Optimal => {
            candidates.push((ForceSelection::LeastEnergy, qs.x))
        }
        other => {
            if std::env::var_os("VOUSSOIR_TRACE").is_some() {
                eprintln!(
                    "trace: energy QP not optimal ({:?}): the admissible field stands",
                    other.map(|q| q.status)
                );
            }
        }
    }
    if let Some(x) = admissible.filter(|x| x.len() == fp.lp.num_cols()) {
        candidates.push((ForceSelection::Admissible, x));
    }
    if candidates.is_empty() {
        return Ok(None);
    }
    // An interior-point solution within its tolerance of the bounds: on them (open points carry
    // exactly nothing, compression is never negative).
    let clamp = |mut x: Vec<f64>| {
        for (j, x) in x.iter_mut().enumerate() {
            *x = x.clamp(fp.lp.col_lower[j], fp.lp.col_upper[j]);
        }
        x
    };
    let mut rejected: Vec<RejectedField> = Vec::new();
    if let Some(reason) = qp_reason {
        rejected.push(RejectedField {
            field: ForceSelection::LeastEnergy,
            gap: None,
            reason: Some(reason),
        });
    }
    // The least gap so far (reported if nothing certifies).
    let mut best: Option<(f64, ForceSelection, Vec<f64>)> = None;
    let mut chosen: Option<(ForceSelection, Vec<f64>)> = None;
    let mut consider = |sel: ForceSelection, x: Vec<f64>, i: usize, rejected: &mut Vec<_>| {
        let (pn, pt) = fp.forces(&x);
        let gap = certify(&pn, &pt);
        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
            eprintln!("trace: candidate {sel:?}: gap {gap:.3e}");
        }
        if gap <= FIELD_GAP_TOLERANCE && i >= copts.reject_fields {
            return Some((sel, x));
        }
        rejected.push(RejectedField {
            field: sel,
            gap: Some(gap),
            reason: None,
        });
        if best.as_ref().is_none_or(|(g, _, _)| gap < *g) {
            best = Some((gap, sel, x));
        }
        None
    };
    for (i, (sel, x)) in candidates.into_iter().enumerate() {
        chosen = consider(sel, clamp(x), i, &mut rejected);
        if chosen.is_some() {
            break;
        }
    }
    if chosen.is_none() {
        // Neither canonical field certifies: the force program's own optimum, through the
        // solver layer's fallback chain, as the raw analysis reports it.
        let raw = build(map);
        let sol = raw.solve(opts)?;
        solves += 1;
        if sol.status == LpStatus::Optimal {
            let (rpn, rpt) = raw.forces(&sol.x);
            let mut x = vec![0.0; fp.lp.num_cols()];
            for (c, v) in fp.pn.iter().zip(&rpn).chain(fp.pt.iter().zip(&rpt)) {
                if let Some(c) = c {
                    x[*c] = *v;
                }
            }
            chosen = consider(ForceSelection::ForceProgram, x, usize::MAX, &mut rejected);
        }
    }
    let (selected_by, x) = match chosen {
        Some(c) => c,
        None => {
            let (_, sel, x) = best.expect("a candidate was considered");
            rejected.retain(|r| r.field != sel);
            (sel, x)
        }
    };
    let (pn, pt) = fp.forces(&x);
    // The force program's optimum holds no imposed μ.
    let mu = if selected_by == ForceSelection::ForceProgram {
        None
    } else {
        mu
    };
    // Checks: forces at open points, friction excess.
    let nt = map.tangents_per_point;
    let mut largest_open_force = 0.0f64;
    let mut excess = 0.0f64;
    // The friction the reported field needs on the joints without friction of their own: the
    // least μ with |p_t| ≤ μ·p_n + ε at every point, ε = 1e-8 of the largest force (the energy
    // QP's tolerance: without it, shears of 1e-9 of the largest force at points carrying
    // 1e-11 of it read as μ ≈ 150 on the 3,200-block wall).
    let fscale = max_abs(&pn).max(max_abs(&pt)).max(1e-300);
    let eps = 1e-8 * fscale;
    let mut demand: Option<f64> = None;
    for k in 0..map.num_points() {
        let shear = (0..nt).map(|m| pt[k * nt + m].powi(2)).sum::<f64>().sqrt();
        if open[k] {
            largest_open_force = largest_open_force.max(pn[k].abs()).max(shear);
        }
        let law = &map.laws[map.points[k].joint];
        if needs_mu && law.friction.is_none() && !map.bilateral[k] && !open[k] {
            let d = demand.get_or_insert(0.0);
            if shear > eps && pn[k] > 0.0 {
                *d = d.max((shear - eps) / pn[k]);
            }
        }
        if !map.bilateral[k] && !(relaxed && open[k]) {
            let m = law.friction.or(mu);
            if let Some(m) = m {
                excess = excess.max(shear - m * pn[k] - law.cohesion);
            }
        }
    }
    // Reaction ranges over the same set.
    let mut ranges = Vec::new();
    if copts.reaction_ranges && st.num_blocks() <= copts.ranges_max_blocks {
        let nd = <S::D as Dim>::DOFS;
        let ns = st.num_supports();
        let mut coeff: Vec<Vec<Vec<(usize, f64)>>> = vec![vec![Vec::new(); nd]; ns];
        let mut loaded = vec![false; ns];
        crate::reporting::reaction_terms(st, map, |s, k, which, row| {
            let col = if which == 0 {
                fp.pn[k]
            } else {
                fp.pt[k * nt + which - 1]
            };
            if !open[k] {
                loaded[s] = true;
            }
            if let Some(c) = col {
                for (i, &v) in row.iter().enumerate() {
                    if v != 0.0 {
                        coeff[s][i].push((c, v));
                    }
                }
            }
        });
        let value_of = |entries: &[(usize, f64)], x: &[f64]| -> f64 {
            entries.iter().map(|&(c, v)| v * x[c]).sum()
        };
        let centres = st.contact_bodies().supports;
        let mut rstages = Stages::new(opts);
        let mut b = basis.clone();
        for s in 0..ns {
            let mut lo = vec![0.0; nd];
            let mut hi = vec![0.0; nd];
            if loaded[s] {
                for i in 0..nd {
                    let mut lp = fp.lp.clone();
                    for &(c, v) in &coeff[s][i] {
                        lp.cost[c] += v;
                    }
                    let a = rstages.solve(&lp, &mut b)?;
                    lp.maximise = true;
                    let z = rstages.solve(&lp, &mut b)?;
                    let here = value_of(&coeff[s][i], &x);
                    lo[i] = if a.status == LpStatus::Optimal {
                        value_of(&coeff[s][i], &a.x).min(here)
                    } else {
                        here
                    };
                    hi[i] = if z.status == LpStatus::Optimal {
                        value_of(&coeff[s][i], &z.x).max(here)
                    } else {
                        f64::INFINITY
                    };
                }
            }
            let clean = |v: f64| crate::result::clean(v, fscale);
            let lo: Vec<f64> = lo.into_iter().map(clean).collect();
            let hi: Vec<f64> = hi.into_iter().map(clean).collect();
            let unique = lo
                .iter()
                .zip(&hi)
                .all(|(a, b)| (b - a).abs() <= 1e-6 * fscale);
            ranges.push(ReactionRange {
                support: st.support_name(s).to_string(),
                unique,
                min: S::D::wrench(&lo, centres[s].0),
                max: S::D::wrench(&hi, centres[s].0),
            });
        }
        solves += rstages.solves;
    }
    Ok(Some((
        pn,
        pt,
        CanonicalForces {
            least_friction: least,
            least_friction_above: least_above,
            friction_precision: precision_shown,
            friction: mu,
            friction_demand: demand,
            selected_by,
            physical: if selected_by == ForceSelection::ForceProgram {
                largest_open_force <= eps
            } else {
                !relaxed
            },
            largest_open_force,
            largest_friction_excess: excess.max(0.0),
            reaction_ranges: ranges,
            solves,
            elastic_trials: elastic_count.get(),
            rejected,
        },
    )))
}

/// Solver options of the canonical stages: an interior-point backend runs at a tighter
/// tolerance, since the optimal values it holds fix the faces the next stages search.
fn stage_options(opts: &SolverOptions) -> SolverOptions {
    if opts.method != Method::Clarabel {
        *opts
    } else {
        SolverOptions {
            feasibility_tolerance: opts.feasibility_tolerance.min(1e-11),
            ..*opts
        }
    }
}

/// Settlement analysis with the canonical mechanism and forces (`docs/canonical.md`); the
/// solver's own solution is [`settlement::settle_with`]. The motion LP is solved first (its
/// basis starts the selection; `form` applies to the solver's own solution only), the force
/// LP only if no physical optimal field is found.
///
/// Where the result's certificate fails at the feasibility tolerance asked (two LPs each
/// optimal to 1e-9 can leave a small work's two sides more than 1e-7 apart), the whole analysis
/// runs once more at [`lp::policy::RETRY_FEASIBILITY_TOLERANCE`], as the solver's own
/// settlement does (`settlement::recertify`), and that result is reported if it certifies, its
/// `tried` naming the first attempt.
pub fn settle_canonical<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    form: SettlementForm,
    copts: &CanonicalOptions,
) -> Result<SettlementResult<S::D>> {
    let r = settle_canonical_at(st, opts, form, copts, &[])?;
    let tight = lp::policy::RETRY_FEASIBILITY_TOLERANCE;
    let gap = match &r.certificate {
        Some(c) if !c.ok && r.status == SettlementStatus::Mechanism => c.relative_gap,
        _ => return Ok(r),
    };
    if opts.feasibility_tolerance <= tight {
        return Ok(r);
    }
    let why = format!(
        "{} at feasibility tolerance {:.0e}: the settlement's duality gap {gap:.1e} exceeds {:.0e}",
        r.solver.method.name(),
        opts.feasibility_tolerance,
        FIELD_GAP_TOLERANCE
    );
    let o2 = SolverOptions {
        feasibility_tolerance: tight,
        ..*opts
    };
    match settle_canonical_at(st, &o2, form, copts, &[why]) {
        Ok(r2) if r2.certificate.as_ref().is_some_and(|c| c.ok) => Ok(r2),
        _ => Ok(r),
    }
}

/// [`settle_canonical`] at the options given, `tried` heading the solver's record.
fn settle_canonical_at<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    form: SettlementForm,
    copts: &CanonicalOptions,
    tried: &[String],
) -> Result<SettlementResult<S::D>> {
    let map = KinematicMap::new(st);
    let dead = st.load_vector(false);
    let mp = programs::settlement_motion_program(&map, &dead)?;
    let o = stage_options(opts);
    let mut basis = None;
    let t0 = std::time::Instant::now();
    let primal = lp::solve_warm(&mp.lp, &o, &mut basis)?;
    trace("stage 1", t0);
    if primal.status != LpStatus::Optimal {
        return settlement::settle_with(st, opts, form);
    }
    let raw = mp.motion(&primal.x);
    // The motion LP's optimum: the dead loads' work.
    let value = primal.objective;
    let weights = tributary_weights(st, &map);
    let t0 = std::time::Instant::now();
    let found = settlement_selection(&map, &mp, &primal, &raw, basis, &weights, &o, opts, copts)?;
    trace("mechanism", t0);
    let (d, mech) = match found {
        Some((d, m)) => (d, Some(m)),
        None => (raw, None),
    };
    let work = mp.objective_sign * value;
    let mut forces = None;
    let mut pnt = None;
    // The certificate of a field with the mechanism d, as the result states it.
    let wscale = crate::scale::settlement_work_scale(&map, &dead);
    let primal_work = dot(&dead, &d);
    let certify = |pn: &[f64], pt: &[f64]| {
        crate::scale::relative_gap(primal_work, settlement_dual(&map, pn, pt), wscale)
    };
    if copts.forces && mech.is_some() {
        let open = open_points(&map, &d, 1.0);
        let build = |m: &KinematicMap| programs::settlement_force_program(m, &dead);
        let t0 = std::time::Instant::now();
        if let Some((pn, pt, f)) =
            canonical_forces(st, &map, build, work, &open, &weights, &o, copts, &certify)?
        {
            pnt = Some((pn, pt));
            forces = Some(f);
        }
        trace("forces", t0);
    }
    // The method that solved the motion program (after any fallback), as the solver's own
    // settlement reports it.
    let mut solver = primal.solver_info();
    solver.tried.splice(0..0, tried.iter().cloned());
    let (pn, pt) = match pnt {
        Some(p) => p,
        None => {
            let fp = programs::settlement_force_program(&map, &dead);
            let sol = fp.solve(opts)?;
            if sol.status != LpStatus::Optimal {
                return settlement::settle_with(st, opts, form);
            }
            fp.forces(&sol.x)
        }
    };
    let s = settlement::SettlementSolution {
        status: SettlementStatus::Mechanism,
        primal: primal_work,
        dual: settlement_dual(&map, &pn, &pt),
        mechanism: d,
        pn,
        pt,
        solver,
    };
    let mut r = settlement::settlement_result_checked(st, &map, &s);
    if mech.is_none() {
        // Said, not silent: the default analysis asked for the canonical mechanism.
        r.message = format!(
            "{}; the canonical selection was not reached (its least-crack face could not be \
             solved): the solver's own mechanism is reported, which may depend on the method",
            r.message
        );
    }
    r.canonical = mech.map(|mechanism| Canonical { mechanism, forces });
    Ok(r)
}

/// The mechanism stages of a settlement from the motion program's solution `primal` (its
/// mechanism `raw`, its basis `basis`); after an interior point whose duals did not fix the
/// optimal face, again from a vertex of the dual simplex.
#[allow(clippy::too_many_arguments)]
fn settlement_selection(
    map: &KinematicMap,
    mp: &programs::MotionProgram,
    primal: &lp::LpSolution,
    raw: &[f64],
    basis: Option<Basis>,
    weights: &[f64],
    o: &SolverOptions,
    opts: &SolverOptions,
    copts: &CanonicalOptions,
) -> Result<Option<(Vec<f64>, CanonicalMechanism)>> {
    let found = canonical_mechanism(map, &mp.lp, primal, raw, basis, weights, o, copts)?;
    if found.is_some() || !primal.method.is_interior() {
        return Ok(found);
    }
    // The interior point's duals did not fix the optimal face (its solution is optimal only to
    // the solver's tolerance): cross over to a vertex with the dual simplex, as HiGHS's
    // crossover would, and select from there. (Not after a vertex: its duals are exact, and the
    // dual simplex would find the same face again; on the 30 × 20 wall with μ = 0.6 that second
    // pass took 81 s to reach the same dead end.)
    let vo = SolverOptions {
        method: Method::DualSimplex,
        ..*opts
    };
    let mut vbasis = None;
    let vertex = lp::solve_warm(&mp.lp, &vo, &mut vbasis)?;
    if vertex.status != LpStatus::Optimal {
        return Ok(None);
    }
    let vraw = mp.motion(&vertex.x);
    canonical_mechanism(map, &mp.lp, &vertex, &vraw, vbasis, weights, &vo, copts)
}

/// The canonical settlement mechanism alone (no force stage) of `st` on its map `map` (its
/// facets as the caller set them): the motion program solved again, then the mechanism
/// stages of [`settle_canonical`]. `None` where the motion program is not optimal or a stage
/// did not solve (the caller keeps the solver's mechanism). What capacity curves deform the
/// structure with and sweeps report (docs/canonical.md).
pub fn settlement_mechanism<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
    copts: &CanonicalOptions,
) -> Result<Option<(Vec<f64>, CanonicalMechanism)>> {
    let dead = st.load_vector(false);
    let mp = programs::settlement_motion_program(map, &dead)?;
    let o = stage_options(opts);
    let mut basis = None;
    let primal = lp::solve_warm(&mp.lp, &o, &mut basis)?;
    if primal.status != LpStatus::Optimal {
        return Ok(None);
    }
    let raw = mp.motion(&primal.x);
    let weights = tributary_weights(st, map);
    settlement_selection(map, &mp, &primal, &raw, basis, &weights, &o, opts, copts)
}

/// The canonical collapse mechanism alone (no force stage) among the optima of the limit
/// program of `st` on `map`, whose solver's solution is `sol` (a multiplier, λ ≥ 0 or not):
/// the kinematic program solved for the duals that fix the optimal face, then the mechanism
/// stages. `None` where `sol` has no multiplier, the kinematic program is not optimal or a stage did not solve.
/// The mechanism is in the normalisation of `sol.mechanism` (λ unchanged).
pub fn limit_mechanism<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    sol: &LimitSolution,
    opts: &SolverOptions,
    copts: &CanonicalOptions,
) -> Result<Option<(Vec<f64>, CanonicalMechanism)>> {
    // A multiplier and its mechanism: a collapse, or a negative λ (no equilibrium under the
    // dead loads alone, as a capacity curve's steps past its zero report it).
    if sol.lambda.is_none() || sol.mechanism.is_empty() {
        return Ok(None);
    }
    let (dead, live) = (st.load_vector(false), st.load_vector(true));
    let fp = programs::limit_force_program(map, &dead, &live);
    let kp = programs::kinematic_program(&fp)?;
    // The kinematic program (its maximisation's optimum is −λ; `y = −d`), solved for the
    // duals that fix its optimal face.
    let o = stage_options(opts);
    // From the static program's optimal basis where its solve left one: the complementary
    // basis is optimal for the kinematic program, so the primal simplex ends at once (the
    // 0.25 m façade in running bond's `tilt`: the kinematic program from scratch by the
    // interior point took 73 s of wall clock after the static one's 85 s; docs/performance.md
    // "The kinematic program from the static program's basis (session 29)"). Where that start
    // does not end optimal, from scratch with the method as before.
    let mut basis = sol
        .basis
        .as_ref()
        .and_then(|b| crate::duality::dual_basis(&fp.lp, b));
    let warm = basis.is_some().then(|| {
        let wo = SolverOptions {
            method: Method::PrimalSimplex,
            ..o
        };
        lp::solve_warm(&kp.lp, &wo, &mut basis)
    });
    let first = match warm {
        Some(Ok(s)) if s.status == LpStatus::Optimal && s.tried.is_empty() => s,
        _ => {
            basis = None;
            lp::solve_warm(&kp.lp, &o, &mut basis)?
        }
    };
    if std::env::var_os("VOUSSOIR_TRACE").is_some() {
        eprintln!(
            "trace: limit mechanism: the kinematic program by {:?}, {} iterations",
            first.method, first.iterations
        );
    }
    if first.status != LpStatus::Optimal {
        return Ok(None);
    }
    let weights = tributary_weights(st, map);
    // A limit mechanism's openings are N d: support motions do not enter.
    let mut kmap = map.clone();
    kmap.support_normal.iter_mut().for_each(|g| *g = 0.0);
    let found = canonical_mechanism(
        &kmap,
        &kp.lp,
        &first,
        &sol.mechanism,
        basis,
        &weights,
        &o,
        copts,
    )?;
    if found.is_some() || !first.method.is_interior() {
        return Ok(found);
    }
    // As for a settlement ([`settlement_selection`]): an interior point's duals that did not
    // fix the optimal face; cross over to a vertex with the dual simplex and select from there
    // (the README's dome tilted, with Clarabel).
    let vo = SolverOptions {
        method: Method::DualSimplex,
        ..*opts
    };
    let mut vbasis = None;
    let vertex = lp::solve_warm(&kp.lp, &vo, &mut vbasis)?;
    if vertex.status != LpStatus::Optimal {
        return Ok(None);
    }
    canonical_mechanism(
        &kmap,
        &kp.lp,
        &vertex,
        &sol.mechanism,
        vbasis,
        &weights,
        &vo,
        copts,
    )
}

/// The work of a settlement force field on the support motions, with the closing gaps' term of
/// the force program's objective (`programs::settlement_force_program`: a point with a gap `Δ`
/// on a joint of infinite strength costs `Δ` per unit normal force).
fn settlement_dual(map: &KinematicMap, pn: &[f64], pt: &[f64]) -> f64 {
    let gaps: f64 = (0..map.num_points())
        .filter(|&k| {
            map.gap[k] > 0.0
                && !map.bilateral[k]
                && map.laws[map.points[k].joint].strength.is_none()
        })
        .map(|k| map.gap[k] * pn[k])
        .sum();
    dot(&map.support_normal, pn) + dot(&map.support_tangent, pt) + gaps
}

/// Limit analysis with the canonical collapse mechanism and forces (`docs/canonical.md`).
/// `facets` as in [`limit::limit_with`] with the linear crushing model.
pub fn limit_canonical<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    facets: usize,
    copts: &CanonicalOptions,
) -> Result<LimitResult<S::D>> {
    if !(limit::MIN_FACETS..=limit::MAX_FACETS).contains(&facets) {
        return limit::limit_with(st, opts, limit::Crushing::Linear, facets);
    }
    let mut map = KinematicMap::new(st);
    map.facets = facets;
    let mut s: LimitSolution = limit::solve_limit_checked(st, &map, opts)?;
    if s.status != LimitStatus::Collapse || s.mechanism.is_empty() {
        return Ok(limit::limit_result(st, &map, &s));
    }
    let (dead, live) = (st.load_vector(false), st.load_vector(true));
    let lambda = s.lambda.unwrap_or(0.0);
    let o = stage_options(opts);
    let weights = tributary_weights(st, &map);
    let Some((d, mech)) = limit_mechanism(st, &map, &s, opts, copts)? else {
        return Ok(limit::limit_result(st, &map, &s));
    };
    if mech.changed {
        s.mechanism = d;
    }
    let mut forces = None;
    if copts.forces {
        let open = open_points(&map, &s.mechanism, 0.0);
        let build = |m: &KinematicMap| programs::limit_force_program(m, &dead, &live);
        // A field's certificate: the λ its work on the mechanism gives (equilibrium
        // `F_D + λ F_L + Nᵀp_n + Tᵀp_t = 0` along d), against λ, as the limit certificate
        // measures it (for the plain laws it covers; other laws: not checked).
        let plain = map.shear_limits.is_none()
            && map
                .laws
                .iter()
                .all(|l| l.cohesion == 0.0 && l.strength.is_none());
        let mech = &s.mechanism;
        let (wd, wl) = (dot(&dead, mech), dot(&live, mech));
        let unit = crate::scale::lambda_unit(map.dofs_per_block, &dead, &live);
        let certify = |pn: &[f64], pt: &[f64]| {
            if !plain || wl.abs() < 1e-300 {
                return 0.0;
            }
            let res = map.resultants(pn, pt);
            crate::scale::relative_gap(lambda, -(wd + dot(&res, mech)) / wl, unit)
        };
        if let Some((pn, pt, f)) = canonical_forces(
            st, &map, build, lambda, &open, &weights, &o, copts, &certify,
        )? {
            s.pn = pn;
            s.pt = pt;
            forces = Some(f);
        }
    }
    let mut r = limit::limit_result(st, &map, &s);
    r.canonical = Some(Canonical {
        mechanism: mech,
        forces,
    });
    Ok(r)
}

impl StepSelection {
    /// The canonical collapse mechanism of step `step` among its optimal mechanisms
    /// ([`limit_mechanism`]; λ unchanged), counted in the record: `Some` with the selected
    /// mechanism where it differs from the solver's, `None` where the solver's stands (the same
    /// mechanism, a step without a multiplier or mechanism, or the selection not reached: then
    /// the step is listed in `steps_not_reached`).
    pub fn select<S: Assembly>(
        &mut self,
        st: &S,
        map: &KinematicMap,
        sol: &LimitSolution,
        opts: &SolverOptions,
        copts: &CanonicalOptions,
        step: usize,
    ) -> Result<Option<Vec<f64>>> {
        if sol.lambda.is_none() || sol.mechanism.is_empty() {
            return Ok(None);
        }
        let _kind = lp::ProgramKind::set(
            "canonical selection",
            "the mechanism stages: least crack area among the optimal mechanisms, then the generic tie-break",
        );
        Ok(match limit_mechanism(st, map, sol, opts, copts)? {
            Some((d, m)) => {
                self.steps_selected += 1;
                self.solves += m.solves;
                if m.changed {
                    self.steps_changed += 1;
                    Some(d)
                } else {
                    None
                }
            }
            None => {
                self.steps_not_reached.push(step);
                None
            }
        })
    }
}
