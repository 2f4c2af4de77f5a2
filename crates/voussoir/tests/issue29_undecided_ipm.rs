//! Found in session 22: `settle --move right=1cm,0,0 --friction 0.3` on the README's vault
//! (192 blocks) took 77 CPU s to answer "cannot stand". HiGHS's interior point (the default
//! for 3D programs with friction) found the motion program dual infeasible in 1.7 s, then
//! HiGHS "cleaned up" with the simplex from scratch for 24 s into "Solve error"; the fallback
//! chain's dual simplex ran 22 s into the same error before Clarabel decided in 0.2 s. HiGHS
//! now hands such a program on ("unbounded or infeasible without deciding which"), and the
//! chain asks Clarabel next: 4.8 CPU s, the same certified answer.

use voussoir::analysis::settlement::{certify_cannot_stand, settle_with, SettlementStatus};
use voussoir::generate::ArchSpec;
use voussoir::generate3d::{vault, Bond};
use voussoir::lp::{highs::UNDECIDED, Method, SolverOptions};
use voussoir::settlement_input::move_support;
use voussoir::{BuildOptions, Structure3d};

fn vault_mu(mu: f64) -> Structure3d {
    let mut m = vault(&ArchSpec::default(), 1.0, 3, Bond::Stack).unwrap();
    for mat in m.materials.values_mut() {
        mat.friction = Some(mu);
    }
    move_support(&mut m, "right", &[0.01, 0.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    Structure3d::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn issue29_an_interior_point_without_a_decision_hands_the_program_to_clarabel() {
    let st = vault_mu(0.3);
    let ipm = SolverOptions {
        method: Method::Ipm,
        ..SolverOptions::default()
    };
    let mut r = settle_with(&st, &ipm, Default::default()).unwrap();
    assert_eq!(r.status, SettlementStatus::CannotStand, "{}", r.message);
    // Clarabel answered right after the interior point: no HiGHS simplex in between.
    assert_eq!(r.solver.method, Method::Clarabel);
    assert_eq!(r.solver.tried.len(), 1, "{:?}", r.solver.tried);
    assert!(
        r.solver.tried[0].starts_with("ipm:"),
        "{:?}",
        r.solver.tried
    );
    assert!(
        r.solver.tried[0].contains(UNDECIDED),
        "{:?}",
        r.solver.tried
    );
    // The answer with its certificate: the dead loads' equilibrium decided infeasible by its
    // elastic program, a Farkas certificate checked on the program (a violation well above 0).
    certify_cannot_stand(&st, &mut r, &ipm, 8).unwrap();
    let c = r.no_equilibrium.as_ref().unwrap();
    assert!(c.ok, "{}", r.message);
    assert!(c.violation.unwrap() > 1e-3, "{:?}", c.violation);

    // The reference, independent of HiGHS: Clarabel asked directly gives the same status.
    let clarabel = SolverOptions {
        method: Method::Clarabel,
        ..SolverOptions::default()
    };
    let r2 = settle_with(&st, &clarabel, Default::default()).unwrap();
    assert_eq!(r2.status, SettlementStatus::CannotStand);

    // Where it stands (μ = 0.5), the interior point answers as before, certified, with no
    // fallback: the option changes nothing where HiGHS finds an optimum.
    let ok = settle_with(&vault_mu(0.5), &ipm, Default::default()).unwrap();
    assert_eq!(ok.status, SettlementStatus::Mechanism, "{}", ok.message);
    assert!(ok.certificate.as_ref().unwrap().ok, "{}", ok.message);
    assert_eq!(ok.solver.method, Method::Ipm);
    assert!(ok.solver.tried.is_empty(), "{:?}", ok.solver.tried);
}
