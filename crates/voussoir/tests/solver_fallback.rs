//! Issue 29: a solver failure is never the user's problem while another method can answer.
//! A backend failure is forced (an iteration limit of 1 on the requested method); the solver
//! layer's fallback chain (`lp::fallback_chain`) must produce the certified answer and say
//! which method did.

use voussoir::analysis::limit::limit;
use voussoir::analysis::settlement::settle;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::{fallback_chain, Method, SolverOptions};
use voussoir::{BuildOptions, Structure};

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
