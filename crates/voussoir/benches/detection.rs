//! Interface detection at scale: running-bond walls of 1,000 to 100,000 bricks.
//! `cargo bench -p voussoir --bench detection` prints model size and time per stage.

use std::time::Instant;
use voussoir::discretize::KinematicMap;
use voussoir::generate::{wall, WallSpec};
use voussoir::{BuildOptions, Structure};

fn main() {
    println!(
        "{:>9} {:>9} {:>9} {:>10} {:>12} {:>10}",
        "bricks", "joints", "points", "generate", "validate+detect", "assemble"
    );
    for (courses, units) in [(22, 45), (71, 141), (224, 447)] {
        let t0 = Instant::now();
        let m = wall(&WallSpec {
            courses,
            units,
            unit: [0.25, 0.055],
            ..WallSpec::default()
        })
        .unwrap();
        let t1 = Instant::now();
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let t2 = Instant::now();
        let map = KinematicMap::new(&st);
        let t3 = Instant::now();
        println!(
            "{:>9} {:>9} {:>9} {:>9.3}s {:>11.3}s {:>9.3}s",
            st.blocks.len(),
            st.joints.len(),
            map.num_points(),
            (t1 - t0).as_secs_f64(),
            (t2 - t1).as_secs_f64(),
            (t3 - t2).as_secs_f64()
        );
    }
}
