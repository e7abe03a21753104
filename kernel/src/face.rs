//! Conversion of input faces into exact convex polygons, on the corners as given.
//!
//! 1. Non-finite corners are refused; consecutive duplicates (and a closing corner equal
//!    to the first) are dropped.
//! 2. The supporting plane is the plane through the fan triangle `(p₀, pᵢ, pᵢ₊₁)` that
//!    agrees best with the face's (approximate) Newell normal, among those that are not
//!    exactly degenerate.
//! 3. **Exact planarity.** Only a face whose corners all lie exactly on that plane goes in
//!    as one polygon; any other face is triangulated, so faces that share corners share
//!    them exactly and no corner is ever moved.
//! 4. Collinear corners are removed and strict convexity is checked exactly in the
//!    projection along the dominant axis `k` of the support normal (a projection along a
//!    coordinate axis drops a coordinate, so it is exact); a convex face becomes one
//!    polygon with all edges original. Its edge planes contain the edge and the direction
//!    `e_k`, so vertex `i` is exactly corner `i`.
//! 5. Otherwise the outline is triangulated (constrained Delaunay, projected along the
//!    dominant axis of the Newell normal); diagonals are non-original and every triangle
//!    gets its own exact supporting plane. Outlines that are not simple
//!    (self-intersecting) are dropped, like zero-area faces.

use std::cmp::Ordering;

use glam::DVec3;

use crate::plane::{check_finite, plane_axes, robust_safe, Plane};
use crate::polygon::{Builder, Corner, ExactPolygon};
use crate::triangulate::triangulate;
use crate::KernelError;

type P3 = [f64; 3];

/// Exact orientation of `a, b, c` projected along axis `k` (`Greater`:
/// counter-clockwise seen from `+e_k`).
pub(crate) fn orient_k(a: P3, b: P3, c: P3, k: usize) -> Ordering {
    let (u, v) = plane_axes(k);
    if robust_safe(&[a, b, c]) {
        let c2 = |p: P3| robust::Coord { x: p[u], y: p[v] };
        let o = robust::orient2d(c2(a), c2(b), c2(c));
        return o.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
    }
    use crate::dyadic::Dyadic;
    let d = |x: f64| Dyadic::from_f64(x);
    let (bu, bv) = (&d(b[u]) - &d(a[u]), &d(b[v]) - &d(a[v]));
    let (cu, cv) = (&d(c[u]) - &d(a[u]), &d(c[v]) - &d(a[v]));
    (&(&bu * &cv) - &(&bv * &cu)).signum()
}

/// Builds the polygon of an outline that is strictly convex in projection along the
/// dominant axis of `support`, whose corners lie exactly on `support`.
/// Its edge planes (through corners `i` and `i + 1` along the dominant exact axis of
/// `support`, see [`crate::polygon::input_edge_axis`]) are made only when asked for.
pub(crate) fn convex_polygon(pts: &[P3], support: Plane, original: &[bool]) -> ExactPolygon {
    let mut out = Builder::default();
    for (&pos, &original) in pts.iter().zip(original) {
        out.push_input_corner(Corner {
            pos,
            err: 0.0,
            original,
        });
    }
    out.finish(support)
}

/// Removes corners collinear with their neighbours (in projection along `k`), repeatedly.
fn drop_collinear(pts: &mut Vec<P3>, k: usize) {
    let mut i = 0;
    let mut stable = 0;
    while pts.len() >= 3 && stable < pts.len() {
        let n = pts.len();
        let (a, b, c) = (pts[(i + n - 1) % n], pts[i % n], pts[(i + 1) % n]);
        if orient_k(a, b, c, k) == Ordering::Equal {
            pts.remove(i % n);
            stable = 0;
        } else {
            stable += 1;
            i = (i % n) + 1;
        }
        if pts.is_empty() {
            break;
        }
        i %= pts.len();
    }
}

/// Whether the outline is strictly convex and simple, turning with sign `sgn` along `k`.
///
/// All turns having the same sign is not enough: the outline may wind around more than
/// once. With the fan `(p₀, pᵢ, pᵢ₊₁)` also turning the same way, the rays from `p₀` are
/// sorted by angle, each step below 180°; requiring every `pᵢ` strictly on the same side
/// of the line `p₀p₁` keeps the whole sweep below 180°, so the outline winds once.
fn strictly_convex(pts: &[P3], k: usize, sgn: Ordering) -> bool {
    let n = pts.len();
    if n < 3 {
        return false;
    }
    let turns = (0..n).all(|i| orient_k(pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n], k) == sgn);
    let fan = (1..n - 1).all(|i| orient_k(pts[0], pts[i], pts[i + 1], k) == sgn);
    let half = (2..n).all(|i| orient_k(pts[0], pts[1], pts[i], k) == sgn);
    turns && fan && half
}

fn cross(u: P3, v: P3) -> P3 {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Converts one input face (see the module docs).
pub(crate) fn face_polygons(corners: &[DVec3]) -> Result<Vec<ExactPolygon>, KernelError> {
    if corners.is_empty() {
        return Err(KernelError::Empty);
    }
    let mut g: Vec<P3> = Vec::with_capacity(corners.len());
    for c in corners {
        let p = c.to_array();
        check_finite(p)?;
        if g.last() != Some(&p) {
            g.push(p);
        }
    }
    while g.len() > 1 && g.first() == g.last() {
        g.pop();
    }
    if g.len() < 3 {
        return Ok(Vec::new());
    }
    if g.len() == 3 {
        // A triangle of three distinct corners is exactly planar, and when its normal is
        // not zero it is strictly convex in the projection along any axis where the
        // normal's component is not zero: no check needed.
        return Ok(match Plane::through(g[0], g[1], g[2]) {
            Ok(support) => vec![convex_polygon(&g, support, &[true; 3])],
            Err(_) => Vec::new(),
        });
    }
    let n = g.len();
    let p0 = g[0];
    // Approximate Newell normal (a choice of fan triangle and projection only; every
    // decision below is exact). Coordinates are centred on p₀ so that far-away faces
    // keep their precision.
    let fan: Vec<P3> = (1..n - 1)
        .map(|i| cross(sub(g[i], p0), sub(g[i + 1], p0)))
        .collect();
    let mut newell = [0.0f64; 3];
    for c in &fan {
        for j in 0..3 {
            newell[j] += c[j];
        }
    }
    let mut order: Vec<usize> = (0..fan.len()).collect();
    let score = |i: usize| -> f64 { (0..3).map(|j| fan[i][j] * newell[j]).sum() };
    order.sort_by(|&a, &b| score(b).total_cmp(&score(a)));
    for &best in order.iter().take(3) {
        if let Ok(support) = Plane::through(p0, g[best + 1], g[best + 2]) {
            if let Some(poly) = try_convex(&g, &support) {
                return Ok(vec![poly]);
            }
            break;
        }
    }
    if g.len() == 4 {
        if let Some(polys) = quad_triangles(&g, newell) {
            return Ok(polys);
        }
    }
    triangulated(&g, newell)
}

/// A quad that is not one convex planar polygon, as two triangles along a diagonal whose
/// triangles both turn the way of the (approximate) Newell normal in the projection along
/// its dominant axis, decided exactly: the diagonal `p₀p₂` first, then `p₁p₃`. `None`
/// when neither works (a self-intersecting or degenerate outline), for the general path.
fn quad_triangles(g: &[P3], newell: P3) -> Option<Vec<ExactPolygon>> {
    let m = newell.map(f64::abs);
    let k = if m[0] >= m[1] && m[0] >= m[2] {
        0
    } else if m[1] >= m[2] {
        1
    } else {
        2
    };
    let want = if newell[k] > 0.0 {
        Ordering::Greater
    } else if newell[k] < 0.0 {
        Ordering::Less
    } else {
        return None;
    };
    for (a, b, c, d) in [(0, 1, 2, 3), (1, 2, 3, 0)] {
        if orient_k(g[a], g[b], g[c], k) == want && orient_k(g[a], g[c], g[d], k) == want {
            let (Ok(s1), Ok(s2)) = (
                Plane::through(g[a], g[b], g[c]),
                Plane::through(g[a], g[c], g[d]),
            ) else {
                return None;
            };
            // Edges: a→b, b→c original, c→a the diagonal; a→c the diagonal, c→d, d→a
            // original.
            return Some(vec![
                convex_polygon(&[g[a], g[b], g[c]], s1, &[true, true, false]),
                convex_polygon(&[g[a], g[c], g[d]], s2, &[false, true, true]),
            ]);
        }
    }
    None
}

/// The single-polygon path: exact planarity check, collinear removal, convexity check.
fn try_convex(g: &[P3], support: &Plane) -> Option<ExactPolygon> {
    if g.iter().any(|&p| support.side_of(p) != crate::Side::On) {
        return None;
    }
    let k = support.dominant_exact_axis();
    let mut pts = g.to_vec();
    drop_collinear(&mut pts, k);
    let sgn = support.normal_sign(k);
    if !strictly_convex(&pts, k, sgn) {
        return None;
    }
    let original = vec![true; pts.len()];
    Some(convex_polygon(&pts, support.clone(), &original))
}

/// The triangulated path for non-convex or non-planar faces.
fn triangulated(g: &[P3], newell: P3) -> Result<Vec<ExactPolygon>, KernelError> {
    let m = newell.map(f64::abs);
    let k = if m[0] >= m[1] && m[0] >= m[2] {
        0
    } else if m[1] >= m[2] {
        1
    } else {
        2
    };
    let (u, v) = plane_axes(k);
    let pts2: Vec<[f64; 2]> = g.iter().map(|p| [p[u], p[v]]).collect();
    let Some(tris) = triangulate(&pts2) else {
        return Ok(Vec::new());
    };
    let mut out = Vec::with_capacity(tris.len());
    for t in tris {
        let (idx, orig) = if newell[k] > 0.0 {
            (t.idx, t.original)
        } else {
            (
                [t.idx[0], t.idx[2], t.idx[1]],
                [t.original[2], t.original[1], t.original[0]],
            )
        };
        let pts = idx.map(|i| g[i]);
        if let Ok(support) = Plane::through(pts[0], pts[1], pts[2]) {
            out.push(convex_polygon(&pts, support, &orig));
        }
    }
    Ok(out)
}
