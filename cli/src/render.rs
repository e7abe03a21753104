//! `limn render`: a scene file or mesh to a picture.

use std::process::ExitCode;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use limn_depthsort::{order, order_with_marks, OrderError, OrderOptions, Ordered, VisibleMarks};
use limn_paint::{
    hidden_line_picture, hidden_line_scene, painter_for, picture_with_marks, Format,
    HiddenLineStyle, Outline, Painter, Style, SvgOptions, SvgPainter, TikzOptions, TikzPainter,
};
use limn_scene::{Camera, Effects, Scene};

use crate::args::{Background, FillArg, HiddenArg, MethodArg, RenderArgs, StyleArg};
use crate::losses::losses;
use crate::output::{check_writable, write_atomic};
use crate::progress::Progress;
use crate::raster::raster;
use crate::setup::{camera, explain_order, format_of, load, order_options};
use crate::stats::{write_stats, Drawn, Timing};

/// Runs `limn render`.
pub fn render(a: RenderArgs) -> Result<ExitCode> {
    let t0 = Instant::now();
    let progress = Progress::start(a.view.quiet);
    let loaded = load(&a.input, &a.view)?;
    let cam = camera(&loaded.scene, &a.view, loaded.opts.size, &a.input)?;
    let oo = order_options(&a.view, &loaded.opts)?;
    let output = a.output.clone().unwrap_or_else(|| {
        let ext = a.format.map_or("svg", Format::name);
        a.input.with_extension(ext)
    });
    let format = match (a.format, &loaded.opts.format, &a.output) {
        (None, Some(f), None) => Format::from_name(f)
            .with_context(|| format!("unknown format `{f}` in the scene file"))?,
        _ => format_of(&output, a.format)?,
    };
    let output = if a.output.is_none() {
        a.input.with_extension(format.name())
    } else {
        output
    };
    if a.standalone && format != Format::Tikz {
        bail!("--standalone applies to TikZ output only (the format is {format})");
    }
    check_writable(&output, &loaded.scene.files)?;
    if let Some(stats) = &a.view.stats {
        check_writable(stats, &loaded.scene.files)?;
    }
    if !matches!(a.method, MethodArg::Painter) {
        if format != Format::Png {
            bail!("--method {:?} renders a raster: write a .png", a.method);
        }
        progress.phase("rendering");
        let maps = limn_zbuffer::ShadowMapOptions {
            size: a.shadow_map_size,
            bias: a.shadow_bias,
        };
        let done = raster(&loaded.scene, &cam, a.method, &output, &a.view, &oo, &maps);
        drop(progress);
        return done;
    }
    let t1 = Instant::now();
    progress.phase("ordering");
    let hidden_line = hidden_line_style(&a, &loaded.opts)?;
    let background = match a.background {
        Some(Background::None) => None,
        Some(Background::Colour(c)) => Some([c[0], c[1], c[2], 1.0]),
        None => loaded.opts.background.map(|c| [c[0], c[1], c[2], 1.0]),
    };
    let drawn_scene = hidden_line.as_ref().map(|h| {
        let fill = background.map_or([1.0; 3], |b| [b[0], b[1], b[2]]);
        hidden_line_scene(&loaded.scene, &cam, h, fill)
    });
    let scene = drawn_scene.as_ref().map_or(&loaded.scene, |d| &d.0);
    let (ordered, marks) = order_scene(scene, &cam, &oo).map_err(|e| explain_order(e, &a.input))?;
    let t2 = Instant::now();
    progress.phase("writing");
    let fo = &loaded.opts;
    // SVG draws Phong in two approximations (Phong to Gouraud triangles, those to
    // gradients and flat pieces): each gets half of the tolerance.
    let phong_in_svg = format == Format::Svg && Effects::of(&loaded.scene).phong;
    let tolerance = if phong_in_svg {
        a.shading_tolerance / 2.0
    } else {
        a.shading_tolerance
    };
    let style = Style {
        seamless: true,
        smooth: true,
        tolerance,
        seams: a.seams,
        background,
        outline: (a.outline || fo.outline == Some(true)).then(|| {
            let c = fo.outline_color.unwrap_or([0.1, 0.1, 0.1]);
            Outline {
                color: [c[0], c[1], c[2], 1.0],
                width: fo.outline_width.unwrap_or(1.0),
            }
        }),
    };
    let pic = match (&hidden_line, &drawn_scene) {
        (Some(h), Some((s, first))) => hidden_line_picture(s, &ordered, &marks, *first, h, &style),
        _ => picture_with_marks(scene, &ordered, &marks, &style),
    };
    let painter: Box<dyn Painter> = match format {
        Format::Tikz => Box::new(TikzPainter::new(TikzOptions {
            standalone: a.standalone,
            ..TikzOptions::default()
        })),
        Format::Svg => Box::new(SvgPainter::new(SvgOptions {
            tolerance,
            ..SvgOptions::default()
        })),
        _ => painter_for(format),
    };
    let ps = write_atomic(
        &output,
        &loaded.scene.files,
        |w| Ok(painter.paint(&pic, w)?),
    )?;
    let t3 = Instant::now();
    drop(progress);
    let lost = losses(&loaded.scene, &ordered, &ps, format, cam.near.is_some());
    if !a.view.quiet {
        for w in &lost {
            eprintln!("limn: warning: {w}");
        }
    }
    let warnings: Vec<String> = loaded.scene.warnings.iter().chain(&lost).cloned().collect();
    let timing = Timing {
        load: (t1 - t0).as_secs_f64() * 1e3,
        order: (t2 - t1).as_secs_f64() * 1e3,
        write: (t3 - t2).as_secs_f64() * 1e3,
        total: t0.elapsed().as_secs_f64() * 1e3,
    };
    write_stats(
        &a.view.stats,
        &loaded.scene,
        &ordered,
        &oo,
        &Drawn {
            paint: &ps,
            marks: &marks.stats,
        },
        &timing,
        &warnings,
    )?;
    if !a.view.quiet && output.as_os_str() != "-" {
        eprintln!(
            "limn: wrote {} ({} faces, {} fragments, {} splits, {:.0} ms)",
            output.display(),
            ordered.stats.faces_in,
            ordered.stats.fragments_out,
            ordered.stats.splits,
            timing.total
        );
    }
    // The process ends after this: freeing the scene, the order and the picture one
    // allocation at a time (millions on large scenes) takes longer than the system takes
    // to reclaim the whole process.
    std::mem::forget((loaded, drawn_scene, ordered, marks, pic));
    Ok(ExitCode::SUCCESS)
}

/// Orders `scene` and hides its lines, markers and labels. A scene without any is only
/// ordered: hiding marks makes an occluder of every fragment (a copy of its exact
/// polygon, its planes and screen bins) even when there is nothing to hide.
fn order_scene(
    scene: &Scene,
    cam: &Camera,
    oo: &OrderOptions,
) -> Result<(Ordered, VisibleMarks), OrderError> {
    if scene.lines.is_empty() && scene.points.is_empty() && scene.labels.is_empty() {
        return Ok((order(scene, cam, oo)?, VisibleMarks::default()));
    }
    order_with_marks(scene, cam, oo)
}

/// The hidden-line style the flags and the scene file ask for, or `None` for filled
/// pictures.
fn hidden_line_style(
    a: &RenderArgs,
    fo: &limn_load::SceneOptions,
) -> Result<Option<HiddenLineStyle>> {
    let hidden_line = match a.style {
        Some(s) => s == StyleArg::HiddenLine,
        None => fo.style.as_deref() == Some("hidden-line"),
    };
    if !hidden_line {
        return Ok(None);
    }
    let c = fo.outline_color.unwrap_or([0.0; 3]);
    Ok(Some(HiddenLineStyle {
        color: [c[0], c[1], c[2], 1.0],
        width: fo.outline_width.unwrap_or(1.0),
        dashed: match a.hidden {
            Some(h) => h == HiddenArg::Dashed,
            None => fo.hidden.as_deref() == Some("dashed"),
        },
        fill: match a.fill {
            Some(f) => f == FillArg::Background,
            None => fo.fill.as_deref() != Some("none"),
        },
        crease: a.crease.or(fo.crease).unwrap_or(30.0),
    }))
}
