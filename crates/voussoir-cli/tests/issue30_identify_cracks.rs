//! Issue 30 item 3: a result's crack polylines (`cracks`: `points`, `openings`, and the derived
//! fields as written) go back in as they are — as `identify` observations and as a model's
//! existing cracks. Must-show: `identify` recovers the paper arch's settlement from the crack
//! polylines of its forward run.
use crate::common::{json, run, tmpdir};

/// The arch's forward settlement: the right support moves 5 mm out and 10 mm down.
const U: f64 = 0.005;
const V: f64 = -0.010;

fn forward(d: &std::path::Path) -> serde_json::Value {
    run(d, &["gen", "arch", "-o", "arch.json"]);
    run(
        d,
        &[
            "settle",
            "arch.json",
            "--move",
            &format!("right={U},{V}"),
            "-o",
            "fwd.json",
        ],
    );
    json(&std::fs::read_to_string(d.join("fwd.json")).unwrap())
}

#[test]
fn issue30_item3_identify_recovers_the_arch_settlement_from_its_crack_polylines() {
    let d = tmpdir("i30id", "polylines");
    let fwd = forward(&d);
    let cracks = fwd["cracks"].as_array().unwrap();
    assert!(cracks.len() >= 3, "the settled arch has three hinges");
    // The result's crack records exactly as written (points, openings, length, joints, …).
    std::fs::write(
        d.join("obs.json"),
        serde_json::json!({ "cracks": cracks }).to_string(),
    )
    .unwrap();
    run(
        &d,
        &[
            "identify",
            "arch.json",
            "--cracks",
            "obs.json",
            "--unknown",
            "right=u,v",
            "-o",
            "id.json",
        ],
    );
    let id = json(&std::fs::read_to_string(d.join("id.json")).unwrap());
    let right = id["support_motions"]
        .as_array()
        .expect("support_motions")
        .iter()
        .find(|m| m["support"] == "right")
        .expect("right");
    let (u, v) = (right["u"].as_f64().unwrap(), right["v"].as_f64().unwrap());
    // Reproduced: the forward analysis of the identified motion opens the same widths.
    assert!(
        id["total_misfit"].as_f64().unwrap() < 1e-6,
        "{}",
        id["total_misfit"]
    );
    assert!((u - U).abs() < 1e-6 && (v - V).abs() < 1e-6, "u {u}, v {v}");
}

#[test]
fn issue30_item3_a_results_cracks_are_a_models_existing_cracks() {
    let d = tmpdir("i30id", "existing");
    let fwd = forward(&d);
    let mut m = json(&std::fs::read_to_string(d.join("arch.json")).unwrap());
    m["cracks"] = fwd["cracks"].clone();
    std::fs::write(d.join("cracked.json"), m.to_string()).unwrap();
    // The same cracks written as the survey form (polyline + one width per vertex).
    let survey: Vec<serde_json::Value> = fwd["cracks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| serde_json::json!({"polyline": c["points"], "opening": c["openings"]}))
        .collect();
    m["cracks"] = serde_json::Value::Array(survey);
    std::fs::write(d.join("survey.json"), m.to_string()).unwrap();
    // Reading either model opens the same joint points by the same gaps: the settlement of
    // the cracked arch pushed back (1 mm in, 2 mm up: the old cracks close first) is the same
    // number.
    let work = |f: &str| {
        run(
            &d,
            &["settle", f, "--move", "right=-0.001,0.002", "-o", "w.json"],
        );
        let r = json(&std::fs::read_to_string(d.join("w.json")).unwrap());
        r["certificate"]["primal"].as_f64().unwrap()
    };
    let (a, b) = (work("cracked.json"), work("survey.json"));
    assert!((a - b).abs() <= 1e-12 * a.abs().max(1e-300), "{a} vs {b}");
    // And the cracks change the answer (the gaps are read, not ignored): the uncracked arch.
    let c = work("arch.json");
    assert!((a - c).abs() > 1e-6 * c.abs(), "cracks ignored: {a} vs {c}");
}
