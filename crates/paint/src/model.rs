//! The picture model: what every painter paints.

use std::collections::BTreeMap;
use std::sync::Arc;

pub use limn_scene::{LabelAnchor, MarkerShape, Texture, TextureAlpha};

/// A vertex colour as a picture keeps it: linear RGB and alpha, each in `[0, 1]`, in
/// single precision. A smooth picture's fragments and seam flaps carry three or four
/// each: in double precision a million smooth triangles' picture took 408 MB instead
/// of 356, and single precision is finer than the 16 bits per channel of the
/// finest output (a PDF shading). The painters compute in double precision
/// ([`wide_color`]); colours are stored through [`narrow_color`].
pub type VertexColor = [f32; 4];

/// `c` rounded to a stored vertex colour (to nearest).
pub fn narrow_color(c: [f64; 4]) -> VertexColor {
    c.map(|v| v as f32)
}

/// Stored vertex colour `c` in double precision (exactly).
pub fn wide_color(c: VertexColor) -> [f64; 4] {
    c.map(f64::from)
}

/// One convex (or at least simple) polygon to paint, in pixel coordinates (x right, y down).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PaintFragment {
    /// Polygon corners in order (either orientation).
    pub points: Vec<[f64; 2]>,
    /// Linear-RGB fill colour with alpha = opacity, each in `[0, 1]`.
    pub fill: [f64; 4],
    /// Optional per-vertex colours (Gouraud); same length as points. Linear RGB and
    /// alpha like [`PaintFragment::fill`], in single precision ([`VertexColor`]).
    pub vertex_colors: Option<Vec<VertexColor>>,
    /// Input face id this fragment came from.
    pub face: u32,
    /// Index into Picture::objects.
    pub object: u32,
    /// Per edge `i` (`points[i]` to `points[(i + 1) % n]`): is it an original model edge (outlined
    /// when outlines are on)?
    pub original_edges: Vec<bool>,
    /// A texture drawn over the fragment: each point's colour is its colour without the
    /// texture ([`PaintFragment::fill`] (RGB), or the vertex colours interpolated when
    /// there are any: a smoothly lit textured face) times the texture's colour there;
    /// opacity stays `fill[3]`. Boxed: most fragments have none, and the map inline made
    /// every fragment 80 bytes larger (a million-face picture's fragments and flaps,
    /// held two or three times while flaps are put in, 190 MB more).
    pub texture: Option<Box<TextureMap>>,
    /// Whether this is a seam flap of the fragment of the same face painted before it
    /// (see [`crate::seam_flaps`]): it lies inside a fragment painted later, so it
    /// changes no pixel once that one is painted and only fills the anti-aliased pixels
    /// of the shared edge. A flap carries its fragment's paint (a smooth fragment's flap
    /// has vertex colours that run along the shared edge as the fragment's do), so a
    /// writer may paint it in one fill with its fragment.
    pub flap: bool,
}

/// How a textured fragment maps the page onto its texture: a projective map from pixel
/// coordinates to texture coordinates `(s, t)` (see [`limn_scene::texture`] for how
/// textures are sampled). Every part of the fragment (clipped, covered, flaps) uses the
/// same map, so it needs no per-corner data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TextureMap {
    /// Index into [`Picture::textures`].
    pub texture: u32,
    /// Rows of the 3 × 3 matrix `H`: `(s·q, t·q, q) = H · (x, y, 1)`.
    pub screen_to_st: [[f64; 3]; 3],
    /// How the texture's alpha is drawn (see [`limn_scene::TextureAlpha`]).
    pub alpha: TextureAlpha,
}

impl TextureMap {
    /// Whether the texture's alpha is drawn (a cut-out or blended texture): what is
    /// behind the fragment may show through it.
    pub fn see_through(&self) -> bool {
        self.alpha != TextureAlpha::Opaque
    }

    /// The texture coordinates at pixel point `p`; `None` where the map is undefined
    /// (on the horizon of the fragment's plane).
    pub fn st_at(&self, p: [f64; 2]) -> Option<[f64; 2]> {
        let h = &self.screen_to_st;
        let row = |r: usize| h[r][0] * p[0] + h[r][1] * p[1] + h[r][2];
        let q = row(2);
        let st = [row(0) / q, row(1) / q];
        (st[0].is_finite() && st[1].is_finite()).then_some(st)
    }

    /// The same map for a page scaled by `k` (pixel `(x, y)` becomes `(k·x, k·y)`).
    pub fn scaled(&self, k: f64) -> TextureMap {
        let mut m = *self;
        for row in &mut m.screen_to_st {
            row[0] /= k;
            row[1] /= k;
        }
        m
    }
}

impl PaintFragment {
    /// Whether the fragment hides what is behind it wherever it lies: opacity 1 and no
    /// texture whose alpha is drawn.
    pub fn is_opaque(&self) -> bool {
        self.fill[3] >= 1.0 && self.texture.as_ref().is_none_or(|t| !t.see_through())
    }

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
            texture: None,
            flap: false,
        }
    }
}

/// Everything a painter needs: the page, the object names, the fragments in paint order and
/// the marks (line pieces, markers, labels, arrow heads) interleaved with them.
///
/// # Paint order
///
/// Fragments are painted in the order of [`Picture::fragments`]. Each [`Mark`] carries
/// [`Mark::before`], an index into the fragments: it is painted after
/// `fragments[..before]` and before `fragments[before..]` (`before == fragments.len()`
/// paints it after every fragment). Marks with the same `before` are painted in the order
/// of [`Picture::marks`], which writers never reorder. A writer paints, for each `i` in
/// `0..=fragments.len()`, first the marks whose `before` is `i`, then fragment `i`.
/// [`Picture::marks`] is kept sorted by `before` (stable); a mark whose `before` exceeds
/// the fragment count is painted last.
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
    /// Line pieces, markers, labels and arrow heads, sorted by [`Mark::before`] (their
    /// position among the fragments; see the paint-order rules above).
    pub marks: Vec<Mark>,
    /// The textures of textured fragments ([`TextureMap::texture`] indexes this), each
    /// once: writers embed each image once however many fragments use it.
    pub textures: Vec<Arc<Texture>>,
    /// Whether the vector writers (SVG, PDF, EPS, TikZ) write each path of a face's flat
    /// fragments (and their seam flaps) as one outline, the union of the fragments with
    /// holes where needed, instead of one subpath per fragment (see `merge.rs`): the
    /// edges between a face's pieces are then not in the file. The union is taken of the
    /// polygons as written (corners rounded to the writer's decimals), so the filled
    /// area stays that of the subpaths. Set for every composed picture, painter's output
    /// and the visible map alike: viewers then draw no mark along the edges between a
    /// face's pieces (Chromium drew one where three pieces met at a corner). Default
    /// `false` (each fragment a subpath, the subpaths snap-rounded together).
    pub merge_pieces: bool,
    /// The corners, on the page, of translucent input faces that lie wholly in front of
    /// the eye, by face index: every fragment of such a face lies in the convex hull of
    /// its face's corners, so writers that group translucent fragments use them to show
    /// two faces' fragments apart (see [`PaintFragment::face`]). Empty by default; a
    /// face left out is judged by its fragments' own corners.
    pub face_outlines: BTreeMap<u32, Vec<[f64; 2]>>,
    /// The texture that is an image of the page, sampled by
    /// [`crate::draw_from_page_image`]: the vector writers embed it in tiles and draw
    /// each run of the fragments that read it from the tiles it covers. `None` by
    /// default.
    pub page_image: Option<PageImage>,
}

/// An image of the page among [`Picture::textures`]: sample `(i, j)` (its centre) lies
/// at page point `((i + ½) / samples, (j + ½) / samples)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageImage {
    /// Its index in [`Picture::textures`].
    pub texture: u32,
    /// Samples per page unit, each way.
    pub samples: f64,
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

    /// Whether some fragment is textured.
    pub fn has_textures(&self) -> bool {
        self.fragments.iter().any(|f| f.texture.is_some())
    }

    /// The picture itself when it has no textured fragment, else
    /// [`Picture::textures_flattened`]; with the number of fragments flattened.
    pub fn untextured(&self) -> (std::borrow::Cow<'_, Picture>, usize) {
        let n = self
            .fragments
            .iter()
            .filter(|f| f.texture.is_some())
            .count();
        if n == 0 {
            (std::borrow::Cow::Borrowed(self), 0)
        } else {
            (std::borrow::Cow::Owned(self.textures_flattened()), n)
        }
    }

    /// The picture with every textured fragment filled with its fill (or its vertex
    /// colours) times its texture's mean colour, and no textures: what the writers that draw no images
    /// paint (they report it as approximated). A texture whose alpha is drawn also
    /// multiplies the opacity by its mean alpha.
    pub fn textures_flattened(&self) -> Picture {
        let means: Vec<[f64; 4]> = self
            .textures
            .iter()
            .map(|t| {
                let [r, g, b] = t.mean();
                [r, g, b, t.mean_alpha()]
            })
            .collect();
        let mut out = self.clone();
        out.textures.clear();
        for f in &mut out.fragments {
            if let Some(t) = f.texture.take() {
                let m = means.get(t.texture as usize).copied().unwrap_or([1.0; 4]);
                for (c, m) in f.fill.iter_mut().zip(m) {
                    *c *= m;
                }
                for vc in f.vertex_colors.iter_mut().flatten() {
                    let mut wide = wide_color(*vc);
                    for (c, m) in wide.iter_mut().zip(m) {
                        *c *= m;
                    }
                    *vc = narrow_color(wide);
                }
            }
        }
        out
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

/// One thing painted over (or between) the fragments: where it goes in paint order and
/// what it is.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// Paint position: painted after `fragments[..before]` and before
    /// `fragments[before..]`.
    pub before: usize,
    /// Index into [`Picture::objects`] (the line set, point set or label it came from);
    /// writers may group marks by it.
    pub object: u32,
    /// What to paint.
    pub kind: MarkKind,
}

/// The kinds of marks.
#[derive(Debug, Clone, PartialEq)]
pub enum MarkKind {
    /// A visible piece of a polyline, stroked (never filled).
    Line(LinePiece),
    /// A marker drawn whole at a visible anchor.
    Marker(Marker),
    /// A text label at a visible anchor.
    Label(Label),
    /// The filled head of an arrow whose tip is visible.
    Head(ArrowHead),
}

/// How a line is stroked: colour, width and dash pattern.
#[derive(Debug, Clone, PartialEq)]
pub struct LineStyle {
    /// Stroke colour, RGBA in [0, 1] (alpha = opacity).
    pub color: [f64; 4],
    /// Stroke width in pixels (points in PDF and EPS); must be finite and positive to be
    /// painted.
    pub width: f64,
    /// Dash pattern in pixels: lengths of dash, gap, dash, gap, … (empty = solid). Every
    /// entry must be finite and non-negative, and their sum positive, or the line is
    /// painted solid.
    pub dash: Vec<f64>,
}

impl LineStyle {
    /// A solid line.
    pub fn solid(color: [f64; 4], width: f64) -> Self {
        LineStyle {
            color,
            width,
            dash: Vec::new(),
        }
    }
}

/// A visible piece of a polyline in pixel coordinates, stroked with butt caps and round
/// joins. Consecutive visible segments of one input polyline that share an end point and
/// a paint position are joined into one piece.
#[derive(Debug, Clone, PartialEq)]
pub struct LinePiece {
    /// At least two points, in order along the line (x right, y down).
    pub points: Vec<[f64; 2]>,
    /// Colour, width, dashes.
    pub style: LineStyle,
    /// Where the dash pattern starts, in pixels: the on-screen length of the input
    /// polyline before this piece, so that dashes run on across hidden gaps.
    pub dash_offset: f64,
    /// Which input line (index in the scene's lines, or the model edge for hidden-line
    /// drawings) the piece belongs to.
    pub line: u32,
}

/// A marker at a visible anchor, in screen size (it does not shrink with distance).
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    /// The projected anchor (x right, y down).
    pub at: [f64; 2],
    /// The shape.
    pub shape: MarkerShape,
    /// Diameter (or side) in pixels.
    pub size: f64,
    /// Colour, RGBA in [0, 1]: the fill of a dot, the stroke of the other shapes.
    pub color: [f64; 4],
    /// Stroke width in pixels of the stroked shapes (ignored for dots).
    pub stroke: f64,
}

/// A text label at a visible anchor.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    /// The projected anchor (x right, y down).
    pub at: [f64; 2],
    /// Screen offset in pixels added to `at` (y down) before the text box is placed.
    pub offset: [f64; 2],
    /// Which point of the text box sits at `at + offset`.
    pub anchor: LabelAnchor,
    /// The text, one line, as given (writers escape it for their format).
    pub text: String,
    /// Font size in points (1 pt = 1 px of the picture, as everywhere).
    pub size: f64,
    /// Text colour, RGBA in [0, 1].
    pub color: [f64; 4],
}

/// The filled head of an arrow: a triangle with its tip at the polyline's last point,
/// pointing along the polyline's last segment as projected.
#[derive(Debug, Clone, PartialEq)]
pub struct ArrowHead {
    /// Tip, then the two back corners (x right, y down).
    pub points: [[f64; 2]; 3],
    /// Fill colour, RGBA in [0, 1].
    pub color: [f64; 4],
}
