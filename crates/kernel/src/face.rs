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
//! 5. Otherwise the face becomes the triangles of [`crate::face_split`]: triangulated
//!    in a coordinate projection in which its outline is simple, or fanned from corner 0
//!    when there is none. Diagonals are non-original and every triangle gets its own
//!    exact supporting plane; only triangles of exactly zero area are dropped, so a face
//!    with area always draws something.
//! 6. An exactly planar face that is not convex has its triangles merged across
//!    diagonals into convex pieces ([`crate::convex_pieces`]): a contour region or a
//!    letter becomes a few polygons rather than one triangle per corner. The
//!    image-space references keep the triangles: the surface is the same.

use std::cmp::Ordering;

use glam::DVec3;

use crate::convex_pieces::convex_pieces;
use crate::face_split::split_face;
use crate::plane::{check_finite, plane_axes, robust_safe, Plane};
use crate::polygon::{Builder, Corner, ExactPolygon};
use crate::triangulate::Tri;
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

/// An input face's corners, cleaned: non-finite corners refused, consecutive repeats
/// (and a last corner equal to the first) dropped. `given[i]` is the index of `pts[i]`
/// among the corners as given, when kept.
struct Outline {
    pts: Vec<P3>,
    given: Vec<usize>,
}

/// `given` is kept only when `keep_given` (the conversion to polygons has no use for it
/// and does not pay for it).
fn outline(corners: &[DVec3], keep_given: bool) -> Result<Outline, KernelError> {
    if corners.is_empty() {
        return Err(KernelError::Empty);
    }
    let mut o = Outline {
        pts: Vec::with_capacity(corners.len()),
        given: Vec::with_capacity(if keep_given { corners.len() } else { 0 }),
    };
    for (i, c) in corners.iter().enumerate() {
        let p = c.to_array();
        check_finite(p)?;
        if o.pts.last() != Some(&p) {
            o.pts.push(p);
            if keep_given {
                o.given.push(i);
            }
        }
    }
    while o.pts.len() > 1 && o.pts.first() == o.pts.last() {
        o.pts.pop();
        if keep_given {
            o.given.pop();
        }
    }
    Ok(o)
}

/// What a cleaned outline is drawn as.
// A `Shape` lives on the stack for one call; boxing the polygon would cost an allocation
// per face on the path every triangle takes.
#[allow(clippy::large_enum_variant)]
enum Shape {
    /// Its corners all lie on one line (or there are fewer than three): nothing.
    Degenerate,
    /// One convex polygon (exactly planar, strictly convex once collinear corners are
    /// dropped).
    Convex(ExactPolygon),
    /// The triangles of [`split_face`] (those of exactly zero area, which have no plane,
    /// are left out by the callers).
    Triangles(Vec<Tri>),
    /// An exactly planar face that is not convex: the triangles of [`split_face`], which
    /// the conversion merges into convex pieces ([`convex_pieces`]); `k` is an axis along
    /// which the face has area.
    Planar { tris: Vec<Tri>, k: usize },
}

fn shape(g: &[P3]) -> Shape {
    if g.len() < 3 {
        return Shape::Degenerate;
    }
    if g.len() == 3 {
        // A triangle of three distinct corners is exactly planar, and when its normal is
        // not zero it is strictly convex in the projection along any axis where the
        // normal's component is not zero: no check needed.
        return match Plane::through(g[0], g[1], g[2]) {
            Ok(support) => Shape::Convex(convex_polygon(g, support, &[true; 3])),
            Err(_) => Shape::Degenerate,
        };
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
            if g.iter().any(|&p| support.side_of(p) != crate::Side::On) {
                break;
            }
            if let Some(poly) = try_convex(g, &support) {
                return Shape::Convex(poly);
            }
            return Shape::Planar {
                tris: split_face(g, newell, orient_k),
                k: support.dominant_exact_axis(),
            };
        }
    }
    Shape::Triangles(split_face(g, newell, orient_k))
}

/// Converts one input face (see the module docs).
pub(crate) fn face_polygons(corners: &[DVec3]) -> Result<Vec<ExactPolygon>, KernelError> {
    let o = outline(corners, false)?;
    if let [a, b, c] = o.pts[..] {
        // The common case, without the detour through `Shape`.
        return Ok(match Plane::through(a, b, c) {
            Ok(support) => vec![convex_polygon(&o.pts, support, &[true; 3])],
            Err(_) => Vec::new(),
        });
    }
    Ok(match shape(&o.pts) {
        Shape::Degenerate => Vec::new(),
        Shape::Convex(poly) => vec![poly],
        Shape::Triangles(tris) => {
            let mut out = Vec::with_capacity(tris.len());
            for t in tris {
                let [a, b, c] = t.idx.map(|i| o.pts[i]);
                if let Ok(support) = Plane::through(a, b, c) {
                    out.push(convex_polygon(&[a, b, c], support, &t.original));
                }
            }
            out
        }
        Shape::Planar { tris, k } => {
            let pts = &o.pts;
            let turn = |a: usize, b: usize, c: usize| orient_k(pts[a], pts[b], pts[c], k);
            let pieces = convex_pieces(&tris, turn);
            let mut out = Vec::with_capacity(pieces.len());
            for piece in pieces {
                let corners: Vec<P3> = piece.idx.iter().map(|&i| pts[i]).collect();
                // Strictly convex: its first three corners span the face's plane, and the
                // other corners lie on it exactly (the face is planar).
                if let Ok(support) = Plane::through(corners[0], corners[1], corners[2]) {
                    let support = match corners.get(3) {
                        Some(&x) => support.also_through(x),
                        None => support,
                    };
                    out.push(convex_polygon(&corners, support, &piece.original));
                }
            }
            out
        }
    })
}

/// One triangle of an input face, as [`face_triangles`] gives it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FaceTriangle {
    /// Indices into the face's corners as given, in the face's winding.
    pub corners: [usize; 3],
    /// Per edge `k` (from corner `k` to corner `k + 1`): whether it is an edge of the
    /// face's outline (not a diagonal).
    pub outline: [bool; 3],
}

/// The triangles that cover what the exact kernel draws of the face with these corners,
/// for image-space renderers: the face's one convex polygon fanned from its first
/// corner, or the triangles of the kernel's rule for the other faces (a coordinate
/// projection in which the outline is simple, else the fan from corner 0). Triangles of
/// exactly zero area are left out; a face with area always has at least one.
///
/// # Errors
///
/// [`KernelError::Empty`] for no corners, [`KernelError::NonFinite`] for a corner that
/// is not finite.
pub fn face_triangles(corners: &[DVec3]) -> Result<Vec<FaceTriangle>, KernelError> {
    let o = outline(corners, true)?;
    let given = |t: [usize; 3]| t.map(|i| o.given[i]);
    Ok(match shape(&o.pts) {
        Shape::Degenerate => Vec::new(),
        Shape::Convex(_) => {
            let n = o.pts.len();
            (1..n - 1)
                .filter(|&i| Plane::through(o.pts[0], o.pts[i], o.pts[i + 1]).is_ok())
                .map(|i| FaceTriangle {
                    corners: given([0, i, i + 1]),
                    outline: [i == 1, true, i + 1 == n - 1],
                })
                .collect()
        }
        Shape::Triangles(tris) | Shape::Planar { tris, .. } => tris
            .into_iter()
            .filter(|t| {
                let [a, b, c] = t.idx.map(|i| o.pts[i]);
                Plane::through(a, b, c).is_ok()
            })
            .map(|t| FaceTriangle {
                corners: given(t.idx),
                outline: t.original,
            })
            .collect(),
    })
}

/// The single-polygon path for a face whose corners all lie on `support`: collinear
/// removal, convexity check.
fn try_convex(g: &[P3], support: &Plane) -> Option<ExactPolygon> {
    let k = support.dominant_exact_axis();
    let mut pts = g.to_vec();
    drop_collinear(&mut pts, k);
    let sgn = support.normal_sign(k);
    if !strictly_convex(&pts, k, sgn) {
        return None;
    }
    let original = vec![true; pts.len()];
    // A corner outside the support's definition (the fourth of a quad) is known to lie on
    // it exactly: the shortcut answers for it from now on.
    let support = match pts.iter().find(|p| !support.defined_by(p)) {
        Some(&x) => support.also_through(x),
        None => support.clone(),
    };
    Some(convex_polygon(&pts, support, &original))
}
