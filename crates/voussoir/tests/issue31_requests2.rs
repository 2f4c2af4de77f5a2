//! Issue 31 item 1 (the rest of the front door): incremental, identify, sweep and least
//! thickness as requests of the request layer, reached by `request::run` (least thickness, which
//! has no model of its own, by `request::least_thickness`). References: the paper's half-loaded
//! arch (λ = 0.2189 at the start of its incremental curve) and its barrel vault (the same curve),
//! a forward settlement whose cracks are observed (identify recovers its motion), the linearity of
//! a settlement in its magnitude (a magnitude sweep's works scale by k/N), Milankovitch's least
//! thickness of a semicircular arch (t/R = 0.1075).

use voussoir::analysis::identify::{Crack, Observations, Width};
use voussoir::analysis::settlement::SettlementStatus;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::generate3d::{vault, Bond};
use voussoir::model3d::AnyModel;
use voussoir::request::{
    least_thickness, run, Analysis, AnyResult, Generator, IdentifyRequest, IncrementalRequest,
    LeastThicknessRequest, Names, Request, SolverRequest, SupportMotion, SweepRequest, Toward,
    UnknownSpec,
};

fn half_arch() -> AnyModel {
    AnyModel::Planar(
        arch(&ArchSpec {
            live: LiveLoad::Left,
            ..ArchSpec::default()
        })
        .unwrap(),
    )
}

fn curve(r: &AnyResult) -> Vec<(f64, f64)> {
    let pts = match r {
        AnyResult::Planar(r) => &r.output.incremental().unwrap().curve,
        AnyResult::Spatial(r) => &r.output.incremental().unwrap().curve,
    };
    pts.iter()
        .map(|p| (p.displacement, p.load_multiplier))
        .collect()
}

fn incremental(control: Vec<f64>, direction: Toward) -> Request {
    Request::new(Analysis::Incremental(IncrementalRequest {
        control,
        direction,
        max: 0.002,
        step: 0.0005,
        ..IncrementalRequest::default()
    }))
}

#[test]
fn issue31_item1_incremental_request_vault_equals_arch() {
    // The crown of the paper's arch (intrados radius 2.86 m, thickness 0.33 m: the extrados's
    // top at 3.19 m), pushed along +x; the vault is the arch extruded 1 m along y.
    let a = run(
        &half_arch(),
        &incremental(vec![0.0, 3.19], Toward::Axis("+x".into())),
    )
    .unwrap();
    let v = vault(
        &ArchSpec {
            live: LiveLoad::Left,
            ..ArchSpec::default()
        },
        1.0,
        1,
        Bond::Stack,
    )
    .unwrap();
    let b = run(
        &AnyModel::Spatial(v),
        &incremental(vec![0.0, 0.5, 3.19], Toward::Vector(vec![1.0, 0.0, 0.0])),
    )
    .unwrap();
    let (ca, cb) = (curve(&a), curve(&b));
    // The paper's λ of the half-loaded arch (Fig. 14): 0.2189.
    assert!(
        (ca[0].1 - 0.2189).abs() < 5e-4,
        "λ at the start {}",
        ca[0].1
    );
    assert_eq!(ca.len(), cb.len());
    for ((da, la), (db, lb)) in ca.iter().zip(&cb) {
        assert!((da - db).abs() < 1e-9, "{da} {db}");
        assert!((la - lb).abs() < 1e-6, "λ {la} (arch) against {lb} (vault)");
    }
}

#[test]
fn issue31_item1_incremental_request_defaults_and_names() {
    // A complete request: only the control point; the documented defaults.
    let req = Request::from_json(r#"{"analysis": {"type": "incremental", "control": [0, 3.19]}}"#)
        .unwrap();
    let Analysis::Incremental(r) = &req.analysis else {
        panic!("not incremental")
    };
    assert_eq!((r.max, r.step, r.snapshot_every), (0.05, 0.0005, 0));
    assert_eq!(r.direction, Toward::Axis("+x".into()));
    // Validated once, each error naming the caller's flag or keyword.
    let mut bad = incremental(vec![0.0, 3.19], Toward::default());
    if let Analysis::Incremental(r) = &mut bad.analysis {
        r.step = 0.01;
    }
    bad.names = Names::Flags;
    let e = bad.validate().unwrap_err().to_string();
    assert!(e.contains("--step 10 mm is larger than --max 2 mm"), "{e}");
    bad.names = Names::Keywords;
    let e = bad.validate().unwrap_err().to_string();
    assert!(e.contains("step=10 mm"), "{e}");
    // The control point's dimension against the model's.
    let e = run(
        &half_arch(),
        &incremental(vec![0.0, 0.5, 3.19], Toward::default()),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("control=0,0.5,3.19") && e.contains("2D"), "{e}");
    // +z on a 2D model.
    let mut up = incremental(vec![0.0, 3.19], Toward::Axis("+z".into()));
    up.names = Names::Flags;
    let e = run(&half_arch(), &up).unwrap_err().to_string();
    assert!(e.contains("--direction +z"), "{e}");
}

#[test]
fn issue31_item1_identify_request_recovers_a_spreading() {
    // Forward: the right support of the paper's arch moves 1 cm to the right.
    let model = AnyModel::Planar(
        arch(&ArchSpec {
            live: LiveLoad::None,
            ..ArchSpec::default()
        })
        .unwrap(),
    );
    let mut settle = Request::new(Analysis::Settle(Default::default()));
    settle.motion =
        SupportMotion::parse(&["right=0.01,0".into()], &[], None, &[], Names::Fields).unwrap();
    let AnyResult::Planar(f) = run(&model, &settle).unwrap() else {
        panic!("2D")
    };
    let fr = f.output.settlement().unwrap();
    assert_eq!(fr.status, SettlementStatus::Mechanism);
    let omax = fr
        .joints
        .iter()
        .flat_map(|j| &j.points)
        .fold(0.0f64, |m, p| m.max(p.opening));
    let cracks: Vec<Crack> = fr
        .joints
        .iter()
        .filter(|j| j.points.iter().any(|p| p.opening > 1e-7 * omax))
        .map(|j| Crack {
            joint: Some(j.id),
            opening: Width::PerPoint(
                j.points
                    .iter()
                    .map(|p| {
                        if p.opening > 1e-7 * omax {
                            p.opening
                        } else {
                            0.0
                        }
                    })
                    .collect(),
            ),
            ..Default::default()
        })
        .collect();
    assert!(!cracks.is_empty());
    // Inverse: the command line's syntax and Python's object, the same request.
    for unknown in [
        UnknownSpec::Text("right=u".into()),
        serde_json::from_str(r#"{"supports": ["right"], "component": "u"}"#).unwrap(),
    ] {
        let req = Request::new(Analysis::Identify(IdentifyRequest {
            observations: Observations {
                cracks: cracks.clone(),
                ..Default::default()
            },
            unknowns: vec![unknown],
            no_ranges: true,
            ..Default::default()
        }));
        let AnyResult::Planar(r) = run(&model, &req).unwrap() else {
            panic!("2D")
        };
        let (r, unknowns) = r.output.identify().unwrap();
        assert_eq!(unknowns.len(), 1);
        let u = r.unknowns[0].value;
        assert!((u - 0.01).abs() < 1e-6, "identified u = {u}, settled 0.01");
    }
}

#[test]
fn issue31_item1_sweep_request_scales_and_shards() {
    let model = AnyModel::Planar(
        arch(&ArchSpec {
            live: LiveLoad::None,
            ..ArchSpec::default()
        })
        .unwrap(),
    );
    let motion =
        SupportMotion::parse(&["right=0,-0.01".into()], &[], None, &[], Names::Fields).unwrap();
    let sweep = |shard: Option<[usize; 2]>| {
        let mut req = Request::new(Analysis::Sweep(SweepRequest {
            magnitudes: Some(2),
            shard,
            ..SweepRequest::default()
        }));
        req.motion = motion.clone();
        match run(&model, &req).unwrap() {
            AnyResult::Planar(r) => r.output.sweep().unwrap().to_vec(),
            AnyResult::Spatial(_) => panic!("2D"),
        }
    };
    let all = sweep(None);
    assert_eq!(all.len(), 2);
    // A settlement's work is linear in its magnitude: W(1/2) = W(1) / 2.
    let (w1, w2) = (
        all[0].work_dead_loads.unwrap(),
        all[1].work_dead_loads.unwrap(),
    );
    assert!(w2.abs() > 0.0);
    assert!((2.0 * w1 - w2).abs() <= 1e-7 * w2.abs(), "{w1} {w2}");
    // The shard 1/2 is task 1, the same record.
    let odd = sweep(Some([1, 2]));
    assert_eq!(odd.len(), 1);
    assert_eq!(odd[0], all[1]);
    // Exactly one mode, named as the caller names it.
    let mut none = Request::new(Analysis::Sweep(SweepRequest::default()));
    none.names = Names::Flags;
    let e = none.validate().unwrap_err().to_string();
    assert!(
        e.contains("give exactly one of --magnitudes, --angles, --samples"),
        "{e}"
    );
}

#[test]
fn issue31_item1_least_thickness_request_milankovitch() {
    let g = Generator::Arch(ArchSpec {
        live: LiveLoad::None,
        voussoirs: 64,
        ..ArchSpec::default()
    });
    let r = least_thickness(
        &g,
        &LeastThicknessRequest {
            bisection_tolerance: 1e-4,
            ..Default::default()
        },
        &SolverRequest::default(),
        Names::Fields,
    )
    .unwrap();
    // Milankovitch's t/R = 0.1075 for a continuous semicircular arch; 64 joints lie within 1 %.
    let tr = r.result.thickness_over_radius;
    assert!((tr - 0.1075).abs() < 0.01 * 0.1075, "t/R = {tr}");
    assert_eq!(r.result.solver.method, voussoir::lp::Method::DualSimplex);
    // The model at the least thickness is the arch regenerated there.
    let AnyModel::Planar(m) = &r.model else {
        panic!("2D")
    };
    assert_eq!(m.blocks.len(), 64);
    // Bad tolerance, named.
    let e = least_thickness(
        &g,
        &LeastThicknessRequest {
            bisection_tolerance: 2.0,
            ..Default::default()
        },
        &SolverRequest::default(),
        Names::Keywords,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("bisection_tolerance=2"), "{e}");
}
