//! `voussoir sweep` and `voussoir merge` end to end on the paper's arch (intrados radius 2.86 m,
//! 0.33 m thick, 64 voussoirs): the sweep must reproduce single `settle` runs exactly, and the
//! paper's hinges (crown and the 13th joint from each springing) for an outward settlement.

use crate::common::cwd::ok as run;
use std::path::{Path, PathBuf};
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_voussoir"))
}

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-sweep-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn paper_arch(dir: &Path) -> String {
    let p = dir.join("arch.json");
    run(&["gen", "arch", "--live", "full", "-o", p.to_str().unwrap()]);
    p.to_str().unwrap().to_string()
}

fn lines(p: &Path) -> Vec<serde_json::Value> {
    std::fs::read_to_string(p)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

#[test]
fn hundred_magnitudes_match_hundred_single_runs() {
    let d = tmpdir("magnitudes");
    let arch = paper_arch(&d);
    let jl = d.join("sweep.jsonl");
    let csv = d.join("sweep.csv");
    let o = run(&[
        "sweep",
        &arch,
        "--move",
        "right=0.02,0",
        "--steps",
        "100",
        "--jsonl",
        jl.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(
        msg.contains("100 analyses") && msg.contains("100 certified"),
        "{msg}"
    );
    // One task per core: on this 2-core machine the sweep runs on both.
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    assert!(msg.contains(&format!("on {cores} threads")), "{msg}");
    let recs = lines(&jl);
    assert_eq!(recs.len(), 100);
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 101);
    for (k, r) in recs.iter().enumerate() {
        let s = (k + 1) as f64 / 100.0;
        assert_eq!(r["index"], k);
        assert!((r["parameter"].as_f64().unwrap() - s).abs() < 1e-15);
        let u = format!("right={},0", 0.02 * s);
        let single = run(&["settle", &arch, "--move", &u, "--json"]);
        let v: serde_json::Value = serde_json::from_slice(&single.stdout).unwrap();
        let (a, b) = (
            r["work_dead_loads"].as_f64().unwrap(),
            v["work_dead_loads"].as_f64().unwrap(),
        );
        assert!(
            (a - b).abs() <= 1e-9 * b.abs(),
            "step {k}: sweep {a}, single {b}"
        );
        let hinges: Vec<u64> = v["hinges"]
            .as_array()
            .unwrap()
            .iter()
            .map(|h| h["joint"].as_u64().unwrap())
            .collect();
        let swept: Vec<u64> = r["hinge_joints"]
            .as_array()
            .unwrap()
            .iter()
            .map(|h| h.as_u64().unwrap())
            .collect();
        assert_eq!(swept, hinges, "step {k}");
        // The paper (Figs 9–10): three hinges, the crown and the 13th joint from each springing
        // (joints are numbered from the left support: 0 is left|block 0, 32 the crown).
        assert_eq!(swept, vec![13, 32, 51], "step {k}");
        assert_eq!(r["certified"], true);
    }
    // Work is proportional to the settlement (both LPs are homogeneous of degree one).
    let w1 = recs[0]["work_dead_loads"].as_f64().unwrap();
    let w100 = recs[99]["work_dead_loads"].as_f64().unwrap();
    assert!((w100 / w1 - 100.0).abs() < 1e-9 * 100.0, "{w1} {w100}");
}

#[test]
fn shards_merge_into_the_whole_sweep_and_samples_repeat_with_their_seed() {
    let d = tmpdir("shards");
    let arch = paper_arch(&d);
    let p = |n: &str| d.join(n).to_str().unwrap().to_string();
    run(&[
        "sweep",
        &arch,
        "--move",
        "right=0.01,0",
        "--directions",
        "12",
        "--jsonl",
        &p("all.jsonl"),
    ]);
    for i in 0..3 {
        let shard = format!("{i}/3");
        run(&[
            "sweep",
            &arch,
            "--move",
            "right=0.01,0",
            "--directions",
            "12",
            "--shard",
            &shard,
            "--threads",
            "1",
            "--jsonl",
            &p(&format!("s{i}.jsonl")),
        ]);
    }
    run(&[
        "merge",
        &p("s2.jsonl"),
        &p("s0.jsonl"),
        &p("s1.jsonl"),
        "--jsonl",
        &p("merged.jsonl"),
    ]);
    assert_eq!(
        std::fs::read(p("merged.jsonl")).unwrap(),
        std::fs::read(p("all.jsonl")).unwrap()
    );
    let dirs = lines(Path::new(&p("all.jsonl")));
    assert_eq!(dirs.len(), 12);
    assert!((dirs[3]["parameter"].as_f64().unwrap() - 90.0).abs() < 1e-12);
    // Monte Carlo: the same seed gives the same samples whatever the number of threads.
    run(&[
        "sweep",
        &arch,
        "--move",
        "right=0.01,-0.005",
        "--samples",
        "8",
        "--seed",
        "42",
        "--jsonl",
        &p("mc1.jsonl"),
    ]);
    run(&[
        "sweep",
        &arch,
        "--move",
        "right=0.01,-0.005",
        "--samples",
        "8",
        "--seed",
        "42",
        "--threads",
        "1",
        "--jsonl",
        &p("mc2.jsonl"),
    ]);
    assert_eq!(
        std::fs::read(p("mc1.jsonl")).unwrap(),
        std::fs::read(p("mc2.jsonl")).unwrap()
    );
    let mc = lines(Path::new(&p("mc1.jsonl")));
    let u: Vec<f64> = mc
        .iter()
        .map(|r| r["motions"]["right"][0].as_f64().unwrap())
        .collect();
    assert!(u.windows(2).any(|w| w[0] != w[1]), "samples differ: {u:?}");
    // Duplicate shards are refused in one line.
    let o = bin()
        .args(["merge", &p("s0.jsonl"), &p("s0.jsonl")])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("more than one shard") && e.lines().count() == 1,
        "{e}"
    );
}
