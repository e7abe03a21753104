//! The bad-input battery through the command: each case exits with status 1, names the
//! file (and, for text formats, the line), and leaves no output or temporary file.

mod common;

use common::{assert_failed_cleanly, limn, put, stray_temporaries, tempdir, TRIANGLE_OBJ};

/// Renders `input` (already written in `dir`) to `out.svg` and checks a clean failure
/// whose message contains every needle.
fn fails(dir: &std::path::Path, input: &str, needles: &[&str]) -> String {
    fails_with(dir, &["render", input, "-o", "out.svg"], "out.svg", needles)
}

fn fails_with(dir: &std::path::Path, args: &[&str], out: &str, needles: &[&str]) -> String {
    let run = limn(dir, args);
    assert_failed_cleanly(&run, 1, dir, out);
    for n in needles {
        assert!(run.stderr.contains(n), "stderr lacks `{n}`: {}", run.stderr);
    }
    assert!(
        !run.stderr.contains("panicked"),
        "limn panicked: {}",
        run.stderr
    );
    run.stderr
}

/// A binary STL holding `n` copies of one triangle, claiming `claimed` triangles.
fn binary_stl(n: usize, claimed: u32) -> Vec<u8> {
    let mut b = vec![0u8; 80];
    b.extend_from_slice(&claimed.to_le_bytes());
    for _ in 0..n {
        let coords: [f32; 12] = [0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1., 0.];
        for c in coords {
            b.extend_from_slice(&c.to_le_bytes());
        }
        b.extend_from_slice(&0u16.to_le_bytes());
    }
    b
}

/// A binary little-endian PLY header claiming `verts` vertices and `faces` faces, then
/// three vertices and one triangle.
fn binary_ply(verts: u32, faces: u32) -> Vec<u8> {
    let mut b = format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {verts}\n\
         property float x\nproperty float y\nproperty float z\n\
         element face {faces}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    .into_bytes();
    for c in [0f32, 0., 0., 1., 0., 0., 0., 1., 0.] {
        b.extend_from_slice(&c.to_le_bytes());
    }
    b.push(3);
    for i in [0i32, 1, 2] {
        b.extend_from_slice(&i.to_le_bytes());
    }
    b
}

#[test]
fn the_well_formed_files_of_this_battery_render() {
    // The fixtures below differ from these only in the defect under test.
    let d = tempdir();
    put(d.path(), "ok.obj", TRIANGLE_OBJ);
    put(d.path(), "ok.stl", binary_stl(1, 1));
    put(d.path(), "ok.ply", binary_ply(3, 1));
    for input in ["ok.obj", "ok.stl", "ok.ply"] {
        let run = limn(d.path(), &["render", input, "-o", "out.svg"]);
        assert_eq!(run.code, 0, "{input}: {}", run.stderr);
        assert!(d.path().join("out.svg").exists());
        std::fs::remove_file(d.path().join("out.svg")).unwrap();
    }
}

#[test]
fn empty_file() {
    let d = tempdir();
    put(d.path(), "a.obj", "");
    fails(d.path(), "a.obj", &["a.obj", "empty"]);
}

#[test]
fn truncated_binary_stl() {
    let d = tempdir();
    let mut b = binary_stl(2, 2);
    b.truncate(b.len() - 20);
    put(d.path(), "a.stl", b);
    fails(d.path(), "a.stl", &["a.stl"]);
}

#[test]
fn truncated_ascii_stl() {
    let d = tempdir();
    put(
        d.path(),
        "a.stl",
        "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n",
    );
    fails(d.path(), "a.stl", &["a.stl:"]);
}

#[test]
fn truncated_binary_ply() {
    let d = tempdir();
    let mut b = binary_ply(3, 1);
    b.truncate(b.len() - 9);
    put(d.path(), "a.ply", b);
    fails(d.path(), "a.ply", &["a.ply"]);
}

#[test]
fn binary_garbage_with_obj_extension() {
    let d = tempdir();
    // Deterministic bytes covering the whole range, including NUL.
    let bytes: Vec<u8> = (0..4096u32)
        .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
        .collect();
    put(d.path(), "a.obj", bytes);
    fails(d.path(), "a.obj", &["a.obj:"]);
}

#[test]
fn nan_coordinate() {
    let d = tempdir();
    put(d.path(), "a.obj", "v 0 0 0\nv 1 0 0\nv nan 0 0\nf 1 2 3\n");
    fails(d.path(), "a.obj", &["a.obj:3"]);
}

#[test]
fn infinite_coordinate() {
    let d = tempdir();
    put(d.path(), "a.obj", "v 0 0 0\nv 1 0 0\nv inf 0 0\nf 1 2 3\n");
    fails(d.path(), "a.obj", &["a.obj:3"]);
}

#[test]
fn coordinate_overflowing_f64() {
    let d = tempdir();
    put(
        d.path(),
        "a.obj",
        "v 0 0 0\nv 1e400 0 0\nv 0 1 0\nf 1 2 3\n",
    );
    fails(d.path(), "a.obj", &["a.obj:2"]);
}

#[test]
fn twenty_digit_index_is_too_large_not_a_non_integer() {
    let d = tempdir();
    put(
        d.path(),
        "a.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
    );
    let e = fails(d.path(), "a.obj", &["a.obj:4", "too large"]);
    assert!(!e.contains("not an integer"), "{e}");
    put(d.path(), "b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x3\n");
    fails(d.path(), "b.obj", &["b.obj:4", "not an integer"]);
}

#[test]
fn face_index_out_of_range() {
    let d = tempdir();
    put(d.path(), "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    fails(d.path(), "a.obj", &["a.obj:4", "4"]);
}

#[test]
fn negative_face_index_out_of_range() {
    let d = tempdir();
    put(d.path(), "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n");
    fails(d.path(), "a.obj", &["a.obj:4"]);
}

#[test]
fn face_index_zero() {
    let d = tempdir();
    put(d.path(), "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    fails(d.path(), "a.obj", &["a.obj:4"]);
}

#[test]
fn face_with_two_vertices() {
    let d = tempdir();
    put(d.path(), "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
    fails(d.path(), "a.obj", &["a.obj:4"]);
}

#[test]
fn missing_mtl_warns_and_renders() {
    let d = tempdir();
    put(
        d.path(),
        "a.obj",
        format!("mtllib missing.mtl\nusemtl m\n{TRIANGLE_OBJ}"),
    );
    let run = limn(d.path(), &["render", "a.obj", "-o", "out.svg"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stderr.contains("warning"), "{}", run.stderr);
    assert!(run.stderr.contains("a.obj:1"), "{}", run.stderr);
    assert!(run.stderr.contains("missing.mtl"), "{}", run.stderr);
    let svg = std::fs::read_to_string(d.path().join("out.svg")).unwrap();
    assert!(svg.contains("<path"), "{svg}");
}

#[test]
fn mtllib_escaping_the_folder_is_refused() {
    let d = tempdir();
    put(d.path(), "x.mtl", "newmtl m\nillum 0\nKd 1 0 0\n");
    put(
        d.path(),
        "sub/a.obj",
        format!("mtllib ../x.mtl\nusemtl m\n{TRIANGLE_OBJ}"),
    );
    let err = fails_with(
        d.path(),
        &["render", "sub/a.obj", "-o", "sub/out.svg"],
        "sub/out.svg",
        &["a.obj:1", "../x.mtl", "--allow-outside"],
    );
    assert!(err.contains("refus"), "{err}");
}

#[test]
fn mtllib_escaping_the_folder_loads_with_allow_outside() {
    let d = tempdir();
    put(d.path(), "x.mtl", "newmtl m\nillum 0\nKd 1 0 0\n");
    put(
        d.path(),
        "sub/a.obj",
        format!("mtllib ../x.mtl\nusemtl m\n{TRIANGLE_OBJ}"),
    );
    let run = limn(
        d.path(),
        &[
            "render",
            "sub/a.obj",
            "-o",
            "sub/out.svg",
            "--allow-outside",
        ],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = std::fs::read_to_string(d.path().join("sub/out.svg")).unwrap();
    // The material from outside was used: exactly red.
    assert!(svg.contains("#ff0000"), "{svg}");
}

#[test]
fn absolute_mtllib_is_refused() {
    let d = tempdir();
    let mtl = put(d.path(), "x.mtl", "newmtl m\nKd 1 0 0\n");
    put(
        d.path(),
        "sub/a.obj",
        format!("mtllib {}\n{TRIANGLE_OBJ}", mtl.display()),
    );
    fails_with(
        d.path(),
        &["render", "sub/a.obj", "-o", "sub/out.svg"],
        "sub/out.svg",
        &["a.obj:1"],
    );
}

#[test]
fn scene_mesh_escaping_the_folder_is_refused() {
    let d = tempdir();
    put(d.path(), "tri.obj", TRIANGLE_OBJ);
    put(d.path(), "sub/s.toml", "[[mesh]]\npath = \"../tri.obj\"\n");
    fails_with(
        d.path(),
        &["render", "sub/s.toml", "-o", "sub/out.svg"],
        "sub/out.svg",
        &["s.toml:2", "../tri.obj"],
    );
    // The same scene file is fine when allowed.
    let run = limn(
        d.path(),
        &[
            "render",
            "sub/s.toml",
            "-o",
            "sub/out.svg",
            "--allow-outside",
        ],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(d.path().join("sub/out.svg").exists());
}

#[test]
fn scene_file_with_missing_mesh() {
    let d = tempdir();
    put(d.path(), "s.toml", "[[mesh]]\npath = \"nowhere.obj\"\n");
    fails(d.path(), "s.toml", &["s.toml:2", "nowhere.obj"]);
}

#[test]
fn scene_file_syntax_error() {
    let d = tempdir();
    put(d.path(), "s.toml", "[[mesh]]\npath = \n");
    fails(d.path(), "s.toml", &["s.toml:2"]);
}

#[test]
fn binary_stl_claiming_more_triangles_than_it_holds() {
    let d = tempdir();
    put(d.path(), "a.stl", binary_stl(1, 1000));
    fails(d.path(), "a.stl", &["a.stl", "1000"]);
}

#[test]
fn binary_stl_claiming_billions_of_triangles() {
    let d = tempdir();
    put(d.path(), "a.stl", binary_stl(1, u32::MAX));
    fails(d.path(), "a.stl", &["a.stl"]);
}

#[test]
fn binary_ply_claiming_more_faces_than_it_holds() {
    let d = tempdir();
    put(d.path(), "a.ply", binary_ply(3, 5));
    fails(d.path(), "a.ply", &["a.ply"]);
}

#[test]
fn binary_ply_claiming_billions_of_vertices() {
    let d = tempdir();
    put(d.path(), "a.ply", binary_ply(4_000_000_000, 1));
    fails(d.path(), "a.ply", &["a.ply:3"]);
}

#[test]
fn ascii_ply_claiming_more_vertices_than_it_holds() {
    let d = tempdir();
    put(
        d.path(),
        "a.ply",
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n\
         property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
         end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    );
    fails(d.path(), "a.ply", &["a.ply:"]);
}

#[test]
fn unsupported_extension() {
    let d = tempdir();
    put(d.path(), "a.xyz", TRIANGLE_OBJ);
    fails(d.path(), "a.xyz", &["a.xyz", "xyz"]);
}

#[test]
fn missing_input() {
    let d = tempdir();
    fails(d.path(), "nothing.obj", &["nothing.obj"]);
}

#[test]
fn unknown_output_extension() {
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    fails_with(
        d.path(),
        &["render", "a.obj", "-o", "out.jpg"],
        "out.jpg",
        &["out.jpg"],
    );
}

#[test]
fn output_over_a_folder_fails_without_leaving_a_temporary_file() {
    // The temporary file is created and written, then cannot be renamed over a folder.
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    std::fs::create_dir(d.path().join("taken.svg")).unwrap();
    let run = limn(d.path(), &["render", "a.obj", "-o", "taken.svg"]);
    assert_eq!(run.code, 1, "{}", run.stderr);
    assert!(run.stderr.contains("taken.svg"), "{}", run.stderr);
    assert!(d.path().join("taken.svg").is_dir());
    assert!(stray_temporaries(d.path()).is_empty());
}

#[test]
fn output_into_a_missing_folder() {
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    let run = limn(d.path(), &["render", "a.obj", "-o", "no/such/out.svg"]);
    assert_eq!(run.code, 1, "{}", run.stderr);
    assert!(run.stderr.contains("no/such"), "{}", run.stderr);
    assert!(stray_temporaries(d.path()).is_empty());
}

#[test]
fn scene_without_faces() {
    let d = tempdir();
    put(d.path(), "a.obj", "# nothing\n");
    fails(
        d.path(),
        "a.obj",
        &["a.obj", "no faces, lines, points or labels"],
    );
}

#[test]
fn huge_but_finite_coordinates_name_the_file() {
    let d = tempdir();
    put(
        d.path(),
        "a.obj",
        "v 1e300 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    );
    let run = limn(d.path(), &["render", "a.obj", "-o", "out.svg"]);
    // Either it renders, or it says which input could not be framed.
    if run.code != 0 {
        assert_failed_cleanly(&run, 1, d.path(), "out.svg");
        assert!(run.stderr.contains("a.obj"), "{}", run.stderr);
    }
    assert!(!run.stderr.contains("panicked"), "{}", run.stderr);
}

#[test]
fn scene_file_naming_a_bad_mesh_names_both_once() {
    let d = tempdir();
    put(d.path(), "a.obj", "v 0 0 0\nv 1 0 0\nv nan 0 0\nf 1 2 3\n");
    put(
        d.path(),
        "s.toml",
        "# a figure\n[[mesh]]\npath = \"a.obj\"\n",
    );
    let err = fails(d.path(), "s.toml", &["s.toml:3", "a.obj:3"]);
    assert_eq!(err.matches("a.obj:3").count(), 1, "repeated: {err}");
}

#[test]
fn scene_file_with_an_unusable_camera() {
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    put(
        d.path(),
        "s.toml",
        "[camera]\neye = [1, 1, 1]\ntarget = [1, 1, 1]\n[[mesh]]\npath = \"a.obj\"\n",
    );
    let err = fails(d.path(), "s.toml", &["s.toml:1", "coincide"]);
    assert_eq!(err.matches("coincide").count(), 1, "repeated: {err}");
}

#[test]
fn oversized_pictures_are_refused_without_internal_names() {
    let d = tempdir();
    put(d.path(), "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    for method in ["painter", "zbuffer"] {
        let e = fails_with(
            d.path(),
            &[
                "render",
                "t.obj",
                "-o",
                "big.png",
                "--size",
                "60000x60000",
                "--method",
                method,
            ],
            "big.png",
            &["60000x60000", "268,435,456"],
        );
        assert!(!e.contains("::") && !e.contains("max_pixels"), "{e}");
    }
}
