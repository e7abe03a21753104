//! The bad-input battery, second half: bad indices, short faces, references leaving
//! the folder, counts beyond the data, extensions, I/O, format-specific errors. Every
//! error must be the right variant and name the file, and for text formats the line.

mod common;

use common::*;
use limn_load::{load, LoadError, LoadOptions};

// ---------------------------------------------------------------- bad indices

#[test]
fn index_zero_and_out_of_range_obj() {
    let d = dir();
    for (f, zero) in [
        ("f 0 1 2", true),
        ("f 1 2 4", false),
        ("f -4 1 2", false),
        ("f 1//3 2//1 3//1", false),
    ] {
        let p = write(d.path(), "i.obj", format!("{TRI_OBJ}vn 0 0 1\n{f}\n"));
        let e = err(&p);
        if zero {
            assert!(matches!(e, LoadError::IndexZero { .. }), "{f}: {e}");
        } else {
            assert!(matches!(e, LoadError::IndexOutOfRange { .. }), "{f}: {e}");
        }
        assert_at(&e, &p, Some(5));
    }
}

#[test]
fn texture_coordinates_and_normals_never_defined_are_dropped_with_a_warning() {
    // Exporters write `f 1/1/1` with no `vt` or `vn` in the file: the faces are drawn
    // without them, one warning per kind naming the first line and the count.
    let d = dir();
    for (body, what, line) in [
        (
            "f 1/1/1 2/2/2 3/3/3\nf 3/1 2/1 1/1\n",
            "texture coordinates",
            4,
        ),
        (
            "f 1//1 2//2 3//3\nf 1 2 3\nf 3//1 2//1 1//1\n",
            "normals",
            4,
        ),
    ] {
        let p = write(d.path(), "u.obj", format!("{TRI_OBJ}{body}"));
        let s = ok(&p);
        assert!(s.faces.len() >= 2, "{what}");
        assert!(s
            .faces
            .iter()
            .all(|f| f.texcoords.is_none() && f.normals.is_none()));
        let w: Vec<_> = s.warnings.iter().filter(|w| w.contains(what)).collect();
        assert_eq!(w.len(), 1, "{:?}", s.warnings);
        assert!(
            w[0].contains(&format!("u.obj:{line}:")) && w[0].contains("(2 faces)"),
            "{w:?}"
        );
    }
    // Once some are defined, an index beyond them is an error, as before.
    let p = write(
        d.path(),
        "v.obj",
        format!("{TRI_OBJ}vt 0 0\nf 1/1 2/1 3/2\n"),
    );
    assert!(matches!(err(&p), LoadError::IndexOutOfRange { .. }));
}

#[test]
fn index_out_of_range_ply_and_gltf() {
    let d = dir();
    let body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n";
    let p = write(
        d.path(),
        "i.ply",
        ply("ascii", PLY_TRI_HEADER, body.as_bytes()),
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::IndexOutOfRange { .. }), "{e}");
    assert_at(&e, &p, Some(13));
    let body = "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n";
    let p = write(
        d.path(),
        "j.ply",
        ply("ascii", PLY_TRI_HEADER, body.as_bytes()),
    );
    assert!(matches!(err(&p), LoadError::IndexOutOfRange { .. }));
    let mut buf = quad_buffer();
    buf[50..52].copy_from_slice(&9u16.to_le_bytes());
    let p = write(d.path(), "i.gltf", quad_gltf(&data_uri(&buf), 4));
    let e = err(&p);
    assert!(matches!(e, LoadError::IndexOutOfRange { .. }), "{e}");
    assert_at(&e, &p, None);
}

// ---------------------------------------------------------------- fewer than 3 vertices

#[test]
fn too_few_vertices() {
    let d = dir();
    let p = write(d.path(), "f.obj", format!("{TRI_OBJ}f 1 2\n"));
    let e = err(&p);
    assert!(
        matches!(e, LoadError::TooFewVertices { count: 2, .. }),
        "{e}"
    );
    assert_at(&e, &p, Some(4));
    let body = "0 0 0\n1 0 0\n0 1 0\n2 0 1\n";
    let p = write(
        d.path(),
        "f.ply",
        ply("ascii", PLY_TRI_HEADER, body.as_bytes()),
    );
    let e = err(&p);
    assert!(
        matches!(e, LoadError::TooFewVertices { count: 2, .. }),
        "{e}"
    );
    assert_at(&e, &p, Some(13));
    let p = write(d.path(), "f.stl", ascii_stl("vertex 0 0 0\nvertex 1 0 0\n"));
    let e = err(&p);
    assert!(
        matches!(e, LoadError::TooFewVertices { count: 2, .. }),
        "{e}"
    );
    assert_at(&e, &p, Some(6));
}

// ---------------------------------------------------------------- references leaving the folder

#[test]
fn mtllib_outside_the_folder_is_refused_unless_allowed() {
    let d = dir();
    write(d.path(), "outside.mtl", "newmtl a\nKd 1 0 0\n");
    let abs = d.path().join("outside.mtl");
    let mut cases = vec!["../outside.mtl".to_string(), abs.display().to_string()];
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(&abs, d.path().join("in/link.mtl")).unwrap_or_else(|_| {
            std::fs::create_dir_all(d.path().join("in")).unwrap();
            std::os::unix::fs::symlink(&abs, d.path().join("in/link.mtl")).unwrap();
        });
        cases.push("link.mtl".to_string());
    }
    for r in cases {
        let p = write(
            d.path(),
            "in/m.obj",
            format!("mtllib {r}\n{TRI_OBJ}usemtl a\nf 1 2 3\n"),
        );
        let e = err(&p);
        assert!(matches!(e, LoadError::OutsideFolder { .. }), "{r}: {e}");
        assert_at(&e, &p, Some(1));
        let s = load(
            &p,
            &LoadOptions {
                allow_outside: true,
            },
        )
        .unwrap();
        assert_eq!(
            s.materials[0].kd,
            [1.0, 0.0, 0.0],
            "{r} is followed when allowed"
        );
    }
}

#[test]
fn gltf_buffer_outside_the_folder_is_refused() {
    let d = dir();
    write(d.path(), "quad.bin", quad_buffer());
    let p = write(d.path(), "in/q.gltf", quad_gltf("../quad.bin", 4));
    let e = err(&p);
    assert!(matches!(e, LoadError::OutsideFolder { .. }), "{e}");
    assert_at(&e, &p, None);
    assert!(load(
        &p,
        &LoadOptions {
            allow_outside: true
        }
    )
    .is_ok());
}

#[test]
fn scene_mesh_outside_the_folder_is_refused() {
    let d = dir();
    write(d.path(), "m.obj", format!("{TRI_OBJ}f 1 2 3\n"));
    let p = write(
        d.path(),
        "in/s.toml",
        "# scene\n[[mesh]]\npath = \"../m.obj\"\n",
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::OutsideFolder { .. }), "{e}");
    assert_at(&e, &p, Some(3));
    assert_eq!(
        load(
            &p,
            &LoadOptions {
                allow_outside: true
            }
        )
        .unwrap()
        .faces
        .len(),
        1
    );
}

// ---------------------------------------------------------------- counts beyond the data

#[test]
fn counts_claiming_more_than_the_file_holds() {
    let d = dir();
    let mut stl = binary_stl(b"", &cube_triangles());
    stl[80..84].copy_from_slice(&4_000_000_000u32.to_le_bytes());
    let p = write(d.path(), "c.stl", stl);
    let e = err(&p);
    assert!(
        matches!(
            e,
            LoadError::CountTooLarge {
                claimed: 4_000_000_000,
                room: 12,
                ..
            }
        ),
        "{e}"
    );
    assert_at(&e, &p, None);

    let huge = PLY_TRI_HEADER.replace("vertex 3", "vertex 4000000000");
    for fmt in ["ascii", "binary_little_endian"] {
        let p = write(
            d.path(),
            "c.ply",
            ply(fmt, &huge, b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
        );
        let e = err(&p);
        assert!(matches!(e, LoadError::CountTooLarge { .. }), "{fmt}: {e}");
        assert_at(&e, &p, Some(3));
    }

    let p = write(
        d.path(),
        "c.gltf",
        quad_gltf(&data_uri(&quad_buffer()), 400),
    );
    let e = err(&p);
    assert!(
        matches!(e, LoadError::CountTooLarge { claimed: 400, .. }),
        "{e}"
    );
    assert_at(&e, &p, None);

    let mut g = glb(&quad_gltf("", 4), &quad_buffer());
    g[12..16].copy_from_slice(&u32::MAX.to_le_bytes());
    let p = write(d.path(), "c.glb", g);
    let e = err(&p);
    assert!(matches!(e, LoadError::CountTooLarge { .. }), "{e}");
    assert_at(&e, &p, None);
}

// ---------------------------------------------------------------- extension and I/O

#[test]
fn unsupported_extension() {
    let d = dir();
    for name in ["m.3ds", "noext"] {
        let p = write(d.path(), name, "v 0 0 0\n");
        let e = err(&p);
        assert!(matches!(e, LoadError::UnsupportedExtension { .. }), "{e}");
        assert_at(&e, &p, None);
    }
}

#[test]
fn unreadable_file() {
    let d = dir();
    let p = d.path().join("missing.obj");
    let e = err(&p);
    assert!(matches!(e, LoadError::Io { .. }), "{e}");
    assert_at(&e, &p, None);
    let p = d.path().join("folder.stl");
    std::fs::create_dir(&p).unwrap();
    let e = err(&p);
    assert!(matches!(e, LoadError::Io { .. }), "{e}");
    let p = d.path().join("missing.toml");
    assert!(matches!(err(&p), LoadError::Io { .. }));
}

// ---------------------------------------------------------------- format-specific

#[test]
fn obj_unknown_statement_and_bad_numbers() {
    let d = dir();
    for (src, line) in [
        ("v 0 0 0\nbogus 1 2\n", 2),
        ("v 0 0 0\nv 1 x 0\n", 2),
        ("v 0 0 0 1 2 3 4 5\n", 1),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3.5\n", 4),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3/4 2 3\n", 4),
    ] {
        let p = write(d.path(), "u.obj", src);
        let e = err(&p);
        assert!(matches!(e, LoadError::Syntax { .. }), "{src:?}: {e}");
        assert_at(&e, &p, Some(line));
    }
}

#[test]
fn broken_mtl_names_the_mtl_file_and_line() {
    let d = dir();
    let mtl = write(d.path(), "b.mtl", "newmtl a\nKd 1 0 0\nd nope\n");
    let p = write(
        d.path(),
        "b.obj",
        format!("mtllib b.mtl\n{TRI_OBJ}f 1 2 3\n"),
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::Syntax { .. }), "{e}");
    assert_at(&e, &mtl, Some(3));
}

#[test]
fn ply_semantic_errors() {
    let d = dir();
    let no_xyz = "element vertex 1\nproperty float a\n";
    let p = write(d.path(), "x.ply", ply("ascii", no_xyz, b"1\n"));
    let e = err(&p);
    assert!(matches!(e, LoadError::Invalid { .. }), "{e}");
    assert_at(&e, &p, Some(3));
    let p = write(d.path(), "y.ply", "ply\nformat ascii 2.0\nend_header\n");
    let e = err(&p);
    assert!(matches!(e, LoadError::Syntax { .. }), "{e}");
    assert_at(&e, &p, Some(2));
    // A value beyond the header's properties is ignored, with a warning naming its line.
    let body = "0 0 0 9\n1 0 0\n0 1 0\n3 0 1 2\n";
    let p = write(
        d.path(),
        "z.ply",
        ply("ascii", PLY_TRI_HEADER, body.as_bytes()),
    );
    let s = ok(&p);
    assert_eq!(s.faces.len(), 1);
    assert!(
        s.warnings.iter().any(|w| w.contains("z.ply:10:")),
        "{:?}",
        s.warnings
    );
}

#[test]
fn gltf_invalid_documents() {
    let d = dir();
    let bad_ref = quad_gltf(&data_uri(&quad_buffer()), 4).replace(r#""mesh": 0"#, r#""mesh": 7"#);
    let p = write(d.path(), "v.gltf", bad_ref);
    let e = err(&p);
    assert!(matches!(e, LoadError::Invalid { .. }), "{e}");
    assert_at(&e, &p, None);
    let cycle = quad_gltf(&data_uri(&quad_buffer()), 4).replace(
        r#""scale": [2, 2, 2]"#,
        r#""scale": [2, 2, 2], "children": [0]"#,
    );
    let p = write(d.path(), "c.gltf", cycle);
    let e = err(&p);
    assert!(matches!(e, LoadError::Invalid { .. }), "{e}");
    let p = write(
        d.path(),
        "s.gltf",
        "{\"asset\": {\"version\": \"2.0\"},\n \"nodes\": 3}\n",
    );
    let e = err(&p);
    assert!(matches!(e, LoadError::Syntax { .. }), "{e}");
    assert_at(&e, &p, Some(2));
}

#[test]
fn gltf_position_accessor_out_of_range_is_an_error_not_a_panic() {
    // `gltf-json` indexes the POSITION accessor while validating, unchecked (found by
    // the `gltf` fuzz target); in a GLB as in JSON.
    let d = dir();
    let json =
        quad_gltf(&data_uri(&quad_buffer()), 4).replace(r#""POSITION": 0"#, r#""POSITION": 5"#);
    assert!(json.contains(r#""POSITION": 5"#));
    let p = write(d.path(), "a.gltf", &json);
    let e = err(&p);
    assert!(matches!(e, LoadError::Invalid { .. }), "{e}");
    assert!(e.to_string().contains("POSITION"), "{e}");
    assert_at(&e, &p, None);
    let glb_json = quad_gltf("", 4).replace(r#""POSITION": 0"#, r#""POSITION": 2"#);
    let p = write(d.path(), "a.glb", glb(&glb_json, &quad_buffer()));
    let e = err(&p);
    assert!(matches!(e, LoadError::Invalid { .. }), "{e}");
}
