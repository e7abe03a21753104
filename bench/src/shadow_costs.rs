//! The shadows' part of `limn-bench effects`: what shadows cost on a 100k-triangle
//! scene (exact object-space shadows in the vector path, shadow maps in the z-buffer,
//! exact shadow rays in ray casting), what a light that casts none costs (nothing: the
//! same picture through the shadow-aware path and through a flat-only replica, timed
//! interleaved), and the shadow maps' disagreements with exact ray casting at several
//! biases (acne where the bias is too small, detached shadows where it is too large).

use std::fmt::Write as _;
use std::time::Instant;

use anyhow::Result;
use glam::DVec3;
use limn_check::paint;
use limn_depthsort::{order, OrderOptions};
use limn_paint::{picture, Style, SvgPainter};
use limn_scene::{shapes, Camera, Light, LightKind, Material, Scene, Shading};
use limn_zbuffer::{render, Method, RenderOptions, ShadowMapOptions};

use crate::measure::{flat_only_picture, median, time, write};

/// A lit UV sphere of `rings × segments` quads' triangles floating over a ground
/// square, under one directional light (with or without shadows) and ambient light.
pub fn sphere_over_ground(rings: u32, segments: u32, shadows: bool) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("matte", [0.7, 0.5, 0.3]));
    let g = s.add_material(Material::diffuse("ground", [0.85; 3]));
    let o = s.add_object("sphere");
    shapes::uv_sphere(
        &mut s,
        DVec3::new(0.0, 1.3, 0.0),
        1.0,
        rings,
        segments,
        m,
        o,
    )
    .expect("valid sphere");
    let ground = s.add_object("ground");
    let pts: Vec<DVec3> = [[-4.0, 4.0], [4.0, 4.0], [4.0, -4.0], [-4.0, -4.0]]
        .iter()
        .map(|c| DVec3::new(c[0], 0.0, c[1]))
        .collect();
    s.add_polygon(&pts, g, ground).expect("valid ground");
    s.lights = vec![
        Light {
            kind: LightKind::Directional(DVec3::new(1.0, 2.0, 0.6)),
            color: [0.8; 3],
            shadows,
        },
        Light {
            kind: LightKind::Ambient,
            color: [0.3; 3],
            shadows: false,
        },
    ];
    s
}

/// Runs the measurements and returns the Markdown section.
pub fn run(quick: bool, runs: usize) -> Result<String> {
    let (rings, segments) = if quick { (50, 100) } else { (160, 316) };
    let plain = sphere_over_ground(rings, segments, false);
    let lit = sphere_over_ground(rings, segments, true);
    let cam = Camera::new(
        DVec3::new(3.5, 5.0, 6.5),
        DVec3::new(0.0, 0.7, 0.0),
        800,
        600,
    );
    let mut out = String::new();
    writeln!(
        out,
        "\n### Shadows\n\nScene: a UV sphere over a ground square, {} triangles, one \
         directional light (and ambient light), 800×600; medians of {runs} runs (ray \
         casting: of {}).\n",
        plain.faces.len(),
        runs.min(3)
    )?;
    out += "| path | without shadows ms | with shadows ms | ratio | fragments (without → with) | SVG bytes (without → with) |\n";
    out += "|---|---:|---:|---:|---:|---:|\n";
    let oo = OrderOptions::default();
    let style = Style::default();
    let svg = SvgPainter::default();
    let vector = |s: &Scene| {
        let o = order(s, &cam, &oo).expect("orderable");
        let p = picture(s, &o, &style);
        let bytes = write(&svg, &p);
        (o.fragments.len(), o.stats.ms_shadows, bytes)
    };
    eprintln!("limn-bench effects: shadows, vector");
    let (v0, (f0, _, b0)) = time(runs, || vector(&plain));
    let (v1, (f1, split_ms, b1)) = time(runs, || vector(&lit));
    writeln!(
        out,
        "| vector (order + picture + SVG) | {v0:.0} | {v1:.0} | {:.2} | {f0} → {f1} | {b0} → {b1} |",
        v1 / v0
    )?;
    let ropts = RenderOptions::default();
    eprintln!("limn-bench effects: shadows, z-buffer");
    let (z0, _) = time(runs, || render(&plain, &cam, Method::ZBuffer, &ropts));
    let (z1, _) = time(runs, || render(&lit, &cam, Method::ZBuffer, &ropts));
    writeln!(
        out,
        "| z-buffer + 2048² shadow map | {z0:.0} | {z1:.0} | {:.2} | | |",
        z1 / z0
    )?;
    eprintln!("limn-bench effects: shadows, ray casting");
    let (r0, _) = time(runs.min(3), || {
        render(&plain, &cam, Method::RayCast, &ropts)
    });
    let (r1, _) = time(runs.min(3), || render(&lit, &cam, Method::RayCast, &ropts));
    writeln!(
        out,
        "| ray casting + exact shadow rays | {r0:.0} | {r1:.0} | {:.2} | | |",
        r1 / r0
    )?;
    writeln!(
        out,
        "\nOf the vector path with shadows, splitting along the shadows took {split_ms:.0} ms \
         (the last run).\n"
    )?;

    // A light that casts no shadows costs nothing: the shadow-aware picture path against
    // the flat-only replica, on the same ordered fragments, interleaved.
    let mut flat = plain.clone();
    flat.shading = Some(Shading::Flat);
    let ordered = order(&flat, &cam, &oo)?;
    assert_eq!(
        picture(&flat, &ordered, &style),
        flat_only_picture(&flat, &ordered, &style),
        "the two paths must give the same picture"
    );
    let reps = runs.max(5) * 3;
    let (mut aware, mut replica) = (Vec::new(), Vec::new());
    for rep in 0..reps {
        let a = || {
            let t = Instant::now();
            let p = picture(&flat, &ordered, &style);
            let _ = write(&svg, &p);
            t.elapsed().as_secs_f64() * 1e3
        };
        let b = || {
            let t = Instant::now();
            let p = flat_only_picture(&flat, &ordered, &style);
            let _ = write(&svg, &p);
            t.elapsed().as_secs_f64() * 1e3
        };
        if rep % 2 == 0 {
            aware.push(a());
            replica.push(b());
        } else {
            replica.push(b());
            aware.push(a());
        }
    }
    let (a, b) = (median(aware), median(replica));
    writeln!(
        out,
        "Lit flat scene, a light with `shadows = false`, picture + SVG: shadow-aware path \
         {a:.1} ms, flat-only path {b:.1} ms: ratio {:.3} ({reps} interleaved runs, \
         medians; the orderings take the unchanged path when no light casts shadows).\n",
        a / b
    )?;

    // The shadow maps against exact ray casting, per pixel, at several biases.
    let small = sphere_over_ground(24, 48, true);
    let painted = paint(&small, &cam, &oo)?;
    let exact = painted.reference_shadows(&small, Method::RayCast, &ShadowMapOptions::default())?;
    let on_faces = exact.ids.iter().filter(|&&i| i != u32::MAX).count();
    let vector_vs_exact = painted.compare_shadows(&exact);
    writeln!(
        out,
        "Shadow maps against exact ray casting (sphere of {} triangles over the ground, \
         800×600, {on_faces} pixels on faces): pixels whose point a map puts in shadow \
         and rays do not (acne, or shadows spread), and the reverse (light leaking, \
         shadows detached: peter-panning). The vector shadows differ from the rays at \
         {} pixels, all {} of them inside the edge band.\n",
        small.faces.len(),
        vector_vs_exact.mismatches,
        vector_vs_exact.mismatches - vector_vs_exact.mismatches_outside_band,
    )?;
    out += "| map size | bias (× diagonal) | shadowed by map only | lit by map only | differing |\n|---:|---:|---:|---:|---:|\n";
    let sizes: &[u32] = if quick {
        &[1024, 2048]
    } else {
        &[1024, 2048, 4096]
    };
    for &size in sizes {
        for bias in [0.0, 1e-4, 1e-3, 1e-2, 3e-2] {
            let maps = ShadowMapOptions { size, bias };
            let m = painted.reference_shadows(&small, Method::ZBuffer, &maps)?;
            let (mut extra, mut missing) = (0, 0);
            for (a, b) in m.ids.iter().zip(&exact.ids) {
                if a == b || *a == u32::MAX || *b == u32::MAX {
                    continue;
                }
                if a & !b != 0 {
                    extra += 1;
                } else {
                    missing += 1;
                }
            }
            writeln!(
                out,
                "| {size} | {bias} | {extra} | {missing} | {:.2} % |",
                100.0 * (extra + missing) as f64 / on_faces as f64
            )?;
        }
    }
    Ok(out)
}
