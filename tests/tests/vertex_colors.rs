//! A face with three corner colours, drawn by every writer and by the image-space
//! references: at known points inside it, each picture shows the colours interpolated
//! between the corners (Gouraud), in flat shading too (a face with vertex colours is
//! not one colour). The face squarely faces the camera, so the painter's screen-space
//! interpolation and the references' world-space one are the same function.
//! limn's PNG, the SVG (resvg, in process), the z-buffer and ray casting always;
//! the PDF (pdftoppm) and the EPS (ghostscript) where those programs are installed.

use std::path::Path;
use std::process::Command;

use glam::DVec3;
use limn_depthsort::{order, OrderOptions};
use limn_paint::{
    picture, EpsPainter, Painter, PdfPainter, Picture, PngOptions, PngPainter, Style, SvgPainter,
};
use limn_scene::{Camera, Material, Scene, Shading};
use limn_zbuffer::{render, Method, RenderOptions};

const SIZE: u32 = 96;

/// How far (8-bit levels per channel) resvg's picture of the SVG may be from the
/// interpolated colour: SVG has no mesh gradient, and three unrelated corner colours
/// are three channel ramps added by `mix-blend-mode: lighten`, each stop rounded to 8
/// bits.
const SVG_LEVELS: f64 = 3.0;

/// How far poppler's and ghostscript's pictures of the mesh shading may be (they
/// subdivide it to a depth of their own; measured: 5 levels).
const VIEWER_LEVELS: f64 = 6.0;
const COLORS: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// A triangle facing the camera, unlit white under red, green and blue corners, or lit
/// diffusely (flat: no normals) under them.
fn scene(lit: bool) -> Scene {
    let mut s = Scene::default();
    let m = if lit {
        let mut m = Material::diffuse("white", [1.0; 3]);
        m.ka = [0.0; 3];
        m
    } else {
        Material::unlit("white", [1.0; 3])
    };
    let m = s.add_material(m);
    let o = s.add_object("tri");
    s.add_polygon(
        &[
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            DVec3::new(-1.0, 1.0, 0.0),
        ],
        m,
        o,
    )
    .unwrap();
    s.colors = COLORS.to_vec();
    s.faces[0].colors = Some(Box::new([0, 1, 2]));
    s.shading = Some(Shading::Flat);
    s.validate().unwrap();
    s
}

fn camera() -> Camera {
    Camera::new(DVec3::new(0.0, 0.0, 4.0), DVec3::ZERO, SIZE, SIZE)
}

/// Sample points as barycentric weights of the corners.
const WEIGHTS: [[f64; 3]; 5] = [
    [1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0],
    [0.7, 0.15, 0.15],
    [0.15, 0.7, 0.15],
    [0.15, 0.15, 0.7],
    [0.45, 0.45, 0.1],
];

/// The pixels (x, y) at the sample points and the colour expected there (8 bits),
/// `scale` times the interpolated vertex colour.
fn samples(scale: f64) -> Vec<([usize; 2], [f64; 3])> {
    let s = scene(false);
    let cam = camera();
    let (near, far) = cam.near_far(&s);
    let vp = cam.view_projection(near, far);
    let corners: Vec<[f64; 2]> = s
        .face_points(0)
        .iter()
        .map(|&p| {
            let q = cam.project_with(&vp, p);
            [q.x, q.y]
        })
        .collect();
    WEIGHTS
        .iter()
        .map(|w| {
            let at = |k: usize| (0..3).map(|j| w[j] * corners[j][k]).sum::<f64>();
            let [x, y] = [at(0).floor(), at(1).floor()];
            // The weights at the pixel's centre.
            let [a, b, c] = [corners[0], corners[1], corners[2]];
            let (px, py) = (x + 0.5, y + 0.5);
            let area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
            let w1 = ((px - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (py - a[1])) / area;
            let w2 = ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) / area;
            let wc = [1.0 - w1 - w2, w1, w2];
            let want = [0, 1, 2]
                .map(|k| 255.0 * scale * (0..3).map(|j| wc[j] * COLORS[j][k]).sum::<f64>());
            ([x as usize, y as usize], want)
        })
        .collect()
}

/// Checks `rgb(x, y)` at every sample point against the expected colour within
/// `levels`.
fn check(what: &str, scale: f64, levels: f64, rgb: impl Fn(usize, usize) -> [u8; 3]) {
    for ([x, y], want) in samples(scale) {
        let got = rgb(x, y);
        for k in 0..3 {
            assert!(
                (f64::from(got[k]) - want[k]).abs() <= levels,
                "{what}: at ({x}, {y}) {got:?}, expected {want:?}"
            );
        }
    }
}

fn painted(lit: bool) -> Picture {
    let s = scene(lit);
    let o = order(&s, &camera(), &OrderOptions::default()).unwrap();
    picture(&s, &o, &Style::default())
}

/// RGB at (x, y) of RGBA rows `w` wide.
fn rgba_at(data: &[u8], w: usize) -> impl Fn(usize, usize) -> [u8; 3] + '_ {
    move |x, y| {
        let i = 4 * (y * w + x);
        [data[i], data[i + 1], data[i + 2]]
    }
}

#[test]
fn the_painter_interpolates_corner_colours_in_png_and_svg() {
    for lit in [false, true] {
        // Lit: the headlight meets the face head-on (diffuse 1), at the centroid.
        let pic = painted(lit);
        assert!(
            pic.fragments.iter().all(|f| f.vertex_colors.is_some()),
            "a face with vertex colours is not one colour"
        );
        let scale = if lit {
            let c = DVec3::new(-1.0 / 3.0, -1.0 / 3.0, 0.0);
            4.0 / (DVec3::new(0.0, 0.0, 4.0) - c).length()
        } else {
            1.0
        };
        let (png, _) = PngPainter::new(PngOptions::default()).render(&pic).unwrap();
        check("png", scale, 3.0, rgba_at(png.data(), SIZE as usize));
        let mut svg = Vec::new();
        SvgPainter::default().paint(&pic, &mut svg).unwrap();
        let svg = String::from_utf8(svg).unwrap();
        let tree = resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default()).unwrap();
        let mut pixmap = resvg::tiny_skia::Pixmap::new(SIZE, SIZE).unwrap();
        resvg::render(
            &tree,
            resvg::tiny_skia::Transform::identity(),
            &mut pixmap.as_mut(),
        );
        check(
            "svg",
            scale,
            SVG_LEVELS,
            rgba_at(pixmap.data(), SIZE as usize),
        );
    }
}

#[test]
fn the_references_draw_the_same_colours() {
    for method in [Method::ZBuffer, Method::RayCast] {
        let r = render(&scene(false), &camera(), method, &RenderOptions::default()).unwrap();
        check(&format!("{method:?}"), 1.0, 3.0, |x, y| {
            r.color.get(x as u32, y as u32).unwrap()
        });
    }
}

/// Rasterises `file` with `cmd` into `png`; `false` when the program is not installed.
fn rasterise(mut cmd: Command, png: &Path) -> Option<Vec<u8>> {
    match cmd.output() {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            eprintln!("SKIPPED: {cmd:?} is not installed");
            None
        }
        Err(e) => panic!("{cmd:?}: {e}"),
        Ok(out) => {
            assert!(out.status.success(), "{cmd:?}: {out:?}");
            Some(
                resvg::tiny_skia::Pixmap::load_png(png)
                    .unwrap()
                    .data()
                    .to_vec(),
            )
        }
    }
}

#[test]
fn pdf_and_eps_draw_the_colours_as_mesh_shading() {
    let pic = painted(false);
    let dir = tempfile::tempdir().unwrap();
    let (pdf, eps) = (dir.path().join("t.pdf"), dir.path().join("t.eps"));
    let mut out = Vec::new();
    PdfPainter::default().paint(&pic, &mut out).unwrap();
    assert!(String::from_utf8_lossy(&out).contains("/ShadingType 4"));
    std::fs::write(&pdf, &out).unwrap();
    let mut out = Vec::new();
    EpsPainter::default().paint(&pic, &mut out).unwrap();
    assert!(String::from_utf8_lossy(&out).contains("/ShadingType 4"));
    std::fs::write(&eps, &out).unwrap();

    let stem = dir.path().join("poppler");
    let mut cmd = Command::new("pdftoppm");
    cmd.args(["-r", "72", "-png", "-singlefile"])
        .arg(&pdf)
        .arg(&stem);
    if let Some(px) = rasterise(cmd, &stem.with_extension("png")) {
        check("pdftoppm", 1.0, VIEWER_LEVELS, rgba_at(&px, SIZE as usize));
    }
    let gs = dir.path().join("gs.png");
    let mut cmd = Command::new("gs");
    cmd.args([
        "-q",
        "-dSAFER",
        "-dBATCH",
        "-dNOPAUSE",
        "-sDEVICE=png16m",
        "-r72",
        "-dEPSCrop",
    ])
    .arg(format!("-sOutputFile={}", gs.display()))
    .arg(&eps);
    if let Some(px) = rasterise(cmd, &gs) {
        check(
            "ghostscript",
            1.0,
            VIEWER_LEVELS,
            rgba_at(&px, SIZE as usize),
        );
    }
}
