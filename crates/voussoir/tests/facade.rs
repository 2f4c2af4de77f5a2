//! The façade generator: valid geometry (simple polygons, no overlaps, every element touching
//! something), areas against closed forms, radial voussoirs, and the paper's settlement case.

mod support;
use support::settle_right_half;
use voussoir::analysis::settlement::{settle_with, SettlementForm, SettlementStatus};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh, FacadeSpec, Opening};
use voussoir::geometry::{area_centroid, cross, sub};
use voussoir::lp::SolverOptions;
use voussoir::structure::Body;
use voussoir::{BuildOptions, Structure};

fn area(p: &[[f64; 2]]) -> f64 {
    area_centroid(p).0
}

/// Gross area of the Bondeno façade minus its openings, from closed forms: rectangle plus gable
/// triangle; doors = jamb rectangle + equilateral pointed arch of span s, area s²(π/3 − √3/4);
/// rose windows = πr².
fn net_area(s: &FacadeSpec) -> f64 {
    let mut a = s.width * s.height + 0.5 * s.width * s.gable;
    for o in &s.openings {
        a -= match *o {
            Opening::PointedDoor {
                width, springing, ..
            } => {
                width * springing + width * width * (std::f64::consts::PI / 3.0 - 3f64.sqrt() / 4.0)
            }
            Opening::Round { radius, .. } => std::f64::consts::PI * radius * radius,
            Opening::Rect { x0, y0, x1, y1 } => (x1 - x0) * (y1 - y0),
        };
    }
    a
}

#[test]
fn bondeno_grid_is_a_valid_structure_with_the_right_area() {
    let spec = bondeno(0.5, FacadeMesh::Grid);
    let m = facade(&spec).unwrap();
    // Structure::new rejects non-simple polygons, overlaps and elements touching nothing.
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    assert_eq!(st.supports.len(), 44);
    let total: f64 = m.blocks.iter().map(|b| area(&b.polygon)).sum();
    let net = net_area(&spec);
    // Differences: chords of the arcs (openings drawn as inscribed polygons, so slightly
    // smaller: more wall) and dropped slivers (less wall). Both well under 0.5 %.
    assert!(
        (total - net).abs() < 0.005 * net,
        "blocks {total} m², closed form {net} m²"
    );
    // Every block is a simple polygon of positive area.
    for b in &st.blocks {
        assert!(b.area > 0.0);
    }
    println!(
        "{} blocks, {} joints, area {total:.3} m² (closed form {net:.3})",
        st.blocks.len(),
        st.joints.len()
    );
}

#[test]
fn ring_voussoirs_are_radial() {
    let spec = FacadeSpec {
        openings: vec![Opening::Round {
            x: 11.0,
            y: 10.0,
            radius: 2.0,
            ring: 0.5,
        }],
        ..bondeno(0.5, FacadeMesh::RunningBond)
    };
    let m = facade(&spec).unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    // The ring: quadrilaterals with two vertices at radius 2 and two at 2.5 from the centre.
    let c = [11.0, 10.0];
    let r = |p: [f64; 2]| (p[0] - c[0]).hypot(p[1] - c[1]);
    let ring: Vec<&Vec<[f64; 2]>> = m
        .blocks
        .iter()
        .map(|b| &b.polygon)
        .filter(|p| p.len() == 4 && p.iter().filter(|q| (r(**q) - 2.0).abs() < 1e-9).count() == 2)
        .collect();
    assert!(ring.len() >= 24, "{} voussoirs", ring.len());
    assert_eq!(ring.len() % 4, 0);
    for p in ring {
        // Each side joint (inner vertex to outer vertex) points at the centre.
        for i in 0..4 {
            let (a, b) = (p[i], p[(i + 1) % 4]);
            if ((r(a) - 2.0).abs() < 1e-9) != ((r(b) - 2.0).abs() < 1e-9) {
                let d = sub(b, a);
                let off = cross(d, sub(c, a)).abs() / d[0].hypot(d[1]);
                assert!(off < 1e-9, "joint {a:?}–{b:?} misses the centre by {off}");
            }
        }
    }
    // The ring rests on the wall: some ring voussoir has joints with wall elements.
    assert!(st.joints.len() > st.blocks.len());
}

#[test]
fn running_bond_with_a_rectangular_window_is_valid() {
    let spec = FacadeSpec {
        width: 6.0,
        height: 4.0,
        gable: 0.0,
        element: [0.4, 0.2],
        openings: vec![
            Opening::Rect {
                x0: 1.0,
                y0: 1.5,
                x1: 2.3,
                y1: 2.9,
            },
            Opening::PointedDoor {
                x: 4.3,
                width: 1.0,
                springing: 1.6,
                offset: 0.5,
                ring: 0.3,
            },
        ],
        segments: 6,
        ..bondeno(0.4, FacadeMesh::RunningBond)
    };
    let m = facade(&spec).unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let total: f64 = m.blocks.iter().map(|b| area(&b.polygon)).sum();
    let net = net_area(&spec);
    assert!((total - net).abs() < 0.01 * net, "{total} vs {net}");
    // The window's sill and head are course lines: elements end exactly there.
    for y in [1.5, 2.9] {
        let on = st
            .blocks
            .iter()
            .filter(|b| b.polygon.iter().any(|p| (p[1] - y).abs() < 1e-12))
            .count();
        assert!(on > 10, "{on} blocks with a vertex at y = {y}");
    }
}

#[test]
fn bad_facades_are_refused_in_one_line() {
    let mut s = bondeno(0.5, FacadeMesh::Grid);
    s.openings.push(Opening::Round {
        x: 11.0,
        y: 10.5,
        radius: 1.0,
        ring: 0.3,
    });
    let e = facade(&s).unwrap_err().to_string();
    assert!(e.contains("overlap") && !e.contains('\n'), "{e}");
    let mut s = bondeno(0.5, FacadeMesh::Grid);
    s.openings = vec![Opening::Round {
        x: 0.5,
        y: 5.0,
        radius: 1.0,
        ring: 0.3,
    }];
    assert!(facade(&s).unwrap_err().to_string().contains("does not fit"));
    let mut s = bondeno(0.5, FacadeMesh::Grid);
    s.element = [-1.0, 0.5];
    assert!(facade(&s).is_err());
}

#[test]
fn paper_settlement_of_half_the_facade_fractures_it() {
    // Coarser elements keep the test quick; the example uses 0.5 m.
    let spec = bondeno(0.8, FacadeMesh::Grid);
    let m = facade(&spec).unwrap();
    let st = settle_right_half(m);
    let r = settle_with(&st, &SolverOptions::default(), SettlementForm::ForceOnly).unwrap();
    assert_eq!(r.status, SettlementStatus::Mechanism);
    let c = r.certificate.as_ref().unwrap();
    assert!(c.ok && c.relative_gap < 1e-7, "{c:?}");
    // The dead loads do positive work: the settled half follows the foundation down.
    let w = r.work_dead_loads.unwrap();
    assert!(w > 0.0, "{w}");
    // Upper bound: no block's centroid can drop by more than the 0.2 m settlement plus the
    // rotation of the tallest part about its base over the wall's width (0.2/11·19 m).
    let total: f64 = st.blocks.iter().map(|b| b.weight).sum();
    assert!(w < total * (0.2 + 0.2 / 11.0 * 19.0), "{w}");
    // Blocks resting on the unsettled half do not go down into it.
    for j in &st.joints {
        if let (Body::Block(i), Body::Support(s)) = (j.a, j.b) {
            if st.supports[s].centroid[0] < 11.0 {
                let b = &r.blocks[i];
                let c = st.blocks[i].centroid;
                for p in &j.points {
                    let v = b.v + b.theta * (p.x[0] - c[0]);
                    assert!(v > -1e-9, "block {i} sinks into support {s}: {v}");
                }
            }
        }
    }
    assert!(!r.hinges.is_empty());
}
