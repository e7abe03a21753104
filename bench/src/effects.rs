//! `limn-bench effects`: what each shading effect (and a texture) costs on a
//! 100k-triangle scene, what
//! the effects machinery costs a scene that asks for none (against the flat-only path
//! the painter took before smooth effects existed, replicated here), and SVG bytes
//! against the shading tolerance.

use std::fmt::Write as _;
use std::time::Instant;

use anyhow::Result;
use glam::DVec3;
use limn_depthsort::{order, OrderOptions, Ordered};
use limn_paint::{
    covers, picture, seam_flaps_indexed, EpsPainter, PaintFragment, Painter, PdfPainter, Picture,
    Style, SvgOptions, SvgPainter,
};
use limn_scene::{
    shade_face, shapes, Camera, Fog, FogFalloff, Light, LightKind, Material, Scene, Shading,
};
use limn_zbuffer::{render, Method, RenderOptions};

/// A glossy UV sphere with vertex normals under a point light and ambient light.
fn lit_sphere(rings: u32, segments: u32) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::glossy(
        "glossy",
        [0.7, 0.3, 0.2],
        [0.8, 0.8, 0.8],
        60.0,
    ));
    let o = s.add_object("sphere");
    shapes::uv_sphere(&mut s, DVec3::ZERO, 1.0, rings, segments, m, o).expect("valid sphere");
    // The sphere's own normals at the vertices (centred at the origin, radius 1).
    s.normals = s.vertices.clone();
    for f in &mut s.faces {
        f.normals = Some(f.vertices.clone());
    }
    s.lights = vec![
        Light {
            kind: LightKind::Point(DVec3::new(2.0, 3.0, 4.0)),
            color: [1.0; 3],
            shadows: false,
        },
        Light {
            kind: LightKind::Ambient,
            color: [0.3; 3],
            shadows: false,
        },
    ];
    s
}

/// Gives the sphere spherical texture coordinates (`s` around, `t` from the top) and a
/// 256 × 256 checker of 16 × 16 texels per square as its material's texture.
fn add_texture(s: &mut Scene) {
    let n = 256u32;
    let mut rgba = Vec::with_capacity(4 * (n * n) as usize);
    for j in 0..n {
        for i in 0..n {
            let c = if (i / 16 + j / 16) % 2 == 0 {
                [230, 80, 50]
            } else {
                [245, 235, 200]
            };
            rgba.extend_from_slice(&[c[0], c[1], c[2], 255]);
        }
    }
    let t = limn_scene::Texture::new("checker", n, n, rgba).expect("valid texture");
    s.materials[0].texture = Some(std::sync::Arc::new(t));
    s.texcoords = s
        .vertices
        .iter()
        .map(|p| {
            let around = 0.5 + p.z.atan2(p.x) / std::f64::consts::TAU;
            [around, p.y.clamp(-1.0, 1.0).acos() / std::f64::consts::PI]
        })
        .collect();
    for f in &mut s.faces {
        f.texcoords = Some(f.vertices.clone());
    }
}

/// How one configuration changes the base scene.
type Change = fn(&mut Scene);

/// The effect configurations measured: a name and how the scene is changed.
fn configs() -> Vec<(&'static str, Change)> {
    vec![
        ("unlit (illum 0)", |s| {
            s.materials[0].illum = 0;
        }),
        ("flat lit", |s| s.shading = Some(Shading::Flat)),
        ("gouraud", |s| s.shading = Some(Shading::Gouraud)),
        ("phong", |s| s.shading = Some(Shading::Phong)),
        ("texture, unlit", |s| {
            s.materials[0].illum = 0;
            add_texture(s);
        }),
        ("texture, flat lit", |s| {
            s.shading = Some(Shading::Flat);
            add_texture(s);
        }),
        ("gouraud + fog", |s| {
            s.shading = Some(Shading::Gouraud);
            s.fog = Some(Fog {
                color: [1.0; 3],
                start: 3.0,
                end: 6.0,
                falloff: FogFalloff::Linear,
            });
        }),
    ]
}

/// The median (upper middle) of `v`.
pub(crate) fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The median time of `runs` runs after one run to warm caches and the allocator.
pub(crate) fn time<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let _ = f();
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs {
        let t = Instant::now();
        last = Some(f());
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    (median(times), last.expect("at least one run"))
}

/// The bytes `painter` writes for `pic`.
pub(crate) fn write(painter: &dyn Painter, pic: &Picture) -> usize {
    let mut out = Vec::new();
    painter.paint(pic, &mut out).expect("in-memory writing");
    out.len()
}

/// The painter's flat-only picture as it was built before smooth effects: one flat
/// colour per face, covers, seam flaps. For an unlit scene it gives the same picture
/// as [`picture`]; the benchmark checks that.
pub(crate) fn flat_only_picture(scene: &Scene, ordered: &Ordered, style: &Style) -> Picture {
    let cam = &ordered.camera;
    let mut cache: Vec<Option<[f64; 4]>> = vec![None; scene.faces.len()];
    let cover = covers(scene, ordered);
    let mut fragments = Vec::with_capacity(ordered.fragments.len());
    for (f, cover) in ordered.fragments.iter().zip(&cover) {
        let face = &scene.faces[f.face as usize];
        let fill = *cache[f.face as usize].get_or_insert_with(|| {
            let m = &scene.materials[face.material as usize];
            let c = shade_face(scene, f.face, cam.eye);
            [c[0], c[1], c[2], m.opacity.clamp(0.0, 1.0)]
        });
        let use_cover = fill[3] >= 1.0 && style.seamless && cover.is_some();
        let (points, original_edges) = match cover {
            Some(c) if use_cover => (c.clone(), vec![true; c.len()]),
            _ => (f.points.clone(), f.original_edges.clone()),
        };
        fragments.push(PaintFragment {
            points,
            fill,
            vertex_colors: None,
            face: f.face,
            object: face.object,
            original_edges,
            texture: None,
            flap: false,
        });
    }
    Picture {
        width: cam.width,
        height: cam.height,
        background: style.background,
        objects: scene.objects.iter().map(|o| o.name.clone()).collect(),
        fragments: if style.seams.is_finite() && style.seams > 0.0 {
            seam_flaps_indexed(fragments, style.seams, style.flap_join()).0
        } else {
            fragments
        },
        outline: style.outline,
        seams: 0.0,
        marks: Vec::new(),
        textures: Vec::new(),
    }
}

/// Runs the measurements and returns the Markdown report.
pub fn run(quick: bool, runs: usize) -> Result<String> {
    let (rings, segments) = if quick { (50, 100) } else { (160, 316) };
    let base = lit_sphere(rings, segments);
    let cam = Camera::framing(&base, 800, 600)?;
    let mut out = String::new();
    writeln!(
        out,
        "Scene: glossy UV sphere, {} triangles with vertex normals, point + ambient light, \
         800×600; median of {runs} runs; ordering (shared by all rows) excluded.\n",
        base.faces.len()
    )?;
    let t = Instant::now();
    let ordered = order(&base, &cam, &OrderOptions::default())?;
    writeln!(
        out,
        "Ordering: {:.0} ms, {} fragments.\n",
        t.elapsed().as_secs_f64() * 1e3,
        ordered.fragments.len()
    )?;
    out += "| effects | picture ms | fragments | SVG ms | SVG bytes | PDF ms | PDF bytes | EPS ms | EPS bytes | z-buffer ms | ray cast ms |\n";
    out += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    let svg = SvgPainter::default();
    let pdf = PdfPainter::default();
    let eps = EpsPainter::default();
    let ropts = RenderOptions::default();
    for (name, change) in configs() {
        eprintln!("limn-bench effects: {name}");
        let mut scene = base.clone();
        change(&mut scene);
        let style = Style::default();
        let (pic_ms, pic) = time(runs, || picture(&scene, &ordered, &style));
        let (svg_ms, svg_bytes) = time(runs, || write(&svg, &pic));
        let (pdf_ms, pdf_bytes) = time(runs, || write(&pdf, &pic));
        let (eps_ms, eps_bytes) = time(runs, || write(&eps, &pic));
        let (z_ms, _) = time(runs, || render(&scene, &cam, Method::ZBuffer, &ropts));
        let (r_ms, _) = time(runs.min(3), || {
            render(&scene, &cam, Method::RayCast, &ropts)
        });
        writeln!(
            out,
            "| {name} | {pic_ms:.1} | {} | {svg_ms:.1} | {svg_bytes} | {pdf_ms:.1} | {pdf_bytes} | {eps_ms:.1} | {eps_bytes} | {z_ms:.1} | {r_ms:.0} |",
            pic.fragments.len()
        )?;
    }

    // Effects available but none asked, against the flat-only path, interleaved so
    // that the machine's load falls on both alike.
    let mut unlit = base.clone();
    unlit.materials[0].illum = 0;
    let style = Style::default();
    assert_eq!(
        picture(&unlit, &ordered, &style),
        flat_only_picture(&unlit, &ordered, &style),
        "the two paths must give the same picture"
    );
    let reps = runs.max(5) * 3;
    let (mut full, mut flat) = (Vec::new(), Vec::new());
    for rep in 0..reps {
        // Each path builds, writes and drops its picture inside its own timing; the
        // order alternates so that neither always runs on the other's leftovers.
        let full_path = || {
            let t = Instant::now();
            let p = picture(&unlit, &ordered, &style);
            let _ = write(&svg, &p);
            drop(p);
            t.elapsed().as_secs_f64() * 1e3
        };
        let flat_path = || {
            let t = Instant::now();
            let p = flat_only_picture(&unlit, &ordered, &style);
            let _ = write(&svg, &p);
            drop(p);
            t.elapsed().as_secs_f64() * 1e3
        };
        if rep % 2 == 0 {
            full.push(full_path());
            flat.push(flat_path());
        } else {
            flat.push(flat_path());
            full.push(full_path());
        }
    }
    let (full, flat) = (median(full), median(flat));
    writeln!(
        out,
        "\nUnlit scene, picture + SVG: full path (effects available, none asked) {full:.1} ms, \
         flat-only path {flat:.1} ms: ratio {:.3} ({reps} interleaved runs, medians).\n",
        full / flat
    )?;

    // SVG bytes against the tolerance, on a coarser sphere (larger triangles).
    let small = lit_sphere(24, 48);
    let scam = Camera::framing(&small, 800, 600)?;
    let sordered = order(&small, &scam, &OrderOptions::default())?;
    out += &format!(
        "SVG size against --shading-tolerance (UV sphere of {} triangles, 800×600):\n\n",
        small.faces.len()
    );
    out += "| shading | tolerance | bytes | paths | gradients | PDF bytes |\n|---|---:|---:|---:|---:|---:|\n";
    for shading in [Shading::Gouraud, Shading::Phong] {
        for steps in [0.5, 1.0, 2.0, 4.0, 8.0] {
            let tol = steps / 255.0;
            let mut s = small.clone();
            s.shading = Some(shading);
            // As the command does: Phong in SVG spends half the tolerance on each step.
            let t = if shading == Shading::Phong {
                tol / 2.0
            } else {
                tol
            };
            let style = Style {
                tolerance: t,
                ..Style::default()
            };
            let pic = picture(&s, &sordered, &style);
            let painter = SvgPainter::new(SvgOptions {
                tolerance: t,
                ..SvgOptions::default()
            });
            let mut bytes = Vec::new();
            let stats = painter.paint(&pic, &mut bytes)?;
            let text = String::from_utf8_lossy(&bytes);
            let pdf_style = Style {
                tolerance: tol,
                ..Style::default()
            };
            let pdf_bytes = write(&pdf, &picture(&s, &sordered, &pdf_style));
            writeln!(
                out,
                "| {} | {steps}/255 | {} | {} | {} | {pdf_bytes} |",
                shading.name(),
                bytes.len(),
                stats.paths,
                text.matches("<linearGradient").count()
            )?;
        }
    }
    out += &crate::shadow_costs::run(quick, runs)?;
    Ok(out)
}
