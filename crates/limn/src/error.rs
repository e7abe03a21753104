//! What can go wrong in a render or a check, as one typed error.
//!
//! Every message names what it is about (the input file and line, the output, the option)
//! and, where a setting lifts a refusal, the setting's name as the command spells it
//! (`--allow-outside`, `--max-fragments`; in Python the same names with `_`).

use std::path::PathBuf;

use limn_check::CheckError;
use limn_depthsort::OrderError;
use limn_load::LoadError;
use limn_paint::{Format, PaintError};
use limn_scene::{CameraError, SceneError};
use limn_zbuffer::ZError;

use crate::output::OutputError;

/// Why a render or a check failed. Nothing is written when one is returned.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The input could not be read or understood.
    #[error("{0}")]
    Load(#[from] LoadError),
    /// The input refers to a file outside its folder (a material library, a buffer, a
    /// texture, a scene file's mesh) and following it was not allowed.
    #[error("{source} (with --allow-outside)")]
    Outside {
        /// The refusal.
        source: LoadError,
    },
    /// The scene has nothing to draw.
    #[error("{input}: the scene has {what}")]
    Empty {
        /// The input's name.
        input: String,
        /// What it lacks.
        what: &'static str,
    },
    /// The scene built in memory is invalid.
    #[error("{input}: {source}")]
    Scene {
        /// The input's name.
        input: String,
        /// Why.
        source: SceneError,
    },
    /// No camera could be made from the options and the scene.
    #[error("{input}: {what}")]
    Camera {
        /// The input's name.
        input: String,
        /// What could not be done ("cannot frame the scene (try --eye)", "invalid camera").
        what: &'static str,
        /// Why, when the camera model says.
        source: Option<CameraError>,
    },
    /// A name the library does not know, in a scene file or an option.
    #[error("unknown {what} `{name}`{place}")]
    UnknownName {
        /// What kind of name (`sort`, `format`, …).
        what: &'static str,
        /// The name given.
        name: String,
        /// Where it was given (" in the scene file", or the accepted names).
        place: String,
    },
    /// An option's value is out of its range.
    #[error("{0}")]
    Value(String),
    /// The output's name says no format limn writes.
    #[error(
        "{output}: unknown output extension `.{ext}` (use .svg, .pdf, .eps, .png, .tikz or {flag})"
    )]
    Extension {
        /// The output.
        output: PathBuf,
        /// Its extension.
        ext: String,
        /// How to name the format instead (`--format`, `format=`).
        flag: &'static str,
    },
    /// Two options that cannot go together.
    #[error("{0}")]
    Conflict(String),
    /// `standalone` was asked for another format than TikZ.
    #[error("--standalone applies to TikZ output only (the format is {0})")]
    Standalone(Format),
    /// An image-space method was asked to write a vector format.
    #[error("--method {0} renders a raster: write a .png")]
    RasterFormat(&'static str),
    /// The scene could not be ordered.
    #[error("{input}{hint}")]
    Order {
        /// The input's name.
        input: String,
        /// The setting that lifts the refusal, if one does.
        hint: &'static str,
        /// Why.
        source: OrderError,
    },
    /// The picture could not be painted.
    #[error(transparent)]
    Paint(#[from] PaintError),
    /// An image-space reference could not be rendered.
    #[error(transparent)]
    Reference(#[from] ZError),
    /// The check could not be made.
    #[error("{input}")]
    Check {
        /// The input's name.
        input: String,
        /// Why.
        source: CheckError,
    },
    /// A comparison with a reference could not be made.
    #[error(transparent)]
    Compare(#[from] CheckError),
    /// An output could not be written (or was refused to protect a file).
    #[error(transparent)]
    Output(#[from] OutputError),
    /// The statistics could not be serialised.
    #[error("cannot write the statistics: {0}")]
    Stats(#[from] serde_json::Error),
}

impl Error {
    /// The error and its causes on one line, `: `-separated, leaving out a cause whose
    /// text the message already contains (many errors repeat their source in their own
    /// text): what the command prints after `limn: error:` and Python raises.
    pub fn message(&self) -> String {
        let mut out = String::new();
        let mut cause: Option<&dyn std::error::Error> = Some(self);
        while let Some(c) = cause {
            let s = c.to_string();
            if !out.contains(&s) {
                if !out.is_empty() {
                    out.push_str(": ");
                }
                out.push_str(&s);
            }
            cause = c.source();
        }
        out
    }

    /// Whether the error is about the file system (an output refused or not written, an
    /// input not read) rather than about what the input or the options say: Python
    /// raises `OSError` for these, `ValueError` for the others.
    pub fn is_file_error(&self) -> bool {
        match self {
            Error::Output(_) => true,
            Error::Load(e) | Error::Outside { source: e } => {
                matches!(
                    e.innermost(),
                    LoadError::Io { .. } | LoadError::OutsideFolder { .. }
                )
            }
            _ => false,
        }
    }

    /// A loading error, with the setting that lifts a refusal to follow a reference.
    pub(crate) fn load(e: LoadError) -> Error {
        if matches!(e.innermost(), LoadError::OutsideFolder { .. }) {
            Error::Outside { source: e }
        } else {
            Error::Load(e)
        }
    }

    /// An ordering error about `input`, with the setting that lifts a fragment limit.
    pub(crate) fn order(e: OrderError, input: &str) -> Error {
        let hint = match e {
            OrderError::TooManyFragments { .. } => " (raise --max-fragments to go on)",
            _ => "",
        };
        Error::Order {
            input: input.to_string(),
            hint,
            source: e,
        }
    }
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::Error;
    use crate::output::OutputError;

    #[test]
    fn causes_repeated_in_the_message_are_left_out() {
        let e = Error::from(OutputError::Write {
            path: PathBuf::from("out.svg"),
            source: std::io::Error::other("disk on fire"),
        });
        assert_eq!(e.message(), "cannot write out.svg: disk on fire");
        assert!(e.is_file_error());
        let e = Error::Value("a.obj:3: disk on fire".into());
        assert_eq!(e.message(), "a.obj:3: disk on fire");
        assert!(!e.is_file_error());
    }
}
