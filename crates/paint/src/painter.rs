//! The one trait every writer implements, and what a writer reports.

use std::io::Write;

use crate::{
    EpsPainter, Format, PaintError, PdfPainter, Picture, PngPainter, SvgPainter, TikzPainter,
};

/// What a painter did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub struct PaintStats {
    /// Filled paths written: one per run of merged fragments (see the module docs).
    pub paths: usize,
    /// Bytes written to the output.
    pub bytes: u64,
    /// Outline paths written (at most one per filled path).
    pub strokes: usize,
    /// Invalid fragments that were not painted (see the module docs).
    pub skipped: usize,
    /// Fragments clipped to the guard box or dropped outside it.
    pub clipped: usize,
    /// Fragments (and outline paths) the format could only approximate: translucency in
    /// EPS, Gouraud shading in TikZ.
    pub approximated: usize,
    /// Textured fragments filled with their fill times the texture's mean colour, by
    /// formats that draw no images here (EPS, TikZ).
    pub textures_flattened: usize,
    /// Line pieces stroked (marks of kind [`crate::MarkKind::Line`]).
    pub lines: usize,
    /// Markers drawn.
    pub markers: usize,
    /// Labels written.
    pub labels: usize,
    /// Arrow heads filled.
    pub heads: usize,
}

/// Writes a [`Picture`] in one format.
pub trait Painter {
    /// Paints `picture` to `out`, fragments in order, and reports what was written.
    fn paint(&self, picture: &Picture, out: &mut dyn Write) -> Result<PaintStats, PaintError>;
}

/// A painter for `format` with default options.
pub fn painter_for(format: Format) -> Box<dyn Painter> {
    match format {
        Format::Svg => Box::new(SvgPainter::default()),
        Format::Pdf => Box::new(PdfPainter::default()),
        Format::Eps => Box::new(EpsPainter::default()),
        Format::Png => Box::new(PngPainter::default()),
        Format::Tikz => Box::new(TikzPainter::default()),
    }
}
