//! From ordered fragments to a paintable [`Picture`]: flat or Gouraud shading per face
//! (only the effects the scene asks for), opacity, object names, outlines, whole-face
//! covers and seam flaps.

use std::collections::HashMap;

use glam::DVec3;
use limn_scene::{shade_face, shade_face_in_shadow, FaceTexcoords, Scene, Shading};

use limn_depthsort::Ordered;

use crate::covers::covers;
use crate::phong::DEFAULT_TOLERANCE;
use crate::seams::{seam_flaps_indexed, FlapJoin};
use crate::smooth::{FaceLight, View};
use crate::texturing::{FaceTexture, Projector, TextureTable};
use crate::{Outline, PaintFragment, Picture};

/// How to turn an order into a picture.
#[derive(Debug, Clone, PartialEq)]
pub struct Style {
    /// Page background (RGBA); `None` = transparent. Default: `None`.
    pub background: Option<[f64; 4]>,
    /// Outline original model edges with this style; `None` = no outlines. Default:
    /// `None`.
    pub outline: Option<Outline>,
    /// Paint the first piece of a split opaque polygon as the whole polygon, so that the
    /// cuts leave no anti-aliasing seams (the picture is otherwise the same; see
    /// [`covers`]). Default: `true`.
    pub seamless: bool,
    /// Smooth shading for lit faces with vertex normals, as the scene asks
    /// ([`Scene::shading`], see [`Shading::of_face`]): Gouraud (colours computed at the
    /// fragment's vertices, normals interpolated over the input face, interpolated by
    /// the painter) or Phong (the fragment split into Gouraud triangles within
    /// [`Style::tolerance`] of per-point shading). `false` draws every face flat.
    /// Default: `true`.
    pub smooth: bool,
    /// Phong shading: the largest difference per channel (colours in [0, 1]) between
    /// the painted Gouraud triangles and per-point shading; must be > 0. Default 1/255.
    pub tolerance: f64,
    /// Width in pixels of the seam flaps (see [`crate::seam_flaps`]); 0 = none. Default:
    /// 0.5 px.
    pub seams: f64,
}

impl Default for Style {
    fn default() -> Self {
        Style {
            background: None,
            outline: None,
            seamless: true,
            smooth: true,
            tolerance: DEFAULT_TOLERANCE,
            seams: 0.5,
        }
    }
}

impl Style {
    /// How seam flaps are painted: joined into their fragments' outlines, unless
    /// outline strokes need every original edge.
    pub fn flap_join(&self) -> FlapJoin {
        if self.outline.is_some() {
            FlapJoin::Separate
        } else {
            FlapJoin::Joined
        }
    }
}

/// Builds the picture of `ordered` (which must come from `scene`). Each face is shaded
/// once (flat, at its centroid, from the eye actually used); `illum 0` materials keep
/// exactly their `Kd`.
///
/// Textured faces (texture coordinates and a textured material) are shaded flat and
/// their fragments carry a [`crate::TextureMap`]: the texture's colour multiplies the
/// lit colour (as OpenGL's modulate: for `illum 0` exactly `Kd` times the texture).
pub fn picture(scene: &Scene, ordered: &Ordered, style: &Style) -> Picture {
    let cam = &ordered.camera;
    let mut cache: Vec<Option<[f64; 4]>> = vec![None; scene.faces.len()];
    let cover = covers(scene, ordered);
    let mut fragments = Vec::with_capacity(ordered.fragments.len());
    let mut view: Option<View<'_>> = None;
    // Textures cost nothing unless some material has one.
    let any_texture = scene.materials.iter().any(|m| m.texture.is_some());
    let mut textures = TextureTable::default();
    let mut face_textures: HashMap<u32, Option<FaceTexture>> = HashMap::new();
    let projector = any_texture.then(|| Projector {
        camera: cam,
        vp: cam.view_projection(ordered.near, ordered.far),
    });
    for (f, cover) in ordered.fragments.iter().zip(&cover) {
        let face = &scene.faces[f.face as usize];
        let opacity = || {
            scene.materials[face.material as usize]
                .opacity
                .clamp(0.0, 1.0)
        };
        let fill = if f.shadowed.is_empty() {
            *cache[f.face as usize].get_or_insert_with(|| {
                let c = shade_face(scene, f.face, cam.eye);
                [c[0], c[1], c[2], opacity()]
            })
        } else {
            let c = shade_face_in_shadow(scene, f.face, cam.eye, f.shadowed);
            [c[0], c[1], c[2], opacity()]
        };
        // An opaque face's first piece is painted as the whole polygon (see `covers`);
        // translucent faces must not be painted twice.
        let use_cover = fill[3] >= 1.0 && style.seamless && cover.is_some();
        let (points, original_edges) = match cover {
            Some(c) if use_cover => (c.clone(), vec![true; c.len()]),
            _ => (f.points.clone(), f.original_edges.clone()),
        };
        let m = &scene.materials[face.material as usize];
        if let Some(projector) = &projector {
            let tex = face_textures.entry(f.face).or_insert_with(|| {
                let ft = FaceTexcoords::new(scene, f.face)?;
                let index = textures.index_of(ft.texture());
                Some(FaceTexture::new(&ft, index, projector))
            });
            if let Some(tex) = tex {
                let world: Vec<DVec3> = if use_cover {
                    face.vertices
                        .iter()
                        .map(|&v| scene.vertices[v as usize])
                        .collect()
                } else {
                    f.world.clone()
                };
                let frag = PaintFragment {
                    points,
                    fill,
                    vertex_colors: None,
                    face: f.face,
                    object: face.object,
                    original_edges,
                    texture: None,
                };
                tex.apply(frag, &world, projector, &mut fragments);
                continue;
            }
        }
        let shading = if style.smooth {
            Shading::of_face(scene.shading, face, m)
        } else {
            Shading::Flat
        };
        let mut frag = PaintFragment {
            points,
            fill,
            vertex_colors: None,
            face: f.face,
            object: face.object,
            original_edges,
            texture: None,
        };
        if shading == Shading::Flat {
            fragments.push(frag);
            continue;
        }
        let world: Vec<DVec3> = if use_cover {
            face.vertices
                .iter()
                .map(|&v| scene.vertices[v as usize])
                .collect()
        } else {
            f.world.clone()
        };
        let light = FaceLight::new(scene, f.face).in_shadow_of(f.shadowed);
        if shading == Shading::Phong && world.len() == frag.points.len() {
            let view = view.get_or_insert_with(|| View {
                camera: cam,
                vp: cam.view_projection(ordered.near, ordered.far),
                tolerance: style.tolerance,
            });
            light.phong(&frag, &world, view, &mut fragments);
        } else {
            frag.vertex_colors = Some(light.vertex_colors(&world, cam.eye, fill[3]));
            fragments.push(frag);
        }
    }
    let fragments = if style.seams.is_finite() && style.seams > 0.0 {
        seam_flaps_indexed(fragments, style.seams, style.flap_join()).0
    } else {
        fragments
    };
    Picture {
        width: cam.width,
        height: cam.height,
        background: style.background,
        objects: scene.objects.iter().map(|o| o.name.clone()).collect(),
        fragments,
        outline: style.outline,
        seams: 0.0,
        marks: Vec::new(),
        textures: textures.list,
    }
}
