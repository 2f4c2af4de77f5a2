//! Interface detection and model validation.

use voussoir::generate::{wall, FirstCourse, WallSpec};
use voussoir::model::{Block, Loads, Model, Support};
use voussoir::{BuildOptions, Error, Structure};

/// Joints of a running-bond wall counted by hand: head joints per course (U−1 in a full course,
/// U in a half course), 2U bed joints between consecutive courses, one base joint per unit of
/// the first course (each on its own foundation segment).
fn expected_joints(courses: usize, units: usize, first: FirstCourse) -> usize {
    let mut heads = 0;
    for c in 0..courses {
        let full = (c % 2 == 0) == (first == FirstCourse::Full);
        heads += if full { units - 1 } else { units };
    }
    let base = if first == FirstCourse::Full {
        units
    } else {
        units + 1
    };
    heads + (courses - 1) * 2 * units + base
}

#[test]
fn running_bond_joint_counts() {
    for (c, u, first) in [
        (6, 5, FirstCourse::Full),
        (7, 4, FirstCourse::Half),
        (20, 10, FirstCourse::Full),
    ] {
        let m = wall(&WallSpec {
            courses: c,
            units: u,
            first_course: first,
            ..WallSpec::default()
        })
        .unwrap();
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let n = expected_joints(c, u, first);
        assert_eq!(st.joints.len(), n, "{c} courses × {u} units, {first:?}");
        // Two collocation points per joint, at the ends of the overlap.
        assert_eq!(
            st.joints.iter().map(|j| j.points.len()).sum::<usize>(),
            2 * n
        );
        // Bed joints between a full and a half unit are half a unit long, heads a course high,
        // base joints a whole unit (or a half unit at the ends of a half first course).
        for j in &st.joints {
            let ok = [0.2, 0.175, 0.4]
                .iter()
                .any(|l| (j.length - l).abs() < 1e-12);
            assert!(ok, "length {}", j.length);
        }
    }
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

fn model(blocks: Vec<Vec<[f64; 2]>>) -> Model {
    Model {
        blocks: blocks
            .into_iter()
            .map(|p| Block {
                polygon: p,
                material: None,
            })
            .collect(),
        supports: vec![Support {
            name: "base".into(),
            polygon: rect(-5.0, -1.0, 5.0, 0.0),
            motion: [0.0; 3],
            connection: Default::default(),
        }],
        loads: Loads::default(),
        ..Model::default()
    }
}

fn error_of(m: &Model) -> String {
    match Structure::new(m, BuildOptions::default()) {
        Err(Error::Model(s)) => s,
        other => panic!("expected a model error, got {other:?}"),
    }
}

#[test]
fn clockwise_polygons_are_reoriented() {
    let mut p = rect(0.0, 0.0, 1.0, 1.0);
    p.reverse();
    let st = Structure::new(&model(vec![p]), BuildOptions::default()).unwrap();
    assert_eq!(st.joints.len(), 1);
    assert!(
        (st.joints[0].normal[1] + 1.0).abs() < 1e-12,
        "normal from the block into the base"
    );
}

#[test]
fn bad_models_are_explained() {
    let e = error_of(&model(vec![
        rect(0.0, 0.0, 1.0, 1.0),
        vec![[0.0, 1.0], [2.0, 2.0], [2.0, 1.0], [0.0, 3.0]],
    ]));
    assert!(
        e.contains("block 1") && e.contains("self-intersecting"),
        "{e}"
    );
    let e = error_of(&model(vec![
        rect(0.0, 0.0, 1.0, 1.0),
        rect(0.5, 0.0, 1.5, 1.0),
    ]));
    assert!(e.contains("block 0 and block 1 overlap"), "{e}");
    let e = error_of(&model(vec![
        rect(0.0, 0.0, 1.0, 1.0),
        rect(3.0, 2.0, 4.0, 3.0),
    ]));
    assert!(e.contains("block 1 touches nothing"), "{e}");
    let e = error_of(&model(vec![vec![[0.0, 0.0], [1.0, 0.0]]]));
    assert!(e.contains("block 0") && e.contains("at least 3"), "{e}");
    let e = error_of(&model(vec![vec![[0.0, 0.0], [1.0, 0.0], [f64::NAN, 1.0]]]));
    assert!(e.contains("block 0") && e.contains("finite"), "{e}");
    let e = error_of(&model(vec![vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]]));
    assert!(e.contains("degenerate"), "{e}");
    let mut m = model(vec![rect(0.0, 0.0, 1.0, 1.0)]);
    m.supports.clear();
    assert!(error_of(&m).contains("no supports"));
    // A block inside another.
    let e = error_of(&model(vec![
        rect(0.0, 0.0, 2.0, 2.0),
        rect(0.5, 0.5, 1.0, 1.0),
    ]));
    assert!(e.contains("overlap"), "{e}");
}
