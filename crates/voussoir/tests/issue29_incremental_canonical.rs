//! Issue 29, item 5: canonical crack patterns in the incremental analysis. The settlement run
//! first is the canonical one by default (as `capacity`); every step's collapse mechanism is
//! selected with `canonical_steps` (opt-in: 5–10× the raw CPU time, docs/performance.md); `raw`
//! gives the solver's own. References: the solver's own path where the optimum is unique (the
//! paper's arch under a half-span load), and the other LP methods where it is not (the arch
//! under a full-span load, whose collapse optimum is a segment between two mirror four-hinge
//! mechanisms, docs/canonical.md).

use voussoir::analysis::canonical::CanonicalOptions;
use voussoir::analysis::incremental::{
    incremental, settled, settled_canonical, Control, IncrementalOptions, IncrementalResult,
};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::{Method, SolverOptions};
use voussoir::model::Connection;
use voussoir::model3d::AnyModel;
use voussoir::request::{self, AnyResult, Output, Request};
use voussoir::{BuildOptions, Structure};

/// The selection's options as the request layer passes them (the mechanism stages only).
fn mechanism_options() -> CanonicalOptions {
    CanonicalOptions {
        forces: false,
        reaction_ranges: false,
        ..CanonicalOptions::default()
    }
}

fn solver(method: Method) -> SolverOptions {
    SolverOptions {
        method,
        ..SolverOptions::default()
    }
}

/// The paper's arch with its live load on `live`; with `settlement` (m), the right springing
/// moved down and tied for the settlement analysis.
fn model(live: LiveLoad, settlement: f64) -> voussoir::Model {
    let mut m = arch(&ArchSpec {
        live,
        ..ArchSpec::default()
    })
    .unwrap();
    if settlement != 0.0 {
        m.supports[1].motion = [0.0, -settlement, 0.0];
        m.supports[1].connection = Connection::Fixed;
    }
    m
}

/// Incremental analysis from `st`, crown control point moving along `dir`, every step kept.
fn path(
    st: &Structure,
    dir: [f64; 2],
    method: Method,
    canonical: bool,
    max: f64,
    step: f64,
) -> IncrementalResult {
    let c = Control::nearest(st, [0.0, 3.19], dir).unwrap();
    incremental(
        st,
        &c,
        &IncrementalOptions {
            step,
            max_displacement: max,
            snapshot_every: 1,
            solver: solver(method),
            canonical: canonical.then(mechanism_options),
            ..Default::default()
        },
    )
    .unwrap()
}

/// Each kept step's hinges (joint numbers, sorted).
fn hinge_sets(r: &IncrementalResult) -> Vec<(usize, Vec<usize>)> {
    r.snapshots
        .iter()
        .map(|s| {
            let mut j: Vec<usize> = s.hinges.iter().map(|h| h.joint).collect();
            j.sort_unstable();
            j.dedup();
            (s.step, j)
        })
        .collect()
}

fn assert_curves_equal(a: &IncrementalResult, b: &IncrementalResult, tol: f64, what: &str) {
    assert_eq!(a.curve.len(), b.curve.len(), "{what}: curve lengths");
    for (p, q) in a.curve.iter().zip(&b.curve) {
        assert_eq!(p.step, q.step, "{what}");
        assert!(
            (p.displacement - q.displacement).abs() <= tol
                && (p.equilibrium_multiplier - q.equilibrium_multiplier).abs() <= tol,
            "{what}: step {}: ({}, {}) against ({}, {})",
            p.step,
            p.displacement,
            p.equilibrium_multiplier,
            q.displacement,
            q.equilibrium_multiplier
        );
    }
}

/// The paper's case (Figs 13–17): half-span live load after a 2.5 mm settlement of the right
/// springing. Its optima are unique: the canonical settlement and every canonical step are the
/// solver's own, so the canonical path is the raw one (to 1e-9: the same arithmetic).
#[test]
fn issue29_item5_unique_optimum_canonical_path_equals_raw() {
    let st = Structure::new(&model(LiveLoad::Left, 0.0025), BuildOptions::default()).unwrap();
    let dual = solver(Method::DualSimplex);
    let raw_start = settled(&st, &dual, true).unwrap();
    let (can_start, sel) = settled_canonical(&st, &dual, true, Some(mechanism_options())).unwrap();
    let sel = sel.expect("the settlement's selection is reached");
    assert!(sel.unique && !sel.changed, "{sel:?}");
    assert_eq!(
        serde_json::to_string(&voussoir::Assembly::shapes(&raw_start)).unwrap(),
        serde_json::to_string(&voussoir::Assembly::shapes(&can_start)).unwrap()
    );
    let raw = path(
        &raw_start,
        [1.0, 0.0],
        Method::DualSimplex,
        false,
        0.005,
        1e-4,
    );
    let can = path(
        &can_start,
        [1.0, 0.0],
        Method::DualSimplex,
        true,
        0.005,
        1e-4,
    );
    let c = &can.canonical.as_ref().expect("the steps' record").selection;
    assert!(c.steps && c.steps_selected > 20, "{c:?}");
    assert_eq!(c.steps_changed, 0, "{c:?}");
    assert!(c.steps_not_reached.is_empty(), "{c:?}");
    assert!(raw.canonical.is_none());
    assert_curves_equal(&raw, &can, 1e-9, "half-span arch");
    assert_eq!(hinge_sets(&raw), hinge_sets(&can));
    let ev = |r: &IncrementalResult| -> Vec<(usize, usize, usize)> {
        r.events
            .iter()
            .map(|e| (e.step, e.joint, e.point))
            .collect()
    };
    assert_eq!(ev(&raw), ev(&can));
    // The paper's peak (its Fig. 14: λ ≈ 0.2 after the settlement) and three closures.
    assert!((raw.peak_load_multiplier - 0.2031).abs() < 1e-3);
}

/// The full-span live load: the collapse optimum is a segment between two mirror four-hinge
/// mechanisms (λ = 0.43465); the dual simplex reports its midpoint, five hinges. With the
/// canonical steps every method follows one path: the same hinges at every step and the same
/// λ to 1e-6; the first step's λ is the solver's own (the selection only picks among the
/// optima) and its mechanism one end of the segment (four of the five hinges).
#[test]
fn issue29_item5_non_unique_optimum_every_method_one_path() {
    let st = Structure::new(&model(LiveLoad::Full, 0.0), BuildOptions::default()).unwrap();
    let down = [0.0, -1.0];
    let raw = path(&st, down, Method::DualSimplex, false, 0.01, 2e-4);
    let reference = path(&st, down, Method::DualSimplex, true, 0.01, 2e-4);
    let c = &reference.canonical.as_ref().unwrap().selection;
    assert!(c.steps_changed >= 1, "{c:?}");
    // Step 0: the same geometry, the same λ, and a subset of the midpoint's hinges.
    let (l_raw, l_can) = (
        raw.curve[0].equilibrium_multiplier,
        reference.curve[0].equilibrium_multiplier,
    );
    assert!((l_raw - l_can).abs() < 1e-6, "{l_raw} {l_can}");
    assert!((l_can - 0.43465).abs() < 1e-4, "{l_can}");
    let (h_raw, h_can) = (&hinge_sets(&raw)[0].1, &hinge_sets(&reference)[0].1);
    assert_eq!(h_raw.len(), 5, "{h_raw:?}");
    assert_eq!(h_can.len(), 4, "{h_can:?}");
    assert!(
        h_can.iter().all(|j| h_raw.contains(j)),
        "{h_can:?} {h_raw:?}"
    );
    let sets = hinge_sets(&reference);
    assert!(sets.len() > 5, "{sets:?}");
    for method in [Method::PrimalSimplex, Method::Clarabel, Method::Ipm] {
        let r = path(&st, down, method, true, 0.01, 2e-4);
        assert_eq!(hinge_sets(&r), sets, "{method:?}");
        assert_curves_equal(&r, &reference, 1e-6, &format!("{method:?}"));
    }
}

fn incremental_of(r: &AnyResult) -> &IncrementalResult {
    match r {
        AnyResult::Planar(run) => match &run.output {
            Output::Incremental(i) => i,
            _ => panic!("an incremental result"),
        },
        _ => panic!("2D"),
    }
}

/// The request layer: the canonical settlement by default, recorded; `raw` leaves it out;
/// `canonical_steps` selects the steps; `raw` with `canonical_steps` is refused in one line;
/// and the request runs exactly the library calls it stands for.
#[test]
fn issue29_item5_request_raw_and_canonical_steps() {
    let m = AnyModel::Planar(model(LiveLoad::Left, 0.0));
    let run = |extra: &str| {
        let json = format!(
            r#"{{"motion": {{"move": ["right=0,-2.5mm"], "fixed": ["right"]}},
                "analysis": {{"type": "incremental", "control": [0, 3.19], "max": 0.005, "step": 0.0001{extra}}}}}"#
        );
        Request::from_json(&json).and_then(|r| request::run(&m, &r))
    };
    let default = run("").unwrap();
    let d = incremental_of(&default);
    let c = d.canonical.as_ref().expect("the settlement's record");
    assert!(c.settlement.as_ref().is_some_and(|s| s.unique) && !c.selection.steps);
    assert_eq!(c.selection.steps_selected, 0);
    let raw = run(r#", "raw": true"#).unwrap();
    assert!(incremental_of(&raw).canonical.is_none());
    let steps = run(r#", "canonical_steps": true"#).unwrap();
    let s = incremental_of(&steps).canonical.as_ref().unwrap();
    assert!(
        s.selection.steps && s.selection.steps_selected > 20 && s.settlement.is_some(),
        "{s:?}"
    );
    let e = run(r#", "raw": true, "canonical_steps": true"#)
        .err()
        .expect("refused")
        .to_string();
    assert!(
        e.contains("canonical_steps") && e.contains("raw") && !e.contains('\n'),
        "{e}"
    );

    // The same analysis through the library: settle canonically, control block on the
    // structure before the settlement, then step; the record's settlement filled in after.
    let mut moved = model(LiveLoad::Left, 0.0);
    voussoir::settlement_input::move_support(&mut moved, "right", &[0.0, -0.0025, 0.0]).unwrap();
    moved.supports[1].connection = Connection::Fixed;
    let st = Structure::new(&moved, BuildOptions::default()).unwrap();
    let dual = solver(Method::DualSimplex);
    let (start, sel) = settled_canonical(&st, &dual, true, Some(mechanism_options())).unwrap();
    let block = Control::nearest(&st, [0.0, 3.19], [1.0, 0.0])
        .unwrap()
        .block;
    let control = Control::new(&start, block, [0.0, 3.19], [1.0, 0.0]).unwrap();
    let mut direct = incremental(
        &start,
        &control,
        &IncrementalOptions {
            step: 1e-4,
            max_displacement: 0.005,
            solver: dual,
            ..Default::default()
        },
    )
    .unwrap();
    let rec = direct.canonical.get_or_insert_with(Default::default);
    rec.selection.solves += sel.as_ref().map_or(0, |m| m.solves);
    rec.settlement = sel;
    assert_eq!(
        serde_json::to_string(d).unwrap(),
        serde_json::to_string(&direct).unwrap()
    );
}
