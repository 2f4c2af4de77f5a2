//! Issue 31, item 5: every result type lives in `result/`. A result type is a public,
//! serialisable struct or enum that an analysis returns or a front end writes: the library's
//! sources outside `result/` may re-export such types but define none. Read from the source
//! tree itself, so a type moved back out of `result/` fails here.

use std::path::{Path, PathBuf};

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// The names of public types whose derive list holds `Serialize` and whose name says what
/// they are: a result, a record of a run, a summary, ranges or an iteration of an analysis.
fn serialised_result_types(text: &str) -> Vec<String> {
    let lines: Vec<&str> = text.lines().collect();
    let mut found = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        let l = l.trim_start();
        let Some(rest) = l
            .strip_prefix("pub struct ")
            .or_else(|| l.strip_prefix("pub enum "))
        else {
            continue;
        };
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        // The attributes right above the item.
        let serialised = lines[..i]
            .iter()
            .rev()
            .take_while(|a| {
                let a = a.trim_start();
                a.starts_with("#[") || a.starts_with("///")
            })
            .any(|a| a.contains("derive(") && a.contains("Serialize"));
        let named = ["Result", "Record", "Summary", "Ranges", "Iteration"]
            .iter()
            .any(|s| name.ends_with(s));
        if serialised && named {
            found.push(name);
        }
    }
    found
}

#[test]
fn issue31_item5_every_result_type_is_defined_in_result() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    assert!(files.len() > 20, "the library's sources are missing");
    let mut inside = Vec::new();
    let mut outside = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        let names = serialised_result_types(&text);
        if f.starts_with(src.join("result")) {
            inside.extend(names);
        } else {
            outside.extend(names.into_iter().map(|n| format!("{n} in {}", f.display())));
        }
    }
    assert!(
        outside.is_empty(),
        "result types defined outside result/: {outside:?}"
    );
    // The scan sees the types it is about (so that it cannot pass by seeing nothing).
    for name in [
        "LimitResult",
        "SettlementResult",
        "SafetyResult",
        "LeastThicknessResult",
        "SweepRecord",
        "CapacitySummary",
        "AdaptRecord",
        "IdentifyResult",
    ] {
        assert!(
            inside.iter().any(|n| n == name),
            "{name} not found in result/ (found {inside:?})"
        );
    }
}

#[test]
fn the_scan_finds_a_serialised_result_type_and_ignores_the_rest() {
    let text = "#[derive(Clone, Serialize)]\n/// doc\npub struct FooResult {\n}\n\
                #[derive(Clone)]\npub struct BarResult;\n\
                #[derive(Serialize)]\npub struct Options {}\n";
    assert_eq!(serialised_result_types(text), vec!["FooResult".to_string()]);
}
