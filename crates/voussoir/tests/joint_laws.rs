//! Joint laws: finite compressive strength and Coulomb friction, against closed forms.

use voussoir::analysis::limit::{limit_with, Crushing};
use voussoir::analysis::settlement::SettlementStatus;
use voussoir::analysis::{limit, settle, LimitStatus};
use voussoir::generate::{arch, ArchSpec, LiveLoad, RadiusAt};
use voussoir::lp::SolverOptions;
use voussoir::model::{Block, Load, Loads, Material, Model, Support};
use voussoir::result::JointState;
use voussoir::{BuildOptions, Structure};

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

fn block(b: f64, h: f64, mat: Material) -> Structure {
    let mut m = Model {
        blocks: vec![Block {
            polygon: rect(0.0, 0.0, b, h),
            material: None,
        }],
        supports: vec![Support {
            name: "base".into(),
            polygon: rect(-1.0, -0.5, b + 1.0, 0.0),
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
    m.materials.insert("default".into(), mat);
    Structure::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn finite_compressive_strength_on_a_rocking_block() {
    // Closed form: the base reaction is a stress block of depth a = W/(f_c w) at the toe, so
    // λ W h/2 = W (b − a)/2, λ = (b − W/(f_c w))/h.
    let (b, h, gamma, fc) = (1.0, 2.0, 18.0, 400.0);
    let mat = Material {
        unit_weight: gamma,
        compressive_strength: Some(fc),
        ..Material::default()
    };
    let st = block(b, h, mat);
    let w = gamma * b * h;
    let exact = (b - w / fc) / h;
    // Conic: exact to 1e-6.
    let r = limit_with(&st, &SolverOptions::default(), Crushing::Conic, 16).unwrap();
    let l = r.load_multiplier.unwrap();
    assert!((l - exact).abs() < 1e-6, "conic λ = {l}, exact {exact}");
    // Inscribed polygon with K chords on [0, f_c w t]: never above the exact value, and below it
    // by at most the chord sag ΔN²/(8 f_c w) in moment, i.e. 2·sag/(W h) in λ.
    for k in [4usize, 16, 64] {
        let r = limit_with(&st, &SolverOptions::default(), Crushing::Linear, k).unwrap();
        let l = r.load_multiplier.unwrap();
        let dn = fc * b / k as f64;
        let bound = 2.0 * dn * dn / (8.0 * fc) / (w * h);
        assert!(
            l <= exact + 1e-9 && exact - l <= bound + 1e-9,
            "K = {k}: λ = {l}, exact {exact}, bound {bound}"
        );
    }
    // Without the strength limit: λ = b/h.
    let r = limit(
        &block(
            b,
            h,
            Material {
                unit_weight: gamma,
                ..Material::default()
            },
        ),
        &SolverOptions::default(),
    )
    .unwrap();
    assert!((r.load_multiplier.unwrap() - b / h).abs() < 1e-9);
}

#[test]
fn friction_sliding_or_rocking() {
    // b/h = 0.5: with μ < 0.5 the block slides at λ = μ, otherwise it rocks at λ = b/h.
    for (mu, expect, sliding) in [
        (0.3, 0.3, true),
        (0.45, 0.45, true),
        (0.8, 0.5, false),
        (2.0, 0.5, false),
    ] {
        let st = block(
            1.0,
            2.0,
            Material {
                friction: Some(mu),
                ..Material::default()
            },
        );
        let r = limit(&st, &SolverOptions::default()).unwrap();
        let l = r.load_multiplier.unwrap();
        assert!((l - expect).abs() < 1e-9, "μ = {mu}: λ = {l}");
        let state = r.joints[0].state;
        assert_eq!(state == JointState::Sliding, sliding, "μ = {mu}: {state:?}");
    }
    // Cohesion adds c·b to the shear capacity: λ W = μ W + c b.
    let st = block(
        1.0,
        2.0,
        Material {
            friction: Some(0.2),
            cohesion: 3.6,
            ..Material::default()
        },
    );
    let r = limit(&st, &SolverOptions::default()).unwrap();
    let w = 18.0 * 2.0;
    assert!((r.load_multiplier.unwrap() - (0.2 * w + 3.6) / w).abs() < 1e-9);
}

fn paper_arch(mat: Material, live: LiveLoad) -> Structure {
    let mut m = arch(&ArchSpec {
        live,
        ..ArchSpec::default()
    })
    .unwrap();
    m.materials.insert("default".into(), mat);
    Structure::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn large_friction_reproduces_heyman() {
    let heyman = Material::default();
    let rough = Material {
        friction: Some(1e4),
        ..Material::default()
    };
    for live in [LiveLoad::Full, LiveLoad::Left] {
        let a = limit(&paper_arch(heyman.clone(), live), &SolverOptions::default()).unwrap();
        let b = limit(&paper_arch(rough.clone(), live), &SolverOptions::default()).unwrap();
        let (la, lb) = (a.load_multiplier.unwrap(), b.load_multiplier.unwrap());
        assert!((la - lb).abs() < 1e-9, "{la} vs {lb}");
        // Under the symmetric load the collapse mechanism is not unique (the five-hinge
        // mechanism combines two four-hinge ones of equal λ), so only the half-span mechanism
        // is compared.
        if live == LiveLoad::Left {
            assert_eq!(a.hinges, b.hinges);
        }
    }
    let mut st = paper_arch(rough, LiveLoad::None);
    st.supports[1].motion = [0.01, 0.0, 0.0];
    let r = settle(&st, &SolverOptions::default()).unwrap();
    let joints: Vec<usize> = r.hinges.iter().map(|h| h.joint).collect();
    assert_eq!(joints, vec![13, 32, 51]);
    assert!(r.duality_gap.unwrap() < 1e-7);
}

/// Whether a semicircular arch (centreline radius 1, thickness t) with friction μ stands under
/// self-weight: the settlement primal without settlement is bounded.
fn stands(t: f64, mu: Option<f64>) -> bool {
    let mut m = arch(&ArchSpec {
        radius: 1.0,
        radius_at: RadiusAt::Centreline,
        thickness: t,
        voussoirs: 64,
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    m.materials.insert(
        "default".into(),
        Material {
            friction: mu,
            ..Material::default()
        },
    );
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    settle(&st, &SolverOptions::default()).unwrap().status == SettlementStatus::Mechanism
}

fn min_thickness(mu: Option<f64>) -> Option<f64> {
    let (mut lo, mut hi) = (0.05, 0.6);
    if !stands(hi, mu) {
        return None;
    }
    for _ in 0..20 {
        let mid = 0.5 * (lo + hi);
        if stands(mid, mu) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}

#[test]
fn arch_minimum_thickness_rises_as_friction_falls() {
    let heyman = min_thickness(None).unwrap();
    let t06 = min_thickness(Some(0.6)).unwrap();
    let t035 = min_thickness(Some(0.35)).unwrap();
    assert!((heyman - 0.1075).abs() < 0.001, "{heyman}");
    // Monotone: less friction never needs less thickness; at μ = 0.35 sliding governs.
    assert!(
        t06 >= heyman - 1e-6 && t035 > t06 + 0.01,
        "t(∞) = {heyman}, t(0.6) = {t06}, t(0.35) = {t035}"
    );
    // Below some μ no thickness up to t/R = 0.6 is enough (mixed sliding–rotation collapse).
    assert_eq!(min_thickness(Some(0.25)), None);
}

#[test]
fn tilt_angle_of_a_block() {
    use voussoir::analysis::tilt::tilt;
    // Overturning at tan α = b/h, sliding at tan α = μ.
    let st = block(1.0, 2.0, Material::default());
    let r = tilt(&st, 1.0, &SolverOptions::default()).unwrap();
    assert!((r.tilt_angle.unwrap() - 0.5f64.atan().to_degrees()).abs() < 1e-7);
    let st = block(
        1.0,
        2.0,
        Material {
            friction: Some(0.3),
            ..Material::default()
        },
    );
    let r = tilt(&st, -1.0, &SolverOptions::default()).unwrap();
    assert!((r.tilt_angle.unwrap() - 0.3f64.atan().to_degrees()).abs() < 1e-7);
    assert_eq!(r.limit.status, LimitStatus::Collapse);
}

#[test]
fn lintel_with_finite_strength_has_the_flat_arch_capacity() {
    use voussoir::generate::{lintel, LintelSpec};
    // A flat lintel is a three-hinge flat arch: thrust H with lever arm t − H/(f_c w), largest
    // moment capacity f_c w t²/4 at H = f_c w t/2, equal to the midspan moment (g + λq)L²/8.
    let spec = LintelSpec {
        compressive_strength: Some(2400.0),
        ..LintelSpec::default()
    };
    let st = Structure::new(&lintel(&spec).unwrap(), BuildOptions::default()).unwrap();
    let (t, l, fc) = (spec.thickness, spec.span, 2400.0);
    let g = spec.unit_weight * t;
    let exact = (fc * t * t / 4.0 - g * l * l / 8.0) / (spec.live_load * l * l / 8.0);
    for crushing in [Crushing::Conic, Crushing::Linear] {
        let r = limit_with(&st, &SolverOptions::default(), crushing, 16).unwrap();
        let lam = r.load_multiplier.unwrap();
        assert!(
            (lam - exact).abs() < 1e-5 * exact,
            "{crushing:?}: λ = {lam}, flat arch {exact}"
        );
        // The crown joint is crushed over half the depth: a = H/(f_c w) = t/2.
        let crown = r
            .joints
            .iter()
            .find(|j| j.state == JointState::Hinge && j.points[0].x.abs() < 1e-9)
            .unwrap();
        assert!((crown.compressed_depth.unwrap() - t / 2.0).abs() < 1e-5);
    }
    // Without finite strength the lintel is locked.
    let st = Structure::new(
        &lintel(&LintelSpec::default()).unwrap(),
        BuildOptions::default(),
    )
    .unwrap();
    assert_eq!(
        limit(&st, &SolverOptions::default()).unwrap().status,
        LimitStatus::Locked
    );
}

#[test]
fn non_associative_friction() {
    use voussoir::analysis::nonassociative::{limit_nonassociative, NonAssociativeOptions};
    let o = NonAssociativeOptions::default();
    // A sliding block: no dilatancy is involved, both laws give λ = μ.
    let st = block(
        1.0,
        2.0,
        Material {
            friction: Some(0.3),
            ..Material::default()
        },
    );
    let r = limit_nonassociative(&st, &SolverOptions::default(), &o).unwrap();
    assert!(r.converged);
    assert!((r.limit.load_multiplier.unwrap() - 0.3).abs() < 1e-7);
    // The paper arch under a half-span load with μ = 0.4: the dilatancy-free multiplier is not
    // above the associative one, and the converged forces satisfy Coulomb with their own
    // normal forces.
    let st = paper_arch(
        Material {
            friction: Some(0.4),
            ..Material::default()
        },
        LiveLoad::Left,
    );
    let r = limit_nonassociative(&st, &SolverOptions::default(), &o).unwrap();
    let (na, a) = (
        r.limit.load_multiplier.unwrap(),
        r.associative_multiplier.unwrap(),
    );
    assert!(r.converged, "history {:?}", r.history);
    assert!(na <= a + 1e-9, "non-associative {na} > associative {a}");
    for j in &r.limit.joints {
        for p in &j.points {
            assert!(
                p.shear_force.abs() <= 0.4 * p.normal_force + 1e-6 * (1.0 + p.normal_force),
                "joint {}",
                j.id
            );
        }
    }
}

#[test]
fn two_voussoir_arch_slides_below_the_hand_threshold() {
    // Two chord-sided voussoirs (intrados radius 1, extrados 1.5): each half is the triangle
    // (O, (−Re, 0), (0, Re)) minus (O, (−Ri, 0), (0, Ri)), centroid at x̄ = (Re³ − Ri³)/(3(Re² − Ri²))
    // from the axis. The only joints are the horizontal springings and the vertical crown joint
    // (no shear there, by symmetry). Moment equilibrium of a half about the inner springing
    // corner with the crown thrust at the extrados gives the least thrust
    // H = (W/2)(Ri − x̄)/Re, so the arch stands iff μ ≥ (Ri − x̄)/Re.
    let (ri, re) = (1.0f64, 1.5f64);
    let xbar = (re.powi(3) - ri.powi(3)) / (3.0 * (re * re - ri * ri));
    let mu_star = (ri - xbar) / re;
    let stands = |mu: f64| {
        let mut m = arch(&ArchSpec {
            radius: ri,
            thickness: re - ri,
            voussoirs: 2,
            live: LiveLoad::None,
            ..ArchSpec::default()
        })
        .unwrap();
        m.materials.insert(
            "default".into(),
            Material {
                friction: Some(mu),
                ..Material::default()
            },
        );
        let st = Structure::new(&m, BuildOptions::default()).unwrap();
        settle(&st, &SolverOptions::default()).unwrap().status == SettlementStatus::Mechanism
    };
    assert!((mu_star - 0.244444).abs() < 1e-6);
    assert!(
        stands(mu_star * (1.0 + 1e-6)),
        "should stand just above μ* = {mu_star}"
    );
    assert!(
        !stands(mu_star * (1.0 - 1e-6)),
        "should slide just below μ* = {mu_star}"
    );
}
