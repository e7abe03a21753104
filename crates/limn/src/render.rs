//! A render, from input to written file: load → (hidden-line preparation) → order →
//! compose → write, or an image-space method per pixel; the statistics and warnings.

use std::borrow::Cow;
use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

use limn_depthsort::{order, order_with_marks, OrderError, OrderOptions, Ordered, VisibleMarks};
use limn_paint::{
    add_seam_flaps, draw_from_page_image, hidden_line_picture, painter_for,
    picture_with_marks_unflapped, Format, Painter, Picture, SvgOptions, SvgPainter, TikzOptions,
    TikzPainter,
};
use limn_scene::{Camera, Effects, Scene};

use crate::error::Error;
use crate::events::Events;
use crate::hidden_line::hidden_line_scene;
use crate::input::{load, Input};
use crate::losses::losses;
use crate::options::{Method, RenderOptions};
use crate::output::{check_writable, write_atomic};
use crate::raster::raster;
use crate::settings;
use crate::stats::RenderStats;

/// What to render, where, and how.
#[derive(Debug, Clone)]
pub struct Request<'a> {
    /// The scene.
    pub input: Input<'a>,
    /// Where to write the picture (`-` for standard output) [default: the input file
    /// beside itself, with the format's extension].
    pub output: Option<PathBuf>,
    /// Every option.
    pub options: RenderOptions,
}

/// A finished render.
pub struct Rendered<'a> {
    /// Where the picture went.
    pub output: PathBuf,
    /// Its format.
    pub format: Format,
    /// How it was computed.
    pub method: Method,
    /// The statistics of a painter's render (`None` for the image-space methods).
    pub stats: Option<RenderStats>,
    /// Every warning of the render, loading and drawing.
    pub warnings: Vec<String>,
    /// The scene (a loaded one without its faces and vertex data, released once the
    /// picture was composed), the order and the picture, kept so that a caller about to
    /// exit can leave them to the system instead of freeing millions of allocations one
    /// by one (`std::mem::forget` on the whole result).
    _scene: Cow<'a, Scene>,
    parts: Option<Box<Parts>>,
}

/// What a painter's render made: the order and the picture (and the scene the edges of a
/// hidden-line drawing were added to).
struct Parts {
    _drawn: Option<(Scene, usize)>,
    ordered: Ordered,
    _marks: VisibleMarks,
    picture: Picture,
}

impl Rendered<'_> {
    /// The ordering's result (`None` for the image-space methods), without its fragments:
    /// they are released once composed into the picture (their count is
    /// [`limn_depthsort::Stats::fragments_out`]).
    pub fn ordered(&self) -> Option<&Ordered> {
        self.parts.as_ref().map(|p| &p.ordered)
    }

    /// The picture as composed before writing: fragments in paint order with their
    /// fills, and the visible marks (`None` for the image-space methods).
    pub fn picture(&self) -> Option<&Picture> {
        self.parts.as_ref().map(|p| &p.picture)
    }
}

impl std::fmt::Debug for Rendered<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Rendered")
            .field("output", &self.output)
            .field("format", &self.format)
            .field("method", &self.method)
            .field("stats", &self.stats)
            .field("warnings", &self.warnings)
            .finish_non_exhaustive()
    }
}

/// Warnings passed on to the caller's events and kept for the statistics.
struct Kept<'e> {
    events: &'e mut dyn Events,
    warnings: Vec<String>,
}

impl Events for Kept<'_> {
    fn warning(&mut self, text: &str) {
        self.warnings.push(text.to_string());
        self.events.warning(text);
    }
    fn phase(&mut self, name: &'static str) {
        self.events.phase(name);
    }
}

/// Milliseconds between two instants.
fn ms(from: Instant, to: Instant) -> f64 {
    (to - from).as_secs_f64() * 1e3
}

/// Runs a render: writes the picture (and the statistics, when asked) safely — nothing
/// is left behind on error, and no file the scene was read from is written over.
pub fn render<'a>(req: &Request<'a>, events: &mut dyn Events) -> Result<Rendered<'a>, Error> {
    run(req, None, events)
}

/// Runs a render that writes the picture to `out` instead of a file: the request's
/// output path, if any, only names the format (else the format option, else SVG). The
/// statistics file, when asked, is still written safely.
pub fn render_into<'a>(
    req: &Request<'a>,
    out: &mut dyn Write,
    events: &mut dyn Events,
) -> Result<Rendered<'a>, Error> {
    run(req, Some(out), events)
}

/// A render, written to `out` or else to the request's output file.
fn run<'a>(
    req: &Request<'a>,
    out: Option<&mut dyn Write>,
    events: &mut dyn Events,
) -> Result<Rendered<'a>, Error> {
    let t0 = Instant::now();
    let o = &req.options;
    o.validate()?;
    let mut ev = Kept {
        events,
        warnings: Vec::new(),
    };
    let mut loaded = load(&req.input, &o.view, &mut ev)?;
    let scene: &Scene = &loaded.scene;
    let name = &loaded.name;
    let cam = settings::camera(scene, &o.view, loaded.settings.size, name)?;
    let oo = settings::order_options(&o.view, &loaded.settings)?;
    let (output, format) = match (&out, &req.output) {
        (Some(_), None) => (PathBuf::from("-"), o.format.unwrap_or(Format::Svg)),
        _ => settings::output_and_format(
            &req.input,
            req.output.as_deref(),
            o.format,
            &loaded.settings,
        )?,
    };
    if o.standalone && format != Format::Tikz {
        return Err(Error::Standalone(format));
    }
    if out.is_none() {
        check_writable(&output, &scene.files)?;
    }
    if let Some(stats) = &o.stats {
        check_writable(stats, &scene.files)?;
    }
    if o.method != Method::Painter {
        if format != Format::Png {
            return Err(Error::RasterFormat(o.method.name()));
        }
        ev.phase("rendering");
        raster(scene, &cam, o, &oo, &output, out, &mut ev)?;
        let warnings = ev.warnings;
        return Ok(Rendered {
            output,
            format,
            method: o.method,
            stats: None,
            warnings,
            _scene: loaded.scene,
            parts: None,
        });
    }
    let t1 = Instant::now();
    ev.phase("ordering");
    // What the statistics and warnings need of the scene, which may be released before.
    let faces = scene.faces.len();
    let effects = Effects::of(scene);
    let files = scene.files.clone();
    let hidden_line = settings::hidden_line_style(o, &loaded.settings);
    let background = settings::background(o, &loaded.settings);
    let drawn_scene = hidden_line.as_ref().map(|h| {
        let fill = background.map_or([1.0; 3], |b| [b[0], b[1], b[2]]);
        hidden_line_scene(scene, &cam, h, fill)
    });
    let ordered_scene = drawn_scene.as_ref().map_or(scene, |d| &d.0);
    let (mut ordered, marks) =
        order_scene(ordered_scene, &cam, &oo).map_err(|e| Error::order(e, name))?;
    let t2 = Instant::now();
    ev.phase("writing");
    let tolerance = settings::tolerance(o, scene, format);
    let style = settings::style(o, &loaded.settings, background, tolerance);
    let mut pic = match (&hidden_line, &drawn_scene) {
        (Some(h), Some((s, first))) => {
            hidden_line_picture(s, &mut ordered, &marks, *first, h, &style)
        }
        _ => {
            let mut pic = picture_with_marks_unflapped(scene, &mut ordered, &marks, &style);
            release_faces(&mut loaded.scene);
            add_seam_flaps(&mut pic, &style);
            pic
        }
    };
    if matches!(format, Format::Svg | Format::Pdf) {
        draw_from_page_image(&mut pic, o.texture_samples);
    }
    let painter: Box<dyn Painter> = match format {
        Format::Tikz => Box::new(TikzPainter::new(TikzOptions {
            standalone: o.standalone,
            ..TikzOptions::default()
        })),
        Format::Svg => Box::new(SvgPainter::new(SvgOptions {
            tolerance,
            ..SvgOptions::default()
        })),
        _ => painter_for(format),
    };
    let ps = match out {
        Some(w) => painter.paint(&pic, w)?,
        None => write_atomic(&output, &files, |w| Ok(painter.paint(&pic, w)?))?,
    };
    let t3 = Instant::now();
    for w in losses(faces, &ordered, &ps, format, cam.near.is_some()) {
        ev.warning(&w);
    }
    let timing = [ms(t0, t1), ms(t1, t2), ms(t2, t3), ms(t0, Instant::now())];
    let stats = RenderStats::new(
        effects,
        &ordered,
        &oo,
        (&ps, &marks.stats),
        timing,
        ev.warnings.clone(),
    );
    if let Some(path) = &o.stats {
        let text = stats.to_json_text();
        write_atomic(path, &files, |w| {
            w.write_all(text.as_bytes())
                .map_err(|source| crate::output::OutputError::Write {
                    path: path.clone(),
                    source,
                })?;
            Ok(())
        })?;
    }
    let warnings = ev.warnings;
    let parts = Parts {
        _drawn: drawn_scene,
        ordered,
        _marks: marks,
        picture: pic,
    };
    Ok(Rendered {
        output,
        format,
        method: Method::Painter,
        stats: Some(stats),
        warnings,
        _scene: loaded.scene,
        parts: Some(Box::new(parts)),
    })
}

/// Releases a loaded scene's faces and vertex data, which a composed picture no longer
/// needs (a million-face scene's were about 150 MB, held while the seam flaps were put
/// in and the picture written); a scene borrowed from the caller stays as it is.
fn release_faces(scene: &mut Cow<'_, Scene>) {
    if let Cow::Owned(s) = scene {
        s.faces = Vec::new();
        s.vertices = Vec::new();
        s.normals = Vec::new();
        s.texcoords = Vec::new();
        s.colors = Vec::new();
    }
}

/// Orders `scene` and hides its lines, markers and labels. A scene without any is only
/// ordered: hiding marks makes an occluder of every fragment (a copy of its exact
/// polygon, its planes and screen bins) even when there is nothing to hide.
pub fn order_scene(
    scene: &Scene,
    cam: &Camera,
    oo: &OrderOptions,
) -> Result<(Ordered, VisibleMarks), OrderError> {
    if scene.lines.is_empty() && scene.points.is_empty() && scene.labels.is_empty() {
        return Ok((order(scene, cam, oo)?, VisibleMarks::default()));
    }
    order_with_marks(scene, cam, oo)
}
