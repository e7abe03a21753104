//! What every backend does with marks before writing them: validation, clipping to the
//! guard box, marker and arrow-head geometry, dash patterns and label boxes (placed with
//! Helvetica's metrics, so that every format puts a label's box in the same place).

use crate::runs::Guard;
use crate::{Label, LineStyle, Mark, MarkKind, Marker, MarkerShape, PaintError, PaintStats};

/// What a backend writes for marks; [`paint_mark`] validates, clips and computes the
/// geometry, then calls these.
pub(crate) trait MarkSink {
    /// Strokes polylines (closed ones get a closing segment) with butt caps and round
    /// joins; `dash` is even-length or empty.
    fn polylines(
        &mut self,
        lines: &[Vec<[f64; 2]>],
        closed: bool,
        color: [f64; 4],
        width: f64,
        dash: &[f64],
        offset: f64,
    ) -> Result<(), PaintError>;
    /// A circle of centre `c` and radius `r`: filled when `stroke` is `None`, else
    /// stroked with that width.
    fn circle(
        &mut self,
        c: [f64; 2],
        r: f64,
        color: [f64; 4],
        stroke: Option<f64>,
    ) -> Result<(), PaintError>;
    /// A filled triangle.
    fn triangle(&mut self, points: [[f64; 2]; 3], color: [f64; 4]) -> Result<(), PaintError>;
    /// One line of text starting at `origin` (the left end of its baseline); returns
    /// whether the format could only approximate it.
    fn text(&mut self, origin: [f64; 2], label: &Label) -> Result<bool, PaintError>;
}

/// Paints one mark through `sink`, counting it in `stats` (or as skipped or clipped).
pub(crate) fn paint_mark(
    m: &Mark,
    guard: &Guard,
    sink: &mut impl MarkSink,
    stats: &mut PaintStats,
) -> Result<(), PaintError> {
    match &m.kind {
        MarkKind::Line(p) => {
            let Some(lines) = clip_polyline(&p.points, guard).filter(|_| style_ok(&p.style)) else {
                stats.skipped += 1;
                return Ok(());
            };
            if lines.is_empty() {
                stats.clipped += 1;
                return Ok(());
            }
            let offset = if p.dash_offset.is_finite() {
                p.dash_offset
            } else {
                0.0
            };
            let d = dash(&p.style.dash);
            sink.polylines(&lines, false, p.style.color, p.style.width, &d, offset)?;
            stats.lines += 1;
        }
        MarkKind::Marker(mk) => {
            if !mk.at.iter().all(|v| v.is_finite()) || !marker_ok(mk) {
                stats.skipped += 1;
                return Ok(());
            }
            if !guard.contains(mk.at) {
                stats.clipped += 1;
                return Ok(());
            }
            match marker_geometry(mk) {
                MarkerGeometry::Circle { c, r, fill } => {
                    sink.circle(c, r, mk.color, (!fill).then_some(mk.stroke))?
                }
                MarkerGeometry::Lines(parts) => {
                    for (line, closed) in parts {
                        sink.polylines(&[line], closed, mk.color, mk.stroke, &[], 0.0)?;
                    }
                }
            }
            stats.markers += 1;
        }
        MarkKind::Label(l) => {
            if !label_ok(l) {
                stats.skipped += 1;
                return Ok(());
            }
            if !guard.contains(l.at) {
                stats.clipped += 1;
                return Ok(());
            }
            if sink.text(label_origin(l), l)? {
                stats.approximated += 1;
            }
            stats.labels += 1;
        }
        MarkKind::Head(h) => {
            let ok = h.points.iter().flatten().all(|v| v.is_finite())
                && h.color.iter().all(|c| c.is_finite());
            if !ok {
                stats.skipped += 1;
                return Ok(());
            }
            if !h.points.iter().all(|&p| guard.contains(p)) {
                stats.clipped += 1;
                return Ok(());
            }
            sink.triangle(h.points, h.color)?;
            stats.heads += 1;
        }
    }
    Ok(())
}

/// Whether a style can be painted: finite colour, positive finite width.
fn style_ok(s: &LineStyle) -> bool {
    s.color.iter().all(|c| c.is_finite()) && s.width.is_finite() && s.width > 0.0
}

/// The dash pattern as written (see [`Stroke::dash`]); solid when invalid.
fn dash(pattern: &[f64]) -> Vec<f64> {
    let ok = !pattern.is_empty()
        && pattern.iter().all(|d| d.is_finite() && *d >= 0.0)
        && pattern.iter().sum::<f64>() > 0.0;
    if !ok {
        return Vec::new();
    }
    let mut d = pattern.to_vec();
    if d.len() % 2 == 1 {
        d.extend_from_slice(pattern);
    }
    d
}

/// The polylines of `points` inside `guard`, or `None` when the piece is invalid (fewer
/// than two points, a non-finite coordinate). Segments are clipped to the box one by one
/// (Liang–Barsky); a piece entirely outside gives no polyline.
fn clip_polyline(points: &[[f64; 2]], guard: &Guard) -> Option<Vec<Vec<[f64; 2]>>> {
    if points.len() < 2 || !points.iter().all(|p| p[0].is_finite() && p[1].is_finite()) {
        return None;
    }
    if points.iter().all(|&p| guard.contains(p)) {
        return Some(vec![points.to_vec()]);
    }
    let (lo, hi) = guard.bounds();
    let mut out: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut cur: Vec<[f64; 2]> = Vec::new();
    for w in points.windows(2) {
        let Some((a, b)) = clip_segment(w[0], w[1], lo, hi) else {
            if cur.len() >= 2 {
                out.push(std::mem::take(&mut cur));
            }
            cur.clear();
            continue;
        };
        if cur.last() != Some(&a) {
            if cur.len() >= 2 {
                out.push(std::mem::take(&mut cur));
            }
            cur = vec![a];
        }
        cur.push(b);
    }
    if cur.len() >= 2 {
        out.push(cur);
    }
    Some(out)
}

/// Liang–Barsky clipping of one segment to the box `[lo, hi]`.
fn clip_segment(
    a: [f64; 2],
    b: [f64; 2],
    lo: [f64; 2],
    hi: [f64; 2],
) -> Option<([f64; 2], [f64; 2])> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for k in 0..2 {
        for (p, q) in [(-d[k], a[k] - lo[k]), (d[k], hi[k] - a[k])] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
    }
    if t0.partial_cmp(&t1) != Some(std::cmp::Ordering::Less) && t0 != t1 {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            [a[0] + t * d[0], a[1] + t * d[1]]
        }
    };
    Some((at(t0), at(t1)))
}

/// A marker's geometry: a disc or circle, or polylines.
enum MarkerGeometry {
    /// Centre and radius; filled when `fill`, stroked otherwise.
    Circle {
        /// Centre.
        c: [f64; 2],
        /// Radius.
        r: f64,
        /// Filled (a dot) or stroked (a circle).
        fill: bool,
    },
    /// Stroked polylines, closed when the flag is set.
    Lines(Vec<(Vec<[f64; 2]>, bool)>),
}

/// Whether a marker can be painted.
fn marker_ok(m: &Marker) -> bool {
    m.size.is_finite()
        && m.size > 0.0
        && m.color.iter().all(|c| c.is_finite())
        && (m.shape == MarkerShape::Dot || (m.stroke.is_finite() && m.stroke > 0.0))
}

/// The geometry of a marker centred on its anchor.
fn marker_geometry(m: &Marker) -> MarkerGeometry {
    let [x, y] = m.at;
    let h = m.size / 2.0;
    match m.shape {
        MarkerShape::Dot => MarkerGeometry::Circle {
            c: m.at,
            r: h,
            fill: true,
        },
        MarkerShape::Circle => MarkerGeometry::Circle {
            c: m.at,
            r: h,
            fill: false,
        },
        MarkerShape::Square => MarkerGeometry::Lines(vec![(
            vec![
                [x - h, y - h],
                [x + h, y - h],
                [x + h, y + h],
                [x - h, y + h],
            ],
            true,
        )]),
        MarkerShape::Triangle => {
            let s = h * 3f64.sqrt() / 2.0;
            MarkerGeometry::Lines(vec![(
                vec![[x, y - h], [x + s, y + h / 2.0], [x - s, y + h / 2.0]],
                true,
            )])
        }
        MarkerShape::Cross => MarkerGeometry::Lines(vec![
            (vec![[x - h, y - h], [x + h, y + h]], false),
            (vec![[x - h, y + h], [x + h, y - h]], false),
        ]),
        MarkerShape::Plus => MarkerGeometry::Lines(vec![
            (vec![[x - h, y], [x + h, y]], false),
            (vec![[x, y - h], [x, y + h]], false),
        ]),
    }
}

/// The four cubic Bézier segments of a circle (start point, then three control points
/// per quarter), for formats without circles.
pub(crate) fn circle_beziers(c: [f64; 2], r: f64) -> ([f64; 2], [[[f64; 2]; 3]; 4]) {
    const K: f64 = 0.552_284_749_830_793_4;
    let k = K * r;
    let [x, y] = c;
    (
        [x + r, y],
        [
            [[x + r, y + k], [x + k, y + r], [x, y + r]],
            [[x - k, y + r], [x - r, y + k], [x - r, y]],
            [[x - r, y - k], [x - k, y - r], [x, y - r]],
            [[x + k, y - r], [x + r, y - k], [x + r, y]],
        ],
    )
}

/// Helvetica's advance widths (per 1000 units of the font size) of the printable ASCII
/// characters 32 to 126, from Adobe's standard font metrics.
const HELVETICA: [u16; 95] = [
    278, 278, 355, 556, 556, 889, 667, 191, 333, 333, 389, 584, 278, 333, 278,
    278, // ' ' to /
    556, 556, 556, 556, 556, 556, 556, 556, 556, 556, // 0 to 9
    278, 278, 584, 584, 584, 556, 1015, // : to @
    667, 667, 722, 722, 667, 611, 778, 722, 278, 500, 667, 556, 833, 722, 778, 667, 778, 722, 667,
    611, 722, 667, 944, 667, 667, 611, // A to Z
    278, 278, 278, 469, 556, 333, // [ to `
    556, 556, 500, 556, 556, 278, 556, 556, 222, 222, 500, 222, 833, 556, 556, 556, 556, 333, 500,
    278, 556, 500, 722, 500, 500, 500, // a to z
    334, 260, 334, 584, // { to ~
];

/// Helvetica's ascender and descender, per 1000.
const ASCENT: f64 = 718.0;
const DESCENT: f64 = 207.0;

/// The text as written in the base-14 fonts: printable ASCII kept, anything else becomes
/// `?`; returns the text and whether something was replaced.
pub(crate) fn ascii_text(text: &str) -> (String, bool) {
    let mut changed = false;
    let s = text
        .chars()
        .map(|c| {
            if (' '..='~').contains(&c) {
                c
            } else {
                changed = true;
                '?'
            }
        })
        .collect();
    (s, changed)
}

/// The width of `text` in Helvetica at `size` (non-ASCII characters count as `?`).
pub(crate) fn text_width(text: &str, size: f64) -> f64 {
    text.chars()
        .map(|c| {
            let i = if (' '..='~').contains(&c) {
                c as usize - 32
            } else {
                b'?' as usize - 32
            };
            HELVETICA[i] as f64
        })
        .sum::<f64>()
        * size
        / 1000.0
}

/// Whether a label can be painted.
fn label_ok(l: &Label) -> bool {
    l.at.iter().chain(&l.offset).all(|v| v.is_finite())
        && l.size.is_finite()
        && l.size > 0.0
        && l.color.iter().all(|c| c.is_finite())
}

/// Where a label's text starts: the left end of its baseline, with the text box (from
/// Helvetica's descender to its ascender, as wide as the text) placed so that its
/// `anchor` point sits at `at + offset`.
pub(crate) fn label_origin(l: &Label) -> [f64; 2] {
    let w = text_width(&l.text, l.size);
    let h = (ASCENT + DESCENT) * l.size / 1000.0;
    let (fx, fy) = l.anchor.fractions();
    let left = l.at[0] + l.offset[0] - fx * w;
    let top = l.at[1] + l.offset[1] - fy * h;
    [left, top + ASCENT * l.size / 1000.0]
}

/// `m` scaled by `s` about the origin (positions, widths, sizes, dashes): for
/// supersampled rasters.
pub(crate) fn scaled(m: &Mark, s: f64) -> Mark {
    let p = |q: [f64; 2]| [q[0] * s, q[1] * s];
    let kind = match &m.kind {
        MarkKind::Line(l) => {
            let mut l = l.clone();
            l.points.iter_mut().for_each(|q| *q = p(*q));
            l.style.width *= s;
            l.style.dash.iter_mut().for_each(|d| *d *= s);
            l.dash_offset *= s;
            MarkKind::Line(l)
        }
        MarkKind::Marker(mk) => {
            let mut mk = mk.clone();
            mk.at = p(mk.at);
            mk.size *= s;
            mk.stroke *= s;
            MarkKind::Marker(mk)
        }
        MarkKind::Label(l) => {
            let mut l = l.clone();
            l.at = p(l.at);
            l.offset = p(l.offset);
            l.size *= s;
            MarkKind::Label(l)
        }
        MarkKind::Head(h) => {
            let mut h = h.clone();
            h.points = h.points.map(p);
            MarkKind::Head(h)
        }
    };
    Mark {
        before: m.before,
        object: m.object,
        kind,
    }
}

/// The glyph rectangles of a label in the 8×8 bitmap font of PNG output: each glyph is
/// stretched over its Helvetica advance (so the box matches the vector formats) and 0.8
/// of the font size tall, its top 0.7 of the size above the baseline. Characters the font
/// lacks are drawn as `?`. Returns `[x, y, w, h]` rectangles.
pub(crate) fn glyph_rects(origin: [f64; 2], label: &Label) -> Vec<[f64; 4]> {
    use font8x8::UnicodeFonts;
    let size = label.size;
    let cell_h = 0.1 * size;
    let top = origin[1] - 0.7 * size;
    let mut x = origin[0];
    let mut out = Vec::new();
    for ch in label.text.chars() {
        let advance = text_width(&ch.to_string(), size);
        let glyph = font8x8::BASIC_FONTS
            .get(ch)
            .or_else(|| font8x8::LATIN_FONTS.get(ch))
            .or_else(|| font8x8::GREEK_FONTS.get(ch))
            .or_else(|| font8x8::BASIC_FONTS.get('?'))
            .unwrap_or([0; 8]);
        let cell_w = advance / 8.0;
        for (row, bits) in glyph.iter().enumerate() {
            let mut col = 0;
            while col < 8 {
                if bits >> col & 1 == 1 {
                    let start = col;
                    while col < 8 && bits >> col & 1 == 1 {
                        col += 1;
                    }
                    out.push([
                        x + start as f64 * cell_w,
                        top + row as f64 * cell_h,
                        (col - start) as f64 * cell_w,
                        cell_h,
                    ]);
                } else {
                    col += 1;
                }
            }
        }
        x += advance;
    }
    out
}
