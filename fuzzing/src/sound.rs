//! The property every loader target checks on a loaded scene.

use limn_load::{load_bytes, Format, LoadOptions};
use limn_scene::Scene;
use std::path::Path;

/// Loads `bytes` as `format` (references resolved next to `path`) and, when that
/// succeeds, checks the scene with [`assert_sound`]. An error is a fine outcome.
pub(crate) fn load_and_check(bytes: &[u8], format: Format, path: &Path) {
    if let Ok(scene) = load_bytes(bytes, format, path, &LoadOptions::default()) {
        assert_sound(&scene);
    }
}

/// Every vertex and normal is finite, every face has at least three corners and every
/// index a face holds (vertex, normal, material, object) is in range.
pub(crate) fn assert_sound(scene: &Scene) {
    for (i, v) in scene.vertices.iter().enumerate() {
        assert!(v.is_finite(), "vertex {i} is not finite: {v:?}");
    }
    for (i, n) in scene.normals.iter().enumerate() {
        assert!(n.is_finite(), "normal {i} is not finite: {n:?}");
    }
    for (i, f) in scene.faces.iter().enumerate() {
        assert!(
            f.vertices.len() >= 3,
            "face {i} has {} corners",
            f.vertices.len()
        );
        for &v in &f.vertices {
            assert!(
                (v as usize) < scene.vertices.len(),
                "face {i}: vertex {v} of {}",
                scene.vertices.len()
            );
        }
        for &n in f.normals.iter().flatten() {
            assert!(
                (n as usize) < scene.normals.len(),
                "face {i}: normal {n} of {}",
                scene.normals.len()
            );
        }
        assert!(
            (f.material as usize) < scene.materials.len(),
            "face {i}: material {} of {}",
            f.material,
            scene.materials.len()
        );
        assert!(
            (f.object as usize) < scene.objects.len(),
            "face {i}: object {} of {}",
            f.object,
            scene.objects.len()
        );
    }
}

/// A path in a folder that does not exist: formats that refer to other files find
/// none there.
pub(crate) fn nowhere(name: &str) -> std::path::PathBuf {
    Path::new("/nonexistent-limn-fuzz").join(name)
}

/// Loads a file that refers to one other: `data` holds the main file, then (after the
/// first NUL byte, if any) the referred file, written as `companion` in a fresh
/// temporary folder beside the main file `main`; then [`load_and_check`].
pub(crate) fn load_with_companion(data: &[u8], format: Format, main: &str, companion: &str) {
    let (head, tail) = crate::split_nul(data);
    // A failure to make the folder is the machine's, not the loader's: skip the case.
    let Ok(dir) = tempfile::tempdir() else {
        return;
    };
    if let Some(tail) = tail {
        if std::fs::write(dir.path().join(companion), tail).is_err() {
            return;
        }
    }
    load_and_check(head, format, &dir.path().join(main));
}
