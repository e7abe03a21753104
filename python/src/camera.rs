//! Camera options from Python to a [`Camera`]: the command's defaults (framing the scene
//! from the right, above and in front), an orthographic view, or a 4×4 matrix.

use glam::{DMat4, DVec3};
use limn_scene::{Camera, Projection, Scene, DEFAULT_VIEW_DIRECTION};
use pyo3::prelude::*;

use crate::errors::value_error;

/// What the caller asked of the camera.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CameraSpec {
    pub eye: Option<DVec3>,
    pub target: Option<DVec3>,
    pub up: DVec3,
    pub fov: f64,
    pub size: (u32, u32),
    /// `Some(None)`: orthographic, height framed; `Some(Some(h))`: height `h`.
    pub ortho: Option<Option<f64>>,
    /// A view-projection matrix (world to OpenGL clip coordinates).
    pub matrix: Option<DMat4>,
}

impl Default for CameraSpec {
    fn default() -> Self {
        CameraSpec {
            eye: None,
            target: None,
            up: DVec3::Y,
            fov: 45.0,
            size: (800, 600),
            ortho: None,
            matrix: None,
        }
    }
}

impl CameraSpec {
    /// The camera for `scene`, resolved as the command resolves its flags: an eye
    /// looks at the target (or the centre of the scene's bounds); without an eye the
    /// scene is framed from the default direction, moved to the target when one is given.
    pub fn camera(&self, scene: &Scene) -> PyResult<Camera> {
        let (w, h) = self.size;
        if let Some(m) = self.matrix {
            return Camera::from_matrix(m, w, h).map_err(value_error);
        }
        let mut cam = match self.eye {
            Some(eye) => {
                let target = match self.target {
                    Some(t) => t,
                    None => scene
                        .bounds()
                        .map(|(lo, hi)| (lo + hi) * 0.5)
                        .ok_or_else(|| value_error("the scene is empty"))?,
                };
                Camera::new(eye, target, w, h)
            }
            None => {
                let dir = DVec3::from(DEFAULT_VIEW_DIRECTION);
                let mut c = Camera::framing_scene(scene, dir, self.fov, w, h)
                    .map_err(|e| value_error(format!("cannot frame the scene: {e}")))?;
                if let Some(t) = self.target {
                    c.eye = t + (c.eye - c.target);
                    c.target = t;
                }
                c
            }
        };
        cam.fov_deg = self.fov;
        cam.up = self.up;
        if let Some(height) = self.ortho {
            let framed = Camera::framing_orthographic(scene, cam.eye - cam.target, w, h)
                .map_err(|e| value_error(format!("cannot frame the scene: {e}")))?;
            if self.eye.is_none() {
                cam.eye = cam.target + (framed.eye - framed.target);
            }
            let height = height.unwrap_or(match framed.projection {
                Projection::Orthographic { height } => height,
                _ => 1.0,
            });
            cam.projection = Projection::Orthographic { height };
        }
        cam.validate().map_err(value_error)?;
        Ok(cam)
    }
}

/// A picture size from Python.
pub(crate) fn size(s: (i64, i64)) -> PyResult<(u32, u32)> {
    let ok = |v: i64| (1..=65536).contains(&v);
    if !ok(s.0) || !ok(s.1) {
        return Err(value_error(format!(
            "size ({}, {}) must be two whole numbers from 1 to 65536",
            s.0, s.1
        )));
    }
    Ok((s.0 as u32, s.1 as u32))
}
