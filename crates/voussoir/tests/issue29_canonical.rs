//! Issue 29, item 5: the canonical selection that scales (docs/canonical.md, "Cost").
//!
//! The least friction coefficient the canonical forces report is the least μ for which an
//! optimal field with the open points unloaded satisfies Coulomb's rule: checked here against
//! an independent bisection, written out on the public programs, on the feasibility of those
//! fields (a faster search tried for item 5 stopped 1.5 % above it; docs/canonical.md).

use voussoir::analysis::canonical::{settle_canonical, CanonicalOptions};
use voussoir::analysis::settlement::SettlementForm;
use voussoir::discretize::KinematicMap;
use voussoir::generate::{wall, WallSpec};
use voussoir::lp::{self, LpStatus, Method, SolverOptions};
use voussoir::programs;
use voussoir::settlement_input::{apply_profile, Profile};
use voussoir::{BuildOptions, Structure};

/// The README's wall: `gen wall --courses 8 --units 10 --unit 0.4,0.2`,
/// `settle --profile uniform:2.8,4.0,-0.01`.
fn readme_wall() -> Structure {
    let mut m = wall(&WallSpec {
        courses: 8,
        units: 10,
        unit: [0.4, 0.2],
        ..WallSpec::default()
    })
    .unwrap();
    apply_profile(
        &mut m,
        &Profile::Uniform {
            x0: 2.8,
            x1: 4.0,
            v: -0.01,
        },
    )
    .unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn issue29_item5_least_friction_equals_a_bisection() {
    let st = readme_wall();
    let r = settle_canonical(
        &st,
        &SolverOptions::default(),
        SettlementForm::Both,
        &CanonicalOptions {
            reaction_ranges: false,
            ..CanonicalOptions::default()
        },
    )
    .unwrap();
    let f = r.canonical.as_ref().unwrap().forces.as_ref().unwrap();
    assert!(f.physical);
    let mu = f.least_friction.expect("a least friction coefficient");
    // The points open in the reported mechanism (results list them joint by joint, point by
    // point, in the kinematic map's order), as the selection counts them.
    let jumps: Vec<f64> = r
        .joints
        .iter()
        .flat_map(|j| j.points.iter().map(|p| p.opening))
        .collect();
    let big = jumps.iter().fold(0.0f64, |m, o| m.max(o.abs()));
    let open: Vec<bool> = jumps.iter().map(|&o| o > 1e-7 * big).collect();
    let map = KinematicMap::new(&st);
    assert_eq!(open.len(), map.num_points());
    let dead = st.load_vector(false);
    let work = r.work_dead_loads.unwrap();
    let clarabel = SolverOptions {
        method: Method::Clarabel,
        feasibility_tolerance: 1e-10,
        ..SolverOptions::default()
    };
    // Is there an optimal field with the open points unloaded and |p_t| ≤ μ p_n everywhere?
    let admissible = |m: f64| {
        let fp = programs::physical_force_program(
            &map,
            |k: &KinematicMap| programs::settlement_force_program(k, &dead),
            work,
            1e-9,
            &open,
            Some(m),
            false,
        );
        lp::solve(&fp.lp, &clarabel).is_ok_and(|s| s.status == LpStatus::Optimal)
    };
    // The reference: bisection on [0, 8] to 1e-6 (relative).
    assert!(!admissible(0.0) && admissible(8.0));
    let (mut lo, mut hi) = (0.0, 8.0);
    while hi - lo > 1e-6 * hi {
        let mid = 0.5 * (lo + hi);
        if admissible(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    println!("least friction: selection {mu}, bisection {hi}");
    // Both to the selection's precision 1e-4 (and the solvers' tolerance).
    assert!(
        (mu - hi).abs() <= 2e-4 * hi,
        "least friction {mu}, bisection {hi}"
    );
}
