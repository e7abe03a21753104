//! Exact vertex coordinates and the orientation seen from the eye, for the one case the
//! plane tests cannot settle: polygons that touch at a shared vertex or edge, where a
//! float overlap test can never prove that their projections only touch.

use limn_kernel::{ExactKernel, ExactPolygon, FloatKernel, FloatPolygon, GridPoint, Kernel};

/// A kernel that can give some vertices exactly and orient four such points exactly.
pub trait ExactVertices: Kernel {
    /// An exactly represented point.
    type Exact: Copy + PartialEq;
    /// Vertex `i` of `poly`, when it is exactly representable (an input grid point for
    /// the exact kernel; every vertex for the float kernel).
    fn vertex_exact(&self, poly: &Self::Polygon, i: usize) -> Option<Self::Exact>;
    /// A point, exactly.
    fn point_exact(&self, p: &Self::Point) -> Self::Exact;
    /// The sign (−1, 0, 1) of the orientation of `a`, `b`, `c` as seen from `e`.
    fn orient(&self, e: &Self::Exact, a: &Self::Exact, b: &Self::Exact, c: &Self::Exact) -> i32;
    /// A cheap world position of vertex `i`, within a millionth of a grid step of the
    /// true one, when the kernel has it at hand (for the float prefilters only).
    fn vertex_world_fast(&self, poly: &Self::Polygon, i: usize) -> Option<glam::DVec3>;
}

impl ExactVertices for ExactKernel {
    type Exact = [i64; 3];

    fn vertex_exact(&self, poly: &ExactPolygon, i: usize) -> Option<[i64; 3]> {
        let (c, err) = poly.vertex_approx(i);
        (err == 0.0).then(|| c.map(|v| v as i64))
    }

    fn point_exact(&self, p: &GridPoint) -> [i64; 3] {
        [p.x, p.y, p.z]
    }

    fn orient(&self, e: &[i64; 3], a: &[i64; 3], b: &[i64; 3], c: &[i64; 3]) -> i32 {
        use ethnum::I256;
        let d = |p: &[i64; 3]| [0, 1, 2].map(|k| I256::from(p[k] as i128 - e[k] as i128));
        let (a, b, c) = (d(a), d(b), d(c));
        let det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]);
        det.signum().as_i32()
    }

    fn vertex_world_fast(&self, poly: &ExactPolygon, i: usize) -> Option<glam::DVec3> {
        let (c, err) = poly.vertex_approx(i);
        (err <= 1e-6).then(|| self.quantizer().world_f(c))
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
