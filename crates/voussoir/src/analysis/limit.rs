//! Classic limit analysis (the paper's Remark 3).
//!
//! Static: `max λ  s.t.  F_D + λ F_L + Nᵀ p_n + Tᵀ p_t = 0,  p_n ≥ 0`.
//! Kinematic (its dual, read from the equilibrium rows' duals): the collapse mechanism `d`,
//! normalised so that the live loads do unit work, `F_Lᵀ d = 1`; then `λ = −F_Dᵀ d`.

pub use super::laws::{check_facets, Crushing, DEFAULT_FACETS, MAX_FACETS, MIN_FACETS};
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::{self, LpSolution, LpStatus, SolverInfo, SolverOptions};
use crate::programs::{self, ForceProgram};
use crate::reporting::report;
pub use crate::result::limit::*;
use crate::structure::Assembly;

/// The raw vectors of a limit analysis, for the analyses built on top of it.
#[derive(Clone, Debug)]
pub struct LimitSolution {
    pub status: LimitStatus,
    pub lambda: Option<f64>,
    /// Mechanism (block DOFs), empty unless a collapse was found.
    pub mechanism: Vec<f64>,
    pub pn: Vec<f64>,
    pub pt: Vec<f64>,
    pub iterations: i64,
    /// The solver and method that produced it.
    pub solver: SolverInfo,
    /// The least multiplier in equilibrium (`None`: unbounded below, or not computed).
    pub least: Option<f64>,
    /// A sentence to add to the result's message (how the result was obtained, when not as
    /// asked), or empty.
    pub note: String,
    /// The solver stopped at reduced accuracy ([`LpSolution::reduced_accuracy`]).
    pub reduced_accuracy: bool,
    /// The optimal basis of the static program where the method left one (a simplex, or
    /// HiGHS's interior point with crossover): the canonical mechanism's kinematic program
    /// starts from its complementary basis ([`crate::duality::dual_basis`]).
    pub basis: Option<lp::Basis>,
}

/// Solve the static LP of `st` and read the mechanism from its duals.
pub fn solve_limit<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<LimitSolution> {
    Ok(solve_static(st, map, opts)?.0)
}

/// The static program of `st`, solved: the solution, the program, the optimal basis the
/// solve left where the method keeps one (a simplex, or HiGHS's interior point with
/// crossover), and the solver's answer where the solution is read from it unchanged (not
/// after a cleanup or a widening), for the least multiplier's program
/// ([`solve_limit_checked`]).
#[allow(clippy::type_complexity)]
fn solve_static<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<(LimitSolution, ForceProgram, Option<LpSolution>)> {
    let (dead, live) = load_vectors(st)?;
    let fp = programs::limit_force_program(map, &dead, &live);
    if opts.infeasibility_first && fp.cones.is_empty() && no_equilibrium_first(&fp, opts)? {
        let sol = LpSolution {
            status: LpStatus::Infeasible,
            objective: f64::NAN,
            x: vec![],
            row_dual: vec![],
            col_dual: vec![],
            iterations: 0,
            dual_objective: f64::NAN,
            reduced_accuracy: false,
            method: lp::Method::Clarabel,
            tried: vec![],
        };
        // Decided by Clarabel (the look and its elastic program): the result names it.
        let by = SolverOptions {
            method: lp::Method::Clarabel,
            ..*opts
        };
        let s = limit_solution(map, &fp, &live, &sol, by.info());
        return Ok((s, fp, None));
    }
    let mut basis = None;
    let sol = if fp.cones.is_empty() {
        lp::solve_warm(&fp.lp, opts, &mut basis)?
    } else {
        fp.solve(opts)?
    };
    if sol.status == LpStatus::Optimal && programs::crushing_cap_reached(map, &fp, &sol.x) {
        let (s, fp) = solve_widened(map, &dead, &live, opts)?;
        return Ok((s, fp, None));
    }
    let s = limit_solution(map, &fp, &live, &sol, opts.info());
    let mut c = cleaned_up(map, &fp, &dead, &live, s, &sol, opts);
    c.basis = basis;
    let raw = (c.lambda == sol.x.get(fp.lambda.unwrap_or(usize::MAX)).copied()).then_some(sol);
    Ok((c, fp, raw))
}

/// Whether the limit program `fp` has no feasible point, decided before the policy's method
/// runs ([`lp::policy::infeasibility_first`]): Clarabel on its zero-objective form, and where
/// that says "infeasible", the elastic program by Clarabel, which certifies it (a positive
/// least violation bounded by its duals). `false` wherever either does not say so: the
/// program then goes to the policy's method as before.
fn no_equilibrium_first(fp: &ForceProgram, opts: &SolverOptions) -> Result<bool> {
    let o = SolverOptions {
        method: lp::Method::Clarabel,
        infeasibility_first: false,
        decision: true,
        ..*opts
    };
    let t0 = std::time::Instant::now();
    let mut zero = fp.lp.clone();
    zero.cost.iter_mut().for_each(|c| *c = 0.0);
    let look = lp::solve_without_fallback(&zero, &o).map(|s| s.status);
    let mut decided = None;
    if matches!(look, Ok(LpStatus::Infeasible)) {
        // The no-equilibrium certificate's own first look: the elastic program by Clarabel.
        decided = no_equilibrium_certificate_by(fp, &o, &[lp::Method::Clarabel])?.map(|c| c.ok);
    }
    if std::env::var_os("VOUSSOIR_TRACE").is_some() {
        eprintln!(
            "trace: limit: infeasibility first by clarabel: {look:?}, certified infeasible {decided:?} {:.3} s",
            t0.elapsed().as_secs_f64()
        );
    }
    Ok(decided == Some(true))
}

/// The cleanup pass: when an interior point's collapse multiplier fails its certificate (or
/// the solver says it stopped at reduced accuracy), a primal simplex from that point's active
/// set ([`lp::crossover`]) to an optimal vertex, whose λ and mechanism [`limit_result`] then
/// certifies again. Where that fails, the uncertified result stays, with a note saying so.
fn cleaned_up(
    map: &KinematicMap,
    fp: &ForceProgram,
    dead: &[f64],
    live: &[f64],
    s: LimitSolution,
    sol: &LpSolution,
    opts: &SolverOptions,
) -> LimitSolution {
    if !opts.cleanup || !opts.method.is_interior() || !fp.cones.is_empty() {
        return s;
    }
    let (wd, wl) = load_works(&s.mechanism, dead, live);
    let unit = crate::scale::lambda_unit(map.dofs_per_block, dead, live);
    let failed = limit_certificate(map, &s, wd, wl, unit).is_some_and(|c| !c.ok);
    if !(failed || sol.reduced_accuracy) || s.status != LimitStatus::Collapse {
        return s;
    }
    match lp::run_crossover(&fp.lp, sol, opts) {
        Ok(vertex) => {
            let mut c = limit_solution(map, fp, live, &vertex, s.solver.clone());
            c.iterations += s.iterations;
            c.note = "cleaned up: a primal simplex from the interior point's active set to a vertex (crossover)".into();
            c
        }
        Err(e) => LimitSolution {
            note: format!("the cleanup pass failed: {e}"),
            ..s
        },
    }
}

/// The work of the dead and of the live loads on a mechanism (`None` without one).
fn load_works(mechanism: &[f64], dead: &[f64], live: &[f64]) -> (Option<f64>, Option<f64>) {
    if mechanism.is_empty() {
        return (None, None);
    }
    let work = |f: &[f64]| Some(f.iter().zip(mechanism).map(|(a, b)| a * b).sum::<f64>());
    (work(dead), work(live))
}

/// The static program again with crushing polygons reaching further (×64 each time, at last
/// to f_c·w·t), until no joint's force stops at the cap of its polygon: the polygons stay
/// where the forces are, however large these are against the loads' scale.
fn solve_widened(
    map: &KinematicMap,
    dead: &[f64],
    live: &[f64],
    opts: &SolverOptions,
) -> Result<(LimitSolution, ForceProgram)> {
    let mut m = map.clone();
    let mut round = 0;
    loop {
        round += 1;
        m.crushing_reach = if round < 8 {
            map.crushing_reach * 64f64.powi(round)
        } else {
            f64::INFINITY
        };
        let fp = programs::limit_force_program(&m, dead, live);
        let sol = fp.solve(opts)?;
        if m.crushing_reach == f64::INFINITY
            || sol.status != LpStatus::Optimal
            || !programs::crushing_cap_reached(&m, &fp, &sol.x)
        {
            return Ok((limit_solution(&m, &fp, live, &sol, opts.info()), fp));
        }
    }
}

/// [`solve_limit`] of a structure as given, with the check that it stands under its dead loads
/// alone ([`with_least_multiplier`]). The analyses that deform a structure along a settlement
/// or a mechanism (capacity, incremental) ask for the collapse multiplier only: a displaced
/// structure is routinely held by its live load there.
pub fn solve_limit_checked<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<LimitSolution> {
    let t0 = std::time::Instant::now();
    let (s, fp, largest) = solve_static(st, map, opts)?;
    let basis = s.basis.clone();
    let trace = std::env::var_os("VOUSSOIR_TRACE").is_some();
    if trace {
        eprintln!(
            "trace: limit: the largest multiplier ({} rows, {} columns) {:?} ({} iterations) {:.3} s",
            fp.lp.num_rows(),
            fp.lp.num_cols(),
            s.status,
            s.iterations,
            t0.elapsed().as_secs_f64()
        );
    }
    let t0 = std::time::Instant::now();
    let friction = map.shear_limits.is_none() && map.laws.iter().any(|l| l.friction.is_some());
    let lambda = fp.lambda.filter(|_| {
        lp::policy::least_multiplier_by_clarabel(
            <S::D as crate::dim::Dim>::N as u8,
            friction,
            fp.lp.num_cols(),
        )
    });
    // A structure symmetric about a vertical line under a horizontal live load (the tilting
    // table): the least multiplier is the mirror image of the largest's optimum, certified on
    // its own program, without solving it (safety::least_by_mirror; the 0.5 m grid façade's
    // `tilt`: about 6 CPU s, docs/performance.md "Façade tilt, safety and capacity (session
    // 25)"). Otherwise, or where the image does not certify, its program as before.
    let r = with_least_multiplier(s, &fp, |lp| {
        let image = largest
            .as_ref()
            .and_then(|l| super::safety::least_by_mirror(st, map, &fp, l, lp));
        if trace {
            eprintln!(
                "trace: limit: the least multiplier by the mirror image of the largest's optimum: {}",
                if image.is_some() { "certified" } else { "none" }
            );
        }
        match image {
            Some(m) => Ok(m),
            None => least_program(lp, opts, basis, lambda),
        }
    });
    if trace {
        eprintln!(
            "trace: limit: the least multiplier {:?} {:.3} s",
            r.as_ref().map(|s| (s.least, s.iterations)),
            t0.elapsed().as_secs_f64()
        );
    }
    r
}

/// Solve the least multiplier's program `lp` (the limit program minimised: only the objective
/// differs). After HiGHS's interior point with crossover (the 3D default) the optimal basis of
/// the largest multiplier's program is primal feasible for it, so the primal simplex goes on
/// from there instead of a second interior point from scratch: on the 48 × 48 dome (2,257
/// blocks) the second program took as long as the first in HiGHS's clock (about 1,470 s at load
/// 10–14), and 146 s from the basis; `limit` 224.3 → 197.9 CPU s (docs/performance.md, "Dome
/// 48 × 48 (session 17)"). With a simplex (the 2D default) or without a basis (Clarabel) the
/// program is solved as before, from scratch with the method asked for. After Clarabel with
/// crossover ([`lp::Method::ClarabelVertex`]) it goes to Clarabel alone: only its optimal value
/// is read, which needs no vertex, and on the 48 × 48 dome Clarabel answers it in about 5 CPU s
/// where the crossover from scratch took over 60 (docs/performance.md, "Clarabel with
/// crossover (session 19)").
///
/// A large program of the class [`lp::policy::least_multiplier_by_clarabel`] names (`lambda`
/// is `None` otherwise) after HiGHS's interior point goes to Clarabel alone first, as after
/// Clarabel with crossover. Where Clarabel's value is within [`LEAST_CLARABEL_MARGIN`] of
/// zero, or not certified, the warm primal simplex answers, exact to its tolerance.
fn least_program(
    lp: &lp::LinearProgram,
    opts: &SolverOptions,
    basis: Option<lp::Basis>,
    lambda: Option<usize>,
) -> Result<LpSolution> {
    let clarabel = SolverOptions {
        method: lp::Method::Clarabel,
        ..*opts
    };
    if opts.method == lp::Method::ClarabelVertex {
        return lp::solve(lp, &clarabel);
    }
    if let (Some(_), Some(j), lp::Method::Ipm) = (&basis, lambda, opts.method) {
        if lp.num_cols() >= LEAST_CLARABEL_MIN_COLUMNS {
            // Clarabel alone: where it fails or does not certify, the warm primal simplex
            // below (its fallback chain would go on to HiGHS's interior point from scratch).
            if let Ok(s) = lp::solve_without_fallback(lp, &clarabel) {
                let certified =
                    s.status != LpStatus::Optimal || lp::policy::check(lp, &s).is_none();
                let decided = s.status != LpStatus::Optimal
                    || s.x.get(j).is_some_and(|l| l.abs() > LEAST_CLARABEL_MARGIN);
                if certified && decided {
                    return Ok(s);
                }
            }
        }
    }
    match basis {
        Some(b) if !opts.method.is_simplex() => {
            let warm = SolverOptions {
                method: lp::Method::PrimalSimplex,
                ..*opts
            };
            // On the program without the second of each pair of twin columns (in 2D the two
            // shear forces of a joint: super::safety::Twins), its optimum expanded and
            // certified on the program itself; otherwise as before. The 0.5 m grid façade's
            // `tilt`: 20,993 → 15,745 columns (docs/performance.md, "0.5 m grid façade safety
            // and tilt (session 22)").
            if let Some(t) = super::safety::Twins::of(lp, &[]) {
                if b.cols.len() == lp.num_cols() && b.rows.len() == lp.num_rows() {
                    let mut rb = Some(t.basis(&b));
                    if let Ok(s) = lp::solve_warm(&t.program(lp), &warm, &mut rb) {
                        let s = t.solution(s);
                        if s.status == LpStatus::Optimal
                            && lp::sequence::certify(lp, &s).is_some_and(|c| c.ok())
                            && lp::policy::check(lp, &s).is_none()
                        {
                            return Ok(s);
                        }
                    }
                }
            }
            lp::solve_warm(lp, &warm, &mut Some(b))
        }
        _ => lp::solve(lp, opts),
    }
}

/// Statics that cannot lie: the multipliers in equilibrium form an interval `[λ_min, λ_max]`;
/// the structure stands under its dead loads alone only if 0 is in it. Having found `λ_max`
/// (or that it is unbounded), solve `min λ` on the same program: if `λ_min > 0` the structure
/// needs the live load to stand (a block overhanging its support, held by a push), and the
/// status is `no_equilibrium` with the range, never a collapse at `λ_max`.
fn with_least_multiplier(
    mut s: LimitSolution,
    fp: &ForceProgram,
    solve: impl FnOnce(&lp::LinearProgram) -> Result<LpSolution>,
) -> Result<LimitSolution> {
    if !matches!(s.status, LimitStatus::Collapse | LimitStatus::Locked) || !fp.cones.is_empty() {
        return Ok(s);
    }
    let mut lp = fp.lp.clone();
    lp.maximise = false;
    let least = solve(&lp)?;
    s.iterations += least.iterations;
    if least.status != LpStatus::Optimal {
        return Ok(s);
    }
    let lmin = least.x[fp.lambda.expect("program has λ")];
    s.least = Some(lmin);
    let scale = s.lambda.map_or(1.0, |l| l.abs().max(1.0));
    if lmin > LEAST_TOLERANCE * scale {
        s.status = LimitStatus::NoEquilibrium;
        s.mechanism.clear();
    }
    Ok(s)
}

/// Columns from which the least multiplier's program after HiGHS's interior point goes to
/// Clarabel ([`least_program`]): clarabel::PRESOLVE_MIN_COLUMNS, the size of a large program.
pub const LEAST_CLARABEL_MIN_COLUMNS: usize = lp::clarabel::PRESOLVE_MIN_COLUMNS;

/// A least multiplier from Clarabel within this of zero is decided again by the simplex.
pub const LEAST_CLARABEL_MARGIN: f64 = 1e-6;

/// Relative tolerance below which a positive least multiplier counts as zero.
pub const LEAST_TOLERANCE: f64 = 1e-9;

/// Dead and live load vectors; an error if there is no live load.
pub(crate) fn load_vectors<S: Assembly>(st: &S) -> Result<(Vec<f64>, Vec<f64>)> {
    if !st.has_live_loads() {
        return Err(Error::Request(
            "limit analysis needs live loads (the model has none)".into(),
        ));
    }
    Ok((st.load_vector(false), st.load_vector(true)))
}

/// Limit analysis with the exact crushing domain (second-order cones, Clarabel) instead of
/// its inscribed polygon. Without finite compressive strength this is the same problem.
///
/// The cone program is checked against an inscribed polygon of [`CHECK_FACETS`] facets
/// (HiGHS): the polygon's λ is a lower bound within its chord error (about 10⁻³ of the
/// crushing effect) of the exact λ. Where the interior-point method fails — the cone is nearly
/// flat where f_c is far above the joint stresses — or stops at a point that contradicts the
/// bound, the polygon's result is returned, and the message says so.
pub fn solve_limit_conic<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<LimitSolution> {
    let (dead, live) = load_vectors(st)?;
    let fp = programs::limit_force_program_exact(map, &dead, &live);
    let o = SolverOptions {
        feasibility_tolerance: opts.feasibility_tolerance.min(1e-10),
        ..*opts
    };
    let solver = crate::lp::SolverInfo {
        solver: crate::lp::cone_backend(&o).name().to_string(),
        method: crate::lp::Method::Clarabel,
        tried: Vec::new(),
    };
    // Crushing cones (2D) have a polygon to check them by; the 3D friction cones do not.
    let crushing = map.tangents_per_point == 1 && !fp.cones.is_empty();
    if !crushing {
        let sol = fp.solve(&o)?;
        return Ok(limit_solution(map, &fp, &live, &sol, solver));
    }
    let conic = fp
        .solve(&o)
        .map(|sol| limit_solution(map, &fp, &live, &sol, solver));
    let mut fine = map.clone();
    fine.facets = CHECK_FACETS;
    let (poly, _, _) = solve_static(st, &fine, opts)?;
    let why = match &conic {
        Err(e) => format!("the cone program failed ({e})"),
        Ok(c) => match (c.status, c.lambda, poly.status, poly.lambda) {
            (LimitStatus::Collapse, Some(lc), LimitStatus::Collapse, Some(lp)) => {
                let tol = 1e-6 * lp.abs().max(1e-300);
                if lc >= lp - tol && lc <= lp + 1e-3 * lp.abs() + tol {
                    String::new()
                } else {
                    format!("the cone program's λ = {lc:.6} contradicts the polygon's bound")
                }
            }
            // The polygon is inscribed: where it stands, the exact domain does too.
            (cs, _, LimitStatus::Collapse | LimitStatus::Locked, _)
                if cs != LimitStatus::Collapse && cs != poly.status =>
            {
                format!(
                    "the cone program's '{}' contradicts the polygon",
                    cs.sentence()
                )
            }
            _ => String::new(),
        },
    };
    match conic {
        Ok(c) if why.is_empty() => Ok(c),
        _ => Ok(LimitSolution {
            note: format!(
                "{why}: result of the inscribed polygon with {CHECK_FACETS} facets (a lower bound within about 1e-3 of the crushing effect)"
            ),
            ..poly
        }),
    }
}

/// Facets of the inscribed polygon that checks (and replaces, where the interior-point method
/// fails) the exact crushing cones.
pub const CHECK_FACETS: usize = 256;

/// λ, forces and the mechanism (duals of the equilibrium rows, normalised to unit live-load
/// work) from a solved force program.
pub fn limit_solution(
    map: &KinematicMap,
    fp: &ForceProgram,
    live: &[f64],
    sol: &LpSolution,
    solver: SolverInfo,
) -> LimitSolution {
    let (status, x, row_dual, iterations) = (sol.status, &sol.x, &sol.row_dual, sol.iterations);
    // The method that answered, where the requested one failed (lp::fallback_chain).
    let solver = if sol.tried.is_empty() {
        solver
    } else {
        sol.solver_info()
    };
    let none = |status| LimitSolution {
        status,
        lambda: None,
        mechanism: vec![],
        pn: vec![0.0; map.num_points()],
        pt: vec![0.0; map.num_tangent_rows()],
        iterations,
        solver: solver.clone(),
        least: None,
        note: String::new(),
        reduced_accuracy: sol.reduced_accuracy,
        basis: None,
    };
    match status {
        LpStatus::Unbounded => return none(LimitStatus::Locked),
        LpStatus::Infeasible => return none(LimitStatus::NoEquilibrium),
        LpStatus::Optimal => {}
    }
    let lambda = x[fp.lambda.expect("program has λ")];
    // A negative multiplier within round-off of zero is zero (crate::scale::LAMBDA_ZERO): the
    // structure stands with no reserve, as the exact answer says; only a clearly negative one
    // means that it cannot stand. A small positive λ (μ = 1e-9) is kept as it is.
    // fp.force_scale is the dead loads' (the live loads' when there are none: then 1).
    let unit = crate::scale::lambda_unit_of(
        fp.force_scale,
        crate::scale::force_scale(map.dofs_per_block, live),
    );
    let lambda = if lambda < 0.0 && -lambda <= crate::scale::LAMBDA_ZERO * unit {
        0.0
    } else {
        lambda
    };
    let (pn, pt) = fp.forces(x);
    let y = &row_dual[..map.num_dofs];
    let wl: f64 = live.iter().zip(y).map(|(a, b)| a * b).sum();
    let mechanism = if wl.abs() > 0.0 {
        y.iter().map(|v| v / wl).collect()
    } else {
        vec![0.0; y.len()]
    };
    LimitSolution {
        status: if lambda >= 0.0 {
            LimitStatus::Collapse
        } else {
            LimitStatus::NoEquilibrium
        },
        lambda: Some(lambda),
        mechanism,
        pn,
        pt,
        iterations,
        solver,
        least: None,
        note: String::new(),
        reduced_accuracy: sol.reduced_accuracy,
        basis: None,
    }
}

/// Limit analysis with a choice of crushing model and number of facets.
pub fn limit_with<S: Assembly>(
    st: &S,
    opts: &SolverOptions,
    crushing: Crushing,
    facets: usize,
) -> Result<LimitResult<S::D>> {
    check_facets(facets)?;
    let mut map = KinematicMap::new(st);
    map.facets = facets;
    let s = match crushing {
        Crushing::Linear => solve_limit_checked(st, &map, opts)?,
        Crushing::Conic => solve_limit_conic(st, &map, opts)?,
    };
    Ok(limit_result(st, &map, &s))
}

/// Limit analysis of a structure: collapse multiplier, mechanism, forces, thrust line.
pub fn limit<S: Assembly>(st: &S, opts: &SolverOptions) -> Result<LimitResult<S::D>> {
    let map = KinematicMap::new(st);
    let s = solve_limit_checked(st, &map, opts)?;
    Ok(limit_result(st, &map, &s))
}

/// The certificate of the multiplier `s.lambda` of a solved limit program on `st` (a
/// collapse, or a negative λ whose mechanism the dead loads drive: the same strong duality),
/// as [`limit_result`] reports it; `None` without a multiplier and a mechanism, or for joint
/// laws whose kinematic multiplier has more terms than the dead loads' work. For the analyses
/// that solve many limit programs (capacity).
pub fn multiplier_certificate<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    s: &LimitSolution,
) -> Option<LimitCertificate> {
    s.lambda?;
    let (dead, live) = (st.load_vector(false), st.load_vector(true));
    let (wd, wl) = load_works(&s.mechanism, &dead, &live);
    let unit = crate::scale::lambda_unit(map.dofs_per_block, &dead, &live);
    let as_collapse = LimitSolution {
        status: LimitStatus::Collapse,
        lambda: s.lambda,
        mechanism: s.mechanism.clone(),
        pn: vec![],
        pt: vec![],
        iterations: 0,
        solver: s.solver.clone(),
        least: None,
        note: String::new(),
        reduced_accuracy: false,
        basis: None,
    };
    limit_certificate(map, &as_collapse, wd, wl, unit)
}

/// The certificate of a collapse multiplier ([`LimitCertificate`]): for the joint laws whose
/// kinematic multiplier is `−F_D·d` alone (no cohesion, no crushing, no fixed shear
/// capacities), the static λ against it and the mechanism's admissibility.
fn limit_certificate(
    map: &KinematicMap,
    s: &LimitSolution,
    wd: Option<f64>,
    wl: Option<f64>,
    lambda_unit: f64,
) -> Option<LimitCertificate> {
    let plain = map.shear_limits.is_none()
        && map
            .laws
            .iter()
            .all(|l| l.cohesion == 0.0 && l.strength.is_none());
    let (LimitStatus::Collapse, Some(l), Some(wd), Some(wl)) = (s.status, s.lambda, wd, wl) else {
        return None;
    };
    if !plain || s.mechanism.is_empty() || wl.abs() < 1e-300 {
        return None;
    }
    // On the problem's own scale (crate::scale): λ against the mechanism's λ relative to
    // max(|λ|, 1e-3 λ_unit); the mechanism, a rate with the supports held still (support
    // motions play no part in a collapse mechanism), against its own motion scale.
    let gap = crate::scale::relative_gap(l, -wd / wl, lambda_unit);
    let scale = crate::scale::motion_scale(map, &s.mechanism, 0.0);
    let admissibility = if scale > 0.0 {
        super::laws::kinematic_violation(map, &s.mechanism, 0.0) / scale
    } else {
        0.0
    };
    Some(LimitCertificate {
        gap,
        admissibility,
        ok: gap <= CERTIFICATE_TOLERANCE && admissibility <= CERTIFICATE_TOLERANCE,
    })
}

/// The methods that decide a no-equilibrium certificate's elastic program, in turn, each alone
/// (a chain ending in the simplex's phase 1 stalled on the 24 × 24 dome's elastic programs):
/// Clarabel, the dual simplex, then the primal simplex and HiGHS's interior point with
/// crossover. The last two since session 20: on the 1.0 m grid façade's capacity curve (right
/// half settling 20 cm, 20 steps) Clarabel's point did not decide 4 settled steps (row
/// violation 2.3e-6, elastic optimum −1.2e-5) and the dual simplex and the interior point ended
/// "HiGHS run failed: Error"; the primal simplex decided them (least violation 3.0e-6 of the
/// largest load, a Farkas certificate), where the curve was reported NOT CERTIFIED at 4 of 21
/// steps before.
const NO_EQUILIBRIUM_METHODS: [lp::Method; 4] = [
    lp::Method::Clarabel,
    lp::Method::DualSimplex,
    lp::Method::PrimalSimplex,
    lp::Method::Ipm,
];

/// The certificate that a force program `fp` (limit or settlement; its objective ignored) has
/// no equilibrium: its elastic program decided with a certificate either way
/// ([`lp::sequence::decide_feasibility`]) by the first of [`NO_EQUILIBRIUM_METHODS`] that
/// decides it.
/// `None` for a cone program (the elastic program is an LP). `ok` only where a method decided
/// "infeasible"; a "feasible" decision contradicts the answer and is reported with `ok: false`.
pub fn no_equilibrium_certificate(
    fp: &ForceProgram,
    solver: &SolverOptions,
) -> Result<Option<NoEquilibriumCertificate>> {
    no_equilibrium_certificate_by(fp, solver, &NO_EQUILIBRIUM_METHODS)
}

/// [`no_equilibrium_certificate`] by `methods` in turn (a cheap first look: Clarabel alone,
/// where an undecided answer sends the caller to the limit program).
pub fn no_equilibrium_certificate_by(
    fp: &ForceProgram,
    solver: &SolverOptions,
    methods: &[lp::Method],
) -> Result<Option<NoEquilibriumCertificate>> {
    if !fp.cones.is_empty() {
        return Ok(None);
    }
    let _kind = lp::ProgramKind::set(
        "no-equilibrium certificates",
        "the elastic program decides with a certificate either way, Clarabel first",
    );
    for &method in methods {
        let o = SolverOptions { method, ..*solver };
        let t0 = std::time::Instant::now();
        let d = lp::sequence::decide_feasibility(&fp.lp, &o, 0.0)?;
        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
            eprintln!(
                "trace: no-equilibrium certificate by {}: {:?} {:.3} s",
                method.name(),
                d.as_ref().map(|d| (d.feasible, d.violation)),
                t0.elapsed().as_secs_f64()
            );
        }
        if let Some(d) = d {
            return Ok(Some(NoEquilibriumCertificate {
                violation: Some(d.violation),
                method: Some(method),
                ok: !d.feasible,
            }));
        }
    }
    Ok(Some(NoEquilibriumCertificate {
        violation: None,
        method: None,
        ok: false,
    }))
}

/// A "cannot stand" limit result (`no_equilibrium`: no equilibrium under the dead loads alone)
/// given its certificate: the dead loads' statics on `st` (the settlement force program with no
/// support motion, whose feasible set is their equilibrium, with the polygonal laws of
/// `facets`, `None` the map's default) decided infeasible ([`no_equilibrium_certificate`]);
/// the message says whether it holds. `st` is the structure as given, also for a limit result
/// of a structure built on it (the tilting table's, whose live load is the tilt). Other
/// results unchanged.
pub fn certify_no_equilibrium<S: Assembly>(
    st: &S,
    r: &mut LimitResult<S::D>,
    solver: &SolverOptions,
    facets: Option<usize>,
) -> Result<()> {
    if r.status != LimitStatus::NoEquilibrium || r.no_equilibrium.is_some() {
        return Ok(());
    }
    r.no_equilibrium = dead_loads_certificate(st, solver, facets, &mut r.message)?;
    Ok(())
}

/// The certificate that `st`'s dead loads have no equilibrium (the settlement force program
/// with no support motion, whose feasible set is their equilibrium, with the polygonal laws of
/// `facets`, `None` the map's default; [`no_equilibrium_certificate`]), with `message` told
/// whether it holds ([`no_equilibrium_message`]). The one step of every "cannot stand" answer:
/// `limit`, `tilt`, `settle`, `capacity`.
pub fn dead_loads_certificate<S: Assembly>(
    st: &S,
    solver: &SolverOptions,
    facets: Option<usize>,
    message: &mut String,
) -> Result<Option<NoEquilibriumCertificate>> {
    let mut map = KinematicMap::new(st);
    if let Some(f) = facets {
        map.facets = f;
    }
    let fp = programs::settlement_force_program(&map, &st.load_vector(false));
    let c = no_equilibrium_certificate(&fp, solver)?;
    if let Some(c) = &c {
        *message = no_equilibrium_message(message, c);
    }
    Ok(c)
}

/// The message of a "cannot stand" answer with its certificate.
pub fn no_equilibrium_message(message: &str, c: &NoEquilibriumCertificate) -> String {
    match (c.ok, c.violation, c.method) {
        (true, Some(v), Some(m)) => format!(
            "{message} (certified: the equilibrium rows' least total violation is {v:.1e} of the largest load, a Farkas certificate by {})",
            m.name()
        ),
        (false, Some(_), Some(m)) => format!(
            "NOT CERTIFIED (the elastic program by {} found an equilibrium within its tolerance): {message}",
            m.name()
        ),
        _ => format!("NOT CERTIFIED (no method decided the equilibrium's infeasibility): {message}"),
    }
}

/// Turn raw vectors into the reported result.
pub fn limit_result<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    s: &LimitSolution,
) -> LimitResult<S::D> {
    let d = if s.mechanism.is_empty() {
        vec![0.0; map.num_dofs]
    } else {
        s.mechanism.clone()
    };
    let rep = report(st, map, &d, 0.0, &s.pn, &s.pt);
    let cracks = if s.mechanism.is_empty() {
        vec![]
    } else {
        rep.cracks(st)
    };
    let (dead, live) = (st.load_vector(false), st.load_vector(true));
    let (wd, wl) = load_works(&s.mechanism, &dead, &live);
    let unit = crate::scale::lambda_unit(map.dofs_per_block, &dead, &live);
    let mut message = match (s.status, s.lambda) {
        (LimitStatus::NoEquilibrium, Some(l)) if s.least.is_some_and(|m| m > 0.0) => format!(
            "{}: it stands only with the live load, for λ between {:.6} and {l:.6}",
            s.status.sentence(),
            s.least.unwrap_or(f64::NAN)
        ),
        (LimitStatus::NoEquilibrium, None) if s.least.is_some_and(|m| m > 0.0) => format!(
            "{}: it stands only with the live load, for λ ≥ {:.6}",
            s.status.sentence(),
            s.least.unwrap_or(f64::NAN)
        ),
        (LimitStatus::Collapse, Some(l)) => {
            format!("collapse load multiplier λ = {}", show_multiplier(l))
        }
        (LimitStatus::NoEquilibrium, Some(l)) => format!(
            "{} (the largest multiplier in equilibrium is λ = {} < 0)",
            s.status.sentence(),
            show_multiplier(l)
        ),
        (st_, _) => st_.sentence().to_string(),
    };
    // Existing cracks carry nothing in limit analysis; a mechanism that would close one is
    // not the structure's collapse (the crack closes first and then carries force).
    let closing = super::laws::closing_joints(st, map, &s.mechanism);
    if !closing.is_empty() {
        message.push_str(&format!(
            "; WARNING: the collapse mechanism closes the open crack of joint {} (limit analysis is not valid there: after that crack closes the structure carries more; use the incremental analysis)",
            closing.iter().map(|j| j.to_string()).collect::<Vec<_>>().join(", ")
        ));
    }
    let certificate = limit_certificate(map, s, wd, wl, unit);
    if certificate.is_none() && s.reduced_accuracy && s.lambda.is_some() {
        message = format!(
            "NOT CERTIFIED (the solver stopped at reduced accuracy; try another --method): {message}"
        );
    }
    if let Some(c) = certificate.as_ref().filter(|c| !c.ok) {
        message = format!(
            "NOT CERTIFIED (gap {:.1e}, admissibility {:.1e}: the solver stopped short of the optimum; try another --method or a tighter --solver-tolerance): {message}",
            c.gap, c.admissibility
        );
    }
    if !s.note.is_empty() {
        message = format!("{message} ({})", s.note);
    }
    if let Some(n) = s.solver.fallback_note() {
        message = format!("{message} ({n})");
    }
    LimitResult {
        status: s.status,
        certificate,
        message,
        solver: s.solver.clone(),
        load_multiplier: s.lambda,
        least_load_multiplier: s.least,
        work_dead_loads: wd,
        work_live_loads: wl,
        blocks: if s.mechanism.is_empty() {
            vec![]
        } else {
            rep.blocks
        },
        joints: rep.joints,
        hinges: if s.mechanism.is_empty() {
            vec![]
        } else {
            rep.hinges
        },
        cracks,
        thrust_line: rep.thrust_line,
        reactions: rep.reactions,
        iterations: s.iterations,
        friction_iteration: None,
        geometry: st.shapes(),
        canonical: None,
        no_equilibrium: None,
    }
}

/// A load multiplier as the summaries print it: six decimals, or six significant digits in
/// e-notation below 1e-3, so that a small structure's λ (the paper's arch scaled by 1e-6:
/// λ = 4.346453e-7) is not printed as 0.000000 (session 24).
pub fn show_multiplier(l: f64) -> String {
    if l != 0.0 && l.abs() < 1e-3 {
        format!("{l:.6e}")
    } else {
        format!("{l:.6}")
    }
}
