//! Smooth shading per pixel, for every method that yields a face id per pixel: the
//! world point seen at the pixel centre (the pixel's ray met with the face's plane) is
//! shaded with the face's mode ([`Shading::of_face`]): Gouraud interpolates the
//! corners' colours with the point's barycentric weights (perspective-correct, as
//! they are taken in world space), Phong interpolates the normals and lights the point.
//! Flat faces keep their one colour. Textured faces (texture coordinates and a textured
//! material) are shaded as the others (flat, Gouraud or Phong, vertex colours as a
//! tint), as the painter draws them, times the texture sampled at the point's texture
//! coordinates (bilinear, repeating; perspective-correct, as they are interpolated in
//! world space). A face with vertex colours is tinted at the point
//! by its interpolated colour (Phong), or interpolates its corners' tinted colours
//! (Gouraud; lit flat, the corners' colours are the flat lighting times their vertex
//! colours), as the painter draws it. Nothing here runs when no face is smooth,
//! textured or vertex-coloured.

use glam::DVec3;
use limn_scene::{
    fan_weights, polygon_normal, shade_face, shade_face_in_shadow, shade_face_tinted,
    shade_tinted_in_shadow, FaceColors, FaceNormals, FaceTexcoords, LightSet, Rgb, Scene, Shading,
};

use crate::image::{rgb_to_u8, NO_FACE};
use crate::pixel_rays::PixelRays;
use crate::setup::Frame;

/// Whether some face of `scene` is shaded smoothly, textured or vertex-coloured (and
/// [`shade`] is needed).
pub(crate) fn needed(scene: &Scene) -> bool {
    scene.faces.iter().any(|f| {
        let m = &scene.materials[f.material as usize];
        Shading::of_face(scene.shading, f, m) != Shading::Flat
            || (f.texcoords.is_some() && m.texture.is_some())
            || f.colors.is_some()
    })
}

/// What one smooth or textured face needs per pixel.
struct Smooth {
    phong: bool,
    /// Textured: the mapping and the face's flat colour it multiplies.
    texture: Option<(FaceTexcoords, Rgb)>,
    normals: Option<FaceNormals>,
    /// The vertex colours, if the face has them.
    colors: Option<FaceColors>,
    /// Lit flat (with vertex colours: the corners' colours are the flat lighting times
    /// theirs).
    flat: bool,
    /// The face's corners.
    corners: Vec<DVec3>,
    /// Gouraud: the colour at each corner.
    corner_colors: Vec<Rgb>,
    /// The face's geometric normal (lit side, plane).
    side: DVec3,
    /// A point of the face's plane.
    origin: DVec3,
    /// The eye the face is shaded from.
    eye: DVec3,
}

/// Colours of `ids` (face per pixel, [`NO_FACE`] for the background): `flat(pixel,
/// face)` for flat faces, per-pixel shading for smooth ones, leaving out the lights of
/// `shadowed[pixel]` when given.
pub(crate) fn shade(
    scene: &Scene,
    frame: &Frame,
    ids: &[u32],
    shadowed: Option<&[LightSet]>,
    flat: &mut dyn FnMut(usize, u32) -> [u8; 3],
    background: [u8; 3],
) -> Vec<[u8; 3]> {
    let eye = frame.camera.eye;
    let rays = PixelRays::new(frame);
    let mut faces: Vec<Option<Option<Smooth>>> = (0..scene.faces.len()).map(|_| None).collect();
    ids.iter()
        .enumerate()
        .map(|(i, &id)| {
            if id == NO_FACE {
                return background;
            }
            let smooth = faces[id as usize].get_or_insert_with(|| smooth_face(scene, id, eye));
            let Some(s) = smooth else {
                return flat(i, id);
            };
            let set = shadowed.map_or(LightSet::EMPTY, |sh| sh[i]);
            let Some((p, _)) = rays.meet(i, s.side, s.origin) else {
                return flat(i, id);
            };
            let m = &scene.materials[scene.faces[id as usize].material as usize];
            let c = if let (Some((_, flat)), true, None) = (&s.texture, s.flat, &s.colors) {
                // Textured, lit flat, no vertex colours: the face's one colour.
                if set.is_empty() {
                    *flat
                } else {
                    shade_face_in_shadow(scene, id, eye, set)
                }
            } else if s.phong {
                let n = s.normals.as_ref().and_then(|ns| ns.at(p)).unwrap_or(s.side);
                let tint = s.colors.as_ref().map_or([1.0; 3], |c| c.at(p));
                shade_tinted_in_shadow(scene, m, tint, p, n, s.side, eye, set)
            } else {
                match fan_weights(&s.corners, p) {
                    Some((idx, wts)) => {
                        let corner = |j: usize| -> Rgb {
                            if set.is_empty() {
                                s.corner_colors[j]
                            } else {
                                corner_color(scene, id, s, j, set)
                            }
                        };
                        let cc = idx.map(corner);
                        [0, 1, 2].map(|k| (0..3).map(|j| wts[j] * cc[j][k]).sum::<f64>())
                    }
                    None => return flat(i, id),
                }
            };
            // Textured: the lit colour times the texture.
            let c = match &s.texture {
                Some((tex, _)) => {
                    let t = tex.color_at(p);
                    [0, 1, 2].map(|k| c[k] * t[k])
                }
                None => c,
            };
            rgb_to_u8(c)
        })
        .collect()
}

fn smooth_face(scene: &Scene, face: u32, eye: DVec3) -> Option<Smooth> {
    let f = &scene.faces[face as usize];
    let m = &scene.materials[f.material as usize];
    let texture = FaceTexcoords::new(scene, face);
    let colors = FaceColors::new(scene, face);
    let (phong, flat) = match Shading::of_face(scene.shading, f, m) {
        Shading::Flat if colors.is_some() || texture.is_some() => (false, true),
        Shading::Flat => return None,
        Shading::Gouraud => (false, false),
        Shading::Phong => (true, false),
    };
    let normals = if flat {
        None
    } else {
        Some(FaceNormals::new(scene, face)?)
    };
    let corners = scene.face_points(face);
    let side = polygon_normal(&corners);
    if side.length_squared() == 0.0 {
        return None;
    }
    let origin = corners.iter().copied().sum::<DVec3>() / corners.len() as f64;
    let mut s = Smooth {
        phong,
        texture: texture.map(|t| (t, shade_face(scene, face, eye))),
        normals,
        colors,
        flat,
        corners,
        corner_colors: Vec::new(),
        side,
        origin,
        eye,
    };
    if !phong {
        s.corner_colors = (0..s.corners.len())
            .map(|j| corner_color(scene, face, &s, j, LightSet::EMPTY))
            .collect();
    }
    Some(s)
}

/// The Gouraud colour of corner `j` of smooth face `face` without the lights in
/// `shadowed`: lit there with its normal (or flat, at the centroid), tinted by its
/// vertex colour.
fn corner_color(scene: &Scene, face: u32, s: &Smooth, j: usize, shadowed: LightSet) -> Rgb {
    let tint = s.colors.as_ref().map_or([1.0; 3], |c| c.colors()[j]);
    if s.flat {
        return shade_face_tinted(scene, face, s.eye, shadowed, tint);
    }
    let m = &scene.materials[scene.faces[face as usize].material as usize];
    let n = s.normals.as_ref().map_or(s.side, |ns| ns.normals()[j]);
    shade_tinted_in_shadow(scene, m, tint, s.corners[j], n, s.side, s.eye, shadowed)
}
