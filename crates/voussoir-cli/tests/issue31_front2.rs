//! Issue 31, the rest of the front door: incremental, identify, sweep and least thickness go
//! through the request layer (item 1), `voussoir plot` draws a saved 3D incremental result
//! (item 2). References: Milankovitch's and Heyman's least thicknesses (t/R = 0.1075 for a
//! semicircular arch, 0.042 for a hemispherical dome), the figure `incremental --svg` draws
//! while it runs (the saved result drawn again must be the same figure), the source of the
//! front ends (no library analysis called but through the request layer).

use crate::common::{json, refused, run, tmpdir};
use std::path::Path;

#[test]
fn issue31_item1_least_thickness_through_the_request_layer() {
    let dir = tmpdir("issue31f2", "least");
    let arch = json(&run(
        &dir,
        &[
            "least-thickness",
            "arch",
            "--live",
            "none",
            "--voussoirs",
            "64",
            "--bisection-tolerance",
            "1e-4",
            "--json",
            "-o",
            "arch.json",
        ],
    ));
    let tr = arch["thickness_over_radius"].as_f64().unwrap();
    // Milankovitch: 0.1075 for the continuous arch; 64 joints lie within 1 %.
    assert!((tr - 0.1075).abs() < 0.01 * 0.1075, "t/R = {tr}");
    assert_eq!(arch["solver"]["method"], "dual-simplex");
    // -o wrote the model at the least thickness: the intrados radius 2.86 m plus it.
    let m = json(&std::fs::read_to_string(dir.join("arch.json")).unwrap());
    assert_eq!(m["blocks"].as_array().unwrap().len(), 64);
    let dome = json(&run(
        &dir,
        &[
            "least-thickness",
            "dome",
            "--courses",
            "8",
            "--segments",
            "16",
            "--bisection-tolerance",
            "1e-3",
            "--json",
        ],
    ));
    let tr = dome["thickness_over_radius"].as_f64().unwrap();
    // Heyman: 0.042 for the hemisphere; 8 × 16 blocks within 10 %.
    assert!((tr - 0.042).abs() < 0.1 * 0.042, "t/R = {tr}");
    // The 3D default solver of the request layer.
    assert_eq!(dome["solver"]["method"], "ipm");
    refused(
        &dir,
        &["least-thickness", "arch", "--bisection-tolerance", "2"],
        "--bisection-tolerance 2: must be a number between 0 and 1",
    );
}

/// The library's analyses (and the choice between their variants) called from a front end's
/// source outside the request layer.
const ENTRY_POINTS: &[&str] = &[
    "limit_canonical",
    "settle_canonical",
    "limit_with(",
    "settle_with(",
    "settle_crushing",
    "limit_nonassociative",
    "settle_nonassociative",
    "incremental_with",
    "settled(",
    "Control::",
    "tilt_azimuth",
    "tilt::tilt(",
    "safety::safety(",
    "safety::least_thickness",
    "identify::identify",
    "sweep::run(&",
    "sweep::run_assembly",
    "sweep::analyse",
    "default_method",
];

fn sources(dir: &Path, out: &mut Vec<(String, String)>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs" || x == "py") {
            out.push((
                p.display().to_string(),
                std::fs::read_to_string(&p).unwrap(),
            ));
        }
    }
}

#[test]
fn issue31_item1_front_ends_choose_no_analysis_variant() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    for d in ["voussoir-cli/src", "voussoir-py/src", "voussoir-py/python"] {
        sources(&root.join(d), &mut files);
    }
    assert!(files.len() > 20, "{} source files", files.len());
    let mut found = Vec::new();
    for (path, text) in &files {
        for (i, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for e in ENTRY_POINTS {
                if code.contains(e) {
                    found.push(format!("{path}:{}: {e}", i + 1));
                }
            }
        }
    }
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn issue31_item2_plot_draws_a_saved_3d_incremental_result() {
    let dir = tmpdir("issue31f2", "plot3d");
    run(
        &dir,
        &[
            "gen",
            "vault",
            "--live",
            "left",
            "--depth",
            "1",
            "-o",
            "vault.json",
        ],
    );
    // The run draws its λ curve and saves the result.
    run(
        &dir,
        &[
            "incremental",
            "vault.json",
            "--control",
            "0,0.5,3.19",
            "--max",
            "2mm",
            "--step",
            "0.5mm",
            "--svg",
            "run.svg",
            "-o",
            "inc.json",
        ],
    );
    let saved = json(&std::fs::read_to_string(dir.join("inc.json")).unwrap());
    assert_eq!(saved["control"]["point"].as_array().unwrap().len(), 3);
    // Drawn again from the file: the same figure, byte for byte.
    run(&dir, &["plot", "inc.json", "-o", "again.svg"]);
    let a = std::fs::read(dir.join("run.svg")).unwrap();
    let b = std::fs::read(dir.join("again.svg")).unwrap();
    assert!(!a.is_empty());
    assert!(
        a == b,
        "plot of the saved 3D result differs from the run's figure"
    );
    // PNG too; a report of a 3D incremental result is refused in one line.
    run(&dir, &["plot", "inc.json", "-o", "again.png"]);
    assert!(std::fs::read(dir.join("again.png"))
        .unwrap()
        .starts_with(b"\x89PNG"));
    refused(
        &dir,
        &["plot", "inc.json", "-o", "inc.html"],
        "a 3D incremental result has no report",
    );
    assert!(!dir.join("inc.html").exists());
}

#[test]
fn issue31_item5_draw3d_stages_draw_the_same_bytes() {
    // The README's vault and dome, drawn before the renderer was split into stages (fixtures,
    // with their commands in tests/fixtures/issue31_draw3d/README.md) and now.
    let dir = tmpdir("issue31f2", "draw3d");
    let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/issue31_draw3d");
    run(
        &dir,
        &[
            "gen",
            "vault",
            "--live",
            "full",
            "--depth",
            "1",
            "--rings",
            "3",
            "-o",
            "vault3.json",
        ],
    );
    run(
        &dir,
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
    let cases: [(&str, &[&str]); 3] = [
        (
            "vault-settle.svg",
            &["settle", "vault3.json", "--move", "right=1cm,0,0", "--svg"],
        ),
        ("vault-limit.svg", &["limit", "vault3.json", "--svg"]),
        (
            "dome-settle.svg",
            &[
                "settle",
                "dome.json",
                "--friction",
                "0.5",
                "--move",
                "base0=0,0,-2cm",
                "--move",
                "base1=0,0,-2cm",
                "--svg",
            ],
        ),
    ];
    for (name, args) in cases {
        let mut a = args.to_vec();
        a.push(name);
        run(&dir, &a);
        let now = std::fs::read(dir.join(name)).unwrap();
        let before = std::fs::read(fixtures.join(name)).unwrap();
        assert!(now.len() > 10_000, "{name}: {} bytes", now.len());
        assert!(
            now == before,
            "{name} differs from the drawing before the split"
        );
    }
}
