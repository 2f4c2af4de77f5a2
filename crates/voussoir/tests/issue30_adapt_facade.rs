//! Issue 30, item 2, the must-shows on the paper's façade (`gen facade`, the right half
//! settling 20 cm: `settle --profile uniform:11,22,-0.2`), and the Hausdorff distance used to
//! compare crack polylines.
//!
//! The façade runs solve LPs of thousands of blocks; those that take more than a few minutes
//! in a release build are `#[ignore]`d with their measured time, and their numbers are in
//! docs/cracks.md ("The paper's façade: adapted").

mod support;
use support::right_half_down;
use voussoir::analysis::adapt::{hausdorff_polylines, settle_adapt, AdaptOptions};
use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions};
use voussoir::analysis::settlement::{settle, SettlementForm};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh};
use voussoir::lp::SolverOptions;
use voussoir::model::{Model, Point};
use voussoir::{BuildOptions, Structure};

/// The Hausdorff distance by hand: two segments, a V and its chord, a point and a segment.
#[test]
fn issue30_item2_hausdorff_distance_of_polylines_by_hand() {
    // Two parallel segments 1 m apart, the second 2 m longer to the right: from its right
    // end (5, 1) the nearest point of the first is its end (3, 0), √(2² + 1²) = √5 away;
    // every point of the first is 1 m from the second.
    let a = [[0.0, 0.0], [3.0, 0.0]];
    let b = [[0.0, 1.0], [5.0, 1.0]];
    assert!((hausdorff_polylines(&a, &b) - 5f64.sqrt()).abs() < 1e-8);
    assert_eq!(hausdorff_polylines(&a, &b), hausdorff_polylines(&b, &a));
    // A V of apex (2, 2) over its chord from (0, 0) to (4, 0): both ends of the chord lie on
    // the V, but the chord's middle (2, 0) is √2 from it (nearest points (1, 1) and (3, 1)),
    // a distance reached inside a segment, not at a vertex; the V's apex is 2 from the chord.
    // The Hausdorff distance is the larger, 2.
    let v = [[0.0, 0.0], [2.0, 2.0], [4.0, 0.0]];
    let chord = [[0.0, 0.0], [4.0, 0.0]];
    assert!((hausdorff_polylines(&chord, &v) - 2.0).abs() < 1e-8);
    // Lower the apex to (2, 0.5): the apex is 0.5 from the chord; from the chord's middle
    // (2, 0) the side from (0, 0) to (2, 0.5) is |2·0 − 0.5·2|/√(2² + 0.5²) = 1/√4.25 ≈ 0.485
    // away (its foot inside the side), less: the distance is the apex's, 0.5.
    let flat = [[0.0, 0.0], [2.0, 0.5], [4.0, 0.0]];
    assert!((hausdorff_polylines(&chord, &flat) - 0.5).abs() < 1e-8);
    // The same polyline traversed backwards: 0.
    let back: Vec<Point> = v.iter().rev().copied().collect();
    assert!(hausdorff_polylines(&v, &back) < 1e-12);
    // A point against a segment: its distance to the segment's far end, √(4² + 1²).
    assert!((hausdorff_polylines(&[[0.0, 1.0]], &chord) - 17f64.sqrt()).abs() < 1e-12);
    // An empty polyline is infinitely far.
    assert!(hausdorff_polylines(&[], &chord).is_infinite());
}

/// The façade meshed with `element` (m) and `mesh`, the right half settling 20 cm.
fn settling_facade(element: f64, mesh: FacadeMesh) -> Model {
    right_half_down(facade(&bondeno(element, mesh)).unwrap())
}

/// The work of the dead loads (the solver's own vertex, certified) and the longest crack.
fn solve(m: &Model) -> (f64, Vec<Point>) {
    let st = Structure::new(m, BuildOptions::default()).unwrap();
    solve_structure(&st)
}

fn solve_structure(st: &Structure) -> (f64, Vec<Point>) {
    let r = settle(st, &SolverOptions::default()).unwrap();
    assert!(r.certificate.as_ref().is_some_and(|c| c.ok));
    let longest = r
        .cracks
        .iter()
        .max_by(|a, b| a.length.total_cmp(&b.length))
        .map(|c| c.points.clone())
        .unwrap_or_default();
    (r.work_dead_loads.unwrap(), longest)
}

/// Adapted with the default settings: the work of the adapted mesh (certified) and its longest
/// crack; the iterations' works never decrease and are all certified.
fn adapted(m: &Model) -> (f64, Vec<Point>) {
    let ad = settle_adapt(
        m,
        BuildOptions::default(),
        &SolverOptions::default(),
        &AdaptOptions::default(),
    )
    .unwrap();
    let its = &ad.record.iterations;
    for w in its.windows(2) {
        assert!(w[1].value >= w[0].value * (1.0 - 1e-7), "{its:?}");
    }
    assert!(its.iter().all(|i| i.certified), "{its:?}");
    let (w, longest) = solve_structure(&ad.structure);
    assert!((w - its.last().unwrap().value).abs() <= 1e-7 * w);
    (w, longest)
}

/// Convergence: the adapted 1.0 m grid reaches the 0.25 m grid's work within 2 % (or goes
/// beyond it). The time (10× less) is measured, not asserted: docs/cracks.md.
#[test]
#[ignore = "the 0.25 m grid's solve alone takes 136 s of CPU (release, load 1-2 on 2 cores)"]
fn issue30_item2_facade_adapted_coarse_grid_reaches_the_finest_grid() {
    let (fine, _) = solve(&settling_facade(0.25, FacadeMesh::Grid));
    let coarse = settling_facade(1.0, FacadeMesh::Grid);
    let (w0, _) = solve(&coarse);
    let (w, _) = adapted(&coarse);
    assert!(w >= w0 * (1.0 - 1e-7), "adapted {w} below unadapted {w0}");
    assert!(
        w >= 0.98 * fine,
        "adapted 1.0 m grid {w} vs 0.25 m grid {fine}"
    );
}

/// The adapted 1.0 m grid against the 0.5 m grid solved here (the reference: the same wall
/// meshed twice as fine): it goes beyond it. And the regression of this session's speed
/// defect: every iteration moves only its new lines, so its search solves stay at most
/// `1 + 2·evaluations·lines_per_iteration` (they grew with all the lines before: 31, 61, 91,
/// 121 on this façade, and the run did not finish in a session). The local search alone (no
/// global stage), as the convergence of docs/cracks.md was measured: about 45 s of CPU in a
/// release build (with the global stage, added later and tested in `issue30_adapt_global.rs`,
/// this test took 114 s of CI's time).
#[test]
fn issue30_item2_facade_adapted_1m_grid_passes_the_half_metre_grid() {
    let (half, _) = solve(&settling_facade(0.5, FacadeMesh::Grid));
    let coarse = settling_facade(1.0, FacadeMesh::Grid);
    let (w0, _) = solve(&coarse);
    let o = AdaptOptions {
        global_lines: 0,
        ..AdaptOptions::default()
    };
    let ad = settle_adapt(
        &coarse,
        BuildOptions::default(),
        &SolverOptions::default(),
        &o,
    )
    .unwrap();
    let its = &ad.record.iterations;
    assert!((its[0].value - w0).abs() <= 1e-9 * w0);
    // The local iterations.
    for it in &its[1..] {
        assert!(!it.global, "{its:?}");
        assert!(
            it.evaluations <= 1 + 2 * o.evaluations * o.lines_per_iteration,
            "{its:?}"
        );
        assert!(it.certified, "{its:?}");
    }
    for w in its.windows(2) {
        assert!(w[1].value >= w[0].value * (1.0 - 1e-7), "{its:?}");
    }
    let w = its.last().unwrap().value;
    assert!(its.len() >= 2, "{its:?}");
    // The unadapted coarse grid is 2.2 % below the half-metre grid; the adapted one above it.
    assert!(
        w0 < half && w > half,
        "adapted {w}, unadapted {w0}, 0.5 m grid {half}"
    );
}

/// Regression (this session): the adaptation stopped as converged after one iteration whose
/// change was below the tolerance, although the next iteration's new lines raised the work by
/// 3.3 % (the 0.5 m grid: 369.66, 370.96 (+0.35 %), 383.10, 384.60, 384.93 kN·m). Converged
/// now takes two small iterations in a row.
#[test]
#[ignore = "238 s of CPU in a release build (load 9 on 2 cores: 26 min wall)"]
fn issue30_item2_adapt_does_not_stop_after_one_small_step() {
    let m = settling_facade(0.5, FacadeMesh::Grid);
    let (w0, _) = solve(&m);
    let o = AdaptOptions::default();
    let ad = settle_adapt(&m, BuildOptions::default(), &SolverOptions::default(), &o).unwrap();
    let its = &ad.record.iterations;
    let change = (its[1].value - its[0].value) / its[1].value;
    assert!(change < o.tolerance, "{its:?}");
    assert!(its.len() > 2, "stopped after one small step: {its:?}");
    assert!(its.last().unwrap().value > 1.03 * w0, "{its:?}");
}

/// The final analysis of an adapted model as `settle --adapt` runs it by default (the canonical
/// selection of docs/canonical.md; reaction ranges are not computed beyond 500 blocks anyway):
/// its work (certified) and its longest crack polyline.
fn adapted_canonical(m: &Model) -> (f64, Vec<Point>) {
    let ad = settle_adapt(
        m,
        BuildOptions::default(),
        &SolverOptions::default(),
        &AdaptOptions::default(),
    )
    .unwrap();
    let its = &ad.record.iterations;
    assert!(its.iter().all(|i| i.certified), "{its:?}");
    let r = settle_canonical(
        &ad.structure,
        &SolverOptions::default(),
        SettlementForm::Both,
        &CanonicalOptions {
            reaction_ranges: false,
            ..CanonicalOptions::default()
        },
    )
    .unwrap();
    assert!(r.certificate.as_ref().is_some_and(|c| c.ok));
    let w = r.work_dead_loads.unwrap();
    assert!((w - its.last().unwrap().value).abs() <= 1e-7 * w);
    let longest = r
        .cracks
        .iter()
        .max_by(|a, b| a.length.total_cmp(&b.length))
        .map(|c| c.points.clone())
        .unwrap_or_default();
    (w, longest)
}

/// The must-show (issue 30): the façade at 0.5 m adapted from the grid and from triangles
/// (`settle --adapt`, default settings, canonical final analysis): works within 2 % of each
/// other and neither below either unadapted mesh (grid 369.66, triangles 384.71 kN·m), and
/// their longest crack polylines within 1 m of each other (Hausdorff). Measured (session 17,
/// docs/cracks.md): grid 418.30, triangles 425.12 kN·m, 1.61 % apart, both above both
/// unadapted works: met; the longest polylines 3.82 m apart: not met (the triangles' longest
/// is a 3.4 mm hairline chain through the pieces over the rose window; the main cracks
/// match within 0.51–0.61 m).
#[test]
#[ignore = "measured 669 + 959 s of CPU for the two adaptations (CLI, load 9-16 on 2 cores); fails on the Hausdorff clause: longest polylines 3.82 m apart (works 1.61 % apart: met)"]
fn issue30_item2_facade_adapted_from_grid_and_triangles_must_show() {
    let grid = settling_facade(0.5, FacadeMesh::Grid);
    let tri = settling_facade(0.5, FacadeMesh::Triangles);
    let (g0, _) = solve(&grid);
    let (t0, _) = solve(&tri);
    assert!(
        (g0 - 369.66).abs() < 0.005 && (t0 - 384.71).abs() < 0.005,
        "{g0} {t0}"
    );
    let (g, gl) = adapted_canonical(&grid);
    let (t, tl) = adapted_canonical(&tri);
    assert!((g - t).abs() <= 0.02 * g.max(t), "grid {g}, triangles {t}");
    assert!(
        g.min(t) >= g0.max(t0) * (1.0 - 1e-7),
        "{g} {t} vs {g0} {t0}"
    );
    let h = hausdorff_polylines(&gl, &tl);
    assert!(h <= 1.0, "longest cracks {h} m apart: {gl:?} vs {tl:?}");
}
