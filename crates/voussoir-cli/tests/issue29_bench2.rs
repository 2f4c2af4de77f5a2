//! Issue 29 item 6 (session 14): the realistic benchmark reports the certificate of an analysis
//! of many programs. `safety` answers its bisection and reaction-range programs each with a
//! certificate (or a certified decision: infeasible) and says so in its `answered` lines; the
//! benchmark read no `certificate` object there and printed "— (none reported)", and its method
//! column named only the bisection's method although the ranges were answered by another.
use crate::common::{json, run, tmpdir};

#[test]
fn issue29_item6_bench_reads_safetys_answered_programs() {
    let dir = tmpdir("issue29-bench2", "safety");
    let table = run(
        &dir,
        &[
            "bench",
            "--scenario",
            "realistic",
            "--models",
            "arch",
            "--analyses",
            "safety",
            "--workdir",
            "cells",
            "-o",
            "cells.json",
        ],
    );
    let cells = json(&std::fs::read_to_string(dir.join("cells.json")).unwrap());
    let cell = &cells.as_array().unwrap()[0];
    assert_eq!(cell["analysis"], "safety");
    assert_eq!(cell["outcome"], "ok", "{cell}");

    // The reference: the command's own output, read here independently of the benchmark.
    let out = json(&std::fs::read_to_string(dir.join("cells/arch/safety.out.json")).unwrap());
    let answered = out["answered"]
        .as_array()
        .expect("safety reports `answered`");
    assert!(!answered.is_empty());
    // The verdict by hand: every line certified or a decided infeasibility (no "not certified"
    // line on the arch, so no re-solve to account for).
    let decided = answered.iter().all(|l| {
        matches!(
            l["outcome"].as_str(),
            Some("certified") | Some("infeasible") | Some("unbounded")
        )
    });
    assert!(decided, "{answered:?}");
    assert_eq!(cell["certified"], true, "{cell}");
    assert_eq!(
        cell["programs"].as_array().map(|a| a.len()),
        Some(answered.len()),
        "{cell}"
    );
    // The key number is the command's, to the last digit.
    let f = out["geometric_safety_factor"].as_f64().unwrap();
    assert!((cell["value"].as_f64().unwrap() - f).abs() <= 1e-12 * f);
    // Both kinds of program are there (2 supports × 2 components × min/max = 8 range LPs at
    // most, the bisection's at least one), and the row says "yes", not "none reported".
    let answers = |kind: &str| -> u64 {
        answered
            .iter()
            .filter(|l| l["programs"] == kind)
            .map(|l| l["answers"].as_u64().unwrap())
            .sum()
    };
    assert!(answers("bisection") >= 1, "{answered:?}");
    assert!(
        (1..=8).contains(&answers("reaction ranges")),
        "{answered:?}"
    );
    let row = table
        .lines()
        .find(|l| l.starts_with("| arch | 2D | 64 | safety |"))
        .unwrap_or_else(|| panic!("{table}"));
    assert!(row.contains("| yes |"), "{row}");
    assert!(!row.contains("none reported"), "{row}");
    // The method column names every method that answered a kind of program, beside the one
    // the command reports.
    let main = out["solver"]["method"].as_str().unwrap();
    for l in answered {
        let m = l["method"].as_str().unwrap();
        if m != main {
            let want = format!("{}: {m}", l["programs"].as_str().unwrap());
            assert!(row.contains(&want), "{want} not in {row}");
        }
    }
}

/// The μ = 0.6 non-associative façades: `safety` and `tilt` take --friction but refuse
/// --non-associative, so the benchmark's cells failed on the flag ("error: --non-associative does
/// not apply to `voussoir tilt`") instead of measuring. They now run μ = 0.6 associatively and
/// say so. A one-second cell limit keeps the test short: the cell may time out, but it must not
/// fail, and the command run is the one recorded.
#[test]
fn issue29_item6_bench_runs_tilt_of_a_non_associative_model_associatively() {
    let dir = tmpdir("issue29-bench2", "tilt-mu");
    run(
        &dir,
        &[
            "bench",
            "--scenario",
            "realistic",
            "--models",
            "facade-grid-0.5-mu0.6",
            "--analyses",
            "limit,tilt",
            "--cell-time-limit",
            "1",
            "--workdir",
            "cells",
            "-o",
            "cells.json",
        ],
    );
    let cells = json(&std::fs::read_to_string(dir.join("cells.json")).unwrap());
    let cells = cells.as_array().unwrap();
    assert_eq!(cells.len(), 2);
    let (limit, tilt) = (&cells[0], &cells[1]);
    assert_eq!(limit["analysis"], "limit");
    assert_eq!(tilt["analysis"], "tilt");
    // limit keeps the non-associative law; tilt gets the same μ without the flag it refuses.
    let lc = limit["command"].as_str().unwrap();
    assert!(
        lc.contains("--friction 0.6") && lc.contains("--non-associative"),
        "{lc}"
    );
    let tc = tilt["command"].as_str().unwrap();
    assert!(tc.contains("--friction 0.6"), "{tc}");
    assert!(!tc.contains("--non-associative"), "{tc}");
    assert_ne!(tilt["outcome"], "failed", "{tilt}");
    if tilt["outcome"] == "ok" {
        assert!(
            tilt["result"]
                .as_str()
                .unwrap()
                .starts_with("associative μ"),
            "{tilt}"
        );
    }
}
