//! Issue 31, item 1: the request layer — one options struct per analysis, validated once, and
//! one entry `request::run` for a model of either dimension.

use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions};
use voussoir::analysis::limit::{limit_with, Crushing};
use voussoir::analysis::settlement::SettlementForm;
use voussoir::generate::{self, FirstCourse, LiveLoad, WallSpec};
use voussoir::lp::{Method, SolverOptions};
use voussoir::model3d::AnyModel;
use voussoir::request::{self, AnyResult, Names, Output, Request};
use voussoir::{BuildOptions, Structure};

/// One block b × h on a support, horizontal live load equal to its weight (2D wall generator).
fn block_2d(b: f64, h: f64) -> voussoir::Model {
    generate::wall(&WallSpec {
        courses: 1,
        units: 1,
        unit: [b, h],
        first_course: FirstCourse::Full,
        unit_weight: 18.0,
        width: 1.0,
        live: LiveLoad::Horizontal,
    })
    .unwrap()
}

fn lambda(r: &AnyResult) -> f64 {
    match r {
        AnyResult::Planar(run) => match &run.output {
            Output::Limit(l) => l.load_multiplier.unwrap(),
            _ => panic!("not a limit result"),
        },
        AnyResult::Spatial(run) => match &run.output {
            Output::Limit(l) => l.load_multiplier.unwrap(),
            _ => panic!("not a limit result"),
        },
    }
}

/// A rigid block overturns about its toe when λ·W·h/2 = W·b/2: λ = b/h, in 2D and in 3D,
/// through the same `run` and the same request.
#[test]
fn issue31_item1_one_run_for_2d_and_3d() {
    let req = Request::from_json(r#"{"analysis": {"type": "limit"}}"#).unwrap();
    let planar = AnyModel::Planar(block_2d(0.4, 1.0));
    let spatial =
        AnyModel::Spatial(voussoir::generate3d::block([0.4, 0.6, 1.0], 0.0, 18.0).unwrap());
    let r2 = request::run(&planar, &req).unwrap();
    let r3 = request::run(&spatial, &req).unwrap();
    assert!((lambda(&r2) - 0.4).abs() < 1e-6, "2D λ = {}", lambda(&r2));
    assert!((lambda(&r3) - 0.4).abs() < 1e-6, "3D λ = {}", lambda(&r3));
    // The default solver of each dimension: dual simplex in 2D, interior point in 3D.
    match (&r2, &r3) {
        (AnyResult::Planar(a), AnyResult::Spatial(b)) => {
            assert_eq!(a.solver.method, Method::DualSimplex);
            assert_eq!(b.solver.method, Method::Ipm);
        }
        _ => panic!("dimension lost"),
    }
}

/// A request read from JSON runs exactly the library call it stands for.
#[test]
fn issue31_item1_json_request_equals_library_call() {
    let mut arch = generate::arch(&generate::ArchSpec {
        live: LiveLoad::Full,
        ..Default::default()
    })
    .unwrap();
    let req = Request::from_json(
        r#"{"model": {"friction": 0.6, "compressive_strength": 4000}, "solver": {"method": "primal-simplex"},
            "analysis": {"type": "limit", "crushing": "linear", "facets": 24}}"#,
    )
    .unwrap();
    let via = request::run(&AnyModel::Planar(arch.clone()), &req).unwrap();
    arch.override_joint_laws(Some(0.6), Some(4000.0));
    let st = Structure::new(&arch, BuildOptions::default()).unwrap();
    let opts = SolverOptions {
        method: Method::PrimalSimplex,
        ..SolverOptions::default()
    };
    let mut direct = limit_with(&st, &opts, Crushing::Linear, 24).unwrap();
    // The request layer also certifies a "cannot stand" answer (this arch with crushing has
    // no equilibrium under its dead loads: λ = −0.023): the library's second call.
    voussoir::analysis::limit::certify_no_equilibrium(&st, &mut direct, &opts, Some(24)).unwrap();
    assert!(
        direct.no_equilibrium.as_ref().is_some_and(|c| c.ok),
        "{}",
        direct.message
    );
    let AnyResult::Planar(run) = via else {
        panic!("a 2D model gives a 2D result")
    };
    let Output::Limit(l) = &run.output else {
        panic!("limit")
    };
    assert_eq!(
        serde_json::to_string(l).unwrap(),
        serde_json::to_string(&direct).unwrap()
    );

    // Settlement: a move with a unit, the canonical selection by default.
    let model = generate::arch(&generate::ArchSpec::default()).unwrap();
    let req = Request::from_json(
        r#"{"motion": {"move": ["right=0,-5mm"]}, "analysis": {"type": "settle"}}"#,
    )
    .unwrap();
    let via = request::run(&AnyModel::Planar(model.clone()), &req).unwrap();
    let mut moved = model.clone();
    voussoir::settlement_input::move_support(&mut moved, "right", &[0.0, -0.005, 0.0]).unwrap();
    let st = Structure::new(&moved, BuildOptions::default()).unwrap();
    let direct = settle_canonical(
        &st,
        &SolverOptions::default(),
        SettlementForm::Both,
        &CanonicalOptions::default(),
    )
    .unwrap();
    let AnyResult::Planar(run) = via else {
        panic!("2D")
    };
    let Output::Settlement(s) = &run.output else {
        panic!("settle")
    };
    assert_eq!(
        serde_json::to_string(s).unwrap(),
        serde_json::to_string(&direct).unwrap()
    );
    // The work of the dead loads is W·|v| of what the support carries: positive and finite.
    assert!(s.work_dead_loads.unwrap() > 0.0);
}

fn err(json: &str, model: &AnyModel) -> String {
    match Request::from_json(json).and_then(|r| request::run(model, &r)) {
        Ok(_) => panic!("{json} was accepted"),
        Err(e) => e.to_string(),
    }
}

/// Validation errors are one line and name the field (in a request's own words, or in the
/// front end's: `--facets` on the command line).
#[test]
fn issue31_item1_validation_errors_name_the_field() {
    let m = AnyModel::Planar(block_2d(0.4, 1.0));
    let cases = [
        (
            r#"{"analysis": {"type": "limit", "facets": 1}}"#,
            "facets=1",
        ),
        (
            r#"{"model": {"friction": -1}, "analysis": {"type": "limit"}}"#,
            "friction=-1",
        ),
        (
            r#"{"model": {"tolerance": 0}, "analysis": {"type": "limit"}}"#,
            "tolerance=0",
        ),
        (
            r#"{"analysis": {"type": "limit", "crushing": "conic", "facets": 8}}"#,
            "facets",
        ),
        (
            r#"{"analysis": {"type": "limit", "crushing": "conic"}}"#,
            "crushing=conic needs a compressive strength",
        ),
        (
            r#"{"analysis": {"type": "settle"}}"#,
            "settle needs a support motion",
        ),
        (
            r#"{"analysis": {"type": "capacity", "steps": 0}, "motion": {"move": ["right=0,-1cm"]}}"#,
            "steps=0",
        ),
        (
            r#"{"analysis": {"type": "capacity"}}"#,
            "capacity needs a settlement",
        ),
        (r#"{"analysis": {"type": "limit", "facet": 8}}"#, "facet"),
        (
            r#"{"motion": {"move": ["right=0,x"]}, "analysis": {"type": "settle"}}"#,
            "move right=0,x",
        ),
        (
            r#"{"model": {"friction_cone": "exact"}, "analysis": {"type": "limit"}}"#,
            "friction_cone apply to 3D models",
        ),
    ];
    for (json, field) in cases {
        let e = err(json, &m);
        assert!(e.contains(field), "{json}: {e}");
        assert!(!e.contains('\n'), "{e}");
    }
    // 3D: finite compressive strength is 2D only.
    let s = AnyModel::Spatial(voussoir::generate3d::block([0.4, 0.6, 1.0], 0.0, 18.0).unwrap());
    let e = err(
        r#"{"analysis": {"type": "limit", "crushing": "conic"}}"#,
        &s,
    );
    assert!(
        e.contains("crushing and facets describe finite compressive strength"),
        "{e}"
    );
    // The CLI's names.
    let mut r = Request::from_json(r#"{"analysis": {"type": "limit", "facets": 1}}"#).unwrap();
    r.names = Names::Flags;
    let e = r.validate().unwrap_err().to_string();
    assert!(e.starts_with("--facets 1: "), "{e}");
}

/// Moves and profiles are parsed in the library, with units: `right=0,-5mm` is
/// `right=0,-0.005`; a unit on an angle is refused.
#[test]
fn issue31_item1_moves_with_units() {
    let a = request::Move::parse("right=0,-5mm", Names::Fields).unwrap();
    let b = request::Move::parse("right=0,-0.005", Names::Fields).unwrap();
    assert_eq!(a, b);
    assert_eq!(a.values, vec![0.0, -0.005]);
    let p = request::parse_profile("uniform:1m,200cm,-5mm").unwrap();
    assert_eq!(p, request::parse_profile("uniform:1,2,-0.005").unwrap());
    let e = request::Move::parse("right=0,0,0,1,2mm,3", Names::Flags)
        .unwrap_err()
        .to_string();
    assert!(e.contains("--move right: value 5 is an angle"), "{e}");
    // A unit on a 2D θ is refused when the model is known to be 2D.
    let m = AnyModel::Planar(block_2d(0.4, 1.0));
    let e = err(
        r#"{"motion": {"move": ["base=0,0,1mm"]}, "analysis": {"type": "settle"}}"#,
        &m,
    );
    assert!(e.contains("value 3 is an angle in degrees"), "{e}");
}

/// The tilting table through the same request in 2D and 3D: a block b × d × h tips over its
/// edge when tan α = (width along the tilt) / h.
#[test]
fn issue31_item1_tilt_through_one_request() {
    let tilt = |m: &AnyModel, az: f64| -> f64 {
        let req = Request::from_json(&format!(
            r#"{{"analysis": {{"type": "tilt", "azimuth": {az}}}}}"#
        ))
        .unwrap();
        match request::run(m, &req).unwrap() {
            AnyResult::Planar(r) => r.output.tilt().unwrap().tilt_angle.unwrap(),
            AnyResult::Spatial(r) => r.output.tilt().unwrap().tilt_angle.unwrap(),
        }
    };
    let planar = AnyModel::Planar(block_2d(0.4, 1.0));
    let spatial =
        AnyModel::Spatial(voussoir::generate3d::block([0.4, 0.6, 1.0], 0.0, 18.0).unwrap());
    let deg = |x: f64| x.atan().to_degrees();
    assert!((tilt(&planar, 180.0) - deg(0.4)).abs() < 1e-6);
    assert!((tilt(&spatial, 0.0) - deg(0.4)).abs() < 1e-6);
    assert!((tilt(&spatial, 90.0) - deg(0.6)).abs() < 1e-6);
    // A 2D model tilts along x only: the azimuth is named.
    let e = err(r#"{"analysis": {"type": "tilt", "azimuth": 90}}"#, &planar);
    assert!(
        e.starts_with("direction=90: a 2D model tilts along x"),
        "{e}"
    );
}
