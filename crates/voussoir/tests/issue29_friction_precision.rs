//! Issue 29, items 4 and 5 (session 14): the canonical force stage and the early uniqueness
//! test at the cost the issue asks (docs/canonical.md, "Cost").
//!
//! * The least friction coefficient is found to a relative precision (default 5 %): the
//!   reported `least_friction` is an admissible μ (a field needs no more) and no field admits
//!   `least_friction · (1 − precision)`. Checked against an independent bisection written out
//!   on the public programs, to 1e-6.
//! * The early uniqueness test keeps the answer the fallback chain gives once the primal
//!   simplex reaches its pivot cap, instead of solving both faces' extremes from scratch.

mod support;
use support::{least_friction_by_bisection, readme_wall, stack_wall_20x10};
use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions, Selection};
use voussoir::analysis::settlement::{settle, SettlementForm};
use voussoir::lp::SolverOptions;

#[test]
fn issue29_item5_least_friction_to_its_precision_against_a_bisection() {
    let st = readme_wall();
    for precision in [0.05, 0.01] {
        let r = settle_canonical(
            &st,
            &SolverOptions::default(),
            SettlementForm::Both,
            &CanonicalOptions {
                reaction_ranges: false,
                friction_precision: precision,
                ..CanonicalOptions::default()
            },
        )
        .unwrap();
        assert!(r.certificate.as_ref().unwrap().ok);
        let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
        assert!(f.physical);
        // The precision shown (every trial decided on this wall): at most the one asked.
        let shown = f.friction_precision.expect("a precision");
        assert!(shown > 0.0 && shown <= precision, "{shown}");
        let least = f.least_friction.expect("a least friction coefficient");
        let imposed = f.friction.expect("the μ imposed");
        assert!(
            imposed >= least,
            "imposed {imposed} below the least {least}"
        );
        // The reported field: open points unloaded, |shear| ≤ μ·normal with the imposed μ, and
        // the friction it needs (`friction_demand`) is at most that μ.
        let demand = f.friction_demand.expect("a friction demand");
        assert!(demand <= imposed * (1.0 + 1e-6), "{demand} > {imposed}");
        let big = r
            .joints
            .iter()
            .flat_map(|j| &j.points)
            .fold(0.0f64, |m, p| m.max(p.normal_force.abs()));
        for p in r.joints.iter().flat_map(|j| &j.points) {
            assert!(
                p.shear_force.abs() <= imposed * p.normal_force + 1e-7 * big,
                "{p:?}"
            );
        }
        // The reference: the least μ by an independent bisection on [0, 8] to 1e-6.
        let hi = least_friction_by_bisection(&st, &r);
        println!("precision {precision}: least μ {least} (imposed {imposed}), reference {hi}");
        // From above, within the precision (and the solvers' tolerance).
        assert!(least >= hi * (1.0 - 1e-5), "least μ {least} below {hi}");
        assert!(
            least <= hi / (1.0 - shown) * (1.0 + 1e-5),
            "least μ {least} beyond {shown} of {hi}"
        );
    }
}

/// A 20 × 10 stack-bond wall (1 × 0.5 m blocks on 20 foundation segments, the left 30 % of
/// the base settling 1 cm; the 3,200-block wall of issue 29 at a sixteenth of its size). Its
/// optimal mechanism is unique; the early test's warm extremes take 14 and 35 primal simplex
/// pivots. With the pivot cap at 5 both reach it and the fallback chain (the dual simplex)
/// answers: the early test must still settle uniqueness in its three programs (stage 2 and
/// the two extremes), where before it gave up and solved the extremes of both faces from
/// scratch (seven programs; 27 s of the 3,200-block wall's 30 s of mechanism stages). The
/// reference: the solver's own mechanism and work, unchanged, and the uncapped selection.
#[test]
fn issue29_item5_early_uniqueness_test_keeps_the_fallback_answer() {
    let st = stack_wall_20x10();
    assert_eq!(st.num_blocks(), 200);
    let o = SolverOptions::default();
    let raw = settle(&st, &o).unwrap();
    let mut results = Vec::new();
    for pivots in [5, CanonicalOptions::default().unique_pivots] {
        let can = settle_canonical(
            &st,
            &o,
            SettlementForm::Both,
            &CanonicalOptions {
                reaction_ranges: false,
                forces: false,
                unique_pivots: pivots,
                ..CanonicalOptions::default()
            },
        )
        .unwrap();
        let c = can.canonical.clone().expect("a canonical record");
        assert!(c.mechanism.unique, "cap {pivots}: {c:?}");
        assert_eq!(c.mechanism.selected_by, Selection::Optimum);
        assert!(!c.mechanism.changed);
        assert_eq!(
            c.mechanism.solves, 3,
            "cap {pivots}: the early test did not settle uniqueness"
        );
        let (w0, w) = (raw.work_dead_loads.unwrap(), can.work_dead_loads.unwrap());
        assert!((w - w0).abs() <= 1e-9 * w0, "work {w} against {w0}");
        assert_eq!(raw.hinges, can.hinges);
        results.push(can.hinges.clone());
    }
    assert_eq!(results[0], results[1]);
}
