//! No input makes a loader panic: random bytes, every truncation of valid files, and
//! random mutations of them. Every scene that does load passes `Scene::validate`.

mod common;

use std::path::{Path, PathBuf};

use common::*;
use limn_load::{load_bytes, Format, LoadOptions};
use proptest::prelude::*;

const FORMATS: [(Format, &str); 6] = [
    (Format::Obj, "f.obj"),
    (Format::Stl, "f.stl"),
    (Format::Ply, "f.ply"),
    (Format::Gltf, "f.gltf"),
    (Format::Glb, "f.glb"),
    (Format::Toml, "f.toml"),
];

/// Valid files of every format (with the files they refer to written beside them).
fn fixtures(d: &Path) -> Vec<(Format, PathBuf, Vec<u8>)> {
    write(d, "cube.mtl", CUBE_MTL);
    write(d, "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write(d, "quad.bin", quad_buffer());
    let ascii_stl = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n\
                     vertex 0 1 0\nendloop\nendfacet\nendsolid s\n";
    let ascii_ply = ply(
        "ascii",
        "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
         property uchar red\nproperty uchar green\nproperty uchar blue\n\
         element face 1\nproperty list uchar int vertex_indices\n",
        b"0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n",
    );
    let toml =
        "[camera]\neye = [1, 2, 3]\n[output]\nsize = \"10x10\"\n[[mesh]]\npath = \"tri.obj\"\n\
                scale = 2\nrotate = [0, 90, 0]\nmaterial = { kd = \"#ff0000\" }\n\
                [[light]]\nkind = \"ambient\"\n";
    let all: Vec<(Format, &str, Vec<u8>)> = vec![
        (Format::Obj, "cube.obj", CUBE_OBJ.as_bytes().to_vec()),
        (Format::Stl, "a.stl", ascii_stl.as_bytes().to_vec()),
        (
            Format::Stl,
            "b.stl",
            binary_stl(b"solid x", &cube_triangles()[..3]),
        ),
        (Format::Ply, "a.ply", ascii_ply),
        (Format::Ply, "le.ply", binary_ply_square(false)),
        (Format::Ply, "be.ply", binary_ply_square(true)),
        (
            Format::Gltf,
            "d.gltf",
            quad_gltf(&data_uri(&quad_buffer()), 4).into_bytes(),
        ),
        (
            Format::Gltf,
            "f.gltf",
            quad_gltf("quad.bin", 4).into_bytes(),
        ),
        (Format::Glb, "g.glb", glb(&quad_gltf("", 4), &quad_buffer())),
        (Format::Toml, "s.toml", toml.as_bytes().to_vec()),
    ];
    all.into_iter()
        .map(|(f, name, bytes)| (f, d.join(name), bytes))
        .collect()
}

fn must_not_panic(bytes: &[u8], format: Format, path: &Path) {
    if let Ok(scene) = load_bytes(bytes, format, path, &LoadOptions::default()) {
        scene.validate().expect("a loaded scene validates");
    }
}

#[test]
fn fixtures_load_and_every_truncation_is_handled() {
    let d = dir();
    for (format, path, bytes) in fixtures(d.path()) {
        let scene = load_bytes(&bytes, format, &path, &LoadOptions::default())
            .unwrap_or_else(|e| panic!("fixture {}: {e}", path.display()));
        scene.validate().unwrap();
        assert!(!scene.faces.is_empty());
        for n in 0..bytes.len() {
            must_not_panic(&bytes[..n], format, &path);
        }
    }
}

#[test]
fn every_single_byte_flip_of_small_binaries_is_handled() {
    let d = dir();
    for (format, path, bytes) in fixtures(d.path()) {
        if matches!(format, Format::Stl | Format::Ply | Format::Glb) {
            for i in 0..bytes.len() {
                for v in [0u8, 0xff, bytes[i] ^ 0x80] {
                    let mut b = bytes.clone();
                    b[i] = v;
                    must_not_panic(&b, format, &path);
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn random_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..600), which in 0usize..6) {
        let d = dir();
        let (format, name) = FORMATS[which];
        must_not_panic(&bytes, format, &d.path().join(name));
    }

    #[test]
    fn random_mutations(
        which in 0usize..10,
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..8),
        cut in any::<prop::sample::Index>(),
    ) {
        let d = dir();
        let (format, path, mut bytes) = fixtures(d.path()).swap_remove(which);
        for (at, v) in edits {
            let i = at.index(bytes.len());
            bytes[i] = v;
        }
        let keep = cut.index(bytes.len() + 1).max(bytes.len() / 2);
        must_not_panic(&bytes[..keep], format, &path);
    }

    #[test]
    fn random_obj_like_text(lines in proptest::collection::vec(
        prop::sample::select(vec![
            "v 0 0 0", "v 1 2 3", "v 1e308 1e308 -1e308", "vn 0 0 1", "vt 0 0", "f 1 2 3",
            "f -1 -2 -3", "f 1//1 2//1 3//1", "f 1/1/1 2/1/1 3/1/1 4/1/1", "f 0 1 2",
            "f 1", "f 4294967296 1 2", "f -9223372036854775808 1 2", "o a", "g", "usemtl red",
            "usemtl", "mtllib cube.mtl", "mtllib", "mtllib ../../etc/passwd", "s off",
            "# comment", "", "\\", "l 1 2",
        ]),
        0..30,
    )) {
        let d = dir();
        write(d.path(), "cube.mtl", CUBE_MTL);
        let text = lines.join("\n");
        must_not_panic(text.as_bytes(), Format::Obj, &d.path().join("r.obj"));
    }
}
