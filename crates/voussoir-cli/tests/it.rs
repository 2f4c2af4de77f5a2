//! Every integration test of this crate, compiled as ONE test binary (`it`).
//!
//! Each file of this directory stays a file of its own (a regression test per defect, named after
//! its issue) and is a module here. One binary instead of one per file: the test binaries were
//! linked ~100 times against HiGHS, Clarabel and the library, 9 of the CI's 30 minutes; and the
//! tests of all files share the cores instead of waiting file by file. `autotests = false` in
//! Cargo.toml, so a new file must be listed below: `every_test_file_is_a_module`
//! (crates/voussoir/tests/it.rs, for every crate) fails otherwise.
//! One file: `cargo test --release -p CRATE --test it -- FILE::`.

#[path = "cli.rs"]
mod cli;
/// The helpers every test file shares (`common/mod.rs`: `use crate::common::…`).
mod common;
#[path = "files.rs"]
mod files;
#[path = "first_hour.rs"]
mod first_hour;
#[path = "gen3d.rs"]
mod gen3d;
#[path = "gen_live_load.rs"]
mod gen_live_load;
#[path = "identify.rs"]
mod identify;
#[path = "import3d.rs"]
mod import3d;
#[path = "issue28_flags.rs"]
mod issue28_flags;
#[path = "issue28_io.rs"]
mod issue28_io;
#[path = "issue28_plot.rs"]
mod issue28_plot;
#[path = "issue28_scale.rs"]
mod issue28_scale;
#[path = "issue29_bench.rs"]
mod issue29_bench;
#[path = "issue29_bench2.rs"]
mod issue29_bench2;
#[path = "issue29_canonical_default_cli.rs"]
mod issue29_canonical_default_cli;
#[path = "issue29_capacity_cert_cli.rs"]
mod issue29_capacity_cert_cli;
#[path = "issue29_fixes_cli.rs"]
mod issue29_fixes_cli;
#[path = "issue29_friction_precision_cli.rs"]
mod issue29_friction_precision_cli;
#[path = "issue29_incremental_canonical_cli.rs"]
mod issue29_incremental_canonical_cli;
#[path = "issue30_adapted_model_cli.rs"]
mod issue30_adapted_model_cli;
#[path = "issue30_cracks.rs"]
mod issue30_cracks;
#[path = "issue30_friction_cli.rs"]
mod issue30_friction_cli;
#[path = "issue30_friction_wall.rs"]
mod issue30_friction_wall;
#[path = "issue30_identify_cracks.rs"]
mod issue30_identify_cracks;
#[path = "issue30_meshes.rs"]
mod issue30_meshes;
#[path = "issue30_plot_unbounded_cli.rs"]
mod issue30_plot_unbounded_cli;
#[path = "issue31_front2.rs"]
mod issue31_front2;
#[path = "issue31_inc3d.rs"]
mod issue31_inc3d;
#[path = "issue32_existing.rs"]
mod issue32_existing;
#[path = "issue32_foundations.rs"]
mod issue32_foundations;
#[path = "issue32_pictures.rs"]
mod issue32_pictures;
#[path = "issue32_report.rs"]
mod issue32_report;
#[path = "issue32_reports2.rs"]
mod issue32_reports2;
#[path = "issue32_surveys.rs"]
mod issue32_surveys;
#[path = "issue32_vocab.rs"]
mod issue32_vocab;
#[path = "joint_laws_cli.rs"]
mod joint_laws_cli;
#[path = "output_names.rs"]
mod output_names;
#[path = "readme.rs"]
mod readme;
#[path = "reliability.rs"]
mod reliability;
#[path = "safety.rs"]
mod safety;
#[path = "session12_regressions.rs"]
mod session12_regressions;
#[path = "session24_audit.rs"]
mod session24_audit;
#[path = "session24_extremes.rs"]
mod session24_extremes;
#[path = "session25_trust.rs"]
mod session25_trust;
#[path = "session26_trust.rs"]
mod session26_trust;
#[path = "session27_capacity.rs"]
mod session27_capacity;
#[path = "session28_trust.rs"]
mod session28_trust;
#[path = "sweep.rs"]
mod sweep;
#[path = "sweep_capacity.rs"]
mod sweep_capacity;
#[path = "three_d_cli.rs"]
mod three_d_cli;
