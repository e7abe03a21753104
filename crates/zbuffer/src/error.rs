//! The crate's error type.

use limn_scene::{CameraError, SceneError};
use thiserror::Error;

/// Everything that can go wrong while rendering, comparing or writing images.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum ZError {
    /// The scene breaks an invariant (index out of range, non-finite coordinate, ...).
    #[error("invalid scene: {0}")]
    Scene(#[from] SceneError),
    /// The camera cannot be used.
    #[error("invalid camera: {0}")]
    Camera(#[from] CameraError),
    /// Near and far planes must satisfy `0 < near < far < ∞`.
    #[error("near {near} and far {far} planes must satisfy 0 < near < far < inf")]
    BadDepthRange {
        /// The near distance given.
        near: f64,
        /// The far distance given.
        far: f64,
    },
    /// A coordinate lies outside the range a method accepts (see [`crate::MAX_COORD`] and
    /// [`crate::MIN_RAYCAST_COORD`] for ray casting's shadow rays).
    #[error("{what} coordinate {value:e} is outside the accepted range")]
    OutOfRange {
        /// Which input the coordinate belongs to ("vertex", "eye", "ray").
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// Shadow map options out of range (size 1 to 16384, bias finite and ≥ 0).
    #[error("shadow map of size {size} with bias {bias}: the size must be 1 to 16384 and the bias finite and >= 0")]
    BadShadowMap {
        /// The size asked for.
        size: u32,
        /// The bias asked for.
        bias: f64,
    },
    /// The A-buffer would need more than 2³² − 1 fragments.
    #[error("the A-buffer needs more than 2^32 - 1 fragments")]
    TooManyFragments,
    /// The picture has more pixels than [`crate::MAX_PIXELS`].
    #[error(
        "picture of {0}x{1} pixels: the image-space methods render at most 268,435,456 pixels"
    )]
    TooManyPixels(u32, u32),
    /// Two images that must have the same size do not.
    #[error("image sizes differ: {0}x{1} and {2}x{3}")]
    SizeMismatch(u32, u32, u32, u32),
    /// PNG encoding failed.
    #[error("PNG encoding failed: {0}")]
    Png(String),
    /// Writing a file failed.
    #[error("cannot write {path}: {message}")]
    Io {
        /// The file.
        path: String,
        /// The operating system's message.
        message: String,
    },
}
