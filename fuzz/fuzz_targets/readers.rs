//! The `readers` fuzz target: clip_fuzz_checks' `readers` check on libFuzzer's bytes; a failure panics.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let target = clip_fuzz_checks::target("readers").expect("a registered target");
    if let Err(why) = (target.check)(data) {
        panic!("{why}");
    }
});
