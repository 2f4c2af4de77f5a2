//! Issue #29 item 3 for `capacity` and `least-thickness` (helper h-cap, session 15): every
//! step of a capacity curve carries the certificate of its limit program, and every decision of
//! the least-thickness bisection is reported as `safety` reports its programs (`answered`).

use voussoir::analysis::capacity::{capacity, CapacityOptions, StepCertificateKind};
use voussoir::analysis::limit;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::{Method, SolverOptions};
use voussoir::request::{least_thickness, Generator, LeastThicknessRequest, Names, SolverRequest};
use voussoir::{BuildOptions, Structure};

/// The paper's arch, live load on the whole span, the right springing moving `right`.
fn settled_arch(right: [f64; 2]) -> Structure {
    let mut m = arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap();
    m.supports[1].motion = [right[0], right[1], 0.0];
    Structure::new(&m, BuildOptions::default()).unwrap()
}

/// λ recomputed from a reported mechanism (block motions at the centroids, normalised to unit
/// work of the live loads): `−F_D·d / F_L·d` with the load vectors of the undeformed structure.
fn kinematic_multiplier(st: &Structure, blocks: &[voussoir::result::BlockMotion]) -> f64 {
    let (dead, live) = (st.load_vector(false), st.load_vector(true));
    let mut d = vec![0.0; dead.len()];
    for b in blocks {
        d[3 * b.id] = b.u;
        d[3 * b.id + 1] = b.v;
        d[3 * b.id + 2] = b.theta;
    }
    let w = |f: &[f64]| f.iter().zip(&d).map(|(a, b)| a * b).sum::<f64>();
    -w(&dead) / w(&live)
}

#[test]
fn issue29_item3_capacity_every_step_certified() {
    // Outward and downward settlement of the right springing (the benchmark's motion).
    let st = settled_arch([0.01, -0.005]);
    let r = capacity(
        &st,
        &CapacityOptions {
            steps: 4,
            ..CapacityOptions::default()
        },
    )
    .unwrap();
    let c = r.certificate.as_ref().expect("a curve has its certificate");
    assert_eq!(c.steps, 5);
    assert_eq!(c.certified, 5, "{c:?}");
    assert!(c.ok && c.uncertified_steps.is_empty());
    assert!(c.gap <= 1e-6 && c.admissibility <= 1e-6, "{c:?}");
    // Each step: the multiplier certificate, whose gap is the distance between λ and the
    // kinematic multiplier of the reported mechanism.
    for p in &r.curve {
        let s = p.certificate.as_ref().expect("every step has one");
        assert_eq!(s.kind, StepCertificateKind::Multiplier);
        assert!(s.ok && s.gap.unwrap() <= 1e-6 && s.admissibility.unwrap() <= 1e-6);
    }
    // At s = 0 the step is the plain limit analysis: the same certificate as `limit`'s, and
    // λ equal to the work ratio of its mechanism recomputed here (dead loads at the
    // centroids: the ratio does not depend on the geometry's rotation).
    let plain = limit::limit(&st, &SolverOptions::default()).unwrap();
    let pc = plain.certificate.unwrap();
    let s0 = r.curve[0].certificate.as_ref().unwrap();
    assert_eq!(s0.gap, Some(pc.gap));
    assert_eq!(s0.admissibility, Some(pc.admissibility));
    let l0 = r.curve[0].load_multiplier.unwrap();
    let lk = kinematic_multiplier(&st, &r.mechanisms[0].blocks);
    assert!((l0 - lk).abs() <= 1e-6 * l0, "λ {l0} against {lk}");
    // The paper's value (Fig 7: λ = 0.4346 for the arch under a full-span load).
    assert!((l0 - 0.434645).abs() < 1e-6, "{l0}");
}

#[test]
fn issue29_item3_capacity_certificate_method_independent() {
    // The same curve by Clarabel (an interior point: its λ certified by its own mechanism).
    let st = settled_arch([0.01, -0.005]);
    let by = |method| {
        capacity(
            &st,
            &CapacityOptions {
                steps: 2,
                solver: SolverOptions {
                    method,
                    ..SolverOptions::default()
                },
                ..CapacityOptions::default()
            },
        )
        .unwrap()
    };
    let (a, b) = (by(Method::DualSimplex), by(Method::Clarabel));
    for (p, q) in a.curve.iter().zip(&b.curve) {
        let (lp, lq) = (p.load_multiplier.unwrap(), q.load_multiplier.unwrap());
        assert!((lp - lq).abs() <= 1e-6 * lp.abs().max(1e-3), "{lp} {lq}");
    }
    assert!(a.certificate.unwrap().ok);
    assert!(b.certificate.unwrap().ok);
}

#[test]
fn issue29_item3_least_thickness_decisions_answered() {
    let g = Generator::Arch(ArchSpec {
        live: LiveLoad::None,
        voussoirs: 64,
        ..ArchSpec::default()
    });
    let r = least_thickness(
        &g,
        &LeastThicknessRequest {
            bisection_tolerance: 1e-4,
            ..Default::default()
        },
        &SolverRequest::default(),
        Names::Fields,
    )
    .unwrap()
    .result;
    // Milankovitch's t/R = 0.1075 (continuous semicircular arch; 64 joints within 1 %).
    assert!((r.thickness_over_radius - 0.1075).abs() < 0.01 * 0.1075);
    assert!(r.certified, "{:?}", r.answered);
    // Every decision reported: the two ends and one per bisection step, each an equilibrium
    // state checked on the program or a proof of infeasibility.
    let n: usize = r.answered.iter().map(|a| a.answers).sum();
    assert_eq!(n, r.found.steps + 2, "{:?}", r.answered);
    assert!(r
        .answered
        .iter()
        .all(|a| a.programs == "bisection"
            && matches!(a.outcome.as_str(), "certified" | "infeasible")));
    // Both kinds of decision are there: it stands at the upper end, not at the lower one.
    assert!(r.answered.iter().any(|a| a.outcome == "infeasible"));
    assert!(r.answered.iter().any(|a| a.outcome == "certified"));
    let json = serde_json::to_value(&r).unwrap();
    assert_eq!(json["certified"], true);
    assert!(json["answered"].as_array().is_some_and(|a| !a.is_empty()));
}
