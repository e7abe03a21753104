//! TikZ output from the command: its structure always, and a LaTeX run when `pdflatex`
//! is installed (the PDF page must be the picture's size).

mod common;

use std::collections::HashSet;
use std::process::Command;

use common::{limn, put, stray_temporaries, tempdir};

/// A tetrahedron with one translucent face.
const TETRA: &str = "mtllib t.mtl\no tetra\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
usemtl a\nf 1 3 2\nf 1 2 4\nusemtl b\nf 1 4 3\nf 2 3 4\n";
const MTL: &str = "newmtl a\nKd 0.8 0.2 0.1\nillum 0\nnewmtl b\nKd 0.1 0.3 0.9\nd 0.5\nillum 0\n";

/// The tetrahedron with a dashed polyline through it ending in an arrow, scatter points
/// and a label whose text holds LaTeX's special characters.
const SCENE: &str = r##"[[mesh]]
path = "t.obj"

[[line]]
points = [[-0.5, 0.2, 0.2], [0.3, 0.3, 0.3], [1.2, 0.4, 0.4]]
color = [0.9, 0.1, 0.1]
width = 1.5
dash = [4.0, 2.0]
head = true

[[points]]
positions = [[0.0, 0.0, 1.2], [0.2, 0.2, -0.5], [1.0, 1.0, 1.0]]
marker = "circle"
size = 6.0

[[label]]
at = [1.0, 0.0, 0.0]
text = "50% of x_1 & {y} #2 ~ ^"
anchor = "south-west"
offset = [2.0, -2.0]
size = 9.0
"##;

/// A temporary folder holding the tetrahedron `t.obj` and its `t.mtl`.
fn tetra_folder() -> tempfile::TempDir {
    let dir = tempdir();
    put(dir.path(), "t.obj", TETRA);
    put(dir.path(), "t.mtl", MTL);
    dir
}

/// Checks the structure every TikZ file from limn has: one picture, colours defined
/// before use, every drawing command ended, brackets balanced.
fn check_structure(text: &str) {
    assert_eq!(text.matches("\\begin{tikzpicture}").count(), 1, "{text}");
    assert!(text.ends_with("\\end{tikzpicture}\n") || text.ends_with("\\end{document}\n"));
    let mut defined = HashSet::new();
    for line in text.lines().filter(|l| !l.starts_with('%')) {
        if let Some(rest) = line.strip_prefix("\\definecolor{") {
            let name = rest.split('}').next().unwrap();
            assert!(defined.insert(name.to_string()), "{name} defined twice");
            continue;
        }
        for cmd in ["\\fill[", "\\filldraw[", "\\draw[", "\\node["] {
            if let Some(rest) = line.strip_prefix(cmd) {
                let options = &rest[..rest.find(']').unwrap()];
                // The colour is the first option, or a node's `text=`.
                let colour = options
                    .split(',')
                    .find_map(|o| o.strip_prefix("text="))
                    .unwrap_or_else(|| options.split(',').next().unwrap());
                assert!(
                    defined.contains(colour),
                    "{colour} used before it is defined"
                );
                assert!(line.ends_with(';'), "unended: {line}");
            }
        }
        let open = line.matches(['(', '[', '{']).count();
        let close = line.matches([')', ']', '}']).count();
        assert_eq!(open, close, "unbalanced: {line}");
    }
}

#[test]
fn tikz_by_extension_flag_and_standalone() {
    let dir = tetra_folder();
    let run = limn(
        dir.path(),
        &["render", "t.obj", "-o", "t.pgf", "--outline", "-q"],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let text = std::fs::read_to_string(dir.path().join("t.pgf")).unwrap();
    check_structure(&text);
    assert!(text.starts_with("% limn picture, 800 x 600 px"));
    assert!(text.contains("\\definecolor{limn0}{RGB}{"));
    assert!(text.contains("fill opacity=0.5"), "the translucent face");
    assert!(text.contains("\\draw["), "outlines");
    assert!(text.contains("% object: tetra\n"));

    let run = limn(
        dir.path(),
        &[
            "render",
            "t.obj",
            "-o",
            "t.tex",
            "--format",
            "tikz",
            "--standalone",
            "-q",
        ],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let doc = std::fs::read_to_string(dir.path().join("t.tex")).unwrap();
    check_structure(&doc);
    assert!(doc.starts_with("\\documentclass[tikz]{standalone}\n\\begin{document}\n"));
}

#[test]
fn lines_points_and_labels_are_tikz_commands() {
    let dir = tetra_folder();
    put(dir.path(), "s.toml", SCENE);
    let run = limn(dir.path(), &["render", "s.toml", "-o", "s.tikz", "-q"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let text = std::fs::read_to_string(dir.path().join("s.tikz")).unwrap();
    check_structure(&text);
    assert!(
        text.contains("line cap=butt,dash pattern=on 4bp off 2bp"),
        "{text}"
    );
    assert!(text.contains(" circle[radius=3];"), "{text}");
    assert!(
        text.contains("{50\\% of x\\_1 \\& \\{y\\} \\#2 \\textasciitilde{} \\textasciicircum{}};"),
        "{text}"
    );
}

#[test]
fn standalone_without_tikz_is_refused_without_output() {
    let dir = tetra_folder();
    let run = limn(
        dir.path(),
        &["render", "t.obj", "-o", "t.svg", "--standalone"],
    );
    assert_eq!(run.code, 1);
    assert!(
        run.stderr.contains("--standalone applies to TikZ"),
        "{}",
        run.stderr
    );
    assert!(!dir.path().join("t.svg").exists());
    assert!(stray_temporaries(dir.path()).is_empty());
}

#[test]
fn pages_beyond_tex_lengths_are_refused_without_output() {
    let dir = tetra_folder();
    let run = limn(
        dir.path(),
        &["render", "t.obj", "-o", "t.tikz", "--size", "6000x100"],
    );
    assert_eq!(run.code, 1);
    assert!(run.stderr.contains("5000 px"), "{}", run.stderr);
    assert!(!dir.path().join("t.tikz").exists());
    assert!(stray_temporaries(dir.path()).is_empty());
}

/// With a LaTeX engine installed, the standalone demo compiles and its page is the
/// picture's size; without one, only the structure above is checked.
#[test]
fn standalone_tikz_compiles_with_pdflatex() {
    let found = Command::new("pdflatex")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        eprintln!("pdflatex is not installed: the TikZ output is checked for structure only");
        return;
    }
    let dir = tetra_folder();
    let run = limn(
        dir.path(),
        &[
            "render",
            "t.obj",
            "-o",
            "t.tex",
            "--format",
            "tikz",
            "--standalone",
            "--size",
            "400x300",
            "--outline",
            "-q",
        ],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let out = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "t.tex"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "pdflatex failed:\n{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let pdf = lopdf::Document::load(dir.path().join("t.pdf")).unwrap();
    let (_, page) = pdf.get_pages().into_iter().next().unwrap();
    let page = pdf.get_dictionary(page).unwrap();
    let media: Vec<f64> = page
        .get(b"MediaBox")
        .unwrap()
        .as_array()
        .unwrap()
        .iter()
        .map(|v| {
            v.as_float()
                .map(f64::from)
                .or_else(|_| v.as_i64().map(|i| i as f64))
                .unwrap()
        })
        .collect();
    // TeX rounds lengths to 2^-16 pt and converts pt to bp: within a hundredth.
    assert!((media[2] - media[0] - 400.0).abs() < 0.05, "{media:?}");
    assert!((media[3] - media[1] - 300.0).abs() < 0.05, "{media:?}");
}
