//! The eye and the view volume as the orderings see them: the exact predicates that
//! involve the eye (a finite point or a point at infinity, see [`Eye`]), and the planes
//! bounding what the camera sees.
//!
//! A perspective camera's eye is a point and the orderings classify it like any point.
//! An orthographic camera's eye (or an affine view-projection matrix's) lies at infinity
//! in a direction `d`: its side of a plane is the sign of the plane's normal dotted with
//! `d`, and the orientation of the eye with three points is the sign of
//! `d · ((a − c) × (b − c))`, both exact in the exact kernel. Planes "through the eye"
//! become planes parallel to `d`.

use glam::DVec4;
use limn_kernel::{Kernel, Orientation, Side};

use crate::eye::Eye;
use crate::options::OrderError;
use crate::pieces::Ctx;

impl<K: Kernel> Ctx<'_, K> {
    /// The side of `plane` the eye lies on (exact in the exact kernel).
    pub fn eye_side(&self, plane: &K::Plane) -> Side {
        match &self.eye {
            Eye::At(p) => self.k.side_of_point(plane, p),
            Eye::Toward(d) => self.k.side_of_direction(plane, *d),
        }
    }

    /// The orientation of the eye with `v`, `a`, `b` (`orientation(eye, v, a, b)`, the
    /// eye at infinity taken as its limit).
    pub fn eye_orientation(
        &self,
        v: &K::ExactPoint,
        a: &K::ExactPoint,
        b: &K::ExactPoint,
    ) -> Orientation {
        match &self.eye {
            Eye::At(p) => self.k.orientation(&self.k.point_exact(p), v, a, b),
            Eye::Toward(d) => self.k.orientation_toward(*d, v, a, b),
        }
    }
}

/// The planes bounding the view, each facing inwards: the near plane, the plane through
/// the eye facing forward (what lies behind it is behind the camera; none for an eye at
/// infinity), and the four sides of the view volume.
pub(crate) struct ViewPlanes<P> {
    pub near: P,
    pub eye: Option<P>,
    pub sides: [P; 4],
}

/// The view's planes. A perspective camera's come from its eye, view axis and field of
/// view; any other camera's from the rows of its view-projection matrix (clip
/// `z ≥ −w`, `w ≥ 0`, `−w ≤ x, y ≤ w`).
pub(crate) fn view_planes<K: Kernel>(
    ctx: &Ctx<'_, K>,
    near: f64,
) -> Result<ViewPlanes<K::Plane>, OrderError> {
    let cam = ctx.camera;
    if cam.is_perspective() {
        let eye = cam.eye;
        let f = cam.forward();
        let r = f.cross(cam.up).normalize();
        let u = r.cross(f);
        let th = (cam.fov_deg.to_radians() * 0.5).tan();
        let tw = th * cam.aspect();
        return Ok(ViewPlanes {
            near: ctx.k.plane_through(eye + f * near, f)?,
            eye: Some(ctx.k.plane_through(eye, f)?),
            sides: [
                ctx.k.plane_through(eye, f * tw + r)?,
                ctx.k.plane_through(eye, f * tw - r)?,
                ctx.k.plane_through(eye, f * th + u)?,
                ctx.k.plane_through(eye, f * th - u)?,
            ],
        });
    }
    let m = ctx.vp;
    let (x, y, z, w) = (m.row(0), m.row(1), m.row(2), m.row(3));
    let plane = |r: DVec4| -> Result<K::Plane, OrderError> {
        let n = r.truncate();
        let p = n * (-r.w / n.length_squared());
        Ok(ctx.k.plane_through(p, n)?)
    };
    let eye = match ctx.eye {
        Eye::At(_) => Some(plane(w)?),
        Eye::Toward(_) => None,
    };
    Ok(ViewPlanes {
        near: plane(w + z)?,
        eye,
        sides: [plane(w + x)?, plane(w - x)?, plane(w + y)?, plane(w - y)?],
    })
}
