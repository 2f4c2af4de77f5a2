//! Issue 20 ("the first hour") and issue 12 item 4: commands refuse what they cannot do, flags
//! only where they mean something, one rule for --json and -o, spelling aliases, outputs that
//! read well (units, no λ in settlement drawings, subtitles that fit, honest linear fits), and
//! `tilt` draws. Each test is named after the behaviour it pins.

use crate::common::{cwd::ok, cwd::run};
use std::path::{Path, PathBuf};
use std::process::Output;

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-first-hour-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// The command fails, with exactly one line on stderr that starts with `error:` and contains
/// every needle.
fn fails_in_one_line(args: &[&str], needles: &[&str]) -> String {
    let o = run(args);
    assert!(!o.status.success(), "voussoir {args:?} should fail");
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.starts_with("error: "), "{err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: '{n}' not in: {err}");
    }
    assert!(o.stdout.is_empty(), "nothing on stdout");
    err
}

fn arch(dir: &Path, live: &str) -> String {
    let p = dir.join(format!("arch-{live}.json"));
    ok(&["gen", "arch", "--live", live, "-o", p.to_str().unwrap()]);
    p.to_str().unwrap().to_string()
}

fn help(args: &[&str]) -> String {
    stdout(&ok(args))
}

#[test]
fn settle_without_motion_fails_in_one_line() {
    let d = tmpdir("no-motion");
    let a = arch(&d, "full");
    let out = d.join("r.json");
    fails_in_one_line(
        &["settle", &a, "-o", out.to_str().unwrap()],
        &["settle needs a support motion", "--move"],
    );
    assert!(!out.exists(), "no result file");
    // A `fixed` support that does not move is no settlement either.
    fails_in_one_line(&["settle", &a, "--fixed", "right"], &["support motion"]);
}

#[test]
fn tilt_with_crushing_conic_is_refused_in_one_line() {
    let d = tmpdir("crushing");
    let a = arch(&d, "full");
    let err = fails_in_one_line(
        &["tilt", &a, "--crushing", "conic"],
        &["--crushing", "tilt", "`limit`, `settle`, `capacity`"],
    );
    assert!(!err.contains("Usage"), "{err}");
}

#[test]
fn flags_that_do_not_apply_are_absent_from_help_and_refused() {
    let d = tmpdir("flags");
    let a = arch(&d, "full");
    let mv = ["--move", "right=0.01,0"];
    // (command and its required arguments, foreign flag with a value)
    let cases: Vec<(Vec<&str>, [&str; 2])> = vec![
        (vec!["tilt", &a], ["--crushing", "linear"]),
        (
            vec!["capacity", &a, mv[0], mv[1]],
            ["--settlement-form", "both"],
        ),
        (vec!["tilt", &a], ["--facets", "32"]),
        (vec!["tilt", &a], ["--settlement-form", "both"]),
        (vec!["limit", &a], ["--settlement-form", "force-only"]),
        (vec!["limit", &a], ["--move", "right=0.01,0"]),
        (
            vec!["incremental", &a, "--control", "0,3"],
            ["--crushing", "conic"],
        ),
        (
            vec!["incremental", &a, "--control", "0,3"],
            ["--settlement-form", "both"],
        ),
        (
            vec!["sweep", &a, mv[0], mv[1], "--steps", "2"],
            ["--facets", "32"],
        ),
    ];
    for (cmd, [flag, value]) in cases {
        let h = help(&[cmd[0], "--help"]);
        assert!(!h.contains(flag), "`{} --help` offers {flag}", cmd[0]);
        let mut args = cmd.clone();
        args.extend([flag, value]);
        fails_in_one_line(&args, &[flag, "does not apply"]);
    }
    // --forces draws contact forces on a structure: not on the curves of capacity, incremental.
    for cmd in [
        vec!["capacity", &a, mv[0], mv[1], "--forces"],
        vec!["incremental", &a, "--control", "0,3", "--forces"],
    ] {
        assert!(
            !help(&[cmd[0], "--help"]).contains("--forces"),
            "{}",
            cmd[0]
        );
        fails_in_one_line(&cmd, &["--forces", "does not apply"]);
    }
    for cmd in ["limit", "settle", "tilt"] {
        assert!(help(&[cmd, "--help"]).contains("--forces"), "{cmd}");
    }
    // Flags of the settlement before an incremental analysis need --move.
    fails_in_one_line(
        &["incremental", &a, "--control", "0,3", "--keep-fixed"],
        &["--keep-fixed only applies with --move"],
    );
    // ... and present where they are used.
    let h = help(&["limit", "--help"]);
    assert!(h.contains("--crushing") && h.contains("--facets"));
    for cmd in ["settle", "sweep"] {
        assert!(
            help(&[cmd, "--help"]).contains("--settlement-form"),
            "{cmd}"
        );
    }
}

#[test]
fn facets_with_the_exact_cone_are_refused() {
    let d = tmpdir("facets");
    let a = arch(&d, "full");
    fails_in_one_line(
        &["limit", &a, "--crushing", "conic", "--facets", "32"],
        &["--facets", "--crushing linear"],
    );
    fails_in_one_line(&["limit", &a, "--facets", "1"], &["--facets 1", "between"]);
    fails_in_one_line(
        &["limit", &a, "--facets", "5000"],
        &["--facets 5000", "between"],
    );
}

#[test]
fn dxf_flags_are_refused_for_a_json_model() {
    let d = tmpdir("dxf-flags");
    let a = arch(&d, "full");
    fails_in_one_line(&["limit", &a, "--units", "mm"], &["--units", "DXF"]);
    fails_in_one_line(
        &[
            "settle",
            &a,
            "--move",
            "right=0.01,0",
            "--unit-weight",
            "20",
        ],
        &["--unit-weight", "DXF"],
    );
}

#[test]
fn help_lists_own_flags_first_then_headed_shared_groups_with_every_value_described() {
    let h = help(&["settle", "--help"]);
    let at = |s: &str| {
        h.find(s)
            .unwrap_or_else(|| panic!("'{s}' not in settle --help:\n{h}"))
    };
    // Own flags before the shared groups, the groups in a fixed order.
    let own = at("--move");
    let groups = [
        at("Model input:"),
        at("DXF import:"),
        at("Solver:"),
        at("Output:"),
        at("Drawing:"),
    ];
    assert!(own < groups[0], "{h}");
    assert!(groups.windows(2).all(|w| w[0] < w[1]), "{h}");
    assert!(at("--settlement-form") < groups[0]);
    // Every value of every choice has a description (`- value: text` in the long help).
    for (cmd, values) in [
        (
            "limit",
            vec![
                "dual-simplex",
                "primal-simplex",
                "ipm",
                "choose",
                "ipm-no-crossover",
                "pdlp",
                "clarabel",
                "linear",
                "conic",
                "mm",
                "cm",
                "none",
                "horizontal",
            ],
        ),
        ("settle", vec!["both", "force-only"]),
    ] {
        let h = help(&[cmd, "--help"]);
        for v in values {
            let line = format!("- {v}: ");
            assert!(
                h.contains(&line),
                "`{cmd} --help`: value {v} undescribed:\n{h}"
            );
        }
    }
    // `--direction` is no choice but one syntax (issue 32): its help says every form.
    let t = help(&["tilt", "--help"]);
    assert!(
        t.contains("+x, -x, +y, -y, an azimuth in degrees") && t.contains("vector DX,DY"),
        "{t}"
    );
    let g = help(&["gen", "arch", "--help"]);
    for v in [
        "intrados",
        "centreline",
        "extrados",
        "semicircular",
        "pointed",
        "left",
    ] {
        assert!(g.contains(&format!("- {v}: ")), "gen arch: {v}");
    }
    // --json and -o are documented together with their rule.
    assert!(h.contains("--json") && h.contains("-o, --output"));
}

#[test]
fn json_with_output_file_prints_the_json_and_writes_the_same_json() {
    let d = tmpdir("json-o");
    let a = arch(&d, "full");
    let f = d.join("r.json");
    let o = ok(&["limit", &a, "--json", "-o", f.to_str().unwrap()]);
    let file = std::fs::read(&f).unwrap();
    assert_eq!(
        o.stdout, file,
        "--json -o: the same JSON on stdout and in the file"
    );
    serde_json::from_slice::<serde_json::Value>(&file).unwrap();
    // Without --json: the summary on stdout, the JSON in the file.
    std::fs::remove_file(&f).unwrap();
    let o = ok(&["limit", &a, "-o", f.to_str().unwrap()]);
    assert!(stdout(&o).contains("hinges of the collapse mechanism"));
    assert_eq!(std::fs::read(&f).unwrap(), file);
}

#[test]
fn spelling_aliases_engineers_type_are_accepted() {
    let d = tmpdir("aliases");
    let gen = |radius_at: &str| {
        let p = d.join(format!("a-{radius_at}.json"));
        ok(&[
            "gen",
            "arch",
            "--radius-at",
            radius_at,
            "-o",
            p.to_str().unwrap(),
        ]);
        std::fs::read(p).unwrap()
    };
    let reference = gen("centreline");
    for alias in ["centerline", "center-line", "Centreline", "CENTERLINE"] {
        assert_eq!(gen(alias), reference, "--radius-at {alias}");
    }
    assert_ne!(gen("intrados"), reference);
    ok(&["gen", "façade", "--help"]);
    // DXF units spelled out, and method names in upper case.
    let dxf = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../voussoir-io/tests/fixtures/lact3/arch_1.dxf");
    let dxf = dxf.to_str().unwrap();
    let a = ok(&["limit", dxf, "--units", "mm", "--json"]);
    let b = ok(&[
        "limit",
        dxf,
        "--units",
        "millimetres",
        "--method",
        "Dual-Simplex",
        "--json",
    ]);
    assert_eq!(a.stdout, b.stdout);
}

#[test]
fn tilt_draws_png_svg_and_report() {
    let d = tmpdir("tilt");
    let w = d.join("wall.json");
    ok(&[
        "gen",
        "wall",
        "--courses",
        "4",
        "--units",
        "4",
        "-o",
        w.to_str().unwrap(),
    ]);
    let (png, svg, html) = (d.join("t.png"), d.join("t.svg"), d.join("t.html"));
    ok(&[
        "tilt",
        w.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
        "--report",
        html.to_str().unwrap(),
    ]);
    assert_eq!(&std::fs::read(&png).unwrap()[1..4], b"PNG");
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.contains("critical tilt angle α = "),
        "the angle is in the figure"
    );
    assert!(std::fs::read_to_string(&html).unwrap().contains("<svg"));
}

#[test]
fn settlement_drawings_have_no_lambda() {
    let d = tmpdir("no-lambda");
    let a = arch(&d, "full");
    let svg = d.join("s.svg");
    ok(&[
        "settle",
        &a,
        "--move",
        "right=0.01,0",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        !text.contains('λ') && !text.contains("live load"),
        "settlement drawing mentions λ"
    );
    // Nor does its report (figures, captions, model summary).
    let html = d.join("s.html");
    ok(&[
        "settle",
        &a,
        "--move",
        "right=0.01,0",
        "--report",
        html.to_str().unwrap(),
    ]);
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(
        !page.contains("× λ") && !page.contains("multiplied by λ"),
        "settlement report mentions λ"
    );
    assert!(page.contains("not applied (a settlement analysis has no λ)"));
    // The limit drawing of the same model keeps its live loads × λ.
    ok(&["limit", &a, "--svg", svg.to_str().unwrap()]);
    assert!(std::fs::read_to_string(&svg)
        .unwrap()
        .contains("live load × λ"));
}

#[test]
fn many_settling_supports_are_summarised_in_one_subtitle_line() {
    let d = tmpdir("subtitle");
    let w = d.join("wall.json");
    ok(&[
        "gen",
        "wall",
        "--courses",
        "3",
        "--units",
        "6",
        "-o",
        w.to_str().unwrap(),
    ]);
    let svg = d.join("w.svg");
    ok(&[
        "settle",
        w.to_str().unwrap(),
        "--profile",
        "uniform:-10,10,-0.2",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&svg).unwrap();
    let line = text
        .lines()
        .find(|l| l.contains("prescribed support motion"))
        .expect("subtitle");
    assert!(
        line.contains("6 supports (f0 … f5): u = 0 mm, v = -200 mm"),
        "{line}"
    );
}

#[test]
fn incremental_uses_one_length_unit_on_flags_tables_and_plots() {
    let d = tmpdir("incremental-units");
    let a = arch(&d, "left");
    let svg = d.join("i.svg");
    let mm = ok(&[
        "incremental",
        &a,
        "--control",
        "0,3.19",
        "--max",
        "2mm",
        "--step",
        "0.25mm",
        "--json",
    ]);
    let m = ok(&[
        "incremental",
        &a,
        "--control",
        "0,3.19",
        "--max",
        "0.002",
        "--step",
        "0.00025",
        "--json",
    ]);
    assert_eq!(mm.stdout, m.stdout, "2mm is 0.002 m");
    let o = ok(&[
        "incremental",
        &a,
        "--control",
        "0,3.19",
        "--max",
        "2mm",
        "--step",
        "0.25mm",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    let summary = stdout(&o);
    // Issue 32: displacements in cm in the summary (README, "Units in the summaries") and on
    // the plot alike.
    assert!(
        summary.contains("dx (cm)") && !summary.contains(" mm"),
        "{summary}"
    );
    let plot = std::fs::read_to_string(&svg).unwrap();
    assert!(plot.contains("control displacement dx (cm)") && !plot.contains("(mm)"));
    let help = help(&["incremental", "--help"]);
    assert!(
        help.contains("[default: 50mm]") && help.contains("[default: 0.5mm]"),
        "{help}"
    );
    fails_in_one_line(
        &[
            "incremental",
            &a,
            "--control",
            "0,3.19",
            "--max",
            "5 furlongs",
        ],
        &["--max", "50mm"],
    );
}

#[test]
fn incremental_names_the_same_control_block_with_and_without_settlement() {
    // (0, 3.19) is the extrados end of the crown joint, between blocks 31 and 32: the block is
    // chosen on the undeformed arch in both runs.
    let d = tmpdir("control-block");
    let a = arch(&d, "left");
    let block = |extra: &[&str]| -> u64 {
        let mut args = vec![
            "incremental",
            &a,
            "--control",
            "0,3.19",
            "--max",
            "2mm",
            "--json",
        ];
        args.extend_from_slice(extra);
        let v: serde_json::Value = serde_json::from_slice(&ok(&args).stdout).unwrap();
        v["control"]["block"].as_u64().unwrap()
    };
    let perfect = block(&[]);
    let settled = block(&["--settle", "right=0,-0.0025", "--fixed", "right"]);
    assert_eq!(perfect, settled);
    assert_eq!(perfect, 31);
}

#[test]
fn incremental_message_counts_in_the_singular_for_one() {
    let d = tmpdir("plural");
    let a = arch(&d, "left");
    let v: serde_json::Value =
        serde_json::from_slice(&ok(&["incremental", &a, "--control", "0,3.19", "--json"]).stdout)
            .unwrap();
    let m = v["message"].as_str().unwrap();
    assert!(
        m.contains(" 1 closure,") && !m.contains("1 closures"),
        "{m}"
    );
}

#[test]
fn capacity_prints_a_linear_fit_only_where_it_fits() {
    let d = tmpdir("linear-fit");
    // The paper's arch, right springing outwards: λ(s) is nearly straight (≈ 2 % of λ(0)).
    let a = arch(&d, "full");
    let s = stdout(&ok(&[
        "capacity",
        &a,
        "--move",
        "right=0.02,0",
        "--steps",
        "20",
    ]));
    let fit = s
        .lines()
        .find(|l| l.starts_with("linear fit: "))
        .expect("fit");
    assert!(!s.contains("warning"), "{s}");
    let dev: f64 = fit
        .split("largest deviation ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap();
    assert!(dev < 5.0, "{fit}");
    // A lintel with finite compressive strength: λ(s) is curved, so no fit, a warning instead.
    let l = d.join("lintel.json");
    ok(&[
        "gen",
        "lintel",
        "--compressive-strength",
        "1000",
        "-o",
        l.to_str().unwrap(),
    ]);
    let s = stdout(&ok(&[
        "capacity",
        l.to_str().unwrap(),
        "--move",
        "right=0.14,0",
        "--steps",
        "28",
    ]));
    assert!(!s.contains("linear fit:"), "{s}");
    let w = s
        .lines()
        .find(|l| l.starts_with("warning: "))
        .expect("warning");
    assert!(w.contains("not linear") && w.contains("% of λ(0)"), "{w}");
}

#[test]
fn support_motions_take_a_length_unit() {
    let d = tmpdir("motion-units");
    let a = arch(&d, "full");
    let m = ok(&["settle", &a, "--move", "right=0.01,0", "--json"]);
    for spelled in ["right=10mm,0", "right=1cm,0mm", "right=0.01m,0"] {
        let o = ok(&["settle", &a, "--move", spelled, "--json"]);
        assert_eq!(o.stdout, m.stdout, "--move {spelled}");
    }
    fails_in_one_line(
        &["settle", &a, "--move", "right=10 furlongs,0"],
        &["must be numbers"],
    );
}

#[test]
fn every_value_of_every_choice_is_described_in_every_help() {
    let commands: [&[&str]; 14] = [
        &["gen", "arch"],
        &["gen", "lintel"],
        &["gen", "wall"],
        &["gen", "facade"],
        &["import"],
        &["limit"],
        &["settle"],
        &["tilt"],
        &["capacity"],
        &["incremental"],
        &["plot"],
        &["sweep"],
        &["merge"],
        &["bench"],
    ];
    let mut values = 0;
    for cmd in commands {
        let mut args = cmd.to_vec();
        args.push("--help");
        let h = help(&args);
        let mut in_values = false;
        for line in h.lines() {
            let t = line.trim();
            if t == "Possible values:" {
                in_values = true;
                continue;
            }
            if in_values {
                if let Some(v) = t.strip_prefix("- ") {
                    let (name, text) = v.split_once(':').unwrap_or((v, ""));
                    assert!(
                        !text.trim().is_empty(),
                        "`voussoir {}`: value '{name}' has no description",
                        cmd.join(" ")
                    );
                    values += 1;
                } else {
                    in_values = false;
                }
            }
        }
        assert!(
            !h.contains("[possible values:"),
            "{cmd:?}: an undescribed value list"
        );
    }
    assert!(values >= 40, "only {values} values found");
}
