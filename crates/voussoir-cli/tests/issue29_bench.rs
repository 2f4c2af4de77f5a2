//! Issue 29 item 6: `voussoir bench --scenario realistic`, the models engineers build × the
//! analyses they run. A tiny subset is run here (the paper's arch × limit and settle, LACT3's
//! arch × limit); the whole table is in docs/performance.md.

use crate::common::{json, refused, run, tmpdir};
use std::path::PathBuf;

fn lact3() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../voussoir-io/tests/fixtures/lact3");
    assert!(
        d.join("arch_1.dxf").is_file(),
        "the LACT3 fixtures are missing: {}",
        d.display()
    );
    d
}

#[test]
fn issue29_item6_realistic_bench_cells_are_certified_and_match_the_references() {
    let dir = tmpdir("issue29-bench", "subset");
    // The drawings given by a folder relative to the working directory, as a user types it:
    // the cells run in their own scratch folders (`--workdir cells`), where a relative folder
    // named nothing and ended the whole benchmark (session 23).
    std::fs::create_dir_all(dir.join("drawings")).unwrap();
    for f in ["arch_1.dxf", "Portal.dxf", "wall.dxf"] {
        std::fs::copy(lact3().join(f), dir.join("drawings").join(f)).unwrap();
    }
    let table = run(
        &dir,
        &[
            "bench",
            "--scenario",
            "realistic",
            "--models",
            "arch,lact3-arch",
            "--analyses",
            "limit,settle",
            "--lact3",
            "drawings",
            "--workdir",
            "cells",
            "-o",
            "cells.json",
        ],
    );
    let cells = json(&std::fs::read_to_string(dir.join("cells.json")).unwrap());
    let cells = cells.as_array().unwrap();
    // Two models × two analyses, in table order, each a row of the markdown table too.
    let got: Vec<(&str, &str)> = cells
        .iter()
        .map(|c| {
            (
                c["model"].as_str().unwrap(),
                c["analysis"].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        got,
        [
            ("arch", "limit"),
            ("arch", "settle"),
            ("lact3-arch", "limit"),
            ("lact3-arch", "settle")
        ]
    );
    assert!(
        table.contains("| model | dim | blocks | analysis |"),
        "{table}"
    );
    assert_eq!(table.matches("\n| arch | 2D | 64 |").count(), 2, "{table}");
    for c in cells {
        let what = format!("{} × {}", c["model"], c["analysis"]);
        assert_eq!(c["outcome"], "ok", "{what}: {c}");
        assert_eq!(c["certified"], true, "{what}: {c}");
        assert!(c["gap"].as_f64().unwrap() <= 1e-6, "{what}: {c}");
        assert!(c["wall_s"].as_f64().unwrap() > 0.0, "{what}");
        assert!(c["peak_mib"].as_f64().unwrap() > 1.0, "{what}");
        assert_eq!(c["dim"], 2, "{what}");
        // The method the solver layer reports; the default for 2D is a HiGHS method.
        assert!(
            c["method"].as_str().is_some_and(|m| !m.is_empty()),
            "{what}"
        );
        assert!(
            c["command"].as_str().unwrap().starts_with("voussoir "),
            "{what}"
        );
    }
    assert_eq!(cells[0]["blocks"], 64);
    assert_eq!(cells[2]["blocks"], 25);
    // The README's verified value of the paper's arch: λ = 0.4346 (to its 4 decimals).
    let l = cells[0]["value"].as_f64().unwrap();
    assert!((l - 0.4346).abs() <= 5e-5, "arch λ {l}");
    // LACT3's own tilting-table test: arch_1 collapses at a tilt of 17.10° (to 0.01°), λ = tan θ.
    let l = cells[2]["value"].as_f64().unwrap();
    let theta = l.atan().to_degrees();
    assert!((theta - 17.10).abs() <= 0.01, "LACT3 arch λ {l}: {theta}°");
    // The settlement's work is positive (the springing moves: the dead loads do work).
    assert!(cells[1]["value"].as_f64().unwrap() > 0.0);
    // The cells' models and results are in the work folder.
    assert!(dir.join("cells/arch/live.json").is_file());
}

#[test]
fn issue29_item6_a_cell_over_its_time_limit_is_recorded_not_waited_for() {
    let dir = tmpdir("issue29-bench", "timeout");
    run(
        &dir,
        &[
            "bench",
            "--scenario",
            "realistic",
            "--models",
            "arch",
            "--analyses",
            "capacity",
            "--cell-time-limit",
            "1e-9",
            "--workdir",
            "w",
            "-o",
            "c.json",
        ],
    );
    let c = json(&std::fs::read_to_string(dir.join("c.json")).unwrap());
    assert_eq!(c[0]["outcome"], "timed out", "{c}");
    assert_eq!(c[0]["result"], "timed out after 0.000000001 s", "{c}");
}

#[test]
fn issue29_item6_realistic_bench_flags_are_checked() {
    let dir = tmpdir("issue29-bench", "flags");
    refused(
        &dir,
        &["bench", "--scenario", "realistic", "--models", "cathedral"],
        "--models cathedral: no such model",
    );
    refused(
        &dir,
        &[
            "bench",
            "--scenario",
            "realistic",
            "--analyses",
            "limit,fly",
        ],
        "--analyses fly: no such analysis",
    );
    refused(
        &dir,
        &["bench", "--scenario", "realistic", "--sizes", "100"],
        "--sizes: does not apply to --scenario realistic",
    );
    refused(
        &dir,
        &["bench", "--scenario", "wall", "--models", "arch"],
        "--models: applies to --scenario realistic only",
    );
    refused(
        &dir,
        &["bench", "--scenario", "realistic", "--lact3", "no/such/dir"],
        "--lact3 no/such/dir: not a directory",
    );
    refused(
        &dir,
        &["bench", "--scenario", "realistic", "--cell-time-limit", "0"],
        "--cell-time-limit 0",
    );
}
