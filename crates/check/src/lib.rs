//! The one comparison of a painted order with an image-space reference, used by
//! `limn check` and by the tests.
//!
//! The painter's face ids come from [`rasterize_ids`] over the ordered fragments (the last
//! painted wins at every pixel centre); the reference renders with the camera the
//! ordering used and its near and far planes, culling the back faces of exactly the
//! faces whose back faces the ordering culled ([`Ordered::culled_faces`]: with
//! `--cull auto`, those of the closed opaque objects and parts), each back face by its own exact test; the band of ambiguous pixel centres
//! surrounds every scene edge and every fragment edge (fragments also trace where faces
//! pierce each other and where the near plane cuts them). The scene's lines are compared
//! too ([`Painted::compare_lines`]): the painter's visible pieces against the z-buffer's
//! depth-tested lines.
//!
//! ```
//! use glam::DVec3;
//! use limn_check::paint;
//! use limn_depthsort::OrderOptions;
//! use limn_scene::{Camera, Material, Scene};
//! use limn_zbuffer::{DepthFormat, Method};
//!
//! let mut scene = Scene::default();
//! let m = scene.add_material(Material::unlit("grey", [0.5, 0.5, 0.5]));
//! let o = scene.add_object("quad");
//! let q = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
//! let c: Vec<DVec3> = q.iter().map(|p| DVec3::new(p[0], p[1], 0.0)).collect();
//! scene.add_polygon(&c, m, o).unwrap();
//! let camera = Camera::new(DVec3::new(0.5, 0.5, 3.0), DVec3::new(0.5, 0.5, 0.0), 64, 64);
//! let painted = paint(&scene, &camera, &OrderOptions::default())?;
//! let reference = painted.reference(&scene, Method::RayCast, DepthFormat::F64)?;
//! assert_eq!(painted.compare(&reference).mismatches_outside_band, 0);
//! # Ok::<(), limn_check::CheckError>(())
//! ```

mod lines;
mod shadows;

pub use lines::{compare_line_images, LineComparison};

use limn_depthsort::{order_with_marks, CullMode, OrderError, OrderOptions, Ordered, VisibleMarks};
use limn_scene::{Camera, Scene};
use limn_zbuffer::{
    compare, coverage_counts, default_band_tolerance, edge_band, rasterize_ids, render,
    scene_edges, Comparison, DepthFormat, IdImage, Mask, Method, RenderOptions, Segment2, ZError,
};

/// Why a check could not be made.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CheckError {
    /// The scene could not be ordered.
    #[error(transparent)]
    Order(#[from] OrderError),
    /// The reference (or the scene's edges) could not be rendered.
    #[error(transparent)]
    Reference(#[from] ZError),
}

/// A scene ordered by depthsort, with what a comparison with a reference needs.
#[derive(Debug, Clone)]
pub struct Painted {
    /// The ordering's result.
    pub ordered: Ordered,
    /// Which fragment's face covers each pixel centre (the last painted wins).
    pub ids: IdImage,
    /// Reference options matching the ordering: its near and far planes, and the back
    /// faces of the objects the ordering culled them of culled
    /// ([`RenderOptions::cull_objects`]; `cull_back_faces` says whether it was asked to
    /// cull every back face).
    pub ropts: RenderOptions,
    /// Scene edges (as the reference clips them) and every fragment edge.
    pub edges: Vec<Segment2>,
    /// Pixel centres within [`default_band_tolerance`] of [`Painted::edges`].
    pub band: Mask,
    /// The visible parts of the scene's lines, markers and labels.
    pub marks: VisibleMarks,
    /// Which line the painter draws at each pixel (Bresenham along the visible pieces).
    pub line_ids: IdImage,
    /// Pixels within 2 pixels of a visible piece's end.
    pub line_band: Mask,
}

impl Painted {
    /// The camera the ordering used.
    pub fn camera(&self) -> &Camera {
        &self.ordered.camera
    }

    /// Renders the scene with `method` and `depth`, otherwise with [`Painted::ropts`],
    /// and returns the face id at every pixel centre.
    pub fn reference(
        &self,
        scene: &Scene,
        method: Method,
        depth: DepthFormat,
    ) -> Result<IdImage, CheckError> {
        let opts = RenderOptions {
            depth,
            ..self.ropts.clone()
        };
        Ok(render(scene, self.camera(), method, &opts)?.ids)
    }

    /// Compares the painter's ids with `other` outside [`Painted::band`].
    pub fn compare(&self, other: &IdImage) -> Comparison {
        compare(&self.ids, other, Some(&self.band))
    }

    /// Pixel centres outside [`Painted::band`] covered by two or more opaque fragments
    /// (a visible map's regions cover each centre once: this is 0).
    pub fn double_covered(&self, scene: &Scene) -> usize {
        let polys: Vec<&[[f64; 2]]> = self
            .ordered
            .fragments
            .iter()
            .filter(|f| {
                let face = &scene.faces[f.face as usize];
                scene.materials[face.material as usize].is_opaque()
            })
            .map(|f| f.points.as_slice())
            .collect();
        let c = self.camera();
        coverage_counts(&polys, c.width, c.height)
            .iter()
            .zip(&self.band.bits)
            .filter(|&(&n, &in_band)| n > 1 && !in_band)
            .count()
    }

    /// A band of `tolerance_px` around the same edges.
    pub fn band_with(&self, tolerance_px: f64) -> Mask {
        let c = self.camera();
        edge_band(&self.edges, c.width, c.height, tolerance_px)
    }
}

/// Orders `scene` with `opts` and prepares the comparison.
pub fn paint(scene: &Scene, camera: &Camera, opts: &OrderOptions) -> Result<Painted, CheckError> {
    let (ordered, marks) = order_with_marks(scene, camera, opts)?;
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
        cull_objects: Some(ordered.culled_objects.as_slice().into()),
        cull_faces: Some(ordered.culled_faces.as_slice().into()),
        near_far: Some((ordered.near, ordered.far)),
        ..RenderOptions::default()
    };
    let mut edges = scene_edges(scene, c, &ropts)?;
    for f in &ordered.fragments {
        let n = f.points.len();
        for i in 0..n {
            edges.push((f.points[i], f.points[(i + 1) % n]));
        }
    }
    let tolerance = default_band_tolerance(w, h);
    let band = edge_band(&edges, w, h, tolerance);
    let line_ids = lines::painted_lines(&marks, w, h);
    let mut painted = Painted {
        ordered,
        ids,
        ropts,
        edges,
        band,
        marks,
        line_ids,
        line_band: Mask::new(w, h),
    };
    painted.line_band = lines::line_band(&painted, 2.0);
    Ok(painted)
}
