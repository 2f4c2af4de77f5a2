//! Session 28 (lead), issue 29: two answers the CLI gives on ordinary models, checked as a user
//! reads them.
//!
//! 1. The least μ above masonry's friction (docs/canonical.md "The forces"): on a force program
//!    of 20,000 columns and more (the 1,800-block stack-bond wall) the default search stops
//!    where μ = 2 is shown inadmissible and states the bracket; `--least-friction-precision`
//!    searches on. Checked against the field the JSON holds (Coulomb's rule at the μ stated)
//!    and against the full search, whose least μ must lie in the bracket.
//! 2. The capacity curve of the grid façade loses its equilibrium at the onset of settlement,
//!    while `settle` says the structure accommodates the settlement: both hold, because the
//!    settlement's forces need shear across its open joints (`canonical.forces.physical`
//!    false, `largest_open_force` > 0). The capacity message now says so; `settle` on the same
//!    model is the independent check.

use crate::common::{gen_model, json_file, run, tmpdir, w};

#[test]
fn session28_the_least_mu_above_masonrys_friction_is_a_bracket() {
    let d = tmpdir("s28", "friction-limit");
    gen_model(&d, "wall --courses 30 --units 60 --unit 1,0.5 -o wall.json");
    let args = "settle wall.json --profile uniform:0,18,-0.01";
    let text = run(&d, &w(&format!("{args} -o default.json")));
    assert!(
        text.contains("the least μ lies between 2.0000 (shown inadmissible) and")
            && text.contains(
                "more than masonry's friction, so Heyman's no-sliding rule carries this field"
            ),
        "{text}"
    );
    let r = json_file(&d.join("default.json"));
    assert_eq!(r["certificate"]["ok"], true);
    let f = &r["canonical"]["forces"];
    assert_eq!(f["least_friction_above"].as_f64(), Some(2.0));
    let upper = f["least_friction"].as_f64().unwrap();
    let mu = f["friction"].as_f64().unwrap();
    assert!(upper > 2.0 && mu >= upper, "{f}");
    // The field in the JSON holds |shear| ≤ μ·normal at every point, to 1e-7 of its largest
    // force.
    let (mut excess, mut big) = (f64::NEG_INFINITY, 0.0f64);
    for p in r["joints"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|j| j["points"].as_array().unwrap())
    {
        let (n, t) = (
            p["normal_force"].as_f64().unwrap(),
            p["shear_force"].as_f64().unwrap(),
        );
        excess = excess.max(t.abs() - mu * n);
        big = big.max(n.abs()).max(t.abs());
    }
    assert!(excess <= 1e-7 * big, "excess {excess} of {big} kN");

    // Asked for a precision, the search goes on: its least μ lies in the bracket, no bracket.
    run(
        &d,
        &w(&format!(
            "{args} --least-friction-precision 0.05 -o full.json"
        )),
    );
    let g = &json_file(&d.join("full.json"))["canonical"]["forces"];
    assert!(g.get("least_friction_above").is_none(), "{g}");
    let least = g["least_friction"].as_f64().unwrap();
    assert!(
        least > 2.0 && least <= upper,
        "least {least}, bracket (2, {upper}]"
    );
}

#[test]
fn session28_capacity_at_the_onset_says_why_settle_stands() {
    let d = tmpdir("s28", "onset-why");
    gen_model(&d, "facade --element 2.0 --live horizontal -o grid.json");
    let profile = "--profile uniform:11,22,-0.2";
    run(
        &d,
        &w(&format!("capacity grid.json --steps 2 {profile} -o c.json")),
    );
    let m = json_file(&d.join("c.json"))["message"]
        .as_str()
        .unwrap()
        .to_string();
    assert!(
        m.contains("no equilibrium (certified); the settlement analysis carries them only by shear across its open joints"),
        "{m}"
    );
    // The independent check: settle's own forces need shear at open points.
    run(&d, &w(&format!("settle grid.json {profile} -o s.json")));
    let s = json_file(&d.join("s.json"));
    assert_eq!(s["status"], "mechanism");
    let f = &s["canonical"]["forces"];
    assert_eq!(f["physical"], false, "{f}");
    assert!(f["largest_open_force"].as_f64().unwrap() > 1.0, "{f}");
}

/// Found by the realistic benchmark's re-run (h-bench, session 28): where the dead loads have no
/// field in Coulomb's cone (the 0.5 m grid façade with μ = 0.6: its gable cannot stand), the
/// non-associative `limit` printed the certified "no equilibrium" and then called it "the fixed
/// point of a heuristic iteration (0 LPs), not a certified bound". No iteration ran; the
/// statics decide it whatever the flow rule.
#[test]
fn session28_no_equilibrium_is_not_called_a_heuristic_fixed_point() {
    let d = tmpdir("s28", "nonassoc-cannot-stand");
    gen_model(&d, "facade --element 0.5 --live horizontal -o grid.json");
    run(
        &d,
        &w("limit grid.json --friction 0.6 --non-associative -o l.json"),
    );
    let r = json_file(&d.join("l.json"));
    let m = r["message"].as_str().unwrap();
    assert!(
        m.contains("no equilibrium under the dead loads") && m.contains("a Farkas certificate"),
        "{m}"
    );
    assert!(!m.contains("heuristic"), "{m}");
    assert!(
        m.contains("non-associative friction: no iteration ran"),
        "{m}"
    );
    assert!(r["friction_iteration"]["history"]
        .as_array()
        .unwrap()
        .is_empty());
}
