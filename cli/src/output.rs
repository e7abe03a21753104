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

use anyhow::{bail, Context, Result};

/// Links followed at most before giving up (as the operating system does).
const MAX_LINKS: usize = 40;

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
pub fn check_writable(path: &Path, read: &[PathBuf]) -> Result<()> {
    plan(path, read).map(|_| ())
}

/// Writes what `fill` produces to `path` (`-` = standard output), refusing to write over
/// any of the files in `read` (see the module docs).
pub fn write_atomic<T>(
    path: &Path,
    read: &[PathBuf],
    fill: impl FnOnce(&mut dyn Write) -> Result<T>,
) -> Result<T> {
    match plan(path, read)? {
        Plan::Stdout => {
            let stdout = std::io::stdout();
            let mut lock = stdout.lock();
            let mut buf = std::io::BufWriter::new(&mut lock);
            let v = fill(&mut buf)?;
            buf.flush().context("cannot write to standard output")?;
            Ok(v)
        }
        Plan::Direct(target) => write_direct(path, &target, fill),
        Plan::Replace(target, existing) => write_replacing(path, &target, existing.as_ref(), fill),
    }
}

fn plan(path: &Path, read: &[PathBuf]) -> Result<Plan> {
    if path.as_os_str() == "-" {
        return Ok(Plan::Stdout);
    }
    let target = follow_links(path)?;
    let existing = match std::fs::metadata(&target) {
        Ok(m) => Some(m),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
        Err(e) => return Err(e).with_context(|| format!("cannot write {}", path.display())),
    };
    if let Some(meta) = &existing {
        if let Some(input) = read.iter().find(|f| same_file(meta, f)) {
            bail!(
                "refusing to write {}: the scene was read from {} (choose another output with -o)",
                path.display(),
                input.display()
            );
        }
        if meta.is_dir() {
            bail!("cannot write {}: it is a folder", path.display());
        }
        if !meta.is_file() {
            return Ok(Plan::Direct(target));
        }
        if meta.permissions().readonly() {
            bail!(
                "refusing to replace {}: the file is read-only",
                path.display()
            );
        }
    }
    Ok(Plan::Replace(target, existing))
}

/// The path a write to `path` lands on: symbolic links followed (a dangling link names
/// the file to create).
fn follow_links(path: &Path) -> Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p)
                    .with_context(|| format!("cannot read the link {}", p.display()))?;
                p = if to.is_absolute() {
                    to
                } else {
                    p.parent().unwrap_or(Path::new(".")).join(to)
                };
            }
            _ => return Ok(p),
        }
    }
    bail!(
        "cannot write {}: more than {MAX_LINKS} symbolic links",
        path.display()
    )
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
    fill: impl FnOnce(&mut dyn Write) -> Result<T>,
) -> Result<T> {
    let file = OpenOptions::new()
        .write(true)
        .open(target)
        .with_context(|| format!("cannot open {} for writing", path.display()))?;
    let mut w = std::io::BufWriter::new(file);
    let v = fill(&mut w)?;
    w.flush()
        .with_context(|| format!("cannot write {}", path.display()))?;
    Ok(v)
}

/// Writes a regular file through a temporary file renamed over `target`.
fn write_replacing<T>(
    path: &Path,
    target: &Path,
    existing: Option<&Metadata>,
    fill: impl FnOnce(&mut dyn Write) -> Result<T>,
) -> Result<T> {
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let tmp = tempfile::Builder::new()
        .prefix(".limn-")
        .suffix(".tmp")
        .tempfile_in(dir)
        .with_context(|| format!("cannot create a file in {}", dir.display()))?;
    let mut w = std::io::BufWriter::new(tmp);
    let v = fill(&mut w)?;
    let tmp = w
        .into_inner()
        .map_err(|e| e.into_error())
        .with_context(|| format!("cannot write {}", path.display()))?;
    tmp.as_file()
        .sync_all()
        .with_context(|| format!("cannot write {}", path.display()))?;
    set_permissions(tmp.as_file(), existing);
    tmp.persist(target)
        .map_err(|e| e.error)
        .with_context(|| format!("cannot write {}", path.display()))?;
    Ok(v)
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
