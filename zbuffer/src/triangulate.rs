//! Triangulation of input faces.
//!
//! Faces are simple polygons, but may be non-convex and (after input rounding or by
//! construction) non-planar. A face is projected onto the coordinate plane most
//! perpendicular to its Newell normal by *dropping* one coordinate (exact, no rounding),
//! then:
//!
//! * a triangle is used as is;
//! * a polygon whose projection turns left at every corner (convex) is fanned from its
//!   first corner;
//! * otherwise it is ear-clipped with exact `orient2d` tests. If no ear can be found
//!   (self-intersecting or degenerate input), collinear corners are dropped and, as a
//!   last resort, the remainder is fanned, so triangulation always terminates.
//!
//! A non-planar face is therefore drawn as the triangles above; another renderer that
//! triangulates it differently may differ inside the face's outline, where the pieces
//! are not coplanar.

use glam::DVec3;
use limn_scene::polygon_normal;
use robust::{orient2d, Coord};

/// Triangulates the polygon `points` (in order) into triangles of local corner indices,
/// appended to `out`, each wound like the polygon.
pub fn triangulate(points: &[DVec3], out: &mut Vec<[usize; 3]>) {
    let n = points.len();
    if n < 3 {
        return;
    }
    if n == 3 {
        out.push([0, 1, 2]);
        return;
    }
    let normal = polygon_normal(points);
    if !normal.is_finite() || normal == DVec3::ZERO {
        fan(0..n, out);
        return;
    }
    let a = normal.abs();
    let (u, v, flip) = if a.x >= a.y && a.x >= a.z {
        (1, 2, normal.x < 0.0)
    } else if a.y >= a.z {
        (2, 0, normal.y < 0.0)
    } else {
        (0, 1, normal.z < 0.0)
    };
    // 2D coordinates in which the polygon is counter-clockwise.
    let p: Vec<Coord<f64>> = points
        .iter()
        .map(|q| {
            let (x, y) = (q.to_array()[u], q.to_array()[v]);
            if flip {
                Coord { x: y, y: x }
            } else {
                Coord { x, y }
            }
        })
        .collect();
    if (0..n).all(|i| orient2d(p[(i + n - 1) % n], p[i], p[(i + 1) % n]) >= 0.0) {
        fan(0..n, out);
        return;
    }
    ear_clip(&p, out);
}

fn fan(ring: impl IntoIterator<Item = usize>, out: &mut Vec<[usize; 3]>) {
    let ring: Vec<usize> = ring.into_iter().collect();
    for k in 1..ring.len().saturating_sub(1) {
        out.push([ring[0], ring[k], ring[k + 1]]);
    }
}

fn ear_clip(p: &[Coord<f64>], out: &mut Vec<[usize; 3]>) {
    let mut ring: Vec<usize> = (0..p.len()).collect();
    let turn = |ring: &[usize], k: usize| {
        let m = ring.len();
        orient2d(p[ring[(k + m - 1) % m]], p[ring[k]], p[ring[(k + 1) % m]])
    };
    let mut reflex: Vec<bool> = (0..ring.len()).map(|k| turn(&ring, k) <= 0.0).collect();
    let mut k = 0;
    let mut misses = 0;
    while ring.len() > 3 {
        let m = ring.len();
        k %= m;
        if !reflex[k] && is_ear(p, &ring, &reflex, k) {
            let (a, b, c) = (ring[(k + m - 1) % m], ring[k], ring[(k + 1) % m]);
            out.push([a, b, c]);
            ring.remove(k);
            reflex.remove(k);
            let m = ring.len();
            let before = (k + m - 1) % m;
            let after = k % m;
            reflex[before] = turn(&ring, before) <= 0.0;
            reflex[after] = turn(&ring, after) <= 0.0;
            k = before;
            misses = 0;
            continue;
        }
        k += 1;
        misses += 1;
        if misses > m {
            // No ear: drop a collinear corner (it bounds no area), else give up and fan.
            if let Some(c) = (0..m).find(|&c| turn(&ring, c) == 0.0) {
                ring.remove(c);
                reflex.remove(c);
                let m = ring.len();
                for j in [(c + m - 1) % m, c % m] {
                    reflex[j] = turn(&ring, j) <= 0.0;
                }
                misses = 0;
            } else {
                fan(ring.iter().copied(), out);
                return;
            }
        }
    }
    out.push([ring[0], ring[1], ring[2]]);
}

/// Whether the convex corner `k` of `ring` is an ear: no reflex corner lies inside or on
/// the triangle it cuts off (corners at the same position as the ear's are ignored).
fn is_ear(p: &[Coord<f64>], ring: &[usize], reflex: &[bool], k: usize) -> bool {
    let m = ring.len();
    let (ia, ib, ic) = (ring[(k + m - 1) % m], ring[k], ring[(k + 1) % m]);
    let (a, b, c) = (p[ia], p[ib], p[ic]);
    ring.iter().zip(reflex).all(|(&j, &r)| {
        if !r || j == ia || j == ib || j == ic {
            return true;
        }
        let q = p[j];
        if q == a || q == b || q == c {
            return true;
        }
        !(orient2d(a, b, q) >= 0.0 && orient2d(b, c, q) >= 0.0 && orient2d(c, a, q) >= 0.0)
    })
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
    fn l_shape_is_ear_clipped_with_the_right_area() {
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
    fn clockwise_and_degenerate_polygons_terminate() {
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
        assert_eq!(tris.len(), 4);
        let bowtie: Vec<DVec3> = [(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0), (0.5, 3.0)]
            .iter()
            .map(|&(x, y)| DVec3::new(x, y, 0.0))
            .collect();
        tris.clear();
        triangulate(&bowtie, &mut tris);
        assert!(tris.len() <= 3);
    }
}
