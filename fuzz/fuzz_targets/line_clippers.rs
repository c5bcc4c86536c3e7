//! The `line_clippers` fuzz target: clip_fuzz_checks' `line_clippers` check on libFuzzer's bytes; a failure panics.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let target = clip_fuzz_checks::target("line_clippers").expect("a registered target");
    if let Err(why) = (target.check)(data) {
        panic!("{why}");
    }
});
