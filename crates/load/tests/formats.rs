//! Every format loads what it should.

mod common;

use common::*;
use glam::DVec3;
use limn_load::{load, LoadOptions};
use limn_scene::{Material, Scene};

fn face_points(s: &Scene, f: usize) -> Vec<DVec3> {
    s.face_points(f as u32)
}

#[test]
fn obj_keeps_ngons_materials_and_order() {
    let d = dir();
    write(d.path(), "cube.mtl", CUBE_MTL);
    let p = write(d.path(), "cube.obj", CUBE_OBJ);
    let s = ok(&p);
    assert_eq!(s.faces.len(), 6);
    assert!(
        s.faces.iter().all(|f| f.vertices.len() == 4),
        "quads stay quads"
    );
    assert_eq!(
        s.faces[0].vertices.to_vec(),
        vec![0, 3, 2, 1],
        "file order and 0-based indices"
    );
    assert_eq!(s.objects.len(), 1);
    assert_eq!(s.objects[0].name, "box");
    let red = &s.materials[s.faces[0].material as usize];
    assert_eq!(red.name, "red");
    assert_eq!(
        (red.kd, red.ka, red.ks),
        ([1.0, 0.0, 0.0], [0.1, 0.0, 0.0], [0.5; 3])
    );
    assert_eq!((red.ns, red.illum, red.opacity), (32.0, 2, 1.0));
    let glass = &s.materials[s.faces[2].material as usize];
    assert_eq!(
        (glass.kd, glass.opacity, glass.illum),
        ([0.2, 0.4, 0.6], 0.25, 0)
    );
    assert_eq!(s.faces[1].material, s.faces[0].material);
    assert!(s.is_closed(), "the cube's quads face outwards consistently");
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
}

#[test]
fn obj_negative_indices_normals_groups_and_defaults() {
    let d = dir();
    let src = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 1.5 0\nv 0 1 0\n\
               vn 0 0 1\nvt 0 0\n\
               f -5 -4 -3 -2 -1\n\
               g left side\n\
               f 1//1 2//1 3//1\n\
               g right\n\
               f 1/1/1 3/1/1 5/1/1\n\
               g left side\n\
               f 1/1 2/1 5/1\n";
    let p = write(d.path(), "pent.obj", src);
    let s = ok(&p);
    assert_eq!(s.faces.len(), 4);
    assert_eq!(
        s.faces[0].vertices.to_vec(),
        vec![0, 1, 2, 3, 4],
        "a pentagon, negative indices"
    );
    assert_eq!(s.faces[0].normals, None);
    assert_eq!(
        s.faces[1].normals.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 0, 0])
    );
    assert_eq!(
        s.faces[2].normals.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 0, 0])
    );
    assert_eq!(s.faces[3].normals, None);
    let names: Vec<_> = s.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["pent", "left side", "right"]);
    assert_eq!(
        s.faces[3].object, s.faces[1].object,
        "a group named again continues"
    );
    assert!(s
        .faces
        .iter()
        .all(|f| s.materials[f.material as usize] == Material::default_grey()));
    assert_eq!(s.materials.len(), 1);
}

#[test]
fn obj_tr_line_continuation_and_ignored_statements() {
    let d = dir();
    write(
        d.path(),
        "m.mtl",
        "newmtl a\nKd 0 1 0\nTr 0.75\nmap_Ks tex.png\n",
    );
    let src = "mtllib m.mtl\ns 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nusemtl a\nf 1 2 \\\n 3\n";
    let p = write(d.path(), "t.obj", src);
    let s = ok(&p);
    assert_eq!(s.faces.len(), 1);
    let m = &s.materials[s.faces[0].material as usize];
    assert_eq!((m.kd, m.opacity), ([0.0, 1.0, 0.0], 0.25));
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    assert!(s.warnings[0].contains("m.mtl:4: texture maps (map_Ks"));
    // The `l` before any `usemtl` is a black polyline of width 1.
    assert_eq!(s.lines.len(), 1);
    assert_eq!(s.lines[0].points, vec![DVec3::ZERO, DVec3::X]);
    assert_eq!(s.lines[0].color, [0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn obj_missing_mtl_warns_and_uses_defaults() {
    let d = dir();
    let p = write(
        d.path(),
        "m.obj",
        "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl shiny\nf 1 2 3\n",
    );
    let s = ok(&p);
    assert_eq!(
        s.materials[s.faces[0].material as usize].kd,
        Material::default_grey().kd
    );
    assert_eq!(s.warnings.len(), 2, "{:?}", s.warnings);
    assert!(s.warnings[0].contains("nowhere.mtl") && s.warnings[0].contains("m.obj:1"));
    assert!(s.warnings[1].contains("shiny") && s.warnings[1].contains("m.obj:5"));
}

#[test]
fn obj_materials_are_added_once_each_in_order_of_first_use() {
    let d = dir();
    write(
        d.path(),
        "a.mtl",
        "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n",
    );
    write(
        d.path(),
        "late.mtl",
        "newmtl late\nKd 0 0 1\nnewmtl a\nKd 1 1 1\n",
    );
    let src = "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n\
               usemtl b\nf 1 2 3\nusemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n\
               usemtl late\nf 1 2 3\nmtllib late.mtl\nusemtl late\nf 1 2 3\n\
               usemtl a\nf 1 2 3\nusemtl nowhere\nf 1 2 3\nusemtl b\nf 1 2 3\n";
    let p = write(d.path(), "m.obj", src);
    let s = ok(&p);
    let used: Vec<u32> = s.faces.iter().map(|f| f.material).collect();
    // b, a, b again, `late` before its library (grey) and after it (still the grey
    // it was first given), `a` as first defined, an unknown name, b again.
    assert_eq!(used, vec![0, 1, 0, 2, 2, 1, 3, 0]);
    let names: Vec<&str> = s.materials.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(names.len(), 4, "{names:?}");
    assert_eq!((names[0], names[1]), ("b", "a"));
    assert_eq!(s.materials[0].kd, [0.0, 1.0, 0.0]);
    assert_eq!(s.materials[1].kd, [1.0, 0.0, 0.0]);
    for grey in [2, 3] {
        assert_eq!(s.materials[grey].kd, Material::default_grey().kd);
    }
    let undefined: Vec<&String> = s
        .warnings
        .iter()
        .filter(|w| w.contains("not defined"))
        .collect();
    assert_eq!(undefined.len(), 2, "{:?}", s.warnings);
    assert!(undefined[0].contains("m.obj:11") && undefined[1].contains("m.obj:18"));
}

/// The material a library of `n` gives name `k` (every field differs between names).
fn numbered_material(k: usize, n: usize) -> Material {
    let f = k as f64 / n as f64;
    Material {
        name: format!("m{k}"),
        kd: [f, 1.0 - f, 0.5],
        ks: [0.25, f, 0.0],
        ns: k as f64,
        opacity: 1.0 - f / 2.0,
        illum: (k % 3) as u8,
        ..Material::default_grey()
    }
}

#[test]
fn obj_materials_are_the_library_definitions_in_order_of_first_use() {
    let n = 40;
    let d = dir();
    let mut mtl = String::new();
    for k in 0..n {
        let m = numbered_material(k, n);
        mtl += &format!(
            "newmtl {}\nKd {} {} {}\nKs {} {} {}\nNs {}\nd {}\nillum {}\n",
            m.name, m.kd[0], m.kd[1], m.kd[2], m.ks[0], m.ks[1], m.ks[2], m.ns, m.opacity, m.illum
        );
    }
    write(d.path(), "many.mtl", &mtl);
    // Used from the last to the first, every third name twice in a row and every name
    // again afterwards (found in the scene, not taken from the library again).
    let mut src = String::from("mtllib many.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for k in (0..n).rev().chain(0..n) {
        src += &format!("usemtl m{k}\nf 1 2 3\n");
        if k % 3 == 0 {
            src += &format!("usemtl m{k}\nf 1 2 3\n");
        }
    }
    let s = ok(&write(d.path(), "many.obj", &src));
    let want: Vec<Material> = (0..n).rev().map(|k| numbered_material(k, n)).collect();
    assert_eq!(s.materials, want);
    let used: Vec<u32> = s.faces.iter().map(|f| f.material).collect();
    let mut expected = Vec::new();
    for k in (0..n).rev().chain(0..n) {
        let m = (n - 1 - k) as u32;
        expected.push(m);
        if k % 3 == 0 {
            expected.push(m);
        }
    }
    assert_eq!(used, expected);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);

    // One name of the library used: the scene keeps room for about one material, not
    // for the whole library.
    let one = ok(&write(
        d.path(),
        "one.obj",
        "mtllib many.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m7\nf 1 2 3\n",
    ));
    assert_eq!(one.materials, vec![numbered_material(7, n)]);
    assert!(one.materials.capacity() < n, "{}", one.materials.capacity());
}

#[test]
fn obj_mtllib_inside_a_subfolder_is_fine() {
    let d = dir();
    write(d.path(), "mats/a.mtl", "newmtl a\nKd 0 0 1\n");
    let p = write(
        d.path(),
        "m.obj",
        "mtllib mats/../mats/a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n",
    );
    let s = ok(&p);
    assert_eq!(s.materials[0].kd, [0.0, 0.0, 1.0]);
}

#[test]
fn binary_stl_starting_with_solid_is_binary_and_shares_vertices() {
    let d = dir();
    let p = write(
        d.path(),
        "cube.stl",
        binary_stl(b"solid cube exported", &cube_triangles()),
    );
    let s = ok(&p);
    assert_eq!(s.faces.len(), 12);
    assert_eq!(s.vertices.len(), 8, "identical corners are shared");
    assert!(s.is_closed());
    assert_eq!(s.objects[0].name, "cube");
    assert_eq!(s.materials, vec![Material::default_grey()]);
    // Face ids follow the file: the first face is the first triangle.
    let t = cube_triangles();
    let want: Vec<DVec3> = t[0]
        .iter()
        .map(|v| DVec3::new(v[0] as f64, v[1] as f64, v[2] as f64))
        .collect();
    assert_eq!(face_points(&s, 0), want);
}

#[test]
fn ascii_stl_with_uppercase_keywords_and_two_solids() {
    let d = dir();
    let src = "solid first\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n\
               vertex 0 1 0\n  endloop\n endfacet\nendsolid first\n\
               SOLID\nFACET NORMAL 0 0 0\nOUTER LOOP\nVERTEX 0 0 1\nVERTEX 1 0 1\nVERTEX 0 1 1\n\
               ENDLOOP\nENDFACET\nENDSOLID\n";
    let p = write(d.path(), "two.stl", src);
    let s = ok(&p);
    assert_eq!(s.faces.len(), 2);
    let names: Vec<_> = s.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["first", "two"]);
    assert_eq!(face_points(&s, 1)[2], DVec3::new(0.0, 1.0, 1.0));
}

#[test]
fn ascii_ply_vertex_colours_are_kept_per_corner_over_a_white_unlit_material() {
    let d = dir();
    let header = "comment made by hand\nelement vertex 4\nproperty float x\nproperty float y\n\
                  property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n\
                  element face 3\nproperty list uchar int vertex_indices\n";
    let body = "0 0 0 255 0 0\n1 0 0 255 0 0\n1 1 0 0 0 255\n0 1 0 0 0 255\n\
                4 0 1 2 3\n3 0 1 2\n3 2 3 2\n";
    let p = write(d.path(), "sq.ply", ply("ascii", header, body.as_bytes()));
    let s = ok(&p);
    assert_eq!(s.faces.len(), 3);
    assert_eq!(
        s.faces[0].vertices.to_vec(),
        vec![0, 1, 2, 3],
        "quads stay quads"
    );
    assert_eq!(
        s.colors,
        [
            [1.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, 1.0]
        ]
    );
    // Corners of different colours: vertex colours over white.
    assert_eq!(
        s.faces[0].colors.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 1, 2, 3])
    );
    assert_eq!(
        s.faces[1].colors.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 1, 2])
    );
    let m0 = &s.materials[s.faces[0].material as usize];
    assert_eq!((m0.kd, m0.illum), ([1.0; 3], 0));
    assert_eq!(s.faces[0].material, s.faces[1].material);
    // Corners of one colour: that colour, no vertex colours.
    assert_eq!(s.faces[2].colors, None);
    let m2 = &s.materials[s.faces[2].material as usize];
    assert_eq!((m2.kd, m2.name.as_str()), ([0.0, 0.0, 1.0], "#0000ff"));
    assert_eq!(s.materials.len(), 2);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
}

#[test]
fn binary_ply_both_byte_orders_read_the_same() {
    let d = dir();
    let le = ok(&write(d.path(), "le.ply", binary_ply_square(false)));
    let be = ok(&write(d.path(), "be.ply", binary_ply_square(true)));
    assert_eq!(le.vertices, be.vertices);
    assert_eq!(le.faces, be.faces);
    assert_eq!(le.vertices[2], DVec3::new(1.0, 1.0, 0.0));
    assert_eq!(le.faces[1].vertices.to_vec(), vec![0, 2, 3]);
    assert_eq!(
        le.faces[1].colors.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 2, 3])
    );
    assert_eq!(le.colors, be.colors);
}

#[test]
fn ply_face_colours_normals_and_extra_elements() {
    let d = dir();
    let header = "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n\
                  property float nx\nproperty float ny\nproperty float nz\n\
                  element face 1\nproperty list uchar uint vertex_index\nproperty float red\n\
                  property float green\nproperty float blue\nproperty float alpha\n\
                  element edge 1\nproperty int vertex1\nproperty int vertex2\n";
    let body = "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2 0.25 0.5 1 0.5\n0 1\n";
    let s = ok(&write(
        d.path(),
        "n.ply",
        ply("ascii", header, body.as_bytes()),
    ));
    assert_eq!(s.normals.len(), 3);
    assert_eq!(
        s.faces[0].normals.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 1, 2])
    );
    let m = &s.materials[0];
    assert_eq!((m.kd, m.opacity, m.illum), ([0.25, 0.5, 1.0], 0.5, 0));
}

#[test]
fn gltf_with_data_uri_applies_the_node_hierarchy() {
    let d = dir();
    let json = quad_gltf(&data_uri(&quad_buffer()), 4);
    let s = ok(&write(d.path(), "quad.gltf", json));
    assert_eq!(s.faces.len(), 2);
    assert_eq!(s.objects[0].name, "child");
    // child scale 2, then parent translation 10 along x.
    assert_eq!(
        face_points(&s, 0),
        vec![
            DVec3::new(10.0, 0.0, 0.0),
            DVec3::new(12.0, 0.0, 0.0),
            DVec3::new(12.0, 2.0, 0.0),
        ]
    );
    let m = &s.materials[0];
    assert_eq!(
        (m.name.as_str(), m.kd, m.opacity, m.illum),
        ("red", [1.0, 0.0, 0.0], 0.5, 1)
    );
}

#[test]
fn gltf_with_buffer_file_and_glb_load_the_same() {
    let d = dir();
    write(d.path(), "bin/quad.bin", quad_buffer());
    let a = ok(&write(d.path(), "a.gltf", quad_gltf("bin/quad.bin", 4)));
    let b = ok(&write(
        d.path(),
        "b.glb",
        glb(&quad_gltf("", 4), &quad_buffer()),
    ));
    assert_eq!(a.vertices, b.vertices);
    assert_eq!(a.faces, b.faces);
    assert_eq!(a.materials, b.materials);
}

#[test]
fn gltf_mirrored_node_reverses_winding_and_unlit_is_illum0() {
    let d = dir();
    let json = quad_gltf(&data_uri(&quad_buffer()), 4)
        .replace(r#""scale": [2, 2, 2]"#, r#""scale": [-1, 1, 1]"#)
        .replace(
            r#""alphaMode": "BLEND","#,
            r#""extensions": {"KHR_materials_unlit": {}},"#,
        );
    let s = ok(&write(d.path(), "m.gltf", json));
    let n = limn_scene::polygon_normal(&face_points(&s, 0));
    assert!(
        n.z > 0.0,
        "a mirrored node keeps faces facing the same way: {n}"
    );
    assert_eq!((s.materials[0].illum, s.materials[0].opacity), (0, 1.0));
}

#[test]
fn extensions_are_case_insensitive() {
    let d = dir();
    let p = write(d.path(), "CUBE.STL", binary_stl(b"", &cube_triangles()));
    assert_eq!(ok(&p).faces.len(), 12);
    let e = load(&d.path().join("x.3ds"), &LoadOptions::default()).unwrap_err();
    assert!(e.to_string().contains("x.3ds"));
}
