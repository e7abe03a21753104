//! Wavefront OBJ with an MTL library: the input is the OBJ text, then (after the first
//! NUL byte, if any) the bytes of `m.mtl`, written beside it in a fresh temporary
//! folder, so `mtllib m.mtl` reads it. Any input loads or fails with a typed error, and
//! a loaded scene is sound (finite coordinates, indices in range).

use limn_load::Format;

use crate::sound::load_with_companion;

/// Loads the OBJ part of `data` (with the MTL part as `m.mtl`) and checks the scene.
pub fn run(data: &[u8]) {
    load_with_companion(data, Format::Obj, "f.obj", "m.mtl");
}
