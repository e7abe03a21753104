//! The picture limn writes by default is the exact picture: the painted fragments (with
//! whole-face covers and seam flaps, as the writers receive them) give every pixel centre
//! the face exact ray casting sees, outside a 1/64-pixel band around the true edges.

use limn_depthsort::{OrderOptions, SortMode};
use limn_paint::{picture, seam_flaps, Style};
use limn_scene::{shapes, Camera, Material, Scene};
use limn_tests::corpus;
use limn_tests::reference::{paint, Painted};
use limn_zbuffer::{compare, rasterize_ids, DepthFormat, IdImage, Method};

/// The order, set up for comparison as `limn check` does, and exact ray casting's ids.
fn ordered_and_raycast(scene: &Scene, camera: &Camera, sort: SortMode) -> (Painted, IdImage) {
    let opts = OrderOptions {
        sort,
        ..OrderOptions::default()
    };
    let p = paint(scene, camera, &opts);
    let reference = p
        .reference(scene, Method::RayCast, DepthFormat::F64)
        .expect("ray casting");
    (p, reference)
}

const BAND_PX: f64 = 1.0 / 64.0;

/// The band for pictures rasterised by tiny-skia: 1/64 px for the picture, and 1/64 px
/// more for tiny-skia's own fixed-point edges (26.6: 1/64 px), which alone move a few
/// pixel centres at 1/64 px from an edge.
const RASTER_BAND_PX: f64 = 1.0 / 32.0;

/// Pixels outside the band where the default picture disagrees with ray casting, and
/// the corners seam flaps add to the picture (as fragments of their own or joined into
/// their fragments' outlines).
fn wrong_pixels(scene: &Scene, camera: &Camera, sort: SortMode) -> (usize, usize) {
    let (p, reference) = ordered_and_raycast(scene, camera, sort);
    let o = &p.ordered;
    let pic = picture(scene, o, &Style::default());
    let corners = |style: &Style| -> usize {
        let pic = picture(scene, o, style);
        pic.fragments.iter().map(|f| f.points.len()).sum()
    };
    let no_flaps = Style {
        seams: 0.0,
        ..Style::default()
    };
    let flaps = corners(&Style::default()) - corners(&no_flaps);
    let (w, h) = (o.camera.width, o.camera.height);
    let painted: Vec<(Vec<[f64; 2]>, u32)> = pic
        .fragments
        .iter()
        .map(|f| (f.points.clone(), f.face))
        .collect();
    // True edges: the scene's edges and where faces meet (the fragments' edges).
    let band = p.band_with(BAND_PX);
    let c = compare(&rasterize_ids(&painted, w, h), &reference, Some(&band));
    (c.mismatches_outside_band, flaps)
}

#[test]
fn default_pictures_of_the_corpus_are_exact() {
    let mut flaps = 0;
    for case in corpus::all() {
        for sort in [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell] {
            let (bad, f) = wrong_pixels(&case.scene, &case.camera, sort);
            flaps += f;
            assert_eq!(
                bad,
                0,
                "{} / {}: {bad} wrong pixels",
                case.name,
                sort.name()
            );
        }
    }
    assert!(flaps > 0, "the corpus must exercise seam flaps");
}

#[test]
fn default_pictures_of_meshes_and_soups_are_exact() {
    let mut sphere = Scene::default();
    let m = sphere.add_material(Material::diffuse("s", [0.7, 0.7, 0.7]));
    let o = sphere.add_object("s");
    shapes::uv_sphere(&mut sphere, glam::DVec3::ZERO, 1.0, 12, 24, m, o).unwrap();
    let mut soup = Scene::default();
    let m = soup.add_material(Material::diffuse("soup", [0.7, 0.7, 0.7]));
    let o = soup.add_object("soup");
    shapes::random_soup(&mut soup, 300, 0.4, 7, m, o).unwrap();
    for (name, scene) in [("sphere", &sphere), ("soup", &soup)] {
        let cam = Camera::framing(scene, 160, 120).unwrap();
        for sort in [SortMode::Adaptive, SortMode::Bsp] {
            let (bad, flaps) = wrong_pixels(scene, &cam, sort);
            assert_eq!(bad, 0, "{name} / {}: {bad} wrong pixels", sort.name());
            // Neighbouring mesh faces share edges, so the sphere has flaps; soup
            // triangles share none, but the pieces of one triangle split by another
            // may get flaps into each other.
            if name == "sphere" {
                assert!(flaps > 0, "{name}: {flaps} flaps");
            }
        }
    }
}

#[test]
fn flaps_go_only_under_later_opaque_faces_of_other_faces() {
    use limn_paint::PaintFragment;
    // Two unit squares sharing the edge x = 1, and a translucent third one.
    let sq = |x0: f64| vec![[x0, 0.0], [x0 + 1.0, 0.0], [x0 + 1.0, 1.0], [x0, 1.0]];
    let mut a = PaintFragment::new(sq(0.0), [1.0, 0.0, 0.0, 1.0]);
    a.face = 0;
    let mut b = PaintFragment::new(sq(1.0), [0.0, 1.0, 0.0, 1.0]);
    b.face = 1;
    let mut c = PaintFragment::new(sq(2.0), [0.0, 0.0, 1.0, 0.5]);
    c.face = 2;
    let out = seam_flaps(vec![a.clone(), b.clone(), c.clone()], 0.25);
    // a gets one flap inside b (x in [1, 1.25]); b's edge with the translucent c gets
    // none, and b is not flapped back under a (painted earlier).
    assert_eq!(out.len(), 4, "{out:?}");
    let flap = &out[1];
    assert_eq!(flap.fill, a.fill);
    assert!(
        flap.points.iter().all(|p| (1.0..=1.25).contains(&p[0])),
        "{flap:?}"
    );
    assert!(flap.original_edges.iter().all(|&o| !o));
    // Reversed order: b first, then a: the flap goes under a, on a's side.
    let out = seam_flaps(vec![b, a], 0.25);
    assert_eq!(out.len(), 3);
    assert!(out[1].points.iter().all(|p| (0.75..=1.0).contains(&p[0])));
}

/// Pixels outside the band where the SVG limn writes by default, rasterised without
/// anti-aliasing, shows another colour than the face exact ray casting sees
/// (pixels of translucent or smooth-shaded faces are not compared).
fn svg_wrong_pixels(scene: &Scene, camera: &Camera) -> usize {
    use limn_paint::{Painter, SvgPainter};
    let (p, reference) = ordered_and_raycast(scene, camera, SortMode::Adaptive);
    let o = &p.ordered;
    let pic = picture(scene, o, &Style::default());
    let mut svg = Vec::new();
    SvgPainter::default().paint(&pic, &mut svg).expect("svg");
    let svg = String::from_utf8(svg).expect("utf-8").replacen(
        "<svg ",
        "<svg shape-rendering=\"crispEdges\" ",
        1,
    );
    let tree = resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default()).expect("parse");
    let (w, h) = (o.camera.width, o.camera.height);
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).expect("pixmap");
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::identity(),
        &mut pixmap.as_mut(),
    );
    // The colour each face is painted in (flat, opaque faces only).
    let mut colour: Vec<Option<[u8; 3]>> = vec![None; scene.faces.len()];
    let mut excluded = vec![false; scene.faces.len()];
    for f in &pic.fragments {
        let c = f.fill.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
        if f.fill[3] < 1.0 || f.vertex_colors.is_some() {
            excluded[f.face as usize] = true;
        }
        colour[f.face as usize] = Some([c[0], c[1], c[2]]);
    }
    let band = p.band_with(RASTER_BAND_PX);
    let mut wrong = 0;
    for y in 0..h {
        for x in 0..w {
            if band.get(x, y) {
                continue;
            }
            let px = pixmap.pixel(x, y).expect("inside");
            let got = (px.alpha() > 0).then(|| [px.red(), px.green(), px.blue()]);
            let id = reference.get(x, y).expect("inside");
            let want = if id == limn_zbuffer::NO_FACE {
                None
            } else {
                if excluded[id as usize] {
                    continue;
                }
                colour[id as usize]
            };
            if got != want {
                wrong += 1;
            }
        }
    }
    wrong
}

#[test]
fn default_svg_of_the_corpus_is_the_exact_picture() {
    let mut total = Vec::new();
    for case in corpus::all() {
        let bad = svg_wrong_pixels(&case.scene, &case.camera);
        total.push((case.name, bad));
    }
    assert!(
        total.iter().all(|&(_, b)| b == 0),
        "wrong pixels per case: {total:?}"
    );
}
