//! Issue 30, item 4: the 20 × 10 running-bond wall of docs/joint-laws.md with μ = 0.6
//! non-associative friction (`settle --profile uniform:5.2,8.0,-0.01`): the drawing's title
//! counts the hinge dots it draws, and every crack states the chord of its polyline (rise and
//! run of its end points), the summary the longest crack's slope.

use crate::common;
use crate::common::cwd::ok;
use std::path::PathBuf;

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i30fw", name)
}

/// The wall settled as in docs/joint-laws.md: (summary, result JSON, SVG).
fn friction_wall(name: &str) -> (String, serde_json::Value, String) {
    let d = tmpdir(name);
    let m = d.join("wall.json").to_string_lossy().into_owned();
    ok(&[
        "gen",
        "wall",
        "--courses",
        "10",
        "--units",
        "20",
        "--unit",
        "0.4,0.2",
        "-o",
        &m,
    ]);
    let out = d.join("r.json").to_string_lossy().into_owned();
    let svg = d.join("w.svg").to_string_lossy().into_owned();
    let o = ok(&[
        "settle",
        &m,
        "--profile",
        "uniform:5.2,8.0,-0.01",
        "--friction",
        "0.6",
        "--non-associative",
        "-o",
        &out,
        "--svg",
        &svg,
    ]);
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let s = std::fs::read_to_string(&svg).unwrap();
    let _ = std::fs::remove_dir_all(&d);
    (String::from_utf8_lossy(&o.stdout).into_owned(), r, s)
}

#[test]
fn issue30_item4_title_counts_the_hinge_dots_drawn() {
    let (_, r, svg) = friction_wall("dots");
    // The dots drawn: the circles of the SVG's hinge group (counted in the SVG itself).
    let group = svg
        .split("<g class=\"hinges\"")
        .nth(1)
        .and_then(|g| g.split("</g>").next())
        .unwrap_or("");
    let dots = group.matches("<circle").count();
    // The result's hinged joints (its hinges, a joint counted once).
    let joints: std::collections::BTreeSet<u64> = r["hinges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|h| h["joint"].as_u64().unwrap())
        .collect();
    // The wall leaves most hinges out of the drawing (they are bends of crack lines or ends of
    // hairlines): the case where the title's count used to differ from the dots.
    assert!(
        dots > 0 && dots < joints.len(),
        "{dots} dots, {} joints",
        joints.len()
    );
    let want = format!(
        "{dots} hinge{} drawn of {} hinged joints",
        if dots == 1 { "" } else { "s" },
        joints.len()
    );
    assert!(svg.contains(&want), "title should say {want:?}");
}

#[test]
fn issue30_item4_cracks_state_their_chord_and_the_summary_the_longest_slope() {
    let (summary, r, _) = friction_wall("chord");
    let cracks = r["cracks"].as_array().unwrap();
    assert!(!cracks.is_empty());
    let f = |v: &serde_json::Value| v.as_f64().unwrap();
    // Every crack's rise and run are |Δy| and |Δx| of its polyline's end points.
    for c in cracks {
        let p = c["points"].as_array().unwrap();
        let (a, b) = (&p[0], &p[p.len() - 1]);
        assert!(
            (f(&c["rise"]) - (f(&b[1]) - f(&a[1])).abs()).abs() < 1e-12,
            "{c}"
        );
        assert!(
            (f(&c["run"]) - (f(&b[0]) - f(&a[0])).abs()).abs() < 1e-12,
            "{c}"
        );
    }
    // The summary states the longest crack's slope: recomputed from its points.
    let (i, longest) = cracks
        .iter()
        .enumerate()
        .fold((0, &cracks[0]), |(bi, b), (i, c)| {
            if f(&c["length"]) > f(&b["length"]) * (1.0 + 1e-9) {
                (i, c)
            } else {
                (bi, b)
            }
        });
    let p = longest["points"].as_array().unwrap();
    let (a, b) = (&p[0], &p[p.len() - 1]);
    let (rise, run) = ((f(&b[1]) - f(&a[1])).abs(), (f(&b[0]) - f(&a[0])).abs());
    let line = summary
        .lines()
        .find(|l| l.trim_start().starts_with("longest: crack"))
        .unwrap_or_else(|| panic!("no longest-crack line in\n{summary}"));
    assert!(line.contains(&format!("crack {},", i + 1)), "{line}");
    assert!(
        line.contains(&format!("rise {rise:.4} m over {run:.4} m")),
        "{line}"
    );
    if run > 0.0 {
        assert!(line.contains(&format!("slope {:.3}", rise / run)), "{line}");
    }
}

#[test]
fn issue30_item4_drawing_says_which_hairlines_it_leaves_out() {
    let (_, r, svg) = friction_wall("hairlines");
    let f = |v: &serde_json::Value| v.as_f64().unwrap();
    let widths: Vec<f64> = r["cracks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| f(&c["max_opening"]))
        .collect();
    let widest = widths.iter().fold(0.0f64, |m, w| m.max(*w));
    // The drawing's threshold (docs/drawing.md): cracks narrower than 1 % of the widest.
    let left: Vec<f64> = widths
        .iter()
        .copied()
        .filter(|w| *w < 0.01 * widest)
        .collect();
    assert!(!left.is_empty(), "the wall has hairline cracks");
    let most = left.iter().fold(0.0f64, |m, w| m.max(*w));
    assert!(most < 0.01 * widest);
    let want = format!(
        "{} hairline cracks narrower than 1 % of the widest not drawn (the widest of them {:.3} mm)",
        left.len(),
        most * 1e3
    );
    assert!(svg.contains(&want), "the drawing should say {want:?}");
    // The crack lines drawn are the others.
    let lines = svg
        .split("<g class=\"crack-lines\"")
        .nth(1)
        .and_then(|g| g.split("</g>").next())
        .unwrap_or("")
        .matches("<polyline")
        .count();
    assert_eq!(lines + left.len(), widths.len());
}

/// Session 23: a vertical crack is called vertical. The paper arch's spreading opens its crown
/// joint, a vertical crack 0.33 m long (the ring's thickness) whose chord has a run of
/// round-off (2e-17 m); the summary printed "slope 16331239353195370.000".
#[test]
fn a_vertical_longest_crack_is_called_vertical() {
    let d = common::tmpdir("vertical-crack", "arch");
    common::gen_model(&d, "arch -o arch.json");
    let s = common::run(&d, &["settle", "arch.json", "--move", "right=0.01,0"]);
    let line = s
        .lines()
        .find(|l| l.trim_start().starts_with("longest: crack"))
        .unwrap_or_else(|| panic!("no longest-crack line in\n{s}"));
    assert!(
        line.contains("0.3300 m long; its ends rise 0.3300 m over 0.0000 m (vertical)"),
        "{line}"
    );
}
