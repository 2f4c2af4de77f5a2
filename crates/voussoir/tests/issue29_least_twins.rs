//! Issue 29 item 6 (session 22): the least load multiplier of a 2D limit analysis after
//! HiGHS's interior point, by the warm primal simplex on the limit program with one column of
//! each pair of twins (the two shear forces of a joint: `safety::Twins`), its optimum expanded
//! and certified on the whole program (`limit::least_program`; otherwise the program itself as
//! before). On the 0.5 m grid façade's `tilt` the least multiplier took about 5 CPU s.
//!
//! Times: docs/performance.md, "0.5 m grid façade safety and tilt (session 22)".

mod support;
use support::facade_grid;
use voussoir::analysis::tilt::tilt;
use voussoir::discretize::KinematicMap;
use voussoir::lp::{self, LpStatus, Method, SolverOptions};
use voussoir::programs::limit_force_program;
use voussoir::Assembly;

/// The least multiplier's program of `st` (the limit program minimised), twins and all, by the
/// dual simplex from scratch.
fn least_from_scratch(st: &voussoir::Structure) -> f64 {
    let map = KinematicMap::new(st);
    let mut fp = limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    fp.lp.maximise = false;
    let s = lp::solve(&fp.lp, &SolverOptions::default()).unwrap();
    assert_eq!(s.status, LpStatus::Optimal);
    s.x[fp.lambda.unwrap()]
}

#[test]
fn issue29_least_multiplier_without_twins_equals_the_program_from_scratch() {
    // The 2.0 m grid façade (223 blocks) on the tilting table towards +x, by HiGHS's interior
    // point (the CLI's 2D default for limit analysis): the least multiplier came from the
    // crossover basis; since session 25 it is the mirror image of the largest's optimum (the
    // test below reaches the basis path).
    let st = facade_grid(2.0);
    let ipm = SolverOptions {
        method: Method::Ipm,
        ..SolverOptions::default()
    };
    let r = tilt(&st, 1.0, &ipm).unwrap();
    let (hi, lo) = (
        r.limit.load_multiplier.unwrap(),
        r.limit.least_load_multiplier.unwrap(),
    );
    // Reference 1: the least multiplier's program itself (the whole program, twins and all)
    // by the dual simplex from scratch.
    let reference = least_from_scratch(&st.with_weight_as_live_load([1.0, 0.0]).unwrap());
    // Reference 2, by symmetry: the façade is symmetric about its vertical midline, and the
    // mirror image of a state under the load λ·W(+1, 0) is one under −λ·W(+1, 0), so the
    // multipliers in equilibrium form [−λ_max, λ_max].
    println!("λ_max {hi}, λ_min {lo}, from scratch {reference}");
    assert!(hi > 0.1, "{hi}");
    assert!((lo - reference).abs() <= 1e-9 * hi, "{lo} {reference}");
    assert!((lo + hi).abs() <= 1e-9 * hi, "{lo} {hi}");
}

#[test]
fn issue29_least_multiplier_without_twins_on_an_asymmetric_live_load() {
    // Since session 25 the symmetric façade's tilt takes its least multiplier from the mirror
    // image of the largest's optimum (`safety::least_by_mirror`), so the test above no longer
    // reaches the twins' path. Here the live load is the weight along (1, 0.25): its mirror
    // image (−1, 0.25) is not a multiple of it, so no mirror applies and the least multiplier
    // comes from `limit::least_program` (the crossover basis, the twins) — shown by the range
    // itself, which is not symmetric (λ_min ≠ −λ_max). Reference: the least multiplier's
    // program by the dual simplex from scratch.
    let st = facade_grid(2.0)
        .with_weight_as_live_load([1.0, 0.25])
        .unwrap();
    let map = KinematicMap::new(&st);
    let ipm = SolverOptions {
        method: Method::Ipm,
        ..SolverOptions::default()
    };
    let r = voussoir::analysis::limit::solve_limit_checked(&st, &map, &ipm).unwrap();
    let (hi, lo) = (r.lambda.unwrap(), r.least.unwrap());
    let reference = least_from_scratch(&st);
    println!("λ_max {hi}, λ_min {lo}, from scratch {reference}");
    assert!(hi > 0.1, "{hi}");
    assert!(
        (lo + hi).abs() > 1e-3 * hi,
        "the range is symmetric: {lo} {hi}"
    );
    assert!((lo - reference).abs() <= 1e-9 * hi, "{lo} {reference}");
}
