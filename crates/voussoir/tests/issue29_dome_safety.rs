//! Issue 29, items 3 and 4, on the 24 × 24 dome's `safety` (session 13): the bisection
//! decides f = 0 only where it must, the elastic decisions go to interior points without
//! crossover (certified by their duals), and the reaction ranges start from the bisection's
//! first basis, take HiGHS's own ray where it certifies, and decide a warm "unbounded" that no
//! ray confirms again. Every answer against statics, a hand value, or the programs solved one
//! by one from scratch by the dual simplex.

use voussoir::analysis::safety::{
    least_joint_fraction, reaction_ranges_by, safety, RangeSolve, SafetyOptions,
};
use voussoir::lp::sequence::{certify_ray, decide_feasibility, ray_violation};
use voussoir::lp::{Direction, LinearProgram, Method, SolverOptions};
use voussoir::request::default_method;
use voussoir::Assembly;

mod support;
use support::{dome_structure, offset_stack};

#[test]
fn issue29_item3_the_bisection_decides_f0_only_where_it_must() {
    // The program at f = 0 (every joint shrunk to its centre) is the most degenerate of the
    // bisection: on the 24 × 24 dome no method decided it with a certificate in minutes. It is
    // needed only where every trial fraction stood; otherwise one that did not stand proves
    // that f = 0 does not (feasibility grows with f).
    let dual = SolverOptions {
        method: Method::DualSimplex,
        ..SolverOptions::default()
    };
    // By hand: the upper box offset by e = 0.3 needs the fraction e/(1 − e) = 3/7.
    let hand = 0.3 / 0.7;
    let (f, solves) = least_joint_fraction(&offset_stack(0.3, 1.0), 1e-7, &dual).unwrap();
    let f = f.unwrap();
    assert!(
        f >= hand - 1e-9 && f <= hand + 1.01e-7,
        "{f} against {hand}"
    );
    // The structure as given, then ⌈log2(1e7)⌉ = 24 halvings, and one program at f = 0:
    // f = 1 and 1/2 stand (the factor 7/3 is above 2), so Clarabel is asked about f = 0 on the
    // merged program (session 21: it does not say "stands", and nothing more is asked there;
    // before, no program at f = 0: 25).
    assert_eq!(solves, 26);
    // Centred boxes stand with every joint a point at its centre: f = 1 and 1/2 stand, then
    // f = 0 is decided by Clarabel (and stands; session 18: asked once 1/16 stood, 6 programs;
    // session 21: once 1/2 stood): the factor is unbounded.
    let (f, solves) = least_joint_fraction(&offset_stack(0.0, 1.0), 1e-7, &dual).unwrap();
    assert_eq!(f, Some(0.0));
    assert_eq!(solves, 3);
    let r = safety(
        &offset_stack(0.0, 1.0),
        &SafetyOptions {
            solver: SolverOptions {
                method: default_method(3),
                ..SolverOptions::default()
            },
            ..SafetyOptions::default()
        },
    )
    .unwrap();
    assert_eq!(
        (r.least_joint_fraction, r.geometric_safety_factor),
        (Some(0.0), None)
    );
}

/// `lo ≤ x ≤ hi` (one column) and the row `x = b`.
fn one_row(lo: f64, hi: f64, b: f64) -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Minimise);
    let r = lp.add_row(b, b);
    lp.add_column(0.0, lo, hi, [(r, 1.0)]);
    lp
}

#[test]
fn issue29_item3_elastic_decisions_by_interior_points_without_crossover() {
    // The elastic program's least total violation, by hand: x ∈ [0, 1] and x = 3 miss by 2,
    // relative to the largest row bound 3: 2/3; x = 0.5 is feasible (violation 0). Each
    // interior point alone (no fallback chain), certified by its duals.
    for method in [Method::IpmNoCrossover, Method::Clarabel] {
        let o = SolverOptions {
            method,
            ..SolverOptions::default()
        };
        let d = decide_feasibility(&one_row(0.0, 1.0, 3.0), &o, 1e-9)
            .unwrap()
            .unwrap_or_else(|| panic!("{method:?}: not certified"));
        assert!(!d.feasible, "{method:?}");
        assert!((d.violation - 2.0 / 3.0).abs() <= 1e-7, "{method:?}: {d:?}");
        // "Infeasible" rests on the dual half of the certificate (a Farkas bound), as
        // `decide_feasibility` documents; the point need not hold the elastic rows to 1e-7.
        assert!(
            d.certificate.dual <= voussoir::lp::sequence::CERTIFICATE_TOLERANCE,
            "{method:?}: {d:?}"
        );
        // The feasible one: HiGHS's interior point certifies it (Clarabel's point of this
        // one-column program does not hold the row to 1e-7, and is left undecided: `None`,
        // the caller's next method then decides — never a wrong answer).
        let d = decide_feasibility(&one_row(0.0, 1.0, 0.5), &o, 1e-9).unwrap();
        match (method, d) {
            (_, Some(d)) => assert!(d.feasible && d.violation <= 1e-9, "{method:?}: {d:?}"),
            (Method::Clarabel, None) => {}
            (_, None) => panic!("{method:?}: not certified"),
        }
    }
}

#[test]
fn issue29_item4_ray_violation_without_building_the_recession_program() {
    // x1 − x2 = 3 with x1 ∈ [0, 5], x2 ≥ 0: the recession cone is d1 − d2 = 0, d1 = 0 (a
    // finite upper bound), d2 ≥ 0, so d = (1, 1) violates d1 ≤ 0 by 1 (relative to |d1| = 1);
    // with x1 ≥ 0 unbounded above it is a ray, and it increases x1 + x2 (decrease of the
    // maximisation: (1 + 1)/(‖c‖₁ ‖d‖∞) = 1).
    let lp = |hi: f64| {
        let mut lp = LinearProgram::new(Direction::Maximise);
        let r = lp.add_row(3.0, 3.0);
        lp.add_column(1.0, 0.0, hi, [(r, 1.0)]);
        lp.add_column(1.0, 0.0, f64::INFINITY, [(r, -1.0)]);
        lp
    };
    let d = [1.0, 1.0];
    assert!((ray_violation(&lp(5.0), &d) - 1.0).abs() < 1e-15);
    assert_eq!(ray_violation(&lp(f64::INFINITY), &d), 0.0);
    let c = certify_ray(&lp(f64::INFINITY), &d);
    assert!(c.ok() && (c.decrease - 1.0).abs() < 1e-15, "{c:?}");
    // Its opposite leaves x2 ≥ 0: violation 1.
    assert!((ray_violation(&lp(f64::INFINITY), &[-1.0, -1.0]) - 1.0).abs() < 1e-15);
}

#[test]
fn issue29_item4_dome_ranges_from_the_bisection_basis_against_statics_and_cold_solves() {
    // A 6 × 12 dome without sliding (73 blocks, 12 supports). `safety` starts its ranges from
    // the bisection's first basis and takes HiGHS's rays where they certify; every bounded
    // end must be the dual simplex's from scratch (program by program) to 1e-9 of W, every
    // horizontal side unbounded, and statics must hold: 0 ≤ fz ≤ W at every support, the
    // least vertical reactions add up to at most W and the largest to at least W; the twelve
    // supports alike (the dome's symmetry).
    let st = dome_structure(6, 12, 0.0);
    let w: f64 = -st.load_vector(false).chunks(6).map(|f| f[2]).sum::<f64>();
    assert!(w > 0.0);
    let dual = SolverOptions {
        method: Method::DualSimplex,
        ..SolverOptions::default()
    };
    let cold = reaction_ranges_by(&st, &dual, RangeSolve::Independent).unwrap();
    assert!(cold.certified());
    for method in [default_method(3), Method::DualSimplex] {
        let o = SolverOptions {
            method,
            ..SolverOptions::default()
        };
        let r = safety(
            &st,
            &SafetyOptions {
                solver: o,
                ..SafetyOptions::default()
            },
        )
        .unwrap();
        assert!(r.stands);
        let warm = reaction_ranges_by(&st, &o, RangeSolve::Sequence).unwrap();
        assert!(warm.certified(), "{method:?}: {warm:?}");
        assert_eq!(warm.unbounded, 12 * 2 * 2, "{method:?}");
        let (mut lows, mut highs) = (0.0, 0.0);
        let first = cold.ranges[0].component("fz").unwrap().clone();
        for ((a, b), c) in r.reactions.iter().zip(&warm.ranges).zip(&cold.ranges) {
            for comp in ["fx", "fy"] {
                for x in [a, b, c] {
                    let x = x.component(comp).unwrap();
                    assert_eq!((x.min, x.max), (None, None), "{method:?} {comp}");
                }
            }
            let (za, zb, zc) = (
                a.component("fz").unwrap(),
                b.component("fz").unwrap(),
                c.component("fz").unwrap(),
            );
            for z in [za, zb] {
                assert!(
                    (z.min.unwrap() - zc.min.unwrap()).abs() <= 1e-9 * w
                        && (z.max.unwrap() - zc.max.unwrap()).abs() <= 1e-9 * w,
                    "{method:?} {}: {z:?} against {zc:?}",
                    a.support
                );
            }
            assert!((zc.max.unwrap() - first.max.unwrap()).abs() <= 1e-9 * w);
            assert!(zc.min.unwrap() >= -1e-9 * w && zc.max.unwrap() <= w * (1.0 + 1e-9));
            lows += zc.min.unwrap();
            highs += zc.max.unwrap();
        }
        assert!(lows <= w * (1.0 + 1e-9) && highs >= w * (1.0 - 1e-9));
    }
}

#[test]
#[ignore = "the 24 × 24 dome of issue 29: minutes on a shared machine (run with --ignored)"]
fn issue29_item4_safety_of_the_24x24_dome_with_ranges_certifies() {
    // 553 blocks, t/R = 0.06, no sliding: the whole `safety` as the CLI runs it. Every
    // vertical end within [0, W] by statics, the supports alike (24-fold symmetry), every
    // horizontal side unbounded.
    let st = dome_structure(24, 24, 0.0);
    let w: f64 = -st.load_vector(false).chunks(6).map(|f| f[2]).sum::<f64>();
    let t = std::time::Instant::now();
    let r = safety(
        &st,
        &SafetyOptions {
            solver: SolverOptions {
                method: default_method(3),
                ..SolverOptions::default()
            },
            ..SafetyOptions::default()
        },
    )
    .unwrap();
    eprintln!(
        "24 × 24 dome safety: {:.1} s wall, {} solves, factor {:?}",
        t.elapsed().as_secs_f64(),
        r.solves,
        r.geometric_safety_factor
    );
    assert!(r.stands);
    let first = r.reactions[0].component("fz").unwrap().clone();
    for a in &r.reactions {
        let fz = a.component("fz").unwrap();
        assert!(fz.min.unwrap() >= -1e-9 * w && fz.max.unwrap() <= w * (1.0 + 1e-9));
        assert!((fz.max.unwrap() - first.max.unwrap()).abs() <= 1e-7 * w);
        for c in ["fx", "fy"] {
            let x = a.component(c).unwrap();
            assert_eq!((x.min, x.max), (None, None));
        }
    }
}
