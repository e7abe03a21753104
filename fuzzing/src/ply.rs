//! PLY (ASCII or binary of either byte order): any bytes load or fail with a typed
//! error, and a loaded scene is sound (finite coordinates, indices in range).

use limn_load::Format;

use crate::sound::{load_and_check, nowhere};

/// Loads `data` as a PLY file and checks the scene.
pub fn run(data: &[u8]) {
    load_and_check(data, Format::Ply, &nowhere("f.ply"));
}
