//! Issue 31 item 2, 3D sweeps: the sweep engine written once over `Assembly`, run on 3D
//! structures (motions of six components).
//!
//! * A 3D sweep of a barrel vault (the paper's arch extruded) over support settlements equals,
//!   scenario by scenario, individual 3D settlement analyses of the same motions computed here
//!   by hand (the works to 1e-9 relative: the same programs solved by the same solver).
//! * The extruded arch's sweep equals the 2D arch's sweep per metre of depth: a stack-bonded
//!   vault's mechanism does not vary along y, so its works per metre are the 2D works (per
//!   metre of width) — to 1e-7 relative, the tolerance of the vault's settlement against the
//!   2D arch in tests/three_d_structures.rs (interior point in 3D, dual simplex in 2D, both
//!   certified to a gap ≤ 1e-7) — and its motions are the 2D ones extruded, `[u, v, θ]` →
//!   `[u, 0, v, 0, −θ, 0]`, for every kind of sweep (the 3D direction sweep rotates in the
//!   vertical x–z plane).

use voussoir::analysis::settlement::{settle_with, SettlementForm};
use voussoir::generate::{arch, ArchSpec, LiveLoad, RadiusAt};
use voussoir::generate3d::{vault, Bond};
use voussoir::lp::{Method, SolverOptions};
use voussoir::model3d::Model3d;
use voussoir::settlement_input::move_support;
use voussoir::sweep::{self, SweepKind, SweepRecord, SweepSpec};
use voussoir::{BuildOptions, Model, Structure3d};

/// The paper's arch with 16 voussoirs (R = 2.86 m at the intrados, t = 0.33 m, 18 kN/m³).
fn small_arch() -> ArchSpec {
    ArchSpec {
        radius: 2.86,
        radius_at: RadiusAt::Intrados,
        thickness: 0.33,
        voussoirs: 16,
        unit_weight: 18.0,
        live: LiveLoad::None,
        ..ArchSpec::default()
    }
}

fn ipm() -> SolverOptions {
    SolverOptions {
        method: Method::Ipm,
        ..SolverOptions::default()
    }
}

fn spec(kind: SweepKind, solver: SolverOptions) -> SweepSpec {
    SweepSpec {
        kind,
        build: BuildOptions::default(),
        solver,
        form: SettlementForm::Both,
        capacity: None,
        canonical: None,
    }
}

const KINDS: [SweepKind; 3] = [
    SweepKind::Scale(3),
    SweepKind::Direction(4),
    SweepKind::Sample {
        count: 3,
        cov: 0.3,
        seed: 7,
    },
];

/// Base settlement (2D): the right springing spreads 1 cm, drops 5 mm and turns 0.002 rad; the
/// left one drops 3 mm.
const RIGHT_2D: [f64; 3] = [0.01, -0.005, 0.002];
const LEFT_2D: [f64; 3] = [0.0, -0.003, 0.0];

/// The 2D motion extruded along y (as `generate3d`'s extrusion maps it).
fn extruded(m: &[f64]) -> Vec<f64> {
    vec![m[0], 0.0, m[1], 0.0, -m[2], 0.0]
}

fn vault3d(depth: f64, rings: usize) -> Model3d {
    let mut m = vault(&small_arch(), depth, rings, Bond::Stack).unwrap();
    move_support(&mut m, "right", &extruded(&RIGHT_2D)).unwrap();
    move_support(&mut m, "left", &extruded(&LEFT_2D)).unwrap();
    m
}

fn close(a: Option<f64>, b: Option<f64>, rel: f64, what: &str) {
    match (a, b) {
        (Some(a), Some(b)) => assert!(
            (a - b).abs() <= rel * b.abs().max(1e-9),
            "{what}: {a} vs {b} (relative tolerance {rel})"
        ),
        (a, b) => assert_eq!(a.is_some(), b.is_some(), "{what}: {a:?} vs {b:?}"),
    }
}

/// The motion of task `k` computed by hand from the base motion `m` (3D, six components).
fn by_hand(kind: &SweepKind, k: usize, m: &[f64], rec: &SweepRecord, name: &str) -> Vec<f64> {
    match *kind {
        SweepKind::Scale(n) => m.iter().map(|x| x * (k + 1) as f64 / n as f64).collect(),
        SweepKind::Direction(n) => {
            // Rotation by a = 360°·k/n in the x–z plane (from x towards z): (u, w) and (θx, θz).
            let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            let (s, c) = (a.sin(), a.cos());
            vec![
                c * m[0] - s * m[2],
                m[1],
                s * m[0] + c * m[2],
                c * m[3] - s * m[5],
                m[4],
                s * m[3] + c * m[5],
            ]
        }
        SweepKind::Sample { .. } => {
            // A random factor per support: the record's motion is the base motion times one
            // number (every component the same factor).
            let got = &rec.motions[name];
            let i = m.iter().position(|x| *x != 0.0).unwrap();
            let f = got[i] / m[i];
            m.iter().map(|x| x * f).collect()
        }
    }
}

#[test]
fn issue31_item2_vault_sweep_equals_individual_3d_settlements() {
    let model = vault3d(1.0, 2);
    let st = Structure3d::new(&model, BuildOptions::default()).unwrap();
    for kind in KINDS {
        let s = spec(kind, ipm());
        let tasks: Vec<usize> = (0..kind.count()).collect();
        let records = sweep::run_assembly(&st, &s, &tasks, &|| {}).unwrap();
        assert_eq!(records.len(), kind.count());
        for (k, rec) in records.iter().enumerate() {
            assert_eq!(rec.index, k);
            // The individual analysis: the model with the motions of task k, by hand.
            let mut m = model.clone();
            for (name, base) in [("right", extruded(&RIGHT_2D)), ("left", extruded(&LEFT_2D))] {
                let want = by_hand(&kind, k, &base, rec, name);
                let got = &rec.motions[name];
                assert_eq!(got.len(), 6, "six components in 3D");
                for (g, w) in got.iter().zip(&want) {
                    assert!(
                        (g - w).abs() <= 1e-12 * 0.01,
                        "{kind:?} {k} {name}: {got:?} vs {want:?}"
                    );
                }
                move_support(&mut m, name, &want).unwrap();
            }
            let st1 = Structure3d::new(&m, BuildOptions::default()).unwrap();
            let r = settle_with(&st1, &ipm(), SettlementForm::Both).unwrap();
            let status = serde_json::to_value(r.status).unwrap();
            assert_eq!(rec.status, status.as_str().unwrap(), "{kind:?} {k}");
            close(
                rec.work_dead_loads,
                r.work_dead_loads,
                1e-9,
                "work of the dead loads",
            );
            close(
                rec.work_reactions,
                r.work_reactions,
                1e-9,
                "work of the reactions",
            );
            assert_eq!(rec.hinges, r.hinges.len(), "{kind:?} {k}");
            let dmax = r.blocks.iter().fold(0.0f64, |x, b| {
                x.max((b.u * b.u + b.v * b.v + b.w * b.w).sqrt())
            });
            assert!((rec.max_displacement - dmax).abs() <= 1e-9 * dmax.max(1e-12));
            assert!(rec.certified, "{kind:?} {k}: {rec:?}");
        }
    }
}

#[test]
fn issue31_item2_extruded_arch_sweep_is_the_2d_sweep_per_metre() {
    let depth = 1.5;
    let mut m2: Model = arch(&small_arch()).unwrap();
    move_support(&mut m2, "right", &RIGHT_2D).unwrap();
    move_support(&mut m2, "left", &LEFT_2D).unwrap();
    let st3 = Structure3d::new(&vault3d(depth, 3), BuildOptions::default()).unwrap();
    for kind in KINDS {
        let tasks: Vec<usize> = (0..kind.count()).collect();
        let r2 = sweep::run(&m2, &spec(kind, SolverOptions::default()), &tasks, &|| {}).unwrap();
        let r3 = sweep::run_assembly(&st3, &spec(kind, ipm()), &tasks, &|| {}).unwrap();
        for (a, b) in r2.iter().zip(&r3) {
            assert_eq!(
                (a.index, &a.kind, a.parameter),
                (b.index, &b.kind, b.parameter)
            );
            assert_eq!(a.status, b.status, "{kind:?} {}", a.index);
            assert!(b.certified, "{kind:?} {}", a.index);
            // The motions: the 2D ones extruded, bit for bit (the same arithmetic).
            assert_eq!(a.motions.len(), b.motions.len());
            for (name, m) in &a.motions {
                assert_eq!(a.motions[name].len(), 3);
                assert_eq!(b.motions[name], extruded(m), "{kind:?} {} {name}", a.index);
            }
            let per_metre = |w: Option<f64>| w.map(|w| w / depth);
            close(
                per_metre(b.work_dead_loads),
                a.work_dead_loads,
                1e-7,
                "dead loads' work per metre",
            );
            close(
                per_metre(b.work_reactions),
                a.work_reactions,
                1e-7,
                "reactions' work per metre",
            );
        }
        // A sweep that moves something: the works are not all zero.
        assert!(r2
            .iter()
            .any(|r| r.work_dead_loads.is_some_and(|w| w.abs() > 1e-6)));
    }
}

#[test]
fn issue31_item2_3d_records_carry_six_components_in_json_and_csv() {
    let st = Structure3d::new(&vault3d(1.0, 1), BuildOptions::default()).unwrap();
    let records =
        sweep::run_assembly(&st, &spec(SweepKind::Scale(2), ipm()), &[1], &|| {}).unwrap();
    let line = sweep::jsonl(&records).unwrap();
    let v: serde_json::Value = serde_json::from_str(line.trim()).unwrap();
    // Task 1 of 2: the whole base motion, [u, v, w, θx, θy, θz].
    let right: Vec<f64> = serde_json::from_value(v["motions"]["right"].clone()).unwrap();
    assert_eq!(right, extruded(&RIGHT_2D));
    // Records read back (as `voussoir merge` does) are the same records.
    let back: SweepRecord = serde_json::from_str(line.trim()).unwrap();
    assert_eq!(back, records[0]);
    // A 3D support motion of the wrong length is refused, not truncated.
    let err = sweep::analyse(
        &st,
        &spec(SweepKind::Scale(2), ipm()),
        0,
        &vec![vec![0.01, 0.0, 0.0]; 2],
    );
    assert!(err.unwrap_err().to_string().contains("expected 6"));
}
