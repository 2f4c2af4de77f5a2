//! Issue 32 item 1, foundations as drawn: a support that spans a profile's breakpoints is cut
//! there before the structure is built, so that the blocks on each part follow the profile.

use voussoir::analysis::settlement::settle;
use voussoir::generate3d::{extrude, Bond};
use voussoir::geometry::{area_centroid, signed_area};
use voussoir::lp::SolverOptions;
use voussoir::model::Model;
use voussoir::settlement_input::{
    apply_profile, apply_profile_as_drawn, split_support, split_supports_at, Profile,
};
use voussoir::{BuildOptions, Structure, Structure3d};

const GAMMA: f64 = 20.0;

fn model(supports: &str, blocks: &str) -> Model {
    serde_json::from_str(&format!(
        r#"{{"materials": {{"default": {{"unit_weight": {GAMMA}, "width": 1.0}}}},
            "blocks": [{blocks}], "supports": [{supports}]}}"#
    ))
    .unwrap()
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> String {
    format!("[[{x0},{y0}],[{x1},{y0}],[{x1},{y1}],[{x0},{y1}]]")
}

/// One base 2 m × 0.5 m; on it, apart, a left block 0.7 × 1.0 and a right one 0.7 × 0.8.
fn two_blocks_on_one_base() -> Model {
    model(
        &format!(
            r#"{{"name": "base", "polygon": {}}}"#,
            rect(0.0, 0.0, 2.0, 0.5)
        ),
        &format!(
            r#"{{"polygon": {}}}, {{"polygon": {}}}"#,
            rect(0.2, 0.5, 0.9, 1.5),
            rect(1.1, 0.5, 1.8, 1.3)
        ),
    )
}

const V: f64 = -0.01;

/// The profile v = −1 cm on 1 ≤ x ≤ 2 ends inside the base (x = 1) and on its edge (x = 2):
/// the base is cut once, the right block drops by 1 cm, the left stays, and the work of the
/// dead loads is the right block's weight times the drop, by hand: 0.7 × 0.8 × 20 × 0.01.
#[test]
fn issue32_item1_two_blocks_on_one_base_split_by_the_profile() {
    let mut m = two_blocks_on_one_base();
    let profile = Profile::Uniform {
        x0: 1.0,
        x1: 2.0,
        v: V,
    };
    let splits = apply_profile_as_drawn(&mut m, &profile).unwrap();
    assert_eq!(splits.len(), 1);
    let s = &splits[0];
    assert_eq!(s.support, "base");
    assert_eq!(s.cuts, vec![1.0]);
    let names: Vec<&str> = s.parts.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["base@0", "base@1"]);
    assert_eq!(s.parts[0].x_range, [0.0, 1.0]);
    assert_eq!(s.parts[1].x_range, [1.0, 2.0]);
    assert_eq!(s.parts[0].motion, vec![0.0, 0.0, 0.0]);
    assert_eq!(s.parts[1].motion, vec![0.0, V, 0.0]);
    // The parts are exactly the two rectangles.
    assert_eq!(m.supports.len(), 2);
    for (sp, x) in m.supports.iter().zip([[0.0, 1.0], [1.0, 2.0]]) {
        let mut p = sp.polygon.clone();
        p.sort_by(|a, b| a.partial_cmp(b).unwrap());
        assert_eq!(p, vec![[x[0], 0.0], [x[0], 0.5], [x[1], 0.0], [x[1], 0.5]]);
        assert!(signed_area(&sp.polygon) > 0.0);
    }

    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = settle(&st, &SolverOptions::default()).unwrap();
    let w_right = 0.7 * 0.8 * GAMMA * 1.0;
    let expect = w_right * -V;
    let work = r.work_dead_loads.unwrap();
    assert!(
        (work - expect).abs() <= 1e-9 * expect,
        "work {work} against W_right·v = {expect}"
    );
    assert!(r.certificate.as_ref().unwrap().ok);
    let (left, right) = (&r.blocks[0], &r.blocks[1]);
    assert!(left.u.abs() < 1e-12 && left.v.abs() < 1e-12 && left.theta.abs() < 1e-12);
    assert!((right.v - V).abs() < 1e-12 && right.u.abs() < 1e-12 && right.theta.abs() < 1e-12);

    // By the centroid alone (the library's `apply_profile`), the whole base (centroid x = 1)
    // drops: both blocks go down, work = (W_left + W_right)·v.
    let mut whole = two_blocks_on_one_base();
    apply_profile(&mut whole, &profile).unwrap();
    let st = Structure::new(&whole, BuildOptions::default()).unwrap();
    let r = settle(&st, &SolverOptions::default()).unwrap();
    let all = (0.7 * 1.0 + 0.7 * 0.8) * GAMMA * -V;
    assert!((r.work_dead_loads.unwrap() - all).abs() <= 1e-9 * all);
}

/// The same in 3D (the model extruded 1.5 m deep): the base box is cut by the plane x = 1.
#[test]
fn issue32_item1_a_convex_3d_support_is_cut_by_the_plane() {
    let mut m = extrude(&two_blocks_on_one_base(), 1.5, 1, Bond::Stack).unwrap();
    let profile = Profile::Uniform {
        x0: 1.0,
        x1: 2.0,
        v: V,
    };
    let splits = apply_profile_as_drawn(&mut m, &profile).unwrap();
    assert_eq!(splits[0].parts.len(), 2);
    assert_eq!(splits[0].parts[0].x_range, [0.0, 1.0]);
    assert_eq!(splits[0].parts[1].motion, vec![0.0, 0.0, V, 0.0, 0.0, 0.0]);
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let r = settle(&st, &SolverOptions::default()).unwrap();
    let expect = 0.7 * 0.8 * 1.5 * GAMMA * -V;
    let work = r.work_dead_loads.unwrap();
    assert!(
        (work - expect).abs() <= 1e-7 * expect,
        "{work} against {expect}"
    );
}

/// A C-shaped (non-convex) support cut at x = 2: the left strip is one piece, the right one
/// two (the arms), each exact (vertices on the original ones or on the cut line).
#[test]
fn issue32_item1_a_non_convex_support_is_cut_exactly() {
    let c = "[[0,0],[3,0],[3,1],[1,1],[1,2],[3,2],[3,3],[0,3]]";
    let mut m = model(
        &format!(r#"{{"name": "c", "polygon": {c}}}"#),
        &format!(r#"{{"polygon": {}}}"#, rect(0.0, 3.0, 1.0, 4.0)),
    );
    let s = split_support(&mut m, "c", &[2.0]).unwrap();
    let names: Vec<&str> = s.parts.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["c@0", "c@1", "c@2"]);
    let areas: Vec<f64> = m.supports.iter().map(|s| signed_area(&s.polygon)).collect();
    assert_eq!(areas, vec![5.0, 1.0, 1.0]);
    let mut left = m.supports[0].polygon.clone();
    left.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let mut expect = vec![
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [2.0, 2.0],
        [2.0, 3.0],
        [0.0, 3.0],
    ];
    expect.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(left, expect);
    // The arms from the lower one up.
    assert_eq!(area_centroid(&m.supports[1].polygon).1, [2.5, 0.5]);
    assert_eq!(area_centroid(&m.supports[2].polygon).1, [2.5, 2.5]);

    // A slanted edge: the cut vertex lies on it, x exactly the cut.
    let mut m = model(
        r#"{"name": "t", "polygon": [[0,0],[3,0],[2,1],[0.5,1]]}"#,
        &format!(r#"{{"polygon": {}}}"#, rect(0.5, 1.0, 2.0, 2.0)),
    );
    split_support(&mut m, "t", &[0.3, 2.5]).unwrap();
    assert_eq!(m.supports.len(), 3);
    let on_cut: Vec<[f64; 2]> = m.supports[0]
        .polygon
        .iter()
        .copied()
        .filter(|p| p[0] == 0.3)
        .collect();
    assert_eq!(on_cut.len(), 2, "{:?}", m.supports[0].polygon);
    assert!(on_cut.iter().any(|p| p[1] == 0.0));
    assert!(on_cut.iter().any(|p| (p[1] - 0.6).abs() < 1e-15));
    let total: f64 = m.supports.iter().map(|s| signed_area(&s.polygon)).sum();
    assert!((total - 2.25).abs() < 1e-14, "{total}");
}

/// Refusals, one line each; a support that spans no breakpoint is left exactly as it was.
#[test]
fn issue32_item1_refusals_and_untouched_supports() {
    let mut m = two_blocks_on_one_base();
    let e = split_support(&mut m, "nope", &[1.0])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("no support named 'nope'") && !e.contains('\n'),
        "{e}"
    );
    let e = split_support(&mut m, "base", &[2.5])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("x = 2.5 m is not inside") && !e.contains('\n'),
        "{e}"
    );
    let e = split_support(&mut m, "base", &[2.0])
        .unwrap_err()
        .to_string();
    assert!(e.contains("not inside"), "{e}");
    assert_eq!(m, two_blocks_on_one_base());
    // Breakpoints on the edges or outside: nothing cut.
    assert!(split_supports_at(&mut m, &[0.0, 2.0, 7.0])
        .unwrap()
        .is_empty());
    assert_eq!(m, two_blocks_on_one_base());
    // A 3D support that is not convex is refused.
    let mut m3 = extrude(
        &model(
            r#"{"name": "c", "polygon": [[0,0],[3,0],[3,1],[1,1],[1,2],[3,2],[3,3],[0,3]]}"#,
            &format!(r#"{{"polygon": {}}}"#, rect(0.0, 3.0, 1.0, 4.0)),
        ),
        1.0,
        1,
        Bond::Stack,
    )
    .unwrap();
    let e = split_support(&mut m3, "c", &[2.0]).unwrap_err().to_string();
    assert!(e.contains("not convex"), "{e}");
}
