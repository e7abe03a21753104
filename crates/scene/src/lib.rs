//! Scene model, camera, lights, materials and shading for limn (the file loaders are in
//! `limn-load`).
//!
//! A [`Scene`] is a flat list of polygonal [`Face`]s over a shared vertex array, in world
//! coordinates. Every face keeps its index in the input order: that index is the *face
//! id*, which survives culling, clipping, splitting and merging, so that pictures can be
//! compared face by face.
//!
//! ```
//! use limn_scene::{Scene, Material, Camera};
//! use glam::DVec3;
//!
//! let mut scene = Scene::default();
//! let red = scene.add_material(Material::unlit("red", [1.0, 0.0, 0.0]));
//! let obj = scene.add_object("triangle");
//! let a = scene.add_vertex(DVec3::new(0.0, 0.0, 0.0));
//! let b = scene.add_vertex(DVec3::new(1.0, 0.0, 0.0));
//! let c = scene.add_vertex(DVec3::new(0.0, 1.0, 0.0));
//! let id = scene.add_face(&[a, b, c], red, obj).unwrap();
//! assert_eq!(id, 0);
//! let camera = Camera::framing(&scene, 800, 600).unwrap();
//! assert!(camera.eye.is_finite());
//! ```

mod camera;
mod face_colors;
mod light_set;
mod look;
mod marks;
mod model;
mod shade;
pub mod shapes;
pub mod texture;
pub mod texture_wrap;

pub use camera::{Camera, CameraError, Projected, Projection, Viewpoint, DEFAULT_VIEW_DIRECTION};
pub use face_colors::FaceColors;
pub use light_set::LightSet;
pub use look::{Fog, FogError, FogFalloff, ParseShadingError, Shading};
pub use marks::{LabelAnchor, MarkerShape, PointMark, Polyline, TextLabel};
pub use model::{Face, Light, LightKind, Material, Object, Scene, SceneError};
pub use shade::{
    fan_weights, interpolated_normal, polygon_normal, shade_face, shade_face_in_shadow,
    shade_face_tinted, shade_in_scene, shade_point, shade_sided, shade_sided_in_scene,
    shade_sided_in_shadow, shade_tinted_in_shadow, Effects, FaceNormals, Rgb,
};
pub use texture::{FaceTexcoords, Texture, TextureAlpha, TextureError};
pub use texture_wrap::{wrap_material_texture, Wrap, WrapError};
