//! The paper's programs on 3D contact frames: the dimension-generic core (kinematic map,
//! programs, solver layer) gives the closed-form answers for a box on a base.
//!
//! The box is `b × d × h` (x, y, z; z up), resting on a base with a contact point at each corner
//! of its bottom face, weight `W` at its centroid. These tests build the contact frames by hand
//! (the 3D model and interface detection come with the 3D issue); everything after that — the
//! kinematic map, the force and motion programs, the solves — is the same code as in 2D.

use voussoir::dim::{Dim, Three};
use voussoir::discretize::{ContactBodies, ContactJoint, JointLaw, KinematicMap};
use voussoir::lp::{self, LpStatus, SolverOptions};
use voussoir::programs;
use voussoir::structure::Body;

const W: f64 = 10.0;

/// A box `b × d × h` with its bottom face on z = 0, on a base whose reference point is
/// `base_ref` and whose prescribed motion is `base_motion` (6 values); optional friction μ.
fn box_on_base(
    [b, d, h]: [f64; 3],
    base_ref: [f64; 3],
    base_motion: [f64; 6],
    friction: Option<f64>,
) -> KinematicMap {
    let n = [0.0, 0.0, -1.0]; // from the box (a) into the base (b)
    let joints = vec![ContactJoint::<Three> {
        a: Body::Block(0),
        b: Body::Support(0),
        normal: n,
        tangents: Three::tangents(n),
        points: vec![
            ([0.0, 0.0, 0.0], 0.0),
            ([b, 0.0, 0.0], 0.0),
            ([b, d, 0.0], 0.0),
            ([0.0, d, 0.0], 0.0),
        ],
        bilateral: false,
        law: JointLaw {
            friction,
            cohesion: 0.0,
            strength: None,
            depth: b,
            width: d,
        },
        along: vec![],
    }];
    let bodies = ContactBodies::<Three> {
        blocks: vec![[b / 2.0, d / 2.0, h / 2.0]],
        supports: vec![(base_ref, base_motion.to_vec())],
    };
    KinematicMap::assemble(&bodies, &joints)
}

/// Load multiplier of a horizontal live load `W (cos θ, sin θ, 0)` at the centroid.
fn lambda(map: &KinematicMap, theta: f64) -> f64 {
    let dead = [0.0, 0.0, -W, 0.0, 0.0, 0.0];
    let live = [W * theta.cos(), W * theta.sin(), 0.0, 0.0, 0.0, 0.0];
    let fp = programs::limit_force_program(map, &dead, &live);
    let s = fp.solve(&SolverOptions::default()).unwrap();
    assert_eq!(s.status, LpStatus::Optimal);
    s.x[fp.lambda.unwrap()]
}

#[test]
fn box_overturns_at_the_closed_form_multiplier_at_every_azimuth() {
    // Overturning about the edge x = b (or 0) needs λ W h/2 |cos θ| = W b/2, about y = d (or 0)
    // λ W h/2 |sin θ| = W d/2; the box tips about the first: λ = min(b/(h|cos θ|), d/(h|sin θ|)).
    for dims in [[1.0, 1.0, 2.0], [0.4, 1.2, 3.0], [2.0, 0.5, 1.5]] {
        let map = box_on_base(dims, [0.0, 0.0, -0.5], [0.0; 6], None);
        let [b, d, h] = dims;
        for deg in [0.0f64, 20.0, 45.0, 90.0, 135.0, 200.0, 290.0] {
            let t = deg.to_radians();
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
            let got = lambda(&map, t);
            assert!(
                (got - want).abs() < 1e-9,
                "{dims:?} at {deg}°: λ = {got}, closed form {want}"
            );
        }
    }
}

#[test]
fn inscribed_friction_pyramid_slides_between_mu_cos_pi_over_k_and_mu() {
    // A flat box (overturning needs λ ≥ b/h = 10) with friction μ = 0.6: it slides first. The
    // pyramid of K facets is inscribed in the cone: its vertices (azimuths 2πi/K) carry μ, the
    // middles of its facets ((2i + 1)π/K) carry μ cos(π/K), and every azimuth lies in between.
    let mu = 0.6;
    for k in [4usize, 8, 16] {
        let mut map = box_on_base([1.0, 1.0, 0.1], [0.0, 0.0, -0.5], [0.0; 6], Some(mu));
        map.friction_facets = k;
        let pi_k = std::f64::consts::PI / k as f64;
        let at_vertex = lambda(&map, 0.0);
        let at_facet = lambda(&map, pi_k);
        assert!((at_vertex - mu).abs() < 1e-9, "K = {k}: {at_vertex}");
        assert!(
            (at_facet - mu * pi_k.cos()).abs() < 1e-9,
            "K = {k}: {at_facet}"
        );
        for deg in [7.0f64, 33.0, 61.0, 100.0, 250.0] {
            let l = lambda(&map, deg.to_radians());
            assert!(
                l >= mu * pi_k.cos() - 1e-9 && l <= mu + 1e-9,
                "K = {k} at {deg}°: {l}"
            );
        }
    }
}

#[test]
fn settling_base_carries_the_box_with_both_programs_agreeing() {
    // The base drops by 1 cm and tilts by 0.002 rad about y, about its reference point
    // (0.5, 0.5, −0.5) right under the box's centroid: the box follows it, its centroid drops by
    // 1 cm (the tilt only moves it sideways there), so the dead load does W × 0.01 of work, and
    // the base's reaction, W up, does the same work on the base's motion.
    let h = 2.0;
    let map = box_on_base(
        [1.0, 1.0, h],
        [0.5, 0.5, -0.5],
        [0.0, 0.0, -0.01, 0.0, 0.002, 0.0],
        None,
    );
    let dead = [0.0, 0.0, -W, 0.0, 0.0, 0.0];
    let o = SolverOptions::default();
    let mp = programs::settlement_motion_program(&map, &dead).unwrap();
    let primal = lp::solve(&mp.lp, &o).unwrap();
    assert_eq!(primal.status, LpStatus::Optimal);
    let work = mp.objective_sign * primal.objective;
    assert!((work - W * 0.01).abs() < 1e-9, "primal {work}");
    let fp = programs::settlement_force_program(&map, &dead);
    let dual = fp.solve(&o).unwrap();
    assert!(
        (dual.objective - W * 0.01).abs() < 1e-9,
        "dual {}",
        dual.objective
    );
    // The mechanism is the base's rigid motion carried to the box's centroid:
    // u = ω × (c − c_base) = (0, 0.002, 0) × (0, 0, 1.5) = (0.003, 0, 0), w = −0.01, θy = 0.002.
    let d = mp.motion(&primal.x);
    let want = [0.003, 0.0, -0.01, 0.0, 0.002, 0.0];
    for (a, b) in d.iter().zip(want) {
        assert!((a - b).abs() < 1e-9, "{d:?}");
    }
    // The forces are in equilibrium with the weight: the normal forces sum to W.
    let (pn, pt) = fp.forces(&dual.x);
    assert!((pn.iter().sum::<f64>() - W).abs() < 1e-9);
    let f = map.resultants(&pn, &pt);
    for (a, b) in f.iter().zip(dead) {
        assert!((a + b).abs() < 1e-9, "{f:?}");
    }
}
