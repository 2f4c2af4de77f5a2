//! Load capacity after a settlement: limit analysis on the deformed geometry (the paper's
//! Section 6, Figs 7, 10, 12).
//!
//! ## What is computed
//!
//! The supports of the structure carry prescribed motions (`support.motion`): they give the
//! *direction* of the settlement and its *largest* value. The settlement magnitude `s` is
//! measured in metres as the largest support translation `max_k |(u_k, v_k)|` (in radians if the
//! supports only rotate; shown in cm or mrad: [`SettlementUnit`]). For the unit settlement (motions divided by that magnitude):
//!
//! 1. the settlement analysis ([`crate::analysis::settlement`]) gives the mechanism `d₁` and the
//!    openings `o₁ = N d₁ + g_n` per collocation point, per unit of settlement;
//! 2. for each `s` the structure is **deformed** ([`deform`]): every block moves by the exact
//!    finite rigid motion `s·d₁` (rotation by `s·θ` about its centroid, not the linearised one),
//!    every support by `s·motion`, and every point takes the gap `s·o₁`. A point whose opening
//!    exceeds `1e-7` of the largest opening is *open*: it stays in the structure with its gap
//!    but carries no force (an opened joint bears only on its hinge point; a fully opened joint
//!    carries nothing). Loads move with their blocks and keep their directions;
//! 3. the classic limit analysis ([`crate::analysis::limit`]) on the deformed structure gives the
//!    collapse multiplier `λ(s)` and its mechanism.
//!
//! `λ(s)` is computed at `steps + 1` equally spaced settlements from 0 to the largest; `s = 0` is
//! the plain limit analysis of the undeformed structure (the same LP with the same options,
//! equal bit for bit). The settlement at which `λ` reaches zero (the structure can no longer carry its own weight) is
//! bracketed from the curve (λ is allowed to go negative: the live load, reversed, that would be
//! needed) and refined by the Illinois variant of regula falsi to `root_tolerance` (1e-6 m).
//!
//! ## Validity
//!
//! Limit analysis on the deformed geometry is valid only if the collapse mechanism does not
//! close hinges that the settlement opened (the paper's Remark 1: a crack must close before it
//! carries force again, so the structure then behaves as a nonlinear elastic, not a plastic,
//! body). Open points are absent from the limit LP, so its mechanism is free to move them either
//! way. Each step therefore evaluates the collapse mechanism's opening rate `N d` at every open
//! point: a negative rate (beyond `1e-7` of the largest rate) means the mechanism closes a
//! settlement crack, and the step is flagged `valid: false` with the joints concerned. That is
//! the case for the incremental analysis ([`crate::analysis::incremental`]).
//!
//! ## Re-using the solver
//!
//! For `s > 0` every deformed structure has the same joints, points and open set (openings
//! scale with `s`), so the limit LPs differ only in their coefficients. [`WarmLimit`] keeps all
//! points as columns (open ones fixed at zero by their bounds), so that the optimal basis of one
//! step is a valid starting basis for the next, and hands it to the solver layer's warm start
//! ([`crate::lp::solve_warm`]; HiGHS's simplex takes it, Clarabel solves from scratch).
//! What that saves is measured in `docs/capacity.md`.
//!
//! A step whose step before was certified to have no equilibrium on the same open points is
//! decided by its own no-equilibrium certificate first (`no_equilibrium_first`, the request
//! layer's default where no method is named): its limit program is solved only where that
//! certificate does not hold (docs/performance.md, "Capacity steps without equilibrium
//! (session 21)").

use crate::analysis::canonical::StepSelection;
pub use crate::analysis::laws::closing_joints;
use crate::analysis::limit::{
    check_facets, multiplier_certificate, show_multiplier, Crushing, LimitSolution, LimitStatus,
    DEFAULT_FACETS,
};
use crate::analysis::paths::{SettlementPath, WarmLimit};
use crate::analysis::settlement::SettlementStatus;
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::{self, SolverOptions};
use crate::programs;
use crate::reporting::report;
pub use crate::result::capacity::*;
use crate::result::limit::NoEquilibriumCertificate;
use crate::result::JointState;
use crate::structure::Assembly;

/// Options of the capacity analysis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CapacityOptions {
    /// Number of intervals: the curve has `steps + 1` points from 0 to the largest settlement.
    pub steps: usize,
    /// Tolerance of the zero-capacity settlement (m).
    pub root_tolerance: f64,
    /// Re-use the previous optimal basis (HiGHS hot start) between steps.
    pub hot_start: bool,
    /// Keep the collapse mechanism (block motions) of every step in the result.
    pub mechanisms: bool,
    /// After the settlement, treat `fixed` supports as ordinary contact joints (no tension, no
    /// sliding). `fixed` is how the paper prescribes a settlement (an essential boundary
    /// condition); the analyses that follow it use unilateral contact at every support. Default
    /// true; false keeps the blocks tied to their fixed supports.
    pub release_fixed: bool,
    /// Finite compressive strength: inscribed polygon (LPs) or the exact cone (Clarabel), in
    /// the settlement and in every limit analysis of the curve.
    pub crushing: Crushing,
    /// Facets of the inscribed crushing polygon ([`Crushing::Linear`]).
    pub facets: usize,
    /// Non-associative Coulomb friction in the settlement and in every limit analysis
    /// (the fixed-point iteration of [`crate::analysis::nonassociative`]); None: associative.
    pub nonassociative: Option<crate::analysis::nonassociative::NonAssociativeOptions>,
    pub solver: SolverOptions,
    /// The method of a step whose program has the open points of the step before (only its
    /// coefficients changed), warm from that step's basis (with `hot_start`); `None`: every
    /// step by `solver`'s method. The request layer sets it from the solver policy
    /// ([`lp::policy::curve_warm_method`]) where no method is named.
    pub warm_method: Option<lp::Method>,
    /// Decide a step by its no-equilibrium certificate first (the elastic program,
    /// [`crate::analysis::limit::no_equilibrium_certificate`]) where the step before was
    /// certified without equilibrium on the same open points, and solve its limit program only
    /// where that certificate does not hold; the same for the root finding's settlements next
    /// to such a step. A step without equilibrium has no limit program to solve (its answer is
    /// the certificate, which is computed either way). The request layer sets it where no
    /// method is named (a named method solves every step's limit program, as before).
    pub no_equilibrium_first: bool,
    /// The canonical selection (docs/canonical.md) of the settlement mechanism, which deforms
    /// the structure (the mechanism stages only); `None`: the solver's own. Only with the
    /// inscribed polygons and associative friction.
    pub canonical: Option<crate::analysis::canonical::CanonicalOptions>,
    /// With `canonical`: also select every step's collapse mechanism (λ unchanged). Costly on
    /// deformed 3D geometry (the README's vault: 37× the raw CPU time, docs/performance.md).
    pub canonical_steps: bool,
}

impl Default for CapacityOptions {
    fn default() -> Self {
        CapacityOptions {
            steps: 40,
            root_tolerance: 1e-6,
            hot_start: true,
            mechanisms: true,
            release_fixed: true,
            crushing: Crushing::Linear,
            facets: DEFAULT_FACETS,
            nonassociative: None,
            solver: SolverOptions::default(),
            warm_method: None,
            no_equilibrium_first: false,
            canonical: None,
            canonical_steps: false,
        }
    }
}

/// The solver a capacity curve states: Clarabel for the cone programs of `Crushing::Conic`
/// (exact crushing in 2D, the exact friction cone in 3D), else the method asked for.
fn capacity_solver(opts: &CapacityOptions) -> crate::lp::SolverInfo {
    match opts.crushing {
        Crushing::Conic => crate::lp::SolverInfo {
            solver: crate::lp::cone_backend(&opts.solver).name().to_string(),
            method: crate::lp::Method::Clarabel,
            tried: Vec::new(),
        },
        Crushing::Linear => opts.solver.info(),
    }
}

/// λ as a number for root finding: locked counts as +∞, no equilibrium at all as −∞.
fn signed_lambda(s: &LimitSolution) -> f64 {
    match (s.status, s.lambda) {
        (_, Some(l)) => l,
        (LimitStatus::Locked, None) => f64::INFINITY,
        _ => f64::NEG_INFINITY,
    }
}

/// Most steps of a capacity curve: each is a limit analysis, and the curve is kept in memory.
pub const MAX_STEPS: usize = 100_000;

/// Capacity curve λ(s) after the settlement prescribed by the supports' motions.
pub fn capacity<S: Assembly>(st: &S, opts: &CapacityOptions) -> Result<CapacityResult<S::D>> {
    if opts.steps == 0 || opts.steps > MAX_STEPS {
        return Err(Error::Request(format!(
            "steps {}: a capacity curve takes between 1 and {MAX_STEPS} steps",
            opts.steps
        )));
    }
    if opts.root_tolerance.is_nan() || opts.root_tolerance <= 0.0 {
        return Err(Error::Request("the root tolerance must be positive".into()));
    }
    if !st.has_live_loads() {
        return Err(Error::Request(
            "capacity analysis needs live loads (the model has none)".into(),
        ));
    }
    check_facets(opts.facets)?;
    let kind = lp::ProgramKind::set("settlement", "");
    // The canonical selection applies to LP optima: not to cone programs or the
    // non-associative iteration.
    let canonical = opts
        .canonical
        .filter(|_| opts.crushing == Crushing::Linear && opts.nonassociative.is_none());
    let path = SettlementPath::with_canonical(
        st,
        &opts.solver,
        opts.crushing,
        opts.facets,
        opts.nonassociative,
        canonical,
    )?;
    drop(kind);
    let smax = path.max_settlement;
    let direction: Vec<SupportDirection> = (0..path.unit.num_supports())
        .filter(|&k| path.unit.support_motion(k).iter().any(|&x| x != 0.0))
        .map(|k| SupportDirection {
            support: path.unit.support_name(k).to_string(),
            motion: path.unit.support_motion(k).to_vec(),
        })
        .collect();
    if path.status != SettlementStatus::Mechanism {
        let mut message = format!("settlement analysis: {}", path.status.sentence());
        // "Cannot stand" certified, as `settle` certifies it (the polygonal statics).
        let mut no_equilibrium = None;
        if path.status == SettlementStatus::CannotStand && opts.crushing == Crushing::Linear {
            no_equilibrium = crate::analysis::limit::dead_loads_certificate(
                &path.unit,
                &opts.solver,
                Some(opts.facets),
                &mut message,
            )?;
        }
        return Ok(CapacityResult {
            status: CapacityStatus::NoSettlementMechanism,
            message,
            solver: capacity_solver(opts),
            max_settlement: smax,
            direction,
            curve: vec![],
            certificate: None,
            answered: vec![],
            zero_capacity_settlement: None,
            zero_capacity_bracket: None,
            existing_cracks_closed_at: None,
            linear_fit: None,
            settlement_mechanism: vec![],
            settlement_hinges: vec![],
            cracks: vec![],
            mechanisms: vec![],
            solves: 0,
            iterations: 0,
            geometry: st.shapes(),
            canonical: None,
            no_equilibrium,
        });
    }
    let mut selection = canonical.map(|_| CapacityCanonical {
        settlement: path.selection.clone(),
        selection: StepSelection {
            steps: opts.canonical_steps,
            solves: path.selection.as_ref().map_or(0, |m| m.solves),
            ..StepSelection::default()
        },
    });
    let umap = KinematicMap::new(&path.unit);
    let (pn0, pt0) = (
        vec![0.0; umap.num_points()],
        vec![0.0; umap.num_tangent_rows()],
    );
    let srep = report(&path.unit, &umap, &path.mechanism, 1.0, &pn0, &pt0);
    // The cracks at the largest settlement: the unit settlement's openings times s_max (plus
    // the gap of an existing crack).
    let swidths: Vec<Vec<f64>> = srep
        .joints
        .iter()
        .zip(&srep.open)
        .map(|(j, o)| {
            j.points
                .iter()
                .zip(o)
                .map(|(p, &op)| {
                    if op {
                        (p.opening * smax + p.gap).max(0.0)
                    } else {
                        0.0
                    }
                })
                .collect()
        })
        .collect();
    let settlement_cracks = path.unit.cracks(&srep.joints, &srep.open, &swidths);

    let mut warm = WarmLimit::new(&opts.solver, opts.hot_start)
        .with_warm_method(opts.warm_method)
        .with_crushing(opts.crushing)
        .with_nonassociative(opts.nonassociative);
    let mut curve = Vec::with_capacity(opts.steps + 1);
    let mut mechanisms = Vec::new();
    let mut values = Vec::with_capacity(opts.steps + 1);
    // The open points of the step before where it was certified without equilibrium, and of
    // every such step (for the root finding).
    let mut last_without: Option<Vec<bool>> = None;
    let mut certified_without: Vec<Option<Vec<bool>>> = Vec::with_capacity(opts.steps + 1);
    let (mut solves, mut iterations) = (0usize, 0i64);
    for i in 0..=opts.steps {
        let s = smax * i as f64 / opts.steps as f64;
        let (dst, map) = step_structure(&path, s, opts)?;
        let cracks_open =
            (!path.existing_cracks.is_empty()).then(|| path.existing_cracks_open(&map));
        // At s = 0 no point has a gap: the warm LP is then the plain limit LP itself (same
        // columns, same options, no starting basis), so λ(0) is the plain limit analysis
        // exactly, and its basis starts the next step.
        let open = open_points(&map);
        let clock = std::time::Instant::now();
        // The step before had no equilibrium (certified) on these open points: this one is
        // decided by its certificate first, its limit program solved only where that does not
        // hold (`no_equilibrium_first`).
        let first = if opts.no_equilibrium_first && last_without.as_ref() == Some(&open) {
            Some(elastic_certificate(&dst, &map, opts)?)
        } else if opts.no_equilibrium_first && i == 1 {
            // The first settled step too, by Clarabel alone (undecided: the limit program
            // decides, and the whole chain certifies a failure, as before): a structure that
            // loses its equilibrium at the first settlement happens (the 0.5 m grid façade,
            // whose step 1's limit program failed in every method after 467 s; decided here in
            // 2.6 s), and where the step stands the elastic program costs about what it costs
            // there (3 s on the 0.5 m running-bond façade, docs/performance.md "Capacity of
            // the 0.5 m grid façade (session 27)").
            let c = elastic_certificate_by(&dst, &map, opts, Some(&[lp::Method::Clarabel]))?;
            c.filter(|c| c.violation.is_some()).map(Some)
        } else {
            None
        };
        let mut by_certificate = first
            .as_ref()
            .is_some_and(|c| c.as_ref().is_some_and(|c| c.ok));
        let by_elastic = |c: Option<NoEquilibriumCertificate>| {
            (
                without_equilibrium(&map, &opts.solver),
                c.map(|c| StepCertificate {
                    kind: StepCertificateKind::NoEquilibrium,
                    gap: None,
                    admissibility: None,
                    violation: c.violation,
                    ok: c.ok,
                }),
            )
        };
        let (mut sol, mut certificate) = if by_certificate {
            by_elastic(first.flatten())
        } else {
            match warm.solve(&dst, &map) {
                Ok(sol) => {
                    let certificate = step_certificate(&dst, &map, &sol, opts, first)?;
                    (sol, certificate)
                }
                // Every method failed on the step's limit program: the step's own
                // no-equilibrium certificate (its elastic program, a Farkas certificate)
                // decides it where it holds, so that a step without equilibrium is an answer,
                // not a failure (the 0.5 m grid façade's first settled step, session 26:
                // minutes in HiGHS's dual simplex, then an error from every method). Where it
                // does not hold, the failure stands.
                Err(e @ (Error::Solver(_) | Error::Undecided)) => {
                    let c = match first {
                        Some(c) => c,
                        None => elastic_certificate(&dst, &map, opts)?,
                    };
                    let c = decided_after_failure(e.clone(), c)?;
                    if std::env::var_os("VOUSSOIR_TRACE").is_some() {
                        eprintln!(
                            "trace: capacity step {i}: the limit program failed ({e}); decided by its no-equilibrium certificate"
                        );
                    }
                    by_certificate = true;
                    by_elastic(c)
                }
                Err(e) => return Err(e),
            }
        };
        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
            eprintln!(
                "trace: capacity step {i} s {s:.6} {:?} λ {:?} by {} it {}; certificate {:?}; in {:.3} s",
                sol.status,
                sol.lambda,
                if by_certificate {
                    "its no-equilibrium certificate first".to_string()
                } else {
                    format!("{:?}", sol.solver.method)
                },
                sol.iterations,
                certificate.as_ref().map(|c| (c.kind, c.ok)),
                clock.elapsed().as_secs_f64()
            );
        }
        // A multiplier whose certificate does not hold (the warm simplex stopped short: the
        // LACT3 portal's steps at 0.4 and 0.45 cm, gap 6e-7 and 6e-6) is solved again from
        // scratch, by the method asked for and then by Clarabel; the first certified answer
        // stands, else the warm one with its certificate (not certified).
        if certificate
            .as_ref()
            .is_some_and(|c| !c.ok && c.kind == StepCertificateKind::Multiplier)
        {
            let _kind = lp::ProgramKind::set(
                "steps re-solved",
                "a step whose certificate did not hold, solved again from scratch",
            );
            for method in [opts.solver.method, lp::Method::Clarabel] {
                let o = SolverOptions {
                    method,
                    ..opts.solver
                };
                let again = crate::analysis::limit::solve_limit(&dst, &map, &o)?;
                let c = step_certificate(&dst, &map, &again, opts, None)?;
                if c.as_ref().is_some_and(|c| c.ok) {
                    sol = again;
                    certificate = c;
                    break;
                }
            }
        }
        // A "locked" step (the program unbounded) that the elastic program proves to have no
        // equilibrium at any λ: the warm simplex's status was wrong (HiGHS's dual simplex, warm,
        // reported `lact3-wall`'s program at 0.25 cm unbounded between two infeasible ones).
        if sol.status == LimitStatus::Locked
            && certificate
                .as_ref()
                .is_some_and(|c| c.ok && c.kind == StepCertificateKind::NoEquilibrium)
        {
            sol.status = LimitStatus::NoEquilibrium;
        }
        last_without = (sol.status == LimitStatus::NoEquilibrium
            && sol.lambda.is_none()
            && certificate
                .as_ref()
                .is_some_and(|c| c.ok && c.kind == StepCertificateKind::NoEquilibrium))
        .then_some(open);
        certified_without.push(last_without.clone());
        values.push(signed_lambda(&sol));
        // The canonical collapse mechanism among the step's optima (λ unchanged).
        if let (Some(copts), Some(rec), true) =
            (canonical.as_ref(), selection.as_mut(), opts.canonical_steps)
        {
            if let Some(d) = rec
                .selection
                .select(&dst, &map, &sol, &opts.solver, copts, i)?
            {
                sol.mechanism = d;
            }
        }
        let closing = closing_joints(&dst, &map, &sol.mechanism);
        let hinges = if sol.mechanism.is_empty() {
            vec![]
        } else {
            report(&dst, &map, &sol.mechanism, 0.0, &sol.pn, &sol.pt).hinges
        };
        if opts.mechanisms && !sol.mechanism.is_empty() {
            let rep = report(&dst, &map, &sol.mechanism, 0.0, &sol.pn, &sol.pt);
            mechanisms.push(CapacityMechanism {
                settlement: s,
                blocks: rep.blocks,
            });
        }
        curve.push(CapacityPoint {
            settlement: s,
            load_multiplier: sol.lambda,
            status: sol.status,
            valid: closing.is_empty(),
            closing_joints: closing,
            hinges,
            existing_cracks_open: cracks_open,
            certificate,
        });
    }
    let certificate = Some(summarise(&curve));

    // Zero-capacity settlement: first sign change of λ on the curve, refined.
    let mut zero = None;
    // The refined bracket of the zero (where it was refined).
    let mut bracket: Option<[f64; 2]> = None;
    // The zero at the onset of settlement, certified ([`without_equilibrium_at_onset`]).
    let mut at_onset = false;
    if values[0] == 0.0 {
        zero = Some(0.0);
    } else {
        for i in 1..values.len() {
            if values[i - 1] > 0.0 && values[i] <= 0.0 {
                if values[i] == 0.0 {
                    zero = Some(curve[i].settlement);
                } else if i == 1
                    && certified_without[1]
                        .as_ref()
                        .map(|open| without_equilibrium_at_onset(&path, open, opts))
                        .transpose()?
                        .unwrap_or(false)
                {
                    zero = Some(0.0);
                    at_onset = true;
                } else {
                    // A settlement next to a step certified without equilibrium, on its open
                    // points, is decided by its certificate first (`no_equilibrium_first`).
                    let without = certified_without[i].as_ref();
                    let lam = |s: f64, w: &mut WarmLimit| -> Result<f64> {
                        let (dst, map) = step_structure(&path, s, opts)?;
                        let clock = std::time::Instant::now();
                        // Clarabel alone: near the root the program is nearly feasible, its
                        // elastic program undecided by every method (HiGHS's interior point
                        // on it ran for minutes on the 1.0 m grid façade at s = 2.5 mm).
                        let first = opts.no_equilibrium_first
                            && without == Some(&open_points(&map))
                            && elastic_certificate_by(
                                &dst,
                                &map,
                                opts,
                                Some(&[lp::Method::Clarabel]),
                            )?
                            .is_some_and(|c| c.ok);
                        let v = if first {
                            f64::NEG_INFINITY
                        } else {
                            signed_lambda(&w.solve(&dst, &map)?)
                        };
                        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
                            eprintln!(
                                "trace: capacity root s {s:.9} λ {v} ({}) in {:.3} s",
                                if first {
                                    "by its no-equilibrium certificate first"
                                } else {
                                    "by its limit program"
                                },
                                clock.elapsed().as_secs_f64()
                            );
                        }
                        Ok(v)
                    };
                    let (z, br) = illinois(
                        (curve[i - 1].settlement, values[i - 1]),
                        (curve[i].settlement, values[i]),
                        opts.root_tolerance,
                        |s| lam(s, &mut warm),
                    )?;
                    zero = Some(z);
                    bracket = Some(br);
                }
                break;
            }
        }
    }
    solves += warm.solves;
    iterations += warm.iterations;

    // Existing cracks: the settlement at which the last of them closes, by bisection between
    // the curve points where the count of open ones reaches zero.
    let mut closed_at = None;
    if let Some(i) = curve
        .iter()
        .position(|p| p.existing_cracks_open == Some(0))
        .filter(|&i| i > 0)
    {
        let (mut a, mut b) = (curve[i - 1].settlement, curve[i].settlement);
        while b - a > opts.root_tolerance {
            let m = 0.5 * (a + b);
            let dst = path.deformed(m)?;
            if path.existing_cracks_open(&KinematicMap::new(&dst)) == 0 {
                b = m;
            } else {
                a = m;
            }
        }
        closed_at = Some(b);
    }

    let linear_fit = fit(&curve);
    let l0 = curve[0].load_multiplier;
    let invalid = curve.iter().filter(|p| !p.valid).count();
    let unit = SettlementUnit::of(&direction);
    // The bracket where it is the answer (wider than a tenth of the zero).
    let wide_bracket = wide(zero, bracket);
    let mut message = match (l0, zero, wide_bracket) {
        (Some(l0), Some(_), _) if at_onset => format!(
            // Every optimal field of the settlement is complementary to its mechanism (no
            // normal force at its open points): one without shear there would be an
            // equilibrium of this very program. So the settlement analysis's forces need shear
            // across open joints, which its no-sliding rule allows (`settle`'s canonical forces
            // say "physical: false").
            "λ falls from {} at no settlement to 0 at its onset: with the cracks the {} opens, however small, the dead loads have no equilibrium (certified); the settlement analysis carries them only by shear across its open joints (its no-sliding rule holds at open joints)",
            show_multiplier(l0),
            unit.noun()
        ),
        // The zero known only to a bracket wider than a tenth of it (every settlement tried
        // next to 0 without equilibrium: the 0.5 m grid façade's curve, whose zero was printed
        // as 3.052e-5 cm from a bracket [0, 6.104e-5] cm): the bracket is the answer.
        (Some(l0), Some(_), Some([lo, hi])) => {
            if lo == 0.0 {
                format!(
                    "λ falls from {} at no settlement to 0 within the first {} of {} (the root tolerance: no {} tried carries the dead loads)",
                    show_multiplier(l0),
                    unit.show(hi, 4),
                    unit.noun(),
                    unit.noun()
                )
            } else {
                format!(
                    "λ falls from {} at no settlement to 0 at a {} between {} and {} (the root tolerance, {})",
                    show_multiplier(l0),
                    unit.noun(),
                    unit.show(lo, 4),
                    unit.show(hi, 4),
                    unit.show(opts.root_tolerance, 4)
                )
            }
        }
        (Some(l0), Some(z), _) => format!(
            "λ falls from {} at no settlement to 0 at a {} of {}",
            show_multiplier(l0),
            unit.noun(),
            unit.show(z, 4)
        ),
        (Some(l0), None, _) => format!(
            "λ = {} at no settlement and {} at the largest {} {}: no zero crossing in the range",
            show_multiplier(l0),
            curve
                .last()
                .and_then(|p| p.load_multiplier)
                .map_or("undefined".to_string(), show_multiplier),
            unit.noun(),
            unit.show(smax, 4)
        ),
        (None, _, _) => format!("at no settlement: {}", curve[0].status.sentence()),
    };
    // Steps after the first without any equilibrium: where the settlement mechanism slides
    // under associative friction, its sliding joints also open by μ per unit slip (dilatancy)
    // and the deformed blocks come apart, a property of that law rather than of the masonry
    // (docs/joint-laws.md: an 8 × 5 wall keeps λ ≈ 0.365 without dilatancy). Said in the
    // message so that the engineer does not read a lost structure where the law is the cause.
    let without = curve[1..]
        .iter()
        .filter(|p| p.status == LimitStatus::NoEquilibrium)
        .count();
    let slides = srep.joints.iter().any(|j| j.state == JointState::Sliding);
    if without > 0 && slides && opts.nonassociative.is_none() {
        message.push_str(&format!(
            "; no equilibrium under the dead loads at {without} of {} settled steps: the settlement slides with associative friction, whose sliding joints also open by μ per unit slip (dilatancy) and come apart; non-associative friction slides without opening (docs/joint-laws.md)",
            curve.len() - 1
        ));
    }
    if warm.unconverged > 0 {
        message.push_str(&format!(
            "; WARNING: the non-associative friction iteration did not converge in {} of {} limit analyses",
            warm.unconverged, warm.solves
        ));
    }
    if let Some(c) = closed_at {
        message.push_str(&format!(
            "; the existing cracks close at a {} of {}",
            unit.noun(),
            unit.show(c, 4)
        ));
    } else if curve
        .last()
        .and_then(|p| p.existing_cracks_open)
        .is_some_and(|n| n > 0)
    {
        message.push_str("; some existing cracks stay open over the whole range");
    }
    if let Some(c) = certificate.as_ref().filter(|c| !c.ok) {
        // Steps without any certificate are said so, with the reason where the law has none:
        // "largest gap 0.0e0" read as a certificate that holds (the non-associative curve of
        // the README wall, session 23).
        let without = c
            .uncertified_steps
            .iter()
            .filter(|&&i| curve[i].certificate.is_none())
            .count();
        let reason = if opts.nonassociative.is_some() {
            "no certificate: the non-associative friction iteration is a heuristic, its fixed point not an optimum with a dual"
        } else if opts.crushing == Crushing::Conic {
            "no certificate: the steps are cone programs, whose answers are not certified here"
        } else {
            "no certificate computed"
        };
        let failed = c.steps - c.certified - without;
        let detail = match (failed, without) {
            (0, _) => reason.to_string(),
            (_, 0) => format!(
                "largest gap {:.1e}, admissibility {:.1e}",
                c.gap, c.admissibility
            ),
            (_, w) => format!(
                "largest gap {:.1e}, admissibility {:.1e}; {w} with {reason}",
                c.gap, c.admissibility
            ),
        };
        message = format!(
            "NOT CERTIFIED at {} of {} steps ({detail}): {message}",
            c.steps - c.certified,
            c.steps,
        );
    }
    if let Some(c) = selection.as_ref() {
        if c.settlement.is_none() {
            message.push_str("; the canonical selection of the settlement mechanism was not reached: the solver's own deforms the structure, which may depend on the method");
        }
        let s = &c.selection;
        if !s.steps_not_reached.is_empty() {
            message.push_str(&format!(
                "; the canonical selection was not reached at {} of {} steps with a multiplier: the solver's own mechanism is reported there",
                s.steps_not_reached.len(),
                s.steps_not_reached.len() + s.steps_selected
            ));
        }
    }
    if invalid > 0 {
        message.push_str(&format!(
            "; WARNING: at {invalid} of {} settlements the collapse mechanism closes cracks opened by the settlement, so limit analysis is not valid there (use the incremental analysis)",
            curve.len()
        ));
    }
    Ok(CapacityResult {
        status: CapacityStatus::Curve,
        message,
        solver: capacity_solver(opts),
        max_settlement: smax,
        direction,
        curve,
        certificate,
        answered: vec![],
        zero_capacity_settlement: zero,
        zero_capacity_bracket: wide_bracket,
        existing_cracks_closed_at: closed_at,
        linear_fit,
        settlement_mechanism: srep.blocks,
        settlement_hinges: srep.hinges,
        cracks: settlement_cracks,
        mechanisms,
        solves,
        iterations,
        geometry: st.shapes(),
        canonical: selection,
        no_equilibrium: None,
    })
}

/// The certificate of one step's answer: λ and its mechanism ([`multiplier_certificate`], as
/// `limit` reports it) where the program has a multiplier; where it has none at any λ (no
/// equilibrium), the infeasibility decided again by the elastic program with its Farkas
/// certificate ([`lp::sequence::decide_feasibility`]; Clarabel, then the dual simplex). `None`
/// for the laws without one (cohesion, crushing, non-associative friction). A locked step (the
/// program unbounded) is decided the same way: where it has no equilibrium at all, the
/// certificate says so and the caller corrects the status; where it has one, no certificate
/// (its ray of unbounded λ is not computed).
///
/// `elastic`: the step's no-equilibrium certificate where it was already computed
/// ([`elastic_certificate`]), then not computed again.
fn step_certificate<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    sol: &LimitSolution,
    opts: &CapacityOptions,
    elastic: Option<Option<NoEquilibriumCertificate>>,
) -> Result<Option<StepCertificate>> {
    if opts.nonassociative.is_some() || opts.crushing == Crushing::Conic {
        return Ok(None);
    }
    if sol.lambda.is_some() {
        return Ok(
            multiplier_certificate(st, map, sol).map(|c| StepCertificate {
                kind: StepCertificateKind::Multiplier,
                gap: Some(c.gap),
                admissibility: Some(c.admissibility),
                violation: None,
                ok: c.ok,
            }),
        );
    }
    if !matches!(sol.status, LimitStatus::NoEquilibrium | LimitStatus::Locked) {
        return Ok(None);
    }
    let locked = sol.status == LimitStatus::Locked;
    let c = match elastic {
        Some(c) => c,
        None => elastic_certificate(st, map, opts)?,
    };
    let Some(c) = c else {
        return Ok(None);
    };
    // Locked and feasible (decided): the certificate would be a ray of unbounded λ (not
    // computed here): no certificate.
    if locked && c.violation.is_some() && !c.ok {
        return Ok(None);
    }
    Ok(Some(StepCertificate {
        kind: StepCertificateKind::NoEquilibrium,
        gap: None,
        admissibility: None,
        violation: c.violation,
        // Decided infeasible, as the step says; a feasible decision contradicts it.
        ok: c.ok,
    }))
}

/// The certificate that a step's limit program has no equilibrium at any λ, decided on the step's
/// own program ([`crate::analysis::limit::no_equilibrium_certificate`]: its elastic program with
/// a Farkas certificate); `None` for the laws without one.
fn elastic_certificate<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &CapacityOptions,
) -> Result<Option<NoEquilibriumCertificate>> {
    elastic_certificate_by(st, map, opts, None)
}

/// [`elastic_certificate`] by `methods` in turn (`None`: the whole chain of
/// [`crate::analysis::limit::no_equilibrium_certificate`]).
fn elastic_certificate_by<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    opts: &CapacityOptions,
    methods: Option<&[lp::Method]>,
) -> Result<Option<NoEquilibriumCertificate>> {
    if opts.nonassociative.is_some() || opts.crushing == Crushing::Conic {
        return Ok(None);
    }
    let (dead, live) = (st.load_vector(false), st.load_vector(true));
    let fp = programs::limit_force_program(map, &dead, &live);
    match methods {
        None => crate::analysis::limit::no_equilibrium_certificate(&fp, &opts.solver),
        Some(m) => crate::analysis::limit::no_equilibrium_certificate_by(&fp, &opts.solver, m),
    }
}

/// A step whose limit program failed in every method (`failure`): its no-equilibrium
/// certificate `c` decides it where it certifies that the step has no equilibrium; otherwise
/// the failure stands (a step that may have an equilibrium is not answered without its λ).
fn decided_after_failure(
    failure: Error,
    c: Option<NoEquilibriumCertificate>,
) -> Result<Option<NoEquilibriumCertificate>> {
    if c.as_ref().is_some_and(|c| c.ok) {
        Ok(c)
    } else {
        Err(failure)
    }
}

/// The structure deformed by the settlement `s` as the curve analyses it (its `fixed` supports
/// released where `opts` says so), and its kinematic map with the curve's crushing facets.
fn step_structure<S: Assembly>(
    path: &SettlementPath<S>,
    s: f64,
    opts: &CapacityOptions,
) -> Result<(S, KinematicMap)> {
    let mut dst = path.deformed(s)?;
    if opts.release_fixed {
        dst.release_fixed();
    }
    let mut map = KinematicMap::new(&dst);
    map.facets = opts.facets;
    Ok((dst, map))
}

/// The bracket of a zero where it, not the zero, is the answer: wider than a tenth of it.
fn wide(zero: Option<f64>, bracket: Option<[f64; 2]>) -> Option<[f64; 2]> {
    match (zero, bracket) {
        (Some(z), Some([lo, hi])) if hi - lo > 0.1 * z.abs() => Some([lo, hi]),
        _ => None,
    }
}

/// Whether the structure has no equilibrium at the onset of the settlement (`s → 0+`), decided
/// by a certificate: the undeformed geometry with the points that the first settled step opens
/// carrying nothing. Without existing cracks a deformed structure's openings scale with `s`
/// and so does the tolerance that counts one open ([`SettlementPath::deformed`]), so every
/// `s > 0` has the same open points; the programs differ only by the geometry, which tends to
/// the undeformed one. A program without equilibrium by a certified margin stays so near that
/// limit, so λ is negative or undefined just after 0: the first zero is the onset itself.
/// (The 0.5 m grid façade: its root finding took 10 limit programs and 112 s to find it within
/// the root tolerance of 0, docs/performance.md "Capacity of the 0.5 m grid façade (session
/// 27)".) `false` where the certificate does not hold or with existing cracks.
fn without_equilibrium_at_onset<S: Assembly>(
    path: &SettlementPath<S>,
    open: &[bool],
    opts: &CapacityOptions,
) -> Result<bool> {
    if !path.existing_cracks.is_empty() {
        return Ok(false);
    }
    let (dst, mut map) = step_structure(path, 0.0, opts)?;
    if map.gap.len() != open.len() || map.gap.iter().any(|g| *g > 0.0) {
        return Ok(false);
    }
    // Open: a gap, which fixes the point's forces at zero (its size plays no part in a limit
    // program).
    for (g, &o) in map.gap.iter_mut().zip(open) {
        if o {
            *g = 1.0;
        }
    }
    let t0 = std::time::Instant::now();
    let c = elastic_certificate(&dst, &map, opts)?;
    if std::env::var_os("VOUSSOIR_TRACE").is_some() {
        eprintln!(
            "trace: capacity onset (s → 0+): no-equilibrium certificate {:?} in {:.3} s",
            c.as_ref().map(|c| (c.ok, c.violation)),
            t0.elapsed().as_secs_f64()
        );
    }
    Ok(c.is_some_and(|c| c.ok))
}

/// The points of a step's map that are open (a gap: fixed at zero in its limit program).
fn open_points(map: &KinematicMap) -> Vec<bool> {
    map.gap.iter().map(|g| *g > 0.0).collect()
}

/// The answer of a step decided by its no-equilibrium certificate alone: no equilibrium at any
/// λ, no limit program solved.
fn without_equilibrium(map: &KinematicMap, solver: &SolverOptions) -> LimitSolution {
    LimitSolution {
        status: LimitStatus::NoEquilibrium,
        lambda: None,
        mechanism: vec![],
        pn: vec![0.0; map.num_points()],
        pt: vec![0.0; map.num_tangent_rows()],
        iterations: 0,
        solver: solver.info(),
        least: None,
        note: String::new(),
        reduced_accuracy: false,
        basis: None,
    }
}

/// The steps' certificates summed up.
fn summarise<D: crate::result::Spatial>(curve: &[CapacityPoint<D>]) -> CapacityCertificate {
    let mut c = CapacityCertificate {
        steps: curve.len(),
        certified: 0,
        uncertified_steps: vec![],
        gap: 0.0,
        admissibility: 0.0,
        ok: true,
    };
    for (i, p) in curve.iter().enumerate() {
        match &p.certificate {
            Some(s) if s.ok => c.certified += 1,
            _ => c.uncertified_steps.push(i),
        }
        if let Some(s) = &p.certificate {
            c.gap = c.gap.max(s.gap.unwrap_or(0.0));
            c.admissibility = c.admissibility.max(s.admissibility.unwrap_or(0.0));
        }
    }
    c.ok = c.uncertified_steps.is_empty();
    c
}

/// Root of `f` in `[a, b]` with `f(a) > 0 ≥ f(b)` (values may be ±∞), to `tol` in x: Illinois
/// regula falsi, bisecting whenever a value is infinite. With it, the last bracket (the root
/// lies in it).
fn illinois(
    mut a: (f64, f64),
    mut b: (f64, f64),
    tol: f64,
    mut f: impl FnMut(f64) -> Result<f64>,
) -> Result<(f64, [f64; 2])> {
    let mut side = 0i8;
    let mut width = f64::INFINITY;
    for _ in 0..200 {
        let w = (b.0 - a.0).abs();
        if w <= tol {
            break;
        }
        // Bisect whenever the last step did not halve the bracket (λ may jump, e.g. where a
        // hinge opens): at most twice the iterations of plain bisection.
        let bisect = w > 0.5 * width;
        width = w;
        let x = if !bisect && a.1.is_finite() && b.1.is_finite() && a.1 != b.1 {
            let x = (a.0 * b.1 - b.0 * a.1) / (b.1 - a.1);
            // Stay strictly inside and away from the ends by a fraction of the tolerance.
            x.clamp(a.0.min(b.0) + 0.25 * tol, a.0.max(b.0) - 0.25 * tol)
        } else {
            0.5 * (a.0 + b.0)
        };
        let fx = f(x)?;
        if fx == 0.0 {
            return Ok((x, [x, x]));
        }
        if fx > 0.0 {
            a = (x, fx);
            if side == 1 {
                b.1 *= 0.5;
            }
            side = 1;
        } else {
            b = (x, fx);
            if side == -1 {
                a.1 *= 0.5;
            }
            side = -1;
        }
    }
    // The crossing is between a and b; linear interpolation when both are finite.
    let x = if a.1.is_finite() && b.1.is_finite() && a.1 != b.1 {
        (a.0 * b.1 - b.0 * a.1) / (b.1 - a.1)
    } else {
        0.5 * (a.0 + b.0)
    };
    Ok((x, [a.0.min(b.0), a.0.max(b.0)]))
}

fn fit<D: crate::result::Spatial>(curve: &[CapacityPoint<D>]) -> Option<LinearFit> {
    let pts: Vec<(f64, f64)> = curve
        .iter()
        .filter(|p| p.settlement > 0.0 && p.valid)
        .filter_map(|p| p.load_multiplier.map(|l| (p.settlement, l)))
        .collect();
    if pts.len() < 2 {
        return None;
    }
    let n = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / n, sy / n);
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    if sxx == 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    let l0 = curve[0].load_multiplier.unwrap_or(my).abs().max(1e-300);
    let dev = pts
        .iter()
        .fold(0.0f64, |m, p| m.max((p.1 - intercept - slope * p.0).abs()));
    Some(LinearFit {
        intercept,
        slope,
        max_relative_deviation: dev / l0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A zero the root finding cannot place away from 0 (every settlement tried without
    /// equilibrium, λ = −∞): the bracket ends at 0 and is within the tolerance, so the bracket
    /// is the answer; a zero found at 1.3753 cm to 1e-6 m is a number.
    #[test]
    fn a_zero_at_the_tolerance_of_0_is_a_bracket() {
        let (z, br) = illinois((0.0, 0.9), (0.01, f64::NEG_INFINITY), 1e-6, |_| {
            Ok(f64::NEG_INFINITY)
        })
        .unwrap();
        // Bisection from 1 cm: 0.01 / 2^14 = 6.1e-7 m is the first width within 1e-6.
        assert_eq!(br, [0.0, 0.01 / 16384.0]);
        assert_eq!(z, 0.5 * br[1]);
        assert_eq!(wide(Some(z), Some(br)), Some(br));
        // λ = 1 − s/0.013753 crosses at 0.013753 m, found by regula falsi to 1e-6.
        let (z, br) = illinois((0.0, 1.0), (0.02, 1.0 - 0.02 / 0.013753), 1e-6, |s| {
            Ok(1.0 - s / 0.013753)
        })
        .unwrap();
        assert!((z - 0.013753).abs() < 1e-9, "{z}");
        assert!(br[0] <= z && z <= br[1]);
        assert_eq!(wide(Some(z), Some(br)), None);
    }

    #[test]
    fn a_failed_step_is_answered_only_by_a_certified_no_equilibrium() {
        // Session 26: the 0.5 m grid façade's first settled step failed in every method
        // (minutes in HiGHS's dual simplex) and the command ended in that error; its
        // no-equilibrium certificate decides it (docs/performance.md, "`capacity` on the
        // 0.5 m façades (session 26)").
        let failure = Error::Solver("every method failed".into());
        let certified = NoEquilibriumCertificate {
            violation: Some(35.5),
            method: Some(lp::Method::Clarabel),
            ok: true,
        };
        let c = decided_after_failure(failure.clone(), Some(certified.clone())).unwrap();
        assert_eq!(c, Some(certified));
        // Decided feasible (the step has an equilibrium: its λ is needed), undecided, or no
        // certificate for the law: the failure stands.
        for c in [
            Some(NoEquilibriumCertificate {
                violation: Some(1e-12),
                method: Some(lp::Method::Clarabel),
                ok: false,
            }),
            Some(NoEquilibriumCertificate {
                violation: None,
                method: None,
                ok: false,
            }),
            None,
        ] {
            assert_eq!(
                decided_after_failure(failure.clone(), c),
                Err(failure.clone())
            );
        }
    }
}
