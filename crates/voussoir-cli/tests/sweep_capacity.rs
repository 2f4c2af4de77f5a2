//! `voussoir sweep --capacity`: a seeded Monte Carlo of a wall's foundation profile, the capacity
//! after each settlement. The wall: 5 courses × 4 units of 0.4 × 0.175 m (1.6 m long, 0.875 m
//! high) with a horizontal live load equal to each block's weight (the tilting table); its
//! right half (segments f2, f3) settles by 1 cm, each segment's settlement × (1 + 0.3 z).

use crate::common::cwd::ok as run;
use std::path::{Path, PathBuf};
use std::process::Command;

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "voussoir-sweep-capacity-{}-{name}",
        std::process::id()
    ));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn lines(p: &Path) -> Vec<serde_json::Value> {
    std::fs::read_to_string(p)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

fn close(a: Option<f64>, b: Option<f64>, rel: f64) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() <= rel * a.abs().max(b.abs()).max(1e-300),
        (None, None) => true,
        _ => false,
    }
}

#[test]
fn a_monte_carlo_of_a_wall_s_foundation_gives_the_distribution_of_its_residual_capacity() {
    let d = tmpdir("wall");
    let wall = d.join("wall.json");
    run(&[
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
    let (jl, csv, summary, svg, png, report) = (
        d.join("mc.jsonl"),
        d.join("mc.csv"),
        d.join("summary.json"),
        d.join("mc.svg"),
        d.join("mc.png"),
        d.join("mc.html"),
    );
    let o = run(&[
        "sweep",
        s(&wall),
        "--profile",
        "uniform:0.8,1.7,-0.01",
        "--samples",
        "200",
        "--seed",
        "7",
        "--capacity",
        "--capacity-steps",
        "10",
        "--jsonl",
        s(&jl),
        "--csv",
        s(&csv),
        "--summary",
        s(&summary),
        "--svg",
        s(&svg),
        "--png",
        s(&png),
        "--report",
        s(&report),
    ]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(msg.contains("quantiles of λ after the settlement"), "{msg}");
    let records = lines(&jl);
    assert_eq!(records.len(), 200);
    let cap = |r: &serde_json::Value, k: &str| r["capacity"][k].as_f64();

    // Before the settlement the wall overturns as one rigid block about its toe: λ = b/h.
    let b_over_h = 1.6 / 0.875;
    for r in &records {
        let l0 = cap(r, "load_multiplier_before").unwrap();
        assert!((l0 - b_over_h).abs() <= 1e-9 * b_over_h, "{l0}");
    }
    // After it, where limit analysis on the deformed geometry is valid, the capacity is lower.
    let done: Vec<&serde_json::Value> = records
        .iter()
        .filter(|r| r["capacity"]["status"] == "curve")
        .collect();
    assert!(done.len() >= 190, "{} of 200 capacity curves", done.len());
    for r in done.iter().filter(|r| r["capacity"]["valid"] == true) {
        let l = cap(r, "load_multiplier_after").unwrap();
        assert!(l > 0.0 && l <= b_over_h + 1e-12, "{l}");
    }

    // The summary's quantiles from the records, recomputed here (linear interpolation between
    // order statistics).
    let mut lam: Vec<f64> = records
        .iter()
        .filter_map(|r| cap(r, "load_multiplier_after"))
        .collect();
    lam.sort_by(f64::total_cmp);
    let q = |p: f64| {
        let h = (lam.len() - 1) as f64 * p;
        let i = h.floor() as usize;
        lam[i] + (h - i as f64) * (lam[(i + 1).min(lam.len() - 1)] - lam[i])
    };
    let sm: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&summary).unwrap()).unwrap();
    assert_eq!(sm["with_load_multiplier"].as_u64(), Some(lam.len() as u64));
    for e in sm["quantiles"].as_array().unwrap() {
        let p = e["probability"].as_f64().unwrap();
        assert!((e["value"].as_f64().unwrap() - q(p)).abs() <= 1e-12, "{p}");
    }
    let median = q(0.5);
    eprintln!(
        "λ after the settlement: 5 % {:.6}, median {median:.6}, 95 % {:.6}",
        q(0.05),
        q(0.95)
    );
    // Two modes: most samples keep nearly the whole capacity; where the end segment drops more
    // than its neighbour, the left half (0.8 m of the 1.6 m) overturns alone, λ ≈ (b/2)/h.
    assert!(median > 0.98 * b_over_h && median < b_over_h, "{median}");
    let low = q(0.05);
    assert!(
        (low - 0.5 * b_over_h).abs() <= 0.01 * 0.5 * b_over_h,
        "{low}"
    );

    // Three samples equal to single `voussoir capacity` runs with the same motions.
    let low_sample = records
        .iter()
        .find(|r| cap(r, "load_multiplier_after").is_some_and(|l| l < 1.0))
        .unwrap();
    for r in [&records[0], &records[1], low_sample] {
        let mut args: Vec<String> = vec!["capacity".into(), s(&wall).into()];
        for (name, m) in r["motions"].as_object().unwrap() {
            let m: Vec<f64> = m
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            assert_eq!(m[2], 0.0);
            args.push("--move".into());
            args.push(format!("{name}={},{}", m[0], m[1]));
        }
        args.extend(["--steps", "10", "--json"].map(String::from));
        let argv: Vec<&str> = args.iter().map(|a| a.as_str()).collect();
        let c: serde_json::Value = serde_json::from_slice(&run(&argv).stdout).unwrap();
        let curve = c["curve"].as_array().unwrap();
        let after = curve.last().unwrap()["load_multiplier"].as_f64();
        assert!(
            close(cap(r, "load_multiplier_after"), after, 1e-9),
            "{}",
            r["index"]
        );
        assert!(close(
            cap(r, "load_multiplier_before"),
            curve[0]["load_multiplier"].as_f64(),
            1e-9
        ));
        assert!(close(
            cap(r, "zero_capacity_settlement"),
            c["zero_capacity_settlement"].as_f64(),
            1e-9
        ));
        assert!(close(
            cap(r, "max_settlement"),
            c["max_settlement"].as_f64(),
            1e-9
        ));
        let valid = curve.iter().all(|p| p["valid"] == true);
        assert_eq!(r["capacity"]["valid"], valid, "{}", r["index"]);
    }
    assert_eq!(low_sample["capacity"]["valid"], false);

    // The CSV has the capacity columns; the figures are written.
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.lines().next().unwrap().ends_with(
        ",capacity_status,max_settlement,lambda_before,lambda_after,zero_capacity_settlement,capacity_valid,invalid_steps,valid_after"
    ));
    assert_eq!(text.lines().count(), 201);
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    let svg_text = std::fs::read_to_string(&svg).unwrap();
    assert!(svg_text.contains("Exceedance curve") && svg_text.contains("samples per bin"));
    let html = std::fs::read_to_string(&report).unwrap();
    assert!(html.contains("Quantiles") && html.contains("<svg"));
}

#[test]
fn a_settlement_sweep_without_capacity_keeps_its_records_and_refuses_the_figures() {
    let d = tmpdir("plain");
    let wall = d.join("wall.json");
    run(&["gen", "wall", "--live", "horizontal", "-o", s(&wall)]);
    let jl = d.join("plain.jsonl");
    run(&[
        "sweep",
        s(&wall),
        "--profile",
        "uniform:0.8,2.1,-0.01",
        "--samples",
        "4",
        "--jsonl",
        s(&jl),
    ]);
    for r in lines(&jl) {
        assert!(r.get("capacity").is_none());
    }
    let o = Command::new(env!("CARGO_BIN_EXE_voussoir"))
        .args([
            "sweep",
            s(&wall),
            "--profile",
            "uniform:0.8,2.1,-0.01",
            "--samples",
            "4",
            "--png",
            s(&d.join("x.png")),
        ])
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("give --capacity"));
    // A capacity sweep of a model without live loads is refused before any work.
    let bare = d.join("bare.json");
    run(&["gen", "wall", "-o", s(&bare)]);
    let o = Command::new(env!("CARGO_BIN_EXE_voussoir"))
        .args([
            "sweep",
            s(&bare),
            "--profile",
            "uniform:0.8,2.1,-0.01",
            "--samples",
            "4",
            "--capacity",
        ])
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("needs live loads"));
}
