//! Textures drawn by the vector writers against the PNG painter, perspective
//! correctness at a grazing angle, and seams between textured triangles.

use std::sync::Arc;

use glam::DVec3;
use limn_depthsort::{order, OrderOptions};
use limn_paint::{
    affine_pieces, draw_from_page_image, picture, EpsPainter, Painter, PdfPainter, Picture,
    PngOptions, PngPainter, Style, SvgPainter, DEFAULT_TEXTURE_SAMPLES, MAX_PERSPECTIVE_ERROR,
};
use limn_scene::{Camera, Material, Scene, Texture, TextureAlpha, Wrap};

/// An `n` × `n` checker of two soft colours (so that bilinear blending stays gentle).
fn checker(n: u32) -> Arc<Texture> {
    let mut rgba = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let c = if (i + j) % 2 == 0 {
                [200, 90, 60]
            } else {
                [240, 220, 150]
            };
            rgba.extend_from_slice(&[c[0], c[1], c[2], 255]);
        }
    }
    Arc::new(Texture::new("checker", n, n, rgba).unwrap())
}

/// A `cells` × `cells` grid of textured triangles covering the square [-1, 1]² at
/// y = 0, texture coordinates `reps` repetitions across; `lit` gives a diffusely lit
/// material (the fill is not white) instead of an unlit white one.
fn textured_floor(cells: u32, reps: f64, lit: bool, texture: Arc<Texture>) -> Scene {
    let mut s = Scene::default();
    let mut m = if lit {
        Material::diffuse("t", [0.9, 0.8, 1.0])
    } else {
        Material::unlit("t", [1.0; 3])
    };
    m.texture = Some(texture);
    let mat = s.add_material(m);
    let obj = s.add_object("floor");
    let k = f64::from(cells);
    for j in 0..=cells {
        for i in 0..=cells {
            let (u, v) = (f64::from(i) / k, f64::from(j) / k);
            s.add_vertex(DVec3::new(2.0 * u - 1.0, 0.0, 1.0 - 2.0 * v));
            s.texcoords.push([reps * u, reps * v]);
        }
    }
    let id = |i: u32, j: u32| j * (cells + 1) + i;
    for j in 0..cells {
        for i in 0..cells {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            for tri in [[a, b, c], [a, c, d]] {
                let f = s.add_face(&tri, mat, obj).unwrap();
                s.faces[f as usize].texcoords = Some(Box::new(tri));
            }
        }
    }
    s
}

fn ordered_picture(scene: &Scene, camera: &Camera) -> Picture {
    let o = order(scene, camera, &OrderOptions::default()).unwrap();
    picture(scene, &o, &Style::default())
}

fn png_pixels(p: &Picture) -> Vec<u8> {
    let (pixmap, _) = PngPainter::new(PngOptions::default()).render(p).unwrap();
    pixmap.data().to_vec()
}

fn svg_pixels(p: &Picture) -> (String, Vec<u8>) {
    let mut out = Vec::new();
    SvgPainter::default().paint(p, &mut out).unwrap();
    let svg = String::from_utf8(out).unwrap();
    let tree = resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default()).unwrap();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(p.width, p.height).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::identity(),
        &mut pixmap.as_mut(),
    );
    (svg, pixmap.data().to_vec())
}

/// Pixels within `band` pixels of the picture's silhouette (the projected outline of
/// the floor), where anti-aliasing differs between renderers.
fn near_outline(x: f64, y: f64, outline: &[[f64; 2]], band: f64) -> bool {
    (0..outline.len()).any(|i| {
        let (a, b) = (outline[i], outline[(i + 1) % outline.len()]);
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let t = (((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
        (x - a[0] - t * dx).hypot(y - a[1] - t * dy) <= band
    })
}

fn floor_outline(camera: &Camera) -> Vec<[f64; 2]> {
    let vp = camera.view_projection(0.1, 100.0);
    [(-1.0, 1.0), (1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)]
        .map(|(x, z)| {
            let p = camera.project_with(&vp, DVec3::new(x, 0.0, z));
            [p.x, p.y]
        })
        .to_vec()
}

/// Over the pixels away from the outline: the largest channel difference, how many
/// differ by more than `tolerance` levels, and how many were compared.
fn compare(a: &[u8], b: &[u8], w: u32, outline: &[[f64; 2]], tolerance: u8) -> (u8, usize, usize) {
    let mut worst = 0u8;
    let mut over = 0;
    let mut compared = 0;
    for (i, (pa, pb)) in a.chunks_exact(4).zip(b.chunks_exact(4)).enumerate() {
        let (x, y) = ((i as u32 % w) as f64 + 0.5, (i as u32 / w) as f64 + 0.5);
        if near_outline(x, y, outline, 2.0) {
            continue;
        }
        let d = pa
            .iter()
            .zip(pb)
            .map(|(p, q)| p.abs_diff(*q))
            .max()
            .unwrap();
        worst = worst.max(d);
        compared += 1;
        if d > tolerance {
            over += 1;
        }
    }
    (worst, over, compared)
}

/// The stated tolerance, outside a 2 px band around the outline: every pixel within
/// [`MOST`] levels of 255 per channel but at most [`FEW`] of the pixels compared, and
/// every pixel within [`ALL`] levels. Bilinear interpolation has a corner at each texel
/// centre (the checker's extremes); the PNG painter samples it exactly, while image
/// filters of SVG renderers round it off over a pixel or two (resvg and librsvg both
/// do, by 10 to 25 levels there): the few pixels on those corners are the exception.
const MOST: u8 = 8;
/// See [`MOST`]: the share of pixels allowed above it.
const FEW: f64 = 0.02;
/// See [`MOST`]: the bound for every pixel.
const ALL: u8 = 40;

fn assert_agree(png: &[u8], svg: &[u8], w: u32, outline: &[[f64; 2]], what: &str) {
    assert_agree_within(png, svg, w, outline, what, FEW);
}

/// [`assert_agree`] with `few` for [`FEW`].
fn assert_agree_within(png: &[u8], svg: &[u8], w: u32, outline: &[[f64; 2]], what: &str, few: f64) {
    let (worst, over, compared) = compare(png, svg, w, outline, MOST);
    let share = over as f64 / compared as f64;
    eprintln!("{what}: worst {worst}, {over} of {compared} pixels above {MOST} levels");
    assert!(compared > 10_000, "{what}: {compared} pixels compared");
    assert!(
        share <= few,
        "{what}: {over} of {compared} pixels above {MOST} levels"
    );
    assert!(worst <= ALL, "{what}: worst difference {worst}");
}

#[test]
fn a_textured_quad_in_svg_matches_the_png_painter() {
    let camera = Camera::new(DVec3::new(0.6, 1.4, 2.6), DVec3::ZERO, 240, 180);
    let outline = floor_outline(&camera);
    for lit in [false, true] {
        let scene = textured_floor(1, 2.0, lit, checker(8));
        let pic = ordered_picture(&scene, &camera);
        assert!(pic.has_textures());
        let png = png_pixels(&pic);
        let (svg, rendered) = svg_pixels(&pic);
        assert_eq!(
            svg.matches("<image").count(),
            1,
            "the image is embedded once"
        );
        assert_eq!(svg.contains("<feColorMatrix"), lit);
        assert_agree(&png, &rendered, pic.width, &outline, &format!("lit {lit}"));
        // The comparison can fail: without the texture most pixels are far off.
        let flat = svg_pixels(&pic.textures_flattened()).1;
        let (_, over, compared) = compare(&png, &flat, pic.width, &outline, MOST);
        assert!(
            over as f64 > 5.0 * FEW * compared as f64,
            "{over} of {compared}"
        );
    }
}

/// `bytes` (an EPS or PDF file with extension `ext`) rasterised by ghostscript at 72 dpi
/// (one pixel per point, so the picture's size), anti-aliased, on white; `None`, saying
/// so, when `gs` is not installed (any other failure fails the test).
fn ghostscript_pixels(bytes: &[u8], ext: &str) -> Option<Vec<u8>> {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join(format!("picture.{ext}"));
    let output = dir.path().join("picture.png");
    std::fs::write(&input, bytes).unwrap();
    let mut gs = std::process::Command::new("gs");
    gs.args([
        "-q",
        "-dSAFER",
        "-dBATCH",
        "-dNOPAUSE",
        "-sDEVICE=png16m",
        "-r72",
        "-dGraphicsAlphaBits=4",
    ]);
    if ext == "eps" {
        gs.arg("-dEPSCrop");
    }
    gs.arg(format!("-sOutputFile={}", output.display()))
        .arg(&input);
    let done = match gs.output() {
        Ok(done) => done,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            eprintln!(
                "SKIPPED: ghostscript (`gs`) is not installed, so the {ext} textures are not \
                 rasterised (Debian: apt-get install ghostscript)"
            );
            return None;
        }
        Err(e) => panic!("gs: {e}"),
    };
    assert!(
        done.status.success() && done.stdout.is_empty() && done.stderr.is_empty(),
        "gs on the {ext}: {}\n{}\n{}",
        done.status,
        String::from_utf8_lossy(&done.stdout),
        String::from_utf8_lossy(&done.stderr)
    );
    let pixmap = resvg::tiny_skia::Pixmap::load_png(&output).unwrap();
    Some(pixmap.data().to_vec())
}

/// [`textured_floor`] stood up as a wall facing +z (the plane z = 0, texture `t` down
/// the wall), and its outline seen by `camera`.
fn textured_wall(cells: u32, lit: bool, camera: &Camera) -> (Scene, Vec<[f64; 2]>) {
    let mut scene = textured_floor(cells, 2.0, lit, checker(8));
    for v in &mut scene.vertices {
        *v = DVec3::new(v.x, -v.z, 0.0);
    }
    let vp = camera.view_projection(0.1, 100.0);
    let outline = [(-1.0, 1.0), (1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)]
        .map(|(x, y)| {
            let p = camera.project_with(&vp, DVec3::new(x, y, 0.0));
            [p.x, p.y]
        })
        .to_vec();
    (scene, outline)
}

/// The share of pixels allowed above [`MOST`] levels when ghostscript rasterises:
/// its image interpolation is not bilinear but a wider filter, which rounds off every
/// texel centre's corner over more pixels than resvg does (EPS and PDF, drawn with the
/// same matrices, give the same pixels). Measured: 2.9 % to 7.3 %; [`ALL`] holds.
const FEW_GHOSTSCRIPT: f64 = 0.1;

#[test]
fn textured_walls_in_eps_and_pdf_match_the_png_painter() {
    // As the SVG test above, rasterised by ghostscript on a white page, for a wall
    // seen head-on: ghostscript interpolates an image (`/Interpolate true`) only when
    // it is drawn axis-aligned, and draws its texels as squares otherwise. The 1 × 1
    // quad and the 8 × 8 mesh, each unlit and lit, and translucent in EPS, where the
    // fill is flattened onto the page as for flat fills.
    let camera = Camera::new(DVec3::new(0.0, 0.0, 2.6), DVec3::ZERO, 240, 180);
    for (cells, lit, alpha) in [
        (1, false, 1.0),
        (1, true, 1.0),
        (8, false, 1.0),
        (8, true, 1.0),
        (1, true, 0.6),
    ] {
        let (mut scene, outline) = textured_wall(cells, lit, &camera);
        scene.materials[0].opacity = alpha;
        let mut pic = ordered_picture(&scene, &camera);
        pic.background = Some([1.0; 4]);
        assert!(pic.has_textures());
        let png = png_pixels(&pic);
        let painters: [(&str, &dyn Painter); 2] = [
            ("eps", &EpsPainter::default()),
            ("pdf", &PdfPainter::default()),
        ];
        for (ext, painter) in painters {
            if ext == "pdf" && alpha < 1.0 {
                // PDF blends a translucent lit fragment twice (counted as approximated).
                continue;
            }
            let mut file = Vec::new();
            let stats = painter.paint(&pic, &mut file).unwrap();
            assert_eq!(stats.textures_flattened, 0, "{ext}");
            let Some(rendered) = ghostscript_pixels(&file, ext) else {
                return;
            };
            let what = format!("{ext}, {cells} × {cells} cells, lit {lit}, opacity {alpha}");
            assert_agree_within(&png, &rendered, pic.width, &outline, &what, FEW_GHOSTSCRIPT);
            // The comparison can fail: filled with mean colours most pixels are far off.
            let mut flat = Vec::new();
            painter.paint(&pic.textures_flattened(), &mut flat).unwrap();
            let flat = ghostscript_pixels(&flat, ext).unwrap();
            let (_, over, compared) = compare(&png, &flat, pic.width, &outline, MOST);
            eprintln!("{what}, flattened: {over} of {compared} pixels above {MOST} levels");
            assert!(
                over as f64 > 2.5 * FEW_GHOSTSCRIPT * compared as f64,
                "{what}: flattened, {over} of {compared}"
            );
        }
    }
}

/// The least alpha over pixels inside the floor (opaque in the PNG painter's picture,
/// away from the outline).
fn least_inner_alpha(png: &[u8], svg: &[u8], w: u32, outline: &[[f64; 2]]) -> u8 {
    (0..svg.len() / 4)
        .filter(|&i| {
            let (x, y) = ((i as u32 % w) as f64 + 0.5, (i as u32 / w) as f64 + 0.5);
            png[4 * i + 3] == 255 && !near_outline(x, y, outline, 2.0)
        })
        .map(|i| svg[4 * i + 3])
        .min()
        .unwrap_or(255)
}

#[test]
fn textured_triangles_show_no_seams() {
    // 8 × 8 cells, 128 triangles sharing edges, lit (a colour filter per fill) and
    // unlit. On a transparent page a hairline along a shared edge lets the page show
    // through the anti-aliased edge pixels: their alpha drops. Stated bound: every
    // pixel inside the floor keeps alpha ≥ 250 (the page shows through by at most 2 %;
    // flat fills with their seam flaps reach 229 in the same view, a bare mesh less).
    let camera = Camera::new(DVec3::new(0.3, 1.5, 1.9), DVec3::ZERO, 240, 180);
    let outline = floor_outline(&camera);
    for lit in [false, true] {
        let scene = textured_floor(8, 2.0, lit, checker(8));
        let pic = ordered_picture(&scene, &camera);
        let png = png_pixels(&pic);
        let (_, rendered) = svg_pixels(&pic);
        let least = least_inner_alpha(&png, &rendered, pic.width, &outline);
        eprintln!("lit {lit}: least alpha inside {least}");
        assert!(least >= 250, "lit {lit}: alpha {least} inside the floor");
        assert_agree(
            &png,
            &rendered,
            pic.width,
            &outline,
            &format!("8 × 8 cells, lit {lit}"),
        );
        // Without seam flaps the test sees the hairlines.
        let style = Style {
            seams: 0.0,
            ..Style::default()
        };
        let o = order(&scene, &camera, &OrderOptions::default()).unwrap();
        let (_, bare) = svg_pixels(&picture(&scene, &o, &style));
        let least = least_inner_alpha(&png, &bare, pic.width, &outline);
        assert!(least < 240, "lit {lit}: bare mesh, alpha {least}");
    }
}

#[test]
fn checker_corners_land_at_their_projected_points_at_a_grazing_angle() {
    // The eye 0.15 above a 2 × 2 floor, looking along it: strong perspective.
    let camera = Camera::new(
        DVec3::new(0.0, 0.15, 2.2),
        DVec3::new(0.0, 0.0, -1.0),
        320,
        200,
    );
    let n = 8u32;
    let scene = textured_floor(1, 1.0, false, checker(n));
    let pic = ordered_picture(&scene, &camera);
    let o = order(&scene, &camera, &OrderOptions::default()).unwrap();
    let vp = camera.view_projection(o.near, o.far);
    let mut pieces = 0;
    let mut checked = 0;
    for f in &pic.fragments {
        let map = *f.texture.as_deref().expect("textured");
        let affine = affine_pieces(&f.points, &map, MAX_PERSPECTIVE_ERROR);
        pieces += affine.len();
        for j in 0..=n {
            for i in 0..=n {
                let (s, t) = (f64::from(i) / f64::from(n), f64::from(j) / f64::from(n));
                // The world point with these texture coordinates, and its projection.
                let world = DVec3::new(2.0 * s - 1.0, 0.0, 1.0 - 2.0 * t);
                let p = camera.project_with(&vp, world);
                // The exact map takes the projected point back to (s, t).
                let st = map.st_at([p.x, p.y]).unwrap();
                assert!(
                    (st[0] - s).abs() < 1e-9 && (st[1] - t).abs() < 1e-9,
                    "{st:?}"
                );
                // The affine piece holding the point draws (s, t) within 0.5 px of it.
                for piece in &affine {
                    if !inside(&piece.points, [p.x, p.y]) {
                        continue;
                    }
                    let [a, b, c, d, e, ff] = piece.st_to_page;
                    let (x, y) = (a * s + c * t + e, b * s + d * t + ff);
                    let err = (x - p.x).hypot(y - p.y);
                    assert!(
                        err <= MAX_PERSPECTIVE_ERROR * 1.05,
                        "{err} px at ({s}, {t})"
                    );
                    checked += 1;
                }
            }
        }
    }
    eprintln!("grazing view: {pieces} affine pieces, {checked} corners checked");
    assert!(
        pieces > 8,
        "a grazing view needs subdivision: {pieces} pieces"
    );
    assert!(checked >= 40, "{checked}");
    // One affine map for the whole quad would be far off.
    let f = &pic.fragments[0];
    let whole = affine_pieces(&f.points, f.texture.as_deref().unwrap(), 1e9);
    let [a, b, c, d, e, ff] = whole[0].st_to_page;
    let p = camera.project_with(&vp, DVec3::new(0.0, 0.0, 0.0));
    let (x, y) = (a * 0.5 + c * 0.5 + e, b * 0.5 + d * 0.5 + ff);
    assert!((x - p.x).hypot(y - p.y) > 5.0);
}

/// Whether `p` lies in the convex polygon `t`.
fn inside(t: &[[f64; 2]], p: [f64; 2]) -> bool {
    let side =
        |a: [f64; 2], b: [f64; 2]| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    let s: Vec<f64> = (0..t.len())
        .map(|i| side(t[i], t[(i + 1) % t.len()]))
        .collect();
    s.iter().all(|&v| v >= 0.0) || s.iter().all(|&v| v <= 0.0)
}

#[test]
fn image_space_renderers_sample_as_the_png_painter() {
    let camera = Camera::new(DVec3::new(0.5, 0.6, 2.4), DVec3::ZERO, 200, 150);
    let scene = textured_floor(4, 3.0, true, checker(8));
    let pic = ordered_picture(&scene, &camera);
    // Pixels whose centre lies on an edge between faces may go to either face (whose
    // flat lighting differs a little): left out, as in every per-pixel comparison.
    // Both sample the same bilinear texture at each pixel centre: equal up to the
    // rounding of the texture coordinates.
    references_agree_with_png(&scene, &camera, &pic, &pic, 1);
}

/// Renders `pic` with the PNG painter (no anti-aliasing) and compares it with the
/// z-buffer's and ray casting's pictures of `scene` pixel by pixel, leaving out pixels
/// not covered opaquely, near the floor's outline or on an edge of `edges_of`'s
/// fragments: the worst channel difference is at most `worst_allowed`.
fn references_agree_with_png(
    scene: &Scene,
    camera: &Camera,
    pic: &Picture,
    edges_of: &Picture,
    worst_allowed: u8,
) {
    use limn_zbuffer::{edge_band, render, Method, RenderOptions};
    let outline = floor_outline(camera);
    let (painted, _) = PngPainter::new(PngOptions {
        anti_alias: false,
        ..PngOptions::default()
    })
    .render(pic)
    .unwrap();
    let painted = painted.data();
    let mut edges = Vec::new();
    for f in &edges_of.fragments {
        let n = f.points.len();
        for i in 0..n {
            edges.push((f.points[i], f.points[(i + 1) % n]));
        }
    }
    let band = edge_band(&edges, 200, 150, 0.5);
    for method in [Method::ZBuffer, Method::RayCast] {
        let r = render(scene, camera, method, &RenderOptions::default()).unwrap();
        let mut compared = 0;
        let mut worst = 0u8;
        for (i, px) in r.color.pixels.iter().enumerate() {
            let (x, y) = ((i as u32 % 200) as f64 + 0.5, (i as u32 / 200) as f64 + 0.5);
            if painted[4 * i + 3] != 255
                || band.get(x as u32, y as u32)
                || near_outline(x, y, &outline, 1.5)
            {
                continue;
            }
            let d = (0..3)
                .map(|k| px[k].abs_diff(painted[4 * i + k]))
                .max()
                .unwrap();
            worst = worst.max(d);
            compared += 1;
        }
        assert!(compared > 3000, "{compared}");
        eprintln!("{method:?}: worst {worst} over {compared} pixels");
        assert!(
            worst <= worst_allowed,
            "{method:?}: worst difference {worst}"
        );
    }
}

/// [`textured_floor`] (lit) with vertex normals bent outwards like a dome's and
/// `shading`: the lighting varies smoothly across every triangle.
fn smooth_floor(cells: u32, texture: Arc<Texture>, shading: limn_scene::Shading) -> Scene {
    let mut s = textured_floor(cells, 2.0, true, texture);
    s.normals = s
        .vertices
        .iter()
        .map(|v| DVec3::new(0.9 * v.x, 1.0, 0.9 * v.z).normalize())
        .collect();
    for f in &mut s.faces {
        f.normals = Some(f.vertices.clone());
    }
    s.shading = Some(shading);
    s
}

/// 2 × 2 texels of nearly one grey: the picture shows the lighting nearly alone.
fn grey() -> Arc<Texture> {
    let mut rgba = Vec::new();
    for v in [200, 204, 204, 200] {
        rgba.extend_from_slice(&[v, v, v, 255]);
    }
    Arc::new(Texture::new("grey", 2, 2, rgba).unwrap())
}

/// The step in the PNG pixels across the quad's diagonal (from its first to its third
/// corner) along its middle: the largest channel difference between a pixel 2 px away
/// on one side and its value extrapolated linearly from the other side.
fn step_across_diagonal(png: &[u8], w: u32, camera: &Camera) -> u8 {
    let vp = camera.view_projection(0.1, 100.0);
    let at = |x: f64, z: f64| {
        let p = camera.project_with(&vp, DVec3::new(x, 0.0, z));
        [p.x, p.y]
    };
    // Corners 0 and 2 of the cell: (-1, 0, 1) and (1, 0, -1).
    let (a, b) = (at(-1.0, 1.0), at(1.0, -1.0));
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len = dx.hypot(dy);
    let (nx, ny) = (-dy / len, dx / len);
    let pixel = |x: f64, y: f64| {
        let i = 4 * (y as usize * w as usize + x as usize);
        &png[i..i + 3]
    };
    // The pixel 2 px on one side against its value extrapolated from the pixels 2 and
    // 6 px on the other (the lighting's own gradient taken out).
    let mut worst = 0.0f64;
    for k in 8..=24 {
        let t = f64::from(k) / 32.0;
        let (x, y) = (a[0] + t * dx, a[1] + t * dy);
        let p = pixel(x + 2.0 * nx, y + 2.0 * ny);
        let far = pixel(x + 6.0 * nx, y + 6.0 * ny);
        let q = pixel(x - 2.0 * nx, y - 2.0 * ny);
        for c in 0..3 {
            let expected = 2.0 * f64::from(p[c]) - f64::from(far[c]);
            worst = worst.max((f64::from(q[c]) - expected).abs());
        }
    }
    worst.round() as u8
}

#[test]
fn a_smoothly_lit_textured_quad_shows_no_diagonal() {
    // One quad (two triangles) of one grey texel, Gouraud and Phong: across the shared
    // diagonal the lit colour runs on, so the PNG shows no step there; drawn flat, the
    // two triangles are lit differently and the step shows (the test can fail).
    let camera = Camera::new(DVec3::new(0.3, 2.2, 1.2), DVec3::ZERO, 240, 180);
    for shading in [limn_scene::Shading::Gouraud, limn_scene::Shading::Phong] {
        let scene = smooth_floor(1, grey(), shading);
        let o = order(&scene, &camera, &OrderOptions::default()).unwrap();
        let pic = picture(&scene, &o, &Style::default());
        assert!(pic.has_textures());
        assert!(pic.fragments.iter().all(|f| f.vertex_colors.is_some()));
        let smooth = step_across_diagonal(&png_pixels(&pic), pic.width, &camera);
        let flat_style = Style {
            smooth: false,
            ..Style::default()
        };
        let flat = picture(&scene, &o, &flat_style);
        let step = step_across_diagonal(&png_pixels(&flat), pic.width, &camera);
        eprintln!("{shading:?}: {smooth} levels across the diagonal, flat {step}");
        assert!(smooth <= 5, "{shading:?}: a step of {smooth} levels");
        assert!(step >= 8, "flat: a step of only {step} levels");
    }
}

/// A Gouraud-lit textured wall (4 × 4 cells, its normals bent about the wall's own
/// axes) and its outline seen by `camera`.
fn smoothly_lit_wall(camera: &Camera) -> (Scene, Vec<[f64; 2]>) {
    let (wall, outline) = textured_wall(4, true, camera);
    let mut scene = smooth_floor(4, checker(8), limn_scene::Shading::Gouraud);
    scene.vertices = wall.vertices;
    scene.normals = scene
        .vertices
        .iter()
        .map(|v| DVec3::new(0.9 * v.x, 0.9 * v.y, 1.0).normalize())
        .collect();
    (scene, outline)
}

#[test]
fn smoothly_lit_textures_in_svg_and_pdf_match_the_png_painter() {
    // The lit colours multiplied over the texture: in SVG a group with
    // `mix-blend-mode:multiply` (resvg), in PDF a transparency group with the blend
    // mode Multiply (ghostscript), against the PNG painter's per-pixel product. Flat
    // shading (the colours of the triangles' centroids) is far off: the test can fail.
    let camera = Camera::new(DVec3::new(0.0, 0.0, 2.6), DVec3::ZERO, 240, 180);
    let (scene, outline) = smoothly_lit_wall(&camera);
    let mut pic = ordered_picture(&scene, &camera);
    pic.background = Some([1.0; 4]);
    assert!(pic.fragments.iter().any(|f| f.vertex_colors.is_some()));
    let png = png_pixels(&pic);
    let (svg, rendered) = svg_pixels(&pic);
    assert!(svg.contains("mix-blend-mode:multiply"));
    assert!(!svg.contains("<feColorMatrix"));
    // The share only: the smooth fills themselves (untextured as well) show a dark
    // line one pixel wide along a few shared edges in resvg and librsvg.
    let (worst, over, compared) = compare(&png, &rendered, pic.width, &outline, MOST);
    eprintln!("svg, Gouraud: worst {worst}, {over} of {compared} pixels above {MOST} levels");
    assert!(compared > 10_000 && (over as f64) <= FEW * compared as f64);
    let mut flat_scene = scene.clone();
    flat_scene.shading = Some(limn_scene::Shading::Flat);
    let mut flat = ordered_picture(&flat_scene, &camera);
    flat.background = Some([1.0; 4]);
    let (_, over, compared) = compare(&png, &svg_pixels(&flat).1, pic.width, &outline, MOST);
    eprintln!("svg, flat: {over} of {compared} pixels above {MOST} levels");
    assert!(
        over as f64 > 5.0 * FEW * compared as f64,
        "{over} of {compared}"
    );
    let mut pdf = Vec::new();
    PdfPainter::default().paint(&pic, &mut pdf).unwrap();
    assert!(String::from_utf8_lossy(&pdf).contains("/Mul gs"));
    if let Some(rendered) = ghostscript_pixels(&pdf, "pdf") {
        assert_agree_within(&png, &rendered, pic.width, &outline, "pdf", FEW_GHOSTSCRIPT);
    }
}

#[test]
fn image_space_renderers_light_textures_as_the_png_painter() {
    // Phong: the painter's triangles are within 1/255 of per-point lighting, which the
    // references compute at each pixel's point, times the same bilinear sample.
    let camera = Camera::new(DVec3::new(0.5, 0.6, 2.4), DVec3::ZERO, 200, 150);
    let scene = smooth_floor(4, checker(8), limn_scene::Shading::Phong);
    let pic = ordered_picture(&scene, &camera);
    // The faces' edges (Phong's triangles inside them are not edges between faces).
    let faces = picture(
        &scene,
        &order(&scene, &camera, &OrderOptions::default()).unwrap(),
        &Style {
            smooth: false,
            ..Style::default()
        },
    );
    references_agree_with_png(&scene, &camera, &pic, &faces, 3);
}

#[test]
fn vertex_colours_multiply_the_texture() {
    // An unlit quad of one grey with red, green, blue and white corners: near each
    // corner the picture is that colour times the grey (ignored, every pixel would be
    // the grey: the test can fail).
    let mut scene = textured_floor(1, 1.0, false, grey());
    scene.colors = vec![
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 1.0],
        [0.0, 0.0, 1.0],
    ];
    for f in &mut scene.faces {
        f.colors = Some(f.vertices.clone());
    }
    let camera = Camera::new(DVec3::new(0.0, 3.0, 0.01), DVec3::ZERO, 200, 200);
    let pic = ordered_picture(&scene, &camera);
    assert!(pic.has_textures());
    let png = png_pixels(&pic);
    let vp = camera.view_projection(0.1, 100.0);
    for (v, want) in scene.vertices.iter().zip(&scene.colors) {
        // 4 % of the way from the corner towards the centre.
        let p = camera.project_with(&vp, *v * 0.96);
        let i = 4 * (p.y as usize * 200 + p.x as usize);
        for k in 0..3 {
            let expected = want[k] * 202.0;
            let got = f64::from(png[i + k]);
            assert!(
                (got - expected).abs() < 30.0,
                "corner {v}: channel {k} is {got}, expected about {expected}"
            );
        }
    }
}

/// An 8 × 8 texture whose red rises along s and green along t, over a soft checker of
/// blue: every repetition, mirror image and edge strip tells where it samples.
fn ramps() -> Arc<Texture> {
    let mut rgba = Vec::new();
    for j in 0..8u8 {
        for i in 0..8u8 {
            let b = if (i + j) % 2 == 0 { 90 } else { 150 };
            rgba.extend_from_slice(&[50 + 22 * i, 50 + 22 * j, b, 255]);
        }
    }
    Arc::new(Texture::new("ramps", 8, 8, rgba).unwrap())
}

/// The colour of a texture under `wrap` at `st`, sampled as OpenGL and glTF
/// define it (bilinear between texel centres, each neighbour's index wrapped by the
/// mode), for 8-bit channels.
fn wrapped_sample(t: &Texture, wrap: [Wrap; 2], st: [f64; 2]) -> [f64; 3] {
    let index = |i: i64, n: i64, w: Wrap| match w {
        Wrap::Repeat => i.rem_euclid(n),
        Wrap::ClampToEdge => i.clamp(0, n - 1),
        Wrap::MirroredRepeat => {
            let m = i.rem_euclid(2 * n);
            if m < n {
                m
            } else {
                2 * n - 1 - m
            }
        }
    };
    let (w, h) = (i64::from(t.width()), i64::from(t.height()));
    let (x, y) = (st[0] * w as f64 - 0.5, st[1] * h as f64 - 0.5);
    let (ax, ay) = (x - x.floor(), y - y.floor());
    let (i, j) = (x.floor() as i64, y.floor() as i64);
    let texel = |i: i64, j: i64| {
        let (i, j) = (index(i, w, wrap[0]), index(j, h, wrap[1]));
        let at = 4 * (j * w + i) as usize;
        [0, 1, 2].map(|k| f64::from(t.rgba()[at + k]))
    };
    let (c00, c10, c01, c11) = (
        texel(i, j),
        texel(i + 1, j),
        texel(i, j + 1),
        texel(i + 1, j + 1),
    );
    [0, 1, 2].map(|k| {
        let top = c00[k] + (c10[k] - c00[k]) * ax;
        let bottom = c01[k] + (c11[k] - c01[k]) * ax;
        top + (bottom - top) * ay
    })
}

#[test]
fn wrap_modes_draw_mirrored_and_clamped_texels() {
    // A wall [-1, 1]² seen head-on with texture coordinates -1 … 2 along both axes
    // over an 8 × 8 texture, under every pair of wrap modes: the PNG painter's pixels
    // against the wrapped sampler computed here, and SVG (resvg), PDF and EPS
    // (ghostscript) against the PNG painter.
    let camera = Camera::new(DVec3::new(0.0, 0.0, 2.6), DVec3::ZERO, 240, 180);
    let modes = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge];
    let texture = ramps();
    for ws in modes {
        for wt in modes {
            let wrap = [ws, wt];
            let (mut scene, outline) = textured_wall(1, false, &camera);
            scene.materials[0].texture = Some(texture.clone());
            for st in &mut scene.texcoords {
                *st = st.map(|c| 1.5 * c - 1.0);
            }
            let changed = limn_scene::wrap_material_texture(&mut scene, 0, wrap).unwrap();
            assert_eq!(changed, wrap != [Wrap::Repeat; 2]);
            let mut pic = ordered_picture(&scene, &camera);
            pic.background = Some([1.0; 4]);
            let png = png_pixels(&pic);
            // The wall's corners on the page: top left (s, t) = (-1, 2), bottom right
            // (2, -1); head-on, the page maps affinely onto texture coordinates.
            let (lo, hi) = (outline[0], outline[2]);
            let mut worst = 0.0f64;
            let mut compared = 0;
            for (i, px) in png.chunks_exact(4).enumerate() {
                let (x, y) = ((i as u32 % 240) as f64 + 0.5, (i as u32 / 240) as f64 + 0.5);
                let inner =
                    x > lo[0] + 2.0 && x < hi[0] - 2.0 && y > lo[1] + 2.0 && y < hi[1] - 2.0;
                if !inner {
                    continue;
                }
                let st = [
                    -1.0 + 3.0 * (x - lo[0]) / (hi[0] - lo[0]),
                    2.0 - 3.0 * (y - lo[1]) / (hi[1] - lo[1]),
                ];
                let want = wrapped_sample(&texture, wrap, st);
                for k in 0..3 {
                    worst = worst.max((f64::from(px[k]) - want[k]).abs());
                }
                compared += 1;
            }
            let what = format!("{ws:?}/{wt:?}");
            eprintln!("{what}: PNG against the wrapped sampler: worst {worst:.1} over {compared}");
            assert!(compared > 10_000, "{what}: {compared}");
            // Up to rounding (8-bit channels, the painter's own page-to-texture map); a
            // texel out of place is off by 22 levels or more.
            assert!(worst <= 6.0, "{what}: worst {worst}");
            let (_, svg) = svg_pixels(&pic);
            assert_agree(&png, &svg, pic.width, &outline, &format!("{what}, svg"));
            let painters: [(&str, &dyn Painter); 2] = [
                ("eps", &EpsPainter::default()),
                ("pdf", &PdfPainter::default()),
            ];
            for (ext, painter) in painters {
                let mut file = Vec::new();
                painter.paint(&pic, &mut file).unwrap();
                let Some(rendered) = ghostscript_pixels(&file, ext) else {
                    return;
                };
                assert_agree_within(
                    &png,
                    &rendered,
                    pic.width,
                    &outline,
                    &format!("{what}, {ext}"),
                    FEW_GHOSTSCRIPT,
                );
            }
        }
    }
}

/// An 8 × 8 texture whose left half (texels 0–3 of each row) is an opaque blue and
/// whose right half is the same blue with alpha `right` (`mode` says how it is drawn).
fn half_alpha(mode: TextureAlpha, right: u8) -> Arc<Texture> {
    let mut rgba = Vec::new();
    for _ in 0..8 {
        for i in 0..8 {
            let a = if i < 4 { 255 } else { right };
            rgba.extend_from_slice(&[40, 120, 200, a]);
        }
    }
    Arc::new(Texture::new("half", 8, 8, rgba).unwrap().with_alpha(mode))
}

/// A textured wall of `cells` × `cells` cells (texture `t` once across it, unlit white)
/// in front of a red unlit wall at z = −0.5 that reaches beyond it, seen head-on; and
/// the textured wall's outline.
fn wall_before_red(t: Arc<Texture>, cells: u32, camera: &Camera) -> (Scene, Vec<[f64; 2]>) {
    let mut scene = textured_floor(cells, 1.0, false, t);
    for v in &mut scene.vertices {
        *v = DVec3::new(v.x, -v.z, 0.0);
    }
    let red = scene.add_material(Material::unlit("red", [1.0, 0.0, 0.0]));
    let obj = scene.add_object("back");
    let base = scene.vertices.len() as u32;
    for (x, y) in [(-9.0, -9.0), (9.0, -9.0), (9.0, 9.0), (-9.0, 9.0)] {
        scene.add_vertex(DVec3::new(x, y, -0.5));
    }
    scene
        .add_face(&[base, base + 1, base + 2, base + 3], red, obj)
        .unwrap();
    let vp = camera.view_projection(0.1, 100.0);
    let outline = [(-1.0, 1.0), (1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)]
        .map(|(x, y)| {
            let p = camera.project_with(&vp, DVec3::new(x, y, 0.0));
            [p.x, p.y]
        })
        .to_vec();
    (scene, outline)
}

/// The colour expected at page point `p` of [`wall_before_red`] drawn with
/// [`half_alpha`] (alpha `right` on the right half, `mode`), worked out from the
/// scene rather than by any painter: red beyond the wall, on it the blue over the red
/// with the texture's alpha at the point (under a mask, the alpha of the texel holding
/// it, 1 or 0; under `Blend`, bilinear between texel centres, repeating); `None`
/// within 2 pixels of the wall's outline or its middle (anti-aliased edges).
fn expected_half_alpha(
    p: [f64; 2],
    outline: &[[f64; 2]],
    mode: TextureAlpha,
    right: u8,
) -> Option<[u8; 3]> {
    let middle = [
        [
            (outline[0][0] + outline[1][0]) / 2.0,
            (outline[0][1] + outline[1][1]) / 2.0,
        ],
        [
            (outline[2][0] + outline[3][0]) / 2.0,
            (outline[2][1] + outline[3][1]) / 2.0,
        ],
    ];
    if near_outline(p[0], p[1], outline, 2.0) || near_outline(p[0], p[1], &middle, 2.0) {
        return None;
    }
    let (lo, hi) = (
        outline.iter().map(|q| q[0]).fold(f64::INFINITY, f64::min),
        outline
            .iter()
            .map(|q| q[0])
            .fold(f64::NEG_INFINITY, f64::max),
    );
    let (top, bottom) = (
        outline.iter().map(|q| q[1]).fold(f64::INFINITY, f64::min),
        outline
            .iter()
            .map(|q| q[1])
            .fold(f64::NEG_INFINITY, f64::max),
    );
    let blue = [40.0, 120.0, 200.0];
    let red = [255.0, 0.0, 0.0];
    let on_wall = p[0] > lo && p[0] < hi && p[1] > top && p[1] < bottom;
    // Seen head-on, the texture lies affinely on the page: s from the wall's left
    // edge to its right one. Texel i's alpha, repeating.
    let s = (p[0] - lo) / (hi - lo);
    let texel = |i: f64| {
        if i.rem_euclid(8.0) < 4.0 {
            1.0
        } else {
            match mode {
                TextureAlpha::Mask => f64::from(u8::from(right >= 128)),
                _ => f64::from(right) / 255.0,
            }
        }
    };
    let a = if !on_wall {
        0.0
    } else {
        match mode {
            // The texel holding the point.
            TextureAlpha::Mask | TextureAlpha::Opaque => texel((s * 8.0).floor()),
            // Bilinear between texel centres (the texture's colour is one).
            TextureAlpha::Blend => {
                let x = s * 8.0 - 0.5;
                let (i, f) = (x.floor(), x - x.floor());
                (1.0 - f) * texel(i) + f * texel(i + 1.0)
            }
        }
    };
    Some([0, 1, 2].map(|k| (a * blue[k] + (1.0 - a) * red[k]).round() as u8))
}

/// How many pixels of `pixels` (RGBA, `w` wide) differ from [`expected_half_alpha`] by
/// more than `tolerance` levels in some channel, and how many were compared.
fn off_half_alpha(
    pixels: &[u8],
    w: u32,
    outline: &[[f64; 2]],
    mode: TextureAlpha,
    right: u8,
    tolerance: u8,
) -> (usize, usize) {
    let (mut off, mut compared) = (0, 0);
    for (i, px) in pixels.chunks_exact(4).enumerate() {
        let p = [(i as u32 % w) as f64 + 0.5, (i as u32 / w) as f64 + 0.5];
        let Some(want) = expected_half_alpha(p, outline, mode, right) else {
            continue;
        };
        compared += 1;
        if (0..3).any(|k| px[k].abs_diff(want[k]) > tolerance) {
            if off == 0 {
                eprintln!("first off at {p:?}: {:?}, expected {want:?}", &px[..4]);
            }
            off += 1;
        }
    }
    (off, compared)
}

#[test]
fn texture_alpha_cuts_and_blends_in_every_format() {
    // A wall whose texture's right half is transparent (a cut-out, and blended at
    // alpha 0 and 128) in front of a red wall: the red shows through the right half,
    // in the PNG painter as worked out independently, with the ordinary painter's
    // order and with the visible map (which must not hide the red wall behind the
    // cut-out); the SVG (resvg), PDF and EPS (ghostscript) agree with the PNG.
    let camera = Camera::new(DVec3::new(0.0, 0.0, 2.6), DVec3::ZERO, 240, 180);
    for (mode, right) in [
        (TextureAlpha::Mask, 0),
        (TextureAlpha::Blend, 0),
        (TextureAlpha::Blend, 128),
    ] {
        for cells in [1, 4] {
            let (scene, outline) = wall_before_red(half_alpha(mode, right), cells, &camera);
            assert!(!scene.materials[0].is_opaque(), "{mode:?}");
            for visible in [false, true] {
                let opts = OrderOptions {
                    visible,
                    ..OrderOptions::default()
                };
                let o = order(&scene, &camera, &opts).unwrap();
                let pic = picture(&scene, &o, &Style::default());
                let png = png_pixels(&pic);
                let what = format!("{mode:?} {right}, {cells} cells, visible {visible}");
                let (off, compared) = off_half_alpha(&png, pic.width, &outline, mode, right, 2);
                eprintln!("{what}: png {off} of {compared} pixels off");
                assert!(compared > 30_000, "{what}");
                assert_eq!(off, 0, "{what}: png");
                // Drawn opaque, the same test fails on the right half.
                let mut opaque = pic.clone();
                opaque.textures = opaque
                    .textures
                    .iter()
                    .map(|t| Arc::new(Texture::clone(t).with_alpha(TextureAlpha::Opaque)))
                    .collect();
                let (off_opaque, _) =
                    off_half_alpha(&png_pixels(&opaque), pic.width, &outline, mode, right, 2);
                assert!(off_opaque > compared / 10, "{what}: {off_opaque}");
                // Blended faces, as translucent ones, get no seam flaps: viewers that
                // anti-alias each path on its own show the red through their shared
                // edges. Compared in the viewers as one cell, its diagonal left out.
                if visible || (mode == TextureAlpha::Blend && cells > 1) {
                    continue;
                }
                // The renderers anti-alias the cut-out's edge down the wall's middle as
                // any edge, each its own way: left out with the outline (and the
                // diagonal from outline[3] to outline[1]).
                let mid = |a: [f64; 2], b: [f64; 2]| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
                let (top, bottom) = (mid(outline[0], outline[1]), mid(outline[2], outline[3]));
                let mut outline = vec![
                    outline[0], top, bottom, top, outline[1], outline[2], outline[3],
                ];
                if mode == TextureAlpha::Blend {
                    outline.extend([outline[4], outline[6]]);
                }
                let (_, svg) = svg_pixels(&pic);
                assert_agree(&png, &svg, pic.width, &outline, &format!("{what}, svg"));
                let painters: [(&str, &dyn Painter); 2] = [
                    ("eps", &EpsPainter::default()),
                    ("pdf", &PdfPainter::default()),
                ];
                for (ext, painter) in painters {
                    let mut file = Vec::new();
                    let stats = painter.paint(&pic, &mut file).unwrap();
                    if ext == "eps" && mode == TextureAlpha::Blend {
                        // No soft alpha in PostScript: drawn opaque, counted.
                        assert!(stats.approximated > 0, "{what}");
                        continue;
                    }
                    assert_eq!(stats.approximated, 0, "{what}, {ext}");
                    let Some(rendered) = ghostscript_pixels(&file, ext) else {
                        return;
                    };
                    let what = format!("{what}, {ext}");
                    assert_agree_within(&png, &rendered, pic.width, &outline, &what, FEW);
                }
            }
        }
    }
}

/// `pic` with its opaque textured fragments drawn from the page image, as the command
/// writes SVG and PDF.
fn paged(pic: &Picture) -> Picture {
    let mut p = pic.clone();
    assert!(draw_from_page_image(&mut p, DEFAULT_TEXTURE_SAMPLES) > 0);
    p
}

#[test]
fn the_page_image_matches_the_png_painter() {
    // The quad unlit (a fill colour) and lit, the 8 × 8 floor (128 triangles, one run:
    // no hairline, every pixel inside opaque) and the smoothly lit wall, each drawn
    // from the page image: resvg's SVG and ghostscript's PDF against the PNG painter's
    // picture as composed, with the bounds of the tests above. Without the texture the
    // comparison fails.
    let camera = Camera::new(DVec3::new(0.6, 1.4, 2.6), DVec3::ZERO, 240, 180);
    let outline = floor_outline(&camera);
    let mut cases = Vec::new();
    for (cells, lit) in [(1, false), (1, true), (8, true)] {
        let scene = textured_floor(cells, 2.0, lit, checker(8));
        let mut pic = ordered_picture(&scene, &camera);
        pic.background = Some([1.0; 4]);
        cases.push((
            format!("{cells} × {cells} cells, lit {lit}"),
            pic,
            outline.clone(),
        ));
    }
    let wall_camera = Camera::new(DVec3::new(0.0, 0.0, 2.6), DVec3::ZERO, 240, 180);
    let (scene, wall_outline) = smoothly_lit_wall(&wall_camera);
    let mut pic = ordered_picture(&scene, &wall_camera);
    pic.background = Some([1.0; 4]);
    cases.push((
        "the smoothly lit wall".into(),
        pic.clone(),
        wall_outline.clone(),
    ));
    // Translucent: the wall's lit colours times its texture from an image of its own,
    // blended once with the page.
    for f in &mut pic.fragments {
        f.fill[3] = 0.5;
        if let Some(cs) = &mut f.vertex_colors {
            cs.iter_mut().for_each(|c| c[3] = 0.5);
        }
    }
    cases.push((
        "the smoothly lit wall at opacity 0.5".into(),
        pic,
        wall_outline,
    ));
    for (what, pic, outline) in cases {
        let png = png_pixels(&pic);
        let page = paged(&pic);
        let (svg, rendered) = svg_pixels(&page);
        // Opaque: one clip, the run of the floor's fragments (and their flaps) as one
        // union. Translucent: each face from an image of its own (its own unit clip).
        let clips = svg.matches("<clipPath").count();
        if pic.fragments.iter().all(|f| f.fill[3] >= 1.0) {
            assert_eq!(clips, 1, "{what}");
        } else {
            assert_eq!(
                svg.matches("<clipPath id=\"tc").count(),
                clips / 2,
                "{what}"
            );
        }
        assert!(!svg.contains("<feColorMatrix") && !svg.contains("mix-blend-mode"));
        assert_agree(
            &png,
            &rendered,
            pic.width,
            &outline,
            &format!("{what}, SVG"),
        );
        let mut pdf = Vec::new();
        PdfPainter::default().paint(&page, &mut pdf).unwrap();
        let translucent = pic.fragments.iter().any(|f| f.fill[3] < 1.0);
        match ghostscript_pixels(&pdf, "pdf") {
            // Ghostscript blends the edge pixels two translucent faces share twice
            // (each face's clip takes them): a line along every edge, a few per cent of
            // the pixels (two thirds of them with each face under its own maps).
            Some(rendered) if translucent => {
                let (worst, over, compared) = compare(&png, &rendered, pic.width, &outline, MOST);
                eprintln!(
                    "{what}, PDF: worst {worst}, {over} of {compared} pixels above {MOST} levels"
                );
                assert!(
                    over as f64 <= 0.1 * compared as f64,
                    "{what}, PDF: {over} of {compared}"
                );
            }
            Some(rendered) => {
                let what = format!("{what}, PDF");
                assert_agree_within(&png, &rendered, pic.width, &outline, &what, FEW_GHOSTSCRIPT);
            }
            None => {}
        }
        let flat = svg_pixels(&paged(&pic).textures_flattened()).1;
        let (_, over, compared) = compare(&png, &flat, pic.width, &outline, MOST);
        assert!(
            over as f64 > 5.0 * FEW * compared as f64,
            "{what}: flattened, {over} of {compared}"
        );
    }
}
