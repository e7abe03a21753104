//! Texture coordinates that collapse to a point or a segment (real files have them:
//! 276 of the 2,512 textured triangles of the glTF sample CesiumMilkTruck): drawn in
//! every format with the colours they name, and no number in the file out of scale
//! with the page.

use std::sync::Arc;

use glam::DVec3;
use limn_depthsort::{order, OrderOptions};
use limn_paint::{
    picture, EpsPainter, Painter, PdfPainter, Picture, PngOptions, PngPainter, Style, SvgPainter,
    TikzPainter,
};
use limn_scene::{Camera, Material, Scene, Texture};

/// 64 × 64 texels: red rising to the right, green downwards, blue constant.
fn ramp() -> Arc<Texture> {
    let mut rgba = Vec::new();
    for j in 0..64u32 {
        for i in 0..64u32 {
            rgba.extend_from_slice(&[(i * 4) as u8, (j * 4) as u8, 128, 255]);
        }
    }
    Arc::new(Texture::new("ramp", 64, 64, rgba).unwrap())
}

/// The centre of texel `(i, j)` of a 64-texel texture.
fn centre(i: u32, j: u32) -> [f64; 2] {
    [(f64::from(i) + 0.5) / 64.0, (f64::from(j) + 0.5) / 64.0]
}

/// Four unlit squares side by side on the wall z = 0 (x from -2 to 2), each two
/// triangles: texture coordinates collapsed to one texel centre; on a horizontal
/// segment; on a segment up to rounding (a thousandth of a texel off it); and spanning
/// an area.
fn wall() -> Scene {
    let mut s = Scene::default();
    let mut m = Material::unlit("t", [1.0; 3]);
    m.texture = Some(ramp());
    let mat = s.add_material(m);
    let obj = s.add_object("wall");
    let point = [centre(10, 20); 4];
    let segment = [centre(8, 40), centre(56, 40), centre(56, 40), centre(8, 40)];
    let mut sliver = segment;
    sliver[2][1] += 0.001 / 64.0;
    sliver[3][1] -= 0.0007 / 64.0;
    let area = [centre(0, 0), centre(63, 0), centre(63, 63), centre(0, 63)];
    for (k, st) in [point, segment, sliver, area].into_iter().enumerate() {
        let x0 = -2.0 + k as f64;
        let v = [[x0, -0.5], [x0 + 0.9, -0.5], [x0 + 0.9, 0.5], [x0, 0.5]]
            .map(|[x, y]| s.add_vertex(DVec3::new(x, y, 0.0)));
        let t0 = s.texcoords.len() as u32;
        s.texcoords.extend_from_slice(&st);
        for tri in [[0, 1, 2], [0, 2, 3]] {
            let f = s.add_face(&tri.map(|i| v[i]), mat, obj).unwrap();
            s.faces[f as usize].texcoords = Some(Box::new(tri.map(|i| t0 + i as u32)));
        }
    }
    s
}

fn camera() -> Camera {
    Camera::new(DVec3::new(0.0, 0.0, 4.0), DVec3::ZERO, 400, 200)
}

fn wall_picture() -> Picture {
    let scene = wall();
    let cam = camera();
    let o = order(&scene, &cam, &OrderOptions::default()).unwrap();
    picture(&scene, &o, &Style::default())
}

/// The page point of world point `(x, y, 0)`.
fn project(x: f64, y: f64) -> (usize, usize) {
    let cam = camera();
    let p = cam.project_with(&cam.view_projection(0.1, 100.0), DVec3::new(x, y, 0.0));
    (p.x as usize, p.y as usize)
}

fn pixel(rgba: &[u8], w: u32, (x, y): (usize, usize)) -> [u8; 4] {
    let at = 4 * (y * w as usize + x);
    [rgba[at], rgba[at + 1], rgba[at + 2], rgba[at + 3]]
}

fn close(a: [u8; 4], b: [u8; 3], tolerance: u8) -> bool {
    (0..3).all(|k| a[k].abs_diff(b[k]) <= tolerance) && a[3] == 255
}

/// Every number written in `text` (digits with an optional sign and point).
fn numbers(text: &str) -> Vec<f64> {
    let mut out = Vec::new();
    let mut cur = String::new();
    for c in text.chars().chain(std::iter::once(' ')) {
        if c.is_ascii_digit() || c == '.' || (c == '-' && cur.is_empty()) {
            cur.push(c);
        } else {
            if let Ok(v) = cur.parse::<f64>() {
                out.push(v);
            }
            cur.clear();
        }
    }
    out
}

/// The transforms of the SVG (`matrix(…)`) and the EPS (`[… ] T0`): every coefficient
/// within a million (the page is 400 wide; a collapsed map gave 1e18).
fn assert_maps_in_scale(text: &str, what: &str) {
    let mut seen = 0;
    for part in text.split("matrix(").skip(1) {
        let inner = &part[..part.find(')').unwrap()];
        for v in numbers(inner) {
            assert!(v.abs() < 1e6, "{what}: coefficient {v} in matrix({inner})");
            seen += 1;
        }
    }
    for line in text
        .lines()
        .filter(|l| l.starts_with('[') && l.contains("] T"))
    {
        for v in numbers(&line[1..line.find(']').unwrap()]) {
            assert!(v.abs() < 1e6, "{what}: coefficient {v} in {line}");
            seen += 1;
        }
    }
    assert!(seen > 0, "{what}: no texture drawn");
    for bad in ["NaN", "nan", "inf"] {
        assert!(!text.contains(bad), "{what}: {bad}");
    }
}

#[test]
fn collapsed_coordinates_are_drawn_as_the_colours_they_name() {
    let pic = wall_picture();
    let (w, h) = (pic.width, pic.height);
    // The point: texel (10, 20) = (40, 80, 128), everywhere on the square.
    let texel = [40, 80, 128];
    let (png, _) = PngPainter::new(PngOptions::default()).render(&pic).unwrap();
    let png = png.data().to_vec();
    let mut svg = Vec::new();
    SvgPainter::default().paint(&pic, &mut svg).unwrap();
    let svg = String::from_utf8(svg).unwrap();
    assert_maps_in_scale(&svg, "svg");
    let tree = resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default()).unwrap();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::identity(),
        &mut pixmap.as_mut(),
    );
    let drawn = pixmap.data().to_vec();
    let mut eps = Vec::new();
    EpsPainter::default().paint(&pic, &mut eps).unwrap();
    let eps = String::from_utf8(eps).unwrap();
    assert_maps_in_scale(&eps, "eps");
    // PDF and TikZ write and say nothing non-finite either.
    let mut pdf = Vec::new();
    PdfPainter::default().paint(&pic, &mut pdf).unwrap();
    let mut tikz = Vec::new();
    TikzPainter::default().paint(&pic, &mut tikz).unwrap();
    let tikz = String::from_utf8(tikz).unwrap();
    assert!(!tikz.contains("NaN") && !tikz.contains("inf"));

    for (x, y) in [(-1.9, -0.4), (-1.55, 0.0), (-1.2, 0.4)] {
        let p = project(x, y);
        assert!(
            close(pixel(&png, w, p), texel, 1),
            "png at {p:?}: {:?}",
            pixel(&png, w, p)
        );
        assert!(
            close(pixel(&drawn, w, p), texel, 2),
            "svg at {p:?}: {:?}",
            pixel(&drawn, w, p)
        );
    }
    // The segment and the sliver: red rising from texel 8 to texel 56 of row 40 (green
    // 160) from left to right, the same up and down the square.
    for x0 in [-1.0, 0.0] {
        for (fx, fy) in [(0.1, -0.3), (0.45, 0.0), (0.8, 0.3)] {
            let p = project(x0 + fx, fy);
            // The texel position across the square, perspective aside (the wall faces
            // the eye): 8 + 48 · fx / 0.9.
            let red = (8.0 + 48.0 * fx / 0.9) * 4.0;
            let want = [red.round() as u8, 160, 128];
            assert!(
                close(pixel(&png, w, p), want, 3),
                "png at {p:?}: {:?} {want:?}",
                pixel(&png, w, p)
            );
            assert!(
                close(pixel(&drawn, w, p), want, 4),
                "svg at {p:?}: {:?} {want:?}",
                pixel(&drawn, w, p)
            );
        }
    }
    // The last square keeps its image: near its corner of texel (0, 0), at texel
    // position (0.5 + 63 · 0.05 / 0.9, 0.5 + 63 · 0.05) = (4, 3.65).
    let p = project(1.05, -0.45);
    let want = [14, 13, 128];
    assert!(close(pixel(&png, w, p), want, 3), "{:?}", pixel(&png, w, p));
    assert!(
        close(pixel(&drawn, w, p), want, 6),
        "{:?}",
        pixel(&drawn, w, p)
    );
}
