//! Fixtures written from code, and assertions on loader errors.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use base64::Engine as _;
use limn_load::{load, LoadError, LoadOptions};
use limn_scene::Scene;

/// A fresh temporary folder.
pub fn dir() -> tempfile::TempDir {
    tempfile::tempdir().expect("temp dir")
}

/// Writes `bytes` to `dir/name` and returns the path.
pub fn write(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let p = dir.join(name);
    if let Some(parent) = p.parent() {
        std::fs::create_dir_all(parent).unwrap();
    }
    std::fs::write(&p, bytes).unwrap();
    p
}

/// Loads with default options, expecting success and a valid scene.
pub fn ok(path: &Path) -> Scene {
    let s = load(path, &LoadOptions::default())
        .unwrap_or_else(|e| panic!("{} should load: {e}", path.display()));
    s.validate().expect("loaded scenes validate");
    s
}

/// Loads with default options, expecting an error.
pub fn err(path: &Path) -> LoadError {
    match load(path, &LoadOptions::default()) {
        Ok(_) => panic!("{} should fail to load", path.display()),
        Err(e) => e,
    }
}

/// Asserts that the error's message names `path` and, when given, the line (as
/// `path:line:`), and that its location says so too.
pub fn assert_at(e: &LoadError, path: &Path, line: Option<u64>) {
    let msg = e.to_string();
    let shown = path.display().to_string();
    assert!(
        msg.contains(&shown),
        "message {msg:?} does not name {shown}"
    );
    let at = e.location();
    assert_eq!(at.path, path, "location of {msg:?}");
    if let Some(l) = line {
        assert_eq!(at.line, Some(l), "line of {msg:?}");
        assert!(
            msg.contains(&format!("{shown}:{l}:")),
            "message {msg:?} lacks :{l}:"
        );
    }
}

/// A binary STL of the given triangles, with the given 80-byte header text.
pub fn binary_stl(header: &[u8], tris: &[[[f32; 3]; 3]]) -> Vec<u8> {
    let mut out = vec![0u8; 80];
    out[..header.len().min(80)].copy_from_slice(&header[..header.len().min(80)]);
    out.extend_from_slice(&(tris.len() as u32).to_le_bytes());
    for t in tris {
        out.extend_from_slice(&[0u8; 12]); // normal (ignored)
        for v in t {
            for c in v {
                out.extend_from_slice(&c.to_le_bytes());
            }
        }
        out.extend_from_slice(&[0u8; 2]);
    }
    out
}

/// The 12 triangles of the unit cube, counter-clockwise seen from outside.
pub fn cube_triangles() -> Vec<[[f32; 3]; 3]> {
    let q: [[[f32; 3]; 4]; 6] = [
        [[0., 0., 0.], [0., 1., 0.], [1., 1., 0.], [1., 0., 0.]], // -z
        [[0., 0., 1.], [1., 0., 1.], [1., 1., 1.], [0., 1., 1.]], // +z
        [[0., 0., 0.], [1., 0., 0.], [1., 0., 1.], [0., 0., 1.]], // -y
        [[0., 1., 0.], [0., 1., 1.], [1., 1., 1.], [1., 1., 0.]], // +y
        [[0., 0., 0.], [0., 0., 1.], [0., 1., 1.], [0., 1., 0.]], // -x
        [[1., 0., 0.], [1., 1., 0.], [1., 1., 1.], [1., 0., 1.]], // +x
    ];
    q.iter()
        .flat_map(|f| [[f[0], f[1], f[2]], [f[0], f[2], f[3]]])
        .collect()
}

/// An OBJ unit cube made of six quads, with an MTL library `cube.mtl`.
pub const CUBE_OBJ: &str = "\
# a cube of quads
mtllib cube.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
o box
usemtl red
f 1 4 3 2
f 5 6 7 8
usemtl glass
f 1 2 6 5
f 4 8 7 3
f 1 5 8 4
f 2 3 7 6
";

/// The MTL library of [`CUBE_OBJ`].
pub const CUBE_MTL: &str = "\
newmtl red
Kd 1 0 0
Ka 0.1 0 0
Ks 0.5 0.5 0.5
Ns 32
illum 2
newmtl glass
Kd 0.2 0.4 0.6
d 0.25
illum 0
";

/// A PLY header followed by `body`.
pub fn ply(format: &str, header_rest: &str, body: &[u8]) -> Vec<u8> {
    let mut out = format!("ply\nformat {format} 1.0\n{header_rest}end_header\n").into_bytes();
    out.extend_from_slice(body);
    out
}

/// A binary PLY square (two faces: a triangle with a face colour, a triangle
/// without) with per-vertex colours, in either byte order.
pub fn binary_ply_square(big: bool) -> Vec<u8> {
    let header = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n\
                  property uchar red\nproperty uchar green\nproperty uchar blue\n\
                  element face 2\nproperty list uchar int vertex_indices\n";
    let mut body = Vec::new();
    let f = |v: f32, b: &mut Vec<u8>| {
        b.extend_from_slice(&if big {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        })
    };
    let i = |v: i32, b: &mut Vec<u8>| {
        b.extend_from_slice(&if big {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        })
    };
    let verts = [
        ([0., 0., 0.], [255, 0, 0]),
        ([1., 0., 0.], [255, 0, 0]),
        ([1., 1., 0.], [0, 0, 255]),
        ([0., 1., 0.], [0, 0, 255]),
    ];
    for (p, c) in verts {
        for v in p {
            f(v, &mut body);
        }
        body.extend_from_slice(&c);
    }
    for face in [[0, 1, 2], [0, 2, 3]] {
        body.push(3);
        for v in face {
            i(v, &mut body);
        }
    }
    let fmt = if big {
        "binary_big_endian"
    } else {
        "binary_little_endian"
    };
    ply(fmt, header, &body)
}

/// Buffer bytes of a unit quad in z = 0: four f32 VEC3 positions, then six u16 indices.
pub fn quad_buffer() -> Vec<u8> {
    let mut b = Vec::new();
    for p in [[0f32, 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]] {
        for c in p {
            b.extend_from_slice(&c.to_le_bytes());
        }
    }
    for i in [0u16, 1, 2, 0, 2, 3] {
        b.extend_from_slice(&i.to_le_bytes());
    }
    b
}

/// glTF JSON for the quad of [`quad_buffer`] placed by a two-node hierarchy; `uri` is
/// the buffer's `"uri"` member (or empty for a GLB's BIN chunk).
pub fn quad_gltf(uri: &str, count: usize) -> String {
    let uri = if uri.is_empty() {
        String::new()
    } else {
        format!(r#""uri": "{uri}", "#)
    };
    format!(
        r#"{{
  "asset": {{"version": "2.0"}},
  "scene": 0,
  "scenes": [{{"nodes": [0]}}],
  "nodes": [
    {{"name": "parent", "translation": [10, 0, 0], "children": [1]}},
    {{"name": "child", "mesh": 0, "scale": [2, 2, 2]}}
  ],
  "meshes": [{{"name": "quad", "primitives": [
    {{"attributes": {{"POSITION": 0}}, "indices": 1, "material": 0}}]}}],
  "materials": [{{"name": "red", "alphaMode": "BLEND",
    "pbrMetallicRoughness": {{"baseColorFactor": [1, 0, 0, 0.5]}}}}],
  "buffers": [{{{uri}"byteLength": 60}}],
  "bufferViews": [
    {{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
    {{"buffer": 0, "byteOffset": 48, "byteLength": 12}}
  ],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": {count}, "type": "VEC3",
      "min": [0, 0, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}}
  ]
}}
"#
    )
}

/// A `data:` URI holding `bytes`.
pub fn data_uri(bytes: &[u8]) -> String {
    format!(
        "data:application/octet-stream;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(bytes)
    )
}

/// A GLB container around `json` and `bin`, assembled by hand.
pub fn glb(json: &str, bin: &[u8]) -> Vec<u8> {
    let mut j = json.as_bytes().to_vec();
    while !j.len().is_multiple_of(4) {
        j.push(b' ');
    }
    let mut b = bin.to_vec();
    while !b.len().is_multiple_of(4) {
        b.push(0);
    }
    let total = 12 + 8 + j.len() + if b.is_empty() { 0 } else { 8 + b.len() };
    let mut out = Vec::new();
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(j.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&j);
    if !b.is_empty() {
        out.extend_from_slice(&(b.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&b);
    }
    out
}

/// The three vertices of a unit triangle in OBJ (no face line).
pub const TRI_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

/// An ASCII STL solid with one facet around `body` (its `vertex` lines).
pub fn ascii_stl(body: &str) -> String {
    format!("solid t\nfacet normal 0 0 1\nouter loop\n{body}endloop\nendfacet\nendsolid t\n")
}

/// PLY element declarations for three vertices and one face.
pub const PLY_TRI_HEADER: &str =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
                              element face 1\nproperty list uchar int vertex_indices\n";
