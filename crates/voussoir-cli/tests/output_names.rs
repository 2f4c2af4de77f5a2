//! Session 23: an output flag given a name whose extension is another format's is refused
//! before any work, in one line naming the flag (`--report out.pdf` wrote HTML into a file
//! called .pdf; `-o r.png` JSON into a .png). Names with the flag's own extension, or with none
//! of the known ones, are written as before.

use crate::common::{gen_model, refused, run, tmpdir};

#[test]
fn output_names_of_another_format_are_refused_before_any_work() {
    let d = tmpdir("outnames", "refused");
    gen_model(&d, "arch --live left -o arch.json");
    gen_model(&d, "vault --live full --depth 1 --rings 3 -o vault.json");
    refused(
        &d,
        &["limit", "arch.json", "--report", "out.pdf"],
        "--report out.pdf: --report writes HTML, not PDF; give a name ending in .html; print the HTML report to PDF from a browser",
    );
    refused(
        &d,
        &["limit", "vault.json", "--png", "out.svg"],
        "--png out.svg: --png writes PNG, not SVG",
    );
    refused(
        &d,
        &[
            "settle",
            "arch.json",
            "--move",
            "right=0.01,0",
            "-o",
            "r.png",
        ],
        "-o r.png: -o writes JSON, not PNG",
    );
    refused(
        &d,
        &[
            "safety",
            "vault.json",
            "--no-reactions",
            "--report",
            "s.PDF",
        ],
        "--report s.PDF: --report writes HTML, not PDF",
    );
    refused(
        &d,
        &["tilt", "arch.json", "--svg", "t.png"],
        "--svg t.png: --svg writes SVG, not PNG",
    );
    // Nothing was written.
    for f in ["out.pdf", "out.svg", "r.png", "s.PDF", "t.png"] {
        assert!(!d.join(f).exists(), "{f} written");
    }
    // The flag's own extension, in any case, and a name without a known one, are accepted.
    run(
        &d,
        &[
            "limit",
            "arch.json",
            "--report",
            "a.HTML",
            "--png",
            "a.png",
            "-o",
            "r.result",
        ],
    );
    for f in ["a.HTML", "a.png", "r.result"] {
        assert!(d.join(f).exists(), "{f} not written");
    }
    let html = std::fs::read_to_string(d.join("a.HTML")).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
}
