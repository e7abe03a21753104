//! Hidden-line drawings: a mesh's silhouette, boundary and crease edges drawn exactly
//! where visible (hidden parts left out or dashed), faces filled with the background
//! colour or not at all.
//!
//! The edges become lines of the scene (the `limn` crate's hidden-line stage, before
//! ordering) and are hidden by the same exact machinery as any line: an edge lies in the planes of its own faces, so the
//! in-plane rule keeps it drawn over them. Without fills ([`HiddenLineStyle::fill`] off)
//! the picture holds only lines, and the visible pieces of the edges are joined into
//! polylines as long as possible (pieces meeting end to end, at equal pixel points), for
//! pen plotters and cutters.

use std::collections::HashMap;

use limn_depthsort::{Ordered, VisibleMarks};
use limn_scene::Scene;

use crate::{picture_with_marks, LinePiece, LineStyle, Mark, MarkKind, Picture, Style};

/// What a hidden-line drawing looks like.
#[derive(Debug, Clone, PartialEq)]
pub struct HiddenLineStyle {
    /// Edge colour, RGBA. Default black.
    pub color: [f64; 4],
    /// Edge width in pixels. Default 1.
    pub width: f64,
    /// Dash hidden parts (pattern `[4w, 3w]`) instead of leaving them out. Default off.
    pub dashed: bool,
    /// Fill faces with the background colour (white when the picture has none). Default
    /// on; off draws lines only.
    pub fill: bool,
    /// Crease angle in degrees: edges between faces whose normals differ by more are
    /// drawn. Default 30.
    pub crease: f64,
}

impl Default for HiddenLineStyle {
    fn default() -> Self {
        HiddenLineStyle {
            color: [0.0, 0.0, 0.0, 1.0],
            width: 1.0,
            dashed: false,
            fill: true,
            crease: 30.0,
        }
    }
}

/// The picture of a hidden-line drawing: `scene` is the scene with its feature edges
/// appended to its lines from `first_edge` on, its materials the fill colour (the `limn`
/// crate's `hidden_line_scene`); `ordered` and `marks` come from
/// `limn_depthsort::order_with_marks`; the ordered fragments are released once composed
/// (see [`picture_with_marks`]).
pub fn hidden_line_picture(
    scene: &Scene,
    ordered: &mut Ordered,
    marks: &VisibleMarks,
    first_edge: usize,
    style: &HiddenLineStyle,
    base: &Style,
) -> Picture {
    let base = Style {
        outline: None,
        smooth: false,
        ..base.clone()
    };
    let mut pic = picture_with_marks(scene, ordered, marks, &base);
    let end = pic.fragments.len();
    if style.dashed {
        let w = style.width;
        for p in marks
            .hidden
            .iter()
            .filter(|p| p.line as usize >= first_edge)
        {
            pic.marks.push(Mark {
                before: end,
                object: scene.lines[p.line as usize].object,
                kind: MarkKind::Line(LinePiece {
                    points: p.points.clone(),
                    style: LineStyle {
                        color: style.color,
                        width: w,
                        dash: vec![4.0 * w, 3.0 * w],
                    },
                    dash_offset: 0.0,
                    line: p.line,
                }),
            });
        }
    }
    if !style.fill {
        pic.fragments.clear();
        pic.background = None;
        let (edges, other): (Vec<Mark>, Vec<Mark>) = pic
            .marks
            .into_iter()
            .partition(|m| matches!(&m.kind, MarkKind::Line(l) if l.line as usize >= first_edge));
        let mut marks: Vec<Mark> = other;
        marks.extend(join(edges));
        for m in &mut marks {
            m.before = 0;
        }
        pic.marks = marks;
    } else {
        pic.marks.sort_by_key(|m| m.before);
    }
    pic
}

/// A polyline in pixel coordinates.
type Polyline2 = Vec<[f64; 2]>;

/// Joins line marks of equal style that meet end to end (equal pixel points) into the
/// longest polylines a greedy walk finds: starting from ends where the number of pieces
/// meeting is not two, then around what remains (closed loops).
fn join(marks: Vec<Mark>) -> Vec<Mark> {
    let mut groups: Vec<(LineStyle, u32, Vec<Polyline2>)> = Vec::new();
    for m in marks {
        if let MarkKind::Line(l) = m.kind {
            match groups
                .iter_mut()
                .find(|(s, o, _)| *s == l.style && *o == m.object)
            {
                Some(g) => g.2.push(l.points),
                None => groups.push((l.style, m.object, vec![l.points])),
            }
        }
    }
    let mut out = Vec::new();
    for (style, object, pieces) in groups {
        for points in chain(pieces) {
            out.push(Mark {
                before: 0,
                object,
                kind: MarkKind::Line(LinePiece {
                    points,
                    style: style.clone(),
                    dash_offset: 0.0,
                    line: 0,
                }),
            });
        }
    }
    out
}

/// Chains polylines end to end (either direction).
fn chain(pieces: Vec<Vec<[f64; 2]>>) -> Vec<Vec<[f64; 2]>> {
    let key = |p: [f64; 2]| (p[0].to_bits(), p[1].to_bits());
    let mut at: HashMap<(u64, u64), Vec<usize>> = HashMap::new();
    for (i, p) in pieces.iter().enumerate() {
        at.entry(key(p[0])).or_default().push(i);
        at.entry(key(p[p.len() - 1])).or_default().push(i);
    }
    let mut used = vec![false; pieces.len()];
    let mut out = Vec::new();
    // Ends where a chain must start (not exactly two pieces meet), then the rest.
    let starts: Vec<usize> = (0..pieces.len())
        .filter(|&i| {
            let p = &pieces[i];
            at[&key(p[0])].len() != 2 || at[&key(p[p.len() - 1])].len() != 2
        })
        .chain(0..pieces.len())
        .collect();
    for s in starts {
        if used[s] {
            continue;
        }
        used[s] = true;
        let mut line = pieces[s].clone();
        // Start from the end that is not a junction of two, so the walk runs forward.
        if at[&key(line[line.len() - 1])].len() != 2 && at[&key(line[0])].len() == 2 {
            line.reverse();
        }
        loop {
            let end = key(line[line.len() - 1]);
            let next = at[&end].iter().copied().find(|&j| !used[j]);
            let Some(j) = next.filter(|_| at[&end].len() == 2) else {
                break;
            };
            used[j] = true;
            let mut p = pieces[j].clone();
            if key(p[0]) != end {
                p.reverse();
            }
            line.extend_from_slice(&p[1..]);
        }
        out.push(line);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::chain;

    #[test]
    fn chains_join_end_to_end_in_either_direction() {
        let pieces = vec![
            vec![[1.0, 0.0], [2.0, 0.0]],
            vec![[0.0, 0.0], [1.0, 0.0]],
            vec![[3.0, 0.0], [2.0, 0.0]],
            vec![[5.0, 5.0], [6.0, 5.0]],
        ];
        let mut c = chain(pieces);
        c.sort_by_key(Vec::len);
        assert_eq!(c.len(), 2);
        assert_eq!(c[1].len(), 4);
        let ends = [c[1][0], c[1][3]];
        assert!(ends.contains(&[0.0, 0.0]) && ends.contains(&[3.0, 0.0]));
    }

    #[test]
    fn a_closed_loop_is_one_chain() {
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let pieces = (0..4).map(|i| vec![sq[i], sq[(i + 1) % 4]]).collect();
        let c = chain(pieces);
        assert_eq!(c.len(), 1);
        assert_eq!(c[0].len(), 5);
    }
}
