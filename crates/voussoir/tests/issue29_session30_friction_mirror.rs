//! Issue 29 item 6 (session 30): the mirror symmetry of a planar program with Coulomb friction.
//!
//! A frictional joint adds two rows per point, `±p_t − μ p_n ≤ c`, after the three equilibrium
//! rows per block. The mirror (`safety::Mirror`) took only programs of equilibrium rows, so a
//! symmetric façade with μ = 0.6 solved its least load multiplier's program (the tilt: 90,774
//! warm primal simplex iterations, 325 s of wall clock on the 0.5 m running bond) and every
//! reaction range. Now each friction row maps onto the friction row of the mirrored point whose
//! entries it maps onto (the `+p_t` row onto the `−p_t` row where the shear flips), and the
//! whole program is checked entry by entry as before.
//!
//! References: the least multiplier's program solved from scratch by the dual simplex, and the
//! reaction ranges solved side by side from scratch without the mirror (a different method and
//! path each). Times: docs/performance.md, "Frictional façades: the least multiplier and the
//! mirror (session 30)".

mod support;
use support::{
    dual_simplex_and_ipm, least_multiplier_from_scratch, range_ends, same_ranges,
    tilt_least_is_the_mirror_image,
};
use voussoir::analysis::limit::limit;
use voussoir::analysis::safety::{reaction_ranges_by, RangeSolve};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure};

const MU: f64 = 0.6;

fn frictional(mut m: voussoir::model::Model) -> Structure {
    m.override_joint_laws(Some(MU), None);
    Structure::new(&m, BuildOptions::default()).unwrap()
}

fn facade_of(element: f64, mesh: FacadeMesh) -> Structure {
    frictional(facade(&bondeno(element, mesh)).unwrap())
}

#[test]
fn issue29_session30_least_multiplier_with_friction_is_the_mirror_image() {
    // The paper's arch with μ = 0.6 under horizontal loads equal to its voussoirs' weights.
    let arch = frictional(
        arch(&ArchSpec {
            live: LiveLoad::Horizontal,
            ..ArchSpec::default()
        })
        .unwrap(),
    );
    let reference = least_multiplier_from_scratch(&arch);
    for o in dual_simplex_and_ipm() {
        let r = limit(&arch, &o).unwrap();
        let (hi, lo) = (r.load_multiplier.unwrap(), r.least_load_multiplier.unwrap());
        println!(
            "arch, {:?}: λ_max {hi}, λ_min {lo}, from scratch {reference}",
            o.method
        );
        assert!(hi > 0.0, "{hi}");
        // The image of the largest multiplier's optimum: exactly −λ_max (a program solved
        // agrees only to its tolerance).
        assert_eq!(lo, -hi);
        assert!((lo - reference).abs() <= 1e-7 * hi, "{lo} {reference}");
    }
    // The 2.0 m façades, grid and running bond, with μ = 0.6, on the tilting table both ways.
    for mesh in [FacadeMesh::Grid, FacadeMesh::RunningBond] {
        tilt_least_is_the_mirror_image(&facade_of(2.0, mesh), &format!("{mesh:?} façade"), 1e-7);
    }
}

#[test]
fn issue29_session30_no_mirror_with_friction_where_the_structure_is_not_symmetric() {
    // The arch with μ = 0.6 under a live load on its left half: the least multiplier is its
    // program's, not −λ_max.
    let st = frictional(
        arch(&ArchSpec {
            live: LiveLoad::Left,
            ..ArchSpec::default()
        })
        .unwrap(),
    );
    let reference = least_multiplier_from_scratch(&st);
    for o in dual_simplex_and_ipm() {
        let r = limit(&st, &o).unwrap();
        let (hi, lo) = (r.load_multiplier.unwrap(), r.least_load_multiplier.unwrap());
        println!(
            "left half, {:?}: λ_max {hi}, λ_min {lo}, from scratch {reference}",
            o.method
        );
        assert!(
            (lo - reference).abs() <= 1e-7 * hi.abs().max(reference.abs()),
            "{lo} {reference}"
        );
        assert!((lo + hi).abs() > 1e-3 * hi, "{lo} {hi}");
    }
}

#[test]
fn issue29_session30_frictional_reaction_ranges_by_the_mirror_equal_the_programs_from_scratch() {
    // A 6 × 4 m running-bond panel of 0.5 m units with a door in its middle, on 6 foundation
    // segments, μ = 0.6 (its horizontal reactions bounded by friction).
    let spec = voussoir::generate_facade::FacadeSpec {
        width: 6.0,
        height: 4.0,
        gable: 0.0,
        openings: vec![voussoir::generate_facade::Opening::Rect {
            x0: 2.5,
            y0: 0.0,
            x1: 3.5,
            y1: 2.2,
        }],
        segments: 6,
        ..bondeno(0.5, FacadeMesh::RunningBond)
    };
    let st = frictional(facade(&spec).unwrap());
    let o = SolverOptions::default();
    let warm = reaction_ranges_by(&st, &o, RangeSolve::Sequence).unwrap();
    let cold = reaction_ranges_by(&st, &o, RangeSolve::Independent).unwrap();
    println!(
        "sequence: {} solves, {} mirrored; independent: {} solves",
        warm.solves, warm.mirrored, cold.solves
    );
    assert_eq!(cold.mirrored, 0);
    let ends = range_ends(&warm, true);
    // The supports pair up about the façade's midline: a third of the bounded ends at least
    // come as images.
    assert!(3 * warm.mirrored >= ends, "{} of {ends}", warm.mirrored);
    same_ranges(&warm, &cold, 1e-6);
    // The vertical reactions add up to the weight in every admissible state, so the least
    // ones add up to at most the weight and the largest to at least it (by hand), and each
    // is bounded (a support pushes, it does not pull).
    let weight = -st.load_vector(false).chunks(3).map(|f| f[1]).sum::<f64>();
    for r in &warm.ranges {
        println!("{} {:?}", r.support, r.components);
    }
    let (lo, hi) = warm.ranges.iter().fold((0.0, 0.0), |(a, b), r| {
        let c = r.component("fy").unwrap();
        (a + c.min.unwrap(), b + c.max.unwrap())
    });
    assert!(
        lo <= weight * (1.0 + 1e-9) && hi >= weight * (1.0 - 1e-9),
        "{lo} {weight} {hi}"
    );
}
