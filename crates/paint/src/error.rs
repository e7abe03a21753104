//! Why a picture could not be painted.

/// Why a picture could not be painted.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PaintError {
    /// Writing to the output failed.
    #[error("cannot write the picture: {0}")]
    Io(#[from] std::io::Error),
    /// The page size cannot be painted.
    #[error("picture size {width}x{height} is not supported: {reason}")]
    Size {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A picture-wide style value is unusable.
    #[error("invalid {what}: {reason}")]
    Style {
        /// Which value (`"background"`, `"outline"`).
        what: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The PNG encoder failed.
    #[error("cannot encode the PNG: {0}")]
    Png(String),
}
