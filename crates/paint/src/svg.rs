//! SVG, written directly as text.
//!
//! Layout of the output (one element per line):
//!
//! ```text
//! <svg xmlns="http://www.w3.org/2000/svg" width="W" height="H" viewBox="0 0 W H"[ stroke attributes]>
//! <rect width="W" height="H" fill="#rrggbb"/>            (only with a background)
//! <g data-name="object name">                            (one per run of the same object)
//! <path d="M… L… Z M… Z" fill="#rrggbb"[ fill-opacity="a"]/>
//! <path d="M… L…" fill="none" stroke="#rrggbb"/>          (outline of the path above)
//! <path d="M… L…" fill="none" stroke="#rrggbb" stroke-width="w" stroke-linecap="butt" …/>
//!                                                        (a line piece; markers are
//!                                                        <circle> or <path>, labels <text>)
//! </g>
//! </svg>
//! ```
//!
//! Object names go in `data-name` (XML-escaped) because names need not be unique nor free
//! of spaces, which rules out `id` and `class`; an object index out of range gives a `<g>`
//! without `data-name`. Stroke width, caps, joins and opacity are set once on `<svg>` and
//! inherited by the outline paths.
//!
//! SVG has no mesh gradient: a fragment with vertex colours is drawn as linear
//! gradients and flat pieces within [`SvgOptions::tolerance`] of its linear
//! interpolation (see `svg_smooth.rs`). A face's run of such fragments and its seam
//! flaps is drawn without seams (see `svg_smooth_run.rs`): each fragment is first filled
//! whole in one paint (its gradient when it is one piece) with its seam flaps and its
//! flaps into the later fragments of the run as subpaths, then the pieces of those drawn
//! as two or more, each with its flaps into later pieces. Consecutive translucent smooth
//! runs of one object and opacity whose fragments are shown disjoint (`layers.rs`; not
//! with outlines) are drawn so, opaque, inside one `<g opacity="a">`: blended once, with
//! no seams inside. Each gradient is a `<linearGradient id="sN"
//! gradientUnits="userSpaceOnUse">` written just before the path that uses it.
//!
//! **Textures**: each texture is embedded once in `<defs>`, as a PNG `data:` URI in an
//! `<image id="texK">` filling the unit square of texture space (with a wrapped border
//! of one texel outside it, see `texture_images.rs`; `image-rendering:smooth` asks for
//! bilinear interpolation, as limn samples), with a `<clipPath id="unitK">`: that square
//! grown by half a texel (a cut-out texture's: the rectangles of its shown texels, see
//! `texture_mask.rs`; a blended texture's PNG carries its alpha). A textured fragment is drawn as triangles within
//! [`crate::MAX_PERSPECTIVE_ERROR`] pixels of the exact projective map (see
//! `texture_pieces.rs`), each a `<clipPath id="tcN">` of its own and a
//! `<g clip-path="url(#tcN)">` holding one `<use href="#texK" transform="matrix(…)"
//! clip-path="url(#unitK)"/>` per repetition of the texture the triangle reaches (the
//! matrix is the affine map from texture to page, shifted to the repetition; a triangle
//! reaching more than 1024 repetitions is filled with the mean colour instead and
//! counted as approximated). A fragment's triangles go in one `<g>`: with
//! `opacity` when translucent, and when the fill is not white with
//! `filter="url(#mN)"`, a `<feColorMatrix>` scaling each channel by the fill's (one
//! filter per fill colour, written before its first use): fill times texture at every
//! pixel. Smoothly lit textured fragments (vertex colours) have no filter: the smooth
//! fills of consecutive opaque ones are written after their textures as one
//! `<g style="mix-blend-mode:multiply">` (a translucent one's inside its own group). A fragment drawn as two triangles or more is first drawn whole under one
//! affine map (its first fan triangle's), so the hairlines between its triangles show
//! nearly the same texels. A run whose fragments all share one affine map is drawn
//! whole only, clipped to the union of its fragments.
//!
//! **The page image** ([`crate::draw_from_page_image`], [`Picture::page_image`]): its
//! tiles are embedded instead, each an `<image id="pgN" x y width height>` placed on the
//! page (see `texture_page.rs`), and a run drawn from it is one `<clipPath id="tcN">`
//! (the union of its fragments) and a `<g clip-path="url(#tcN)">` holding a
//! `<use href="#pgN"/>` per tile its fragments read.
//!
//! The `svg` crate could build the same document, but it stores numbers as `f32` and
//! allocates per attribute; the benchmark `paint` compares both (see BENCHMARKS.md).

use std::cell::{Cell, RefCell};
use std::io::Write;

use rayon::prelude::*;

use super::layers::Layers;
use super::marks::{paint_mark, MarkSink};
use super::merge;
use super::number::{
    alpha_milli, push_hex_color, push_milli, push_num, push_uint, push_xml_attr, rgb_u8, Sink,
};
use super::runs::{check, reversals, walk_with_marks, Frag};
use super::texture_page::Tiles;
use super::{
    svg_smooth_run, svg_texture, Label, Outline, PaintError, PaintStats, Painter, Picture,
};

/// Options for [`SvgPainter`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SvgOptions {
    /// Maximal decimals for coordinates and the outline width. Default 2 (a hundredth of
    /// a pixel); at most 9.
    pub decimals: u8,
    /// Smooth fills: the largest difference per channel (colours in [0, 1]) between
    /// the written colours and the linear interpolation of a fragment's vertex colours.
    /// Must be > 0; default 1/255.
    pub tolerance: f64,
}

impl Default for SvgOptions {
    fn default() -> Self {
        SvgOptions {
            decimals: 2,
            tolerance: crate::phong::DEFAULT_TOLERANCE,
        }
    }
}

/// Writes SVG 1.1 text.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SvgPainter {
    /// How numbers are written.
    pub options: SvgOptions,
}

impl SvgPainter {
    /// A painter with the given options.
    pub fn new(options: SvgOptions) -> Self {
        SvgPainter { options }
    }
}

/// What makes two fragments' fills identical in SVG (textured ones: the texture too).
/// Smooth fragments of one face (and their seam flaps) are one run whatever their
/// colours: the run is drawn as a whole (see `svg_smooth_run.rs`).
fn style_key(f: &Frag<'_>) -> ([u8; 3], u16, bool, Option<u32>) {
    let smooth = f.colors.is_some();
    (
        if smooth { [0; 3] } else { rgb_u8(f.flat_rgb()) },
        alpha_milli(f.alpha()),
        smooth,
        f.src.texture.as_ref().map(|t| t.texture),
    )
}

impl Painter for SvgPainter {
    fn paint<'p>(
        &self,
        picture: &'p Picture,
        out: &mut dyn Write,
    ) -> Result<PaintStats, PaintError> {
        let checked = check(picture)?;
        let d = self.options.decimals;
        let mut sink = Sink::new(out);
        let stats = PaintStats::default();
        let b = &mut sink.buf;

        b.extend_from_slice(b"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"");
        push_uint(b, picture.width.into());
        b.extend_from_slice(b"\" height=\"");
        push_uint(b, picture.height.into());
        b.extend_from_slice(b"\" viewBox=\"0 0 ");
        push_uint(b, picture.width.into());
        b.push(b' ');
        push_uint(b, picture.height.into());
        b.push(b'"');
        let seams = if picture.seams.is_finite() && picture.seams > 0.0 {
            picture.seams
        } else {
            0.0
        };
        // The root carries the stroke style of whichever strokes are most frequent: the
        // seam strokes when there are any (outline paths then say their own width and
        // opacity), else the outlines.
        if seams > 0.0 {
            b.extend_from_slice(b" stroke-width=\"");
            push_num(b, seams, d);
            b.extend_from_slice(b"\" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
        } else if let Some(o) = checked.outline {
            b.extend_from_slice(b" stroke-width=\"");
            push_num(b, o.width, d);
            b.extend_from_slice(b"\" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
            opacity_attr(b, b"stroke-opacity", alpha_milli(o.color[3]));
        }
        b.extend_from_slice(b">\n");
        if let Some(bg) = picture.background {
            b.extend_from_slice(b"<rect width=\"");
            push_uint(b, picture.width.into());
            b.extend_from_slice(b"\" height=\"");
            push_uint(b, picture.height.into());
            b.extend_from_slice(b"\" fill=\"");
            push_hex_color(b, rgb_u8([bg[0], bg[1], bg[2]]));
            b.push(b'"');
            opacity_attr(b, b"fill-opacity", alpha_milli(bg[3]));
            b.extend_from_slice(b"/>\n");
        }

        let tiles = Tiles::of(picture);
        let used = tiles.as_ref().map(|t| t.used(picture));
        svg_texture::write_defs(b, &picture.textures, tiles.as_ref().zip(used.as_deref()))?;
        let group: Cell<Option<u32>> = Cell::new(None);
        let tolerance = if self.options.tolerance > 0.0 {
            self.options.tolerance
        } else {
            crate::phong::DEFAULT_TOLERANCE
        };
        let gradients = Cell::new(0u64);
        let textured = RefCell::new(svg_texture::SvgTextures::new(tiles));
        let means: Vec<[f64; 3]> = picture.textures.iter().map(|t| t.mean()).collect();
        let sink = RefCell::new(sink);
        let stats = RefCell::new(stats);
        let enter = |b: &mut Vec<u8>, object: u32| {
            if group.get() != Some(object) {
                if group.get().is_some() {
                    b.extend_from_slice(b"</g>\n");
                }
                open_group(b, picture.objects.get(object as usize));
                group.set(Some(object));
            }
        };
        // Flat runs (neither smooth nor textured) wait in a batch and are written in
        // parallel, each task into a buffer of its own; the buffers then go out in order
        // (with the groups opened between runs), so the bytes do not depend on the
        // threads. Anything else first sends the batch out.
        let batch: RefCell<Vec<FlatRun<'p>>> = RefCell::new(Vec::new());
        let outline = checked.outline;
        let merge = picture.merge_pieces;
        let send = |sink: &mut Sink<'_>, stats: &mut PaintStats| -> Result<(), PaintError> {
            let mut batch = batch.borrow_mut();
            let written: Vec<(Vec<u8>, Vec<usize>, usize, usize)> = batch
                .par_chunks(RUNS_PER_TASK)
                .map(|chunk| {
                    let (mut b, mut ends, mut paths, mut strokes) = (Vec::new(), Vec::new(), 0, 0);
                    for r in chunk {
                        let (p, s) = r.write(&mut b, outline, seams > 0.0, merge, d);
                        paths += p;
                        strokes += s;
                        ends.push(b.len());
                    }
                    (b, ends, paths, strokes)
                })
                .collect();
            for (chunk, (b, ends, paths, strokes)) in batch.chunks(RUNS_PER_TASK).zip(written) {
                let mut start = 0;
                for (r, end) in chunk.iter().zip(ends) {
                    if end > start {
                        enter(&mut sink.buf, r.frags[0].src.object);
                        sink.buf.extend_from_slice(&b[start..end]);
                    }
                    start = end;
                    sink.maybe_flush()?;
                }
                stats.paths += paths;
                stats.strokes += strokes;
            }
            batch.clear();
            Ok(())
        };
        // Translucent smooth runs wait to be drawn as layers (see `layers.rs`): each a
        // group, opaque inside, blended once; other runs disjoint from them are painted
        // first. Not with outlines, which are painted after each run.
        let layer: RefCell<Layers<'p>> = RefCell::new(Layers::new(&picture.face_outlines));
        let flush_layer = |sink: &mut Sink<'_>, stats: &mut PaintStats| -> Result<(), PaintError> {
            if let Some((layers, (object, alpha))) = layer.borrow_mut().take() {
                // Runs painted before the layers (see `Layers::clear_of`) go first.
                send(sink, stats)?;
                enter(&mut sink.buf, object);
                let mut g = gradients.get();
                for frags in &layers {
                    stats.paths += svg_smooth_run::write(
                        &mut sink.buf,
                        frags,
                        alpha,
                        tolerance,
                        d,
                        &mut g,
                        merge,
                    );
                }
                gradients.set(g);
                sink.maybe_flush()?;
            }
            Ok(())
        };
        // Opaque smoothly lit textured runs: their textures are written as they come,
        // their smooth fills wait here and go out as one group multiplied over them
        // (`mix-blend-mode:multiply`) before anything else is written. Inside the group
        // the fills are composited as untextured smooth runs are (seams closed by
        // flaps), so the lit colour multiplies each pixel once.
        let lit: RefCell<Vec<Vec<Frag<'p>>>> = RefCell::new(Vec::new());
        let flush_lit = |sink: &mut Sink<'_>, stats: &mut PaintStats| {
            let mut lit = lit.borrow_mut();
            if lit.is_empty() {
                return;
            }
            let b = &mut sink.buf;
            b.extend_from_slice(b"<g style=\"mix-blend-mode:multiply\">\n");
            let mut g = gradients.get();
            for run in lit.iter() {
                stats.paths += svg_smooth_run::write(b, run, 1000, tolerance, d, &mut g, false);
            }
            gradients.set(g);
            b.extend_from_slice(b"</g>\n");
            lit.clear();
        };
        let on_run = |run: &[Frag<'p>], key: &([u8; 3], u16, bool, Option<u32>)| {
            let (rgb, alpha, smooth, texture) = *key;
            let mut sink = sink.borrow_mut();
            let mut stats = stats.borrow_mut();
            let lit_run =
                smooth && texture.is_some() && alpha >= 1000 && !svg_texture::see_through(run);
            // Anything else written first: the waiting lit fills go out before it.
            if !lit_run
                || !batch.borrow().is_empty()
                || !layer.borrow().clear_of(run)
                || group.get() != Some(run[0].src.object)
            {
                flush_lit(&mut sink, &mut stats);
            }
            if smooth && texture.is_none() && alpha < 1000 && checked.outline.is_none() {
                send(&mut sink, &mut stats)?;
                let key = (run[0].src.object, alpha);
                if !layer.borrow_mut().join(key, run) {
                    flush_layer(&mut sink, &mut stats)?;
                    layer.borrow_mut().join(key, run);
                }
                return Ok(());
            }
            if !layer.borrow().clear_of(run) {
                flush_layer(&mut sink, &mut stats)?;
            }
            if !smooth && texture.is_none() {
                let mut waiting = batch.borrow_mut();
                waiting.push(FlatRun {
                    frags: run.to_vec(),
                    rgb,
                    alpha,
                });
                if waiting.len() >= RUNS_PER_BATCH {
                    drop(waiting);
                    send(&mut sink, &mut stats)?;
                }
                return Ok(());
            }
            send(&mut sink, &mut stats)?;
            let b = &mut sink.buf;
            enter(b, run[0].src.object);
            if let Some(k) = texture {
                let mut g = gradients.get();
                let inside = (smooth && !lit_run).then_some((tolerance, &mut g));
                stats.paths += textured.borrow_mut().run(
                    b,
                    run,
                    k,
                    alpha,
                    means[k as usize],
                    d,
                    merge,
                    inside,
                );
                gradients.set(g);
                if lit_run {
                    lit.borrow_mut().push(run.to_vec());
                }
            } else {
                let mut g = gradients.get();
                stats.paths += svg_smooth_run::write(b, run, alpha, tolerance, d, &mut g, merge);
                gradients.set(g);
            }
            let outlined = checked
                .outline
                .filter(|_| run.iter().any(Frag::has_outline));
            if let Some(o) = outlined {
                // Over the lit texture.
                flush_lit(&mut sink, &mut stats);
                let b = &mut sink.buf;
                write_outline(b, run, o, seams > 0.0, d);
                stats.strokes += 1;
            }
            sink.maybe_flush()?;
            Ok(())
        };
        let on_mark = |m: &super::Mark| {
            let mut sink = sink.borrow_mut();
            flush_lit(&mut sink, &mut stats.borrow_mut());
            flush_layer(&mut sink, &mut stats.borrow_mut())?;
            send(&mut sink, &mut stats.borrow_mut())?;
            enter(&mut sink.buf, m.object);
            let mut w = SvgMarks {
                b: &mut sink.buf,
                d,
            };
            paint_mark(m, &checked.guard, &mut w, &mut stats.borrow_mut())?;
            sink.maybe_flush()?;
            Ok(())
        };
        let counts = walk_with_marks(
            picture,
            &checked.guard,
            checked.runs(),
            style_key,
            on_run,
            on_mark,
        )?;
        let mut sink = sink.into_inner();
        let mut stats = stats.into_inner();
        flush_lit(&mut sink, &mut stats);
        flush_layer(&mut sink, &mut stats)?;
        send(&mut sink, &mut stats)?;
        stats.approximated += textured.into_inner().approximated;
        if group.get().is_some() {
            sink.buf.extend_from_slice(b"</g>\n");
        }
        sink.buf.extend_from_slice(b"</svg>\n");
        stats.skipped += counts.skipped;
        stats.clipped += counts.clipped;
        stats.bytes = sink.finish()?;
        Ok(stats)
    }
}

/// Flat runs waiting to be written, at most.
const RUNS_PER_BATCH: usize = 16384;

/// Flat runs written by one parallel task.
const RUNS_PER_TASK: usize = 512;

/// A run of flat fragments (neither smooth nor textured) waiting to be written.
struct FlatRun<'a> {
    frags: Vec<Frag<'a>>,
    rgb: [u8; 3],
    alpha: u16,
}

impl FlatRun<'_> {
    /// Writes the run's fill (the union of its fragments when `merge`, nothing when
    /// that fills no point and is not stroked; else its fragments snap-rounded together)
    /// and outline; returns the number of fill
    /// paths and of strokes (0 or 1 each).
    fn write(
        &self,
        b: &mut Vec<u8>,
        outline: Option<Outline>,
        seams: bool,
        merge: bool,
        d: u8,
    ) -> (usize, usize) {
        let stroked = seams && self.alpha >= 1000;
        let merged = merge::run_shapes(&self.frags, d, merge, |p| p)
            .filter(|shapes| !(shapes.is_empty() && stroked));
        let paths = match merged {
            Some(shapes) if shapes.is_empty() => 0,
            merged => {
                write_fill(b, &self.frags, merged, self.rgb, self.alpha, seams, d);
                1
            }
        };
        match outline.filter(|_| self.frags.iter().any(Frag::has_outline)) {
            Some(o) => {
                write_outline(b, &self.frags, o, seams, d);
                (paths, 1)
            }
            None => (paths, 0),
        }
    }
}

/// Writes the fill of a run as one path: the rings of `merged` (the run on the grid,
/// see [`merge::run_shapes`]) when given, else each fragment a subpath, turned the way
/// the first one turns; stroked in its own colour when seams close it.
fn write_fill(
    b: &mut Vec<u8>,
    run: &[Frag<'_>],
    merged: Option<merge::Shapes>,
    rgb: [u8; 3],
    alpha: u16,
    seams: bool,
    d: u8,
) {
    b.extend_from_slice(b"<path d=\"");
    let command = |k: usize| match k {
        0 => b'M',
        1 => b'L',
        _ => b' ',
    };
    match merged {
        Some(shapes) => merge::push_svg_rings(b, shapes.iter().flatten(), d),
        None => {
            for (f, reverse) in run.iter().zip(reversals(run)) {
                for (k, p) in f.oriented(reverse).enumerate() {
                    b.push(command(k));
                    push_point(b, p, d);
                }
                b.push(b'Z');
            }
        }
    }
    b.extend_from_slice(b"\" fill=\"");
    push_hex_color(b, rgb);
    b.push(b'"');
    opacity_attr(b, b"fill-opacity", alpha);
    if seams && alpha >= 1000 {
        b.extend_from_slice(b" stroke=\"");
        push_hex_color(b, rgb);
        b.push(b'"');
    }
    b.extend_from_slice(b"/>\n");
}

/// Writes the original edges of a run as one stroked path (its own width and opacity
/// when the root's stroke style is the seams').
fn write_outline(b: &mut Vec<u8>, run: &[Frag<'_>], o: Outline, seams: bool, d: u8) {
    b.extend_from_slice(b"<path d=\"");
    for f in run {
        push_outline(b, f, d);
    }
    b.extend_from_slice(b"\" fill=\"none\" stroke=\"");
    push_hex_color(b, rgb_u8([o.color[0], o.color[1], o.color[2]]));
    b.push(b'"');
    if seams {
        b.extend_from_slice(b" stroke-width=\"");
        push_num(b, o.width, d);
        b.push(b'"');
        opacity_attr(b, b"stroke-opacity", alpha_milli(o.color[3]));
    }
    b.extend_from_slice(b"/>\n");
}

/// ` name="0.5"` when the opacity is below 1.
fn opacity_attr(b: &mut Vec<u8>, name: &[u8], milli: u16) {
    if milli < 1000 {
        b.push(b' ');
        b.extend_from_slice(name);
        b.extend_from_slice(b"=\"");
        push_milli(b, milli);
        b.push(b'"');
    }
}

fn open_group(b: &mut Vec<u8>, name: Option<&String>) {
    match name {
        Some(name) => {
            b.extend_from_slice(b"<g data-name=\"");
            push_xml_attr(b, name);
            b.extend_from_slice(b"\">\n");
        }
        None => b.extend_from_slice(b"<g>\n"),
    }
}

fn push_point(b: &mut Vec<u8>, p: [f64; 2], d: u8) {
    push_num(b, p[0], d);
    b.push(b' ');
    push_num(b, p[1], d);
}

/// The original edges of `f` as open subpaths (one closed subpath when all are original).
fn push_outline(b: &mut Vec<u8>, f: &Frag<'_>, d: u8) {
    let n = f.points.len();
    f.polylines(|start, edges, closed| {
        let last = if closed { edges - 1 } else { edges };
        for k in 0..=last {
            b.push(match k {
                0 => b'M',
                1 => b'L',
                _ => b' ',
            });
            push_point(b, f.points[(start + k) % n], d);
        }
        if closed {
            b.push(b'Z');
        }
    });
}

/// Marks as SVG elements.
struct SvgMarks<'b> {
    b: &'b mut Vec<u8>,
    d: u8,
}

impl SvgMarks<'_> {
    fn paint_attrs(&mut self, name: &[u8], color: [f64; 4]) {
        self.b.push(b' ');
        self.b.extend_from_slice(name);
        self.b.extend_from_slice(b"=\"");
        push_hex_color(self.b, rgb_u8([color[0], color[1], color[2]]));
        self.b.push(b'"');
        let opacity: &[u8] = if name == b"fill" {
            b"fill-opacity"
        } else {
            b"stroke-opacity"
        };
        opacity_attr(self.b, opacity, alpha_milli(color[3]));
    }

    fn stroke_attrs(&mut self, color: [f64; 4], width: f64) {
        self.b.extend_from_slice(b" fill=\"none\"");
        self.paint_attrs(b"stroke", color);
        self.b.extend_from_slice(b" stroke-width=\"");
        push_num(self.b, width, self.d);
        self.b.push(b'"');
    }
}

impl MarkSink for SvgMarks<'_> {
    fn polylines(
        &mut self,
        lines: &[Vec<[f64; 2]>],
        closed: bool,
        color: [f64; 4],
        width: f64,
        dash: &[f64],
        offset: f64,
    ) -> Result<(), PaintError> {
        self.b.extend_from_slice(b"<path d=\"");
        for line in lines {
            for (k, &p) in line.iter().enumerate() {
                self.b.push(match k {
                    0 => b'M',
                    1 => b'L',
                    _ => b' ',
                });
                push_point(self.b, p, self.d);
            }
            if closed {
                self.b.push(b'Z');
            }
        }
        self.b.push(b'"');
        self.stroke_attrs(color, width);
        self.b
            .extend_from_slice(b" stroke-linecap=\"butt\" stroke-linejoin=\"round\"");
        if !dash.is_empty() {
            self.b.extend_from_slice(b" stroke-dasharray=\"");
            for (i, &v) in dash.iter().enumerate() {
                if i > 0 {
                    self.b.push(b' ');
                }
                push_num(self.b, v, self.d);
            }
            self.b.push(b'"');
            if offset != 0.0 {
                self.b.extend_from_slice(b" stroke-dashoffset=\"");
                push_num(self.b, offset, self.d);
                self.b.push(b'"');
            }
        }
        self.b.extend_from_slice(b"/>\n");
        Ok(())
    }

    fn circle(
        &mut self,
        c: [f64; 2],
        r: f64,
        color: [f64; 4],
        stroke: Option<f64>,
    ) -> Result<(), PaintError> {
        self.b.extend_from_slice(b"<circle cx=\"");
        push_num(self.b, c[0], self.d);
        self.b.extend_from_slice(b"\" cy=\"");
        push_num(self.b, c[1], self.d);
        self.b.extend_from_slice(b"\" r=\"");
        push_num(self.b, r, self.d);
        self.b.push(b'"');
        match stroke {
            None => self.paint_attrs(b"fill", color),
            Some(w) => self.stroke_attrs(color, w),
        }
        self.b.extend_from_slice(b"/>\n");
        Ok(())
    }

    fn triangle(&mut self, points: [[f64; 2]; 3], color: [f64; 4]) -> Result<(), PaintError> {
        self.b.extend_from_slice(b"<path d=\"");
        for (k, p) in points.into_iter().enumerate() {
            self.b.push(if k == 0 {
                b'M'
            } else if k == 1 {
                b'L'
            } else {
                b' '
            });
            push_point(self.b, p, self.d);
        }
        self.b.extend_from_slice(b"Z\"");
        self.paint_attrs(b"fill", color);
        self.b.extend_from_slice(b" stroke=\"none\"/>\n");
        Ok(())
    }

    fn text(&mut self, origin: [f64; 2], label: &Label) -> Result<bool, PaintError> {
        self.b.extend_from_slice(b"<text x=\"");
        push_num(self.b, origin[0], self.d);
        self.b.extend_from_slice(b"\" y=\"");
        push_num(self.b, origin[1], self.d);
        self.b
            .extend_from_slice(b"\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"");
        push_num(self.b, label.size, self.d);
        self.b.push(b'"');
        self.paint_attrs(b"fill", label.color);
        self.b
            .extend_from_slice(b" stroke=\"none\" xml:space=\"preserve\">");
        push_xml_attr(self.b, &label.text);
        self.b.extend_from_slice(b"</text>\n");
        Ok(false)
    }
}
