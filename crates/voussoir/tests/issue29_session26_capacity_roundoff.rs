//! Issue 29 (session 26, helper h-cert): a capacity step's structure does not depend on the
//! round-off of the settlement mechanism. The 1.0 m grid façade with the horizontal live load,
//! its supports from x = 11 to 22 m settling 1 cm (`capacity --steps 1 --profile
//! uniform:11,22,-0.01`): the canonical mechanism's vertex had exact zeros on one solver path
//! (the face extremes as written) and about 1e-9 on the other (equilibrated) at the same
//! components; deformed by the second, the joints of blocks that do not move turned by 1e-11
//! rad, whose map entries steered the geometric-mean scaling of the step's programs over 12
//! orders of magnitude, and the settled step's least violation of equilibrium came out 3.0e-6
//! instead of 16.8 (docs/performance.md, "Capacity step round-off and the as-written face
//! extremes (session 26)"). The mechanism of a settlement path now has its round-off set to
//! zero (`scale::without_round_off`).
//!
//! The reference is independent of that tolerance's form: the same mechanism with every
//! component rounded to a multiple of 1e-7 of its largest (which removes round-off of 1e-9 and
//! moves a real component by at most 5e-8 of the largest), the structure deformed by it
//! (`Assembly::deform`), and its step program's certificate decided the same way. The two
//! certificates must agree to 1e-4 relative (the rounding moves the geometry by 1e-9 m at
//! this settlement; the violations measured agreed to 1e-10).

use voussoir::analysis::canonical::CanonicalOptions;
use voussoir::analysis::laws::{Crushing, DEFAULT_FACETS};
use voussoir::analysis::limit::no_equilibrium_certificate;
use voussoir::analysis::paths::SettlementPath;
use voussoir::discretize::KinematicMap;
use voussoir::generate::LiveLoad;
use voussoir::generate_facade::{bondeno, facade, FacadeMesh, FacadeSpec};
use voussoir::lp::SolverOptions;
use voussoir::programs::limit_force_program;
use voussoir::settlement_input::{apply_profile_as_drawn, Profile};
use voussoir::{Assembly, BuildOptions, Structure};

/// The step program's least violation of equilibrium, decided with a certificate (the
/// capacity step's no-equilibrium certificate: released fixed supports, the default facets).
fn step_violation(mut st: Structure) -> f64 {
    st.release_fixed();
    let mut map = KinematicMap::new(&st);
    map.facets = DEFAULT_FACETS;
    let fp = limit_force_program(&map, &st.load_vector(false), &st.load_vector(true));
    let c = no_equilibrium_certificate(&fp, &SolverOptions::default())
        .unwrap()
        .expect("an LP law has a certificate");
    assert!(
        c.ok,
        "the settled step is certified without equilibrium: {c:?}"
    );
    c.violation.unwrap()
}

#[test]
fn issue29_session26_settled_step_does_not_depend_on_mechanism_round_off() {
    let mut m = facade(&FacadeSpec {
        live: LiveLoad::Horizontal,
        ..bondeno(1.0, FacadeMesh::Grid)
    })
    .unwrap();
    apply_profile_as_drawn(
        &mut m,
        &Profile::Uniform {
            x0: 11.0,
            x1: 22.0,
            v: -0.01,
        },
    )
    .unwrap();
    let st = Structure::new(&m, BuildOptions::default()).unwrap();
    let path = SettlementPath::with_canonical(
        &st,
        &SolverOptions::default(),
        Crushing::Linear,
        DEFAULT_FACETS,
        None,
        Some(CanonicalOptions::default()),
    )
    .unwrap();
    let s = path.max_settlement;
    assert!((s - 0.01).abs() < 1e-12, "{s}");
    let d = &path.mechanism;
    let q = 1e-7 * d.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let rounded: Vec<f64> = d.iter().map(|x| (x / q).round() * q).collect();
    // Round-off is gone from the path's mechanism: no component of it below the rounding.
    let small = d.iter().filter(|x| **x != 0.0 && x.abs() < q).count();
    assert_eq!(small, 0, "components of round-off size in the mechanism");

    let by_path = step_violation(path.deformed(s).unwrap());
    let mut reference = path.unit.deform(&rounded, s).unwrap();
    for k in 0..reference.num_supports() {
        reference.set_support_motion(k, &[0.0; 3]);
    }
    let by_reference = step_violation(reference);
    assert!(
        (by_path - by_reference).abs() <= 1e-4 * by_reference,
        "the settled step's least violation: {by_path} by the path, {by_reference} by the rounded mechanism"
    );
}
