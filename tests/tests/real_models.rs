//! The real-model corpus (`tests/models/`, see its README): public files as other
//! programs wrote them — glTF binary (plain, interleaved, quantized, meshopt, Draco),
//! OBJ with MTL and textures (MeshLab's and trimesh's), PLY (binary, with vertex
//! colours and texture coordinates), binary STL — and, made here from them, the truck
//! far from the origin, the truck a trillion trillion times smaller, and the truck cut
//! into 130,000 faces. Each renders in every format with the command's defaults, with no
//! warning but those its file calls for; `limn check` with its defaults agrees with
//! exact ray casting; the textured ones open in the viewers people use within a time
//! bound and look as limn's own PNG does.

use std::path::{Path, PathBuf};
use std::time::Duration;

use limn::{CheckOptions, Collected, Format, Input, RenderOptions, Request, ViewOptions};
use limn_tests::viewers::{agreement, load_png, rasters};

/// The longest a viewer may take over a textured model (well under a second each on an
/// idle machine; the bound leaves room for a busy one).
const BOUND: Duration = Duration::from_secs(60);

/// A corpus file.
fn model(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("models")
        .join(name)
}

/// A corpus model and what its file calls for.
struct Case {
    path: PathBuf,
    /// A piece of every warning its file calls for (any format); none else may come.
    warns: &'static [&'static str],
    /// Textured: opened in the viewers too.
    textured: bool,
}

fn case(name: &str, warns: &'static [&'static str], textured: bool) -> Case {
    Case {
        path: model(name),
        warns,
        textured,
    }
}

/// Warnings that say what a format cannot draw (EPS has no opacity and no blend modes,
/// TikZ no mesh shading and no images): expected of those formats, not of the file.
const FORMAT_LIMITS: [&str; 3] = [
    "EPS has no opacity",
    "TikZ has no triangle-mesh shading",
    "TikZ draws no texture images",
];

/// Renders `c` in every format into `dir` with the defaults; returns the SVG, PDF and
/// PNG written.
fn renders_in_every_format(c: &Case, dir: &Path) -> [PathBuf; 3] {
    let stem = c
        .path
        .file_name()
        .unwrap()
        .to_string_lossy()
        .replace(' ', "_");
    let mut out = Vec::new();
    for format in [
        Format::Svg,
        Format::Pdf,
        Format::Png,
        Format::Eps,
        Format::Tikz,
    ] {
        let file = dir.join(format!("{stem}.{}", format.name()));
        let req = Request {
            input: Input::File(c.path.clone()),
            output: Some(file.clone()),
            options: RenderOptions {
                format: Some(format),
                ..RenderOptions::default()
            },
        };
        let mut events = Collected::default();
        let r = limn::render(&req, &mut events)
            .unwrap_or_else(|e| panic!("{} as {format:?}: {e}", c.path.display()));
        let size = std::fs::metadata(&file).unwrap().len();
        assert!(size > 100, "{}: {size} bytes", file.display());
        for w in &r.warnings {
            let called_for = c.warns.iter().any(|p| w.contains(p))
                || FORMAT_LIMITS.iter().any(|p| w.contains(p));
            assert!(
                called_for,
                "{} as {format:?}: unexpected warning: {w}",
                c.path.display()
            );
        }
        for p in c.warns {
            assert!(
                r.warnings.iter().any(|w| w.contains(p)),
                "{} as {format:?}: no warning saying {p:?}: {:?}",
                c.path.display(),
                r.warnings
            );
        }
        out.push(file);
    }
    [out[0].clone(), out[1].clone(), out[2].clone()]
}

/// `limn check` with its defaults: painter's picture against exact ray casting.
fn checks(path: &Path) {
    let r = limn::check(
        &Input::File(path.to_path_buf()),
        &CheckOptions {
            view: ViewOptions::default(),
            ..CheckOptions::default()
        },
        &mut Collected::default(),
    )
    .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(r.agrees(), "{}: {:?}", path.display(), r.failures);
}

/// The textured model's SVG and PDF in each installed viewer: within [`BOUND`], and
/// inside what is drawn nearly every pixel as limn's PNG has it.
fn opens_in_the_viewers(svg: &Path, pdf: &Path, png: &Path) {
    let (reference, w, h) = load_png(png);
    for (viewer, raster) in rasters(svg, pdf, BOUND) {
        let (pixels, vw, vh) = load_png(&raster);
        assert_eq!((vw, vh), (w, h), "{viewer}: {}", raster.display());
        let (share, compared) = agreement(&reference, &pixels, w, h, 24.0);
        eprintln!(
            "{}: {viewer}: {:.2} % of {compared} pixels within 24 levels",
            svg.display(),
            100.0 * share
        );
        assert!(compared > 10_000, "{compared} pixels compared");
        assert!(share >= 0.9, "{viewer} on {}: {share}", svg.display());
    }
}

fn corpus() -> Vec<Case> {
    vec![
        case("BoxInterleaved.glb", &[], false),
        case("BoxTextured.glb", &[], true),
        case("BoxTextured-quantized.glb", &[], false),
        case("BoxTextured-meshopt.glb", &[], false),
        case("BoxTextured-draco.glb", &[], false),
        case("CesiumMilkTruck.glb", &[], true),
        case("truck.obj", &[], true),
        case("truck.stl", &[], false),
        case("truck-colours.ply", &[], false),
        // MeshLab's `Tr 1` means opaque to it: drawn opaque, with a warning.
        case("fuze.obj", &["would draw nothing (Tr 1"], true),
        case("fuze.ply", &[], false),
    ]
}

#[test]
fn every_corpus_model_renders_in_every_format_and_checks() {
    let dir = tempfile::tempdir().unwrap();
    for c in corpus() {
        let [svg, pdf, png] = renders_in_every_format(&c, dir.path());
        checks(&c.path);
        if c.textured {
            opens_in_the_viewers(&svg, &pdf, &png);
        }
    }
}

/// The vertex lines of an OBJ file with each position mapped by `f`, every other line
/// as it is (written with every digit of the result).
fn moved_obj(text: &str, f: impl Fn(f64) -> f64) -> String {
    let mut out = String::with_capacity(text.len() * 2);
    for line in text.lines() {
        match line.strip_prefix("v ") {
            Some(rest) => {
                out.push('v');
                for v in rest.split_whitespace() {
                    out.push_str(&format!(" {:e}", f(v.parse::<f64>().unwrap())));
                }
            }
            None => out.push_str(line),
        }
        out.push('\n');
    }
    out
}

#[test]
fn the_truck_far_from_the_origin_and_tiny() {
    // The OBJ with its MTL and texture beside it: moved a billion units along every
    // axis, and scaled by 1e-25 (float32 could not hold either; limn reads f64).
    let dir = tempfile::tempdir().unwrap();
    for f in ["truck.mtl", "truck.png"] {
        std::fs::copy(model(f), dir.path().join(f)).unwrap();
    }
    let text = std::fs::read_to_string(model("truck.obj")).unwrap();
    for (name, moved) in [
        ("far.obj", moved_obj(&text, |v| v + 1e9)),
        ("tiny.obj", moved_obj(&text, |v| v * 1e-25)),
    ] {
        let path = dir.path().join(name);
        std::fs::write(&path, moved).unwrap();
        let c = Case {
            path,
            warns: &[],
            textured: true,
        };
        let [svg, pdf, png] = renders_in_every_format(&c, dir.path());
        checks(&c.path);
        opens_in_the_viewers(&svg, &pdf, &png);
    }
}

#[test]
fn the_truck_in_130_thousand_faces() {
    // Every triangle of the binary STL cut into 36 (six steps along two edges).
    let stl = std::fs::read(model("truck.stl")).unwrap();
    let n = u32::from_le_bytes(stl[80..84].try_into().unwrap()) as usize;
    let corner = |t: usize, k: usize| -> [f32; 3] {
        let at = 84 + 50 * t + 12 + 12 * k;
        [0, 1, 2].map(|i| f32::from_le_bytes(stl[at + 4 * i..at + 4 * i + 4].try_into().unwrap()))
    };
    const STEPS: usize = 6;
    let mut out = vec![0u8; 80];
    let mut tris: Vec<[[f32; 3]; 3]> = Vec::new();
    for t in 0..n {
        let [a, b, c] = [corner(t, 0), corner(t, 1), corner(t, 2)];
        let at = |i: usize, j: usize| -> [f32; 3] {
            let (u, v) = (i as f32 / STEPS as f32, j as f32 / STEPS as f32);
            [0, 1, 2].map(|k| a[k] + u * (b[k] - a[k]) + v * (c[k] - a[k]))
        };
        for i in 0..STEPS {
            for j in 0..STEPS - i {
                tris.push([at(i, j), at(i + 1, j), at(i, j + 1)]);
                if i + j + 1 < STEPS {
                    tris.push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            }
        }
    }
    assert!(tris.len() > 130_000, "{}", tris.len());
    out.extend_from_slice(&(tris.len() as u32).to_le_bytes());
    for t in &tris {
        out.extend_from_slice(&[0u8; 12]);
        for p in t {
            for v in p {
                out.extend_from_slice(&v.to_le_bytes());
            }
        }
        out.extend_from_slice(&[0u8; 2]);
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("truck-130k.stl");
    std::fs::write(&path, out).unwrap();
    let c = Case {
        path,
        warns: &[],
        textured: false,
    };
    renders_in_every_format(&c, dir.path());
    checks(&c.path);
}
