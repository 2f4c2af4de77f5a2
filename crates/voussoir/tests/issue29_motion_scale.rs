//! Sessions 23–24: the canonical settlement is a property of the structure and the direction of
//! the support motion, not of its magnitude. The settlement programs are positively
//! homogeneous in the motion (no gaps here): the mechanism scales with it, the works too, and
//! the optimal force fields — so the least friction coefficient — do not change at all.
//! Before the fix, the optimal face's value row carried the motion's scale (coefficients 1e10
//! at `right=1e10,0` among equilibrium rows of order 1): the force stage printed a least μ of
//! 0.3281 at 1e10 m and 0 at 1e30 m for the paper's arch, whose least μ is 0.4034 (to 3 %) at
//! 1 cm, and its fields failed their certificates; at 1e-12 m its energy QP failed. The fix
//! (`programs::optimal_face_in_band`) divides the row only outside a band about the program's
//! own coefficients, so ordinary motions are untouched. The reference here is an independent
//! bisection to 1e-6 on the public programs at the ordinary scale (1 cm).

mod support;
use support::least_friction_by_bisection;
use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions};
use voussoir::analysis::settlement::SettlementForm;
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure};

fn spreading(u: f64) -> Structure {
    let mut m = arch(&ArchSpec {
        live: LiveLoad::None,
        ..ArchSpec::default()
    })
    .unwrap();
    let i = m.support_index("right").unwrap();
    m.supports[i].motion = [u, 0.0, 0.0];
    Structure::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn issue29_canonical_forces_do_not_depend_on_the_motion_magnitude() {
    let copts = CanonicalOptions {
        reaction_ranges: false,
        ..CanonicalOptions::default()
    };
    let st = spreading(0.01);
    let base =
        settle_canonical(&st, &SolverOptions::default(), SettlementForm::Both, &copts).unwrap();
    let reference = least_friction_by_bisection(&st, &base);
    let w0 = base.work_dead_loads.unwrap();
    for u in [1e-12, 1e-6, 0.01, 1.0, 1e3, 1e7, 1e10, 1e30] {
        let st = spreading(u);
        let r =
            settle_canonical(&st, &SolverOptions::default(), SettlementForm::Both, &copts).unwrap();
        let c = r.certificate.as_ref().unwrap();
        assert!(c.ok, "u = {u}: not certified: {c:?}");
        // The work scales with the motion (to the certificate's tolerance).
        let w = r.work_dead_loads.unwrap();
        assert!(
            (w - w0 * u / 0.01).abs() <= 1e-7 * w.abs(),
            "u = {u}: work {w}, expected {}",
            w0 * u / 0.01
        );
        assert_eq!(r.hinges.len(), base.hinges.len(), "u = {u}");
        let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
        assert!(f.physical, "u = {u}");
        assert!(f.rejected.is_empty(), "u = {u}: rejected {:?}", f.rejected);
        // The stated bracket holds the reference: least μ shown admissible at or above it, the
        // μ shown inadmissible below it.
        let least = f.least_friction.expect("a least friction coefficient");
        let p = f.friction_precision.expect("a precision");
        assert!(
            least >= reference * (1.0 - 1e-6) && least * (1.0 - p) <= reference * (1.0 + 1e-6),
            "u = {u}: least μ {least} (precision {p}), reference {reference}"
        );
        assert!(p <= 0.05, "u = {u}: precision {p}");
    }
}
