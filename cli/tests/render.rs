//! `limn render` end to end: usage errors, every output format, statistics, the raster
//! methods and quiet runs.

mod common;

use common::{
    assert_failed_cleanly, limn, put, stray_temporaries, tempdir, PNG_MAGIC, TRIANGLE_OBJ,
};

/// A triangle with an unlit material of colour (0.2, 0.4, 0.6) = #336699.
fn coloured(dir: &std::path::Path) {
    put(dir, "c.mtl", "newmtl blue\nillum 0\nKd 0.2 0.4 0.6\n");
    put(
        dir,
        "a.obj",
        format!("mtllib c.mtl\nusemtl blue\n{TRIANGLE_OBJ}"),
    );
}

fn ok(dir: &std::path::Path, args: &[&str]) -> common::Run {
    let run = limn(dir, args);
    assert_eq!(run.code, 0, "limn {args:?}: {}", run.stderr);
    run
}

fn usage_error(args: &[&str]) {
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    let run = limn(d.path(), args);
    assert_failed_cleanly(&run, 2, d.path(), "out.svg");
    assert!(!run.stderr.is_empty());
}

#[test]
fn unknown_flag_is_a_usage_error() {
    usage_error(&["render", "a.obj", "-o", "out.svg", "--frobnicate"]);
}

#[test]
fn zero_size_is_a_usage_error() {
    usage_error(&["render", "a.obj", "-o", "out.svg", "--size", "0x5"]);
}

#[test]
fn malformed_size_is_a_usage_error() {
    usage_error(&["render", "a.obj", "-o", "out.svg", "--size", "800"]);
}

#[test]
fn two_component_eye_is_a_usage_error() {
    usage_error(&["render", "a.obj", "-o", "out.svg", "--eye", "1,2"]);
}

#[test]
fn non_finite_eye_is_a_usage_error() {
    usage_error(&["render", "a.obj", "-o", "out.svg", "--eye=nan,0,1"]);
}

#[test]
fn unknown_sort_is_a_usage_error() {
    usage_error(&["render", "a.obj", "-o", "out.svg", "--sort", "bubble"]);
}

#[test]
fn bad_field_of_view_is_a_usage_error() {
    for fov in ["0", "180", "nan", "-10"] {
        usage_error(&["render", "a.obj", "-o", "out.svg", &format!("--fov={fov}")]);
    }
}

#[test]
fn missing_subcommand_and_input_are_usage_errors() {
    usage_error(&[]);
    usage_error(&["render"]);
    usage_error(&["paint", "a.obj"]);
}

#[test]
fn help_exits_zero() {
    let d = tempdir();
    let run = ok(d.path(), &["render", "--help"]);
    assert!(run.stdout_text().contains("--allow-outside"));
}

#[test]
fn eye_with_leading_minus_after_equals() {
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    ok(
        d.path(),
        &["render", "a.obj", "-o", "out.svg", "--eye=-1,2,3"],
    );
    assert!(d.path().join("out.svg").is_file());
}

#[test]
fn eye_with_leading_minus_as_next_argument() {
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    ok(
        d.path(),
        &["render", "a.obj", "-o", "out.svg", "--eye", "-1,2,3"],
    );
    assert!(d.path().join("out.svg").is_file());
}

#[test]
fn the_eye_changes_the_picture() {
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    ok(
        d.path(),
        &["render", "a.obj", "-o", "a.svg", "--eye=-1,2,3"],
    );
    ok(
        d.path(),
        &["render", "a.obj", "-o", "b.svg", "--eye", "1,2,3"],
    );
    let a = std::fs::read(d.path().join("a.svg")).unwrap();
    let b = std::fs::read(d.path().join("b.svg")).unwrap();
    assert_ne!(a, b);
}

#[test]
fn svg_has_exact_unlit_colour() {
    let d = tempdir();
    coloured(d.path());
    ok(d.path(), &["render", "a.obj", "-o", "out.svg"]);
    let svg = std::fs::read_to_string(d.path().join("out.svg")).unwrap();
    assert!(svg.contains("<svg"), "{svg}");
    assert!(svg.contains("viewBox=\"0 0 800 600\""), "{svg}");
    assert!(svg.contains("#336699"), "{svg}");
    // No stroke by default: seams are closed by flaps under later faces, never by
    // growing a face.
    assert!(!svg.contains("stroke"), "{svg}");
    ok(
        d.path(),
        &["render", "a.obj", "-o", "bare.svg", "--seams", "0"],
    );
    let bare = std::fs::read_to_string(d.path().join("bare.svg")).unwrap();
    assert!(!bare.contains("stroke"), "{bare}");
}

#[test]
fn pdf_header() {
    let d = tempdir();
    coloured(d.path());
    ok(d.path(), &["render", "a.obj", "-o", "out.pdf"]);
    let pdf = std::fs::read(d.path().join("out.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF"));
}

#[test]
fn eps_header() {
    let d = tempdir();
    coloured(d.path());
    ok(d.path(), &["render", "a.obj", "-o", "out.eps"]);
    let eps = std::fs::read(d.path().join("out.eps")).unwrap();
    assert!(eps.starts_with(b"%!PS-Adobe-3.0 EPSF-3.0"));
}

#[test]
fn png_header_and_size() {
    let d = tempdir();
    coloured(d.path());
    ok(
        d.path(),
        &["render", "a.obj", "-o", "out.png", "--size", "64x48"],
    );
    let png = std::fs::read(d.path().join("out.png")).unwrap();
    assert!(png.starts_with(PNG_MAGIC));
    // IHDR: width and height, big-endian, at bytes 16..24.
    assert_eq!(&png[16..20], &64u32.to_be_bytes());
    assert_eq!(&png[20..24], &48u32.to_be_bytes());
}

#[test]
fn format_flag_overrides_the_extension() {
    let d = tempdir();
    coloured(d.path());
    ok(
        d.path(),
        &["render", "a.obj", "-o", "out.svg", "--format", "pdf"],
    );
    let pdf = std::fs::read(d.path().join("out.svg")).unwrap();
    assert!(pdf.starts_with(b"%PDF"));
}

#[test]
fn default_output_follows_the_input_and_format() {
    let d = tempdir();
    coloured(d.path());
    ok(d.path(), &["render", "a.obj", "--format", "eps"]);
    let eps = std::fs::read(d.path().join("a.eps")).unwrap();
    assert!(eps.starts_with(b"%!PS-Adobe-3.0 EPSF-3.0"));
    ok(d.path(), &["render", "a.obj"]);
    assert!(std::fs::read_to_string(d.path().join("a.svg"))
        .unwrap()
        .contains("<svg"));
}

#[test]
fn dash_writes_svg_to_standard_output() {
    let d = tempdir();
    coloured(d.path());
    let run = ok(d.path(), &["render", "a.obj", "-o", "-"]);
    let text = run.stdout_text();
    assert!(text.contains("<svg"), "{text}");
    assert!(text.contains("#336699"), "{text}");
    assert!(text.trim_end().ends_with("</svg>"), "{text}");
    // Nothing was written to a file called `-` or next to it.
    assert!(!d.path().join("-").exists());
    assert!(stray_temporaries(d.path()).is_empty());
}

#[test]
fn dash_with_format_writes_png_to_standard_output() {
    let d = tempdir();
    coloured(d.path());
    let run = ok(
        d.path(),
        &[
            "render", "a.obj", "-o", "-", "--format", "png", "--size", "32x32",
        ],
    );
    assert!(run.stdout.starts_with(PNG_MAGIC));
}

#[test]
fn outline_adds_strokes() {
    let d = tempdir();
    coloured(d.path());
    ok(
        d.path(),
        &["render", "a.obj", "-o", "plain.svg", "--seams", "0"],
    );
    ok(
        d.path(),
        &[
            "render",
            "a.obj",
            "-o",
            "lines.svg",
            "--outline",
            "--seams",
            "0",
        ],
    );
    let plain = std::fs::read_to_string(d.path().join("plain.svg")).unwrap();
    let lines = std::fs::read_to_string(d.path().join("lines.svg")).unwrap();
    assert!(!plain.contains("stroke"), "{plain}");
    assert!(lines.contains("stroke"), "{lines}");
    assert!(lines.contains("#336699"), "{lines}");
}

const STATS_FIELDS: [&str; 9] = [
    "faces_in",
    "faces_culled",
    "fragments_out",
    "splits",
    "paths_out",
    "filter_fallbacks",
    "sort",
    "arith",
    "effects",
];

fn check_stats(v: &serde_json::Value, faces: u64) {
    for f in STATS_FIELDS {
        assert!(v.get(f).is_some(), "no `{f}` in {v}");
    }
    assert_eq!(v["faces_in"], faces, "{v}");
    assert!(v["fragments_out"].as_u64().unwrap() >= 1, "{v}");
    assert!(v["paths_out"].as_u64().unwrap() >= 1, "{v}");
    assert!(v["splits"].is_u64(), "{v}");
    assert!(v["faces_culled"].is_u64(), "{v}");
    assert!(v["filter_fallbacks"].is_u64(), "{v}");
    assert_eq!(v["sort"], "adaptive", "{v}");
    assert_eq!(v["arith"], "exact", "{v}");
    assert!(v["effects"].is_array(), "{v}");
    for t in ["load", "order", "write", "total"] {
        let ms = v["ms"][t].as_f64();
        assert!(ms.is_some_and(|m| m >= 0.0), "ms.{t} in {v}");
    }
    let total = v["ms"]["total"].as_f64().unwrap();
    let parts: f64 = ["load", "order", "write"]
        .iter()
        .map(|t| v["ms"][t].as_f64().unwrap())
        .sum();
    assert!(parts <= total + 1e-6, "{v}");
}

#[test]
fn stats_to_a_file() {
    let d = tempdir();
    coloured(d.path());
    ok(
        d.path(),
        &["render", "a.obj", "-o", "out.svg", "--stats", "s.json"],
    );
    let text = std::fs::read_to_string(d.path().join("s.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    check_stats(&v, 1);
    assert!(d.path().join("out.svg").is_file());
}

#[test]
fn stats_to_standard_output() {
    let d = tempdir();
    coloured(d.path());
    let run = ok(
        d.path(),
        &["render", "a.obj", "-o", "out.svg", "--stats", "-"],
    );
    let v: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    check_stats(&v, 1);
}

#[test]
fn stats_follow_the_flags() {
    let d = tempdir();
    put(d.path(), "a.obj", common::CUBE_OBJ);
    let run = ok(
        d.path(),
        &[
            "render", "a.obj", "-o", "out.svg", "--stats", "-", "--sort", "bsp", "--arith", "float",
        ],
    );
    let v: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    assert_eq!(v["sort"], "bsp", "{v}");
    assert_eq!(v["arith"], "float", "{v}");
    assert_eq!(v["faces_in"], 6, "{v}");
    // A closed opaque cube seen from outside: three faces face away.
    assert_eq!(v["faces_culled"], 3, "{v}");
    let effects: Vec<&str> = v["effects"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap())
        .collect();
    assert!(effects.contains(&"backface-culling"), "{v}");
}

#[test]
fn stats_to_standard_output_with_svg_to_standard_output_is_refused() {
    // Both would be mixed on one stream.
    let d = tempdir();
    coloured(d.path());
    let run = limn(d.path(), &["render", "a.obj", "-o", "-", "--stats", "-"]);
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert!(run.stdout.is_empty());
}

#[test]
fn quiet_success_prints_nothing_on_standard_error() {
    let d = tempdir();
    // A missing MTL would otherwise warn.
    put(
        d.path(),
        "a.obj",
        format!("mtllib missing.mtl\n{TRIANGLE_OBJ}"),
    );
    let loud = ok(d.path(), &["render", "a.obj", "-o", "out.svg"]);
    assert!(!loud.stderr.is_empty());
    let quiet = ok(d.path(), &["render", "a.obj", "-o", "out.svg", "--quiet"]);
    assert_eq!(quiet.stderr, "");
    let quiet = ok(d.path(), &["render", "a.obj", "-o", "out.png", "-q"]);
    assert_eq!(quiet.stderr, "");
    let quiet = ok(
        d.path(),
        &[
            "render", "a.obj", "-o", "z.png", "-q", "--method", "zbuffer",
        ],
    );
    assert_eq!(quiet.stderr, "");
}

#[test]
fn quiet_still_reports_errors() {
    let d = tempdir();
    put(d.path(), "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    let run = limn(d.path(), &["render", "a.obj", "-o", "out.svg", "--quiet"]);
    assert_failed_cleanly(&run, 1, d.path(), "out.svg");
    assert!(run.stderr.contains("a.obj:4"), "{}", run.stderr);
}

#[test]
fn raster_methods_write_pngs() {
    let d = tempdir();
    put(
        d.path(),
        "a.obj",
        format!("{}{}", common::CROSSING_OBJ, common::CUBE_OBJ),
    );
    for m in ["zbuffer", "scanline", "abuffer", "warnock", "raycast"] {
        let out = format!("{m}.png");
        ok(
            d.path(),
            &[
                "render", "a.obj", "-o", &out, "--method", m, "--size", "80x60",
            ],
        );
        let png = std::fs::read(d.path().join(&out)).unwrap();
        assert!(png.starts_with(PNG_MAGIC), "{m}");
        assert_eq!(&png[16..20], &80u32.to_be_bytes(), "{m}");
    }
    // Z-buffer and scan-line z-buffer give the same picture.
    let z = std::fs::read(d.path().join("zbuffer.png")).unwrap();
    let s = std::fs::read(d.path().join("scanline.png")).unwrap();
    assert_eq!(z, s);
}

#[test]
fn raster_method_to_svg_is_an_error_and_leaves_nothing() {
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    let run = limn(
        d.path(),
        &["render", "a.obj", "-o", "x.svg", "--method", "zbuffer"],
    );
    assert_failed_cleanly(&run, 1, d.path(), "x.svg");
    assert!(run.stderr.contains("png"), "{}", run.stderr);
}

#[test]
fn scene_file_settings_are_used_and_flags_win() {
    let d = tempdir();
    coloured(d.path());
    put(
        d.path(),
        "s.toml",
        "[output]\nsize = [320, 200]\nformat = \"pdf\"\n[[mesh]]\npath = \"a.obj\"\n",
    );
    ok(d.path(), &["render", "s.toml"]);
    let pdf = std::fs::read(d.path().join("s.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF"));
    ok(
        d.path(),
        &["render", "s.toml", "-o", "s.svg", "--size", "10x20"],
    );
    let svg = std::fs::read_to_string(d.path().join("s.svg")).unwrap();
    assert!(svg.contains("viewBox=\"0 0 10 20\""), "{svg}");
    ok(d.path(), &["render", "s.toml", "-o", "t.svg"]);
    let svg = std::fs::read_to_string(d.path().join("t.svg")).unwrap();
    assert!(svg.contains("viewBox=\"0 0 320 200\""), "{svg}");
}

#[test]
fn painter_only_flags_with_a_raster_method_are_usage_errors() {
    // Silently ignoring them would leave the caller without the statistics asked for.
    let d = tempdir();
    put(d.path(), "a.obj", TRIANGLE_OBJ);
    for extra in ["--outline", "--stats=s.json"] {
        let run = limn(
            d.path(),
            &[
                "render", "a.obj", "-o", "z.png", "--method", "zbuffer", extra,
            ],
        );
        assert_failed_cleanly(&run, 2, d.path(), "z.png");
        assert!(!d.path().join("s.json").exists());
    }
}
