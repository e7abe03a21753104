//! Lines, points and labels: OBJ `l` and `p`, scene-file `[[line]]`, `[[points]]` and
//! `[[label]]`, and their errors (with file and line).

mod common;

use common::*;
use glam::DVec3;
use limn_scene::{LabelAnchor, MarkerShape};

#[test]
fn obj_lines_and_points_take_the_current_material_colour() {
    let d = dir();
    write(d.path(), "m.mtl", "newmtl red\nKd 1 0 0\nd 0.5\n");
    let src = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl red\nl 1 2 3\np 1 -1\no other\nl 3/1 1\nvt 0 0\n";
    // `3/1` names texture coordinate 1 before any `vt`: an error, on line 9.
    let p = write(d.path(), "bad_vt.obj", src);
    assert_at(&err(&p), &p, Some(9));
    let src =
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl red\nl 1 2 3\np 1 -1\no other\nl 3 1\n";
    let p = write(d.path(), "t.obj", src);
    let s = ok(&p);
    assert_eq!(s.faces.len(), 0);
    assert_eq!(s.lines.len(), 2);
    assert_eq!(s.lines[0].points.len(), 3);
    assert_eq!(s.lines[0].color, [1.0, 0.0, 0.0, 0.5]);
    assert_eq!(s.lines[0].width, 1.0);
    assert_ne!(s.lines[0].object, s.lines[1].object);
    assert_eq!(s.points.len(), 2);
    assert_eq!(s.points[1].at, DVec3::new(1.0, 1.0, 0.0));
    assert_eq!(s.points[0].shape, MarkerShape::Dot);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
}

#[test]
fn obj_line_errors_name_file_and_line() {
    let d = dir();
    for (name, src, line) in [
        ("one.obj", "v 0 0 0\nv 1 0 0\nl 1\n", 3),
        ("range.obj", "v 0 0 0\nv 1 0 0\nl 1 3\n", 3),
        ("zero.obj", "v 0 0 0\nl 0 1\n", 2),
        ("empty_p.obj", "v 0 0 0\n\np\n", 3),
        ("nan.obj", "v 0 0 0\nv nan 0 0\nl 1 2\n", 2),
        ("slash.obj", "v 0 0 0\nv 1 0 0\nl 1/1/1 2\n", 3),
    ] {
        let p = write(d.path(), name, src);
        assert_at(&err(&p), &p, Some(line));
    }
}

const MESH: &str = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1 2 3\n";

#[test]
fn scene_file_lines_points_and_labels() {
    let d = dir();
    write(d.path(), "m.obj", MESH);
    write(
        d.path(),
        "curve.obj",
        "v 0 0 1\nv 1 0 1\nv 2 0 1\nl 1 2 3\nl 3 1\n",
    );
    let src = r##"
[[mesh]]
path = "m.obj"
translate = [0.0, 0.0, 1.0]

[[line]]
points = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
color = "#ff0000"
width = 2.5
dash = [4.0, 2.0, 1.0]
head = true
name = "arrow"

[[line]]
path = "curve.obj"
opacity = 0.5

[[points]]
positions = [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]
marker = "plus"
size = 7.0

[[label]]
at = [1.0, 0.0, 0.0]
text = "x axis"
anchor = "south-west"
offset = [2.0, -2.0]
size = 9.0
"##;
    let p = write(d.path(), "s.toml", src);
    let s = ok(&p);
    assert_eq!(s.faces.len(), 1);
    assert_eq!(
        s.vertices[0],
        DVec3::new(-1.0, -1.0, 1.0),
        "mesh translated"
    );
    assert_eq!(s.lines.len(), 3);
    let a = &s.lines[0];
    assert_eq!(
        (a.color, a.width, a.dash.clone(), a.head),
        ([1.0, 0.0, 0.0, 1.0], 2.5, vec![4.0, 2.0, 1.0], true)
    );
    assert_eq!(s.objects[a.object as usize].name, "arrow");
    assert_eq!(s.lines[1].points.len(), 3);
    assert_eq!(
        s.lines[2].points,
        vec![DVec3::new(2.0, 0.0, 1.0), DVec3::new(0.0, 0.0, 1.0)]
    );
    assert_eq!(s.lines[1].color[3], 0.5);
    assert_eq!(s.points.len(), 2);
    assert_eq!(
        (s.points[0].shape, s.points[0].size),
        (MarkerShape::Plus, 7.0)
    );
    let l = &s.labels[0];
    assert_eq!(
        (l.anchor, l.offset, l.size),
        (LabelAnchor::SouthWest, [2.0, -2.0], 9.0)
    );
    assert_eq!(l.text, "x axis");
    assert!(s.files.iter().any(|f| f.ends_with("curve.obj")));
}

#[test]
fn scene_file_mark_errors_name_file_and_line() {
    let d = dir();
    write(d.path(), "m.obj", MESH);
    write(d.path(), "faces.obj", MESH);
    for (name, src, line) in [
        ("one.toml", "[[line]]\npoints = [[0.0, 0.0, 0.0]]\n", 2),
        (
            "marker.toml",
            "[[points]]\npositions = [[0.0, 0.0, 0.0]]\nmarker = \"star\"\n",
            3,
        ),
        (
            "size.toml",
            "[[points]]\npositions = [[0.0, 0.0, 0.0]]\nsize = -1.0\n",
            3,
        ),
        (
            "width.toml",
            "[[line]]\npoints = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]\nwidth = 0.0\n",
            3,
        ),
        (
            "dash.toml",
            "[[line]]\npoints = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]\ndash = [0.0]\n",
            3,
        ),
        (
            "nan.toml",
            "[[label]]\nat = [nan, 0.0, 0.0]\ntext = \"a\"\n",
            2,
        ),
        (
            "inf.toml",
            "[[points]]\npositions = [[0.0, 0.0, 0.0],\n [inf, 0.0, 0.0]]\n",
            2,
        ),
        (
            "anchor.toml",
            "[[label]]\nat = [0.0, 0.0, 0.0]\ntext = \"a\"\nanchor = \"up\"\n",
            4,
        ),
        ("both.toml", "[[line]]\nhead = true\n", 1),
        ("faces.toml", "[[line]]\npath = \"faces.obj\"\n", 2),
        (
            "colour.toml",
            "[[line]]\npoints = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]\ncolor = [2.0, 0.0, 0.0]\n",
            3,
        ),
        (
            "unknown.toml",
            "[[label]]\nat = [0.0, 0.0, 0.0]\ntext = \"a\"\nfont = \"x\"\n",
            4,
        ),
    ] {
        let p = write(d.path(), name, src);
        let e = err(&p);
        assert_at(&e, &p, Some(line));
    }
}
