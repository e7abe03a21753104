//! Writing outputs without ever destroying a file.
//!
//! * `-` is standard output.
//! * A symbolic link is followed: the picture goes to the file it points to, and the link
//!   stays a link.
//! * A device, a FIFO or a socket is written directly (no temporary file, no rename), so
//!   `-o /dev/null` or a pipe's reader works.
//! * A regular file (new or replaced) is written into a temporary file beside it and
//!   renamed into place only when everything was written: a failed run leaves no file
//!   behind, and a replaced file keeps its permissions.
//! * Refused with a clear error: a file the scene was read from (the input, its material
//!   libraries, buffers, a scene file's meshes), a read-only file, a folder.

use std::fs::{File, Metadata, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::error::Error;

/// Links followed at most before giving up (as the operating system does).
const MAX_LINKS: usize = 40;

/// Why an output was not written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum OutputError {
    /// The output is one of the files the scene was read from.
    #[error(
        "refusing to write {path}: the scene was read from {input} (choose another output with -o)"
    )]
    IsInput {
        /// The output.
        path: PathBuf,
        /// The input it is.
        input: PathBuf,
    },
    /// The output is a folder.
    #[error("cannot write {path}: it is a folder")]
    Folder {
        /// The output.
        path: PathBuf,
    },
    /// The output is a read-only file.
    #[error("refusing to replace {path}: the file is read-only")]
    ReadOnly {
        /// The output.
        path: PathBuf,
    },
    /// Following the output's symbolic links did not end.
    #[error("cannot write {path}: more than {MAX_LINKS} symbolic links")]
    Links {
        /// The output.
        path: PathBuf,
    },
    /// A symbolic link on the way could not be read.
    #[error("cannot read the link {path}")]
    Link {
        /// The link.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The output could not be opened.
    #[error("cannot open {path} for writing")]
    Open {
        /// The output.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// No temporary file could be made beside the output.
    #[error("cannot create a file in {dir}")]
    Create {
        /// The folder.
        dir: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Writing, flushing or renaming into place failed.
    #[error("cannot write {path}")]
    Write {
        /// The output.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Writing to standard output failed.
    #[error("cannot write to standard output")]
    Stdout {
        /// Why.
        source: std::io::Error,
    },
}

/// Where and how a write goes.
enum Plan {
    /// Standard output.
    Stdout,
    /// Straight into a device, FIFO or socket at this path.
    Direct(PathBuf),
    /// A regular file at this path (symbolic links resolved), replacing the one with
    /// this metadata if any.
    Replace(PathBuf, Option<Metadata>),
}

/// Checks, before any work is done, that `path` may be written (see the module docs):
/// so that a refused output costs nothing and leaves no other output behind.
pub fn check_writable(path: &Path, read: &[PathBuf]) -> Result<(), OutputError> {
    plan(path, read).map(|_| ())
}

/// Writes what `fill` produces to `path` (`-` = standard output), refusing to write over
/// any of the files in `read` (see the module docs). An error of `fill` is returned as
/// it is, and nothing is left at `path`.
pub fn write_atomic<T>(
    path: &Path,
    read: &[PathBuf],
    fill: impl FnOnce(&mut dyn Write) -> Result<T, Error>,
) -> Result<T, Error> {
    match plan(path, read)? {
        Plan::Stdout => {
            let stdout = std::io::stdout();
            let mut lock = stdout.lock();
            let mut buf = std::io::BufWriter::new(&mut lock);
            let v = fill(&mut buf)?;
            buf.flush()
                .map_err(|source| OutputError::Stdout { source })?;
            Ok(v)
        }
        Plan::Direct(target) => write_direct(path, &target, fill),
        Plan::Replace(target, existing) => write_replacing(path, &target, existing.as_ref(), fill),
    }
}

fn plan(path: &Path, read: &[PathBuf]) -> Result<Plan, OutputError> {
    if path.as_os_str() == "-" {
        return Ok(Plan::Stdout);
    }
    let target = follow_links(path)?;
    let existing = match std::fs::metadata(&target) {
        Ok(m) => Some(m),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
        Err(source) => {
            return Err(OutputError::Write {
                path: path.to_path_buf(),
                source,
            })
        }
    };
    if let Some(meta) = &existing {
        if let Some(input) = read.iter().find(|f| same_file(meta, f)) {
            return Err(OutputError::IsInput {
                path: path.to_path_buf(),
                input: input.clone(),
            });
        }
        if meta.is_dir() {
            return Err(OutputError::Folder {
                path: path.to_path_buf(),
            });
        }
        if !meta.is_file() {
            return Ok(Plan::Direct(target));
        }
        if meta.permissions().readonly() {
            return Err(OutputError::ReadOnly {
                path: path.to_path_buf(),
            });
        }
    }
    Ok(Plan::Replace(target, existing))
}

/// The path a write to `path` lands on: symbolic links followed (a dangling link names
/// the file to create).
fn follow_links(path: &Path) -> Result<PathBuf, OutputError> {
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p).map_err(|source| OutputError::Link {
                    path: p.clone(),
                    source,
                })?;
                p = if to.is_absolute() {
                    to
                } else {
                    p.parent().unwrap_or(Path::new(".")).join(to)
                };
            }
            _ => return Ok(p),
        }
    }
    Err(OutputError::Links {
        path: path.to_path_buf(),
    })
}

/// Whether `meta` describes the same file as `other` (same device and inode on Unix,
/// the same canonical path elsewhere).
fn same_file(meta: &Metadata, other: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        std::fs::metadata(other).is_ok_and(|m| m.dev() == meta.dev() && m.ino() == meta.ino())
    }
    #[cfg(not(unix))]
    {
        let _ = meta;
        false
    }
}

/// Writes straight into a device, FIFO or socket.
fn write_direct<T>(
    path: &Path,
    target: &Path,
    fill: impl FnOnce(&mut dyn Write) -> Result<T, Error>,
) -> Result<T, Error> {
    let file = OpenOptions::new()
        .write(true)
        .open(target)
        .map_err(|source| OutputError::Open {
            path: path.to_path_buf(),
            source,
        })?;
    let mut w = std::io::BufWriter::new(file);
    let v = fill(&mut w)?;
    w.flush().map_err(write_error(path))?;
    Ok(v)
}

/// Writes a regular file through a temporary file renamed over `target`.
fn write_replacing<T>(
    path: &Path,
    target: &Path,
    existing: Option<&Metadata>,
    fill: impl FnOnce(&mut dyn Write) -> Result<T, Error>,
) -> Result<T, Error> {
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let tmp = tempfile::Builder::new()
        .prefix(".limn-")
        .suffix(".tmp")
        .tempfile_in(dir)
        .map_err(|source| OutputError::Create {
            dir: dir.to_path_buf(),
            source,
        })?;
    let mut w = std::io::BufWriter::new(tmp);
    let v = fill(&mut w)?;
    let tmp = w
        .into_inner()
        .map_err(|e| write_error(path)(e.into_error()))?;
    tmp.as_file().sync_all().map_err(write_error(path))?;
    set_permissions(tmp.as_file(), existing);
    tmp.persist(target)
        .map_err(|e| write_error(path)(e.error))?;
    Ok(v)
}

/// The error of a failed write to `path`.
fn write_error(path: &Path) -> impl Fn(std::io::Error) -> OutputError + '_ {
    move |source| OutputError::Write {
        path: path.to_path_buf(),
        source,
    }
}

/// Temporary files are private (0600): a replaced file keeps its permissions, a new one
/// gets the usual 0644.
fn set_permissions(file: &File, existing: Option<&Metadata>) {
    let perms = match existing {
        Some(m) => m.permissions(),
        None => {
            #[cfg(unix)]
            {
                use std::os::unix::fs::PermissionsExt;
                std::fs::Permissions::from_mode(0o644)
            }
            #[cfg(not(unix))]
            {
                return;
            }
        }
    };
    let _ = file.set_permissions(perms);
}
