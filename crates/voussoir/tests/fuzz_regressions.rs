//! One test per defect of the library found by fuzzing (docs/fuzzing.md, "Findings"), named
//! after the defect. The inputs the fuzzer found are replayed as they are by
//! crates/voussoir-io/tests/fuzz_corpus.rs; these tests state each defect on a model written
//! by hand.

use voussoir::{BuildOptions, Model, Structure};

/// Two stacked 1 mm blocks and a 100 m block, side by side on a 200 m foundation: the overlap
/// check's grid has cells of the median block (1 mm), which the 100 m block would fill 10¹⁰
/// times over.
fn one_giant_among_small_blocks(giant_x0: f64) -> Model {
    let rect = |x0: f64, y0: f64, x1: f64, y1: f64| {
        format!("[[{x0}, {y0}], [{x1}, {y0}], [{x1}, {y1}], [{x0}, {y1}]]")
    };
    serde_json::from_str(&format!(
        r#"{{
        "materials": {{ "default": {{ "unit_weight": 20 }} }},
        "blocks": [
            {{ "polygon": {} }},
            {{ "polygon": {} }},
            {{ "polygon": {} }}
        ],
        "supports": [ {{ "name": "ground", "polygon": {} }} ],
        "loads": {{ "live": [ {{ "type": "body", "coefficients": [1, 0] }} ] }}
    }}"#,
        rect(0.0, 0.0, 0.001, 0.001),
        rect(0.0, 0.001, 0.001, 0.002),
        rect(giant_x0, 0.0, giant_x0 + 100.0, 100.0),
        rect(-1.0, -1.0, 200.0, 0.0),
    ))
    .expect("valid JSON model")
}

#[test]
fn a_block_1e5_times_the_median_size_does_not_exhaust_memory_in_the_overlap_check() {
    // Found by the `dxf` target: a bulge of 776979 (an arc of 359.9997°) turned one voussoir of
    // the LACT3 arch into a polygon of radius ~10⁴ km, and the overlap check allocated a cell
    // entry for every median-block-sized cell it covers (out of memory at 2 GB).
    let st = Structure::new(&one_giant_among_small_blocks(1.0), BuildOptions::default())
        .expect("three blocks on a foundation");
    // Joints: block 0 on the ground, block 1 on block 0, block 2 on the ground.
    assert_eq!(st.joints.len(), 3);
    // The same giant moved onto the small blocks is an overlap, named in one line.
    let e = Structure::new(
        &one_giant_among_small_blocks(-50.0),
        BuildOptions::default(),
    )
    .expect_err("the giant covers blocks 0 and 1");
    let msg = e.to_string();
    assert!(
        msg.contains("block 0 and block 2 overlap") && !msg.contains('\n'),
        "{msg}"
    );
}
