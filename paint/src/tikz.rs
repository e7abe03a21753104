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
//! \end{tikzpicture}
//! ```
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

use std::collections::HashMap;
use std::io::Write;

use super::number::{alpha_milli, push_milli, push_num, push_uint, rgb_u8, Sink};
use super::runs::{check, reversals, walk, Frag};
use super::{PaintError, PaintStats, Painter, Picture};

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
        let checked = check(picture)?;
        check_tex_limits(picture, checked.outline.map_or(0.0, |o| o.width))?;
        let d = self.options.decimals;
        let mut sink = Sink::new(out);
        let mut stats = PaintStats::default();
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

        let outline = checked.outline.map(|o| {
            (
                rgb_u8([o.color[0], o.color[1], o.color[2]]),
                alpha_milli(o.color[3]),
                o.width,
            )
        });
        let mut object: Option<u32> = None;
        let counts = walk(picture, &checked.guard, style_key, |run, &(rgb, alpha)| {
            let b = &mut sink.buf;
            let o = run[0].src.object;
            if object != Some(o) {
                push_object_comment(b, picture.objects.get(o as usize));
                object = Some(o);
            }
            let id = palette.name(b, rgb);
            let stroked = seams > 0.0 && alpha >= 1000;
            let mut points = 0;
            let mut open = false;
            for (f, reverse) in run.iter().zip(reversals(run)) {
                if open && points + f.points.len() > MAX_POINTS_PER_FILL {
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
                for p in f.oriented(reverse) {
                    b.push(b' ');
                    push_point(b, p, d);
                    b.extend_from_slice(b" --");
                }
                b.extend_from_slice(b" cycle");
                points += f.points.len();
            }
            b.extend_from_slice(b";\n");
            stats.paths += 1;
            stats.approximated += run.iter().filter(|f| f.colors.is_some()).count();

            if let Some((orgb, oalpha, owidth)) = outline {
                if run.iter().any(Frag::has_outline) {
                    let oid = palette.name(b, orgb);
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
                    stats.strokes += 1;
                }
            }
            sink.maybe_flush()?;
            Ok(())
        })?;
        sink.buf.extend_from_slice(b"\\end{tikzpicture}\n");
        if self.options.standalone {
            sink.buf.extend_from_slice(b"\\end{document}\n");
        }
        stats.skipped = counts.skipped;
        stats.clipped = counts.clipped;
        stats.bytes = sink.finish()?;
        Ok(stats)
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
}
