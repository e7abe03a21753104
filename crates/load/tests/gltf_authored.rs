//! glTF as authored: sides, alpha modes, the file's camera, and compressed files
//! (`KHR_mesh_quantization`, `EXT_meshopt_compression` read; Draco and KTX2 refused by
//! name).

mod common;

use common::*;
use glam::DVec3;

/// The quad of [`quad_gltf`] with its material's JSON changed by `edit`.
fn quad(edit: impl Fn(String) -> String) -> String {
    edit(quad_gltf(&data_uri(&quad_buffer()), 4))
}

#[test]
fn single_sided_materials_make_single_sided_objects() {
    let d = dir();
    let s = ok(&write(d.path(), "one.gltf", quad(|j| j)));
    assert!(s.objects[0].single_sided, "doubleSided defaults to false");
    let s = ok(&write(
        d.path(),
        "two.gltf",
        quad(|j| {
            j.replace(
                r#""alphaMode": "BLEND","#,
                r#""alphaMode": "BLEND", "doubleSided": true,"#,
            )
        }),
    ));
    assert!(!s.objects[0].single_sided);
}

#[test]
fn mask_below_the_cutoff_cuts_the_primitive_away_and_says_so() {
    let d = dir();
    let masked = |cutoff: &str| {
        quad(move |j| {
            j.replace(
                r#""alphaMode": "BLEND","#,
                &format!(r#""alphaMode": "MASK", "alphaCutoff": {cutoff},"#),
            )
        })
    };
    // Alpha 0.5 against a cutoff of 0.6: cut away.
    let s = ok(&write(d.path(), "cut.gltf", masked("0.6")));
    assert!(s.faces.is_empty());
    assert!(
        s.warnings
            .iter()
            .any(|w| w.contains("MASK") && w.contains("2 faces")),
        "{:?}",
        s.warnings
    );
    // Against 0.4: drawn, opaque.
    let s = ok(&write(d.path(), "kept.gltf", masked("0.4")));
    assert_eq!(s.faces.len(), 2);
    assert_eq!(s.materials[0].opacity, 1.0);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
}

#[test]
fn the_first_camera_is_the_default_view() {
    let d = dir();
    let json = quad(|j| {
        j.replace(
            r#""scenes": [{"nodes": [0]}]"#,
            r#""scenes": [{"nodes": [0, 2]}]"#,
        )
        .replace(
            r#"{"name": "child", "mesh": 0, "scale": [2, 2, 2]}"#,
            r#"{"name": "child", "mesh": 0, "scale": [2, 2, 2]},
    {"camera": 0, "translation": [1, 2, 10], "rotation": [0, 0.7071068, 0, 0.7071068]}"#,
        )
        .replace(
            r#""materials""#,
            r#""cameras": [{"type": "perspective",
    "perspective": {"yfov": 0.5, "znear": 0.1, "zfar": 100}}],
  "materials""#,
        )
    });
    let s = ok(&write(d.path(), "cam.gltf", json));
    let c = s.default_camera.expect("the camera is the default view");
    assert!(s.camera.is_none(), "options and scene files still win");
    assert!((c.eye - DVec3::new(1.0, 2.0, 10.0)).length() < 1e-6);
    // Turned a quarter about +Y: looking down −X.
    let dir = (c.target - c.eye).normalize();
    assert!((dir - DVec3::NEG_X).length() < 1e-6, "{dir}");
    assert!((c.fov_deg - 0.5f64.to_degrees()).abs() < 1e-4);
    assert_eq!((c.near, c.far), (Some(0.1f32 as f64), Some(100.0)));
}

#[test]
fn unread_compression_is_refused_naming_the_extension_first() {
    let d = dir();
    for ext in ["KHR_texture_basisu", "EXT_texture_webp"] {
        let json = quad(|j| {
            j.replacen(
                "{\n",
                &format!(
                    "{{\n  \"extensionsUsed\": [\"{ext}\"], \"extensionsRequired\": [\"{ext}\"],\n"
                ),
                1,
            )
        });
        let p = write(d.path(), &format!("{ext}.gltf"), json);
        let e = err(&p).to_string();
        let at = e.find(ext).unwrap_or(usize::MAX);
        assert!(at < 80, "{e}");
        // Used without being required: the fallback is drawn, with a warning.
        let json = quad(|j| {
            j.replacen(
                "{\n",
                &format!("{{\n  \"extensionsUsed\": [\"{ext}\"],\n"),
                1,
            )
        });
        let s = ok(&write(d.path(), &format!("used-{ext}.gltf"), json));
        assert_eq!(s.faces.len(), 2);
        assert!(
            s.warnings.iter().any(|w| w.contains(ext)),
            "{:?}",
            s.warnings
        );
    }
}

#[test]
fn quantized_positions_are_read() {
    let d = dir();
    // Unnormalised unsigned shorts, as KHR_mesh_quantization allows.
    let mut b = Vec::new();
    for p in [[0u16, 0, 0], [3, 0, 0], [0, 5, 0]] {
        for c in p {
            b.extend_from_slice(&c.to_le_bytes());
        }
    }
    b.extend_from_slice(&[0, 0]); // padding to 4 bytes a vertex
    let json = format!(
        r#"{{
  "asset": {{"version": "2.0"}},
  "extensionsUsed": ["KHR_mesh_quantization"],
  "extensionsRequired": ["KHR_mesh_quantization"],
  "nodes": [{{"mesh": 0}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
  "buffers": [{{"uri": "{}", "byteLength": 20}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 18}}],
  "accessors": [{{"bufferView": 0, "componentType": 5123, "count": 3, "type": "VEC3",
    "min": [0, 0, 0], "max": [3, 5, 0]}}]
}}"#,
        data_uri(&b)
    );
    let s = ok(&write(d.path(), "q.gltf", json));
    assert_eq!(
        s.vertices,
        [
            DVec3::ZERO,
            DVec3::new(3.0, 0.0, 0.0),
            DVec3::new(0.0, 5.0, 0.0)
        ]
    );
}

#[test]
fn meshopt_compressed_views_are_decoded() {
    let d = dir();
    let positions: Vec<[f32; 3]> = vec![[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]];
    let indices: Vec<u32> = vec![0, 1, 2, 0, 2, 3];
    let vb = meshopt::encode_vertex_buffer(&positions).unwrap();
    let ib = meshopt::encode_index_buffer(&indices, 4).unwrap();
    let mut packed = vb.clone();
    packed.extend_from_slice(&ib);
    let json = format!(
        r#"{{
  "asset": {{"version": "2.0"}},
  "extensionsUsed": ["EXT_meshopt_compression"],
  "extensionsRequired": ["EXT_meshopt_compression"],
  "nodes": [{{"mesh": 0}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1}}]}}],
  "buffers": [
    {{"uri": "{}", "byteLength": {}}},
    {{"byteLength": 72, "extensions": {{"EXT_meshopt_compression": {{"fallback": true}}}}}}
  ],
  "bufferViews": [
    {{"buffer": 1, "byteOffset": 0, "byteLength": 48, "byteStride": 12,
      "extensions": {{"EXT_meshopt_compression": {{"buffer": 0, "byteOffset": 0,
        "byteLength": {}, "byteStride": 12, "count": 4, "mode": "ATTRIBUTES"}}}}}},
    {{"buffer": 1, "byteOffset": 48, "byteLength": 24,
      "extensions": {{"EXT_meshopt_compression": {{"buffer": 0, "byteOffset": {},
        "byteLength": {}, "byteStride": 4, "count": 6, "mode": "TRIANGLES"}}}}}}
  ],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
      "min": [0, 0, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"}}
  ]
}}"#,
        data_uri(&packed),
        packed.len(),
        vb.len(),
        vb.len(),
        ib.len()
    );
    let s = ok(&write(d.path(), "m.gltf", json));
    let want: Vec<DVec3> = positions
        .iter()
        .map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into()))
        .collect();
    assert_eq!(s.vertices, want);
    assert_eq!(s.faces.len(), 2);
    assert_eq!(s.faces[1].vertices.to_vec(), vec![0, 2, 3]);
}
