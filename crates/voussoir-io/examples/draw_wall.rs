//! Timing of the drawing of a 10 000-block wall (run with `--release`):
//!
//! ```text
//! cargo run --release -p voussoir-io --example draw_wall [-- COURSES UNITS OUT_DIR]
//! ```
//! Prints the time to draw the SVG and to render the PNG, and the file sizes.

use std::time::Instant;
use voussoir::generate::{wall, WallSpec};
use voussoir::result::{Geometry, SupportShape};
use voussoir_io::draw::{self, DrawOptions, Scene};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let courses = args.first().and_then(|s| s.parse().ok()).unwrap_or(100);
    let units = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(100);
    let out = std::path::PathBuf::from(
        args.get(2)
            .cloned()
            .unwrap_or_else(|| std::env::temp_dir().display().to_string()),
    );
    let m = wall(&WallSpec {
        courses,
        units,
        ..WallSpec::default()
    })
    .expect("wall");
    let g = Geometry {
        blocks: m.blocks.iter().map(|b| b.polygon.clone()).collect(),
        supports: m
            .supports
            .iter()
            .map(|s| SupportShape {
                name: s.name.clone(),
                polygon: s.polygon.clone(),
                motion: s.motion,
                fixed: false,
            })
            .collect(),
        loads: vec![],
    };
    let title = format!("Running-bond wall, {} blocks", g.blocks.len());
    let scene = Scene::geometry(&g, &title);
    // Warm up once (page faults, allocator), then time the best of five.
    let _ = draw::draw(&scene, &DrawOptions::default());
    let mut best_svg = f64::INFINITY;
    let mut svg = String::new();
    for _ in 0..5 {
        let t = Instant::now();
        svg = draw::draw(&scene, &DrawOptions::default()).svg;
        best_svg = best_svg.min(t.elapsed().as_secs_f64());
    }
    let t = Instant::now();
    let png = draw::svg_to_png(&svg, draw::PNG_ZOOM).expect("png");
    let t_png = t.elapsed().as_secs_f64();
    let svg_path = out.join("wall-10k.svg");
    let png_path = out.join("wall-10k.png");
    voussoir_io::write_atomic(&svg_path, svg.as_bytes()).expect("write svg");
    voussoir_io::write_atomic(&png_path, &png).expect("write png");
    println!(
        "{} blocks: SVG drawn in {:.1} ms ({} kB), PNG rendered in {:.1} ms ({} kB) → {}, {}",
        g.blocks.len(),
        best_svg * 1e3,
        svg.len() / 1024,
        t_png * 1e3,
        png.len() / 1024,
        svg_path.display(),
        png_path.display()
    );
}
