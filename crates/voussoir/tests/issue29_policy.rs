//! Issue 29 items 1 and 2: the solver policy in one place (`lp::policy`, asked by the request
//! layer, through which the CLI and Python run), and a fallback that moves on not only where a
//! method fails but also where it answers uncertified, the result saying which method answered
//! and what was tried.

use voussoir::analysis::limit::limit;
use voussoir::analysis::safety::{safety, SafetyOptions};
use voussoir::analysis::settlement::SettlementStatus;
use voussoir::generate::{arch, wall, ArchSpec, LiveLoad, WallSpec};
use voussoir::generate3d::{dome, vault, Bond, DomeSpec};
use voussoir::lp::policy::{self, class_of, default_method, ProblemClass, Purpose};
use voussoir::lp::{fallback_chain, Method, SolverOptions};
use voussoir::model3d::AnyModel;
use voussoir::request::{
    self, Analysis, AnyResult, LimitRequest, Request, SafetyRequest, SettleRequest, SolverRequest,
};
use voussoir::{BuildOptions, Structure, Structure3d};

fn paper_arch() -> voussoir::Model {
    arch(&ArchSpec {
        live: LiveLoad::Full,
        ..ArchSpec::default()
    })
    .unwrap()
}

/// The README's vault: the paper's arch extruded 1 m, 3 rings (λ = 0.4346, as in 2D).
fn readme_vault() -> voussoir::model3d::Model3d {
    vault(
        &ArchSpec {
            live: LiveLoad::Full,
            ..ArchSpec::default()
        },
        1.0,
        3,
        Bond::Stack,
    )
    .unwrap()
}

fn request(analysis: Analysis, method: Option<Method>) -> Request {
    Request {
        solver: SolverRequest { method, log: false },
        ..Request::new(analysis)
    }
}

#[test]
fn issue29_item2_an_uncertified_answer_moves_along_the_chain() {
    let st = Structure::new(&paper_arch(), BuildOptions::default()).unwrap();
    let reference = limit(&st, &SolverOptions::default()).unwrap();
    let lref = reference.load_multiplier.unwrap();
    // README's verified value.
    assert!((lref - 0.4346).abs() < 5e-5, "{lref}");
    // Clarabel stopped at a loose tolerance (1e-4) answers "optimal" with a duality gap far
    // above the certificate's 1e-6: the solver layer does not accept it, and the next method
    // of the chain (HiGHS's interior point with crossover, at the same loose tolerance, ends on
    // an exact vertex) answers.
    let o = SolverOptions {
        method: Method::Clarabel,
        feasibility_tolerance: 1e-4,
        ..SolverOptions::default()
    };
    let r = limit(&st, &o).unwrap();
    let l = r.load_multiplier.unwrap();
    assert!((l - lref).abs() <= 1e-7 * lref, "λ {l} against {lref}");
    assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
    assert_eq!(r.solver.method, fallback_chain(Method::Clarabel)[1]);
    assert!(
        r.solver.tried[0].starts_with("clarabel: not certified (row violation"),
        "{:?}",
        r.solver.tried
    );
    assert!(
        r.message.contains("solved by ipm after clarabel failed"),
        "{}",
        r.message
    );
}

#[test]
fn issue29_item2_the_layer_certificate_accepts_every_ordinary_answer() {
    // The solver layer's own certificate must not reject exact answers: the arch's limit with
    // each method, and its settlement and the vault's with the interior points, answer with
    // the method asked for (a certificate measuring each row on its own scale rejected
    // Clarabel's settlements, whose residuals are 1e-10 of the loads).
    let mut m = paper_arch();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    for method in [
        Method::DualSimplex,
        Method::PrimalSimplex,
        Method::Ipm,
        Method::Clarabel,
    ] {
        let o = SolverOptions {
            method,
            ..SolverOptions::default()
        };
        let r = limit(&st, &o).unwrap();
        assert_eq!(r.solver.method, method, "{:?}", r.solver.tried);
        assert!(r.solver.tried.is_empty(), "{:?}", r.solver.tried);
    }
    m.supports[1].motion = [0.01, -0.005, 0.0];
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    for method in [Method::DualSimplex, Method::Clarabel] {
        let o = SolverOptions {
            method,
            ..SolverOptions::default()
        };
        let r = voussoir::analysis::settlement::settle(&st, &o).unwrap();
        assert_eq!(r.solver.method, method, "{:?}", r.solver.tried);
        assert!(r.solver.tried.is_empty(), "{:?}", r.solver.tried);
        assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
    }
}

#[test]
fn issue29_item1_the_policy_picks_by_class_and_only_without_a_named_method() {
    let m = paper_arch();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let c = class_of(&st, Purpose::Optimise);
    assert_eq!(
        (c.dim, c.blocks, c.friction, c.cones),
        (2, 64, false, false)
    );
    assert_eq!(default_method(&c), Method::DualSimplex);
    // The request layer asks the policy with the class of its program; a named method stands.
    let limit_req = Analysis::Limit(LimitRequest::default());
    let req = request(limit_req.clone(), None);
    assert_eq!(request::class(&st, &req), c);
    assert_eq!(
        req.solver.options(&request::class(&st, &req)).method,
        Method::DualSimplex
    );
    let named = request(limit_req.clone(), Some(Method::Pdlp));
    assert_eq!(
        named.solver.options(&request::class(&st, &named)).method,
        Method::Pdlp
    );
    // Safety is a feasibility question; the non-associative iteration a sequence of iterates.
    let s = request(Analysis::Safety(SafetyRequest::default()), None);
    assert_eq!(request::class(&st, &s).purpose, Purpose::Feasibility);
    let na = request(
        Analysis::Limit(LimitRequest {
            non_associative: true,
            ..LimitRequest::default()
        }),
        None,
    );
    assert_eq!(request::class(&st, &na).purpose, Purpose::Iteration);
    assert_eq!(
        na.solver.options(&request::class(&st, &na)).method,
        Method::Clarabel
    );
    // A 2D wall above the simplex's size: HiGHS's interior point; any 3D structure: a vertex,
    // HiGHS's interior point with crossover (Clarabel's centre of the optimal face changed
    // the crack patterns; lp::policy).
    let big = wall(&WallSpec {
        courses: 40,
        units: 80,
        unit: [1.0, 0.5],
        ..WallSpec::default()
    })
    .unwrap();
    let big = Structure::new(&big, BuildOptions::default()).unwrap();
    assert!(big.blocks.len() > policy::SIMPLEX_MAX_BLOCKS_2D);
    assert_eq!(
        default_method(&class_of(&big, Purpose::Optimise)),
        Method::Ipm
    );
    let d = dome(&DomeSpec {
        courses: 4,
        segments: 8,
        ..DomeSpec::default()
    })
    .unwrap();
    let d = Structure3d::new(&d, BuildOptions::default()).unwrap();
    assert_eq!(class_of(&d, Purpose::Optimise).dim, 3);
    assert_eq!(
        default_method(&class_of(&d, Purpose::Optimise)),
        Method::Ipm
    );
    assert_eq!(request::default_method(3), Method::Ipm);
    assert_eq!(request::default_method(2), Method::DualSimplex);
    // Cones: only Clarabel takes them.
    let cones = ProblemClass {
        cones: true,
        ..ProblemClass::of_dim(2)
    };
    assert_eq!(default_method(&cones), Method::Clarabel);
}

#[test]
fn issue29_item1_the_request_layer_runs_the_vault_with_the_policy_method() {
    // `voussoir limit vault.json` without --method: the request layer's method is the
    // policy's for a 3D structure, and λ is the README's (0.4346, the 2D arch's).
    let req = request(Analysis::Limit(LimitRequest::default()), None);
    let AnyResult::Spatial(run) = request::run(&AnyModel::Spatial(readme_vault()), &req).unwrap()
    else {
        panic!("a 3D model gives a 3D result")
    };
    let r = run.output.limit().unwrap();
    assert_eq!(run.solver.method, request::default_method(3));
    assert_eq!(
        r.solver.method,
        request::default_method(3),
        "{:?}",
        r.solver.tried
    );
    assert!((r.load_multiplier.unwrap() - 0.4346).abs() < 5e-5);
    assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
}

#[test]
fn issue29_item2_dome_4x8_safety_without_ranges_with_the_default_method() {
    // The issue's first failing command: `gen dome --courses 4 --segments 8`, `safety
    // --no-reactions` ("HiGHS run failed: Error" under the former 3D default), through the
    // request layer as the CLI runs it.
    let d = dome(&DomeSpec {
        courses: 4,
        segments: 8,
        ..DomeSpec::default()
    })
    .unwrap();
    let req = request(
        Analysis::Safety(SafetyRequest {
            no_ranges: true,
            ..SafetyRequest::default()
        }),
        None,
    );
    let AnyResult::Spatial(run) = request::run(&AnyModel::Spatial(d.clone()), &req).unwrap() else {
        panic!("a 3D model gives a 3D result")
    };
    let default = run.output.safety().unwrap();
    // The reference: the dual simplex, whose vertices are exact.
    let st = Structure3d::new(&d, BuildOptions::default()).unwrap();
    let exact = safety(
        &st,
        &SafetyOptions {
            reactions: false,
            ..SafetyOptions::default()
        },
    )
    .unwrap();
    assert!(default.stands && exact.stands);
    let (f, g) = (
        default.least_joint_fraction.unwrap(),
        exact.least_joint_fraction.unwrap(),
    );
    // Both bisections end within their tolerance (1e-6) of the same fraction.
    assert!((f - g).abs() <= 2e-6, "{f} against the dual simplex's {g}");
    // The result states the method that answered its programs.
    assert_eq!(
        default.solver.method,
        request::default_method(3),
        "{:?}",
        default.solver.tried
    );
}

#[test]
fn issue29_item2_vault_limit_with_ipm_no_crossover_falls_back_and_says_so() {
    // `limit --method ipm-no-crossover` on the README's vault ended "status Unknown": now
    // the next method of the chain answers, certified, at the 2D arch's λ (0.4346), and the
    // result names it and what failed before it.
    let req = request(
        Analysis::Limit(LimitRequest::default()),
        Some(Method::IpmNoCrossover),
    );
    let AnyResult::Spatial(run) = request::run(&AnyModel::Spatial(readme_vault()), &req).unwrap()
    else {
        panic!("a 3D model gives a 3D result")
    };
    let r = run.output.limit().unwrap();
    let l = r.load_multiplier.unwrap();
    assert!((l - 0.4346).abs() < 5e-5, "{l}");
    assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
    assert_ne!(r.solver.method, Method::IpmNoCrossover);
    assert!(
        r.solver.tried[0].starts_with("ipm-no-crossover:"),
        "{:?}",
        r.solver.tried
    );
    assert!(
        r.message.contains(&format!(
            "solved by {} after ipm-no-crossover",
            r.solver.method.name()
        )),
        "{}",
        r.message
    );
    let json = serde_json::to_value(r).unwrap();
    assert_eq!(json["solver"]["method"], r.solver.method.name());
    assert!(json["solver"]["tried"][0]
        .as_str()
        .unwrap()
        .starts_with("ipm-no-crossover:"));
}

#[test]
fn issue29_item2_a_forced_failure_of_the_default_method_is_answered_by_the_next() {
    // The default method of the vault (the policy's) with an iteration limit of 1 fails; the
    // next method of its chain answers with the certified λ and says so.
    let st = Structure3d::new(&readme_vault(), BuildOptions::default()).unwrap();
    let class = class_of(&st, Purpose::Optimise);
    let forced = policy::options(
        &class,
        None,
        &SolverOptions {
            iteration_limit: Some(1),
            ..SolverOptions::default()
        },
    );
    let m = default_method(&class);
    assert_eq!(forced.method, m);
    let r = limit(&st, &forced).unwrap();
    let l = r.load_multiplier.unwrap();
    assert!((l - 0.4346).abs() < 5e-5, "{l}");
    assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
    assert_ne!(r.solver.method, m);
    assert!(fallback_chain(m)[1..].contains(&r.solver.method));
    assert!(
        r.solver.tried[0].starts_with(&format!("{}:", m.name())),
        "{:?}",
        r.solver.tried
    );
    assert!(
        r.message
            .contains(&format!("solved by {}", r.solver.method.name())),
        "{}",
        r.message
    );
}

#[test]
#[ignore = "passes, measured in session 16: 609 CPU s (1,881 s wall at load 2-9), most of it the dual-simplex reference; too long for CI (run with --ignored)"]
fn issue29_item2_friction_wall_settle_with_primal_simplex_falls_back() {
    // `settle --method primal-simplex --friction 0.6 --raw` on a 60 × 30 wall (1 × 0.5 m
    // units), the left 30 % of the base settling 1 cm: HiGHS's primal simplex stops with "Solve
    // error"; the next method of its chain (the interior point with crossover since session
    // 16) answers, certified, with the work of an independent solve by the dual simplex.
    let mut m = wall(&WallSpec {
        courses: 30,
        units: 60,
        unit: [1.0, 0.5],
        ..WallSpec::default()
    })
    .unwrap();
    for s in m.supports.iter_mut().take(18) {
        s.motion = [0.0, -0.01, 0.0];
    }
    let settle = |method| {
        let mut req = request(
            Analysis::Settle(SettleRequest {
                raw: true,
                ..SettleRequest::default()
            }),
            Some(method),
        );
        req.model.friction = Some(0.6);
        match request::run(&AnyModel::Planar(m.clone()), &req).unwrap() {
            AnyResult::Planar(run) => run.output.settlement().unwrap().clone(),
            AnyResult::Spatial(_) => panic!("a 2D model gives a 2D result"),
        }
    };
    let r = settle(Method::PrimalSimplex);
    assert_eq!(r.status, SettlementStatus::Mechanism, "{}", r.message);
    assert!(r.certificate.as_ref().unwrap().ok, "{}", r.message);
    // The reference: the same settlement by the dual simplex.
    let reference = settle(Method::DualSimplex);
    let (w, wref) = (
        r.work_dead_loads.unwrap(),
        reference.work_dead_loads.unwrap(),
    );
    assert!((w - wref).abs() <= 1e-6 * wref.abs(), "{w} against {wref}");
    if r.solver.method != Method::PrimalSimplex {
        assert!(r.message.contains("after primal-simplex"), "{}", r.message);
        assert!(r.solver.tried[0].starts_with("primal-simplex:"));
    }
}
