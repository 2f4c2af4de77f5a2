//! Issue 28, items 2, 3, 8 and 10 (unit weight): what "certified", "zero", "open" and
//! "sliding" mean relative to the problem's own scale (crates/voussoir/src/scale.rs,
//! docs/tolerances.md). Every reference is a hand calculation on boxes.

use voussoir::analysis::limit::{limit, limit_with, Crushing, LimitStatus, DEFAULT_FACETS};
use voussoir::analysis::safety::{safety, SafetyOptions};
use voussoir::analysis::settlement::{settle, SettlementStatus};
use voussoir::lp::SolverOptions;
use voussoir::model::{Material, Model};
use voussoir::result::JointState;
use voussoir::{BuildOptions, Structure, Structure3d};

fn material(
    unit_weight: f64,
    friction: Option<f64>,
) -> std::collections::BTreeMap<String, Material> {
    let mut m = std::collections::BTreeMap::new();
    m.insert(
        "default".into(),
        Material {
            unit_weight,
            friction,
            ..Material::default()
        },
    );
    m
}

/// A 2D block `b × h` on a base, with a horizontal live load equal to its weight.
fn box2d(b: f64, h: f64, motion: [f64; 3], unit_weight: f64) -> Structure {
    let m: Model = serde_json::from_value(serde_json::json!({
        "materials": {"default": {"unit_weight": unit_weight}},
        "blocks": [{"polygon": [[0.0, 0.0], [b, 0.0], [b, h], [0.0, h]]}],
        "supports": [{"name": "base", "motion": motion,
                      "polygon": [[-1.0, -1.0], [b + 1.0, -1.0], [b + 1.0, 0.0], [-1.0, 0.0]]}],
        "loads": {"live": [{"type": "body", "coefficients": [1.0, 0.0]}]}
    }))
    .unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

/// A 3D box `b × d × h` on a base (the `block` generator), horizontal live load along +x
/// equal to its weight, with the base's motion and the joints' friction set.
fn box3d(
    b: f64,
    d: f64,
    h: f64,
    motion: [f64; 6],
    unit_weight: f64,
    friction: Option<f64>,
) -> Structure3d {
    let mut m = voussoir::generate3d::block([b, d, h], 0.0, unit_weight).unwrap();
    m.supports[0].motion = motion;
    m.materials = material(unit_weight, friction);
    Structure3d::new(&m, BuildOptions::default()).unwrap()
}

fn opts() -> SolverOptions {
    SolverOptions::default()
}

#[test]
fn issue28_item2_limit_is_certified_whatever_motion_the_supports_carry_2d() {
    // Overturning about the toe: λ W h/2 = W b/2, λ = b/h = 1/3 — the support's motion plays
    // no part in a collapse mechanism (a rate with the supports held still).
    for u in [0.0, 0.01, 1e6, 1e300] {
        let st = box2d(1.0, 3.0, [u, 0.0, 0.0], 18.0);
        let r = limit(&st, &opts()).unwrap();
        let c = r
            .certificate
            .as_ref()
            .expect("a plain model has a certificate");
        assert!(c.ok, "motion {u}: {} ({c:?})", r.message);
        assert!(!r.message.contains("NOT CERTIFIED"), "{}", r.message);
        assert!(
            (r.load_multiplier.unwrap() - 1.0 / 3.0).abs() < 1e-9,
            "{:?}",
            r.load_multiplier
        );
    }
}

#[test]
fn issue28_item2_limit_is_certified_whatever_motion_the_supports_carry_3d() {
    for u in [0.0, 0.01, 1e6] {
        let st = box3d(1.0, 2.0, 3.0, [u, 0.0, -u, 0.0, 0.0, 0.0], 20.0, Some(0.6));
        let r = limit(&st, &opts()).unwrap();
        let c = r
            .certificate
            .as_ref()
            .expect("a plain model has a certificate");
        assert!(c.ok, "motion {u}: {} ({c:?})", r.message);
        // μ = 0.6 > b/h: it overturns, at λ = b/h along x.
        assert!((r.load_multiplier.unwrap() - 1.0 / 3.0).abs() < 1e-7);
    }
}

#[test]
fn issue28_item3_zero_friction_with_the_exact_cone_stands_at_lambda_zero() {
    // μ = 0: any horizontal push slides it, but it stands under its weight alone: λ = 0, the
    // same with the exact cone, the pyramid and `safety`.
    let st = box3d(1.0, 1.0, 1.0, [0.0; 6], 20.0, Some(0.0));
    let cone = limit_with(&st, &opts(), Crushing::Conic, DEFAULT_FACETS).unwrap();
    let pyramid = limit(&st, &opts()).unwrap();
    for r in [&cone, &pyramid] {
        assert_eq!(r.status, LimitStatus::Collapse, "{}", r.message);
        // Zero to the interior point's round-off (1e-8 of λ_unit = 1), never negative.
        let l = r.load_multiplier.unwrap();
        assert!((0.0..=1e-8).contains(&l), "{l}: {}", r.message);
        assert!(!r.message.contains("NOT CERTIFIED"), "{}", r.message);
    }
    let s = safety(&st, &SafetyOptions::default()).unwrap();
    assert!(s.stands, "{}", s.message);
}

#[test]
fn issue28_item8_a_rigid_settlement_opens_no_joint_and_is_certified() {
    // Two blocks stacked on one base; the whole base translates (and, separately, rotates by
    // 0.5 rad): the structure follows rigidly. Work of the dead loads = W·v for the
    // translation; every joint stays closed, nothing slides, the certificate holds.
    let stack = |motion: [f64; 3]| {
        let m: Model = serde_json::from_value(serde_json::json!({
            "blocks": [
                {"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]},
                {"polygon": [[0, 1], [1, 1], [1, 2], [0, 2]]}
            ],
            "supports": [{"name": "base", "polygon": [[-1, -1], [2, -1], [2, 0], [-1, 0]],
                           "motion": motion}]
        }))
        .unwrap();
        Structure::new(&m, BuildOptions::default()).unwrap()
    };
    for motion in [[0.0, -0.01, 0.0], [0.003, -0.01, 0.0], [0.0, 0.0, 0.5]] {
        let r = settle(&stack(motion), &opts()).unwrap();
        assert_eq!(r.status, SettlementStatus::Mechanism, "{}", r.message);
        let c = r.certificate.as_ref().unwrap();
        assert!(c.ok, "{motion:?}: {} {c:?}", r.message);
        assert!(r.hinges.is_empty(), "{motion:?}: {:?}", r.hinges);
        for j in &r.joints {
            assert_eq!(j.state, JointState::Closed, "{motion:?}: joint {}", j.id);
            for p in &j.points {
                assert_eq!(p.opening, 0.0);
            }
        }
        // W = 18 kN/m³ × 2 m² × 1 m = 36 kN; a translation (u, v) does work W·v... of the
        // weights: −36 × v.
        if motion[2] == 0.0 {
            let w = r.work_dead_loads.unwrap();
            assert!((w - (-36.0 * motion[1])).abs() < 1e-9, "{w}");
        }
    }
}

#[test]
fn issue28_item10_a_unit_weight_of_1e_200_overturns_at_b_over_h() {
    for g in [1e-200, 1e-150, 18.0, 1e150] {
        let st = box2d(1.0, 3.0, [0.0; 3], g);
        let r = limit(&st, &opts()).unwrap();
        assert_eq!(r.status, LimitStatus::Collapse, "γ = {g}: {}", r.message);
        assert!(
            (r.load_multiplier.unwrap() - 1.0 / 3.0).abs() < 1e-9,
            "γ = {g}: {:?}",
            r.load_multiplier
        );
    }
}
