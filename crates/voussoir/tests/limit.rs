//! Classic limit analysis against closed forms and the literature.

use voussoir::analysis::settlement::SettlementStatus;
use voussoir::analysis::{limit, settle, LimitStatus};
use voussoir::generate::{arch, lintel, ArchSpec, LintelSpec, LiveLoad, RadiusAt};
use voussoir::lp::SolverOptions;
use voussoir::model::{Block, Load, Loads, Model, Support};
use voussoir::{BuildOptions, Structure};

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

/// One block b × h on a base, horizontal live load λ·W at its centroid.
fn block_on_base(b: f64, h: f64) -> Model {
    Model {
        blocks: vec![Block {
            polygon: rect(0.0, 0.0, b, h),
            material: None,
        }],
        supports: vec![Support {
            name: "base".into(),
            polygon: rect(-1.0, -0.5, b + 1.0, 0.0),
            motion: [0.0; 3],
            connection: Default::default(),
        }],
        loads: Loads {
            live: vec![Load::Body {
                coefficients: [1.0, 0.0],
                blocks: None,
            }],
            ..Loads::default()
        },
        ..Model::default()
    }
}

#[test]
fn rocking_block_lambda_is_b_over_h() {
    // Closed form: overturning about the toe when λ W h/2 = W b/2.
    for (b, h) in [(0.5, 1.0), (1.0, 1.0), (0.3, 2.0), (2.0, 0.5)] {
        let st = Structure::new(&block_on_base(b, h), BuildOptions::default()).unwrap();
        let r = limit(&st, &SolverOptions::default()).unwrap();
        assert_eq!(r.status, LimitStatus::Collapse);
        let l = r.load_multiplier.unwrap();
        assert!(
            (l - b / h).abs() < 1e-9,
            "b={b} h={h}: λ = {l}, expected {}",
            b / h
        );
        // The mechanism is a rotation about the right toe (b, 0): one hinge there.
        assert_eq!(r.hinges.len(), 1);
        assert!((r.hinges[0].x - b).abs() < 1e-12 && r.hinges[0].y.abs() < 1e-12);
        // Virtual work: dead-load work = −λ when live-load work is 1.
        assert!((r.work_live_loads.unwrap() - 1.0).abs() < 1e-9);
        assert!((r.work_dead_loads.unwrap() + l).abs() < 1e-9);
        // Thrust line at collapse passes through the toe.
        let t = &r.thrust_line[0];
        assert!((t.x - b).abs() < 1e-9, "centre of pressure at {}", t.x);
    }
}

#[test]
fn paper_arch_collapse_multipliers() {
    // Tralli et al. (2020) §6: 0.429 (whole span), 0.215 (half span), ±2 %.
    for (live, paper) in [(LiveLoad::Full, 0.429), (LiveLoad::Left, 0.215)] {
        let st = Structure::new(
            &arch(&ArchSpec {
                live,
                ..ArchSpec::default()
            })
            .unwrap(),
            BuildOptions::default(),
        )
        .unwrap();
        let r = limit(&st, &SolverOptions::default()).unwrap();
        let l = r.load_multiplier.unwrap();
        assert!(
            (l - paper).abs() <= 0.02 * paper,
            "{live:?}: λ = {l}, paper {paper}"
        );
        // Openings are non-negative everywhere in the mechanism (admissibility).
        for j in &r.joints {
            for p in &j.points {
                assert!(p.opening >= -1e-9, "joint {} opens by {}", j.id, p.opening);
                assert!(p.normal_force >= -1e-9);
            }
        }
    }
}

#[test]
fn symmetric_full_span_mechanism_has_five_hinges() {
    let st = Structure::new(
        &arch(&ArchSpec::default()).unwrap(),
        BuildOptions::default(),
    )
    .unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    let joints: Vec<usize> = r.hinges.iter().map(|h| h.joint).collect();
    // Springings (joints 1 and 64), 13th joints from each springing, crown (32).
    assert_eq!(joints, vec![1, 13, 32, 51, 64]);
}

/// Whether a semicircular arch with centreline radius 1 and thickness t stands under its own
/// weight: the settlement primal with no settlement is bounded iff it does.
fn stands(t: f64, voussoirs: usize) -> bool {
    let m = arch(&ArchSpec {
        radius: 1.0,
        radius_at: RadiusAt::Centreline,
        thickness: t,
        voussoirs,
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    settle(&st, &SolverOptions::default()).unwrap().status == SettlementStatus::Mechanism
}

#[test]
fn minimum_thickness_of_semicircular_arch() {
    // Milankovitch / Heyman: t/R = 0.1075 (R at the centreline), approached from below as
    // the number of voussoirs grows.
    let mut bracket = [0.05, 0.2];
    assert!(!stands(bracket[0], 64) && stands(bracket[1], 64));
    for _ in 0..30 {
        let mid = 0.5 * (bracket[0] + bracket[1]);
        if stands(mid, 64) {
            bracket[1] = mid;
        } else {
            bracket[0] = mid;
        }
    }
    let t = bracket[1];
    eprintln!("minimum t/R with 64 voussoirs: {t:.5}");
    assert!((t - 0.1075).abs() <= 0.005 * 0.1075, "t/R = {t}");
    assert!(
        t <= 0.1075 + 1e-4,
        "a discrete arch should need slightly less thickness: {t}"
    );
}

#[test]
fn flat_lintel_is_locked() {
    let st = Structure::new(
        &lintel(&LintelSpec::default()).unwrap(),
        BuildOptions::default(),
    )
    .unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::Locked);
    assert!(r.load_multiplier.is_none());
    assert!(r.message.contains("no finite collapse load"));
}

#[test]
fn block_without_base_support_cannot_stand() {
    // A block leaning on a wall only (touching it with a vertical face): no equilibrium.
    let m = Model {
        blocks: vec![Block {
            polygon: rect(0.0, 0.0, 1.0, 1.0),
            material: None,
        }],
        supports: vec![Support {
            name: "wall".into(),
            polygon: rect(1.0, -1.0, 2.0, 2.0),
            motion: [0.0; 3],
            connection: Default::default(),
        }],
        loads: Loads {
            live: vec![Load::Body {
                coefficients: [-1.0, 0.0],
                blocks: None,
            }],
            ..Loads::default()
        },
        ..Model::default()
    };
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::NoEquilibrium, "{}", r.message);
}

/// Regression (issue 19, "collapse for structures that cannot stand"): a 1 m cube whose base
/// overhangs its support (support under x ∈ [0, 0.45], centroid at x = 0.5), pushed to the left
/// by λW at its centroid. It tips right about (0.45, 0) unless λW·0.5 ≥ W·0.05 (λ ≥ 0.1) and
/// tips left about (0, 0) once λW·0.5 > W·0.5 (λ > 1): it stands only for λ ∈ [0.1, 1], so under
/// its own weight it cannot stand — never "collapse at λ = 1".
#[test]
fn overhanging_block_that_stands_only_when_pushed_is_not_a_collapse() {
    let model: voussoir::Model = serde_json::from_str(
        r#"{
        "blocks": [ { "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]] } ],
        "supports": [ { "name": "base", "polygon": [[-1, -1], [0.45, -1], [0.45, 0], [-1, 0]] } ],
        "loads": { "live": [ { "type": "body", "coefficients": [-1.0, 0.0] } ] }
    }"#,
    )
    .unwrap();
    let st = Structure::new(&model, BuildOptions::default()).unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::NoEquilibrium, "{}", r.message);
    assert!((r.load_multiplier.unwrap() - 1.0).abs() < 1e-9);
    assert!((r.least_load_multiplier.unwrap() - 0.1).abs() < 1e-9);
    assert!(r.hinges.is_empty() && r.blocks.is_empty());
    assert!(
        r.message.contains("0.100000") && r.message.contains("1.000000"),
        "{}",
        r.message
    );
    // The settlement analysis agrees: under its own weight it cannot stand.
    let s = settle(&st, &SolverOptions::default()).unwrap();
    assert_eq!(s.status, SettlementStatus::CannotStand);
    // And so does the tilting table (towards −x): no tilt angle.
    let t = voussoir::analysis::tilt::tilt(&st, -1.0, &SolverOptions::default()).unwrap();
    assert_eq!(t.tilt_angle, None);
    // The paper's arch stands without its live load: its least multiplier is ≤ 0.
    let m = arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap();
    let arch = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = limit(&arch, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::Collapse);
    assert!(r.least_load_multiplier.is_none_or(|m| m <= 0.0));
}

/// The paper's arch with a live load over its whole span.
fn paper_arch_with_full_live_load() -> Structure {
    Structure::new(
        &arch(&ArchSpec {
            live: LiveLoad::Full,
            ..ArchSpec::default()
        })
        .unwrap(),
        BuildOptions::default(),
    )
    .unwrap()
}

/// Issue 18, item 3: every collapse multiplier carries its certificate, and one the solver did
/// not reach is said to be not certified. The paper arch (λ = 0.4346) is certified with the
/// simplex and with Clarabel; the same solution with λ moved 1 % off the kinematic multiplier
/// −F_D·d of its own mechanism (a solver stopped short) is reported NOT CERTIFIED with a gap of
/// 0.01 (hand calculation: |1.01 λ − λ| / 1.01 λ = 0.0099).
#[test]
fn collapse_multipliers_carry_their_certificate_and_a_short_one_is_flagged() {
    use voussoir::analysis::limit::{limit_result, solve_limit};
    use voussoir::discretize::KinematicMap;
    use voussoir::lp::Method;
    let st = paper_arch_with_full_live_load();
    for method in [Method::DualSimplex, Method::Clarabel] {
        let o = SolverOptions {
            method,
            ..SolverOptions::default()
        };
        let r = limit(&st, &o).unwrap();
        let c = r.certificate.expect("a collapse has a certificate");
        assert!(
            c.ok && c.gap <= 1e-6 && c.admissibility <= 1e-6,
            "{method:?}: {c:?}"
        );
        assert!(!r.message.contains("NOT CERTIFIED"));
    }
    let map = KinematicMap::new(&st);
    let mut s = solve_limit(&st, &map, &SolverOptions::default()).unwrap();
    let l = s.lambda.unwrap();
    s.lambda = Some(1.01 * l);
    let r = limit_result(&st, &map, &s);
    let c = r.certificate.unwrap();
    assert!(!c.ok);
    assert!((c.gap - 0.01 / 1.01).abs() < 1e-6, "{}", c.gap);
    assert!(r.message.starts_with("NOT CERTIFIED"), "{}", r.message);
    // Finite compressive strength adds the crushing work to the kinematic multiplier: no
    // certificate of this form is claimed.
    let mut m = arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap();
    m.override_joint_laws(None, Some(2400.0));
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    assert!(limit(&st, &SolverOptions::default())
        .unwrap()
        .certificate
        .is_none());
}

/// The cleanup pass (issue 18): an interior point stopped early (Clarabel at a tolerance of
/// 1e-3) leaves a collapse multiplier of the paper's arch that fails its certificate; with the
/// cleanup pass on (the default) a primal simplex from that point's active set ends at a
/// vertex, whose λ equals the dual simplex's to 1e-9 and the paper's 0.4346 to its 4 digits, certified, with
/// a note saying how it was obtained.
#[test]
fn an_interior_point_stopped_short_is_cleaned_up_by_crossover() {
    use voussoir::lp::Method;
    let st = paper_arch_with_full_live_load();
    let exact = limit(&st, &SolverOptions::default())
        .unwrap()
        .load_multiplier
        .unwrap();
    assert!((exact - 0.4346).abs() < 5e-5, "{exact}");
    let loose = SolverOptions {
        method: Method::Clarabel,
        feasibility_tolerance: 1e-3,
        cleanup: false,
        ..SolverOptions::default()
    };
    // Without the cleanup pass the loose interior point fails the solver layer's own
    // certificate (issue 29: an uncertified optimum is never the answer) and the next method
    // of the fallback chain answers, certified, saying what was tried.
    let raw = limit(&st, &loose).unwrap();
    let c = raw.certificate.expect("a collapse has a certificate");
    assert!(c.ok, "{c:?} {}", raw.message);
    assert_ne!(
        raw.solver.method,
        Method::Clarabel,
        "{:?}",
        raw.solver.tried
    );
    assert!(
        raw.solver
            .tried
            .iter()
            .any(|t| t.starts_with("clarabel: not certified")),
        "{:?}",
        raw.solver.tried
    );
    assert!((raw.load_multiplier.unwrap() - exact).abs() <= 1e-9);
    let r = limit(
        &st,
        &SolverOptions {
            cleanup: true,
            ..loose
        },
    )
    .unwrap();
    let c = r.certificate.expect("a collapse has a certificate");
    assert!(c.ok, "{c:?} {}", r.message);
    let l = r.load_multiplier.unwrap();
    assert!((l - exact).abs() <= 1e-9, "{l} against {exact}");
    // The cleanup pass, or (where the solver layer's certificate rejects the loose point
    // first) the next method of the fallback chain, says how the answer was obtained.
    assert!(
        r.message.contains("cleaned up") || r.message.contains("after clarabel failed"),
        "{}",
        r.message
    );
    assert!(!r.message.contains("NOT CERTIFIED"), "{}", r.message);
}

/// Issue 18: a no-sliding running-bond wall of 2,178 units (33 courses of 66; 26,000 force-LP
/// columns) goes through HiGHS's presolve before Clarabel. Its collapse under the tilting-table
/// load is the whole wall overturning about its right toe, λ = B/H = 66·0.25 / (33·0.055) =
/// 9.090909… (closed form); with and without presolve the λ is that to 1e-7, certified.
#[test]
fn a_presolved_interior_point_gives_the_closed_form_collapse_of_a_large_wall() {
    use voussoir::bench::wall_of;
    use voussoir::generate::wall;
    use voussoir::lp::clarabel::{presolve_pays, PRESOLVE_MIN_COLUMNS};
    use voussoir::lp::Method;
    let spec = wall_of(2178, LiveLoad::Horizontal);
    assert_eq!((spec.courses, spec.units), (33, 66));
    let st = Structure::new(&wall(&spec).unwrap(), BuildOptions::default()).unwrap();
    let exact = 66.0 * 0.25 / (33.0 * 0.055);
    for presolve in [true, false] {
        let o = SolverOptions {
            method: Method::Clarabel,
            presolve,
            ..SolverOptions::default()
        };
        let r = limit(&st, &o).unwrap();
        let l = r.load_multiplier.unwrap();
        assert!(
            (l - exact).abs() <= 1e-7 * exact,
            "presolve {presolve}: λ {l}"
        );
        let c = r.certificate.expect("a collapse has a certificate");
        assert!(c.ok, "presolve {presolve}: {c:?}");
        assert!(!r.message.contains("cleaned up"), "{}", r.message);
    }
    let lp = voussoir::programs::limit_force_program(
        &voussoir::discretize::KinematicMap::new(&st),
        &st.load_vector(false),
        &st.load_vector(true),
    )
    .lp;
    assert!(lp.num_cols() >= PRESOLVE_MIN_COLUMNS);
    assert!(presolve_pays(&lp), "the wall's limit LP is not presolved");
}
