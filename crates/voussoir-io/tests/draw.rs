//! Drawings: PNGs of the paper arch show the structure where the geometry puts it, SVG output is
//! deterministic (snapshots) and valid XML, reports are self-contained.
//!
//! References are independent of the drawing code: the arch's joints are placed from its
//! definition (intrados radius 2.86 m, extrados 3.19 m, 64 voussoirs, so joint k from the left
//! springing lies at the angle π − kπ/64), block positions from `RigidMotion::scaled` of each
//! block's own motion, and the single-block collapse multiplier from statics (λ = b/h).

use resvg::tiny_skia::Pixmap;
use std::f64::consts::PI;
use std::path::PathBuf;
use voussoir::analysis::{limit, settle, LimitResult, SettlementResult};
use voussoir::generate::{arch, wall, ArchSpec, LiveLoad, WallSpec};
use voussoir::geometry::{area_centroid, RigidMotion};
use voussoir::lp::SolverOptions;
use voussoir::model::{Block, Load, Loads, Model, Support};
use voussoir::result::Geometry;
use voussoir::settlement_input::move_support;
use voussoir::{BuildOptions, Structure};
use voussoir_io::draw::{
    self, draw, limit_report, plot, settlement_report, DrawOptions, Drawing, Mark, PlotSpec,
    ReportOptions, Scene, Series,
};

const R_IN: f64 = 2.86;
const R_OUT: f64 = 3.19;

fn structure(m: &Model) -> Structure {
    Structure::new(m, BuildOptions { tolerance: None }).expect("valid model")
}

fn paper_arch_limit() -> LimitResult {
    let m = arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap();
    limit(&structure(&m), &SolverOptions::default()).unwrap()
}

fn paper_arch_spreading() -> SettlementResult {
    let mut m = arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    move_support(&mut m, "right", &[0.01, 0.0, 0.0]).unwrap();
    settle(&structure(&m), &SolverOptions::default()).unwrap()
}

/// Joint k from the left springing, on the intrados (`r = R_IN`) or the extrados.
fn joint_point(k: usize, r: f64) -> [f64; 2] {
    let a = PI - k as f64 * PI / 64.0;
    [r * a.cos(), r * a.sin()]
}

fn png_of(d: &Drawing) -> Pixmap {
    let bytes = draw::svg_to_png(&d.svg, 1.0).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    Pixmap::decode_png(&bytes).unwrap()
}

fn pixel(p: &Pixmap, x: f64, y: f64) -> [u8; 3] {
    let (xi, yi) = (x.round() as u32, y.round() as u32);
    let c = p
        .pixel(xi.min(p.width() - 1), yi.min(p.height() - 1))
        .unwrap();
    [c.red(), c.green(), c.blue()]
}

fn is_white(c: [u8; 3]) -> bool {
    c.iter().all(|&v| v >= 245)
}

/// Whether some pixel within `r` pixels of `(x, y)` satisfies `f`.
fn near(p: &Pixmap, x: f64, y: f64, r: i32, f: impl Fn([u8; 3]) -> bool) -> bool {
    (-r..=r).any(|dx| (-r..=r).any(|dy| f(pixel(p, x + dx as f64, y + dy as f64))))
}

fn dark(c: [u8; 3]) -> bool {
    c.iter().all(|&v| v < 70)
}

/// Deformed centroid of block `i` by its own finite rigid motion at the drawing's scale.
fn moved_centroid(
    g: &Geometry,
    blocks: &[voussoir::result::BlockMotion],
    i: usize,
    s: f64,
) -> [f64; 2] {
    let (_, c) = area_centroid(&g.blocks[i]);
    let b = blocks.iter().find(|b| b.id == i).unwrap();
    RigidMotion::scaled(c, [b.u, b.v, b.theta], s).apply(c)
}

fn moved_point(
    g: &Geometry,
    blocks: &[voussoir::result::BlockMotion],
    i: usize,
    s: f64,
    p: [f64; 2],
) -> [f64; 2] {
    let (_, c) = area_centroid(&g.blocks[i]);
    let b = blocks.iter().find(|b| b.id == i).unwrap();
    RigidMotion::scaled(c, [b.u, b.v, b.theta], s).apply(p)
}

fn check_structure_pixels(
    d: &Drawing,
    img: &Pixmap,
    g: &Geometry,
    blocks: &[voussoir::result::BlockMotion],
) {
    assert_eq!(
        (img.width(), img.height()),
        (d.width.ceil() as u32, d.height.ceil() as u32)
    );
    // Every block's deformed centroid is painted (block fill or the thrust line over it).
    for i in 0..g.blocks.len() {
        let c = d.frame.px(moved_centroid(g, blocks, i, d.scale));
        assert!(
            c[0] > 0.0 && c[0] < d.width && c[1] > 0.0 && c[1] < d.height,
            "block {i} off the image at {c:?}"
        );
        assert!(
            !is_white(pixel(img, c[0], c[1])),
            "block {i}: white pixel at its centroid {c:?}"
        );
    }
    // The opening under the arch and the sky over the crown are empty.
    for p in [[0.0, 1.2], [0.0, 0.4], [-1.5, 0.5], [1.5, 0.5]] {
        let q = d.frame.px(p);
        assert!(
            is_white(pixel(img, q[0], q[1])),
            "pixel at {p:?} should be background"
        );
    }
    // The supports are hatched: both ink and paper inside them.
    for s in &g.supports {
        let (_, c) = area_centroid(&s.polygon);
        let m = RigidMotion::scaled(c, s.motion, d.scale).apply(c);
        let q = d.frame.px(m);
        let darkest = (-6..=6)
            .flat_map(|dx| (-6..=6).map(move |dy| (dx, dy)))
            .map(|(dx, dy)| {
                *pixel(img, q[0] + dx as f64, q[1] + dy as f64)
                    .iter()
                    .max()
                    .unwrap()
            })
            .min()
            .unwrap();
        assert!(
            darkest < 160,
            "support {}: no hatching ink (darkest {darkest})",
            s.name
        );
        assert!(
            near(img, q[0], q[1], 6, is_white),
            "support {}: no paper between hatches",
            s.name
        );
    }
    // Not blank: a good share of the image is ink.
    let ink = img
        .pixels()
        .iter()
        .filter(|c| c.red() < 245 || c.green() < 245 || c.blue() < 245)
        .count();
    let share = ink as f64 / (img.width() * img.height()) as f64;
    assert!(share > 0.08 && share < 0.7, "ink share {share}");
}

#[test]
fn paper_arch_collapse_mechanism_png() {
    let r = paper_arch_limit();
    let d = draw(&Scene::limit(&r), &DrawOptions::default());
    assert!(d.deformed && d.scale > 0.0);
    let img = png_of(&d);
    check_structure_pixels(&d, &img, &r.geometry, &r.blocks);
    // Hinges are drawn as dark dots where the mechanism puts them.
    assert!(r.hinges.len() >= 4);
    for h in &r.hinges {
        let j = r.joints.iter().find(|j| j.id == h.joint).unwrap();
        let a = match &j.a {
            voussoir::result::BodyName::Block(i) => *i,
            _ => match &j.b {
                voussoir::result::BodyName::Block(i) => *i,
                _ => unreachable!(),
            },
        };
        let p = d
            .frame
            .px(moved_point(&r.geometry, &r.blocks, a, d.scale, [h.x, h.y]));
        assert!(
            near(&img, p[0], p[1], 2, dark),
            "no hinge dot at joint {} ({:?})",
            h.joint,
            p
        );
    }
    // The crown hinge is the paper's, at the extrados of joint 32.
    let crown = joint_point(32, R_OUT);
    assert!(r
        .hinges
        .iter()
        .any(|h| (h.x - crown[0]).abs() < 1e-6 && (h.y - crown[1]).abs() < 1e-6));
    // Live-load arrows stand on the extrados (purple shafts just above each loaded block's
    // moved load point).
    // Purple, pure or blended by anti-aliasing with white or a block's fill.
    let purple = |c: [u8; 3]| c[1] < c[2] && c[1] as u16 + 25 < c[0] as u16;
    let live: Vec<_> = r.geometry.loads.iter().filter(|l| l.live).collect();
    assert_eq!(live.len(), 64);
    for l in live {
        let tip = moved_point(&r.geometry, &r.blocks, l.block, d.scale, [l.x, l.y]);
        let q = d.frame.px([tip[0], tip[1] + 0.1]);
        assert!(
            near(&img, q[0], q[1], 2, purple),
            "no load arrow over block {}",
            l.block
        );
    }
}

#[test]
fn paper_arch_spreading_mechanism_png_shows_three_hinges() {
    let r = paper_arch_spreading();
    let d = draw(&Scene::settlement(&r), &DrawOptions::default());
    // 1 cm on a 6.38 m arch: the automatic scale is a round number that draws ~7 % of the size.
    assert_eq!(d.scale, 50.0);
    let img = png_of(&d);
    check_structure_pixels(&d, &img, &r.geometry, &r.blocks);
    // The paper's three hinges: crown (extrados) and the 13th joint from each springing
    // (intrados), at pixels given by the blocks' own motions.
    let expected = [
        (13, joint_point(13, R_IN), 12),
        (32, joint_point(32, R_OUT), 31),
        (51, joint_point(51, R_IN), 50),
    ];
    assert_eq!(r.hinges.len(), 3);
    for (k, p, block) in expected {
        assert!(
            r.hinges
                .iter()
                .any(|h| (h.x - p[0]).abs() < 1e-6 && (h.y - p[1]).abs() < 1e-6),
            "no hinge at joint {k} from the left"
        );
        let q = d
            .frame
            .px(moved_point(&r.geometry, &r.blocks, block, d.scale, p));
        assert!(
            near(&img, q[0], q[1], 2, dark),
            "no hinge dot at joint {k}: {q:?}"
        );
    }
    // The crown crack opens at the intrados: red wedge just below the crown hinge.
    let below = d.frame.px(moved_point(
        &r.geometry,
        &r.blocks,
        31,
        d.scale,
        [0.0, R_IN + 0.03],
    ));
    assert!(
        near(&img, below[0], below[1], 3, |c| c[0] > 180
            && c[1] < 120
            && c[2] < 110),
        "no crack wedge at the crown"
    );
    // The right support is drawn moved by 50 × 1 cm = 0.5 m: its undeformed place is empty
    // but for the dashed outline.
    let old = d.frame.px([3.025, -0.165]);
    let new = d.frame.px([3.525, -0.165]);
    assert!(is_white(pixel(&img, old[0], old[1])) || !dark(pixel(&img, old[0], old[1])));
    assert!(near(&img, new[0], new[1], 6, |c| c
        .iter()
        .all(|&v| v < 140)));
}

#[test]
fn svg_is_deterministic_and_valid_xml() {
    let r = paper_arch_spreading();
    let scene = Scene::settlement(&r);
    for opts in [
        DrawOptions::default(),
        DrawOptions {
            interactive: true,
            forces: true,
            ..DrawOptions::default()
        },
        DrawOptions {
            deformed: false,
            dead_loads: true,
            ..DrawOptions::default()
        },
        DrawOptions {
            scale: Some(120.0),
            ..DrawOptions::default()
        },
    ] {
        let a = draw(&scene, &opts).svg;
        let b = draw(&scene, &opts).svg;
        assert_eq!(a, b);
        let doc = roxmltree::Document::parse(&a).expect("valid XML");
        assert_eq!(doc.root_element().tag_name().name(), "svg");
        assert_eq!(
            doc.root_element().tag_name().namespace(),
            Some("http://www.w3.org/2000/svg")
        );
    }
    // A second, independently solved copy draws to the same bytes, and so does its PNG.
    let r2 = paper_arch_spreading();
    let a = draw(&Scene::settlement(&r), &DrawOptions::default()).svg;
    let b = draw(&Scene::settlement(&r2), &DrawOptions::default()).svg;
    assert_eq!(a, b);
    assert_eq!(
        draw::svg_to_png(&a, 1.0).unwrap(),
        draw::svg_to_png(&b, 1.0).unwrap()
    );
    // A user-chosen scale is used as given and printed.
    let d = draw(
        &scene,
        &DrawOptions {
            scale: Some(120.0),
            ..DrawOptions::default()
        },
    );
    assert_eq!(d.scale, 120.0);
    assert!(d
        .svg
        .contains("displacements drawn × <tspan class=\"scale-value\">120</tspan>"));
}

/// One 0.4 m × 1 m block on the ground under a horizontal load λ·W: λ = b/h = 0.4, rotating about
/// its right toe.
fn single_block() -> (Model, LimitResult) {
    let m = Model {
        description: "single block".into(),
        blocks: vec![Block {
            polygon: vec![[0.0, 0.0], [0.4, 0.0], [0.4, 1.0], [0.0, 1.0]],
            material: None,
        }],
        supports: vec![Support {
            name: "ground".into(),
            polygon: vec![[-0.2, -0.2], [0.6, -0.2], [0.6, 0.0], [-0.2, 0.0]],
            motion: [0.0; 3],
            connection: Default::default(),
        }],
        loads: Loads {
            live: vec![Load::Body {
                coefficients: [1.0, 0.0],
                blocks: None,
            }],
            ..Loads::default()
        },
        ..Model::default()
    };
    let r = limit(&structure(&m), &SolverOptions::default()).unwrap();
    (m, r)
}

fn snapshot(name: &str, text: &str) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/snapshots")
        .join(name);
    if std::env::var_os("UPDATE_SNAPSHOTS").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, text).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path).unwrap_or_else(|_| {
        panic!(
            "missing snapshot {}; run with UPDATE_SNAPSHOTS=1",
            path.display()
        )
    });
    assert!(
        want == text,
        "{name} differs from its snapshot; inspect and run with UPDATE_SNAPSHOTS=1 if intended"
    );
}

#[test]
fn snapshots_of_a_block_mechanism_and_a_plot() {
    let (_, r) = single_block();
    let lambda = r.load_multiplier.unwrap();
    assert!((lambda - 0.4).abs() < 1e-6, "λ = {lambda}");
    let d = draw(
        &Scene::limit(&r),
        &DrawOptions {
            width: 600.0,
            ..DrawOptions::default()
        },
    );
    assert!(d.svg.contains("λ = 0.4000"));
    snapshot("block_limit.svg", &d.svg);
    let p = plot(
        &[
            Series::new(
                "horizontal settlement",
                vec![[0.0, 0.429], [0.7, 0.215], [1.4, 0.0]],
            )
            .with_markers(),
            Series::new("vertical settlement", vec![[0.0, 0.429], [0.42, 0.0]]).dashed(),
        ],
        &PlotSpec {
            title: "Capacity after settlement".into(),
            x_label: "settlement s (cm)".into(),
            y_label: "load multiplier λ".into(),
            marks: vec![Mark::new(1.4, 0.0, "λ = 0 at s = 1.4 cm")],
            ..PlotSpec::default()
        },
    );
    roxmltree::Document::parse(&p.svg).expect("valid XML");
    snapshot("capacity_plot.svg", &p.svg);
}

#[test]
fn plot_draws_the_curve_where_the_data_are() {
    let pts: Vec<[f64; 2]> = (0..=14)
        .map(|i| [i as f64 * 0.1, 0.429 * (1.0 - i as f64 / 14.0)])
        .collect();
    let p = plot(
        &[Series::new("λ(s)", pts.clone())],
        &PlotSpec {
            x_label: "s (cm)".into(),
            y_label: "λ".into(),
            ..PlotSpec::default()
        },
    );
    // Axes fitted on nice ticks that contain the data and zero.
    assert_eq!((p.x_axis.min, p.y_axis.min), (0.0, 0.0));
    assert!((p.x_axis.max - 1.4).abs() < 1e-9, "{:?}", p.x_axis);
    assert!((p.y_axis.max - 0.45).abs() < 1e-9, "{:?}", p.y_axis);
    let img = Pixmap::decode_png(&draw::svg_to_png(&p.svg, 1.0).unwrap()).unwrap();
    assert_eq!((img.width(), img.height()), (820, 520));
    let blue = |c: [u8; 3]| c[2] > 150 && c[0] < 90;
    for w in pts.windows(2) {
        let mid = [(w[0][0] + w[1][0]) / 2.0, (w[0][1] + w[1][1]) / 2.0];
        let q = p.px(mid[0], mid[1]);
        assert!(near(&img, q[0], q[1], 1, blue), "curve missing at {mid:?}");
    }
    // Far from the line (upper right) the plot is empty paper.
    let q = p.px(1.3, 0.4);
    assert!(!near(&img, q[0], q[1], 3, blue));
}

#[test]
fn reports_are_self_contained_with_figures_and_numbers() {
    let r = paper_arch_limit();
    let html = limit_report(&r, &ReportOptions::default()).to_html();
    let lambda = format!("{:.6}", r.load_multiplier.unwrap());
    assert!(html.contains(&lambda), "λ {lambda} missing");
    assert_eq!(html.matches("<svg ").count(), 3, "model, mechanism, forces");
    assert_eq!(
        html.matches("type=\"range\"").count(),
        1,
        "one slider for the mechanism"
    );
    for bad in ["src=\"http", "href=\"http", "url(http", "@import", "<link "] {
        assert!(!html.contains(bad), "report refers to the network: {bad}");
    }
    // Every inline figure is well-formed XML.
    let mut rest = html.as_str();
    while let Some(i) = rest.find("<svg ") {
        let j = rest[i..].find("</svg>").unwrap() + i + 6;
        roxmltree::Document::parse(&rest[i..j]).expect("inline SVG is valid XML");
        rest = &rest[j..];
    }
    let s = paper_arch_spreading();
    let html = settlement_report(&s, &ReportOptions::default()).to_html();
    assert!(html.contains("certified (≤ 1e-7)"));
    assert!(html.contains("right u = 10 mm, v = 0 mm"));
}

#[test]
fn saved_results_are_recognised() {
    let r = paper_arch_limit();
    let json = serde_json::to_string(&r).unwrap();
    assert!(matches!(
        draw::parse_saved(&json).unwrap(),
        draw::Saved::Limit(_)
    ));
    let s = paper_arch_spreading();
    let json = serde_json::to_string(&s).unwrap();
    assert!(matches!(
        draw::parse_saved(&json).unwrap(),
        draw::Saved::Settlement(_)
    ));
    let (m, _) = single_block();
    let json = serde_json::to_string(&m).unwrap();
    match draw::parse_saved(&json).unwrap() {
        draw::Saved::Model(g) => assert_eq!(g.blocks.len(), 1),
        other => panic!("model read as {}", other.kind()),
    }
    assert!(draw::parse_saved("[1, 2]").is_err());
    assert!(draw::parse_saved("{\"status\": \"x\", \"geometry\": {}}").is_err());
}

#[test]
fn a_ten_thousand_block_wall_gives_a_file_of_reasonable_size() {
    // 100 courses of 100 units: 10 050 blocks. The timing is measured by
    // `cargo run --release -p voussoir-io --example draw_wall`, not here.
    let m = wall(&WallSpec {
        courses: 100,
        units: 100,
        ..WallSpec::default()
    })
    .unwrap();
    let g = Geometry {
        blocks: m.blocks.iter().map(|b| b.polygon.clone()).collect(),
        supports: m
            .supports
            .iter()
            .map(|s| voussoir::result::SupportShape {
                name: s.name.clone(),
                polygon: s.polygon.clone(),
                motion: s.motion,
                fixed: false,
            })
            .collect(),
        loads: vec![],
    };
    assert!(g.blocks.len() >= 10_000);
    let d = draw(&Scene::geometry(&g, "wall"), &DrawOptions::default());
    // About 4 vertices × 2 numbers per block: well under 1 MB.
    assert!(d.svg.len() < 1_000_000, "{} bytes", d.svg.len());
    roxmltree::Document::parse(&d.svg).expect("valid XML");
}

#[test]
fn paper_arch_capacity_curve_png() {
    use voussoir::analysis::{capacity, CapacityOptions};
    // Outward horizontal settlement of the right springing up to 2 cm, live load on the span.
    let mut m = arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap();
    move_support(&mut m, "right", &[0.02, 0.0, 0.0]).unwrap();
    let r = capacity(
        &structure(&m),
        &CapacityOptions {
            steps: 8,
            ..CapacityOptions::default()
        },
    )
    .unwrap();
    let s0 = r
        .zero_capacity_settlement
        .expect("λ reaches zero below 2 cm");
    // The paper: λ = 0 at 1.4 cm (±5 %).
    assert!((s0 - 0.014).abs() < 0.05 * 0.014, "s0 = {s0}");
    let p = draw::capacity_plot(
        &[("horizontal settlement", &r)],
        "Capacity after settlement",
    );
    roxmltree::Document::parse(&p.svg).expect("valid XML");
    assert!(p.svg.contains(&format!(
        "λ = 0 at s = {} cm",
        voussoir_io::draw::svg::fmt_fixed(s0 * 100.0, 3)
    )));
    let img = Pixmap::decode_png(&draw::svg_to_png(&p.svg, 1.0).unwrap()).unwrap();
    assert_eq!((img.width(), img.height()), (820, 520));
    // The curve passes through every computed point (blue line or marker), and the zero mark
    // is a dark ring on the s axis at s0.
    let blue = |c: [u8; 3]| c[2] > 150 && c[0] < 120;
    for q in r.curve.iter().filter(|q| q.valid) {
        let l = q.load_multiplier.unwrap();
        let xy = p.px(q.settlement * 100.0, l);
        assert!(
            near(&img, xy[0], xy[1], 2, blue),
            "curve missing at s = {}",
            q.settlement
        );
    }
    let z = p.px(s0 * 100.0, 0.0);
    assert!(
        near(&img, z[0] + 6.0, z[1], 1, dark) && near(&img, z[0] - 6.0, z[1], 1, dark),
        "no mark at λ = 0"
    );
    let html = draw::capacity_report(&r, &ReportOptions::default()).to_html();
    assert!(html.contains(&format!(
        "{} cm",
        voussoir_io::draw::svg::fmt_fixed(s0 * 100.0, 4)
    )));
    assert_eq!(
        html.matches("<svg ").count(),
        2,
        "curve and settlement mechanism"
    );
}
