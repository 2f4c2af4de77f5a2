//! Issue 32, item 4 ("one vocabulary") through the binary: every renamed flag gives the same
//! bytes under its old and its new name; `--direction` has one syntax; the summaries of
//! identify, capacity, incremental and settle print lengths by the README's rule (openings in
//! mm, motions and displacements in cm, positions in m), checked against the JSON (× 1000,
//! × 100) within the printed precision; `--help` lists the new names.

use crate::common;
use crate::common::{gen_model, json, refused, run};
use std::path::{Path, PathBuf};

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("i32vocab", name)
}

/// `base` run with `old` and with `new` (each a list of extra arguments): the same stdout.
fn same(dir: &Path, base: &[&str], old: &[&str], new: &[&str]) -> String {
    let with = |extra: &[&str]| {
        let mut a: Vec<&str> = base.to_vec();
        a.extend_from_slice(extra);
        run(dir, &a)
    };
    let (a, b) = (with(old), with(new));
    assert!(!a.is_empty());
    assert_eq!(a, b, "{base:?}: {old:?} and {new:?} differ");
    a
}

/// The paper's arch with 16 voussoirs (quick), loaded on its left half.
fn arch(dir: &Path) -> String {
    gen_model(dir, "arch --voussoirs 16 --live left -o arch.json");
    "arch.json".into()
}

fn dxf_fixture() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../voussoir-io/tests/fixtures/lact3/arch_1.dxf")
        .to_str()
        .unwrap()
        .to_string()
}

/// The number just before `unit` after `label` on `line` ("largest settlement 1.4142 cm").
fn number_before(line: &str, label: &str, unit: &str) -> f64 {
    let rest = &line[line
        .find(label)
        .unwrap_or_else(|| panic!("{label} in {line}"))
        + label.len()..];
    let rest = rest.trim_start();
    let end = rest
        .find(&format!(" {unit}"))
        .unwrap_or_else(|| panic!("{unit} after {label} in {line}"));
    rest[..end]
        .trim()
        .parse()
        .unwrap_or_else(|_| panic!("a number after {label} in {line}"))
}

/// No length in bare e-notation: no "1.2e-3" anywhere in a summary.
fn no_e_notation(summary: &str, skip: &[&str]) {
    for line in summary
        .lines()
        .filter(|l| !skip.iter().any(|s| l.starts_with(s)))
    {
        let b = line.as_bytes();
        for i in 1..b.len().saturating_sub(1) {
            assert!(
                !(b[i] == b'e'
                    && b[i - 1].is_ascii_digit()
                    && (b[i + 1] == b'-' || b[i + 1].is_ascii_digit())),
                "e-notation in: {line}"
            );
        }
    }
}

#[test]
fn issue32_item4_incremental_move_and_direction() {
    let d = tmpdir("incremental");
    let a = arch(&d);
    let base = [
        "incremental",
        a.as_str(),
        "--control",
        "0,3.19",
        "--max",
        "1mm",
        "--step",
        "0.5mm",
        "--fixed",
        "right",
        "--json",
    ];
    // `--settle` is the old name of `--move`.
    same(
        &d,
        &base,
        &["--settle", "right=0,-1mm"],
        &["--move", "right=0,-1mm"],
    );
    // One direction syntax: the old vector, the axis and the angle.
    let plain = &[&base[..8], &["--json"][..]].concat()[..];
    let r = same(&d, plain, &["--direction", "1,0"], &["--direction", "+x"]);
    same(&d, plain, &["--direction", "1,0"], &["--direction", "0"]);
    assert_eq!(
        json(&r)["control"]["direction"],
        serde_json::json!([1.0, 0.0])
    );
    let up = same(&d, plain, &["--direction", "0,1"], &["--direction=+y"]);
    same(&d, plain, &["--direction", "0,1"], &["--direction", "90"]);
    assert_eq!(
        json(&up)["control"]["direction"],
        serde_json::json!([0.0, 1.0])
    );
    same(&d, plain, &["--direction=-1,0"], &["--direction=-x"]);
    // 45°: the vector (cos 45°, sin 45°), normalised by the analysis as (1, 1) is.
    let diag = json(&run(&d, &[plain, &["--direction", "45"][..]].concat()));
    let vec = json(&run(&d, &[plain, &["--direction", "1,1"][..]].concat()));
    for k in 0..2 {
        let (p, q) = (
            diag["control"]["direction"][k].as_f64().unwrap(),
            vec["control"]["direction"][k].as_f64().unwrap(),
        );
        assert!((p - q).abs() < 1e-12, "{p} against {q}");
    }
    // A vertical or 3D direction has no meaning in a 2D model: refused, naming the flag.
    refused(
        &d,
        &[plain, &["--direction", "+z"][..]].concat(),
        "--direction +z",
    );
    refused(
        &d,
        &[plain, &["--direction", "1,0,0"][..]].concat(),
        "--direction 1,0,0",
    );
    refused(
        &d,
        &[plain, &["--direction", "0,0"][..]].concat(),
        "--direction",
    );
}

#[test]
fn issue32_item4_tilt_and_gen_block_direction() {
    let d = tmpdir("tilt");
    // gen block: `--azimuth` is the old name of `--direction`; +y is 90°.
    same(
        &d,
        &["gen", "block"],
        &["--azimuth", "30"],
        &["--direction", "30"],
    );
    same(
        &d,
        &["gen", "block"],
        &["--azimuth", "90"],
        &["--direction", "+y"],
    );
    same(
        &d,
        &["gen", "block"],
        &["--azimuth", "90"],
        &["--direction", "0,2"],
    );
    gen_model(&d, "block -o b.json");
    let base = ["tilt", "b.json", "--json"];
    same(&d, &base, &["--azimuth", "30"], &["--direction", "30"]);
    let minus = same(&d, &base, &["--azimuth", "180"], &["--direction", "-x"]);
    same(&d, &base, &["--azimuth", "180"], &["--direction=-1,0"]);
    assert_eq!(json(&minus)["azimuth"].as_f64(), Some(180.0));
    let y = same(&d, &base, &["--azimuth", "90"], &["--direction", "+y"]);
    same(&d, &base, &["--azimuth", "90"], &["--direction", "0,1"]);
    assert_eq!(json(&y)["azimuth"].as_f64(), Some(90.0));
    // Hand calculation: the 1 × 1 × 2 box overturns when the resultant of W and λW along the
    // azimuth, from the centroid at height 1, leaves the square base [-0.5, 0.5]²: at
    // λ = 0.5 / cos(az) for az in [0, 45°] (0.5 along ±x).
    let angle = |t: &str| json(t)["tilt_angle"].as_f64().unwrap();
    let tan0 = angle(&minus).to_radians().tan();
    assert!((tan0 - 0.5).abs() < 1e-6, "{tan0}");
    let t30 = angle(&run(&d, &["tilt", "b.json", "--direction", "30", "--json"]));
    let expect = (0.5 / 30f64.to_radians().cos()).atan().to_degrees();
    assert!((t30 - expect).abs() < 1e-6, "{t30} against {expect}");
    // The summary names the axis it was given.
    let s = run(&d, &["tilt", "b.json", "--direction", "+y"]);
    assert!(s.contains("towards +y (azimuth 90°)"), "{s}");
    refused(
        &d,
        &["tilt", "b.json", "--direction", "0,0,1"],
        "must be horizontal",
    );
    // 2D: along x only.
    gen_model(&d, "wall --live horizontal -o w.json");
    let base = ["tilt", "w.json", "--json"];
    same(&d, &base, &["--direction", "-x"], &["--direction", "180"]);
    same(&d, &base, &["--direction", "-x"], &["--azimuth", "180"]);
    same(&d, &base, &["--direction", "+x"], &["--direction", "2,0"]);
    refused(
        &d,
        &["tilt", "w.json", "--direction", "+y"],
        "a 2D model tilts along x",
    );
}

#[test]
fn issue32_item4_sweep_counts() {
    let d = tmpdir("sweep");
    let a = arch(&d);
    let base = [
        "sweep",
        a.as_str(),
        "--move",
        "right=0.01,0",
        "--threads",
        "1",
    ];
    let m = same(&d, &base, &["--steps", "2"], &["--magnitudes", "2"]);
    assert_eq!(m.lines().count(), 3, "{m}");
    let g = same(&d, &base, &["--directions", "2"], &["--angles", "2"]);
    assert_eq!(g.lines().count(), 3, "{g}");
    refused(
        &d,
        &[
            "sweep",
            &a,
            "--move",
            "right=0.01,0",
            "--magnitudes",
            "2",
            "--angles",
            "2",
        ],
        "give exactly one of --magnitudes, --angles, --samples",
    );
}

#[test]
fn issue32_item4_import_live_and_weld() {
    let d = tmpdir("import");
    let dxf = dxf_fixture();
    let base = ["import", dxf.as_str(), "--units", "mm"];
    same(&d, &base, &["--dxf-live", "none"], &["--live", "none"]);
    same(
        &d,
        &base,
        &["--dxf-live", "horizontal"],
        &["--live", "horizontal"],
    );
    same(
        &d,
        &base,
        &["--merge-tolerance", "0.001"],
        &["--weld", "0.001"],
    );
    // Meshes: `--mesh-live` is the old name of `--live` too.
    gen_model(&d, "block -o b.json");
    run(&d, &["export", "b.json", "-o", "b.obj"]);
    let none = same(
        &d,
        &["import", "b.obj"],
        &["--mesh-live", "none"],
        &["--live", "none"],
    );
    same(
        &d,
        &["import", "b.obj"],
        &["--dxf-live", "none"],
        &["--live", "none"],
    );
    assert!(json(&none)["loads"]["live"]
        .as_array()
        .is_none_or(|l| l.is_empty()));
    same(
        &d,
        &["limit", "b.obj", "--json"],
        &["--mesh-live", "horizontal"],
        &["--live", "horizontal"],
    );
    same(
        &d,
        &["limit", "b.obj", "--json"],
        &["--merge-tolerance", "1e-6"],
        &["--weld", "1e-6"],
    );
    // A JSON model carries its own loads: refused by the flag's one name.
    refused(
        &d,
        &["limit", "b.json", "--dxf-live", "none"],
        "--live applies to imported DXF drawings and OBJ/PLY meshes only",
    );
}

#[test]
fn issue32_item4_safety_flags() {
    let d = tmpdir("safety");
    let a = arch(&d);
    same(
        &d,
        &["safety", &a, "--json"],
        &["--no-reactions"],
        &["--no-ranges"],
    );
    same(
        &d,
        &["least-thickness", "arch", "--voussoirs", "16", "--json"],
        &["--relative-tolerance", "1e-3"],
        &["--bisection-tolerance", "1e-3"],
    );
}

#[test]
fn issue32_item4_old_names_hidden_new_names_listed() {
    let d = tmpdir("help");
    let help = |cmd: &[&str]| run(&d, &[cmd, &["--help"][..]].concat());
    for (cmd, new, old) in [
        (&["incremental"][..], "--move", "--settle"),
        (
            &["incremental"][..],
            "--direction <DIR>",
            "--direction <DX,DY>",
        ),
        (&["tilt"][..], "--direction <DIR>", "--azimuth <"),
        (&["gen", "block"][..], "--direction <DIR>", "--azimuth <"),
        (&["sweep"][..], "--magnitudes <N>", "--steps <"),
        (&["sweep"][..], "--angles <N>", "--directions <"),
        (&["import"][..], "--live <LIVE>", "--dxf-live <"),
        (&["import"][..], "--weld <M>", "--merge-tolerance <"),
        (&["limit"][..], "--live <LIVE>", "--mesh-live <"),
        (&["settle"][..], "--weld <M>", "--merge-tolerance <"),
        (&["safety"][..], "--no-ranges", "--no-reactions"),
        (
            &["least-thickness", "arch"][..],
            "--bisection-tolerance <REL>",
            "--relative-tolerance <",
        ),
    ] {
        let h = help(cmd);
        assert!(h.contains(new), "`{cmd:?} --help` lacks {new}: {h}");
        assert!(
            !h.lines().any(|l| l.trim_start().starts_with(old)),
            "`{cmd:?} --help` still lists {old}"
        );
    }
    // An old name on a command it does not belong to is named with its command.
    let a = arch(&d);
    refused(
        &d,
        &["limit", &a, "--settle", "right=0,-1mm"],
        "it is a flag of `incremental`",
    );
}

#[test]
fn issue32_item4_capacity_summary_in_cm() {
    let d = tmpdir("capacity");
    let a = arch(&d);
    let args = [
        "capacity",
        a.as_str(),
        "--move",
        "right=0.02,0",
        "--steps",
        "8",
    ];
    let text = run(&d, &args);
    let r = json(&run(&d, &[&args[..], &["--json"][..]].concat()));
    no_e_notation(&text, &[]);
    let line = text
        .lines()
        .find(|l| l.contains("largest settlement"))
        .unwrap();
    let largest = number_before(line, "largest settlement", "cm");
    assert!((largest - 100.0 * r["max_settlement"].as_f64().unwrap()).abs() <= 0.5e-4);
    assert!(
        (largest - 2.0).abs() <= 0.5e-4,
        "the --move given, 2 cm: {line}"
    );
    let line = text
        .lines()
        .find(|l| l.starts_with("zero-capacity"))
        .unwrap();
    let z = number_before(line, "settlement:", "cm");
    let zj = 100.0 * r["zero_capacity_settlement"].as_f64().unwrap();
    assert!((z - zj).abs() <= 0.5e-4, "{z} against {zj}");
    // The table: s in cm, each row the JSON's settlement × 100 to the 5 decimals printed.
    let start = text.lines().position(|l| l.contains("s (cm)")).unwrap() + 1;
    let rows: Vec<f64> = text
        .lines()
        .skip(start)
        .take_while(|l| !l.contains("LP solves"))
        .map(|l| l.split_whitespace().next().unwrap().parse().unwrap())
        .collect();
    let curve = r["curve"].as_array().unwrap();
    assert_eq!(rows.len(), curve.len());
    for (x, p) in rows.iter().zip(curve) {
        let s = 100.0 * p["settlement"].as_f64().unwrap();
        assert!((x - s).abs() <= 0.5e-5, "{x} against {s}");
    }
    let fit = text.lines().find(|l| l.starts_with("linear fit")).unwrap();
    assert!(fit.contains("(s in cm)"), "{fit}");
}

#[test]
fn issue32_item4_incremental_summary_in_cm() {
    let d = tmpdir("incremental-summary");
    let a = arch(&d);
    let args = [
        "incremental",
        a.as_str(),
        "--control",
        "0,3.19",
        "--max",
        "2mm",
        "--step",
        "0.25mm",
    ];
    let text = run(&d, &args);
    let r = json(&run(&d, &[&args[..], &["--json"][..]].concat()));
    no_e_notation(&text, &[]);
    assert!(!text.contains(" mm"), "{text}");
    let start = text.lines().position(|l| l.contains("dx (cm)")).unwrap() + 1;
    let rows: Vec<(f64, f64)> = text
        .lines()
        .skip(start)
        .take_while(|l| !l.contains("LP solves"))
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            (v[0], v[1])
        })
        .collect();
    let curve = r["curve"].as_array().unwrap();
    assert!(rows.len() >= 2 && rows.len() <= curve.len());
    // Every row is a point of the curve: its displacement × 100 to the 4 decimals printed.
    for (x, l) in &rows {
        assert!(
            curve.iter().any(|p| {
                (100.0 * p["displacement"].as_f64().unwrap() - x).abs() <= 0.5e-4
                    && (p["load_multiplier"].as_f64().unwrap() - l).abs() <= 0.5e-6
            }),
            "row {x} cm, λ {l} is not a point of the curve"
        );
    }
    // The steps are 0.25 mm = 0.025 cm apart (the --step given).
    assert!(
        ((rows[1].0 - rows[0].0).abs() - 0.025).abs() < 1e-9,
        "{rows:?}"
    );
    let peak = r["peak_displacement"].as_f64().unwrap();
    let msg = text.lines().find(|l| l.starts_with("peak λ")).unwrap();
    let shown = number_before(msg, "control displacement of", "cm");
    assert!((shown - 100.0 * peak).abs() <= 0.5e-4, "{msg}");
}

#[test]
fn issue32_item4_settle_summary_units() {
    let d = tmpdir("settle");
    let a = arch(&d);
    let args = ["settle", a.as_str(), "--move", "right=1cm,-5mm,0.1"];
    let text = run(&d, &args);
    let r = json(&run(&d, &[&args[..], &["--json"][..]].concat()));
    // The motion: u, v in cm, θ in mrad (0.1° = 1.7453 mrad), against the JSON's geometry.
    let line = text
        .lines()
        .find(|l| l.starts_with("motion") && l.contains("right:"))
        .unwrap_or_else(|| panic!("{text}"));
    let m = &r["geometry"]["supports"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == "right")
        .unwrap()["motion"];
    let u = number_before(line, "u ", "cm");
    let v = number_before(line, "v ", "cm");
    let t = number_before(line, "θ ", "mrad");
    assert!((u - 100.0 * m[0].as_f64().unwrap()).abs() <= 0.5e-4 && (u - 1.0).abs() <= 0.5e-4);
    assert!((v - 100.0 * m[1].as_f64().unwrap()).abs() <= 0.5e-4 && (v + 0.5).abs() <= 0.5e-4);
    let mrad = 0.1f64.to_radians() * 1000.0;
    assert!((t - 1000.0 * m[2].as_f64().unwrap()).abs() <= 0.5e-4 && (t - mrad).abs() <= 0.5e-4);
    // The hinges: positions in m, the JSON's to the 4 decimals printed.
    let hinges = r["hinges"].as_array().unwrap();
    assert!(!hinges.is_empty());
    for h in hinges {
        let j = h["joint"].as_u64().unwrap();
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("joint {j:>4} (")))
            .unwrap_or_else(|| panic!("joint {j} in {text}"));
        assert!(line.ends_with(" m"), "{line}");
        let inner = &line[line.find(" at (").unwrap() + 5..line.rfind(')').unwrap()];
        let xy: Vec<f64> = inner.split(", ").map(|x| x.parse().unwrap()).collect();
        assert!((xy[0] - h["x"].as_f64().unwrap()).abs() <= 0.5e-4, "{line}");
        assert!((xy[1] - h["y"].as_f64().unwrap()).abs() <= 0.5e-4, "{line}");
    }
    // Works and the canonical crack area are not lengths; nothing else is in e-notation.
    no_e_notation(&text, &["work of", "canonical:"]);
}

#[test]
fn issue32_item4_identify_summary_units() {
    let d = tmpdir("identify");
    gen_model(
        &d,
        "arch --radius 2.86 --thickness 0.33 --voussoirs 64 --live none -o arch.json",
    );
    // docs/identify.md's worked example: the survey of the arch spreading by 1 cm.
    std::fs::write(
        d.join("cracks.json"),
        r#"{ "tolerance": 0.0001,
  "cracks": [ {"at": [-2.56, 1.90], "opening": 0.0011},
              {"at": [0.0, 2.86],   "opening": 0.0022},
              {"at": [2.56, 1.90],  "opening": 0.0011} ] }"#,
    )
    .unwrap();
    let args = [
        "identify",
        "arch.json",
        "--cracks",
        "cracks.json",
        "--unknown",
        "right=u[0:]",
    ];
    let text = run(&d, &args);
    let r = json(&run(&d, &[&args[..], &["--json"][..]].concat()));
    no_e_notation(&text, &[]);
    // The unknown: cm, the JSON's value × 100; about the true 1 cm (docs/identify.md: 9.91 mm).
    let line = text.lines().find(|l| l.contains("right.u")).unwrap();
    let u = number_before(line, "=", "cm");
    let uj = r["unknowns"][0]["value"].as_f64().unwrap();
    assert!((u - 100.0 * uj).abs() <= 0.5e-4, "{line}");
    assert!((u - 0.991).abs() < 0.001, "{line}");
    // The range, in cm too.
    let lo = r["unknowns"][0]["range_min"].as_f64().unwrap();
    let range = &line[line.find("range [").unwrap() + 7..];
    let shown_lo: f64 = range.split(',').next().unwrap().parse().unwrap();
    assert!((shown_lo - 100.0 * lo).abs() <= 0.5e-4, "{line}");
    // The support motion in cm.
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("right: u"))
        .unwrap();
    let mu = number_before(line, "u", "cm");
    assert!((mu - 100.0 * r["support_motions"][0]["u"].as_f64().unwrap()).abs() <= 0.5e-4);
    // The widths in mm: observed = the survey's (1.1, 2.2, 1.1 mm), predicted = the JSON's.
    let obs = r["observations"].as_array().unwrap();
    let lines: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_start().starts_with("crack "))
        .collect();
    assert_eq!(lines.len(), obs.len());
    for (line, o) in lines.iter().zip(obs) {
        let seen = number_before(line, "observed", "mm");
        let pred = number_before(line, "predicted", "mm");
        assert!(
            (seen - 1000.0 * o["observed"].as_f64().unwrap()).abs() <= 0.5e-3,
            "{line}"
        );
        assert!(
            (pred - 1000.0 * o["predicted"].as_f64().unwrap()).abs() <= 0.5e-3,
            "{line}"
        );
        assert!([1.1, 2.2].iter().any(|w| (seen - w).abs() < 1e-9), "{line}");
        assert!(line.contains(") m: "), "positions in m: {line}");
    }
}
