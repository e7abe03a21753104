//! Depth fighting: coarse depth formats get pixels wrong where exact ray casting and an
//! f64 z-buffer do not.

mod common;

use common::{poly, scene_with};
use glam::DVec3;
use limn_scene::{Camera, Scene};
use limn_zbuffer::{
    compare, default_band_tolerance, edge_band, render, scene_edges, DepthFormat, IdImage, Mask,
    Method, RenderOptions, NO_FACE,
};

const W: u32 = 64;

fn band(scene: &Scene, camera: &Camera, opts: &RenderOptions) -> Mask {
    let e = scene_edges(scene, camera, opts).unwrap();
    edge_band(&e, W, W, default_band_tolerance(W, W))
}

/// Mismatches outside the band for each depth format, and for ray casting.
fn wrong_pixels(
    scene: &Scene,
    camera: &Camera,
    near_far: Option<(f64, f64)>,
    truth: &IdImage,
) -> (Vec<usize>, usize) {
    let mut per_format = Vec::new();
    let base = RenderOptions {
        near_far,
        ..RenderOptions::default()
    };
    let band = band(scene, camera, &base);
    for depth in DepthFormat::ALL {
        let opts = RenderOptions {
            depth,
            ..base.clone()
        };
        for m in [Method::ZBuffer, Method::ScanLine] {
            let r = render(scene, camera, m, &opts).unwrap();
            let c = compare(truth, &r.ids, Some(&band));
            if m == Method::ZBuffer {
                per_format.push(c.mismatches_outside_band);
            }
        }
    }
    let r = render(scene, camera, Method::RayCast, &base).unwrap();
    (
        per_format,
        compare(truth, &r.ids, Some(&band)).mismatches_outside_band,
    )
}

/// Two unit squares crossing at 1e-7 rad along a line that falls between pixel
/// centres. With a near plane close to the eye (0.01, far 100) every depth difference
/// is below what f32, 24-bit and 16-bit depth can tell apart, and the tie goes to the
/// later face on the wrong side; f64 and exact ray casting see the crossing.
#[test]
fn crossing_at_1e7_radians() {
    let mut s = scene_with(&[[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
    let camera = Camera::new(DVec3::new(0.0, 0.0, 3.0), DVec3::ZERO, W, W);
    // World x on the z = 0 plane of a pixel column boundary (pixel x = 40.25).
    let half = 3.0 * (22.5f64).to_radians().tan();
    let xc = (40.25 / W as f64 * 2.0 - 1.0) * half;
    let t = (1e-7f64).tan();
    let a =
        [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(x, y)| DVec3::new(x, y, 0.0));
    let b = a.map(|p| DVec3::new(p.x, p.y, (p.x - xc) * t));
    poly(&mut s, &a, 0);
    poly(&mut s, &b, 1);
    // Truth: B (later, tilted towards the eye for x > xc) right of column 40.25.
    let r = render(&s, &camera, Method::ZBuffer, &RenderOptions::default()).unwrap();
    let mut truth = IdImage::new(W, W);
    for y in 0..W {
        for x in 0..W {
            if r.ids.get(x, y) != Some(NO_FACE) {
                truth.ids[(y * W + x) as usize] = if x as f64 + 0.5 > 40.25 { 1 } else { 0 };
            }
        }
    }
    assert!(truth.covered() > 1000);
    let (formats, raycast) = wrong_pixels(&s, &camera, Some((0.01, 100.0)), &truth);
    assert_eq!(raycast, 0, "ray casting is exact");
    assert_eq!(formats[0], 0, "f64 resolves the crossing");
    for (k, &wrong) in formats.iter().enumerate().skip(1) {
        assert!(
            wrong > 200,
            "{:?} should fight: {wrong}",
            DepthFormat::ALL[k]
        );
    }
}

/// Two parallel squares 100 units apart, 1e7 away from the eye. With near = 1 the
/// window depths differ by about 1e-12: f32, 24-bit and 16-bit depth store the same
/// value and the later (farther) square wins everywhere; f64 and ray casting do not.
/// Choosing near and far from the scene's bounds fixes even 16-bit depth.
#[test]
fn scene_offset_by_1e7() {
    let mut s = scene_with(&[[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
    let z = -1.0e7;
    let sq =
        |r: f64, z: f64| [(-r, -r), (r, -r), (r, r), (-r, r)].map(|(x, y)| DVec3::new(x, y, z));
    poly(&mut s, &sq(2.0e6, z), 0); // near, first
    poly(&mut s, &sq(3.5e6, z - 100.0), 1); // far, later, larger
    let camera = Camera::new(DVec3::ZERO, DVec3::new(0.0, 0.0, -1.0), W, W);
    // Truth from geometry: the near square covers |ndc| < 2e6 / (1e7 · tan 22.5°).
    let lim = 2.0e6 / (1.0e7 * (22.5f64).to_radians().tan());
    let lim_far = 3.5e6 / ((1.0e7 + 100.0) * (22.5f64).to_radians().tan());
    let mut truth = IdImage::new(W, W);
    for y in 0..W {
        for x in 0..W {
            let nx = (x as f64 + 0.5) / W as f64 * 2.0 - 1.0;
            let ny = 1.0 - (y as f64 + 0.5) / W as f64 * 2.0;
            let m = nx.abs().max(ny.abs());
            truth.ids[(y * W + x) as usize] = if m < lim {
                0
            } else if m < lim_far {
                1
            } else {
                NO_FACE
            };
        }
    }
    assert!(truth.ids.iter().filter(|&&i| i == 0).count() > 500);
    let (formats, raycast) = wrong_pixels(&s, &camera, Some((1.0, 2.0e7)), &truth);
    assert_eq!(raycast, 0);
    assert_eq!(formats[0], 0);
    for (k, &wrong) in formats.iter().enumerate().skip(1) {
        assert!(
            wrong > 500,
            "{:?} should fight: {wrong}",
            DepthFormat::ALL[k]
        );
    }
    // Near and far chosen from the scene: every format is right.
    let (formats, raycast) = wrong_pixels(&s, &camera, None, &truth);
    assert_eq!(raycast, 0);
    assert_eq!(formats, vec![0; 4]);
}
