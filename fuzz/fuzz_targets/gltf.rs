//! cargo-fuzz wrapper of `limn_fuzzing::gltf` (see its docs for the input and the
//! property checked).

#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| limn_fuzzing::gltf::run(data));
