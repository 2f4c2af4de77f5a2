//! Generated models are valid structures with the expected geometry.

use voussoir::analysis::{limit, LimitStatus};
use voussoir::generate::{arch, wall, ArchShape, ArchSpec, LiveLoad, RadiusAt, WallSpec};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure};

fn radii(st: &Structure) -> (f64, f64) {
    let r: Vec<f64> = st
        .blocks
        .iter()
        .flat_map(|b| b.polygon.iter().map(|p| p[0].hypot(p[1])))
        .collect();
    (
        r.iter().cloned().fold(f64::INFINITY, f64::min),
        r.iter().cloned().fold(0.0, f64::max),
    )
}

#[test]
fn arch_radius_references() {
    for (at, ri) in [
        (RadiusAt::Intrados, 2.0),
        (RadiusAt::Centreline, 1.9),
        (RadiusAt::Extrados, 1.8),
    ] {
        let m = arch(&ArchSpec {
            radius: 2.0,
            radius_at: at,
            thickness: 0.2,
            voussoirs: 20,
            ..ArchSpec::default()
        })
        .unwrap();
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let (lo, hi) = radii(&st);
        assert!(
            (lo - ri).abs() < 1e-12 && (hi - ri - 0.2).abs() < 1e-12,
            "{at:?}: {lo}, {hi}"
        );
        assert_eq!(st.joints.len(), 21);
        // Weight: a ring of 20 chord-sided voussoirs: (n/2) sin(2π/2n)·(re² − ri²)·γ.
        let n = 20.0;
        let area = 0.5 * n * (std::f64::consts::PI / n).sin() * ((ri + 0.2f64).powi(2) - ri * ri);
        let w: f64 = st.blocks.iter().map(|b| b.weight).sum();
        assert!((w - 18.0 * area).abs() < 1e-9, "{w}");
    }
}

#[test]
fn segmental_and_pointed_arches_stand_and_collapse() {
    for shape in [
        ArchShape::Segmental {
            half_angle: 60f64.to_radians(),
        },
        ArchShape::Pointed { offset: 0.5 },
    ] {
        let m = arch(&ArchSpec {
            shape,
            radius: 3.0,
            thickness: 0.4,
            voussoirs: 24,
            live: LiveLoad::Left,
            ..ArchSpec::default()
        })
        .unwrap();
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        assert_eq!(st.joints.len(), 25, "{shape:?}");
        // Mirror symmetry of the geometry.
        let xs: f64 = st.blocks.iter().map(|b| b.centroid[0] * b.area).sum();
        assert!(xs.abs() < 1e-9, "{shape:?}");
        let r = limit(&st, &SolverOptions::default()).unwrap();
        assert_eq!(r.status, LimitStatus::Collapse, "{shape:?}: {}", r.message);
        assert!(r.load_multiplier.unwrap() > 0.0);
    }
    // The segmental springings are inclined: the support joints are radial at ±60° from the top.
    let m = arch(&ArchSpec {
        shape: ArchShape::Segmental {
            half_angle: 60f64.to_radians(),
        },
        voussoirs: 12,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let j = st
        .joints
        .iter()
        .find(|j| matches!(j.b, voussoir::structure::Body::Support(_)))
        .unwrap();
    let ang = j.normal[1].atan2(j.normal[0]).to_degrees().abs();
    assert!(
        (ang - 120.0).abs() < 1e-9 || (ang - 60.0).abs() < 1e-9,
        "{ang}"
    );
}

#[test]
fn wall_with_tilting_table_load() {
    // A wall is monolithic under Heyman's rule: on a tilting table it overturns as one body
    // about its toe, λ = b/h of the whole wall.
    let m = wall(&WallSpec {
        courses: 10,
        units: 4,
        unit: [0.4, 0.2],
        live: LiveLoad::Horizontal,
        ..WallSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert!(
        (r.load_multiplier.unwrap() - 1.6 / 2.0).abs() < 1e-9,
        "{:?}",
        r.load_multiplier
    );
}
