//! A glTF camera placed by its node: the view the file suggests
//! ([`limn_scene::Scene::default_camera`]).
//!
//! The camera looks down its node's −Z axis with +Y up, from the node's origin (the
//! node's world transform applied). Perspective: `yfov` (radians) is the vertical field
//! of view; `aspectRatio` is not used (the picture's size decides the width seen).
//! Orthographic: `ymag` is half the visible height. `znear` and `zfar` become the near
//! and far planes when they are usable (0 < near < far).

use std::path::Path;

use ::gltf::camera::Projection as GltfProjection;
use glam::{DMat4, DVec3};
use limn_scene::{Camera, Projection};

/// The camera of `camera` placed by the world transform `world`; `Err` with the reason
/// when it cannot be used as given.
pub(crate) fn placed(camera: &::gltf::Camera, world: &DMat4) -> Result<Camera, String> {
    let eye = world.transform_point3(DVec3::ZERO);
    let forward = world.transform_vector3(DVec3::NEG_Z).normalize_or_zero();
    let up = world.transform_vector3(DVec3::Y).normalize_or_zero();
    if !eye.is_finite() || forward == DVec3::ZERO || up == DVec3::ZERO {
        return Err("its node's transform gives no view direction".into());
    }
    let mut cam = Camera::new(eye, eye + forward, 1, 1);
    cam.up = up;
    let (near, far) = match camera.projection() {
        GltfProjection::Perspective(p) => {
            let fov = f64::from(p.yfov()).to_degrees();
            if !(fov > 0.0 && fov < 180.0) {
                return Err(format!("yfov {} is outside (0, π)", p.yfov()));
            }
            cam.fov_deg = fov;
            (f64::from(p.znear()), p.zfar().map(f64::from))
        }
        GltfProjection::Orthographic(o) => {
            let height = 2.0 * f64::from(o.ymag()).abs();
            if !(height > 0.0 && height.is_finite()) {
                return Err(format!("ymag {} is not a usable half height", o.ymag()));
            }
            cam.projection = Projection::Orthographic { height };
            (f64::from(o.znear()), Some(f64::from(o.zfar())))
        }
    };
    if near > 0.0 && near.is_finite() {
        cam.near = Some(near);
    }
    if let Some(far) = far.filter(|&f| f.is_finite() && f > cam.near.unwrap_or(0.0)) {
        cam.far = Some(far);
    }
    cam.validate().map_err(|e| e.to_string())?;
    Ok(cam)
}

/// The warning for a camera that cannot be used.
pub(crate) fn unusable(path: &Path, camera: &::gltf::Camera, why: &str) -> String {
    format!(
        "{} (camera {}): not used as the default view: {why}",
        path.display(),
        camera.index()
    )
}
