//! Issue 29, item 5 (must show): 3D settlement canonical by default. What the CLI and Python
//! run by default — `request::run` with a settle request and no method — reports the canonical
//! mechanism (docs/canonical.md), and every method gives the same hinged and open joints as it
//! on the README's vault and dome. The reference for the vault is the 2D arch it extrudes: the
//! three hinge lines at the 2D hinges and the 2D work per metre of depth.

use voussoir::analysis::settlement::settle;
use voussoir::analysis::SettlementResult;
use voussoir::dim::Three;
use voussoir::generate::{arch, ArchSpec};
use voussoir::generate3d::{dome, vault, Bond, DomeSpec};
use voussoir::lp::SolverOptions;
use voussoir::model3d::AnyModel;
use voussoir::request::{self, AnyResult, Output, Request};
use voussoir::result::JointState;
use voussoir::settlement_input::move_support;
use voussoir::{BuildOptions, Structure};

/// `request::run` of a settle request (`raw`: its field; `extra`: the request's other JSON
/// fields) on a 3D model.
fn settle3(
    model: &voussoir::model3d::Model3d,
    moves: &str,
    raw: bool,
    extra: &str,
) -> SettlementResult<Three> {
    let json = format!(
        r#"{{"motion": {{"move": [{moves}]}}, "analysis": {{"type": "settle", "raw": {raw}}}{extra}}}"#
    );
    let req = Request::from_json(&json).unwrap();
    match request::run(&AnyModel::Spatial(model.clone()), &req).unwrap() {
        AnyResult::Spatial(run) => match run.output {
            Output::Settlement(r) => r,
            _ => panic!("not a settlement"),
        },
        AnyResult::Planar(_) => panic!("dimension lost"),
    }
}

/// Hinged joints (sorted, each once) and open joints of a 3D result.
fn pattern(r: &SettlementResult<Three>) -> (Vec<usize>, Vec<usize>) {
    let mut h: Vec<usize> = r.hinges.iter().map(|h| h.joint).collect();
    h.sort();
    h.dedup();
    let open = r
        .joints
        .iter()
        .filter(|j| j.state == JointState::Open)
        .map(|j| j.id)
        .collect();
    (h, open)
}

/// The default run is canonical (a record, no reaction ranges in 3D unless asked), certified;
/// `--method dual-simplex`, `ipm`, `clarabel` give its hinged and open joints and its work (to
/// 1e-6). Returns the default result.
fn same_as_default_with_every_method(
    model: &voussoir::model3d::Model3d,
    moves: &str,
    extra: &str,
    what: &str,
) -> SettlementResult<Three> {
    let default = settle3(model, moves, false, extra);
    let c = default
        .canonical
        .as_ref()
        .unwrap_or_else(|| panic!("{what}: the default 3D settle is not canonical"));
    assert!(
        c.forces
            .as_ref()
            .is_none_or(|f| f.reaction_ranges.is_empty()),
        "{what}: reaction ranges computed by default in 3D"
    );
    assert!(
        default.certificate.as_ref().is_some_and(|c| c.ok),
        "{what}: default not certified"
    );
    let p0 = pattern(&default);
    let w0 = default.work_dead_loads.unwrap();
    println!(
        "{what} default ({}): hinged joints {:?}, {} open joints, work {w0}",
        default.solver.method.name(),
        p0.0,
        p0.1.len()
    );
    assert!(!p0.0.is_empty(), "{what}: no hinge");
    for method in ["dual-simplex", "ipm", "clarabel"] {
        let r = settle3(
            model,
            moves,
            false,
            &format!(r#"{extra}, "solver": {{"method": "{method}"}}"#),
        );
        assert!(r.canonical.is_some(), "{what} {method}: not canonical");
        assert!(
            r.certificate.as_ref().is_some_and(|c| c.ok),
            "{what} {method}: not certified"
        );
        let w = r.work_dead_loads.unwrap();
        assert!(
            (w - w0).abs() <= 1e-6 * w0.abs(),
            "{what} {method}: work {w} against the default's {w0}"
        );
        let p = pattern(&r);
        println!(
            "{what} {method}: hinged joints {:?}, {} open joints",
            p.0,
            p.1.len()
        );
        assert_eq!(p, p0, "{what}: {method} against the default");
    }
    default
}

/// The README's vault: `gen vault --live full --depth 1 --rings 3`, `settle --move
/// right=1cm,0,0`. Reference: the 2D paper arch with its right support moved 1 cm out (the
/// dual simplex's vertex, a unique optimum): three hinges, whose positions are the vault's hinge
/// lines, and the same work per metre of depth (to 1e-7).
#[test]
fn issue29_item5_readme_vault_default_settle_is_canonical_with_every_method() {
    let spec = ArchSpec::default();
    let m = vault(&spec, 1.0, 3, Bond::Stack).unwrap();
    let r = same_as_default_with_every_method(&m, r#""right=1cm,0,0""#, "", "vault");
    let mut m2 = arch(&spec).unwrap();
    move_support(&mut m2, "right", &[0.01, 0.0, 0.0]).unwrap();
    let st2 = Structure::new(&m2, BuildOptions::default()).unwrap();
    let r2 = settle(&st2, &SolverOptions::default()).unwrap();
    let w2 = r2.work_dead_loads.unwrap();
    let w = r.work_dead_loads.unwrap();
    assert!(
        (w - w2).abs() <= 1e-7 * w2,
        "vault {w} against 2D {w2} per metre"
    );
    let mut lines: Vec<(i64, i64)> = r
        .hinges
        .iter()
        .map(|h| ((h.x * 1e6).round() as i64, (h.z * 1e6).round() as i64))
        .collect();
    lines.sort();
    lines.dedup();
    let mut want: Vec<(i64, i64)> = r2
        .hinges
        .iter()
        .map(|h| ((h.x * 1e6).round() as i64, (h.y * 1e6).round() as i64))
        .collect();
    want.sort();
    assert_eq!(want.len(), 3, "2D spreading: three hinges");
    assert_eq!(lines, want, "the vault's hinge lines at the 2D hinges");
    // One hinged joint per ring at each 2D hinge: 3 × 3.
    assert_eq!(pattern(&r).0.len(), 9);
    // `raw` is honoured: the solver's own optimum, without a canonical record.
    let raw = settle3(&m, r#""right=1cm,0,0""#, true, "");
    assert!(raw.canonical.is_none());
}

/// The README's dome: `gen dome --courses 8 --segments 16 --thickness 0.3`, `settle --friction
/// 0.5 --move base0=0,0,-2cm --move base1=0,0,-2cm`. Reference for the work: the solver's own
/// optimum with the dual simplex (`raw`, the same kinematic LP), to 1e-6.
#[test]
fn issue29_item5_readme_dome_default_settle_is_canonical_with_every_method() {
    let m = dome(&DomeSpec {
        courses: 8,
        segments: 16,
        thickness: 0.3,
        ..DomeSpec::default()
    })
    .unwrap();
    let moves = r#""base0=0,0,-2cm", "base1=0,0,-2cm""#;
    let extra = r#", "model": {"friction": 0.5}"#;
    let r = same_as_default_with_every_method(&m, moves, extra, "dome");
    let raw = settle3(
        &m,
        moves,
        true,
        &format!(r#"{extra}, "solver": {{"method": "dual-simplex"}}"#),
    );
    assert!(raw.canonical.is_none());
    let (w, w0) = (r.work_dead_loads.unwrap(), raw.work_dead_loads.unwrap());
    assert!(
        (w - w0).abs() <= 1e-6 * w0.abs(),
        "dome {w} against raw {w0}"
    );
    // Only the settled quarter parts from the rest: a mechanism with hinged joints.
    assert!(w0 > 0.0);
}

/// The flags of the selection are honoured or refused: the reaction ranges asked for where the
/// selection does not run (`raw`, the exact friction cone), and the canonical limit of a cone
/// program, are refused in one line naming the fields.
#[test]
fn issue29_item5_selection_flags_refused_where_it_does_not_run() {
    let m = AnyModel::Spatial(vault(&ArchSpec::default(), 1.0, 1, Bond::Stack).unwrap());
    let err = |json: &str| -> String {
        let req = Request::from_json(json).unwrap();
        match request::run(&m, &req) {
            Ok(_) => panic!("{json}: accepted"),
            Err(e) => e.to_string(),
        }
    };
    let e = err(
        r#"{"motion": {"move": ["right=1cm,0,0"]}, "analysis": {"type": "settle", "raw": true, "ranges": true}}"#,
    );
    assert!(e.contains("ranges") && e.contains("raw"), "{e}");
    let e = err(
        r#"{"model": {"friction": 0.6, "friction_cone": "exact"}, "motion": {"move": ["right=1cm,0,0"]}, "analysis": {"type": "settle", "ranges": true}}"#,
    );
    assert!(
        e.contains("ranges") && e.contains("friction_cone=exact"),
        "{e}"
    );
    let e = err(
        r#"{"model": {"friction": 0.6, "friction_cone": "exact"}, "analysis": {"type": "limit", "canonical": true}}"#,
    );
    assert!(
        e.contains("canonical") && e.contains("friction_cone=exact"),
        "{e}"
    );
}
