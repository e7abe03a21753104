//! Nothing vanishes silently: whatever is not drawn as given gets a warning on standard
//! error and an entry in `--stats`; `--near`, `--far` and `--background` are flags.

mod common;

use common::{limn, put, tempdir};

/// A ground quad 2·10⁵ wide and a small triangle one unit in front of the eye.
const GROUND_AND_SMALL: &str = "v -1e5 -1 -1e5\nv 1e5 -1 -1e5\nv 1e5 -1 1e5\nv -1e5 -1 1e5\n\
v -0.1 -0.1 0\nv 0.1 -0.1 0\nv 0 0.1 0\nf 1 4 3 2\nf 5 6 7\n";

fn stats(dir: &std::path::Path, name: &str) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join(name)).unwrap()).unwrap()
}

#[test]
fn the_automatic_near_plane_warns_and_near_lifts_it() {
    let dir = tempdir();
    put(dir.path(), "g.obj", GROUND_AND_SMALL);
    let view = ["--eye", "0,0,1", "--target", "0,0,0", "--cull", "off"];
    let mut args = vec!["render", "g.obj", "-o", "a.svg", "--stats", "a.json"];
    args.extend(view);
    let r = limn(dir.path(), &args);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stderr.contains("near plane") && r.stderr.contains("--near"),
        "{}",
        r.stderr
    );
    let s = stats(dir.path(), "a.json");
    assert!(s["faces_near_clipped"].as_u64().unwrap() >= 1, "{s}");
    assert!(!s["warnings"].as_array().unwrap().is_empty());

    let mut args = vec![
        "render", "g.obj", "-o", "b.svg", "--stats", "b.json", "--near", "0.01",
    ];
    args.extend(view);
    let r = limn(dir.path(), &args);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(!r.stderr.contains("near plane"), "{}", r.stderr);
    let s = stats(dir.path(), "b.json");
    assert_eq!(s["faces_near_clipped"], 0, "{s}");
    // The small triangle is drawn now: more paths than before.
    assert!(s["paths_out"].as_u64() > stats(dir.path(), "a.json")["paths_out"].as_u64());
}

#[test]
fn check_says_what_both_sides_clipped() {
    let dir = tempdir();
    put(dir.path(), "g.obj", GROUND_AND_SMALL);
    let r = limn(
        dir.path(),
        &[
            "check", "g.obj", "--eye", "0,0,1", "--target", "0,0,0", "--cull", "off", "--size",
            "64x48",
        ],
    );
    let report: serde_json::Value = serde_json::from_slice(&r.stdout).unwrap();
    assert!(report["faces_near_clipped_by_both"].as_u64().unwrap() >= 1);
    assert!(r.stderr.contains("both cut"), "{}", r.stderr);
}

#[test]
fn degenerate_faces_are_reported() {
    let dir = tempdir();
    put(
        dir.path(),
        "d.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n",
    );
    let r = limn(dir.path(), &["render", "d.obj", "--stats", "s.json"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stderr.contains("zero area"), "{}", r.stderr);
    assert_eq!(stats(dir.path(), "s.json")["faces_degenerate"], 1);
}

#[test]
fn eps_translucency_is_reported() {
    let dir = tempdir();
    put(
        dir.path(),
        "t.obj",
        "mtllib m.mtl\nusemtl glass\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    );
    put(dir.path(), "m.mtl", "newmtl glass\nKd 0 0 1\nd 0.5\n");
    let r = limn(dir.path(), &["render", "t.obj", "-o", "t.eps"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stderr.contains("EPS has no opacity"), "{}", r.stderr);
    let r = limn(dir.path(), &["render", "t.obj", "-o", "t.pdf"]);
    assert!(!r.stderr.contains("warning"), "{}", r.stderr);
}

#[test]
fn texture_maps_are_reported_with_file_and_line() {
    let dir = tempdir();
    put(
        dir.path(),
        "t.obj",
        "mtllib m.mtl\nusemtl wood\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    );
    put(
        dir.path(),
        "m.mtl",
        "newmtl wood\nKd 0.5 0.3 0.1\nmap_Ks wood.png\n",
    );
    let r = limn(dir.path(), &["render", "t.obj"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    // map_Kd is drawn (tests/textures.rs); the other maps are reported.
    assert!(
        r.stderr.contains("m.mtl:3") && r.stderr.contains("map_Ks"),
        "{}",
        r.stderr
    );
}

#[test]
fn ply_vertex_colours_are_drawn_and_only_averaged_alphas_reported() {
    let head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n\
property uchar alpha\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    let dir = tempdir();
    put(
        dir.path(),
        "mixed.ply",
        format!("{head}0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n"),
    );
    put(
        dir.path(),
        "alphas.ply",
        format!("{head}0 0 0 9 9 9 255\n1 0 0 9 9 9 100\n0 1 0 9 9 9 255\n3 0 1 2\n"),
    );
    let r = limn(dir.path(), &["render", "mixed.ply", "--stats", "-"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(!r.stderr.contains("warning"), "{}", r.stderr);
    let stats = String::from_utf8_lossy(&r.stdout);
    assert!(stats.contains("vertex-colors"), "{stats}");
    let r = limn(dir.path(), &["render", "alphas.ply", "--stats", "-"]);
    assert!(r.stderr.contains("different alphas"), "{}", r.stderr);
    let stats = String::from_utf8_lossy(&r.stdout);
    assert!(stats.contains("different alphas"), "{stats}");
}

#[test]
fn an_empty_picture_is_reported() {
    let dir = tempdir();
    // Seen from behind with every back face culled.
    put(dir.path(), "b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let r = limn(
        dir.path(),
        &[
            "render",
            "b.obj",
            "--eye",
            "0.2,0.2,-3",
            "--cull",
            "on",
            "--stats",
            "s.json",
        ],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stderr.contains("picture is empty"), "{}", r.stderr);
    assert_eq!(stats(dir.path(), "s.json")["fragments_out"], 0);
}

#[test]
fn negative_option_values_reach_their_range_check() {
    let dir = tempdir();
    put(dir.path(), "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    for (flag, needle) in [
        ("--seams", "between 0 and 10"),
        ("--near", "positive"),
        ("--fov", "outside (0, 180)"),
    ] {
        let r = limn(dir.path(), &["render", "t.obj", flag, "-1"]);
        assert_eq!(r.code, 2, "{flag}: {}", r.stderr);
        assert!(r.stderr.contains(needle), "{flag}: {}", r.stderr);
    }
}

#[test]
fn background_flag_overrides_the_scene_file() {
    let dir = tempdir();
    put(dir.path(), "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    put(
        dir.path(),
        "s.toml",
        "[output]\nbackground = \"#00ff00\"\n[[mesh]]\npath = \"t.obj\"\n",
    );
    let r = limn(dir.path(), &["render", "s.toml", "-o", "a.svg"]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let a = std::fs::read_to_string(dir.path().join("a.svg")).unwrap();
    assert!(a.contains("#00ff00"));
    let r = limn(
        dir.path(),
        &["render", "s.toml", "-o", "b.svg", "--background", "#ff0000"],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    let b = std::fs::read_to_string(dir.path().join("b.svg")).unwrap();
    assert!(b.contains("#ff0000") && !b.contains("#00ff00"));
    let r = limn(
        dir.path(),
        &["render", "s.toml", "-o", "c.svg", "--background", "none"],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    let c = std::fs::read_to_string(dir.path().join("c.svg")).unwrap();
    assert!(!c.contains("#00ff00"));
    let r = limn(dir.path(), &["render", "t.obj", "--background", "#12345"]);
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("#rrggbb"), "{}", r.stderr);
}

#[test]
fn a_point_cloud_is_drawn_as_points_and_said_so() {
    let dir = tempdir();
    put(dir.path(), "c.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
    let r = limn(
        dir.path(),
        &["render", "c.obj", "-o", "c.svg", "--stats", "s.json"],
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stderr.contains("4 vertices are drawn as points"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("picture is empty"), "{}", r.stderr);
    let s = stats(dir.path(), "s.json");
    assert_eq!(s["lines"]["markers_shown"], 4, "{s}");
    let w = s["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].as_str().unwrap().contains("drawn as points"), "{w:?}");
}
