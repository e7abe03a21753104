//! limn's painters: the picture model, shading of ordered fragments, and the writers that
//! turn it into SVG, PDF, EPS, PNG or TikZ.
//!
//! [`picture()`] turns the fragments `limn-depthsort` ordered into a [`Picture`] (flat or
//! Gouraud shading per face, only the effects the scene asks for, whole-face covers and
//! seam flaps); a [`Painter`] writes it.
//!
//! A [`Picture`] holds fragments in pixel coordinates (x right, y down, the page is
//! `[0, W] × [0, H]`) in painting order, back to front. Every backend implements
//! [`Painter`] and paints them in exactly that order:
//!
//! | backend | writer | Gouraud fragments | opacity < 1 |
//! |---|---|---|---|
//! | [`SvgPainter`] | text written directly | linear gradients and flat pieces within a tolerance | `fill-opacity` |
//! | [`PdfPainter`] | `pdf-writer` | type-4 free-form triangle-mesh shading | `ExtGState` `/ca` |
//! | [`EpsPainter`] | text written directly | `shfill` with a type-4 shading | blended with the backdrop (approximated) |
//! | [`PngPainter`] | tiny-skia, anti-aliased | interpolated per pixel | source-over blending |
//! | [`TikzPainter`] | text written directly | average colour (counted as approximated) | `fill opacity` |
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
//! - **Marks** ([`Picture::marks`]: visible line pieces, markers, labels, arrow heads) are
//!   painted between the fragments at their [`Mark::before`] position (see [`Picture`]);
//!   a run of fragments never spans a mark. Line pieces are stroked with butt caps and
//!   round joins, dashed from their `dash_offset`; markers are drawn whole, centred on
//!   their anchor; labels are one line of text in a standard sans-serif font (SVG
//!   `<text>`, PDF and EPS Helvetica, PNG a bundled font); arrow heads are filled
//!   triangles. Invalid marks (non-finite numbers, fewer than two points, a width or size
//!   that is not positive) are skipped and counted in [`PaintStats::skipped`].
//! - **Objects**: a fragment's `object` indexes [`Picture::objects`]; an index out of range
//!   is painted as an unnamed object.
//!
//! # Example
//!
//! ```
//! use limn_paint::{painter_for, Format, PaintFragment, Picture};
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
//! # Ok::<(), limn_paint::PaintError>(())
//! ```

mod annotate;
mod chunked_queue;
mod compose;
mod covers;
mod eps;
mod eps_texture;
mod error;
mod face_outlines;
mod format;
mod hidden_line;
mod layers;
mod marks;
mod merge;
mod model;
mod number;
mod painter;
mod pdf;
mod pdf_objects;
mod pdf_texture;
pub mod phong;
mod png;
mod runs;
mod seams;
mod seams_across;
mod smooth;
mod snap;
mod svg;
mod svg_smooth;
mod svg_smooth_run;
mod svg_texture;
mod texture_bake;
mod texture_collapse;
mod texture_images;
mod texture_levels;
mod texture_mask;
mod texture_page;
mod texture_patches;
mod texture_pieces;
mod texturing;
mod tikz;

pub use annotate::{
    add_seam_flaps, add_seam_flaps_beside_strokes, head_length, marker_stroke, picture_with_marks,
    picture_with_marks_unflapped,
};
pub use compose::{picture, Style};
pub use covers::covers;
pub use eps::{EpsOptions, EpsPainter};
pub use error::PaintError;
pub use format::Format;
pub use hidden_line::{hidden_line_picture, HiddenLineStyle};
pub use merge::union_of_polygons;
pub use model::{
    narrow_color, wide_color, ArrowHead, Label, LabelAnchor, LinePiece, LineStyle, Mark, MarkKind,
    Marker, MarkerShape, Outline, PageImage, PaintFragment, Picture, Texture, TextureAlpha,
    TextureMap, VertexColor,
};
pub use painter::{painter_for, PaintStats, Painter};
pub use pdf::{PdfOptions, PdfPainter};
pub use png::{PngOptions, PngPainter};
pub use seams::{seam_flaps, seam_flaps_beside_strokes, seam_flaps_indexed, FlapJoin};
pub use svg::{SvgOptions, SvgPainter};
pub use texture_page::{draw_from_page_image, DEFAULT_TEXTURE_SAMPLES};
pub use texture_pieces::{affine_pieces, AffinePiece, MAX_PERSPECTIVE_ERROR};
pub use tikz::{TikzOptions, TikzPainter, MAX_TIKZ_SIDE, MAX_TIKZ_STROKE};
