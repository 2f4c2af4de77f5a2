//! Session 24, extreme inputs that were ignored or answered wrongly (lead):
//! - a compressive strength of 1e-200 kPa gave the rigid arch's λ (n² underflowed in the
//!   crushing chords, which then lay on the rigid |M| ≤ N t/2): the arch cannot stand;
//! - a `--profile` that is zero at every support's centre moved nothing, with or without a
//!   `--move` beside it, and the run went on as if the flag had not been given: refused in one
//!   line naming the flag, no output written;
//! - a motion within the round-off of the structure's coordinates (the paper's arch spreading
//!   1e-30 m: its energy QP failed; 1e-60 m: reported uncertified with zero work) is refused
//!   by `settle` and `capacity`, 2D and 3D (`request::MOTION_FLOOR`, 1e-14 of the size);
//! - a small motion above it is resolved: the work is proportional to the motion (the
//!   settlement programs are positively homogeneous in it), certified.

use crate::common::{gen_model, json, refused, run, tmpdir, w};

#[test]
fn session24_a_profile_that_moves_no_support_is_refused() {
    let d = tmpdir("s24m", "profile");
    gen_model(
        &d,
        "wall --courses 8 --units 10 --unit 0.4,0.2 -o wall.json",
    );
    // The wall spans x = 0 … 4 m; the profile settles x = 20 … 30 m.
    for extra in [&[][..], &["--move", "f9=0,-0.01"][..]] {
        let mut args = w("settle wall.json --profile uniform:20,30,-0.01 -o r.json");
        args.extend_from_slice(extra);
        refused(&d, &args, "--profile: the profile moves no support");
        assert!(!d.join("r.json").exists());
    }
    // The README's profile under the wall still settles it.
    let out = run(&d, &w("settle wall.json --profile uniform:2.8,4.0,-0.01"));
    assert!(out.contains("accommodates the settlement"), "{out}");
}

#[test]
fn session24_motions_within_round_off_are_refused_and_small_ones_resolved() {
    let d = tmpdir("s24m", "floor");
    gen_model(&d, "arch -o arch.json");
    for cmd in ["settle", "capacity"] {
        refused(
            &d,
            &[cmd, "arch.json", "--move", "right=1e-30,0", "-o", "r.json"],
            "below 1e-14 of the structure's size",
        );
        assert!(!d.join("r.json").exists());
    }
    gen_model(&d, "vault --depth 1 --rings 1 -o vault.json");
    refused(
        &d,
        &w("settle vault.json --move right=1e-40,0,0"),
        "below 1e-14 of the structure's size",
    );
    // 1 cm and 1e-12 m (1.4e-13 of the arch's size): the work in the ratio of the motions.
    let work = |u: &str| {
        let v = json(&run(
            &d,
            &[
                "settle",
                "arch.json",
                "--move",
                &format!("right={u},0"),
                "--json",
            ],
        ));
        assert_eq!(v["certificate"]["ok"], true, "{u}: {}", v["certificate"]);
        v["work_dead_loads"].as_f64().unwrap()
    };
    let (w0, w1) = (work("0.01"), work("1e-12"));
    assert!(w0 > 0.1, "{w0}");
    assert!(
        (w1 - w0 * 1e-10).abs() <= 1e-6 * w0 * 1e-10,
        "{w1} against {}",
        w0 * 1e-10
    );
}

/// The paper's arch with the live load on its right half: with f_c·w·t of 3e-201 kN against
/// voussoirs of about 0.5 kN, no joint carries its dead load, so it cannot stand, at 1e-150 as
/// at 1e-300 kPa (before: 0.218883, the rigid λ, from 1e-200 kPa down); at 1e4 kPa λ lies below
/// the rigid 0.218883 (crushing only lowers it), the conic model at or above the polygon's.
#[test]
fn session24_a_vanishing_compressive_strength_cannot_stand() {
    let d = tmpdir("s24m", "crushing");
    gen_model(&d, "arch --live right -o arch.json");
    let lam = |extra: &[&str]| {
        let mut a = vec!["limit", "arch.json", "--json"];
        a.extend_from_slice(extra);
        let v = json(&run(&d, &a));
        (
            v["status"].as_str().unwrap().to_string(),
            v["load_multiplier"].as_f64(),
        )
    };
    let (_, rigid) = lam(&[]);
    let rigid = rigid.unwrap();
    assert!((rigid - 0.218883).abs() < 1e-6, "{rigid}");
    for fc in ["1e-150", "1e-200", "1e-300"] {
        for crushing in ["linear", "conic"] {
            let (status, l) = lam(&["--compressive-strength", fc, "--crushing", crushing]);
            assert_eq!(status, "no_equilibrium", "f_c {fc} {crushing}: λ {l:?}");
        }
    }
    let (_, poly) = lam(&["--compressive-strength", "1e4"]);
    let (_, cone) = lam(&w("--compressive-strength 1e4 --crushing conic"));
    let (poly, cone) = (poly.unwrap(), cone.unwrap());
    assert!(
        poly < rigid && cone < rigid && cone >= poly - 1e-9,
        "{poly} {cone} {rigid}"
    );
}

/// `--keep-fixed` on a model without a fixed support changed nothing and was accepted: now
/// refused (capacity and incremental); with `--fixed` it runs and the curve keeps its reference
/// λ (the arch with the live load on its right half, 0.218883 before any settlement).
#[test]
fn session24_keep_fixed_without_a_fixed_support_is_refused() {
    let d = tmpdir("s24m", "keepfixed");
    gen_model(&d, "arch --live right -o arch.json");
    refused(
        &d,
        &w("capacity arch.json --move right=0.02,0 --steps 4 --keep-fixed"),
        "--keep-fixed keeps fixed supports fixed, but no support is fixed",
    );
    refused(
        &d,
        &w("incremental arch.json --control 0,3.19 --direction +x --max 1mm --step 0.5mm --move right=0.001,0 --keep-fixed"),
        "--keep-fixed keeps fixed supports fixed, but no support is fixed",
    );
    let out = run(
        &d,
        &w("capacity arch.json --move right=0,-0.01 --fixed right --steps 4 --keep-fixed"),
    );
    assert!(out.contains("from 0.218883 at no settlement"), "{out}");
}

/// `settle --non-associative` on a model without friction ran an iteration in which nothing can
/// slide; `limit` and `capacity` already refused it (h-audit): now `settle` does too. With
/// friction it runs.
#[test]
fn session24_settle_non_associative_without_friction_is_refused() {
    let d = tmpdir("s24m", "nonassoc");
    gen_model(&d, "arch -o arch.json");
    refused(
        &d,
        &w("settle arch.json --move right=0.01,0 --non-associative"),
        "--non-associative needs friction",
    );
    let out = run(
        &d,
        &w("settle arch.json --move right=0.01,0 --non-associative --friction 0.6"),
    );
    assert!(out.contains("accommodates the settlement"), "{out}");
}

/// A capacity curve's λ printed as itself when small (h-audit found `limit`'s "0.000000"; the
/// curve's summary had the same six decimals): the paper's arch drawn a million times smaller
/// has λ(0) = 1e-6 × 0.218883 (its weight scales with its area, its live load with its span).
#[test]
fn session24_a_small_capacity_curve_prints_its_multiplier() {
    let d = tmpdir("s24m", "smallcap");
    gen_model(
        &d,
        "arch --live right --radius 2.86e-6 --thickness 0.33e-6 -o tiny.json",
    );
    let out = run(&d, &w("capacity tiny.json --move right=2e-8,0 --steps 4"));
    let line = out.lines().find(|l| l.starts_with("λ falls from")).unwrap();
    let l: f64 = line["λ falls from ".len()..]
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((l - 0.218883e-6).abs() <= 1e-6 * l, "{line}");
}

/// `capacity --cold` asks for every step solved from scratch; with friction (or finite strength)
/// the steps are solved from scratch anyway, so the flag changed nothing and was accepted:
/// refused there. On Heyman's joints it runs, and gives the hot-started curve's λ(0).
#[test]
fn session24_cold_capacity_with_friction_is_refused() {
    let d = tmpdir("s24m", "cold");
    gen_model(&d, "arch --live right -o arch.json");
    let args = w("capacity arch.json --move right=0.02,0 --steps 4");
    let mut with_friction = args.clone();
    with_friction.extend_from_slice(&["--friction", "0.6", "--cold"]);
    refused(
        &d,
        &with_friction,
        "--cold: the steps of a curve with friction",
    );
    let mut cold = args.clone();
    cold.push("--cold");
    let (a, b) = (run(&d, &args), run(&d, &cold));
    let first = |s: &str| {
        s.lines()
            .find(|l| l.starts_with("λ falls from"))
            .unwrap()
            .to_string()
    };
    assert_eq!(first(&a), first(&b));
    assert!(first(&a).starts_with("λ falls from 0.218883"), "{a}");
}
