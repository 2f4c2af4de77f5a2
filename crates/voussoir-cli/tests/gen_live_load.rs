//! Regression (session 10): `gen arch --live none --live-load 5` wrote a model and ignored the
//! intensity. `--live-load` is now refused with `--live none|horizontal` (which have none) and
//! honoured with a vertical live load: λ is inversely proportional to q (the live load is
//! linear in q, the dead loads do not change), so q = 5 gives λ(q = 1) / 5.
use crate::common::{refused, run, tmpdir};

fn lambda(summary: &str) -> f64 {
    let line = summary
        .lines()
        .find(|l| l.contains("λ ="))
        .unwrap_or_else(|| panic!("no λ in {summary}"));
    line.split("λ =").nth(1).unwrap().trim().parse().unwrap()
}

#[test]
fn live_load_without_a_vertical_live_load_is_refused() {
    let d = tmpdir("genlive", "refused");
    refused(
        &d,
        &[
            "gen",
            "arch",
            "--live",
            "none",
            "--live-load",
            "5",
            "-o",
            "a.json",
        ],
        "--live-load 5",
    );
    refused(
        &d,
        &[
            "gen",
            "vault",
            "--live",
            "horizontal",
            "--live-load",
            "2",
            "-o",
            "v.json",
        ],
        "--live horizontal has no intensity",
    );
    assert!(!d.join("a.json").exists() && !d.join("v.json").exists());
}

#[test]
fn live_load_scales_the_collapse_multiplier_inversely() {
    let d = tmpdir("genlive", "scales");
    run(&d, &["gen", "arch", "--live", "left", "-o", "q1.json"]);
    run(
        &d,
        &[
            "gen",
            "arch",
            "--live",
            "left",
            "--live-load",
            "5",
            "-o",
            "q5.json",
        ],
    );
    let l1 = lambda(&run(&d, &["limit", "q1.json"]));
    let l5 = lambda(&run(&d, &["limit", "q5.json"]));
    // The summary prints 6 significant digits: agreement to 2e-5 relative.
    assert!(
        (l5 * 5.0 - l1).abs() <= 2e-5 * l1,
        "λ(q=5) = {l5}, λ(q=1) = {l1}"
    );
    // The paper's half-span value (README verification table).
    assert!((l1 - 0.2189).abs() < 5e-4, "{l1}");
}
