//! Issue 30, item 1: meshes of any wall (`voussoir::outline_mesh`): an outline with holes cut
//! into a grid, a running bond or refined constrained-Delaunay triangles, on foundation
//! segments along its base.
//!
//! References: areas from closed forms (rectangles, a regular octagon (n/2)·r²·sin(2π/n));
//! the weight γ·A·t; the coverage of every element edge computed here edge against edge
//! (independently of the library's joint detection); the tilting-table collapse of a panel,
//! λ = b/h (hand calculation below); the paper's façade settlement against the same façade
//! meshed as a grid and as a running bond.

mod support;
use support::settle_right_half;
use voussoir::analysis::limit::limit;
use voussoir::analysis::settlement::{settle_with, SettlementForm, SettlementStatus};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
use voussoir::geometry::signed_area;
use voussoir::lp::SolverOptions;
use voussoir::model::{Load, Point};
use voussoir::outline_mesh::{
    foundation_supports, mesh_polygons, mesh_wall, min_angle_deg, Foundation, MeshKind,
    MeshOptions, Outline,
};
use voussoir::result::limit::LimitStatus;
use voussoir::{BuildOptions, Structure};

/// An 8 × 5 m wall with a door notch (1.2 × 2.2 m) in its base, a rectangular window
/// (1 × 1.2 m) and a regular octagonal window (circumradius 0.6 m).
fn wall() -> (Outline, f64) {
    let oct: Vec<Point> = (0..8)
        .map(|k| {
            let a = std::f64::consts::PI / 4.0 * k as f64 + 0.1;
            [6.0 + 0.6 * a.cos(), 3.0 + 0.6 * a.sin()]
        })
        .collect();
    let outline = Outline::new(
        vec![
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 2.2],
            [4.2, 2.2],
            [4.2, 0.0],
            [8.0, 0.0],
            [8.0, 5.0],
            [0.0, 5.0],
        ],
        // The rectangle drawn clockwise: either orientation is accepted.
        vec![vec![[1.0, 2.5], [1.0, 3.7], [2.0, 3.7], [2.0, 2.5]], oct],
    );
    let octagon = 4.0 * 0.6 * 0.6 * (std::f64::consts::PI / 4.0).sin();
    let net = 8.0 * 5.0 - 1.2 * 2.2 - 1.0 * 1.2 - octagon;
    (outline, net)
}

fn kinds() -> [MeshKind; 3] {
    [
        MeshKind::Grid {
            length: 0.5,
            height: 0.25,
        },
        MeshKind::RunningBond {
            length: 0.5,
            height: 0.25,
        },
        MeshKind::Triangles {
            max_area: 0.125,
            min_angle_deg: 30.0,
        },
    ]
}

/// Length of the part of segment a–b that lies on segment c–d (collinear within `tol`).
fn overlap(a: Point, b: Point, c: Point, d: Point, tol: f64) -> f64 {
    let e = [b[0] - a[0], b[1] - a[1]];
    let l = e[0].hypot(e[1]);
    let e = [e[0] / l, e[1] / l];
    let off = |p: Point| ((p[0] - a[0]) * e[1] - (p[1] - a[1]) * e[0]).abs();
    if off(c) > tol || off(d) > tol {
        return 0.0;
    }
    let s = |p: Point| (p[0] - a[0]) * e[0] + (p[1] - a[1]) * e[1];
    let (s0, s1) = (s(c).min(s(d)), s(c).max(s(d)));
    (s1.min(l) - s0.max(0.0)).max(0.0)
}

fn edges(p: &[Point]) -> impl Iterator<Item = (Point, Point)> + '_ {
    (0..p.len()).map(move |i| (p[i], p[(i + 1) % p.len()]))
}

#[test]
fn issue30_item1_meshed_area_is_the_outline_minus_its_holes() {
    let (o, net) = wall();
    for kind in kinds() {
        for min_piece in [0.0, 0.2] {
            if min_piece > 0.0 && matches!(kind, MeshKind::Triangles { .. }) {
                continue;
            }
            let opts = MeshOptions {
                min_piece,
                ..MeshOptions::default()
            };
            let p = mesh_polygons(&o, &kind, &opts).unwrap();
            let a: f64 = p.iter().map(|q| signed_area(q)).sum();
            assert!(
                (a - net).abs() <= 1e-9 * net,
                "{kind:?}, min piece {min_piece}: {a} m² of elements, {net} m² by hand"
            );
            // Every element counter-clockwise, of positive area, inside the outline.
            for q in &p {
                assert!(signed_area(q) > 0.0, "{kind:?}: {q:?}");
            }
        }
    }
}

#[test]
fn issue30_item1_total_weight_is_density_area_thickness() {
    let (o, net) = wall();
    let (gamma, t) = (20.0, 0.4);
    for kind in kinds() {
        let m = mesh_wall(
            &o,
            &kind,
            gamma,
            t,
            &Foundation::segments(4, "f", 0.5),
            &MeshOptions::default(),
        )
        .unwrap();
        // The library's own validation: simple polygons, no overlaps, nothing isolated.
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        let w: f64 = st.blocks.iter().map(|b| b.weight).sum();
        let want = gamma * net * t;
        assert!(
            (w - want).abs() <= 1e-9 * want,
            "{kind:?}: weight {w} kN, γ·A·t = {want} kN"
        );
    }
}

#[test]
fn issue30_item1_every_element_edge_is_shared_by_two_elements_or_a_support_or_is_free() {
    let (o, _) = wall();
    let tol = 1e-9;
    for kind in kinds() {
        let m = mesh_wall(
            &o,
            &kind,
            18.0,
            1.0,
            &Foundation::segments(3, "f", 0.5),
            &MeshOptions::default(),
        )
        .unwrap();
        let polys: Vec<&Vec<Point>> = m.blocks.iter().map(|b| &b.polygon).collect();
        // The outline's edges except the base (which stands on the supports).
        let free: Vec<(Point, Point)> = std::iter::once(&o.outer)
            .chain(&o.holes)
            .flat_map(|r| edges(r).collect::<Vec<_>>())
            .filter(|(a, b)| !(a[1] == 0.0 && b[1] == 0.0))
            .collect();
        let supports: Vec<(Point, Point)> = m
            .supports
            .iter()
            .flat_map(|s| edges(&s.polygon).collect::<Vec<_>>())
            .collect();
        let boxes: Vec<[f64; 4]> = polys.iter().map(|p| voussoir::geometry::bbox(p)).collect();
        for (i, p) in polys.iter().enumerate() {
            for (a, b) in edges(p) {
                let len = (b[0] - a[0]).hypot(b[1] - a[1]);
                let mut by_blocks = 0.0;
                let mut count = 0;
                for (j, q) in polys.iter().enumerate() {
                    let bb = boxes[j];
                    if j == i
                        || bb[0] > a[0].max(b[0]) + tol
                        || bb[2] < a[0].min(b[0]) - tol
                        || bb[1] > a[1].max(b[1]) + tol
                        || bb[3] < a[1].min(b[1]) - tol
                    {
                        continue;
                    }
                    for (c, d) in edges(q) {
                        let l = overlap(a, b, c, d, tol);
                        if l > tol {
                            by_blocks += l;
                            count += 1;
                        }
                    }
                }
                let on_free: f64 = free.iter().map(|&(c, d)| overlap(a, b, c, d, tol)).sum();
                let on_support: f64 = supports
                    .iter()
                    .map(|&(c, d)| overlap(a, b, c, d, tol))
                    .sum();
                let covered = by_blocks + on_free + on_support;
                assert!(
                    (covered - len).abs() <= 1e-9 * len.max(1.0),
                    "{kind:?}: edge {a:?}–{b:?} of element {i} ({len} m): {by_blocks} m on {count} other element edge(s), {on_free} m free, {on_support} m on supports"
                );
            }
        }
    }
}

#[test]
fn issue30_item1_triangles_respect_the_min_angle() {
    let (o, _) = wall();
    for (max_area, angle) in [(0.125, 30.0), (0.3, 20.0), (0.05, 25.0)] {
        let p = mesh_polygons(
            &o,
            &MeshKind::Triangles {
                max_area,
                min_angle_deg: angle,
            },
            &MeshOptions::default(),
        )
        .unwrap();
        assert!(p.iter().all(|t| t.len() == 3));
        let worst = p
            .iter()
            .map(|t| min_angle_deg(t))
            .fold(f64::INFINITY, f64::min);
        let largest = p.iter().map(|t| signed_area(t)).fold(0.0, f64::max);
        // The outline has no corner sharper than 90°: the bound holds everywhere.
        assert!(
            worst >= angle - 1e-9,
            "max area {max_area}, min angle {angle}: worst {worst}°"
        );
        assert!(
            largest <= max_area * (1.0 + 1e-12),
            "{largest} > {max_area}"
        );
    }
}

#[test]
fn issue30_item1_a_size_field_refines_locally() {
    let (o, net) = wall();
    let kind = MeshKind::Triangles {
        max_area: 0.3,
        min_angle_deg: 25.0,
    };
    let coarse = mesh_polygons(&o, &kind, &MeshOptions::default()).unwrap();
    // Fine (≤ 0.01 m²) in a band along the diagonal crack line y = x/2 + 0.5, coarse elsewhere.
    let band = |p: Point| (p[1] - (0.5 * p[0] + 0.5)).abs() < 0.4;
    let size = |p: Point| if band(p) { 0.01 } else { 1.0 };
    let fine = mesh_polygons(
        &o,
        &kind,
        &MeshOptions {
            size: Some(&size),
            ..MeshOptions::default()
        },
    )
    .unwrap();
    let a: f64 = fine.iter().map(|q| signed_area(q)).sum();
    assert!((a - net).abs() <= 1e-9 * net);
    let centroid = |t: &Vec<Point>| {
        [
            (t[0][0] + t[1][0] + t[2][0]) / 3.0,
            (t[0][1] + t[1][1] + t[2][1]) / 3.0,
        ]
    };
    let in_band = |m: &[Vec<Point>]| m.iter().filter(|t| band(centroid(t))).count();
    for t in &fine {
        let s = if band(centroid(t)) { 0.01 } else { 0.3 };
        assert!(
            signed_area(t) <= s * (1.0 + 1e-12),
            "{t:?}: {}",
            signed_area(t)
        );
    }
    assert!(
        in_band(&fine) > 5 * in_band(&coarse),
        "{} triangles in the band, {} without the size field",
        in_band(&fine),
        in_band(&coarse)
    );
    let worst = fine
        .iter()
        .map(|t| min_angle_deg(t))
        .fold(f64::INFINITY, f64::min);
    assert!(worst >= 25.0 - 1e-9, "{worst}");
    // A bad size is refused in one line.
    let bad = |_: Point| -1.0;
    let e = mesh_polygons(
        &o,
        &kind,
        &MeshOptions {
            size: Some(&bad),
            ..MeshOptions::default()
        },
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("size field") && !e.contains('\n'), "{e}");
}

#[test]
fn issue30_item1_foundation_segments_along_the_base() {
    let (o, _) = wall();
    let f = Foundation::segments(4, "f", 0.5);
    let s = foundation_supports(&o, &f).unwrap();
    let names: Vec<&str> = s.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["f0", "f1", "f2", "f3"]);
    // Equal parts of the base 0 … 8 m, 0.5 m deep under y = 0.
    for (k, sp) in s.iter().enumerate() {
        let b = voussoir::geometry::bbox(&sp.polygon);
        assert_eq!(b, [2.0 * k as f64, -0.5, 2.0 * (k + 1) as f64, 0.0]);
    }
    // Triangles end where the segments do: no triangle edge on the base crosses x = 2, 4, 6.
    let m = mesh_wall(
        &o,
        &MeshKind::Triangles {
            max_area: 0.5,
            min_angle_deg: 20.0,
        },
        18.0,
        1.0,
        &f,
        &MeshOptions::default(),
    )
    .unwrap();
    for b in &m.blocks {
        for (a, c) in edges(&b.polygon) {
            if a[1] == 0.0 && c[1] == 0.0 {
                for x in [2.0, 4.0, 6.0] {
                    assert!(
                        !(a[0].min(c[0]) < x - 1e-12 && a[0].max(c[0]) > x + 1e-12),
                        "base edge {a:?}–{c:?} straddles x = {x}"
                    );
                }
            }
        }
    }
    // One support: the name given.
    let s = foundation_supports(&o, &Foundation::single("base", 0.3)).unwrap();
    assert_eq!(s.len(), 1);
    assert_eq!(s[0].name, "base");
    // A base that is not horizontal is refused.
    let tilted = Outline::new(vec![[0.0, 0.0], [4.0, 1.0], [4.0, 3.0], [0.0, 3.0]], vec![]);
    let e = foundation_supports(&tilted, &f).unwrap_err().to_string();
    assert!(e.contains("horizontal edge"), "{e}");
}

#[test]
fn issue30_item1_bad_outlines_are_refused_naming_the_polygon() {
    let sq = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]];
    let kind = MeshKind::Triangles {
        max_area: 0.5,
        min_angle_deg: 25.0,
    };
    let err = |o: Outline| {
        let e = mesh_polygons(&o, &kind, &MeshOptions::default())
            .unwrap_err()
            .to_string();
        assert!(!e.contains('\n'), "{e}");
        e
    };
    let bowtie = vec![[0.0, 0.0], [4.0, 3.0], [4.0, 0.0], [0.0, 3.0]];
    let e = err(Outline::new(bowtie.clone(), vec![]));
    assert!(e.contains("the outer boundary intersects itself"), "{e}");
    let e = err(Outline::new(
        sq.clone(),
        vec![vec![[1.0, 1.0], [2.0, 1.0], [1.5, 1.0]]],
    ));
    assert!(e.contains("hole 0 has no area"), "{e}");
    let e = err(Outline::new(
        sq.clone(),
        vec![vec![[5.0, 1.0], [6.0, 1.0], [6.0, 2.0]]],
    ));
    assert!(e.contains("hole 0 lies outside"), "{e}");
    let e = err(Outline::new(
        sq.clone(),
        vec![vec![[3.0, 1.0], [5.0, 1.0], [5.0, 2.0], [3.0, 2.0]]],
    ));
    assert!(
        e.contains("hole 0 crosses or touches the outer boundary"),
        "{e}"
    );
    let e = err(Outline::new(
        sq.clone(),
        vec![
            vec![[0.5, 0.5], [1.5, 0.5], [1.5, 1.5], [0.5, 1.5]],
            vec![[1.0, 1.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0]],
        ],
    ));
    assert!(e.contains("hole 0 and hole 1"), "{e}");
    let e = err(Outline::new(
        sq.clone(),
        vec![
            vec![[0.5, 0.5], [3.5, 0.5], [3.5, 2.5], [0.5, 2.5]],
            vec![[1.0, 1.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0]],
        ],
    ));
    assert!(e.contains("hole 0 and hole 1 overlap"), "{e}");
    let e = err(Outline::new(
        vec![[0.0, 0.0], [f64::NAN, 0.0], [1.0, 1.0]],
        vec![],
    ));
    assert!(e.contains("not a finite number"), "{e}");
    let e = err(Outline::new(vec![[0.0, 0.0], [1.0, 0.0]], vec![]));
    assert!(e.contains("fewer than 3"), "{e}");
    // Bad sizes, one line each.
    for (k, want) in [
        (
            MeshKind::Grid {
                length: 0.0,
                height: 0.2,
            },
            "positive",
        ),
        (
            MeshKind::Triangles {
                max_area: 0.1,
                min_angle_deg: 40.0,
            },
            "min angle",
        ),
        (
            MeshKind::Triangles {
                max_area: -1.0,
                min_angle_deg: 20.0,
            },
            "max area",
        ),
        (
            MeshKind::Triangles {
                max_area: 1e-9,
                min_angle_deg: 20.0,
            },
            "elements",
        ),
    ] {
        let e = mesh_polygons(
            &Outline::new(sq.clone(), vec![]),
            &k,
            &MeshOptions::default(),
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains(want) && !e.contains('\n'), "{k:?}: {e}");
    }
}

#[test]
fn issue30_item1_meshes_are_deterministic() {
    let (o, _) = wall();
    for kind in kinds() {
        let m = || {
            serde_json::to_string(
                &mesh_wall(
                    &o,
                    &kind,
                    18.0,
                    1.0,
                    &Foundation::segments(2, "f", 0.5),
                    &MeshOptions::default(),
                )
                .unwrap(),
            )
            .unwrap()
        };
        assert_eq!(m(), m(), "{kind:?}");
    }
}

fn tilt(o: &Outline, kind: MeshKind) -> (f64, usize) {
    let mut m = mesh_wall(
        o,
        &kind,
        18.0,
        1.0,
        &Foundation::single("base", 0.5),
        &MeshOptions::default(),
    )
    .unwrap();
    m.loads.live.push(Load::Body {
        coefficients: [1.0, 0.0],
        blocks: None,
    });
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::Collapse, "{kind:?}");
    (r.load_multiplier.unwrap(), st.blocks.len())
}

/// λ of a piece of a panel (a polygon) overturning about the point `c` under the tilting-table
/// load: λ·W·(ȳ − y_c) = W·(x_c − x̄).
fn overturning(piece: &[Point], c: Point) -> f64 {
    let (_, g) = voussoir::geometry::area_centroid(piece);
    (c[0] - g[0]) / (g[1] - c[1])
}

/// The tilting-table load (a horizontal force equal to each element's weight) on a b × h
/// panel standing on one support. Hand calculation: the whole panel overturning about its
/// right toe, λ·W·h/2 = W·b/2, gives λ = b/h; that mechanism is open to every mesh, so
/// λ ≤ b/h always. Under Heyman's hypotheses (no sliding) a piece separates from the rest
/// only along a straight crack through its centre of rotation: the grid's pieces above a bed
/// joint at height y give b/(h − y) ≥ b/h, and its head joints would have to slide, so the
/// grid collapses at b/h.
#[test]
fn issue30_item1_a_grid_panel_tilts_at_b_over_h() {
    for (b, h) in [(2.0, 3.0), (1.0, 4.0)] {
        let o = Outline::new(vec![[0.0, 0.0], [b, 0.0], [b, h], [0.0, h]], vec![]);
        let (lambda, n) = tilt(
            &o,
            MeshKind::Grid {
                length: 0.4,
                height: 0.2,
            },
        );
        assert!(
            (lambda - b / h).abs() <= 1e-6 * (b / h),
            "{b} × {h} m grid ({n} elements): λ = {lambda}, b/h = {}",
            b / h
        );
    }
}

/// Triangles do hinge internally: a straight crack through the toe splits off a wedge, as in
/// a no-tension continuum. A 1 × 4 m panel with a vertex at (0, 1) on its left face,
/// triangulated without refinement (min angle 0, max area above the panel's): its
/// constrained Delaunay triangulation is unique, three triangles: (0,0)-(1,0)-(0,1) (its
/// circumcircle holds no other vertex), then (1,0)-(1,4)-(0,1) and (0,1)-(1,4)-(0,4) (the
/// circumcircle of (1,0)-(1,4)-(0,4) holds (0,1)). By hand: the whole panel tips at b/h =
/// 0.25; the two upper triangles together, cracked from the lower-left one along the 45° edge
/// (1,0)-(0,1) through the toe, tip about the toe at λ = (x_c − x̄)/(ȳ − y_c) = 0.21277; the
/// upper-left triangle alone would close its crack. So λ = 0.21277 < b/h.
#[test]
fn issue30_item1_a_triangle_panel_tips_along_its_diagonal_crack_as_by_hand() {
    let o = Outline::new(
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 4.0], [0.0, 4.0], [0.0, 1.0]],
        vec![],
    );
    let kind = MeshKind::Triangles {
        max_area: 10.0,
        min_angle_deg: 0.0,
    };
    let tris = mesh_polygons(&o, &kind, &MeshOptions::default()).unwrap();
    assert_eq!(tris.len(), 3, "{tris:?}");
    let wedge = overturning(
        &[[1.0, 0.0], [1.0, 4.0], [0.0, 4.0], [0.0, 1.0]],
        [1.0, 0.0],
    );
    assert!((wedge - 0.212766).abs() < 1e-6, "{wedge}");
    let (lambda, _) = tilt(&o, kind);
    assert!(
        (lambda - wedge).abs() <= 1e-6 * wedge,
        "λ = {lambda}, the wedge by hand {wedge}, b/h = 0.25"
    );
    // The same panel as a grid: b/h.
    let (grid, _) = tilt(
        &o,
        MeshKind::Grid {
            length: 0.25,
            height: 0.25,
        },
    );
    assert!((grid - 0.25).abs() <= 1e-6 * 0.25, "grid λ = {grid}");
    // Refined triangles: never above b/h (the whole panel's mechanism is open to them too).
    let (fine, n) = tilt(
        &o,
        MeshKind::Triangles {
            max_area: 0.05,
            min_angle_deg: 30.0,
        },
    );
    assert!(fine <= 0.25 * (1.0 + 1e-6), "{n} triangles: λ = {fine}");
}

fn settle_facade(element: f64, mesh: FacadeMesh) -> (f64, f64, usize) {
    let m = facade(&bondeno(element, mesh)).unwrap();
    let st = settle_right_half(m);
    let r = settle_with(&st, &SolverOptions::default(), SettlementForm::ForceOnly).unwrap();
    assert_eq!(r.status, SettlementStatus::Mechanism, "{mesh:?}");
    let c = r.certificate.as_ref().unwrap();
    assert!(c.ok && c.relative_gap < 1e-7, "{mesh:?}: {c:?}");
    let weight: f64 = st.blocks.iter().map(|b| b.weight).sum();
    (r.work_dead_loads.unwrap(), weight, st.blocks.len())
}

/// The paper's façade (right half settling 20 cm) meshed as triangles: the settlement runs and
/// is certified; its work is at least the running bond's (whose bond interlocks: the least of
/// the three) and at most the physical bound W·v (no element drops further than the foundation
/// under it). It is close to the grid's and may exceed it: the settlement's work is the largest
/// over the mesh's mechanisms, and triangles let cracks run diagonally. Measured (printed, not
/// asserted): element 1.0 m, triangles 382.17 kN·m (1,094 elements), grid 361.68, running bond
/// 179.53; element 0.5 m (docs/meshes.md), 384.71, 369.66 and 179.25.
fn triangles_between_the_bond_and_the_bound(element: f64) {
    let (tri, w_tri, n) = settle_facade(element, FacadeMesh::Triangles);
    let (grid, w_grid, _) = settle_facade(element, FacadeMesh::Grid);
    let (bond, _, _) = settle_facade(element, FacadeMesh::RunningBond);
    println!(
        "element {element} m: work: triangles {tri} kN·m ({n} elements), grid {grid}, running bond {bond}, W·v {}",
        w_tri * 0.2
    );
    assert!(tri > 0.0);
    assert!(bond <= grid, "running bond {bond} > grid {grid}");
    assert!(
        tri >= bond * (1.0 - 1e-6),
        "triangles {tri} < running bond {bond}"
    );
    assert!(tri <= w_tri * 0.2, "{tri} > W·v = {}", w_tri * 0.2);
    // The same wall: the weights of the meshes agree to the arcs' chords (the triangles
    // follow the rings exactly; the grid drops slivers under 5 % of an element).
    assert!(
        (w_tri - w_grid).abs() < 0.01 * w_grid,
        "{w_tri} vs {w_grid}"
    );
}

#[test]
fn issue30_item1_facade_of_triangles_settles_between_the_bond_and_the_bound() {
    triangles_between_the_bond_and_the_bound(1.0);
}

#[test]
#[ignore = "the 0.5 m façades: 428 s wall in the whole suite at load 10 on 2 cores (session 18); element 1.0 m runs in CI"]
fn issue30_item1_half_metre_facade_of_triangles_settles_between_the_bond_and_the_bound() {
    triangles_between_the_bond_and_the_bound(0.5);
}
