//! Issue 29 item 5 (session 14): `--least-friction-precision` on `settle` and `limit
//! --canonical` — honoured where the canonical forces are selected, refused in one line
//! where they are not (every flag honoured or refused). The least μ's reference is an
//! independent bisection to 1e-6 (crates/voussoir/tests/issue29_friction_precision.rs: 1.20280
//! on the README's wall).
use crate::common::{json, refused, run, tmpdir};

const REFERENCE: f64 = 1.2027998;

fn readme_wall(dir: &std::path::Path) {
    run(
        dir,
        &[
            "gen",
            "wall",
            "--courses",
            "8",
            "--units",
            "10",
            "--unit",
            "0.4,0.2",
            "-o",
            "wall.json",
        ],
    );
}

#[test]
fn issue29_item5_least_friction_precision_is_honoured_and_stated() {
    let d = tmpdir("i29fp", "honoured");
    readme_wall(&d);
    for (prec, flag) in [(0.05, None), (1e-3, Some("1e-3"))] {
        let mut args = vec![
            "settle",
            "wall.json",
            "--profile",
            "uniform:2.8,4.0,-0.01",
            "--no-ranges",
            "-o",
            "r.json",
        ];
        if let Some(f) = flag {
            args.extend(["--least-friction-precision", f]);
        }
        let out = run(&d, &args);
        let r = json(&std::fs::read_to_string(d.join("r.json")).unwrap());
        let f = &r["canonical"]["forces"];
        let shown = f["friction_precision"].as_f64().unwrap();
        assert!(shown > 0.0 && shown <= prec, "{shown}");
        let least = f["least_friction"].as_f64().unwrap();
        assert!(
            least >= REFERENCE * (1.0 - 1e-5) && least <= REFERENCE / (1.0 - shown) * (1.0 + 1e-5),
            "least μ {least}"
        );
        // The summary states the μ and the precision it is shown to.
        assert!(
            out.contains(&format!("least admissible μ = {least:.4} (to ")),
            "{out}"
        );
    }
}

#[test]
fn issue29_item5_least_friction_precision_refused_where_it_does_not_apply() {
    let d = tmpdir("i29fp", "refused");
    readme_wall(&d);
    let settle = ["settle", "wall.json", "--profile", "uniform:2.8,4.0,-0.01"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        let mut a: Vec<&'static str> = settle.to_vec();
        a.extend(extra);
        a.extend(["-o", "r.json"]);
        a
    };
    for bad in [
        "--least-friction-precision=0",
        "--least-friction-precision=1",
        "--least-friction-precision=-0.1",
        "--least-friction-precision=NaN",
    ] {
        refused(
            &d,
            &with(&[bad]),
            "--least-friction-precision must be a relative precision in (0, 1)",
        );
    }
    refused(
        &d,
        &with(&["--raw", "--least-friction-precision", "1e-3"]),
        "--least-friction-precision applies to the canonical selection, which --raw leaves out",
    );
    refused(
        &d,
        &with(&[
            "--friction",
            "0.6",
            "--non-associative",
            "--least-friction-precision",
            "1e-3",
        ]),
        "--least-friction-precision is not computed with --non-associative",
    );
    assert!(!d.join("r.json").exists());
    run(&d, &["gen", "arch", "--live", "left", "-o", "arch.json"]);
    refused(
        &d,
        &["limit", "arch.json", "--least-friction-precision", "1e-3"],
        "--least-friction-precision applies to the canonical selection: add --canonical",
    );
}
