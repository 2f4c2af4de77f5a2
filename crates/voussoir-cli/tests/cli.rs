//! The `voussoir` binary end to end: generation, analyses, JSON output, bad input.

use crate::common::cwd::run;
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn paper_arch(dir: &Path, live: &str) -> String {
    let p = dir.join(format!("arch-{live}.json"));
    let mut args = vec![
        "gen",
        "arch",
        "--radius",
        "2.86",
        "--radius-at",
        "intrados",
        "--thickness",
        "0.33",
        "--voussoirs",
        "64",
        "--unit-weight",
        "18",
        "--live",
        live,
    ];
    // An intensity only for a vertical live load (`--live none` refuses it).
    if live != "none" {
        args.extend(["--live-load", "1"]);
    }
    args.extend(["-o", p.to_str().unwrap()]);
    let o = run(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    p.to_str().unwrap().to_string()
}

#[test]
fn limit_json_has_the_documented_fields_and_is_deterministic() {
    let d = tmpdir("limit");
    let arch = paper_arch(&d, "full");
    let a = run(&["limit", &arch, "--json"]);
    assert!(a.status.success());
    let b = run(&["limit", &arch, "--json"]);
    assert_eq!(a.stdout, b.stdout, "same input, byte-identical JSON");
    let v: serde_json::Value = serde_json::from_slice(&a.stdout).unwrap();
    assert_eq!(v["status"], "collapse");
    let l = v["load_multiplier"].as_f64().unwrap();
    assert!((l - 0.429).abs() < 0.02 * 0.429, "λ = {l}");
    assert_eq!(v["blocks"].as_array().unwrap().len(), 64);
    let j = &v["joints"][1];
    assert_eq!(j["a"], 0);
    assert_eq!(j["b"], "left");
    for key in ["x", "y", "opening", "normal_force", "shear_force"] {
        assert!(j["points"][0][key].is_number(), "{key}");
    }
    assert!(j["state"].is_string());
    // -o writes the same JSON and prints the summary.
    let out = d.join("r.json");
    let c = run(&["limit", &arch, "-o", out.to_str().unwrap()]);
    assert!(String::from_utf8_lossy(&c.stdout).contains("collapse load multiplier"));
    assert_eq!(std::fs::read(&out).unwrap(), a.stdout);
}

#[test]
fn settle_json_has_the_documented_fields() {
    let d = tmpdir("settle");
    let arch = paper_arch(&d, "none");
    let o = run(&["settle", &arch, "--move", "right=0.01,0", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["status"], "mechanism");
    let (p, q) = (
        v["work_dead_loads"].as_f64().unwrap(),
        v["work_reactions"].as_f64().unwrap(),
    );
    assert!((p - q).abs() <= 1e-7 * p.abs());
    assert!(v["duality_gap"].as_f64().unwrap() <= 1e-7);
    let hinges: Vec<u64> = v["hinges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|h| h["joint"].as_u64().unwrap())
        .collect();
    assert_eq!(hinges, vec![13, 32, 51]);
    let r = &v["reactions"][1];
    assert_eq!(r["support"], "right");
    assert!(
        r["fx"].as_f64().unwrap() < 0.0,
        "the support pushes the arch inwards"
    );
    // Fixed support and a rotation in degrees are accepted.
    let o = run(&[
        "settle",
        &arch,
        "--move",
        "right=0,-0.01,0",
        "--fixed",
        "right",
        "--json",
    ]);
    assert!(o.status.success());
}

fn expect_failure(args: &[&str], needle: &str, out: Option<&Path>) {
    let o = run(args);
    assert!(!o.status.success(), "{args:?} should fail");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.starts_with("error: ") && err.contains(needle), "{err}");
    if let Some(p) = out {
        assert!(!p.exists(), "no output file may be written");
    }
}

#[test]
fn bad_input_fails_in_one_line_without_output() {
    let d = tmpdir("bad");
    let write = |name: &str, text: &str| {
        let p = d.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let base = r#"{"name": "base", "polygon": [[-2,-1],[2,-1],[2,0],[-2,0]]}"#;
    let cases = [
        (
            "open.json",
            format!(r#"{{"blocks": [{{"polygon": [[0,0],[1,0]]}}], "supports": [{base}]}}"#),
            "block 0",
        ),
        (
            "bowtie.json",
            format!(
                r#"{{"blocks": [{{"polygon": [[0,0],[1,1],[1,0],[0,1]]}}], "supports": [{base}]}}"#
            ),
            "self-intersecting",
        ),
        (
            "overlap.json",
            format!(
                r#"{{"blocks": [{{"polygon": [[0,0],[1,0],[1,1],[0,1]]}}, {{"polygon": [[0.5,0],[1.5,0],[1.5,1],[0.5,1]]}}], "supports": [{base}]}}"#
            ),
            "block 0 and block 1 overlap",
        ),
        (
            "isolated.json",
            format!(
                r#"{{"blocks": [{{"polygon": [[0,0],[1,0],[1,1],[0,1]]}}, {{"polygon": [[5,5],[6,5],[6,6],[5,6]]}}], "supports": [{base}]}}"#
            ),
            "block 1 touches nothing",
        ),
        (
            "nosupport.json",
            r#"{"blocks": [{"polygon": [[0,0],[1,0],[1,1],[0,1]]}], "supports": []}"#.to_string(),
            "no supports",
        ),
        (
            "nan.json",
            format!(
                r#"{{"blocks": [{{"polygon": [[0,0],[1,0],[1,1],[0,NaN]]}}], "supports": [{base}]}}"#
            ),
            "invalid model JSON",
        ),
        (
            "unknown.json",
            format!(
                r#"{{"blocks": [{{"polygon": [[0,0],[1,0],[1,1],[0,1]], "colour": "red"}}], "supports": [{base}]}}"#
            ),
            "unknown field `colour`",
        ),
    ];
    for (name, text, needle) in cases {
        let p = write(name, &text);
        let out = d.join(format!("{name}.out.json"));
        expect_failure(
            &["limit", &p, "-o", out.to_str().unwrap()],
            needle,
            Some(&out),
        );
        expect_failure(
            &["settle", &p, "-o", out.to_str().unwrap()],
            needle,
            Some(&out),
        );
    }
    expect_failure(
        &["limit", d.join("missing.json").to_str().unwrap()],
        "cannot read",
        None,
    );
    let arch = paper_arch(&d, "full");
    expect_failure(
        &["settle", &arch, "--move", "middle=0.01,0"],
        "no support named 'middle'",
        None,
    );
    expect_failure(
        &["settle", &arch, "--move", "right=a,b"],
        "must be numbers",
        None,
    );
}

#[test]
fn drawings_from_the_command_line() {
    let d = tmpdir("draw");
    let arch = paper_arch(&d, "full");
    let (png, svg, html, res) = (
        d.join("m.png"),
        d.join("m.svg"),
        d.join("m.html"),
        d.join("r.json"),
    );
    let o = run(&[
        "settle",
        &arch,
        "--move",
        "right=0.01,0",
        "--png",
        png.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
        "--report",
        html.to_str().unwrap(),
        "-o",
        res.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") || text.starts_with("<?xml"));
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(page.contains("<svg"), "the report inlines its figures");
    assert!(
        !page.contains("<script src") && !page.contains("<link "),
        "no external resources"
    );
    // A saved result draws alone, identically to the direct drawing.
    let png2 = d.join("m2.svg");
    let o = run(&["plot", res.to_str().unwrap(), "-o", png2.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::metadata(&png2).unwrap().len() > 1000);
    // Bad input: no drawing is left behind.
    let bad = d.join("bad.json");
    std::fs::write(&bad, r#"{"blocks": [], "supports": []}"#).unwrap();
    let none = d.join("none.png");
    expect_failure(
        &[
            "limit",
            bad.to_str().unwrap(),
            "--png",
            none.to_str().unwrap(),
        ],
        "no blocks",
        Some(&none),
    );
}
