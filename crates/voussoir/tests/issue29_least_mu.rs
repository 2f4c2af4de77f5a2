//! Issue 29, item 5 (session 17): the least friction coefficient of the canonical force stage
//! by the ratio search (`FrictionSearch::Ratio`: a Dinkelbach-type iteration on the generalised
//! fractional program `min max_k |p_t,k| / p_n,k`, with decisive trials below; docs/canonical.md
//! "The forces"), against a closed form, an independent fine bisection written out on the public
//! programs, and the bisection of the force stage itself (`FrictionSearch::Bisection`).
//!
//! What each check catches: the reported least μ is a field's own ratio, so it can only be
//! below the reference if a field was misread; the μ the result says was shown inadmissible,
//! `least · (1 − friction_precision)`, must be below the reference (a false certificate of
//! inadmissibility would put it above); and the precision shown must be the one asked.

mod support;
use support::{least_friction_by_bisection, readme_wall, stack_wall_20x10};
use voussoir::analysis::canonical::{
    limit_canonical, settle_canonical, CanonicalForces, CanonicalOptions, FrictionSearch,
};
use voussoir::analysis::limit::DEFAULT_FACETS;
use voussoir::analysis::settlement::SettlementForm;
use voussoir::analysis::SettlementResult;
use voussoir::generate::{wall, LiveLoad, WallSpec};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure};

fn options(search: FrictionSearch, precision: f64) -> CanonicalOptions {
    CanonicalOptions {
        reaction_ranges: false,
        friction_precision: precision,
        friction_search: search,
        ..CanonicalOptions::default()
    }
}

fn forces(r: &SettlementResult) -> &CanonicalForces<voussoir::dim::Two> {
    r.canonical.as_ref().unwrap().forces.as_ref().unwrap()
}

/// The bracket a result states: (least μ shown admissible, largest μ shown inadmissible).
fn bracket(f: &CanonicalForces<voussoir::dim::Two>) -> (f64, f64) {
    let least = f.least_friction.expect("a least friction coefficient");
    let p = f.friction_precision.expect("a precision");
    (least, least * (1.0 - p))
}

/// One block `b × h` on its foundation under a horizontal live load: it tips about its toe at
/// λ = b/h, and the toe then carries the whole reaction, normal W and shear λW (the heel opens,
/// sliding is excluded by Heyman's rule). The field is unique; the least μ is b/h exactly, and
/// no μ below it is admissible.
#[test]
fn issue29_least_mu_ratio_search_tipping_block_is_b_over_h() {
    for (b, h) in [(1.0, 2.0), (1.5, 2.0), (0.4, 1.0)] {
        let m = wall(&WallSpec {
            courses: 1,
            units: 1,
            unit: [b, h],
            live: LiveLoad::Horizontal,
            ..WallSpec::default()
        })
        .unwrap();
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let r = limit_canonical(
            &st,
            &SolverOptions::default(),
            DEFAULT_FACETS,
            &options(FrictionSearch::Ratio, 0.05),
        )
        .unwrap();
        let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
        let hand = b / h;
        let least = f.least_friction.expect("a least friction coefficient");
        let p = f.friction_precision.expect("a precision");
        assert!(
            (least - hand).abs() <= 1e-6 * hand,
            "b/h {hand}: least μ {least}"
        );
        assert!(p > 0.0 && p <= 0.05, "precision shown {p}");
        assert!(least * (1.0 - p) < hand, "shown inadmissible above b/h");
        let mu = f.friction.expect("the μ imposed");
        assert!(mu >= least && mu <= least * 1.03, "imposed {mu}");
    }
}

/// The README's wall (least μ 1.2029, docs/canonical.md) and a 20 × 10 stack-bond wall (the
/// 3,200-block wall of issue 29 at a sixteenth of its size), at the default precision and at
/// 1e-4: the ratio search's bracket holds the least μ of an independent bisection to 1e-6, its
/// precision is the one asked, and it agrees with the force stage's bisection to the precision.
#[test]
fn issue29_least_mu_ratio_search_against_bisection() {
    let stack = stack_wall_20x10();
    let o = SolverOptions::default();
    for (name, st) in [("README wall", readme_wall()), ("20 × 10 wall", stack)] {
        let mut reference = None;
        for precision in [0.05, 1e-4] {
            let ratio = settle_canonical(
                &st,
                &o,
                SettlementForm::Both,
                &options(FrictionSearch::Ratio, precision),
            )
            .unwrap();
            assert!(ratio.certificate.as_ref().unwrap().ok, "{name}");
            let bis = settle_canonical(
                &st,
                &o,
                SettlementForm::Both,
                &options(FrictionSearch::Bisection, precision),
            )
            .unwrap();
            let hi = *reference.get_or_insert_with(|| least_friction_by_bisection(&st, &ratio));
            let (fr, fb) = (forces(&ratio), forces(&bis));
            let (least, shown) = bracket(fr);
            let (least_b, _) = bracket(fb);
            println!(
                "{name}, precision {precision}: ratio search {least} (shown inadmissible {shown}, \
                 {} programs), bisection {least_b} ({} programs), reference {hi}",
                fr.solves, fb.solves
            );
            assert!(fr.physical);
            assert!(least >= hi * (1.0 - 1e-5), "{name}: {least} below {hi}");
            assert!(
                shown <= hi * (1.0 + 1e-5),
                "{name}: {shown} shown inadmissible, least {hi}"
            );
            let p = fr.friction_precision.unwrap();
            assert!(p <= precision, "{name}: precision {p} asked {precision}");
            assert!(
                (least - least_b).abs() <= precision * least_b * (1.0 + 1e-6),
                "{name}: ratio search {least}, bisection {least_b}"
            );
            // The reported field holds Coulomb's rule at the μ imposed.
            let mu = fr.friction.unwrap();
            assert!(mu >= least);
            assert!(fr.friction_demand.unwrap() <= mu * (1.0 + 1e-6));
            // The same work and hinges as the bisection's result (the mechanism is shared).
            assert_eq!(ratio.hinges, bis.hinges, "{name}");
        }
    }
}
