//! The paper's semicircular arch (Section 6; `shared/reference/paper-cases.md`).

use voussoir::analysis::{limit, settle, LimitStatus};
use voussoir::generate::{arch, ArchSpec, LiveLoad};
use voussoir::lp::SolverOptions;
use voussoir::{BuildOptions, Structure};

fn paper_arch(live: LiveLoad) -> Structure {
    let m = arch(&ArchSpec { live, ..ArchSpec::default() }).unwrap();
    Structure::new(&m, BuildOptions::default()).unwrap()
}

#[test]
fn collapse_multiplier_full_span() {
    let st = paper_arch(LiveLoad::Full);
    assert_eq!(st.joints.len(), 65);
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::Collapse);
    let l = r.load_multiplier.unwrap();
    eprintln!("lambda full = {l}, hinges {:?}", r.hinges.iter().map(|h| h.joint).collect::<Vec<_>>());
    assert!((l - 0.429).abs() <= 0.02 * 0.429, "λ = {l}");
}

#[test]
fn collapse_multiplier_half_span() {
    let st = paper_arch(LiveLoad::Left);
    let r = limit(&st, &SolverOptions::default()).unwrap();
    let l = r.load_multiplier.unwrap();
    eprintln!("lambda half = {l}, hinges {:?}", r.hinges.iter().map(|h| h.joint).collect::<Vec<_>>());
    assert!((l - 0.215).abs() <= 0.02 * 0.215, "λ = {l}");
}

#[test]
fn spreading() {
    let mut st = paper_arch(LiveLoad::Full);
    st.supports[1].motion = [0.01, 0.0, 0.0];
    let r = settle(&st, &SolverOptions::default()).unwrap();
    eprintln!("{:?} {} gap {:?}", r.status, r.message, r.duality_gap);
    eprintln!("hinges {:?}", r.hinges);
    eprintln!("reactions {:?}", r.reactions);
}
