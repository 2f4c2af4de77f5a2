//! Inverse settlement analysis: forward settlement → its crack pattern as observations →
//! `identify` recovers the support motion. References: the motion that produced the pattern
//! (round trips), the ±20 % noise bound of a one-parameter least-absolute fit, and rigid-body
//! motions (which no crack depends on).

use voussoir::analysis::identify::{
    identify, Component, Crack, IdentifyOptions, IdentifyResult, IdentifyStatus, Observations,
    Unknown, Unobserved, Width,
};
use voussoir::analysis::settlement::{settle_with, SettlementForm, SettlementStatus};
use voussoir::analysis::{settle, SettlementResult};
use voussoir::generate::{arch, wall, ArchSpec, LiveLoad, WallSpec};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
use voussoir::lp::SolverOptions;
use voussoir::model::{Connection, Model};
use voussoir::settlement_input::{apply_profile, Profile};
use voussoir::Assembly;
use voussoir::{BuildOptions, Structure};

fn paper_arch() -> Model {
    arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap()
}

fn with_moves(mut m: Model, moves: &[(&str, [f64; 3])], fixed: &[&str]) -> Model {
    for (name, mv) in moves {
        let i = m.support_index(name).unwrap();
        m.supports[i].motion = *mv;
    }
    for name in fixed {
        let i = m.support_index(name).unwrap();
        m.supports[i].connection = Connection::Fixed;
    }
    m
}

fn forward(m: &Model, form: SettlementForm) -> (Structure, SettlementResult) {
    let st = Structure::new(m, BuildOptions::default()).unwrap();
    let r = match form {
        SettlementForm::Both => settle(&st, &SolverOptions::default()).unwrap(),
        _ => settle_with(&st, &SolverOptions::default(), form).unwrap(),
    };
    assert_eq!(r.status, SettlementStatus::Mechanism);
    assert!(
        r.certificate.as_ref().unwrap().ok,
        "{:?} {}",
        r.certificate,
        r.message
    );
    (st, r)
}

/// The structure with every support motion reset: what the surveyor models.
fn at_rest(st: &Structure) -> Structure {
    st.with_support_motions(&vec![[0.0; 3]; st.supports.len()])
}

/// The forward result's crack pattern, one observation per joint with an open point (widths at
/// both points; below 1e-7 of the largest opening counts as closed). `noise(i)` multiplies the
/// width of the i-th open point; `tol(w)` gives its tolerance.
fn pattern(
    r: &SettlementResult,
    by_coordinates: bool,
    noise: &mut dyn FnMut() -> f64,
    tol: Option<&dyn Fn(f64) -> f64>,
) -> Observations {
    let omax = r
        .joints
        .iter()
        .flat_map(|j| &j.points)
        .fold(0.0f64, |m, p| m.max(p.opening));
    let thr = 1e-7 * omax;
    let mut cracks = Vec::new();
    for j in &r.joints {
        if !j.points.iter().any(|p| p.opening > thr) {
            continue;
        }
        let ws: Vec<f64> = j
            .points
            .iter()
            .map(|p| {
                if p.opening > thr {
                    p.opening * noise()
                } else {
                    0.0
                }
            })
            .collect();
        if by_coordinates {
            for (p, w) in j.points.iter().zip(&ws) {
                if *w > 0.0 {
                    cracks.push(Crack {
                        at: Some(vec![p.x, p.y]),
                        joint: None,
                        opening: Width::One(*w),
                        tolerance: tol.map(|t| t(*w)),
                        ..Default::default()
                    });
                }
            }
        } else {
            let t = tol.map(|t| t(ws.iter().cloned().fold(0.0, f64::max)));
            cracks.push(Crack {
                at: None,
                joint: Some(j.id),
                opening: Width::PerPoint(ws),
                tolerance: t,
                ..Default::default()
            });
        }
    }
    Observations {
        tolerance: None,
        cracks,
        unobserved: vec![],
        ..Default::default()
    }
}

fn exact(r: &SettlementResult, by_coordinates: bool) -> Observations {
    pattern(r, by_coordinates, &mut || 1.0, None)
}

/// What `--unknown` specifications make: one component shared by supports `names`.
enum U<'a> {
    Sup(&'a [&'a str], Component, Option<f64>),
    Uniform(f64, f64),
}

fn run(st: &Structure, obs: &Observations, unknowns: &[U], form: SettlementForm) -> IdentifyResult {
    let rest = at_rest(st);
    let us: Vec<Unknown> = unknowns
        .iter()
        .map(|u| match u {
            U::Sup(names, c, lo) => {
                let names: Vec<String> = names.iter().map(|s| s.to_string()).collect();
                Unknown::supports(&rest, &names.join("+"), &names, *c, *lo, None).unwrap()
            }
            U::Uniform(x0, x1) => {
                let at = |v| Profile::Uniform {
                    x0: *x0,
                    x1: *x1,
                    v,
                };
                Unknown::profile(&rest, "uniform", &at(0.0), &at(1.0), None, None).unwrap()
            }
        })
        .collect();
    identify(
        &rest,
        obs,
        &us,
        &IdentifyOptions {
            form,
            ..IdentifyOptions::default()
        },
    )
    .unwrap()
}

fn assert_recovers(r: &IdentifyResult, q: usize, truth: f64) {
    assert_eq!(r.status, IdentifyStatus::Identified, "{}", r.message);
    let u = &r.unknowns[q];
    assert!(
        (u.value - truth).abs() <= 1e-6 * truth.abs(),
        "{}: {} against {truth}",
        u.name,
        u.value
    );
    let c = r.certificate.as_ref().unwrap();
    assert!(c.forward_certified && c.reproduces, "{c:?}");
    assert!(r.total_misfit < 1e-4, "misfit {}", r.total_misfit);
    // Exact widths: the range collapses onto the value (within the default 0.1 mm tolerance).
    let (lo, hi) = (u.range_min.unwrap(), u.range_max.unwrap());
    assert!(lo <= truth + 1e-9 && truth - 1e-9 <= hi, "[{lo}, {hi}]");
    assert!(u.identifiable, "{}", u.note);
}

#[test]
fn arch_spreading_round_trip_by_coordinates() {
    let m = with_moves(paper_arch(), &[("right", [0.01, 0.0, 0.0])], &[]);
    let (st, f) = forward(&m, SettlementForm::Both);
    let obs = exact(&f, true);
    // Three hinges, one open point each.
    assert_eq!(obs.cracks.len(), 3);
    let r = run(
        &st,
        &obs,
        &[U::Sup(&["right"], Component::U, None)],
        SettlementForm::Both,
    );
    assert_recovers(&r, 0, 0.01);
    // The predicted cracks are the observed ones, at joints 13, 32, 51.
    let joints: Vec<usize> = r.predicted_cracks.iter().map(|c| c.joint).collect();
    assert_eq!(joints, vec![13, 32, 51]);
    // With a 0.1 mm tolerance on ~mm widths, the range is a few per cent of the value.
    let u = &r.unknowns[0];
    let w = u.range_max.unwrap() - u.range_min.unwrap();
    assert!(w > 0.0 && w < 0.2 * 0.01, "range width {w}");
}

#[test]
fn arch_vertical_settlement_of_a_fixed_support_round_trip() {
    let m = with_moves(paper_arch(), &[("right", [0.0, -0.01, 0.0])], &["right"]);
    let (st, f) = forward(&m, SettlementForm::Both);
    let obs = exact(&f, false);
    let r = run(
        &st,
        &obs,
        &[U::Sup(&["right"], Component::V, None)],
        SettlementForm::Both,
    );
    assert_recovers(&r, 0, -0.01);
    let joints: Vec<usize> = r.predicted_cracks.iter().map(|c| c.joint).collect();
    let mut hinge_joints: Vec<usize> = f.hinges.iter().map(|h| h.joint).collect();
    hinge_joints.sort();
    assert_eq!(hinge_joints, vec![1, 13, 32]);
    let mut jj = joints.clone();
    jj.dedup();
    assert_eq!(jj, hinge_joints);
}

const F5_7: [&str; 3] = ["f5", "f6", "f7"];
const F0_7: [&str; 8] = ["f0", "f1", "f2", "f3", "f4", "f5", "f6", "f7"];

/// The friction wall with its three right foundation segments (f5..f7) settled by 1 cm.
fn settled_friction_wall() -> Model {
    let mut m = friction_wall();
    for k in 5..8 {
        let i = m.support_index(&format!("f{k}")).unwrap();
        m.supports[i].motion = [0.0, -0.01, 0.0];
    }
    m
}

fn friction_wall() -> Model {
    let mut m = wall(&WallSpec {
        courses: 6,
        units: 8,
        ..WallSpec::default()
    })
    .unwrap();
    m.materials.entry("default".into()).or_default();
    for mat in m.materials.values_mut() {
        mat.friction = Some(0.6);
    }
    m
}

#[test]
fn running_bond_wall_with_friction_round_trip() {
    // The three right foundation segments (f5..f7) settle by 1 cm.
    let (st, f) = forward(&settled_friction_wall(), SettlementForm::Both);
    let obs = exact(&f, false);
    assert!(!obs.cracks.is_empty());
    let r = run(
        &st,
        &obs,
        &[U::Sup(&F5_7, Component::V, None)],
        SettlementForm::Both,
    );
    assert_recovers(&r, 0, -0.01);
}

#[test]
fn facade_half_settlement_with_one_shared_unknown() {
    // The paper's case: 20 cm uniform settlement of the right half (x ≥ 11 m), coarse mesh.
    let mut m = facade(&bondeno(0.8, FacadeMesh::Grid)).unwrap();
    let profile = Profile::Uniform {
        x0: 11.0,
        x1: 22.0,
        v: -0.2,
    };
    apply_profile(&mut m, &profile).unwrap();
    let moving: Vec<usize> = m
        .supports
        .iter()
        .filter(|s| s.motion[1] != 0.0)
        .map(|s| s.name[1..].parse::<usize>().unwrap())
        .collect();
    let (a, b) = (moving[0], *moving.last().unwrap());
    assert_eq!(
        moving.len(),
        b - a + 1,
        "the settling segments are contiguous"
    );
    let (st, f) = forward(&m, SettlementForm::ForceOnly);
    let obs = exact(&f, false);
    let names: Vec<String> = (a..=b).map(|k| format!("f{k}")).collect();
    let names: Vec<&str> = names.iter().map(|s| s.as_str()).collect();
    let r = run(
        &st,
        &obs,
        &[U::Sup(&names, Component::V, None)],
        SettlementForm::ForceOnly,
    );
    assert_recovers(&r, 0, -0.2);
    // The same through the profile family `uniform:11,22,?`.
    let r = run(
        &st,
        &obs,
        &[U::Uniform(11.0, 22.0)],
        SettlementForm::ForceOnly,
    );
    assert_recovers(&r, 0, -0.2);
}

/// Deterministic ±20 % multipliers (SplitMix64, seed 16).
fn noise(seed: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s = s.wrapping_add(0x9E3779B97F4A7C15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58476D1CE4E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D049BB133111EB);
        z ^= z >> 31;
        let u = (z >> 11) as f64 / (1u64 << 53) as f64;
        0.8 + 0.4 * u
    }
}

#[test]
fn noisy_widths_still_recover_the_spreading() {
    let m = with_moves(paper_arch(), &[("right", [0.01, 0.0, 0.0])], &[]);
    let (st, f) = forward(&m, SettlementForm::Both);
    // Tolerance 25 % of the measured width: |w_obs − w| ≤ 0.2 w ≤ 0.25 w_obs.
    let tol = |w: f64| 0.25 * w;
    let obs = pattern(&f, false, &mut noise(16), Some(&tol));
    let r = run(
        &st,
        &obs,
        &[U::Sup(&["right"], Component::U, None)],
        SettlementForm::Both,
    );
    assert_eq!(r.status, IdentifyStatus::Identified, "{}", r.message);
    let u = &r.unknowns[0];
    // One unknown, openings proportional to it: the least-absolute fit is a weighted median
    // of the ratios w_obs/w_pred(1), each within ±20 % of the truth.
    assert!((u.value - 0.01).abs() <= 0.2 * 0.01, "{}", u.value);
    let (lo, hi) = (u.range_min.unwrap(), u.range_max.unwrap());
    assert!(lo <= 0.01 && 0.01 <= hi, "[{lo}, {hi}] must contain 0.01");
    // Still a forward settlement mechanism with these cracks.
    assert!(r.certificate.as_ref().unwrap().reproduces);
    println!("noisy: u = {} range [{lo}, {hi}]", u.value);
}

#[test]
fn noisy_widths_on_the_friction_wall() {
    let (st, f) = forward(&settled_friction_wall(), SettlementForm::Both);
    let tol = |w: f64| 0.25 * w;
    let obs = pattern(&f, false, &mut noise(7), Some(&tol));
    let r = run(
        &st,
        &obs,
        &[U::Sup(&F5_7, Component::V, None)],
        SettlementForm::Both,
    );
    assert_eq!(r.status, IdentifyStatus::Identified, "{}", r.message);
    let u = &r.unknowns[0];
    assert!((u.value + 0.01).abs() <= 0.2 * 0.01, "{}", u.value);
    let (lo, hi) = (u.range_min.unwrap(), u.range_max.unwrap());
    assert!(
        lo <= -0.01 && -0.01 <= hi,
        "[{lo}, {hi}] must contain -0.01"
    );
}

#[test]
fn a_rigid_translation_is_not_identifiable() {
    // Settlement of f5..f7 as above; a second unknown moves every segment horizontally: the
    // whole wall translates, no crack depends on it.
    let (st, f) = forward(&settled_friction_wall(), SettlementForm::Both);
    let obs = exact(&f, false);
    let r = run(
        &st,
        &obs,
        &[
            U::Sup(&F5_7, Component::V, None),
            U::Sup(&F0_7, Component::U, None),
        ],
        SettlementForm::Both,
    );
    assert_eq!(r.status, IdentifyStatus::Identified, "{}", r.message);
    let v = &r.unknowns[0];
    assert!(
        (v.value + 0.01).abs() <= 1e-6 * 0.01 && v.identifiable,
        "{v:?}"
    );
    let u = &r.unknowns[1];
    assert!(!u.identifiable, "{u:?}");
    assert!(u.range_min.is_none() && u.range_max.is_none(), "{u:?}");
    assert!(u.note.contains("not identifiable"), "{}", u.note);
}

#[test]
fn a_pattern_no_spreading_can_open_is_inconsistent() {
    // Spreading opens the crown at the intrados and the haunches (joints 13, 51) at the
    // extrados. Observed: the crown crack alone, everything else closed, right=u ≥ 0.
    let m = with_moves(paper_arch(), &[("right", [0.01, 0.0, 0.0])], &[]);
    let (st, f) = forward(&m, SettlementForm::Both);
    let crown = f.joints[32].clone();
    let (i, p) = crown
        .points
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.opening.total_cmp(&b.1.opening))
        .unwrap();
    assert!(
        p.y.hypot(p.x) < 2.87,
        "the crown opens at the intrados (point {i})"
    );
    let obs = Observations {
        tolerance: None,
        cracks: vec![Crack {
            at: Some(vec![p.x, p.y]),
            joint: None,
            opening: Width::One(p.opening),
            tolerance: None,
            ..Default::default()
        }],
        unobserved: vec![],
        ..Default::default()
    };
    let r = run(
        &st,
        &obs,
        &[U::Sup(&["right"], Component::U, Some(0.0))],
        SettlementForm::Both,
    );
    assert_eq!(r.status, IdentifyStatus::Inconsistent);
    assert!(r.message.starts_with("no settlement"), "{}", r.message);
    // The closest motion: the spreading whose crown crack has the observed width (here the
    // 1 cm that produced it), which opens the haunches too. Every spreading opens the crown and
    // each haunch in the ratio 2 : 1 : 1, so the misfit is flat between 0 and that spreading;
    // the closest is its upper end.
    let u = r.unknowns[0].value;
    assert!((u - 0.01).abs() <= 1e-6 * 0.01, "closest u = {u}");
    assert!(
        r.observations[0].misfit.abs() <= 1e-9,
        "{:?}",
        r.observations
    );
    // Its misfit: the two haunch cracks, observed closed, in units of the default 0.1 mm.
    let haunch = f.joints[13]
        .points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.opening));
    let expect = 2.0 * haunch / 1e-4;
    assert!(
        (r.misfit_all_points - expect).abs() <= 1e-6 * expect,
        "{} against {expect}",
        r.misfit_all_points
    );
    assert!(r
        .predicted_cracks
        .iter()
        .any(|c| c.joint == 13 && c.observed == "closed"));
    println!(
        "{}\nclosest u = {u}\n{:?}\n{:?}",
        r.message, r.observations, r.predicted_cracks
    );
}

#[test]
fn an_unobserved_joint_is_left_free() {
    // Spreading of 1 cm; joint 51 (the right haunch) is hidden under plaster: its crack is not
    // in the survey and nothing is assumed there. The other two cracks still fix u, and the
    // prediction opens the hidden joint as the forward analysis does.
    let m = with_moves(paper_arch(), &[("right", [0.01, 0.0, 0.0])], &[]);
    let (st, f) = forward(&m, SettlementForm::Both);
    let mut obs = exact(&f, false);
    obs.cracks.retain(|c| c.joint != Some(51));
    assert_eq!(obs.cracks.len(), 2);
    obs.unobserved.push(Unobserved {
        joint: Some(51),
        region: None,
    });
    let r = run(
        &st,
        &obs,
        &[U::Sup(&["right"], Component::U, None)],
        SettlementForm::Both,
    );
    assert_recovers(&r, 0, 0.01);
    let hidden = r
        .predicted_cracks
        .iter()
        .find(|c| c.joint == 51)
        .expect("joint 51 opens");
    assert_eq!(hidden.observed, "unobserved");
    let fw = f.joints[51]
        .points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.opening));
    assert!(
        (hidden.opening - fw).abs() <= 1e-6 * fw,
        "{} against {fw}",
        hidden.opening
    );
}
