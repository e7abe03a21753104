//! The one error type of the loaders, and where in a file an error was found.

use std::fmt;
use std::path::{Path, PathBuf};

use thiserror::Error;

use limn_scene::{CameraError, SceneError};

/// Where in an input file a problem was found: the file, and for text formats the
/// 1-based line; for binary formats a record such as `triangle 17` (numbered from 1)
/// when one applies.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// The file, as given (not canonicalised).
    pub path: PathBuf,
    /// 1-based line number, for text formats.
    pub line: Option<u64>,
    /// A record in a binary format: `triangle 17`, `vertex 3` (numbered from 1, as
    /// people count), or `accessor 2`, `node 0` (glTF's own 0-based indices).
    pub record: Option<String>,
}

impl Location {
    /// The whole file.
    pub fn file(path: &Path) -> Self {
        Location {
            path: path.to_path_buf(),
            line: None,
            record: None,
        }
    }

    /// A line of a text file (1-based).
    pub fn line(path: &Path, line: u64) -> Self {
        Location {
            path: path.to_path_buf(),
            line: Some(line),
            record: None,
        }
    }

    /// A record of a binary file.
    pub fn record(path: &Path, record: String) -> Self {
        Location {
            path: path.to_path_buf(),
            line: None,
            record: Some(record),
        }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.path.display())?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        if let Some(r) = &self.record {
            write!(f, " ({r})")?;
        }
        Ok(())
    }
}

/// Everything that can go wrong while loading a scene. Every variant names the file
/// (and, for text formats, the line) in its [`Location`]; the message starts with it.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum LoadError {
    /// The file could not be read.
    #[error("{at}: cannot read the file: {source}")]
    Io {
        /// The file.
        at: Location,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
    /// The file's extension names no format limn reads.
    #[error(
        "{at}: unsupported file extension {ext:?} (expected obj, stl, ply, gltf, glb or toml)"
    )]
    UnsupportedExtension {
        /// The file.
        at: Location,
        /// The extension found (empty when there is none).
        ext: String,
    },
    /// The file is empty.
    #[error("{at}: the file is empty")]
    Empty {
        /// The file.
        at: Location,
    },
    /// The file ends before the data it announces.
    #[error("{at}: the file ends early: {detail}")]
    Truncated {
        /// Where the data ran out.
        at: Location,
        /// What was expected.
        detail: String,
    },
    /// A count in a header claims more data than the file holds.
    #[error("{at}: the file claims {claimed} {what}, but has room for at most {room}")]
    CountTooLarge {
        /// Where the count is.
        at: Location,
        /// What is counted (`triangles`, `vertex elements`, `bytes`).
        what: String,
        /// The count claimed.
        claimed: u64,
        /// How many fit in the bytes that are there.
        room: u64,
    },
    /// A text format contains binary data (NUL bytes).
    #[error("{at}: binary data in a text file")]
    NotText {
        /// The first line with binary data.
        at: Location,
    },
    /// Malformed content: an unknown statement, a bad number, a missing field.
    #[error("{at}: {message}")]
    Syntax {
        /// Where.
        at: Location,
        /// What is wrong.
        message: String,
    },
    /// A coordinate, normal or other number is NaN or infinite.
    #[error("{at}: non-finite {what} (NaN or infinite)")]
    NonFinite {
        /// Where.
        at: Location,
        /// What holds the bad number (`vertex`, `normal`, `transform`).
        what: String,
    },
    /// A 1-based index is zero.
    #[error("{at}: {what} index 0 (indices start at 1; negative ones count back)")]
    IndexZero {
        /// Where.
        at: Location,
        /// `vertex` or `normal`.
        what: &'static str,
    },
    /// An index refers past the data defined.
    #[error("{at}: {what} index {index} is out of range ({count} defined)")]
    IndexOutOfRange {
        /// Where.
        at: Location,
        /// `vertex` or `normal`.
        what: &'static str,
        /// The index as written in the file.
        index: i64,
        /// How many items were defined at that point.
        count: u64,
    },
    /// A face has fewer than three vertices.
    #[error("{at}: a face has {count} vertices; at least 3 are needed")]
    TooFewVertices {
        /// Where.
        at: Location,
        /// How many it has.
        count: usize,
    },
    /// A referenced file lies outside the folder of the file that names it.
    #[error(
        "{at}: refusing {reference:?}: it lies outside the folder of the file that names it \
         (absolute path, `..`, or a symbolic link leading out); allow it explicitly to load it"
    )]
    OutsideFolder {
        /// The reference.
        at: Location,
        /// The path as written.
        reference: String,
    },
    /// Well-formed input that limn does not read (e.g. sparse glTF accessors).
    #[error("{at}: unsupported: {what}")]
    Unsupported {
        /// Where.
        at: Location,
        /// What.
        what: String,
    },
    /// Well-formed but inconsistent content (failed glTF validation, a bad value in a
    /// scene file).
    #[error("{at}: {message}")]
    Invalid {
        /// Where.
        at: Location,
        /// What is wrong.
        message: String,
    },
    /// A camera given in a scene file cannot be used.
    #[error("{at}: {source}")]
    Camera {
        /// Where the camera is defined.
        at: Location,
        /// Why it cannot be used.
        #[source]
        source: CameraError,
    },
    /// More vertices or faces than 32-bit ids can name.
    #[error("{at}: too large: more than {limit} {what}")]
    TooLarge {
        /// The file.
        at: Location,
        /// What overflowed.
        what: &'static str,
        /// The limit.
        limit: u64,
    },
    /// A texture image named at `at` is missing, unreadable, not PNG or JPEG, corrupt, or
    /// too large.
    #[error("{at}: texture image {image:?}: {message}")]
    Image {
        /// The file and line (or glTF record) naming the image.
        at: Location,
        /// The image as named (a path, or `data:` URI / buffer view for embedded ones).
        image: String,
        /// What is wrong.
        message: String,
    },
    /// A mesh named by a scene file failed to load.
    #[error("{at}: in the mesh named here: {source}")]
    InMesh {
        /// The scene file and the line naming the mesh.
        at: Location,
        /// The mesh's own error.
        #[source]
        source: Box<LoadError>,
    },
    /// The loaded scene breaks an invariant (a bug in a loader).
    #[error("{at}: internal error, the loaded scene is inconsistent: {source}")]
    Internal {
        /// The file.
        at: Location,
        /// The broken invariant.
        #[source]
        source: SceneError,
    },
}

impl LoadError {
    /// Where the error was found (for [`LoadError::InMesh`], the scene file's line).
    pub fn location(&self) -> &Location {
        match self {
            LoadError::Io { at, .. }
            | LoadError::UnsupportedExtension { at, .. }
            | LoadError::Empty { at }
            | LoadError::Truncated { at, .. }
            | LoadError::CountTooLarge { at, .. }
            | LoadError::NotText { at }
            | LoadError::Syntax { at, .. }
            | LoadError::NonFinite { at, .. }
            | LoadError::IndexZero { at, .. }
            | LoadError::IndexOutOfRange { at, .. }
            | LoadError::TooFewVertices { at, .. }
            | LoadError::OutsideFolder { at, .. }
            | LoadError::Unsupported { at, .. }
            | LoadError::Invalid { at, .. }
            | LoadError::Camera { at, .. }
            | LoadError::TooLarge { at, .. }
            | LoadError::Image { at, .. }
            | LoadError::InMesh { at, .. }
            | LoadError::Internal { at, .. } => at,
        }
    }

    /// The innermost error: for [`LoadError::InMesh`] the mesh's own error, else `self`.
    pub fn innermost(&self) -> &LoadError {
        match self {
            LoadError::InMesh { source, .. } => source.innermost(),
            e => e,
        }
    }

    /// Shorthand for a syntax error at a line.
    pub(crate) fn syntax(path: &Path, line: u64, message: impl Into<String>) -> Self {
        LoadError::Syntax {
            at: Location::line(path, line),
            message: message.into(),
        }
    }
}
