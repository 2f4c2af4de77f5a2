//! Issue 29, item 5 through the binary: `tilt`, `capacity` and `sweep` report the canonical
//! mechanism by default in 2D and 3D, `--raw` the solver's own (the same λ, tilt and works),
//! and `--canonical-steps` is refused with `--raw` in one line naming both flags.

use crate::common;
use crate::common::{json, refused, run};
use std::path::PathBuf;

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i29candef", name)
}

/// The README's vault (`gen vault --live full --depth 1 --rings 3`) in `dir`.
fn vault(dir: &std::path::Path) -> String {
    let m = dir.join("vault.json");
    run(
        dir,
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
            m.to_str().unwrap(),
        ],
    );
    m.display().to_string()
}

/// `tilt` of the vault: the default JSON has the canonical record (mechanism only), `--raw`
/// none; the same critical tilt (to 1e-9 relative) and the same hinged joints; the summary
/// says how the mechanism was selected.
#[test]
fn issue29_item5_tilt_canonical_by_default_cli() {
    let dir = tmpdir("tilt");
    let m = vault(&dir);
    let d = json(&run(&dir, &["tilt", &m, "--json"]));
    let r = json(&run(&dir, &["tilt", &m, "--raw", "--json"]));
    assert!(d["limit"]["canonical"]["mechanism"].is_object(), "{d}");
    assert!(d["limit"]["canonical"]["forces"].is_null());
    assert!(r["limit"].get("canonical").is_none_or(|c| c.is_null()));
    let (a, b) = (
        d["tilt_angle"].as_f64().unwrap(),
        r["tilt_angle"].as_f64().unwrap(),
    );
    assert!((a - b).abs() <= 1e-9 * b.abs(), "{a} against {b}");
    let joints = |v: &serde_json::Value| {
        let mut j: Vec<u64> = v["limit"]["hinges"]
            .as_array()
            .unwrap()
            .iter()
            .map(|h| h["joint"].as_u64().unwrap())
            .collect();
        j.sort_unstable();
        j.dedup();
        j
    };
    assert!(!joints(&d).is_empty());
    assert_eq!(joints(&d), joints(&r), "the vault's tilt optimum is unique");
    let text = run(&dir, &["tilt", &m]);
    assert!(
        text.contains("canonical: the optimal mechanism is"),
        "{text}"
    );
}

/// `capacity` of the 2D paper arch: by default the settlement mechanism is canonical (the
/// record, the summary line), with `--canonical-steps` the steps' too; λ the same as `--raw`
/// at every step (1e-9 of λ(0)); `--canonical-steps --raw` refused naming both flags.
#[test]
fn issue29_item5_capacity_canonical_by_default_cli() {
    let dir = tmpdir("capacity");
    let m = dir.join("arch.json");
    run(
        &dir,
        &["gen", "arch", "--live", "full", "-o", m.to_str().unwrap()],
    );
    let m = m.to_str().unwrap();
    let base = [
        "capacity",
        m,
        "--steps",
        "6",
        "--move",
        "right=0.02,0",
        "--json",
    ];
    let with = |extra: &[&str]| {
        let mut a = base.to_vec();
        a.extend_from_slice(extra);
        json(&run(&dir, &a))
    };
    let d = with(&[]);
    let s = with(&["--canonical-steps"]);
    let r = with(&["--raw"]);
    assert_eq!(d["canonical"]["steps"], false, "{}", d["canonical"]);
    assert!(d["canonical"]["settlement"].is_object());
    assert_eq!(s["canonical"]["steps"], true);
    assert_eq!(s["canonical"]["steps_selected"], 7, "{}", s["canonical"]);
    assert!(r.get("canonical").is_none_or(|c| c.is_null()));
    let l0 = r["curve"][0]["load_multiplier"].as_f64().unwrap();
    for v in [&d, &s] {
        for (p, q) in v["curve"]
            .as_array()
            .unwrap()
            .iter()
            .zip(r["curve"].as_array().unwrap())
        {
            let (a, b) = (
                p["load_multiplier"].as_f64().unwrap(),
                q["load_multiplier"].as_f64().unwrap(),
            );
            assert!((a - b).abs() <= 1e-9 * l0, "{a} against {b}");
        }
    }
    let text = run(&dir, &base[..base.len() - 1]);
    assert!(
        text.contains("canonical: the settlement mechanism is unique; the steps' collapse mechanisms are the solver's"),
        "{text}"
    );
    let mut a = base[..base.len() - 1].to_vec();
    a.extend_from_slice(&["--raw", "--canonical-steps"]);
    refused(
        &dir,
        &a,
        "--canonical-steps applies to the canonical selection, which --raw leaves out",
    );
}

/// `sweep` of the vault: the default and `--raw` give the same works (CSV), and both run.
#[test]
fn issue29_item5_sweep_canonical_by_default_cli() {
    let dir = tmpdir("sweep");
    let m = vault(&dir);
    let jl = |raw: bool| {
        let f = dir.join(format!("s{raw}.jsonl"));
        let mut a = vec![
            "sweep",
            m.as_str(),
            "--move",
            "right=1cm,0,0",
            "--magnitudes",
            "2",
            "--jsonl",
            f.to_str().unwrap(),
        ];
        if raw {
            a.push("--raw");
        }
        run(&dir, &a);
        std::fs::read_to_string(&f)
            .unwrap()
            .lines()
            .map(json)
            .collect::<Vec<_>>()
    };
    let (d, r) = (jl(false), jl(true));
    assert_eq!(d.len(), 2);
    for (a, b) in d.iter().zip(&r) {
        let (wa, wb) = (
            a["work_dead_loads"].as_f64().unwrap(),
            b["work_dead_loads"].as_f64().unwrap(),
        );
        assert!((wa - wb).abs() <= 1e-9 * wb.abs(), "{wa} against {wb}");
        assert_eq!(a["certified"], true);
        assert_eq!(a["hinge_joints"], b["hinge_joints"], "unique on the vault");
    }
}
