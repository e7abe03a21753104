//! Object-space shadows against exact ray-cast shadows, per pixel: the same lights
//! hidden at every pixel centre outside the edge band; and the shadow maps'
//! disagreements, which exist but stay few at the default bias.

use glam::{DMat3, DVec3};
use limn_check::paint;
use limn_depthsort::OrderOptions;
use limn_scene::{shapes, Camera, Light, LightKind, Material, Scene};
use limn_zbuffer::{DepthFormat, Method, ShadowMapOptions};

/// A ground square and two boxes (one turned, one tilted) under the given lights.
fn scene(lights: Vec<Light>) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("grey", [0.8; 3]));
    let ground = s.add_object("ground");
    let pts: Vec<DVec3> = [[-4.0, 4.0], [4.0, 4.0], [4.0, -4.0], [-4.0, -4.0]]
        .iter()
        .map(|c| DVec3::new(c[0], 0.0, c[1]))
        .collect();
    s.add_polygon(&pts, m, ground).unwrap();
    let a = s.add_object("a");
    shapes::cuboid(
        &mut s,
        DVec3::new(-0.5, 0.5, -0.5),
        DVec3::new(0.5, 1.5, 0.5),
        DMat3::from_rotation_y(0.4),
        m,
        a,
    )
    .unwrap();
    let b = s.add_object("b");
    shapes::cuboid(
        &mut s,
        DVec3::new(-2.2, 0.0, -1.0),
        DVec3::new(-1.6, 2.4, 0.3),
        DMat3::from_rotation_z(0.2),
        m,
        b,
    )
    .unwrap();
    s.lights = lights;
    s
}

fn light(kind: LightKind, shadows: bool) -> Light {
    Light {
        kind,
        color: [0.6; 3],
        shadows,
    }
}

fn camera() -> Camera {
    Camera::new(
        DVec3::new(4.0, 6.0, 7.5),
        DVec3::new(-0.5, 0.3, 0.0),
        320,
        240,
    )
}

/// Mismatching shadow sets outside the band (faces must agree first).
fn check(s: &Scene) -> usize {
    let painted = paint(s, &camera(), &OrderOptions::default()).unwrap();
    let faces = painted
        .reference(s, Method::RayCast, DepthFormat::F64)
        .unwrap();
    assert_eq!(painted.compare(&faces).mismatches_outside_band, 0);
    let exact = painted
        .reference_shadows(s, Method::RayCast, &ShadowMapOptions::default())
        .unwrap();
    let shadowed = exact
        .ids
        .iter()
        .filter(|&&i| i != 0 && i != u32::MAX)
        .count();
    assert!(
        shadowed > 500,
        "the scene has shadows to compare ({shadowed})"
    );
    painted.compare_shadows(&exact).mismatches_outside_band
}

#[test]
fn vector_shadows_equal_ray_cast_shadows_under_a_directional_light() {
    let s = scene(vec![light(
        LightKind::Directional(DVec3::new(1.0, 2.0, 0.5)),
        true,
    )]);
    assert_eq!(check(&s), 0);
}

#[test]
fn vector_shadows_equal_ray_cast_shadows_under_a_point_light() {
    let s = scene(vec![light(
        LightKind::Point(DVec3::new(1.5, 3.5, 1.0)),
        true,
    )]);
    assert_eq!(check(&s), 0);
}

#[test]
fn vector_shadows_equal_ray_cast_shadows_under_two_lights() {
    // Light 1 asks for no shadows: only lights 0 and 2 appear in the sets.
    let s = scene(vec![
        light(LightKind::Point(DVec3::new(-1.0, 3.0, 2.5)), true),
        light(LightKind::Directional(DVec3::new(0.0, 1.0, 0.0)), false),
        light(LightKind::Directional(DVec3::new(-1.0, 1.5, -0.5)), true),
    ]);
    assert_eq!(check(&s), 0);
}

#[test]
fn shadow_maps_disagree_with_ray_casting_only_near_shadow_edges_at_the_default_bias() {
    let s = scene(vec![light(
        LightKind::Directional(DVec3::new(1.0, 2.0, 0.5)),
        true,
    )]);
    let painted = paint(&s, &camera(), &OrderOptions::default()).unwrap();
    let exact = painted
        .reference_shadows(&s, Method::RayCast, &ShadowMapOptions::default())
        .unwrap();
    let differing = |maps: &ShadowMapOptions| {
        let m = painted
            .reference_shadows(&s, Method::ZBuffer, maps)
            .unwrap();
        m.ids.iter().zip(&exact.ids).filter(|(a, b)| a != b).count()
    };
    let at_default = differing(&ShadowMapOptions::default());
    let no_bias = differing(&ShadowMapOptions {
        bias: 0.0,
        ..ShadowMapOptions::default()
    });
    // Without bias, lit faces shadow themselves (acne) on many pixels; with the stated
    // bias only pixels along the shadow edges differ.
    assert!(no_bias > 4 * at_default, "{no_bias} vs {at_default}");
    assert!(at_default < 320 * 240 / 100, "{at_default}");
}
