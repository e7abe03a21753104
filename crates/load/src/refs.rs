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
///
/// Backslashes are folder separators (Windows exporters write `.\tex.jpg` and
/// `maps\tex.jpg`) unless a file of that very name exists; a reference starting with
/// a drive letter (`C:\…`, `C:/…`) is absolute. The folder rule applies to the path
/// so read.
pub(crate) fn resolve(
    reference: &str,
    at: &Location,
    opts: &LoadOptions,
) -> Result<PathBuf, LoadError> {
    let folder = folder_of(&at.path);
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
    let slashed;
    let rel = if reference.contains('\\') && !folder.join(reference).exists() {
        slashed = reference.replace('\\', "/");
        Path::new(&slashed)
    } else {
        Path::new(reference)
    };
    if opts.allow_outside {
        return Ok(folder.join(rel));
    }
    if has_drive_letter(reference) {
        return Err(refuse());
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

/// Whether `reference` starts with a Windows drive letter and a separator (`C:\`,
/// `c:/`): absolute on Windows, whatever it means elsewhere.
fn has_drive_letter(reference: &str) -> bool {
    matches!(reference.as_bytes(), [d, b':', b'\\' | b'/', ..] if d.is_ascii_alphabetic())
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
        for r in [
            "..\\x.mtl",
            "a\\..\\..\\x.mtl",
            "C:\\x.mtl",
            "c:/x.mtl",
            "\\\\server\\x.mtl",
        ] {
            let e = resolve(r, &at(), &o).unwrap_err();
            assert!(matches!(e, LoadError::OutsideFolder { .. }), "{r}");
        }
        let allow = LoadOptions {
            allow_outside: true,
        };
        assert!(resolve("../x.mtl", &at(), &allow).is_ok());
    }

    #[test]
    fn backslashes_separate_folders_unless_a_file_has_that_name() {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        std::fs::create_dir(d.join("maps")).unwrap();
        std::fs::write(d.join("tex.jpg"), b"x").unwrap();
        std::fs::write(d.join("maps").join("a.png"), b"x").unwrap();
        std::fs::write(d.join("odd\\name.png"), b"x").unwrap();
        let at = Location::line(&d.join("m.mtl"), 2);
        let o = LoadOptions::default();
        for (r, want) in [
            (".\\tex.jpg", d.join("tex.jpg")),
            ("maps\\a.png", d.join("maps").join("a.png")),
            ("odd\\name.png", d.join("odd\\name.png")),
        ] {
            let got = resolve(r, &at, &o).unwrap();
            assert!(got.is_file(), "{r}: {}", got.display());
            assert_eq!(
                got.canonicalize().unwrap(),
                want.canonicalize().unwrap(),
                "{r}"
            );
        }
    }
}
