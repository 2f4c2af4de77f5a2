//! Canonical solutions (docs/canonical.md): the crack pattern does not depend on the LP method,
//! unique mechanisms are reported unique and unchanged, and the canonical forces are physical
//! (open points unloaded, no shear without compression on the foundation).

mod support;
use support::settle_right_half;
use voussoir::analysis::canonical::{
    limit_canonical, settle_canonical, CanonicalOptions, Selection,
};
use voussoir::analysis::limit::limit;
use voussoir::analysis::settlement::{settle, SettlementForm};
use voussoir::analysis::SettlementResult;
use voussoir::generate::{arch, wall, ArchSpec, LiveLoad, WallSpec};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
use voussoir::lp::{Method, SolverOptions};
use voussoir::result::JointState;
use voussoir::settlement_input::{apply_profile, Profile};
use voussoir::{BuildOptions, Structure};

fn opts(method: Method) -> SolverOptions {
    SolverOptions {
        method,
        ..SolverOptions::default()
    }
}

/// Hinges (joint, x, y rounded to 0.1 mm) and fully open joints.
fn pattern(r: &SettlementResult) -> (Vec<(usize, i64, i64)>, Vec<usize>) {
    let mut h: Vec<(usize, i64, i64)> = r
        .hinges
        .iter()
        .map(|h| {
            (
                h.joint,
                (h.x * 1e4).round() as i64,
                (h.y * 1e4).round() as i64,
            )
        })
        .collect();
    h.sort();
    let open = r
        .joints
        .iter()
        .filter(|j| j.state == JointState::Open)
        .map(|j| j.id)
        .collect();
    (h, open)
}

/// Largest force (normal or shear) at a point that opens.
fn largest_open_force(r: &SettlementResult) -> (f64, f64) {
    let scale = r
        .joints
        .iter()
        .flat_map(|j| &j.points)
        .fold(0.0f64, |m, p| m.max(p.opening.abs()));
    let mut n = 0.0f64;
    let mut t = 0.0f64;
    for p in r.joints.iter().flat_map(|j| &j.points) {
        if p.opening > 1e-7 * scale {
            n = n.max(p.normal_force.abs());
            t = t.max(p.shear_force.abs());
        }
    }
    (n, t)
}

#[test]
fn facade_crack_pattern_is_the_same_with_every_method() {
    let m = facade(&bondeno(0.6, FacadeMesh::Grid)).unwrap();
    let st = settle_right_half(m);
    let copts = CanonicalOptions {
        reaction_ranges: false,
        ..CanonicalOptions::default()
    };
    let mut patterns = Vec::new();
    for method in [Method::DualSimplex, Method::PrimalSimplex, Method::Clarabel] {
        let r = settle_canonical(&st, &opts(method), SettlementForm::Both, &copts).unwrap();
        let w = r.work_dead_loads.unwrap();
        // The README's façade: 336.857 kN·m with every method.
        assert!(
            (w - 336.857).abs() <= 1e-6 * 336.857,
            "{method:?}: work {w}"
        );
        let c = r.canonical.as_ref().unwrap();
        assert!(!c.mechanism.unique, "the façade's optimum is a face");
        assert!(c.mechanism.crack_area <= c.mechanism.crack_area_solver * (1.0 + 1e-9));
        // Open points carry no normal force.
        let (n, _) = largest_open_force(&r);
        assert!(n <= 1e-6, "{method:?}: an open point carries {n} kN");
        let p = pattern(&r);
        println!(
            "{method:?}: {} hinges, {} open joints, crack area {}",
            p.0.len(),
            p.1.len(),
            c.mechanism.crack_area
        );
        patterns.push(p);
    }
    assert_eq!(patterns[0], patterns[1], "dual vs primal simplex");
    assert_eq!(patterns[0], patterns[2], "dual simplex vs Clarabel");
}

#[test]
fn paper_arch_mechanisms_are_unique_and_unchanged() {
    // Settlement: spreading of the right support (tests/settlement.rs).
    let mut m = arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    let i = m.support_index("right").unwrap();
    m.supports[i].motion = [0.01, 0.0, 0.0];
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let o = SolverOptions::default();
    let raw = settle(&st, &o).unwrap();
    let can =
        settle_canonical(&st, &o, SettlementForm::Both, &CanonicalOptions::default()).unwrap();
    let c = can.canonical.as_ref().unwrap();
    assert!(c.mechanism.unique);
    assert_eq!(c.mechanism.selected_by, Selection::Optimum);
    assert!(!c.mechanism.changed);
    assert_eq!(raw.hinges, can.hinges);
    assert_eq!(raw.blocks, can.blocks);
    let (wr, wc) = (raw.work_dead_loads.unwrap(), can.work_dead_loads.unwrap());
    assert!((wr - wc).abs() <= 1e-12 * wr.abs(), "{wr} vs {wc}");
    // The thrust of the spreading arch (its minimum) is the same in every optimal field.
    let f = c.forces.as_ref().unwrap();
    for r in &f.reaction_ranges {
        assert!(
            r.unique,
            "{} not unique: {:?} … {:?}",
            r.support, r.min, r.max
        );
    }
    // Limit analysis (tests/limit.rs). Half-span live load: unique, unchanged (λ = 0.2189,
    // hinges at joints 12, 32, 51, 64).
    let limit_of = |live| {
        let st = Structure::new(
            &arch(&ArchSpec {
                live,
                ..ArchSpec::default()
            })
            .unwrap(),
            BuildOptions::default(),
        )
        .unwrap();
        let raw = limit(&st, &o).unwrap();
        let can = limit_canonical(&st, &o, 16, &CanonicalOptions::default()).unwrap();
        (raw, can)
    };
    let (raw, can) = limit_of(LiveLoad::Left);
    let c = can.canonical.as_ref().unwrap();
    assert!(c.mechanism.unique);
    assert!(!c.mechanism.changed);
    assert_eq!(raw.hinges, can.hinges);
    assert_eq!(raw.load_multiplier, can.load_multiplier);
    // Whole-span live load: the optimum is NOT unique. The symmetric five-hinge mechanism the
    // dual simplex reports (joints 1, 13, 32, 51, 64) is the midpoint of a segment of optimal
    // mechanisms whose ends are two mirror four-hinge mechanisms with the same λ and the same
    // crack area (crack area is linear along the segment); the tie-break reports one end.
    let (raw, can) = limit_of(LiveLoad::Full);
    let c = can.canonical.as_ref().unwrap();
    assert!(!c.mechanism.unique);
    assert_eq!(c.mechanism.selected_by, Selection::GenericVertex);
    assert_eq!(raw.load_multiplier, can.load_multiplier);
    let rel =
        (c.mechanism.crack_area - c.mechanism.crack_area_solver).abs() / c.mechanism.crack_area;
    assert!(rel <= 1e-9, "crack areas {c:?}");
    let joints: Vec<usize> = can.hinges.iter().map(|h| h.joint).collect();
    assert_eq!(joints.len(), 4, "{joints:?}");
}

#[test]
fn readme_wall_has_no_shear_without_compression() {
    // `voussoir gen wall --courses 8 --units 10 --unit 0.4,0.2`,
    // `settle --profile uniform:2.8,4.0,-0.01`.
    let mut m = wall(&WallSpec {
        courses: 8,
        units: 10,
        unit: [0.4, 0.2],
        ..WallSpec::default()
    })
    .unwrap();
    apply_profile(
        &mut m,
        &Profile::Uniform {
            x0: 2.8,
            x1: 4.0,
            v: -0.01,
        },
    )
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = settle_canonical(
        &st,
        &SolverOptions::default(),
        SettlementForm::Both,
        &CanonicalOptions::default(),
    )
    .unwrap();
    assert!(r.certificate.as_ref().unwrap().ok);
    let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
    assert!(f.physical);
    // The μ imposed on the reported field (at least the least μ, to its precision).
    let mu = f.friction.unwrap();
    assert!(mu >= f.least_friction.unwrap());
    // By hand: the segments f7–f9 drop away; their joints open and carry nothing.
    let (n, t) = largest_open_force(&r);
    assert!(n <= 1e-9 && t <= 1e-9, "open points carry {n} kN, {t} kN");
    // Every segment without vertical reaction has no horizontal reaction nor moment (no shear
    // without compression), and |shear| ≤ μ·normal everywhere.
    let mut unloaded = 0;
    for re in &r.reactions {
        if re.fy.abs() <= 1e-9 {
            unloaded += 1;
            assert!(re.fx.abs() <= 1e-9 && re.m.abs() <= 1e-9, "{re:?}");
        } else {
            assert!(re.fx.abs() <= mu * re.fy * (1.0 + 1e-6) + 1e-9, "{re:?}");
        }
    }
    assert!(unloaded >= 3, "f7–f9 are unloaded");
    for p in r.joints.iter().flat_map(|j| &j.points) {
        assert!(p.shear_force.abs() <= mu * p.normal_force + 1e-6, "{p:?}");
    }
    println!("least friction μ = {mu}; reactions {:?}", r.reactions);
}
