//! Issue 29 item 3: an analysis of many programs is certified only when every program's answer
//! is (`lp::outcomes_certified`, shared by the results' `answered[]` and the realistic
//! benchmark). Hand-made lines, each verdict worked out by hand.

use voussoir::lp::{outcomes_certified, CANDIDATE_WORDS};

#[test]
fn issue29_item3_every_uncertified_answer_must_be_decided_again_by_its_own_kind() {
    // Two bisection trials not certified by the IPM, both decided again by the dual simplex.
    assert!(outcomes_certified([
        ("bisection", 2, "not certified"),
        ("bisection", 2, "certified"),
    ]));
    // Decisions with their certificates count as answered.
    assert!(outcomes_certified([
        ("elastic decisions", 3, "infeasible"),
        ("reaction ranges", 4, "unbounded"),
    ]));
    // One of the two re-solved only: one program is left without a certificate.
    assert!(!outcomes_certified([
        ("bisection", 2, "not certified"),
        ("bisection", 1, "certified"),
    ]));
    // Re-solved by another kind of program: that does not cover it.
    assert!(!outcomes_certified([
        ("bisection", 1, "not certified"),
        ("reaction ranges", 1, "certified"),
    ]));
    // A candidate's answer (a ray searched for, used only once certified on the whole
    // program) neither certifies nor fails the result (session 22).
    assert!(outcomes_certified([
        ("rays of unbounded reactions", 2, CANDIDATE_WORDS),
        ("reaction ranges", 4, "certified"),
    ]));
    assert!(!outcomes_certified([
        ("rays of unbounded reactions", 1, CANDIDATE_WORDS),
        ("reaction ranges", 1, "not certified"),
    ]));
    // An outcome the layer does not know is not a certificate.
    assert!(!outcomes_certified([("capacity steps", 1, "stalled")]));
    // Nothing to answer: nothing left uncertified.
    assert!(outcomes_certified(std::iter::empty::<(&str, u64, &str)>()));
}
