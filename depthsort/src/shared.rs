//! Exact vertex coordinates and the orientation seen from the eye, for the one case the
//! plane tests cannot settle: polygons that touch at a shared vertex or edge, where a
//! float overlap test can never prove that their projections only touch.

use glam::DVec3;
use limn_kernel::{ExactKernel, ExactPolygon, FloatKernel, FloatPolygon, Kernel};

/// A kernel that can give some vertices exactly and orient four such points exactly.
pub trait ExactVertices: Kernel {
    /// An exactly represented point.
    type Exact: Copy + PartialEq;
    /// Vertex `i` of `poly`, when it is exactly representable (an input point, or an
    /// intersection whose coordinates are exactly representable, for the exact kernel; every vertex for the float kernel).
    fn vertex_exact(&self, poly: &Self::Polygon, i: usize) -> Option<Self::Exact>;
    /// A point, exactly.
    fn point_exact(&self, p: &Self::Point) -> Self::Exact;
    /// The sign (−1, 0, 1) of the orientation of `a`, `b`, `c` as seen from `e`.
    fn orient(&self, e: &Self::Exact, a: &Self::Exact, b: &Self::Exact, c: &Self::Exact) -> i32;
    /// A cheap world position of vertex `i`, within a relative 1e-9 of the true
    /// one, when the kernel has it at hand (for the float prefilters only).
    fn vertex_world_fast(&self, poly: &Self::Polygon, i: usize) -> Option<glam::DVec3>;
}

impl ExactVertices for ExactKernel {
    type Exact = [f64; 3];

    fn vertex_exact(&self, poly: &ExactPolygon, i: usize) -> Option<[f64; 3]> {
        let (c, err) = poly.vertex_approx(i);
        (err == 0.0).then_some(c)
    }

    fn point_exact(&self, p: &DVec3) -> [f64; 3] {
        p.to_array()
    }

    fn orient(&self, e: &[f64; 3], a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> i32 {
        match limn_kernel::predicates::orient3d(*e, *a, *b, *c) {
            std::cmp::Ordering::Greater => 1,
            std::cmp::Ordering::Less => -1,
            std::cmp::Ordering::Equal => 0,
        }
    }

    fn vertex_world_fast(&self, poly: &ExactPolygon, i: usize) -> Option<DVec3> {
        let (c, err) = poly.vertex_approx(i);
        let scale = c[0].abs().max(c[1].abs()).max(c[2].abs());
        (err <= 1e-9 * scale).then(|| DVec3::from_array(c))
    }
}

impl ExactVertices for FloatKernel {
    type Exact = [f64; 3];

    fn vertex_exact(&self, poly: &FloatPolygon, i: usize) -> Option<[f64; 3]> {
        poly.vertices().nth(i).map(|v| v.to_array())
    }

    fn point_exact(&self, p: &glam::DVec3) -> [f64; 3] {
        p.to_array()
    }

    fn orient(&self, e: &[f64; 3], a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> i32 {
        let pt = |p: &[f64; 3]| robust::Coord3D {
            x: p[0],
            y: p[1],
            z: p[2],
        };
        let o = robust::orient3d(pt(e), pt(a), pt(b), pt(c));
        if o > 0.0 {
            1
        } else if o < 0.0 {
            -1
        } else {
            0
        }
    }

    fn vertex_world_fast(&self, poly: &FloatPolygon, i: usize) -> Option<glam::DVec3> {
        poly.vertices().nth(i)
    }
}
