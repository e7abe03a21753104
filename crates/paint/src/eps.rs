//! Encapsulated PostScript, written directly as text.
//!
//! ```text
//! %!PS-Adobe-3.0 EPSF-3.0
//! %%BoundingBox: 0 0 W H
//! %%Creator: limn
//! %%LanguageLevel: 2            (3 when a Gouraud fragment needs shfill)
//! %%EndComments
//! 12 dict begin
//! /m/moveto load def /l/lineto load def /h/closepath load def /f/fill load def …
//! 0.2 0.4 0.6 c
//! 10 90 m 90 90 l 50 20 l h f
//! end
//! showpage
//! %%EOF
//! ```
//!
//! Coordinates are pixel coordinates with y flipped: (x, y) is written as (x, H − y). The
//! short names live in a private dictionary that is popped at the end, so an including
//! document's dictionaries are left as they were.
//!
//! **Translucency**: PostScript has no opacity. A fill (or outline) with opacity `a` < 1 is
//! painted opaquely in `a · colour + (1 − a) · backdrop`, where the backdrop is the
//! picture's background (itself flattened onto the paper colour) or, with no background,
//! [`EpsOptions::paper`]. What lies under the fragment is ignored, so the result is an
//! approximation; each such fragment and outline path is counted in
//! [`PaintStats::approximated`]. A fill of opacity 0 is not painted at all.
//!
//! **Gouraud** fragments become `shfill` with a type-4 shading (LanguageLevel 3) whose
//! `DataSource` is an array of `flag x y r g b` vertices, the fragment fan-triangulated;
//! arrays hold at most 27 triangles to stay within the 500-entry operand stack of small
//! interpreters. Long runs are filled in pieces of at most 1000 points (the LanguageLevel 2
//! path limit is 1500).
//!
//! **Textured** fragments are drawn as in PDF (affine pieces within
//! [`crate::MAX_PERSPECTIVE_ERROR`] pixels, each clipped, the image once per texture
//! repetition, under a cover of the whole run), with the `image` operator of
//! LanguageLevel 2; the images are defined once in the prolog and the fill multiplies
//! them through `/Decode` (see `eps_texture.rs`). A translucent textured fragment is
//! flattened like a flat fill (and counted); a piece reaching more than 1024
//! repetitions is filled with the fill times the texture's mean colour (counted). A
//! smoothly lit textured fragment (vertex colours) multiplies its texture by the mean
//! of its corners' colours (counted): LanguageLevel 2 has no blend mode to multiply a
//! shading over an image.
//!
//! **Marks** are each painted inside `gsave … grestore`: line pieces with butt caps, round
//! joins and `setdash`; markers as stroked or filled paths (circles with `arc`); labels
//! with the standard font Helvetica (`findfont scalefont setfont … show`, not embedded),
//! printable ASCII only (other characters become `?`, counted as approximated).
//! Translucent marks are flattened like fills (and counted as approximated).

use std::cell::RefCell;
use std::io::Write;

use super::marks::{ascii_text, circle_beziers, paint_mark, MarkSink};
use super::merge;
use super::number::{alpha_milli, channel_fixed, push_fixed, push_num, push_uint, Sink};
use super::pdf::push_ps_string;
use super::runs::{check, reversals, walk_with_marks, Frag};
use super::texture_pieces::{affine_pieces, pieces_over};
use super::{
    eps_texture, texture_images, texture_mask, wide_color, Label, PaintError, PaintStats, Painter,
    Picture,
};
use limn_scene::TextureAlpha;

/// Options for [`EpsPainter`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EpsOptions {
    /// Maximal decimals for coordinates and the outline width. Default 2; at most 9.
    pub decimals: u8,
    /// Maximal decimals for colour components. Default 4; at most 9.
    pub color_decimals: u8,
    /// The colour translucent paint is blended with when the picture has no background.
    /// Default white; components are clamped to [0, 1] and non-finite ones read as 1.
    pub paper: [f64; 3],
}

impl Default for EpsOptions {
    fn default() -> Self {
        EpsOptions {
            decimals: 2,
            color_decimals: 4,
            paper: [1.0; 3],
        }
    }
}

/// Writes EPSF-3.0.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct EpsPainter {
    /// How numbers are written and translucency flattened.
    pub options: EpsOptions,
}

impl EpsPainter {
    /// A painter with the given options.
    pub fn new(options: EpsOptions) -> Self {
        EpsPainter { options }
    }
}

const MAX_TRIANGLES_PER_SHFILL: usize = 27;
const MAX_POINTS_PER_FILL: usize = 1000;

/// What makes two fragments paint alike in EPS.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Style {
    /// Flattened colour; `None` when fully transparent.
    Flat(Option<[u32; 3]>),
    /// Opacity in thousandths.
    Gouraud(u16),
    /// Texture index, fill and opacity in thousandths.
    Textured(u32, [u32; 3], u16),
}

struct Writer {
    d: u8,
    cd: u8,
    height: f64,
    backdrop: [f64; 3],
    rgb: Option<[u32; 3]>,
    /// Flat fills are also stroked in their own colour (`Picture::seams`).
    seams: bool,
    /// Whether a flat run is written as the union of its fragments
    /// ([`crate::Picture::merge_pieces`]).
    merge: bool,
}

/// `a · c + (1 − a) · backdrop`.
fn flatten(c: [f64; 3], a: f64, backdrop: [f64; 3]) -> [f64; 3] {
    let a = a.clamp(0.0, 1.0);
    [0, 1, 2].map(|k| a * c[k].clamp(0.0, 1.0) + (1.0 - a) * backdrop[k])
}

impl Writer {
    fn point(&self, b: &mut Vec<u8>, p: [f64; 2]) {
        push_num(b, p[0], self.d);
        b.push(b' ');
        push_num(b, self.height - p[1], self.d);
    }

    fn quantise(&self, c: [f64; 3]) -> [u32; 3] {
        c.map(|v| channel_fixed(v, self.cd))
    }

    fn set_color(&mut self, b: &mut Vec<u8>, q: [u32; 3]) {
        if self.rgb != Some(q) {
            for v in q {
                push_fixed(b, v, self.cd);
                b.push(b' ');
            }
            b.extend_from_slice(b"c\n");
            self.rgb = Some(q);
        }
    }

    fn flat_run(&mut self, b: &mut Vec<u8>, run: &[Frag<'_>], q: [u32; 3]) {
        let height = self.height;
        let merged = merge::run_shapes(run, self.d, self.merge, |p| [p[0], height - p[1]])
            .filter(|shapes| !(shapes.is_empty() && self.seams));
        if merged.as_ref().is_some_and(Vec::is_empty) {
            // Fills no point.
            return;
        }
        self.set_color(b, q);
        let mut points = 0;
        if let Some(shapes) = merged {
            // A shape's outer ring and holes go in one fill.
            for shape in &shapes {
                let n = merge::corners(shape);
                if points > 0 && points + n > MAX_POINTS_PER_FILL {
                    b.extend_from_slice(b"f\n");
                    points = 0;
                }
                merge::push_moveto_lineto(b, shape, self.d);
                points += n;
            }
            b.extend_from_slice(if self.seams { b"F\n" } else { b"f\n" });
            return;
        }
        for (f, reverse) in run.iter().zip(reversals(run)) {
            if points > 0 && points + f.points.len() > MAX_POINTS_PER_FILL {
                b.extend_from_slice(b"f\n");
                points = 0;
            }
            for (k, p) in f.oriented(reverse).enumerate() {
                self.point(b, p);
                b.extend_from_slice(if k == 0 { b" m " } else { b" l " });
            }
            b.extend_from_slice(b"h\n");
            points += f.points.len();
        }
        b.extend_from_slice(if self.seams { b"F\n" } else { b"f\n" });
    }

    fn gouraud_run(&mut self, b: &mut Vec<u8>, run: &[Frag<'_>], alpha: f64) {
        let mut triangles = 0;
        b.push(b'[');
        for f in run {
            let Some(colors) = &f.colors else { continue };
            for i in 1..f.points.len() - 1 {
                if triangles == MAX_TRIANGLES_PER_SHFILL {
                    b.extend_from_slice(b"] g\n[");
                    triangles = 0;
                }
                for v in [0, i, i + 1] {
                    b.extend_from_slice(b"0 ");
                    self.point(b, f.points[v]);
                    let c = wide_color(colors[v]);
                    let c = flatten([c[0], c[1], c[2]], alpha, self.backdrop);
                    for q in self.quantise(c) {
                        b.push(b' ');
                        push_fixed(b, q, self.cd);
                    }
                    b.push(b'\n');
                }
                triangles += 1;
            }
        }
        b.extend_from_slice(b"] g\n");
    }

    /// A run of textured fragments with texture `k` (see `eps_texture.rs`): the image
    /// decoded between `lo` and `hi` (the fill, flattened when translucent), first the
    /// whole run under one affine map, then each affine piece. Pieces reaching too many
    /// repetitions are filled with `mean` (already fill × mean texture colour,
    /// flattened). Returns how many fragments were filled so.
    fn textured_run(
        &mut self,
        b: &mut Vec<u8>,
        run: &[Frag<'_>],
        k: u32,
        decode: ([u32; 3], [u32; 3]),
        mean: [u32; 3],
    ) -> usize {
        b.extend_from_slice(b"/D [");
        for i in 0..3 {
            push_fixed(b, decode.0[i], self.cd);
            b.push(b' ');
            push_fixed(b, decode.1[i], self.cd);
            b.extend_from_slice(if i < 2 { b" " } else { b"] def\n" });
        }
        let polys: Vec<Vec<[f64; 2]>> = run
            .iter()
            .zip(reversals(run))
            .map(|(f, reverse)| f.oriented(reverse).collect())
            .collect();
        let mean_fill = |w: &mut Writer, b: &mut Vec<u8>, polys: &[Vec<[f64; 2]>]| {
            w.set_color(b, mean);
            for poly in polys {
                for (i, &p) in poly.iter().enumerate() {
                    w.point(b, p);
                    b.extend_from_slice(if i == 0 { b" m " } else { b" l " });
                }
                b.extend_from_slice(b"h ");
            }
            b.extend_from_slice(b"f\n");
        };
        // Under the pieces, the whole run (fragments and seam flaps) under one affine
        // map, the first fan triangle's: the edges between pieces then show nearly the
        // same texels. In clips of at most MAX_POINTS_PER_FILL points.
        // (Not under a cut-out: it would show where the pieces' boundaries cut.)
        let whole = run
            .iter()
            .find_map(|f| f.src.texture.as_deref().copied())
            .filter(|map| !map.see_through())
            .and_then(|map| {
                affine_pieces(&run[0].points, &map, f64::INFINITY)
                    .into_iter()
                    .next()
            });
        if let Some(whole) = &whole {
            let mut start = 0;
            while start < polys.len() {
                let mut end = start;
                let mut points = 0;
                while end < polys.len()
                    && (end == start || points + polys[end].len() <= MAX_POINTS_PER_FILL)
                {
                    points += polys[end].len();
                    end += 1;
                }
                let chunk = &polys[start..end];
                if !eps_texture::write_clipped(b, chunk, whole, k, self.height, self.d) {
                    mean_fill(self, b, chunk);
                }
                start = end;
            }
        }
        let mut approximated = 0;
        for f in run {
            let Some(map) = &f.src.texture else { continue };
            let mut flat = false;
            for p in pieces_over(&f.points, map, whole.as_ref(), run.len() == 1) {
                let tri = [p.points.clone()];
                if !eps_texture::write_clipped(b, &tri, &p, k, self.height, self.d) {
                    flat = true;
                    mean_fill(self, b, &tri);
                }
            }
            approximated += usize::from(flat);
        }
        approximated
    }

    fn outline(&self, b: &mut Vec<u8>, run: &[Frag<'_>]) {
        for f in run {
            let n = f.points.len();
            f.polylines(|start, edges, closed| {
                let last = if closed { edges - 1 } else { edges };
                for k in 0..=last {
                    self.point(b, f.points[(start + k) % n]);
                    b.extend_from_slice(if k == 0 { b" m " } else { b" l " });
                }
                if closed {
                    b.extend_from_slice(b"h ");
                }
            });
        }
        b.extend_from_slice(b"s\n");
    }
}

impl Painter for EpsPainter {
    fn paint(&self, picture: &Picture, out: &mut dyn Write) -> Result<PaintStats, PaintError> {
        let checked = check(picture)?;
        let o = &self.options;
        let paper = o.paper.map(|v| {
            if v.is_finite() {
                v.clamp(0.0, 1.0)
            } else {
                1.0
            }
        });
        let mut stats = PaintStats::default();
        let backdrop = match picture.background {
            Some(bg) => flatten([bg[0], bg[1], bg[2]], bg[3], paper),
            None => paper,
        };
        let mut w = Writer {
            d: o.decimals,
            cd: o.color_decimals,
            height: f64::from(picture.height),
            backdrop,
            rgb: None,
            seams: picture.seams.is_finite() && picture.seams > 0.0,
            merge: picture.merge_pieces,
        };
        let gouraud = picture.fragments.iter().any(|f| f.vertex_colors.is_some());

        let mut sink = Sink::new(out);
        let b = &mut sink.buf;
        b.extend_from_slice(b"%!PS-Adobe-3.0 EPSF-3.0\n%%BoundingBox: 0 0 ");
        push_uint(b, picture.width.into());
        b.push(b' ');
        push_uint(b, picture.height.into());
        b.extend_from_slice(b"\n%%Creator: limn\n%%LanguageLevel: ");
        b.extend_from_slice(if gouraud { b"3" } else { b"2" });
        b.extend_from_slice(b"\n%%EndComments\n");
        // The short names, and per texture its rows, procedure and the decode array.
        push_uint(b, 12 + 2 * picture.textures.len() as u64 + 2);
        b.extend_from_slice(b" dict begin\n");
        b.extend_from_slice(
            b"/m/moveto load def /l/lineto load def /h/closepath load def /f/fill load def\n\
              /s/stroke load def /c/setrgbcolor load def\n",
        );
        if gouraud {
            b.extend_from_slice(
                b"/g{<< exch /DataSource exch /ShadingType 4 /ColorSpace /DeviceRGB >> shfill}def\n",
            );
        }
        for (k, t) in picture.textures.iter().enumerate() {
            let (rgb, tw, th) = texture_images::rgb_rows(t);
            let mask = texture_mask::shown_rects_y_up(t);
            eps_texture::write_definition(b, k as u32, &rgb, (tw, th), mask.as_deref());
        }
        if w.seams {
            // Fill, then stroke the same path in the fill colour (closing seams).
            b.extend_from_slice(b"/F{gsave f grestore gsave 1 setlinejoin ");
            push_num(b, picture.seams, w.d);
            b.extend_from_slice(b" setlinewidth s grestore newpath}def\n");
        }
        let outline = checked.outline.map(|ol| {
            let c = flatten(
                [ol.color[0], ol.color[1], ol.color[2]],
                ol.color[3],
                backdrop,
            );
            (ol, w.quantise(c))
        });
        if let Some((ol, _)) = outline {
            b.extend_from_slice(b"1 setlinecap 1 setlinejoin ");
            push_num(b, ol.width, w.d);
            b.extend_from_slice(b" setlinewidth\n");
        }
        if let Some(bg) = picture.background {
            if alpha_milli(bg[3]) < 1000 {
                stats.approximated += 1;
            }
            let q = w.quantise(backdrop);
            w.set_color(b, q);
            b.extend_from_slice(b"0 0 ");
            push_uint(b, picture.width.into());
            b.push(b' ');
            push_uint(b, picture.height.into());
            b.extend_from_slice(b" rectfill\n");
        }

        let cd = o.color_decimals;
        let key = move |f: &Frag<'_>| {
            let a = alpha_milli(f.alpha());
            if let Some(t) = &f.src.texture {
                return Style::Textured(t.texture, f.flat_rgb().map(|v| channel_fixed(v, cd)), a);
            }
            match f.colors {
                Some(_) => Style::Gouraud(a),
                None if a == 0 => Style::Flat(None),
                None => Style::Flat(Some(
                    flatten(f.flat_rgb(), f.alpha(), backdrop).map(|v| channel_fixed(v, cd)),
                )),
            }
        };
        let means: Vec<[f64; 3]> = picture.textures.iter().map(|t| t.mean()).collect();
        let state = RefCell::new((sink, w, stats));
        let on_run = |run: &[Frag<'_>], &style: &Style| {
            let mut st = state.borrow_mut();
            let (sink, w, stats) = &mut *st;
            let b = &mut sink.buf;
            match style {
                Style::Flat(Some(q)) => w.flat_run(b, run, q),
                Style::Flat(None) => {}
                Style::Gouraud(a) => w.gouraud_run(b, run, f64::from(a) / 1000.0),
                Style::Textured(k, _, a) => {
                    // Fill × texture, flattened onto the backdrop: a·fill·t + (1 − a)·B.
                    let a = f64::from(a) / 1000.0;
                    let fill = run[0].flat_rgb();
                    let lo = [0, 1, 2].map(|i| (1.0 - a) * backdrop[i]);
                    let hi = [0, 1, 2].map(|i| lo[i] + a * fill[i].clamp(0.0, 1.0));
                    let m = means[k as usize];
                    let mean = flatten([0, 1, 2].map(|i| fill[i] * m[i]), a, backdrop);
                    let decode = (w.quantise(lo), w.quantise(hi));
                    let mean = w.quantise(mean);
                    stats.approximated += w.textured_run(b, run, k, decode, mean);
                    // A blended texture's alpha: not drawn (no soft alpha).
                    if picture.textures[k as usize].alpha() == TextureAlpha::Blend {
                        stats.approximated += run.len();
                    }
                    // Smoothly lit: each fragment in the mean of its corners' colours
                    // (PostScript has no blend mode to multiply a shading over an
                    // image).
                    stats.approximated += run
                        .iter()
                        .filter(|f| {
                            f.colors
                                .as_ref()
                                .is_some_and(|cs| cs.iter().any(|c| *c != cs[0]))
                        })
                        .count();
                }
            }
            stats.paths += usize::from(style != Style::Flat(None));
            stats.approximated += run
                .iter()
                .filter(|f| (1..1000).contains(&alpha_milli(f.alpha())))
                .count();
            if let Some((ol, q)) = outline {
                if run.iter().any(Frag::has_outline) {
                    w.set_color(b, q);
                    w.outline(b, run);
                    stats.strokes += 1;
                    stats.approximated += usize::from(alpha_milli(ol.color[3]) < 1000);
                }
            }
            sink.maybe_flush()?;
            Ok(())
        };
        let on_mark = |m: &super::Mark| {
            let mut st = state.borrow_mut();
            let (sink, w, stats) = &mut *st;
            let mut marks = EpsMarks {
                w,
                b: &mut sink.buf,
                approximated: false,
            };
            paint_mark(m, &checked.guard, &mut marks, stats)?;
            stats.approximated += usize::from(marks.approximated);
            sink.maybe_flush()?;
            Ok(())
        };
        let counts = walk_with_marks(
            picture,
            &checked.guard,
            checked.runs(),
            key,
            on_run,
            on_mark,
        )?;
        let (mut sink, _, mut stats) = state.into_inner();
        sink.buf.extend_from_slice(b"end\nshowpage\n%%EOF\n");
        stats.skipped += counts.skipped;
        stats.clipped += counts.clipped;
        stats.bytes = sink.finish()?;
        Ok(stats)
    }
}

/// Marks as PostScript.
struct EpsMarks<'a> {
    w: &'a Writer,
    b: &'a mut Vec<u8>,
    /// Whether the mark's colour was flattened (a mark counts once however many paths).
    approximated: bool,
}

impl EpsMarks<'_> {
    /// `gsave` and the mark's colour, flattened onto the backdrop when translucent.
    fn begin(&mut self, color: [f64; 4]) {
        let a = alpha_milli(color[3]);
        if a < 1000 {
            self.approximated = true;
        }
        let c = flatten([color[0], color[1], color[2]], color[3], self.w.backdrop);
        self.b.extend_from_slice(b"gsave ");
        for v in self.w.quantise(c) {
            push_fixed(self.b, v, self.w.cd);
            self.b.push(b' ');
        }
        self.b.extend_from_slice(b"c ");
    }

    fn width(&mut self, w: f64) {
        push_num(self.b, w, self.w.d);
        self.b.extend_from_slice(b" setlinewidth ");
    }
}

impl MarkSink for EpsMarks<'_> {
    fn polylines(
        &mut self,
        lines: &[Vec<[f64; 2]>],
        closed: bool,
        color: [f64; 4],
        width: f64,
        dash: &[f64],
        offset: f64,
    ) -> Result<(), PaintError> {
        self.begin(color);
        self.width(width);
        self.b.extend_from_slice(b"0 setlinecap 1 setlinejoin ");
        if !dash.is_empty() {
            self.b.push(b'[');
            for (i, &v) in dash.iter().enumerate() {
                if i > 0 {
                    self.b.push(b' ');
                }
                push_num(self.b, v, self.w.d);
            }
            self.b.extend_from_slice(b"] ");
            push_num(self.b, offset, self.w.d);
            self.b.extend_from_slice(b" setdash ");
        }
        self.b.push(b'\n');
        for line in lines {
            for (k, &p) in line.iter().enumerate() {
                self.w.point(self.b, p);
                self.b
                    .extend_from_slice(if k == 0 { b" m " } else { b" l " });
            }
            if closed {
                self.b.extend_from_slice(b"h ");
            }
        }
        self.b.extend_from_slice(b"s grestore\n");
        Ok(())
    }

    fn circle(
        &mut self,
        c: [f64; 2],
        r: f64,
        color: [f64; 4],
        stroke: Option<f64>,
    ) -> Result<(), PaintError> {
        self.begin(color);
        if let Some(w) = stroke {
            self.width(w);
        }
        let (start, quarters) = circle_beziers(c, r);
        self.w.point(self.b, start);
        self.b.extend_from_slice(b" m");
        for q in quarters {
            for p in q {
                self.b.push(b' ');
                self.w.point(self.b, p);
            }
            self.b.extend_from_slice(b" curveto");
        }
        self.b.extend_from_slice(if stroke.is_some() {
            b" h s grestore\n"
        } else {
            b" h f grestore\n"
        });
        Ok(())
    }

    fn triangle(&mut self, points: [[f64; 2]; 3], color: [f64; 4]) -> Result<(), PaintError> {
        self.begin(color);
        for (k, p) in points.into_iter().enumerate() {
            self.w.point(self.b, p);
            self.b
                .extend_from_slice(if k == 0 { b" m " } else { b" l " });
        }
        self.b.extend_from_slice(b"h f grestore\n");
        Ok(())
    }

    fn text(&mut self, origin: [f64; 2], label: &Label) -> Result<bool, PaintError> {
        let (text, changed) = ascii_text(&label.text);
        self.begin(label.color);
        self.b.extend_from_slice(b"/Helvetica findfont ");
        push_num(self.b, label.size, self.w.d);
        self.b.extend_from_slice(b" scalefont setfont ");
        self.w.point(self.b, origin);
        self.b.extend_from_slice(b" moveto (");
        push_ps_string(self.b, &text);
        self.b.extend_from_slice(b") show grestore\n");
        Ok(changed)
    }
}
