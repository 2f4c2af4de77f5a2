//! The kinematic map's signs and the programs' rows, against hand calculations.
//!
//! * A known rigid motion gives the known openings and slips, in 2D (from a model) and in 3D
//!   (from contact frames: a unit cube on the ground).
//! * The settlement force program (69)–(71), its dual the motion program (62)–(66), and the
//!   static limit program (Remark 3) of two stacked blocks, entry by entry.

use voussoir::dim::{Dim, Three, Two};
use voussoir::discretize::{ContactBodies, ContactJoint, JointLaw, KinematicMap};
use voussoir::lp::{self, LpStatus, SolverOptions};
use voussoir::programs;
use voussoir::structure::Body;
use voussoir::{BuildOptions, Model, Structure};

const TOL: f64 = 1e-12;

/// Two unit squares stacked on a 2 m wide base: block 0 = [0,1]², block 1 = [0,1]×[1,2].
/// γ = 10 kN/m³, width 1 m: each block weighs 10 kN. A horizontal live load of 1 kN at the top
/// right corner of block 1 (point (1, 2)).
fn two_blocks(support_motion: [f64; 3]) -> Structure {
    let json = format!(
        r#"{{
        "materials": {{ "default": {{ "unit_weight": 10.0 }} }},
        "blocks": [
            {{ "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]] }},
            {{ "polygon": [[0, 1], [1, 1], [1, 2], [0, 2]] }}
        ],
        "supports": [
            {{ "name": "base", "polygon": [[-0.5, -1], [1.5, -1], [1.5, 0], [-0.5, 0]],
               "motion": [{}, {}, {}] }}
        ],
        "loads": {{ "live": [ {{ "type": "point", "block": 1, "at": [1, 2], "force": [1, 0] }} ] }}
    }}"#,
        support_motion[0], support_motion[1], support_motion[2]
    );
    let model: Model = serde_json::from_str(&json).unwrap();
    Structure::new(&model, BuildOptions::default()).unwrap()
}

/// Index of the joint between `a` and `b`.
fn joint(st: &Structure, a: Body, b: Body) -> usize {
    st.joints
        .iter()
        .position(|j| (j.a, j.b) == (a, b))
        .expect("joint exists")
}

#[test]
fn map_signs_2d_rocking_and_sliding_of_the_top_block() {
    let st = two_blocks([0.0; 3]);
    let map = KinematicMap::new(&st);
    assert_eq!((map.dofs_per_block, map.tangents_per_point), (3, 1));
    let j = joint(&st, Body::Block(0), Body::Block(1));
    let jt = &st.joints[j];
    // The normal points from block 0 into block 1: up; the tangent t = (−n_y, n_x) = (−1, 0).
    assert_eq!(jt.normal, [0.0, 1.0]);
    // Block 1 rocks about its bottom left corner (0, 1) by θ = 0.01 (counter-clockwise): its
    // centroid (0.5, 1.5) moves by θ·(−(1.5 − 1), 0.5 − 0) = (−0.005, 0.005).
    let th = 0.01;
    let d = [0.0, 0.0, 0.0, -0.5 * th, 0.5 * th, th];
    let (open, slide) = map.jumps(&d, 1.0);
    for k in map.joint_start[j]..map.joint_start[j + 1] {
        let x = jt.points[map.points[k].index].x;
        // The point (1, 1) lifts by θ·1 (opening θ); the pivot (0, 1) stays.
        let expect = if x[0] > 0.5 { th } else { 0.0 };
        assert!(
            (open[k] - expect).abs() < TOL,
            "opening {} at {x:?}",
            open[k]
        );
        assert!(slide[k].abs() < TOL, "slide {} at {x:?}", slide[k]);
    }
    // Block 1 slides by u = 0.02 to the right: slip along t = (−1, 0) is −0.02, no opening.
    let d = [0.0, 0.0, 0.0, 0.02, 0.0, 0.0];
    let (open, slide) = map.jumps(&d, 1.0);
    for k in map.joint_start[j]..map.joint_start[j + 1] {
        assert!(open[k].abs() < TOL && (slide[k] + 0.02).abs() < TOL);
    }
    // The base settles by 1 cm: the bed joint of block 0 opens by 0.01 at both points (block 0
    // is `a` of that joint, the support `b`; n points down, into the support).
    let st = two_blocks([0.0, -0.01, 0.0]);
    let map = KinematicMap::new(&st);
    let j = joint(&st, Body::Block(0), Body::Support(0));
    assert_eq!(st.joints[j].normal, [0.0, -1.0]);
    for k in map.joint_start[j]..map.joint_start[j + 1] {
        assert!((map.support_normal[k] - 0.01).abs() < TOL);
        assert!(map.support_tangent[k].abs() < TOL);
    }
}

/// A unit cube [0,1]³ (block 0, centroid (0.5, 0.5, 0.5)) on the ground (support 0, reference
/// point the origin), contact points at the four corners of the base.
fn cube_on_ground(ground_motion: [f64; 6]) -> KinematicMap {
    let n = [0.0, 0.0, -1.0]; // from the cube (a) into the ground (b)
    let law = JointLaw {
        friction: None,
        cohesion: 0.0,
        strength: None,
        depth: 1.0,
        width: 1.0,
    };
    let joints = vec![ContactJoint::<Three> {
        a: Body::Block(0),
        b: Body::Support(0),
        normal: n,
        tangents: Three::tangents(n),
        points: vec![
            ([0.0, 0.0, 0.0], 0.0),
            ([1.0, 0.0, 0.0], 0.0),
            ([1.0, 1.0, 0.0], 0.0),
            ([0.0, 1.0, 0.0], 0.0),
        ],
        bilateral: false,
        law,
        along: vec![],
    }];
    let bodies = ContactBodies::<Three> {
        blocks: vec![[0.5, 0.5, 0.5]],
        supports: vec![([0.0, 0.0, 0.0], ground_motion.to_vec())],
    };
    KinematicMap::assemble(&bodies, &joints)
}

#[test]
fn map_signs_3d_cube_tipping_sliding_and_moving_ground() {
    let map = cube_on_ground([0.0; 6]);
    assert_eq!((map.dofs_per_block, map.tangents_per_point), (6, 2));
    assert_eq!((map.num_points(), map.num_tangent_rows()), (4, 8));
    // Tangents of n = −z: t₁ = x, t₂ = n × t₁ = −y.
    assert_eq!(
        Three::tangents([0.0, 0.0, -1.0]),
        [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0]]
    );
    // The cube tips about its base edge y = 1 (towards +y) by θ = 0.02: rotation vector
    // ω = (−θ, 0, 0); the centroid moves by ω × (c − p) with p = (0.5, 1, 0):
    // (−θ, 0, 0) × (0, −0.5, 0.5) = (0, 0.5θ, 0.5θ). The edge y = 0 lifts by θ.
    let th = 0.02;
    let d = [0.0, 0.5 * th, 0.5 * th, -th, 0.0, 0.0];
    let (open, slide) = map.jumps(&d, 1.0);
    let expect = [th, th, 0.0, 0.0];
    for k in 0..4 {
        assert!((open[k] - expect[k]).abs() < TOL, "opening {open:?}");
    }
    assert!(slide.iter().all(|s| s.abs() < TOL), "slides {slide:?}");
    // Sliding by (a, b, 0): the ground moves by −(a, b, 0) relative to the cube: slip along
    // t₁ = x is −a, along t₂ = −y is +b.
    let (a, b) = (0.03, -0.01);
    let (open, slide) = map.jumps(&[a, b, 0.0, 0.0, 0.0, 0.0], 1.0);
    for k in 0..4 {
        assert!(open[k].abs() < TOL);
        assert!((slide[2 * k] + a).abs() < TOL && (slide[2 * k + 1] - b).abs() < TOL);
    }
    // Twisting about the vertical axis through the centroid by ψ = 0.01: the corner (0, 0, 0)
    // moves by ψ ẑ × (−0.5, −0.5, ·) = ψ (0.5, −0.5, 0): slips −0.5ψ (t₁) and −0.5ψ (t₂).
    let psi = 0.01;
    let (_, slide) = map.jumps(&[0.0, 0.0, 0.0, 0.0, 0.0, psi], 1.0);
    assert!((slide[0] + 0.5 * psi).abs() < TOL && (slide[1] + 0.5 * psi).abs() < TOL);
    // The ground rotates about its reference point (the origin) by φ = 0.01 about y: the point
    // (1, 0, 0) moves by φ ŷ × x̂ = −φ ẑ (down: away from the cube), so that point opens by φ
    // (n = −z); the points on x = 0 stay.
    let phi = 0.01;
    let map = cube_on_ground([0.0, 0.0, 0.0, 0.0, phi, 0.0]);
    let g = &map.support_normal;
    assert!(
        g[0].abs() < TOL
            && (g[1] - phi).abs() < TOL
            && (g[2] - phi).abs() < TOL
            && g[3].abs() < TOL
    );
    // Equilibrium is the transpose: for any forces, the work of the resultants on d equals the
    // work of the forces on the jumps (virtual work), here with d the tipping motion.
    let pn = [1.0, 2.0, 3.0, 4.0];
    let pt = [0.5, -0.5, 0.25, 0.0, -1.0, 2.0, 0.0, 0.1];
    let f = map.resultants(&pn, &pt);
    let (open, slide) = map.jumps(&d, 0.0);
    let lhs: f64 = f.iter().zip(&d).map(|(a, b)| a * b).sum();
    let rhs: f64 = pn.iter().zip(&open).map(|(a, b)| a * b).sum::<f64>()
        + pt.iter().zip(&slide).map(|(a, b)| a * b).sum::<f64>();
    assert!((lhs - rhs).abs() < TOL);
}

#[test]
fn dof_rows_are_the_same_code_in_both_dimensions() {
    // A 3D motion in the xy-plane (u, v, θz) acts on points of the plane z = 0 like the 2D motion
    // (u, v, θ): one dimension layer, two instances that agree where they overlap.
    let (c2, x2) = ([0.3, 0.4], [1.2, -0.7]);
    let d2 = [0.01, -0.02, 0.03];
    let u2 = Two::small_displacement(c2, &d2, x2);
    let u3 = Three::small_displacement(
        [0.3, 0.4, 0.0],
        &[0.01, -0.02, 0.0, 0.0, 0.0, 0.03],
        [1.2, -0.7, 0.0],
    );
    assert!((u2[0] - u3[0]).abs() < TOL && (u2[1] - u3[1]).abs() < TOL && u3[2] == 0.0);
}

/// Entries of column `col` of an LP as a dense vector over its rows.
fn column(lp: &voussoir::lp::LinearProgram, col: usize) -> Vec<f64> {
    let mut v = vec![0.0; lp.num_rows()];
    for (r, x) in lp.column(col) {
        v[r] = x;
    }
    v
}

#[test]
fn settlement_and_limit_programs_of_two_stacked_blocks_by_hand() {
    // The base settles by 1 cm.
    let st = two_blocks([0.0, -0.01, 0.0]);
    let map = KinematicMap::new(&st);
    let dead = st.load_vector(false);
    // Dead loads: 10 kN down at each centroid → F_D = (0, −10, 0, 0, −10, 0).
    assert_eq!(dead, vec![0.0, -10.0, 0.0, 0.0, -10.0, 0.0]);
    let fp = programs::settlement_force_program(&map, &dead);
    // 6 equilibrium rows `Nᵀp_n + Tᵀp_t = −F_D`, no joint-law rows; 4 points × (p_n, p_t).
    assert_eq!((fp.lp.num_rows(), fp.lp.num_cols()), (6, 8));
    for r in 0..6 {
        assert_eq!(fp.lp.row_lower[r], -dead[r]);
        assert_eq!(fp.lp.row_upper[r], -dead[r]);
    }
    // The p_n column of the interface point (0, 1) (block 0 = a, block 1 = b, n = (0, 1)):
    // on block 0: −n and −(r₀ × n), r₀ = (0, 1) − (0.5, 0.5) = (−0.5, 0.5), r₀ × n = −0.5;
    // on block 1: +n and r₁ × n, r₁ = (0, 1) − (0.5, 1.5) = (−0.5, −0.5), r₁ × n = −0.5.
    let j = joint(&st, Body::Block(0), Body::Block(1));
    let k = (map.joint_start[j]..map.joint_start[j + 1])
        .find(|&k| st.joints[j].points[map.points[k].index].x[0] < 0.5)
        .unwrap();
    let col = fp.pn[k].unwrap();
    assert_eq!(column(&fp.lp, col), vec![0.0, -1.0, 0.5, 0.0, 1.0, -0.5]);
    assert_eq!(
        (fp.lp.col_lower[col], fp.lp.col_upper[col]),
        (0.0, f64::INFINITY)
    );
    // Its shear column (t = (−1, 0)): block 0: −t, −(r₀ × t) = −(−0.5·0 − 0.5·(−1)) = −0.5;
    // block 1: +t, r₁ × t = −0.5·0 − (−0.5)(−1) = −0.5. A free variable.
    let colt = fp.pt[k].unwrap();
    assert_eq!(column(&fp.lp, colt), vec![1.0, 0.0, -0.5, -1.0, 0.0, -0.5]);
    assert_eq!(fp.lp.col_lower[colt], f64::NEG_INFINITY);
    // Costs: the opening the settlement causes at each point, g_n = 0.01 at the base joint's
    // points (block 0 is `a`, the support `b`, n = (0, −1), support motion (0, −0.01)).
    let base = joint(&st, Body::Block(0), Body::Support(0));
    for k in map.joint_start[base]..map.joint_start[base + 1] {
        assert!((fp.lp.cost[fp.pn[k].unwrap()] - 0.01).abs() < TOL);
    }
    assert_eq!(fp.lp.cost[col], 0.0);
    // Solved: the base carries the whole 20 kN, so the work on the settling support is
    // 20 kN × 0.01 m = 0.2 kN·m.
    let o = SolverOptions::default();
    let s = fp.solve(&o).unwrap();
    assert_eq!(s.status, LpStatus::Optimal);
    assert!((s.objective - 0.2).abs() < 1e-9, "{}", s.objective);

    // The motion program is the LP dual: one row per force column, one column per equilibrium
    // row (block DOF, sign-flipped). Both blocks follow the base down by 1 cm: the dead loads
    // do 10 × 0.01 + 10 × 0.01 = 0.2 kN·m of work.
    let mp = programs::settlement_motion_program(&map, &dead).unwrap();
    assert_eq!((mp.lp.num_rows(), mp.lp.num_cols()), (8, 6));
    // The row of a p_n ≥ 0 column is one-sided (an opening ≥ 0), of a free p_t an equality.
    let (r_n, r_t) = (col, colt);
    assert!(mp.lp.row_lower[r_n] == f64::NEG_INFINITY && mp.lp.row_upper[r_n] == 0.0);
    assert!(mp.lp.row_lower[r_t] == 0.0 && mp.lp.row_upper[r_t] == 0.0);
    let m = lp::solve(&mp.lp, &o).unwrap();
    assert!((mp.objective_sign * m.objective - 0.2).abs() < 1e-9);
    let d = mp.motion(&m.x);
    for (got, want) in d.iter().zip([0.0, -0.01, 0.0, 0.0, -0.01, 0.0]) {
        assert!((got - want).abs() < 1e-9, "{d:?}");
    }

    // Limit program: the same equilibrium rows with a λ column holding the live load
    // F_L = (0, 0, 0, 1, 0, r × f) on block 1, r = (1, 2) − (0.5, 1.5) = (0.5, 0.5),
    // r × (1, 0) = −0.5; cost 1, maximised. λ by hand: block 1 overturns about (1, 1) when
    // λ·1·1 = 10·0.5 (λ = 5); the pair overturns about (1, 0) when λ·2 = 20·0.5 (λ = 5 too).
    let st0 = two_blocks([0.0; 3]);
    let map0 = KinematicMap::new(&st0);
    let live = st0.load_vector(true);
    assert_eq!(live, vec![0.0, 0.0, 0.0, 1.0, 0.0, -0.5]);
    let lp0 = programs::limit_force_program(&map0, &st0.load_vector(false), &live);
    let lam = lp0.lambda.unwrap();
    assert_eq!(column(&lp0.lp, lam), live);
    assert_eq!(lp0.lp.cost[lam], 1.0);
    assert!(lp0.lp.maximise);
    let s = lp0.solve(&o).unwrap();
    assert!((s.x[lam] - 5.0).abs() < 1e-9, "λ = {}", s.x[lam]);
}
