//! Bad and awkward input: errors where the input is invalid, a picture otherwise.

mod common;

use common::{cam, layered_triangles, poly, scene_with, Lcg};
use glam::DVec3;
use limn_scene::{Camera, Face, Scene, SceneError};
use limn_zbuffer::{
    compare, default_band_tolerance, diff_png, edge_band, rasterize_ids, render, scene_edges,
    Method, RenderOptions, ZError, MAX_COORD, NO_FACE,
};

fn all_methods(s: &Scene, c: &Camera, o: &RenderOptions) -> Vec<limn_zbuffer::Raster> {
    Method::ALL
        .iter()
        .map(|&m| render(s, c, m, o).unwrap())
        .collect()
}

#[test]
fn invalid_input_is_an_error_not_a_panic() {
    let mut s = scene_with(&[[1.0; 3]]);
    poly(&mut s, &[DVec3::ZERO, DVec3::X, DVec3::Y], 0);
    let c = cam(DVec3::new(0.0, 0.0, 3.0), 16, 16);
    let o = RenderOptions::default();
    let mut bad = s.clone();
    bad.vertices[1].x = f64::NAN;
    for m in Method::ALL {
        assert_eq!(
            render(&bad, &c, m, &o).unwrap_err(),
            ZError::Scene(SceneError::NonFinite("vertex"))
        );
    }
    let mut bad = s.clone();
    bad.faces.push(Face {
        vertices: Box::new([0, 1, 9]),
        normals: None,
        texcoords: None,
        colors: None,
        material: 0,
        object: 0,
    });
    assert!(matches!(
        render(&bad, &c, Method::ZBuffer, &o),
        Err(ZError::Scene(_))
    ));
    let mut huge = s.clone();
    huge.vertices[0].z = MAX_COORD * 4.0;
    assert!(matches!(
        render(&huge, &c, Method::ZBuffer, &o),
        Err(ZError::OutOfRange { .. })
    ));
    // Any tiny coordinate is accepted (decided with big integers).
    let mut tiny = s.clone();
    tiny.vertices[0].z = 1e-200;
    assert!(render(&tiny, &c, Method::RayCast, &o).is_ok());
    assert!(render(&tiny, &c, Method::ZBuffer, &o).is_ok());
    for nf in [
        (0.0, 1.0),
        (2.0, 1.0),
        (1.0, f64::INFINITY),
        (f64::NAN, 1.0),
    ] {
        let o = RenderOptions {
            near_far: Some(nf),
            ..o.clone()
        };
        assert!(matches!(
            render(&s, &c, Method::ZBuffer, &o),
            Err(ZError::BadDepthRange { .. })
        ));
    }
    let mut big = c;
    (big.width, big.height) = (20000, 20000);
    assert_eq!(
        render(&s, &big, Method::ZBuffer, &o).unwrap_err(),
        ZError::TooManyPixels(20000, 20000)
    );
    let mut flat = c;
    flat.target = flat.eye;
    assert!(matches!(
        render(&s, &flat, Method::ZBuffer, &o),
        Err(ZError::Camera(_))
    ));
}

#[test]
fn degenerate_faces_draw_nothing_and_break_nothing() {
    let mut s = scene_with(&[[1.0; 3]]);
    let p = DVec3::new(0.2, 0.1, 0.0);
    poly(&mut s, &[p, p, p], 0); // a point
    poly(&mut s, &[DVec3::ZERO, DVec3::X, DVec3::X * 2.0], 0); // collinear
    poly(&mut s, &[DVec3::ZERO, DVec3::X, DVec3::X, DVec3::ZERO], 0); // zero area quad
    poly(
        &mut s,
        &[DVec3::ZERO, DVec3::Z, DVec3::new(0.0, 0.0, 2.0), DVec3::X],
        0,
    ); // edge-on
    let c = cam(DVec3::new(3.0, 0.0, 0.0), 32, 32);
    for r in all_methods(&s, &c, &RenderOptions::default()) {
        assert_eq!(r.ids.covered(), 0);
        assert!(r.depth.depths.iter().all(|d| d.is_infinite()));
    }
    // An empty scene renders the background.
    let e = scene_with(&[]);
    for r in all_methods(&e, &c, &RenderOptions::default()) {
        assert_eq!(r.ids.covered(), 0);
        assert_eq!(r.color.get(3, 3), Some([255; 3]));
    }
}

#[test]
fn faces_behind_the_eye_never_show() {
    let mut s = scene_with(&[[1.0; 3]]);
    // Behind, straddling the eye plane, and huge around the eye.
    poly(
        &mut s,
        &[
            DVec3::new(-1.0, -1.0, 5.0),
            DVec3::new(1.0, -1.0, 5.0),
            DVec3::new(0.0, 1.0, 5.0),
        ],
        0,
    );
    poly(
        &mut s,
        &[
            DVec3::new(-1e6, -1e6, 3.0),
            DVec3::new(1e6, -1e6, 3.0),
            DVec3::new(0.0, 1e6, 3.0),
        ],
        0,
    );
    let c = cam(DVec3::new(0.0, 0.0, 3.0), 32, 32);
    for r in all_methods(&s, &c, &RenderOptions::default()) {
        assert_eq!(r.ids.covered(), 0);
    }
}

#[test]
fn non_convex_faces_keep_their_notch() {
    // An L-shaped face and the same area as two rectangles.
    let l = [
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 2.0),
        (0.0, 2.0),
    ]
    .map(|(x, y)| DVec3::new(x - 1.0, y - 1.0, 0.0));
    let mut a = scene_with(&[[1.0; 3]]);
    poly(&mut a, &l, 0);
    // Start the outline at the reflex corner too.
    let mut rot = l;
    rot.rotate_left(3);
    let mut b = scene_with(&[[1.0; 3]]);
    poly(&mut b, &rot, 0);
    let c = cam(DVec3::new(0.3, 0.2, 4.0), 48, 48);
    let o = RenderOptions::default();
    let band = edge_band(
        &scene_edges(&a, &c, &o).unwrap(),
        48,
        48,
        default_band_tolerance(48, 48),
    );
    let vp = c.view_projection(1.0, 10.0);
    let notch = c.project_with(&vp, DVec3::new(0.5, 0.5, 0.0));
    let arm = c.project_with(&vp, DVec3::new(0.5, -0.5, 0.0));
    for m in Method::ALL {
        for s in [&a, &b] {
            let r = render(s, &c, m, &o).unwrap();
            assert_eq!(
                r.ids.get(notch.x as u32, notch.y as u32),
                Some(NO_FACE),
                "{m}"
            );
            assert_eq!(r.ids.get(arm.x as u32, arm.y as u32), Some(0), "{m}");
        }
        let (ra, rb) = (
            render(&a, &c, m, &o).unwrap(),
            render(&b, &c, m, &o).unwrap(),
        );
        assert_eq!(
            compare(&ra.ids, &rb.ids, Some(&band)).mismatches_outside_band,
            0
        );
    }
}

/// Coplanar overlapping faces: only exact ray casting can tell their depths are equal;
/// it gives the overlap to the later face.
#[test]
fn coplanar_faces_go_to_the_later_face() {
    let mut s = scene_with(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    let n = DVec3::new(0.3, 0.5, 1.0);
    let (u, v) = (n.any_orthonormal_pair().0, n.any_orthonormal_pair().1);
    let on = |x: f64, y: f64| u * x + v * y;
    poly(&mut s, &[on(-1.0, -1.0), on(1.0, -0.9), on(0.1, 1.0)], 0);
    poly(&mut s, &[on(-0.9, 0.8), on(-0.7, -0.95), on(0.9, 0.1)], 1);
    let c = cam(n * 4.0 + DVec3::new(0.2, -0.1, 0.0), 64, 64);
    let r = render(&s, &c, Method::RayCast, &RenderOptions::default()).unwrap();
    let b = render(&s, &c, Method::ZBuffer, &RenderOptions::default()).unwrap();
    assert!(r.stats.exact_fallbacks > 0, "ties need exact arithmetic");
    let alone = {
        let mut t = s.clone();
        t.faces.truncate(1);
        t.faces.push(s.faces[1].clone());
        t.faces.swap(0, 1);
        render(&t, &c, Method::RayCast, &RenderOptions::default()).unwrap()
    };
    // Wherever face 1 is drawn alone (first in `t`, id 0 there), ray casting shows 1.
    let band = edge_band(
        &scene_edges(&s, &c, &RenderOptions::default()).unwrap(),
        64,
        64,
        default_band_tolerance(64, 64),
    );
    let mut overlap = 0;
    for i in 0..r.ids.ids.len() {
        if alone.ids.ids[i] == 0 && !band.bits[i] {
            assert_eq!(r.ids.ids[i], 1);
            overlap += 1;
        }
    }
    assert!(overlap > 100);
    assert!(b.ids.covered() > 0);
}

/// The same scene scaled by a power of two, moved far away, or with its faces in
/// another order gives the same picture (outside the band).
#[test]
fn transformed_scenes_give_the_same_picture() {
    let base = layered_triangles(&mut Lcg(5), 12, 0.1);
    let camera = cam(DVec3::new(1.0, 0.7, 4.0), 64, 48);
    let o = RenderOptions::default();
    let band = edge_band(
        &scene_edges(&base, &camera, &o).unwrap(),
        64,
        48,
        default_band_tolerance(64, 48),
    );
    for m in [Method::ZBuffer, Method::RayCast] {
        let r0 = render(&base, &camera, m, &o).unwrap();
        // Scaled by 2^20 (exact), camera too.
        let k = (1u64 << 20) as f64;
        let mut big = base.clone();
        big.vertices.iter_mut().for_each(|v| *v *= k);
        let mut bc = camera;
        bc.eye *= k;
        let r1 = render(&big, &bc, m, &o).unwrap();
        assert_eq!(
            compare(&r0.ids, &r1.ids, Some(&band)).mismatches_outside_band,
            0,
            "{m} scaled"
        );
        // Translated by 2^23 in every axis (exact for these coordinates' magnitudes).
        let t = DVec3::splat((1u64 << 23) as f64);
        let mut far = base.clone();
        far.vertices.iter_mut().for_each(|v| *v += t);
        let mut fc = camera;
        fc.eye += t;
        fc.target += t;
        let r2 = render(&far, &fc, m, &o).unwrap();
        let c = compare(&r0.ids, &r2.ids, Some(&band));
        assert_eq!(c.mismatches_outside_band, 0, "{m} translated: {c:?}");
        // Faces reversed: ids map back.
        let mut rev = base.clone();
        rev.faces.reverse();
        let n = rev.faces.len() as u32;
        let mut r3 = render(&rev, &camera, m, &o).unwrap();
        r3.ids
            .ids
            .iter_mut()
            .filter(|i| **i != NO_FACE)
            .for_each(|i| *i = n - 1 - *i);
        assert_eq!(
            compare(&r0.ids, &r3.ids, Some(&band)).mismatches_outside_band,
            0,
            "{m} reversed"
        );
    }
}

#[test]
fn painter_raster_handles_junk() {
    let polys = vec![
        (vec![[0.0, 0.0], [1e300, 0.0], [0.0, 1e300]], 0),
        (vec![[f64::NAN, 0.0], [5.0, 0.0], [0.0, 5.0]], 1),
        (vec![[1.0, 1.0], [2.0, 2.0]], 2),
        (vec![[-1e9, -1e9], [1e9, -1e9], [0.0, 1e9]], 3),
    ];
    let img = rasterize_ids(&polys, 20, 10);
    assert!(
        img.ids.iter().all(|&i| i == 3),
        "the last big triangle covers everything"
    );
    let empty = rasterize_ids(&polys, 0, 0);
    assert!(empty.ids.is_empty());
}

#[test]
fn pngs_are_written() {
    let s = layered_triangles(&mut Lcg(1), 5, 0.1);
    let c = cam(DVec3::new(0.0, 0.0, 4.0), 40, 30);
    let r = render(&s, &c, Method::ZBuffer, &RenderOptions::default()).unwrap();
    for bytes in [
        r.color.encode_png().unwrap(),
        r.depth.encode_png().unwrap(),
        r.ids.encode_png().unwrap(),
        diff_png(&r.ids, &r.ids, None).unwrap(),
    ] {
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    }
    let other = limn_zbuffer::IdImage::new(3, 3);
    assert!(matches!(
        diff_png(&r.ids, &other, None),
        Err(ZError::SizeMismatch(..))
    ));
    let dir = std::env::temp_dir().join("limn-zbuffer-test-missing-dir/x/y.png");
    assert!(matches!(r.color.save_png(&dir), Err(ZError::Io { .. })));
}

/// Lit faces get exactly `shade_face`'s colour.
#[test]
fn flat_colours_are_shade_face() {
    let mut s = Scene::default();
    s.add_material(limn_scene::Material::diffuse("d", [0.3, 0.6, 0.9]));
    s.add_object("o");
    poly(
        &mut s,
        &[
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.2),
            DVec3::new(0.0, 1.0, -0.3),
        ],
        0,
    );
    let q = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .map(|(x, y)| DVec3::new(x, y, -2.0 + 0.1 * x));
    poly(&mut s, &q, 0);
    let c = cam(DVec3::new(0.5, 0.4, 4.0), 40, 40);
    for m in Method::ALL {
        let r = render(&s, &c, m, &RenderOptions::default()).unwrap();
        for (i, &id) in r.ids.ids.iter().enumerate() {
            if id != NO_FACE && m != Method::ABuffer {
                let want = limn_zbuffer::rgb_to_u8(limn_scene::shade_face(&s, id, c.eye));
                assert_eq!(r.color.pixels[i], want);
            }
        }
        assert!(r.ids.ids.contains(&0) && r.ids.ids.contains(&1));
    }
}

/// Smooth faces are shaded per pixel: Phong at the pixel's world point, Gouraud by
/// the corners' colours; flat faces keep `shade_face`.
#[test]
fn smooth_faces_are_shaded_per_pixel() {
    smooth_per_pixel(Camera::new(
        glam::DVec3::new(0.0, 0.0, 4.0),
        glam::DVec3::ZERO,
        64,
        64,
    ));
}

/// The same under a parallel projection: every pixel's ray runs along the view axis.
#[test]
fn smooth_faces_are_shaded_per_pixel_in_parallel_projection() {
    smooth_per_pixel(Camera::orthographic(
        glam::DVec3::new(0.0, 0.0, 4.0),
        glam::DVec3::ZERO,
        2.5,
        64,
        64,
    ));
}

fn smooth_per_pixel(cam: Camera) {
    use limn_scene::{
        polygon_normal, shade_sided_in_scene, shapes, FaceNormals, Light, LightKind, Material,
        Shading,
    };
    let mut s = Scene::default();
    let m = s.add_material(Material::glossy("g", [0.7, 0.3, 0.2], [0.8; 3], 40.0));
    let o = s.add_object("o");
    shapes::icosphere(&mut s, glam::DVec3::ZERO, 1.0, 1, m, o).unwrap();
    s.lights = vec![Light {
        kind: LightKind::Point(glam::DVec3::new(2.0, 3.0, 4.0)),
        color: [1.0; 3],
        shadows: false,
    }];
    let opts = RenderOptions::default();
    let (near, far) = cam.near_far(&s);
    let inv = cam.view_projection(near, far).inverse();
    let world_at = |s: &Scene, x: u32, y: u32, face: u32| {
        let ndc = glam::DVec4::new(
            (x as f64 + 0.5) / 32.0 - 1.0,
            1.0 - (y as f64 + 0.5) / 32.0,
            -1.0,
            1.0,
        );
        let q = inv * ndc;
        let on_near = q.truncate() / q.w;
        // From the eye through the pixel, or along the view axis without perspective.
        let (from, dir) = if cam.is_perspective() {
            (cam.eye, on_near - cam.eye)
        } else {
            (on_near, cam.forward())
        };
        let pts = s.face_points(face);
        let n = polygon_normal(&pts);
        let c = pts.iter().copied().sum::<glam::DVec3>() / 3.0;
        (from + dir * ((c - from).dot(n) / dir.dot(n)), n)
    };
    let mut distinct = std::collections::HashSet::new();
    for mode in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        s.shading = Some(mode);
        for method in [Method::ZBuffer, Method::RayCast] {
            let r = render(&s, &cam, method, &opts).unwrap();
            let mut checked = 0;
            for y in 0..64 {
                for x in 0..64 {
                    let id = r.ids.ids[(y * 64 + x) as usize];
                    if id == limn_zbuffer::NO_FACE {
                        continue;
                    }
                    let (p, side) = world_at(&s, x, y, id);
                    let fn_ = FaceNormals::new(&s, id).unwrap();
                    let want = match mode {
                        Shading::Flat => limn_scene::shade_face(&s, id, cam.eye),
                        Shading::Phong => shade_sided_in_scene(
                            &s,
                            &s.materials[0],
                            p,
                            fn_.at(p).unwrap(),
                            side,
                            cam.eye,
                        ),
                        Shading::Gouraud => {
                            let (idx, w) = fn_.weights(p).unwrap();
                            let cs: Vec<_> = idx
                                .iter()
                                .map(|&i| {
                                    shade_sided_in_scene(
                                        &s,
                                        &s.materials[0],
                                        fn_.corners()[i],
                                        fn_.normals()[i],
                                        side,
                                        cam.eye,
                                    )
                                })
                                .collect();
                            [0, 1, 2].map(|k| (0..3).map(|j| w[j] * cs[j][k]).sum::<f64>())
                        }
                    };
                    let got = r.color.pixels[(y * 64 + x) as usize];
                    let want = limn_zbuffer::rgb_to_u8(want);
                    for k in 0..3 {
                        assert!(
                            got[k].abs_diff(want[k]) <= 1,
                            "{mode:?} {method:?} ({x}, {y}): {got:?} vs {want:?}"
                        );
                    }
                    distinct.insert((mode, got));
                    checked += 1;
                }
            }
            assert!(checked > 1000);
        }
    }
    // Per-pixel shading shows many more colours than one per face.
    let count = |m: Shading| distinct.iter().filter(|(d, _)| *d == m).count();
    assert!(
        count(Shading::Phong) > 3 * count(Shading::Flat),
        "{} {}",
        count(Shading::Phong),
        count(Shading::Flat)
    );
}

#[test]
fn a_corner_given_twice_in_a_row_keeps_its_edge_an_edge() {
    // A square whose second corner is repeated: the edge from it to the third corner is an
    // edge of the face (in the edge band), the square's diagonal is not.
    let mut s = Scene::default();
    let m = s.add_material(limn_scene::Material::unlit("m", [0.5, 0.5, 0.5]));
    let o = s.add_object("square");
    for p in [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]] {
        s.add_vertex(DVec3::new(p[0], p[1], 0.0));
    }
    s.add_face(&[0, 1, 1, 2, 3], m, o).unwrap();
    let c = Camera::new(DVec3::new(0.5, 0.5, 3.0), DVec3::new(0.5, 0.5, 0.0), 64, 64);
    let edges = scene_edges(&s, &c, &RenderOptions::default()).unwrap();
    // Pixel x and y do not depend on the near and far planes.
    let vp = c.view_projection(1.0, 10.0);
    let project = |v: usize| {
        let p = c.project_with(&vp, s.vertices[v]);
        [p.x, p.y]
    };
    let has = |a: usize, b: usize| {
        let (pa, pb) = (project(a), project(b));
        edges
            .iter()
            .any(|&(x, y)| (x == pa && y == pb) || (x == pb && y == pa))
    };
    assert!(
        has(0, 1) && has(1, 2) && has(2, 3) && has(3, 0),
        "{edges:?}"
    );
    assert!(
        !has(0, 2) && !has(1, 3),
        "a diagonal is in the band: {edges:?}"
    );
}
