//! Issue 29, item 5: the canonical force stage (docs/canonical.md, "The forces").
//!
//! The least friction coefficient against a closed form, and what the result says when the
//! energy QP does not end optimal (the admissible field of the bisection stands, and
//! `selected_by` says so instead of the solver's forces coming back silently).

mod support;
use support::readme_wall;
use voussoir::analysis::canonical::{
    limit_canonical, settle_canonical, CanonicalOptions, ForceSelection,
};
use voussoir::analysis::limit::DEFAULT_FACETS;
use voussoir::analysis::settlement::SettlementForm;
use voussoir::generate::{wall, LiveLoad, WallSpec};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure};

/// One block `b × h` on its foundation, with a horizontal live load equal to its weight.
fn tilting_block(b: f64, h: f64) -> Structure {
    let m = wall(&WallSpec {
        courses: 1,
        units: 1,
        unit: [b, h],
        live: LiveLoad::Horizontal,
        ..WallSpec::default()
    })
    .unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

/// By hand: the block tips about its toe at λ = b/h (moments about the toe: λW·h/2 = W·b/2;
/// sliding is excluded by Heyman's no-sliding rule). At collapse the heel opens and carries
/// nothing, so the toe carries the whole reaction: normal W, shear λW. The least μ admitting
/// that (unique) field is λ = b/h; the bisection reports it from above to 1e-4.
#[test]
fn issue29_item5_least_friction_of_a_tipping_block_is_b_over_h() {
    for (b, h) in [(1.0, 2.0), (1.5, 2.0), (0.4, 1.0)] {
        let st = tilting_block(b, h);
        let r = limit_canonical(
            &st,
            &SolverOptions::default(),
            DEFAULT_FACETS,
            &CanonicalOptions::default(),
        )
        .unwrap();
        let lambda = r.load_multiplier.unwrap();
        let hand = b / h;
        assert!(
            (lambda - hand).abs() <= 1e-9 * hand,
            "λ {lambda}, by hand {hand}"
        );
        let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
        assert!(f.physical);
        assert_eq!(f.selected_by, ForceSelection::LeastEnergy);
        let mu = f.least_friction.expect("a least friction coefficient");
        assert!(
            mu >= hand * (1.0 - 1e-7) && mu <= hand * (1.0 + 1e-4) + 1e-7,
            "b/h {hand}: least μ {mu}"
        );
        // The reaction: the whole weight W = 18 kN/m³ · b·h·1 m and the shear λW.
        let w = 18.0 * b * h;
        let re = &r.reactions[0];
        assert!((re.fy - w).abs() <= 1e-6 * w, "{re:?}, W {w}");
        assert!((re.fx.abs() - hand * w).abs() <= 1e-6 * w, "{re:?}");
    }
}

/// With an iteration limit of 1 the energy QP (Clarabel, no fallback chain: the only backend
/// with quadratic objectives) stops at its limit; the feasibility programs of the bisection fall
/// back along the solver layer's chain and answer. The reported field is then the admissible
/// field of the bisection's upper bracket, and the result says so (`selected_by: admissible`):
/// still physical (open points unloaded, Coulomb at the reported μ), still in equilibrium
/// (the duality certificate holds), with the same least μ as the default run.
#[test]
fn issue29_item5_energy_qp_failure_keeps_an_admissible_field_and_says_so() {
    let st = readme_wall();
    let copts = CanonicalOptions {
        reaction_ranges: false,
        friction_precision: 1e-4,
        ..CanonicalOptions::default()
    };
    let normal =
        settle_canonical(&st, &SolverOptions::default(), SettlementForm::Both, &copts).unwrap();
    let fa = normal.canonical.as_ref().unwrap().forces.as_ref().unwrap();
    assert_eq!(fa.selected_by, ForceSelection::LeastEnergy);
    let limited = SolverOptions {
        iteration_limit: Some(1),
        ..SolverOptions::default()
    };
    let r = settle_canonical(&st, &limited, SettlementForm::Both, &copts).unwrap();
    assert!(r.certificate.as_ref().unwrap().ok, "{:?}", r.certificate);
    let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
    assert_eq!(f.selected_by, ForceSelection::Admissible);
    assert!(f.physical);
    let (m0, m1) = (fa.least_friction.unwrap(), f.least_friction.unwrap());
    assert!((m0 - m1).abs() <= 2e-4 * m0, "least μ {m0} and {m1}");
    // Open points carry nothing; |shear| ≤ μ·normal everywhere (kN; forces of order 10 kN).
    let big = r
        .joints
        .iter()
        .flat_map(|j| &j.points)
        .fold(0.0f64, |m, p| m.max(p.opening.abs()));
    let mut carried = 0.0f64;
    for p in r.joints.iter().flat_map(|j| &j.points) {
        if p.opening > 1e-7 * big {
            assert!(
                p.normal_force.abs() <= 1e-7 && p.shear_force.abs() <= 1e-7,
                "{p:?}"
            );
        }
        assert!(
            p.shear_force.abs() <= f.friction.unwrap() * p.normal_force + 1e-6,
            "{p:?}"
        );
        carried += p.normal_force.abs();
    }
    assert!(carried > 1.0, "a field, not zeros");
    assert!(f.largest_friction_excess <= 1e-6 && f.largest_open_force <= 1e-7);
}
