//! Lines, markers and labels through the command: every format, `--stats`, `limn check`
//! on lines, hidden-line drawings, and bad input (no output file left).

mod common;

use common::{assert_failed_cleanly, limn, put, tempdir, CUBE_OBJ, PNG_MAGIC};

const QUAD_OBJ: &str =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\nv -1 -1 0\nv 1 1 0\nl 5 6\n";

const SCENE: &str = r##"
[camera]
eye = [2.0, 1.5, 5.0]
target = [0.0, 0.0, 0.0]
[output]
size = [300, 240]
[[mesh]]
path = "quad.obj"
material = { kd = "#88aacc", illum = 0 }
[[line]]
points = [[-2.0, 0.5, -1.0], [2.0, 0.5, 1.0]]
color = "#c03020"
head = true
[[points]]
positions = [[0.0, 0.0, -1.0], [0.0, 0.0, 1.0]]
marker = "square"
[[label]]
at = [0.0, 0.0, 1.0]
text = "front"
[[label]]
at = [0.0, 0.0, -1.0]
text = "behind"
"##;

#[test]
fn every_format_draws_lines_markers_and_labels_and_counts_them() {
    let d = tempdir();
    put(d.path(), "quad.obj", QUAD_OBJ);
    put(d.path(), "s.toml", SCENE);
    for ext in ["svg", "pdf", "eps", "png"] {
        let out = format!("s.{ext}");
        let run = limn(
            d.path(),
            &["render", "s.toml", "-o", &out, "--stats", "st.json"],
        );
        assert_eq!(run.code, 0, "{}", run.stderr);
        let bytes = std::fs::read(d.path().join(&out)).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        match ext {
            "svg" => {
                assert!(text.contains(">front</text>"));
                assert!(!text.contains("behind"));
            }
            "pdf" => assert!(text.contains("(front) Tj") && !text.contains("behind")),
            "eps" => assert!(text.contains("(front) show") && !text.contains("behind")),
            _ => assert!(bytes.starts_with(PNG_MAGIC)),
        }
        let st: serde_json::Value =
            serde_json::from_slice(&std::fs::read(d.path().join("st.json")).unwrap()).unwrap();
        let l = &st["lines"];
        assert_eq!(l["lines"], 2, "{st}");
        assert_eq!(l["segments_in"], 2);
        assert_eq!(l["pieces_out"], 3);
        assert_eq!(l["hidden_pieces"], 1);
        assert_eq!(
            (l["markers"].clone(), l["markers_shown"].clone()),
            (2.into(), 1.into())
        );
        assert_eq!(
            (l["labels"].clone(), l["labels_shown"].clone()),
            (2.into(), 1.into())
        );
    }
    let run = limn(d.path(), &["check", "s.toml"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let report: serde_json::Value = serde_json::from_str(&run.stdout_text()).unwrap();
    assert!(
        report["lines"]["pixels"].as_u64().unwrap() > 100,
        "{report}"
    );
}

#[test]
fn hidden_line_drawing_of_a_cube() {
    let d = tempdir();
    put(d.path(), "cube.obj", CUBE_OBJ);
    let args = [
        "render",
        "cube.obj",
        "-o",
        "c.svg",
        "--style",
        "hidden-line",
        "--fill",
        "none",
        "--hidden",
        "dashed",
        "--eye",
        "3,2.5,4",
        "--target",
        "0.5,0.5,0.5",
        "--stats",
        "s.json",
    ];
    let run = limn(d.path(), &args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = std::fs::read_to_string(d.path().join("c.svg")).unwrap();
    assert!(!svg.contains("fill=\"#"), "lines only: {svg}");
    assert_eq!(svg.matches("stroke-dasharray").count(), 3, "{svg}");
    let st: serde_json::Value =
        serde_json::from_slice(&std::fs::read(d.path().join("s.json")).unwrap()).unwrap();
    assert_eq!(st["lines"]["lines"], 12);
}

#[test]
fn bad_lines_fail_cleanly_with_file_and_line() {
    let d = tempdir();
    for (name, src, needle) in [
        ("one.obj", "v 0 0 0\nv 1 0 0\nl 1\n", "one.obj:3:"),
        ("range.obj", "v 0 0 0\nl 1 9\n", "range.obj:2:"),
        (
            "marker.toml",
            "[[points]]\npositions = [[0.0, 0.0, 0.0]]\nmarker = \"star\"\n",
            "marker.toml:3:",
        ),
        (
            "nan.toml",
            "[[line]]\npoints = [[nan, 0.0, 0.0], [1.0, 0.0, 0.0]]\n",
            "nan.toml:2:",
        ),
    ] {
        put(d.path(), name, src);
        let run = limn(d.path(), &["render", name, "-o", "out.svg"]);
        assert_failed_cleanly(&run, 1, d.path(), "out.svg");
        assert!(run.stderr.contains(needle), "{}", run.stderr);
    }
}

/// The README figure renders (its scene file stays valid).
#[test]
fn the_readme_figure_renders() {
    let docs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/lines");
    let d = tempdir();
    for f in ["figure.toml", "surface.obj", "grid.obj"] {
        std::fs::copy(docs.join(f), d.path().join(f)).unwrap();
    }
    let run = limn(
        d.path(),
        &["render", "figure.toml", "-o", "f.svg", "--stats", "s.json"],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let st: serde_json::Value =
        serde_json::from_slice(&std::fs::read(d.path().join("s.json")).unwrap()).unwrap();
    assert_eq!(st["lines"]["labels"], 5);
    assert_eq!(
        st["lines"]["labels_shown"], 4,
        "the label under the surface is hidden"
    );
    assert!(st["lines"]["hidden_pieces"].as_u64().unwrap() > 0);
}
