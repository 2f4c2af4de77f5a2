//! Issue 29, item 5 (session 18): `voussoir incremental` settles by the canonical settlement
//! mechanism by default (a summary line says so, the JSON records it), `--raw` by the solver's
//! own (no record), `--canonical-steps` selects every step's collapse mechanism, and the two
//! together are refused in one line. Reference: the same curve either way on the paper's arch,
//! whose optima are unique.

use crate::common::{cwd::ok_text as ok, cwd::run};

#[test]
fn issue29_item5_incremental_raw_and_canonical_steps_flags() {
    let dir = std::env::temp_dir().join(format!("voussoir-inc-canonical-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let m = dir.join("half.json");
    let m = m.to_str().unwrap();
    ok(&["gen", "arch", "--live", "left", "-o", m]);
    let base = [
        "incremental",
        m,
        "--control",
        "0,3.19",
        "--max",
        "2mm",
        "--step",
        "0.2mm",
        "--move",
        "right=0,-2.5mm",
        "--fixed",
        "right",
    ];
    let with = |extra: &[&str]| -> Vec<String> {
        let mut a: Vec<String> = base.iter().map(|s| s.to_string()).collect();
        a.extend(extra.iter().map(|s| s.to_string()));
        a
    };
    let text = |extra: &[&str]| {
        let a = with(extra);
        ok(&a.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let json = |extra: &[&str]| -> serde_json::Value {
        let mut e = extra.to_vec();
        e.push("--json");
        serde_json::from_str(&text(&e)).unwrap()
    };
    // The summary's one line.
    let d = text(&[]);
    let lines: Vec<&str> = d.lines().filter(|l| l.starts_with("canonical:")).collect();
    assert_eq!(lines.len(), 1, "{d}");
    assert!(
        lines[0].contains("settlement mechanism is the canonical one")
            && lines[0].contains("--canonical-steps"),
        "{d}"
    );
    assert!(!text(&["--raw"]).contains("canonical:"));
    let s = text(&["--canonical-steps"]);
    assert!(
        s.contains("step") && s.contains("selected, 0 of them not the solver's"),
        "{s}"
    );
    // The JSON: recorded by default and with --canonical-steps, absent with --raw; the same
    // curve (unique optima).
    let (jd, jr, js) = (json(&[]), json(&["--raw"]), json(&["--canonical-steps"]));
    assert_eq!(jd["canonical"]["settlement"]["unique"], true);
    assert_eq!(jd["canonical"]["steps"], false);
    assert!(jr.get("canonical").is_none());
    assert_eq!(js["canonical"]["steps"], true);
    assert!(js["canonical"]["steps_selected"].as_u64().unwrap() >= 10);
    assert_eq!(jd["curve"], jr["curve"]);
    assert_eq!(js["curve"], jr["curve"]);
    // Refused together, in one line.
    let a = with(&["--raw", "--canonical-steps"]);
    let o = run(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(
        err.contains("--canonical-steps") && err.contains("--raw"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Regression (session 18): `incremental --friction-cone exact` on a 3D model ran its steps on
/// the inscribed pyramid and said nothing (the curve was identical to the pyramid's). It is
/// refused in one line naming the flag, and nothing is written.
#[test]
fn issue29_incremental_refuses_the_exact_cone() {
    let dir = std::env::temp_dir().join(format!("voussoir-inc-cone-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let m = dir.join("vault.json");
    let m = m.to_str().unwrap();
    ok(&["gen", "vault", "--live", "right", "-o", m]);
    let out = dir.join("out.json");
    let o = run(&[
        "incremental",
        m,
        "--control",
        "0,0.5,3",
        "--friction",
        "0.6",
        "--friction-cone",
        "exact",
        "--max",
        "2mm",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        err.contains("--friction-cone exact") && err.contains("incremental"),
        "{err}"
    );
    assert!(!out.exists());
    // The pyramid (the default) runs.
    ok(&[
        "incremental",
        m,
        "--control",
        "0,0.5,3",
        "--friction",
        "0.6",
        "--max",
        "2mm",
    ]);
}

/// Regression (session 18): the README's wall with a horizontal live load, settled 5 mm at
/// `f9` and driven to 20 mm, ran the 100,000-step cap (minutes of LPs; killed after 120 s)
/// where 17 mm ends in a fraction of a second: near 20 mm the dead loads alone move it again
/// and again, each move closing a contact point, with no equilibrium at any λ. The run now
/// stops once those moves outnumber the contact points, says so, and keeps the curve: the
/// 17 mm run's curve (but its last step, cut to end at 17 mm) is its beginning, point for
/// point (reference: that run, which ends at its maximum displacement and never takes such a
/// move).
#[test]
fn issue29_incremental_dead_load_moves_in_a_row_stop() {
    let dir = std::env::temp_dir().join(format!("voussoir-inc-snaps-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let m = dir.join("wall.json");
    let m = m.to_str().unwrap();
    ok(&[
        "gen",
        "wall",
        "--courses",
        "8",
        "--units",
        "10",
        "--unit",
        "0.4,0.2",
        "--live",
        "horizontal",
        "-o",
        m,
    ]);
    let run_to = |max: &str| -> serde_json::Value {
        let out = ok(&[
            "incremental",
            m,
            "--control",
            "4.0,1.6",
            "--move",
            "f9=0,-5mm",
            "--max",
            max,
            "--step",
            "0.5mm",
            "--raw",
            "--json",
        ]);
        serde_json::from_str(&out).unwrap()
    };
    let short = run_to("17mm");
    assert_eq!(short["status"], "max_displacement", "{}", short["message"]);
    assert_eq!(short["snaps"], 0);
    let long = run_to("20mm");
    assert_eq!(long["status"], "no_equilibrium", "{}", long["message"]);
    let msg = long["message"].as_str().unwrap();
    assert!(
        msg.contains("times in a row") && msg.contains("stopped"),
        "{msg}"
    );
    assert!(long["snaps"].as_u64().unwrap() > 0);
    let steps = long["curve"].as_array().unwrap().last().unwrap()["step"]
        .as_u64()
        .unwrap();
    assert!(steps < 2_000, "{steps} steps");
    let (a, b) = (
        short["curve"].as_array().unwrap(),
        long["curve"].as_array().unwrap(),
    );
    assert!(b.len() > a.len());
    // The short run's last step is cut to end at 17 mm; the steps before it are the same.
    for (p, q) in a[..a.len() - 1].iter().zip(b) {
        for f in ["displacement", "load_multiplier"] {
            let (x, y) = (p[f].as_f64().unwrap(), q[f].as_f64().unwrap());
            assert!(
                (x - y).abs() <= 1e-12 * (1.0 + x.abs()),
                "{f}: {x} against {y}"
            );
        }
    }
}
