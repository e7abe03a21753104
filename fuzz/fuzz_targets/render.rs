//! cargo-fuzz wrapper of `limn_fuzzing::render` (see its docs for the input and the
//! property checked).

#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| limn_fuzzing::render::run(data));
