//! The ray through a pixel centre, from the near to the far plane, for any projection,
//! and the world point where it meets a plane.

use glam::{DMat4, DVec3, DVec4};

use crate::setup::Frame;

/// The pixels' rays of one frame.
pub(crate) struct PixelRays {
    inv: DMat4,
    width: usize,
    w: f64,
    h: f64,
}

impl PixelRays {
    /// The rays of `frame`'s pixels.
    pub fn new(frame: &Frame) -> Self {
        PixelRays {
            inv: frame.vp.inverse(),
            width: frame.width as usize,
            w: f64::from(frame.width),
            h: f64::from(frame.height),
        }
    }

    /// Where the ray of pixel `i` (row-major) meets the plane through `origin` with
    /// normal `n`, with the ray's point on the near plane; `None` when the ray runs
    /// along the plane or the point is not finite.
    pub fn meet(&self, i: usize, n: DVec3, origin: DVec3) -> Option<(DVec3, DVec3)> {
        let x = (i % self.width) as f64 + 0.5;
        let y = (i / self.width) as f64 + 0.5;
        let at = |z: f64| {
            let q = self.inv * DVec4::new(x / self.w * 2.0 - 1.0, 1.0 - y / self.h * 2.0, z, 1.0);
            q.truncate() / q.w
        };
        let (near, far) = (at(-1.0), at(1.0));
        let dir = far - near;
        let den = dir.dot(n);
        if den == 0.0 || !den.is_finite() {
            return None;
        }
        let p = near + dir * ((origin - near).dot(n) / den);
        p.is_finite().then_some((p, near))
    }
}
