//! Compressed glTF files as packers write them (`tests/models/`, see its README): the
//! glTF sample Box Textured packed by gltfpack (`KHR_mesh_quantization` with
//! `KHR_texture_transform`, `EXT_meshopt_compression`) draws the same picture as the
//! plain file; compressed by glTF-Transform with Draco, it is refused naming the
//! extension first.

use std::path::{Path, PathBuf};

use limn_depthsort::{order, OrderOptions};
use limn_load::{load, LoadOptions};
use limn_paint::{picture, PngOptions, PngPainter, Style};
use limn_scene::{Camera, Scene};

fn model(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(name)
}

fn read(name: &str) -> Scene {
    load(&model(name), &LoadOptions::default()).unwrap()
}

/// limn's PNG of `scene` from `camera`, RGBA.
fn drawn(scene: &Scene, camera: &Camera) -> Vec<u8> {
    let o = order(scene, camera, &OrderOptions::default()).unwrap();
    let pic = picture(scene, &o, &Style::default());
    let (png, _) = PngPainter::new(PngOptions::default()).render(&pic).unwrap();
    png.data().to_vec()
}

#[test]
fn packed_boxes_draw_the_plain_box() {
    let plain = read("BoxTextured.glb");
    let camera = Camera::framing(&plain, 240, 180).unwrap();
    let want = drawn(&plain, &camera);
    for name in ["BoxTextured-quantized.glb", "BoxTextured-meshopt.glb"] {
        let s = read(name);
        assert!(s.warnings.is_empty(), "{name}: {:?}", s.warnings);
        assert_eq!(s.faces.len(), plain.faces.len(), "{name}");
        let got = drawn(&s, &camera);
        let far = want
            .chunks_exact(4)
            .zip(got.chunks_exact(4))
            .filter(|(a, b)| (0..4).any(|k| a[k].abs_diff(b[k]) > 16))
            .count();
        // Quantized positions and texture coordinates move edges by a fraction of a
        // pixel at most.
        assert!(far * 200 < want.len() / 4, "{name}: {far} pixels differ");
    }
}

#[test]
fn draco_is_refused_naming_the_extension_first() {
    let e = load(&model("BoxTextured-draco.glb"), &LoadOptions::default())
        .unwrap_err()
        .to_string();
    let at = e.find("KHR_draco_mesh_compression").expect("named");
    let file = e.find("BoxTextured-draco.glb").unwrap();
    assert!(at < file + 80, "{e}");
}
