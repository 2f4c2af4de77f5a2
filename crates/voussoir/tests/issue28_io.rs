//! Issue 28, items 5 and 10 at the library level: blocks whose faces form several closed shells
//! (a hollow block is accepted with the hollow block's volume, centroid and λ; nested outward
//! shells, separate pieces and misplaced cavities are refused naming the block), coordinates
//! whose size overflows, and a contact polygon of 20,000 vertices kept within the geometric
//! tolerance. References are hand calculations on boxes and the closed form of the polygon.

use voussoir::analysis::limit::{limit, LimitStatus};
use voussoir::geometry3d::{clean_polyhedron, detect_interfaces3};
use voussoir::lp::SolverOptions;
use voussoir::model::Material;
use voussoir::model3d::{Block3d, Load3d, Loads3d, Model3d, Support3d};
use voussoir::{BuildOptions, Structure3d};

type V3 = [f64; 3];
type Shape = (Vec<V3>, Vec<Vec<usize>>);

/// Vertices and outward faces of the box `[lo, hi]` (faces turned round if `inward`).
fn cuboid(lo: V3, hi: V3, inward: bool) -> (Vec<V3>, Vec<Vec<usize>>) {
    let v = (0..8)
        .map(|i| {
            [
                if i & 1 == 0 { lo[0] } else { hi[0] },
                if i & 2 == 0 { lo[1] } else { hi[1] },
                if i & 4 == 0 { lo[2] } else { hi[2] },
            ]
        })
        .collect();
    let mut f = vec![
        vec![0, 2, 3, 1],
        vec![4, 5, 7, 6],
        vec![0, 1, 5, 4],
        vec![2, 6, 7, 3],
        vec![0, 4, 6, 2],
        vec![1, 3, 7, 5],
    ];
    if inward {
        for face in f.iter_mut() {
            face.reverse();
        }
    }
    (v, f)
}

/// Two boxes' surfaces in one vertex/face list (the second's indices shifted).
fn two_shells(
    (mut v, mut f): (Vec<V3>, Vec<Vec<usize>>),
    (v2, f2): (Vec<V3>, Vec<Vec<usize>>),
) -> (Vec<V3>, Vec<Vec<usize>>) {
    let off = v.len();
    v.extend(v2);
    f.extend(
        f2.into_iter()
            .map(|g| g.into_iter().map(|i| i + off).collect()),
    );
    (v, f)
}

fn model_of(blocks: Vec<(Vec<V3>, Vec<Vec<usize>>)>, base: (Vec<V3>, Vec<Vec<usize>>)) -> Model3d {
    let mut m = Model3d {
        blocks: blocks
            .into_iter()
            .map(|(vertices, faces)| Block3d {
                vertices,
                faces,
                material: None,
            })
            .collect(),
        supports: vec![Support3d {
            name: "base".into(),
            vertices: base.0,
            faces: base.1,
            motion: [0.0; 6],
            connection: Default::default(),
        }],
        loads: Loads3d {
            live: vec![Load3d::Body {
                coefficients: [1.0, 0.0, 0.0],
                blocks: None,
            }],
            ..Loads3d::default()
        },
        ..Model3d::default()
    };
    m.materials.insert(
        "default".into(),
        Material {
            unit_weight: 20.0,
            ..Material::default()
        },
    );
    m
}

fn base() -> (Vec<V3>, Vec<Vec<usize>>) {
    cuboid([-1.0, -1.0, -0.5], [2.0, 2.0, 0.0], false)
}

/// The block 1 × 1 × 1.5 with the cube cavity [0.25, 0.75]² × [0.75, 1.25], cavity faces
/// facing into the cavity.
fn hollow_block(outer_inward: bool) -> (Vec<V3>, Vec<Vec<usize>>) {
    two_shells(
        cuboid([0.0, 0.0, 0.0], [1.0, 1.0, 1.5], outer_inward),
        cuboid([0.25, 0.25, 0.75], [0.75, 0.75, 1.25], !outer_inward),
    )
}

fn build_err(m: &Model3d) -> String {
    Structure3d::new(m, BuildOptions::default())
        .expect_err("the model should be refused")
        .to_string()
}

#[test]
fn issue28_item5_a_hollow_block_has_the_hollow_volume_centroid_weight_and_lambda() {
    // By hand: V = 1.5 − 0.5³ = 1.375 m³; z̄ = (1.5·0.75 − 0.125·1.0)/1.375 = 1/1.375; x̄ = ȳ =
    // 0.5; W = 20 · 1.375 = 27.5 kN. Tipping about the edge x = 1 under λW along +x at the
    // centroid: λ W z̄ = W · 0.5, λ = 0.5 · 1.375 = 0.6875. Counted twice (the inner shell facing
    // outwards too) it would be V = 1.625, z̄ = 1.25/1.625, λ = 0.65.
    for outer_inward in [false, true] {
        let m = model_of(vec![hollow_block(outer_inward)], base());
        let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
        let b = &st.blocks[0];
        assert!((b.shape.volume - 1.375).abs() < 1e-12, "{}", b.shape.volume);
        let c = b.shape.centroid;
        assert!(
            (c[0] - 0.5).abs() < 1e-12 && (c[1] - 0.5).abs() < 1e-12,
            "{c:?}"
        );
        assert!((c[2] - 1.0 / 1.375).abs() < 1e-12, "{c:?}");
        assert!((b.weight - 27.5).abs() < 1e-10, "{}", b.weight);
        let r = limit(&st, &SolverOptions::default()).unwrap();
        assert_eq!(r.status, LimitStatus::Collapse);
        let lambda = r.load_multiplier.unwrap();
        assert!((lambda - 0.6875).abs() < 1e-9, "λ = {lambda}");
    }
}

#[test]
fn issue28_item5_nested_outward_shells_are_refused_naming_the_block() {
    // Both shells counter-clockwise seen from their own outside: the inner one's volume would
    // be counted twice (V = 1.625 instead of 1.375).
    let nested = two_shells(
        cuboid([0.0, 0.0, 0.0], [1.0, 1.0, 1.5], false),
        cuboid([0.25, 0.25, 0.75], [0.75, 0.75, 1.25], false),
    );
    let e = build_err(&model_of(vec![nested], base()));
    assert!(e.contains("block 0"), "{e}");
    assert!(
        e.contains("faces 6–11") && e.contains("count its volume twice"),
        "{e}"
    );
    assert_eq!(e.lines().count(), 1);
}

#[test]
fn issue28_item5_separate_pieces_and_misplaced_cavities_are_refused() {
    let solid = || cuboid([0.0, 0.0, 0.0], [1.0, 1.0, 1.5], false);
    let cases: Vec<(Shape, &str)> = vec![
        // Two boxes side by side as one block.
        (
            two_shells(solid(), cuboid([1.5, 0.0, 0.0], [2.0, 1.0, 1.5], false)),
            "separate closed surfaces",
        ),
        // A cavity outside the block.
        (
            two_shells(solid(), cuboid([1.5, 0.0, 0.5], [1.8, 0.5, 1.0], true)),
            "not strictly inside",
        ),
        // A cavity crossing the block's surface.
        (
            two_shells(
                solid(),
                cuboid([0.25, 0.25, 0.75], [1.25, 0.75, 1.25], true),
            ),
            "not strictly inside",
        ),
        // A cavity touching the block's surface (a wall of no thickness).
        (
            two_shells(solid(), cuboid([0.25, 0.25, 0.75], [1.0, 0.75, 1.25], true)),
            "not strictly inside",
        ),
    ];
    for (shape, needle) in cases {
        let e = build_err(&model_of(vec![shape], base()));
        assert!(e.contains("block 0") && e.contains(needle), "{e}");
    }
    // Two cavities that overlap.
    let (v, f) = two_shells(
        two_shells(solid(), cuboid([0.2, 0.2, 0.2], [0.6, 0.6, 0.6], true)),
        cuboid([0.4, 0.4, 0.4], [0.8, 0.8, 0.8], true),
    );
    let e = build_err(&model_of(vec![(v, f)], base()));
    assert!(
        e.contains("block 0") && e.contains("cavities") && e.contains("overlap"),
        "{e}"
    );
    // Two cavities apart: V = 1.5 − 2 · 0.2³ = 1.484.
    let (v, f) = two_shells(
        two_shells(solid(), cuboid([0.1, 0.1, 0.1], [0.3, 0.3, 0.3], true)),
        cuboid([0.6, 0.6, 1.0], [0.8, 0.8, 1.2], true),
    );
    let s = clean_polyhedron("block 0", &v, &f, 1e-9).unwrap();
    assert!(
        (s.volume - (1.5 - 2.0 * 0.008)).abs() < 1e-12,
        "{}",
        s.volume
    );
}

#[test]
fn issue28_item5_coordinates_whose_size_overflows_are_refused() {
    // Every coordinate finite, but the model's extent (and the faces' areas) overflow f64.
    let m = model_of(
        vec![cuboid([0.0, 0.0, 0.0], [1e308, 1.0, 1.5], false)],
        cuboid([-1e308, -1.0, -0.5], [1e308, 2.0, 0.0], false),
    );
    let e = build_err(&m);
    assert!(e.contains("overflows"), "{e}");
    // One block alone: its faces' size overflows.
    let (v, f) = cuboid([-1e308, 0.0, 0.0], [1e308, 1.0, 1.0], false);
    let e = clean_polyhedron("block 0", &v, &f, 1e-7)
        .unwrap_err()
        .to_string();
    assert!(e.contains("block 0") && e.contains("overflows"), "{e}");
}

/// A prism of height 0.5 under the plane z = 0 whose top is the regular N-gon of radius `r`
/// about the origin, first vertex at angle `phase`.
fn ngon_prism(n: usize, r: f64, phase: f64) -> (Vec<V3>, Vec<Vec<usize>>) {
    let ring: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let t = phase + 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    let mut v: Vec<V3> = ring.iter().map(|p| [p[0], p[1], 0.0]).collect();
    v.extend(ring.iter().map(|p| [p[0], p[1], -0.5]));
    let mut f = vec![(0..n).collect::<Vec<_>>(), (n..2 * n).rev().collect()];
    for k in 0..n {
        let j = (k + 1) % n;
        f.push(vec![k, n + k, n + j, j]);
    }
    (v, f)
}

#[test]
fn issue28_item10_a_20000_gon_contact_keeps_lambda_within_the_tolerance() {
    // A box 2 × 2 × 2 centred over the origin on a prism whose top is a 20,000-gon of radius
    // 0.5: the contact polygon is the 20,000-gon. Under λW along azimuth a at the centroid
    // (height 1), the box tips about the support line of the polygon in that direction:
    // λ = max_k (x_k · e_a) / 1, the polygon's support function (closed form over its
    // vertices). The contact ring is simplified, but only within the geometric tolerance
    // tol = 1e-7 × the model's diagonal: λ is then low by at most tol / 1 (safe side), where
    // the ring simplified vertex by vertex lost 3.1e-6 (1,250 of the 20,000 vertices kept).
    let n = 20_000;
    let r = 0.5;
    for (phase, azimuth) in [(0.0, 0.0), (1.234e-4, 0.0), (0.0, 90.0f64), (5e-5, 33.0)] {
        let mut m = model_of(
            vec![cuboid([-1.0, -1.0, 0.0], [1.0, 1.0, 2.0], false)],
            ngon_prism(n, r, phase),
        );
        let a = azimuth.to_radians();
        m.loads.live = vec![Load3d::Body {
            coefficients: [a.cos(), a.sin(), 0.0],
            blocks: None,
        }];
        let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
        // Diagonal of the model's bounding box: (−1, −1, −0.5) to (1, 1, 2).
        let tol = 1e-7 * (4.0f64 + 4.0 + 6.25).sqrt();
        assert!((st.tolerance - tol).abs() < 1e-15, "{}", st.tolerance);
        assert_eq!(st.joints.len(), 1);
        let exact = (0..n)
            .map(|k| {
                let t = phase + 2.0 * std::f64::consts::PI * k as f64 / n as f64;
                r * (t - a).cos()
            })
            .fold(f64::NEG_INFINITY, f64::max);
        let lambda = limit(&st, &SolverOptions::default())
            .unwrap()
            .load_multiplier
            .unwrap();
        assert!(
            lambda <= exact + 1e-9,
            "phase {phase}, {azimuth}°: λ = {lambda} > {exact}"
        );
        assert!(
            exact - lambda <= tol,
            "phase {phase}, {azimuth}°: λ = {lambda}, closed form {exact}: low by {:.3e} > tol {tol:.3e}",
            exact - lambda
        );
    }
}

#[test]
fn issue28_item10_every_vertex_of_a_many_vertex_contact_is_within_tol_of_its_polygon() {
    // The guarantee behind the λ above, on the geometry alone: each of the 20,000 vertices of
    // the clipped face lies within tol of the contact polygon kept (its distance to the nearest
    // edge), while far fewer vertices are kept.
    let n = 20_000;
    let tol = 3e-7;
    let (bv, bf) = ngon_prism(n, 0.5, 0.0);
    let support = clean_polyhedron("support", &bv, &bf, tol).unwrap();
    let (v, f) = cuboid([-1.0, -1.0, 0.0], [1.0, 1.0, 2.0], false);
    let block = clean_polyhedron("block", &v, &f, tol).unwrap();
    let it = detect_interfaces3(&[&block, &support], tol);
    assert_eq!(it.len(), 1);
    let poly = &it[0].polygon;
    assert!(poly.len() < n / 2, "{} vertices kept", poly.len());
    let seg = |p: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let t = (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
        (p[0] - a[0] - t * dx).hypot(p[1] - a[1] - t * dy)
    };
    let mut worst: f64 = 0.0;
    for q in &bv[..n] {
        let p = [q[0], q[1]];
        let d = (0..poly.len())
            .map(|i| {
                let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
                seg(p, [a[0], a[1]], [b[0], b[1]])
            })
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(d);
    }
    assert!(
        worst <= tol * (1.0 + 1e-9),
        "a vertex is {worst:.3e} from the polygon, tol {tol:.1e}"
    );
}
