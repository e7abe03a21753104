//! Image-space reference renderers for limn: the independent answers every vector
//! picture is checked against.
//!
//! Five methods render a [`Scene`] per pixel and produce colour, depth and face-id
//! images ([`Raster`]): a z-buffer with several depth formats, a scan-line z-buffer
//! using one row of depth, an A-buffer for transparency, Warnock's area subdivision and
//! exact ray casting. All of them follow limn's conventions:
//!
//! * `gluLookAt` / `gluPerspective` matrices from [`Camera`]; pixel coordinates
//!   `px = (ndc.x + 1)/2 · W`, `py = (1 − ndc.y)/2 · H` (y down);
//! * pixel `(i, j)` is sampled at its centre `(i + ½, j + ½)`; a centre exactly on an
//!   edge belongs to the triangle for which the edge is a top or left edge;
//! * geometry is clipped in homogeneous clip space to `near ≤ w ≤ far` before the
//!   perspective divide, so nothing behind the eye is ever projected;
//! * the face id is the face's index in `scene.faces`; [`NO_FACE`] marks the background;
//! * among equally deep faces the later one in input order wins;
//! * back faces (the eye strictly behind the face's plane) are dropped only when
//!   [`RenderOptions::cull_back_faces`] is set.
//!
//! Faces with more than three corners are triangulated by the kernel's rule, written
//! apart (see [`triangulate`]'s notes: in a coordinate projection where the outline is
//! simple, fanned when convex there and ear-clipped otherwise; fanned from the first
//! corner when no projection is simple). Colours are 8-bit channels
//! `round(c · 255)` of `shade_face` of limn-scene at the face's centroid for flat faces
//! (fog included there), and per pixel for faces the scene shades smoothly (Gouraud or
//! Phong, see `Shading::of_face`): the world point at the pixel centre is shaded, so
//! interpolation is perspective-correct. The A-buffer keeps flat colours.
//!
//! Besides rendering, the crate draws lines ([`bresenham`], [`dda`], [`wireframe`]),
//! paints 2D polygons for checking vector output ([`rasterize_ids`]), compares id
//! images ([`compare`]) outside a band of ambiguous pixels ([`edge_band`],
//! [`scene_edges`]), and writes PNGs.
//!
//! ```
//! use glam::DVec3;
//! use limn_scene::{Camera, Material, Scene};
//! use limn_zbuffer::{compare, render, Method, RenderOptions};
//!
//! let mut scene = Scene::default();
//! let red = scene.add_material(Material::unlit("red", [1.0, 0.0, 0.0]));
//! let obj = scene.add_object("quad");
//! let quad = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
//!     .map(|(x, y)| DVec3::new(x, y, 0.0));
//! scene.add_polygon(&quad, red, obj).unwrap();
//! let camera = Camera::new(DVec3::new(0.0, 0.0, 5.0), DVec3::ZERO, 64, 48);
//! let opts = RenderOptions::default();
//! let z = render(&scene, &camera, Method::ZBuffer, &opts).unwrap();
//! let r = render(&scene, &camera, Method::RayCast, &opts).unwrap();
//! assert_eq!(z.ids.get(32, 24), Some(0));
//! assert_eq!(z.color.get(32, 24), Some([255, 0, 0]));
//! assert_eq!(compare(&z.ids, &r.ids, None).mismatches, 0);
//! ```

mod abuffer;
mod bvh;
mod compare;
mod depth;
mod error;
mod exact;
mod fragment_ids;
mod image;
mod lines;
mod options;
mod pixel_rays;
mod pixel_shading;
mod png;
mod raycast;
mod render;
mod scanline;
mod setup;
mod shadow_map;
mod shadow_rays;
mod span;
mod triangulate;
mod warnock;
mod zbuf;

pub use compare::{compare, default_band_tolerance, edge_band, Comparison, Segment2};
pub use depth::DepthFormat;
pub use error::ZError;
pub use fragment_ids::{coverage_counts, rasterize_ids};
pub use image::{rgb_to_u8, to_u8, ColorImage, DepthImage, IdImage, Mask, NO_FACE};
pub use lines::{bresenham, dda, scene_lines, wireframe, LineAlgorithm, LineOptions};
pub use options::{Method, ParseMethodError, RenderOptions};
pub use png::{diff_png, id_color, save_diff_png};
pub use render::{render, render_with_shadow_maps, scene_edges, Raster, RenderStats};
pub use shadow_map::ShadowMapOptions;
pub use triangulate::triangulate;

#[doc(no_inline)]
pub use limn_scene::{Camera, Scene};

/// The largest coordinate magnitude accepted (2¹⁰⁰ ≈ 1.27e30) for vertices, the eye and
/// the target; larger values are rejected with [`ZError::OutOfRange`].
pub const MAX_COORD: f64 = 1.2676506002282294e30;

/// The largest picture rendered, in pixels (2²⁸, e.g. 16384 × 16384): beyond it the
/// buffers would need tens of gigabytes.
pub const MAX_PIXELS: u64 = 1 << 28;

/// The smallest non-zero coordinate magnitude (2⁻¹⁰⁰ ≈ 7.9e-31) at which ray casting's
/// f64 expansions never underflow: triangles with a smaller coordinate are decided with
/// big integers instead, and shadow rays (ray casting with lights that cast shadows)
/// refuse them.
pub const MIN_RAYCAST_COORD: f64 = 7.888609052210118e-31;
