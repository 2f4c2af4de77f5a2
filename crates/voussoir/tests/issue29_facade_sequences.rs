//! Issue 29 items 4 and 6 (session 18): `safety` and `capacity` on the paper's façades as
//! sequences of programs.
//!
//! * **Defect: every warm decision of `safety`'s bisection was re-decided.** A decision
//!   "stands" was checked with each row on its own scale
//!   ([`LinearProgram::relative_violation`]): a block's horizontal equilibrium row with no
//!   horizontal load, whose forces at a simplex's vertex are round-off (1e-13), counted as
//!   violated by 1, and so did a basic force of −1e-13 against `p_n ≥ 0`. Every such decision
//!   went to the elastic program (Clarabel, then HiGHS's interior point: 15–70 s each on the
//!   0.5 m façade). The check is now [`point_violation`]: on the nondimensional program, the
//!   point clamped onto its bounds, the rows' violation relative to the largest load — the
//!   measure the elastic program's own decision uses, at the same tolerance as before (1e-9).
//! * **Fewer decisions**: a bisection that has found only "stands" down to 1/16 asks about
//!   f = 0 there, once (the façades stand on the centres of their joints).
//!
//! `capacity` was unchanged in session 18 (the warm dual simplex from the interior point's
//! crossover basis measured slower per step there); since session 20 a 2D curve above 2,000
//! blocks solves the steps after the first settled one by the warm dual simplex
//! (`tests/issue29_curve_warm2d.rs`; docs/performance.md, "Façade capacity curves (session 20)").
//! * **f = 0 on the merged program**: at f = 0 a joint's points coincide and their columns are
//!   equal; the decision is taken on the program with one column of each ([`merged_columns`]),
//!   which is feasible exactly when the program is.
//!
//! Times on the 0.5 m façades: docs/performance.md, "Façade safety and capacity (session 18)".

mod support;
use support::{facade_grid, least_fraction_from_scratch};
use voussoir::analysis::safety::{merged_columns, safety, shrunk_map, Decisions, SafetyOptions};
use voussoir::discretize::KinematicMap;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::sequence::{decide_feasibility, point_violation};
use voussoir::lp::{collecting, Direction, LinearProgram, Method, SolverOptions};
use voussoir::programs::equilibrium_program;
use voussoir::{BuildOptions, Structure};

/// By hand: `x0 + x1 = 10` (a load), `x2 − x3 = 0` (a row without load), every `x ≥ 0`.
fn two_rows() -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Minimise);
    let r0 = lp.add_row(10.0, 10.0);
    let r1 = lp.add_row(0.0, 0.0);
    lp.add_column(0.0, 0.0, f64::INFINITY, [(r0, 1.0)]);
    lp.add_column(0.0, 0.0, f64::INFINITY, [(r0, 1.0)]);
    lp.add_column(0.0, 0.0, f64::INFINITY, [(r1, 1.0)]);
    lp.add_column(0.0, 0.0, f64::INFINITY, [(r1, -1.0)]);
    lp
}

#[test]
fn issue29_point_violation_measures_round_off_as_round_off_and_a_violation_as_one() {
    let lp = two_rows();
    // Round-off on the row without load: each row on its own scale calls it a violation of 1
    // (|1e-13| / |1e-13|); against the largest load (10) it is 1e-14.
    let x = [4.0, 6.0, 1e-13, 0.0];
    assert_eq!(lp.relative_violation(&x), 1.0);
    let v = point_violation(&lp, &x);
    assert!(v > 0.0 && v < 1e-13, "{v}");
    // A force of −1e-13 against its bound 0: clamped onto the bound, the point holds exactly.
    let x = [4.0, 6.0, 0.0, -1e-13];
    assert_eq!(lp.relative_violation(&x), 1.0);
    assert_eq!(point_violation(&lp, &x), 0.0);
    // A real violation: the load row short by 0.1 of 10, by hand 1e-2 (the scaling's factors
    // are powers of two and cancel in the ratio).
    let x = [4.0, 5.9, 0.0, 0.0];
    let v = point_violation(&lp, &x);
    assert!((v - 0.01).abs() < 1e-12, "{v}");
    // A point that is not a point of the program at all.
    assert_eq!(
        point_violation(&lp, &[1.0, f64::NAN, 0.0, 0.0]),
        f64::INFINITY
    );
    assert_eq!(point_violation(&lp, &[1.0]), f64::INFINITY);
}

#[test]
fn issue29_warm_decisions_on_the_facade_are_not_redecided() {
    // The 1.0 m grid façade (716 blocks): before the fix the warm dual simplex's vertices
    // were re-decided by the elastic program at 22 of 24 decisions (measured with
    // `voussoir safety`, VOUSSOIR_TRACE=1). Each decision is also taken independently, by the
    // dual simplex from scratch: the same answers.
    let st = facade_grid(1.0);
    let base = KinematicMap::new(&st);
    let dead = st.load_vector(false);
    let mut d = Decisions::new(&SolverOptions::default());
    for f in [1.0, 0.5, 0.25, 0.125] {
        let map = shrunk_map(&st, &base, f);
        let stands = d.stands(&map, &dead).unwrap();
        let fp = equilibrium_program(&map, &dead);
        // The reference: the dual simplex from scratch (a vertex that holds the program, or a
        // proof of infeasibility).
        let scratch = voussoir::lp::solve(&fp.lp, &SolverOptions::default()).unwrap();
        assert_eq!(scratch.status, voussoir::lp::LpStatus::Optimal, "f = {f}");
        assert!(point_violation(&fp.lp, &scratch.x) <= 1e-8, "f = {f}");
        assert!(stands, "f = {f}");
    }
    // Before the fix every warm decision was re-decided (the per-row measure: violation 1).
    // Now a warm vertex is re-decided only where its violation exceeds 1e-9 of the largest
    // load: measured 2.2e-11 at f = 1/2, 1.8e-9 at f = 1/4 (HiGHS's tolerance is 1e-9 on its
    // own scaling), so one of the three at most.
    assert!(d.redecided <= 1, "{} re-decided", d.redecided);
    assert_eq!(
        d.warm, 3,
        "every decision after the first from the basis before"
    );
}

#[test]
fn issue29_safety_of_the_facade_asks_about_zero_early_with_the_same_answer() {
    // The 1.0 m grid façade stands with every joint shrunk to its centre (factor unbounded:
    // least fraction 0). Before: 24 decisions (f = 1, twenty halvings, then 0); now f = 1,
    // 1/2, 1/4, 1/8, 1/16 and 0 (six programs of the bisection; a vertex marginally above
    // 1e-9 goes to the elastic program besides). The reference: f = 0 decided by the elastic
    // program on Clarabel, on the program as written (not merged).
    let st = facade_grid(1.0);
    let (r, solves) = collecting(|| {
        safety(
            &st,
            &SafetyOptions {
                reactions: false,
                ..SafetyOptions::default()
            },
        )
        .unwrap()
    });
    assert!(r.stands);
    assert_eq!(r.least_joint_fraction, Some(0.0));
    assert_eq!(r.geometric_safety_factor, None);
    // (Session 19: f = 0 is asked of Clarabel on the merged program first, an "elastic
    // decisions" record: five programs of the bisection. Session 21: it is asked once f = 1
    // and 1/2 have stood, `tests/issue29_local_rays.rs`: two programs of the bisection.
    // Session 29: a 2D structure asks as soon as f = 1 stands: one program of the bisection.)
    let bisection = solves.iter().filter(|s| s.programs == "bisection").count();
    assert_eq!(bisection, 1, "{solves:?}");
    let base = KinematicMap::new(&st);
    let dead = st.load_vector(false);
    let fp = equilibrium_program(&shrunk_map(&st, &base, 0.0), &dead);
    let clarabel = SolverOptions {
        method: Method::Clarabel,
        ..SolverOptions::default()
    };
    let reference = decide_feasibility(&fp.lp, &clarabel, 1e-9)
        .unwrap()
        .unwrap();
    assert!(reference.feasible);
}

#[test]
fn issue29_a_bisection_that_falls_below_one_sixteenth_gives_the_same_fraction() {
    // The paper's arch stands down to a fraction of about 0.98 (factor 1.0159, session 14's
    // benchmark): the early question about 0 is never asked, and the fraction is the one the
    // bisection from [0, 1] ends on, decided the same way by the dual simplex from scratch at
    // every step (the reference: `stands` of each shrunk structure, independent programs).
    let m = arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = safety(
        &st,
        &SafetyOptions {
            reactions: false,
            ..SafetyOptions::default()
        },
    )
    .unwrap();
    let f = r.least_joint_fraction.unwrap();
    assert!((1.0 / f - 1.015886).abs() < 1e-5, "factor {}", 1.0 / f);
    // The bisection by hand on independent programs (each from scratch).
    assert_eq!(f, least_fraction_from_scratch(&st));
}

#[test]
fn issue29_merged_columns_keep_feasibility() {
    // By hand: x0 and x1 are equal columns (both `≥ 0`, the same entry in the load row), x2
    // and x3 are not (entries +1 and −1): three columns remain, and the merged program is
    // feasible (x0 = 10) as the program is (x0 + x1 = 10).
    let lp = two_rows();
    let merged = merged_columns(&lp);
    assert_eq!((merged.num_rows(), merged.num_cols()), (2, 3));
    let s = voussoir::lp::solve(&merged, &SolverOptions::default()).unwrap();
    assert_eq!(s.status, voussoir::lp::LpStatus::Optimal);
    assert!(point_violation(&merged, &s.x) < 1e-15);
    // A load the merged columns cannot carry: the row without load made to need 1 from x2 − x3
    // while x2 is fixed at 0 (a bounded column, never merged) and x3 ≥ 0: infeasible both ways.
    let mut bad = two_rows();
    bad.row_lower[1] = 1.0;
    bad.row_upper[1] = 1.0;
    bad.col_upper[2] = 0.0;
    let merged = merged_columns(&bad);
    assert_eq!(merged.num_cols(), 3);
    for p in [&bad, &merged] {
        let s = voussoir::lp::solve(p, &SolverOptions::default()).unwrap();
        assert_eq!(s.status, voussoir::lp::LpStatus::Infeasible);
    }
    // The 1.0 m grid façade shrunk to the centres of its joints: the points of a joint (two
    // or more) coincide, and the merged program has at most half the columns (measured 2,836
    // of 5,708).
    let st = facade_grid(1.0);
    let base = KinematicMap::new(&st);
    let fp = equilibrium_program(&shrunk_map(&st, &base, 0.0), &st.load_vector(false));
    let merged = merged_columns(&fp.lp);
    assert!(2 * merged.num_cols() <= fp.lp.num_cols());
    assert_eq!(merged.num_rows(), fp.lp.num_rows());
    // Away from 0 only the shear columns of a joint are equal (a shear along the joint's line
    // has the same moment wherever on the line it acts): fewer merged than at 0, and both
    // merged programs stand as the façade does (the dual simplex from scratch).
    let half = equilibrium_program(&shrunk_map(&st, &base, 0.5), &st.load_vector(false));
    let merged_half = merged_columns(&half.lp);
    assert!(merged_half.num_cols() > merged.num_cols());
    assert!(merged_half.num_cols() < half.lp.num_cols());
    for p in [&merged, &merged_half] {
        let s = voussoir::lp::solve(p, &SolverOptions::default()).unwrap();
        assert_eq!(s.status, voussoir::lp::LpStatus::Optimal);
        assert!(point_violation(p, &s.x) <= 1e-9);
    }
}
