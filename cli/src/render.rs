//! The subcommands.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use glam::DVec3;
use limn_depthsort::paint::{painter_for, Format, Outline};
use limn_depthsort::{order, picture, Arith, CullMode, OrderOptions, Ordered, SortMode, Style};
use limn_scene::load::{load_scene_file, LoadError, LoadOptions, SceneOptions};
use limn_scene::{Camera, Effects, Scene};
use serde_json::json;

use crate::args::{
    ArithArg, Cli, Command, CullArg, DemoArgs, FormatArg, RenderArgs, SortArg, ViewArgs,
};
use crate::output::write_atomic;
use crate::progress::Progress;

/// Runs one command and returns the exit status.
pub fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        Command::Render(a) => render(a),
        Command::Demo(a) => demo(a),
        Command::Check(a) => crate::check::check(a),
    }
}

/// A loaded scene with the options its file gave (all unset for mesh files).
pub struct Loaded {
    /// The scene.
    pub scene: Scene,
    /// Options of a TOML scene file.
    pub opts: SceneOptions,
}

/// Loads INPUT and reports its warnings.
pub fn load(path: &Path, view: &ViewArgs) -> Result<Loaded> {
    let opts = LoadOptions {
        allow_outside: view.allow_outside,
    };
    let is_toml = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"));
    let loaded = if is_toml {
        let (scene, opts) = load_scene_file(path, &opts).map_err(explain)?;
        Loaded { scene, opts }
    } else {
        let scene = limn_scene::load::load(path, &opts).map_err(explain)?;
        Loaded {
            scene,
            opts: SceneOptions::default(),
        }
    };
    if !view.quiet {
        for w in &loaded.scene.warnings {
            eprintln!("limn: warning: {w}");
        }
    }
    if loaded.scene.faces.is_empty() {
        bail!("{}: the scene has no faces", path.display());
    }
    Ok(loaded)
}

/// A loading error, with the flag that lifts a refusal to follow a reference.
fn explain(e: LoadError) -> anyhow::Error {
    if matches!(e.innermost(), LoadError::OutsideFolder { .. }) {
        let text = format!("{e} (with --allow-outside)");
        anyhow::Error::new(e).context(text)
    } else {
        anyhow::Error::new(e)
    }
}

/// The camera: flags first, then the scene file's camera, then framing the scene.
///
/// With `--eye` and no camera in the scene file the camera looks at `--target` or the
/// centre of the scene's bounds; nothing is framed, so a scene too large to frame can
/// still be drawn from a chosen eye. Without `--eye` the framed camera keeps its
/// direction when `--target` moves it. Errors name `input`.
pub fn camera(
    scene: &Scene,
    view: &ViewArgs,
    size: Option<(u32, u32)>,
    input: &Path,
) -> Result<Camera> {
    let (w, h) = view.size.or(size).unwrap_or((800, 600));
    let at = || format!("{}", input.display());
    let mut cam = match (scene.camera, view.eye) {
        (Some(c), _) => c,
        (None, Some(eye)) => {
            let (lo, hi) = scene
                .bounds()
                .with_context(|| format!("{}: empty scene", at()))?;
            let target = view.target.map_or(lo * 0.5 + hi * 0.5, DVec3::from);
            Camera::new(DVec3::from(eye), target, w, h)
        }
        (None, None) => {
            let frame_error = || format!("{}: cannot frame the scene (try --eye)", at());
            let mut c = Camera::framing(scene, w, h).with_context(frame_error)?;
            if let (Some(fov), Some((lo, hi))) = (view.fov, scene.bounds()) {
                // Re-frame for the new field of view, from the same direction.
                let dir = c.eye - c.target;
                c = Camera::framing_bounds(lo, hi, dir, fov, w, h).with_context(frame_error)?;
            }
            if let Some(t) = view.target {
                let t = DVec3::from(t);
                c.eye = t + (c.eye - c.target);
                c.target = t;
            }
            c
        }
    };
    cam.width = w;
    cam.height = h;
    if let Some(fov) = view.fov {
        cam.fov_deg = fov;
    }
    if let Some(e) = view.eye {
        cam.eye = DVec3::from(e);
    }
    if let Some(t) = view.target {
        cam.target = DVec3::from(t);
    }
    if let Some(u) = view.up {
        cam.up = DVec3::from(u);
    }
    cam.validate()
        .with_context(|| format!("{}: invalid camera", at()))?;
    Ok(cam)
}

/// The ordering options: flags first, then the scene file's, then the defaults.
pub fn order_options(view: &ViewArgs, file: &SceneOptions) -> Result<OrderOptions> {
    let sort = match view.sort {
        Some(SortArg::Adaptive) => SortMode::Adaptive,
        Some(SortArg::Bsp) => SortMode::Bsp,
        Some(SortArg::Newell) => SortMode::Newell,
        Some(SortArg::Simple) => SortMode::Simple,
        None => match &file.sort {
            Some(s) => SortMode::from_name(s)
                .with_context(|| format!("unknown sort `{s}` in the scene file"))?,
            None => SortMode::Adaptive,
        },
    };
    let arith = match view.arith {
        Some(ArithArg::Exact) => Arith::Exact,
        Some(ArithArg::Float) => Arith::Float,
        None => match &file.arith {
            Some(s) => Arith::from_name(s)
                .with_context(|| format!("unknown arith `{s}` in the scene file"))?,
            None => Arith::Exact,
        },
    };
    let cull = match view.cull {
        Some(CullArg::Auto) => CullMode::Auto,
        Some(CullArg::On) => CullMode::On,
        Some(CullArg::Off) => CullMode::Off,
        None => match &file.cull {
            Some(s) => CullMode::from_name(s)
                .with_context(|| format!("unknown cull `{s}` in the scene file"))?,
            None => CullMode::Auto,
        },
    };
    Ok(OrderOptions {
        sort,
        arith,
        cull,
        ..OrderOptions::default()
    })
}

fn format_of(output: &Path, flag: Option<FormatArg>) -> Result<Format> {
    if let Some(f) = flag {
        return Ok(match f {
            FormatArg::Svg => Format::Svg,
            FormatArg::Pdf => Format::Pdf,
            FormatArg::Eps => Format::Eps,
            FormatArg::Png => Format::Png,
        });
    }
    if output.as_os_str() == "-" {
        return Ok(Format::Svg);
    }
    match output.extension().and_then(|e| e.to_str()) {
        Some(ext) => Format::from_extension(ext).with_context(|| {
            format!(
                "{}: unknown output extension `.{ext}` (use .svg, .pdf, .eps, .png or --format)",
                output.display()
            )
        }),
        None => Ok(Format::Svg),
    }
}

struct Timing {
    load: f64,
    order: f64,
    write: f64,
    total: f64,
}

fn write_stats(
    path: &Option<PathBuf>,
    scene: &Scene,
    ordered: &Ordered,
    oo: &OrderOptions,
    paths_out: usize,
    bytes: u64,
    t: &Timing,
) -> Result<()> {
    let Some(path) = path else { return Ok(()) };
    let s = &ordered.stats;
    let effects = Effects::of(scene);
    let mut effect_names: Vec<&str> = effects.names();
    if s.faces_culled > 0 {
        effect_names.push("backface-culling");
    }
    let v = json!({
        "faces_in": s.faces_in,
        "faces_culled": s.faces_culled,
        "faces_degenerate": s.faces_degenerate,
        "faces_clipped": s.faces_clipped,
        "polygons": s.polygons,
        "candidate_pairs": s.candidate_pairs,
        "constraints": s.constraints,
        "components": s.components,
        "largest_component": s.largest_component,
        "splits": s.splits,
        "fragments_before_merge": s.fragments_before_merge,
        "fragments_out": s.fragments_out,
        "paths_out": paths_out,
        "bytes_out": bytes,
        "filter_fallbacks": s.filter_fallbacks,
        "sort": oo.sort.name(),
        "arith": oo.arith.name(),
        "effects": effect_names,
        "ms": {
            "load": t.load,
            "order": t.order,
            "write": t.write,
            "total": t.total,
            "prepare": s.ms_prepare,
            "sort": s.ms_order,
            "merge": s.ms_merge,
        },
    });
    let text = serde_json::to_string_pretty(&v)? + "\n";
    write_atomic(path, |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })
}

fn render(a: RenderArgs) -> Result<ExitCode> {
    let t0 = Instant::now();
    let progress = Progress::start(a.view.quiet);
    let loaded = load(&a.input, &a.view)?;
    let cam = camera(&loaded.scene, &a.view, loaded.opts.size, &a.input)?;
    let oo = order_options(&a.view, &loaded.opts)?;
    let output = a.output.clone().unwrap_or_else(|| {
        let ext = a.format.map_or("svg", |f| match f {
            FormatArg::Svg => "svg",
            FormatArg::Pdf => "pdf",
            FormatArg::Eps => "eps",
            FormatArg::Png => "png",
        });
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
    if !matches!(a.method, crate::args::MethodArg::Painter) {
        if format != Format::Png {
            bail!("--method {:?} renders a raster: write a .png", a.method);
        }
        drop(progress);
        return crate::check::raster(&loaded.scene, &cam, a.method, &output, &a.view, &oo);
    }
    let t1 = Instant::now();
    progress.phase("ordering");
    let ordered =
        order(&loaded.scene, &cam, &oo).with_context(|| format!("{}", a.input.display()))?;
    let t2 = Instant::now();
    progress.phase("writing");
    let fo = &loaded.opts;
    let style = Style {
        seamless: true,
        smooth: true,
        seams: a.seams,
        background: fo.background.map(|c| [c[0], c[1], c[2], 1.0]),
        outline: (a.outline || fo.outline == Some(true)).then(|| {
            let c = fo.outline_color.unwrap_or([0.1, 0.1, 0.1]);
            Outline {
                color: [c[0], c[1], c[2], 1.0],
                width: fo.outline_width.unwrap_or(1.0),
            }
        }),
    };
    let pic = picture(&loaded.scene, &ordered, &style);
    let painter = painter_for(format);
    let ps = write_atomic(&output, |w| Ok(painter.paint(&pic, w)?))?;
    let t3 = Instant::now();
    drop(progress);
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
        ps.paths,
        ps.bytes,
        &timing,
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
    Ok(ExitCode::SUCCESS)
}

fn demo(a: DemoArgs) -> Result<ExitCode> {
    let t0 = Instant::now();
    let scene = crate::demo::scene()?;
    let output = a
        .output
        .clone()
        .unwrap_or_else(|| PathBuf::from("demo.svg"));
    let format = format_of(&output, None)?;
    let mut cam = Camera::framing(&scene, 960, 540)?;
    cam.eye = cam.target + (cam.eye - cam.target) * 0.8;
    let t1 = Instant::now();
    let oo = OrderOptions::default();
    let ordered = order(&scene, &cam, &oo)?;
    let t2 = Instant::now();
    let style = Style {
        seamless: true,
        smooth: true,
        seams: Style::default().seams,
        background: Some([1.0, 1.0, 1.0, 1.0]),
        outline: a.outline.then_some(Outline {
            color: [0.1, 0.1, 0.1, 1.0],
            width: 1.0,
        }),
    };
    let pic = picture(&scene, &ordered, &style);
    let ps = write_atomic(&output, |w| Ok(painter_for(format).paint(&pic, w)?))?;
    let t3 = Instant::now();
    let timing = Timing {
        load: (t1 - t0).as_secs_f64() * 1e3,
        order: (t2 - t1).as_secs_f64() * 1e3,
        write: (t3 - t2).as_secs_f64() * 1e3,
        total: t0.elapsed().as_secs_f64() * 1e3,
    };
    write_stats(&a.stats, &scene, &ordered, &oo, ps.paths, ps.bytes, &timing)?;
    if !a.quiet && output.as_os_str() != "-" {
        eprintln!(
            "limn: wrote {} ({} faces, {} fragments, {} splits)",
            output.display(),
            ordered.stats.faces_in,
            ordered.stats.fragments_out,
            ordered.stats.splits
        );
    }
    Ok(ExitCode::SUCCESS)
}
