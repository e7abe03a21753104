//! TikZ/PGF, written directly as text, for LaTeX documents.
//!
//! Layout of the output (one command per line):
//!
//! ```text
//! % limn picture, W x H px (1 px = 1 bp); needs \usepackage{tikz}
//! \begin{tikzpicture}[x=1bp,y=-1bp,line cap=round,line join=round]
//! \useasboundingbox (0,0) rectangle (W,H);
//! \definecolor{limn0}{RGB}{51,102,153}                 (once, before its first use)
//! \fill[limn0] (0,0) rectangle (W,H);                   (only with a background)
//! % object: name                                        (one per run of the same object)
//! \fill[limn0] (10,10) -- (90,10) -- (50,80) -- cycle;
//! \draw[limn1,line width=1] (10,10) -- (90,10);         (outline of the path above)
//! \draw[limn2,line width=1.5bp,line cap=butt,dash pattern=on 4bp off 2bp] (1,2) -- (3,4);
//! \fill[limn2] (20,20) circle[radius=2];                (a dot marker)
//! \node[anchor=south west,inner sep=0pt,text=limn3,font=…] at (72,67) {text};
//! \end{tikzpicture}
//! ```
//!
//! Marks (line pieces, markers, arrow heads, labels) are painted at their place among
//! the fills, as in every format. A label is a node placed by its anchor, so LaTeX
//! typesets it in the document's font at the label's size; its text is escaped so that
//! it prints as given (`%`, `_`, `&`, `{`, `}`, `#`, `$`, `\`, `~`, `^`, `<`, `>`, `|`).
//!
//! Coordinates are the picture's pixel coordinates, written as they are: the picture's
//! options make one unit one PostScript point (`bp`, the unit of PDF) and turn y down, so
//! a W × H px picture is W × H bp on the page, exactly the size of the PDF writer's page.
//! Colours are 8-bit RGB as in SVG, each defined once with `\definecolor` right before its
//! first use; opacity becomes `fill opacity` / `draw opacity` (three decimals). The fill
//! rule is TikZ's default, non-zero, so the subpaths of a run (oriented alike) fill their
//! union as in the other formats. Long runs are filled in pieces of at most 1000 points to
//! stay within TeX's memory.
//!
//! TikZ has no Gouraud shading of arbitrary triangles: a fragment with vertex colours is
//! filled with their mean, as in SVG, and counted in [`PaintStats::approximated`].
//!
//! TeX lengths end at 16383.99 pt. Every coordinate lies in the guard box (the page grown
//! by `max(W, H)` and twice the outline width on each side), so pages are limited to
//! [`MAX_TIKZ_SIDE`] px on a side and outlines to [`MAX_TIKZ_STROKE`] px; larger ones are
//! refused with [`PaintError::Size`] or [`PaintError::Style`] rather than written as a
//! file TeX cannot typeset.
//!
//! With [`TikzOptions::standalone`] the picture is wrapped in a document of the
//! `standalone` class, which `pdflatex` or `lualatex` compiles as it is.

use std::cell::RefCell;
use std::collections::HashMap;
use std::io::Write;

use super::marks::{paint_mark, MarkSink};
use super::merge;
use super::number::{alpha_milli, push_milli, push_num, push_scaled, push_uint, rgb_u8, Sink};
use super::runs::{check, reversals, walk_with_marks, Frag};
use super::{Label, Mark, PaintError, PaintStats, Painter, Picture};

/// The largest page side, in pixels, that TikZ output accepts: three times it (the guard
/// box) stays below TeX's largest length.
pub const MAX_TIKZ_SIDE: u32 = 5000;

/// The widest outline, in pixels, that TikZ output accepts.
pub const MAX_TIKZ_STROKE: f64 = 100.0;

const MAX_POINTS_PER_FILL: usize = 1000;

/// Options for [`TikzPainter`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TikzOptions {
    /// Maximal decimals for coordinates and line widths. Default 2; at most 9.
    pub decimals: u8,
    /// Wrap the picture in a complete LaTeX document (`standalone` class). Default off:
    /// the output is one `tikzpicture` environment for `\input`.
    pub standalone: bool,
}

impl Default for TikzOptions {
    fn default() -> Self {
        TikzOptions {
            decimals: 2,
            standalone: false,
        }
    }
}

/// Writes a TikZ picture (PGF commands through TikZ's front end).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TikzPainter {
    /// How numbers are written and whether a document wraps the picture.
    pub options: TikzOptions,
}

impl TikzPainter {
    /// A painter with the given options.
    pub fn new(options: TikzOptions) -> Self {
        TikzPainter { options }
    }
}

/// What makes two fragments' fills identical in TikZ.
fn style_key(f: &Frag<'_>) -> ([u8; 3], u16) {
    (rgb_u8(f.flat_rgb()), alpha_milli(f.alpha()))
}

/// Colour names, each defined once before its first use.
#[derive(Default)]
struct Palette {
    names: HashMap<[u8; 3], usize>,
}

impl Palette {
    /// The number of the colour `rgb`, defining it first if it is new.
    fn name(&mut self, b: &mut Vec<u8>, rgb: [u8; 3]) -> usize {
        let next = self.names.len();
        let id = *self.names.entry(rgb).or_insert(next);
        if id == next {
            b.extend_from_slice(b"\\definecolor{limn");
            push_uint(b, id as u64);
            b.extend_from_slice(b"}{RGB}{");
            for (k, c) in rgb.iter().enumerate() {
                if k > 0 {
                    b.push(b',');
                }
                push_uint(b, u64::from(*c));
            }
            b.extend_from_slice(b"}\n");
        }
        id
    }
}

fn push_color_name(b: &mut Vec<u8>, id: usize) {
    b.extend_from_slice(b"limn");
    push_uint(b, id as u64);
}

fn push_point(b: &mut Vec<u8>, p: [f64; 2], d: u8) {
    b.push(b'(');
    push_num(b, p[0], d);
    b.push(b',');
    push_num(b, p[1], d);
    b.push(b')');
}

/// `, key=0.5` when the opacity is below 1.
fn opacity_option(b: &mut Vec<u8>, key: &[u8], milli: u16) {
    if milli < 1000 {
        b.extend_from_slice(b",");
        b.extend_from_slice(key);
        b.push(b'=');
        push_milli(b, milli);
    }
}

/// Checks the limits TeX's lengths put on the page and the strokes.
fn check_tex_limits(picture: &Picture, outline_width: f64) -> Result<(), PaintError> {
    if picture.width > MAX_TIKZ_SIDE || picture.height > MAX_TIKZ_SIDE {
        return Err(PaintError::Size {
            width: picture.width,
            height: picture.height,
            reason:
                "TeX lengths end at 16383 pt, so a TikZ picture can be at most 5000 px on a side",
        });
    }
    if outline_width > MAX_TIKZ_STROKE {
        return Err(PaintError::Style {
            what: "outline",
            reason: "width must be at most 100 px in TikZ output (TeX lengths end at 16383 pt)",
        });
    }
    Ok(())
}

impl Painter for TikzPainter {
    fn paint(&self, picture: &Picture, out: &mut dyn Write) -> Result<PaintStats, PaintError> {
        // Textures are drawn as their mean colour here (counted in the stats).
        let (picture, flattened) = picture.untextured();
        let picture: &Picture = &picture;
        let checked = check(picture)?;
        check_tex_limits(picture, checked.outline.map_or(0.0, |o| o.width))?;
        let d = self.options.decimals;
        let mut sink = Sink::new(out);
        let stats = PaintStats::default();
        let mut palette = Palette::default();
        let seams = if picture.seams.is_finite() && picture.seams > 0.0 {
            picture.seams.min(MAX_TIKZ_STROKE)
        } else {
            0.0
        };

        let b = &mut sink.buf;
        if self.options.standalone {
            b.extend_from_slice(b"\\documentclass[tikz]{standalone}\n\\begin{document}\n");
        }
        b.extend_from_slice(b"% limn picture, ");
        push_uint(b, picture.width.into());
        b.extend_from_slice(b" x ");
        push_uint(b, picture.height.into());
        b.extend_from_slice(b" px (1 px = 1 bp)");
        if !self.options.standalone {
            b.extend_from_slice(b"; needs \\usepackage{tikz}");
        }
        b.extend_from_slice(b"\n\\begin{tikzpicture}[x=1bp,y=-1bp,line cap=round,line join=round");
        // The picture carries the width of the most frequent strokes: the seam strokes
        // when there are any (outlines then say their own width), else the outlines.
        if seams > 0.0 {
            b.extend_from_slice(b",line width=");
            push_num(b, seams, d);
            b.extend_from_slice(b"bp");
        } else if let Some(o) = checked.outline {
            b.extend_from_slice(b",line width=");
            push_num(b, o.width, d);
            b.extend_from_slice(b"bp");
        }
        b.extend_from_slice(b"]\n\\useasboundingbox (0,0) rectangle ");
        push_point(b, [picture.width.into(), picture.height.into()], d);
        b.extend_from_slice(b";\n");
        if let Some(bg) = picture.background {
            let id = palette.name(b, rgb_u8([bg[0], bg[1], bg[2]]));
            b.extend_from_slice(b"\\fill[");
            push_color_name(b, id);
            opacity_option(b, b"fill opacity", alpha_milli(bg[3]));
            b.extend_from_slice(b"] (0,0) rectangle ");
            push_point(b, [picture.width.into(), picture.height.into()], d);
            b.extend_from_slice(b";\n");
        }

        let merge_pieces = picture.merge_pieces;
        let outline = checked.outline.map(|o| {
            (
                rgb_u8([o.color[0], o.color[1], o.color[2]]),
                alpha_milli(o.color[3]),
                o.width,
            )
        });
        let state = RefCell::new(State {
            sink,
            stats,
            palette,
            object: None,
        });
        let on_run = |run: &[Frag<'_>], &(rgb, alpha): &([u8; 3], u16)| {
            let mut st = state.borrow_mut();
            let st = &mut *st;
            st.enter(picture, run[0].src.object);
            let b = &mut st.sink.buf;
            let id = st.palette.name(b, rgb);
            let stroked = seams > 0.0 && alpha >= 1000;
            let mut points = 0;
            let mut open = false;
            // Starts a new fill when `n` more corners would make the current one too long.
            let mut start = |b: &mut Vec<u8>, n: usize| {
                if open && points + n > MAX_POINTS_PER_FILL {
                    b.extend_from_slice(b";\n");
                    open = false;
                    points = 0;
                }
                if !open {
                    b.extend_from_slice(if stroked { b"\\filldraw[" } else { b"\\fill[" });
                    push_color_name(b, id);
                    opacity_option(b, b"fill opacity", alpha);
                    b.push(b']');
                    open = true;
                }
                points += n;
            };
            let merged = merge::run_shapes(run, d, merge_pieces, |p| p)
                .filter(|shapes| !(shapes.is_empty() && stroked));
            match merged {
                // Fills no point: no fill.
                Some(shapes) if shapes.is_empty() => {}
                Some(shapes) => {
                    // A shape's outer ring and holes go in one fill.
                    for shape in &shapes {
                        start(b, merge::corners(shape));
                        for ring in shape {
                            for p in ring {
                                b.extend_from_slice(b" (");
                                push_scaled(b, p[0], d);
                                b.push(b',');
                                push_scaled(b, p[1], d);
                                b.extend_from_slice(b") --");
                            }
                            b.extend_from_slice(b" cycle");
                        }
                    }
                }
                None => {
                    for (f, reverse) in run.iter().zip(reversals(run)) {
                        start(b, f.points.len());
                        for p in f.oriented(reverse) {
                            b.push(b' ');
                            push_point(b, p, d);
                            b.extend_from_slice(b" --");
                        }
                        b.extend_from_slice(b" cycle");
                    }
                }
            }
            if open {
                b.extend_from_slice(b";\n");
                st.stats.paths += 1;
            }
            st.stats.approximated += run.iter().filter(|f| f.colors.is_some()).count();

            if let Some((orgb, oalpha, owidth)) = outline {
                if run.iter().any(Frag::has_outline) {
                    let oid = st.palette.name(b, orgb);
                    b.extend_from_slice(b"\\draw[");
                    push_color_name(b, oid);
                    opacity_option(b, b"draw opacity", oalpha);
                    if seams > 0.0 {
                        b.extend_from_slice(b",line width=");
                        push_num(b, owidth, d);
                        b.extend_from_slice(b"bp");
                    }
                    b.push(b']');
                    for f in run {
                        push_outline(b, f, d);
                    }
                    b.extend_from_slice(b";\n");
                    st.stats.strokes += 1;
                }
            }
            st.sink.maybe_flush()?;
            Ok(())
        };
        let on_mark = |m: &Mark| {
            let mut st = state.borrow_mut();
            let st = &mut *st;
            st.enter(picture, m.object);
            let mut marks = TikzMarks {
                b: &mut st.sink.buf,
                palette: &mut st.palette,
                d,
            };
            paint_mark(m, &checked.guard, &mut marks, &mut st.stats)?;
            st.sink.maybe_flush()?;
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
        let State {
            mut sink,
            mut stats,
            ..
        } = state.into_inner();
        sink.buf.extend_from_slice(b"\\end{tikzpicture}\n");
        if self.options.standalone {
            sink.buf.extend_from_slice(b"\\end{document}\n");
        }
        stats.skipped += counts.skipped;
        stats.clipped += counts.clipped;
        stats.bytes = sink.finish()?;
        stats.textures_flattened = flattened;
        Ok(stats)
    }
}

/// What the closures of [`TikzPainter::paint`] share.
struct State<'w> {
    sink: Sink<'w>,
    stats: PaintStats,
    palette: Palette,
    /// The object of the last thing written.
    object: Option<u32>,
}

impl State<'_> {
    /// Writes the object comment when `object` differs from the last one.
    fn enter(&mut self, picture: &Picture, object: u32) {
        if self.object != Some(object) {
            push_object_comment(&mut self.sink.buf, picture.objects.get(object as usize));
            self.object = Some(object);
        }
    }
}

/// `% object: name`, the name on one line (line breaks become spaces).
fn push_object_comment(b: &mut Vec<u8>, name: Option<&String>) {
    b.extend_from_slice(b"% object:");
    if let Some(name) = name {
        b.push(b' ');
        for c in name.chars() {
            let c = if c.is_control() { ' ' } else { c };
            let mut utf8 = [0; 4];
            b.extend_from_slice(c.encode_utf8(&mut utf8).as_bytes());
        }
    }
    b.push(b'\n');
}

/// The original edges of `f` as open subpaths (one closed subpath when all are original).
fn push_outline(b: &mut Vec<u8>, f: &Frag<'_>, d: u8) {
    let n = f.points.len();
    f.polylines(|start, edges, closed| {
        let last = if closed { edges - 1 } else { edges };
        for k in 0..=last {
            b.extend_from_slice(if k == 0 { b" " } else { b" -- " });
            push_point(b, f.points[(start + k) % n], d);
        }
        if closed {
            b.extend_from_slice(b" -- cycle");
        }
    });
}

/// Marks as TikZ commands.
struct TikzMarks<'b> {
    b: &'b mut Vec<u8>,
    palette: &'b mut Palette,
    d: u8,
}

impl TikzMarks<'_> {
    /// `[limnK,opacity option` for a paint of `color` (the caller closes the bracket).
    fn open(&mut self, command: &[u8], color: [f64; 4], opacity: &[u8]) {
        let id = self
            .palette
            .name(self.b, rgb_u8([color[0], color[1], color[2]]));
        self.b.extend_from_slice(command);
        self.b.push(b'[');
        push_color_name(self.b, id);
        opacity_option(self.b, opacity, alpha_milli(color[3]));
    }

    fn line_width(&mut self, width: f64) {
        self.b.extend_from_slice(b",line width=");
        push_num(self.b, width, self.d);
        self.b.extend_from_slice(b"bp");
    }
}

/// Appends `text` so that LaTeX prints it as given: its special characters escaped,
/// control characters as spaces.
fn push_latex_text(b: &mut Vec<u8>, text: &str) {
    for c in text.chars() {
        let escaped: &[u8] = match c {
            '\\' => b"\\textbackslash{}",
            '#' => b"\\#",
            '$' => b"\\$",
            '%' => b"\\%",
            '&' => b"\\&",
            '_' => b"\\_",
            '{' => b"\\{",
            '}' => b"\\}",
            '^' => b"\\textasciicircum{}",
            '~' => b"\\textasciitilde{}",
            '<' => b"\\textless{}",
            '>' => b"\\textgreater{}",
            '|' => b"\\textbar{}",
            c if c.is_control() => b" ",
            c => {
                let mut utf8 = [0; 4];
                b.extend_from_slice(c.encode_utf8(&mut utf8).as_bytes());
                continue;
            }
        };
        b.extend_from_slice(escaped);
    }
}

/// Labels become nodes at their anchor, so that LaTeX typesets the text in the
/// document's font at the label's size: the anchor point is the one the other formats
/// use, the box is LaTeX's (not the Helvetica box they place).
impl MarkSink for TikzMarks<'_> {
    fn polylines(
        &mut self,
        lines: &[Vec<[f64; 2]>],
        closed: bool,
        color: [f64; 4],
        width: f64,
        dash: &[f64],
        offset: f64,
    ) -> Result<(), PaintError> {
        self.open(b"\\draw", color, b"draw opacity");
        self.line_width(width);
        self.b.extend_from_slice(b",line cap=butt");
        if !dash.is_empty() {
            self.b.extend_from_slice(b",dash pattern=");
            for (i, &v) in dash.iter().enumerate() {
                self.b
                    .extend_from_slice(if i % 2 == 0 { b"on " } else { b"off " });
                push_num(self.b, v, self.d);
                self.b
                    .extend_from_slice(if i + 1 < dash.len() { b"bp " } else { b"bp" });
            }
            if offset != 0.0 {
                self.b.extend_from_slice(b",dash phase=");
                push_num(self.b, offset, self.d);
                self.b.extend_from_slice(b"bp");
            }
        }
        self.b.push(b']');
        for line in lines {
            for (k, &p) in line.iter().enumerate() {
                self.b
                    .extend_from_slice(if k == 0 { b" " } else { b" -- " });
                push_point(self.b, p, self.d);
            }
            if closed {
                self.b.extend_from_slice(b" -- cycle");
            }
        }
        self.b.extend_from_slice(b";\n");
        Ok(())
    }

    fn circle(
        &mut self,
        c: [f64; 2],
        r: f64,
        color: [f64; 4],
        stroke: Option<f64>,
    ) -> Result<(), PaintError> {
        match stroke {
            None => self.open(b"\\fill", color, b"fill opacity"),
            Some(w) => {
                self.open(b"\\draw", color, b"draw opacity");
                self.line_width(w);
            }
        }
        self.b.extend_from_slice(b"] ");
        push_point(self.b, c, self.d);
        self.b.extend_from_slice(b" circle[radius=");
        push_num(self.b, r, self.d);
        self.b.extend_from_slice(b"];\n");
        Ok(())
    }

    fn triangle(&mut self, points: [[f64; 2]; 3], color: [f64; 4]) -> Result<(), PaintError> {
        self.open(b"\\fill", color, b"fill opacity");
        self.b.push(b']');
        for p in points {
            self.b.push(b' ');
            push_point(self.b, p, self.d);
            self.b.extend_from_slice(b" --");
        }
        self.b.extend_from_slice(b" cycle;\n");
        Ok(())
    }

    fn text(&mut self, _origin: [f64; 2], label: &Label) -> Result<bool, PaintError> {
        let c = label.color;
        let id = self.palette.name(self.b, rgb_u8([c[0], c[1], c[2]]));
        self.b.extend_from_slice(b"\\node[anchor=");
        self.b.extend_from_slice(label.anchor.name().as_bytes());
        self.b.extend_from_slice(b",inner sep=0pt,text=");
        push_color_name(self.b, id);
        opacity_option(self.b, b"text opacity", alpha_milli(c[3]));
        self.b.extend_from_slice(b",font=\\fontsize{");
        push_num(self.b, label.size, self.d);
        self.b.extend_from_slice(b"bp}{");
        push_num(self.b, 1.2 * label.size, self.d);
        self.b.extend_from_slice(b"bp}\\selectfont] at ");
        let at = [label.at[0] + label.offset[0], label.at[1] + label.offset[1]];
        push_point(self.b, at, self.d);
        self.b.extend_from_slice(b" {");
        push_latex_text(self.b, &label.text);
        self.b.extend_from_slice(b"};\n");
        Ok(false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Outline, PaintFragment};

    fn paint(picture: &Picture, options: TikzOptions) -> (PaintStats, String) {
        let mut out = Vec::new();
        let stats = TikzPainter::new(options).paint(picture, &mut out).unwrap();
        assert_eq!(stats.bytes, out.len() as u64);
        (stats, String::from_utf8(out).unwrap())
    }

    #[test]
    fn a_triangle_is_one_fill_in_a_defined_colour() {
        let mut picture = Picture::new(100, 80);
        picture.objects.push("tri".into());
        picture.fragments.push(PaintFragment::new(
            vec![[10.0, 10.0], [90.0, 10.0], [50.0, 70.5]],
            [0.2, 0.4, 0.6, 1.0],
        ));
        let (stats, text) = paint(&picture, TikzOptions::default());
        assert_eq!(stats.paths, 1);
        assert!(text.contains("\\useasboundingbox (0,0) rectangle (100,80);\n"));
        assert!(text.contains("% object: tri\n\\definecolor{limn0}{RGB}{51,102,153}\n"));
        assert!(text.contains("\\fill[limn0] (10,10) -- (90,10) -- (50,70.5) -- cycle;\n"));
        assert!(text.ends_with("\\end{tikzpicture}\n"));
        assert!(!text.contains("documentclass"));
    }

    #[test]
    fn colours_are_defined_once_and_opacity_is_an_option() {
        let mut picture = Picture::new(50, 50);
        for (face, alpha) in [(0, 1.0), (1, 0.5), (2, 1.0)] {
            let mut f = PaintFragment::new(
                vec![[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]],
                [1.0, 0.0, 0.0, alpha],
            );
            f.face = face;
            picture.fragments.push(f);
        }
        let (stats, text) = paint(&picture, TikzOptions::default());
        assert_eq!(stats.paths, 3);
        assert_eq!(text.matches("\\definecolor").count(), 1);
        assert_eq!(text.matches("\\fill[limn0,fill opacity=0.5]").count(), 1);
        assert_eq!(text.matches("\\fill[limn0] ").count(), 2);
    }

    #[test]
    fn seams_and_outlines_stroke_with_their_widths() {
        let mut picture = Picture::new(50, 50);
        picture.fragments.push(PaintFragment::new(
            vec![[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]],
            [0.0, 0.0, 0.0, 1.0],
        ));
        picture.seams = 0.35;
        picture.outline = Some(Outline {
            color: [1.0, 1.0, 1.0, 0.25],
            width: 2.0,
        });
        let (stats, text) = paint(&picture, TikzOptions::default());
        assert_eq!(stats.strokes, 1);
        assert!(text.contains("line join=round,line width=0.35bp]"));
        assert!(text.contains("\\filldraw[limn0] (0,0)"));
        assert!(text.contains(
            "\\draw[limn1,draw opacity=0.25,line width=2bp] (0,0) -- (10,0) -- (0,10) -- cycle;"
        ));
    }

    #[test]
    fn standalone_wraps_a_document() {
        let (_, text) = paint(
            &Picture::new(10, 10),
            TikzOptions {
                standalone: true,
                ..TikzOptions::default()
            },
        );
        assert!(text.starts_with("\\documentclass[tikz]{standalone}\n\\begin{document}\n"));
        assert!(text.ends_with("\\end{tikzpicture}\n\\end{document}\n"));
    }

    #[test]
    fn pages_beyond_tex_lengths_are_refused() {
        let mut out = Vec::new();
        let err = TikzPainter::default()
            .paint(&Picture::new(MAX_TIKZ_SIDE + 1, 10), &mut out)
            .unwrap_err();
        assert!(matches!(err, PaintError::Size { .. }), "{err}");
        assert!(out.is_empty());
        assert!(TikzPainter::default()
            .paint(&Picture::new(MAX_TIKZ_SIDE, 10), &mut out)
            .is_ok());
        let mut wide = Picture::new(10, 10);
        wide.outline = Some(Outline {
            color: [0.0; 4].map(|_| 1.0),
            width: 101.0,
        });
        assert!(matches!(
            TikzPainter::default().paint(&wide, &mut Vec::new()),
            Err(PaintError::Style { .. })
        ));
    }

    #[test]
    fn long_runs_are_filled_in_pieces() {
        let mut picture = Picture::new(100, 100);
        for k in 0..600 {
            let x = f64::from(k % 30) * 3.0;
            let y = f64::from(k / 30) * 3.0;
            picture.fragments.push(PaintFragment::new(
                vec![[x, y], [x + 2.0, y], [x, y + 2.0]],
                [0.5, 0.5, 0.5, 1.0],
            ));
        }
        let (stats, text) = paint(&picture, TikzOptions::default());
        assert_eq!(stats.paths, 1);
        // 1800 points: one fill of 999 points (333 triangles) and one of the rest.
        assert_eq!(text.matches("\\fill[").count(), 2);
        assert_eq!(text.matches("cycle").count(), 600);
    }

    #[test]
    fn object_names_stay_on_their_comment_line() {
        let mut picture = Picture::new(10, 10);
        picture.objects.push("two\nlines\\par".into());
        picture.fragments.push(PaintFragment::new(
            vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            [0.0, 0.0, 0.0, 1.0],
        ));
        let (_, text) = paint(&picture, TikzOptions::default());
        assert!(text.contains("% object: two lines\\par\n"));
    }

    fn marked_picture() -> Picture {
        use crate::{ArrowHead, LinePiece, LineStyle, MarkKind, Marker, MarkerShape};
        let mut picture = Picture::new(100, 100);
        picture.objects = vec!["faces".into(), "curve".into(), "dots".into(), "note".into()];
        for face in 0..2 {
            let mut f = PaintFragment::new(
                vec![[0.0, 0.0], [50.0, 0.0], [0.0, 50.0]],
                [0.5, 0.5, 0.5, 1.0],
            );
            f.face = face;
            picture.fragments.push(f);
        }
        let line = LinePiece {
            points: vec![[1.0, 2.0], [30.0, 40.0], [60.0, 40.0]],
            style: LineStyle {
                color: [1.0, 0.0, 0.0, 0.5],
                width: 1.5,
                dash: vec![4.0, 2.0],
            },
            dash_offset: 3.0,
            line: 0,
        };
        picture.marks = vec![
            Mark {
                before: 1,
                object: 1,
                kind: MarkKind::Line(line),
            },
            Mark {
                before: 2,
                object: 2,
                kind: MarkKind::Marker(Marker {
                    at: [20.0, 20.0],
                    shape: MarkerShape::Dot,
                    size: 4.0,
                    color: [0.0, 0.0, 1.0, 1.0],
                    stroke: 1.0,
                }),
            },
            Mark {
                before: 2,
                object: 3,
                kind: MarkKind::Label(Label {
                    at: [70.0, 70.0],
                    offset: [2.0, -3.0],
                    anchor: crate::LabelAnchor::SouthWest,
                    text: "50% of x_1 & {y} \\ #2".into(),
                    size: 9.0,
                    color: [0.0, 0.0, 0.0, 1.0],
                }),
            },
            Mark {
                before: 2,
                object: 1,
                kind: MarkKind::Head(ArrowHead {
                    points: [[60.0, 40.0], [55.0, 37.0], [55.0, 43.0]],
                    color: [1.0, 0.0, 0.0, 1.0],
                }),
            },
        ];
        picture
    }

    #[test]
    fn marks_are_painted_at_their_place_among_the_fills() {
        let (stats, text) = paint(&marked_picture(), TikzOptions::default());
        assert_eq!(
            (
                stats.paths,
                stats.lines,
                stats.markers,
                stats.labels,
                stats.heads
            ),
            (2, 1, 1, 1, 1)
        );
        let first_fill = text.find("\\fill[limn0]").unwrap();
        let line = text
            .find("\\draw[limn1,draw opacity=0.5,line width=1.5bp,line cap=butt,dash pattern=on 4bp off 2bp,dash phase=3bp] (1,2) -- (30,40) -- (60,40);")
            .unwrap();
        let second_fill = text[first_fill + 1..].find("\\fill[limn0]").unwrap() + first_fill + 1;
        assert!(first_fill < line && line < second_fill, "{text}");
        assert!(
            text.contains("\\fill[limn2] (20,20) circle[radius=2];"),
            "{text}"
        );
        assert!(text.contains(
            "\\node[anchor=south west,inner sep=0pt,text=limn3,font=\\fontsize{9bp}{10.8bp}\\selectfont] at (72,67) {50\\% of x\\_1 \\& \\{y\\} \\textbackslash{} \\#2};"
        ), "{text}");
        assert!(
            text.contains("\\fill[limn1] (60,40) -- (55,37) -- (55,43) -- cycle;"),
            "{text}"
        );
        assert!(text.contains("% object: curve\n") && text.contains("% object: note\n"));
    }
}
