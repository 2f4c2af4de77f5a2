//! Issue 30, item 3: cracks as an engineer draws them — every result carries `cracks`,
//! polylines through consecutive open joints (2D) and records per crack (3D), checked against
//! hand values (docs/cracks.md).

use voussoir::analysis::{limit, settle, SettlementStatus};
use voussoir::generate::{arch, wall, ArchSpec, LiveLoad, WallSpec};
use voussoir::generate3d::{vault, Bond};
use voussoir::lp::SolverOptions;
use voussoir::result::{BodyName, Crack, CrackFront, SettlementResult};
use voussoir::{BuildOptions, Model, Structure, Structure3d};

const TOL: f64 = 1e-9;

fn model(json: &str) -> Model {
    serde_json::from_str(json).unwrap()
}

fn settled(m: &Model) -> SettlementResult {
    let st = Structure::new(m, BuildOptions::default()).unwrap();
    let r = settle(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, SettlementStatus::Mechanism, "{}", r.message);
    assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
    r
}

fn close(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).abs() <= TOL && (a[1] - b[1]).abs() <= TOL
}

/// Two unit blocks stacked, the lower one tied to a fixed base, the upper one tied to a cap
/// that turns clockwise by θ = 0.01 rad about the joint's right end (1, 1). The joint between
/// the blocks opens as a wedge: opening θ·x' at distance x' from the hinge, 0.01 m at (0, 1).
#[test]
fn issue30_item3_a_wedge_along_one_joint_has_the_hand_values() {
    let theta: f64 = -0.01;
    // The cap's centroid is (0.5, 2.25); a rotation θ about (1, 1) moves it by
    // θ × (c − (1, 1)) = (−θ·1.25, θ·(−0.5)).
    let (u, v) = (-theta * 1.25, -0.5 * theta);
    let m = model(&format!(
        r#"{{"materials": {{"default": {{"unit_weight": 20.0, "width": 1.0}}}},
        "blocks": [{{"polygon": [[0,0],[1,0],[1,1],[0,1]]}}, {{"polygon": [[0,1],[1,1],[1,2],[0,2]]}}],
        "supports": [
          {{"name": "base", "polygon": [[0,-0.5],[1,-0.5],[1,0],[0,0]], "connection": "fixed"}},
          {{"name": "cap", "polygon": [[0,2],[1,2],[1,2.5],[0,2.5]], "connection": "fixed", "motion": [{u}, {v}, {theta}]}}
        ]}}"#
    ));
    let r = settled(&m);
    assert_eq!(r.cracks.len(), 1, "{:?}", r.cracks);
    let c = &r.cracks[0];
    // From the mouth (0, 1), 0.01 m wide, to the tip at the hinge (1, 1).
    assert_eq!(c.points.len(), 2);
    assert!(close(c.points[0], [0.0, 1.0]), "{:?}", c.points);
    assert!(close(c.points[1], [1.0, 1.0]), "{:?}", c.points);
    assert!((c.openings[0] - 0.01).abs() <= TOL, "{:?}", c.openings);
    assert!(c.openings[1].abs() <= TOL, "{:?}", c.openings);
    assert!((c.length - 1.0).abs() <= TOL, "{}", c.length);
    assert!((c.max_opening - 0.01).abs() <= TOL, "{}", c.max_opening);
    assert_eq!(c.faces, vec![[BodyName::Block(0), BodyName::Block(1)]]);
    assert!(!c.start.hinge && c.end.hinge);
    // Both ends are on the column's faces (x = 0 and x = 1), neither on a support.
    assert!(c.start.free_edge && c.end.free_edge);
    assert!(!c.start.support && !c.end.support);
    // The hinge the report gives is the crack's tip.
    assert_eq!(r.hinges.len(), 1);
    assert!(close([r.hinges[0].x, r.hinges[0].y], c.points[1]));
}

/// Two blocks side by side, tied to a cap that lifts them by 1 cm off the base they stand on:
/// the two base joints open fully (1 cm everywhere) and meet end to end at (1, 0): one
/// polyline from (0, 0) through (1, 0) to (2, 0), 2 m long.
#[test]
fn issue30_item3_open_joints_meeting_end_to_end_chain_into_one_polyline() {
    let m = model(
        r#"{"materials": {"default": {"unit_weight": 20.0, "width": 1.0}},
        "blocks": [{"polygon": [[0,0],[1,0],[1,1],[0,1]]}, {"polygon": [[1,0],[2,0],[2,1],[1,1]]}],
        "supports": [
          {"name": "base", "polygon": [[0,-0.5],[2,-0.5],[2,0],[0,0]]},
          {"name": "cap", "polygon": [[0,1],[2,1],[2,1.5],[0,1.5]], "connection": "fixed", "motion": [0, 0.01, 0]}
        ]}"#,
    );
    let r = settled(&m);
    assert_eq!(r.cracks.len(), 1, "{:?}", r.cracks);
    let c = &r.cracks[0];
    assert_eq!(c.joints.len(), 2);
    assert_eq!(c.points.len(), 3, "{:?}", c.points);
    for (p, q) in c.points.iter().zip([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]) {
        assert!(close(*p, q), "{:?}", c.points);
    }
    for w in &c.openings {
        assert!((w - 0.01).abs() <= TOL, "{:?}", c.openings);
    }
    // Length = the sum of the two joints' lengths.
    assert!((c.length - 2.0).abs() <= TOL, "{}", c.length);
    assert!((c.max_opening - 0.01).abs() <= TOL);
    assert!(!c.start.hinge && !c.end.hinge);
    assert!(c.start.support && c.end.support && c.start.free_edge && c.end.free_edge);
    assert!(!c.start.junction && !c.end.junction);
    // The faces: each block on the base.
    let mut faces = c.faces.clone();
    faces.sort_by_key(|f| format!("{f:?}"));
    assert_eq!(
        faces,
        vec![
            [BodyName::Block(0), BodyName::Support("base".into())],
            [BodyName::Block(1), BodyName::Support("base".into())]
        ]
    );
}

/// The paper's Fig 9: the right springing moves out by 1 cm; the arch turns about three
/// hinges (tests/settlement.rs). Three cracks, one per hinged joint, each through the arch's
/// thickness (0.33 m) from its mouth to the hinge; the crown's twice as wide as the haunches',
/// which are equal (the mechanism is symmetric: the crown hinge's two halves each turn by the
/// haunch rotation).
#[test]
fn issue30_item3_the_paper_arch_settlement_has_three_cracks_at_its_hinges() {
    let m = arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    let mut st = Structure::new(&m, BuildOptions::default()).unwrap();
    let right = st.supports.iter().position(|s| s.name == "right").unwrap();
    st.supports[right].motion = [0.01, 0.0, 0.0];
    let r = settle(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.hinges.len(), 3);
    assert_eq!(r.cracks.len(), 3, "{:?}", r.cracks);
    for c in &r.cracks {
        assert_eq!(c.joints.len(), 1);
        let h = r.hinges.iter().find(|h| h.joint == c.joints[0]).unwrap();
        assert!(close(c.points[1], [h.x, h.y]), "{:?} vs {:?}", c.points, h);
        assert!(c.end.hinge && !c.start.hinge);
        assert!((c.length - 0.33).abs() <= 1e-9, "{}", c.length);
        assert!(c.start.free_edge && c.end.free_edge);
    }
    let w: Vec<f64> = r.cracks.iter().map(|c| c.max_opening).collect();
    assert!((w[1] - w[2]).abs() <= 1e-9 * w[0], "{w:?}");
    assert!((w[0] - 2.0 * w[1]).abs() <= 1e-6 * w[0], "{w:?}");
    // Widest first: the crown, at x = 0.
    assert!(r.cracks[0].points[0][0].abs() <= 1e-9);
}

/// A running-bond wall whose foundation under x ∈ [2.8, 4.0] drops 1 cm: the wall bridges the
/// gap, the base joints there open by 1 cm and chain into one 1.2 m crack.
fn wall_settlement() -> SettlementResult {
    let m = wall(&WallSpec {
        courses: 8,
        units: 10,
        unit: [0.4, 0.2],
        ..WallSpec::default()
    })
    .unwrap();
    let mut st = Structure::new(&m, BuildOptions::default()).unwrap();
    for s in &mut st.supports {
        let c = s.polygon.iter().map(|p| p[0]).sum::<f64>() / s.polygon.len() as f64;
        if (2.8..=4.0).contains(&c) {
            s.motion = [0.0, -0.01, 0.0];
        }
    }
    settle(&st, &SolverOptions::default()).unwrap()
}

#[test]
fn issue30_item3_a_bridging_wall_has_one_crack_over_the_settled_foundation() {
    let r = wall_settlement();
    assert_eq!(r.cracks.len(), 1, "{:?}", r.cracks);
    let c: &Crack = &r.cracks[0];
    assert_eq!(c.joints.len(), 3);
    assert!((c.length - 1.2).abs() <= 1e-9, "{}", c.length);
    assert!((c.max_opening - 0.01).abs() <= 1e-9, "{}", c.max_opening);
    assert!(
        close(c.points[0], [2.8, 0.0]) && close(c.points[3], [4.0, 0.0]),
        "{:?}",
        c.points
    );
}

#[test]
fn issue30_item3_the_cracks_serialise_identically_run_after_run() {
    let a = serde_json::to_string(&wall_settlement()).unwrap();
    let b = serde_json::to_string(&wall_settlement()).unwrap();
    assert!(a.contains("\"cracks\":[{\"points\""));
    assert_eq!(a, b);
    let m = arch(&ArchSpec {
        live: LiveLoad::Left,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let run = || serde_json::to_string(&limit(&st, &SolverOptions::default()).unwrap()).unwrap();
    let (a, b) = (run(), run());
    assert_eq!(a, b);
    // A result read back keeps its cracks.
    let back: voussoir::result::LimitResult = serde_json::from_str(&a).unwrap();
    assert_eq!(back.cracks.len(), 4);
}

/// The paper's arch under a live load on its left half collapses on four hinges
/// (λ = 0.2189): four cracks, one at each hinge, the mechanism's openings (a rate).
#[test]
fn issue30_item3_a_collapse_mechanism_has_a_crack_at_each_hinge() {
    let m = arch(&ArchSpec {
        live: LiveLoad::Left,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.hinges.len(), 4);
    assert_eq!(r.cracks.len(), 4);
    let mut joints: Vec<usize> = r.cracks.iter().map(|c| c.joints[0]).collect();
    joints.sort_unstable();
    let mut hinged: Vec<usize> = r.hinges.iter().map(|h| h.joint).collect();
    hinged.sort_unstable();
    assert_eq!(joints, hinged);
    // Listed widest first.
    assert!(r
        .cracks
        .windows(2)
        .all(|w| w[0].max_opening >= w[1].max_opening));
}

/// The paper's arch as a barrel vault of three rings, 1 m deep, under the Fig 9 settlement:
/// the three hinged joints of each ring line up into three hinge lines across the vault, 1 m
/// long, as wide as in 2D.
#[test]
fn issue30_item3_3d_vault_cracks_are_hinge_lines_across_the_vault() {
    let m = vault(
        &ArchSpec {
            live: LiveLoad::None,
            ..ArchSpec::default()
        },
        1.0,
        3,
        Bond::Stack,
    )
    .unwrap();
    let mut st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let right = st.supports.iter().position(|s| s.name == "right").unwrap();
    st.supports[right].motion = [0.01, 0.0, 0.0, 0.0, 0.0, 0.0];
    let r = settle(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.cracks.len(), 3, "{:?}", r.cracks);
    for c in &r.cracks {
        assert_eq!(c.joints.len(), 3);
        assert_eq!(c.front, CrackFront::HingeLine);
        assert!((c.length - 1.0).abs() <= 1e-9, "{}", c.length);
        assert!((c.position[1] - 0.5).abs() <= 1e-9, "{:?}", c.position);
        assert!((c.area - 0.33).abs() <= 1e-9, "{}", c.area);
    }
    // The same widths as the 2D arch: 2.22 mm at the crown, half that at the haunches.
    let m2 = arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    let mut st2 = Structure::new(&m2, BuildOptions::default()).unwrap();
    let right = st2.supports.iter().position(|s| s.name == "right").unwrap();
    st2.supports[right].motion = [0.01, 0.0, 0.0];
    let r2 = settle(&st2, &SolverOptions::default()).unwrap();
    for (a, b) in r.cracks.iter().zip(&r2.cracks) {
        assert!((a.max_opening - b.max_opening).abs() <= 1e-7 * b.max_opening);
    }
}

/// A "T" of three fully open joints meeting at (1, 0), traced by the library's tracer on
/// joints written by hand: the widest (0 → 1, 30 mm) continues along the wider of the other
/// two (up to (1, 1), 20 mm); the narrowest (to (2, 0), 10 mm) is a crack of its own whose end
/// at (1, 0) is a junction.
#[test]
fn issue30_item3_at_a_branch_the_crack_continues_along_the_widest_joint() {
    use voussoir::result::cracks::trace_cracks;
    use voussoir::result::{CrackGeometry, JointResult, JointState, PlanarPoint, PointResult};
    let joint = |id: usize, p: [[f64; 2]; 2], normal: [f64; 2], w: f64| JointResult {
        id,
        a: BodyName::Block(id),
        b: BodyName::Block(id + 1),
        normal,
        points: p
            .iter()
            .map(|q| PointResult {
                position: PlanarPoint { x: q[0], y: q[1] },
                opening: w,
                sliding: 0.0,
                normal_force: 0.0,
                shear_force: 0.0,
                gap: 0.0,
            })
            .collect(),
        normal_force: 0.0,
        shear_force: 0.0,
        eccentricity: None,
        state: JointState::Open,
        compressed_depth: None,
    };
    let joints = vec![
        joint(0, [[0.0, 0.0], [1.0, 0.0]], [0.0, 1.0], 0.03),
        joint(1, [[1.0, 0.0], [2.0, 0.0]], [0.0, 1.0], 0.01),
        joint(2, [[1.0, 0.0], [1.0, 1.0]], [1.0, 0.0], 0.02),
    ];
    let open = vec![vec![true, true]; 3];
    let widths: Vec<Vec<f64>> = joints
        .iter()
        .map(|j| j.points.iter().map(|p| p.opening).collect())
        .collect();
    let geo = CrackGeometry {
        blocks: vec![],
        supports: vec![],
        tolerance: 1e-9,
    };
    let c = trace_cracks(&joints, &open, &widths, &geo);
    assert_eq!(c.len(), 2, "{c:?}");
    assert_eq!(c[0].joints, vec![0, 2]);
    for (p, q) in c[0].points.iter().zip([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]) {
        assert!(close(*p, q), "{:?}", c[0].points);
    }
    assert!((c[0].length - 2.0).abs() <= TOL);
    assert!((c[0].max_opening - 0.03).abs() <= TOL);
    assert!(!c[0].start.junction && !c[0].end.junction);
    assert_eq!(c[1].joints, vec![1]);
    assert!(close(c[1].points[0], [1.0, 0.0]) && close(c[1].points[1], [2.0, 0.0]));
    assert!(c[1].start.junction && !c[1].end.junction);
    assert!((c[1].max_opening - 0.01).abs() <= TOL);
}
