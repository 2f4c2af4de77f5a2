//! Issue 29, items 2, 4 and 6 (session 17): two avoidable costs found on the 48 × 48 dome's
//! `limit` (docs/performance.md, "Dome 48 × 48 (session 17)").
//!
//! 1. `limit` and `tilt` check that the
//! structure stands under its dead loads alone by a second program, the least multiplier
//! (`min λ` over the same constraints). After HiGHS's interior point with crossover (the 3D
//! default) that program was solved by a second interior point from scratch: on the 48 × 48
//! dome (2,257 blocks) each took about 95 CPU s. Only the objective differs, so the optimal
//! basis of the first program is primal feasible for the second, and the primal simplex goes
//! on from it.
//! 2. Clarabel's answer to a large program of equations (the limit program of a dome without
//!    friction) went through HiGHS's presolve and postsolve, whose duals did not price the
//!    program (duality gap 0.13 on the 32 × 32 dome, 0.18 on the 48 × 48): the answer failed
//!    the solver layer's certificate and the fallback chain went on to HiGHS's interior point
//!    (about 95 CPU s on the 48 × 48 dome, against 4.4 for Clarabel on the program as it is).

use voussoir::analysis::limit::limit;
use voussoir::discretize::KinematicMap;
use voussoir::lp::{self, LpStatus, Method, SolverOptions};
use voussoir::programs;
use voussoir::structure::Assembly;
use voussoir::Structure3d;

mod support;
use support::crowned_dome;

/// The largest and least multipliers of the dome's limit program, each solved from scratch by
/// the dual simplex (another method than the default's, and no warm start).
fn reference(st: &Structure3d) -> (f64, f64) {
    let map = KinematicMap::new(st);
    let fp = programs::limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    let o = SolverOptions {
        method: Method::DualSimplex,
        ..SolverOptions::default()
    };
    let mut p = fp.lp.clone();
    let max = lp::solve(&p, &o).unwrap();
    p.maximise = false;
    let min = lp::solve(&p, &o).unwrap();
    assert_eq!(max.status, LpStatus::Optimal);
    assert_eq!(min.status, LpStatus::Optimal);
    let j = fp.lambda.unwrap();
    (max.x[j], min.x[j])
}

#[test]
fn issue29_least_multiplier_goes_on_from_the_crossover_basis() {
    let st = crowned_dome(8, 16);
    let (lmax, lmin) = reference(&st);
    let o = SolverOptions {
        method: Method::Ipm,
        ..SolverOptions::default()
    };
    let (r, solves) = lp::collecting(|| limit(&st, &o).unwrap());
    let l = r.load_multiplier.unwrap();
    let least = r.least_load_multiplier.unwrap();
    // The same numbers as the dual simplex from scratch, to the certificate's tolerance.
    assert!(
        (l - lmax).abs() <= 1e-6 * lmax.abs(),
        "λ {l} against {lmax}"
    );
    assert!(
        (least - lmin).abs() <= 1e-6 * lmin.abs().max(1.0),
        "least λ {least} against {lmin}"
    );
    // The dome stands without its crown load (least λ ≤ 0) and collapses under it.
    assert!(lmin < 0.0 && lmax > 0.0, "{lmin} {lmax}");
    assert!(r.certificate.as_ref().unwrap().ok);
    // Two programs: the interior point, then the primal simplex from its basis (before: a
    // second interior point from scratch).
    let methods: Vec<Method> = solves.iter().map(|s| s.method).collect();
    assert_eq!(
        methods,
        vec![Method::Ipm, Method::PrimalSimplex],
        "{solves:?}"
    );
    assert!(solves.iter().all(|s| s.tried.is_empty()), "{solves:?}");
}

#[test]
fn issue29_clarabel_presolved_answer_that_does_not_certify_is_solved_as_written() {
    // 993 blocks, 24,193 columns: above clarabel::PRESOLVE_MIN_COLUMNS, every row an equation.
    let st = crowned_dome(32, 32);
    let o = SolverOptions {
        method: Method::Clarabel,
        ..SolverOptions::default()
    };
    let (r, solves) = lp::collecting(|| limit(&st, &o).unwrap());
    // Both programs answered by Clarabel itself, nothing tried before it (before: "clarabel:
    // not certified (row violation 4.5e-16, duality gap 1.3e-1)", then HiGHS's IPM).
    let methods: Vec<Method> = solves.iter().map(|s| s.method).collect();
    assert_eq!(
        methods,
        vec![Method::Clarabel, Method::Clarabel],
        "{solves:?}"
    );
    assert!(solves.iter().all(|s| s.tried.is_empty()), "{solves:?}");
    assert_eq!(r.solver.method, Method::Clarabel);
    // The static λ against the kinematic multiplier of its own mechanism (−F_D·d / F_L·d): the
    // certificate, an independent reference for the value.
    let c = r.certificate.as_ref().unwrap();
    assert!(c.ok && c.gap <= 1e-6, "{c:?}");
    let l = r.load_multiplier.unwrap();
    let kinematic = -r.work_dead_loads.unwrap() / r.work_live_loads.unwrap();
    assert!(
        (l - kinematic).abs() <= 1e-6 * l,
        "λ {l} against {kinematic}"
    );
}
