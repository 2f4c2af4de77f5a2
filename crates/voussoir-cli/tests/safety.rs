//! `voussoir safety` and `voussoir least-thickness` end to end: Milankovitch's least thickness of
//! a semicircular arch through the command, a geometric safety factor of 1 there, the paper
//! arch's thrust range equal to the settlement analysis under spreading and closing supports,
//! and a 3D vault equal to its arch.

use crate::common::cwd::ok as run;
use std::path::{Path, PathBuf};

fn json(args: &[&str]) -> serde_json::Value {
    serde_json::from_slice(&run(args).stdout).unwrap()
}

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-safety-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn path(d: &Path, f: &str) -> String {
    d.join(f).to_str().unwrap().to_string()
}

/// `[min, max]` of a reaction component of a support in a safety result.
fn range(v: &serde_json::Value, support: &str, component: &str) -> [Option<f64>; 2] {
    let r = v["reactions"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["support"] == support)
        .unwrap();
    let c = r["components"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["component"] == component)
        .unwrap();
    [c["min"].as_f64(), c["max"].as_f64()]
}

#[test]
fn least_thickness_of_a_semicircular_arch_through_the_command_and_a_safety_factor_of_one_there() {
    let d = tmpdir("least");
    let model = path(&d, "least.json");
    let v = json(&[
        "least-thickness",
        "arch",
        "--radius",
        "1",
        "--radius-at",
        "centreline",
        "--voussoirs",
        "64",
        "--json",
        "-o",
        &model,
    ]);
    let t = v["thickness_over_radius"].as_f64().unwrap();
    // Milankovitch: t/R = 0.1075, approached from below with 64 voussoirs (0.10738).
    assert!((t - 0.1075).abs() <= 0.005 * 0.1075, "{t}");
    assert!(t <= 0.1075 + 1e-4, "{t}");
    assert!(v["thickness"].as_f64().unwrap() - v["below"].as_f64().unwrap() <= 1e-6);
    // The model written at the least thickness stands with a geometric safety factor of 1 to
    // the two bisections' tolerances (1e-6 each).
    let s = json(&["safety", &model, "--json"]);
    assert_eq!(s["stands"], true);
    let g = s["geometric_safety_factor"].as_f64().unwrap();
    assert!((1.0..=1.0 + 2e-5).contains(&g), "{g}");
    // There the admissible states shrink to one: the least and the largest thrust coincide.
    let [lo, hi] = range(&s, "right", "fx");
    let (lo, hi) = (lo.unwrap(), hi.unwrap());
    assert!(hi - lo <= 1e-3 * lo.abs(), "[{lo}, {hi}]");
    let s = json(&["safety", &model, "--json", "--no-reactions"]);
    assert!(s["reactions"].as_array().unwrap().is_empty());
    // Just below it, it does not stand: `safety` says so with `stands: false` (not an error).
    let thin = path(&d, "thin.json");
    run(&[
        "gen",
        "arch",
        "--radius",
        "1",
        "--radius-at",
        "centreline",
        "--thickness",
        &format!("{}", v["below"].as_f64().unwrap()),
        "-o",
        &thin,
    ]);
    let s = json(&["safety", &thin, "--json"]);
    assert_eq!(s["stands"], false);
    assert!(s["geometric_safety_factor"].is_null());
    assert!(s["reactions"].as_array().unwrap().is_empty());
}

#[test]
fn the_paper_arch_thrust_range_is_bounded_by_spreading_and_closing_settlements() {
    let d = tmpdir("thrust");
    let arch = path(&d, "arch.json");
    run(&["gen", "arch", "-o", &arch]);
    let s = json(&["safety", &arch, "--json"]);
    assert_eq!(s["stands"], true);
    // The paper arch (t/R = 0.109 at the centreline) is barely thicker than the least: 1.0159.
    let g = s["geometric_safety_factor"].as_f64().unwrap();
    assert!((g - 1.0159).abs() < 5e-4, "{g}");
    let thrust = |moves: &str| -> f64 {
        let v = json(&["settle", &arch, "--move", moves, "--json"]);
        assert_eq!(v["certificate"]["ok"], true);
        let r = v["reactions"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["support"] == "right")
            .unwrap();
        -r["fx"].as_f64().unwrap()
    };
    // The right support pushes the arch to the left: thrust H = −fx(right).
    let [lo, hi] = range(&s, "right", "fx");
    let (h_min, h_max) = (-hi.unwrap(), -lo.unwrap());
    let (spreading, closing) = (thrust("right=0.01,0"), thrust("right=-0.01,0"));
    eprintln!("thrust range [{h_min}, {h_max}] kN; spreading {spreading}, closing {closing}");
    assert!(
        (h_min - spreading).abs() <= 1e-6 * spreading,
        "{h_min} vs {spreading}"
    );
    assert!(
        (h_max - closing).abs() <= 1e-6 * closing,
        "{h_max} vs {closing}"
    );
    assert!(h_max > h_min * 1.005);
    // The left support gives the opposite.
    let [l_lo, l_hi] = range(&s, "left", "fx");
    assert!((l_lo.unwrap() - h_min).abs() <= 1e-6 * h_min);
    assert!((l_hi.unwrap() - h_max).abs() <= 1e-6 * h_max);
}

#[test]
fn a_3d_vault_stands_with_the_safety_factor_and_thrust_of_its_arch() {
    let d = tmpdir("vault");
    let (arch, vault) = (path(&d, "arch.json"), path(&d, "vault.json"));
    run(&["gen", "arch", "--voussoirs", "32", "-o", &arch]);
    run(&["gen", "vault", "--voussoirs", "32", "-o", &vault]);
    let a = json(&["safety", &arch, "--json"]);
    let v = json(&["safety", &vault, "--json"]);
    assert_eq!(v["stands"], true);
    let (ga, gv) = (
        a["geometric_safety_factor"].as_f64().unwrap(),
        v["geometric_safety_factor"].as_f64().unwrap(),
    );
    assert!((ga - gv).abs() <= 3e-6, "{ga} vs {gv}");
    for side in ["left", "right"] {
        let (x2, x3) = (range(&a, side, "fx"), range(&v, side, "fx"));
        let (y2, z3) = (range(&a, side, "fy"), range(&v, side, "fz"));
        for (p, q) in x2.iter().zip(&x3).chain(y2.iter().zip(&z3)) {
            let (p, q) = (p.unwrap(), q.unwrap());
            assert!((p - q).abs() <= 1e-6 * p.abs(), "{side}: {p} vs {q}");
        }
    }
    // Deterministic output.
    let again = run(&["safety", &vault, "--json"]).stdout;
    assert_eq!(again, run(&["safety", &vault, "--json"]).stdout);
}
