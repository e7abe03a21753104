//! Ordered fragments plus visible marks → a paintable [`Picture`]: the fragments as
//! [`picture()`] makes them, and the visible line pieces, markers, labels and arrow heads
//! as [`Mark`]s at their paint positions.

use limn_depthsort::{Ordered, VisibleMarks};
use limn_scene::Scene;

use crate::seams::seam_flaps_beside_strokes;
use crate::{
    picture, ArrowHead, Label, LinePiece, LineStyle, Mark, MarkKind, Marker, Picture, Style,
};

/// Length of an arrow head for a line of width `w`, in pixels.
pub fn head_length(w: f64) -> f64 {
    6.0 + 3.0 * w
}

/// Stroke width of the outlined markers (circle, square, triangle, cross, plus) of size
/// `size`: an eighth of the size, at least 1 px.
pub fn marker_stroke(size: f64) -> f64 {
    (size / 8.0).max(1.0)
}

/// Builds the picture of `ordered` (see [`picture()`]) with the visible marks of `scene`
/// (from `limn_depthsort::order_with_marks`) placed among the fragments. Line pieces come
/// first at each position, then arrow heads, markers and labels, so labels are on top.
/// An arrow head is an isosceles triangle [`head_length`] long and 0.6 times as wide,
/// tip on the line's last point; a piece ending at a visible tip is shortened by half a
/// head so that its butt end hides under the head.
///
/// The ordered fragments are released once composed (`ordered.fragments` is left empty;
/// [`limn_depthsort::Stats::fragments_out`] still counts them): the seam flaps are put in
/// without them beside the picture (a million-face picture's ordered fragments were
/// 110 MB of its peak). It is [`picture_with_marks_unflapped`] then [`add_seam_flaps`].
pub fn picture_with_marks(
    scene: &Scene,
    ordered: &mut Ordered,
    visible: &VisibleMarks,
    style: &Style,
) -> Picture {
    let mut pic = picture_with_marks_unflapped(scene, ordered, visible, style);
    add_seam_flaps(&mut pic, style);
    pic
}

/// [`picture_with_marks`] without its seam flaps, which [`add_seam_flaps`] puts in: the
/// scene is not needed for them, and a caller that holds it only for this picture can
/// release it first (a million-face scene's faces are about 150 MB).
pub fn picture_with_marks_unflapped(
    scene: &Scene,
    ordered: &mut Ordered,
    visible: &VisibleMarks,
    style: &Style,
) -> Picture {
    let plain = Style {
        seams: 0.0,
        ..style.clone()
    };
    let mut pic = picture(scene, ordered, &plain);
    let count = ordered.fragments.len();
    ordered.fragments = Vec::new();
    let total = pic.fragments.len();
    let place = |before: usize| if before < count { before } else { total };
    let mut marks = Vec::new();
    let mut pieces: Vec<(usize, LinePiece)> = visible
        .pieces
        .iter()
        .map(|p| {
            let l = &scene.lines[p.line as usize];
            let piece = LinePiece {
                points: p.points.clone(),
                style: LineStyle {
                    color: l.color,
                    width: l.width,
                    dash: l.dash.clone(),
                },
                dash_offset: p.start,
                line: p.line,
            };
            (p.before, piece)
        })
        .collect();
    let mut heads = Vec::new();
    for h in &visible.heads {
        let l = &scene.lines[h.index as usize];
        let d = [h.at[0] - h.from[0], h.at[1] - h.from[1]];
        let len = d[0].hypot(d[1]);
        if !(len.is_finite() && len > 0.0) {
            continue;
        }
        let u = [d[0] / len, d[1] / len];
        let hl = head_length(l.width);
        let hw = 0.3 * hl;
        let base = [h.at[0] - hl * u[0], h.at[1] - hl * u[1]];
        heads.push(Mark {
            before: place(h.before),
            object: l.object,
            kind: MarkKind::Head(ArrowHead {
                points: [
                    h.at,
                    [base[0] - hw * u[1], base[1] + hw * u[0]],
                    [base[0] + hw * u[1], base[1] - hw * u[0]],
                ],
                color: l.color,
            }),
        });
        // Shorten the piece ending at the tip.
        if let Some((_, p)) = pieces
            .iter_mut()
            .rev()
            .find(|(_, p)| p.line == h.index && p.points.last() == Some(&h.at))
        {
            let n = p.points.len();
            let back = 0.5 * hl;
            let prev = p.points[n - 2];
            let seg = (h.at[0] - prev[0]).hypot(h.at[1] - prev[1]);
            if seg > back {
                p.points[n - 1] = [h.at[0] - back * u[0], h.at[1] - back * u[1]];
            }
        }
    }
    for (before, piece) in pieces {
        marks.push(Mark {
            before: place(before),
            object: scene.lines[piece.line as usize].object,
            kind: MarkKind::Line(piece),
        });
    }
    marks.extend(heads);
    for a in &visible.points {
        let p = &scene.points[a.index as usize];
        marks.push(Mark {
            before: place(a.before),
            object: p.object,
            kind: MarkKind::Marker(Marker {
                at: a.at,
                shape: p.shape,
                size: p.size,
                color: p.color,
                stroke: marker_stroke(p.size),
            }),
        });
    }
    for a in &visible.labels {
        let l = &scene.labels[a.index as usize];
        marks.push(Mark {
            before: place(a.before),
            object: l.object,
            kind: MarkKind::Label(Label {
                at: a.at,
                offset: l.offset,
                anchor: l.anchor,
                text: l.text.clone(),
                size: l.size,
                color: l.color,
            }),
        });
    }
    marks.sort_by_key(|m| m.before);
    pic.marks = marks;
    pic
}

/// Puts the seam flaps `style` asks for into a picture of [`picture_with_marks_unflapped`]
/// (see [`crate::seam_flaps`]), its marks moved with the fragments they follow.
pub fn add_seam_flaps(pic: &mut Picture, style: &Style) {
    add_seam_flaps_beside_strokes(pic, style, &[]);
}

/// [`add_seam_flaps`] for a caller that strokes every original edge of the faces
/// `stroked` marks, opaque and at least `style.seams` wide, right after each fill: no
/// flap along those edges (see [`seam_flaps_beside_strokes`]).
pub fn add_seam_flaps_beside_strokes(pic: &mut Picture, style: &Style, stroked: &[bool]) {
    if !(style.seams.is_finite() && style.seams > 0.0) {
        return;
    }
    let (frags, at) = seam_flaps_beside_strokes(
        std::mem::take(&mut pic.fragments),
        style.seams,
        style.flap_join(),
        stroked,
    );
    pic.fragments = frags;
    let total = pic.fragments.len();
    for m in &mut pic.marks {
        m.before = at.get(m.before).copied().unwrap_or(total);
    }
    pic.marks.sort_by_key(|m| m.before);
}
