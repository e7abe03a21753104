//! What a rendering is asked for: the image-space method and the options shared by
//! every method.

use std::fmt;
use std::str::FromStr;
use std::sync::Arc;

use thiserror::Error;

use crate::DepthFormat;

/// An image-space hidden-surface method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// Full-screen z-buffer.
    ZBuffer,
    /// Scan-line z-buffer (one row of depth); the same ids as [`Method::ZBuffer`].
    ScanLine,
    /// Per-pixel fragment lists, for transparency.
    ABuffer,
    /// Warnock's area subdivision.
    Warnock,
    /// One exact ray per pixel centre (the arbiter).
    RayCast,
}

impl Method {
    /// Every method.
    pub const ALL: [Method; 5] = [
        Method::ZBuffer,
        Method::ScanLine,
        Method::ABuffer,
        Method::Warnock,
        Method::RayCast,
    ];

    /// The method's name as used on command lines: `zbuffer`, `scanline`, `abuffer`,
    /// `warnock`, `raycast`.
    pub fn name(self) -> &'static str {
        match self {
            Method::ZBuffer => "zbuffer",
            Method::ScanLine => "scanline",
            Method::ABuffer => "abuffer",
            Method::Warnock => "warnock",
            Method::RayCast => "raycast",
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A method name that [`Method::from_str`] does not know.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("unknown method {0:?} (expected zbuffer, scanline, abuffer, warnock or raycast)")]
pub struct ParseMethodError(pub String);

impl FromStr for Method {
    type Err = ParseMethodError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Method::ALL
            .into_iter()
            .find(|m| m.name().eq_ignore_ascii_case(s))
            .ok_or_else(|| ParseMethodError(s.to_string()))
    }
}

/// Options shared by every method.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// How depth is stored (z-buffer, scan-line, Warnock and A-buffer ordering; ray
    /// casting is always exact). Default [`DepthFormat::F64`].
    pub depth: DepthFormat,
    /// Drop faces whose plane has the eye strictly behind it. Default `false`.
    pub cull_back_faces: bool,
    /// Per object (indexed like the scene's objects), whether its back faces are
    /// dropped; when given, it decides in place of [`RenderOptions::cull_back_faces`]
    /// (objects beyond its end are not culled). What a painter culled per object, so
    /// that a reference culls the same. Default `None`.
    pub cull_objects: Option<Arc<[bool]>>,
    /// Per face (indexed like the scene's faces), whether it is dropped when its back is
    /// seen; when given, it decides in place of [`RenderOptions::cull_objects`] and
    /// [`RenderOptions::cull_back_faces`] (faces beyond its end are not culled). What a
    /// painter culled per face (the closed parts of an object that is not closed as a
    /// whole), so that a reference culls the same. Default `None`.
    pub cull_faces: Option<Arc<[bool]>>,
    /// Near and far distances; when `None`, the camera's own, else chosen from the
    /// scene's bounds by `Camera::near_far`. Default `None`.
    pub near_far: Option<(f64, f64)>,
    /// Background colour, linear RGB in [0, 1]. Default white.
    pub background: [f64; 3],
}

impl RenderOptions {
    /// Whether the back faces of `object` are dropped (by object: [`RenderOptions::cull_faces`]
    /// is not consulted).
    pub fn culls(&self, object: u32) -> bool {
        match &self.cull_objects {
            Some(c) => c.get(object as usize).copied().unwrap_or(false),
            None => self.cull_back_faces,
        }
    }
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            depth: DepthFormat::F64,
            cull_back_faces: false,
            cull_objects: None,
            cull_faces: None,
            near_far: None,
            background: [1.0; 3],
        }
    }
}
