//! Issue 29, item 3 ("feasibility questions decided with a certificate either way"): a "cannot
//! stand" answer of `limit` or `settle` carries the certificate that no equilibrium exists (the
//! elastic program's Farkas certificate, `no_equilibrium`), with Heyman's rules, associative
//! friction and non-associative friction alike (the statics are the same set: the non-associative
//! iteration's first program). Before, those answers carried none (the μ = 0.6 grid façade's
//! `limit`, `settle` and `capacity` cells of the realistic benchmark, docs/performance.md).
//!
//! The model, by hand: a 1 m cube resting on a support under x ∈ [0, `edge`] (weight at
//! x = 0.5), beside a second cube on its own support that alone carries the live load (pushed
//! sideways). With `edge` = 0.45 the first cube's weight falls outside its base: no contact
//! force balances it, whatever the live load does to the other cube, so no λ has an equilibrium
//! and the settlement's dead loads none either. With `edge` = 0.55 it stands.

use voussoir::model3d::AnyModel;
use voussoir::request::{self, AnyResult, Output, Request};

fn model(edge: f64, friction: Option<f64>) -> AnyModel {
    let json = format!(
        r#"{{
        "blocks": [
            {{ "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]] }},
            {{ "polygon": [[3, 0], [4, 0], [4, 1], [3, 1]] }}
        ],
        "supports": [
            {{ "name": "a", "polygon": [[-1, -1], [{edge}, -1], [{edge}, 0], [-1, 0]] }},
            {{ "name": "b", "polygon": [[2, -1], [5, -1], [5, 0], [2, 0]] }}
        ],
        {}
        "loads": {{ "live": [ {{ "type": "point", "block": 1, "at": [3.5, 1.0], "force": [-1.0, 0.0] }} ] }}
    }}"#,
        friction.map_or(String::new(), |mu| {
            format!(r#""materials": {{"default": {{"unit_weight": 18, "friction": {mu}}}}},"#)
        })
    );
    let m: voussoir::Model = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"));
    AnyModel::Planar(m)
}

fn run(m: &AnyModel, json: &str) -> Output<voussoir::dim::Two> {
    let req = Request::from_json(json).unwrap_or_else(|e| panic!("{json}: {e}"));
    match request::run(m, &req).unwrap_or_else(|e| panic!("{json}: {e}")) {
        AnyResult::Planar(run) => run.output,
        AnyResult::Spatial(_) => panic!("dimension"),
    }
}

const LIMIT: &str = r#"{"analysis": {"type": "limit"}}"#;
const SETTLE: &str = r#"{"motion": {"move": ["b=0,-0.01"]}, "analysis": {"type": "settle"}}"#;

fn certified(c: &Option<voussoir::result::NoEquilibriumCertificate>, what: &str) {
    let c = c
        .as_ref()
        .unwrap_or_else(|| panic!("{what}: no certificate"));
    assert!(c.ok, "{what}: {c:?}");
    let v = c.violation.expect("a decided violation");
    // Decided infeasible: the least violation is bounded away from zero by more than the
    // decision's margin (lp::sequence::INFEASIBLE_MARGIN).
    assert!(
        v > voussoir::lp::sequence::INFEASIBLE_MARGIN,
        "{what}: violation {v}"
    );
    assert_eq!(c.method, Some(voussoir::lp::Method::Clarabel), "{what}");
}

#[test]
fn issue29_item3_cannot_stand_certified_heyman_and_friction() {
    for (friction, extra) in [
        (None, ""),
        (Some(0.6), ""),
        (Some(0.6), r#", "non_associative": true"#),
    ] {
        let what = format!("friction {friction:?}{extra}");
        let m = model(0.45, friction);
        let l = run(
            &m,
            &LIMIT.replace(r#""limit""#, &format!(r#""limit"{extra}"#)),
        );
        let l = l.limit().unwrap();
        assert_eq!(
            l.status,
            voussoir::analysis::limit::LimitStatus::NoEquilibrium,
            "{what}: {}",
            l.message
        );
        assert!(l.load_multiplier.is_none() && l.least_load_multiplier.is_none());
        certified(&l.no_equilibrium, &format!("limit, {what}"));
        assert!(l.message.contains("certified"), "{}", l.message);
        assert!(!l.message.contains("NOT CERTIFIED"), "{}", l.message);

        let s = run(
            &m,
            &SETTLE.replace(r#""settle""#, &format!(r#""settle"{extra}"#)),
        );
        let s = s.settlement().unwrap();
        assert_eq!(
            s.status,
            voussoir::analysis::settlement::SettlementStatus::CannotStand,
            "{what}: {}",
            s.message
        );
        certified(&s.no_equilibrium, &format!("settle, {what}"));

        let c = run(
            &m,
            &format!(
                r#"{{"motion": {{"move": ["b=0,-0.01"]}}, "analysis": {{"type": "capacity", "steps": 2{extra}}}}}"#
            ),
        );
        let c = c.capacity().unwrap();
        assert!(c.curve.is_empty(), "{what}: {}", c.message);
        assert!(c.message.contains("cannot stand"), "{}", c.message);
        certified(&c.no_equilibrium, &format!("capacity, {what}"));
    }
}

/// The tilting table: towards +x the overhanging cube tips further, so no tilt (nor the
/// opposite tilt: λ is free in sign) gives it an equilibrium; "no angle" is certified on the
/// dead loads alone.
#[test]
fn issue29_item3_tilt_that_cannot_stand_certified() {
    let m = model(0.45, None);
    let t = run(&m, r#"{"analysis": {"type": "tilt"}}"#);
    let t = t.tilt().unwrap();
    assert_eq!(t.tilt_angle, None, "{}", t.limit.message);
    assert_eq!(
        t.limit.status,
        voussoir::analysis::limit::LimitStatus::NoEquilibrium,
        "{}",
        t.limit.message
    );
    certified(&t.limit.no_equilibrium, "tilt");
}

/// The control: with its base under x ∈ [0, 0.55] the first cube stands; no "cannot stand"
/// certificate is made up (the live load collapses the second cube: λ = 0.5 by hand, the cube
/// of weight W = γ·1 m² tipping about its left corner under λ·1 kN at height 1 m: λ·1 = W·0.5).
#[test]
fn issue29_item3_no_certificate_where_it_stands() {
    let m = model(0.55, None);
    let l = run(&m, LIMIT);
    let l = l.limit().unwrap();
    assert_eq!(
        l.status,
        voussoir::analysis::limit::LimitStatus::Collapse,
        "{}",
        l.message
    );
    assert!(l.no_equilibrium.is_none());
    let AnyModel::Planar(pm) = &m else {
        unreachable!()
    };
    let mat = pm.material_of(1);
    let w = mat.unit_weight * mat.width;
    assert!(
        (l.load_multiplier.unwrap() - 0.5 * w).abs() <= 1e-9 * w,
        "λ {:?}, W {w}",
        l.load_multiplier
    );
    let s = run(&m, SETTLE);
    let s = s.settlement().unwrap();
    assert_ne!(
        s.status,
        voussoir::analysis::settlement::SettlementStatus::CannotStand
    );
    assert!(s.no_equilibrium.is_none());
}
