//! Issue 29, solver layer (session 19): `Method::ClarabelVertex`, Clarabel's interior point
//! then HiGHS's crossover from its duals (docs/performance.md, "Clarabel with crossover
//! (session 19)"). Its answer is an optimal vertex with a basis HiGHS takes back: the primal
//! simplex started from that basis makes no iteration and ends at the same point.

use voussoir::analysis::limit::limit;
use voussoir::discretize::KinematicMap;
use voussoir::lp::{
    self, policy, Basis, Direction, LinearProgram, LpStatus, Method, SolverOptions,
};
use voussoir::programs;
use voussoir::structure::Assembly;

mod support;
use support::crowned_dome;

fn with(method: Method) -> SolverOptions {
    SolverOptions {
        method,
        ..SolverOptions::default()
    }
}

/// Solve `lp` with `Method::ClarabelVertex`; check that it answered itself, certified, with a
/// basis that the primal simplex takes back without an iteration, at the same objective.
fn vertex_of(lp: &LinearProgram) -> (lp::LpSolution, Basis) {
    let mut basis = None;
    let s = lp::solve_warm(lp, &with(Method::ClarabelVertex), &mut basis).unwrap();
    assert_eq!(s.status, LpStatus::Optimal);
    assert_eq!(s.method, Method::ClarabelVertex, "{:?}", s.tried);
    assert!(s.tried.is_empty(), "{:?}", s.tried);
    assert!(
        policy::check(lp, &s).is_none(),
        "{:?}",
        policy::check(lp, &s)
    );
    let basis = basis.expect("a basis");
    assert_eq!(basis.cols.len(), lp.num_cols());
    assert_eq!(basis.rows.len(), lp.num_rows());
    let basic = basis
        .cols
        .iter()
        .chain(&basis.rows)
        .filter(|&&b| b == lp::BasisStatus::Basic)
        .count();
    assert_eq!(basic, lp.num_rows());
    let mut again = Some(basis.clone());
    let warm = lp::solve_warm(lp, &with(Method::PrimalSimplex), &mut again).unwrap();
    assert_eq!(warm.method, Method::PrimalSimplex);
    assert_eq!(
        warm.iterations, 0,
        "the primal simplex moved from the basis"
    );
    assert!(
        (warm.objective - s.objective).abs() <= 1e-9 * s.objective.abs().max(1.0),
        "{} against {}",
        warm.objective,
        s.objective
    );
    (s, basis)
}

#[test]
fn issue29_clarabel_vertex_on_rows_of_every_kind() {
    // max x + y  s.t. 1 ≤ x + 2y ≤ 4 (a range), 3x + y ≤ 6, x − y free, x, y ≥ 0: by hand the
    // vertex (1.6, 1.2), objective 2.8, duals 0.4 and 0.2 (both rows active), 0 on the free
    // row. The crossover takes equations only: the range and the inequality become equations
    // with a slack column each, the free row is left out.
    let mut lp = LinearProgram::new(Direction::Maximise);
    let r0 = lp.add_row(1.0, 4.0);
    let r1 = lp.add_row(f64::NEG_INFINITY, 6.0);
    let r2 = lp.add_row(f64::NEG_INFINITY, f64::INFINITY);
    lp.add_column(1.0, 0.0, f64::INFINITY, [(r0, 1.0), (r1, 3.0), (r2, 1.0)]);
    lp.add_column(1.0, 0.0, f64::INFINITY, [(r0, 2.0), (r1, 1.0), (r2, -1.0)]);
    let (s, basis) = vertex_of(&lp);
    assert!(
        (s.x[0] - 1.6).abs() < 1e-9 && (s.x[1] - 1.2).abs() < 1e-9,
        "{:?}",
        s.x
    );
    assert!((s.objective - 2.8).abs() < 1e-9);
    assert!((s.row_dual[0] - 0.4).abs() < 1e-9, "{:?}", s.row_dual);
    assert!((s.row_dual[1] - 0.2).abs() < 1e-9, "{:?}", s.row_dual);
    assert!(s.row_dual[2].abs() < 1e-12, "{:?}", s.row_dual);
    // Both columns basic, the two active rows nonbasic at their upper sides, the free row basic.
    assert_eq!(
        basis.cols,
        vec![lp::BasisStatus::Basic, lp::BasisStatus::Basic]
    );
    assert_eq!(
        basis.rows,
        vec![
            lp::BasisStatus::Upper,
            lp::BasisStatus::Upper,
            lp::BasisStatus::Basic
        ]
    );
    // A minimisation with a column bounded above: min −x − y, x ≤ 1, x + y ≤ 3 (y ≥ 0): the
    // optimal face is the segment x + y = 3, 0 ≤ x ≤ 1; its vertices are (0, 3) and (1, 2),
    // each of objective −3. The method ends at one of them, not at the face's centre.
    let mut lp = LinearProgram::new(Direction::Minimise);
    let r = lp.add_row(f64::NEG_INFINITY, 3.0);
    lp.add_column(-1.0, 0.0, 1.0, [(r, 1.0)]);
    lp.add_column(-1.0, 0.0, f64::INFINITY, [(r, 1.0)]);
    let (s, _) = vertex_of(&lp);
    assert!((s.objective + 3.0).abs() < 1e-9);
    assert!(
        s.x[0].abs() < 1e-9 || (s.x[0] - 1.0).abs() < 1e-9,
        "not a vertex: {:?}",
        s.x
    );
}

#[test]
fn issue29_clarabel_vertex_limit_program_of_a_dome() {
    // The crowned 8 × 16 dome's limit program (every row an equation, many free shear
    // forces): a vertex with its basis, λ equal to the dual simplex's from scratch.
    let st = crowned_dome(8, 16);
    let map = KinematicMap::new(&st);
    let fp = programs::limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    let (s, _) = vertex_of(&fp.lp);
    let d = lp::solve(&fp.lp, &with(Method::DualSimplex)).unwrap();
    assert_eq!(d.method, Method::DualSimplex);
    let j = fp.lambda.unwrap();
    assert!(
        (s.x[j] - d.x[j]).abs() <= 1e-6 * d.x[j].abs(),
        "λ {} against the dual simplex's {}",
        s.x[j],
        d.x[j]
    );
}

#[test]
fn issue29_clarabel_vertex_limit_analysis_as_the_interior_point_with_crossover() {
    // `limit` with the new method against HiGHS's interior point with crossover (the 3D
    // default): the same λ and least λ to 1e-6, certified, and the same hinged joints (the
    // crowned dome's collapse is unique up to its symmetry: both vertices agree).
    let st = crowned_dome(8, 16);
    let (r, solves) = lp::collecting(|| limit(&st, &with(Method::ClarabelVertex)).unwrap());
    let ipm = limit(&st, &with(Method::Ipm)).unwrap();
    // The limit program by the method itself; the least multiplier's (only its value is read)
    // by Clarabel alone.
    let methods: Vec<Method> = solves.iter().map(|s| s.method).collect();
    assert_eq!(
        methods,
        vec![Method::ClarabelVertex, Method::Clarabel],
        "{solves:?}"
    );
    assert!(solves.iter().all(|s| s.tried.is_empty()), "{solves:?}");
    assert_eq!(r.solver.method, Method::ClarabelVertex);
    let (l, li) = (r.load_multiplier.unwrap(), ipm.load_multiplier.unwrap());
    assert!((l - li).abs() <= 1e-6 * li, "λ {l} against {li}");
    let (m, mi) = (
        r.least_load_multiplier.unwrap(),
        ipm.least_load_multiplier.unwrap(),
    );
    assert!(
        (m - mi).abs() <= 1e-6 * mi.abs().max(1.0),
        "{m} against {mi}"
    );
    assert!(r.certificate.as_ref().unwrap().ok);
    let joints = |h: Vec<usize>| {
        let mut j = h;
        j.sort_unstable();
        j.dedup();
        j
    };
    assert!(!r.hinges.is_empty());
    assert_eq!(r.hinges.len(), ipm.hinges.len());
    assert_eq!(
        joints(r.hinges.iter().map(|h| h.joint).collect()),
        joints(ipm.hinges.iter().map(|h| h.joint).collect())
    );
}

#[test]
fn issue29_clarabel_vertex_failure_goes_down_its_chain() {
    // An iteration limit of 1 stops Clarabel (and the simplex after the crossover): the chain
    // goes on to HiGHS's interior point with crossover, which answers with the dual simplex's
    // λ and says what failed before it.
    let st = crowned_dome(4, 8);
    let map = KinematicMap::new(&st);
    let fp = programs::limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    let o = SolverOptions {
        iteration_limit: Some(1),
        ..with(Method::ClarabelVertex)
    };
    let s = lp::solve(&fp.lp, &o).unwrap();
    assert_eq!(s.method, Method::Ipm, "{:?}", s.tried);
    assert_eq!(s.tried.len(), 1, "{:?}", s.tried);
    assert!(s.tried[0].starts_with("clarabel-vertex:"), "{:?}", s.tried);
    assert!(policy::check(&fp.lp, &s).is_none());
    let d = lp::solve(&fp.lp, &with(Method::DualSimplex)).unwrap();
    let j = fp.lambda.unwrap();
    assert!((s.x[j] - d.x[j]).abs() <= 1e-6 * d.x[j].abs());
}

#[test]
fn issue29_clarabel_vertex_basis_of_a_program_of_inequalities() {
    // The dead-load ray program of the crowned 8 × 16 dome (`N d ≥ 0` on every point, bounded
    // columns, degenerate: the dome stands, so its optimum is 0 at d = 0): every inequality
    // becomes an equation with a slack column for the crossover, and where such an equation
    // ends basic the row comes back basic. Before: no basis (the count of basic statuses was
    // short), and the stages after it ran from scratch.
    let st = crowned_dome(8, 16);
    let map = KinematicMap::new(&st);
    let lp = programs::dead_load_ray_program(&map, &st.load_vector(false), &st.load_vector(true));
    let (s, _) = vertex_of(&lp);
    let d = lp::solve(&lp, &with(Method::DualSimplex)).unwrap();
    assert!(
        (s.objective - d.objective).abs() <= 1e-9 * d.objective.abs().max(1.0),
        "{} against the dual simplex's {}",
        s.objective,
        d.objective
    );
}
