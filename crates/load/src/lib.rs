//! File loaders: Wavefront OBJ (+MTL), STL, PLY, glTF 2.0 and limn's TOML scene files.
//!
//! [`load`] picks the format from the file's extension; [`load_bytes`] parses bytes
//! already in memory (references to other files are still resolved against the given
//! path's folder). Every error is a [`LoadError`] naming the file and, for text formats,
//! the 1-based line. No input makes a loader panic, and no count read from a file is
//! trusted for an allocation before the file is known to hold that much data.
//!
//! Face ids: faces appear in [`Scene::faces`] in the order the file gives them.
//!
//! ```no_run
//! use limn_load::{load, LoadOptions};
//! use std::path::Path;
//!
//! let scene = load(Path::new("bunny.obj"), &LoadOptions::default())?;
//! for w in &scene.warnings {
//!     eprintln!("warning: {w}");
//! }
//! # Ok::<(), limn_load::LoadError>(())
//! ```

mod error;
mod gltf;
mod image;
mod library_loader;
mod mtl;
mod name_table;
mod obj;
mod ply;
mod refs;
mod scenefile;
mod stl;
mod text;
mod transform;

use std::path::Path;

pub use error::{LoadError, Location};
pub use scenefile::{load_scene_file, SceneOptions};

use limn_scene::Scene;

/// Options for every loader.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LoadOptions {
    /// Follow references (an OBJ's `mtllib`, a glTF buffer `uri`, a scene file's mesh
    /// paths) that lead outside the folder of the file naming them: absolute paths, `..`
    /// above the folder, or symbolic links pointing out. Default `false`: such
    /// references are refused with [`LoadError::OutsideFolder`].
    pub allow_outside: bool,
}

/// The file formats limn reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Format {
    /// Wavefront OBJ, with MTL material libraries.
    Obj,
    /// STL, ASCII or binary (told apart by content, not extension).
    Stl,
    /// PLY, ASCII or binary of either byte order.
    Ply,
    /// glTF 2.0 JSON (`.gltf`).
    Gltf,
    /// glTF 2.0 binary container (`.glb`).
    Glb,
    /// limn's TOML scene file.
    Toml,
}

impl Format {
    /// The format named by a path's extension (case-insensitive), if any.
    pub fn from_path(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        Some(match ext.as_str() {
            "obj" => Format::Obj,
            "stl" => Format::Stl,
            "ply" => Format::Ply,
            "gltf" => Format::Gltf,
            "glb" => Format::Glb,
            "toml" => Format::Toml,
            _ => return None,
        })
    }
}

/// Loads the scene in `path`, choosing the loader by the file's extension (`obj`, `stl`,
/// `ply`, `gltf`, `glb`, `toml`). A scene file (`toml`) yields its meshes, lights and,
/// when it has a `[camera]` table, `scene.camera`; use [`load_scene_file`] to get its
/// output options too. Warnings (a missing MTL file, ignored statements) are collected
/// in `scene.warnings`.
pub fn load(path: &Path, opts: &LoadOptions) -> Result<Scene, LoadError> {
    let format = format_of(path)?;
    if format == Format::Toml {
        return load_scene_file(path, opts).map(|(scene, _)| scene);
    }
    let bytes = refs::read(path)?;
    let mut scene = load_bytes(&bytes, format, path, opts)?;
    scene.files.insert(0, path.to_path_buf());
    Ok(scene)
}

/// Parses `bytes` as `format`. `path` names the data in messages, and its folder is
/// where references to other files (MTL libraries, glTF buffers, a scene file's meshes)
/// are looked up.
pub fn load_bytes(
    bytes: &[u8],
    format: Format,
    path: &Path,
    opts: &LoadOptions,
) -> Result<Scene, LoadError> {
    if bytes.is_empty() {
        return Err(LoadError::Empty {
            at: Location::file(path),
        });
    }
    let scene = match format {
        Format::Obj => obj::parse(bytes, path, opts)?,
        Format::Stl => stl::parse(bytes, path)?,
        Format::Ply => ply::parse(bytes, path)?,
        Format::Gltf | Format::Glb => gltf::parse(bytes, path, opts)?,
        Format::Toml => scenefile::parse(bytes, path, opts)?.0,
    };
    checked(scene, path)
}

fn format_of(path: &Path) -> Result<Format, LoadError> {
    Format::from_path(path).ok_or_else(|| LoadError::UnsupportedExtension {
        at: Location::file(path),
        ext: path
            .extension()
            .map(|e| e.to_string_lossy().into_owned())
            .unwrap_or_default(),
    })
}

/// Runs [`Scene::validate`] on a loaded scene: a failure is a loader bug, reported
/// rather than passed on.
fn checked(scene: Scene, path: &Path) -> Result<Scene, LoadError> {
    scene.validate().map_err(|source| LoadError::Internal {
        at: Location::file(path),
        source,
    })?;
    Ok(scene)
}

/// The name of the default object of a file: its stem.
fn stem(path: &Path) -> String {
    path.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "mesh".to_string())
}

/// Fails when a scene would need more than `u32::MAX` ids of something.
fn check_u32(len: usize, what: &'static str, path: &Path) -> Result<(), LoadError> {
    if len >= u32::MAX as usize {
        return Err(LoadError::TooLarge {
            at: Location::file(path),
            what,
            limit: u32::MAX as u64 - 1,
        });
    }
    Ok(())
}
