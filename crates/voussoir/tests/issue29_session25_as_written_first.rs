//! Issue 29 item 6 (session 25): `SolverOptions::as_written_first`, the canonical selection's
//! extremes of `r·y` on an optimal face solved as written before the equilibrated program
//! (`lp::scale`), which on the 0.5 m grid façade's `tilt` came out worse conditioned than as
//! written (HiGHS failed on it after 4.2 and 13.3 s, then solved the program as written in 2.9
//! and 2.1 s). The path is checked here on a small program that is equilibrated (its factors
//! beyond 2^±10) against its optimum by hand and against the path before (the equilibrated
//! program first), by each method and warm or not; the façade's selection with it is compared
//! with the binary before in docs/performance.md, "Façade tilt, safety and capacity (session
//! 25)" (the same JSON).

use voussoir::lp::{self, Direction, LinearProgram, LpStatus, Method, Scaling, SolverOptions};

/// min 3x + 2y subject to x + 2y ≥ 4 and x − y ≤ 1, x, y ≥ 0, the first row written in
/// 10⁶ units and the second in 10⁻⁵: the optimum is (0, 2) of cost 4 (the vertices of the
/// feasible set's lower boundary are (0, 2) and (2, 1), of costs 4 and 8).
fn program() -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Minimise);
    let r0 = lp.add_row(4e6, f64::INFINITY);
    let r1 = lp.add_row(-f64::INFINITY, 1e-5);
    lp.add_column(3.0, 0.0, f64::INFINITY, [(r0, 1e6), (r1, 1e-5)]);
    lp.add_column(2.0, 0.0, f64::INFINITY, [(r0, 2e6), (r1, -1e-5)]);
    lp
}

#[test]
fn issue29_session25_as_written_first_has_the_same_optimum() {
    let lp = program();
    // The program is one the solver layer equilibrates (else the option changes nothing).
    assert!(Scaling::needed(&lp, &[]).is_some());
    for method in [
        Method::DualSimplex,
        Method::PrimalSimplex,
        Method::Ipm,
        Method::Clarabel,
    ] {
        for first in [false, true] {
            let o = SolverOptions {
                method,
                as_written_first: first,
                ..SolverOptions::default()
            };
            let cold = lp::solve(&lp, &o).unwrap();
            let mut basis = None;
            let warm = lp::solve_warm(&lp, &o, &mut basis).unwrap();
            for s in [&cold, &warm] {
                assert_eq!(s.status, LpStatus::Optimal, "{method:?} {first}");
                assert!(
                    (s.objective - 4.0).abs() <= 1e-7,
                    "{method:?} {first}: {}",
                    s.objective
                );
                assert!(
                    s.x[0].abs() <= 1e-7 && (s.x[1] - 2.0).abs() <= 1e-7,
                    "{:?}",
                    s.x
                );
                assert!(lp::policy::check(&lp, s).is_none(), "{method:?} {first}");
            }
            // A simplex leaves a basis for the next program (the one of the answer returned).
            if method.is_simplex() {
                assert!(basis.is_some(), "{method:?} {first}");
            }
        }
    }
}
