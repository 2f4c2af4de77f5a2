//! Non-associative Coulomb friction in the settlement analysis (issue #17, item 3).
//!
//! The classic case: a running-bond wall with friction over a settling end cracks along a
//! stepped diagonal through head and bed joints, whose slope follows the bond: for units
//! b × h laid in half bond the staircase rises one course (h) per half unit (b/2), a slope
//! of 2h/b. With associative friction the sliding joints open as they slide (dilatancy
//! μ·|slip|); with the non-associative law they slide closed.

mod support;
use voussoir::analysis::nonassociative::{settle_nonassociative, NonAssociativeOptions};
use voussoir::analysis::settlement::settle_crushing;
use voussoir::analysis::{Crushing, SettlementResult, SettlementStatus};
use voussoir::generate::{wall, WallSpec};
use voussoir::lp::{Method, SolverOptions};
use voussoir::settlement_input::{apply_profile, Profile};
use voussoir::{BuildOptions, Structure};

const B: f64 = 0.4;
const H: f64 = 0.2;
const SETTLEMENT: f64 = 0.01;

/// 20 units × 10 courses, μ = 0.6, the right third of the foundation (x ≥ 16/3 m) down 1 cm.
fn friction_wall() -> Structure {
    support::friction_wall_20x10(20.0 * B * 2.0 / 3.0, 20.0 * B + 1.0)
}

/// The crack: per course, the x between the last block that stays (|v| < ½ of the settlement
/// at its centroid) and the first that goes down with the settling part. Returns the slope of
/// the least-squares line y(x) through those points, and the median of the slopes of the
/// steps from one course to the next (the staircase's own step).
fn crack_slope(st: &Structure, r: &SettlementResult) -> (f64, f64) {
    let mut pts = Vec::new();
    for c in 0..10 {
        let y = (c as f64 + 0.5) * H;
        let mut row: Vec<(f64, f64)> = st
            .blocks
            .iter()
            .zip(&r.blocks)
            .filter(|(b, _)| (b.centroid[1] - y).abs() < 0.25 * H)
            .map(|(b, m)| {
                let c = b.centroid;
                (c[0], m.motion.v)
            })
            .collect();
        row.sort_by(|a, b| a.0.total_cmp(&b.0));
        if let Some(i) = row.iter().position(|(_, v)| *v < -0.5 * SETTLEMENT) {
            if i > 0 {
                pts.push((0.5 * (row[i - 1].0 + row[i].0), y));
            }
        }
    }
    assert!(pts.len() >= 6, "crack found in {} courses only", pts.len());
    let n = pts.len() as f64;
    let (mx, my) = pts
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0 / n, b + p.1 / n));
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let mut steps: Vec<f64> = pts
        .windows(2)
        .filter(|w| w[1].0 != w[0].0)
        .map(|w| (w[1].1 - w[0].1) / (w[1].0 - w[0].0))
        .collect();
    steps.sort_by(f64::total_cmp);
    (sxy / sxx, steps[steps.len() / 2])
}

/// Largest opening at a point that slides (by more than 1 % of the settlement) while it
/// carries compression, relative to the settlement: the dilatancy (a joint that has come
/// apart may move any way; one in contact opens only by dilating).
fn dilatancy(r: &SettlementResult) -> (usize, f64) {
    let fmax = r
        .joints
        .iter()
        .flat_map(|j| j.points.iter())
        .fold(0.0f64, |m, p| m.max(p.normal_force));
    let mut n = 0;
    let mut worst = 0.0f64;
    for j in &r.joints {
        for p in &j.points {
            if p.sliding.abs() > 0.01 * SETTLEMENT && p.normal_force > 1e-6 * fmax {
                n += 1;
                worst = worst.max(p.opening / SETTLEMENT);
            }
        }
    }
    (n, worst)
}

#[test]
fn friction_wall_over_a_settling_end_cracks_along_the_bond_without_dilatancy() {
    let st = friction_wall();
    let clarabel = SolverOptions {
        method: Method::Clarabel,
        feasibility_tolerance: 1e-10,
        ..SolverOptions::default()
    };
    let non = settle_nonassociative(
        &st,
        &clarabel,
        Crushing::Linear,
        16,
        &NonAssociativeOptions::settlement(),
    )
    .unwrap();
    let it = non.friction_iteration.as_ref().unwrap();
    assert_eq!(non.status, SettlementStatus::Mechanism);
    assert!(it.converged, "{:?}", it.history);
    assert!(non.certificate.as_ref().unwrap().ok, "{}", non.message);
    let ass = settle_crushing(&st, &SolverOptions::default(), Crushing::Linear, 16).unwrap();
    assert!(ass.certificate.as_ref().unwrap().ok);

    // The stepped crack: its typical step is the bond's, one course per half unit (2h/b = 1,
    // exactly: block positions); overall it rises somewhat more steeply (measured 1.30: the
    // crack starts over the settlement's edge and turns up in the top course).
    let bond = 2.0 * H / B;
    let (fit, step) = crack_slope(&st, &non);
    let (fit_a, step_a) = crack_slope(&st, &ass);
    eprintln!("crack slope: non-associative fit {fit:.3}, step {step:.3}; associative fit {fit_a:.3}, step {step_a:.3} (bond {bond})");
    assert!((step - bond).abs() < 1e-9, "step slope {step}");
    assert!(fit >= bond && fit <= 1.5 * bond, "fitted slope {fit}");

    // Sliding without opening: at every point that slides in contact the opening is below
    // 1e-6 of the settlement (solver tolerance), where the associative law opens μ·|slip|.
    let (n_non, d_non) = dilatancy(&non);
    let (n_ass, d_ass) = dilatancy(&ass);
    eprintln!("sliding points: non-associative {n_non} (dilatancy {d_non:.2e}), associative {n_ass} (dilatancy {d_ass:.2e})");
    assert!(n_non > 0, "no joint slides");
    assert!(
        d_non < 1e-6,
        "non-associative joints open by {d_non} of the settlement"
    );
    assert!(d_ass > 0.1, "associative dilatancy {d_ass}");
    // The associative work (Clarabel, where the iteration starts) is the simplex's.
    let (wa, wb) = (it.associative.unwrap(), ass.work_dead_loads.unwrap());
    assert!((wa - wb).abs() <= 1e-7 * wb, "{wa} vs {wb}");
    eprintln!(
        "work: associative {wb:.6}, non-associative {:.6} after {} iterations",
        non.work_dead_loads.unwrap(),
        it.history.len()
    );
}

/// Capacity after a settlement with non-associative friction: a 8 × 5 wall, μ = 0.6, pushed
/// by a horizontal live load equal to its weight, the foundation under x ∈ [2.1, 3.3] m down
/// 1 cm. Undeformed, the wall slides on its base as one body: λ = μ (closed form). After the
/// settlement the associative law has dilated the cracked part apart (no equilibrium at all),
/// while without dilatancy the wall still carries a horizontal load, less than before.
#[test]
fn capacity_with_non_associative_friction_keeps_a_settled_wall_together() {
    use voussoir::analysis::capacity::{capacity, CapacityOptions};
    use voussoir::generate::LiveLoad;
    let mut m = wall(&WallSpec {
        courses: 5,
        units: 8,
        unit: [B, H],
        live: LiveLoad::Horizontal,
        ..WallSpec::default()
    })
    .unwrap();
    m.override_joint_laws(Some(0.6), None);
    apply_profile(
        &mut m,
        &Profile::Uniform {
            x0: 2.1,
            x1: 3.3,
            v: -SETTLEMENT,
        },
    )
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let run = |nonassociative| {
        capacity(
            &st,
            &CapacityOptions {
                steps: 4,
                nonassociative,
                solver: SolverOptions {
                    method: Method::Clarabel,
                    feasibility_tolerance: 1e-10,
                    ..SolverOptions::default()
                },
                ..CapacityOptions::default()
            },
        )
        .unwrap()
    };
    let non = run(Some(NonAssociativeOptions::settlement()));
    let ass = run(None);
    for r in [&non, &ass] {
        let l0 = r.curve[0].load_multiplier.unwrap();
        assert!((l0 - 0.6).abs() < 1e-6, "λ(0) = {l0}");
    }
    // Ignored in sessions 12–13: the step at 1 cm had "no equilibrium" (a false zero at
    // 0.9855 cm, 11 of 17 iterations unsettled). Cause: Clarabel stopped at reduced accuracy
    // on the equilibrated limit program and its fallback, HiGHS's interior point, called the
    // equilibrated program infeasible; as written it has a certified optimum. Both answers are
    // now checked on the program as written (`lp::as_written_if_better`); every step settles
    // (λ 0.365 at 1 cm; tests/issue29_fixes.rs).
    eprintln!("{}", non.message);
    for p in &non.curve[1..] {
        let l = p.load_multiplier.unwrap();
        assert!(l > 0.0 && l < 0.6, "s = {}: λ = {l}", p.settlement);
    }
    assert!(ass.curve[1..].iter().all(|p| p.load_multiplier.is_none()));
    // Session 23: the associative curve's message says why every settled step lost its
    // equilibrium (the dilatancy of its sliding joints), once, with the count of such steps;
    // the non-associative one, which keeps its equilibrium, says nothing of the kind.
    assert!(
        ass.message
            .contains("no equilibrium under the dead loads at 4 of 4 settled steps")
            && ass.message.contains("(dilatancy)"),
        "{}",
        ass.message
    );
    assert!(!non.message.contains("dilatancy"), "{}", non.message);
    // Its steps have no certificate (a heuristic's fixed point): the message says so instead
    // of quoting a gap of 0 (session 23).
    assert!(
        non.message.starts_with(
            "NOT CERTIFIED at 5 of 5 steps (no certificate: the non-associative friction iteration is a heuristic"
        ),
        "{}",
        non.message
    );
}
