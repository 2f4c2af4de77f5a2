//! Issue 29, item 1 (session 19): a 3D capacity curve with friction. The solver policy gave every
//! 3D curve up to 300 blocks to the dual simplex, warm from step to step, measured without
//! friction; with μ = 0.6 on the README's vault each step's program (the pyramid's facets at
//! every contact point) took the dual simplex about 30 CPU s: `voussoir capacity vault.json
//! --move right=1cm,0,0 --steps 5 --friction 0.6` ran 155.9 CPU s (5 min 41 s wall). A 3D curve
//! with friction now goes to Clarabel (9.96 CPU s on the same command; docs/performance.md, "3D
//! curves with friction (session 19)").
//!
//! Reference, independent of the method: the vault's mechanisms are hinging, without sliding, so
//! μ = 0.6 does not bind and the frictional curve equals the curve of the vault with Heyman's
//! no-sliding joints, which the dual simplex computes (the policy's method there), to 1e-6 of λ(0).

use voussoir::analysis::CapacityResult;
use voussoir::dim::Three;
use voussoir::generate::ArchSpec;
use voussoir::generate3d::{vault, Bond};
use voussoir::lp::Method;
use voussoir::model3d::{AnyModel, Model3d};
use voussoir::request::{self, AnyResult, Request};

fn capacity3(model: &Model3d, extra: &str) -> CapacityResult<Three> {
    let json = format!(
        r#"{{"motion": {{"move": ["right=1cm,0,0"]}}, "analysis": {{"type": "capacity", "steps": 3}}{extra}}}"#
    );
    let req = Request::from_json(&json).unwrap_or_else(|e| panic!("{json}: {e}"));
    match request::run(&AnyModel::Spatial(model.clone()), &req)
        .unwrap_or_else(|e| panic!("{json}: {e}"))
    {
        AnyResult::Spatial(run) => run.output.capacity().unwrap().clone(),
        AnyResult::Planar(_) => panic!("dimension lost"),
    }
}

#[test]
fn issue29_item1_frictional_3d_curve_by_clarabel_equals_the_no_sliding_curve() {
    // The README's vault: `gen vault --live full --depth 1 --rings 3`.
    let model = vault(&ArchSpec::default(), 1.0, 3, Bond::Stack).unwrap();
    let heyman = capacity3(&model, "");
    assert_eq!(heyman.solver.method, Method::DualSimplex, "no friction");
    let friction = capacity3(&model, r#", "model": {"friction": 0.6}"#);
    assert_eq!(
        friction.solver.method,
        Method::Clarabel,
        "a frictional 3D curve goes to Clarabel: {:?}",
        friction.solver
    );
    assert!(friction.solver.tried.is_empty(), "{:?}", friction.solver);
    let cert = friction.certificate.as_ref().expect("a certificate");
    assert!(cert.ok, "every step certified: {cert:?}");
    assert_eq!(cert.steps, 4);
    assert_eq!(friction.curve.len(), heyman.curve.len());
    let l0 = heyman.curve[0].load_multiplier.unwrap();
    // The paper's arch, λ = 0.4346 (README).
    assert!((l0 - 0.4346).abs() < 1e-4, "λ(0) = {l0}");
    for (p, q) in friction.curve.iter().zip(&heyman.curve) {
        let (a, b) = (p.load_multiplier.unwrap(), q.load_multiplier.unwrap());
        assert!(
            (a - b).abs() <= 1e-6 * l0,
            "at {} m: λ {a} with μ = 0.6 against {b} without sliding",
            p.settlement
        );
    }
    // λ falls with the spreading (0.4346 → 0.1132 at 1 cm, README vault).
    let last = friction.curve.last().unwrap().load_multiplier.unwrap();
    assert!(last < 0.5 * l0, "λ at 1 cm {last}");
}
