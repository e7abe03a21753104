//! Lines, point markers and text labels: scene content drawn over the surfaces, each
//! shown only where (or when) it is visible.

use glam::DVec3;

use crate::SceneError;

/// Marker shapes, drawn centred on their anchor in screen size.
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
    /// Every shape, in the order of their names in [`MarkerShape::NAMES`].
    pub const ALL: [MarkerShape; 6] = [
        MarkerShape::Dot,
        MarkerShape::Circle,
        MarkerShape::Square,
        MarkerShape::Triangle,
        MarkerShape::Cross,
        MarkerShape::Plus,
    ];

    /// The accepted names, for error messages.
    pub const NAMES: &'static str = "dot, circle, square, triangle, cross, plus";

    /// Parses `dot`, `circle`, `square`, `triangle`, `cross` or `plus`.
    pub fn from_name(s: &str) -> Option<MarkerShape> {
        MarkerShape::ALL.into_iter().find(|m| m.name() == s)
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
    /// Every anchor.
    pub const ALL: [LabelAnchor; 9] = [
        LabelAnchor::Center,
        LabelAnchor::North,
        LabelAnchor::South,
        LabelAnchor::East,
        LabelAnchor::West,
        LabelAnchor::NorthEast,
        LabelAnchor::NorthWest,
        LabelAnchor::SouthEast,
        LabelAnchor::SouthWest,
    ];

    /// Parses TikZ's names (`center`, `north`, `south east`, …); `-` or `_` may replace
    /// the space, and `centre` is accepted.
    pub fn from_name(s: &str) -> Option<LabelAnchor> {
        let s = s.replace(['-', '_'], " ");
        let s = if s == "centre" { "center" } else { &s };
        LabelAnchor::ALL.into_iter().find(|a| a.name() == s)
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

/// A polyline in world coordinates (an OBJ `l`, a scene file's `[[line]]`), drawn only
/// where visible.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline {
    /// At least two points.
    pub points: Vec<DVec3>,
    /// Colour, RGBA in [0, 1].
    pub color: [f64; 4],
    /// Width in pixels (positive).
    pub width: f64,
    /// Dash pattern in pixels (dash, gap, …); empty = solid.
    pub dash: Vec<f64>,
    /// Whether an arrow head is drawn at the last point (when that point is visible).
    pub head: bool,
    /// Index into [`crate::Scene::objects`].
    pub object: u32,
}

impl Polyline {
    /// A solid black line of width 1 px in object 0.
    pub fn new(points: Vec<DVec3>) -> Self {
        Polyline {
            points,
            color: [0.0, 0.0, 0.0, 1.0],
            width: 1.0,
            dash: Vec::new(),
            head: false,
            object: 0,
        }
    }
}

/// A point shown as a marker (an OBJ `p`, one position of a scene file's `[[points]]`)
/// when its anchor is visible.
#[derive(Debug, Clone, PartialEq)]
pub struct PointMark {
    /// The anchor.
    pub at: DVec3,
    /// Marker shape.
    pub shape: MarkerShape,
    /// Diameter or side in pixels (positive).
    pub size: f64,
    /// Colour, RGBA in [0, 1].
    pub color: [f64; 4],
    /// Index into [`crate::Scene::objects`].
    pub object: u32,
}

impl PointMark {
    /// A black dot of 4 px in object 0.
    pub fn new(at: DVec3) -> Self {
        PointMark {
            at,
            shape: MarkerShape::Dot,
            size: 4.0,
            color: [0.0, 0.0, 0.0, 1.0],
            object: 0,
        }
    }
}

/// A text label shown when its anchor is visible.
#[derive(Debug, Clone, PartialEq)]
pub struct TextLabel {
    /// The anchor.
    pub at: DVec3,
    /// One line of text.
    pub text: String,
    /// Font size in points (= pixels of the picture); positive.
    pub size: f64,
    /// Colour, RGBA in [0, 1].
    pub color: [f64; 4],
    /// Which point of the text box sits at the projected anchor plus `offset`.
    pub anchor: LabelAnchor,
    /// Offset in pixels (x right, y down).
    pub offset: [f64; 2],
    /// Index into [`crate::Scene::objects`].
    pub object: u32,
}

impl TextLabel {
    /// A black 10 pt label centred on `at`, in object 0.
    pub fn new(at: DVec3, text: &str) -> Self {
        TextLabel {
            at,
            text: text.to_string(),
            size: 10.0,
            color: [0.0, 0.0, 0.0, 1.0],
            anchor: LabelAnchor::Center,
            offset: [0.0, 0.0],
            object: 0,
        }
    }
}

/// Checks a colour: four finite channels in [0, 1].
fn check_color(c: &[f64; 4], what: &'static str) -> Result<(), SceneError> {
    if c.iter().all(|v| v.is_finite() && (0.0..=1.0).contains(v)) {
        Ok(())
    } else {
        Err(SceneError::BadMark {
            what,
            problem: "colour channels must lie in [0, 1]".into(),
        })
    }
}

/// Checks a size or width: finite and positive.
fn check_positive(v: f64, what: &'static str, name: &str) -> Result<(), SceneError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(SceneError::BadMark {
            what,
            problem: format!("{name} must be a positive number, not {v}"),
        })
    }
}

impl Polyline {
    /// Checks the invariants: at least two finite points, a positive width, a valid
    /// colour, dash lengths finite and non-negative with a positive sum.
    pub fn validate(&self, objects: usize) -> Result<(), SceneError> {
        if self.points.len() < 2 {
            return Err(SceneError::BadMark {
                what: "line",
                problem: format!("{} point(s); at least 2 are needed", self.points.len()),
            });
        }
        if self.points.iter().any(|p| !p.is_finite()) {
            return Err(SceneError::NonFinite("line point"));
        }
        check_positive(self.width, "line", "width")?;
        check_color(&self.color, "line")?;
        if !self.dash.is_empty()
            && (self.dash.iter().any(|d| !d.is_finite() || *d < 0.0)
                || self.dash.iter().sum::<f64>() <= 0.0)
        {
            return Err(SceneError::BadMark {
                what: "line",
                problem: "dash lengths must be non-negative numbers with a positive sum".into(),
            });
        }
        check_object(self.object, objects)
    }
}

impl PointMark {
    /// Checks the invariants: a finite anchor, a positive size, a valid colour.
    pub fn validate(&self, objects: usize) -> Result<(), SceneError> {
        if !self.at.is_finite() {
            return Err(SceneError::NonFinite("point"));
        }
        check_positive(self.size, "point", "size")?;
        check_color(&self.color, "point")?;
        check_object(self.object, objects)
    }
}

impl TextLabel {
    /// Checks the invariants: a finite anchor and offset, a positive size, a valid
    /// colour, text on one line.
    pub fn validate(&self, objects: usize) -> Result<(), SceneError> {
        if !self.at.is_finite() || !self.offset.iter().all(|v| v.is_finite()) {
            return Err(SceneError::NonFinite("label anchor or offset"));
        }
        check_positive(self.size, "label", "size")?;
        check_color(&self.color, "label")?;
        if self.text.contains(['\n', '\r']) {
            return Err(SceneError::BadMark {
                what: "label",
                problem: "text must be one line".into(),
            });
        }
        check_object(self.object, objects)
    }
}

fn check_object(object: u32, objects: usize) -> Result<(), SceneError> {
    if (object as usize) < objects {
        Ok(())
    } else {
        Err(SceneError::BadReference {
            what: "object",
            index: object,
        })
    }
}
