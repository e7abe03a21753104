//! What real exporters write, read as their users mean it: Windows texture paths,
//! Rhino's empty `usemtl`, MeshLab's `Tr` and extra PLY values, PLY triangle strips,
//! point clouds.

mod common;

use common::*;
use limn_scene::Material;

/// A 2 × 2 RGB PNG.
fn tiny_png() -> Vec<u8> {
    let mut out = Vec::new();
    let mut e = png::Encoder::new(&mut out, 2, 2);
    e.set_color(png::ColorType::Rgb);
    e.set_depth(png::BitDepth::Eight);
    let mut wr = e.write_header().unwrap();
    wr.write_image_data(&[200; 12]).unwrap();
    drop(wr);
    out
}

const TEXTURED: &str = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n\
                        usemtl spider\nf 1/1 2/2 3/3\n";

#[test]
fn a_windows_texture_path_beside_the_model_is_read() {
    let d = dir();
    write(d.path(), "SpiderTex.png", tiny_png());
    write(d.path(), "maps/Leg.png", tiny_png());
    for map in [".\\SpiderTex.png", "maps\\Leg.png"] {
        write(
            d.path(),
            "m.mtl",
            format!("newmtl spider\nKd 1 1 1\nmap_Kd {map}\n"),
        );
        let s = ok(&write(d.path(), "m.obj", TEXTURED));
        assert!(s.materials[0].texture.is_some(), "{map}");
        assert!(s.warnings.is_empty(), "{map}: {:?}", s.warnings);
    }
    // Still inside the folder only.
    write(
        d.path(),
        "m.mtl",
        "newmtl spider\nmap_Kd ..\\SpiderTex.png\n",
    );
    let p = write(d.path(), "m.obj", TEXTURED);
    let e = err(&p);
    assert!(
        matches!(e.innermost(), limn_load::LoadError::OutsideFolder { .. }),
        "{e}"
    );
}

#[test]
fn an_empty_usemtl_is_the_default_material_with_a_warning() {
    let d = dir();
    let p = write(
        d.path(),
        "rhino.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl\nf 1 2 3\n",
    );
    let s = ok(&p);
    assert_eq!(s.materials, vec![Material::default_grey()]);
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    let w = &s.warnings[0];
    assert!(
        w.starts_with(&format!("{}:4: usemtl without a name", p.display())),
        "{w}"
    );
}

#[test]
fn meshlab_tr_one_is_opaque_with_a_warning() {
    let d = dir();
    // As MeshLab writes it (trimesh's fuze.obj.mtl).
    write(
        d.path(),
        "m.mtl",
        "#\n# Wavefront material file\n# Converted by Meshlab Group\n#\n\n\
         newmtl\ta-super-duper-material\t\t\nKa 0.2 0.2 0.2\nKd 1 1 1\nKs 1 1 1\n\
         Tr 1.000000\nillum 2\nNs 0.000000\n",
    );
    let p = write(
        d.path(),
        "m.obj",
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a-super-duper-material\nf 1 2 3\n",
    );
    let s = ok(&p);
    assert_eq!(s.materials[0].opacity, 1.0);
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    let w = &s.warnings[0];
    let mtl = d.path().join("m.mtl");
    assert!(
        w.starts_with(&format!("{}:10: material", mtl.display())) && w.contains("drawn opaque"),
        "{w}"
    );
}

const SQUARE_VERTICES: &str = "element vertex 5\nproperty float x\nproperty float y\n\
                               property float z\n";
const SQUARE_BODY: &str = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 0 0\n";

#[test]
fn ply_triangle_strips_keep_their_winding_and_restart_at_minus_one() {
    let d = dir();
    // Strip 0 1 2 3 (two triangles, the second turned), a restart, then 1 4 3, and
    // a joining triangle of a repeated corner that is no face.
    let header =
        format!("{SQUARE_VERTICES}element tristrips 1\nproperty list int int vertex_indices\n");
    let body = format!("{SQUARE_BODY}9 0 1 2 3 -1 1 4 3 3\n");
    let s = ok(&write(
        d.path(),
        "s.ply",
        ply("ascii", &header, body.as_bytes()),
    ));
    let faces: Vec<Vec<u32>> = s.faces.iter().map(|f| f.vertices.to_vec()).collect();
    assert_eq!(faces, [vec![0, 1, 2], vec![2, 1, 3], vec![1, 4, 3]]);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    // All counter-clockwise seen from +z, as the strip's first triangle.
    for f in 0..3 {
        let p = s.face_points(f);
        assert!((p[1] - p[0]).cross(p[2] - p[0]).z > 0.0, "face {f}");
    }
    // Binary, and an index out of range named with its element.
    let mut bin = Vec::new();
    for v in [
        [0f32, 0., 0.],
        [1., 0., 0.],
        [0., 1., 0.],
        [1., 1., 0.],
        [2., 0., 0.],
    ] {
        for c in v {
            bin.extend_from_slice(&c.to_le_bytes());
        }
    }
    bin.extend_from_slice(&4i32.to_le_bytes());
    for i in [0i32, 1, 2, 3] {
        bin.extend_from_slice(&i.to_le_bytes());
    }
    let b = ok(&write(
        d.path(),
        "b.ply",
        ply("binary_little_endian", &header, &bin),
    ));
    assert_eq!(b.faces.len(), 2);
    let bad = format!("{SQUARE_BODY}3 0 1 7\n");
    let p = write(d.path(), "bad.ply", ply("ascii", &header, bad.as_bytes()));
    let e = err(&p);
    assert!(e.to_string().contains("index 7"), "{e}");
}

#[test]
fn point_clouds_are_drawn_as_points_with_a_warning() {
    let d = dir();
    let header = format!("{SQUARE_VERTICES}property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 0\nproperty list uchar int vertex_indices\n");
    let body = "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n1 1 0 0 0 0\n2 0 0 255 255 255\n";
    let s = ok(&write(
        d.path(),
        "cloud.ply",
        ply("ascii", &header, body.as_bytes()),
    ));
    assert!(s.faces.is_empty());
    assert_eq!(s.points.len(), 5);
    assert_eq!(s.points[0].color, [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(s.points[4].at, s.vertices[4]);
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    assert!(
        s.warnings[0].contains("5 vertices are drawn as points"),
        "{:?}",
        s.warnings
    );

    let s = ok(&write(d.path(), "cloud.obj", "v 0 0 0\nv 1 2 3\nv 1 0 0\n"));
    assert_eq!(s.points.len(), 3);
    assert_eq!(s.points[1].at, s.vertices[1]);
    assert!(
        s.warnings[0].contains("3 vertices are drawn as points"),
        "{:?}",
        s.warnings
    );
    // Nothing at all is still said.
    let s = ok(&write(d.path(), "empty.obj", "# nothing\n"));
    assert!(s.points.is_empty());
    assert!(s.warnings[0].ends_with("no faces"), "{:?}", s.warnings);
}

/// MeshLab's ASCII PLY with texture coordinates writes a list its header does not name
/// after each face (trimesh's `fuze_ascii.ply`): the faces are read, the extra values
/// ignored with one warning naming the first such line.
#[test]
fn values_beyond_the_ply_header_are_ignored_with_a_warning() {
    let d = dir();
    let head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
                property float z\nelement face 2\nproperty list uchar int vertex_indices\n\
                end_header\n";
    let body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 9 1 1 1\n3 0 2 1\n";
    let p = write(d.path(), "m.ply", format!("{head}{body}"));
    let s = ok(&p);
    assert_eq!(s.faces.len(), 2);
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    let w = &s.warnings[0];
    assert!(
        w.contains("m.ply:13:") && w.contains("beyond") && w.contains("(1 lines)"),
        "{w}"
    );
}
