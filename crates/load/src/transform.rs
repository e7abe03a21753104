//! Placing geometry: affine transforms applied to vertices, normals and windings.

use glam::{DMat3, DMat4, DVec3};

use limn_scene::Scene;

/// Applies the affine transform `m` to the vertices from `first_vertex` on and the
/// normals from `first_normal` on, and, when `m` mirrors (negative determinant),
/// reverses the winding of the faces from `first_face` on so that they keep facing
/// outwards. Normals are transformed by the inverse transpose and normalised (left as
/// they are when `m` is singular).
pub(crate) fn apply(
    scene: &mut Scene,
    m: &DMat4,
    first_vertex: usize,
    first_normal: usize,
    first_face: usize,
) {
    for v in &mut scene.vertices[first_vertex..] {
        *v = m.transform_point3(*v);
    }
    let linear = DMat3::from_mat4(*m);
    let det = linear.determinant();
    if det != 0.0 && det.is_finite() {
        let nm = linear.inverse().transpose();
        for n in &mut scene.normals[first_normal..] {
            let t = nm * *n;
            *n = if t.length_squared() > 0.0 && t.is_finite() {
                t.normalize()
            } else {
                *n
            };
        }
    }
    if det < 0.0 {
        for f in &mut scene.faces[first_face..] {
            f.vertices.reverse();
            if let Some(ns) = &mut f.normals {
                ns.reverse();
            }
        }
    }
}

/// Applies `m` to the points of every line and the anchors of every point and label.
pub(crate) fn apply_to_marks(scene: &mut Scene, m: &DMat4) {
    for l in &mut scene.lines {
        for p in &mut l.points {
            *p = m.transform_point3(*p);
        }
    }
    for p in &mut scene.points {
        p.at = m.transform_point3(p.at);
    }
    for l in &mut scene.labels {
        l.at = m.transform_point3(l.at);
    }
}

/// Whether all line points and anchors are finite (after a transform).
pub(crate) fn marks_finite(scene: &Scene) -> bool {
    scene
        .lines
        .iter()
        .flat_map(|l| &l.points)
        .all(|p| p.is_finite())
        && scene.points.iter().all(|p| p.at.is_finite())
        && scene.labels.iter().all(|l| l.at.is_finite())
}

/// Whether every entry of `m` is finite.
pub(crate) fn is_finite(m: &DMat4) -> bool {
    m.to_cols_array().iter().all(|v| v.is_finite())
}

/// Whether all transformed vertices are finite (a huge scale can overflow).
pub(crate) fn vertices_finite(scene: &Scene, first_vertex: usize) -> bool {
    scene.vertices[first_vertex..]
        .iter()
        .all(|v: &DVec3| v.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;
    use limn_scene::Material;

    #[test]
    fn mirror_flips_winding_and_keeps_normals_unit() {
        let mut s = Scene::default();
        let m = s.add_material(Material::default_grey());
        let o = s.add_object("t");
        s.add_polygon(&[DVec3::ZERO, DVec3::X, DVec3::Y], m, o)
            .unwrap();
        s.normals.push(DVec3::Z);
        apply(
            &mut s,
            &DMat4::from_scale(DVec3::new(-2.0, 1.0, 1.0)),
            0,
            0,
            0,
        );
        assert_eq!(s.faces[0].vertices.to_vec(), vec![2, 1, 0]);
        assert_eq!(s.vertices[1], DVec3::new(-2.0, 0.0, 0.0));
        assert!((s.normals[0] - DVec3::Z).length() < 1e-15);
        let n = limn_scene::polygon_normal(&s.face_points(0));
        assert!(n.z > 0.0, "the face still faces +z");
    }
}
