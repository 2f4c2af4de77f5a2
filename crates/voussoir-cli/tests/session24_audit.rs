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

/// A friction coefficient meant as "no sliding" (`--friction 1e10`, `1e300`) put rows of that
/// scale into the programs: on the paper's arch μ = 1e10 gave λ = 0.434623 with 17 hinges and
/// μ = 1e300 a "certified" no-equilibrium, where Heyman's λ is 0.434645. Refused above 1e4
/// (in a model's materials too); at 1e4 the no-sliding answer is kept (the same λ as without
/// friction, to 1e-9).
#[test]
fn friction_above_bound_refused() {
    let d = dir("friction");
    gen_model(&d, "arch --live full -o arch.json");
    for mu in ["1e10", "1e300", "10001"] {
        refused(
            &d,
            &["limit", "arch.json", "--friction", mu, "-o", "r.json"],
            &format!("--friction {}: above 10000", mu.parse::<f64>().unwrap()),
        );
    }
    assert!(!d.join("r.json").exists());
    let heyman = json(&run(&d, &["limit", "arch.json", "--json"]))["load_multiplier"]
        .as_f64()
        .unwrap();
    let rough = json(&run(
        &d,
        &["limit", "arch.json", "--friction", "1e4", "--json"],
    ))["load_multiplier"]
        .as_f64()
        .unwrap();
    assert!((heyman - rough).abs() < 1e-9, "{heyman} vs {rough}");
    // The same bound on a model's own material.
    let mut m = json(&std::fs::read_to_string(d.join("arch.json")).unwrap());
    m["materials"]["default"]["friction"] = serde_json::json!(1e10);
    std::fs::write(d.join("rough.json"), m.to_string()).unwrap();
    refused(
        &d,
        &["limit", "rough.json"],
        "friction 10000000000 is above 10000",
    );
}

/// `--scale`, `--title` and `--forces` without a figure or report to apply to were accepted and
/// ignored (the output was the same with and without them). Refused in one line, before any
/// work (no -o file); with a figure they are honoured (the title is in the SVG).
#[test]
fn drawing_flags_without_a_figure_refused() {
    let d = dir("drawflags");
    gen_model(&d, "arch --live full -o arch.json");
    refused(
        &d,
        &["limit", "arch.json", "--scale", "5", "-o", "r.json"],
        "--scale shapes the --svg/--png drawing and the --report",
    );
    refused(
        &d,
        &[
            "settle",
            "arch.json",
            "--move",
            "right=1cm,0",
            "--title",
            "T",
            "-o",
            "r.json",
        ],
        "--title shapes the --svg/--png drawing and the --report",
    );
    refused(
        &d,
        &["tilt", "arch.json", "--forces", "-o", "r.json"],
        "--forces draws arrows on the --svg/--png drawing",
    );
    refused(
        &d,
        &["limit", "arch.json", "--forces", "--report", "r.html"],
        "--forces draws arrows on the --svg/--png drawing",
    );
    assert!(!d.join("r.json").exists() && !d.join("r.html").exists());
    run(
        &d,
        &[
            "limit",
            "arch.json",
            "--forces",
            "--title",
            "My arch",
            "--svg",
            "a.svg",
        ],
    );
    let svg = std::fs::read_to_string(d.join("a.svg")).unwrap();
    assert!(svg.contains("My arch"));
}

/// `safety --bisection-tolerance 1e-300` never ended (minutes of LPs until killed: the
/// interval on the joint fraction cannot halve below a double's resolution). Refused below
/// 1e-12, in `least-thickness` too; 1e-12 itself is accepted.
#[test]
fn bisection_tolerance_floor() {
    let d = dir("bisect");
    gen_model(&d, "arch --live full -o arch.json");
    refused(
        &d,
        &["safety", "arch.json", "--bisection-tolerance", "1e-300"],
        "below 1e-12, finer than the bisection can resolve",
    );
    refused(
        &d,
        &["least-thickness", "arch", "--bisection-tolerance", "1e-13"],
        "below 1e-12",
    );
}

/// `sweep --magnitudes 3 --cov 0.2 --seed 5 --capacity-steps 10` wrote the very lines of
/// `sweep --magnitudes 3`: the Monte Carlo options and the capacity curves' intervals were
/// accepted and ignored. Each is refused where it has no effect; with `--samples` the seed is
/// honoured (another seed, other samples).
#[test]
fn sweep_options_of_another_mode_refused() {
    let d = dir("sweep");
    gen_model(&d, "arch --live full -o arch.json");
    let base = ["sweep", "arch.json", "--move", "right=1cm,0"];
    let with = |extra: &[&str]| -> Vec<String> {
        base.iter().chain(extra).map(|s| s.to_string()).collect()
    };
    for (extra, needle) in [
        (
            &["--magnitudes", "3", "--cov", "0.2"][..],
            "--cov 0.2: applies to the Monte Carlo samples of --samples N only",
        ),
        (
            &["--angles", "4", "--seed", "5"][..],
            "--seed 5: applies to the Monte Carlo samples",
        ),
        (
            &["--magnitudes", "3", "--capacity-steps", "10"][..],
            "--capacity-steps 10: the intervals of the capacity curves of --capacity",
        ),
    ] {
        let mut args = with(extra);
        args.extend(["--jsonl".to_string(), "s.jsonl".to_string()]);
        let args: Vec<&str> = args.iter().map(|s| s.as_str()).collect();
        refused(&d, &args, needle);
        assert!(!d.join("s.jsonl").exists());
    }
    let sample = |seed: &str, file: &str| {
        let mut args = with(&["--samples", "2", "--seed", seed, "--jsonl", file]);
        args.push("--threads".into());
        args.push("1".into());
        let args: Vec<&str> = args.iter().map(|s| s.as_str()).collect();
        run(&d, &args);
        std::fs::read_to_string(d.join(file)).unwrap()
    };
    assert_ne!(sample("5", "a.jsonl"), sample("6", "b.jsonl"));
}

/// `incremental --raw` without a settlement was accepted and ignored (the same curve, the same
/// JSON): it chooses the settlement's mechanism, and without one the steps follow the solver's
/// mechanism anyway. Refused in one line; with `--move` it is honoured (no `canonical`
/// record). A `--max` far beyond the step bound printed 300-digit numbers: now in e-notation.
#[test]
fn incremental_raw_without_settlement_refused() {
    let d = dir("incraw");
    gen_model(&d, "arch --live left -o half.json");
    let base = [
        "incremental",
        "half.json",
        "--control",
        "0,3.19",
        "--max",
        "1mm",
        "--step",
        "0.2mm",
    ];
    let mut a = base.to_vec();
    a.extend(["--raw", "-o", "r.json"]);
    refused(&d, &a, "--raw chooses the solver's own settlement mechanism and only applies with --move or --profile");
    assert!(!d.join("r.json").exists());
    let mut a = base.to_vec();
    a.extend([
        "--move",
        "right=0,-2.5mm",
        "--fixed",
        "right",
        "--raw",
        "--json",
    ]);
    let r = json(&run(&d, &a));
    assert!(r.get("canonical").is_none());
    let o = crate::common::refusal(
        &d,
        &[
            "incremental",
            "half.json",
            "--control",
            "0,3.19",
            "--max",
            "1e300",
        ],
    );
    assert!(
        o.contains("a largest displacement of 1.000e300 m in steps of 0.0005 m takes 2.000e303 steps, more than the bound of 100000"),
        "{o}"
    );
}

/// `sweep … -o FILE` and `merge … -o FILE` were refused with clap's tip "to pass '-o' as a
/// value, use '-- -o'", which is wrong: these commands write `--jsonl` and `--csv`. The refusal
/// now says where their results go.
#[test]
fn sweep_and_merge_output_flag_says_where_results_go() {
    let d = dir("sweepo");
    gen_model(&d, "arch --live full -o arch.json");
    refused(
        &d,
        &["sweep", "arch.json", "--move", "right=1cm,0", "--magnitudes", "2", "-o", "s.jsonl"],
        "-o does not apply to `voussoir sweep`: its results go to --jsonl FILE (JSON lines) and --csv FILE",
    );
    refused(
        &d,
        &["merge", "a.jsonl", "b.jsonl", "--output", "m.jsonl"],
        "--output does not apply to `voussoir merge`: its results go to --jsonl FILE",
    );
    assert!(!d.join("s.jsonl").exists() && !d.join("m.jsonl").exists());
}

/// The paper's arch scaled by 1e-6 (every length; γ and the live load per m² kept): dead loads
/// scale as L², the live load as L, so λ scales as L: 0.434645 × 1e-6. The summary printed
/// "λ = 0.000000" (six decimals); it now prints six significant digits, and the JSON's value is
/// the scaled one.
#[test]
fn small_multiplier_printed_as_itself() {
    let d = dir("smalllambda");
    gen_model(
        &d,
        "arch --radius 2.86e-6 --thickness 0.33e-6 --radius-at intrados --voussoirs 64 --unit-weight 18 --live full --live-load 1 -o tiny.json",
    );
    gen_model(
        &d,
        "arch --radius 2.86 --thickness 0.33 --radius-at intrados --voussoirs 64 --unit-weight 18 --live full --live-load 1 -o arch.json",
    );
    let l = json(&run(&d, &["limit", "arch.json", "--json"]))["load_multiplier"]
        .as_f64()
        .unwrap();
    let r = json(&run(&d, &["limit", "tiny.json", "--json"]));
    let t = r["load_multiplier"].as_f64().unwrap();
    assert!((t / (l * 1e-6) - 1.0).abs() < 1e-5, "{t} vs {l}e-6");
    let line = run(&d, &["limit", "tiny.json"])
        .lines()
        .nth(1)
        .unwrap()
        .to_string();
    assert_eq!(line, format!("collapse load multiplier λ = {t:.6e}"));
    assert!(line.ends_with("e-7"), "{line}");
}
