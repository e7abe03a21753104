//! Shadow maps: the two-pass z-buffer of the reference notes. First a depth image of the
//! scene seen from each light that casts shadows (a light at infinity: one orthographic
//! view of the whole scene; a point light: the six 90° views of a cube around it); then,
//! for each pixel's point, its depth from the light compared with the map's nearest
//! sample: the point is in shadow when it lies farther than the stored depth **plus the
//! bias**, a distance along the light's view axis stated in
//! [`ShadowMapOptions::bias`].
//!
//! The map is a sampled approximation, with the two classic errors against exact ray
//! casting: *acne* (a lit surface shadowing itself where the bias is smaller than the
//! depth change across one map sample) and *peter-panning* (shadows detached from their
//! casters where the bias hides thin gaps). `limn-bench effects` measures both.
//!
//! As in the object-space shadows and ray casting, only opaque faces cast shadows, and a
//! point whose seen side faces away from the light is in its shadow (decided here in
//! floats).

use std::cmp::Ordering;

use glam::{DMat4, DVec3};
use limn_scene::{Camera, LightKind, LightSet, Projection, Scene};

use crate::options::RenderOptions;
use crate::setup::{prepare, Collect, Culling, Frame, Prepared};
use crate::{zbuf, DepthFormat, ZError};

/// How shadow maps are made and read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShadowMapOptions {
    /// Samples per side of each map (each of a point light's six). Default 2048.
    pub size: u32,
    /// Depth bias, as a fraction of the diagonal of the scene's bounding box: a point is
    /// in shadow only when it lies farther from the light than the map's sample by more
    /// than `bias × diagonal`. Default 0.001 (about two samples of a surface at 45° in a
    /// 2048 map of the whole scene).
    pub bias: f64,
}

impl Default for ShadowMapOptions {
    fn default() -> Self {
        ShadowMapOptions {
            size: 2048,
            bias: 1e-3,
        }
    }
}

/// One depth image from a light.
struct View {
    /// The light's camera (eye and axis), its view-projection, near and far.
    camera: Camera,
    vp: DMat4,
    near: f64,
    far: f64,
    /// Distance along the view axis of the nearest surface per sample (∞: none).
    depth: Vec<f32>,
}

/// The maps of one light.
struct LightMaps {
    index: usize,
    kind: LightKind,
    views: Vec<View>,
}

/// The shadow maps of every light that casts shadows.
pub(crate) struct ShadowMaps {
    lights: Vec<LightMaps>,
    size: u32,
    bias: f64,
}

impl ShadowMaps {
    /// The maps of `scene`'s shadow-casting lights; `None` when no light casts shadows.
    pub fn new(scene: &Scene, opts: &ShadowMapOptions) -> Result<Option<ShadowMaps>, ZError> {
        let set = scene.shadow_lights();
        if set.is_empty() {
            return Ok(None);
        }
        if opts.size == 0 || opts.size > 16384 || !(opts.bias.is_finite() && opts.bias >= 0.0) {
            return Err(ZError::BadShadowMap {
                size: opts.size,
                bias: opts.bias,
            });
        }
        let Some((lo, hi)) = scene.bounds() else {
            return Ok(None);
        };
        // Only opaque faces cast shadows.
        let opaque;
        let casters = if scene
            .faces
            .iter()
            .all(|f| scene.materials[f.material as usize].is_opaque())
        {
            scene
        } else {
            let mut s = scene.clone();
            s.faces
                .retain(|f| scene.materials[f.material as usize].is_opaque());
            opaque = s;
            &opaque
        };
        let centre = (lo + hi) * 0.5;
        let radius = ((hi - lo).length() * 0.5).max(f64::MIN_POSITIVE);
        let mut lights = Vec::new();
        for index in set.iter() {
            let kind = scene.lights[index].kind;
            let cams: Vec<(Camera, f64, f64)> = match kind {
                LightKind::Directional(d) => {
                    let d = d.normalize();
                    let mut cam = Camera::orthographic(
                        centre + d * (2.0 * radius),
                        centre,
                        2.0 * radius,
                        opts.size,
                        opts.size,
                    );
                    cam.up = d.any_orthonormal_vector();
                    vec![(cam, 0.5 * radius, 3.5 * radius)]
                }
                LightKind::Point(l) => {
                    let far = (l - centre).length() + 1.01 * radius;
                    let near = far * 1e-6;
                    let faces = [
                        (DVec3::X, DVec3::NEG_Y),
                        (DVec3::NEG_X, DVec3::NEG_Y),
                        (DVec3::Y, DVec3::Z),
                        (DVec3::NEG_Y, DVec3::NEG_Z),
                        (DVec3::Z, DVec3::NEG_Y),
                        (DVec3::NEG_Z, DVec3::NEG_Y),
                    ];
                    faces
                        .iter()
                        .map(|&(axis, up)| {
                            let mut cam = Camera::new(l, l + axis, opts.size, opts.size);
                            cam.fov_deg = 90.0;
                            cam.up = up;
                            (cam, near, far)
                        })
                        .collect()
                }
                LightKind::Ambient | LightKind::Headlight => continue,
            };
            let mut views = Vec::with_capacity(cams.len());
            for (camera, near, far) in cams {
                views.push(depth_view(casters, camera, near, far)?);
            }
            lights.push(LightMaps { index, kind, views });
        }
        Ok(Some(ShadowMaps {
            lights,
            size: opts.size,
            bias: opts.bias * (hi - lo).length(),
        }))
    }

    /// The lights whose shadow the point `x` (on a face with geometric normal `n`, seen
    /// from `eye`) lies in, by the maps.
    pub fn shadowed(&self, x: DVec3, n: DVec3, eye: DVec3) -> LightSet {
        let mut set = LightSet::EMPTY;
        let seen = n.dot(eye - x);
        for l in &self.lights {
            let (to_light, views) = match l.kind {
                LightKind::Directional(d) => (d, &l.views[..]),
                LightKind::Point(p) => {
                    let v = x - p;
                    let a = v.abs();
                    let k = if a.x >= a.y && a.x >= a.z {
                        usize::from(v.x < 0.0)
                    } else if a.y >= a.z {
                        2 + usize::from(v.y < 0.0)
                    } else {
                        4 + usize::from(v.z < 0.0)
                    };
                    (p - x, &l.views[k..k + 1])
                }
                _ => continue,
            };
            // Lit only when the light lies strictly on the seen side (a NaN is not).
            let lit_side = (n.dot(to_light) * seen).partial_cmp(&0.0) == Some(Ordering::Greater);
            if !lit_side || views.iter().any(|v| self.behind(v, x)) {
                set.insert(l.index);
            }
        }
        set
    }

    /// Whether `x` lies farther along `v`'s axis than its sample plus the bias.
    fn behind(&self, v: &View, x: DVec3) -> bool {
        let p = v.camera.project_with(&v.vp, x);
        let s = f64::from(self.size);
        if !(p.x >= 0.0 && p.y >= 0.0 && p.x <= s && p.y <= s) {
            return false;
        }
        let (i, j) = (
            (p.x as u32).min(self.size - 1),
            (p.y as u32).min(self.size - 1),
        );
        let stored = f64::from(v.depth[(j * self.size + i) as usize]);
        let depth = (x - v.camera.eye).dot(v.camera.forward());
        depth > stored + self.bias && depth >= v.near && depth <= v.far
    }
}

/// The z-buffer of `scene` from `camera`, as distances along its axis.
fn depth_view(scene: &Scene, camera: Camera, near: f64, far: f64) -> Result<View, ZError> {
    let opts = RenderOptions {
        near_far: Some((near, far)),
        ..RenderOptions::default()
    };
    let frame = Frame::new(scene, &camera, &opts)?;
    let mut prep = Prepared::default();
    prepare(scene, &frame, Culling::NONE, Collect::Triangles(&mut prep));
    let b = zbuf::zbuffer(&prep, camera.width, camera.height, DepthFormat::F64);
    let perspective = matches!(camera.projection, Projection::Perspective);
    let depth = b
        .depths
        .iter()
        .map(|&d| {
            if !d.is_finite() {
                return f32::INFINITY;
            }
            // Window depth back to the distance along the axis.
            let z = 2.0 * d - 1.0;
            let lin = if perspective {
                2.0 * near * far / (far + near - z * (far - near))
            } else {
                near + d * (far - near)
            };
            lin as f32
        })
        .collect();
    Ok(View {
        camera,
        vp: frame.vp,
        near,
        far,
        depth,
    })
}
