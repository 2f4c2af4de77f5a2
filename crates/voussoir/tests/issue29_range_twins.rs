//! Issue 29 item 6 (session 22): the reaction ranges' sequence on the equilibrium program with
//! one column of each pair of twins.
//!
//! In 2D the two shear forces of a joint have the same entries (a force along the joint has
//! the same moment wherever it acts on that line) to round-off, the same bounds (free) and
//! the same coefficient in every objective of the ranges. The sequence of warm primal simplex
//! runs now goes on the program without the second of each such pair (`safety::Twins`; on the
//! 0.5 m grid façade 5,248 of 20,992 columns), and every answer is expanded (the dropped twin
//! at 0, its reduced cost its twin's) and certified on the whole program before it is used.
//! `ReactionRanges::twin_columns` counts the columns left out.
//!
//! Times: docs/performance.md, "0.5 m grid façade safety and tilt (session 22)".

mod support;
use support::{facade_grid, same_ranges};
use voussoir::analysis::safety::{reaction_ranges_by, RangeSolve};
use voussoir::discretize::KinematicMap;
use voussoir::lp::SolverOptions;
use voussoir::programs::equilibrium_program;

#[test]
fn issue29_ranges_without_twin_shear_columns_equal_the_programs_from_scratch() {
    // The 2.0 m grid façade (223 blocks, 44 supports): every joint and support of its grid
    // has two contact points, so half its free (shear) columns are twins of the other half.
    let st = facade_grid(2.0);
    let map = KinematicMap::new(&st);
    let program = equilibrium_program(&map, &st.load_vector(false));
    let free = (0..program.lp.num_cols())
        .filter(|&j| {
            program.lp.col_lower[j] == f64::NEG_INFINITY && program.lp.col_upper[j] == f64::INFINITY
        })
        .count();
    let o = SolverOptions::default();
    let warm = reaction_ranges_by(&st, &o, RangeSolve::Sequence).unwrap();
    // The reference: every end its own program of the whole equilibrium program, from
    // scratch (no twins, no warm start, no mirror).
    let cold = reaction_ranges_by(&st, &o, RangeSolve::Independent).unwrap();
    println!(
        "{} columns, {free} free; sequence: {} twins left out, {} solves; independent {} solves",
        program.lp.num_cols(),
        warm.twin_columns,
        warm.solves,
        cold.solves
    );
    assert!(free > 0 && free % 2 == 0);
    assert_eq!(warm.twin_columns, free / 2);
    assert_eq!(cold.twin_columns, 0);
    // The same ends to 1e-9 of the largest, both certified.
    same_ranges(&warm, &cold, 1e-9);
}
