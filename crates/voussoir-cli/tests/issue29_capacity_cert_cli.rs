//! Issue #29 items 3 and 6 through the binary (helper h-cap, session 15): `capacity` reports
//! each step's certificate and the curve's summary (JSON and text), `least-thickness` its
//! decisions (`answered`), and every step of the LACT3 wall's capacity is certified (a warm
//! "locked" between two steps without equilibrium is decided again).

use crate::common;
use crate::common::{json, run};
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i29capcert", name)
}

fn lact3_wall(dir: &Path) -> String {
    let dxf =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../voussoir-io/tests/fixtures/lact3/wall.dxf");
    let out = dir.join("wall.json");
    run(
        dir,
        &[
            "import",
            dxf.to_str().unwrap(),
            "--units",
            "mm",
            "-o",
            out.to_str().unwrap(),
        ],
    );
    out.display().to_string()
}

#[test]
fn issue29_item3_capacity_text_and_json_certificates() {
    let dir = tmpdir("arch");
    let m = dir.join("arch.json");
    run(
        &dir,
        &["gen", "arch", "--live", "full", "-o", m.to_str().unwrap()],
    );
    let args = [
        "capacity",
        m.to_str().unwrap(),
        "--steps",
        "4",
        "--move",
        "right=0.01,-0.005",
    ];
    let text = run(&dir, &args);
    assert!(
        text.contains("certificates: every step certified (5 of 5; largest gap"),
        "{text}"
    );
    let mut a = args.to_vec();
    a.push("--json");
    let v = json(&run(&dir, &a));
    let c = &v["certificate"];
    assert_eq!(c["steps"], 5);
    assert_eq!(c["certified"], 5);
    assert_eq!(c["ok"], true);
    assert!(c["gap"].as_f64().unwrap() <= 1e-6);
    for p in v["curve"].as_array().unwrap() {
        assert_eq!(p["certificate"]["kind"], "multiplier");
        assert_eq!(p["certificate"]["ok"], true);
    }
    // λ at no settlement: the paper's 0.434645 (Fig 7), the same as `limit`.
    let l0 = v["curve"][0]["load_multiplier"].as_f64().unwrap();
    assert!((l0 - 0.434645).abs() < 1e-6, "{l0}");
}

#[test]
fn issue29_item2a_lact3_wall_capacity_steps_certified_no_equilibrium() {
    let dir = tmpdir("wall");
    let m = lact3_wall(&dir);
    let v = json(&run(
        &dir,
        &[
            "capacity",
            &m,
            "--steps",
            "20",
            "--split",
            "base@1.25",
            "--move",
            "base@1=0,-0.01",
            "--json",
        ],
    ));
    let curve = v["curve"].as_array().unwrap();
    assert_eq!(curve.len(), 21);
    // s = 0: the plain limit analysis (λ = 0.400765, session 14's table), certified.
    assert!((curve[0]["load_multiplier"].as_f64().unwrap() - 0.400765).abs() < 1e-6);
    // Every step certified, whatever its answer: a multiplier by its mechanism, "no
    // equilibrium" by the elastic program's Farkas certificate (a positive least violation).
    // The warm simplex once said "locked" at 0.25 cm between two infeasible programs: a
    // locked step must not stand between steps without equilibrium.
    for p in &curve[1..] {
        let c = &p["certificate"];
        assert_eq!(c["ok"], true, "{p}");
        if p["status"] == "no_equilibrium" {
            assert_eq!(c["kind"], "no_equilibrium");
            assert!(c["violation"].as_f64().unwrap() > 1e-6);
        }
    }
    for w in curve.windows(3) {
        assert!(
            !(w[1]["status"] == "locked"
                && w[0]["status"] == "no_equilibrium"
                && w[2]["status"] == "no_equilibrium"),
            "{w:?}"
        );
    }
    assert_eq!(v["certificate"]["ok"], true);
    assert_eq!(v["certificate"]["certified"], 21);
}

#[test]
fn issue29_item3_least_thickness_reports_its_decisions() {
    let dir = tmpdir("lt");
    let text = run(
        &dir,
        &["least-thickness", "arch", "--bisection-tolerance", "1e-4"],
    );
    assert!(
        text.contains(
            "decisions: every one certified (an equilibrium state, or a certificate of infeasibility)"
        ),
        "{text}"
    );
    let v = json(&run(
        &dir,
        &[
            "least-thickness",
            "arch",
            "--bisection-tolerance",
            "1e-4",
            "--json",
        ],
    ));
    assert_eq!(v["certified"], true);
    let n: u64 = v["answered"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["answers"].as_u64().unwrap())
        .sum();
    assert_eq!(n, v["steps"].as_u64().unwrap() + 2);
    // Milankovitch's t/R = 0.1075 within 1 %.
    let tr = v["thickness_over_radius"].as_f64().unwrap();
    assert!((tr - 0.1075).abs() < 0.01 * 0.1075, "{tr}");
}

#[test]
fn issue29_item1_vault_capacity_default_is_the_dual_simplex_and_agrees_with_clarabel() {
    // The README's vault (192 blocks), the benchmark's motion: the solver policy's method of a
    // 3D capacity curve is the dual simplex (warm from step to step); every step's λ equals
    // the dual simplex's, and an interior point's (Clarabel, an independent method), to 1e-6.
    let dir = tmpdir("vault");
    let m = dir.join("vault.json");
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
            m.to_str().unwrap(),
        ],
    );
    let curve = |method: Option<&str>| {
        let mut a = vec![
            "capacity",
            m.to_str().unwrap(),
            "--steps",
            "20",
            "--move",
            "right=0.01,0,-0.005",
            "--json",
        ];
        if let Some(x) = method {
            a.extend(["--method", x]);
        }
        json(&run(&dir, &a))
    };
    let (d, ds, cl) = (
        curve(None),
        curve(Some("dual-simplex")),
        curve(Some("clarabel")),
    );
    assert_eq!(d["solver"]["method"], "dual-simplex");
    // The canonical selection of the settlement mechanism (session 16, on by default) runs its
    // warm stages by the primal simplex by design, and the first settled step's no-equilibrium
    // certificate is asked of Clarabel first by design (session 27: the vault stands there, so
    // its limit program follows); every other program by the dual simplex.
    let answered = d["answered"].as_array().unwrap();
    assert!(answered
        .iter()
        .filter(|a| a["programs"] != "canonical selection"
            && a["programs"] != "no-equilibrium certificates")
        .all(|a| a["method"] == "dual-simplex"));
    assert!(answered
        .iter()
        .filter(|a| a["programs"] == "no-equilibrium certificates")
        .all(|a| a["method"] == "clarabel" && a["answers"] == 1));
    assert_eq!(d["certificate"]["ok"], true);
    let lam = |v: &serde_json::Value| -> Vec<f64> {
        v["curve"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["load_multiplier"].as_f64().unwrap())
            .collect()
    };
    let (a, b, c) = (lam(&d), lam(&ds), lam(&cl));
    assert_eq!(a.len(), 21);
    for i in 0..21 {
        assert!(
            (a[i] - b[i]).abs() <= 1e-6 * b[i].abs(),
            "step {i}: {} {}",
            a[i],
            b[i]
        );
        assert!(
            (a[i] - c[i]).abs() <= 1e-6 * c[i].abs(),
            "step {i}: {} {}",
            a[i],
            c[i]
        );
    }
    // The vault's λ at no settlement is the paper arch's (a vault of arches, full-span load).
    assert!((a[0] - 0.434645).abs() < 1e-6, "{}", a[0]);
}

#[test]
fn issue29_item3_lact3_portal_uncertified_warm_steps_solved_again() {
    // The LACT3 portal, the right half of its base 1 cm down: the warm dual simplex stopped
    // short at 0.4 and 0.45 cm (gap 6e-7, 6e-6; the curve was "not certified"). Those steps
    // are solved again from scratch: every step certified, and each λ equal to the curve
    // solved cold (every step from scratch: `--cold`) to 1e-6 (the certificates' tolerance).
    let dir = tmpdir("portal");
    let dxf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../voussoir-io/tests/fixtures/lact3/Portal.dxf");
    let m = dir.join("portal.json");
    run(
        &dir,
        &[
            "import",
            dxf.to_str().unwrap(),
            "--units",
            "mm",
            "-o",
            m.to_str().unwrap(),
        ],
    );
    let curve = |cold: bool| {
        let mut a = vec![
            "capacity",
            m.to_str().unwrap(),
            "--steps",
            "20",
            "--split",
            "base@1.25",
            "--move",
            "base@1=0,-0.01",
            "--json",
        ];
        if cold {
            a.push("--cold");
        }
        json(&run(&dir, &a))
    };
    let (warm, cold) = (curve(false), curve(true));
    assert_eq!(warm["certificate"]["ok"], true, "{}", warm["certificate"]);
    assert_eq!(warm["certificate"]["certified"], 21);
    let (a, b) = (
        warm["curve"].as_array().unwrap(),
        cold["curve"].as_array().unwrap(),
    );
    // Compared where both are a collapse (λ ≥ 0): at 0.05–0.35 cm (no equilibrium, λ < 0)
    // the warm program (open points kept as columns fixed at zero) and the cold one give
    // different negative multipliers (−0.425 against −0.385 at 0.05 cm), each certified by its
    // own mechanism: found in session 15, not resolved (docs/performance.md).
    for (p, q) in a.iter().zip(b) {
        if p["status"] != "collapse" || q["status"] != "collapse" {
            continue;
        }
        if let (Some(x), Some(y)) = (p["load_multiplier"].as_f64(), q["load_multiplier"].as_f64()) {
            assert!((x - y).abs() <= 1e-6 * y.abs().max(1e-3), "{x} {y}");
        }
    }
}

/// Session 20: the 1.0 m grid façade's capacity curve (right half settling) was reported NOT
/// CERTIFIED at 4 of 21 steps: each settled step has no equilibrium, and on 4 of them neither
/// Clarabel (row violation 2.3e-6) nor the dual simplex ("HiGHS run failed: Error") decided the
/// elastic program of the no-equilibrium certificate. The primal simplex decides it now. The
/// first settled step (1 cm) is one of the four: "no equilibrium" there is decided twice
/// independently — by the step's own program (the dual simplex: infeasible) and by the
/// certificate's elastic program (a positive least violation with duals that bound it).
#[test]
fn issue29_facade_settled_step_without_equilibrium_is_certified() {
    let dir = tmpdir("facade");
    let m = dir.join("f.json");
    let ms = m.to_str().unwrap();
    run(
        &dir,
        &[
            "gen",
            "facade",
            "--mesh",
            "grid",
            "--element",
            "1.0",
            "--live",
            "horizontal",
            "-o",
            ms,
        ],
    );
    let v = json(&run(
        &dir,
        &[
            "capacity",
            ms,
            "--steps",
            "1",
            "--profile",
            "uniform:11,22,-0.01",
            "--json",
        ],
    ));
    let c = &v["certificate"];
    assert_eq!(c["steps"], 2, "{c}");
    assert_eq!(c["certified"], 2, "{c}");
    assert_eq!(c["ok"], true, "{c}");
    let step = &v["curve"][1];
    assert_eq!(step["status"], "no_equilibrium", "{step}");
    let cert = &step["certificate"];
    assert_eq!(cert["ok"], true, "{cert}");
    // Certified: the least violation's dual bound above the margin of 1e-6 of the largest
    // load. Before session 26 it was 3.0e-6 on one solver path and 16.8 on the other: the
    // settlement mechanism's round-off turned the deformed joints and steered the step
    // program's scaling (docs/performance.md, "Capacity step round-off and the as-written
    // face extremes (session 26)"); the structure's own value is the latter.
    let violation = cert["violation"].as_f64().unwrap();
    assert!(violation > 1.0, "{violation}");
    // λ before any settlement: the façade's collapse load under the tilting table, certified.
    assert!(v["curve"][0]["load_multiplier"].as_f64().unwrap() > 1.0);
}
