//! Shared by the library's integration tests (`mod support;`): the README's models and the
//! independent references more than one test file checks against.
#![allow(dead_code)]

use voussoir::analysis::SettlementResult;
use voussoir::discretize::KinematicMap;
use voussoir::generate::{wall, WallSpec};
use voussoir::generate3d::{dome, DomeSpec};
use voussoir::lp::{self, LpStatus, Method, SolverOptions};
use voussoir::model3d::Model3d;
use voussoir::outline_mesh::{mesh_wall, Foundation, MeshKind, MeshOptions, Outline};
use voussoir::programs;
use voussoir::settlement_input::{apply_profile, Profile};
use voussoir::{BuildOptions, Structure, Structure3d};

/// The 20 × 10 running-bond wall of 0.4 × 0.2 m units with μ = 0.6 on every joint, the
/// foundation under x ∈ [x0, x1] 1 cm down (docs/joint-laws.md, docs/cracks.md: the friction
/// wall of the non-associative tests).
pub fn friction_wall_20x10(x0: f64, x1: f64) -> Structure {
    let mut m = wall(&WallSpec {
        courses: 10,
        units: 20,
        unit: [0.4, 0.2],
        ..WallSpec::default()
    })
    .unwrap();
    m.override_joint_laws(Some(0.6), None);
    apply_profile(&mut m, &Profile::Uniform { x0, x1, v: -0.01 }).unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

/// A 20 × 10 stack-bond wall of 1 × 0.5 m blocks on 20 foundation segments, the left 6 m of
/// its base 1 cm down: the 3,200-block wall of issue 29 at a sixteenth of its size.
pub fn stack_wall_20x10() -> Structure {
    let outline = Outline {
        outer: vec![[0.0, 0.0], [20.0, 0.0], [20.0, 5.0], [0.0, 5.0]],
        holes: vec![],
    };
    let mut stack = mesh_wall(
        &outline,
        &MeshKind::Grid {
            length: 1.0,
            height: 0.5,
        },
        18.0,
        1.0,
        &Foundation::segments(20, "f", 0.5),
        &MeshOptions::default(),
    )
    .unwrap();
    apply_profile(
        &mut stack,
        &Profile::Uniform {
            x0: 0.0,
            x1: 6.0,
            v: -0.01,
        },
    )
    .unwrap();
    Structure::new(&stack, BuildOptions::default()).unwrap()
}

/// `gen wall --courses C --units U --unit L,H`, settled by `--profile uniform:X0,X1,V`.
pub fn wall_settled(
    courses: usize,
    units: usize,
    unit: [f64; 2],
    x0: f64,
    x1: f64,
    v: f64,
) -> Structure {
    let mut m = wall(&WallSpec {
        courses,
        units,
        unit,
        ..WallSpec::default()
    })
    .unwrap();
    apply_profile(&mut m, &Profile::Uniform { x0, x1, v }).unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

/// The README's wall: `gen wall --courses 8 --units 10 --unit 0.4,0.2`,
/// `settle --profile uniform:2.8,4.0,-0.01`.
pub fn readme_wall() -> Structure {
    wall_settled(8, 10, [0.4, 0.2], 2.8, 4.0, -0.01)
}

/// The least friction coefficient μ for which an optimal force field of the settlement `r`
/// of `st` with the points open in its mechanism unloaded satisfies `|p_t| ≤ μ p_n`: an
/// independent bisection on [0, 8] to 1e-6 (relative), written out on the public programs
/// (Clarabel feasibility of each μ).
pub fn least_friction_by_bisection(st: &Structure, r: &SettlementResult) -> f64 {
    let jumps: Vec<f64> = r
        .joints
        .iter()
        .flat_map(|j| j.points.iter().map(|p| p.opening))
        .collect();
    let big = jumps.iter().fold(0.0f64, |m, o| m.max(o.abs()));
    let open: Vec<bool> = jumps.iter().map(|&o| o > 1e-7 * big).collect();
    let map = KinematicMap::new(st);
    assert_eq!(open.len(), map.num_points());
    let dead = st.load_vector(false);
    let work = r.work_dead_loads.unwrap();
    let clarabel = SolverOptions {
        method: Method::Clarabel,
        feasibility_tolerance: 1e-10,
        ..SolverOptions::default()
    };
    let admissible = |m: f64| {
        let fp = programs::physical_force_program(
            &map,
            |k: &KinematicMap| programs::settlement_force_program(k, &dead),
            work,
            1e-9,
            &open,
            Some(m),
            false,
        );
        lp::solve(&fp.lp, &clarabel).is_ok_and(|s| s.status == LpStatus::Optimal)
    };
    assert!(!admissible(0.0) && admissible(8.0));
    let (mut lo, mut hi) = (0.0, 8.0);
    while hi - lo > 1e-6 * hi {
        let mid = 0.5 * (lo + hi);
        if admissible(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// Two boxes on a base, the upper one offset by `e` along x, every length × `s`.
pub fn offset_stack(e: f64, s: f64) -> Structure3d {
    let cuboid = |lo: [f64; 3], hi: [f64; 3]| -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
        let v = (0..8)
            .map(|i| {
                [
                    s * if i & 1 == 0 { lo[0] } else { hi[0] },
                    s * if i & 2 == 0 { lo[1] } else { hi[1] },
                    s * if i & 4 == 0 { lo[2] } else { hi[2] },
                ]
            })
            .collect();
        let f = vec![
            vec![0, 2, 3, 1],
            vec![4, 5, 7, 6],
            vec![0, 1, 5, 4],
            vec![2, 6, 7, 3],
            vec![0, 4, 6, 2],
            vec![1, 3, 7, 5],
        ];
        (v, f)
    };
    let block = |lo, hi| {
        let (v, f) = cuboid(lo, hi);
        serde_json::json!({"vertices": v, "faces": f})
    };
    let (bv, bf) = cuboid([-1.0, -1.0, -1.0], [3.0, 2.0, 0.0]);
    let m: voussoir::model3d::Model3d = serde_json::from_value(serde_json::json!({
        "blocks": [block([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]), block([e, 0.0, 1.0], [1.0 + e, 1.0, 2.0])],
        "supports": [{"name": "base", "vertices": bv, "faces": bf}]
    }))
    .unwrap();
    Structure3d::new(&m, BuildOptions::default()).unwrap()
}

/// The panel of issue 30's adaptation tests: `B` × `H` m on two supports, the right one (from
/// x = `A`) settling by `DELTA`; unit weight `GAMMA`, 1 m thick.
pub mod settling_panel {
    use voussoir::model::{Block, Loads, Material, Model, Point, Support};

    pub const B: f64 = 4.0;
    pub const H: f64 = 2.0;
    pub const A: f64 = 2.5;
    pub const DELTA: f64 = 0.01;
    pub const GAMMA: f64 = 18.0;

    /// The panel of `issue30_adapt.rs` with the given blocks.
    pub fn panel(blocks: Vec<Vec<Point>>) -> Model {
        let mut materials = std::collections::BTreeMap::new();
        materials.insert(
            "default".to_string(),
            Material {
                unit_weight: GAMMA,
                width: 1.0,
                ..Material::default()
            },
        );
        Model {
            description: "panel on two supports, the right one settling".into(),
            materials,
            blocks: blocks
                .into_iter()
                .map(|polygon| Block {
                    polygon,
                    material: None,
                })
                .collect(),
            supports: vec![
                Support {
                    name: "L".into(),
                    polygon: vec![[0.0, -0.5], [A, -0.5], [A, 0.0], [0.0, 0.0]],
                    motion: [0.0; 3],
                    connection: Default::default(),
                },
                Support {
                    name: "R".into(),
                    polygon: vec![[A, -0.5], [B, -0.5], [B, 0.0], [A, 0.0]],
                    motion: [0.0, -DELTA, 0.0],
                    connection: Default::default(),
                },
            ],
            loads: Loads::default(),
            tolerance: None,
            cracks: vec![],
        }
    }
}

/// The paper's façade (Fig 18) in a grid of `element` m, dead loads only.
pub fn facade_grid(element: f64) -> Structure {
    use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
    let m = facade(&bondeno(element, FacadeMesh::Grid)).unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

/// `m` (the paper's façade, Fig 18) with the right half of its base, x ∈ [11, 22] m, 0.2 m
/// down (docs/canonical.md, the realistic benchmark's settlement), as a structure.
pub fn settle_right_half(m: voussoir::model::Model) -> Structure {
    Structure::new(&right_half_down(m), BuildOptions::default()).unwrap()
}

/// The model of [`settle_right_half`].
pub fn right_half_down(mut m: voussoir::model::Model) -> voussoir::model::Model {
    apply_profile(
        &mut m,
        &Profile::Uniform {
            x0: 11.0,
            x1: 22.0,
            v: -0.2,
        },
    )
    .unwrap();
    m
}

/// Whether `st` stands with every joint shrunk to the fraction `f`: the equilibrium program of
/// the shrunk joints solved from scratch by the default method (not infeasible).
pub fn stands_from_scratch(st: &Structure, f: f64) -> bool {
    let base = KinematicMap::new(st);
    let fp = programs::equilibrium_program(
        &voussoir::analysis::safety::shrunk_map(st, &base, f),
        &st.load_vector(false),
    );
    lp::solve(&fp.lp, &SolverOptions::default()).unwrap().status != LpStatus::Infeasible
}

/// The least joint fraction at which `st` stands, by a bisection by hand to 1e-6 on
/// [`stands_from_scratch`] (the upper end of the final bracket).
pub fn least_fraction_from_scratch(st: &Structure) -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    while hi - lo > 1e-6 {
        let mid = 0.5 * (lo + hi);
        if stands_from_scratch(st, mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// `gen dome --courses C --segments S --crown-load P`: the other fields default (radius 5 m,
/// thickness 0.3 m, a hemisphere).
pub fn dome_model(courses: usize, segments: usize, crown_load: f64) -> Model3d {
    dome(&DomeSpec {
        courses,
        segments,
        thickness: 0.3,
        crown_load,
        ..DomeSpec::default()
    })
    .unwrap()
}

/// [`dome_model`]'s structure (default build options).
pub fn dome_structure(courses: usize, segments: usize, crown_load: f64) -> Structure3d {
    Structure3d::new(
        &dome_model(courses, segments, crown_load),
        BuildOptions::default(),
    )
    .unwrap()
}

/// The crowned dome of issue 29's solver tests: [`dome_structure`] with 10 kN at the crown.
pub fn crowned_dome(courses: usize, segments: usize) -> Structure3d {
    dome_structure(courses, segments, 10.0)
}

/// Every end of `warm` equal to the same end of `cold` to `rel` of the largest end; both
/// certified.
pub fn same_ranges(
    warm: &voussoir::result::safety::ReactionRanges,
    cold: &voussoir::result::safety::ReactionRanges,
    rel: f64,
) {
    assert!(warm.certified() && cold.certified());
    let scale = cold
        .ranges
        .iter()
        .flat_map(|r| r.components.iter())
        .flat_map(|c| [c.min, c.max])
        .flatten()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    assert_eq!(warm.ranges.len(), cold.ranges.len());
    for (w, c) in warm.ranges.iter().zip(&cold.ranges) {
        assert_eq!(w.support, c.support);
        for (a, b) in w.components.iter().zip(&c.components) {
            for (x, y) in [(a.min, b.min), (a.max, b.max)] {
                match (x, y) {
                    (Some(x), Some(y)) => assert!(
                        (x - y).abs() <= rel * scale,
                        "{} {}: {x} {y}",
                        w.support,
                        a.component
                    ),
                    (None, None) => {}
                    _ => panic!("{} {}: {x:?} against {y:?}", w.support, a.component),
                }
            }
        }
    }
}

/// Two capacity curves: λ at every step within `tol` (relative) of the reference `b` (or no
/// multiplier in both), the same status and validity at every step, and every step of both
/// certified. (Not the hinges: where the optimum is not unique, the mechanism is the vertex's
/// of each method.)
#[allow(dead_code)]
pub fn same_curve(
    a: &voussoir::analysis::capacity::CapacityResult<voussoir::dim::Two>,
    b: &voussoir::analysis::capacity::CapacityResult<voussoir::dim::Two>,
    tol: f64,
) {
    assert_eq!(a.curve.len(), b.curve.len());
    for r in [a, b] {
        let c = r.certificate.as_ref().unwrap();
        assert!(c.ok && c.certified == r.curve.len(), "{c:?}");
    }
    for (p, q) in a.curve.iter().zip(&b.curve) {
        assert_eq!(p.status, q.status, "s {}", p.settlement);
        assert_eq!(p.valid, q.valid, "s {}", p.settlement);
        match (p.load_multiplier, q.load_multiplier) {
            (Some(lp), Some(lq)) => assert!(
                (lp - lq).abs() <= tol * lq.abs(),
                "s {}: {lp} against {lq}",
                p.settlement
            ),
            (None, None) => {}
            (x, y) => panic!("s {}: {x:?} against {y:?}", p.settlement),
        }
    }
}

/// The canonical settlement of `st` under `o` by the default method, asserted certified.
pub fn settle_certified(
    st: &Structure,
    o: voussoir::analysis::canonical::CanonicalOptions,
) -> SettlementResult {
    let r = voussoir::analysis::canonical::settle_canonical(
        st,
        &SolverOptions::default(),
        voussoir::analysis::settlement::SettlementForm::Both,
        &o,
    )
    .unwrap();
    assert!(r.certificate.as_ref().unwrap().ok, "certified");
    r
}

/// The canonical force record of a canonical settlement.
pub fn canonical_forces_of(
    r: &SettlementResult,
) -> &voussoir::analysis::canonical::CanonicalForces<voussoir::dim::Two> {
    r.canonical.as_ref().unwrap().forces.as_ref().unwrap()
}

/// The least load multiplier of `st` (its own live loads): the limit program minimised, solved
/// from scratch by the dual simplex (the reference of the mirror-image tests).
pub fn least_multiplier_from_scratch(st: &Structure) -> f64 {
    let map = KinematicMap::new(st);
    let mut fp = programs::limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    fp.lp.maximise = false;
    let o = SolverOptions {
        method: Method::DualSimplex,
        ..SolverOptions::default()
    };
    let s = lp::solve(&fp.lp, &o).unwrap();
    assert_eq!(s.status, LpStatus::Optimal);
    s.x[fp.lambda.unwrap()]
}

/// The 2D default method (the dual simplex) and the CLI's at scale (HiGHS's interior point).
pub fn dual_simplex_and_ipm() -> [SolverOptions; 2] {
    [
        SolverOptions::default(),
        SolverOptions {
            method: Method::Ipm,
            ..SolverOptions::default()
        },
    ]
}

/// How many ends of `r`'s reaction ranges are bounded (`bounded`) or not.
pub fn range_ends(r: &voussoir::result::safety::ReactionRanges, bounded: bool) -> usize {
    r.ranges
        .iter()
        .flat_map(|r| r.components.iter())
        .flat_map(|c| [c.min, c.max])
        .filter(|v| v.is_some() == bounded)
        .count()
}

/// `st` on the tilting table both ways, by [`dual_simplex_and_ipm`]: the least multiplier is
/// exactly −λ_max (the mirror image of the largest's optimum; a program solved would agree
/// only to its tolerance) and within `rel`·λ_max of its program solved from scratch
/// ([`least_multiplier_from_scratch`]).
pub fn tilt_least_is_the_mirror_image(st: &Structure, what: &str, rel: f64) {
    for direction in [1.0, -1.0] {
        let tilted = voussoir::Assembly::with_weight_as_live_load(st, [direction, 0.0]).unwrap();
        let reference = least_multiplier_from_scratch(&tilted);
        for o in dual_simplex_and_ipm() {
            let r = voussoir::analysis::tilt::tilt(st, direction, &o).unwrap();
            let (hi, lo) = (
                r.limit.load_multiplier.unwrap(),
                r.limit.least_load_multiplier.unwrap(),
            );
            println!(
                "{what} {direction}, {:?}: λ_max {hi}, λ_min {lo}, from scratch {reference}",
                o.method
            );
            assert!(hi > 0.1, "{what}: {hi}");
            assert_eq!(lo, -hi, "{what}");
            assert!(
                (lo - reference).abs() <= rel * hi,
                "{what}: {lo} {reference}"
            );
        }
    }
}
