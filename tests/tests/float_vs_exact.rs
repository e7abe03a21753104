//! What exactness buys: an epsilon kernel's decisions break down on hard cases (a tiny
//! crossing angle, geometry far from the origin), while the exact kernel stays right
//! (exact ray casting decides).

use glam::DVec3;
use limn_depthsort::{order_with, OrderOptions, SortMode};
use limn_kernel::Kernel;
use limn_kernel::{ExactKernel, FloatKernel};
use limn_tests::corpus::{self, transformed, Case};
use limn_zbuffer::{
    compare, default_band_tolerance, edge_band, rasterize_ids, render, scene_edges, Method,
    RenderOptions,
};

fn mismatches<K: Kernel>(kernel: &K, case: &Case, sort: SortMode) -> usize {
    let o = order_with(
        kernel,
        &case.scene,
        &case.camera,
        &OrderOptions {
            sort,
            ..OrderOptions::default()
        },
    )
    .expect("orderable");
    let c = &o.camera;
    let (w, h) = (c.width, c.height);
    let polys: Vec<(Vec<[f64; 2]>, u32)> = o
        .fragments
        .iter()
        .map(|f| (f.points.clone(), f.face))
        .collect();
    let ropts = RenderOptions {
        near_far: Some((o.near, o.far)),
        ..RenderOptions::default()
    };
    let reference = render(&case.scene, c, Method::RayCast, &ropts).expect("renders");
    let mut edges = scene_edges(&case.scene, c, &ropts).expect("edges");
    for (p, _) in &polys {
        for i in 0..p.len() {
            edges.push((p[i], p[(i + 1) % p.len()]));
        }
    }
    let band = edge_band(&edges, w, h, default_band_tolerance(w, h));
    compare(&rasterize_ids(&polys, w, h), &reference.ids, Some(&band)).mismatches_outside_band
}

const MODES: [SortMode; 3] = [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell];

fn exact_kernel(_case: &Case) -> ExactKernel {
    ExactKernel::new()
}

#[test]
fn an_epsilon_kernel_misses_the_tiny_crossing_and_the_exact_kernel_does_not() {
    // An epsilon of 1e-6 of the scene (gl2ps uses 5e-3 window units in single
    // precision) takes faces crossing at 1e-7 rad for coplanar.
    let case = corpus::tiny_angle();
    let float = FloatKernel::with_epsilon(2e-6).expect("epsilon");
    for sort in MODES {
        let bad = mismatches(&float, &case, sort);
        assert!(bad > 100, "{}: only {bad} wrong pixels", sort.name());
        assert_eq!(
            mismatches(&exact_kernel(&case), &case, sort),
            0,
            "{}",
            sort.name()
        );
    }
}

#[test]
fn far_from_the_origin_the_default_float_kernel_slips_and_the_exact_kernel_does_not() {
    let off = DVec3::new(1e9, -5e8, 2.5e8);
    let cases = [
        transformed(&corpus::cyclic_quads(), "cyclic@1e9", move |p| p + off),
        transformed(&corpus::woven_grid(), "woven@1e9", move |p| p + off),
    ];
    let mut float_bad = 0;
    for case in &cases {
        let (lo, hi) = case.scene.bounds().expect("faces");
        let float = FloatKernel::new(lo, hi).expect("kernel");
        for sort in MODES {
            float_bad += mismatches(&float, case, sort);
            assert_eq!(
                mismatches(&exact_kernel(case), case, sort),
                0,
                "{} / {}",
                case.name,
                sort.name()
            );
        }
    }
    assert!(
        float_bad > 0,
        "the float kernel was expected to slip somewhere"
    );
}
