//! The eye as the orderings hold it: a finite point converted by the kernel, or a
//! direction towards an eye at infinity (parallel projections).

use glam::DVec3;
use limn_kernel::Kernel;
use limn_scene::{Camera, Viewpoint};

use crate::options::OrderError;

/// The eye: a point, or a direction towards an eye at infinity.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Eye<P> {
    /// A finite eye.
    At(P),
    /// An eye at infinity in this direction (from the scene towards the viewer).
    Toward(DVec3),
}

impl<P> Eye<P> {
    /// The eye of `camera`, with finite points converted by `kernel`.
    pub fn of<K: Kernel<Point = P>>(kernel: &K, camera: &Camera) -> Result<Eye<P>, OrderError> {
        Ok(match camera.viewpoint()? {
            Viewpoint::At(p) => Eye::At(kernel.point(p)?),
            Viewpoint::Toward(d) => Eye::Toward(d),
        })
    }
}
