//! Floating-point screen geometry used only to *prune* work: bounding boxes and the
//! separating-axis test. Every answer is conservative (two polygons are called disjoint
//! only when a gap wider than a margin separates them), so a float error can cost work
//! but never change an order.

/// An axis-aligned box in pixel space: `[min_x, min_y, max_x, max_y]`.
pub(crate) type Box2 = [f64; 4];

/// The bounding box of a point list.
pub(crate) fn bbox(pts: &[[f64; 2]]) -> Box2 {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in pts {
        b[0] = b[0].min(p[0]);
        b[1] = b[1].min(p[1]);
        b[2] = b[2].max(p[0]);
        b[3] = b[3].max(p[1]);
    }
    b
}

/// Whether two boxes overlap or come within `margin` of each other.
#[inline]
pub(crate) fn boxes_meet(a: &Box2, b: &Box2, margin: f64) -> bool {
    a[0] <= b[2] + margin && b[0] <= a[2] + margin && a[1] <= b[3] + margin && b[1] <= a[3] + margin
}

/// Whether the convex polygons `a` and `b` are separated by a gap wider than `margin`
/// along one of their edge normals (the separating axis theorem). `false` means "may
/// overlap".
pub(crate) fn convex_disjoint(a: &[[f64; 2]], b: &[[f64; 2]], margin: f64) -> bool {
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
            amin = amin.min(d);
            amax = amax.max(d);
        }
        let (mut bmin, mut bmax) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in b {
            let d = v[0] * nx + v[1] * ny;
            bmin = bmin.min(d);
            bmax = bmax.max(d);
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
    fn diagonal_separation_is_found() {
        let a = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let b = [[1.0, 1.0], [2.0, 1.0], [1.0, 2.0]];
        assert!(!boxes_meet(&bbox(&a), &bbox(&[[1.1, 1.1]]), 0.0));
        assert!(convex_disjoint(&a, &b, 1e-9));
    }
}
