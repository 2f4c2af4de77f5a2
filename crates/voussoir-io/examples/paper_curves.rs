//! The paper's curves (Figs 10, 12, 14–17) drawn from the library, for `examples/paper/run.sh`
//! while the CLI has no `capacity` / `incremental` commands:
//!
//! ```text
//! cargo run --release -p voussoir-io --example paper_curves -- OUT_DIR
//! ```
//! Writes SVG + PNG of: the λ–settlement curves for a horizontal (Fig 10) and a vertical (Fig 12)
//! settlement of the right springing, the λ–dx incremental curves of the arch under a half-span
//! load, perfect and with 0.25 and 0.5 cm vertical settlements (Figs 14b, 15, 16), and the three
//! together (Fig 17).

use std::path::{Path, PathBuf};
use voussoir::analysis::incremental::{
    incremental, settled, Control, IncrementalOptions, IncrementalResult,
};
use voussoir::analysis::{capacity, CapacityOptions, CapacityResult};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::SolverOptions;
use voussoir::model::{Connection, Model};
use voussoir::{BuildOptions, Structure};
use voussoir_io::draw::{self, Plot};

fn fail(msg: String) -> ! {
    eprintln!("error: {msg}");
    std::process::exit(1)
}

fn structure(m: &Model) -> Structure {
    Structure::new(m, BuildOptions::default()).unwrap_or_else(|e| fail(e.to_string()))
}

fn write(out: &Path, name: &str, p: &Plot) {
    let svg = out.join(format!("{name}.svg"));
    let png = out.join(format!("{name}.png"));
    voussoir_io::write_atomic(&svg, p.svg.as_bytes()).unwrap_or_else(|e| fail(e.0));
    let bytes = draw::svg_to_png(&p.svg, draw::PNG_ZOOM).unwrap_or_else(|e| fail(e.0));
    voussoir_io::write_atomic(&png, &bytes).unwrap_or_else(|e| fail(e.0));
    println!("wrote {}", png.display());
}

/// Capacity curve of the paper's arch (full-span live load) for a settlement of the right
/// springing with motion `motion` at its largest.
fn capacity_of(motion: [f64; 3], fixed: bool) -> CapacityResult {
    let mut m = arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap_or_else(|e| fail(e.to_string()));
    m.supports[1].motion = motion;
    if fixed {
        m.supports[1].connection = Connection::Fixed;
    }
    capacity(
        &structure(&m),
        &CapacityOptions {
            steps: 30,
            mechanisms: false,
            ..CapacityOptions::default()
        },
    )
    .unwrap_or_else(|e| fail(e.to_string()))
}

/// Incremental analysis of the arch with the live load on the left half, after a downward
/// settlement of the right springing (m; that support `fixed` for the settlement).
fn incremental_of(settlement: f64) -> IncrementalResult {
    let mut m = arch(&ArchSpec {
        live: LiveLoad::Left,
        ..ArchSpec::default()
    })
    .unwrap_or_else(|e| fail(e.to_string()));
    let st = if settlement == 0.0 {
        structure(&m)
    } else {
        m.supports[1].motion = [0.0, -settlement, 0.0];
        m.supports[1].connection = Connection::Fixed;
        settled(&structure(&m), &SolverOptions::default(), true)
            .unwrap_or_else(|e| fail(e.to_string()))
    };
    let c = Control::nearest(&st, [0.0, 3.19], [1.0, 0.0]).unwrap_or_else(|e| fail(e.to_string()));
    incremental(
        &st,
        &c,
        &IncrementalOptions {
            step: 1e-4,
            max_displacement: 0.05,
            ..Default::default()
        },
    )
    .unwrap_or_else(|e| fail(e.to_string()))
}

fn main() {
    let out = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "examples/paper/out".into()),
    );
    std::fs::create_dir_all(&out)
        .unwrap_or_else(|e| fail(format!("cannot create {}: {e}", out.display())));

    let h = capacity_of([0.02, 0.0, 0.0], false);
    write(
        &out,
        "fig10-capacity-horizontal",
        &draw::capacity_plot(
            &[("horizontal settlement of one springing", &h)],
            "Fig 10 — λ against a horizontal settlement",
        ),
    );
    let v = capacity_of([0.0, -0.006, 0.0], true);
    write(
        &out,
        "fig12-capacity-vertical",
        &draw::capacity_plot(
            &[("vertical settlement of one springing", &v)],
            "Fig 12 — λ against a vertical settlement",
        ),
    );

    let runs = [
        (
            0.0,
            "perfect arch",
            "fig14b-incremental-perfect",
            "Fig 14b — perfect arch",
        ),
        (
            0.0025,
            "settlement 0.25 cm",
            "fig15-incremental-0.25cm",
            "Fig 15 — after a 0.25 cm settlement",
        ),
        (
            0.005,
            "settlement 0.5 cm",
            "fig16-incremental-0.5cm",
            "Fig 16 — after a 0.5 cm settlement",
        ),
    ];
    let results: Vec<IncrementalResult> = runs.iter().map(|r| incremental_of(r.0)).collect();
    for (r, (_, label, name, title)) in results.iter().zip(&runs) {
        write(&out, name, &draw::incremental_plot(&[(label, r)], title));
    }
    let report = |name: &str, html: String| {
        let path = out.join(name);
        voussoir_io::write_atomic(&path, html.as_bytes()).unwrap_or_else(|e| fail(e.0));
        println!("wrote {}", path.display());
    };
    let opts = |t: &str| draw::ReportOptions {
        title: Some(t.to_string()),
        ..Default::default()
    };
    report(
        "fig10-report.html",
        draw::capacity_report(&h, &opts("Fig 10 — capacity after a horizontal settlement"))
            .to_html(),
    );
    report(
        "fig12-report.html",
        draw::capacity_report(&v, &opts("Fig 12 — capacity after a vertical settlement")).to_html(),
    );
    report(
        "fig15-report.html",
        draw::incremental_report(
            &results[1],
            &opts("Fig 15 — incremental analysis after a 0.25 cm settlement"),
        )
        .to_html(),
    );
    let all: Vec<(&str, &IncrementalResult)> = runs.iter().map(|r| r.1).zip(&results).collect();
    write(
        &out,
        "fig17-incremental-comparison",
        &draw::incremental_plot(&all, "Fig 17 — force–displacement curves compared"),
    );
}
