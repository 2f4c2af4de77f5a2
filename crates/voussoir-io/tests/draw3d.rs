//! 3D drawings: deterministic SVG, a PNG whose pixels are where the projection says, and
//! hidden faces painted over by nearer ones.

use resvg::tiny_skia::Pixmap;
use voussoir::analysis::SettlementResult;
use voussoir::dim::Three;
use voussoir::result::spatial::SpatialMotion;
use voussoir_io::draw::PNG_ZOOM;
use voussoir_io::draw3d::{draw3d, draw3d_png, Draw3dOptions, View};

fn fixture() -> SettlementResult<Three> {
    let text = include_str!("fixtures/settlement3d_two_cubes.json");
    serde_json::from_str(text).expect("fixture parses as a 3D settlement result")
}

/// The RGBA pixel at SVG position `p`.
fn pixel(img: &Pixmap, p: [f64; 2]) -> [u8; 4] {
    let (x, y) = (
        (p[0] * PNG_ZOOM as f64).floor() as u32,
        (p[1] * PNG_ZOOM as f64).floor() as u32,
    );
    let c = img.pixel(x, y).expect("inside the image");
    [c.red(), c.green(), c.blue(), c.alpha()]
}

const WHITE: [u8; 4] = [255, 255, 255, 255];

#[test]
fn svg_is_byte_identical_across_runs() {
    let r = fixture();
    let a = draw3d(&r, &Draw3dOptions::default()).unwrap();
    let b = draw3d(&r, &Draw3dOptions::default()).unwrap();
    assert_eq!(a.svg, b.svg);
    assert!(a.deformed && a.scale > 0.0);
    // The SVG parses and has the title, both blocks and the crack.
    let doc = roxmltree::Document::parse(&a.svg).unwrap();
    assert!(doc
        .descendants()
        .any(|n| n.has_tag_name("title") && n.text() == Some("Settlement mechanism")));
    assert!(a.svg.contains("data-block=\"0\"") && a.svg.contains("data-block=\"1\""));
    assert!(a.svg.contains("class=\"cracks\""));
    assert!(a.svg.contains("class=\"hinge-lines\""));
    // PNG bytes are deterministic too.
    let (p1, _) = draw3d_png(&r, &Draw3dOptions::default()).unwrap();
    let (p2, _) = draw3d_png(&r, &Draw3dOptions::default()).unwrap();
    assert_eq!(p1, p2);
}

#[test]
fn png_has_the_block_where_the_projection_puts_it() {
    let r = fixture();
    let (png, d) = draw3d_png(&r, &Draw3dOptions::default()).unwrap();
    let img = Pixmap::decode_png(&png).unwrap();
    assert_eq!(
        (img.width(), img.height()),
        (
            (d.width * PNG_ZOOM as f64).ceil() as u32,
            (d.height * PNG_ZOOM as f64).ceil() as u32
        )
    );
    // The centroid of the upper cube, projected: inside its silhouette, not background.
    let c = d.camera.px([0.5, 0.5, 1.5]);
    assert!(c[0] > 0.0 && c[0] < d.width && c[1] > 0.0 && c[1] < d.height);
    assert_ne!(pixel(&img, c), WHITE, "centroid at {c:?}");
    // The lower cube too.
    assert_ne!(pixel(&img, d.camera.px([0.5, 0.5, 0.5])), WHITE);
    // Far away (a point well outside the model, and the figure's corners): background.
    let far = d.camera.px([6.0, -6.0, 1.0]);
    if far[0] > 0.0 && far[0] < d.width && far[1] > 0.0 && far[1] < d.height {
        assert_eq!(pixel(&img, far), WHITE);
    }
    assert_eq!(pixel(&img, [3.0, 3.0]), WHITE);
    assert_eq!(pixel(&img, [d.width - 3.0, 3.0]), WHITE);
    assert_eq!(pixel(&img, [d.width - 3.0, d.height * 0.45]), WHITE);
}

/// Two cubes on one line of sight: block 0 rocks (drawn in a palette colour), block 1 is at
/// rest (grey). Both take block 0's place, then the far one is moved 3 m away from the camera along the viewing direction, so
/// both centroids project to the same pixel.
fn behind_model(moving_in_front: bool) -> SettlementResult<Three> {
    let mut r = fixture();
    let toward = draw3d(&r, &fixed_view()).unwrap().camera.toward;
    // Block 1 (on top of block 0 in the fixture) first comes down onto block 0's place.
    for v in &mut r.geometry.blocks[1].vertices {
        v[2] -= 1.0;
    }
    r.geometry.centroids[1][2] -= 1.0;
    let far = if moving_in_front { 1 } else { 0 };
    let shift = [-3.0 * toward[0], -3.0 * toward[1], -3.0 * toward[2]];
    for v in &mut r.geometry.blocks[far].vertices {
        for c in 0..3 {
            v[c] += shift[c];
        }
    }
    for (c, d) in r.geometry.centroids[far].iter_mut().zip(shift) {
        *c += d;
    }
    r.blocks[1].motion = SpatialMotion {
        u: 0.0,
        v: 0.0,
        w: 0.0,
        theta_x: 0.0,
        theta_y: 0.0,
        theta_z: 0.0,
    };
    // Nothing else in the way.
    r.geometry.supports.clear();
    r.geometry.loads.clear();
    r.joints.clear();
    r.hinges.clear();
    r.thrust_line.clear();
    r
}

/// The usual axonometric view, fixed (the automatic view turns with the motions, and the
/// two models of `behind_model` move differently).
fn fixed_view() -> Draw3dOptions {
    Draw3dOptions {
        view: View::Axonometric {
            azimuth: -35.0,
            elevation: 30.0,
        },
        ..Draw3dOptions::default()
    }
}

/// Warm (the moving block's palette colour, #f6c97f shaded) rather than grey (at rest).
fn warm(p: [u8; 4]) -> bool {
    p[0] as i32 - p[2] as i32 > 40
}
fn grey(p: [u8; 4]) -> bool {
    (p[0] as i32 - p[2] as i32).abs() < 20 && p != WHITE
}

#[test]
fn the_nearer_block_is_painted_on_top() {
    for moving_in_front in [true, false] {
        let r = behind_model(moving_in_front);
        // Displacements drawn × 0: the picture is the geometry, block 0 still coloured as moving.
        let opts = Draw3dOptions {
            scale: Some(0.0),
            undeformed: false,
            ..fixed_view()
        };
        let (png, d) = draw3d_png(&r, &opts).unwrap();
        let img = Pixmap::decode_png(&png).unwrap();
        let p = d.camera.px(r.geometry.centroids[0]);
        let q = d.camera.px(r.geometry.centroids[1]);
        assert!((p[0] - q[0]).abs() < 1e-6 && (p[1] - q[1]).abs() < 1e-6);
        let c = pixel(&img, p);
        if moving_in_front {
            assert!(
                warm(c),
                "the near block (moving, coloured) should be on top: {c:?}"
            );
        } else {
            assert!(
                grey(c),
                "the near block (at rest, grey) should be on top: {c:?}"
            );
        }
        // The two cases differ only in which block is nearer: index order plays no part.
    }
}

#[test]
fn plan_and_elevation_views_draw() {
    let r = fixture();
    for view in [View::Plan, View::Elevation] {
        let d = draw3d(
            &r,
            &Draw3dOptions {
                view,
                ..Draw3dOptions::default()
            },
        )
        .unwrap();
        assert!(d.svg.contains("data-block=\"1\""));
    }
    // In plan the top face of the upper cube covers its centroid's position.
    let d = draw3d(
        &r,
        &Draw3dOptions {
            view: View::Plan,
            ..Draw3dOptions::default()
        },
    )
    .unwrap();
    let p = d.camera.px([0.5, 0.5, 2.0]);
    let q = d.camera.px([0.5, 0.5, 0.0]);
    assert!((p[0] - q[0]).abs() < 1e-9 && (p[1] - q[1]).abs() < 1e-9);
}

#[test]
fn corrupt_shapes_are_an_error() {
    let mut r = fixture();
    r.geometry.blocks[0].faces[0] = vec![0, 1, 42];
    assert!(draw3d(&r, &Draw3dOptions::default()).is_err());
}

#[test]
#[ignore]
fn write_pictures_for_inspection() {
    let r = fixture();
    // `cargo test --release -p voussoir-io --test draw3d -- --ignored` to look at the picture.
    let (png, d) = draw3d_png(&r, &Draw3dOptions::default()).unwrap();
    std::fs::create_dir_all("/tmp/io3d").unwrap();
    std::fs::write("/tmp/io3d/two_cubes.png", png).unwrap();
    std::fs::write("/tmp/io3d/two_cubes.svg", d.svg).unwrap();
}
