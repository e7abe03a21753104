//! `limn demo` and `limn check` end to end.

mod common;

use common::{limn, put, stray_temporaries, tempdir, Run, CROSSING_OBJ, CUBE_OBJ, PNG_MAGIC};

fn json(run: &Run) -> serde_json::Value {
    serde_json::from_slice(&run.stdout)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}", run.stdout_text()))
}

#[test]
fn demo_writes_the_named_svg() {
    let d = tempdir();
    let run = limn(d.path(), &["demo", "-o", "x.svg"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = std::fs::read_to_string(d.path().join("x.svg")).unwrap();
    assert!(svg.starts_with("<?xml") || svg.starts_with("<svg"), "{svg}");
    assert!(svg.contains("<svg"));
    assert!(svg.trim_end().ends_with("</svg>"));
    // One group per object, named.
    for name in ["cyclic strips", "box A", "box B", "sphere"] {
        assert!(svg.contains(name), "no `{name}` in the demo");
    }
    assert!(svg.matches("<path").count() > 100);
    assert!(!d.path().join("demo.svg").exists());
}

/// The demo's SVG, byte for byte: a change to the ordering, the kernel or the writers
/// that moves anything in the picture shows here. After an intended change, regenerate
/// with `cargo run --release -- demo -o cli/tests/golden/demo.svg` and say why in the
/// commit.
#[test]
fn demo_svg_is_unchanged() {
    let d = tempdir();
    let run = limn(d.path(), &["demo", "-o", "x.svg"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let got = std::fs::read(d.path().join("x.svg")).unwrap();
    let want = include_bytes!("golden/demo.svg");
    assert!(
        got == want,
        "the demo SVG changed ({} bytes, golden {}); regenerate cli/tests/golden/demo.svg \
         if the change is intended",
        got.len(),
        want.len()
    );
}

#[test]
fn demo_without_output_writes_demo_svg_in_the_current_folder() {
    let d = tempdir();
    let run = limn(d.path(), &["demo"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = std::fs::read_to_string(d.path().join("demo.svg")).unwrap();
    assert!(svg.contains("<svg"));
    assert!(run.stderr.contains("demo.svg"), "{}", run.stderr);
    assert!(stray_temporaries(d.path()).is_empty());
}

#[test]
fn demo_splits_the_cycle_and_reports_stats() {
    let d = tempdir();
    let run = limn(
        d.path(),
        &["demo", "-o", "d.pdf", "--stats", "-", "--quiet"],
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(run.stderr, "");
    let v = json(&run);
    assert_eq!(v["faces_in"], 1 + 3 + 12 + 5120, "{v}");
    assert!(v["effects"].to_string().contains("shadows"), "{v}");
    assert_eq!(v["lines"]["lines"], 1, "{v}");
    assert!(v["splits"].as_u64().unwrap() >= 1, "{v}");
    assert!(std::fs::read(d.path().join("d.pdf"))
        .unwrap()
        .starts_with(b"%PDF"));
}

/// Two interpenetrating triangles and a cube, seen from the front.
fn scene(dir: &std::path::Path) {
    put(dir, "s.obj", format!("{CROSSING_OBJ}{CUBE_OBJ}"));
}

const VIEW: [&str; 6] = [
    "--eye",
    "0.5,0.3,4",
    "--target",
    "0.5,0,0",
    "--size",
    "160x120",
];

fn check(dir: &std::path::Path, extra: &[&str]) -> Run {
    let mut args = vec!["check", "s.obj"];
    args.extend_from_slice(&VIEW);
    args.extend_from_slice(extra);
    limn(dir, &args)
}

#[test]
fn check_agrees_with_every_reference() {
    let d = tempdir();
    scene(d.path());
    for against in ["raycast", "zbuffer", "warnock", "scanline"] {
        let run = check(d.path(), &["--against", against]);
        assert_eq!(run.code, 0, "{against}: {}", run.stderr);
        let v = json(&run);
        assert_eq!(v["pixels"], 160 * 120, "{v}");
        assert!(v["mismatches"].is_u64(), "{v}");
        assert_eq!(v["mismatches_outside_band"], 0, "{against}: {v}");
        assert!(
            v["mismatches"].as_u64() <= v["band_pixels"].as_u64(),
            "{against}: {v}"
        );
    }
}

#[test]
fn check_in_every_exact_ordering() {
    let d = tempdir();
    scene(d.path());
    for sort in ["adaptive", "bsp", "newell"] {
        let run = check(d.path(), &["--sort", sort]);
        assert_eq!(run.code, 0, "{sort}: {}", run.stderr);
        assert_eq!(json(&run)["mismatches_outside_band"], 0, "{sort}");
    }
}

#[test]
fn check_writes_a_diff_png() {
    let d = tempdir();
    scene(d.path());
    let run = check(d.path(), &["--diff", "d.png"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let png = std::fs::read(d.path().join("d.png")).unwrap();
    assert!(png.starts_with(PNG_MAGIC));
    assert_eq!(&png[16..24], &[0, 0, 0, 160, 0, 0, 0, 120]);
}

#[test]
fn check_stats_go_to_the_named_file() {
    let d = tempdir();
    scene(d.path());
    let run = check(d.path(), &["--stats", "c.json"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(run.stdout.is_empty());
    let v: serde_json::Value =
        serde_json::from_slice(&std::fs::read(d.path().join("c.json")).unwrap()).unwrap();
    assert_eq!(v["mismatches_outside_band"], 0, "{v}");
}

#[test]
fn simple_sort_on_interpenetrating_triangles_fails_the_check() {
    let d = tempdir();
    scene(d.path());
    let run = check(d.path(), &["--sort", "simple", "--diff", "bad.png"]);
    assert_eq!(run.code, 3, "{}", run.stderr);
    let v = json(&run);
    let outside = v["mismatches_outside_band"].as_u64().unwrap();
    // One of the two triangles is wrongly on top over about half their overlap.
    assert!(outside > 500, "{v}");
    assert!(!v["per_face"].as_object().unwrap().is_empty(), "{v}");
    assert!(run.stderr.contains("disagree"), "{}", run.stderr);
    // The diff is written even when the check fails.
    assert!(std::fs::read(d.path().join("bad.png"))
        .unwrap()
        .starts_with(PNG_MAGIC));
}

#[test]
fn simple_sort_on_the_cyclic_strips_fails_the_check() {
    // Three strips, each over the next and under the previous.
    let d = tempdir();
    put(
        d.path(),
        "s.obj",
        "\
o strips
v -2 -0.3 0.0
v 2 -0.3 0.2
v 2 0.3 0.2
v -2 0.3 0.0
f 1 2 3 4
v 1.3 -1.6 0.0
v -0.7 1.9 0.2
v -1.2 1.6 0.2
v 0.8 -1.9 0.0
f 5 6 7 8
v -0.7 -1.9 0.0
v 1.2 1.6 0.2
v 0.7 1.9 0.2
v -1.2 -1.6 0.0
f 9 10 11 12
",
    );
    let view = ["--eye", "0,0,6", "--target", "0,0,0", "--size", "200x200"];
    let mut args = vec!["check", "s.obj", "--sort", "adaptive"];
    args.extend_from_slice(&view);
    let run = limn(d.path(), &args);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(json(&run)["splits"].as_u64().unwrap() >= 1);
    args[3] = "simple";
    let run = limn(d.path(), &args);
    assert_eq!(run.code, 3, "{}", run.stderr);
    assert!(json(&run)["mismatches_outside_band"].as_u64().unwrap() > 0);
}

#[test]
fn check_of_bad_input_exits_1() {
    let d = tempdir();
    put(d.path(), "s.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
    let run = limn(d.path(), &["check", "s.obj", "--diff", "d.png"]);
    assert_eq!(run.code, 1, "{}", run.stderr);
    assert!(run.stderr.contains("s.obj:3"), "{}", run.stderr);
    assert!(!d.path().join("d.png").exists());
    assert!(run.stdout.is_empty());
}

#[test]
fn check_usage_errors_exit_2() {
    let d = tempdir();
    scene(d.path());
    for args in [
        &["check", "s.obj", "--against", "painter"][..],
        &["check", "s.obj", "--against", "abuffer"],
        &["check"],
        &["check", "s.obj", "--diff", "-"],
    ] {
        let run = limn(d.path(), args);
        assert_eq!(run.code, 2, "{args:?}: {}", run.stderr);
    }
}

#[test]
fn orthographic_views_check_against_ray_casting() {
    let d = tempdir();
    put(d.path(), "s.obj", CROSSING_OBJ);
    for extra in [&["--ortho"][..], &["--ortho", "3", "--eye", "0.5,2,4"]] {
        let mut args = vec!["check", "s.obj", "--against", "raycast", "--stats", "-"];
        args.extend_from_slice(extra);
        let run = limn(d.path(), &args);
        assert_eq!(run.code, 0, "{extra:?}: {}", run.stderr);
        let j = json(&run);
        assert_eq!(j["mismatches_outside_band"], 0, "{j}");
    }
    // A scene file asks for the same projection.
    put(
        d.path(),
        "o.toml",
        "[camera]\nprojection = \"orthographic\"\nheight = 3\n[[mesh]]\npath = \"s.obj\"\n",
    );
    let run = limn(d.path(), &["check", "o.toml", "--against", "raycast"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    // The orthographic picture differs from the perspective one.
    let a = limn(d.path(), &["render", "s.obj", "-o", "p.svg"]);
    let b = limn(d.path(), &["render", "s.obj", "-o", "q.svg", "--ortho"]);
    assert_eq!((a.code, b.code), (0, 0));
    let (p, q) = (
        std::fs::read(d.path().join("p.svg")).unwrap(),
        std::fs::read(d.path().join("q.svg")).unwrap(),
    );
    assert_ne!(p, q);
}
