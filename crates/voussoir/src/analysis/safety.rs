//! Does the structure stand, and with what margin (Heyman's safe theorem).
//!
//! * **Stands**: an equilibrium state exists under the dead loads alone — contact forces with
//!   `F_D + Nᵀp_n + Tᵀp_t = 0`, `p_n ≥ 0` and the joint laws
//!   ([`programs::equilibrium_program`], a feasibility LP). This is the question `limit` answers
//!   only with live loads (0 in `[λ_min, λ_max]`, [`crate::analysis::limit`]'s least-multiplier
//!   check) and `settle` answers by an unbounded mechanism program (status `cannot_stand`); the
//!   three agree (tested).
//! * **Geometric safety factor** (Heyman 1969): every joint shrunk about its centre — each
//!   collocation point `x` moved to `c + f·(x − c)`, `c` the mean of the joint's points (the
//!   joint's midpoint in 2D, the centre of its vertices in 3D) — to the least fraction `f_min`
//!   at which an equilibrium state still exists (bisection on the feasibility LP; feasibility
//!   only grows with `f`, since a force at a shrunk point is a convex combination of forces at
//!   wider ones). Loads stay those of the structure as given. The factor is
//!   `thickness / least thickness = 1 / f_min`: 2 means that the thrust can be kept within the
//!   middle half of every joint, 3 within the middle third. With finite compressive strength a
//!   shrunk joint is a thinner joint of the same material (its depth scales by `f`).
//! * **Reaction ranges**: for every support and force component, the least and the largest
//!   value over the statically admissible states ([`programs::reaction_extreme_program`]); for
//!   an arch on two supports, the least and the largest horizontal thrust — the two extreme
//!   states that a spreading and a closing settlement select ([`crate::analysis::settlement`]).
//! * **Least thickness** of a generated structure: bisection on the generator's thickness
//!   ([`least_thickness`], any generator as a closure).

use crate::dim::Dim;
use crate::discretize::{ContactJoint, KinematicMap};
use crate::error::{Error, Result};
use crate::lp::{self, BasisStatus, Direction, LpSolution, LpStatus, SolverOptions};
use crate::programs;
pub use crate::result::safety::*;
use crate::structure::{Assembly, Body};

/// Options of the safety assessment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SafetyOptions {
    /// Absolute tolerance of the bisection on the joint fraction (default 1e-6).
    pub tolerance: f64,
    /// Compute the ranges of the support reactions (2·N LPs per support, N = 2 in 2D, 3 in 3D).
    pub reactions: bool,
    pub solver: SolverOptions,
    /// The solver of the bisection's decisions where it is not `solver` (the solver policy's
    /// [`lp::policy::decision_method`]); `None`: `solver`, which also solves the ranges.
    pub decisions: Option<SolverOptions>,
}

impl Default for SafetyOptions {
    fn default() -> Self {
        SafetyOptions {
            tolerance: 1e-6,
            reactions: true,
            solver: SolverOptions::default(),
            decisions: None,
        }
    }
}

/// Whether an LP status says "feasible"; an unbounded zero-objective program cannot occur.
fn feasible(status: LpStatus) -> bool {
    status != LpStatus::Infeasible
}

/// Whether `st` can carry its dead loads: the equilibrium program is feasible.
pub fn stands<S: Assembly>(st: &S, solver: &SolverOptions) -> Result<bool> {
    stands_on(&KinematicMap::new(st), &st.load_vector(false), solver)
}

fn stands_on(map: &KinematicMap, dead: &[f64], solver: &SolverOptions) -> Result<bool> {
    let fp = programs::equilibrium_program(map, dead);
    let sol = fp.solve(solver)?;
    // An exact decision: an interior point's "feasible" is checked on the program itself, and
    // where its point violates a row by more than round-off (it did by 5e-4 on a stack at
    // scale ×0.003, so that the bisection drifted) the dual simplex decides, with a vertex or
    // a certificate of infeasibility.
    if feasible(sol.status)
        && !sol.method.is_simplex()
        && lp::sequence::point_violation(&fp.lp, &sol.x) > DECISION_TOLERANCE
    {
        let o = SolverOptions {
            method: lp::Method::DualSimplex,
            ..*solver
        };
        let _kind = lp::ProgramKind::set("bisection", LAST_RESORT);
        return Ok(feasible(fp.solve(&o)?.status));
    }
    Ok(feasible(sol.status))
}

/// The simplex iterations a warm run of a sequence may take before the program is solved
/// otherwise: as many as the program has rows (at least 1,000). On the 24 × 24 dome (3,318
/// rows) the warm runs that answered took 1,000–2,700 iterations; one ran for minutes.
fn warm_limit(lp: &lp::LinearProgram) -> usize {
    lp.num_rows().max(1000)
}

/// The simplex iterations a warm run of a bisection may take before the decision goes to the
/// elastic program ([`Decisions::stands`]): an eighth of the program's rows, at least 500. A
/// warm run pays only while it is shorter than the elastic program by Clarabel: on the
/// 24 × 24 dome (3,318 rows) the warm dual simplex took 1,770–1,895 iterations (3.5–4.2 s)
/// where Clarabel decides in 1 s, about 400 iterations' time.
fn decision_warm_limit(lp: &lp::LinearProgram) -> usize {
    (lp.num_rows() / 8).max(500)
}

/// The fraction below which a bisection that has found only "stands" asks about f = 0
/// ([`bisect_fraction`]): after 1, 1/2, 1/4, 1/8 and 1/16 stood. Below it lies a geometric
/// safety factor above 16, which few structures have but those that stand on the centres of
/// their joints (an unbounded factor: the façades of docs/performance.md).
const EARLY_ZERO: f64 = 1.0 / 16.0;

/// The fraction at which a bisection that has found only "stands" first asks Clarabel whether
/// the structure stands at f = 0 ([`stands_at_zero_directly`]: "stands" by a point that holds
/// the merged program, never "does not stand"): after 1 and 1/2 stood, a factor above 2. Where
/// it stands the answer is 0 without the decisions at 1/4, 1/8 and 1/16 (on the 0.5 m grid
/// façade 7.7 CPU s of 14.6, session 21); where Clarabel does not say so the bisection goes on
/// as before, and at [`EARLY_ZERO`] the other decisions of [`stands_at_zero`] follow (Clarabel
/// is not asked twice). A structure with a factor below 2 (an arch, a dome) never gets here.
/// In 3D only: a 2D structure asks at [`FIRST_ZERO_2D`].
const FIRST_ZERO: f64 = 0.5;

/// [`FIRST_ZERO`] of a 2D structure: Clarabel is asked about f = 0 as soon as f = 1 stands, before
/// the decision at 1/2. On the 0.5 m grid façade, which stands at 0, that decision (the warm
/// dual simplex, 628 iterations, 2.1 s) is not needed: 30.6–32.3 → 28.3–31.3 CPU s, the same
/// answer in 90 programs instead of 91. A 2D structure with a bounded factor pays one Clarabel
/// run on its merged program, which does not decide (it never says "does not stand"): 0.04 s on
/// the paper's arch. In 3D that run is dearer and domes rarely stand at 0 (the 24 × 24 dome:
/// 21.3 → 22.8 CPU s with it, measured), so 3D keeps [`FIRST_ZERO`] (docs/performance.md, "Grid
/// façade safety and capacity (session 29)").
const FIRST_ZERO_2D: f64 = 1.0;

/// Largest relative violation of an equilibrium state that still counts as one (round-off).
const DECISION_TOLERANCE: f64 = 1e-9;

/// With the environment variable `VOUSSOIR_TRACE` set: one line per program on stderr (what,
/// how it was answered, the time since `t0`).
fn trace(what: std::fmt::Arguments, t0: std::time::Instant) {
    if std::env::var_os("VOUSSOIR_TRACE").is_some() {
        eprintln!("trace: safety {what} {:.3} s", t0.elapsed().as_secs_f64());
    }
}

/// Why the kinds of program that go to methods of their own do so, as the result states it
/// ([`lp::ProgramKind`]; docs/safety.md).
const ELASTIC_DESIGN: &str = "interior points without crossover decide them, Clarabel first; HiGHS's simplex stalled for minutes on them";
const LAST_RESORT: &str = "the dual simplex from scratch decides what no other answer did";
const RAYS: &str = "rays of unbounded reactions";
const RAYS_DESIGN: &str =
    "Clarabel first on the recession programs: a ray need not be a vertex, and it was faster";
const LOCAL_RAYS: &str = "rays of unbounded reactions on the blocks around the support";
const LOCAL_RAYS_DESIGN: &str = "the dual simplex on a small recession program: a few blocks' rows, each ray certified on the whole program";
const SCRATCH_DESIGN: &str = "an end that the warm runs did not certify goes to interior points certified by their duals, Clarabel first";

/// The methods that solve a reaction range's end from scratch, in order: interior points
/// (certified by their duals, no vertex needed), Clarabel's and HiGHS's without crossover;
/// then the dual simplex ([`end_from_scratch`]).
const SCRATCH_METHODS: [lp::Method; 3] = [
    lp::Method::Clarabel,
    lp::Method::IpmNoCrossover,
    lp::Method::DualSimplex,
];

/// Whether each method of [`end_from_scratch`] goes alone or with its fallback chain.
#[derive(Clone, Copy)]
enum Chain {
    /// [`lp::solve_without_fallback`].
    Alone,
    /// [`lp::solve`].
    WithFallback,
}

/// Whether `sol` is an optimum of `program` certified by its duals.
fn certified(program: &lp::LinearProgram, sol: &LpSolution) -> bool {
    sol.status == LpStatus::Optimal && lp::sequence::certify(program, sol).is_some_and(|c| c.ok())
}

/// A reaction range's end from scratch: `program` by each of `methods` in turn until one
/// answer is certified. That answer, or else the last one (`None` for no method); `solves`
/// counts the programs; `(side, when, t0)` names them in the trace.
fn end_from_scratch(
    program: &lp::LinearProgram,
    solver: &SolverOptions,
    methods: &[lp::Method],
    chain: Chain,
    solves: &mut usize,
    (side, when, t0): (&str, &str, std::time::Instant),
) -> Option<Result<LpSolution>> {
    let _kind = lp::ProgramKind::set("reaction ranges from scratch", SCRATCH_DESIGN);
    let mut last = None;
    for &method in methods {
        *solves += 1;
        let o = SolverOptions { method, ..*solver };
        let got = match chain {
            Chain::Alone => lp::solve_without_fallback(program, &o),
            Chain::WithFallback => lp::solve(program, &o),
        };
        trace(
            format_args!(
                "range {side}: from scratch by {}{when}: {:?}",
                method.name(),
                got.as_ref().map(|g| (g.status, certified(program, g)))
            ),
            t0,
        );
        let done = got.as_ref().is_ok_and(|g| certified(program, g));
        last = Some(got);
        if done {
            break;
        }
    }
    last
}

/// The joints of `st` with every point moved towards its joint's centre: `x → c + f·(x − c)`,
/// `c` the mean of the joint's points. In 2D the lever arms of the crushing domain and the
/// joint's depth scale by `f` too.
pub fn shrunk_joints<S: Assembly>(st: &S, f: f64) -> Vec<ContactJoint<S::D>> {
    let mut joints = st.contact_joints();
    for j in &mut joints {
        let Some(&(first, _)) = j.points.first() else {
            continue;
        };
        let n = j.points.len() as f64;
        let mut c = <S::D as Dim>::sub(first, first);
        for (x, _) in &j.points {
            for (ci, xi) in c.as_mut().iter_mut().zip(x.as_ref()) {
                *ci += xi / n;
            }
        }
        for (x, _) in j.points.iter_mut() {
            for (xi, ci) in x.as_mut().iter_mut().zip(c.as_ref()) {
                *xi = ci + f * (*xi - ci);
            }
        }
        for a in j.along.iter_mut() {
            *a *= f;
        }
        j.law.depth *= f;
    }
    joints
}

/// The kinematic map of `st` with its joints shrunk by `f` ([`shrunk_joints`]); every other
/// setting of the structure's own map (facets, gaps, …) is kept.
pub fn shrunk_map<S: Assembly>(st: &S, base: &KinematicMap, f: f64) -> KinematicMap {
    let s = KinematicMap::assemble(&st.contact_bodies(), &shrunk_joints(st, f));
    let mut m = base.clone();
    m.normal = s.normal;
    m.tangent = s.tangent;
    m.support_normal = s.support_normal;
    m.support_tangent = s.support_tangent;
    m.along = s.along;
    m.laws = s.laws;
    m
}

/// The decisions of a bisection as one sequence ([`lp::sequence`]): each equilibrium program
/// has the shape of the one before (the same points, moved), so it starts from the basis the
/// previous one ended with — dual feasible, as every basis of a program with a zero objective
/// is, so HiGHS's dual simplex goes on from it. The first program is solved with the requested
/// method. Each decision is exact as in [`stands`]: a feasible point is checked on the program
/// itself, and one that violates it beyond round-off is decided again by the dual simplex from
/// scratch.
pub struct Decisions {
    solver: SolverOptions,
    sequence: Option<lp::sequence::Sequence>,
    /// LP solves, and of those the ones started from the previous basis.
    pub solves: usize,
    pub warm: usize,
    /// Decisions taken again by the dual simplex from scratch (their first answer could not
    /// be checked: [`Decisions::stands`]).
    pub redecided: usize,
    /// A warm run has failed: later decisions go to the elastic program directly.
    warm_failed: bool,
    /// The least total violation of the last decision where the elastic program decided
    /// "does not stand" (`None` where another method decided, or it stood): what
    /// [`bisect_fraction`]'s secant steps read.
    pub last_violation: Option<f64>,
}

impl Decisions {
    pub fn new(solver: &SolverOptions) -> Decisions {
        Decisions {
            solver: *solver,
            sequence: None,
            solves: 0,
            warm: 0,
            redecided: 0,
            warm_failed: false,
            last_violation: None,
        }
    }

    /// Whether an equilibrium state exists for the structure of kinematic map `map` under the
    /// dead loads `dead` ([`programs::equilibrium_program`]).
    pub fn stands(&mut self, map: &KinematicMap, dead: &[f64]) -> Result<bool> {
        let fp = programs::equilibrium_program(map, dead);
        if !fp.cones.is_empty() {
            self.solves += 1;
            return stands_on(map, dead, &self.solver);
        }
        self.stands_lp(fp.lp)
    }

    /// [`Decisions::stands`] of an equilibrium program without cones.
    fn stands_lp(&mut self, program: lp::LinearProgram) -> Result<bool> {
        self.solves += 1;
        self.last_violation = None;
        // The warm run (the first program: the requested method), until one fails: then
        // every later decision goes to the elastic program directly (on the 24 × 24 dome the
        // warm dual simplex reached its iteration limit on 15 of 17 later decisions).
        let sol = if self.warm_failed {
            None
        } else {
            let seq = match &mut self.sequence {
                Some(seq) => {
                    seq.replace(program.clone())?;
                    seq
                }
                None => {
                    let mut seq = lp::sequence::Sequence::new(program.clone(), &self.solver)?;
                    seq.limit_warm_iterations(Some(decision_warm_limit(&program)));
                    self.sequence.insert(seq)
                }
            };
            let before = seq.stats.warm;
            let t0 = std::time::Instant::now();
            let sol = seq.try_solve();
            self.warm += seq.stats.warm - before;
            trace(
                format_args!(
                    "decision {} ({} rows, {} columns): {:?} by {:?} ({} warm, {:?} iterations)",
                    self.solves,
                    program.num_rows(),
                    program.num_cols(),
                    sol.as_ref().map(|s| s.status),
                    sol.as_ref().map(|s| s.method.name()),
                    seq.stats.warm - before,
                    sol.as_ref().map(|s| s.iterations)
                ),
                t0,
            );
            if sol.is_none() && self.solves > 1 {
                self.warm_failed = true;
            }
            sol
        };
        // Each decision exact, either way: "stands" with an equilibrium state checked on the
        // program itself (largest relative violation ≤ DECISION_TOLERANCE, whatever the
        // method); "does not stand" as the dual simplex says it (its proof of infeasibility is
        // a dual ray). A decision that is neither — a point that violates the program, or
        // "infeasible" from another method (an interior point, the primal simplex) — is
        // decided again by the elastic program (`lp::sequence::decide_feasibility`: the least
        // total violation, certified by its duals, a Farkas certificate where it is positive).
        if let Some(sol) = &sol {
            let checked = match sol.status {
                LpStatus::Infeasible => sol.method == lp::Method::DualSimplex,
                _ => {
                    let v = lp::sequence::point_violation(&program, &sol.x);
                    trace(
                        format_args!("decision {}: violation {v:.1e}", self.solves),
                        std::time::Instant::now(),
                    );
                    v <= DECISION_TOLERANCE
                }
            };
            if checked {
                return Ok(feasible(sol.status));
            }
        }
        // The elastic program decides, with a certificate either way; where even that does
        // not certify, the dual simplex from scratch.
        self.solves += 1;
        self.redecided += 1;
        // Interior points without crossover, each alone (no fallback chain) and certified by
        // its duals: Clarabel's (2 s on the 24 × 24 dome's elastic programs), then HiGHS's
        // (9 s). Crossover and HiGHS's simplex stalled for minutes on them (phase 1).
        let kind = lp::ProgramKind::set("elastic decisions", ELASTIC_DESIGN);
        // Where Clarabel's elastic program leaves the decision open (on the 24 × 24 dome two
        // feasible programs just above the least fraction: least violation between 1e-7 and
        // 1e-6, the interior point's resolution; HiGHS's interior point took 5 s each), Clarabel
        // on the equilibrium program itself decides "stands" where its point holds the
        // program to DECISION_TOLERANCE (`lp::sequence::decide_directly`: 0.3–0.5 s, never
        // "does not stand"); then HiGHS's interior point on the elastic program.
        for (step, method) in [
            lp::Method::Clarabel,
            lp::Method::Clarabel,
            lp::Method::IpmNoCrossover,
        ]
        .into_iter()
        .enumerate()
        {
            let o = SolverOptions {
                method,
                ..self.solver
            };
            let t0 = std::time::Instant::now();
            let d = if step == 1 {
                lp::sequence::decide_directly(&program, &o, DECISION_TOLERANCE)?
            } else {
                lp::sequence::decide_feasibility(&program, &o, DECISION_TOLERANCE)?
            };
            trace(
                format_args!(
                    "decision {}: {} by {}: {:?}",
                    self.solves,
                    if step == 1 {
                        "the program itself"
                    } else {
                        "elastic program"
                    },
                    method.name(),
                    d.as_ref().map(|d| (d.feasible, d.violation))
                ),
                t0,
            );
            if let Some(d) = d {
                if !d.feasible && step != 1 {
                    self.last_violation = Some(d.violation);
                }
                return Ok(d.feasible);
            }
        }
        drop(kind);
        let _kind = lp::ProgramKind::set("bisection", LAST_RESORT);
        self.solves += 1;
        let o = SolverOptions {
            method: lp::Method::DualSimplex,
            ..self.solver
        };
        Ok(feasible(lp::solve(&program, &o)?.status))
    }
}

/// The least joint fraction `f` in `[0, 1]` at which `st` stands, to `tolerance` (the upper
/// end of the final bracket), and the LP solves spent; `None` if it does not stand at `f = 1`.
/// The decisions are one warm-started sequence ([`Decisions`]).
pub fn least_joint_fraction<S: Assembly>(
    st: &S,
    tolerance: f64,
    solver: &SolverOptions,
) -> Result<(Option<f64>, usize)> {
    let (f, solves, _) = bisect_fraction(st, tolerance, solver)?;
    Ok((f, solves))
}

/// How [`least_joint_fraction_by`] searches the joint fraction (for tests).
#[doc(hidden)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FractionSearch {
    /// Secant steps on the elastic program's least violation ([`bisect_fraction`]); `false`:
    /// plain bisection.
    pub secant: bool,
    /// Every decision after the first by the elastic program (as where a warm run has
    /// failed), so that each "does not stand" carries its least violation.
    pub elastic: bool,
}

/// [`least_joint_fraction`] with the search chosen (for tests: the secant steps against plain
/// bisection, on small structures whose decisions the warm dual simplex would otherwise take).
#[doc(hidden)]
pub fn least_joint_fraction_by<S: Assembly>(
    st: &S,
    tolerance: f64,
    solver: &SolverOptions,
    search: FractionSearch,
) -> Result<(Option<f64>, usize)> {
    let (f, solves, _) = search_fraction(st, tolerance, solver, search)?;
    Ok((f, solves))
}

/// The bisection's grid: `2⁻ᴹ`, the width of its final bracket (`M` the least with
/// `2⁻ᴹ ≤ tolerance`). Every fraction the bisection asks about is a multiple of it.
fn fraction_grid(tolerance: f64) -> f64 {
    let mut g = 1.0;
    while g > tolerance {
        g *= 0.5;
    }
    g
}

/// The next fraction to ask about by a secant step, or `None` (then the bisection's midpoint):
/// the zero of the line through the two largest fractions at which the structure did not
/// stand, by their elastic programs' least violations `below` (`lo` the larger; the violation
/// must fall from the first to the second), rounded up to the bisection's `grid` and kept one
/// grid step inside `(lo, hi)`.
fn secant_fraction(below: &[(f64, f64)], lo: f64, hi: f64, grid: f64) -> Option<f64> {
    let [.., (f1, v1), (f2, v2)] = below else {
        return None;
    };
    // Finite, increasing fractions with falling, positive violations (NaN fails each test).
    let usable = *f2 == lo && f1 < f2 && *v2 > 0.0 && v1 > v2;
    if !usable {
        return None;
    }
    let g = f2 + v2 * (f2 - f1) / (v1 - v2);
    // A zero at or beyond the upper end says nothing the bracket does not (on the 24 × 24
    // dome such a step, kept one grid step inside, stood and shrank the bracket by 1e-6).
    if !(g.is_finite() && g < hi) {
        return None;
    }
    if lo + grid > hi - grid {
        return None;
    }
    let t = ((g / grid).ceil() * grid).clamp(lo + grid, hi - grid);
    (t > lo && t < hi).then_some(t)
}

/// [`least_joint_fraction`], and the basis of its first program (the structure as given, a
/// feasible vertex where it stands and the method leaves one), which starts the reaction
/// ranges' sequence: the same constraints, another objective.
fn bisect_fraction<S: Assembly>(
    st: &S,
    tolerance: f64,
    solver: &SolverOptions,
) -> Result<(Option<f64>, usize, Option<lp::Basis>)> {
    search_fraction(
        st,
        tolerance,
        solver,
        FractionSearch {
            secant: true,
            elastic: false,
        },
    )
}

/// [`bisect_fraction`] with the search chosen ([`FractionSearch`]).
///
/// Secant steps: once the structure has failed to stand at two fractions decided by the
/// elastic program, the next fraction asked about is where the line through their least
/// violations reaches zero (the violation falls to 0 at the least fraction, and near it
/// linearly: on the 24 × 24 dome 3.6e-3, 1.4e-3 and 2.4e-4 at 6.1e-5 apart), rounded up to the
/// bisection's grid (`2⁻ᴹ`, the width of its final bracket). Every fraction asked about is a
/// grid point, and the search ends as the bisection does, with a bracket of one grid step
/// whose lower end does not stand and whose upper end does: with feasibility growing with
/// `f`, the same bracket and the same answer (the least grid point at which it stands), in
/// fewer decisions. A secant step that stands is followed by the grid point below it (a
/// probe: where the secant's zero is within a grid step of the least fraction, that ends the
/// search); a secant step that does not halve the bracket, or a probe that stands, by a
/// bisection step (so at most three decisions per halving); where a decision carries no
/// violation (the warm dual simplex's "infeasible"), the bisection's midpoint.
fn search_fraction<S: Assembly>(
    st: &S,
    tolerance: f64,
    solver: &SolverOptions,
    search: FractionSearch,
) -> Result<(Option<f64>, usize, Option<lp::Basis>)> {
    if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
        return Err(Error::Request(format!(
            "tolerance {tolerance}: the bisection on the joint fraction needs 0 < tolerance < 1"
        )));
    }
    let base = KinematicMap::new(st);
    let dead = st.load_vector(false);
    let mut d = Decisions::new(solver);
    if !d.stands(&base, &dead)? {
        return Ok((None, d.solves, None));
    }
    let start = d.sequence.as_ref().and_then(|s| s.basis().cloned());
    if search.elastic {
        d.warm_failed = true;
    }
    let grid = fraction_grid(tolerance);
    // The fractions at which it did not stand with their least violations (secant steps).
    let mut below: Vec<(f64, f64)> = Vec::new();
    // Whether the last secant step halved the bracket (else the next step bisects).
    let mut secant_ok = true;
    // After a secant step that stood: the grid point below it, asked next (the zero of a
    // secant near the least fraction lies within a grid step of it).
    let mut probe: Option<f64> = None;
    // f = 0 (every joint a point at its centre) is decided only where the bisection needs it:
    // feasibility only grows with f, so one fraction at which it does not stand proves that
    // it does not stand at 0. The program at f = 0 is the most degenerate of all (on the
    // 24 × 24 dome every method stalled or failed to certify it for minutes), and most
    // structures are decided at f = 1/2.
    let (mut lo, mut hi) = (0.0, 1.0);
    let mut fell = false;
    // Whether Clarabel has been asked about f = 0 on the merged program (FIRST_ZERO).
    let mut asked = false;
    let first_zero = if base.dofs_per_block == 3 {
        FIRST_ZERO_2D
    } else {
        FIRST_ZERO
    };
    while hi - lo > tolerance {
        if !fell && !asked && hi <= first_zero {
            asked = true;
            if stands_at_zero_directly(st, &base, &dead, &mut d)? {
                return Ok((Some(0.0), d.solves, start));
            }
        }
        // A structure that has stood at every fraction down to EARLY_ZERO is asked about
        // f = 0 there, once: where it stands at 0 the answer is 0 (as the bisection would end,
        // feasibility growing with f) without the 16 or so decisions below; where it does not,
        // the bisection goes on, knowing it (the same decisions and the same end). On the
        // 0.5 m grid façade the warm runs failed at f ≈ 2e-6 and the decisions after went to
        // the elastic program (minutes).
        if !fell && hi <= EARLY_ZERO && hi - lo > tolerance {
            if stands_at_zero(st, &base, &dead, &mut d, asked)? {
                return Ok((Some(0.0), d.solves, start));
            }
            fell = true;
        }
        let width = hi - lo;
        let probing = probe.take().filter(|&p| p > lo && p < hi);
        let step = if probing.is_some() {
            probing
        } else if search.secant && fell && secant_ok {
            secant_fraction(&below, lo, hi, grid)
        } else {
            None
        };
        // The midpoint on the grid (after a secant step the bracket need not be a node of the
        // bisection's tree; within one it is the bisection's midpoint, exactly).
        let mid = step.unwrap_or(((0.5 * (lo + hi)) / grid).floor() * grid);
        if d.stands(&shrunk_map(st, &base, mid), &dead)? {
            hi = mid;
            if step.is_some() && probing.is_none() {
                probe = Some(mid - grid);
            }
        } else {
            lo = mid;
            fell = true;
            if let Some(v) = d.last_violation {
                below.push((mid, v));
            }
        }
        if step.is_some() {
            trace(
                format_args!(
                    "{} to f = {mid} (bracket {width:.3e} -> {:.3e})",
                    if probing.is_some() {
                        "probe below a secant step"
                    } else {
                        "secant step"
                    },
                    hi - lo
                ),
                std::time::Instant::now(),
            );
        }
        // A probe that stood, or a secant step that did not halve the bracket: bisect next.
        secant_ok = step.is_none() || (probing.is_none() && hi - lo <= 0.5 * width);
    }
    if !fell && stands_at_zero(st, &base, &dead, &mut d, asked)? {
        return Ok((Some(0.0), d.solves, start));
    }
    Ok((Some(hi), d.solves, start))
}

/// Whether `st` stands with every joint shrunk to its centre (f = 0), decided on
/// [`merged_columns`] of its equilibrium program by decisions of their own (`d` counts the
/// solves): at f = 0 the points of a joint coincide, so their columns are equal, and the
/// program with one column of each kind per joint is feasible exactly when the program is (a
/// state of the merged program is one of the program with each joint's force on one point; a
/// state of the program sums to one of the merged). The program as written is the most
/// degenerate of the bisection: on the 0.5 m grid façade the warm dual simplex, Clarabel and
/// HiGHS's interior point on its elastic program each failed or took minutes on it.
///
/// `asked`: [`stands_at_zero_directly`] has been asked already (and did not say "stands").
fn stands_at_zero<S: Assembly>(
    st: &S,
    base: &KinematicMap,
    dead: &[f64],
    d: &mut Decisions,
    asked: bool,
) -> Result<bool> {
    let fp = programs::equilibrium_program(&shrunk_map(st, base, 0.0), dead);
    if !fp.cones.is_empty() {
        return d.stands(&shrunk_map(st, base, 0.0), dead);
    }
    let merged = merged_columns(&fp.lp);
    if !asked && directly(&merged, d)? {
        return Ok(true);
    }
    let mut own = Decisions::new(&d.solver);
    let stands = own.stands_lp(merged)?;
    d.solves += own.solves;
    d.redecided += own.redecided;
    d.warm += own.warm;
    Ok(stands)
}

/// Whether Clarabel on [`merged_columns`] of the equilibrium program at f = 0 finds a point
/// that holds it ("stands", certified by that point; `false` where it does not: nothing is
/// decided then). A program with cones is not asked (`false`).
fn stands_at_zero_directly<S: Assembly>(
    st: &S,
    base: &KinematicMap,
    dead: &[f64],
    d: &mut Decisions,
) -> Result<bool> {
    let fp = programs::equilibrium_program(&shrunk_map(st, base, 0.0), dead);
    if !fp.cones.is_empty() {
        return Ok(false);
    }
    directly(&merged_columns(&fp.lp), d)
}

/// Clarabel on the merged program at f = 0 (`merged`) itself: "stands" where its point holds
/// the program to [`DECISION_TOLERANCE`] ([`lp::sequence::decide_directly`]); `false` decides
/// nothing.
fn directly(merged: &lp::LinearProgram, d: &mut Decisions) -> Result<bool> {
    trace(
        format_args!("f = 0: merged program of {} columns", merged.num_cols()),
        std::time::Instant::now(),
    );
    // Clarabel on the merged program itself first: its point, held to DECISION_TOLERANCE,
    // decides "stands" (`lp::sequence::decide_directly`; it never decides "does not stand").
    // On the 0.5 m grid façade the decisions below spent 14 s of wall clock before they came to
    // this answer (the interior point on the merged program uncertified, Clarabel's elastic
    // program undecided); it alone took 3 s.
    {
        let _kind = lp::ProgramKind::set("elastic decisions", ELASTIC_DESIGN);
        let o = SolverOptions {
            method: lp::Method::Clarabel,
            ..d.solver
        };
        let t0 = std::time::Instant::now();
        d.solves += 1;
        let direct = lp::sequence::decide_directly(merged, &o, DECISION_TOLERANCE)?;
        trace(
            format_args!(
                "f = 0: the merged program itself by clarabel: {:?}",
                direct.as_ref().map(|x| (x.feasible, x.violation))
            ),
            t0,
        );
        Ok(direct.is_some_and(|x| x.feasible))
    }
}

/// `lp` with every set of equal columns (bounds, cost and entries bit for bit) replaced by the
/// first of them. Where the equal columns' bounds are `[0, ∞)` or free, as the forces of an
/// equilibrium program are, the two programs are feasible together: a point of the merged
/// program is one of `lp` with the others at 0, and a point of `lp` sums to one of the merged.
/// Columns with other bounds are kept as they are.
pub fn merged_columns(lp: &lp::LinearProgram) -> lp::LinearProgram {
    use std::collections::HashMap;
    let key = |j: usize| -> Vec<u64> {
        let mut k = vec![
            lp.col_lower[j].to_bits(),
            lp.col_upper[j].to_bits(),
            lp.cost[j].to_bits(),
        ];
        for (i, v) in lp.column(j) {
            k.push(i as u64);
            k.push(v.to_bits());
        }
        k
    };
    let mut seen: HashMap<Vec<u64>, usize> = HashMap::new();
    let mut out = lp.rows_only();
    for j in 0..lp.num_cols() {
        let (lo, hi) = (lp.col_lower[j], lp.col_upper[j]);
        let cone = (lo == 0.0 || lo == f64::NEG_INFINITY) && hi == f64::INFINITY;
        if cone {
            let k = key(j);
            if seen.contains_key(&k) {
                continue;
            }
            seen.insert(k, j);
        }
        out.add_column(lp.cost[j], lo, hi, lp.column(j));
    }
    out
}

/// Coefficients of the force components of each support's reaction in the point forces:
/// `[support][component] → (c_n per point, c_t per point and tangent)`, so that the component
/// is `c_n·p_n + c_t·p_t` (the force of the support on the structure, as in
/// [`crate::result::reactions`]).
fn reaction_coefficients<S: Assembly>(
    st: &S,
    map: &KinematicMap,
) -> Vec<Vec<(Vec<f64>, Vec<f64>)>> {
    let (n, nt) = (<S::D as Dim>::N, <S::D as Dim>::TANGENTS);
    let joints = st.contact_joints();
    let mut out = vec![
        vec![
            (
                vec![0.0; map.num_points()],
                vec![0.0; map.num_tangent_rows()]
            );
            n
        ];
        st.num_supports()
    ];
    for (k, pr) in map.points.iter().enumerate() {
        let joint = &joints[pr.joint];
        // The force on b is p_n·n + p_t·t; a support that is `a` gives it to the structure,
        // one that is `b` receives it (the structure gets −f).
        for (body, sign) in [(joint.a, 1.0), (joint.b, -1.0)] {
            if let Body::Support(s) = body {
                for (c, comp) in out[s].iter_mut().enumerate() {
                    comp.0[k] += sign * joint.normal.as_ref()[c];
                    for (m, t) in joint.tangents.as_ref().iter().enumerate() {
                        comp.1[k * nt + m] += sign * t.as_ref()[c];
                    }
                }
            }
        }
    }
    out
}

/// Positions by cell (side 1e-6 of the structure's extent), to find those within `tol` of a
/// point: the images of blocks, supports and contact points under a symmetry ([`Mirror`] in
/// 2D, [`isometries_3d`] in 3D). Positions that are not finite (a support without a point) are
/// left out.
struct PositionIndex<'a, const N: usize> {
    pos: &'a [[f64; N]],
    q: f64,
    tol: f64,
    cells: std::collections::HashMap<[i64; N], Vec<usize>>,
}

impl<'a, const N: usize> PositionIndex<'a, N> {
    fn new(pos: &'a [[f64; N]], extent: f64) -> Self {
        let mut index = PositionIndex {
            pos,
            q: 1e-6 * extent,
            tol: 1e-9 * extent,
            cells: std::collections::HashMap::new(),
        };
        for (i, p) in pos.iter().enumerate() {
            if p.iter().all(|v| v.is_finite()) {
                index.cells.entry(index.key(p)).or_default().push(i);
            }
        }
        index
    }

    fn key(&self, p: &[f64; N]) -> [i64; N] {
        p.map(|v| (v / self.q).round() as i64)
    }

    /// The positions within `tol` of `p` in every coordinate (the 3^N cells around it).
    fn near(&self, p: [f64; N]) -> Vec<usize> {
        let k = self.key(&p);
        let mut out = Vec::new();
        for m in 0..3usize.pow(N as u32) {
            let mut cell = k;
            let mut r = m;
            for c in cell.iter_mut() {
                *c += (r % 3) as i64 - 1;
                r /= 3;
            }
            for &i in self.cells.get(&cell).into_iter().flatten() {
                if (0..N).all(|c| (self.pos[i][c] - p[c]).abs() <= self.tol) {
                    out.push(i);
                }
            }
        }
        out
    }
}

/// A mirror symmetry of a planar equilibrium program (the structure, its supports and its
/// dead loads symmetric about a vertical line): the columns, rows and supports it maps onto
/// each other, with the signs (a force's normal component keeps its sign, its shear may flip;
/// a block's horizontal force and moment flip, its vertical force does not). Found from the
/// geometry and kept only where the program itself is invariant under it, entry by entry, to
/// round-off ([`Mirror::of`]). An optimum of one reaction's side mapped by it is an optimum of
/// the mirrored support's side, and certified as any other on that program.
struct Mirror {
    /// Column `j` ↦ `(j', α)`: `x'_{j'} = α x_j`.
    col: Vec<(usize, f64)>,
    /// Row `i` ↦ `(i', s)`.
    row: Vec<(usize, f64)>,
    /// Support `s` ↦ its mirror.
    support: Vec<usize>,
}

impl Mirror {
    /// The mirror symmetry of `base` (the equilibrium program of `st` on `map`) about the
    /// vertical line through the middle of the blocks' reference points, if `st` is planar,
    /// every column is a point's normal or shear force and the program maps onto itself;
    /// otherwise what is not symmetric.
    fn of<S: Assembly>(
        st: &S,
        map: &KinematicMap,
        base: &programs::ForceProgram,
    ) -> std::result::Result<Mirror, &'static str> {
        if <S::D as Dim>::N != 2 || map.dofs_per_block != 3 || <S::D as Dim>::TANGENTS != 1 {
            return Err("not planar");
        }
        let lp = &base.lp;
        let bodies = st.contact_bodies();
        let nb = bodies.blocks.len();
        // The equilibrium rows, three per block, then the joint laws' rows (Coulomb's two
        // rows `±p_t − μ p_n ≤ c` per point), each mapped onto the row its entries map onto.
        let neq = 3 * nb;
        if nb == 0 || lp.num_rows() < neq {
            return Err("rows are not three per block");
        }
        let xy = |v: &<S::D as Dim>::Vector| (v.as_ref()[0], v.as_ref()[1]);
        let (mut lo, mut hi, mut ylo, mut yhi) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for b in &bodies.blocks {
            let (x, y) = xy(b);
            lo = lo.min(x);
            hi = hi.max(x);
            ylo = ylo.min(y);
            yhi = yhi.max(y);
        }
        let extent = (hi - lo).max(yhi - ylo);
        if !(extent.is_finite() && extent > 0.0) {
            return Err("blocks extent");
        }
        let xc = 0.5 * (lo + hi);
        let block_pos: Vec<[f64; 2]> = bodies
            .blocks
            .iter()
            .map(|b| {
                let (x, y) = xy(b);
                [x, y]
            })
            .collect();
        let block_index = PositionIndex::new(&block_pos, extent);
        let mut sigma = vec![usize::MAX; nb];
        for (i, &[x, y]) in block_pos.iter().enumerate() {
            match block_index.near([2.0 * xc - x, y])[..] {
                [j] => sigma[i] = j,
                _ => return Err("a block without its mirror image"),
            }
        }
        let joints = st.contact_joints();
        let point_pos: Vec<[f64; 2]> = map
            .points
            .iter()
            .map(|pr| {
                let (x, y) = xy(&joints[pr.joint].points[pr.index].0);
                [x, y]
            })
            .collect();
        let point_index = PositionIndex::new(&point_pos, extent);
        // Each support's image: the support whose points' mean is the mirror of its own (a
        // support without a point has no column and is its own image).
        let ns = st.num_supports();
        let mut mean = vec![(0.0, 0.0, 0usize); ns];
        for (k, &[x, y]) in point_pos.iter().enumerate() {
            let j = &joints[map.points[k].joint];
            for body in [j.a, j.b] {
                if let Body::Support(s) = body {
                    mean[s].0 += x;
                    mean[s].1 += y;
                    mean[s].2 += 1;
                }
            }
        }
        let support_pos: Vec<[f64; 2]> = mean
            .iter()
            .map(|&(x, y, n)| {
                if n > 0 {
                    [x / n as f64, y / n as f64]
                } else {
                    [f64::NAN, f64::NAN]
                }
            })
            .collect();
        let support_index = PositionIndex::new(&support_pos, extent);
        let mut support: Vec<usize> = (0..ns).collect();
        for (s, &[x, y]) in support_pos.iter().enumerate() {
            if x.is_finite() {
                match support_index.near([2.0 * xc - x, y])[..] {
                    [s2] => support[s] = s2,
                    _ => return Err("a support without its mirror image"),
                }
            }
        }
        let mut col = vec![(usize::MAX, 0.0); lp.num_cols()];
        // The load multiplier's column (a limit program): its own image, the sign from its
        // entries (the live load mirrored: −1 for a horizontal load, [`least_by_mirror`]).
        if let Some(l) = base.lambda {
            col[l] = (l, 0.0);
        }
        let mirrored_body = |b: Body| match b {
            Body::Block(i) => Body::Block(sigma[i]),
            Body::Support(s) => Body::Support(support[s]),
        };
        for (k, &[x, y]) in point_pos.iter().enumerate() {
            let j = &joints[map.points[k].joint];
            let mut image = None;
            for k2 in point_index.near([2.0 * xc - x, y]) {
                let j2 = &joints[map.points[k2].joint];
                // The same pair of bodies mirrored, in either order.
                let (a2, b2) = (mirrored_body(j.a), mirrored_body(j.b));
                if (j2.a, j2.b) == (a2, b2) || (j2.a, j2.b) == (b2, a2) {
                    if image.is_some() {
                        return Err("a point with two mirror images");
                    }
                    image = Some(k2);
                }
            }
            let Some(k2) = image else {
                return Err("a point without its mirror image");
            };
            for (c, c2) in [(base.pn[k], base.pn[k2]), (base.pt[k], base.pt[k2])] {
                match (c, c2) {
                    (Some(c), Some(c2)) => col[c] = (c2, 0.0),
                    (None, None) => {}
                    _ => return Err("a point and its image: force columns differ"),
                }
            }
        }
        let mut row: Vec<(usize, f64)> = (0..neq)
            .map(|i| (3 * sigma[i / 3] + i % 3, [-1.0, 1.0, -1.0][i % 3]))
            .collect();
        // The program invariant, entry by entry: each column's image is ± a column, with its
        // bounds and cost; each row's bounds those of its image.
        let mut entries: Vec<Vec<(usize, f64)>> = vec![Vec::new(); lp.num_cols()];
        for (j, e) in entries.iter_mut().enumerate() {
            *e = lp.column(j).collect();
            e.sort_by_key(|&(i, _)| i);
        }
        if lp.num_rows() > neq {
            row.extend(law_rows_image(lp, neq, &col, &row, &entries)?);
        }
        for j in 0..lp.num_cols() {
            let (j2, _) = col[j];
            if j2 == usize::MAX {
                return Err("a column without an image");
            }
            let mut image: Vec<(usize, f64)> = entries[j]
                .iter()
                .map(|&(i, v)| (row[i].0, row[i].1 * v))
                .collect();
            image.sort_by_key(|&(i, _)| i);
            let target = &entries[j2];
            let size = image.iter().fold(0.0f64, |m, &(_, v)| m.max(v.abs()));
            if size == 0.0 {
                return Err("a column without entries");
            }
            // The sign from the largest entry; then every entry of either list matched in the
            // other (a missing one counts as 0: round-off such as a moment of 1e-17 is stored
            // in one column and not in its image).
            let (ib, vb) = image.iter().copied().fold((0, 0.0f64), |m, (i, v)| {
                if v.abs() > m.1.abs() {
                    (i, v)
                } else {
                    m
                }
            });
            let Ok(tb) = target.binary_search_by_key(&ib, |&(i, _)| i) else {
                return Err("a column and its image: entries differ");
            };
            let alpha = if vb * target[tb].1 >= 0.0 { 1.0 } else { -1.0 };
            let (mut p, mut q) = (0, 0);
            while p < image.len() || q < target.len() {
                let (ip, vp) = image.get(p).copied().unwrap_or((usize::MAX, 0.0));
                let (iq, vq) = target.get(q).copied().unwrap_or((usize::MAX, 0.0));
                let (a, b) = if ip == iq {
                    p += 1;
                    q += 1;
                    (alpha * vp, vq)
                } else if ip < iq {
                    p += 1;
                    (alpha * vp, 0.0)
                } else {
                    q += 1;
                    (0.0, vq)
                };
                if (a - b).abs() > 1e-9 * size {
                    return Err("a column and its image: entries differ");
                }
            }
            let (l, u) = (lp.col_lower[j], lp.col_upper[j]);
            let (l, u) = if alpha > 0.0 { (l, u) } else { (-u, -l) };
            // The multiplier's cost is λ itself on both sides: a mirror that flips λ maps the
            // largest multiplier's optimum onto the least's ([`Symmetry::optimum`] flips the
            // sense where the image of the cost is minus the target's).
            let cost_differs = Some(j) != base.lambda && lp.cost[j] * alpha != lp.cost[j2];
            if l != lp.col_lower[j2] || u != lp.col_upper[j2] || cost_differs {
                return Err("a column and its image: bounds or cost differ");
            }
            col[j].1 = alpha;
        }
        let load = (0..lp.num_rows())
            .flat_map(|i| [lp.row_lower[i], lp.row_upper[i]])
            .filter(|v| v.is_finite())
            .fold(0.0f64, |m, v| m.max(v.abs()));
        for (i, &(i2, sg)) in row.iter().enumerate() {
            let (l, u) = (lp.row_lower[i], lp.row_upper[i]);
            let (l, u) = if sg > 0.0 { (l, u) } else { (-u, -l) };
            let close = |a: f64, b: f64| a == b || (a - b).abs() <= 1e-12 * load.max(1e-300);
            if !close(l, lp.row_lower[i2]) || !close(u, lp.row_upper[i2]) {
                return Err("a row and its image: loads differ");
            }
        }
        Ok(Mirror { col, row, support })
    }
}

/// The images of the rows of `lp` after its `neq` equilibrium rows (the joint laws' rows:
/// Coulomb's `±p_t − μ p_n ≤ c` in 2D), given the images of the columns (`col`, without their
/// signs yet) and of the equilibrium rows (`eq_rows`). A column's sign is read from its
/// largest entry in an equilibrium row (a point's normal and shear forces have one there);
/// each law row is then mapped onto the law row whose entries are its own mapped, times +1 or
/// −1 (so `p_t − μ p_n ≤ c` of a point whose shear flips goes onto `−p_t − μ p_n ≤ c` of its
/// image). Every law row must have exactly one image, and no two the same one; the whole
/// program, the rows' bounds included, is checked entry by entry afterwards ([`Mirror::of`]).
fn law_rows_image(
    lp: &lp::LinearProgram,
    neq: usize,
    col: &[(usize, f64)],
    eq_rows: &[(usize, f64)],
    entries: &[Vec<(usize, f64)>],
) -> std::result::Result<Vec<(usize, f64)>, &'static str> {
    let ncols = lp.num_cols();
    let nlaw = lp.num_rows() - neq;
    // Each column's sign under the mirror, from its largest equilibrium entry.
    let mut alpha = vec![0.0; ncols];
    for j in 0..ncols {
        let Some(&(i, v)) = entries[j]
            .iter()
            .filter(|&&(i, _)| i < neq)
            .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        else {
            return Err("a column without an equilibrium entry");
        };
        let (i2, sg) = eq_rows[i];
        let j2 = col[j].0;
        let Ok(t) = entries[j2].binary_search_by_key(&i2, |&(r, _)| r) else {
            return Err("a column and its image: entries differ");
        };
        alpha[j] = if sg * v * entries[j2][t].1 >= 0.0 {
            1.0
        } else {
            -1.0
        };
    }
    // The law rows by their entries, and the law rows of each column.
    let mut law: Vec<Vec<(usize, f64)>> = vec![Vec::new(); nlaw];
    for (j, e) in entries.iter().enumerate() {
        for &(i, v) in e.iter().filter(|&&(i, _)| i >= neq) {
            law[i - neq].push((j, v));
        }
    }
    let mut used = vec![false; nlaw];
    let mut out = Vec::with_capacity(nlaw);
    for r in 0..nlaw {
        let mut image: Vec<(usize, f64)> = law[r]
            .iter()
            .map(|&(j, v)| (col[j].0, alpha[j] * v))
            .collect();
        image.sort_by_key(|&(j, _)| j);
        let size = image.iter().fold(0.0f64, |m, &(_, v)| m.max(v.abs()));
        let Some(&(jb, vb)) = image.iter().find(|&&(_, v)| v.abs() == size) else {
            // A row without entries: its own image, its bounds checked with the others.
            out.push((neq + r, 1.0));
            continue;
        };
        let found = entries[jb]
            .iter()
            .filter(|&&(i, _)| i >= neq && !used[i - neq])
            .find_map(|&(i2, v2)| {
                let s = if v2 * vb >= 0.0 { 1.0 } else { -1.0 };
                let target = &law[i2 - neq];
                let same = target.len() == image.len()
                    && target
                        .iter()
                        .zip(&image)
                        .all(|(a, b)| a.0 == b.0 && (a.1 - s * b.1).abs() <= 1e-9 * size);
                same.then_some((i2, s))
            });
        let Some((i2, s)) = found else {
            return Err("a law row without its mirror image");
        };
        used[i2 - neq] = true;
        out.push((i2, s));
    }
    Ok(out)
}

/// The least load multiplier of a planar limit program `fp` (of `st` on `map`; `least` is its
/// program minimised) as the mirror image of the largest multiplier's optimum `largest`, where
/// the structure, its supports and its dead loads are symmetric about a vertical line and the
/// live load is mirrored onto minus itself (a horizontal load: the tilting table). The image of
/// a state under `λ·F_L` is one under `−λ·F_L`, so the multipliers in equilibrium form
/// `[−λ_max, λ_max]`; the image of the optimum (its duals too) is returned only where it is
/// certified on `least` itself (its primal and dual feasibility and gap,
/// [`lp::sequence::certify`], and the solver policy's check), so nothing rests on the
/// symmetry's detection. `None` where there is no such mirror or the image does not certify.
pub(crate) fn least_by_mirror<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    fp: &programs::ForceProgram,
    largest: &LpSolution,
    least: &lp::LinearProgram,
) -> Option<LpSolution> {
    let lambda = fp.lambda?;
    if largest.status != LpStatus::Optimal
        || !fp.cones.is_empty()
        || !fp.lp.maximise
        || least.maximise
        || largest.x.len() != fp.lp.num_cols()
    {
        return None;
    }
    let m = match Mirror::of(st, map, fp) {
        Ok(m) => m,
        Err(why) => {
            trace(
                format_args!("least multiplier: no mirror: {why}"),
                std::time::Instant::now(),
            );
            return None;
        }
    };
    if m.col[lambda].1 >= 0.0 {
        return None; // the live load is its own mirror image: λ is not flipped
    }
    let (flipped, image) = Symmetry::from(m).optimum(largest, &fp.lp.cost, &least.cost)?;
    // Certified as the solver layer certifies any optimum it hands on (a least multiplier by
    // Clarabel included): primal and dual feasibility and the gap within the policy's
    // tolerance. The image keeps the largest optimum's own residuals (a mirror is a signed
    // permutation), so a vertex whose duals HiGHS left 2.3e-7 from feasible — within its own
    // tolerance, above the sequences' stricter 1e-7 — is not refused here for that (the 1.0 m
    // running-bond façade with μ = 0.6, tilted).
    let tol = lp::policy::CERTIFICATE_TOLERANCE;
    let cert = lp::sequence::certify(least, &image);
    trace(
        format_args!("least multiplier: the mirror image {cert:?}"),
        std::time::Instant::now(),
    );
    let certified = image.status == LpStatus::Optimal
        && cert.is_some_and(|c| c.primal <= tol && c.dual <= tol && c.gap <= tol);
    (flipped && certified && lp::policy::check(least, &image).is_none()).then_some(image)
}

impl From<Mirror> for Symmetry {
    fn from(m: Mirror) -> Symmetry {
        Symmetry {
            col: m.col.into_iter().map(|c| vec![c]).collect(),
            row: m.row.into_iter().map(|r| vec![r]).collect(),
            support: m.support,
        }
    }
}

/// A symmetry of an equilibrium program as linear maps of its columns and rows: a mirror
/// ([`Mirror`], 2D: signed permutations) or an isometry of a 3D structure ([`isometries_3d`]:
/// a point's normal force maps to its image's, its two shears to a rotation of its image's
/// two, a block's force and moment rows to the isometry of its image's). Both maps are
/// orthogonal, so the image of a direction, of a cost or of reduced costs is the same column
/// map. An optimum mapped by it is only a candidate: it is used where its certificate on the
/// target program holds ([`certified`]).
struct Symmetry {
    /// Column `j` ↦ `[(j', α), …]`: `x'_{j'} += α x_j`.
    col: Vec<Vec<(usize, f64)>>,
    /// Row `i` ↦ `[(i', s), …]`: `y'_{i'} += s y_i`.
    row: Vec<Vec<(usize, f64)>>,
    /// Support `s` ↦ its image.
    support: Vec<usize>,
}

impl Symmetry {
    /// The image of a direction or a point of the program's columns.
    fn columns(&self, x: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; x.len()];
        for (j, m) in self.col.iter().enumerate() {
            for &(j2, a) in m {
                out[j2] += a * x[j];
            }
        }
        out
    }

    /// The image of an optimum of the objective `cost` as an optimum of the objective
    /// `target` (the image of `cost`, or minus it: then the sense flips and so do the duals),
    /// with `target`'s sense: `None` where `target` is neither.
    fn optimum(
        &self,
        sol: &LpSolution,
        cost: &[f64],
        target: &[f64],
    ) -> Option<(bool, LpSolution)> {
        let image = self.columns(cost);
        let size = image.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let same = image
            .iter()
            .zip(target)
            .all(|(a, b)| (a - b).abs() <= 1e-12 * size);
        let flipped = image
            .iter()
            .zip(target)
            .all(|(a, b)| (a + b).abs() <= 1e-12 * size);
        if size == 0.0 || !(same || flipped) {
            return None;
        }
        let sign = if same { 1.0 } else { -1.0 };
        let x = self.columns(&sol.x);
        let mut row_dual = vec![0.0; sol.row_dual.len()];
        for (i, m) in self.row.iter().enumerate() {
            for &(i2, sg) in m {
                row_dual[i2] += sign * sg * sol.row_dual[i];
            }
        }
        let col_dual: Vec<f64> = self
            .columns(&sol.col_dual)
            .iter()
            .map(|v| sign * v)
            .collect();
        let objective = target.iter().zip(&x).map(|(c, v)| c * v).sum();
        Some((
            flipped,
            LpSolution {
                x,
                row_dual,
                col_dual,
                objective,
                iterations: 0,
                tried: vec![],
                ..sol.clone()
            },
        ))
    }
}

/// At most this many rotations are tried as symmetries of a 3D structure ([`isometries_3d`]):
/// each is a pass over the blocks and points, so the search stays linear in the model.
const MAX_ROTATIONS: usize = 64;

/// The isometries of a 3D structure that may map its equilibrium program onto itself: the
/// rotations about the vertical line through the middle of the blocks' reference points
/// that take the first support onto another support (at the same height and distance from
/// the line; at most [`MAX_ROTATIONS`]), and the mirrors in the vertical planes `x = x_c` and
/// `y = y_c` through that line. One is kept where every block, support and contact point has
/// exactly one image (to 1e-9 of the structure's extent, the image point on a joint between
/// the image bodies, its normal the image of the normal) and every column is a point's
/// force; the loads are not compared, as every image of an optimum is certified on its own
/// program before it is used. `Err` says why none was looked for.
fn isometries_3d<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    base: &programs::ForceProgram,
) -> std::result::Result<Vec<Symmetry>, &'static str> {
    type V3 = [f64; 3];
    if <S::D as Dim>::N != 3 || map.dofs_per_block != 6 || <S::D as Dim>::TANGENTS != 2 {
        return Err("not 3D");
    }
    let lp = &base.lp;
    let bodies = st.contact_bodies();
    let nb = bodies.blocks.len();
    if nb == 0 || lp.num_rows() != 6 * nb {
        return Err("rows are not six per block");
    }
    let v3 = |v: &<S::D as Dim>::Vector| -> V3 {
        let a = v.as_ref();
        [a[0], a[1], a[2]]
    };
    let blocks: Vec<V3> = bodies.blocks.iter().map(v3).collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for b in &blocks {
        for c in 0..3 {
            lo[c] = lo[c].min(b[c]);
            hi[c] = hi[c].max(b[c]);
        }
    }
    let extent = (0..3).fold(0.0f64, |m, c| m.max(hi[c] - lo[c]));
    if !(extent.is_finite() && extent > 0.0) {
        return Err("blocks extent");
    }
    let (xc, yc) = (0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]));
    let tol = 1e-9 * extent;
    let joints = st.contact_joints();
    let point_pos: Vec<V3> = map
        .points
        .iter()
        .map(|pr| v3(&joints[pr.joint].points[pr.index].0))
        .collect();
    // Every column a point's force: its normal or one of its two shears.
    let mut owned = vec![false; lp.num_cols()];
    for c in base.pn.iter().chain(&base.pt).flatten() {
        owned[*c] = true;
    }
    if owned.iter().any(|o| !o) {
        return Err("a column that is not a point's force");
    }
    let ns = st.num_supports();
    let mut mean = vec![([0.0; 3], 0usize); ns];
    for (k, p) in point_pos.iter().enumerate() {
        let j = &joints[map.points[k].joint];
        for body in [j.a, j.b] {
            if let Body::Support(s) = body {
                for (m, v) in mean[s].0.iter_mut().zip(p) {
                    *m += v;
                }
                mean[s].1 += 1;
            }
        }
    }
    let support_pos: Vec<V3> = mean
        .iter()
        .map(|&(p, n)| {
            if n > 0 {
                p.map(|v| v / n as f64)
            } else {
                [f64::NAN; 3]
            }
        })
        .collect();
    let (block_index, point_index, support_index) = (
        PositionIndex::new(&blocks, extent),
        PositionIndex::new(&point_pos, extent),
        PositionIndex::new(&support_pos, extent),
    );
    // The candidates, as 3 × 3 matrices about the vertical line (xc, yc).
    let mut candidates: Vec<[V3; 3]> = vec![
        [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]],
    ];
    if let Some(s0) = support_pos.iter().position(|p| p[0].is_finite()) {
        let p0 = [support_pos[s0][0] - xc, support_pos[s0][1] - yc];
        let r0 = p0[0].hypot(p0[1]);
        if r0 > tol {
            for (s, p) in support_pos.iter().enumerate() {
                if s == s0 || !p[0].is_finite() || (p[2] - support_pos[s0][2]).abs() > tol {
                    continue;
                }
                let d = [p[0] - xc, p[1] - yc];
                if (d[0].hypot(d[1]) - r0).abs() > tol {
                    continue;
                }
                let th = (p0[0] * d[1] - p0[1] * d[0]).atan2(p0[0] * d[0] + p0[1] * d[1]);
                let (sn, cs) = th.sin_cos();
                candidates.push([[cs, -sn, 0.0], [sn, cs, 0.0], [0.0, 0.0, 1.0]]);
                if candidates.len() >= 2 + MAX_ROTATIONS {
                    break;
                }
            }
        }
    }
    let mul = |m: &[V3; 3], v: V3| -> V3 {
        [0, 1, 2].map(|r| m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2])
    };
    let dot = |a: V3, b: V3| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let build = |m: &[V3; 3]| -> Option<Symmetry> {
        let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        let place = |p: V3| {
            let r = mul(m, [p[0] - xc, p[1] - yc, p[2]]);
            [r[0] + xc, r[1] + yc, r[2]]
        };
        let mut sigma = vec![0; nb];
        for (i, &b) in blocks.iter().enumerate() {
            match block_index.near(place(b))[..] {
                [j] => sigma[i] = j,
                _ => return None,
            }
        }
        let mut support: Vec<usize> = (0..ns).collect();
        for (s, &p) in support_pos.iter().enumerate() {
            if p[0].is_finite() {
                match support_index.near(place(p))[..] {
                    [s2] => support[s] = s2,
                    _ => return None,
                }
            }
        }
        let image_body = |b: Body| match b {
            Body::Block(i) => Body::Block(sigma[i]),
            Body::Support(s) => Body::Support(support[s]),
        };
        let frame = |k: usize| {
            let j = &joints[map.points[k].joint];
            let t = j.tangents.as_ref();
            [
                (base.pn[k], v3(&j.normal)),
                (base.pt[2 * k], v3(&t[0])),
                (base.pt[2 * k + 1], v3(&t[1])),
            ]
        };
        let mut col = vec![Vec::new(); lp.num_cols()];
        for (k, &p) in point_pos.iter().enumerate() {
            let j = &joints[map.points[k].joint];
            let (a2, b2) = (image_body(j.a), image_body(j.b));
            let mut image = None;
            for k2 in point_index.near(place(p)) {
                let j2 = &joints[map.points[k2].joint];
                let sign = if (j2.a, j2.b) == (a2, b2) {
                    1.0
                } else if (j2.a, j2.b) == (b2, a2) {
                    -1.0
                } else {
                    continue;
                };
                if image.is_some() {
                    return None;
                }
                image = Some((k2, sign));
            }
            let (k2, sign) = image?;
            // A force applied to b (and its opposite to a) maps to the image force applied to
            // the image of b: the image joint's own b, or its a (sign -1).
            let (from, to) = (frame(k), frame(k2));
            for (c, e) in from {
                let qe = mul(m, e).map(|v| sign * v);
                for &(c2, e2) in &to {
                    match (c, c2) {
                        (Some(c), Some(c2)) => {
                            let v = dot(qe, e2);
                            if v.abs() > 1e-12 {
                                col[c].push((c2, v));
                            }
                        }
                        (None, None) => {}
                        _ => return None,
                    }
                }
            }
            if let (Some(c), Some(c2)) = (base.pn[k], base.pn[k2]) {
                if !col[c]
                    .iter()
                    .any(|&(j, v)| j == c2 && (v - 1.0).abs() <= 1e-9)
                {
                    return None;
                }
            }
        }
        let mut row = vec![Vec::new(); lp.num_rows()];
        for (b, &b2) in sigma.iter().enumerate() {
            for r in 0..3 {
                for (c, mc) in m.iter().enumerate() {
                    if mc[r] != 0.0 {
                        row[6 * b + r].push((6 * b2 + c, mc[r]));
                        row[6 * b + 3 + r].push((6 * b2 + 3 + c, det * mc[r]));
                    }
                }
            }
        }
        Some(Symmetry { col, row, support })
    };
    Ok(candidates.iter().filter_map(build).collect())
}

/// Blocks of rows around a reaction's columns on which [`LocalRays::find`] looks for a ray:
/// at most this many rounds of growth (each adds every row that shares a column with the rows
/// so far: the neighbouring blocks) and this many rows.
const LOCAL_RAY_ROUNDS: usize = 4;
const LOCAL_RAY_ROWS: usize = 240;
/// Sides tried for a local ray before the first is found ([`LocalRays`]): none found on these,
/// no more are tried.
const LOCAL_RAY_SIDES: usize = 4;

/// Rays of a reaction's side found on a small part of the equilibrium program (session 21):
/// the rows of the blocks around the support and the columns that touch no other row. A
/// direction of that small recession program is one of the whole program (its columns have
/// no entry elsewhere, and every other column is 0), so a ray of it, padded with zeros, is a
/// candidate ray of the side, certified on the side's own program ([`lp::sequence::certify_ray`])
/// before it is used. On the façades a horizontal side is unbounded by a compression between
/// two neighbouring base blocks (the support's shear against the next support's): two or three
/// blocks' rows, a program of a few dozen columns, where the warm primal simplex on the whole
/// program took up to 7 CPU s to say "unbounded".
struct LocalRays {
    /// The rows of each column, and the columns of each row.
    col_rows: Vec<Vec<usize>>,
    row_cols: Vec<Vec<usize>>,
}

impl LocalRays {
    fn new(lp: &lp::LinearProgram) -> LocalRays {
        let col_rows: Vec<Vec<usize>> = (0..lp.num_cols())
            .map(|j| {
                lp.column(j)
                    .filter(|&(_, v)| v != 0.0)
                    .map(|(i, _)| i)
                    .collect()
            })
            .collect();
        let mut row_cols = vec![Vec::new(); lp.num_rows()];
        for (j, rows) in col_rows.iter().enumerate() {
            for &i in rows {
                row_cols[i].push(j);
            }
        }
        LocalRays { col_rows, row_cols }
    }

    /// A ray of `program` (the side's program: the equilibrium program with the side's
    /// objective) certified on it, found on the rows around the objective's columns; `None`
    /// where none is found within [`LOCAL_RAY_ROUNDS`] rounds and [`LOCAL_RAY_ROWS`] rows.
    /// `solves` counts the small programs.
    fn find(
        &self,
        program: &lp::LinearProgram,
        solver: &SolverOptions,
        solves: &mut usize,
    ) -> Option<(Vec<f64>, lp::sequence::RayCertificate)> {
        let (m, n) = (program.num_rows(), program.num_cols());
        let mut in_rows = vec![false; m];
        let mut rows: Vec<usize> = Vec::new();
        fn add(i: usize, rows: &mut Vec<usize>, in_rows: &mut [bool]) {
            if !in_rows[i] {
                in_rows[i] = true;
                rows.push(i);
            }
        }
        for j in (0..n).filter(|&j| program.cost[j] != 0.0) {
            for &i in &self.col_rows[j] {
                add(i, &mut rows, &mut in_rows);
            }
        }
        if rows.is_empty() {
            return None;
        }
        let rec = |b: f64| if b.is_finite() { 0.0 } else { b };
        let o = SolverOptions {
            method: lp::Method::DualSimplex,
            ..*solver
        };
        let _kind = lp::ProgramKind::candidates(LOCAL_RAYS, LOCAL_RAYS_DESIGN);
        for _ in 0..LOCAL_RAY_ROUNDS {
            if rows.len() > LOCAL_RAY_ROWS {
                return None;
            }
            // The columns with every entry on these rows.
            let mut cols: Vec<usize> = rows
                .iter()
                .flat_map(|&i| self.row_cols[i].iter().copied())
                .filter(|&j| self.col_rows[j].iter().all(|&i| in_rows[i]))
                .collect();
            cols.sort_unstable();
            cols.dedup();
            if cols.iter().any(|&j| program.cost[j] != 0.0) {
                let mut pos = vec![usize::MAX; m];
                let mut small = lp::LinearProgram::new(if program.maximise {
                    Direction::Maximise
                } else {
                    Direction::Minimise
                });
                for (k, &i) in rows.iter().enumerate() {
                    pos[i] = k;
                    small.add_row(rec(program.row_lower[i]), rec(program.row_upper[i]));
                }
                for &j in &cols {
                    let entries: Vec<(usize, f64)> =
                        program.column(j).map(|(i, v)| (pos[i], v)).collect();
                    small.add_column(
                        program.cost[j],
                        rec(program.col_lower[j]).max(-1.0),
                        rec(program.col_upper[j]).min(1.0),
                        entries,
                    );
                }
                *solves += 1;
                if let Ok(s) = lp::solve(&small, &o) {
                    if s.status == LpStatus::Optimal {
                        let mut d = vec![0.0; n];
                        for (k, &j) in cols.iter().enumerate() {
                            d[j] = s.x[k];
                        }
                        let cert = lp::sequence::certify_ray(program, &d);
                        if cert.ok() {
                            return Some((d, cert));
                        }
                    }
                }
            }
            // The neighbouring blocks: every row that shares a column with these (none left:
            // the whole structure was this program, and it has no ray).
            let grow: Vec<usize> = rows
                .iter()
                .flat_map(|&i| self.row_cols[i].iter())
                .flat_map(|&j| self.col_rows[j].iter().copied())
                .collect();
            let before = rows.len();
            for i in grow {
                add(i, &mut rows, &mut in_rows);
            }
            if rows.len() == before {
                return None;
            }
        }
        None
    }
}

/// Largest difference, relative to the column's largest entry, between two columns that
/// [`Twins`] takes as one (round-off: in 2D the two shear forces of a joint have the same
/// entries but for the last bits of the moment's).
const TWIN_TOLERANCE: f64 = 1e-12;

/// The reaction ranges' sequence on the equilibrium program with one column of each set of
/// twins: columns with the same bounds (`[0, ∞)` or free), the same entries to
/// [`TWIN_TOLERANCE`] and the same coefficient in every objective of the ranges. In 2D the two
/// shear forces of a joint are such twins (on the 0.5 m grid façade a quarter of the
/// program's 20,992 columns). A point of the reduced program is one of the whole with the
/// twins dropped at 0 (the kept column's entries are the program's own: every row holds
/// exactly as it did), and every answer is expanded so and certified on the whole program
/// before it is used (a dropped twin's reduced cost is its kept twin's, to round-off).
pub(crate) struct Twins {
    /// The column of the whole program of each column of the reduced one.
    keep: Vec<usize>,
    /// The reduced program's column of each column of the whole (its twin's where dropped),
    /// and whether it is the kept one.
    of: Vec<(usize, bool)>,
}

impl Twins {
    /// The twins of `lp`'s columns, where each objective in `costs` gives them the same
    /// coefficient; `None` where there are none.
    pub(crate) fn of(lp: &lp::LinearProgram, costs: &[Vec<f64>]) -> Option<Twins> {
        use std::collections::HashMap;
        let n = lp.num_cols();
        // Candidates by their bounds, row pattern and costs (bit for bit); their entries are
        // compared within the tolerance below.
        let mut groups: HashMap<Vec<u64>, Vec<usize>> = HashMap::new();
        for j in 0..n {
            let (lo, hi) = (lp.col_lower[j], lp.col_upper[j]);
            if !((lo == 0.0 || lo == f64::NEG_INFINITY) && hi == f64::INFINITY) {
                continue;
            }
            let mut k = vec![lo.to_bits(), lp.cost[j].to_bits()];
            k.extend(lp.column(j).map(|(i, _)| i as u64));
            k.push(u64::MAX);
            for (o, c) in costs.iter().enumerate() {
                if c[j] != 0.0 {
                    k.push(o as u64);
                    k.push(c[j].to_bits());
                }
            }
            groups.entry(k).or_default().push(j);
        }
        let mut twin_of: Vec<Option<usize>> = vec![None; n];
        let mut any = false;
        for cols in groups.values().filter(|c| c.len() > 1) {
            let mut kept: Vec<usize> = Vec::new();
            for &j in cols {
                let a: Vec<f64> = lp.column(j).map(|(_, v)| v).collect();
                let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                let same = kept.iter().copied().find(|&r| {
                    lp.column(r)
                        .zip(&a)
                        .all(|((_, v), w)| (v - w).abs() <= TWIN_TOLERANCE * scale)
                });
                match same {
                    Some(r) => {
                        twin_of[j] = Some(r);
                        any = true;
                    }
                    None => kept.push(j),
                }
            }
        }
        if !any {
            return None;
        }
        let mut keep = Vec::new();
        let mut of = vec![(0, false); n];
        for j in 0..n {
            if twin_of[j].is_none() {
                of[j] = (keep.len(), true);
                keep.push(j);
            }
        }
        for j in 0..n {
            if let Some(r) = twin_of[j] {
                of[j] = (of[r].0, false);
            }
        }
        Some(Twins { keep, of })
    }

    pub(crate) fn program(&self, lp: &lp::LinearProgram) -> lp::LinearProgram {
        let mut out = lp.rows_only();
        for &j in &self.keep {
            out.add_column(lp.cost[j], lp.col_lower[j], lp.col_upper[j], lp.column(j));
        }
        out
    }

    /// A vector of the whole program's columns (an objective) on the reduced one.
    pub(crate) fn reduce(&self, v: &[f64]) -> Vec<f64> {
        self.keep.iter().map(|&j| v[j]).collect()
    }

    /// A point or direction of the reduced program as one of the whole (the twins at 0).
    pub(crate) fn expand(&self, v: &[f64]) -> Vec<f64> {
        self.of
            .iter()
            .map(|&(k, kept)| if kept { v[k] } else { 0.0 })
            .collect()
    }

    /// A solution of the reduced program as one of the whole: the dropped twins at 0 with
    /// their twin's reduced cost (certified on the whole program by the caller).
    pub(crate) fn solution(&self, mut s: LpSolution) -> LpSolution {
        if s.x.len() == self.keep.len() {
            s.x = self.expand(&s.x);
        }
        if s.col_dual.len() == self.keep.len() {
            s.col_dual = self.of.iter().map(|&(k, _)| s.col_dual[k]).collect();
        }
        s
    }

    /// A basis of the whole program as one of the reduced: a kept column is basic where it
    /// or a dropped twin is (the twins are dependent: at most one of them is basic).
    pub(crate) fn basis(&self, b: &lp::Basis) -> lp::Basis {
        let mut cols: Vec<BasisStatus> = self.keep.iter().map(|&j| b.cols[j]).collect();
        for (j, &(k, kept)) in self.of.iter().enumerate() {
            if !kept && b.cols[j] == BasisStatus::Basic {
                cols[k] = BasisStatus::Basic;
            }
        }
        lp::Basis {
            cols,
            rows: b.rows.clone(),
        }
    }
}

/// How the reaction ranges are solved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum RangeSolve {
    /// One program of one solver instance whose objective changes ([`lp::sequence`]), and no
    /// program where statics gives the answer (one or two supports). The default.
    #[default]
    Sequence,
    /// Every endpoint its own program, solved from scratch (the reference the sequence is
    /// tested against).
    Independent,
}

/// The range of every force component of every support's reaction over the statically
/// admissible states, and the LP solves spent ([`reaction_ranges_by`] with
/// [`RangeSolve::Sequence`]).
pub fn reaction_ranges<S: Assembly>(
    st: &S,
    solver: &SolverOptions,
) -> Result<(Vec<AdmissibleReactionRange>, usize)> {
    let r = reaction_ranges_by(st, solver, RangeSolve::Sequence)?;
    Ok((r.ranges, r.solves))
}

/// The range of every force component of every support's reaction over the statically
/// admissible states.
///
/// Every endpoint is the optimum of `min` or `max` of the component over the feasible set of
/// [`programs::equilibrium_program`], certified ([`lp::sequence::certify`]); an endpoint whose
/// certificate fails is an error. With [`RangeSolve::Sequence`] the programs share one solver
/// instance and start from each other's bases, and statics saves programs exactly:
///
/// * one support carries the whole load, in every admissible state: its reaction is minus the
///   total load, no program;
/// * with two supports the reactions add up to minus the total load in every admissible state
///   (summing the blocks' force equations, the joint forces between blocks cancel), so the
///   second support's least value is the total minus the first's largest, attained by the
///   same state, and so on: half the programs;
/// * a structure symmetric about a vertical line (its program mapped onto itself by the
///   mirror, checked entry by entry): each optimum's mirror image is the mirrored support's
///   optimum, certified on that side's program without solving it, and each ray's image a
///   ray (`Mirror`; the 0.5 m grid façade: 152 → 95 solves, 104.5 → 56.4 CPU s).
pub fn reaction_ranges_by<S: Assembly>(
    st: &S,
    solver: &SolverOptions,
    how: RangeSolve,
) -> Result<ReactionRanges> {
    ranges_from(st, solver, how, None)
}

/// [`reaction_ranges_by`], the sequence starting from `start` where given (a feasible basis of
/// the equilibrium program: the first decision of [`safety`]'s bisection).
fn ranges_from<S: Assembly>(
    st: &S,
    solver: &SolverOptions,
    how: RangeSolve,
    start: Option<lp::Basis>,
) -> Result<ReactionRanges> {
    let map = KinematicMap::new(st);
    let dead = st.load_vector(false);
    let coefficients = reaction_coefficients(st, &map);
    let n = <S::D as Dim>::N;
    // The force components of the reaction (z up in 3D).
    let labels = &["fx", "fy", "fz"][..n];
    // Minus the total load: the sum of the supports' reactions in every admissible state.
    let total: Vec<f64> = (0..n)
        .map(|c| -dead.chunks(map.dofs_per_block).map(|f| f[c]).sum::<f64>())
        .collect();
    let base = programs::equilibrium_program(&map, &dead);
    if !base.cones.is_empty() {
        return Err(Error::Request(
            "the reaction ranges are LPs: cone constraints are not taken".into(),
        ));
    }
    let cost_of = |cn: &[f64], ct: &[f64]| -> Vec<f64> {
        let mut cost = vec![0.0; base.lp.num_cols()];
        for (k, col) in base.pn.iter().enumerate() {
            if let Some(j) = col {
                cost[*j] += cn[k];
            }
        }
        for (r, col) in base.pt.iter().enumerate() {
            if let Some(j) = col {
                cost[*j] += ct[r];
            }
        }
        cost
    };
    let supports = st.num_supports();
    let statics = how == RangeSolve::Sequence && supports <= 2;
    let mut out = ReactionRanges {
        ranges: Vec::with_capacity(supports),
        solves: 0,
        warm: 0,
        restarts: 0,
        from_statics: 0,
        worst: lp::sequence::Certificate {
            primal: 0.0,
            dual: 0.0,
            gap: 0.0,
        },
        unbounded: 0,
        ray_programs: 0,
        lineality_rays: 0,
        worst_ray: 0.0,
        mirrored: 0,
        local_rays: 0,
        local_ray_programs: 0,
        without_columns: 0,
        twin_columns: 0,
    };
    // A mirror symmetry of the program: each side solved gives its mirror image's
    // (the mirrored support's side, checked by its certificate on that program) and each ray
    // its image, without a program (half the programs of a symmetric structure).
    // In 3D the rotations about a vertical line and the mirrors in vertical planes
    // ([`isometries_3d`]; the 24 × 24 dome: 23 rotations and 24 mirrors, one support's sides
    // solved give every other's).
    let symmetries: Vec<Symmetry> = match how {
        RangeSolve::Sequence => {
            let found = match Mirror::of(st, &map, &base) {
                Err("not planar") => isometries_3d(st, &map, &base),
                m => m.map(|m| vec![m.into()]),
            };
            trace(
                format_args!("ranges: symmetries {:?}", found.as_ref().map(|v| v.len())),
                std::time::Instant::now(),
            );
            found.unwrap_or_default()
        }
        RangeSolve::Independent => vec![],
    };
    let mut mirrored: std::collections::HashMap<(usize, usize, usize), LpSolution> =
        std::collections::HashMap::new();
    // The sequence runs on the program with one column of each set of twins ([`Twins`]).
    let twins = match how {
        RangeSolve::Sequence => {
            let costs: Vec<Vec<f64>> = coefficients
                .iter()
                .flat_map(|comps| comps.iter().map(|(cn, ct)| cost_of(cn, ct)))
                .collect();
            Twins::of(&base.lp, &costs)
        }
        RangeSolve::Independent => None,
    };
    out.twin_columns = twins
        .as_ref()
        .map_or(0, |t| base.lp.num_cols() - t.keep.len());
    trace(
        format_args!(
            "ranges: {} of {} columns kept (twins dropped)",
            twins.as_ref().map_or(base.lp.num_cols(), |t| t.keep.len()),
            base.lp.num_cols()
        ),
        std::time::Instant::now(),
    );
    let mut sequence = match how {
        RangeSolve::Sequence => {
            let reduced = match &twins {
                Some(t) => t.program(&base.lp),
                None => base.lp.clone(),
            };
            let mut seq = lp::sequence::Sequence::new(reduced, solver)?;
            seq.limit_warm_iterations(Some(warm_limit(&base.lp)));
            // A feasible vertex of these constraints (the bisection's first program): the
            // first endpoint goes on from it with the primal simplex.
            if let Some(b) = start {
                seq.start_from(match &twins {
                    Some(t) if b.cols.len() == base.lp.num_cols() => t.basis(&b),
                    _ => b,
                });
            }
            Some(seq)
        }
        RangeSolve::Independent => None,
    };
    // ends[s][c] = (min, max)
    let mut ends: Vec<Vec<[Option<f64>; 2]>> = vec![vec![[None, None]; n]; supports];
    // Rays found so far with their violation of the recession cone (a property of the
    // constraints, measured once: [`lp::sequence::ray_violation`]), the recession program's
    // sequence and a feasible point (a ray certifies unboundedness from one).
    let mut rays: Vec<(Vec<f64>, f64)> = Vec::new();
    let mut ray_sequence: Option<lp::sequence::Sequence> = None;
    let mut feasible_point: Option<Vec<f64>> = None;
    // The projection onto the free columns' lineality space (made at the first side that
    // needs it; `Some(None)` where the program has none).
    let mut lineality: Option<Option<lp::sequence::Lineality>> = None;
    // The rows and columns of the program by each other, for rays on a few blocks (made at
    // the first horizontal side).
    let mut local_rays: Option<LocalRays> = None;
    let mut local_misses = 0;
    for (s, comps) in coefficients.iter().enumerate() {
        // The vertical component first: bounded where the structure stands, so the first
        // program has an optimum for the later ones to start from.
        for c in std::iter::once(n - 1).chain(0..n - 1) {
            let (cn, ct) = &comps[c];
            if statics && supports == 1 {
                ends[s][c] = [Some(total[c]), Some(total[c])];
                out.from_statics += 2;
                continue;
            }
            if statics && s == 1 {
                // R₁ = total − R₀ in every admissible state.
                let [lo, hi] = ends[0][c];
                ends[s][c] = [hi.map(|v| total[c] - v), lo.map(|v| total[c] - v)];
                out.from_statics += 2;
                continue;
            }
            let cost = cost_of(cn, ct);
            if how == RangeSolve::Sequence && cost.iter().all(|&v| v == 0.0) {
                // A component with no column (a support without a contact point, under an
                // opening): 0 in every admissible state, no program.
                ends[s][c] = [Some(0.0), Some(0.0)];
                out.without_columns += 2;
                trace(
                    format_args!("range {} {}: no column, 0", st.support_name(s), labels[c]),
                    std::time::Instant::now(),
                );
                continue;
            }
            for (e, direction) in [Direction::Minimise, Direction::Maximise]
                .into_iter()
                .enumerate()
            {
                let program = match &sequence {
                    Some(_) => {
                        let mut p = base.lp.clone();
                        p.cost.copy_from_slice(&cost);
                        p.maximise = direction == Direction::Maximise;
                        p
                    }
                    None => programs::reaction_extreme_program(&map, &dead, cn, ct, direction).lp,
                };
                let t0 = std::time::Instant::now();
                let side = format!(
                    "{} {} {}",
                    st.support_name(s),
                    labels[c],
                    if e == 0 { "min" } else { "max" }
                );
                // A ray found for an earlier endpoint that improves this one: unbounded, no
                // program.
                if let Some(&(_, v)) = rays.iter().find(|(d, _)| {
                    lp::sequence::ray_decrease(&program, d) >= lp::sequence::RAY_DECREASE
                }) {
                    out.unbounded += 1;
                    out.worst_ray = out.worst_ray.max(v);
                    ends[s][c][e] = None;
                    trace(format_args!("range {side}: unbounded by a kept ray"), t0);
                    continue;
                }
                // A ray along the free columns, both ways, without a program: the objective
                // projected onto their lineality space (one factorisation for every side; on
                // the 24 × 24 dome the self-equilibrated shear that makes every horizontal
                // side unbounded). Where the side is bounded the projection is round-off and
                // the certificate refuses it.
                let mut lineality_ray = None;
                if sequence.is_some() {
                    let l = lineality.get_or_insert_with(|| lp::sequence::Lineality::new(&base.lp));
                    if let Some(l) = l.as_mut() {
                        let mut d = l.project(&cost);
                        if direction == Direction::Minimise {
                            d.iter_mut().for_each(|v| *v = -*v);
                        }
                        let cert = lp::sequence::certify_ray(&program, &d);
                        if cert.ok() {
                            trace(format_args!("range {side}: lineality ray {cert:?}"), t0);
                            out.lineality_rays += 1;
                            lineality_ray = Some((d, cert.violation));
                        }
                    }
                }
                let image = mirrored
                    .remove(&(s, c, e))
                    .filter(|m| certified(&program, m));
                // A horizontal side: a ray on the blocks around the support first (a small
                // recession program; [`LocalRays`]), certified on this side's program.
                // Until the first is found, at most LOCAL_RAY_SIDES sides are tried (a
                // structure whose horizontal sides are all bounded, as with friction, pays
                // for those few small programs only).
                if lineality_ray.is_none()
                    && image.is_none()
                    && sequence.is_some()
                    && c != n - 1
                    && (out.local_rays > 0 || local_misses < LOCAL_RAY_SIDES)
                {
                    let local = local_rays.get_or_insert_with(|| LocalRays::new(&base.lp));
                    let before = out.local_ray_programs;
                    let found = local.find(&program, solver, &mut out.local_ray_programs);
                    out.solves += out.local_ray_programs - before;
                    if let Some((d, cert)) = found {
                        trace(format_args!("range {side}: local ray {cert:?}"), t0);
                        out.local_rays += 1;
                        lineality_ray = Some((d, cert.violation));
                    } else {
                        local_misses += 1;
                    }
                }
                let mut tried = if lineality_ray.is_some() {
                    None
                } else if let Some(m) = image {
                    out.mirrored += 1;
                    trace(
                        format_args!("range {side}: the image of a side solved under a symmetry"),
                        t0,
                    );
                    Some(m)
                } else {
                    let tried = match &mut sequence {
                        Some(seq) => match &twins {
                            Some(t) => {
                                seq.set_objective(&t.reduce(&cost), direction)?;
                                seq.try_solve().map(|s| t.solution(s))
                            }
                            None => {
                                seq.set_objective(&cost, direction)?;
                                seq.try_solve()
                            }
                        },
                        None => lp::solve(&program, solver).ok(),
                    };
                    out.solves += 1;
                    trace(
                        format_args!(
                            "range {side}: {:?} by {:?} ({:?} iterations)",
                            tried.as_ref().map(|t| t.status),
                            tried.as_ref().map(|t| t.method.name()),
                            tried.as_ref().map(|t| t.iterations)
                        ),
                        t0,
                    );
                    tried
                };
                // "Unbounded": HiGHS's own primal ray, checked on the program. Where it gives
                // none that certifies, the run is repeated once in a new instance from the
                // last optimal basis (the warm primal simplex once called a vertical reaction
                // of the 24 × 24 dome unbounded: it is bounded by the weight).
                let mut ray: Option<(Vec<f64>, f64)> = lineality_ray;
                for attempt in 0..2 {
                    if !matches!(&tried, Some(t) if t.status == LpStatus::Unbounded) {
                        break;
                    }
                    let Some(seq) = sequence.as_mut() else {
                        break;
                    };
                    if let Some(d) = seq.last_ray() {
                        let d = match &twins {
                            Some(t) => t.expand(d),
                            None => d.to_vec(),
                        };
                        let cert = lp::sequence::certify_ray(&program, &d);
                        trace(format_args!("range {side}: HiGHS's ray {cert:?}"), t0);
                        if cert.ok() {
                            ray = Some((d, cert.violation));
                            break;
                        }
                    }
                    if attempt == 1 || !seq.restart_from_optimal() {
                        break;
                    }
                    tried = seq.try_solve().map(|s| match &twins {
                        Some(t) => t.solution(s),
                        None => s,
                    });
                    out.solves += 1;
                    trace(
                        format_args!(
                            "range {side}: again from the last optimal basis: {:?}",
                            tried.as_ref().map(|t| t.status)
                        ),
                        t0,
                    );
                }
                // What the warm runs settled: a certified optimum or "infeasible", or an
                // optimum that did not certify (the side is bounded: decided again below).
                let mut sol: Option<LpSolution> = None;
                let mut bounded = false;
                match tried {
                    Some(t) if certified(&program, &t) || t.status == LpStatus::Infeasible => {
                        sol = Some(t)
                    }
                    Some(t) if t.status == LpStatus::Optimal => bounded = true,
                    _ => {}
                }
                if sol.is_none() && ray.is_none() && !bounded {
                    // Unbounded without a ray, or a failure (an unbounded program fails in some
                    // methods rather than saying so): the recession program decides, first by
                    // Clarabel (a ray need not be a vertex; 1–2 s on the 24 × 24 dome where
                    // HiGHS took 4–14 s): a certified ray, or a certified optimum along which
                    // nothing improves — no ray, the side is bounded.
                    out.solves += 1;
                    out.ray_programs += 1;
                    let rp = {
                        let mut r = lp::sequence::recession_program(&base.lp);
                        r.cost.copy_from_slice(&cost);
                        r.maximise = direction == Direction::Maximise;
                        r
                    };
                    // Clarabel alone (its fallback chain went on to HiGHS's interior point,
                    // 9–12 s on the 24 × 24 dome), and its point checked as a ray whether or
                    // not its optimum certifies: a ray needs only to be a recession direction
                    // that improves the objective ([`lp::sequence::certify_ray`]); "bounded"
                    // needs the certified optimum.
                    let o = SolverOptions {
                        method: lp::Method::Clarabel,
                        ..*solver
                    };
                    let _kind = lp::ProgramKind::candidates(RAYS, RAYS_DESIGN);
                    if let Ok(d) = lp::solve_without_fallback(&rp, &o) {
                        let opt = certified(&rp, &d);
                        let cert = lp::sequence::certify_ray(&program, &d.x);
                        trace(
                            format_args!(
                                "range {side}: recession program by {} ({:?}) certified {opt}, ray {cert:?}",
                                d.method.name(),
                                d.status
                            ),
                            t0,
                        );
                        if cert.ok() {
                            ray = Some((d.x, cert.violation));
                        } else if opt && cert.decrease < lp::sequence::RAY_DECREASE {
                            bounded = true;
                        }
                    }
                }
                // Regression (session 19): on the README's vault with μ = 0.6 one side (`left fy
                // min`) was left undecided by the warm run and Clarabel's recession program, and
                // HiGHS's recession programs spent 10 s finding no ray, where the program itself
                // from scratch by Clarabel answered in 0.27 s. Before those: the program from
                // scratch by Clarabel alone; a certified optimum decides the side (bounded, and
                // its value), anything else goes on as before. The methods from scratch, in
                // order: Clarabel, alone, here where it is tried; the rest, each with its
                // fallback chain, where the side is bounded and still undecided below.
                let mut scratch = SCRATCH_METHODS.as_slice();
                if sol.is_none() && ray.is_none() && !bounded {
                    let (first, rest) = scratch.split_at(1);
                    scratch = rest;
                    let got = end_from_scratch(
                        &program,
                        solver,
                        first,
                        Chain::Alone,
                        &mut out.solves,
                        (&side, " before the recession programs", t0),
                    );
                    if let Some(Ok(g)) = got {
                        if certified(&program, &g) {
                            if let Some(seq) = sequence.as_mut() {
                                seq.restart_from_optimal();
                            }
                            sol = Some(g);
                        }
                    }
                }
                if sol.is_none() && ray.is_none() && !bounded {
                    // The HiGHS sequence of recession programs (warm primal simplex).
                    out.solves += 1;
                    out.ray_programs += 1;
                    let ray_seq = match &mut ray_sequence {
                        Some(r) => r,
                        None => {
                            let mut r = lp::sequence::Sequence::new(
                                lp::sequence::recession_program(&base.lp),
                                solver,
                            )?;
                            r.limit_warm_iterations(Some(warm_limit(&base.lp)));
                            ray_sequence.insert(r)
                        }
                    };
                    ray_seq.set_objective(&cost, direction)?;
                    let _kind = lp::ProgramKind::set(RAYS, "");
                    let d = ray_seq.solve()?;
                    let cert = (d.status == LpStatus::Optimal)
                        .then(|| lp::sequence::certify_ray(&program, &d.x));
                    trace(
                        format_args!(
                            "range {side}: recession program {:?} by {}, ray {:?}",
                            d.status,
                            d.method.name(),
                            cert
                        ),
                        t0,
                    );
                    if let Some(cert) = cert.filter(|c| c.ok()) {
                        ray = Some((d.x, cert.violation));
                    }
                }
                if let Some((d, violation)) = ray {
                    if feasible_point.is_none() {
                        // The ray needs a feasible point to start from.
                        out.solves += 1;
                        let mut p = program.clone();
                        p.cost.iter_mut().for_each(|v| *v = 0.0);
                        let _kind = lp::ProgramKind::set(
                            "a ray's starting point",
                            "the dual simplex finds the admissible state a ray starts from",
                        );
                        let f = lp::solve(
                            &p,
                            &SolverOptions {
                                method: lp::Method::DualSimplex,
                                ..*solver
                            },
                        )?;
                        if f.status != LpStatus::Optimal
                            || p.relative_violation(&f.x) > lp::sequence::CERTIFICATE_TOLERANCE
                        {
                            return Err(Error::Request(
                                "the structure does not stand: its reactions have no range".into(),
                            ));
                        }
                        feasible_point = Some(f.x);
                    }
                    out.unbounded += 1;
                    out.worst_ray = out.worst_ray.max(violation);
                    ends[s][c][e] = None;
                    trace(format_args!("range {side}: unbounded, ray certified"), t0);
                    // Kept for later sides, and its opposite where that is a ray too (a
                    // self-equilibrated shear: no normal force along it).
                    let opposite: Vec<f64> = d.iter().map(|v| -v).collect();
                    let back = lp::sequence::ray_violation(&base.lp, &opposite);
                    for mi in &symmetries {
                        let image = mi.columns(&d);
                        let v = lp::sequence::ray_violation(&base.lp, &image);
                        if v <= lp::sequence::CERTIFICATE_TOLERANCE {
                            rays.push((image, v));
                        }
                    }
                    rays.push((d, violation));
                    if back <= lp::sequence::CERTIFICATE_TOLERANCE {
                        rays.push((opposite, back));
                    }
                    continue;
                }
                let sol = match sol {
                    Some(sol) => sol,
                    None => {
                        // Bounded, and the warm runs did not certify it: from scratch by
                        // the methods not tried yet ([`SCRATCH_METHODS`]).
                        if let Some(seq) = sequence.as_mut() {
                            seq.restart_from_optimal();
                        }
                        end_from_scratch(
                            &program,
                            solver,
                            scratch,
                            Chain::WithFallback,
                            &mut out.solves,
                            (&side, "", t0),
                        )
                        .expect("two methods tried")?
                    }
                };
                trace(
                    format_args!(
                        "range {side}: {:?} {} by {}",
                        sol.status,
                        sol.objective,
                        sol.method.name()
                    ),
                    t0,
                );
                if sol.status == LpStatus::Optimal {
                    for mi in &symmetries {
                        let s2 = mi.support[s];
                        if s2 > s || (s2 == s && e == 0) {
                            let (cn2, ct2) = &coefficients[s2][c];
                            if let Some((flipped, m)) = mi.optimum(&sol, &cost, &cost_of(cn2, ct2))
                            {
                                mirrored
                                    .entry((s2, c, if flipped { 1 - e } else { e }))
                                    .or_insert(m);
                            }
                        }
                    }
                }
                ends[s][c][e] = match sol.status {
                    LpStatus::Optimal => {
                        let cert = lp::sequence::certify(&program, &sol).ok_or_else(|| {
                            Error::Solver(
                                "a reaction range's optimum came without its duals".into(),
                            )
                        })?;
                        out.worst.primal = out.worst.primal.max(cert.primal);
                        out.worst.dual = out.worst.dual.max(cert.dual);
                        out.worst.gap = out.worst.gap.max(cert.gap);
                        if feasible_point.is_none() {
                            feasible_point = Some(sol.x.clone());
                        }
                        Some(sol.objective)
                    }
                    LpStatus::Unbounded => {
                        return Err(Error::Solver(format!(
                            "support {} {}: the solver says the {} is unbounded, but no ray certifies it",
                            st.support_name(s),
                            labels[c],
                            if e == 0 { "minimum" } else { "maximum" }
                        )))
                    }
                    LpStatus::Infeasible => {
                        return Err(Error::Request(
                            "the structure does not stand: its reactions have no range".into(),
                        ))
                    }
                };
            }
        }
    }
    if let Some(seq) = &sequence {
        out.warm = seq.stats.warm;
        out.restarts = seq.stats.restarts;
    }
    if !out.certified() {
        return Err(Error::Solver(format!(
            "the reaction ranges could not be certified (relative primal violation {:.1e}, dual violation {:.1e}, duality gap {:.1e}, ray violation {:.1e})",
            out.worst.primal, out.worst.dual, out.worst.gap, out.worst_ray
        )));
    }
    out.ranges = coefficients
        .iter()
        .enumerate()
        .map(|(s, comps)| AdmissibleReactionRange {
            support: st.support_name(s).to_string(),
            components: (0..comps.len())
                .map(|c| ComponentRange {
                    component: labels[c].to_string(),
                    min: ends[s][c][0],
                    max: ends[s][c][1],
                })
                .collect(),
        })
        .collect();
    Ok(out)
}

/// The safety assessment of `st`: whether it stands, its geometric safety factor and the
/// ranges of its support reactions.
pub fn safety<S: Assembly>(st: &S, opts: &SafetyOptions) -> Result<SafetyResult> {
    let kind = lp::ProgramKind::set("bisection", "");
    let decisions = opts.decisions.as_ref().unwrap_or(&opts.solver);
    let (fraction, mut solves, start) = bisect_fraction(st, opts.tolerance, decisions)?;
    drop(kind);
    let stands = fraction.is_some();
    let factor = fraction.and_then(|f| (f > 0.0).then_some(1.0 / f));
    let (reactions, by_symmetry) = if stands && opts.reactions {
        let _kind = lp::ProgramKind::set("reaction ranges", "");
        let r = ranges_from(st, &opts.solver, RangeSolve::Sequence, start)?;
        solves += r.solves;
        (r.ranges, r.mirrored)
    } else {
        (vec![], 0)
    };
    let message = match (stands, factor) {
        (false, _) => {
            "the structure cannot carry its dead loads: no equilibrium state exists".to_string()
        }
        (true, Some(g)) => format!(
            "the structure stands; geometric safety factor {g:.4} (its dead loads can be carried through the middle {:.2} % of every joint)",
            100.0 / g
        ),
        (true, None) => "the structure stands with every joint shrunk to its centre: the geometric safety factor is unbounded".to_string(),
    };
    Ok(SafetyResult {
        stands,
        message,
        solver: opts.solver.info(),
        geometric_safety_factor: factor,
        least_joint_fraction: fraction,
        tolerance: opts.tolerance,
        reactions,
        solves,
        reaction_ends_by_symmetry: by_symmetry,
        answered: vec![],
    })
}

/// The least thickness at which the structure `build(t)` stands, by bisection on `t` in
/// `[lo, hi]` to the absolute tolerance `tolerance`: it must not stand at `lo` and must stand
/// at `hi`. `build` is any generator with its other parameters fixed, e.g.
/// `|t| Structure::new(&arch(&ArchSpec { thickness: t, ..spec })?, BuildOptions::default())`.
/// Secant steps on the elastic program's least violations shorten the bisection to the same
/// answer, as in [`least_joint_fraction`] (every thickness asked about is a node of the
/// bisection's tree, computed by the same halvings).
pub fn least_thickness<S: Assembly>(
    build: impl Fn(f64) -> Result<S>,
    lo: f64,
    hi: f64,
    tolerance: f64,
    solver: &SolverOptions,
) -> Result<LeastThickness> {
    least_thickness_by(
        build,
        lo,
        hi,
        tolerance,
        solver,
        FractionSearch {
            secant: true,
            elastic: false,
        },
    )
}

/// [`least_thickness`] with the search chosen (for tests, as [`least_joint_fraction_by`]).
#[doc(hidden)]
pub fn least_thickness_by<S: Assembly>(
    build: impl Fn(f64) -> Result<S>,
    lo: f64,
    hi: f64,
    tolerance: f64,
    solver: &SolverOptions,
    search: FractionSearch,
) -> Result<LeastThickness> {
    if !(lo.is_finite() && hi.is_finite() && 0.0 < lo && lo < hi) {
        return Err(Error::Request(format!(
            "thickness bracket [{lo}, {hi}]: needs 0 < lo < hi"
        )));
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(Error::Request(format!(
            "tolerance {tolerance}: must be a finite number > 0"
        )));
    }
    let mut d = Decisions::new(solver);
    let elastic = search.elastic;
    // The lower thickness, which must not stand: in 3D by the elastic program directly. Its
    // decision by the requested method (in 3D HiGHS's interior point) would say "infeasible",
    // which only the dual simplex's proof decides, and go to the elastic program anyway (on the
    // 24 × 24 dome 17 s of a 146 s run's wall clock for nothing); the sequence's first program
    // is then the upper thickness's, whose basis the warm decisions start from. In 2D (the dual
    // simplex, whose "infeasible" is a proof) as before.
    let at_lo = if <S::D as Dim>::N == 3 {
        let st = build(lo)?;
        let mut e = Decisions::new(solver);
        e.warm_failed = true;
        let stands = e.stands(&KinematicMap::new(&st), &st.load_vector(false))?;
        (stands, e.last_violation)
    } else {
        let st = build(lo)?;
        let stands = d.stands(&KinematicMap::new(&st), &st.load_vector(false))?;
        (stands, d.last_violation)
    };
    // Whether it stands at `t`, and the least violation where the elastic program said not.
    let mut at = |t: f64| -> Result<(bool, Option<f64>)> {
        let st = build(t)?;
        if elastic && d.solves > 0 {
            d.warm_failed = true;
        }
        let stands = d.stands(&KinematicMap::new(&st), &st.load_vector(false))?;
        Ok((stands, d.last_violation))
    };
    if at_lo.0 {
        return Err(Error::Request(format!(
            "the structure already stands at the lower thickness {lo}: give a smaller one"
        )));
    }
    if !at(hi)?.0 {
        return Err(Error::Request(format!(
            "the structure does not stand at the upper thickness {hi}: give a larger one"
        )));
    }
    // The bisection on `[lo, hi]`, with the secant steps of [`search_fraction`] on the
    // elastic program's least violations: every thickness asked about is a node of the
    // bisection's tree (`node`: computed by the halvings the bisection would take to it, so
    // the same number bit for bit), and the search ends with the bisection's last bracket.
    let depth = {
        let (mut w, mut m) = (hi - lo, 0u32);
        while w > tolerance && m < 60 {
            w *= 0.5;
            m += 1;
        }
        m
    };
    let top = 1u64 << depth;
    let node = |k: u64| -> f64 {
        let (mut a, mut b, mut ia, mut ib) = (lo, hi, 0u64, top);
        if k == 0 {
            return lo;
        }
        if k == top {
            return hi;
        }
        loop {
            let im = ia + (ib - ia) / 2;
            let m = 0.5 * (a + b);
            if k == im || ib - ia < 2 {
                return m;
            }
            if k < im {
                (ib, b) = (im, m);
            } else {
                (ia, a) = (im, m);
            }
        }
    };
    let (mut a, mut b) = (lo, hi);
    let (mut ka, mut kb) = (0u64, top);
    let mut steps = 0;
    // The thicknesses at which it did not stand, with their least violations.
    let mut below: Vec<(f64, f64)> = at_lo.1.map(|v| (lo, v)).into_iter().collect();
    let mut secant_ok = true;
    let mut probe: Option<u64> = None;
    while b - a > tolerance && kb - ka >= 2 {
        let width = kb - ka;
        let probing = probe.take().filter(|&k| k > ka && k < kb);
        let step = probing.or_else(|| {
            if !search.secant || !secant_ok {
                return None;
            }
            let [.., (t1, v1), (t2, v2)] = below[..] else {
                return None;
            };
            let usable = t2 == a && t1 < t2 && v2 > 0.0 && v1 > v2;
            if !usable {
                return None;
            }
            let g = t2 + v2 * (t2 - t1) / (v1 - v2);
            if !(g.is_finite() && g < b) {
                return None;
            }
            let k = ((g - lo) / (hi - lo) * top as f64).ceil();
            let k = if k.is_finite() { k.max(0.0) as u64 } else { kb };
            Some(k.clamp(ka + 1, kb - 1))
        });
        let k = step.unwrap_or(ka + width / 2);
        let mid = node(k);
        steps += 1;
        let (stands, violation) = at(mid)?;
        if stands {
            (b, kb) = (mid, k);
            if step.is_some() && probing.is_none() {
                probe = Some(k - 1);
            }
        } else {
            (a, ka) = (mid, k);
            if let Some(v) = violation {
                below.push((mid, v));
            }
        }
        secant_ok = step.is_none() || (probing.is_none() && kb - ka <= width / 2);
    }
    Ok(LeastThickness {
        thickness: b,
        below: a,
        tolerance,
        steps,
    })
}
