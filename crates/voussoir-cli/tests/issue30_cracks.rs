//! Issue 30, item 3 and issue 32 ("settle's summary lists the crack widths in mm"): the
//! summaries of `settle` (2D and 3D) list the cracks, widest first, with their widths in mm
//! (at most ten lines, then "… and N more"); `limit` lists the mechanism's cracks with openings
//! relative to the largest; the JSON carries `cracks` and the drawing draws them as lines.
//!
//! References: the widths printed are the JSON's `max_opening` in mm; the paper's Fig 9
//! settlement opens three cracks through the arch's 0.33 m thickness, the crown's twice as wide
//! as each haunch's (tests/issue30_cracks.rs of the library).

use crate::common;
use crate::common::run;
use std::path::PathBuf;

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i30cracks", name)
}

fn crack_lines(summary: &str) -> Vec<&str> {
    summary
        .lines()
        .filter(|l| l.trim_start().starts_with("crack "))
        .collect()
}

#[test]
fn issue32_settle_summary_lists_the_crack_widths_in_mm() {
    let d = tmpdir("settle");
    run(&d, &["gen", "arch", "--live", "none", "-o", "arch.json"]);
    let s = run(
        &d,
        &[
            "settle",
            "arch.json",
            "--move",
            "right=0.01,0",
            "-o",
            "r.json",
        ],
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("r.json")).unwrap()).unwrap();
    let cracks = json["cracks"].as_array().unwrap();
    assert_eq!(cracks.len(), 3);
    assert!(s.contains("cracks: 3 (widths in mm, widest first)"), "{s}");
    let lines = crack_lines(&s);
    assert_eq!(lines.len(), 3, "{s}");
    for (i, (line, c)) in lines.iter().zip(cracks).enumerate() {
        let mm = c["max_opening"].as_f64().unwrap() * 1000.0;
        let p0 = &c["points"][0];
        let p1 = &c["points"][1];
        let xy = |p: &serde_json::Value| {
            let f = |v: f64| {
                let t = format!("{v:.4}");
                if t == "-0.0000" {
                    "0.0000".to_string()
                } else {
                    t
                }
            };
            format!(
                "({}, {})",
                f(p[0].as_f64().unwrap()),
                f(p[1].as_f64().unwrap())
            )
        };
        let want = format!(
            "crack  {}: {mm:.3} mm wide, 0.3300 m long, joint {}",
            i + 1,
            c["joints"][0]
        );
        assert!(
            line.trim_start().starts_with(want.trim_start()),
            "{line} vs {want}"
        );
        assert!(
            line.contains(&format!(
                "from {} to {} m (closing at a hinge)",
                xy(p0),
                xy(p1)
            )),
            "{line}"
        );
    }
    // The crown's crack is the widest: 2.220 mm (twice each haunch's 1.110 mm).
    assert!(lines[0].contains("2.220 mm wide"), "{}", lines[0]);
    assert!(lines[1].contains("1.110 mm wide") && lines[2].contains("1.110 mm wide"));
}

#[test]
fn issue32_settle_summary_lists_ten_cracks_then_the_rest_counted() {
    // A 3D dome settling under two base segments cracks in many places.
    let d = tmpdir("dome");
    run(
        &d,
        &[
            "gen",
            "dome",
            "--courses",
            "8",
            "--segments",
            "16",
            "--thickness",
            "0.3",
            "-o",
            "dome.json",
        ],
    );
    let s = run(
        &d,
        &[
            "settle",
            "dome.json",
            "--friction",
            "0.5",
            "--move",
            "base0=0,0,-2cm",
            "--move",
            "base1=0,0,-2cm",
            "-o",
            "r.json",
        ],
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("r.json")).unwrap()).unwrap();
    let cracks = json["cracks"].as_array().unwrap();
    let n = cracks.len();
    assert!(n > 10, "{n}");
    assert_eq!(crack_lines(&s).len(), 10, "{s}");
    assert!(s.contains(&format!("cracks: {n} (widths in mm")), "{s}");
    assert!(s.contains(&format!("… and {} more", n - 10)), "{s}");
    // Widest first, each line the JSON's record in mm.
    for (line, c) in crack_lines(&s).iter().zip(cracks) {
        let mm = c["max_opening"].as_f64().unwrap() * 1000.0;
        assert!(
            line.contains(&format!(": {mm:.3} mm wide")),
            "{line} vs {mm}"
        );
    }
    let w: Vec<f64> = cracks
        .iter()
        .map(|c| c["max_opening"].as_f64().unwrap())
        .collect();
    assert!(w.windows(2).all(|p| p[0] >= p[1]), "{w:?}");
}

#[test]
fn issue30_item3_limit_summary_lists_the_mechanism_cracks_without_widths() {
    let d = tmpdir("limit");
    run(&d, &["gen", "arch", "--live", "left", "-o", "half.json"]);
    let s = run(&d, &["limit", "half.json", "--svg", "c.svg"]);
    assert!(
        s.contains("cracks of the collapse mechanism: 4 (openings relative to the largest: a mechanism's amplitude is arbitrary)"),
        "{s}"
    );
    let lines = crack_lines(&s);
    assert_eq!(lines.len(), 4);
    assert!(lines[0].contains("relative opening 1.000"), "{}", lines[0]);
    assert!(!s.contains(" mm wide"), "{s}");
    // Drawn as four numbered lines.
    let svg = std::fs::read_to_string(d.join("c.svg")).unwrap();
    let group = svg.split("<g class=\"crack-lines\"").nth(1).unwrap();
    let group = &group[..group.find("</g>").unwrap()];
    assert_eq!(group.matches("<polyline").count(), 4, "{group}");
    assert!(svg.contains("<g class=\"crack-labels\""));
}
