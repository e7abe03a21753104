//! The camera: look-at plus an OpenGL projection (perspective, orthographic, or any 4×4
//! view-projection matrix), and the pixel conventions.
//!
//! The matrices are exactly those of `gluLookAt` and `gluPerspective` or `glOrtho`
//! (right-handed, the camera looks down its −z axis, clip z in [−1, 1]). Pixel coordinates are
//! `px = (ndc.x + 1) / 2 · W`, `py = (1 − ndc.y) / 2 · H` (y down); pixel (i, j) covers
//! [i, i+1) × [j, j+1) and is sampled at its centre.

use glam::{DMat4, DVec3, DVec4};
use thiserror::Error;

use crate::Scene;

/// Errors in a camera description.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum CameraError {
    /// A camera vector or number is NaN or infinite.
    #[error("camera {0} is not finite")]
    NonFinite(&'static str),
    /// The eye and the target coincide.
    #[error("camera eye and target coincide")]
    EyeIsTarget,
    /// The up vector is zero or parallel to the viewing direction.
    #[error("camera up vector is zero or parallel to the viewing direction")]
    BadUp,
    /// The field of view is outside (0°, 180°).
    #[error("field of view {0}° is outside (0, 180)")]
    BadFov(f64),
    /// The picture size is zero or absurdly large.
    #[error("picture size {0}x{1} is invalid (each side must be 1 to 65536)")]
    BadSize(u32, u32),
    /// Near/far planes are not 0 < near < far.
    #[error("near {0} and far {1} planes must satisfy 0 < near < far")]
    BadClip(f64, f64),
    /// The orthographic view height is not a positive finite number.
    #[error("orthographic view height {0} must be positive and finite")]
    BadViewHeight(f64),
    /// A view-projection matrix has a NaN or infinite entry, or sees nothing (its x, y
    /// and w rows are linearly dependent: no centre of projection).
    #[error("the view-projection matrix is not finite or has no centre of projection")]
    BadMatrix,
    /// The scene has no faces to frame.
    #[error("the scene has no faces to frame")]
    EmptyScene,
    /// The eye is so far from the target (or the scene so large) that distances
    /// overflow f64.
    #[error("camera distances overflow: the scene or the eye is too far out (|coordinates| must stay well below 1e150)")]
    OutOfRange,
}

/// How a camera projects the world onto the picture.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Projection {
    /// `gluPerspective` with the camera's `fov_deg`: the eye is the camera's `eye`.
    Perspective,
    /// `glOrtho`: parallel projection along the view direction, `height` world units
    /// visible vertically (`height · W/H` horizontally), centred on the view axis. The
    /// eye lies at infinity in the direction from `target` to `eye`; `eye` still fixes
    /// where depth (and so the near and far planes) is measured from.
    Orthographic {
        /// The visible height in world units.
        height: f64,
    },
    /// Any 4×4 view-projection matrix from world to OpenGL clip coordinates; pixels follow
    /// from it as for the others, and `eye`, `target`, `up`, `fov_deg`, `near` and `far`
    /// play no part in projecting. Its centre of projection (the point with clip
    /// `x = y = w = 0`) is the eye of the orderings: a finite point, or a direction when
    /// the matrix is affine (a parallel projection); it is computed once in f64 from the
    /// matrix (see [`Camera::viewpoint`]), and every decision is exact for that eye.
    /// Clipping keeps what lies in `−w ≤ z ≤ w`.
    Matrix(DMat4),
}

/// Where the eye is, as the orderings see it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Viewpoint {
    /// A finite eye point (perspective).
    At(DVec3),
    /// An eye at infinity (parallel projection), in this direction from the scene.
    Toward(DVec3),
}

/// A camera: look-at and a [`Projection`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// Eye position.
    pub eye: DVec3,
    /// Point looked at.
    pub target: DVec3,
    /// Up direction (need not be orthogonal to the view direction).
    pub up: DVec3,
    /// Vertical field of view in degrees.
    pub fov_deg: f64,
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// Near plane distance; chosen from the scene bounds when `None`.
    pub near: Option<f64>,
    /// Far plane distance; chosen from the scene bounds when `None`.
    pub far: Option<f64>,
    /// How the camera projects (perspective unless set otherwise).
    pub projection: Projection,
}

/// A point after projection.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projected {
    /// Pixel x (right).
    pub x: f64,
    /// Pixel y (down).
    pub y: f64,
    /// Normalised device depth in [−1, 1] for points between near and far.
    pub z: f64,
    /// Clip-space w (the distance in front of the eye along the view axis for a
    /// perspective camera; 1 for an orthographic one).
    pub w: f64,
}

/// The default direction from the target to the eye when the camera frames a scene:
/// to the right, above and in front (+x, +y, +z), normalised.
pub const DEFAULT_VIEW_DIRECTION: [f64; 3] = [1.0, 0.8, 1.6];

impl Camera {
    /// A camera with the given eye, target and size; up +Y, fov 45°, automatic clipping.
    pub fn new(eye: DVec3, target: DVec3, width: u32, height: u32) -> Self {
        Camera {
            eye,
            target,
            up: DVec3::Y,
            fov_deg: 45.0,
            width,
            height,
            near: None,
            far: None,
            projection: Projection::Perspective,
        }
    }

    /// An orthographic camera with the given eye, target, visible height (world units)
    /// and size; up +Y, automatic clipping.
    pub fn orthographic(eye: DVec3, target: DVec3, height: f64, width: u32, h: u32) -> Self {
        Camera {
            projection: Projection::Orthographic { height },
            ..Camera::new(eye, target, width, h)
        }
    }

    /// A camera from a view-projection matrix (world to OpenGL clip coordinates) and a
    /// picture size. `eye` and `target` are set to the matrix's centre of projection and
    /// a point in front of it (they serve shading and reports only).
    pub fn from_matrix(m: DMat4, width: u32, height: u32) -> Result<Camera, CameraError> {
        let mut cam = Camera::new(DVec3::Z, DVec3::ZERO, width, height);
        cam.projection = Projection::Matrix(m);
        let (eye, fwd) = match matrix_viewpoint(&m)? {
            Viewpoint::At(e) => (e, matrix_forward(&m)),
            Viewpoint::Toward(d) => {
                // A stand-in eye in front of everything the matrix keeps (z = −w).
                let inv = m.inverse();
                let c = inv * DVec4::new(0.0, 0.0, -1.0, 1.0);
                let near = c.truncate() / c.w;
                let d = d.normalize();
                (near + d, -d)
            }
        };
        if !eye.is_finite() || !fwd.is_finite() || fwd == DVec3::ZERO {
            return Err(CameraError::BadMatrix);
        }
        cam.eye = eye;
        cam.target = eye + fwd;
        cam.up = if fwd.cross(DVec3::Y).length_squared() < 1e-12 {
            DVec3::Z
        } else {
            DVec3::Y
        };
        cam.validate()?;
        Ok(cam)
    }

    /// Whether this is the `gluPerspective` camera (the one whose clipping and depth
    /// are measured by clip w).
    pub fn is_perspective(&self) -> bool {
        matches!(self.projection, Projection::Perspective)
    }

    /// The eye the orderings classify against: the eye point of a perspective camera,
    /// the direction from `target` to `eye` of an orthographic one, a matrix's centre of
    /// projection (computed in f64 from the matrix: the null vector of its x, y and w
    /// rows, by cofactors).
    pub fn viewpoint(&self) -> Result<Viewpoint, CameraError> {
        match self.projection {
            Projection::Perspective => Ok(Viewpoint::At(self.eye)),
            Projection::Orthographic { .. } => Ok(Viewpoint::Toward(self.eye - self.target)),
            Projection::Matrix(m) => matrix_viewpoint(&m),
        }
    }

    /// A camera that frames the whole scene: it looks at the centre of the scene's
    /// bounding box from the direction [`DEFAULT_VIEW_DIRECTION`] (right, above, in
    /// front), as close as the projected scene fits the picture with a 5 % margin (see
    /// [`Camera::framing_scene`]).
    pub fn framing(scene: &Scene, width: u32, height: u32) -> Result<Camera, CameraError> {
        let dir = DVec3::from(DEFAULT_VIEW_DIRECTION);
        Camera::framing_scene(scene, dir, 45.0, width, height)
    }

    /// A camera looking at the centre of the scene's bounding box from direction `dir`
    /// (target to eye), as close as every vertex of a face projects inside the picture
    /// with a 5 % margin on each side, and never closer than a twentieth of the bounding
    /// sphere's radius in front of the nearest vertex. The projected extent decides, not
    /// the bounding sphere (which leaves most of the frame empty for flat or elongated
    /// scenes).
    pub fn framing_scene(
        scene: &Scene,
        dir: DVec3,
        fov_deg: f64,
        width: u32,
        height: u32,
    ) -> Result<Camera, CameraError> {
        let (lo, hi) = scene.bounds().ok_or(CameraError::EmptyScene)?;
        let mut cam = Camera::framing_bounds(lo, hi, dir, fov_deg, width, height)?;
        let back = (cam.eye - cam.target).normalize();
        let right = (-back).cross(cam.up).normalize();
        let up = right.cross(-back);
        let th = (fov_deg.to_radians() * 0.5).tan() / 1.05;
        let tw = th * cam.aspect();
        let radius = (hi - lo).length() * 0.5;
        let mut dist: f64 = 0.0;
        let mut nearest: f64 = f64::NEG_INFINITY;
        for f in &scene.faces {
            for &v in &f.vertices {
                let w = scene.vertices[v as usize] - cam.target;
                let along = w.dot(back);
                nearest = nearest.max(along);
                let need = along + (w.dot(right).abs() / tw).max(w.dot(up).abs() / th);
                dist = dist.max(need);
            }
        }
        let dist = dist.max(nearest + 0.05 * radius);
        let eye = cam.target + back * dist;
        if dist.is_finite()
            && dist > 0.0
            && dist < (cam.eye - cam.target).length()
            && eye != cam.target
        {
            cam.eye = eye;
        }
        cam.validate()?;
        Ok(cam)
    }

    /// A camera looking at the centre of `lo..hi` from direction `dir` (target to eye),
    /// fitting the bounding sphere with a 5 % margin.
    pub fn framing_bounds(
        lo: DVec3,
        hi: DVec3,
        dir: DVec3,
        fov_deg: f64,
        width: u32,
        height: u32,
    ) -> Result<Camera, CameraError> {
        if !lo.is_finite() || !hi.is_finite() {
            return Err(CameraError::NonFinite("bounds"));
        }
        let centre = (lo + hi) * 0.5;
        let mut radius = (hi - lo).length() * 0.5;
        if radius <= 0.0 {
            radius = 1.0;
        }
        let aspect = width.max(1) as f64 / height.max(1) as f64;
        let half_v = (fov_deg.to_radians() * 0.5).min(1.5);
        let half_h = (half_v.tan() * aspect).atan();
        let half = half_v.min(half_h);
        let dist = radius / half.sin() * 1.05;
        let dir = if dir.length_squared() > 0.0 {
            dir.normalize()
        } else {
            DVec3::Z
        };
        let up = if dir.cross(DVec3::Y).length_squared() < 1e-12 {
            DVec3::Z
        } else {
            DVec3::Y
        };
        if !(centre + dir * dist).is_finite() || !radius.is_finite() {
            return Err(CameraError::OutOfRange);
        }
        let cam = Camera {
            eye: centre + dir * dist,
            target: centre,
            up,
            fov_deg,
            width,
            height,
            near: None,
            far: None,
            projection: Projection::Perspective,
        };
        cam.validate()?;
        Ok(cam)
    }

    /// An orthographic camera looking at the centre of the scene's bounding box from
    /// direction `dir` (target to eye), its view height fitting every vertex of a face
    /// inside the picture with a 5 % margin on each side, its eye outside the bounding
    /// sphere (so nothing is clipped).
    pub fn framing_orthographic(
        scene: &Scene,
        dir: DVec3,
        width: u32,
        height: u32,
    ) -> Result<Camera, CameraError> {
        let (lo, hi) = scene.bounds().ok_or(CameraError::EmptyScene)?;
        let mut cam = Camera::framing_bounds(lo, hi, dir, 45.0, width, height)?;
        let back = (cam.eye - cam.target).normalize();
        let right = (-back).cross(cam.up).normalize();
        let up = right.cross(-back);
        let (mut half_w, mut half_h) = (0.0f64, 0.0f64);
        for f in &scene.faces {
            for &v in &f.vertices {
                let w = scene.vertices[v as usize] - cam.target;
                half_w = half_w.max(w.dot(right).abs());
                half_h = half_h.max(w.dot(up).abs());
            }
        }
        let mut h = 2.0 * half_h.max(half_w / cam.aspect()) * 1.05;
        if !(h > 0.0 && h.is_finite()) {
            h = ((hi - lo).length()).max(1.0);
        }
        let radius = (hi - lo).length() * 0.5;
        cam.eye = cam.target + back * (radius * 2.0).max(1.0);
        cam.projection = Projection::Orthographic { height: h };
        cam.validate()?;
        Ok(cam)
    }

    /// Checks that the camera can be used: finite vectors, eye ≠ target, up not
    /// parallel to the view direction, fov in (0°, 180°), a sensible picture size.
    pub fn validate(&self) -> Result<(), CameraError> {
        if !self.eye.is_finite() {
            return Err(CameraError::NonFinite("eye"));
        }
        if !self.target.is_finite() {
            return Err(CameraError::NonFinite("target"));
        }
        if !self.up.is_finite() {
            return Err(CameraError::NonFinite("up"));
        }
        let f = self.target - self.eye;
        if !f.length_squared().is_finite() {
            return Err(CameraError::OutOfRange);
        }
        if f.length_squared() == 0.0 {
            return Err(CameraError::EyeIsTarget);
        }
        let s = f.normalize().cross(self.up);
        let s2 = s.length_squared();
        if s2.is_nan() || s2 <= 1e-24 || self.up.length_squared() == 0.0 {
            return Err(CameraError::BadUp);
        }
        if !(self.fov_deg > 0.0 && self.fov_deg < 180.0) {
            return Err(CameraError::BadFov(self.fov_deg));
        }
        if self.width == 0 || self.height == 0 || self.width > 65536 || self.height > 65536 {
            return Err(CameraError::BadSize(self.width, self.height));
        }
        match self.projection {
            Projection::Perspective => {}
            Projection::Orthographic { height } => {
                if !(height > 0.0 && height.is_finite()) {
                    return Err(CameraError::BadViewHeight(height));
                }
            }
            Projection::Matrix(m) => {
                matrix_viewpoint(&m)?;
            }
        }
        if let (Some(n), Some(fa)) = (self.near, self.far) {
            if !(n > 0.0 && n < fa && fa.is_finite()) {
                return Err(CameraError::BadClip(n, fa));
            }
        }
        Ok(())
    }

    /// Unit vector from the eye towards the target.
    pub fn forward(&self) -> DVec3 {
        (self.target - self.eye).normalize()
    }

    /// Width / height.
    pub fn aspect(&self) -> f64 {
        self.width as f64 / self.height as f64
    }

    /// The view matrix of `gluLookAt(eye, target, up)`.
    pub fn view(&self) -> DMat4 {
        glam::dcamera::rh::view::look_at_mat4(self.eye, self.target, self.up)
    }

    /// The projection matrix: `gluPerspective(fov, W/H, near, far)`, or
    /// `glOrtho(−h·W/H/2, h·W/H/2, −h/2, h/2, near, far)` for an orthographic camera of
    /// height `h`. For a matrix camera the view matrix is the identity and this is the
    /// matrix itself.
    pub fn projection(&self, near: f64, far: f64) -> DMat4 {
        match self.projection {
            Projection::Perspective => glam::dcamera::rh::proj::opengl::perspective(
                self.fov_deg.to_radians(),
                self.aspect(),
                near,
                far,
            ),
            Projection::Orthographic { height } => {
                let (hh, hw) = (height * 0.5, height * 0.5 * self.aspect());
                glam::dcamera::rh::proj::opengl::orthographic(-hw, hw, -hh, hh, near, far)
            }
            Projection::Matrix(m) => m,
        }
    }

    /// Near and far distances: the given ones, or chosen from the scene's bounds. The far
    /// plane lies just beyond the farthest corner of the bounding box; the near plane just
    /// before the nearest corner, but never closer than far / 10⁴ (so geometry beside or
    /// behind the eye is clipped there).
    pub fn near_far(&self, scene: &Scene) -> (f64, f64) {
        let f = self.forward();
        let (mut lo_d, mut hi_d) = (f64::INFINITY, f64::NEG_INFINITY);
        if let Some((lo, hi)) = scene.bounds() {
            for i in 0..8 {
                let c = DVec3::new(
                    if i & 1 == 0 { lo.x } else { hi.x },
                    if i & 2 == 0 { lo.y } else { hi.y },
                    if i & 4 == 0 { lo.z } else { hi.z },
                );
                let d = (c - self.eye).dot(f);
                lo_d = lo_d.min(d);
                hi_d = hi_d.max(d);
            }
        }
        let far = match self.far {
            Some(v) => v,
            None if hi_d.is_finite() && hi_d > 0.0 => hi_d * 1.01,
            None => 1.0,
        };
        let near = match self.near {
            Some(v) => v,
            None => {
                let min_near = far * 1e-4;
                if lo_d.is_finite() && lo_d * 0.99 > min_near {
                    lo_d * 0.99
                } else {
                    min_near
                }
            }
        };
        (near, far)
    }

    /// `projection(near, far) · view()` (the matrix itself for a matrix camera).
    pub fn view_projection(&self, near: f64, far: f64) -> DMat4 {
        match self.projection {
            Projection::Matrix(m) => m,
            _ => self.projection(near, far) * self.view(),
        }
    }

    /// Projects a world point with the given view-projection matrix into pixel
    /// coordinates. Only meaningful for points in front of the eye (`w > 0`).
    pub fn project_with(&self, vp: &DMat4, p: DVec3) -> Projected {
        let c: DVec4 = *vp * p.extend(1.0);
        let inv_w = 1.0 / c.w;
        let nx = c.x * inv_w;
        let ny = c.y * inv_w;
        Projected {
            x: (nx + 1.0) * 0.5 * self.width as f64,
            y: (1.0 - ny) * 0.5 * self.height as f64,
            z: c.z * inv_w,
            w: c.w,
        }
    }
}

/// The centre of projection of a view-projection matrix: the homogeneous point on which
/// its x, y and w rows vanish (their cross product in four dimensions, by cofactors),
/// finite or at infinity. A direction is oriented towards the viewer: the side where
/// clip depth `z/w` decreases.
fn matrix_viewpoint(m: &DMat4) -> Result<Viewpoint, CameraError> {
    if !m.is_finite() {
        return Err(CameraError::BadMatrix);
    }
    let (rx, ry, rz, rw) = (m.row(0), m.row(1), m.row(2), m.row(3));
    let rows = [rx.to_array(), ry.to_array(), rw.to_array()];
    // Cofactor k: the determinant of the 3×3 minor without column k, signed.
    let minor = |skip: usize| {
        let cols: Vec<usize> = (0..4).filter(|&c| c != skip).collect();
        let a = |r: usize, c: usize| rows[r][cols[c]];
        a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1))
            - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0))
            + a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0))
    };
    let n = DVec4::new(-minor(0), minor(1), -minor(2), minor(3));
    if !n.is_finite() || n.truncate() == DVec3::ZERO {
        return Err(CameraError::BadMatrix);
    }
    if n.w != 0.0 {
        let e = n.truncate() / n.w;
        if !e.is_finite() {
            return Err(CameraError::BadMatrix);
        }
        return Ok(Viewpoint::At(e));
    }
    // At infinity: moving along d must bring points nearer (clip z / w decreasing).
    let d = n.truncate();
    let dz = rz.truncate().dot(d) * rw.w.signum();
    if dz == 0.0 || !dz.is_finite() {
        return Err(CameraError::BadMatrix);
    }
    Ok(Viewpoint::Toward(if dz > 0.0 { -d } else { d }))
}

/// The viewing direction of a perspective matrix: the direction in which clip w grows.
fn matrix_forward(m: &DMat4) -> DVec3 {
    m.row(3).truncate().normalize_or_zero()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The share of the picture's width and height the scene's projection spans, and
    /// whether every vertex lies inside.
    fn coverage(scene: &Scene, cam: &Camera) -> (f64, f64, bool) {
        let (near, far) = cam.near_far(scene);
        let vp = cam.view_projection(near, far);
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for f in &scene.faces {
            for &v in &f.vertices {
                let p = cam.project_with(&vp, scene.vertices[v as usize]);
                lo = [lo[0].min(p.x), lo[1].min(p.y)];
                hi = [hi[0].max(p.x), hi[1].max(p.y)];
            }
        }
        let (w, h) = (cam.width as f64, cam.height as f64);
        let inside = lo[0] >= 0.0 && lo[1] >= 0.0 && hi[0] <= w && hi[1] <= h;
        ((hi[0] - lo[0]) / w, (hi[1] - lo[1]) / h, inside)
    }

    #[test]
    fn framing_fits_the_projected_extent_not_the_bounding_sphere() {
        let mut flat = Scene::default();
        let m = flat.add_material(crate::Material::default_grey());
        let o = flat.add_object("strip");
        let pts = [
            [-5.0, 0.0, -0.5],
            [5.0, 0.0, -0.5],
            [5.0, 0.0, 0.5],
            [-5.0, 0.0, 0.5],
        ];
        flat.add_polygon(&pts.map(DVec3::from), m, o).unwrap();
        for (w, h) in [(800, 600), (300, 900), (1920, 1080)] {
            let cam = Camera::framing(&flat, w, h).unwrap();
            let (cw, ch, inside) = coverage(&flat, &cam);
            assert!(inside, "{w}x{h}: {cw} {ch}");
            // Fills most of the frame in one direction.
            assert!(cw.max(ch) > 0.75, "{w}x{h}: {cw} {ch}");
            // Fitting the bounding sphere instead leaves much of it empty.
            let (lo, hi) = flat.bounds().unwrap();
            let dir = DVec3::from(DEFAULT_VIEW_DIRECTION);
            let sphere = Camera::framing_bounds(lo, hi, dir, 45.0, w, h).unwrap();
            let (sw, sh, _) = coverage(&flat, &sphere);
            // (In a tall frame the sphere was already limited by the width.)
            let gain = if w > h { 1.2 } else { 1.0 };
            assert!(
                cw.max(ch) > gain * sw.max(sh),
                "{w}x{h}: {cw} {ch} vs {sw} {sh}"
            );
        }
    }

    #[test]
    fn target_projects_to_picture_centre() {
        let cam = Camera::new(
            DVec3::new(3.0, 2.0, 5.0),
            DVec3::new(0.5, 0.0, -1.0),
            800,
            600,
        );
        let vp = cam.view_projection(0.1, 100.0);
        let p = cam.project_with(&vp, cam.target);
        assert!((p.x - 400.0).abs() < 1e-9 && (p.y - 300.0).abs() < 1e-9);
    }

    #[test]
    fn up_is_up_in_pixels() {
        let cam = Camera::new(DVec3::new(0.0, 0.0, 5.0), DVec3::ZERO, 100, 100);
        let vp = cam.view_projection(0.1, 100.0);
        let a = cam.project_with(&vp, DVec3::new(0.0, 1.0, 0.0));
        let b = cam.project_with(&vp, DVec3::new(1.0, 0.0, 0.0));
        assert!(a.y < 50.0, "+y world must be above the centre (smaller py)");
        assert!(b.x > 50.0, "+x world must be right of the centre");
    }

    #[test]
    fn bad_cameras_are_rejected() {
        let mut cam = Camera::new(DVec3::ZERO, DVec3::ZERO, 10, 10);
        assert_eq!(cam.validate(), Err(CameraError::EyeIsTarget));
        cam.target = DVec3::new(0.0, 5.0, 0.0);
        assert_eq!(cam.validate(), Err(CameraError::BadUp));
        cam.up = DVec3::X;
        cam.fov_deg = 180.0;
        assert!(matches!(cam.validate(), Err(CameraError::BadFov(_))));
        cam.fov_deg = 30.0;
        cam.eye.x = f64::NAN;
        assert_eq!(cam.validate(), Err(CameraError::NonFinite("eye")));
    }
}

#[cfg(test)]
mod projection_tests {
    use super::*;

    fn square() -> Scene {
        let mut s = Scene::default();
        let m = s.add_material(crate::Material::default_grey());
        let o = s.add_object("square");
        let pts = [
            [-1.0, -1.0, 0.0],
            [1.0, -1.0, 0.0],
            [1.0, 1.0, 0.0],
            [-1.0, 1.0, 0.0],
        ];
        s.add_polygon(&pts.map(DVec3::from), m, o).unwrap();
        s
    }

    #[test]
    fn orthographic_keeps_sizes_at_every_depth() {
        let cam = Camera::orthographic(DVec3::new(0.0, 0.0, 10.0), DVec3::ZERO, 4.0, 100, 100);
        cam.validate().unwrap();
        let vp = cam.view_projection(1.0, 20.0);
        for z in [-5.0, 0.0, 5.0] {
            let a = cam.project_with(&vp, DVec3::new(1.0, 0.0, z));
            // Height 4 over 100 pixels: one unit is 25 pixels, whatever the depth.
            assert!((a.x - 75.0).abs() < 1e-9, "{z}: {}", a.x);
            assert_eq!(a.w, 1.0);
        }
        assert_eq!(
            cam.viewpoint(),
            Ok(Viewpoint::Toward(DVec3::new(0.0, 0.0, 10.0)))
        );
    }

    #[test]
    fn framing_orthographic_fits_the_scene() {
        let s = square();
        let cam = Camera::framing_orthographic(&s, DVec3::Z, 200, 100).unwrap();
        let (n, f) = cam.near_far(&s);
        let vp = cam.view_projection(n, f);
        let xs: Vec<f64> = [-1.0, 1.0]
            .iter()
            .map(|&x| cam.project_with(&vp, DVec3::new(x, 1.0, 0.0)).y)
            .collect();
        // The square's height (2) fills the picture's height up to the 5 % margins.
        let top = cam.project_with(&vp, DVec3::new(0.0, 1.0, 0.0)).y;
        assert!(
            (top - 100.0 * (1.0 - 1.0 / 1.05) / 2.0).abs() < 1e-6,
            "{top} {xs:?}"
        );
        assert!(n > 0.0 && n < f);
    }

    #[test]
    fn a_matrix_camera_finds_its_centre_of_projection() {
        let persp = Camera::new(DVec3::new(3.0, 2.0, 5.0), DVec3::ZERO, 80, 60);
        let m = persp.view_projection(0.5, 50.0);
        let cam = Camera::from_matrix(m, 80, 60).unwrap();
        match cam.viewpoint().unwrap() {
            Viewpoint::At(e) => assert!((e - persp.eye).length() < 1e-12, "{e}"),
            v => panic!("{v:?}"),
        }
        let p = DVec3::new(0.3, -0.2, 0.1);
        let a = persp.project_with(&m, p);
        let b = cam.project_with(&cam.view_projection(9.0, 10.0), p);
        assert_eq!((a.x, a.y), (b.x, b.y));

        let ortho = Camera::orthographic(DVec3::new(1.0, 2.0, 3.0), DVec3::ZERO, 2.0, 80, 60);
        let m = ortho.view_projection(0.5, 10.0);
        let cam = Camera::from_matrix(m, 80, 60).unwrap();
        match cam.viewpoint().unwrap() {
            Viewpoint::Toward(d) => {
                let want = DVec3::new(1.0, 2.0, 3.0).normalize();
                assert!((d.normalize() - want).length() < 1e-12, "{d}");
            }
            v => panic!("{v:?}"),
        }
    }

    #[test]
    fn bad_projections_are_rejected() {
        let mut cam = Camera::orthographic(DVec3::Z, DVec3::ZERO, 0.0, 10, 10);
        assert_eq!(cam.validate(), Err(CameraError::BadViewHeight(0.0)));
        cam.projection = Projection::Orthographic { height: f64::NAN };
        assert!(matches!(cam.validate(), Err(CameraError::BadViewHeight(_))));
        assert_eq!(
            Camera::from_matrix(DMat4::ZERO, 10, 10),
            Err(CameraError::BadMatrix)
        );
        let mut m = DMat4::IDENTITY;
        m.x_axis.x = f64::NAN;
        assert_eq!(Camera::from_matrix(m, 10, 10), Err(CameraError::BadMatrix));
    }
}
