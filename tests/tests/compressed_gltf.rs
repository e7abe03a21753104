//! Compressed glTF files as packers write them (`tests/models/`, see its README): the
//! glTF sample Box Textured packed by gltfpack (`KHR_mesh_quantization` with
//! `KHR_texture_transform`, `EXT_meshopt_compression`) draws the same picture as the
//! plain file, and so does the same compressed by glTF-Transform with Draco
//! (`KHR_draco_mesh_compression`); a Draco stream cut short is an error naming the
//! extension and the primitive.

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
    for name in [
        "BoxTextured-quantized.glb",
        "BoxTextured-meshopt.glb",
        "BoxTextured-draco.glb",
    ] {
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
fn a_draco_stream_cut_short_is_an_error_naming_the_extension() {
    // The Draco stream (233 bytes, after the PNG in the binary chunk): all but its
    // header zeroed, so it cannot decode.
    let mut bytes = std::fs::read(model("BoxTextured-draco.glb")).unwrap();
    let at = bytes
        .windows(5)
        .position(|w| w == b"DRACO")
        .expect("a Draco stream");
    bytes[at + 16..at + 200].fill(0);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("broken-draco.glb");
    std::fs::write(&path, bytes).unwrap();
    let e = load(&path, &LoadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("broken-draco.glb"), "{e}");
    assert!(e.contains("mesh 0 primitive 0"), "{e}");
    assert!(e.contains("KHR_draco_mesh_compression"), "{e}");
}
