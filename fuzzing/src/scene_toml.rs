//! limn's TOML scene files: the input is the scene file, then (after the first NUL
//! byte, if any) the bytes of the OBJ mesh `m.obj`, written beside it in a fresh
//! temporary folder, so `path = "m.obj"` reads it. Any input loads or fails with a typed
//! error, and a loaded scene is sound (finite coordinates, indices in range).

use limn_load::Format;

use crate::sound::load_with_companion;

/// Loads the TOML part of `data` (with the OBJ part as `m.obj`) and checks the scene.
pub fn run(data: &[u8]) {
    load_with_companion(data, Format::Toml, "s.toml", "m.obj");
}
