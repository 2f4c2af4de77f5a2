//! Issue 32 item 2 (and issue 30 item 3, input side): crack surveys in millimetres and as
//! lines. The references are the forward settlement analyses whose cracks make the surveys
//! (the motion that produced them), and the same survey written in metres, by point or by
//! joint (the forms identify and existing cracks accepted before).

use serde_json::Value;
use voussoir::analysis::identify::{
    identify, Component, Crack, IdentifyOptions, IdentifyResult, IdentifyStatus, Observations,
    Unknown, Width,
};
use voussoir::analysis::{settle, SettlementResult, SettlementStatus};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::SolverOptions;
use voussoir::model::{Connection, ExistingCrack};
use voussoir::{Assembly, BuildOptions, Model, Structure};

/// The paper's arch (intrados radius 2.86 m, 0.33 m thick, 64 voussoirs, 18 kN/m³), no live
/// load: `voussoir gen arch --radius 2.86 --radius-at intrados --thickness 0.33 --voussoirs 64`.
fn paper_arch() -> Model {
    arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap()
}

/// The paper arch with its right springing moved by `mv` (fixed: tied to it).
fn moved(mv: [f64; 3], fixed: bool) -> Model {
    let mut m = paper_arch();
    let i = m.support_index("right").unwrap();
    m.supports[i].motion = mv;
    if fixed {
        m.supports[i].connection = Connection::Fixed;
    }
    m
}

fn build(m: &Model) -> Structure {
    Structure::new(m, BuildOptions::default()).unwrap()
}

fn forward(m: &Model) -> (Structure, SettlementResult) {
    let st = build(m);
    let r = settle(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, SettlementStatus::Mechanism, "{}", r.message);
    assert!(r.certificate.as_ref().unwrap().ok);
    (st, r)
}

fn at_rest(st: &Structure) -> Structure {
    st.with_support_motions(&vec![[0.0; 3]; st.supports.len()])
}

fn run(st: &Structure, obs: &Observations, comp: Component) -> IdentifyResult {
    let rest = at_rest(st);
    let u = Unknown::supports(&rest, "right", &["right".to_string()], comp, None, None).unwrap();
    identify(&rest, obs, &[u], &IdentifyOptions::default()).unwrap()
}

/// The identify tests' criterion (tests/identify.rs `assert_recovers`): the value to 1e-6
/// relative, reproduced by the forward analysis, no misfit.
fn assert_recovers(r: &IdentifyResult, truth: f64) {
    assert_eq!(r.status, IdentifyStatus::Identified, "{}", r.message);
    let u = &r.unknowns[0];
    assert!(
        (u.value - truth).abs() <= 1e-6 * truth.abs(),
        "{}: {} against {truth}",
        u.name,
        u.value
    );
    let c = r.certificate.as_ref().unwrap();
    assert!(c.forward_certified && c.reproduces, "{c:?}");
    assert!(r.total_misfit < 1e-4, "misfit {}", r.total_misfit);
}

/// Open points of a forward result: (joint, point, x, y, opening), above 1e-7 of the largest.
fn open_points(r: &SettlementResult) -> Vec<(usize, usize, [f64; 2], f64)> {
    let omax = r
        .joints
        .iter()
        .flat_map(|j| &j.points)
        .fold(0.0f64, |m, p| m.max(p.opening));
    let mut out = Vec::new();
    for j in &r.joints {
        for (k, p) in j.points.iter().enumerate() {
            if p.opening > 1e-7 * omax {
                out.push((j.id, k, [p.x, p.y], p.opening));
            }
        }
    }
    out
}

/// Every number of two JSON documents equal within 1e-12 relative, every other value
/// identical. Numbers below 1e-9 in magnitude on both sides are round-off zeros (the misfits of
/// exact widths, in m or in tolerances, the certificate's relative differences): the smallest
/// physical number here is the tolerance, 1e-4 m, and identify counts a misfit below 1e-6
/// tolerances as exact.
fn assert_same_json(a: &Value, b: &Value, path: &str) {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(y.abs()) || (x.abs() < 1e-9 && y.abs() < 1e-9),
                "{path}: {x} vs {y}"
            );
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "{path}");
            for (i, (p, q)) in x.iter().zip(y).enumerate() {
                assert_same_json(p, q, &format!("{path}[{i}]"));
            }
        }
        (Value::Object(x), Value::Object(y)) => {
            assert_eq!(
                x.keys().collect::<Vec<_>>(),
                y.keys().collect::<Vec<_>>(),
                "{path}"
            );
            for (k, p) in x {
                assert_same_json(p, &y[k], &format!("{path}.{k}"));
            }
        }
        // Messages quote numbers: compare them as numbers, the words exactly.
        (Value::String(x), Value::String(y)) => {
            let (tx, ty) = (tokens(x), tokens(y));
            assert_eq!(tx.len(), ty.len(), "{path}: {x} vs {y}");
            for (p, q) in tx.iter().zip(&ty) {
                match (p.parse::<f64>(), q.parse::<f64>()) {
                    (Ok(u), Ok(v)) => assert_same_json(&u.into(), &v.into(), path),
                    _ => assert_eq!(p, q, "{path}: {x} vs {y}"),
                }
            }
        }
        _ => assert_eq!(a, b, "{path}"),
    }
}

/// Words and numbers of a message (a number: an optional sign, digits, '.', an exponent).
fn tokens(s: &str) -> Vec<String> {
    let chars: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let digit_at = |k: usize| chars.get(k).is_some_and(|c| c.is_ascii_digit());
        let starts = digit_at(i) || (matches!(chars[i], '-' | '+') && digit_at(i + 1));
        if !starts {
            out.push(chars[i].to_string());
            i += 1;
            continue;
        }
        let mut t = String::from(chars[i]);
        i += 1;
        while i < chars.len() {
            let c = chars[i];
            let exp_sign = matches!(c, '-' | '+') && t.ends_with(['e', 'E']);
            if c.is_ascii_digit()
                || c == '.'
                || (matches!(c, 'e' | 'E') && digit_at(i + 1))
                || (matches!(c, 'e' | 'E') && matches!(chars.get(i + 1), Some('-' | '+')))
                || exp_sign
            {
                t.push(c);
                i += 1;
            } else {
                break;
            }
        }
        out.push(t);
    }
    out
}

/// The same survey in metres and in millimetres (JSON, as a surveyor writes it: the metre
/// numbers × 1000, printed): identify's whole result is the same.
#[test]
fn issue32_item2_units_mm_gives_the_same_answer_as_metres() {
    let (st, f) = forward(&moved([0.01, 0.0, 0.0], false));
    let open = open_points(&f);
    assert_eq!(open.len(), 3);
    let cracks_m: Vec<Value> = open
        .iter()
        .map(|(_, _, p, w)| serde_json::json!({"at": p, "opening": w}))
        .collect();
    let metres = serde_json::json!({"tolerance": 1e-4, "cracks": cracks_m});
    // Widths and tolerance in mm; a per-crack tolerance in cm on one of them.
    let cracks_mm: Vec<Value> = open
        .iter()
        .enumerate()
        .map(|(i, (_, _, p, w))| {
            let w: f64 = format!("{}", w * 1000.0).parse().unwrap();
            if i == 1 {
                serde_json::json!({"at": p, "opening": w / 10.0, "units": "cm", "tolerance": 0.01})
            } else {
                serde_json::json!({"at": p, "opening": w})
            }
        })
        .collect();
    let mm = serde_json::json!({"units": "mm", "tolerance": 0.1, "cracks": cracks_mm});
    // Coordinates in mm too.
    let cracks_xy: Vec<Value> = open
        .iter()
        .map(|(_, _, p, w)| {
            serde_json::json!({"at": [p[0] * 1000.0, p[1] * 1000.0], "opening": w * 1000.0})
        })
        .collect();
    let all_mm = serde_json::json!({"units": "mm", "coordinate_units": "mm", "tolerance": 0.1,
        "cracks": cracks_xy});
    let answer = |v: &Value| {
        let obs: Observations = serde_json::from_value(v.clone()).unwrap();
        let r = run(&st, &obs, Component::U);
        assert_recovers(&r, 0.01);
        serde_json::to_value(&r).unwrap()
    };
    let reference = answer(&metres);
    assert_same_json(&reference, &answer(&mm), "result");
    assert_same_json(&reference, &answer(&all_mm), "result");
    // The observed widths are reported in metres whatever the input unit.
    let r: IdentifyResult = serde_json::from_value(answer(&mm)).unwrap();
    for (o, (_, _, _, w)) in r.observations.iter().zip(&open) {
        assert!((o.observed - w).abs() <= 1e-12 * w, "{} vs {w}", o.observed);
        assert!((o.tolerance - 1e-4).abs() <= 1e-16, "{}", o.tolerance);
    }
}

/// Unknown units are refused in one line naming the field (file, crack, model crack).
#[test]
fn issue32_item2_unknown_units_are_refused_naming_the_field() {
    let (st, _) = forward(&moved([0.01, 0.0, 0.0], false));
    for (json, needle) in [
        (
            r#"{"units": "in", "cracks": []}"#,
            r#"observations: "units": unknown unit "in""#,
        ),
        (
            r#"{"coordinate_units": "ft", "cracks": []}"#,
            r#"observations: "coordinate_units": unknown unit "ft""#,
        ),
        (
            r#"{"cracks": [{"joint": 32, "opening": 2}, {"joint": 13, "opening": 1, "units": "inch"}]}"#,
            r#"cracks[1]: "units": unknown unit "inch""#,
        ),
        (
            r#"{"units": "mm", "cracks": [{"joint": 32, "opening": -2}]}"#,
            "cracks[0]: width -2 must be a finite number ≥ 0 (mm)",
        ),
    ] {
        let obs: Observations = serde_json::from_str(json).unwrap();
        let rest = at_rest(&st);
        let u =
            Unknown::supports(&rest, "right", &["right".into()], Component::U, None, None).unwrap();
        let e = identify(&rest, &obs, &[u], &IdentifyOptions::default())
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains(needle), "{e}");
        assert_eq!(e.lines().count(), 1, "{e}");
    }
    let mut m = paper_arch();
    m.cracks = vec![ExistingCrack {
        joint: Some(32),
        opening: Width::One(2.0),
        units: Some("furlong".into()),
        ..Default::default()
    }];
    let e = Structure::new(&m, BuildOptions::default())
        .err()
        .unwrap()
        .to_string();
    assert!(
        e.contains(r#"cracks[0]: "units": unknown unit "furlong""#),
        "{e}"
    );
}

/// A crack line drawn from each open point's mouth along its joint, 40 % of the way to the
/// other end (the crack as seen, not reaching the hinge), in metres.
fn crack_line(st: &Structure, joint: usize, point: usize) -> Vec<[f64; 2]> {
    let jt = &st.joints[joint];
    let p = jt.points[point].x;
    let q = jt.points[1 - point].x;
    vec![p, [p[0] + 0.4 * (q[0] - p[0]), p[1] + 0.4 * (q[1] - p[1])]]
}

/// Polyline observations identify the settlement of the paper's arch (its right springing,
/// tied to the arch, settles 1 cm): the recovered motion is the forward one to 1e-6, and the
/// lines catch exactly the forward analysis's open points.
#[test]
fn issue32_item2_polyline_observations_identify_the_settlement() {
    let (st, f) = forward(&moved([0.0, -0.01, 0.0], true));
    let open = open_points(&f);
    let joints: Vec<usize> = open.iter().map(|o| o.0).collect();
    assert_eq!(joints, vec![1, 13, 32]);
    // Widths in mm, each line along its joint from the mouth.
    let cracks: Vec<Crack> = open
        .iter()
        .map(|&(j, k, _, w)| Crack {
            polyline: Some(crack_line(&st, j, k)),
            opening: Width::One(w * 1000.0),
            ..Default::default()
        })
        .collect();
    let obs = Observations {
        units: Some("mm".into()),
        cracks,
        ..Default::default()
    };
    let r = run(&st, &obs, Component::V);
    assert_recovers(&r, -0.01);
    let seen: Vec<(usize, usize)> = r.observations.iter().map(|o| (o.joint, o.point)).collect();
    let want: Vec<(usize, usize)> = open.iter().map(|o| (o.0, o.1)).collect();
    assert_eq!(seen, want);
    // The whole joint drawn, tapering from the mouth's width to zero at the hinge: the same.
    let cracks: Vec<Crack> = open
        .iter()
        .map(|&(j, k, _, w)| {
            let jt = &st.joints[j];
            Crack {
                polyline: Some(vec![jt.points[k].x, jt.points[1 - k].x]),
                opening: Width::PerPoint(vec![w, 0.0]),
                ..Default::default()
            }
        })
        .collect();
    let r = run(
        &st,
        &Observations {
            cracks,
            ..Default::default()
        },
        Component::V,
    );
    assert_recovers(&r, -0.01);
    // Both points of each joint observed: the mouth open, the hinge closed.
    assert_eq!(r.observations.len(), 6);
    for o in &r.observations {
        let w = open.iter().find(|p| p.0 == o.joint && p.1 == o.point);
        assert_eq!(o.observed, w.map_or(0.0, |p| p.3), "{o:?}");
    }
}

/// A line that catches no joint point is refused in one line naming it, in observations and
/// in a model's existing cracks; so is a line given with three widths.
#[test]
fn issue32_item2_a_polyline_catching_nothing_is_refused() {
    let (st, _) = forward(&moved([0.01, 0.0, 0.0], false));
    // Inside voussoir 20, well away from its joints (a quarter of 0.33 m is 8 cm).
    let c = st.blocks[20].centroid;
    let far = vec![[c[0] - 0.01, c[1]], [c[0] + 0.01, c[1]]];
    let obs = Observations {
        cracks: vec![
            Crack {
                joint: Some(32),
                opening: Width::One(0.002),
                ..Default::default()
            },
            Crack {
                polyline: Some(far.clone()),
                opening: Width::One(0.001),
                ..Default::default()
            },
        ],
        ..Default::default()
    };
    let rest = at_rest(&st);
    let u = Unknown::supports(&rest, "right", &["right".into()], Component::U, None, None).unwrap();
    let e = identify(
        &rest,
        &obs,
        std::slice::from_ref(&u),
        &IdentifyOptions::default(),
    )
    .err()
    .unwrap()
    .to_string();
    assert!(
        e.contains("cracks[1]: the polyline from") && e.contains("catches no joint point"),
        "{e}"
    );
    assert_eq!(e.lines().count(), 1);
    // A generous snap catches the joints on either side of the block.
    let mut obs2 = obs.clone();
    obs2.cracks[1].snap = Some(0.2);
    obs2.cracks[1].opening = Width::One(0.0);
    assert!(identify(
        &rest,
        &obs2,
        std::slice::from_ref(&u),
        &IdentifyOptions::default()
    )
    .is_ok());
    let mut obs3 = obs.clone();
    obs3.cracks[1].opening = Width::PerPoint(vec![0.001, 0.0, 0.002]);
    let e = identify(&rest, &obs3, &[u], &IdentifyOptions::default())
        .err()
        .unwrap()
        .to_string();
    assert!(
        e.contains("cracks[1]: a crack given by \"polyline\" takes one width, two (at its start and end) or one per vertex (2); 3 given"),
        "{e}"
    );
    let mut m = paper_arch();
    m.cracks = vec![ExistingCrack {
        polyline: Some(far),
        opening: Width::One(0.001),
        ..Default::default()
    }];
    let e = Structure::new(&m, BuildOptions::default())
        .err()
        .unwrap()
        .to_string();
    assert!(
        e.contains("cracks[0]: the polyline from") && e.contains("catches no joint point"),
        "{e}"
    );
}

/// An existing crack given as a polyline (widths in mm) is the same crack as given by joint
/// (in m): same gaps, and the same settlement and limit results. The arch of
/// tests/existing_cracks.rs: 0.45 m thick, live load on the left half, 3 mm at the crown's
/// intrados.
#[test]
fn issue32_item2_existing_crack_as_a_polyline_equals_the_same_crack_by_joint() {
    let base = || {
        arch(&ArchSpec {
            thickness: 0.45,
            live: LiveLoad::Left,
            ..ArchSpec::default()
        })
        .unwrap()
    };
    let sound = build(&base());
    // The crown joint's intrados point (0, 2.86).
    let (j, k) = sound
        .joints
        .iter()
        .enumerate()
        .flat_map(|(j, jt)| jt.points.iter().enumerate().map(move |(k, p)| (j, k, p.x)))
        .find(|(_, _, x)| x[0].abs() < 1e-9 && (x[1] - 2.86).abs() < 1e-9)
        .map(|(j, k, _)| (j, k))
        .unwrap();
    let mut by_joint = base();
    let mut w = vec![0.0; 2];
    w[k] = 0.003;
    by_joint.cracks = vec![ExistingCrack {
        joint: Some(j),
        opening: Width::PerPoint(w),
        ..Default::default()
    }];
    let mut by_line = base();
    by_line.cracks = vec![ExistingCrack {
        polyline: Some(vec![[0.0, 2.86], [0.0, 2.86 + 0.12]]),
        opening: Width::One(3.0),
        units: Some("mm".into()),
        ..Default::default()
    }];
    // The JSON form reads back the same.
    let text = serde_json::to_string(&by_line).unwrap();
    assert!(
        text.contains(r#""polyline":[[0.0,2.86],[0.0,2.98]]"#),
        "{text}"
    );
    assert_eq!(serde_json::from_str::<Model>(&text).unwrap(), by_line);
    let (a, b) = (build(&by_joint), build(&by_line));
    let gaps = |s: &Structure| -> Vec<f64> {
        s.joints
            .iter()
            .flat_map(|jt| jt.points.iter().map(|p| p.gap))
            .collect()
    };
    let (ga, gb) = (gaps(&a), gaps(&b));
    assert_eq!(ga.iter().filter(|g| **g > 0.0).count(), 1);
    for (x, y) in ga.iter().zip(&gb) {
        assert!((x - y).abs() <= 1e-15, "{x} vs {y}");
    }
    // Settling (closing supports 1 cm) and collapsing give the same numbers.
    let settled = |m: &Model| {
        let mut m = m.clone();
        let i = m.support_index("right").unwrap();
        m.supports[i].motion = [-0.01, 0.0, 0.0];
        let r = settle(&build(&m), &SolverOptions::default()).unwrap();
        serde_json::to_value(&r).unwrap()
    };
    assert_same_json(&settled(&by_joint), &settled(&by_line), "settle");
    let limit = |s: &Structure| {
        let r = voussoir::analysis::limit(s, &SolverOptions::default()).unwrap();
        serde_json::to_value(&r).unwrap()
    };
    assert_same_json(&limit(&a), &limit(&b), "limit");
}
