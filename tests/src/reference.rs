//! The painter's result against the image-space references, through the same routine
//! `limn check` uses ([`limn_check`]); these wrappers panic instead of returning errors,
//! as tests want.

pub use limn_check::Painted;
use limn_depthsort::OrderOptions;
use limn_scene::{Camera, Scene};

/// Orders `scene` with `opts` and prepares the comparison (see [`limn_check::paint`]).
///
/// Panics if the ordering or the edge extraction fails.
pub fn paint(scene: &Scene, camera: &Camera, opts: &OrderOptions) -> Painted {
    limn_check::paint(scene, camera, opts).unwrap_or_else(|e| panic!("check setup failed: {e}"))
}
