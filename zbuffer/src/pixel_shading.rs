//! Smooth shading per pixel, for every method that yields a face id per pixel: the
//! world point seen at the pixel centre (the pixel's ray met with the face's plane) is
//! shaded with the face's mode ([`Shading::of_face`]): Gouraud interpolates the
//! corners' colours with the point's barycentric weights (perspective-correct, as
//! they are taken in world space), Phong interpolates the normals and lights the point.
//! Flat faces keep their one colour. Nothing here runs when no face is smooth.

use glam::{DMat4, DVec3, DVec4};
use limn_scene::{polygon_normal, shade_sided_in_scene, FaceNormals, Rgb, Scene, Shading};

use crate::image::{rgb_to_u8, NO_FACE};
use crate::setup::Frame;

/// Whether some face of `scene` is shaded smoothly (and [`shade`] is needed).
pub(crate) fn needed(scene: &Scene) -> bool {
    scene.faces.iter().any(|f| {
        Shading::of_face(scene.shading, f, &scene.materials[f.material as usize]) != Shading::Flat
    })
}

/// What one smooth face needs per pixel.
struct Smooth {
    phong: bool,
    normals: FaceNormals,
    /// Gouraud: the colour at each corner.
    corner_colors: Vec<Rgb>,
    /// The face's geometric normal (lit side, plane).
    side: DVec3,
    /// A point of the face's plane.
    origin: DVec3,
}

/// Colours of `ids` (face per pixel, [`NO_FACE`] for the background): `flat[face]` for
/// flat faces, per-pixel shading for smooth ones.
pub(crate) fn shade(
    scene: &Scene,
    frame: &Frame,
    ids: &[u32],
    flat: &[[u8; 3]],
    background: [u8; 3],
) -> Vec<[u8; 3]> {
    let eye = frame.camera.eye;
    let inv: DMat4 = frame.vp.inverse();
    let (w, h) = (f64::from(frame.width), f64::from(frame.height));
    let mut faces: Vec<Option<Option<Smooth>>> = (0..scene.faces.len()).map(|_| None).collect();
    ids.iter()
        .enumerate()
        .map(|(i, &id)| {
            if id == NO_FACE {
                return background;
            }
            let smooth = faces[id as usize].get_or_insert_with(|| smooth_face(scene, id, eye));
            let Some(s) = smooth else {
                return flat[id as usize];
            };
            let x = (i % frame.width as usize) as f64 + 0.5;
            let y = (i / frame.width as usize) as f64 + 0.5;
            // The pixel's ray from the near to the far plane (any projection).
            let at = |z: f64| {
                let q = inv * DVec4::new(x / w * 2.0 - 1.0, 1.0 - y / h * 2.0, z, 1.0);
                q.truncate() / q.w
            };
            let (near, far) = (at(-1.0), at(1.0));
            let dir = far - near;
            let den = dir.dot(s.side);
            if den == 0.0 || !den.is_finite() {
                return flat[id as usize];
            }
            let p = near + dir * ((s.origin - near).dot(s.side) / den);
            if !p.is_finite() {
                return flat[id as usize];
            }
            let m = &scene.materials[scene.faces[id as usize].material as usize];
            let c = if s.phong {
                let n = s.normals.at(p).unwrap_or(s.side);
                shade_sided_in_scene(scene, m, p, n, s.side, eye)
            } else {
                match s.normals.weights(p) {
                    Some((idx, wts)) => {
                        let cc = &s.corner_colors;
                        [0, 1, 2].map(|k| (0..3).map(|j| wts[j] * cc[idx[j]][k]).sum::<f64>())
                    }
                    None => return flat[id as usize],
                }
            };
            rgb_to_u8(c)
        })
        .collect()
}

fn smooth_face(scene: &Scene, face: u32, eye: DVec3) -> Option<Smooth> {
    let f = &scene.faces[face as usize];
    let m = &scene.materials[f.material as usize];
    let phong = match Shading::of_face(scene.shading, f, m) {
        Shading::Flat => return None,
        Shading::Gouraud => false,
        Shading::Phong => true,
    };
    let normals = FaceNormals::new(scene, face)?;
    let pts = normals.corners();
    let side = polygon_normal(pts);
    if side.length_squared() == 0.0 {
        return None;
    }
    let origin = pts.iter().copied().sum::<DVec3>() / pts.len() as f64;
    let corner_colors = if phong {
        Vec::new()
    } else {
        pts.iter()
            .zip(normals.normals())
            .map(|(&p, &n)| shade_sided_in_scene(scene, m, p, n, side, eye))
            .collect()
    };
    Some(Smooth {
        phong,
        normals,
        corner_colors,
        side,
        origin,
    })
}
