//! Issue #29, the defects left from session 13 (regression tests of helper h-fixes).
//!
//! Item 1: the non-associative capacity curve of a settled wall (the test of
//! `nonassociative_settlement.rs`, ignored in session 13) — each limit analysis of the curve
//! settles, and a status from the equilibrated program is checked on the program as written.
//! Item 2: `lp::as_written_if_better` on constructed solutions of a program solved by hand.

use voussoir::analysis::capacity::{capacity, CapacityOptions};
use voussoir::analysis::limit::{solve_limit, LimitStatus};
use voussoir::analysis::nonassociative::{solve_limit_nonassociative, NonAssociativeOptions};
use voussoir::analysis::paths::SettlementPath;
use voussoir::analysis::Crushing;
use voussoir::discretize::KinematicMap;
use voussoir::generate::{wall, LiveLoad, WallSpec};
use voussoir::lp::{
    as_written_if_better, Answer, Direction, LinearProgram, LpSolution, LpStatus, Method,
    SolverOptions,
};
use voussoir::settlement_input::{apply_profile, Profile};
use voussoir::{BuildOptions, Structure};

const MU: f64 = 0.6;

/// The wall of `nonassociative_settlement.rs`: 8 units × 5 courses of 0.4 × 0.2 m, μ = 0.6, a
/// horizontal live load equal to the weight, the foundation under x ∈ [2.1, 3.3] m down 1 cm.
fn settled_wall() -> Structure {
    let mut m = wall(&WallSpec {
        courses: 5,
        units: 8,
        unit: [0.4, 0.2],
        live: LiveLoad::Horizontal,
        ..WallSpec::default()
    })
    .unwrap();
    m.override_joint_laws(Some(MU), None);
    apply_profile(
        &mut m,
        &Profile::Uniform {
            x0: 2.1,
            x1: 3.3,
            v: -0.01,
        },
    )
    .unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

fn solver(method: Method) -> SolverOptions {
    SolverOptions {
        method,
        feasibility_tolerance: 1e-10,
        ..SolverOptions::default()
    }
}

fn curve(st: &Structure, method: Method) -> voussoir::analysis::capacity::CapacityResult {
    capacity(
        st,
        &CapacityOptions {
            steps: 4,
            nonassociative: Some(NonAssociativeOptions::settlement()),
            solver: solver(method),
            ..CapacityOptions::default()
        },
    )
    .unwrap()
}

/// Largest excess of a point's shear over Coulomb's μ·(its own normal force), relative to the
/// largest normal force: 0 for a statically admissible non-associative state.
fn coulomb_excess(map: &KinematicMap, pn: &[f64], pt: &[f64]) -> f64 {
    let fmax = pn.iter().fold(0.0f64, |m, &p| m.max(p));
    (0..map.num_points())
        .map(|k| {
            let mu = map.laws[map.points[k].joint].friction.unwrap();
            (pt[k].abs() - mu * pn[k].max(0.0)).max(0.0) / fmax
        })
        .fold(0.0, f64::max)
}

/// The capacity curve with Clarabel (the setting of the test ignored in session 13): every
/// limit analysis of the curve settles, λ(0) is the closed form μ (the undeformed wall slides
/// on its base as one body), and at the largest settlement (1 cm) the iterate is a statically
/// admissible non-associative state — Coulomb's inequality with its own normal forces, to
/// 1e-3 of the largest normal force (measured 1.8e-4) — carrying a multiplier below the associative one on the same
/// deformed wall (dilatancy can only add strength: the associative multiplier is an upper
/// bound). Before session 13's `as_written_if_better` the step at 1 cm had no equilibrium: the
/// curve fell to a false zero at 0.9855 cm, 11 of 17 iterations unsettled.
#[test]
fn issue29_item1_nonassociative_capacity_settles_at_every_step() {
    let st = settled_wall();
    let r = curve(&st, Method::Clarabel);
    eprintln!("{}", r.message);
    assert!(!r.message.contains("did not converge"), "{}", r.message);
    assert_eq!(r.zero_capacity_settlement, None, "{}", r.message);
    let l0 = r.curve[0].load_multiplier.unwrap();
    assert!((l0 - MU).abs() < 1e-6, "λ(0) = {l0}");
    for p in &r.curve[1..] {
        let l = p.load_multiplier.unwrap();
        assert!(l > 0.0 && l < MU, "s = {}: λ = {l}", p.settlement);
    }

    // The step at 1 cm on its own: the iteration's last iterate, checked.
    let o = NonAssociativeOptions::settlement();
    let s = solver(Method::Clarabel);
    let path = SettlementPath::with_laws(&st, &s, Crushing::Linear, 16, Some(o)).unwrap();
    let mut dst = path.deformed(path.max_settlement).unwrap();
    dst.release_fixed();
    let mut map = KinematicMap::new(&dst);
    let (associative, it) = solve_limit_nonassociative(&dst, &mut map, &s, &o).unwrap();
    assert!(it.converged, "{:?}", it.history);
    let l = it.last.lambda.unwrap();
    let last = r.curve.last().unwrap().load_multiplier.unwrap();
    assert!((l - last).abs() <= 1e-9 * last, "{l} vs the curve's {last}");
    // The associative multiplier by another method (HiGHS's dual simplex) as the upper bound.
    let assoc = solve_limit(&dst, &KinematicMap::new(&dst), &solver(Method::DualSimplex))
        .unwrap()
        .lambda
        .unwrap();
    assert!(
        (assoc - associative.unwrap()).abs() < 1e-6 * assoc,
        "{assoc} vs {associative:?}"
    );
    let excess = coulomb_excess(&map, &it.last.pn, &it.last.pt);
    eprintln!("at 1 cm: λ = {l:.6}, associative {assoc:.6}, Coulomb excess {excess:.1e} of the largest normal force, {} iterations", it.history.len());
    assert!(
        l < assoc,
        "non-associative {l} above the associative {assoc}"
    );
    assert!(
        l > 0.5 * assoc,
        "non-associative {l} against the associative {assoc}"
    );
    assert!(
        excess < 1e-3,
        "shear beyond μ·(own normal force) by {excess}"
    );
}

/// The wall deformed by Clarabel's settlement mechanism to 1 cm (the curve above), its limit
/// analysis by HiGHS's dual simplex: on the equilibrated program of the first friction
/// iteration HiGHS said "infeasible" (so did its interior point, the fallback of the curve
/// above before session 13's fix), where the program as written has a certified optimum; the
/// status was taken on trust, the iteration stopped at "no equilibrium", and a capacity curve
/// fell to a false zero (0.9855 cm). A status of the equilibrated program is now checked as
/// written. Reference: the same step on the dual simplex's own settlement path (the deformed
/// walls differ by round-off; there the status question does not arise), and Coulomb's
/// inequality with the iterate's own normal forces.
#[test]
fn issue29_item1_a_status_of_the_equilibrated_program_is_checked_as_written() {
    let st = settled_wall();
    let o = NonAssociativeOptions::settlement();
    let ds = solver(Method::DualSimplex);
    let at_1cm = |path_method: Method| {
        let path =
            SettlementPath::with_laws(&st, &solver(path_method), Crushing::Linear, 16, Some(o))
                .unwrap();
        let mut dst = path.deformed(path.max_settlement).unwrap();
        dst.release_fixed();
        let mut map = KinematicMap::new(&dst);
        let (_, it) = solve_limit_nonassociative(&dst, &mut map, &ds, &o).unwrap();
        (map, it)
    };
    let (map, it) = at_1cm(Method::Clarabel);
    assert_eq!(it.last.status, LimitStatus::Collapse, "{:?}", it.history);
    assert!(it.converged, "{:?}", it.history);
    let l = it.last.lambda.unwrap();
    let (_, reference) = at_1cm(Method::DualSimplex);
    let r = reference.last.lambda.unwrap();
    let excess = coulomb_excess(&map, &it.last.pn, &it.last.pt);
    eprintln!("at 1 cm by the dual simplex: λ = {l:.9} (on its own path {r:.9}), Coulomb excess {excess:.1e}");
    assert!((l - r).abs() < 1e-6 * r, "{l} vs {r}");
    assert!(l > 0.0 && l < MU);
    // The iteration settles λ (to 1e-3 over 8 iterates), not the forces, which wander on the
    // optimal face between the simplex's vertices: measured 3.4e-3.
    assert!(
        excess < 1e-2,
        "shear beyond μ·(own normal force) by {excess}"
    );
}

/// max x + y  s.t. x + 2y ≤ 4, 3x + y ≤ 6, x, y ≥ 0: by hand x = 1.6, y = 1.2, objective 2.8,
/// row duals 0.4 and 0.2.
fn tiny() -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Maximise);
    let r0 = lp.add_row(f64::NEG_INFINITY, 4.0);
    let r1 = lp.add_row(f64::NEG_INFINITY, 6.0);
    lp.add_column(1.0, 0.0, f64::INFINITY, [(r0, 1.0), (r1, 3.0)]);
    lp.add_column(1.0, 0.0, f64::INFINITY, [(r0, 2.0), (r1, 1.0)]);
    lp
}

/// A solution of `tiny` with the given point and the hand duals.
fn answer(status: LpStatus, x: [f64; 2]) -> LpSolution {
    let optimal = status == LpStatus::Optimal;
    LpSolution {
        status,
        objective: x[0] + x[1],
        x: if optimal { x.to_vec() } else { vec![] },
        row_dual: if optimal { vec![0.4, 0.2] } else { vec![] },
        col_dual: if optimal { vec![0.0, 0.0] } else { vec![] },
        iterations: 0,
        dual_objective: f64::NAN,
        reduced_accuracy: false,
        method: Method::DualSimplex,
        tried: vec![],
    }
}

/// `as_written_if_better` on constructed answers of `tiny` (solved by hand): a certified
/// answer of the equilibrated program stands without a second solve; one that is not (its
/// point violates the rows by 1e-3, or a status) is replaced by the program's answer as
/// written where that one is a certified optimum, and says so; otherwise it stands.
#[test]
fn issue29_item2_as_written_if_better_takes_the_certified_answer_and_says_which() {
    let lp = tiny();
    let exact = [1.6, 1.2];
    let off = [1.6 + 1e-3, 1.2 + 1e-3]; // x + 2y = 4.003 > 4: not certified
    let never = || -> voussoir::Result<LpSolution> { panic!("solved again although certified") };

    let (s, a) = as_written_if_better(&lp, answer(LpStatus::Optimal, exact), never);
    assert_eq!(a, Answer::Scaled);
    assert!((s.objective - 2.8).abs() < 1e-12);

    // Not certified: the program as written, certified, replaces it.
    let (s, a) = as_written_if_better(&lp, answer(LpStatus::Optimal, off), || {
        Ok(answer(LpStatus::Optimal, exact))
    });
    assert_eq!(a, Answer::AsWritten);
    assert!((s.x[0] - 1.6).abs() < 1e-12 && (s.x[1] - 1.2).abs() < 1e-12);

    // "Infeasible" from the equilibrated program, a certified optimum as written: the optimum.
    let (s, a) = as_written_if_better(&lp, answer(LpStatus::Infeasible, exact), || {
        Ok(answer(LpStatus::Optimal, exact))
    });
    assert_eq!((a, s.status), (Answer::AsWritten, LpStatus::Optimal));

    // As written no better (not certified, the same status, a failure): the first answer.
    for again in [
        Ok(answer(LpStatus::Optimal, off)),
        Ok(answer(LpStatus::Infeasible, exact)),
        Err(voussoir::Error::Solver("HiGHS run failed: Error".into())),
    ] {
        let (s, a) = as_written_if_better(&lp, answer(LpStatus::Optimal, off), || again);
        assert_eq!(a, Answer::Scaled);
        assert!((s.x[0] - off[0]).abs() < 1e-15);
    }

    // And through the solver: the certified optimum of `tiny` by the dual simplex is the
    // hand solution.
    let s = voussoir::lp::solve(&lp, &solver(Method::DualSimplex)).unwrap();
    assert!((s.objective - 2.8).abs() < 1e-9);
}

/// Item 4: the nine derived crack-record fields are written once (`crack_record!`) for both
/// readers; the formats and messages are those before the change. The message of an unknown
/// field in a model's crack is the one `voussoir limit` printed before (session 14, commit
/// 49d0916): the field order, and so the list, is unchanged.
#[test]
fn issue29_item4_crack_records_read_and_refuse_as_before() {
    use voussoir::analysis::identify::Crack;
    use voussoir::model::ExistingCrack;
    let record = r#"{"polyline": [[0.0, 0.0], [0.5, 0.25]], "openings": [0.001, 0.002],
        "length": 0.559, "max_opening": 0.002, "joints": [3, 4], "faces": [], "start": [0, 0],
        "end": [0.5, 0.25], "closed_loop": false, "rise": 0.25, "run": 0.5, "units": "m"}"#;
    let e: ExistingCrack = serde_json::from_str(record).unwrap();
    let c: Crack = serde_json::from_str(record).unwrap();
    // Read, not used: the observation is the polyline and its widths; nothing derived is
    // written back.
    assert_eq!(e.length, Some(serde_json::json!(0.559)));
    assert_eq!(c.closed_loop, Some(serde_json::json!(false)));
    assert_eq!(e.run, Some(serde_json::json!(0.5)));
    let written = r#"{"polyline":[[0.0,0.0],[0.5,0.25]],"opening":[0.001,0.002],"units":"m"}"#;
    assert_eq!(serde_json::to_string(&e).unwrap(), written);
    assert_eq!(serde_json::to_string(&c).unwrap(), written);

    let fields = "`at`, `joint`, `points`, `polyline`, `snap`, `opening`, `openings`, `length`, `max_opening`, `joints`, `faces`, `start`, `end`, `closed_loop`, `rise`, `run`";
    let bad = r#"{"joint": 3, "opening": 0.001, "bogus": 1}"#;
    let msg = serde_json::from_str::<ExistingCrack>(bad)
        .unwrap_err()
        .to_string();
    assert!(
        msg.starts_with(&format!(
            "unknown field `bogus`, expected one of {fields}, `units`"
        )),
        "{msg}"
    );
    let msg = serde_json::from_str::<Crack>(bad).unwrap_err().to_string();
    assert!(
        msg.starts_with(&format!(
            "unknown field `bogus`, expected one of {fields}, `tolerance`, `units`"
        )),
        "{msg}"
    );
    // A survey's `tolerance` is not a field of a model's crack.
    let msg =
        serde_json::from_str::<ExistingCrack>(r#"{"joint": 3, "opening": 0.001, "tolerance": 1}"#)
            .unwrap_err()
            .to_string();
    assert!(msg.starts_with("unknown field `tolerance`"), "{msg}");
}
