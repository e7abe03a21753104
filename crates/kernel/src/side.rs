//! Where a point or a polygon lies with respect to a plane.

use std::cmp::Ordering;

/// The side of a plane a point lies on. `Front` is the side the plane's normal points to
/// (where `a·x + b·y + c·z + d > 0`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// Strictly on the side the normal points to.
    Front,
    /// Strictly on the other side.
    Back,
    /// Exactly on the plane.
    On,
}

impl Side {
    /// The opposite side (`On` stays `On`).
    pub fn flip(self) -> Side {
        match self {
            Side::Front => Side::Back,
            Side::Back => Side::Front,
            Side::On => Side::On,
        }
    }
}

/// Where a convex polygon lies with respect to a plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PolygonSide {
    /// Every vertex is in front or on the plane, at least one strictly in front.
    Front,
    /// Every vertex is behind or on the plane, at least one strictly behind.
    Back,
    /// In the plane, facing the same way as the plane.
    Coplanar,
    /// In the plane, facing the opposite way.
    CoplanarOpposite,
    /// Vertices strictly on both sides.
    Spanning,
}

impl Side {
    /// The side for the sign of a plane's value (`Greater` is the front).
    #[inline]
    pub fn from_ordering(o: Ordering) -> Side {
        match o {
            Ordering::Greater => Side::Front,
            Ordering::Less => Side::Back,
            Ordering::Equal => Side::On,
        }
    }
}
