//! Issue 29, solver layer (session 20): before HiGHS's interior point (and the crossover of
//! `Method::ClarabelVertex`) the free columns of zero cost that other free columns of the same
//! rows span are left out (`lp::free_columns`): in a 3D force program without friction, the
//! shears of one joint span three directions whatever their number of points. On the 48 × 48
//! dome the limit program's free columns went from 34,617 to 16,182 after presolve, and IPX's
//! interior point from 423 to 211 s of its own clock, its crossover from 32 to 55 s (load
//! 9-10; docs/performance.md, "Dome 48 × 48 (session 20)"). Exact: the same optimum, and the
//! duals of the reduced program price the program as written.

use voussoir::analysis::limit::limit;
use voussoir::discretize::KinematicMap;
use voussoir::generate3d::{dome, DomeSpec};
use voussoir::lp::{self, free_columns, policy, LpStatus, Method, SolverOptions};
use voussoir::programs;
use voussoir::structure::Assembly;
use voussoir::{BuildOptions, Structure3d};

fn crowned_dome(courses: usize, segments: usize) -> Structure3d {
    let m = dome(&DomeSpec {
        courses,
        segments,
        thickness: 0.3,
        crown_load: 10.0,
        ..DomeSpec::default()
    })
    .unwrap();
    Structure3d::new(&m, BuildOptions::default()).unwrap()
}

fn with(method: Method) -> SolverOptions {
    SolverOptions {
        method,
        ..SolverOptions::default()
    }
}

#[test]
fn issue29_free_shears_of_a_joint_reduce_to_three() {
    let st = crowned_dome(8, 16);
    let map = KinematicMap::new(&st);
    let fp = programs::limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    let r = free_columns::reduce(&fp.lp).expect("a dome's shears are dependent");
    // Counted from the map: two free shears per contact point; the shears of a joint of two
    // or more points span three directions (the tangential resultant and the torsion), of a
    // joint of one point two: at most that many are kept. Fewer are left out where a shear's
    // column has a structural zero the others of its joint have not (axis-aligned geometry:
    // a group is a row pattern): 1,041 left out here, against 1,200 were every joint's group
    // whole. Every left-out column is spanned by kept ones (the optimum below is the same).
    let free = (0..fp.lp.num_cols())
        .filter(|&j| {
            fp.lp.cost[j] == 0.0
                && fp.lp.col_lower[j] == f64::NEG_INFINITY
                && fp.lp.col_upper[j] == f64::INFINITY
        })
        .count();
    assert_eq!(free, 2 * map.num_points());
    let mut per_joint = std::collections::BTreeMap::<usize, usize>::new();
    for p in &map.points {
        *per_joint.entry(p.joint).or_default() += 1;
    }
    let span: usize = per_joint
        .values()
        .map(|&k| if k >= 2 { 3 } else { 2 })
        .sum();
    let most = free - span;
    let left_out = r.left_out(&fp.lp);
    assert!(left_out <= most, "{left_out} of at most {most}");
    assert!(left_out * 100 >= 80 * most, "{left_out} of at most {most}");
    // The reduced program's optimum (dual simplex) is the one as written (dual simplex, from
    // scratch), and its solution put back prices the program as written: certified by the
    // solver layer on the original columns.
    let o = with(Method::DualSimplex);
    let full = lp::solve(&fp.lp, &o).unwrap();
    let red = lp::solve(&r.lp, &o).unwrap();
    assert_eq!(full.status, LpStatus::Optimal);
    assert_eq!(red.status, LpStatus::Optimal);
    assert!(
        (full.objective - red.objective).abs() <= 1e-9 * full.objective.abs(),
        "{} against {}",
        red.objective,
        full.objective
    );
    let back = r.expand(&fp.lp, red);
    assert_eq!(back.x.len(), fp.lp.num_cols());
    assert_eq!(policy::check(&fp.lp, &back), None);
}

#[test]
fn issue29_interior_point_without_the_dependent_shears_answers_as_before() {
    // The 3D default (HiGHS's interior point with crossover; on the program as written since
    // the reduction was withdrawn from it: the 0.5 m grid façade's `limit` regressed, 10.1 →
    // 32.6 CPU s, docs/performance.md "Dome 48 × 48 (session 20)") against the dual simplex
    // from scratch: the same λ and least λ
    // to 1e-6, certified, answered by the method itself; its basis put back is a vertex the
    // primal simplex takes without an iteration; and the same hinged joints as the dual
    // simplex's vertex (the crowned dome's collapse is unique up to its symmetry).
    let st = crowned_dome(8, 16);
    let map = KinematicMap::new(&st);
    let fp = programs::limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    let mut basis = None;
    let s = lp::solve_warm(&fp.lp, &with(Method::Ipm), &mut basis).unwrap();
    assert_eq!(s.method, Method::Ipm, "{:?}", s.tried);
    assert!(s.tried.is_empty(), "{:?}", s.tried);
    assert_eq!(policy::check(&fp.lp, &s), None);
    let b = basis.expect("a basis after the crossover");
    assert_eq!(b.cols.len(), fp.lp.num_cols());
    let mut again = Some(b);
    let p = lp::solve_warm(&fp.lp, &with(Method::PrimalSimplex), &mut again).unwrap();
    assert_eq!(p.iterations, 0, "{:?}", p.tried);
    assert!((p.objective - s.objective).abs() <= 1e-9 * s.objective.abs());

    let ipm = limit(&st, &with(Method::Ipm)).unwrap();
    let dual = limit(&st, &with(Method::DualSimplex)).unwrap();
    let (l, ld) = (ipm.load_multiplier.unwrap(), dual.load_multiplier.unwrap());
    assert!((l - ld).abs() <= 1e-6 * ld, "λ {l} against {ld}");
    let (m, md) = (
        ipm.least_load_multiplier.unwrap(),
        dual.least_load_multiplier.unwrap(),
    );
    assert!(
        (m - md).abs() <= 1e-6 * md.abs().max(1.0),
        "{m} against {md}"
    );
    assert!(ipm.certificate.as_ref().unwrap().ok);
    let joints = |r: &voussoir::analysis::limit::LimitResult<voussoir::dim::Three>| {
        let mut j: Vec<usize> = r.hinges.iter().map(|h| h.joint).collect();
        j.sort_unstable();
        j.dedup();
        j
    };
    assert!(!ipm.hinges.is_empty());
    assert_eq!(joints(&ipm), joints(&dual));
}

#[test]
#[ignore = "slow: this file's three tests took 71 s together in release at load 10-11, this one \
            solving the 32 x 32 dome's programs three times (the others the 8 x 16 dome's)"]
fn issue29_least_multiplier_of_a_large_program_after_the_interior_point_by_clarabel() {
    // 993 blocks, 24,193 columns (at least analysis::limit::LEAST_CLARABEL_MIN_COLUMNS): after
    // HiGHS's interior point the least multiplier's program goes to Clarabel (before: the
    // primal simplex from the crossover basis, 15,791 iterations on the 48 × 48 dome). Its
    // value against HiGHS's interior point with crossover on the same program from scratch.
    let st = crowned_dome(32, 32);
    let map = KinematicMap::new(&st);
    let fp = programs::limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    assert!(fp.lp.num_cols() >= voussoir::analysis::limit::LEAST_CLARABEL_MIN_COLUMNS);
    let (r, solves) = lp::collecting(|| limit(&st, &with(Method::Ipm)).unwrap());
    let methods: Vec<Method> = solves.iter().map(|s| s.method).collect();
    assert_eq!(methods, vec![Method::Ipm, Method::Clarabel], "{solves:?}");
    assert!(solves.iter().all(|s| s.tried.is_empty()), "{solves:?}");
    assert!(r.certificate.as_ref().unwrap().ok);
    let mut least = fp.lp.clone();
    least.maximise = false;
    let reference = lp::solve(&least, &with(Method::Ipm)).unwrap();
    assert_eq!(reference.status, LpStatus::Optimal);
    let lmin = reference.x[fp.lambda.unwrap()];
    let m = r.least_load_multiplier.unwrap();
    assert!(lmin < 0.0, "{lmin}");
    assert!((m - lmin).abs() <= 1e-6 * lmin.abs(), "{m} against {lmin}");
}
