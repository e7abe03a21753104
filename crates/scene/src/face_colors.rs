//! Vertex colours over a face: the colour at any world point of the face, interpolated
//! from its corners' colours as normals are ([`crate::fan_weights`]: barycentric in
//! triangles, in the fan triangle from the first corner that holds the point in larger
//! faces).

use glam::DVec3;

use crate::{fan_weights, Rgb, Scene};

/// A face's corners and their vertex colours, gathered once for many look-ups.
#[derive(Debug, Clone, PartialEq)]
pub struct FaceColors {
    corners: Vec<DVec3>,
    colors: Vec<Rgb>,
}

impl FaceColors {
    /// The corners and colours of `face`; `None` when it has no vertex colours.
    pub fn new(scene: &Scene, face: u32) -> Option<FaceColors> {
        let f = &scene.faces[face as usize];
        let cs = f.colors.as_ref()?;
        Some(FaceColors {
            corners: f
                .vertices
                .iter()
                .map(|&v| scene.vertices[v as usize])
                .collect(),
            colors: cs.iter().map(|&i| scene.colors[i as usize]).collect(),
        })
    }

    /// The colour at `p` (a point in or on the face), each channel kept in [0, 1]; the
    /// first corner's colour when every fan triangle is degenerate.
    pub fn at(&self, p: DVec3) -> Rgb {
        match fan_weights(&self.corners, p) {
            Some((idx, w)) => [0, 1, 2].map(|k| {
                (0..3)
                    .map(|j| w[j] * self.colors[idx[j]][k])
                    .sum::<f64>()
                    .clamp(0.0, 1.0)
            }),
            None => self.colors[0],
        }
    }

    /// The colour of each corner.
    pub fn colors(&self) -> &[Rgb] {
        &self.colors
    }

    /// The face's corners.
    pub fn corners(&self) -> &[DVec3] {
        &self.corners
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Material;

    #[test]
    fn colours_interpolate_between_corners() {
        let mut s = Scene::default();
        let m = s.add_material(Material::unlit("m", [1.0; 3]));
        let o = s.add_object("o");
        let f = s
            .add_polygon(
                &[
                    DVec3::ZERO,
                    DVec3::new(2.0, 0.0, 0.0),
                    DVec3::new(0.0, 2.0, 0.0),
                ],
                m,
                o,
            )
            .unwrap();
        assert!(FaceColors::new(&s, f).is_none());
        s.colors = vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        s.faces[0].colors = Some(Box::new([0, 1, 2]));
        s.validate().unwrap();
        let c = FaceColors::new(&s, f).unwrap();
        assert_eq!(c.at(DVec3::new(2.0, 0.0, 0.0)), [0.0, 1.0, 0.0]);
        let mid = c.at(DVec3::new(1.0, 0.0, 0.0));
        assert!((mid[0] - 0.5).abs() < 1e-12 && (mid[1] - 0.5).abs() < 1e-12);
        assert!(mid[2].abs() < 1e-12);
        let inside = c.at(DVec3::new(0.5, 0.5, 0.0));
        assert!((inside[2] - 0.25).abs() < 1e-12 && (inside[0] - 0.5).abs() < 1e-12);
    }

    #[test]
    fn bad_colours_are_refused() {
        let mut s = Scene::default();
        let m = s.add_material(Material::unlit("m", [1.0; 3]));
        let o = s.add_object("o");
        s.add_polygon(&[DVec3::ZERO, DVec3::X, DVec3::Y], m, o)
            .unwrap();
        s.colors = vec![[1.0, 0.0, 0.0]];
        s.faces[0].colors = Some(Box::new([0, 0]));
        assert!(s.validate().is_err());
        s.faces[0].colors = Some(Box::new([0, 0, 1]));
        assert!(s.validate().is_err());
        s.faces[0].colors = Some(Box::new([0, 0, 0]));
        s.validate().unwrap();
        s.colors[0][1] = 1.5;
        assert!(s.validate().is_err());
        s.colors[0][1] = f64::NAN;
        assert!(s.validate().is_err());
    }
}
