//! Issue 29 (session 21, helper h-capnoeq): capacity curves whose settled steps have no
//! equilibrium. The 1.0 m grid façade, its right half settling 20 cm (`capacity --steps 20
//! --profile uniform:11,22,-0.2`), has no equilibrium at any settled step; every step's limit
//! program was solved (the warm dual simplex, failing over to the primal simplex, the interior
//! point and Clarabel) and then its no-equilibrium certificate (the elastic program): 258.5
//! CPU s. Now a step after one certified without equilibrium on the same open points is decided
//! by its own certificate first, and its limit program solved only where that does not hold;
//! the root finding next to such a step asks Clarabel's elastic program first: 52.3 CPU s, the
//! curve's JSON identical (docs/performance.md, "Capacity steps without equilibrium
//! (session 21)").
//!
//! The tests: the request layer's row (a named method solves every step's limit program, as
//! before); on the 2.0 m grid façade (223 blocks, the same settlement; no equilibrium at every
//! settled step) the curve with the shortcut equals, step by step, the curve whose every step's
//! limit program is solved (the dual simplex warm, and HiGHS's interior point from scratch:
//! independent decisions of the infeasibility), and the shortcut was taken at every settled step
//! after the first (counted in the solver layer's records).

use voussoir::analysis::canonical::CanonicalOptions;
use voussoir::analysis::capacity::{capacity, CapacityOptions, CapacityResult};
use voussoir::analysis::limit::LimitStatus;
use voussoir::dim::Two;
use voussoir::generate::LiveLoad;
use voussoir::generate_facade::{bondeno, facade, FacadeMesh, FacadeSpec};
use voussoir::lp::policy::{ProblemClass, Purpose};
use voussoir::lp::{collecting, Method, SolverOptions};
use voussoir::request::{Analysis, CapacityRequest, Request};
use voussoir::result::capacity::StepCertificateKind;
use voussoir::settlement_input::{apply_profile_as_drawn, Profile};
use voussoir::{BuildOptions, Structure};

#[test]
fn issue29_no_equilibrium_first_in_the_request_layer() {
    let class = ProblemClass {
        blocks: 716,
        purpose: Purpose::Curve,
        ..ProblemClass::of_dim(2)
    };
    let mut req = Request::new(Analysis::Capacity(CapacityRequest::default()));
    let cap = CapacityRequest::default();
    assert!(cap.options(&req, 2, &class).no_equilibrium_first);
    // A method named: every step's limit program by it, as before.
    req.solver.method = Some(Method::DualSimplex);
    assert!(!cap.options(&req, 2, &class).no_equilibrium_first);
    // The library's default: off.
    assert!(!CapacityOptions::default().no_equilibrium_first);
}

/// The paper's façade in a 2.0 m grid with the horizontal live load, its supports from x = 11
/// to 22 m settling 20 cm (`gen facade --mesh grid --element 2.0 --live horizontal`,
/// `--profile uniform:11,22,-0.2`).
fn settled_facade() -> Structure {
    let mut m = facade(&FacadeSpec {
        live: LiveLoad::Horizontal,
        ..bondeno(2.0, FacadeMesh::Grid)
    })
    .unwrap();
    apply_profile_as_drawn(
        &mut m,
        &Profile::Uniform {
            x0: 11.0,
            x1: 22.0,
            v: -0.2,
        },
    )
    .unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

/// The curve, and how many limit programs ("steps") and elastic programs ("no-equilibrium
/// certificates") were answered.
fn run(
    st: &Structure,
    method: Method,
    hot_start: bool,
    first: bool,
) -> (CapacityResult<Two>, usize, usize) {
    let (r, solves) = collecting(|| {
        capacity(
            st,
            &CapacityOptions {
                steps: 4,
                // The bracket of the root (0 to 5 cm) is taken as it is: no root finding, so
                // that the counts below are the steps'.
                root_tolerance: 1.0,
                hot_start,
                mechanisms: false,
                solver: SolverOptions {
                    method,
                    ..SolverOptions::default()
                },
                no_equilibrium_first: first,
                // The settlement mechanism canonical (as the request layer selects it), so that
                // the deformed geometry does not depend on the method.
                canonical: Some(CanonicalOptions {
                    forces: false,
                    reaction_ranges: false,
                    ..CanonicalOptions::default()
                }),
                ..CapacityOptions::default()
            },
        )
        .unwrap()
    });
    let count =
        |programs: &str| -> usize { solves.iter().filter(|s| s.programs == programs).count() };
    (r, count("steps"), count("no-equilibrium certificates"))
}

#[test]
fn issue29_capacity_steps_without_equilibrium_decided_by_their_certificate_first() {
    let st = settled_facade();
    // The shortcut (the request layer's default for this model: the dual simplex warm).
    let (fast, fast_steps, fast_certificates) = run(&st, Method::DualSimplex, true, true);
    // References: every step's limit program solved, by the same method warm, and by HiGHS's
    // interior point from scratch.
    let (warm, warm_steps, _) = run(&st, Method::DualSimplex, true, false);
    let (ipm, _, _) = run(&st, Method::Ipm, false, false);
    assert_eq!(fast.curve.len(), 5);
    for reference in [&warm, &ipm] {
        assert_eq!(reference.curve.len(), 5);
        for (i, (a, b)) in fast.curve.iter().zip(&reference.curve).enumerate() {
            assert_eq!(a.settlement, b.settlement, "step {i}");
            assert_eq!(a.status, b.status, "step {i}: {}", fast.message);
            let c = a.certificate.as_ref().expect("a certificate");
            assert!(c.ok, "step {i}: {c:?}");
            if i == 0 {
                // λ(0): the plain limit analysis, a multiplier (the same program by two
                // methods: to 1e-9 relative).
                let (la, lb) = (a.load_multiplier.unwrap(), b.load_multiplier.unwrap());
                assert!(la > 0.0);
                assert!((la - lb).abs() <= 1e-9 * lb.abs(), "λ(0) {la} against {lb}");
                continue;
            }
            // Every settled step: no equilibrium at any λ, certified (the least violation of
            // the equilibrium rows above the decision's margin), as the reference's limit
            // program found it.
            assert_eq!(a.status, LimitStatus::NoEquilibrium, "step {i}");
            assert_eq!(a.load_multiplier, None, "step {i}");
            assert_eq!(c.kind, StepCertificateKind::NoEquilibrium, "step {i}");
            let (va, vb) = (
                c.violation.unwrap(),
                b.certificate.as_ref().unwrap().violation.unwrap(),
            );
            assert!(
                va > voussoir::lp::sequence::INFEASIBLE_MARGIN,
                "step {i}: {va}"
            );
            // On the same settlement (the dual simplex's: the same deformed geometry) the same
            // elastic program, so the same least violation. (The interior point's settlement
            // mechanism, though canonical, deforms the façade a little differently: its least
            // violations differ by a few per cent, e.g. 3.59 against 3.69 at 5 cm.)
            if std::ptr::eq(reference, &warm) {
                assert!(
                    (va - vb).abs() <= 1e-9 * vb,
                    "step {i}: violation {va} against {vb}"
                );
            }
        }
        assert_eq!(
            fast.zero_capacity_settlement,
            reference.zero_capacity_settlement
        );
        assert_eq!(
            fast.certificate.as_ref().map(|c| (c.steps, c.certified)),
            Some((5, 5))
        );
    }
    // The references solved the limit program of every step; the shortcut that of step 0
    // only (steps 1–4 decided by their certificates, one elastic program each, the first
    // settled step's by Clarabel first since session 27: four certificates in all, and the
    // onset's).
    // (From scratch the limit programs are not the warm "steps" records: counted by the
    // curve's own `solves`.)
    assert_eq!((warm_steps, warm.solves, ipm.solves), (5, 5, 5));
    assert_eq!((fast_steps, fast.solves), (1, 1), "{}", fast.message);
    assert!(fast_certificates >= 4, "{fast_certificates}");
}
