//! Incremental (nonlinear kinematic) analysis of the paper's arch under a half-span live load,
//! with and without a vertical settlement of the other springing (paper, Section 6,
//! Figs 13–17; `shared/reference/paper-cases.md`).

use voussoir::analysis::incremental::{
    incremental, settled, Control, EventKind, IncrementalOptions, IncrementalResult,
    IncrementalStatus,
};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::SolverOptions;
use voussoir::model::Connection;
use voussoir::{BuildOptions, Structure};

/// The paper's arch, live load on the left half, the right springing settled downward by
/// `settlement` (m, `fixed` for the settlement analysis), as the incremental analysis starts.
fn start(settlement: f64) -> Structure {
    let mut m = arch(&ArchSpec {
        live: LiveLoad::Left,
        ..ArchSpec::default()
    })
    .unwrap();
    if settlement == 0.0 {
        return Structure::new(&m, BuildOptions::default()).unwrap();
    }
    m.supports[1].motion = [0.0, -settlement, 0.0];
    m.supports[1].connection = Connection::Fixed;
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    settled(&st, &SolverOptions::default(), true).unwrap()
}

/// Crown control point (extrados), horizontal displacement, as in the paper's Fig. 14.
fn run(settlement: f64, step: f64) -> IncrementalResult {
    let st = start(settlement);
    let c = Control::nearest(&st, [0.0, 3.19], [1.0, 0.0]).unwrap();
    incremental(
        &st,
        &c,
        &IncrementalOptions {
            step,
            max_displacement: 0.05,
            ..Default::default()
        },
    )
    .unwrap()
}

/// Largest deviation from the least-squares line through `(x, y)`.
fn line_residual(pts: &[(f64, f64)]) -> f64 {
    let n = pts.len() as f64;
    let (mx, my) = pts
        .iter()
        .fold((0.0, 0.0), |a, p| (a.0 + p.0 / n, a.1 + p.1 / n));
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let b = sxy / sxx;
    pts.iter()
        .fold(0.0f64, |m, p| m.max((p.1 - my - b * (p.0 - mx)).abs()))
}

#[test]
fn control_point_is_on_the_crown_voussoir() {
    let st = start(0.0);
    let c = Control::nearest(&st, [0.0, 3.19], [2.0, 0.0]).unwrap();
    assert!(c.block == 31 || c.block == 32, "block {}", c.block);
    assert_eq!(c.direction, [1.0, 0.0]);
    assert!(Control::new(&st, 64, [0.0, 0.0], [1.0, 0.0]).is_err());
    assert!(Control::new(&st, 0, [0.0, 0.0], [0.0, 0.0]).is_err());
}

#[test]
fn perfect_arch_starts_at_0_215_and_falls_linearly() {
    let r = run(0.0, 1e-4);
    assert_eq!(r.status, IncrementalStatus::Collapsed);
    let l0 = r.curve[0].load_multiplier;
    assert!((l0 - 0.215).abs() <= 0.02 * 0.215, "λ(0) = {l0}");
    assert_eq!(r.peak_load_multiplier, l0);
    // Four hinges open at the first step (Fig. 13b): the 12th joint from the loaded springing,
    // the crown, the 13th joint from the other springing and the other springing.
    let mut first: Vec<usize> = r
        .events
        .iter()
        .filter(|e| e.step == 0)
        .map(|e| e.joint)
        .collect();
    first.sort();
    assert_eq!(first, vec![12, 32, 51, 64]);
    // Decreasing, and almost linear: within 2 % of λ(0) of a straight line.
    let pts: Vec<(f64, f64)> = r
        .curve
        .iter()
        .map(|p| (p.displacement, p.equilibrium_multiplier))
        .collect();
    for w in pts.windows(2) {
        assert!(w[1].1 < w[0].1 && w[1].0 > w[0].0);
    }
    assert!(
        line_residual(&pts) <= 0.02 * l0,
        "residual {}",
        line_residual(&pts)
    );
}

/// Index of the curve point evaluated just before the closure of the base hinge (joint 1, the
/// loaded springing, opened by the settlement) took effect; the next point is just after it.
fn base_closure(r: &IncrementalResult) -> (usize, f64) {
    let e = r
        .events
        .iter()
        .find(|e| e.kind == EventKind::Closed && e.joint == 1)
        .expect("the base hinge closes");
    let i = r
        .curve
        .iter()
        .position(|p| p.before_closure && p.step == e.step)
        .unwrap();
    assert_eq!(r.curve[i].displacement, e.displacement);
    (i, e.displacement)
}

#[test]
fn settlement_of_0_25_cm_zero_then_jump_then_linear_fall() {
    let r = run(0.0025, 1e-4);
    assert_eq!(r.status, IncrementalStatus::Collapsed);
    assert_eq!(r.initial_open_joints, vec![1, 13, 32]);
    let (i, x_b) = base_closure(&r);
    // A–B: the self-weight closes the hinges, λ = 0 (the dead loads alone drive the mechanism).
    assert!(x_b > 5e-4, "closure at {x_b}");
    for p in &r.curve[..=i] {
        assert_eq!(p.load_multiplier, 0.0, "at {}", p.displacement);
        assert!(p.equilibrium_multiplier < 0.0);
    }
    // B: a jump at the closure (two curve points at the same displacement).
    let jump = r.curve[i + 1].load_multiplier - r.curve[i].load_multiplier;
    assert_eq!(r.curve[i + 1].displacement, r.curve[i].displacement);
    assert!(jump > 0.1, "jump {jump}");
    // After the peak: a linear fall to zero.
    let k = r
        .curve
        .iter()
        .position(|p| p.load_multiplier == r.peak_load_multiplier)
        .unwrap();
    let tail: Vec<(f64, f64)> = r.curve[k..]
        .iter()
        .map(|p| (p.displacement, p.equilibrium_multiplier))
        .collect();
    for w in tail.windows(2) {
        assert!(w[1].1 < w[0].1);
    }
    assert!(
        line_residual(&tail) <= 0.03 * r.peak_load_multiplier,
        "residual {}",
        line_residual(&tail)
    );
}

#[test]
fn settlement_of_0_5_cm_starts_positive_drops_jumps_and_falls() {
    let r = run(0.005, 1e-4);
    assert_eq!(r.status, IncrementalStatus::Collapsed);
    let l0 = r.curve[0].load_multiplier;
    assert!(l0 > 0.0, "λ(0) = {l0}");
    let (i, _) = base_closure(&r);
    // Before the closure λ falls to zero (the self-weight then drives the mechanism) ...
    assert_eq!(r.curve[i].load_multiplier, 0.0);
    assert!(r.curve[..=i]
        .windows(2)
        .all(|w| w[1].equilibrium_multiplier < w[0].equilibrium_multiplier));
    // ... then jumps above its starting value when the base hinge closes, and falls again.
    assert!(r.curve[i + 1].load_multiplier > l0 + 0.05);
    assert_eq!(r.peak_load_multiplier, r.curve[i + 1].load_multiplier);
    assert!(r.curve[i + 1..]
        .windows(2)
        .all(|w| w[1].equilibrium_multiplier < w[0].equilibrium_multiplier));
}

#[test]
fn peak_falls_with_the_settlement_and_converges_with_the_step() {
    let mut peaks = Vec::new();
    for s in [0.0, 0.0025, 0.005] {
        let a = run(s, 1e-4);
        let b = run(s, 5e-5);
        let (pa, pb) = (a.peak_load_multiplier, b.peak_load_multiplier);
        assert!(
            (pa - pb).abs() <= 0.01 * pb,
            "settlement {s}: peak {pa} vs {pb} with half the step"
        );
        peaks.push(pb);
    }
    assert!(
        peaks[0] > peaks[1] && peaks[1] > peaks[2],
        "peaks {peaks:?}"
    );
}

#[test]
fn bad_options_are_errors() {
    let st = start(0.0);
    let c = Control::nearest(&st, [0.0, 3.19], [1.0, 0.0]).unwrap();
    for o in [
        IncrementalOptions {
            step: 0.0,
            ..Default::default()
        },
        IncrementalOptions {
            max_displacement: f64::NAN,
            ..Default::default()
        },
    ] {
        let e = incremental(&st, &c, &o).unwrap_err();
        assert!(!e.to_string().contains('\n'));
    }
}
