//! A textured mesh like the glTF sample Duck (a thousand triangles, a 512 × 512
//! texture, some texture coordinates collapsed to points and segments) opened
//! in the viewers people use: rsvg-convert for the SVG, poppler's pdftoppm and
//! ghostscript for the PDF. Each must rasterise it within a time bound and agree with
//! limn's own PNG. Skipped (with a message) where a viewer is not installed.
//!
//! Before, collapsed coordinates gave maps that rsvg-convert refused ("InvalidMatrix")
//! or crashed on, and every small face drew the whole image (pdftoppm took minutes over
//! the Duck).

use std::path::Path;
use std::process::{Command, Stdio};
use std::sync::Arc;
use std::time::{Duration, Instant};

use glam::DVec3;
use limn_depthsort::{order, OrderOptions};
use limn_paint::{
    picture, Painter, PdfPainter, Picture, PngOptions, PngPainter, Style, SvgPainter,
};
use limn_scene::{Camera, Material, Scene, Texture};

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
                s.faces[f as usize].texcoords = Some(tri.map(|i| st[i]).to_vec());
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

/// Runs `cmd` with a deadline of [`BOUND`]; `None` when the program is not installed.
fn run_within(mut cmd: Command, what: &str) -> Option<Duration> {
    let start = Instant::now();
    let mut child = match cmd.stdout(Stdio::null()).stderr(Stdio::piped()).spawn() {
        Ok(c) => c,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            eprintln!("SKIPPED: {what} is not installed");
            return None;
        }
        Err(e) => panic!("{what}: {e}"),
    };
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let took = start.elapsed();
            let mut err = String::new();
            if let Some(mut e) = child.stderr.take() {
                std::io::Read::read_to_string(&mut e, &mut err).unwrap();
            }
            assert!(status.success(), "{what} failed: {status}: {err}");
            eprintln!("{what}: {:.2} s", took.as_secs_f64());
            return Some(took);
        }
        if start.elapsed() > BOUND {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{what} took more than {} s", BOUND.as_secs());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// RGBA pixels of a PNG file.
fn load(path: &Path) -> Vec<u8> {
    resvg::tiny_skia::Pixmap::load_png(path)
        .unwrap()
        .data()
        .to_vec()
}

/// Over the pixels whose 3 × 3 neighbourhood is opaque in limn's PNG (the inside of
/// the globe, away from its silhouette), the share within 16 levels per channel of
/// the viewer's (composited on white, as the viewers of PDF draw it).
fn agreement(png: &[u8], viewer: &[u8], w: usize, h: usize) -> f64 {
    let (mut agree, mut compared) = (0usize, 0usize);
    for y in 1..h - 1 {
        for x in 1..w - 1 {
            let opaque = (0..9).all(|k| png[4 * ((y + k / 3 - 1) * w + x + k % 3 - 1) + 3] == 255);
            if !opaque {
                continue;
            }
            let at = 4 * (y * w + x);
            let va = f64::from(viewer[at + 3]) / 255.0;
            let near = (0..3).all(|c| {
                let v = f64::from(viewer[at + c]) + (1.0 - va) * 255.0;
                (v - f64::from(png[at + c])).abs() <= 16.0
            });
            compared += 1;
            agree += usize::from(near);
        }
    }
    assert!(compared > 20_000, "{compared} pixels compared");
    agree as f64 / compared as f64
}

#[test]
fn a_duck_sized_textured_mesh_opens_quickly_and_as_drawn() {
    let pic = globe_picture();
    let (w, h) = (pic.width as usize, pic.height as usize);
    let (png, _) = PngPainter::new(PngOptions::default()).render(&pic).unwrap();
    let png = png.data().to_vec();
    let dir = tempfile::tempdir().unwrap();
    let (svg, pdf) = (dir.path().join("globe.svg"), dir.path().join("globe.pdf"));
    let mut out = Vec::new();
    SvgPainter::default().paint(&pic, &mut out).unwrap();
    std::fs::write(&svg, &out).unwrap();
    let mut out = Vec::new();
    PdfPainter::default().paint(&pic, &mut out).unwrap();
    std::fs::write(&pdf, &out).unwrap();

    let mut cmd = Command::new("rsvg-convert");
    let rsvg = dir.path().join("rsvg.png");
    cmd.arg("-o").arg(&rsvg).arg(&svg);
    if run_within(cmd, "rsvg-convert").is_some() {
        let share = agreement(&png, &load(&rsvg), w, h);
        eprintln!(
            "rsvg-convert: {:.2} % of the inside within 16 levels",
            100.0 * share
        );
        assert!(share >= 0.97, "rsvg-convert: {share}");
    }
    let mut cmd = Command::new("pdftoppm");
    let stem = dir.path().join("poppler");
    cmd.args(["-r", "72", "-png", "-singlefile"])
        .arg(&pdf)
        .arg(&stem);
    if run_within(cmd, "pdftoppm").is_some() {
        let share = agreement(&png, &load(&stem.with_extension("png")), w, h);
        eprintln!(
            "pdftoppm: {:.2} % of the inside within 16 levels",
            100.0 * share
        );
        assert!(share >= 0.97, "pdftoppm: {share}");
    }
    let mut cmd = Command::new("gs");
    let gs = dir.path().join("gs.png");
    cmd.args([
        "-q",
        "-dSAFER",
        "-dBATCH",
        "-dNOPAUSE",
        "-sDEVICE=png16m",
        "-r72",
    ])
    .arg(format!("-sOutputFile={}", gs.display()))
    .arg(&pdf);
    if run_within(cmd, "ghostscript").is_some() {
        let share = agreement(&png, &load(&gs), w, h);
        eprintln!(
            "ghostscript: {:.2} % of the inside within 16 levels",
            100.0 * share
        );
        assert!(share >= 0.97, "ghostscript: {share}");
    }
}
