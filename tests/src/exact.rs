//! Running an ordering with the exact kernel and turning its fragments into exact
//! rational polygons for the [`crate::checker`].

use glam::DVec3;
use limn_depthsort::{order_polygons, OrderOptions, Ordered};
use limn_kernel::{ExactKernel, ExactPolygon, Kernel, Plane};
use limn_scene::{Camera, Scene};
use num_bigint::BigInt;
use num_traits::Zero;

use crate::checker::{Checker, ExactFragment, P3, Q};

fn qi(x: i128) -> Q {
    Q::from_integer(BigInt::from(x))
}

/// The intersection point of three planes, solved independently of the kernel (Cramer's
/// rule in big rationals).
pub fn intersect(p: &[Plane; 3]) -> P3 {
    let rows: Vec<[Q; 4]> = p
        .iter()
        .map(|pl| {
            let (a, b, c, d) = pl.coefficients();
            [qi(a as i128), qi(b as i128), qi(c as i128), -qi(d)]
        })
        .collect();
    let det3 = |m: [[&Q; 3]; 3]| -> Q {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    // Row `r` of the coefficient matrix, with column `k` replaced by the right-hand side
    // when k < 3.
    let col = |r: &[Q; 4], k: usize| -> [Q; 3] {
        let mut v = [r[0].clone(), r[1].clone(), r[2].clone()];
        if k < 3 {
            v[k] = r[3].clone();
        }
        v
    };
    let m: Vec<[Q; 3]> = rows.iter().map(|r| col(r, 3)).collect();
    let d = det3([
        [&m[0][0], &m[0][1], &m[0][2]],
        [&m[1][0], &m[1][1], &m[1][2]],
        [&m[2][0], &m[2][1], &m[2][2]],
    ]);
    assert!(!d.is_zero(), "vertex planes must meet in one point");
    let mut out: Vec<Q> = Vec::new();
    for k in 0..3 {
        let mk: Vec<[Q; 3]> = rows.iter().map(|r| col(r, k)).collect();
        let dk = det3([
            [&mk[0][0], &mk[0][1], &mk[0][2]],
            [&mk[1][0], &mk[1][1], &mk[1][2]],
            [&mk[2][0], &mk[2][1], &mk[2][2]],
        ]);
        out.push(dk / &d);
    }
    [out[0].clone(), out[1].clone(), out[2].clone()]
}

/// The exact vertices of a kernel polygon, in grid coordinates.
pub fn exact_vertices(poly: &ExactPolygon) -> Vec<P3> {
    (0..poly.len())
        .map(|i| intersect(&poly.vertex_planes(i)))
        .collect()
}

/// An exact run: the order, its fragments as exact polygons (grid coordinates), and a
/// checker for the (snapped) eye.
pub struct ExactRun {
    /// The order.
    pub ordered: Ordered,
    /// Exact fragments in painting order.
    pub fragments: Vec<ExactFragment>,
    /// The checker for this view.
    pub checker: Checker,
}

/// Orders `scene` with the exact kernel and prepares the exact check.
pub fn exact_run(scene: &Scene, camera: &Camera, opts: &OrderOptions) -> ExactRun {
    let (lo, hi) = scene.bounds().expect("scene has faces");
    let kernel = ExactKernel::new(lo, hi).expect("kernel");
    let (ordered, polys) = order_polygons(&kernel, scene, camera, opts).expect("orderable");
    let fragments = ordered
        .fragments
        .iter()
        .zip(&polys)
        .map(|(f, p)| ExactFragment {
            face: f.face,
            verts: exact_vertices(p),
        })
        .collect();
    let eye = kernel.point(camera.eye).expect("eye");
    let eye: P3 = [qi(eye.x as i128), qi(eye.y as i128), qi(eye.z as i128)];
    let fwd: DVec3 = ordered.camera.forward();
    let checker = Checker::new(eye, fwd.to_array());
    ExactRun {
        ordered,
        fragments,
        checker,
    }
}
