//! The whole 3D pipeline on models written as polyhedra: validation, interface detection,
//! kinematic map, limit, tilting table, settlement and capacity, against closed forms.
//!
//! Every model here is made of boxes written out vertex by vertex (`cuboid`), so that the
//! references are hand calculations on the geometry, independent of the generators.

use voussoir::analysis::limit::{limit, limit_with, Crushing, LimitStatus};
use voussoir::analysis::settlement::{settle, SettlementStatus};
use voussoir::analysis::tilt::{tilt_azimuth, tilt_azimuth_exact};
use voussoir::lp::SolverOptions;
use voussoir::model::Material;
use voussoir::model3d::{Block3d, Load3d, Loads3d, Model3d, Support3d};
use voussoir::{Assembly, BuildOptions, Structure3d};

/// Vertices and outward faces of the box `[lo, hi]`.
fn cuboid(lo: [f64; 3], hi: [f64; 3]) -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
    let v = (0..8)
        .map(|i| {
            [
                if i & 1 == 0 { lo[0] } else { hi[0] },
                if i & 2 == 0 { lo[1] } else { hi[1] },
                if i & 4 == 0 { lo[2] } else { hi[2] },
            ]
        })
        .collect();
    let f = vec![
        vec![0, 2, 3, 1], // z = lo (outward −z)
        vec![4, 5, 7, 6], // z = hi
        vec![0, 1, 5, 4], // y = lo
        vec![2, 6, 7, 3], // y = hi
        vec![0, 4, 6, 2], // x = lo
        vec![1, 3, 7, 5], // x = hi
    ];
    (v, f)
}

fn block(lo: [f64; 3], hi: [f64; 3]) -> Block3d {
    let (vertices, faces) = cuboid(lo, hi);
    Block3d {
        vertices,
        faces,
        material: None,
    }
}

fn support(name: &str, lo: [f64; 3], hi: [f64; 3]) -> Support3d {
    let (vertices, faces) = cuboid(lo, hi);
    Support3d {
        name: name.into(),
        vertices,
        faces,
        motion: [0.0; 6],
        connection: Default::default(),
    }
}

fn model(blocks: Vec<Block3d>, supports: Vec<Support3d>, live: Vec<Load3d>) -> Model3d {
    let mut m = Model3d {
        blocks,
        supports,
        loads: Loads3d {
            live,
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

fn horizontal(theta: f64) -> Load3d {
    Load3d::Body {
        coefficients: [theta.cos(), theta.sin(), 0.0],
        blocks: None,
    }
}

fn opts() -> SolverOptions {
    SolverOptions::default()
}

fn box_on_base(b: f64, d: f64, h: f64, live: Vec<Load3d>) -> Model3d {
    model(
        vec![block([0.0, 0.0, 0.0], [b, d, h])],
        vec![support("base", [-1.0, -1.0, -0.5], [b + 1.0, d + 1.0, 0.0])],
        live,
    )
}

#[test]
fn a_box_overturns_at_the_closed_form_multiplier_at_every_azimuth() {
    // Horizontal live load λW along azimuth θ at the centroid: tipping about the edge x = b
    // (or 0) needs λ W (h/2)|cos θ| = W b/2, about y = d (or 0) λ W (h/2)|sin θ| = W d/2, so
    // λ = min(b/(h|cos θ|), d/(h|sin θ|)). The contact polygon is the box's whole base, found by
    // interface detection; its four corners are the collocation points.
    for [b, d, h] in [[1.0, 1.0, 2.0], [0.4, 1.2, 3.0], [2.0, 0.5, 1.5]] {
        for deg in [0.0f64, 20.0, 45.0, 90.0, 135.0, 200.0, 290.0] {
            let t = deg.to_radians();
            let st = Structure3d::new(
                &box_on_base(b, d, h, vec![horizontal(t)]),
                BuildOptions::default(),
            )
            .unwrap();
            assert_eq!(st.joints.len(), 1);
            assert_eq!(st.joints[0].points.len(), 4);
            let by_x = if t.cos().abs() > 1e-12 {
                b / (h * t.cos().abs())
            } else {
                f64::INFINITY
            };
            let by_y = if t.sin().abs() > 1e-12 {
                d / (h * t.sin().abs())
            } else {
                f64::INFINITY
            };
            let want = by_x.min(by_y);
            let r = limit(&st, &opts()).unwrap();
            assert_eq!(r.status, LimitStatus::Collapse);
            let got = r.load_multiplier.unwrap();
            assert!(
                (got - want).abs() < 1e-9,
                "{b}×{d}×{h} at {deg}°: λ = {got}, closed form {want}"
            );
            // The mechanism is a rotation about a base edge (or corner): the block rises.
            assert_eq!(r.blocks.len(), 1);
            let m = &r.blocks[0];
            assert!(m.theta_x.abs() + m.theta_y.abs() > 0.0);
            // Unit work of the live loads; the dead loads' work is −λ.
            assert!((r.work_live_loads.unwrap() - 1.0).abs() < 1e-9);
            assert!((r.work_dead_loads.unwrap() + got).abs() < 1e-9);
        }
    }
}

#[test]
fn tilting_table_slides_at_tan_alpha_equal_mu_with_the_exact_cone_and_within_the_pyramid() {
    // A flat box (overturning would need tan α ≥ b/h = 10) on a base with friction μ = 0.6:
    // it slides when tan α = μ whatever the azimuth with the exact cone; with the inscribed
    // pyramid of K facets, at μ where the load points at a vertex of the pyramid (azimuths
    // 2πi/K, in the frame of the joint's tangents) and at μ cos(π/K) mid-facet, never outside.
    let mu = 0.6;
    let mut m = box_on_base(1.0, 1.0, 0.1, vec![]);
    m.materials.get_mut("default").unwrap().friction = Some(mu);
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    for deg in [0.0f64, 22.5, 37.0, 90.0, 150.0, 255.0] {
        let exact = tilt_azimuth_exact(&st, deg, &opts()).unwrap();
        let tan = exact.tilt_angle.unwrap().to_radians().tan();
        assert!(
            (tan - mu).abs() < 1e-6,
            "exact cone at {deg}°: tan α = {tan}"
        );
        for k in [4usize, 8, 16] {
            let mut s = st.clone();
            s.friction_facets = k;
            let r = tilt_azimuth(&s, deg, &opts()).unwrap();
            let tan = r.tilt_angle.unwrap().to_radians().tan();
            let lo = mu * (std::f64::consts::PI / k as f64).cos();
            assert!(
                tan >= lo - 1e-9 && tan <= mu + 1e-9,
                "K = {k} at {deg}°: tan α = {tan} outside [{lo}, {mu}]"
            );
        }
    }
}

/// A wall of `courses` courses of `units` bricks `l × t × h` along x in running bond (every
/// other course shifted by half a brick, with half bricks at its ends), on a ground slab.
fn wall(courses: usize, units: usize, [l, t, h]: [f64; 3]) -> Model3d {
    let mut blocks = Vec::new();
    for c in 0..courses {
        let z = c as f64 * h;
        let mut xs: Vec<f64> = (0..=units).map(|i| i as f64 * l).collect();
        if c % 2 == 1 {
            xs = std::iter::once(0.0)
                .chain((0..units).map(|i| (i as f64 + 0.5) * l))
                .chain(std::iter::once(units as f64 * l))
                .collect();
        }
        for w in xs.windows(2) {
            blocks.push(block([w[0], 0.0, z], [w[1], t, z + h]));
        }
    }
    let len = units as f64 * l;
    model(
        blocks,
        vec![support(
            "ground",
            [-1.0, -1.0, -0.5],
            [len + 1.0, t + 1.0, 0.0],
        )],
        vec![horizontal(std::f64::consts::FRAC_PI_2)],
    )
}

#[test]
fn a_free_standing_wall_overturns_out_of_plane_at_t_over_h() {
    // Out-of-plane load λW (along +y) on every brick: the wall above any bed joint at height z
    // tips about that joint's edge when λ W_above (h_wall − z)/2 = W_above t/2, so the base
    // joint governs: λ = t/h_wall, the whole wall turning as one block about its toe.
    for (courses, units, brick) in [(6, 4, [0.5, 0.3, 0.25]), (10, 3, [0.4, 0.2, 0.1])] {
        let m = wall(courses, units, brick);
        let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
        let r = limit(&st, &opts()).unwrap();
        let height = courses as f64 * brick[2];
        let want = brick[1] / height;
        let got = r.load_multiplier.unwrap();
        assert!((got - want).abs() < 1e-9, "λ = {got}, t/h = {want}");
        // Every block turns the same way about the toe line y = t, z = 0: θx = −1/… the same
        // rotation for all (rigid overturning).
        let th: Vec<f64> = r.blocks.iter().map(|b| b.theta_x).collect();
        assert!(th
            .iter()
            .all(|x| (x - th[0]).abs() < 1e-9 * th[0].abs().max(1.0)));
        assert!(
            th[0] < 0.0,
            "turning towards +y is a negative rotation about x"
        );
    }
}

#[test]
fn a_settling_base_carries_the_box_and_both_programs_agree() {
    // The base drops by 1 cm and tilts by 0.002 rad about y, about its centroid right under
    // the box's centroid (the base is centred on the box). The box follows it rigidly: its
    // centroid, 0.5 + 0.25 = 0.75 m above the base's centroid, moves by
    // ω × r = (0, 0.002, 0) × (0, 0, 1.25)… the dead load W does work W·0.01 exactly.
    let (b, d, h) = (1.0, 1.0, 2.0);
    let mut m = model(
        vec![block([0.0, 0.0, 0.0], [b, d, h])],
        vec![support("base", [-1.0, -1.0, -0.5], [2.0, 2.0, 0.0])],
        vec![],
    );
    m.supports[0].motion = [0.0, 0.0, -0.01, 0.0, 0.002, 0.0];
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let w = 20.0 * b * d * h;
    let r = settle(&st, &opts()).unwrap();
    assert_eq!(r.status, SettlementStatus::Mechanism);
    let c = r.certificate.as_ref().unwrap();
    assert!(c.ok && c.relative_gap <= 1e-9, "{c:?}");
    assert!((c.primal - w * 0.01).abs() < 1e-9, "primal {}", c.primal);
    assert!((c.dual - w * 0.01).abs() < 1e-9, "dual {}", c.dual);
    // The box's motion: the base's rigid motion carried to the box centroid (0.5, 0.5, 1):
    // r = (0, 0, 1.25) from the base centroid (0.5, 0.5, −0.25); ω × r = (0.0025, 0, 0).
    let bm = &r.blocks[0];
    for (got, want) in [
        (bm.u, 0.0025),
        (bm.v, 0.0),
        (bm.w, -0.01),
        (bm.theta_x, 0.0),
        (bm.theta_y, 0.002),
        (bm.theta_z, 0.0),
    ] {
        assert!((got - want).abs() < 1e-12, "{bm:?}");
    }
    // The base carries the weight: reaction fz = W, and nothing else but a moment… about the
    // base's centroid the weight line passes through it: all moments vanish.
    let re = &r.reactions[0];
    assert!(
        (re.fz - w).abs() < 1e-9 && re.fx.abs() < 1e-9 && re.my.abs() < 1e-9,
        "{re:?}"
    );
}

#[test]
fn limit_on_the_deformed_geometry_moves_blocks_by_finite_rotations() {
    // Rotate the box about its base edge x = b by a finite angle through `deform`: its vertices
    // must stay at their distances (a rigid motion), and its centroid must land where the
    // exact rotation puts it.
    let st = Structure3d::new(
        &box_on_base(1.0, 1.0, 2.0, vec![horizontal(0.0)]),
        BuildOptions::default(),
    )
    .unwrap();
    let r = limit(&st, &opts()).unwrap();
    let d: Vec<f64> = {
        let m = &r.blocks[0];
        vec![m.u, m.v, m.w, m.theta_x, m.theta_y, m.theta_z]
    };
    // Scale so that the rotation is 0.3 rad.
    let s = 0.3 / d[4].abs();
    let moved = st.deform(&d, s).unwrap();
    let v0 = &st.blocks[0].shape.vertices;
    let v1 = &moved.blocks[0].shape.vertices;
    for i in 0..8 {
        for j in 0..8 {
            let dist = |v: &Vec<[f64; 3]>| {
                ((v[i][0] - v[j][0]).powi(2)
                    + (v[i][1] - v[j][1]).powi(2)
                    + (v[i][2] - v[j][2]).powi(2))
                .sqrt()
            };
            assert!((dist(v0) - dist(v1)).abs() < 1e-12);
        }
    }
    // As in 2D, a block's finite motion is the exact rotation by s·θ about its centroid and
    // the translation s·u of the centroid: the centroid (0.5, 0.5, 1) goes to c + s·u, here
    // u = ω × (c − hinge) per unit θy = (1, 0, 0.5)·θy, so (0.8, 0.5, 1.15) for 0.3 rad.
    let c = moved.blocks[0].shape.centroid;
    for (got, want) in c.iter().zip([0.8, 0.5, 1.15]) {
        assert!((got - want).abs() < 1e-12, "{c:?}");
    }
    // And the top face turned by exactly 0.3 rad: its normal is (sin 0.3, 0, cos 0.3).
    let v = &moved.blocks[0].shape.vertices;
    let e = [v[5][0] - v[4][0], v[5][2] - v[4][2]]; // the top edge along x
    assert!((e[1].atan2(e[0]) + 0.3).abs() < 1e-12, "{e:?}");
    // The contact points of the base joint moved with the blocks: the hinge edge's points are
    // still closed (gap 0), the opened ones carry their gap.
    let gaps: Vec<f64> = moved.joints[0].points.iter().map(|p| p.gap).collect();
    assert_eq!(gaps.iter().filter(|g| **g == 0.0).count(), 2, "{gaps:?}");
}

#[test]
fn finite_strength_and_bad_polyhedra_are_refused_in_one_line() {
    let mut m = box_on_base(1.0, 1.0, 1.0, vec![horizontal(0.0)]);
    m.materials.get_mut("default").unwrap().compressive_strength = Some(1000.0);
    let e = Structure3d::new(&m, BuildOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("2D only") && !e.contains('\n'), "{e}");
    let mut m = box_on_base(1.0, 1.0, 1.0, vec![]);
    m.blocks[0].faces.pop();
    let e = Structure3d::new(&m, BuildOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("block 0") && !e.contains('\n'), "{e}");
    // A block floating above the base touches nothing.
    let m = model(
        vec![
            block([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]),
            block([0.0, 0.0, 2.0], [1.0, 1.0, 3.0]),
        ],
        vec![support("base", [-1.0, -1.0, -0.5], [2.0, 2.0, 0.0])],
        vec![],
    );
    let e = Structure3d::new(&m, BuildOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("block 1 touches nothing"), "{e}");
    // Overlapping blocks are named.
    let m = model(
        vec![
            block([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]),
            block([0.5, 0.0, 0.0], [1.5, 1.0, 1.0]),
        ],
        vec![support("base", [-1.0, -1.0, -0.5], [2.0, 2.0, 0.0])],
        vec![],
    );
    let e = Structure3d::new(&m, BuildOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("block 0 and block 1 overlap"), "{e}");
    // The exact friction cone needs Clarabel's cones; the option is the same path as the 2D
    // conic crushing model: without friction it is the plain limit analysis.
    let st = Structure3d::new(
        &box_on_base(1.0, 1.0, 2.0, vec![horizontal(0.0)]),
        BuildOptions::default(),
    )
    .unwrap();
    let a = limit(&st, &opts()).unwrap().load_multiplier.unwrap();
    let b = limit_with(&st, &opts(), Crushing::Conic, 16)
        .unwrap()
        .load_multiplier
        .unwrap();
    assert!((a - 0.5).abs() < 1e-9 && (b - 0.5).abs() < 1e-6, "{a} {b}");
}
