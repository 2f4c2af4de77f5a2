//! Issue 29 item 6 (session 29): a 2D structure's `safety` asks Clarabel whether it stands at
//! f = 0 (every joint shrunk to its centre, on the merged program) as soon as f = 1 stands,
//! before the bisection's decision at 1/2 (`safety::FIRST_ZERO_2D`; 3D keeps asking after 1/2).
//! A structure that stands at 0 (the façades, the README wall) is answered without the decision
//! at 1/2; one with a bounded factor (an arch) pays one undecided Clarabel run and ends where it
//! did. The references are programs solved from scratch by hand, not the search.
//! Times: docs/performance.md, "Grid façade safety and capacity (session 29)".

mod support;
use support::{least_fraction_from_scratch, readme_wall, stands_from_scratch};
use voussoir::analysis::safety::{safety, SafetyOptions};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::collecting;
use voussoir::{BuildOptions, Structure};

fn without_ranges() -> SafetyOptions {
    SafetyOptions {
        reactions: false,
        ..SafetyOptions::default()
    }
}

#[test]
fn issue29_session29_a_2d_structure_standing_at_zero_is_answered_after_f_1() {
    // The README wall (84 blocks) stands with every joint shrunk to its centre: by hand, the
    // equilibrium program at f = 0 solved from scratch is feasible.
    let st = readme_wall();
    assert!(stands_from_scratch(&st, 0.0));
    let (r, solves) = collecting(|| safety(&st, &without_ranges()).unwrap());
    assert!(r.stands);
    assert_eq!(r.least_joint_fraction, Some(0.0));
    assert_eq!(r.geometric_safety_factor, None);
    // f = 1 is the bisection's only program; f = 0 is Clarabel's decision on the merged program.
    let bisection = solves.iter().filter(|s| s.programs == "bisection").count();
    assert_eq!(bisection, 1, "{solves:?}");
    assert!(
        solves
            .iter()
            .any(|s| s.programs == "elastic decisions" && s.method.name() == "clarabel"),
        "{solves:?}"
    );
}

#[test]
fn issue29_session29_an_arch_with_a_bounded_factor_ends_on_the_hand_bisection() {
    // `gen arch`'s defaults with its dead loads only: a finite factor. Clarabel's early look at
    // f = 0 does not decide (the arch does not stand there), and the search ends on the least
    // fraction of a bisection by hand on programs from scratch, to the grid point.
    let m = arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    assert!(!stands_from_scratch(&st, 0.0));
    let r = safety(&st, &without_ranges()).unwrap();
    let by_hand = least_fraction_from_scratch(&st);
    assert!(r.stands);
    assert_eq!(r.least_joint_fraction, Some(by_hand));
    assert!(by_hand > 0.5 && by_hand < 1.0, "{by_hand}");
    let factor = r.geometric_safety_factor.unwrap();
    assert!(
        (factor - 1.0 / by_hand).abs() <= 1e-12 * factor,
        "{factor} {by_hand}"
    );
}
