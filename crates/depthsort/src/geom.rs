//! Floating-point screen geometry used only to *prune* work: bounding boxes and the
//! separating-axis test. Every answer is conservative (two polygons are called disjoint
//! only when a gap wider than a margin separates them), so a float error can cost work
//! but never change an order.

/// An axis-aligned box in pixel space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Box2 {
    pub min_x: f64,
    pub min_y: f64,
    pub max_x: f64,
    pub max_y: f64,
}

impl Box2 {
    /// The empty box (the identity of [`Box2::union`]).
    pub const EMPTY: Box2 = Box2 {
        min_x: f64::INFINITY,
        min_y: f64::INFINITY,
        max_x: f64::NEG_INFINITY,
        max_y: f64::NEG_INFINITY,
    };

    /// The box grown by `m` on every side.
    #[inline]
    pub fn grown(&self, m: f64) -> Box2 {
        Box2 {
            min_x: self.min_x - m,
            min_y: self.min_y - m,
            max_x: self.max_x + m,
            max_y: self.max_y + m,
        }
    }

    /// The smallest box containing both.
    #[inline]
    pub fn union(&self, o: &Box2) -> Box2 {
        Box2 {
            min_x: self.min_x.min(o.min_x),
            min_y: self.min_y.min(o.min_y),
            max_x: self.max_x.max(o.max_x),
            max_y: self.max_y.max(o.max_y),
        }
    }

    /// Width (negative for the empty box).
    #[inline]
    pub fn width(&self) -> f64 {
        self.max_x - self.min_x
    }

    /// Height (negative for the empty box).
    #[inline]
    pub fn height(&self) -> f64 {
        self.max_y - self.min_y
    }
}

/// The bounding box of a point list.
pub(crate) fn bbox(pts: &[[f64; 2]]) -> Box2 {
    let mut b = Box2::EMPTY;
    for p in pts {
        b.min_x = b.min_x.min(p[0]);
        b.min_y = b.min_y.min(p[1]);
        b.max_x = b.max_x.max(p[0]);
        b.max_y = b.max_y.max(p[1]);
    }
    b
}

/// The smaller of `d` and `m`, ignoring a NaN `d` (as [`f64::min`] does; `m` starts
/// infinite and is never NaN): one comparison, where `f64::min` needs four instructions
/// more to handle a NaN on either side. The separating-axis tests run it for every
/// corner of every pair.
#[inline(always)]
pub(crate) fn lower(d: f64, m: f64) -> f64 {
    if d < m {
        d
    } else {
        m
    }
}

/// The larger of `d` and `m`, ignoring a NaN `d` (see [`lower`]).
#[inline(always)]
pub(crate) fn higher(d: f64, m: f64) -> f64 {
    if d > m {
        d
    } else {
        m
    }
}

/// Whether two boxes overlap or come within `margin` of each other.
#[inline]
pub(crate) fn boxes_meet(a: &Box2, b: &Box2, margin: f64) -> bool {
    a.min_x <= b.max_x + margin
        && b.min_x <= a.max_x + margin
        && a.min_y <= b.max_y + margin
        && b.min_y <= a.max_y + margin
}

/// Whether the convex polygons `a` and `b` are separated by a gap wider than `margin`
/// along one of their edge normals (the separating axis theorem). `false` means "may
/// overlap".
///
/// Polygons with a common corner (the same `f64` point, as neighbours in a mesh have) are
/// never separated (the corner lies in both projections on every axis): they are answered
/// at once, without the axes, which are the dearest case (no axis separates them).
pub(crate) fn convex_disjoint(a: &[[f64; 2]], b: &[[f64; 2]], margin: f64) -> bool {
    if a.iter().any(|p| b.contains(p)) {
        return false;
    }
    separated_by_edges_of(a, b, margin) || separated_by_edges_of(b, a, margin)
}

fn separated_by_edges_of(a: &[[f64; 2]], b: &[[f64; 2]], margin: f64) -> bool {
    let n = a.len();
    for i in 0..n {
        let p = a[i];
        let q = a[(i + 1) % n];
        // Unnormalised edge normal; the margin is scaled by its length instead.
        let (nx, ny) = (q[1] - p[1], p[0] - q[0]);
        let len = nx.abs() + ny.abs();
        if len.is_nan() || len <= 0.0 {
            continue;
        }
        let m = margin * len;
        let (mut amin, mut amax) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in a {
            let d = v[0] * nx + v[1] * ny;
            amin = lower(d, amin);
            amax = higher(d, amax);
        }
        let (mut bmin, mut bmax) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in b {
            let d = v[0] * nx + v[1] * ny;
            bmin = lower(d, bmin);
            bmax = higher(d, bmax);
        }
        if amax + m < bmin || bmax + m < amin {
            return true;
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn touching_squares_may_overlap_but_gapped_ones_do_not() {
        let a = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let b = [[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]];
        let c = [[1.5, 0.0], [2.0, 0.0], [2.0, 1.0], [1.5, 1.0]];
        assert!(!convex_disjoint(&a, &b, 1e-9));
        assert!(convex_disjoint(&a, &c, 1e-9));
        assert!(!convex_disjoint(&a, &c, 1.0));
    }

    #[test]
    fn polygons_with_a_common_corner_are_never_disjoint() {
        let a = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let b = [[1.0, 0.0], [2.0, 0.0], [2.0, 1.0]];
        assert!(!convex_disjoint(&a, &b, 1e-9));
        assert!(!convex_disjoint(&b, &a, 0.0));
        // The same triangles a hair apart are.
        let c = [[1.0 + 1e-6, 0.0], [2.0, 0.0], [2.0, 1.0]];
        assert!(convex_disjoint(&a, &c, 1e-9));
    }

    #[test]
    fn diagonal_separation_is_found() {
        let a = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let b = [[1.0, 1.0], [2.0, 1.0], [1.0, 2.0]];
        assert!(!boxes_meet(&bbox(&a), &bbox(&[[1.1, 1.1]]), 0.0));
        assert!(convex_disjoint(&a, &b, 1e-9));
    }
}
