//! Issue 32, item 3 ("a report to sign") through the CLI: the HTML report of a 2D and of a 3D
//! settlement states the hypotheses (the joint laws actually in force), echoes the inputs with
//! their units, and has a reaction table whose vertical reactions sum to the total weight and a
//! crack table in millimetres whose widths are the result's openings × 1000; it is
//! byte-identical from one run to the next.
//!
//! References: the total weight by hand (a voussoir between two circles, cut by two radial
//! planes, is a trapezoid of area ½·sin(π/n)·(Re² − Ri²)), the joints' depths (a hinge opens a
//! 2D joint over its whole depth, a 3D vault joint over the vault's whole length), and the
//! result JSON written by the same run.

use crate::common;
use crate::common::cwd::ok;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("issue32", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The cells of a table's body and footer rows: the first `<table>` after `heading`.
fn table_after(html: &str, heading: &str) -> (Vec<Vec<String>>, Vec<Vec<String>>) {
    let at = html
        .find(heading)
        .unwrap_or_else(|| panic!("no {heading:?} in the report"));
    let rest = &html[at..];
    let end = rest.find("</table>").expect("table ends");
    let t = &rest[..end];
    let rows = |part: &str| -> Vec<Vec<String>> {
        part.split("<tr")
            .skip(1)
            .map(|r| {
                r.split("<td>")
                    .skip(1)
                    .map(|c| c[..c.find("</td>").unwrap()].to_string())
                    .collect()
            })
            .collect()
    };
    let body = &t[t.find("<tbody>").expect("tbody")..t.find("</tbody>").unwrap()];
    let foot = t.find("<tfoot>").map(|i| rows(&t[i..])).unwrap_or_default();
    (rows(body), foot)
}

fn num(c: &str) -> f64 {
    c.parse()
        .unwrap_or_else(|_| panic!("not a number in the table: {c:?}"))
}

/// The joints of a result that are not closed, with their largest opening (m).
fn open_joints(result: &Value) -> Vec<(u64, f64)> {
    result["joints"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|j| j["state"] != "closed")
        .map(|j| {
            let w = j["points"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| p["opening"].as_f64().unwrap())
                .fold(0.0, f64::max);
            (j["id"].as_u64().unwrap(), w)
        })
        .collect()
}

/// The crack table's rows against the result: one row per joint that is not closed, its width
/// (mm, 4 significant digits) the largest opening × 1000, its length (mm) `length_mm`.
fn check_cracks(html: &str, result: &Value, dim: usize, length_mm: f64) {
    let (rows, _) = table_after(html, "<h3>Cracked joints");
    let open = open_joints(result);
    assert!(open.len() >= 3, "a settlement mechanism opens 3 hinges");
    assert_eq!(rows.len(), open.len(), "one row per cracked joint");
    let head = &html[html.find("<h3>Cracked joints").unwrap()..];
    let head = &head[..head.find("</thead>").unwrap()];
    assert!(
        head.contains("<th>width (mm)</th><th>length (mm)</th>"),
        "{head}"
    );
    for (row, (id, w)) in rows.iter().zip(&open) {
        assert_eq!(num(&row[0]) as u64, *id);
        let width = num(&row[3 + dim]);
        let expected = w * 1000.0;
        assert!(
            (width - expected).abs() <= 5e-4 * expected,
            "joint {id}: width {width} mm, the result's opening × 1000 is {expected}"
        );
        let length = num(&row[4 + dim]);
        assert!(
            (length - length_mm).abs() <= 5e-4 * length_mm,
            "joint {id}: length {length} mm, expected {length_mm}"
        );
    }
}

/// The reactions' vertical column (index `col`) sums to `w` (kN) within 1e-6, row by row and
/// in the footer's total.
fn check_reactions(html: &str, col: usize, w: f64) {
    let (rows, foot) = table_after(html, "<h3>Support reactions");
    assert!(rows.len() >= 2);
    let sum: f64 = rows.iter().map(|r| num(&r[col])).sum();
    assert!(
        (sum - w).abs() <= 1e-6 * w,
        "Σ vertical reactions {sum} kN, total weight by hand {w} kN"
    );
    assert_eq!(foot.len(), 1);
    assert_eq!(foot[0][0], "total");
    let total = num(&foot[0][col]);
    assert!((total - w).abs() <= 1e-6 * w, "total row {total}, W {w}");
    // The total weight echoed in the inputs, with its unit.
    let echoed = html
        .split("<th>total weight W (vertical dead load)</th><td>")
        .nth(1)
        .expect("total weight in the inputs");
    let echoed = &echoed[..echoed.find(" kN</td>").expect("in kN")];
    assert!((num(echoed) - w).abs() <= 1e-6 * w, "{echoed} vs {w}");
}

/// Sections every report opens with, in order.
fn check_sections(html: &str) {
    let order = [
        "<h2>Hypotheses</h2>",
        "<h2>Inputs</h2>",
        "<h2>Results</h2>",
        "<h2>Sign-off</h2>",
    ];
    let at: Vec<usize> = order
        .iter()
        .map(|h| html.find(h).unwrap_or_else(|| panic!("{h} missing")))
        .collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]), "{order:?} out of order");
    for h in [
        "Rigid blocks",
        "No tension",
        "<h3>Materials</h3>",
        "<h3>Loads</h3>",
        "<h3>Supports and prescribed motions</h3>",
        "<h3>Solver, tolerances and certificate</h3>",
        "<th>solver</th>",
        "<th>fallback</th>",
        "<th>joint detection</th><td>1e-7 × the model&#39;s bounding-box diagonal (default)</td>",
        "certified (≤ 1e-7)",
        // The date and the signatures are left to fill in (no clock in the file).
        "<th>date</th><td class=\"blank\"></td>",
        "<th>checked by</th><td class=\"blank\"></td>",
        "@media print",
        "size:A4",
    ] {
        assert!(html.contains(h), "{h} missing");
    }
}

#[test]
fn issue32_item3_report_of_a_2d_settlement() {
    let d = tmpdir("2d");
    let model = d.join("arch.json");
    ok(&["gen", "arch", "--voussoirs", "16", "-o", s(&model)]);
    // Unit weight 22.5 kN/m³ and width 0.8 m: not the defaults, so their echo is the model's.
    let mut m: Value = serde_json::from_str(&std::fs::read_to_string(&model).unwrap()).unwrap();
    m["materials"] = serde_json::json!({"default": {"unit_weight": 22.5, "width": 0.8}});
    std::fs::write(&model, m.to_string()).unwrap();
    let (html_a, html_b, json) = (d.join("a.html"), d.join("b.html"), d.join("r.json"));
    let mv = "right=0.01,-0.02";
    ok(&[
        "settle",
        s(&model),
        "--move",
        mv,
        "--report",
        s(&html_a),
        "-o",
        s(&json),
    ]);
    ok(&["settle", s(&model), "--move", mv, "--report", s(&html_b)]);
    let html = std::fs::read_to_string(&html_a).unwrap();
    assert_eq!(
        html.as_bytes(),
        std::fs::read(&html_b).unwrap().as_slice(),
        "the same input gives the same bytes"
    );
    let result: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    check_sections(&html);
    // No friction given: the hypothesis is Heyman's no sliding, over every joint of the result.
    let joints = result["joints"].as_array().unwrap().len();
    assert!(html.contains(&format!(
        "No sliding: no friction coefficient is given, so every joint ({joints}) resists any shear"
    )));
    assert!(html.contains("Infinite compressive strength: no crushing"));
    // The inputs with their units: the unit weight and width in the materials table, the
    // support motion of --move in mm.
    assert!(html.contains("<th>unit weight γ (kN/m³)</th><th>width (m)</th>"));
    assert!(html.contains("<tr><td>default</td><td>16</td><td>22.5</td><td>0.8</td>"));
    assert!(html.contains("<th>u (mm)</th><th>v (mm)</th><th>θ (°)</th>"));
    assert!(
        html.contains("<tr><td>right</td><td>contact</td><td>10</td><td>-20</td><td>0</td></tr>")
    );
    assert!(html.contains("<tr><td>left</td><td>contact</td><td>0</td><td>0</td><td>0</td></tr>"));

    // W by hand: 16 trapezoids between the intrados (2.86 m) and the extrados (3.19 m).
    let (ri, re, n): (f64, f64, f64) = (2.86, 2.86 + 0.33, 16.0);
    let w = 22.5 * 0.8 * n * 0.5 * (std::f64::consts::PI / n).sin() * (re * re - ri * ri);
    check_reactions(&html, 2, w);
    // A 2D hinge opens its joint over the whole depth: the ring's thickness, 330 mm.
    check_cracks(&html, &result, 2, 330.0);

    // With friction the hypothesis is Coulomb's, associative, with the μ of every joint.
    ok(&[
        "settle",
        s(&model),
        "--move",
        mv,
        "--friction",
        "0.6",
        "--report",
        s(&html_b),
    ]);
    let f = std::fs::read_to_string(&html_b).unwrap();
    assert!(
        f.contains(&format!(
            "Coulomb friction: μ = 0.6 ({joints} joints). Associative (normality)"
        )),
        "{}",
        &f[f.find("<h2>Hypotheses").unwrap()..f.find("<h2>Inputs").unwrap()]
    );
}

#[test]
fn issue32_item3_report_of_a_3d_settlement() {
    let d = tmpdir("3d");
    let fixture =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../voussoir-io/tests/fixtures/vault3d.json");
    let model = d.join("vault.json");
    let mut m: Value = serde_json::from_str(&std::fs::read_to_string(&fixture).unwrap()).unwrap();
    m["materials"] = serde_json::json!({"default": {"unit_weight": 24.0}});
    std::fs::write(&model, m.to_string()).unwrap();
    let (html_a, html_b, json) = (d.join("a.html"), d.join("b.html"), d.join("r.json"));
    let mv = "right=0.02,0,-0.01";
    ok(&[
        "settle",
        s(&model),
        "--move",
        mv,
        "--report",
        s(&html_a),
        "-o",
        s(&json),
    ]);
    ok(&["settle", s(&model), "--move", mv, "--report", s(&html_b)]);
    let html = std::fs::read_to_string(&html_a).unwrap();
    assert_eq!(
        html.as_bytes(),
        std::fs::read(&html_b).unwrap().as_slice(),
        "the same input gives the same bytes"
    );
    let result: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    check_sections(&html);
    assert!(html.contains("No sliding: no friction coefficient is given"));
    assert!(html.contains("<th>unit weight γ (kN/m³)</th><th>compressive strength"));
    assert!(html.contains("<tr><td>default</td><td>7</td><td>24</td>"));
    assert!(html.contains(
        "<th>u (mm)</th><th>v (mm)</th><th>w (mm)</th><th>θx (°)</th><th>θy (°)</th><th>θz (°)</th>"
    ));
    assert!(html.contains(
        "<tr><td>right</td><td>contact</td><td>20</td><td>0</td><td>-10</td><td>0</td><td>0</td><td>0</td></tr>"
    ));
    // The interactive view is not printed; the static drawing is.
    assert!(html.contains("<section id=\"view\" class=\"screen-only\">"));

    // W by hand: 7 voussoirs between radii 1.85 and 2.15 m, 1 m long, 24 kN/m³.
    let (ri, re, n): (f64, f64, f64) = (1.85, 2.15, 7.0);
    let w = 24.0 * 1.0 * n * 0.5 * (std::f64::consts::PI / n).sin() * (re * re - ri * ri);
    // Columns: support, Fx, Fy, Fz.
    check_reactions(&html, 3, w);
    // A hinge of the vault strip opens its joint along the strip's whole length, 1 m.
    check_cracks(&html, &result, 3, 1000.0);

    // With friction: Coulomb, and the friction cone in force (the default pyramid).
    ok(&[
        "settle",
        s(&model),
        "--move",
        mv,
        "--friction",
        "0.5",
        "--report",
        s(&html_b),
    ]);
    let f = std::fs::read_to_string(&html_b).unwrap();
    let joints = result["joints"].as_array().unwrap().len();
    assert!(f.contains(&format!("Coulomb friction: μ = 0.5 ({joints} joints)")));
    assert!(f.contains("Friction cone: the pyramid of 8 facets inscribed in the cone"));
}

#[test]
fn issue32_item3_report_of_a_2d_limit_analysis() {
    let d = tmpdir("limit");
    let model = d.join("arch.json");
    // Live load 1 kN/m² on the left half of the extrados (per unit horizontal projection).
    ok(&[
        "gen",
        "arch",
        "--voussoirs",
        "16",
        "--live",
        "left",
        "-o",
        s(&model),
    ]);
    let mut m: Value = serde_json::from_str(&std::fs::read_to_string(&model).unwrap()).unwrap();
    m["materials"] = serde_json::json!({"default": {"unit_weight": 20.0}});
    std::fs::write(&model, m.to_string()).unwrap();
    let (html, json) = (d.join("l.html"), d.join("l.json"));
    ok(&[
        "limit",
        s(&model),
        "--friction",
        "0.7",
        "--report",
        s(&html),
        "-o",
        s(&json),
    ]);
    let html = std::fs::read_to_string(&html).unwrap();
    let result: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let lambda = result["load_multiplier"].as_f64().unwrap();
    for h in [
        "<h2>Hypotheses</h2>",
        "<h2>Inputs</h2>",
        "<h2>Results</h2>",
        "<h2>Sign-off</h2>",
        "Coulomb friction: μ = 0.7 (17 joints). Associative (normality)",
        "<th>live loads (multiplied by λ)</th>",
        "certified (≤ 1e-6)",
    ] {
        assert!(html.contains(h), "{h} missing");
    }
    // At collapse the supports carry the weight and λ times the live load: W by hand as above,
    // the live load q × the half span's horizontal projection (the extrados radius) × 1 m.
    let (ri, re, n): (f64, f64, f64) = (2.86, 2.86 + 0.33, 16.0);
    let w = 20.0 * n * 0.5 * (std::f64::consts::PI / n).sin() * (re * re - ri * ri);
    let live = 1.0 * re;
    let (rows, foot) = table_after(&html, "<h3>Support reactions");
    let sum: f64 = rows.iter().map(|r| num(&r[2])).sum();
    let expected = w + lambda * live;
    assert!(
        (sum - expected).abs() <= 1e-6 * expected,
        "Σ Fy {sum} kN, W + λ·L = {w} + {lambda}·{live} = {expected} kN"
    );
    assert!((num(&foot[0][2]) - expected).abs() <= 1e-6 * expected);
    // The live load at collapse is echoed as λ × its resultant, in kN.
    let at = html
        .split("<th>live loads at collapse (× λ)</th><td>")
        .nth(1)
        .expect("live load at collapse");
    let fy = at[at.find("resultant (0, ").unwrap() + 14..at.find(") kN").unwrap()].to_string();
    assert!(
        (num(&fy) + lambda * live).abs() <= 1e-5 * lambda * live,
        "{fy} vs −λ·L = {}",
        -lambda * live
    );
    // The crack table exists (a rate: widths relative), one row per joint not closed.
    let (cracks, _) = table_after(&html, "<h3>Cracks");
    assert_eq!(cracks.len(), open_joints(&result).len());
}
