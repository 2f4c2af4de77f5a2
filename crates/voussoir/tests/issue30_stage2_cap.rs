//! Regression (session 17, issue 30's façade must-show): the canonical final analysis of the
//! 0.5 m façade in triangles adapted by `settle --adapt` (4,637 blocks) stalled in stage 2 of
//! the mechanism selection — the least crack area on the optimal face, a primal simplex
//! warm-started from the optimal vertex, ran for more than 25 minutes on 28,901 rows. The warm
//! primal simplex of stage 2 is now capped (`CanonicalOptions::stage2_pivots`) and the solver
//! layer's fallback chain answers beyond the cap. Here the cap is forced down to 1 pivot on the
//! paper's façade at 1.0 m (716 blocks, a face of optima: the selection changes the mechanism):
//! the fallback reaches the same least crack area and the same canonical mechanism as the
//! uncapped warm simplex (the reference: a different method on the same program).

mod support;
use support::settle_right_half;
use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions, STAGE2_PIVOTS};
use voussoir::analysis::settlement::SettlementForm;
use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
use voussoir::lp::{collecting, SolverOptions};

#[test]
fn issue30_stage2_beyond_its_pivot_cap_the_fallback_gives_the_same_canonical_mechanism() {
    let m = facade(&bondeno(1.0, FacadeMesh::Grid)).unwrap();
    let st = settle_right_half(m);
    let base = CanonicalOptions {
        reaction_ranges: false,
        forces: false,
        ..CanonicalOptions::default()
    };
    assert_eq!(base.stage2_pivots, STAGE2_PIVOTS);
    let run = |copts: &CanonicalOptions| {
        collecting(|| {
            settle_canonical(&st, &SolverOptions::default(), SettlementForm::Both, copts).unwrap()
        })
    };
    let (free, free_solves) = run(&base);
    let (capped, capped_solves) = run(&CanonicalOptions {
        stage2_pivots: 1,
        ..base
    });
    // The uncapped run needs no fallback; the capped one reaches the cap in stage 2 and the
    // next method of the chain answers.
    let fell_back = |solves: &[voussoir::lp::SolveRecord]| {
        solves
            .iter()
            .any(|s| s.tried.iter().any(|t| t.starts_with("primal-simplex:")))
    };
    assert!(!fell_back(&free_solves), "{free_solves:?}");
    assert!(fell_back(&capped_solves), "{capped_solves:?}");
    // The paper's façade at 1.0 m: 361.68 kN·m (docs/cracks.md), the same in both.
    let (w1, w2) = (
        free.work_dead_loads.unwrap(),
        capped.work_dead_loads.unwrap(),
    );
    assert!((w1 - 361.68).abs() < 0.005, "{w1}");
    // (Held on the optimal face to 1e-9 relative, the selection's tolerance: 1.0e-9 measured.)
    assert!((w2 - w1).abs() <= 1e-8 * w1, "{w2} vs {w1}");
    let (c1, c2) = (
        &free.canonical.as_ref().unwrap().mechanism,
        &capped.canonical.as_ref().unwrap().mechanism,
    );
    assert!(c1.changed, "the test needs a face of optima: {c1:?}");
    assert!(
        (c1.crack_area - c2.crack_area).abs() <= 1e-7 * c1.crack_area,
        "{c1:?} vs {c2:?}"
    );
    assert_eq!(c1.selected_by, c2.selected_by);
    // The same mechanism: every block's motion (u, v in m, θ in rad) within 1e-6 of the
    // settlement (0.2 m; the selection's own point tolerance).
    assert_eq!(free.blocks.len(), capped.blocks.len());
    for (a, b) in free.blocks.iter().zip(&capped.blocks) {
        let (p, q) = (&a.motion, &b.motion);
        let d = (p.u - q.u)
            .abs()
            .max((p.v - q.v).abs())
            .max((p.theta - q.theta).abs());
        assert!(d <= 1e-6 * 0.2, "block {}: {p:?} vs {q:?}", a.id);
    }
}
