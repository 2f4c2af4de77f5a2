//! Flags and models that were accepted and silently gave a meaningless answer, now refused in
//! one line (a regression test per defect): `limit --no-ranges` without `--canonical` (the
//! ranges are a stage of the canonical selection, so the flag did nothing), and a settlement
//! of a weightless model (every mechanism does zero work: the LP's "answer" was printed with a
//! relative gap of 1 as if it meant something), in 2D and 3D.
use crate::common::{json, refused, run, tmpdir};

/// The generated arch with a live load at its crown (so that `limit` has something to do).
fn arch(dir: &std::path::Path) {
    run(dir, &["gen", "arch", "-o", "arch.json"]);
}

/// The model with every unit weight set to zero.
fn weightless(dir: &std::path::Path, from: &str, to: &str) {
    let mut m = json(&std::fs::read_to_string(dir.join(from)).unwrap());
    let mats = m["materials"].as_object_mut().expect("materials");
    assert!(!mats.is_empty());
    for (_, v) in mats.iter_mut() {
        v["unit_weight"] = serde_json::json!(0.0);
    }
    std::fs::write(dir.join(to), serde_json::to_string(&m).unwrap()).unwrap();
}

#[test]
fn session12_limit_no_ranges_needs_canonical() {
    let d = tmpdir("s12", "noranges");
    run(&d, &["gen", "arch", "--live", "left", "-o", "arch.json"]);
    refused(
        &d,
        &["limit", "arch.json", "--no-ranges", "-o", "r.json"],
        "--no-ranges applies to the canonical selection: add --canonical",
    );
    assert!(!d.join("r.json").exists());
    // With --canonical it is honoured: the same λ, no reaction ranges computed.
    run(&d, &["limit", "arch.json", "-o", "plain.json"]);
    run(
        &d,
        &[
            "limit",
            "arch.json",
            "--canonical",
            "--no-ranges",
            "-o",
            "r.json",
        ],
    );
    run(
        &d,
        &["limit", "arch.json", "--canonical", "-o", "ranges.json"],
    );
    let read = |f: &str| json(&std::fs::read_to_string(d.join(f)).unwrap());
    let (plain, r, ranges) = (read("plain.json"), read("r.json"), read("ranges.json"));
    let l0 = plain["load_multiplier"].as_f64().unwrap();
    let l1 = r["load_multiplier"].as_f64().unwrap();
    assert!((l0 - l1).abs() <= 1e-9 * l0, "λ {l0} vs {l1}");
    let n_ranges = |v: &serde_json::Value| {
        v["canonical"]["forces"]["reaction_ranges"]
            .as_array()
            .map_or(0, |a| a.len())
    };
    assert_eq!(n_ranges(&r), 0, "--no-ranges computed ranges");
    assert_eq!(
        n_ranges(&ranges),
        2,
        "the arch's two supports have ranges by default"
    );
}

#[test]
fn session12_settle_of_a_weightless_model_is_refused_2d() {
    let d = tmpdir("s12", "weightless2d");
    arch(&d);
    weightless(&d, "arch.json", "w0.json");
    refused(
        &d,
        &[
            "settle",
            "w0.json",
            "--move",
            "right=0,-0.01",
            "-o",
            "r.json",
        ],
        "settle needs dead loads",
    );
    assert!(!d.join("r.json").exists());
    // The same model with its weight settles (the refusal is about the weight only).
    run(&d, &["settle", "arch.json", "--move", "right=0,-0.01"]);
}

#[test]
fn session12_settle_of_a_weightless_model_is_refused_3d() {
    let d = tmpdir("s12", "weightless3d");
    run(&d, &["gen", "vault", "-o", "vault.json"]);
    weightless(&d, "vault.json", "w0.json");
    refused(
        &d,
        &[
            "settle",
            "w0.json",
            "--move",
            "right=0,0,-0.01",
            "-o",
            "r.json",
        ],
        "settle needs dead loads",
    );
    assert!(!d.join("r.json").exists());
}

/// The report's crack table was made per joint while the summary and the drawings list crack
/// polylines: the report now lists the result's `cracks` in the summary's own words, in the
/// same order, and keeps the per-joint table after it.
#[test]
fn session12_report_lists_the_cracks_of_the_summary() {
    let d = tmpdir("s12", "reportcracks");
    arch(&d);
    let out = run(
        &d,
        &[
            "settle",
            "arch.json",
            "--move",
            "right=0.005,-0.01",
            "--report",
            "r.html",
            "-o",
            "r.json",
        ],
    );
    let html = std::fs::read_to_string(d.join("r.html")).unwrap();
    let r = json(&std::fs::read_to_string(d.join("r.json")).unwrap());
    let n = r["cracks"].as_array().unwrap().len();
    assert!(n >= 3, "a settled arch opens at least three joints: {n}");
    let lines: Vec<&str> = out
        .lines()
        .filter_map(|l| l.trim_start().strip_prefix("crack "))
        .collect();
    assert_eq!(lines.len(), n.min(10), "{out}");
    let start = html.find("Cracks, widest first").expect("crack table");
    let joints = html.find("Cracked joints").expect("joint table");
    assert!(start < joints);
    let table = &html[start..joints];
    for l in lines {
        let (k, text) = l.split_once(": ").unwrap();
        let row = format!("<tr><td>{}</td><td>{}</td></tr>", k.trim(), text);
        assert!(table.contains(&row), "no row {row} in\n{table}");
    }
}
