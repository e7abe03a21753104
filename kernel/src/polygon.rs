//! Convex polygons as a supporting plane plus one bounding plane per edge, and their
//! classification and splitting by a plane.

use smallvec::SmallVec;

use crate::plane::Plane;
use crate::predicates::{self, as_grid, PlaneF};
use crate::traits::{PolygonSide, Side};

/// Corners stored inline (no heap allocation) up to this count.
pub(crate) const INLINE: usize = 4;

/// One corner of a polygon: vertex `i` and the edge leaving it (towards vertex `i + 1`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Corner {
    /// The plane of edge `i`; the polygon's interior is on its back side.
    pub(crate) edge: Plane,
    /// Approximate grid coordinates of vertex `i`.
    pub(crate) pos: [f64; 3],
    /// Bound on the error of every coordinate of `pos`; 0 means `pos` is exact (and then a
    /// grid point).
    pub(crate) err: f32,
    /// Whether edge `i` lies on an edge of the input face.
    pub(crate) original: bool,
}

/// Rounds an f64 error bound up to f32.
#[inline]
pub(crate) fn err32(e: f64) -> f32 {
    let f = e as f32;
    if (f as f64) < e {
        f.next_up()
    } else {
        f
    }
}

/// A convex polygon of the exact kernel.
///
/// Representation: the supporting plane `S` and, per edge `i`, a bounding plane `Eᵢ` with
/// the interior on its back side. Vertex `i` is `S ∩ Eᵢ₋₁ ∩ Eᵢ`; it is never stored as
/// rounded coordinates for decisions: the cached f64 position only feeds the filter,
/// together with its proven error bound. Guarantees: at least three vertices, strictly
/// convex (no three consecutive vertices collinear), non-zero area, vertices
/// counter-clockwise seen from the front of `S`.
#[derive(Debug, Clone)]
pub struct ExactPolygon {
    pub(crate) support: Plane,
    pub(crate) corners: SmallVec<[Corner; INLINE]>,
}

impl ExactPolygon {
    /// The supporting plane (normal towards the front).
    pub fn support(&self) -> &Plane {
        &self.support
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.corners.len()
    }

    /// Always false (a polygon has at least three vertices); present for API symmetry.
    pub fn is_empty(&self) -> bool {
        self.corners.is_empty()
    }

    /// The bounding plane of edge `i` (from vertex `i` to `i + 1`); the interior is on its
    /// back side. Panics if `i` is out of range.
    pub fn edge_plane(&self, i: usize) -> &Plane {
        &self.corners[i].edge
    }

    /// Whether edge `i` lies on an edge of the input face.
    pub fn edge_is_original(&self, i: usize) -> bool {
        self.corners.get(i).is_some_and(|c| c.original)
    }

    /// The three planes whose intersection is vertex `i`: support, edge `i - 1`, edge `i`.
    pub fn vertex_planes(&self, i: usize) -> [Plane; 3] {
        let n = self.corners.len();
        [
            self.support,
            self.corners[(i + n - 1) % n].edge,
            self.corners[i].edge,
        ]
    }

    /// The cached approximate grid coordinates of vertex `i` and their error bound.
    pub fn vertex_approx(&self, i: usize) -> ([f64; 3], f64) {
        let c = &self.corners[i];
        (c.pos, c.err as f64)
    }

    /// Exact side of `h` at vertex `i`, without the filter.
    pub fn side_exact(&self, i: usize, h: &Plane) -> Side {
        let c = &self.corners[i];
        if let Some(g) = as_grid(&c.pos, c.err as f64) {
            return h.side_of(&g);
        }
        let [s, a, b] = self.vertex_planes(i);
        predicates::side_of_intersection(&s, &a, &b, h).unwrap_or(Side::On)
    }

    /// Side of vertex `i` using the filter first; counts a fallback in `fallbacks`.
    #[inline]
    pub(crate) fn side_filtered(
        &self,
        i: usize,
        h: &Plane,
        hf: &PlaneF,
        fallbacks: &mut u64,
    ) -> Side {
        let c = &self.corners[i];
        match hf.side(&c.pos, c.err as f64) {
            Some(s) => s,
            None => {
                *fallbacks += 1;
                self.side_exact(i, h)
            }
        }
    }

    /// Sides of all vertices (filter first unless `filter` is false).
    pub(crate) fn sides(
        &self,
        h: &Plane,
        filter: bool,
        fallbacks: &mut u64,
    ) -> SmallVec<[Side; 8]> {
        let hf = PlaneF::new(h);
        (0..self.corners.len())
            .map(|i| {
                if filter {
                    self.side_filtered(i, h, &hf, fallbacks)
                } else {
                    self.side_exact(i, h)
                }
            })
            .collect()
    }

    /// Classification against `h`.
    pub(crate) fn classify(&self, h: &Plane, filter: bool, fallbacks: &mut u64) -> PolygonSide {
        let hf = PlaneF::new(h);
        let (mut front, mut back) = (false, false);
        for i in 0..self.corners.len() {
            let s = if filter {
                self.side_filtered(i, h, &hf, fallbacks)
            } else {
                self.side_exact(i, h)
            };
            match s {
                Side::Front => front = true,
                Side::Back => back = true,
                Side::On => {}
            }
            if front && back {
                return PolygonSide::Spanning;
            }
        }
        match (front, back) {
            (true, _) => PolygonSide::Front,
            (_, true) => PolygonSide::Back,
            _ if self.support.same_facing(h) => PolygonSide::Coplanar,
            _ => PolygonSide::CoplanarOpposite,
        }
    }

    /// Splits by `h` (see [`crate::Kernel::split`]).
    pub(crate) fn split(
        &self,
        h: &Plane,
        filter: bool,
        fallbacks: &mut u64,
    ) -> (Option<ExactPolygon>, Option<ExactPolygon>) {
        let sides = self.sides(h, filter, fallbacks);
        let front = sides.contains(&Side::Front);
        let back = sides.contains(&Side::Back);
        match (front, back) {
            (true, false) => return (Some(self.clone()), None),
            (false, true) => return (None, Some(self.clone())),
            (false, false) => {
                return if self.support.same_facing(h) {
                    (Some(self.clone()), None)
                } else {
                    (None, Some(self.clone()))
                };
            }
            (true, true) => {}
        }
        let n = self.corners.len();
        let neg = h.flipped();
        let mut fp: SmallVec<[Corner; INLINE]> = SmallVec::new();
        let mut bp: SmallVec<[Corner; INLINE]> = SmallVec::new();
        for i in 0..n {
            let c = self.corners[i];
            let j = if i + 1 == n { 0 } else { i + 1 };
            let (si, sj) = (sides[i], sides[j]);
            // Vertex i itself.
            if si != Side::Back {
                let cut = si == Side::On && sj == Side::Back;
                fp.push(if cut { cut_corner(&c, neg) } else { c });
            }
            if si != Side::Front {
                let cut = si == Side::On && sj == Side::Front;
                bp.push(if cut { cut_corner(&c, *h) } else { c });
            }
            // A strict crossing of edge i.
            let crossing = matches!(
                (si, sj),
                (Side::Front, Side::Back) | (Side::Back, Side::Front)
            );
            if crossing {
                let (pos, err) = predicates::approximate(&self.support, &c.edge, h)
                    .unwrap_or(([0.0; 3], f64::INFINITY));
                let on_edge = Corner {
                    edge: c.edge,
                    pos,
                    err: err32(err),
                    original: c.original,
                };
                if si == Side::Front {
                    fp.push(cut_corner(&on_edge, neg));
                    bp.push(on_edge);
                } else {
                    fp.push(on_edge);
                    bp.push(cut_corner(&on_edge, *h));
                }
            }
        }
        let mk = |corners| ExactPolygon {
            support: self.support,
            corners,
        };
        (Some(mk(fp)), Some(mk(bp)))
    }
}

/// The corner at the same vertex whose outgoing edge is the cut `plane`.
#[inline]
fn cut_corner(c: &Corner, plane: Plane) -> Corner {
    Corner {
        edge: plane,
        pos: c.pos,
        err: c.err,
        original: false,
    }
}
