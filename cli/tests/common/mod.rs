//! Helpers for running the `limn` binary in a temporary folder.

// Each test file uses a different subset of these helpers.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// What one run of `limn` did.
pub struct Run {
    /// Exit status (`-1` when killed by a signal).
    pub code: i32,
    /// Everything written to standard output.
    pub stdout: Vec<u8>,
    /// Everything written to standard error.
    pub stderr: String,
}

impl Run {
    /// Standard output as text.
    pub fn stdout_text(&self) -> String {
        String::from_utf8_lossy(&self.stdout).into_owned()
    }
}

/// Runs `limn ARGS` with `dir` as the current folder.
pub fn limn(dir: &Path, args: &[&str]) -> Run {
    let out = Command::new(env!("CARGO_BIN_EXE_limn"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("cannot run limn");
    Run {
        code: out.status.code().unwrap_or(-1),
        stdout: out.stdout,
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// A fresh temporary folder.
pub fn tempdir() -> tempfile::TempDir {
    tempfile::tempdir().expect("cannot create a temporary folder")
}

/// Writes `contents` to `dir/name` (creating parent folders) and returns the path.
pub fn put(dir: &Path, name: &str, contents: impl AsRef<[u8]>) -> PathBuf {
    let p = dir.join(name);
    if let Some(parent) = p.parent() {
        std::fs::create_dir_all(parent).unwrap();
    }
    std::fs::write(&p, contents).unwrap();
    p
}

/// Names of leftover temporary output files (`.limn-*.tmp`) in `dir`.
pub fn stray_temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".limn-") && n.ends_with(".tmp"))
        .collect()
}

/// Asserts that a run failed with status `code`, that `out` (relative to `dir`) was not
/// created and that no temporary file was left in its folder.
pub fn assert_failed_cleanly(run: &Run, code: i32, dir: &Path, out: &str) {
    assert_eq!(
        run.code, code,
        "expected exit status {code}; stderr: {}",
        run.stderr
    );
    let out = dir.join(out);
    assert!(
        !out.exists(),
        "{} exists after a failed run; stderr: {}",
        out.display(),
        run.stderr
    );
    let folder = out.parent().unwrap();
    let stray = stray_temporaries(folder);
    assert!(stray.is_empty(), "temporary files left: {stray:?}");
}

/// A triangle in the plane z = 0, as OBJ text.
pub const TRIANGLE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

/// Two triangles passing through each other along y = 0, both covering the middle of
/// the picture when seen from +z (object `a`: z = 0; object `b`: tilted).
pub const CROSSING_OBJ: &str = "\
o a
v -1 -1 0
v 1 -1 0
v 0 1 0
f 1 2 3
o b
v -1 -1 0.5
v 1 -1 0.5
v 0 1 -0.5
f 4 5 6
";

/// A closed unit cube from (1.5, -0.5, -0.5), faces wound outwards, with
/// relative (negative) indices so it can follow other OBJ text.
pub const CUBE_OBJ: &str = "\
o cube
v 1.5 -0.5 -0.5
v 2.5 -0.5 -0.5
v 2.5 0.5 -0.5
v 1.5 0.5 -0.5
v 1.5 -0.5 0.5
v 2.5 -0.5 0.5
v 2.5 0.5 0.5
v 1.5 0.5 0.5
f -8 -5 -6 -7
f -4 -3 -2 -1
f -8 -7 -3 -4
f -5 -1 -2 -6
f -8 -4 -1 -5
f -7 -6 -2 -3
";

/// PNG signature.
pub const PNG_MAGIC: &[u8] = b"\x89PNG\r\n\x1a\n";
