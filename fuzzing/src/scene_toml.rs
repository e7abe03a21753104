//! limn's TOML scene files: the input is the scene file, then (after the first NUL
//! byte, if any) the bytes of the OBJ mesh `m.obj`, written beside it in a fresh
//! temporary folder, so `path = "m.obj"` reads it. Any input loads or fails with a typed
//! error, and a loaded scene is sound (finite coordinates, indices in range).

use limn_load::Format;

use crate::sound::load_and_check;
use crate::split_nul;

/// Loads the TOML part of `data` (with the OBJ part as `m.obj`) and checks the scene.
pub fn run(data: &[u8]) {
    let (toml, mesh) = split_nul(data);
    // A failure to make the folder is the machine's, not the loader's: skip the case.
    let Ok(dir) = tempfile::tempdir() else {
        return;
    };
    if let Some(mesh) = mesh {
        if std::fs::write(dir.path().join("m.obj"), mesh).is_err() {
            return;
        }
    }
    load_and_check(toml, Format::Toml, &dir.path().join("s.toml"));
}
