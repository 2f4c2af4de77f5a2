//! Issue 29 item 6 (session 25): the least load multiplier of a 2D limit analysis as the mirror
//! image of the largest multiplier's optimum, where the structure and its dead loads are
//! symmetric about a vertical line and the live load is mirrored onto minus itself (a
//! horizontal load: the tilting table). The image is certified on the least multiplier's own
//! program (`safety::least_by_mirror`, called from `limit::solve_limit_checked`); otherwise the
//! program is solved as before. On the 0.5 m grid façade's `tilt` the least multiplier's
//! program took about 6 CPU s.
//!
//! The reference everywhere is the least multiplier's program itself (the limit program
//! minimised, twins and all) solved from scratch by the dual simplex: a different method.
//! Times: docs/performance.md, "Façade tilt, safety and capacity (session 25)".

mod support;
use support::{
    dual_simplex_and_ipm, facade_grid, least_multiplier_from_scratch,
    tilt_least_is_the_mirror_image,
};
use voussoir::analysis::limit::limit;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::{BuildOptions, Structure};

fn paper_arch(live: LiveLoad) -> Structure {
    let m = arch(&ArchSpec {
        live,
        ..ArchSpec::default()
    })
    .unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn issue29_session25_least_multiplier_of_a_symmetric_tilt_is_the_mirror_image() {
    // The paper's arch under horizontal loads equal to its voussoirs' weights (the tilting
    // table), by the 2D default (dual simplex) and by HiGHS's interior point (the CLI's).
    let st = paper_arch(LiveLoad::Horizontal);
    let reference = least_multiplier_from_scratch(&st);
    for o in dual_simplex_and_ipm() {
        let r = limit(&st, &o).unwrap();
        let (hi, lo) = (r.load_multiplier.unwrap(), r.least_load_multiplier.unwrap());
        println!(
            "{:?}: λ_max {hi}, λ_min {lo}, from scratch {reference}",
            o.method
        );
        // The arch tilts by 0.370082° (the realistic benchmark's cell): λ_max = tan of it (to its printed digits).
        assert!((hi.atan().to_degrees() - 0.370082).abs() <= 1e-6, "{hi}");
        // The image of the largest multiplier's optimum: exactly −λ_max (a program solved
        // would agree only to its tolerance).
        assert_eq!(lo, -hi);
        assert!((lo - reference).abs() <= 1e-9 * hi, "{lo} {reference}");
    }
    // The 2.0 m grid façade (223 blocks, 44 supports) on the tilting table both ways.
    tilt_least_is_the_mirror_image(&facade_grid(2.0), "grid façade", 1e-9);
}

#[test]
fn issue29_session25_no_mirror_where_the_live_load_is_not_flipped() {
    // The same symmetric arch under a vertical live load on the whole span (its own mirror
    // image: λ keeps its sign) and on the left half (not symmetric): the least multiplier is
    // its program's, not −λ_max.
    for live in [LiveLoad::Full, LiveLoad::Left] {
        let st = paper_arch(live);
        let reference = least_multiplier_from_scratch(&st);
        for o in dual_simplex_and_ipm() {
            let r = limit(&st, &o).unwrap();
            let hi = r.load_multiplier.unwrap();
            let lo = r.least_load_multiplier.unwrap();
            println!(
                "{live:?} {:?}: λ_max {hi}, λ_min {lo}, from scratch {reference}",
                o.method
            );
            assert!(
                (lo - reference).abs() <= 1e-9 * hi.abs().max(reference.abs()),
                "{lo}"
            );
            // −λ_max would be wrong here by far.
            assert!((lo + hi).abs() > 1e-3 * hi, "{lo} {hi}");
        }
    }
}
