//! Issue 29 item 6 (session 26, helper h-cap): a capacity curve's step whose kept basis is still
//! optimal on the step's program is answered by the solver layer itself (`lp::solve_warm_kept`:
//! the basic solution and duals of that basis by the solver layer's own sparse LU, `lp::lu`,
//! feasible within the backend's tolerance and certified by `policy::check`), without a HiGHS
//! run; every other step by the warm dual simplex as before (docs/performance.md, "`capacity`
//! on the 0.5 m façades (session 26)").
//!
//! The references are independent of that path: each program solved from scratch by HiGHS's
//! dual simplex (a HiGHS run, no kept basis), and the curve with every step's limit program
//! solved from scratch by the dual simplex (`hot_start: false`).

use voussoir::analysis::capacity::{capacity, CapacityOptions, CapacityResult};
use voussoir::dim::Two;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
use voussoir::lp::{
    kept, solve, solve_warm, solve_warm_kept, Direction, LinearProgram, LpStatus, Method,
    SolverOptions,
};
use voussoir::{BuildOptions, Structure};

mod support;

/// `max c·(x, y)  s.t.  x + a·y ≤ 4,  3x + y ≤ 6,  x, y ≥ 0`.
fn program(c: [f64; 2], a: f64) -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Maximise);
    let r0 = lp.add_row(f64::NEG_INFINITY, 4.0);
    let r1 = lp.add_row(f64::NEG_INFINITY, 6.0);
    lp.add_column(c[0], 0.0, f64::INFINITY, [(r0, 1.0), (r1, 3.0)]);
    lp.add_column(c[1], 0.0, f64::INFINITY, [(r0, a), (r1, 1.0)]);
    lp
}

fn dual_simplex() -> SolverOptions {
    SolverOptions {
        method: Method::DualSimplex,
        ..SolverOptions::default()
    }
}

#[test]
fn issue29_kept_basis_answers_only_where_it_is_optimal() {
    let o = dual_simplex();
    // The basis of max x + y (by hand: (1.6, 1.2), both rows tight).
    let mut basis = None;
    let first = solve_warm(&program([1.0, 1.0], 2.0), &o, &mut basis).unwrap();
    assert!((first.objective - 2.8).abs() < 1e-12, "{}", first.objective);
    let b = basis.clone().expect("a simplex basis");
    // A coefficient moved a little: the same two rows stay tight; by hand, x + 2.1 y = 4 and
    // 3x + y = 6 give y = 6/5.3, x = (6 − y)/3.
    let moved = program([1.0, 1.0], 2.1);
    let got = kept::answer(&moved, &o, &b).expect("the kept basis is optimal");
    let y = 6.0 / 5.3;
    let x = (6.0 - y) / 3.0;
    assert!(
        (got.x[0] - x).abs() < 1e-14 && (got.x[1] - y).abs() < 1e-14,
        "{:?}",
        got.x
    );
    let scratch = solve(&moved, &o).unwrap();
    assert!((got.objective - scratch.objective).abs() < 1e-12);
    for (u, v) in got.row_dual.iter().zip(&scratch.row_dual) {
        assert!(
            (u - v).abs() < 1e-12,
            "{:?} {:?}",
            got.row_dual,
            scratch.row_dual
        );
    }
    // The cost changed so that the basis is no longer optimal (max 10x + y: the optimum moves
    // to (2, 0)): no answer from the kept basis, and the solver layer's warm solve from it
    // still reaches the optimum (20) by the simplex.
    let costly = program([10.0, 1.0], 2.0);
    assert!(kept::answer(&costly, &o, &b).is_none());
    let mut start = Some(b.clone());
    let s = solve_warm_kept(&costly, &o, &mut start).unwrap();
    assert_eq!(s.status, LpStatus::Optimal);
    assert!((s.objective - 20.0).abs() < 1e-12, "{}", s.objective);
    // A right-hand side that makes the basis primal infeasible (x + 2y ≤ −1: no point at all
    // with x, y ≥ 0): no answer from the kept basis either; the warm solve says infeasible.
    let mut bad = program([1.0, 1.0], 2.0);
    bad.row_upper[0] = -1.0;
    assert!(kept::answer(&bad, &o, &b).is_none());
    let mut start = Some(b);
    assert_eq!(
        solve_warm_kept(&bad, &o, &mut start).unwrap().status,
        LpStatus::Infeasible
    );
}

/// The curve with every settled step after the first warm from the step before by the dual
/// simplex (the policy's path for a curve above `SIMPLEX_MAX_BLOCKS_2D`, which looks at the
/// kept basis first), and the curve with every step's limit program from scratch by the dual
/// simplex.
fn curves(st: &Structure, steps: usize) -> (CapacityResult<Two>, CapacityResult<Two>) {
    let kept = capacity(
        st,
        &CapacityOptions {
            steps,
            solver: SolverOptions {
                method: Method::Ipm,
                ..SolverOptions::default()
            },
            warm_method: Some(Method::DualSimplex),
            ..CapacityOptions::default()
        },
    )
    .unwrap();
    let scratch = capacity(
        st,
        &CapacityOptions {
            steps,
            solver: dual_simplex(),
            hot_start: false,
            ..CapacityOptions::default()
        },
    )
    .unwrap();
    (kept, scratch)
}

#[test]
fn issue29_kept_basis_curve_of_the_arch_equals_the_curve_from_scratch() {
    // The paper's arch, live load on the whole span, the right springing moving out and down
    // (as issue29_curve_warm2d): λ(0) = 0.434645 (Fig 7).
    let mut m = arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap();
    m.supports[1].motion = [0.01, -0.005, 0.0];
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let (kept, scratch) = curves(&st, 8);
    support::same_curve(&kept, &scratch, 1e-9);
    assert!((kept.curve[0].load_multiplier.unwrap() - 0.434645).abs() < 1e-6);
}

#[test]
fn issue29_kept_basis_curve_of_the_2m_running_bond_equals_the_curve_from_scratch() {
    // The paper's façade (Fig 18) in running bond of 2.0 m (231 blocks) under the horizontal
    // live load, the right half of its base settling 0.2 m (the realistic benchmark's
    // `capacity` cell of the 0.5 m running bond, smaller). With VOUSSOIR_TRACE, all 5 steps
    // after the first settled one were answered by the kept basis.
    let mut spec = bondeno(2.0, FacadeMesh::RunningBond);
    spec.live = LiveLoad::Horizontal;
    let m = support::right_half_down(facade(&spec).unwrap());
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let (kept, scratch) = curves(&st, 6);
    assert!(kept.curve.iter().all(|p| p.load_multiplier.is_some()));
    // Against every program from scratch by the dual simplex: to the certificates' tolerance
    // (1e-6). Measured: 7.7e-7 at the first settled step, which the interior point with
    // crossover answers (not this path, and as before), and 2.6e-8 or less at the steps after
    // it, each the optimum at the basis that step left (feasible to the simplex's 1e-9).
    support::same_curve(&kept, &scratch, 1e-6);
    // The way before, from the same start: steps 0 and 1 by the dual simplex, and each later
    // step by HiGHS's dual simplex warm from the basis of the step before (no warm method of
    // its own, so the kept basis is not looked at), against the same with the warm method
    // set (each later step looked at by its kept basis first): the same bases, so the same
    // vertices to round-off (measured 3e-13 relative or less).
    let by = |warm_method| {
        capacity(
            &st,
            &CapacityOptions {
                steps: 6,
                solver: dual_simplex(),
                warm_method,
                ..CapacityOptions::default()
            },
        )
        .unwrap()
    };
    support::same_curve(&by(Some(Method::DualSimplex)), &by(None), 1e-10);
}
