//! The painter's result against the image-space references of limn-zbuffer, set up as
//! `limn check` does: the painter's face ids come from [`rasterize_ids`] over the ordered
//! fragments, the reference renders with the camera the ordering actually used and its
//! near and far planes, and the band of ambiguous pixel centres surrounds every scene
//! edge and every fragment edge (fragments also trace where faces pierce each other).

use limn_depthsort::{order, CullMode, OrderOptions, Ordered};
use limn_scene::{Camera, Scene};
use limn_zbuffer::{
    compare, default_band_tolerance, edge_band, rasterize_ids, render, scene_edges, Comparison,
    IdImage, Mask, Method, RenderOptions, Segment2,
};

/// A scene ordered by depthsort, with what a comparison with a reference needs.
#[derive(Debug, Clone)]
pub struct Painted {
    /// The ordering's result.
    pub ordered: Ordered,
    /// Which fragment's face covers each pixel centre (the last painted wins).
    pub ids: IdImage,
    /// Reference options matching the ordering: its near and far planes, culling on
    /// exactly when the ordering was asked to cull every back face.
    pub ropts: RenderOptions,
    /// Scene edges (as the reference clips them) and every fragment edge.
    pub edges: Vec<Segment2>,
    /// Pixel centres within [`default_band_tolerance`] of [`Painted::edges`].
    pub band: Mask,
}

impl Painted {
    /// The camera the ordering actually used.
    pub fn camera(&self) -> &Camera {
        &self.ordered.camera
    }

    /// Renders the scene with `method` and `depth`, otherwise with [`Painted::ropts`].
    ///
    /// Panics if the reference fails.
    pub fn reference(
        &self,
        scene: &Scene,
        method: Method,
        depth: limn_zbuffer::DepthFormat,
    ) -> IdImage {
        let opts = RenderOptions {
            depth,
            ..self.ropts
        };
        render(scene, self.camera(), method, &opts)
            .unwrap_or_else(|e| panic!("{} failed: {e}", method.name()))
            .ids
    }

    /// Compares the painter's ids with `other` outside [`Painted::band`].
    pub fn compare(&self, other: &IdImage) -> Comparison {
        compare(&self.ids, other, Some(&self.band))
    }

    /// A band of `tolerance_px` around the same edges.
    pub fn band_with(&self, tolerance_px: f64) -> Mask {
        let c = self.camera();
        edge_band(&self.edges, c.width, c.height, tolerance_px)
    }
}

/// Orders `scene` with `opts` and prepares the comparison.
///
/// Panics if the ordering or the edge extraction fails.
pub fn paint(scene: &Scene, camera: &Camera, opts: &OrderOptions) -> Painted {
    let ordered = order(scene, camera, opts).unwrap_or_else(|e| panic!("order failed: {e}"));
    let c = &ordered.camera;
    let (w, h) = (c.width, c.height);
    let polys: Vec<(Vec<[f64; 2]>, u32)> = ordered
        .fragments
        .iter()
        .map(|f| (f.points.clone(), f.face))
        .collect();
    let ids = rasterize_ids(&polys, w, h);
    let ropts = RenderOptions {
        cull_back_faces: opts.cull == CullMode::On,
        near_far: Some((ordered.near, ordered.far)),
        ..RenderOptions::default()
    };
    let mut edges =
        scene_edges(scene, c, &ropts).unwrap_or_else(|e| panic!("scene_edges failed: {e}"));
    for f in &ordered.fragments {
        let n = f.points.len();
        for i in 0..n {
            edges.push((f.points[i], f.points[(i + 1) % n]));
        }
    }
    let band = edge_band(&edges, w, h, default_band_tolerance(w, h));
    Painted {
        ordered,
        ids,
        ropts,
        edges,
        band,
    }
}
