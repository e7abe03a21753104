//! Conversion of input faces into exact convex polygons.
//!
//! 1. Corners are snapped to the grid; consecutive duplicates are dropped.
//! 2. The supporting plane is taken from the fan triangle `(p₀, pᵢ, pᵢ₊₁)` that agrees
//!    best with the face's (exact, integer) Newell normal.
//! 3. **Exact planarity.** Only a face whose snapped corners all lie exactly on that plane
//!    goes in as one polygon. A face that snapping made non-planar (even by less than a
//!    grid step) is triangulated instead: moving its corners onto one plane would open
//!    cracks and overlaps of up to a grid step against its neighbours, and those would
//!    turn into real (if tiny) interpenetrations that must be split. With triangles, faces
//!    that share corners in the input share them exactly. (The polygon builder still
//!    supports corners within one step along `k`: vertex `S ∩ Eᵢ₋₁ ∩ Eᵢ` is the corner
//!    projected along `k`, since edge planes contain the direction `e_k`.)
//! 4. Collinear corners are removed and strict convexity is checked exactly in the
//!    projection along `k`; a convex face becomes one polygon with all edges original.
//! 5. Otherwise the outline is triangulated (constrained Delaunay, projected along the
//!    dominant axis of the Newell normal, where grid coordinates as f64 are exact);
//!    diagonals are non-original and every triangle gets its own exact supporting plane.
//!    Outlines that are not simple (self-intersecting) are dropped, like zero-area faces.

use glam::DVec3;

use crate::grid::{GridPoint, Quantizer};
use crate::plane::{dominant_axis, Coeffs, Plane};
use crate::polygon::{err32, Builder, Corner, ExactPolygon};
use crate::triangulate::triangulate;
use crate::KernelError;

type I3 = [i64; 3];

fn sub(a: GridPoint, b: GridPoint) -> I3 {
    [a.x - b.x, a.y - b.y, a.z - b.z]
}

fn cross128(u: I3, v: I3) -> [i128; 3] {
    let w = |a: i64, b: i64| a as i128 * b as i128;
    [
        w(u[1], v[2]) - w(u[2], v[1]),
        w(u[2], v[0]) - w(u[0], v[2]),
        w(u[0], v[1]) - w(u[1], v[0]),
    ]
}

/// The two axes spanning the projection along `k`, so that `(u, v, k)` is right-handed.
fn plane_axes(k: usize) -> (usize, usize) {
    ((k + 1) % 3, (k + 2) % 3)
}

/// Orientation of `a, b, c` projected along axis `k` (positive: counter-clockwise seen
/// from `+e_k`).
fn orient_k(a: GridPoint, b: GridPoint, c: GridPoint, k: usize) -> i32 {
    let (u, v) = plane_axes(k);
    let (a, b, c) = (a.to_array(), b.to_array(), c.to_array());
    let det = (b[u] - a[u]) as i128 * (c[v] - a[v]) as i128
        - (b[v] - a[v]) as i128 * (c[u] - a[u]) as i128;
    det.signum() as i32
}

/// Builds the polygon of a strictly convex outline (in projection along the dominant axis
/// of `support`), whose corners lie within one step of `support` along that axis.
pub(crate) fn convex_polygon(pts: &[GridPoint], support: Plane, original: &[bool]) -> ExactPolygon {
    let n_s = support.normal();
    let k = dominant_axis(n_s);
    let (u, v) = plane_axes(k);
    let sgn: i64 = if n_s[k] > 0 { 1 } else { -1 };
    let n = pts.len();
    let mut out = Builder::default();
    for i in 0..n {
        let p = pts[i].to_array();
        let q = pts[(i + 1) % n].to_array();
        let (du, dv) = (q[u] - p[u], q[v] - p[v]);
        let mut m = [0i64; 3];
        m[u] = sgn * dv;
        m[v] = -sgn * du;
        let d = -(sgn as i128) * (dv as i128 * p[u] as i128 - du as i128 * p[v] as i128);
        let edge = Coeffs::new(m[0], m[1], m[2], d);
        let mut pos = p.map(|c| c as f64);
        let s = support.eval(&pts[i]);
        let mut err = 0.0;
        if s != 0 {
            // The corner moved along k onto the support plane.
            let t = -(n_s[u] as i128 * p[u] as i128 + n_s[v] as i128 * p[v] as i128 + support.d());
            pos[k] = t as f64 / n_s[k] as f64;
            err = crate::predicates::finish_err(pos[k].abs() * (1.0 / 1_125_899_906_842_624.0));
        }
        let corner = Corner {
            pos,
            err: err32(err),
            original: original[i],
        };
        out.push(corner, edge);
    }
    out.finish(support.coeffs())
}

/// Removes corners collinear with their neighbours (in projection along `k`), repeatedly.
fn drop_collinear(pts: &mut Vec<GridPoint>, k: usize) {
    let mut i = 0;
    let mut stable = 0;
    while pts.len() >= 3 && stable < pts.len() {
        let n = pts.len();
        let (a, b, c) = (pts[(i + n - 1) % n], pts[i % n], pts[(i + 1) % n]);
        if orient_k(a, b, c, k) == 0 {
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
fn strictly_convex(pts: &[GridPoint], k: usize, sgn: i32) -> bool {
    let n = pts.len();
    if n < 3 {
        return false;
    }
    let turns = (0..n).all(|i| orient_k(pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n], k) == sgn);
    let fan = (1..n - 1).all(|i| orient_k(pts[0], pts[i], pts[i + 1], k) == sgn);
    let half = (2..n).all(|i| orient_k(pts[0], pts[1], pts[i], k) == sgn);
    turns && fan && half
}

/// Converts one input face (see the module docs).
pub(crate) fn face_polygons(
    q: &Quantizer,
    corners: &[DVec3],
) -> Result<Vec<ExactPolygon>, KernelError> {
    if corners.is_empty() {
        return Err(KernelError::Empty);
    }
    let mut g: Vec<GridPoint> = Vec::with_capacity(corners.len());
    for c in corners {
        let p = q.snap(*c)?;
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
    let n = g.len();
    let p0 = g[0];
    let fan: Vec<[i128; 3]> = (1..n - 1)
        .map(|i| cross128(sub(g[i], p0), sub(g[i + 1], p0)))
        .collect();
    let mut newell = [0i128; 3];
    for c in &fan {
        for j in 0..3 {
            newell[j] += c[j];
        }
    }
    if newell == [0; 3] {
        return Ok(Vec::new());
    }
    let nf = newell.map(|v| v as f64);
    let best = (0..fan.len())
        .max_by(|&a, &b| {
            let da: f64 = (0..3).map(|j| fan[a][j] as f64 * nf[j]).sum();
            let db: f64 = (0..3).map(|j| fan[b][j] as f64 * nf[j]).sum();
            da.total_cmp(&db)
        })
        .unwrap_or(0);
    if let Some(support) = Plane::through(p0, g[best + 1], g[best + 2]) {
        if let Some(poly) = try_convex(&g, support) {
            return Ok(vec![poly]);
        }
    }
    triangulated(&g, newell)
}

/// The single-polygon path: exact planarity check, collinear removal, convexity check.
fn try_convex(g: &[GridPoint], support: Plane) -> Option<ExactPolygon> {
    let n_s = support.normal();
    let k = dominant_axis(n_s);
    if g.iter().any(|p| support.eval(p) != 0) {
        return None;
    }
    let mut pts = g.to_vec();
    drop_collinear(&mut pts, k);
    let sgn = if n_s[k] > 0 { 1 } else { -1 };
    if !strictly_convex(&pts, k, sgn) {
        return None;
    }
    let original = vec![true; pts.len()];
    Some(convex_polygon(&pts, support, &original))
}

/// The triangulated path for non-convex or non-planar faces.
fn triangulated(g: &[GridPoint], newell: [i128; 3]) -> Result<Vec<ExactPolygon>, KernelError> {
    let k = dominant_axis(newell);
    let (u, v) = plane_axes(k);
    let pts2: Vec<[f64; 2]> = g
        .iter()
        .map(|p| {
            let a = p.to_array();
            [a[u] as f64, a[v] as f64]
        })
        .collect();
    let Some(tris) = triangulate(&pts2) else {
        return Ok(Vec::new());
    };
    let mut out = Vec::with_capacity(tris.len());
    for t in tris {
        let (idx, orig) = if newell[k] > 0 {
            (t.idx, t.original)
        } else {
            (
                [t.idx[0], t.idx[2], t.idx[1]],
                [t.original[2], t.original[1], t.original[0]],
            )
        };
        let pts = idx.map(|i| g[i]);
        if let Some(support) = Plane::through(pts[0], pts[1], pts[2]) {
            out.push(convex_polygon(&pts, support, &orig));
        }
    }
    Ok(out)
}
