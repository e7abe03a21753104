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
    assert!(
        e.contains("KHR_draco_mesh_compression: the stream does not decode"),
        "{e}"
    );
}

#[test]
fn a_draco_point_cloud_is_read_as_points() {
    use draco_core::{
        DataType, EncoderBuffer, EncoderOptions, GeometryAttributeType, PointAttribute, PointCloud,
        PointCloudEncoder,
    };
    let coords: [f32; 9] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    let mut position = PointAttribute::new();
    position.init(
        GeometryAttributeType::Position,
        3,
        DataType::Float32,
        false,
        3,
    );
    for (i, v) in coords.iter().enumerate() {
        position.buffer_mut().write(i * 4, &v.to_le_bytes());
    }
    let mut cloud = PointCloud::new();
    let id = cloud.add_attribute(position);
    let unique = cloud.attribute(id).unique_id();
    let mut encoder = PointCloudEncoder::new();
    encoder.set_point_cloud(cloud);
    let mut stream = EncoderBuffer::new();
    encoder.encode(&EncoderOptions::new(), &mut stream).unwrap();
    let n = stream.data().len();
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("cloud.bin"), stream.data()).unwrap();
    let ext = "KHR_draco_mesh_compression";
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "extensionsUsed": ["{ext}"],
        "extensionsRequired": ["{ext}"],
        "buffers": [{{"uri": "cloud.bin", "byteLength": {n}}}],
        "bufferViews": [{{"buffer": 0, "byteLength": {n}}}],
        "accessors": [{{"componentType": 5126, "count": 3, "type": "VEC3",
            "min": [0, 0, 0], "max": [1, 1, 0]}}],
        "meshes": [{{"primitives": [{{"mode": 0, "attributes": {{"POSITION": 0}},
            "extensions": {{"{ext}": {{"bufferView": 0, "attributes": {{"POSITION": {unique}}}}}}}}}]}}],
        "nodes": [{{"mesh": 0}}], "scenes": [{{"nodes": [0]}}]}}"#
    );
    let path = dir.path().join("cloud.gltf");
    std::fs::write(&path, json).unwrap();
    // Decoded as a point cloud (a mesh decoder refuses the stream), then, as every
    // point primitive, left out with a warning.
    let s = load(&path, &LoadOptions::default()).unwrap();
    assert!(s.faces.is_empty());
    assert!(
        s.warnings
            .iter()
            .any(|w| w.contains("1 point or line primitives skipped")),
        "{:?}",
        s.warnings
    );
}
