//! The common entry point: a rendering by any method, and its results.

use std::collections::HashMap;

use glam::DVec3;
use limn_scene::{
    polygon_normal, shade_face, shade_face_in_shadow, shade_in_scene, Camera, LightSet, Rgb, Scene,
};

use crate::abuffer::{abuffer, FaceLook};
use crate::image::{rgb_to_u8, ColorImage, DepthImage, IdImage, NO_FACE};
use crate::options::{Method, RenderOptions};
use crate::pixel_rays::PixelRays;
use crate::setup::{prepare, Collect, Culling, Frame, Prepared};
use crate::shadow_map::{ShadowMapOptions, ShadowMaps};
use crate::shadow_rays::Casters;
use crate::{pixel_shading, raycast, scanline, warnock, zbuf, Segment2, ZError};

/// Counters of one rendering.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RenderStats {
    /// Triangles after culling and clipping (world triangles for ray casting).
    pub triangles: usize,
    /// Triangles that needed clipping.
    pub clipped_triangles: usize,
    /// Faces dropped as back faces.
    pub culled_faces: usize,
    /// Pixel fragments generated (ray–triangle tests for ray casting, areas examined for
    /// Warnock).
    pub fragments: u64,
    /// Depth comparisons decided by exact arithmetic (ray casting).
    pub exact_fallbacks: u64,
    /// Working memory of the method's own buffers in bytes (depth and id buffers, row
    /// buffers and edge tables, fragment lists, BVH), excluding the output images.
    pub working_bytes: usize,
    /// Exact shadow-ray–triangle tests (ray casting with lights that cast shadows).
    pub shadow_tests: u64,
}

/// What a method produces.
#[derive(Debug, Clone, PartialEq)]
pub struct Raster {
    /// Flat-shaded colours over the background.
    pub color: ColorImage,
    /// Window depth of the visible surface.
    pub depth: DepthImage,
    /// Face id of the visible surface.
    pub ids: IdImage,
    /// Per pixel (row-major), the lights (indices into the scene's lights) the visible
    /// point is in the shadow of: exact for ray casting, by shadow maps for the z-buffer,
    /// scan-line and Warnock methods. `None` when no light casts shadows, and for the
    /// A-buffer (which draws no shadows).
    pub shadowed: Option<Vec<LightSet>>,
    /// Counters.
    pub stats: RenderStats,
}

/// Renders `scene` seen by `camera` with `method`.
///
/// Errors: an invalid scene or camera, a bad near/far override, or coordinates outside
/// the accepted range ([`crate::MAX_COORD`]; for ray casting with a light that casts
/// shadows also [`crate::MIN_RAYCAST_COORD`]). Any valid scene renders, including
/// NaN-free degenerate faces, faces behind the eye and huge coordinates.
pub fn render(
    scene: &Scene,
    camera: &Camera,
    method: Method,
    opts: &RenderOptions,
) -> Result<Raster, ZError> {
    render_with_shadow_maps(scene, camera, method, opts, &ShadowMapOptions::default())
}

/// [`render`] with the shadow maps made and read as `maps` says (they are used only when
/// a light casts shadows, and only by the z-buffer, scan-line and Warnock methods; ray
/// casting's shadows are exact).
pub fn render_with_shadow_maps(
    scene: &Scene,
    camera: &Camera,
    method: Method,
    opts: &RenderOptions,
    maps: &ShadowMapOptions,
) -> Result<Raster, ZError> {
    let frame = Frame::new(scene, camera, opts)?;
    let mut shadowed = None;
    let (w, h) = (frame.width, frame.height);
    let mut stats = RenderStats::default();
    let (ids, depths, colors) = match method {
        Method::RayCast => {
            let mut casters = Casters::new(scene)?;
            let out = raycast::raycast(scene, &frame, Culling::of(opts), casters.as_mut())?;
            shadowed = out.shadowed;
            stats.fragments = out.tests;
            stats.exact_fallbacks = out.exact_fallbacks;
            if let Some(c) = &casters {
                stats.shadow_tests = c.tests;
                stats.exact_fallbacks += c.fallbacks;
            }
            stats.working_bytes = out.working_bytes;
            stats.triangles = out.triangles;
            stats.culled_faces = out.culled_faces;
            (out.ids, out.depths, None)
        }
        Method::ZBuffer | Method::ScanLine => {
            let prep = prepared(scene, &frame, opts, &mut stats);
            let b = if method == Method::ZBuffer {
                zbuf::zbuffer(&prep, w, h, opts.depth)
            } else {
                scanline::scanline(&prep, w, h, opts.depth)
            };
            stats.fragments = b.fragments;
            stats.working_bytes = b.working_bytes;
            (b.ids, b.depths, None)
        }
        Method::Warnock => {
            let prep = prepared(scene, &frame, opts, &mut stats);
            let o = warnock::warnock(&prep, w, h, opts.depth);
            stats.fragments = o.areas;
            stats.working_bytes = o.working_bytes;
            (o.ids, o.depths, None)
        }
        Method::ABuffer => {
            let prep = prepared(scene, &frame, opts, &mut stats);
            let eye = frame.camera.eye;
            let alpha = |face: u32| {
                let m = &scene.materials[scene.faces[face as usize].material as usize];
                if m.opacity.is_nan() {
                    1.0
                } else {
                    m.opacity.clamp(0.0, 1.0)
                }
            };
            let color = |face: u32| flat_color(scene, face, eye);
            let look = FaceLook {
                color: &color,
                alpha: &alpha,
            };
            let a = abuffer(&prep, w, h, opts.depth, opts.background, &look)?;
            stats.fragments = a.fragments;
            stats.working_bytes = a.working_bytes;
            (a.ids, a.depths, Some(a.colors))
        }
    };
    if method != Method::RayCast && method != Method::ABuffer {
        if let Some(m) = ShadowMaps::new(scene, maps)? {
            shadowed = Some(map_shadows(scene, &frame, &ids, &m));
        }
    }
    Ok(finish(
        scene, &frame, opts, ids, depths, colors, shadowed, stats,
    ))
}

/// The shadow sets of the pixels' points by the shadow maps.
fn map_shadows(scene: &Scene, frame: &Frame, ids: &[u32], maps: &ShadowMaps) -> Vec<LightSet> {
    let rays = PixelRays::new(frame);
    let mut planes: Vec<Option<(DVec3, DVec3)>> = vec![None; scene.faces.len()];
    ids.iter()
        .enumerate()
        .map(|(i, &id)| {
            if id == NO_FACE {
                return LightSet::EMPTY;
            }
            let (n, origin) = *planes[id as usize].get_or_insert_with(|| {
                let pts = scene.face_points(id);
                let c = pts.iter().copied().sum::<DVec3>() / pts.len() as f64;
                (polygon_normal(&pts), c)
            });
            let Some((p, near)) = rays.meet(i, n, origin) else {
                return LightSet::EMPTY;
            };
            maps.shadowed(p, n, near)
        })
        .collect()
}

/// Culls, clips and projects for the screen-space methods.
fn prepared(
    scene: &Scene,
    frame: &Frame,
    opts: &RenderOptions,
    stats: &mut RenderStats,
) -> Prepared {
    let mut prep = Prepared::default();
    prepare(
        scene,
        frame,
        Culling::of(opts),
        Collect::Triangles(&mut prep),
    );
    stats.triangles = prep.tris.len();
    stats.clipped_triangles = prep.clipped_tris;
    stats.culled_faces = prep.culled_faces;
    prep
}

#[allow(clippy::too_many_arguments)] // the parts of a result, gathered once
fn finish(
    scene: &Scene,
    frame: &Frame,
    opts: &RenderOptions,
    ids: Vec<u32>,
    depths: Vec<f64>,
    colors: Option<Vec<[f64; 3]>>,
    shadowed: Option<Vec<LightSet>>,
    stats: RenderStats,
) -> Raster {
    let (w, h) = (frame.width, frame.height);
    let pixels = match colors {
        Some(c) => c.into_iter().map(rgb_to_u8).collect(),
        None => {
            // Shade each visible face once, in face order (sequential memory access).
            let mut visible = vec![false; scene.faces.len()];
            for &id in &ids {
                if id != NO_FACE {
                    visible[id as usize] = true;
                }
            }
            let palette: Vec<[u8; 3]> = visible
                .iter()
                .enumerate()
                .map(|(f, &v)| {
                    if v {
                        rgb_to_u8(flat_color(scene, f as u32, frame.camera.eye))
                    } else {
                        [0; 3]
                    }
                })
                .collect();
            let bg = rgb_to_u8(opts.background);
            let eye = frame.camera.eye;
            let mut in_shadow: HashMap<(u32, LightSet), [u8; 3]> = HashMap::new();
            let sets = shadowed.as_deref();
            let mut flat = |i: usize, id: u32| match sets.map(|s| s[i]) {
                Some(set) if !set.is_empty() => *in_shadow
                    .entry((id, set))
                    .or_insert_with(|| rgb_to_u8(shade_face_in_shadow(scene, id, eye, set))),
                _ => palette[id as usize],
            };
            if pixel_shading::needed(scene) {
                pixel_shading::shade(scene, frame, &ids, sets, &mut flat, bg)
            } else if sets.is_some() {
                ids.iter()
                    .enumerate()
                    .map(|(i, &id)| if id == NO_FACE { bg } else { flat(i, id) })
                    .collect()
            } else {
                ids.iter()
                    .map(|&id| {
                        if id == NO_FACE {
                            bg
                        } else {
                            palette[id as usize]
                        }
                    })
                    .collect()
            }
        }
    };
    Raster {
        color: ColorImage {
            width: w,
            height: h,
            pixels,
        },
        depth: DepthImage {
            width: w,
            height: h,
            depths,
        },
        ids: IdImage {
            width: w,
            height: h,
            ids,
        },
        shadowed,
        stats,
    }
}

/// `shade_face(scene, face, eye)`, computed without allocating for triangles (the same
/// operations in the same order, so the same bits).
fn flat_color(scene: &Scene, face: u32, eye: DVec3) -> Rgb {
    let f = &scene.faces[face as usize];
    let m = &scene.materials[f.material as usize];
    if m.illum == 0 {
        return m.kd;
    }
    if let [a, b, c] = f.vertices[..] {
        let pts = [a, b, c].map(|v| scene.vertices[v as usize]);
        let centre = pts.iter().copied().sum::<DVec3>() / 3.0;
        return shade_in_scene(scene, m, centre, polygon_normal(&pts), eye);
    }
    shade_face(scene, face, eye)
}

/// The projected edges whose neighbourhood is ambiguous between float and exact
/// answers: every face's outline and the edges cut by the near and far planes (after
/// culling and clipping as [`render`] does), in pixel coordinates. Triangulation
/// diagonals are left out. Lines where faces pierce each other are not included; a
/// caller comparing with a painter's output adds the edges of its fragments.
pub fn scene_edges(
    scene: &Scene,
    camera: &Camera,
    opts: &RenderOptions,
) -> Result<Vec<Segment2>, ZError> {
    let frame = Frame::new(scene, camera, opts)?;
    let mut edges = Vec::new();
    prepare(scene, &frame, Culling::of(opts), Collect::Edges(&mut edges));
    Ok(edges
        .into_iter()
        .map(|(a, b, _)| ([a.x, a.y], [b.x, b.y]))
        .collect())
}
