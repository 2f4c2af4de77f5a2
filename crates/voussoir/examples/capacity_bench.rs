//! Timing of capacity curves (limit analysis on the deformed geometry), with and without the
//! HiGHS hot start. Run in release mode:
//!
//! ```text
//! cargo run --release -p voussoir --example capacity_bench            # both cases
//! cargo run --release -p voussoir --example capacity_bench -- arch    # the paper's arch only
//! cargo run --release -p voussoir --example capacity_bench -- wall    # the 10,000-unit wall only
//! cargo run --release -p voussoir --example capacity_bench -- wall cold   # also from scratch
//! ```
//!
//! Prints the model size, the time of the curve, LP solves and simplex iterations. Numbers are
//! recorded in `docs/capacity.md`.

use std::time::Instant;
use voussoir::analysis::capacity::{capacity, CapacityOptions};
use voussoir::generate::{arch, wall, ArchSpec, LiveLoad, WallSpec};
use voussoir::settlement_input::{apply_profile, Profile};
use voussoir::{BuildOptions, Model, Structure};

fn run(name: &str, model: &Model, steps: usize, hot: bool) {
    let t = Instant::now();
    let st = Structure::new(model, BuildOptions::default()).expect("valid model");
    let build = t.elapsed();
    let npts: usize = st.joints.iter().map(|j| j.points.len()).sum();
    let t = Instant::now();
    let r = capacity(
        &st,
        &CapacityOptions {
            steps,
            hot_start: hot,
            mechanisms: false,
            ..Default::default()
        },
    )
    .expect("capacity curve");
    let el = t.elapsed();
    println!(
        "{name}: {} blocks, {} joints, {} points; {} curve points, hot start {hot}: {:.3} s \
         ({:.1} ms per point; {} LP solves, {} simplex iterations; model built in {:.3} s)",
        st.blocks.len(),
        st.joints.len(),
        npts,
        r.curve.len(),
        el.as_secs_f64(),
        1e3 * el.as_secs_f64() / r.curve.len() as f64,
        r.solves,
        r.iterations,
        build.as_secs_f64()
    );
    println!("  {}", r.message);
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let all = !args.iter().any(|a| a == "arch" || a == "wall");
    let cold = args.iter().any(|a| a == "cold");
    if all || args.iter().any(|a| a == "arch") {
        // The paper's arch, outward settlement of the right springing up to 2 cm: 100 points.
        let mut m = arch(&ArchSpec {
            live: LiveLoad::Full,
            ..ArchSpec::default()
        })
        .unwrap();
        m.supports[1].motion = [0.02, 0.0, 0.0];
        run("paper arch", &m, 99, true);
        run("paper arch", &m, 99, false);
    }
    if all || args.iter().any(|a| a == "wall") {
        // A running-bond wall of 100 courses × 100 units (10,050 blocks with the half units),
        // 40 m long, horizontal live load proportional to the weight (tilting table), the last
        // 2 m of its foundation (5 segments) settling by up to 2 cm: 40 points.
        let mut m = wall(&WallSpec {
            courses: 100,
            units: 100,
            live: LiveLoad::Horizontal,
            ..WallSpec::default()
        })
        .unwrap();
        let len = 100.0 * 0.4;
        apply_profile(
            &mut m,
            &Profile::Uniform {
                x0: len - 2.0,
                x1: len,
                v: -0.02,
            },
        )
        .unwrap();
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let t = Instant::now();
        let l = voussoir::analysis::limit(&st, &Default::default()).unwrap();
        println!(
            "wall: one limit analysis from scratch (presolve, dual simplex): {:.3} s, {} iterations, λ = {:?}",
            t.elapsed().as_secs_f64(),
            l.iterations,
            l.load_multiplier
        );
        run("wall", &m, 39, true);
        if cold {
            run("wall", &m, 39, false);
        }
    }
}
