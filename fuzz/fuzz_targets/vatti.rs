//! The `vatti` fuzz target: clip_fuzz_checks' `vatti` check on libFuzzer's bytes; a failure panics.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let target = clip_fuzz_checks::target("vatti").expect("a registered target");
    if let Err(why) = (target.check)(data) {
        panic!("{why}");
    }
});
