//! Session 25, trust (helper h-trust):
//! - an option typed with its default value in a mode where it does nothing was accepted while
//!   any other value was refused (`sweep --magnitudes 2 --seed 1`, `--cov 0.3`,
//!   `--capacity-steps 40`; `--crushing linear` on a model that cannot crush, or in 3D): the
//!   checks now ask whether the option was given, not whether its value is the default's;
//!   `gen arch --half-angle`/`--offset` with another `--shape` were ignored: refused;
//!   `bench --scenario realistic` compared the wall benchmark's flags with their defaults, and
//!   `--friction-cone pyramid` passed on a 2D model where `exact` was refused: both refused;
//! - a structure drawn at micrometre size printed its lengths as 0.0000 m / 0.000 mm: small
//!   lengths above the round-off now print in significant digits (voussoir::lengths);
//! - the 2D `tilt` summary did not count the supports (3D did).

use crate::common::{gen_model, json, json_file, refused, run, tmpdir, w};

#[test]
fn session25_sweep_options_of_another_mode_refused_at_their_default_value() {
    let d = tmpdir("s25", "sweep");
    gen_model(&d, "arch --voussoirs 16 --live full -o arch.json");
    let base = "sweep arch.json --move right=0.01,0 --magnitudes 2";
    // The defaults' own values, refused as any other value is.
    for (extra, needle) in [
        (
            "--seed 1",
            "--seed 1: applies to the Monte Carlo samples of --samples N only",
        ),
        (
            "--seed 2",
            "--seed 2: applies to the Monte Carlo samples of --samples N only",
        ),
        (
            "--cov 0.3",
            "--cov 0.3: applies to the Monte Carlo samples of --samples N only",
        ),
        (
            "--capacity-steps 40",
            "--capacity-steps 40: the intervals of the capacity curves of --capacity",
        ),
    ] {
        refused(&d, &w(&format!("{base} {extra} --csv out.csv")), needle);
        assert!(!d.join("out.csv").exists(), "{extra}");
    }
    // With --samples, --seed 1 is the default: the same records as without it.
    let mc = "sweep arch.json --move right=0.01,0 --samples 2";
    let without = run(&d, &w(mc));
    let with = run(&d, &w(&format!("{mc} --seed 1 --cov 0.3")));
    assert_eq!(without, with);
    assert_eq!(without.lines().count(), 3, "{without}");
    // … and another seed gives other samples.
    assert_ne!(run(&d, &w(&format!("{mc} --seed 2"))), without);
}

#[test]
fn session25_arch_shape_parameters_refused_with_another_shape() {
    let d = tmpdir("s25", "shape");
    refused(
        &d,
        &w("gen arch --half-angle 60 -o a.json"),
        "--half-angle 60: applies to --shape segmental only",
    );
    refused(
        &d,
        &w("gen arch --shape segmental --offset 0.5 -o a.json"),
        "--offset 0.5: applies to --shape pointed only",
    );
    refused(
        &d,
        &w("gen vault --shape pointed --half-angle 30 -o v.json"),
        "--half-angle 30: applies to --shape segmental only",
    );
    assert!(!d.join("a.json").exists() && !d.join("v.json").exists());
    // Given with their own shape, the defaults' values give the default arch; others another.
    let seg = gen_model(&d, "arch --shape segmental");
    assert_eq!(seg, gen_model(&d, "arch --shape segmental --half-angle 60"));
    assert_ne!(seg, gen_model(&d, "arch --shape segmental --half-angle 50"));
    let pointed = gen_model(&d, "arch --shape pointed");
    assert_eq!(pointed, gen_model(&d, "arch --shape pointed --offset 0.5"));
}

#[test]
fn session25_crushing_given_where_nothing_can_crush_refused_whatever_its_value() {
    let d = tmpdir("s25", "crushing");
    gen_model(&d, "arch --voussoirs 16 --live full -o arch.json");
    for value in ["linear", "conic"] {
        refused(
            &d,
            &["limit", "arch.json", "--crushing", value],
            &format!("--crushing {value} needs a compressive strength"),
        );
    }
    gen_model(&d, "vault --voussoirs 8 --depth 1 --rings 1 -o vault.json");
    refused(
        &d,
        &w("limit vault.json --crushing linear"),
        "modelled in 2D only",
    );
    // With a strength, `--crushing linear` is the default: the same λ as without it.
    let lambda = |extra: &str| {
        json(&run(
            &d,
            &w(&format!(
                "limit arch.json --compressive-strength 5000 --json {extra}"
            )),
        ))["load_multiplier"]
            .as_f64()
            .unwrap()
    };
    let (plain, linear) = (lambda(""), lambda("--crushing linear"));
    assert_eq!(plain, linear);
    // The strength lowers Heyman's λ of the rigid arch (16 voussoirs: above 0).
    let rigid = json(&run(&d, &w("limit arch.json --json")))["load_multiplier"]
        .as_f64()
        .unwrap();
    assert!(plain > 0.0 && plain < rigid, "{plain} vs {rigid}");
}

/// The number after `key` in `line` (up to the next space or comma).
fn number_after(line: &str, key: &str) -> String {
    let at = line.find(key).unwrap_or_else(|| panic!("{key} in {line}")) + key.len();
    line[at..]
        .split([' ', ','])
        .next()
        .unwrap()
        .trim_matches(['(', ')'])
        .to_string()
}

/// `x` printed as `printed` (fixed or e-notation, in `unit_factor` units of m): equal to the
/// printed digits, and the printed text has at least four significant digits.
fn agrees(printed: &str, si: f64, unit_factor: f64) {
    let v: f64 = printed.parse().unwrap_or_else(|_| panic!("{printed}"));
    assert!(v != 0.0, "{printed} printed for {si}");
    let digits = printed
        .split(['e', 'E'])
        .next()
        .unwrap()
        .chars()
        .filter(|c| c.is_ascii_digit())
        .skip_while(|c| *c == '0')
        .count();
    assert!(digits >= 4, "{printed}: {digits} significant digits");
    let x = si * unit_factor;
    // Rounded to the digits printed: within half a unit of the last one.
    assert!(
        (v - x).abs() <= 0.5e-3 * x.abs() * 1.000001,
        "{printed} against {x}"
    );
}

#[test]
fn session25_a_micrometre_arch_prints_its_lengths_in_significant_digits() {
    let d = tmpdir("s25", "micro");
    // The paper's arch a million times smaller (R = 2.86 µm, t = 0.33 µm), 16 voussoirs.
    gen_model(
        &d,
        "arch --voussoirs 16 --radius 2.86e-6 --thickness 0.33e-6 --live full -o arch.json",
    );
    // Settlement: the right springing 10 nm out; crack widths in mm, motions in cm, lengths
    // and positions in m (they printed "< 0.001 mm wide", "0.0000 cm", "0.0000 m").
    let out = run(
        &d,
        &w("settle arch.json --move right=1e-8,0 -o s.json --raw"),
    );
    let r = json_file(&d.join("s.json"));
    let motion = out
        .lines()
        .find(|l| l.starts_with("motion") && l.contains("right"))
        .unwrap_or_else(|| panic!("{out}"));
    agrees(&number_after(motion, "u "), 1e-8, 1e2);
    assert!(motion.contains(" cm"), "{motion}");
    let crack = &r["cracks"][0];
    let widest = crack["max_opening"].as_f64().unwrap();
    // The crown's crack: the springing's 10 nm opens it by about 2 nm.
    assert!(widest > 1e-9 && widest < 1e-8, "{widest}");
    let first = out
        .lines()
        .find(|l| l.trim_start().starts_with("crack  1:"))
        .unwrap_or_else(|| panic!("{out}"));
    agrees(&number_after(first, "crack  1: "), widest, 1e3);
    assert!(first.contains(" mm wide, "), "{first}");
    // Its length: the ring's thickness, 0.33 µm.
    let length = crack["length"].as_f64().unwrap();
    assert!((length - 0.33e-6).abs() < 1e-15, "{length}");
    agrees(&number_after(first, "mm wide, "), length, 1.0);
    // The hinges' positions as the JSON's.
    for h in r["hinges"].as_array().unwrap() {
        let line = out
            .lines()
            .find(|l| {
                l.trim_start()
                    .starts_with(&format!("joint {:>4} ", h["joint"].as_u64().unwrap()))
            })
            .unwrap_or_else(|| panic!("{h} in {out}"));
        let at = &line[line.find("at (").unwrap() + 4..];
        let (xs, ys) = at.split_once(", ").unwrap();
        let ys = ys.split(')').next().unwrap();
        let (x, y) = (h["x"].as_f64().unwrap(), h["y"].as_f64().unwrap());
        assert!(y > 1e-6 && y < 4e-6, "{h}");
        agrees(ys, y, 1.0);
        if x.abs() > 1e-15 {
            agrees(xs, x, 1.0);
        } else {
            // The crown joint's x is the coordinates' round-off (1e-23 m): zero.
            assert_eq!(xs, "0.0000", "{line}");
        }
    }
    // Limit analysis: λ in six significant digits (session 24), the JSON's.
    let lim = run(&d, &w("limit arch.json -o l.json"));
    let lambda = json_file(&d.join("l.json"))["load_multiplier"]
        .as_f64()
        .unwrap();
    assert!(lambda > 1e-7 && lambda < 1e-6, "{lambda}");
    assert!(lim.contains(&format!("λ = {lambda:.6e}")), "{lim}");
    // Capacity: the largest settlement in cm and the linear fit's λ(0) as the JSON's (they
    // printed "0.0000 cm" and "λ ≈ 0 − 0.2941·s").
    let cap = run(
        &d,
        &w("capacity arch.json --move right=1e-8,0 --steps 4 -o c.json"),
    );
    let c = json_file(&d.join("c.json"));
    let first = cap.lines().nth(1).unwrap();
    agrees(&number_after(first, "largest settlement "), 1e-8, 1e2);
    let intercept = c["linear_fit"]["intercept"].as_f64().unwrap();
    assert!(intercept > 1e-7 && intercept < 1e-6, "{intercept}");
    let fit = cap
        .lines()
        .find(|l| l.starts_with("linear fit: λ ≈ "))
        .unwrap_or_else(|| panic!("{cap}"));
    agrees(&number_after(fit, "λ ≈ "), intercept, 1.0);
    // Incremental: λ at the start and in the table as λ (they printed 0.000001 and 0.000000).
    let inc = run(
        &d,
        &w("incremental arch.json --control 0,3.19e-6 --direction -y --max 1e-8 --step 2.5e-9 -o i.json"),
    );
    let curve = json_file(&d.join("i.json"))["curve"].clone();
    let l0 = curve[0]["load_multiplier"].as_f64().unwrap();
    assert!(l0 > 1e-7 && l0 < 1e-6, "{l0}");
    assert!(inc.contains(&format!("λ at the start {l0:.6e} ")), "{inc}");
    let l1 = curve[1]["load_multiplier"].as_f64().unwrap();
    assert!(l1 > 0.0 && l1 < l0, "{l1}");
    assert!(inc.contains(&format!("    2.500e-7  {l1:.6e}")), "{inc}");
}

#[test]
fn session25_a_metre_arch_prints_its_lengths_as_before() {
    // The paper's arch at full size: widths with three decimals of mm, positions with four
    // of m, the crown joint's x (round-off, ~1e-16 m, below 1e-9 of the size) as 0.0000.
    let d = tmpdir("s25", "roundoff");
    gen_model(&d, "arch --live full -o arch.json");
    let out = run(
        &d,
        &w("settle arch.json --move right=0.01,0 -o s.json --raw"),
    );
    let r = json_file(&d.join("s.json"));
    let crack = &r["cracks"][0];
    let widest = crack["max_opening"].as_f64().unwrap();
    assert!(
        out.contains(&format!(
            "crack  1: {:.3} mm wide, 0.3300 m long",
            widest * 1e3
        )),
        "{out}"
    );
    let crown = crack["points"][0][0].as_f64().unwrap();
    assert!(crown != 0.0 && crown.abs() < 1e-12, "{crown}");
    assert!(
        out.contains("from (0.0000, 2.8600) to (0.0000, 3.1900) m"),
        "{out}"
    );
}

#[test]
fn session25_two_d_tilt_counts_its_supports() {
    let d = tmpdir("s25", "tilt");
    gen_model(&d, "wall --live horizontal -o wall.json");
    let m = json_file(&d.join("wall.json"));
    let blocks = m["blocks"].as_array().unwrap().len();
    let supports = m["supports"].as_array().unwrap().len();
    assert!(blocks > 1 && supports >= 1);
    let out = run(&d, &w("tilt wall.json"));
    let first = out.lines().next().unwrap();
    let prefix = format!("blocks {blocks}, joints ");
    assert!(first.starts_with(&prefix), "{first}");
    assert!(
        first.ends_with(&format!(", supports {supports}")),
        "{first}"
    );
    // The same line as limit's (its first line counts the same structure).
    let limit = run(&d, &w("limit wall.json"));
    assert_eq!(limit.lines().next().unwrap(), first);
}

#[test]
fn session25_bench_and_friction_cone_flags_refused_at_their_default_value() {
    let d = tmpdir("s25", "bench");
    // `bench --scenario realistic` refuses the wall benchmark's flags: it compared them with
    // their defaults, so the defaults' values typed out passed.
    for (extra, flag) in [
        ("--sizes 1000,4000,16000,64000", "--sizes"),
        ("--friction-cone pyramid", "--friction-cone"),
        ("--solver-tolerance 1e-9", "--solver-tolerance"),
        ("--form force", "--form"),
        ("--geometry-sizes 100000", "--geometry-sizes"),
        ("--analysis both", "--analysis (use --analyses)"),
    ] {
        refused(
            &d,
            &w(&format!(
                "bench --scenario realistic --models arch --analyses limit {extra}"
            )),
            &format!("{flag}: does not apply to --scenario realistic"),
        );
    }
    // `--friction-cone` on a 2D model: `exact` was refused, `pyramid` passed; both refused.
    gen_model(&d, "arch --voussoirs 16 --live full -o arch.json");
    for cone in ["pyramid", "exact"] {
        refused(
            &d,
            &[
                "limit",
                "arch.json",
                "--friction",
                "0.6",
                "--friction-cone",
                cone,
            ],
            "--friction-facets and --friction-cone apply to 3D models",
        );
    }
}
