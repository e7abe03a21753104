//! Vertex colours as each format writes them: OBJ `v x y z r g b`, PLY per-vertex
//! colours, glTF `COLOR_0` (float, normalised bytes and shorts; RGB or RGBA).

mod common;

use common::*;

#[test]
fn obj_vertex_colours_are_kept_per_corner() {
    let d = dir();
    let src = "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
    let s = ok(&write(d.path(), "c.obj", src));
    assert_eq!(
        s.colors,
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    );
    assert_eq!(
        s.faces[0].colors.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 1, 2])
    );
    // A corner without a colour: the face has none.
    assert_eq!(s.faces[1].colors, None);
    // Faces with vertex colours and no usemtl: white, not the grey that would darken them.
    let m = &s.materials[s.faces[0].material as usize];
    assert_eq!((m.name.as_str(), m.kd), ("vertex colours", [1.0; 3]));
    assert_eq!(s.materials[s.faces[1].material as usize].name, "default");
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    s.validate().unwrap();
}

#[test]
fn obj_colours_out_of_range_are_clamped_with_a_warning_naming_the_line() {
    let d = dir();
    let src = "v 0 0 0 255 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n";
    let p = write(d.path(), "c.obj", src);
    let s = ok(&p);
    assert_eq!(s.colors[0], [1.0, 0.0, 0.0]);
    assert_eq!(s.warnings.len(), 1);
    assert!(s.warnings[0].contains("c.obj:1:"), "{:?}", s.warnings);
    // A NaN channel (trimesh's nancolor.obj): that vertex has no colour.
    let nan = write(
        d.path(),
        "n.obj",
        "v 0 0 0 1 0 0\nv 1 0 0 nan nan nan\nv 0 1 0 0 0 1\nv 1 1 0 0 1 0\nf 1 2 3\nf 1 4 3\n",
    );
    let s = ok(&nan);
    assert_eq!(s.faces[0].colors, None);
    assert_eq!(
        s.faces[1].colors.as_deref().map(<[u32]>::to_vec),
        Some(vec![0, 2, 1])
    );
    assert!(
        s.warnings.iter().any(|w| w.contains("n.obj:2:")),
        "{:?}",
        s.warnings
    );
}

#[test]
fn obj_point_clouds_take_their_vertex_colours() {
    let d = dir();
    let s = ok(&write(d.path(), "p.obj", "v 0 0 0 1 0 0\nv 1 0 0\n"));
    assert_eq!(s.points.len(), 2);
    assert_eq!(s.points[0].color, [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(
        s.points[1].color,
        limn_scene::PointMark::new(glam::DVec3::ZERO).color
    );
}

/// A triangle with `COLOR_0` of `count` elements of `ty`/`kind` stored as `bytes`.
fn coloured_triangle(component: u32, kind: &str, normalized: bool, colors: &[u8]) -> String {
    let mut b = Vec::new();
    for p in [[0f32, 0., 0.], [1., 0., 0.], [0., 1., 0.]] {
        for c in p {
            b.extend_from_slice(&c.to_le_bytes());
        }
    }
    b.extend_from_slice(colors);
    while b.len() % 4 != 0 {
        b.push(0);
    }
    format!(
        r#"{{
  "asset": {{"version": "2.0"}},
  "nodes": [{{"mesh": 0}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "COLOR_0": 1}}}}]}}],
  "buffers": [{{"uri": "{}", "byteLength": {}}}],
  "bufferViews": [
    {{"buffer": 0, "byteOffset": 0, "byteLength": 36}},
    {{"buffer": 0, "byteOffset": 36, "byteLength": {}}}
  ],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
      "min": [0, 0, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": {component}, "normalized": {normalized},
      "count": 3, "type": "{kind}"}}
  ]
}}"#,
        data_uri(&b),
        b.len(),
        colors.len()
    )
}

#[test]
fn gltf_color_0_of_every_component_type_is_read() {
    let d = dir();
    let floats: Vec<u8> = [1f32, 0., 0., 0., 1., 0., 0., 0., 1.]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    let bytes = [255u8, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255];
    let shorts: Vec<u8> = [65535u16, 0, 0, 0, 65535, 0, 0, 0, 65535]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    for (name, json) in [
        ("f.gltf", coloured_triangle(5126, "VEC3", false, &floats)),
        ("b.gltf", coloured_triangle(5121, "VEC4", true, &bytes)),
        ("s.gltf", coloured_triangle(5123, "VEC3", true, &shorts)),
    ] {
        let s = ok(&write(d.path(), name, json));
        assert_eq!(
            s.colors,
            [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            "{name}"
        );
        assert_eq!(
            s.faces[0].colors.as_deref().map(<[u32]>::to_vec),
            Some(vec![0, 1, 2]),
            "{name}"
        );
        s.validate().unwrap();
    }
    // Unnormalised bytes are not colours.
    let bad = write(
        d.path(),
        "u.gltf",
        coloured_triangle(5121, "VEC4", false, &bytes),
    );
    let e = err(&bad).to_string();
    assert!(e.contains("colour"), "{e}");
}
