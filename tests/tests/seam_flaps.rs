//! Seam flaps never change the picture: every flap lies inside the later fragment that
//! covers it, decided exactly, so the default picture (with flaps) gives every pixel
//! centre outside the edge band the same face as the picture without them, and as exact
//! ray casting wherever that one does.
//!
//! The measurements behind BENCHMARKS.md's seam-flap rows are here too, `#[ignore]`d:
//! `LIMN_SEAM_SCENES='a.obj;a.obj@1,2,3' cargo test --release -p limn-tests --test
//! seam_flaps -- --ignored --nocapture` for files (`@` an eye), `LIMN_SEAM_SEARCH=N` for
//! N random pairs of height fields 1e-6 apart, and `survey` for the hard cases.

use std::path::Path;

use glam::DVec3;
use limn_depthsort::OrderOptions;
use limn_paint::{picture, seam_flaps_indexed, FlapJoin, PaintFragment, Style};
use limn_scene::{Camera, Material, Scene};
use limn_tests::reference::{paint, Painted};
use limn_zbuffer::{
    compare, default_band_tolerance, edge_band, rasterize_ids, DepthFormat, IdImage, Method,
};

/// Face ids of `fragments` painted in order (the last painted wins at each pixel centre).
fn ids_of(fragments: &[PaintFragment], width: u32, height: u32) -> IdImage {
    let polys: Vec<(Vec<[f64; 2]>, u32)> = fragments
        .iter()
        .map(|f| (f.points.clone(), f.face))
        .collect();
    rasterize_ids(&polys, width, height)
}

/// Three fragments in paint order: a backdrop (face 0), a triangle (face 1) and, painted
/// after it across their shared edge a–b, a triangle (face 2) whose third corner lies
/// 10¹² px away (as a face passing close to the eye projects with a small near plane).
/// The pixel centre (10.5, 10.5) lies outside the far triangle, 3.4e-5 px from its edge
/// c–a: far outside the edge band of a 64 × 48 picture (6.5e-8 px).
fn far_corner_fragments() -> Vec<PaintFragment> {
    let a = [10.297325759870414, 10.139052267325667];
    let b = [14.0, 10.139052267325667];
    let c = [1011364615736.0, 1800814051367.0];
    let fragment = |points: Vec<[f64; 2]>, face: u32| {
        let mut f = PaintFragment::new(points, [0.2 * face as f64, 0.5, 0.5, 1.0]);
        f.face = face;
        f
    };
    vec![
        fragment(vec![[0.0, 0.0], [64.0, 0.0], [64.0, 48.0], [0.0, 48.0]], 0),
        fragment(vec![b, a, [12.0, 2.0]], 1),
        fragment(vec![a, b, c], 2),
    ]
}

#[test]
fn a_flap_into_a_fragment_with_a_far_corner_stays_inside_it() {
    let frags = far_corner_fragments();
    let (w, h) = (64, 48);
    let edges: Vec<([f64; 2], [f64; 2])> = frags
        .iter()
        .flat_map(|f| {
            let n = f.points.len();
            (0..n).map(move |k| (f.points[k], f.points[(k + 1) % n]))
        })
        .collect();
    let band = edge_band(&edges, w, h, default_band_tolerance(w, h));
    let without = ids_of(&frags, w, h);
    assert_eq!(
        without.get(10, 10),
        Some(0),
        "the centre shows the backdrop"
    );
    for join in [FlapJoin::Separate, FlapJoin::Joined] {
        let (with, _) = seam_flaps_indexed(frags.clone(), 0.5, join);
        assert!(
            with.len() > frags.len() || with[1].points.len() > 3,
            "{join:?}: a flap under the far triangle"
        );
        let c = compare(&ids_of(&with, w, h), &without, Some(&band));
        assert_eq!(
            c.mismatches_outside_band,
            0,
            "{join:?}: the flap changed a pixel centre (10.5, 10.5 shows face {:?})",
            ids_of(&with, w, h).get(10, 10)
        );
    }
}

/// The scene of [`far_corner_fragments`] with corner `a` at (10.287…, 10.174…) px and the
/// far corner at about 10¹² px, seen straight on through an orthographic camera that
/// maps world (x, y) to pixel (x, 48 − y): a backdrop at z = −1, the near triangle at
/// z = −0.5 (painted before the far one), the far triangle at z = 0.
fn far_corner_scene() -> (Scene, Camera) {
    let a = [10.287359636840073, 10.174008270802116];
    let b = [14.0, a[1]];
    let c = [918496175004.0, 1407834696895.0];
    let mut s = Scene::default();
    let o = s.add_object("o");
    let m: Vec<u32> = (0..3)
        .map(|k| s.add_material(Material::unlit("m", [0.2 * k as f64, 0.5, 0.5])))
        .collect();
    let p = |q: [f64; 2], z: f64| DVec3::new(q[0], 48.0 - q[1], z);
    let backdrop = [[0.0, 0.0], [0.0, 48.0], [64.0, 48.0], [64.0, 0.0]].map(|q| p(q, -1.0));
    s.add_polygon(&backdrop, m[0], o).expect("backdrop");
    s.add_polygon(&[b, a, [12.0, 2.0]].map(|q| p(q, -0.5)), m[1], o)
        .expect("near triangle");
    s.add_polygon(&[a, b, c].map(|q| p(q, 0.0)), m[2], o)
        .expect("far triangle");
    let mut cam = Camera::orthographic(
        DVec3::new(32.0, 24.0, 10.0),
        DVec3::new(32.0, 24.0, 0.0),
        48.0,
        64,
        48,
    );
    cam.near = Some(1.0);
    cam.far = Some(20.0);
    (s, cam)
}

#[test]
fn the_default_picture_of_a_face_with_a_far_corner_is_the_picture_without_flaps() {
    let (scene, cam) = far_corner_scene();
    let (p, pics) = with_and_without(&scene, &cam);
    // Flaps were made: the near triangle's outline takes a detour under the far one.
    assert!(pics[0]
        .fragments
        .iter()
        .any(|f| f.face == 1 && f.points.len() > 3));
    let reference = p
        .reference(&scene, Method::RayCast, DepthFormat::F64)
        .expect("ray casting");
    let [with, without] = pics.map(|pic| ids_of(&pic.fragments, 64, 48));
    let wrong = |ids: &IdImage| compare(ids, &reference, Some(&p.band)).mismatches_outside_band;
    assert_eq!((wrong(&with), wrong(&without)), (0, 0));
}

#[test]
fn flaps_change_no_pixel_of_height_fields_a_millionth_apart() {
    for (name, scene, cam) in hard_height_field_views(7) {
        let (p, pics) = with_and_without(&scene, &cam);
        let reference = p
            .reference(&scene, Method::RayCast, DepthFormat::F64)
            .expect("ray casting");
        let [with, without] = pics.map(|pic| ids_of(&pic.fragments, cam.width, cam.height));
        let wrong = |ids: &IdImage| compare(ids, &reference, Some(&p.band)).mismatches_outside_band;
        assert_eq!(wrong(&with), wrong(&without), "{name}");
        let changed = compare(&with, &without, Some(&p.band)).mismatches_outside_band;
        assert_eq!(changed, 0, "{name}");
    }
}

/// Random pairs of height fields 1e-6 apart (triangles, 4² to 16² cells, rough and
/// smooth), seen from above, below, the side and close up.
fn hard_height_field_views(count: u64) -> impl Iterator<Item = (String, Scene, Camera)> {
    (0..count).map(|seed| {
        let grid = 4 + (seed % 13) as usize;
        let rough = [0.1, 0.01, 0.3][(seed % 3) as usize];
        let s = height_fields(grid, seed, 1e-6, rough);
        let eyes = [
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(-2.0, 1.5, 0.5),
            DVec3::new(0.3, 3.0, -1.0),
            DVec3::new(2.0, 0.3, 0.2),
            DVec3::new(0.0, -2.0, 1.0),
            DVec3::new(0.1, 0.35, 0.2),
            DVec3::new(-0.9, 0.25, -0.8),
        ];
        let eye = eyes[(seed / 3 % 7) as usize];
        let size = [(64, 48), (160, 120), (400, 300)][(seed / 21 % 3) as usize];
        let target = if eye.length() < 1.5 {
            DVec3::new(0.7, 0.0, 0.9)
        } else {
            DVec3::ZERO
        };
        let mut cam = Camera::new(eye, target, size.0, size.1);
        if seed % 2 == 1 {
            cam.fov_deg = 90.0;
        }
        let name = format!("seed {seed} grid {grid} rough {rough} eye {eye} size {size:?}");
        (name, s, cam)
    })
}

/// Pixels outside the band of `p` where the picture drawn with `style` disagrees with
/// `reference`: face ids (default band, 1/64 px band) and the SVG through resvg (1/32 px).
fn wrong_pixels(scene: &Scene, p: &Painted, reference: &IdImage, style: &Style) -> [usize; 3] {
    let o = &p.ordered;
    let pic = picture(scene, o, style);
    let ids = ids_of(&pic.fragments, o.camera.width, o.camera.height);
    let a = compare(&ids, reference, Some(&p.band)).mismatches_outside_band;
    let b = compare(&ids, reference, Some(&p.band_with(1.0 / 64.0))).mismatches_outside_band;
    [a, b, svg_wrong(scene, p, reference, &pic)]
}

/// The SVG limn writes for `pic`, rasterised by resvg without anti-aliasing.
fn svg_pixels(pic: &limn_paint::Picture) -> resvg::tiny_skia::Pixmap {
    use limn_paint::{Painter, SvgPainter};
    let mut svg = Vec::new();
    SvgPainter::default().paint(pic, &mut svg).expect("svg");
    let svg = String::from_utf8(svg).expect("utf-8").replacen(
        "<svg ",
        "<svg shape-rendering=\"crispEdges\" ",
        1,
    );
    let tree = resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default()).expect("parse");
    let mut pixmap = resvg::tiny_skia::Pixmap::new(pic.width, pic.height).expect("pixmap");
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::identity(),
        &mut pixmap.as_mut(),
    );
    pixmap
}

/// Pixels outside a 1/32 px band where the SVG of `pic` shows another colour than the
/// face ray casting sees (pixels of translucent or smooth faces are not compared).
fn svg_wrong(scene: &Scene, p: &Painted, reference: &IdImage, pic: &limn_paint::Picture) -> usize {
    let pixmap = svg_pixels(pic);
    let (w, h) = (pic.width, pic.height);
    let mut colour: Vec<Option<[u8; 3]>> = vec![None; scene.faces.len()];
    let mut excluded = vec![false; scene.faces.len()];
    for f in &pic.fragments {
        let c = f.fill.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
        if f.fill[3] < 1.0 || f.vertex_colors.is_some() {
            excluded[f.face as usize] = true;
        }
        colour[f.face as usize] = Some([c[0], c[1], c[2]]);
    }
    let band = p.band_with(1.0 / 32.0);
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

/// Measures files named in `LIMN_SEAM_SCENES` (`path[@x,y,z]` separated by `;`):
/// `LIMN_SEAM_SCENES='a.obj;a.obj@1,2,3' cargo test --release -p limn-tests --test
/// seam_flaps -- --ignored --nocapture`.
#[test]
#[ignore = "measures files named in LIMN_SEAM_SCENES"]
fn measure_files() {
    let Ok(list) = std::env::var("LIMN_SEAM_SCENES") else {
        return;
    };
    for item in list.split(';').filter(|s| !s.is_empty()) {
        let (path, eye) = match item.split_once('@') {
            Some((p, e)) => (p, Some(e)),
            None => (item, None),
        };
        let scene = limn_load::load(Path::new(path), &Default::default()).expect("load");
        let cam = match eye {
            None => Camera::framing(&scene, 800, 600).expect("frame"),
            Some(e) => {
                let v: Vec<f64> = e.split(',').map(|x| x.parse().expect("eye")).collect();
                let (lo, hi) = scene.bounds().expect("bounds");
                Camera::new(DVec3::new(v[0], v[1], v[2]), lo * 0.5 + hi * 0.5, 800, 600)
            }
        };
        let p = paint(&scene, &cam, &OrderOptions::default());
        let reference = p
            .reference(&scene, Method::RayCast, DepthFormat::F64)
            .expect("ray casting");
        let order_only = p.compare(&reference).mismatches_outside_band;
        let flaps = wrong_pixels(&scene, &p, &reference, &Style::default());
        let none = wrong_pixels(
            &scene,
            &p,
            &reference,
            &Style {
                seams: 0.0,
                ..Style::default()
            },
        );
        println!(
            "{item}: order {order_only}, default {flaps:?}, seams 0 {none:?}, {} flaps",
            flap_count(&scene, &p)
        );
    }
}

/// How many flaps the picture of `p` has (painted separately, as with outlines).
fn flap_count(scene: &Scene, p: &Painted) -> usize {
    let outlined = |seams: f64| Style {
        seams,
        outline: Some(limn_paint::Outline {
            color: [0.0, 0.0, 0.0, 1.0],
            width: 1.0,
        }),
        ..Style::default()
    };
    let count = |seams| picture(scene, &p.ordered, &outlined(seams)).fragments.len();
    count(0.5) - count(0.0)
}

/// The pictures of `scene` with and without flaps, and the comparison's setup.
fn with_and_without(scene: &Scene, cam: &Camera) -> (Painted, [limn_paint::Picture; 2]) {
    let p = paint(scene, cam, &OrderOptions::default());
    let pics = [0.5, 0.0].map(|seams| {
        let style = Style {
            seams,
            ..Style::default()
        };
        picture(scene, &p.ordered, &style)
    });
    (p, pics)
}

/// Pixel centres outside the edge band where the face ids of the default picture differ
/// from those of the picture without flaps.
fn id_changes(scene: &Scene, cam: &Camera) -> usize {
    let (p, pics) = with_and_without(scene, cam);
    let [with, without] = pics.map(|pic| ids_of(&pic.fragments, cam.width, cam.height));
    compare(&with, &without, Some(&p.band)).mismatches_outside_band
}

/// Pixels outside the band where the default picture differs from the picture without
/// flaps: face ids (the edge band), and PNG and SVG without anti-aliasing (outside a
/// 1/32 px band).
fn flap_changes(scene: &Scene, cam: &Camera) -> [usize; 3] {
    use limn_paint::{PngOptions, PngPainter};
    let (p, pics) = with_and_without(scene, cam);
    let band = p.band_with(1.0 / 32.0);
    let differ = |x: &[u8], y: &[u8]| {
        let pixels = x.chunks(4).zip(y.chunks(4)).enumerate();
        pixels
            .filter(|&(k, (u, v))| u != v && !band.get(k as u32 % cam.width, k as u32 / cam.width))
            .count()
    };
    let png = |pic: &limn_paint::Picture| {
        let painter = PngPainter::new(PngOptions {
            anti_alias: false,
            ..PngOptions::default()
        });
        painter.render(pic).expect("png").0.data().to_vec()
    };
    [
        id_changes(scene, cam),
        differ(&png(&pics[0]), &png(&pics[1])),
        differ(svg_pixels(&pics[0]).data(), svg_pixels(&pics[1]).data()),
    ]
}

/// Two random height fields of `n` × `n` cells (two triangles each) over [−1, 1]², the
/// second `gap` above the first, heights up to `rough`, in two colours.
fn height_fields(n: usize, seed: u64, gap: f64, rough: f64) -> Scene {
    let mut rng = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64
    };
    let h: Vec<f64> = (0..(n + 1) * (n + 1))
        .map(|_| rough * (2.0 * next() - 1.0))
        .collect();
    let mut s = Scene::default();
    let o = s.add_object("fields");
    for layer in 0..2 {
        let m = s.add_material(limn_scene::Material::unlit(
            "m",
            [0.2 + 0.6 * layer as f64, 0.3, 0.8 - 0.6 * layer as f64],
        ));
        let at = |i: usize, j: usize| {
            DVec3::new(
                -1.0 + 2.0 * i as f64 / n as f64,
                h[i * (n + 1) + j] + layer as f64 * gap,
                -1.0 + 2.0 * j as f64 / n as f64,
            )
        };
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                s.add_polygon(&[a, b, c], m, o).expect("triangle");
                s.add_polygon(&[a, c, d], m, o).expect("triangle");
            }
        }
    }
    s
}

#[test]
#[ignore = "a search: LIMN_SEAM_SEARCH=N cargo test --release -p limn-tests --test seam_flaps -- --ignored --nocapture"]
fn search_height_fields() {
    let Ok(n) = std::env::var("LIMN_SEAM_SEARCH") else {
        return;
    };
    let mut total = [0; 3];
    for (name, s, cam) in hard_height_field_views(n.parse().expect("count")) {
        let bad = flap_changes(&s, &cam);
        if bad.iter().any(|&b| b > 0) {
            println!("{name}: {bad:?}");
        }
        for k in 0..3 {
            total[k] += bad[k];
        }
    }
    println!("total {total:?}");
}

#[test]
#[ignore = "a survey: cargo test --release -p limn-tests --test seam_flaps -- --ignored --nocapture survey"]
fn survey_hard_cases() {
    let mut cases: Vec<(String, Scene, Camera)> = limn_tests::corpus::all()
        .into_iter()
        .map(|c| (c.name.to_string(), c.scene, c.camera))
        .collect();
    for s in limn_tests::hard_input::all() {
        cases.push((s.name, s.scene, s.camera));
    }
    for (name, scene, cam) in &cases {
        let p = paint(scene, cam, &OrderOptions::default());
        let reference = p
            .reference(scene, Method::RayCast, DepthFormat::F64)
            .expect("ray casting");
        let order_only = p.compare(&reference).mismatches_outside_band;
        let flaps = wrong_pixels(scene, &p, &reference, &Style::default());
        let none = wrong_pixels(
            scene,
            &p,
            &reference,
            &Style {
                seams: 0.0,
                ..Style::default()
            },
        );
        let changes = flap_changes(scene, cam);
        println!(
            "{name}: order {order_only}, default {flaps:?}, seams 0 {none:?}, changes {changes:?}"
        );
    }
}

/// Times the seam flaps of the default picture of two 300² height fields 1e-6 apart (the
/// best of 7 runs, joined as without outlines): `cargo test --release -p limn-tests --test
/// seam_flaps -- --ignored --nocapture time_flaps`.
#[test]
#[ignore = "timing: run in release with --ignored --nocapture time_flaps"]
fn time_flaps() {
    let scene = height_fields(300, 1, 1e-6, 0.05);
    let cam = Camera::new(DVec3::new(1.0, 2.0, 3.0), DVec3::ZERO, 800, 600);
    let ordered = limn_depthsort::order(&scene, &cam, &OrderOptions::default()).expect("order");
    let style = Style {
        seams: 0.0,
        ..Style::default()
    };
    let fragments = picture(&scene, &ordered, &style).fragments;
    let mut best = f64::INFINITY;
    let mut out = 0;
    for _ in 0..7 {
        let frags = fragments.clone();
        let t = std::time::Instant::now();
        let (flapped, _) = seam_flaps_indexed(frags, 0.5, FlapJoin::Joined);
        best = best.min(t.elapsed().as_secs_f64());
        out = flapped.iter().map(|f| f.points.len()).sum::<usize>();
    }
    println!(
        "{} fragments, {} corners with flaps: {:.1} ms",
        fragments.len(),
        out,
        best * 1e3
    );
}
