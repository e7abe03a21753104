//! A textured mesh like the glTF sample Duck (a thousand triangles, a 512 × 512
//! texture, some texture coordinates collapsed to points and segments) opened
//! in the viewers people use: rsvg-convert for the SVG, poppler's pdftoppm and
//! ghostscript for the PDF. Each must rasterise it within a time bound and agree with
//! limn's own PNG. Skipped (with a message) where a viewer is not installed.
//!
//! Before, collapsed coordinates gave maps that rsvg-convert refused ("InvalidMatrix")
//! or crashed on, and every small face drew the whole image (pdftoppm took minutes over
//! the Duck).

use std::sync::Arc;
use std::time::Duration;

use glam::DVec3;
use limn_depthsort::{order, OrderOptions};
use limn_paint::{
    draw_from_page_image, picture, Painter, PdfPainter, Picture, PngOptions, PngPainter, Style,
    SvgPainter, DEFAULT_TEXTURE_SAMPLES,
};
use limn_scene::{Camera, Material, Scene, Texture};
use limn_tests::viewers::{agreement, load_png, rasters};

/// The longest a viewer may take over the picture (a few seconds each on one core;
/// the bound leaves room for a busy machine).
const BOUND: Duration = Duration::from_secs(60);

/// A smooth 512 × 512 texture (gentle waves in each channel).
fn waves() -> Arc<Texture> {
    let mut rgba = Vec::with_capacity(4 * 512 * 512);
    for j in 0..512 {
        for i in 0..512 {
            let (x, y) = (f64::from(i) / 512.0, f64::from(j) / 512.0);
            let tau = std::f64::consts::TAU;
            let c = [
                0.5 + 0.4 * (tau * 3.0 * x).sin(),
                0.5 + 0.4 * (tau * 2.0 * y).cos(),
                0.5 + 0.3 * (tau * (x + y)).sin(),
            ];
            rgba.extend(c.map(|v| (v * 255.0).round() as u8));
            rgba.push(255);
        }
    }
    Arc::new(Texture::new("waves", 512, 512, rgba).unwrap())
}

/// A sphere of `rings` × `segments` quads (two triangles each), unlit and textured by
/// longitude and latitude; the quads of ring 8 have their coordinates collapsed to one
/// point each, those of ring 12 to a segment along the ring.
fn globe(rings: u32, segments: u32) -> Scene {
    let mut s = Scene::default();
    let mut m = Material::unlit("globe", [1.0; 3]);
    m.texture = Some(waves());
    let mat = s.add_material(m);
    let obj = s.add_object("globe");
    let pi = std::f64::consts::PI;
    let mut id = Vec::new();
    for r in 0..=rings {
        for k in 0..=segments {
            let (lat, lon) = (
                pi * f64::from(r) / f64::from(rings),
                2.0 * pi * f64::from(k) / f64::from(segments),
            );
            id.push(s.add_vertex(DVec3::new(
                lat.sin() * lon.cos(),
                lat.cos(),
                lat.sin() * lon.sin(),
            )));
            s.texcoords.push([
                f64::from(k) / f64::from(segments),
                f64::from(r) / f64::from(rings),
            ]);
        }
    }
    let at = |r: u32, k: u32| r * (segments + 1) + k;
    for r in 0..rings {
        for k in 0..segments {
            let quad = [at(r, k), at(r, k + 1), at(r + 1, k + 1), at(r + 1, k)];
            let st: [u32; 4] = match r {
                8 => [at(r, k); 4],
                12 => [at(r, k), at(r, k + 1), at(r, k + 1), at(r, k)],
                _ => quad,
            };
            for tri in [[0, 1, 2], [0, 2, 3]] {
                let Ok(f) = s.add_face(&tri.map(|i| id[quad[i] as usize]), mat, obj) else {
                    continue; // the poles' zero-area triangles
                };
                s.faces[f as usize].texcoords = Some(Box::new(tri.map(|i| st[i])));
            }
        }
    }
    s
}

fn globe_picture() -> Picture {
    let scene = globe(20, 32);
    let camera = Camera::new(DVec3::new(0.6, 0.9, 2.6), DVec3::ZERO, 400, 300);
    let o = order(&scene, &camera, &OrderOptions::default()).unwrap();
    assert!(o.fragments.len() > 600, "{} fragments", o.fragments.len());
    picture(&scene, &o, &Style::default())
}

#[test]
fn a_duck_sized_textured_mesh_opens_quickly_and_as_drawn() {
    // Each face under its own maps, and (as the command writes SVG and PDF) drawn
    // from the page image; limn's PNG of the picture as composed is the reference.
    let pic = globe_picture();
    let (png, _) = PngPainter::new(PngOptions::default()).render(&pic).unwrap();
    let png = png.data().to_vec();
    opens_quickly_and_as_drawn(&pic, &png);
    let mut paged = pic.clone();
    assert!(draw_from_page_image(&mut paged, DEFAULT_TEXTURE_SAMPLES) > 600);
    opens_quickly_and_as_drawn(&paged, &png);
}

/// `pic` in SVG and PDF rasterised by each installed viewer within [`BOUND`] and
/// agreeing with `png` (limn's raster of the same page).
fn opens_quickly_and_as_drawn(pic: &Picture, png: &[u8]) {
    let (w, h) = (pic.width as usize, pic.height as usize);
    let dir = tempfile::tempdir().unwrap();
    let (svg, pdf) = (dir.path().join("globe.svg"), dir.path().join("globe.pdf"));
    let mut out = Vec::new();
    SvgPainter::default().paint(pic, &mut out).unwrap();
    std::fs::write(&svg, &out).unwrap();
    let mut out = Vec::new();
    PdfPainter::default().paint(pic, &mut out).unwrap();
    std::fs::write(&pdf, &out).unwrap();
    for (viewer, raster) in rasters(&svg, &pdf, BOUND) {
        let (share, compared) = agreement(png, &load_png(&raster).0, w, h, 16.0);
        eprintln!(
            "{viewer}: {:.2} % of the inside within 16 levels",
            100.0 * share
        );
        assert!(compared > 20_000, "{compared} pixels compared");
        assert!(share >= 0.97, "{viewer}: {share}");
    }
}
