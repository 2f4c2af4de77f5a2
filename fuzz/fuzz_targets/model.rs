#![no_main]
// See docs/fuzzing.md; the code path is voussoir_fuzz::model (fuzz/src/lib.rs), which the stable
// test crates/voussoir-io/tests/fuzz_corpus.rs replays on the corpus.
libfuzzer_sys::fuzz_target!(|data: &[u8]| voussoir_fuzz::model(data));
