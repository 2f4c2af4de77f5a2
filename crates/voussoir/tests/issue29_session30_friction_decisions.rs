//! Issue 29 items 1 and 6 (session 30): the bisection's decisions of `safety` on a large 2D
//! program with Coulomb friction go to Clarabel (`lp::policy::decision_method`). HiGHS's
//! interior point took 87.7 s to show that the 0.5 m running-bond façade with μ = 0.6 stands
//! at f = 1 (Clarabel: 1.3 s) and 214 s to show that the 0.25 m grid façade with μ = 0.6 does
//! not (Clarabel: 4.1 s, then the same certified elastic program); docs/performance.md,
//! "Frictional façades: the least multiplier and the mirror (session 30)". A decision needs no
//! vertex: "stands" is checked on the program itself, "does not stand" decided again by the
//! elastic program with a certificate, whatever the method (`analysis::safety::Decisions`).
//!
//! References: the same questions decided by HiGHS (the dual simplex and its interior point,
//! the paths before), and, for the arch, the least joint fraction by a bisection of decisions
//! by the dual simplex from scratch.

use voussoir::analysis::safety::{safety, SafetyOptions};
use voussoir::generate::{arch, ArchSpec};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
use voussoir::lp::policy::{class_of, decision_method, Purpose};
use voussoir::lp::{Method, SolverOptions};
use voussoir::model3d::AnyModel;
use voussoir::request::{self, Analysis, AnyResult, Output, Request, SafetyRequest};
use voussoir::{BuildOptions, Structure};

fn with_friction(mut m: voussoir::Model, mu: f64) -> voussoir::Model {
    m.override_joint_laws(Some(mu), None);
    m
}

#[test]
fn issue29_session30_a_large_frictional_facades_decisions_go_to_clarabel() {
    // The 0.5 m grid façade with μ = 0.6 (2,654 blocks): its stack bond over the openings does
    // not stand under its own weight (the realistic benchmark's "cannot stand", sessions 18–28).
    let m = with_friction(facade(&bondeno(0.5, FacadeMesh::Grid)).unwrap(), 0.6);
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    assert_eq!(
        decision_method(&class_of(&st, Purpose::Feasibility)),
        Some(Method::Clarabel)
    );
    // Without friction, or below the size, the class's own method decides.
    let plain = Structure::new(
        &facade(&bondeno(0.5, FacadeMesh::Grid)).unwrap(),
        BuildOptions::default(),
    )
    .unwrap();
    assert_eq!(
        decision_method(&class_of(&plain, Purpose::Feasibility)),
        None
    );
    let req = Request::new(Analysis::Safety(SafetyRequest {
        no_ranges: true,
        ..SafetyRequest::default()
    }));
    let out = match request::run(&AnyModel::Planar(m.clone()), &req).unwrap() {
        AnyResult::Planar(run) => run.output,
        AnyResult::Spatial(_) => panic!("dimension"),
    };
    let Output::Safety(r) = out else {
        panic!("not a safety result")
    };
    println!("{} {:?}", r.message, r.answered);
    assert!(!r.stands);
    let bisection = r
        .answered
        .iter()
        .find(|a| a.programs == "bisection")
        .expect("the bisection's programs");
    assert_eq!(bisection.method, Method::Clarabel);
    // The elastic program's certificate decided "does not stand".
    assert!(r
        .answered
        .iter()
        .any(|a| a.programs == "elastic decisions" && a.outcome == "certified"));
    // The path before: HiGHS's interior point with crossover decides, the same answer.
    let before = safety(
        &st,
        &SafetyOptions {
            reactions: false,
            solver: SolverOptions {
                method: Method::Ipm,
                ..SolverOptions::default()
            },
            ..SafetyOptions::default()
        },
    )
    .unwrap();
    assert!(!before.stands);
}

#[test]
fn issue29_session30_clarabels_decisions_give_the_dual_simplexs_least_fraction() {
    // The paper's arch with μ = 0.6 (it stands; its joints shrunk, down to a least fraction):
    // the bisection decided by Clarabel ends where the one by the dual simplex does, to the
    // bisection's tolerance (both brackets hold the least fraction).
    let st = Structure::new(
        &with_friction(arch(&ArchSpec::default()).unwrap(), 0.6),
        BuildOptions::default(),
    )
    .unwrap();
    let tolerance = 1e-6;
    let by = |decisions: Option<Method>| {
        safety(
            &st,
            &SafetyOptions {
                tolerance,
                reactions: false,
                decisions: decisions.map(|method| SolverOptions {
                    method,
                    ..SolverOptions::default()
                }),
                ..SafetyOptions::default()
            },
        )
        .unwrap()
    };
    let simplex = by(None);
    let clarabel = by(Some(Method::Clarabel));
    let (fs, fc) = (
        simplex.least_joint_fraction.unwrap(),
        clarabel.least_joint_fraction.unwrap(),
    );
    println!("least fraction: dual simplex {fs}, Clarabel {fc}");
    assert!(fs > 0.05 && fs < 1.0, "{fs}");
    assert!((fs - fc).abs() <= 2.0 * tolerance, "{fs} {fc}");
}

#[test]
fn issue29_session30_a_large_frictional_limit_looks_for_no_equilibrium_with_clarabel_first() {
    // The 0.5 m grid façade with μ = 0.6 on the tilting table: no λ has an equilibrium (it
    // cannot stand under its own weight). The policy's options look with Clarabel first
    // (`SolverOptions::infeasibility_first`) and answer "no equilibrium" without HiGHS's
    // interior point; a method named by the user is honoured: HiGHS's interior point answers,
    // the same.
    use voussoir::analysis::limit::{dead_loads_certificate, limit, LimitStatus};
    use voussoir::lp::policy::{infeasibility_first, options};
    use voussoir::Assembly;
    let m = with_friction(facade(&bondeno(0.5, FacadeMesh::Grid)).unwrap(), 0.6);
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let tilted = st.with_weight_as_live_load([1.0, 0.0]).unwrap();
    let class = class_of(&tilted, Purpose::Optimise);
    assert!(infeasibility_first(&class));
    let policy = options(&class, None, &SolverOptions::default());
    assert!(policy.infeasibility_first);
    let named = options(&class, Some(Method::Ipm), &SolverOptions::default());
    assert!(!named.infeasibility_first);
    let first = limit(&tilted, &policy).unwrap();
    assert_eq!(first.status, LimitStatus::NoEquilibrium);
    assert_eq!(first.solver.method, Method::Clarabel);
    let by_ipm = limit(&tilted, &named).unwrap();
    assert_eq!(by_ipm.status, LimitStatus::NoEquilibrium);
    assert_ne!(by_ipm.solver.method, Method::Clarabel);
    // And the dead loads alone have no equilibrium, certified (the sessions-18–28 answer:
    // least violation 7.0e-3 of the largest load).
    let mut message = String::new();
    let c = dead_loads_certificate(&st, &SolverOptions::default(), None, &mut message)
        .unwrap()
        .unwrap();
    println!("{message}: {c:?}");
    assert!(c.ok);
    assert!((c.violation.unwrap() - 7.0e-3).abs() < 0.05e-3, "{c:?}");
}
