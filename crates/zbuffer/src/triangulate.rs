//! Triangulation of input faces: the triangles the exact kernel draws a face as
//! ([`limn_kernel::face_triangles`]), so that a face that is not planar or not simple
//! has the same surface here as in the painter's order. What is hidden is computed here
//! independently; what a face *is* is defined once.
//!
//! The rule: a face whose corners are exactly coplanar and that is strictly convex is
//! fanned from its first corner; any other face is triangulated in the first coordinate
//! projection (by the size of its Newell normal's components) in which its outline is
//! simple, or fanned from its first corner when there is none. Triangles of exactly zero
//! area are left out.

use glam::DVec3;

/// Triangulates the polygon `points` (in order) into triangles of local corner indices,
/// appended to `out`, each wound like the polygon. A face with a corner that is not
/// finite gives none.
pub fn triangulate(points: &[DVec3], out: &mut Vec<[usize; 3]>) {
    if let Ok(tris) = limn_kernel::face_triangles(points) {
        out.extend(tris.iter().map(|t| t.corners));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area2(points: &[DVec3], tris: &[[usize; 3]]) -> f64 {
        tris.iter()
            .map(|t| {
                let (a, b, c) = (points[t[0]], points[t[1]], points[t[2]]);
                (b - a).cross(c - a).z
            })
            .sum()
    }

    #[test]
    fn l_shape_is_triangulated_with_the_right_area() {
        let pts: Vec<DVec3> = [
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (1.0, 1.0),
            (1.0, 2.0),
            (0.0, 2.0),
        ]
        .iter()
        .map(|&(x, y)| DVec3::new(x, y, 0.0))
        .collect();
        let mut tris = Vec::new();
        triangulate(&pts, &mut tris);
        assert_eq!(tris.len(), 4);
        assert!((area2(&pts, &tris) - 6.0).abs() < 1e-12);
        for t in &tris {
            let (a, b, c) = (pts[t[0]], pts[t[1]], pts[t[2]]);
            assert!(
                (b - a).cross(c - a).z >= 0.0,
                "every triangle keeps the winding"
            );
        }
    }

    #[test]
    fn clockwise_crossing_and_degenerate_polygons() {
        let cw: Vec<DVec3> = [(0.0, 0.0), (0.0, 2.0), (1.0, 1.0), (2.0, 2.0), (2.0, 0.0)]
            .iter()
            .map(|&(x, y)| DVec3::new(x, 0.0, y))
            .collect();
        let mut tris = Vec::new();
        triangulate(&cw, &mut tris);
        assert_eq!(tris.len(), 3);
        let line: Vec<DVec3> = (0..6).map(|i| DVec3::splat(i as f64)).collect();
        tris.clear();
        triangulate(&line, &mut tris);
        assert!(tris.is_empty(), "corners on one line bound no area");
        let bowtie: Vec<DVec3> = [(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0), (0.5, 3.0)]
            .iter()
            .map(|&(x, y)| DVec3::new(x, y, 0.0))
            .collect();
        tris.clear();
        triangulate(&bowtie, &mut tris);
        // It crosses itself seen along every axis: the fan from its first corner.
        assert_eq!(tris, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
    }
}
