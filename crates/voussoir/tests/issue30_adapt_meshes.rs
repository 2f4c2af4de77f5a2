//! Issue 30, the first must-show on a model small enough for a test: `settle --adapt` from a
//! grid and from triangles of the same wall. The wall is the door panel of docs/cracks.md
//! (`gen facade --width 6 --height 4 --gable 0 --element 0.5 --opening rect:2.5,0,3.5,2.2
//! --segments 12 [--mesh triangles]`, `settle --profile uniform:3,6,-0.02 --adapt`), the
//! final analysis the default one (the canonical selection of docs/canonical.md), as the CLI
//! runs it.
//!
//! The reference, by hand (no tension, no sliding, γ = 18 kN/m³, 1 m thick, δ = 2 cm): the
//! right pier x ∈ [3.5, 6], y ∈ [0, 2.2] stands on the settling foundation and goes down with
//! it (δ·A = 0.02 × 5.5 m²); the wall above the door and the pier, x ∈ [2.5, 6], y ∈ [2.2, 4],
//! cracks along x = 2.5 up from the door's top-left corner and rotates about that corner, its
//! far end following the pier down (rotation δ/3.5): the work of its weight is
//! γ·δ/3.5·∫(x − 2.5) dA = γ·δ/3.5 × 6.3 × 1.75. In all
//! W = 18 × 0.02 × (5.5 + 6.3 × 1.75 / 3.5) = 3.114 kN·m, with the widest crack from the door's
//! top-left corner (2.5, 2.2) to the top. A mechanism of more pieces can do more work; the
//! grid (whose lines include x = 2.5) finds exactly this one.

use std::sync::OnceLock;
use voussoir::analysis::adapt::{hausdorff_polylines, settle_adapt, AdaptOptions};
use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions};
use voussoir::analysis::settlement::{settle, SettlementForm};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh, Opening};
use voussoir::lp::SolverOptions;
use voussoir::model::{Model, Point};
use voussoir::result::cracks::Crack;
use voussoir::settlement_input::{apply_profile, Profile};
use voussoir::{BuildOptions, Structure};

/// The hand mechanism's work (module docs), kN·m.
const HAND_WORK: f64 = 18.0 * 0.02 * (5.5 + 6.3 * 1.75 / 3.5);
/// The door's top-left corner, where the hand mechanism's crack starts.
const CORNER: Point = [2.5, 2.2];
/// The element length of both meshes (m).
const ELEMENT: f64 = 0.5;

/// The door panel meshed with `mesh`, the foundation under x ∈ [3, 6] settling 2 cm.
fn door_panel(mesh: FacadeMesh) -> Model {
    let mut s = bondeno(ELEMENT, mesh);
    s.width = 6.0;
    s.height = 4.0;
    s.gable = 0.0;
    s.segments = 12;
    s.openings = vec![Opening::Rect {
        x0: 2.5,
        y0: 0.0,
        x1: 3.5,
        y1: 2.2,
    }];
    let mut m = facade(&s).unwrap();
    apply_profile(
        &mut m,
        &Profile::Uniform {
            x0: 3.0,
            x1: 6.0,
            v: -0.02,
        },
    )
    .unwrap();
    m
}

/// What a run gives: the unadapted work (certified), the adapted work (certified, canonical
/// final analysis) and the adapted result's cracks.
struct Run {
    unadapted: f64,
    adapted: f64,
    cracks: Vec<Crack>,
}

fn run(mesh: FacadeMesh) -> Run {
    let m = door_panel(mesh);
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let r0 = settle(&st, &SolverOptions::default()).unwrap();
    assert!(r0.certificate.as_ref().is_some_and(|c| c.ok));
    let ad = settle_adapt(
        &m,
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
    Run {
        unadapted: r0.work_dead_loads.unwrap(),
        adapted: w,
        cracks: r.cracks,
    }
}

/// The two runs, from the grid and from triangles, made once for both tests below (they are
/// deterministic, and each test made both: 67 and 61 s of wall at load 4 in session 23, each
/// about the time of one pair). The second test to ask waits for the first's.
fn runs() -> &'static (Run, Run) {
    static RUNS: OnceLock<(Run, Run)> = OnceLock::new();
    RUNS.get_or_init(|| (run(FacadeMesh::Grid), run(FacadeMesh::Triangles)))
}

fn widest(c: &[Crack]) -> &Crack {
    c.iter()
        .max_by(|a, b| a.max_opening.total_cmp(&b.max_opening))
        .unwrap()
}

fn longest(c: &[Crack]) -> &Crack {
    c.iter()
        .max_by(|a, b| a.length.total_cmp(&b.length))
        .unwrap()
}

fn dist(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The door's crack from its corner: adapted from the grid and from triangles, each at least
/// its unadapted work and the hand mechanism's, and the widest crack of each from the door's
/// top-left corner to the top, the two within one element of each other. Measured (global
/// stage, then the local one): grid 3.1140 → 3.3384, triangles 3.1937 → 3.3618 kN·m; the
/// widest cracks (2.5, 4) → (2.5, 2.2), 14.8 mm, and (2.52, 4) → (2.5, 2.2), 14.2 mm: 0.018 m
/// apart (Hausdorff); without the global stage 3.2339 and 3.3473, 0.41 m apart. About 27 s of
/// CPU in a release build.
#[test]
fn issue30_adapt_meshes_door_crack_from_the_corner_from_grid_and_triangles() {
    // The hand value is the grid's own unadapted optimum: its mechanism is the one above.
    assert!((HAND_WORK - 3.114).abs() < 1e-12);
    let (grid, tri) = runs();
    assert!((grid.unadapted - HAND_WORK).abs() <= 1e-6 * HAND_WORK);
    for (name, r) in [("grid", grid), ("triangles", tri)] {
        // A cut only adds freedom and a move is kept only when it gains: never below the
        // unadapted mesh, nor (the grid's optimum being the hand mechanism) below the hand
        // value.
        assert!(
            r.adapted >= r.unadapted * (1.0 - 1e-7) && r.adapted >= HAND_WORK * (1.0 - 1e-7),
            "{name}: adapted {} unadapted {} hand {HAND_WORK}",
            r.adapted,
            r.unadapted
        );
        // The widest crack runs from the door's corner (an end on it, to the joint
        // detection's tolerance) to the top of the wall (y = 4).
        let c = widest(&r.cracks);
        let (a, b) = (c.points[0], *c.points.last().unwrap());
        let (at_corner, other) = if dist(a, CORNER) < dist(b, CORNER) {
            (a, b)
        } else {
            (b, a)
        };
        assert!(
            dist(at_corner, CORNER) < 1e-6 && (other[1] - 4.0).abs() < 1e-6,
            "{name}: widest crack {:?}",
            c.points
        );
    }
    let d = hausdorff_polylines(&widest(&grid.cracks).points, &widest(&tri.cracks).points);
    assert!(d <= ELEMENT, "widest cracks {d} m apart");
}

/// The must-show's own criteria on the door panel: works within 2 % of each other and the
/// longest crack polylines within 1 m. With the local search alone the two meshes ended on
/// different local optima, grid 3.2339 and triangles 3.3473 kN·m (3.4 % apart), their longest
/// polylines 3.13 m apart; with the global stage before it (docs/cracks.md, "The global
/// stage"): grid 3.3384 and triangles 3.3618 kN·m (0.70 % apart), the longest polylines 0.52 m
/// apart (Hausdorff).
#[test]
fn issue30_adapt_meshes_door_works_within_2_percent_and_longest_cracks_within_1_m() {
    let (grid, tri) = runs();
    let (g, t) = (grid.adapted, tri.adapted);
    assert!((g - t).abs() <= 0.02 * g.max(t), "grid {g}, triangles {t}");
    let d = hausdorff_polylines(&longest(&grid.cracks).points, &longest(&tri.cracks).points);
    assert!(d <= 1.0, "longest cracks {d} m apart");
}
