//! Fuzz targets for limn, runnable with and without libFuzzer.
//!
//! Every module is one target with a `run(data: &[u8])` entry point that must never
//! panic: a panic, or a failed `assert!` of the property the module states, is a bug.
//! The cargo-fuzz wrappers in `fuzz/fuzz_targets/` call these functions, and
//! `tests/replay.rs` runs every file of the committed corpus (`fuzz/corpus/<target>/`)
//! through them in `cargo test`.
//!
//! | target | input | property |
//! |---|---|---|
//! | [`obj`] | OBJ bytes, then a NUL byte and an MTL library | loads or fails with a typed error; a loaded scene is sound |
//! | [`stl`] | STL bytes (ASCII or binary) | the same |
//! | [`ply`] | PLY bytes | the same |
//! | [`gltf`] | glTF JSON, or GLB when the bytes start with `glTF` | the same |
//! | [`scene_toml`] | a TOML scene file, then a NUL byte and the OBJ mesh `m.obj` | the same |
//! | [`kernel_split`] | structured: a face and planes cutting it | the kernel's invariants hold after every split |
//! | [`pipeline`] | structured: a small degenerate scene and a camera | every ordering runs; the exact ones pass the exact painter's checker |
//! | [`writers`] | structured: a picture with finite and extreme values | every writer runs; its output parses |
//!
//! Structured inputs are decoded with [`arbitrary::Unstructured`]; their `Debug` form is
//! Rust source (floats are stored as their bit patterns, lists print as `vec![...]`),
//! so a crashing case pastes into a regression test as it is.
//!
//! ```
//! // Any bytes are a valid input; an empty one too.
//! limn_fuzzing::stl::run(b"solid s\nendsolid s\n");
//! limn_fuzzing::pipeline::run(&[]);
//! ```

pub mod gltf;
pub mod kernel_split;
pub mod obj;
pub mod pipeline;
pub mod ply;
pub mod render;
pub mod scene_toml;
pub mod stl;
pub mod writers;

mod sound;

/// A target's entry point: runs one input, panicking only on a bug.
pub type Run = fn(&[u8]);

/// Every target by name, as the corpus folders and the cargo-fuzz binaries name them.
pub const TARGETS: [(&str, Run); 9] = [
    ("obj", obj::run),
    ("stl", stl::run),
    ("ply", ply::run),
    ("gltf", gltf::run),
    ("scene_toml", scene_toml::run),
    ("kernel_split", kernel_split::run),
    ("pipeline", pipeline::run),
    ("writers", writers::run),
    ("render", render::run),
];

/// `Debug` of a slice as a `vec![...]` literal, so structured cases print as Rust.
struct VecLit<'a, T>(&'a [T]);

impl<T: std::fmt::Debug> std::fmt::Debug for VecLit<'_, T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("vec!")?;
        f.debug_list().entries(self.0).finish()
    }
}

/// `Debug` of an optional slice as `None` or `Some(vec![...])`.
struct OptVecLit<'a, T>(Option<&'a [T]>);

impl<T: std::fmt::Debug> std::fmt::Debug for OptVecLit<'_, T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.0 {
            None => f.write_str("None"),
            Some(v) => f.debug_tuple("Some").field(&VecLit(v)).finish(),
        }
    }
}

/// Splits `data` at its first NUL byte: the main file and the file it refers to (absent
/// when there is no NUL).
fn split_nul(data: &[u8]) -> (&[u8], Option<&[u8]>) {
    match data.iter().position(|&b| b == 0) {
        Some(i) => (&data[..i], Some(&data[i + 1..])),
        None => (data, None),
    }
}
