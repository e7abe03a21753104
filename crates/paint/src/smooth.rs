//! Smooth shading of one fragment: Gouraud (colours at the fragment's corners, the
//! painter interpolates) or Phong (the fragment split into Gouraud triangles within a
//! tolerance of per-point shading, see [`crate::phong`]). A face with vertex colours
//! ([`limn_scene::Face::colors`]) is tinted at each point by its interpolated colour,
//! and lit flat it still is not one colour: its corners get the flat lighting times
//! their colours, interpolated by the painter.

use glam::{DMat4, DVec3};
use limn_scene::{
    polygon_normal, shade_face_tinted, shade_tinted_in_shadow, Camera, FaceColors, FaceNormals,
    LightSet, Material, Rgb, Scene,
};

use crate::phong::{subdivide, Surface};
use crate::{narrow_color, PaintFragment, VertexColor};

/// The highlight guard of [`crate::phong`] uses at most this specular exponent
/// (narrower highlights are left to the colour samples).
pub(crate) const MAX_GUARDED_EXPONENT: f64 = 1000.0;

/// What smooth shading needs to know about the view.
pub(crate) struct View<'a> {
    /// The camera the fragments were projected with.
    pub camera: &'a Camera,
    /// Its view-projection matrix (near and far as ordered).
    pub vp: DMat4,
    /// The Phong tolerance per channel.
    pub tolerance: f64,
}

/// One face's shading data, gathered once per face.
pub(crate) struct FaceLight<'a> {
    scene: &'a Scene,
    face: u32,
    material: &'a Material,
    colors: Option<FaceColors>,
    normals: Option<FaceNormals>,
    flat_normal: DVec3,
    /// The lights left out (the fragment lies in their shadow).
    shadowed: LightSet,
}

impl<'a> FaceLight<'a> {
    pub fn new(scene: &'a Scene, face: u32) -> Self {
        let f = &scene.faces[face as usize];
        FaceLight {
            scene,
            face,
            material: &scene.materials[f.material as usize],
            colors: FaceColors::new(scene, face),
            normals: FaceNormals::new(scene, face),
            flat_normal: polygon_normal(&scene.face_points(face)),
            shadowed: LightSet::EMPTY,
        }
    }

    /// The same face shaded without the lights in `shadowed`.
    pub fn in_shadow_of(self, shadowed: LightSet) -> Self {
        FaceLight { shadowed, ..self }
    }

    fn normal(&self, p: DVec3) -> DVec3 {
        self.normals
            .as_ref()
            .and_then(|n| n.at(p))
            .unwrap_or(self.flat_normal)
    }

    /// The vertex colour at `p` (white without vertex colours).
    fn tint(&self, p: DVec3) -> Rgb {
        self.colors.as_ref().map_or([1.0; 3], |c| c.at(p))
    }

    fn shade(&self, p: DVec3, eye: DVec3) -> [f64; 3] {
        shade_tinted_in_shadow(
            self.scene,
            self.material,
            self.tint(p),
            p,
            self.normal(p),
            self.flat_normal,
            eye,
            self.shadowed,
        )
    }

    /// Gouraud: the colour at each world corner, with alpha `alpha`.
    pub fn vertex_colors(&self, world: &[DVec3], eye: DVec3, alpha: f64) -> Vec<VertexColor> {
        world
            .iter()
            .map(|&p| {
                let c = self.shade(p, eye);
                narrow_color([c[0], c[1], c[2], alpha])
            })
            .collect()
    }

    /// A flat-lit face with vertex colours: at each world corner, the face's flat
    /// colour (lit at its centroid) tinted by the vertex colour there, with alpha
    /// `alpha`.
    pub fn flat_vertex_colors(&self, world: &[DVec3], eye: DVec3, alpha: f64) -> Vec<[f64; 4]> {
        world
            .iter()
            .map(|&p| {
                let c = shade_face_tinted(self.scene, self.face, eye, self.shadowed, self.tint(p));
                [c[0], c[1], c[2], alpha]
            })
            .collect()
    }

    /// Phong: `template` (screen `points`, flags, face, object, fill) with world corners
    /// `world` split into Gouraud triangles, appended to `out`.
    pub fn phong(
        &self,
        template: &PaintFragment,
        world: &[DVec3],
        view: &View<'_>,
        out: &mut Vec<PaintFragment>,
    ) {
        let eye = view.camera.eye;
        let shade = |p: DVec3| self.shade(p, eye);
        let normal = |p: DVec3| self.normal(p).normalize_or_zero();
        let project = |p: DVec3| {
            let q = view.camera.project_with(&view.vp, p);
            [q.x, q.y]
        };
        let m = self.material;
        let surface = Surface {
            shade: &shade,
            normal: &normal,
            project: &project,
            highlight: if m.illum >= 2 && m.ks.iter().any(|&k| k > 0.0) {
                // Capped so that an extreme exponent cannot ask for millions of pieces.
                m.ns.clamp(1.0, MAX_GUARDED_EXPONENT)
            } else {
                0.0
            },
            tolerance: view.tolerance,
        };
        let n = template.points.len();
        let corner = |i: usize| crate::phong::Corner {
            world: world[i],
            screen: template.points[i],
            color: shade(world[i]),
        };
        let edge = |i: usize| template.original_edges.get(i).copied().unwrap_or(false);
        let first = corner(0);
        let mut prev = corner(1);
        let mut tris = Vec::new();
        for i in 1..n - 1 {
            let next = corner(i + 1);
            let flags = [i == 1 && edge(0), edge(i), i + 1 == n - 1 && edge(n - 1)];
            subdivide(&surface, [first, prev, next], flags, &mut tris);
            prev = next;
        }
        let alpha = template.fill[3];
        out.extend(tris.into_iter().map(|t| {
            PaintFragment {
                points: t.corners.iter().map(|c| c.screen).collect(),
                vertex_colors: Some(
                    t.corners
                        .iter()
                        .map(|c| narrow_color([c.color[0], c.color[1], c.color[2], alpha]))
                        .collect(),
                ),
                original_edges: t.edges.to_vec(),
                ..template.clone()
            }
        }));
    }
}
