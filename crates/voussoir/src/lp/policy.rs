//! The solver policy, in one place (issue 29 items 1 and 2): which method solves a program when
//! the user names none ([`default_method`], by dimension, size and purpose, from the
//! measurements of docs/performance.md, "Solver policy (session 11)" and "Solver policy by
//! purpose (session 15)"), and when an answer counts as one ([`check`]): the fallback
//! chain of [`super::fallback_chain`] moves on not only where a method fails, but also where it
//! ends at a point that is not certified as optimal (primal rows violated, or a duality gap)
//! beyond [`CERTIFICATE_TOLERANCE`].

use super::{LinearProgram, LpSolution, LpStatus, Method};

/// What the program is for: the sense in which it is solved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    /// An optimisation whose optimal value and duals are the result (limit, settle, capacity,
    /// tilt).
    Optimise,
    /// A yes/no feasibility question (does it stand; the bisections of `safety` and
    /// `least-thickness`).
    Feasibility,
    /// A stage of the canonical selection (re-optimisation over the optimal face).
    CanonicalStage,
    /// An iterate of the non-associative friction iteration (a sequence of LPs whose solutions
    /// must move smoothly from one iterate to the next).
    Iteration,
    /// A curve: a sequence of optimisations of one shape whose coefficients change a little
    /// from one to the next (`capacity`'s limit analyses on the settled geometries), each
    /// warm-started from the basis of the one before where the method keeps one.
    Curve,
}

/// The class of a program, as far as the choice of method goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ProblemClass {
    /// 2 or 3.
    pub dim: u8,
    /// Blocks of the structure (0: not known).
    pub blocks: usize,
    /// Frictional joints (Coulomb; the friction rows or pyramid facets).
    pub friction: bool,
    /// Second-order cones (exact crushing or friction cone): only Clarabel takes them.
    pub cones: bool,
    pub purpose: Purpose,
}

impl ProblemClass {
    /// An optimisation of a `dim`-dimensional structure of unknown size, without friction or
    /// cones.
    pub fn of_dim(dim: u8) -> Self {
        ProblemClass {
            dim,
            blocks: 0,
            friction: false,
            cones: false,
            purpose: Purpose::Optimise,
        }
    }
}

/// The class of the programs of structure `st` (dimension, blocks, friction; no cones).
pub fn class_of<S: crate::structure::Assembly>(st: &S, purpose: Purpose) -> ProblemClass {
    use crate::dim::Dim;
    ProblemClass {
        dim: if <S::D as Dim>::DOFS == 3 { 2 } else { 3 },
        blocks: st.num_blocks(),
        friction: st.contact_joints().iter().any(|j| j.law.friction.is_some()),
        cones: false,
        purpose,
    }
}

/// The solver options of a program of `class`: with a method named (`named`), that method;
/// else [`default_method`]. `base` gives the other settings (log, tolerances). An iterate of the
/// non-associative iteration without a named method is solved to a tighter tolerance (1e-10),
/// so that every iterate is certified.
pub fn options(
    class: &ProblemClass,
    named: Option<Method>,
    base: &super::SolverOptions,
) -> super::SolverOptions {
    match named {
        Some(method) => super::SolverOptions { method, ..*base },
        None if class.purpose == Purpose::Iteration => super::SolverOptions {
            method: default_method(class),
            feasibility_tolerance: base.feasibility_tolerance.min(1e-10),
            ..*base
        },
        None => super::SolverOptions {
            method: default_method(class),
            infeasibility_first: infeasibility_first(class),
            ..*base
        },
    }
}

/// Whether an optimisation of `class` by the policy's method first asks Clarabel whether its
/// program has any feasible point (`SolverOptions::infeasibility_first`, read by
/// `analysis::limit`): a 2D program with Coulomb friction above [`SIMPLEX_MAX_BLOCKS_2D`]
/// blocks. HiGHS's interior point is slow to prove such a program infeasible (the 0.5 m grid
/// façade with μ = 0.6, tilted: 38 iterations, 24.6 s, then Clarabel's certificate 5.3 s;
/// `tilt` 36.1 CPU s), where Clarabel's look at the zero-objective program takes about a
/// second either way (docs/performance.md, "Frictional façades: the least multiplier and the
/// mirror (session 30)"). Never where the user names a method: then that method answers.
pub fn infeasibility_first(class: &ProblemClass) -> bool {
    class.purpose == Purpose::Optimise && large_frictional_2d(class)
}

/// A 2D program with Coulomb friction rows and no cones above [`SIMPLEX_MAX_BLOCKS_2D`]
/// blocks: the class on which HiGHS's interior point is slow (IPX on the frictional rows) and
/// Clarabel answers yes/no questions in about a second ([`infeasibility_first`],
/// [`decision_method`]).
fn large_frictional_2d(class: &ProblemClass) -> bool {
    class.dim == 2 && class.friction && !class.cones && class.blocks > SIMPLEX_MAX_BLOCKS_2D
}

/// The solver options for structure `st` when the user named no method (`method_named`
/// false): `opts` with the method of [`default_method`] for the structure's class; with a
/// method named, `opts` unchanged.
pub fn options_for<S: crate::structure::Assembly>(
    st: &S,
    opts: &super::SolverOptions,
    method_named: bool,
) -> super::SolverOptions {
    options(
        &class_of(st, Purpose::Optimise),
        method_named.then_some(opts.method),
        opts,
    )
}

/// The largest 2D model the dual simplex solves by default; above it HiGHS's interior point
/// with crossover (docs/performance.md, "Solver policy (session 12)").
pub const SIMPLEX_MAX_BLOCKS_2D: usize = 2_000;

/// The largest 2D model with frictional joints the dual simplex solves by default; above it
/// HiGHS's interior point with crossover (docs/performance.md, "Frictional 2D programs
/// (session 15)"): every Coulomb point adds two rows, on which the simplex pivots for minutes
/// (a 60 × 30 wall, 1,815 blocks, μ = 0.6: `settle --raw` 349.5 CPU s, against 68.8 with the
/// interior point and 49.1 with Clarabel). At 205 blocks the two take about a second each.
pub const FRICTION_SIMPLEX_MAX_BLOCKS_2D: usize = 300;

/// The largest 3D model whose capacity curve ([`Purpose::Curve`]) the dual simplex solves by
/// default; above it Clarabel (docs/performance.md, "Solver policy by purpose (session 15)":
/// measured at 113 and 192 blocks (dual simplex fastest) and 553 (its first program alone over
/// 59 CPU s); the boundary between is not measured).
pub const CURVE_SIMPLEX_MAX_BLOCKS_3D: usize = 300;

/// The method of a capacity curve's step ([`Purpose::Curve`]) whose program has the open
/// points of the step before — the steps after the first settled one, whose programs differ
/// only in their coefficients — warm from that step's basis, where the user named no method;
/// `None`: every step by [`default_method`]. A 2D curve above [`SIMPLEX_MAX_BLOCKS_2D`]
/// without friction or cones: the dual simplex (its first program and the first settled one
/// stay with [`default_method`], HiGHS's interior point with crossover, whose vertex starts the
/// next). At or below the bound the dual simplex already solves every step warm
/// ([`default_method`]); 3D curves are the 3D rows' (not changed here).
///
/// Measured on the 0.5 m façade in running bond (2,672 blocks, `capacity --steps 20
/// --profile uniform:11,22,-0.2`; docs/performance.md, "Façade capacity curves (session
/// 20)"): a step by the interior point from scratch 8.4–25 CPU s, the same step by the warm dual
/// simplex about 1.4 CPU s (0 or 1 iterations: the basis of the step before stays optimal),
/// λ equal to 1e-11 relative.
pub fn curve_warm_method(class: &ProblemClass) -> Option<Method> {
    (class.purpose == Purpose::Curve
        && class.dim == 2
        && class.blocks > SIMPLEX_MAX_BLOCKS_2D
        && !class.friction
        && !class.cones)
        .then_some(Method::DualSimplex)
}

/// The smallest 2D force program (columns) whose least-μ bisection asks its trials as bounded
/// elastic programs (`analysis::canonical`) once Clarabel has proved one trial infeasible in
/// more than [`ELASTIC_SWITCH_ITERATIONS`] iterations. Clarabel's proof that a nearly feasible
/// trial is infeasible is its slow case: on the 0.5 m façade in running bond (2,672 blocks,
/// 30,640 columns) 83–101 iterations and 8.5–10.5 s each against 23–37 iterations for a
/// feasible trial, where the elastic program took 26–39. Small programs keep the feasibility
/// trials, which decide in a second, and their results as before (docs/performance.md
/// "Least-μ trials as elastic programs (session 21)").
pub const ELASTIC_TRIAL_MIN_COLUMNS: usize = 20_000;

/// Clarabel's iterations on an infeasible trial above which the least-μ bisection of a large
/// 2D program turns to elastic trials. From the first trial on, they cost the 3,200-block
/// stack-bond wall more than they saved (its infeasible trials took 9, 23 and 80 iterations,
/// 0.9–7.3 s; the elastic trials at the same θ 45, 41 and 129): the switch waits for a trial
/// that shows the slow case. Since session 29 an armed trial is run to at most this many
/// iterations: one that reaches them is that slow case, asked again at once as an elastic
/// trial instead of being run to its end (the 0.5 m façade in running bond's trial at μ = 2:
/// 101 iterations, 9.4 s; capped, 5.3 s and its elastic trial 2.0 s; docs/performance.md "The
/// force stage's trials in the size class (session 29)").
pub const ELASTIC_SWITCH_ITERATIONS: i64 = 50;

/// The smallest force program (columns; 2D or 3D) whose least-μ search stops above masonry's
/// friction where no precision is asked for (`CanonicalOptions::friction_search_limit`,
/// docs/canonical.md "The forces"): about 1,800 blocks in 2D, where the bisection above μ = 2
/// cost the stack-bond walls and the façades most of their `settle` (the 1,800-block wall:
/// 21.7 CPU s against 5.7 with the limit; the 3,200-block one 55.0 against 16.5). Below it
/// the search costs seconds and goes on to its precision: there the field at the first
/// admissible μ above 2 made the reaction ranges slower, not faster (a 300-block stack-bond
/// wall: 48.6 CPU s against 23.4 without the limit; docs/performance.md "The least μ above
/// masonry's friction (session 28)").
pub const FRICTION_LIMIT_MIN_COLUMNS: usize = 20_000;

/// Whether the least-μ bisection of a 2D force program of `columns` columns asks its trials
/// first as elastic programs.
pub fn elastic_trials(columns: usize) -> bool {
    columns >= ELASTIC_TRIAL_MIN_COLUMNS
}

/// The method of the bisection's decisions (`safety`: does the structure stand with its joints
/// shrunk to a fraction `f`) where it differs from the class's own ([`default_method`], which
/// also solves the reaction ranges after them): `None` but for a 2D program with Coulomb
/// friction above [`SIMPLEX_MAX_BLOCKS_2D`] blocks, whose decisions go to Clarabel. A decision
/// needs no vertex: "stands" is checked on the program itself and "does not stand" decided
/// again by the elastic program with a certificate (`analysis::safety::Decisions`), whatever
/// the method. Measured (docs/performance.md, "Frictional façades: the least multiplier and
/// the mirror (session 30)"):
///
/// | model (μ = 0.6) | HiGHS's interior point with crossover | Clarabel |
/// |---|---:|---:|
/// | 0.5 m running-bond façade (2,672 blocks), f = 1, stands | 87.7 s wall (IPX 26 iterations, 63 s; crossover 11,598 iterations) | 1.3 s (10 iterations) |
/// | 0.25 m grid façade (10,062 blocks), f = 1, does not stand | 214 s wall ("infeasible" after 25 iterations), then Clarabel's elastic program 28.7 s | 4.1 s ("infeasible", 17 iterations), then the same elastic program 32.3 s |
///
/// The ranges keep the class's method: without the decisions' basis their first program is
/// solved from scratch by it.
pub fn decision_method(class: &ProblemClass) -> Option<Method> {
    (class.purpose == Purpose::Feasibility && large_frictional_2d(class))
        .then_some(Method::Clarabel)
}

/// Whether the least load multiplier's program of a limit analysis (`analysis::limit`: the
/// limit program minimised, to check that the structure stands under its dead loads alone),
/// after HiGHS's interior point with crossover answered the largest, asks Clarabel alone
/// first, before the primal simplex from the crossover's basis: a `dim`-dimensional program of
/// `columns` columns, with associative Coulomb friction or not. Only its optimal value is
/// read, which needs no vertex; Clarabel's answer is used where the solver layer certifies it
/// and it is clear of zero, else the warm primal simplex answers.
///
/// | class | measured | chosen |
/// |---|---|---|
/// | 3D, ≥ 20,000 columns | 48 × 48 dome: the warm primal simplex over 10,000 iterations, about as long as the interior point; Clarabel about 5 CPU s (docs/performance.md, "Dome 48 × 48 (session 20)") | Clarabel first |
/// | 2D with friction, ≥ 20,000 columns | 0.5 m running-bond façade, μ = 0.6, tilted (30,641 columns): the warm primal simplex 90,774 iterations, 325 s of wall clock (docs/performance.md, "Frictional façades: the least multiplier and the mirror (session 30)") | Clarabel first |
/// | 2D without friction | 0.5 m grid façade (20,993 columns): Clarabel did not certify and its fallback chain solved the program again from scratch, `limit` 10.1 → 32.6 CPU s (session 20); the warm primal simplex 80 iterations on the running bond | the warm primal simplex |
pub fn least_multiplier_by_clarabel(dim: u8, friction: bool, columns: usize) -> bool {
    columns >= super::clarabel::PRESOLVE_MIN_COLUMNS && (dim == 3 || friction)
}

/// Degrees of freedom above which the canonical selection's extremes from scratch (the least
/// and largest value of a generic functional on a face, solved by the dual simplex with
/// presolve) go to HiGHS's interior point with crossover, not to the primal simplex, where the
/// dual simplex's answer is not certified: the 0.5 m grid façade's `tilt` (7,962 degrees of
/// freedom), whose maximum the dual simplex ended "not certified (row violation 2.5e-2)": the
/// primal simplex from scratch then took 8,599 iterations, 103 s of the 135 s wall clock
/// (89.8 CPU s), where the interior point answers either extreme in 18–20 s wall, the same
/// vertex (docs/performance.md, "The realistic benchmark (session 18)"). 2,000 blocks in 2D,
/// the size above which the interior point is already the default ([`SIMPLEX_MAX_BLOCKS_2D`]).
pub const EXTREMES_INTERIOR_FALLBACK_MIN_DOFS: usize = 3 * SIMPLEX_MAX_BLOCKS_2D;

/// The method that answers a canonical selection's extreme from scratch on a program of `dofs`
/// degrees of freedom after the dual simplex did not certify one: HiGHS's interior point with
/// crossover above [`EXTREMES_INTERIOR_FALLBACK_MIN_DOFS`] (then its own fallback chain),
/// else `None`: the dual simplex's own chain (the primal simplex next).
pub fn extremes_fallback(dofs: usize) -> Option<Method> {
    (dofs > EXTREMES_INTERIOR_FALLBACK_MIN_DOFS).then_some(Method::Ipm)
}

/// The method used when the user names none: the one that measured fastest and certified in
/// each class (docs/performance.md, "Solver policy (session 12)", every row measured on the
/// 2-core machine):
///
/// | class | method | why |
/// |---|---|---|
/// | cones | Clarabel | the only backend with cones |
/// | non-associative iterate | Clarabel | centres of optimal faces: the iteration converges (docs/joint-laws.md) |
/// | canonical stage | dual simplex | the stages need vertices and bases |
/// | 2D with friction, > 300 blocks (optimisations) | HiGHS IPM + crossover | 30 × 20 wall (610 blocks), μ = 0.6: `limit` 8.5 CPU s (dual simplex 34.9, Clarabel 0.7), `settle --raw` 7.1 (21.4, Clarabel 8.1 not certified: gap 2.2e-6); 60 × 30 wall: `settle --raw` 68.8 (349.5, 49.1); a vertex, certified |
/// | 2D with friction, > 2,000 blocks, limit programs | Clarabel looks for "no equilibrium" first ([`infeasibility_first`]), then this table's method | 0.5 m grid façade, μ = 0.6, `tilt`: 36.1 → 12.6 CPU s (cannot stand); the 0.5 m running bond, which stands: the look 1.65 s of 113 |
/// | 2D with friction, > 2,000 blocks, `safety`'s decisions | Clarabel ([`decision_method`]; the ranges keep this table's method) | 0.5 m running-bond façade, μ = 0.6: f = 1 in 1.3 s against the interior point's 87.7; 0.25 m grid façade: `safety` 239 → 40.7 CPU s |
/// | 2D, ≤ 2,000 blocks | dual simplex | vertex solutions (crisp hinges); as fast as any on these sizes |
/// | 2D capacity curve ([`Purpose::Curve`]), > 2,000 blocks, no friction | HiGHS IPM + crossover for the first program and the first settled one, then the dual simplex warm from step to step ([`curve_warm_method`]) | session 20: 0.5 m façade in running bond (2,672 blocks), 21 steps: 44.1 CPU s (every step by the IPM: step 0 4.4, step 1 8.4, step 2 about 25; a warm step about 1.4, 0 or 1 iterations), λ the same to 1e-11 |
/// | 2D, > 2,000 blocks | HiGHS IPM + crossover | 80 × 40 wall (3,220 blocks): `limit` 11.8 CPU s (dual simplex > 79, Clarabel not certified: duality gap 1.0, answered by the IPM after it), `settle --raw` 6.3 (dual simplex 8.0, Clarabel 8.5 with its fallback); a vertex |
/// | 3D capacity curve ([`Purpose::Curve`]), ≤ 300 blocks, no friction | dual simplex, warm from step to step | session 15: README vault 21 steps 1.3 CPU s (Clarabel 1.8, HiGHS IPM 6.5–62: it stalls on some settled geometries), README dome 1.2 (Clarabel 2.2, IPM 5.3); a vertex, as the IPM's crossover gives |
/// | 3D capacity curve, > 300 blocks or with friction | Clarabel | README vault, μ = 0.6, 5 steps: 11.4 CPU s (dual simplex 155.9); README dome, μ = 0.5, 10 steps: 14.2 (37.3); 24 × 24 dome (553 blocks): 23.7–35.6 CPU s; the dual simplex's first program alone > 59, the IPM's curve > 60, the IPM's first program then the warm dual simplex > 119 |
/// | 3D | HiGHS IPM + crossover (a vertex; Clarabel measured faster, see below) | vault `limit` 0.13 CPU s (dual simplex 0.53, IPM 1.16), `settle` 0.13 (0.51, 0.56); dome 12 × 24 `limit` 0.30 (IPM 1.33, dual simplex > 97); `safety` within 1.3× of the fastest; HiGHS's IPM failed ("HiGHS run failed: Error") on domes and stacks |
///
/// Measured in session 19 and not made a default: [`Method::ClarabelVertex`] (Clarabel, then
/// HiGHS's crossover from its duals: the IPM's vertex, the same λ and hinges) — `limit` of the
/// crowned 24 × 24 dome 2.81 CPU s (this table's 3D default 5.72), of the 48 × 48 dome 68.8
/// (197.9): faster, but over the 30 s target; and `tilt` and `settle` of the 24 × 24 dome,
/// whose canonical selection goes on from the vertex, slower (`tilt` 33.9 against 7.7,
/// `settle` 18.3 against 13.9)
/// (docs/performance.md, "Clarabel with crossover (session 19)"). Session 20 (docs/performance.md,
/// "Dome 48 × 48 (session 20)"): before HiGHS's interior point and the crossover of
/// [`Method::ClarabelVertex`] the free columns that others span are left out
/// ([`super::free_columns`]: a joint's shears span three directions), and after HiGHS's
/// interior point a large program's least multiplier goes to Clarabel; the table is unchanged
/// (the 48 × 48 dome's `limit`: default 173.6 → 84.7 CPU s side by side, `clarabel-vertex`
/// 51.6, both over the 30 s target, the same vertex).
///
/// Every method is followed by its [`super::fallback_chain`]: where it fails or ends
/// uncertified, the next method answers, and the result says so.
pub fn default_method(class: &ProblemClass) -> Method {
    if class.cones {
        return Method::Clarabel;
    }
    match (class.purpose, class.dim) {
        (Purpose::Iteration, _) => Method::Clarabel,
        (Purpose::CanonicalStage, _) => Method::DualSimplex,
        // Clarabel measured fastest on 3D programs (table above), but its answer is the centre
        // of the optimal face: where the optimum is not unique the mechanism mixes the optimal
        // ones (the README's vault: 15 hinged joints against the vertex's 12) and openings
        // come out at -1e-12 m, so the crack pattern changed with the method. Until the
        // canonical selection is on in 3D, the default stays a vertex: HiGHS's IPM with
        // crossover, followed by the fallback chain where it fails (docs/performance.md).
        // A 3D curve (capacity): the dual simplex, warm from step to step, up to
        // CURVE_SIMPLEX_MAX_BLOCKS_3D blocks (the README's vault's 21 steps: 1.3 CPU s, HiGHS's
        // IPM 6.5–62: it stalls on some settled geometries); above, Clarabel (the 24 × 24
        // dome: 36 CPU s; the dual simplex's first program alone took over 59, the IPM's
        // curve over 60, the IPM's first program then the warm dual simplex over 119).
        // With friction (the pyramid's facets add rows at every contact point) the dual simplex
        // pivots for tens of seconds on each step even on the README's models: measured in
        // session 19 (docs/performance.md, "3D curves with friction (session 19)"), the README
        // vault with μ = 0.6, 5 steps: 155.9 CPU s, Clarabel 11.4; the README dome with a crown
        // load and μ = 0.5, 10 steps: 37.3 against 14.2, the same λ to 1e-6 at every step.
        (Purpose::Curve, 3) if class.blocks <= CURVE_SIMPLEX_MAX_BLOCKS_3D && !class.friction => {
            Method::DualSimplex
        }
        (Purpose::Curve, 3) => Method::Clarabel,
        (_, 3) => Method::Ipm,
        _ if class.blocks > SIMPLEX_MAX_BLOCKS_2D => Method::Ipm,
        (Purpose::Optimise, _)
            if class.friction && class.blocks > FRICTION_SIMPLEX_MAX_BLOCKS_2D =>
        {
            Method::Ipm
        }
        _ => Method::DualSimplex,
    }
}

/// The feasibility tolerance of a settlement's second attempt with the same method, where the
/// two works of its LPs, each optimal to the default 1e-9, stay more than the settlement's
/// 1e-7 apart (`analysis::settlement`, and the canonical settlement's force program). Found on
/// a 205-block running-bond wall with μ = 2.0 settling near its least friction (work 0.036
/// kN·m, 2e-3 of W·u): every method's force LP at 1e-9 was 2e-8 to 1e-6 kN·m off the motion
/// LP's work (gaps 5e-6 to 2.7e-5), every one at 1e-10 within 6e-13 (docs/tolerances.md).
pub const RETRY_FEASIBILITY_TOLERANCE: f64 = 1e-10;

/// The tolerance of the solver layer's own certificate: the largest relative row violation
/// and the largest relative duality gap of an answer that counts as optimal (the analyses'
/// certificates use 1e-6 too, docs/tolerances.md).
pub const CERTIFICATE_TOLERANCE: f64 = 1e-6;

/// The solver layer's certificate of an optimal answer: its largest relative row or bound
/// violation, and the duality gap `|cᵀx − D(y, z)|` of the duals relative to the work scale
/// `Σ|c_j x_j| + Σ|dual terms|` (so that an optimum of exactly 0 is measured against the sizes
/// of the terms that cancel). `None` for statuses other than optimal and for solutions without
/// duals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LpCertificate {
    pub primal_violation: f64,
    pub gap: f64,
}

/// The certificate of `s` on `lp` (see [`LpCertificate`]).
pub fn certificate(lp: &LinearProgram, s: &LpSolution) -> Option<LpCertificate> {
    if s.status != LpStatus::Optimal
        || s.x.len() != lp.num_cols()
        || s.row_dual.len() != lp.num_rows()
        || s.col_dual.len() != lp.num_cols()
    {
        return None;
    }
    let primal_violation = violation(lp, &s.x);
    // HiGHS's convention (Clarabel's duals are returned in it): c − Aᵀy = z. For a
    // minimisation the dual value is Σ y_i·(L_i if y_i ≥ 0 else U_i) + Σ z_j·(l_j or u_j
    // alike); for a maximisation the signs turn.
    let sense = if lp.maximise { -1.0 } else { 1.0 };
    let mut scale = 0.0;
    let mut primal = 0.0;
    for (c, x) in lp.cost.iter().zip(&s.x) {
        primal += c * x;
        scale += (c * x).abs();
    }
    let cmax = lp.cost.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let mut dual = 0.0;
    // A dual on a side without a bound makes the dual value infinite: that dual must be round-off.
    let mut infeasible = 0.0f64;
    let mut term = |d: f64, lo: f64, hi: f64, x: f64| {
        let b = if sense * d >= 0.0 { lo } else { hi };
        if b.is_finite() {
            dual += d * b;
            scale += (d * b).abs();
        } else {
            infeasible = infeasible.max(d.abs());
            // It still prices the point where it is.
            dual += d * x;
        }
    };
    let act = lp.row_activity(&s.x);
    for i in 0..lp.num_rows() {
        term(s.row_dual[i], lp.row_lower[i], lp.row_upper[i], act[i]);
    }
    for j in 0..lp.num_cols() {
        term(s.col_dual[j], lp.col_lower[j], lp.col_upper[j], s.x[j]);
    }
    // An optimum of 0 (a settlement that needs no work) whose terms all vanish: the gap is
    // measured against the largest cost times the largest value instead (measured: Clarabel's
    // settlement of an 810-block wall, |cᵀx − D| = 1e-12 against terms of 1e-12, a "gap" of
    // 0.77 on the terms alone).
    let xmax = s.x.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let scale = scale.max(cmax * xmax).max(f64::MIN_POSITIVE);
    // A feasibility question (no cost): every feasible point is optimal, and there is no gap to
    // certify (measured: Clarabel's duals on `safety`'s programs of a dome, a "gap" of 0.45
    // between two meaningless numbers).
    if cmax == 0.0 {
        return Some(LpCertificate {
            primal_violation,
            gap: 0.0,
        });
    }
    let gap = ((primal - dual).abs() / scale).max(if cmax > 0.0 { infeasible / cmax } else { 0.0 });
    Some(LpCertificate {
        primal_violation,
        gap,
    })
}

/// The largest violation of a row or bound at `x`, relative to the program's scale: a row's
/// violation over the largest row size (`Σ_j |a_ij x_j|` or a finite bound) of the program, a
/// bound's over the largest column size — the scaled ∞-norm residual interior-point methods
/// are stopped on. Measuring each row on its own scale
/// (`LinearProgram::relative_violation`) rejects every interior-point answer with a residual
/// of 1e-10 of the loads on a row whose terms nearly vanish (measured: Clarabel's settlements
/// of the paper's arch, 1.8e-2; the vault's, 5.6e-2, whose analyses certify them).
pub fn violation(lp: &LinearProgram, x: &[f64]) -> f64 {
    let mut act = vec![0.0; lp.num_rows()];
    let mut size = vec![0.0; lp.num_rows()];
    for (j, &xj) in x.iter().enumerate() {
        for (i, v) in lp.column(j) {
            act[i] += v * xj;
            size[i] += (v * xj).abs();
        }
    }
    let finite = |b: f64| if b.is_finite() { b.abs() } else { 0.0 };
    let row_scale = (0..lp.num_rows())
        .map(|i| {
            size[i]
                .max(finite(lp.row_lower[i]))
                .max(finite(lp.row_upper[i]))
        })
        .fold(0.0, f64::max);
    let col_scale = (0..lp.num_cols())
        .map(|j| {
            x[j].abs()
                .max(finite(lp.col_lower[j]))
                .max(finite(lp.col_upper[j]))
        })
        .fold(0.0, f64::max);
    let over = |v: f64, lo: f64, hi: f64, s: f64| {
        let d = (lo - v).max(v - hi).max(0.0);
        if d == 0.0 {
            0.0
        } else if s > 0.0 {
            d / s
        } else {
            f64::INFINITY
        }
    };
    let rows = (0..lp.num_rows())
        .map(|i| over(act[i], lp.row_lower[i], lp.row_upper[i], row_scale))
        .fold(0.0f64, f64::max);
    (0..lp.num_cols())
        .map(|j| over(x[j], lp.col_lower[j], lp.col_upper[j], col_scale))
        .fold(rows, f64::max)
}

/// Why an answer does not count (`None`: it does): an optimal point whose certificate exceeds
/// [`CERTIFICATE_TOLERANCE`], or the backend's own reduced-accuracy stop.
pub fn check(lp: &LinearProgram, s: &LpSolution) -> Option<String> {
    let c = certificate(lp, s)?;
    if c.primal_violation > CERTIFICATE_TOLERANCE || c.gap > CERTIFICATE_TOLERANCE {
        return Some(format!(
            "not certified (row violation {:.1e}, duality gap {:.1e}{})",
            c.primal_violation,
            c.gap,
            if s.reduced_accuracy {
                ", reduced accuracy"
            } else {
                ""
            }
        ));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lp::{solve, Direction, SolverOptions};

    #[test]
    fn certificates_of_exact_answers_are_zero_and_of_a_perturbed_one_are_not() {
        // max x + y s.t. x + 2y ≤ 4, 3x + y ≤ 6 (by hand: 2.8 at (1.6, 1.2)), with each method.
        let mut lp = LinearProgram::new(Direction::Maximise);
        let r0 = lp.add_row(f64::NEG_INFINITY, 4.0);
        let r1 = lp.add_row(f64::NEG_INFINITY, 6.0);
        lp.add_column(1.0, 0.0, f64::INFINITY, [(r0, 1.0), (r1, 3.0)]);
        lp.add_column(1.0, 0.0, f64::INFINITY, [(r0, 2.0), (r1, 1.0)]);
        for method in [Method::DualSimplex, Method::Ipm, Method::Clarabel] {
            let o = SolverOptions {
                method,
                ..SolverOptions::default()
            };
            let s = solve(&lp, &o).unwrap();
            let c = certificate(&lp, &s).unwrap();
            assert!(
                c.gap < 1e-8 && c.primal_violation < 1e-8,
                "{method:?} {c:?}"
            );
            assert!(check(&lp, &s).is_none());
            // Duals halved: the dual value is 1.4, the gap 1.4 / 4.2 (scale 2.8 + 1.4).
            let mut bad = s.clone();
            bad.row_dual.iter_mut().for_each(|y| *y *= 0.5);
            let g = certificate(&lp, &bad).unwrap().gap;
            assert!((g - 1.4 / 4.2).abs() < 1e-6, "{method:?} {g}");
            assert!(check(&lp, &bad).is_some());
        }
        // min 2a + b, a + b = 1: the minimisation's convention.
        let mut lp = LinearProgram::new(Direction::Minimise);
        let r = lp.add_row(1.0, 1.0);
        lp.add_column(2.0, 0.0, f64::INFINITY, [(r, 1.0)]);
        lp.add_column(1.0, 0.0, f64::INFINITY, [(r, 1.0)]);
        let s = solve(&lp, &SolverOptions::default()).unwrap();
        assert!(certificate(&lp, &s).unwrap().gap < 1e-12);
    }

    #[test]
    fn the_policy_table() {
        let c = |dim, blocks| ProblemClass {
            blocks,
            ..ProblemClass::of_dim(dim)
        };
        assert_eq!(default_method(&c(2, 64)), Method::DualSimplex);
        assert_eq!(default_method(&c(2, 10_000)), Method::Ipm);
        assert_eq!(default_method(&c(3, 25)), Method::Ipm);
        let cones = ProblemClass {
            cones: true,
            ..c(2, 10)
        };
        assert_eq!(default_method(&cones), Method::Clarabel);
    }

    #[test]
    fn issue29_item1_policy_by_purpose_curves() {
        let curve = |dim, blocks, cones| ProblemClass {
            purpose: Purpose::Curve,
            cones,
            blocks,
            ..ProblemClass::of_dim(dim)
        };
        // 3D capacity curves: the dual simplex (warm from step to step) up to the bound,
        // Clarabel above it and wherever there are cones.
        assert_eq!(default_method(&curve(3, 192, false)), Method::DualSimplex);
        assert_eq!(
            default_method(&curve(3, CURVE_SIMPLEX_MAX_BLOCKS_3D, false)),
            Method::DualSimplex
        );
        assert_eq!(
            default_method(&curve(3, CURVE_SIMPLEX_MAX_BLOCKS_3D + 1, false)),
            Method::Clarabel
        );
        assert_eq!(default_method(&curve(3, 553, false)), Method::Clarabel);
        assert_eq!(default_method(&curve(3, 192, true)), Method::Clarabel);
        // With friction, Clarabel at every size (session 19: the README vault with μ = 0.6).
        let frictional = ProblemClass {
            friction: true,
            ..curve(3, 192, false)
        };
        assert_eq!(default_method(&frictional), Method::Clarabel);
        // 2D curves as 2D optimisations: the dual simplex up to 2,000 blocks, the IPM above
        // for the first program and the first settled one, and the warm dual simplex after.
        assert_eq!(default_method(&curve(2, 182, false)), Method::DualSimplex);
        assert_eq!(curve_warm_method(&curve(2, 182, false)), None);
        assert_eq!(default_method(&curve(2, 2_654, false)), Method::Ipm);
        assert_eq!(
            curve_warm_method(&curve(2, 2_654, false)),
            Some(Method::DualSimplex)
        );
        assert_eq!(curve_warm_method(&curve(2, 2_654, true)), None);
        assert_eq!(curve_warm_method(&curve(3, 192, false)), None);
        // A single 3D optimisation (limit, tilt) keeps the IPM with crossover (a vertex).
        let limit3 = ProblemClass {
            blocks: 553,
            ..ProblemClass::of_dim(3)
        };
        assert_eq!(default_method(&limit3), Method::Ipm);
    }
}
