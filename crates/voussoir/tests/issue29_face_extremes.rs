//! Issue 29 (session 21): the least-crack face's maximum of the generic functional is not
//! solved where the stage-2 vertex, a point of that face, already lies above its minimum by
//! more than the point tolerance (the face is then not a point; `canonical_mechanism`). The
//! shortcut's mechanism is checked against the selection that solves both extremes from
//! scratch (`CanonicalOptions::both_extremes`, the path before session 21), and that it was
//! taken by the count of the selection's solves (one program fewer).

mod support;
use support::settle_right_half;
use voussoir::analysis::canonical::{
    limit_canonical, settle_canonical, CanonicalMechanism, CanonicalOptions, Selection,
};
use voussoir::analysis::settlement::SettlementForm;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::generate_facade::{bondeno, facade, FacadeMesh, FacadeSpec};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure};

fn options(both_extremes: bool) -> CanonicalOptions {
    CanonicalOptions {
        forces: false,
        reaction_ranges: false,
        both_extremes,
        ..CanonicalOptions::default()
    }
}

/// Everything the selection reports but its count of solves.
fn same_selection(a: &CanonicalMechanism, b: &CanonicalMechanism) {
    assert_eq!(a.unique, b.unique);
    assert_eq!(a.selected_by, b.selected_by);
    assert_eq!(a.changed, b.changed);
    let rel = (a.crack_area - b.crack_area).abs() / b.crack_area.abs().max(1e-300);
    assert!(
        rel <= 1e-12,
        "crack areas {} vs {}",
        a.crack_area,
        b.crack_area
    );
}

#[test]
fn full_span_arch_generic_vertex_without_the_maximum() {
    // tests/canonical.rs: the paper's arch under a full-span live load has a segment of optimal
    // mechanisms of equal crack area (the least-crack face is that segment); the tie-break
    // reports one of its four-hinge ends.
    let st = Structure::new(
        &arch(&ArchSpec {
            live: LiveLoad::Full,
            ..ArchSpec::default()
        })
        .unwrap(),
        BuildOptions::default(),
    )
    .unwrap();
    let o = SolverOptions::default();
    let new = limit_canonical(&st, &o, 16, &options(false)).unwrap();
    let old = limit_canonical(&st, &o, 16, &options(true)).unwrap();
    let (cn, co) = (
        &new.canonical.as_ref().unwrap().mechanism,
        &old.canonical.as_ref().unwrap().mechanism,
    );
    assert_eq!(co.selected_by, Selection::GenericVertex);
    same_selection(cn, co);
    assert_eq!(cn.solves + 1, co.solves, "new {cn:?}, old {co:?}");
    assert_eq!(new.load_multiplier, old.load_multiplier);
    assert_eq!(new.hinges, old.hinges);
    assert_eq!(new.blocks, old.blocks);
    let joints: Vec<usize> = new.hinges.iter().map(|h| h.joint).collect();
    assert_eq!(joints.len(), 4, "{joints:?}");
}

#[test]
fn settled_facade_generic_vertex_without_the_maximum() {
    // The README's façade (`bondeno`) at 1 m (716 blocks), settling by 0.2 m under
    // x ∈ [11, 22] m (as the 0.5 m façade of docs/performance.md, session 21, whose maximum
    // this saves 5 CPU s; at 2 m the least-crack face is a point).
    let m = facade(&FacadeSpec {
        live: LiveLoad::Horizontal,
        ..bondeno(1.0, FacadeMesh::Grid)
    })
    .unwrap();
    let st = settle_right_half(m);
    let o = SolverOptions::default();
    let new = settle_canonical(&st, &o, SettlementForm::Both, &options(false)).unwrap();
    let old = settle_canonical(&st, &o, SettlementForm::Both, &options(true)).unwrap();
    let (cn, co) = (
        &new.canonical.as_ref().unwrap().mechanism,
        &old.canonical.as_ref().unwrap().mechanism,
    );
    assert_eq!(co.selected_by, Selection::GenericVertex);
    same_selection(cn, co);
    assert_eq!(cn.solves + 1, co.solves);
    assert_eq!(new.hinges, old.hinges);
    assert_eq!(new.blocks, old.blocks);
    assert_eq!(new.work_dead_loads, old.work_dead_loads);
}

#[test]
#[ignore = "0.5 m grid facade (2,654 blocks): both selections 88.6 CPU s (session 21, load 2-4)"]
fn grid_facade_tilt_maximum_by_the_interior_point_directly() {
    // docs/performance.md, "Tilt and the least-crack face's extremes (session 21)": the
    // stage-2 vertex is at the minimum (8.3e-12 above it, point tolerance 5.2e-10), the face
    // is a point, and its maximum goes to HiGHS's interior point straight away (7,962 degrees
    // of freedom) instead of after the dual simplex's uncertified answer: one solve fewer.
    use voussoir::analysis::tilt::tilt_along_canonical;
    let st = Structure::new(
        &facade(&FacadeSpec {
            live: LiveLoad::None,
            ..bondeno(0.5, FacadeMesh::Grid)
        })
        .unwrap(),
        BuildOptions::default(),
    )
    .unwrap();
    // The CLI's method for this size (HiGHS's interior point with crossover).
    let o = voussoir::lp::policy::options_for(&st, &SolverOptions::default(), false);
    let (a_new, new) = tilt_along_canonical(&st, [1.0, 0.0], &o, &options(false)).unwrap();
    let (a_old, old) = tilt_along_canonical(&st, [1.0, 0.0], &o, &options(true)).unwrap();
    let (cn, co) = (
        &new.canonical.as_ref().unwrap().mechanism,
        &old.canonical.as_ref().unwrap().mechanism,
    );
    // The benchmark's answer (session 19): 43.466713°, least crack area, 52 hinges.
    let a = a_new.unwrap();
    assert!((a - 43.466713).abs() <= 1e-6, "{a}");
    assert_eq!(a_new, a_old);
    assert_eq!(co.selected_by, Selection::LeastCrackArea);
    same_selection(cn, co);
    assert_eq!(cn.solves + 1, co.solves, "new {cn:?}, old {co:?}");
    assert_eq!(new.hinges.len(), 52);
    assert_eq!(new.hinges, old.hinges);
    assert_eq!(new.blocks, old.blocks);
}
