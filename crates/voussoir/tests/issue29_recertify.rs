//! Issue 29 item 2, found in session 15: a settlement whose two LPs each pass the solver
//! layer's check (1e-6 on each program alone) can still leave the two works further apart than
//! the settlement's certificate allows (1e-7, docs/tolerances.md). `settle --raw --method
//! clarabel --friction 0.6` on a 30 × 20 stack-bond wall printed "WARNING: the duality gap
//! 2.204e-6 exceeds 1e-7: the result is not certified", while HiGHS's interior point with
//! crossover and its dual simplex certify the same settlement. The settlement analysis now
//! solves it again along the fallback chain and reports the first certified answer, naming
//! the uncertified one.

use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions};
use voussoir::analysis::settlement::{settle_with, SettlementForm, SettlementStatus};
use voussoir::generate::{wall, WallSpec};
use voussoir::lp::{Method, SolverOptions};
use voussoir::{BuildOptions, Structure};

/// A running-bond wall of `units` units of 1 × 0.5 m in `courses` courses on one foundation
/// segment per unit, friction `mu` on every joint, the first `settling` segments 1 cm down.
fn friction_wall_of(courses: usize, units: usize, mu: f64, settling: usize) -> Structure {
    let mut m = wall(&WallSpec {
        courses,
        units,
        unit: [1.0, 0.5],
        ..WallSpec::default()
    })
    .unwrap();
    for mat in m.materials.values_mut() {
        mat.friction = Some(mu);
    }
    for s in m.supports.iter_mut().take(settling) {
        s.motion = [0.0, -0.01, 0.0];
    }
    Structure::new(&m, BuildOptions::default()).unwrap()
}

/// 30 units in 20 courses (610 blocks, 30 foundation segments), μ = 0.6, the 9 segments under
/// x ∈ [0, 9] settling 1 cm.
fn friction_wall() -> Structure {
    friction_wall_of(20, 30, 0.6, 9)
}

#[test]
fn issue29_item2_an_uncertified_settlement_is_solved_again_and_says_so() {
    let st = friction_wall();
    let settle = |method| {
        settle_with(
            &st,
            &SolverOptions {
                method,
                ..SolverOptions::default()
            },
            SettlementForm::Both,
        )
        .unwrap()
    };
    let r = settle(Method::Clarabel);
    assert_eq!(r.status, SettlementStatus::Mechanism, "{}", r.message);
    let c = r.certificate.as_ref().unwrap();
    assert!(c.ok, "{}", r.message);
    assert!(c.relative_gap <= 1e-7, "{}", c.relative_gap);
    // The reference: the dual simplex, a vertex method independent of both interior points.
    let reference = settle(Method::DualSimplex);
    assert!(reference.certificate.as_ref().unwrap().ok);
    let (w, wref) = (
        r.work_dead_loads.unwrap(),
        reference.work_dead_loads.unwrap(),
    );
    assert!((w - wref).abs() <= 1e-6 * wref.abs(), "{w} against {wref}");
    // Where Clarabel's own answer certifies, nothing was re-solved and nothing is said; where
    // it did not, the answer names it and why.
    if r.solver.method != Method::Clarabel {
        assert!(
            r.solver
                .tried
                .iter()
                .any(|t| t.starts_with("clarabel at feasibility tolerance")),
            "{:?}",
            r.solver.tried
        );
        assert!(r.message.contains("after clarabel"), "{}", r.message);
    }
    assert!(!r.message.contains("WARNING"), "{}", r.message);

    // The default analysis (canonical selection, the policy's method for this class: HiGHS's
    // interior point with crossover) on the same wall: certified, the same work. Its
    // least-crack face is "infeasible" to the dual simplex from scratch; its extremes are then
    // found from the least-crack vertex's basis (before: the selection was dropped without a
    // word, after a second pass of 81 s from a dual-simplex vertex that ended the same way).
    let o = voussoir::lp::policy::options_for(&st, &SolverOptions::default(), false);
    assert_eq!(o.method, Method::Ipm);
    let c = settle_canonical(&st, &o, SettlementForm::Both, &CanonicalOptions::default()).unwrap();
    assert!(c.certificate.as_ref().unwrap().ok, "{}", c.message);
    let wc = c.work_dead_loads.unwrap();
    assert!(
        (wc - wref).abs() <= 1e-6 * wref.abs(),
        "{wc} against {wref}"
    );
    let mech = &c
        .canonical
        .as_ref()
        .expect("the selection is reached")
        .mechanism;
    // The selected mechanism is optimal: its crack area is at most the solver's own.
    assert!(
        mech.crack_area <= mech.crack_area_solver * (1.0 + 1e-9),
        "{} against {}",
        mech.crack_area,
        mech.crack_area_solver
    );
}

/// The 20 × 10 running-bond wall (205 blocks, 20 foundation segments) with μ = `mu`, the 6
/// segments under x ∈ [0, 6] settling 1 cm.
fn wall_near_least_friction(mu: f64) -> Structure {
    friction_wall_of(10, 20, mu, 6)
}

/// Found in session 22: near the least friction at which it stands on the other supports
/// (2.29 on this wall), the settlement's work is small (0.036 kN·m at μ = 2.0, 2e-3 of the
/// dead load times the settlement), and every method's force LP, optimal to the default
/// feasibility tolerance 1e-9, left its work 2e-8 to 1e-6 kN·m off the motion LP's: `settle
/// --friction 2.0` printed "WARNING: the duality gap 2.689e-5 exceeds 1e-7: the result is not
/// certified" with every method and with the canonical selection. The same method at 1e-10
/// certifies (gaps below 1e-12); both analyses now retry so and say so.
#[test]
fn issue29_item2_a_small_work_uncertified_at_1e9_is_solved_again_at_1e10() {
    // (μ = 2.2 fails and is recovered the same way: gap 5.0e-7 at 1e-9; one value keeps CI short.)
    for mu in [2.0] {
        let st = wall_near_least_friction(mu);
        // The defect as it was: the dual simplex's pair at 1e-9 does not certify (so that the
        // retry below is exercised; if HiGHS ever certifies it, this part says so).
        let map = voussoir::discretize::KinematicMap::new(&st);
        let first =
            voussoir::analysis::settlement::solve_settlement(&st, &map, &SolverOptions::default())
                .unwrap();
        let first_gap = (first.primal - first.dual).abs() / first.primal.abs();
        assert!(first_gap > 1e-7, "μ = {mu}: gap {first_gap:e} at 1e-9");

        // The reference: HiGHS's interior point with crossover at 1e-10, a method independent
        // of the dual simplex, its two LPs' works.
        let reference = voussoir::analysis::settlement::solve_settlement(
            &st,
            &map,
            &SolverOptions {
                method: Method::Ipm,
                feasibility_tolerance: 1e-10,
                ..SolverOptions::default()
            },
        )
        .unwrap();
        let wref = reference.primal;
        assert!(
            (reference.primal - reference.dual).abs() <= 1e-9 * wref,
            "μ = {mu}"
        );

        let raw = settle_with(&st, &SolverOptions::default(), SettlementForm::Both).unwrap();
        let canonical = settle_canonical(
            &st,
            &SolverOptions::default(),
            SettlementForm::Both,
            &CanonicalOptions::default(),
        )
        .unwrap();
        for r in [&raw, &canonical] {
            let c = r.certificate.as_ref().unwrap();
            assert!(c.ok && c.relative_gap <= 1e-7, "μ = {mu}: {}", r.message);
            assert!(!r.message.contains("WARNING"), "{}", r.message);
            let w = r.work_dead_loads.unwrap();
            assert!(
                (w - wref).abs() <= 1e-9 * wref,
                "μ = {mu}: {w} against {wref}"
            );
            assert_eq!(r.solver.method, Method::DualSimplex);
            assert!(
                r.solver
                    .tried
                    .iter()
                    .any(|t| t.starts_with("dual-simplex at feasibility tolerance 1e-9:")),
                "{:?}",
                r.solver.tried
            );
            assert!(r
                .message
                .contains("after dual-simplex at feasibility tolerance 1e-9"));
        }
    }
}
