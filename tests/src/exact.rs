//! Running an ordering with the exact kernel and turning its fragments into exact
//! rational polygons for the [`crate::checker`].

use glam::DVec3;
use limn_depthsort::{order_polygons, OrderError, OrderOptions, Ordered};
use limn_kernel::{ExactKernel, ExactPolygon, Plane, PlaneDef};
use limn_scene::{Camera, Scene, Viewpoint};
use num_traits::Zero;

use crate::checker::{Checker, ExactFragment, P3, Q};

fn qf(x: f64) -> Q {
    Q::from_float(x).expect("finite coordinate")
}

fn qsub(a: &[Q; 3], b: &[Q; 3]) -> [Q; 3] {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn qcross(a: &[Q; 3], b: &[Q; 3]) -> [Q; 3] {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn qp(p: [f64; 3]) -> [Q; 3] {
    p.map(qf)
}

/// The exact coefficients `[a, b, c, d]` of a kernel plane, computed here in big
/// rationals from the plane's definition (independently of the kernel's arithmetic).
pub fn coefficients(pl: &Plane) -> [Q; 4] {
    let (n, p) = match pl.definition() {
        PlaneDef::Through([p, q, r]) => {
            let p = qp(p);
            (qcross(&qsub(&qp(q), &p), &qsub(&qp(r), &p)), p)
        }
        PlaneDef::Edge { p, q, k, flip } => {
            let p = qp(p);
            let w = qsub(&qp(q), &p);
            let z = Q::zero();
            let n = match k {
                0 => [z, w[2].clone(), -&w[1]],
                1 => [-&w[2], z, w[0].clone()],
                _ => [w[1].clone(), -&w[0], z],
            };
            (if flip { n.map(|x| -x) } else { n }, p)
        }
        PlaneDef::Along { p, q, d } => {
            let p = qp(p);
            (qcross(&qsub(&qp(q), &p), &qp(d)), p)
        }
        PlaneDef::PointNormal { p, n } => (qp(n), qp(p)),
    };
    let d = -(&n[0] * &p[0] + &n[1] * &p[1] + &n[2] * &p[2]);
    let [a, b, c] = n;
    if pl.is_flipped() {
        [-a, -b, -c, -d]
    } else {
        [a, b, c, d]
    }
}

/// The intersection point of three planes, solved independently of the kernel (Cramer's
/// rule in big rationals).
pub fn intersect(p: &[Plane; 3]) -> P3 {
    let rows: Vec<[Q; 4]> = p
        .iter()
        .map(|pl| {
            let [a, b, c, d] = coefficients(pl);
            [a, b, c, -d]
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

/// The exact vertices of a kernel polygon, in world coordinates.
pub fn exact_vertices(poly: &ExactPolygon) -> Vec<P3> {
    (0..poly.len())
        .map(|i| intersect(&poly.vertex_planes(i)))
        .collect()
}

/// An exact run: the order, its fragments as exact polygons (grid coordinates), and a
/// checker for the eye.
pub struct ExactRun {
    /// The order.
    pub ordered: Ordered,
    /// Exact fragments in painting order.
    pub fragments: Vec<ExactFragment>,
    /// The checker for this view.
    pub checker: Checker,
}

/// Orders `scene` with the exact kernel and prepares the exact check; panics when the
/// scene cannot be ordered (see [`try_exact_run`]).
pub fn exact_run(scene: &Scene, camera: &Camera, opts: &OrderOptions) -> ExactRun {
    try_exact_run(scene, camera, opts).expect("orderable")
}

/// [`exact_run`], returning the ordering's error for scenes or cameras it refuses.
pub fn try_exact_run(
    scene: &Scene,
    camera: &Camera,
    opts: &OrderOptions,
) -> Result<ExactRun, OrderError> {
    let kernel = ExactKernel::new();
    let (ordered, polys) = order_polygons(&kernel, scene, camera, opts)?;
    let fragments = ordered
        .fragments
        .iter()
        .zip(&polys)
        .map(|(f, p)| ExactFragment {
            face: f.face,
            verts: exact_vertices(p),
        })
        .collect();
    let fwd: DVec3 = ordered.camera.forward();
    // A parallel projection is checked along its own direction, exactly.
    let checker = match ordered.camera.viewpoint() {
        Ok(Viewpoint::Toward(d)) => Checker::toward(d.to_array()),
        _ => Checker::new(qp(camera.eye.to_array()), fwd.to_array()),
    };
    Ok(ExactRun {
        ordered,
        fragments,
        checker,
    })
}
