//! Existing cracks (issue #17, item 4): a model may give measured crack widths; the analyses
//! start from that cracked state (the paper's initial gap Δ, equations 42 and 58).
//!
//! The arch: the paper's intrados radius 2.86 m, 64 voussoirs, but 0.45 m thick (the paper's
//! 0.33 m arch already hinges at the crown's extrados, so a crack at its intrados changes
//! nothing: checked below), a live load on the left half, and a 3 mm crack at the crown's
//! intrados, the point (0, 2.86).

use voussoir::analysis::capacity::{capacity, CapacityOptions};
use voussoir::analysis::{limit, settle, LimitStatus, SettlementStatus};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::SolverOptions;
use voussoir::model::{ExistingCrack, Width};
use voussoir::{BuildOptions, Error, Model, Structure};

const CROWN_INTRADOS: [f64; 2] = [0.0, 2.86];

fn thick_arch(thickness: f64, crack: Option<f64>) -> Model {
    let mut m = arch(&ArchSpec {
        thickness,
        live: LiveLoad::Left,
        ..ArchSpec::default()
    })
    .unwrap();
    if let Some(w) = crack {
        m.cracks = vec![ExistingCrack {
            at: Some(CROWN_INTRADOS),
            joint: None,
            opening: Width::One(w),
            ..Default::default()
        }];
    }
    m
}

fn build(m: &Model) -> Structure {
    Structure::new(m, BuildOptions::default()).unwrap()
}

fn lambda(m: &Model) -> f64 {
    let r = limit(&build(m), &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::Collapse, "{}", r.message);
    r.load_multiplier.unwrap()
}

#[test]
fn a_crack_at_the_crown_intrados_lowers_the_collapse_load_of_a_thick_arch() {
    let sound = lambda(&thick_arch(0.45, None));
    let cracked = lambda(&thick_arch(0.45, Some(0.003)));
    // The sound arch's mechanism pivots on the crown's intrados; the open crack forbids it.
    assert!(cracked < 0.5 * sound, "cracked {cracked} vs sound {sound}");
    // Limit analysis is a rate problem: any open crack, however narrow, carries nothing.
    let hairline = lambda(&thick_arch(0.45, Some(1e-6)));
    assert!(
        (hairline - cracked).abs() <= 1e-9 * cracked,
        "{hairline} vs {cracked}"
    );
    // The collapse mechanism closes the crack: the result says limit analysis is not valid.
    let r = limit(
        &build(&thick_arch(0.45, Some(0.003))),
        &SolverOptions::default(),
    )
    .unwrap();
    assert!(r.message.contains("closes the open crack"), "{}", r.message);
}

#[test]
fn the_paper_arch_already_hinges_at_its_crown_extrados_so_an_intrados_crack_changes_nothing() {
    // 0.2189 (the paper's half-span value, tests/limit.rs) with and without the crack.
    let sound = lambda(&thick_arch(0.33, None));
    let cracked = lambda(&thick_arch(0.33, Some(0.003)));
    assert!((sound - 0.2189).abs() < 5e-4, "{sound}");
    assert!(
        (cracked - sound).abs() <= 1e-9 * sound,
        "{cracked} vs {sound}"
    );
}

/// Closing supports (the right springing moves left by s): the cracked arch turns as three
/// rigid pieces about the springings' extrados corners (±3.31, 0) and the crown's extrados
/// (0, 3.31), so the halves rotate by ∓s/(2·3.31) and the crown's intrados, 0.45 m below the
/// pivot, closes by 0.45·s/3.31 (hand calculation). The 3 mm crack is closed at
/// s_c = 0.003·3.31/0.45 = 2.2067 cm; beyond it, the mechanism changes.
#[test]
fn closing_supports_close_the_crack_at_the_hand_calculated_settlement() {
    let rate = 0.45 / 3.31;
    let s_c = 0.003 / rate;
    let settle_at = |s: f64| {
        let mut m = thick_arch(0.45, Some(0.003));
        let i = m.support_index("right").unwrap();
        m.supports[i].motion = [-s, 0.0, 0.0];
        let r = settle(&build(&m), &SolverOptions::default()).unwrap();
        assert_eq!(r.status, SettlementStatus::Mechanism);
        assert!(r.certificate.as_ref().unwrap().ok);
        let p = r
            .joints
            .iter()
            .flat_map(|j| j.points.iter())
            .find(|p| p.position.x.abs() < 1e-9 && (p.position.y - 2.86).abs() < 1e-9)
            .unwrap()
            .clone();
        (r, p)
    };
    // Before closure: the crack narrows at the hand-calculated rate, and carries nothing.
    for s in [0.001, 0.01, 0.02] {
        let (_, p) = settle_at(s);
        assert!(
            (p.opening + rate * s).abs() < 1e-9,
            "s = {s}: {}",
            p.opening
        );
        assert_eq!(p.normal_force, 0.0);
        assert_eq!(p.gap, 0.003);
    }
    // After it: the crack is closed (its gap used up exactly) and bears the thrust.
    let (_, p) = settle_at(0.03);
    assert!((p.gap + p.opening).abs() < 1e-9, "{} {}", p.gap, p.opening);
    assert!(p.normal_force > 1.0, "{}", p.normal_force);
    // The capacity curve: starts below the sound arch's, and shows where the crack closes.
    let curve = |crack| {
        let mut m = thick_arch(0.45, crack);
        let i = m.support_index("right").unwrap();
        m.supports[i].motion = [-0.04, 0.0, 0.0];
        capacity(
            &build(&m),
            &CapacityOptions {
                steps: 20,
                ..CapacityOptions::default()
            },
        )
        .unwrap()
    };
    let (cracked, sound) = (curve(Some(0.003)), curve(None));
    let l0 = |r: &voussoir::analysis::CapacityResult| r.curve[0].load_multiplier.unwrap();
    assert!(
        l0(&cracked) < 0.5 * l0(&sound),
        "{} {}",
        l0(&cracked),
        l0(&sound)
    );
    let closed = cracked.existing_cracks_closed_at.unwrap();
    assert!(
        (closed - s_c).abs() < 2e-6,
        "closed at {closed}, hand {s_c}"
    );
    for p in &cracked.curve {
        let open = p.existing_cracks_open.unwrap();
        assert_eq!(
            open,
            usize::from(p.settlement < closed),
            "s = {}",
            p.settlement
        );
    }
    assert!(cracked.message.contains("existing cracks close"));
    assert_eq!(sound.existing_cracks_closed_at, None);
    assert!(sound.curve.iter().all(|p| p.existing_cracks_open.is_none()));
}

#[test]
fn bad_crack_descriptions_are_one_line_errors_naming_the_crack() {
    let mut m = thick_arch(0.33, None);
    let cases: Vec<(ExistingCrack, &str)> = vec![
        (
            ExistingCrack {
                at: Some(CROWN_INTRADOS),
                joint: Some(3),
                opening: Width::One(0.001),
                ..Default::default()
            },
            "exactly one of",
        ),
        (
            ExistingCrack {
                at: None,
                joint: Some(9999),
                opening: Width::One(0.001),
                ..Default::default()
            },
            "joint 9999 does not exist",
        ),
        (
            ExistingCrack {
                at: Some(CROWN_INTRADOS),
                joint: None,
                opening: Width::One(-0.001),
                ..Default::default()
            },
            "finite number ≥ 0",
        ),
        (
            ExistingCrack {
                at: None,
                joint: Some(3),
                opening: Width::PerPoint(vec![0.001]),
                ..Default::default()
            },
            "2 points, 1 widths",
        ),
    ];
    for (c, want) in cases {
        m.cracks = vec![c];
        match Structure::new(&m, BuildOptions::default()) {
            Err(Error::Model(msg)) => {
                assert!(
                    msg.starts_with("cracks[0]: ") && msg.contains(want),
                    "{msg}"
                );
                assert!(!msg.contains('\n'));
            }
            other => panic!("expected a model error for {want}, got {:?}", other.err()),
        }
    }
    let twice = ExistingCrack {
        at: Some(CROWN_INTRADOS),
        joint: None,
        opening: Width::One(0.001),
        ..Default::default()
    };
    m.cracks = vec![twice.clone(), twice];
    let e = Structure::new(&m, BuildOptions::default()).err().unwrap();
    assert!(e.to_string().contains("name the same point"), "{e}");
}
