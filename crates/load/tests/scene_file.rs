//! TOML scene files: meshes placed and overridden, camera, lights, output options.

mod common;

use common::*;
use glam::DVec3;
use limn_load::{load, load_scene_file, LoadError, LoadOptions, SceneOptions};
use limn_scene::LightKind;

const TRI: &str = "o tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

fn scene(d: &std::path::Path, toml: &str) -> std::path::PathBuf {
    write(d, "tri.obj", TRI);
    write(d, "meshes/cube.stl", binary_stl(b"", &cube_triangles()));
    write(d, "s.toml", toml)
}

#[test]
fn full_scene_file() {
    let d = dir();
    let p = scene(
        d.path(),
        r##"
[camera]
eye = [3.0, 2.0, 5.0]
target = [0, 0, 0]
up = [0, 1, 0]
fov = 30
near = 0.5
far = 50

[output]
size = "640x480"
background = "#ff8000"
outline = true
outline_color = [0, 0, 0]
outline_width = 0.75
format = "pdf"
sort = "bsp"
arith = "float"
cull = "off"

[[mesh]]
path = "tri.obj"
name = "moved"
translate = [10, 0, 0]
rotate = [0, 0, 90]
scale = 2
material = { kd = "#0000ff", illum = 0, opacity = 0.5 }

[[mesh]]
path = "meshes/cube.stl"
rotate = { axis = [0, 1, 0], angle = 180 }
scale = [1, 1, -1]

[[light]]
kind = "directional"
direction = [1, 1, 1]
color = [1, 0.5, 0.5]
intensity = 0.5

[[light]]
kind = "point"
position = [0, 5, 0]

[[light]]
kind = "ambient"
color = "#202020"

[[light]]
kind = "headlight"
"##,
    );
    let (s, o) = load_scene_file(&p, &LoadOptions::default()).unwrap();
    s.validate().unwrap();
    assert_eq!(
        o,
        SceneOptions {
            size: Some((640, 480)),
            background: Some([1.0, 128.0 / 255.0, 0.0]),
            outline: Some(true),
            outline_color: Some([0.0; 3]),
            outline_width: Some(0.75),
            format: Some("pdf".into()),
            sort: Some("bsp".into()),
            arith: Some("float".into()),
            cull: Some("off".into()),
            ..SceneOptions::default()
        }
    );
    let cam = s.camera.expect("camera");
    assert_eq!(
        (cam.eye, cam.target, cam.fov_deg),
        (DVec3::new(3.0, 2.0, 5.0), DVec3::ZERO, 30.0)
    );
    assert_eq!(
        (cam.width, cam.height, cam.near, cam.far),
        (640, 480, Some(0.5), Some(50.0))
    );
    assert_eq!(
        s.faces.len(),
        13,
        "1 triangle then 12 cube faces, in file order"
    );
    assert_eq!(s.objects[0].name, "moved");
    assert_eq!(s.objects[1].name, "cube");
    // Scale 2, then 90° about z, then translate: (1,0,0) -> (2,0,0) -> (0,2,0) -> (10,2,0).
    let p1 = s.vertices[s.faces[0].vertices[1] as usize];
    assert!((p1 - DVec3::new(10.0, 2.0, 0.0)).length() < 1e-12, "{p1}");
    let m = &s.materials[s.faces[0].material as usize];
    assert_eq!((m.kd, m.illum, m.opacity), ([0.0, 0.0, 1.0], 0, 0.5));
    // The cube was mirrored (z scale -1) and rotated: it must still be closed and
    // face outwards.
    let mut cube = s.clone();
    cube.faces.remove(0);
    assert!(cube.is_closed());
    let c = DVec3::new(-0.5, 0.5, 0.5);
    for f in 0..cube.faces.len() as u32 {
        let pts = cube.face_points(f);
        let n = limn_scene::polygon_normal(&pts);
        let centre = pts.iter().copied().sum::<DVec3>() / 3.0;
        assert!(n.dot(centre - c) > 0.0, "face {f} faces outwards");
    }
    assert_eq!(s.lights.len(), 4);
    assert_eq!(s.lights[0].kind, LightKind::Directional(DVec3::ONE));
    assert_eq!(s.lights[0].color, [0.5, 0.25, 0.25]);
    assert_eq!(
        s.lights[1].kind,
        LightKind::Point(DVec3::new(0.0, 5.0, 0.0))
    );
    assert_eq!(s.lights[2].kind, LightKind::Ambient);
    assert_eq!(s.lights[3].kind, LightKind::Headlight);
    // load() gives the same scene.
    assert_eq!(load(&p, &LoadOptions::default()).unwrap(), s);
}

#[test]
fn camera_without_eye_frames_the_scene() {
    let d = dir();
    let p = scene(
        d.path(),
        "[camera]\nfov = 60\n[[mesh]]\npath = \"meshes/cube.stl\"\n",
    );
    let s = load(&p, &LoadOptions::default()).unwrap();
    let cam = s.camera.unwrap();
    assert_eq!(cam.target, DVec3::splat(0.5));
    assert_eq!((cam.fov_deg, cam.width, cam.height), (60.0, 800, 600));
    cam.validate().unwrap();
    let p = scene(d.path(), "[[mesh]]\npath = \"tri.obj\"\n");
    assert!(load(&p, &LoadOptions::default()).unwrap().camera.is_none());
}

#[test]
fn unknown_keys_are_errors_with_lines() {
    let d = dir();
    for (src, line) in [
        ("[camera]\neye = [1, 2, 3]\nzoom = 2\n", 3),
        ("[[mesh]]\npath = \"tri.obj\"\n\ncolour = [1, 0, 0]\n", 4),
        ("[output]\nsize = [10, 10]\nsort = \"fastest\"\n", 3),
        ("[[light]]\nkind = \"spot\"\n", 2),
        ("title = \"x\"\n", 1),
        (
            "[[mesh]]\npath = \"tri.obj\"\nmaterial = { kd = [1, 0, 0], shine = 3 }\n",
            3,
        ),
    ] {
        let p = scene(d.path(), src);
        let e = err(&p);
        assert!(matches!(e, LoadError::Syntax { .. }), "{src:?}: {e}");
        assert_at(&e, &p, Some(line));
    }
}

#[test]
fn bad_values_are_errors_with_lines() {
    let d = dir();
    for (src, line) in [
        ("[output]\nsize = \"0x10\"\n", 2),
        ("[output]\nbackground = \"#12345\"\n", 2),
        ("[output]\nbackground = [2, 0, 0]\n", 2),
        ("[[mesh]]\npath = \"tri.obj\"\nscale = 0\n", 3),
        (
            "[[mesh]]\npath = \"tri.obj\"\nrotate = { axis = [0, 0, 0], angle = 5 }\n",
            3,
        ),
        ("[[light]]\nkind = \"point\"\ndirection = [1, 0, 0]\n", 3),
        ("[[light]]\nkind = \"directional\"\n", 1),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[camera]\neye = [0, 0, 0]\ntarget = [0, 0, 0]\n",
            3,
        ),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[camera]\neye = [0, 0, 5]\nfov = 200\n",
            3,
        ),
        ("[[mesh]]\npath = \"tri.obj\"\n[camera]\nheight = 2\n", 3),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[camera]\nprojection = \"orthographic\"\nheight = -1\n",
            3,
        ),
    ] {
        let p = scene(d.path(), src);
        let e = err(&p);
        assert!(
            matches!(e, LoadError::Invalid { .. } | LoadError::Camera { .. }),
            "{src:?}: {e}"
        );
        assert_at(&e, &p, Some(line));
    }
}

#[test]
fn mesh_errors_name_the_scene_line_and_the_mesh() {
    let d = dir();
    write(d.path(), "bad.obj", "v 0 0 0\nf 1 1 1 9\n");
    let p = scene(d.path(), "\n[[mesh]]\npath = \"bad.obj\"\n");
    let e = err(&p);
    assert!(matches!(e, LoadError::InMesh { .. }), "{e}");
    assert_at(&e, &p, Some(3));
    let inner = e.innermost();
    assert!(
        matches!(inner, LoadError::IndexOutOfRange { .. }),
        "{inner}"
    );
    assert_at(inner, &d.path().join("bad.obj"), Some(2));
    assert!(e.to_string().contains("bad.obj:2:"), "{e}");

    let p = scene(d.path(), "[[mesh]]\npath = \"missing.ply\"\n");
    let e = err(&p);
    assert!(matches!(e.innermost(), LoadError::Io { .. }), "{e}");
    assert_at(&e, &p, Some(2));

    let p = scene(d.path(), "[[mesh]]\npath = \"s.toml\"\n");
    let e = err(&p);
    assert!(matches!(e, LoadError::Unsupported { .. }), "{e}");
    assert_at(&e, &p, Some(2));
}

#[test]
fn shading_and_fog() {
    use limn_scene::{Fog, FogFalloff, Shading};
    let d = dir();
    let p = scene(
        d.path(),
        "[output]\nshading = \"phong\"\n[[mesh]]\npath = \"tri.obj\"\n[fog]\ncolor = \"#ffffff\"\nstart = 1\nend = 4\n",
    );
    let s = ok(&p);
    assert_eq!(s.shading, Some(Shading::Phong));
    assert_eq!(
        s.fog,
        Some(Fog {
            color: [1.0; 3],
            start: 1.0,
            end: 4.0,
            falloff: FogFalloff::Linear,
        })
    );
    let p = scene(
        d.path(),
        "[[mesh]]\npath = \"tri.obj\"\n[fog]\nmode = \"exponential\"\ndensity = 0.25\n",
    );
    let s = ok(&p);
    assert_eq!(s.shading, None);
    assert_eq!(
        s.fog.map(|f| f.falloff),
        Some(FogFalloff::Exponential { density: 0.25 })
    );
    for (bad, line) in [
        (
            "[[mesh]]\npath = \"tri.obj\"\n\n[fog]\nstart = 3\nend = 2\n",
            4,
        ),
        ("[[mesh]]\npath = \"tri.obj\"\n[fog]\nstart = 1\n", 3),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[fog]\nmode = \"exponential\"\nend = 3\n",
            3,
        ),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[fog]\nend = 3\ncolor = [2, 0, 0]\n",
            5,
        ),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[output]\nshading = \"smooth\"\n",
            4,
        ),
    ] {
        let p = scene(d.path(), bad);
        assert_at(&err(&p), &p, Some(line));
    }
}

#[test]
fn light_shadows_are_read_and_refused_where_no_shadow_can_be_cast() {
    let d = dir();
    let p = scene(
        d.path(),
        "[[mesh]]\npath = \"tri.obj\"\n[[light]]\nkind = \"point\"\nposition = [0, 2, 3]\nshadows = true\n\
         [[light]]\nkind = \"directional\"\ndirection = [0, 1, 0]\n\
         [[light]]\nkind = \"directional\"\ndirection = [1, 1, 0]\nshadows = false\n",
    );
    let s = ok(&p);
    let flags: Vec<bool> = s.lights.iter().map(|l| l.shadows).collect();
    assert_eq!(flags, [true, false, false]);
    assert_eq!(s.shadow_lights().iter().collect::<Vec<_>>(), [0]);
    for (bad, line) in [
        (
            "[[mesh]]\npath = \"tri.obj\"\n[[light]]\nkind = \"ambient\"\nshadows = true\n",
            5,
        ),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[[light]]\nkind = \"headlight\"\n\nshadows = true\n",
            6,
        ),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[[light]]\nkind = \"point\"\nposition = [0, 2, 3]\nshadows = 1\n",
            6,
        ),
        (
            "[[mesh]]\npath = \"tri.obj\"\n[[light]]\nkind = \"point\"\nposition = [0, 2, 3]\nshadow = true\n",
            6,
        ),
    ] {
        let p = scene(d.path(), bad);
        assert_at(&err(&p), &p, Some(line));
    }
}
