//! One test per defect found by trying voussoir as a careful user would (issue 19's list), named
//! after the defect.

use voussoir::analysis::capacity::{capacity, CapacityOptions};
use voussoir::analysis::limit::{limit_with, Crushing};
use voussoir::analysis::settle;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Error, Model, Structure};

fn paper_arch() -> Model {
    arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap()
}

#[test]
fn overlapping_supports_are_rejected() {
    // Two foundations sharing x ∈ [0.5, 1]: a block's bed face would get two joints.
    let model: Model = serde_json::from_str(
        r#"{
        "blocks": [ { "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]] } ],
        "supports": [
            { "name": "a", "polygon": [[-1, -1], [1, -1], [1, 0], [-1, 0]] },
            { "name": "b", "polygon": [[0.5, -1], [2, -1], [2, 0], [0.5, 0]] }
        ]
    }"#,
    )
    .unwrap();
    let e = Structure::new(&model, BuildOptions::default()).unwrap_err();
    let msg = e.to_string();
    assert!(matches!(e, Error::Model(_)), "{msg}");
    assert!(
        msg.contains("support 'a'") && msg.contains("support 'b'") && msg.contains("overlap"),
        "{msg}"
    );
    assert!(!msg.contains('\n'));
}

#[test]
fn facet_counts_outside_two_to_4096_are_rejected() {
    let mut m = paper_arch();
    m.materials
        .entry("default".into())
        .or_default()
        .compressive_strength = Some(1e4);
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let o = SolverOptions::default();
    for bad in [0usize, 1, 4097, 100_000_000] {
        let e = limit_with(&st, &o, Crushing::Linear, bad).unwrap_err();
        assert!(e.to_string().contains(&format!("facets {bad}")), "{e}");
    }
    // Within the range: the inscribed polygon is conservative, λ(64 facets) ≤ λ(exact cone) ≤
    // the rigid 0.4346 (the paper's arch, t/R = 0.109, is near Milankovitch's least thickness
    // 0.1075, so a few millimetres of compressed depth at 10 MPa take most of its capacity).
    let poly = limit_with(&st, &o, Crushing::Linear, 64).unwrap();
    let cone = limit_with(&st, &o, Crushing::Conic, 64).unwrap();
    let (lp, lc) = (poly.load_multiplier.unwrap(), cone.load_multiplier.unwrap());
    assert!(
        0.0 <= lp && lp <= lc + 1e-7 && lc < 0.4346,
        "polygon {lp}, cone {lc}"
    );
}

#[test]
fn capacity_steps_beyond_the_bound_are_rejected_before_any_work() {
    let mut m = paper_arch();
    m.supports[1].motion = [0.02, 0.0, 0.0];
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let e = capacity(
        &st,
        &CapacityOptions {
            steps: 100_000_000,
            ..Default::default()
        },
    )
    .unwrap_err();
    assert!(e.to_string().contains("steps 100000000"), "{e}");
}

#[test]
fn a_support_motion_of_1e300_is_a_one_line_error_not_a_panic() {
    let mut m = paper_arch();
    m.supports[1].motion = [1e300, 0.0, 0.0];
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    match settle(&st, &SolverOptions::default()) {
        Err(e) => assert!(!e.to_string().contains('\n'), "{e}"),
        // A solver that copes must still report a certified or flagged result.
        Ok(r) => assert!(
            r.certificate.is_some() || r.status != voussoir::analysis::SettlementStatus::Mechanism
        ),
    }
}

/// Regression: with friction, `settle_with(.., Both)` flagged every sliding mechanism as
/// uncertified, because the admissibility check counted sliding on frictional joints as a
/// violation. A running-bond wall with μ = 0.6 whose end segments settle is certified.
#[test]
fn frictional_settlement_mechanisms_are_not_flagged_as_inadmissible() {
    use voussoir::analysis::settlement::{settle_with, SettlementForm};
    use voussoir::generate::{wall, WallSpec};
    let mut m = wall(&WallSpec {
        courses: 6,
        units: 8,
        ..WallSpec::default()
    })
    .unwrap();
    m.materials.entry("default".into()).or_default().friction = Some(0.6);
    let n = m.supports.len();
    for s in m.supports[n - 3..].iter_mut() {
        s.motion = [0.0, -0.01, 0.0];
    }
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = settle_with(&st, &SolverOptions::default(), SettlementForm::Both).unwrap();
    let c = r.certificate.as_ref().unwrap();
    assert!(c.ok, "{}", r.message);
    assert!(!r.message.contains("WARNING"), "{}", r.message);
    assert!(c.relative_gap <= 1e-7);
}

/// Regression: an incremental control point far outside the structure was attached to some
/// block; now it is refused in one line naming the distance and the nearest block. A point on
/// the extrados (the README's `0,3.19`) is still accepted.
#[test]
fn incremental_control_point_far_from_the_structure_is_refused() {
    use voussoir::analysis::incremental::Control;
    let m = arch(&ArchSpec {
        live: LiveLoad::Left,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    assert!(Control::nearest(&st, [0.0, 3.19], [1.0, 0.0]).is_ok());
    let e = Control::nearest(&st, [0.0, 319.0], [1.0, 0.0]).unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.contains("315.810 m from the nearest block") && !msg.contains('\n'),
        "{msg}"
    );
}

/// Regression: a model without a `"default"` material silently gave its blocks 18 kN/m³; the
/// model now says so in one line (the CLI prints it as a warning), and says nothing when the
/// material is defined.
#[test]
fn implicit_default_material_is_warned_about() {
    let bare: Model = serde_json::from_str(
        r#"{
        "blocks": [ { "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]] } ],
        "supports": [ { "name": "base", "polygon": [[-1, -1], [2, -1], [2, 0], [-1, 0]] } ]
    }"#,
    )
    .unwrap();
    let w = bare.warnings();
    assert_eq!(w.len(), 1);
    assert!(
        w[0].contains("18 kN/m³") && w[0].contains("materials.default") && !w[0].contains('\n')
    );
    // The weight is still the documented default: 18 kN/m³ × 1 m² × 1 m.
    let st = Structure::new(&bare, BuildOptions::default()).unwrap();
    assert_eq!(st.blocks[0].weight, 18.0);
    assert!(paper_arch().warnings().is_empty());
}
