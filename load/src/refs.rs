//! Reading files, and resolving references from one file to another (an OBJ's
//! `mtllib`, a glTF buffer's `uri`, a scene file's meshes) without leaving the folder of
//! the file that names them unless the caller allows it.

use std::path::{Component, Path, PathBuf};

use super::{LoadError, LoadOptions, Location};

/// Reads a whole file.
pub(crate) fn read(path: &Path) -> Result<Vec<u8>, LoadError> {
    std::fs::read(path).map_err(|source| LoadError::Io {
        at: Location::file(path),
        source,
    })
}

/// The folder holding `file` (`.` for a bare file name).
pub(crate) fn folder_of(file: &Path) -> PathBuf {
    match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Resolves `reference` (as written in the file at `at`) against the folder of
/// `at.path`. Refused, unless `opts.allow_outside`, when it is absolute, when `..` leads
/// above the folder, or when the file exists and its real path (symbolic links resolved)
/// lies outside the folder's real path. The returned path need not exist.
pub(crate) fn resolve(
    reference: &str,
    at: &Location,
    opts: &LoadOptions,
) -> Result<PathBuf, LoadError> {
    let folder = folder_of(&at.path);
    let rel = Path::new(reference);
    let refuse = || LoadError::OutsideFolder {
        at: at.clone(),
        reference: reference.to_string(),
    };
    if reference.is_empty() {
        return Err(LoadError::Syntax {
            at: at.clone(),
            message: "empty file reference".into(),
        });
    }
    if opts.allow_outside {
        return Ok(folder.join(rel));
    }
    let mut depth: i64 = 0;
    for c in rel.components() {
        match c {
            Component::Prefix(_) | Component::RootDir => return Err(refuse()),
            Component::CurDir => {}
            Component::ParentDir => {
                depth -= 1;
                if depth < 0 {
                    return Err(refuse());
                }
            }
            Component::Normal(_) => depth += 1,
        }
    }
    let full = folder.join(rel);
    if let (Ok(real), Ok(real_folder)) = (full.canonicalize(), folder.canonicalize()) {
        if !real.starts_with(&real_folder) {
            return Err(refuse());
        }
    }
    Ok(full)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at() -> Location {
        Location::line(Path::new("dir/model.obj"), 3)
    }

    #[test]
    fn lexical_escapes_are_refused() {
        let o = LoadOptions::default();
        for r in ["../x.mtl", "a/../../x.mtl", "/etc/passwd"] {
            let e = resolve(r, &at(), &o).unwrap_err();
            assert!(matches!(e, LoadError::OutsideFolder { .. }), "{r}");
            assert!(e.to_string().contains("dir/model.obj:3"));
        }
        assert_eq!(
            resolve("sub/../x.mtl", &at(), &o).unwrap(),
            Path::new("dir/sub/../x.mtl")
        );
        let allow = LoadOptions {
            allow_outside: true,
        };
        assert!(resolve("../x.mtl", &at(), &allow).is_ok());
    }
}
