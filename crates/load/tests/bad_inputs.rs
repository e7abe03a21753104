//! The bad-input battery, first half (empty, truncated, garbage, non-finite): each case
//! for each format it applies to. Every error must be
//! the right variant and name the file, and for text formats the line.

mod common;

use common::*;
use limn_load::LoadError;

// ---------------------------------------------------------------- empty file

#[test]
fn empty_file_every_format() {
    let d = dir();
    for name in ["e.obj", "e.stl", "e.ply", "e.gltf", "e.glb", "e.toml"] {
        let p = write(d.path(), name, b"");
        let e = err(&p);
        assert!(matches!(e, LoadError::Empty { .. }), "{name}: {e}");
        assert_at(&e, &p, None);
    }
}

// ---------------------------------------------------------------- truncated file

#[test]
fn truncated_obj_line() {
    let d = dir();
    let p = write(d.path(), "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1");
    let e = err(&p);
    assert!(matches!(e, LoadError::Syntax { .. }), "{e}");
    assert_at(&e, &p, Some(3));
}

#[test]
fn truncated_ascii_stl() {
    let d = dir();
    let p = write(
        d.path(),
        "t.stl",
        "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n",
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::Truncated { .. }), "{e}");
    assert_at(&e, &p, Some(5));
}

#[test]
fn truncated_binary_stl_header() {
    let d = dir();
    let p = write(d.path(), "t.stl", [7u8; 40]);
    let e = err(&p);
    assert!(matches!(e, LoadError::Truncated { .. }), "{e}");
    assert_at(&e, &p, None);
}

#[test]
fn truncated_ply_header() {
    let d = dir();
    let p = write(
        d.path(),
        "t.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::Truncated { .. }), "{e}");
    assert_at(&e, &p, Some(5));
}

#[test]
fn truncated_binary_ply_inside_a_face_list() {
    let d = dir();
    let mut bytes = binary_ply_square(false);
    bytes.truncate(bytes.len() - 3);
    let p = write(d.path(), "t.ply", bytes);
    let e = err(&p);
    assert!(matches!(e, LoadError::Truncated { .. }), "{e}");
    assert_at(&e, &p, None);
    assert_eq!(e.location().record.as_deref(), Some("face 2"));
}

#[test]
fn truncated_ascii_ply_line() {
    let d = dir();
    let body = "0 0 0\n1 0 0\n0 1 0\n3 0 1\n";
    let p = write(
        d.path(),
        "t.ply",
        ply("ascii", PLY_TRI_HEADER, body.as_bytes()),
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::Syntax { .. }), "{e}");
    assert_at(&e, &p, Some(13));
}

#[test]
fn truncated_gltf_json() {
    let d = dir();
    let json = quad_gltf(&data_uri(&quad_buffer()), 4);
    let cut: String = json.lines().take(6).collect::<Vec<_>>().join("\n");
    let p = write(d.path(), "t.gltf", cut);
    let e = err(&p);
    assert!(matches!(e, LoadError::Truncated { .. }), "{e}");
    assert_at(&e, &p, Some(6));
}

#[test]
fn truncated_glb() {
    let d = dir();
    let full = glb(&quad_gltf("", 4), &quad_buffer());
    let p = write(d.path(), "t.glb", &full[..10]);
    let e = err(&p);
    assert!(matches!(e, LoadError::Truncated { .. }), "{e}");
    assert_at(&e, &p, None);
    let p = write(d.path(), "u.glb", &full[..full.len() - 20]);
    let e = err(&p);
    assert!(matches!(e, LoadError::CountTooLarge { .. }), "{e}");
}

#[test]
fn truncated_toml() {
    let d = dir();
    let p = write(d.path(), "t.toml", "[output]\nsize = [800, 600]\n[camera\n");
    let e = err(&p);
    assert!(matches!(e, LoadError::Syntax { .. }), "{e}");
    assert_at(&e, &p, Some(3));
}

// ---------------------------------------------------------------- binary garbage

fn garbage(n: usize) -> Vec<u8> {
    let mut x: u32 = 0x1234_5678;
    (0..n)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            (x >> 24) as u8
        })
        .chain([0u8])
        .collect()
}

#[test]
fn garbage_text_formats_name_a_line() {
    let d = dir();
    for (name, ok_variant) in [
        ("g.obj", "NotText|Syntax"),
        ("g.ply", "Syntax|NotText"),
        ("g.gltf", "Syntax"),
        ("g.toml", "Syntax"),
    ] {
        let p = write(d.path(), name, garbage(300));
        let e = err(&p);
        assert!(
            matches!(e, LoadError::NotText { .. } | LoadError::Syntax { .. }),
            "{name} ({ok_variant}): {e}"
        );
        assert_at(&e, &p, Some(e.location().line.expect("a line")));
    }
}

#[test]
fn garbage_binary_formats() {
    let d = dir();
    let p = write(d.path(), "g.stl", garbage(300));
    let e = err(&p);
    assert!(matches!(e, LoadError::CountTooLarge { .. }), "{e}");
    assert_at(&e, &p, None);
    let mut g = b"glTF".to_vec();
    g.extend(garbage(300));
    let p = write(d.path(), "g.glb", g);
    let e = err(&p);
    assert_at(&e, &p, None);
}

// ---------------------------------------------------------------- NaN / infinity

#[test]
fn non_finite_obj() {
    let d = dir();
    for v in ["v nan 0 0", "v 0 inf 0", "v 0 0 -1e999", "vn 0 NaN 1"] {
        let p = write(d.path(), "n.obj", format!("{TRI_OBJ}{v}\n"));
        let e = err(&p);
        assert!(matches!(e, LoadError::NonFinite { .. }), "{v}: {e}");
        assert_at(&e, &p, Some(4));
    }
}

#[test]
fn non_finite_stl() {
    let d = dir();
    let p = write(
        d.path(),
        "n.stl",
        ascii_stl("vertex 0 0 0\nvertex inf 0 0\nvertex 0 1 0\n"),
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::NonFinite { .. }), "{e}");
    assert_at(&e, &p, Some(5));
    let mut tris = cube_triangles();
    tris[3][1][2] = f32::NAN;
    let p = write(d.path(), "b.stl", binary_stl(b"", &tris));
    let e = err(&p);
    assert!(matches!(e, LoadError::NonFinite { .. }), "{e}");
    assert_at(&e, &p, None);
    assert_eq!(e.location().record.as_deref(), Some("triangle 4"));
}

#[test]
fn non_finite_ply() {
    let d = dir();
    let body = "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n";
    let p = write(
        d.path(),
        "n.ply",
        ply("ascii", PLY_TRI_HEADER, body.as_bytes()),
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::NonFinite { .. }), "{e}");
    assert_at(&e, &p, Some(11));
    let mut bytes = binary_ply_square(true);
    let at = bytes.len() - 2 * 13 - 4 * 15; // the first vertex's x, big endian
    bytes[at..at + 4].copy_from_slice(&f32::INFINITY.to_be_bytes());
    let p = write(d.path(), "b.ply", bytes);
    let e = err(&p);
    assert!(matches!(e, LoadError::NonFinite { .. }), "{e}");
    assert_eq!(e.location().record.as_deref(), Some("vertex 1"));
}

#[test]
fn non_finite_gltf() {
    let d = dir();
    let mut buf = quad_buffer();
    buf[16..20].copy_from_slice(&f32::NAN.to_le_bytes());
    let p = write(d.path(), "n.gltf", quad_gltf(&data_uri(&buf), 4));
    let e = err(&p);
    assert!(matches!(e, LoadError::NonFinite { .. }), "{e}");
    assert_at(&e, &p, None);
}

#[test]
fn non_finite_toml() {
    let d = dir();
    write(d.path(), "m.obj", format!("{TRI_OBJ}f 1 2 3\n"));
    let p = write(
        d.path(),
        "s.toml",
        "[[mesh]]\npath = \"m.obj\"\ntranslate = [nan, 0, 0]\n",
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::NonFinite { .. }), "{e}");
    assert_at(&e, &p, Some(3));
}
