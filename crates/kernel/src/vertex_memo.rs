//! A per-thread memory of exact answers at split vertices: the ordering asks the same
//! questions about a vertex made by splitting many times over (the side of one plane at
//! it, as the pieces of a set are scored as splitter candidates again at every level of
//! the partition and tested again in later occlusion tests; its rounded position, for
//! every piece that has it as a corner), and each answer may cost an exact evaluation of
//! a polynomial of degree up to 9 in the input coordinates.
//!
//! A vertex made by splitting is the intersection of three planes; it and the plane
//! asked about are named by the planes' identities ([`Plane::id`], never reused), so a
//! remembered answer is the exact answer to the same question whatever the orientations
//! and the order of the planes: the intersection point depends on neither, and the side
//! of a flipped plane is the opposite side. Each memory is a direct-mapped table of fixed
//! size per thread (a newer question replaces an older one in its slot): it costs a
//! bounded amount of memory and never changes an answer.

use std::cell::RefCell;

use crate::plane::Plane;
use crate::side::Side;

/// Slots of each table per thread (a power of two): under a megabyte each. The same
/// question mostly comes back soon: on the 2CylinderEngine assembly 2¹⁶ slots took the
/// same time with more memory, and 2¹⁸ answered 0.7 % more of its questions about
/// sides than 2¹⁶.
const SLOTS: usize = 1 << 14;

/// A remembered side: the sorted identities of the vertex's three planes and the identity
/// of the plane asked about (0, never an identity, in an empty slot), and the side for
/// that plane's definition unflipped.
#[derive(Clone, Copy)]
struct SideSlot {
    key: [u64; 4],
    side: Side,
}

/// A remembered rounded position: the sorted identities of the vertex's three planes (0
/// in an empty slot) and the position, `None` when the planes do not meet in one point.
#[derive(Clone, Copy)]
struct PointSlot {
    key: [u64; 3],
    point: Option<[f64; 3]>,
}

thread_local! {
    static SIDES: RefCell<Vec<SideSlot>> = const { RefCell::new(Vec::new()) };
    static POINTS: RefCell<Vec<PointSlot>> = const { RefCell::new(Vec::new()) };
}

/// The sorted identities of a vertex's planes.
#[inline]
fn vertex_key(planes: [&Plane; 3]) -> [u64; 3] {
    let mut v = planes.map(Plane::id);
    v.sort_unstable();
    v
}

/// The exact side of `h` at the intersection of `planes`, remembered: `exact` computes it
/// when this thread does not remember the answer.
#[inline]
pub(crate) fn side_at(planes: [&Plane; 3], h: &Plane, exact: impl FnOnce() -> Side) -> Side {
    let [a, b, c] = vertex_key(planes);
    let key = [a, b, c, h.id()];
    let slot = index(&key);
    // Flipping is its own inverse: the same map turns a remembered side into the answer
    // and an answer into the side remembered.
    let orient = |s: Side| if h.is_flipped() { s.flip() } else { s };
    let known = SIDES
        .try_with(|m| {
            let m = m.borrow();
            m.get(slot).filter(|s| s.key == key).map(|s| s.side)
        })
        .ok()
        .flatten();
    if let Some(s) = known {
        return orient(s);
    }
    let side = exact();
    let _ = SIDES.try_with(|m| {
        let mut m = m.borrow_mut();
        if m.is_empty() {
            m.resize(
                SLOTS,
                SideSlot {
                    key: [0; 4],
                    side: Side::On,
                },
            );
        }
        m[slot] = SideSlot {
            key,
            side: orient(side),
        };
    });
    side
}

/// The intersection of `planes` rounded to f64, remembered: `exact` computes it when
/// this thread does not remember it.
#[inline]
pub(crate) fn rounded(
    planes: [&Plane; 3],
    exact: impl FnOnce() -> Option<[f64; 3]>,
) -> Option<[f64; 3]> {
    let key = vertex_key(planes);
    let slot = index(&key);
    let known = POINTS
        .try_with(|m| {
            let m = m.borrow();
            m.get(slot).filter(|s| s.key == key).map(|s| s.point)
        })
        .ok()
        .flatten();
    if let Some(p) = known {
        return p;
    }
    let point = exact();
    let _ = POINTS.try_with(|m| {
        let mut m = m.borrow_mut();
        if m.is_empty() {
            m.resize(
                SLOTS,
                PointSlot {
                    key: [0; 3],
                    point: None,
                },
            );
        }
        m[slot] = PointSlot { key, point };
    });
    point
}

/// The slot of a key: a multiplicative hash of the identities.
#[inline]
fn index(key: &[u64]) -> usize {
    const K: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut h = 0u64;
    for &k in key {
        h = (h.rotate_left(5) ^ k).wrapping_mul(K);
    }
    (h >> (64 - SLOTS.trailing_zeros())) as usize
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::predicates;

    fn planes() -> [Plane; 4] {
        let t = |p, q, r| Plane::through(p, q, r).unwrap();
        [
            t([0.0, 0.0, 0.1], [1.0, 0.0, 0.2], [0.0, 1.0, 0.3]),
            t([0.3, 0.0, 0.0], [0.3, 1.0, 0.1], [0.4, 0.0, 1.0]),
            t([0.0, 0.7, 0.0], [1.0, 0.6, 0.0], [0.0, 0.7, 1.0]),
            t([0.1, 0.2, 0.3], [1.1, 0.3, 0.2], [0.2, 1.4, 0.1]),
        ]
    }

    #[test]
    fn a_remembered_side_answers_any_order_and_orientation() {
        let [s, a, b, h] = planes();
        let exact = |h: &Plane| predicates::side_of_intersection(&s, &a, &b, h).unwrap();
        let first = side_at([&s, &a, &b], &h, || exact(&h));
        assert_ne!(first, Side::On);
        // Remembered: the planes in another order, flipped, and the flipped plane asked.
        let (b2, s2, hf) = (b.flipped(), s.flipped(), h.flipped());
        let again = side_at([&b2, &a, &s2], &hf, || panic!("not remembered"));
        assert_eq!(again, exact(&hf));
        assert_eq!(again, first.flip());
        // Another plane is another question.
        let other = Plane::through([0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
        let mut asked = false;
        side_at([&s, &a, &b], &other, || {
            asked = true;
            exact(&other)
        });
        assert!(asked);
    }

    #[test]
    fn a_remembered_position_is_the_rounded_intersection() {
        let [s, a, b, _] = planes();
        let exact = || predicates::rounded_intersection(&s, &a, &b);
        let first = rounded([&s, &a, &b], exact);
        assert!(first.is_some());
        let again = rounded([&a.flipped(), &b, &s], || panic!("not remembered"));
        assert_eq!(again, exact());
    }

    #[test]
    fn planes_made_apart_have_apart_identities() {
        let [s, a, ..] = planes();
        let twin = Plane::through([0.0, 0.0, 0.1], [1.0, 0.0, 0.2], [0.0, 1.0, 0.3]).unwrap();
        assert_ne!(s.id(), twin.id());
        assert_ne!(s.id(), a.id());
        assert_eq!(s.id(), s.flipped().id());
        assert_ne!(s.id(), 0);
    }
}
