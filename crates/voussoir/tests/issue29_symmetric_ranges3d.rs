//! Issue 29 items 4 and 6 (session 20): the reaction ranges of a 3D structure by its
//! symmetries. `safety`'s ranges of a dome are one range per support, all alike: the 24 × 24
//! dome spent 68 of its 82 s (wall, load 8–9) on 24 equal vertical maxima (343.34 kN each).
//! The rotations about the vertical axis and the mirrors in vertical planes that map the
//! structure onto itself are found from the geometry (`safety::isometries_3d`); each side
//! solved gives its image under each of them — the image support's side, used only where its
//! own certificate on that side's program holds (`lp::sequence::certify`). The 24 × 24 dome's
//! `safety`: range solves 89 → 43, 41.7 → 29.6 CPU s, the same ranges
//! (docs/performance.md, "3D symmetries of the reaction ranges (session 20)").
//!
//! The reference: every side's program solved from scratch (`RangeSolve::Independent`: no
//! warm start, no symmetry), to 1e-6 of the largest end.

mod support;
use support::{dome_model, same_ranges};
use voussoir::analysis::safety::{reaction_ranges_by, RangeSolve};
use voussoir::lp::SolverOptions;
use voussoir::structure::Assembly;
use voussoir::{BuildOptions, Structure3d};

#[test]
fn issue29_item4_a_domes_ranges_by_its_rotations_equal_every_side_from_scratch() {
    let (courses, segments) = (4, 12);
    let st =
        Structure3d::new(&dome_model(courses, segments, 0.0), BuildOptions::default()).unwrap();
    let o = SolverOptions::default();
    let warm = reaction_ranges_by(&st, &o, RangeSolve::Sequence).unwrap();
    let cold = reaction_ranges_by(&st, &o, RangeSolve::Independent).unwrap();
    same_ranges(&warm, &cold, 1e-6);
    assert_eq!(cold.mirrored, 0);
    // The first support's two vertical ends solved give every other support's: 2 per support.
    assert!(
        warm.mirrored >= 2 * (segments - 1),
        "{} sides by symmetry",
        warm.mirrored
    );
    assert!(
        warm.solves < cold.solves,
        "{} against {}",
        warm.solves,
        cold.solves
    );
    // Every support carries the same vertical range (the dome's rotational symmetry), and the
    // supports' largest vertical reactions exceed an equal share of the weight.
    let fz = |r: &voussoir::result::safety::AdmissibleReactionRange| {
        let c = r.components.iter().find(|c| c.component == "fz").unwrap();
        (c.min.unwrap(), c.max.unwrap())
    };
    let first = fz(&warm.ranges[0]);
    for r in &warm.ranges {
        let (lo, hi) = fz(r);
        assert!((lo - first.0).abs() <= 1e-9 * first.1 && (hi - first.1).abs() <= 1e-9 * first.1);
    }
    let weight: f64 = st.load_vector(false).chunks(6).map(|f| f[2].abs()).sum();
    assert!(
        first.1 > weight / segments as f64,
        "{} against {}",
        first.1,
        weight
    );
}

#[test]
fn issue29_item4_a_symmetry_broken_by_the_loads_is_refused_by_the_certificates() {
    // One block of the first segment three times as heavy: the geometry keeps its rotations,
    // the program does not. Every image is refused by its certificate and solved instead.
    let mut m = dome_model(4, 12, 0.0);
    let mut heavy = m.materials["default"].clone();
    heavy.unit_weight *= 3.0;
    m.materials.insert("heavy".into(), heavy);
    m.blocks[1].material = Some("heavy".into());
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let o = SolverOptions::default();
    let warm = reaction_ranges_by(&st, &o, RangeSolve::Sequence).unwrap();
    let cold = reaction_ranges_by(&st, &o, RangeSolve::Independent).unwrap();
    same_ranges(&warm, &cold, 1e-6);
    // The supports' largest vertical reactions differ now (the heavy block's side).
    let maxima: Vec<f64> = warm
        .ranges
        .iter()
        .map(|r| {
            r.components
                .iter()
                .find(|c| c.component == "fz")
                .unwrap()
                .max
                .unwrap()
        })
        .collect();
    let (lo, hi) = maxima
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
    assert!(hi - lo > 1e-3 * hi, "{maxima:?}");
}

#[test]
fn issue29_item4_safety_reports_the_ends_given_by_symmetry() {
    use voussoir::analysis::safety::{safety, SafetyOptions};
    let segments = 12;
    let st = Structure3d::new(&dome_model(4, segments, 0.0), BuildOptions::default()).unwrap();
    let r = safety(&st, &SafetyOptions::default()).unwrap();
    assert!(r.stands);
    // Every support but the first: its two vertical ends.
    assert!(
        r.reaction_ends_by_symmetry >= 2 * (segments - 1),
        "{}",
        r.reaction_ends_by_symmetry
    );
    let cold = reaction_ranges_by(&st, &SolverOptions::default(), RangeSolve::Independent).unwrap();
    for (a, b) in r.reactions.iter().zip(&cold.ranges) {
        let (x, y) = (a.component("fz").unwrap(), b.component("fz").unwrap());
        assert!((x.max.unwrap() - y.max.unwrap()).abs() <= 1e-6 * y.max.unwrap());
    }
}
