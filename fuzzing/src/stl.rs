//! STL (ASCII or binary, told apart by content): any bytes load or fail with a typed
//! error, and a loaded scene is sound (finite coordinates, indices in range).

use limn_load::Format;

use crate::sound::{load_and_check, nowhere};

/// Loads `data` as an STL file and checks the scene.
pub fn run(data: &[u8]) {
    load_and_check(data, Format::Stl, &nowhere("f.stl"));
}
