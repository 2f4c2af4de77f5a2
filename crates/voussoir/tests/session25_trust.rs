//! Session 25, trust (helper h-trust): where no canonical force field certifies, the force
//! program's own optimum is reported (`selected_by: force_program`) and the least μ of the
//! bisection has no certified field; the summary printed it as "the least admissible μ =
//! 0.xxxx" all the same. No model found triggers the fallback from the command line (the
//! README wall's fields certify; the 0.35 m façade that failed took 7 minutes, see
//! issue29_cert025), so the fields are rejected with the testing option
//! `CanonicalOptions::reject_fields`, as issue29_cert025 does, and the summary line is the
//! library's (`CanonicalForces::summary_line`, which the CLI prints).

mod support;
use support::readme_wall;
use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions, ForceSelection};
use voussoir::analysis::settlement::SettlementForm;
use voussoir::lp::SolverOptions;

fn forces(reject: usize) -> voussoir::analysis::canonical::CanonicalForces {
    let st = readme_wall();
    let r = settle_canonical(
        &st,
        &SolverOptions::default(),
        SettlementForm::Both,
        &CanonicalOptions {
            reaction_ranges: false,
            reject_fields: reject,
            ..CanonicalOptions::default()
        },
    )
    .unwrap();
    r.canonical.unwrap().forces.unwrap()
}

#[test]
fn session25_the_least_mu_without_a_certified_field_is_said_uncertified() {
    // Both canonical fields rejected: the force program's optimum.
    let f = forces(2);
    assert_eq!(f.selected_by, ForceSelection::ForceProgram);
    assert_eq!(f.friction, None);
    let l = f
        .least_friction
        .expect("the wall's joints have no friction: a least μ");
    assert!(l > 0.0 && l < 100.0, "{l}");
    let line = f.summary_line();
    assert!(
        line.contains(&format!(
            "the least μ is not certified: the bisection's least admissible μ ({l:.4}) has no certified field"
        )),
        "{line}"
    );
    assert!(!line.contains("with the least admissible μ ="), "{line}");
    // The same μ where a field certifies (nothing rejected): printed as the least, with the
    // precision the bisection showed (5 % by default), and the same bisection's value.
    let g = forces(0);
    assert_eq!(g.selected_by, ForceSelection::LeastEnergy);
    assert_eq!(g.least_friction, Some(l));
    let p = g.friction_precision.unwrap();
    assert!(p > 0.0 && p <= 0.05, "{p}");
    let line = g.summary_line();
    assert!(
        line.starts_with(&format!(
            "canonical forces: least complementary energy, open points unloaded, |shear| ≤ μ·normal with the least admissible μ = {l:.4} (to "
        )),
        "{line}"
    );
}
