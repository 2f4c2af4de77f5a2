//! Issue 32, item 3 ("a report to sign") for the reports of `safety` (2D and 3D, its new
//! `--report`), `incremental`, `identify` and `sweep --capacity`: each opens with the hypotheses
//! and the echo of the inputs (a value given on the command line appears with its unit), its
//! results have units (mm for openings, cm for motions), and it is byte-identical from one run
//! to the next. The safety report states the geometric safety factor (and its definition) equal
//! to the result JSON's value to the printed digits, and the reaction ranges of the JSON.
//!
//! References: the arch's total weight by hand (16 voussoirs between circles of radius 2.86 and
//! 3.19 m, each a trapezoid of area ½·sin(π/16)·(Re² − Ri²), γ = 18 kN/m³), the unit
//! conversions of the values given on the command line, and the JSON written by the same run.

use crate::common;
use crate::common::cwd::ok;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("issue32r2", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The paper's arch: 16 voussoirs, intrados radius 2.86 m, thickness 0.33 m, γ = 18 kN/m³.
fn arch(d: &Path, live: &str) -> String {
    let p = d.join(format!("arch-{live}.json"));
    ok(&[
        "gen",
        "arch",
        "--radius",
        "2.86",
        "--radius-at",
        "intrados",
        "--thickness",
        "0.33",
        "--voussoirs",
        "16",
        "--unit-weight",
        "18",
        "--live",
        live,
        "-o",
        s(&p),
    ]);
    s(&p).to_string()
}

/// W of the arch by hand (kN).
fn arch_weight() -> f64 {
    let (ri, re) = (2.86f64, 3.19f64);
    18.0 * 16.0 * 0.5 * (std::f64::consts::PI / 16.0).sin() * (re * re - ri * ri)
}

/// The value cell of the key–value row `key` (HTML-escaped text).
fn kv<'a>(html: &'a str, key: &str) -> &'a str {
    let at = format!("<th>{key}</th><td>");
    let rest = html
        .split(&at)
        .nth(1)
        .unwrap_or_else(|| panic!("no row {key:?} in the report"));
    &rest[..rest.find("</td>").unwrap()]
}

/// The body rows of the first table after `heading`.
fn table_after(html: &str, heading: &str) -> Vec<Vec<String>> {
    let at = html
        .find(heading)
        .unwrap_or_else(|| panic!("no {heading:?} in the report"));
    let rest = &html[at..];
    let t = &rest[rest.find("<tbody>").unwrap()..rest.find("</tbody>").unwrap()];
    t.split("<tr")
        .skip(1)
        .map(|r| {
            r.split("<td>")
                .skip(1)
                .map(|c| c[..c.find("</td>").unwrap()].to_string())
                .collect()
        })
        .collect()
}

/// `printed` is `x` to its printed digits (at most `decimals` after the point, trailing zeros
/// dropped): |printed − x| ≤ half a unit of the last printed place.
fn same_to_printed_digits(printed: &str, x: f64, decimals: usize) {
    let places = printed.split('.').nth(1).map_or(0, str::len);
    assert!(
        places <= decimals,
        "{printed:?}: more than {decimals} decimals"
    );
    assert_eq!(
        printed,
        {
            let t = format!("{x:.decimals$}");
            let t = if t.contains('.') {
                t.trim_end_matches('0').trim_end_matches('.').to_string()
            } else {
                t
            };
            t
        },
        "printed {printed:?}, the JSON's {x}"
    );
    assert!((num(printed) - x).abs() <= 0.5 * 10f64.powi(-(decimals as i32)) * (1.0 + 1e-9));
}

fn num(c: &str) -> f64 {
    c.trim()
        .parse()
        .unwrap_or_else(|_| panic!("not a number: {c:?}"))
}

/// Hypotheses and inputs precede the results, in this order; the title block names the
/// analysis; the sign-off closes the report.
fn check_front_matter(html: &str, command: &str) {
    let order = [
        "<h2>Hypotheses</h2>",
        "Rigid blocks: the blocks do not deform",
        "No tension: a joint transmits compression only",
        "<h2>Inputs</h2>",
        "<h3>Geometry</h3>",
        "<h3>Materials</h3>",
        "<h3>Loads</h3>",
        "<h3>Supports and prescribed motions</h3>",
        "<h3>Settings of the analysis</h3>",
        "<h3>Solver, tolerances and certificate</h3>",
        "<h2>Results</h2>",
        "<h2>Sign-off</h2>",
    ];
    let mut at = 0;
    for w in order {
        let i = html[at..]
            .find(w)
            .unwrap_or_else(|| panic!("{command}: {w:?} missing or out of order"));
        at += i;
    }
    assert!(
        html.contains(&format!("<th>analysis</th><td>{command}</td>")),
        "{command}: the title block names the analysis"
    );
    // The backend that answered (safety's decisions may be answered by Clarabel's certified
    // elastic program: lp::sequence::decide_feasibility).
    let solver = kv(html, "solver");
    assert!(
        solver.starts_with("highs (") || (command == "safety" && solver.starts_with("clarabel (")),
        "{command}: {solver}"
    );
    assert!(
        kv(html, "joint detection").starts_with("1e-7 × "),
        "{command}"
    );
}

/// A support's row in the inputs' table of supports and prescribed motions.
fn support_row(html: &str, name: &str) -> Vec<String> {
    table_after(html, "<h3>Supports and prescribed motions</h3>")
        .into_iter()
        .find(|r| r[0] == name)
        .unwrap_or_else(|| panic!("no support {name} in the inputs"))
}

/// Run `args` (which write `report`) twice: the report is byte-identical.
fn twice(args: &[&str], report: &Path) -> String {
    ok(args);
    let a = std::fs::read(report).unwrap();
    ok(args);
    let b = std::fs::read(report).unwrap();
    assert!(a == b, "{args:?}: the report differs between two runs");
    String::from_utf8(a).unwrap()
}

#[test]
fn issue32_item3_safety_report_2d_states_the_safety_factor_of_the_json() {
    let d = tmpdir("safety2d");
    let a = arch(&d, "none");
    let report = d.join("safety.html");
    let args = [
        "safety",
        &a,
        "--friction",
        "0.6",
        "--compressive-strength",
        "4000",
        "--report",
        s(&report),
        "--json",
    ];
    let html = twice(&args, &report);
    let json: Value = serde_json::from_slice(&ok(&args).stdout).unwrap();
    check_front_matter(&html, "safety");
    // The values of the command line, with their units.
    assert!(html.contains("Coulomb friction: μ = 0.6 (17 joints)"));
    assert!(html.contains("Finite compressive strength: f_c = 4000 kPa (17 joints)"));
    assert!(html.contains("Static (lower-bound, safe) theorem"));
    assert!(
        html.contains("Drucker"),
        "the static theorem's caveat with friction"
    );
    // The total weight by hand, echoed in kN.
    let w = kv(&html, "total weight W (vertical dead load)");
    let w = num(w.strip_suffix(" kN").expect("in kN"));
    assert!(
        (w - arch_weight()).abs() <= 1e-6 * w,
        "W {w}, by hand {}",
        arch_weight()
    );
    // The safety factor, to the printed digits (6 decimals), and its definition.
    let g = json["geometric_safety_factor"].as_f64().expect("a factor");
    let f = json["least_joint_fraction"].as_f64().unwrap();
    assert!(g > 1.0 && (g * f - 1.0).abs() < 1e-12);
    same_to_printed_digits(
        kv(
            &html,
            "geometric safety factor (Heyman) = 1 / least joint fraction",
        ),
        g,
        6,
    );
    let printed = kv(&html, "least joint fraction");
    same_to_printed_digits(printed.strip_suffix(" %").expect("in %"), 100.0 * f, 4);
    assert!(html.contains("Geometric safety factor: every joint is shrunk about its centre"));
    // The reaction ranges of the JSON, in kN.
    let rows = table_after(&html, "<h3>Admissible support reactions");
    let mut n = 0;
    for re in json["reactions"].as_array().unwrap() {
        for c in re["components"].as_array().unwrap() {
            let row = &rows[n];
            assert_eq!(row[0], re["support"].as_str().unwrap());
            assert_eq!(row[1], c["component"].as_str().unwrap());
            same_to_printed_digits(&row[2], c["min"].as_f64().unwrap(), 6);
            same_to_printed_digits(&row[3], c["max"].as_f64().unwrap(), 6);
            n += 1;
        }
    }
    assert_eq!(n, rows.len());
    assert_eq!(n, 4, "fx and fy of two supports");
    // The left support's vertical reaction brackets W/2 (a symmetric arch).
    assert!(num(&rows[1][2]) <= w / 2.0 + 1e-6 && num(&rows[1][3]) >= w / 2.0 - 1e-6);
}

#[test]
fn issue32_item3_safety_report_3d_echoes_the_vault_and_its_factor() {
    let d = tmpdir("safety3d");
    let vault = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../voussoir-io/tests/fixtures/vault3d.json"
    );
    let report = d.join("safety3d.html");
    let args = [
        "safety",
        vault,
        "--no-ranges",
        "--bisection-tolerance",
        "1e-5",
        "--report",
        s(&report),
        "--json",
    ];
    let html = twice(&args, &report);
    let json: Value = serde_json::from_slice(&ok(&args).stdout).unwrap();
    check_front_matter(&html, "safety");
    assert!(kv(&html, "size").ends_with("(3D)"));
    assert_eq!(
        kv(&html, "bisection tolerance (--bisection-tolerance)"),
        "1e-5 (absolute, on the joint fraction)"
    );
    assert_eq!(kv(&html, "reaction ranges"), "not computed (--no-ranges)");
    assert!(html.contains("Reaction ranges: not computed (--no-ranges)."));
    let g = json["geometric_safety_factor"].as_f64().expect("a factor");
    same_to_printed_digits(
        kv(
            &html,
            "geometric safety factor (Heyman) = 1 / least joint fraction",
        ),
        g,
        6,
    );
    // The supports' motions in 3D: u, v, w in mm and three rotations in degrees.
    assert!(html.contains("<th>w (mm)</th><th>θx (°)</th>"));
}

#[test]
fn issue32_item3_incremental_report_echoes_its_lengths_in_cm() {
    let d = tmpdir("incremental");
    let a = arch(&d, "left");
    let report = d.join("inc.html");
    let args = [
        "incremental",
        &a,
        "--control",
        "0,3",
        "--max",
        "30mm",
        "--step",
        "1mm",
        "--move",
        "right=5mm,0",
        "--report",
        s(&report),
        "--json",
    ];
    let html = twice(&args, &report);
    let json: Value = serde_json::from_slice(&ok(&args).stdout).unwrap();
    check_front_matter(&html, "incremental");
    assert!(html.contains("Finite displacements: the live loads grow with λ"));
    // 30 mm and 1 mm as the README's cm; the settlement of --move in the supports' table (mm).
    assert_eq!(
        kv(&html, "largest control displacement (--max)"),
        "3.0000 cm"
    );
    assert_eq!(kv(&html, "step (--step)"), "0.1000 cm");
    let right = support_row(&html, "right");
    assert_eq!(num(&right[2]), 5.0, "u (mm) of the right support");
    assert!(html.contains("live loads (multiplied by λ)"));
    // Results: the peak λ of the JSON to 6 decimals, the final displacement in cm.
    let peak = json["peak_load_multiplier"].as_f64().unwrap();
    same_to_printed_digits(kv(&html, "peak load multiplier"), peak, 6);
    let last = json["curve"].as_array().unwrap().last().unwrap()["displacement"]
        .as_f64()
        .unwrap();
    assert!(kv(&html, "final control displacement").starts_with(&format!("{:.4} cm", last * 100.0)));
}

#[test]
fn issue32_item3_identify_report_echoes_the_known_motion_and_gives_the_unknown_in_cm() {
    let d = tmpdir("identify");
    let a = arch(&d, "none");
    // The cracks of a forward settlement: right support 10 mm out, left 2 mm down.
    let f = ok(&[
        "settle",
        &a,
        "--move",
        "right=0.01,0",
        "--move",
        "left=0,-0.002",
        "--json",
    ]);
    let v: Value = serde_json::from_slice(&f.stdout).unwrap();
    let mut cracks = Vec::new();
    for j in v["joints"].as_array().unwrap() {
        for p in j["points"].as_array().unwrap() {
            let w = p["opening"].as_f64().unwrap();
            if w > 1e-9 {
                cracks.push(serde_json::json!({"at": [p["x"], p["y"]], "opening": w}));
            }
        }
    }
    let obs = d.join("obs.json");
    std::fs::write(
        &obs,
        serde_json::json!({"tolerance": 1e-4, "cracks": cracks}).to_string(),
    )
    .unwrap();
    let report = d.join("id.html");
    let args = [
        "identify",
        &a,
        "--cracks",
        s(&obs),
        "--unknown",
        "right=u[0:]",
        "--move",
        "left=0,-2mm",
        "--report",
        s(&report),
        "--json",
    ];
    let html = twice(&args, &report);
    let json: Value = serde_json::from_slice(&ok(&args).stdout).unwrap();
    check_front_matter(&html, "identify");
    assert!(html.contains("Inverse settlement analysis: the unknown support motions"));
    // The inputs: the known motion (−2 mm), not the identified one; the unknown as given.
    assert_eq!(num(&support_row(&html, "left")[3]), -2.0, "v (mm) of left");
    assert_eq!(
        num(&support_row(&html, "right")[2]),
        0.0,
        "u of right is unknown"
    );
    assert_eq!(kv(&html, "unknowns (--unknown; m and rad)"), "right=u[0:]");
    // The identified unknown in cm, the JSON's value (≈ 1 cm) to 4 decimals.
    let u = json["unknowns"][0]["value"].as_f64().unwrap();
    assert!((u - 0.01).abs() < 1e-6, "identified {u} m");
    assert!(kv(&html, "unknown right.u").starts_with(&format!("{:.4} cm", u * 100.0)));
    // Observed and predicted widths in mm (3 decimals), the observation tolerance 0.1 mm.
    let rows = table_after(&html, "Observed against predicted widths (mm)");
    assert_eq!(rows.len(), json["observations"].as_array().unwrap().len());
    for (row, o) in rows.iter().zip(json["observations"].as_array().unwrap()) {
        assert_eq!(
            row[4],
            format!("{:.3}", o["observed"].as_f64().unwrap() * 1e3)
        );
        assert_eq!(row[7], "0.100");
    }
    // The forward analysis' crack table in mm follows, once; the hypotheses are not repeated.
    assert!(html.contains("<th>width (mm)</th><th>length (mm)</th>"));
    assert_eq!(html.matches("<h2>Hypotheses</h2>").count(), 1);
    assert_eq!(html.matches("<h2>Inputs</h2>").count(), 1);
}

#[test]
fn issue32_item3_sweep_report_echoes_the_profile_and_the_monte_carlo() {
    let d = tmpdir("sweep");
    let wall = d.join("wall.json");
    ok(&[
        "gen",
        "wall",
        "--courses",
        "5",
        "--units",
        "4",
        "--live",
        "horizontal",
        "-o",
        s(&wall),
    ]);
    let (jl, report) = (d.join("mc.jsonl"), d.join("mc.html"));
    let args = [
        "sweep",
        s(&wall),
        "--profile",
        "uniform:0.8,1.7,-0.01",
        "--samples",
        "12",
        "--cov",
        "0.25",
        "--seed",
        "3",
        "--capacity",
        "--capacity-steps",
        "4",
        "--threads",
        "1",
        "--jsonl",
        s(&jl),
        "--report",
        s(&report),
    ];
    let html = twice(&args, &report);
    check_front_matter(&html, "sweep --capacity");
    assert!(html.contains("Each analysis of the sweep is a settlement"));
    assert_eq!(
        kv(&html, "sweep"),
        "Monte Carlo (--samples 12): coefficient of variation 0.25 (--cov), seed 3 (--seed)"
    );
    assert_eq!(
        kv(&html, "capacity curve of each analysis (--capacity-steps)"),
        "4 intervals"
    );
    assert_eq!(
        kv(&html, "base settlement profile (--profile)"),
        "uniform:0.8,1.7,-0.01"
    );
    // The profile's 10 mm drop on the supports between x = 0.8 and 1.7 m, in mm.
    let dropped: Vec<Vec<String>> = table_after(&html, "<h3>Supports and prescribed motions</h3>")
        .into_iter()
        .filter(|r| num(&r[3]) == -10.0)
        .collect();
    assert!(!dropped.is_empty(), "a support settles by −10 mm");
    assert!(html.contains("live loads (multiplied by λ)"));
    // Results: the records' settlements in cm, from the JSON lines.
    let settlements: Vec<f64> = std::fs::read_to_string(&jl)
        .unwrap()
        .lines()
        .map(|l| {
            serde_json::from_str::<Value>(l).unwrap()["capacity"]["max_settlement"]
                .as_f64()
                .unwrap()
        })
        .collect();
    assert_eq!(settlements.len(), 12);
    let lo = settlements.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = settlements.iter().copied().fold(0.0, f64::max);
    assert_eq!(
        kv(
            &html,
            "largest support settlement of a record: least / largest"
        ),
        format!("{:.4} cm / {:.4} cm", lo * 100.0, hi * 100.0)
    );
}

#[test]
fn issue32_item3_a_saved_safety_result_reports_that_its_inputs_are_not_recorded() {
    let d = tmpdir("plot");
    let a = arch(&d, "none");
    let saved = d.join("safety.json");
    ok(&["safety", &a, "-o", s(&saved)]);
    let report = d.join("plot.html");
    let html = twice(&["plot", s(&saved), "-o", s(&report)], &report);
    assert!(html.contains("<h2>Hypotheses</h2>"));
    assert!(html.contains(
        "The model (geometry, materials, loads, supports) is not recorded with this result"
    ));
    assert!(html.contains("Joint laws (friction, compressive strength): not recorded"));
    assert!(html.contains("<h2>Results</h2>"));
}
