//! Painter backends: turn an ordered list of 2D fragments into SVG, PDF, EPS or PNG.
//!
//! A [`Picture`] holds fragments in pixel coordinates (x right, y down, the page is
//! `[0, W] × [0, H]`) in painting order, back to front. Every backend implements
//! [`Painter`] and paints them in exactly that order:
//!
//! | backend | writer | Gouraud fragments | opacity < 1 |
//! |---|---|---|---|
//! | [`SvgPainter`] | text written directly | average colour (counted as approximated) | `fill-opacity` |
//! | [`PdfPainter`] | `pdf-writer` | type-4 free-form triangle-mesh shading | `ExtGState` `/ca` |
//! | [`EpsPainter`] | text written directly | `shfill` with a type-4 shading | blended with the backdrop (approximated) |
//! | [`PngPainter`] | tiny-skia, anti-aliased | interpolated per pixel | source-over blending |
//!
//! # Rules shared by every backend
//!
//! - **Colours** are written as given, with no transfer function: a channel `c` becomes
//!   `round(clamp(c, 0, 1) · 255)` in 8-bit outputs (SVG `#rrggbb`, PNG), so an `illum 0`
//!   colour (0.2, 0.4, 0.6) is `#336699` and (51, 102, 153).
//! - **Opacity** of a fragment is always `fill[3]`, rounded to three decimals; vertex colours
//!   supply red, green and blue only (their alpha is ignored).
//! - **Invalid fragments are skipped and counted** in [`PaintStats::skipped`], never painted
//!   and never an error: fewer than 3 points, a non-finite coordinate, a non-finite fill
//!   component, or `vertex_colors` whose length differs from `points` or that holds a
//!   non-finite value. `original_edges` may be shorter than `points`: missing entries mean
//!   "not an original edge"; extra entries are ignored.
//! - **Huge coordinates**: a fragment reaching outside the guard box — the page grown by
//!   `max(W, H) + 2 · outline width` on every side — is clipped to it (Sutherland–Hodgman;
//!   edges created by the clip are never outlined) and counted in [`PaintStats::clipped`].
//!   The guard box lies outside the page, so the visible picture does not change, and every
//!   number written stays small. A fragment entirely outside it is dropped (also counted as
//!   clipped); one whose clipping overflows `f64` is skipped.
//! - **Runs**: consecutive fragments with the same object, the same face and the same style
//!   (as the format writes it) are painted as one path with one subpath per fragment,
//!   oriented alike. That path counts once in [`PaintStats::paths`], and viewers and the PNG
//!   rasteriser cover it in one pass, so a face split into several fragments shows no
//!   anti-aliasing seams. The outline of a run is drawn right after the run's fill.
//! - **Outlines** ([`Picture::outline`]) stroke only the original edges of each fragment,
//!   joined into open polylines (a closed one when every edge is original), with round caps
//!   and joins. An outline of width 0 or opacity 0 draws nothing.
//! - **Numbers** in the text formats are written with a fixed maximal number of decimals
//!   (trailing zeros trimmed, never `-0`, never an exponent), so equal input gives equal
//!   bytes.
//! - **Objects**: a fragment's `object` indexes [`Picture::objects`]; an index out of range
//!   is painted as an unnamed object.
//!
//! # Example
//!
//! ```
//! use limn_depthsort::paint::{painter_for, Format, PaintFragment, Picture};
//!
//! let mut picture = Picture::new(100, 100);
//! picture.objects.push("triangle".to_string());
//! picture.fragments.push(PaintFragment::new(
//!     vec![[10.0, 10.0], [90.0, 10.0], [50.0, 80.0]],
//!     [0.2, 0.4, 0.6, 1.0],
//! ));
//! let mut svg = Vec::new();
//! let stats = painter_for(Format::Svg).paint(&picture, &mut svg)?;
//! assert_eq!(stats.paths, 1);
//! let text = String::from_utf8(svg).unwrap();
//! assert!(text.contains(r##"<path d="M10 10L90 10 50 80Z" fill="#336699"/>"##));
//! # Ok::<(), limn_depthsort::paint::PaintError>(())
//! ```

mod eps;
mod fmt;
mod pdf;
mod png;
mod prep;
mod svg;

pub use eps::{EpsOptions, EpsPainter};
pub use pdf::{PdfOptions, PdfPainter};
pub use png::{PngOptions, PngPainter};
pub use svg::{SvgOptions, SvgPainter};

use std::fmt as stdfmt;
use std::io::Write;

/// One convex (or at least simple) polygon to paint, in pixel coordinates (x right, y down).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PaintFragment {
    /// Polygon corners in order (either orientation).
    pub points: Vec<[f64; 2]>,
    /// Linear-RGB fill colour with alpha = opacity, each in [0,1].
    pub fill: [f64; 4],
    /// Optional per-vertex colours (Gouraud); same length as points.
    pub vertex_colors: Option<Vec<[f64; 4]>>,
    /// Input face id this fragment came from.
    pub face: u32,
    /// Index into Picture::objects.
    pub object: u32,
    /// Per edge i (points[i] -> points[i+1 mod n]): is it an original model edge (outlined
    /// when outlines are on)?
    pub original_edges: Vec<bool>,
}

impl PaintFragment {
    /// A flat-coloured fragment of face 0 and object 0 whose edges are all original.
    pub fn new(points: Vec<[f64; 2]>, fill: [f64; 4]) -> Self {
        let original_edges = vec![true; points.len()];
        PaintFragment {
            points,
            fill,
            vertex_colors: None,
            face: 0,
            object: 0,
            original_edges,
        }
    }
}

/// Everything a painter needs: the page, the object names and the fragments in paint order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Picture {
    /// Page width in pixels (points in PDF and EPS). Must be at least 1.
    pub width: u32,
    /// Page height in pixels (points in PDF and EPS). Must be at least 1.
    pub height: u32,
    /// Colour painted under everything, RGBA in [0, 1]; `None` leaves the page transparent
    /// (white paper in EPS).
    pub background: Option<[f64; 4]>,
    /// Object names, indexed by [`PaintFragment::object`].
    pub objects: Vec<String>,
    /// Back to front: paint in this order.
    pub fragments: Vec<PaintFragment>,
    /// Outline style; `None` = no outlines.
    pub outline: Option<Outline>,
    /// Width in pixels of a stroke in its own colour around every opaque flat fill in
    /// the vector formats (SVG, PDF, EPS); 0 = none. Viewers anti-alias each path on
    /// its own, so where two polygons meet both edge pixels are only partly covered and
    /// the background shows through as a hairline; a stroke of half a pixel or less
    /// closes it, at the price of growing every fill by half the width. PNG does not need
    /// it (it is supersampled). Default 0.
    pub seams: f64,
}

impl Picture {
    /// An empty picture of the given size: no background, objects, fragments or outlines.
    pub fn new(width: u32, height: u32) -> Self {
        Picture {
            width,
            height,
            ..Picture::default()
        }
    }
}

/// How original model edges are stroked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outline {
    /// Stroke colour, RGBA in [0, 1] (alpha = opacity).
    pub color: [f64; 4],
    /// Stroke width in pixels; must be finite and non-negative (0 draws nothing).
    pub width: f64,
}

/// An output file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// Scalable Vector Graphics.
    Svg,
    /// Portable Document Format, one page.
    Pdf,
    /// Encapsulated PostScript.
    Eps,
    /// Portable Network Graphics (a raster).
    Png,
}

impl Format {
    /// Every format, in a fixed order.
    pub const ALL: [Format; 4] = [Format::Svg, Format::Pdf, Format::Eps, Format::Png];

    /// The format of a file extension (`"svg"`, `".PDF"`, `"eps"`, `"ps"`, `"png"`; any case,
    /// with or without the dot).
    pub fn from_extension(ext: &str) -> Option<Format> {
        let ext = ext.strip_prefix('.').unwrap_or(ext);
        if ext.eq_ignore_ascii_case("ps") {
            return Some(Format::Eps);
        }
        Format::from_name(ext)
    }

    /// The format called `name` (`"svg"`, `"pdf"`, `"eps"` or `"png"`, any case).
    pub fn from_name(name: &str) -> Option<Format> {
        Format::ALL
            .into_iter()
            .find(|f| f.name().eq_ignore_ascii_case(name))
    }

    /// The lower-case name, which is also the usual file extension.
    pub fn name(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Pdf => "pdf",
            Format::Eps => "eps",
            Format::Png => "png",
        }
    }
}

impl stdfmt::Display for Format {
    fn fmt(&self, f: &mut stdfmt::Formatter<'_>) -> stdfmt::Result {
        f.write_str(self.name())
    }
}

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
    /// EPS, Gouraud shading in SVG.
    pub approximated: usize,
}

/// Why a picture could not be painted.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PaintError {
    /// Writing to the output failed.
    #[error("cannot write the picture: {0}")]
    Io(#[from] std::io::Error),
    /// The page size cannot be painted.
    #[error("picture size {width}x{height} is not supported: {reason}")]
    Size {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A picture-wide style value is unusable.
    #[error("invalid {what}: {reason}")]
    Style {
        /// Which value (`"background"`, `"outline"`).
        what: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The PNG encoder failed.
    #[error("cannot encode the PNG: {0}")]
    Png(String),
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
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_names_and_extensions() {
        assert_eq!(Format::from_extension(".SVG"), Some(Format::Svg));
        assert_eq!(Format::from_extension("ps"), Some(Format::Eps));
        assert_eq!(Format::from_extension("Png"), Some(Format::Png));
        assert_eq!(Format::from_extension("jpg"), None);
        assert_eq!(Format::from_name("ps"), None);
        for f in Format::ALL {
            assert_eq!(Format::from_name(&f.to_string()), Some(f));
            assert_eq!(Format::from_extension(f.name()), Some(f));
        }
    }
}
