//! Exact shadows in object space: a cube over a plane under a directional and a point
//! light (the shadow's corners where projecting the cube by hand puts them), a face
//! split exactly once along a shadow boundary, faces turned away from a light.

use glam::{DMat3, DVec3};
use limn_depthsort::{order, Fragment, OrderOptions};
use limn_scene::{shapes, Camera, Light, LightKind, Material, Scene};

/// A ground square `[-4, 4]²` at `y = 0` facing up (face 0) and a unit cube floating
/// over it, `[-0.5, 0.5] × [0.5, 1.5] × [-0.5, 0.5]` (faces 1 to 6).
fn cube_over_ground(light: LightKind) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("grey", [0.8; 3]));
    let ground = s.add_object("ground");
    let corners = [[-4.0, 4.0], [4.0, 4.0], [4.0, -4.0], [-4.0, -4.0]];
    let pts: Vec<DVec3> = corners
        .iter()
        .map(|c| DVec3::new(c[0], 0.0, c[1]))
        .collect();
    s.add_polygon(&pts, m, ground).unwrap();
    let cube = s.add_object("cube");
    shapes::cuboid(
        &mut s,
        DVec3::new(-0.5, 0.5, -0.5),
        DVec3::new(0.5, 1.5, 0.5),
        DMat3::IDENTITY,
        m,
        cube,
    )
    .unwrap();
    s.lights = vec![Light {
        kind: light,
        color: [1.0; 3],
        shadows: true,
    }];
    s
}

fn camera() -> Camera {
    Camera::new(DVec3::new(3.0, 7.0, 9.0), DVec3::ZERO, 400, 300)
}

/// Twice the signed area of a polygon in the x-z plane.
fn area_xz(pts: &[DVec3]) -> f64 {
    let n = pts.len();
    (0..n)
        .map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % n]);
            a.x * b.z - b.x * a.z
        })
        .sum::<f64>()
        .abs()
        * 0.5
}

/// The ground's fragments in the shadow of light 0, and those lit by it.
fn ground_parts(frags: &[Fragment]) -> (Vec<&Fragment>, Vec<&Fragment>) {
    frags
        .iter()
        .filter(|f| f.face == 0)
        .partition(|f| f.shadowed.contains(0))
}

/// Whether `p` lies in the convex polygon `hull` (x-z, counter-clockwise or not) up to
/// `tol`.
fn inside_xz(p: DVec3, hull: &[[f64; 2]], tol: f64) -> bool {
    let n = hull.len();
    let sgn = |i: usize| {
        let (a, b) = (hull[i], hull[(i + 1) % n]);
        (b[0] - a[0]) * (p.z - a[1]) - (b[1] - a[1]) * (p.x - a[0])
    };
    let s: Vec<f64> = (0..n).map(sgn).collect();
    s.iter().all(|&v| v >= -tol) || s.iter().all(|&v| v <= tol)
}

/// The shadow on the ground is exactly `hull` (corners computed by hand): its area, its
/// corners among the shadowed fragments' vertices, and no vertex outside it.
fn assert_shadow_is(scene: &Scene, hull: &[[f64; 2]]) {
    let out = order(scene, &camera(), &OrderOptions::default()).unwrap();
    let (dark, lit) = ground_parts(&out.fragments);
    assert!(!dark.is_empty() && !lit.is_empty());
    let hull3: Vec<DVec3> = hull.iter().map(|c| DVec3::new(c[0], 0.0, c[1])).collect();
    let want = area_xz(&hull3);
    let got: f64 = dark.iter().map(|f| area_xz(&f.world)).sum();
    assert!((got - want).abs() < 1e-12, "shadow area {got} vs {want}");
    let lit_area: f64 = lit.iter().map(|f| area_xz(&f.world)).sum();
    assert!(
        (lit_area + got - 64.0).abs() < 1e-12,
        "parts tile the ground"
    );
    for f in &dark {
        for &p in &f.world {
            assert!(
                p.y == 0.0 && inside_xz(p, hull, 1e-12),
                "{p} outside the shadow"
            );
        }
    }
    for c in hull {
        let found = dark
            .iter()
            .flat_map(|f| f.world.iter())
            .any(|p| (p.x - c[0]).abs() < 1e-14 && (p.z - c[1]).abs() < 1e-14);
        assert!(found, "no shadow corner at {c:?}");
    }
}

#[test]
fn cube_shadow_under_a_directional_light_has_its_projected_corners() {
    // Along (1, 2, 0): a point (x, y, z) falls on (x - y/2, 0, z); the cube's top and
    // bottom squares fall on [-1.25, -0.25] and [-0.75, 0.25] in x: together the
    // rectangle [-1.25, 0.25] × [-0.5, 0.5].
    let s = cube_over_ground(LightKind::Directional(DVec3::new(1.0, 2.0, 0.0)));
    assert_shadow_is(
        &s,
        &[[-1.25, -0.5], [0.25, -0.5], [0.25, 0.5], [-1.25, 0.5]],
    );
}

#[test]
fn cube_shadow_under_a_point_light_has_its_projected_corners() {
    // From L = (1, 4, 0.5): the top square (y = 1.5) is scaled by 4/2.5 = 8/5 about L's
    // foot, the bottom square (y = 0.5) by 4/3.5 = 8/7. Top: x in [-7/5, 1/5], z in
    // [-11/10, 1/2]; bottom: x in [-5/7, 3/7], z in [-9/14, 1/2]. Their hull:
    let s = cube_over_ground(LightKind::Point(DVec3::new(1.0, 4.0, 0.5)));
    assert_shadow_is(
        &s,
        &[
            [-7.0 / 5.0, -11.0 / 10.0],
            [1.0 / 5.0, -11.0 / 10.0],
            [3.0 / 7.0, -9.0 / 14.0],
            [3.0 / 7.0, 0.5],
            [-7.0 / 5.0, 0.5],
        ],
    );
}

#[test]
fn a_face_partly_in_shadow_is_split_exactly_once() {
    // A 2 × 2 floor under a large roof ending at x = 0.25, light straight down.
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("grey", [0.8; 3]));
    let o = s.add_object("o");
    let quad = |x0: f64, x1: f64, z0: f64, z1: f64, y: f64| {
        vec![
            DVec3::new(x0, y, z1),
            DVec3::new(x1, y, z1),
            DVec3::new(x1, y, z0),
            DVec3::new(x0, y, z0),
        ]
    };
    s.add_polygon(&quad(-1.0, 1.0, -1.0, 1.0, 0.0), m, o)
        .unwrap();
    s.add_polygon(&quad(-5.0, 0.25, -5.0, 5.0, 1.0), m, o)
        .unwrap();
    s.lights = vec![Light {
        kind: LightKind::Directional(DVec3::new(0.0, 1.0, 0.0)),
        color: [1.0; 3],
        shadows: true,
    }];
    let cam = Camera::new(DVec3::new(2.0, 0.5, 6.0), DVec3::ZERO, 400, 300);
    let out = order(&s, &cam, &OrderOptions::default()).unwrap();
    let floor: Vec<&Fragment> = out.fragments.iter().filter(|f| f.face == 0).collect();
    assert_eq!(floor.len(), 2, "{floor:#?}");
    let dark: Vec<_> = floor.iter().filter(|f| f.shadowed.contains(0)).collect();
    assert_eq!(dark.len(), 1);
    assert!((area_xz(&dark[0].world) - 2.5).abs() < 1e-12);
    assert!(dark[0].world.iter().all(|p| p.x <= 0.25));
    // The roof is lit on its top, seen from below: in its own shadow everywhere.
    let roof: Vec<&Fragment> = out.fragments.iter().filter(|f| f.face == 1).collect();
    assert!(roof.iter().all(|f| f.shadowed.contains(0)));
    assert_eq!(out.stats.fragments_in_shadow, 1 + roof.len());
    // Without shadows asked, nothing is split and nothing is shadowed.
    s.lights[0].shadows = false;
    let plain = order(&s, &cam, &OrderOptions::default()).unwrap();
    assert_eq!(plain.fragments.iter().filter(|f| f.face == 0).count(), 1);
    assert!(plain.fragments.iter().all(|f| f.shadowed.is_empty()));
}

#[test]
fn translucent_faces_cast_no_shadow_and_unlit_faces_are_not_split() {
    let mut s = cube_over_ground(LightKind::Directional(DVec3::new(1.0, 2.0, 0.0)));
    let glass = s.add_material(Material {
        opacity: 0.5,
        ..Material::diffuse("glass", [0.8; 3])
    });
    for f in 1..7 {
        s.faces[f].material = glass;
    }
    let out = order(&s, &camera(), &OrderOptions::default()).unwrap();
    let (dark, _) = ground_parts(&out.fragments);
    assert!(dark.is_empty());
    let mut s = cube_over_ground(LightKind::Directional(DVec3::new(1.0, 2.0, 0.0)));
    let flat = s.add_material(Material::unlit("flat", [0.8; 3]));
    s.faces[0].material = flat;
    let out = order(&s, &camera(), &OrderOptions::default()).unwrap();
    assert_eq!(out.fragments.iter().filter(|f| f.face == 0).count(), 1);
}
