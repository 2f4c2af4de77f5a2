//! Issue 29: a solver failure is never the user's problem while another method can answer.
//! A backend failure is forced (an iteration limit of 1 on the requested method); the solver
//! layer's fallback chain (`lp::fallback_chain`) must produce the certified answer and say
//! which method did.

use voussoir::analysis::limit::limit;
use voussoir::analysis::settlement::settle;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::{fallback_chain, Method, SolverOptions};
use voussoir::{BuildOptions, Structure};

mod support;
use support::offset_stack;

fn paper_arch(live: LiveLoad) -> Structure {
    let mut m = arch(&ArchSpec {
        live,
        ..ArchSpec::default()
    })
    .unwrap();
    // The right springing moves out and down (a settlement for `settle`).
    m.supports[1].motion = [0.01, -0.005, 0.0];
    Structure::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn a_limit_analysis_whose_method_fails_is_answered_by_the_next_method() {
    let st = paper_arch(LiveLoad::Full);
    // The reference: the same analysis without any limit (README: λ = 0.4346).
    let reference = limit(&st, &SolverOptions::default()).unwrap();
    let lref = reference.load_multiplier.unwrap();
    assert!((lref - 0.4346).abs() < 5e-5, "{lref}");
    for method in [Method::Ipm, Method::DualSimplex, Method::Clarabel] {
        let o = SolverOptions {
            method,
            iteration_limit: Some(1),
            ..SolverOptions::default()
        };
        let r = limit(&st, &o).unwrap();
        let l = r.load_multiplier.unwrap();
        assert!(
            (l - lref).abs() <= 1e-6 * lref,
            "{method:?}: λ {l} against {lref}"
        );
        assert!(
            r.certificate.as_ref().unwrap().ok,
            "{method:?}: {}",
            r.message
        );
        // The method that answered is the next one in the chain, and the result says so.
        assert_eq!(r.solver.method, fallback_chain(method)[1], "{method:?}");
        assert!(
            r.solver.tried[0].starts_with(&format!("{}:", method.name())),
            "{:?}",
            r.solver.tried
        );
        assert!(
            r.message.contains(&format!(
                "solved by {} after {} failed",
                r.solver.method.name(),
                method.name()
            )),
            "{}",
            r.message
        );
    }
}

#[test]
fn a_settlement_whose_method_fails_is_answered_and_certified() {
    let st = paper_arch(LiveLoad::None);
    let reference = settle(&st, &SolverOptions::default()).unwrap();
    let wref = reference.work_dead_loads.unwrap();
    let o = SolverOptions {
        method: Method::DualSimplex,
        iteration_limit: Some(1),
        ..SolverOptions::default()
    };
    let r = settle(&st, &o).unwrap();
    let w = r.work_dead_loads.unwrap();
    assert!((w - wref).abs() <= 1e-9 * wref.abs(), "{w} against {wref}");
    assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
    assert_eq!(r.solver.method, Method::PrimalSimplex);
    assert!(
        r.message.contains("after dual-simplex failed"),
        "{}",
        r.message
    );
    // Without a failure nothing is said and nothing is written.
    assert!(reference.solver.tried.is_empty());
    let json = serde_json::to_string(&reference).unwrap();
    assert!(!json.contains("\"tried\""), "{json}");
}

#[test]
fn the_safety_factor_of_a_stack_is_exact_at_every_scale_and_with_every_method() {
    use voussoir::analysis::safety::{safety, SafetyOptions};
    // By hand (Heyman's geometric factor): the upper box's centroid (x = 0.5 + e) over its
    // contact [e, 1] (centre (1 + e)/2, half-width (1 − e)/2) needs the fraction
    // f ≥ (0.5 + e − (1 + e)/2) / ((1 − e)/2) = e / (1 − e); the pair's centroid (0.5 + e/2)
    // over the base contact [0, 1] needs f ≥ e. With e = 0.3: f = 3/7.
    let e = 0.3;
    let hand = e / (1.0 - e);
    for s in [1.0, 100.0, 0.003] {
        let st = offset_stack(e, s);
        for method in [Method::DualSimplex, Method::Ipm, Method::Clarabel] {
            let o = SafetyOptions {
                reactions: false,
                solver: SolverOptions {
                    method,
                    ..SolverOptions::default()
                },
                ..SafetyOptions::default()
            };
            let r = safety(&st, &o).unwrap();
            let f = r.least_joint_fraction.unwrap();
            // The bisection's tolerance is 1e-6 on the fraction, from above.
            assert!(
                f >= hand - 1e-9 && f <= hand + 1.01e-6,
                "×{s}, {method:?}: {f} against {hand}"
            );
        }
    }
}
