//! Issue 29, item 5: the energy QP of the canonical force stage has an iteration cap
//! (`CanonicalOptions::energy_qp_iterations`, default `ENERGY_QP_ITERATIONS`).
//!
//! On the façade in running bond at 0.25 m (10,163 blocks) the QP iterated to Clarabel's own
//! limit of 500 (280–465 s) among point forces of 4.4e7 kN, and its point then failed the
//! duality certificate: the admissible field was reported. A QP that reaches the cap is not
//! used — even where Clarabel calls its last point "almost solved" — and the result names the
//! cap in `rejected` (docs/performance.md, "Canonical force stage at 0.25 m (session 16)").
//! The README wall's QP ends in a few dozen iterations; a cap of 2 makes it stop there.

mod support;
use support::readme_wall;
use voussoir::analysis::canonical::{
    settle_canonical, tributary_weights, CanonicalOptions, ForceSelection, ENERGY_QP_ITERATIONS,
};
use voussoir::analysis::settlement::{settle_with, SettlementForm, SettlementResult};
use voussoir::discretize::KinematicMap;
use voussoir::lp::{Method, SolverOptions};
use voussoir::Structure;

/// The settlement's optimal work by the raw analysis with another method (primal simplex; the
/// canonical selection's motion program runs on the dual simplex, its forces on Clarabel).
fn reference_work(st: &Structure) -> f64 {
    let o = SolverOptions {
        method: Method::PrimalSimplex,
        ..SolverOptions::default()
    };
    let r = settle_with(st, &o, SettlementForm::Both).unwrap();
    assert!(r.certificate.as_ref().unwrap().ok);
    r.work_dead_loads.unwrap()
}

fn capped(cap: usize) -> CanonicalOptions {
    CanonicalOptions {
        reaction_ranges: false,
        energy_qp_iterations: cap,
        ..CanonicalOptions::default()
    }
}

/// The complementary energy `Σ (p_n² + p_t²) / w_k` of a reported field (the QP's objective,
/// up to its factor ½), with the tributary weights of the selection.
fn energy(st: &Structure, r: &SettlementResult) -> f64 {
    let map = KinematicMap::new(st);
    let w = tributary_weights(st, &map);
    let pts: Vec<(f64, f64)> = r
        .joints
        .iter()
        .flat_map(|j| j.points.iter().map(|p| (p.normal_force, p.shear_force)))
        .collect();
    assert_eq!(pts.len(), w.len());
    pts.iter()
        .zip(&w)
        .map(|(&(n, t), &w)| (n * n + t * t) / w)
        .sum()
}

/// With the QP capped at 2 iterations it stops there; the admissible field of the bisection's
/// upper bracket is reported, certified (both works equal the primal simplex's optimum to
/// 1e-6), and `rejected` names the least-energy field with the cap as its reason (no gap:
/// no field was computed). Uncapped (the default cap), the least-energy field is reported with
/// nothing rejected, at the same μ, and its energy is at most the admissible field's (which is
/// feasible for the same QP).
#[test]
fn issue29_item5_capped_energy_qp_is_named_in_rejected() {
    let st = readme_wall();
    let w = reference_work(&st);
    let o = SolverOptions::default();
    let full =
        settle_canonical(&st, &o, SettlementForm::Both, &capped(ENERGY_QP_ITERATIONS)).unwrap();
    let cut = settle_canonical(&st, &o, SettlementForm::Both, &capped(2)).unwrap();
    for (name, r) in [("default cap", &full), ("cap 2", &cut)] {
        let c = r.certificate.as_ref().unwrap();
        assert!(c.ok && c.relative_gap <= 1e-7, "{name}: {c:?}");
        for work in [r.work_dead_loads.unwrap(), r.work_reactions.unwrap()] {
            assert!((work - w).abs() <= 1e-6 * w, "{name}: {work} vs {w}");
        }
        assert!(c.equilibrium_residual <= 1e-6, "{name}: {c:?}");
    }
    let ff = full.canonical.as_ref().unwrap().forces.as_ref().unwrap();
    assert_eq!(ff.selected_by, ForceSelection::LeastEnergy);
    assert!(ff.rejected.is_empty(), "{:?}", ff.rejected);
    let fc = cut.canonical.as_ref().unwrap().forces.as_ref().unwrap();
    assert_eq!(fc.selected_by, ForceSelection::Admissible);
    assert!(fc.physical);
    assert_eq!(fc.rejected.len(), 1, "{:?}", fc.rejected);
    let rej = &fc.rejected[0];
    assert_eq!(rej.field, ForceSelection::LeastEnergy);
    assert_eq!(rej.gap, None);
    let reason = rej.reason.as_deref().unwrap();
    assert!(
        reason.starts_with("the energy QP stopped at its cap of 2 iterations"),
        "{reason}"
    );
    // The same bisection, so the same μ imposed on both fields.
    assert_eq!(ff.friction, fc.friction);
    assert_eq!(ff.least_friction, fc.least_friction);
    // Least energy: no more than the admissible field's (1e-6 for the QP's tolerance).
    let (ef, ec) = (energy(&st, &full), energy(&st, &cut));
    assert!(
        ef <= ec * (1.0 + 1e-6),
        "least energy {ef} vs admissible {ec}"
    );
    // In JSON: the reason, and no gap.
    let json = serde_json::to_value(fc).unwrap();
    assert_eq!(json["selected_by"], "admissible");
    assert_eq!(json["rejected"][0]["field"], "least_energy");
    assert_eq!(json["rejected"][0]["reason"].as_str(), Some(reason));
    assert!(json["rejected"][0].get("gap").is_none());
}

/// An iteration limit of the solver options below the cap holds too, and the reason names it;
/// a field rejected by its certificate keeps its gap and no reason.
#[test]
fn issue29_item5_solver_iteration_limit_caps_the_energy_qp_too() {
    let st = readme_wall();
    let o = SolverOptions {
        iteration_limit: Some(1),
        ..SolverOptions::default()
    };
    let r = settle_canonical(&st, &o, SettlementForm::Both, &capped(ENERGY_QP_ITERATIONS)).unwrap();
    let c = r.certificate.as_ref().unwrap();
    assert!(c.ok && c.relative_gap <= 1e-7, "{c:?}");
    let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
    assert_eq!(f.selected_by, ForceSelection::Admissible);
    let reason = f.rejected[0].reason.as_deref().unwrap();
    assert!(
        reason.starts_with("the energy QP stopped at its cap of 1 iteration"),
        "{reason}"
    );
    // The certificate's fallback (issue29_cert025): the least-energy field rejected by its
    // gap is listed with the gap, without a reason.
    let r = settle_canonical(
        &st,
        &SolverOptions::default(),
        SettlementForm::Both,
        &CanonicalOptions {
            reject_fields: 1,
            ..capped(ENERGY_QP_ITERATIONS)
        },
    )
    .unwrap();
    let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
    assert_eq!(f.selected_by, ForceSelection::Admissible);
    assert_eq!(f.rejected.len(), 1);
    assert!(f.rejected[0].gap.unwrap() <= 1e-7);
    assert_eq!(f.rejected[0].reason, None);
}
