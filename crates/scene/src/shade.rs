//! Shading: only the effects a scene asks for.
//!
//! * `illum 0` materials are drawn with exactly their `Kd`: nothing else is computed.
//! * Lit materials (`illum 1`, `illum 2`) use the Phong reflection model (ambient,
//!   diffuse, and for `illum 2` specular) with the scene's lights, or a white headlight
//!   when the scene has none.
//! * Faces are lit two-sided: a face seen from behind is lit with its normal flipped.

use glam::DVec3;

use crate::{Light, LightKind, LightSet, Material, Scene, Shading};

/// A linear RGB colour, each channel in [0, 1].
pub type Rgb = [f64; 3];

/// Which effects a scene calls for. Everything that is `false` costs nothing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Effects {
    /// Some material is lit (`illum` ≥ 1).
    pub lighting: bool,
    /// Some lit material has a specular term (`illum 2` with non-zero `Ks`).
    pub specular: bool,
    /// Some material is translucent (opacity < 1): blending in painter's order.
    pub transparency: bool,
    /// Some face is Gouraud-shaded (see [`Shading::of_face`]): colours computed at the
    /// vertices and interpolated.
    pub smooth: bool,
    /// Some face is Phong-shaded: normals interpolated, lighting per point.
    pub phong: bool,
    /// Some face has texture coordinates and a textured material.
    pub texture: bool,
    /// The scene has fog and some face is lit (fog never touches `illum 0` colours).
    pub fog: bool,
    /// Some light casts shadows (`shadows = true`) and some face is lit.
    pub shadows: bool,
    /// Some face has vertex colours (interpolated between its corners).
    pub vertex_colors: bool,
}

impl Effects {
    /// The effects the faces of `scene` need.
    pub fn of(scene: &Scene) -> Effects {
        let mut used = vec![false; scene.materials.len()];
        let mut e = Effects::default();
        for f in &scene.faces {
            used[f.material as usize] = true;
            e.vertex_colors |= f.colors.is_some();
            if f.texcoords.is_some() && scene.materials[f.material as usize].texture.is_some() {
                e.texture = true;
            }
            match Shading::of_face(scene.shading, f, &scene.materials[f.material as usize]) {
                Shading::Flat => {}
                Shading::Gouraud => e.smooth = true,
                Shading::Phong => e.phong = true,
            }
        }
        for (m, _) in scene.materials.iter().zip(&used).filter(|(_, &u)| u) {
            if m.illum >= 1 {
                e.lighting = true;
            }
            if m.illum >= 2 && m.ks.iter().any(|&c| c > 0.0) {
                e.specular = true;
            }
            if !m.is_opaque() {
                e.transparency = true;
            }
        }
        e.fog = e.lighting && scene.fog.is_some();
        e.shadows = e.lighting && !scene.shadow_lights().is_empty();
        e
    }

    /// Names of the effects that are on, for reports.
    pub fn names(&self) -> Vec<&'static str> {
        let mut v = Vec::new();
        if self.lighting {
            v.push("lighting");
        }
        if self.specular {
            v.push("specular");
        }
        if self.transparency {
            v.push("transparency");
        }
        if self.smooth {
            v.push("gouraud");
        }
        if self.phong {
            v.push("phong");
        }
        if self.fog {
            v.push("fog");
        }
        if self.texture {
            v.push("texture");
        }
        if self.shadows {
            v.push("shadows");
        }
        if self.vertex_colors {
            v.push("vertex-colors");
        }
        v
    }
}

/// The geometric normal of a polygon (Newell's method), not normalised; zero for a
/// degenerate polygon.
pub fn polygon_normal(points: &[DVec3]) -> DVec3 {
    let mut n = DVec3::ZERO;
    let c = points.iter().copied().sum::<DVec3>() / points.len().max(1) as f64;
    for i in 0..points.len() {
        let a = points[i] - c;
        let b = points[(i + 1) % points.len()] - c;
        n += a.cross(b);
    }
    n
}

/// The colour of a point with normal `n` (any length) seen from `eye`, under `lights`
/// (a white headlight when empty). `illum 0` returns `Kd` unchanged.
pub fn shade_point(m: &Material, p: DVec3, n: DVec3, eye: DVec3, lights: &[Light]) -> Rgb {
    shade_sided(m, p, n, n, eye, lights)
}

/// [`shade_point`] with the lit side chosen by `side` (the face's geometric normal)
/// instead of `n`: an interpolated normal of a face seen from its front may turn away
/// from the eye near a silhouette, and must not flip there (the colour would jump).
pub fn shade_sided(
    m: &Material,
    p: DVec3,
    n: DVec3,
    side: DVec3,
    eye: DVec3,
    lights: &[Light],
) -> Rgb {
    shade_lit_by(m, WHITE, p, n, side, eye, lights, LightSet::EMPTY)
}

/// The tint that changes nothing.
const WHITE: Rgb = [1.0; 3];

/// [`shade_sided`] leaving out the lights in `shadowed` (indices into `lights`): the
/// colour of a point in their shadow. Ambient light is never left out. `tint` (a vertex
/// colour) multiplies `Kd` and `Ka`, not the specular term.
#[allow(clippy::too_many_arguments)]
fn shade_lit_by(
    m: &Material,
    tint: Rgb,
    p: DVec3,
    n: DVec3,
    side: DVec3,
    eye: DVec3,
    lights: &[Light],
    shadowed: LightSet,
) -> Rgb {
    if m.illum == 0 {
        return [0, 1, 2].map(|k| m.kd[k] * tint[k]);
    }
    let to_eye = (eye - p).normalize_or_zero();
    let mut n = n.normalize_or_zero();
    if side.dot(eye - p) < 0.0 {
        n = -n; // two-sided lighting
    }
    const HEADLIGHT: [Light; 1] = [Light {
        kind: LightKind::Headlight,
        color: [1.0, 1.0, 1.0],
        shadows: false,
    }];
    let lights = if lights.is_empty() {
        &HEADLIGHT[..]
    } else {
        lights
    };
    // Ambient: `Ka` times the sum of the ambient lights (white when the scene has no
    // ambient light of its own).
    let mut ambient = [0.0f64; 3];
    let mut has_ambient = false;
    for l in lights {
        if let LightKind::Ambient = l.kind {
            has_ambient = true;
            for (a, c) in ambient.iter_mut().zip(l.color) {
                *a += c;
            }
        }
    }
    if !has_ambient {
        ambient = [1.0; 3];
    }
    let mut out = [0.0f64; 3];
    for (k, o) in out.iter_mut().enumerate() {
        *o = m.ka[k] * tint[k] * ambient[k];
    }
    for (i, l) in lights.iter().enumerate() {
        if shadowed.contains(i) {
            continue;
        }
        let dir = match l.kind {
            LightKind::Ambient => continue,
            LightKind::Directional(d) => d.normalize_or_zero(),
            LightKind::Point(q) => (q - p).normalize_or_zero(),
            LightKind::Headlight => to_eye,
        };
        let cos = n.dot(dir);
        let diff = cos.max(0.0);
        let spec = if m.illum >= 2 && cos > 0.0 {
            let r = 2.0 * cos * n - dir;
            r.dot(to_eye).max(0.0).powf(m.ns.max(1.0))
        } else {
            0.0
        };
        for (k, o) in out.iter_mut().enumerate() {
            *o += l.color[k] * (m.kd[k] * tint[k] * diff + m.ks[k] * spec);
        }
    }
    out.map(|c| c.clamp(0.0, 1.0))
}

/// The normal of face `face` at world point `p` (which lies in or on the face),
/// interpolated from the face's vertex normals; `None` when the face has none. Triangles
/// interpolate barycentrically; larger faces use the fan triangle from the first corner
/// that contains `p` (the nearest one when rounding puts `p` just outside all of them).
pub fn interpolated_normal(scene: &Scene, face: u32, p: DVec3) -> Option<DVec3> {
    FaceNormals::new(scene, face)?.at(p)
}

/// A face's corners and vertex normals, gathered once for many
/// [`interpolated_normal`] look-ups (per-point shading asks for thousands per face).
#[derive(Debug, Clone, PartialEq)]
pub struct FaceNormals {
    corners: Vec<DVec3>,
    normals: Vec<DVec3>,
}

impl FaceNormals {
    /// The corners and normals of `face`; `None` when it has no vertex normals.
    pub fn new(scene: &Scene, face: u32) -> Option<FaceNormals> {
        let f = &scene.faces[face as usize];
        let ns = f.normals.as_ref()?;
        Some(FaceNormals {
            corners: f
                .vertices
                .iter()
                .map(|&v| scene.vertices[v as usize])
                .collect(),
            normals: ns.iter().map(|&i| scene.normals[i as usize]).collect(),
        })
    }

    /// The interpolated normal at `p`, as [`interpolated_normal`]; `None` when it
    /// vanishes or every fan triangle is degenerate.
    pub fn at(&self, p: DVec3) -> Option<DVec3> {
        let ([a, b, c], w) = self.weights(p)?;
        let n = &self.normals;
        Some(n[a] * w[0] + n[b] * w[1] + n[c] * w[2]).filter(|v| v.length_squared() > 0.0)
    }

    /// The fan triangle (corner indices `0, i, i + 1`) that contains `p` (the nearest
    /// when rounding puts `p` just outside all of them) and `p`'s barycentric
    /// coordinates in it: the weights [`FaceNormals::at`] gives the corners' normals,
    /// for interpolating anything else given per corner.
    pub fn weights(&self, p: DVec3) -> Option<([usize; 3], [f64; 3])> {
        fan_weights(&self.corners, p)
    }

    /// The face's corners.
    pub fn corners(&self) -> &[DVec3] {
        &self.corners
    }

    /// The face's vertex normals, one per corner.
    pub fn normals(&self) -> &[DVec3] {
        &self.normals
    }
}

/// The fan triangle (corner indices `0, i, i + 1`) of the polygon `c` that contains `p`
/// (the nearest when rounding puts `p` just outside all of them) and `p`'s barycentric
/// coordinates in it; `None` when every fan triangle is degenerate.
pub fn fan_weights(c: &[DVec3], p: DVec3) -> Option<([usize; 3], [f64; 3])> {
    let mut best: Option<(f64, [usize; 3], [f64; 3])> = None;
    for i in 1..c.len().saturating_sub(1) {
        let (a, b, d) = (c[0], c[i], c[i + 1]);
        let nrm = (b - a).cross(d - a);
        let den = nrm.length_squared();
        if den <= 0.0 || !den.is_finite() {
            continue;
        }
        let wa = (d - b).cross(p - b).dot(nrm) / den;
        let wb = (a - d).cross(p - d).dot(nrm) / den;
        let wd = 1.0 - wa - wb;
        let worst = wa.min(wb).min(wd);
        if best.is_none_or(|(w, ..)| worst > w) {
            best = Some((worst, [0, i, i + 1], [wa, wb, wd]));
        }
        if worst >= 0.0 {
            break;
        }
    }
    best.map(|(_, idx, w)| (idx, w))
}

/// The flat colour of face `face` seen from `eye`: lit at its centroid with its geometric
/// normal (and fogged there, when the scene has fog). Returns `Kd` exactly for `illum 0`
/// materials.
pub fn shade_face(scene: &Scene, face: u32, eye: DVec3) -> Rgb {
    shade_face_in_shadow(scene, face, eye, LightSet::EMPTY)
}

/// [`shade_face`] for a piece of the face in the shadow of the lights in `shadowed`: the
/// same point, normal and fog, without those lights.
pub fn shade_face_in_shadow(scene: &Scene, face: u32, eye: DVec3, shadowed: LightSet) -> Rgb {
    shade_face_tinted(scene, face, eye, shadowed, WHITE)
}

/// [`shade_face_in_shadow`] with `Kd` and `Ka` multiplied by `tint`: the flat colour of
/// a face's point whose vertex colour is `tint` (lit at the centroid, as the face).
pub fn shade_face_tinted(
    scene: &Scene,
    face: u32,
    eye: DVec3,
    shadowed: LightSet,
    tint: Rgb,
) -> Rgb {
    let f = &scene.faces[face as usize];
    let m = &scene.materials[f.material as usize];
    if m.illum == 0 {
        return [0, 1, 2].map(|k| m.kd[k] * tint[k]);
    }
    let pts = scene.face_points(face);
    let c = pts.iter().copied().sum::<DVec3>() / pts.len() as f64;
    let n = polygon_normal(&pts);
    shade_tinted_in_shadow(scene, m, tint, c, n, n, eye, shadowed)
}

/// [`shade_point`] under the scene's lights, then seen through the scene's fog (when it
/// has one; `illum 0` colours stay exactly `Kd`).
pub fn shade_in_scene(scene: &Scene, m: &Material, p: DVec3, n: DVec3, eye: DVec3) -> Rgb {
    shade_sided_in_scene(scene, m, p, n, n, eye)
}

/// [`shade_sided`] under the scene's lights, then through the scene's fog.
pub fn shade_sided_in_scene(
    scene: &Scene,
    m: &Material,
    p: DVec3,
    n: DVec3,
    side: DVec3,
    eye: DVec3,
) -> Rgb {
    shade_sided_in_shadow(scene, m, p, n, side, eye, LightSet::EMPTY)
}

/// [`shade_sided_in_scene`] leaving out the scene's lights in `shadowed` (the point lies
/// in their shadow); fog is applied as usual.
pub fn shade_sided_in_shadow(
    scene: &Scene,
    m: &Material,
    p: DVec3,
    n: DVec3,
    side: DVec3,
    eye: DVec3,
    shadowed: LightSet,
) -> Rgb {
    shade_tinted_in_shadow(scene, m, WHITE, p, n, side, eye, shadowed)
}

/// [`shade_sided_in_shadow`] with `Kd` and `Ka` multiplied by `tint` (the vertex colour
/// at `p`).
#[allow(clippy::too_many_arguments)]
pub fn shade_tinted_in_shadow(
    scene: &Scene,
    m: &Material,
    tint: Rgb,
    p: DVec3,
    n: DVec3,
    side: DVec3,
    eye: DVec3,
    shadowed: LightSet,
) -> Rgb {
    let c = shade_lit_by(m, tint, p, n, side, eye, &scene.lights, shadowed);
    match &scene.fog {
        Some(fog) if m.illum >= 1 => fog.apply(c, p, eye),
        _ => c,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn illum0_is_exactly_kd() {
        let m = Material::unlit("x", [0.25, 0.5, 0.75]);
        let c = shade_point(&m, DVec3::ZERO, DVec3::Z, DVec3::new(0.0, 0.0, -3.0), &[]);
        assert_eq!(c, [0.25, 0.5, 0.75]);
    }

    #[test]
    fn normals_interpolate_barycentrically_and_over_fans() {
        let mut s = Scene::default();
        let m = s.add_material(Material::diffuse("m", [1.0; 3]));
        let o = s.add_object("o");
        for p in [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
        ] {
            s.add_vertex(DVec3::from(p));
        }
        s.normals = vec![DVec3::X, DVec3::Y, DVec3::Z, DVec3::NEG_X];
        let f = s.add_face(&[0, 1, 2, 3], m, o).unwrap();
        assert_eq!(interpolated_normal(&s, f, DVec3::ZERO), None);
        s.faces[0].normals = Some(Box::new([0, 1, 2, 3]));
        // At a corner: that corner's normal.
        let n = interpolated_normal(&s, f, DVec3::new(2.0, 2.0, 0.0)).unwrap();
        assert!((n - DVec3::Z).length() < 1e-12);
        // Inside the second fan triangle (0, 2, 3): a mix of X, Z and -X only.
        let n = interpolated_normal(&s, f, DVec3::new(0.5, 1.5, 0.0)).unwrap();
        assert!(n.y.abs() < 1e-12 && n.z > 0.0);
        // Inside the first fan triangle (0, 1, 2): no -X component.
        let n = interpolated_normal(&s, f, DVec3::new(1.5, 0.5, 0.0)).unwrap();
        assert!(n.y > 0.0 && n.x > 0.0);
    }

    #[test]
    fn effects_name_gouraud_only_for_lit_faces_with_normals() {
        let mut s = Scene::default();
        let lit = s.add_material(Material::diffuse("lit", [1.0; 3]));
        let flat = s.add_material(Material::unlit("flat", [1.0; 3]));
        let o = s.add_object("o");
        let f = s
            .add_polygon(&[DVec3::ZERO, DVec3::X, DVec3::Y], flat, o)
            .unwrap();
        s.normals = vec![DVec3::Z];
        s.faces[f as usize].normals = Some(Box::new([0, 0, 0]));
        assert!(!Effects::of(&s).smooth);
        s.faces[f as usize].material = lit;
        assert!(Effects::of(&s).smooth);
        assert!(Effects::of(&s).names().contains(&"gouraud"));
    }

    #[test]
    fn effects_follow_the_asked_shading_and_fog() {
        let mut s = Scene::default();
        let lit = s.add_material(Material::diffuse("lit", [1.0; 3]));
        let o = s.add_object("o");
        let f = s
            .add_polygon(&[DVec3::ZERO, DVec3::X, DVec3::Y], lit, o)
            .unwrap();
        assert_eq!(Effects::of(&s).names(), ["lighting"]);
        s.normals = vec![DVec3::Z];
        s.faces[f as usize].normals = Some(Box::new([0, 0, 0]));
        s.shading = Some(Shading::Phong);
        assert_eq!(Effects::of(&s).names(), ["lighting", "phong"]);
        s.shading = Some(Shading::Flat);
        s.fog = Some(crate::Fog {
            color: [1.0; 3],
            start: 0.0,
            end: 1.0,
            falloff: crate::FogFalloff::Linear,
        });
        assert_eq!(Effects::of(&s).names(), ["lighting", "fog"]);
        s.materials[lit as usize].illum = 0;
        assert!(Effects::of(&s).names().is_empty());
    }

    #[test]
    fn flat_colour_is_fogged_at_the_centroid() {
        let mut s = Scene::default();
        let mut m = Material::diffuse("lit", [0.5; 3]);
        m.ka = [0.0; 3];
        let lit = s.add_material(m);
        let o = s.add_object("o");
        // Facing the eye at distance 4 from it: full headlight diffuse 0.5.
        let f = s
            .add_polygon(
                &[
                    DVec3::new(-1.0, -1.0, 0.0),
                    DVec3::new(2.0, -1.0, 0.0),
                    DVec3::new(-1.0, 2.0, 0.0),
                ],
                lit,
                o,
            )
            .unwrap();
        let eye = DVec3::new(0.0, 0.0, 4.0);
        let plain = shade_face(&s, f, eye);
        assert!((plain[0] - 0.5).abs() < 1e-12);
        s.fog = Some(crate::Fog {
            color: [1.0, 0.0, 0.0],
            start: 2.0,
            end: 6.0,
            falloff: crate::FogFalloff::Linear,
        });
        // Half-way through the fog: half the surface, half the fog colour.
        let c = shade_face(&s, f, eye);
        let want = [0.25 + 0.5, 0.25, 0.25];
        for k in 0..3 {
            assert!((c[k] - want[k]).abs() < 1e-12, "{c:?}");
        }
    }

    #[test]
    fn headlight_facing_gives_full_diffuse() {
        let mut m = Material::diffuse("x", [0.5, 0.5, 0.5]);
        m.ka = [0.0; 3];
        let c = shade_point(&m, DVec3::ZERO, DVec3::Z, DVec3::new(0.0, 0.0, 3.0), &[]);
        assert!((c[0] - 0.5).abs() < 1e-12);
        let oblique = shade_point(&m, DVec3::ZERO, DVec3::X, DVec3::new(0.0, 0.0, 3.0), &[]);
        assert!(oblique[0] < 1e-12);
    }
}
