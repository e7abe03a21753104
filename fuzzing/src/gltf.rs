//! glTF 2.0: bytes starting with the GLB magic `glTF` are loaded as a binary container,
//! others as glTF JSON. Buffers can come from `data:` URIs or the GLB chunk; relative
//! URIs point into a folder that does not exist. Any bytes load or fail with a typed
//! error, and a loaded scene is sound (finite coordinates, indices in range).

use limn_load::Format;

use crate::sound::{load_and_check, nowhere};

/// Loads `data` as glTF JSON or GLB and checks the scene.
pub fn run(data: &[u8]) {
    if data.starts_with(b"glTF") {
        load_and_check(data, Format::Glb, &nowhere("f.glb"));
    } else {
        load_and_check(data, Format::Gltf, &nowhere("f.gltf"));
    }
}
