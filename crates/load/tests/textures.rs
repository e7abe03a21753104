//! Texture coordinates and base-colour images: OBJ `vt` with MTL `map_Kd`, glTF
//! `baseColorTexture`, and their errors with file and line.

mod common;

use std::path::Path;

use common::*;
use limn_load::LoadError;

/// A PNG of `w` × `h` RGB texels, `f(i, j)` each.
fn png_bytes(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 3]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut e = png::Encoder::new(&mut out, w, h);
    e.set_color(png::ColorType::Rgb);
    e.set_depth(png::BitDepth::Eight);
    let mut wr = e.write_header().unwrap();
    let f = &f;
    let data: Vec<u8> = (0..h)
        .flat_map(|j| (0..w).flat_map(move |i| f(i, j)))
        .collect();
    wr.write_image_data(&data).unwrap();
    drop(wr);
    out
}

fn checker() -> Vec<u8> {
    png_bytes(
        4,
        4,
        |i, j| if (i + j) % 2 == 0 { [255; 3] } else { [0; 3] },
    )
}

const QUAD: &str = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
                    vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl tex\nf 1/1 2/2 3/3 4/4\n";

#[test]
fn obj_texture_coordinates_and_map_kd_are_read() {
    let d = dir();
    write(d.path(), "img/c.png", checker());
    write(
        d.path(),
        "m.mtl",
        "newmtl tex\nKd 1 1 1\nillum 0\nmap_Kd img/c.png\n",
    );
    let s = ok(&write(d.path(), "q.obj", QUAD));
    // OBJ's v runs up the image; limn's t runs down.
    assert_eq!(
        s.texcoords,
        vec![[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]]
    );
    assert_eq!(
        s.faces[0].texcoords.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 1, 2, 3])
    );
    let t = s.materials[0].texture.as_ref().expect("texture read");
    assert_eq!((t.width(), t.height()), (4, 4));
    assert_eq!(&t.rgba()[..8], &[255, 255, 255, 255, 0, 0, 0, 255]);
    assert!(
        s.files.iter().any(|f| f.ends_with("img/c.png")),
        "{:?}",
        s.files
    );
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert!(limn_scene::Effects::of(&s).texture);
}

#[test]
fn one_image_is_shared_and_offsets_move_coordinates() {
    let d = dir();
    write(d.path(), "c.png", checker());
    write(
        d.path(),
        "m.mtl",
        "newmtl tex\nmap_Kd c.png\nnewmtl moved\nmap_Kd -s 2 2 -o 0.5 0 c.png\n",
    );
    let obj = format!("{QUAD}usemtl moved\nf 1/1 2/2 3/3\n");
    let s = ok(&write(d.path(), "q.obj", obj));
    let (a, b) = (&s.materials[0], &s.materials[1]);
    assert!(std::sync::Arc::ptr_eq(
        a.texture.as_ref().unwrap(),
        b.texture.as_ref().unwrap()
    ));
    let moved: Vec<[f64; 2]> = s.faces[1]
        .texcoords
        .as_ref()
        .unwrap()
        .iter()
        .map(|&i| s.texcoords[i as usize])
        .collect();
    // u ↦ 2u + 0.5, v ↦ 2v, t = 1 − v.
    assert_eq!(moved, vec![[0.5, 1.0], [2.5, 1.0], [2.5, -1.0]]);
}

#[test]
fn unused_textures_are_not_read() {
    let d = dir();
    // The image is missing, but no face with texture coordinates uses the material.
    write(d.path(), "m.mtl", "newmtl tex\nmap_Kd missing.png\n");
    let s = ok(&write(
        d.path(),
        "q.obj",
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl tex\nf 1 2 3\n",
    ));
    assert!(s.materials[0].texture.is_none());
    assert!(s.faces[0].texcoords.is_none());
    assert!(!limn_scene::Effects::of(&s).texture);
}

#[test]
fn obj_texture_errors_name_file_and_line() {
    let d = dir();
    let obj = write(d.path(), "q.obj", QUAD);
    let mtl = d.path().join("m.mtl");
    // Missing image: the MTL line naming it.
    write(d.path(), "m.mtl", "newmtl tex\n\nmap_Kd nothing.png\n");
    let e = err(&obj);
    assert!(matches!(e, LoadError::Image { .. }), "{e}");
    assert_at(&e, &mtl, Some(3));
    // Escaping the folder.
    write(d.path(), "m.mtl", "newmtl tex\nmap_Kd ../c.png\n");
    let e = err(&obj);
    assert!(matches!(e, LoadError::OutsideFolder { .. }), "{e}");
    assert_at(&e, &mtl, Some(2));
    // Corrupt PNG.
    let mut bad = checker();
    bad.truncate(bad.len() / 2);
    write(d.path(), "c.png", bad);
    write(d.path(), "m.mtl", "newmtl tex\nmap_Kd c.png\n");
    let e = err(&obj);
    assert!(e.to_string().contains("corrupt PNG"), "{e}");
    assert_at(&e, &mtl, Some(2));
    // A vt index past the coordinates defined: the face's line.
    write(d.path(), "c.png", checker());
    let obj2 = write(
        d.path(),
        "w.obj",
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl tex\nf 1/1 2/1 3/2\n",
    );
    let e = err(&obj2);
    assert!(matches!(e, LoadError::IndexOutOfRange { .. }), "{e}");
    assert_at(&e, &obj2, Some(7));
    // A non-finite vt.
    let obj3 = write(d.path(), "n.obj", "vt 0 nan\n");
    assert_at(&err(&obj3), &obj3, Some(1));
}

#[test]
fn jpeg_textures_are_decoded() {
    let d = dir();
    let jpg = std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/two_tone.jpg"))
        .unwrap();
    write(d.path(), "t.jpg", jpg);
    write(d.path(), "m.mtl", "newmtl tex\nmap_Kd t.jpg\n");
    let s = ok(&write(d.path(), "q.obj", QUAD));
    let t = s.materials[0].texture.as_ref().unwrap();
    assert_eq!((t.width(), t.height()), (16, 8));
    // Left half red, right half blue (JPEG: within a few levels).
    let near = |c: [f64; 3], want: [f64; 3]| c.iter().zip(want).all(|(a, b)| (a - b).abs() < 0.05);
    assert!(near(
        t.sample([0.2, 0.5]),
        [200.0 / 255.0, 40.0 / 255.0, 40.0 / 255.0]
    ));
    assert!(near(
        t.sample([0.8, 0.5]),
        [40.0 / 255.0, 40.0 / 255.0, 200.0 / 255.0]
    ));
}

/// A textured quad: positions, texture coordinates (float VEC2), u16 indices.
fn textured_buffer() -> Vec<u8> {
    let mut b = quad_buffer();
    for st in [[0f32, 1.], [1., 1.], [1., 0.], [0., 0.]] {
        for c in st {
            b.extend_from_slice(&c.to_le_bytes());
        }
    }
    b
}

fn textured_gltf(buffer_uri: &str, image: &str) -> String {
    format!(
        r#"{{
  "asset": {{"version": "2.0"}},
  "scenes": [{{"nodes": [0]}}],
  "nodes": [{{"name": "q", "mesh": 0}}],
  "meshes": [{{"primitives": [
    {{"attributes": {{"POSITION": 0, "TEXCOORD_0": 2}}, "indices": 1, "material": 0}}]}}],
  "materials": [{{"pbrMetallicRoughness": {{"baseColorFactor": [1, 0.5, 1, 1],
    "baseColorTexture": {{"index": 0}}}}}}],
  "textures": [{{"source": 0}}],
  "images": [{image}],
  "buffers": [{{"uri": "{buffer_uri}", "byteLength": 92}}],
  "bufferViews": [
    {{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
    {{"buffer": 0, "byteOffset": 48, "byteLength": 12}},
    {{"buffer": 0, "byteOffset": 60, "byteLength": 32}}
  ],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
      "min": [0, 0, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}},
    {{"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"}}
  ]
}}
"#
    )
}

#[test]
fn gltf_base_colour_textures_from_files_and_data_uris() {
    let d = dir();
    write(d.path(), "tex/c.png", checker());
    let buffer = data_uri(&textured_buffer());
    let a = ok(&write(
        d.path(),
        "a.gltf",
        textured_gltf(&buffer, r#"{"uri": "tex/c.png"}"#),
    ));
    let png_uri = format!(
        "data:image/png;base64,{}",
        &data_uri(&checker())["data:application/octet-stream;base64,".len()..]
    );
    let b = ok(&write(
        d.path(),
        "b.gltf",
        textured_gltf(&buffer, &format!(r#"{{"uri": "{png_uri}"}}"#)),
    ));
    for s in [&a, &b] {
        assert_eq!(s.faces.len(), 2);
        assert_eq!(
            s.faces[0].texcoords.as_deref().map(<[u32]>::to_vec),
            Some(vec![0, 1, 2])
        );
        assert_eq!(s.texcoords[2], [1.0, 0.0]);
        let m = &s.materials[0];
        assert_eq!(m.kd, [1.0, 0.5, 1.0]);
        let t = m.texture.as_ref().unwrap();
        assert_eq!((t.width(), t.height()), (4, 4));
    }
    let rgba = |s: &limn_scene::Scene| s.materials[0].texture.as_ref().unwrap().rgba().to_vec();
    assert_eq!(rgba(&a), rgba(&b));
    assert!(a.files.iter().any(|f| f.ends_with("tex/c.png")));
}

#[test]
fn gltf_texture_errors_name_the_image() {
    let d = dir();
    let buffer = data_uri(&textured_buffer());
    for (image, what) in [
        (r#"{"uri": "missing.png"}"#, "cannot read"),
        (r#"{"uri": "../c.png"}"#, "outside the folder"),
        (
            r#"{"uri": "data:image/png;base64,iVBORw0KGgo="}"#,
            "corrupt PNG",
        ),
        (r#"{"name": "nothing"}"#, "needs a uri"),
    ] {
        let p = write(d.path(), "e.gltf", textured_gltf(&buffer, image));
        let e = err(&p);
        assert_at(&e, &p, None);
        assert!(e.to_string().contains("(image 0)"), "{e}");
        assert!(e.to_string().contains(what), "{image}: {e}");
    }
}

#[test]
fn scene_files_keep_each_mesh_textured() {
    let d = dir();
    write(d.path(), "c.png", checker());
    write(d.path(), "m.mtl", "newmtl tex\nmap_Kd c.png\n");
    write(d.path(), "q.obj", QUAD);
    // A first mesh without texture coordinates, then the textured quad twice: the
    // coordinates of each copy follow its own faces.
    write(d.path(), "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let s = ok(&write(
        d.path(),
        "s.toml",
        "[[mesh]]\npath = \"t.obj\"\n[[mesh]]\npath = \"q.obj\"\n\
         [[mesh]]\npath = \"q.obj\"\ntranslate = [3, 0, 0]\n",
    ));
    assert_eq!(s.faces.len(), 3);
    assert!(s.faces[0].texcoords.is_none());
    assert_eq!(
        s.faces[1].texcoords.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 1, 2, 3])
    );
    assert_eq!(
        s.faces[2].texcoords.as_deref().map(<[u32]>::to_vec),
        Some(vec![4, 5, 6, 7])
    );
    assert_eq!(s.texcoords[4..], s.texcoords[..4]);
    let t = |f: usize| s.materials[s.faces[f].material as usize].texture.clone();
    assert!(t(1).is_some() && t(2).is_some());
    assert!(limn_scene::Effects::of(&s).texture);
}

#[test]
fn gltf_wrap_modes_are_drawn_through_a_repeating_texture() {
    // MIRRORED_REPEAT along s: the texture and its mirror image, read at s / 2;
    // CLAMP_TO_EDGE along t: a copy of the edge row on either side, read at
    // (4t + 1) / 6. No warning: both are drawn.
    let d = dir();
    write(d.path(), "tex/c.png", checker());
    let gltf = textured_gltf(&data_uri(&textured_buffer()), r#"{"uri": "tex/c.png"}"#).replace(
        r#""textures": [{"source": 0}],"#,
        r#""textures": [{"source": 0, "sampler": 0}],
  "samplers": [{"wrapS": 33648, "wrapT": 33071}],"#,
    );
    let s = ok(&write(d.path(), "w.gltf", gltf));
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    let t = s.materials[0].texture.as_ref().unwrap();
    assert_eq!((t.width(), t.height()), (8, 6));
    // Row 0 copies row 0 of the checker (the clamped edge), mirrored after 4 texels.
    let row0: Vec<u8> = (0..8).map(|i| t.rgba()[4 * i]).collect();
    assert_eq!(row0, [255, 0, 255, 0, 0, 255, 0, 255]);
    assert_eq!(&t.rgba()[..32], &t.rgba()[32..64]);
    let want = [
        [0.0, 5.0 / 6.0],
        [0.5, 5.0 / 6.0],
        [0.5, 1.0 / 6.0],
        [0.0, 1.0 / 6.0],
    ];
    assert!(close(&s.texcoords, &want), "{:?}", s.texcoords);
}

/// Whether two lists of texture coordinates agree up to rounding.
fn close(a: &[[f64; 2]], b: &[[f64; 2]]) -> bool {
    a.len() == b.len()
        && a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .all(|(x, y)| (x - y).abs() < 1e-12)
}

#[test]
fn mtl_clamp_on_extends_the_edge_texels() {
    let d = dir();
    write(d.path(), "img/c.png", checker());
    write(
        d.path(),
        "m.mtl",
        "newmtl tex\nKd 1 1 1\nillum 0\nmap_Kd -clamp on img/c.png\n",
    );
    let s = ok(&write(d.path(), "q.obj", QUAD));
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    let t = s.materials[0].texture.as_ref().unwrap();
    assert_eq!((t.width(), t.height()), (6, 6));
    let at = |i: usize, j: usize| t.rgba()[4 * (6 * j + i)];
    // The corner texel of the checker (white) fills the 2 × 2 corner; the edges extend.
    assert_eq!([at(0, 0), at(1, 0), at(0, 1), at(1, 1)], [255; 4]);
    assert_eq!((at(2, 0), at(2, 1), at(5, 5)), (0, 0, 255));
    // The face's coordinates (copies of its own) moved onto the inner 4 × 4 texels.
    let f = s.faces[0].texcoords.as_ref().unwrap();
    let st: Vec<[f64; 2]> = f.iter().map(|&i| s.texcoords[i as usize]).collect();
    let (a, b) = (1.0 / 6.0, 5.0 / 6.0);
    assert!(close(&st, &[[a, b], [b, b], [b, a], [a, a]]), "{st:?}");
}
