//! Issue 29 (session 29, lead): the force stage's trials in the size class of the least-μ
//! limit (docs/canonical.md "The forces"). Two changes of order, not of answers:
//!
//! - μ = 0 is tried after the limit's trial, and only where no trial has shown its μ
//!   inadmissible (the admissible sets are nested in μ): a column of blocks that drops with its
//!   foundation still reports μ = 0 (a hand value: its joints carry their weight straight
//!   down), where a wall whose least μ lies above the limit no longer pays a trial at 0.
//! - An armed trial (elastic trials not yet on) runs to at most `elastic_switch_iterations`
//!   iterations; one that reaches them is asked again as an elastic trial at the same μ. With
//!   the cap at one iteration every armed trial takes that path; the bracket must still hold
//!   the least μ of an independent bisection (`support::least_friction_by_bisection`, written
//!   out on the public programs) and the field must be the one the uncapped search reports (the
//!   same μ imposed, the same energy program).

mod support;
use support::{
    canonical_forces_of as forces, least_friction_by_bisection, settle_certified as settle,
    wall_settled,
};
use voussoir::analysis::canonical::{CanonicalOptions, FRICTION_SEARCH_LIMIT};

fn base() -> CanonicalOptions {
    CanonicalOptions {
        reaction_ranges: false,
        ..CanonicalOptions::default()
    }
}

#[test]
fn issue29_session29_a_column_dropping_with_its_foundation_needs_no_friction_in_the_size_class() {
    // `gen wall --courses 3 --units 1 --unit 1,0.5`, the whole foundation settling 1 cm: the
    // column drops as one body. By hand: work 3 × (1 × 0.5 × 1 m³) × 18 kN/m³ × 0.01 m = 0.27
    // kN·m, and the bed joints carry the weight above them with no shear: least μ 0.
    let st = wall_settled(3, 1, [1.0, 0.5], 0.0, 1.0, -0.01);
    let limited = settle(
        &st,
        CanonicalOptions {
            friction_limit_min_columns: 0,
            ..base()
        },
    );
    let default = settle(&st, base());
    let work = limited.work_dead_loads.expect("a mechanism");
    assert!((work - 0.27).abs() < 1e-9, "work {work}");
    for r in [&limited, &default] {
        let f = forces(r);
        assert_eq!(f.least_friction, Some(0.0));
        assert_eq!(f.friction, Some(0.0));
        assert_eq!(f.least_friction_above, None);
        for p in r.joints.iter().flat_map(|j| j.points.iter()) {
            assert!(p.shear_force.abs() <= 1e-9, "shear {}", p.shear_force);
        }
    }
    // The same answer by either order: the field and the mechanism to the bit.
    assert_eq!(
        serde_json::to_string(&limited.joints).unwrap(),
        serde_json::to_string(&default.joints).unwrap()
    );
    assert_eq!(limited.blocks, default.blocks);
}

#[test]
fn issue29_session29_an_armed_trial_at_its_cap_is_asked_as_an_elastic_trial() {
    // The session-28 wall (`gen wall --courses 10 --units 20 --unit 1,0.5`, settling 1 cm over
    // x 0–6 m), least μ 2.2306 by the reference: above the limit.
    let st = wall_settled(10, 20, [1.0, 0.5], 0.0, 6.0, -0.01);
    let sized = CanonicalOptions {
        friction_limit_min_columns: 0,
        elastic_trial_min_columns: 0,
        ..base()
    };
    let uncapped = settle(&st, sized);
    let capped = settle(
        &st,
        CanonicalOptions {
            elastic_switch_iterations: 1,
            ..sized
        },
    );
    let reference = least_friction_by_bisection(&st, &uncapped);
    assert!(reference > FRICTION_SEARCH_LIMIT, "reference {reference}");

    let f = forces(&capped);
    // The path taken: the trial at the limit reached its cap, and the elastic trials answered.
    assert!(f.elastic_trials >= 1, "elastic trials {}", f.elastic_trials);
    // The bracket holds the reference: 2 shown inadmissible below it, the admissible field's
    // ratio above it.
    assert_eq!(f.least_friction_above, Some(FRICTION_SEARCH_LIMIT));
    let upper = f.least_friction.expect("an admissible μ");
    assert!(
        upper >= reference * (1.0 - 1e-6),
        "upper {upper}, reference {reference}"
    );
    // The same μ imposed as without the cap, so the same least-energy field and mechanism.
    let g = forces(&uncapped);
    assert_eq!(f.friction, g.friction);
    assert_eq!(capped.blocks, uncapped.blocks);
    assert_eq!(capped.work_dead_loads, uncapped.work_dead_loads);
    let big = capped
        .joints
        .iter()
        .flat_map(|j| j.points.iter())
        .fold(0.0f64, |m, p| m.max(p.normal_force.abs()));
    for (a, b) in capped
        .joints
        .iter()
        .flat_map(|j| j.points.iter())
        .zip(uncapped.joints.iter().flat_map(|j| j.points.iter()))
    {
        assert!(
            (a.normal_force - b.normal_force).abs() <= 1e-9 * big
                && (a.shear_force - b.shear_force).abs() <= 1e-9 * big,
            "fields differ: ({}, {}) against ({}, {})",
            a.normal_force,
            a.shear_force,
            b.normal_force,
            b.shear_force
        );
    }
}
