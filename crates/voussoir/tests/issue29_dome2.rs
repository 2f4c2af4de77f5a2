//! Issue 29, item 4 (session 14): the 24 × 24 dome's `safety` with its ranges under a minute.
//! What changed in behaviour, each against an independent reference (a hand value, statics,
//! or the dual simplex from scratch):
//!
//! * the unbounded sides of the reaction ranges are certified by a ray along the free columns,
//!   the objective projected onto their lineality space, without a program
//!   (`lp::sequence::Lineality`);
//! * the bisection's decisions leave the warm dual simplex after rows/8 iterations (at least
//!   500) for the elastic program, and an elastic decision left open goes to Clarabel on the
//!   program itself, which decides only "stands" (`lp::sequence::decide_directly`);
//! * the least fraction is still the bisection's: standing at it and not at it minus the
//!   tolerance, each decided again by the simplex from scratch.

use voussoir::analysis::safety::{
    reaction_ranges_by, safety, shrunk_map, RangeSolve, SafetyOptions,
};
use voussoir::discretize::KinematicMap;
use voussoir::lp::sequence::{certify_ray, decide_directly, Lineality};
use voussoir::lp::{self, Direction, LinearProgram, LpStatus, Method, SolverOptions};
use voussoir::programs::equilibrium_program;
use voussoir::request::default_method;
use voussoir::{Assembly, Structure3d};

mod support;
use support::dome_structure;

/// `x0 ≥ 0`, `x1`, `x2` free; the rows `x0 + x1 + x2 = 1` and `x1 + x2 ≤ 4`.
fn two_free_columns() -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Minimise);
    let r0 = lp.add_row(1.0, 1.0);
    let r1 = lp.add_row(f64::NEG_INFINITY, 4.0);
    lp.add_column(0.0, 0.0, f64::INFINITY, [(r0, 1.0)]);
    lp.add_column(
        0.0,
        f64::NEG_INFINITY,
        f64::INFINITY,
        [(r0, 1.0), (r1, 1.0)],
    );
    lp.add_column(
        0.0,
        f64::NEG_INFINITY,
        f64::INFINITY,
        [(r0, 1.0), (r1, 1.0)],
    );
    lp
}

#[test]
fn issue29_item4_lineality_ray_by_hand() {
    // The free columns keep both rows along d = t·(0, 1, −1) only (x1 + x2 fixed). By hand, the
    // projection of c onto that line is ((c1 − c2)/2)·(0, 1, −1).
    let lp = two_free_columns();
    let mut l = Lineality::new(&lp).expect("two free columns");
    let d = l.project(&[0.0, 3.0, 1.0]);
    for (got, want) in d.iter().zip([0.0, 1.0, -1.0]) {
        assert!((got - want).abs() <= 1e-12, "{d:?}");
    }
    // min 3·x1 + x2 decreases along −d without end; max along +d: each a certified ray.
    let mut p = lp.clone();
    p.cost = vec![0.0, 3.0, 1.0];
    let minus: Vec<f64> = d.iter().map(|v| -v).collect();
    let c = certify_ray(&p, &minus);
    assert!(c.ok() && c.violation <= 1e-15, "{c:?}");
    p.maximise = true;
    assert!(certify_ray(&p, &d).ok());
    // A cost in the rows' span (x1 + x2, fixed by the first row given x0... bounded below
    // by statics: x1 + x2 = 1 − x0 ≤ 1) and a cost on the bounded column have no component
    // along the line: the projection is round-off and no certificate accepts it.
    for cost in [[0.0, 1.0, 1.0], [1.0, 0.0, 0.0]] {
        let d = l.project(&cost);
        assert!(d.iter().all(|v| v.abs() <= 1e-12), "{cost:?}: {d:?}");
        let mut p = lp.clone();
        p.cost = cost.to_vec();
        let minus: Vec<f64> = d.iter().map(|v| -v).collect();
        assert!(!certify_ray(&p, &minus).ok() && !certify_ray(&p, &d).ok());
    }
    // No free column: nothing to project on.
    let mut bounded = LinearProgram::new(Direction::Minimise);
    let r = bounded.add_row(1.0, 1.0);
    bounded.add_column(1.0, 0.0, f64::INFINITY, [(r, 1.0)]);
    assert!(Lineality::new(&bounded).is_none());
}

/// `lo ≤ x ≤ hi` (one column) and the row `x = b`.
fn one_row(lo: f64, hi: f64, b: f64) -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Minimise);
    let r = lp.add_row(b, b);
    lp.add_column(0.0, lo, hi, [(r, 1.0)]);
    lp
}

#[test]
fn issue29_item3_the_program_itself_decides_only_stands() {
    // x ∈ [0, 1] with x = 0.5 stands (x = 0.5 by hand); with x = 3 it cannot (it misses by
    // 2): the direct decision says "stands" for the first, with the point's violation, and
    // leaves the second to the elastic program (`None`), never "does not stand".
    let o = SolverOptions {
        method: Method::Clarabel,
        ..SolverOptions::default()
    };
    let d = decide_directly(&one_row(0.0, 1.0, 0.5), &o, 1e-9)
        .unwrap()
        .expect("feasible");
    assert!(d.feasible && d.violation <= 1e-9, "{d:?}");
    assert_eq!(
        decide_directly(&one_row(0.0, 1.0, 3.0), &o, 1e-9).unwrap(),
        None
    );
}

/// Whether the structure's equilibrium program with its joints shrunk by `f` is feasible, by
/// the simplex from scratch.
fn stands_by_dual_simplex(st: &Structure3d, f: f64) -> bool {
    let base = KinematicMap::new(st);
    let fp = equilibrium_program(&shrunk_map(st, &base, f), &st.load_vector(false));
    let o = SolverOptions {
        method: Method::DualSimplex,
        ..SolverOptions::default()
    };
    // The dual simplex from scratch, with its fallback chain where it stops (HiGHS's dual
    // simplex ends "Unknown" on some of these degenerate programs): "stands" only with a
    // point that holds the program to 1e-9, "does not" only from a simplex method.
    let s = lp::solve(&fp.lp, &o).unwrap();
    match s.status {
        LpStatus::Optimal => {
            assert!(
                fp.lp.relative_violation(&s.x) <= 1e-9,
                "{f}: {:?}",
                s.method
            );
            true
        }
        LpStatus::Infeasible => {
            assert!(s.method.is_simplex(), "{f}: {:?}", s.method);
            false
        }
        other => panic!("{f}: {other:?}"),
    }
}

#[test]
fn issue29_item4_dome_ranges_by_lineality_rays_against_cold_dual_simplex() {
    // A 6 × 12 dome without sliding (12 supports): every horizontal side is unbounded (the
    // self-equilibrated shear of its joints), now certified by lineality rays without a
    // recession program; every vertical end must be the dual simplex's from scratch, program
    // by program, to 1e-9 of the weight W, and statics hold: 0 ≤ fz ≤ W.
    let st = dome_structure(6, 12, 0.0);
    let w: f64 = -st.load_vector(false).chunks(6).map(|f| f[2]).sum::<f64>();
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
        let warm = reaction_ranges_by(&st, &o, RangeSolve::Sequence).unwrap();
        assert!(warm.certified(), "{method:?}: {warm:?}");
        assert_eq!(warm.unbounded, 12 * 2 * 2, "{method:?}");
        assert!(warm.lineality_rays >= 1, "{method:?}: {warm:?}");
        assert_eq!(warm.ray_programs, 0, "{method:?}: {warm:?}");
        assert!(warm.worst_ray <= 1e-9, "{method:?}: {warm:?}");
        for (a, c) in warm.ranges.iter().zip(&cold.ranges) {
            for comp in ["fx", "fy"] {
                for x in [a, c] {
                    let x = x.component(comp).unwrap();
                    assert_eq!((x.min, x.max), (None, None), "{method:?} {comp}");
                }
            }
            let (za, zc) = (a.component("fz").unwrap(), c.component("fz").unwrap());
            assert!(
                (za.min.unwrap() - zc.min.unwrap()).abs() <= 1e-9 * w
                    && (za.max.unwrap() - zc.max.unwrap()).abs() <= 1e-9 * w,
                "{method:?} {}: {za:?} against {zc:?}",
                a.support
            );
            assert!(zc.min.unwrap() >= -1e-9 * w && zc.max.unwrap() <= w * (1.0 + 1e-9));
        }
    }
}

#[test]
fn issue29_item3_dome_factor_is_the_bisection_bracket_of_the_dual_simplex() {
    // A 12 × 12 dome (145 blocks, 870 rows: the bisection's warm runs are limited to 500
    // iterations before the elastic programs decide). The least fraction f that `safety`
    // reports must stand and f − tolerance must not, each decided again by the simplex from
    // scratch; the default method and the dual simplex give the same factor to 1e-6.
    let st = dome_structure(12, 12, 0.0);
    let mut factors = Vec::new();
    for method in [default_method(3), Method::DualSimplex] {
        let r = safety(
            &st,
            &SafetyOptions {
                solver: SolverOptions {
                    method,
                    ..SolverOptions::default()
                },
                reactions: false,
                ..SafetyOptions::default()
            },
        )
        .unwrap();
        let f = r.least_joint_fraction.unwrap();
        assert!(f > 0.0 && f < 1.0, "{method:?}: {f}");
        assert!(stands_by_dual_simplex(&st, f), "{method:?}: {f}");
        assert!(
            !stands_by_dual_simplex(&st, f - r.tolerance),
            "{method:?}: {f}"
        );
        factors.push(r.geometric_safety_factor.unwrap());
    }
    assert!((factors[0] - factors[1]).abs() <= 1e-6, "{factors:?}");
}
