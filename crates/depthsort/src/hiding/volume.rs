//! One occluder's volume as exact half-spaces (what it hides from a light or from the
//! eye), and the exact clip of a convex polygon by it.
//!
//! A convex occluder `Q` (its corners are input points) hides a point `x` from a source
//! (a light, or the eye) exactly when the segment from `x` to the source crosses `Q`'s
//! interior: `x` lies strictly beyond `Q`'s plane (on the side away from the source) and
//! strictly inside every side plane, the plane through the source and an edge of `Q`
//! (for a source at infinity in direction `d`, the plane through the edge containing
//! `d`). Every one of these planes is defined by input points and the source, so every
//! side a clip decides is exact; the pieces it cuts have implicit vertices, never
//! rounded ones.
//!
//! Seen from the eye, a polygon lying in `Q`'s plane is hidden where `Q` covers it when
//! `Q` is painted over it (the painter's coplanar rule: the later face wins); the clip
//! then keeps only the side planes, which meet that plane in `Q`'s edges.

use std::collections::HashMap;

use glam::DVec3;
use limn_kernel::{Kernel, PolygonSide, Side};

use crate::options::OrderError;

/// A light, or the eye, as the volumes see it.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Source<P> {
    /// A point light (or a finite eye) at this position (`P`: the kernel's point).
    At(DVec3, P),
    /// A light (or an eye) at infinity in this direction (from the scene towards it).
    Toward(DVec3),
}

impl<P> Source<P> {
    /// The side of `plane` the source lies on.
    pub fn side<K: Kernel<Point = P>>(&self, k: &K, plane: &K::Plane) -> Side {
        match self {
            Source::At(_, p) => k.side_of_point(plane, p),
            Source::Toward(d) => k.side_of_direction(plane, *d),
        }
    }
}

/// A plane and the side of it that is inside the volume.
#[derive(Debug, Clone)]
pub(crate) struct Bound<P> {
    pub plane: P,
    pub inside: Side,
}

/// The volume one convex occluder hides: the intersection of its bounds' inner open
/// half-spaces. The first bound is the occluder's own plane.
#[derive(Debug, Clone)]
pub(crate) struct Volume<P> {
    pub bounds: Vec<Bound<P>>,
    /// The occluder's input face.
    pub face: u32,
}

/// The side planes of the occluders, one per edge: occluders sharing an edge share its
/// plane (the same plane value, so that a vertex cut by it is known to lie on it without
/// arithmetic when the neighbour's volume classifies it).
pub(crate) struct SidePlanes<P> {
    planes: HashMap<([u64; 3], [u64; 3]), P>,
}

impl<P: Clone> SidePlanes<P> {
    /// No planes yet.
    pub fn new() -> Self {
        SidePlanes {
            planes: HashMap::new(),
        }
    }

    /// The plane through the light and the edge `a b`, made once per edge (its
    /// orientation is that of the edge's corners in a fixed order).
    fn plane<K: Kernel<Plane = P>>(
        &mut self,
        k: &K,
        light: &Source<K::Point>,
        a: DVec3,
        b: DVec3,
    ) -> Result<P, OrderError> {
        let key = |v: DVec3| v.to_array().map(f64::to_bits);
        let (lo, hi) = if key(a) <= key(b) { (a, b) } else { (b, a) };
        let entry = (key(lo), key(hi));
        if let Some(p) = self.planes.get(&entry) {
            return Ok(p.clone());
        }
        let plane = match light {
            Source::At(l, _) => k.plane_through_points(*l, lo, hi)?,
            Source::Toward(d) => k.plane_along(lo, hi, *d)?,
        };
        self.planes.insert(entry, plane.clone());
        Ok(plane)
    }
}

/// What a clip by a volume leaves of a polygon.
#[derive(Debug)]
pub(crate) enum Clip<P> {
    /// No part of positive area lies inside.
    Outside,
    /// All of it lies inside (its boundary may touch the volume's).
    Inside,
    /// Both: the part inside and the parts outside (together they tile the polygon).
    Split { inside: P, outside: Vec<P> },
}

/// The volume the convex polygon `poly` of input face `face` (whose vertices must be
/// input points) hides from `light`; `None` when it hides none of positive volume (the
/// light lies in its plane).
pub(crate) fn volume<K: Kernel>(
    k: &K,
    poly: &K::Polygon,
    face: u32,
    light: &Source<K::Point>,
    corners: &mut Vec<DVec3>,
    shared: &mut SidePlanes<K::Plane>,
) -> Result<Option<Volume<K::Plane>>, OrderError> {
    let support = k.support(poly).clone();
    let beyond = match light.side(k, &support) {
        Side::On => return Ok(None),
        Side::Front => Side::Back,
        Side::Back => Side::Front,
    };
    corners.clear();
    k.vertices_world(poly, corners);
    let n = corners.len();
    let mut bounds = Vec::with_capacity(n + 1);
    bounds.push(Bound {
        plane: support,
        inside: beyond,
    });
    for i in 0..n {
        let (a, b) = (corners[i], corners[(i + 1) % n]);
        let plane = shared.plane(k, light, a, b)?;
        // The inside is where the occluder's other corners are.
        let mut inside = Side::On;
        for j in 2..n {
            let c = k.point(corners[(i + j) % n])?;
            inside = k.side_of_point(&plane, &c);
            if inside != Side::On {
                break;
            }
        }
        if inside == Side::On {
            return Ok(None); // a degenerate occluder
        }
        bounds.push(Bound { plane, inside });
    }
    Ok(Some(Volume { bounds, face }))
}

/// How a convex polygon lies with respect to a volume.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Reach {
    /// All of it lies inside (its boundary may touch the volume's): [`clip`] says
    /// [`Clip::Inside`].
    Covered,
    /// It lies wholly outside one of the volume's bounds, and so does every part of it:
    /// [`clip`] says [`Clip::Outside`] for it and for each of its parts.
    Apart,
    /// It crosses a bound (the bounds after it were not looked at).
    Across,
}

/// Whether a polygon on `side` of a bound lies inside it (`Some(true)`), outside it
/// (`Some(false)`, also when it lies in the bound's plane, unless `coplanar_inside`), or
/// across it (`None`).
fn inside_of(side: PolygonSide, inside: Side, coplanar_inside: bool) -> Option<bool> {
    match (side, inside) {
        (PolygonSide::Front, Side::Front) | (PolygonSide::Back, Side::Back) => Some(true),
        (PolygonSide::Coplanar | PolygonSide::CoplanarOpposite, _) => Some(coplanar_inside),
        (PolygonSide::Spanning, _) => None,
        _ => Some(false),
    }
}

/// How the convex polygon `poly` lies with respect to `vol`, exactly, without cutting
/// anything: the bounds in order, up to the first one it does not lie inside.
pub(crate) fn reach<K: Kernel>(
    k: &K,
    poly: &K::Polygon,
    vol: &Volume<K::Plane>,
    coplanar_hidden: bool,
) -> Reach {
    for (i, b) in vol.bounds.iter().enumerate() {
        match inside_of(
            k.classify(poly, &b.plane),
            b.inside,
            i == 0 && coplanar_hidden,
        ) {
            Some(true) => {}
            Some(false) => return Reach::Apart,
            None => return Reach::Across,
        }
    }
    Reach::Covered
}

/// Clips the convex polygon `poly` by `vol`, exactly. A polygon lying in one of the
/// volume's planes is outside (it touches the volume in zero volume), except in the
/// occluder's own plane when `coplanar_hidden`: there the occluder covers it.
pub(crate) fn clip<K: Kernel>(
    k: &K,
    poly: &K::Polygon,
    vol: &Volume<K::Plane>,
    coplanar_hidden: bool,
) -> Clip<K::Polygon> {
    let mut rest: Option<K::Polygon> = None;
    let mut outside = Vec::new();
    for (i, b) in vol.bounds.iter().enumerate() {
        let cur = rest.as_ref().unwrap_or(poly);
        match inside_of(
            k.classify(cur, &b.plane),
            b.inside,
            i == 0 && coplanar_hidden,
        ) {
            Some(true) => {}
            Some(false) => return Clip::Outside,
            None => {
                let (front, back) = k.split(cur, &b.plane);
                let (inn, out) = if b.inside == Side::Front {
                    (front, back)
                } else {
                    (back, front)
                };
                match (inn, out) {
                    (Some(inn), Some(out)) => {
                        outside.push(out);
                        rest = Some(inn);
                    }
                    (Some(inn), None) => rest = Some(inn),
                    (None, _) => return Clip::Outside,
                }
            }
        }
    }
    match rest {
        None => Clip::Inside,
        Some(_) if outside.is_empty() => Clip::Inside,
        Some(inside) => Clip::Split { inside, outside },
    }
}
