//! The visible map (`OrderOptions::visible`): on the hard-case corpus and on meshes, in
//! perspective and parallel views, every ordering's visible map agrees with exact ray
//! casting, covers no pixel centre twice with its opaque regions, and shows exactly the
//! face painter's output shows at every pixel centre; what lies behind translucent faces
//! stays; and the front door draws it in every format and style.

use std::borrow::Cow;

use glam::DVec3;
use limn::{Input, RenderOptions, Request, SceneOptions, Silent, ViewOptions};
use limn_depthsort::{order, CullMode, OrderOptions, SortMode};
use limn_paint::Format;
use limn_scene::shapes::{icosphere, random_soup, torus};
use limn_scene::{Camera, Material, Projection, Scene};
use limn_tests::corpus;
use limn_tests::reference::paint;
use limn_zbuffer::{DepthFormat, Method, NO_FACE};

const MODES: [SortMode; 3] = [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell];

fn opts(sort: SortMode, cull: CullMode, visible: bool) -> OrderOptions {
    OrderOptions {
        sort,
        cull,
        visible,
        ..OrderOptions::default()
    }
}

/// Meshes: two linked tori (closed: their back faces culled), the same with no culling
/// (every back face drawn, and hidden), a sphere through a torus, and a soup of 300
/// triangles; each with a camera.
fn meshes() -> Vec<(&'static str, Scene, Camera, CullMode)> {
    let mut linked = Scene::default();
    let a = linked.add_material(Material::unlit("a", [0.8, 0.3, 0.2]));
    let b = linked.add_material(Material::unlit("b", [0.2, 0.5, 0.8]));
    let o = linked.add_object("tori");
    torus(&mut linked, DVec3::ZERO, 1.0, 0.3, 24, 12, a, o).unwrap();
    let first = linked.vertices.len();
    torus(&mut linked, DVec3::ZERO, 1.0, 0.3, 24, 12, b, o).unwrap();
    // The second torus turned upright and moved through the first.
    for v in &mut linked.vertices[first..] {
        *v = DVec3::new(v.x + 1.0, v.z, -v.y);
    }
    let cam = Camera::new(
        DVec3::new(1.5, 2.5, 4.0),
        DVec3::new(0.5, 0.0, 0.0),
        160,
        120,
    );
    let mut through = Scene::default();
    let m = through.add_material(Material::unlit("s", [0.7, 0.7, 0.2]));
    let n = through.add_material(Material::unlit("t", [0.3, 0.6, 0.3]));
    let o = through.add_object("shapes");
    icosphere(&mut through, DVec3::new(1.0, 0.0, 0.0), 0.45, 2, m, o).unwrap();
    torus(&mut through, DVec3::ZERO, 1.0, 0.3, 20, 10, n, o).unwrap();
    let mut soup = Scene::default();
    let m = soup.add_material(Material::unlit("g", [0.5, 0.5, 0.5]));
    let o = soup.add_object("soup");
    random_soup(&mut soup, 300, 0.5, 11, m, o).unwrap();
    let soup_cam = Camera::new(DVec3::new(0.8, 1.1, 4.5), DVec3::ZERO, 160, 120);
    vec![
        ("linked_tori", linked.clone(), cam, CullMode::Auto),
        ("linked_tori_unculled", linked, cam, CullMode::Off),
        ("sphere_through_torus", through, cam, CullMode::Off),
        ("soup_300", soup, soup_cam, CullMode::Auto),
    ]
}

/// The same camera looking in parallel (orthographic, the scene's height framed).
fn parallel(cam: &Camera, height: f64) -> Camera {
    let mut c = *cam;
    c.projection = Projection::Orthographic { height };
    c
}

/// Every scene of the test: the corpus (culling as the corpus asks) and the meshes, each
/// in its perspective view and in a parallel one.
fn scenes() -> Vec<(String, Scene, Camera, CullMode)> {
    let mut out = Vec::new();
    let mut add = |name: &str, scene: Scene, cam: Camera, cull: CullMode| {
        let size = scene.bounds().map_or(1.0, |(lo, hi)| (hi - lo).length());
        out.push((
            format!("{name}/parallel"),
            scene.clone(),
            parallel(&cam, size),
            cull,
        ));
        out.push((name.to_string(), scene, cam, cull));
    };
    for case in corpus::all() {
        add(case.name, case.scene, case.camera, CullMode::Auto);
    }
    for (name, scene, cam, cull) in meshes() {
        add(name, scene, cam, cull);
    }
    out
}

/// For every scene and exact ordering: the visible map agrees with exact ray casting
/// outside the edge band, covers no pixel centre outside it with two opaque regions
/// (unless the near plane cuts an occluder: `behind_eye`),
/// and shows the face painter's output shows at every pixel centre outside both
/// pictures' bands (so they paint the same pixels). Scenes where much is hidden must
/// drop parts.
#[test]
fn the_visible_map_is_exact_covers_each_pixel_once_and_paints_what_the_painter_paints() {
    let mut failures = Vec::new();
    let mut hidden_total = 0;
    for (name, scene, cam, cull) in scenes() {
        for sort in MODES {
            let v = paint(&scene, &cam, &opts(sort, cull, true));
            let p = paint(&scene, &cam, &opts(sort, cull, false));
            let r = v
                .reference(&scene, Method::RayCast, DepthFormat::F64)
                .expect("ray casting renders");
            let against_rays = v.compare(&r).mismatches_outside_band;
            let twice = v.double_covered(&scene);
            let differ = v
                .ids
                .ids
                .iter()
                .zip(&p.ids.ids)
                .zip(v.band.bits.iter().zip(&p.band.bits))
                .filter(|&((a, b), (&va, &pa))| a != b && !va && !pa)
                .count();
            let painted = v.ids.ids.iter().filter(|&&f| f != NO_FACE).count();
            let hidden = v.ordered.stats.fragments_hidden;
            hidden_total += hidden;
            eprintln!(
                "{name:<34} {:<8} painted {painted:>6} hidden parts {hidden:>5} rays {against_rays} \
                 twice {twice} differ {differ}",
                sort.name()
            );
            // A polygon the near plane cuts hides nothing in the map (its drawn pieces are
            // painted over what they hide, see `hiding/sight.rs`): only there may a
            // centre be covered twice.
            let near_cut = v.ordered.stats.faces_near_clipped > 0;
            if against_rays > 0 || (twice > 0 && !near_cut) || differ > 0 || painted == 0 {
                failures.push(format!(
                    "{name} {}: {against_rays} pixels disagree with ray casting, {twice} \
                     covered twice, {differ} differ from painter's, {painted} painted",
                    sort.name()
                ));
            }
            let much_hidden = name.starts_with("linked_tori_unculled")
                || name.starts_with("sphere_through_torus")
                || name.starts_with("soup");
            if much_hidden && hidden == 0 {
                failures.push(format!("{name} {}: no part left out", sort.name()));
            }
        }
    }
    assert!(hidden_total > 0);
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Overlapping coplanar faces: the later face wins where they overlap, so the earlier
/// one keeps only what the later does not cover (the painter's rule), and its hidden
/// part is left out.
#[test]
fn coplanar_faces_keep_the_painters_rule() {
    let case = corpus::coplanar_overlaps();
    let o = order(
        &case.scene,
        &case.camera,
        &opts(SortMode::Adaptive, CullMode::Auto, true),
    )
    .unwrap();
    assert!(o.stats.fragments_hidden > 0);
    // Face 0 lies under face 1 over [-0.5, 0.5]²: none of its visible fragments has a
    // world point strictly inside that square and off the later faces' edges.
    let inside = |p: DVec3| p.x > -0.5 && p.x < 0.5 && p.y > -0.5 && p.y < 0.5;
    for f in o.fragments.iter().filter(|f| f.face == 0) {
        let centre = f.world.iter().copied().sum::<DVec3>() / f.world.len() as f64;
        assert!(
            !inside(centre),
            "face 0 drawn where face 1 covers it: {centre}"
        );
    }
}

/// Translucent faces hide nothing: the opaque face behind a translucent one keeps its
/// part there (drawn under it), while its part behind an opaque face is left out.
#[test]
fn what_lies_behind_a_translucent_face_stays_and_what_lies_behind_an_opaque_one_goes() {
    let mut s = Scene::default();
    let back = s.add_material(Material::unlit("back", [0.2, 0.2, 0.8]));
    let mut glass = Material::unlit("glass", [0.9, 0.9, 0.9]);
    glass.opacity = 0.5;
    let glass = s.add_material(glass);
    let wall = s.add_material(Material::unlit("wall", [0.8, 0.2, 0.2]));
    let o = s.add_object("layers");
    let quad = |x0: f64, x1: f64, z: f64| {
        [
            DVec3::new(x0, -1.0, z),
            DVec3::new(x1, -1.0, z),
            DVec3::new(x1, 1.0, z),
            DVec3::new(x0, 1.0, z),
        ]
    };
    s.add_polygon(&quad(-2.0, 2.0, 0.0), back, o).unwrap();
    s.add_polygon(&quad(-1.5, -0.5, 1.0), glass, o).unwrap();
    s.add_polygon(&quad(0.5, 1.5, 1.0), wall, o).unwrap();
    let cam = Camera::new(DVec3::new(0.0, 0.0, 6.0), DVec3::ZERO, 200, 100);
    let o = order(&s, &cam, &opts(SortMode::Adaptive, CullMode::Auto, true)).unwrap();
    let back_area = |x0: f64, x1: f64| -> f64 {
        // The area of face 0's fragments within x0..x1 (world), by their corners' boxes
        // clipped to the strip (the fragments are rectangles in this view).
        o.fragments
            .iter()
            .filter(|f| f.face == 0)
            .map(|f| {
                let lo = f.world.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
                let hi = f
                    .world
                    .iter()
                    .map(|p| p.x)
                    .fold(f64::NEG_INFINITY, f64::max);
                (hi.min(x1) - lo.max(x0)).max(0.0)
            })
            .sum()
    };
    // Seen from the eye, the glass covers x in -1.8..-0.6 of face 0 (z = 0): kept there
    // (fragments spanning all of -1.7..-0.7). The wall covers x in 0.6..1.8: gone there.
    assert!(back_area(-1.7, -0.7) >= 1.0, "{}", back_area(-1.7, -0.7));
    assert!(back_area(0.7, 1.7) == 0.0, "{}", back_area(0.7, 1.7));
    assert!(o.stats.fragments_hidden > 0);
}

/// The front door draws the visible map in every format and in the hidden-line style,
/// leaves hidden parts out (and writes a smaller SVG than painter's output for a scene
/// where much is hidden); a scene file's `visible = true` asks for it too.
#[test]
fn every_format_and_style_draws_the_visible_map() {
    let (_, scene, _, _) = meshes().swap_remove(2);
    let dir = tempfile::tempdir().unwrap();
    let render = |name: &str, format: Format, visible: bool, style, file_visible| {
        let req = Request {
            input: Input::Scene {
                scene: Cow::Borrowed(&scene),
                settings: SceneOptions {
                    visible: file_visible,
                    ..SceneOptions::default()
                },
                name: "shapes".into(),
            },
            output: Some(dir.path().join(name)),
            options: RenderOptions {
                view: ViewOptions {
                    size: Some((240, 180)),
                    cull: Some(CullMode::Off),
                    visible,
                    ..ViewOptions::default()
                },
                format: Some(format),
                style,
                ..RenderOptions::default()
            },
        };
        limn::render(&req, &mut Silent).unwrap_or_else(|e| panic!("{name}: {e}"))
    };
    for format in [
        Format::Svg,
        Format::Pdf,
        Format::Eps,
        Format::Tikz,
        Format::Png,
    ] {
        for style in [None, Some(limn::Look::HiddenLine)] {
            let name = format!("v{}{}", style.is_some() as u8, format.name());
            let r = render(&name, format, true, style, None);
            let stats = r.stats.expect("painter's statistics");
            assert!(stats.fragments_hidden > 0, "{name}: nothing left out");
            assert!(stats.bytes_out > 0, "{name}: nothing written");
        }
    }
    let painter = render("p.svg", Format::Svg, false, None, None);
    let visible = render("v.svg", Format::Svg, true, None, None);
    let from_file = render("f.svg", Format::Svg, false, None, Some(true));
    let (p, v, f) = (
        painter.stats.unwrap(),
        visible.stats.unwrap(),
        from_file.stats.unwrap(),
    );
    assert_eq!(p.fragments_hidden, 0);
    assert!(
        v.bytes_out < p.bytes_out,
        "{} >= {}",
        v.bytes_out,
        p.bytes_out
    );
    assert_eq!(
        (f.fragments_hidden, f.bytes_out),
        (v.fragments_hidden, v.bytes_out)
    );
}

/// A face the visible map cuts into several pieces around a hole (what a smaller face in
/// front of it hides) is written as one outline with a hole: an outer ring and one hole,
/// no edge between its pieces (the pieces, written one subpath each, meet at
/// T-junctions). Seam flaps are on (the default): the hole is what the flaps leave of the
/// front face, and the front face is painted after it. A parallel view puts every corner
/// on the written grid (25 px per unit), so that the T-junctions stay exact once
/// rounded.
#[test]
fn a_faces_visible_pieces_are_written_as_one_outline_with_its_hole() {
    use limn_paint::{picture, Painter, Style, SvgPainter};
    let mut s = Scene::default();
    let back = s.add_material(Material::unlit("back", [0.2, 0.2, 0.8]));
    let front = s.add_material(Material::unlit("front", [0.8, 0.2, 0.2]));
    let o = s.add_object("layers");
    let quad = |h: f64, z: f64| {
        [
            DVec3::new(-h, -h, z),
            DVec3::new(h, -h, z),
            DVec3::new(h, h, z),
            DVec3::new(-h, h, z),
        ]
    };
    s.add_polygon(&quad(2.0, 0.0), back, o).unwrap();
    s.add_polygon(&quad(0.5, 1.0), front, o).unwrap();
    let cam = parallel(
        &Camera::new(DVec3::new(0.0, 0.0, 6.0), DVec3::ZERO, 200, 200),
        8.0,
    );
    let ordered = order(&s, &cam, &opts(SortMode::Adaptive, CullMode::Auto, true)).unwrap();
    let pieces = ordered.fragments.iter().filter(|f| f.face == 0).count();
    assert!(pieces >= 3, "the back face in {pieces} pieces");
    let mut pic = picture(&s, &ordered, &Style::default());
    assert!(pic.merge_pieces);
    // The subpaths of the back face's path (its fill is the first path).
    let subpaths = |pic: &limn_paint::Picture| -> Vec<String> {
        let mut out = Vec::new();
        SvgPainter::default().paint(pic, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let path = text
            .lines()
            .find(|l| l.starts_with("<path d="))
            .expect("a path")
            .to_string();
        let d = path.split('"').nth(1).unwrap().to_string();
        d.split('M')
            .filter(|p| !p.is_empty())
            .map(str::to_string)
            .collect()
    };
    let merged = subpaths(&pic);
    assert_eq!(merged.len(), 2, "an outer ring and a hole: {merged:?}");
    let rings: Vec<Vec<f64>> = merged
        .iter()
        .map(|ring| {
            ring.replace(['L', 'Z'], " ")
                .split_whitespace()
                .map(|v| v.parse().unwrap())
                .collect()
        })
        .collect();
    let area2 = |r: &[f64]| -> f64 {
        let n = r.len() / 2;
        (0..n)
            .map(|i| {
                let j = (i + 1) % n;
                r[2 * i] * r[2 * j + 1] - r[2 * j] * r[2 * i + 1]
            })
            .sum()
    };
    // The outer ring is the back face's square (50..150), its four corners only: the
    // pieces' corners on its edges are gone.
    assert_eq!(rings[0].len(), 8, "{:?}", merged[0]);
    assert_eq!(area2(&rings[0]).abs(), 2.0 * 100.0 * 100.0);
    // The hole turns the other way, inside the front square (87.5..112.5) less the flaps.
    let (outer, hole) = (area2(&rings[0]), area2(&rings[1]));
    assert!(outer * hole < 0.0, "{merged:?}");
    assert!(
        hole.abs() < 2.0 * 25.0 * 25.0 && hole.abs() > 2.0 * 20.0 * 20.0,
        "{hole}"
    );
    pic.merge_pieces = false;
    let separate = subpaths(&pic);
    assert!(separate.len() > 2, "{separate:?}");
}
