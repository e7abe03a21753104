//! Pixel-centre sampling, the top-left rule, perspective-correct depth, near-plane
//! clipping.

mod common;

use common::{cam, poly, scene_with};
use glam::{DVec3, DVec4};
use limn_scene::Camera;
use limn_zbuffer::{
    compare, default_band_tolerance, edge_band, rasterize_ids, render, scene_edges, IdImage,
    Method, RenderOptions, NO_FACE,
};

fn coverage(img: &IdImage) -> Vec<bool> {
    img.ids.iter().map(|&i| i != NO_FACE).collect()
}

/// Two triangles sharing an edge through many pixel centres (diagonal, horizontal,
/// vertical): every centre is covered by exactly one of them.
#[test]
fn shared_edges_cover_each_centre_exactly_once_in_2d() {
    let (w, h) = (40, 36);
    // (a, b) is the shared edge; c and d lie on either side.
    let cases: [[[f64; 2]; 4]; 4] = [
        [[2.5, 2.5], [30.5, 30.5], [30.5, 2.5], [2.5, 30.5]], // diagonal through centres
        [[1.0, 10.5], [38.0, 10.5], [20.0, 1.0], [20.0, 30.0]], // horizontal through centres
        [[12.5, 0.3], [12.5, 35.0], [1.0, 17.0], [39.0, 17.0]], // vertical through centres
        [[3.5, 4.5], [33.5, 28.5], [35.0, 2.0], [1.0, 33.0]], // slope 4/5 through centres
    ];
    for (k, [a, b, c, d]) in cases.into_iter().enumerate() {
        for (p, q) in [(a, b), (b, a)] {
            let one = rasterize_ids(&[(vec![p, q, c], 1)], w, h);
            let two = rasterize_ids(&[(vec![q, p, d], 2)], w, h);
            let both = rasterize_ids(&[(vec![c, q, d, p], 3)], w, h);
            let (c1, c2, cb) = (coverage(&one), coverage(&two), coverage(&both));
            let mut on_edge = 0;
            for i in 0..c1.len() {
                assert!(!(c1[i] && c2[i]), "case {k}: pixel {i} covered twice");
                assert_eq!(c1[i] || c2[i], cb[i], "case {k}: pixel {i}");
                let (x, y) = ((i % w as usize) as f64 + 0.5, (i / w as usize) as f64 + 0.5);
                let cross = (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]);
                if cross == 0.0 && cb[i] {
                    on_edge += 1;
                }
            }
            assert!(
                on_edge >= 5,
                "case {k}: only {on_edge} centres on the shared edge"
            );
        }
    }
}

/// Six triangles around a vertex placed exactly on a pixel centre: the centre goes to
/// exactly one of them.
#[test]
fn a_vertex_on_a_centre_goes_to_one_triangle() {
    let c = [10.5, 10.5];
    let ring: Vec<[f64; 2]> = (0..6)
        .map(|k| {
            let a = k as f64 * std::f64::consts::PI / 3.0 + 0.1;
            [10.5 + 8.0 * a.cos(), 10.5 + 8.0 * a.sin()]
        })
        .collect();
    let mut hits = vec![0; 21 * 21];
    for k in 0..6 {
        let img = rasterize_ids(&[(vec![c, ring[k], ring[(k + 1) % 6]], k as u32)], 21, 21);
        for (i, &id) in img.ids.iter().enumerate() {
            hits[i] += (id != NO_FACE) as u32;
        }
    }
    assert_eq!(hits[10 * 21 + 10], 1);
    assert!(hits.iter().all(|&n| n <= 1));
}

/// The same through the 3D pipeline: a square split into four triangles meeting at its
/// centre, seen head-on so that the centre falls on a pixel centre: every method covers
/// each centre once and agrees with ray casting outside the edge band.
#[test]
fn shared_edges_in_3d_are_watertight() {
    let mut s = scene_with(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    let corners =
        [(1.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0)].map(|(x, y)| DVec3::new(x, y, 0.0));
    for k in 0..4 {
        poly(
            &mut s,
            &[DVec3::ZERO, corners[k], corners[(k + 1) % 4]],
            (k % 2) as u32,
        );
    }
    let camera = cam(DVec3::new(0.0, 0.0, 4.0), 65, 65);
    let opts = RenderOptions::default();
    let z = render(&s, &camera, Method::ZBuffer, &opts).unwrap();
    let a = render(&s, &camera, Method::ABuffer, &opts).unwrap();
    assert_eq!(
        a.stats.fragments as usize,
        z.ids.covered(),
        "no centre covered twice"
    );
    assert_eq!(z.ids.get(32, 32).map(|id| id != NO_FACE), Some(true));
    // No hole: the covered pixels form the square's full set of centres.
    let xs: Vec<u32> = (0..65)
        .filter(|&x| z.ids.get(x, 32) != Some(NO_FACE))
        .collect();
    let ys: Vec<u32> = (0..65)
        .filter(|&y| z.ids.get(32, y) != Some(NO_FACE))
        .collect();
    assert_eq!(z.ids.covered(), xs.len() * ys.len());
    let band = edge_band(
        &scene_edges(&s, &camera, &opts).unwrap(),
        65,
        65,
        default_band_tolerance(65, 65),
    );
    for m in [Method::ScanLine, Method::Warnock, Method::RayCast] {
        let r = render(&s, &camera, m, &opts).unwrap();
        let c = compare(&z.ids, &r.ids, Some(&band));
        assert_eq!(c.mismatches_outside_band, 0, "{m}: {c:?}");
    }
}

/// Four quads meeting along the x and y axes, seen head-on: the axes fall exactly on a
/// column and a row of pixel centres, in pixel space and for the rays alike, so every
/// centre there is decided by the top-left rule, and all methods must decide it the
/// same way (the one to the right of a vertical edge, below a horizontal one).
#[test]
fn top_left_ties_are_decided_alike_by_every_method() {
    let mut s = scene_with(&[
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 1.0, 0.0],
    ]);
    for (k, (sx, sy)) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
        .into_iter()
        .enumerate()
    {
        let q = [(0.0, 0.0), (sx, 0.0), (sx, sy), (0.0, sy)].map(|(x, y)| DVec3::new(x, y, 0.0));
        poly(&mut s, &q, k as u32);
    }
    let camera = cam(DVec3::new(0.0, 0.0, 4.0), 65, 65);
    let opts = RenderOptions::default();
    let z = render(&s, &camera, Method::ZBuffer, &opts).unwrap();
    // Face 0 is the quad at x > 0, y > 0 (upper right on screen).
    assert_eq!(
        z.ids.get(32, 32),
        Some(3),
        "the centre goes right and down: lower right"
    );
    assert_eq!(z.ids.get(32, 20), Some(0), "vertical edge: the right side");
    assert_eq!(
        z.ids.get(20, 32),
        Some(2),
        "horizontal edge: the lower side"
    );
    for m in Method::ALL {
        let r = render(&s, &camera, m, &opts).unwrap();
        let c = compare(&z.ids, &r.ids, None);
        assert_eq!(c.mismatches, 0, "{m}: {c:?}");
    }
}

/// Window depth at each pixel equals the depth of the point where the pixel centre's
/// ray meets the face's plane; interpolating eye depth linearly on screen would not.
#[test]
fn depth_is_perspective_correct() {
    let mut s = scene_with(&[[0.5, 0.5, 0.5]]);
    // A steep quad receding from the camera.
    let q = [
        (-1.0, -1.0, 1.0),
        (1.0, -1.0, 1.0),
        (1.0, 1.0, -6.0),
        (-1.0, 1.0, -6.0),
    ]
    .map(|(x, y, z)| DVec3::new(x, y, z));
    poly(&mut s, &q, 0);
    let camera = Camera::new(
        DVec3::new(0.0, 0.2, 3.0),
        DVec3::new(0.0, 0.0, -1.0),
        48,
        48,
    );
    let opts = RenderOptions {
        near_far: Some((0.5, 20.0)),
        ..RenderOptions::default()
    };
    let vp = camera.view_projection(0.5, 20.0);
    let inv = vp.inverse();
    let normal = (q[1] - q[0]).cross(q[3] - q[0]);
    let mut worst_naive: f64 = 0.0;
    for m in [
        Method::ZBuffer,
        Method::ScanLine,
        Method::Warnock,
        Method::RayCast,
    ] {
        let r = render(&s, &camera, m, &opts).unwrap();
        assert!(r.ids.covered() > 500);
        for j in 0..48u32 {
            for i in 0..48u32 {
                if r.ids.get(i, j) == Some(NO_FACE) {
                    continue;
                }
                let nx = (i as f64 + 0.5) / 24.0 - 1.0;
                let ny = 1.0 - (j as f64 + 0.5) / 24.0;
                let un = |z: f64| {
                    let p = inv * DVec4::new(nx, ny, z, 1.0);
                    p.truncate() / p.w
                };
                let (pn, pf) = (un(-1.0), un(1.0));
                let t = normal.dot(q[0] - pn) / normal.dot(pf - pn);
                let c = vp * (pn + (pf - pn) * t).extend(1.0);
                let d = (c.z / c.w + 1.0) * 0.5;
                let got = r.depth.get(i, j).unwrap();
                assert!((got - d).abs() < 1e-12, "{m} at {i},{j}: {got} vs {d}");
                // Linear-in-screen eye depth: what an affine interpolation would give.
                worst_naive = worst_naive.max((c.w - affine_w(&vp, &q, nx, ny)).abs());
            }
        }
    }
    assert!(
        worst_naive > 0.05,
        "affine eye depth should be visibly wrong ({worst_naive})"
    );
}

/// Eye depth `w` interpolated affinely in screen space over the quad's two triangles.
fn affine_w(vp: &glam::DMat4, q: &[DVec3; 4], nx: f64, ny: f64) -> f64 {
    let p: Vec<DVec4> = q.iter().map(|&v| *vp * v.extend(1.0)).collect();
    let sc: Vec<(f64, f64, f64)> = p.iter().map(|c| (c.x / c.w, c.y / c.w, c.w)).collect();
    for tri in [[0, 1, 2], [0, 2, 3]] {
        let [a, b, c] = tri.map(|k| sc[k]);
        let det = (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1);
        let u = ((nx - a.0) * (c.1 - a.1) - (c.0 - a.0) * (ny - a.1)) / det;
        let v = ((b.0 - a.0) * (ny - a.1) - (nx - a.0) * (b.1 - a.1)) / det;
        if u >= -1e-9 && v >= -1e-9 && u + v <= 1.0 + 1e-9 {
            return a.2 + u * (b.2 - a.2) + v * (c.2 - a.2);
        }
    }
    f64::NAN
}

/// A ground quad running from far in front to far behind the camera: clipped at the
/// near plane, nothing projected through the eye, the same pixels as ray casting.
#[test]
fn ground_running_behind_the_camera_is_clipped() {
    let mut s = scene_with(&[[0.3, 0.6, 0.3]]);
    let g = [(-10.0, -50.0), (10.0, -50.0), (10.0, 50.0), (-10.0, 50.0)]
        .map(|(x, z)| DVec3::new(x, -1.0, z));
    poly(&mut s, &g, 0);
    // A triangle entirely behind the eye, which must never show.
    poly(
        &mut s,
        &[
            DVec3::new(-5.0, -5.0, 3.0),
            DVec3::new(5.0, -5.0, 3.0),
            DVec3::new(0.0, 5.0, 3.0),
        ],
        0,
    );
    let camera = Camera::new(DVec3::ZERO, DVec3::new(0.0, -0.3, -1.0), 64, 48);
    for near_far in [None, Some((0.05, 100.0)), Some((4.0, 100.0))] {
        let opts = RenderOptions {
            near_far,
            ..RenderOptions::default()
        };
        let r = render(&s, &camera, Method::RayCast, &opts).unwrap();
        let edges = scene_edges(&s, &camera, &opts).unwrap();
        let band = edge_band(&edges, 64, 48, default_band_tolerance(64, 48));
        for m in [
            Method::ZBuffer,
            Method::ScanLine,
            Method::ABuffer,
            Method::Warnock,
        ] {
            let z = render(&s, &camera, m, &opts).unwrap();
            assert!(z.stats.clipped_triangles > 0);
            let c = compare(&r.ids, &z.ids, Some(&band));
            assert_eq!(c.mismatches_outside_band, 0, "{m} {near_far:?}: {c:?}");
            assert!(z
                .depth
                .depths
                .iter()
                .all(|&d| d.is_infinite() || (0.0..=1.0).contains(&d)));
            // Only the ground shows, and never above the horizon.
            assert!(z.ids.ids.iter().all(|&id| id == 0 || id == NO_FACE));
            for y in 0..6 {
                for x in 0..64 {
                    assert_eq!(z.ids.get(x, y), Some(NO_FACE), "{m} above the horizon");
                }
            }
        }
        let bottom = (0..64).filter(|&x| r.ids.get(x, 47) == Some(0)).count();
        if let Some((4.0, _)) = near_far {
            // The ground nearer than 4 is cut away: the bottom row shows background.
            assert_eq!(bottom, 0);
        } else {
            assert_eq!(bottom, 64);
        }
    }
}

/// A painter's picture made of the same projected corners (`Camera::project_with`), in
/// depth order, matches the z-buffer on every pixel, not just outside the band: the
/// references project exactly as `project_with` and sample exactly like
/// `rasterize_ids`.
#[test]
fn painter_raster_matches_the_zbuffer_exactly() {
    let scene = common::layered_triangles(&mut common::Lcg(11), 30, 0.05);
    let camera = cam(DVec3::new(0.8, -0.6, 4.0), 96, 72);
    let opts = RenderOptions::default();
    let (near, far) = camera.near_far(&scene);
    let vp = camera.view_projection(near, far);
    let mut order: Vec<usize> = (0..scene.faces.len()).collect();
    // Layers are flat to within a quarter gap: sort far to near by the first corner.
    order.sort_by(|&a, &b| {
        let za = scene.face_points(a as u32)[0].z;
        let zb = scene.face_points(b as u32)[0].z;
        za.total_cmp(&zb)
    });
    let polys: Vec<(Vec<[f64; 2]>, u32)> = order
        .iter()
        .map(|&f| {
            let pts = scene
                .face_points(f as u32)
                .iter()
                .map(|&p| {
                    let q = camera.project_with(&vp, p);
                    [q.x, q.y]
                })
                .collect();
            (pts, f as u32)
        })
        .collect();
    let painted = rasterize_ids(&polys, 96, 72);
    let z = render(&scene, &camera, Method::ZBuffer, &opts).unwrap();
    assert!(z.ids.covered() > 1000);
    assert_eq!(compare(&z.ids, &painted, None).mismatches, 0);
}
