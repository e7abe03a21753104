//! The picture model: what every painter paints.

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

/// Marker shapes, drawn centred on the anchor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MarkerShape {
    /// A filled disc of diameter `size`.
    #[default]
    Dot,
    /// A stroked circle of diameter `size`.
    Circle,
    /// A stroked axis-aligned square of side `size`.
    Square,
    /// A stroked upright equilateral triangle inscribed in the circle of diameter `size`.
    Triangle,
    /// A diagonal cross (×) of width and height `size`.
    Cross,
    /// An upright cross (+) of width and height `size`.
    Plus,
}

impl MarkerShape {
    /// Parses `dot`, `circle`, `square`, `triangle`, `cross` or `plus`.
    pub fn from_name(s: &str) -> Option<MarkerShape> {
        Some(match s {
            "dot" => MarkerShape::Dot,
            "circle" => MarkerShape::Circle,
            "square" => MarkerShape::Square,
            "triangle" => MarkerShape::Triangle,
            "cross" => MarkerShape::Cross,
            "plus" => MarkerShape::Plus,
            _ => return None,
        })
    }

    /// The name accepted by [`MarkerShape::from_name`].
    pub fn name(self) -> &'static str {
        match self {
            MarkerShape::Dot => "dot",
            MarkerShape::Circle => "circle",
            MarkerShape::Square => "square",
            MarkerShape::Triangle => "triangle",
            MarkerShape::Cross => "cross",
            MarkerShape::Plus => "plus",
        }
    }
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

/// Which point of a label's text box is placed at the anchor (plus the offset): the
/// TikZ `anchor` convention, so `South` puts the text above the point and `West` to its
/// right.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LabelAnchor {
    /// The centre of the box.
    #[default]
    Center,
    /// The middle of the top edge (text below the point).
    North,
    /// The middle of the bottom edge (text above the point).
    South,
    /// The middle of the right edge (text left of the point).
    East,
    /// The middle of the left edge (text right of the point).
    West,
    /// The top right corner.
    NorthEast,
    /// The top left corner.
    NorthWest,
    /// The bottom right corner.
    SouthEast,
    /// The bottom left corner.
    SouthWest,
}

impl LabelAnchor {
    /// Parses `center`, `north`, `south`, `east`, `west`, `north east`, `north west`,
    /// `south east` or `south west` (TikZ's names; `-` or `_` may replace the space).
    pub fn from_name(s: &str) -> Option<LabelAnchor> {
        Some(match s.replace(['-', '_'], " ").as_str() {
            "center" | "centre" => LabelAnchor::Center,
            "north" => LabelAnchor::North,
            "south" => LabelAnchor::South,
            "east" => LabelAnchor::East,
            "west" => LabelAnchor::West,
            "north east" => LabelAnchor::NorthEast,
            "north west" => LabelAnchor::NorthWest,
            "south east" => LabelAnchor::SouthEast,
            "south west" => LabelAnchor::SouthWest,
            _ => return None,
        })
    }

    /// TikZ's name of the anchor (`center`, `north east`, …).
    pub fn name(self) -> &'static str {
        match self {
            LabelAnchor::Center => "center",
            LabelAnchor::North => "north",
            LabelAnchor::South => "south",
            LabelAnchor::East => "east",
            LabelAnchor::West => "west",
            LabelAnchor::NorthEast => "north east",
            LabelAnchor::NorthWest => "north west",
            LabelAnchor::SouthEast => "south east",
            LabelAnchor::SouthWest => "south west",
        }
    }

    /// The anchor's place in the text box as fractions `(fx, fy)` of its width and
    /// height, from the box's left and top edges: `Center` is `(0.5, 0.5)`, `SouthWest`
    /// is `(0, 1)`.
    pub fn fractions(self) -> (f64, f64) {
        match self {
            LabelAnchor::Center => (0.5, 0.5),
            LabelAnchor::North => (0.5, 0.0),
            LabelAnchor::South => (0.5, 1.0),
            LabelAnchor::East => (1.0, 0.5),
            LabelAnchor::West => (0.0, 0.5),
            LabelAnchor::NorthEast => (1.0, 0.0),
            LabelAnchor::NorthWest => (0.0, 0.0),
            LabelAnchor::SouthEast => (1.0, 1.0),
            LabelAnchor::SouthWest => (0.0, 1.0),
        }
    }
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
