//! Textures end to end: a textured OBJ in every format (one embedded image in SVG and
//! PDF and EPS, the mean colour with a warning in TikZ, `texture` in `--stats`), and
//! texture errors reported with file and line, leaving no output.

mod common;

use common::{assert_failed_cleanly, limn, put, tempdir};

/// A `w` × `h` checker PNG (red and cream).
fn checker_png(w: u32, h: u32) -> Vec<u8> {
    let mut out = Vec::new();
    let mut e = png::Encoder::new(&mut out, w, h);
    e.set_color(png::ColorType::Rgb);
    e.set_depth(png::BitDepth::Eight);
    let mut wr = e.write_header().unwrap();
    let data: Vec<u8> = (0..h)
        .flat_map(|j| {
            (0..w).flat_map(move |i| {
                if (i + j) % 2 == 0 {
                    [230, 60, 40]
                } else {
                    [250, 240, 200]
                }
            })
        })
        .collect();
    wr.write_image_data(&data).unwrap();
    drop(wr);
    out
}

const QUAD: &str = "mtllib q.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n\
                    vt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\nusemtl tex\nf 1/1 2/2 3/3 4/4\n";

fn effects(stdout: &[u8]) -> Vec<String> {
    let v: serde_json::Value = serde_json::from_slice(stdout).unwrap();
    v["effects"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap().to_string())
        .collect()
}

#[test]
fn a_textured_obj_in_every_format() {
    let d = tempdir();
    put(d.path(), "img/c.png", checker_png(4, 2));
    put(
        d.path(),
        "q.mtl",
        "newmtl tex\nKd 1 1 1\nillum 1\nmap_Kd img/c.png\n",
    );
    put(d.path(), "q.obj", QUAD);
    // SVG and PDF by default from the page image (see `page_image_tiles_in_svg_and_pdf`);
    // here each face under its own maps.
    for ext in ["svg", "pdf", "eps", "png", "tikz"] {
        let out = format!("q.{ext}");
        let run = limn(
            d.path(),
            &[
                "render",
                "q.obj",
                "-o",
                &out,
                "--stats",
                "-",
                "--texture-samples",
                "0",
            ],
        );
        assert_eq!(run.code, 0, "{ext}: {}", run.stderr);
        assert!(
            effects(&run.stdout).contains(&"texture".to_string()),
            "{ext}"
        );
        let bytes = std::fs::read(d.path().join(&out)).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        let flattened = run.stderr.contains("textured fragments");
        match ext {
            "svg" => {
                assert_eq!(text.matches("<image").count(), 1);
                assert!(text.contains("<feColorMatrix"), "lit: the fill filters");
                assert!(!flattened);
            }
            "pdf" => {
                let doc = lopdf::Document::load_mem(&bytes).unwrap();
                let images: Vec<&lopdf::Stream> = doc
                    .objects
                    .values()
                    .filter_map(|o| o.as_stream().ok())
                    .filter(|s| {
                        s.dict.get(b"Subtype").and_then(|v| v.as_name()).ok() == Some(b"Image")
                    })
                    .collect();
                assert_eq!(images.len(), 1, "one image XObject");
                let img = images[0];
                let int = |k: &[u8]| img.dict.get(k).unwrap().as_i64().unwrap();
                // A wrapped border of one texel on each side.
                assert_eq!((int(b"Width"), int(b"Height")), (6, 4));
                let rgb = img.decompressed_content().unwrap();
                assert_eq!(rgb.len(), 6 * 4 * 3);
                // Row 1, column 1 is texel (0, 0): red; column 0 wraps to texel (3, 0).
                assert_eq!(&rgb[3 * 7..3 * 8], &[230, 60, 40]);
                assert_eq!(&rgb[3 * 6..3 * 7], &[250, 240, 200]);
                assert!(!flattened);
            }
            "eps" => {
                // The rows once (a 4 × 2 texture padded to 6 × 4), drawn per piece.
                assert_eq!(text.matches("/td0 [").count(), 1);
                assert_eq!(text.matches("/Width 6 /Height 4").count(), 1);
                assert!(text.contains("] T0\n"));
                assert!(text.contains("%%BoundingBox: 0 0 "));
                assert!(!flattened, "{}", run.stderr);
            }
            "tikz" => {
                assert!(flattened, "{ext}: {}", run.stderr);
                assert!(!text.contains("image"), "{ext}");
            }
            _ => assert!(!flattened),
        }
    }
}

#[test]
fn faces_without_texture_coordinates_read_no_image() {
    let d = tempdir();
    // The image does not exist: no face needs it.
    put(d.path(), "q.mtl", "newmtl tex\nmap_Kd missing.png\n");
    put(
        d.path(),
        "q.obj",
        "mtllib q.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl tex\nf 1 2 3\n",
    );
    for ext in ["svg", "pdf"] {
        let out = format!("q.{ext}");
        let run = limn(d.path(), &["render", "q.obj", "-o", &out, "--stats", "-"]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        assert!(!effects(&run.stdout).contains(&"texture".to_string()));
        let text =
            String::from_utf8_lossy(&std::fs::read(d.path().join(&out)).unwrap()).into_owned();
        assert!(
            !text.contains("<image") && !text.contains("/Image"),
            "{ext}"
        );
    }
}

#[test]
fn texture_errors_name_file_and_line_and_leave_no_output() {
    let d = tempdir();
    put(d.path(), "q.obj", QUAD);
    for (mtl, line, what) in [
        ("newmtl tex\nmap_Kd nothing.png\n", 2, "cannot read"),
        ("newmtl tex\n\nmap_Kd ../c.png\n", 3, "outside the folder"),
        ("newmtl tex\nmap_Kd bad.png\n", 2, "corrupt PNG"),
    ] {
        put(d.path(), "bad.png", &checker_png(4, 4)[..30]);
        put(d.path(), "q.mtl", mtl);
        let run = limn(d.path(), &["render", "q.obj", "-o", "q.svg"]);
        assert_failed_cleanly(&run, 1, d.path(), "q.svg");
        assert!(
            run.stderr.contains(&format!("q.mtl:{line}:")) && run.stderr.contains(what),
            "{}",
            run.stderr
        );
    }
}

/// The image XObjects of a PDF: (width, height) each.
fn pdf_images(bytes: &[u8]) -> Vec<(i64, i64)> {
    let doc = lopdf::Document::load_mem(bytes).unwrap();
    doc.objects
        .values()
        .filter_map(|o| o.as_stream().ok())
        .filter(|s| s.dict.get(b"Subtype").and_then(|v| v.as_name()).ok() == Some(b"Image"))
        .map(|s| {
            let int = |k: &[u8]| s.dict.get(k).unwrap().as_i64().unwrap();
            (int(b"Width"), int(b"Height"))
        })
        .collect()
}

#[test]
fn page_image_tiles_in_svg_and_pdf() {
    let d = tempdir();
    put(d.path(), "img/c.png", checker_png(4, 2));
    put(
        d.path(),
        "q.mtl",
        "newmtl tex\nKd 1 0.5 1\nillum 1\nmap_Kd img/c.png\n",
    );
    put(d.path(), "q.obj", QUAD);
    // 300 × 200 pixels, two samples each way: 600 × 400 samples in tiles of 128 (and the
    // next tile's first column and row), only those the quad reads.
    let size = ["--size", "300x200"];
    let run = limn(
        d.path(),
        &[&["render", "q.obj", "-o", "q.svg"][..], &size].concat(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = std::fs::read_to_string(d.path().join("q.svg")).unwrap();
    let tiles = svg.matches("<image id=\"pg").count();
    assert!((1..=20).contains(&tiles), "{tiles} tiles");
    // No texture of its own, no colour filter, no per-triangle placement: one clip.
    assert!(
        !svg.contains("id=\"tex"),
        "the face's texture is in the page image"
    );
    assert!(!svg.contains("<feColorMatrix"));
    assert_eq!(svg.matches("<clipPath").count(), 1);
    assert_eq!(svg.matches("<use href=\"#pg").count(), tiles);
    let run = limn(
        d.path(),
        &[&["render", "q.obj", "-o", "q.pdf"][..], &size].concat(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let images = pdf_images(&std::fs::read(d.path().join("q.pdf")).unwrap());
    assert_eq!(images.len(), tiles, "{images:?}");
    assert!(
        images.iter().all(|&(w, h)| w <= 129 && h <= 129),
        "{images:?}"
    );
    // Asked for 0 samples: the texture itself, once.
    let run = limn(
        d.path(),
        &[
            &["render", "q.obj", "-o", "q0.pdf", "--texture-samples", "0"][..],
            &size,
        ]
        .concat(),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(
        pdf_images(&std::fs::read(d.path().join("q0.pdf")).unwrap()),
        [(6, 4)]
    );
    // Out of range: refused by name.
    let run = limn(
        d.path(),
        &["render", "q.obj", "-o", "x.svg", "--texture-samples", "17"],
    );
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert!(run.stderr.contains("texture samples"), "{}", run.stderr);
}
