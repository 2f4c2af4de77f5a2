//! 3D structures from the generators against their references: the paper's arch extruded as a
//! barrel vault (the 2D results, per metre of depth), walls overturning out of plane (t/h, and
//! more with returns), the least thickness of a hemispherical dome (Heyman's 0.042 R), and
//! certified settlements of a vault and a dome.

use voussoir::analysis::limit::{limit, LimitStatus};
use voussoir::analysis::settlement::{settle, SettlementStatus};
use voussoir::generate::{arch, ArchSpec, LiveLoad, RadiusAt};
use voussoir::generate3d::{dome, vault, walls, Bond, DomeSpec, Plan, WallsLive, WallsSpec};
use voussoir::lp::{LpStatus, Method, SolverOptions};
use voussoir::result::JointState;
use voussoir::settlement_input::move_support;
use voussoir::{programs, Assembly, BuildOptions, Structure, Structure3d};

/// The paper's arch (README: R = 2.86 m at the intrados, t = 0.33 m, 64 voussoirs, 18 kN/m³).
fn paper_arch(live: LiveLoad) -> ArchSpec {
    ArchSpec {
        radius: 2.86,
        radius_at: RadiusAt::Intrados,
        thickness: 0.33,
        voussoirs: 64,
        unit_weight: 18.0,
        live,
        live_load: 1.0,
        ..ArchSpec::default()
    }
}

fn ipm() -> SolverOptions {
    SolverOptions {
        method: Method::Ipm,
        ..SolverOptions::default()
    }
}

#[test]
fn the_paper_arch_extruded_as_a_vault_gives_the_2d_multipliers_and_hinges() {
    // Stack bond: every ring is the 2D arch, so the vault's λ is the arch's, for any depth and
    // number of rings (0.4346 and 0.2189, the README's verification table), and its hinge
    // lines run through the depth at the 2D hinge joints.
    for live in [LiveLoad::Full, LiveLoad::Left] {
        let spec = paper_arch(live);
        let st2 = Structure::new(&arch(&spec).unwrap(), BuildOptions::default()).unwrap();
        let r2 = limit(&st2, &SolverOptions::default()).unwrap();
        let l2 = r2.load_multiplier.unwrap();
        let mut hinge_joints2: Vec<(f64, f64)> = r2.hinges.iter().map(|h| (h.x, h.y)).collect();
        hinge_joints2.sort_by(|a, b| a.partial_cmp(b).unwrap());
        for (depth, rings) in [(1.0, 1), (0.6, 3), (2.0, 2)] {
            let m = vault(&spec, depth, rings, Bond::Stack).unwrap();
            let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
            assert_eq!(st.blocks.len(), 64 * rings);
            let r = limit(&st, &SolverOptions::default()).unwrap();
            assert_eq!(r.status, LimitStatus::Collapse);
            let l = r.load_multiplier.unwrap();
            assert!(
                (l - l2).abs() < 1e-6,
                "{live:?} depth {depth}, {rings} rings: λ {l} vs 2D {l2}"
            );
            // Each 2D hinge (x, y) appears as a hinge line at (x, ·, z = y) through the depth.
            let mut lines: Vec<(f64, f64)> = r.hinges.iter().map(|h| (h.x, h.z)).collect();
            lines.sort_by(|a, b| a.partial_cmp(b).unwrap());
            lines.dedup_by(|a, b| (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9);
            assert_eq!(
                lines.len(),
                hinge_joints2.len(),
                "{live:?}: {lines:?} vs {hinge_joints2:?}"
            );
            for (a, b) in lines.iter().zip(&hinge_joints2) {
                assert!(
                    (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9,
                    "{a:?} vs {b:?}"
                );
            }
        }
    }
    let l = |live| {
        let st =
            Structure::new(&arch(&paper_arch(live)).unwrap(), BuildOptions::default()).unwrap();
        limit(&st, &SolverOptions::default())
            .unwrap()
            .load_multiplier
            .unwrap()
    };
    assert!((l(LiveLoad::Full) - 0.4346).abs() < 5e-5 && (l(LiveLoad::Left) - 0.2189).abs() < 5e-5);
}

#[test]
fn a_spreading_vault_cracks_at_the_2d_hinges_with_the_2d_work_per_metre() {
    // The right springing line moves out by 1 cm: the same three-hinge mechanism as the 2D
    // arch, the dead loads' work per metre of depth equal to the 2D work (per metre of width),
    // both programs agreeing to 1e-7.
    let spec = paper_arch(LiveLoad::None);
    let mut m2 = arch(&spec).unwrap();
    move_support(&mut m2, "right", &[0.01, 0.0, 0.0]).unwrap();
    let st2 = Structure::new(&m2, BuildOptions::default()).unwrap();
    let r2 = settle(&st2, &SolverOptions::default()).unwrap();
    let w2 = r2.work_dead_loads.unwrap();
    let mut hinges2: Vec<usize> = r2.hinges.iter().map(|h| h.joint).collect();
    hinges2.sort();
    for (depth, rings, bond) in [
        (1.0, 1, Bond::Stack),
        (1.5, 3, Bond::Stack),
        (1.0, 2, Bond::Running),
    ] {
        let mut m = vault(&spec, depth, rings, bond).unwrap();
        move_support(&mut m, "right", &[0.01, 0.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
        if bond == Bond::Running {
            // Staggered rings hinge at different joints, so their shared faces would have to
            // slide: under Heyman's no-sliding hypothesis the spreading is incompatible.
            let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
            let r = settle(&st, &SolverOptions::default()).unwrap();
            assert_eq!(r.status, SettlementStatus::Incompatible);
            // With Coulomb friction (μ = 0.6) the rings slide on each other and spread.
            m.materials.entry("default".into()).or_default().friction = Some(0.6);
        }
        let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
        let r = settle(&st, &SolverOptions::default()).unwrap();
        assert_eq!(r.status, SettlementStatus::Mechanism);
        let c = r.certificate.as_ref().unwrap();
        assert!(c.ok && c.relative_gap <= 1e-7, "{bond:?}: {c:?}");
        let per_metre = r.work_dead_loads.unwrap() / depth;
        if bond == Bond::Stack {
            assert!((per_metre - w2).abs() < 1e-7 * w2, "{per_metre} vs 2D {w2}");
            // Hinge lines at the 2D hinge joints: ring 0's joints are numbered as the 2D ones
            // only in the arch's own order, so compare positions through the joint's points.
            let mut lines: Vec<(i64, i64)> = r
                .hinges
                .iter()
                .map(|h| ((h.x * 1e6).round() as i64, (h.z * 1e6).round() as i64))
                .collect();
            lines.sort();
            lines.dedup();
            let mut want: Vec<(i64, i64)> = r2
                .hinges
                .iter()
                .map(|h| ((h.x * 1e6).round() as i64, (h.y * 1e6).round() as i64))
                .collect();
            want.sort();
            assert_eq!(lines, want, "{bond:?}");
        } else {
            // Running bond with friction: a spreading mechanism, certified; its work per metre
            // is within 10 % of the stack-bonded vault's (measured: 0.1102 against 0.1110).
            assert!(
                (per_metre - w2).abs() < 0.1 * w2,
                "running bond: {per_metre} vs {w2}"
            );
        }
    }
    assert_eq!(hinges2.len(), 3, "2D spreading: three hinges");
}

#[test]
fn a_wall_bonded_to_returns_carries_more_than_the_free_wall() {
    // Out-of-plane load on the main wall: free-standing (plan I) it overturns at λ = t/h; with
    // returns (L, U) bonded at the corners it has to drag or lift the returns' bricks with it.
    let spec = |plan| WallsSpec {
        plan,
        length: 2.0,
        return_length: 1.0,
        height: 1.2,
        thickness: 0.2,
        courses: 6,
        units: 5,
        unit_weight: 18.0,
        live: WallsLive::Main,
    };
    let lambda = |plan| {
        let st = Structure3d::new(&walls(&spec(plan)).unwrap(), BuildOptions::default()).unwrap();
        let r = limit(&st, &ipm()).unwrap();
        assert_eq!(r.status, LimitStatus::Collapse, "{plan:?}");
        (r.load_multiplier.unwrap(), r, st)
    };
    let (free, _, _) = lambda(Plan::I);
    assert!(
        (free - 0.2 / 1.2).abs() < 1e-6,
        "free wall λ = {free}, t/h = {}",
        0.2 / 1.2
    );
    let (l, rl, st_l) = lambda(Plan::L);
    let (u, _, _) = lambda(Plan::U);
    assert!(l > free * 1.05 && u >= l - 1e-9, "I {free}, L {l}, U {u}");
    // The mechanism: with no sliding and bonded corners the whole L (main wall and return)
    // overturns as one rigid body about the base (every brick has the same rotation), hinged
    // at the base joints only; the return's weight is what the main wall has to lift.
    let th: Vec<[f64; 3]> = rl
        .blocks
        .iter()
        .map(|b| [b.theta_x, b.theta_y, b.theta_z])
        .collect();
    let scale = th[0].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    assert!(scale > 0.0 && th.len() == st_l.num_blocks());
    for t in &th {
        for k in 0..3 {
            assert!(
                (t[k] - th[0][k]).abs() < 1e-7 * scale,
                "{t:?} vs {:?}",
                th[0]
            );
        }
    }
    assert!(rl.joints.iter().all(|j| j.state == JointState::Closed
        || matches!(j.b, voussoir::result::BodyName::Support(_))
        || matches!(j.a, voussoir::result::BodyName::Support(_))));
}

/// Whether a dome of thickness `t` stands under its own weight: the equilibrium program
/// `F_D + Nᵀ p_n + Tᵀ p_t = 0, p_n ≥ 0` is feasible (the settlement force program with no
/// support motion: its objective is zero, only feasibility matters).
fn dome_stands(t: f64, courses: usize, segments: usize) -> bool {
    let m = dome(&DomeSpec {
        radius: 10.0,
        radius_at: RadiusAt::Centreline,
        thickness: t,
        courses,
        segments,
        ..DomeSpec::default()
    })
    .unwrap();
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let map = st.kinematic_map();
    let fp = programs::settlement_force_program(&map, &st.load_vector(false));
    let s = fp.solve(&ipm()).unwrap();
    match s.status {
        LpStatus::Optimal => true,
        LpStatus::Infeasible => false,
        other => panic!("t = {t}: {other:?}"),
    }
}

#[test]
fn a_hemispherical_dome_needs_about_heymans_least_thickness() {
    // Heyman (1977): a hemispherical dome (no hoop tension) stands under its own weight down to
    // t ≈ 0.042 R. For refining discretisations (R = 10 m at the centreline): the dome does not
    // stand at 0.9 × 0.042 R and stands at 1.1 × 0.042 R, so its least thickness is within
    // 10 % of Heyman's; then a bisection of that bracket on the generator's thickness to
    // 0.0084 R / 2⁶ = 1.3e-4 R, printed (the README's 0.0422 R, 0.0427 R). (It bisected
    // [0.01 R, 0.1 R] 12 times, 14 feasibility programs per dome instead of 8: 165 s of wall at
    // load 4 in session 23.)
    let r = 10.0;
    let (t_lo, t_hi) = (0.9 * 0.042 * r, 1.1 * 0.042 * r);
    let mut found = Vec::new();
    for (courses, segments) in [(8, 16), (12, 24), (16, 32)] {
        assert!(
            !dome_stands(t_lo, courses, segments),
            "{courses} × {segments}: stands at 0.9 × 0.042 R"
        );
        assert!(
            dome_stands(t_hi, courses, segments),
            "{courses} × {segments}: does not stand at 1.1 × 0.042 R"
        );
        let (mut lo, mut hi) = (t_lo, t_hi);
        for _ in 0..6 {
            let mid = 0.5 * (lo + hi);
            if dome_stands(mid, courses, segments) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        found.push((courses, segments, hi / r));
    }
    eprintln!("least thickness t/R (courses, segments, t/R to 1.3e-4): {found:?}");
}

#[test]
fn a_dome_whose_support_sector_settles_is_certified_bridged_without_friction_and_cracked_with_it() {
    // A quarter of the supports (4 of 16 segments) settle by 2 cm. Under Heyman's hypotheses
    // (no sliding) the dome arches over the settled sector: the settled supports simply part
    // from the dome (their four joints open fully) and the dead loads do no work. With
    // friction μ = 0.5 the blocks above the sector follow it, sliding and hinging: positive
    // work, the two programs agreeing to 1e-7.
    let mut m = dome(&DomeSpec {
        radius: 5.0,
        radius_at: RadiusAt::Centreline,
        thickness: 0.3,
        courses: 8,
        segments: 16,
        ..DomeSpec::default()
    })
    .unwrap();
    for k in 0..4 {
        move_support(
            &mut m,
            &format!("base{k}"),
            &[0.0, 0.0, -0.02, 0.0, 0.0, 0.0],
        )
        .unwrap();
    }
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let r = settle(&st, &ipm()).unwrap();
    assert_eq!(r.status, SettlementStatus::Mechanism);
    let c = r.certificate.as_ref().unwrap();
    assert!(
        c.ok && c.primal.abs() < 1e-9 && c.dual.abs() < 1e-9,
        "{c:?}"
    );
    let open: Vec<&str> = r
        .joints
        .iter()
        .filter(|j| j.state != JointState::Closed)
        .filter_map(|j| match &j.b {
            voussoir::result::BodyName::Support(s) => Some(s.as_str()),
            _ => None,
        })
        .collect();
    assert_eq!(open, ["base0", "base1", "base2", "base3"], "{open:?}");
    assert_eq!(
        r.joints
            .iter()
            .filter(|j| j.state != JointState::Closed)
            .count(),
        4
    );

    m.materials.entry("default".into()).or_default().friction = Some(0.5);
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let r = settle(&st, &ipm()).unwrap();
    let c = r.certificate.as_ref().unwrap();
    assert!(c.ok && c.relative_gap <= 1e-7, "{c:?}");
    assert!(r.work_dead_loads.unwrap() > 0.1, "{c:?}");
    let cracked = r
        .joints
        .iter()
        .filter(|j| j.state != JointState::Closed)
        .count();
    assert!(cracked > 4, "{cracked}");
}
