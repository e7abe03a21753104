//! Wavefront OBJ with an MTL library: the input is the OBJ text, then (after the first
//! NUL byte, if any) the bytes of `m.mtl`, written beside it in a fresh temporary
//! folder, so `mtllib m.mtl` reads it. Any input loads or fails with a typed error, and
//! a loaded scene is sound (finite coordinates, indices in range).

use limn_load::Format;

use crate::sound::load_and_check;
use crate::split_nul;

/// Loads the OBJ part of `data` (with the MTL part as `m.mtl`) and checks the scene.
pub fn run(data: &[u8]) {
    let (obj, mtl) = split_nul(data);
    // A failure to make the folder is the machine's, not the loader's: skip the case.
    let Ok(dir) = tempfile::tempdir() else {
        return;
    };
    if let Some(mtl) = mtl {
        if std::fs::write(dir.path().join("m.mtl"), mtl).is_err() {
            return;
        }
    }
    load_and_check(obj, Format::Obj, &dir.path().join("f.obj"));
}
