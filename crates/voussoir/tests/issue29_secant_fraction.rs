//! Issue 29 item 6 (session 22): the search of `safety`'s least joint fraction by secant steps
//! on the elastic program's least violation, on the bisection's grid. Every fraction asked
//! about is a multiple of the bisection's final width (2⁻²⁰ for the tolerance 1e-6), and the
//! search ends with a bracket of one such step whose lower end does not stand and whose upper
//! end does, so it answers what the bisection answers — the least grid point at which the
//! structure stands — in fewer decisions. The 24 × 24 dome's `safety`: 43 → 33 programs,
//! 29.2 → 23.4 CPU s, the same factor bit for bit (docs/performance.md, "Domes (session 22)").
//!
//! References: the hand value of the offset stack (3/7), a bisection by hand on programs solved
//! from scratch (`support::least_fraction_from_scratch`), and the plain bisection with the same
//! decisions (`FractionSearch { secant: false, .. }`). The decisions go to the elastic program
//! (`elastic: true`, as on the 24 × 24 dome after its first warm run fails), whose "does not
//! stand" carries the least violation the secant steps read.

mod support;
use support::{dome_structure, least_fraction_from_scratch, offset_stack};
use voussoir::analysis::safety::{
    least_joint_fraction, least_joint_fraction_by, least_thickness, least_thickness_by,
    FractionSearch,
};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::generate3d::{dome, DomeSpec};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure, Structure3d};

const SECANT: FractionSearch = FractionSearch {
    secant: true,
    elastic: true,
};
const BISECTION: FractionSearch = FractionSearch {
    secant: false,
    elastic: true,
};

#[test]
fn issue29_item6_secant_search_gives_the_hand_fraction_of_the_offset_stack() {
    // The upper box offset by e over its contact needs the joint fraction e/(1 − e) = 3/7
    // (tests/solver_fallback.rs); the bisection's answer is the least multiple of 2⁻²⁰ at or
    // above it.
    let e = 0.3;
    let hand = e / (1.0 - e);
    let grid = 0.5f64.powi(20);
    let on_grid = (hand / grid).ceil() * grid;
    let st = offset_stack(e, 1.0);
    let o = SolverOptions::default();
    let (fs, ns) = least_joint_fraction_by(&st, 1e-6, &o, SECANT).unwrap();
    let (fb, nb) = least_joint_fraction_by(&st, 1e-6, &o, BISECTION).unwrap();
    let (fs, fb) = (fs.unwrap(), fb.unwrap());
    assert_eq!(fs, fb, "secant {fs} against bisection {fb}");
    assert!(
        (fs - on_grid).abs() <= 1e-12,
        "{fs} against the hand value's grid point {on_grid} (3/7 = {hand})"
    );
    assert!(ns < nb, "{ns} programs against the bisection's {nb}");
}

#[test]
fn issue29_item6_secant_search_equals_a_bisection_from_scratch_on_an_arch() {
    // The generated arch (`gen arch`'s defaults, its dead loads): a finite factor (the README
    // wall stands at f = 0, where neither search takes a secant step).
    let m = arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let o = SolverOptions::default();
    let (fs, ns) = least_joint_fraction_by(&st, 1e-6, &o, SECANT).unwrap();
    let (_, nb) = least_joint_fraction_by(&st, 1e-6, &o, BISECTION).unwrap();
    let by_hand = least_fraction_from_scratch(&st);
    let fs = fs.unwrap();
    assert_eq!(fs, by_hand);
    assert!(fs > 0.0 && fs < 1.0, "{fs}");
    assert!(ns <= nb, "{ns} programs against the bisection's {nb}");
}

#[test]
fn issue29_item6_secant_search_equals_the_bisection_on_a_dome() {
    let st = dome_structure(4, 12, 0.0);
    let o = SolverOptions::default();
    let (fs, ns) = least_joint_fraction_by(&st, 1e-6, &o, SECANT).unwrap();
    let (fb, nb) = least_joint_fraction_by(&st, 1e-6, &o, BISECTION).unwrap();
    // The default search (warm dual simplex decisions, secant steps where the elastic
    // program decided) and the plain bisection: the same grid point.
    let (fd, _) = least_joint_fraction(&st, 1e-6, &o).unwrap();
    let (fs, fb, fd) = (fs.unwrap(), fb.unwrap(), fd.unwrap());
    assert_eq!(fs, fb, "secant {fs} against bisection {fb}");
    assert_eq!(fd, fb, "default {fd} against bisection {fb}");
    assert!(fs > 0.0 && fs < 1.0, "{fs}");
    assert!(ns < nb, "{ns} programs against the bisection's {nb}");
}

#[test]
fn issue29_item6_secant_search_of_the_least_thickness_equals_the_bisection() {
    // `least-thickness` of a 4 × 12 dome (R = 5 m, centreline radius): the same bracket bit
    // for bit with the secant steps and with plain bisection (each thickness asked about a node
    // of the bisection's tree), and by the default search (warm dual simplex decisions).
    let build = |t: f64| {
        Structure3d::new(
            &dome(&DomeSpec {
                thickness: t,
                courses: 4,
                segments: 12,
                ..DomeSpec::default()
            })?,
            BuildOptions::default(),
        )
    };
    let o = SolverOptions::default();
    let (lo, hi, tol) = (0.05, 2.5, 5e-6 * 5.0);
    let s = least_thickness_by(build, lo, hi, tol, &o, SECANT).unwrap();
    let b = least_thickness_by(build, lo, hi, tol, &o, BISECTION).unwrap();
    let d = least_thickness(build, lo, hi, tol, &o).unwrap();
    assert_eq!((s.thickness, s.below), (b.thickness, b.below));
    assert_eq!((d.thickness, d.below), (b.thickness, b.below));
    assert!(b.thickness - b.below <= tol && b.thickness > b.below);
    assert!(
        s.steps < b.steps,
        "{} steps against the bisection's {}",
        s.steps,
        b.steps
    );
}
