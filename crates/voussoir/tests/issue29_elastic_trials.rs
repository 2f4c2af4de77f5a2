//! Issue 29, items 4–6 (session 21): the least-μ bisection of the canonical force stage asks
//! its trials first as bounded elastic programs on large 2D models (`lp::policy::
//! elastic_trials`; docs/canonical.md "The forces"). Clarabel proves a nearly feasible trial
//! infeasible slowly (15–20 s on the 0.5 m façade in running bond, where a feasible one takes
//! 2–4 s); the elastic program answers the same question in the time of a feasible one.
//!
//! Checked on small models with the elastic trials forced on (`CanonicalOptions::
//! elastic_trials`): the bracket the result states holds the least μ of an independent fine
//! bisection (`support::least_friction_by_bisection`, to 1e-6) — a false "inadmissible" from an
//! elastic trial would put the μ shown inadmissible above it, a misread field the least below
//! it — at the precision asked, within that precision of the feasibility trials' bisection,
//! with the same mechanism; and the trials were in fact decided by elastic programs. With the
//! default options these models stay below the policy's size: no elastic trial, results as
//! before.

mod support;
use support::{least_friction_by_bisection, readme_wall, stack_wall_20x10};
use voussoir::analysis::canonical::{settle_canonical, CanonicalForces, CanonicalOptions};
use voussoir::analysis::settlement::SettlementForm;
use voussoir::analysis::SettlementResult;
use voussoir::lp::policy::{elastic_trials, ELASTIC_TRIAL_MIN_COLUMNS};
use voussoir::lp::SolverOptions;

fn options(elastic: Option<bool>, precision: f64) -> CanonicalOptions {
    CanonicalOptions {
        reaction_ranges: false,
        friction_precision: precision,
        elastic_trials: elastic,
        ..CanonicalOptions::default()
    }
}

fn forces(r: &SettlementResult) -> &CanonicalForces<voussoir::dim::Two> {
    r.canonical.as_ref().unwrap().forces.as_ref().unwrap()
}

#[test]
fn issue29_elastic_trials_bracket_the_least_mu() {
    assert!(elastic_trials(ELASTIC_TRIAL_MIN_COLUMNS));
    assert!(!elastic_trials(ELASTIC_TRIAL_MIN_COLUMNS - 1));
    let o = SolverOptions::default();
    for (name, st) in [
        ("README wall", readme_wall()),
        ("20 × 10 wall", stack_wall_20x10()),
    ] {
        let mut reference = None;
        for precision in [0.05, 1e-4] {
            let run = |elastic| {
                settle_canonical(&st, &o, SettlementForm::Both, &options(elastic, precision))
                    .unwrap()
            };
            let (el, feas, default) = (run(Some(true)), run(Some(false)), run(None));
            assert!(el.certificate.as_ref().unwrap().ok, "{name}");
            let hi = *reference.get_or_insert_with(|| least_friction_by_bisection(&st, &el));
            let (fe, ff) = (forces(&el), forces(&feas));
            let least = fe.least_friction.expect("a least μ");
            let p = fe.friction_precision.expect("a precision");
            let least_f = ff.least_friction.expect("a least μ");
            println!(
                "{name}, precision {precision}: elastic {least} (precision {p}, {} of {} \
                 programs elastic), feasibility trials {least_f} ({} programs), reference {hi}",
                fe.elastic_trials, fe.solves, ff.solves
            );
            assert!(fe.elastic_trials > 0, "{name}: no trial was elastic");
            assert_eq!(ff.elastic_trials, 0, "{name}");
            assert!(fe.physical, "{name}");
            assert!(least >= hi * (1.0 - 1e-5), "{name}: {least} below {hi}");
            assert!(
                least * (1.0 - p) <= hi * (1.0 + 1e-5),
                "{name}: {} shown inadmissible, least {hi}",
                least * (1.0 - p)
            );
            assert!(p <= precision, "{name}: precision {p}, asked {precision}");
            assert!(
                (least - least_f).abs() <= precision * least_f * (1.0 + 1e-6),
                "{name}: elastic {least}, feasibility {least_f}"
            );
            // The reported field holds Coulomb's rule at the μ imposed.
            let mu = fe.friction.unwrap();
            assert!(mu >= least);
            assert!(fe.friction_demand.unwrap() <= mu * (1.0 + 1e-6), "{name}");
            assert_eq!(el.hinges, feas.hinges, "{name}");
            // Below the policy's size the default is the feasibility trials: the same result.
            assert_eq!(forces(&default), ff, "{name}");
        }
    }
}
