//! Issue 29 items 4 and 6 (session 20, helper h-cap2d): a 2D capacity curve above
//! `SIMPLEX_MAX_BLOCKS_2D` solves its first program and its first settled one by the policy's
//! method (HiGHS's interior point with crossover), and every later step — whose program has the
//! open points of the step before, only its coefficients changed — by the dual simplex warm
//! from the basis the step before left ([`policy::curve_warm_method`]). Measured on the 0.5 m
//! façade in running bond (2,672 blocks): a step by the interior point from scratch 8.4–25 CPU
//! s, by the warm dual simplex about 1.4 (docs/performance.md, "Façade capacity curves
//! (session 20)").
//!
//! The tests: the policy's rows and the request layer's use of them (a named method is
//! honoured at every step); the warm curve certified at every step and equal to the curve
//! solved from scratch at every step by the interior point, and to the dual simplex's, on the
//! paper's arch (the same code path as the façade's, the size threshold aside).

use voussoir::analysis::capacity::{capacity, CapacityOptions, CapacityResult};
use voussoir::dim::Two;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::policy::{self, ProblemClass, Purpose, SIMPLEX_MAX_BLOCKS_2D};
use voussoir::lp::{collecting, Method, SolverOptions};
use voussoir::request::{Analysis, CapacityRequest, Request};
use voussoir::{BuildOptions, Structure};

fn curve(dim: u8, blocks: usize) -> ProblemClass {
    ProblemClass {
        blocks,
        purpose: Purpose::Curve,
        ..ProblemClass::of_dim(dim)
    }
}

#[test]
fn issue29_curve_warm_method_rows() {
    // 2D curves above the simplex's bound, without friction or cones: the warm dual simplex.
    let big = curve(2, SIMPLEX_MAX_BLOCKS_2D + 1);
    assert_eq!(policy::default_method(&big), Method::Ipm);
    assert_eq!(policy::curve_warm_method(&big), Some(Method::DualSimplex));
    assert_eq!(
        policy::curve_warm_method(&curve(2, 2_672)),
        Some(Method::DualSimplex)
    );
    // At or below the bound every step is the dual simplex's already (warm from step to step).
    let small = curve(2, SIMPLEX_MAX_BLOCKS_2D);
    assert_eq!(policy::default_method(&small), Method::DualSimplex);
    assert_eq!(policy::curve_warm_method(&small), None);
    // Friction, cones, 3D and the other purposes: unchanged (None).
    for class in [
        ProblemClass {
            friction: true,
            ..big
        },
        ProblemClass { cones: true, ..big },
        curve(3, 2_257),
        ProblemClass {
            purpose: Purpose::Optimise,
            ..big
        },
        ProblemClass {
            purpose: Purpose::CanonicalStage,
            ..big
        },
    ] {
        assert_eq!(policy::curve_warm_method(&class), None, "{class:?}");
    }
}

#[test]
fn issue29_curve_warm_method_in_the_request_layer() {
    let big = curve(2, 2_654);
    let mut req = Request::new(Analysis::Capacity(CapacityRequest::default()));
    let cap = CapacityRequest::default();
    let o = cap.options(&req, 2, &big);
    assert_eq!(o.solver.method, Method::Ipm);
    assert_eq!(o.warm_method, Some(Method::DualSimplex));
    // Below the bound: no warm method of its own (the dual simplex throughout).
    let o = cap.options(&req, 2, &curve(2, 716));
    assert_eq!(o.solver.method, Method::DualSimplex);
    assert_eq!(o.warm_method, None);
    // A method named is honoured at every step.
    req.solver.method = Some(Method::Ipm);
    let o = cap.options(&req, 2, &big);
    assert_eq!((o.solver.method, o.warm_method), (Method::Ipm, None));
    // Non-associative friction: the iteration's programs, no warm method.
    req.solver.method = None;
    let nonassociative = CapacityRequest {
        non_associative: true,
        ..CapacityRequest::default()
    };
    assert_eq!(nonassociative.options(&req, 2, &big).warm_method, None);
}

/// The paper's arch, live load on the whole span, the right springing moving out and down.
fn settled_arch() -> Structure {
    let mut m = arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap();
    m.supports[1].motion = [0.01, -0.005, 0.0];
    Structure::new(&m, BuildOptions::default()).unwrap()
}

fn run(st: &Structure, method: Method, warm: Option<Method>) -> (CapacityResult<Two>, usize) {
    let (r, solves) = collecting(|| {
        capacity(
            st,
            &CapacityOptions {
                steps: 8,
                solver: SolverOptions {
                    method,
                    ..SolverOptions::default()
                },
                warm_method: warm,
                ..CapacityOptions::default()
            },
        )
    });
    let warm_steps = solves
        .iter()
        .filter(|s| s.programs == "steps" && Some(s.method) == warm)
        .count();
    (r.unwrap(), warm_steps)
}

#[test]
fn issue29_curve_warm_steps_certified_and_equal_to_the_cold_curve() {
    let st = settled_arch();
    let (warm, warm_steps) = run(&st, Method::Ipm, Some(Method::DualSimplex));
    let (cold, cold_warm_steps) = run(&st, Method::Ipm, None);
    let (simplex, _) = run(&st, Method::DualSimplex, None);
    assert_eq!(cold_warm_steps, 0);
    // Steps 0 (no open point) and 1 (the first settled one: the open points fixed at zero)
    // by the interior point; the 7 after them by the warm dual simplex.
    assert_eq!(warm_steps, 7, "{:?}", warm.answered);
    for r in [&warm, &cold, &simplex] {
        let c = r.certificate.as_ref().unwrap();
        assert!(c.ok && c.certified == 9, "{c:?}");
    }
    // λ at every step: the three curves agree to the certificates' tolerance (1e-6
    // relative; measured 1e-11 and below here and on the façade).
    for ((a, b), c) in warm.curve.iter().zip(&cold.curve).zip(&simplex.curve) {
        let (la, lb, lc) = (
            a.load_multiplier.unwrap(),
            b.load_multiplier.unwrap(),
            c.load_multiplier.unwrap(),
        );
        assert!(
            (la - lb).abs() <= 1e-6 * lb.abs(),
            "s {}: {la} {lb}",
            a.settlement
        );
        assert!(
            (la - lc).abs() <= 1e-6 * lc.abs(),
            "s {}: {la} {lc}",
            a.settlement
        );
    }
    // λ(0): the paper's (Fig 7: 0.4346), and it falls with the settlement.
    let l0 = warm.curve[0].load_multiplier.unwrap();
    assert!((l0 - 0.434645).abs() < 1e-6, "{l0}");
    assert!(warm.curve[8].load_multiplier.unwrap() < l0);
}
