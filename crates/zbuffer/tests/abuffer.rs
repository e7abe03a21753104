//! A-buffer transparency against hand-computed blends.

mod common;

use common::poly;
use glam::DVec3;
use limn_scene::{Camera, Material, Scene};
use limn_zbuffer::{render, Method, RenderOptions};

fn square(x0: f64, y0: f64, x1: f64, y1: f64, z: f64) -> [DVec3; 4] {
    [(x0, y0), (x1, y0), (x1, y1), (x0, y1)].map(|(x, y)| DVec3::new(x, y, z))
}

fn close(got: [u8; 3], want: [f64; 3]) -> bool {
    got.iter()
        .zip(want)
        .all(|(&g, w)| (g as f64 - w * 255.0).abs() <= 1.0)
}

/// `src` over `dst` with opacity `a` (back-to-front painting).
fn over(src: [f64; 3], a: f64, dst: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|k| a * src[k] + (1.0 - a) * dst[k])
}

#[test]
fn translucent_layers_blend_like_painting_back_to_front() {
    let mut s = Scene::default();
    let mut mat = |name: &str, kd: [f64; 3], d: f64| {
        let mut m = Material::unlit(name, kd);
        m.opacity = d;
        s.add_material(m)
    };
    let blue = mat("blue", [0.0, 0.0, 1.0], 1.0);
    let red = mat("red", [1.0, 0.0, 0.0], 0.5);
    let green = mat("green", [0.0, 1.0, 0.0], 0.25);
    let grey = mat("grey", [0.4, 0.4, 0.4], 0.6);
    s.add_object("o");
    // Input order unrelated to depth: green (front) first, blue (back) last.
    poly(&mut s, &square(-0.2, -0.2, 0.8, 0.8, 0.5), green);
    poly(&mut s, &square(-0.8, -0.8, 0.4, 0.4, 0.0), red);
    poly(&mut s, &square(-0.6, -0.1, 0.6, 0.6, -1.0), blue);
    // An opaque face behind the blue one must not show through it.
    poly(&mut s, &square(-0.9, -0.9, 0.9, 0.9, -2.0), grey);
    let camera = Camera::new(DVec3::new(0.0, 0.0, 5.0), DVec3::ZERO, 80, 80);
    let bg = [1.0, 1.0, 0.9];
    let opts = RenderOptions {
        background: bg,
        ..RenderOptions::default()
    };
    let r = render(&s, &camera, Method::ABuffer, &opts).unwrap();
    let (g, rd, b, gy) = ([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.4; 3]);
    // Point → expected, painted back to front by hand.
    let behind_all = over(g, 0.25, over(rd, 0.5, b));
    let cases: [((f64, f64), [f64; 3], u32); 5] = [
        ((0.1, 0.1), behind_all, 0),
        ((-0.5, -0.5), over(rd, 0.5, over(gy, 0.6, bg)), 1),
        ((0.5, 0.5), over(g, 0.25, over(gy, 0.6, bg)), 0),
        ((-0.55, 0.5), b, 2),
        ((0.85, -0.85), over(gy, 0.6, bg), 3),
    ];
    let vp = camera.view_projection(4.0, 8.0);
    for ((x, y), want, id) in cases {
        // Every case point lies in the plane nearest the eye among those covering it.
        let z = [0.5, 0.0, -1.0, -2.0][id as usize];
        let p = camera.project_with(&vp, DVec3::new(x, y, z));
        let (px, py) = (p.x as u32, p.y as u32);
        let got = r.color.get(px, py).unwrap();
        assert!(close(got, want), "at ({x}, {y}): {got:?} vs {want:?}");
        assert_eq!(r.ids.get(px, py), Some(id), "nearest fragment's face");
    }
    // Outside everything: the background.
    assert_eq!(r.color.get(0, 0), Some([255, 255, 230]));
    // The z-buffer ignores opacity: the nearest face's own colour.
    let z = render(&s, &camera, Method::ZBuffer, &opts).unwrap();
    let p = camera.project_with(&vp, DVec3::new(0.1, 0.1, 0.5));
    assert_eq!(z.color.get(p.x as u32, p.y as u32), Some([0, 255, 0]));
}
