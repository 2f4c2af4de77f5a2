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

// --- issue 19, second round: scale-free numerics, statics that cannot lie, finite strength ----

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

/// `model` with every coordinate multiplied by `s`.
fn scaled(model: &Model, s: f64) -> Model {
    let mut m = model.clone();
    for p in m.blocks.iter_mut().map(|b| &mut b.polygon) {
        p.iter_mut().for_each(|v| *v = [v[0] * s, v[1] * s]);
    }
    for p in m.supports.iter_mut().map(|b| &mut b.polygon) {
        p.iter_mut().for_each(|v| *v = [v[0] * s, v[1] * s]);
    }
    m
}

/// Two blocks 1 × 0.5 stacked on a base, a horizontal live load equal to each block's weight
/// (the tilting table). Hand calculation: the stack overturns about its toe when
/// λ W·(h/2) = W·(b/2) with h = 1, b = 1, so λ = 1 (the top block alone needs λ = 2).
fn two_block_stack() -> Model {
    use voussoir::model::{Block, Load, Loads, Material, Support};
    let mut m = Model {
        blocks: vec![
            Block {
                polygon: rect(0.0, 0.0, 1.0, 0.5),
                material: None,
            },
            Block {
                polygon: rect(0.0, 0.5, 1.0, 1.0),
                material: None,
            },
        ],
        supports: vec![Support {
            name: "base".into(),
            polygon: rect(-1.0, -1.0, 2.0, 0.0),
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
    };
    m.materials.insert("default".into(), Material::default());
    m
}

/// Regression: the two-block stack came out `locked` at 1e-5 scale and `no_equilibrium` at
/// 1e6 (absolute tolerances); λ = 1 at every scale now, by limit analysis and by tilt.
#[test]
fn two_block_stack_has_lambda_one_at_every_scale_from_1e_minus_5_to_1e6() {
    use voussoir::analysis::tilt::tilt;
    let o = SolverOptions::default();
    for e in -5..=6 {
        let s = 10f64.powi(e);
        let st = Structure::new(&scaled(&two_block_stack(), s), BuildOptions::default()).unwrap();
        let r = voussoir::analysis::limit(&st, &o).unwrap();
        let lam = r.load_multiplier.unwrap();
        assert_eq!(
            r.status,
            voussoir::analysis::LimitStatus::Collapse,
            "scale {s}"
        );
        assert!((lam - 1.0).abs() < 1e-6, "scale {s}: λ = {lam}");
        let t = tilt(&st, 1.0, &o).unwrap();
        assert!(
            (t.tilt_angle.unwrap() - 45.0).abs() < 1e-5,
            "scale {s}: {t:?}"
        );
    }
}

/// Regression: the paper's arch read as if its metres were millimetres (×1e-3) "could not
/// stand" in a settlement analysis. Scaled by s, the dead loads scale by s² and the live
/// loads by s, so λ = 0.434645·s; the settlement mechanism is the same, with work ∝ s³.
#[test]
fn paper_arch_read_as_millimetres_stands_and_scales() {
    let o = SolverOptions::default();
    let base = Structure::new(&paper_arch(), BuildOptions::default()).unwrap();
    let lam0 = voussoir::analysis::limit(&base, &o)
        .unwrap()
        .load_multiplier
        .unwrap();
    assert!((lam0 - 0.434645).abs() < 1e-6, "{lam0}");
    for s in [1e-3, 1e3, 1e9] {
        let mut m = scaled(&paper_arch(), s);
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let lam = voussoir::analysis::limit(&st, &o)
            .unwrap()
            .load_multiplier
            .unwrap();
        assert!(((lam / s) - lam0).abs() < 1e-6 * lam0, "×{s}: λ = {lam}");
        // Spreading of the right springing by 1 cm × s.
        m.supports[1].motion = [0.01 * s, 0.0, 0.0];
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let r = settle(&st, &o).unwrap();
        assert_eq!(
            r.status,
            voussoir::analysis::SettlementStatus::Mechanism,
            "×{s}"
        );
        assert!(r.certificate.as_ref().unwrap().ok, "×{s}: {}", r.message);
    }
}

/// Regression: a unit weight of 1e18 kN/m³ made HiGHS refuse the program (or return a wrong
/// λ). Dead loads ×(1e18/18) with the live load unchanged: λ = 0.434645 × 1e18/18.
#[test]
fn unit_weight_of_1e18_gives_the_proportional_multiplier() {
    let o = SolverOptions::default();
    let mut m = paper_arch();
    m.materials.get_mut("default").unwrap().unit_weight = 1e18;
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let lam = voussoir::analysis::limit(&st, &o)
        .unwrap()
        .load_multiplier
        .unwrap();
    let expected = 0.4346453270 * 1e18 / 18.0;
    assert!(
        (lam - expected).abs() < 1e-6 * expected,
        "{lam} vs {expected}"
    );
    m.supports[1].motion = [0.01, 0.0, 0.0];
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = settle(&st, &o).unwrap();
    assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
}

/// Regression: a live point force of 1e20 kN was refused by HiGHS ("a number too large").
/// λ is inversely proportional to the force: λ(1e20 kN) = λ(1 kN)·1e-20.
#[test]
fn live_force_of_1e20_gives_the_inverse_multiplier() {
    use voussoir::model::Load;
    let o = SolverOptions::default();
    let with_force = |f: f64| {
        let mut m = paper_arch();
        let at = m.blocks[10].polygon[0];
        m.loads.live = vec![Load::Point {
            block: 10,
            at,
            force: [f, 0.0],
        }];
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        voussoir::analysis::limit(&st, &o)
            .unwrap()
            .load_multiplier
            .unwrap()
    };
    let (one, huge) = (with_force(1.0), with_force(1e20));
    assert!(one > 1.0, "{one}");
    assert!((huge * 1e20 - one).abs() < 1e-6 * one, "{huge} vs {one}");
}

/// A block overhanging its support: standing needs a push λ between 0.1 and 1.1 of its weight
/// (about the support's edge: λ·W·0.5 ≥ W·0.05; about the block's heel: λ·W·0.5 ≤ W·0.55).
fn overhanging_block() -> Model {
    use voussoir::model::{Block, Load, Loads, Material, Support};
    let mut m = Model {
        blocks: vec![Block {
            polygon: rect(0.5, 0.0, 1.6, 1.0),
            material: None,
        }],
        supports: vec![Support {
            name: "base".into(),
            polygon: rect(-1.0, -1.0, 1.0, 0.0),
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
    m.materials.insert("default".into(), Material::default());
    m
}

/// Regression: limit analysis and tilt reported "collapse λ = 0.1" and a 5.7° tilt for a block
/// that cannot stand without the live load, while settle said it cannot stand. All three now
/// agree; limit analysis and tilt give the admissible range [0.1, 1.1].
#[test]
fn overhanging_block_cannot_stand_in_limit_tilt_and_settle_alike() {
    use voussoir::analysis::tilt::tilt;
    use voussoir::analysis::{LimitStatus, SettlementStatus};
    let o = SolverOptions::default();
    let st = Structure::new(&overhanging_block(), BuildOptions::default()).unwrap();
    let r = voussoir::analysis::limit(&st, &o).unwrap();
    assert_eq!(r.status, LimitStatus::NoEquilibrium, "{}", r.message);
    assert!((r.least_load_multiplier.unwrap() - 0.1).abs() < 1e-9);
    assert!((r.load_multiplier.unwrap() - 1.1).abs() < 1e-9);
    // Safety analysis agrees: it does not stand under its dead loads.
    assert!(!voussoir::analysis::safety::stands(&st, &o).unwrap());
    assert!(
        r.message.contains("between 0.100000 and 1.100000"),
        "{}",
        r.message
    );
    // Tilting towards −x pushes it back onto its support: the same range, no tilt angle.
    let t = tilt(&st, -1.0, &o).unwrap();
    assert_eq!(t.tilt_angle, None);
    assert_eq!(t.limit.status, LimitStatus::NoEquilibrium);
    assert!((t.limit.least_load_multiplier.unwrap() - 0.1).abs() < 1e-9);
    // Towards +x it falls: the largest multiplier in equilibrium is −0.1.
    let t = tilt(&st, 1.0, &o).unwrap();
    assert_eq!(t.tilt_angle, None);
    assert_eq!(t.limit.status, LimitStatus::NoEquilibrium);
    assert!((t.limit.load_multiplier.unwrap() + 0.1).abs() < 1e-9);
    // Settlement analysis (any support motion): cannot stand.
    let mut m = overhanging_block();
    m.supports[0].motion = [0.0, -0.01, 0.0];
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    assert_eq!(
        settle(&st, &o).unwrap().status,
        SettlementStatus::CannotStand
    );
}

/// Regression: with f_c = 1 GPa the paper's arch got "no equilibrium" with the default 16-facet
/// polygon (chords spread evenly over [0, f_c·w·t]). Placed where the forces are, 16 facets
/// give λ within 0.5 % of the rigid 0.4346 and within 0.05 % of the exact cone.
#[test]
fn crushing_at_1_gpa_with_16_facets_is_near_the_rigid_arch() {
    let o = SolverOptions::default();
    let mut m = paper_arch();
    m.materials.get_mut("default").unwrap().compressive_strength = Some(1e6);
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let poly = limit_with(&st, &o, Crushing::Linear, 16)
        .unwrap()
        .load_multiplier
        .unwrap();
    let cone = limit_with(&st, &o, Crushing::Conic, 16)
        .unwrap()
        .load_multiplier
        .unwrap();
    assert!((poly - 0.4346).abs() < 0.005 * 0.4346, "16 facets: {poly}");
    assert!(
        poly <= cone + 1e-9 && cone - poly < 5e-4 * cone,
        "{poly} {cone}"
    );
    assert!(cone < 0.434646, "{cone}");
}

/// Regression: f_c → ∞ must recover the rigid λ at any facet count (evenly spread chords cut
/// the eccentricity by t/(2K) whatever f_c). At f_c = 1e12 kPa, 2 facets give 0.434645.
#[test]
fn crushing_polygon_tends_to_the_rigid_result_at_any_facet_count() {
    let o = SolverOptions::default();
    let mut m = paper_arch();
    m.materials.get_mut("default").unwrap().compressive_strength = Some(1e12);
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    for k in [2usize, 3, 4, 16, 64] {
        let lam = limit_with(&st, &o, Crushing::Linear, k)
            .unwrap()
            .load_multiplier
            .unwrap();
        assert!((lam - 0.4346453).abs() < 1e-6, "{k} facets: {lam}");
    }
}

/// Regression: `--crushing conic` stopped with `InsufficientProgress` from f_c ≥ 1e5 kPa. From
/// 1e4 to 1e12 kPa it gives a result between the 16-facet polygon's (a lower bound) and the
/// rigid λ, within 5e-4 of the 256-facet polygon.
#[test]
fn conic_crushing_is_robust_from_1e4_to_1e12_kpa() {
    let o = SolverOptions::default();
    for fc in [1e4, 1e5, 1e6, 1e7, 1e9, 1e12] {
        let mut m = paper_arch();
        m.materials.get_mut("default").unwrap().compressive_strength = Some(fc);
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let cone = limit_with(&st, &o, Crushing::Conic, 16).unwrap();
        let lc = cone.load_multiplier.unwrap();
        let p16 = limit_with(&st, &o, Crushing::Linear, 16)
            .unwrap()
            .load_multiplier
            .unwrap();
        let p256 = limit_with(&st, &o, Crushing::Linear, 256)
            .unwrap()
            .load_multiplier
            .unwrap();
        assert!(
            lc >= p16 - 1e-9 && lc <= 0.4346454 && (lc - p256).abs() < 5e-4 * lc,
            "f_c {fc}: cone {lc}, 16 facets {p16}, 256 facets {p256}: {}",
            cone.message
        );
    }
}

/// Regression: `--max 5mm --step 1e-12mm` ran 100,000 solves (minutes) before stopping; the
/// step count is checked before any work, and a step too small for the coordinates to record
/// (below 1e-10 of the structure's size) is refused.
#[test]
fn incremental_steps_beyond_the_bound_are_refused_before_any_work() {
    use voussoir::analysis::incremental::{incremental, Control, IncrementalOptions};
    let m = arch(&ArchSpec {
        live: LiveLoad::Left,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let c = Control::nearest(&st, [0.0, 3.19], [1.0, 0.0]).unwrap();
    let run = |step: f64, max_displacement: f64| {
        incremental(
            &st,
            &c,
            &IncrementalOptions {
                step,
                max_displacement,
                ..Default::default()
            },
        )
        .unwrap_err()
        .to_string()
    };
    let msg = run(1e-6, 5.0);
    assert!(
        msg.contains("5000000 steps") && msg.contains("100000"),
        "{msg}"
    );
    let msg = run(5e-15, 5e-3);
    assert!(
        msg.contains("step 5.000e-15 m") && msg.contains("1e-10"),
        "{msg}"
    );
}

/// Regression: `sweep --samples 100000000` started work that would have run out of memory
/// (every record is kept); sizes are bounded before any work.
#[test]
fn sweep_sizes_beyond_the_bound_are_refused() {
    use voussoir::sweep::{check_size, MAX_ANALYSES_PER_RUN};
    assert!(check_size(MAX_ANALYSES_PER_RUN, 1).is_ok());
    let e = check_size(100_000_000, 1).unwrap_err().to_string();
    assert!(
        e.contains("at most 1000000 per run") && e.contains("100 shards"),
        "{e}"
    );
    assert!(check_size(100_000_000, 100).is_ok());
    assert!(check_size(0, 1).is_err());
}
