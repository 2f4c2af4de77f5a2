//! The paper's lintel (Figs 6–7): single course of bricks, span 1.5 m, depth 0.24 m, 1 kN/m on
//! the extrados, a horizontal displacement imposed at one end, f_c = 2.4 MPa.
//! Model chosen here (the paper does not give it): 6 bricks of 0.25 m, γ = 18 kN/m³, abutments
//! as supports `left` and `right`, the right one moving outwards.

use voussoir::analysis::capacity::{capacity, CapacityOptions};
use voussoir::analysis::{settle, LimitStatus};
use voussoir::generate::{lintel, LintelSpec};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure};

fn paper_lintel(fc: Option<f64>, delta: f64) -> Structure {
    let mut m = lintel(&LintelSpec {
        compressive_strength: fc,
        ..LintelSpec::default()
    })
    .unwrap();
    let i = m.support_index("right").unwrap();
    m.supports[i].motion = [delta, 0.0, 0.0];
    Structure::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn lintel_spreading_mechanism_is_a_flat_three_hinge_arch() {
    let st = paper_lintel(None, 0.02);
    let r = settle(&st, &SolverOptions::default()).unwrap();
    // Hinges at the bottom corners on both abutments and at the top of the crown joint.
    let pts: Vec<(f64, f64)> = r.hinges.iter().map(|h| (h.x, h.y)).collect();
    assert_eq!(pts.len(), 3);
    let close =
        |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12;
    assert!(
        close(pts[0], (-0.75, 0.0)) && close(pts[1], (0.0, 0.24)) && close(pts[2], (0.75, 0.0)),
        "{pts:?}"
    );
    // Compatibility of the rigid halves: each rotates by δ/(2t) and the crown drops by
    // (L/2)·δ/(2t).
    let crown_drop = 0.75 * 0.02 / 0.48;
    let b2 = &r.blocks[2];
    let b0 = &r.blocks[0];
    assert!(
        (b0.theta + 0.02 / 0.48).abs() < 1e-12,
        "rotation {}",
        b0.theta
    );
    let x = [0.0, 0.24];
    let c = st.blocks[2].centroid;
    let v_crown = b2.v + b2.theta * (x[0] - c[0]);
    assert!(
        (v_crown + crown_drop).abs() < 1e-12,
        "crown moves by {v_crown}"
    );
}

#[test]
fn lintel_capacity_falls_with_the_imposed_displacement() {
    let st = paper_lintel(Some(2400.0), 0.2);
    let r = capacity(
        &st,
        &CapacityOptions {
            steps: 20,
            ..CapacityOptions::default()
        },
    )
    .unwrap();
    assert_eq!(r.curve[0].status, LimitStatus::Collapse);
    // Undeformed: the flat-arch capacity f_c w t²/4 = (g + λq) L²/8 (see tests/joint_laws.rs).
    let l0 = r.curve[0].load_multiplier.unwrap();
    assert!((l0 - 118.56).abs() < 1e-6, "λ(0) = {l0}");
    // The multiplier falls monotonically with the imposed displacement …
    let lams: Vec<f64> = r.curve.iter().filter_map(|p| p.load_multiplier).collect();
    let zero = r.zero_capacity_settlement.unwrap();
    for (p, w) in r.curve.iter().zip(lams.windows(2)) {
        if p.settlement < zero {
            assert!(w[1] < w[0], "λ rises at s = {}", p.settlement);
        }
    }
    // … and vanishes near half the thickness (the paper's Fig 7): within 8 % of t/2.
    assert!((zero - 0.12).abs() <= 0.08 * 0.12, "λ = 0 at {zero} m");
}
