//! Every integration test of this crate, compiled as ONE test binary (`it`).
//!
//! Each file of this directory stays a file of its own (a regression test per defect, named after
//! its issue) and is a module here. One binary instead of one per file: the test binaries were
//! linked ~100 times against HiGHS, Clarabel and the library, 9 of the CI's 30 minutes; and the
//! tests of all files share the cores instead of waiting file by file. `autotests = false` in
//! Cargo.toml, so a new file must be listed below: `every_test_file_is_a_module`
//! (below, for every crate) fails otherwise.
//! One file: `cargo test --release -p CRATE --test it -- FILE::`.

#[path = "bench_scenarios.rs"]
mod bench_scenarios;
#[path = "canonical.rs"]
mod canonical;
#[path = "capacity.rs"]
mod capacity;
#[path = "detection.rs"]
mod detection;
#[path = "existing_cracks.rs"]
mod existing_cracks;
#[path = "facade.rs"]
mod facade;
#[path = "fuzz_regressions.rs"]
mod fuzz_regressions;
#[path = "generators.rs"]
mod generators;
#[path = "generators3d.rs"]
mod generators3d;
#[path = "geometry3d.rs"]
mod geometry3d;
#[path = "identify.rs"]
mod identify;
#[path = "incremental.rs"]
mod incremental;
#[path = "issue28_identify.rs"]
mod issue28_identify;
#[path = "issue28_io.rs"]
mod issue28_io;
#[path = "issue28_scale.rs"]
mod issue28_scale;
#[path = "issue29_cannot_stand_certified.rs"]
mod issue29_cannot_stand_certified;
#[path = "issue29_canonical.rs"]
mod issue29_canonical;
#[path = "issue29_canonical3d.rs"]
mod issue29_canonical3d;
#[path = "issue29_canonical_default_all.rs"]
mod issue29_canonical_default_all;
#[path = "issue29_capacity_cert.rs"]
mod issue29_capacity_cert;
#[path = "issue29_capacity_no_equilibrium.rs"]
mod issue29_capacity_no_equilibrium;
#[path = "issue29_cert025.rs"]
mod issue29_cert025;
#[path = "issue29_crossover.rs"]
mod issue29_crossover;
#[path = "issue29_curve_friction3d.rs"]
mod issue29_curve_friction3d;
#[path = "issue29_curve_warm2d.rs"]
mod issue29_curve_warm2d;
#[path = "issue29_dome2.rs"]
mod issue29_dome2;
#[path = "issue29_dome48.rs"]
mod issue29_dome48;
#[path = "issue29_dome_safety.rs"]
mod issue29_dome_safety;
#[path = "issue29_elastic_trials.rs"]
mod issue29_elastic_trials;
#[path = "issue29_extremes_fallback.rs"]
mod issue29_extremes_fallback;
#[path = "issue29_facade_sequences.rs"]
mod issue29_facade_sequences;
#[path = "issue29_facade_shortcuts.rs"]
mod issue29_facade_shortcuts;
#[path = "issue29_face_extremes.rs"]
mod issue29_face_extremes;
#[path = "issue29_fixes.rs"]
mod issue29_fixes;
#[path = "issue29_force_stage.rs"]
mod issue29_force_stage;
#[path = "issue29_free_columns.rs"]
mod issue29_free_columns;
#[path = "issue29_friction_precision.rs"]
mod issue29_friction_precision;
#[path = "issue29_incremental_canonical.rs"]
mod issue29_incremental_canonical;
#[path = "issue29_least_mu.rs"]
mod issue29_least_mu;
#[path = "issue29_least_twins.rs"]
mod issue29_least_twins;
#[path = "issue29_local_rays.rs"]
mod issue29_local_rays;
#[path = "issue29_motion_scale.rs"]
mod issue29_motion_scale;
#[path = "issue29_nonassoc_iteration.rs"]
mod issue29_nonassoc_iteration;
#[path = "issue29_outcomes.rs"]
mod issue29_outcomes;
#[path = "issue29_policy.rs"]
mod issue29_policy;
#[path = "issue29_qp_budget.rs"]
mod issue29_qp_budget;
#[path = "issue29_range_twins.rs"]
mod issue29_range_twins;
#[path = "issue29_recertify.rs"]
mod issue29_recertify;
#[path = "issue29_secant_fraction.rs"]
mod issue29_secant_fraction;
#[path = "issue29_sequences.rs"]
mod issue29_sequences;
#[path = "issue29_session25_as_written_first.rs"]
mod issue29_session25_as_written_first;
#[path = "issue29_session25_least_mirror.rs"]
mod issue29_session25_least_mirror;
#[path = "issue29_session26_capacity_roundoff.rs"]
mod issue29_session26_capacity_roundoff;
#[path = "issue29_session26_capacity_steps.rs"]
mod issue29_session26_capacity_steps;
#[path = "issue29_session27_kept_pivots.rs"]
mod issue29_session27_kept_pivots;
#[path = "issue29_session28_friction_limit.rs"]
mod issue29_session28_friction_limit;
#[path = "issue29_session29_force_trials.rs"]
mod issue29_session29_force_trials;
#[path = "issue29_session29_zero_first.rs"]
mod issue29_session29_zero_first;
#[path = "issue29_session30_friction_decisions.rs"]
mod issue29_session30_friction_decisions;
#[path = "issue29_session30_friction_mirror.rs"]
mod issue29_session30_friction_mirror;
#[path = "issue29_symmetric_ranges3d.rs"]
mod issue29_symmetric_ranges3d;
#[path = "issue29_undecided_ipm.rs"]
mod issue29_undecided_ipm;
#[path = "issue29_vault_friction_safety.rs"]
mod issue29_vault_friction_safety;
#[path = "issue30_adapt.rs"]
mod issue30_adapt;
#[path = "issue30_adapt_facade.rs"]
mod issue30_adapt_facade;
#[path = "issue30_adapt_global.rs"]
mod issue30_adapt_global;
#[path = "issue30_adapt_meshes.rs"]
mod issue30_adapt_meshes;
#[path = "issue30_cracks.rs"]
mod issue30_cracks;
#[path = "issue30_friction.rs"]
mod issue30_friction;
#[path = "issue30_meshes.rs"]
mod issue30_meshes;
#[path = "issue30_stage2_cap.rs"]
mod issue30_stage2_cap;
#[path = "issue31_request.rs"]
mod issue31_request;
#[path = "issue31_requests2.rs"]
mod issue31_requests2;
#[path = "issue31_result_types.rs"]
mod issue31_result_types;
#[path = "issue31_sweep3d.rs"]
mod issue31_sweep3d;
#[path = "issue32_split.rs"]
mod issue32_split;
#[path = "issue32_surveys.rs"]
mod issue32_surveys;
#[path = "joint_laws.rs"]
mod joint_laws;
#[path = "kinematics.rs"]
mod kinematics;
#[path = "limit.rs"]
mod limit;
#[path = "lintel.rs"]
mod lintel;
#[path = "nonassociative_settlement.rs"]
mod nonassociative_settlement;
#[path = "properties.rs"]
mod properties;
#[path = "regressions.rs"]
mod regressions;
#[path = "safety.rs"]
mod safety;
#[path = "session25_trust.rs"]
mod session25_trust;
#[path = "settlement.rs"]
mod settlement;
#[path = "solver_fallback.rs"]
mod solver_fallback;
#[path = "three_d.rs"]
mod three_d;
#[path = "three_d_core.rs"]
mod three_d_core;
#[path = "three_d_structures.rs"]
mod three_d_structures;

/// A test file not listed in its crate's `tests/it.rs` would never be compiled nor run: refuse
/// that, for every crate of the workspace with integration tests (one guard, here).
#[test]
fn every_test_file_is_a_module() {
    let crates = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut missing = Vec::new();
    for krate in ["voussoir", "voussoir-cli", "voussoir-io"] {
        let dir = crates.join(krate).join("tests");
        let me = std::fs::read_to_string(dir.join("it.rs")).expect("tests/it.rs");
        for e in std::fs::read_dir(&dir).expect("the tests directory") {
            let name = e.unwrap().file_name().into_string().unwrap();
            if name.ends_with(".rs")
                && name != "it.rs"
                && !me.contains(&format!("#[path = \"{name}\"]"))
            {
                missing.push(format!("{krate}/tests/{name}"));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "test files not in their tests/it.rs (never compiled): {missing:?}"
    );
}
