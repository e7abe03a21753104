//! Phong interpolation in the picture: Gouraud triangles within the tolerance of
//! per-point shading, adaptive, and written by PDF as one type-4 mesh per face.

use glam::{DVec3, DVec4};
use limn_depthsort::{order, OrderOptions};
use limn_paint::{picture, Painter, PdfPainter, Picture, Style};
use limn_scene::{
    interpolated_normal, polygon_normal, shade_sided_in_scene, shapes, Camera, Light, LightKind,
    Material, Scene, Shading,
};

/// A glossy icosphere under a point light, its normals the sphere's.
fn glossy_sphere(level: u32, ns: f64) -> (Scene, Camera) {
    let mut s = Scene::default();
    let m = s.add_material(Material::glossy(
        "glossy",
        [0.7, 0.3, 0.2],
        [0.8, 0.8, 0.8],
        ns,
    ));
    let o = s.add_object("sphere");
    shapes::icosphere(&mut s, DVec3::ZERO, 1.0, level, m, o).unwrap();
    s.lights = vec![
        Light {
            kind: LightKind::Point(DVec3::new(2.0, 3.0, 4.0)),
            color: [1.0; 3],
            shadows: false,
        },
        Light {
            kind: LightKind::Ambient,
            color: [0.3; 3],
            shadows: false,
        },
    ];
    let cam = Camera::new(DVec3::new(0.0, 0.0, 4.0), DVec3::ZERO, 160, 160);
    (s, cam)
}

fn draw(
    scene: &Scene,
    cam: &Camera,
    shading: Shading,
    tolerance: f64,
) -> (Picture, Camera, f64, f64) {
    let mut scene = scene.clone();
    scene.shading = Some(shading);
    let ordered = order(&scene, cam, &OrderOptions::default()).unwrap();
    let style = Style {
        tolerance,
        seams: 0.0,
        ..Style::default()
    };
    let pic = picture(&scene, &ordered, &style);
    (pic, ordered.camera, ordered.near, ordered.far)
}

/// The world point of face `face` seen at pixel position `px`.
fn unproject(scene: &Scene, cam: &Camera, near: f64, far: f64, face: u32, px: [f64; 2]) -> DVec3 {
    let inv = cam.view_projection(near, far).inverse();
    let ndc = DVec4::new(
        px[0] / cam.width as f64 * 2.0 - 1.0,
        1.0 - px[1] / cam.height as f64 * 2.0,
        -1.0,
        1.0,
    );
    let q = inv * ndc;
    let dir = (q.truncate() / q.w - cam.eye).normalize();
    let pts = scene.face_points(face);
    let n = (pts[1] - pts[0]).cross(pts[2] - pts[0]);
    let t = (pts[0] - cam.eye).dot(n) / dir.dot(n);
    cam.eye + dir * t
}

#[test]
fn phong_triangles_are_within_tolerance_of_per_point_shading() {
    let (scene, cam) = glossy_sphere(1, 60.0);
    let tol = 1.0 / 255.0;
    let (pic, cam, near, far) = draw(&scene, &cam, Shading::Phong, tol);
    let m = &scene.materials[0];
    let (mut worst, mut samples) = (0.0f64, 0);
    for f in &pic.fragments {
        let cs = f
            .vertex_colors
            .as_ref()
            .expect("every Phong piece is Gouraud");
        assert_eq!(f.points.len(), 3);
        // Interior points at a few barycentric positions of the piece.
        for b in [
            [1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0],
            [0.6, 0.2, 0.2],
            [0.2, 0.6, 0.2],
            [0.2, 0.2, 0.6],
            [0.45, 0.45, 0.1],
            [0.1, 0.45, 0.45],
            [0.45, 0.1, 0.45],
        ] {
            let px = [0, 1].map(|k| (0..3).map(|i| b[i] * f.points[i][k]).sum::<f64>());
            let gouraud =
                [0, 1, 2].map(|k| (0..3).map(|i| b[i] * f64::from(cs[i][k])).sum::<f64>());
            let p = unproject(&scene, &cam, near, far, f.face, px);
            let n = interpolated_normal(&scene, f.face, p).unwrap();
            let side = polygon_normal(&scene.face_points(f.face));
            let phong = shade_sided_in_scene(&scene, m, p, n, side, cam.eye);
            for k in 0..3 {
                worst = worst.max((gouraud[k] - phong[k]).abs());
            }
            samples += 1;
        }
    }
    assert!(samples > 1000, "{samples}");
    assert!(worst <= tol, "worst difference {worst} > {tol}");
}

#[test]
fn phong_splits_where_the_highlight_is_and_gouraud_does_not_split() {
    let (scene, cam) = glossy_sphere(2, 10.0);
    let (gouraud, ..) = draw(&scene, &cam, Shading::Gouraud, 1.0 / 255.0);
    let (phong, ..) = draw(&scene, &cam, Shading::Phong, 1.0 / 255.0);
    let (loose, ..) = draw(&scene, &cam, Shading::Phong, 8.0 / 255.0);
    let (flat, ..) = draw(&scene, &cam, Shading::Flat, 1.0 / 255.0);
    assert!(gouraud.fragments.iter().all(|f| f.vertex_colors.is_some()));
    assert!(flat.fragments.iter().all(|f| f.vertex_colors.is_none()));
    assert_eq!(flat.fragments.len(), gouraud.fragments.len());
    assert!(phong.fragments.len() > 4 * gouraud.fragments.len());
    assert!(loose.fragments.len() < phong.fragments.len());
    // Pieces per face: the face with the brightest corner is cut finer than the
    // dimmest visible face.
    let per_face = |face: u32| phong.fragments.iter().filter(|f| f.face == face).count();
    let peak = |face: u32| {
        gouraud
            .fragments
            .iter()
            .filter(|f| f.face == face)
            .flat_map(|f| f.vertex_colors.iter().flatten())
            .map(|c| f64::from(c[0]) + f64::from(c[1]) + f64::from(c[2]))
            .fold(0.0, f64::max)
    };
    let faces: Vec<u32> = {
        let mut v: Vec<u32> = gouraud.fragments.iter().map(|f| f.face).collect();
        v.dedup();
        v
    };
    let bright = faces
        .iter()
        .copied()
        .max_by(|&a, &b| peak(a).total_cmp(&peak(b)))
        .unwrap();
    let dim = faces
        .iter()
        .copied()
        .min_by(|&a, &b| peak(a).total_cmp(&peak(b)))
        .unwrap();
    assert!(
        per_face(bright) > per_face(dim),
        "{} vs {}",
        per_face(bright),
        per_face(dim)
    );
}

#[test]
fn pdf_writes_one_mesh_per_face_with_every_piece() {
    let (scene, cam) = glossy_sphere(0, 60.0);
    let (pic, ..) = draw(&scene, &cam, Shading::Phong, 1.0 / 255.0);
    let faces = {
        let mut v: Vec<u32> = pic.fragments.iter().map(|f| f.face).collect();
        v.dedup();
        v.len()
    };
    let mut out = Vec::new();
    PdfPainter::default().paint(&pic, &mut out).unwrap();
    let text = String::from_utf8_lossy(&out);
    assert_eq!(text.matches("/ShadingType 4").count(), faces);
    // Each triangle is 3 vertices of flag (1) + x, y (4 + 4) + 16-bit RGB (6) bytes.
    let lengths: usize = text
        .match_indices("/ShadingType 4")
        .map(|(i, _)| {
            let dict = &text[text[..i].rfind("<<").unwrap()..];
            let l = &dict[dict.find("/Length ").unwrap() + 8..];
            l[..l.find(|c: char| !c.is_ascii_digit()).unwrap()]
                .parse::<usize>()
                .unwrap()
        })
        .sum();
    assert_eq!(lengths, pic.fragments.len() * 45);
}
