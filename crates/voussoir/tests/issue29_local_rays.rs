//! Issue 29 (session 21): `safety` of the 0.5 m grid façade with fewer and cheaper programs.
//!
//! * **Rays on the blocks around the support.** A horizontal side of a façade's support is
//!   unbounded by a compression between two neighbouring base blocks (the support's shear
//!   against the next one's). Each such side took a warm primal simplex run on the whole
//!   program (8,000 rows) to say "unbounded" (0.02–7 CPU s each). It is now looked for on a
//!   small recession program: the rows of the blocks around the support, grown by neighbours
//!   (at most 4 rounds, 240 rows), and the columns with no entry elsewhere; its ray, padded
//!   with zeros, is certified on the side's own program (`lp::sequence::certify_ray`) before
//!   it is used (`safety::LocalRays`; `ReactionRanges::local_rays`).
//! * **No program for a component without columns** (a support under an opening: 0 in every
//!   admissible state; `ReactionRanges::without_columns`).
//! * **f = 0 asked of Clarabel once 1 and 1/2 have stood**, before 1/4, 1/8 and 1/16; where it
//!   does not say "stands" the bisection goes on as before.
//!
//! Times: docs/performance.md, "0.5 m façade safety (session 21)".

mod support;
use support::{least_fraction_from_scratch, range_ends, same_ranges, stands_from_scratch};
use voussoir::analysis::safety::{reaction_ranges_by, safety, RangeSolve, SafetyOptions};
use voussoir::generate::{arch, ArchSpec, LiveLoad, RadiusAt};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh, FacadeSpec, Opening};
use voussoir::lp::{collecting, Outcome, SolverOptions};
use voussoir::structure::Body;
use voussoir::{Assembly, BuildOptions, Structure};

/// A façade 6 m wide and 3 m high in the 0.5 m grid of the paper's façade (0.5 × 0.25 m
/// elements, one support per 0.5 m of the base as on the 0.5 m façade: each base block on one
/// support), with a pointed door 1 m wide in the middle: 12 supports, two of them under the
/// door without a contact point. (On the 1.0 and 2.0 m façades a base block stands on two or
/// four supports, and their horizontal sides are rays of the free columns: no local ray.)
fn small_facade() -> Structure {
    let spec = FacadeSpec {
        width: 6.0,
        height: 3.0,
        gable: 0.0,
        openings: vec![Opening::PointedDoor {
            x: 3.0,
            width: 1.0,
            springing: 1.5,
            offset: 0.25,
            ring: 0.5,
        }],
        segments: 12,
        ..bondeno(0.5, FacadeMesh::Grid)
    };
    Structure::new(&facade(&spec).unwrap(), BuildOptions::default()).unwrap()
}

#[test]
fn issue29_local_rays_give_the_ranges_of_every_side_from_scratch() {
    // The sequence with the local rays against every side's program from scratch
    // (`RangeSolve::Independent`: the requested method's whole chain, no ray kept, no mirror,
    // no local ray), equal to 1e-9 of the largest end, the unbounded ends the same.
    let st = small_facade();
    println!(
        "{} blocks, {} supports",
        st.contact_bodies().blocks.len(),
        st.num_supports()
    );
    let o = SolverOptions::default();
    let (warm, records) = collecting(|| reaction_ranges_by(&st, &o, RangeSolve::Sequence).unwrap());
    let cold = reaction_ranges_by(&st, &o, RangeSolve::Independent).unwrap();
    println!(
        "sequence: {} solves, {} local rays, {} unbounded, {} without columns, {} mirrored; independent: {} solves",
        warm.solves, warm.local_rays, warm.unbounded, warm.without_columns, warm.mirrored, cold.solves
    );
    assert_eq!((cold.local_rays, cold.without_columns), (0, 0));
    same_ranges(&warm, &cold, 1e-9);
    let unbounded = range_ends(&cold, false);
    assert!(unbounded > 0);
    assert_eq!(warm.unbounded, unbounded);
    // The new path: local rays were found, and no run of the whole program ended
    // "unbounded" (before: one warm run per unbounded `fx max`, each with HiGHS's ray).
    assert!(warm.local_rays > 0);
    assert!(records
        .iter()
        .any(|r| r.programs.contains("around the support")));
    let whole_unbounded = records
        .iter()
        .filter(|r| r.programs == "reaction ranges" && r.outcome == Outcome::Unbounded)
        .count();
    assert_eq!(whole_unbounded, 0, "{records:?}");
    // The supports without a contact point, from the joints: 4 ends each (fx, fy; min, max)
    // are 0 without a program.
    let mut touched = vec![false; st.num_supports()];
    for j in st.contact_joints() {
        for b in [j.a, j.b] {
            if let Body::Support(s) = b {
                touched[s] = true;
            }
        }
    }
    let bare = touched.iter().filter(|t| !**t).count();
    assert!(bare > 0);
    assert_eq!(warm.without_columns, 4 * bare);
    for (r, t) in warm.ranges.iter().zip(&touched) {
        if !t {
            for c in &r.components {
                assert_eq!((c.min, c.max), (Some(0.0), Some(0.0)), "{}", r.support);
            }
        }
    }
}

#[test]
fn issue29_clarabel_at_zero_after_one_half_leaves_a_finite_factor_as_it_was() {
    // A semicircular arch of centreline radius 1, t/R = 0.5, 64 voussoirs: its factor 4.6083
    // (docs/safety.md) is above 2, so f = 1 and 1/2 stand and Clarabel is asked about f = 0 on
    // the merged program; it does not stand there, and the bisection goes on. The fraction is
    // the one the bisection by hand on independent programs ends on (each from scratch).
    let spec = ArchSpec {
        radius: 1.0,
        radius_at: RadiusAt::Centreline,
        thickness: 0.5,
        voussoirs: 64,
        live: LiveLoad::None,
        ..ArchSpec::default()
    };
    let st = Structure::new(&arch(&spec).unwrap(), BuildOptions::default()).unwrap();
    let (r, records) = collecting(|| {
        safety(
            &st,
            &SafetyOptions {
                reactions: false,
                ..SafetyOptions::default()
            },
        )
        .unwrap()
    });
    let f = r.least_joint_fraction.unwrap();
    assert!((1.0 / f - 4.6083).abs() < 1e-3, "factor {}", 1.0 / f);
    // Clarabel was asked about f = 0 (an "elastic decisions" record), once.
    let asked = records
        .iter()
        .filter(|r| r.programs == "elastic decisions")
        .count();
    assert_eq!(asked, 1, "{records:?}");
    assert!(!stands_from_scratch(&st, 0.0));
    assert_eq!(f, least_fraction_from_scratch(&st));
}
