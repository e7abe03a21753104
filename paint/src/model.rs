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
