//! Session 24's trust audit of the command line: each defect found, one regression test.

use crate::common::{gen_model, json, refused, run, tmpdir};

fn dir(name: &str) -> std::path::PathBuf {
    tmpdir("s24audit", name)
}

/// `incremental` with a control direction at right angles to the collapse mechanism stopped at
/// step 0 with "the mechanism does not move the control point along the direction" and nothing
/// more. A dome under a crown load collapses axisymmetrically: by symmetry its crown moves
/// straight down, so a horizontal control direction has nothing to step by. The summary now says
/// how the mechanism moves the control point (exactly −z, by symmetry) and what to change; along
/// −z the same run steps to the largest displacement.
#[test]
fn incremental_control_still_says_why() {
    let d = dir("still");
    gen_model(&d, "dome --crown-load 10 -o dome.json");
    let inc = |direction: &str| {
        json(&run(
            &d,
            &[
                "incremental",
                "dome.json",
                "--control",
                "0,0,5",
                "--direction",
                direction,
                "--step",
                "1mm",
                "--max",
                "3mm",
                "--json",
            ],
        ))
    };
    let r = inc("+x");
    assert_eq!(r["status"], "control_still");
    let msg = r["message"].as_str().unwrap();
    assert!(
        msg.contains("moves the control point along (0.000, 0.000, -1.000)")
            && msg.contains("at right angles to the control direction (1.000, 0.000, 0.000)"),
        "{msg}"
    );
    // The direction it names is the one that works: 3 steps of 1 mm down.
    let r = inc("-z");
    assert_eq!(r["status"], "max_displacement", "{}", r["message"]);
    let last = r["curve"].as_array().unwrap().last().unwrap()["displacement"]
        .as_f64()
        .unwrap();
    assert!((last - 0.003).abs() < 1e-9, "{last}");

    // A control point on a block the mechanism leaves still: the half-loaded arch's hinges are
    // at joints 12, 32, 51 and 64, so voussoirs 0–11 stay on the left springing.
    gen_model(&d, "arch --live left -o half.json");
    let out = run(
        &d,
        &[
            "incremental",
            "half.json",
            "--control",
            "-2.9,0.1",
            "--step",
            "0.1mm",
            "--max",
            "1mm",
        ],
    );
    assert!(
        out.contains("does not move the control point (block 0 stays still)"),
        "{out}"
    );
}

/// `limit --non-associative` printed its λ exactly as the associative, certified one. The
/// summary (and the JSON's message) now say it is a heuristic fixed-point iteration's value,
/// not a certified bound, with the associative λ that bounds it from above — the same number a
/// plain `limit --friction` run certifies.
#[test]
fn limit_nonassociative_says_heuristic() {
    let d = dir("nonassoc");
    gen_model(&d, "arch --live left -o half.json");
    let assoc = json(&run(
        &d,
        &["limit", "half.json", "--friction", "0.5", "--json"],
    ));
    let la = assoc["load_multiplier"].as_f64().unwrap();
    assert_eq!(assoc["certificate"]["ok"], true);
    let text = run(
        &d,
        &[
            "limit",
            "half.json",
            "--friction",
            "0.5",
            "--non-associative",
        ],
    );
    let line = text.lines().nth(1).unwrap();
    assert!(
        line.contains("non-associative friction: the fixed point of a heuristic iteration (")
            && !line.contains("did not converge")
            && line.contains("not a certified bound")
            && line.contains(&format!(
                "the associative λ = {la:.6} bounds the true one from above"
            )),
        "{line}"
    );
    let na = json(&run(
        &d,
        &[
            "limit",
            "half.json",
            "--friction",
            "0.5",
            "--non-associative",
            "--json",
        ],
    ));
    assert!(na.get("certificate").is_none());
    assert!(
        na["message"]
            .as_str()
            .unwrap()
            .contains("not a certified bound"),
        "{}",
        na["message"]
    );
    // λ of the iteration never above the associative one here (half-span arch: hinging only).
    assert!(na["load_multiplier"].as_f64().unwrap() <= la * (1.0 + 1e-7));
}

/// `--non-associative` without any friction coefficient ran the iteration on joints that cannot
/// slide and printed the associative answer under the iteration's name. Refused in one line,
/// with no output file, in `limit` and `capacity`.
#[test]
fn nonassociative_without_friction_refused() {
    let d = dir("nofriction");
    gen_model(&d, "arch --live full -o arch.json");
    refused(
        &d,
        &["limit", "arch.json", "--non-associative", "-o", "r.json"],
        "--non-associative needs friction",
    );
    refused(
        &d,
        &[
            "capacity",
            "arch.json",
            "--move",
            "right=1cm,0",
            "--non-associative",
            "-o",
            "c.json",
        ],
        "--non-associative needs friction",
    );
    assert!(!d.join("r.json").exists() && !d.join("c.json").exists());
}
