//! Settlement analysis: the paper's two dual LPs on the paper arch and on walls.

use voussoir::analysis::settlement::SettlementStatus;
use voussoir::analysis::{settle, SettlementResult};
use voussoir::discretize::KinematicMap;
use voussoir::generate::{arch, wall, ArchSpec, LiveLoad, WallSpec};
use voussoir::lp::{self, Direction, LpStatus, SolverOptions};
use voussoir::model::{Connection, Model};
use voussoir::programs::ForceProgram;
use voussoir::result::JointState;
use voussoir::structure::Body;
use voussoir::{BuildOptions, Structure};

const INTRADOS: f64 = 2.86;
const EXTRADOS: f64 = 3.19;

fn paper_arch() -> Model {
    arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap()
}

fn run(mut m: Model, moves: &[(&str, [f64; 3])], fixed: &[&str]) -> (Structure, SettlementResult) {
    for (name, mv) in moves {
        let i = m.support_index(name).unwrap();
        m.supports[i].motion = *mv;
    }
    for name in fixed {
        let i = m.support_index(name).unwrap();
        m.supports[i].connection = Connection::Fixed;
    }
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = settle(&st, &SolverOptions::default()).unwrap();
    (st, r)
}

fn radius(x: f64, y: f64) -> f64 {
    x.hypot(y)
}

fn assert_certified(r: &SettlementResult) {
    let c = r.certificate.as_ref().expect("certificate");
    assert!(c.relative_gap <= 1e-7, "duality gap {}", c.relative_gap);
    let fmax = r
        .joints
        .iter()
        .flat_map(|j| &j.points)
        .fold(0.0f64, |m, p| m.max(p.normal_force.abs()));
    let omax = r
        .joints
        .iter()
        .flat_map(|j| &j.points)
        .fold(0.0f64, |m, p| m.max(p.opening.abs()));
    assert!(
        c.complementarity <= 1e-7 * fmax * omax,
        "complementarity {}",
        c.complementarity
    );
    assert!(
        c.equilibrium_residual <= 1e-8 * fmax,
        "equilibrium residual {}",
        c.equilibrium_residual
    );
    for j in &r.joints {
        for p in &j.points {
            assert!(
                p.opening >= -1e-12,
                "joint {} interpenetrates by {}",
                j.id,
                p.opening
            );
        }
    }
}

/// Joint ids of the paper arch: 0 = (0|1), 1 = (0|left), k+1 = (k|k+1), 64 = (63|right).
/// The joint after the n-th voussoir from the left is n+1 (n ≥ 1).
#[test]
fn spreading_gives_three_symmetric_hinges() {
    let (_, r) = run(paper_arch(), &[("right", [0.01, 0.0, 0.0])], &[]);
    assert_eq!(r.status, SettlementStatus::Mechanism);
    assert_certified(&r);
    let joints: Vec<usize> = r.hinges.iter().map(|h| h.joint).collect();
    // 13th joint from each springing: after voussoir 13 from the left (joint 13) and after
    // voussoir 13 from the right (between blocks 50 and 51: joint 51); the crown (31|32) = 32.
    assert_eq!(joints, vec![13, 32, 51]);
    let crown = &r.hinges[1];
    // The crown rotates about its extrados point, so the crack opens at the intrados.
    assert!((radius(crown.x, crown.y) - EXTRADOS).abs() < 1e-9 && crown.x.abs() < 1e-9);
    for h in [&r.hinges[0], &r.hinges[2]] {
        // The haunch hinges rotate about the intrados: cracks open at the extrados.
        assert!((radius(h.x, h.y) - INTRADOS).abs() < 1e-9);
    }
    assert!((r.hinges[0].x + r.hinges[2].x).abs() < 1e-9, "symmetric");
    // Every other joint, the springings included, stays closed.
    let n_open = r
        .joints
        .iter()
        .filter(|j| j.state != JointState::Closed)
        .count();
    assert_eq!(n_open, 3);
}

#[test]
fn vertical_settlement_with_fixed_support() {
    let (_, r) = run(paper_arch(), &[("right", [0.0, -0.01, 0.0])], &["right"]);
    assert_certified(&r);
    let joints: Vec<usize> = r.hinges.iter().map(|h| h.joint).collect();
    // Left springing (0|left) = joint 1, 13th joint from the left springing, crown; none in the
    // settled (right) half.
    assert_eq!(joints, vec![1, 13, 32]);
    // The settled half moves down rigidly with the support: every right-half block has v = −1 cm
    // at the right springing. Block 63 is tied to the support: its motion is the support's.
    let b63 = &r.blocks[63];
    assert!((b63.v + 0.01).abs() < 1e-12 && b63.u.abs() < 1e-12 && b63.theta.abs() < 1e-12);
}

#[test]
fn contact_support_admits_more_mechanisms_than_fixed() {
    let mv = [("right", [0.0, -0.01, 0.0])];
    let (_, fixed) = run(paper_arch(), &mv, &["right"]);
    let (_, contact) = run(paper_arch(), &mv, &[]);
    assert_certified(&contact);
    let (wf, wc) = (
        fixed.work_dead_loads.unwrap(),
        contact.work_dead_loads.unwrap(),
    );
    assert!(wc >= wf - 1e-12 * wf.abs(), "contact {wc} < fixed {wf}");
    assert!(!contact.hinges.is_empty());
}

#[test]
fn primal_and_dual_agree_and_linearity_holds() {
    for (mv, fixed) in [
        ([0.01, 0.0, 0.0], false),
        ([-0.005, 0.0, 0.0], false),
        ([0.0, -0.01, 0.0], true),
        ([0.004, -0.003, 0.0], false),
    ] {
        let f: &[&str] = if fixed { &["right"] } else { &[] };
        let (_, r1) = run(paper_arch(), &[("right", mv)], f);
        let (_, r2) = run(
            paper_arch(),
            &[("right", [2.0 * mv[0], 2.0 * mv[1], 2.0 * mv[2]])],
            f,
        );
        assert_certified(&r1);
        assert_certified(&r2);
        // Doubling the settlement doubles every displacement and the works, forces unchanged.
        for (a, b) in r1.blocks.iter().zip(&r2.blocks) {
            for (x, y) in [(a.u, b.u), (a.v, b.v), (a.theta, b.theta)] {
                assert!((2.0 * x - y).abs() <= 1e-9 * (y.abs() + 1e-6), "{x} vs {y}");
            }
        }
        assert!((2.0 * r1.work_dead_loads.unwrap() - r2.work_dead_loads.unwrap()).abs() < 1e-9);
        for (a, b) in r1.reactions.iter().zip(&r2.reactions) {
            assert!(
                (a.fx - b.fx).abs() < 1e-7
                    && (a.fy - b.fy).abs() < 1e-7
                    && (a.m - b.m).abs() < 1e-7
            );
        }
    }
}

/// Horizontal thrust the arch exerts on its right support, optimised by a separate static LP
/// over all statically admissible force fields (equilibrium with self-weight, p_n ≥ 0).
fn extreme_thrust(direction: Direction) -> f64 {
    let st = Structure::new(&paper_arch(), BuildOptions::default()).unwrap();
    let map = KinematicMap::new(&st);
    let right = st.supports.iter().position(|s| s.name == "right").unwrap();
    // Force on the support: the support is body b of its joint, so it receives +p_n n + p_t t.
    // (2D: one tangent per point, so sliding row k is point k.)
    let cost = |k: usize, normal: bool| {
        let j = &st.joints[map.points[k].joint];
        match (j.b == Body::Support(right), normal) {
            (true, true) => j.normal[0],
            (true, false) => j.tangent()[0],
            _ => 0.0,
        }
    };
    let fp = ForceProgram::new(
        &map,
        &st.load_vector(false),
        None,
        direction,
        |k| cost(k, true),
        |k| cost(k, false),
    );
    let s = lp::solve(&fp.lp, &SolverOptions::default()).unwrap();
    assert_eq!(s.status, LpStatus::Optimal);
    s.objective
}

#[test]
fn spreading_reaction_is_minimum_thrust_and_closing_is_maximum() {
    let hmin = extreme_thrust(Direction::Minimise);
    let hmax = extreme_thrust(Direction::Maximise);
    assert!(hmin > 0.0 && hmax > hmin);
    // Outward motion of the right springing: the support pushes back with the minimum thrust.
    let (_, out) = run(paper_arch(), &[("right", [0.01, 0.0, 0.0])], &[]);
    let r = out.reactions.iter().find(|r| r.support == "right").unwrap();
    assert!(
        (-r.fx - hmin).abs() <= 1e-9 * hmin,
        "reaction {} vs min thrust {hmin}",
        -r.fx
    );
    // Inward motion: maximum thrust.
    let (_, inw) = run(paper_arch(), &[("right", [-0.01, 0.0, 0.0])], &[]);
    assert_certified(&inw);
    let r = inw.reactions.iter().find(|r| r.support == "right").unwrap();
    assert!(
        (-r.fx - hmax).abs() <= 1e-9 * hmax,
        "reaction {} vs max thrust {hmax}",
        -r.fx
    );
    // Work of the reactions = thrust × settlement.
    assert!((out.work_reactions.unwrap() - hmin * 0.01).abs() < 1e-9);
}

/// A running-bond wall on foundation segments f0…; segments whose centroid lies beyond
/// `x_from` settle by `v`.
fn wall_settling(x_from: f64, v: f64) -> (Structure, SettlementResult, f64) {
    let spec = WallSpec {
        courses: 8,
        units: 10,
        unit: [0.4, 0.2],
        ..WallSpec::default()
    };
    let mut m = wall(&spec).unwrap();
    for s in m.supports.iter_mut() {
        let cx = 0.5 * (s.polygon[0][0] + s.polygon[1][0]);
        if cx > x_from {
            s.motion = [0.0, v, 0.0];
        }
    }
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r = settle(&st, &SolverOptions::default()).unwrap();
    (st, r, spec.units as f64 * spec.unit[0])
}

#[test]
fn wall_bridges_a_settlement_over_less_than_half_its_length() {
    // Segments over the right 30 % settle: the wall spans over them.
    let (st, r, _) = wall_settling(2.8, -0.01);
    assert_certified(&r);
    assert!(
        r.work_dead_loads.unwrap().abs() < 1e-12,
        "dead loads do no work"
    );
    assert!(
        r.blocks
            .iter()
            .all(|b| b.u == 0.0 && b.v == 0.0 && b.theta == 0.0),
        "no block moves"
    );
    for (j, jr) in st.joints.iter().zip(&r.joints) {
        let on_settled = match (j.a, j.b) {
            (_, Body::Support(s)) | (Body::Support(s), _) => st.supports[s].motion[1] != 0.0,
            _ => false,
        };
        let expect = if on_settled {
            JointState::Open
        } else {
            JointState::Closed
        };
        assert_eq!(jr.state, expect, "joint {}", jr.id);
    }
}

#[test]
fn wall_tilts_as_one_body_over_more_than_half() {
    // Segments over the right 70 % settle by 1 cm: the wall rotates rigidly about the left edge
    // of the settling zone (x = 1.2) until its far corner (x = 4) meets the settled foundation.
    let (_, r, len) = wall_settling(1.2, -0.01);
    assert_certified(&r);
    let theta = -0.01 / (len - 1.2);
    for b in &r.blocks {
        assert!(
            (b.theta - theta).abs() < 1e-12,
            "block {} rotates by {}",
            b.id,
            b.theta
        );
    }
    // Dead-load work: W · (drop of the centroid) = W · |θ| · (x_G − 1.2).
    let w: f64 = r.reactions.iter().map(|x| x.fy).sum();
    let expected = w * theta.abs() * (0.5 * len - 1.2);
    assert!(
        (r.work_dead_loads.unwrap() - expected).abs() < 1e-9 * expected,
        "{} vs {expected}",
        r.work_dead_loads.unwrap()
    );
}
