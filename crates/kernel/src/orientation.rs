//! The orientation of four points: the predicate the orderings need beyond plane sides
//! (polygons that only touch at a shared vertex, seen from the eye).

use std::cmp::Ordering;

/// The orientation of four points `e, a, b, c`: the sign of Shewchuk's
/// `orient3d(e, a, b, c)`, the determinant of the rows `e − c`, `a − c`, `b − c`.
/// `Positive` when `c` lies below the plane through `e, a, b` (those three running
/// counter-clockwise seen from above).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// A positive determinant.
    Positive,
    /// A negative determinant.
    Negative,
    /// The four points are coplanar.
    Coplanar,
}

impl Orientation {
    /// The orientation for the sign of the determinant.
    pub fn from_ordering(o: Ordering) -> Orientation {
        match o {
            Ordering::Greater => Orientation::Positive,
            Ordering::Less => Orientation::Negative,
            Ordering::Equal => Orientation::Coplanar,
        }
    }

    /// The orientation of the same points with two of them swapped.
    pub fn reverse(self) -> Orientation {
        match self {
            Orientation::Positive => Orientation::Negative,
            Orientation::Negative => Orientation::Positive,
            Orientation::Coplanar => Orientation::Coplanar,
        }
    }
}
